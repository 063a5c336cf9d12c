//! Every input file under `c_tests/fixtures/` (Boost.Polygon's text format,
//! the CGAL cross-check's regression inputs) built through the public API:
//! the diagram validates and passes the brute-force empty-circle check, for
//! the file as it is, with every segment reversed, and with the points and
//! segments in reversed order. The CGAL harness checks the same files
//! against CGAL's exact topology; this test runs them without CGAL.
//!
//! The fixtures are all small (at most about a hundred sites), so the
//! brute-force check (every vertex against every site) runs on all of them;
//! it is skipped past `BRUTE_FORCE_LIMIT` sites to keep the test quick
//! should a large fixture be added (the validation still runs).
//!
//! `KNOWN` lists the fixtures on which the library is known to be wrong
//! (`c_tests/cgal.cmake` disables those whose topology differs): they still run, their
//! failures are printed but do not fail the test, and one that passes in
//! every variant is reported so that it can be taken off the list. An input
//! rejected as intersecting always fails: the fixture itself is broken.

mod common;

use common::check_empty_circles_relative;
use segvoronoi::{Builder, Diagram, ErrorKind};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

/// Sites above which the O(vertices x sites) empty-circle check is skipped.
const BRUTE_FORCE_LIMIT: usize = 2_000;

/// Tolerance of the empty-circle check, relative to the larger of the
/// extent and the vertex's clearance. Vertices of three nearly parallel
/// segments at coordinates of 1e9 (boost_bench_invalid_40seg) come out of
/// the double-precision solvers about 2e-8 of their radius off; a wrong
/// topology puts a site far deeper inside a circle (1.4e-6 of the radius in
/// point_near_segment_int, the whole radius in near_vertical_chain3).
const TOLERANCE: f64 = 1e-7;

/// Fixtures on which the library is known to be wrong, with the reason.
/// Delete an entry once the fixture passes (the test says when).
const KNOWN: &[(&str, &str)] = &[];

type Segment = [[f64; 2]; 2];

/// A name and the points and segments it builds from.
type Variant<'a> = (&'a str, &'a [[f64; 2]], &'a [Segment]);

struct Fixture {
    points: Vec<[f64; 2]>,
    segments: Vec<Segment>,
}

/// A fixture through the library's reader of Boost.Polygon's text format
/// (the one the CLI uses; `c_tests/cgal_crosscheck.cpp` reads the same
/// files), every coordinate finite.
fn read_boost_text(path: &Path) -> Result<Fixture, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read: {e}"))?;
    let input = segvoronoi::boost_text::parse(&text)?;
    if let Some(v) = input.points.iter().flatten().chain(input.segments.iter().flatten()).find(|v| !v.is_finite()) {
        return Err(format!("coordinate {v} is not finite"));
    }
    let segments = input.segments.iter().map(|&[x1, y1, x2, y2]| [[x1, y1], [x2, y2]]).collect();
    Ok(Fixture { points: input.points, segments })
}

fn fixture_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../c_tests/fixtures");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "txt"))
        .collect();
    files.sort();
    files
}

/// Builds and validates one variant; an input rejected as intersecting is
/// a broken fixture (every fixture is a legal input).
fn build_checked(points: &[[f64; 2]], segments: &[Segment]) -> Result<Diagram, String> {
    let mut b = Builder::new();
    b.add_points(points.iter().copied()).map_err(|e| format!("add_points: {e}"))?;
    b.add_segments(segments.iter().copied()).map_err(|e| format!("add_segments: {e}"))?;
    let d = match b.build() {
        Ok(d) => d,
        Err(e) if e.kind() == ErrorKind::Intersecting => {
            return Err(format!("rejected as intersecting, the fixture is broken: {e}"))
        }
        Err(e) => return Err(format!("build failed: {e}")),
    };
    d.validate().map_err(|e| format!("invalid diagram: {e}"))?;
    if d.site_count() <= BRUTE_FORCE_LIMIT {
        catch_unwind(AssertUnwindSafe(|| check_empty_circles_relative(&d, TOLERANCE)))
            .map_err(|p| format!("empty-circle check: {}", panic_text(&*p)))?;
    }
    Ok(d)
}

fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
        .unwrap_or_else(|| "(no message)".into())
}

#[test]
fn every_fixture_builds_valid_in_every_direction_and_order() {
    let files = fixture_files();
    assert!(files.len() >= 25, "only {} fixtures found", files.len());
    // The failures are collected with their messages; the default hook would
    // print each caught panic a second time.
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let mut failures = Vec::new();
    let mut known_failures = Vec::new();
    for path in &files {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let known = KNOWN.iter().find(|(file, _)| *file == name).map(|(_, why)| *why);
        let failures_before = failures.len();
        let fixture = match read_boost_text(path) {
            Ok(f) => f,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        let reversed_segments: Vec<Segment> = fixture.segments.iter().map(|&[a, b]| [b, a]).collect();
        let points_backwards: Vec<[f64; 2]> = fixture.points.iter().rev().copied().collect();
        let segments_backwards: Vec<Segment> = fixture.segments.iter().rev().copied().collect();
        let variants: [Variant; 3] = [
            ("as given", &fixture.points, &fixture.segments),
            ("every segment reversed", &fixture.points, &reversed_segments),
            ("points and segments in reversed order", &points_backwards, &segments_backwards),
        ];
        let mut site_counts = Vec::new();
        for (variant, points, segments) in variants {
            // A panic inside the library (a debug assertion) is one more
            // failure of this variant, not the end of the run.
            match catch_unwind(AssertUnwindSafe(|| build_checked(points, segments))) {
                Ok(Ok(d)) => site_counts.push(d.site_count()),
                Ok(Err(e)) => failures.push(format!("{name} ({variant}): {e}")),
                Err(p) => failures.push(format!("{name} ({variant}): panicked: {}", panic_text(&*p))),
            }
        }
        if site_counts.windows(2).any(|w| w[0] != w[1]) {
            failures.push(format!("{name}: site counts differ between the variants: {site_counts:?}"));
        }
        if let Some(why) = known {
            let mine = failures.split_off(failures_before);
            if mine.iter().any(|f| f.contains("rejected as intersecting")) {
                failures.extend(mine);
            } else if mine.is_empty() {
                eprintln!("{name}: passes in every variant; remove it from KNOWN ({why})");
            } else {
                known_failures.extend(mine.into_iter().map(|f| format!("{f} [known: {why}]")));
            }
        }
    }
    std::panic::set_hook(default_hook);
    for f in &known_failures {
        eprintln!("known failure: {f}");
    }
    for (file, _) in KNOWN {
        assert!(files.iter().any(|p| p.ends_with(file)), "KNOWN names {file}, which is not a fixture");
    }
    assert!(failures.is_empty(), "{} fixture failures:\n{}", failures.len(), failures.join("\n"));
}
