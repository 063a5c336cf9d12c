//! Command-line arguments, parsed by hand: the program has a dozen flags,
//! which does not justify a dependency.

use std::path::PathBuf;

/// The usage text printed by `--help`.
pub const USAGE: &str = "\
Usage: segvoronoi [INPUT] [--svg OUT.svg] [--topology] [--voronoi-pairs] [--stats]
                  [--medial-axis OUT.wkt|OUT.json] [--tolerance T]
                  [--corner-angle DEG] [--prune-spurs K] [--max-inscribed-circle]
                  [--offset D]... [--offsets OUT.wkt|OUT.json]
                  [--split-crossings] [--write-sites OUT.txt]

Builds the Voronoi diagram of the points and line segments in INPUT.

INPUT is Boost.Polygon's voronoi text format: a count P, then P lines `x y`,
then a count S and S lines `x1 y1 x2 y2` (line segments; a missing S means
0). Tokens are separated by any whitespace. `-` reads standard input.
Segments may share endpoints but must not cross or overlap (unless
--split-crossings); a point or an endpoint inside a segment cuts it there,
exactly (--stats: split_at_vertices). Without INPUT a built-in demo (a jittered ring, a cluster, collinear
points, a grid of cocircular points, a repeated point, short segments and a
polyline) is used.

INPUT is read as WKT instead when its name ends in `.wkt` or its text
starts with a WKT keyword: POINT, MULTIPOINT, LINESTRING, MULTILINESTRING,
POLYGON, MULTIPOLYGON, GEOMETRYCOLLECTION, in any case, EMPTY allowed, an
optional Z, M or ZM dimension (the extra ordinates are ignored), any number
of geometries one after the other. Each polygon's rings bound the domain
(even-odd: a ring inside a ring is a hole; orientation does not matter);
linestrings and points are obstacles. Rings may touch at points (a hole
touching its shell, polygons touching at corners: valid OGC input builds as
it is) and share stretches (polygons along a common border, a spike out and
back: the two copies cancel by the even-odd rule, --stats:
cancelled_ring_pieces), but must not cross themselves or each other (the
message names the polygons and rings).

Options:
  --svg OUT.svg      draw the diagram: edges (parabolic arcs as exact
                     quadratic Bezier curves), vertices (small dots), sites
                     (dots; segments as thick lines). With polygons also the
                     domain (lightly shaded, even-odd), the medial axis
                     (thick, coloured by clearance from teal at 0 to
                     magenta at the largest clearance, linear in RGB) and
                     the largest inscribed circle (dashed); with --offset
                     also the offset loops (exact lines and circular arcs)
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
  --offset D         an offset distance, for --offsets (and drawn by
                     --svg); repeat it for more, kept in the order given.
                     With polygons D < 0 shrinks the domain (the points
                     inside at least -D from its boundary) and D > 0 grows
                     it (the points at most D from it), as GEOS's buffer;
                     without polygons only D > 0 (the points at most D
                     from any site). Points and linestrings count as sites
                     either way. D = 0, NaN or infinite: exit status 1
  --offsets OUT      write the offsets at each --offset D (both options or
                     neither). OUT.wkt: one line per D, in order, the region
                     as one MULTIPOLYGON (EMPTY when there is none), each
                     polygon an outer ring and its holes sampled within the
                     tolerance, rings closed. OUT.json: the exact loops, per
                     D its area and loops, each with its parent (the loop it
                     lies directly inside, an index, or null), whether it
                     bounds a hole, its signed area (counter-clockwise
                     positive) and its pieces: kind (line or arc), site id,
                     from and to, for an arc its centre, radius and
                     direction (counter_clockwise; a whole circle has
                     from = to)
  --split-crossings  split the input where it crosses itself instead of
                     refusing it: crossings, overlaps, T-junctions and
                     points inside segments become shared endpoints, by
                     snap rounding to pixels 2^-46 of the largest
                     coordinate wide (segments that meet nothing keep their
                     coordinates; --stats reports the crossings, pieces and
                     the largest displacement). Polygons bound the even-odd
                     region of their split rings
  --write-sites OUT  write the points and segments actually built (the
                     pieces, where segments were cut) in Boost.Polygon's text
                     format, each coordinate exactly
  -h, --help         print this help
  -V, --version      print the version

Examples: segvoronoi glyph.wkt --medial-axis axis.wkt --svg axis.svg
          segvoronoi glyph.wkt --offset -0.1 --offset 0.2 --offsets o.wkt

Exit status: 0 on success, 1 when the library rejects the input (a
non-finite coordinate, segments that cross or overlap, a point inside a
segment, rings that cross: the message names the input indices, their
lines in a Boost.Polygon text input, their coordinates, polygons and rings) or an offset distance, or an output cannot be written, 2 for
usage errors and unreadable or malformed input (for WKT the message names
the line and column).
";

/// The format of `--medial-axis` and `--offsets`, from the file name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Sampled within the tolerance: one `MULTILINESTRING Z` for the
    /// axis, one `MULTIPOLYGON` per distance for offsets.
    Wkt,
    /// The exact pieces.
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
    pub medial_axis: Option<(PathBuf, Format)>,
    /// `--tolerance`: positive and finite.
    pub tolerance: Option<f64>,
    /// `--corner-angle`, in degrees.
    pub corner_angle: Option<f64>,
    /// `--prune-spurs`.
    pub prune_spurs: Option<f64>,
    pub max_inscribed_circle: bool,
    /// `--offset`, in the order given; checked by the library, not here.
    pub offset_distances: Vec<f64>,
    /// `--offsets`: where and in which format. Given exactly when
    /// `offset_distances` is not empty.
    pub offsets: Option<(PathBuf, Format)>,
    /// `--split-crossings`.
    pub split_crossings: bool,
    /// `--write-sites`: where to write the input as built.
    pub write_sites: Option<PathBuf>,
}

/// The outcome of parsing: run, or answer `--help` / `--version` and stop.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    Run(Box<Options>),
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
        offset_distances: Vec::new(),
        offsets: None,
        split_crossings: false,
        write_sites: None,
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
        let takes_value = matches!(
            flag,
            "--svg"
                | "--medial-axis"
                | "--tolerance"
                | "--corner-angle"
                | "--prune-spurs"
                | "--offset"
                | "--offsets"
                | "--write-sites"
        );
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
                if matches!(flag, "--svg" | "--medial-axis" | "--offsets" | "--write-sites") {
                    "a file name"
                } else {
                    "a number"
                }
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
            "--split-crossings" => options.split_crossings = true,
            "--write-sites" => options.write_sites = Some(PathBuf::from(value)),
            "--max-inscribed-circle" => options.max_inscribed_circle = true,
            "--svg" => options.svg = Some(PathBuf::from(value)),
            "--medial-axis" => options.medial_axis = Some((PathBuf::from(&value), format(flag, &value)?)),
            "--offsets" => options.offsets = Some((PathBuf::from(&value), format(flag, &value)?)),
            // Any number, NaN and infinities too: the library says what
            // distances it takes, and why not.
            "--offset" => {
                options.offset_distances.push(value.parse().map_err(|_| format!("--offset needs a number, not {value:?}"))?)
            }
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
    match (options.offset_distances.is_empty(), options.offsets.is_some()) {
        (true, true) => return Err("--offsets needs at least one --offset D (the distances to write)".into()),
        (false, false) => return Err("--offset D needs --offsets OUT.wkt or OUT.json (where to write the offsets)".into()),
        _ => {}
    }
    options.source = match input.as_deref() {
        None => Source::Demo,
        Some("-") => Source::Stdin,
        Some(path) => Source::File(PathBuf::from(path)),
    };
    Ok(Command::Run(Box::new(options)))
}

/// The format of the output of `flag`, by the file name's extension.
fn format(flag: &str, path: &str) -> Result<Format, String> {
    let extension = std::path::Path::new(path).extension().map(|e| e.to_ascii_lowercase());
    match extension.as_ref().and_then(|e| e.to_str()) {
        Some("wkt") => Ok(Format::Wkt),
        Some("json") => Ok(Format::Json),
        _ => Err(format!("{flag} writes .wkt or .json, not {path:?}")),
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
            Command::Run(o) => Ok(*o),
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
        assert_eq!(o.medial_axis, Some((PathBuf::from("a.WKT"), Format::Wkt)));
        assert_eq!(o.tolerance, Some(0.01));
        assert!(o.max_inscribed_circle);
        let o = run(&["--medial-axis=a.json", "--corner-angle", "45", "--prune-spurs=1.5"]).unwrap();
        assert_eq!(o.medial_axis, Some((PathBuf::from("a.json"), Format::Json)));
        assert_eq!((o.corner_angle, o.prune_spurs), (Some(45.0), Some(1.5)));
    }

    #[test]
    fn offsets_keep_their_order() {
        let o = run(&["g.wkt", "--offset", "-0.5", "--offsets", "o.WKT", "--offset=2", "--offset", "1e-3"]).unwrap();
        assert_eq!(o.offset_distances, [-0.5, 2.0, 1e-3]);
        assert_eq!(o.offsets, Some((PathBuf::from("o.WKT"), Format::Wkt)));
        let o = run(&["--offsets=o.json", "--offset", "1", "--offset", "1"]).unwrap();
        assert_eq!((o.offset_distances, o.offsets), (vec![1.0, 1.0], Some((PathBuf::from("o.json"), Format::Json))));
        // the library judges the distances
        let o = run(&["--offset", "nan", "--offset", "0", "--offset", "-inf", "--offsets", "o.wkt"]).unwrap();
        assert!(o.offset_distances[0].is_nan() && o.offset_distances[1..] == [0.0, f64::NEG_INFINITY]);
        assert!(run(&[]).unwrap().offset_distances.is_empty() && run(&[]).unwrap().offsets.is_none());
    }

    #[test]
    fn offset_mistakes_are_reported() {
        assert!(run(&["--offset", "1"]).unwrap_err().contains("--offset D needs --offsets"));
        assert!(run(&["--offsets", "o.wkt"]).unwrap_err().contains("--offsets needs at least one --offset"));
        assert!(run(&["--offsets", "o.svg", "--offset", "1"]).unwrap_err().contains("--offsets writes .wkt or .json"));
        assert!(run(&["--offset", "one", "--offsets", "o.wkt"]).unwrap_err().contains("--offset needs a number, not \"one\""));
        assert!(run(&["--offset"]).unwrap_err().contains("--offset needs a number"));
        assert!(run(&["--offset", "1", "--offsets"]).unwrap_err().contains("--offsets needs a file name"));
    }

    #[test]
    fn help_and_version_stop() {
        assert_eq!(parse(["--stats".to_string(), "-h".to_string()]).unwrap(), Command::Help);
        assert_eq!(parse(["--version".to_string()]).unwrap(), Command::Version);
    }
}
