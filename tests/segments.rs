//! Line-segment sites through the public API: validation, brute-force
//! geometry, input errors, naming.

mod common;

use common::{build_sites as build, check_empty_circles as check_geometry, segment_grid, Rng};
use segvoronoi::{Builder, ErrorKind, Point, Site, TopologyOptions};

#[test]
fn random_disjoint_segments_and_points() {
    for seed in 0..30 {
        let (pts, segs) = segment_grid(4 + seed as usize % 12, seed, 0.5);
        let d = build(&pts, &segs);
        assert_eq!(d.site_count(), pts.len() + 3 * segs.len());
        check_geometry(&d, 1e-9);
    }
}

#[test]
fn a_single_segment_is_a_strip() {
    let d = build(&[], &[[[0.0, 0.0], [2.0, 1.0]]]);
    assert_eq!((d.site_count(), d.vertex_count(), d.edge_count()), (3, 0, 2));
    let text = d.topology(TopologyOptions::default());
    assert_eq!(text, "EDGES 2\nP0 S0\nP1 S0\nFACES 0\n");
}

#[test]
fn collinear_chain_of_segments() {
    let d = build(&[[6.0, 3.0]], &[[[0.0, 0.0], [2.0, 1.0]], [[4.0, 2.0], [2.0, 1.0]]]);
    // P0 (6,3), P1 (0,0), P2 (2,1), P3 (4,2): a ladder P1 S0 P2 S1 P3 P0.
    assert_eq!((d.vertex_count(), d.edge_count()), (0, 5));
    let text = d.topology(TopologyOptions::default());
    assert_eq!(text, "EDGES 5\nP0 P3\nP1 S0\nP2 S0\nP2 S1\nP3 S1\nFACES 0\n");
}

#[test]
fn one_segment_among_points_by_hand() {
    // The segment (0,0)-(4,0) and a point above its middle at (2,2): the
    // vertex of P2 (2,2), S0 and P0 (0,0) is where the perpendicular at
    // (0,0) meets the parabola of (2,2) and the x axis: x = 0, y = 2.
    let d = build(&[[2.0, 2.0]], &[[[0.0, 0.0], [4.0, 0.0]]]);
    check_geometry(&d, 1e-12);
    let on_axis: Vec<Point> = d.vertices().map(|v| v.position).filter(|p| p.x.abs() < 1e-12).collect();
    assert_eq!(on_axis.len(), 1);
    assert!((on_axis[0].y - 2.0).abs() < 1e-12, "{:?}", on_axis[0]);
}

#[test]
fn crossing_segments_are_refused_with_both_indices() {
    let mut b = Builder::new();
    b.add_segment([0.0, 0.0], [2.0, 2.0]).unwrap();
    b.add_segment([5.0, 5.0], [6.0, 5.0]).unwrap();
    b.add_segment([0.0, 2.0], [2.0, 0.0]).unwrap();
    let e = b.build().unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Intersecting);
    assert_eq!(e.indices(), &[0, 2]);
    assert!(e.message().contains('0') && e.message().contains('2'), "{e}");
    assert_eq!(b.segment_count(), 3, "builder unchanged");
}

#[test]
fn repeats_and_zero_length_segments_are_merged() {
    let mut b = Builder::new();
    b.add_segments([[[0.0, 0.0], [3.0, 1.0]], [[3.0, 1.0], [0.0, 0.0]], [[5.0, 5.0], [5.0, 5.0]]]).unwrap();
    b.add_point(1.0, 4.0).unwrap();
    let d = b.build().unwrap();
    d.validate().unwrap();
    let stats = d.stats();
    assert_eq!((stats.input_segments, stats.duplicate_segments, stats.zero_length_segments), (3, 1, 1));
    assert_eq!(d.site_of_segment(0), d.site_of_segment(1));
    assert!(matches!(d.site(d.site_of_segment(0).unwrap()), Site::Segment { .. }));
    assert_eq!(d.site(d.site_of_segment(2).unwrap()), Site::Point(Point::new(5.0, 5.0)));
    check_geometry(&d, 1e-9);
}

#[test]
fn non_finite_segment_is_refused() {
    let mut b = Builder::new();
    b.add_segment([0.0, 0.0], [1.0, 1.0]).unwrap();
    let e = b.add_segments([[[0.0, 1.0], [1.0, 2.0]], [[f64::NAN, 0.0], [1.0, 0.0]]]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::InvalidCoordinate);
    assert_eq!(e.indices(), &[2]);
    assert_eq!(b.segment_count(), 1);
}

fn polygon(n: usize, r: f64, cx: f64, cy: f64) -> Vec<[[f64; 2]; 2]> {
    let corner = |k: usize| {
        let t = std::f64::consts::TAU * (k % n) as f64 / n as f64;
        [cx + r * t.cos(), cy + r * t.sin()]
    };
    (0..n).map(|k| [corner(k), corner(k + 1)]).collect()
}

#[test]
fn shared_endpoints_polyline() {
    let segs = [[[0.0, 0.0], [2.0, 0.3]], [[2.0, 0.3], [3.0, 2.0]], [[3.0, 2.0], [1.0, 3.0]]];
    let d = build(&[[1.0, 1.0], [5.0, 0.0], [-1.0, 2.0]], &segs);
    check_geometry(&d, 1e-9);
}

#[test]
fn shared_endpoints_triangle() {
    let segs = [[[0.0, 0.0], [4.0, 0.0]], [[4.0, 0.0], [1.0, 3.0]], [[1.0, 3.0], [0.0, 0.0]]];
    let d = build(&[[1.5, 1.0], [6.0, 4.0]], &segs);
    check_geometry(&d, 1e-9);
}

#[test]
fn regular_polygons() {
    for n in 3..=64 {
        let d = build(&[[0.1, 0.05]], &polygon(n, 1.0, 0.0, 0.0));
        check_geometry(&d, 1e-9);
    }
}

#[test]
fn star_of_segments() {
    let segs: Vec<[[f64; 2]; 2]> = (0..64)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 64.0 + 0.01;
            [[0.0, 0.0], [t.cos(), t.sin()]]
        })
        .collect();
    let d = build(&[], &segs);
    check_geometry(&d, 1e-9);
}

/// Known failure (issue 3): with spokes of mixed lengths at one point the
/// diagram validates but some vertices fail the empty-circle check (the
/// same cause as the random-segment CGAL differences, see
/// `c_tests/cgal.cmake`). Run with `--ignored`.
#[test]
#[ignore]
fn star_of_256_segments_with_points() {
    let segs: Vec<[[f64; 2]; 2]> = (0..256)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 256.0;
            [[0.0, 0.0], [(1.0 + (k % 3) as f64) * t.cos(), (1.0 + (k % 3) as f64) * t.sin()]]
        })
        .collect();
    let d = build(&[[0.3, 0.2], [5.0, 5.0]], &segs);
    check_geometry(&d, 1e-9);
}

#[test]
fn square_with_a_square_hole() {
    let mut segs = polygon(4, 2.0, 0.0, 0.0);
    segs.extend(polygon(4, 0.5, 0.1, -0.05));
    let d = build(&[[1.0, 0.2]], &segs);
    check_geometry(&d, 1e-9);
}

#[test]
fn lattice_of_unit_segments() {
    // Every grid line split into unit segments: degree-4 shared endpoints,
    // collinear neighbours, cocircular everything.
    let n = 6;
    let mut segs = Vec::new();
    for i in 0..=n {
        for j in 0..n {
            let (x, y) = (i as f64, j as f64);
            segs.push([[x, y], [x, y + 1.0]]);
            segs.push([[y, x], [y + 1.0, x]]);
        }
    }
    let d = build(&[], &segs);
    assert_eq!(d.site_count(), (n + 1) * (n + 1) + 2 * n * (n + 1));
    check_geometry(&d, 1e-9);
}

#[test]
fn collinear_consecutive_segments_among_points() {
    let segs = [[[0.0, 0.0], [1.0, 0.0]], [[1.0, 0.0], [2.5, 0.0]], [[2.5, 0.0], [3.0, 0.0]]];
    let d = build(&[[1.2, 1.0], [2.0, -0.7]], &segs);
    check_geometry(&d, 1e-9);
}

/// A boustrophedon polyline through one jittered point per grid cell:
/// consecutive segments share endpoints, none cross.
fn snake(side: usize, seed: u64) -> Vec<[[f64; 2]; 2]> {
    let mut rng = Rng(seed);
    let mut path = Vec::new();
    for i in 0..side {
        for k in 0..side {
            let j = if i % 2 == 0 { k } else { side - 1 - k };
            path.push([i as f64 + 0.1 + 0.8 * rng.unit(), j as f64 + 0.1 + 0.8 * rng.unit()]);
        }
    }
    path.windows(2).map(|w| [w[0], w[1]]).collect()
}

#[test]
fn random_polylines() {
    for seed in 0..20 {
        let segs = snake(3 + seed as usize % 9, seed);
        let d = build(&[], &segs);
        check_geometry(&d, 1e-9);
    }
}

#[test]
fn small_star() {
    let segs: Vec<[[f64; 2]; 2]> = (0..24)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 24.0 + 0.1;
            [[0.0, 0.0], [t.cos(), t.sin()]]
        })
        .collect();
    let d = build(&[[3.0, 0.5]], &segs);
    check_geometry(&d, 1e-9);
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    /// Segments and points on a jittered grid with a random fraction of
    /// cells holding a segment, some cells joined into polylines with the
    /// next cell's point (shared endpoints), and some points snapped to a
    /// coarse lattice (cocircular and collinear subsets).
    fn scene() -> impl Strategy<Value = (Vec<[f64; 2]>, Vec<[[f64; 2]; 2]>)> {
        (2usize..9, any::<u64>(), 0.0f64..1.0, any::<bool>()).prop_map(|(side, seed, share, snap)| {
            let mut rng = Rng(seed);
            let mut coord = |base: f64| {
                let v = base + 0.1 + 0.8 * rng.unit();
                if snap {
                    (v * 4.0).round() / 4.0
                } else {
                    v
                }
            };
            let (mut pts, mut segs) = (Vec::new(), Vec::new());
            let mut prev: Option<[f64; 2]> = None;
            for i in 0..side {
                for j in 0..side {
                    let (x, y) = (i as f64, j as f64);
                    let a = [coord(x), coord(y)];
                    let b = [coord(x), coord(y)];
                    if a == b {
                        pts.push(a);
                        continue;
                    }
                    segs.push([a, b]);
                    // join to the previous cell's segment end: both ends lie in
                    // adjacent cells of one column, so nothing else is crossed
                    if let Some(p) = prev {
                        if j > 0 && share > 0.5 {
                            segs.push([p, a]);
                        }
                    }
                    prev = Some(b);
                }
                prev = None;
            }
            (pts, segs)
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

        #[test]
        fn segment_diagrams_validate((pts, segs) in scene()) {
            let mut b = Builder::new();
            b.add_points(pts.iter().copied()).unwrap();
            b.add_segments(segs.iter().copied()).unwrap();
            match b.build() {
                Ok(d) => d.validate().unwrap_or_else(|e| panic!("{e}")),
                Err(e) => {
                    prop_assert_eq!(e.kind(), ErrorKind::Intersecting);
                    prop_assert_eq!(e.indices().len(), 2);
                }
            }
        }

        /// Known failure (issue 3): nearly degenerate configurations of
        /// segments sharing endpoints (and two plain disjoint segments, see
        /// the CGAL check) get a deletion set the segment insertion cannot
        /// take (a conflicting vertex adjacent to two tree vertices), and a
        /// vertex off its true position. Run with `--ignored`.
        #[test]
        #[ignore]
        fn segment_diagrams_are_geometrically_right((pts, segs) in scene()) {
            let mut b = Builder::new();
            b.add_points(pts.iter().copied()).unwrap();
            b.add_segments(segs.iter().copied()).unwrap();
            match b.build() {
                Ok(d) => check_geometry(&d, 1e-9),
                // joined polylines may cross a neighbour's segment: then the
                // input is refused, with both indices
                Err(e) => {
                    prop_assert_eq!(e.kind(), ErrorKind::Intersecting);
                    prop_assert_eq!(e.indices().len(), 2);
                }
            }
        }

        #[test]
        fn power_of_two_scaling_keeps_the_topology((pts, segs) in scene(), k in -40i32..40) {
            let f = 2f64.powi(k);
            let build_scaled = |f: f64| {
                let mut b = Builder::new();
                b.add_points(pts.iter().map(|p| [p[0] * f, p[1] * f])).unwrap();
                b.add_segments(segs.iter().map(|s| s.map(|p| [p[0] * f, p[1] * f]))).unwrap();
                b.build().map(|d| d.topology(TopologyOptions::default()))
            };
            match (build_scaled(1.0), build_scaled(f)) {
                (Ok(a), Ok(b)) => prop_assert_eq!(a, b),
                (Err(a), Err(b)) => prop_assert_eq!(a.indices(), b.indices()),
                _ => prop_assert!(false, "scaling changed whether the input is valid"),
            }
        }
    }
}

/// Found by the CGAL cross-check: a segment passing just below another's
/// endpoint conflicts with both ends of that endpoint's separator, whose
/// middle survives (the separator is cut twice).
#[test]
fn segment_passing_near_another_segments_endpoint() {
    let segs = [
        [[0.4549379074702896, 0.5300789975015889], [0.43596539982472504, 0.16703498914055104]],
        [[0.06596019314557644, 0.08141465400346082], [0.4958799515892044, 0.12310888693805211]],
    ];
    let d = build(&[], &segs);
    check_geometry(&d, 1e-12);
    let text = d.topology(TopologyOptions::default());
    assert!(text.contains("\nS0 S1\n"), "{text}");
}
