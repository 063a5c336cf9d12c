//! Splitting crossings (issue 11) against CGAL's segment Delaunay graph
//! with intersections, in one run on the same input: crossing road
//! networks of 10k, 100k and 1M segments, or real inputs read from files.
//!
//! `cargo run --release --bin split -- [--sizes 10000,100000,1000000] [--runs 3] [--budget 120] [--c 2]`
//! `cargo run --release --bin split -- --file PATH [--file PATH]... [--runs 3] [--budget 120]`
//!
//! `--file` replaces the road networks by the segments of each file
//! (Boost.Polygon's text format, without isolated points), e.g. GSHHG
//! coastlines, borders and rivers made by `scripts/coastlines.py`. Each row
//! also gives the machine's load average (1 minute, /proc/loadavg) when
//! the row started, since the machine may be shared.
//!
//! The input: n segments, each from a uniform point of the unit square in a
//! uniform direction, of length c/√n (c = 2 by default). Two such segments
//! cross with probability 2L²/π (Buffon, up to the border), so about
//! c²n/π crossings in all (1.27 n for c = 2): each segment crosses 2.5
//! others on average, as in a road network. The table gives the crossings
//! the split found.
//!
//! Ours, the median of `--runs`: `Builder::split_crossings(true)`,
//! `add_segments` and `build` (the split, then the diagram of the pieces);
//! then the pieces alone (`Diagram::piece`) built without splitting, the
//! diagram part of the first, so that their difference is the split. CGAL:
//! `cpp/cgal_split.cpp`, the segments inserted in the given order into
//! `Segment_Delaunay_graph_hierarchy_2` with
//! `Segment_Delaunay_graph_filtered_traits_2<K, Field_with_sqrt_tag>`
//! (CGAL splits at exact intersection points itself), the median of
//! `--runs` where they fit in `--budget` seconds, else one run; a size
//! whose estimate (the last size's time times the size ratio) exceeds the
//! budget is not run, and the table gives the estimate.

#[path = "../roads.rs"]
mod roads;
#[path = "../text.rs"]
mod text;

use roads::{roads, Segment};
use segvoronoi::Builder;
use std::time::Instant;
use text::thousands;

/// Where a row's input comes from.
enum Source {
    /// `roads(n, c, 11)`.
    Roads(usize, f64),
    /// A Boost text file.
    File(String),
}

impl Source {
    /// The row's label and its segments (made or read when the row runs, so
    /// that only one input is in memory at a time).
    fn load(&self) -> (String, Vec<Segment>) {
        match self {
            &Source::Roads(n, c) => (format!("roads, c = {c}"), roads(n, c, 11)),
            Source::File(path) => {
                let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
                let input = segvoronoi::boost_text::parse(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
                assert!(input.points.is_empty(), "{path}: isolated points are not supported here (CGAL's shim takes segments)");
                let name = std::path::Path::new(path).file_name().map_or(path.clone(), |f| f.to_string_lossy().into_owned());
                (name, input.segments.iter().map(|&[x0, y0, x1, y1]| [[x0, y0], [x1, y1]]).collect())
            }
        }
    }
}

/// The 1-minute load average, or "?" where /proc/loadavg is missing.
fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().map(str::to_string))
        .unwrap_or_else(|| "?".to_string())
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

struct Ours {
    total: f64,
    pieces_build: f64,
    crossings: usize,
    pieces: usize,
    sites: usize,
    rounds: usize,
    displacement: f64,
}

fn ours(input: &[Segment]) -> Ours {
    let start = Instant::now();
    let mut b = Builder::new();
    b.split_crossings(true);
    b.add_segments(input.iter().copied()).expect("finite segments");
    let d = b.build().expect("a diagram of the split input");
    let total = start.elapsed().as_secs_f64();
    let stats = d.stats();
    let displacement = d.max_split_displacement();
    let pieces: Vec<[segvoronoi::Point; 2]> = (0..d.piece_count()).filter_map(|j| d.piece(j)).collect();
    drop(d);

    let start = Instant::now();
    let mut b = Builder::new();
    b.add_segments(pieces.iter().copied()).expect("finite pieces");
    let built = b.build().expect("the pieces do not cross");
    let pieces_build = start.elapsed().as_secs_f64();
    assert_eq!(built.stats().sites, stats.sites, "the pieces give the same sites");
    Ours {
        total,
        pieces_build,
        crossings: stats.crossings,
        pieces: stats.pieces,
        sites: stats.sites,
        rounds: stats.snap_rounds,
        displacement,
    }
}

#[cfg(has_cgal_split)]
#[path = "../cgal_split.rs"]
mod cgal;

/// The CGAL cell of the table and the ratio to ours (`total`), timing it
/// unless the last size's time scaled by the size exceeds `budget`.
#[cfg(has_cgal_split)]
fn cgal_cells(
    input: &[Segment],
    n: usize,
    total: f64,
    runs: usize,
    budget: f64,
    last: &mut Option<(usize, f64)>,
) -> (String, String) {
    if let Some(e) = last.map(|(m, t)| t * n as f64 / m as f64).filter(|&e| e > budget) {
        return (format!("not run (est. {} from the last size)", seconds(e)), format!("~{:.0}x (est.)", e / total));
    }
    let mut times = Vec::new();
    let mut counts = (0, 0, 0);
    for k in 0..runs.max(1) {
        if k == 1 && times[0] * runs as f64 > budget {
            break;
        }
        let start = Instant::now();
        counts = cgal::build(input);
        times.push(start.elapsed().as_secs_f64());
    }
    let one_run = times.len() == 1 && runs > 1;
    let t = median(times);
    *last = Some((n, t));
    let cell = format!(
        "{}{} ({} sites, {} crossings)",
        seconds(t),
        if one_run { ", 1 run" } else { "" },
        thousands(counts.0),
        thousands(counts.1)
    );
    (cell, format!("{:.1}x", t / total))
}

#[cfg(not(has_cgal_split))]
fn cgal_cells(_: &[Segment], _: usize, _: f64, _: usize, _: f64, _: &mut Option<(usize, f64)>) -> (String, String) {
    ("not built (no CGAL)".to_string(), "-".to_string())
}

fn seconds(t: f64) -> String {
    if t < 1.0 {
        format!("{:.1} ms", t * 1e3)
    } else {
        format!("{t:.2} s")
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let value = |name: &str| args.iter().position(|a| a == name).map(|i| args[i + 1].clone());
    let sizes: Vec<usize> = value("--sizes")
        .map_or(vec![10_000, 100_000, 1_000_000], |s| s.split(',').map(|n| n.parse().expect("--sizes N,N,...")).collect());
    let runs: usize = value("--runs").map_or(3, |r| r.parse().expect("--runs R"));
    let budget: f64 = value("--budget").map_or(120.0, |r| r.parse().expect("--budget SECONDS"));
    let c: f64 = value("--c").map_or(2.0, |r| r.parse().expect("--c C"));
    let files: Vec<Source> = args.windows(2).filter(|w| w[0] == "--file").map(|w| Source::File(w[1].clone())).collect();
    let sources = if files.is_empty() { sizes.iter().map(|&n| Source::Roads(n, c)).collect() } else { files };

    println!(
        "| input | segments | crossings | pieces | snap rounds | max displacement | ours split + build | ours build of the pieces | split (difference) | CGAL with intersections | CGAL / ours | load |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|");
    let mut last_cgal: Option<(usize, f64)> = None;
    for source in &sources {
        let load = load_average();
        let (label, input) = source.load();
        let n = input.len();
        let results: Vec<Ours> = (0..runs.max(1)).map(|_| ours(&input)).collect();
        let total = median(results.iter().map(|r| r.total).collect());
        let pieces_build = median(results.iter().map(|r| r.pieces_build).collect());
        let r = &results[0];

        let (cgal_cell, ratio_cell) = cgal_cells(&input, n, total, runs, budget, &mut last_cgal);
        println!(
            "| {label} | {} | {} | {} | {} | {:.1e} | {} | {} | {} | {} (ours: {} sites) | {} | {load} |",
            thousands(n),
            thousands(r.crossings),
            thousands(r.pieces),
            r.rounds,
            r.displacement,
            seconds(total),
            seconds(pieces_build),
            seconds(total - pieces_build),
            cgal_cell,
            thousands(r.sites),
            ratio_cell
        );
    }
}
