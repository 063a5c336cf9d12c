//! The rings of polygon input, as the builder remembers them: which
//! segments (and arcs) each ring of each polygon became, so that the
//! diagram can tell the domain they bound (`query::domain`) and an error
//! can name the ring. The builder's adders (`Builder::add_polygon`,
//! `add_bulged_polygon`) make them.

use crate::error::{Error, ErrorKind};

/// What a piece of [`Builder::add_bulged_polyline`](crate::Builder::add_bulged_polyline) became: the input index
/// of a segment or of an arc.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChainPiece {
    /// A straight piece: this segment input index.
    Segment(usize),
    /// A curved piece: this arc input index.
    Arc(usize),
}

/// One ring of a polygon as the builder keeps it: which polygon and ring
/// it is, and the input indices of its segments, in ring order.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct RingInput {
    pub polygon: usize,
    pub ring: usize,
    pub segments: std::ops::Range<usize>,
    /// A ring of segments and arcs (`Builder::add_bulged_polygon`): its
    /// pieces in ring order, each running from its corner to the next
    /// (`segments` is then empty: such rings share no stretches, and are
    /// not split by `split_crossings`). `None` for a ring of `segments`.
    pub pieces: Option<Vec<ChainPiece>>,
}

/// The rings over the pieces the diagram was built from: a ring whose
/// segments were cut at input vertices inside them (`BuildStats::
/// split_at_vertices`) runs through the same points with one more corner
/// per cut, so each input segment's range becomes that of its pieces (in
/// its direction, as the pieces are numbered). Without cuts, the rings.
pub(crate) fn rings_over_pieces(diagram: &crate::Diagram, rings: &[RingInput]) -> Vec<RingInput> {
    rings
        .iter()
        .map(|r| {
            if let Some(pieces) = &r.pieces {
                // a segment cut at vertices inside it: its pieces, in its direction
                let pieces = pieces
                    .iter()
                    .flat_map(|&p| -> Vec<ChainPiece> {
                        match p {
                            ChainPiece::Segment(j) => {
                                let cut: Vec<ChainPiece> = diagram.pieces_of_input(j).map(ChainPiece::Segment).collect();
                                if cut.is_empty() {
                                    vec![p]
                                } else {
                                    cut
                                }
                            }
                            arc => vec![arc],
                        }
                    })
                    .collect();
                return RingInput { pieces: Some(pieces), ..r.clone() };
            }
            let first = diagram.pieces_of_input(r.segments.start).next();
            let last = diagram.pieces_of_input(r.segments.end - 1).last();
            let segments = match (first, last) {
                (Some(first), Some(last)) => first..last + 1,
                _ => r.segments.clone(), // (a ring has no zero-length segment)
            };
            RingInput { polygon: r.polygon, ring: r.ring, segments, pieces: None }
        })
        .collect()
}

/// Per input segment (`segments` of them), whether a ring of `rings` made
/// it; empty when there are no rings. Ring segments may share stretches,
/// which cancel (`construct::shared_stretches`).
pub(crate) fn ring_segments(rings: &[RingInput], segments: usize) -> Vec<bool> {
    if rings.is_empty() {
        return Vec::new();
    }
    let mut ring = vec![false; segments];
    for j in rings.iter().flat_map(|r| r.segments.clone()) {
        ring[j] = true;
    }
    ring
}

/// Per input segment (`segments` of them) and per input arc (`arcs`),
/// whether a ring of `rings` made it: its plain segments and the pieces of
/// a bulged ring alike (the splits' even-odd rule counts both).
pub(crate) fn ring_inputs(rings: &[RingInput], segments: usize, arcs: usize) -> (Vec<bool>, Vec<bool>) {
    let (mut segment, mut arc) = (vec![false; segments], vec![false; arcs]);
    for ring in rings {
        ring.segments.clone().for_each(|j| segment[j] = true);
        for piece in ring.pieces.iter().flatten() {
            match *piece {
                ChainPiece::Segment(j) => segment[j] = true,
                ChainPiece::Arc(k) => arc[k] = true,
            }
        }
    }
    (segment, arc)
}

/// An input error with the polygons and rings of the segments it names
/// added to its message (a ring that crosses itself or another ring, or
/// a ring segment that an obstacle overlaps).
pub(crate) fn name_rings(error: Error, rings: &[RingInput]) -> Error {
    if error.kind() != ErrorKind::Intersecting || rings.is_empty() {
        return error;
    }
    let ring_of = |j: usize| {
        rings.iter().find(|r| r.segments.contains(&j) || r.pieces.as_ref().is_some_and(|p| p.contains(&ChainPiece::Segment(j))))
    };
    let named: Vec<String> = error
        .indices()
        .iter()
        .filter_map(|&j| ring_of(j).map(|r| (j, r)))
        .map(|(j, r)| format!("segment {j} is in polygon {}, ring {}", r.polygon, r.ring))
        .collect();
    if named.is_empty() {
        return error;
    }
    let message = format!("{} ({})", error.message(), named.join("; "));
    Error::new(error.kind(), message, error.indices().to_vec())
}
