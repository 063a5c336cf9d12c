//! The figures of the parallel build's scaling model (issue 33,
//! `docs/studies/parallel-build.md`): for uniform random points and short
//! random segments at the sizes given, the build at one thread and at two
//! (in halves), with the parts of the two-thread build that
//! `diagnostics::take_halves_report` times (the plan, the halves with the
//! input check beside them, the glue) and the sites each half held.
//!
//! Also `lattice` (a square lattice of points: every vertex degenerate,
//! those on the cut cut two ways by the halves) and `raster` (the outline
//! of a random raster, unit edges between filled and empty pixels, SIZE
//! pixels).
//!
//! `cargo run --release --example halves_scaling -- [points|segments|lattice|raster] [SIZE ...]`
//! (default: points and segments, 1M).

use segvoronoi::diagnostics::take_halves_report;
use segvoronoi::splitmix::SplitMix64;
use segvoronoi::Builder;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let kinds: Vec<&str> = match args.first().map(String::as_str) {
        Some(k @ ("points" | "segments" | "lattice" | "raster")) => vec![k],
        _ => vec!["points", "segments"],
    };
    let sizes: Vec<usize> = args.iter().filter_map(|a| a.parse().ok()).collect();
    let sizes = if sizes.is_empty() { vec![1_000_000] } else { sizes };
    println!("| input | size | 1 thread | 2 threads | speed-up | plan | halves | glue | rest | held by the halves |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for kind in kinds {
        for &n in &sizes {
            let mut b = Builder::new();
            let mut rng = SplitMix64(7);
            if kind == "points" {
                b.add_points((0..n).map(|_| [rng.unit(), rng.unit()])).expect("finite");
            } else if kind == "lattice" {
                let k = (n as f64).sqrt().ceil() as usize;
                b.add_points((0..n).map(|i| [(i % k) as f64, (i / k) as f64])).expect("finite");
            } else if kind == "raster" {
                b.add_segments(raster_outline((n as f64).sqrt().ceil() as i64, &mut rng)).expect("finite");
            } else {
                // one segment of length 0.3 per unit cell, starting in its
                // lower left 0.3 x 0.3: none meet
                let k = (n as f64).sqrt().ceil() as usize;
                b.add_segments((0..n).map(|i| {
                    let (x, y) = ((i % k) as f64 + 0.3 * rng.unit(), (i / k) as f64 + 0.3 * rng.unit());
                    let a = rng.unit() * std::f64::consts::TAU;
                    [[x, y], [x + 0.3 * a.cos(), y + 0.3 * a.sin()]]
                }))
                .expect("finite");
            }
            let one = time(|| b.threads(1).build().map(|_| ()));
            let two = time(|| b.threads(2).build().map(|_| ()));
            let r = take_halves_report().unwrap_or_default();
            let [plan, halves, glue] = r.times.map(|t| t.as_secs_f64());
            println!(
                "| {kind} | {n} | {one:.3} s | {two:.3} s | {:.2}x | {plan:.3} s | {halves:.3} s | {glue:.3} s | {:.3} s | {} + {} of {} ({:.1} % more){} |",
                one / two,
                two - plan - halves - glue,
                r.held[0],
                r.held[1],
                r.sites,
                100.0 * ((r.held[0] + r.held[1]) as f64 / r.sites as f64 - 1.0),
                if r.glued { if r.attempts > 1 { ", 2 attempts" } else { "" } } else { ", not glued" },
            );
        }
    }
}

/// Seconds of the fastest of three runs.
fn time(mut build: impl FnMut() -> Result<(), segvoronoi::Error>) -> f64 {
    (0..3)
        .map(|_| {
            let start = Instant::now();
            build().expect("a diagram");
            start.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

/// The outline of a random `k` x `k` raster, each pixel filled with
/// probability 1/2: a unit edge between every filled pixel and an empty
/// one (or the outside).
fn raster_outline(k: i64, rng: &mut SplitMix64) -> Vec<[[f64; 2]; 2]> {
    let filled: Vec<bool> = (0..k * k).map(|_| rng.unit() < 0.5).collect();
    let at = |x: i64, y: i64| x >= 0 && y >= 0 && x < k && y < k && filled[(y * k + x) as usize];
    let mut edges = Vec::new();
    for y in 0..=k {
        for x in 0..=k {
            let (fx, fy) = (x as f64, y as f64);
            if x < k && at(x, y) != at(x, y - 1) {
                edges.push([[fx, fy], [fx + 1.0, fy]]);
            }
            if y < k && at(x, y) != at(x - 1, y) {
                edges.push([[fx, fy], [fx, fy + 1.0]]);
            }
        }
    }
    edges
}
