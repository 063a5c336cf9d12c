//! A build that cannot have its memory is refused with `OutOfMemory`, not
//! aborted (issue 28: "no abort on memory"). The library's collections
//! abort the process when an allocation fails, so the build asks for its
//! estimated peak first (`construct/headroom.rs`). Checked in a child
//! process of this test binary run under `ulimit -v` (the address-space
//! limit that makes allocations fail rather than the kernel kill the
//! process): a build that fits still succeeds, one that cannot fit returns
//! the error, and the child exits normally.

use segvoronoi::{Builder, ErrorKind};
use std::process::Command;

/// Set in the child's environment: run the builds under the limit.
const CHILD: &str = "SEGVORONOI_MEMORY_LIMIT_CHILD";

/// The child's address-space limit: room for the test binary, its threads
/// and a 10k-point build, far from the 3M-point build's estimated 768 MiB.
const LIMIT_KIB: u64 = 640 * 1024;

fn grid(n: usize) -> Vec<[f64; 2]> {
    let side = (n as f64).sqrt().ceil() as usize;
    (0..n).map(|k| [(k % side) as f64 + 0.25 * ((k * 7) % 3) as f64, (k / side) as f64]).collect()
}

#[test]
fn a_build_beyond_the_memory_limit_is_refused_not_aborted() {
    if std::env::var_os(CHILD).is_some() {
        return under_the_limit();
    }
    let exe = std::env::current_exe().expect("the test binary");
    let output = Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {LIMIT_KIB} && exec \"$0\" --exact a_build_beyond_the_memory_limit_is_refused_not_aborted --nocapture --test-threads 1"))
        .arg(exe)
        .env(CHILD, "1")
        .output()
        .expect("the child runs");
    let (stdout, stderr) = (String::from_utf8_lossy(&output.stdout), String::from_utf8_lossy(&output.stderr));
    assert!(output.status.success(), "the child failed ({}):\n{stdout}\n{stderr}", output.status);
    assert!(stdout.contains("refused: out of memory: building 3000000 points"), "{stdout}\n{stderr}");
    assert!(stdout.contains("small build: ok"), "{stdout}\n{stderr}");
}

/// In the child, under the limit.
fn under_the_limit() {
    let mut small = Builder::new();
    small.add_points(grid(10_000)).expect("10k points");
    let d = small.build().expect("a 10k-point build fits");
    assert_eq!(d.point_site_count(), 10_000);
    println!("small build: ok");

    let mut large = Builder::new();
    large.add_points(grid(3_000_000)).expect("3M points (48 MB) fit");
    let e = large.build().expect_err("a 3M-point build does not fit in 640 MiB");
    assert_eq!(e.kind(), ErrorKind::OutOfMemory, "{e}");
    println!("refused: {e}");
    // the builder is intact: the same input still builds where memory allows
    assert_eq!(large.point_count(), 3_000_000);
}
