//! The headline table: every main workload against every peer that does it,
//! measured in one run on one machine, printed as markdown
//! (`bash scripts/headline-bench.sh`, which builds this and runs it).
//!
//! `cargo run --release --bin headline -- [--runs 3] [--scale 1.0]
//! [--timeout 300] [--coast FILE] [--coast-split FILE]`
//!
//! Workloads (sizes times `--scale`):
//! - points: 1M uniform random points, integer coordinates in [0, 10⁶)²;
//! - short segments: 100k random disjoint segments (Boost.Polygon's own
//!   benchmark style), integer endpoints;
//! - long segments: 16k long nearly parallel segments (issue 11);
//! - polygons: 200 star-shaped parts with a hole each, 100k segments,
//!   endpoints rounded to integers (so that the integer-only peers get the
//!   same input), built as segments;
//! - real coastlines (`--coast`): GSHHG's coastlines as segments, repeated
//!   segments removed (the script makes it with `scripts/coastlines.py`);
//! - medial axis: the polygons again through `add_polygon`, then the
//!   medial axis and its samples within 1e-4 of the extent;
//! - offsets: the same polygons (before rounding), one distance (-0.1, a
//!   tenth of a part's radius, within 1e-4): ours the build, the offset and
//!   its polylines; GEOS one buffer of the MultiPolygon; Clipper one offset;
//! - splitting: 20k crossing random "roads" (about 1.3 crossings per
//!   segment), and GSHHG's coastlines, borders and rivers, which cross
//!   (`--coast-split`): ours `split_crossings(true)` and the build, CGAL's
//!   segment Delaunay graph with intersections.
//!
//! Every (workload, peer) runs in its own child process (this binary with
//! `--child`), which prints the median time of `--runs` runs and the growth
//! of its peak resident set from its start (input included). A child still
//! running after `--timeout` seconds is killed and its cell says so.

#[path = "../cgal_split.rs"]
#[cfg(has_cgal_split)]
mod cgal_split;
#[path = "../child.rs"]
mod child;
#[path = "../contenders.rs"]
#[allow(dead_code)]
mod contenders;
#[path = "../input.rs"]
mod input;
#[path = "../offset_peers.rs"]
#[allow(dead_code)]
mod offset_peers;
#[path = "../peak.rs"]
mod peak;
#[path = "../roads.rs"]
mod roads;
#[path = "../segments.rs"]
#[allow(dead_code, unused_imports)]
mod segments;
#[path = "../sheet.rs"]
mod sheet;
#[path = "../text.rs"]
mod text;

use std::path::{Path, PathBuf};
use std::process::{exit, Command};
use std::time::{Duration, Instant};

use contenders::Contender;
use segments::Seg;
use segvoronoi::Builder;
use text::{seconds, thousands};

/// The peers, in the table's column order (ours first).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Peer {
    Ours,
    /// Ours with `Builder::threads(1)` (the build in halves needs two).
    OursOneThread,
    BoostCpp,
    Boostvoronoi,
    Spade,
    Cgal,
    Geos,
    Clipper,
}

const PEERS: [Peer; 8] =
    [Peer::Ours, Peer::OursOneThread, Peer::BoostCpp, Peer::Boostvoronoi, Peer::Spade, Peer::Cgal, Peer::Geos, Peer::Clipper];

impl Peer {
    fn name(self) -> &'static str {
        match self {
            Peer::Ours => "segvoronoi",
            Peer::OursOneThread => "segvoronoi-1-thread",
            Peer::BoostCpp => "boost-cpp",
            Peer::Boostvoronoi => "boostvoronoi",
            Peer::Spade => "spade",
            Peer::Cgal => "cgal",
            Peer::Geos => "geos",
            Peer::Clipper => "clipper",
        }
    }

    fn title(self) -> &'static str {
        match self {
            Peer::Ours => "segvoronoi",
            Peer::OursOneThread => "segvoronoi, 1 thread",
            Peer::BoostCpp => "Boost.Polygon (C++)",
            Peer::Boostvoronoi => "boostvoronoi",
            Peer::Spade => "spade",
            Peer::Cgal => "CGAL",
            Peer::Geos => "GEOS",
            Peer::Clipper => "Clipper",
        }
    }

    fn parse(name: &str) -> Option<Peer> {
        PEERS.into_iter().find(|p| p.name() == name)
    }

    /// Whether this binary has the peer compiled in.
    fn built(self) -> bool {
        match self {
            Peer::BoostCpp => cfg!(has_boost_cpp),
            Peer::Cgal => cfg!(has_cgal) && cfg!(has_cgal_split),
            Peer::Geos => cfg!(has_geos),
            Peer::Clipper => cfg!(has_clipper),
            _ => true,
        }
    }

    fn contender(self) -> Option<Contender> {
        match self {
            Peer::Ours | Peer::OursOneThread => Some(Contender::Segvoronoi),
            Peer::BoostCpp => Some(Contender::BoostCpp),
            Peer::Boostvoronoi => Some(Contender::Boostvoronoi),
            Peer::Spade => Some(Contender::Spade),
            Peer::Cgal => Some(Contender::Cgal),
            Peer::Geos | Peer::Clipper => None,
        }
    }
}

/// A row of the table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Workload {
    Points,
    Short,
    Long,
    Polygons,
    Coast,
    MedialAxis,
    Offsets,
    SplitRoads,
    SplitCoast,
}

const WORKLOADS: [Workload; 9] = [
    Workload::Points,
    Workload::Short,
    Workload::Long,
    Workload::Polygons,
    Workload::Coast,
    Workload::MedialAxis,
    Workload::Offsets,
    Workload::SplitRoads,
    Workload::SplitCoast,
];

impl Workload {
    fn name(self) -> &'static str {
        match self {
            Workload::Points => "points",
            Workload::Short => "short",
            Workload::Long => "long",
            Workload::Polygons => "polygons",
            Workload::Coast => "coast",
            Workload::MedialAxis => "medial-axis",
            Workload::Offsets => "offsets",
            Workload::SplitRoads => "split-roads",
            Workload::SplitCoast => "split-coast",
        }
    }

    fn parse(name: &str) -> Option<Workload> {
        WORKLOADS.into_iter().find(|w| w.name() == name)
    }

    /// The peers that do this workload.
    fn peers(self) -> &'static [Peer] {
        use Peer::*;
        match self {
            Workload::Points => &[Ours, OursOneThread, BoostCpp, Boostvoronoi, Spade, Cgal],
            Workload::Short | Workload::Long | Workload::Polygons | Workload::Coast => {
                &[Ours, OursOneThread, BoostCpp, Boostvoronoi, Cgal]
            }
            Workload::MedialAxis => &[Ours],
            Workload::Offsets => &[Ours, Geos, Clipper],
            Workload::SplitRoads | Workload::SplitCoast => &[Ours, Cgal],
        }
    }
}

/// What the parent prepared for a row: its label, its size and the child's
/// argument (a size or a file).
struct Prepared {
    label: String,
    size: String,
    arg: String,
    /// What the table's reader should know about the input.
    note: Option<String>,
}

struct Options {
    runs: usize,
    scale: f64,
    timeout: Duration,
    coast: Option<PathBuf>,
    coast_split: Option<PathBuf>,
    only: Option<Vec<Workload>>,
}

const USAGE: &str = "usage: headline [--runs R] [--scale F] [--timeout SECONDS] [--coast FILE] [--coast-split FILE] \
[--only WORKLOAD,..]\n(workloads: points, short, long, polygons, coast, medial-axis, offsets, split-roads, split-coast)";

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--child") {
        child(&args[1..]);
        return;
    }
    if args.iter().any(|a| a == "--help" || a == "-h") {
        println!("{USAGE}");
        return;
    }
    let options = parse_options(&args).unwrap_or_else(|message| {
        eprintln!("error: {message}\n{USAGE}");
        exit(2);
    });
    let dir = std::env::temp_dir().join(format!("segvoronoi-headline-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("cannot create {}: {e}", dir.display()));
    let load_before = load_average();
    let start = Instant::now();
    let mut rows = Vec::new();
    let mut notes = Vec::new();
    for workload in WORKLOADS {
        if options.only.as_ref().is_some_and(|only| !only.contains(&workload)) {
            continue;
        }
        let prepared = match prepare(workload, &options, &dir) {
            Ok(p) => p,
            Err(why) => {
                eprintln!("{}: skipped ({why})", workload.name());
                notes.push(format!("{}: not run ({why}).", workload.name()));
                continue;
            }
        };
        let mut cells = Vec::new();
        for peer in PEERS {
            let cell = if !workload.peers().contains(&peer) {
                Cell::Nothing
            } else if !peer.built() {
                Cell::NotBuilt
            } else {
                eprintln!("{} ({}): {} ...", prepared.label, prepared.size, peer.name());
                let result = run_child(workload, peer, &prepared.arg, &options);
                match &result {
                    Ok(r) => eprintln!("  {:.3} s, {:.1} MiB, {}", r.seconds, r.peak_kib as f64 / 1024.0, r.detail),
                    Err(e) => eprintln!("  failed: {e}"),
                }
                Cell::Ran(result)
            };
            cells.push(cell);
        }
        notes.extend(prepared.note.clone());
        rows.push((prepared, cells));
    }
    let _ = std::fs::remove_dir_all(&dir);
    print_table(&rows, &options, &load_before, start.elapsed(), &notes);
}

/// One cell of the table.
enum Cell {
    /// The peer does not do this workload.
    Nothing,
    /// The peer's library was missing when the benchmark was compiled.
    NotBuilt,
    Ran(Result<Report, String>),
}

/// What a child reported.
struct Report {
    seconds: f64,
    peak_kib: u64,
    runs: usize,
    detail: String,
}

fn parse_options(args: &[String]) -> Result<Options, String> {
    let mut options =
        Options { runs: 3, scale: 1.0, timeout: Duration::from_secs(300), coast: None, coast_split: None, only: None };
    let mut args = args.iter();
    while let Some(flag) = args.next() {
        let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
        match flag.as_str() {
            "--runs" => options.runs = value.parse().ok().filter(|&r| r > 0).ok_or("bad --runs")?,
            "--scale" => options.scale = value.parse().ok().filter(|&s: &f64| s > 0.0).ok_or("bad --scale")?,
            "--timeout" => {
                options.timeout = Duration::from_secs_f64(value.parse().ok().filter(|&s: &f64| s > 0.0).ok_or("bad --timeout")?)
            }
            "--coast" => options.coast = Some(value.into()),
            "--coast-split" => options.coast_split = Some(value.into()),
            "--only" => {
                options.only = Some(
                    value
                        .split(',')
                        .map(|w| Workload::parse(w).ok_or_else(|| format!("unknown workload {w:?}")))
                        .collect::<Result<_, _>>()?,
                )
            }
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    Ok(options)
}

fn scaled(n: usize, options: &Options) -> usize {
    ((n as f64 * options.scale).round() as usize).max(100)
}

/// Makes the row's input (a file for the segment workloads) and its label.
fn prepare(workload: Workload, options: &Options, dir: &Path) -> Result<Prepared, String> {
    let file = |name: &str, segments: &[Seg]| -> Result<String, String> {
        let path = dir.join(name);
        segments::write_file(&path, segments).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        Ok(path.to_string_lossy().into_owned())
    };
    let polygons = scaled(100_000, options);
    Ok(match workload {
        Workload::Points => {
            let n = scaled(1_000_000, options);
            // CGAL's shim takes segments: a zero-length one is its point.
            let points = input::grid_points(n, input::SEED);
            let degenerate: Vec<Seg> = points.iter().map(|&[x, y]| [x, y, x, y]).collect();
            let arg = file("points.bin", &degenerate)?;
            Prepared { label: "points (uniform random)".into(), size: thousands(n), arg, note: None }
        }
        Workload::Short => {
            let n = scaled(100_000, options);
            let generated = segments::generate(segments::Method::Short, n, input::SEED);
            let arg = file("short.bin", &generated.segments)?;
            Prepared {
                label: "short segments (random, disjoint)".into(),
                size: thousands(generated.segments.len()),
                arg,
                note: None,
            }
        }
        Workload::Long => {
            let n = scaled(16_384, options);
            let generated = segments::parallel(n, input::SEED);
            let arg = file("long.bin", &generated)?;
            Prepared { label: "long segments (nearly parallel)".into(), size: thousands(generated.len()), arg, note: None }
        }
        Workload::Polygons => {
            let segments = integer_polygons(polygons)?;
            let arg = file("polygons.bin", &segments)?;
            Prepared { label: "polygons (star parts with a hole)".into(), size: thousands(segments.len()), arg, note: None }
        }
        Workload::Coast => {
            let path = options.coast.as_ref().ok_or("no --coast file")?;
            let (segments, dropped) = coast_segments(path)?;
            let arg = file("coast.bin", &segments)?;
            let note = (dropped > 0).then(|| {
                format!("real coastlines: {dropped} pairs of crossing segments of the binned data left out, for the peers.")
            });
            Prepared { label: "real coastlines (GSHHG)".into(), size: thousands(segments.len()), arg, note }
        }
        Workload::MedialAxis => Prepared {
            label: "medial axis of the polygons".into(),
            size: thousands(sheet::for_segments(polygons).len() * (sheet::OUTER + sheet::HOLE)),
            arg: polygons.to_string(),
            note: None,
        },
        Workload::Offsets => Prepared {
            label: "offset of the polygons".into(),
            size: thousands(sheet::for_segments(polygons).len() * (sheet::OUTER + sheet::HOLE)),
            arg: polygons.to_string(),
            note: None,
        },
        Workload::SplitRoads => {
            let n = scaled(20_000, options);
            Prepared { label: "splitting crossing roads".into(), size: thousands(n), arg: n.to_string(), note: None }
        }
        Workload::SplitCoast => {
            let path = options.coast_split.as_ref().ok_or("no --coast-split file")?;
            let n = read_boost_text(path)?.len();
            Prepared {
                label: "splitting real coasts, borders, rivers".into(),
                size: thousands(n),
                arg: path.to_string_lossy().into_owned(),
                note: None,
            }
        }
    })
}

/// The polygons' segments with their ends rounded to integers (2^15 to a
/// unit, where the parts have radius 1); checked to stay disjoint.
fn integer_polygons(segments: usize) -> Result<Vec<Seg>, String> {
    let round = |p: [f64; 2]| [(p[0] * 32768.0).round() as i32, (p[1] * 32768.0).round() as i32];
    let mut out = Vec::new();
    for part in sheet::for_segments(segments) {
        for ring in &part {
            for k in 0..ring.len() {
                let ([x0, y0], [x1, y1]) = (round(ring[k]), round(ring[(k + 1) % ring.len()]));
                out.push([x0, y0, x1, y1]);
            }
        }
    }
    let mut b = Builder::new();
    b.add_segments(out.iter().copied().map(segments::to_float)).map_err(|e| e.to_string())?;
    b.check().map_err(|e| format!("the rounded polygons: {e}"))?;
    Ok(out)
}

/// A Boost.Polygon text file's segments (no isolated points).
fn read_boost_text(path: &Path) -> Result<Vec<[f64; 4]>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let input = segvoronoi::boost_text::parse(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    if !input.points.is_empty() {
        return Err(format!("{}: isolated points are not supported here", path.display()));
    }
    Ok(input.segments)
}

/// The coastline file's segments as integers, each once (the binned files
/// repeat a few chords, which the strict build merges but the peers may
/// not), without the few pairs that cross (the binned coastlines cross at
/// a few places; the peers take no crossing input). Returns the segments
/// and the number of pairs left out.
fn coast_segments(path: &Path) -> Result<(Vec<Seg>, usize), String> {
    let mut out: Vec<Seg> = read_boost_text(path)?
        .into_iter()
        .map(|s| {
            let [x0, y0, x1, y1] = s.map(|c| c as i32);
            if (x0, y0) <= (x1, y1) {
                [x0, y0, x1, y1]
            } else {
                [x1, y1, x0, y0]
            }
        })
        .filter(|[x0, y0, x1, y1]| (x0, y0) != (x1, y1))
        .collect();
    out.sort_unstable();
    out.dedup();
    for dropped in 0..1000 {
        let mut b = Builder::new();
        b.add_segments(out.iter().copied().map(segments::to_float)).map_err(|e| e.to_string())?;
        match b.check() {
            Ok(()) => return Ok((out, dropped)),
            Err(e) if e.kind() == segvoronoi::ErrorKind::Intersecting && e.indices().len() == 2 => {
                let (i, j) = (e.indices()[0].min(e.indices()[1]), e.indices()[0].max(e.indices()[1]));
                out.remove(j);
                out.remove(i);
            }
            Err(e) => return Err(format!("{}: {e}", path.display())),
        }
    }
    Err(format!("{}: more than 1000 crossing pairs", path.display()))
}

/// Runs one (workload, peer) in a fresh process and parses its report line
/// `RESULT <peak KiB> <median seconds> <runs> <detail...>`.
fn run_child(workload: Workload, peer: Peer, arg: &str, options: &Options) -> Result<Report, String> {
    let exe = std::env::current_exe().map_err(|e| format!("cannot find own executable: {e}"))?;
    let mut command = Command::new(exe);
    command.args(["--child", workload.name(), peer.name(), &options.runs.to_string(), arg]);
    if peer == Peer::OursOneThread {
        command.env(contenders::THREADS_VARIABLE, "1");
    }
    // a cell has room for one line: a timeout, or the child's last words
    let stdout = child::run(command, options.timeout).map_err(|e| match e.lines().last() {
        Some(last) if e.starts_with("child exited") => format!("failed: {}", last.rsplit(": ").next().unwrap_or(last)),
        _ => e,
    })?;
    let line = stdout.lines().find_map(|l| l.strip_prefix("RESULT ")).ok_or("no RESULT line")?;
    let mut words = line.splitn(4, ' ');
    let bad = || format!("malformed RESULT line {line:?}");
    let peak_kib = words.next().and_then(|w| w.parse().ok()).ok_or_else(bad)?;
    let seconds = words.next().and_then(|w| w.parse().ok()).ok_or_else(bad)?;
    let runs = words.next().and_then(|w| w.parse().ok()).ok_or_else(bad)?;
    Ok(Report { seconds, peak_kib, runs, detail: words.next().unwrap_or("").to_string() })
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Times `work` `runs` times (fewer when one run takes more than a minute)
/// and returns the median and the runs made; `work` returns the detail.
fn timed(runs: usize, mut work: impl FnMut() -> String) -> (f64, usize, String) {
    let mut seconds = Vec::new();
    let mut detail = String::new();
    while seconds.len() < runs {
        let start = Instant::now();
        detail = work();
        seconds.push(start.elapsed().as_secs_f64());
        if seconds.iter().sum::<f64>() > 60.0 {
            break;
        }
    }
    let n = seconds.len();
    (median(seconds), n, detail)
}

/// The hidden child mode: `--child <workload> <peer> <runs> <size or file>`.
fn child(args: &[String]) {
    let [workload, peer, runs, arg] = args else {
        panic!("usage: --child <workload> <peer> <runs> <size or file>");
    };
    let workload = Workload::parse(workload).unwrap_or_else(|| panic!("unknown workload {workload:?}"));
    let peer = Peer::parse(peer).unwrap_or_else(|| panic!("unknown peer {peer:?}"));
    let runs: usize = runs.parse().expect("runs");
    let base = peak::reset_peak();
    let (seconds, runs, detail) = match (workload, peer) {
        (Workload::Points, Peer::Cgal) => {
            // the points as the zero-length segments the parent wrote
            let m = contenders::measure_segments(Contender::Cgal, Path::new(arg), runs);
            let detail = format!("{} vertices", thousands(m.vertices));
            (median(m.seconds.clone()), m.seconds.len(), detail)
        }
        (Workload::Points, _) => {
            // the same points, generated again (16 bytes a point in the file)
            let n =
                std::fs::metadata(arg).map(|m| m.len() as usize / 16).unwrap_or_else(|e| contenders::fail(format!("{arg}: {e}")));
            let m = contenders::measure(peer.contender().expect("a builder"), n, runs);
            let detail = format!("{} vertices", thousands(m.vertices));
            (median(m.seconds.clone()), m.seconds.len(), detail)
        }
        (Workload::Short | Workload::Long | Workload::Polygons | Workload::Coast, _) => {
            let m = contenders::measure_segments(peer.contender().expect("a builder"), Path::new(arg), runs);
            let detail = format!("{} vertices", thousands(m.vertices));
            (median(m.seconds.clone()), m.seconds.len(), detail)
        }
        (Workload::MedialAxis, Peer::Ours) => {
            let input = sheet::for_segments(arg.parse().expect("a size"));
            timed(runs, || medial_axis(&input))
        }
        (Workload::Offsets, _) => {
            let input = sheet::for_segments(arg.parse().expect("a size"));
            offsets(peer, &input, runs)
        }
        (Workload::SplitRoads | Workload::SplitCoast, _) => {
            let input: Vec<roads::Segment> = match workload {
                Workload::SplitRoads => roads::roads(arg.parse().expect("a size"), 2.0, 11),
                _ => read_boost_text(Path::new(arg))
                    .unwrap_or_else(|e| contenders::fail(e))
                    .into_iter()
                    .map(|[x0, y0, x1, y1]| [[x0, y0], [x1, y1]])
                    .collect(),
            };
            split(peer, &input, runs)
        }
        _ => contenders::fail(format!("{} does not do {}", peer.name(), workload.name())),
    };
    println!("RESULT {} {seconds:.9} {runs} {detail}", peak::peak_above(base));
}

/// Ours: the polygons' build, the medial axis and its samples.
fn medial_axis(input: &[sheet::Polygon]) -> String {
    let mut b = Builder::new();
    for rings in input {
        b.add_polygon(rings).expect("simple, disjoint rings");
    }
    let d = b.build().expect("a diagram");
    let axis = d.medial_axis();
    let tolerance = 1e-4 * d.extent();
    let samples: usize = axis.chains.iter().map(|c| d.sample_chain(c, tolerance).map_or(0, |p| p.len())).sum();
    format!("{} chains, {} samples", thousands(axis.chains.len()), thousands(samples))
}

/// The offset's distance and its chord tolerance (a ten-thousandth of a
/// part's radius; GEOS's quadrant segments chosen for it).
const OFFSET: f64 = -0.1;
const OFFSET_TOLERANCE: f64 = 1e-4;

fn offsets(peer: Peer, input: &[sheet::Polygon], runs: usize) -> (f64, usize, String) {
    let (_, tolerance) = offset_peers::quadsegs_within(OFFSET, OFFSET_TOLERANCE);
    match peer {
        Peer::Ours => timed(runs, || {
            let mut b = Builder::new();
            for rings in input {
                b.add_polygon(rings).expect("simple, disjoint rings");
            }
            let d = b.build().expect("a diagram");
            let offset = d.offset(OFFSET).expect("an offset");
            let lines = offset.polylines(tolerance).expect("a tolerance");
            format!("{} rings, {} vertices", thousands(lines.len()), thousands(lines.iter().map(Vec::len).sum()))
        }),
        #[cfg(has_geos)]
        Peer::Geos => {
            let g = offset_peers::geos::Input::new(input);
            timed(runs, || {
                let (vertices, rings) = g.buffer_within(OFFSET, OFFSET_TOLERANCE);
                format!("{} rings, {} vertices", thousands(rings), thousands(vertices))
            })
        }
        #[cfg(has_clipper)]
        Peer::Clipper => {
            let c = offset_peers::clipper::Input::new(input);
            timed(runs, || {
                let (vertices, rings) = c.offset(OFFSET, tolerance);
                format!("{} rings, {} vertices", thousands(rings), thousands(vertices))
            })
        }
        _ => contenders::fail(format!("{} is not built in", peer.name())),
    }
}

fn split(peer: Peer, input: &[roads::Segment], runs: usize) -> (f64, usize, String) {
    match peer {
        Peer::Ours => timed(runs, || {
            let mut b = Builder::new();
            b.split_crossings(true);
            b.add_segments(input.iter().copied()).expect("finite segments");
            let d = b.build().expect("a diagram of the split input");
            let stats = d.stats();
            format!("{} crossings, {} sites", thousands(stats.crossings), thousands(stats.sites))
        }),
        #[cfg(has_cgal_split)]
        Peer::Cgal => timed(runs, || {
            let (sites, crossings, _) = cgal_split::build(input);
            format!("{} intersection points, {} sites", thousands(crossings), thousands(sites))
        }),
        _ => contenders::fail(format!("{} is not built in", peer.name())),
    }
}

fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".into())
}

/// A line of a command's output, or "unknown".
fn command_line(program: &str, args: &[&str]) -> String {
    Command::new(program)
        .args(args)
        .output()
        .ok()
        .filter(|o| o.status.success())
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map(|s| s.trim().to_string())
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| "unknown".into())
}

/// The machine in one line: CPU, cores, memory, OS.
fn machine() -> String {
    let cpuinfo = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let cpu = cpuinfo
        .lines()
        .find_map(|l| l.strip_prefix("model name"))
        .map_or("unknown CPU", |v| v.trim_start_matches([' ', '\t', ':']));
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    let meminfo = std::fs::read_to_string("/proc/meminfo").unwrap_or_default();
    let memory = meminfo
        .lines()
        .find_map(|l| l.strip_prefix("MemTotal:"))
        .and_then(|v| v.split_whitespace().next()?.parse::<f64>().ok())
        .map_or("? GiB".into(), |kib| format!("{:.0} GiB", kib / 1024.0 / 1024.0));
    let os = std::fs::read_to_string("/etc/os-release")
        .ok()
        .and_then(|s| s.lines().find_map(|l| l.strip_prefix("PRETTY_NAME=")).map(|v| v.trim_matches('"').to_string()))
        .unwrap_or_else(|| "unknown OS".into());
    format!("{cpu}, {cores} cores, {memory}, {os}")
}

fn print_table(rows: &[(Prepared, Vec<Cell>)], options: &Options, load_before: &str, elapsed: Duration, notes: &[String]) {
    let commit = command_line("git", &["rev-parse", "--short", "HEAD"]);
    let dirty = command_line("git", &["status", "--porcelain", "--untracked-files=no"]);
    let commit = if dirty == "unknown" { commit } else { format!("{commit} (with uncommitted changes)") };
    println!(
        "Measured {} UTC at commit `{commit}`; {}; {}; load average (1, 5, 15 min) {load_before} before, {} after; \
         median of {} runs (fewer where one took over a minute); {:.0} s in all.\n",
        command_line("date", &["-u", "+%Y-%m-%d %H:%M"]),
        machine(),
        command_line("rustc", &["--version"]),
        load_average(),
        options.runs,
        elapsed.as_secs_f64()
    );
    let ours_column = PEERS.iter().position(|&p| p == Peer::Ours).expect("ours");
    let mut header = "| workload | size |".to_string();
    let mut rule = "|---|---:|".to_string();
    for peer in PEERS {
        header += &format!(" {} |", peer.title());
        rule += "---:|";
    }
    println!("{header}\n{rule}");
    let mut details = Vec::new();
    for (prepared, cells) in rows {
        let ours = match &cells[ours_column] {
            Cell::Ran(Ok(r)) => Some(r.seconds),
            _ => None,
        };
        let mut line = format!("| {} | {} |", prepared.label, prepared.size);
        let mut row_details = Vec::new();
        for (peer, cell) in PEERS.iter().zip(cells) {
            let text = match cell {
                Cell::Nothing => "—".to_string(),
                Cell::NotBuilt => "not built".to_string(),
                Cell::Ran(Err(e)) => e.clone(),
                Cell::Ran(Ok(r)) => {
                    let mib = r.peak_kib as f64 / 1024.0;
                    let runs = if r.runs < options.runs {
                        format!(", {} run{}", r.runs, if r.runs == 1 { "" } else { "s" })
                    } else {
                        String::new()
                    };
                    row_details.push((peer.title(), r.detail.clone()));
                    match ours {
                        Some(o) if *peer != Peer::Ours => {
                            format!("**{:.2}×** {} {mib:.0} MiB{runs}", r.seconds / o, seconds(r.seconds))
                        }
                        _ => format!("{} {mib:.0} MiB{runs}", seconds(r.seconds)),
                    }
                }
            };
            line += &format!(" {text} |");
        }
        println!("{line}");
        if row_details.iter().all(|(_, d)| *d == row_details[0].1) && row_details.len() > 1 {
            details.push(format!("{}: {} (each)", prepared.label, row_details[0].1));
        } else {
            let each: Vec<String> = row_details.iter().map(|(p, d)| format!("{p} {d}")).collect();
            details.push(format!("{}: {}", prepared.label, each.join("; ")));
        }
    }
    println!(
        "\nEach peer's cell: its time as a multiple of segvoronoi's (**bold**; above 1 segvoronoi is faster), \
         its median time, and the growth of its process's peak resident set while it ran (input included). \
         — : the peer does not do this workload."
    );
    for note in notes {
        println!("\n{note}");
    }
    println!("\nWhat each built:\n");
    for d in details {
        println!("- {d}");
    }
}
