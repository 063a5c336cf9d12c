//! Parabolic arcs: the Voronoi edge between a point site (the focus) and a
//! segment site (the directrix is its supporting line).
//!
//! An arc is kept as the focus, the directrix and the two end parameters, and
//! is drawn three ways: as points at given parameters, as one quadratic
//! Bézier curve (an arc of a parabola is exactly one, which is how SVG
//! draws it), and as a polyline within a caller's tolerance.
//!
//! Coordinates along the arc: with `o` the foot of the focus on the
//! directrix, `t` the directrix's unit direction and `n` the unit normal
//! towards the focus at distance `p`, the point at parameter `s` is
//! `o + s t + (s^2 + p^2) / (2 p) n`: equidistant from the focus and the
//! line, as `|x - f|^2 = s^2 + (h - p)^2 = h^2` for `h = (s^2 + p^2) / (2p)`.
//!
//! Precision: not exact. Each point is a few ulps of `|s| + p + s^2 / p`
//! from the true parabola.

use crate::geometry::point::Point;
use crate::geometry::site::Site;

/// The parabola of points equidistant from `focus` and the line through
/// `directrix[0]` and `directrix[1]`, in the coordinates of the module doc.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Parabola {
    /// Foot of the focus on the directrix.
    origin: Point,
    /// Unit direction of the directrix.
    tangent: Point,
    /// Unit normal of the directrix, towards the focus.
    normal: Point,
    /// Distance from the focus to the directrix (positive).
    focal_distance: f64,
}

impl Parabola {
    /// The parabola of `focus` and the line through `a` and `b`; `None` when
    /// `a == b`, when the focus lies on the line (the equidistant set is then
    /// the perpendicular through the focus, a straight edge), or when the
    /// numbers are not finite.
    pub(crate) fn new(focus: Point, a: Point, b: Point) -> Option<Parabola> {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let len = dx.hypot(dy);
        if !(len > 0.0 && len.is_finite()) {
            return None;
        }
        let tangent = Point::new(dx / len, dy / len);
        let (fx, fy) = (focus.x - a.x, focus.y - a.y);
        let along = fx * tangent.x + fy * tangent.y;
        // left of a → b when positive; in double-double, because a focus
        // nearly on the line (the kinks of flattened curves) would lose the
        // digits of its small distance to the rounding of the differences
        let across = cross_accurately(a, b, focus) / len;
        if across == 0.0 || !across.is_finite() {
            return None;
        }
        let normal = if across > 0.0 { Point::new(-tangent.y, tangent.x) } else { Point::new(tangent.y, -tangent.x) };
        let origin = Point::new(a.x + along * tangent.x, a.y + along * tangent.y);
        Some(Parabola { origin, tangent, normal, focal_distance: across.abs() })
    }

    /// The parabola of the bisector of two sites, when it is one: a point
    /// and a segment that does not end at it (in either order). `None` for
    /// every straight bisector (two points, two segments, a segment and its
    /// own endpoint) and where [`Parabola::new`] gives none.
    pub(crate) fn of_sites(first: &Site, second: &Site) -> Option<Parabola> {
        let (focus, a, b) = focus_and_directrix(first, second)?;
        Parabola::new(focus, a, b)
    }

    /// The parameter of the point of the parabola nearest to `q` along the
    /// directrix (exact for points on the parabola, up to rounding).
    pub(crate) fn parameter(&self, q: Point) -> f64 {
        (q.x - self.origin.x) * self.tangent.x + (q.y - self.origin.y) * self.tangent.y
    }

    /// The distance from the focus to the directrix (positive).
    pub(crate) fn focal_distance(&self) -> f64 {
        self.focal_distance
    }

    /// The unit direction of the directrix, in which the parameter grows.
    pub(crate) fn tangent(&self) -> Point {
        self.tangent
    }

    /// The point at parameter `s`.
    pub(crate) fn point(&self, s: f64) -> Point {
        let p = self.focal_distance;
        let h = (s * s + p * p) / (2.0 * p);
        Point::new(self.origin.x + s * self.tangent.x + h * self.normal.x, self.origin.y + s * self.tangent.y + h * self.normal.y)
    }

    /// The point at parameter `s` placed at height `h` over the directrix
    /// (`h` is the height of `s` when both are right; see
    /// `EdgeTrack::point_at_distance` for why it is given).
    pub(crate) fn point_at_height(&self, s: f64, h: f64) -> Point {
        Point::new(self.origin.x + s * self.tangent.x + h * self.normal.x, self.origin.y + s * self.tangent.y + h * self.normal.y)
    }

    /// The quadratic Bézier control points `[start, control, end]` of the arc
    /// from parameter `s0` to `s1`: the curve is exactly that arc. The
    /// control point is where the tangents at the two ends meet.
    pub(crate) fn bezier(&self, s0: f64, s1: f64) -> [Point; 3] {
        let start = self.point(s0);
        // P'(s) = t + (s / p) n; the control point is P(s0) + (s1 - s0)/2 P'(s0).
        let half = (s1 - s0) / 2.0;
        let slope = s0 / self.focal_distance;
        let control = Point::new(
            start.x + half * (self.tangent.x + slope * self.normal.x),
            start.y + half * (self.tangent.y + slope * self.normal.y),
        );
        [start, control, self.point(s1)]
    }

    /// A polyline along the arc from `s0` to `s1` (both ends included) whose
    /// distance from the arc is at most `tolerance`, with at most
    /// `max_points` points (the tolerance is then not met; `max_points` is at
    /// least 2). A chord over a parameter step `d` strays at most
    /// `d^2 / (8 p)` from the arc, so steps of `sqrt(8 p tolerance)` suffice.
    #[cfg(test)]
    pub(crate) fn sample(&self, s0: f64, s1: f64, tolerance: f64, max_points: usize) -> Vec<Point> {
        let mut points = Vec::new();
        self.sample_into(s0, s1, tolerance, max_points, |p| points.push(p));
        points
    }

    /// The points of [`Parabola::sample`], in order, handed to `emit`.
    pub(crate) fn sample_into(&self, s0: f64, s1: f64, tolerance: f64, max_points: usize, mut emit: impl FnMut(Point)) {
        let max_points = max_points.max(2);
        let step = (8.0 * self.focal_distance * tolerance.max(0.0)).sqrt();
        let span = (s1 - s0).abs();
        let wanted = if step > 0.0 { (span / step).ceil() } else { f64::INFINITY };
        // `as` saturates, and NaN (from non-finite input) becomes 0.
        let pieces = if wanted.is_finite() { (wanted as usize).max(1) } else { max_points - 1 };
        let pieces = pieces.min(max_points - 1);
        for k in 0..=pieces {
            emit(self.point(s0 + (s1 - s0) * (k as f64 / pieces as f64)));
        }
    }
}

/// `(b − a) × (c − a)` to nearly full relative precision: in `f64` when
/// that is already within 2^-40 of its value (the differences and products
/// each round by half an ulp, so the error is below 2^-50 of the terms'
/// magnitude), else again in double-double from the exact coordinates.
fn cross_accurately(a: Point, b: Point, c: Point) -> f64 {
    let (l, r) = ((b.x - a.x) * (c.y - a.y), (b.y - a.y) * (c.x - a.x));
    let cross = l - r;
    if cross.abs() >= (l.abs() + r.abs()) * 2f64.powi(-10) {
        return cross;
    }
    use crate::geometry::arithmetic::double_double::DoubleDouble as Dd;
    let d = |p: f64, q: f64| Dd::from_f64(p).sub(Dd::from_f64(q));
    d(b.x, a.x).mul(d(c.y, a.y)).sub(d(b.y, a.y).mul(d(c.x, a.x))).to_f64()
}

/// For a point and a segment that does not end at it (in either order):
/// the point and the segment's endpoints, whose bisector is a parabola
/// unless the point lies on the segment's line. `None` for every other
/// pair of sites.
pub(crate) fn focus_and_directrix(first: &Site, second: &Site) -> Option<(Point, Point, Point)> {
    match (*first, *second) {
        (Site::Point(f), s @ Site::Segment { a, b }) | (s @ Site::Segment { a, b }, Site::Point(f)) if !s.has_endpoint(f) => {
            Some((f, a, b))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    fn distance_to_line(q: Point, a: Point, b: Point) -> f64 {
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        (dx * (q.y - a.y) - dy * (q.x - a.x)).abs() / dx.hypot(dy)
    }

    #[test]
    fn unit_parabola_by_hand() {
        // Focus (0, 1), directrix y = -1: x^2 = 4y, so s = 2 gives (2, 1) and
        // the vertex (s = 0) is the origin. Here the directrix is the x axis
        // shifted: o = (0, -1), p = 2, h = (s^2 + 4) / 4 above it.
        let par = Parabola::new(p(0.0, 1.0), p(-5.0, -1.0), p(5.0, -1.0)).unwrap();
        assert_eq!(par.point(0.0), p(0.0, 0.0));
        assert_eq!(par.point(2.0), p(2.0, 1.0));
        assert_eq!(par.point(-4.0), p(-4.0, 4.0));
        assert_eq!(par.parameter(p(2.0, 1.0)), 2.0);
    }

    #[test]
    fn directrix_orientation_does_not_matter() {
        let f = p(0.3, 2.0);
        let (a, b) = (p(-1.0, 0.5), p(3.0, -0.5));
        let forward = Parabola::new(f, a, b).unwrap();
        let backward = Parabola::new(f, b, a).unwrap();
        for s in [-3.0, -0.5, 0.0, 1.0, 4.0] {
            let q = forward.point(s);
            let r = backward.point(backward.parameter(q));
            assert!(q.distance(r) < 1e-12, "{q:?} {r:?}");
        }
    }

    #[test]
    fn points_are_equidistant_from_focus_and_directrix() {
        let cases = [
            (p(1.0, 1.0), p(0.0, 0.0), p(3.0, 0.5)),
            (p(-2.0, 5.0), p(1e3, -2.0), p(-1e3, 3.0)),
            (p(0.0, 1e-6), p(-1.0, 0.0), p(1.0, 0.0)),
            (p(1e9 + 1.0, 1e9), p(1e9, 1e9 - 3.0), p(1e9 + 5.0, 1e9 + 2.0)),
        ];
        for (f, a, b) in cases {
            let par = Parabola::new(f, a, b).unwrap();
            for s in [-10.0, -1.0, -0.01, 0.0, 0.5, 3.0] {
                let q = par.point(s);
                let (df, dl) = (q.distance(f), distance_to_line(q, a, b));
                let scale = 1.0 + q.x.abs().max(q.y.abs());
                assert!((df - dl).abs() <= 1e-12 * scale.max(df), "{f:?} s={s}: {df} vs {dl}");
            }
        }
    }

    #[test]
    fn degenerate_parabolas_are_refused() {
        assert!(Parabola::new(p(2.0, 0.0), p(0.0, 0.0), p(1.0, 0.0)).is_none(), "focus on the line");
        assert!(Parabola::new(p(2.0, 1.0), p(1.0, 1.0), p(1.0, 1.0)).is_none(), "no directrix");
        assert!(Parabola::new(p(f64::NAN, 1.0), p(0.0, 0.0), p(1.0, 0.0)).is_none());
    }

    #[test]
    fn bezier_is_the_arc() {
        let par = Parabola::new(p(0.5, 2.0), p(-1.0, -0.3), p(4.0, 0.2)).unwrap();
        let (s0, s1) = (-2.5, 3.5);
        let [b0, b1, b2] = par.bezier(s0, s1);
        assert!(b0.distance(par.point(s0)) < 1e-12 && b2.distance(par.point(s1)) < 1e-12);
        // B(u) = (1-u)^2 b0 + 2u(1-u) b1 + u^2 b2 is P(s0 + u (s1 - s0)).
        for u in [0.1, 0.25, 0.5, 0.8] {
            let w = [(1.0 - u) * (1.0 - u), 2.0 * u * (1.0 - u), u * u];
            let b = p(w[0] * b0.x + w[1] * b1.x + w[2] * b2.x, w[0] * b0.y + w[1] * b1.y + w[2] * b2.y);
            assert!(b.distance(par.point(s0 + u * (s1 - s0))) < 1e-12, "u={u}");
        }
    }

    #[test]
    fn samples_stay_within_tolerance() {
        let par = Parabola::new(p(0.0, 0.25), p(-1.0, -0.25), p(1.0, -0.25)).unwrap(); // y = x^2, p = 0.5
        let (s0, s1) = (-3.0, 2.0);
        for tolerance in [1e-1, 1e-3, 1e-6] {
            let poly = par.sample(s0, s1, tolerance, 1 << 20);
            assert_eq!(poly.first().copied(), Some(par.point(s0)));
            assert_eq!(poly.last().copied(), Some(par.point(s1)));
            // For y = x^2 the vertical gap between chord and curve bounds the distance.
            for w in poly.windows(2) {
                let (a, b) = (w[0], w[1]);
                for k in 1..8 {
                    let x = a.x + (b.x - a.x) * k as f64 / 8.0;
                    let chord_y = a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
                    assert!(chord_y - x * x <= tolerance + 1e-12, "tolerance {tolerance}");
                }
            }
            // and not wastefully many: within a factor 2 of the bound's count
            let needed = ((s1 - s0) / (8.0f64 * 0.5 * tolerance).sqrt()).ceil() as usize + 1;
            assert!(poly.len() <= needed + 1, "{} points for {needed}", poly.len());
        }
        assert_eq!(par.sample(s0, s1, 0.0, 100).len(), 100, "capped");
        assert_eq!(par.sample(s0, s1, 1e-300, 1).len(), 2, "at least the two ends");
        assert_eq!(par.sample(1.0, 1.0, 1e-3, 100).len(), 2, "empty arc");
    }
}
