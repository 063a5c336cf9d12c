//! The inputs of the cross-check's randomised search: small random inputs
//! of several kinds, one drawn per case, each with a shuffled copy. The
//! harness (`segvoronoi_cgal_check --search`) reads them as a stream of
//! records from `segvoronoi-testgen search SEED` (see [`write_stream`]).
//!
//! Kinds: integer junctions (2..40 segments in [0, 20|1000|1e6]^2, 30% of
//! endpoints reused so that up to ten segments meet), stars (3..10 spokes
//! pointing in or out, a few points), polylines (2..40 steps, sometimes
//! closed), snapped floats (multiples of 2^-2..2^-6 with endpoint reuse),
//! small boost-split inputs, and near-degenerate ones (small-grid junctions
//! or snapped floats with points moved by a few ulps, zeros to subnormals,
//! or by 1e-12 or 1e-9). Junctions in [0, 20]^2 and snapped floats are
//! compared as degenerate, the rest as generic.

use std::collections::HashMap;
use std::io::{self, Write};

use crate::exact::{legal_addition, legal_point, same_point};
use crate::split::boost_split;
use crate::{next_after, power_of_two, shuffle, write_text, Input, Point, Rng, Segment, TWO_PI};

/// One case: the input as generated and its kind's name.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Case {
    pub input: Input,
    pub kind: String,
}

fn random_int(rng: &mut Rng, range: f64) -> f64 {
    (rng.unit() * (range + 1.0)).floor()
}

/// A point that is an earlier endpoint with probability `reuse` (half of
/// those from the first three distinct endpoints, the hubs, so that up to
/// ten segments meet at a point), else a fresh one from `fresh`.
fn pick_endpoint(ends: &[Point], reuse: f64, rng: &mut Rng, fresh: impl FnOnce(&mut Rng) -> Point) -> Point {
    if !ends.is_empty() && rng.unit() < reuse {
        let hubs = ends.len().min(3);
        return if rng.below(2) == 0 { ends[rng.below(hubs)] } else { ends[rng.below(ends.len())] };
    }
    fresh(rng)
}

/// Segments drawn one at a time (up to 40 tries each) and kept when legal.
fn draw_segments(n: usize, rng: &mut Rng, mut draw: impl FnMut(&mut Rng, &[Segment]) -> Segment) -> Vec<Segment> {
    let mut segs = Vec::new();
    for _ in 0..n {
        for _attempt in 0..40 {
            let mut s = draw(rng, &segs);
            if rng.below(2) == 1 {
                s.swap(0, 1);
            }
            if legal_addition(&segs, s) {
                segs.push(s);
                break;
            }
        }
    }
    segs
}

fn endpoints_of(segs: &[Segment]) -> Vec<Point> {
    let mut ends: Vec<Point> = Vec::new();
    for &p in segs.iter().flatten() {
        if !ends.iter().any(|&q| same_point(p, q)) {
            ends.push(p);
        }
    }
    ends
}

/// 0..=max isolated points, legal ones only (an endpoint repeated is legal).
fn add_points(input: &mut Input, max: usize, rng: &mut Rng, mut fresh: impl FnMut(&mut Rng) -> Point) {
    let count = rng.below(max + 1);
    for _ in 0..count {
        let p = fresh(rng);
        if legal_point(&input.segments, p) {
            input.points.push(p);
        }
    }
}

/// Kind 0..4 (see the module doc); with `generic_only`, junctions never
/// on the small grid, with `small_grid` always.
fn random_case_of(kind: usize, rng: &mut Rng, generic_only: bool, small_grid: bool) -> Case {
    let mut c = Case::default();
    let input = &mut c.input;
    match kind {
        0 => {
            // Integer junctions: endpoints in [0, range]^2, 30% of them
            // earlier endpoints; short or long segments.
            const RANGES: [f64; 3] = [20.0, 1000.0, 1e6];
            let r = if small_grid {
                0
            } else if generic_only {
                1 + rng.below(2)
            } else {
                rng.below(3)
            };
            let range = RANGES[r];
            let n = 2 + rng.below(39);
            let short_ones = rng.below(2) == 0;
            let fresh = move |rng: &mut Rng| [random_int(rng, range), random_int(rng, range)];
            input.segments = draw_segments(n, rng, |rng, segs| {
                let ends = endpoints_of(segs);
                let a = pick_endpoint(&ends, 0.3, rng, fresh);
                let b = pick_endpoint(&ends, 0.3, rng, |rng| {
                    if !short_ones {
                        return fresh(rng);
                    }
                    let reach = (range / 4.0).max(2.0);
                    [(a[0] + reach * (2.0 * rng.unit() - 1.0)).round(), (a[1] + reach * (2.0 * rng.unit() - 1.0)).round()]
                });
                [a, b]
            });
            add_points(input, 3, rng, fresh);
            input.degenerate = range < 100.0;
            c.kind = format!("junctions-{}", range as i64);
        }
        1 => {
            // A star: 3..10 spokes from one hub at random angles and
            // lengths, each pointing in or out at random, and a few points.
            let integer = rng.below(2) == 0;
            let range = if integer { 1e6 } else { 1.0 };
            let coordinate = move |v: f64| if integer { v.round() } else { v };
            let hub = [coordinate(range * (0.25 + 0.5 * rng.unit())), coordinate(range * (0.25 + 0.5 * rng.unit()))];
            let n = 3 + rng.below(8);
            input.segments = draw_segments(n, rng, |rng, _| {
                let (angle, length) = (TWO_PI * rng.unit(), range * (0.05 + 0.25 * rng.unit()));
                [hub, [coordinate(hub[0] + length * angle.cos()), coordinate(hub[1] + length * angle.sin())]]
            });
            add_points(input, 4, rng, |rng| [coordinate(range * rng.unit()), coordinate(range * rng.unit())]);
            c.kind = if integer { "star-int" } else { "star-double" }.into();
        }
        2 => {
            // A random polyline (sometimes closed) of 2..40 steps, each
            // segment in a random direction.
            let integer = rng.below(2) == 0;
            let range = if integer { 1e6 } else { 1.0 };
            let coordinate = move |v: f64| if integer { v.round() } else { v };
            let n = 2 + rng.below(39);
            let step = range * 0.5 / (n as f64).sqrt();
            let mut segs: Vec<Segment> = Vec::new();
            let mut at = [coordinate(range * rng.unit()), coordinate(range * rng.unit())];
            let first = at;
            let (mut k, mut tries) = (0, 0);
            while k < n && tries < 40 * n {
                tries += 1;
                let (angle, length) = (TWO_PI * rng.unit(), step * (0.3 + rng.unit()));
                let to = [coordinate(at[0] + length * angle.cos()), coordinate(at[1] + length * angle.sin())];
                if !legal_addition(&segs, [at, to]) {
                    continue;
                }
                segs.push([at, to]);
                at = to;
                k += 1;
            }
            if segs.len() >= 2 && rng.below(3) == 0 && legal_addition(&segs, [at, first]) {
                segs.push([at, first]);
            }
            for s in &mut segs {
                if rng.below(2) == 1 {
                    s.swap(0, 1);
                }
            }
            input.segments = segs;
            add_points(input, 2, rng, |rng| [coordinate(range * rng.unit()), coordinate(range * rng.unit())]);
            c.kind = if integer { "polyline-int" } else { "polyline-double" }.into();
        }
        3 => {
            // Snapped floats: random doubles rounded to 2..6 bits after the
            // binary point in [0, 4)^2 (exact repeats, collinear and
            // cocircular sites), with endpoint reuse: degenerate.
            let bits = 2 + rng.below(5);
            let scale = power_of_two(bits as i32);
            let snap = move |v: f64| (v * scale).round() / scale;
            let fresh = move |rng: &mut Rng| [snap(4.0 * rng.unit()), snap(4.0 * rng.unit())];
            let n = 2 + rng.below(24);
            input.segments = draw_segments(n, rng, |rng, segs| {
                let ends = endpoints_of(segs);
                let a = pick_endpoint(&ends, 0.3, rng, fresh);
                let b = pick_endpoint(&ends, 0.3, rng, |rng| {
                    [snap(a[0] + 2.0 * rng.unit() - 1.0), snap(a[1] + 2.0 * rng.unit() - 1.0)]
                });
                [a, b]
            });
            add_points(input, 3, rng, fresh);
            input.degenerate = true;
            c.kind = format!("snapped-{bits}");
        }
        _ => {
            // Boost.Polygon's benchmark style, small: 2..30 random segments
            // split at their crossings rounded to the integer grid.
            let side = if rng.below(2) == 0 { 1000.0 } else { 1e6 };
            let n = 2 + rng.below(29);
            input.segments = boost_split(n, rng, side);
            for s in &mut input.segments {
                if rng.below(2) == 1 {
                    s.swap(0, 1);
                }
            }
            c.kind = format!("split-{}", side as i64);
        }
    }
    c
}

/// Near-degenerate: a small-grid junction or snapped input (exact
/// coincidences everywhere) with every distinct point moved, with
/// probability one half, in x, y or both (shared endpoints move together);
/// segments and points that become illegal are left out. Compared as
/// generic.
fn nudged_case(rng: &mut Rng) -> Case {
    let base_kind = if rng.below(2) == 0 { 0 } else { 3 };
    let base = random_case_of(base_kind, rng, false, true);
    // ulps: nonzero coordinates by 1..4 ulps (zero stays); denormal: zero
    // coordinates by 1..4 times the least subnormal (the rest stays);
    // 1e-12, 1e-9: any coordinate by up to that much of the extent.
    let level = rng.below(4);
    const LEVEL_NAMES: [&str; 4] = ["ulps", "denormal", "1e-12", "1e-9"];
    let extent = if base.kind.starts_with("junctions") { 20.0 } else { 4.0 };
    let shift = |rng: &mut Rng, mut v: f64| -> f64 {
        if level <= 1 {
            if (v == 0.0) != (level == 1) {
                return v;
            }
            let up = rng.below(2) == 0;
            for _ in 0..1 + rng.below(4) {
                v = next_after(v, up);
            }
            return v;
        }
        v + (2.0 * rng.unit() - 1.0) * extent * if level == 2 { 1e-12 } else { 1e-9 }
    };
    // keyed by value (-0 as +0, as a std::map of doubles)
    let mut moved: HashMap<[u64; 2], Point> = HashMap::new();
    let mut nudge = |rng: &mut Rng, p: Point| -> Point {
        let key = [(p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits()];
        if let Some(&q) = moved.get(&key) {
            return q;
        }
        let mut q = p;
        if rng.below(2) == 0 {
            let axes = rng.below(3);
            if axes != 1 {
                q[0] = shift(rng, q[0]);
            }
            if axes != 0 {
                q[1] = shift(rng, q[1]);
            }
        }
        moved.insert(key, q);
        q
    };
    let mut c = Case::default();
    for &[a, b] in &base.input.segments {
        let a = nudge(rng, a);
        let t = [a, nudge(rng, b)];
        if legal_addition(&c.input.segments, t) {
            c.input.segments.push(t);
        }
    }
    for &p in &base.input.points {
        let q = nudge(rng, p);
        if legal_point(&c.input.segments, q) {
            c.input.points.push(q);
        }
    }
    let base_name = base.kind.split('-').next().unwrap_or_default();
    c.kind = format!("nudged-{base_name}-{}", LEVEL_NAMES[level]);
    c
}

/// One case of a random kind; with `generic_only`, only the kinds compared
/// as generic, and not the near-degenerate ones.
pub fn random_case(rng: &mut Rng, generic_only: bool) -> Case {
    let mut kind = rng.below(6);
    if generic_only && (kind == 3 || kind == 5) {
        kind = if rng.below(2) == 0 { 0 } else { 4 };
    }
    if kind == 5 {
        return nudged_case(rng);
    }
    random_case_of(kind, rng, generic_only, false)
}

/// The seed of the search's k-th case.
pub fn case_seed(seed: u64, k: u64) -> u64 {
    Rng(seed ^ 0xD1B5_4A32_D192_ED03u64.wrapping_mul(k + 1)).next_u64()
}

/// The k-th case of the search from `seed`, and its copy with the segments
/// and then the points shuffled (by the same generator, after the case).
pub fn case(seed: u64, k: u64, generic_only: bool) -> (Case, Input) {
    let mut rng = Rng(case_seed(seed, k));
    let c = random_case(&mut rng, generic_only);
    let mut order: Vec<usize> = (0..c.input.segments.len()).collect();
    shuffle(&mut order, &mut rng);
    let mut shuffled = c.input.clone();
    for (j, &o) in order.iter().enumerate() {
        shuffled.segments[j] = c.input.segments[o];
    }
    shuffle(&mut shuffled.points, &mut rng);
    (c, shuffled)
}

/// Writes the cases `0..count` (without end when `None`) of the search
/// from `seed`, one record each: a line `input K CASE_SEED KIND DEGENERATE`
/// (DEGENERATE 0 or 1), the input as generated and its shuffled copy, each
/// in Boost.Polygon's text format. Every case is written, also those
/// without segments (the harness skips them).
pub fn write_stream(out: &mut impl Write, seed: u64, generic_only: bool, count: Option<u64>) -> io::Result<()> {
    let mut k = 0u64;
    while count.map_or(true, |count| k < count) {
        let (c, shuffled) = case(seed, k, generic_only);
        writeln!(out, "input {k} {} {} {}", case_seed(seed, k), c.kind, u8::from(c.input.degenerate))?;
        write_text(out, &c.input.points, &c.input.segments)?;
        write_text(out, &shuffled.points, &shuffled.segments)?;
        k += 1;
    }
    out.flush()
}
