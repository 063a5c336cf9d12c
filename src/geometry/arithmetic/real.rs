//! The arithmetics the vertex solvers and the oracle's Newton iteration
//! are written in, behind one trait: `f64` (the fast path), double-double
//! (about 106 bits, no allocation) and big floats of any precision. Code
//! written once against [`Real`] runs in each; the `f64` instance is the
//! plain `f64` expression, operation for operation.

use super::bigfloat::BigFloat;
use super::double_double::DoubleDouble;

/// An arithmetic the solvers and the oracle's equations are written in.
pub(crate) trait Real: Clone {
    fn add(&self, o: &Self) -> Self;
    fn sub(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
    fn div(&self, o: &Self) -> Self;
    fn sqrt(&self) -> Self;
    fn neg(&self) -> Self;
    fn abs(&self) -> Self;
    fn signum(&self) -> i32;
    fn to_f64(&self) -> f64;
    /// `1 / self` (the solvers scale by a reciprocal, as their `f64`
    /// arithmetic always did).
    fn recip(&self) -> Self;
    /// `√(x² + y²)`.
    fn hypot(x: &Self, y: &Self) -> Self {
        x.mul(x).add(&y.mul(y)).sqrt()
    }
}

impl Real for f64 {
    fn add(&self, o: &f64) -> f64 {
        self + o
    }
    fn sub(&self, o: &f64) -> f64 {
        self - o
    }
    fn mul(&self, o: &f64) -> f64 {
        self * o
    }
    fn div(&self, o: &f64) -> f64 {
        self / o
    }
    fn sqrt(&self) -> f64 {
        f64::sqrt(*self)
    }
    fn neg(&self) -> f64 {
        -self
    }
    fn abs(&self) -> f64 {
        f64::abs(*self)
    }
    fn signum(&self) -> i32 {
        if *self > 0.0 {
            1
        } else if *self < 0.0 {
            -1
        } else {
            0
        }
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn recip(&self) -> f64 {
        1.0 / self
    }
    fn hypot(x: &f64, y: &f64) -> f64 {
        norm(*x, *y)
    }
}

impl Real for BigFloat {
    fn add(&self, o: &BigFloat) -> BigFloat {
        self + o
    }
    fn sub(&self, o: &BigFloat) -> BigFloat {
        self - o
    }
    fn mul(&self, o: &BigFloat) -> BigFloat {
        self * o
    }
    fn div(&self, o: &BigFloat) -> BigFloat {
        BigFloat::div(self, o)
    }
    fn sqrt(&self) -> BigFloat {
        BigFloat::sqrt(self)
    }
    fn neg(&self) -> BigFloat {
        -self
    }
    fn abs(&self) -> BigFloat {
        BigFloat::abs(self)
    }
    fn signum(&self) -> i32 {
        BigFloat::signum(self)
    }
    fn to_f64(&self) -> f64 {
        BigFloat::to_f64(self)
    }
    fn recip(&self) -> BigFloat {
        BigFloat::from_f64(1.0, self.precision()).div(self)
    }
}

impl Real for DoubleDouble {
    fn add(&self, o: &DoubleDouble) -> DoubleDouble {
        DoubleDouble::add(*self, *o)
    }
    fn sub(&self, o: &DoubleDouble) -> DoubleDouble {
        DoubleDouble::sub(*self, *o)
    }
    fn mul(&self, o: &DoubleDouble) -> DoubleDouble {
        DoubleDouble::mul(*self, *o)
    }
    fn div(&self, o: &DoubleDouble) -> DoubleDouble {
        DoubleDouble::div(*self, *o)
    }
    fn sqrt(&self) -> DoubleDouble {
        DoubleDouble::sqrt(*self)
    }
    fn neg(&self) -> DoubleDouble {
        DoubleDouble::neg(*self)
    }
    fn abs(&self) -> DoubleDouble {
        DoubleDouble::abs(*self)
    }
    fn signum(&self) -> i32 {
        DoubleDouble::signum(*self)
    }
    fn to_f64(&self) -> f64 {
        DoubleDouble::to_f64(*self)
    }
    fn recip(&self) -> DoubleDouble {
        DoubleDouble::from_f64(1.0).div(*self)
    }
}

/// `sqrt(dx² + dy²)` without overflow or underflow in between: the plain
/// formula (within an ulp or two of `hypot`, and several times faster) while
/// the sum of squares is finite and far from the subnormal range, so that a
/// square lost to underflow would not matter; `hypot` otherwise.
#[inline]
pub(crate) fn norm(dx: f64, dy: f64) -> f64 {
    /// Below this a lost square could matter; about 2^-897.
    const SMALLEST_SAFE: f64 = 1e-270;
    let sum = dx * dx + dy * dy;
    if (SMALLEST_SAFE..=f64::MAX).contains(&sum) {
        sum.sqrt()
    } else {
        dx.hypot(dy)
    }
}

/// A power of two near `1 / x` (for `x > 0`; subnormal `x` count as
/// `2^-1023`), within `2^±1000`: numbers of `x`'s size times it are about
/// 1, so that their products neither underflow nor overflow.
#[inline]
pub(crate) fn unit_near_inverse(x: f64) -> f64 {
    let exponent = ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    power_of_two((-exponent).clamp(-1000, 1000))
}

/// `2f64.powi(e)` for a normal result (`e` from -1022 to 1023), the same
/// value from the bits rather than by repeated squaring (`powi` is a loop
/// in a library call, on the arcs' hot paths; and no `powi` in any
/// branch: the compiler hoists the call out of it and pays it every
/// time). Beyond, where no caller goes: infinity above, zero below.
#[inline]
pub(crate) fn power_of_two(e: i32) -> f64 {
    if (-1022..=1023).contains(&e) {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else if e > 0 {
        f64::INFINITY
    } else {
        0.0
    }
}

/// `x.log2().round()`, the same value, without the logarithm where the
/// bits decide it: for a positive normal `x = m · 2^k` (`1 ≤ m < 2`) it is
/// `k`, or `k + 1` when `m > √2`. Only a mantissa within 1e-9 of `√2`
/// (where `log2` lands within its own rounding of a half, and `round`
/// goes by that rounding) and the other numbers (zero, subnormal,
/// negative, not finite) ask `log2` itself.
#[inline]
pub(crate) fn rounded_log2(x: f64) -> f64 {
    if x > 0.0 && x.is_normal() {
        let bits = x.to_bits();
        let k = (bits >> 52) as i32 - 1023;
        let m = f64::from_bits((bits & ((1u64 << 52) - 1)) | (1023u64 << 52));
        if (m - std::f64::consts::SQRT_2).abs() > 1e-9 {
            return f64::from(k + i32::from(m > std::f64::consts::SQRT_2));
        }
    }
    x.log2().round()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    #[test]
    fn rounded_log2_is_log2_rounded() {
        let mut rng = SplitMix64(7);
        let sqrt2 = std::f64::consts::SQRT_2;
        let special = [0.0, -0.0, -1.0, f64::MIN_POSITIVE, 1e-310, f64::MAX, f64::INFINITY, f64::NAN, 1.0, 2.0, 0.5, 3.0];
        // random bit patterns (every exponent), and mantissas on both
        // sides of √2 and at its neighbours
        let random = (0..200_000).map(|_| f64::from_bits(rng.next_u64()));
        let near = (-2000i64..2000).flat_map(|k| {
            let m = f64::from_bits((sqrt2.to_bits() as i64 + k) as u64);
            [-1000, -3, -1, 0, 1, 5, 1000].map(move |e| m * 2f64.powi(e))
        });
        let boundary = (-40i32..40).flat_map(|k| [sqrt2 * (1.0 + k as f64 * 2.5e-11), 2.0 - k.abs() as f64 * f64::EPSILON]);
        for x in special.into_iter().chain(random).chain(near).chain(boundary) {
            let (got, want) = (rounded_log2(x), x.log2().round());
            assert!(got == want || got.is_nan() && want.is_nan(), "{x:e}: {got} against {want}");
        }
    }

    #[test]
    fn power_of_two_is_powi() {
        for e in -1022..=1023 {
            assert_eq!(power_of_two(e).to_bits(), 2f64.powi(e).to_bits(), "2^{e}");
        }
        for e in [1024, 5000, i32::MAX] {
            assert_eq!(power_of_two(e), f64::INFINITY);
        }
        for e in [-1023, -1100, -5000, i32::MIN] {
            assert_eq!(power_of_two(e), 0.0);
        }
    }
}
