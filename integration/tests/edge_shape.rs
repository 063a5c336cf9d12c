//! Edge geometry through the public API: `Diagram::edge_shape`,
//! `edge_polyline` and `edge_bezier`, checked against the defining property
//! of a Voronoi edge: every point of it is as far from one of its sites as
//! from the other (`Site::distance`). (Their C counterparts:
//! `capi/tests/edge_shape.rs`.)

mod common;

use common::{build_sites as build, segment_grid};
use segvoronoi::{Diagram, EdgeEnd, EdgeId, EdgeShape, Point, Site};

/// How much farther `q` is from one site of the edge than from the other.
fn imbalance(d: &Diagram, sites: [segvoronoi::SiteId; 2], q: Point) -> f64 {
    (d.site(sites[0]).unwrap().distance(q) - d.site(sites[1]).unwrap().distance(q)).abs()
}

fn lerp(a: Point, b: Point, u: f64) -> Point {
    Point::new(a.x + (b.x - a.x) * u, a.y + (b.y - a.y) * u)
}

fn bezier_at([b0, b1, b2]: [Point; 3], u: f64) -> Point {
    let w = [(1.0 - u) * (1.0 - u), 2.0 * u * (1.0 - u), u * u];
    Point::new(w[0] * b0.x + w[1] * b1.x + w[2] * b2.x, w[0] * b0.y + w[1] * b1.y + w[2] * b2.y)
}

fn position(d: &Diagram, end: EdgeEnd) -> Option<Point> {
    match end {
        EdgeEnd::Vertex(v) => Some(d.vertex(v).unwrap().position),
        EdgeEnd::Infinite { .. } => None,
    }
}

/// The checks every diagram must pass, at polyline tolerance `tol`
/// (absolute); `eps` is the allowed rounding, relative to the largest
/// coordinate involved. Returns the number of parabolic edges.
fn check_edges(d: &Diagram, tol: f64, eps: f64) -> usize {
    let mut arcs = 0;
    for e in d.edges() {
        let shape = d.edge_shape(e.id).unwrap();
        let (Some(start), Some(end)) = (position(d, e.ends[0]), position(d, e.ends[1])) else {
            assert_eq!(d.edge_polyline(e.id, tol), None, "ray {e:?}");
            assert_eq!(d.edge_bezier(e.id), None, "ray {e:?}");
            continue;
        };
        let poly = d.edge_polyline(e.id, tol).unwrap();
        assert_eq!((poly[0], poly[poly.len() - 1]), (start, end), "{e:?}: the ends are the vertices");
        let scale = 1.0 + poly.iter().fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        // Every polyline point is on the edge, every chord within tol of it:
        // a point at distance δ from the bisector is at most 2δ farther from
        // one site than from the other.
        for w in poly.windows(2) {
            assert!(imbalance(d, e.sites, w[0]) <= eps * scale, "{e:?} {shape:?}: point {:?}", w[0]);
            for u in [0.25, 0.5, 0.75] {
                let q = lerp(w[0], w[1], u);
                assert!(imbalance(d, e.sites, q) <= 2.0 * tol + eps * scale, "{e:?} {shape:?}: chord at {q:?}");
            }
        }
        match shape {
            EdgeShape::Line => {
                assert_eq!(poly.len(), 2, "{e:?}");
                assert_eq!(d.edge_bezier(e.id), None, "{e:?}: a line has no Bézier");
            }
            EdgeShape::Parabola { focus, directrix } => {
                arcs += 1;
                // The shape names the edge's own sites.
                let sites = e.sites.map(|s| d.site(s).unwrap());
                assert!(sites.contains(&Site::Point(focus)), "{e:?}");
                let seg = sites.iter().find(|s| !s.is_point()).unwrap();
                assert_eq!(*seg, Site::Segment { a: directrix[0], b: directrix[1] });
                assert!(!seg.has_endpoint(focus));
                let bez = d.edge_bezier(e.id).unwrap();
                assert_eq!((bez[0], bez[2]), (start, end), "{e:?}: Bézier ends are the vertices");
                for u in [0.5, 0.1, 0.3, 0.9] {
                    let q = bezier_at(bez, u);
                    assert!(imbalance(d, e.sites, q) <= eps * scale, "{e:?}: B({u}) = {q:?}");
                }
            }
            other => panic!("a shape this test does not know: {other:?}"),
        }
    }
    arcs
}

#[test]
fn one_point_over_one_segment_by_hand() {
    // The point (2,2) over the segment (0,0)-(4,0): the arc is
    // y = ((x-2)^2 + 4) / 4 from x = 0 (the perpendicular at (0,0), where
    // the bisector of (2,2) and (0,0) also passes) to x = 4.
    let d = build(&[[2.0, 2.0]], &[[[0.0, 0.0], [4.0, 0.0]]]);
    let parabolic: Vec<_> = d.edges().filter(|e| d.edge_shape(e.id) != Some(EdgeShape::Line)).collect();
    assert_eq!(parabolic.len(), 1);
    let e = parabolic[0];
    assert_eq!(
        d.edge_shape(e.id),
        Some(EdgeShape::Parabola { focus: Point::new(2.0, 2.0), directrix: [Point::new(0.0, 0.0), Point::new(4.0, 0.0)] })
    );
    let [b0, b1, b2] = d.edge_bezier(e.id).unwrap();
    let mut xs = [b0.x, b2.x];
    xs.sort_by(f64::total_cmp);
    assert!(xs[0].abs() < 1e-12 && (xs[1] - 4.0).abs() < 1e-12, "{xs:?}");
    assert!((b0.y - 2.0).abs() < 1e-12 && (b2.y - 2.0).abs() < 1e-12);
    assert!(b1.distance(Point::new(2.0, 0.0)) < 1e-12, "tangents at x = 0 and 4 meet at (2, 0): {b1:?}");
    // The apex is the Bézier midpoint.
    assert!(bezier_at([b0, b1, b2], 0.5).distance(Point::new(2.0, 1.0)) < 1e-12);
    // y = x^2/4 + ... has curvature 1/2 at the apex: a tolerance of 1e-4
    // needs steps of sqrt(8 * 2 * 1e-4) = 0.04, 100 pieces over 4 units.
    let poly = d.edge_polyline(e.id, 1e-4).unwrap();
    assert_eq!(poly.len(), 101);
    for q in &poly {
        assert!((q.y - ((q.x - 2.0).powi(2) + 4.0) / 4.0).abs() < 1e-12, "{q:?}");
    }
    // A coarse tolerance still keeps the ends; an infinite one gives the chord.
    assert_eq!(d.edge_polyline(e.id, 10.0).unwrap().len(), 2);
    assert_eq!(d.edge_polyline(e.id, f64::INFINITY).unwrap().len(), 2);
    assert_eq!(check_edges(&d, 1e-4, 1e-12), 1);
}

#[test]
fn the_chord_check_catches_a_missing_curve() {
    // The test's own chord criterion fails for the straight chord of the arc
    // above (it strays 1 from the apex): so passing it means something.
    let d = build(&[[2.0, 2.0]], &[[[0.0, 0.0], [4.0, 0.0]]]);
    let e = d.edges().find(|e| d.edge_bezier(e.id).is_some()).unwrap();
    let poly = d.edge_polyline(e.id, 1e-3).unwrap();
    let chord_middle = lerp(poly[0], poly[poly.len() - 1], 0.5);
    assert!(imbalance(&d, e.sites, chord_middle) > 2.0 * 1e-3);
}

#[test]
fn random_points_and_segments() {
    let mut arcs = 0;
    for seed in 0..12 {
        let (pts, segs) = segment_grid(3 + seed as usize % 8, seed, 0.5);
        let d = build(&pts, &segs);
        for tol in [1e-2, 1e-5] {
            arcs += check_edges(&d, tol, 1e-9);
        }
    }
    assert!(arcs > 50, "only {arcs} parabolic edges");
}

#[test]
fn shared_endpoints_triangle_around_a_point() {
    // Each side sees the inner point over a parabolic arc; the corners'
    // separators and the bisectors between sides are straight.
    let segs = [[[0.0, 0.0], [4.0, 0.0]], [[4.0, 0.0], [1.0, 3.0]], [[1.0, 3.0], [0.0, 0.0]]];
    let d = build(&[[1.5, 1.0], [6.0, 4.0]], &segs);
    assert!(check_edges(&d, 1e-6, 1e-9) >= 3);
    // A side and its own corner: a separator, straight. Every corner has
    // two, one with each of its sides.
    let mut separators = 0;
    for e in d.edges() {
        let [a, b] = e.sites.map(|s| d.site(s).unwrap());
        let own_corner = match (a, b) {
            (Site::Point(p), s) | (s, Site::Point(p)) => s.has_endpoint(p),
            _ => false,
        };
        if own_corner {
            assert_eq!(d.edge_shape(e.id), Some(EdgeShape::Line), "{e:?}");
            separators += 1;
        }
    }
    assert_eq!(separators, 6);
}

#[test]
fn point_on_the_perpendicular_bisector_is_symmetric() {
    // Points right above the middle of the segment: each arc is symmetric
    // about x = 2, and so is its polyline.
    for h in [0.5, 2.0, 7.0] {
        let d = build(&[[2.0, h]], &[[[0.0, 0.0], [4.0, 0.0]]]);
        assert_eq!(check_edges(&d, 1e-5, 1e-12), 1);
        let e = d.edges().find(|e| d.edge_bezier(e.id).is_some()).unwrap();
        let [b0, b1, b2] = d.edge_bezier(e.id).unwrap();
        assert!((b1.x - 2.0).abs() < 1e-12 && (b0.x + b2.x - 4.0).abs() < 1e-12, "h={h}");
        let poly = d.edge_polyline(e.id, 1e-5).unwrap();
        for (p, q) in poly.iter().zip(poly.iter().rev()) {
            assert!((p.x + q.x - 4.0).abs() < 1e-12 && (p.y - q.y).abs() < 1e-12, "h={h}: {p:?} {q:?}");
        }
    }
}

#[test]
fn point_above_an_endpoint_has_its_apex_on_the_separator() {
    // (0,3) over the segment (0,0)-(4,0): the focus is on the perpendicular
    // at (0,0), so the arc starts at the parabola's apex (0, 1.5), where the
    // separator x = 0 and the bisector y = 1.5 of (0,3) and (0,0) meet it;
    // the tangent there is horizontal, so the Bézier control point is at
    // height 1.5 too. The other end is on the perpendicular at (4,0):
    // y = (16 + 9) / 6.
    let d = build(&[[0.0, 3.0]], &[[[0.0, 0.0], [4.0, 0.0]]]);
    assert_eq!(check_edges(&d, 1e-6, 1e-12), 1);
    let e = d.edges().find(|e| d.edge_bezier(e.id).is_some()).unwrap();
    let mut bez = d.edge_bezier(e.id).unwrap();
    if bez[0].x > bez[2].x {
        bez.reverse();
    }
    let [b0, b1, b2] = bez;
    assert!(b0.distance(Point::new(0.0, 1.5)) < 1e-12, "{b0:?}");
    assert!(b2.distance(Point::new(4.0, 25.0 / 6.0)) < 1e-12, "{b2:?}");
    assert!(b1.distance(Point::new(2.0, 1.5)) < 1e-12, "{b1:?}");
}

#[test]
fn point_on_the_supporting_line_gives_straight_edges() {
    // Beyond the end of the segment, on its line: no parabola anywhere.
    let d = build(&[[6.0, 3.0], [-2.0, -1.0]], &[[[0.0, 0.0], [4.0, 2.0]]]);
    assert_eq!(check_edges(&d, 1e-6, 1e-12), 0);
    assert!(d.edges().all(|e| d.edge_shape(e.id) == Some(EdgeShape::Line)));
}

#[test]
fn point_very_close_to_a_segment() {
    // Focal distance 1e-6: the point's cell is a sliver under the bisector
    // y = 2.5 with (2, 5), a tight, tall arc (half-width sqrt(5e-6) at that
    // height) that needs about 50 points for 1e-3.
    let d = build(&[[2.0, 1e-6], [2.0, 5.0]], &[[[0.0, 0.0], [4.0, 0.0]]]);
    assert!(check_edges(&d, 1e-3, 1e-9) >= 1);
    let near = Site::Point(Point::new(2.0, 1e-6));
    let arcs: Vec<_> =
        d.edges().filter(|e| d.edge_bezier(e.id).is_some() && e.sites.map(|s| d.site(s)).contains(&Some(near))).collect();
    assert_eq!(arcs.len(), 1, "the sliver has one arc");
    let poly = d.edge_polyline(arcs[0].id, 1e-3).unwrap();
    assert!((45..=55).contains(&poly.len()), "{} points", poly.len());
    let top = poly.iter().map(|q| q.y).fold(f64::NEG_INFINITY, f64::max);
    assert!((top - 2.5).abs() < 1e-6, "the arc ends on the bisector y = 2.5, not {top}");
}

#[test]
fn too_fine_a_tolerance_is_capped() {
    let d = build(&[[2.0, 2.0]], &[[[0.0, 0.0], [4.0, 0.0]]]);
    let e = d.edges().find(|e| d.edge_bezier(e.id).is_some()).unwrap();
    let poly = d.edge_polyline(e.id, 1e-300).unwrap();
    assert_eq!(poly.len(), 1_000_000);
    assert_eq!(poly[0], d.edge_bezier(e.id).unwrap()[0]);
}

#[test]
fn extreme_magnitudes_scale_exactly() {
    // A power of two scales every answer by itself: the arc is computed in
    // the diagram's normalised coordinates, so 1e300-sized input does not
    // overflow (s^2 would) and 1e-300-sized input does not underflow.
    let points = [[2.0, 2.0], [5.0, 3.0], [-1.0, 2.5]];
    let segs = [[[0.0, 0.0], [4.0, 0.0]], [[1.0, 4.0], [3.0, 5.0]]];
    let reference = build(&points, &segs);
    let tol = 1e-4;
    assert!(check_edges(&reference, tol, 1e-12) >= 2);
    for factor in [2f64.powi(990), 2f64.powi(-1000)] {
        let sp: Vec<[f64; 2]> = points.iter().map(|p| [p[0] * factor, p[1] * factor]).collect();
        let ss: Vec<[[f64; 2]; 2]> = segs.iter().map(|s| s.map(|p| [p[0] * factor, p[1] * factor])).collect();
        let d = build(&sp, &ss);
        assert_eq!(d.edge_count(), reference.edge_count());
        for e in reference.edges() {
            let (a, b) = (reference.edge_polyline(e.id, tol), d.edge_polyline(e.id, tol * factor));
            assert_eq!(a.is_some(), b.is_some());
            if let (Some(a), Some(b)) = (a, b) {
                assert_eq!(
                    a.len(),
                    b.len(),
                    "{e:?} factor {factor:e}: {:?} vs {:?}",
                    reference.edge_shape(e.id),
                    d.edge_shape(e.id)
                );
                for (p, q) in a.iter().zip(&b) {
                    assert!(q.is_finite() && p.distance(Point::new(q.x / factor, q.y / factor)) < 1e-12, "{p:?} {q:?}");
                }
            }
            match (reference.edge_bezier(e.id), d.edge_bezier(e.id)) {
                (None, None) => {}
                (Some(a), Some(b)) => {
                    for (p, q) in a.iter().zip(&b) {
                        assert!(p.distance(Point::new(q.x / factor, q.y / factor)) < 1e-12, "{p:?} {q:?}");
                    }
                }
                other => panic!("{e:?}: {other:?}"),
            }
        }
    }
}

#[test]
fn refusals() {
    let d = build(&[[2.0, 2.0]], &[[[0.0, 0.0], [4.0, 0.0]]]);
    let arc = d.edges().find(|e| d.edge_bezier(e.id).is_some()).unwrap().id;
    for tol in [0.0, -1.0, f64::NAN, f64::NEG_INFINITY] {
        assert_eq!(d.edge_polyline(arc, tol), None, "tolerance {tol}");
    }
    let ray = d.edges().find(|e| e.is_infinite()).unwrap().id;
    assert_eq!(d.edge_polyline(ray, 1.0), None);
    assert_eq!(d.edge_bezier(ray), None);
    assert!(d.edge_shape(ray).is_some());
    let beyond = EdgeId::from_index(d.edge_count());
    assert_eq!(d.edge_shape(beyond), None);
    assert_eq!(d.edge_polyline(beyond, 1.0), None);
    assert_eq!(d.edge_bezier(beyond), None);
    // Points only: every edge is straight.
    let p = build(&[[0.0, 0.0], [3.0, 0.5], [1.0, 2.0], [2.0, 1.0]], &[]);
    assert!(p.edges().all(|e| p.edge_shape(e.id) == Some(EdgeShape::Line) && p.edge_bezier(e.id).is_none()));
    assert_eq!(check_edges(&p, 1e-3, 1e-12), 0);
}
