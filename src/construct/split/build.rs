//! The build in splitting mode: split, reassemble the rings, build the
//! pieces' diagram, and record which input segments each piece came from.

use super::rings::split_rings;
use super::{split, SplitInput};
use crate::construct::polygon_input::RingInput;
use crate::diagram::{Diagram, SplitPieces};
use crate::error::{Error, ErrorKind};
use crate::geometry::Point;

/// The diagram of `points` and `segments` split where they meet; `rings`
/// are the polygons' rings over the input segments.
pub(crate) fn diagram_of_split(points: &[Point], segments: &[[Point; 2]], rings: &[RingInput]) -> Result<Diagram, Error> {
    let mut split = split(points, segments)?;
    let (mut split_rings_over_pieces, mut cancelled) = (Vec::new(), 0);
    if !rings.is_empty() {
        let (pieces, new_rings, dropped) = split_rings(std::mem::take(&mut split.pieces), rings, segments.len());
        (split.pieces, split_rings_over_pieces, cancelled) = (pieces, new_rings, dropped);
    }
    let ends: Vec<[Point; 2]> = split.pieces.iter().map(|p| p.ends).collect();
    // (the rings' pieces are some of the split's, reordered and some
    // reversed: still meeting only at common endpoints)
    let mut diagram = crate::construct::diagram_of_contact_free(&split.points, &ends, split.contact_free_in)
        .map_err(|e| in_input_terms(e, &split))?;
    if !rings.is_empty() {
        diagram.set_domain(&split_rings_over_pieces);
    }
    let origins: Vec<Vec<u32>> = split.pieces.iter().map(|p| p.origins.clone()).collect();
    diagram.split = Some(Box::new(SplitPieces::new(&origins, segments.len(), split.max_displacement, split.pixel)));
    let stats = &mut diagram.stats;
    stats.input_segments = segments.len();
    // the pieces are merged already: the repeats are counted in the input
    stats.duplicate_segments = repeated_segments(segments);
    stats.pieces = split.pieces.len();
    stats.crossings = split.crossings;
    stats.overlaps = split.overlaps;
    stats.touchings = split.touchings;
    stats.snap_rounds = split.rounds;
    stats.cancelled_ring_pieces = cancelled;
    Ok(diagram)
}

/// Input segments of nonzero length that repeat an earlier one (either
/// direction), as the strict build counts them; their pieces merge.
fn repeated_segments(segments: &[[Point; 2]]) -> usize {
    let mut keys: Vec<[u64; 4]> = segments
        .iter()
        .map(|s| s.map(Point::canonical_zero))
        .filter(|[a, b]| a != b)
        .map(|[a, b]| Point::segment_key(a, b))
        .collect();
    keys.sort_unstable();
    keys.windows(2).filter(|w| w[0] == w[1]).count()
}

/// A build error about pieces, its indices turned into the input segments
/// the pieces came from. An internal error keeps its message; a conflict
/// (none is expected: the split input passed the same exact test) becomes
/// an internal error.
fn in_input_terms(error: Error, split: &SplitInput) -> Error {
    if error.kind() != ErrorKind::Intersecting && error.kind() != ErrorKind::Internal {
        return error;
    }
    let mut inputs: Vec<usize> =
        error.indices().iter().filter_map(|&k| split.pieces.get(k)).flat_map(|p| p.origins.iter().map(|&i| i as usize)).collect();
    inputs.sort_unstable();
    inputs.dedup();
    let message = match error.kind() {
        ErrorKind::Internal => error.message().to_string(),
        _ => format!(
            "construction could not complete: after splitting crossings, {} (pieces of input segments {inputs:?}); please report this input",
            error.message()
        ),
    };
    Error::new(ErrorKind::Internal, message, inputs)
}
