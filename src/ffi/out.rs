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

use super::plumbing::segvoronoi_status;

/// Writes `value` through `out` and reports success.
pub(super) fn write_out<T>(out: *mut T, value: T) -> segvoronoi_status {
    // SAFETY: callers check `out` for NULL first; it points to writable memory.
    unsafe { out.write(value) };
    segvoronoi_status::Ok
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
        unsafe impl $crate::ffi::out::Versioned for $t {
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
        return segvoronoi_status::InvalidArgument;
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
/// shorter). `None` when `struct_size` is below the first version's size.
///
/// # Safety
/// `p` is non-NULL and points to at least `struct_size` readable bytes.
pub(super) unsafe fn read_versioned<T: Versioned + Default>(p: *const T) -> Option<T> {
    // SAFETY: `struct_size` is the first field (the `Versioned` contract)
    // and every caller's struct has it.
    let size = unsafe { p.cast::<usize>().read_unaligned() };
    if size < T::FIRST_SIZE {
        return None;
    }
    let mut value = T::default();
    let n = size.min(std::mem::size_of::<T>());
    // SAFETY: the caller's struct has `size >= n` readable bytes, `value`
    // has `size_of::<T>() >= n` writable ones, and every field is plain
    // data for which any bytes the caller wrote are its own value.
    unsafe { std::ptr::copy_nonoverlapping(p.cast::<u8>(), (&mut value as *mut T).cast::<u8>(), n) };
    Some(value)
}

/// Returns early with `NullArgument` unless `count` is non-NULL and
/// `buffer` is non-NULL or `capacity` is 0.
macro_rules! require_buffer {
    ($buffer:expr, $capacity:expr, $count:expr) => {
        $crate::ffi::plumbing::require_non_null!($count);
        if $capacity > 0 {
            $crate::ffi::plumbing::require_non_null!($buffer);
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
    if n > capacity && !buffer.is_null() {
        segvoronoi_status::BufferTooSmall
    } else {
        segvoronoi_status::Ok
    }
}
