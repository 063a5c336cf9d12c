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
        super::point::norm(*x, *y)
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
