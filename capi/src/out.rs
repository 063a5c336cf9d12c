//! Writing outputs to the caller: a plain value, a versioned struct, a
//! caller's buffer with its count.
//!
//! **Versioned structs.** Every struct the library fills in may gain fields
//! at its end in a later version. Its first field is `size_t struct_size`,
//! which the caller sets to `sizeof` the struct as its header knows it; the
//! library writes only the fields that fit in that many bytes and sets
//! `struct_size` to the number of bytes it wrote. A program built against an
//! older header gets the fields it knows; one built against a newer header
//! and run with an older library sees a smaller `struct_size` and knows that
//! the fields beyond it were not written. A `struct_size` smaller than the
//! first version of the struct is `SEGVORONOI_STATUS_INVALID_ARGUMENT`.
//!
//! **Buffers.** A query that returns a list takes a buffer, its capacity
//! and a `size_t *count`. It writes up to `capacity` items and the full
//! number to `*count`. Called with `(NULL, 0)` it only counts: `OK` with the
//! count. A non-NULL buffer that is too small gives `BUFFER_TOO_SMALL`, with
//! the count and the first `capacity` items written.

use super::plumbing::{fail, segvoronoi_status};

/// Writes `value` through `out` and reports success.
///
/// Callers check `out` for NULL first (`require_non_null!`); the caller of
/// the export promises that it points to a writable, aligned `T`.
pub(super) fn write_out<T>(out: *mut T, value: T) -> segvoronoi_status {
    // SAFETY: non-null (checked by the caller), and writable and aligned
    // for a `T` (the C caller's promise for this argument).
    unsafe { out.write(value) };
    segvoronoi_status::Ok
}

/// The C name of a type: its last path segment.
fn c_name<T>() -> &'static str {
    let name = std::any::type_name::<T>();
    name.rsplit("::").next().unwrap_or(name)
}

/// A C struct whose first field is `size_t struct_size` (see the module
/// doc). Implemented by [`versioned!`] only.
///
/// # Safety
/// `Self` is `#[repr(C)]`, its first field is `struct_size: usize`, and
/// `FIRST_SIZE <= size_of::<Self>()`.
pub(super) unsafe trait Versioned: Sized {
    /// The bytes up to the end of the last field of the struct's first
    /// version: the least `struct_size` a caller may pass. It never changes
    /// when fields are added.
    const FIRST_SIZE: usize;
}

/// A versioned struct that the caller passes in (read by
/// [`read_versioned`]): every field is an integer, a float or an array of
/// them, so that any bytes a C caller writes are a valid value. No `bool`
/// (only 0 and 1 are valid `bool`s in Rust; a C caller's 2 or 0x80 would be
/// undefined behaviour) and no enum: flags cross as integers, nonzero true.
///
/// # Safety
/// Every bit pattern of `size_of::<Self>()` bytes is a valid `Self`.
pub(super) unsafe trait FromAnyBytes: Versioned {}

/// Declares a struct [`Versioned`]: `versioned!(segvoronoi_vertex, sites:
/// [u32; 3])` names the last field of its first version and that field's
/// type (both checked at compile time). Also gives it a `Default`: all
/// zero, with `struct_size` set to its size, ready to pass.
macro_rules! versioned {
    ($t:ty, $last:ident: $last_type:ty) => {
        impl Default for $t {
            fn default() -> Self {
                // SAFETY: the versioned structs hold only integers, floats,
                // bools and arrays or structs of them, for which all-zero
                // bytes are a valid value.
                let mut value: $t = unsafe { std::mem::zeroed() };
                value.struct_size = std::mem::size_of::<$t>();
                value
            }
        }
        // SAFETY: `struct_size: usize` is the first field (checked below),
        // the struct is `#[repr(C)]` (declared with it beside this call),
        // and FIRST_SIZE ends at one of its fields.
        unsafe impl $crate::out::Versioned for $t {
            const FIRST_SIZE: usize = std::mem::offset_of!($t, $last) + std::mem::size_of::<$last_type>();
        }
        const _: () = assert!(std::mem::offset_of!($t, struct_size) == 0);
        const _: fn(&$t) -> (&usize, &$last_type) = |s: &$t| (&s.struct_size, &s.$last);
    };
}
pub(super) use versioned;

/// Writes as much of `value` to `*out` as the caller's `struct_size` asks
/// for, and sets `struct_size` to the bytes written (see the module doc).
/// `INVALID_ARGUMENT`, with nothing written, when the caller's
/// `struct_size` is below [`Versioned::FIRST_SIZE`].
pub(super) fn write_versioned<T: Versioned>(out: *mut T, value: T) -> segvoronoi_status {
    // SAFETY: callers check `out` for NULL first; it points to a struct the
    // caller owns, whose first field (a `usize`, so aligned for one) the
    // caller has set.
    let asked = unsafe { out.cast::<usize>().read() };
    if asked < T::FIRST_SIZE {
        let message = format!(
            "struct_size of the {} is {asked}, below {}, the size of its first version: set it to sizeof the struct",
            c_name::<T>(),
            T::FIRST_SIZE
        );
        return fail(segvoronoi_status::InvalidArgument, message);
    }
    let n = asked.min(std::mem::size_of::<T>());
    let value = std::mem::MaybeUninit::new(value);
    // SAFETY: the caller's struct holds at least `asked >= n` bytes (it
    // declared so), `value` holds `size_of::<T>() >= n` bytes, and the two do
    // not overlap. Copying bytes also copies padding, which is allowed.
    unsafe {
        std::ptr::copy_nonoverlapping(value.as_ptr().cast::<u8>(), out.cast::<u8>(), n);
        out.cast::<usize>().write(n);
    }
    segvoronoi_status::Ok
}

/// Reads a versioned struct the caller passes in (`p` non-NULL): the
/// bytes its `struct_size` says it has, up to the library's own size, over
/// the defaults of the fields it lacks (an older caller's struct is
/// shorter). `INVALID_ARGUMENT`, with a message, when `struct_size` is
/// below the first version's size.
///
/// # Safety
/// `p` is non-NULL and points to at least `struct_size` readable bytes.
pub(super) unsafe fn read_versioned<T: FromAnyBytes + Default>(p: *const T) -> Result<T, segvoronoi_status> {
    // SAFETY: `struct_size` is the first field (the `Versioned` contract)
    // and every caller's struct has it; read unaligned, as C may hand us
    // any address.
    let size = unsafe { p.cast::<usize>().read_unaligned() };
    if size < T::FIRST_SIZE {
        let message =
            format!("struct_size of the {} is {size}, below {}, the size of its first version", c_name::<T>(), T::FIRST_SIZE);
        return Err(fail(segvoronoi_status::InvalidArgument, message));
    }
    let mut value = T::default();
    let n = size.min(std::mem::size_of::<T>());
    // SAFETY: the caller's struct has `size >= n` readable bytes, `value`
    // has `size_of::<T>() >= n` writable ones, they do not overlap, and
    // any bytes are a valid value of every field (`FromAnyBytes`), so the
    // mix of the caller's bytes and the defaults is a valid `T`.
    unsafe { std::ptr::copy_nonoverlapping(p.cast::<u8>(), (&mut value as *mut T).cast::<u8>(), n) };
    Ok(value)
}

/// Returns early with `NullArgument` unless `count` is non-NULL and
/// `buffer` is non-NULL or `capacity` is 0.
macro_rules! require_buffer {
    ($buffer:expr, $capacity:expr, $count:expr) => {
        $crate::plumbing::require_non_null!($count);
        if $capacity > 0 {
            $crate::plumbing::require_non_null!($buffer);
        }
    };
}
pub(super) use require_buffer;

/// Writes the first `capacity` of `items` to `buffer` and their full number
/// to `*count` (see the module doc): `OK` when all fit or for a count
/// query (`buffer` NULL), `BUFFER_TOO_SMALL` otherwise.
///
/// Callers check the arguments with [`require_buffer!`] first: `count` is
/// non-NULL, and `buffer` holds `capacity` writable items when `capacity > 0`.
pub(super) fn write_buffer<T>(
    items: impl IntoIterator<Item = T>,
    buffer: *mut T,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    let mut n = 0usize;
    for item in items {
        if n < capacity {
            // SAFETY: `buffer` holds `capacity` writable items (the caller's
            // promise, checked non-NULL by `require_buffer!`), and n < capacity.
            unsafe { buffer.add(n).write(item) };
        }
        n += 1;
    }
    write_out(count, n);
    too_small(n, buffer, capacity)
}

/// `BUFFER_TOO_SMALL`, with its message, when a non-NULL buffer of
/// `capacity` items is too small for `total`; else `OK`.
fn too_small<T>(total: usize, buffer: *mut T, capacity: usize) -> segvoronoi_status {
    if total > capacity && !buffer.is_null() {
        let message =
            format!("the buffer holds {capacity} items and {total} are needed: *count holds {total}, and the first {capacity} were written");
        fail(segvoronoi_status::BufferTooSmall, message)
    } else {
        segvoronoi_status::Ok
    }
}

/// Most points one polyline or sample of the C API holds
/// (`segvoronoi_offset_loop_polyline`, `segvoronoi_medial_axis_sample_chain`,
/// `segvoronoi_diagram_edge_polyline`): a tolerance that asks for more is
/// `SEGVORONOI_STATUS_TOO_LARGE`, found by counting, before anything is
/// written or allocated. 2^24 points are 256 MiB of `{x, y}` doubles, past
/// any drawing; the cap is on the whole output, not per piece.
pub const SEGVORONOI_MAX_POLYLINE_POINTS: usize = 16_777_216;

/// `TOO_LARGE` when a polyline of `total` points (counted first) is over
/// [`SEGVORONOI_MAX_POLYLINE_POINTS`], with a message naming the tolerance.
pub(super) fn check_polyline_len(total: usize, tolerance: f64) -> Result<(), segvoronoi_status> {
    if total <= SEGVORONOI_MAX_POLYLINE_POINTS {
        return Ok(());
    }
    let needed = if total == usize::MAX { "more than SIZE_MAX".to_string() } else { total.to_string() };
    Err(fail(
        segvoronoi_status::TooLarge,
        format!(
            "tolerance {tolerance:e} asks for {needed} points, more than SEGVORONOI_MAX_POLYLINE_POINTS \
             ({SEGVORONOI_MAX_POLYLINE_POINTS}): use a larger tolerance"
        ),
    ))
}

/// Writes a list of `total` items, counted before: `fill` is called
/// (only when there is a buffer) with a sink that takes each item and its
/// index in the list, in any order; the sink writes those below
/// `capacity`. Then as [`write_buffer`]: `*count = total`, and
/// `BUFFER_TOO_SMALL` when a non-NULL buffer is too small. Nothing is
/// allocated, so a count query costs only the count.
///
/// Callers check the arguments with [`require_buffer!`] first, and `fill`
/// gives exactly the indices `0..total`.
pub(super) fn write_indexed<T>(
    total: usize,
    buffer: *mut T,
    capacity: usize,
    count: *mut usize,
    fill: impl FnOnce(&mut dyn FnMut(usize, T)),
) -> segvoronoi_status {
    if !buffer.is_null() && capacity > 0 {
        fill(&mut |j, item| {
            if j < capacity {
                // SAFETY: `buffer` holds `capacity` writable items (the
                // caller's promise, non-NULL checked above), and j < capacity.
                unsafe { buffer.add(j).write(item) };
            }
        });
    }
    write_out(count, total);
    too_small(total, buffer, capacity)
}
