//! The clearance along an edge beside a circular arc (a conic), for the
//! offsets.
//!
//! Along a line or a parabola the clearance is quasi-convex, and
//! `EdgeTrack` knows its lowest point in closed form. Along a conic beside
//! an arc it need not be: an ellipse around a point on an arc's concave
//! side has its clearance highest where the empty circle touches the point
//! and the arc at opposite ends of a diameter, which is a local maximum of
//! the distance to the sites inside the edge, with no vertex there. So the
//! edge is cut into pieces along which the clearance is monotone (found by
//! sampling and refined by golden-section search), each piece crossing a
//! level at most once; a crossing is found by bisection on the edge's
//! parameter to the precision of `f64`.
//!
//! The parameter is the angle around the arc's centre. An edge beside an
//! arc lies in the arc's cone and on one side of its circle, and a ray from
//! the centre meets it at most once: along the ray, the distance to the
//! arc changes at rate 1 and the distance to any other site at rate at
//! most 1, so their difference is monotone on each side of the circle.
//! The point at an angle is found by bisection along its ray; a chord's
//! perpendicular (what the drawings use) would not do for an edge that
//! turns by more than half a turn (the ellipse around a point in a nearly
//! closed arc).

use crate::geometry::{CircularArc, Point, Site};

/// The widest turn around the arc's centre between an edge's ends that
/// the angle is not asked to resolve: such an edge is found across the ray
/// to its farther end instead (`narrow_ray`).
const NARROW: f64 = 1e-9;

/// Samples of the clearance along an edge, to find where it turns.
const SAMPLES: usize = 48;

/// Clearance changes within this fraction of the edge's size count as
/// flat: a constant clearance (the circle halfway between an arc and a
/// point at its centre) must not turn on rounding.
const FLAT: f64 = 1e-11;

/// A point where the clearance along a conic edge turns.
#[derive(Clone, Copy, Debug)]
pub(super) struct Knot {
    /// The edge's parameter (0 at its first end, 1 at its second).
    pub(super) t: f64,
    /// The clearance there (internal units).
    pub(super) value: f64,
    /// Whether it is a local maximum (a region above a level can hold it
    /// and no vertex).
    pub(super) peak: bool,
}

/// An edge beside an arc as a track for the offsets (see the module doc).
/// Internal coordinates.
#[derive(Clone, Debug)]
pub(super) struct ConicTrack {
    /// The arc whose centre the parameter turns around, and the edge's
    /// other site.
    arc: CircularArc,
    other: Site,
    /// Whether the edge lies outside the arc's circle.
    convex: bool,
    /// The angle of the arc's start around its centre, and `+1` for a
    /// counter-clockwise arc, `-1` for a clockwise one.
    start_angle: f64,
    turn: f64,
    /// The angles of the edge's ends from the arc's start, along the arc
    /// (within its sweep).
    along: [f64; 2],
    /// The vertices at the ends; `None` at infinity.
    ends: [Option<Point>; 2],
    /// For an edge along a ray from the centre, or nearly (the other site
    /// continues the arc tangentially at a shared endpoint, or within a
    /// microradian of it: every point of that ray is equally far from
    /// both, or the edge stays beside it), the ray's unit direction and
    /// the distances of the ends from the centre along it (infinite at
    /// infinity). The angle hardly moves along such an edge, the distance
    /// from the centre does: the edge's point at a distance is found
    /// across the ray (`across_ray`).
    radial: Option<(Point, [f64; 2])>,
    /// For the edge between two arcs of one circle (to rounding) from one
    /// of their joins to the other: the two rays from the centre to those
    /// joins. Every point inside the circle is nearest the arc its
    /// direction falls in, so the edge runs in from one join to the centre
    /// and out to the other; no vertex is at the centre, where only these
    /// two sites are, and neither the angle (constant along each ray) nor
    /// one ray describes it. The first half of `t` runs in, the second
    /// out.
    bent: Option<[Point; 2]>,
    /// Where the clearance turns strictly inside the edge, by `t`.
    pub(super) knots: Vec<Knot>,
}

/// One end of a conic edge: a vertex, or infinity in a direction.
#[derive(Clone, Copy, Debug)]
pub(super) enum ConicEnd {
    At(Point),
    Towards(Point),
}

impl ConicTrack {
    /// The track of the edge between `sites` (one at least an arc) from
    /// `start` to `end` (either or both at infinity: the bisector of two
    /// arcs facing each other is a whole line or hyperbola branch). `None`
    /// without an arc, or for numbers that are not finite.
    pub(super) fn new(sites: [Site; 2], start: ConicEnd, end: ConicEnd) -> Option<ConicTrack> {
        let (arc, other) = match sites {
            [Site::Arc(arc), other] | [other, Site::Arc(arc)] => (arc, other),
            _ => return None,
        };
        let c = arc.centre();
        let position = |e: ConicEnd| match e {
            ConicEnd::At(p) => Some(p),
            ConicEnd::Towards(_) => None,
        };
        let ends = [position(start), position(end)];
        // the side of the circle: from the end farther from it; an edge to
        // infinity is outside
        let convex = match ends {
            [Some(p), Some(q)] => {
                let off = |v: Point| c.distance(v) - arc.radius();
                if off(p).abs().max(off(q).abs()) <= 1e-9 * arc.radius() {
                    // both ends on the circle (an edge between an arc and
                    // its chord, or two arcs meeting at both ends): their
                    // sides are rounding; the edge lies on the other
                    // site's side, beside the arc halfway between them
                    // (along the arc: the middle of the ends' chord may lie
                    // across the centre)
                    let (start, turn) =
                        ((arc.start().y - c.y).atan2(arc.start().x - c.x), if arc.is_counter_clockwise() { 1.0 } else { -1.0 });
                    let along = |v: Point| angle_along(&arc, start, turn, v);
                    let angle = start + turn * (along(p) + along(q)) / 2.0;
                    let between = Point::new(c.x + arc.radius() * angle.cos(), c.y + arc.radius() * angle.sin());
                    off(other.nearest_point(between)) > 0.0
                } else if off(p).abs() >= off(q).abs() {
                    off(p) > 0.0
                } else {
                    off(q) > 0.0
                }
            }
            // an edge to infinity (at one end or both) is outside
            _ => true,
        };
        let start_angle = (arc.start().y - c.y).atan2(arc.start().x - c.x);
        let turn = if arc.is_counter_clockwise() { 1.0 } else { -1.0 };
        // the direction from the centre to the edge's farthest end
        let toward = match (start, end) {
            (ConicEnd::Towards(u), _) | (_, ConicEnd::Towards(u)) => u,
            (ConicEnd::At(p), ConicEnd::At(q)) => {
                let far = if c.distance(p) >= c.distance(q) { p } else { q };
                Point::new(far.x - c.x, far.y - c.y)
            }
        };
        let radial = tangent_join(&arc, &other, toward).map(|u| {
            let rho = |e: Option<Point>| e.map_or(f64::INFINITY, |v| (v.x - c.x) * u.x + (v.y - c.y) * u.y);
            (u, [rho(ends[0]), rho(ends[1])])
        });
        let bent = match (other, ends) {
            (Site::Arc(second), [Some(p), Some(q)]) if second.has_circle(c, arc.radius()) => {
                let ray = |v: Point| {
                    let (dx, dy) = (v.x - c.x, v.y - c.y);
                    let length = dx.hypot(dy);
                    (length > 0.5 * arc.radius()).then(|| Point::new(dx / length, dy / length))
                };
                // both ends at joins on the circle, on two rays that are
                // not one line (a diameter is `radial`'s)
                let on_circle = |v: Point| (c.distance(v) - arc.radius()).abs() <= 1e-9 * arc.radius();
                match (ray(p), ray(q)) {
                    (Some(u), Some(w)) if on_circle(p) && on_circle(q) && (u.x * w.y - u.y * w.x).abs() > 1e-6 => Some([u, w]),
                    _ => None,
                }
            }
            _ => None,
        };
        let radial = if bent.is_some() { None } else { radial };
        let mut track =
            ConicTrack { arc, other, convex, start_angle, turn, along: [0.0; 2], ends, radial, bent, knots: Vec::new() };
        // (a direction's own angle: the centre plus a unit step rounds back
        // to the centre where the centre is far larger than 1, as in the
        // internal coordinates of an input with coordinates near 1e-130)
        let direction = |e: ConicEnd| match e {
            ConicEnd::At(p) => track.along(p),
            ConicEnd::Towards(u) => angle_along_direction(&track.arc, track.start_angle, track.turn, u),
        };
        track.along = [direction(start), direction(end)];
        if !(c.is_finite() && arc.radius().is_finite() && track.along.iter().all(|a| a.is_finite())) {
            return None;
        }
        let narrow = (track.along[1] - track.along[0]).abs() <= NARROW;
        if track.radial.is_none() && track.bent.is_none() && (narrow || from_the_centre(c, arc.radius(), ends)) {
            track.radial = narrow_ray(c, [start, end]);
        }
        track.knots = track.find_knots();
        Some(track)
    }

    /// The angle of `q` around the arc's centre from the arc's start,
    /// along the arc, clamped to its sweep (the edge lies in the arc's
    /// cone; a vertex on its boundary may round out of it).
    fn along(&self, q: Point) -> f64 {
        angle_along(&self.arc, self.start_angle, self.turn, q)
    }

    /// The point of the edge at parameter `t` (0 and 1: its ends); `None`
    /// where the ray meets no point of the edge (toward an end at
    /// infinity).
    pub(super) fn point(&self, t: f64) -> Option<Point> {
        if t <= 0.0 || t >= 1.0 {
            if let Some(v) = self.ends[usize::from(t >= 1.0)] {
                return Some(v);
            }
        }
        if let Some([u, w]) = self.bent {
            let (c, radius) = (self.arc.centre(), self.arc.radius());
            let (ray, rho) = if t <= 0.5 { (u, radius * (1.0 - 2.0 * t)) } else { (w, radius * (2.0 * t - 1.0)) };
            return Some(Point::new(c.x + rho * ray.x, c.y + rho * ray.y));
        }
        if let Some((u, [r0, r1])) = self.radial {
            // an end at infinity: the distance grows without bound toward it
            let rho = match (r0.is_finite(), r1.is_finite()) {
                // Ends far apart in distance (a vertex 1e15 out along a
                // tangent join's ray, the other at the join): geometric,
                // so that `t` resolves the distance relatively at both
                // ends. Linear, `t`'s ulp near 1 was 0.125 of distance
                // there, and an offset 1 from the join ended 0.75 from it
                // (LibreCAD's tp3).
                (true, true) if r0 > 0.0 && r1 > 0.0 && (r0 > 4.0 * r1 || r1 > 4.0 * r0) => r0 * (r1 / r0).powf(t),
                (true, true) => r0 + t * (r1 - r0),
                (true, false) => r0 + t / (1.0 - t) * self.arc.radius(),
                (false, true) => r1 + (1.0 - t) / t * self.arc.radius(),
                (false, false) => return None,
            };
            return Some(self.across_ray(u, rho));
        }
        let [a0, a1] = self.along;
        let angle = self.start_angle + self.turn * (a0 + t * (a1 - a0));
        let u = Point::new(angle.cos(), angle.sin());
        let rho = self.radius_along(u)?;
        let c = self.arc.centre();
        Some(Point::new(c.x + rho * u.x, c.y + rho * u.y))
    }

    /// The point of a (nearly) radial edge on the line across the ray `u`
    /// at `rho` from the centre: where the distances to the two sites
    /// cross, by bisection from a bracket widened from the ray outward
    /// (on the ray itself for an exact tangent join).
    fn across_ray(&self, u: Point, rho: f64) -> Point {
        let c = self.arc.centre();
        let at = |s: f64| Point::new(c.x + rho * u.x - s * u.y, c.y + rho * u.y + s * u.x);
        let nearer_arc = |s: f64| {
            let p = at(s);
            self.arc.distance(p) < self.other.distance(p)
        };
        // on the ray itself to rounding (an exact tangent join, or one a
        // few ulps off: most of them), no search: this is asked for every
        // sample of the edge's clearance
        let on_ray = at(0.0);
        let size = self.arc.radius() + rho.abs();
        if (self.arc.distance(on_ray) - self.other.distance(on_ray)).abs() <= 16.0 * f64::EPSILON * size {
            return on_ray;
        }
        let mut step = f64::EPSILON * size;
        while step < 2.0 * self.arc.radius() {
            let (lo, hi) = (nearer_arc(-step), nearer_arc(step));
            if lo != hi {
                let (mut a, mut b) = (-step, step);
                for _ in 0..200 {
                    let mid = 0.5 * (a + b);
                    if mid <= a || mid >= b {
                        break;
                    }
                    if nearer_arc(mid) == lo {
                        a = mid;
                    } else {
                        b = mid;
                    }
                }
                return at(0.5 * (a + b));
            }
            step *= 2.0;
        }
        at(0.0)
    }

    /// How far from the centre the ray in direction `u` meets the edge: by
    /// bisection on the difference of the distances to the two sites,
    /// monotone along the ray on the edge's side of the circle.
    fn radius_along(&self, u: Point) -> Option<f64> {
        let (c, radius) = (self.arc.centre(), self.arc.radius());
        let at = |rho: f64| Point::new(c.x + rho * u.x, c.y + rho * u.y);
        // positive beyond the edge (away from the circle)
        let beyond = |rho: f64| (rho - radius).abs() - self.other.distance(at(rho));
        let (mut near, mut far) = if self.convex {
            let mut step = radius;
            let mut far = radius + step;
            let mut found = false;
            for _ in 0..2100 {
                if beyond(far) > 0.0 {
                    found = true;
                    break;
                }
                step *= 2.0;
                far = radius + step;
                if !far.is_finite() {
                    break;
                }
            }
            if !found {
                return None;
            }
            (radius, far)
        } else {
            if beyond(0.0) <= 0.0 {
                return Some(0.0);
            }
            (radius, 0.0)
        };
        // A difference within the rounding of its terms is taken as beyond:
        // where the two distances tie along a stretch of the ray to
        // rounding, the edge is the end of it nearest the circle (between
        // an arc and its chord a rounding apart, split off a tangency, the
        // difference is the sagitta, 1e-15, everywhere below the chord, and
        // its sign noise sent the edge 1 below it: LibreCAD's mik2).
        // (the rounding of the distances themselves; the centre's distance
        // from the origin is left out, so that far out the threshold does
        // not move the edge by more than its own rounding)
        let noise = |rho: f64| 8.0 * f64::EPSILON * (radius + rho.abs());
        for _ in 0..200 {
            let mid = 0.5 * (near + far);
            if mid == near || mid == far {
                break;
            }
            if beyond(mid) > -noise(mid) {
                far = mid;
            } else {
                near = mid;
            }
        }
        Some(0.5 * (near + far))
    }

    /// `p`, a crossing of `level` found along the track, moved onto both
    /// sites' offset curves where they meet (`level_point::onto_level`).
    pub(super) fn onto_level(&self, p: Point, level: f64) -> Point {
        super::level_point::onto_level(&self.arc, &self.other, p, level)
    }

    /// The clearance at parameter `t` (internal units): the distance to
    /// the arc; infinite where the edge has gone to infinity.
    pub(super) fn clearance(&self, t: f64) -> f64 {
        match self.point(t) {
            Some(q) => self.arc.distance(q),
            None => f64::INFINITY,
        }
    }

    /// The local extrema of the clearance strictly inside the edge.
    fn find_knots(&self) -> Vec<Knot> {
        let ts: Vec<f64> = (0..=SAMPLES).map(|k| k as f64 / SAMPLES as f64).collect();
        let gs: Vec<f64> = ts.iter().map(|&t| self.clearance(t)).collect();
        // flat: relative to the values compared (an edge to infinity
        // reaches far larger ones)
        let flat = |a: f64, b: f64| (a - b).abs() <= FLAT * (a.abs() + b.abs() + self.arc.radius());
        // the steps that are not flat, with their direction (toward an end
        // at infinity: rising); where the direction changes, the extremum
        // lies among the samples between
        let steps: Vec<(usize, bool)> = (1..gs.len())
            .filter(|&k| !(gs[k] - gs[k - 1]).is_finite() || !flat(gs[k], gs[k - 1]))
            .map(|k| (k, gs[k] > gs[k - 1] || (gs[k].is_infinite() && gs[k - 1].is_finite())))
            .collect();
        let mut knots = Vec::new();
        for pair in steps.windows(2) {
            let ((before, was), (after, rising)) = (pair[0], pair[1]);
            if was != rising {
                let peak = was;
                let centre = extreme_sample(&gs, before - 1, after, peak);
                knots.push(self.refine(&ts, centre, peak));
            }
        }
        // a refinement may leave the order of close extrema: keep them by t
        knots.sort_by(|a, b| a.t.total_cmp(&b.t));
        knots
    }

    /// The extremum near sample `k` (a maximum if `peak`), by
    /// golden-section search over the samples either side.
    fn refine(&self, ts: &[f64], k: usize, peak: bool) -> Knot {
        let (mut lo, mut hi) = (ts[k.saturating_sub(1)], ts[(k + 1).min(ts.len() - 1)]);
        let better = |a: f64, b: f64| if peak { a > b } else { a < b };
        let ratio = 0.5 * (5f64.sqrt() - 1.0);
        let (mut x1, mut x2) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
        let (mut g1, mut g2) = (self.clearance(x1), self.clearance(x2));
        for _ in 0..60 {
            if better(g1, g2) {
                hi = x2;
                x2 = x1;
                g2 = g1;
                x1 = hi - ratio * (hi - lo);
                g1 = self.clearance(x1);
            } else {
                lo = x1;
                x1 = x2;
                g1 = g2;
                x2 = lo + ratio * (hi - lo);
                g2 = self.clearance(x2);
            }
        }
        let t = 0.5 * (lo + hi);
        // never at the ends: those are vertices
        let t = t.clamp(f64::EPSILON, 1.0 - f64::EPSILON);
        Knot { t, value: self.clearance(t), peak }
    }

    /// The parameter in `[a, b]` where the clearance, monotone there,
    /// equals `level`, by bisection (to the precision of `f64`), given
    /// whether it is below the level at `a` (the band's classification of
    /// that end, which recomputing the clearance there may contradict by
    /// rounding: the root is then at `a`); an end when it does not cross.
    pub(super) fn root(&self, a: f64, b: f64, level: f64, below_at_a: bool) -> f64 {
        let (mut lo, mut hi) = (a, b);
        let below_at_lo = below_at_a;
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if (self.clearance(mid) < level) == below_at_lo {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }
}

/// The angle of `q` around the centre of `arc` from its start (at angle
/// `start_angle`), the way it turns (`turn`, ±1), clamped to its sweep
/// (an end a rounding outside it is at the nearer end, not a turn away).
fn angle_along(arc: &CircularArc, start_angle: f64, turn: f64, q: Point) -> f64 {
    let c = arc.centre();
    angle_along_direction(arc, start_angle, turn, Point::new(q.x - c.x, q.y - c.y))
}

/// [`angle_along`] of the direction `u` from the centre.
fn angle_along_direction(arc: &CircularArc, start_angle: f64, turn: f64, u: Point) -> f64 {
    let full = std::f64::consts::TAU;
    let angle = u.y.atan2(u.x);
    let along = (turn * (angle - start_angle)).rem_euclid(full);
    let sweep = arc.sweep().abs();
    if along <= sweep {
        along
    } else if along - sweep < full - along {
        sweep
    } else {
        0.0
    }
}

/// When `other` continues `arc` tangentially at an endpoint they share,
/// leaving it the other way (a segment along the arc's tangent there, or
/// an arc whose centre lies on the same line through that endpoint, e.g.
/// of the same circle), or
/// within 1e-4 rad of it (a join an ulp off straight, or a bulge written
/// with six digits, as DXF files have them: a kink of 2e-6), the unit
/// direction from the arc's centre through that endpoint: the edge
/// between them lies along that ray, or beside it, where the angle around
/// the centre cannot tell its points apart (its points are found across
/// the ray, `across_ray`).
///
/// Two arcs of one circle share both ends, and both joins qualify: the
/// one whose ray the edge lies along is taken, the nearer in angle to
/// `toward` (a direction from the centre to the edge's farthest end).
fn tangent_join(arc: &CircularArc, other: &Site, toward: Point) -> Option<Point> {
    let alignment = |u: &Point| u.x * toward.x + u.y * toward.y;
    [arc.start(), arc.end()]
        .into_iter()
        .filter_map(|e| tangent_join_at(arc, other, e))
        .max_by(|u, w| alignment(u).total_cmp(&alignment(w)))
}

/// `tangent_join` at one end `e` of `arc`.
fn tangent_join_at(arc: &CircularArc, other: &Site, e: Point) -> Option<Point> {
    let c = arc.centre();
    let shared = match *other {
        Site::Segment { a, b } => [a, b],
        Site::Arc(o) => [o.start(), o.end()],
        _ => return None,
    };
    if !shared.contains(&e) {
        return None;
    }
    let radial = Point::new(e.x - c.x, e.y - c.y);
    let length = radial.x.hypot(radial.y);
    // the other's direction at `e` that must be parallel to the radius
    // (a segment's normal, an arc's radius)
    let across = match *other {
        Site::Segment { a, b } => {
            let f = if a == e { b } else { a };
            Point::new(-(f.y - e.y), f.x - e.x)
        }
        Site::Arc(o) => Point::new(e.x - o.centre().x, e.y - o.centre().y),
        _ => return None,
    };
    let cross = radial.x * across.y - radial.y * across.x;
    let size = length * across.x.hypot(across.y);
    // continuing the arc: leaving `e` the other way (both leaving it the
    // same way, a cusp, as a circle touching a side at a segment's end,
    // the edge between them is a parabola, not the ray)
    let ahead = arc.tangent_into(e);
    let other_ahead = match *other {
        Site::Segment { a, b } => {
            let f = if a == e { b } else { a };
            Point::new(f.x - e.x, f.y - e.y)
        }
        Site::Arc(o) => o.tangent_into(e),
        _ => return None,
    };
    let continues = ahead.x * other_ahead.x + ahead.y * other_ahead.y < 0.0;
    (length > 0.0 && continues && cross.abs() <= 1e-4 * size).then(|| Point::new(radial.x / length, radial.y / length))
}

/// For an edge whose ends lie within [`NARROW`] of one ray from the
/// centre `c`: that ray's direction (toward the end at infinity, else the
/// farther end) and the ends' distances along it (infinite at infinity),
/// for `ConicTrack::radial`; `None` for two ends at infinity. Such edges
/// run beside a piece of rounding size: an arc cut a hair (1e-11) before
/// a point or a short segment that continues it (a tangent line split off
/// a circle it dips into), from the join in to the centre or out to
/// infinity, or between two arcs of one circle to rounding, all within
/// 1e-11 of the centre. Their angles, rounding and clamped to the sweep,
/// could not tell their points apart: the clearance sampled along them
/// dipped to zero where it stays near the radius, and a crossing of a
/// level came out at the join (LibreCAD's Relay).
fn narrow_ray(c: Point, ends: [ConicEnd; 2]) -> Option<(Point, [f64; 2])> {
    let unit = |v: Point| {
        let length = v.x.hypot(v.y);
        Point::new(v.x / length, v.y / length)
    };
    let u = match ends {
        [ConicEnd::Towards(u), ConicEnd::At(_)] | [ConicEnd::At(_), ConicEnd::Towards(u)] => unit(u),
        [ConicEnd::At(p), ConicEnd::At(q)] => {
            let far = if c.distance(p) >= c.distance(q) { p } else { q };
            unit(Point::new(far.x - c.x, far.y - c.y))
        }
        [ConicEnd::Towards(_), ConicEnd::Towards(_)] => return None,
    };
    let rho = |e: ConicEnd| match e {
        ConicEnd::At(v) => (v.x - c.x) * u.x + (v.y - c.y) * u.y,
        ConicEnd::Towards(_) => f64::INFINITY,
    };
    u.is_finite().then(|| (u, ends.map(rho)))
}

/// Whether one end of an edge is the arc's centre `c` (to 1e-9 of the
/// radius) and the other is not, nor outside the circle. Such an edge
/// lies on the radius from the centre to where the other site touches the
/// circle (a distance is 1-Lipschitz, so the arc's own inside, the radius
/// less the distance from the centre, meets the other site's along no
/// other ray; an edge that goes on outside can turn there), and the
/// centre's angle is rounding: between the pieces of a circle cut at both roots
/// of a tangency (4e-8 apart: LibreCAD's kin3), the offsets' crossings
/// came out at the far end.
fn from_the_centre(c: Point, radius: f64, ends: [Option<Point>; 2]) -> bool {
    let at_centre = |e: Option<Point>| e.is_some_and(|p| c.distance(p) <= 1e-9 * radius);
    let not_outside = |e: Option<Point>| e.is_some_and(|p| c.distance(p) <= (1.0 + 1e-9) * radius);
    (at_centre(ends[0]) && !at_centre(ends[1]) && not_outside(ends[1]))
        || (at_centre(ends[1]) && !at_centre(ends[0]) && not_outside(ends[0]))
}

/// Of samples `from..=to`, the one with the highest clearance (`peak`)
/// or the lowest.
fn extreme_sample(gs: &[f64], from: usize, to: usize, peak: bool) -> usize {
    let range = from..to + 1;
    let mut best = range.start;
    for k in range {
        if (peak && gs[k] > gs[best]) || (!peak && gs[k] < gs[best]) {
            best = k;
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::CircularArc;

    #[test]
    fn an_ellipse_inside_an_arc_peaks_opposite_the_point() {
        // a point at (0, 0.5) inside the unit circle's arc from 100° to
        // 80° (the long way round): the bisector is the ellipse
        // |q| + |q - p| = 1, clearance 0.25 at its top, 0.75 at its bottom
        let at = |deg: f64| Point::new(deg.to_radians().cos(), deg.to_radians().sin());
        let arc = CircularArc::through(at(100.0), at(270.0), at(80.0)).unwrap();
        let p = Point::new(0.0, 0.5);
        let sites = [Site::Arc(arc), Site::Point(p)];
        // from the ellipse's right end to its left, the long way (through
        // the bottom)
        let x = 0.375; // |x| + sqrt(x² + 1/4) = 1 at y = 0
        let track = ConicTrack::new(sites, ConicEnd::At(Point::new(-x, 0.0)), ConicEnd::At(Point::new(x, 0.0))).unwrap();
        let peaks: Vec<&Knot> = track.knots.iter().filter(|k| k.peak).collect();
        assert_eq!(peaks.len(), 1, "{:?}", track.knots);
        assert!((peaks[0].value - 0.75).abs() < 1e-12, "{:?}", peaks[0]);
        let bottom = track.point(peaks[0].t).unwrap();
        assert!(bottom.x.abs() < 1e-6 && (bottom.y + 0.25).abs() < 1e-12, "{bottom:?}");
        for t in [track.root(0.0, peaks[0].t, 0.7, true), track.root(peaks[0].t, 1.0, 0.7, false)] {
            let q = track.point(t).unwrap();
            assert!((q.distance(p) - 0.7).abs() < 1e-14 && (1.0 - q.distance(Point::new(0.0, 0.0)) - 0.7).abs() < 1e-14);
        }
    }
}
