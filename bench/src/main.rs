//! Wall time and peak memory of segvoronoi, Boost.Polygon's voronoi (the C++
//! original and the boostvoronoi port) and spade on uniform random points.
//!
//! `cargo run --release -- [--sizes 10000,100000,1000000] [--runs 5]
//! [--contenders segvoronoi,boost-cpp,boostvoronoi,spade]`
//!
//! Each (contender, size) runs in a child process (this binary again, in the
//! hidden `--child` mode), so the peak resident set size it reports (VmHWM) is
//! that contender's alone and not the high-water mark of whatever ran before.
//! One more child per size only generates the input: its peak is the
//! baseline that readers can subtract.

mod contenders;
mod input;
mod report;

use std::process::{exit, Command};

use contenders::{measure, Contender, Measured};

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
    pub n: usize,
    pub who: Who,
    pub result: Result<ChildReport, String>,
}

struct Options {
    sizes: Vec<usize>,
    runs: usize,
    contenders: Vec<Contender>,
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--child") {
        child(&args[1..]);
        return;
    }
    let options = parse_options(&args).unwrap_or_else(|message| {
        eprintln!("error: {message}");
        eprintln!("usage: segvoronoi-bench [--sizes N,N,..] [--runs R] [--contenders NAME,NAME,..]");
        exit(2);
    });
    let load_before = load_average();
    let mut rows = Vec::new();
    for &n in &options.sizes {
        let everyone = std::iter::once(Who::Input).chain(options.contenders.iter().copied().map(Who::Lib));
        for who in everyone {
            eprintln!("running {} on {n} points ...", who.name());
            let result = run_child(who, n, options.runs);
            if let Err(message) = &result {
                eprintln!("  failed: {message}");
            }
            rows.push(Row { n, who, result });
        }
    }
    report::print_all(&rows, options.runs);
    // Other work on a 2-core machine skews the times; this says how busy it was.
    println!("\nload average (1, 5, 15 min): before {load_before}, after {}", load_average());
}

fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".into())
}

fn parse_options(args: &[String]) -> Result<Options, String> {
    let mut options = Options {
        sizes: vec![10_000, 100_000, 1_000_000],
        runs: 5,
        contenders: Contender::available(),
    };
    let mut args = args.iter();
    while let Some(flag) = args.next() {
        let value = args.next().ok_or_else(|| format!("{flag} needs a value"))?;
        match flag.as_str() {
            "--sizes" => {
                options.sizes = value
                    .split(',')
                    .map(|s| s.trim().replace('_', "").parse::<usize>().map_err(|_| format!("bad size {s:?}")))
                    .collect::<Result<_, _>>()?;
            }
            "--runs" => {
                options.runs = value.parse().map_err(|_| format!("bad run count {value:?}"))?;
                if options.runs == 0 {
                    return Err("--runs must be at least 1".into());
                }
            }
            "--contenders" => {
                options.contenders = value
                    .split(',')
                    .map(|s| Contender::parse(s.trim()).ok_or_else(|| format!("unknown contender {s:?}")))
                    .collect::<Result<_, _>>()?;
            }
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    Ok(options)
}

/// Runs one measurement in a fresh process and parses its one-line report:
/// `RESULT <peak KiB> [<sites> <vertices> <seconds>...]`.
fn run_child(who: Who, n: usize, runs: usize) -> Result<ChildReport, String> {
    let exe = std::env::current_exe().map_err(|e| format!("cannot find own executable: {e}"))?;
    let output = Command::new(exe)
        .args(["--child", who.name(), &n.to_string(), &runs.to_string()])
        .output()
        .map_err(|e| format!("cannot start child: {e}"))?;
    if !output.status.success() {
        let stderr = String::from_utf8_lossy(&output.stderr);
        return Err(format!("child exited with {}: {}", output.status, stderr.trim()));
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
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
            let seconds = numbers[3.min(numbers.len())..]
                .iter()
                .map(|s| s.parse::<f64>().map_err(|_| bad()))
                .collect::<Result<Vec<_>, _>>()?;
            if seconds.is_empty() {
                return Err(bad());
            }
            Some(Measured { sites: int(1)?, vertices: int(2)?, seconds })
        }
    };
    Ok(ChildReport { peak_kib, measured })
}

/// The hidden child mode: `--child <who> <size> <runs>`.
fn child(args: &[String]) {
    let (who, n, runs) = match args {
        [who, n, runs] => (
            Who::parse(who).unwrap_or_else(|| panic!("unknown contender {who:?}")),
            n.parse::<usize>().expect("size"),
            runs.parse::<usize>().expect("runs"),
        ),
        _ => panic!("usage: --child <who> <size> <runs>"),
    };
    match who {
        Who::Input => {
            // The largest input form any contender holds (16 bytes a point);
            // kept alive until the peak is read.
            let points = std::hint::black_box(input::float_points(n, input::SEED));
            println!("RESULT {}", peak_rss_kib());
            drop(points);
        }
        Who::Lib(contender) => {
            let m = measure(contender, n, runs);
            let seconds: Vec<String> = m.seconds.iter().map(|s| format!("{s:.9}")).collect();
            println!("RESULT {} {} {} {}", peak_rss_kib(), m.sites, m.vertices, seconds.join(" "));
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
