//! Debug aid (tests only): a built diagram checked vertex by vertex
//! against every site in 400-bit arithmetic (`oracle::audit_depth`).
//!
//! `SEGFILE=input.txt cargo test --lib audit_file -- --ignored --nocapture`
//! builds an input in Boost.Polygon's text format and prints the sites, the
//! vertices, and every vertex whose circle holds another site or cannot be
//! solved: where the topology is not the exact diagram's, whatever the
//! rounded positions say.

use crate::geometry::segments::oracle::audit_depth;
use crate::{Builder, Diagram, Site};

/// The vertices of `diagram` whose circle holds another site, with the
/// depth (most negative first within a vertex), or whose position is not
/// the exact centre of its sites' circle — empty for the exact diagram.
/// Points are not checked against vertices of three points (that
/// predicate is exact already); segments are.
pub(crate) fn audit(diagram: &Diagram, print: bool) -> Vec<String> {
    let mut bad = Vec::new();
    for v in diagram.vertices() {
        let geometry = v.sites.map(|s| diagram.sites[s.index()]);
        let of_points = geometry.iter().all(Site::is_point);
        if print && !of_points {
            eprintln!("vertex {:?} {:?} at {:?} r {}", v.id, v.sites, v.position, v.clearance);
        }
        let mut centre_checked = false;
        for s in diagram.site_ids().filter(|s| !v.sites.contains(s)) {
            let other = diagram.sites[s.index()];
            if of_points && other.is_point() {
                continue;
            }
            match audit_depth(&geometry, &other) {
                Some((c, r, depth)) => {
                    // (relative beyond the range of f64: r infinite)
                    let scale = if r.is_finite() { r.max(1.0) } else { 1.0 };
                    if depth < -1e-30 * scale {
                        bad.push(format!(
                            "vertex {:?} {:?}: site {s:?} inside by {depth:e} (exact centre {c:?}, r {r})",
                            v.id, v.sites
                        ));
                    }
                    // a vertex on the wrong side of a nearly flat
                    // configuration has an empty exact circle but is
                    // far from it
                    if !centre_checked && c.distance(v.position) > 1e-6 * scale {
                        bad.push(format!("vertex {:?} {:?}: at {:?}, exact centre {c:?} (r {r})", v.id, v.sites, v.position));
                    }
                    centre_checked = true;
                }
                None => bad.push(format!("vertex {:?} {:?}: not solved", v.id, v.sites)),
            }
        }
    }
    bad
}

#[test]
#[ignore]
fn audit_file() {
    let path = std::env::var("SEGFILE").expect("SEGFILE names the input to audit");
    let builder = builder_of(&std::fs::read_to_string(path).expect("a readable input"));
    let diagram = builder.build().expect("a diagram");
    for s in diagram.site_ids() {
        eprintln!("site {s:?}: {:?}", diagram.sites[s.index()]);
    }
    let bad = audit(&diagram, true);
    for line in &bad {
        eprintln!("{line}");
    }
    assert!(bad.is_empty(), "{} vertices hold a site", bad.len());
}

/// A builder of an input in Boost.Polygon's text format (`boost_text`).
fn builder_of(text: &str) -> Builder {
    let input = crate::boost_text::parse(text).expect("an input in Boost.Polygon's text format");
    let mut builder = Builder::new();
    builder.add_points(input.points).expect("points");
    builder.add_segments(input.segments.iter().map(|&[x1, y1, x2, y2]| [[x1, y1], [x2, y2]])).expect("segments");
    builder
}

/// Every small fixture's diagram is the exact one: no vertex's circle
/// holds a site, in 400-bit arithmetic (fixtures above `LIMIT` sites are
/// left out: the check is quadratic and slow in big floats).
#[test]
fn every_small_fixture_passes_the_audit() {
    const LIMIT: usize = 60;
    // Known to be wrong (c_tests/cgal.cmake disables each with the reason).
    const KNOWN: &[&str] = &[];
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("c_tests/fixtures");
    let mut failures = Vec::new();
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).expect("the fixtures") {
        let path = entry.expect("an entry").path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or_default().to_string();
        if !name.ends_with(".txt") || KNOWN.contains(&name.as_str()) {
            continue;
        }
        let diagram = builder_of(&std::fs::read_to_string(&path).expect("a readable fixture")).build().expect("a diagram");
        if diagram.site_count() > LIMIT {
            continue;
        }
        checked += 1;
        failures.extend(audit(&diagram, false).into_iter().map(|line| format!("{name}: {line}")));
    }
    assert!(checked > 20, "only {checked} fixtures checked");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
