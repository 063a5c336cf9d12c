//! Carrier crate for the C API tests in `c_tests/test_c_api.c`; see
//! `tests/c_api.rs`. Re-exports segvoronoi-capi so the test links its C
//! symbols.

pub use segvoronoi_capi;
