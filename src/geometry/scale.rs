//! Normalisation of the input by an exact power of two.
//!
//! The predicates are exact as long as their intermediate products neither
//! overflow nor underflow. Those products are of coordinates and of their
//! differences, up to degree 4; what must fit is therefore the *span* of an
//! input: from its largest coordinate magnitude down to the smallest
//! nonzero magnitude or difference between coordinates (`Magnitudes`).
//!
//! - Coordinates up to `2^60` in magnitude whose span fits are used as they
//!   are; larger or tinier inputs are multiplied by a power of two (exact
//!   in binary floating point) to bring the largest magnitude near 1.
//! - Where that leaves the smallest one below `2^-240` (degree 4 would
//!   underflow), an input spanning at most `2^480` is put in the middle:
//!   its largest magnitude at `2^(span/2)`, its smallest at `2^(-span/2)`.
//!   Every product of degree 4 then lies within `f64`'s normal range. A
//!   segment `(0, -M)-(1, -M)` beside coordinates of `M = 1e170` is such an
//!   input: at unit scale its length would be `2^-565` and its square lost.
//! - Beyond a span of `2^480` no scale serves every product. The input is
//!   put where the products of its smallest magnitude with three ordinary
//!   ones stay normal and its far vertices finite, as far as both can be
//!   had (`tiny_input_target`; a zero moved by a few ulps beside ordinary
//!   coordinates is such an input). The construction then checks its
//!   result (`construct::exact_range`).
//!
//! Nothing is translated, because a translation rounds and would change the
//! answer to near-degenerate questions.

use super::point::Point;

/// Largest magnitude used without rescaling.
const UPPER: f64 = (1u64 << 60) as f64;
/// Smallest largest-magnitude used without rescaling.
const LOWER: f64 = 1.0 / UPPER;
/// Where an input with tiny magnitudes puts its largest one when no scale
/// also keeps its far vertices finite (`tiny_input_target`): `2^100`, with
/// room for degree-4 predicates (`2^400`) below overflow.
const TINY_INPUT_TARGET: i32 = 100;
/// How far (in bits) the smallest and the largest magnitude may lie from 1
/// with every product of degree 4 in the normal range of `f64` (`2^±1022`),
/// with a margin for sums of such products.
const PRODUCT_REACH: i32 = 240;
/// The largest span (in bits, `Magnitudes::span`) that a scale puts wholly
/// within `PRODUCT_REACH`: the range in which every sign is decided in
/// `f64` expansions without underflow or overflow.
pub(crate) const EXACT_SPAN: i32 = 2 * PRODUCT_REACH;
/// Below this span (in bits) of the coordinates' magnitudes, no difference
/// of two coordinates can reach `PRODUCT_REACH` below the largest one (a
/// nonzero difference is at least an ulp of the smaller nonzero coordinate,
/// 53 bits below it, or the coordinate itself when the other is 0), so the
/// differences need not be looked at.
const ORDINARY_SPAN: i32 = PRODUCT_REACH - 60;

/// A power-of-two scale factor and its inverse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scale {
    /// Input coordinates are multiplied by this to get internal ones.
    pub to_internal: f64,
    /// Internal coordinates are multiplied by this to get input ones.
    pub to_input: f64,
}

impl Scale {
    pub const IDENTITY: Scale = Scale { to_internal: 1.0, to_input: 1.0 };

    /// The scale for inputs with these coordinates (`for_magnitudes` of
    /// their largest magnitude and their smallest nonzero one).
    pub fn for_coordinates(values: impl IntoIterator<Item = f64>) -> Scale {
        let (max_abs, min_abs) = extreme_magnitudes(values);
        Scale::for_magnitudes(max_abs, min_abs)
    }

    /// The scale for an input of these points (`Magnitudes::of_points`).
    pub fn for_points<'a>(points: impl Iterator<Item = &'a Point> + Clone) -> Scale {
        let m = Magnitudes::of_points(points);
        Scale::for_magnitudes(m.max_abs, m.smallest)
    }

    /// The scale for inputs whose largest coordinate magnitude is `max_abs`
    /// and whose smallest nonzero magnitude or difference is `smallest`
    /// (see the module documentation).
    pub fn for_magnitudes(max_abs: f64, smallest: f64) -> Scale {
        if max_abs == 0.0 || !max_abs.is_finite() {
            return Scale::IDENTITY;
        }
        let scale = if (LOWER..=UPPER).contains(&max_abs) { Scale::IDENTITY } else { Scale::to_unit(max_abs) };
        if !(smallest > 0.0 && smallest.is_finite()) {
            return scale;
        }
        let span = span_of(max_abs, smallest);
        let top = exponent_of(max_abs * scale.to_internal);
        if top <= PRODUCT_REACH && top - span >= -PRODUCT_REACH {
            return scale;
        }
        let target = if span <= EXACT_SPAN { span / 2 } else { tiny_input_target(span) };
        let e = (exponent_of(max_abs) - target).clamp(-1022, 1022);
        Scale { to_internal: pow2(-e), to_input: pow2(e) }
    }

    /// The scale that brings `max_abs` into `[1, 2)` (the identity for zero
    /// or a value that is not finite): `2^-e` for `2^e <= max_abs < 2^(e+1)`,
    /// clamped so that both factors are normal numbers (subnormal inputs then
    /// land a little below 1).
    pub fn to_unit(max_abs: f64) -> Scale {
        if max_abs == 0.0 || !max_abs.is_finite() {
            return Scale::IDENTITY;
        }
        let e = exponent_of(max_abs.abs()).clamp(-1022, 1022);
        Scale { to_internal: pow2(-e), to_input: pow2(e) }
    }

    /// An internal point in input coordinates, each coordinate beyond the
    /// range of `f64` saturated at `±f64::MAX`, as the vertices beyond it
    /// are (a point of an edge or an offset that reaches there).
    pub fn point_to_input(&self, p: Point) -> Point {
        let saturated = |v: f64| (v * self.to_input).clamp(-f64::MAX, f64::MAX);
        Point::new(saturated(p.x), saturated(p.y))
    }

    pub fn is_identity(&self) -> bool {
        self.to_internal == 1.0
    }
}

/// The two magnitudes that bound an input's products: its largest
/// coordinate magnitude and the smallest nonzero magnitude or difference
/// between two coordinates on one axis (`∞` when there is none).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Magnitudes {
    pub max_abs: f64,
    pub smallest: f64,
}

impl Magnitudes {
    /// The magnitudes of an input of these points. The differences are
    /// looked at (a sort) only where the magnitudes alone leave room for
    /// them to matter (`ORDINARY_SPAN`).
    pub fn of_points<'a>(points: impl Iterator<Item = &'a Point> + Clone) -> Magnitudes {
        let (max_abs, min_abs) = extreme_magnitudes(points.clone().flat_map(|p| [p.x, p.y]));
        let ordinary = Magnitudes { max_abs, smallest: min_abs };
        if !(max_abs.is_finite() && min_abs.is_finite()) || ordinary.span() + 53 <= ORDINARY_SPAN {
            return ordinary;
        }
        let smallest_gap = |axis: fn(&Point) -> f64| {
            let mut values: Vec<f64> = points.clone().map(axis).collect();
            values.sort_unstable_by(f64::total_cmp);
            values.windows(2).map(|w| w[1] - w[0]).filter(|&d| d > 0.0).fold(f64::INFINITY, f64::min)
        };
        Magnitudes { max_abs, smallest: min_abs.min(smallest_gap(|p| p.x)).min(smallest_gap(|p| p.y)) }
    }

    /// How many bits lie between the two (0 when there is nothing to span).
    pub fn span(&self) -> i32 {
        if self.max_abs > 0.0 && self.max_abs.is_finite() && self.smallest > 0.0 && self.smallest.is_finite() {
            span_of(self.max_abs, self.smallest)
        } else {
            0
        }
    }
}

/// Where an input whose magnitudes span `2^span` puts its largest one, as
/// `2^target`. Two needs pull apart. The products of the tiniest
/// coordinate with three ordinary ones (degree-4 predicates) must stay out
/// of the subnormal range: `3 · target + (target − span) ≥ −1022`. The far
/// vertices of such an input must stay finite: a point `2^-span` of the
/// size off a segment's line has a circle with the segment's end of radius
/// about `2^span` sizes, so `target + span ≤ 1023`. Between the two bounds
/// (spans up to about 1,000: a coordinate of 1e-300 next to 16) the middle
/// is taken, with a margin of `2^8` either side; beyond them no scale serves
/// both, the products are kept (`TINY_INPUT_TARGET`), and a far vertex lies
/// beyond `f64` (`vertex_placement` stores it as such, and `oracle` decides
/// it from its sites in big floats).
fn tiny_input_target(span: i32) -> i32 {
    const MARGIN: i32 = 8;
    let lowest = (span - 1022 + 3).div_euclid(4) + MARGIN;
    let highest = 1023 - span - MARGIN;
    if lowest <= highest {
        (lowest + highest) / 2
    } else {
        TINY_INPUT_TARGET
    }
}

/// The largest magnitude of `values` and the smallest nonzero one (`∞`
/// when none is nonzero); a NaN is skipped. Comparisons, not `f64::max`,
/// whose NaN checks slowed the fold: about 5 ms for a million points.
fn extreme_magnitudes(values: impl IntoIterator<Item = f64>) -> (f64, f64) {
    values.into_iter().fold((0.0f64, f64::INFINITY), |(max, min), v| {
        let v = v.abs();
        let positive = if v > 0.0 { v } else { f64::INFINITY };
        (if v > max { v } else { max }, if positive < min { positive } else { min })
    })
}

/// The span in bits from `smallest` up to `max_abs` (both positive).
pub fn span_of(max_abs: f64, smallest: f64) -> i32 {
    exponent_of(max_abs) - exponent_of(smallest)
}

fn exponent_of(x: f64) -> i32 {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // subnormal: scale up first
        exponent_of(x * pow2(64)) - 64
    } else {
        biased - 1023
    }
}

/// 2^e for e in the normal range, built from bits.
fn pow2(e: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&e));
    f64::from_bits(((e + 1023) as u64) << 52)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extreme_magnitudes_are_those_of_the_plain_fold() {
        // the fold of `f64::max` and `f64::min` it replaced, as the reference
        let reference = |values: &[f64]| {
            values.iter().fold((0.0f64, f64::INFINITY), |(max, min), &v| {
                let v = v.abs();
                (max.max(v), if v > 0.0 { min.min(v) } else { min })
            })
        };
        let cases: [&[f64]; 6] = [
            &[],
            &[0.0, -0.0, 0.0, 0.0],
            &[3.0, -7.5, 1e-300, 0.0, -5e-324, 2.0],
            &[f64::NAN, 1.0, -2.0, f64::NAN],
            &[f64::INFINITY, 1.0, 0.5, f64::NEG_INFINITY],
            &[-1e300, 1e-300, 4.0, -0.25, 1e300, 3.0, 0.0, 1e-310],
        ];
        for coordinates in cases {
            let (a, b) = extreme_magnitudes(coordinates.iter().copied());
            let (c, d) = reference(coordinates);
            assert_eq!((a.to_bits(), b.to_bits()), (c.to_bits(), d.to_bits()), "{coordinates:?}");
        }
    }

    #[test]
    fn ordinary_inputs_are_not_scaled() {
        assert!(Scale::for_coordinates([1e9, -3.0]).is_identity());
        assert!(Scale::for_coordinates([1e-9]).is_identity());
        assert!(Scale::for_coordinates([0.0, -0.0]).is_identity());
    }

    #[test]
    fn inputs_with_coordinates_near_the_subnormal_range_are_scaled_up() {
        let tiny = 5e-324;
        let s = Scale::for_magnitudes(20.0, tiny);
        assert_eq!(s.to_internal, pow2(96));
        assert!(tiny * s.to_internal >= f64::MIN_POSITIVE);
        assert_eq!(s.to_internal * s.to_input, 1.0);
        // not when the smallest magnitude is ordinary
        assert!(Scale::for_magnitudes(20.0, 1e-30).is_identity());
    }

    #[test]
    fn a_tiny_coordinate_within_reach_of_the_far_vertices_is_barely_scaled() {
        // 1e-300 next to 16: scaled up to 2^100 the far vertex of a point
        // that far off a segment's line (a radius of 16^2/1e-300 sizes)
        // would overflow; the middle of the two bounds keeps it finite
        let s = Scale::for_magnitudes(16.0, 1e-300);
        let target = exponent_of(16.0 * s.to_internal);
        assert!((1..=20).contains(&target), "{target}");
        assert!(1e-300 * s.to_internal * (16.0 * s.to_internal).powi(3) >= f64::MIN_POSITIVE);
        assert!((16.0 * s.to_internal).powi(2) / (1e-300 * s.to_internal) < f64::MAX / 1e3);
    }

    #[test]
    fn huge_and_tiny_inputs_are_scaled_by_powers_of_two() {
        for &m in &[1e300, 3e-300, 5e-320, f64::MAX] {
            let s = Scale::for_coordinates([m, -m / 2.0]);
            let v = m * s.to_internal;
            assert!((LOWER..4.0).contains(&v), "{m} -> {v}");
            assert_eq!(s.to_internal * s.to_input, 1.0);
        }
    }
}
