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
        let geometry = v.sites.map(|s| diagram.sites.at(s.index()));
        let of_points = geometry.iter().all(Site::is_point);
        if print && !of_points {
            eprintln!("vertex {:?} {:?} at {:?} r {}", v.id, v.sites, v.position, v.clearance);
        }
        let mut centre_checked = false;
        for s in diagram.site_ids().filter(|s| !v.sites.contains(s)) {
            let other = diagram.sites.at(s.index());
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
        eprintln!("site {s:?}: {:?}", diagram.sites.at(s.index()));
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

/// Two parallel segments a few ulps to a billionth apart, one shorter than
/// the other and beside it, with points and a segment near them: the
/// configuration of a ring's vertex an ulp off a neighbouring ring's side
/// (issue 28's open case, minimised into the `parallel_*` fixtures). The
/// circle through two points an ulp nearer one line than the other is
/// far out, and the margin of an edge there is below the rounding of its
/// distances: each diagram must still be the exact one. Horizontal and
/// vertical pairs (exactly parallel at any offset), mirrored and in both
/// orders, near the origin and at 2^30, with the shorter one cut at a
/// straight vertex or a point exactly on the longer one.
#[test]
fn parallel_segments_an_ulp_apart_pass_the_audit() {
    use crate::splitmix::SplitMix64;
    let mut rng = SplitMix64(28);
    let mut failures = Vec::new();
    for case in 0..240 {
        let mut coordinate = |lo: f64, hi: f64| lo + (hi - lo) * rng.unit();
        // every other 48 cases far from the origin (2^30: an ulp is 2^-22)
        let base = if (case / 48) % 2 == 1 { 1_073_741_824.0 } else { 0.0 };
        let y = base + coordinate(0.5, 4.0) * if case % 5 < 2 { -1.0 } else { 1.0 };
        let (x0, x1) = (base + coordinate(-4.0, 0.0), base + coordinate(0.5, 4.0));
        let (inner0, inner1) = (coordinate(x0, x1), coordinate(x0, x1));
        let (inner0, inner1) = (inner0.min(inner1), inner0.max(inner1));
        let ulps = [1u64, 2, 7, 1 << 10, 1 << 20, 1 << 30][case % 6];
        // the shorter segment above the longer one or below it, with the
        // point and the leg on its far side
        let up = (case / 6) % 2 == 0;
        let side = if up { 1.0 } else { -1.0 };
        let bits = y.to_bits();
        let y_inner = f64::from_bits(if (y > 0.0) == up { bits + ulps } else { bits - ulps });
        let mut points = vec![
            [base + coordinate(-4.0, 4.0), y + (9.0 + coordinate(0.0, 4.0)) * side],
            [inner0, y_inner + side * coordinate(0.1, 1.0)],
        ];
        let mut segments = vec![[[x0, y], [x1, y]]];
        let middle = 0.5 * (inner0 + inner1);
        if case % 4 == 2 && inner0 < middle && middle < inner1 {
            // the shorter one in two pieces with a straight (180°) vertex
            segments.extend([[[inner0, y_inner], [middle, y_inner]], [[middle, y_inner], [inner1, y_inner]]]);
        } else {
            segments.push([[inner0, y_inner], [inner1, y_inner]]);
        }
        if case % 4 == 3 {
            // a point exactly on the longer one (it splits it there)
            points.push([0.5 * (x0 + x1), y]);
        }
        if case % 3 == 0 {
            // a leg from the shorter one's end towards the point
            segments.push([[inner0, y_inner + side * 0.05], [inner0, y_inner]]);
        }
        let transform = |[x, y]: [f64; 2]| match (case / 12) % 4 {
            0 => [x, y],
            1 => [-x, y],
            2 => [y, x],
            _ => [-y, -x],
        };
        let mut builder = Builder::new();
        let order: Vec<usize> = if case % 2 == 0 { (0..segments.len()).collect() } else { (0..segments.len()).rev().collect() };
        builder.add_points(points.iter().map(|&p| transform(p))).expect("points");
        builder.add_segments(order.iter().map(|&k| segments[k].map(transform))).expect("segments");
        let Ok(diagram) = builder.build() else {
            failures.push(format!("case {case}: no diagram"));
            continue;
        };
        failures.extend(audit(&diagram, false).into_iter().map(|line| format!("case {case}: {line}")));
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}
