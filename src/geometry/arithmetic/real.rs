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
    2f64.powi((-exponent).clamp(-1000, 1000))
}
