//! Exact sums of products of doubles, for the predicates the `robust`
//! crate does not cover (comparing two distances, the turn between two
//! directions). Shewchuk's expansion
//! arithmetic: a number is kept as a sum of non-overlapping doubles, in
//! increasing magnitude, whose sign is the sign of its largest component.
//! Exact as long as no product underflows (the same condition as `robust`).

/// `a + b` as `(sum, error)` with `sum + error == a + b` exactly.
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    (s, (a - av) + (b - bv))
}

/// `a * b` as `(product, error)` with `product + error == a * b` exactly.
#[inline]
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// A number held exactly as a sum of doubles.
#[derive(Clone, Default)]
pub(crate) struct Expansion {
    components: Vec<f64>,
}

impl Expansion {
    /// Adds `b` exactly (Shewchuk's GROW-EXPANSION with zero elimination).
    pub(crate) fn add(&mut self, mut b: f64) {
        let mut out = 0;
        for i in 0..self.components.len() {
            let (s, e) = two_sum(b, self.components[i]);
            b = s;
            if e != 0.0 {
                self.components[out] = e;
                out += 1;
            }
        }
        self.components.truncate(out);
        if b != 0.0 {
            self.components.push(b);
        }
    }

    /// Adds `x * y` exactly.
    pub(crate) fn add_product(&mut self, x: f64, y: f64) {
        let (p, e) = two_product(x, y);
        self.add(e);
        self.add(p);
    }

    /// Adds `(x - y)^2` exactly.
    pub(crate) fn add_squared_difference(&mut self, x: f64, y: f64) {
        let (h, l) = two_sum(x, -y);
        self.add_product(h, h);
        self.add_product(2.0 * h, l);
        self.add_product(l, l);
    }

    /// Adds `(x.0 - x.1) * (y.0 - y.1)` exactly.
    pub(crate) fn add_product_of_differences(&mut self, x: (f64, f64), y: (f64, f64)) {
        let (xh, xl) = two_sum(x.0, -x.1);
        let (yh, yl) = two_sum(y.0, -y.1);
        self.add_product(xh, yh);
        self.add_product(xh, yl);
        self.add_product(xl, yh);
        self.add_product(xl, yl);
    }

    /// -1, 0 or 1.
    pub(crate) fn sign(&self) -> i8 {
        match self.components.last() {
            Some(&c) if c > 0.0 => 1,
            Some(&c) if c < 0.0 => -1,
            _ => 0,
        }
    }

    /// Adds `other · (x.0 − x.1)` exactly.
    pub(crate) fn add_product_with_difference(&mut self, other: &Expansion, x: (f64, f64)) {
        let (h, l) = two_sum(x.0, -x.1);
        for &c in &other.components {
            self.add_product(c, h);
            self.add_product(c, l);
        }
    }

    /// Subtracts `other` exactly.
    pub(crate) fn subtract(&mut self, other: &Expansion) {
        for &c in &other.components {
            self.add(-c);
        }
    }

    /// The number rounded to a double, within an ulp or so: the components
    /// do not overlap, so summing from the smallest loses at most the last
    /// bits.
    pub(crate) fn approximate(&self) -> f64 {
        self.components.iter().sum()
    }

    /// Negates the number.
    pub(crate) fn negate(&mut self) {
        self.components.iter_mut().for_each(|c| *c = -*c);
    }

    /// `x` as an expansion.
    pub(crate) fn of(x: f64) -> Expansion {
        let mut e = Expansion::default();
        e.add(x);
        e
    }

    /// `x − y`, exactly.
    pub(crate) fn difference(x: f64, y: f64) -> Expansion {
        let (s, e) = two_sum(x, -y);
        let mut out = Expansion::of(e);
        out.add(s);
        out
    }

    /// `self + other`, exactly.
    pub(crate) fn plus(&self, other: &Expansion) -> Expansion {
        let (mut long, short) =
            if self.components.len() >= other.components.len() { (self.clone(), other) } else { (other.clone(), self) };
        for &c in &short.components {
            long.add(c);
        }
        long
    }

    /// `self − other`, exactly.
    pub(crate) fn minus(&self, other: &Expansion) -> Expansion {
        let mut out = self.clone();
        out.subtract(other);
        out
    }

    /// `self · other`, exactly (as long as no product underflows or
    /// overflows: see [`Expansion::is_finite`]).
    pub(crate) fn times(&self, other: &Expansion) -> Expansion {
        let mut out = Expansion { components: Vec::with_capacity(2 * self.components.len() * other.components.len()) };
        for &x in &self.components {
            for &y in &other.components {
                out.add_product(x, y);
            }
        }
        out
    }

    /// `−self`.
    pub(crate) fn negated(&self) -> Expansion {
        let mut out = self.clone();
        out.negate();
        out
    }

    /// Whether every component is finite: an overflow shows as an
    /// infinite or NaN component, and then [`Expansion::sign`] means
    /// nothing.
    pub(crate) fn is_finite(&self) -> bool {
        self.components.iter().all(|c| c.is_finite())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cancellation_is_exact() {
        let mut e = Expansion::default();
        e.add(1e100);
        e.add(1.0);
        e.add(-1e100);
        assert_eq!(e.sign(), 1);
        e.add(-1.0);
        assert_eq!(e.sign(), 0);
    }

    #[test]
    fn squared_difference_keeps_the_low_bits() {
        // (1 + 2^-52)^2 - 1 - 2^-51 = 2^-104: far below one ulp of 1.
        let x = 1.0 + f64::EPSILON;
        let mut e = Expansion::default();
        e.add_squared_difference(x, 0.0);
        e.add(-1.0);
        e.add(-2.0 * f64::EPSILON);
        assert_eq!(e.sign(), 1);
        e.add(-f64::EPSILON * f64::EPSILON);
        assert_eq!(e.sign(), 0);
        e.negate();
        assert_eq!(e.sign(), 0);
    }
}
