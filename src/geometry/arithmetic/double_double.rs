//! Double-double arithmetic: a value is the unevaluated sum `hi + lo` of
//! two doubles with `|lo| <= ulp(hi) / 2`, about 106 bits of precision, by
//! error-free transformations (Dekker, Knuth; the fused multiply-add gives
//! the exact product error). The fast first stage of the segment
//! predicates' refinement (`oracle`), before arbitrary precision.

/// A double-double number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DoubleDouble {
    hi: f64,
    lo: f64,
}

/// `a + b` as `(sum, error)`, exactly.
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    (s, (a - (s - bv)) + (b - bv))
}

/// `a + b` as `(sum, error)` when `|a| >= |b|`, exactly.
#[inline]
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a * b` as `(product, error)`, exactly.
#[inline]
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl DoubleDouble {
    /// `x` exactly.
    pub fn from_f64(x: f64) -> DoubleDouble {
        DoubleDouble { hi: x, lo: 0.0 }
    }

    /// The nearest double (the leading part).
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    fn normalised(hi: f64, lo: f64) -> DoubleDouble {
        let (hi, lo) = quick_two_sum(hi, lo);
        DoubleDouble { hi, lo }
    }

    pub fn add(self, o: DoubleDouble) -> DoubleDouble {
        let (s, e) = two_sum(self.hi, o.hi);
        let (t, f) = two_sum(self.lo, o.lo);
        let (s, e) = quick_two_sum(s, e + t);
        DoubleDouble::normalised(s, e + f)
    }

    pub fn neg(self) -> DoubleDouble {
        DoubleDouble { hi: -self.hi, lo: -self.lo }
    }

    pub fn sub(self, o: DoubleDouble) -> DoubleDouble {
        self.add(o.neg())
    }

    pub fn mul(self, o: DoubleDouble) -> DoubleDouble {
        let (p, e) = two_product(self.hi, o.hi);
        DoubleDouble::normalised(p, e + (self.hi * o.lo + self.lo * o.hi))
    }

    pub fn div(self, o: DoubleDouble) -> DoubleDouble {
        let q1 = self.hi / o.hi;
        let r = self.sub(o.mul(DoubleDouble::from_f64(q1)));
        let q2 = r.hi / o.hi;
        let r = r.sub(o.mul(DoubleDouble::from_f64(q2)));
        let q3 = r.hi / o.hi;
        DoubleDouble::normalised(q1, q2).add(DoubleDouble::from_f64(q3))
    }

    /// The square root of `|self|`: one Newton step from the double root.
    pub fn sqrt(self) -> DoubleDouble {
        let a = self.abs();
        if a.hi == 0.0 {
            return DoubleDouble::from_f64(0.0);
        }
        let x = a.hi.sqrt();
        let x = DoubleDouble::from_f64(x);
        let correction = a.sub(x.mul(x)).div(DoubleDouble::from_f64(2.0 * x.hi));
        x.add(correction)
    }

    pub fn abs(self) -> DoubleDouble {
        if self.hi < 0.0 || (self.hi == 0.0 && self.lo < 0.0) {
            self.neg()
        } else {
            self
        }
    }

    /// -1, 0 or 1.
    pub fn signum(self) -> i32 {
        let lead = if self.hi != 0.0 { self.hi } else { self.lo };
        if lead > 0.0 {
            1
        } else if lead < 0.0 {
            -1
        } else {
            0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dd(x: f64) -> DoubleDouble {
        DoubleDouble::from_f64(x)
    }

    #[test]
    fn keeps_what_a_double_loses() {
        let tiny = 2f64.powi(-80);
        let s = dd(1.0).add(dd(tiny)).sub(dd(1.0));
        assert_eq!(s.to_f64(), tiny);
    }

    #[test]
    fn square_root_and_quotient_have_about_106_bits() {
        let r = dd(2.0).sqrt();
        let err = r.mul(r).sub(dd(2.0)).to_f64().abs();
        assert!(err < 2f64.powi(-100), "{err:e}");
        let third = dd(1.0).div(dd(3.0));
        let err = third.mul(dd(3.0)).sub(dd(1.0)).to_f64().abs();
        assert!(err < 2f64.powi(-100), "{err:e}");
    }
}
