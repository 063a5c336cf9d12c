//! Polygon rings that share a stretch: two polygons of a MultiPolygon along
//! one border, a ring and its hole along one edge, a spike that runs out
//! and back along itself. The domain is the even-odd region of the rings,
//! in which two copies of one stretch cancel; so they are dropped, exactly,
//! and the domain is unchanged.
//!
//! # How
//! The input check allows ring segments to overlap each other
//! (`input_check`, `Normalised::may_overlap`) and splits them at every
//! input vertex inside them: the ends of a shared stretch are endpoints of
//! the segments sharing it, so after the split the stretch is made of equal
//! pieces, cut at the same input vertices, with nothing moved or rounded.
//! Pieces equal as point sets (either direction) form groups; a group of
//! `k` ring pieces leaves one piece when `k` is odd and none when it is
//! even. The pieces left bound the even-odd region of the input rings: at
//! every point an even number of them meet, so they are walked into simple
//! rings (touching at points, never crossing), as splitting crossings does
//! (`split::rings`). The diagram is then built of the pieces left and the
//! input points alone, so a vertex whose every piece cancelled is no site
//! (unless an input point lies there), and its domain is that of the new
//! rings.
//!
//! A piece that a ring and an obstacle (a polyline or free segment) both
//! made stays an obstacle when its ring copies cancel: it is still there.
//! Overlaps that involve anything but ring segments are refused by the
//! check, as before: an obstacle has no even-odd rule to say what two
//! copies mean.
//!
//! # Cost
//! Only inputs where two ring segments coincide, or where a ring segment is
//! split, pay anything beyond a pass over the input: the pieces are keyed
//! by their exact endpoints in a hash map. When pieces do cancel, the
//! diagram is built of the pieces left, and the points inserted for the
//! first attempt are dropped (about a third of a build, and only for such
//! input).

use std::collections::HashMap;

use super::input_check::{CheckedInput, Vertex};
use super::polygon_input::RingInput;
use super::split::{split_rings, Piece};
use crate::diagram::{Diagram, SplitPieces};
use crate::error::{Error, ErrorKind};
use crate::geometry::input::segment_contact::lex_cmp;
use crate::geometry::Point;

/// The pieces of the checked input (input coordinates, each input segment
/// cut at the input vertices inside it, equal pieces merged with all their
/// input segments), when two ring segments share a piece; `None` otherwise,
/// the common case, which the build handles as before. `ring` says per
/// input segment whether a ring made it (empty: no rings).
pub(super) fn shared_pieces(
    checked: &CheckedInput,
    points: &[Point],
    segments: &[[Point; 2]],
    ring: &[bool],
) -> Option<Vec<Piece>> {
    if ring.is_empty() {
        return None;
    }
    // Two ring segments that repeat one another share all of it; any other
    // shared stretch splits a ring segment. Neither: nothing to cancel.
    let mut has_ring = vec![false; checked.segments.len()];
    let mut repeated = false;
    for (j, kept) in checked.kept_of_input.iter().enumerate() {
        if let (Some(k), true) = (*kept, ring[j]) {
            repeated |= has_ring[k];
            has_ring[k] = true;
        }
    }
    if !repeated && checked.splits.iter().all(|s| !has_ring[s.segment]) {
        return None;
    }
    let pieces = pieces_of(checked, points, segments);
    let shared = pieces.iter().any(|p| ring_copies(p, ring) > 1);
    shared.then_some(pieces)
}

/// How many ring segments made piece `p`.
fn ring_copies(p: &Piece, ring: &[bool]) -> usize {
    p.origins.iter().filter(|&&j| ring[j as usize]).count()
}

/// Every input segment cut at the input vertices inside it, in input order
/// and each in its direction, equal pieces merged (the first keeps its
/// place and gains the later input segments). A zero-length input segment
/// is a zero-length piece, a point.
fn pieces_of(checked: &CheckedInput, points: &[Point], segments: &[[Point; 2]]) -> Vec<Piece> {
    let vertex = |v: Vertex| match v {
        Vertex::Point(i) => points[i].canonical_zero(),
        Vertex::End { segment, end } => segments[segment][end].canonical_zero(),
    };
    // per kept segment, its cut points from its lexicographically smaller
    // end (`splits` is sorted so)
    let mut cuts: Vec<Vec<Point>> = vec![Vec::new(); checked.segments.len()];
    for split in &checked.splits {
        cuts[split.segment].push(vertex(split.at));
    }
    let mut pieces: Vec<Piece> = Vec::with_capacity(segments.len() + checked.splits.len());
    let mut index: HashMap<[u64; 4], usize> = HashMap::with_capacity(pieces.capacity());
    let mut add = |ends: [Point; 2], j: usize| match index.entry(Point::segment_key(ends[0], ends[1])) {
        std::collections::hash_map::Entry::Occupied(e) => pieces[*e.get()].origins.push(j as u32),
        std::collections::hash_map::Entry::Vacant(e) => {
            e.insert(pieces.len());
            pieces.push(Piece { ends, origins: vec![j as u32] });
        }
    };
    for (j, s) in segments.iter().enumerate() {
        let [a, b] = s.map(Point::canonical_zero);
        let Some(k) = checked.kept_of_input[j] else {
            add([a, a], j);
            continue;
        };
        let mut chain = Vec::with_capacity(cuts[k].len() + 2);
        chain.push(a);
        if lex_cmp(a, b) == std::cmp::Ordering::Less {
            chain.extend(cuts[k].iter().copied());
        } else {
            chain.extend(cuts[k].iter().rev().copied());
        }
        chain.push(b);
        for w in chain.windows(2) {
            add([w[0], w[1]], j);
        }
    }
    pieces
}

/// The diagram when ring pieces cancel (`pieces` from [`shared_pieces`]):
/// the pieces left and `points`, with the domain of the rings they form.
/// Piece numbering as with `Builder::split_crossings`: the rings' pieces
/// first, ring by ring in ring order, then the other pieces; a cancelled
/// piece has no number, so an input segment that cancelled entirely has no
/// pieces (`Diagram::pieces_of_input` is empty).
pub(super) fn diagram_of_shared(
    points: &[Point],
    segments: &[[Point; 2]],
    rings: &[RingInput],
    checked: &CheckedInput,
    pieces: Vec<Piece>,
) -> Result<Diagram, Error> {
    // (the cancelled pieces are dropped there)
    let (pieces, rings_left, cancelled) = split_rings(pieces, rings, segments.len());
    let ends: Vec<[Point; 2]> = pieces.iter().map(|p| p.ends).collect();
    let mut diagram = super::diagram_of(points, &ends, &[]).map_err(|e| in_input_terms(e, &pieces))?;
    diagram.set_domain(&rings_left);
    let origins: Vec<Vec<u32>> = pieces.iter().map(|p| p.origins.clone()).collect();
    diagram.split = Some(Box::new(SplitPieces::new(&origins, segments.len(), 0.0, 0.0)));
    let stats = &mut diagram.stats;
    stats.input_segments = segments.len();
    stats.pieces = pieces.len();
    stats.duplicate_segments = checked.duplicate_segments;
    stats.zero_length_segments = checked.degenerate_segments;
    stats.split_at_vertices = checked.splits.len();
    stats.cancelled_ring_pieces = cancelled;
    Ok(diagram)
}

/// An error of the build of the pieces, as an internal error naming the
/// input segments of the pieces it names: the pieces meet only at their
/// endpoints (every vertex inside a segment was a cut), so no conflict is
/// expected.
fn in_input_terms(error: Error, pieces: &[Piece]) -> Error {
    let mut inputs: Vec<usize> =
        error.indices().iter().filter_map(|&k| pieces.get(k)).flat_map(|p| p.origins.iter().map(|&i| i as usize)).collect();
    inputs.sort_unstable();
    inputs.dedup();
    let message = match error.kind() {
        ErrorKind::Internal => error.message().to_string(),
        _ => format!(
            "construction could not complete: after cancelling shared stretches of rings, {} (pieces of input \
             segments {inputs:?}); please report this input",
            error.message()
        ),
    };
    Error::new(ErrorKind::Internal, message, inputs)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    /// Two unit squares side by side share the edge x = 1; a third
    /// segment overlaps part of it.
    #[test]
    fn equal_pieces_merge_with_all_their_segments() {
        let segments = [
            [p(0., 0.), p(1., 0.)],
            [p(1., 0.), p(1., 1.)],
            [p(1., 1.), p(0., 1.)],
            [p(0., 1.), p(0., 0.)],
            [p(1., 0.), p(2., 0.)],
            [p(2., 0.), p(2., 1.)],
            [p(2., 1.), p(1., 1.)],
            [p(1., 1.), p(1., 0.)],
        ];
        let ring = vec![true; segments.len()];
        let scale = super::super::input_scale(&[], &segments);
        let checked = super::super::input_check::check_segments(&[], &segments, &ring, scale).unwrap();
        let pieces = shared_pieces(&checked, &[], &segments, &ring).expect("a shared edge");
        assert_eq!(pieces.len(), 7);
        let shared: Vec<&Piece> = pieces.iter().filter(|p| p.origins.len() > 1).collect();
        assert_eq!(shared.len(), 1);
        assert_eq!(shared[0].origins, vec![1, 7]);
        assert!(shared_pieces(&checked, &[], &segments, &[]).is_none(), "no rings: nothing cancels");
    }

    /// A square with a spike up from (3, 4) to (3, 6) that comes back
    /// only to (3, 5): the overlap is cut at (3, 5).
    #[test]
    fn a_partial_overlap_is_split_at_its_ends() {
        let ring = [p(0., 0.), p(4., 0.), p(4., 4.), p(3., 4.), p(3., 6.), p(3., 5.), p(1., 4.), p(0., 4.)];
        let segments: Vec<[Point; 2]> = (0..ring.len()).map(|k| [ring[k], ring[(k + 1) % ring.len()]]).collect();
        let mask = vec![true; segments.len()];
        let scale = super::super::input_scale(&[], &segments);
        let checked = super::super::input_check::check_segments(&[], &segments, &mask, scale).unwrap();
        let pieces = shared_pieces(&checked, &[], &segments, &mask).expect("a shared stretch");
        let shared: Vec<[Point; 2]> = pieces.iter().filter(|p| p.origins.len() == 2).map(|p| p.ends).collect();
        assert_eq!(shared.len(), 1);
        assert_eq!(Point::segment_key(shared[0][0], shared[0][1]), Point::segment_key(p(3., 5.), p(3., 6.)));
    }
}
