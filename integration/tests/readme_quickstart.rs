//! The README's Rust quick start and `examples/quickstart.rs` are the same
//! code: the example holds the README's block, its `use` lines at the top
//! and the rest as the start of `main`, between the markers
//! `// --- as in README.md ---` and `// --- beyond the README ---`. (The
//! README's blocks also run as doctests, so both compile and run.)

const README: &str = include_str!("../../README.md");
const EXAMPLE: &str = include_str!("../../examples/quickstart.rs");

/// The first ```rust block after the heading `## Rust quick start`,
/// without the lines rustdoc hides (`# ...`).
fn readme_block() -> Vec<&'static str> {
    let after = README.split_once("\n## Rust quick start\n").expect("README has a '## Rust quick start' section").1;
    let block = after.split_once("```rust\n").expect("a rust block in the quick start").1;
    let block = block.split_once("\n```").expect("the block ends").0;
    block.lines().filter(|l| !l.starts_with("# ")).collect()
}

#[test]
fn example_is_the_readme_quick_start() {
    let lines = readme_block();
    let (uses, body): (Vec<&str>, Vec<&str>) = lines.iter().partition(|l| l.starts_with("use "));
    let body: Vec<&str> = body.into_iter().skip_while(|l| l.is_empty()).collect();
    let mut expected = uses.join("\n");
    expected += "\n\nfn main() -> Result<(), segvoronoi::Error> {\n    // --- as in README.md ---\n";
    for line in body {
        if !line.is_empty() {
            expected += "    ";
            expected += line;
        }
        expected += "\n";
    }
    expected += "    // --- beyond the README ---\n";
    assert!(
        EXAMPLE.contains(&expected),
        "examples/quickstart.rs does not hold the README's Rust quick start; it should contain:\n{expected}"
    );
}
