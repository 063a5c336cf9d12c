//! The benchmark's inputs (bench/): every contender must see the identical
//! input, so both kinds are integers, generated here from one seed.
//!
//! **Points.** Uniform random points, snapped to the integer grid:
//! boostvoronoi only takes integers, so each coordinate is `floor(u * 1e6)`
//! for a uniform `u` in [0, 1); segvoronoi and spade get the same integers
//! as `f64`.
//!
//! **Segments.** Pairwise disjoint segments with integer endpoints in
//! [0, 10⁶)², so boostvoronoi (integers only), Boost.Polygon's C++ builder
//! (as `i32`) and segvoronoi (as `f64`) all get the identical input.
//!
//! Four generators, all driven by [`Rng`](crate::Rng):
//!
//! - [`Method::Short`]: short random segments in the style of Boost.Polygon's
//!   own segment benchmark. Midpoint uniform, direction uniform, length
//!   uniform in [L/2, 3L/2] with L = 10⁶/√n, endpoints snapped by `floor`;
//!   a segment that would leave the square, cross or touch an earlier one, or
//!   come closer than [`GAP`] integer units to it, is thrown away and drawn
//!   again.
//! - [`Method::Redraw`], [`Method::Shorten`], [`Method::Swap`]: the three
//!   ways of the seed paper's experiment (seed 000 §6, "取り方 1, 2, 3"),
//!   endpoints uniform in the unit square, scaled to [0, 10⁶) and snapped:
//!   1. draw a segment; while it crosses an earlier one, draw it again;
//!   2. draw a segment; each time it crosses an earlier one (tested in input
//!      order), move its second endpoint to the 1:9 point between the crossing
//!      and its first endpoint, i.e. keep 90% of the part before the
//!      crossing;
//!   3. draw all n segments; while two cross, swap their second endpoints
//!      (this strictly shortens the total length, so it ends).
//!
//! "Crosses" is always the same test: the two closed integer segments share
//! a point (exact, in `i64`) or come closer than [`GAP`] units (in `f64`).
//! The gap keeps the input away from touching configurations that exist
//! only because of the snapping; every contender accepts the result as
//! disjoint segments. Candidate pairs come from a uniform grid, so the
//! generators take about linear time except method 1, whose acceptance rate
//! falls like 1/i (about n²/2 draws in all, a few seconds at n = 4096).

use crate::Rng;

/// Side of the square the points are drawn from: [0, SIDE)^2.
pub const SIDE: f64 = 1e6;

/// The seed every run uses; a fixed seed makes the sizes nest (the first
/// 10k points of the 100k input are the 10k input).
pub const SEED: u64 = 0x5EED_0F_B0_0575;

/// `n` snapped points, coordinates in `0..1_000_000`.
pub fn grid_points(n: usize, seed: u64) -> Vec<[i32; 2]> {
    snapped(n, seed).collect()
}

/// The same points as `f64`, for the contenders that take floating point.
/// Collected straight from the generator, so no integer copy inflates the
/// child's peak memory.
pub fn float_points(n: usize, seed: u64) -> Vec<[f64; 2]> {
    snapped(n, seed).map(|[x, y]| [f64::from(x), f64::from(y)]).collect()
}

fn snapped(n: usize, seed: u64) -> impl Iterator<Item = [i32; 2]> {
    let mut rng = Rng(seed);
    (0..n).map(move |_| {
        let x = (rng.unit() * SIDE).floor() as i32;
        let y = (rng.unit() * SIDE).floor() as i32;
        [x, y]
    })
}

/// A segment as `[x1, y1, x2, y2]`: first endpoint, then second.
pub type Seg = [i32; 4];

/// Least distance between two generated segments, in integer units.
pub const GAP: f64 = 4.0;

/// How the segments are drawn (see the module comment).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    Short,
    Redraw,
    Shorten,
    Swap,
}

impl Method {
    /// The seed paper's number of the method ("取り方"), 0 for `Short`.
    pub fn number(self) -> u8 {
        match self {
            Method::Short => 0,
            Method::Redraw => 1,
            Method::Shorten => 2,
            Method::Swap => 3,
        }
    }

    pub fn from_number(k: u8) -> Option<Method> {
        [Method::Redraw, Method::Shorten, Method::Swap].into_iter().find(|m| m.number() == k)
    }
}

/// A generated input and what it cost to make.
#[derive(Clone, Debug, Default)]
pub struct Generated {
    pub segments: Vec<Seg>,
    /// Segments drawn (both endpoints, or the second one for a redraw in
    /// method 3), accepted or not.
    pub draws: u64,
    /// Shortenings (method 2) or endpoint swaps (method 3).
    pub repairs: u64,
    /// Method 3: times the whole set was drawn again because it did not
    /// settle within the step limit.
    pub restarts: u64,
}

impl Generated {
    pub fn mean_length(&self) -> f64 {
        if self.segments.is_empty() {
            return 0.0;
        }
        self.segments.iter().map(|&s| length(s)).sum::<f64>() / self.segments.len() as f64
    }
}

/// `n` disjoint segments drawn by `method` from `seed`.
pub fn generate(method: Method, n: usize, seed: u64) -> Generated {
    let mut rng = Rng(seed ^ (u64::from(method.number()) << 56));
    match method {
        Method::Short => short(n, &mut rng),
        Method::Redraw => redraw(n, &mut rng),
        Method::Shorten => shorten(n, &mut rng),
        Method::Swap => swap(n, &mut rng),
    }
}

// ---------------------------------------------------------------- generators

fn short(n: usize, rng: &mut Rng) -> Generated {
    let mean = SIDE / (n.max(1) as f64).sqrt();
    let mut grid = Grid::new(mean);
    let mut seen = Seen::default();
    let mut g = Generated { segments: Vec::with_capacity(n), ..Generated::default() };
    while g.segments.len() < n {
        g.draws += 1;
        assert!(g.draws < 1000 + 200 * n as u64, "short segments: cannot place segment {}", g.segments.len());
        let (mx, my) = (rng.unit() * SIDE, rng.unit() * SIDE);
        let angle = rng.unit() * std::f64::consts::TAU;
        let half = 0.5 * mean * (0.5 + rng.unit());
        let (dx, dy) = (half * angle.cos(), half * angle.sin());
        let ends = [mx - dx, my - dy, mx + dx, my + dy];
        if ends.iter().any(|&c| !(0.0..SIDE).contains(&c)) {
            continue;
        }
        let s = ends.map(|c| c.floor() as i32);
        if !try_add(&mut g.segments, &mut grid, &mut seen, s) {
            continue;
        }
    }
    g
}

/// Method 1: redraw the whole segment until it crosses nothing.
fn redraw(n: usize, rng: &mut Rng) -> Generated {
    let mut grid = Grid::new(SIDE / (n.max(1) as f64).sqrt());
    let mut seen = Seen::default();
    let mut g = Generated { segments: Vec::with_capacity(n), ..Generated::default() };
    let limit = 10_000 + 50 * (n as u64) * (n as u64);
    while g.segments.len() < n {
        g.draws += 1;
        assert!(g.draws < limit, "method 1: cannot place segment {}", g.segments.len());
        let s = random_segment(rng);
        try_add(&mut g.segments, &mut grid, &mut seen, s);
    }
    g
}

/// Method 2: shorten toward the first endpoint on every crossing.
fn shorten(n: usize, rng: &mut Rng) -> Generated {
    let mut grid = Grid::new(SIDE / (n.max(1) as f64).sqrt());
    let mut seen = Seen::default();
    let mut g = Generated { segments: Vec::with_capacity(n), ..Generated::default() };
    let mut candidates = Vec::new();
    'draw: while g.segments.len() < n {
        g.draws += 1;
        assert!(g.draws < 1000 + 1000 * n as u64, "method 2: cannot place segment {}", g.segments.len());
        let mut s = random_segment(rng);
        // The first endpoint stays: it must be clear of every earlier segment.
        let a = [s[0], s[1], s[0], s[1]];
        if grid.find(&mut seen, &g.segments, a, |_, t| conflict(a, t)).is_some() {
            continue;
        }
        // Passes in input order; the snapping of the new endpoint can make a
        // segment tested earlier in the pass conflict again, hence the loop.
        for _pass in 0..64 {
            candidates.clear();
            grid.collect(&mut seen, g.segments.len(), s, &mut candidates);
            candidates.sort_unstable();
            let mut changed = false;
            for &j in &candidates {
                let t = g.segments[j as usize];
                if conflict(s, t) {
                    match cut_before(s, t) {
                        Some(shorter) => s = shorter,
                        None => continue 'draw,
                    }
                    g.repairs += 1;
                    changed = true;
                }
            }
            if !changed {
                let id = g.segments.len() as u32;
                grid.insert(id, s);
                g.segments.push(s);
                continue 'draw;
            }
        }
    }
    g
}

/// Method 3: draw all, then swap the second endpoints of crossing pairs.
/// Pairs are found through a work queue (each segment checked again after it
/// changes) rather than in the paper's lexicographic (i, j) order; a pair
/// that conflicts without a proper crossing (touching, collinear, closer
/// than the gap) gets the second endpoint of its later segment drawn again.
fn swap(n: usize, rng: &mut Rng) -> Generated {
    let mut g = Generated::default();
    let mut seen = Seen::default();
    'restart: loop {
        g.segments = (0..n).map(|_| random_segment(rng)).collect();
        g.draws += n as u64;
        let mut grid = Grid::new(SIDE / (n.max(1) as f64).sqrt());
        for (i, &s) in g.segments.iter().enumerate() {
            grid.insert(i as u32, s);
        }
        let mut queue: std::collections::VecDeque<u32> = (0..n as u32).collect();
        let mut queued = vec![true; n];
        let mut steps = 0u64;
        while let Some(i) = queue.pop_front() {
            queued[i as usize] = false;
            let s = g.segments[i as usize];
            let Some(j) = grid.find(&mut seen, &g.segments, s, |k, t| k != i && conflict(s, t)) else { continue };
            steps += 1;
            if steps > 1000 + 2000 * n as u64 {
                g.restarts += 1;
                assert!(g.restarts < 20, "method 3 does not settle");
                continue 'restart;
            }
            let t = g.segments[j as usize];
            grid.remove(i, s);
            grid.remove(j, t);
            let swapped = [[s[0], s[1], t[2], t[3]], [t[0], t[1], s[2], s[3]]];
            if proper_cross(s, t) && swapped.iter().all(|&u| u[..2] != u[2..]) {
                g.segments[i as usize] = swapped[0];
                g.segments[j as usize] = swapped[1];
                g.repairs += 1;
            } else {
                let k = i.max(j) as usize;
                let [x, y] = loop {
                    let p = random_point(rng);
                    if p != [g.segments[k][0], g.segments[k][1]] {
                        break p;
                    }
                };
                g.segments[k][2] = x;
                g.segments[k][3] = y;
                g.draws += 1;
            }
            for id in [i, j] {
                grid.insert(id, g.segments[id as usize]);
                if !queued[id as usize] {
                    queued[id as usize] = true;
                    queue.push_back(id);
                }
            }
        }
        return g;
    }
}

/// Adds `s` unless it is degenerate or conflicts with one already there.
fn try_add(segments: &mut Vec<Seg>, grid: &mut Grid, seen: &mut Seen, s: Seg) -> bool {
    if s[..2] == s[2..] || grid.find(seen, segments, s, |_, t| conflict(s, t)).is_some() {
        return false;
    }
    grid.insert(segments.len() as u32, s);
    segments.push(s);
    true
}

fn random_point(rng: &mut Rng) -> [i32; 2] {
    [(rng.unit() * SIDE).floor() as i32, (rng.unit() * SIDE).floor() as i32]
}

/// Both endpoints uniform, distinct.
fn random_segment(rng: &mut Rng) -> Seg {
    loop {
        let ([x1, y1], [x2, y2]) = (random_point(rng), random_point(rng));
        if [x1, y1] != [x2, y2] {
            return [x1, y1, x2, y2];
        }
    }
}

/// Method 2's repair: `s` conflicts with `t`; move its second endpoint to
/// `X + (A − X) / 10`, X the crossing (or, when they only come too close,
/// the point of `s` nearest to `t`), A the first endpoint. `None` when
/// nothing usable is left (the segment is then drawn again).
fn cut_before(s: Seg, t: Seg) -> Option<Seg> {
    let [ax, ay, bx, by] = s.map(f64::from);
    let [cx, cy, dx, dy] = t.map(f64::from);
    let x = if intersect(s, t) {
        let denom = cross(bx - ax, by - ay, dx - cx, dy - cy);
        if denom == 0.0 {
            return None; // collinear overlap
        }
        let u = cross(cx - ax, cy - ay, dx - cx, dy - cy) / denom;
        [ax + u * (bx - ax), ay + u * (by - ay)]
    } else {
        // The nearest approach is at an endpoint of one of the two.
        let d_b = point_segment_distance([bx, by], t);
        let d_c = point_segment_distance([cx, cy], s);
        let d_d = point_segment_distance([dx, dy], s);
        let d_a = point_segment_distance([ax, ay], t);
        if d_a <= d_b.min(d_c).min(d_d) {
            return None;
        }
        if d_b <= d_c.min(d_d) {
            [bx, by]
        } else {
            let p = if d_c <= d_d { [cx, cy] } else { [dx, dy] };
            let (vx, vy) = (bx - ax, by - ay);
            let u = (((p[0] - ax) * vx + (p[1] - ay) * vy) / (vx * vx + vy * vy)).clamp(0.0, 1.0);
            [ax + u * vx, ay + u * vy]
        }
    };
    let nb = [(x[0] + 0.1 * (ax - x[0])).round(), (x[1] + 0.1 * (ay - x[1])).round()];
    if (nb[0] - ax).hypot(nb[1] - ay) < 2.0 {
        return None;
    }
    Some([s[0], s[1], nb[0] as i32, nb[1] as i32])
}

// ------------------------------------------------------------------ geometry

fn cross(ux: f64, uy: f64, vx: f64, vy: f64) -> f64 {
    ux * vy - uy * vx
}

/// Sign of the turn a → b → c, exact (coordinates below 2^21).
fn orient(a: [i64; 2], b: [i64; 2], c: [i64; 2]) -> i64 {
    ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).signum()
}

fn ends(s: Seg) -> ([i64; 2], [i64; 2]) {
    ([s[0].into(), s[1].into()], [s[2].into(), s[3].into()])
}

/// `p`, collinear with `a`b, lies in the closed box of `a`b.
fn in_box(a: [i64; 2], b: [i64; 2], p: [i64; 2]) -> bool {
    a[0].min(b[0]) <= p[0] && p[0] <= a[0].max(b[0]) && a[1].min(b[1]) <= p[1] && p[1] <= a[1].max(b[1])
}

/// The closed segments share a point. Exact.
pub fn intersect(s: Seg, t: Seg) -> bool {
    let ((a, b), (c, d)) = (ends(s), ends(t));
    let (o1, o2, o3, o4) = (orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b));
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return true;
    }
    (o1 == 0 && in_box(a, b, c)) || (o2 == 0 && in_box(a, b, d)) || (o3 == 0 && in_box(c, d, a)) || (o4 == 0 && in_box(c, d, b))
}

/// The interiors cross at one point and no endpoint is on the other segment.
fn proper_cross(s: Seg, t: Seg) -> bool {
    let ((a, b), (c, d)) = (ends(s), ends(t));
    orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0
}

fn point_segment_distance(p: [f64; 2], s: Seg) -> f64 {
    let [ax, ay, bx, by] = s.map(f64::from);
    let (vx, vy) = (bx - ax, by - ay);
    let len2 = vx * vx + vy * vy;
    let u = if len2 == 0.0 { 0.0 } else { (((p[0] - ax) * vx + (p[1] - ay) * vy) / len2).clamp(0.0, 1.0) };
    (p[0] - ax - u * vx).hypot(p[1] - ay - u * vy)
}

/// Distance between two closed segments (0 when they share a point).
pub fn distance(s: Seg, t: Seg) -> f64 {
    if intersect(s, t) {
        return 0.0;
    }
    let f = |k: usize, u: Seg| [f64::from(u[k]), f64::from(u[k + 1])];
    point_segment_distance(f(0, s), t)
        .min(point_segment_distance(f(2, s), t))
        .min(point_segment_distance(f(0, t), s))
        .min(point_segment_distance(f(2, t), s))
}

/// Too close to be in one input: sharing a point, or nearer than the gap.
fn conflict(s: Seg, t: Seg) -> bool {
    // Boxes more than the gap apart: no conflict, without the distances.
    let far = |lo1: i32, hi1: i32, lo2: i32, hi2: i32| f64::from(lo2 - hi1) >= GAP || f64::from(lo1 - hi2) >= GAP;
    let (sx, sy, tx, ty) = (
        (s[0].min(s[2]), s[0].max(s[2])),
        (s[1].min(s[3]), s[1].max(s[3])),
        (t[0].min(t[2]), t[0].max(t[2])),
        (t[1].min(t[3]), t[1].max(t[3])),
    );
    if far(sx.0, sx.1, tx.0, tx.1) || far(sy.0, sy.1, ty.0, ty.1) {
        return false;
    }
    distance(s, t) < GAP
}

pub fn length(s: Seg) -> f64 {
    f64::from(s[2] - s[0]).hypot(f64::from(s[3] - s[1]))
}

// ---------------------------------------------------------------------- grid

/// A uniform grid over [0, SIDE)², each cell listing the segments whose
/// `GAP + 1` neighbourhood may reach into it.
struct Grid {
    side: f64,
    dim: usize,
    cells: Vec<Vec<u32>>,
}

/// Which segments a query has already tested (a segment sits in several
/// cells).
#[derive(Default)]
struct Seen {
    stamp: Vec<u32>,
    epoch: u32,
}

impl Seen {
    fn start(&mut self, n: usize) {
        if self.stamp.len() < n {
            self.stamp.resize(n, 0);
        }
        self.epoch = self.epoch.wrapping_add(1);
        if self.epoch == 0 {
            self.stamp.fill(0);
            self.epoch = 1;
        }
    }

    fn first(&mut self, id: u32) -> bool {
        let slot = &mut self.stamp[id as usize];
        let fresh = *slot != self.epoch;
        *slot = self.epoch;
        fresh
    }
}

impl Grid {
    fn new(cell_side: f64) -> Grid {
        let dim = ((SIDE / cell_side).ceil() as usize).clamp(1, 2048);
        Grid { side: SIDE / dim as f64, dim, cells: vec![Vec::new(); dim * dim] }
    }

    fn index(&self, v: f64) -> usize {
        ((v / self.side).floor().max(0.0) as usize).min(self.dim - 1)
    }

    /// Calls `f` on every cell the `pad`-neighbourhood of `s` may touch
    /// (conservatively), row by row from the first endpoint's side; stops
    /// early, returning `true`, when `f` does.
    fn visit(&self, s: Seg, pad: f64, mut f: impl FnMut(usize) -> bool) -> bool {
        let [x1, y1, x2, y2] = s.map(f64::from);
        let (r0, r1) = (self.index(y1.min(y2) - pad), self.index(y1.max(y2) + pad));
        let rows: Box<dyn Iterator<Item = usize>> = if y2 >= y1 { Box::new(r0..=r1) } else { Box::new((r0..=r1).rev()) };
        for r in rows {
            // The part of the segment within `pad` of this row's band.
            let (lo, hi) = (r as f64 * self.side - pad, (r + 1) as f64 * self.side + pad);
            let (xa, xb) = if y1 == y2 {
                (x1, x2)
            } else {
                let at = |y: f64| {
                    let u = ((y - y1) / (y2 - y1)).clamp(0.0, 1.0);
                    x1 + u * (x2 - x1)
                };
                (at(lo), at(hi))
            };
            let (c0, c1) = (self.index(xa.min(xb) - pad), self.index(xa.max(xb) + pad));
            let mut visit_col = |c: usize| f(r * self.dim + c);
            if x2 >= x1 {
                if (c0..=c1).any(&mut visit_col) {
                    return true;
                }
            } else if (c0..=c1).rev().any(&mut visit_col) {
                return true;
            }
        }
        false
    }

    /// The cells a segment is registered in.
    fn cells_of(&self, s: Seg) -> Vec<usize> {
        let mut touched = Vec::new();
        self.visit(s, GAP + 1.0, |c| {
            touched.push(c);
            false
        });
        touched
    }

    fn insert(&mut self, id: u32, s: Seg) {
        for c in self.cells_of(s) {
            self.cells[c].push(id);
        }
    }

    fn remove(&mut self, id: u32, s: Seg) {
        for c in self.cells_of(s) {
            let cell = &mut self.cells[c];
            let k = cell.iter().position(|&x| x == id).expect("segment registered in its cells");
            cell.swap_remove(k);
        }
    }

    /// The first segment (in the cell order of `visit`) for which `hit`
    /// holds; each segment tested once.
    fn find(&self, seen: &mut Seen, segments: &[Seg], s: Seg, mut hit: impl FnMut(u32, Seg) -> bool) -> Option<u32> {
        seen.start(segments.len());
        let mut found = None;
        self.visit(s, 1.0, |c| {
            for &id in &self.cells[c] {
                if seen.first(id) && hit(id, segments[id as usize]) {
                    found = Some(id);
                    return true;
                }
            }
            false
        });
        found
    }

    /// Every segment registered near `s`, once each, in no particular order.
    fn collect(&self, seen: &mut Seen, n: usize, s: Seg, out: &mut Vec<u32>) {
        seen.start(n);
        self.visit(s, 1.0, |c| {
            out.extend(self.cells[c].iter().copied().filter(|&id| seen.first(id)));
            false
        });
    }
}

/// Checks that no two segments share a point (exactly) or come closer than
/// [`GAP`]; returns the least distance between segments near each other
/// (`None` when no two are within a grid cell of each other).
pub fn verify(segments: &[Seg]) -> Result<Option<f64>, String> {
    if segments.is_empty() {
        return Ok(None);
    }
    let mean = segments.iter().map(|&s| length(s)).sum::<f64>() / segments.len() as f64;
    let mut grid = Grid::new(mean.max(SIDE / 2048.0));
    for (i, &s) in segments.iter().enumerate() {
        grid.insert(i as u32, s);
    }
    let mut seen = Seen::default();
    let mut least: Option<f64> = None;
    for (i, &s) in segments.iter().enumerate() {
        let mut problem = None;
        let found = grid.find(&mut seen, segments, s, |j, t| {
            if j as usize == i {
                return false;
            }
            let d = distance(s, t);
            least = Some(least.map_or(d, |l| l.min(d)));
            if d < GAP {
                problem = Some((t, d));
            }
            problem.is_some()
        });
        if let (Some(j), Some((t, d))) = (found, problem) {
            return Err(format!("segments {i} {s:?} and {j} {t:?} are {d:.2} apart (least allowed {GAP})"));
        }
    }
    Ok(least)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deterministic_in_range_and_nested() {
        let a = grid_points(1000, SEED);
        assert_eq!(a, grid_points(1000, SEED));
        assert_eq!(&a[..100], &grid_points(100, SEED)[..]);
        assert!(a.iter().flatten().all(|&c| (0..1_000_000).contains(&c)));
        let f = float_points(1000, SEED);
        assert!(a.iter().zip(&f).all(|(i, f)| f64::from(i[0]) == f[0] && f64::from(i[1]) == f[1]));
    }

    fn brute_force_ok(segments: &[Seg]) -> bool {
        (0..segments.len()).all(|i| (0..i).all(|j| distance(segments[i], segments[j]) >= GAP))
    }

    #[test]
    fn geometry() {
        assert!(intersect([0, 0, 10, 10], [0, 10, 10, 0]));
        assert!(proper_cross([0, 0, 10, 10], [0, 10, 10, 0]));
        assert!(intersect([0, 0, 10, 0], [10, 0, 20, 5])); // shared endpoint
        assert!(!proper_cross([0, 0, 10, 0], [10, 0, 20, 5]));
        assert!(intersect([0, 0, 10, 0], [5, 0, 20, 0])); // collinear overlap
        assert!(!intersect([0, 0, 10, 0], [11, 0, 20, 0]));
        assert!(intersect([0, 0, 10, 0], [5, 0, 5, 7])); // T
        assert_eq!(distance([0, 0, 10, 0], [5, 3, 5, 7]), 3.0);
        assert!(conflict([0, 0, 10, 0], [5, 3, 5, 7]));
        assert!(!conflict([0, 0, 10, 0], [5, 4, 5, 7]));
    }

    #[test]
    fn every_method_gives_disjoint_segments() {
        for method in [Method::Short, Method::Redraw, Method::Shorten, Method::Swap] {
            let g = generate(method, 300, 7);
            assert_eq!(g.segments.len(), 300, "{method:?}");
            assert!(brute_force_ok(&g.segments), "{method:?}");
            assert!(verify(&g.segments).is_ok(), "{method:?}");
            assert!(g.segments.iter().flatten().all(|&c| (0..1_000_000).contains(&c)));
            assert_eq!(g.segments, generate(method, 300, 7).segments, "deterministic");
        }
    }

    #[test]
    fn verify_finds_a_crossing() {
        let bad = [[0, 0, 100, 100], [0, 100, 100, 0], [500, 500, 600, 600]];
        assert!(verify(&bad).is_err());
        assert!(verify(&bad[1..]).is_ok());
    }
}
