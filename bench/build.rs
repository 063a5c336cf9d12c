//! Compiles Boost.Polygon's C++ Voronoi builder (header-only, Debian's
//! `libboost-dev`) into the benchmark, so the C++ original runs in the same
//! harness as the Rust contenders. Without the headers the contender
//! `boost-cpp` is left out, with a warning.

fn main() {
    println!("cargo:rerun-if-changed=cpp/boost_polygon.cpp");
    println!("cargo::rustc-check-cfg=cfg(has_boost_cpp)");
    let built = cc::Build::new()
        .cpp(true)
        .file("cpp/boost_polygon.cpp")
        .flag_if_supported("-std=c++17")
        .opt_level(2)
        .define("NDEBUG", None)
        .warnings(false)
        .try_compile("boost_polygon_bench");
    match built {
        Ok(()) => println!("cargo:rustc-cfg=has_boost_cpp"),
        Err(e) => println!("cargo:warning=boost-cpp contender left out (Boost headers missing?): {e}"),
    }
}
