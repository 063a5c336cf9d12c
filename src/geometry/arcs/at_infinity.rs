//! Whether a new arc takes the place of a vertex at infinity: the far end
//! of the bisector of two hull sites `x` and `y`, in the direction `d` out
//! of the hull where both reach equally far (their common supporting line
//! `L`, `d` its outward normal).
//!
//! The arc conflicts when it reaches further out along `d` than `L`. Where
//! it only touches `L` (a tie of the support functions, the rule for every
//! half circle beside its neighbours and every rounded corner), the order
//! along `L` decides, as for collinear points on a hull: the arc's cell
//! then reaches infinity exactly when the arc touches `L` strictly between
//! the places where `x` and `y` touch it, or touches it where one of them
//! does and runs on along `L` toward the other (the arc's end on `L`,
//! tangent to it: near its end the arc is a short segment on `L`, and its
//! curve away from `L` keeps it nearer than the site it starts beside, at
//! every far point off `L`'s normal through that end).

use crate::geometry::arc::CircularArc;
use crate::geometry::arcs::exact_join;
use crate::geometry::point::Point;
use crate::geometry::site::Site;

/// A tie of two reaches, relative to the size of the numbers involved.
const TIE: f64 = 1e-12;

/// How nearly along `L` the arc must leave its end to run on along it.
const ALONG: f64 = 1e-9;

/// Whether the arc conflicts with the vertex at infinity between the hull
/// sites `x` and `y` in direction `d` (neither pair of which is the arc's
/// endpoints; see the module doc).
pub(crate) fn arc_conflict_at_infinity(arc: &CircularArc, d: Point, x: &Site, y: &Site) -> bool {
    let norm = d.x.hypot(d.y);
    if !(norm.is_finite() && norm > 0.0) {
        return false;
    }
    let d = Point::new(d.x / norm, d.y / norm);
    let arc_site = Site::Arc(*arc);
    let reach = arc_site.support(d).0;
    let level = x.support(d).0.max(y.support(d).0);
    let c = arc.centre();
    let size = reach.abs() + level.abs() + (d.x * c.x).abs() + (d.y * c.y).abs() + arc.radius();
    let tie = TIE * size;
    if reach - level > tie {
        return true;
    }
    if reach - level < -tie {
        return false;
    }
    // One of x and y is an end of the arc (on L exactly, where that site
    // touches it) and the arc leaves it clearly to the far side of L: the
    // arc's points next to it reach beyond L, by however little (an arc
    // of a few ulps, whose sagitta is a rounding of its coordinates, lies
    // beyond the line its ends are on as a bigger one would)
    let leaves_beyond = |e: Point| {
        let t = arc.tangent_into(e);
        [x, y].iter().any(|s| s.as_point() == Some(e)) && t.x * d.x + t.y * d.y > ALONG
    };
    if leaves_beyond(arc.start()) || leaves_beyond(arc.end()) {
        return true;
    }
    // along L, counter-clockwise round the hull
    let u = Point::new(-d.y, d.x);
    let along = |p: Point| u.x * p.x + u.y * p.y;
    let (Some(xs), Some(ys)) = (touching(x, d, level, tie), touching(y, d, level, tie)) else {
        return false;
    };
    let (low, high) = if xs.1 <= ys.0 { (xs.1, ys.0) } else { (ys.1, xs.0) };
    if high - low <= tie {
        // x and y touch L at one place: no room between them
        return false;
    }
    let along_tie = TIE * (low.abs() + high.abs() + size);
    // the arc's farthest point inside it, on L strictly between (whether
    // `d` is in the span asked at a point far enough along it that `c`'s
    // rounding does not swallow a small component of `d`: the answer
    // must not depend on where the input lies)
    let far = (c.x.abs().max(c.y.abs()) + arc.radius()) * 2f64.powi(40);
    if arc.spans(Point::new(c.x + far * d.x, c.y + far * d.y)) {
        let top = along(Point::new(c.x + arc.radius() * d.x, c.y + arc.radius() * d.y));
        if low + along_tie < top && top < high - along_tie {
            return true;
        }
    }
    // an end on L where x or y touches it, running on along L toward the other
    [arc.start(), arc.end()].into_iter().any(|e| {
        if (d.x * e.x + d.y * e.y) < level - tie {
            return false;
        }
        let t = arc.tangent_into(e);
        if (t.x * d.x + t.y * d.y).abs() > ALONG {
            return false;
        }
        let s = along(e);
        let toward = t.x * u.x + t.y * u.y;
        ((s - low).abs() <= along_tie && toward > 0.0) || ((s - high).abs() <= along_tie && toward < 0.0)
    })
}

/// Whether the arc conflicts with the vertex at infinity of the edge
/// between one of its endpoints `end` and a `piece` (segment or arc)
/// ending there too: the far end of `piece`'s normal at `end`, in
/// direction `d`. Both reach `end · d` along `d`, and so does the arc's
/// circle, through `end`; the arc reaches further exactly when `d` lies in
/// its span, on the side of its own normal at `end` that it leaves
/// toward: `d · t > 0`, `t` its tangent leaving `end`, or `(d⊥-sign) ×
/// (piece's tangent × t)`, an exact sign (`exact_join`). Where the pieces
/// meet an ulp off tangent, floating point sees a tie of 1e-20 there and
/// kept the end's cell on both sides of the join. `None` (the caller
/// decides as before) where `d` is not near the arc's normal at `end`
/// (within a fraction of its sweep, not a near tie then), where the
/// pieces are tangent to 1e-12 rad (curvatures decide), or out of range.
pub(crate) fn beside_a_shared_end(arc: &CircularArc, d: Point, end: Point, piece: &Site) -> Option<bool> {
    let norm = d.x.hypot(d.y);
    if !(norm.is_finite() && norm > 0.0) {
        return None;
    }
    let d = Point::new(d.x / norm, d.y / norm);
    let (c, r) = (arc.centre(), arc.radius());
    let n = Point::new((end.x - c.x) / r, (end.y - c.y) / r);
    let off_normal = (d.x * n.y - d.y * n.x).abs().asin();
    if !(d.x * n.x + d.y * n.y > 0.0 && off_normal < (arc.sweep().abs() / 2.0).min(0.1)) {
        return None;
    }
    let along_piece = exact_join::leaving(piece, end)?;
    let along_arc = exact_join::leaving(&Site::Arc(*arc), end)?;
    // `d` is the piece's tangent turned a quarter, one way or the other:
    // which one is clear in floating point (they are perpendicular)
    let t = along_piece.approximate();
    let quarter = t.x * d.y - t.y * d.x;
    if quarter.abs() < 0.5 * t.x.hypot(t.y) {
        return None;
    }
    // A join within 1e-12 rad of tangent (an ulp off, as where biarcs
    // meet) stays with the curvature rules: the exact side there would
    // need the direction at infinity of the two pieces' bisector, which
    // the floating-point search places no better than the tie itself
    // (a font's æ was refused once it was asked).
    let u = along_arc.approximate();
    if (t.x * u.y - t.y * u.x).abs() <= 1e-12 * t.x.hypot(t.y) * u.x.hypot(u.y) {
        return None;
    }
    let turn = exact_join::cross_sign(&along_piece, &along_arc)?;
    match turn * if quarter > 0.0 { 1 } else { -1 } {
        0 => None,
        s => Some(s > 0),
    }
}

/// Where along `L` (counter-clockwise) the site touches it: the least and
/// greatest places of its points that reach `level` along `d` (its ends,
/// and an arc's farthest point where `d` lies in its span).
fn touching(site: &Site, d: Point, level: f64, tie: f64) -> Option<(f64, f64)> {
    let u = Point::new(-d.y, d.x);
    let mut candidates: Vec<Point> = site.ends().to_vec();
    if matches!(site, Site::Arc(_)) {
        candidates.push(site.support(d).1);
    }
    let reaching = candidates.into_iter().filter(|p| d.x * p.x + d.y * p.y >= level - tie).map(|p| u.x * p.x + u.y * p.y);
    reaching.fold(None, |span: Option<(f64, f64)>, s| Some(span.map_or((s, s), |(a, b)| (a.min(s), b.max(s)))))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn an_arc_running_on_along_the_hull_line_between_two_points() {
        // hull points (1, 0) and (1, 2), the line x = 1, outward (1, 0);
        // the upper half circle from (0, 0) to (1, 0) ends at (1, 0)
        // tangent to the line, running up toward (1, 2): its cell takes
        // the strip 0 < y < 1 at infinity
        let (x, y) = (Site::Point(p(1.0, 0.0)), Site::Point(p(1.0, 2.0)));
        let up = CircularArc::from_bulge(p(0.0, 0.0), p(1.0, 0.0), -1.0).unwrap();
        assert!(arc_conflict_at_infinity(&up, p(1.0, 0.0), &x, &y));
        assert!(arc_conflict_at_infinity(&up, p(1.0, 0.0), &y, &x));
        // the lower half circle leaves (1, 0) downward, away from (1, 2)
        let down = CircularArc::from_bulge(p(0.0, 0.0), p(1.0, 0.0), 1.0).unwrap();
        assert!(!arc_conflict_at_infinity(&down, p(1.0, 0.0), &x, &y));
        // a quarter arc around (1, 1) leaving (1, 0) leftward, across the
        // line into the hull; the one around (0, 0) leaves it upward,
        // along the line
        let across = CircularArc::from_bulge(p(1.0, 0.0), p(0.0, 1.0), -0.4142135623730951).unwrap();
        assert!(!arc_conflict_at_infinity(&across, p(1.0, 0.0), &x, &y));
        let along = CircularArc::from_bulge(p(1.0, 0.0), p(0.0, 1.0), 0.4142135623730951).unwrap();
        assert!(arc_conflict_at_infinity(&along, p(1.0, 0.0), &x, &y));
    }

    #[test]
    fn an_arc_of_a_few_ulps_leaving_its_end_on_the_hull_line_outward() {
        // hull points (1, 1) and the arc's end (1, 4 ulps), the line x = 1,
        // outward (1, 0); the arc from (1, 0) bulges right of x = 1 by
        // 2.2e-16, a rounding of 1 (a tie by the support functions), but
        // leaves its end at 53 degrees outward: it reaches beyond the line
        let ulp = f64::EPSILON;
        let (top, end) = (Site::Point(p(1.0, 1.0)), Site::Point(p(1.0, 4.0 * ulp)));
        let out = CircularArc::from_bulge(p(1.0, 0.0), p(1.0, 4.0 * ulp), 0.5).unwrap();
        assert!(arc_conflict_at_infinity(&out, p(1.0, 0.0), &top, &end));
        assert!(arc_conflict_at_infinity(&out, p(1.0, 0.0), &end, &top));
        // bulging left of the line, into the hull: no conflict
        let inward = CircularArc::from_bulge(p(1.0, 0.0), p(1.0, 4.0 * ulp), -0.5).unwrap();
        assert!(!arc_conflict_at_infinity(&inward, p(1.0, 0.0), &top, &end));
    }

    #[test]
    fn an_arc_touching_the_line_between_or_beyond() {
        let (x, y) = (Site::Point(p(1.0, 0.0)), Site::Point(p(1.0, 2.0)));
        // the right half circle centred (0.5, 1), touching x = 1 at (1, 1)
        let between = CircularArc::from_bulge(p(0.5, 0.5), p(0.5, 1.5), 1.0).unwrap();
        assert!(arc_conflict_at_infinity(&between, p(1.0, 0.0), &x, &y));
        // the same touching at (1, 3), beyond (1, 2)
        let beyond = CircularArc::from_bulge(p(0.5, 2.5), p(0.5, 3.5), 1.0).unwrap();
        assert!(!arc_conflict_at_infinity(&beyond, p(1.0, 0.0), &x, &y));
        // reaching past the line, and short of it
        let past = CircularArc::from_bulge(p(0.5, 0.5), p(0.5, 1.5), 1.5).unwrap();
        assert!(arc_conflict_at_infinity(&past, p(1.0, 0.0), &x, &y));
        let short = CircularArc::from_bulge(p(0.5, 0.5), p(0.5, 1.5), 0.5).unwrap();
        assert!(!arc_conflict_at_infinity(&short, p(1.0, 0.0), &x, &y));
    }

    #[test]
    fn no_room_where_the_two_sites_touch_the_line_at_one_place() {
        // a segment along y = 0 ending at (2, 0), and that point: their
        // separator goes down; a corner arc continuing the segment
        // tangentially from (2, 0) takes nothing at infinity there
        let (x, y) = (Site::Segment { a: p(0.0, 0.0), b: p(2.0, 0.0) }, Site::Point(p(2.0, 0.0)));
        let corner = CircularArc::from_bulge(p(2.0, 0.0), p(3.0, 1.0), 0.4142135623730951).unwrap();
        assert!(!arc_conflict_at_infinity(&corner, p(0.0, -1.0), &x, &y));
        assert!(!arc_conflict_at_infinity(&corner, p(0.0, -1.0), &y, &x));
    }
}
