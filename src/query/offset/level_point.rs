//! A crossing of an offset level found along a conic edge, moved onto
//! both sites' offset curves.
//!
//! The bisection along an edge's track (`ConicTrack::root`) finds the
//! crossing's parameter to the last bit, but the point there is only as
//! good as the track: where the edge runs nearly along a ray from the
//! arc's centre (beside a point a hair off the arc's end, or a tangent
//! line), the distance to the arc and to the other site change at nearly
//! the same rate along the ray, and the point's clearance came out 2e-9
//! off its level (LibreCAD's elk38: the ends of two offset pieces, each
//! on its own curve, 8e-9 apart in radius). The crossing is where the two
//! sites' offset curves at the level meet (a circle around the arc's
//! centre, and a circle or a line for the other), and that intersection,
//! computed directly, lies on both to rounding. It is taken only where it
//! is nearer the level than the tracked point and within a hair of it.

use crate::geometry::{CircularArc, Point, Site};

/// How far (relative to the level and the arc's radius) the intersection
/// may lie from the tracked point: the tracked point is off by the square
/// root of rounding at worst (1e-8); the other intersection of the two
/// curves is much farther, except where they touch, where both are one.
const REACH: f64 = 1e-6;

/// A site's offset curve at a level, near a point: a circle (centre,
/// radius) or a line (a point of it, unit direction).
#[derive(Clone, Copy, Debug)]
enum Curve {
    Circle(Point, f64),
    Line(Point, Point),
}

/// `p`, a point of the edge between `arc` and `other` at about `level`
/// from both, moved to where their offset curves at `level` meet, if that
/// is nearer the level (see the module documentation).
pub(super) fn onto_level(arc: &CircularArc, other: &Site, p: Point, level: f64) -> Point {
    let off = |q: Point| (arc.distance(q) - level).abs().max((other.distance(q) - level).abs());
    let (Some(Curve::Circle(c, radius)), Some(second)) = (curve_of(&Site::Arc(*arc), p, level), curve_of(other, p, level)) else {
        return p;
    };
    let candidates = match second {
        Curve::Circle(c2, r2) => circle_circle(c, radius, c2, r2),
        Curve::Line(o, u) => circle_line(c, radius, o, u),
    };
    let reach = REACH * (level + arc.radius());
    candidates
        .into_iter()
        .flatten()
        .filter(|q| q.is_finite() && q.distance(p) <= reach)
        .min_by(|q, w| q.distance(p).total_cmp(&w.distance(p)))
        .filter(|&q| off(q) < off(p))
        .unwrap_or(p)
}

/// The offset curve at `level` of `site` on the side of `p` (whose
/// nearest point on the site tells which part: an end's circle, a
/// segment's parallel, an arc's concentric circle); `None` where it has
/// none (inside an arc of radius below the level).
fn curve_of(site: &Site, p: Point, level: f64) -> Option<Curve> {
    match *site {
        Site::Point(q) => Some(Curve::Circle(q, level)),
        Site::Segment { a, b } => {
            let n = site.nearest_point(p);
            let length = a.distance(b);
            if n == a || n == b || !(length > 0.0) {
                return Some(Curve::Circle(n, level));
            }
            let u = Point::new((b.x - a.x) / length, (b.y - a.y) / length);
            let side = if (p.x - a.x) * -u.y + (p.y - a.y) * u.x >= 0.0 { level } else { -level };
            Some(Curve::Line(Point::new(a.x - side * u.y, a.y + side * u.x), u))
        }
        Site::Arc(arc) => {
            let n = arc.nearest_point(p);
            if n == arc.start() || n == arc.end() {
                return Some(Curve::Circle(n, level));
            }
            let (c, r) = (arc.centre(), arc.radius());
            let radius = if p.distance(c) >= r { r + level } else { r - level };
            (radius >= 0.0).then_some(Curve::Circle(c, radius))
        }
    }
}

/// The points of two circles (where they touch to rounding, the one
/// point along the centres' line).
fn circle_circle(c1: Point, r1: f64, c2: Point, r2: f64) -> [Option<Point>; 2] {
    let d = c1.distance(c2);
    if !(d > 0.0) {
        return [None, None];
    }
    let along = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);
    let across = (r1 * r1 - along * along).max(0.0).sqrt();
    let (ux, uy) = ((c2.x - c1.x) / d, (c2.y - c1.y) / d);
    let at = |s: f64| Some(Point::new(c1.x + along * ux - s * uy, c1.y + along * uy + s * ux));
    [at(across), at(-across)]
}

/// The points of a circle and a line through `o` with unit direction `u`
/// (where it touches to rounding, the foot of the centre).
fn circle_line(c: Point, r: f64, o: Point, u: Point) -> [Option<Point>; 2] {
    let t = (c.x - o.x) * u.x + (c.y - o.y) * u.y;
    let foot = Point::new(o.x + t * u.x, o.y + t * u.y);
    let half = (r * r - foot.distance_squared(c)).max(0.0).sqrt();
    [Some(Point::new(foot.x + half * u.x, foot.y + half * u.y)), Some(Point::new(foot.x - half * u.x, foot.y - half * u.y))]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An arc of radius 2.5 and a point 1.1e-8 off its end (elk38's
    /// configuration): the offset circles at level 1 nearly touch, and
    /// meet 1.75e-4 from the axis; a tracked point 1e-7 beside that is
    /// moved onto both.
    #[test]
    fn a_crossing_beside_a_near_tangency_lands_on_both_curves() {
        let arc = CircularArc::from_bulge(Point::new(2.5, 0.0), Point::new(0.0, 2.5), 0.41421356237309503).unwrap();
        let other = Site::Point(Point::new(2.5 + 1.1e-8, 0.0));
        let tracked = Point::new(3.5 + 2e-9, 1.75e-4);
        assert!((arc.distance(tracked) - 1.0).abs().max((other.distance(tracked) - 1.0).abs()) > 1e-9);
        let moved = onto_level(&arc, &other, tracked, 1.0);
        assert!((arc.distance(moved) - 1.0).abs() <= 1e-15, "{moved:?}");
        assert!((other.distance(moved) - 1.0).abs() <= 1e-15, "{moved:?}");
        // a point far from the crossing is left alone
        let far = Point::new(3.0, 2.0);
        assert_eq!(onto_level(&arc, &other, far, 1.0), far);
    }

    /// Beside a segment: the arc's offset circle meets the segment's
    /// parallel on the side of the tracked point.
    #[test]
    fn beside_a_segment_the_parallel_on_the_points_side() {
        // the lower half of the unit circle, a line below it
        let arc = CircularArc::from_bulge(Point::new(-1.0, 0.0), Point::new(1.0, 0.0), 1.0).unwrap();
        let other = Site::Segment { a: Point::new(-3.0, -2.0), b: Point::new(3.0, -2.0) };
        let level = 0.75;
        let exact_y = -2.0 + level;
        let x = ((1.0f64 + level).powi(2) - exact_y * exact_y).sqrt();
        let moved = onto_level(&arc, &other, Point::new(x + 1e-9, exact_y - 1e-9), level);
        assert!((moved.x - x).abs() <= 1e-14 && (moved.y - exact_y).abs() <= 1e-14, "{moved:?}");
    }
}
