//! The medial axis in C: a handle with its chains and their pieces, and
//! the sampling of a chain as `(x, y, clearance)`. Delegates to
//! `Diagram::medial_axis` and `Diagram::sample_chain`.

use std::sync::Arc;

use super::diagram::{edge_end, segvoronoi_diagram, segvoronoi_edge_end, with_diagram};
use super::offset::not_positive;
use super::out::{
    check_polyline_len, read_versioned, require_buffer, versioned, write_indexed, write_out, write_versioned, FromAnyBytes,
};
use super::plumbing::{fail, guard, guard_or, out_of_range, require_non_null, segvoronoi_status, try_box};
use super::SEGVORONOI_MAX_POLYLINE_POINTS;
use segvoronoi::{Diagram, EdgeEnd, EdgeShape, MedialAxis, MedialAxisFilter};

/// A medial axis (`segvoronoi_diagram_medial_axis`). Opaque and immutable.
/// Free it with `segvoronoi_medial_axis_free`.
///
/// Ownership: it shares its diagram (a reference count), so it may be
/// freed before or after the diagram: the diagram's memory goes when the
/// last of them is freed, and after `segvoronoi_diagram_free` the axis
/// still answers every query as before.
///
/// Thread safety: any number of threads may read one medial axis at once,
/// also while another thread reads or frees its diagram;
/// `segvoronoi_medial_axis_free` must not overlap another call on the same
/// axis.
pub struct segvoronoi_medial_axis {
    /// The diagram the pieces' edges belong to, kept alive by the axis.
    diagram: Arc<Diagram>,
    inner: MedialAxis,
}

/// Hands a new medial axis of `diagram` to C.
fn new_axis(diagram: &segvoronoi_diagram, inner: MedialAxis, out: *mut *mut segvoronoi_medial_axis) -> segvoronoi_status {
    match try_box(segvoronoi_medial_axis { diagram: diagram.shared(), inner }) {
        Some(axis) => write_out(out, axis),
        None => fail(segvoronoi_status::OutOfMemory, "out of memory: no room for the medial axis's handle"),
    }
}

/// One piece of a chain of the medial axis: an edge of the diagram walked in
/// the chain's direction. Versioned: set `struct_size` before the call.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct segvoronoi_piece {
    /// Set by the caller to `sizeof(segvoronoi_piece)`; the library writes
    /// the fields that fit and sets it to the number of bytes written.
    pub struct_size: usize,
    /// The edge (its shape: `segvoronoi_diagram_edge_shape`).
    pub edge: u32,
    /// `true` when the chain walks the edge from its `ends[1]` to `ends[0]`.
    pub reversed: bool,
    /// Where the piece starts and ends, in the chain's direction.
    pub ends: [segvoronoi_edge_end; 2],
    /// The clearance at both ends (infinite at an end at infinity).
    pub clearance: [f64; 2],
    /// The sites on its left and on its right, in the chain's direction
    /// (the edge's `sites`, swapped when `reversed`).
    pub sites: [u32; 2],
}
versioned!(segvoronoi_piece, sites: [u32; 2]);

/// The medial axis of a diagram (the edges inside the domain that are not
/// separators; without polygons, every edge that is not a separator) in
/// `*out`.
///
/// Ownership: the caller frees it with `segvoronoi_medial_axis_free`; it
/// shares the diagram, which may be freed before or after it.
///
/// Errors: `NULL_ARGUMENT`; then `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_medial_axis(
    diagram: *const segvoronoi_diagram,
    out: *mut *mut segvoronoi_medial_axis,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| {
        // SAFETY: `with_diagram` checked it non-null; a live diagram.
        new_axis(unsafe { &*diagram }, d.medial_axis(), out)
    })
}

/// Which branches `segvoronoi_diagram_medial_axis_filtered` leaves out
/// (Rust's `MedialAxisFilter`). Versioned: set `struct_size` to
/// `sizeof(segvoronoi_medial_axis_filter)`; a zeroed struct filters nothing.
/// The flags are integers, nonzero meaning on (any nonzero value: 1, 2,
/// 0x80, -1); they were `bool` before 0.2.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct segvoronoi_medial_axis_filter {
    /// Set by the caller to `sizeof(segvoronoi_medial_axis_filter)`.
    pub struct_size: usize,
    /// Nonzero: the corner filter is on.
    pub corner_filter: u32,
    /// With the corner filter: leave out the branches into convex corners
    /// whose interior angle, in degrees, is above this.
    pub corner_angle: f64,
    /// Nonzero: the spur filter is on.
    pub spur_filter: u32,
    /// With the spur filter: leave out the leaf branches shorter than this
    /// times the clearance at their junction.
    pub spur_factor: f64,
}
versioned!(segvoronoi_medial_axis_filter, spur_factor: f64);
// SAFETY: integers and floats only: any bytes are a valid value.
unsafe impl FromAnyBytes for segvoronoi_medial_axis_filter {}

/// The medial axis without the branches `filter` leaves out (NULL: none;
/// the rules are Rust's `MedialAxisFilter`'s, with pictures in
/// `docs/medial_axis_filters.svg`) in `*out`. Free it with
/// `segvoronoi_medial_axis_free`, before the diagram.
///
/// Errors: `NULL_ARGUMENT`, `INVALID_ARGUMENT` (`filter->struct_size` too
/// small, or a filter that is on with a NaN); then `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_medial_axis_filtered(
    diagram: *const segvoronoi_diagram,
    filter: *const segvoronoi_medial_axis_filter,
    out: *mut *mut segvoronoi_medial_axis,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| {
        let rules = if filter.is_null() {
            MedialAxisFilter::new()
        } else {
            // SAFETY: non-null; the caller passes a filter of `struct_size` bytes.
            let f = match unsafe { read_versioned(filter) } {
                Ok(f) => f,
                Err(status) => return status,
            };
            let mut rules = MedialAxisFilter::new();
            if f.corner_filter != 0 {
                rules = rules.with_corner_angle(f.corner_angle);
            }
            if f.spur_filter != 0 {
                rules = rules.with_spur_pruning(f.spur_factor);
            }
            if rules.corner_angle.is_nan() || rules.spur_factor.is_nan() {
                let message =
                    format!("filter->corner_angle ({}) or filter->spur_factor ({}) is NaN", f.corner_angle, f.spur_factor);
                return fail(segvoronoi_status::InvalidArgument, message);
            }
            rules
        };
        // SAFETY: `with_diagram` checked it non-null; a live diagram.
        new_axis(unsafe { &*diagram }, d.medial_axis_filtered(&rules), out)
    })
}

/// Frees a medial axis. NULL does nothing.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_medial_axis_free(axis: *mut segvoronoi_medial_axis) {
    if axis.is_null() {
        return;
    }
    // SAFETY: the caller passes an axis from `segvoronoi_diagram_medial_axis`
    // (made by `try_box`), not freed yet and in no other call. Dropping it
    // drops its share of the diagram.
    guard_or((), || drop(unsafe { Box::from_raw(axis) }))
}

/// Runs `f` on the axis and its chain `chain`: `OUT_OF_RANGE` past the
/// chains.
fn with_chain(
    axis: *const segvoronoi_medial_axis,
    chain: usize,
    f: impl FnOnce(&segvoronoi_medial_axis, &segvoronoi::Chain) -> segvoronoi_status,
) -> segvoronoi_status {
    require_non_null!(axis);
    guard(|| {
        // SAFETY: non-null; the caller passes a live axis (not freed; its
        // diagram is alive through the axis's share). Only read.
        let axis = unsafe { &*axis };
        match axis.inner.chains.get(chain) {
            Some(c) => f(axis, c),
            None => out_of_range("chain", chain, axis.inner.chains.len()),
        }
    })
}

/// Runs `f` on piece `piece` of chain `chain` and the axis's diagram:
/// `OUT_OF_RANGE` past the chains or the chain's pieces.
fn with_piece(
    axis: *const segvoronoi_medial_axis,
    chain: usize,
    piece: usize,
    f: impl FnOnce(&Diagram, &segvoronoi::Piece) -> segvoronoi_status,
) -> segvoronoi_status {
    with_chain(axis, chain, |axis, c| match c.pieces.get(piece) {
        Some(p) => f(&axis.diagram, p),
        None => out_of_range(&format!("chain {chain}'s piece"), piece, c.pieces.len()),
    })
}

/// The number of chains; 0 for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_medial_axis_chain_count(axis: *const segvoronoi_medial_axis) -> usize {
    if axis.is_null() {
        return 0;
    }
    // SAFETY: non-null live axis.
    guard_or(0, || unsafe { &*axis }.inner.chains.len())
}

/// The number of pieces of chain `chain` in `*count`, and whether it is
/// closed (a cycle) in `*closed`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`; then the outputs are untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_medial_axis_chain(
    axis: *const segvoronoi_medial_axis,
    chain: usize,
    count: *mut usize,
    closed: *mut bool,
) -> segvoronoi_status {
    require_non_null!(count, closed);
    with_chain(axis, chain, |_, c| {
        write_out(closed, c.closed);
        write_out(count, c.pieces.len())
    })
}

/// Piece `piece` of chain `chain` in `*out`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`, `INVALID_ARGUMENT`
/// (`out->struct_size` too small); then `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_medial_axis_piece(
    axis: *const segvoronoi_medial_axis,
    chain: usize,
    piece: usize,
    out: *mut segvoronoi_piece,
) -> segvoronoi_status {
    require_non_null!(out);
    with_piece(axis, chain, piece, |d, p| {
        let value = segvoronoi_piece {
            edge: p.edge.index() as u32,
            reversed: p.reversed,
            ends: p.ends.map(|end| edge_end(d, end)),
            clearance: p.clearance,
            sites: p.sites.map(|s| s.index() as u32),
            ..Default::default()
        };
        write_versioned(out, value)
    })
}

/// The points of chain `chain` within `tolerance` (input units) of its exact
/// curve, each `{x, y, clearance}`: up to `capacity` points (`3 * capacity`
/// doubles) to `xyr`, the full number of points to `*count`; `xyr = NULL,
/// capacity = 0` only counts (`OK`), allocating nothing. Each piece gets at
/// most 1,000,000 points (the tolerance is then not met there).
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`, `INVALID_ARGUMENT` (a tolerance
/// that is not positive, or a chain that reaches infinity), `TOO_LARGE`
/// (the chain would have more than `SEGVORONOI_MAX_POLYLINE_POINTS` points:
/// nothing is written), `BUFFER_TOO_SMALL` (then `*count` holds the number
/// needed and the first `capacity` points are written).
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_medial_axis_sample_chain(
    axis: *const segvoronoi_medial_axis,
    chain: usize,
    tolerance: f64,
    xyr: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    require_buffer!(xyr, capacity, count);
    with_chain(axis, chain, |axis, c| {
        let d = &*axis.diagram;
        if tolerance.is_nan() || tolerance <= 0.0 {
            return not_positive(tolerance);
        }
        // counted first (stopping past the cap), allocating nothing
        let Some(total) = d.chain_sample_len(c, tolerance, SEGVORONOI_MAX_POLYLINE_POINTS) else {
            return fail(segvoronoi_status::InvalidArgument, format!("chain {chain} reaches infinity: it has no finite samples"));
        };
        if let Err(status) = check_polyline_len(total, tolerance) {
            return status;
        }
        // three consecutive doubles per point: the alignment of an array of them
        write_indexed(total, xyr.cast::<[f64; 3]>(), capacity, count, |sink| {
            d.for_each_chain_sample(c, tolerance, sink);
        })
    })
}

/// Whether `point` (`[x, y, clearance]`), the library's point of a piece
/// of a conic edge beside a circular arc, is off that edge: not as far
/// from one of the edge's sites as from the other (to a relative 1e-9 of
/// the input's extent and the clearance). The library's edge curves do
/// not evaluate curved conics yet (it answers the chord); such a point is
/// refused rather than passed on. Straight (degenerate) conics and every
/// other shape pass.
fn off_its_conic(d: &Diagram, p: &segvoronoi::Piece, point: [f64; 3]) -> bool {
    if !matches!(d.edge_shape(p.edge), Some(EdgeShape::Conic { .. })) {
        return false;
    }
    let q = segvoronoi::Point::new(point[0], point[1]);
    let Some([a, b]) = d.edge(p.edge).map(|e| e.sites.map(|s| d.site(s))) else { return false };
    let (Some(a), Some(b)) = (a, b) else { return false };
    (a.distance(q) - b.distance(q)).abs() > 1e-9 * d.extent().max(point[2]).max(f64::MIN_POSITIVE)
}

/// The point of piece `piece` of chain `chain` at parameter `t` (0 at its
/// start, 1 at its end, in the chain's direction) and the clearance there,
/// as `{x, y, clearance}` in `xyr[0..3]`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (chain or piece), `INVALID_ARGUMENT`
/// (`t` outside `[0, 1]`, or a piece that reaches infinity, or a curved
/// conic piece beside a circular arc, which this version cannot evaluate
/// at a parameter: `segvoronoi_medial_axis_sample_chain` samples it),
/// `UNSUPPORTED_RANGE` (a point that f64 cannot compute, only on inputs
/// beyond the exact range); then `xyr` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_medial_axis_piece_at(
    axis: *const segvoronoi_medial_axis,
    chain: usize,
    piece: usize,
    t: f64,
    xyr: *mut f64,
) -> segvoronoi_status {
    require_non_null!(xyr);
    with_piece(axis, chain, piece, |d, p| match d.piece_point_at(p, t) {
        // three consecutive doubles: the alignment of an array of them
        Some(point) if off_its_conic(d, p, point) => fail(
            segvoronoi_status::InvalidArgument,
            format!(
                "piece {piece} of chain {chain} is a conic edge beside a circular arc, which this version cannot \
                 evaluate at a parameter (segvoronoi_medial_axis_sample_chain and segvoronoi_diagram_edge_polyline \
                 sample it)"
            ),
        ),
        Some(point) => write_out(xyr.cast::<[f64; 3]>(), point),
        None if !(0.0..=1.0).contains(&t) => fail(segvoronoi_status::InvalidArgument, format!("t = {t} is outside [0, 1]")),
        None if p.ends.iter().any(|end| matches!(end, EdgeEnd::Infinite { .. })) => fail(
            segvoronoi_status::InvalidArgument,
            format!("piece {piece} of chain {chain} reaches infinity: it has no point at a parameter"),
        ),
        None if matches!(d.edge_shape(p.edge), Some(EdgeShape::Conic { .. })) => fail(
            segvoronoi_status::InvalidArgument,
            format!(
                "piece {piece} of chain {chain} is a conic edge beside a circular arc, which this version cannot \
                 evaluate at a parameter (segvoronoi_diagram_edge_polyline samples it)"
            ),
        ),
        None => fail(
            segvoronoi_status::UnsupportedRange,
            format!(
                "the point at t = {t} of piece {piece} of chain {chain} cannot be computed in f64: \
                 the input's coordinates span more than the exact range"
            ),
        ),
    })
}
