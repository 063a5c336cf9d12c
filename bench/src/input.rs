//! The benchmark input: uniform random points, snapped to the integer grid.
//!
//! Every contender must see the identical point set, and boostvoronoi only
//! takes integers, so the points are snapped once here: each coordinate is
//! `floor(u * 1e6)` for a uniform `u` in [0, 1). segvoronoi and spade get the
//! same integers as `f64`. The generator is SplitMix64 written out, so the
//! input depends on nothing but the seed.

/// Side of the square the points are drawn from: [0, SIDE)^2.
pub const SIDE: f64 = 1e6;

/// The seed every run uses; a fixed seed makes the sizes nest (the first
/// 10k points of the 100k input are the 10k input).
pub const SEED: u64 = 0x5EED_0F_B0_0575;

/// SplitMix64 (Steele, Lea, Flood 2014): tiny, fast, and good enough to
/// spread points uniformly; not for anything cryptographic.
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1) with 53 random bits, the most an `f64` holds.
    pub fn next_unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// `n` snapped points, coordinates in `0..1_000_000`.
pub fn grid_points(n: usize, seed: u64) -> Vec<[i32; 2]> {
    snapped(n, seed).collect()
}

/// The same points as `f64`, for the contenders that take floating point.
/// Collected straight from the generator, so no integer copy inflates the
/// child's peak memory.
pub fn float_points(n: usize, seed: u64) -> Vec<[f64; 2]> {
    snapped(n, seed)
        .map(|[x, y]| [f64::from(x), f64::from(y)])
        .collect()
}

fn snapped(n: usize, seed: u64) -> impl Iterator<Item = [i32; 2]> {
    let mut rng = SplitMix64(seed);
    (0..n).map(move |_| {
        let x = (rng.next_unit() * SIDE).floor() as i32;
        let y = (rng.next_unit() * SIDE).floor() as i32;
        [x, y]
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deterministic_in_range_and_nested() {
        let a = grid_points(1000, SEED);
        assert_eq!(a, grid_points(1000, SEED));
        assert_eq!(&a[..100], &grid_points(100, SEED)[..]);
        assert!(a.iter().flatten().all(|&c| (0..1_000_000).contains(&c)));
        let f = float_points(1000, SEED);
        assert!(a.iter().zip(&f).all(|(i, f)| f64::from(i[0]) == f[0] && f64::from(i[1]) == f[1]));
    }
}
