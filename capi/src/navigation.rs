//! Half-edge navigation in C. A half-edge is a number: `2 * edge + side`,
//! side 0 running from the edge's `ends[0]` to `ends[1]` with `sites[0]` on
//! its left, side 1 its twin (`h ^ 1`). Delegates to `Diagram::next_half_edge`,
//! `prev_half_edge`, `half_edge_cell`, `vertex_half_edges` and
//! `cell_half_edges`.

use super::diagram::{segvoronoi_diagram, site_id, with_diagram};
use super::out::{require_buffer, write_buffer, write_out};
use super::plumbing::{out_of_range, require_non_null, segvoronoi_status};
use segvoronoi::{Diagram, HalfEdge, VertexId};

/// Runs `f` on half-edge `h` of the diagram and writes its answer to
/// `*out`: `OUT_OF_RANGE` past the half-edges (`2 * edge_count`).
fn half_edge_query(
    diagram: *const segvoronoi_diagram,
    h: u32,
    out: *mut u32,
    f: impl FnOnce(&Diagram, HalfEdge) -> Option<usize>,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| {
        // bounded first: `HalfEdge::from_index` asserts (in debug builds)
        // that the index is below `u32::MAX`
        let answer = ((h as usize) < 2 * d.edge_count()).then(|| f(d, HalfEdge::from_index(h as usize))).flatten();
        match answer {
            Some(answer) => write_out(out, answer as u32),
            None => out_of_range("half-edge", h as usize, 2 * d.edge_count()),
        }
    })
}

/// The half-edge after `h` around the cell on its left, counter-clockwise,
/// in `*out` (around an unbounded cell, from the ray that leaves to
/// infinity to the ray that comes back).
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (`h >= 2 * edge_count`); then
/// `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_half_edge_next(
    diagram: *const segvoronoi_diagram,
    h: u32,
    out: *mut u32,
) -> segvoronoi_status {
    half_edge_query(diagram, h, out, |d, h| d.next_half_edge(h).map(HalfEdge::index))
}

/// The half-edge before `h` around the cell on its left, in `*out`.
///
/// Errors: as `segvoronoi_diagram_half_edge_next`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_half_edge_prev(
    diagram: *const segvoronoi_diagram,
    h: u32,
    out: *mut u32,
) -> segvoronoi_status {
    half_edge_query(diagram, h, out, |d, h| d.prev_half_edge(h).map(HalfEdge::index))
}

/// The site whose cell is on the left of half-edge `h`, in `*out`.
///
/// Errors: as `segvoronoi_diagram_half_edge_next`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_half_edge_cell(
    diagram: *const segvoronoi_diagram,
    h: u32,
    out: *mut u32,
) -> segvoronoi_status {
    half_edge_query(diagram, h, out, |d, h| d.half_edge_cell(h).map(|s| s.index()))
}

/// The three half-edges leaving finite vertex `vertex`, counter-clockwise,
/// in `out[0..3]`; the cell on the left of `out[k]` is the vertex's
/// `sites[(k + 1) % 3]`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`; then `out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_vertex_half_edges(
    diagram: *const segvoronoi_diagram,
    vertex: usize,
    out: *mut u32,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| {
        let v = (vertex < d.vertex_count()).then(|| VertexId::from_index(vertex));
        match v.and_then(|v| d.vertex_half_edges(v)) {
            // three consecutive u32s: the alignment of an array of them
            Some(three) => write_out(out.cast::<[u32; 3]>(), three.map(|h| h.index() as u32)),
            None => out_of_range("vertex", vertex, d.vertex_count()),
        }
    })
}

/// The half-edges around the cell of site `site`, counter-clockwise, the
/// cell on their left (each is a side of the edge of
/// `segvoronoi_diagram_cell_edges` at the same place). Writes up to
/// `capacity` to `half_edges` and the full number to `*count`;
/// `half_edges = NULL, capacity = 0` only counts (`OK`).
///
/// Errors: `NULL_ARGUMENT` (`count` NULL, or `half_edges` NULL with
/// `capacity > 0`), `OUT_OF_RANGE`, `BUFFER_TOO_SMALL` (then `*count` holds
/// the number needed and the first `capacity` are written).
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_cell_half_edges(
    diagram: *const segvoronoi_diagram,
    site: usize,
    half_edges: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    require_buffer!(half_edges, capacity, count);
    with_diagram(diagram, |d| match site_id(d, site) {
        Some(s) => write_buffer(d.cell_half_edges(s).map(|h| h.index() as u32), half_edges, capacity, count),
        None => out_of_range("site", site, d.site_count()),
    })
}
