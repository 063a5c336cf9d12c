//! Real drawings: LibreCAD's part library (Debian's librecad-data,
//! /usr/share/librecad/library: some 1,300 DXF files of mechanical, electrical
//! and architectural parts, drawn by people, with lines, arcs, circles,
//! polylines with bulges, blocks and ellipses). Each goes through the
//! program with the largest inscribed circle, offsets at -0.5 and 1 (the
//! exact loops as JSON) and the medial axis, as a CAD user would try them.
//!
//! What must hold on every file: the program answers, within its time,
//! with status 0, or 1/2 and a message that names the file (crossing
//! entities named by entity and layer, "needs a polygon" where nothing
//! closes), never a crash; an internal error only on the files listed
//! (`KNOWN_REFUSED`). Where it answers: every
//! loop is closed exactly, no piece is a point (but a loop's whole circle),
//! arcs have their centre as far from both ends, the region of the outward
//! offset is larger than the inward one's, and every medial-axis sample
//! has a clearance at least 0. A file refused as crossing is run again
//! with `--split-crossings` (issue 32: polygons with arcs split), and
//! checked the same where answered; the count refused there by the
//! library's own checks is bounded by what it gives now. Skipped where
//! the package is missing (CI installs it: scripts/test-all.sh).

mod common;

use common::{path_str, stderr, temp_path, BIN};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

const LIBRARY: &str = "/usr/share/librecad/library";

/// The drawings the library refuses as `Internal` (the arcs' decisions
/// are not certified yet): none now. Any file refused so fails the test,
/// and a file listed here that is answered is reported (`answered_now`).
///
/// Answered since: dev15, hl_27 and Bathroom-basin-V once the joins'
/// turns were exact; kin13 and the four Logic-*-IEC gates once a circle
/// touching a side at the side's end was no tangent join; ed69 and elk61
/// once the domain counted a shell at a hole's corner; c13, c14, nl and
/// Resistor-heatfuse once a vertex on an arc's circle at a cusp was in
/// conflict with it; t2 once an arc leaving its end into a circle 1e16
/// across at an angle of 3e-16 was seen to enter it; aw16 once a vertex
/// on an arc's circle with an edge into the arc's sector was in conflict
/// with it; Chair-sofa-V once a vertex at an arc's centre with every site
/// on its circle was placed there where the solvers found none; blk1 and
/// block2 (bulges of six digits) once the edges beside kinks of 2e-6 rad
/// were found across the ray; l2 once arcs were cut where a segment ends
/// on them (`dxf::t_junctions`), which brought 46 drawings that had been
/// refused as crossing to the arcs. Of those, ed125 was answered once a
/// kink's point kept its cell on one side of the join; ed83, the JFETs,
/// kin6, kin15 and Meter once an arc's centre was a vertex only for sites
/// round it in the order asked; Logic-NAND once a double root at an arc's
/// end point was solved with the end's separator; kin10 once the edge
/// between an arc and its chord lay on the chord's side; n13 once a line
/// along a circle's tangent from a corner lay outside it; Headphone once
/// the edge between two arcs meeting at both ends, each over half a turn,
/// lay on the side of the arc halfway between them.
const KNOWN_REFUSED: [&str; 0] = [];

fn dxf_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            dxf_files(&path, out);
        } else if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("dxf")) {
            out.push(path);
        }
    }
}

/// The checks of one answered file's exact offsets (see the module doc).
fn check_offsets(name: &str, offsets: &Value) {
    let mut areas = Vec::new();
    for offset in offsets["offsets"].as_array().unwrap() {
        let d = offset["distance"].as_f64().unwrap();
        areas.push((d, offset["area"].as_f64().unwrap()));
        for (l, lp) in offset["loops"].as_array().unwrap().iter().enumerate() {
            let pieces = lp["pieces"].as_array().unwrap();
            assert!(!pieces.is_empty(), "{name} at {d}: loop {l} empty");
            for (k, piece) in pieces.iter().enumerate() {
                let next = &pieces[(k + 1) % pieces.len()];
                assert_eq!(piece["to"], next["from"], "{name} at {d}: loop {l} opens after piece {k}");
                let (from, to) = (common::xy(&piece["from"]), common::xy(&piece["to"]));
                let apart = (from[0] - to[0]).hypot(from[1] - to[1]);
                let whole_circle = pieces.len() == 1 && from == to && piece["kind"] == "arc";
                assert!(whole_circle || apart > 1e-9 * d.abs(), "{name} at {d}: loop {l} piece {k} is a point: {piece}");
                if piece["kind"] == "arc" {
                    let c = common::xy(&piece["centre"]);
                    let (rf, rt) = ((from[0] - c[0]).hypot(from[1] - c[1]), (to[0] - c[0]).hypot(to[1] - c[1]));
                    assert!((rf - rt).abs() <= 1e-9 * (rf + c[0].abs() + c[1].abs()), "{name} at {d}: arc {piece}");
                }
            }
        }
    }
    if let [(d0, a0), (d1, a1)] = areas[..] {
        // (a region within d of the drawing grows with d)
        assert!(d0 < d1 && a0 < a1, "{name}: the region at {d0} ({a0}) is not smaller than at {d1} ({a1})");
    }
}

#[test]
fn every_part_of_librecads_library_is_answered() {
    let mut files = Vec::new();
    dxf_files(Path::new(LIBRARY), &mut files);
    if files.is_empty() {
        eprintln!("skipped: {LIBRARY} is missing (Debian's librecad-data)");
        return;
    }
    files.sort();
    let (offsets, axis) = (temp_path("librecad_offsets.json"), temp_path("librecad_axis.wkt"));
    let (mut domains, mut no_polygon, mut refused, mut internal) = (0, 0, 0, 0);
    let (mut split_domains, mut split_internal) = (0, Vec::new());
    let mut answered_now = Vec::new();
    let started = Instant::now();
    let run_program = |file: &Path, split: bool| {
        let _ = std::fs::remove_file(&offsets);
        let run = Instant::now();
        let o = Command::new(BIN)
            .args([path_str(file), "--max-inscribed-circle", "--offset=-0.5", "--offset=1", "--offsets"])
            .arg(&offsets)
            .arg("--medial-axis")
            .arg(&axis)
            .args(if split { &["--split-crossings"][..] } else { &[] })
            .output()
            .unwrap();
        (o, run.elapsed())
    };
    for file in &files {
        let name = file.strip_prefix(LIBRARY).unwrap_or(file).display().to_string();
        let (o, elapsed) = run_program(file, false);
        let run_elapsed = elapsed;
        assert!(run_elapsed < Duration::from_secs(30), "{name}: {run_elapsed:?}");
        let message = stderr(&o);
        let lower = message.to_lowercase();
        assert!(!lower.contains("panicked"), "{name}: {message}");
        if lower.contains("please report") {
            assert!(KNOWN_REFUSED.contains(&name.trim_start_matches('/')), "{name}: refused as internal: {message}");
            internal += 1;
            continue;
        }
        match o.status.code() {
            Some(0) => {
                domains += 1;
                if KNOWN_REFUSED.contains(&name.trim_start_matches('/')) {
                    answered_now.push(name.clone());
                }
                let value: Value = serde_json::from_str(&std::fs::read_to_string(&offsets).unwrap()).unwrap();
                check_offsets(&name, &value);
                for line in common::multilinestring_z(&std::fs::read_to_string(&axis).unwrap()) {
                    assert!(line.iter().all(|p| p[2] >= 0.0 && p.iter().all(|v| v.is_finite())), "{name}: axis {line:?}");
                }
            }
            Some(1) | Some(2) => {
                assert!(
                    message.contains(&name) || message.contains(path_str(file)),
                    "{name}: the message names the file: {message}"
                );
                if message.contains("needs a polygon") {
                    no_polygon += 1;
                    continue;
                }
                refused += 1;
                // what a user does next: split the crossing entities
                let (o, elapsed) = run_program(file, true);
                assert!(elapsed < Duration::from_secs(30), "{name}, split: {elapsed:?}");
                let message = stderr(&o);
                assert!(!message.to_lowercase().contains("panicked"), "{name}, split: {message}");
                if message.contains("please report") {
                    split_internal.push(name.clone());
                } else if o.status.code() == Some(0) {
                    split_domains += 1;
                    let value: Value = serde_json::from_str(&std::fs::read_to_string(&offsets).unwrap()).unwrap();
                    check_offsets(&format!("{name}, split"), &value);
                    for line in common::multilinestring_z(&std::fs::read_to_string(&axis).unwrap()) {
                        assert!(
                            line.iter().all(|p| p[2] >= 0.0 && p.iter().all(|v| v.is_finite())),
                            "{name}, split: axis {line:?}"
                        );
                    }
                } else {
                    assert!(matches!(o.status.code(), Some(1) | Some(2)), "{name}, split: {:?}: {message}", o.status);
                    assert!(message.contains(path_str(file)), "{name}, split: the message names the file: {message}");
                }
            }
            other => panic!("{name}: status {other:?}: {message}"),
        }
    }
    eprintln!(
        "LibreCAD's library: {} files in {:?}: {domains} domains answered and checked, {internal} refused by the arcs' checks of vertices and offset pieces (KNOWN_REFUSED), {no_polygon} without a closed outline, \
         {refused} refused (crossing entities, degenerate arcs)",
        files.len(),
        started.elapsed()
    );
    eprintln!(
        "with --split-crossings, of the {refused} refused: {split_domains} answered and checked, {} refused by the arcs' own checks: {split_internal:?}",
        split_internal.len()
    );
    // what the library gives now (2026-12-06, the fourteenth session: 443
    // answered, 12 refused as internal: arcs' vertex checks after the
    // split's cuts, offsets beside near-tangent cusps, splits that did not
    // converge; kin3, mik2 and d2 answered since)
    assert!(split_domains >= 442, "{split_domains} split domains");
    assert!(split_internal.len() <= 13, "{} split refused as internal", split_internal.len());
    if !answered_now.is_empty() {
        eprintln!("answered now, and checked, though listed in KNOWN_REFUSED (take them off): {answered_now:?}");
    }
    assert!(domains >= 300, "{domains} domains");
}

/// Two LibreCAD drawings minimised (`scripts/dxf-minimise.py`), whose
/// tangencies the drawings' rounding makes crossings, split at both roots
/// into pieces of rounding size. Inside each circle the offset at `d` is
/// the circle of radius `R + d` (the other entities touch it from
/// outside), so its area is known exactly; outside they must be answered
/// (the program's own check of every piece's distance, and closed loops).
/// - kin3 (R = 0.75, touched from above and from inside below): edges from
///   a circle's centre were tracked by the centre's angle, which is
///   rounding there (`conic::from_the_centre`);
/// - mik2 (R = 4, a line along the tangent at its top): the edge between
///   the chord piece and its arc piece, 1e-15 apart, was found 1 below
///   them by a bisection reading rounding (`ConicTrack::radius_along`).
/// Both had every inward offset refused.
#[test]
fn minimised_tangencies_split_at_both_roots() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    for (file, radius) in [("librecad_kin3_minimised.dxf", 0.75), ("librecad_mik2_minimised.dxf", 4.0)] {
        let fractions = [-0.1, -0.5, -0.9, 0.1, 0.5];
        let distances: Vec<f64> = fractions.iter().map(|f| f * radius).collect();
        let offsets = temp_path(&format!("{file}.json"));
        let o = Command::new(BIN)
            .arg(path_str(&data.join(file)))
            .args(distances.iter().map(|d| format!("--offset={d}")))
            .arg("--offsets")
            .arg(&offsets)
            .arg("--split-crossings")
            .output()
            .unwrap();
        assert!(o.status.success(), "{file}: {}", stderr(&o));
        let json: Value = serde_json::from_str(&std::fs::read_to_string(&offsets).unwrap()).unwrap();
        let answered = json["offsets"].as_array().unwrap();
        assert_eq!(answered.len(), distances.len(), "{file}");
        for (offset, &d) in answered.iter().zip(&distances) {
            let area = offset["area"].as_f64().unwrap();
            if d < 0.0 {
                let want = std::f64::consts::PI * (radius + d) * (radius + d);
                assert!((area - want).abs() <= 1e-9 * want, "{file} at {d}: area {area}, the circle's {want}");
            } else {
                assert!(area > std::f64::consts::PI * radius * radius, "{file} at {d}: area {area}");
            }
        }
    }
}
