//! The exactly cocircular families of issue 27 (`segvoronoi_testgen::ties`:
//! stacks and hatches of equal parallel segments with aligned ends,
//! vertical stacks, rows of collinear segments on a lattice, stacks
//! staggered by exact multiples, a bus with groups of aligned ends), whose
//! true zeros the oracle decides in expansions (`quadratic_vertex`): each
//! diagram validates, passes the brute-force empty-circle check and the
//! nearest-site check on a grid of queries, and keeps its counts under
//! exact transformations (power-of-two scaling, the quarter turn, the
//! mirror, reversed input order).

mod common;

use common::{build_sites, check_empty_circles, check_nearest_sites};
use segvoronoi::Point;
use segvoronoi_testgen::ties::{family, FAMILIES};

type Segment = [[f64; 2]; 2];

fn segments_of(name: &str, n: usize) -> Vec<Segment> {
    family(name, n).unwrap().iter().map(|s| [[f64::from(s[0]), f64::from(s[1])], [f64::from(s[2]), f64::from(s[3])]]).collect()
}

/// Vertices and edges.
fn counts(segments: &[Segment]) -> (usize, usize) {
    let d = build_sites(&[], segments);
    (d.vertex_count(), d.edge_count())
}

/// A grid of queries over the input's box and a margin, off the lattice
/// by a quarter so that few land on a bisector.
fn queries(segments: &[Segment]) -> Vec<Point> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in segments.iter().flatten() {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let steps = 24;
    let mut out = Vec::new();
    for i in 0..=steps {
        for j in 0..=steps {
            let t = |k: usize, s: usize| lo[k] - 3.25 + (hi[k] - lo[k] + 6.5) * s as f64 / steps as f64;
            out.push(Point::new(t(0, i), t(1, j)));
        }
    }
    out
}

#[test]
fn every_family_validates_and_passes_the_brute_force_checks() {
    for name in FAMILIES {
        for n in [2, 3, 7, 40, 150] {
            let segments = segments_of(name, n);
            let d = build_sites(&[], &segments);
            assert_eq!(d.site_count(), 3 * segments.len(), "{name} {n}");
            check_empty_circles(&d, 1e-9);
            check_nearest_sites(&d, &queries(&segments), 1e-9);
        }
    }
}

#[test]
fn every_family_keeps_its_counts_under_exact_transformations() {
    for name in FAMILIES {
        let segments = segments_of(name, 120);
        let expected = counts(&segments);
        let transformed: [(&str, Box<dyn Fn([f64; 2]) -> [f64; 2]>); 5] = [
            ("scaled by 2^-30", Box::new(|p: [f64; 2]| [p[0] * 2f64.powi(-30), p[1] * 2f64.powi(-30)])),
            ("scaled by 2^40", Box::new(|p: [f64; 2]| [p[0] * 2f64.powi(40), p[1] * 2f64.powi(40)])),
            ("turned a quarter", Box::new(|p: [f64; 2]| [-p[1], p[0]])),
            ("mirrored", Box::new(|p: [f64; 2]| [-p[0], p[1]])),
            ("moved by (1024, -512)", Box::new(|p: [f64; 2]| [p[0] + 1024.0, p[1] - 512.0])),
        ];
        for (what, f) in &transformed {
            let moved: Vec<Segment> = segments.iter().map(|s| s.map(f)).collect();
            assert_eq!(counts(&moved), expected, "{name} {what}");
        }
        let reversed: Vec<Segment> = segments.iter().rev().map(|s| [s[1], s[0]]).collect();
        assert_eq!(counts(&reversed), expected, "{name} reversed");
    }
}

/// A stack of `n` equal aligned segments has the ladder of the seed
/// paper's figure 8 (4): its counts in closed form, as CGAL's (checked by
/// the benchmark at 3,000 and 30,000: 4n − 4 vertices, 7n − 5 edges).
#[test]
fn stacks_and_hatches_have_the_ladder_counts() {
    for name in ["stack", "vstack", "hatch"] {
        for n in [2usize, 5, 64] {
            assert_eq!(counts(&segments_of(name, n)), (4 * n - 4, 7 * n - 5), "{name} {n}");
        }
    }
}
