//! The exact sign of a short sum of integer multiples of square roots of
//! integers, `Σ eᵢ √mᵢ`, by squaring: the sign of `A + B` where `A` and
//! `B` have opposite signs is `A`'s times the sign of `A² − B²`, a sum with
//! one square root fewer once the squares' rational parts are merged. Up to
//! four roots this ends in a comparison of integers after three squarings,
//! with no rounding anywhere: the true zeros of four lines tangent to one
//! circle (mirror-symmetric outlines) cost a few big-integer products,
//! where the tower of square roots (`radical_tower`) costs hundreds.

use num_bigint::{BigInt, Sign};

/// One term `e √m` (`m ≥ 0`).
pub(crate) type Term = (BigInt, BigInt);

/// The most terms [`sign_of_root_sum`] takes (after merging equal roots,
/// the rational part counting as one): each squaring of up to four terms
/// leaves fewer (two halves of two give a rational part and two roots),
/// which a fifth would not.
pub(crate) const MAX_TERMS: usize = 4;

/// The sign (−1, 0 or 1) of `Σ eᵢ √mᵢ`; `None` for a negative radicand or
/// more than [`MAX_TERMS`] distinct terms.
pub(crate) fn sign_of_root_sum(terms: &[Term]) -> Option<i8> {
    if terms.iter().any(|(_, m)| m.sign() == Sign::Minus) {
        return None;
    }
    let terms = merged(terms.to_vec());
    if terms.len() > MAX_TERMS {
        return None;
    }
    Some(sign_of(terms))
}

/// The sign of at most [`MAX_TERMS`] merged terms; each squaring leaves
/// fewer.
fn sign_of(terms: Vec<Term>) -> i8 {
    match terms.len() {
        0 => 0,
        1 => sign(&terms[0].0),
        n => {
            let (a, b) = terms.split_at(n / 2);
            let (sa, sb) = (sign_of(a.to_vec()), sign_of(b.to_vec()));
            if sa == 0 || sb == 0 || sa == sb {
                return if sa == 0 { sb } else { sa };
            }
            // opposite signs: |A| > |B| exactly when A² − B² > 0
            let mut difference = squared(a);
            difference.extend(squared(b).into_iter().map(|(e, m)| (-e, m)));
            sa * sign_of(merged(difference))
        }
    }
}

/// `(Σ eᵢ √mᵢ)²` as terms: `eᵢ² mᵢ` rational, `2 eᵢ eⱼ √(mᵢ mⱼ)`.
fn squared(terms: &[Term]) -> Vec<Term> {
    let mut out = Vec::with_capacity(terms.len() * (terms.len() + 1) / 2);
    for (i, (e, m)) in terms.iter().enumerate() {
        out.push((e * e * m, BigInt::from(1)));
        for (f, n) in &terms[i + 1..] {
            out.push((BigInt::from(2) * e * f, m * n));
        }
    }
    out
}

/// The terms with zero ones dropped, perfect-square radicands taken out
/// (so that `√(m n)` with `m = n` joins the rational part) and equal
/// radicands added.
fn merged(terms: Vec<Term>) -> Vec<Term> {
    let mut out: Vec<Term> = Vec::with_capacity(terms.len());
    for (e, m) in terms {
        if sign(&e) == 0 || sign(&m) == 0 {
            continue;
        }
        let root = m.sqrt();
        let (e, m) = if &root * &root == m { (e * root, BigInt::from(1)) } else { (e, m) };
        match out.iter_mut().find(|(_, n)| *n == m) {
            Some(term) => term.0 += e,
            None => out.push((e, m)),
        }
    }
    out.retain(|(e, _)| sign(e) != 0);
    out
}

fn sign(x: &BigInt) -> i8 {
    match x.sign() {
        Sign::Minus => -1,
        Sign::NoSign => 0,
        Sign::Plus => 1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    fn terms(t: &[(i64, i64)]) -> Vec<Term> {
        t.iter().map(|&(e, m)| (BigInt::from(e), BigInt::from(m))).collect()
    }

    #[test]
    fn exact_zeros_and_near_misses() {
        // √2 + √8 − √18 = 0; √2 + √3 − √(5 + 2√6) = 0 is beyond (a nested
        // root), so: 3√2 − √18 = 0 and √50 − 5√2 = 0 after merging
        assert_eq!(sign_of_root_sum(&terms(&[(1, 2), (1, 8), (-1, 18)])), Some(0));
        assert_eq!(sign_of_root_sum(&terms(&[(1, 50), (-5, 2)])), Some(0));
        // √2 + √3 against √10: 5 + 2√6 ≈ 9.899 < 10
        assert_eq!(sign_of_root_sum(&terms(&[(1, 2), (1, 3), (-1, 10)])), Some(-1));
        // 1,000,001² against 1,000,000² + 2,000,001 = the same: zero
        assert_eq!(sign_of_root_sum(&terms(&[(1_000_001, 1), (-1, 1_000_000_000_000 + 2_000_001)])), Some(0));
        // one more: below zero by 1 under the root, a difference of 5e-7
        assert_eq!(sign_of_root_sum(&terms(&[(1_000_001, 1), (-1, 1_000_000_000_000 + 2_000_000)])), Some(1));
        assert_eq!(sign_of_root_sum(&terms(&[(1, -1)])), None);
    }

    #[test]
    fn agrees_with_floating_point_where_that_is_clear() {
        let mut rng = SplitMix64(5);
        for _ in 0..2000 {
            let n = 1 + (rng.next_u64() % 4) as usize;
            let t: Vec<(i64, i64)> =
                (0..n).map(|_| ((rng.next_u64() % 2001) as i64 - 1000, (rng.next_u64() % 100_000) as i64)).collect();
            let value: f64 = t.iter().map(|&(e, m)| e as f64 * (m as f64).sqrt()).sum();
            let size: f64 = t.iter().map(|&(e, m)| (e as f64 * (m as f64).sqrt()).abs()).sum();
            if value.abs() > 1e-9 * size {
                assert_eq!(sign_of_root_sum(&terms(&t)), Some(value.signum() as i8), "{t:?}");
            }
        }
    }

    #[test]
    fn four_roots_that_cancel_in_pairs() {
        // a√m + b√n − a√m − b√n in any order: zero; and a(√m − √(m + 1))
        for (a, m, b, n) in [(3, 7, 5, 11), (12, 1_000_003, 7, 999_983), (1, 2, 1, 3)] {
            assert_eq!(sign_of_root_sum(&terms(&[(a, m), (b, n), (-a, m), (-b, n)])), Some(0));
            assert_eq!(sign_of_root_sum(&terms(&[(a, m), (b, n), (-a, m + 1), (-b, n + 1)])), Some(-1));
            assert_eq!(sign_of_root_sum(&terms(&[(a, m), (-b, n), (b, n), (-a, m + 1)])), Some(-1));
        }
    }
}
