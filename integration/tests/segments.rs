//! Line-segment sites through the public API: validation, brute-force
//! geometry, input errors, naming.

mod common;

use common::{
    build_sites as build, check_empty_circles as check_geometry, check_nearest_sites, has_positive_length, polygon, segment_grid,
    snake, unit_segment_lattice, Rng,
};
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
    b.add_segment([[0.0, 0.0], [2.0, 2.0]]).unwrap();
    b.add_segment([[5.0, 5.0], [6.0, 5.0]]).unwrap();
    b.add_segment([[0.0, 2.0], [2.0, 0.0]]).unwrap();
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
    b.add_point([1.0, 4.0]).unwrap();
    let d = b.build().unwrap();
    d.validate().unwrap();
    let stats = d.stats();
    assert_eq!((stats.input_segments, stats.duplicate_segments, stats.zero_length_segments), (3, 1, 1));
    assert_eq!(d.site_of_segment(0), d.site_of_segment(1));
    assert!(matches!(d.site(d.site_of_segment(0).unwrap()), Some(Site::Segment { .. })));
    assert_eq!(d.site(d.site_of_segment(2).unwrap()), Some(Site::Point(Point::new(5.0, 5.0))));
    check_geometry(&d, 1e-9);
}

#[test]
fn non_finite_segment_is_refused() {
    let mut b = Builder::new();
    b.add_segment([[0.0, 0.0], [1.0, 1.0]]).unwrap();
    let e = b.add_segments([[[0.0, 1.0], [1.0, 2.0]], [[f64::NAN, 0.0], [1.0, 0.0]]]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::InvalidCoordinate);
    assert_eq!(e.indices(), &[2]);
    assert_eq!(b.segment_count(), 1);
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

/// Spokes of three lengths at one point, with points among them.
#[test]
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
    let d = build(&[], &unit_segment_lattice(n));
    assert_eq!(d.site_count(), (n + 1) * (n + 1) + 2 * n * (n + 1));
    check_geometry(&d, 1e-9);
}

#[test]
fn collinear_consecutive_segments_among_points() {
    let segs = [[[0.0, 0.0], [1.0, 0.0]], [[1.0, 0.0], [2.5, 0.0]], [[2.5, 0.0], [3.0, 0.0]]];
    let d = build(&[[1.2, 1.0], [2.0, -0.7]], &segs);
    check_geometry(&d, 1e-9);
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

/// The build, or its error.
fn try_build(points: &[[f64; 2]], segments: &[[[f64; 2]; 2]]) -> Result<segvoronoi::Diagram, segvoronoi::Error> {
    let mut b = Builder::new();
    b.add_points(points.iter().copied())?;
    b.add_segments(segments.iter().copied())?;
    b.build()
}

/// A site named by its coordinates: a point, or a segment's endpoints in
/// sorted order.
type SiteKey = Vec<[f64; 2]>;

/// The positive-length edges (longer than 1e-9 of the extent; rays always)
/// as sorted pairs of site keys, sorted: what every valid answer on
/// degenerate input shares, independent of the input's numbering.
fn positive_edges(d: &segvoronoi::Diagram) -> Vec<[SiteKey; 2]> {
    let key = |s| -> SiteKey {
        let mut k = match d.site(s).unwrap() {
            Site::Point(p) => vec![[p.x, p.y]],
            Site::Segment { a, b } => vec![[a.x, a.y], [b.x, b.y]],
            other => panic!("a site kind this test does not know: {other:?}"),
        };
        k.sort_by(|p, q| p.partial_cmp(q).unwrap());
        k
    };
    let mut out: Vec<[SiteKey; 2]> = d
        .edges()
        .filter(|e| has_positive_length(d, e))
        .map(|e| {
            let mut pair = e.sites.map(key);
            pair.sort_by(|p, q| p.partial_cmp(q).unwrap());
            pair
        })
        .collect();
    out.sort_by(|p, q| p.partial_cmp(q).unwrap());
    out
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    /// Segments and points on a jittered grid with a random fraction of
    /// cells holding a segment, some cells joined into polylines with the
    /// next cell's point (shared endpoints), and some points snapped to a
    /// coarse lattice (cocircular and collinear subsets).
    fn scene() -> impl Strategy<Value = (Vec<[f64; 2]>, Vec<[[f64; 2]; 2]>)> {
        scene_snapped(any::<bool>())
    }

    /// [`scene`], snapped to the quarter lattice or not as `snap` says.
    fn scene_snapped(snap: impl Strategy<Value = bool>) -> impl Strategy<Value = (Vec<[f64; 2]>, Vec<[[f64; 2]; 2]>)> {
        (2usize..9, any::<u64>(), 0.0f64..1.0, snap).prop_map(|(side, seed, share, snap)| {
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

        /// Every vertex equidistant from its sites and no site closer
        /// (1e-9 of the extent); random query points lie in the cell of a
        /// nearest site, and `nearest_site` finds one.
        #[test]
        fn segment_diagrams_are_geometrically_right((pts, segs) in scene(), seed in any::<u64>()) {
            let mut b = Builder::new();
            b.add_points(pts.iter().copied()).unwrap();
            b.add_segments(segs.iter().copied()).unwrap();
            match b.build() {
                Ok(d) => {
                    check_geometry(&d, 1e-9);
                    let mut rng = Rng(seed);
                    let queries: Vec<Point> =
                        (0..40).map(|_| Point::new(rng.unit() * 12.0 - 1.5, rng.unit() * 12.0 - 1.5)).collect();
                    check_nearest_sites(&d, &queries, 1e-9);
                    let mut hint = None;
                    for q in queries {
                        let found = d.nearest_site(q, hint).unwrap();
                        let best = d.site_ids().map(|s| d.site(s).unwrap().distance(q)).fold(f64::INFINITY, f64::min);
                        prop_assert!(d.site(found).unwrap().distance(q) <= best + 1e-9 * d.extent());
                        hint = Some(found);
                    }
                }
                // joined polylines may cross a neighbour's segment: then the
                // input is refused, with both indices
                Err(e) => {
                    prop_assert_eq!(e.kind(), ErrorKind::Intersecting);
                    prop_assert_eq!(e.indices().len(), 2);
                }
            }
        }

        /// Shuffling the points and the segments and reversing some
        /// segments changes no positive-length edge (sites named by their
        /// coordinates).
        #[test]
        fn topology_is_independent_of_input_order((pts, segs) in scene(), seed in any::<u64>()) {
            let mut rng = Rng(seed);
            let (mut pts2, mut segs2) = (pts.clone(), segs.clone());
            for i in (1..pts2.len()).rev() {
                pts2.swap(i, (rng.next_u64() % (i as u64 + 1)) as usize);
            }
            for i in (1..segs2.len()).rev() {
                segs2.swap(i, (rng.next_u64() % (i as u64 + 1)) as usize);
            }
            for s in segs2.iter_mut() {
                if rng.unit() < 0.5 {
                    s.reverse();
                }
            }
            match (try_build(&pts, &segs), try_build(&pts2, &segs2)) {
                (Ok(a), Ok(b)) => prop_assert_eq!(positive_edges(&a), positive_edges(&b)),
                (Err(_), Err(_)) => {}
                _ => prop_assert!(false, "the order changed whether the input is valid"),
            }
        }

        /// Translating a quarter-lattice scene by whole units (exact) changes
        /// no positive-length edge.
        #[test]
        fn topology_is_invariant_under_translation((pts, segs) in scene_snapped(Just(true)), dx in -64i32..64, dy in -64i32..64) {
            let (dx, dy) = (dx as f64, dy as f64);
            let pts2: Vec<[f64; 2]> = pts.iter().map(|p| [p[0] + dx, p[1] + dy]).collect();
            let segs2: Vec<[[f64; 2]; 2]> = segs.iter().map(|s| s.map(|p| [p[0] + dx, p[1] + dy])).collect();
            match (try_build(&pts, &segs), try_build(&pts2, &segs2)) {
                (Ok(a), Ok(b)) => {
                    let back: Vec<_> = positive_edges(&b)
                        .into_iter()
                        .map(|pair| {
                            let mut pair = pair.map(|key| key.into_iter().map(|[x, y]| [x - dx, y - dy]).collect::<Vec<_>>());
                            pair.iter_mut().for_each(|k| k.sort_by(|p, q| p.partial_cmp(q).unwrap()));
                            pair.sort_by(|p, q| p.partial_cmp(q).unwrap());
                            pair
                        })
                        .collect::<Vec<_>>();
                    let mut back = back;
                    back.sort_by(|p, q| p.partial_cmp(q).unwrap());
                    prop_assert_eq!(positive_edges(&a), back);
                }
                (Err(_), Err(_)) => {}
                _ => prop_assert!(false, "translation changed whether the input is valid"),
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

/// The nearest-site walk against brute force on a thousand segments among
/// points, with and without hints, including queries far outside.
#[test]
fn nearest_site_walk_with_segments() {
    let (pts, segs) = segment_grid(40, 11, 0.6);
    let d = build(&pts, &segs);
    let mut rng = Rng(12);
    let mut hint = None;
    for k in 0..2000 {
        let spread = if k % 10 == 0 { 400.0 } else { 44.0 };
        let q = Point::new(rng.unit() * spread - spread / 2.0 + 20.0, rng.unit() * spread - spread / 2.0 + 20.0);
        let best = d.site_ids().map(|s| d.site(s).unwrap().distance(q)).fold(f64::INFINITY, f64::min);
        for h in [None, hint] {
            let found = d.nearest_site(q, h).unwrap();
            assert!(d.site(found).unwrap().distance(q) <= best * (1.0 + 1e-12), "query {q:?}: {found:?} is not nearest");
        }
        hint = d.nearest_site(q, hint);
    }
}

/// On a large input the crossing check runs beside the point insertions:
/// its error still comes back, naming both segments, and the builder keeps
/// its input.
#[test]
fn crossing_found_in_a_large_input() {
    let (pts, mut segs) = segment_grid(160, 3, 0.9);
    assert!(segs.len() > 20_000);
    let n = segs.len();
    // from the middle of cell (0, 0) into cell (1, 1), crossing nothing
    // but the segment added after it, which runs the other way
    segs.push([[0.95, 0.95], [1.05, 1.05]]);
    segs.push([[0.95, 1.05], [1.05, 0.95]]);
    let mut b = Builder::new();
    b.add_points(pts.iter().copied()).unwrap();
    b.add_segments(segs.iter().copied()).unwrap();
    let e = b.build().unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Intersecting);
    assert_eq!(e.indices(), [n, n + 1]);
    assert_eq!(b.segment_count(), n + 2);
    segs.pop();
    let mut b = Builder::new();
    b.add_points(pts.iter().copied()).unwrap();
    b.add_segments(segs.iter().copied()).unwrap();
    b.build().unwrap().validate().unwrap();
}
