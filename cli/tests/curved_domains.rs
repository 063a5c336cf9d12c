//! Domains bounded by circular arcs (issue 32), run as a user would: a
//! slot, a rounded rectangle with a round hole and a filleted L, as WKT
//! `CURVEPOLYGON`s and as DXF closed LWPOLYLINEs with bulges. The largest
//! inscribed circle and the offsets' areas against their analytic values
//! (or the library's own build of the shape with 256 chords per arc); the
//! medial axis's clearance against the distance to the boundary, computed
//! here; the offsets' arcs in curved WKT, DXF and G-code read back.

mod common;

use std::f64::consts::PI;
use std::path::{Path, PathBuf};

use common::*;
use dxf::entities::EntityType;
use dxf::enums::AcadVersion;
use dxf::{Drawing, Point as DxfPoint};
use serde_json::Value;

/// A ring as DXF's LWPOLYLINE holds it: each vertex with the bulge of the
/// piece from it to the next (0: a segment), closed.
type Ring = Vec<([f64; 2], f64)>;

/// One piece of a ring: start, end, bulge.
fn pieces(ring: &Ring) -> Vec<([f64; 2], [f64; 2], f64)> {
    (0..ring.len()).map(|k| (ring[k].0, ring[(k + 1) % ring.len()].0, ring[k].1)).collect()
}

/// The point halfway along the arc from `s` to `e` with bulge `b` (as
/// `CircularArc::midpoint` has it), and its centre.
fn arc_middle_and_centre(s: [f64; 2], e: [f64; 2], b: f64) -> ([f64; 2], [f64; 2]) {
    let (dx, dy) = (e[0] - s[0], e[1] - s[1]);
    let half = [0.5 * (s[0] + e[0]), 0.5 * (s[1] + e[1])];
    let k = (1.0 - b * b) / (4.0 * b);
    ([half[0] + 0.5 * b * dy, half[1] - 0.5 * b * dx], [half[0] - k * dy, half[1] + k * dx])
}

/// The same ring the other way round.
fn reversed(ring: &Ring) -> Ring {
    pieces(ring).iter().rev().map(|&(_, e, b)| (e, -b)).collect()
}

/// The ring mirrored in the y axis (which turns its arcs the other way).
fn mirrored(ring: &Ring) -> Ring {
    ring.iter().map(|&([x, y], b)| ([-x, y], -b)).collect()
}

fn wkt_xy(p: [f64; 2]) -> String {
    format!("{} {}", p[0], p[1])
}

/// The rings as one WKT `CURVEPOLYGON` of `COMPOUNDCURVE`s, an arc a
/// `CIRCULARSTRING` through its middle.
fn curvepolygon(rings: &[Ring]) -> String {
    let rings: Vec<String> = rings
        .iter()
        .map(|ring| {
            let members: Vec<String> = pieces(ring)
                .iter()
                .map(|&(s, e, b)| {
                    if b == 0.0 {
                        format!("({}, {})", wkt_xy(s), wkt_xy(e))
                    } else {
                        let (m, _) = arc_middle_and_centre(s, e, b);
                        format!("CIRCULARSTRING({}, {}, {})", wkt_xy(s), wkt_xy(m), wkt_xy(e))
                    }
                })
                .collect();
            format!("COMPOUNDCURVE({})", members.join(", "))
        })
        .collect();
    format!("CURVEPOLYGON({})\n", rings.join(", "))
}

fn write_input(name: &str, text: &str) -> PathBuf {
    let path = temp_path(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// The rings as a DXF drawing, a closed LWPOLYLINE each.
fn dxf_input(name: &str, rings: &[Ring]) -> PathBuf {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    for ring in rings {
        let vertices: Vec<(f64, f64, f64)> = ring.iter().map(|&([x, y], b)| (x, y, b)).collect();
        d.add_entity(lwpolyline(&vertices, "PART"));
    }
    save(&d, name)
}

/// The distance from `p` to the rings' segments and arcs.
fn boundary_distance(p: [f64; 2], rings: &[Ring]) -> f64 {
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    let mut best = f64::INFINITY;
    for (s, e, b) in rings.iter().flat_map(pieces) {
        let d = if b == 0.0 {
            segment_distance(p, s, e)
        } else {
            let (m, c) = arc_middle_and_centre(s, e, b);
            let r = (s[0] - c[0]).hypot(s[1] - c[1]);
            let to = (p[0] - c[0]).hypot(p[1] - c[1]);
            // the circle's point nearest `p` is on the arc when it is on the
            // middle's side of the chord
            let q = [c[0] + r * (p[0] - c[0]) / to, c[1] + r * (p[1] - c[1]) / to];
            let ends = (p[0] - s[0]).hypot(p[1] - s[1]).min((p[0] - e[0]).hypot(p[1] - e[1]));
            if to > 0.0 && cross(s, e, q) * cross(s, e, m) > 0.0 {
                (to - r).abs().min(ends)
            } else {
                ends
            }
        };
        best = best.min(d);
    }
    best
}

/// The rings with each arc cut into 256 chords.
fn chords(rings: &[Ring]) -> Vec<Vec<[f64; 2]>> {
    rings
        .iter()
        .map(|ring| {
            let mut points = Vec::new();
            for (s, e, b) in pieces(ring) {
                points.push(s);
                if b != 0.0 {
                    let (_, c) = arc_middle_and_centre(s, e, b);
                    let (r, start, sweep) = ((s[0] - c[0]).hypot(s[1] - c[1]), (s[1] - c[1]).atan2(s[0] - c[0]), 4.0 * b.atan());
                    for k in 1..256 {
                        let a = start + sweep * k as f64 / 256.0;
                        points.push([c[0] + r * a.cos(), c[1] + r * a.sin()]);
                    }
                }
            }
            points
        })
        .collect()
}

/// The slot: two half circles of radius `r` around (0, 0) and (`length`, 0)
/// joined by two sides.
fn slot(length: f64, r: f64) -> Ring {
    vec![([0.0, -r], 0.0), ([length, -r], 1.0), ([length, r], 0.0), ([0.0, r], 1.0)]
}

/// A `width` × `height` rectangle at `corner` with corners of radius `r`.
fn rounded_rectangle(corner: [f64; 2], width: f64, height: f64, r: f64) -> Ring {
    let q = (PI / 8.0).tan();
    let [x0, y0] = corner;
    let (x1, y1) = (x0 + width, y0 + height);
    vec![
        ([x0 + r, y0], 0.0),
        ([x1 - r, y0], q),
        ([x1, y0 + r], 0.0),
        ([x1, y1 - r], q),
        ([x1 - r, y1], 0.0),
        ([x0 + r, y1], q),
        ([x0, y1 - r], 0.0),
        ([x0, y0 + r], q),
    ]
}

/// A circle of radius `r` around `c`, counter-clockwise: two half circles.
fn circle(c: [f64; 2], r: f64) -> Ring {
    vec![([c[0] + r, c[1]], 1.0), ([c[0] - r, c[1]], 1.0)]
}

/// An L of arms 10 long and 4 wide with its inner corner at (4, 4)
/// rounded by a fillet of radius 1 (the domain outside its circle).
fn filleted_l() -> Ring {
    let q = (PI / 8.0).tan();
    vec![
        ([0.0, 0.0], 0.0),
        ([10.0, 0.0], 0.0),
        ([10.0, 4.0], 0.0),
        ([5.0, 4.0], -q),
        ([4.0, 5.0], 0.0),
        ([4.0, 10.0], 0.0),
        ([0.0, 10.0], 0.0),
    ]
}

/// The program's largest inscribed circle: centre and radius.
fn inscribed_circle(input: &Path) -> ([f64; 2], f64) {
    let o = run(&[path_str(input), "--max-inscribed-circle"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Vec<f64> = stdout(&o).split_whitespace().map(|v| v.parse().unwrap()).collect();
    ([v[0], v[1]], v[2])
}

/// The areas of the program's exact offsets.
fn offset_areas(input: &Path, distances: &[&str], name: &str) -> Vec<f64> {
    let exact = exact_offsets(input, distances, name);
    exact["offsets"].as_array().unwrap().iter().map(|o| o["area"].as_f64().unwrap()).collect()
}

/// The medial axis's samples (`--medial-axis OUT.wkt`): each point's
/// clearance is its distance to the boundary, and no point is nearer the
/// boundary than `least` (a branch into a tangent joint would end on the
/// boundary). Returns the chains.
fn check_axis(input: &Path, rings: &[Ring], least: f64, name: &str) -> Vec<Vec<[f64; 3]>> {
    let out = temp_path(name);
    let o = run(&[path_str(input), "--medial-axis", path_str(&out), "--tolerance", "1e-4"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let chains = multilinestring_z(&std::fs::read_to_string(&out).unwrap());
    assert!(!chains.is_empty());
    for &[x, y, z] in chains.iter().flatten() {
        let d = boundary_distance([x, y], rings);
        assert!((d - z).abs() < 1e-7, "{name}: ({x}, {y}) has clearance {z}, distance {d}");
        assert!(z >= least - 1e-9, "{name}: ({x}, {y}) at {z} from the boundary");
    }
    chains
}

fn close_to(a: f64, b: f64, relative: f64) -> bool {
    (a - b).abs() <= relative * b.abs()
}

#[test]
fn a_slot_as_wkt_and_as_dxf() {
    let (length, r) = (7.0, 1.25);
    let rings = [slot(length, r)];
    let wkt = write_input("slot.wkt", &curvepolygon(&rings));
    let dxf = dxf_input("slot.dxf", &rings);
    for input in [&wkt, &dxf] {
        let (centre, radius) = inscribed_circle(input);
        assert!((radius - r).abs() < 1e-12 && centre[1].abs() < 1e-12, "{centre:?} {radius}");
        assert!((-1e-12..=length + 1e-12).contains(&centre[0]), "{centre:?}");
        // shrunk and grown: the slot of radius r ∓ d
        let areas = offset_areas(input, &["-0.5", "0.75"], "slot-exact.json");
        for (area, d) in areas.iter().zip([-0.5, 0.75]) {
            let expected = length * 2.0 * (r + d) + PI * (r + d) * (r + d);
            assert!(close_to(*area, expected, 1e-12), "{area} vs {expected}");
        }
        // the axis: one segment between the arcs' centres, at clearance r
        let chains = check_axis(input, &rings, r, "slot-axis.wkt");
        let points: Vec<[f64; 3]> = chains.concat();
        assert!(points.iter().all(|p| p[1].abs() < 1e-12 && (p[2] - r).abs() < 1e-12), "{chains:?}");
        let (low, high) = points.iter().fold((f64::MAX, f64::MIN), |(l, h), p| (l.min(p[0]), h.max(p[0])));
        assert!(low.abs() < 1e-12 && (high - length).abs() < 1e-12, "{chains:?}");
    }
}

#[test]
fn a_slot_of_lines_and_arcs_is_a_domain() {
    // as a CAD program draws it piece by piece: two LINEs and two ARCs
    // (counter-clockwise, in degrees), in no order, a LINE backwards, and
    // a circular hole of two ARCs
    let (length, r) = (7.0, 1.25);
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    let arc = |c: [f64; 2], r: f64, from: f64, to: f64| {
        on_layer(EntityType::Arc(dxf::entities::Arc::new(DxfPoint::new(c[0], c[1], 0.0), r, from, to)), "PART")
    };
    d.add_entity(arc([length, 0.0], r, 270.0, 90.0));
    d.add_entity(line([0.0, r], [length, r], "PART"));
    d.add_entity(arc([0.0, 0.0], r, 90.0, 270.0));
    d.add_entity(line([length, -r], [0.0, -r], "PART"));
    d.add_entity(arc([3.5, 0.0], 0.5, 0.0, 180.0));
    d.add_entity(arc([3.5, 0.0], 0.5, 180.0, 360.0));
    let input = save(&d, "slot-pieces.dxf");
    let o = run(&[path_str(&input), "--max-inscribed-circle", "--stats"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Vec<f64> = stdout(&o).split_whitespace().map(|v| v.parse().unwrap()).collect();
    // the hole leaves room for the full width: r (anywhere on the axis
    // from (5.25, 0) to (7, 0), or its mirror)
    assert!((v[2] - r).abs() < 1e-12 && v[1].abs() < 1e-12 && (v[0] - 3.5).abs() >= 1.75 - 1e-12, "{v:?}");
    let area = offset_areas(&input, &["-0.2"], "slot-pieces.json")[0];
    let expected = length * 2.0 * (r - 0.2) + PI * (r - 0.2) * (r - 0.2) - PI * 0.7 * 0.7;
    assert!(close_to(area, expected, 1e-12), "{area} vs {expected}");
}

#[test]
fn a_rounded_rectangle_with_a_round_hole_any_way_round() {
    // 12 × 7 at (3, 2) with corners of radius 1.5, a hole of radius 1.2
    let (width, height, corner, hole) = (12.0, 7.0, 1.5, 1.2);
    let shape = [rounded_rectangle([3.0, 2.0], width, height, corner), circle([7.0, 5.5], hole)];
    let area =
        |d: f64| (width + 2.0 * d) * (height + 2.0 * d) - (4.0 - PI) * (corner + d) * (corner + d) - PI * (hole - d) * (hole - d);
    let distances = ["-0.4", "0.6"];
    let mut circles = Vec::new();
    for (name, rings) in [
        ("as-drawn", shape.to_vec()),
        ("reversed", shape.iter().map(reversed).collect()),
        ("mirrored", shape.iter().map(mirrored).collect()),
        ("holes-first", vec![reversed(&shape[1]), mirrored(&mirrored(&shape[0]))]),
    ] {
        for input in [write_input(&format!("{name}.wkt"), &curvepolygon(&rings)), dxf_input(&format!("{name}.dxf"), &rings)] {
            let areas = offset_areas(&input, &distances, "rounded-exact.json");
            for (got, d) in areas.iter().zip([-0.4, 0.6]) {
                assert!(close_to(*got, area(d), 1e-12), "{name}: {got} vs {}", area(d));
            }
            // the axis stays off the boundary: its branches end at the
            // corners' centres, not at the tangent joints; nearest it
            // between the hole and the long sides
            let chains = check_axis(&input, &rings, 1e-3, "rounded-axis.wkt");
            let least = chains.iter().flatten().fold(f64::MAX, |m, p| m.min(p[2]));
            let expected = corner.min((height / 2.0 - hole) / 2.0);
            // (sampled within 1e-4: the samples miss the least by a little)
            assert!(least >= expected - 1e-9 && least < expected + 1e-3, "{name}: the axis comes within {least} of the boundary");
            circles.push(inscribed_circle(&input).1);
        }
    }
    // the same largest circle whichever way round or mirrored
    assert!(circles.iter().all(|&r| (r - circles[0]).abs() < 1e-12), "{circles:?}");
    // right of the hole, touching it, the right side and the top (or the
    // bottom): with the centre (15 − r, 5.5 ± (3.5 − r)),
    // (8 − r)² + (3.5 − r)² = (r + 1.2)², r² − 25.4 r + 74.81 = 0
    let r = (25.4 - (25.4f64 * 25.4 - 4.0 * 74.81).sqrt()) / 2.0;
    assert!((circles[0] - r).abs() < 1e-9, "{circles:?} vs {r}");
}

#[test]
fn a_filleted_l() {
    let rings = [filleted_l()];
    let wkt = write_input("l.wkt", &curvepolygon(&rings));
    // the largest circle touches both outer sides and the fillet:
    // t = √2 (5 − t) − 1
    let t = (5.0 * 2f64.sqrt() - 1.0) / (1.0 + 2f64.sqrt());
    let (centre, radius) = inscribed_circle(&wkt);
    assert!((radius - t).abs() < 1e-9 && (centre[0] - t).abs() < 1e-9 && (centre[1] - t).abs() < 1e-9, "{centre:?} {radius}");
    // the areas against the library's own 256-chord build
    let distances = [-0.5, -1.5, 0.8];
    let areas = offset_areas(&wkt, &["-0.5", "-1.5", "0.8"], "l-exact.json");
    let mut b = segvoronoi::Builder::new();
    b.add_polygon(&chords(&rings)).unwrap();
    let chorded = b.build().unwrap().offsets(&distances).unwrap();
    for ((got, expected), d) in areas.iter().zip(&chorded).zip(distances) {
        assert!(close_to(*got, expected.area(), 1e-4), "{d}: {got} vs {}", expected.area());
    }
    // the axis: the clearance is the distance to the boundary, also along
    // its conic pieces beside the fillet; no branch ends at the fillet's
    // tangent joints (5, 4) and (4, 5), only at the L's six corners
    let chains = check_axis(&wkt, &rings, 0.0, "l-axis.wkt");
    for joint in [[5.0, 4.0], [4.0, 5.0]] {
        assert!(chains.iter().flatten().all(|p| (p[0] - joint[0]).hypot(p[1] - joint[1]) > 0.5), "{chains:?}");
    }
    let leaves: Vec<[f64; 3]> = chains.iter().flat_map(|c| [c[0], c[c.len() - 1]]).filter(|p| p[2] < 1e-9).collect();
    let corners = [[0.0, 0.0], [10.0, 0.0], [10.0, 4.0], [4.0, 10.0], [0.0, 10.0]];
    assert!(leaves.iter().all(|p| corners.iter().any(|c| (p[0] - c[0]).hypot(p[1] - c[1]) < 1e-9)), "{leaves:?}");
    // the JSON names the conic pieces and their sites
    let out = temp_path("l-axis.json");
    let o = run(&[path_str(&wkt), "--medial-axis", path_str(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let axis: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let mut conics = 0;
    for conic in axis["chains"].as_array().unwrap().iter().flat_map(|c| c["pieces"].as_array().unwrap()) {
        if conic["kind"] != "conic" {
            continue;
        }
        conics += 1;
        let kinds: Vec<&str> = conic["sites"].as_array().unwrap().iter().map(|s| s["kind"].as_str().unwrap()).collect();
        assert!(kinds.contains(&"arc"), "{conic}");
        if let Some(bezier) = conic.get("bezier") {
            let points = bezier["points"].as_array().unwrap();
            assert_eq!((xy(&points[0]), xy(&points[2])), (xy(&conic["ends"][0]["point"]), xy(&conic["ends"][1]["point"])));
        }
    }
    assert!(conics > 0, "{axis}");
}

/// The area of a WKT `MULTISURFACE` line of `--curves` from its pieces:
/// each ring's polygon of piece ends plus, for each `CIRCULARSTRING`, the
/// circular segment between its chord and its arc; and the count of
/// `CIRCULARSTRING`s.
fn curved_area(line: &str) -> (f64, usize) {
    let cross = |a: [f64; 2], b: [f64; 2]| a[0] * b[1] - a[1] * b[0];
    let mut area = 0.0;
    let mut arcs = 0;
    let point = |t: &str| -> [f64; 2] {
        let v: Vec<f64> = t.split_whitespace().map(|w| w.parse().unwrap()).collect();
        [v[0], v[1]]
    };
    // one member a time: `CIRCULARSTRING (a, m, b` or `(a, b, ...`
    for member in line.split(['(', ')']).map(str::trim).filter(|m| m.starts_with(|c: char| c.is_ascii_digit() || c == '-')) {
        let points: Vec<[f64; 2]> = member.split(',').map(point).collect();
        for w in points.windows(2) {
            area += cross(w[0], w[1]) / 2.0;
        }
        let before = line[..line.find(member).unwrap()].trim_end_matches([' ', '(']);
        if before.ends_with("CIRCULARSTRING") {
            arcs += 1;
            let [a, m, b] = [points[0], points[1], points[2]];
            // undo the chord through the middle, add the circular segment
            area -= (cross(a, m) + cross(m, b) - cross(a, b)) / 2.0;
            let ab = (b[0] - a[0]).hypot(b[1] - a[1]);
            let turn = (m[0] - a[0]) * (b[1] - a[1]) - (m[1] - a[1]) * (b[0] - a[0]);
            let (am, mb) = ((m[0] - a[0]).hypot(m[1] - a[1]), (b[0] - m[0]).hypot(b[1] - m[1]));
            let r = am * mb * ab / (2.0 * turn.abs());
            // the half sweep: the chord subtends twice the angle at m's supplement
            let sweep = 2.0 * (ab / (2.0 * r)).min(1.0).asin();
            let minor = (am * am + mb * mb) < ab * ab; // the angle at m is obtuse
            let sweep = if minor { sweep } else { 2.0 * PI - sweep };
            let segment = r * r / 2.0 * (sweep - sweep.sin());
            // m on the right of a→b: the arc bulges that way, counter-clockwise
            area += if turn > 0.0 { segment } else { -segment };
        }
    }
    (area, arcs)
}

#[test]
fn offsets_of_curved_domains_as_curved_wkt_dxf_and_gcode() {
    let rings = [rounded_rectangle([3.0, 2.0], 12.0, 7.0, 1.5), circle([7.0, 5.5], 1.2)];
    let input = dxf_input("plate.dxf", &rings);
    let distances = ["-0.4", "0.6", "-1.7"];
    let exact = exact_offsets(&input, &distances, "plate-exact.json");
    let offsets = exact["offsets"].as_array().unwrap();

    // curved WKT: the arcs of the corners and the hole as CIRCULARSTRINGs,
    // the area from the pieces the library's, and the program reads it back
    let wkt = temp_path("plate-offsets.wkt");
    let args: Vec<String> = distances.iter().map(|d| format!("--offset={d}")).collect();
    let mut all: Vec<&str> = vec![path_str(&input), "--offsets", path_str(&wkt), "--curves"];
    all.extend(args.iter().map(String::as_str));
    let o = run(&all);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&wkt).unwrap();
    assert_eq!(text.lines().count(), distances.len());
    let mut total_arcs = 0;
    for (line, offset) in text.lines().zip(offsets) {
        let (area, arcs) = curved_area(line);
        let expected = offset["area"].as_f64().unwrap();
        assert!(close_to(area, expected, 1e-9), "{area} vs {expected}: {line}");
        // the hole's arcs at least; four corners and the hole beside
        assert!(arcs >= 2, "{arcs} arcs: {line}");
        total_arcs += arcs;
        let back = write_input("plate-offset.wkt", line);
        let again = offset_areas(&back, &["-0.01"], "plate-again.json");
        assert!(again[0] < expected && again[0] > 0.9 * expected, "{} vs {expected}", again[0]);
    }
    // at -0.4 and 0.6 the four corners and two halves of the hole; at
    // -1.7 the corners are sharp
    assert!(total_arcs >= 14, "{total_arcs}: {text}");

    // DXF: a closed LWPOLYLINE per loop, the loops' own vertices, bulges
    let out = temp_path("plate-offsets.dxf");
    let mut all: Vec<&str> = vec![path_str(&input), "--offsets", path_str(&out)];
    all.extend(args.iter().map(String::as_str));
    let o = run(&all);
    assert!(o.status.success(), "{}", stderr(&o));
    let drawing = Drawing::load_file(&out).unwrap();
    let loops: Vec<&Value> = offsets.iter().flat_map(|o| o["loops"].as_array().unwrap()).collect();
    let entities: Vec<&dxf::entities::Entity> = drawing.entities().collect();
    assert_eq!(entities.len(), loops.len());
    let mut bulges = 0;
    for (entity, lp) in entities.iter().zip(&loops) {
        let pieces = json_pieces(lp);
        match &entity.specific {
            EntityType::LwPolyline(p) => {
                assert!(p.is_closed());
                assert_eq!(p.vertices.len(), pieces.len());
                for (v, piece) in p.vertices.iter().zip(&pieces) {
                    let (Piece::Line { from, .. } | Piece::Arc { from, .. }) = *piece;
                    assert_eq!([v.x, v.y], from);
                    let b = expected_bulge(piece);
                    assert!((v.bulge - b).abs() <= 1e-12 * b.abs().max(1.0), "{} vs {b}", v.bulge);
                    bulges += usize::from(b != 0.0);
                }
            }
            // the hole grown from a circle
            EntityType::Circle(c) => assert!(
                matches!(pieces[..], [Piece::Arc { .. }, Piece::Arc { .. }])
                    && (c.center.x - 7.0).abs() < 1e-12
                    && (c.center.y - 5.5).abs() < 1e-12
            ),
            other => panic!("{other:?}"),
        }
    }
    assert!(bulges >= 8, "{bulges}");
    // and the drawing read back as input: the same region
    let again = offset_areas(&out, &["-0.01"], "plate-dxf-again.json");
    assert!(again[0] > 0.0, "{again:?}");

    // G-code: every loop cut once, its arcs G2/G3 around their centres
    let nc = temp_path("plate.nc");
    let mut all: Vec<&str> = vec![path_str(&input), "--offsets", path_str(&nc)];
    all.extend(args.iter().map(String::as_str));
    let o = run(&all);
    assert!(o.status.success(), "{}", stderr(&o));
    let cut = parse_gcode(&std::fs::read_to_string(&nc).unwrap(), "G1 Z-1 F100");
    assert_eq!(cut.len(), loops.len());
    let mut arcs = 0;
    for c in &cut {
        let offset = offsets.iter().find(|o| o["distance"].as_f64() == Some(c.distance)).unwrap();
        let expected = json_pieces(&offset["loops"][c.index]);
        assert_eq!(c.pieces.len(), expected.len());
        for (got, want) in c.pieces.iter().zip(&expected) {
            // a piece's end and the next one's start may differ in the
            // last bit: the G-code's piece starts where the one before ends
            match (got, want) {
                (Piece::Line { from: a, to: b }, Piece::Line { from: c, to: d }) => {
                    assert!(close(*a, *c, 10.0) && close(*b, *d, 10.0), "{got:?} vs {want:?}")
                }
                // a sliver of an arc (where the loop passes a tangent
                // joint) is cut as its chord
                (Piece::Line { from: a, to: b }, Piece::Arc { from: e, to: f, .. }) if close(*e, *f, 10.0) => {
                    assert!(close(*a, *e, 10.0) && close(*b, *f, 10.0), "{got:?} vs {want:?}")
                }
                (Piece::Arc { from: a, to: b, centre: c, ccw: x }, Piece::Arc { from: e, to: f, centre: g, ccw: y }) => {
                    assert!(close(*a, *e, 10.0) && close(*b, *f, 10.0) && x == y, "{got:?} vs {want:?}");
                    assert!(close(*c, *g, 10.0), "{c:?} vs {g:?}");
                    arcs += 1;
                }
                other => panic!("a different piece: {other:?}"),
            }
        }
    }
    assert!(arcs >= 14, "{arcs}");
}

#[test]
fn the_picture_draws_the_curved_domain_and_its_axis() {
    let rings = [rounded_rectangle([0.0, 0.0], 10.0, 6.0, 2.0), circle([3.0, 3.0], 1.0)];
    let input = write_input("picture.wkt", &curvepolygon(&rings));
    let svg = temp_path("picture.svg");
    let o = run(&[path_str(&input), "--svg", path_str(&svg)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let picture = std::fs::read_to_string(&svg).unwrap();
    let domain = picture.lines().find(|l| l.starts_with(r#"<path id="domain""#)).expect("the domain");
    // four corners and two half circles, as SVG arcs
    assert_eq!(domain.matches(" A ").count(), 6, "{domain}");
    assert!(picture.contains(r#"<g id="medial-axis""#) && picture.contains(r#"id="inscribed-circle""#));
    assert!(picture.contains(": medial axis,"), "the title says what is drawn");
    assert!(!picture.contains("NaN") && !picture.contains("inf"));
    // an open curve inside a polygon is an obstacle, drawn as an arc
    let input = write_input("obstacle-arc.wkt", "POLYGON((0 0, 10 0, 10 10, 0 10, 0 0))\nCIRCULARSTRING(3 3, 5 5, 7 3)\n");
    let o = run(&[path_str(&input), "--svg", path_str(&svg)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let picture = std::fs::read_to_string(&svg).unwrap();
    let obstacles = picture.lines().find(|l| l.starts_with(r#"<path id="obstacles""#)).expect("the obstacles");
    assert_eq!(obstacles.matches(" A ").count(), 1, "{obstacles}");
}

#[test]
fn a_refused_ring_names_its_entity() {
    // a circle (two bulges) across a side of the plate
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    d.add_entity(lwpolyline(&[(0.0, 0.0, 0.0), (10.0, 0.0, 0.0), (10.0, 10.0, 0.0), (0.0, 10.0, 0.0)], "PART"));
    d.add_entity(lwpolyline(&[(11.0, 5.0, 1.0), (9.0, 5.0, 1.0)], "HOLE"));
    let input = save(&d, "refused.dxf");
    let o = run(&[path_str(&input), "--max-inscribed-circle"]);
    let message = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{message}");
    assert!(message.contains("entity 1 (LWPOLYLINE, layer \"HOLE\")"), "{message}");
    assert!(message.contains("entity 0 (LWPOLYLINE, layer \"PART\")"), "{message}");
    // two crossing circles of a MULTISURFACE: both named, with their rings
    let input = write_input(
        "crossing-circles.wkt",
        "MULTISURFACE(CURVEPOLYGON(CIRCULARSTRING(0 0, 2 0, 0 0)), CURVEPOLYGON(CIRCULARSTRING(1 0, 3 0, 1 0)))",
    );
    let o = run(&[path_str(&input), "--max-inscribed-circle"]);
    let message = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{message}");
    assert!(message.contains("cross"), "{message}");
    for geometry in ["geometry 0 (a curve polygon), ring 0: ", "geometry 1 (a curve polygon), ring 0: "] {
        assert!(message.contains(geometry), "{message}");
    }
}
