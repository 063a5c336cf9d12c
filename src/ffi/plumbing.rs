//! Status codes, the panic boundary, pointer helpers, static strings.

use std::ffi::{c_char, c_int, CStr};
use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::error::{Error, ErrorKind};

/// Result of every fallible call. The numbers are stable across versions.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum segvoronoi_status {
    /// Success.
    Ok = 0,
    /// A required pointer argument was NULL.
    NullArgument = 1,
    /// An input coordinate is NaN or infinite (the message names the input index).
    InvalidCoordinate = 2,
    /// Input segments cross or overlap, or a point lies inside a segment
    /// (the message names both input indices).
    Intersecting = 3,
    /// An index argument is out of range.
    OutOfRange = 4,
    /// The caller's buffer is too small; the required count was written.
    BufferTooSmall = 5,
    /// More input than the diagram's 32-bit ids can hold.
    TooLarge = 6,
    /// An argument has an invalid value (for example unknown flag bits).
    InvalidArgument = 7,
    /// A bug in segvoronoi, not in the input: a caught panic, or a build that
    /// could not complete a valid diagram (no diagram is returned; the
    /// builder is unchanged and `segvoronoi_builder_last_error` says what
    /// failed). Please report it with the input.
    Internal = 8,
    /// A polygon ring has fewer than three distinct points (the message
    /// names the polygon and the ring).
    InvalidPolygon = 9,
    /// The input's coordinates span more than the exact range (largest
    /// magnitude over `2^480` times the smallest nonzero magnitude or
    /// difference) and could not be built at that span; the message names
    /// the two coordinates and the range. Not a bug; see the README.
    UnsupportedRange = 10,
}

impl segvoronoi_status {
    /// Every status, in numeric order.
    const ALL: [segvoronoi_status; 11] = [
        segvoronoi_status::Ok,
        segvoronoi_status::NullArgument,
        segvoronoi_status::InvalidCoordinate,
        segvoronoi_status::Intersecting,
        segvoronoi_status::OutOfRange,
        segvoronoi_status::BufferTooSmall,
        segvoronoi_status::TooLarge,
        segvoronoi_status::InvalidArgument,
        segvoronoi_status::Internal,
        segvoronoi_status::InvalidPolygon,
        segvoronoi_status::UnsupportedRange,
    ];

    fn from_number(n: c_int) -> Option<segvoronoi_status> {
        Self::ALL.into_iter().find(|s| *s as c_int == n)
    }
}

impl From<&Error> for segvoronoi_status {
    fn from(e: &Error) -> Self {
        match e.kind() {
            ErrorKind::InvalidCoordinate => segvoronoi_status::InvalidCoordinate,
            ErrorKind::TooLarge => segvoronoi_status::TooLarge,
            ErrorKind::Intersecting => segvoronoi_status::Intersecting,
            ErrorKind::Internal => segvoronoi_status::Internal,
            ErrorKind::UnsupportedRange => segvoronoi_status::UnsupportedRange,
            ErrorKind::InvalidPolygon => segvoronoi_status::InvalidPolygon,
            ErrorKind::InvalidArgument => segvoronoi_status::InvalidArgument,
        }
    }
}

/// Runs `f`, turning a panic into `Internal`.
pub(crate) fn guard(f: impl FnOnce() -> segvoronoi_status) -> segvoronoi_status {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or(segvoronoi_status::Internal)
}

/// Runs `f`, turning a panic into `fallback`.
pub(crate) fn guard_or<T>(fallback: T, f: impl FnOnce() -> T) -> T {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or(fallback)
}

/// Returns early with `NullArgument` when any pointer is NULL.
macro_rules! require_non_null {
    ($($p:expr),+) => {
        if $($p.is_null())||+ {
            return $crate::ffi::plumbing::segvoronoi_status::NullArgument;
        }
    };
}
pub(crate) use require_non_null;

/// Static text for a status code (a `segvoronoi_status` value); never NULL,
/// valid forever. Numbers that are no status give `"unknown status"`.
///
/// Thread safety: safe from any thread.
#[no_mangle]
pub extern "C" fn segvoronoi_status_str(status: c_int) -> *const c_char {
    // An `int`, not the enum: C may pass any number, and a Rust enum holding
    // an undeclared value would be undefined behaviour.
    let Some(status) = segvoronoi_status::from_number(status) else {
        return c"unknown status".as_ptr();
    };
    let s: &'static CStr = match status {
        segvoronoi_status::Ok => c"ok",
        segvoronoi_status::NullArgument => c"a required pointer argument is NULL",
        segvoronoi_status::InvalidCoordinate => c"a coordinate is NaN or infinite",
        segvoronoi_status::Intersecting => c"input segments intersect",
        segvoronoi_status::OutOfRange => c"index out of range",
        segvoronoi_status::BufferTooSmall => c"buffer too small",
        segvoronoi_status::TooLarge => c"too many input sites",
        segvoronoi_status::InvalidArgument => c"invalid argument",
        segvoronoi_status::Internal => c"internal error in segvoronoi",
        segvoronoi_status::InvalidPolygon => c"a polygon ring has fewer than three distinct points",
        segvoronoi_status::UnsupportedRange => c"the input's coordinates span more than the exact range",
    };
    s.as_ptr()
}

/// The library version, `"MAJOR.MINOR.PATCH"`, the same as
/// `SEGVORONOI_VERSION_STRING` in a matching header. Static, never NULL.
///
/// Thread safety: safe from any thread.
#[no_mangle]
pub extern "C" fn segvoronoi_version() -> *const c_char {
    const V: &str = concat!(env!("CARGO_PKG_VERSION"), "\0");
    V.as_ptr() as *const c_char
}

/// The library version as one number, `MAJOR * 10000 + MINOR * 100 +
/// PATCH` (0.1.0 is 100), the same as `SEGVORONOI_VERSION_NUMBER` in a
/// matching header: compare the two to find a library older than the
/// header.
///
/// Thread safety: safe from any thread.
#[no_mangle]
pub extern "C" fn segvoronoi_version_number() -> u32 {
    SEGVORONOI_VERSION_NUMBER
}

/// Frees a string returned by segvoronoi (for example by
/// `segvoronoi_diagram_topology`). NULL does nothing.
///
/// Ownership: takes back the string; it must not be used afterwards.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_string_free(text: *mut c_char) {
    if text.is_null() {
        return;
    }
    guard_or((), || {
        // SAFETY: the caller passes a string made by `into_c_string` and not freed yet.
        drop(unsafe { std::ffi::CString::from_raw(text) });
    })
}

/// Hands a Rust string to C as an owned, NUL-terminated buffer and its length.
pub(crate) fn into_c_string(text: String) -> (*mut c_char, usize) {
    let len = text.len();
    // The text never contains NUL: it is made of names and numbers.
    let c = std::ffi::CString::new(text).unwrap_or_default();
    (c.into_raw(), len)
}

/// Major version of the library this header belongs to.
pub const SEGVORONOI_VERSION_MAJOR: u32 = 0;
/// Minor version of the library this header belongs to.
pub const SEGVORONOI_VERSION_MINOR: u32 = 1;
/// Patch version of the library this header belongs to.
pub const SEGVORONOI_VERSION_PATCH: u32 = 0;
/// The version of the library this header belongs to as one number,
/// `MAJOR * 10000 + MINOR * 100 + PATCH` (see `segvoronoi_version_number`).
pub const SEGVORONOI_VERSION_NUMBER: u32 =
    SEGVORONOI_VERSION_MAJOR * 10000 + SEGVORONOI_VERSION_MINOR * 100 + SEGVORONOI_VERSION_PATCH;
