//! The rings of split polygons: the boundary of the even-odd region of the
//! input rings, as simple rings of pieces.
//!
//! A piece is on the boundary when it came from an odd number of ring
//! segments (two rings along one edge cancel, as the even-odd rule says).
//! Each input ring became a closed walk of pieces, so every point has an
//! even number of boundary pieces; pairing them in angular order at each
//! point and walking the pairs gives closed walks that touch but never
//! cross, and cutting a walk where it comes back to a point gives simple
//! rings. Any such decomposition bounds the same even-odd region.

use std::collections::HashMap;

use super::Piece;
use crate::construct::polygon_input::RingInput;
use crate::geometry::predicates::compare_directions;
use crate::geometry::Point;

/// The pieces reordered so that each ring's pieces come first, in ring
/// order and pointing along it, then the rest; and the rings over them.
pub(crate) fn split_rings(pieces: Vec<Piece>, rings: &[RingInput], input_segments: usize) -> (Vec<Piece>, Vec<RingInput>) {
    let mut ring_segment = vec![false; input_segments];
    for j in rings.iter().flat_map(|r| r.segments.clone()) {
        ring_segment[j] = true;
    }
    let in_ring = |i: u32| ring_segment[i as usize];
    let (boundary, rest): (Vec<Piece>, Vec<Piece>) =
        pieces.into_iter().partition(|p| p.ends[0] != p.ends[1] && p.origins.iter().filter(|&&i| in_ring(i)).count() % 2 == 1);
    let key = Point::bit_key;
    // per point, its boundary pieces (as (piece, whether it starts there))
    let mut at: HashMap<[u64; 2], Vec<(usize, bool)>> = HashMap::new();
    for (k, p) in boundary.iter().enumerate() {
        at.entry(key(p.ends[0])).or_default().push((k, true));
        at.entry(key(p.ends[1])).or_default().push((k, false));
    }
    // pair neighbours in (exact) angular order: (0, 1), (2, 3), ...
    let mut partner: HashMap<([u64; 2], usize), usize> = HashMap::new();
    for (point, list) in &mut at {
        let here = Point::new(f64::from_bits(point[0]), f64::from_bits(point[1]));
        let away = |&(k, starts): &(usize, bool)| boundary[k].ends[usize::from(starts)];
        list.sort_by(|x, y| compare_directions(here, away(x), away(y)));
        for pair in list.chunks(2) {
            if let [x, y] = pair {
                partner.insert((*point, x.0), y.0);
                partner.insert((*point, y.0), x.0);
            }
        }
    }
    let mut used = vec![false; boundary.len()];
    let mut ordered: Vec<Piece> = Vec::with_capacity(boundary.len() + rest.len());
    let mut out_rings = Vec::new();
    for start in 0..boundary.len() {
        if used[start] {
            continue;
        }
        // walk from `start` forwards, as points and pieces
        let mut walk: Vec<(Point, usize)> = Vec::new();
        let (mut k, mut from) = (start, boundary[start].ends[0]);
        while !used[k] {
            used[k] = true;
            let to = if boundary[k].ends[0] == from { boundary[k].ends[1] } else { boundary[k].ends[0] };
            walk.push((from, k));
            match partner.get(&(key(to), k)) {
                Some(&next) => (k, from) = (next, to),
                None => break, // an odd point: cannot happen for closed rings
            }
        }
        // cut the walk into simple rings where it comes back to a point
        let mut stack: Vec<(Point, usize)> = Vec::new();
        let mut seen: HashMap<[u64; 2], usize> = HashMap::new();
        for (point, piece) in walk {
            if let Some(&depth) = seen.get(&key(point)) {
                let ring: Vec<(Point, usize)> = stack.drain(depth..).collect();
                for (q, _) in &ring {
                    seen.remove(&key(*q));
                }
                emit(&ring, &boundary, &mut ordered, &mut out_rings);
            }
            seen.insert(key(point), stack.len());
            stack.push((point, piece));
        }
        emit(&stack, &boundary, &mut ordered, &mut out_rings);
    }
    ordered.extend(rest);
    (ordered, out_rings)
}

/// Appends one ring (its pieces, each from the point given) to the pieces
/// and the rings; fewer than three pieces make no ring.
fn emit(ring: &[(Point, usize)], boundary: &[Piece], ordered: &mut Vec<Piece>, rings: &mut Vec<RingInput>) {
    if ring.len() < 3 {
        ordered.extend(ring.iter().map(|&(_, k)| boundary[k].clone()));
        return;
    }
    let first = ordered.len();
    for &(from, k) in ring {
        let piece = &boundary[k];
        let ends = if piece.ends[0] == from { piece.ends } else { [piece.ends[1], piece.ends[0]] };
        ordered.push(Piece { ends, origins: piece.origins.clone() });
    }
    rings.push(RingInput { polygon: 0, ring: rings.len(), segments: first..ordered.len(), pieces: None });
}
