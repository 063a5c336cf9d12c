//! Arcs through the C API agree with the Rust API: the builder's arcs, a
//! diagram's arc sites and conic edges (shape, rational Bézier) read through
//! C are what Rust gives for the same input. (`c_tests/test_arcs.c` tests
//! the same calls from C, against distances computed there.)

use segvoronoi::{Builder, CircularArc, EdgeId, EdgeShape, Site, SiteId};
use segvoronoi_capi::*;

/// A slot (two half circles joined by segments) and two points, one inside
/// a half disc (its edge with that arc is an ellipse), added through C as a
/// bulged polyline, and through Rust the same way.
fn slot() -> (segvoronoi::Diagram, *mut segvoronoi_diagram) {
    let xy = [0.0, 0.0, 4.0, 0.0, 4.0, 2.0, 0.0, 2.0];
    let bulges = [0.0, 1.0, 0.0, 1.0];
    let points = [1.25, 0.75, 4.5, 1.0];
    let mut rust = Builder::new();
    rust.add_bulged_polyline(&[([0.0, 0.0], 0.0), ([4.0, 0.0], 1.0), ([4.0, 2.0], 0.0), ([0.0, 2.0], 1.0)], true).unwrap();
    rust.add_points([[1.25, 0.75], [4.5, 1.0]]).unwrap();
    unsafe {
        let b = segvoronoi_builder_new();
        let (mut kinds, mut indices, mut n) = ([9u32; 4], [9usize; 4], 0usize);
        let st = segvoronoi_builder_add_bulged_polyline(
            b,
            xy.as_ptr(),
            bulges.as_ptr(),
            4,
            true,
            kinds.as_mut_ptr(),
            indices.as_mut_ptr(),
            &mut n,
        );
        assert_eq!(st, segvoronoi_status::Ok);
        assert_eq!(n, 4);
        assert_eq!(kinds, [SEGVORONOI_SITE_SEGMENT, SEGVORONOI_SITE_ARC, SEGVORONOI_SITE_SEGMENT, SEGVORONOI_SITE_ARC]);
        assert_eq!(indices, [0, 0, 1, 1]);
        assert_eq!(segvoronoi_builder_add_points(b, points.as_ptr(), 2), segvoronoi_status::Ok);
        let mut d = std::ptr::null_mut();
        assert_eq!(segvoronoi_builder_build(b, &mut d), segvoronoi_status::Ok);
        segvoronoi_builder_free(b);
        (rust.build().unwrap(), d)
    }
}

#[test]
fn arc_sites_and_conic_edges_agree_with_rust() {
    let (rust, d) = slot();
    unsafe {
        assert_eq!(segvoronoi_diagram_site_count(d), rust.site_count());
        assert_eq!(segvoronoi_diagram_arc_site_count(d), rust.arc_site_count());
        assert_eq!(rust.arc_site_count(), 2);
        for i in 0..rust.site_count() {
            let mut site = segvoronoi_site::default();
            assert_eq!(segvoronoi_diagram_site(d, i, &mut site), segvoronoi_status::Ok);
            let mut arc = segvoronoi_arc::default();
            let status = segvoronoi_diagram_arc(d, i, &mut arc);
            match rust.site(SiteId::from_index(i)).unwrap() {
                Site::Arc(a) => {
                    assert_eq!(status, segvoronoi_status::Ok);
                    assert_eq!(site.kind, SEGVORONOI_SITE_ARC);
                    assert_eq!((arc.start, arc.end), (a.start().into(), a.end().into()));
                    assert_eq!((arc.centre, arc.radius, arc.bulge), (a.centre().into(), a.radius(), a.bulge()));
                    assert!((arc.sweep - a.sweep()).abs() < 1e-12);
                    assert_eq!(arc.sweep, 4.0 * a.bulge().atan());
                    assert_eq!((arc.counter_clockwise, arc.has_via), (a.is_counter_clockwise(), false));
                    let (mut input, mut back) = (usize::MAX, u32::MAX);
                    assert_eq!(segvoronoi_diagram_arc_input_index(d, i, &mut input), segvoronoi_status::Ok);
                    assert_eq!(Some(input), rust.arc_input_index(SiteId::from_index(i)));
                    assert_eq!(segvoronoi_diagram_site_of_arc(d, input, &mut back), segvoronoi_status::Ok);
                    assert_eq!(back as usize, i);
                    let mut ends = [u32::MAX; 2];
                    assert_eq!(segvoronoi_diagram_segment_endpoints(d, i, ends.as_mut_ptr()), segvoronoi_status::Ok);
                    let rust_ends = rust.segment_endpoints(SiteId::from_index(i)).unwrap();
                    assert_eq!(ends, rust_ends.map(|s| s.index() as u32));
                    assert_eq!(segvoronoi_diagram_segment_input_index(d, i, &mut input), segvoronoi_status::InvalidArgument);
                }
                _ => assert_eq!(status, segvoronoi_status::InvalidArgument),
            }
        }
        let mut conics = 0;
        for e in 0..rust.edge_count() {
            let mut shape = segvoronoi_edge_shape::default();
            assert_eq!(segvoronoi_diagram_edge_shape(d, e, &mut shape), segvoronoi_status::Ok);
            let rust_shape = rust.edge_shape(EdgeId::from_index(e)).unwrap();
            assert_eq!(shape.kind == SEGVORONOI_EDGE_CONIC, matches!(rust_shape, EdgeShape::Conic { .. }));
            conics += usize::from(shape.kind == SEGVORONOI_EDGE_CONIC);
            let (mut xy, mut w) = ([0.0; 6], 0.0);
            let status = segvoronoi_diagram_edge_rational_bezier(d, e, xy.as_mut_ptr(), &mut w);
            match rust.edge_rational_bezier(EdgeId::from_index(e)) {
                Some((p, weight)) => {
                    assert_eq!(status, segvoronoi_status::Ok);
                    assert_eq!(xy, [p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y]);
                    assert_eq!(w, weight);
                }
                None => assert_eq!(status, segvoronoi_status::InvalidArgument),
            }
        }
        assert!(conics > 0);
        let mut stats = segvoronoi_stats::default();
        assert_eq!(segvoronoi_diagram_stats(d, &mut stats), segvoronoi_status::Ok);
        assert_eq!((stats.input_arcs, stats.arc_sites), (2, 2));
        segvoronoi_diagram_free(d);
    }
}

#[test]
fn invalid_arcs_map_to_invalid_arc_and_leave_the_builder_unchanged() {
    unsafe {
        let b = segvoronoi_builder_new();
        let mut index = 77usize;
        assert_eq!(segvoronoi_builder_add_arc(b, 0.0, 0.0, 1.0, 0.0, 0.0, &mut index), segvoronoi_status::InvalidArc);
        assert_eq!(
            segvoronoi_builder_add_arc_through(b, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, &mut index),
            segvoronoi_status::InvalidArc
        );
        assert_eq!(segvoronoi_builder_add_arc(b, f64::NAN, 0.0, 1.0, 0.0, 1.0, &mut index), segvoronoi_status::InvalidCoordinate);
        assert_eq!((index, segvoronoi_builder_arc_count(b)), (77, 0));
        // the Rust error kind maps to the C status
        let e = CircularArc::from_bulge([0.0, 0.0], [1.0, 0.0], 0.0).unwrap_err();
        assert_eq!(e.kind(), segvoronoi::ErrorKind::InvalidArc);
        assert_eq!(segvoronoi_builder_add_arc(b, 0.0, 0.0, 1.0, 0.0, 1.0, &mut index), segvoronoi_status::Ok);
        assert_eq!((index, segvoronoi_builder_arc_count(b)), (0, 1));
        let mut arc = segvoronoi_arc::default();
        assert_eq!(segvoronoi_builder_arc(b, 0, &mut arc), segvoronoi_status::Ok);
        let rust = CircularArc::from_bulge([0.0, 0.0], [1.0, 0.0], 1.0).unwrap();
        assert_eq!((arc.centre, arc.radius), (rust.centre().into(), rust.radius()));
        assert!((arc.sweep - rust.sweep()).abs() < 1e-12);
        segvoronoi_builder_free(b);
    }
}
