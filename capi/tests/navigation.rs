//! Half-edge navigation through the C API
//! (`segvoronoi_diagram_half_edge_next` and the rest) gives what the Rust
//! API gives, which `tests/navigation.rs` checks against the edges' own ends
//! and sites.

#[path = "../../integration/tests/common/mod.rs"]
mod common;

use common::{build_sites, segment_grid};
use segvoronoi::{HalfEdge, SiteId};
use segvoronoi_capi::*;

/// The C calls give what the Rust ones give, on every half-edge, vertex and
/// cell of a diagram of points and segments.
#[test]
fn c_navigation_agrees_with_rust() {
    let (points, segments) = segment_grid(5, 7, 0.5);
    let d = build_sites(&points, &segments);
    let raw = unsafe {
        let b = segvoronoi_builder_new();
        let flat_points: Vec<f64> = points.iter().flatten().copied().collect();
        let flat_segments: Vec<f64> = segments.iter().flatten().flatten().copied().collect();
        assert_eq!(segvoronoi_builder_add_points(b, flat_points.as_ptr(), points.len()), segvoronoi_status::Ok);
        assert_eq!(segvoronoi_builder_add_segments(b, flat_segments.as_ptr(), segments.len()), segvoronoi_status::Ok);
        let mut raw = std::ptr::null_mut();
        assert_eq!(segvoronoi_builder_build(b, &mut raw), segvoronoi_status::Ok);
        segvoronoi_builder_free(b);
        raw
    };
    unsafe {
        let mut out = 0u32;
        for h in (0..2 * d.edge_count()).map(HalfEdge::from_index) {
            let ask = |f: unsafe extern "C" fn(*const segvoronoi_diagram, u32, *mut u32) -> segvoronoi_status, out: &mut u32| {
                f(raw, h.index() as u32, out)
            };
            assert_eq!(ask(segvoronoi_diagram_half_edge_next, &mut out), segvoronoi_status::Ok);
            assert_eq!(out as usize, d.next_half_edge(h).unwrap().index());
            assert_eq!(ask(segvoronoi_diagram_half_edge_prev, &mut out), segvoronoi_status::Ok);
            assert_eq!(out as usize, d.prev_half_edge(h).unwrap().index());
            assert_eq!(ask(segvoronoi_diagram_half_edge_cell, &mut out), segvoronoi_status::Ok);
            assert_eq!(out as usize, d.half_edge_cell(h).unwrap().index());
        }
        let past = 2 * d.edge_count() as u32;
        assert_eq!(segvoronoi_diagram_half_edge_next(raw, past, &mut out), segvoronoi_status::OutOfRange);
        assert_eq!(segvoronoi_diagram_half_edge_next(raw, 0, std::ptr::null_mut()), segvoronoi_status::NullArgument);
        for v in d.vertices() {
            let mut three = [0u32; 3];
            assert_eq!(segvoronoi_diagram_vertex_half_edges(raw, v.id.index(), three.as_mut_ptr()), segvoronoi_status::Ok);
            assert_eq!(three.map(|h| h as usize), d.vertex_half_edges(v.id).unwrap().map(|h| h.index()));
        }
        for site in (0..d.site_count()).map(SiteId::from_index) {
            let mut count = 0usize;
            assert_eq!(
                segvoronoi_diagram_cell_half_edges(raw, site.index(), std::ptr::null_mut(), 0, &mut count),
                segvoronoi_status::Ok
            );
            let mut buffer = vec![0u32; count];
            assert_eq!(
                segvoronoi_diagram_cell_half_edges(raw, site.index(), buffer.as_mut_ptr(), count, &mut count),
                segvoronoi_status::Ok
            );
            let rust: Vec<u32> = d.cell_half_edges(site).map(|h| h.index() as u32).collect();
            assert_eq!(buffer, rust);
        }
        for e in d.edges() {
            let mut edge = segvoronoi_edge::default();
            assert_eq!(segvoronoi_diagram_edge(raw, e.id.index(), &mut edge), segvoronoi_status::Ok);
            assert_eq!(edge.is_separator, d.is_separator(e.id).unwrap());
        }
        segvoronoi_diagram_free(raw);
    }
}
