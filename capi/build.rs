//! Gives the shared library an ELF SONAME, so programs linked against the
//! installed `libsegvoronoi.so` record the ABI version they need and keep
//! working across compatible updates. The rule (shared with
//! `cmake/SegvoronoiCargo.cmake`): the SONAME carries the major version, or
//! `0.MINOR` while the major version is 0, because before 1.0 every minor
//! release may break the ABI.

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let target_os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if target_os == "linux" || target_os == "freebsd" || target_os == "android" {
        let major = std::env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_default();
        let minor = std::env::var("CARGO_PKG_VERSION_MINOR").unwrap_or_default();
        let abi = if major == "0" { format!("0.{minor}") } else { major };
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libsegvoronoi.so.{abi}");
    }
}
