//! The circle tangent to three segments' lines, asked about a fourth line,
//! decided exactly from the input's integers: the true zeros of
//! mirror-symmetric outlines (a chord and its mirror image touch one
//! circle) and of arcs cut into chords, which no refinement tells from
//! zero.
//!
//! Scaled by a power of two, every coordinate is an integer. Line `i`
//! through `aᵢ → bᵢ` has the integer normal `nᵢ = (−(bᵢ−aᵢ)ʸ, (bᵢ−aᵢ)ˣ)`,
//! offset `kᵢ = nᵢ·aᵢ` and length `Lᵢ = √|nᵢ|²`, and the circle `(c, r)` on
//! its side `σᵢ` satisfies `nᵢ·c − σᵢ Lᵢ r = kᵢ`: a linear system whose
//! determinant `D`, and the determinants of Cramer's rule, are sums of
//! integer multiples of `L₁, L₂, L₃` (one root a row), the one for `r` an
//! integer. The fourth line's question, `σ₄ (n₄·c − k₄) − L₄ r` (its
//! distance to the centre minus the radius, times `L₄`), times `D` is then
//! a sum of four such terms, whose sign `root_sums` decides exactly.

use num_bigint::BigInt;

use crate::geometry::arithmetic::bigfloat::dyadic;
use crate::geometry::arithmetic::root_sums::{sign_of_root_sum, Term};
use crate::geometry::point::Point;

/// The widest spread of binary exponents among the coordinates taken:
/// the integers then have up to about this many bits.
const MAX_SPREAD: i64 = 2200;

/// A line from `a` to `b`, the circle on side `side` (`±1`: left when
/// positive).
#[derive(Clone, Copy, Debug)]
pub(super) struct SidedLine {
    pub(super) a: Point,
    pub(super) b: Point,
    pub(super) side: f64,
}

/// The sign of `dist(c, line q) − r` at the circle `(c, r)` tangent to
/// the three lines on their sides, where the centre lies on side `q.side`
/// of the fourth line: −1 inside (the line cuts the circle), 0 tangent,
/// 1 outside. `None` where the coordinates are not all finite, spread too
/// far apart, or the three lines do not fix one circle.
pub(super) fn fourth_line_sign(lines: [SidedLine; 3], q: SidedLine) -> Option<i8> {
    let all = [lines[0], lines[1], lines[2], q];
    let coordinates: Vec<f64> = all.iter().flat_map(|l| [l.a.x, l.a.y, l.b.x, l.b.y]).collect();
    let exponents: Vec<i64> = coordinates.iter().filter_map(|&x| dyadic(x).map(|(_, e)| e)).collect();
    if coordinates.iter().any(|x| !x.is_finite()) {
        return None;
    }
    let low = exponents.iter().copied().min().unwrap_or(0);
    if exponents.iter().any(|&e| e - low > MAX_SPREAD) {
        return None;
    }
    let integer = |x: f64| -> BigInt {
        match dyadic(x) {
            Some((m, e)) => {
                let v = BigInt::from(m) << ((e - low) as usize);
                if x < 0.0 {
                    -v
                } else {
                    v
                }
            }
            None => BigInt::from(0),
        }
    };
    // normal, offset, squared length, side of each line
    let rows: Vec<(BigInt, BigInt, BigInt, BigInt, i8)> = all
        .iter()
        .map(|l| {
            let (ax, ay, bx, by) = (integer(l.a.x), integer(l.a.y), integer(l.b.x), integer(l.b.y));
            let (nx, ny) = (&ay - &by, &bx - &ax);
            let k = &nx * &ax + &ny * &ay;
            let length2 = &nx * &nx + &ny * &ny;
            (nx, ny, k, length2, if l.side > 0.0 { 1 } else { -1 })
        })
        .collect();
    let minor = |u: (&BigInt, &BigInt), v: (&BigInt, &BigInt)| u.0 * v.1 - u.1 * v.0;
    // the cofactors of the roots' column, for the two columns given
    let cofactors = |first: &dyn Fn(usize) -> BigInt, second: &dyn Fn(usize) -> BigInt| -> [BigInt; 3] {
        let pair = |i: usize| (first(i), second(i));
        let (p0, p1, p2) = (pair(0), pair(1), pair(2));
        [minor((&p1.0, &p1.1), (&p2.0, &p2.1)), -minor((&p0.0, &p0.1), (&p2.0, &p2.1)), minor((&p0.0, &p0.1), (&p1.0, &p1.1))]
    };
    let nx = |i: usize| rows[i].0.clone();
    let ny = |i: usize| rows[i].1.clone();
    let k = |i: usize| rows[i].2.clone();
    // the roots' column is −σᵢ Lᵢ
    let with_roots = |c: [BigInt; 3]| -> [BigInt; 3] {
        let mut i = 0;
        c.map(|x| {
            i += 1;
            -x * BigInt::from(rows[i - 1].4)
        })
    };
    let alpha = with_roots(cofactors(&nx, &ny)); // D = Σ αᵢ Lᵢ
    let beta = with_roots(cofactors(&k, &ny)); // D·cx
    let gamma = with_roots(cofactors(&nx, &k)); // D·cy
                                                // D·r: the determinant of [n | k], no roots
    let d_r = {
        let [c0, c1, c2] = cofactors(&nx, &ny);
        c0 * k(0) + c1 * k(1) + c2 * k(2)
    };
    let root = |i: usize, e: BigInt| -> Term { (e, rows[i].3.clone()) };
    let determinant: Vec<Term> = (0..3).map(|i| root(i, alpha[i].clone())).collect();
    let d_sign = sign_of_root_sum(&determinant)?;
    if d_sign == 0 {
        return None;
    }
    let (n4x, n4y, k4, _, s4) = &rows[3];
    let s4 = BigInt::from(*s4);
    let mut question: Vec<Term> = (0..3).map(|i| root(i, &s4 * (n4x * &beta[i] + n4y * &gamma[i] - k4 * &alpha[i]))).collect();
    question.push(root(3, -d_r));
    Some(sign_of_root_sum(&question)? * d_sign)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    fn line(a: (f64, f64), b: (f64, f64), side: f64) -> SidedLine {
        SidedLine { a: Point::new(a.0, a.1), b: Point::new(b.0, b.1), side }
    }

    /// The circle of three lines in `f64` (Cramer), and the fourth line's
    /// question there.
    fn float_value(lines: [SidedLine; 3], q: SidedLine) -> f64 {
        let row = |l: SidedLine| {
            let (nx, ny) = (l.a.y - l.b.y, l.b.x - l.a.x);
            let len = nx.hypot(ny);
            [nx, ny, -l.side * len, nx * l.a.x + ny * l.a.y]
        };
        let m = lines.map(row);
        let det = |c: [[f64; 3]; 3]| {
            c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) - c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0])
                + c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0])
        };
        let a = m.map(|r| [r[0], r[1], r[2]]);
        let d = det(a);
        let col = |j: usize| det(std::array::from_fn(|i| std::array::from_fn(|c| if c == j { m[i][3] } else { a[i][c] })));
        let (x, y, r) = (col(0) / d, col(1) / d, col(2) / d);
        let [nx, ny, _, k] = row(q);
        (q.side * (nx * x + ny * y - k)) / nx.hypot(ny) - r
    }

    /// An integer point on `n·p = k` (`n` with coprime entries).
    fn on_line(nx: i64, ny: i64, k: i64) -> (f64, f64) {
        // extended Euclid: u nx + v ny = 1
        let (mut r0, mut r1, mut s0, mut s1, mut t0, mut t1) = (nx, ny, 1i64, 0i64, 0i64, 1i64);
        while r1 != 0 {
            let q = r0 / r1;
            (r0, r1, s0, s1, t0, t1) = (r1, r0 - q * r1, s1, s0 - q * s1, t1, t0 - q * t1);
        }
        let g = r0; // ±1
        ((s0 * k / g) as f64, (t0 * k / g) as f64)
    }

    #[test]
    fn four_tangent_lines_of_a_circle() {
        // normals with integer lengths (Pythagorean), each line at the
        // distance R from an integer centre: every four of them touch the
        // circle; a line moved by one unit does not
        let normals = [(3, 4, 5), (4, -3, 5), (-5, 12, 13), (12, 5, 13), (-8, -15, 17), (0, 1, 1), (-1, 0, 1), (-3, -4, 5)];
        let mut rng = SplitMix64(13);
        for _ in 0..300 {
            let (cx, cy, radius) =
                ((rng.next_u64() % 200) as i64 - 100, (rng.next_u64() % 200) as i64 - 100, 1 + (rng.next_u64() % 50) as i64);
            let pick: Vec<(i64, i64, i64)> = (0..4).map(|_| normals[(rng.next_u64() % 8) as usize]).collect();
            if pick[..3].iter().any(|p| pick[..3].iter().filter(|q| *q == p).count() > 1) {
                continue;
            }
            // the circle on the normal's negative side: n·c < k
            let tangent = |(nx, ny, len): (i64, i64, i64), shift: i64| {
                let k = nx * cx + ny * cy + len * radius + shift;
                let a = on_line(nx, ny, k);
                // a → a + (ny, −nx): the normal (−(−nx), ny)... points left
                // of a → b is n' = (nx, ny) rotated: choose b so that the
                // left normal is −n (the centre's side is the left)
                let b = (a.0 - ny as f64, a.1 + nx as f64);
                line(a, b, 1.0)
            };
            let three = [tangent(pick[0], 0), tangent(pick[1], 0), tangent(pick[2], 0)];
            let parallel = |x: (i64, i64, i64), y: (i64, i64, i64)| x.0 * y.1 == x.1 * y.0;
            if parallel(pick[0], pick[1]) && parallel(pick[1], pick[2]) {
                continue;
            }
            assert_eq!(fourth_line_sign(three, tangent(pick[3], 0)), Some(0), "{pick:?} {cx} {cy} {radius}");
            // moved away from the centre: outside; toward it: inside
            assert_eq!(fourth_line_sign(three, tangent(pick[3], 1)), Some(1));
            assert_eq!(fourth_line_sign(three, tangent(pick[3], -1)), Some(-1));
        }
    }

    #[test]
    fn agrees_with_floating_point_where_that_is_clear() {
        let mut rng = SplitMix64(12);
        let mut told = 0;
        for _ in 0..3000 {
            let mut v = || ((rng.next_u64() % 2001) as f64 - 1000.0) / 16.0;
            let mut l = || {
                let (a, b) = ((v(), v()), (v(), v()));
                line(a, b, if v() > 0.0 { 1.0 } else { -1.0 })
            };
            let (l0, l1, l2, q) = (l(), l(), l(), l());
            let value = float_value([l0, l1, l2], q);
            if !value.is_finite() || value.abs() < 1e-6 {
                continue;
            }
            if let Some(s) = fourth_line_sign([l0, l1, l2], q) {
                assert_eq!(s, value.signum() as i8, "{l0:?} {l1:?} {l2:?} {q:?}");
                told += 1;
            }
        }
        assert!(told > 2000, "{told}");
    }
}
