//! Offsets (issue 10) against GEOS's buffer and Clipper's offset, in one
//! run on the same input: polygons with holes of 10k, 100k and 1M segments
//! in total, at one distance and at 100.
//!
//! `cargo run --release --bin offsets -- [--sizes 10000,100000,1000000] [--runs 3] [--budget 60] [--hundred-up-to N]`
//!
//! `cargo run --release --bin offsets -- --rings FILE [--runs 3]`: a real
//! outline instead (a rings file as `scripts/country_rings.py` writes it),
//! beside GEOS's buffer at distances relative to its size (`src/offsets_outline.rs`).
//!
//! The input is a grid of star-shaped polygons (testgen's `star_ring`,
//! random radii), each of 400 corners (radii 0.8..1) with a star-shaped
//! hole of 100 (radii 0.2..0.35), 2.2 apart: many polygons with holes, as
//! a sheet of parts to pocket. The wall between hole and outer ring is 0.45
//! to 0.8 wide, so the inscribed radius is at most 0.4. Distances are
//! negative (the parts shrink, as for pocketing; growing would merge the
//! parts of the grid beyond 0.1): one distance, -0.1, and 100 spread evenly
//! from -0.003 to -0.3, where most of the walls have vanished.
//!
//! Tolerance: t = 1e-4 (about 1e-4 of a part's radius). At each distance d
//! GEOS gets quadsegs q = the smallest with d (1 - cos(pi / (4 q))) <= t,
//! and ours and Clipper are sampled at that tolerance exactly, so the vertex
//! counts compare at one tolerance. Clipper works on integers: the
//! coordinates are scaled to 2^28 over the extent.
//!
//! Ours, each the median of `--runs`: the build (`add_polygon` of every
//! part and `build`), `offset(-0.1)`, the polylines of that offset,
//! `offsets(&[100 distances])` and the polylines of all 100. GEOS: one
//! buffer of the whole input (one MultiPolygon) at -0.1, and the 100
//! distances. Clipper: one ClipperOffset of all rings at -0.1, and the 100.
//! For GEOS and Clipper the 100 are timed in full while they fit in
//! `--budget` seconds (estimated from the single run); beyond that an
//! evenly spread subset of the distances is timed and scaled to 100 (the
//! table says "est. from k"). Above `--hundred-up-to N` segments only their
//! single distance is timed, and their x100 is the last smaller size's
//! scaled by the ratio of the single runs (GEOS's buffer of the 1M input at
//! -0.15 or -0.3 took more than the 23 GB of the machine it was written on).

#[path = "../offsets_outline.rs"]
mod outline;

use segvoronoi::Builder;
use segvoronoi_testgen::{shapes::star_ring, Rng};
use std::f64::consts::PI;
use std::time::Instant;

const OUTER: usize = 400;
const HOLE: usize = 100;
const TOLERANCE: f64 = 1e-4;
const ONE: f64 = -0.1;

type Polygon = [Vec<[f64; 2]>; 2];

/// `polygons` star polygons with holes on a square grid; the holes run
/// clockwise (as Clipper wants them).
fn polygons(polygons: usize, seed: u64) -> Vec<Polygon> {
    let mut rng = Rng(seed);
    let side = (polygons as f64).sqrt().ceil() as usize;
    (0..polygons)
        .map(|k| {
            let (cx, cy) = ((k % side) as f64 * 2.2, (k / side) as f64 * 2.2);
            let outer = star_ring(OUTER, cx, cy, 0.8, 1.0, &mut rng);
            let mut hole = star_ring(HOLE, cx, cy, 0.2, 0.35, &mut rng);
            hole.reverse();
            [outer, hole]
        })
        .collect()
}

fn distances() -> Vec<f64> {
    (0..100).map(|k| -(0.003 + (0.3 - 0.003) * k as f64 / 99.0)).collect()
}

/// GEOS's quadrant segments for tolerance `TOLERANCE` at `d`, and the
/// tolerance they give.
fn quadsegs(d: f64) -> (i32, f64) {
    quadsegs_within(d, TOLERANCE)
}

/// GEOS's quadrant segments for tolerance `tolerance` at `d` (the fewest
/// whose chords stay within it), and the tolerance they give.
fn quadsegs_within(d: f64, tolerance: f64) -> (i32, f64) {
    let r = d.abs();
    let q = (PI / (4.0 * (1.0 - (tolerance / r).min(1.0)).acos())).ceil().max(1.0);
    (q as i32, r * (1.0 - (PI / (4.0 * q)).cos()))
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

struct Ours {
    build: f64,
    one: f64,
    one_sampling: f64,
    hundred: f64,
    hundred_sampling: f64,
    one_vertices: usize,
    one_loops: usize,
    hundred_vertices: usize,
}

fn ours(input: &[Polygon], ds: &[f64]) -> Ours {
    let start = Instant::now();
    let mut b = Builder::new();
    for rings in input {
        b.add_polygon(rings).expect("simple, disjoint rings");
    }
    let d = b.build().expect("a diagram");
    let build = start.elapsed().as_secs_f64();

    let start = Instant::now();
    let one = d.offset(ONE).expect("an offset");
    let one_s = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let lines = one.polylines(quadsegs(ONE).1).expect("a tolerance");
    let one_sampling = start.elapsed().as_secs_f64();
    let one_vertices = lines.iter().map(Vec::len).sum();

    let start = Instant::now();
    let all = d.offsets(ds).expect("offsets");
    let hundred = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let hundred_vertices =
        all.iter().map(|o| o.polylines(quadsegs(o.distance).1).expect("a tolerance").iter().map(Vec::len).sum::<usize>()).sum();
    let hundred_sampling = start.elapsed().as_secs_f64();
    Ours {
        build,
        one: one_s,
        one_sampling,
        hundred,
        hundred_sampling,
        one_vertices,
        one_loops: one.loops.len(),
        hundred_vertices,
    }
}

#[cfg_attr(not(any(has_geos, has_clipper)), allow(dead_code))]
/// One contender's results: the single distance, and the 100 (measured in
/// full or from `measured` of them).
struct Other {
    one: f64,
    one_vertices: usize,
    one_rings: usize,
    hundred: f64,
    measured: usize,
    hundred_vertices: Option<usize>,
}

#[cfg_attr(not(any(has_geos, has_clipper)), allow(dead_code))]
/// Times `run(d) -> (vertices, rings)` at ONE and at the distances, within
/// `budget` seconds for the 100.
/// With `budget` 0 only the single distance is timed (`measured` = 0).
fn other(ds: &[f64], budget: f64, mut run: impl FnMut(f64) -> (usize, usize)) -> Other {
    let start = Instant::now();
    let (one_vertices, one_rings) = run(ONE);
    let one = start.elapsed().as_secs_f64();
    if budget <= 0.0 {
        return Other { one, one_vertices, one_rings, hundred: f64::NAN, measured: 0, hundred_vertices: None };
    }
    let k = if one * ds.len() as f64 <= budget { ds.len() } else { ((budget / one) as usize).clamp(3, ds.len()) };
    let picked: Vec<f64> = (0..k).map(|i| ds[i * (ds.len() - 1) / (k - 1).max(1)]).collect();
    let start = Instant::now();
    let vertices: usize = picked.iter().map(|&d| run(d).0).sum();
    let elapsed = start.elapsed().as_secs_f64();
    Other {
        one,
        one_vertices,
        one_rings,
        hundred: elapsed * ds.len() as f64 / k as f64,
        measured: k,
        hundred_vertices: (k == ds.len()).then_some(vertices),
    }
}

#[cfg(has_geos)]
mod geos {
    use super::quadsegs_within;
    use std::ffi::c_void;

    extern "C" {
        fn geos_bench_new(xy: *const f64, lengths: *const usize, rings: *const usize, n_polygons: usize) -> *mut c_void;
        fn geos_bench_buffer(input: *mut c_void, distance: f64, quadsegs: i32, vertices: *mut usize, rings: *mut usize) -> i32;
        fn geos_bench_free(input: *mut c_void);
    }

    /// The input as one GEOS MultiPolygon.
    pub struct Input(*mut c_void);

    impl Input {
        /// Polygons, each its outer ring and then its holes.
        pub fn new<P: AsRef<[Vec<[f64; 2]>]>>(input: &[P]) -> Input {
            let xy: Vec<f64> = input.iter().flat_map(|p| p.as_ref().iter().flatten().flatten().copied()).collect();
            let lengths: Vec<usize> = input.iter().flat_map(|p| p.as_ref().iter().map(Vec::len)).collect();
            let rings: Vec<usize> = input.iter().map(|p| p.as_ref().len()).collect();
            // SAFETY: the arrays hold what the lengths say; GEOS copies them.
            let raw = unsafe { geos_bench_new(xy.as_ptr(), lengths.as_ptr(), rings.as_ptr(), input.len()) };
            assert!(!raw.is_null(), "GEOS input");
            Input(raw)
        }

        /// Buffer at `d` with the benchmark's tolerance: (vertices, rings).
        pub fn buffer(&self, d: f64) -> (usize, usize) {
            self.buffer_within(d, super::TOLERANCE)
        }

        /// Buffer at `d` within `tolerance`: (vertices, rings).
        pub fn buffer_within(&self, d: f64, tolerance: f64) -> (usize, usize) {
            let (mut vertices, mut rings) = (0, 0);
            // SAFETY: a live handle and two out-parameters.
            let status = unsafe { geos_bench_buffer(self.0, d, quadsegs_within(d, tolerance).0, &mut vertices, &mut rings) };
            assert_eq!(status, 0, "GEOS buffer failed");
            (vertices, rings)
        }
    }

    impl Drop for Input {
        fn drop(&mut self) {
            // SAFETY: made by geos_bench_new, freed once.
            unsafe { geos_bench_free(self.0) }
        }
    }
}

#[cfg(has_clipper)]
mod clipper {
    use super::{quadsegs, Polygon};
    use std::ffi::c_void;

    extern "C" {
        fn clipper_bench_new(xy: *const i64, lengths: *const usize, n_rings: usize) -> *mut c_void;
        fn clipper_bench_offset(
            paths: *const c_void,
            delta: f64,
            arc_tolerance: f64,
            vertices: *mut usize,
            rings: *mut usize,
        ) -> i32;
        fn clipper_bench_free(paths: *mut c_void);
    }

    /// The input's rings on Clipper's integer grid (2^28 over the extent).
    pub struct Input {
        paths: *mut c_void,
        scale: f64,
    }

    impl Input {
        pub fn new(input: &[Polygon]) -> Input {
            let points = || input.iter().flat_map(|p| p.iter().flatten());
            let (lo, hi) = points().fold(([f64::MAX; 2], [f64::MIN; 2]), |(lo, hi), p| {
                ([lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])])
            });
            let scale = 2f64.powi(28) / (hi[0] - lo[0]).max(hi[1] - lo[1]);
            let xy: Vec<i64> = points()
                .flat_map(|p| [((p[0] - lo[0]) * scale).round() as i64, ((p[1] - lo[1]) * scale).round() as i64])
                .collect();
            let lengths: Vec<usize> = input.iter().flat_map(|p| p.iter().map(Vec::len)).collect();
            // SAFETY: the arrays hold what the lengths say; Clipper copies them.
            let paths = unsafe { clipper_bench_new(xy.as_ptr(), lengths.as_ptr(), lengths.len()) };
            Input { paths, scale }
        }

        /// Offset at `d` with the benchmark's tolerance: (vertices, rings).
        pub fn offset(&self, d: f64) -> (usize, usize) {
            let (mut vertices, mut rings) = (0, 0);
            let tolerance = quadsegs(d).1 * self.scale;
            // SAFETY: a live handle and two out-parameters.
            let status = unsafe { clipper_bench_offset(self.paths, d * self.scale, tolerance, &mut vertices, &mut rings) };
            assert_eq!(status, 0, "Clipper offset failed");
            (vertices, rings)
        }
    }

    impl Drop for Input {
        fn drop(&mut self) {
            // SAFETY: made by clipper_bench_new, freed once.
            unsafe { clipper_bench_free(self.paths) }
        }
    }
}

fn seconds(s: f64) -> String {
    if s >= 100.0 {
        format!("{s:.0} s")
    } else if s >= 1.0 {
        format!("{s:.2} s")
    } else {
        format!("{:.1} ms", s * 1e3)
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |name: &str| args.iter().position(|a| a == name).and_then(|i| args.get(i + 1));
    if let Some(path) = value("--rings") {
        let runs: usize = value("--runs").map_or(3, |r| r.parse().expect("--runs R"));
        outline::run(path, runs);
        return;
    }
    let sizes: Vec<usize> = value("--sizes")
        .map(|s| s.split(',').map(|n| n.parse().expect("--sizes N,N,..")).collect())
        .unwrap_or_else(|| vec![10_000, 100_000, 1_000_000]);
    let runs: usize = value("--runs").map_or(3, |r| r.parse().expect("--runs R"));
    let budget: f64 = value("--budget").map_or(60.0, |r| r.parse().expect("--budget SECONDS"));
    let hundred_up_to: usize = value("--hundred-up-to").map_or(usize::MAX, |r| r.parse().expect("--hundred-up-to N"));
    // per contender, the last size where the 100 were timed: (x1, x100)
    let mut last: Vec<Option<(f64, f64)>> = vec![None; 2];
    #[cfg(not(has_geos))]
    eprintln!("warning: the geos contender was not compiled in (libgeos-dev missing?)");
    #[cfg(not(has_clipper))]
    eprintln!("warning: the clipper contender was not compiled in (libpolyclipping-dev missing?)");
    #[cfg(not(any(has_geos, has_clipper)))]
    let _ = budget;
    let ds = distances();
    let mut times = Vec::new();
    let mut counts = Vec::new();
    for n in sizes {
        let input = polygons(n.div_ceil(OUTER + HOLE), 1);
        let segments = input.len() * (OUTER + HOLE);
        eprintln!("{segments} segments: ours");
        let results: Vec<Ours> = (0..runs).map(|_| ours(&input, &ds)).collect();
        let m = |f: fn(&Ours) -> f64| median(results.iter().map(f).collect());
        let o = &results[0];
        let (build, one, one_s, hundred, hundred_s) =
            (m(|t| t.build), m(|t| t.one), m(|t| t.one_sampling), m(|t| t.hundred), m(|t| t.hundred_sampling));
        let mut others: Vec<(&str, Other)> = Vec::new();
        #[cfg(has_geos)]
        {
            eprintln!("{segments} segments: GEOS");
            let g = geos::Input::new(&input);
            let b = if segments > hundred_up_to { 0.0 } else { budget };
            others.push(("GEOS", other(&ds, b, |d| g.buffer(d))));
        }
        #[cfg(has_clipper)]
        {
            eprintln!("{segments} segments: Clipper");
            let c = clipper::Input::new(&input);
            let b = if segments > hundred_up_to { 0.0 } else { budget };
            others.push(("Clipper", other(&ds, b, |d| c.offset(d))));
        }
        let ours_one = build + one + one_s;
        let ours_hundred = hundred + hundred_s;
        let mut row = format!(
            "| {segments} | {} | {} | {} | {} | {} | {} |",
            seconds(build),
            seconds(one),
            seconds(one_s),
            seconds(hundred),
            seconds(hundred_s),
            seconds(ours_one)
        );
        let mut vrow = format!("| {segments} | {} ({} loops) | {} |", o.one_vertices, o.one_loops, o.hundred_vertices);
        for (i, (_, r)) in others.iter_mut().enumerate() {
            let est = if r.measured == 0 {
                // x100 from the last size timed, scaled by the ratio of the single runs
                match last[i] {
                    Some((one, hundred)) => {
                        r.hundred = hundred * r.one / one;
                        " (est.: smaller size's x100 times the ratio of x1)".to_string()
                    }
                    None => " (not timed)".to_string(),
                }
            } else {
                last[i] = Some((r.one, r.hundred));
                if r.measured < ds.len() {
                    format!(" (est. from {})", r.measured)
                } else {
                    String::new()
                }
            };
            row += &format!(
                " {} | {}{est} | {:.1}x | {:.1}x |",
                seconds(r.one),
                seconds(r.hundred),
                r.one / ours_one,
                r.hundred / ours_hundred
            );
            vrow += &format!(
                " {} ({} rings) | {} |",
                r.one_vertices,
                r.one_rings,
                r.hundred_vertices.map_or("-".to_string(), |v| v.to_string())
            );
        }
        // each size's rows as soon as they are measured (the table comes at the end)
        eprintln!("{row}\n{vrow}");
        times.push(row);
        counts.push(vrow);
    }
    let names: Vec<&str> = [
        #[cfg(has_geos)]
        "GEOS",
        #[cfg(has_clipper)]
        "Clipper",
    ]
    .to_vec();
    println!();
    let mut header =
        "| segments | build | offset x1 | polylines x1 | offsets x100 | polylines x100 | build + x1 + polylines |".to_string();
    let mut rule = "|---|---|---|---|---|---|---|".to_string();
    for n in &names {
        header += &format!(" {n} x1 | {n} x100 | {n} x1 / ours (build + x1) | {n} x100 / ours x100 |");
        rule += "---|---|---|---|";
    }
    println!("{header}\n{rule}");
    for r in &times {
        println!("{r}");
    }
    println!();
    let mut header = "| segments | vertices ours x1 | ours x100 |".to_string();
    let mut rule = "|---|---|---|".to_string();
    for n in &names {
        header += &format!(" {n} x1 | {n} x100 |");
        rule += "---|---|";
    }
    println!("{header}\n{rule}");
    for r in &counts {
        println!("{r}");
    }
}
