//! The rings of split polygons: the boundary of the even-odd region of the
//! input rings, as simple rings of pieces.
//!
//! A piece is on the boundary when it came from an odd number of ring
//! pieces (two rings along one edge cancel, as the even-odd rule says).
//! Each input ring became a closed walk of pieces, so every point has an
//! even number of boundary pieces; pairing them in angular order at each
//! point and walking the pairs gives closed walks that touch but never
//! cross, and cutting a walk where it comes back to a point gives simple
//! rings. Any such decomposition bounds the same even-odd region.
//!
//! The walk ([`closed_walks`]) sees only the pieces' ends and their order
//! around each point, so segments (`split_rings`) and segments with arcs
//! (`split_rings_with_arcs`, where an arc leaves its end along its
//! tangent) share it.

use std::collections::HashMap;

use super::arcs::ArcPiece;
use super::Piece;
use crate::construct::polygon_input::{ring_inputs, ChainPiece, RingInput};
use crate::geometry::arcs::exact_join::compare_leaving;
use crate::geometry::predicates::compare_directions;
use crate::geometry::{Point, Site};

/// A piece's end as the walk meets it: the piece (an index into the
/// boundary pieces) and whether the piece starts there.
type PieceEnd = (usize, bool);

/// The simple closed walks over the boundary pieces with ends `ends`, each
/// as its pieces in walking order with whether each is walked forward
/// (from `ends[0]`). `sort_around(point, list)` sorts the pieces' ends at
/// `point` counter-clockwise. Every point must hold an even number of ends.
fn closed_walks(ends: &[[Point; 2]], sort_around: impl Fn(Point, &mut [PieceEnd])) -> Vec<Vec<PieceEnd>> {
    // (an arc's end may be -0.0 where a segment's is 0.0: one point)
    let key = |p: Point| p.canonical_zero().bit_key();
    let mut at: HashMap<[u64; 2], Vec<PieceEnd>> = HashMap::new();
    for (k, e) in ends.iter().enumerate() {
        at.entry(key(e[0])).or_default().push((k, true));
        at.entry(key(e[1])).or_default().push((k, false));
    }
    // pair neighbours in angular order: (0, 1), (2, 3), ...
    let mut partner: HashMap<([u64; 2], usize), usize> = HashMap::new();
    for (point, list) in &mut at {
        sort_around(Point::new(f64::from_bits(point[0]), f64::from_bits(point[1])), list);
        for pair in list.chunks(2) {
            if let [x, y] = pair {
                partner.insert((*point, x.0), y.0);
                partner.insert((*point, y.0), x.0);
            }
        }
    }
    let mut used = vec![false; ends.len()];
    let mut walks = Vec::new();
    for start in 0..ends.len() {
        if used[start] {
            continue;
        }
        // walk from `start` forwards, as points and pieces
        let mut walk: Vec<(Point, PieceEnd)> = Vec::new();
        let (mut k, mut from) = (start, ends[start][0]);
        while !used[k] {
            used[k] = true;
            let forward = ends[k][0] == from;
            let to = ends[k][usize::from(forward)];
            walk.push((from, (k, forward)));
            match partner.get(&(key(to), k)) {
                Some(&next) => (k, from) = (next, to),
                None => break, // an odd point: cannot happen for closed rings
            }
        }
        // cut the walk into simple walks where it comes back to a point
        let mut stack: Vec<(Point, PieceEnd)> = Vec::new();
        let mut seen: HashMap<[u64; 2], usize> = HashMap::new();
        for (point, piece) in walk {
            if let Some(&depth) = seen.get(&key(point)) {
                let ring: Vec<(Point, PieceEnd)> = stack.drain(depth..).collect();
                for (q, _) in &ring {
                    seen.remove(&key(*q));
                }
                walks.push(ring.into_iter().map(|(_, p)| p).collect());
            }
            seen.insert(key(point), stack.len());
            stack.push((point, piece));
        }
        walks.push(stack.into_iter().map(|(_, p)| p).collect());
    }
    walks
}

/// Whether a piece came from an odd number of ring pieces (`in_ring`).
fn odd(origins: &[u32], in_ring: &[bool]) -> bool {
    origins.iter().filter(|&&i| in_ring[i as usize]).count() % 2 == 1
}

/// Whether a piece of nonzero length cancelled: every input it came from
/// is a ring's, an even number of them, so it bounds nothing and is no
/// obstacle either. It is dropped, as the strict build drops shared
/// stretches (`construct::shared_stretches`); a piece that an obstacle
/// also made stays, as that obstacle.
fn cancelled(origins: &[u32], in_ring: &[bool]) -> bool {
    !odd(origins, in_ring) && origins.iter().all(|&i| in_ring[i as usize])
}

/// How many ring copies cancelled among pieces with these `origins`: of
/// `k` ring copies of one piece, `k` when even, `k - 1` when odd (the one
/// left bounds the domain).
fn cancelled_copies<'a>(origins: impl Iterator<Item = &'a [u32]>, in_ring: &[bool]) -> usize {
    origins.map(|o| o.iter().filter(|&&i| in_ring[i as usize]).count()).filter(|&k| k > 1).map(|k| k - k % 2).sum()
}

/// The pieces reordered so that each ring's pieces come first, in ring
/// order and pointing along it, then the rest (without the pieces that
/// cancelled, `cancelled`); the rings over them; and how many ring
/// copies cancelled (`cancelled_copies`).
pub(crate) fn split_rings(pieces: Vec<Piece>, rings: &[RingInput], input_segments: usize) -> (Vec<Piece>, Vec<RingInput>, usize) {
    let (ring_segment, _) = ring_inputs(rings, input_segments, 0);
    let cancelled_pieces = cancelled_copies(pieces.iter().map(|p| &p.origins[..]), &ring_segment);
    let (boundary, mut rest): (Vec<Piece>, Vec<Piece>) =
        pieces.into_iter().partition(|p| p.ends[0] != p.ends[1] && odd(&p.origins, &ring_segment));
    rest.retain(|p| p.ends[0] == p.ends[1] || !cancelled(&p.origins, &ring_segment));
    let ends: Vec<[Point; 2]> = boundary.iter().map(|p| p.ends).collect();
    let away = |&(k, starts): &PieceEnd| ends[k][usize::from(starts)];
    let walks = closed_walks(&ends, |here, list| list.sort_by(|x, y| compare_directions(here, away(x), away(y))));
    let mut ordered: Vec<Piece> = Vec::with_capacity(boundary.len() + rest.len());
    let mut out_rings = Vec::new();
    for walk in walks {
        let first = ordered.len();
        ordered.extend(walk.iter().map(|&(k, forward)| {
            let piece = &boundary[k];
            let ends = if forward { piece.ends } else { [piece.ends[1], piece.ends[0]] };
            Piece { ends, origins: piece.origins.clone() }
        }));
        // (fewer than three pieces make no ring)
        if walk.len() >= 3 {
            out_rings.push(RingInput { polygon: 0, ring: out_rings.len(), segments: first..ordered.len(), pieces: None });
        }
    }
    ordered.extend(rest);
    (ordered, out_rings, cancelled_pieces)
}

/// The rings of split polygons with arcs: the boundary pieces among the
/// segment `pieces` and the `arcs` (each from an odd number of the input
/// rings' segments or arcs) turned to point along their ring, and the
/// rings over them as chains of pieces (`ChainPiece` indices into the
/// pieces and arcs as returned, without those that cancelled, see
/// `cancelled`); and how many ring copies cancelled. A ring of two
/// pieces, one of them an arc, is a ring.
pub(crate) fn split_rings_with_arcs(
    mut pieces: Vec<Piece>,
    mut arcs: Vec<ArcPiece>,
    rings: &[RingInput],
    input_segments: usize,
    input_arcs: usize,
) -> (Vec<Piece>, Vec<ArcPiece>, Vec<RingInput>, usize) {
    let (ring_segment, ring_arc) = ring_inputs(rings, input_segments, input_arcs);
    let cancelled_pieces = cancelled_copies(pieces.iter().map(|p| &p.origins[..]), &ring_segment)
        + cancelled_copies(arcs.iter().map(|a| &a.origins[..]), &ring_arc);
    pieces.retain(|p| p.ends[0] == p.ends[1] || !cancelled(&p.origins, &ring_segment));
    arcs.retain(|a| !cancelled(&a.origins, &ring_arc));
    // the boundary, as chain pieces and sites
    let mut boundary: Vec<(ChainPiece, Site)> = Vec::new();
    for (k, p) in pieces.iter().enumerate() {
        if p.ends[0] != p.ends[1] && odd(&p.origins, &ring_segment) {
            boundary.push((ChainPiece::Segment(k), Site::Segment { a: p.ends[0], b: p.ends[1] }));
        }
    }
    for (k, a) in arcs.iter().enumerate() {
        if odd(&a.origins, &ring_arc) {
            boundary.push((ChainPiece::Arc(k), Site::Arc(a.arc)));
        }
    }
    let ends: Vec<[Point; 2]> = boundary.iter().map(|(_, site)| site.ends()).collect();
    let walks = closed_walks(&ends, |here, list| {
        list.sort_by(|&(x, _), &(y, _)| {
            compare_leaving(&boundary[x].1, &boundary[y].1, here)
                .unwrap_or_else(|| leaving_angle(&boundary[x].1, here).total_cmp(&leaving_angle(&boundary[y].1, here)))
        })
    });
    let mut out_rings = Vec::new();
    for walk in walks {
        let has_arc = walk.iter().any(|&(k, _)| matches!(boundary[k].0, ChainPiece::Arc(_)));
        if walk.len() < 3 && !(walk.len() == 2 && has_arc) {
            continue;
        }
        let chain: Vec<ChainPiece> = walk.iter().map(|&(k, _)| boundary[k].0).collect();
        // each piece from its corner to the next
        for &(k, _) in walk.iter().filter(|(_, forward)| !forward) {
            match boundary[k].0 {
                ChainPiece::Segment(j) => pieces[j].ends.reverse(),
                ChainPiece::Arc(j) => arcs[j].arc = arcs[j].arc.reversed(),
            }
        }
        out_rings.push(RingInput { polygon: 0, ring: out_rings.len(), segments: 0..0, pieces: Some(chain) });
    }
    (pieces, arcs, out_rings, cancelled_pieces)
}

/// The angle in `[0, 2π)` at which `site` leaves its endpoint `end`, in
/// floating point: the order around a point where the exact one is out of
/// range.
fn leaving_angle(site: &Site, end: Point) -> f64 {
    let d = match *site {
        Site::Segment { a, b } => {
            let to = if a == end { b } else { a };
            Point::new(to.x - end.x, to.y - end.y)
        }
        Site::Arc(arc) => arc.tangent_into(end),
        Site::Point(_) => Point::new(1.0, 0.0),
    };
    let angle = d.y.atan2(d.x);
    if angle < 0.0 {
        angle + std::f64::consts::TAU
    } else {
        angle
    }
}
