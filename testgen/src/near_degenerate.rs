//! Issue 7's near-degenerate families: polygons inscribed in a circle,
//! fans of equal spokes, chains with tiny kinks, points one ulp off a
//! line, chains open by one ulp, glyph outlines. The seed also picks the
//! scale.

use crate::exact::{legal_addition, legal_point, same_point};
use crate::{next_after, power_of_two, Input, Rng, Segment, TWO_PI};

/// The scale of a near-degenerate family's seed-th run: 1e-6, 1e-3, 1,
/// 1e3, 1e6 in turn, so that every magnitude meets the same shapes.
pub(crate) fn seed_scale(seed: u64) -> f64 {
    [1e-6, 1e-3, 1.0, 1e3, 1e6][(seed % 5) as usize]
}

/// A polygon inscribed in a circle: n corners on the circle of radius
/// seed_scale(seed) (rounded, so cocircular only to the last bit), at
/// regular angles or, jittered, each moved along the circle by up to a
/// third of the spacing. Issue 7's circles flattened into chords.
pub fn inscribed(n: usize, seed: u64, rng: &mut Rng, jitter: bool) -> Vec<Segment> {
    let (radius, spacing) = (seed_scale(seed), TWO_PI / n as f64);
    let corners: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let angle = spacing * (k as f64 + if jitter { (rng.unit() - 0.5) * 0.66 } else { 0.0 });
            [radius * angle.cos(), radius * angle.sin()]
        })
        .collect();
    (0..n).map(|k| [corners[k], corners[(k + 1) % n]]).collect()
}

/// n spokes of equal length from one point in random directions (at least
/// 1e-3 rad apart): their far ends lie on one circle up to rounding.
pub fn fan(n: usize, seed: u64, rng: &mut Rng) -> Vec<Segment> {
    let length = seed_scale(seed);
    let mut angles: Vec<f64> = Vec::new();
    while angles.len() < n {
        let a = TWO_PI * rng.unit();
        let apart = angles.iter().all(|&b| {
            let d = (a - b).abs();
            d.min(TWO_PI - d) >= 1e-3
        });
        if apart {
            angles.push(a);
        }
    }
    angles.into_iter().map(|a| [[0.0, 0.0], [length * a.cos(), length * a.sin()]]).collect()
}

/// A chain of n segments of unit-ish length along a gentle curve whose
/// every joint turns by 10^-(8 + seed % 8) rad, left or right at random:
/// chains with kinks of 1e-8 .. 1e-15 rad.
pub fn kinked_chain(n: usize, seed: u64, rng: &mut Rng) -> Vec<Segment> {
    let kink = 10f64.powf(-8.0 - (seed % 8) as f64);
    let mut heading = TWO_PI * rng.unit();
    let mut at = [0.0, 0.0];
    let mut out = Vec::with_capacity(n);
    for _ in 0..n {
        let length = 0.5 + rng.unit();
        let next = [at[0] + length * heading.cos(), at[1] + length * heading.sin()];
        out.push([at, next]);
        at = next;
        heading += if rng.unit() < 0.5 { kink } else { -kink };
    }
    out
}

/// Short random segments in the cells of a grid (one per cell, scaled by
/// seed_scale(seed)), and near each a point one ulp off its line, either
/// side: on the line's extension beyond an end, or beside the segment at a
/// third of its length (the point's y moved by one ulp from where the line
/// passes; kept when legal: not inside a segment).
pub fn ulp_off_line(n: usize, seed: u64, rng: &mut Rng, input: &mut Input) {
    let scale = seed_scale(seed);
    let side = (n as f64).sqrt().ceil() as usize;
    for k in 0..n {
        let (cx, cy) = ((k % side) as f64 * 4.0, (k / side) as f64 * 4.0);
        let a = [scale * (cx + rng.unit()), scale * (cy + rng.unit())];
        let b = [scale * (cx + 1.5 + rng.unit()), scale * (cy + 1.5 + rng.unit())];
        input.segments.push([a, b]);
    }
    for k in 0..input.segments.len() {
        let [a, b] = input.segments[k];
        let t = if rng.unit() < 0.5 { 1.0 / 3.0 } else { 1.5 };
        let x = a[0] + t * (b[0] - a[0]);
        // where the line passes at x, rounded, then one ulp up or down
        let y_line = a[1] + (x - a[0]) * (b[1] - a[1]) / (b[0] - a[0]);
        let y = next_after(y_line, rng.unit() < 0.5);
        let p = [x, y];
        if legal_point(&input.segments, p) && !same_point(p, a) && !same_point(p, b) {
            input.points.push(p);
        }
    }
}

/// Chains whose consecutive segments do not meet: each starts one ulp (in
/// x) from where the last ended, turned by a random angle (kept when legal).
pub fn ulp_ends(n: usize, seed: u64, rng: &mut Rng) -> Vec<Segment> {
    let scale = seed_scale(seed);
    let mut out: Vec<Segment> = Vec::new();
    let mut at = [0.0, 0.0];
    let mut heading = 0.0;
    let mut tries = 0;
    while out.len() < n && tries < 20 * n {
        tries += 1;
        heading += (rng.unit() - 0.5) * 2.5;
        let length = scale * (0.5 + rng.unit());
        let start = [next_after(at[0], rng.unit() < 0.5), at[1]];
        let s = [start, [start[0] + length * f64::cos(heading), start[1] + length * f64::sin(heading)]];
        if !legal_addition(&out, s) {
            continue;
        }
        out.push(s);
        at = s[1];
    }
    out
}

/// Glyph-like outlines: the rings of an "O" (an outer and an inner
/// ellipse, off-centre, a thin stroke on one side), each flattened into
/// n / 2 chords at font-unit precision (corners rounded to integers, as
/// TrueType glyphs are), the whole scaled by a power of two by seed.
pub fn glyph(n: usize, seed: u64, rng: &mut Rng) -> Vec<Segment> {
    let unit = power_of_two((seed % 5) as i32 * 4 - 8);
    let chords = (n / 2).max(3);
    let mut out: Vec<Segment> = Vec::new();
    let rings = [[0.0, 0.0, 600.0, 720.0], [40.0 + 20.0 * rng.unit(), 0.0, 470.0, 610.0]];
    for ring in rings {
        let mut corners: Vec<[f64; 2]> = Vec::new();
        for k in 0..chords {
            let angle = TWO_PI * (k as f64 + 0.3 * rng.unit()) / chords as f64;
            let p = [unit * (ring[0] + ring[2] * angle.cos()).round(), unit * (ring[1] + ring[3] * angle.sin()).round()];
            if corners.last().map_or(true, |&q| !same_point(q, p)) {
                corners.push(p);
            }
        }
        while corners.len() > 1 && same_point(corners[0], corners[corners.len() - 1]) {
            corners.pop();
        }
        for k in 0..corners.len() {
            let s = [corners[k], corners[(k + 1) % corners.len()]];
            if legal_addition(&out, s) {
                out.push(s);
            }
        }
    }
    out
}

/// In the cells of a grid (scaled by seed_scale(seed)): a long segment,
/// a shorter one parallel to it and 1, 2, 7, 2^10, 2^20 or 2^30 ulps (by
/// cell) to one side of it, within its extent, a point on the shorter
/// one's far side, and in every other cell a leg from the shorter one's end
/// towards the point. Horizontal, or vertical (exactly parallel at any
/// offset) mirrored across the diagonal into the negative quadrant, by cell. Issue 28's open case: the circle through the
/// shorter one's endpoints tangent to the long one lies at 1e9 and beyond,
/// and the margin of their edge is below the rounding of its distances.
pub fn ulp_parallel(n: usize, seed: u64, rng: &mut Rng, input: &mut Input) {
    const OFFSETS: [u32; 6] = [1, 2, 7, 1 << 10, 1 << 20, 1 << 30];
    let scale = seed_scale(seed);
    let side = (n as f64).sqrt().ceil() as usize;
    for k in 0..n {
        let (cx, cy) = ((k % side) as f64 * 6.0, (k / side) as f64 * 6.0);
        let y = scale * (cy + 2.0 + rng.unit());
        let (x0, x1) = (scale * (cx + rng.unit()), scale * (cx + 3.0 + rng.unit()));
        let (u, v) = (x0 + (x1 - x0) * (0.1 + 0.3 * rng.unit()), x0 + (x1 - x0) * (0.6 + 0.3 * rng.unit()));
        let up = rng.unit() < 0.5;
        // y > 0: the bit pattern grows upward
        let ulps = u64::from(OFFSETS[k % OFFSETS.len()]);
        let y_short = f64::from_bits(if up { y.to_bits() + ulps } else { y.to_bits() - ulps });
        let away = if up { scale } else { -scale };
        let point = [u + (v - u) * rng.unit(), y_short + away * (0.1 + 0.8 * rng.unit())];
        let mut cell = vec![[[x0, y], [x1, y]], [[u, y_short], [v, y_short]]];
        if k % 2 == 0 {
            cell.push([[u, y_short], [u, y_short + away * 0.05]]);
        }
        // vertical cells mirrored across the diagonal into the negative
        // quadrant (exact: the offsets stay those ulps)
        let vertical = (k / 2) % 2 == 1;
        let place = |[x, y]: [f64; 2]| if vertical { [-y, -x] } else { [x, y] };
        input.segments.extend(cell.into_iter().map(|s| s.map(place)));
        input.points.push(place(point));
    }
}
