//! Polygon input and the domain (`Builder::add_polygon`,
//! `Diagram::vertex_location`, `edge_location`, `cell_location`,
//! `locate_point`): the classification, made from the topology and exact
//! orientation tests, agrees with a plain even-odd test of the vertices'
//! positions on inputs where those are far from the boundary, does not
//! depend on the rings' orientation or order, and keeps obstacles apart.

mod common;

use common::star_ring;
use segvoronoi::{Builder, Diagram, ErrorKind, Location, Point};

/// Distance from `p` to the nearest ring edge.
fn boundary_distance(rings: &[Vec<[f64; 2]>], p: Point) -> f64 {
    let mut best = f64::INFINITY;
    for ring in rings {
        for k in 0..ring.len() {
            let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
            let s = segvoronoi::Site::Segment { a: Point::new(a[0], a[1]), b: Point::new(b[0], b[1]) };
            best = best.min(s.distance(p));
        }
    }
    best
}

fn build(rings: &[Vec<[f64; 2]>], points: &[[f64; 2]]) -> Diagram {
    let mut b = Builder::new();
    b.add_polygon(rings).expect("a valid polygon");
    b.add_points(points.iter().copied()).expect("points");
    b.build().expect("a diagram")
}

/// Every vertex away from the boundary is classified as the plain test
/// says; vertices on it only at ring corners; every edge as its ends.
fn check_against_positions(rings: &[Vec<[f64; 2]>], d: &Diagram) -> (usize, usize) {
    d.validate().unwrap();
    assert!(d.has_domain());
    let (mut inside, mut outside) = (0, 0);
    for v in d.vertices() {
        let location = d.vertex_location(v.id).unwrap();
        let away = boundary_distance(rings, v.position);
        if location == Location::Boundary {
            assert!(away < 1e-9, "a boundary vertex {v:?} off the boundary by {away}");
            continue;
        }
        if away > 1e-9 {
            let expected = if common::even_odd(rings, v.position) { Location::Inside } else { Location::Outside };
            assert_eq!(location, expected, "vertex {v:?}");
        }
        match location {
            Location::Inside => inside += 1,
            _ => outside += 1,
        }
    }
    for e in d.edges() {
        let location = d.edge_location(e.id).unwrap();
        for end in e.ends {
            if let segvoronoi::EdgeEnd::Vertex(v) = end {
                let at = d.vertex_location(v).unwrap();
                assert!(at == location || at == Location::Boundary, "edge {e:?} {location:?} has an end {at:?}");
            }
        }
    }
    (inside, outside)
}

fn square(x0: f64, y0: f64, side: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x0 + side, y0], [x0 + side, y0 + side], [x0, y0 + side]]
}

#[test]
fn a_square_with_a_hole_and_an_island() {
    let rings = vec![square(0.0, 0.0, 10.0), square(2.0, 2.0, 6.0), square(4.0, 4.0, 2.0)];
    let d = build(&rings, &[]);
    let (inside, outside) = check_against_positions(&rings, &d);
    assert!(inside > 0 && outside > 0);
    assert_eq!(d.locate_point(Point::new(1.0, 1.0)), Some(Location::Inside));
    assert_eq!(d.locate_point(Point::new(3.0, 3.0)), Some(Location::Outside));
    assert_eq!(d.locate_point(Point::new(5.0, 5.0)), Some(Location::Inside));
    assert_eq!(d.locate_point(Point::new(0.0, 5.0)), Some(Location::Boundary));
    assert_eq!(d.locate_point(Point::new(20.0, 5.0)), Some(Location::Outside));
}

#[test]
fn orientation_and_order_of_rings_do_not_matter() {
    let mut rng = common::Rng(11);
    let outer = star_ring(40, 0.0, 0.0, 8.0, 10.0, &mut rng);
    let hole = star_ring(12, 1.0, -1.0, 2.0, 3.0, &mut rng);
    let reference = build(&[outer.clone(), hole.clone()], &[]);
    check_against_positions(&[outer.clone(), hole.clone()], &reference);
    let reversed = |r: &Vec<[f64; 2]>| r.iter().rev().copied().collect::<Vec<_>>();
    for rings in [vec![reversed(&outer), hole.clone()], vec![outer.clone(), reversed(&hole)], vec![hole.clone(), outer.clone()]] {
        let d = build(&rings, &[]);
        check_against_positions(&rings, &d);
        let count = |d: &Diagram, l| d.vertices().filter(|v| d.vertex_location(v.id) == Some(l)).count();
        for l in [Location::Inside, Location::Outside, Location::Boundary] {
            assert_eq!(count(&d, l), count(&reference, l));
        }
    }
}

#[test]
fn random_star_polygons_with_holes_and_obstacles() {
    let mut rng = common::Rng(5);
    for _ in 0..30 {
        let n = 8 + (rng.next_u64() % 60) as usize;
        let rings = vec![star_ring(n, 0.0, 0.0, 6.0, 10.0, &mut rng), star_ring(7, 0.0, 0.0, 1.0, 2.5, &mut rng)];
        // obstacles: points between the hole and the outer ring, and far out
        let points = [[3.5, 0.2], [-0.3, 4.0], [30.0, 30.0]];
        let d = build(&rings, &points);
        check_against_positions(&rings, &d);
        for (k, p) in points.iter().enumerate() {
            let site = d.site_of_input(k).unwrap();
            let expected = if common::even_odd(&rings, Point::new(p[0], p[1])) { Location::Inside } else { Location::Outside };
            assert_eq!(d.cell_location(site), Some(expected));
        }
    }
}

#[test]
fn polygon_input_rules() {
    let mut b = Builder::new();
    // a repeated closing point and repeated consecutive points are dropped
    let made = b.add_polygon(&[vec![[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 0.0]]]).unwrap();
    assert_eq!(made, vec![0..3]);
    assert_eq!(b.segment_count(), 3);
    // fewer than three distinct points: an error naming polygon and ring, nothing added
    let e = b.add_polygon(&[square(5.0, 5.0, 1.0), vec![[0.0, 0.0], [2.0, 0.0], [2.0, 0.0]]]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::InvalidPolygon);
    assert_eq!(e.indices(), &[1, 1]);
    assert_eq!(b.segment_count(), 3);
    let e = b.add_polygon(&[vec![[0.0, 0.0], [f64::NAN, 0.0], [2.0, 3.0]]]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::InvalidCoordinate);
    assert_eq!(b.segment_count(), 3);
    // a polyline is an obstacle, not a ring
    assert_eq!(b.add_polyline(&[[3.0, 3.0], [4.0, 3.0], [4.0, 3.0], [4.0, 4.0]]).unwrap(), 3..5);
    // the dropped points are counted (the ring's one repeat and the
    // polyline's; not the ring's closing point, nor the rejected rings')
    assert_eq!(b.build().unwrap().stats().dropped_chain_points, 2);
    // rings that cross: the build names both segments and their rings
    let mut c = Builder::new();
    c.add_polygon(&[square(0.0, 0.0, 4.0), square(2.0, 2.0, 4.0)]).unwrap();
    let e = c.build().unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Intersecting);
    assert!(e.message().contains("polygon 0, ring 0") && e.message().contains("ring 1"), "{}", e.message());
    // rings that share an edge: its two copies cancel (even-odd), the
    // domain is the union rectangle (tests/shared_stretches.rs)
    let mut shared = Builder::new();
    shared.add_polygon(&[square(0.0, 0.0, 4.0)]).unwrap();
    shared.add_polygon(&[square(4.0, 0.0, 4.0)]).unwrap();
    let d = shared.build().unwrap();
    assert_eq!(d.stats().cancelled_ring_pieces, 2);
    assert_eq!(d.locate_point(Point::new(4.0, 2.0)), Some(Location::Inside));
    // no polygon: no domain
    let mut p = Builder::new();
    p.add_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).unwrap();
    let d = p.build().unwrap();
    assert!(!d.has_domain());
    assert_eq!(d.vertex_location(segvoronoi::VertexId::from_index(0)), None);
}
