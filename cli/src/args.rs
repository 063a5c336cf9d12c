//! Command-line arguments, declared with clap's derive: the flags, their
//! help and the value checks live on the fields of `Cli`; `parse` adds the
//! rules that span several flags and turns the result into `Options`.

use std::path::{Path, PathBuf};

use clap::{Parser, ValueEnum};

use crate::progress::When;

/// What the long help says about the input, after the one-line summary.
const INPUT_HELP: &str = "\
Builds the Voronoi diagram of the points, line segments and circular arcs
in INPUT.

INPUT is read by its extension, else by its first characters:
  .wkt, or text starting with a WKT keyword (POINT, MULTIPOINT, LINESTRING,
    MULTILINESTRING, POLYGON, MULTIPOLYGON, GEOMETRYCOLLECTION, any case,
    EMPTY allowed, Z/M/ZM ordinates ignored), any number of geometries one
    after the other; EWKT too: a leading `SRID=4326;` is accepted and
    reported with --stats (coordinates are used as they are); curves as
    PostGIS writes them: CIRCULARSTRING (start, a point on the arc, end;
    two more points per further arc; three points on a line are a segment,
    start = end a full circle), COMPOUNDCURVE, CURVEPOLYGON, MULTICURVE,
    MULTISURFACE: circular arcs are sites of the diagram; a CURVEPOLYGON
    (alone or in a MULTISURFACE) bounds the domain like a polygon, its
    arcs and all; open curves are obstacles;
  .geojson/.json, or text starting with `{`: a GeoJSON geometry, Feature
    or FeatureCollection (every polygon and multipolygon becomes rings of
    the domain, lines polylines, points points; properties are ignored);
  .dxf, or text starting with `0` and `SECTION` (ASCII or binary DXF,
    R12 to 2018, model space): LINE (a segment), POINT, ARC and CIRCLE
    (arcs; a circle is two half circles), LWPOLYLINE and POLYLINE with
    bulges, INSERT of blocks (location, scales, rotation, arrays; unequal
    x and y scales of arcs are refused). Z is ignored; entities drawn with
    the extrusion direction (0, 0, -1) are mirrored in x as DXF's object
    coordinates say; other directions are refused. Endpoints within 1e-9
    of the drawing's extent of one met before are moved onto it, so that
    chains whose rounded ends do not quite meet stay closed; an arc with
    an entity's end as near its inside is cut there (a LINE ending on a
    CIRCLE: the two then meet exactly; a note on standard error counts
    the cuts). Closed
    polylines (with or without bulges), CIRCLEs, and LINEs and ARCs that
    close up are polygon rings (the domain, even-odd); open polylines and
    the other LINEs and ARCs are obstacles; other entities (text,
    dimensions, splines, ...) are left out, with a note on standard error.
    Messages name the entity, e.g. `entity 12 (LWPOLYLINE, layer
    \"PART\")`, counted from 0 in file order (a POLYLINE with its VERTEXes
    one entity), and the block entity within an INSERT;
  otherwise Boost.Polygon's voronoi text format: a count P, then P lines
    `x y`, then a count S and S lines `x1 y1 x2 y2` (line segments; a
    missing S means 0), tokens separated by any whitespace.
`-` reads standard input. Without INPUT a built-in demo (a jittered ring, a
cluster, collinear points, a grid of cocircular points, a repeated point,
short segments and a polyline) is used.

Segments may share endpoints but must not cross or overlap (unless
--split-crossings); a point or an endpoint inside a segment cuts it there,
exactly (--stats: split_at_vertices). Each polygon's rings bound the domain
(even-odd: a ring inside a ring is a hole; orientation does not matter);
linestrings and points are obstacles. Rings may touch at points and share
stretches (the two copies cancel by the even-odd rule, --stats:
cancelled_ring_pieces), but must not cross themselves or each other (the
message names the polygons and rings).";

/// Examples and exit status, after the options in the long help.
const AFTER_HELP: &str = "\
Examples: segvoronoi glyph.wkt --medial-axis axis.wkt --svg axis.svg
          segvoronoi glyph.wkt --offset -0.1 --offset 0.2 --offsets o.wkt
          segvoronoi countries.geojson --medial-axis axis.geojson --svg map.svg
          segvoronoi plate.dxf --offset -3 --offset -6 --offsets pocket.nc --feed 800
          segvoronoi plate.dxf --offset 1 --offsets outline.dxf --medial-axis axis.dxf
          segvoronoi part.wkt --offset 0.5 --offsets curved.wkt --curves
          segvoronoi slot.dxf --max-inscribed-circle --medial-axis axis.json

Exit status: 0 on success, 1 when the library rejects the input (a
non-finite coordinate, segments that cross or overlap, a point inside a
segment, rings that cross: the message names the input indices, their lines
in a Boost.Polygon text input, their coordinates, polygons and rings) or an
offset distance, or an output cannot be written, 2 for usage errors and
unreadable or malformed input (the message names the line and quotes the
offending text).";

#[derive(Parser, Debug)]
#[command(name = "segvoronoi", version = segvoronoi::VERSION, about = "Builds the Voronoi diagram, medial axis and offsets of points, segments, arcs and polygons.", long_about = INPUT_HELP, after_long_help = AFTER_HELP, allow_negative_numbers = true)]
struct Cli {
    /// The input file (WKT, EWKT, GeoJSON, DXF or Boost.Polygon text), `-` for standard input; none: the built-in demo
    input: Option<String>,

    /// Draw a picture: the domain filled, the medial axis coloured by clearance, the largest inscribed circle, each offset distance in its own colour, with a title, legend and scale bar; without polygons the diagram
    #[arg(long, value_name = "OUT.svg", value_parser = file_name)]
    svg: Option<PathBuf>,

    /// Draw the Voronoi diagram in the --svg picture also when the input has polygons (edges, parabolic arcs as exact quadratic Bézier curves, vertices, sites)
    #[arg(long)]
    svg_diagram: bool,

    /// The name of the input's unit for the --svg scale bar (e.g. km, m, deg; default: "units", or "deg" for EWKT with SRID 4326)
    #[arg(long, value_name = "NAME")]
    units: Option<String>,

    /// Print the canonical topology text on standard output
    #[arg(long)]
    topology: bool,

    /// Add the VPAIRS and VVERTICES sections (implies --topology)
    #[arg(long)]
    voronoi_pairs: bool,

    /// Cut every degenerate vertex (four or more sites on one circle) one way in EDGES and FACES, the same whatever the input's order or the thread count (implies --topology)
    #[arg(long)]
    canonical_cuts: bool,

    /// Print key=value statistics on standard error
    #[arg(long)]
    stats: bool,

    /// Write the whole diagram as JSON, for any input (points, segments, arcs): its sites (id, name, kind point, segment or arc, coordinates, input index; an arc's centre, radius, bulge and direction), its vertices (id, position, clearance, the three sites) and its edges (id, kind line, parabola or conic, the two sites, both ends: a vertex id or a direction to infinity)
    #[arg(long, value_name = "OUT.json", value_parser = file_name)]
    diagram: Option<PathBuf>,

    /// Write the medial axis (the Voronoi edges inside the domain that are not separators; without polygons every such edge). OUT.wkt: one MULTILINESTRING Z, a linestring per chain sampled within the tolerance, z the clearance at each point; the pieces of a chain that reach infinity (only without polygons) are cut off. OUT.geojson: a Feature with a MultiLineString of the same samples and z the clearance, and the property `clearance` (one array per line). OUT.json: the exact chains, each with `closed` and its pieces: Voronoi edge id, kind (line, parabola, or conic beside a circular arc), both ends (a vertex id and point, or a direction to infinity), the clearance at both ends (null at infinity), for a parabola its focus and directrix, for a conic its two sites and the rational quadratic Bézier curve it is. OUT.dxf: a DXF drawing (R2000) on the layer MEDIAL_AXIS, each straight piece a LINE, each curved one an open LWPOLYLINE sampled within the tolerance
    #[arg(long, value_name = "OUT", value_parser = file_name)]
    medial_axis: Option<PathBuf>,

    /// The format of --medial-axis and --offsets, whatever their extension (default: by extension, .wkt, .geojson, .json, .dxf, or .nc/.ngc/.gcode/.tap for G-code)
    #[arg(long, value_enum)]
    format: Option<Format>,

    /// Chord tolerance of every sampled output, in input units (default 1e-4 times the input's bounding-box diagonal)
    #[arg(long, value_name = "T", value_parser = positive)]
    tolerance: Option<f64>,

    /// Leave out the branches of the medial axis that run into a convex corner of interior angle above DEG degrees (0 to 180; 180, the default, leaves out none): the spurs of curves flattened into chords
    #[arg(long, value_name = "DEG", value_parser = angle)]
    corner_angle: Option<f64>,

    /// Leave out the branches from a leaf to a junction that are shorter than K times the clearance at the junction (K >= 0; 0, the default, leaves out none; useful factors are above 1). Both filters look at the unfiltered axis once and keep a part of the axis whole that they would remove entirely; they apply to --medial-axis and --svg
    #[arg(long, value_name = "K", value_parser = not_negative)]
    prune_spurs: Option<f64>,

    /// Print the largest disk inside the domain, `x y r`, on standard output (exit status 1 without polygons)
    #[arg(long)]
    max_inscribed_circle: bool,

    /// An offset distance, for --offsets (and drawn by --svg); repeat it for more, kept in the order given. With polygons D < 0 shrinks the domain and D > 0 grows it, as GEOS's buffer; without polygons only D > 0 (the points at most D from any site). D = 0, NaN or infinite: exit status 1
    // `allow_hyphen_values`: `-inf` too, which clap's negative-number
    // rule does not take for a number.
    #[arg(long, value_name = "D", value_parser = any_number, allow_hyphen_values = true)]
    offset: Vec<f64>,

    /// Write the offsets at each --offset D (both options or neither). OUT.wkt: one line per D, the region as one MULTIPOLYGON (EMPTY when there is none), rings sampled within the tolerance and closed. OUT.geojson: a FeatureCollection, per D a Feature with a MultiPolygon and the properties `distance` and `area`. OUT.json: the exact loops, per D its area and loops, each with its parent, whether it bounds a hole, its signed area and its pieces (line or arc, site id, ends, an arc's centre, radius and direction). OUT.dxf: a DXF drawing (R2000), a layer per D (`OFFSET_0.5`), each loop a closed LWPOLYLINE with its arcs as bulges, a whole circle a CIRCLE. OUT.nc (.ngc, .gcode, .tap): G-code to mill along the loops (see --feed)
    #[arg(long, value_name = "OUT", value_parser = file_name)]
    offsets: Option<PathBuf>,

    /// With --offsets OUT.wkt (and --input-wkt): the exact arcs instead of chords, per D one MULTISURFACE of CURVEPOLYGONs (outer ring, then its holes) whose rings are COMPOUNDCURVEs of linestrings and CIRCULARSTRINGs (start, the middle of the arc, end; a whole circle as two half circles), as PostGIS writes curves; `MULTISURFACE EMPTY` for an empty region
    #[arg(long)]
    curves: bool,

    /// G-code (--offsets OUT.nc): the cutting feed rate, in mm per minute, of the G1/G2/G3 moves along the loops (default 600)
    #[arg(long, value_name = "F", value_parser = positive)]
    feed: Option<f64>,

    /// G-code: the feed rate of the plunge (G1 Z) to --plunge-depth, in mm per minute (default 100)
    #[arg(long, value_name = "F", value_parser = positive)]
    plunge_feed: Option<f64>,

    /// G-code: the depth Z of the cut (default -1)
    #[arg(long, value_name = "Z", value_parser = finite, allow_hyphen_values = true)]
    plunge_depth: Option<f64>,

    /// G-code: the safe height Z of the rapid moves (G0) between loops (default 5; above --plunge-depth)
    #[arg(long, value_name = "Z", value_parser = finite, allow_hyphen_values = true)]
    safe_z: Option<f64>,

    /// G-code: round X, Y, I and J to N decimals (for a controller that takes no more); by default every number is written in full (shortest round-trip form), which reads back exactly
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u8).range(0..=17))]
    gcode_digits: Option<u8>,

    /// Split the input where it crosses itself instead of refusing it: crossings, overlaps, T-junctions and points inside segments become shared endpoints, by snap rounding to pixels 2^-46 of the largest coordinate wide (--stats reports the crossings, pieces and the largest displacement)
    #[arg(long)]
    split_crossings: bool,

    /// At most N threads at once in the build, this one included (default: as many as the machine has cores; 1 starts none). Builds of 60,000 sites or more run in two halves at once (with 4 or more, each half in halves in turn). The diagram is the same for every N (vertices may be numbered, and degenerate ones cut, otherwise: compare with --canonical-cuts)
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    threads: Option<u32>,

    /// Write the input as read, in WKT (after a DXF's ends are snapped, its chains joined into rings and its arcs cut where entities end on them): one GEOMETRYCOLLECTION, each ring a POLYGON of its own (the domain is the even-odd region of all rings), each open chain or linestring a LINESTRING, each point a POINT; arcs as chords within the tolerance, or with --curves as CIRCULARSTRINGs in CURVEPOLYGONs and COMPOUNDCURVEs, as PostGIS writes curves
    #[arg(long, value_name = "OUT.wkt", value_parser = file_name)]
    input_wkt: Option<PathBuf>,

    /// Write the points and segments actually built (the pieces, where segments were cut) in Boost.Polygon's text format, each coordinate exactly
    #[arg(long, value_name = "OUT", value_parser = file_name)]
    write_sites: Option<PathBuf>,

    /// Show the phases (reading, building, medial axis, offsets, writing) and the time on standard error; by default shown only on a terminal for an input file of 4 MiB or more
    #[arg(long, conflicts_with = "quiet")]
    progress: bool,

    /// Never show the phases on standard error (errors and --stats still go there)
    #[arg(long, short = 'q')]
    quiet: bool,
}

/// The format of `--medial-axis` and `--offsets`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Sampled within the tolerance: one `MULTILINESTRING Z` for the
    /// axis, one `MULTIPOLYGON` per distance for offsets.
    Wkt,
    /// The same samples as GeoJSON, with the clearance or the distance as
    /// properties.
    #[value(name = "geojson")]
    GeoJson,
    /// The exact pieces.
    Json,
    /// A DXF drawing.
    Dxf,
    /// G-code (offsets only).
    #[value(name = "gcode")]
    Gcode,
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
    /// `--svg-diagram`: the Voronoi diagram in the picture of a domain too.
    pub svg_diagram: bool,
    /// `--units`: the scale bar's unit.
    pub units: Option<String>,
    pub topology: bool,
    pub voronoi_pairs: bool,
    /// `--canonical-cuts`.
    pub canonical_cuts: bool,
    pub stats: bool,
    /// `--diagram`: where to write the diagram as JSON.
    pub diagram: Option<PathBuf>,
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
    /// `--curves`: WKT offsets and `--input-wkt` with arcs (given only with
    /// one of them).
    pub curves: bool,
    /// The G-code settings (defaults when not asked for).
    pub gcode: crate::gcode::Settings,
    /// `--split-crossings`.
    pub split_crossings: bool,
    /// `--threads`: most threads a build runs at once; 0 for the cores.
    pub threads: usize,
    /// `--write-sites`: where to write the input as built.
    pub write_sites: Option<PathBuf>,
    /// `--input-wkt`: where to write the input as read.
    pub input_wkt: Option<PathBuf>,
    /// `--progress`, `--quiet` or neither.
    pub progress: When,
}

/// Why the arguments do not make a run: clap's own outcome (help, version
/// or its error, which it prints and exits with), or a rule that spans
/// several flags, as a message for the user.
#[derive(Debug)]
pub enum Stop {
    Clap(clap::Error),
    Usage(String),
}

/// Parses the arguments after the program name.
pub fn parse<I: IntoIterator<Item = String>>(args: I) -> Result<Options, Stop> {
    let cli = Cli::try_parse_from(std::iter::once("segvoronoi".to_string()).chain(args)).map_err(Stop::Clap)?;
    let usage = |m: &str| Err(Stop::Usage(m.to_string()));
    if (cli.corner_angle.is_some() || cli.prune_spurs.is_some()) && cli.medial_axis.is_none() && cli.svg.is_none() {
        return usage("--corner-angle and --prune-spurs filter the medial axis of --medial-axis or --svg; give one of them");
    }
    match (cli.offset.is_empty(), cli.offsets.is_some()) {
        (true, true) => return usage("--offsets needs at least one --offset D (the distances to write)"),
        (false, false) => {
            return usage(
                "--offset D needs --offsets OUT.wkt, OUT.geojson, OUT.json, OUT.dxf or OUT.nc (where to write the offsets)",
            )
        }
        _ => {}
    }
    let with_format = |flag: &str, path: Option<PathBuf>| -> Result<Option<(PathBuf, Format)>, Stop> {
        match path {
            None => Ok(None),
            Some(path) => {
                let format = cli.format.or_else(|| by_extension(&path)).ok_or_else(|| {
                    Stop::Usage(format!(
                        "{flag} writes .wkt, .geojson, .json, .dxf or .nc (or give --format), not {:?}",
                        path.display().to_string()
                    ))
                })?;
                Ok(Some((path, format)))
            }
        }
    };
    let medial_axis = with_format("--medial-axis", cli.medial_axis.clone())?;
    let offsets = with_format("--offsets", cli.offsets.clone())?;
    if matches!(medial_axis, Some((_, Format::Gcode))) {
        return usage("--medial-axis writes .wkt, .geojson, .json or .dxf: G-code is for --offsets");
    }
    if cli.curves && !matches!(offsets, Some((_, Format::Wkt))) && cli.input_wkt.is_none() {
        return usage(
            "--curves writes the arcs of --offsets OUT.wkt and --input-wkt; give --offsets with a .wkt file (or --format wkt) \
             or --input-wkt",
        );
    }
    let gcode_asked = cli.feed.is_some()
        || cli.plunge_feed.is_some()
        || cli.plunge_depth.is_some()
        || cli.safe_z.is_some()
        || cli.gcode_digits.is_some();
    if gcode_asked && !matches!(offsets, Some((_, Format::Gcode))) {
        return usage("--feed, --plunge-feed, --plunge-depth, --safe-z and --gcode-digits set the G-code of --offsets OUT.nc");
    }
    let defaults = crate::gcode::Settings::default();
    let gcode = crate::gcode::Settings {
        feed: cli.feed.unwrap_or(defaults.feed),
        plunge_feed: cli.plunge_feed.unwrap_or(defaults.plunge_feed),
        plunge_depth: cli.plunge_depth.unwrap_or(defaults.plunge_depth),
        safe_z: cli.safe_z.unwrap_or(defaults.safe_z),
        digits: cli.gcode_digits.map(usize::from),
    };
    if gcode.safe_z <= gcode.plunge_depth {
        return usage("--safe-z must be above --plunge-depth");
    }
    Ok(Options {
        source: match cli.input.as_deref() {
            None => Source::Demo,
            Some("-") => Source::Stdin,
            Some(path) => Source::File(PathBuf::from(path)),
        },
        svg: cli.svg,
        svg_diagram: cli.svg_diagram,
        units: cli.units,
        topology: cli.topology || cli.voronoi_pairs || cli.canonical_cuts,
        voronoi_pairs: cli.voronoi_pairs,
        canonical_cuts: cli.canonical_cuts,
        stats: cli.stats,
        diagram: cli.diagram,
        medial_axis,
        tolerance: cli.tolerance,
        corner_angle: cli.corner_angle,
        prune_spurs: cli.prune_spurs,
        max_inscribed_circle: cli.max_inscribed_circle,
        offset_distances: cli.offset,
        offsets,
        curves: cli.curves,
        gcode,
        split_crossings: cli.split_crossings,
        threads: cli.threads.map_or(0, |n| n as usize),
        write_sites: cli.write_sites,
        input_wkt: cli.input_wkt,
        progress: match (cli.progress, cli.quiet) {
            (true, _) => When::Always,
            (_, true) => When::Never,
            _ => When::Auto,
        },
    })
}

/// The output format a file name asks for.
fn by_extension(path: &Path) -> Option<Format> {
    let extension = path.extension()?.to_str()?.to_ascii_lowercase();
    match extension.as_str() {
        "wkt" => Some(Format::Wkt),
        "geojson" => Some(Format::GeoJson),
        "json" => Some(Format::Json),
        "dxf" => Some(Format::Dxf),
        "nc" | "ngc" | "gcode" | "tap" => Some(Format::Gcode),
        _ => None,
    }
}

/// A file name: not empty (`--svg=` is a mistake, not the current folder).
fn file_name(text: &str) -> Result<PathBuf, String> {
    if text.is_empty() {
        return Err("needs a file name".into());
    }
    Ok(PathBuf::from(text))
}

/// Any number, NaN and infinities too: the library says which offset
/// distances it takes, and why not.
fn any_number(text: &str) -> Result<f64, String> {
    text.parse().map_err(|_| format!("needs a number, not {text:?}"))
}

/// A finite number that `ok` accepts; `what` says which.
fn number(text: &str, ok: impl Fn(f64) -> bool, what: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() && ok(v) => Ok(v),
        _ => Err(format!("needs {what}, not {text:?}")),
    }
}

fn positive(text: &str) -> Result<f64, String> {
    number(text, |t| t > 0.0, "a positive number")
}

fn finite(text: &str) -> Result<f64, String> {
    number(text, |_| true, "a finite number")
}

fn angle(text: &str) -> Result<f64, String> {
    number(text, |a| (0.0..=180.0).contains(&a), "an angle from 0 to 180")
}

fn not_negative(text: &str) -> Result<f64, String> {
    number(text, |k| k >= 0.0, "a number not below 0")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(args: &[&str]) -> Result<Options, String> {
        parse(args.iter().map(|s| s.to_string())).map_err(|stop| match stop {
            Stop::Clap(e) => e.to_string(),
            Stop::Usage(m) => m,
        })
    }

    #[test]
    fn clap_checks_its_declaration() {
        use clap::CommandFactory;
        Cli::command().debug_assert();
    }

    #[test]
    fn no_arguments_is_the_demo_with_no_output() {
        let o = run(&[]).unwrap();
        assert_eq!(o.source, Source::Demo);
        assert!(o.svg.is_none() && !o.topology && !o.voronoi_pairs && !o.stats && !o.svg_diagram);
        assert!(o.medial_axis.is_none() && o.tolerance.is_none() && !o.max_inscribed_circle);
    }

    #[test]
    fn flags_in_any_order() {
        let o = run(&["--stats", "in.txt", "--svg", "out.svg", "--topology", "--diagram", "d.json"]).unwrap();
        assert_eq!(o.diagram, Some(PathBuf::from("d.json")));
        assert_eq!(o.source, Source::File("in.txt".into()));
        assert_eq!(o.svg, Some(PathBuf::from("out.svg")));
        assert!(o.topology && o.stats && !o.voronoi_pairs);
        assert_eq!(run(&["--svg=a.svg", "--svg-diagram"]).unwrap().svg, Some(PathBuf::from("a.svg")));
        assert!(run(&["--svg=a.svg", "--svg-diagram"]).unwrap().svg_diagram);
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
        assert!(run(&["--svg="]).unwrap_err().contains("needs a file name"));
        assert!(run(&["--frobnicate"]).unwrap_err().contains("--frobnicate"));
        assert!(run(&["a", "b"]).unwrap_err().contains("'b'"));
        assert!(run(&["--stats=1"]).unwrap_err().contains("--stats"));
        assert!(run(&["--medial-axis", "axis.svg"]).unwrap_err().contains(".wkt, .geojson, .json, .dxf or .nc"));
        assert!(run(&["--medial-axis"]).unwrap_err().contains("--medial-axis"));
        assert!(run(&["--tolerance", "0"]).unwrap_err().contains("positive"));
        assert!(run(&["--tolerance=inf"]).unwrap_err().contains("positive"));
        assert!(run(&["--corner-angle", "181", "--svg", "a.svg"]).unwrap_err().contains("0 to 180"));
        assert!(run(&["--prune-spurs", "-1", "--svg", "a.svg"]).unwrap_err().contains("not below 0"));
        assert!(run(&["--prune-spurs", "1"]).unwrap_err().contains("give one of them"));
        assert!(run(&["--format", "svg", "--medial-axis", "a.txt"]).unwrap_err().contains("--format"));
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
        let o = run(&["--medial-axis=a.GeoJSON"]).unwrap();
        assert_eq!(o.medial_axis, Some((PathBuf::from("a.GeoJSON"), Format::GeoJson)));
        // --format wins over the extension, and names one without it.
        let o = run(&["--medial-axis=a.json", "--format", "geojson"]).unwrap();
        assert_eq!(o.medial_axis, Some((PathBuf::from("a.json"), Format::GeoJson)));
        let o = run(&["--medial-axis=axis", "--format=wkt"]).unwrap();
        assert_eq!(o.medial_axis, Some((PathBuf::from("axis"), Format::Wkt)));
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
        assert!(run(&["--offsets", "o.svg", "--offset", "1"])
            .unwrap_err()
            .contains("--offsets writes .wkt, .geojson, .json, .dxf or .nc"));
        assert!(run(&["--offset", "one", "--offsets", "o.wkt"]).unwrap_err().contains("needs a number, not \"one\""));
        assert!(run(&["--offset"]).unwrap_err().contains("--offset"));
        assert!(run(&["--offset", "1", "--offsets"]).unwrap_err().contains("--offsets"));
    }

    #[test]
    fn dxf_gcode_and_curves() {
        let o = run(&["p.dxf", "--offset", "-1", "--offsets", "o.DXF", "--medial-axis", "a.dxf"]).unwrap();
        assert_eq!(o.offsets, Some((PathBuf::from("o.DXF"), Format::Dxf)));
        assert_eq!(o.medial_axis, Some((PathBuf::from("a.dxf"), Format::Dxf)));
        let o = run(&["--offset", "-1", "--offsets", "o.nc", "--feed", "800", "--plunge-depth", "-2.5", "--gcode-digits", "4"])
            .unwrap();
        assert_eq!(o.offsets, Some((PathBuf::from("o.nc"), Format::Gcode)));
        assert_eq!((o.gcode.feed, o.gcode.plunge_depth, o.gcode.digits), (800.0, -2.5, Some(4)));
        assert_eq!(o.gcode.plunge_feed, crate::gcode::Settings::default().plunge_feed);
        let o = run(&["--offset", "1", "--offsets", "o.wkt", "--curves"]).unwrap();
        assert!(o.curves);
        assert!(run(&["--curves"]).unwrap_err().contains("--curves writes the arcs"));
        assert!(run(&["--offset", "1", "--offsets", "o.json", "--curves"]).unwrap_err().contains("--curves"));
        assert!(run(&["--feed", "100"]).unwrap_err().contains("G-code of --offsets OUT.nc"));
        assert!(run(&["--medial-axis", "a.gcode"]).unwrap_err().contains("G-code is for --offsets"));
        assert!(run(&["--offset", "1", "--offsets", "o.nc", "--safe-z", "-3"]).unwrap_err().contains("--safe-z"));
        assert!(run(&["--offset", "1", "--offsets", "o.nc", "--feed", "0"]).unwrap_err().contains("positive"));
    }

    #[test]
    fn help_and_version_stop() {
        let stop = parse(["--stats".to_string(), "-h".to_string()]).unwrap_err();
        assert!(matches!(stop, Stop::Clap(e) if e.kind() == clap::error::ErrorKind::DisplayHelp));
        let stop = parse(["--version".to_string()]).unwrap_err();
        assert!(matches!(stop, Stop::Clap(e) if e.kind() == clap::error::ErrorKind::DisplayVersion));
    }
}
