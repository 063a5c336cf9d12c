//! Compiles the C++ contenders into the benchmark, so they run in the same
//! harness as the Rust ones: Boost.Polygon's Voronoi builder (header-only,
//! Debian's `libboost-dev`), GEOS's buffer (`libgeos-dev`, linked to
//! `geos_c`) and Clipper's offset (`libpolyclipping-dev`, linked to
//! `polyclipping`), and CGAL's segment Delaunay graph (header-only, Debian's
//! `libcgal-dev`, linked to `gmp` and `mpfr`). A contender whose headers are
//! missing is left out, with a warning: `boost-cpp` and `cgal`, and `geos` /
//! `clipper` of the offsets benchmark.

fn compile(file: &str, lib: &str, cfg: &str, link: &[&str], what: &str) {
    println!("cargo:rerun-if-changed={file}");
    println!("cargo::rustc-check-cfg=cfg({cfg})");
    let mut build = cc::Build::new();
    if cfg == "has_cgal" {
        // CGAL's interval filter switches the rounding mode; GCC must not
        // fold floating-point expressions across that (CGAL's own setup
        // adds the same flag, as does c_tests/cgal.cmake).
        build.flag_if_supported("-frounding-math");
    }
    let built = build
        .cpp(true)
        .file(file)
        .flag_if_supported("-std=c++17")
        .opt_level(2)
        .define("NDEBUG", None)
        .warnings(false)
        .try_compile(lib);
    match built {
        Ok(()) => {
            for link in link {
                println!("cargo:rustc-link-lib={link}");
            }
            println!("cargo:rustc-cfg={cfg}");
        }
        Err(e) => println!("cargo:warning={what}: {e}"),
    }
}

/// CGAL's segment Delaunay graph with intersections for the split
/// benchmark (`bin/split`, cfg `has_cgal_split`; Debian's `libcgal-dev`,
/// header-only, with GMP and MPFR), compiled as c_tests/cgal.cmake compiles
/// the CGAL cross-check: -O2 and -frounding-math (CGAL's interval filter
/// switches the rounding mode).
fn compile_cgal_split() {
    let (file, cfg) = ("cpp/cgal_split.cpp", "has_cgal_split");
    println!("cargo:rerun-if-changed={file}");
    println!("cargo::rustc-check-cfg=cfg({cfg})");
    let built = cc::Build::new()
        .cpp(true)
        .file(file)
        .flag_if_supported("-std=c++17")
        .flag_if_supported("-frounding-math")
        .opt_level(2)
        .define("NDEBUG", None)
        .warnings(false)
        .try_compile("cgal_split_bench");
    match built {
        Ok(()) => {
            println!("cargo:rustc-link-lib=mpfr");
            println!("cargo:rustc-link-lib=gmp");
            println!("cargo:rustc-cfg={cfg}");
        }
        Err(e) => println!("cargo:warning=cgal contender of bin/split left out (libcgal-dev missing?): {e}"),
    }
}

fn main() {
    compile_cgal_split();
    compile(
        "cpp/boost_polygon.cpp",
        "boost_polygon_bench",
        "has_boost_cpp",
        &[],
        "boost-cpp contender left out (Boost headers missing?)",
    );
    compile(
        "cpp/geos_buffer.cpp",
        "geos_buffer_bench",
        "has_geos",
        &["geos_c"],
        "geos contender left out (libgeos-dev missing?)",
    );
    compile(
        "cpp/clipper_offset.cpp",
        "clipper_offset_bench",
        "has_clipper",
        &["polyclipping"],
        "clipper contender left out (libpolyclipping-dev missing?)",
    );
    compile(
        "cpp/cgal_sdg.cpp",
        "cgal_sdg_bench",
        "has_cgal",
        &["mpfr", "gmp"],
        "cgal contender left out (libcgal-dev, libgmp-dev or libmpfr-dev missing?)",
    );
}
