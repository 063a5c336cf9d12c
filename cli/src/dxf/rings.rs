//! Closed rings out of LINE and ARC entities: a part drawn piece by piece
//! bounds a domain as a closed LWPOLYLINE does.
//!
//! Each piece is its two ends and its bulge (0 for a LINE; an ARC's, from
//! its first end to its second). After snapping, pieces that meet share
//! their endpoints exactly. Where every point of a connected group of
//! pieces ends an even number of them, the group splits into simple closed
//! rings (each point once per ring; the even-odd domain is the same
//! however it splits); any other group stays separate pieces (obstacles).
//! Pieces of zero length, and second copies of a piece (drawn twice,
//! common in CAD files; by the even-odd rule two copies would cancel), are
//! dropped; two arcs between the same points that bulge differently (a
//! circle drawn as two ARCs) are two pieces.

use std::collections::{HashMap, HashSet};

use crate::wkt::Xy;

/// A ring: its points in order (not repeating the first), each with the
/// bulge of the piece from it to the next, and the pieces (indices into
/// the slice given to [`rings`]) it is made of, in the same order.
#[derive(Clone, Debug, PartialEq)]
pub struct Ring {
    pub points: Vec<(Xy, f64)>,
    pub lines: Vec<usize>,
}

/// What became of the pieces.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Joined {
    pub rings: Vec<Ring>,
    /// The pieces left as they are.
    pub loose: Vec<usize>,
    /// The pieces dropped: zero length or a repeat.
    pub dropped: Vec<usize>,
}

/// An exact key for a point (`-0` as `0`).
fn key(p: Xy) -> (u64, u64) {
    ((p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits())
}

/// Splits `pieces` (ends and bulge) into closed rings and loose pieces.
pub fn rings(pieces: &[([Xy; 2], f64)]) -> Joined {
    let mut joined = Joined::default();
    // the vertices, numbered, and the pieces kept as vertex pairs with
    // their bulge from the first to the second
    let mut ids: HashMap<(u64, u64), usize> = HashMap::new();
    let mut points: Vec<Xy> = Vec::new();
    let mut seen: HashSet<(usize, usize, u64)> = HashSet::new();
    let mut edges: Vec<(usize, [usize; 2], f64)> = Vec::new();
    for (k, &([a, b], bulge)) in pieces.iter().enumerate() {
        let mut id = |p: Xy| {
            *ids.entry(key(p)).or_insert_with(|| {
                points.push(p);
                points.len() - 1
            })
        };
        let (u, v) = (id(a), id(b));
        // the same piece drawn either way round: its bulge from the lower vertex
        let forward = if u < v { bulge } else { -bulge };
        if u == v || !seen.insert((u.min(v), u.max(v), (forward + 0.0).to_bits())) {
            joined.dropped.push(k);
            continue;
        }
        edges.push((k, [u, v], bulge));
    }
    let mut incident: Vec<Vec<usize>> = vec![Vec::new(); points.len()];
    for (e, (_, [u, v], _)) in edges.iter().enumerate() {
        incident[*u].push(e);
        incident[*v].push(e);
    }
    // the connected groups, by union-find over the vertices
    let mut parent: Vec<usize> = (0..points.len()).collect();
    fn root(parent: &mut [usize], mut x: usize) -> usize {
        while parent[x] != x {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        x
    }
    for (_, [u, v], _) in &edges {
        let (a, b) = (root(&mut parent, *u), root(&mut parent, *v));
        parent[a] = b;
    }
    let mut odd_group: HashSet<usize> = HashSet::new();
    for (v, list) in incident.iter().enumerate() {
        if list.len() % 2 == 1 {
            odd_group.insert(root(&mut parent, v));
        }
    }
    let mut used = vec![false; edges.len()];
    for e in 0..edges.len() {
        let group = root(&mut parent, edges[e].1[0]);
        if odd_group.contains(&group) {
            joined.loose.push(edges[e].0);
            used[e] = true;
            continue;
        }
        if !used[e] {
            walk(edges[e].1[0], &edges, &incident, &mut used, &points, &mut joined.rings);
        }
    }
    joined.loose.sort_unstable();
    joined
}

/// Walks unused edges from `start` (in a group where every vertex has an
/// even degree, so a walk can only stop where it began), cutting off a
/// simple ring each time the walk comes back to a vertex on its path.
fn walk(
    start: usize,
    edges: &[(usize, [usize; 2], f64)],
    incident: &[Vec<usize>],
    used: &mut [bool],
    points: &[Xy],
    out: &mut Vec<Ring>,
) {
    let mut path: Vec<usize> = vec![start];
    // each edge walked, with its bulge the way it is walked
    let mut path_edges: Vec<(usize, f64)> = Vec::new();
    let mut on_path: HashMap<usize, usize> = HashMap::from([(start, 0)]);
    loop {
        let v = *path.last().expect("the path keeps its start");
        let Some(&e) = incident[v].iter().find(|&&e| !used[e]) else { break };
        used[e] = true;
        let (_, [a, b], bulge) = edges[e];
        let (w, bulge) = if a == v { (b, bulge) } else { (a, -bulge) };
        path_edges.push((e, bulge));
        if let Some(&at) = on_path.get(&w) {
            // path[at..] and back to w: a simple ring
            let ring_points: Vec<(Xy, f64)> =
                path[at..].iter().zip(&path_edges[at..]).map(|(&p, &(_, b))| (points[p], b)).collect();
            let lines: Vec<usize> = path_edges[at..].iter().map(|&(e, _)| edges[e].0).collect();
            for &p in &path[at + 1..] {
                on_path.remove(&p);
            }
            path.truncate(at + 1);
            path_edges.truncate(at);
            out.push(Ring { points: ring_points, lines });
        } else {
            on_path.insert(w, path.len());
            path.push(w);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn straight(lines: &[[Xy; 2]]) -> Vec<([Xy; 2], f64)> {
        lines.iter().map(|&ends| (ends, 0.0)).collect()
    }

    #[test]
    fn a_slot_of_lines_and_arcs_and_a_circle_of_two_arcs() {
        let pieces = [
            // the slot, its arcs drawn counter-clockwise as ARCs are, its
            // lower side backwards
            ([[4.0, 0.0], [0.0, 0.0]], 0.0),
            ([[4.0, 0.0], [4.0, 2.0]], 1.0),
            ([[4.0, 2.0], [0.0, 2.0]], 0.0),
            ([[0.0, 2.0], [0.0, 0.0]], 1.0),
            // a circle: two half circles between the same points
            ([[10.0, 0.0], [12.0, 0.0]], 1.0),
            ([[12.0, 0.0], [10.0, 0.0]], 1.0),
            // the slot's arc again, drawn the other way round: a repeat
            ([[4.0, 2.0], [4.0, 0.0]], -1.0),
        ];
        let joined = rings(&pieces);
        assert_eq!(joined.dropped, [6]);
        assert_eq!(joined.rings.len(), 2, "{joined:?}");
        let slot = joined.rings.iter().find(|r| r.points.len() == 4).unwrap();
        // walked one way round: each arc's bulge the way it is walked
        let arcs: Vec<f64> = slot.points.iter().map(|&(_, b)| b).filter(|&b| b != 0.0).collect();
        assert!(arcs == [1.0, 1.0] || arcs == [-1.0, -1.0], "{slot:?}");
        let circle = joined.rings.iter().find(|r| r.points.len() == 2).unwrap();
        assert!(circle.points.iter().all(|&(_, b)| b == circle.points[0].1), "{circle:?}");
    }

    #[test]
    fn a_square_of_four_lines_in_any_order_and_direction() {
        let lines = [
            [[0.0, 0.0], [1.0, 0.0]],
            [[0.0, 1.0], [1.0, 1.0]],
            [[1.0, 1.0], [1.0, 0.0]],
            [[0.0, 0.0], [0.0, 1.0]],
            // a loose one, and zero length, and a repeat
            [[5.0, 5.0], [6.0, 5.0]],
            [[2.0, 2.0], [2.0, 2.0]],
            [[1.0, 0.0], [0.0, 0.0]],
        ];
        let joined = rings(&straight(&lines));
        assert_eq!(joined.rings.len(), 1);
        let mut made = joined.rings[0].lines.clone();
        made.sort_unstable();
        assert_eq!(made, [0, 1, 2, 3]);
        assert_eq!(joined.rings[0].points.len(), 4);
        assert_eq!((joined.loose, joined.dropped), (vec![4], vec![5, 6]));
    }

    #[test]
    fn two_squares_sharing_a_corner_are_two_simple_rings() {
        let square = |x: f64, y: f64| {
            vec![
                [[x, y], [x + 1.0, y]],
                [[x + 1.0, y], [x + 1.0, y + 1.0]],
                [[x + 1.0, y + 1.0], [x, y + 1.0]],
                [[x, y + 1.0], [x, y]],
            ]
        };
        let mut lines = square(0.0, 0.0);
        lines.extend(square(1.0, 1.0));
        let joined = rings(&straight(&lines));
        assert_eq!(joined.rings.len(), 2, "{joined:?}");
        for ring in &joined.rings {
            assert_eq!(ring.points.len(), 4);
            let distinct: HashSet<(u64, u64)> = ring.points.iter().map(|&(p, _)| key(p)).collect();
            assert_eq!(distinct.len(), 4);
        }
        assert!(joined.loose.is_empty());
    }

    #[test]
    fn an_open_chain_stays_loose() {
        let lines = [[[0.0, 0.0], [1.0, 0.0]], [[1.0, 0.0], [1.0, 1.0]]];
        let joined = rings(&straight(&lines));
        assert!(joined.rings.is_empty());
        assert_eq!(joined.loose, [0, 1]);
    }
}
