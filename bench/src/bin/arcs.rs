//! Circular arcs against segments and against chords (issue 31), in one
//! run, printed as markdown (`bash scripts/arcs-bench.sh`, which builds
//! this and runs it).
//!
//! `cargo run --release --bin arcs -- [--arcs 100000] [--runs 3]
//! [--timeout 600] [--no-scaling] [--only rounded,chains,random]`
//!
//! Three families of `--arcs` arcs each:
//! - rounded polygons: rounded rectangles (4 sides and 4 quarter arcs,
//!   tangent-continuous, through `add_bulged_polyline`), one in each cell of
//!   a unit grid, random sizes and corner radii; `--arcs / 4` of them;
//! - tangent chains: waves of half circles of radius 1/2, alternately down
//!   and up, tangent at every joint, in parallel rows 2 apart (through
//!   `add_bulged_polyline`);
//! - random arcs: one arc in each cell of a unit grid, random centre,
//!   radius (0.05 to 0.4) and sweep (0.05π to 1.95π, either way), half
//!   given by a bulge and half through a point (`add_arc`).
//!
//! Rows for each family, every one in its own child process (this binary
//! with `--child`), which reports the median time of `--runs` runs (fewer
//! when they pass a minute) and the growth of its peak resident set
//! (input included):
//! 1. segvoronoi on the arcs;
//! 2. segvoronoi on the same layout with every arc replaced by its chord
//!    (one segment): the time per arc against the time per segment;
//! 3. every arc as a polyline of 16 chords, through segvoronoi, Boost.Polygon
//!    (C++) and CGAL's segment Delaunay graph. Boost takes integers, so the
//!    whole input is scaled by a power of two (the largest that keeps every
//!    coordinate below 2^30) and each vertex rounded once (shared endpoints
//!    are the same float, so they round alike and chains stay closed);
//!    zero-length chords are dropped, and any pair of chords the rounding
//!    made cross is found by `Builder::check` and dropped (reported).
//!
//! Then the seed paper's experiment with arcs: random arcs in cells at
//! 1k, 10k and 100k arcs (and their chords), time per arc and per site.

#[path = "../child.rs"]
mod child;
#[path = "../contenders.rs"]
#[allow(dead_code)]
mod contenders;
#[path = "../input.rs"]
#[allow(unused_imports)]
mod input;
#[path = "../peak.rs"]
mod peak;
#[path = "../segments.rs"]
#[allow(dead_code, unused_imports)]
mod segments;
#[path = "../text.rs"]
mod text;

use std::path::Path;
use std::process::{exit, Command};
use std::time::{Duration, Instant};

use contenders::Contender;
use segments::Seg;
use segvoronoi::splitmix::SplitMix64;
use segvoronoi::{Builder, CircularArc, Point};
use segvoronoi_testgen::arcs::random_arc;
use text::{seconds, thousands};

const SEED: u64 = 31;

/// A family of arc inputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Family {
    Rounded,
    Chains,
    Random,
}

const FAMILIES: [Family; 3] = [Family::Rounded, Family::Chains, Family::Random];

impl Family {
    fn name(self) -> &'static str {
        match self {
            Family::Rounded => "rounded",
            Family::Chains => "chains",
            Family::Random => "random",
        }
    }

    fn title(self) -> &'static str {
        match self {
            Family::Rounded => "rounded polygons",
            Family::Chains => "tangent chains",
            Family::Random => "random arcs",
        }
    }

    fn parse(name: &str) -> Option<Family> {
        FAMILIES.into_iter().find(|f| f.name() == name)
    }
}

// ------------------------------------------------------------- the inputs

/// One input piece.
#[derive(Clone, Copy, Debug)]
enum Piece {
    Segment(Point, Point),
    Arc(CircularArc),
}

/// An input as the builder takes it: closed or open bulged polylines
/// (DXF's LWPOLYLINE) and lone arcs.
struct Input {
    /// (vertices with the bulge of the piece after each, closed)
    chains: Vec<(Vec<(Point, f64)>, bool)>,
    arcs: Vec<CircularArc>,
}

impl Input {
    /// Every piece, as `add_bulged_polyline` makes them.
    fn pieces(&self) -> Vec<Piece> {
        let mut out = Vec::new();
        for (chain, closed) in &self.chains {
            let n = chain.len();
            let count = if *closed { n } else { n - 1 };
            for k in 0..count {
                let ((p, bulge), (q, _)) = (chain[k], chain[(k + 1) % n]);
                out.push(if bulge == 0.0 {
                    Piece::Segment(p, q)
                } else {
                    Piece::Arc(CircularArc::from_bulge(p, q, bulge).expect("a valid arc"))
                });
            }
        }
        out.extend(self.arcs.iter().map(|&a| Piece::Arc(a)));
        out
    }

    /// The largest coordinate's magnitude.
    fn extent(&self) -> f64 {
        let chains = self.chains.iter().flat_map(|(c, _)| c.iter().map(|&(p, _)| p));
        let arcs = self.arcs.iter().flat_map(|a| [a.start(), a.end(), a.centre()]);
        chains.chain(arcs).fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()))
    }
}

/// Cells of a unit grid, `n` of them, row by row in a square.
fn cells(n: usize) -> impl Iterator<Item = (f64, f64)> {
    let side = (n as f64).sqrt().ceil().max(1.0) as usize;
    (0..n).map(move |k| ((k % side) as f64, (k / side) as f64))
}

fn generate(family: Family, arcs: usize) -> Input {
    let mut rng = SplitMix64(SEED ^ family as u64);
    let p = Point::new;
    match family {
        Family::Rounded => {
            // a rounded rectangle in each unit cell, w × h with corner radius r
            let q = (std::f64::consts::PI / 8.0).tan();
            let chains = cells(arcs.div_ceil(4))
                .map(|(i, j)| {
                    let (x, y) = (i + 0.05 + 0.1 * rng.unit(), j + 0.05 + 0.1 * rng.unit());
                    let (w, h) = (0.5 + 0.35 * rng.unit(), 0.5 + 0.35 * rng.unit());
                    let r = w.min(h) * (0.1 + 0.35 * rng.unit());
                    let chain = vec![
                        (p(x + r, y), 0.0),
                        (p(x + w - r, y), q),
                        (p(x + w, y + r), 0.0),
                        (p(x + w, y + h - r), q),
                        (p(x + w - r, y + h), 0.0),
                        (p(x + r, y + h), q),
                        (p(x, y + h - r), 0.0),
                        (p(x, y + r), q),
                    ];
                    (chain, true)
                })
                .collect();
            Input { chains, arcs: Vec::new() }
        }
        Family::Chains => {
            // rows of `per_row` half circles of radius 1/2 (reaching 1/2
            // above and below their row), 2 apart
            let per_row = (arcs as f64).sqrt().ceil().max(1.0) as usize;
            let mut chains = Vec::new();
            let mut left = arcs;
            let mut row = 0;
            while left > 0 {
                let m = left.min(per_row);
                let y = 2.0 * row as f64;
                let chain = (0..=m).map(|k| (p(k as f64, y), if k % 2 == 0 { -1.0 } else { 1.0 })).collect();
                chains.push((chain, false));
                left -= m;
                row += 1;
            }
            Input { chains, arcs: Vec::new() }
        }
        Family::Random => Input { chains: Vec::new(), arcs: cells(arcs).map(|(x, y)| random_arc(&mut rng, x, y)).collect() },
    }
}

/// Each arc replaced by its chord, the segments as they are.
fn chords(pieces: &[Piece]) -> Vec<[Point; 2]> {
    pieces
        .iter()
        .map(|&piece| match piece {
            Piece::Segment(a, b) => [a, b],
            Piece::Arc(arc) => [arc.start(), arc.end()],
        })
        .collect()
}

/// Chords an arc in the chord-polyline rows.
const CHORDS: usize = 16;

/// The largest power of two keeping every coordinate below 2^30.
fn integer_scale(extent: f64) -> f64 {
    let mut scale = 1.0f64;
    while extent * scale * 2.0 < (1u64 << 30) as f64 {
        scale *= 2.0;
    }
    while extent * scale >= (1u64 << 30) as f64 {
        scale /= 2.0;
    }
    scale
}

/// The pieces as integer segments: each arc as `CHORDS` chords, every
/// vertex scaled by `scale` and rounded once; zero-length chords dropped,
/// then pairs the rounding made cross dropped. Returns the segments, the
/// zero-length chords and the crossing pairs dropped.
fn integer_chords(pieces: &[Piece], scale: f64) -> Result<(Vec<Seg>, usize, usize), String> {
    let round = |p: Point| [(p.x * scale).round() as i32, (p.y * scale).round() as i32];
    let mut out: Vec<Seg> = Vec::new();
    let mut zero = 0;
    let mut push = |a: Point, b: Point| {
        let ([x0, y0], [x1, y1]) = (round(a), round(b));
        if (x0, y0) == (x1, y1) {
            zero += 1;
        } else {
            out.push([x0, y0, x1, y1]);
        }
    };
    for &piece in pieces {
        match piece {
            Piece::Segment(a, b) => push(a, b),
            Piece::Arc(arc) => {
                let points: Vec<Point> = (0..=CHORDS)
                    .map(|k| match k {
                        0 => arc.start(),
                        k if k == CHORDS => arc.end(),
                        k => arc.point_at(k as f64 / CHORDS as f64),
                    })
                    .collect();
                for w in points.windows(2) {
                    push(w[0], w[1]);
                }
            }
        }
    }
    for dropped in 0..1000 {
        let mut b = Builder::new();
        b.add_segments(out.iter().copied().map(segments::to_float)).map_err(|e| e.to_string())?;
        match b.check() {
            Ok(()) => return Ok((out, zero, dropped)),
            Err(e) if e.kind() == segvoronoi::ErrorKind::Intersecting && e.indices().len() == 2 => {
                let (i, j) = (e.indices()[0].min(e.indices()[1]), e.indices()[0].max(e.indices()[1]));
                out.remove(j);
                out.remove(i);
            }
            Err(e) => return Err(format!("the rounded chords: {e}")),
        }
    }
    Err("more than 1000 crossing pairs after rounding".into())
}

// ------------------------------------------------------------- the builds

/// segvoronoi on the arcs, as the family gives them.
fn build_arcs(input: &Input) -> segvoronoi::Diagram {
    let mut b = Builder::new();
    for (chain, closed) in &input.chains {
        b.add_bulged_polyline(chain, *closed).expect("a finite chain");
    }
    for &arc in &input.arcs {
        b.add_arc(arc).expect("room for the arc");
    }
    b.build().unwrap_or_else(|e| {
        contenders::fail(format!(
            "segvoronoi refused {} arcs: {:?}: {} (indices {:?})",
            b.arc_count(),
            e.kind(),
            e.message(),
            e.indices()
        ))
    })
}

/// segvoronoi on the chords, one segment an arc.
fn build_chords(segments: &[[Point; 2]]) -> segvoronoi::Diagram {
    let mut b = Builder::new();
    b.add_segments(segments.iter().copied()).expect("finite chords");
    b.build().unwrap_or_else(|e| {
        contenders::fail(format!(
            "segvoronoi refused {} chords: {:?}: {} (indices {:?})",
            segments.len(),
            e.kind(),
            e.message(),
            e.indices()
        ))
    })
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Runs `work` `runs` times (fewer when they pass a minute) and returns
/// the median time, the runs made and the detail of the last run. The
/// output is dropped outside the timed region.
fn timed<T>(runs: usize, mut work: impl FnMut() -> T, detail: impl Fn(&T) -> String) -> (f64, usize, String) {
    let mut seconds = Vec::new();
    let mut last = String::new();
    while seconds.len() < runs {
        let start = Instant::now();
        let output = std::hint::black_box(work());
        seconds.push(start.elapsed().as_secs_f64());
        last = detail(&output);
        drop(output);
        if seconds.iter().sum::<f64>() > 60.0 {
            break;
        }
    }
    let n = seconds.len();
    (median(seconds), n, last)
}

fn counts(d: &segvoronoi::Diagram) -> String {
    format!("{} {}", d.site_count(), d.vertex_count())
}

/// The hidden child mode: `--child arcs|chords <family> <arcs> <runs>` or
/// `--child poly16 <peer> <file> <runs>`; prints
/// `RESULT <peak KiB> <median seconds> <runs> <sites> <vertices>`.
fn child(args: &[String]) {
    let [what, which, arg, runs] = args else {
        panic!("usage: --child arcs|chords|poly16 <family or peer> <arcs or file> <runs>");
    };
    let runs: usize = runs.parse().expect("runs");
    let base = peak::reset_peak();
    let (seconds, runs, detail) = match what.as_str() {
        "arcs" | "chords" => {
            let family = Family::parse(which).unwrap_or_else(|| panic!("unknown family {which:?}"));
            let input = generate(family, arg.parse().expect("a number of arcs"));
            if what == "arcs" {
                timed(runs, || build_arcs(&input), counts)
            } else {
                let segments = chords(&input.pieces());
                drop(input);
                timed(runs, || build_chords(&segments), counts)
            }
        }
        "poly16" => {
            let contender = Contender::parse(which).unwrap_or_else(|| panic!("unknown peer {which:?}"));
            // one run a call, so that the runs stop after a minute
            let mut seconds = Vec::new();
            let mut m = None;
            while seconds.len() < runs && seconds.iter().sum::<f64>() <= 60.0 {
                let measured = contenders::measure_segments(contender, Path::new(arg), 1);
                seconds.extend(measured.seconds.iter().copied());
                m = Some(measured);
            }
            let m = m.expect("a run");
            let n = seconds.len();
            (median(seconds), n, format!("{} {}", m.sites, m.vertices))
        }
        _ => panic!("unknown child {what:?}"),
    };
    println!("RESULT {} {seconds:.9} {runs} {detail}", peak::peak_above(base));
}

// ------------------------------------------------------------- the parent

struct Options {
    arcs: usize,
    runs: usize,
    timeout: Duration,
    scaling: bool,
    only: Option<Vec<Family>>,
    /// The builders of the chord-polyline rows.
    peers: Vec<Contender>,
}

const USAGE: &str = "usage: arcs [--arcs N] [--runs R] [--timeout SECONDS] [--no-scaling] [--only rounded,chains,random] \
[--peers segvoronoi,boost-cpp,cgal|none]";

fn parse_options(args: &[String]) -> Result<Options, String> {
    let mut options = Options {
        arcs: 100_000,
        runs: 3,
        timeout: Duration::from_secs(600),
        scaling: true,
        only: None,
        peers: vec![Contender::Segvoronoi, Contender::BoostCpp, Contender::Cgal],
    };
    let mut args = args.iter();
    while let Some(flag) = args.next() {
        if flag == "--no-scaling" {
            options.scaling = false;
            continue;
        }
        let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
        match flag.as_str() {
            "--arcs" => options.arcs = value.parse().ok().filter(|&n| n >= 4).ok_or("bad --arcs")?,
            "--runs" => options.runs = value.parse().ok().filter(|&r| r > 0).ok_or("bad --runs")?,
            "--timeout" => {
                options.timeout = Duration::from_secs_f64(value.parse().ok().filter(|&s: &f64| s > 0.0).ok_or("bad --timeout")?)
            }
            "--only" => {
                options.only = Some(
                    value
                        .split(',')
                        .map(|w| Family::parse(w).ok_or_else(|| format!("unknown family {w:?}")))
                        .collect::<Result<_, _>>()?,
                )
            }
            "--peers" if value == "none" => options.peers.clear(),
            "--peers" => {
                options.peers = value
                    .split(',')
                    .map(|w| {
                        Contender::parse(w)
                            .filter(|c| [Contender::Segvoronoi, Contender::BoostCpp, Contender::Cgal].contains(c))
                            .ok_or_else(|| format!("unknown peer {w:?}"))
                    })
                    .collect::<Result<_, _>>()?
            }
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    Ok(options)
}

/// What a child reported.
#[derive(Clone)]
struct Report {
    seconds: f64,
    peak_kib: u64,
    runs: usize,
    sites: usize,
    vertices: usize,
}

fn run_child(args: &[&str], options: &Options) -> Result<Report, String> {
    let exe = std::env::current_exe().map_err(|e| format!("cannot find own executable: {e}"))?;
    let mut command = Command::new(exe);
    command.arg("--child").args(args).arg(options.runs.to_string());
    let stdout = child::run(command, options.timeout).map_err(|e| match e.lines().last() {
        Some(last) if e.starts_with("child exited") => format!("failed: {last}"),
        _ => e,
    })?;
    let line = stdout.lines().find_map(|l| l.strip_prefix("RESULT ")).ok_or("no RESULT line")?;
    let words: Vec<&str> = line.split(' ').collect();
    let bad = || format!("malformed RESULT line {line:?}");
    let word = |k: usize| words.get(k).copied().ok_or_else(bad);
    Ok(Report {
        peak_kib: word(0)?.parse().map_err(|_| bad())?,
        seconds: word(1)?.parse().map_err(|_| bad())?,
        runs: word(2)?.parse().map_err(|_| bad())?,
        sites: word(3)?.parse().map_err(|_| bad())?,
        vertices: word(4)?.parse().map_err(|_| bad())?,
    })
}

/// One row of a family's table.
struct Row {
    input: String,
    pieces: usize,
    builder: &'static str,
    result: Result<Report, String>,
}

struct FamilyResult {
    family: Family,
    arcs: usize,
    rows: Vec<Row>,
    note: Option<String>,
}

fn measure(label: &str, args: &[&str], options: &Options) -> Result<Report, String> {
    eprintln!("{label} ...");
    let result = run_child(args, options);
    match &result {
        Ok(r) => eprintln!(
            "  {:.3} s ({} run(s)), {:.1} MiB, {} sites, {} vertices",
            r.seconds,
            r.runs,
            r.peak_kib as f64 / 1024.0,
            r.sites,
            r.vertices
        ),
        Err(e) => eprintln!("  {e}"),
    }
    result
}

fn run_family(family: Family, options: &Options, dir: &Path) -> FamilyResult {
    let input = generate(family, options.arcs);
    let pieces = input.pieces();
    let arcs = pieces.iter().filter(|p| matches!(p, Piece::Arc(_))).count();
    let n = options.arcs.to_string();
    let title = family.title();
    let mut rows = vec![
        Row {
            input: "arcs".into(),
            pieces: pieces.len(),
            builder: "segvoronoi",
            result: measure(&format!("{title}: arcs"), &["arcs", family.name(), &n], options),
        },
        Row {
            input: "1 chord an arc".into(),
            pieces: pieces.len(),
            builder: "segvoronoi",
            result: measure(&format!("{title}: chords"), &["chords", family.name(), &n], options),
        },
    ];
    if options.peers.is_empty() {
        return FamilyResult { family, arcs, rows, note: None };
    }
    let scale = integer_scale(input.extent());
    let note;
    match integer_chords(&pieces, scale) {
        Ok((segs, zero, crossing)) => {
            note = Some(format!(
                "{title}: the {CHORDS}-chord polylines scaled by 2^{} and rounded to integers; {zero} zero-length chords \
                 and {crossing} pairs of crossing chords dropped.",
                scale.log2()
            ));
            let path = dir.join(format!("{}-poly16.bin", family.name()));
            let file = path.to_string_lossy().into_owned();
            if let Err(e) = segments::write_file(&path, &segs) {
                eprintln!("cannot write {file}: {e}");
            }
            for &contender in &options.peers {
                let built = contenders::Contender::available().contains(&contender);
                let result = if built {
                    measure(
                        &format!("{title}: {CHORDS} chords, {}", contender.name()),
                        &["poly16", contender.name(), &file],
                        options,
                    )
                } else {
                    Err("not built".into())
                };
                rows.push(Row {
                    input: format!("{CHORDS} chords an arc, integers"),
                    pieces: segs.len(),
                    builder: match contender {
                        Contender::Segvoronoi => "segvoronoi",
                        Contender::BoostCpp => "Boost.Polygon (C++)",
                        _ => "CGAL",
                    },
                    result,
                });
            }
            let _ = std::fs::remove_file(&path);
        }
        Err(e) => note = Some(format!("{title}: no {CHORDS}-chord rows: {e}")),
    }
    FamilyResult { family, arcs, rows, note }
}

fn micros(s: f64) -> String {
    let us = s * 1e6;
    if us >= 10.0 {
        format!("{us:.1} µs")
    } else {
        format!("{us:.2} µs")
    }
}

fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".into())
}

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
    format!("{cpu}, {cores} cores, {memory}")
}

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
    let dir = std::env::temp_dir().join(format!("segvoronoi-arcs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("cannot create {}: {e}", dir.display()));
    let load_before = load_average();
    let start = Instant::now();
    let mut results = Vec::new();
    for family in FAMILIES {
        if options.only.as_ref().is_some_and(|only| !only.contains(&family)) {
            continue;
        }
        results.push(run_family(family, &options, &dir));
    }
    // the seed paper's experiment: random arcs in cells, growing n
    let mut scaling = Vec::new();
    if options.scaling {
        for n in [1_000usize, 10_000, 100_000] {
            let reuse = results.iter().find(|r| r.family == Family::Random && n == options.arcs);
            let (a, c) = match reuse {
                Some(r) => (r.rows[0].result.clone(), r.rows[1].result.clone()),
                None => {
                    let s = n.to_string();
                    (
                        measure(&format!("random arcs n = {n}: arcs"), &["arcs", "random", &s], &options),
                        measure(&format!("random arcs n = {n}: chords"), &["chords", "random", &s], &options),
                    )
                }
            };
            scaling.push((n, a, c));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    print_tables(&results, &scaling, &options, &load_before, start.elapsed());
}

/// One size of the seed paper's experiment: n, the arcs' report, the chords'.
type ScalingRow = (usize, Result<Report, String>, Result<Report, String>);

fn print_tables(results: &[FamilyResult], scaling: &[ScalingRow], options: &Options, load_before: &str, elapsed: Duration) {
    let commit = command_line("git", &["rev-parse", "--short", "HEAD"]);
    let dirty = command_line("git", &["status", "--porcelain", "--untracked-files=no"]);
    let commit = if dirty == "unknown" { commit } else { format!("{commit} (with uncommitted changes)") };
    println!(
        "Measured {} UTC at commit `{commit}`; {}; {}; load average (1, 5, 15 min) {load_before} before, {} after; \
         median of {} runs (fewer where they passed a minute); {:.0} s in all.\n",
        command_line("date", &["-u", "+%Y-%m-%d %H:%M"]),
        machine(),
        command_line("rustc", &["--version"]),
        load_average(),
        options.runs,
        elapsed.as_secs_f64()
    );
    println!("| family | input | pieces | builder | time | per arc | peak memory | sites | vertices |");
    println!("|---|---|---:|---|---:|---:|---:|---:|---:|");
    for f in results {
        for row in &f.rows {
            let cells = match &row.result {
                Ok(r) => {
                    let runs = if r.runs < options.runs {
                        format!(" ({} run{})", r.runs, if r.runs == 1 { "" } else { "s" })
                    } else {
                        String::new()
                    };
                    let sites = if row.builder == "segvoronoi" { thousands(r.sites) } else { "—".into() };
                    format!(
                        "{}{runs} | {} | {:.0} MiB | {sites} | {} |",
                        seconds(r.seconds),
                        micros(r.seconds / f.arcs as f64),
                        r.peak_kib as f64 / 1024.0,
                        thousands(r.vertices)
                    )
                }
                Err(e) => format!("{e} | | | | |"),
            };
            println!(
                "| {} ({} arcs) | {} | {} | {} | {cells}",
                f.family.title(),
                thousands(f.arcs),
                row.input,
                thousands(row.pieces),
                row.builder
            );
        }
    }
    println!("\nArcs against segments and against chords, per family (from the table above):\n");
    println!(
        "| family | arcs: time per piece | 1 chord an arc: time per segment | ratio | {CHORDS} chords (segvoronoi) / arcs: time | \
         sites | vertices |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for f in results {
        let ok = |k: usize| f.rows.get(k).and_then(|r| r.result.as_ref().ok());
        let pieces = f.rows[0].pieces as f64;
        let (Some(a), Some(c)) = (ok(0), ok(1)) else {
            let chord = ok(1).map_or("—".into(), |c| micros(c.seconds / pieces));
            println!("| {} | refused (see above) | {chord} | — | — | — | — |", f.family.title());
            continue;
        };
        let ours16 = f.rows.iter().skip(2).find(|r| r.builder == "segvoronoi").and_then(|r| r.result.as_ref().ok());
        let (time16, sites16, vertices16) = match ours16 {
            Some(p) => (
                format!("{:.1}×", p.seconds / a.seconds),
                format!("{:.1}×", p.sites as f64 / a.sites as f64),
                format!("{:.1}×", p.vertices as f64 / a.vertices as f64),
            ),
            None => ("—".into(), "—".into(), "—".into()),
        };
        println!(
            "| {} | {} | {} | **{:.2}×** | {time16} | {sites16} | {vertices16} |",
            f.family.title(),
            micros(a.seconds / pieces),
            micros(c.seconds / pieces),
            a.seconds / c.seconds
        );
    }
    if !scaling.is_empty() {
        println!("\nThe seed paper's experiment with arcs: random arcs in cells (one arc a cell), growing n:\n");
        println!("| arcs | time | per arc | per site | sites | vertices | chords: per segment | ratio |");
        println!("|---:|---:|---:|---:|---:|---:|---:|---:|");
        for (n, a, c) in scaling {
            match a {
                Ok(a) => {
                    let (chord, ratio) = match c {
                        Ok(c) => (micros(c.seconds / *n as f64), format!("{:.2}×", a.seconds / c.seconds)),
                        Err(e) => (e.clone(), "—".into()),
                    };
                    println!(
                        "| {} | {} | {} | {} | {} | {} | {chord} | {ratio} |",
                        thousands(*n),
                        seconds(a.seconds),
                        micros(a.seconds / *n as f64),
                        micros(a.seconds / a.sites as f64),
                        thousands(a.sites),
                        thousands(a.vertices)
                    );
                }
                Err(e) => println!("| {} | {e} | | | | | | |", thousands(*n)),
            }
        }
    }
    println!(
        "\nTimes are the median wall time of a build from the input in memory to the finished diagram; peak memory is the \
         growth of the child process's peak resident set while it ran (input included). Per arc: the time over the \
         number of arcs (the rounded polygons also have one side per arc). Sites are segvoronoi's (an arc or a \
         segment is its two endpoint sites and its open piece; shared endpoints once); vertices are each \
         library's finite Voronoi vertices (CGAL's a face of the segment Delaunay graph each)."
    );
    for f in results {
        if let Some(note) = &f.note {
            println!("\n{note}");
        }
    }
}
