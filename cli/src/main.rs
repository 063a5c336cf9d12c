//! `segvoronoi`: builds the Voronoi diagram of the points and line segments
//! in a Boost.Polygon voronoi text file or of the polygons, linestrings,
//! points and curves (circular arcs) of a WKT, GeoJSON or DXF file (or of
//! a built-in demo) and writes an SVG picture, the whole diagram as JSON,
//! the canonical topology text, statistics, the medial axis, the largest
//! inscribed circle and offsets, also of domains bounded by arcs (WKT's
//! CURVEPOLYGON, DXF's closed polylines with bulges and circles); the axis
//! and offsets also as DXF, offsets as G-code and curved WKT.
//! `segvoronoi --help` for usage.

mod args;
mod demo;
mod diagram_output;
mod dxf;
mod gcode;
mod geojson_output;
mod input;
mod input_wkt;
mod json_values;
mod medial_output;
mod offset_arcs;
mod offset_output;
mod progress;
mod stats;
mod svg;
mod wkt;
mod wkt_curve_output;

use std::io::Write;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

use args::{Format, Options, Source, Stop};
use progress::Progress;
use segvoronoi::{Builder, Diagram, MedialAxis, MedialAxisFilter, TopologyOptions};

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
        Ok(options) => options,
        // Help and version on standard output with status 0, clap's own
        // usage errors (which name the flag and point to --help) with 2.
        Err(Stop::Clap(e)) => {
            let status = if e.use_stderr() { 2 } else { 0 };
            let text = if e.use_stderr() { e.to_string() } else { e.render().to_string() };
            if status == 0 {
                return print(&text);
            }
            return Err(bad_input(text.trim_start_matches("error: ").trim_end().to_string()));
        }
        Err(Stop::Usage(message)) => return Err(bad_input(format!("{message}\nTry 'segvoronoi --help'."))),
    };
    let input_bytes = match &options.source {
        Source::File(path) => std::fs::metadata(path).ok().map(|m| m.len()),
        _ => None,
    };
    let progress = Progress::new(options.progress, input_bytes);
    progress.phase(&match &options.source {
        Source::File(path) => format!("reading {}", path.display()),
        Source::Stdin => "reading standard input".to_string(),
        Source::Demo => "making the demo input".to_string(),
    });
    let (name, input) = input::read(&options.source)?;
    let arcs = input.has_arcs();
    if arcs && options.write_sites.is_some() {
        return Err(failed(format!(
            "{name}: --write-sites is not available when the input has circular arcs: Boost.Polygon's text has none \
             (--diagram writes every site, arcs too)"
        )));
    }

    // Library errors (a non-finite coordinate, crossing segments or rings,
    // a ring of fewer than three points) name the input indices: exit
    // status 1 with that message.
    let mut builder = Builder::new();
    let origins = input.add_to(&mut builder).map_err(|e| failed(format!("{name}: {e}")))?;
    builder.split_crossings(options.split_crossings).threads(options.threads);
    progress.phase(&format!(
        "building: the input check{}, then the diagram of {} points and {} segments{}",
        if options.split_crossings { " and the split" } else { "" },
        builder.point_count(),
        builder.segment_count(),
        if arcs { format!(" and {} arcs", builder.arc_count()) } else { String::new() }
    ));
    // Only the construction is timed: not reading, not writing.
    let start = Instant::now();
    let diagram = builder.build().map_err(|e| failed(format!("{name}: {}", origins.describe(&e, &builder))))?;
    let build_s = start.elapsed().as_secs_f64();
    // Before any output, so that a failed run writes nothing.
    if options.max_inscribed_circle && !diagram.has_domain() {
        return Err(failed(format!("{name}: --max-inscribed-circle needs a polygon in the input, and there is none")));
    }
    // A distance the library does not take (zero, not finite, negative
    // without a domain) is its error: status 1 with its message.
    let offsets = match options.offset_distances.as_slice() {
        [] => Vec::new(),
        distances => {
            progress.phase(&format!("offsets at {} distance{}", distances.len(), if distances.len() == 1 { "" } else { "s" }));
            diagram.offsets(distances).map_err(|e| failed(format!("{name}: {e}")))?
        }
    };

    let tolerance = options.tolerance.unwrap_or_else(|| default_tolerance(&diagram));
    // The axis is computed once, for the file and the picture alike.
    let has_domain = diagram.has_domain();
    let needs_axis = options.medial_axis.is_some() || (options.svg.is_some() && has_domain);
    let axis = if needs_axis {
        progress.phase("medial axis");
        medial_axis(&diagram, &options)
    } else {
        MedialAxis::default()
    };
    progress.phase("writing");
    if let Some(path) = &options.svg {
        let rings = input.rings();
        let (lines, points) = input.obstacles();
        let domain = svg::Domain { rings: &rings, axis: &axis, tolerance, lines: &lines, points: &points };
        let look = svg::Look {
            title: Some(title(&name, &diagram, &builder)),
            // EWKT's SRID 4326 is longitude and latitude in degrees.
            units: options.units.clone().or_else(|| (input.srid() == Some(4326)).then(|| "deg".to_string())),
            diagram: options.svg_diagram,
        };
        write_file(path, &svg::render(&diagram, has_domain.then_some(&domain), &offsets, &look))?;
    }
    if let Some((path, format)) = &options.medial_axis {
        let text = match format {
            Format::Wkt => medial_output::wkt(&diagram, &axis, tolerance),
            Format::GeoJson => geojson_output::medial_axis(&diagram, &axis, tolerance),
            Format::Json => medial_output::json(&diagram, &axis),
            Format::Dxf => dxf::write::medial_axis(&diagram, &axis, tolerance),
            // refused by `args::parse` already
            Format::Gcode => return Err(bad_input("--medial-axis is not written as G-code".into())),
        };
        write_file(path, &text)?;
    }
    if let Some((path, format)) = &options.offsets {
        let text = match format {
            Format::Wkt if options.curves => wkt_curve_output::wkt(&offsets),
            Format::Wkt => offset_output::wkt(&offsets, tolerance),
            Format::Dxf => dxf::write::offsets(&offsets),
            Format::Gcode => gcode::program(&offsets, &options.gcode),
            Format::GeoJson => geojson_output::offsets(&offsets, tolerance),
            Format::Json => offset_output::json(&offsets),
        };
        write_file(path, &text)?;
    }
    if let Some(path) = &options.diagram {
        write_file(path, &diagram_output::json(&diagram, builder.point_count()))?;
    }
    if let Some(path) = &options.write_sites {
        write_file(path, &sites_as_built(&diagram, builder.point_count()))?;
    }
    if let Some(path) = &options.input_wkt {
        write_file(path, &input_wkt::wkt(&input, tolerance, options.curves))?;
    }
    progress.finish();
    if options.topology {
        let text_options =
            TopologyOptions::default().with_voronoi_pairs(options.voronoi_pairs).with_canonical_cuts(options.canonical_cuts);
        print(&diagram.topology(text_options))?;
    }
    if options.max_inscribed_circle {
        // A domain whose every vertex is on its boundary has no inside
        // vertex; the library's domains always have one, but say so rather
        // than panic.
        let (centre, r) =
            diagram.max_inscribed_circle().ok_or_else(|| failed(format!("{name}: the domain has no inscribed circle")))?;
        print(&format!("{} {} {}\n", centre.x, centre.y, r))?;
    }
    if options.stats {
        eprint!("{}", stats::report(&diagram, build_s));
        if let Some(srid) = input.srid() {
            // EWKT's SRID is reported, not used: the diagram is planar in
            // the coordinates as given.
            eprintln!("input_srid={srid}");
        }
    }
    if !wants_output(&options) {
        // Nothing asked for: say what was built and how to see it.
        print(&format!(
            "{name}: {} sites, {} vertices, {} edges (see --svg, --diagram, --topology, --stats, --medial-axis, --offset)\n",
            diagram.site_count(),
            diagram.vertex_count(),
            diagram.edge_count()
        ))?;
    }
    Ok(())
}

/// The input points (same indices) and the segments the diagram was built
/// from (the pieces, with `--split-crossings` or where input vertices cut
/// segments), in Boost.Polygon's format.
fn sites_as_built(diagram: &Diagram, points: usize) -> String {
    let points: Vec<[f64; 2]> = (0..points)
        .filter_map(|i| match diagram.site(diagram.site_of_input(i)?) {
            Some(segvoronoi::Site::Point(p)) => Some([p.x, p.y]),
            _ => None,
        })
        .collect();
    let segments: Vec<[f64; 4]> =
        (0..diagram.piece_count()).filter_map(|p| diagram.piece(p)).map(|[a, b]| [a.x, a.y, b.x, b.y]).collect();
    segvoronoi::boost_text::write(&points, &segments)
}

/// The picture's title: the input's file name and what it holds.
fn title(name: &str, diagram: &Diagram, builder: &Builder) -> String {
    let name = Path::new(name).file_name().map_or(name.to_string(), |n| n.to_string_lossy().into_owned());
    let arcs = builder.arc_count();
    let what = if diagram.has_domain() { "medial axis" } else { "Voronoi diagram" };
    let segments = builder.segment_count();
    let arcs = if arcs > 0 { format!(", {arcs} arcs") } else { String::new() };
    format!("{name}: {what}, {} sites ({segments} segments{arcs})", diagram.site_count())
}

/// The medial axis, filtered as the options ask (no option: no filter).
fn medial_axis(diagram: &Diagram, options: &Options) -> MedialAxis {
    let mut filter = MedialAxisFilter::new();
    if let Some(degrees) = options.corner_angle {
        filter = filter.with_corner_angle(degrees);
    }
    if let Some(k) = options.prune_spurs {
        filter = filter.with_spur_pruning(k);
    }
    diagram.medial_axis_filtered(&filter)
}

/// The default chord tolerance: 1e-4 times the diagonal of the input's
/// bounding box (1e-4 when the box is a point, where nothing finite gets
/// sampled anyway; from the largest double when the diagonal overflows).
fn default_tolerance(diagram: &segvoronoi::Diagram) -> f64 {
    match diagram.extent() {
        e if e.is_infinite() => 1e-4 * f64::MAX,
        e if e > 0.0 => 1e-4 * e,
        _ => 1e-4,
    }
}

fn wants_output(options: &Options) -> bool {
    options.svg.is_some()
        || options.diagram.is_some()
        || options.topology
        || options.stats
        || options.medial_axis.is_some()
        || options.max_inscribed_circle
        || options.offsets.is_some()
        || options.write_sites.is_some()
        || options.input_wkt.is_some()
}

fn write_file(path: &Path, text: &str) -> Result<(), Failure> {
    std::fs::write(path, text).map_err(|e| failed(format!("cannot write {}: {e}", path.display())))
}

/// Writes to standard output; a closed pipe is an output error, not a panic.
fn print(text: &str) -> Result<(), Failure> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes()).and_then(|()| out.flush()).map_err(|e| failed(format!("cannot write to standard output: {e}")))
}
