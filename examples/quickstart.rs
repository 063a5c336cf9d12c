//! The Rust quick start of README.md, runnable:
//! `cargo run --example quickstart`.
//!
//! The first half is the README's code exactly (`tests/readme_quickstart.rs`
//! checks that it stays so); the second half shows the kind of each cell,
//! the statistics and the invariant check that the README mentions in words.

use segvoronoi::{Builder, EdgeEnd};

fn main() -> Result<(), segvoronoi::Error> {
    // --- as in README.md ---
    let mut builder = Builder::new();
    builder.add_points([[0.0, 0.0], [2.0, 0.0], [1.0, 2.0], [1.0, 0.7]])?;
    let diagram = builder.build()?;
    for v in diagram.vertices() {
        println!("vertex {} at ({}, {}), clearance {}", v.id, v.position.x, v.position.y, v.clearance);
    }
    for e in diagram.edges() {
        let [left, right] = e.sites;
        match e.ends {
            [EdgeEnd::Vertex(a), EdgeEnd::Vertex(b)] => println!("edge {a}-{b} between sites {left} and {right}"),
            _ => println!("ray or line between sites {left} and {right}"),
        }
    }
    for cell in diagram.cells() {
        let neighbors: Vec<String> = cell.neighbors().map(|s| s.to_string()).collect();
        println!("site {} borders {}", cell.site(), neighbors.join(", "));
    }
    assert_eq!(diagram.vertex_count(), 3);
    // --- beyond the README ---
    for cell in diagram.cells() {
        let site = cell.geometry();
        let kind = if cell.is_unbounded() { "unbounded" } else { "bounded" };
        println!("cell of site {} ({site:?}): {kind}", cell.site());
    }
    let stats = diagram.stats();
    println!("{} points, {} sites, {} vertices, {} edges", stats.input_points, stats.sites, stats.vertices, stats.edges);
    diagram.validate().expect("a diagram from the library is always valid");
    Ok(())
}
