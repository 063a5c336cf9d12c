//! Status codes, the panic boundary, the thread's last error, pointer
//! helpers, static strings.
//!
//! **The last error.** Every call that returns a `segvoronoi_status`
//! leaves a message in a thread-local slot (as libgeos_c's `_r` handlers and
//! rustls-ffi's error texts do, but without a callback): `""` after `OK`,
//! else a sentence that names the argument or the input at fault (the Rust
//! error's own message where there is one). `segvoronoi_last_error_message`
//! reads it. Thread-local rather than per handle, because many failing calls
//! have no handle to hold it (a NULL handle, a medial axis or offset shared
//! between threads read-only).
//!
//! **Panics.** Every export runs inside [`guard`] or [`guard_or`], which
//! catch a panic and turn it into `SEGVORONOI_STATUS_INTERNAL`. Rust's
//! default panic hook would first print the message and maybe a backtrace on
//! the host's stderr. So on the first call into the library a hook is
//! installed that wraps the one in place: a panic inside a segvoronoi entry
//! point (a thread-local depth counter says so) is recorded as the last
//! error and prints nothing; every other panic goes to the previous hook
//! unchanged. Why a wrapper and not nothing: there is no other way to keep
//! std from printing. Why not a plain replacement: a Rust host that shares
//! this std (it links the rlib, or the staticlib into a Rust program) keeps
//! its own hook's behaviour for its own panics. In the shared library, std
//! is the library's private copy, so the hook affects only panics inside
//! segvoronoi whatever the host does.

use std::cell::{Cell, RefCell};
use std::ffi::{c_char, c_int, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::Once;

use segvoronoi::{Error, ErrorKind};

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
    /// Input segments or arcs cross or overlap, or a point lies inside a
    /// segment or an arc (the message names both inputs).
    Intersecting = 3,
    /// An index argument is out of range.
    OutOfRange = 4,
    /// The caller's buffer is too small; the required count was written.
    BufferTooSmall = 5,
    /// More input than the diagram's 32-bit ids can hold, a count larger
    /// than any array, or a polyline longer than
    /// `SEGVORONOI_MAX_POLYLINE_POINTS` (the message says which).
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
    /// Memory for a size the caller asked for could not be allocated (for
    /// example `segvoronoi_builder_add_points` with a large count under a
    /// memory limit). Nothing was changed; the call may succeed with less.
    /// Since 0.2.
    OutOfMemory = 10,
    /// The input's coordinates span more than the exact range (largest
    /// magnitude over `2^480` times the smallest nonzero magnitude or
    /// difference) and could not be built at that span; the message names
    /// the two coordinates and the range. Not a bug; see the README.
    /// Since 0.2.
    UnsupportedRange = 11,
    /// A circular arc is not one: a zero or non-finite bulge, equal
    /// endpoints, three points on one line, or a circle beyond the range of
    /// `double` (the message says which and names the arc or the polyline
    /// vertex). Nothing was added. Since 0.2.
    InvalidArc = 12,
}

impl segvoronoi_status {
    /// Every status, in numeric order.
    const ALL: [segvoronoi_status; 13] = [
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
        segvoronoi_status::OutOfMemory,
        segvoronoi_status::UnsupportedRange,
        segvoronoi_status::InvalidArc,
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
            ErrorKind::OutOfMemory => segvoronoi_status::OutOfMemory,
            ErrorKind::InvalidArc => segvoronoi_status::InvalidArc,
            // `#[non_exhaustive]`: see `unknown_variant`.
            _ => segvoronoi_status::Internal,
        }
    }
}

thread_local! {
    /// The message of the last call on this thread that returned a status
    /// (`None`: `""`).
    static LAST_ERROR: RefCell<Option<CString>> = const { RefCell::new(None) };
    /// How deep this thread is in segvoronoi entry points (the panic hook
    /// stays quiet inside).
    static DEPTH: Cell<u32> = const { Cell::new(0) };
    /// The text of the last panic caught inside an entry point.
    static PANIC_TEXT: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Sets this thread's last error message (`""` clears it). During thread
/// teardown, when the slot is gone, the message is dropped.
pub(crate) fn set_last_error(message: &str) {
    let text = (!message.is_empty()).then(|| {
        // the messages are made of names and numbers; a NUL would cut it
        CString::new(message.replace('\0', " ")).unwrap_or_default()
    });
    let _ = LAST_ERROR.try_with(|slot| *slot.borrow_mut() = text);
}

/// This thread's last error message (`""` for none).
pub(crate) fn last_error_string() -> String {
    LAST_ERROR
        .try_with(|slot| slot.borrow().as_ref().map(|s| s.to_string_lossy().into_owned()))
        .ok()
        .flatten()
        .unwrap_or_default()
}

fn last_error_is_empty() -> bool {
    LAST_ERROR.try_with(|slot| slot.borrow().is_none()).unwrap_or(true)
}

/// Records `message` as the last error and returns `status`: the one way
/// a failing export leaves its reason.
pub(crate) fn fail(status: segvoronoi_status, message: impl AsRef<str>) -> segvoronoi_status {
    set_last_error(message.as_ref());
    status
}

/// Records a Rust error (its message) and returns its status.
pub(crate) fn fail_with(error: &Error) -> segvoronoi_status {
    fail(segvoronoi_status::from(error), error.message())
}

/// `INTERNAL` for a value of one of the library's `#[non_exhaustive]` enums
/// (`Site`, `EdgeShape`) that this C API has no name for. It does not
/// happen: this crate is built with the library of its own commit (a path
/// dependency; it is not published), and the change that adds a variant
/// gives it its C name; the arm is what a match outside the library's crate
/// needs.
pub(crate) fn unknown_variant(what: &str) -> segvoronoi_status {
    fail(segvoronoi_status::Internal, format!("{what} unknown to this version of the C API"))
}

/// `OUT_OF_RANGE` with a message naming the index and the valid range.
pub(crate) fn out_of_range(what: &str, index: usize, count: usize) -> segvoronoi_status {
    let valid = match count {
        0 => "there are none".to_string(),
        n => format!("valid are 0 to {}", n - 1),
    };
    fail(segvoronoi_status::OutOfRange, format!("{what} {index} is out of range: {valid}"))
}

/// Installs the quiet panic hook (see the module doc) once per process.
fn install_quiet_hook() {
    static ONCE: Once = Once::new();
    if std::thread::panicking() {
        return; // `set_hook` panics on a panicking thread; try again next call
    }
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if DEPTH.try_with(Cell::get).unwrap_or(0) > 0 {
                let _ = PANIC_TEXT.try_with(|t| *t.borrow_mut() = Some(info.to_string()));
            } else {
                previous(info);
            }
        }));
    });
}

/// Runs `f` inside an entry point: the quiet hook installed, the depth
/// counted, a panic caught and returned as its text.
fn quietly<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    install_quiet_hook();
    let _ = DEPTH.try_with(|d| d.set(d.get() + 1));
    let result = catch_unwind(AssertUnwindSafe(f));
    let _ = DEPTH.try_with(|d| d.set(d.get().saturating_sub(1)));
    result.map_err(|_| {
        let text = PANIC_TEXT.try_with(|t| t.borrow_mut().take()).ok().flatten();
        let text = text.unwrap_or_else(|| "a panic".to_string()).replace('\n', " ");
        format!("internal error in segvoronoi ({text}); please report the input")
    })
}

/// Runs the body of an export that returns a status: clears the last
/// error, runs `f`, turns a panic into `Internal` with its text, and makes
/// sure a failing status leaves a message (the status's own text when `f`
/// gave none).
pub(crate) fn guard(f: impl FnOnce() -> segvoronoi_status) -> segvoronoi_status {
    set_last_error("");
    let status = quietly(f).unwrap_or_else(|text| fail(segvoronoi_status::Internal, text));
    if status != segvoronoi_status::Ok && last_error_is_empty() {
        // SAFETY: `segvoronoi_status_str` returns a static NUL-terminated string.
        let text = unsafe { CStr::from_ptr(segvoronoi_status_str(status as c_int)) };
        set_last_error(&text.to_string_lossy());
    }
    status
}

/// Runs `f`, turning a panic into `fallback` (and the last error into the
/// panic's text). For the exports that return no status: they leave the
/// last error as it was otherwise.
pub(crate) fn guard_or<T>(fallback: T, f: impl FnOnce() -> T) -> T {
    quietly(f).unwrap_or_else(|text| {
        set_last_error(&text);
        fallback
    })
}

/// Allocates `value` on the heap for C without aborting when memory is
/// exhausted (`Box::new` would): `None` then. Free the pointer with
/// `Box::from_raw`.
pub(crate) fn try_box<T>(value: T) -> Option<*mut T> {
    let layout = std::alloc::Layout::new::<T>();
    if layout.size() == 0 {
        return Some(Box::into_raw(Box::new(value)));
    }
    // SAFETY: the layout has a nonzero size.
    let p = unsafe { std::alloc::alloc(layout) }.cast::<T>();
    if p.is_null() {
        return None;
    }
    // SAFETY: `p` is fresh, aligned and large enough for a `T`; memory
    // from the global allocator with `Layout::new::<T>()` is what
    // `Box::from_raw` expects (the `Box` docs' memory layout section).
    unsafe { p.write(value) };
    Some(p)
}

/// Returns early with `NullArgument`, and a message naming the argument,
/// when any pointer is NULL.
macro_rules! require_non_null {
    ($($p:expr),+) => {
        $(
            if $p.is_null() {
                return $crate::plumbing::fail(
                    $crate::plumbing::segvoronoi_status::NullArgument,
                    concat!("argument `", stringify!($p), "` is NULL"),
                );
            }
        )+
    };
}
pub(crate) use require_non_null;

/// The message of the last call on this thread that returned a
/// `segvoronoi_status`: `""` after `SEGVORONOI_STATUS_OK`, else what failed,
/// naming the argument or the input index at fault (for example
/// "argument `out` is NULL", "site 7 is out of range: there are 5 sites",
/// "point 3 has a non-finite coordinate (NaN, 1)"). Never NULL. Calls that
/// return no status (counts, `_free`, `_new`, `segvoronoi_status_str`,
/// `segvoronoi_version`, this function) leave it as it was, except that a
/// `_new` that returns NULL and a count that caught a panic set it.
///
/// Ownership: the library owns the text; it stays valid until the next
/// call into segvoronoi on the same thread.
///
/// Thread safety: each thread has its own last error; safe from any thread.
#[no_mangle]
pub extern "C" fn segvoronoi_last_error_message() -> *const c_char {
    LAST_ERROR.try_with(|slot| slot.borrow().as_ref().map_or(c"".as_ptr(), |s| s.as_ptr())).unwrap_or(c"".as_ptr())
}

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
        segvoronoi_status::Intersecting => c"input segments or arcs intersect",
        segvoronoi_status::OutOfRange => c"index out of range",
        segvoronoi_status::BufferTooSmall => c"buffer too small",
        segvoronoi_status::TooLarge => c"too large: too many input sites or output points",
        segvoronoi_status::InvalidArgument => c"invalid argument",
        segvoronoi_status::Internal => c"internal error in segvoronoi",
        segvoronoi_status::InvalidPolygon => c"a polygon ring has fewer than three distinct points",
        segvoronoi_status::OutOfMemory => c"out of memory",
        segvoronoi_status::UnsupportedRange => c"the input's coordinates span more than the exact range",
        segvoronoi_status::InvalidArc => c"invalid circular arc",
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
/// PATCH` (0.2.0 is 200), the same as `SEGVORONOI_VERSION_NUMBER` in a
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
pub const SEGVORONOI_VERSION_MINOR: u32 = 2;
/// Patch version of the library this header belongs to.
pub const SEGVORONOI_VERSION_PATCH: u32 = 0;
/// The version of the library this header belongs to as one number,
/// `MAJOR * 10000 + MINOR * 100 + PATCH` (see `segvoronoi_version_number`).
pub const SEGVORONOI_VERSION_NUMBER: u32 =
    SEGVORONOI_VERSION_MAJOR * 10000 + SEGVORONOI_VERSION_MINOR * 100 + SEGVORONOI_VERSION_PATCH;

#[cfg(test)]
mod tests {
    use super::*;

    fn message() -> String {
        // SAFETY: the function returns a NUL-terminated string, never NULL.
        unsafe { CStr::from_ptr(segvoronoi_last_error_message()) }.to_string_lossy().into_owned()
    }

    /// A panic inside an entry point is INTERNAL with its text as the last
    /// error: the quiet hook took it (the previous hook, which prints, did
    /// not see it), and the next success clears the message.
    #[test]
    fn panic_becomes_internal_with_its_text() {
        let status = guard(|| panic!("boom at the boundary"));
        assert_eq!(status, segvoronoi_status::Internal);
        let text = message();
        assert!(text.contains("boom at the boundary") && text.contains("internal error"), "{text}");
        assert_eq!(guard(|| segvoronoi_status::Ok), segvoronoi_status::Ok);
        assert_eq!(message(), "");
        // a failure without a message of its own gets the status's text
        assert_eq!(guard(|| segvoronoi_status::OutOfRange), segvoronoi_status::OutOfRange);
        assert_eq!(message(), "index out of range");
        // `guard_or` (no status) keeps the message unless it catches a panic
        assert_eq!(guard_or(7, || 3), 3);
        assert_eq!(message(), "index out of range");
        assert_eq!(guard_or(7, || panic!("second")), 7);
        assert!(message().contains("second"));
    }

    #[test]
    fn out_of_range_names_the_valid_range() {
        out_of_range("site", 9, 3);
        assert_eq!(message(), "site 9 is out of range: valid are 0 to 2");
        out_of_range("chain", 0, 0);
        assert_eq!(message(), "chain 0 is out of range: there are none");
    }
}
