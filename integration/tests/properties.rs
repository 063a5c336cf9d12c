//! Property tests: every diagram validates; the topology does not depend on
//! input order, on translation or on power-of-two scaling; brute-force
//! empty-circle and nearest-site checks on small inputs. Inputs mix generic
//! random points with degenerate ones (small integer grids: many cocircular
//! and collinear subsets, and repeated points; coordinates a hair apart).

mod common;

use common::*;
use proptest::prelude::*;
use segvoronoi::{Diagram, Point, Site};

/// Positive-length Voronoi edges as pairs of site coordinates (sorted), the
/// part of the topology that every valid answer on degenerate input shares.
fn positive_pairs(d: &Diagram) -> Vec<[(u64, u64); 2]> {
    let key = |p: Point| (p.x.to_bits(), p.y.to_bits());
    let mut out: Vec<[(u64, u64); 2]> = d
        .edges()
        .filter(|e| has_positive_length(d, e))
        .map(|e| {
            let point = |s| d.site(s).unwrap().as_point().expect("point sites only");
            let mut pair = [key(point(e.sites[0])), key(point(e.sites[1]))];
            pair.sort_unstable();
            pair
        })
        .collect();
    out.sort_unstable();
    out
}

fn transformed(points: &[[f64; 2]], f: impl Fn(f64) -> f64) -> Vec<[f64; 2]> {
    points.iter().map(|p| [f(p[0]), f(p[1])]).collect()
}

/// Site-coordinate pairs of a transformed input, mapped back by `inverse`.
fn mapped_back(pairs: Vec<[(u64, u64); 2]>, inverse: impl Fn(f64) -> f64) -> Vec<[(u64, u64); 2]> {
    let back = |c: u64| (inverse(f64::from_bits(c)) + 0.0).to_bits();
    let mut out: Vec<_> = pairs
        .into_iter()
        .map(|pair| {
            let mut p = pair.map(|(x, y)| (back(x), back(y)));
            p.sort_unstable();
            p
        })
        .collect();
    out.sort_unstable();
    out
}

fn grid_points(max_len: usize, side: i32) -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop::collection::vec((0..side, 0..side).prop_map(|(x, y)| [x as f64, y as f64]), 0..max_len)
}

fn random_points(max_len: usize) -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop::collection::vec((-1.0e3f64..1.0e3, -1.0e3f64..1.0e3).prop_map(|(x, y)| [x, y]), 0..max_len)
}

/// Coordinates from a few values, some a hair apart: repeats, collinear and
/// cocircular subsets, and needle triangles whose vertices are hard to place
/// (the family that found the circumcentre and walk bugs in the CGAL check).
fn snapped_points(max_len: usize) -> impl Strategy<Value = Vec<[f64; 2]>> {
    const VALUES: [f64; 8] = [0.0, 1.0, -1.0, 1e-20, -1e-20, 2.0, 0.5, -3e-17];
    prop::collection::vec((0..VALUES.len(), 0..VALUES.len()).prop_map(|(i, j)| [VALUES[i], VALUES[j]]), 0..max_len)
}

fn any_points() -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop_oneof![grid_points(120, 6), grid_points(200, 40), random_points(200), snapped_points(120)]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 96, ..ProptestConfig::default() })]

    #[test]
    fn every_diagram_validates_and_counts_agree(points in any_points()) {
        let d = build(&points);
        let mut distinct: Vec<(u64, u64)> = points.iter().map(|p| ((p[0] + 0.0).to_bits(), (p[1] + 0.0).to_bits())).collect();
        distinct.sort_unstable();
        distinct.dedup();
        prop_assert_eq!(d.site_count(), distinct.len());
        prop_assert_eq!(d.stats().duplicate_points, points.len() - distinct.len());
        for (i, p) in points.iter().enumerate() {
            prop_assert_eq!(d.site(d.site_of_input(i).unwrap()), Some(Site::Point(Point::new(p[0] + 0.0, p[1] + 0.0))));
        }
    }

    #[test]
    fn topology_is_independent_of_input_order(points in any_points(), seed in any::<u64>()) {
        let mut shuffled = points.clone();
        let mut rng = Rng(seed);
        for i in (1..shuffled.len()).rev() {
            shuffled.swap(i, (rng.next_u64() % (i as u64 + 1)) as usize);
        }
        prop_assert_eq!(positive_pairs(&build(&points)), positive_pairs(&build(&shuffled)));
    }

    #[test]
    fn topology_is_invariant_under_translation_and_scaling(points in grid_points(150, 30), dx in -50i32..50, k in -60i32..60) {
        let base = positive_pairs(&build(&points));
        // integer translation of small integers is exact
        let moved = build(&transformed(&points, |v| v + dx as f64));
        prop_assert_eq!(&base, &mapped_back(positive_pairs(&moved), |v| v - dx as f64));
        // power-of-two scaling is exact
        let f = 2f64.powi(k);
        let scaled = build(&transformed(&points, |v| v * f));
        prop_assert_eq!(&base, &mapped_back(positive_pairs(&scaled), |v| v / f));
    }

    #[test]
    fn brute_force_geometry_holds(points in prop_oneof![grid_points(200, 25), random_points(200), snapped_points(150)], seed in any::<u64>()) {
        let d = build(&points);
        check_empty_circles(&d, 1e-9);
        let mut rng = Rng(seed);
        let queries: Vec<Point> = (0..50).map(|_| Point::new(rng.unit() * 1200.0 - 600.0, rng.unit() * 1200.0 - 600.0)).collect();
        check_nearest_sites(&d, &queries, 1e-9);
        if d.site_count() > 0 {
            let mut hint = None;
            for q in queries {
                let found = d.nearest_site(q, hint).unwrap();
                let best = d.site_ids().map(|s| d.site(s).unwrap().distance(q)).fold(f64::INFINITY, f64::min);
                prop_assert!(d.site(found).unwrap().distance(q) <= best * (1.0 + 1e-12), "query {:?}", q);
                hint = Some(found);
            }
        }
    }
}
