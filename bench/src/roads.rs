//! The splitting benchmarks' crossing input: random "roads", each crossing
//! a few others (see `bin/split.rs`).

use segvoronoi_testgen::Rng;

/// A segment as the library takes it.
pub type Segment = [[f64; 2]; 2];

/// `n` random segments of length `c / sqrt(n)` from uniform points of the
/// unit square in uniform directions.
pub fn roads(n: usize, c: f64, seed: u64) -> Vec<Segment> {
    let mut rng = Rng(seed);
    let length = c / (n as f64).sqrt();
    (0..n)
        .map(|_| {
            let (x, y) = (rng.unit(), rng.unit());
            let a = rng.unit() * std::f64::consts::TAU;
            [[x, y], [x + length * a.cos(), y + length * a.sin()]]
        })
        .collect()
}
