//! Polygons of segments and arcs through the C API
//! (`segvoronoi_builder_add_bulged_polygon`) agree with the Rust API
//! (`Builder::add_bulged_polygon`): the same pieces, the same locations,
//! offsets of both signs with the same areas and loops, the same largest
//! inscribed circle; bad rings are refused naming the polygon, ring and
//! vertex, with the builder unchanged. (Mirrors
//! `integration/tests/arc_offsets.rs`.)

use segvoronoi::{Builder, Location, Point};
use segvoronoi_capi::*;

/// A 10 × 6 rounded rectangle (corner radius 1.5) with a round hole (two
/// half circles): the rings as (x, y, bulge).
fn rings() -> Vec<Vec<(f64, f64, f64)>> {
    let q = (std::f64::consts::PI / 8.0).tan();
    vec![
        vec![
            (1.5, 0.0, 0.0),
            (8.5, 0.0, q),
            (10.0, 1.5, 0.0),
            (10.0, 4.5, q),
            (8.5, 6.0, 0.0),
            (1.5, 6.0, q),
            (0.0, 4.5, 0.0),
            (0.0, 1.5, q),
        ],
        vec![(2.0, 3.0, 1.0), (4.0, 3.0, 1.0)],
    ]
}

fn rust_diagram() -> segvoronoi::Diagram {
    let rings: Vec<Vec<([f64; 2], f64)>> = rings().iter().map(|r| r.iter().map(|&(x, y, b)| ([x, y], b)).collect()).collect();
    let mut b = Builder::new();
    b.add_bulged_polygon(&rings).unwrap();
    b.build().unwrap()
}

/// The rings through C, flattened.
unsafe fn add_through_c(b: *mut segvoronoi_builder, rings: &[Vec<(f64, f64, f64)>]) -> segvoronoi_status {
    let xy: Vec<f64> = rings.iter().flatten().flat_map(|&(x, y, _)| [x, y]).collect();
    let bulges: Vec<f64> = rings.iter().flatten().map(|&(_, _, b)| b).collect();
    let lengths: Vec<usize> = rings.iter().map(Vec::len).collect();
    unsafe { segvoronoi_builder_add_bulged_polygon(b, xy.as_ptr(), bulges.as_ptr(), lengths.as_ptr(), lengths.len()) }
}

#[test]
fn bulged_polygons_agree_with_rust() {
    let rust = rust_diagram();
    unsafe {
        let b = segvoronoi_builder_new();
        assert_eq!(add_through_c(b, &rings()), segvoronoi_status::Ok);
        assert_eq!((segvoronoi_builder_segment_count(b), segvoronoi_builder_arc_count(b)), (4, 6));
        let mut d = std::ptr::null_mut();
        assert_eq!(segvoronoi_builder_build(b, &mut d), segvoronoi_status::Ok);
        segvoronoi_builder_free(b);
        // locations
        for (x, y) in [(0.3, 0.3), (0.8, 0.8), (3.0, 3.0), (3.0, 4.1), (2.0, 3.0), (11.0, 3.0)] {
            let mut at = u32::MAX;
            assert_eq!(segvoronoi_diagram_locate_point(d, x, y, &mut at), segvoronoi_status::Ok);
            let want = match rust.locate_point(Point::new(x, y)).unwrap() {
                Location::Inside => SEGVORONOI_LOCATION_INSIDE,
                Location::Outside => SEGVORONOI_LOCATION_OUTSIDE,
                _ => SEGVORONOI_LOCATION_BOUNDARY,
            };
            assert_eq!(at, want, "({x}, {y})");
        }
        // offsets of both signs
        for distance in [-0.4, -1.0, 0.3, 1.2] {
            let mut o = std::ptr::null_mut();
            assert_eq!(segvoronoi_diagram_offset(d, distance, &mut o), segvoronoi_status::Ok, "{distance}");
            let want = rust.offset(distance).unwrap();
            assert_eq!(segvoronoi_offset_loop_count(o), want.loops.len(), "{distance}");
            assert_eq!(segvoronoi_offset_area(o), want.area(), "{distance}");
            segvoronoi_offset_free(o);
        }
        // the largest inscribed circle
        let (mut x, mut y, mut r) = (0.0, 0.0, 0.0);
        assert_eq!(segvoronoi_diagram_max_inscribed_circle(d, &mut x, &mut y, &mut r), segvoronoi_status::Ok);
        let (centre, radius) = rust.max_inscribed_circle().unwrap();
        assert_eq!((x, y, r), (centre.x, centre.y, radius));
        segvoronoi_diagram_free(d);
    }
}

#[test]
fn bad_rings_are_refused_naming_the_vertex() {
    let good = rings();
    let cases: [(Vec<(f64, f64, f64)>, segvoronoi_status, Vec<usize>); 3] = [
        (vec![(0.0, 0.0, 0.0), (1.0, 0.0, f64::NAN), (1.0, 1.0, 0.0)], segvoronoi_status::InvalidCoordinate, vec![1, 0, 1]),
        (vec![(0.0, 0.0, 0.0), (1.0, 0.0, 0.0)], segvoronoi_status::InvalidPolygon, vec![1, 0]),
        (vec![(0.0, 0.0, 0.0), (1e10, 0.0, 0.0), (1e10, 1e10, 1e300)], segvoronoi_status::InvalidArc, vec![1, 0, 2]),
    ];
    for (ring, status, indices) in cases {
        unsafe {
            let b = segvoronoi_builder_new();
            assert_eq!(add_through_c(b, &good), segvoronoi_status::Ok);
            let before = (segvoronoi_builder_segment_count(b), segvoronoi_builder_arc_count(b));
            assert_eq!(add_through_c(b, &[ring.clone()]), status, "{ring:?}");
            let (mut got, mut n) = ([0usize; 4], 0usize);
            assert_eq!(segvoronoi_builder_last_error_indices(b, got.as_mut_ptr(), 4, &mut n), segvoronoi_status::Ok);
            assert_eq!(&got[..n], &indices[..], "{ring:?}");
            assert_eq!((segvoronoi_builder_segment_count(b), segvoronoi_builder_arc_count(b)), before);
            // NULL arrays with vertices
            let lengths = [3usize];
            assert_eq!(
                segvoronoi_builder_add_bulged_polygon(b, std::ptr::null(), std::ptr::null(), lengths.as_ptr(), 1),
                segvoronoi_status::NullArgument
            );
            segvoronoi_builder_free(b);
        }
    }
}
