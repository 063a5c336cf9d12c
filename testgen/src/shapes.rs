//! Inputs of the cargo tests: uniform points, points and segments on a
//! jittered grid, regular polygons, a snake, the unit-segment lattice.

use crate::points::scaled_uniform;
use crate::{Point, Rng, Segment};

/// `n` points uniform in the unit square.
pub fn uniform(n: usize, seed: u64) -> Vec<Point> {
    scaled_uniform(n, &mut Rng(seed), 0.0, 1.0)
}

/// Points and short segments on a jittered grid, one item per cell (a
/// segment with probability `segment_share`): no two segments meet.
pub fn segment_grid(side: usize, seed: u64, segment_share: f64) -> (Vec<Point>, Vec<Segment>) {
    let mut rng = Rng(seed);
    let (mut pts, mut segs) = (Vec::new(), Vec::new());
    for i in 0..side {
        for j in 0..side {
            let (x, y) = (i as f64, j as f64);
            let a = [x + 0.1 + 0.8 * rng.unit(), y + 0.1 + 0.8 * rng.unit()];
            if rng.unit() < segment_share {
                segs.push([a, [x + 0.1 + 0.8 * rng.unit(), y + 0.1 + 0.8 * rng.unit()]]);
            } else {
                pts.push(a);
            }
        }
    }
    (pts, segs)
}

/// The sides of the regular `n`-gon of circumradius `r` centred at
/// `(cx, cy)`, each sharing its endpoints with its neighbours (with
/// `r = 1` at the origin: the cross-check's `polygon` family).
pub fn polygon(n: usize, r: f64, cx: f64, cy: f64) -> Vec<Segment> {
    let corner = |k: usize| {
        let t = std::f64::consts::TAU * (k % n) as f64 / n as f64;
        [cx + r * t.cos(), cy + r * t.sin()]
    };
    (0..n).map(|k| [corner(k), corner(k + 1)]).collect()
}

/// A boustrophedon polyline through one jittered point per grid cell:
/// consecutive segments share endpoints, none cross.
pub fn snake(side: usize, seed: u64) -> Vec<Segment> {
    let mut rng = Rng(seed);
    let mut path = Vec::new();
    for i in 0..side {
        for k in 0..side {
            let j = if i % 2 == 0 { k } else { side - 1 - k };
            path.push([i as f64 + 0.1 + 0.8 * rng.unit(), j as f64 + 0.1 + 0.8 * rng.unit()]);
        }
    }
    path.windows(2).map(|w| [w[0], w[1]]).collect()
}

/// Every line of the `n` by `n` unit grid split into unit segments:
/// degree-4 shared endpoints, collinear neighbours, cocircular everything.
pub fn unit_segment_lattice(n: usize) -> Vec<Segment> {
    let mut segs = Vec::new();
    for i in 0..=n {
        for j in 0..n {
            let (x, y) = (i as f64, j as f64);
            segs.push([[x, y], [x, y + 1.0]]);
            segs.push([[y, x], [y + 1.0, x]]);
        }
    }
    segs
}

/// A star-shaped ring of `n` corners around `(cx, cy)`: corner `k` at angle
/// `2π (k + 0.3 u) / n` and radius in `[r0, r1]` (`u` and the radius drawn
/// from `rng`), so corners keep their angular order and the ring is simple.
pub fn star_ring(n: usize, cx: f64, cy: f64, r0: f64, r1: f64, rng: &mut Rng) -> Vec<Point> {
    (0..n)
        .map(|k| {
            let t = std::f64::consts::TAU * (k as f64 + 0.3 * rng.unit()) / n as f64;
            let r = r0 + (r1 - r0) * rng.unit();
            [cx + r * t.cos(), cy + r * t.sin()]
        })
        .collect()
}

/// A sheet of `parts` star-shaped parts with a hole each, on a square grid
/// 2.2 apart: per part its outer ring of `outer` corners (radii 0.8..1,
/// counter-clockwise) and its hole of `hole` corners (radii 0.2..0.35,
/// clockwise), both from [`star_ring`]. Disjoint; the benchmarks' polygons
/// (`bench/src/sheet.rs`), and a lumpy boundary for the parallel build.
pub fn star_sheet(parts: usize, outer: usize, hole: usize, seed: u64) -> Vec<[Vec<Point>; 2]> {
    let mut rng = Rng(seed);
    let side = (parts as f64).sqrt().ceil() as usize;
    (0..parts)
        .map(|k| {
            let (cx, cy) = ((k % side) as f64 * 2.2, (k / side) as f64 * 2.2);
            let outer = star_ring(outer, cx, cy, 0.8, 1.0, &mut rng);
            let mut hole = star_ring(hole, cx, cy, 0.2, 0.35, &mut rng);
            hole.reverse();
            [outer, hole]
        })
        .collect()
}
