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

#[path = "../offset_peers.rs"]
mod offset_peers;
#[path = "../peak.rs"]
mod peak;
#[path = "../sheet.rs"]
mod sheet;
#[path = "../text.rs"]
mod text;

#[cfg(has_clipper)]
use offset_peers::clipper;
#[cfg(has_geos)]
use offset_peers::geos;
use offset_peers::quadsegs_within;
use segvoronoi::Builder;
use sheet::{Polygon, HOLE, OUTER};
use std::time::Instant;
use text::seconds;

const TOLERANCE: f64 = 1e-4;
const ONE: f64 = -0.1;

fn distances() -> Vec<f64> {
    (0..100).map(|k| -(0.003 + (0.3 - 0.003) * k as f64 / 99.0)).collect()
}

/// GEOS's quadrant segments for tolerance `TOLERANCE` at `d`, and the
/// tolerance they give.
fn quadsegs(d: f64) -> (i32, f64) {
    quadsegs_within(d, TOLERANCE)
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
        let input = sheet::for_segments(n);
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
            others.push(("GEOS", other(&ds, b, |d| g.buffer_within(d, TOLERANCE))));
        }
        #[cfg(has_clipper)]
        {
            eprintln!("{segments} segments: Clipper");
            let c = clipper::Input::new(&input);
            let b = if segments > hundred_up_to { 0.0 } else { budget };
            others.push(("Clipper", other(&ds, b, |d| c.offset(d, quadsegs(d).1))));
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
