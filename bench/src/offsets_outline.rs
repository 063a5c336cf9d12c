//! `offsets --rings FILE`: the offsets of one real outline (a rings file as
//! `scripts/country_rings.py` writes it: a country in km, its islands,
//! enclaves as holes, the region even-odd) beside GEOS's buffer of the same
//! region, in one run.
//!
//! Distances are fractions of the outline's extent `E` (the larger side of
//! its bounding box), both signs: -1 %, -0.2 %, +0.2 %, +1 %, +5 %. The
//! tolerance is `1e-5 E` at every distance (GEOS's quadrant segments chosen
//! for it as in the main table, ours sampled at what those give).
//!
//! Ours: the build (`add_polygon` of all rings, `build`), then per distance
//! `offset(d)` and its polylines; the median of `--runs`. GEOS: per distance
//! one buffer of the region as a MultiPolygon (each ring of even nesting
//! depth a shell, the rings directly inside it its holes: the same even-odd
//! region), once, the MultiPolygon made outside the timing. Peak memory:
//! the growth of the process's peak resident set (VmHWM, reset through
//! `/proc/self/clear_refs` before each part) while building and offsetting
//! at every distance, and while GEOS buffers at every distance; the input
//! is loaded before.

use segvoronoi::Builder;
use std::time::Instant;

use super::peak::{peak_above, reset_peak};
use super::{median, quadsegs_within, seconds};

/// The distances, as fractions of the extent.
const FRACTIONS: [f64; 5] = [-0.01, -0.002, 0.002, 0.01, 0.05];
/// The tolerance, as a fraction of the extent.
const TOLERANCE: f64 = 1e-5;

type Ring = Vec<[f64; 2]>;

pub fn run(path: &str, runs: usize) {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let rings: Vec<Ring> = segvoronoi_testgen::rings::read_rings(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
    let points: usize = rings.iter().map(Vec::len).sum();
    let (lo, hi) = rings.iter().flatten().fold(([f64::MAX; 2], [f64::MIN; 2]), |(lo, hi), p| {
        ([lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])])
    });
    let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let tolerance = TOLERANCE * extent;
    let ds: Vec<f64> = FRACTIONS.iter().map(|f| f * extent).collect();
    let name = std::path::Path::new(path).file_name().map_or(path.into(), |n| n.to_string_lossy().into_owned());
    eprintln!("{name}: {} rings, {points} points, extent {extent:.1}", rings.len());

    // ours: the build, then each distance (offset and polylines)
    let mut builds = Vec::new();
    let mut per_distance: Vec<Vec<f64>> = vec![Vec::new(); ds.len()];
    let mut vertices = vec![0usize; ds.len()];
    let mut ours_peak = 0;
    for _ in 0..runs {
        let base = reset_peak();
        let start = Instant::now();
        let mut b = Builder::new();
        b.add_polygon(&rings).unwrap_or_else(|e| panic!("{name}: {e}"));
        let d = b.build().unwrap_or_else(|e| panic!("{name}: {e}"));
        builds.push(start.elapsed().as_secs_f64());
        for (k, &dist) in ds.iter().enumerate() {
            let start = Instant::now();
            let o = d.offset(dist).expect("an offset");
            let lines = o.polylines(quadsegs_within(dist, tolerance).1).expect("a tolerance");
            per_distance[k].push(start.elapsed().as_secs_f64());
            vertices[k] = lines.iter().map(Vec::len).sum();
        }
        ours_peak = ours_peak.max(peak_above(base));
    }
    let build = median(builds);
    let ours: Vec<f64> = per_distance.into_iter().map(median).collect();

    #[cfg(has_geos)]
    let geos: Option<(Vec<f64>, Vec<usize>, u64)> = {
        let g = super::geos::Input::new(&even_odd_polygons(&rings));
        let base = reset_peak();
        let mut times = Vec::new();
        let mut counts = Vec::new();
        for &dist in &ds {
            let start = Instant::now();
            let (v, _) = g.buffer_within(dist, tolerance);
            times.push(start.elapsed().as_secs_f64());
            counts.push(v);
        }
        Some((times, counts, peak_above(base)))
    };
    #[cfg(not(has_geos))]
    let geos: Option<(Vec<f64>, Vec<usize>, u64)> = None;

    println!("\n{name}: {} rings, {points} points, extent E = {extent:.1} km, tolerance {tolerance:.4} km", rings.len());
    println!("build {} (median of {runs})\n", seconds(build));
    println!("| distance | ours: offset + polylines | ours incl. build | GEOS buffer | GEOS / ours | GEOS / ours incl. build | vertices ours | GEOS |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    for (k, &f) in FRACTIONS.iter().enumerate() {
        let (g, ratio, ratio_build, gv) = match &geos {
            Some((t, v, _)) => {
                (seconds(t[k]), format!("{:.1}x", t[k] / ours[k]), format!("{:.1}x", t[k] / (build + ours[k])), v[k].to_string())
            }
            None => ("-".into(), "-".into(), "-".into(), "-".into()),
        };
        println!(
            "| {:+} E ({:+.1} km) | {} | {} | {g} | {ratio} | {ratio_build} | {} | {gv} |",
            f,
            f * extent,
            seconds(ours[k]),
            seconds(build + ours[k]),
            vertices[k]
        );
    }
    let total: f64 = ours.iter().sum();
    match &geos {
        Some((t, _, peak)) => {
            let g: f64 = t.iter().sum();
            println!(
                "| all {} | {} | {} | {} | {:.1}x | {:.1}x | | |",
                ds.len(),
                seconds(total),
                seconds(build + total),
                seconds(g),
                g / total,
                g / (build + total)
            );
            println!("\npeak memory above the loaded input: ours {:.1} MiB, GEOS {:.1} MiB", mib(ours_peak), mib(*peak));
        }
        None => println!("\npeak memory above the loaded input: ours {:.1} MiB (GEOS not compiled in)", mib(ours_peak)),
    }
}

fn mib(kib: u64) -> f64 {
    kib as f64 / 1024.0
}

/// The even-odd region of `rings` (which neither cross nor overlap) as
/// polygons: every ring inside an even number of others is an outer ring,
/// with the rings directly inside it (one level deeper) as its holes.
#[cfg_attr(not(has_geos), allow(dead_code))]
fn even_odd_polygons(rings: &[Ring]) -> Vec<Vec<Ring>> {
    let boxes: Vec<[f64; 4]> = rings
        .iter()
        .map(|r| {
            r.iter().fold([f64::MAX, f64::MAX, f64::MIN, f64::MIN], |b, p| {
                [b[0].min(p[0]), b[1].min(p[1]), b[2].max(p[0]), b[3].max(p[1])]
            })
        })
        .collect();
    // a ring's first point is on no other ring (they do not touch in these
    // files), so it tells which rings hold it
    let holders: Vec<Vec<usize>> = (0..rings.len())
        .map(|i| {
            let p = rings[i][0];
            (0..rings.len())
                .filter(|&j| j != i)
                .filter(|&j| boxes[j][0] <= p[0] && p[0] <= boxes[j][2] && boxes[j][1] <= p[1] && p[1] <= boxes[j][3])
                .filter(|&j| inside(&rings[j], p))
                .collect()
        })
        .collect();
    let depth: Vec<usize> = holders.iter().map(Vec::len).collect();
    let mut polygons: Vec<Vec<Ring>> = Vec::new();
    let mut polygon_of = vec![usize::MAX; rings.len()];
    for i in (0..rings.len()).filter(|&i| depth[i].is_multiple_of(2)) {
        polygon_of[i] = polygons.len();
        polygons.push(vec![rings[i].clone()]);
    }
    for i in (0..rings.len()).filter(|&i| depth[i] % 2 == 1) {
        let parent = holders[i].iter().copied().find(|&j| depth[j] + 1 == depth[i]).expect("a hole has its outer ring");
        polygons[polygon_of[parent]].push(rings[i].clone());
    }
    polygons
}

/// Whether `p` is inside `ring` (even-odd, a ray to the right).
fn inside(ring: &Ring, p: [f64; 2]) -> bool {
    let mut odd = false;
    for k in 0..ring.len() {
        let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
        if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]) {
            odd = !odd;
        }
    }
    odd
}
