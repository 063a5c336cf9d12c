//! Points of the edge between two sites when no closed form is at hand
//! (an arc among them: a conic): from a point between the edge's ends,
//! along the perpendicular to its chord, to where the two sites are
//! equally far.

use crate::geometry::arc::CircularArc;
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

/// [`bisector_point`] for an edge of the construction, `left` the cell on
/// its left going from `from` to `to`: round the point where one site is
/// a point inside the other's circle (`round_enclosed_point`), else from
/// the chord. (Only where that orientation is known: the medial axis and
/// the polylines pass their two sites in either order.)
pub(crate) fn bisector_point_on_edge(left: &Site, right: &Site, from: Point, to: Point, t: f64) -> Point {
    round_enclosed_point(left, right, from, to, t).unwrap_or_else(|| bisector_point(left, right, from, to, t))
}

/// The point at fraction `t` of the edge from `from` to `to` between a
/// point and an arc whose circle holds it strictly, by the angle round the
/// point; `None` for any other pair. Their bisector is then an ellipse
/// round the point with the point's cell inside (a focus at the point:
/// along the unit direction `u` from it, at `ρ = (r² − |w|²) / 2(r + w·u)`,
/// `w` the point less the centre), and the edge runs round it with that
/// cell on its left: counter-clockwise when the point is the left site.
/// From the chord the edge may go either way round, the long way past the
/// point's far side included (an arc's end a hair inside another arc's
/// circle: the edge of that end's cell with the other arc runs round the
/// end, and its middle, all that is left of the cell once a third arc
/// passes, lies beyond the chord's ends, where no perpendicular from the
/// chord meets it).
fn round_enclosed_point(left: &Site, right: &Site, from: Point, to: Point, t: f64) -> Option<Point> {
    let holds = |arc: &CircularArc, p: Point| arc.centre().distance(p) < arc.radius() * (1.0 - 1e-9);
    let (p, arc, counter_clockwise) = match (*left, *right) {
        (Site::Point(p), Site::Arc(arc)) if holds(&arc, p) => (p, arc, true),
        (Site::Arc(arc), Site::Point(p)) if holds(&arc, p) => (p, arc, false),
        _ => return None,
    };
    let angle = |q: Point| (q.y - p.y).atan2(q.x - p.x);
    let (start, end) = (angle(from), angle(to));
    let tau = std::f64::consts::TAU;
    let sweep = if counter_clockwise { (end - start).rem_euclid(tau) } else { -(start - end).rem_euclid(tau) };
    let (c, r) = (arc.centre(), arc.radius());
    let (ux, uy) = ((start + t * sweep).cos(), (start + t * sweep).sin());
    let (wx, wy) = (p.x - c.x, p.y - c.y);
    let denominator = 2.0 * (r + wx * ux + wy * uy);
    let rho = (r * r - (wx * wx + wy * wy)) / denominator;
    (denominator > 0.0 && rho.is_finite()).then(|| Point::new(p.x + rho * ux, p.y + rho * uy))
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
