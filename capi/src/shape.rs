//! Edge geometry in C: the shape of an edge (straight, parabolic, or a
//! conic beside a circular arc), a polyline along it, and the (rational)
//! Bézier curve of a curved one. Delegates to `Diagram::edge_shape`,
//! `Diagram::edge_polyline`, `Diagram::edge_bezier` and
//! `Diagram::edge_rational_bezier`.

use super::diagram::{segvoronoi_diagram, with_diagram};
use super::offset::not_positive;
use super::out::{check_polyline_len, require_buffer, versioned, write_indexed, write_out, write_versioned};
use super::plumbing::{fail, out_of_range, require_non_null, segvoronoi_status, unknown_variant};
use segvoronoi::{Diagram, EdgeId, EdgeShape};

/// `segvoronoi_edge_shape.kind` of a straight edge: between two points,
/// between two segments, or between a segment and one of its endpoints.
pub const SEGVORONOI_EDGE_LINE: u32 = 0;
/// `segvoronoi_edge_shape.kind` of a parabolic arc: between a point site (the
/// focus) and a segment site that does not end at it (its supporting line is
/// the directrix).
pub const SEGVORONOI_EDGE_PARABOLA: u32 = 1;
/// `segvoronoi_edge_shape.kind` of a conic arc: between two sites of which
/// at least one is a circular arc (not between an arc and one of its own
/// endpoints, which is `SEGVORONOI_EDGE_LINE`): a piece of a line,
/// parabola, ellipse or hyperbola branch. Its two sites are the edge's
/// (`segvoronoi_diagram_edge`); the shape's coordinates are 0.
/// `segvoronoi_diagram_edge_polyline` samples it, and
/// `segvoronoi_diagram_edge_rational_bezier` gives a curved one exactly.
/// Since 0.2.
pub const SEGVORONOI_EDGE_CONIC: u32 = 2;

/// The shape of an edge. For `SEGVORONOI_EDGE_LINE` and
/// `SEGVORONOI_EDGE_CONIC` all coordinates are 0.
/// Versioned: set `struct_size` before the call (see the header's
/// introduction); more shapes may come, so treat an unknown `kind` as
/// "neither".
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct segvoronoi_edge_shape {
    /// Set by the caller to `sizeof(segvoronoi_edge_shape)`; the library
    /// writes the fields that fit and sets it to the number of bytes written.
    pub struct_size: usize,
    /// `SEGVORONOI_EDGE_LINE`, `SEGVORONOI_EDGE_PARABOLA` or
    /// `SEGVORONOI_EDGE_CONIC`.
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
versioned!(segvoronoi_edge_shape, directrix_y2: f64);

/// The shape of edge `edge_index` (`0 <= edge_index < edge_count`) in
/// `*out`: straight, a parabolic arc with its focus and directrix, or a
/// conic arc beside a circular-arc site.
///
/// Ownership: `*out` is caller-owned memory, written only on success.
/// Errors: `NULL_ARGUMENT` (`diagram` or `out`), `OUT_OF_RANGE`,
/// `INVALID_ARGUMENT` (`out->struct_size` too small).
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
            return out_of_range("edge", edge_index, d.edge_count());
        };
        let shape = match shape {
            EdgeShape::Parabola { focus, directrix: [a, b] } => segvoronoi_edge_shape {
                kind: SEGVORONOI_EDGE_PARABOLA,
                focus_x: focus.x,
                focus_y: focus.y,
                directrix_x1: a.x,
                directrix_y1: a.y,
                directrix_x2: b.x,
                directrix_y2: b.y,
                ..Default::default()
            },
            EdgeShape::Line => segvoronoi_edge_shape { kind: SEGVORONOI_EDGE_LINE, ..Default::default() },
            EdgeShape::Conic { .. } => segvoronoi_edge_shape { kind: SEGVORONOI_EDGE_CONIC, ..Default::default() },
            _ => return unknown_variant("an edge shape"),
        };
        write_versioned(out, shape)
    })
}

/// A polyline along the finite edge `edge_index`, from its first end to its
/// second (both vertex positions included exactly), within `tolerance`
/// (input units) of the true edge: 2 points for a straight edge, as few as
/// the curvature allows for a parabolic or conic arc, never more than 1,000,000 (the
/// tolerance is then not met). Writes up to `capacity_points` points to `xy`
/// as `x0, y0, x1, y1, ...` (`2 * capacity_points` doubles) and the full
/// number of points to `*count`; `xy = NULL, capacity_points = 0` only
/// counts (`OK`), allocating nothing.
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
    require_buffer!(xy, capacity_points, count);
    with_diagram(diagram, |d| {
        if tolerance.is_nan() || tolerance <= 0.0 {
            return not_positive(tolerance);
        }
        let Some(edge) = edge_id(d, edge_index) else { return out_of_range("edge", edge_index, d.edge_count()) };
        // counted by making the points, without keeping them (at most 1,000,000)
        let mut total = 0usize;
        if d.for_each_edge_polyline_point(edge, tolerance, |_| total += 1).is_none() {
            let message = format!("edge {edge_index} is a ray or a line: it has no finite polyline");
            return fail(segvoronoi_status::InvalidArgument, message);
        }
        if let Err(status) = check_polyline_len(total, tolerance) {
            return status;
        }
        // xy holds 2 * capacity_points doubles: capacity_points pairs, as
        // aligned as one double.
        write_indexed(total, xy.cast::<[f64; 2]>(), capacity_points, count, |sink| {
            let mut j = 0;
            d.for_each_edge_polyline_point(edge, tolerance, |p| {
                sink(j, p.into());
                j += 1;
            });
        })
    })
}

/// The quadratic Bézier curve of the finite parabolic edge `edge_index`:
/// `xy = {x0, y0, x1, y1, x2, y2}` (six doubles) gets its start (the position
/// of `ends[0]`), its control point (where the parabola's tangents at the two
/// ends meet) and its end (the position of `ends[1]`), so that
/// `(1-u)² p0 + 2u(1-u) p1 + u² p2` for `u` in `[0, 1]` runs along the arc
/// (SVG's `M p0 Q p1 p2`). Precision: a few ulps of the input's magnitude;
/// the ends are the vertex positions exactly.
///
/// Ownership: `xy` is caller-owned memory, written only on success.
/// Errors: `NULL_ARGUMENT` (`diagram` or `xy`), `OUT_OF_RANGE`
/// (`edge_index`), `INVALID_ARGUMENT` (a straight edge, see
/// `segvoronoi_diagram_edge_shape`, a conic edge beside a circular arc, see
/// `segvoronoi_diagram_edge_rational_bezier`, or a ray or line; also an arc
/// whose control point is beyond the range of `double`).
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_edge_bezier(
    diagram: *const segvoronoi_diagram,
    edge_index: usize,
    xy: *mut f64,
) -> segvoronoi_status {
    require_non_null!(xy);
    with_diagram(diagram, |d| {
        let Some(edge) = edge_id(d, edge_index) else { return out_of_range("edge", edge_index, d.edge_count()) };
        match d.edge_bezier(edge) {
            Some(curve) => write_out(xy.cast::<[[f64; 2]; 3]>(), curve.map(<[f64; 2]>::from)),
            None if matches!(d.edge_shape(edge), Some(EdgeShape::Conic { .. })) => fail(
                segvoronoi_status::InvalidArgument,
                format!("edge {edge_index} is a conic arc beside a circular arc: use segvoronoi_diagram_edge_rational_bezier"),
            ),
            None => fail(
                segvoronoi_status::InvalidArgument,
                format!("edge {edge_index} is no finite parabolic arc (straight, a ray or a line, or its control point is beyond double)"),
            ),
        }
    })
}

/// The rational quadratic Bézier curve of the finite curved edge
/// `edge_index` (a conic beside a circular arc, or a parabola):
/// `xy = {x0, y0, x1, y1, x2, y2}` (six doubles) gets its start (the
/// position of `ends[0]`), its control point (where the edge's tangents at
/// its ends meet) and its end (the position of `ends[1]`), and `*weight`
/// the control point's weight `w` (the ends' weights are 1), so that
/// `((1-u)² p0 + 2u(1-u) w p1 + u² p2) / ((1-u)² + 2u(1-u) w + u²)` for `u`
/// in `[0, 1]` runs along the edge: `w = 1` for a parabola (then the curve
/// of `segvoronoi_diagram_edge_bezier`), `w < 1` for an ellipse, `w > 1` for
/// a hyperbola. Conics are exactly rational quadratics, so this is the
/// edge itself to the rounding of its numbers; a conic's weight is fitted
/// through the edge's point halfway between its ends. Since 0.2.
///
/// Ownership: `xy` and `weight` are caller-owned memory, written only on
/// success.
/// Errors: `NULL_ARGUMENT` (`diagram`, `xy` or `weight`), `OUT_OF_RANGE`
/// (`edge_index`), `INVALID_ARGUMENT` (a straight edge, see
/// `segvoronoi_diagram_edge_shape`; a ray or a line; or a piece whose
/// tangents at its ends do not meet ahead of both, one that turns by half a
/// turn or more: sample it with `segvoronoi_diagram_edge_polyline`).
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_edge_rational_bezier(
    diagram: *const segvoronoi_diagram,
    edge_index: usize,
    xy: *mut f64,
    weight: *mut f64,
) -> segvoronoi_status {
    require_non_null!(xy, weight);
    with_diagram(diagram, |d| {
        let Some(edge) = edge_id(d, edge_index) else { return out_of_range("edge", edge_index, d.edge_count()) };
        if let Some((curve, w)) = d.edge_rational_bezier(edge) {
            write_out(xy.cast::<[[f64; 2]; 3]>(), curve.map(<[f64; 2]>::from));
            return write_out(weight, w);
        }
        let why = match (d.edge(edge).map(|e| e.is_infinite()), d.edge_shape(edge)) {
            (Some(true), _) => "a ray or a line: it has no finite curve",
            (_, Some(EdgeShape::Line)) => "straight (see segvoronoi_diagram_edge_shape)",
            _ => "a piece whose end tangents do not meet ahead of both (it turns by half a turn or more): sample it with segvoronoi_diagram_edge_polyline",
        };
        fail(segvoronoi_status::InvalidArgument, format!("edge {edge_index} has no rational Bézier curve: it is {why}"))
    })
}

/// The edge id of a C index, if in range.
fn edge_id(d: &Diagram, index: usize) -> Option<EdgeId> {
    (index < d.edge_count()).then(|| EdgeId::from_index(index))
}
