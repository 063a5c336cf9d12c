//! Point families of the cross-check.

use crate::{power_of_two, shuffle, Point, Rng};

/// Uniform in `[offset, offset + size)^2`.
pub fn scaled_uniform(n: usize, rng: &mut Rng, offset: f64, size: f64) -> Vec<Point> {
    (0..n).map(|_| [offset + size * rng.unit(), offset + size * rng.unit()]).collect()
}

/// Gaussian clusters of different spreads around random centres.
pub fn clustered(n: usize, rng: &mut Rng) -> Vec<Point> {
    let cluster_count = (n / 500).max(1);
    let mut centres = Vec::with_capacity(cluster_count);
    let mut spreads = Vec::with_capacity(cluster_count);
    for _ in 0..cluster_count {
        centres.push([0.1 + 0.8 * rng.unit(), 0.1 + 0.8 * rng.unit()]);
        spreads.push(0.001 + 0.02 * rng.unit());
    }
    (0..n)
        .map(|_| {
            let c = rng.below(cluster_count);
            let x = centres[c][0] + spreads[c] * rng.normal();
            [x, centres[c][1] + spreads[c] * rng.normal()]
        })
        .collect()
}

/// The integer grid side x side with side = floor(sqrt(n)), shuffled: every
/// unit square is cocircular.
pub fn lattice(n: usize, rng: &mut Rng) -> Vec<Point> {
    let mut side = (n as f64).sqrt() as usize;
    while (side + 1) * (side + 1) <= n {
        side += 1;
    }
    let mut points = Vec::with_capacity(side * side);
    for i in 0..side {
        for j in 0..side {
            points.push([i as f64, j as f64]);
        }
    }
    shuffle(&mut points, rng);
    points
}

/// Every integer point of x^2 + y^2 = R^2 for R = 5*13*17*29*37*41: R^2 is
/// a product of six squared primes of the form 4k + 1, so it has 4 * 3^6 =
/// 2916 representations, all exactly cocircular (and R^2 < 2^53, so exact
/// doubles). Shuffled; the first n are kept.
pub fn circle(n: usize, rng: &mut Rng) -> Vec<Point> {
    let radius: i64 = 5 * 13 * 17 * 29 * 37 * 41;
    let r2 = radius * radius;
    let mut points = Vec::new();
    for x in 0..=radius {
        let rest = r2 - x * x;
        let mut y = (rest as f64).sqrt() as i64;
        while y * y > rest {
            y -= 1;
        }
        while (y + 1) * (y + 1) <= rest {
            y += 1;
        }
        if y * y != rest {
            continue;
        }
        // (x, y) with x >= 0, y >= 0 and its mirror images, each once.
        for sx in [1i64, -1] {
            for sy in [1i64, -1] {
                if (sx < 0 && x == 0) || (sy < 0 && y == 0) {
                    continue;
                }
                points.push([(sx * x) as f64, (sy * y) as f64]);
            }
        }
    }
    shuffle(&mut points, rng);
    points.truncate(n);
    points
}

/// Points (i, 2i + 1) on one line, about a tenth of them repeated, shuffled.
pub fn collinear(n: usize, rng: &mut Rng) -> Vec<Point> {
    let repeats = n / 10;
    let distinct = n - repeats;
    let mut points: Vec<Point> = (0..distinct).map(|i| [i as f64, 2.0 * i as f64 + 1.0]).collect();
    if distinct > 0 {
        for _ in 0..repeats {
            points.push(points[rng.below(distinct)]);
        }
    }
    shuffle(&mut points, rng);
    points
}

/// The lattice scaled by 2^-600 (exact): Voronoi edges about 1e-181 long,
/// whose squared lengths underflow. Exactly as degenerate as the lattice.
pub fn tiny_lattice(n: usize, rng: &mut Rng) -> Vec<Point> {
    let scale = power_of_two(-600);
    lattice(n, rng).into_iter().map(|[x, y]| [x * scale, y * scale]).collect()
}

/// Coordinates drawn from a few values, some a hair apart (1e-20, 3e-17
/// next to 0 and 1): many repeats, collinear and cocircular points, and
/// near-collinear triples whose Voronoi vertices are hard to place.
pub fn snapped(n: usize, rng: &mut Rng) -> Vec<Point> {
    const VALUES: [f64; 8] = [0.0, 1.0, -1.0, 1e-20, -1e-20, 2.0, 0.5, -3e-17];
    (0..n).map(|_| [VALUES[rng.below(VALUES.len())], VALUES[rng.below(VALUES.len())]]).collect()
}
