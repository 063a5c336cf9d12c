//! The committed C header is exactly what the pinned cbindgen generates from
//! the source, and it compiles alone as C99, C11 and C++17 with warnings as
//! errors. `SEGVORONOI_BLESS=1` rewrites the header instead of failing.

use std::path::Path;
use std::process::Command;

fn generate() -> String {
    let root = env!("CARGO_MANIFEST_DIR");
    let config = cbindgen::Config::from_file(Path::new(root).join("cbindgen.toml")).expect("cbindgen.toml");
    let mut out = Vec::new();
    cbindgen::Builder::new()
        .with_crate(root)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header")
        .write(&mut out);
    String::from_utf8(out).unwrap()
}

#[test]
fn header_is_up_to_date() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("include/segvoronoi.h");
    let generated = generate();
    if std::env::var_os("SEGVORONOI_BLESS").is_some() {
        std::fs::write(&path, &generated).unwrap();
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "include/segvoronoi.h is stale: run `SEGVORONOI_BLESS=1 cargo test -p segvoronoi-capi --test header` and commit it"
    );
}

#[test]
fn header_versions_match_cargo_toml() {
    let header = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("include/segvoronoi.h")).unwrap();
    let expect = [
        format!("#define SEGVORONOI_VERSION_MAJOR {}", env!("CARGO_PKG_VERSION_MAJOR")),
        format!("#define SEGVORONOI_VERSION_MINOR {}", env!("CARGO_PKG_VERSION_MINOR")),
        format!("#define SEGVORONOI_VERSION_PATCH {}", env!("CARGO_PKG_VERSION_PATCH")),
        format!("#define SEGVORONOI_VERSION_STRING \"{}\"", env!("CARGO_PKG_VERSION")),
    ];
    for line in expect {
        assert!(header.contains(&line), "header lacks `{line}`");
    }
    let v = unsafe { std::ffi::CStr::from_ptr(segvoronoi_capi::segvoronoi_version()) };
    assert_eq!(v.to_str().unwrap(), env!("CARGO_PKG_VERSION"));
    let part = |s: &str| s.parse::<u32>().unwrap();
    let number = part(env!("CARGO_PKG_VERSION_MAJOR")) * 10000
        + part(env!("CARGO_PKG_VERSION_MINOR")) * 100
        + part(env!("CARGO_PKG_VERSION_PATCH"));
    assert_eq!(segvoronoi_capi::segvoronoi_version_number(), number);
    assert_eq!(segvoronoi_capi::SEGVORONOI_VERSION_NUMBER, number);
    assert!(header.contains("#define SEGVORONOI_VERSION_NUMBER ("), "header lacks SEGVORONOI_VERSION_NUMBER");
}

fn compiles(compiler: &str, args: &[&str], source: &str, ext: &str) {
    let dir = std::env::temp_dir().join(format!("segvoronoi-header-{}-{ext}-{}", std::process::id(), args.join("")));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join(format!("alone.{ext}"));
    std::fs::write(&file, source).unwrap();
    let include = Path::new(env!("CARGO_MANIFEST_DIR")).join("include");
    let out = Command::new(compiler)
        .args(args)
        .args(["-Wall", "-Wextra", "-Werror", "-pedantic", "-fsyntax-only", "-I"])
        .arg(&include)
        .arg(&file)
        .output()
        .unwrap_or_else(|e| panic!("cannot run {compiler}: {e}"));
    assert!(out.status.success(), "{compiler} {args:?}: {}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn header_compiles_alone_as_c_and_cpp() {
    let src = "#include \"segvoronoi.h\"\nint main(void) { return segvoronoi_version() == 0; }\n";
    compiles("cc", &["-std=c99"], src, "c");
    compiles("cc", &["-std=c11"], src, "c");
    if Command::new("c++").arg("--version").output().is_ok() {
        compiles("c++", &["-std=c++17"], &src.replace("(void)", "()"), "cpp");
    }
}
