//! SplitMix64 (Steele, Lea, Flood 2014), the one pseudo-random generator of
//! the project: the construction's insertion order, fault injection, the
//! CLI's demo, and every generated test input (`testgen`). Tiny, and the
//! same sequence on every platform. Not part of the stable API.

/// A SplitMix64 generator and its state.
#[doc(hidden)]
#[derive(Clone, Debug)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    /// The next 64 random bits.
    #[inline]
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`, 53 random bits (the most an `f64` holds).
    #[inline]
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}
