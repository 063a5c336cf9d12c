//! The strict input check alone (issue 11): `Builder::check` on four
//! crossing-free families at 10k, 100k and 1M segments, with the exponent
//! fitted from the smallest size to the largest.
//!
//! `cargo run --release --bin check -- [--sizes 10000,100000,1000000] [--runs 3] [--budget 120] [--families parallel,star,short,roads]`
//!
//! The families (n segments each, none crossing, so the check runs to the
//! end):
//! - `parallel`: long nearly parallel segments, segment i from
//!   (0, i + u/2) to (1e6, i + v/2) with u, v uniform in [0, 1): a bundle
//!   as long as the input is wide (the old grid's worst shape after stars).
//! - `star`: n spokes from one point, every direction 2π/n apart, radii
//!   1..2: all share one endpoint.
//! - `short`: testgen's short random disjoint segments (`Method::Short`,
//!   integer coordinates, the build benchmark's input).
//! - `roads`: a jittered grid graph split at its junctions, its vertices
//!   (i, j) moved by up to 0.25 on each axis, an edge to the right and one
//!   up from each: every segment shares its ends with up to three others.
//!
//! Each figure is the median of `--runs` runs of `check` (at least 11 up to
//! 100k segments; the builder is filled before the clock starts). The
//! exponent is the least-squares slope of log t against log n over the
//! sizes timed (n log n alone gives 1.09 from 10k to 1M). A size is skipped, and marked so, once
//! the size before it took more than `--budget` / 100 seconds a run (to let
//! the old grid check, whose cost is quadratic on stars, run at all).

use segvoronoi::Builder;
use segvoronoi_testgen::bench::{generate, Method};
use segvoronoi_testgen::Rng;
use std::time::Instant;

type Segment = [[f64; 2]; 2];

/// A family's name and its generator (`n`, seed).
type Family = (&'static str, fn(usize, u64) -> Vec<Segment>);

fn parallel(n: usize, seed: u64) -> Vec<Segment> {
    let mut rng = Rng(seed);
    (0..n)
        .map(|i| {
            let y = i as f64;
            [[0.0, y + 0.5 * rng.unit()], [1e6, y + 0.5 * rng.unit()]]
        })
        .collect()
}

fn star(n: usize, seed: u64) -> Vec<Segment> {
    let mut rng = Rng(seed);
    (0..n)
        .map(|k| {
            let t = k as f64 * std::f64::consts::TAU / n as f64;
            let r = 1.0 + rng.unit();
            [[0.0, 0.0], [r * t.cos(), r * t.sin()]]
        })
        .collect()
}

fn short(n: usize, seed: u64) -> Vec<Segment> {
    let g = generate(Method::Short, n, seed);
    g.segments.iter().map(|s| [[f64::from(s[0]), f64::from(s[1])], [f64::from(s[2]), f64::from(s[3])]]).collect()
}

fn roads(n: usize, seed: u64) -> Vec<Segment> {
    let mut rng = Rng(seed);
    let side = ((n as f64 / 2.0).sqrt().ceil() as usize).max(2);
    let vertices: Vec<[f64; 2]> = (0..side * side)
        .map(|k| [(k % side) as f64 + 0.5 * (rng.unit() - 0.5), (k / side) as f64 + 0.5 * (rng.unit() - 0.5)])
        .collect();
    let mut out = Vec::with_capacity(2 * side * side);
    for k in 0..side * side {
        let (i, j) = (k % side, k / side);
        if i + 1 < side {
            out.push([vertices[k], vertices[k + 1]]);
        }
        if j + 1 < side {
            out.push([vertices[k], vertices[k + side]]);
        }
    }
    out.truncate(n);
    out
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Median seconds of `runs` checks of `segments` (all must pass).
fn time_check(segments: &[Segment], runs: usize) -> f64 {
    let mut builder = Builder::new();
    builder.add_segments(segments.iter().copied()).expect("finite input");
    median(
        (0..runs)
            .map(|_| {
                let start = Instant::now();
                let result = builder.check();
                let seconds = start.elapsed().as_secs_f64();
                if let Err(e) = result {
                    panic!("the bench input conflicts: {e}");
                }
                seconds
            })
            .collect(),
    )
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |name: &str| args.iter().position(|a| a == name).and_then(|i| args.get(i + 1));
    let sizes: Vec<usize> = value("--sizes")
        .map(|s| s.split(',').map(|x| x.parse().expect("--sizes: numbers")).collect())
        .unwrap_or_else(|| vec![10_000, 100_000, 1_000_000]);
    let runs: usize = value("--runs").map_or(3, |s| s.parse().expect("--runs: a number"));
    let budget: f64 = value("--budget").map_or(120.0, |s| s.parse().expect("--budget: seconds"));
    let all: [Family; 4] = [("parallel", parallel), ("star", star), ("short", short), ("roads", roads)];
    let chosen: Option<Vec<String>> = value("--families").map(|s| s.split(',').map(String::from).collect());
    let families = all.into_iter().filter(|(name, _)| chosen.as_ref().map(|c| c.iter().any(|x| x == name)).unwrap_or(true));

    print!("| family   |");
    for n in &sizes {
        print!(" n = {n:>9} |");
    }
    println!(" exponent |");
    print!("|----------|");
    for _ in &sizes {
        print!("---------------|");
    }
    println!("----------|");
    for (name, make) in families {
        print!("| {name:<8} |");
        let mut times: Vec<Option<f64>> = Vec::new();
        for &n in &sizes {
            let skip = times.last().copied().flatten().map_or(times.last().is_some(), |t| t * 100.0 > budget);
            if skip {
                print!(" {:>13} |", "skipped");
                times.push(None);
                continue;
            }
            let segments = make(n, 0x5eed ^ n as u64);
            let t = time_check(&segments, if n <= 100_000 { runs.max(11) } else { runs });
            print!(" {:>11.4} s |", t);
            times.push(Some(t));
            use std::io::Write;
            std::io::stdout().flush().ok();
        }
        // Least squares of log t against log n over the sizes timed.
        let fitted: Vec<(f64, f64)> =
            sizes.iter().zip(&times).filter_map(|(&n, t)| t.map(|t| ((n as f64).ln(), t.ln()))).collect();
        if fitted.len() >= 2 {
            let k = fitted.len() as f64;
            let (mx, my) = (fitted.iter().map(|p| p.0).sum::<f64>() / k, fitted.iter().map(|p| p.1).sum::<f64>() / k);
            let sxy: f64 = fitted.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
            let sxx: f64 = fitted.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
            println!(" {:>8.2} |", sxy / sxx);
        } else {
            println!(" {:>8} |", "-");
        }
    }
}
