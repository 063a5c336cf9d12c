//! Command-line arguments, parsed by hand: the program has six flags, which
//! does not justify a dependency.

use std::path::PathBuf;

/// The usage text printed by `--help`.
pub const USAGE: &str = "\
Usage: segvoronoi [INPUT] [--svg OUT.svg] [--topology] [--voronoi-pairs] [--stats]

Builds the Voronoi diagram of the points and line segments in INPUT.

INPUT is Boost.Polygon's voronoi text format: a count P, then P lines `x y`,
then a count S and S lines `x1 y1 x2 y2` (line segments; a missing S means
0). Tokens are separated by any whitespace. `-` reads standard input.
Segments may share endpoints but must not cross, overlap or pass through a
point. Without INPUT a built-in demo (a jittered ring, a cluster, collinear
points, a grid of cocircular points, a repeated point, short segments and a
polyline) is used.

Options:
  --svg OUT.svg      draw the diagram: edges (parabolic arcs as exact
                     quadratic Bezier curves), vertices (small dots), sites
                     (dots; segments as thick lines)
  --topology         print the canonical topology text on standard output
  --voronoi-pairs    add the VPAIRS and VVERTICES sections (implies --topology)
  --stats            print key=value statistics on standard error
  -h, --help         print this help
  -V, --version      print the version

Exit status: 0 on success, 1 when the library rejects the input (a
non-finite coordinate, segments that cross or overlap, a point inside a
segment: the message names the input indices) or an output cannot be
written, 2 for usage errors and unreadable or malformed input.
";

/// Where the input comes from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Source {
    /// The built-in demo input.
    Demo,
    /// Standard input (`-`).
    Stdin,
    /// A file.
    File(PathBuf),
}

/// What to do with the diagram.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    pub source: Source,
    pub svg: Option<PathBuf>,
    pub topology: bool,
    pub voronoi_pairs: bool,
    pub stats: bool,
}

/// The outcome of parsing: run, or answer `--help` / `--version` and stop.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Command {
    Run(Options),
    Help,
    Version,
}

/// Parses the arguments after the program name. The error is a message for
/// the user.
pub fn parse<I: IntoIterator<Item = String>>(args: I) -> Result<Command, String> {
    let mut options = Options { source: Source::Demo, svg: None, topology: false, voronoi_pairs: false, stats: false };
    let mut input: Option<String> = None;
    let mut args = args.into_iter();
    let mut only_positional = false;
    while let Some(arg) = args.next() {
        if only_positional || arg == "-" || !arg.starts_with('-') {
            if let Some(first) = &input {
                return Err(format!("more than one input given ({first:?} and {arg:?})"));
            }
            input = Some(arg);
            continue;
        }
        match arg.as_str() {
            "--" => only_positional = true,
            "-h" | "--help" => return Ok(Command::Help),
            "-V" | "--version" => return Ok(Command::Version),
            "--topology" => options.topology = true,
            "--voronoi-pairs" => {
                options.topology = true;
                options.voronoi_pairs = true;
            }
            "--stats" => options.stats = true,
            "--svg" => {
                let path = args.next().ok_or("--svg needs a file name")?;
                options.svg = Some(PathBuf::from(path));
            }
            _ => match arg.strip_prefix("--svg=") {
                Some(path) if !path.is_empty() => options.svg = Some(PathBuf::from(path)),
                Some(_) => return Err("--svg needs a file name".into()),
                None => return Err(format!("unknown option {arg:?}")),
            },
        }
    }
    options.source = match input.as_deref() {
        None => Source::Demo,
        Some("-") => Source::Stdin,
        Some(path) => Source::File(PathBuf::from(path)),
    };
    Ok(Command::Run(options))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(args: &[&str]) -> Result<Options, String> {
        match parse(args.iter().map(|s| s.to_string()))? {
            Command::Run(o) => Ok(o),
            other => panic!("expected a run, got {other:?}"),
        }
    }

    #[test]
    fn no_arguments_is_the_demo_with_no_output() {
        let o = run(&[]).unwrap();
        assert_eq!(o.source, Source::Demo);
        assert!(o.svg.is_none() && !o.topology && !o.voronoi_pairs && !o.stats);
    }

    #[test]
    fn flags_in_any_order() {
        let o = run(&["--stats", "in.txt", "--svg", "out.svg", "--topology"]).unwrap();
        assert_eq!(o.source, Source::File("in.txt".into()));
        assert_eq!(o.svg, Some(PathBuf::from("out.svg")));
        assert!(o.topology && o.stats && !o.voronoi_pairs);
        assert_eq!(run(&["--svg=a.svg"]).unwrap().svg, Some(PathBuf::from("a.svg")));
    }

    #[test]
    fn dash_is_stdin_and_double_dash_ends_options() {
        assert_eq!(run(&["-"]).unwrap().source, Source::Stdin);
        assert_eq!(run(&["--", "--stats"]).unwrap().source, Source::File("--stats".into()));
    }

    #[test]
    fn voronoi_pairs_implies_topology() {
        let o = run(&["--voronoi-pairs"]).unwrap();
        assert!(o.topology && o.voronoi_pairs);
    }

    #[test]
    fn mistakes_are_reported() {
        assert!(run(&["--svg"]).unwrap_err().contains("--svg"));
        assert!(run(&["--svg="]).unwrap_err().contains("--svg"));
        assert!(run(&["--frobnicate"]).unwrap_err().contains("--frobnicate"));
        assert!(run(&["a", "b"]).unwrap_err().contains("more than one input"));
    }

    #[test]
    fn help_and_version_stop() {
        assert_eq!(parse(["--stats".to_string(), "-h".to_string()]).unwrap(), Command::Help);
        assert_eq!(parse(["--version".to_string()]).unwrap(), Command::Version);
    }
}
