//! Binary floating point of any precision, for the exact stage of the
//! segment predicates (`oracle`): a value is `m · 2^e` with a big-integer
//! mantissa `m` kept to `bits` significant bits after each rounding
//! operation (truncation). Conversion from `f64` is exact; sums and
//! products of values that fit are exact until truncated to the precision;
//! quotients and square roots are truncated.
//!
//! There is no directed rounding and no interval: the caller bounds the
//! error itself (in `oracle`, from the precision and the last Newton step).

use std::ops::{Add, Mul, Neg, Sub};

use num_bigint::{BigInt, Sign};

/// `|x| = m · 2^e` with an odd integer `m > 0`; `None` for zero and
/// non-finite `x`.
pub(crate) fn dyadic(x: f64) -> Option<(u64, i64)> {
    if x == 0.0 || !x.is_finite() {
        return None;
    }
    let raw = x.to_bits();
    let biased = ((raw >> 52) & 0x7ff) as i64;
    let fraction = raw & ((1u64 << 52) - 1);
    let (m, e) = if biased == 0 { (fraction, -1074) } else { (fraction | (1u64 << 52), biased - 1075) };
    let shift = m.trailing_zeros();
    Some((m >> shift, e + shift as i64))
}

/// A binary floating-point number with a big-integer mantissa.
#[derive(Clone, Debug)]
pub(crate) struct BigFloat {
    mantissa: BigInt,
    exponent: i64,
    /// Significant bits kept by rounding operations.
    bits: u64,
}

impl BigFloat {
    /// `x` exactly (finite `x`), with `bits` of precision for later
    /// operations.
    pub fn from_f64(x: f64, bits: u64) -> BigFloat {
        let Some((m, e)) = dyadic(x) else {
            return BigFloat { mantissa: BigInt::from(0), exponent: 0, bits };
        };
        let m = BigInt::from(m);
        BigFloat { mantissa: if x < 0.0 { -m } else { m }, exponent: e, bits }
    }

    /// `m · 2^e`, truncated to `bits`.
    pub fn from_parts(m: &BigInt, e: i64, bits: u64) -> BigFloat {
        BigFloat { mantissa: m.clone(), exponent: e, bits }.rounded()
    }

    /// `2^e` exactly, with `bits` of precision for later operations (any
    /// exponent, also far outside `f64`'s range).
    pub fn pow2(e: i64, bits: u64) -> BigFloat {
        BigFloat { mantissa: BigInt::from(1), exponent: e, bits }
    }

    /// The value rounded to `f64`, saturated at `±f64::MAX` beyond its
    /// range.
    pub fn to_f64_saturated(&self) -> f64 {
        self.to_f64().clamp(-f64::MAX, f64::MAX)
    }

    /// The same value, kept to `bits` from now on (truncated if longer).
    pub fn with_precision(self, bits: u64) -> BigFloat {
        BigFloat { bits, ..self }.rounded()
    }

    /// The significant bits kept by rounding operations.
    pub fn precision(&self) -> u64 {
        self.bits
    }

    /// The sign: -1, 0 or 1.
    pub fn signum(&self) -> i32 {
        match self.mantissa.sign() {
            Sign::Minus => -1,
            Sign::NoSign => 0,
            Sign::Plus => 1,
        }
    }

    /// The nearest `f64`, roughly (the top 60 bits, then the exponent).
    pub fn to_f64(&self) -> f64 {
        let len = self.mantissa.bits();
        let drop = len.saturating_sub(60);
        let top = &self.mantissa >> drop;
        let top: i64 = top.try_into().unwrap_or(0);
        let e = self.exponent.saturating_add(drop as i64).clamp(-2200, 2200) as i32;
        // in two steps, so that a subnormal result does not underflow early
        top as f64 * 2f64.powi(e / 2) * 2f64.powi(e - e / 2)
    }

    /// The absolute value.
    pub fn abs(&self) -> BigFloat {
        BigFloat { mantissa: BigInt::from_biguint(Sign::Plus, self.mantissa.magnitude().clone()), ..self.clone() }
    }

    /// The binary exponent of the leading bit (`floor(log2 |x|)`), or
    /// `i64::MIN` for zero.
    pub fn magnitude_exponent(&self) -> i64 {
        if self.signum() == 0 {
            i64::MIN
        } else {
            self.exponent + self.mantissa.bits() as i64 - 1
        }
    }

    /// Truncated to the precision.
    fn rounded(mut self) -> BigFloat {
        let len = self.mantissa.bits();
        if len > self.bits {
            let drop = len - self.bits;
            // shifting a negative big integer rounds towards -inf; the
            // magnitude is what is truncated
            let sign = self.mantissa.sign();
            let magnitude = self.mantissa.magnitude() >> drop;
            self.mantissa = BigInt::from_biguint(sign, magnitude);
            self.exponent += drop as i64;
        }
        self
    }

    /// `self / other`, truncated; zero for a zero divisor (the callers
    /// treat the result as undecided then).
    pub fn div(&self, other: &BigFloat) -> BigFloat {
        let bits = self.bits.max(other.bits);
        if other.signum() == 0 {
            return BigFloat { mantissa: BigInt::from(0), exponent: 0, bits };
        }
        let shift = (bits + other.mantissa.bits() + 2).saturating_sub(self.mantissa.bits());
        let mantissa = (&self.mantissa << shift) / &other.mantissa;
        BigFloat { mantissa, exponent: self.exponent - other.exponent - shift as i64, bits }.rounded()
    }

    /// The square root of `|self|`, truncated.
    pub fn sqrt(&self) -> BigFloat {
        let mut shift = (2 * self.bits + 2).saturating_sub(self.mantissa.bits());
        if (self.exponent - shift as i64).rem_euclid(2) != 0 {
            shift += 1;
        }
        let m = self.mantissa.magnitude() << shift;
        let root = BigInt::from_biguint(Sign::Plus, m.sqrt());
        BigFloat { mantissa: root, exponent: (self.exponent - shift as i64) / 2, bits: self.bits }.rounded()
    }

    fn sum(&self, other: &BigFloat, negate_other: bool) -> BigFloat {
        let bits = self.bits.max(other.bits);
        let other_mantissa = if negate_other { -&other.mantissa } else { other.mantissa.clone() };
        if other.signum() == 0 {
            return BigFloat { bits, ..self.clone() }.rounded();
        }
        if self.signum() == 0 {
            return BigFloat { mantissa: other_mantissa, exponent: other.exponent, bits }.rounded();
        }
        // A term entirely below the other's precision only matters for the
        // truncation: keep it as a sticky last bit.
        let (hi, lo) = (self.magnitude_exponent(), other.magnitude_exponent());
        let limit = bits as i64 + 4;
        let (m1, e1, m2, e2) = (&self.mantissa, self.exponent, &other_mantissa, other.exponent);
        if hi - lo > limit {
            return self.with_sticky(m2.sign(), bits);
        }
        if lo - hi > limit {
            return BigFloat { mantissa: other_mantissa.clone(), exponent: e2, bits }.with_sticky(m1.sign(), bits);
        }
        let e = e1.min(e2);
        let mantissa = (m1 << (e1 - e) as u64) + (m2 << (e2 - e) as u64);
        BigFloat { mantissa, exponent: e, bits }.rounded()
    }

    /// `self` plus a tiny amount of sign `sign` (the far smaller term of a
    /// sum): one unit in the last place, so that the sign of a difference of
    /// nearly equal values still sees it.
    fn with_sticky(&self, sign: Sign, bits: u64) -> BigFloat {
        let widen = bits.saturating_sub(self.mantissa.bits());
        let mut mantissa = &self.mantissa << widen;
        match sign {
            Sign::Plus => mantissa += 1,
            Sign::Minus => mantissa -= 1,
            Sign::NoSign => {}
        }
        BigFloat { mantissa, exponent: self.exponent - widen as i64, bits }.rounded()
    }
}

impl Add for &BigFloat {
    type Output = BigFloat;
    fn add(self, other: &BigFloat) -> BigFloat {
        self.sum(other, false)
    }
}

impl Sub for &BigFloat {
    type Output = BigFloat;
    fn sub(self, other: &BigFloat) -> BigFloat {
        self.sum(other, true)
    }
}

impl Mul for &BigFloat {
    type Output = BigFloat;
    fn mul(self, other: &BigFloat) -> BigFloat {
        let bits = self.bits.max(other.bits);
        BigFloat { mantissa: &self.mantissa * &other.mantissa, exponent: self.exponent + other.exponent, bits }.rounded()
    }
}

impl Neg for &BigFloat {
    type Output = BigFloat;
    fn neg(self) -> BigFloat {
        BigFloat { mantissa: -&self.mantissa, ..self.clone() }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn big(x: f64) -> BigFloat {
        BigFloat::from_f64(x, 200)
    }

    #[test]
    fn conversions_are_exact() {
        for x in [1.0, -3.5, 1e-310, 5e-324, 1.7976931348623157e308, 0.1, -0.0] {
            assert_eq!(big(x).to_f64(), x, "{x}");
        }
    }

    #[test]
    fn arithmetic_agrees_with_f64_where_f64_is_exact() {
        assert_eq!((&big(1.5) + &big(2.25)).to_f64(), 3.75);
        assert_eq!((&big(1.5) - &big(2.25)).to_f64(), -0.75);
        assert_eq!((&big(1.5) * &big(-2.25)).to_f64(), -3.375);
        assert_eq!(big(1.0).div(&big(4.0)).to_f64(), 0.25);
        assert_eq!(big(2.25).sqrt().to_f64(), 1.5);
    }

    #[test]
    fn sums_keep_what_f64_loses() {
        // (1 + 2^-80) - 1 = 2^-80, lost in f64
        let tiny = 2f64.powi(-80);
        let s = &(&big(1.0) + &big(tiny)) - &big(1.0);
        assert_eq!(s.to_f64(), tiny);
        // a term far below the precision still tips the sign
        let far = &(&BigFloat::from_f64(1.0, 64) + &big(1e-300)) - &big(1.0);
        assert_eq!(far.signum(), 1);
    }

    #[test]
    fn square_root_and_quotient_are_precise() {
        let two = BigFloat::from_f64(2.0, 400);
        let r = two.sqrt();
        let back = &(&r * &r) - &two;
        assert!(back.magnitude_exponent() < -390, "{:?}", back.magnitude_exponent());
        let third = BigFloat::from_f64(1.0, 400).div(&BigFloat::from_f64(3.0, 400));
        let err = &(&third * &BigFloat::from_f64(3.0, 400)) - &BigFloat::from_f64(1.0, 400);
        assert!(err.magnitude_exponent() < -390);
    }
}
