//! Points of the edge between two sites when no closed form is at hand
//! (an arc among them: a conic): from a point between the edge's ends,
//! along the perpendicular to its chord, to where the two sites are
//! equally far.

use crate::geometry::point::Point;
use crate::geometry::site::Site;

/// The point of the bisector of `left` and `right` near the point at
/// fraction `t` of the chord from `from` to `to`, moved along the chord's
/// perpendicular (by bisection on the difference of the distances, within
/// as far out as the chord is long, then further); the chord's point
/// itself when no sign change is found.
pub(crate) fn bisector_point(left: &Site, right: &Site, from: Point, to: Point, t: f64) -> Point {
    let base = Point::new(from.x + t * (to.x - from.x), from.y + t * (to.y - from.y));
    let (dx, dy) = (to.x - from.x, to.y - from.y);
    let length = dx.hypot(dy);
    if !(length > 0.0) || !length.is_finite() {
        return base;
    }
    let n = Point::new(-dy / length, dx / length);
    let at = |s: f64| Point::new(base.x + s * n.x, base.y + s * n.y);
    let f = |s: f64| {
        let q = at(s);
        left.distance(q) - right.distance(q)
    };
    let f0 = f(0.0);
    if f0 == 0.0 {
        return base;
    }
    // the nearest sign change on either side, looking further out in steps
    let mut reach = 0.25 * length;
    for _ in 0..8 {
        for s in [reach, -reach] {
            let fs = f(s);
            if fs.signum() != f0.signum() {
                let (mut lo, mut hi, mut flo) = (0.0f64, s, f0);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    let fm = f(mid);
                    if fm == 0.0 {
                        return at(mid);
                    }
                    if fm.signum() == flo.signum() {
                        lo = mid;
                        flo = fm;
                    } else {
                        hi = mid;
                    }
                }
                return at(0.5 * (lo + hi));
            }
        }
        reach *= 2.0;
    }
    base
}
