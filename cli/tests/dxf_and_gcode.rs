//! DXF in and out, G-code and WKT curves, run as a user would: drawings
//! made with the `dxf` crate (as CAD programs write them) and by hand (an
//! R12 file as small programs write it), the program's outputs read back
//! and compared with its exact loops (`--offsets OUT.json`).

mod common;

use std::path::{Path, PathBuf};

use common::*;

use dxf::entities::{Circle, Entity, EntityType, Insert};
use dxf::enums::AcadVersion;
use dxf::{Block, Drawing, Point as DxfPoint};
use segvoronoi::{Builder, CircularArc};
use serde_json::Value;

/// Whether the library builds arcs yet (as in `curves_and_diagram.rs`).
fn arcs_build() -> bool {
    let mut b = Builder::new();
    b.add_arc(CircularArc::from_bulge([0.0, 0.0], [2.0, 0.0], 1.0).unwrap()).unwrap();
    b.add_point([1.0, 3.0]).unwrap();
    match b.build() {
        Ok(_) => true,
        Err(e) => {
            eprintln!("skipped until the library builds arcs: {e}");
            false
        }
    }
}

/// A plate 100 × 60 with a square and a triangular hole, drawn only with
/// LINEs, in no particular order or direction (R12, as old programs write).
fn lines_plate() -> PathBuf {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R12;
    let entities = [
        line([100.0, 0.0], [100.0, 60.0], "PART"),
        line([20.0, 20.0], [40.0, 20.0], "HOLES"),
        line([0.0, 0.0], [100.0, 0.0], "PART"),
        line([0.0, 60.0], [0.0, 0.0], "PART"),
        line([40.0, 20.0], [40.0, 40.0], "HOLES"),
        line([100.0, 60.0], [0.0, 60.0], "PART"),
        line([20.0, 40.0], [20.0, 20.0], "HOLES"),
        line([40.0, 40.0], [20.0, 40.0], "HOLES"),
        line([60.0, 15.0], [85.0, 15.0], "HOLES"),
        line([85.0, 15.0], [72.5, 45.0], "HOLES"),
        line([72.5, 45.0], [60.0, 15.0], "HOLES"),
    ];
    for e in entities {
        d.add_entity(e);
    }
    save(&d, "lines-plate.dxf")
}

#[test]
fn offsets_of_a_part_of_lines_round_trip_through_dxf() {
    let input = lines_plate();
    let exact = exact_offsets(&input, &["-2", "3", "-0.1"], "lines-exact.json");
    let out = temp_path("lines-offsets.dxf");
    let o = run(&[path_str(&input), "--offset=-2", "--offset", "3", "--offset=-0.1", "--offsets", path_str(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let drawing = Drawing::load_file(&out).unwrap();
    let entities: Vec<&Entity> = drawing.entities().collect();
    let loops: Vec<(f64, &Value)> = exact["offsets"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|o| o["loops"].as_array().unwrap().iter().map(move |l| (o["distance"].as_f64().unwrap(), l)))
        .collect();
    // two holes and the outline at each of three distances
    assert_eq!(entities.len(), loops.len());
    assert_eq!(loops.len(), 3 * 3);
    let mut arcs = 0;
    for (entity, (distance, lp)) in entities.iter().zip(&loops) {
        assert_eq!(entity.common.layer, format!("OFFSET_{distance}"));
        let EntityType::LwPolyline(p) = &entity.specific else { panic!("a polyline: {entity:?}") };
        assert!(p.is_closed());
        let pieces = json_pieces(lp);
        assert_eq!(p.vertices.len(), pieces.len());
        for (v, piece) in p.vertices.iter().zip(&pieces) {
            let from = match *piece {
                Piece::Line { from, .. } | Piece::Arc { from, .. } => from,
            };
            // the numbers are written in full: the same f64s
            assert_eq!([v.x, v.y], from);
            let b = expected_bulge(piece);
            assert!((v.bulge - b).abs() <= 1e-12 * b.abs().max(1.0), "{} vs {b}", v.bulge);
            arcs += usize::from(b != 0.0);
        }
    }
    assert!(arcs >= 4 * 3, "the outline's corners at +3, the holes' at -2 and -0.1");
    assert!(drawing.layers().any(|l| l.name == "OFFSET_-2"));
}

#[test]
fn points_grown_are_circles_in_dxf_and_two_half_arcs_in_gcode() {
    let input = temp_path("points.dxf");
    std::fs::write(
        &input,
        "0\nSECTION\n2\nENTITIES\n0\nPOINT\n8\n0\n10\n1.5\n20\n2.0\n0\nPOINT\n8\n0\n10\n11.5\n20\n2.0\n0\nENDSEC\n0\nEOF\n",
    )
    .unwrap();
    let out = temp_path("points-offsets.dxf");
    let o = run(&[path_str(&input), "--offset", "1", "--offsets", path_str(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let drawing = Drawing::load_file(&out).unwrap();
    let circles: Vec<(f64, f64, f64)> = drawing
        .entities()
        .filter_map(|e| match &e.specific {
            EntityType::Circle(c) => Some((c.center.x, c.center.y, c.radius)),
            _ => None,
        })
        .collect();
    assert_eq!(circles, [(1.5, 2.0, 1.0), (11.5, 2.0, 1.0)]);
    let nc = temp_path("points.nc");
    let o = run(&[path_str(&input), "--offset", "1", "--offsets", path_str(&nc)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(nc).unwrap();
    assert!(text.contains("G0 X2.5 Y2\nG1 Z-1 F100\nG3 X0.5 Y2 I-1 J0 F600\nG3 X2.5 Y2 I1 J0\nG0 Z5\n"), "{text}");
}

#[test]
fn gcode_reads_back_as_the_loops_inner_first() {
    let input = lines_plate();
    let distances = ["-2", "3", "-0.1"];
    let exact = exact_offsets(&input, &distances, "gcode-exact.json");
    let nc = temp_path("plate.nc");
    let o = run(&[
        path_str(&input),
        "--offset=-2",
        "--offset=3",
        "--offset=-0.1",
        "--offsets",
        path_str(&nc),
        "--feed",
        "800",
        "--plunge-feed",
        "50",
        "--plunge-depth",
        "-2.5",
        "--safe-z",
        "3",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&nc).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(&lines[1..5], ["G21", "G90", "G17", "G0 Z3"]);
    assert_eq!(lines.last(), Some(&"M2"));
    assert_eq!(text.matches(" F800").count(), 3 * 3, "one feed per loop");
    let cut = parse_gcode(&text, "G1 Z-2.5 F50");
    let offsets = exact["offsets"].as_array().unwrap();
    assert_eq!(cut.len(), offsets.iter().map(|o| o["loops"].as_array().unwrap().len()).sum::<usize>());
    // the distances in the order given, every loop once
    let order: Vec<f64> = cut.iter().map(|c| c.distance).collect();
    assert!(order.windows(2).all(|w| w[0] == w[1]
        || distances.iter().position(|d| d.parse::<f64>().unwrap() == w[0])
            < distances.iter().position(|d| d.parse::<f64>().unwrap() == w[1])));
    let mut arcs = 0;
    for offset in offsets {
        let d = offset["distance"].as_f64().unwrap();
        let loops = offset["loops"].as_array().unwrap();
        let here: Vec<&CutLoop> = cut.iter().filter(|c| c.distance == d).collect();
        assert_eq!(here.len(), loops.len());
        for (position, c) in here.iter().enumerate() {
            let lp = &loops[c.index];
            // children before parents
            if let Some(parent) = lp["parent"].as_u64() {
                let parent_at = here.iter().position(|p| p.index == parent as usize).unwrap();
                assert!(position < parent_at, "loop {} before its parent {parent}", c.index);
            }
            let expected = json_pieces(lp);
            assert_eq!(c.pieces.len(), expected.len());
            for (got, want) in c.pieces.iter().zip(&expected) {
                match (got, want) {
                    (Piece::Line { from: a, to: b }, Piece::Line { from: c, to: d }) => assert_eq!((a, b), (c, d)),
                    (Piece::Arc { from: a, to: b, centre: c, ccw: x }, Piece::Arc { from: e, to: f, centre: g, ccw: y }) => {
                        assert_eq!((a, b, x), (e, f, y));
                        assert!(close(*c, *g, 100.0), "{c:?} vs {g:?}");
                        arcs += 1;
                    }
                    other => panic!("a different piece: {other:?}"),
                }
            }
        }
        // with a hole inside the outline, some loop has a parent
        assert!(loops.iter().any(|l| !l["parent"].is_null()) || d > 0.0);
    }
    assert!(arcs >= 12, "{arcs}");
}

#[test]
fn gcode_digits_round_the_numbers() {
    let input = lines_plate();
    let nc = temp_path("digits.nc");
    let o = run(&[path_str(&input), "--offset=-0.3", "--offsets", path_str(&nc), "--gcode-digits", "3"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&nc).unwrap();
    for word in text.split_whitespace().filter(|w| w.starts_with(['X', 'Y', 'I', 'J'])) {
        let decimals = word.split_once('.').map_or(0, |(_, d)| d.len());
        assert!(decimals <= 3, "{word}");
    }
}

/// An R12 file as a small program writes it: the plate 10 × 5 with a
/// square hole, its left side's end a hair off (1e-13) the corner, and a
/// TEXT that is left out.
const R12_PLATE: &str = "0\nSECTION\n2\nENTITIES\n\
0\nLINE\n8\nPART\n10\n0.0\n20\n0.0\n30\n0.0\n11\n10.0\n21\n0.0\n31\n0.0\n\
0\nLINE\n8\nPART\n10\n10.0\n20\n0.0\n11\n10.0\n21\n5.0\n\
0\nLINE\n8\nPART\n10\n10.0\n20\n5.0\n11\n0.0\n21\n5.0\n\
0\nLINE\n8\nPART\n10\n0.0\n20\n5.0\n11\n0.0\n21\n0.0000000000001\n\
0\nPOLYLINE\n8\nHOLE\n66\n1\n70\n1\n10\n0.0\n20\n0.0\n30\n0.0\n\
0\nVERTEX\n8\nHOLE\n10\n2.0\n20\n2.0\n0\nVERTEX\n8\nHOLE\n10\n3.0\n20\n2.0\n\
0\nVERTEX\n8\nHOLE\n10\n3.0\n20\n3.0\n0\nVERTEX\n8\nHOLE\n10\n2.0\n20\n3.0\n0\nSEQEND\n8\nHOLE\n\
0\nTEXT\n8\n0\n10\n0.0\n20\n0.0\n40\n1.0\n1\nPLATE\n\
0\nENDSEC\n0\nEOF\n";

#[test]
fn a_hand_written_r12_file_is_a_domain() {
    let input = temp_path("r12.dxf");
    std::fs::write(&input, R12_PLATE).unwrap();
    let axis = temp_path("r12-axis.dxf");
    let o = run(&[path_str(&input), "--max-inscribed-circle", "--medial-axis", path_str(&axis)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let circle: Vec<f64> = stdout(&o).split_whitespace().map(|v| v.parse().unwrap()).collect();
    assert_eq!(circle[2], 2.5, "{circle:?}");
    let notes = stderr(&o);
    assert!(notes.contains("note: left out the entities the diagram does not take: 1 TEXT"), "{notes}");
    assert!(notes.contains("note: moved 1 endpoint"), "{notes}");
    let drawing = Drawing::load_file(&axis).unwrap();
    assert!(drawing.entities().all(|e| e.common.layer == "MEDIAL_AXIS"));
    let lines = drawing.entities().filter(|e| matches!(e.specific, EntityType::Line(_))).count();
    let curves = drawing.entities().filter(|e| matches!(e.specific, EntityType::LwPolyline(_))).count();
    // parabolas around the hole's corners
    assert!(lines >= 5 && curves >= 4, "{lines} lines, {curves} polylines");
    // also without the extension, by its first lines
    let renamed = temp_path("r12-plate.txt");
    std::fs::write(&renamed, R12_PLATE).unwrap();
    let o = run(&[path_str(&renamed), "--max-inscribed-circle"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn a_rounded_plate_with_bulges_and_circles_is_arcs() {
    let q = (std::f64::consts::PI / 8.0).tan();
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    d.add_entity(lwpolyline(
        &[
            (5.0, 0.0, 0.0),
            (95.0, 0.0, q),
            (100.0, 5.0, 0.0),
            (100.0, 55.0, q),
            (95.0, 60.0, 0.0),
            (5.0, 60.0, q),
            (0.0, 55.0, 0.0),
            (0.0, 5.0, q),
        ],
        "PART",
    ));
    for x in [20.0, 50.0, 80.0] {
        d.add_entity(on_layer(EntityType::Circle(Circle::new(DxfPoint::new(x, 30.0, 0.0), 6.0)), "HOLES"));
    }
    let input = save(&d, "rounded.dxf");
    if !arcs_build() {
        return;
    }
    // a domain: the plate less the holes, shrunk by 1 (corners of radius
    // 4, holes of radius 7)
    let exact = exact_offsets(&input, &["-1"], "rounded-exact.json");
    let area = exact["offsets"][0]["area"].as_f64().unwrap();
    let expected = 98.0 * 58.0 - 16.0 * (4.0 - std::f64::consts::PI) - 3.0 * 49.0 * std::f64::consts::PI;
    assert!((area - expected).abs() < 1e-9 * expected, "{area} vs {expected}");
    let diagram = temp_path("rounded-diagram.json");
    let o = run(&[path_str(&input), "--diagram", path_str(&diagram), "--stats"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn errors_name_the_entity_and_its_layer() {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    d.add_entity(lwpolyline(&[(0.0, 0.0, 0.0), (10.0, 0.0, 0.0), (10.0, 10.0, 0.0), (0.0, 10.0, 0.0)], "PART"));
    d.add_entity(line([5.0, -5.0], [5.0, 5.0], "CUT"));
    let input = save(&d, "crossing.dxf");
    let o = run(&[path_str(&input), "--stats"]);
    assert_eq!(o.status.code(), Some(1));
    let message = stderr(&o);
    assert!(message.contains("entity 0 (LWPOLYLINE, layer \"PART\")"), "{message}");
    assert!(message.contains("entity 1 (LINE, layer \"CUT\")"), "{message}");
}

#[test]
fn blocks_are_inserted_moved_scaled_and_turned() {
    let mut d = Drawing::new();
    d.header.version = AcadVersion::R2000;
    let mut square = Block { name: "SQ".into(), ..Default::default() };
    square.entities.push(lwpolyline(&[(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0)], "0"));
    d.add_block(square);
    let insert = Insert {
        name: "SQ".into(),
        location: DxfPoint::new(10.0, 0.0, 0.0),
        x_scale_factor: 4.0,
        y_scale_factor: 4.0,
        rotation: 90.0,
        ..Default::default()
    };
    d.add_entity(on_layer(EntityType::Insert(insert), "PARTS"));
    let input = save(&d, "insert.dxf");
    let o = run(&[path_str(&input), "--max-inscribed-circle"]);
    assert!(o.status.success(), "{}", stderr(&o));
    // the square [6, 10] × [0, 4]
    let circle: Vec<f64> = stdout(&o).split_whitespace().map(|v| v.parse().unwrap()).collect();
    assert_eq!(circle, [8.0, 2.0, 2.0]);

    // unequal scales of a circle: refused, naming the INSERT and the circle
    let mut hole = Block { name: "HOLE".into(), ..Default::default() };
    hole.entities.push(on_layer(EntityType::Circle(Circle::new(DxfPoint::new(0.0, 0.0, 0.0), 1.0)), "0"));
    d.add_block(hole);
    let stretched = Insert { name: "HOLE".into(), x_scale_factor: 2.0, ..Default::default() };
    d.add_entity(on_layer(EntityType::Insert(stretched), "PARTS"));
    let input = save(&d, "insert-stretched.dxf");
    let o = run(&[path_str(&input), "--stats"]);
    assert_eq!(o.status.code(), Some(2));
    let message = stderr(&o);
    assert!(message.contains("entity 1 (INSERT of block \"HOLE\", layer \"PARTS\"), block entity 0 (CIRCLE"), "{message}");
    assert!(message.contains("ellipses"), "{message}");
}

#[test]
fn a_downward_extrusion_mirrors_x() {
    // a 4 × 4 square at OCS x in [2, 6]: in the drawing x in [-6, -2]
    let text = "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nPART\n90\n4\n70\n1\n\
10\n2.0\n20\n0.0\n10\n6.0\n20\n0.0\n10\n6.0\n20\n4.0\n10\n2.0\n20\n4.0\n210\n0.0\n220\n0.0\n230\n-1.0\n0\nENDSEC\n0\nEOF\n";
    let input = temp_path("mirrored.dxf");
    std::fs::write(&input, text).unwrap();
    let o = run(&[path_str(&input), "--max-inscribed-circle"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o), "-4 2 2\n");
}

#[test]
fn malformed_drawings_are_clear_errors() {
    let cases: [(&str, &[u8]); 3] = [
        ("number.dxf", b"0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n0\n10\nabc\n20\n0\n0\nENDSEC\n0\nEOF\n"),
        ("binary.dxf", &[0u8, 159, 146, 150, 255, 0, 1, 2, 3]),
        ("cut.dxf", b"0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n"),
    ];
    for (name, bytes) in cases {
        let input = temp_path(name);
        std::fs::write(&input, bytes).unwrap();
        let o = run(&[path_str(&input), "--stats"]);
        let message = stderr(&o);
        assert!(!message.contains("panicked"), "{name}: {message}");
        if !o.status.success() {
            assert_eq!(o.status.code(), Some(2), "{name}: {message}");
            assert!(message.contains(name) && message.contains("DXF"), "{name}: {message}");
        }
    }
    let input = temp_path("number.dxf");
    let message = stderr(&run(&[path_str(&input)]));
    assert!(message.contains("line"), "the line of the bad number: {message}");
}

#[test]
fn curved_wkt_offsets_are_read_back_by_the_program() {
    let input = lines_plate();
    let out = temp_path("curves.wkt");
    let o = run(&[path_str(&input), "--offset", "3", "--offset", "-2", "--offsets", path_str(&out), "--curves"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2);
    assert!(lines.iter().all(|l| l.starts_with("MULTISURFACE (CURVEPOLYGON (COMPOUNDCURVE (")), "{text}");
    assert!(lines[0].contains("CIRCULARSTRING ("), "the outline's rounded corners: {text}");
    if !arcs_build() {
        return;
    }
    let o = run(&[path_str(&out), "--diagram", path_str(&temp_path("curves-diagram.json"))]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// A file of `tests/data`, made by another program (ezdxf 1.x, R2010,
/// with its full header, tables and handles); `None` where it is missing
/// (the packaged crate leaves it out).
fn data_file(name: &str) -> Option<PathBuf> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name);
    if path.exists() {
        Some(path)
    } else {
        eprintln!("skipped: {} is missing", path.display());
        None
    }
}

#[test]
fn a_part_written_by_ezdxf_with_arcs_blocks_and_a_mirrored_circle() {
    // a rounded plate (LWPOLYLINE bulges), a slot of LINEs and ARCs, a
    // block of a circle inserted three times, a circle with extrusion
    // (0, 0, -1), a TEXT
    let Some(input) = data_file("ezdxf_plate.dxf") else { return };
    if !arcs_build() {
        return;
    }
    let o = run(&[path_str(&input), "--stats"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report = stderr(&o);
    assert!(report.contains("note: left out the entities the diagram does not take: 1 TEXT"), "{report}");
    // 4 sides and 2 slot lines; 4 corners, 2 slot ends, 3 + 1 circles as halves
    assert!(report.contains("\ninput_segments=6\n") && report.contains("\narc_sites=14\n"), "{report}");
}

#[test]
fn a_domain_written_by_ezdxf_with_a_rotated_block_and_a_mirrored_hole() {
    // the plate 120 × 80 with a 10 × 10 square hole turned by 45° (a block
    // inserted scaled) and a 20 × 20 one drawn with extrusion (0, 0, -1)
    // at OCS x in [-100, -80], so at x in [80, 100]: grown holes by 2,
    // the region shrunk by 2 has this area only if both are inside
    let Some(input) = data_file("ezdxf_square_holes.dxf") else { return };
    let exact = exact_offsets(&input, &["-2"], "ezdxf-square-holes.json");
    let area = exact["offsets"][0]["area"].as_f64().unwrap();
    let grown = |side: f64| side * side + 4.0 * side * 2.0 + std::f64::consts::PI * 4.0;
    let expected = 116.0 * 76.0 - grown(10.0) - grown(20.0);
    assert!((area - expected).abs() < 1e-9 * expected, "{area} vs {expected}");
    assert_eq!(exact["offsets"][0]["loops"].as_array().unwrap().len(), 3);
}

/// A spoke ending on a circle a hair outside it (a drawing's rounding):
/// the program cuts the circle there, so the two meet exactly, and
/// `--input-wkt` writes what it read: with `--curves` a CURVEPOLYGON whose
/// arcs end at the spoke's end as written, which the program reads back
/// into the same diagram; without, the circle as chords within the
/// tolerance.
#[test]
fn a_spoke_ending_on_a_circle_is_read_as_meeting_it() {
    let mut d = Drawing::new();
    d.add_entity(on_layer(EntityType::Circle(Circle::new(DxfPoint::new(0.0, 0.0, 0.0), 2.0)), "0"));
    d.add_entity(line([0.0, 5.0], [0.0, 2.0 + 1e-12], "0"));
    let input = save(&d, "spoke.dxf");
    let (curved, chords) = (temp_path("spoke-curves.wkt"), temp_path("spoke-chords.wkt"));
    let o = run(&[path_str(&input), "--input-wkt", path_str(&curved), "--curves", "--topology"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("cut arcs at 1 vertex"), "{}", stderr(&o));
    let text = std::fs::read_to_string(&curved).unwrap();
    assert!(text.starts_with("GEOMETRYCOLLECTION (CURVEPOLYGON (COMPOUNDCURVE (CIRCULARSTRING"), "{text}");
    assert!(text.contains("0 2.000000000001") && text.contains("LINESTRING (0 5, 0 2.000000000001)"), "{text}");
    // read back: the same topology
    let again = run(&[path_str(&curved), "--topology"]);
    assert!(again.status.success(), "{}", stderr(&again));
    assert_eq!(stdout(&again), stdout(&o));
    let o = run(&[path_str(&input), "--input-wkt", path_str(&chords), "--tolerance", "0.001"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&chords).unwrap();
    assert!(text.starts_with("GEOMETRYCOLLECTION (POLYGON ((") && !text.contains("CIRCULARSTRING"), "{text}");
    // a circle of radius 2 within 0.001: 2π / (2 acos(1 − 0.0005)) = 99.3,
    // so 100 chords (in three arcs: 101, and the spoke's 2 points)
    let points = text.matches(',').count() + 1 - text.matches("), ").count();
    assert!((100..=106).contains(&points), "{points} points: {text}");
    for p in [input, curved, chords] {
        std::fs::remove_file(p).unwrap();
    }
}
