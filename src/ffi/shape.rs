//! Edge geometry in C: the shape of an edge (straight or parabolic) and a
//! polyline along it. Delegates to `Diagram::edge_shape` and
//! `Diagram::edge_polyline`.

use super::diagram::{segvoronoi_diagram, with_diagram, write_out};
use super::plumbing::{require_non_null, segvoronoi_status};
use crate::{Diagram, EdgeId, EdgeShape};

/// `segvoronoi_edge_shape.kind` of a straight edge: between two points,
/// between two segments, or between a segment and one of its endpoints.
pub const SEGVORONOI_EDGE_LINE: u32 = 0;
/// `segvoronoi_edge_shape.kind` of a parabolic arc: between a point site (the
/// focus) and a segment site that does not end at it (its supporting line is
/// the directrix).
pub const SEGVORONOI_EDGE_PARABOLA: u32 = 1;

/// The shape of an edge. For `SEGVORONOI_EDGE_LINE` all coordinates are 0.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct segvoronoi_edge_shape {
    /// `SEGVORONOI_EDGE_LINE` or `SEGVORONOI_EDGE_PARABOLA`.
    pub kind: u32,
    /// The focus (the point site), in input coordinates.
    pub focus_x: f64,
    /// The focus (the point site), in input coordinates.
    pub focus_y: f64,
    /// First point of the directrix (the segment site's first endpoint).
    pub directrix_x1: f64,
    /// First point of the directrix (the segment site's first endpoint).
    pub directrix_y1: f64,
    /// Second point of the directrix (the segment site's second endpoint).
    pub directrix_x2: f64,
    /// Second point of the directrix (the segment site's second endpoint).
    pub directrix_y2: f64,
}

/// The shape of edge `edge_index` (`0 <= edge_index < edge_count`) in
/// `*out`: straight, or a parabolic arc with its focus and directrix.
///
/// Ownership: `*out` is caller-owned memory, written only on success.
/// Errors: `NULL_ARGUMENT` (`diagram` or `out`), `OUT_OF_RANGE`.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_edge_shape(
    diagram: *const segvoronoi_diagram,
    edge_index: usize,
    out: *mut segvoronoi_edge_shape,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| {
        let Some(shape) = edge_id(d, edge_index).and_then(|e| d.edge_shape(e)) else {
            return segvoronoi_status::OutOfRange;
        };
        let shape = match shape {
            EdgeShape::Line => segvoronoi_edge_shape { kind: SEGVORONOI_EDGE_LINE, ..Default::default() },
            EdgeShape::Parabola { focus, directrix: [a, b] } => segvoronoi_edge_shape {
                kind: SEGVORONOI_EDGE_PARABOLA,
                focus_x: focus.x,
                focus_y: focus.y,
                directrix_x1: a.x,
                directrix_y1: a.y,
                directrix_x2: b.x,
                directrix_y2: b.y,
            },
        };
        write_out(out, shape)
    })
}

/// A polyline along the finite edge `edge_index`, from its first end to its
/// second (both vertex positions included exactly), within `tolerance`
/// (input units) of the true edge: 2 points for a straight edge, as few as
/// the curvature allows for a parabolic arc, never more than 1,000,000 (the
/// tolerance is then not met). Writes up to `capacity_points` points to `xy`
/// as `x0, y0, x1, y1, ...` (`2 * capacity_points` doubles) and the full
/// number of points to `*count`. Call with `xy = NULL, capacity_points = 0`
/// to learn the number.
///
/// Ownership: `xy` and `*count` are caller-owned memory.
/// Errors: `NULL_ARGUMENT` (`diagram` or `count` NULL, or `xy` NULL with
/// `capacity_points > 0`), `INVALID_ARGUMENT` (`tolerance <= 0` or NaN, or
/// the edge is a ray or a line: it has no finite polyline, and its direction
/// is in `segvoronoi_diagram_edge`), `OUT_OF_RANGE` (`edge_index`); after
/// these nothing is written. `BUFFER_TOO_SMALL`: `*count` holds the number
/// needed and the first `capacity_points` points are written.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_edge_polyline(
    diagram: *const segvoronoi_diagram,
    edge_index: usize,
    tolerance: f64,
    xy: *mut f64,
    capacity_points: usize,
    count: *mut usize,
) -> segvoronoi_status {
    require_non_null!(count);
    if capacity_points > 0 {
        require_non_null!(xy);
    }
    with_diagram(diagram, |d| {
        if tolerance.is_nan() || tolerance <= 0.0 {
            return segvoronoi_status::InvalidArgument;
        }
        let Some(edge) = edge_id(d, edge_index) else { return segvoronoi_status::OutOfRange };
        let Some(points) = d.edge_polyline(edge, tolerance) else { return segvoronoi_status::InvalidArgument };
        for (k, p) in points.iter().take(capacity_points).enumerate() {
            // SAFETY: xy holds 2 * capacity_points writable doubles (checked
            // non-null above when capacity_points > 0), and k < capacity_points.
            unsafe {
                xy.add(2 * k).write(p.x);
                xy.add(2 * k + 1).write(p.y);
            }
        }
        write_out(count, points.len());
        if points.len() > capacity_points {
            segvoronoi_status::BufferTooSmall
        } else {
            segvoronoi_status::Ok
        }
    })
}

/// The edge id of a C index, if in range.
fn edge_id(d: &Diagram, index: usize) -> Option<EdgeId> {
    (index < d.edge_count()).then(|| EdgeId::from_index(index))
}
