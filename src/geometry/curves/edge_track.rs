//! A Voronoi edge as a track for the offset curves: the edge's curve with a
//! travel parameter `τ` that grows from its first end to its second, and
//! the distance from the edge's sites along it.
//!
//! Along every edge of a segment Voronoi diagram that distance is
//! quasi-convex in `τ` (it falls to one lowest point and then rises):
//! - a straight edge with a point site on either side (two points, or a
//!   segment and its own endpoint): `|o + τ u − c|`, the lowest point the
//!   foot of the centre `c`;
//! - a straight edge between two segments: `|g₀ + τ g₁|`, the distance to
//!   either supporting line (the edge lies in both strips), linear;
//! - a parabolic arc of focus `f` and directrix line `L`:
//!   `(s² + p²) / (2p)` at the directrix parameter `s = στ`, lowest at
//!   the apex `s = 0`.
//!
//! So the distance equals a level `r` at most twice along an edge, at the
//! two roots [`EdgeTrack::roots`] gives: where it falls through `r` and
//! where it rises through it. Which of them lie on the edge, and how many
//! crossings the edge has, is decided by the caller from the vertices'
//! stored radii (so that neighbouring edges agree); this module only
//! places them. Not exact: positions are within a few ulps of the edge's
//! magnitude, as the edge drawings are.

use super::parabola::{focus_and_directrix, Parabola};
use crate::geometry::point::Point;
use crate::geometry::predicates::foot_strictly_inside;
use crate::geometry::site::Site;

/// One end of an edge, in the diagram's internal coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum TrackEnd {
    /// A finite vertex at this position.
    At(Point),
    /// Infinity, reached going this unit direction (away from the edge's
    /// finite part).
    Towards(Point),
}

/// An edge as a curve with its travel parameter (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct EdgeTrack {
    curve: Curve,
    /// The parameter range of the edge, `from <= to`; infinite at an end at
    /// infinity.
    pub(crate) from: f64,
    pub(crate) to: f64,
    /// Whether the curve's lowest point can lie inside a Voronoi edge of
    /// these sites, from the sites alone (exact): a parabola's apex only
    /// when the focus's foot lies inside the segment (the edge lies in the
    /// segment's strip), the crossing of two segments' lines never (the
    /// segments would meet there, and an edge ends where they do), a point's
    /// foot always. So the offsets do not take a dip from the parameters of
    /// vertices rounded far away (two nearly parallel lines meet 1e15 times
    /// the extent out, where an ulp of the vertices exceeds the whole width
    /// of a narrow parabola).
    apex_may_be_inside: bool,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Curve {
    /// `origin + τ unit`; a finite piece also from its far end, `far − (to
    /// − τ) unit`, so that points and roots near either end are computed
    /// from that end (a vertex far away would otherwise cost the digits of
    /// a near one).
    Straight { origin: Point, unit: Point, far: Option<Point>, gauge: Gauge },
    /// The parabola at directrix parameter `sign × τ`.
    Parabolic { parabola: Parabola, sign: f64 },
}

/// What a straight edge measures its distance from.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Gauge {
    Point(Point),
    /// The line through a point with this unit normal.
    Line(Point, Point),
}

impl Gauge {
    /// Where the distance is lowest along `origin + τ unit`.
    fn lowest(self, origin: Point, unit: Point) -> f64 {
        match self {
            Gauge::Point(c) => -((origin.x - c.x) * unit.x + (origin.y - c.y) * unit.y),
            Gauge::Line(a, n) => {
                let (g0, g1) = line_gauge(origin, unit, a, n);
                -g0 / g1
            }
        }
    }

    /// The parameters along `origin + τ unit` at distance `r`.
    fn roots(self, origin: Point, unit: Point, r: f64) -> Option<(f64, f64)> {
        match self {
            Gauge::Point(c) => {
                let (wx, wy) = (origin.x - c.x, origin.y - c.y);
                let foot = -(wx * unit.x + wy * unit.y);
                let height = (unit.x * wy - unit.y * wx).abs();
                (r >= height).then(|| {
                    let half = ((r - height) * (r + height)).sqrt();
                    (foot - half, foot + half)
                })
            }
            Gauge::Line(a, n) => {
                let (g0, g1) = line_gauge(origin, unit, a, n);
                let (t1, t2) = ((r - g0) / g1, (-r - g0) / g1);
                (g1 != 0.0 && t1.is_finite() && t2.is_finite()).then(|| (t1.min(t2), t1.max(t2)))
            }
        }
    }

    fn distance(self, q: Point) -> f64 {
        match self {
            Gauge::Point(c) => q.distance(c),
            Gauge::Line(a, n) => ((q.x - a.x) * n.x + (q.y - a.y) * n.y).abs(),
        }
    }

    fn is_finite(self) -> bool {
        match self {
            Gauge::Point(c) => c.is_finite(),
            Gauge::Line(a, n) => a.is_finite() && n.is_finite(),
        }
    }
}

impl EdgeTrack {
    /// The track of the edge between `sites` from `start` to `end`; `None`
    /// when there is none to follow (a whole line between two segments, or
    /// numbers that are not finite).
    pub(crate) fn new(sites: [&Site; 2], start: TrackEnd, end: TrackEnd) -> Option<EdgeTrack> {
        if let (Some(parabola), TrackEnd::At(p), TrackEnd::At(q)) = (Parabola::of_sites(sites[0], sites[1]), start, end) {
            let (s0, s1) = (parabola.parameter(p), parabola.parameter(q));
            let sign = if s1 >= s0 { 1.0 } else { -1.0 };
            let apex_may_be_inside =
                focus_and_directrix(sites[0], sites[1]).is_some_and(|(focus, a, b)| foot_strictly_inside(a, b, focus));
            return finite(EdgeTrack {
                curve: Curve::Parabolic { parabola, sign },
                from: sign * s0,
                to: sign * s1,
                apex_may_be_inside,
            });
        }
        let gauge = match nearest_point_site(sites) {
            Some(centre) => Gauge::Point(centre),
            None => {
                let Site::Segment { a, b } = *sites[0] else { return None };
                let length = a.distance(b);
                Gauge::Line(a, Point::new(-(b.y - a.y) / length, (b.x - a.x) / length))
            }
        };
        let apex_may_be_inside = matches!(gauge, Gauge::Point(_));
        if let Some((origin, unit)) = line_of_sites(sites) {
            return finite(EdgeTrack { apex_may_be_inside, ..EdgeTrack::along_line(origin, unit, start, end, gauge) });
        }
        let (origin, unit, far, from, to) = match (start, end) {
            (TrackEnd::At(p), TrackEnd::At(q)) => {
                let length = p.distance(q);
                let unit =
                    if length > 0.0 { Point::new((q.x - p.x) / length, (q.y - p.y) / length) } else { Point::new(1.0, 0.0) };
                (p, unit, Some(q), 0.0, length)
            }
            (TrackEnd::At(p), TrackEnd::Towards(u)) => (p, u, None, 0.0, f64::INFINITY),
            (TrackEnd::Towards(u), TrackEnd::At(q)) => (q, Point::new(-u.x, -u.y), None, f64::NEG_INFINITY, 0.0),
            (TrackEnd::Towards(_), TrackEnd::Towards(_)) => return None,
        };
        finite(EdgeTrack { curve: Curve::Straight { origin, unit, far, gauge }, from, to, apex_may_be_inside })
    }

    /// A straight edge on the line `origin + τ unit` known from its sites
    /// (its lowest point there): the parameter runs along it in the edge's
    /// direction, its ends the projections of the vertices.
    fn along_line(origin: Point, unit: Point, start: TrackEnd, end: TrackEnd, gauge: Gauge) -> EdgeTrack {
        let travel = match (start, end) {
            (TrackEnd::At(p), TrackEnd::At(q)) => Point::new(q.x - p.x, q.y - p.y),
            (_, TrackEnd::Towards(u)) => u,
            (TrackEnd::Towards(u), _) => Point::new(-u.x, -u.y),
        };
        let unit = if travel.x * unit.x + travel.y * unit.y < 0.0 { Point::new(-unit.x, -unit.y) } else { unit };
        let at = |p: Point| (p.x - origin.x) * unit.x + (p.y - origin.y) * unit.y;
        let from = match start {
            TrackEnd::At(p) => at(p),
            TrackEnd::Towards(_) => f64::NEG_INFINITY,
        };
        let to = match end {
            TrackEnd::At(q) => at(q).max(from),
            TrackEnd::Towards(_) => f64::INFINITY,
        };
        EdgeTrack { curve: Curve::Straight { origin, unit, far: None, gauge }, from, to, apex_may_be_inside: true }
    }

    /// The point at parameter `τ`.
    pub(crate) fn point(&self, t: f64) -> Point {
        match self.curve {
            Curve::Straight { origin, unit, far, .. } => match far {
                Some(q) if t > self.to / 2.0 => Point::new(q.x - (self.to - t) * unit.x, q.y - (self.to - t) * unit.y),
                _ => Point::new(origin.x + t * unit.x, origin.y + t * unit.y),
            },
            Curve::Parabolic { parabola, sign } => parabola.point(sign * t),
        }
    }

    /// The point at parameter `τ` where the distance is `r` (a root): on a
    /// parabola placed at height `r` over the directrix rather than at the
    /// height its parameter gives, which a narrow parabola (a focus nearly
    /// on the line) would magnify from the rounding of the parameter.
    pub(crate) fn point_at_distance(&self, t: f64, r: f64) -> Point {
        match self.curve {
            Curve::Parabolic { parabola, sign } => parabola.point_at_height(sign * t, r),
            Curve::Straight { .. } => self.point(t),
        }
    }

    /// The distance from the edge's sites at parameter `τ`.
    pub(crate) fn distance(&self, t: f64) -> f64 {
        match self.curve {
            Curve::Straight { gauge, .. } => gauge.distance(self.point(t)),
            Curve::Parabolic { parabola, sign } => {
                let (s, p) = (sign * t, parabola.focal_distance());
                (s * s + p * p) / (2.0 * p)
            }
        }
    }

    /// Where the distance is lowest on the whole curve (not clamped to the
    /// edge); NaN where it is constant.
    pub(crate) fn lowest(&self) -> f64 {
        match self.curve {
            Curve::Straight { origin, unit, far, gauge } => {
                let t = gauge.lowest(origin, unit);
                match far {
                    // past the middle (or NaN): from the far end
                    Some(q) if t > self.to / 2.0 || t.is_nan() => self.to + gauge.lowest(q, unit),
                    _ => t,
                }
            }
            Curve::Parabolic { .. } => 0.0,
        }
    }

    /// The lowest distance strictly inside the edge, if the lowest point
    /// of the curve lies there (and can: see `apex_may_be_inside`).
    pub(crate) fn interior_minimum(&self) -> Option<f64> {
        let t = self.lowest();
        (self.apex_may_be_inside && t > self.from && t < self.to).then(|| self.distance(t))
    }

    /// The two parameters (falling, rising: `lo <= hi`) where the distance
    /// equals `r` on the whole curve; `None` where it never does (or is
    /// constant).
    pub(crate) fn roots(&self, r: f64) -> Option<(f64, f64)> {
        match self.curve {
            Curve::Straight { origin, unit, far, gauge } => {
                let near = gauge.roots(origin, unit, r);
                let Some(q) = far else { return near };
                let from_far = gauge.roots(q, unit, r).map(|(lo, hi)| (self.to + lo, self.to + hi));
                let half = self.to / 2.0;
                match (near, from_far) {
                    (Some((lo, hi)), Some((flo, fhi))) => {
                        Some((if lo <= half { lo } else { flo }, if hi <= half { hi } else { fhi }))
                    }
                    (one, other) => one.or(other),
                }
            }
            Curve::Parabolic { parabola, .. } => {
                let p = parabola.focal_distance();
                let square = p * (2.0 * r - p);
                (square >= 0.0).then(|| {
                    let s = square.sqrt();
                    (-s, s)
                })
            }
        }
    }

    /// `τ` clamped to the edge.
    pub(crate) fn clamp(&self, t: f64) -> f64 {
        if t.is_nan() {
            return if self.from.is_finite() { self.from } else { self.to };
        }
        t.clamp(self.from, self.to)
    }
}

/// The signed distance from the line at the origin and its rate along
/// `unit`.
fn line_gauge(origin: Point, unit: Point, on_line: Point, normal: Point) -> (f64, f64) {
    ((origin.x - on_line.x) * normal.x + (origin.y - on_line.y) * normal.y, unit.x * normal.x + unit.y * normal.y)
}

/// The point site a straight edge measures its distance from: either site
/// when both are points, the endpoint beside its own segment; `None` for
/// two segments. (A point and a segment not ending at it make a parabola,
/// unless the point is on the segment's line; then the point again.)
fn nearest_point_site(sites: [&Site; 2]) -> Option<Point> {
    sites.iter().find_map(|s| s.as_point())
}

/// The line of a straight edge from its sites alone, through its lowest
/// point: the perpendicular bisector of two points (through their
/// midpoint), the perpendicular of a segment through a point on its line
/// (its own endpoint), the bisector of two segments at their shared
/// endpoint. Exact up to rounding wherever the vertices are, so the
/// crossings near the lowest point do not inherit the rounding of
/// vertices far away. `None` for two segments that share no endpoint.
fn line_of_sites(sites: [&Site; 2]) -> Option<(Point, Point)> {
    let unit = |x: f64, y: f64| {
        let n = x.hypot(y);
        (n > 0.0 && n.is_finite()).then(|| Point::new(x / n, y / n))
    };
    match (*sites[0], *sites[1]) {
        (Site::Point(p), Site::Point(q)) => {
            Some((Point::new(p.x + (q.x - p.x) / 2.0, p.y + (q.y - p.y) / 2.0), unit(-(q.y - p.y), q.x - p.x)?))
        }
        (Site::Point(p), Site::Segment { a, b }) | (Site::Segment { a, b }, Site::Point(p)) => {
            Some((p, unit(-(b.y - a.y), b.x - a.x)?))
        }
        (Site::Segment { a, b }, Site::Segment { a: c, b: e }) => {
            let corner = [a, b].into_iter().find(|&x| x == c || x == e)?;
            let away = |s: Point, t: Point| if s == corner { t } else { s };
            let (u, v) = (away(a, b), away(c, e));
            let (u, v) = (unit(u.x - corner.x, u.y - corner.y)?, unit(v.x - corner.x, v.y - corner.y)?);
            // the bisector of the angle below 180°; straight on: the perpendicular
            let line = unit(u.x + v.x, u.y + v.y).filter(|_| u.x * v.x + u.y * v.y > -1.0 + 1e-12).or(unit(-u.y, u.x))?;
            Some((corner, line))
        }
        // a conic bisector: no line
        _ => None,
    }
}

fn finite(track: EdgeTrack) -> Option<EdgeTrack> {
    let ok = match track.curve {
        Curve::Straight { origin, unit, far, gauge } => {
            origin.is_finite() && unit.is_finite() && far.map_or(true, |q| q.is_finite()) && gauge.is_finite()
        }
        Curve::Parabolic { .. } => true,
    };
    (ok && !track.from.is_nan() && !track.to.is_nan() && track.from <= track.to).then_some(track)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn two_points_bisector_crosses_a_level_twice() {
        let (a, b) = (Site::Point(p(0.0, 0.0)), Site::Point(p(2.0, 0.0)));
        let track = EdgeTrack::new([&a, &b], TrackEnd::At(p(1.0, -5.0)), TrackEnd::At(p(1.0, 5.0))).unwrap();
        assert_eq!(track.interior_minimum(), Some(1.0));
        let (lo, hi) = track.roots(2.0_f64.sqrt()).unwrap();
        assert!((track.point(lo).y + 1.0).abs() < 1e-12 && (track.point(hi).y - 1.0).abs() < 1e-12);
    }

    #[test]
    fn parabola_levels_are_at_the_focus_distance() {
        let f = Site::Point(p(0.0, 2.0));
        let s = Site::Segment { a: p(-10.0, 0.0), b: p(10.0, 0.0) };
        // y = (x² + 4) / 4 from x = 3 back to x = -3
        let (start, end) = (p(3.0, 13.0 / 4.0), p(-3.0, 13.0 / 4.0));
        let track = EdgeTrack::new([&s, &f], TrackEnd::At(start), TrackEnd::At(end)).unwrap();
        assert_eq!(track.interior_minimum(), Some(1.0));
        let (lo, hi) = track.roots(2.0).unwrap();
        for t in [lo, hi] {
            let q = track.point(t);
            assert!((q.distance(p(0.0, 2.0)) - 2.0).abs() < 1e-12 && (q.y - 2.0).abs() < 1e-12, "{q:?}");
        }
        assert!(track.point(lo).x > 0.0, "falls first, walking from x = 3");
    }

    #[test]
    fn two_segments_are_linear_and_rays_are_half_open() {
        let s = Site::Segment { a: p(0.0, 0.0), b: p(10.0, 0.0) };
        let t = Site::Segment { a: p(0.0, 0.0), b: p(0.0, 10.0) };
        let track = EdgeTrack::new([&s, &t], TrackEnd::At(p(0.0, 0.0)), TrackEnd::Towards(p(0.6, 0.8).scaled(1.0))).unwrap();
        assert_eq!((track.from, track.to), (0.0, f64::INFINITY));
        assert_eq!(track.interior_minimum(), None);
        let (_, hi) = track.roots(0.8).unwrap();
        assert!((track.point(hi).y - 0.8).abs() < 1e-12);
    }
}
