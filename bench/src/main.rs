//! Wall time and peak memory of segvoronoi, Boost.Polygon's voronoi (the C++
//! original and the boostvoronoi port) and spade on uniform random points,
//! and of the first three on disjoint line segments.
//!
//! `cargo run --release -- [--input points|segments|seed|parallel|staircase]
//! [--sizes N,N,..] [--runs 5]
//! [--contenders segvoronoi,cgal,boost-cpp,boostvoronoi,spade]
//! [--methods 1,2,3] [--timeout SECONDS]`
//!
//! - `points` (the default): uniform random points, 10k, 100k, 1M.
//! - `segments`: short random disjoint segments (Boost.Polygon's benchmark
//!   style), 10k, 100k, 1M.
//! - `seed`: the seed paper's experiment, its three ways of drawing random
//!   disjoint segments (`--methods`), 256 to 4096 segments.
//! - `parallel`, `staircase` (issue 11): long nearly parallel segments, and
//!   axis-parallel staircase outlines (`segvoronoi_testgen::long_segments`),
//!   16k, 64k, 256k. Several segment workloads go in one run as a list,
//!   `--input parallel,staircase,segments`, so their per-segment costs are
//!   measured on the same machine state.
//! - `stack`, `vstack`, `hatch`, `rows`, `staggered`, `bus` (issue 27):
//!   equal parallel segments with aligned ends and other exactly
//!   cocircular families (`segvoronoi_testgen::ties`), 3,000 and 30,000.
//!
//! Each (contender, size) runs in a child process (this binary again, in the
//! hidden `--child` mode), so the peak resident set size it reports (VmHWM) is
//! that contender's alone and not the high-water mark of whatever ran before.
//! One more child per size only holds the input: its peak is the baseline
//! that readers can subtract. Segment inputs are generated and checked once
//! per size by this parent and handed to the children as a file.

mod child;
mod contenders;
mod input;
mod report;
mod segments;
mod text;

use std::path::{Path, PathBuf};
use std::process::{exit, Command};
use std::time::{Duration, Instant};

use contenders::{measure, measure_segments, Contender, Measured};
use segments::Method;

/// Who a child measured: a contender, or nobody (input-only baseline).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Who {
    Input,
    Lib(Contender),
}

impl Who {
    fn name(self) -> &'static str {
        match self {
            Who::Input => "input",
            Who::Lib(c) => c.name(),
        }
    }

    fn parse(name: &str) -> Option<Who> {
        if name == "input" {
            return Some(Who::Input);
        }
        Contender::parse(name).map(Who::Lib)
    }
}

/// What is being built: uniform points, or segments drawn by a method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Workload {
    Points,
    Segments(Method),
    /// Long nearly parallel segments (issue 11).
    Parallel,
    /// Axis-parallel staircase outlines (issue 11).
    Staircase,
    /// An exactly cocircular family of issue 27 (`ties::FAMILIES[i]`:
    /// stacks and hatches of equal parallel segments, rows, ...).
    Ties(usize),
}

impl Workload {
    pub fn name(self) -> String {
        match self {
            Workload::Points => "points".into(),
            Workload::Segments(Method::Short) => "segments".into(),
            Workload::Segments(m) => format!("seed{}", m.number()),
            Workload::Parallel => "parallel".into(),
            Workload::Staircase => "staircase".into(),
            Workload::Ties(i) => segments::TIES[i].into(),
        }
    }

    fn parse(name: &str) -> Option<Workload> {
        match name {
            "points" => Some(Workload::Points),
            "segments" => Some(Workload::Segments(Method::Short)),
            "parallel" => Some(Workload::Parallel),
            "staircase" => Some(Workload::Staircase),
            _ if segments::TIES.contains(&name) => segments::TIES.iter().position(|&t| t == name).map(Workload::Ties),
            _ => name.strip_prefix("seed")?.parse().ok().and_then(Method::from_number).map(Workload::Segments),
        }
    }

    /// What `n` counts.
    pub fn unit(self) -> &'static str {
        match self {
            Workload::Points => "points",
            _ => "segments",
        }
    }
}

/// What one child reported.
#[derive(Clone, Debug)]
pub struct ChildReport {
    pub peak_kib: u64,
    /// `None` for the input-only baseline.
    pub measured: Option<Measured>,
}

/// One line of the results: a child's report, or why it failed.
#[derive(Clone, Debug)]
pub struct Row {
    pub workload: Workload,
    pub n: usize,
    pub who: Who,
    pub result: Result<ChildReport, String>,
}

/// How a segment input came about (generated once, in the parent).
#[derive(Clone, Debug)]
pub struct InputInfo {
    pub workload: Workload,
    pub n: usize,
    pub seconds: f64,
    pub draws: u64,
    pub repairs: u64,
    pub restarts: u64,
    pub mean_length: f64,
    /// Least distance between two segments near each other.
    pub least_gap: Option<f64>,
    /// Share of horizontal and vertical segments.
    pub axis_share: f64,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Suite {
    Points,
    Segments,
    Seed,
}

struct Options {
    suite: Suite,
    /// The segment workloads of a `Segments` suite, in order.
    workloads: Vec<Workload>,
    sizes: Vec<usize>,
    runs: usize,
    contenders: Vec<Contender>,
    methods: Vec<Method>,
    timeout: Duration,
}

const USAGE: &str = "usage: segvoronoi-bench [--input points|segments|seed|parallel|staircase|stack|vstack|hatch|rows|staggered|bus[,..]] [--sizes N,N,..] [--runs R] \
[--contenders NAME,NAME,..] [--methods 1,2,3] [--timeout SECONDS]";

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
        eprintln!("error: {message}");
        eprintln!("{USAGE}");
        exit(2);
    });
    let load_before = load_average();
    match options.suite {
        Suite::Points => {
            let mut rows = Vec::new();
            for &n in &options.sizes {
                for who in everyone(&options) {
                    eprintln!("running {} on {n} points ...", who.name());
                    rows.push(run_logged(Workload::Points, who, n, &options, None));
                }
            }
            report::print_all(&rows, options.runs);
        }
        Suite::Segments | Suite::Seed => {
            let workloads: Vec<Workload> = match options.suite {
                Suite::Segments => options.workloads.clone(),
                _ => options.methods.iter().map(|&m| Workload::Segments(m)).collect(),
            };
            let (rows, inputs) = run_segments(&workloads, &options);
            if options.suite == Suite::Segments {
                report::print_segments(&rows, &inputs, options.runs);
            } else {
                report::print_seed(&rows, &inputs, options.runs);
            }
        }
    }
    // Other work on a 2-core machine skews the times; this says how busy it was.
    println!("\nload average (1, 5, 15 min): before {load_before}, after {}", load_average());
}

fn everyone(options: &Options) -> impl Iterator<Item = Who> + '_ {
    std::iter::once(Who::Input).chain(options.contenders.iter().copied().map(Who::Lib))
}

fn run_logged(workload: Workload, who: Who, n: usize, options: &Options, file: Option<&Path>) -> Row {
    let start = Instant::now();
    let result = run_child(workload, who, n, options, file);
    match &result {
        Err(message) => eprintln!("  failed: {message}"),
        Ok(_) if who != Who::Input => eprintln!("  done in {:.1} s", start.elapsed().as_secs_f64()),
        Ok(_) => {}
    }
    Row { workload, n, who, result }
}

/// Generates, checks and writes each segment input, then runs the children
/// on it.
fn run_segments(workloads: &[Workload], options: &Options) -> (Vec<Row>, Vec<InputInfo>) {
    let dir = std::env::temp_dir().join(format!("segvoronoi-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("cannot create {}: {e}", dir.display()));
    let (mut rows, mut inputs) = (Vec::new(), Vec::new());
    for &workload in workloads {
        for &n in &options.sizes {
            eprintln!("generating {} segments ({}) ...", n, workload.name());
            let start = Instant::now();
            let generated = match workload {
                Workload::Segments(method) => segments::generate(method, n, input::SEED),
                Workload::Parallel => {
                    segments::Generated { segments: segments::parallel(n, input::SEED), draws: n as u64, ..Default::default() }
                }
                Workload::Staircase => {
                    let segments = segments::staircase(n, input::SEED);
                    segments::Generated { draws: segments.len() as u64, segments, ..Default::default() }
                }
                Workload::Ties(i) => {
                    let segments = segments::ties_family(segments::TIES[i], n).expect("a family");
                    segments::Generated { draws: segments.len() as u64, segments, ..Default::default() }
                }
                Workload::Points => unreachable!("segment workloads only"),
            };
            let seconds = start.elapsed().as_secs_f64();
            // The issue-11 shapes are legal by construction (and unit-tested
            // so); the grid check refuses shared endpoints and would choke on
            // long segments. segvoronoi's own exact input check still runs.
            let least_gap = match workload {
                Workload::Segments(_) => segments::verify(&generated.segments)
                    .unwrap_or_else(|e| panic!("generator bug, {} n = {n}: {e}", workload.name())),
                _ => None,
            };
            let n = generated.segments.len();
            let file = dir.join(format!("{}-{n}.bin", workload.name()));
            segments::write_file(&file, &generated.segments).unwrap_or_else(|e| panic!("cannot write {}: {e}", file.display()));
            inputs.push(InputInfo {
                workload,
                n,
                seconds,
                draws: generated.draws,
                repairs: generated.repairs,
                restarts: generated.restarts,
                mean_length: generated.mean_length(),
                least_gap,
                axis_share: segments::axis_parallel_share(&generated.segments),
            });
            drop(generated);
            for who in everyone(options) {
                eprintln!("running {} on {n} segments ({}) ...", who.name(), workload.name());
                rows.push(run_logged(workload, who, n, options, Some(&file)));
            }
            let _ = std::fs::remove_file(&file);
        }
    }
    let _ = std::fs::remove_dir(&dir);
    (rows, inputs)
}

fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".into())
}

fn parse_list<T>(value: &str, parse: impl Fn(&str) -> Result<T, String>) -> Result<Vec<T>, String> {
    value.split(',').map(|s| parse(s.trim())).collect()
}

fn parse_options(args: &[String]) -> Result<Options, String> {
    let mut suite = Suite::Points;
    let mut workloads = vec![Workload::Segments(Method::Short)];
    let mut sizes = None;
    let mut runs = 5;
    let mut contenders = None;
    let mut methods = vec![Method::Redraw, Method::Shorten, Method::Swap];
    let mut timeout = Duration::from_secs(1800);
    let mut args = args.iter();
    while let Some(flag) = args.next() {
        let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
        match flag.as_str() {
            "--input" | "--suite" => {
                suite = match value.as_str() {
                    "points" => Suite::Points,
                    "seed" => Suite::Seed,
                    _ => {
                        workloads = parse_list(value, |s| match Workload::parse(s) {
                            Some(
                                w @ (Workload::Segments(Method::Short)
                                | Workload::Parallel
                                | Workload::Staircase
                                | Workload::Ties(_)),
                            ) => Ok(w),
                            _ => Err(format!(
                                "unknown input {s:?} (points, seed, or a list of segments, parallel, staircase, {})",
                                segments::TIES.join(", ")
                            )),
                        })?;
                        Suite::Segments
                    }
                }
            }
            "--sizes" => {
                sizes = Some(parse_list(value, |s| {
                    s.replace('_', "").parse::<usize>().ok().filter(|&n| n > 0).ok_or_else(|| format!("bad size {s:?}"))
                })?);
            }
            "--runs" => {
                runs = value.parse().map_err(|_| format!("bad run count {value:?}"))?;
                if runs == 0 {
                    return Err("--runs must be at least 1".into());
                }
            }
            "--contenders" => {
                contenders = Some(parse_list(value, |s| Contender::parse(s).ok_or_else(|| format!("unknown contender {s:?}")))?);
            }
            "--methods" => {
                methods = parse_list(value, |s| {
                    s.parse().ok().and_then(Method::from_number).ok_or_else(|| format!("unknown method {s:?} (1, 2 or 3)"))
                })?;
            }
            "--timeout" => {
                let seconds: f64 =
                    value.parse().ok().filter(|&s: &f64| s > 0.0).ok_or_else(|| format!("bad timeout {value:?}"))?;
                timeout = Duration::from_secs_f64(seconds);
            }
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    let issue11 = workloads.iter().any(|w| matches!(w, Workload::Parallel | Workload::Staircase));
    let ties = workloads.iter().all(|w| matches!(w, Workload::Ties(_)));
    let sizes = sizes.unwrap_or_else(|| match suite {
        Suite::Segments if ties => vec![3_000, 30_000],
        Suite::Segments if issue11 => vec![16_384, 65_536, 262_144],
        Suite::Points | Suite::Segments => vec![10_000, 100_000, 1_000_000],
        Suite::Seed => vec![256, 512, 1024, 2048, 4096],
    });
    let contenders = match (contenders, suite) {
        (Some(list), Suite::Points) => {
            if let Some(c) = list.iter().find(|c| !c.takes_points()) {
                return Err(format!("{} is benchmarked on segments only", c.name()));
            }
            list
        }
        (Some(list), _) => {
            if let Some(c) = list.iter().find(|c| !c.takes_segments()) {
                return Err(format!("{} takes no line segments", c.name()));
            }
            list
        }
        (None, Suite::Points) => Contender::available().into_iter().filter(|c| c.takes_points()).collect(),
        (None, _) => Contender::available().into_iter().filter(|c| c.takes_segments()).collect(),
    };
    Ok(Options { suite, workloads, sizes, runs, contenders, methods, timeout })
}

/// Runs one measurement in a fresh process and parses its one-line report:
/// `RESULT <peak KiB> [<sites> <vertices> <edges> <Σx> <Σy> <seconds>...]`
/// (the sums as `f64` bit patterns, exact). A child
/// still running after the timeout is killed.
fn run_child(workload: Workload, who: Who, n: usize, options: &Options, file: Option<&Path>) -> Result<ChildReport, String> {
    let exe = std::env::current_exe().map_err(|e| format!("cannot find own executable: {e}"))?;
    let mut command = Command::new(exe);
    command.args(["--child", &workload.name(), who.name(), &n.to_string(), &options.runs.to_string()]);
    if let Some(file) = file {
        command.arg(file);
    }
    let stdout = child::run(command, options.timeout)?;
    let line = stdout
        .lines()
        .find_map(|l| l.strip_prefix("RESULT "))
        .ok_or_else(|| format!("child printed no RESULT line: {stdout:?}"))?;
    let numbers: Vec<&str> = line.split_whitespace().collect();
    let bad = || format!("malformed RESULT line {line:?}");
    let peak_kib = numbers.first().and_then(|s| s.parse().ok()).ok_or_else(bad)?;
    let measured = match who {
        Who::Input => None,
        Who::Lib(_) => {
            let int = |i: usize| numbers.get(i).and_then(|s| s.parse::<usize>().ok()).ok_or_else(bad);
            let sum = |i: usize| numbers.get(i).and_then(|s| u64::from_str_radix(s, 16).ok()).map(f64::from_bits).ok_or_else(bad);
            let seconds = numbers[6.min(numbers.len())..]
                .iter()
                .map(|s| s.parse::<f64>().map_err(|_| bad()))
                .collect::<Result<Vec<_>, _>>()?;
            if seconds.is_empty() {
                return Err(bad());
            }
            Some(Measured { sites: int(1)?, vertices: int(2)?, edges: int(3)?, vertex_sum: [sum(4)?, sum(5)?], seconds })
        }
    };
    Ok(ChildReport { peak_kib, measured })
}

/// The hidden child mode: `--child <workload> <who> <size> <runs> [<file>]`.
fn child(args: &[String]) {
    let (workload, who, n, runs, file) = match args {
        [workload, who, n, runs, rest @ ..] if rest.len() <= 1 => (
            Workload::parse(workload).unwrap_or_else(|| panic!("unknown workload {workload:?}")),
            Who::parse(who).unwrap_or_else(|| panic!("unknown contender {who:?}")),
            n.parse::<usize>().expect("size"),
            runs.parse::<usize>().expect("runs"),
            rest.first().map(PathBuf::from),
        ),
        _ => panic!("usage: --child <workload> <who> <size> <runs> [<file>]"),
    };
    let file = || file.clone().unwrap_or_else(|| panic!("{} needs the input file", workload.name()));
    match (workload, who) {
        (Workload::Points, Who::Input) => {
            // The largest input form any contender holds (16 bytes a point);
            // kept alive until the peak is read.
            let points = std::hint::black_box(input::float_points(n, input::SEED));
            println!("RESULT {}", peak_rss_kib());
            drop(points);
        }
        (_, Who::Input) => {
            // segvoronoi's `f64` form, the largest (32 bytes a segment).
            let segments = segments::read_file(&file(), segments::to_float).expect("input file");
            let segments = std::hint::black_box(segments);
            println!("RESULT {}", peak_rss_kib());
            drop(segments);
        }
        (_, Who::Lib(contender)) => {
            let m = match workload {
                Workload::Points => measure(contender, n, runs),
                _ => measure_segments(contender, &file(), runs),
            };
            let seconds: Vec<String> = m.seconds.iter().map(|s| format!("{s:.9}")).collect();
            let [sx, sy] = m.vertex_sum.map(|s| format!("{:x}", s.to_bits()));
            println!("RESULT {} {} {} {} {sx} {sy} {}", peak_rss_kib(), m.sites, m.vertices, m.edges, seconds.join(" "));
        }
    }
}

/// The process's peak resident set size (VmHWM), in KiB, as the kernel
/// counts it: every page this process ever had resident at once.
fn peak_rss_kib() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").expect("/proc/self/status (Linux only)");
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .expect("VmHWM in /proc/self/status")
}
