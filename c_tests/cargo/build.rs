//! Compiles the C API tests and the misuse table as strict C99 into a static
//! library for the tests in tests/c_api.rs.

fn main() {
    println!("cargo:rerun-if-changed=../test_c_api.c");
    println!("cargo:rerun-if-changed=../misuse.c");
    println!("cargo:rerun-if-changed=../../capi/include/segvoronoi.h");
    cc::Build::new()
        .file("../test_c_api.c")
        .file("../misuse.c")
        .include("../../capi/include")
        .define("SEGVORONOI_C_TESTS_NO_MAIN", None)
        .std("c99")
        .warnings(true)
        .extra_warnings(true)
        .flag_if_supported("-pedantic")
        .warnings_into_errors(true)
        .compile("segvoronoi_c_api_tests");
    println!("cargo:rustc-link-lib=m");
}
