//! Offsets of a curved part (issue 32) against GEOS's buffer and Clipper's
//! offset of its 16-chord approximation, in one run on the same layout:
//! the time of 100 distances and the size of what comes out (pieces and
//! arcs against chord vertices, the G-code lines either way).
//!
//! `cargo run --release --bin arc_offsets -- [--arcs 10000] [--runs 3] [--budget 120]`
//! (`bash scripts/arc-offsets-bench.sh`).
//!
//! The input is a sheet of parts to pocket, 2.2 apart on a square grid,
//! each a domain of three bulged rings (`add_bulged_polygon`): a rounded
//! rectangle (half sides 0.75..0.95, corner radii 0.1..0.4: 4 arcs), a
//! round hole (radius 0.12..0.2, as two half circles) and a slot hole
//! (half width 0.08..0.12, half length 0.2..0.3: 2 arcs), 8 arcs a part,
//! random sizes from seed 1. The walls are 0.15 to 0.5 wide; the 100
//! distances run from -0.003 to -0.15, inward as a pocketing toolpath.
//!
//! The chord route: every arc as 16 chords (the rings as polygons), offset
//! by segvoronoi, GEOS (one MultiPolygon, quadrant segments for the
//! tolerance 1e-4 at each distance) and Clipper (integers, 2^28 over the
//! extent, arc tolerance 1e-4). Ours on the arcs samples its loops at the
//! same tolerance for the vertex count, and keeps its pieces (lines and
//! arcs) for the output size: a G-code program is one line a piece (`G1`,
//! `G2`/`G3`) and four a loop (rapid, plunge, comment, retract), the
//! chord route's one line a vertex and the same four.
//!
//! GEOS and Clipper get the 100 distances in full while they fit in
//! `--budget` seconds (estimated from one distance); beyond that an evenly
//! spread subset is timed and scaled to 100 (said in the table).

#[path = "../offset_peers.rs"]
mod offset_peers;
#[path = "../text.rs"]
mod text;

#[cfg(has_clipper)]
use offset_peers::clipper;
#[cfg(has_geos)]
use offset_peers::geos;
use offset_peers::quadsegs_within;
use segvoronoi::{Builder, CircularArc, OffsetPiece};
use segvoronoi_testgen::Rng;
use std::time::Instant;
use text::seconds;

const TOLERANCE: f64 = 1e-4;
const CHORDS: usize = 16;
const ARCS_PER_PART: usize = 8;
/// G-code lines a loop costs besides its pieces.
const LINES_PER_LOOP: usize = 4;

/// A ring of `(x, y, bulge)` vertices: the bulge of the piece to the next.
type Ring = Vec<([f64; 2], f64)>;

fn rounded_rectangle(cx: f64, cy: f64, hw: f64, hh: f64, r: f64) -> Ring {
    // counter-clockwise; each corner a quarter turn: bulge tan(π/8)
    let q = (std::f64::consts::PI / 8.0).tan();
    let (x0, x1, y0, y1) = (cx - hw, cx + hw, cy - hh, cy + hh);
    vec![
        ([x0 + r, y0], 0.0),
        ([x1 - r, y0], q),
        ([x1, y0 + r], 0.0),
        ([x1, y1 - r], q),
        ([x1 - r, y1], 0.0),
        ([x0 + r, y1], q),
        ([x0, y1 - r], 0.0),
        ([x0, y0 + r], q),
    ]
}

/// A round hole, clockwise (two half circles).
fn round_hole(cx: f64, cy: f64, r: f64) -> Ring {
    vec![([cx + r, cy], -1.0), ([cx - r, cy], -1.0)]
}

/// A vertical slot hole, clockwise.
fn slot_hole(cx: f64, cy: f64, half_width: f64, half_length: f64) -> Ring {
    let (top, bottom) = (cy + half_length, cy - half_length);
    vec![
        ([cx - half_width, top], -1.0),
        ([cx + half_width, top], 0.0),
        ([cx + half_width, bottom], -1.0),
        ([cx - half_width, bottom], 0.0),
    ]
}

/// About `arcs` arcs of parts.
fn parts(arcs: usize) -> Vec<Vec<Ring>> {
    let n = arcs.div_ceil(ARCS_PER_PART);
    let side = (n as f64).sqrt().ceil() as usize;
    let mut rng = Rng(1);
    let mut u = |lo: f64, hi: f64| lo + (hi - lo) * rng.unit();
    (0..n)
        .map(|k| {
            let (cx, cy) = ((k % side) as f64 * 2.2, (k / side) as f64 * 2.2);
            let outer = rounded_rectangle(cx, cy, u(0.75, 0.95), u(0.75, 0.95), u(0.1, 0.4));
            let round = round_hole(cx - 0.35, cy + u(-0.1, 0.1), u(0.12, 0.2));
            let slot = slot_hole(cx + 0.35, cy + u(-0.1, 0.1), u(0.08, 0.12), u(0.2, 0.3));
            vec![outer, round, slot]
        })
        .collect()
}

/// The ring with every arc cut into `CHORDS` chords.
fn chords(ring: &Ring) -> Vec<[f64; 2]> {
    let mut out = Vec::with_capacity(ring.len() * CHORDS);
    for (k, &(p, bulge)) in ring.iter().enumerate() {
        out.push(p);
        if bulge != 0.0 {
            let next = ring[(k + 1) % ring.len()].0;
            let arc = CircularArc::from_bulge(p, next, bulge).expect("an arc");
            out.extend((1..CHORDS).map(|i| {
                let q = arc.point_at(i as f64 / CHORDS as f64);
                [q.x, q.y]
            }));
        }
    }
    out
}

fn distances() -> Vec<f64> {
    (0..100).map(|k| -(0.003 + (0.15 - 0.003) * k as f64 / 99.0)).collect()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// One route through segvoronoi: its times and what came out.
#[derive(Clone, Copy, Default)]
struct Ours {
    build: f64,
    hundred: f64,
    /// sampling the 100 offsets' loops at the tolerance
    sampling: f64,
    loops: usize,
    lines: usize,
    arcs: usize,
    vertices: usize,
}

/// Builds the domain (`add`), then the 100 offsets, counted.
fn ours(ds: &[f64], add: impl Fn(&mut Builder)) -> Ours {
    let start = Instant::now();
    let mut b = Builder::new();
    add(&mut b);
    let d = b.build().expect("a diagram");
    let build = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let all = d.offsets(ds).expect("offsets");
    let hundred = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let vertices = all
        .iter()
        .map(|o| o.polylines(quadsegs_within(o.distance, TOLERANCE).1).expect("a tolerance").iter().map(Vec::len).sum::<usize>())
        .sum();
    let sampling = start.elapsed().as_secs_f64();
    let mut o = Ours { build, hundred, sampling, vertices, ..Ours::default() };
    for offset in &all {
        o.loops += offset.loops.len();
        for piece in offset.loops.iter().flat_map(|l| &l.pieces) {
            match piece {
                OffsetPiece::Arc { .. } => o.arcs += 1,
                _ => o.lines += 1,
            }
        }
    }
    o
}

#[cfg_attr(not(any(has_geos, has_clipper)), allow(dead_code))]
/// A peer's 100 distances: seconds (scaled from the `measured` timed),
/// vertices and rings (when all were run).
struct Other {
    hundred: f64,
    measured: usize,
    vertices: Option<usize>,
    rings: Option<usize>,
}

#[cfg_attr(not(any(has_geos, has_clipper)), allow(dead_code))]
fn other(ds: &[f64], budget: f64, mut run: impl FnMut(f64) -> (usize, usize)) -> Other {
    let start = Instant::now();
    run(ds[ds.len() / 2]);
    let one = start.elapsed().as_secs_f64();
    let k = if one * ds.len() as f64 <= budget { ds.len() } else { ((budget / one) as usize).clamp(3, ds.len()) };
    let picked: Vec<f64> = (0..k).map(|i| ds[i * (ds.len() - 1) / (k - 1).max(1)]).collect();
    let start = Instant::now();
    let (vertices, rings) = picked.iter().map(|&d| run(d)).fold((0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    let elapsed = start.elapsed().as_secs_f64();
    let all = k == ds.len();
    Other {
        hundred: elapsed * ds.len() as f64 / k as f64,
        measured: k,
        vertices: all.then_some(vertices),
        rings: all.then_some(rings),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |name: &str| args.iter().position(|a| a == name).and_then(|i| args.get(i + 1));
    let arcs: usize = value("--arcs").map_or(10_000, |r| r.parse().expect("--arcs N"));
    let runs: usize = value("--runs").map_or(3, |r| r.parse().expect("--runs R"));
    let budget: f64 = value("--budget").map_or(120.0, |r| r.parse().expect("--budget SECONDS"));
    #[cfg(not(any(has_geos, has_clipper)))]
    let _ = budget;
    let ds = distances();
    let input = parts(arcs);
    let arc_count: usize = input.iter().flatten().flatten().filter(|(_, b)| *b != 0.0).count();
    let line_count: usize = input.iter().flatten().flatten().count() - arc_count;
    let chorded: Vec<Vec<Vec<[f64; 2]>>> = input.iter().map(|part| part.iter().map(chords).collect()).collect();
    let chord_count: usize = chorded.iter().flatten().map(Vec::len).sum();

    let median_of = |results: &[Ours]| Ours {
        build: median(results.iter().map(|o| o.build).collect()),
        hundred: median(results.iter().map(|o| o.hundred).collect()),
        sampling: median(results.iter().map(|o| o.sampling).collect()),
        ..results[0]
    };
    eprintln!("{} parts, {arc_count} arcs and {line_count} sides: ours on the arcs", input.len());
    let on_arcs: Vec<Ours> = (0..runs)
        .map(|_| {
            ours(&ds, |b| {
                for part in &input {
                    b.add_bulged_polygon(part).expect("disjoint rings");
                }
            })
        })
        .collect();
    let on_arcs = median_of(&on_arcs);
    eprintln!("{chord_count} chords: ours on the chords");
    let on_chords: Vec<Ours> = (0..runs)
        .map(|_| {
            ours(&ds, |b| {
                for part in &chorded {
                    b.add_polygon(part).expect("disjoint rings");
                }
            })
        })
        .collect();
    let on_chords = median_of(&on_chords);
    let mut others: Vec<(&str, Other)> = Vec::new();
    #[cfg(has_geos)]
    {
        eprintln!("{chord_count} chords: GEOS");
        let g = geos::Input::new(&chorded);
        others.push(("GEOS buffer", other(&ds, budget, |d| g.buffer_within(d, TOLERANCE))));
    }
    #[cfg(has_clipper)]
    {
        eprintln!("{chord_count} chords: Clipper");
        let c = clipper::Input::new(&chorded);
        others.push(("Clipper offset", other(&ds, budget, |d| c.offset(d, quadsegs_within(d, TOLERANCE).1))));
    }

    let reference = on_arcs.build + on_arcs.hundred + on_arcs.sampling;
    println!(
        "\n{} parts: {arc_count} arcs and {line_count} sides; as chords {chord_count} segments. 100 distances from -0.003 to -0.15, tolerance {TOLERANCE:e}; median of {runs} runs for ours.\n",
        input.len()
    );
    println!(
        "| route | build | 100 offsets | polylines | total | / segvoronoi on arcs | loops | pieces (arcs) | vertices at the tolerance | G-code lines |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let row = |name: &str, o: &Ours| {
        let total = o.build + o.hundred + o.sampling;
        println!(
            "| {name} | {} | {} | {} | {} | {:.2}x | {} | {} ({}) | {} | {} |",
            seconds(o.build),
            seconds(o.hundred),
            seconds(o.sampling),
            seconds(total),
            total / reference,
            o.loops,
            o.lines + o.arcs,
            o.arcs,
            o.vertices,
            o.lines + o.arcs + LINES_PER_LOOP * o.loops
        );
    };
    row("segvoronoi, arcs", &on_arcs);
    row("segvoronoi, 16 chords an arc", &on_chords);
    for (name, r) in &others {
        let est = if r.measured < ds.len() { format!(" (est. from {})", r.measured) } else { String::new() };
        let (vertices, gcode) = match (r.vertices, r.rings) {
            (Some(v), Some(k)) => (v.to_string(), (v + LINES_PER_LOOP * k).to_string()),
            _ => ("-".to_string(), "-".to_string()),
        };
        println!(
            "| {name}, 16 chords an arc | - | {}{est} | (in the offsets) | {} | {:.2}x | {} | - | {vertices} | {gcode} |",
            seconds(r.hundred),
            seconds(r.hundred),
            r.hundred / reference,
            r.rings.map_or("-".to_string(), |k| k.to_string()),
        );
    }
}
