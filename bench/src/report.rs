//! The markdown tables printed at the end of a run.

use crate::contenders::{Contender, Measured};
use crate::text::thousands;
use crate::{InputInfo, Row, Who, Workload};

pub fn print_all(rows: &[Row], runs: usize) {
    println!("\n### Build time and peak memory ({runs} runs each)\n");
    print_times(rows, false);
    println!("\n### Output sizes (sanity check)\n");
    print_counts(rows);
    println!("\n### Scaling\n");
    print_scaling(rows, false);
    print_failures(rows);
}

/// The tables of a `--input segments` run.
pub fn print_segments(rows: &[Row], inputs: &[InputInfo], runs: usize) {
    println!("\n### Input (generated once per size; random segments checked disjoint, the others legal by construction)\n");
    println!("| input | segments | generation s | draws | mean length | least gap | axis-parallel |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for i in inputs {
        println!(
            "| {} | {} | {:.2} | {} | {:.0} | {} | {:.1} % |",
            i.workload.name(),
            thousands(i.n),
            i.seconds,
            thousands(i.draws as usize),
            i.mean_length,
            i.least_gap.map_or("—".into(), |g| format!("{g:.1}")),
            100.0 * i.axis_share
        );
    }
    println!("\n### Build time and peak memory ({runs} runs each)\n");
    print_times(rows, true);
    println!("\n### Output sizes (sanity check)\n");
    print_segment_counts(rows);
    println!("\n### Scaling\n");
    print_scaling(rows, true);
    println!();
    print_slopes(rows, |w| w.name());
    print_failures(rows);
}

/// The tables of a `--input seed` run: the seed paper's experiment.
pub fn print_seed(rows: &[Row], inputs: &[InputInfo], runs: usize) {
    println!("\n### Inputs (seed 000 §6, methods 1-3; generated once per size, checked disjoint)\n");
    println!("| method | segments | generation s | draws | repairs | restarts | mean length | least gap |");
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|");
    for i in inputs {
        println!(
            "| {} | {} | {:.3} | {} | {} | {} | {:.0} | {} |",
            method_number(i.workload),
            thousands(i.n),
            i.seconds,
            thousands(i.draws as usize),
            thousands(i.repairs as usize),
            i.restarts,
            i.mean_length,
            i.least_gap.map_or("—".into(), |g| format!("{g:.1}"))
        );
    }
    println!("\n### Build time ({runs} runs each) and time per segment\n");
    println!("| method | segments | contender | median s | min s | µs per segment (median) | peak RSS MiB | cells | Voronoi vertices | against segvoronoi |");
    println!("|---:|---:|---|---:|---:|---:|---:|---:|---:|---|");
    for row in rows {
        let peak = match &row.result {
            Ok(report) => format!("{:.1}", report.peak_kib as f64 / 1024.0),
            Err(_) => "failed".into(),
        };
        let label = match row.who {
            Who::Input => "input only (baseline)",
            Who::Lib(c) => c.name(),
        };
        let (median_s, min_s, per, cells, vertices, against) = match measured(row) {
            Some(m) => (
                format!("{:.5}", median(m)),
                format!("{:.5}", min(m)),
                format!("{:.2}", median(m) * 1e6 / row.n as f64),
                thousands(m.sites),
                thousands(m.vertices),
                reference(rows, row).map_or("—".into(), |r| versus(m, r)),
            ),
            None => ("—".into(), "—".into(), "—".into(), "—".into(), "—".into(), "—".into()),
        };
        println!(
            "| {} | {} | {label} | {median_s} | {min_s} | {per} | {peak} | {cells} | {vertices} | {against} |",
            method_number(row.workload),
            thousands(row.n)
        );
    }
    println!();
    print_slopes(rows, |w| format!("method {}", method_number(w)));
    print_failures(rows);
}

/// segvoronoi's result on the same input, for the other contenders' rows.
fn reference<'a>(rows: &'a [Row], row: &Row) -> Option<&'a Measured> {
    if row.who == Who::Lib(Contender::Segvoronoi) {
        return None;
    }
    rows.iter()
        .find(|r| r.workload == row.workload && r.n == row.n && r.who == Who::Lib(Contender::Segvoronoi))
        .and_then(measured)
}

/// Largest relative difference of the two vertex coordinate sums.
fn sum_difference(m: &Measured, reference: &Measured) -> f64 {
    (0..2)
        .map(|k| (m.vertex_sum[k] - reference.vertex_sum[k]).abs() / reference.vertex_sum[k].abs().max(f64::MIN_POSITIVE))
        .fold(0.0, f64::max)
}

/// "same" when cells, vertices and edges agree, with the relative
/// difference of the vertex coordinate sums; otherwise the differences.
fn versus(m: &Measured, reference: &Measured) -> String {
    let sums = format!("Σ {}", relative(sum_difference(m, reference)));
    if (m.sites, m.vertices, m.edges) == (reference.sites, reference.vertices, reference.edges) {
        format!("same counts, {sums}")
    } else {
        format!(
            "cells {:+}, vertices {:+}, edges {:+}, {sums}",
            m.sites as i64 - reference.sites as i64,
            m.vertices as i64 - reference.vertices as i64,
            m.edges as i64 - reference.edges as i64
        )
    }
}

fn relative(d: f64) -> String {
    if d == 0.0 {
        "0".into()
    } else {
        format!("{d:.0e}")
    }
}

fn method_number(workload: Workload) -> u8 {
    match workload {
        Workload::Segments(m) => m.number(),
        _ => 0,
    }
}

/// Least-squares slope of log(median time) against log(n) over every size of
/// a (workload, contender): 1.0 is linear growth, n log n a little above.
fn print_slopes(rows: &[Row], label: impl Fn(Workload) -> String) {
    println!("| input | contender | sizes | least-squares growth exponent (log time vs log n) |");
    println!("|---|---|---:|---:|");
    let mut done: Vec<(Workload, Who)> = Vec::new();
    for row in rows {
        if row.who == Who::Input || done.contains(&(row.workload, row.who)) {
            continue;
        }
        done.push((row.workload, row.who));
        let points: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.workload == row.workload && r.who == row.who)
            .filter_map(|r| measured(r).map(|m| ((r.n as f64).ln(), median(m).ln())))
            .collect();
        let slope = least_squares_slope(&points).map_or("—".into(), |s| format!("{s:.3}"));
        println!("| {} | {} | {} | {slope} |", label(row.workload), row.who.name(), points.len());
    }
}

pub fn least_squares_slope(points: &[(f64, f64)]) -> Option<f64> {
    if points.len() < 2 {
        return None;
    }
    let k = points.len() as f64;
    let (mx, my) = (points.iter().map(|p| p.0).sum::<f64>() / k, points.iter().map(|p| p.1).sum::<f64>() / k);
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

fn print_failures(rows: &[Row]) {
    for row in rows {
        if let Err(message) = &row.result {
            println!(
                "\n{} on {} {} ({}) failed: {message}",
                row.who.name(),
                thousands(row.n),
                row.workload.unit(),
                row.workload.name()
            );
        }
    }
}

/// Cells, vertices and edges. Every contender splits a segment into its two
/// endpoints and the open segment, so on disjoint segments all report 3n
/// cells; vertices and edges are compared with segvoronoi's.
fn print_segment_counts(rows: &[Row]) {
    println!("| input | size | contender | cells | Voronoi vertices | edges | vertices minus segvoronoi's | edges minus segvoronoi's | vertex sums vs segvoronoi's (relative) |");
    println!("|---|---:|---|---:|---:|---:|---:|---:|---:|");
    for row in rows {
        let (Who::Lib(c), Some(m)) = (row.who, measured(row)) else { continue };
        let reference = rows
            .iter()
            .find(|r| r.workload == row.workload && r.n == row.n && r.who == Who::Lib(Contender::Segvoronoi))
            .and_then(measured);
        let delta = |f: fn(&Measured) -> usize| reference.map_or("—".into(), |s| format!("{:+}", f(m) as i64 - f(s) as i64));
        let sums = reference.map_or("—".into(), |s| relative(sum_difference(m, s)));
        println!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {sums} |",
            row.workload.name(),
            thousands(row.n),
            c.name(),
            thousands(m.sites),
            thousands(m.vertices),
            thousands(m.edges),
            delta(|m| m.vertices),
            delta(|m| m.edges)
        );
    }
}

/// One line per child; `with_input` adds the workload's name (segment runs
/// may hold several) and, where CGAL ran on the same input, each time
/// against CGAL's.
fn print_times(rows: &[Row], with_input: bool) {
    let cgal = with_input && rows.iter().any(|r| r.who == Who::Lib(Contender::Cgal));
    let (input_head, input_rule) = if with_input { ("| input ", "|---") } else { ("", "") };
    let (cgal_head, cgal_rule) = if cgal { (" time vs cgal |", "---:|") } else { ("", "") };
    println!("{input_head}| size | contender | median s | min s | peak RSS MiB | time vs segvoronoi |{cgal_head}");
    println!("{input_rule}|---:|---|---:|---:|---:|---:|{cgal_rule}");
    for row in rows {
        let label = match row.who {
            Who::Input => "input only (baseline)",
            Who::Lib(c) => c.name(),
        };
        let against = |c: Contender| {
            let reference = median_of(rows, row.workload, row.n, c);
            measured(row).zip(reference).map_or("—".into(), |(m, s)| format!("{:.2}×", median(m) / s))
        };
        let (median_s, min_s) = match measured(row) {
            Some(m) => (format!("{:.4}", median(m)), format!("{:.4}", min(m))),
            None => ("—".into(), "—".into()),
        };
        let peak = match &row.result {
            Ok(report) => format!("{:.1}", report.peak_kib as f64 / 1024.0),
            Err(_) => "failed".into(),
        };
        let input = if with_input { format!("| {} ", row.workload.name()) } else { String::new() };
        let versus_cgal = if cgal { format!(" {} |", against(Contender::Cgal)) } else { String::new() };
        println!(
            "{input}| {} | {label} | {median_s} | {min_s} | {peak} | {} |{versus_cgal}",
            thousands(row.n),
            against(Contender::Segvoronoi)
        );
    }
}

fn print_counts(rows: &[Row]) {
    println!("| size | contender | sites | Voronoi vertices | minus segvoronoi's |");
    println!("|---:|---|---:|---:|---:|");
    for row in rows {
        let (Who::Lib(c), Some(m)) = (row.who, measured(row)) else { continue };
        let what = if c == Contender::Spade { " (Delaunay triangles)" } else { "" };
        let reference = rows.iter().find(|r| r.n == row.n && r.who == Who::Lib(Contender::Segvoronoi)).and_then(measured);
        let delta = reference.map_or("—".into(), |s| format!("{:+}", m.vertices as i64 - s.vertices as i64));
        println!("| {} | {}{what} | {} | {} | {delta} |", thousands(row.n), c.name(), thousands(m.sites), thousands(m.vertices));
    }
}

/// Time per point, and the exponent `log(t2/t1) / log(n2/n1)` between each
/// size and the next smaller one: 1.0 is linear, n log n shows as a little
/// above 1.
fn print_scaling(rows: &[Row], with_input: bool) {
    let unit = rows.first().map_or("point", |r| if r.workload == Workload::Points { "point" } else { "segment" });
    let (input_head, input_rule) = if with_input { ("| input ", "|---") } else { ("", "") };
    println!("{input_head}| size | contender | ns per {unit} | growth exponent from previous size |");
    println!("{input_rule}|---:|---|---:|---:|");
    for row in rows {
        let (Who::Lib(c), Some(m)) = (row.who, measured(row)) else { continue };
        let t = median(m);
        let previous = rows
            .iter()
            .filter(|r| r.workload == row.workload && r.who == row.who && r.n < row.n)
            .filter_map(|r| measured(r).map(|pm| (r.n, median(pm))))
            .max_by_key(|&(n, _)| n);
        let exponent =
            previous.map_or("—".into(), |(n1, t1)| format!("{:.3}", (t / t1).ln() / (row.n as f64 / n1 as f64).ln()));
        let input = if with_input { format!("| {} ", row.workload.name()) } else { String::new() };
        println!("{input}| {} | {} | {:.0} | {exponent} |", thousands(row.n), c.name(), t * 1e9 / row.n as f64);
    }
}

fn measured(row: &Row) -> Option<&Measured> {
    row.result.as_ref().ok().and_then(|r| r.measured.as_ref())
}

/// The median time of contender `c` on the same input.
fn median_of(rows: &[Row], workload: Workload, n: usize, c: Contender) -> Option<f64> {
    rows.iter().find(|r| r.workload == workload && r.n == n && r.who == Who::Lib(c)).and_then(measured).map(median)
}

pub fn median(m: &Measured) -> f64 {
    let mut s = m.seconds.clone();
    s.sort_by(f64::total_cmp);
    let k = s.len() / 2;
    if s.len() % 2 == 1 {
        s[k]
    } else {
        (s[k - 1] + s[k]) / 2.0
    }
}

fn min(m: &Measured) -> f64 {
    m.seconds.iter().copied().fold(f64::INFINITY, f64::min)
}
