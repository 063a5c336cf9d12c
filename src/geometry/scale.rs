//! Normalisation of the input by an exact power of two.
//!
//! The predicates are exact as long as their intermediate products neither
//! overflow nor underflow. Coordinates up to `2^60` in magnitude are used as
//! they are; larger or tinier inputs are multiplied by a power of two (exact
//! in binary floating point) to bring the largest magnitude near 1. An
//! input that also has coordinates near the subnormal range (a zero moved
//! by a few ulps) is scaled up instead, its largest magnitude to about
//! `2^100`: a product of such a coordinate with an ordinary one would
//! otherwise underflow, and the predicates that sum such products would
//! lose the term that decides them. Where the magnitudes span less than
//! about `2^1000`, a smaller scale-up also keeps the far Voronoi vertices
//! such inputs have within `f64` (`tiny_input_target`). Nothing is translated, because a
//! translation rounds and would change the answer to near-degenerate
//! questions.

/// Largest magnitude used without rescaling.
const UPPER: f64 = (1u64 << 60) as f64;
/// Smallest largest-magnitude used without rescaling.
const LOWER: f64 = 1.0 / UPPER;
/// Below this, a nonzero magnitude is near the subnormal range (about
/// `2^-897`).
const TINY: f64 = 1e-270;
/// Where an input with tiny magnitudes puts its largest one when no scale
/// also keeps its far vertices finite (`tiny_input_target`): `2^100`, with
/// room for degree-4 predicates (`2^400`) below overflow.
const TINY_INPUT_TARGET: i32 = 100;

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
        let (max_abs, min_abs) = values.into_iter().fold((0.0f64, f64::INFINITY), |(max, min), v| {
            let v = v.abs();
            (max.max(v), if v > 0.0 { min.min(v) } else { min })
        });
        Scale::for_magnitudes(max_abs, min_abs)
    }

    /// The scale for inputs whose largest coordinate magnitude is
    /// `max_abs` and smallest nonzero one `min_abs` (see the module
    /// documentation).
    pub fn for_magnitudes(max_abs: f64, min_abs: f64) -> Scale {
        if max_abs == 0.0 || !max_abs.is_finite() {
            return Scale::IDENTITY;
        }
        let scale = if (LOWER..=UPPER).contains(&max_abs) { Scale::IDENTITY } else { Scale::to_unit(max_abs) };
        let tiny_left = min_abs > 0.0 && min_abs * scale.to_internal < TINY;
        if !tiny_left {
            return scale;
        }
        let target = tiny_input_target(exponent_of(max_abs) - exponent_of(min_abs));
        if max_abs * scale.to_internal < pow2(target) {
            let e = (exponent_of(max_abs) - target).clamp(-1022, 1022);
            return Scale { to_internal: pow2(-e), to_input: pow2(e) };
        }
        scale
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

    pub fn is_identity(&self) -> bool {
        self.to_internal == 1.0
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
