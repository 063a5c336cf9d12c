//! Boost.Polygon's benchmark style: random segments on the integer grid,
//! every crossing split at the crossing point rounded to the grid (what
//! boost::polygon::intersect_segments does to the benchmark data).

use std::collections::HashSet;

use crate::exact::{in_open_segment, orient, same_point, segments_conflict, SegmentGrid};
use crate::{cmax, cmin, Point, Rng, Segment, TWO_PI};

/// The pairs (i, j), i < j, of segments that the library would reject
/// (crossing, overlapping, touching away from a shared endpoint), found
/// through a grid over the bounding box (all pairs below 64 segments).
fn conflicting_pairs(segs: &[Segment]) -> Vec<(usize, usize)> {
    let mut pairs = Vec::new();
    if segs.len() < 64 {
        for i in 0..segs.len() {
            for j in i + 1..segs.len() {
                if segments_conflict(segs[i], segs[j]) {
                    pairs.push((i, j));
                }
            }
        }
        return pairs;
    }
    let (mut lo, mut hi) = (segs[0][0], segs[0][0]);
    for p in segs.iter().flatten() {
        lo = [cmin(lo[0], p[0]), cmin(lo[1], p[1])];
        hi = [cmax(hi[0], p[0]), cmax(hi[1], p[1])];
    }
    let mut grid = SegmentGrid::new(lo, [hi[0] + 1.0, hi[1] + 1.0], SegmentGrid::side_for(segs.len()));
    for (j, &s) in segs.iter().enumerate() {
        grid.any_near(s, |i| {
            if segments_conflict(segs[i], s) {
                pairs.push((i, j));
            }
            false
        });
        grid.add(s, j);
    }
    pairs
}

/// The crossing point of two properly crossing segments, rounded to the
/// integer grid.
fn rounded_crossing(s: Segment, t: Segment) -> Point {
    let (dx, dy) = (s[1][0] - s[0][0], s[1][1] - s[0][1]);
    let (ex, ey) = (t[1][0] - t[0][0], t[1][1] - t[0][1]);
    let den = dx * ey - dy * ex;
    let u = ((t[0][0] - s[0][0]) * ey - (t[0][1] - s[0][1]) * ex) / den;
    [(s[0][0] + u * dx).round(), (s[0][1] + u * dy).round()]
}

/// A segment's key in the set of pieces: unordered, -0 as +0.
fn piece_key(from: Point, to: Point) -> [u64; 4] {
    let (mut a, mut b) = ([from[0] + 0.0, from[1] + 0.0], [to[0] + 0.0, to[1] + 0.0]);
    if b[0] < a[0] || (b[0] == a[0] && b[1] < a[1]) {
        std::mem::swap(&mut a, &mut b);
    }
    [a[0].to_bits(), a[1].to_bits(), b[0].to_bits(), b[1].to_bits()]
}

/// Splits crossing segments at their rounded crossing points and segments
/// touched inside by another's endpoint at that endpoint, round after round
/// (rounding moves a crossing point off both lines, so the pieces can cross
/// again); after `rounds` rounds, or for overlaps, the later segment of
/// each remaining conflicting pair is dropped. Pieces keep their parent's
/// direction; zero-length and repeated pieces are left out.
pub fn split_at_rounded_crossings(mut segs: Vec<Segment>, rounds: usize) -> Vec<Segment> {
    for _ in 0..rounds {
        let pairs = conflicting_pairs(&segs);
        if pairs.is_empty() {
            return segs;
        }
        let mut cuts: Vec<Vec<Point>> = vec![Vec::new(); segs.len()];
        let mut drop = vec![false; segs.len()];
        for &(first, second) in &pairs {
            let (s, t) = (segs[first], segs[second]);
            let (o1, o2) = (orient(s[0], s[1], t[0]), orient(s[0], s[1], t[1]));
            let (o3, o4) = (orient(t[0], t[1], s[0]), orient(t[0], t[1], s[1]));
            if o1 * o2 < 0 && o3 * o4 < 0 {
                let q = rounded_crossing(s, t);
                cuts[first].push(q);
                cuts[second].push(q);
                continue;
            }
            let mut touched = false;
            for p in t {
                if in_open_segment(s, p) {
                    cuts[first].push(p);
                    touched = true;
                }
            }
            for p in s {
                if in_open_segment(t, p) {
                    cuts[second].push(p);
                    touched = true;
                }
            }
            // Collinear overlap: no cut separates the two.
            if (o1 == 0 && o2 == 0) || !touched {
                drop[second] = true;
            }
        }
        let mut next = Vec::new();
        let mut seen = HashSet::new();
        for (i, &s) in segs.iter().enumerate() {
            if drop[i] {
                continue;
            }
            let c = &mut cuts[i];
            let (dx, dy) = (s[1][0] - s[0][0], s[1][1] - s[0][1]);
            let along = |p: &Point| (p[0] - s[0][0]) * dx + (p[1] - s[0][1]) * dy;
            // Stable, as std::sort is on the few cuts of a segment (an
            // insertion sort up to 16 elements).
            c.sort_by(|p, q| along(p).partial_cmp(&along(q)).expect("finite"));
            let mut from = s[0];
            c.push(s[1]);
            for &to in c.iter() {
                if same_point(from, to) {
                    continue;
                }
                if seen.insert(piece_key(from, to)) {
                    next.push([from, to]);
                }
                from = to;
            }
        }
        segs = next;
    }
    let pairs = conflicting_pairs(&segs);
    let mut drop = vec![false; segs.len()];
    for (first, second) in pairs {
        if !drop[first] {
            drop[second] = true;
        }
    }
    segs.into_iter().zip(drop).filter(|(_, d)| !d).map(|(s, _)| s).collect()
}

/// n random segments with integer endpoints in [0, side]^2, lengths uniform
/// in [0, 3 side / sqrt(n)] (about 1.4 crossings per segment), then split
/// at the rounded crossings: many segments meeting at shared points, kinks
/// of near-zero angle where a crossing point was rounded.
pub fn boost_split(n: usize, rng: &mut Rng, side: f64) -> Vec<Segment> {
    let max_length = 3.0 * side / (n.max(1) as f64).sqrt();
    let mut segs = Vec::with_capacity(n);
    while segs.len() < n {
        let a = [(rng.unit() * (side + 1.0)).floor(), (rng.unit() * (side + 1.0)).floor()];
        let (angle, length) = (TWO_PI * rng.unit(), max_length * rng.unit());
        let b = [(a[0] + length * angle.cos()).round(), (a[1] + length * angle.sin()).round()];
        if same_point(a, b) || b[0] < 0.0 || b[1] < 0.0 || b[0] > side || b[1] > side {
            continue;
        }
        segs.push([a, b]);
    }
    split_at_rounded_crossings(segs, 12)
}
