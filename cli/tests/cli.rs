//! The `segvoronoi` program, run as a user would: exit status, standard
//! output and standard error, files written.

mod common;

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

use common::{multilinestring_z, segment_distance};
use segvoronoi::{Builder, TopologyOptions};

const BIN: &str = env!("CARGO_BIN_EXE_segvoronoi");

/// A path in the temporary directory, unique to this test process and name.
fn temp_path(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("segvoronoi-cli-{}-{name}", std::process::id()))
}

/// Writes `text` to a temporary input file and returns its path.
fn input_file(name: &str, text: &str) -> PathBuf {
    let path = temp_path(name);
    std::fs::write(&path, text).unwrap();
    path
}

fn run(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().expect("the binary runs")
}

fn run_with_stdin(args: &[&str], stdin: &str) -> Output {
    let mut child =
        Command::new(BIN).args(args).stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    child.stdin.take().unwrap().write_all(stdin.as_bytes()).unwrap();
    child.wait_with_output().unwrap()
}

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

/// Boost.Polygon's text format for points only: their count, one point a
/// line (Rust's shortest decimal that reads back the same `f64`), and no
/// segments.
fn boost_text(points: &[[f64; 2]]) -> String {
    let lines: String = points.iter().map(|[x, y]| format!("{x:?} {y:?}\n")).collect();
    format!("{}\n{lines}0\n", points.len())
}

/// The topology text the library gives for the same points.
fn library_topology(points: &[[f64; 2]], voronoi_pairs: bool) -> String {
    let mut b = Builder::new();
    b.add_points(points.iter().copied()).unwrap();
    b.build().unwrap().topology(TopologyOptions::default().with_voronoi_pairs(voronoi_pairs))
}

/// A dozen points with a repeat, a collinear triple and a cocircular square.
const MIXED: [[f64; 2]; 12] = [
    [0.0, 0.0],
    [4.0, 0.0],
    [4.0, 4.0],
    [0.0, 4.0],
    [2.0, 2.0],
    [7.5, 1.25],
    [-3.0, 6.0],
    [1.0, -2.0],
    [3.0, -2.0],
    [5.0, -2.0],
    [4.0, 4.0],
    [6.0, 5.5],
];

#[test]
fn demo_svg_is_a_picture() {
    let path = temp_path("demo.svg");
    let o = run(&["--svg", path.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert!(svg.starts_with("<svg"), "{}", &svg[..100.min(svg.len())]);
    assert!(svg.trim_end().ends_with("</svg>"));
    // The demo has about sixty sites and more vertices than that.
    assert!(svg.matches("<circle").count() > 100, "too few dots");
    assert!(svg.matches("<line").count() > 100, "too few edges");
    assert!(!svg.contains("NaN") && !svg.contains("inf"));
    // The demo's segments: parabolic arcs between them and points.
    assert!(svg.matches(" Q ").count() >= 10, "too few parabolic arcs");
}

#[test]
fn no_output_asked_prints_a_summary() {
    let o = run(&[]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.starts_with("demo input: ") && out.contains(" sites, "), "{out}");
}

#[test]
fn topology_is_the_libraries() {
    let path = input_file("mixed.txt", &boost_text(&MIXED));
    let o = run(&[path.to_str().unwrap(), "--topology"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o), library_topology(&MIXED, false));
    let o = run(&[path.to_str().unwrap(), "--voronoi-pairs"]);
    std::fs::remove_file(&path).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o), library_topology(&MIXED, true));
    assert!(stdout(&o).contains("\nVVERTICES "));
}

#[test]
fn square_and_centre_by_hand() {
    // Sites P0..P3 are the corners counter-clockwise, P4 the centre. The
    // centre is strictly inside the circle through any three corners, so no
    // corner triangle is Delaunay: the Delaunay triangles are the four fans
    // P4 + a square side (four Voronoi vertices, at the sides' midpoints),
    // and the Delaunay edges are the four sides plus four spokes to the
    // centre. The diagonals are not edges (the centre blocks them).
    let path = input_file("square-centre.txt", "5\n0 0\n2 0\n2 2\n0 2\n1 1\n0\n");
    let o = run(&[path.to_str().unwrap(), "--topology"]);
    std::fs::remove_file(&path).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let expected = "EDGES 8\nP0 P1\nP0 P3\nP0 P4\nP1 P2\nP1 P4\nP2 P3\nP2 P4\nP3 P4\n\
                    FACES 4\nP0 P1 P4\nP0 P3 P4\nP1 P2 P4\nP2 P3 P4\n";
    assert_eq!(stdout(&o), expected);
}

#[test]
fn cocircular_square_by_hand() {
    // Four cocircular corners: a degree-4 vertex, stored as two degree-3
    // vertices (FACES 2) joined by a zero-length edge along one diagonal
    // (EDGES 5: the sides plus that diagonal). The voronoi-pairs sections,
    // which every correct answer shares, drop the diagonal and merge the two
    // vertices into one touching all four cells.
    let o = run_with_stdin(&["-", "--voronoi-pairs"], "4\n0 0\n2 0\n2 2\n0 2\n");
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.starts_with("EDGES 5\n"), "{out}");
    assert!(out.contains("\nFACES 2\n"), "{out}");
    let pairs = &out[out.find("VPAIRS").expect(&out)..];
    assert_eq!(pairs, "VPAIRS 4\nP0 P1\nP0 P3\nP1 P2\nP2 P3\nVVERTICES 1\nP0 P1 P2 P3\n");
}

#[test]
fn stdin_input() {
    let o = run_with_stdin(&["-", "--topology"], &boost_text(&MIXED));
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o), library_topology(&MIXED, false));
}

#[test]
fn stats_on_stderr() {
    let path = input_file("stats.txt", &boost_text(&MIXED));
    let o = run(&[path.to_str().unwrap(), "--stats"]);
    std::fs::remove_file(&path).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).is_empty(), "stats go to stderr only");
    let err = stderr(&o);
    let value = |key: &str| -> String {
        let prefix = format!("{key}=");
        err.lines().find_map(|l| l.strip_prefix(&prefix)).unwrap_or_else(|| panic!("no {key}= in {err}")).to_string()
    };
    let mut b = Builder::new();
    b.add_points(MIXED).unwrap();
    let d = b.build().unwrap();
    assert_eq!(value("input_points"), "12");
    assert_eq!(value("sites"), "11");
    assert_eq!(value("duplicates"), "1");
    assert_eq!(value("vertices"), d.vertex_count().to_string());
    assert_eq!(value("edges"), d.edge_count().to_string());
    let rays: usize = value("rays").parse().unwrap();
    let finite: usize = value("finite_edges").parse().unwrap();
    assert_eq!(rays + finite, d.edge_count());
    let build_s: f64 = value("build_s").parse().unwrap();
    assert!(build_s.is_finite() && build_s >= 0.0);
}

/// The topology text the library gives for points and segments.
fn library_topology_with_segments(points: &[[f64; 2]], segments: &[[[f64; 2]; 2]]) -> String {
    let mut b = Builder::new();
    b.add_points(points.iter().copied()).unwrap();
    b.add_segments(segments.iter().copied()).unwrap();
    b.build().unwrap().topology(TopologyOptions::default())
}

/// A point over a segment (one parabolic edge), a point beside it, and a
/// second segment sharing an endpoint with the first.
const WITH_SEGMENTS: &str = "2\n2 2\n7 3\n2\n0 0 4 0\n4 0 5 -2\n";

#[test]
fn segment_input_topology_names_segments() {
    let path = input_file("with-segments.txt", WITH_SEGMENTS);
    let o = run(&[path.to_str().unwrap(), "--topology"]);
    std::fs::remove_file(&path).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let expected =
        library_topology_with_segments(&[[2.0, 2.0], [7.0, 3.0]], &[[[0.0, 0.0], [4.0, 0.0]], [[4.0, 0.0], [5.0, -2.0]]]);
    assert_eq!(out, expected);
    // P0 (2,2) over S0: a parabolic edge; S0 and S1 meet at their shared endpoint.
    assert!(out.contains("\nP0 S0\n") && out.contains("S0 S1"), "{out}");
}

#[test]
fn segment_stats() {
    // Segment 1 repeats segment 0 reversed; segment 2 has zero length.
    let o = run_with_stdin(&["-", "--stats"], "1\n2 2\n3\n0 0 4 0\n4 0 0 0\n9 9 9 9\n");
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    for line in [
        "input_points=1",
        "input_segments=3",
        "duplicate_segments=1",
        "zero_length_segments=1",
        "segment_sites=1",
        "sites=5",
        "parabolic_edges=1",
    ] {
        assert!(err.lines().any(|l| l == line), "no {line} in {err}");
    }
}

#[test]
fn crossing_segments_exit_1_naming_both_indices() {
    let path = input_file("crossing.txt", "1\n9 9\n3\n0 0 2 2\n5 5 6 5\n0 2 2 0\n");
    let o = run(&[path.to_str().unwrap(), "--topology"]);
    std::fs::remove_file(&path).unwrap();
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).is_empty());
    let err = stderr(&o);
    assert!(err.contains("crossing.txt") && err.contains("segments 0 and 2 cross"), "{err}");
    // A point inside a segment splits it (no error), and a non-finite
    // segment coordinate.
    let o = run_with_stdin(&["-", "--stats"], "1\n1 1\n1\n0 0 2 2\n");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("split_at_vertices=1\n") && stderr(&o).contains("pieces=2\n"), "{}", stderr(&o));
    let o = run_with_stdin(&["-"], "0\n2\n0 0 1 0\n0 1 inf 1\n");
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("segment 1"), "{}", stderr(&o));
}

#[test]
fn svg_draws_parabolic_edges_as_quadratic_beziers() {
    let path = temp_path("arcs.svg");
    let o = run_with_stdin(&["-", "--svg", path.to_str().unwrap()], WITH_SEGMENTS);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert!(!svg.contains("NaN") && !svg.contains("inf"));
    let mut b = Builder::new();
    b.add_points([[2.0, 2.0], [7.0, 3.0]]).unwrap();
    b.add_segments([[[0.0, 0.0], [4.0, 0.0]], [[4.0, 0.0], [5.0, -2.0]]]).unwrap();
    let d = b.build().unwrap();
    let arcs = d.edges().filter(|e| d.edge_bezier(e.id).is_some()).count();
    assert!(arcs >= 2);
    let paths: Vec<&str> = svg.lines().filter(|l| l.starts_with(r#"<path d="M "#)).collect();
    // One arc (of (5,-2) under the first segment) lies below the picture.
    assert!((1..=arcs).contains(&paths.len()), "{arcs} arcs: {svg}");
    for p in paths {
        let words: Vec<&str> = p.trim_start_matches(r#"<path d=""#).trim_end_matches(r#""/>"#).split(' ').collect();
        assert_eq!((words.len(), words[0], words[3]), (8, "M", "Q"), "{p}");
        assert!(words.iter().enumerate().all(|(k, w)| k % 3 == 0 || w.parse::<f64>().is_ok()), "{p}");
    }
    // The two segment sites are thick lines of their own.
    let segments = &svg[svg.find(r#"<g id="segments""#).unwrap()..];
    assert_eq!(segments[..segments.find("</g>").unwrap()].matches("<line").count(), 2);
}

#[test]
fn malformed_input_names_the_line() {
    let path = input_file("malformed.txt", "3\n0 0\n\n1 one\n2 2\n");
    let o = run(&[path.to_str().unwrap(), "--topology"]);
    std::fs::remove_file(&path).unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(stdout(&o).is_empty());
    let err = stderr(&o);
    assert!(err.contains("line 4") && err.contains("\"one\""), "{err}");

    let o = run_with_stdin(&["-"], "4\n0 0\n1 1\n");
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("line 3") && stderr(&o).contains("point 2"), "{}", stderr(&o));
}

#[test]
fn non_finite_coordinate_is_a_library_error_naming_the_index() {
    let o = run_with_stdin(&["-", "--topology"], "4\n0 0\n1 0\n0 1\nnan 2\n0\n");
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).is_empty());
    let err = stderr(&o);
    assert!(err.contains("point 3"), "{err}");
}

#[test]
fn usage_errors_and_help() {
    let o = run(&["--frobnicate"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--frobnicate") && stderr(&o).contains("--help"));
    let o = run(&["--svg"]);
    assert_eq!(o.status.code(), Some(2));
    let o = run(&[temp_path("does-not-exist.txt").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("cannot read"), "{}", stderr(&o));
    let o = run(&["--help"]);
    assert!(o.status.success());
    assert!(stdout(&o).contains("Usage: segvoronoi") && stdout(&o).contains("GeoJSON"), "{}", stdout(&o));
    let o = run(&["--version"]);
    assert_eq!(stdout(&o), format!("segvoronoi {}\n", segvoronoi::VERSION));
}

#[test]
fn degenerate_inputs_draw_without_nan() {
    let cases = [
        ("empty", "0\n"),
        ("one", "1\n5 5\n"),
        ("same", "3\n2 2\n2 2\n2 2\n"),
        ("two", "2\n0 0\n3 1\n"),
        ("collinear", "4\n0 0\n1 2\n2 4\n5 10\n"),
    ];
    for (name, text) in cases {
        let path = temp_path(&format!("{name}.svg"));
        let o = run_with_stdin(&["-", "--svg", path.to_str().unwrap()], text);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let svg = std::fs::read_to_string(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert!(svg.starts_with("<svg") && !svg.contains("NaN") && !svg.contains("inf"), "{name}: {svg}");
    }
}

/// A square with a square hole off its centre, as WKT, and its rings.
const HOLED: &str = "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (3 4, 3 7, 6 7, 6 4, 3 4))\n";
const HOLED_RINGS: [&[[f64; 2]]; 2] =
    [&[[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]], &[[3.0, 4.0], [3.0, 7.0], [6.0, 7.0], [6.0, 4.0]]];

/// The distance from `p` to the nearest segment of the rings.
fn distance_to_rings(p: [f64; 2], rings: &[&[[f64; 2]]]) -> f64 {
    let mut best = f64::INFINITY;
    for ring in rings {
        for k in 0..ring.len() {
            best = best.min(segment_distance(p, ring[k], ring[(k + 1) % ring.len()]));
        }
    }
    best
}

fn holed_diagram() -> segvoronoi::Diagram {
    let mut b = Builder::new();
    b.add_polygon(&HOLED_RINGS).unwrap();
    b.build().unwrap()
}

#[test]
fn medial_axis_wkt_z_is_the_clearance() {
    let input = input_file("holed.wkt", HOLED);
    let out = temp_path("holed-axis.wkt");
    let o = run(&[input.to_str().unwrap(), "--medial-axis", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).is_empty(), "{}", stdout(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(text.lines().count(), 1, "one geometry: {text}");
    let lines = multilinestring_z(&text);
    // One linestring per chain: the domain has no rays to cut.
    assert_eq!(lines.len(), holed_diagram().medial_axis().chains.len());
    let diagonal = 10.0f64.hypot(10.0);
    let mut points = 0;
    for point in lines.iter().flatten() {
        let d = distance_to_rings([point[0], point[1]], &HOLED_RINGS);
        assert!((point[2] - d).abs() <= 1e-9 * diagonal, "{point:?}: nearest ring segment at {d}");
        points += 1;
    }
    // A finer tolerance samples the parabolic arcs (at the hole's corners) more densely.
    let o = run(&[input.to_str().unwrap(), "--medial-axis", out.to_str().unwrap(), "--tolerance", "1e-6"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let finer: usize = multilinestring_z(&std::fs::read_to_string(&out).unwrap()).iter().map(Vec::len).sum();
    std::fs::remove_file(&out).unwrap();
    std::fs::remove_file(&input).unwrap();
    assert!(finer > points, "{finer} points at 1e-6, {points} by default");
}

#[test]
fn medial_axis_json_is_valid_and_exact() {
    let input = input_file("holed-json.wkt", HOLED);
    let out = temp_path("holed-axis.json");
    let o = run(&[input.to_str().unwrap(), "--medial-axis", out.to_str().unwrap()]);
    std::fs::remove_file(&input).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    let axis = holed_diagram().medial_axis();
    let pieces: usize = axis.chains.iter().map(|c| c.pieces.len()).sum();
    assert!(!text.contains("NaN") && !text.contains("inf"), "{text}");
    let value: serde_json::Value = serde_json::from_str(&text).unwrap();
    let chains = value["chains"].as_array().unwrap();
    assert_eq!(chains.len(), axis.chains.len(), "{text}");
    let all: Vec<&serde_json::Value> = chains.iter().flat_map(|c| c["pieces"].as_array().unwrap()).collect();
    assert_eq!(all.len(), pieces, "{text}");
    // The hole's corners face the outer ring's sides: parabolic pieces.
    assert!(all.iter().any(|p| p["kind"] == "parabola" && p["focus"] == serde_json::json!([6.0, 7.0])), "{text}");
    std::fs::remove_file(&out).unwrap();
}

#[test]
fn max_inscribed_circle_of_a_rectangle() {
    let o = run_with_stdin(&["-", "--max-inscribed-circle"], "polygon ((0 0, 4 0, 4 2, 0 2, 0 0))\n");
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert_eq!(out.lines().count(), 1, "{out}");
    let v: Vec<f64> = out.split_whitespace().map(|w| w.parse().unwrap()).collect();
    assert_eq!(v.len(), 3, "{out}");
    assert!((1.0..=3.0).contains(&v[0]) && (v[1] - 1.0).abs() < 1e-12 && (v[2] - 1.0).abs() < 1e-12, "{out}");
    // No polygon: exit status 1, nothing on standard output.
    let o = run_with_stdin(&["-", "--max-inscribed-circle"], "MULTIPOINT (0 0, 4 0, 4 2)\n");
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).is_empty());
    assert!(stderr(&o).contains("--max-inscribed-circle needs a polygon"), "{}", stderr(&o));
}

#[test]
fn malformed_wkt_names_line_and_column() {
    let path = input_file("malformed.wkt", "POINT (1 2)\nPOLYGON ((0 0, 4 0, 4 two, 0 0))\n");
    let o = run(&[path.to_str().unwrap(), "--medial-axis", temp_path("never.wkt").to_str().unwrap()]);
    std::fs::remove_file(&path).unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(!temp_path("never.wkt").exists());
    let err = stderr(&o);
    assert!(err.contains("malformed.wkt: line 2, column 23: expected a number or a WKT keyword, found 'two'"), "{err}");
    assert!(err.contains("near: ...") && err.contains("4 two"), "{err}");
    // Recognised by its first word on standard input too.
    let o = run_with_stdin(&["-"], "LineString (0 0, 1 1");
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("line 1, column 1: a '(' of this geometry is never closed"), "{}", stderr(&o));
}

#[test]
fn crossing_rings_exit_1_naming_the_rings() {
    let o = run_with_stdin(
        &["-", "--medial-axis", temp_path("never.json").to_str().unwrap()],
        "POLYGON ((0 0, 4 0, 4 4, 0 4), (1 1, 5 1, 5 2, 1 2))",
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(!temp_path("never.json").exists());
    let err = stderr(&o);
    assert!(err.contains("cross") && err.contains("polygon 0, ring 0") && err.contains("polygon 0, ring 1"), "{err}");
}

#[test]
fn wkt_obstacles_and_the_domain_in_the_picture() {
    // A polygon, a linestring and a point inside it: every kind of input.
    let input = input_file(
        "mixed.wkt",
        "GEOMETRYCOLLECTION (POLYGON ((0 0, 12 0, 12 8, 0 8, 0 0)), LINESTRING Z (2 2 0, 4 3 0), POINT (9 5))\n",
    );
    let svg_path = temp_path("mixed.svg");
    let o = run(&[input.to_str().unwrap(), "--svg", svg_path.to_str().unwrap(), "--stats"]);
    std::fs::remove_file(&input).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).lines().any(|l| l == "input_segments=5"), "{}", stderr(&o));
    assert!(stderr(&o).lines().any(|l| l == "dropped_chain_points=0"), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    std::fs::remove_file(&svg_path).unwrap();
    assert!(!svg.contains("NaN") && !svg.contains("inf"));
    for part in [r#"<path id="domain""#, r#"fill-rule="evenodd""#, r#"<g id="medial-axis""#, r#"<circle id="inscribed-circle""#] {
        assert!(svg.contains(part), "no {part}: {svg}");
    }
    // Without polygons the picture is the diagram alone.
    let svg_path = temp_path("points.svg");
    let o = run_with_stdin(&["-", "--svg", svg_path.to_str().unwrap()], "MULTIPOINT ((0 0), (3 1), (1 4))");
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    std::fs::remove_file(&svg_path).unwrap();
    assert!(!svg.contains("medial-axis") && !svg.contains(r#"id="domain""#), "{svg}");
}

#[test]
fn medial_axis_without_a_domain_cuts_the_rays() {
    // A point over a segment (Boost.Polygon's format): the parabolic edge
    // between them is finite, every other non-separator edge is a ray.
    let out = temp_path("free-axis.wkt");
    let o = run_with_stdin(&["-", "--medial-axis", out.to_str().unwrap()], "1\n2 2\n1\n0 0 4 0\n");
    assert!(o.status.success(), "{}", stderr(&o));
    let lines = multilinestring_z(&std::fs::read_to_string(&out).unwrap());
    std::fs::remove_file(&out).unwrap();
    assert_eq!(lines.len(), 1, "{lines:?}");
    for p in &lines[0] {
        // on the parabola: as far from (2, 2) as from the segment's line
        assert!((p[2] - (p[0] - 2.0).hypot(p[1] - 2.0)).abs() < 1e-12 && (p[2] - p[1]).abs() < 1e-12, "{p:?}");
    }
}

#[test]
fn filters_leave_the_middle_line_of_a_rectangle() {
    // The four branches into the right-angled corners are sqrt(2) long, the
    // clearance at their junctions is 1: either filter leaves the middle line.
    let input = input_file("rectangle.wkt", "POLYGON ((0 0, 4 0, 4 2, 0 2, 0 0))\n");
    let out = temp_path("rectangle-axis.wkt");
    let middle = |args: &[&str]| {
        let mut all = vec![input.to_str().unwrap(), "--medial-axis", out.to_str().unwrap()];
        all.extend(args);
        let o = run(&all);
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        multilinestring_z(&std::fs::read_to_string(&out).unwrap())
    };
    assert_eq!(middle(&[]).len(), 5);
    for filter in [&["--prune-spurs", "2"][..], &["--corner-angle=80"], &["--corner-angle", "80", "--prune-spurs", "0.5"]] {
        let lines = middle(filter);
        assert_eq!(lines.len(), 1, "{filter:?}: {lines:?}");
        let ends = [lines[0][0], *lines[0].last().unwrap()];
        let mut xs = ends.map(|p| p[0]);
        xs.sort_by(f64::total_cmp);
        assert!((xs[0] - 1.0).abs() < 1e-12 && (xs[1] - 3.0).abs() < 1e-12, "{filter:?}: {ends:?}");
        assert!(ends.iter().all(|p| (p[1] - 1.0).abs() < 1e-12 && (p[2] - 1.0).abs() < 1e-12), "{filter:?}: {ends:?}");
    }
    // Branches into corners of 90 degrees stay below a threshold of 90.
    assert_eq!(middle(&["--corner-angle", "90"]).len(), 5);
    std::fs::remove_file(&out).unwrap();
    std::fs::remove_file(&input).unwrap();
    let o = run(&["--prune-spurs", "2"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--medial-axis or --svg"), "{}", stderr(&o));
}

/// The shoelace area of each closed ring of each polygon of each
/// `MULTIPOLYGON` line (`None` for `EMPTY`).
fn multipolygon_ring_areas(text: &str) -> Vec<Option<Vec<Vec<f64>>>> {
    text.lines()
        .map(|line| {
            if line == "MULTIPOLYGON EMPTY" {
                return None;
            }
            let body = line.strip_prefix("MULTIPOLYGON (((").and_then(|b| b.strip_suffix(")))")).expect(line);
            let polygons = body.split(")), ((").map(|polygon| {
                polygon
                    .split("), (")
                    .map(|ring| {
                        let points: Vec<[f64; 2]> = ring
                            .split(", ")
                            .map(|p| {
                                let v: Vec<f64> = p.split(' ').map(|w| w.parse().expect(p)).collect();
                                [v[0], v[1]]
                            })
                            .collect();
                        assert_eq!(points.first(), points.last(), "closed: {ring}");
                        points.windows(2).map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1]).sum::<f64>() / 2.0
                    })
                    .collect()
            });
            Some(polygons.collect())
        })
        .collect()
}

#[test]
fn offsets_wkt_one_multipolygon_per_distance_in_order() {
    let input = input_file("offsets-input.wkt", HOLED);
    let out = temp_path("offsets.wkt");
    let o =
        run(&[input.to_str().unwrap(), "--offset", "1", "--offset=-0.5", "--offset", "-6", "--offsets", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).is_empty(), "{}", stdout(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    let areas = multipolygon_ring_areas(&text);
    assert_eq!(areas.len(), 3, "{text}");
    // grown by 1: the square rounded, the 3 × 3 hole shrunk to 1 × 1;
    // the default tolerance is 1e-4 of the diagonal
    let tolerance = 1e-4 * 10.0f64.hypot(10.0);
    let grown = areas[0].as_ref().expect(&text);
    assert_eq!((grown.len(), grown[0].len()), (1, 2), "{text}");
    let (exact, perimeter) = (100.0 + 40.0 + std::f64::consts::PI, 40.0 + 2.0 * std::f64::consts::PI);
    assert!(grown[0][0] <= exact && exact - grown[0][0] <= tolerance * perimeter, "{grown:?}");
    assert!((grown[0][1] + 1.0).abs() < 1e-9, "{grown:?}");
    // shrunk by 0.5: a 9 × 9 square with a rounded hole
    let shrunk = areas[1].as_ref().expect(&text);
    assert_eq!((shrunk.len(), shrunk[0].len()), (1, 2), "{text}");
    assert!((shrunk[0][0] - 81.0).abs() < 1e-9, "{shrunk:?}");
    // shrunk beyond the largest inscribed circle: nothing
    assert!(areas[2].is_none(), "{text}");
    // a finer tolerance: closer to the exact area
    let o = run(&[input.to_str().unwrap(), "--offset", "1", "--offsets", out.to_str().unwrap(), "--tolerance", "1e-7"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let finer = multipolygon_ring_areas(&std::fs::read_to_string(&out).unwrap());
    std::fs::remove_file(&out).unwrap();
    std::fs::remove_file(&input).unwrap();
    let finer = finer[0].as_ref().unwrap()[0][0];
    assert!(exact - finer <= 1e-7 * perimeter && finer > grown[0][0], "{finer} vs {}", grown[0][0]);
}

#[test]
fn offsets_json_is_valid_and_exact() {
    let out = temp_path("offsets.json");
    let o = run_with_stdin(&["-", "--offset", "-0.5", "--offset", "1", "--offsets", out.to_str().unwrap()], HOLED);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    let offsets = holed_diagram().offsets(&[-0.5, 1.0]).unwrap();
    assert!(!text.contains("NaN") && !text.contains("inf"), "{text}");
    let value: serde_json::Value = serde_json::from_str(&text).unwrap();
    let written = value["offsets"].as_array().unwrap();
    assert_eq!(written.len(), 2);
    assert_eq!((written[0]["distance"].as_f64(), written[1]["distance"].as_f64()), (Some(-0.5), Some(1.0)));
    assert_eq!(written[1]["area"].as_f64(), Some(offsets[1].area()));
    let loops: Vec<&serde_json::Value> = written.iter().flat_map(|o| o["loops"].as_array().unwrap()).collect();
    assert_eq!(loops.len(), offsets.iter().map(|o| o.loops.len()).sum::<usize>(), "{text}");
    let pieces: Vec<&serde_json::Value> = loops.iter().flat_map(|l| l["pieces"].as_array().unwrap()).collect();
    assert_eq!(pieces.len(), offsets.iter().flat_map(|o| &o.loops).map(|l| l.pieces.len()).sum::<usize>(), "{text}");
    let arc = |centre: [f64; 2], radius: f64, ccw: bool| {
        pieces.iter().any(|p| p["centre"] == serde_json::json!(centre) && p["radius"] == radius && p["counter_clockwise"] == ccw)
    };
    // the outer ring's corners grown: quarter circles around them
    assert!(arc([10.0, 10.0], 1.0, true), "{text}");
    // the hole's corners, shrunk: arcs the other way round
    assert!(arc([6.0, 7.0], 0.5, false), "{text}");
    assert!(loops.iter().any(|l| l["parent"] == 0 && l["hole"] == true), "{text}");
    std::fs::remove_file(&out).unwrap();
}

#[test]
fn offsets_in_the_picture() {
    let svg_path = temp_path("offsets.svg");
    let o = run_with_stdin(
        &["-", "--svg", svg_path.to_str().unwrap(), "--offset", "2", "--offsets", temp_path("o.wkt").to_str().unwrap()],
        "2\n0 0\n10 0\n",
    );
    std::fs::remove_file(temp_path("o.wkt")).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    std::fs::remove_file(&svg_path).unwrap();
    assert!(svg.contains(r#"<g id="offsets""#) && !svg.contains("NaN"), "{svg}");
    // two whole circles, each two half arcs
    assert_eq!(svg.matches(r#" data-distance="2" d="M "#).count(), 2, "{svg}");
    assert_eq!(svg.matches(" A ").count(), 4, "{svg}");
}

#[test]
fn offset_usage_and_distance_errors() {
    let out = temp_path("never-offsets.wkt");
    // one option without the other: usage errors
    let o = run(&["--offset", "1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--offset D needs --offsets"), "{}", stderr(&o));
    let o = run(&["--offsets", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--offsets needs at least one --offset"), "{}", stderr(&o));
    let o = run(&["--offset", "x", "--offsets", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    // distances the library rejects: its message, status 1, nothing written
    let cases: [(&str, &str, &str); 4] = [
        ("nan", HOLED, "not a finite number"),
        ("0", HOLED, "zero"),
        ("inf", HOLED, "not a finite number"),
        ("-1", "MULTIPOINT ((0 0), (3 1))", "negative, and there is no domain to shrink"),
    ];
    let svg = temp_path("never-offsets.svg");
    for (distance, input, message) in cases {
        let o = run_with_stdin(
            &["-", "--offset", "1", "--offset", distance, "--offsets", out.to_str().unwrap(), "--svg", svg.to_str().unwrap()],
            input,
        );
        assert_eq!(o.status.code(), Some(1), "{distance}: {}", stderr(&o));
        assert!(stderr(&o).contains("offset distance") && stderr(&o).contains(message), "{distance}: {}", stderr(&o));
        assert!(!out.exists() && !svg.exists(), "{distance}: a failed run writes nothing");
    }
}

#[test]
fn crossing_input_is_refused_naming_lines_and_coordinates_or_split() {
    let path = input_file("split-crossing.txt", "1\n1 0.5\n3\n0 0 2 2\n\n0 2 2 0\n1 0.5 1 3\n");
    let path = path.to_str().unwrap();
    let o = run(&[path]);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(err.contains("segments 0 and 1 cross"), "{err}");
    assert!(err.contains("segment 0, line 4: (0, 0) - (2, 2)") && err.contains("segment 1, line 6: (0, 2) - (2, 0)"), "{err}");
    assert!(err.contains("--split-crossings"), "{err}");

    let sites = temp_path("built.txt");
    let o = run(&[path, "--split-crossings", "--stats", "--write-sites", sites.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report = stderr(&o);
    assert!(report.contains("crossings=3") && report.contains("pieces=6"), "{report}");
    // what was written is the split input: it builds strictly, as the same diagram
    let written = std::fs::read_to_string(&sites).unwrap();
    let again = segvoronoi::boost_text::parse(&written).unwrap();
    assert_eq!((again.points.len(), again.segments.len()), (1, 6));
    let o = run(&[sites.to_str().unwrap(), "--topology"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let split = run(&[path, "--split-crossings", "--topology"]);
    assert_eq!(stdout(&o), stdout(&split));
}

/// Valid OGC input as it is (issue 27): a hole touching its shell inside
/// an edge builds by default, exactly (the shell's edge is cut at the
/// hole's vertex, nothing moves); rings sharing a stretch are refused with
/// the rings, the stretch and what to do.
#[test]
fn a_hole_touching_its_shell_builds_exactly() {
    let path = input_file("touching.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (0 5, 3 4, 3 6, 0 5))\n");
    let o = run(&[path.to_str().unwrap(), "--stats", "--max-inscribed-circle"]);
    std::fs::remove_file(&path).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let report = stderr(&o);
    for figure in ["input_segments=7", "split_at_vertices=1", "pieces=8", "snap_rounds=0", "max_split_displacement=0"] {
        assert!(report.lines().any(|l| l == figure), "{figure} in {report}");
    }
    // the largest circle: inside the shell, outside the hole, touching
    // the shell's right and top edges and the hole's corner (3, 6)
    let circle: Vec<f64> = stdout(&o).split_whitespace().map(|v| v.parse().unwrap()).collect();
    let [x, y, r] = circle[..] else { panic!("{circle:?}") };
    for clearance in [10.0 - x, 10.0 - y, (x - 3.0).hypot(y - 6.0)] {
        assert!((clearance - r).abs() < 1e-9, "{circle:?}");
    }
    assert!(r > 3.5 && x > 3.0 && y > 6.0, "{circle:?}");
    // the medial axis too
    let axis = temp_path("touching-axis.wkt");
    let o = run_with_stdin(
        &["-", "--medial-axis", axis.to_str().unwrap()],
        "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (0 5, 3 4, 3 6, 0 5))",
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&axis).unwrap().starts_with("MULTILINESTRING Z"));
    std::fs::remove_file(&axis).unwrap();

    // two squares of a MultiPolygon sharing part of an edge: the shared
    // stretch cancels (even-odd), counted in --stats
    let o = run_with_stdin(&["-", "--stats"], "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((4 1, 6 1, 6 3, 4 3, 4 1)))");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("cancelled_ring_pieces=2\n"), "{}", stderr(&o));
    // a line along a polygon's edge is an obstacle overlapping it: refused
    let o = run_with_stdin(&["-"], "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))\nLINESTRING (1 0, 3 0)");
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(err.contains("overlap from (1, 0) to (3, 0)"), "{err}");
}

#[test]
fn a_self_crossing_wkt_polygon_is_named_by_geometry_and_ring() {
    let path = input_file("bow.wkt", "POINT (5 5)\nPOLYGON ((0 0, 2 2, 2 0, 0 2))\n");
    let o = run(&[path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(err.contains("segment 0, geometry 1 (a polygon), ring 0: (0, 0) - (2, 2)"), "{err}");
    let o = run(&[path.to_str().unwrap(), "--split-crossings", "--max-inscribed-circle"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn geojson_in_and_out() {
    // A FeatureCollection: a polygon with a hole, a line and a point.
    let input = r#"{"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"name": "holed"}, "geometry": {"type": "Polygon",
         "coordinates": [[[0,0],[20,0],[20,14],[0,14],[0,0]], [[5,5],[8,5],[8,8],[5,8],[5,5]]]}},
        {"type": "Feature", "properties": null, "geometry": {"type": "MultiPoint", "coordinates": [[15, 7]]}}]}"#;
    let axis = temp_path("axis.geojson");
    let offsets = temp_path("offsets.geojson");
    let o = run_with_stdin(
        &[
            "-",
            "--medial-axis",
            axis.to_str().unwrap(),
            "--offset",
            "-1",
            "--offset",
            "2",
            "--offsets",
            offsets.to_str().unwrap(),
        ],
        input,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let axis_text = std::fs::read_to_string(&axis).unwrap();
    let offsets_text = std::fs::read_to_string(&offsets).unwrap();
    std::fs::remove_file(&axis).unwrap();
    std::fs::remove_file(&offsets).unwrap();
    let axis: serde_json::Value = serde_json::from_str(&axis_text).unwrap();
    assert_eq!(axis["type"], "Feature");
    assert_eq!(axis["geometry"]["type"], "MultiLineString");
    let lines = axis["geometry"]["coordinates"].as_array().unwrap();
    let clearance = axis["properties"]["clearance"].as_array().unwrap();
    assert!(!lines.is_empty() && lines.len() == clearance.len());
    // z is the clearance, the same as the property, and at most the
    // largest inscribed circle (the hole leaves at most 6 either way).
    for (line, r) in lines.iter().zip(clearance) {
        for (p, r) in line.as_array().unwrap().iter().zip(r.as_array().unwrap()) {
            assert_eq!(p[2], *r);
            assert!((0.0..=7.0).contains(&p[2].as_f64().unwrap()), "{p}");
        }
    }
    let offsets: serde_json::Value = serde_json::from_str(&offsets_text).unwrap();
    let features = offsets["features"].as_array().unwrap();
    assert_eq!(features.len(), 2);
    assert_eq!(
        (features[0]["properties"]["distance"].as_f64(), features[1]["properties"]["distance"].as_f64()),
        (Some(-1.0), Some(2.0))
    );
    for f in features {
        assert_eq!(f["geometry"]["type"], "MultiPolygon");
        let area = f["properties"]["area"].as_f64().unwrap();
        assert!(area > 0.0, "{f}");
        // Every ring closed.
        for polygon in f["geometry"]["coordinates"].as_array().unwrap() {
            for ring in polygon.as_array().unwrap() {
                let ring = ring.as_array().unwrap();
                assert_eq!(ring.first(), ring.last());
            }
        }
    }
    // --format geojson for any file name.
    let out = temp_path("axis.out");
    let o = run_with_stdin(&["-", "--medial-axis", out.to_str().unwrap(), "--format", "geojson"], input);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&out).unwrap().contains("\"MultiLineString\""));
    std::fs::remove_file(&out).unwrap();
}

#[test]
fn ewkt_srid_is_accepted_and_reported() {
    let o = run_with_stdin(&["-", "--stats", "--max-inscribed-circle"], "SRID=4326;POLYGON ((0 0, 4 0, 4 2, 0 2, 0 0))");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).lines().any(|l| l == "input_srid=4326"), "{}", stderr(&o));
    let v: Vec<f64> = stdout(&o).split_whitespace().map(|w| w.parse().unwrap()).collect();
    assert_eq!(v[2], 1.0);
}

#[test]
fn a_bad_geojson_file_is_quoted_near_the_problem_only() {
    let path = input_file(
        "broken.geojson",
        &format!("{{\"type\": \"MultiPoint\",\n\"coordinates\": [{}[1, oops]]}}\n", "[0, 0], ".repeat(500)),
    );
    let o = run(&[path.to_str().unwrap()]);
    std::fs::remove_file(&path).unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(err.contains("broken.geojson: line 2, column ") && err.contains("oops"), "{err}");
    assert!(err.len() < 400, "the whole file echoed: {err}");
}

/// The repository's `examples/data/`; `None` in the published package,
/// which holds the program and these tests but not the repository's data
/// (the tests that read it then say so and pass: in the repository, where
/// CI runs them, it is always there).
fn example_data() -> Option<std::path::PathBuf> {
    let data = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/data");
    if data.is_dir() {
        Some(data)
    } else {
        eprintln!("no {} (a packaged crate): the example files are not checked", data.display());
        None
    }
}

/// Every file of examples/data/, in every output format: what the README
/// promises for the installed program.
#[test]
fn every_example_file_in_every_output_format() {
    let Some(data) = example_data() else { return };
    let mut seen = 0;
    for entry in std::fs::read_dir(&data).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "md") {
            continue;
        }
        seen += 1;
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        for format in ["wkt", "geojson", "json"] {
            let axis = temp_path(&format!("ex-{name}-axis.{format}"));
            let offsets = temp_path(&format!("ex-{name}-offsets.{format}"));
            let svg = temp_path(&format!("ex-{name}.svg"));
            let o = run(&[
                path.to_str().unwrap(),
                "--medial-axis",
                axis.to_str().unwrap(),
                "--offset",
                "-0.2",
                "--offsets",
                offsets.to_str().unwrap(),
                "--svg",
                svg.to_str().unwrap(),
            ]);
            assert!(o.status.success(), "{name} {format}: {}", stderr(&o));
            let (axis_text, offsets_text) = (std::fs::read_to_string(&axis).unwrap(), std::fs::read_to_string(&offsets).unwrap());
            match format {
                "wkt" => {
                    assert!(axis_text.starts_with("MULTILINESTRING Z ((") && offsets_text.starts_with("MULTIPOLYGON"), "{name}")
                }
                _ => {
                    let a: serde_json::Value = serde_json::from_str(&axis_text).unwrap();
                    let b: serde_json::Value = serde_json::from_str(&offsets_text).unwrap();
                    assert!(a.is_object() && b.is_object(), "{name}");
                }
            }
            let picture = std::fs::read_to_string(&svg).unwrap();
            assert!(picture.contains("<title>") && picture.contains(r#"id="medial-axis""#), "{name}");
            for p in [axis, offsets, svg] {
                std::fs::remove_file(p).unwrap();
            }
        }
    }
    assert!(seen >= 5, "{seen} example files");
}

#[test]
fn several_countries_give_their_medial_axes_and_offsets() {
    let Some(data) = example_data() else { return };
    let data = data.join("countries.geojson");
    let axis = temp_path("countries-axis.geojson");
    let offsets = temp_path("countries-offsets.geojson");
    let o = run(&[
        data.to_str().unwrap(),
        "--medial-axis",
        axis.to_str().unwrap(),
        "--offset",
        "-5",
        "--offsets",
        offsets.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let a: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&axis).unwrap()).unwrap();
    let b: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&offsets).unwrap()).unwrap();
    std::fs::remove_file(axis).unwrap();
    std::fs::remove_file(offsets).unwrap();
    // Three separate countries: their axes are at least three chains, the
    // shrunk region at least three polygons (one per country, or more where
    // a narrow part is cut off).
    assert!(a["geometry"]["coordinates"].as_array().unwrap().len() >= 3);
    assert!(b["features"][0]["geometry"]["coordinates"].as_array().unwrap().len() >= 3);
}

/// `--progress` names every phase on standard error, one line each when
/// standard error is not a terminal, and leaves standard output as it was;
/// `--quiet` shows nothing; the two together are a usage error.
#[test]
fn progress_shows_the_phases_on_stderr_only() {
    let Some(data) = example_data() else { return };
    let glyph = data.join("glyph_B.wkt");
    let glyph = glyph.to_str().unwrap();
    let axis = temp_path("progress-axis.wkt");
    let offsets = temp_path("progress-offsets.wkt");
    let args = |extra: &[&str]| -> Vec<String> {
        let mut a: Vec<String> = [glyph, "--topology", "--medial-axis", axis.to_str().unwrap(), "--offset", "-20"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        a.extend(["--offsets".to_string(), offsets.to_str().unwrap().to_string()]);
        a.extend(extra.iter().map(|s| s.to_string()));
        a
    };
    let call = |extra: &[&str]| {
        let a = args(extra);
        run(&a.iter().map(String::as_str).collect::<Vec<_>>())
    };
    let plain = call(&[]);
    assert!(plain.status.success(), "{}", stderr(&plain));
    assert_eq!(stderr(&plain), "", "no progress by default off a terminal");
    let axis_plain = std::fs::read_to_string(&axis).unwrap();

    let shown = call(&["--progress"]);
    assert!(shown.status.success(), "{}", stderr(&shown));
    assert_eq!(stdout(&shown), stdout(&plain), "standard output unchanged");
    assert_eq!(std::fs::read_to_string(&axis).unwrap(), axis_plain, "files unchanged");
    let lines: Vec<String> = stderr(&shown).lines().map(str::to_string).collect();
    let phases = [
        "reading ",
        "building: the input check, then the diagram of ",
        "offsets at 1 distance",
        "medial axis",
        "writing",
        "done",
    ];
    assert_eq!(lines.len(), phases.len(), "{lines:?}");
    for (line, phase) in lines.iter().zip(phases) {
        let (time, what) = line.strip_prefix("segvoronoi: [").and_then(|l| l.split_once(" s] ")).expect(line);
        assert!(time.trim().parse::<f64>().is_ok_and(|t| t >= 0.0), "{line}");
        assert!(what.starts_with(phase), "{line} should be {phase}");
    }

    let quiet = call(&["--quiet"]);
    assert!(quiet.status.success());
    assert_eq!((stdout(&quiet), stderr(&quiet)), (stdout(&plain), String::new()));
    let both = call(&["--progress", "--quiet"]);
    assert_eq!(both.status.code(), Some(2), "{}", stderr(&both));
    for path in [axis, offsets] {
        let _ = std::fs::remove_file(path);
    }
}

/// `--threads N` (issue 33): the same topology at one thread and at the
/// machine's cores, on 25k segments on a lattice (75k sites: two threads
/// build it in halves), with `--canonical-cuts` (the lattice's cocircular
/// sites are cut one way whatever the build); 0 and words are refused by
/// the parser.
#[test]
fn threads_give_the_same_diagram() {
    let mut text = String::from("0\n25000\n");
    for k in 0..25_000u32 {
        let (x, y) = (f64::from(k % 200) * 4.0, f64::from(k / 200) * 4.0);
        text.push_str(&format!("{x} {y} {} {}\n", x + 1.0 + f64::from(k % 3), y + f64::from(k % 2)));
    }
    let path = input_file("threads.txt", &text);
    let path = path.to_str().unwrap();
    let one = run(&[path, "--threads", "1", "--canonical-cuts", "--voronoi-pairs"]);
    assert!(one.status.success(), "{}", stderr(&one));
    let all = run(&[path, "--canonical-cuts", "--voronoi-pairs"]);
    assert!(all.status.success(), "{}", stderr(&all));
    assert!(stdout(&one) == stdout(&all) && !stdout(&one).is_empty());
    for bad in ["0", "two"] {
        let o = run(&[path, "--threads", bad, "--topology"]);
        assert_eq!(o.status.code(), Some(2), "--threads {bad}: {}", stderr(&o));
        assert!(stderr(&o).contains("--threads"), "{}", stderr(&o));
    }
}
