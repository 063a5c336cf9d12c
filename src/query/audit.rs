//! Debug aid (tests only): a built diagram checked vertex by vertex
//! against every site in 400-bit arithmetic (`oracle::audit_depth`).
//!
//! `SEGFILE=input.txt cargo test --lib audit_file -- --ignored --nocapture`
//! builds an input in Boost.Polygon's text format and prints the sites, the
//! vertices, and every vertex whose circle holds another site or cannot be
//! solved: where the topology is not the exact diagram's, whatever the
//! rounded positions say.

use crate::geometry::oracle::audit_depth;
use crate::{Builder, Diagram, Point, Site};

/// The vertices of `diagram` whose circle holds another site, with the
/// depth (most negative first within a vertex) — empty for the exact
/// diagram. Vertices of three points are left out (their predicate is
/// exact already).
pub(crate) fn audit(diagram: &Diagram, print: bool) -> Vec<String> {
    let mut bad = Vec::new();
    for v in diagram.vertices() {
        let geometry = v.sites.map(|s| diagram.site(s));
        if geometry.iter().all(Site::is_point) {
            continue;
        }
        if print {
            eprintln!("vertex {:?} {:?} at {:?} r {}", v.id, v.sites, v.position, v.clearance);
        }
        for s in diagram.site_ids().filter(|s| !v.sites.contains(s)) {
            match audit_depth(&geometry, &diagram.site(s)) {
                Some((c, r, depth)) if depth < -1e-30 * r.max(1.0) => {
                    bad.push(format!("vertex {:?} {:?}: site {s:?} inside by {depth:e} (exact centre {c:?}, r {r})", v.id, v.sites));
                }
                None => bad.push(format!("vertex {:?} {:?}: not solved", v.id, v.sites)),
                _ => {}
            }
        }
    }
    bad
}

#[test]
#[ignore]
fn audit_file() {
    let path = std::env::var("SEGFILE").expect("SEGFILE names the input to audit");
    let text = std::fs::read_to_string(path).expect("a readable input");
    let mut nums = text.split_whitespace().map(|t| t.parse::<f64>().expect("a number"));
    let mut next = || nums.next().expect("more numbers");
    let mut builder = Builder::new();
    for _ in 0..next() as usize {
        builder.add_point(next(), next()).expect("a point");
    }
    for _ in 0..next() as usize {
        let a = Point::new(next(), next());
        builder.add_segment(a, Point::new(next(), next())).expect("a segment");
    }
    let diagram = builder.build().expect("a diagram");
    for s in diagram.site_ids() {
        eprintln!("site {s:?}: {:?}", diagram.site(s));
    }
    let bad = audit(&diagram, true);
    for line in &bad {
        eprintln!("{line}");
    }
    assert!(bad.is_empty(), "{} vertices hold a site", bad.len());
}
