//! Offsets in C: a handle per distance with its loops, their pieces and
//! nesting, polylines and areas. Delegates to `Diagram::offsets`.

use super::diagram::{segvoronoi_diagram, with_diagram};
use super::out::{check_polyline_len, require_buffer, versioned, write_indexed, write_versioned};
use super::plumbing::{fail, fail_with, guard, guard_or, out_of_range, require_non_null, segvoronoi_status, try_box};
use segvoronoi::{Offset, OffsetLoop, OffsetPiece};

/// `segvoronoi_loop_piece.kind` of a straight piece, parallel to a
/// segment site.
pub const SEGVORONOI_OFFSET_LINE: u32 = 0;
/// `segvoronoi_loop_piece.kind` of a circular arc around a point site (or
/// concentric with a circular-arc site).
pub const SEGVORONOI_OFFSET_ARC: u32 = 1;
/// `segvoronoi_loop.parent` of an outermost loop.
pub const SEGVORONOI_NO_PARENT: u32 = u32::MAX;

/// The offset of a diagram at one distance (`segvoronoi_diagram_offset`):
/// closed loops of exact pieces. Opaque and immutable; it holds its own
/// copy of everything it reports, so it may outlive its diagram. Free it
/// with `segvoronoi_offset_free`.
///
/// Thread safety: any number of threads may read one offset at once;
/// `segvoronoi_offset_free` must not overlap another call on it.
pub struct segvoronoi_offset {
    inner: Offset,
}

/// One loop of an offset. Versioned: set `struct_size` before the call.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct segvoronoi_loop {
    /// Set by the caller to `sizeof(segvoronoi_loop)`; the library
    /// writes the fields that fit and sets it to the number of bytes written.
    pub struct_size: usize,
    /// How many pieces it has.
    pub piece_count: usize,
    /// The loop it lies directly inside, or `SEGVORONOI_NO_PARENT`. A
    /// parent's index is below its children's.
    pub parent: u32,
    /// Whether it bounds a hole (it runs clockwise; outer boundaries run
    /// counter-clockwise, with the region on their left).
    pub hole: bool,
    /// The signed area it encloses, from its exact pieces (negative for a
    /// hole).
    pub signed_area: f64,
}
versioned!(segvoronoi_loop, signed_area: f64);

/// One piece of an offset loop, in the loop's direction. For
/// `SEGVORONOI_OFFSET_LINE` the centre, radius and direction are 0. More
/// kinds may come, so treat an unknown `kind` as "neither". Versioned: set
/// `struct_size` before the call.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct segvoronoi_loop_piece {
    /// Set by the caller to `sizeof(segvoronoi_loop_piece)`; the library
    /// writes the fields that fit and sets it to the number of bytes written.
    pub struct_size: usize,
    /// `SEGVORONOI_OFFSET_LINE` or `SEGVORONOI_OFFSET_ARC`.
    pub kind: u32,
    /// The site it keeps its distance from (a segment site for a line, a
    /// point site for an arc).
    pub site: u32,
    /// Where it starts: `{x, y}`.
    pub from: [f64; 2],
    /// Where it ends: `{x, y}`; for an arc equal to `from`, a whole circle.
    pub to: [f64; 2],
    /// An arc's centre (its point site): `{x, y}`.
    pub centre: [f64; 2],
    /// An arc's radius (the offset's distance).
    pub radius: f64,
    /// Whether an arc runs counter-clockwise from `from` to `to`.
    pub counter_clockwise: bool,
}
versioned!(segvoronoi_loop_piece, counter_clockwise: bool);

/// The offset of `diagram` at signed distance `distance` in `*out` (Rust's
/// `Diagram::offset`: with polygons, a negative distance shrinks the
/// domain and a positive one grows it; without, only a positive distance,
/// the boundary of the points within it of any site).
///
/// Ownership: the caller frees `*out` with `segvoronoi_offset_free`.
/// Errors: `NULL_ARGUMENT`, `INVALID_ARGUMENT` (a distance that is NaN,
/// infinite or zero, or not positive without polygons, or one at which the
/// input's extent plus twice the distance exceeds `2^510`, about 3e153; or
/// an offset that runs along a circular-arc site, which this version does
/// not trace yet),
/// `UNSUPPORTED_RANGE` (loops that f64 cannot trace, only on inputs beyond
/// the exact range); then `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_offset(
    diagram: *const segvoronoi_diagram,
    distance: f64,
    out: *mut *mut segvoronoi_offset,
) -> segvoronoi_status {
    // SAFETY: one distance and one output, as `segvoronoi_diagram_offsets` reads them.
    unsafe { segvoronoi_diagram_offsets(diagram, &distance, 1, out) }
}

/// The offsets of `diagram` at the `count` signed distances `distances`
/// (see `segvoronoi_diagram_offset`), one handle per distance in
/// `out[0..count]`, in the order given. The work they share is done once,
/// so each distance costs about its own output.
///
/// Ownership: the caller frees each `out[k]` with `segvoronoi_offset_free`.
/// Errors: `NULL_ARGUMENT`, `INVALID_ARGUMENT` and `UNSUPPORTED_RANGE` (any
/// distance as for `segvoronoi_diagram_offset`); then `out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_offsets(
    diagram: *const segvoronoi_diagram,
    distances: *const f64,
    count: usize,
    out: *mut *mut segvoronoi_offset,
) -> segvoronoi_status {
    if count > 0 {
        require_non_null!(distances, out);
    }
    with_diagram(diagram, |d| {
        // Bound the count before it becomes a slice: `count` doubles and as
        // many output pointers must fit in the address space.
        if count > isize::MAX as usize / std::mem::size_of::<f64>() {
            return fail(segvoronoi_status::TooLarge, format!("count {count} is larger than any array of doubles"));
        }
        // SAFETY: non-null when count > 0, and the caller passes `count`
        // readable doubles, which span at most isize::MAX bytes (checked above).
        let distances = if count == 0 { &[][..] } else { unsafe { std::slice::from_raw_parts(distances, count) } };
        let offsets = match d.offsets(distances) {
            Ok(offsets) => offsets,
            Err(e) => return fail_with(&e),
        };
        if let Some(site) = offsets.iter().find_map(|o| untrue_arc_piece(d, o)) {
            let message = format!(
                "the offset runs along arc site {site}, and this version traces offsets of points and segments only: \
                 offsets of circular arcs are not supported yet"
            );
            return fail(segvoronoi_status::InvalidArgument, message);
        }
        // All handles first, so that `out` is written only on success.
        let mut handles: Vec<*mut segvoronoi_offset> = Vec::new();
        if handles.try_reserve_exact(count).is_err() {
            return fail(segvoronoi_status::OutOfMemory, format!("out of memory: no room for {count} offset handles"));
        }
        for inner in offsets {
            match try_box(segvoronoi_offset { inner }) {
                Some(h) => handles.push(h),
                None => {
                    for h in handles {
                        // SAFETY: made by `try_box` just above and not handed out.
                        drop(unsafe { Box::from_raw(h) });
                    }
                    return fail(segvoronoi_status::OutOfMemory, "out of memory: no room for an offset's handle");
                }
            }
        }
        for (k, h) in handles.into_iter().enumerate() {
            // SAFETY: `out` holds `count` writable pointers, and k < count.
            unsafe { out.add(k).write(h) };
        }
        segvoronoi_status::Ok
    })
}

/// The arc site of a piece of `offset` that is not the concentric circular
/// arc an offset of an arc site is (a line, or a circle about another
/// centre): the library traces arc sites as it traces the others only
/// once it offsets arcs, and the C API passes on nothing untrue.
fn untrue_arc_piece(d: &segvoronoi::Diagram, offset: &Offset) -> Option<usize> {
    if d.arc_site_count() == 0 {
        return None;
    }
    offset.loops.iter().flat_map(|l| l.pieces.iter()).find_map(|piece| {
        let site = piece.site();
        let Some(segvoronoi::Site::Arc(arc)) = d.site(site) else { return None };
        match *piece {
            OffsetPiece::Arc { centre, .. } if centre == arc.centre() => None,
            _ => Some(site.index()),
        }
    })
}

/// Frees an offset. NULL does nothing.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_offset_free(offset: *mut segvoronoi_offset) {
    if offset.is_null() {
        return;
    }
    // SAFETY: the caller passes an offset from `segvoronoi_diagram_offset(s)`, not freed yet.
    guard_or((), || drop(unsafe { Box::from_raw(offset) }))
}

/// Runs `f` on the offset; `NULL_ARGUMENT` for NULL.
fn with_offset(offset: *const segvoronoi_offset, f: impl FnOnce(&Offset) -> segvoronoi_status) -> segvoronoi_status {
    require_non_null!(offset);
    // SAFETY: non-null; the caller passes a live offset (not freed). It is
    // only read, which many threads may do at once.
    guard(|| f(&unsafe { &*offset }.inner))
}

/// Runs `f` on loop `index` of the offset: `OUT_OF_RANGE` past the loops.
fn with_loop(
    offset: *const segvoronoi_offset,
    index: usize,
    f: impl FnOnce(&OffsetLoop) -> segvoronoi_status,
) -> segvoronoi_status {
    with_offset(offset, |o| match o.loops.get(index) {
        Some(l) => f(l),
        None => out_of_range("loop", index, o.loops.len()),
    })
}

/// A number of the offset; `fallback` for NULL.
fn read<T>(offset: *const segvoronoi_offset, fallback: T, f: impl FnOnce(&Offset) -> T) -> T {
    if offset.is_null() {
        return fallback;
    }
    // SAFETY: non-null live offset.
    guard_or(fallback, || f(&unsafe { &*offset }.inner))
}

/// The signed distance the offset was asked for; NaN for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_offset_distance(offset: *const segvoronoi_offset) -> f64 {
    read(offset, f64::NAN, |o| o.distance)
}

/// The number of loops; 0 for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_offset_loop_count(offset: *const segvoronoi_offset) -> usize {
    read(offset, 0, |o| o.loops.len())
}

/// The area of the region the loops bound, from the exact pieces; NaN for
/// NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_offset_area(offset: *const segvoronoi_offset) -> f64 {
    read(offset, f64::NAN, Offset::area)
}

/// Loop `index` (`0 <= index < loop_count`) in `*out`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`, `INVALID_ARGUMENT`
/// (`out->struct_size` too small); then `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_offset_loop(
    offset: *const segvoronoi_offset,
    index: usize,
    out: *mut segvoronoi_loop,
) -> segvoronoi_status {
    require_non_null!(out);
    with_loop(offset, index, |l| {
        let value = segvoronoi_loop {
            piece_count: l.pieces.len(),
            parent: l.parent.map_or(SEGVORONOI_NO_PARENT, |p| p as u32),
            hole: l.hole,
            signed_area: l.signed_area(),
            ..Default::default()
        };
        write_versioned(out, value)
    })
}

/// Piece `piece` of loop `index` in `*out`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (loop or piece),
/// `INVALID_ARGUMENT` (`out->struct_size` too small); then `*out` is
/// untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_offset_piece(
    offset: *const segvoronoi_offset,
    index: usize,
    piece: usize,
    out: *mut segvoronoi_loop_piece,
) -> segvoronoi_status {
    require_non_null!(out);
    with_loop(offset, index, |l| {
        let Some(&p) = l.pieces.get(piece) else { return out_of_range(&format!("loop {index}'s piece"), piece, l.pieces.len()) };
        let value = match p {
            OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, site } => segvoronoi_loop_piece {
                kind: SEGVORONOI_OFFSET_ARC,
                site: site.index() as u32,
                from: from.into(),
                to: to.into(),
                centre: centre.into(),
                radius,
                counter_clockwise,
                ..Default::default()
            },
            other => segvoronoi_loop_piece {
                kind: SEGVORONOI_OFFSET_LINE,
                site: other.site().index() as u32,
                from: other.from().into(),
                to: other.to().into(),
                ..Default::default()
            },
        };
        write_versioned(out, value)
    })
}

/// The points of loop `index` within `tolerance` (input units) of its exact
/// curve, `{x, y}` each, the first not repeated at the end: simple, and
/// nested as the exact loops are (Rust's `OffsetLoop::polyline`). Up to
/// `capacity` points (`2 * capacity` doubles) to `xy`, the full number to
/// `*count`; `xy = NULL, capacity = 0` only counts (`OK`), allocating
/// nothing.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`, `INVALID_ARGUMENT` (a tolerance
/// that is not positive), `TOO_LARGE` (the loop would have more than
/// `SEGVORONOI_MAX_POLYLINE_POINTS` points: nothing is written),
/// `BUFFER_TOO_SMALL` (then `*count` holds the number needed and the first
/// `capacity` points are written).
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_offset_loop_polyline(
    offset: *const segvoronoi_offset,
    index: usize,
    tolerance: f64,
    xy: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    require_buffer!(xy, capacity, count);
    with_loop(offset, index, |l| {
        let Some(total) = l.polyline_len(tolerance) else { return not_positive(tolerance) };
        if let Err(status) = check_polyline_len(total, tolerance) {
            return status;
        }
        // two consecutive doubles per point: the alignment of an array of them
        write_indexed(total, xy.cast::<[f64; 2]>(), capacity, count, |sink| {
            let mut j = 0;
            l.for_each_polyline_point(tolerance, |p| {
                sink(j, p.into());
                j += 1;
            });
        })
    })
}

/// `INVALID_ARGUMENT` for a tolerance that is not positive.
pub(super) fn not_positive(tolerance: f64) -> segvoronoi_status {
    fail(segvoronoi_status::InvalidArgument, format!("tolerance {tolerance} is not positive"))
}
