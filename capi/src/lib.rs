//! The C API of segvoronoi. Declared in `include/segvoronoi.h`, which
//! cbindgen generates from this crate (`tests/header.rs` regenerates it and
//! fails on any difference). Built on the library's public API only; the
//! CMake package at the repository's root links this crate's staticlib into
//! `libsegvoronoi.a` and `libsegvoronoi.so` and installs them.
//!
//! Conventions, as in every export below:
//! - names are `segvoronoi_<type>_<verb>`; handles are opaque;
//! - every fallible call returns a [`segvoronoi_status`]; outputs come last
//!   and are written only on success;
//! - every pointer argument is checked for NULL
//!   (`SEGVORONOI_STATUS_NULL_ARGUMENT`);
//! - every struct the library fills in is versioned by a leading
//!   `struct_size` that the caller sets, and a list query called with
//!   `(NULL, 0)` returns `OK` with the count (both in `out.rs`);
//! - memory the library hands out is freed by the library's own `_free`
//!   function, and `_free(NULL)` does nothing;
//! - every call that returns a status leaves its reason in the thread's last
//!   error (`segvoronoi_last_error_message`, `""` after success; in
//!   `plumbing.rs`);
//! - no panic crosses the boundary: a panic becomes `SEGVORONOI_STATUS_INTERNAL`,
//!   quietly (nothing on stderr), and no caller-given size aborts the
//!   process: `try_reserve`, `SEGVORONOI_STATUS_OUT_OF_MEMORY`;
//! - a slice is made from a C pointer and count only after the count is
//!   bounded; flags the caller passes in a struct are integers (nonzero is
//!   true), never `bool`;
//! - a diagram, a medial axis and an offset are immutable: any number of
//!   threads may read one at once. A medial axis shares its diagram (an
//!   `Arc`). A builder is used by one thread at a time.
//!
//! The library forbids `unsafe` code: all of it is here, and this crate
//! converts and delegates.

// An undocumented public item (and so an undocumented C export) fails the build.
#![deny(missing_docs)]
#![allow(non_camel_case_types)]
#![allow(clippy::missing_safety_doc)]

mod arcs;
mod builder;
mod diagram;
mod domain;
mod medial_axis;
mod navigation;
mod offset;
mod out;
mod pieces;
mod plumbing;
mod shape;

pub use arcs::*;
pub use builder::*;
pub use diagram::*;
pub use domain::*;
pub use medial_axis::*;
pub use navigation::*;
pub use offset::*;
pub use out::SEGVORONOI_MAX_POLYLINE_POINTS;
pub use pieces::*;
pub use plumbing::{
    segvoronoi_last_error_message, segvoronoi_status, segvoronoi_status_str, segvoronoi_string_free, segvoronoi_version,
    segvoronoi_version_number, SEGVORONOI_VERSION_MAJOR, SEGVORONOI_VERSION_MINOR, SEGVORONOI_VERSION_NUMBER,
    SEGVORONOI_VERSION_PATCH,
};
pub use shape::*;
