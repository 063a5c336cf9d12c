//! Line-segment sites through the public API: validation, brute-force
//! geometry, input errors, naming.

mod common;

use common::Rng;
use segvoronoi::{Builder, Diagram, ErrorKind, Point, Site, TopologyOptions};

/// Every vertex is equidistant from its three sites and no site is closer
/// (within `tol` times the input scale), with distances to segments.
fn check_geometry(d: &Diagram, tol: f64) {
    let scale = d.extent().max(f64::MIN_POSITIVE);
    for v in d.vertices() {
        for s in v.sites {
            let dist = d.site(s).distance(v.position);
            assert!((dist - v.clearance).abs() <= tol * scale, "vertex {} sites {:?}: site {s} at {dist}, clearance {}", v.id, v.sites, v.clearance);
        }
        for s in d.site_ids() {
            let dist = d.site(s).distance(v.position);
            assert!(dist >= v.clearance - tol * scale, "vertex {} sites {:?}: site {s} {:?} inside ({dist} < {})", v.id, v.sites, d.site(s), v.clearance);
        }
    }
}

fn build(points: &[[f64; 2]], segments: &[[[f64; 2]; 2]]) -> Diagram {
    let mut b = Builder::new();
    b.add_points(points.iter().copied()).unwrap();
    b.add_segments(segments.iter().copied()).unwrap();
    let d = b.build().unwrap_or_else(|e| panic!("{e}"));
    d.validate().unwrap_or_else(|e| panic!("{e}"));
    d
}

/// Points and short segments on a jittered grid: one item per cell, so no
/// two segments meet.
fn jittered(side: usize, seed: u64) -> (Vec<[f64; 2]>, Vec<[[f64; 2]; 2]>) {
    let mut rng = Rng(seed);
    let (mut pts, mut segs) = (Vec::new(), Vec::new());
    for i in 0..side {
        for j in 0..side {
            let (x, y) = (i as f64, j as f64);
            let a = [x + 0.1 + 0.8 * rng.unit(), y + 0.1 + 0.8 * rng.unit()];
            if rng.unit() < 0.5 {
                segs.push([a, [x + 0.1 + 0.8 * rng.unit(), y + 0.1 + 0.8 * rng.unit()]]);
            } else {
                pts.push(a);
            }
        }
    }
    (pts, segs)
}

#[test]
fn random_disjoint_segments_and_points() {
    for seed in 0..30 {
        let (pts, segs) = jittered(4 + seed as usize % 12, seed);
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
