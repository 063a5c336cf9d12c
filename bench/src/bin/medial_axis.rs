//! The cost of the medial axis against the build it comes from, on polygons
//! with holes totalling 100k and 1M segments (issue 9's goal: the medial
//! axis with sampling under 15 % of the build).
//!
//! `cargo run --release --bin medial_axis -- [--sizes 100000,1000000] [--runs 3]`
//!
//! The input is a grid of star-shaped polygons (testgen's `star_ring`,
//! random radii, so no two corners are cocircular by construction), each of
//! 400 corners with a star-shaped hole of 100, disjoint. Per size and run,
//! one process times: the build (`Builder::add_polygon` of every polygon
//! and `build`), `medial_axis()`, the sampling of every chain within 1e-4
//! of the bounding-box diagonal (`sample_chain`), and the axis with both
//! filters on (`medial_axis_filtered`). The medians are printed as a table,
//! each step also as a fraction of the build.

#[path = "../sheet.rs"]
mod sheet;

use segvoronoi::{Builder, MedialAxisFilter};
use sheet::{Polygon, HOLE, OUTER};
use std::time::Instant;

struct Times {
    build: f64,
    axis: f64,
    sampling: f64,
    filtered: f64,
    samples: usize,
    chains: usize,
}

fn measure(input: &[Polygon]) -> Times {
    let start = Instant::now();
    let mut b = Builder::new();
    for rings in input {
        b.add_polygon(rings).expect("simple, disjoint rings");
    }
    let d = b.build().expect("a diagram");
    let build = start.elapsed().as_secs_f64();

    let start = Instant::now();
    let axis = d.medial_axis();
    let axis_s = start.elapsed().as_secs_f64();

    let start = Instant::now();
    let tolerance = 1e-4 * d.extent();
    let samples: usize = axis.chains.iter().map(|c| d.sample_chain(c, tolerance).map_or(0, |p| p.len())).sum();
    let sampling = start.elapsed().as_secs_f64();

    let start = Instant::now();
    let filter = MedialAxisFilter::new().with_corner_angle(160.0).with_spur_pruning(1.5);
    let filtered = d.medial_axis_filtered(&filter);
    let filtered_s = start.elapsed().as_secs_f64();
    assert!(!filtered.chains.is_empty());
    Times { build, axis: axis_s, sampling, filtered: filtered_s, samples, chains: axis.chains.len() }
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |name: &str| args.iter().position(|a| a == name).and_then(|i| args.get(i + 1));
    let sizes: Vec<usize> = value("--sizes")
        .map(|s| s.split(',').map(|n| n.parse().expect("--sizes N,N,..")).collect())
        .unwrap_or_else(|| vec![100_000, 1_000_000]);
    let runs: usize = value("--runs").map_or(3, |r| r.parse().expect("--runs R"));
    println!("| segments | build | medial_axis | sampling | axis + sampling | filtered axis | chains | samples |");
    println!("|---|---|---|---|---|---|---|---|");
    for n in sizes {
        let input = sheet::for_segments(n);
        let segments = input.len() * (OUTER + HOLE);
        let times: Vec<Times> = (0..runs).map(|_| measure(&input)).collect();
        let m = |f: fn(&Times) -> f64| median(times.iter().map(f).collect());
        let (build, axis, sampling, filtered) = (m(|t| t.build), m(|t| t.axis), m(|t| t.sampling), m(|t| t.filtered));
        let share = |s: f64| format!("{:.3} s ({:.1} %)", s, 100.0 * s / build);
        println!(
            "| {segments} | {build:.3} s | {} | {} | {} | {} | {} | {} |",
            share(axis),
            share(sampling),
            share(axis + sampling),
            share(filtered),
            times[0].chains,
            times[0].samples
        );
    }
}
