//! `segvoronoi`: builds the Voronoi diagram of the points and line segments
//! in a Boost.Polygon voronoi text file (or of a built-in demo) and writes an
//! SVG picture, the canonical topology text and statistics. `segvoronoi
//! --help` for usage.

mod args;
mod demo;
mod stats;
mod svg;

use std::io::{Read, Write};
use std::process::ExitCode;
use std::time::Instant;

use args::{Command, Options, Source};
use segvoronoi::boost_text as input;
use segvoronoi::{Builder, TopologyOptions};

/// Why the program stops early: an exit status and a message for the user.
struct Failure {
    status: u8,
    message: String,
}

/// The library rejected the input, or an output could not be written.
fn failed(message: String) -> Failure {
    Failure { status: 1, message }
}

/// The command line or the input is wrong.
fn bad_input(message: String) -> Failure {
    Failure { status: 2, message }
}

fn main() -> ExitCode {
    match run(std::env::args().skip(1)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure { status, message }) => {
            eprintln!("segvoronoi: {message}");
            ExitCode::from(status)
        }
    }
}

fn run(arguments: impl Iterator<Item = String>) -> Result<(), Failure> {
    let options = match args::parse(arguments) {
        Ok(Command::Run(options)) => options,
        Ok(Command::Help) => return print(args::USAGE),
        Ok(Command::Version) => return print(&format!("segvoronoi {}\n", segvoronoi::VERSION)),
        Err(message) => return Err(bad_input(format!("{message}\nTry 'segvoronoi --help'."))),
    };
    let (name, input) = read_input(&options.source)?;

    // Library errors (a non-finite coordinate, crossing segments) name the
    // input indices: exit status 1 with that message.
    let mut builder = Builder::new();
    builder.add_points(input.points).map_err(|e| failed(format!("{name}: {e}")))?;
    let segments = input.segments.into_iter().map(|[x1, y1, x2, y2]| [[x1, y1], [x2, y2]]);
    builder.add_segments(segments).map_err(|e| failed(format!("{name}: {e}")))?;
    // Only the construction is timed: not reading, not writing.
    let start = Instant::now();
    let diagram = builder.build().map_err(|e| failed(format!("{name}: {e}")))?;
    let build_s = start.elapsed().as_secs_f64();

    if let Some(path) = &options.svg {
        std::fs::write(path, svg::render(&diagram)).map_err(|e| failed(format!("cannot write {}: {e}", path.display())))?;
    }
    if options.topology {
        print(&diagram.topology(TopologyOptions::default().with_voronoi_pairs(options.voronoi_pairs)))?;
    }
    if options.stats {
        eprint!("{}", stats::report(&diagram, build_s));
    }
    if !wants_output(&options) {
        // Nothing asked for: say what was built and how to see it.
        print(&format!(
            "{name}: {} sites, {} vertices, {} edges (see --svg, --topology, --stats)\n",
            diagram.site_count(),
            diagram.vertex_count(),
            diagram.edge_count()
        ))?;
    }
    Ok(())
}

fn wants_output(options: &Options) -> bool {
    options.svg.is_some() || options.topology || options.stats
}

/// The points and segments of the chosen input and a name for it in messages.
fn read_input(source: &Source) -> Result<(String, input::Input), Failure> {
    let (name, bytes) = match source {
        Source::Demo => return Ok(("demo input".into(), demo::input())),
        Source::Stdin => {
            let mut bytes = Vec::new();
            std::io::stdin().read_to_end(&mut bytes).map_err(|e| bad_input(format!("cannot read standard input: {e}")))?;
            ("standard input".to_string(), bytes)
        }
        Source::File(path) => {
            let bytes = std::fs::read(path).map_err(|e| bad_input(format!("cannot read {}: {e}", path.display())))?;
            (path.display().to_string(), bytes)
        }
    };
    // Invalid UTF-8 becomes U+FFFD and so a parse error on the right line.
    let input = input::parse(&String::from_utf8_lossy(&bytes)).map_err(|e| bad_input(format!("{name}: {e}")))?;
    Ok((name, input))
}

/// Writes to standard output; a closed pipe is an output error, not a panic.
fn print(text: &str) -> Result<(), Failure> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes()).and_then(|()| out.flush()).map_err(|e| failed(format!("cannot write to standard output: {e}")))
}
