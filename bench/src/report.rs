//! The markdown tables printed at the end of a run.

use crate::contenders::{Contender, Measured};
use crate::{Row, Who};

pub fn print_all(rows: &[Row], runs: usize) {
    println!("\n### Build time and peak memory ({runs} runs each)\n");
    print_times(rows);
    println!("\n### Output sizes (sanity check)\n");
    print_counts(rows);
    println!("\n### Scaling\n");
    print_scaling(rows);
    for row in rows {
        if let Err(message) = &row.result {
            println!("\n{} on {} points failed: {message}", row.who.name(), thousands(row.n));
        }
    }
}

fn print_times(rows: &[Row]) {
    println!("| size | contender | median s | min s | peak RSS MiB | time vs segvoronoi |");
    println!("|---:|---|---:|---:|---:|---:|");
    for row in rows {
        let label = match row.who {
            Who::Input => "input only (baseline)",
            Who::Lib(c) => c.name(),
        };
        let (median_s, min_s, ratio) = match measured(row) {
            Some(m) => {
                let ratio = segvoronoi_median(rows, row.n).map_or("—".into(), |s| format!("{:.2}×", median(m) / s));
                (format!("{:.4}", median(m)), format!("{:.4}", min(m)), ratio)
            }
            None => ("—".into(), "—".into(), "—".into()),
        };
        let peak = match &row.result {
            Ok(report) => format!("{:.1}", report.peak_kib as f64 / 1024.0),
            Err(_) => "failed".into(),
        };
        println!("| {} | {label} | {median_s} | {min_s} | {peak} | {ratio} |", thousands(row.n));
    }
}

fn print_counts(rows: &[Row]) {
    println!("| size | contender | sites | Voronoi vertices | minus segvoronoi's |");
    println!("|---:|---|---:|---:|---:|");
    for row in rows {
        let (Who::Lib(c), Some(m)) = (row.who, measured(row)) else { continue };
        let what = if c == Contender::Spade { " (Delaunay triangles)" } else { "" };
        let reference = rows
            .iter()
            .find(|r| r.n == row.n && r.who == Who::Lib(Contender::Segvoronoi))
            .and_then(measured);
        let delta = reference.map_or("—".into(), |s| format!("{:+}", m.vertices as i64 - s.vertices as i64));
        println!(
            "| {} | {}{what} | {} | {} | {delta} |",
            thousands(row.n),
            c.name(),
            thousands(m.sites),
            thousands(m.vertices)
        );
    }
}

/// Time per point, and the exponent `log(t2/t1) / log(n2/n1)` between each
/// size and the next smaller one: 1.0 is linear, n log n shows as a little
/// above 1.
fn print_scaling(rows: &[Row]) {
    println!("| size | contender | ns per point | growth exponent from previous size |");
    println!("|---:|---|---:|---:|");
    for row in rows {
        let (Who::Lib(c), Some(m)) = (row.who, measured(row)) else { continue };
        let t = median(m);
        let previous = rows
            .iter()
            .filter(|r| r.who == row.who && r.n < row.n)
            .filter_map(|r| measured(r).map(|pm| (r.n, median(pm))))
            .max_by_key(|&(n, _)| n);
        let exponent = previous.map_or("—".into(), |(n1, t1)| {
            format!("{:.3}", (t / t1).ln() / (row.n as f64 / n1 as f64).ln())
        });
        println!("| {} | {} | {:.0} | {exponent} |", thousands(row.n), c.name(), t * 1e9 / row.n as f64);
    }
}

fn measured(row: &Row) -> Option<&Measured> {
    row.result.as_ref().ok().and_then(|r| r.measured.as_ref())
}

fn segvoronoi_median(rows: &[Row], n: usize) -> Option<f64> {
    rows.iter()
        .find(|r| r.n == n && r.who == Who::Lib(Contender::Segvoronoi))
        .and_then(measured)
        .map(median)
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

/// 1000000 as "1,000,000", so sizes read at a glance.
fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, ch) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(ch);
    }
    out
}
