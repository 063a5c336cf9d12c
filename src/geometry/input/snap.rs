//! The geometry of snap rounding (used by `construct::split` to make an
//! input that crosses itself into one that does not): a grid of square
//! *pixels* whose centres are exactly representable, the pixel of a point,
//! the exact test "does this closed segment meet this closed pixel", and an
//! accurate crossing point of two segments.
//!
//! # The pixel size
//! For coordinates of magnitude below 2^e the pixel side is δ = 2^(e − 46).
//! Centres are the multiples m·δ (|m| ≤ 2^46) and corners the odd multiples
//! of δ/2, so both are exact doubles: at magnitude 2^e an ulp is 2^(e − 52),
//! and δ/2 is 32 of them. A crossing point computed by [`crossing_point`] is
//! within 2^(e − 50) of the true one (see there), an eighth of δ, and the
//! pixel that holds the true one is then decided exactly
//! ([`PixelGrid::crossing_pixel`]).

use crate::geometry::arithmetic::expansion::Expansion;
use crate::geometry::point::Point;
use crate::geometry::predicates::exact_orientation;

/// A pixel by its integer centre coordinates: the centre is `m · size`.
pub(crate) type Pixel = [i64; 2];

/// The grid of pixels for one input.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PixelGrid {
    /// The pixel side δ, a power of two.
    size: f64,
    /// 1 / δ, also a power of two.
    inverse: f64,
}

/// log2 of (the power of two above the largest coordinate) / δ.
const PIXELS_PER_MAGNITUDE_LOG2: i32 = 46;

impl PixelGrid {
    /// The grid for coordinates of magnitude at most `max_abs` (finite).
    pub(crate) fn for_magnitude(max_abs: f64) -> PixelGrid {
        // the power of two 2^e > max_abs (at least the smallest normal, so
        // that the pixel stays a normal number)
        let mut top = f64::MIN_POSITIVE * 2f64.powi(PIXELS_PER_MAGNITUDE_LOG2 + 2);
        while top <= max_abs {
            top *= 2.0;
        }
        let size = top * 2f64.powi(-PIXELS_PER_MAGNITUDE_LOG2);
        PixelGrid { size, inverse: 1.0 / size }
    }

    /// The pixel side δ.
    pub(crate) fn size(&self) -> f64 {
        self.size
    }

    /// The pixel holding `p`. Pixels are half-open, `[m − ½, m + ½) δ` on
    /// each axis, so they tile the plane and every point is in exactly one.
    pub(crate) fn pixel_of(&self, p: Point) -> Pixel {
        [self.index(p.x), self.index(p.y)]
    }

    /// `floor(x / δ + ½)`, exactly: x / δ is exact (a power of two) and
    /// below 2^47 in magnitude, and so is its distance to its floor.
    fn index(&self, x: f64) -> i64 {
        let v = x * self.inverse;
        let floor = v.floor();
        floor as i64 + i64::from(v - floor >= 0.5)
    }

    /// The centre of a pixel, exactly.
    pub(crate) fn centre(&self, pixel: Pixel) -> Point {
        Point::new(pixel[0] as f64 * self.size, pixel[1] as f64 * self.size)
    }

    /// The pixel holding the point where `s` and `t` cross (properly),
    /// decided exactly: [`crossing_point`] is within δ/8 of it, and which
    /// side of a pixel's edge the true point lies on is the sign of an
    /// exact expansion (see [`side_of_crossing`]).
    pub(crate) fn crossing_pixel(&self, s: [Point; 2], t: [Point; 2]) -> Pixel {
        let guess = self.pixel_of(crossing_point(s, t));
        let (oa, ob) = (orientation_expansion(t[0], t[1], s[0]), orientation_expansion(t[0], t[1], s[1]));
        let mut denominator = oa.clone();
        denominator.subtract(&ob);
        let [a, b] = s;
        let axes = [(a.x, b.x), (a.y, b.y)];
        let mut pixel = guess;
        for (k, &(from, to)) in axes.iter().enumerate() {
            // the crossing is at or beyond the lower edge of pixel m when
            // it is not strictly below (m − ½) δ
            let at_or_above = |m: i64| side_of_crossing(from, to, &oa, &denominator, (m as f64 - 0.5) * self.size) >= 0;
            let mut m = guess[k];
            // at most a step or two: the guess is within δ/8 of the truth
            for _ in 0..4 {
                if !at_or_above(m) {
                    m -= 1;
                } else if at_or_above(m + 1) {
                    m += 1;
                } else {
                    break;
                }
            }
            pixel[k] = m;
        }
        pixel
    }

    /// Whether the closed segment `ab` meets the half-open pixel, decided
    /// exactly.
    ///
    /// The half-open square `[x0, x1) × [y0, y1)` is met when the closed
    /// square `[x0, x1 − ε] × [y0, y1 − ε']` is, for infinitesimal
    /// `0 < ε' ≪ ε`: their bounding boxes overlap, and the (symbolically
    /// moved) corners are not all strictly on one side of the segment's
    /// line. The corners are exact doubles, so each side is an exact sign,
    /// and where it is zero the moved corner's side is the sign of the
    /// first nonzero derivative.
    pub(crate) fn meets(&self, pixel: Pixel, a: Point, b: Point) -> bool {
        let half = self.size / 2.0;
        let c = self.centre(pixel);
        let (x0, x1, y0, y1) = (c.x - half, c.x + half, c.y - half, c.y + half);
        if a.x.max(b.x) < x0 || a.x.min(b.x) >= x1 || a.y.max(b.y) < y0 || a.y.min(b.y) >= y1 {
            return false;
        }
        // Moving a point by −ε along x changes (b − a) × (q − a) by
        // ε (b.y − a.y); by −ε' along y, by −ε' (b.x − a.x).
        let along_x = sign(b.y - a.y);
        let along_y = -sign(b.x - a.x);
        let side = |q: Point, moved_x: bool, moved_y: bool| {
            let exact = exact_orientation(a, b, q).sign();
            [exact, if moved_x { along_x } else { 0 }, if moved_y { along_y } else { 0 }]
                .into_iter()
                .find(|&s| s != 0)
                .unwrap_or(0)
        };
        let sides = [
            side(Point::new(x0, y0), false, false),
            side(Point::new(x1, y0), true, false),
            side(Point::new(x1, y1), true, true),
            side(Point::new(x0, y1), false, true),
        ];
        !(sides.iter().all(|&s| s < 0) || sides.iter().all(|&s| s > 0))
    }
}

fn sign(x: f64) -> i8 {
    if x > 0.0 {
        1
    } else if x < 0.0 {
        -1
    } else {
        0
    }
}

/// The point where segments `s` and `t` cross (they cross properly: each
/// has its endpoints strictly on both sides of the other's line).
///
/// With `o_a`, `o_b` the orientations of `a` and `b` against `t`'s line,
/// the crossing is `a + (o_a / (o_a − o_b)) (b − a)`. The orientations are
/// evaluated exactly and rounded once, and as they have opposite signs the
/// difference does not cancel: the parameter is within 3 ulps, and the point
/// within about 6 ulps of the largest coordinate, however small the angle
/// between the segments.
fn crossing_point(s: [Point; 2], t: [Point; 2]) -> Point {
    let [a, b] = s;
    let (oa, ob) = (orientation_value(t[0], t[1], a), orientation_value(t[0], t[1], b));
    let u = oa / (oa - ob);
    if !u.is_finite() {
        return a; // not a proper crossing; the caller never asks this
    }
    Point::new(a.x + u * (b.x - a.x), a.y + u * (b.y - a.y))
}

/// `(b − a) × (c − a)`, computed exactly and then rounded.
fn orientation_value(a: Point, b: Point, c: Point) -> f64 {
    orientation_expansion(a, b, c).approximate()
}

/// `(b − a) × (c − a)`, exactly.
fn orientation_expansion(a: Point, b: Point, c: Point) -> Expansion {
    let mut e = Expansion::default();
    e.add_product_of_differences((b.x, a.x), (c.y, a.y));
    e.add_product_of_differences((b.y, a.y), (a.x, c.x));
    e
}

/// The sign of `X − edge` along one axis, for the crossing
/// `X = from + (o_a / D) (to − from)` (`D = o_a − o_b`): the sign of
/// `(from − edge) D + o_a (to − from)`, times the sign of `D`, exactly.
fn side_of_crossing(from: f64, to: f64, oa: &Expansion, denominator: &Expansion, edge: f64) -> i8 {
    let mut numerator = Expansion::default();
    numerator.add_product_with_difference(denominator, (from, edge));
    numerator.add_product_with_difference(oa, (to, from));
    numerator.sign() * denominator.sign()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn pixel_centres_and_corners_are_exact() {
        let grid = PixelGrid::for_magnitude(1000.0);
        assert_eq!(grid.size(), 1024.0 * 2f64.powi(-46));
        let q = p(999.123456789, -0.000123);
        let c = grid.centre(grid.pixel_of(q));
        assert!((c.x - q.x).abs() <= grid.size() / 2.0 && (c.y - q.y).abs() <= grid.size() / 2.0);
        assert_eq!(grid.pixel_of(c), grid.pixel_of(q));
    }

    #[test]
    fn a_segment_meets_the_pixels_it_passes_through() {
        let grid = PixelGrid::for_magnitude(10.0);
        let (a, b) = (p(0.0, 0.0), p(7.0, 3.0));
        for k in 0..100 {
            let on = p(7.0 * k as f64 / 99.0, 3.0 * k as f64 / 99.0);
            assert!(grid.meets(grid.pixel_of(on), a, b));
        }
        let off = p(3.5, 1.5 + 4.0 * grid.size());
        assert!(!grid.meets(grid.pixel_of(off), a, b));
        // pixels are half-open: of the four around a corner, a segment
        // through it only meets the one whose lower-left corner it is
        let d = grid.size();
        let corner = p(3.5 * d, 0.5 * d);
        let (from, to) = (p(corner.x - d, corner.y - d), p(corner.x + d, corner.y + d));
        let met: Vec<bool> = [[3, 0], [4, 0], [3, 1], [4, 1]].iter().map(|&q| grid.meets(q, from, to)).collect();
        assert_eq!(met, [true, false, false, true]);
        let (from, to) = (p(corner.x - d, corner.y + d), p(corner.x + d, corner.y - d));
        let met: Vec<bool> = [[3, 0], [4, 0], [3, 1], [4, 1]].iter().map(|&q| grid.meets(q, from, to)).collect();
        assert_eq!(met, [false, true, true, true]);
        assert_eq!(grid.pixel_of(corner), [4, 1]);
    }

    #[test]
    fn crossing_points_are_accurate_at_tiny_angles() {
        let s = [p(0.0, 0.0), p(1.0, 1e-12)];
        let t = [p(0.0, 1e-12), p(1.0, -3e-12)];
        let x = crossing_point(s, t);
        // exact: 1e-12 x = 1e-12 - 4e-12 x, so x = 0.2
        assert!((x.x - 0.2).abs() < 1e-15, "{x:?}");
        let grid = PixelGrid::for_magnitude(1.0);
        assert_eq!(grid.crossing_pixel(s, t), grid.pixel_of(p(0.2, 0.2e-12)));
    }
}
