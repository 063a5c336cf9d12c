//! The Rust quick start of README.md, runnable:
//! `cargo run --example quickstart`.
//!
//! The first half is the README's code as it stands there; the second half
//! shows the cells, the statistics and the invariant check that the README
//! mentions in words.

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
        match e.ends {
            [EdgeEnd::Vertex(a), EdgeEnd::Vertex(b)] => println!("edge {a}-{b} between sites {:?}", e.sites),
            _ => println!("ray or line between sites {:?}", e.sites),
        }
    }
    // --- beyond the README ---
    for cell in diagram.cells() {
        let site = cell.geometry();
        let neighbours: Vec<String> = cell.neighbors().map(|s| s.to_string()).collect();
        let kind = if cell.is_unbounded() { "unbounded" } else { "bounded" };
        println!("cell of site {} ({site:?}): {kind}, neighbours [{}]", cell.site(), neighbours.join(", "));
    }
    let stats = diagram.stats();
    println!("{} points, {} sites, {} vertices, {} edges", stats.input_points, stats.sites, stats.vertices, stats.edges);
    diagram.validate().expect("a diagram from the library is always valid");
    Ok(())
}
