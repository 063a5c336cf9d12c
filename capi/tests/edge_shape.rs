//! Edge geometry through the C API (`segvoronoi_diagram_edge_shape`,
//! `_edge_polyline`, `_edge_bezier`, `_cell_is_unbounded`,
//! `_cell_neighbors`) gives what the Rust API gives (which
//! `tests/edge_shape.rs` checks against the geometry), with the list and
//! error conventions of the header.

#[path = "../../integration/tests/common/mod.rs"]
mod common;

use common::build_sites as build;
use segvoronoi::{Diagram, EdgeShape};
use segvoronoi_capi::*;

/// The diagram of `points` and `segments`, built through the C API.
fn c_diagram(points: &[f64], segments: &[f64]) -> *mut segvoronoi_diagram {
    unsafe {
        let b = segvoronoi_builder_new();
        assert_eq!(segvoronoi_builder_add_points(b, points.as_ptr(), points.len() / 2), segvoronoi_status::Ok);
        assert_eq!(segvoronoi_builder_add_segments(b, segments.as_ptr(), segments.len() / 4), segvoronoi_status::Ok);
        let mut d = std::ptr::null_mut();
        assert_eq!(segvoronoi_builder_build(b, &mut d), segvoronoi_status::Ok);
        segvoronoi_builder_free(b);
        d
    }
}

/// Two points and two segments (at least two parabolic arcs), built
/// through Rust and through C.
fn two_points_two_segments() -> (Diagram, *mut segvoronoi_diagram) {
    let (points, segments) = ([2.0, 2.0, 5.0, 3.0], [0.0, 0.0, 4.0, 0.0, 1.0, 4.0, 3.0, 5.0]);
    let rust = build(&[[2.0, 2.0], [5.0, 3.0]], &[[[0.0, 0.0], [4.0, 0.0]], [[1.0, 4.0], [3.0, 5.0]]]);
    (rust, c_diagram(&points, &segments))
}

#[test]
fn c_edge_shape_agrees_with_rust() {
    let (rust, d) = two_points_two_segments();
    unsafe {
        assert_eq!(segvoronoi_diagram_edge_count(d), rust.edge_count());
        let mut parabolas = 0;
        for e in rust.edges() {
            let mut out = segvoronoi_edge_shape { kind: 99, ..Default::default() };
            assert_eq!(segvoronoi_diagram_edge_shape(d, e.id.index(), &mut out), segvoronoi_status::Ok);
            match rust.edge_shape(e.id).unwrap() {
                EdgeShape::Line => {
                    assert_eq!(out.kind, SEGVORONOI_EDGE_LINE);
                    assert_eq!([out.focus_x, out.focus_y, out.directrix_x1, out.directrix_y2], [0.0; 4]);
                }
                EdgeShape::Parabola { focus, directrix: [a, b] } => {
                    parabolas += 1;
                    assert_eq!(out.kind, SEGVORONOI_EDGE_PARABOLA);
                    assert_eq!((out.focus_x, out.focus_y), (focus.x, focus.y));
                    assert_eq!([out.directrix_x1, out.directrix_y1, out.directrix_x2, out.directrix_y2], [a.x, a.y, b.x, b.y]);
                }
                other => panic!("a shape this test does not know: {other:?}"),
            }
        }
        assert!(parabolas >= 2);
        // Errors leave *out alone.
        let mut out = segvoronoi_edge_shape { kind: 7, ..Default::default() };
        let n = rust.edge_count();
        assert_eq!(segvoronoi_diagram_edge_shape(d, n, &mut out), segvoronoi_status::OutOfRange);
        assert_eq!(segvoronoi_diagram_edge_shape(d, usize::MAX, &mut out), segvoronoi_status::OutOfRange);
        assert_eq!(segvoronoi_diagram_edge_shape(std::ptr::null(), 0, &mut out), segvoronoi_status::NullArgument);
        assert_eq!(segvoronoi_diagram_edge_shape(d, 0, std::ptr::null_mut()), segvoronoi_status::NullArgument);
        assert_eq!(out.kind, 7);
        segvoronoi_diagram_free(d);
    }
}

#[test]
fn c_edge_polyline_buffer_convention() {
    let rust = build(&[[2.0, 2.0]], &[[[0.0, 0.0], [4.0, 0.0]]]);
    let d = c_diagram(&[2.0, 2.0], &[0.0, 0.0, 4.0, 0.0]);
    let arc = rust.edges().find(|e| rust.edge_bezier(e.id).is_some()).unwrap().id;
    let line = rust.edges().find(|e| !e.is_infinite() && rust.edge_bezier(e.id).is_none()).map(|e| e.id);
    let ray = rust.edges().find(|e| e.is_infinite()).unwrap().id;
    let expected = rust.edge_polyline(arc, 1e-3).unwrap();
    let n = expected.len();
    assert!(n > 10);
    unsafe {
        // Asking for the count: (NULL, 0) is OK.
        let mut count = 0usize;
        let st = segvoronoi_diagram_edge_polyline(d, arc.index(), 1e-3, std::ptr::null_mut(), 0, &mut count);
        assert_eq!((st, count), (segvoronoi_status::Ok, n));
        // Exactly enough room.
        let mut xy = vec![f64::NAN; 2 * n];
        count = 0;
        let st = segvoronoi_diagram_edge_polyline(d, arc.index(), 1e-3, xy.as_mut_ptr(), n, &mut count);
        assert_eq!((st, count), (segvoronoi_status::Ok, n));
        for (k, p) in expected.iter().enumerate() {
            assert_eq!((xy[2 * k], xy[2 * k + 1]), (p.x, p.y));
        }
        // Too little: the first points are written, nothing beyond.
        let mut small = vec![-7.0; 2 * 4 + 2];
        let st = segvoronoi_diagram_edge_polyline(d, arc.index(), 1e-3, small.as_mut_ptr(), 4, &mut count);
        assert_eq!((st, count), (segvoronoi_status::BufferTooSmall, n));
        assert_eq!((small[0], small[7]), (expected[0].x, expected[3].y));
        assert_eq!(&small[8..], &[-7.0, -7.0]);
        // A straight edge: two points.
        if let Some(line) = line {
            let mut two = [0.0; 4];
            let st = segvoronoi_diagram_edge_polyline(d, line.index(), 1e-3, two.as_mut_ptr(), 2, &mut count);
            assert_eq!((st, count), (segvoronoi_status::Ok, 2));
        }
        // Errors: *count untouched.
        count = 12345;
        for tol in [0.0, -1.0, f64::NAN] {
            let st = segvoronoi_diagram_edge_polyline(d, arc.index(), tol, xy.as_mut_ptr(), n, &mut count);
            assert_eq!(st, segvoronoi_status::InvalidArgument, "tolerance {tol}");
        }
        let st = segvoronoi_diagram_edge_polyline(d, ray.index(), 1e-3, xy.as_mut_ptr(), n, &mut count);
        assert_eq!(st, segvoronoi_status::InvalidArgument, "a ray");
        let st = segvoronoi_diagram_edge_polyline(d, rust.edge_count(), 1e-3, xy.as_mut_ptr(), n, &mut count);
        assert_eq!(st, segvoronoi_status::OutOfRange);
        assert_eq!(count, 12345);
        let st = segvoronoi_diagram_edge_polyline(d, arc.index(), 1e-3, std::ptr::null_mut(), 1, &mut count);
        assert_eq!(st, segvoronoi_status::NullArgument);
        let st = segvoronoi_diagram_edge_polyline(d, arc.index(), 1e-3, xy.as_mut_ptr(), n, std::ptr::null_mut());
        assert_eq!(st, segvoronoi_status::NullArgument);
        let st = segvoronoi_diagram_edge_polyline(std::ptr::null(), 0, 1e-3, xy.as_mut_ptr(), n, &mut count);
        assert_eq!(st, segvoronoi_status::NullArgument);
        assert_eq!(count, 12345);
        segvoronoi_diagram_free(d);
    }
}

#[test]
fn c_edge_bezier_and_unbounded_agree_with_rust() {
    let (rust, d) = two_points_two_segments();
    unsafe {
        let mut arcs = 0;
        for e in rust.edges() {
            let mut xy = [f64::NAN; 6];
            let st = segvoronoi_diagram_edge_bezier(d, e.id.index(), xy.as_mut_ptr());
            match rust.edge_bezier(e.id) {
                Some(curve) => {
                    arcs += 1;
                    assert_eq!(st, segvoronoi_status::Ok);
                    assert_eq!(xy, [curve[0].x, curve[0].y, curve[1].x, curve[1].y, curve[2].x, curve[2].y]);
                }
                None => {
                    assert_eq!(st, segvoronoi_status::InvalidArgument, "{e:?}");
                    assert!(xy.iter().all(|c| c.is_nan()), "nothing written on error");
                }
            }
            let mut edge = segvoronoi_edge::default();
            assert_eq!(segvoronoi_diagram_edge(d, e.id.index(), &mut edge), segvoronoi_status::Ok);
            assert_eq!(edge.is_infinite, e.is_infinite());
        }
        assert!(arcs >= 2);
        let mut xy = [0.0; 6];
        assert_eq!(segvoronoi_diagram_edge_bezier(d, rust.edge_count(), xy.as_mut_ptr()), segvoronoi_status::OutOfRange);
        assert_eq!(segvoronoi_diagram_edge_bezier(d, 0, std::ptr::null_mut()), segvoronoi_status::NullArgument);
        for cell in rust.cells() {
            let mut unbounded = !cell.is_unbounded();
            assert_eq!(segvoronoi_diagram_cell_is_unbounded(d, cell.site().index(), &mut unbounded), segvoronoi_status::Ok);
            assert_eq!(unbounded, cell.is_unbounded());
            let mut count = 0;
            let st = segvoronoi_diagram_cell_neighbors(d, cell.site().index(), std::ptr::null_mut(), 0, &mut count);
            assert_eq!((st, count), (segvoronoi_status::Ok, cell.neighbors().count()));
            let mut ids = vec![u32::MAX; count];
            let st = segvoronoi_diagram_cell_neighbors(d, cell.site().index(), ids.as_mut_ptr(), count, &mut count);
            assert_eq!(st, segvoronoi_status::Ok);
            assert!(ids.iter().map(|&s| s as usize).eq(cell.neighbors().map(|s| s.index())));
        }
        segvoronoi_diagram_free(d);
    }
}
