//! segvoronoi alone on the exactly cocircular families of issue 27 (part
//! 4, `segvoronoi_testgen::ties`), with the predicate counts by stage: the
//! quick look for profiling (`perf`, `callgrind`); the comparison with
//! CGAL is the main bench's (`--input stack,hatch,...`).
//!
//! `cargo run --release --bin ties -- [--families stack,hatch,...] [--sizes 3000,30000] [--runs 3]`
//!
//! Two more families without ties, for instruction counts before and after
//! (`valgrind --tool=callgrind --toggle-collect='*Builder*build*'`): `short`,
//! the bench's short random segments (`Method::Short`, seed 1), and
//! `points`, its uniform points (`float_points`, the bench's seed).

use segvoronoi::diagnostics::take_predicate_counts;
use segvoronoi::Builder;
use segvoronoi_testgen::bench::{float_points, generate, Method, SEED};
use segvoronoi_testgen::ties;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut families: Vec<String> = ties::FAMILIES.iter().map(|s| s.to_string()).collect();
    let mut sizes = vec![3000usize];
    let mut runs = 1usize;
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let value = it.next().unwrap_or_else(|| panic!("{flag} needs a value"));
        match flag.as_str() {
            "--families" => families = value.split(',').map(str::to_string).collect(),
            "--sizes" => sizes = value.split(',').map(|s| s.parse().expect("size")).collect(),
            "--runs" => runs = value.parse().expect("runs"),
            _ => panic!("unknown option {flag}"),
        }
    }
    for family in &families {
        for &n in &sizes {
            let segments = match family.as_str() {
                "short" => generate(Method::Short, n, 1).segments,
                "points" => Vec::new(),
                _ => ties::family(family, n).unwrap_or_else(|| panic!("unknown family {family}")),
            };
            let points = if family == "points" { float_points(n, SEED) } else { Vec::new() };
            let segments: Vec<[[f64; 2]; 2]> =
                segments.iter().map(|s| [[f64::from(s[0]), f64::from(s[1])], [f64::from(s[2]), f64::from(s[3])]]).collect();
            let mut times = Vec::new();
            let mut summary = String::new();
            for _ in 0..runs {
                let _ = take_predicate_counts();
                let start = Instant::now();
                let mut builder = Builder::new();
                builder.add_segments(segments.iter().copied()).expect("finite input");
                builder.add_points(points.iter().copied()).expect("finite input");
                let diagram = builder.build().expect("a diagram");
                times.push(start.elapsed().as_secs_f64());
                let counts = take_predicate_counts();
                summary = format!(
                    "vertices {} edges {} stages {:?} polished {}",
                    diagram.vertex_count(),
                    diagram.edge_count(),
                    counts.by_stage,
                    counts.polished_vertices
                );
            }
            times.sort_by(f64::total_cmp);
            println!("{family:>10} {:>7} median {:.4} s  {summary}", segments.len().max(points.len()), times[times.len() / 2]);
        }
    }
}
