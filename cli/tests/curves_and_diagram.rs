//! Circular arcs through the program (WKT curves as PostGIS writes them)
//! and `--diagram`, the JSON dump of any diagram, run as a user would.
//!
//! The tests that build a diagram with arcs call `arcs_build()` first,
//! which returns `false` (and says so on standard error) while
//! `Builder::build` answers arcs with its "under construction" error (as
//! it did before the core's build of arcs landed, issue 31); any other
//! refusal fails them. Inputs the library cannot build yet are `#[ignore]`d
//! with the reason, so that `cargo test -- --ignored` shows what is still
//! wrong in the core.

use std::path::PathBuf;
use std::process::{Command, Output};

use segvoronoi::{Builder, CircularArc};
use serde_json::Value;

const BIN: &str = env!("CARGO_BIN_EXE_segvoronoi");

fn temp_path(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("segvoronoi-cli-curves-{}-{name}", std::process::id()))
}

fn input_file(name: &str, text: &str) -> PathBuf {
    let path = temp_path(name);
    std::fs::write(&path, text).unwrap();
    path
}

fn run(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().expect("the binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

/// Whether the library builds arcs yet (see the module doc).
fn arcs_build() -> bool {
    let mut b = Builder::new();
    b.add_arc(CircularArc::from_bulge([0.0, 0.0], [2.0, 0.0], 1.0).unwrap()).unwrap();
    b.add_point([1.0, 3.0]).unwrap();
    match b.build() {
        Ok(_) => true,
        Err(e) => {
            assert!(e.message().contains("under construction"), "the library refuses arcs otherwise: {e}");
            eprintln!("skipped until the library builds arcs: {e}");
            false
        }
    }
}

/// Runs the program on a WKT text with `--diagram` and more arguments;
/// returns the parsed diagram and the output.
fn diagram_of(name: &str, wkt: &str, more: &[&str]) -> (Value, Output) {
    let input = input_file(&format!("{name}.wkt"), wkt);
    let json = temp_path(&format!("{name}.json"));
    let mut args = vec![input.to_str().unwrap(), "--diagram", json.to_str().unwrap()];
    args.extend_from_slice(more);
    let o = run(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&json).unwrap();
    std::fs::remove_file(&json).unwrap();
    std::fs::remove_file(&input).unwrap();
    (serde_json::from_str(&text).unwrap_or_else(|e| panic!("not JSON ({e}): {text}")), o)
}

fn xy(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

fn dist(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// The distance from `p` to a site of the JSON dump, from the dump's own
/// numbers: a point; a closed segment; a closed arc (its circle within its
/// angular span, else the nearer end).
fn site_distance(site: &Value, p: [f64; 2]) -> f64 {
    match site["kind"].as_str().unwrap() {
        "point" => dist(xy(&site["position"]), p),
        "segment" => {
            let (a, b) = (xy(&site["start"]), xy(&site["end"]));
            let d = [b[0] - a[0], b[1] - a[1]];
            let t = (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1])).clamp(0.0, 1.0);
            dist([a[0] + t * d[0], a[1] + t * d[1]], p)
        }
        "arc" => {
            let (a, b, c) = (xy(&site["start"]), xy(&site["end"]), xy(&site["centre"]));
            let r = site["radius"].as_f64().unwrap();
            let sweep = 4.0 * site["bulge"].as_f64().unwrap().atan();
            assert_eq!(sweep > 0.0, site["ccw"].as_bool().unwrap(), "{site}");
            let angle = |q: [f64; 2]| (q[1] - c[1]).atan2(q[0] - c[0]);
            let turn = (angle(p) - angle(a)) * sweep.signum();
            if turn.rem_euclid(std::f64::consts::TAU) <= sweep.abs() {
                (dist(c, p) - r).abs()
            } else {
                dist(a, p).min(dist(b, p))
            }
        }
        other => panic!("a site of kind {other}"),
    }
}

/// The largest coordinate magnitude of a dump's sites, at least 1: the
/// scale of its rounding errors.
fn scale_of(d: &Value) -> f64 {
    let sites = d["sites"].as_array().unwrap();
    let coordinates = sites.iter().flat_map(|s| ["position", "start", "end"].map(|k| s[k].clone())).filter(|v| v.is_array());
    coordinates.map(|v| xy(&v)[0].abs().max(xy(&v)[1].abs())).fold(1.0, f64::max)
}

/// Checks a dump against itself: ids in order, every vertex with three
/// existing sites, a finite clearance `>= 0` that is its distance to each
/// of them, every edge with two existing sites and ends that exist (or a
/// unit direction), segment and arc endpoints that are point sites at
/// their ends. Returns the number of arc sites.
fn check_dump(d: &Value) -> usize {
    let (sites, vertices, edges) =
        (d["sites"].as_array().unwrap(), d["vertices"].as_array().unwrap(), d["edges"].as_array().unwrap());
    let scale = scale_of(d);
    let mut arcs = 0;
    for (k, site) in sites.iter().enumerate() {
        assert_eq!(site["id"].as_u64(), Some(k as u64), "{site}");
        if let Some(ends) = site["endpoints"].as_array() {
            let ends: Vec<&Value> = ends.iter().map(|e| &sites[e.as_u64().unwrap() as usize]).collect();
            assert_eq!((ends[0]["kind"].as_str(), ends[1]["kind"].as_str()), (Some("point"), Some("point")));
            assert_eq!((&ends[0]["position"], &ends[1]["position"]), (&site["start"], &site["end"]), "{site}");
        }
        if site["kind"] == "arc" {
            assert_eq!(site["name"].as_str(), Some(format!("A{}", site["input"]).as_str()), "{site}");
            arcs += 1;
        }
    }
    for (k, v) in vertices.iter().enumerate() {
        assert_eq!(v["id"].as_u64(), Some(k as u64));
        let ids = v["sites"].as_array().unwrap();
        assert_eq!(ids.len(), 3, "{v}");
        let r = v["clearance"].as_f64().unwrap_or_else(|| panic!("a finite clearance: {v}"));
        assert!(r.is_finite() && r >= 0.0, "{v}");
        let p = xy(&v["position"]);
        for id in ids {
            let site = &sites[id.as_u64().unwrap() as usize];
            let d = site_distance(site, p);
            assert!((d - r).abs() <= 1e-9 * scale, "vertex {v}: {d} from {site}");
        }
    }
    for (k, e) in edges.iter().enumerate() {
        assert_eq!(e["id"].as_u64(), Some(k as u64));
        assert!(["line", "parabola", "conic"].contains(&e["kind"].as_str().unwrap()), "{e}");
        for s in e["sites"].as_array().unwrap() {
            assert!((s.as_u64().unwrap() as usize) < sites.len(), "{e}");
        }
        if let Some(bezier) = e.get("bezier") {
            // from the position of one end to that of the other
            assert_ne!(e["kind"], "line", "{e}");
            let points = bezier["points"].as_array().unwrap();
            assert!(points.len() == 3 && bezier["weight"].as_f64().unwrap() > 0.0, "{e}");
            for (k, end) in [(0, &e["ends"][0]), (2, &e["ends"][1])] {
                assert_eq!(points[k], vertices[end["vertex"].as_u64().unwrap() as usize]["position"], "{e}");
            }
        }
        for end in e["ends"].as_array().unwrap() {
            match (end.get("vertex"), end.get("direction")) {
                (Some(v), None) => assert!((v.as_u64().unwrap() as usize) < vertices.len(), "{e}"),
                (None, Some(d)) => assert!((dist(xy(d), [0.0, 0.0]) - 1.0).abs() < 1e-12, "{e}"),
                _ => panic!("an end is a vertex or a direction: {e}"),
            }
        }
    }
    arcs
}

/// Checks that every separator reaching infinity (between a segment or
/// arc and one of its endpoints) runs along its line: its vertex, its
/// direction and the endpoint on one line (for a segment the perpendicular
/// at the endpoint, for an arc the radius through it), within `tolerance`
/// times the input's scale. A vertex off that line by `δ` is off
/// equidistance by only about `δ²/r`, so this sees what `check_dump`
/// cannot. Returns how many there are and the largest miss, relative.
fn check_separator_rays(d: &Value, tolerance: f64) -> (usize, f64) {
    let (sites, vertices) = (d["sites"].as_array().unwrap(), d["vertices"].as_array().unwrap());
    let (mut rays, mut worst, scale) = (0, 0.0f64, scale_of(d));
    for e in d["edges"].as_array().unwrap().iter().filter(|e| e["separator"] == true) {
        let ends = e["ends"].as_array().unwrap();
        let (Some(v), Some(u)) = (ends.iter().find_map(|x| x.get("vertex")), ends.iter().find_map(|x| x.get("direction"))) else {
            continue;
        };
        let at = xy(&vertices[v.as_u64().unwrap() as usize]["position"]);
        let point =
            e["sites"].as_array().unwrap().iter().map(|s| &sites[s.as_u64().unwrap() as usize]).find(|s| s["kind"] == "point");
        let p = xy(&point.unwrap()["position"]);
        let u = xy(u);
        let off = (p[0] - at[0]) * u[1] - (p[1] - at[1]) * u[0];
        assert!(off.abs() <= tolerance * scale, "separator {e} misses its endpoint {p:?} by {off}");
        worst = worst.max(off.abs() / scale);
        rays += 1;
    }
    (rays, worst)
}

#[test]
fn diagram_json_of_points_and_segments() {
    let text = "MULTIPOINT ((0 0), (6 0), (3 5), (3 5))\nLINESTRING (1 -2, 5 -2, 6 -4)\nPOLYGON ((10 0, 14 0, 14 3, 10 0))\n";
    let (d, _) = diagram_of("mixed", text, &[]);
    assert_eq!(check_dump(&d), 0);
    let sites = d["sites"].as_array().unwrap();
    // the repeated point: one site for inputs 2 and 3
    assert!(sites.iter().any(|s| s["inputs"] == serde_json::json!([2, 3])));
    assert_eq!(sites.iter().filter(|s| s["kind"] == "segment").count(), 5);
    let edges = d["edges"].as_array().unwrap();
    assert!(edges.iter().any(|e| e["kind"] == "parabola") && edges.iter().any(|e| e["separator"] == true));
    assert!(check_separator_rays(&d, 1e-12).0 > 0);
    // the same counts as the topology text
    let input = input_file("mixed-topology.wkt", text);
    let o = run(&[input.to_str().unwrap(), "--topology"]);
    std::fs::remove_file(&input).unwrap();
    let topology = stdout(&o);
    let count = |section: &str| -> usize {
        let line = topology.lines().find(|l| l.starts_with(section)).unwrap();
        line[section.len() + 1..].parse().unwrap()
    };
    assert_eq!((count("EDGES"), count("FACES")), (edges.len(), d["vertices"].as_array().unwrap().len()));
}

#[test]
fn diagram_json_of_the_demo_and_boost_text() {
    let json = temp_path("demo.json");
    let o = run(&["--diagram", json.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let d: Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    std::fs::remove_file(&json).unwrap();
    check_dump(&d);
    assert!(d["vertices"].as_array().unwrap().len() > 20);
    assert!(o.stdout.is_empty(), "--diagram is an output: no summary");
}

/// Each curve type as the PostGIS manual writes it (`ST_AsText`), with the
/// arcs the program must make of it. The manual's COMPOUNDCURVE and
/// MULTICURVE touch themselves (a segment ends on the arc; a segment is
/// tangent to the arc inside both), which the library refuses (see
/// `postgis_examples_that_touch_are_refused_naming_both`): here their
/// segments go elsewhere or stop short.
const POSTGIS: [(&str, &str, usize); 6] = [
    ("circularstring", "CIRCULARSTRING(0 0, 1 1, 1 0)", 1),
    ("compoundcurve", "COMPOUNDCURVE(CIRCULARSTRING(0 0, 1 1, 1 0),(1 0, 0 -1))", 1),
    ("curvepolygon", "CURVEPOLYGON(CIRCULARSTRING(0 0, 4 0, 4 4, 0 4, 0 0),(1 1, 3 3, 3 1, 1 1))", 2),
    ("multicurve", "MULTICURVE((0 0, 3 3),CIRCULARSTRING(4 0, 4 4, 8 4))", 1),
    (
        "multisurface",
        "MULTISURFACE(CURVEPOLYGON(CIRCULARSTRING(0 0, 4 0, 4 4, 0 4, 0 0),(1 1, 3 3, 3 1, 1 1)),((10 10, 14 12, 11 10, 10 10),(11 11, 11.5 11, 11 11.5, 11 11)))",
        2,
    ),
    ("collection", "GEOMETRYCOLLECTION Z (POINT Z (9 9 1), CIRCULARSTRING Z (0 0 1, 1 1 1, 1 0 1))", 1),
];

#[test]
fn every_postgis_curve_type_builds() {
    if !arcs_build() {
        // the input reaches the builder: the library's own refusal, status 1
        for (name, wkt, _) in POSTGIS {
            let input = input_file(&format!("{name}-now.wkt"), wkt);
            let o = run(&[input.to_str().unwrap(), "--topology"]);
            std::fs::remove_file(&input).unwrap();
            assert_eq!(o.status.code(), Some(1), "{name}: {}", stderr(&o));
            assert!(stderr(&o).contains("under construction"), "{name}: {}", stderr(&o));
        }
        return;
    }
    for (name, wkt, arcs) in POSTGIS {
        let (d, _) = diagram_of(name, wkt, &[]);
        assert_eq!(check_dump(&d), arcs, "{name}");
    }
    // the arc of the first: through (1 1) from (0 0) to (1 0), clockwise
    let (d, _) = diagram_of("one-arc", POSTGIS[0].1, &[]);
    let arc = d["sites"].as_array().unwrap().iter().find(|s| s["kind"] == "arc").unwrap().clone();
    assert_eq!((xy(&arc["start"]), xy(&arc["end"]), xy(&arc["centre"])), ([0.0, 0.0], [1.0, 0.0], [0.5, 0.5]));
    assert_eq!((arc["ccw"].as_bool(), arc["input"].as_u64()), (Some(false), Some(0)));
}

#[test]
fn a_point_beside_an_arc() {
    if !arcs_build() {
        return; // waits for the library's build of arcs (see the module doc)
    }
    let (d, _) = diagram_of("point-above-arc", "POINT (0.5 3)\nCIRCULARSTRING (0 0, 0.5 0.5, 1 0)", &[]);
    assert_eq!(check_dump(&d), 1);
}

#[test]
fn arc_separator_rays_are_radii() {
    if !arcs_build() {
        return; // waits for the library's build of arcs (see the module doc)
    }
    for (name, wkt) in
        [("rounded-rays", ROUNDED_RECTANGLE), ("slot-rays", SLOT), ("arc-rays", "CIRCULARSTRING (0 2, 1 3, 2 2.5)")]
    {
        let (d, _) = diagram_of(name, wkt, &[]);
        assert!(check_separator_rays(&d, 1e-9).0 > 0, "{name}");
    }
}

/// A rounded rectangle, 10 by 6 with corners of radius 1, and a slot (two
/// half circles joined by two segments), as PostGIS writes them.
const ROUNDED_RECTANGLE: &str =
    "COMPOUNDCURVE((1 0, 9 0), CIRCULARSTRING(9 0, 9.707106781186548 0.2928932188134524, 10 1), (10 1, 10 5), \
     CIRCULARSTRING(10 5, 9.707106781186548 5.707106781186548, 9 6), (9 6, 1 6), \
     CIRCULARSTRING(1 6, 0.2928932188134524 5.707106781186548, 0 5), (0 5, 0 1), \
     CIRCULARSTRING(0 1, 0.2928932188134524 0.2928932188134524, 1 0))";
const SLOT: &str = "COMPOUNDCURVE((0 0, 4 0), CIRCULARSTRING(4 0, 5 1, 4 2), (4 2, 0 2), CIRCULARSTRING(0 2, -1 1, 0 0))";

/// A closed chain of `segments` segments and `arcs` arcs through the
/// program: the diagram, the topology text with VPAIRS, the statistics and
/// the picture; inside, the largest clearance at least `half_width`.
fn closed_chain_end_to_end(name: &str, wkt: &str, arcs: usize, segments: usize, half_width: f64) {
    let svg = temp_path(&format!("{name}.svg"));
    let (d, o) = diagram_of(name, wkt, &["--voronoi-pairs", "--stats", "--svg", svg.to_str().unwrap()]);
    assert_eq!(check_dump(&d), arcs, "{name}");
    assert!(check_separator_rays(&d, 1e-9).0 > 0, "{name}");
    let sites = d["sites"].as_array().unwrap();
    assert_eq!(sites.iter().filter(|s| s["kind"] == "segment").count(), segments, "{name}");
    // a closed chain: as many endpoints as pieces, shared exactly
    assert_eq!(sites.iter().filter(|s| s["kind"] == "point").count(), arcs + segments, "{name}");
    let topology = stdout(&o);
    for j in 0..arcs {
        assert!(topology.contains(&format!("A{j}")), "{name}: {topology}");
    }
    let faces = format!("FACES {}\n", d["vertices"].as_array().unwrap().len());
    assert!(topology.contains(&faces) && topology.contains("\nVPAIRS ") && topology.contains("\nVVERTICES "), "{topology}");
    assert!(stderr(&o).contains(&format!("arc_sites={arcs}")), "{}", stderr(&o));
    let picture = std::fs::read_to_string(&svg).unwrap();
    std::fs::remove_file(&svg).unwrap();
    assert!(picture.contains(r#"<g id="arcs""#) && picture.matches(" A ").count() >= arcs, "{name}");
    assert!(!picture.contains("NaN") && !picture.contains("inf"));
    let largest = d["vertices"].as_array().unwrap().iter().map(|v| v["clearance"].as_f64().unwrap()).fold(0.0, f64::max);
    assert!(largest >= half_width - 1e-9, "{name}: {largest}");
}

#[test]
fn a_slot_end_to_end() {
    if !arcs_build() {
        return; // waits for the library's build of arcs (see the module doc)
    }
    closed_chain_end_to_end("slot", SLOT, 2, 2, 1.0);
    // the same 2^24 from the origin
    let far = "COMPOUNDCURVE((16777216 16777216, 16777220 16777216), CIRCULARSTRING(16777220 16777216, 16777221 16777217, 16777220 16777218), \
               (16777220 16777218, 16777216 16777218), CIRCULARSTRING(16777216 16777218, 16777215 16777217, 16777216 16777216))";
    closed_chain_end_to_end("far-slot", far, 2, 2, 1.0);
}

#[test]
fn a_rounded_rectangle_end_to_end() {
    if !arcs_build() {
        return; // waits for the library's build of arcs (see the module doc)
    }
    closed_chain_end_to_end("rounded", ROUNDED_RECTANGLE, 4, 4, 3.0);
}

#[test]
fn a_segment_then_a_tangent_quarter_arc() {
    if !arcs_build() {
        return; // waits for the library's build of arcs (see the module doc)
    }
    // the rounded rectangle's first corner alone: the arc's middle point
    // rounded to f64, so the arc is tangent to the segment to an ulp
    let corner = "COMPOUNDCURVE((1 0, 9 0), CIRCULARSTRING(9 0, 9.707106781186548 0.2928932188134524, 10 1))";
    let (d, _) = diagram_of("corner", corner, &[]);
    assert_eq!(check_dump(&d), 1);
}

#[test]
fn a_full_circle_is_two_half_arcs() {
    if !arcs_build() {
        return; // waits for the library's build of arcs (see the module doc)
    }
    let (d, _) = diagram_of("circle", "CIRCULARSTRING(1 0, 3 0, 1 0)\nPOINT(2.5 0.25)\n", &[]);
    assert_eq!(check_dump(&d), 2);
    let arcs: Vec<&Value> = d["sites"].as_array().unwrap().iter().filter(|s| s["kind"] == "arc").collect();
    for arc in arcs {
        assert_eq!((xy(&arc["centre"]), arc["radius"].as_f64(), arc["bulge"].as_f64()), ([2.0, 0.0], Some(1.0), Some(1.0)));
    }
}

#[test]
fn postgis_examples_that_touch_are_refused_naming_both() {
    if !arcs_build() {
        return; // waits for the library's build of arcs (see the module doc)
    }
    for (name, wkt, place, why) in [
        (
            "touching-compoundcurve",
            "COMPOUNDCURVE(CIRCULARSTRING(0 0, 1 1, 1 0),(1 0, 0 1))",
            "  segment 0, geometry 0 (a curve): (1, 0) - (0, 1)",
            "an end of the segment lies inside the arc",
        ),
        (
            "touching-multicurve",
            "MULTICURVE((0 0, 5 5),CIRCULARSTRING(4 0, 4 4, 8 4))",
            "  segment 0, geometry 0 (a linestring): (0, 0) - (5, 5)",
            "tangent",
        ),
    ] {
        let input = input_file(&format!("{name}.wkt"), wkt);
        let o = run(&[input.to_str().unwrap(), "--topology"]);
        std::fs::remove_file(&input).unwrap();
        assert_eq!(o.status.code(), Some(1), "{name}: {}", stderr(&o));
        let message = stderr(&o);
        assert!(message.contains("arc 0 and segment 0 touch") && message.contains(why), "{name}: {message}");
        assert!(message.contains("\n  arc 0, geometry ") && message.contains(place), "{name}: {message}");
        assert!(o.stdout.is_empty());
    }
}

#[test]
fn open_curves_are_obstacles_and_write_sites_is_refused() {
    // the slot's outline as a COMPOUNDCURVE: an obstacle, not a domain
    let input = input_file("obstacle.wkt", SLOT);
    let out = temp_path("obstacle-out.json");
    let path = out.to_str().unwrap();
    let run_with = |args: &[&str]| {
        let mut all = vec![input.to_str().unwrap()];
        all.extend_from_slice(args);
        run(&all)
    };
    // grown: the band around the outline, 14.283... (the grown slot less the shrunk one)
    let o = run_with(&["--offset", "0.5", "--offsets", path]);
    assert!(o.status.success(), "{}", stderr(&o));
    let offsets: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let area = offsets["offsets"][0]["area"].as_f64().unwrap();
    let expected = (3.0 * 4.0 + std::f64::consts::PI * 2.25) - (4.0 + std::f64::consts::PI * 0.25);
    assert!((area - expected).abs() < 1e-9 * expected, "{area} vs {expected}");
    std::fs::remove_file(&out).unwrap();
    let o = run_with(&["--medial-axis", path, "--corner-angle", "30", "--prune-spurs", "1"]);
    assert!(o.status.success(), "{}", stderr(&o));
    // what needs a domain, or has no arcs, says so and writes nothing
    for (args, words) in [
        (&["--max-inscribed-circle"][..], &["--max-inscribed-circle needs a polygon"][..]),
        (&["--offset=-0.5", "--offsets", path], &["negative", "no domain"]),
        (&["--write-sites", path], &["--write-sites", "circular arcs"]),
    ] {
        std::fs::remove_file(&out).ok();
        let o = run_with(args);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {}", stderr(&o));
        let message = stderr(&o);
        assert!(words.iter().all(|w| message.contains(w)), "{message}");
        assert!(!out.exists(), "{args:?} wrote a file");
    }
    std::fs::remove_file(&input).unwrap();
}

#[test]
fn curve_errors_name_the_geometry_and_position() {
    for (wkt, line, column, words) in [
        ("POINT (0 0)\nCIRCULARSTRING (0 0, 1 1, 2 0, 3 0)", 2, 1, &["CIRCULARSTRING", "3, 5, 7", "this one 4"][..]),
        ("COMPOUNDCURVE ((0 0, 1 0), CIRCULARSTRING (2 0, 3 1, 4 0))", 1, 28, &["piece 1", "(2 0)", "piece 0 ends (1 0)"]),
        ("CURVEPOLYGON (CIRCULARSTRING (0 0, 1 1, 2 0))", 1, 15, &["ring 0 of this CURVEPOLYGON is not closed"]),
        ("MULTICURVE ((0 0, 1 1), CIRCULARSTRING (0 0, 5 5, 1 1))", 1, 41, &["arc 0", "on one line"]),
    ] {
        let input = input_file("bad-curve.wkt", wkt);
        let o = run(&[input.to_str().unwrap()]);
        std::fs::remove_file(&input).unwrap();
        assert_eq!(o.status.code(), Some(2), "{wkt}: {}", stderr(&o));
        let message = stderr(&o);
        assert!(message.contains(&format!("line {line}, column {column}:")), "{wkt}: {message}");
        for word in words {
            assert!(message.contains(word), "{wkt}: {message}");
        }
        assert!(message.contains("near: "), "{message}");
    }
}

#[test]
fn curves_without_arcs_are_lines_and_polygons() {
    // collinear CIRCULARSTRING points: a segment; a CURVEPOLYGON of
    // straight rings: a domain, with its medial axis
    let input = input_file("straight.wkt", "CURVEPOLYGON ((0 0, 4 0, 4 2, 0 2, 0 0))\nCIRCULARSTRING (6 0, 7 1, 8 2)\n");
    let axis = temp_path("straight-axis.wkt");
    let o = run(&[input.to_str().unwrap(), "--medial-axis", axis.to_str().unwrap(), "--stats"]);
    std::fs::remove_file(&input).unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("input_segments=5") && stderr(&o).contains("arc_sites=0"), "{}", stderr(&o));
    let text = std::fs::read_to_string(&axis).unwrap();
    std::fs::remove_file(&axis).unwrap();
    assert!(text.starts_with("MULTILINESTRING Z ("), "{text}");
}

#[test]
fn an_ewkt_parcel_far_from_the_origin() {
    if !arcs_build() {
        return; // waits for the library's build of arcs (see the module doc)
    }
    // a parcel with two rounded corners in Swiss LV95 coordinates, as
    // PostGIS's ST_AsEWKT writes it (the points on the arcs to the mm)
    let parcel = "SRID=2056;CURVEPOLYGON(COMPOUNDCURVE((2600000.0 1200000.0,2600040.5 1200000.0),\
        CIRCULARSTRING(2600040.5 1200000.0,2600047.571 1200002.929,2600050.5 1200010.0),\
        (2600050.5 1200010.0,2600050.5 1200030.25,2600010.0 1200030.25),\
        CIRCULARSTRING(2600010.0 1200030.25,2600002.929 1200027.321,2600000.0 1200020.25),\
        (2600000.0 1200020.25,2600000.0 1200000.0)))\nSRID=2056;POINT(2600025.0 1200015.0)\n";
    let (d, o) = diagram_of("parcel", parcel, &["--stats"]);
    assert_eq!(check_dump(&d), 2);
    assert!(stderr(&o).contains("input_srid=2056") && stderr(&o).contains("segment_sites=4"), "{}", stderr(&o));
    // the corner arcs' circles: radius about 10 around the corners' centres
    for arc in d["sites"].as_array().unwrap().iter().filter(|s| s["kind"] == "arc") {
        assert!((arc["radius"].as_f64().unwrap() - 10.0).abs() < 1e-3, "{arc}");
        assert_eq!(arc["ccw"].as_bool(), Some(true), "{arc}");
    }
}

/// A grid of 6 × 6 cells, each with an arc of a random circle inside it
/// (any sweep, either way), a point or a segment, from a small linear
/// congruential generator: inputs nobody tuned for.
fn random_grid(seed: u64) -> String {
    let mut state = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    let mut uniform = |low: f64, high: f64| {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        low + (high - low) * ((state >> 11) as f64 / (1u64 << 53) as f64)
    };
    let mut text = String::new();
    for i in 0..6 {
        for j in 0..6 {
            let (x, y) = (f64::from(i) * 10.0, f64::from(j) * 10.0);
            match uniform(0.0, 1.0) {
                k if k < 0.6 => {
                    let (r, a0) = (uniform(1.0, 4.0), uniform(0.0, std::f64::consts::TAU));
                    let sweep = uniform(0.3, 5.5) * if uniform(0.0, 1.0) < 0.5 { -1.0 } else { 1.0 };
                    let at = |t: f64| {
                        let a = a0 + t * sweep;
                        format!("{:.6} {:.6}", x + 5.0 + r * a.cos(), y + 5.0 + r * a.sin())
                    };
                    text += &format!("CIRCULARSTRING({}, {}, {})\n", at(0.0), at(0.5), at(1.0));
                }
                k if k < 0.8 => text += &format!("POINT({:.4} {:.4})\n", x + uniform(1.0, 9.0), y + uniform(1.0, 9.0)),
                _ => {
                    let (a, b) = ((x + uniform(1.0, 4.0), y + uniform(1.0, 9.0)), (x + uniform(6.0, 9.0), y + uniform(1.0, 9.0)));
                    text += &format!("LINESTRING({:.4} {:.4}, {:.4} {:.4})\n", a.0, a.1, b.0, b.1);
                }
            }
        }
    }
    text
}

#[test]
fn random_grids_of_arcs_points_and_segments() {
    if !arcs_build() {
        return; // waits for the library's build of arcs (see the module doc)
    }
    for seed in 0..40 {
        let svg = temp_path(&format!("grid-{seed}.svg"));
        let (d, o) = diagram_of(&format!("grid-{seed}"), &random_grid(seed), &["--topology", "--svg", svg.to_str().unwrap()]);
        let arcs = check_dump(&d);
        assert!(arcs > 10, "seed {seed}: {arcs} arcs");
        // The library's vertices of an endpoint, its segment and an arc
        // stray from the segment's perpendicular by up to about 1e-9 of
        // the input's scale here (seeds 16, 20 and 24; the rest 1e-11 or
        // far less): a coarse bound, and the figure on standard error.
        let (_, worst) = check_separator_rays(&d, 1e-6);
        eprintln!("seed {seed}: separator rays miss their endpoints by {worst:.1e} of the scale at most");
        let faces = format!("FACES {}\n", d["vertices"].as_array().unwrap().len());
        assert!(stdout(&o).contains(&faces), "seed {seed}");
        let picture = std::fs::read_to_string(&svg).unwrap();
        std::fs::remove_file(&svg).unwrap();
        assert!(picture.matches(" A ").count() >= arcs && !picture.contains("NaN"), "seed {seed}");
    }
}
