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

/// [`bisector_point`] for a finite edge of the construction, `left` the
/// cell on its left going from `from` to `to`: by the angle round the
/// point site where one site is a point and the other a segment or an arc
/// (`round_point_site`), else from the chord.
pub(crate) fn bisector_point_on_edge(left: &Site, right: &Site, from: Point, to: Point, t: f64) -> Point {
    bisector_point_of_edge(left, right, from, to, t, &[])
}

/// [`bisector_point_on_edge`] for an edge of a built diagram, `witnesses`
/// the third sites of its end vertices: the point round the point site is
/// taken unless a witness is nearer there than the edge's own sites (it is
/// then on their bisector but past the edge's ends: an edge between two
/// vertices of the same three sites a rounding apart can have its ends in
/// the other order than its sites say, an arc, another arc's end and a
/// third arc 4e-7 apart and 0.1 from the end, and round the point that
/// edge would be a whole loop); then from the chord.
pub(crate) fn bisector_point_of_edge(
    left: &Site,
    right: &Site,
    from: Point,
    to: Point,
    t: f64,
    witnesses: &[Option<Site>],
) -> Point {
    let on_the_edge = |q: Point| {
        let own = 0.5 * (left.distance(q) + right.distance(q));
        witnesses.iter().flatten().all(|w| w.distance(q) >= own * (1.0 - 1e-9))
    };
    match round_point_site(left, right, from, to, t) {
        Some(q) if on_the_edge(q) => q,
        _ => bisector_point(left, right, from, to, t),
    }
}

/// The point at fraction `t` of the edge from `from` to `to` between a
/// point `p` and a segment or an arc, by the angle round `p`; `None` for
/// any other pair, or a point on the segment's line or the arc's circle.
///
/// A point's cell is star-shaped from the point (every point between it
/// and a point nearer it than the other site is nearer too), so each
/// direction `u` from `p` meets the bisector once, at `ρ` from `p`, with a
/// focus at `p`:
/// - a segment at distance `h` along the unit normal `n` from `p` (the
///   edge touches the segment inside, so its line): a parabola,
///   `ρ = h / (1 + u·n)`;
/// - an arc whose circle (centre `c`, radius `r`) holds `p`: an ellipse,
///   `ρ = (r² − |w|²) / 2(r + w·u)`, `w = p − c`;
/// - an arc whose circle leaves `p` outside (then its convex side faces
///   the edge): a hyperbola's branch, `ρ = (|w|² − r²) / 2(r − w·u)`.
///
/// The edge runs round `p` with `p`'s cell on its left: counter-clockwise
/// when `p` is the left site. From the chord it may go either way round,
/// the long way past `p`'s far side included, where no perpendicular from
/// the chord meets it: a point a hair from a segment (its cell a thin
/// tongue, the edge's ends close together across it, its middle at the
/// tongue's far end by the point), an arc's end a hair inside another
/// arc's circle (the edge of that end's cell with the other arc runs round
/// the end). Where a new arc takes both ends of such an edge, all that is
/// left of the point's cell may be that middle.
pub(crate) fn round_point_site(left: &Site, right: &Site, from: Point, to: Point, t: f64) -> Option<Point> {
    let (p, other, counter_clockwise) = match (*left, *right) {
        (Site::Point(p), other) => (p, other, true),
        (other, Site::Point(p)) => (p, other, false),
        _ => return None,
    };
    let angle = |q: Point| (q.y - p.y).atan2(q.x - p.x);
    let (start, end) = (angle(from), angle(to));
    let tau = std::f64::consts::TAU;
    let sweep = if counter_clockwise { (end - start).rem_euclid(tau) } else { -(start - end).rem_euclid(tau) };
    let (uy, ux) = (start + t * sweep).sin_cos();
    let rho = match other {
        Site::Point(_) => return None,
        Site::Segment { a, b } => {
            let length = (b.x - a.x).hypot(b.y - a.y);
            let (mut nx, mut ny) = (-(b.y - a.y) / length, (b.x - a.x) / length);
            let mut h = (a.x - p.x) * nx + (a.y - p.y) * ny;
            if h < 0.0 {
                (nx, ny, h) = (-nx, -ny, -h);
            }
            let denominator = 1.0 + ux * nx + uy * ny;
            if !(h > 0.0 && denominator > 0.0) {
                return None;
            }
            h / denominator
        }
        Site::Arc(arc) => {
            let (c, r) = (arc.centre(), arc.radius());
            let (wx, wy) = (p.x - c.x, p.y - c.y);
            let w = wx.hypot(wy);
            let along = wx * ux + wy * uy;
            let (numerator, denominator) = if w < r * (1.0 - 1e-9) {
                (r * r - w * w, 2.0 * (r + along))
            } else if w > r * (1.0 + 1e-9) {
                (w * w - r * r, 2.0 * (r - along))
            } else {
                return None;
            };
            if !(denominator > 0.0) {
                return None;
            }
            numerator / denominator
        }
    };
    rho.is_finite().then(|| Point::new(p.x + rho * ux, p.y + rho * uy))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::arc::CircularArc;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    /// As far from both sites.
    fn on_bisector(left: &Site, right: &Site, q: Point) -> bool {
        (left.distance(q) - right.distance(q)).abs() < 1e-9
    }

    #[test]
    fn round_a_point_a_hair_from_a_segment() {
        // the point's cell is a thin tongue hanging below it (the parabola
        // x² = -0.02 y - 0.0001); the edge's ends lie on its two sides one
        // and three below, and its middle is by the point, which no
        // perpendicular from the chord reaches
        let (point, segment) = (Site::Point(p(0.0, -0.01)), Site::Segment { a: p(-5.0, 0.0), b: p(5.0, 0.0) });
        let (from, to) = (p(0.0199f64.sqrt(), -1.0), p(-0.0599f64.sqrt(), -3.0));
        assert!(on_bisector(&point, &segment, from) && on_bisector(&point, &segment, to));
        // the point on the left: counter-clockwise round it, over the top
        let middle = bisector_point_on_edge(&point, &segment, from, to, 0.5);
        assert!(on_bisector(&point, &segment, middle), "{middle:?}");
        assert!(middle.y > -0.02, "{middle:?}");
        // from the chord: halfway down the tongue
        assert!(bisector_point(&point, &segment, from, to, 0.5).y < -1.0);
        // the other way along the edge, the sites swapped: the same point
        let back = bisector_point_on_edge(&segment, &point, to, from, 0.5);
        assert!(back.distance(middle) < 1e-12, "{back:?}");
        // a third site of an end vertex nearer than the edge's own there:
        // the round way is past the edge's ends, the chord's is taken
        let witness = Some(Site::Point(p(0.0, -0.004)));
        let checked = bisector_point_of_edge(&point, &segment, from, to, 0.5, &[None, witness]);
        assert_eq!(checked, bisector_point(&point, &segment, from, to, 0.5));
        let far = Some(Site::Point(p(0.0, 3.0)));
        assert_eq!(bisector_point_of_edge(&point, &segment, from, to, 0.5, &[far, None]), middle);
        // a point on the segment's line has no tongue: from the chord
        let on_line = Site::Point(p(6.0, 0.0));
        assert_eq!(round_point_site(&on_line, &segment, p(5.5, 1.0), p(5.5, -1.0), 0.5), None);
    }

    #[test]
    fn round_a_point_inside_and_outside_an_arc() {
        // the upper half of the circle of radius 2 round the origin; a
        // point inside it (an ellipse round the point) and outside (a
        // hyperbola's branch), the edge between where it crosses x = ±0.3,
        // going west: the point on its left when below the edge
        let arc = Site::Arc(CircularArc::from_bulge([2.0, 0.0], [-2.0, 0.0], 1.0).unwrap());
        for q in [p(0.0, 1.5), p(0.0, 3.0)] {
            let point = Site::Point(q);
            let end = |x: f64| bisector_point(&point, &arc, p(x - 0.1, 0.5 * (q.y + 2.0)), p(x + 0.1, 0.5 * (q.y + 2.0)), 0.5);
            let (from, to) = (end(0.3), end(-0.3));
            assert!(on_bisector(&point, &arc, from) && on_bisector(&point, &arc, to), "{q:?}");
            let (left, right) = if q.y < 2.0 { (&point, &arc) } else { (&arc, &point) };
            for t in [0.1, 0.5, 0.9] {
                let on_edge = bisector_point_on_edge(left, right, from, to, t);
                assert!(on_bisector(&point, &arc, on_edge), "{q:?} {t}: {on_edge:?}");
                // the short way, between the ends, on the arc's side
                assert!(on_edge.x.abs() < 0.3 && (on_edge.y - q.y).abs() < 0.6, "{q:?} {t}: {on_edge:?}");
            }
        }
    }
}
