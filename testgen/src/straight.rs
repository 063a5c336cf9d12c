//! Straight and nearly straight vertices, as users' inputs have them: a
//! transform of any family's segments or rings that cuts edges at points
//! exactly on them (a vertex where a chain goes on straight), or cuts them
//! there and then moves each cut point one ulp off the line (nearly
//! straight), plus the touching-rings generator.
//!
//! A cut point is exact when the orientation of the edge's endpoints and
//! the point is exactly zero ([`crate::exact::orient`]); candidates that
//! are not are dropped, never kept rounded. Candidates are the points at
//! parameters `k / 2^m` (`m <= MAX_PARAMETER_BITS`, `k` odd) along the edge,
//! computed in `f64`: exact when the endpoints lie on a dyadic grid a few
//! dozen bits coarse relative to the input's extent. Inputs with random
//! floating-point corners do not, so [`Straight::snap_bits`] first rounds
//! every coordinate to such a grid (the same value to the same grid point,
//! so shared endpoints stay shared), finer until the snapped input is still
//! legal; inputs on coarse grids (integers, font units) are left as they
//! are.
//!
//! Usable by every family (`FAMILY+straight` and the other variants of
//! [`VARIANTS`] in [`crate::generate`] and
//! [`crate::rings::generate_rings`]) and by the cargo tests ([`cut_segments`],
//! [`cut_rings`]).

use crate::exact::{orient, same_point, segments_conflict, SegmentGrid};
use crate::{next_after, Point, Rng, Segment};
use std::collections::HashMap;

/// Cut points are at parameters `k / 2^m` with `m` at most this.
pub const MAX_PARAMETER_BITS: u32 = 8;

/// The variants every chain or ring family gets, as suffixes of its name
/// (`polyline+straight`), with their cut options:
///
/// - `+straight`: about half the edges (each by a coin of the seeded
///   generator) cut at 1 to 3 exact points; an open chain's end edges
///   always, one point 2^-m from the free end (straight vertices at the
///   tips);
/// - `+nudged`: the same, every cut point then moved one ulp off the line,
///   to either side (nearly straight vertices);
/// - `+runs`: about a quarter of the edges cut at 4 to 16 exact points
///   (chains that run straight through many vertices);
/// - `+runs-nudged`: the same, moved one ulp each.
pub const VARIANTS: &[(&str, Straight)] = &[
    ("+straight", Straight { share: 0.5, min_cuts: 1, max_cuts: 3, nudge: false, snap_bits: 36 }),
    ("+nudged", Straight { share: 0.5, min_cuts: 1, max_cuts: 3, nudge: true, snap_bits: 36 }),
    ("+runs", Straight { share: 0.25, min_cuts: 4, max_cuts: 16, nudge: false, snap_bits: 36 }),
    ("+runs-nudged", Straight { share: 0.25, min_cuts: 4, max_cuts: 16, nudge: true, snap_bits: 36 }),
];

/// How edges are cut.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Straight {
    /// The chance that an edge is cut.
    pub share: f64,
    /// Cut points per cut edge, drawn in `min_cuts..=max_cuts` (fewer
    /// where an edge has fewer exact candidates).
    pub min_cuts: usize,
    pub max_cuts: usize,
    /// Move every cut point one ulp off the edge's line afterwards.
    pub nudge: bool,
    /// The grid the input is snapped to first: `2^-snap_bits` of the
    /// power of two above its extent (made finer, up to 44 bits, while
    /// snapping makes the input illegal; `0`: no snapping).
    pub snap_bits: u32,
}

/// The family name without its variant suffix, and the variant.
pub fn split_variant(family: &str) -> (&str, Option<Straight>) {
    for (suffix, straight) in VARIANTS {
        if let Some(base) = family.strip_suffix(suffix) {
            return (base, Some(*straight));
        }
    }
    (family, None)
}

/// The generator of a variant's cuts: its own stream, so that the base
/// input is the family's own.
pub fn variant_rng(seed: u64) -> Rng {
    Rng(seed ^ 0x5354_5241_4947_4854) // "STRAIGHT"
}

/// Whether no two of `segments` conflict (exactly; see
/// [`crate::exact::segments_conflict`]) and none has zero length.
pub fn legal(segments: &[Segment]) -> bool {
    if segments.iter().any(|s| same_point(s[0], s[1])) {
        return false;
    }
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in segments.iter().flatten() {
        lo = [lo[0].min(p[0]), lo[1].min(p[1])];
        hi = [hi[0].max(p[0]), hi[1].max(p[1])];
    }
    let mut grid = SegmentGrid::new(lo, hi, SegmentGrid::side_for(segments.len()));
    for (i, &s) in segments.iter().enumerate() {
        if grid.any_near(s, |id| segments_conflict(s, segments[id])) {
            return false;
        }
        grid.add(s, i);
    }
    true
}

/// `v` rounded to a multiple of `unit` (a power of two).
fn snap_value(v: f64, unit: f64) -> f64 {
    (v / unit).round() * unit
}

/// The grid unit for `bits` below the power of two above the extent of
/// `points`.
fn grid_unit<'a>(points: impl Iterator<Item = &'a Point>, bits: u32) -> f64 {
    let largest = points.flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    if largest == 0.0 {
        return 1.0;
    }
    let exponent = largest.log2().ceil() as i32;
    crate::power_of_two((exponent - bits as i32).max(-1022))
}

/// `segments` snapped to the coarsest grid of `bits..=44` bits that keeps
/// them legal, or as they are when none does (or `bits` is 0, or they are on
/// such a grid already).
pub fn snap_segments(segments: &[Segment], bits: u32) -> Vec<Segment> {
    if bits == 0 {
        return segments.to_vec();
    }
    let mut b = bits;
    while b <= 44 {
        let unit = grid_unit(segments.iter().flatten(), b);
        let snapped: Vec<Segment> = segments.iter().map(|s| s.map(|p| p.map(|v| snap_value(v, unit)))).collect();
        if snapped == segments || legal(&snapped) {
            return snapped;
        }
        b += 4;
    }
    segments.to_vec()
}

/// Up to `count` distinct exact cut points strictly inside the edge
/// `a`-`b`, in order from `a` to `b`; with `near_a`, one of them at
/// `2^-m` of the edge from `a` (the largest `m` that is exact).
pub fn exact_cut_points(a: Point, b: Point, count: usize, near_a: bool, rng: &mut Rng) -> Vec<Point> {
    let at = |t: f64| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
    let inside = |p: Point| {
        !same_point(p, a)
            && !same_point(p, b)
            && orient(a, b, p) == 0
            && (p[0] - a[0]) * (b[0] - a[0]) + (p[1] - a[1]) * (b[1] - a[1]) > 0.0
            && (p[0] - b[0]) * (a[0] - b[0]) + (p[1] - b[1]) * (a[1] - b[1]) > 0.0
    };
    let mut params: Vec<f64> = Vec::new();
    if near_a {
        for m in (1..=MAX_PARAMETER_BITS).rev() {
            let t = crate::power_of_two(-(m as i32));
            if inside(at(t)) {
                params.push(t);
                break;
            }
        }
    }
    for _ in 0..8 * count {
        if params.len() >= count {
            break;
        }
        let m = 1 + rng.below(MAX_PARAMETER_BITS as usize) as u32;
        let k = 2 * rng.below(1 << (m - 1)) + 1; // odd, below 2^m
        let t = k as f64 / (1u64 << m) as f64;
        if !params.contains(&t) && inside(at(t)) {
            params.push(t);
        }
    }
    params.sort_by(f64::total_cmp);
    let mut points: Vec<Point> = params.into_iter().map(at).collect();
    points.dedup();
    points
}

/// `p` (on the line of `a`-`b`) moved by one ulp off that line: the
/// coordinate across the edge's main direction (the other one where that
/// is zero), up or down by the coin. `None` when that stays on the line,
/// or both coordinates are zero.
fn nudge(a: Point, b: Point, p: Point, rng: &mut Rng) -> Option<Point> {
    let up = rng.below(2) == 0;
    let mut across = if (b[0] - a[0]).abs() >= (b[1] - a[1]).abs() { 1 } else { 0 };
    // an ulp of zero is a subnormal (the search's subnormal kinds cover
    // those): the other coordinate, or no nudge
    if p[across] == 0.0 {
        across = 1 - across;
        if p[across] == 0.0 {
            return None;
        }
    }
    let mut q = p;
    q[across] = next_after(p[across], up);
    (orient(a, b, q) != 0).then_some(q)
}

/// The interior points of one edge `a`-`b` under `straight` (empty when
/// the coin says not to cut it); `tip_at_a`: `a` is a free end of an open
/// chain, so the edge is always cut and one point is near `a`.
fn edge_cuts(a: Point, b: Point, straight: &Straight, tip_at_a: bool, rng: &mut Rng) -> Vec<Point> {
    let cut = rng.unit() < straight.share;
    if !cut && !tip_at_a {
        return Vec::new();
    }
    let count = straight.min_cuts + rng.below(straight.max_cuts - straight.min_cuts + 1);
    let mut points = exact_cut_points(a, b, count, tip_at_a, rng);
    if straight.nudge {
        for p in points.iter_mut() {
            if let Some(q) = nudge(a, b, *p, rng) {
                *p = q;
            }
        }
    }
    points
}

/// Every segment of `segments` (after snapping) cut as `straight` says,
/// each cut segment replaced by its pieces in order, in place. A segment
/// with an endpoint no other segment has (the free end of an open chain)
/// is always cut, once near that end. When the nudged pieces would make
/// the input illegal (a point an ulp from another segment), the cuts are
/// made again without nudging.
pub fn cut_segments(segments: &[Segment], straight: &Straight, rng: &mut Rng) -> Vec<Segment> {
    let snapped = snap_segments(segments, straight.snap_bits);
    let mut degree: HashMap<[u64; 2], usize> = HashMap::new();
    let key = |p: Point| [p[0].to_bits(), p[1].to_bits()];
    for p in snapped.iter().flatten() {
        *degree.entry(key(*p)).or_default() += 1;
    }
    let is_tip = |p: Point| degree[&key(p)] == 1;
    let pieces = |a: Point, b: Point, cuts: &[Point]| -> Vec<Segment> {
        let corners: Vec<Point> = std::iter::once(a).chain(cuts.iter().copied()).chain(std::iter::once(b)).collect();
        corners.windows(2).map(|w| [w[0], w[1]]).collect()
    };
    let mut per_edge: Vec<Vec<Segment>> = Vec::with_capacity(snapped.len());
    for &[a, b] in &snapped {
        // a tip at b: cut from b's side, then reversed
        let edge = if is_tip(b) && !is_tip(a) {
            let mut cuts = edge_cuts(b, a, straight, true, rng);
            cuts.reverse();
            pieces(a, b, &cuts)
        } else {
            pieces(a, b, &edge_cuts(a, b, straight, is_tip(a), rng))
        };
        per_edge.push(edge);
    }
    let flat: Vec<Segment> = per_edge.into_iter().flatten().collect();
    if straight.nudge && !legal(&flat) {
        // rare (a cut point an ulp from another segment): exact cuts instead
        let exact = Straight { nudge: false, ..*straight };
        return cut_segments(segments, &exact, rng);
    }
    flat
}

/// Every ring of `rings` (closed: the last corner joins the first; after
/// snapping) with its edges cut as `straight` says, the cut points inserted
/// as corners. Rings have no free ends.
pub fn cut_rings(rings: &[Vec<Point>], straight: &Straight, rng: &mut Rng) -> Vec<Vec<Point>> {
    let segments = crate::rings::ring_segments(rings);
    let snapped = snap_segments(&segments, straight.snap_bits);
    let mut result = Vec::with_capacity(rings.len());
    let mut k = 0;
    for ring in rings {
        let mut out = Vec::new();
        for _ in 0..ring.len() {
            let [a, b] = snapped[k];
            k += 1;
            out.push(a);
            out.extend(edge_cuts(a, b, straight, false, rng));
        }
        result.push(out);
    }
    if straight.nudge && !legal(&crate::rings::ring_segments(&result)) {
        // rare (a corner an ulp from another ring): the exact cuts instead
        let exact = Straight { nudge: false, ..*straight };
        return cut_rings(rings, &exact, rng);
    }
    result
}

/// The rings with every corner of a ring that lies inside a side of
/// another (a T-junction, exact test) inserted there as a corner of that
/// side too, in order along it: what the library's exact split makes of
/// touching rings, as input CGAL's segment Delaunay graph (which takes
/// shared endpoints, not T-junctions) takes as well
/// (`rings-touching-split`).
pub fn split_at_corners(rings: &[Vec<Point>]) -> Vec<Vec<Point>> {
    let corners: Vec<Point> = rings.iter().flatten().copied().collect();
    rings
        .iter()
        .map(|ring| {
            let mut out = Vec::new();
            for k in 0..ring.len() {
                let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
                out.push(a);
                let mut inside: Vec<Point> =
                    corners.iter().copied().filter(|&c| crate::exact::in_open_segment([a, b], c)).collect();
                let along = |p: &Point| (p[0] - a[0]).abs() + (p[1] - a[1]).abs();
                inside.sort_by(|p, q| along(p).total_cmp(&along(q)));
                inside.dedup();
                out.extend(inside);
            }
            out
        })
        .collect()
}

/// `rings-touching`: rings that touch each other at single points, as
/// users' polygons do (a hole whose corner lies on the outer ring, two
/// holes sharing a corner). The outer ring is the square `[0, 2m]^2` with
/// `m` about `sqrt(n / 4)`; the holes are diamonds around the centres
/// `(2i + 1, 2j + 1)` of a seeded share (60 %) of the cells, with the four
/// corners `(2i + 1 +- 1, 2j + 1)`, `(2i + 1, 2j + 1 +- 1)`: neighbouring
/// diamonds share a corner, and a diamond in an edge cell touches the
/// outer square with a corner inside one of its sides (a T-junction:
/// legal only where the library splits such contacts). Integer
/// coordinates, exactly degenerate (every diamond's cell is cocircular).
/// The domain is the even-odd region.
pub fn touching_rings(n: usize, rng: &mut Rng) -> Vec<Vec<Point>> {
    let mut m = 1;
    while 4 * (m + 1) * (m + 1) <= n {
        m += 1;
    }
    let side = (2 * m) as f64;
    let mut rings = vec![vec![[0.0, 0.0], [side, 0.0], [side, side], [0.0, side]]];
    for i in 0..m {
        for j in 0..m {
            if rng.unit() < 0.6 {
                let (cx, cy) = ((2 * i + 1) as f64, (2 * j + 1) as f64);
                rings.push(vec![[cx + 1.0, cy], [cx, cy + 1.0], [cx - 1.0, cy], [cx, cy - 1.0]]);
            }
        }
    }
    rings
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cut_points_are_exactly_on_the_edge() {
        let rng = &mut Rng(3);
        for (a, b) in [([0.0, 0.0], [8.0, 3.0]), ([0.25, -1.0], [1.5, 7.75]), ([1e6, 3.0], [-5.0, 3.0])] {
            let points = exact_cut_points(a, b, 5, true, rng);
            assert!(!points.is_empty());
            for p in &points {
                assert_eq!(orient(a, b, *p), 0);
            }
            // the tip point is 2^-m of the edge from a
            assert!(points.iter().any(|p| (p[0] - a[0]).abs() <= (b[0] - a[0]).abs() / 256.0 + 1e-300));
        }
    }

    #[test]
    fn nudged_points_are_one_ulp_off() {
        let (a, b) = ([0.0, 0.0], [8.0, 2.0]);
        let rng = &mut Rng(5);
        for _ in 0..20 {
            let p = exact_cut_points(a, b, 1, false, rng)[0];
            let q = nudge(a, b, p, rng).unwrap();
            assert_ne!(orient(a, b, q), 0);
            assert_eq!(q[0], p[0]);
            assert!(q[1] == next_after(p[1], true) || q[1] == next_after(p[1], false));
        }
    }

    #[test]
    fn snapping_random_input_makes_exact_cuts_possible() {
        let segments = crate::generate("polyline", 200, 1).unwrap().segments;
        let straight = VARIANTS[0].1;
        let cut = cut_segments(&segments, &straight, &mut variant_rng(1));
        assert!(legal(&cut));
        assert!(cut.len() > segments.len() + segments.len() / 4, "{} pieces of {}", cut.len(), segments.len());
    }
}
