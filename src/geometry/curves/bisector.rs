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
///
/// The perpendicular can meet the two sites' bisector on both sides of the
/// chord, and only one is the edge: a point of an edge touches a segment
/// or an arc among its sites inside it (an edge beside an arc lies in the
/// arc's cone), where the other meeting may touch it at an end (half an
/// ellipse around a point inside an arc, whose chord is the arc's
/// separator). The nearest meeting that touches its pieces inside is
/// taken, else the nearest.
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
    // the nearest sign change on each side, looking further out in steps
    let root_towards = |sign: f64| -> Option<f64> {
        let mut reach = 0.25 * length;
        for _ in 0..8 {
            let s = sign * reach;
            if f(s).signum() != f0.signum() {
                let (mut lo, mut hi, mut flo) = (0.0f64, s, f0);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    let fm = f(mid);
                    if fm == 0.0 {
                        return Some(mid);
                    }
                    if fm.signum() == flo.signum() {
                        lo = mid;
                        flo = fm;
                    } else {
                        hi = mid;
                    }
                }
                return Some(0.5 * (lo + hi));
            }
            reach *= 2.0;
        }
        None
    };
    let inside = |q: Point| touches_inside(left, q) && touches_inside(right, q);
    let roots = [root_towards(1.0), root_towards(-1.0)];
    let mut found: Vec<f64> = roots.iter().flatten().copied().collect();
    found.sort_by(|x, y| x.abs().total_cmp(&y.abs()));
    found.iter().copied().find(|&s| inside(at(s))).or(found.first().copied()).map_or(base, at)
}

/// Whether the point of `site` nearest to `q` lies inside it (a segment's
/// strip, an arc's cone), or the site is a point.
fn touches_inside(site: &Site, q: Point) -> bool {
    match *site {
        Site::Point(_) => true,
        Site::Segment { a, b } => {
            let t = crate::geometry::site::segment_parameter(a, b, q);
            t > -1e-9 && t < 1.0 + 1e-9
        }
        Site::Arc(arc) => arc.spans(q),
    }
}
