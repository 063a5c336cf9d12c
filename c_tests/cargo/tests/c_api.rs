//! Runs the C API tests of `c_tests/test_c_api.c`, compiled by build.rs.

use std::ffi::c_int;

extern "C" {
    fn segvoronoi_run_c_tests() -> c_int;
    fn segvoronoi_run_misuse_tests() -> c_int;
}

#[test]
fn c_api_tests_pass() {
    // Keeps the segvoronoi-capi rlib, and with it the exported C functions
    // the C code calls, in the link.
    let version = segvoronoi_c_tests::segvoronoi_capi::segvoronoi_version();
    assert!(!version.is_null());
    // SAFETY: a plain C function with no arguments.
    let failures = unsafe { segvoronoi_run_c_tests() };
    assert_eq!(failures, 0, "C API checks failed; see stderr");
}

#[test]
fn misuse_table_passes() {
    assert!(!segvoronoi_c_tests::segvoronoi_capi::segvoronoi_version().is_null());
    // SAFETY: a plain C function with no arguments.
    let failures = unsafe { segvoronoi_run_misuse_tests() };
    assert_eq!(failures, 0, "misuse checks failed; see stderr");
}
