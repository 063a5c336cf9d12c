//! Segment families of the cross-check: seed 000's three random methods,
//! short segments, polylines, polygons with holes, the lattice, the
//! figures of seed 000 (tangent, parallel, the letter R), near-vertical
//! segments.

use crate::exact::{closed_segments_meet, segments_conflict, SegmentGrid};
use crate::{cmax, cmin, shuffle, Point, Rng, Segment, TWO_PI};

fn random_unit_segment(rng: &mut Rng) -> Segment {
    let a = [rng.unit(), rng.unit()];
    [a, [rng.unit(), rng.unit()]]
}

/// Seed 000, method 1: draw a segment, redraw while it meets an earlier one.
pub fn seg_random1(n: usize, rng: &mut Rng) -> Vec<Segment> {
    let mut out: Vec<Segment> = Vec::new();
    let mut grid = SegmentGrid::new([0.0, 0.0], [1.0, 1.0], SegmentGrid::side_for(n));
    while out.len() < n {
        let s = random_unit_segment(rng);
        if grid.any_near(s, |id| closed_segments_meet(s, out[id])) {
            continue;
        }
        grid.add(s, out.len());
        out.push(s);
    }
    out
}

/// Seed 000, method 2: draw a segment; for each earlier segment in order
/// that it crosses, move its second endpoint to the 1:9 point between the
/// crossing and the first endpoint (90% of the way from the first endpoint).
pub fn seg_random2(n: usize, rng: &mut Rng) -> Vec<Segment> {
    let mut out: Vec<Segment> = Vec::new();
    let mut grid = SegmentGrid::new([0.0, 0.0], [1.0, 1.0], SegmentGrid::side_for(n));
    while out.len() < n {
        let mut s = random_unit_segment(rng);
        let mut ok = false;
        // The new segment only ever shrinks along itself, so one pass in
        // index order suffices in exact arithmetic; the rounded new endpoint
        // may leave the line by an ulp, hence the re-check.
        for _round in 0..8 {
            if ok {
                break;
            }
            let mut near = Vec::new();
            grid.any_near(s, |id| {
                near.push(id);
                false
            });
            near.sort_unstable();
            for id in near {
                let t = out[id];
                if !closed_segments_meet(s, t) {
                    continue;
                }
                let (dx, dy) = (s[1][0] - s[0][0], s[1][1] - s[0][1]);
                let (ex, ey) = (t[1][0] - t[0][0], t[1][1] - t[0][1]);
                let den = dx * ey - dy * ex;
                let u = if den != 0.0 { ((t[0][0] - s[0][0]) * ey - (t[0][1] - s[0][1]) * ex) / den } else { 0.0 };
                let u = cmin(1.0, cmax(0.0, u));
                s[1] = [s[0][0] + 0.9 * u * dx, s[0][1] + 0.9 * u * dy];
            }
            ok = !grid.any_near(s, |id| closed_segments_meet(s, out[id]));
        }
        if !ok || s[0] == s[1] {
            continue; // degenerate leftovers: draw again
        }
        grid.add(s, out.len());
        out.push(s);
    }
    out
}

/// Seed 000, method 3: draw n segments; test the pairs (i, j), i < j, in
/// lexicographic order and swap the second endpoints of every crossing pair
/// (which shortens the total length, so it ends), until no pair crosses.
pub fn seg_random3(n: usize, rng: &mut Rng) -> Vec<Segment> {
    let mut s: Vec<Segment> = (0..n).map(|_| random_unit_segment(rng)).collect();
    let box_apart = |p: &Segment, q: &Segment| {
        cmax(p[0][0], p[1][0]) < cmin(q[0][0], q[1][0])
            || cmax(q[0][0], q[1][0]) < cmin(p[0][0], p[1][0])
            || cmax(p[0][1], p[1][1]) < cmin(q[0][1], q[1][1])
            || cmax(q[0][1], q[1][1]) < cmin(p[0][1], p[1][1])
    };
    let mut changed = true;
    while changed {
        changed = false;
        for i in 0..n {
            for j in i + 1..n {
                if box_apart(&s[i], &s[j]) || !closed_segments_meet(s[i], s[j]) {
                    continue;
                }
                let end = s[i][1];
                s[i][1] = s[j][1];
                s[j][1] = end;
                changed = true;
            }
        }
    }
    s
}

/// Short segments: random position and direction, length 1/sqrt(n) of the
/// unit square; a segment meeting an earlier one is dropped (and redrawn,
/// until there are n).
pub fn seg_short(n: usize, rng: &mut Rng) -> Vec<Segment> {
    let mut out: Vec<Segment> = Vec::new();
    let length = 1.0 / (n.max(1) as f64).sqrt();
    let mut grid = SegmentGrid::new([-length, -length], [1.0 + length, 1.0 + length], SegmentGrid::side_for(n));
    while out.len() < n {
        let a = [rng.unit(), rng.unit()];
        let angle = TWO_PI * rng.unit();
        let s = [a, [a[0] + length * angle.cos(), a[1] + length * angle.sin()]];
        if grid.any_near(s, |id| closed_segments_meet(s, out[id])) {
            continue;
        }
        grid.add(s, out.len());
        out.push(s);
    }
    out
}

/// A random walk of n short steps in the unit square that never meets
/// itself except where consecutive steps share their endpoint (a step that
/// would is redrawn; a walk that gets stuck restarts from a new random
/// point).
pub fn polyline(n: usize, rng: &mut Rng) -> Vec<Segment> {
    let mut out: Vec<Segment> = Vec::new();
    // Steps of random length: equal steps would make every sharp turn a
    // degenerate spike (the perpendiculars at both far ends meet the angle
    // bisector in one point), which the family is not meant to test.
    let unit_length = 0.5 / (n.max(1) as f64).sqrt();
    let mut grid = SegmentGrid::new([-0.1, -0.1], [1.1, 1.1], SegmentGrid::side_for(n));
    let mut at = [rng.unit(), rng.unit()];
    let mut stuck = 0;
    while out.len() < n {
        let angle = TWO_PI * rng.unit();
        let length = unit_length * (0.5 + rng.unit());
        let s = [at, [at[0] + length * angle.cos(), at[1] + length * angle.sin()]];
        let outside = s[1][0] < 0.0 || s[1][0] > 1.0 || s[1][1] < 0.0 || s[1][1] > 1.0;
        // The previous step shares `at` with this one: only an overlap is a
        // conflict there; with any other segment, any contact is.
        let conflict = |id: usize| {
            let previous = id + 1 == out.len() && out[id][1] == at;
            if previous {
                segments_conflict(s, out[id])
            } else {
                closed_segments_meet(s, out[id])
            }
        };
        if outside || grid.any_near(s, conflict) {
            stuck += 1;
            if stuck > 200 {
                at = [rng.unit(), rng.unit()];
                stuck = 0;
            }
            continue;
        }
        stuck = 0;
        grid.add(s, out.len());
        out.push(s);
        at = s[1];
    }
    out
}

/// n segments from the origin in evenly spaced directions, random lengths.
pub fn star(n: usize, rng: &mut Rng) -> Vec<Segment> {
    (0..n)
        .map(|k| {
            let angle = TWO_PI * k as f64 / n as f64;
            let r = 0.5 + rng.unit();
            [[0.0, 0.0], [r * angle.cos(), r * angle.sin()]]
        })
        .collect()
}

/// A square with a smaller, rotated, off-centre square hole: two closed
/// polygons of four segments each.
pub fn square_hole() -> Vec<Segment> {
    let outer = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]];
    let inner: Vec<Point> = (0..4)
        .map(|k| {
            let angle = 0.3 + 1.5707963267948966 * k as f64;
            [4.3 + 2.0 * angle.cos(), 5.7 + 2.0 * angle.sin()]
        })
        .collect();
    let mut out = Vec::new();
    add_closed_polygon(&outer, &mut out);
    add_closed_polygon(&inner, &mut out);
    out
}

/// The closed polygon through `corners` in order: one segment per corner.
fn add_closed_polygon(corners: &[Point], out: &mut Vec<Segment>) {
    for k in 0..corners.len() {
        out.push([corners[k], corners[(k + 1) % corners.len()]]);
    }
}

/// A random polygon star-shaped around `centre`: m corners at increasing
/// jittered angles (every angular gap is below pi, so the polygon is
/// simple) and radii in [r_min, r_max].
fn random_star_polygon(centre: Point, m: usize, r_min: f64, r_max: f64, rng: &mut Rng) -> Vec<Point> {
    let start = TWO_PI * rng.unit();
    (0..m)
        .map(|k| {
            let angle = start + TWO_PI * (k as f64 + 0.5 * rng.unit()) / m as f64;
            let r = r_min + (r_max - r_min) * rng.unit();
            [centre[0] + r * angle.cos(), centre[1] + r * angle.sin()]
        })
        .collect()
}

/// A random simple polygon with holes, n corners (= segments) in all: an
/// outer star-shaped polygon with radii in [0.9, 1] around the origin, and
/// h holes, each a smaller random star-shaped polygon inside its own cell
/// of a grid over [-0.55, 0.55]^2 (inside radius 0.78, so inside the outer
/// polygon; one hole per cell, so the holes are disjoint). Random
/// coordinates: generic.
pub fn polygon_holes(n: usize, rng: &mut Rng) -> Vec<Segment> {
    let holes = (n / 32).clamp(3, 32);
    let hole_corners = (n / (4 * holes)).max(3);
    let outer_corners = if n > holes * hole_corners + 3 { n - holes * hole_corners } else { 3 };
    let mut out = Vec::new();
    add_closed_polygon(&random_star_polygon([0.0, 0.0], outer_corners, 0.9, 1.0, rng), &mut out);
    let mut side = 1;
    while side * side < holes {
        side += 1;
    }
    let cell = 1.1 / side as f64;
    let mut cells: Vec<usize> = (0..side * side).collect();
    shuffle(&mut cells, rng);
    for &c in &cells[..holes] {
        let cx = -0.55 + cell * ((c % side) as f64 + 0.45 + 0.1 * rng.unit());
        let cy = -0.55 + cell * ((c / side) as f64 + 0.45 + 0.1 * rng.unit());
        let r_max = cell * (0.3 + 0.1 * rng.unit());
        add_closed_polygon(&random_star_polygon([cx, cy], hole_corners, 0.5 * r_max, r_max, rng), &mut out);
    }
    out
}

/// The integer lattice side x side cut into unit segments: every horizontal
/// and vertical unit segment between neighbouring lattice points, up to four
/// segments per point, every unit square a cocircular cell (degenerate).
/// side is the largest with 2 side (side - 1) <= n; shuffled, random
/// directions.
pub fn seg_lattice(n: usize, rng: &mut Rng) -> Vec<Segment> {
    let mut side = 2;
    while 2 * (side + 1) * side <= n {
        side += 1;
    }
    let mut out = Vec::new();
    for i in 0..side {
        for j in 0..side {
            let (x, y) = (i as f64, j as f64);
            if i + 1 < side {
                out.push([[x, y], [x + 1.0, y]]);
            }
            if j + 1 < side {
                out.push([[x, y], [x, y + 1.0]]);
            }
        }
    }
    shuffle(&mut out, rng);
    for s in &mut out {
        if rng.below(2) == 1 {
            s.swap(0, 1);
        }
    }
    out
}

/// Seed 000, figure 8 (3): n short segments tangent to the unit circle at
/// the angles 2 pi k / n, each half as long as the gap to its neighbours'
/// tangent lines allows (so none touch). The centre is equidistant from all
/// of them (degenerate, up to the rounding of the coordinates).
pub fn tangent(n: usize) -> Vec<Segment> {
    let pi = 3.141592653589793;
    let half = 0.5 * (pi / n as f64).tan();
    (0..n)
        .map(|k| {
            let angle = 2.0 * pi * k as f64 / n as f64;
            let (c, s) = (angle.cos(), angle.sin());
            [[c + half * s, s - half * c], [c - half * s, s + half * c]]
        })
        .collect()
}

/// Seed 000, figure 8 (4): n parallel segments (0, k)-(n, k), k = 0..n-1,
/// regularly spaced with aligned endpoints: exactly degenerate (the
/// endpoints lie on two lines, equally spaced).
pub fn parallel(n: usize) -> Vec<Segment> {
    (0..n).map(|k| [[0.0, k as f64], [n as f64, k as f64]]).collect()
}

/// Seed 000, figure 8 (5): the outline of a capital R on a 100 x 100 box,
/// its bowl approximated by straight pieces: an outer polygon of 15
/// segments and the counter (a hole) of 7, sharing endpoints at every
/// corner. Hand-picked integer coordinates with a font's alignments (the
/// stem's inner edge and the counter's left side on x = 20, the corners
/// (20, 40) and (20, 58) aligned, parallel horizontal runs), so not
/// generic. With `gaps`, segment k is shortened by its own amounts, between
/// 0.2 and 0.7, at each end, so that no two segments touch (the seed's form
/// of input) and no two pulled-apart endpoints line up again: equal gaps
/// would put the two endpoints of a corner symmetric about its angle
/// bisector, where both perpendiculars meet, a point equidistant from all
/// four sites.
pub fn letter_r(gaps: bool) -> Vec<Segment> {
    let outer: [Point; 15] = [
        [0.0, 0.0],
        [20.0, 0.0],
        [20.0, 40.0],
        [38.0, 40.0],
        [63.0, 0.0],
        [88.0, 0.0],
        [61.0, 44.0],
        [71.0, 48.0],
        [79.0, 55.0],
        [84.0, 65.0],
        [85.0, 74.0],
        [81.0, 84.0],
        [73.0, 92.0],
        [60.0, 100.0],
        [0.0, 100.0],
    ];
    let counter: [Point; 7] = [[20.0, 58.0], [57.0, 58.0], [63.0, 61.0], [66.0, 69.0], [65.0, 76.0], [59.0, 82.0], [20.0, 82.0]];
    let mut out = Vec::new();
    add_closed_polygon(&outer, &mut out);
    add_closed_polygon(&counter, &mut out);
    if gaps {
        for (k, s) in out.iter_mut().enumerate() {
            let golden = 0.6180339887498949 * k as f64;
            let silver = 0.41421356237309503 * k as f64 + 0.3;
            let start_gap = 0.2 + 0.5 * (golden - golden.floor());
            let end_gap = 0.2 + 0.5 * (silver - silver.floor());
            let [a, b] = *s;
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            let length = dx.hypot(dy);
            let (t0, t1) = (start_gap / length, end_gap / length);
            *s = [[a[0] + t0 * dx, a[1] + t0 * dy], [b[0] - t1 * dx, b[1] - t1 * dy]];
        }
    }
    out
}

/// Almost vertical segments (Boost.Polygon's Voronoi had bugs with vertical
/// and nearly vertical input): n segments of random length about
/// 1/sqrt(n) in the unit square whose x changes by at most 1e-9 of their
/// length. Every other segment, where it fits, continues the previous one
/// from its upper endpoint (a shared endpoint with a tiny kink); the rest
/// start at random points. A segment meeting an earlier one is redrawn.
/// Random coordinates: generic.
pub fn near_vertical(n: usize, rng: &mut Rng) -> Vec<Segment> {
    let mut out: Vec<Segment> = Vec::new();
    let unit_length = 1.0 / (n.max(1) as f64).sqrt();
    let mut grid = SegmentGrid::new([-0.1, -0.1], [1.1, 2.1], SegmentGrid::side_for(n));
    while out.len() < n {
        let chain = !out.is_empty() && rng.below(2) == 1;
        let a = if chain { out[out.len() - 1][1] } else { [rng.unit(), rng.unit()] };
        let length = unit_length * (0.5 + rng.unit());
        let dx = (2.0 * rng.unit() - 1.0) * 1e-9 * length;
        let s = [a, [a[0] + dx, a[1] + length]];
        if s[1][0] == s[0][0] || s[1][1] > 2.0 {
            continue; // exactly vertical, or off the grid
        }
        let conflict = |id: usize| {
            if chain && id + 1 == out.len() {
                segments_conflict(s, out[id])
            } else {
                closed_segments_meet(s, out[id])
            }
        };
        if grid.any_near(s, conflict) {
            continue;
        }
        grid.add(s, out.len());
        out.push(s);
    }
    out
}
