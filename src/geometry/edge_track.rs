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

use super::parabola::Parabola;
use super::point::Point;
use super::site::Site;

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
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Curve {
    /// `origin + τ unit`, measured from the point `centre`.
    FromPoint { origin: Point, unit: Point, centre: Point },
    /// `origin + τ unit`, measured from the line through `on_line` with
    /// unit normal `normal`.
    FromLine { origin: Point, unit: Point, on_line: Point, normal: Point },
    /// The parabola at directrix parameter `sign × τ`.
    Parabolic { parabola: Parabola, sign: f64 },
}

impl EdgeTrack {
    /// The track of the edge between `sites` from `start` to `end`; `None`
    /// when there is none to follow (a whole line between two segments, or
    /// numbers that are not finite).
    pub(crate) fn new(sites: [&Site; 2], start: TrackEnd, end: TrackEnd) -> Option<EdgeTrack> {
        if let (Some(parabola), TrackEnd::At(p), TrackEnd::At(q)) = (Parabola::of_sites(sites[0], sites[1]), start, end) {
            let (s0, s1) = (parabola.parameter(p), parabola.parameter(q));
            let sign = if s1 >= s0 { 1.0 } else { -1.0 };
            return finite(EdgeTrack { curve: Curve::Parabolic { parabola, sign }, from: sign * s0, to: sign * s1 });
        }
        let (origin, unit, from, to) = match (start, end) {
            (TrackEnd::At(p), TrackEnd::At(q)) => {
                let length = p.distance(q);
                let unit =
                    if length > 0.0 { Point::new((q.x - p.x) / length, (q.y - p.y) / length) } else { Point::new(1.0, 0.0) };
                (p, unit, 0.0, length)
            }
            (TrackEnd::At(p), TrackEnd::Towards(u)) => (p, u, 0.0, f64::INFINITY),
            (TrackEnd::Towards(u), TrackEnd::At(q)) => (q, Point::new(-u.x, -u.y), f64::NEG_INFINITY, 0.0),
            (TrackEnd::Towards(_), TrackEnd::Towards(u)) => (lowest_point(sites)?, u, f64::NEG_INFINITY, f64::INFINITY),
        };
        let curve = match nearest_point_site(sites) {
            Some(centre) => Curve::FromPoint { origin, unit, centre },
            None => {
                let Site::Segment { a, b } = *sites[0] else { return None };
                let length = a.distance(b);
                let normal = Point::new(-(b.y - a.y) / length, (b.x - a.x) / length);
                Curve::FromLine { origin, unit, on_line: a, normal }
            }
        };
        finite(EdgeTrack { curve, from, to })
    }

    /// The point at parameter `τ`.
    pub(crate) fn point(&self, t: f64) -> Point {
        match self.curve {
            Curve::FromPoint { origin, unit, .. } | Curve::FromLine { origin, unit, .. } => {
                Point::new(origin.x + t * unit.x, origin.y + t * unit.y)
            }
            Curve::Parabolic { parabola, sign } => parabola.point(sign * t),
        }
    }

    /// The distance from the edge's sites at parameter `τ`.
    pub(crate) fn distance(&self, t: f64) -> f64 {
        match self.curve {
            Curve::FromPoint { centre, .. } => self.point(t).distance(centre),
            Curve::FromLine { on_line, normal, .. } => {
                let q = self.point(t);
                ((q.x - on_line.x) * normal.x + (q.y - on_line.y) * normal.y).abs()
            }
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
            Curve::FromPoint { origin, unit, centre } => -((origin.x - centre.x) * unit.x + (origin.y - centre.y) * unit.y),
            Curve::FromLine { origin, unit, on_line, normal } => {
                let (g0, g1) = line_gauge(origin, unit, on_line, normal);
                -g0 / g1
            }
            Curve::Parabolic { .. } => 0.0,
        }
    }

    /// The lowest distance strictly inside the edge, if the lowest point
    /// of the curve lies there.
    pub(crate) fn interior_minimum(&self) -> Option<f64> {
        let t = self.lowest();
        (t > self.from && t < self.to).then(|| self.distance(t))
    }

    /// The two parameters (falling, rising: `lo <= hi`) where the distance
    /// equals `r` on the whole curve; `None` where it never does (or is
    /// constant).
    pub(crate) fn roots(&self, r: f64) -> Option<(f64, f64)> {
        match self.curve {
            Curve::FromPoint { origin, unit, centre } => {
                let (wx, wy) = (origin.x - centre.x, origin.y - centre.y);
                let foot = -(wx * unit.x + wy * unit.y);
                let height = (unit.x * wy - unit.y * wx).abs();
                (r >= height).then(|| {
                    let half = ((r - height) * (r + height)).sqrt();
                    (foot - half, foot + half)
                })
            }
            Curve::FromLine { origin, unit, on_line, normal } => {
                let (g0, g1) = line_gauge(origin, unit, on_line, normal);
                let (t1, t2) = ((r - g0) / g1, (-r - g0) / g1);
                (g1 != 0.0 && t1.is_finite() && t2.is_finite()).then(|| (t1.min(t2), t1.max(t2)))
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

/// The lowest point of a whole line edge (both ends at infinity, when all
/// sites are collinear): the midpoint of two points, or the endpoint a
/// separator passes through.
fn lowest_point(sites: [&Site; 2]) -> Option<Point> {
    match (*sites[0], *sites[1]) {
        (Site::Point(p), Site::Point(q)) => Some(Point::new(p.x + (q.x - p.x) / 2.0, p.y + (q.y - p.y) / 2.0)),
        (Site::Point(p), Site::Segment { .. }) | (Site::Segment { .. }, Site::Point(p)) => Some(p),
        _ => None,
    }
}

fn finite(track: EdgeTrack) -> Option<EdgeTrack> {
    let ok = match track.curve {
        Curve::FromPoint { origin, unit, centre } => origin.is_finite() && unit.is_finite() && centre.is_finite(),
        Curve::FromLine { origin, unit, on_line, normal } => {
            origin.is_finite() && unit.is_finite() && on_line.is_finite() && normal.is_finite()
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
