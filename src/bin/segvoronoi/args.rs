//! Command-line arguments, parsed by hand: the program has six flags, which
//! does not justify a dependency.

use std::path::PathBuf;

/// The usage text printed by `--help`.
pub const USAGE: &str = "\
Usage: segvoronoi [INPUT] [--svg OUT.svg] [--topology] [--voronoi-pairs] [--stats]
                  [--medial-axis OUT.wkt|OUT.json] [--tolerance T]
                  [--corner-angle DEG] [--prune-spurs K] [--max-inscribed-circle]

Builds the Voronoi diagram of the points and line segments in INPUT.

INPUT is Boost.Polygon's voronoi text format: a count P, then P lines `x y`,
then a count S and S lines `x1 y1 x2 y2` (line segments; a missing S means
0). Tokens are separated by any whitespace. `-` reads standard input.
Segments may share endpoints but must not cross, overlap or pass through a
point. Without INPUT a built-in demo (a jittered ring, a cluster, collinear
points, a grid of cocircular points, a repeated point, short segments and a
polyline) is used.

INPUT is read as WKT instead when its name ends in `.wkt` or its text
starts with a WKT keyword: POINT, MULTIPOINT, LINESTRING, MULTILINESTRING,
POLYGON, MULTIPOLYGON, GEOMETRYCOLLECTION, in any case, EMPTY allowed, an
optional Z, M or ZM dimension (the extra ordinates are ignored), any number
of geometries one after the other. Each polygon's rings bound the domain
(even-odd: a ring inside a ring is a hole; orientation does not matter);
linestrings and points are obstacles. Rings must not cross themselves or
each other (the message names the polygons and rings).

Options:
  --svg OUT.svg      draw the diagram: edges (parabolic arcs as exact
                     quadratic Bezier curves), vertices (small dots), sites
                     (dots; segments as thick lines). With polygons also the
                     domain (lightly shaded, even-odd), the medial axis
                     (thick, coloured by clearance from teal at 0 to
                     magenta at the largest clearance, linear in RGB) and
                     the largest inscribed circle (dashed)
  --topology         print the canonical topology text on standard output
  --voronoi-pairs    add the VPAIRS and VVERTICES sections (implies --topology)
  --stats            print key=value statistics on standard error
  --medial-axis OUT  write the medial axis (the Voronoi edges inside the
                     domain that are not separators; without polygons every
                     such edge). OUT.wkt: one MULTILINESTRING Z, a linestring
                     per chain sampled within the tolerance, z the clearance
                     at each point; the pieces of a chain that reach
                     infinity (only without polygons) are cut off, the rest
                     of the chain is kept. OUT.json: the exact chains, each
                     with `closed` and its pieces: Voronoi edge id, kind
                     (line or parabola), both ends (a vertex id and point,
                     or a direction to infinity), the clearance at both
                     ends (null at infinity), for a parabola its focus (the
                     point site) and directrix (the segment's endpoints)
  --tolerance T      chord tolerance of every sampled output, in input
                     units (default 1e-4 times the input's bounding-box
                     diagonal)
  --corner-angle DEG leave out the branches of the medial axis that run
                     into a convex corner of interior angle above DEG
                     degrees (0 to 180; 180, the default, leaves out none):
                     the spurs of curves flattened into chords
  --prune-spurs K    leave out the branches from a leaf to a junction that
                     are shorter than K times the clearance at the junction
                     (K >= 0; 0, the default, leaves out none; a branch
                     into a corner is at least as long as that clearance,
                     so useful factors are above 1). Both filters
                     look at the unfiltered axis once (what a removal
                     leaves is not filtered again) and keep a part of the
                     axis whole that they would remove entirely; they apply
                     to --medial-axis and --svg
  --max-inscribed-circle
                     print the largest disk inside the domain, `x y r`, on
                     standard output (exit status 1 without polygons)
  -h, --help         print this help
  -V, --version      print the version

Example: segvoronoi glyph.wkt --medial-axis axis.wkt --svg axis.svg

Exit status: 0 on success, 1 when the library rejects the input (a
non-finite coordinate, segments that cross or overlap, a point inside a
segment, rings that cross: the message names the input indices, polygons
and rings) or an output cannot be written, 2 for usage errors and
unreadable or malformed input (for WKT the message names the line and
column).
";

/// The format of `--medial-axis`, from its file name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AxisFormat {
    /// Sampled: one `MULTILINESTRING Z`.
    Wkt,
    /// The exact chains.
    Json,
}

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
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    pub source: Source,
    pub svg: Option<PathBuf>,
    pub topology: bool,
    pub voronoi_pairs: bool,
    pub stats: bool,
    /// `--medial-axis`: where and in which format.
    pub medial_axis: Option<(PathBuf, AxisFormat)>,
    /// `--tolerance`: positive and finite.
    pub tolerance: Option<f64>,
    /// `--corner-angle`, in degrees.
    pub corner_angle: Option<f64>,
    /// `--prune-spurs`.
    pub prune_spurs: Option<f64>,
    pub max_inscribed_circle: bool,
}

/// The outcome of parsing: run, or answer `--help` / `--version` and stop.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    Run(Options),
    Help,
    Version,
}

/// Parses the arguments after the program name. The error is a message for
/// the user.
pub fn parse<I: IntoIterator<Item = String>>(args: I) -> Result<Command, String> {
    let mut options = Options {
        source: Source::Demo,
        svg: None,
        topology: false,
        voronoi_pairs: false,
        stats: false,
        medial_axis: None,
        tolerance: None,
        corner_angle: None,
        prune_spurs: None,
        max_inscribed_circle: false,
    };
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
        // `--flag=value` and `--flag value` alike.
        let (flag, inline) = match arg.split_once('=') {
            Some((flag, value)) if flag.starts_with("--") => (flag, Some(value.to_string())),
            _ => (arg.as_str(), None),
        };
        let takes_value = matches!(flag, "--svg" | "--medial-axis" | "--tolerance" | "--corner-angle" | "--prune-spurs");
        let value = match inline {
            _ if !takes_value => {
                if inline.is_some() {
                    return Err(format!("{flag} takes no value"));
                }
                String::new()
            }
            Some(value) => value,
            None => args.next().unwrap_or_default(),
        };
        if takes_value && value.is_empty() {
            return Err(format!(
                "{flag} needs {}",
                if flag == "--svg" || flag == "--medial-axis" { "a file name" } else { "a number" }
            ));
        }
        match flag {
            "--" => only_positional = true,
            "-h" | "--help" => return Ok(Command::Help),
            "-V" | "--version" => return Ok(Command::Version),
            "--topology" => options.topology = true,
            "--voronoi-pairs" => {
                options.topology = true;
                options.voronoi_pairs = true;
            }
            "--stats" => options.stats = true,
            "--max-inscribed-circle" => options.max_inscribed_circle = true,
            "--svg" => options.svg = Some(PathBuf::from(value)),
            "--medial-axis" => options.medial_axis = Some((PathBuf::from(&value), axis_format(&value)?)),
            "--tolerance" => options.tolerance = Some(number(flag, &value, |t| t > 0.0, "a positive number")?),
            "--corner-angle" => {
                options.corner_angle = Some(number(flag, &value, |a| (0.0..=180.0).contains(&a), "an angle from 0 to 180")?)
            }
            "--prune-spurs" => options.prune_spurs = Some(number(flag, &value, |k| k >= 0.0, "a number not below 0")?),
            _ => return Err(format!("unknown option {arg:?}")),
        }
    }
    if (options.corner_angle.is_some() || options.prune_spurs.is_some()) && options.medial_axis.is_none() && options.svg.is_none()
    {
        return Err("--corner-angle and --prune-spurs filter the medial axis of --medial-axis or --svg; give one of them".into());
    }
    options.source = match input.as_deref() {
        None => Source::Demo,
        Some("-") => Source::Stdin,
        Some(path) => Source::File(PathBuf::from(path)),
    };
    Ok(Command::Run(options))
}

/// The format of `--medial-axis`, by the file name's extension.
fn axis_format(path: &str) -> Result<AxisFormat, String> {
    let extension = std::path::Path::new(path).extension().map(|e| e.to_ascii_lowercase());
    match extension.as_ref().and_then(|e| e.to_str()) {
        Some("wkt") => Ok(AxisFormat::Wkt),
        Some("json") => Ok(AxisFormat::Json),
        _ => Err(format!("--medial-axis writes .wkt or .json, not {path:?}")),
    }
}

/// A finite number for `flag` that `ok` accepts; `what` says which.
fn number(flag: &str, text: &str, ok: impl Fn(f64) -> bool, what: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() && ok(v) => Ok(v),
        _ => Err(format!("{flag} needs {what}, not {text:?}")),
    }
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
        assert!(o.medial_axis.is_none() && o.tolerance.is_none() && !o.max_inscribed_circle);
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
        assert!(run(&["--stats=1"]).unwrap_err().contains("takes no value"));
        assert!(run(&["--medial-axis", "axis.svg"]).unwrap_err().contains(".wkt or .json"));
        assert!(run(&["--medial-axis"]).unwrap_err().contains("a file name"));
        assert!(run(&["--tolerance", "0"]).unwrap_err().contains("positive"));
        assert!(run(&["--tolerance=inf"]).unwrap_err().contains("positive"));
        assert!(run(&["--tolerance"]).unwrap_err().contains("a number"));
        assert!(run(&["--corner-angle", "181", "--svg", "a.svg"]).unwrap_err().contains("0 to 180"));
        assert!(run(&["--prune-spurs", "-1", "--svg", "a.svg"]).unwrap_err().contains("--prune-spurs"));
        assert!(run(&["--prune-spurs", "1"]).unwrap_err().contains("give one of them"));
    }

    #[test]
    fn medial_axis_options() {
        let o = run(&["g.wkt", "--medial-axis", "a.WKT", "--tolerance=0.01", "--max-inscribed-circle"]).unwrap();
        assert_eq!(o.medial_axis, Some((PathBuf::from("a.WKT"), AxisFormat::Wkt)));
        assert_eq!(o.tolerance, Some(0.01));
        assert!(o.max_inscribed_circle);
        let o = run(&["--medial-axis=a.json", "--corner-angle", "45", "--prune-spurs=1.5"]).unwrap();
        assert_eq!(o.medial_axis, Some((PathBuf::from("a.json"), AxisFormat::Json)));
        assert_eq!((o.corner_angle, o.prune_spurs), (Some(45.0), Some(1.5)));
    }

    #[test]
    fn help_and_version_stop() {
        assert_eq!(parse(["--stats".to_string(), "-h".to_string()]).unwrap(), Command::Help);
        assert_eq!(parse(["--version".to_string()]).unwrap(), Command::Version);
    }
}
