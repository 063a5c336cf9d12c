//! The questions the insertion of an open segment `ab` asks of the current
//! diagram, in terms of sites, vertex positions and radii: how far `ab`
//! reaches into the circle of a vertex (with the exact rules where the
//! vertex has an endpoint of `ab` among its sites), which side of `ab` a
//! site lies on seen from a vertex (the left-degree of the path search),
//! whether a vertex lies in the strip of `ab`, and how clearly the middle
//! of an edge whose two ends are deleted stays out of the new cell (the
//! margin of an edge cut twice).
//!
//! Each answer holds one number and gives its sign as an enum and,
//! separately, its magnitude, used only to rank candidates (the strip test
//! is a plain yes or no). The construction (`construct::insert_segment`) decides
//! which vertex, edge or site to ask about and what its sites are; nothing
//! here knows about the diagram. In the fault-injection build the numbers
//! are perturbed here (`fault`), one draw per quantity, in the order the
//! questions are asked.

use super::oracle;
use super::reach::Reach;
use super::vertex_placement;
use crate::geometry::arithmetic::double_double::DoubleDouble;
use crate::geometry::arithmetic::real::norm;
use crate::geometry::arithmetic::real::Real;
use crate::geometry::curves::edge_curve::EdgeCurve;
use crate::geometry::fault;
use crate::geometry::point::Point;
use crate::geometry::predicates::{orientation, CirclePosition, Orientation};
use crate::geometry::site::{distance_in, smaller, Site};
use crate::geometry::solvers::segment_solvers;

/// How far a new segment reaches into the circle of a finite vertex: the
/// signed depth, negative inside, never NaN.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SegmentDepth(f64);

impl SegmentDepth {
    /// A depth computed elsewhere (the arcs' predicates), NaN as outside.
    #[inline]
    pub(crate) fn of(depth: f64) -> SegmentDepth {
        SegmentDepth(if depth.is_nan() { f64::INFINITY } else { depth })
    }

    /// Whether the segment enters the open disk (`Inside`: the vertex is in
    /// conflict with it), touches the circle, or stays outside.
    #[inline]
    pub fn position(self) -> CirclePosition {
        if self.0 < 0.0 {
            CirclePosition::Inside
        } else if self.0 > 0.0 {
            CirclePosition::Outside
        } else {
            CirclePosition::On
        }
    }

    /// The signed depth, only for ranking.
    #[inline]
    pub fn depth(self) -> f64 {
        self.0
    }
}

/// Which endpoints of the new segment `ab` are sites of the vertex asked
/// about (decided by the construction from site ids).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Contact {
    /// Both: the vertex is on the bisector of `a` and `b`.
    BothEnds,
    /// One of them.
    OneEnd(AtEndpoint),
    /// Neither.
    NoEnd,
}

/// A vertex with the endpoint `end` of the new segment `end → other` among
/// its sites, and the segments ending at `end` beside it: of the vertex's
/// sites just after and just before `end` (counter-clockwise), the far
/// endpoint of each that is a segment ending at `end`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct AtEndpoint {
    pub end: Point,
    pub other: Point,
    pub after: Option<Point>,
    pub before: Option<Point>,
}

/// How far inside the circle of a finite vertex (centre `centre`, radius
/// `radius`, its three sites given by `sites` when the certified stage
/// needs them) the open segment `ab` reaches (negative: it enters),
/// perturbed in fault injection.
///
/// When `a` is one of the vertex's sites, `a` lies on the circle and the
/// distance test would compare two equal numbers; the segment enters the
/// circle exactly when it leaves `a` towards the centre, so the sign of
/// `(b - a) · (c - a)` decides, with no cancellation (likewise for `b`);
/// exactly, where the vertex lies on a separator at `a`
/// (`side_at_endpoint`). With both `a` and `b` among its sites the vertex
/// is on their bisector: every point of it is nearer the segment between
/// them, exactly (the rounded position of a far vertex of nearly collinear
/// sites may say otherwise).
#[inline]
pub(crate) fn segment_depth(
    (a, b): (Point, Point),
    contact: Contact,
    centre: Point,
    radius: f64,
    sites: impl FnOnce() -> [Site; 3],
) -> SegmentDepth {
    let c = centre;
    let entering = |from: Point, to: Point| {
        let (dx, dy) = (to.x - from.x, to.y - from.y);
        -((c.x - from.x) * dx + (c.y - from.y) * dy) / norm(dx, dy)
    };
    let depth = match contact {
        Contact::BothEnds => EndpointSide::Enters.apply(entering(a, b)),
        Contact::OneEnd(at) => match side_at_endpoint(&at) {
            EndpointSide::Numeric => {
                certified(Reach::Entering { from: at.end, to: at.other }, entering(at.end, at.other), c, radius, sites)
            }
            side => side.apply(entering(at.end, at.other)),
        },
        Contact::NoEnd => certified(Reach::Distance { a, b }, Site::Segment { a, b }.distance(c) - radius, c, radius, sites),
    };
    let depth = fault::perturb(depth);
    SegmentDepth(if depth.is_nan() { f64::INFINITY } else { depth })
}

/// The rounded depth, its sign certified from the vertex's sites
/// (`oracle`). Not in fault injection: a refinement would make the lying
/// numbers honest again.
#[inline]
fn certified(question: Reach, depth: f64, centre: Point, radius: f64, sites: impl FnOnce() -> [Site; 3]) -> f64 {
    if fault::active() {
        return depth;
    }
    match oracle::reach(sites, centre, radius, question, depth) {
        Some(CirclePosition::Inside) => -depth.abs().max(f64::MIN_POSITIVE),
        Some(CirclePosition::Outside) => depth.abs().max(f64::MIN_POSITIVE),
        Some(CirclePosition::On) => 0.0,
        None => depth,
    }
}

/// For a vertex with the endpoint `end` of the new segment `end → other`
/// among its sites: where the vertex also has a segment `s` ending at
/// `end`, it lies on `s`'s separator at `end`, on the side of `s` given by
/// the order of the sites (`s` just after `end`: left of `end → far`; just
/// before: right), so whether the new segment leaves `end` towards it is
/// the exact orientation of `other` against `end → far` (collinear: along
/// the tangent, as where a chain goes straight on). Two such segments put
/// the vertex at `end` itself (radius 0): then the sector it stands for
/// decides (`sector_side`). `Numeric` where there is none.
#[inline]
fn side_at_endpoint(at: &AtEndpoint) -> EndpointSide {
    let (pe, po) = (at.end, at.other);
    let turn = |far: Point| orientation(pe, far, po);
    match (at.after, at.before) {
        (Some(from), Some(to)) => sector_side(pe, po, from, to),
        (Some(far), None) => EndpointSide::from_turn(turn(far), Orientation::CounterClockwise),
        (None, Some(far)) => EndpointSide::from_turn(turn(far), Orientation::Clockwise),
        (None, None) => EndpointSide::Numeric,
    }
}

/// For a vertex of radius 0 at the endpoint `pe`, between two segments
/// ending there (`pe → pf`, then `pe → pt` counter-clockwise around `pe`):
/// the vertex stands for the sector swept counter-clockwise from the first
/// to the second, where their bisector leaves `pe`. The new segment
/// `pe → po` splits that vertex exactly when it leaves `pe` strictly
/// inside the sector (exact orientations; a sector of 180° or more only
/// arises from lying numbers, and is decided the same way).
#[inline]
fn sector_side(pe: Point, po: Point, pf: Point, pt: Point) -> EndpointSide {
    let after_from = orientation(pe, pf, po) == Orientation::CounterClockwise;
    let before_to = orientation(pe, po, pt) == Orientation::CounterClockwise;
    let inside = match orientation(pe, pf, pt) {
        Orientation::CounterClockwise => after_from && before_to,
        Orientation::Clockwise => after_from || before_to,
        Orientation::Collinear => after_from,
    };
    if inside {
        EndpointSide::Enters
    } else {
        EndpointSide::Misses
    }
}

/// Whether the new segment enters the circle of a vertex through one of
/// its endpoints, decided exactly where the vertex is on a separator there
/// (`side_at_endpoint`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum EndpointSide {
    /// It enters.
    Enters,
    /// It leaves the endpoint away from the circle.
    Misses,
    /// It runs along the circle's tangent, or the circle has radius 0.
    OnCircle,
    /// No exact answer: the rounded position decides.
    Numeric,
}

impl EndpointSide {
    /// From the turn of the new segment against the separator's segment:
    /// `entering` is the turn that points into the circle.
    #[inline]
    fn from_turn(turn: Orientation, entering: Orientation) -> EndpointSide {
        if turn == Orientation::Collinear {
            EndpointSide::OnCircle
        } else if turn == entering {
            EndpointSide::Enters
        } else {
            EndpointSide::Misses
        }
    }

    /// The depth with this sign: the numeric one's size (at least the
    /// smallest positive number, so the sign survives), or 0 on the circle.
    #[inline]
    fn apply(self, numeric: f64) -> f64 {
        let size = numeric.abs().max(f64::MIN_POSITIVE);
        match self {
            EndpointSide::Enters => -size,
            EndpointSide::Misses => size,
            EndpointSide::OnCircle => 0.0,
            EndpointSide::Numeric => numeric,
        }
    }
}

/// A site as the left-degree sees it from a vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum SiteSeen {
    /// The point at infinity: on neither side.
    Infinity,
    /// A segment sharing an endpoint with the new segment, by its other
    /// endpoint: it lies on that endpoint's side.
    SharingEndpoint { far: Point },
    /// Any other site, seen from a finite vertex at `from` (the site's
    /// point nearest to it), or from a vertex at infinity (`None`: the
    /// site's midpoint).
    Other { site: Site, from: Option<Point> },
}

/// Seed 000's left-degree of a site seen from a vertex against the
/// directed segment `a → b`: positive when the site is left of `a → b`,
/// infinite when decided exactly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct LeftDegree(f64);

impl LeftDegree {
    /// A degree computed elsewhere (the arcs' predicates).
    #[inline]
    pub(crate) fn of(degree: f64) -> LeftDegree {
        LeftDegree(degree)
    }

    /// The side of `a → b` the site lies on: `CounterClockwise` (left) when
    /// the degree is positive, `Clockwise` when negative, `Collinear`
    /// otherwise (zero, or NaN).
    #[inline]
    pub fn side(self) -> Orientation {
        if self.0 > 0.0 {
            Orientation::CounterClockwise
        } else if self.0 < 0.0 {
            Orientation::Clockwise
        } else {
            Orientation::Collinear
        }
    }

    /// How certain the side is, for ranking: the degree's size (infinite
    /// when exact, NaN when the numbers failed).
    #[inline]
    pub fn certainty(self) -> f64 {
        self.0.abs()
    }

    /// How clearly an edge has the site `left` on its left of the segment
    /// and the site `right` on its right, for
    /// ranking: the smaller of the two degrees in those directions, `-∞`
    /// when the numbers failed, and at most `f64::MAX` (below a start that
    /// is a vertex of `R(b)`, ranked `+∞`).
    #[inline]
    pub fn separation(left: LeftDegree, right: LeftDegree) -> f64 {
        let separation = left.0.min(-right.0);
        if separation.is_nan() {
            f64::NEG_INFINITY
        } else {
            separation.min(f64::MAX)
        }
    }
}

/// Seed 000's left-degree of a site seen from a vertex against the
/// directed segment `a → b`: positive when the projection of the vertex on
/// the site is left of it (perturbed in fault injection). Only its sign and
/// size guide the walk. A segment that shares an endpoint with `ab` lies on
/// the side of its other endpoint, decided exactly (and reported as
/// certain: infinite).
#[inline]
pub(crate) fn left_degree((a, b): (Point, Point), seen: SiteSeen) -> LeftDegree {
    let q = match seen {
        SiteSeen::Infinity => return LeftDegree(0.0),
        SiteSeen::SharingEndpoint { far } => {
            return LeftDegree(match orientation(a, b, far) {
                Orientation::CounterClockwise => f64::INFINITY,
                Orientation::Clockwise => f64::NEG_INFINITY,
                Orientation::Collinear => 0.0,
            })
        }
        SiteSeen::Other { site, from: Some(v) } => site.nearest_point(v),
        SiteSeen::Other { site, from: None } => site.midpoint(),
    };
    let degree = fault::perturb((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x));
    // A point site is seen as itself: its side is an exact orientation
    // (the rounded cross product of nearly collinear points, or of
    // coordinates near the subnormal range, can have the wrong sign).
    if let SiteSeen::Other { site: Site::Point(_), .. } = seen {
        if !fault::active() {
            return LeftDegree(match orientation(a, b, q) {
                Orientation::CounterClockwise => degree.abs().max(f64::MIN_POSITIVE),
                Orientation::Clockwise => -degree.abs().max(f64::MIN_POSITIVE),
                Orientation::Collinear => 0.0,
            });
        }
    }
    LeftDegree(degree)
}

/// Whether the vertex of `sites` (rounded as `centre`, `radius`) lies in
/// the closed strip between the perpendiculars to `ab` at `a` and at `b`
/// (criterion 2.2), certified from its sites like a conflict (`oracle`):
/// beyond the perpendicular at `a` is the segment leaving `a` away from
/// the centre, `Reach::Entering` of `a → b` with the opposite sign. A far
/// vertex of nearly parallel sites is rounded by more than the strip is
/// wide. Perturbed, uncertified, in fault injection.
#[inline]
pub(crate) fn in_strip(centre: Point, radius: f64, (a, b): (Point, Point), sites: impl Fn() -> [Site; 3]) -> bool {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let t = (centre.x - a.x) * dx + (centre.y - a.y) * dy;
    let t = fault::perturb(t);
    let length2 = dx * dx + dy * dy;
    if fault::active() {
        return (0.0..=length2).contains(&t);
    }
    // Clear answers first, without asking the oracle: its own filter
    // takes an answer beyond `oracle::CLEAR` of the configuration's size
    // outright.
    let length = length2.sqrt();
    let from_a = t / length;
    let from_b = length - from_a;
    let clear = oracle::CLEAR * (radius.abs() + centre.distance(a) + length);
    if from_a > clear && from_b > clear {
        return true;
    }
    if from_a < -clear || from_b < -clear {
        return false;
    }
    // beyond the perpendicular at `from`: the segment from there leaves
    // the centre behind, a positive `Entering` depth
    let beyond =
        |from: Point, to: Point, along: f64| certified(Reach::Entering { from, to }, -along, centre, radius, &sites) > 0.0;
    !(beyond(a, b, from_a) || beyond(b, a, from_b))
}

/// How far, as a fraction of an edge, a computed crossing of the edge may
/// lie beyond one of its ends and still be taken as at that end.
const END_TOLERANCE: f64 = 1e-6;

/// A finite edge of the diagram: the sites on the left and the right of
/// one of its half-edges, and that half-edge's origin and target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FiniteEdge {
    pub left: Site,
    pub right: Site,
    pub from: Point,
    pub to: Point,
}

/// Which endpoints of the new segment are sites of an edge (decided by the
/// construction from site ids).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum EdgeContact {
    /// Both: the edge is on the bisector of the segment's endpoints.
    BothEnds,
    /// One of them.
    OneEnd,
    /// Neither.
    NoEnd,
}

/// How clearly the middle of an edge whose two ends the new cell takes
/// stays out of it: positive when it does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct MiddleMargin(f64);

/// What becomes of the middle of an edge whose two ends are deleted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum EdgeMiddle {
    /// It stays out of the new cell: the edge may be cut at both ends.
    Stays,
    /// It is in the new cell, or the numbers cannot tell.
    Covered,
}

impl MiddleMargin {
    /// A margin computed elsewhere (the arcs' predicates).
    #[inline]
    pub(crate) fn of(margin: f64) -> MiddleMargin {
        MiddleMargin(margin)
    }

    /// `Stays` when the margin is positive.
    #[inline]
    pub fn middle(self) -> EdgeMiddle {
        if self.0 > 0.0 {
            EdgeMiddle::Stays
        } else {
            EdgeMiddle::Covered
        }
    }

    /// The margin, only for ranking.
    #[inline]
    pub fn margin(self) -> f64 {
        self.0
    }
}

/// How clearly the middle of a finite edge stays out of the cell of the
/// segment `ab` when both its ends are in it (perturbed in fault
/// injection). Positive: the edge keeps a middle piece.
///
/// The new cell's boundary would cross the edge at the two vertices a
/// cut at both ends creates: `[right, left, e]` near the edge's origin and
/// `[left, right, e]` near its target, each computed from the three sites
/// by its solver. The middle stays when both exist, lie on the edge, and
/// come in that order; the margin is then how much closer the point
/// halfway between them is to its own sites than to `ab`. (Sampling the
/// edge instead misses a middle piece that is short against the edge.)
/// When a solver finds nothing, the edge is sampled instead.
pub(crate) fn middle_margin(edge: FiniteEdge, contact: EdgeContact, segment: (Point, Point)) -> MiddleMargin {
    if contact == EdgeContact::BothEnds {
        // Every point of the bisector of a and b is closer to the open
        // segment between them (the midpoint is nearer than either end).
        return MiddleMargin(f64::NEG_INFINITY);
    }
    let edge = EdgeUnderSegment::new(edge, segment, contact == EdgeContact::OneEnd);
    // placed as the construction places vertices: an f64 solve that is
    // ill-conditioned (a point an ulp from the segment's line) is solved
    // again finer, or the order of the two crossings is noise
    let crossings = vertex_placement::solved_circle(&[edge.right, edge.left, edge.segment])
        .zip(vertex_placement::solved_circle(&[edge.left, edge.right, edge.segment]))
        .map(|((near_origin, _), (near_target, _))| (edge.arc.parameter(near_origin), edge.arc.parameter(near_target)));
    // Both ends of the edge are in conflict (certified), so a crossing
    // is inside the edge: one a rounding error beyond an end (the end
    // vertex almost on the new cell's boundary) is at that end.
    let crossings = crossings.map(|(t1, t2)| {
        let at_end = |t: f64, end: f64| if (t - end).abs() <= END_TOLERANCE { end } else { t };
        (at_end(t1, 0.0), at_end(t2, 1.0))
    });
    let on_edge = |t: f64| (0.0..=1.0).contains(&t);
    let margin = match crossings {
        Some((t1, t2)) if on_edge(t1) && on_edge(t2) => {
            let excess = if t1 < t2 { edge.excess(0.5 * (t1 + t2)) } else { -(t1 - t2).abs().max(f64::MIN_POSITIVE) };
            // Crossings close along the edge, or an excess within the
            // rounding of the distances it compares (the middle of a
            // needle an ulp wide), are ordered by their difference along
            // the edge in double-double (below, `crossing_order`):
            // rounded to f64 coordinates they may be closer than an ulp
            // of them.
            let doubtful = (t2 - t1).abs() < CLOSE_CROSSINGS || excess.abs() <= EXCESS_NOISE * edge.size(0.5 * (t1 + t2));
            match (doubtful && !fault::active()).then(|| crossing_order(&edge)).flatten() {
                Some(order) if order > 0.0 => order,
                Some(order) => -order.abs().max(f64::MIN_POSITIVE),
                None => excess,
            }
        }
        // Two close crossings off the edge are the two circles tangent
        // near a point an ulp from the segment, where the new cell's
        // boundary meets the bisector beyond the edge: it is covered.
        Some((t1, t2)) => -(t1 - t2).abs().max(f64::MIN_POSITIVE),
        // Two points on opposite sides of the segment's line (exact): no
        // circle through both touches the line, so the new cell's boundary
        // cannot cross their bisector inside the strip, and the edge, both
        // of whose ends the cell takes, is covered whole. (The sampled
        // excess there is noise when a point is an ulp from the segment.)
        None if !fault::active() && points_on_opposite_sides(&edge) => f64::NEG_INFINITY,
        // The sampled excess is rounding noise where the edge lies far out
        // against the segment's distance from the edge's sites (two points
        // an ulp nearer the segment's line than its parallel neighbour: the
        // excess is -1e-9 on distances of 1e9): it is evaluated again at the
        // best sample in double-double, where its sign holds.
        None => match sampled_maximum(&|t| edge.excess(t)) {
            (t, excess) if !fault::active() && excess.abs() <= EXCESS_NOISE * edge.size(t) => edge.fine_excess(t),
            (_, excess) => excess,
        },
    };
    MiddleMargin(fault::perturb(margin))
}

/// Whether the edge's two sites are points strictly on opposite sides of
/// the line of the new segment (exact orientations).
fn points_on_opposite_sides(edge: &EdgeUnderSegment) -> bool {
    let (Site::Point(p), Site::Point(q), Site::Segment { a, b }) = (edge.left, edge.right, edge.segment) else {
        return false;
    };
    let (sp, sq) = (orientation(a, b, p), orientation(a, b, q));
    sp != Orientation::Collinear && sq != Orientation::Collinear && sp != sq
}

/// Crossings of an edge closer than this (in its parameter) are ordered in
/// double-double.
const CLOSE_CROSSINGS: f64 = 1e-6;

/// An excess below this, relative to the size of the configuration where
/// it is measured (`EdgeUnderSegment::size`), is within the rounding of the
/// distances it compares: the crossings are ordered in double-double.
const EXCESS_NOISE: f64 = 1e-12;

/// Which way the two crossings of the new cell's boundary with the edge
/// are ordered along it, from their circles solved in double-double: the
/// difference of the crossing nearer the target and the one nearer the
/// origin, along the direction in which the edge's parameter grows
/// (positive: in order, the middle stays). Where the two new vertices are a
/// few ulps of their coordinates apart (joints open by one ulp), only a
/// finer arithmetic tells them apart. `None` when a circle cannot be solved.
///
/// The parameter is linear in position (along the line of a straight
/// edge, along the directrix of a parabola), so the difference is exact up
/// to the double-double rounding and an ulp's tilt of the direction — also
/// at the tip of a parabola whose focus is an ulp from its directrix, where
/// the curve turns back within a few ulps.
fn crossing_order(edge: &EdgeUnderSegment) -> Option<f64> {
    let dd = DoubleDouble::from_f64;
    let near_origin = segment_solvers::vertex_in(&[edge.right, edge.left, edge.segment], &dd)?;
    let near_target = segment_solvers::vertex_in(&[edge.left, edge.right, edge.segment], &dd)?;
    let Point { x: tx, y: ty } = edge.arc.direction();
    let along = near_target[0].sub(near_origin[0]).mul(dd(tx)).add(near_target[1].sub(near_origin[1]).mul(dd(ty)));
    let along = along.to_f64();
    along.is_finite().then_some(along)
}

/// An edge seen from a new segment (`EdgeUnderSegment::new`).
struct EdgeUnderSegment {
    left: Site,
    right: Site,
    arc: EdgeCurve,
    segment: Site,
    /// One of the edge's sites is an endpoint of the segment.
    touches_end: bool,
}

impl EdgeUnderSegment {
    /// The edge with its two sites, its curve, and the new segment `ab`.
    fn new(edge: FiniteEdge, (a, b): (Point, Point), touches_end: bool) -> EdgeUnderSegment {
        let FiniteEdge { left, right, from, to } = edge;
        let arc = EdgeCurve::between(&left, &right, from, to);
        EdgeUnderSegment { left, right, arc, segment: Site::Segment { a, b }, touches_end }
    }

    /// The size of the numbers the excess at parameter `t` is made of: the
    /// point's coordinates and its distance to the edge's sites.
    fn size(&self, t: f64) -> f64 {
        let q = self.arc.point(t);
        q.x.abs().max(q.y.abs()) + self.left.distance(q)
    }

    /// The excess of the distance to the segment over the distance to the
    /// edge's own sites, at the point of the edge at parameter `t` (0 at its
    /// origin, 1 at its target); NaN gives `-∞`.
    fn excess(&self, t: f64) -> f64 {
        self.excess_in(t, &|x| x)
    }

    /// [`EdgeUnderSegment::excess`] at the same point of the edge, its
    /// distances in double-double. The point itself is the `f64` point of
    /// the edge; off the edge by its rounding, it moves the mean distance
    /// to the edge's two sites only at second order (that mean grows along
    /// the edge, not across it), so the sign of an excess far below the
    /// coordinates' ulp holds.
    fn fine_excess(&self, t: f64) -> f64 {
        self.excess_in(t, &DoubleDouble::from_f64)
    }

    /// The excess at parameter `t`, computed in the arithmetic `T` and
    /// rounded to `f64`; NaN gives `-∞`.
    #[inline]
    fn excess_in<T: Real>(&self, t: f64, lift: &impl Fn(f64) -> T) -> f64 {
        let q = self.arc.point(t);
        let e = match self.segment {
            // On an edge of R(a) or R(b) the distances to the segment and to
            // its endpoint agree outside the strip, so the signed distance
            // beyond the perpendiculars decides, without cancellation.
            Site::Segment { a: pa, b: pb } if self.touches_end => {
                let (dx, dy) = (lift(pb.x).sub(&lift(pa.x)), lift(pb.y).sub(&lift(pa.y)));
                let along =
                    |from: Point, to: Point| lift(to.x).sub(&lift(from.x)).mul(&dx).add(&lift(to.y).sub(&lift(from.y)).mul(&dy));
                // the larger, as `f64::max` picks it
                let beyond = smaller(along(pa, q), along(q, pb)).neg();
                beyond.div(&T::hypot(&dx, &dy))
            }
            _ => {
                let own = distance_in(&self.left, q, lift).add(&distance_in(&self.right, q, lift));
                distance_in(&self.segment, q, lift).sub(&own.mul(&lift(0.5)))
            }
        }
        .to_f64();
        if e.is_nan() {
            f64::NEG_INFINITY
        } else {
            e
        }
    }
}

/// The largest value of `f` over `[0, 1]` as far as sampling finds it, and
/// where: evenly spaced samples, the best refined by golden-section search.
fn sampled_maximum(f: &impl Fn(f64) -> f64) -> (f64, f64) {
    const SAMPLES: usize = 16;
    const REFINEMENTS: usize = 40;
    let step = 1.0 / (SAMPLES + 1) as f64;
    let (mut best_t, mut best) = (0.5, f64::NEG_INFINITY);
    for k in 1..=SAMPLES {
        let t = k as f64 * step;
        let e = f(t);
        if e > best {
            (best_t, best) = (t, e);
        }
    }
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = ((best_t - step).max(0.0), (best_t + step).min(1.0));
    let (mut x1, mut x2) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
    let (mut e1, mut e2) = (f(x1), f(x2));
    for _ in 0..REFINEMENTS {
        if e1 < e2 {
            lo = x1;
            (x1, e1) = (x2, e2);
            x2 = lo + ratio * (hi - lo);
            e2 = f(x2);
        } else {
            hi = x2;
            (x2, e2) = (x1, e1);
            x1 = hi - ratio * (hi - lo);
            e1 = f(x1);
        }
    }
    [(best_t, best), (x1, e1), (x2, e2)].into_iter().fold((best_t, best), |a, b| if b.1 > a.1 { b } else { a })
}
