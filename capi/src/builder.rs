//! `segvoronoi_builder`: collects input and builds diagrams.

use std::ffi::{c_char, CString};

use super::diagram::segvoronoi_diagram;
use super::out::{require_buffer, write_buffer};
use super::plumbing::{
    fail, fail_with, guard, guard_or, last_error_string, require_non_null, segvoronoi_status, set_last_error, try_box,
};
use segvoronoi::Error;
use segvoronoi::{Builder, MAX_POINTS};

/// Collects input sites. Opaque. Create with `segvoronoi_builder_new`, free
/// with `segvoronoi_builder_free`.
///
/// Thread safety: one thread at a time. A builder may move between threads
/// (nothing in it is tied to the thread that made it), but two calls on it
/// must not overlap; calls on different builders may.
pub struct segvoronoi_builder {
    pub(crate) inner: Builder,
    last_error: CString,
    /// The input indices of the last error (`Error::indices`).
    last_error_indices: Vec<usize>,
}

impl segvoronoi_builder {
    /// Keeps the outcome of a call as this builder's last error and the
    /// thread's (`segvoronoi_last_error_message`).
    pub(crate) fn record(&mut self, result: Result<(), Error>) -> segvoronoi_status {
        match result {
            Ok(()) => {
                self.set_error(CString::default(), Vec::new());
                segvoronoi_status::Ok
            }
            Err(e) => {
                self.set_error(CString::new(e.message()).unwrap_or_default(), e.indices().to_vec());
                fail_with(&e)
            }
        }
    }

    /// A failure found at the boundary (a NULL buffer, a count too large to
    /// describe one): the builder's message too, so that it never keeps the
    /// message of an earlier call.
    pub(crate) fn refuse(&mut self, status: segvoronoi_status, message: &str) -> segvoronoi_status {
        self.refuse_naming(status, message, Vec::new())
    }

    /// A failure found at the boundary that names input indices (kept for
    /// `segvoronoi_builder_last_error_indices`).
    pub(crate) fn refuse_naming(&mut self, status: segvoronoi_status, message: &str, indices: Vec<usize>) -> segvoronoi_status {
        self.set_error(CString::new(message.replace('\0', " ")).unwrap_or_default(), indices);
        fail(status, message)
    }

    fn set_error(&mut self, message: CString, indices: Vec<usize>) {
        set_last_error(&message.to_string_lossy());
        self.last_error = message;
        self.last_error_indices = indices;
    }
}

/// A new, empty builder. Returns NULL only if memory is exhausted (then
/// `segvoronoi_last_error_message` says so).
///
/// Ownership: the caller owns the builder and frees it with
/// `segvoronoi_builder_free`.
#[no_mangle]
pub extern "C" fn segvoronoi_builder_new() -> *mut segvoronoi_builder {
    guard_or(std::ptr::null_mut(), || {
        let builder =
            segvoronoi_builder { inner: Builder::new(), last_error: CString::default(), last_error_indices: Vec::new() };
        try_box(builder).unwrap_or_else(|| {
            set_last_error("out of memory: no room for a builder");
            std::ptr::null_mut()
        })
    })
}

/// Frees a builder. NULL does nothing. Diagrams built from it stay valid.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_free(builder: *mut segvoronoi_builder) {
    if builder.is_null() {
        return;
    }
    // SAFETY: the caller passes a builder from `segvoronoi_builder_new`
    // (made by `try_box`, which `Box::from_raw` may free), not freed yet and
    // in no other call.
    guard_or((), || drop(unsafe { Box::from_raw(builder) }))
}

/// Adds one point. Its input index is the number of points added before it.
///
/// Errors: `SEGVORONOI_STATUS_INVALID_COORDINATE` if `x` or `y` is NaN or
/// infinite; the builder is then unchanged and
/// `segvoronoi_builder_last_error` names the input index.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_add_point(builder: *mut segvoronoi_builder, x: f64, y: f64) -> segvoronoi_status {
    require_non_null!(builder);
    guard(|| {
        // SAFETY: non-null, and the caller passes a live builder used by this thread only.
        let b = unsafe { &mut *builder };
        let r = b.inner.add_point([x, y]).map(|_| ());
        b.record(r)
    })
}

/// Adds `count` points from `xy` = `{x0, y0, x1, y1, ...}` (`2 * count`
/// doubles), all or none. `xy` may be NULL when `count` is 0.
///
/// Errors: `SEGVORONOI_STATUS_INVALID_COORDINATE` for the first non-finite
/// coordinate; nothing is added and the message names the input index the
/// point would have had. `SEGVORONOI_STATUS_TOO_LARGE` when the builder
/// would hold more than 600 million points (checked before `xy` is read).
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_add_points(
    builder: *mut segvoronoi_builder,
    xy: *const f64,
    count: usize,
) -> segvoronoi_status {
    // SAFETY: passed on from the caller (see `add_flat`).
    unsafe {
        add_flat::<2>(builder, xy, count, Builder::reserve_points, |b, c| {
            let r = b.inner.add_points(c.chunks_exact(2).map(|c| [c[0], c[1]]));
            b.record(r.map(|_| ()))
        })
    }
}

/// Adds the segment from `(x1, y1)` to `(x2, y2)`. Its input index is the
/// number of segments added before it. Segments may share endpoints;
/// crossings are reported by `segvoronoi_builder_build`.
///
/// Errors: `SEGVORONOI_STATUS_INVALID_COORDINATE` if a coordinate is NaN or
/// infinite (the builder is then unchanged and the message names the
/// segment's index), `SEGVORONOI_STATUS_TOO_LARGE`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_add_segment(
    builder: *mut segvoronoi_builder,
    x1: f64,
    y1: f64,
    x2: f64,
    y2: f64,
) -> segvoronoi_status {
    require_non_null!(builder);
    guard(|| {
        // SAFETY: non-null, and the caller passes a live builder used by this thread only.
        let b = unsafe { &mut *builder };
        let r = b.inner.add_segment([[x1, y1], [x2, y2]]).map(|_| ());
        b.record(r)
    })
}

/// Adds `count` segments from `xy` = `{x1, y1, x2, y2, ...}` (`4 * count`
/// doubles), all or none. `xy` may be NULL when `count` is 0.
///
/// Errors: as `segvoronoi_builder_add_segment`, for the first bad segment;
/// nothing is added. `SEGVORONOI_STATUS_TOO_LARGE` is checked before `xy` is
/// read.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_add_segments(
    builder: *mut segvoronoi_builder,
    xy: *const f64,
    count: usize,
) -> segvoronoi_status {
    // SAFETY: passed on from the caller (see `add_flat`).
    unsafe {
        add_flat::<4>(builder, xy, count, Builder::reserve_segments, |b, c| {
            let r = b.inner.add_segments(c.chunks_exact(4).map(|c| [[c[0], c[1]], [c[2], c[3]]]));
            b.record(r.map(|_| ()))
        })
    }
}

/// Adds a polygon: `n_rings` rings, ring `k` of `ring_lengths[k]` points,
/// their coordinates one after another in `xy` = `{x, y, ...}`. Each ring is
/// closed (its last point joins its first; a repeated closing point is
/// accepted); repeated consecutive points are dropped. The rings of all
/// polygons bound the domain by the even-odd rule, whatever their
/// orientation (see `segvoronoi_diagram_vertex_location`). The segments get
/// the next input indices, ring by ring.
///
/// Errors: `NULL_ARGUMENT`; `INVALID_POLYGON` (a ring with fewer than three
/// distinct points) or `INVALID_COORDINATE`, naming the polygon and the ring
/// (`segvoronoi_builder_last_error_indices`: polygon, ring[, point]);
/// `TOO_LARGE`. The builder is then unchanged. Rings that cross are
/// `INTERSECTING` from `segvoronoi_builder_build`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_add_polygon(
    builder: *mut segvoronoi_builder,
    xy: *const f64,
    ring_lengths: *const usize,
    n_rings: usize,
) -> segvoronoi_status {
    require_non_null!(builder);
    {
        // SAFETY: non-null; the caller passes a live builder used by this thread only.
        let b = unsafe { &mut *builder };
        if n_rings > 0 && ring_lengths.is_null() {
            return b.refuse(segvoronoi_status::NullArgument, "argument `ring_lengths` is NULL");
        }
        // Bound the count before it becomes a slice: every ring has a point,
        // so more rings than a diagram holds points cannot be valid input,
        // and a larger count need not describe memory at all.
        if n_rings > MAX_POINTS {
            let message = format!("{n_rings} rings are too many: a diagram holds at most {MAX_POINTS} points");
            return b.refuse(segvoronoi_status::TooLarge, &message);
        }
    }
    // SAFETY: `ring_lengths` is non-null when n_rings > 0 and holds n_rings
    // readable `size_t`s (the caller's promise); n_rings <= MAX_POINTS keeps
    // the slice's byte size far below isize::MAX.
    let lengths: &[usize] = if n_rings == 0 { &[] } else { unsafe { std::slice::from_raw_parts(ring_lengths, n_rings) } };
    let Some(total) = lengths.iter().try_fold(0usize, |sum, &n| sum.checked_add(n)) else {
        // SAFETY: as above, the live builder.
        let b = unsafe { &mut *builder };
        return b.refuse(segvoronoi_status::TooLarge, "the ring lengths add up to more than SIZE_MAX points");
    };
    // SAFETY: passed on from the caller (see `add_flat`): `xy` holds the
    // `total` points of all rings.
    unsafe {
        add_flat::<2>(builder, xy, total, Builder::reserve_segments, |b, coords| {
            let mut rings: Vec<Vec<[f64; 2]>> = Vec::new();
            if rings.try_reserve(lengths.len()).is_err() {
                return b.refuse(segvoronoi_status::OutOfMemory, &format!("out of memory: no room for {} rings", lengths.len()));
            }
            let mut at = 0;
            for &n in lengths {
                rings.push(coords[2 * at..2 * (at + n)].chunks_exact(2).map(|c| [c[0], c[1]]).collect());
                at += n;
            }
            let r = b.inner.add_polygon(&rings);
            b.record(r.map(|_| ()))
        })
    }
}

/// Adds an open chain of `count` points `xy` = `{x, y, ...}` as segments
/// (repeated consecutive points dropped): an obstacle, which does not bound
/// the domain. `xy` may be NULL when `count` is 0.
///
/// Errors: `NULL_ARGUMENT`, `INVALID_COORDINATE` (naming the point),
/// `TOO_LARGE`; the builder is then unchanged.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_add_polyline(
    builder: *mut segvoronoi_builder,
    xy: *const f64,
    count: usize,
) -> segvoronoi_status {
    // SAFETY: passed on from the caller (see `add_flat`).
    unsafe {
        add_flat::<2>(builder, xy, count, Builder::reserve_segments, |b, c| {
            let points: Vec<[f64; 2]> = c.chunks_exact(2).map(|c| [c[0], c[1]]).collect();
            let r = b.inner.add_polyline(&points);
            b.record(r.map(|_| ()))
        })
    }
}

/// Bulk input shared by the `add_points` / `add_segments` calls: `count`
/// items of `STRIDE` doubles at `xy`, all or none. The room is checked with
/// `reserve` before `xy` is turned into a slice (a count that large cannot
/// describe a real buffer).
///
/// Safety: `builder` is NULL or a live builder used by this thread only;
/// `xy` is valid for `STRIDE * count` reads when `count > 0`.
unsafe fn add_flat<const STRIDE: usize>(
    builder: *mut segvoronoi_builder,
    xy: *const f64,
    count: usize,
    reserve: impl FnOnce(&mut Builder, usize) -> Result<(), Error>,
    add: impl FnOnce(&mut segvoronoi_builder, &[f64]) -> segvoronoi_status,
) -> segvoronoi_status {
    require_non_null!(builder);
    guard(|| {
        // SAFETY: non-null; the caller keeps the builder exclusive.
        let b = unsafe { &mut *builder };
        if count > 0 && xy.is_null() {
            return b.refuse(segvoronoi_status::NullArgument, "argument `xy` is NULL");
        }
        // The size limit (TOO_LARGE) and the room (OUT_OF_MEMORY, by
        // `try_reserve`) come first: `count` is the caller's number.
        if let Err(e) = reserve(&mut b.inner, count) {
            return b.record(Err(e));
        }
        // `reserve` bounds count by MAX_POINTS, so this never fails on a
        // 64-bit target; on a 32-bit one it keeps the slice below isize::MAX bytes.
        let Some(doubles) = STRIDE.checked_mul(count).filter(|n| *n <= isize::MAX as usize / std::mem::size_of::<f64>()) else {
            return b.refuse(segvoronoi_status::TooLarge, "the coordinates would exceed the address space");
        };
        // SAFETY: non-null when count > 0, valid for STRIDE * count reads
        // (the caller's promise), and that many doubles span at most
        // isize::MAX bytes (checked above).
        let coords: &[f64] = if count == 0 { &[] } else { unsafe { std::slice::from_raw_parts(xy, doubles) } };
        add(b, coords)
    })
}

/// The number of segments added so far (repeats included); 0 for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_segment_count(builder: *const segvoronoi_builder) -> usize {
    if builder.is_null() {
        return 0;
    }
    // SAFETY: non-null live builder.
    guard_or(0, || unsafe { &*builder }.inner.segment_count())
}

/// The number of points added so far (repeats included); 0 for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_point_count(builder: *const segvoronoi_builder) -> usize {
    if builder.is_null() {
        return 0;
    }
    // SAFETY: non-null live builder.
    guard_or(0, || unsafe { &*builder }.inner.point_count())
}

/// Builds the diagram of everything added so far and stores it in `*out`.
/// The builder is not consumed and stays as it was.
///
/// Errors: `SEGVORONOI_STATUS_INTERSECTING` when two segments or arcs cross
/// or overlap or a point lies inside a segment or an arc (the message names
/// both inputs). `SEGVORONOI_STATUS_UNSUPPORTED_RANGE` when the input's
/// coordinates span more than the exact range (largest magnitude over
/// `2^480`, about 3e144, times the smallest nonzero magnitude or difference
/// between coordinates) and the build at that span did not check out (see
/// the README's "exact range"): not a bug. `SEGVORONOI_STATUS_INVALID_ARGUMENT`
/// for an input with arcs that this version does not build yet (the
/// message says which and what to do): arcs together with polygons or with
/// splitting (`segvoronoi_builder_set_split_crossings`), or an arc that
/// would reach around every site added before it (give it as two arcs). `SEGVORONOI_STATUS_INTERNAL` when
/// the construction could not complete a valid diagram, or panicked: a bug
/// in segvoronoi (none is known), never an invalid diagram;
/// `segvoronoi_last_error_message` says what failed. Please report the
/// input.
///
/// Ownership: on success the caller owns `*out` and frees it with
/// `segvoronoi_diagram_free`. On any error `*out` is set to NULL.
///
/// Thread safety: one builder must not be used from two threads at once.
/// For 100,000 points or more the call sorts its insertion order on a second,
/// short-lived thread of its own, joined before it returns.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_build(
    builder: *mut segvoronoi_builder,
    out: *mut *mut segvoronoi_diagram,
) -> segvoronoi_status {
    if !out.is_null() {
        // SAFETY: out is non-null and writable.
        unsafe { *out = std::ptr::null_mut() };
    }
    require_non_null!(builder);
    guard(|| {
        // SAFETY: non-null live builder, exclusive to this thread.
        let b = unsafe { &mut *builder };
        if out.is_null() {
            return b.refuse(segvoronoi_status::NullArgument, "argument `out` is NULL");
        }
        // `build` takes the builder by shared reference: a panic leaves it as it was.
        match guard_or(None, || Some(b.inner.build())) {
            Some(Ok(d)) => match segvoronoi_diagram::into_raw(d) {
                Some(diagram) => {
                    b.record(Ok(()));
                    // SAFETY: out is non-null and writable.
                    unsafe { *out = diagram };
                    segvoronoi_status::Ok
                }
                None => b.refuse(segvoronoi_status::OutOfMemory, "out of memory: no room for the diagram's handle"),
            },
            Some(Err(e)) => b.record(Err(e)),
            // the panic's text, from `guard_or`
            None => b.refuse(segvoronoi_status::Internal, &last_error_string()),
        }
    })
}

/// Whether `segvoronoi_builder_build` splits the input where it crosses
/// itself (`on` nonzero) or refuses crossings with
/// `SEGVORONOI_STATUS_INTERSECTING` (0, the default). Splitting cuts
/// crossings, overlaps, T-junctions and points inside segments into shared
/// endpoints by snap rounding; the diagram is then that of the pieces
/// (`segvoronoi_diagram_pieces_of_input`, `_inputs_of_piece`), each within
/// `segvoronoi_diagram_max_split_displacement` of its input segments, and
/// polygons bound the even-odd region of their split rings (see
/// `Builder::split_crossings` in the Rust documentation). Arcs are split
/// too, into arcs (`segvoronoi_diagram_arc_pieces_of_input`), and polygons
/// with arcs (`segvoronoi_builder_add_bulged_polygon`, or plain polygons
/// beside arcs) bound the even-odd region of their split rings, arcs and
/// segments alike.
///
/// Errors: `NULL_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_set_split_crossings(builder: *mut segvoronoi_builder, on: i32) -> segvoronoi_status {
    require_non_null!(builder);
    guard(|| {
        // SAFETY: non-null live builder, exclusive to this thread.
        let b = unsafe { &mut *builder };
        b.inner.split_crossings(on != 0);
        b.record(Ok(()))
    })
}

/// At most `threads` threads running at once in `segvoronoi_builder_build`
/// (the calling one included); 0, the default, for as many as the machine
/// has cores. The diagram is the same for every count (its canonical
/// topology text with `SEGVORONOI_TOPOLOGY_CANONICAL_CUTS` byte for byte,
/// every vertex at the same position; vertices and edges may be numbered
/// otherwise, and a degenerate vertex, four sites or more on one circle,
/// cut into its degree-3 parts another way). With a second thread, a build of
/// 60,000 sites or more without arcs runs in two halves built at once and
/// glued (with four threads or more, each half of 60,000 sites or more in
/// halves in turn); smaller ones run parts of their work on it (the input check
/// beside the point insertions, the sort of the insertion order, the check
/// of the arcs' vertices). 1 starts no thread at all, for programs that
/// run many builds on threads of their own.
///
/// Errors: `NULL_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_set_threads(builder: *mut segvoronoi_builder, threads: usize) -> segvoronoi_status {
    require_non_null!(builder);
    guard(|| {
        // SAFETY: non-null live builder, exclusive to this thread.
        let b = unsafe { &mut *builder };
        b.inner.threads(threads);
        b.record(Ok(()))
    })
}

/// Checks everything added so far as `segvoronoi_builder_build` does first,
/// without building: `SEGVORONOI_STATUS_OK` when no two segments or arcs
/// cross or overlap and no point lies inside a segment or an arc (shared
/// endpoints are fine). Exact, O(n log n) expected time for n points and
/// segments.
///
/// Errors: `SEGVORONOI_STATUS_INTERSECTING` with the same message and
/// indices `_build` would give (`segvoronoi_builder_last_error`,
/// `_last_error_indices`): the conflict whose first common point (by x,
/// then y) is smallest. `NULL_ARGUMENT` for a NULL builder;
/// `INTERNAL` if the check panicked (a bug; please report the input).
///
/// Ownership: nothing is allocated for the caller; the builder stays as it
/// was apart from its last error.
///
/// Thread safety: one builder must not be used from two threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_check(builder: *mut segvoronoi_builder) -> segvoronoi_status {
    require_non_null!(builder);
    guard(|| {
        // SAFETY: non-null live builder, exclusive to this thread.
        let b = unsafe { &mut *builder };
        match guard_or(None, || Some(b.inner.check())) {
            Some(r) => b.record(r),
            // the panic's text, from `guard_or`
            None => b.refuse(segvoronoi_status::Internal, &last_error_string()),
        }
    })
}

/// The message of the last failed call on this builder (naming the offending
/// input indices), or `""` if the last call succeeded. Never NULL. The same
/// text as `segvoronoi_last_error_message` right after a call on this
/// builder; this one stays with the builder while other calls come between.
///
/// Ownership: the builder owns the text; it stays valid until the next call
/// on this builder or its `_free`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_last_error(builder: *const segvoronoi_builder) -> *const c_char {
    if builder.is_null() {
        return c"builder is NULL".as_ptr();
    }
    // SAFETY: non-null live builder.
    guard_or(c"internal error".as_ptr(), || unsafe { &*builder }.last_error.as_ptr())
}

/// The input indices that the last failed call on this builder named (the
/// numbers in its `segvoronoi_builder_last_error` message): for
/// `SEGVORONOI_STATUS_INVALID_COORDINATE` the point's, segment's or arc's
/// index (a bulged polyline's vertex), for `SEGVORONOI_STATUS_INVALID_ARC`
/// the arc's index (a bulged polyline's vertex),
/// for `SEGVORONOI_STATUS_INTERSECTING` both (two segment indices, or the
/// point's and then the segment's), for `SEGVORONOI_STATUS_INTERNAL` the
/// segment that failed when one did; none after a successful call. Writes
/// up to `capacity` of them to `indices` and their number to `*count`;
/// `indices = NULL, capacity = 0` only counts (`OK`).
///
/// Errors: `NULL_ARGUMENT` (`builder` or `count` NULL, or `indices` NULL
/// with `capacity > 0`), `BUFFER_TOO_SMALL` (then `*count` holds the number
/// and the first `capacity` are written). Unlike other calls, a success
/// leaves `segvoronoi_last_error_message` as it was: this reads the error.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_last_error_indices(
    builder: *const segvoronoi_builder,
    indices: *mut usize,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    require_non_null!(builder);
    require_buffer!(indices, capacity, count);
    guard_or(segvoronoi_status::Internal, || {
        // SAFETY: non-null live builder.
        let b = unsafe { &*builder };
        // not `guard`, which would clear the message this call belongs to
        write_buffer(b.last_error_indices.iter().copied(), indices, capacity, count)
    })
}
