//! The questions the insertion of an open arc asks (see `arcs`): the same
//! four as for a segment (`segments::segment_predicates`), answered in
//! floating point, with the tangent and curvature rules where the vertex
//! touches one of the arc's endpoints; a near tie of the arc with a
//! vertex's circle is refined in double-double (`refined_depth`), and
//! where the vertex's sites meet the arc at an endpoint the turn between
//! them is exact (`exact_join`).

use super::exact_join;
use super::refined_depth;
use crate::geometry::arc::CircularArc;
use crate::geometry::curves::bisector::{bisector_point, bisector_point_on_edge, round_point_site};
use crate::geometry::fault;
use crate::geometry::point::Point;
use crate::geometry::segments::segment_predicates::{EdgeContact, FiniteEdge, LeftDegree, MiddleMargin, SegmentDepth};
use crate::geometry::site::Site;

/// Which endpoints of the new arc are sites of the vertex asked about.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum ArcContact {
    /// Both: the vertex is on the bisector of the endpoints, a line through
    /// the arc's centre.
    BothEnds,
    /// The endpoint `end`, with the pieces ending there that are the
    /// vertex's sites just after and just before `end`, counter-clockwise.
    OneEnd { end: Point, after: Option<Site>, before: Option<Site> },
    /// Neither.
    NoEnd,
}

/// How far inside the circle of a finite vertex (`centre`, `radius`) the
/// open arc reaches (negative: it enters), perturbed in fault injection.
///
/// With an endpoint of the arc among the vertex's sites, that endpoint is
/// on the circle; the arc enters when its tangent there points into the
/// disk, and where the tangent runs along the circle (a tangent join of a
/// chain), when it curves into the disk more sharply than the circle.
pub(crate) fn arc_depth(
    arc: &CircularArc,
    contact: ArcContact,
    centre: Point,
    radius: f64,
    sites: impl FnOnce() -> [Site; 3],
) -> SegmentDepth {
    let depth = match contact {
        ArcContact::NoEnd => {
            let depth = arc.distance(centre) - radius;
            if refined_depth::needs_refinement(depth, arc, centre, radius) {
                refined_depth::refined_arc_depth(arc, &sites(), centre, radius).unwrap_or(depth)
            } else {
                depth
            }
        }
        ArcContact::BothEnds => {
            // on the bisector of the ends, a line through the arc's centre:
            // beyond the centre on the side of the arc's middle the arc is
            // nearer than its ends; at the centre itself every point of the
            // arc is as near (a tie: no conflict); beyond it on the other
            // side the ends are nearer
            let (c, m) = (arc.centre(), arc.midpoint());
            let along = ((centre.x - c.x) * (m.x - c.x) + (centre.y - c.y) * (m.y - c.y)) / arc.radius();
            let size = along.abs().max(f64::MIN_POSITIVE);
            // exact where the third site allows (a piece sharing an end, a
            // point): a join an ulp off straight puts the vertex an ulp
            // beyond or before the centre, not at it. At the centre exactly
            // (a tangent join; a cusp, where a whole stretch of the normal
            // ties four sites), the floating-point rule below stands: its
            // answers are what the degenerate configurations were built
            // and tested with.
            // (filtered: only where the floating-point answer is near the
            // tie, far above the solver's error, is the exact one asked)
            let [s, e] = [Site::Point(arc.start()), Site::Point(arc.end())];
            let near_tie = along.abs() <= NEAR_TIE * arc.radius();
            let third = near_tie.then(|| sites().into_iter().find(|t| *t != s && *t != e)).flatten();
            match third.and_then(|t| exact_join::beyond_centre(arc, &t)) {
                Some(1) => -size,
                Some(-1) => size,
                _ if along > 1e-9 * arc.radius() => -size,
                _ if along < -1e-9 * arc.radius() => size,
                _ => 0.0,
            }
        }
        ArcContact::OneEnd { end, after, before } => endpoint_depth(arc, end, after, before, centre, radius, sites),
    };
    SegmentDepth::of(fault::perturb(depth))
}

/// Below this (a cosine, or a fraction of the radius) a floating-point
/// answer at a join is near enough a tie for the exact one (`exact_join`)
/// to be asked; above it the floating-point sign is right (the vertices'
/// error is far smaller, and the bend of `direction_leaving` is 1e-7).
const NEAR_TIE: f64 = 1e-6;

/// [`arc_depth`] for a vertex with the arc's endpoint `end` among its sites.
fn endpoint_depth(
    arc: &CircularArc,
    end: Point,
    after: Option<Site>,
    before: Option<Site>,
    centre: Point,
    radius: f64,
    sites: impl FnOnce() -> [Site; 3],
) -> f64 {
    let (nx, ny) = (centre.x - end.x, centre.y - end.y);
    let n = nx.hypot(ny);
    if let (Some(from), Some(to)) = (after, before) {
        if n <= 1e-12 * (radius.abs() + end.x.abs().max(end.y.abs())) {
            // a vertex of radius 0 at `end`, standing for the sector from
            // one piece to the next: entered when the arc leaves into it
            let entered = exact_sector(&from, &to, arc, end).unwrap_or_else(|| {
                let direction = |s: &Site| piece_direction(s, end).unwrap_or(Point::new(0.0, 0.0));
                in_sector(direction(&from), direction(&to), direction_leaving(arc, end))
            });
            return if entered { -f64::MIN_POSITIVE } else { f64::MIN_POSITIVE };
        }
    }
    if !(n > 0.0) {
        return 0.0;
    }
    // (asked at most once, below)
    let mut sites = Some(sites);
    let mut sites = move || sites.take().map(|f| f());
    let tangent = arc.tangent_into(end);
    let along = (tangent.x * nx + tangent.y * ny) / n;
    let size = (along * radius).abs().max(f64::MIN_POSITIVE);
    // Near a tie the arc leaves `end` nearly along the circle: leaving
    // into it, it is inside just after `end`; leaving out of it, it still
    // comes back in (a hair further on, where the two circles meet again)
    // when it curves toward the vertex more sharply than the circle does,
    // which the tangent rule below says.
    let out = |cusp: bool| if tangent_depth(arc, end, nx, ny, radius, cusp) < 0.0 { -size } else { size };
    // With a piece ending at `end` among the vertex's sites, the vertex is
    // on that piece's normal there, on the side the float cross product
    // tells clearly (the vertex is `n` away): the arc enters when it turns
    // from the piece toward that side, exactly. Where the two leave along
    // one line (tangent, or a cusp) the floating-point rules below stand.
    let mut cusp = false;
    if let Some(piece) = after.or(before).filter(|_| along.abs() <= NEAR_TIE) {
        let turn = exact_join::tangent_turn(&piece, &Site::Arc(*arc), end);
        let exact = piece_direction(&piece, end).zip(turn).map(|(d, turn)| {
            let side: i8 = if d.x * ny - d.y * nx > 0.0 { 1 } else { -1 };
            side * turn
        });
        match exact {
            Some(1) => return -size,
            Some(-1) => return out(false),
            _ => {}
        }
        cusp = turn == Some(0) && exact_join::leave_the_same_way(&piece, &Site::Arc(*arc), end) == Some(true);
    } else if along.abs() <= NEAR_TIE && !arc.has_circle(centre, radius) {
        // The vertex of `end` and two more points: whether the arc leaves
        // into their circle, exactly. Near a tie the circle can be huge
        // (three points nearly in line, its centre 1e16 away), and then
        // the arc enters it at an angle of rounding size, which the
        // floating-point tangent cannot tell from running along it.
        // Likewise with a point and a piece ending there (the circle
        // through `end` touching the piece at that point), and with a
        // point and another arc (a circle through `end` and the point
        // touching the arc's circle: LibreCAD's t2.dxf, two half circles
        // an ulp below a point's line). (Not where the
        // vertex's circle is the arc's own to rounding, a quarter circle
        // of a rounded bulge beside its other quarter's end: there the
        // exact sign is the bulge's rounding, which the solvers, working
        // from the rounded centre, cannot follow; the tie rules stand.)
        let exact = match sites().into_iter().flatten().filter(|&s| s != Site::Point(end)).collect::<Vec<_>>()[..] {
            [Site::Point(b), Site::Point(c)] => exact_join::leaves_into_circle(arc, end, b, c),
            [Site::Point(q), piece] | [piece, Site::Point(q)] if piece.has_endpoint(q) => {
                exact_join::leaves_into_tangent_circle(arc, end, q, &piece)
            }
            [Site::Point(q), Site::Arc(other)] | [Site::Arc(other), Site::Point(q)] => {
                exact_join::leaves_into_circle_touching(arc, end, q, &other, centre)
            }
            _ => None,
        };
        match exact {
            Some(1) => return -size,
            Some(-1) => return out(false),
            _ => {}
        }
    }
    if along > 1e-12 {
        return -along * radius.abs().max(f64::MIN_POSITIVE);
    }
    if along < -1e-12 {
        // leaving out of the circle clearly: in conflict only where the
        // arc comes back into it further on, clearly (the circles' second
        // meeting within the arc's span)
        let back = arc.distance(centre) - radius;
        return if back < -1e-9 * (radius + arc.radius()) { back } else { -along * radius.abs().max(f64::MIN_POSITIVE) };
    }
    if !cusp && arc.has_circle(centre, radius) {
        // the arc on the vertex's circle (a tie): in conflict where one of
        // the vertex's edges leaves it toward the arc's inside, which a
        // vertex kept would leave cut in its middle (a circle's quarter
        // beside a segment that touches the circle where the quarter
        // starts: the edge between the segment and the next site runs
        // inside the quarter's sector)
        if sites().is_some_and(|sites| an_edge_leaves_into(arc, centre, &sites)) {
            return -f64::MIN_POSITIVE;
        }
    }
    tangent_depth(arc, end, nx, ny, radius, cusp)
}

/// Whether an edge of the vertex at `centre` (the arc's own centre, its
/// circle the arc's) with `sites`, counter-clockwise, leaves it strictly
/// inside the arc's span. The edge between two consecutive sites leaves
/// toward the middle of the gap between where they touch the circle (to
/// first order each site is that point, or, an arc on that circle too,
/// its whole span); gaps of no width (two sites touching at one point)
/// have no edge leaving through them.
fn an_edge_leaves_into(arc: &CircularArc, centre: Point, sites: &[Site; 3]) -> bool {
    let full = 2.0 * std::f64::consts::PI;
    let angle_of = |q: Point| (q.y - centre.y).atan2(q.x - centre.x);
    // where a site touches the circle, counter-clockwise: first and last
    let touching = |s: &Site| match *s {
        Site::Arc(other) if other.has_circle(centre, arc.radius()) => {
            let (first, last) =
                if other.is_counter_clockwise() { (other.start(), other.end()) } else { (other.end(), other.start()) };
            (angle_of(first), angle_of(last))
        }
        _ => {
            let a = angle_of(s.nearest_point(centre));
            (a, a)
        }
    };
    let (start, end) = (arc.start(), arc.end());
    let near_an_end = |a: f64| {
        [angle_of(start), angle_of(end)].iter().any(|&e| {
            let d = (a - e).rem_euclid(full);
            d.min(full - d) <= 1e-9
        })
    };
    (0..3).any(|k| {
        let (a, b) = (touching(&sites[k]).1, touching(&sites[(k + 1) % 3]).0);
        let gap = (b - a).rem_euclid(full);
        if gap <= 1e-9 || gap >= full - 1e-9 {
            return false;
        }
        let middle = a + 0.5 * gap;
        let r = arc.radius();
        !near_an_end(middle) && arc.spans(Point::new(centre.x + r * middle.cos(), centre.y + r * middle.sin()))
    })
}

/// Whether the arc leaving `end` turns strictly into the sector swept
/// counter-clockwise from the piece `from` to the piece `to`, both leaving
/// `end` too (exact turns, exact ties broken by curvature); `None` out of
/// range.
fn exact_sector(from: &Site, to: &Site, arc: &CircularArc, end: Point) -> Option<bool> {
    let arc = Site::Arc(*arc);
    let turn = |u: &Site, v: &Site| exact_join::turn_between(u, v, end);
    let (after_from, before_to) = (turn(from, &arc)? > 0, turn(&arc, to)? > 0);
    Some(if turn(from, to)? > 0 { after_from && before_to } else { after_from || before_to })
}

/// [`endpoint_depth`] where the arc leaves `end` along the tangent of the
/// vertex's circle (`(nx, ny)` from `end` to the vertex); `cusp` where a
/// piece among the vertex's sites leaves `end` along the arc, the same way.
///
/// An arc on the vertex's circle itself is a tie, kept out of conflict at
/// a tangent join (the degenerate configurations of chains were built so),
/// but in conflict at a cusp: there the vertex is on the normal from the
/// cusp, where a whole stretch ties, and beside it (along the vertex's
/// edge that leaves toward the arc) the arc is strictly nearer than any of
/// the vertex's sites, so a vertex kept would leave that edge cut in its
/// middle (`exact_join::beyond_centre` decides the cusp the same way where
/// both of the arc's ends are the vertex's sites).
fn tangent_depth(arc: &CircularArc, end: Point, nx: f64, ny: f64, radius: f64, cusp: bool) -> f64 {
    // along the circle's tangent: the arc enters when it curves toward the
    // vertex's centre, on a smaller circle
    let (cx, cy) = (arc.centre().x - end.x, arc.centre().y - end.y);
    let towards = cx * nx + cy * ny > 0.0;
    let sharper = arc.radius() < radius;
    let size = (radius - arc.radius()).abs().max(f64::MIN_POSITIVE);
    // (at a cusp, the vertex's radius is the arc's to within its solver's
    // rounding when the tie is exact in the input: within 1e-9, a tie)
    let on_the_circle = (radius - arc.radius()).abs() <= 1e-9 * arc.radius();
    if towards && (sharper || cusp && on_the_circle) {
        -size.max(f64::MIN_POSITIVE)
    } else if towards && arc.radius() == radius {
        0.0
    } else {
        size
    }
}

/// The direction in which the arc leaves its endpoint `end`, bent a hair
/// toward its centre, so that where it leaves along another piece's
/// direction (a tangent join) the side it curves to decides.
pub(crate) fn direction_leaving(arc: &CircularArc, end: Point) -> Point {
    let t = arc.tangent_into(end);
    let bend = 1e-7;
    let (cx, cy) = ((arc.centre().x - end.x) / arc.radius(), (arc.centre().y - end.y) / arc.radius());
    Point::new(t.x + bend * cx, t.y + bend * cy)
}

/// The direction in which a piece ending at `end` leaves it: a segment
/// toward its other end, an arc as [`direction_leaving`].
pub(crate) fn piece_direction(site: &Site, end: Point) -> Option<Point> {
    match *site {
        Site::Segment { .. } => {
            let far = site.other_endpoint(end)?;
            let (dx, dy) = (far.x - end.x, far.y - end.y);
            let len = dx.hypot(dy);
            Some(Point::new(dx / len, dy / len))
        }
        Site::Arc(arc) if arc.start() == end || arc.end() == end => Some(direction_leaving(&arc, end)),
        _ => None,
    }
}

/// Whether the direction `d` lies strictly inside the sector swept
/// counter-clockwise from the direction `from` to `to`.
fn in_sector(from: Point, to: Point, d: Point) -> bool {
    let cross = |u: Point, v: Point| u.x * v.y - u.y * v.x;
    let (after_from, before_to) = (cross(from, d) > 0.0, cross(d, to) > 0.0);
    if cross(from, to) > 0.0 {
        after_from && before_to
    } else {
        after_from || before_to
    }
}

/// A site as the left-degree of an arc sees it from a vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum ArcSiteSeen {
    /// The point at infinity: on neither side.
    Infinity,
    /// A piece sharing the endpoint `end` with the new arc: its side near
    /// `end`.
    SharingEndpoint { site: Site, end: Point },
    /// Any other site, seen from a finite vertex at `from`, or from a
    /// vertex at infinity (`None`: the site's midpoint).
    Other { site: Site, from: Option<Point> },
}

/// The left-degree against the directed arc (start → end): positive when
/// the site lies on its left (toward the centre of a counter-clockwise
/// arc, away from it for a clockwise one), by the circle's side of the
/// site's point nearest to the vertex. Perturbed in fault injection.
pub(crate) fn arc_left_degree(arc: &CircularArc, seen: ArcSiteSeen) -> LeftDegree {
    let q = match seen {
        ArcSiteSeen::Infinity => return LeftDegree::of(0.0),
        ArcSiteSeen::SharingEndpoint { site, end } => return LeftDegree::of(fault::perturb(side_near_end(arc, &site, end))),
        ArcSiteSeen::Other { site, from: Some(v) } => site.nearest_point(v),
        ArcSiteSeen::Other { site, from: None } => site.midpoint(),
    };
    LeftDegree::of(fault::perturb(arc.left_of(q)))
}

/// The side of the arc's circle (left positive) on which the piece `site`
/// leaves their common endpoint `end`: by its direction against the
/// inward normal, and along the tangent by its curvature (a segment stays
/// outside the circle; an arc curving the same way on a smaller circle
/// inside). Reported as certain (infinite) when the direction decides.
fn side_near_end(arc: &CircularArc, site: &Site, end: Point) -> f64 {
    let inward = Point::new(arc.centre().x - end.x, arc.centre().y - end.y);
    let scale = inward.x.hypot(inward.y);
    // exactly near the tangent (filtered: a clear floating-point turn
    // stands, below), unless the piece leaves exactly along it
    let clear = piece_direction(site, end).is_some_and(|d| ((d.x * inward.x + d.y * inward.y) / scale).abs() > NEAR_TIE);
    let exact = if clear {
        None
    } else {
        let toward_centre: i8 = if exact_join::curves_left(arc, end) { 1 } else { -1 };
        exact_join::tangent_turn(&Site::Arc(*arc), site, end).filter(|&turn| turn != 0).map(|turn| turn == toward_centre)
    };
    let inside = match (exact, piece_direction(site, end)) {
        (Some(inside), _) => inside,
        (None, None) => {
            return arc.left_of(site.midpoint());
        }
        (None, Some(d)) => {
            let dot = (d.x * inward.x + d.y * inward.y) / scale;
            if dot.abs() > NEAR_TIE {
                dot > 0.0
            } else {
                match *site {
                    Site::Arc(other) => {
                        let same_side = (other.centre().x - end.x) * inward.x + (other.centre().y - end.y) * inward.y > 0.0;
                        same_side && other.radius() < arc.radius()
                    }
                    _ => false,
                }
            }
        }
    };
    let left = inside == arc.is_counter_clockwise();
    if left {
        f64::INFINITY
    } else {
        f64::NEG_INFINITY
    }
}

/// Whether a vertex (`centre`) lies in the arc's cone of influence, the
/// wedge at its centre between the rays through its endpoints (the arcs'
/// criterion 2.2); a vertex of both endpoints lies on their bisector, in
/// the cone when on the side of the arc's middle. A vertex at the arc's
/// centre (to within 1e-9 of its radius: a vertex on the arc's circle) is
/// the cone's apex, in it: its edges may lead into the cone whichever way
/// the rounding of its position points.
pub(crate) fn in_cone(arc: &CircularArc, centre: Point) -> bool {
    if arc.centre().distance(centre) <= 1e-9 * arc.radius() {
        return true;
    }
    if fault::active() {
        let c = arc.centre();
        let jiggled = Point::new(c.x + fault::perturb(centre.x - c.x), c.y + fault::perturb(centre.y - c.y));
        return arc.spans(jiggled);
    }
    arc.spans(centre)
}

/// How clearly the middle of a finite edge stays out of the new arc's cell
/// when both its ends are in it: the largest excess of the distance to the
/// arc over the distance to the edge's own sites along the edge (positive:
/// a middle piece stays), from 23 even fractions of it, refined
/// (`largest_excess`). Perturbed in fault injection.
pub(crate) fn arc_middle_margin(edge: FiniteEdge, _contact: EdgeContact, arc: &CircularArc) -> MiddleMargin {
    let fractions: Vec<f64> = (1..24).map(|k| k as f64 / 24.0).collect();
    let point_at = |t: f64| Some(bisector_point_on_edge(&edge.left, &edge.right, edge.from, edge.to, t));
    MiddleMargin::of(fault::perturb(largest_excess(&edge, arc, &fractions, point_at)))
}

/// [`arc_middle_margin`] for an unbounded edge, given from its finite end
/// (`edge.from`) to a point far out along it (`edge.to`), as the stretch
/// the arc may leave in the middle lies anywhere from near the finite end
/// to far out: from the chord at fractions halving down from 1/2 to
/// 2^-30; and where a site is a point, by the angle round it at 23 even
/// fractions and at fractions halving up to 1 - 2^-30, far out (the edge
/// may run the long way round the point from its finite end, where no
/// perpendicular from the chord meets it: an arc's start a hair outside
/// another arc's circle, the edge of that start and the other arc
/// wrapping round it, its stretch outside the new arc's cone kept).
pub(crate) fn arc_middle_margin_on_ray(edge: FiniteEdge, arc: &CircularArc) -> MiddleMargin {
    let (left, right, from, to) = (&edge.left, &edge.right, edge.from, edge.to);
    let halving: Vec<f64> = (1..=30).rev().map(|k| 0.5f64.powi(k)).collect();
    let from_chord = largest_excess(&edge, arc, &halving, |t| Some(bisector_point(left, right, from, to, t)));
    let round: Vec<f64> = (1..24).map(|k| k as f64 / 24.0).chain((5..=30).map(|k| 1.0 - 0.5f64.powi(k))).collect();
    let round = largest_excess(&edge, arc, &round, |t| round_point_site(left, right, from, to, t));
    MiddleMargin::of(fault::perturb(from_chord.max(round)))
}

/// [`arc_middle_margin`] for an edge with both ends at infinity between
/// two sites, one of them a point `p` (a whole bisector: an arc's end a
/// hair outside another arc's circle keeps a cell with no finite vertex,
/// a sliver out to infinity round that circle's radius). Its finite point
/// nearest `p` is halfway from `p` to its foot on the other site (equally
/// far from both, the foot being the other's nearest point to it); the
/// edge is that point and the two rays from it toward its ends'
/// directions (`toward_origin`, `toward_target`). `None` where neither site is a
/// point.
pub(crate) fn arc_middle_margin_on_line(
    (left, right): (&Site, &Site),
    toward_origin: Point,
    toward_target: Point,
    arc: &CircularArc,
) -> Option<MiddleMargin> {
    let (p, other) = match (left.as_point(), right.as_point()) {
        (Some(p), _) => (p, right),
        (None, Some(p)) => (p, left),
        (None, None) => return None,
    };
    let foot = other.nearest_point(p);
    let middle = Point::new(0.5 * (p.x + foot.x), 0.5 * (p.y + foot.y));
    let reach = 1e3 * (middle.x.abs() + middle.y.abs() + p.distance(foot) + 1.0);
    let far = |d: Point| Point::new(middle.x + reach * d.x, middle.y + reach * d.y);
    let there = FiniteEdge { left: *left, right: *right, from: middle, to: middle };
    let at_middle = excess_at(&there, arc, middle).0;
    let to_target = FiniteEdge { left: *left, right: *right, from: middle, to: far(toward_target) };
    let to_origin = FiniteEdge { left: *right, right: *left, from: middle, to: far(toward_origin) };
    let rays = [to_target, to_origin].map(|ray| arc_middle_margin_on_ray(ray, arc).margin());
    Some(MiddleMargin::of(fault::perturb(at_middle.max(rays[0]).max(rays[1]))))
}

/// The excess of the new arc's distance over the edge's own at `q`, and
/// the edge's own distance there (see `largest_excess`).
fn excess_at(edge: &FiniteEdge, arc: &CircularArc, q: Point) -> (f64, f64) {
    let own = 0.5 * (edge.left.distance(q) + edge.right.distance(q));
    (if arc.spans(q) { Site::Arc(*arc).distance(q) - own } else { outside_cone(arc, q) }, own)
}

/// The largest excess of the new arc's distance over the edge's own at
/// its points `point_at(t)`, `t` over the increasing `fractions`; where
/// none is positive, refined between the neighbours of the largest by a
/// golden-section search where it is lost by less than a twentieth of
/// the distance to the sites (a middle that stays can be far narrower than the
/// samples' spacing: a point a hair inside an arc's circle keeps a needle
/// of a cell, from the point to the centre, which crosses the point's
/// other edges).
///
/// A point outside the arc's cone stays out of its cell whatever the
/// distances say (there the arc is as far as its nearer end, a site
/// already: a tie where that end is one of the edge's sites), by as much
/// as it lies outside the cone: an edge of the arc's end running round it
/// keeps its stretch past the arc's end.
fn largest_excess(edge: &FiniteEdge, arc: &CircularArc, fractions: &[f64], point_at: impl Fn(f64) -> Option<Point>) -> f64 {
    // (the excess, and the edge's own distance there)
    let excess = |t: f64| Some(excess_at(edge, arc, point_at(t)?));
    let mut best = (f64::NEG_INFINITY, 0.0, None);
    for (k, &t) in fractions.iter().enumerate() {
        if let Some((e, own)) = excess(t) {
            if e > best.0 || best.0.is_nan() {
                best = (e, own, Some(k));
            }
        }
    }
    let (found, own, Some(k)) = best else { return best.0 };
    // clearly lost (by a twentieth of the distance to the sites there, as
    // nearly every edge an arc takes is): no search
    if found > 0.0 || !(found > -0.05 * own) {
        return found;
    }
    let (mut lo, mut hi) = (if k > 0 { fractions[k - 1] } else { 0.0 }, fractions.get(k + 1).copied().unwrap_or(1.0));
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    let value = |t: f64| excess(t).map_or(f64::NEG_INFINITY, |(e, _)| e);
    let (mut x1, mut x2) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
    let (mut e1, mut e2) = (value(x1), value(x2));
    let mut most = found.max(e1).max(e2);
    for _ in 0..30 {
        if most > 0.0 {
            break;
        }
        if e1 >= e2 {
            (hi, x2, e2) = (x2, x1, e1);
            x1 = hi - ratio * (hi - lo);
            e1 = value(x1);
            most = most.max(e1);
        } else {
            (lo, x1, e1) = (x1, x2, e2);
            x2 = lo + ratio * (hi - lo);
            e2 = value(x2);
            most = most.max(e2);
        }
    }
    most
}

/// How far `q` lies from the arc's cone, outside it: its distance to the
/// nearer of the cone's two bounding rays, from the centre through the
/// arc's ends.
fn outside_cone(arc: &CircularArc, q: Point) -> f64 {
    let c = arc.centre();
    let to_ray = |end: Point| {
        let (ux, uy) = (end.x - c.x, end.y - c.y);
        let (qx, qy) = (q.x - c.x, q.y - c.y);
        let along = ux * qx + uy * qy;
        if along > 0.0 {
            (ux * qy - uy * qx).abs() / ux.hypot(uy)
        } else {
            qx.hypot(qy)
        }
    };
    to_ray(arc.start()).min(to_ray(arc.end()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    fn no_sites() -> [Site; 3] {
        unreachable!("clear depths are not refined")
    }

    #[test]
    fn depth_from_outside_and_at_an_endpoint() {
        let arc = CircularArc::from_bulge([1.0, 0.0], [-1.0, 0.0], 1.0).unwrap();
        // a circle around (0, 3) of radius 1.5 reaches the arc's top (0, 1)
        assert!(arc_depth(&arc, ArcContact::NoEnd, p(0.0, 3.0), 2.5, no_sites).depth() < 0.0);
        assert!(arc_depth(&arc, ArcContact::NoEnd, p(0.0, 3.0), 1.5, no_sites).depth() > 0.0);
        // a circle through the start (1, 0) centred at (1, 2): the arc
        // leaves (1, 0) straight up, into it
        let at_start = ArcContact::OneEnd { end: p(1.0, 0.0), after: None, before: None };
        assert!(arc_depth(&arc, at_start, p(1.0, 2.0), 2.0, no_sites).depth() < 0.0);
        assert!(arc_depth(&arc, at_start, p(1.0, -2.0), 2.0, no_sites).depth() > 0.0);
        // (the vertices below, of the start and two more points: the exact
        // turn is asked, and finds them tangent too)
        let points = |b: Point, c: Point| move || [Site::Point(p(1.0, 0.0)), Site::Point(b), Site::Point(c)];
        // tangent at the start: centred at (3, 0), radius 2, the arc curves away
        assert!(arc_depth(&arc, at_start, p(3.0, 0.0), 2.0, points(p(5.0, 0.0), p(3.0, 2.0))).depth() > 0.0);
        // centred at (0.5, 0), radius 0.5: tangent, the arc's circle is larger: misses
        assert!(arc_depth(&arc, at_start, p(0.5, 0.0), 0.5, points(p(0.0, 0.0), p(0.5, 0.5))).depth() > 0.0);
        // centred at (-1, 0), radius 2: tangent, the arc's circle (radius 1) is sharper: enters
        assert!(arc_depth(&arc, at_start, p(-1.0, 0.0), 2.0, points(p(-3.0, 0.0), p(-1.0, 2.0))).depth() < 0.0);
        // a circle 1e16 across through the start and two points nearly in
        // line with it: the arc leaves the start up, into it by 1e-16 rad,
        // which the floating-point tangent sees as along it (and curving
        // away, out); the exact sign sees it enter
        let (b, c) = (p(1.0 + 1e-15, 4.0), p(1.0, 8.0));
        let far = crate::geometry::solvers::circumcircle(p(1.0, 0.0), b, c).unwrap().0;
        assert!(far.x < -1e14, "{far:?}");
        let radius = far.distance(p(1.0, 0.0));
        assert!(arc_depth(&arc, at_start, far, radius, points(b, c)).depth() < 0.0);
        let (b, c) = (p(1.0 - 1e-15, 4.0), p(1.0, 8.0));
        let far = crate::geometry::solvers::circumcircle(p(1.0, 0.0), b, c).unwrap().0;
        assert!(far.x > 1e14, "{far:?}");
        let radius = far.distance(p(1.0, 0.0));
        assert!(arc_depth(&arc, at_start, far, radius, points(b, c)).depth() < 0.0);
        // leaving out of it: the arc, curving toward its centre, comes back
        // in a hair further on where the circle is on the arc's side...
        let (b, c) = (p(1.0 + 1e-15, -4.0), p(1.0, -8.0));
        let far = crate::geometry::solvers::circumcircle(p(1.0, 0.0), b, c).unwrap().0;
        assert!(far.x < -1e14, "{far:?}");
        let radius = far.distance(p(1.0, 0.0));
        assert!(arc_depth(&arc, at_start, far, radius, points(b, c)).depth() < 0.0);
        // ...and stays out where it is not
        let (b, c) = (p(1.0 - 1e-15, -4.0), p(1.0, -8.0));
        let far = crate::geometry::solvers::circumcircle(p(1.0, 0.0), b, c).unwrap().0;
        assert!(far.x > 1e14, "{far:?}");
        let radius = far.distance(p(1.0, 0.0));
        assert!(arc_depth(&arc, at_start, far, radius, points(b, c)).depth() > 0.0);
    }

    #[test]
    fn sides_of_an_arc() {
        let ccw = CircularArc::from_bulge([1.0, 0.0], [-1.0, 0.0], 1.0).unwrap();
        let inside = Site::Point(p(0.0, 0.5));
        assert!(
            arc_left_degree(&ccw, ArcSiteSeen::Other { site: inside, from: None }).side()
                == crate::geometry::predicates::Orientation::CounterClockwise
        );
        let cw = ccw.reversed();
        assert!(
            arc_left_degree(&cw, ArcSiteSeen::Other { site: inside, from: None }).side()
                == crate::geometry::predicates::Orientation::Clockwise
        );
        // a segment continuing the arc's tangent at its start stays outside
        let tangent = Site::Segment { a: p(1.0, 0.0), b: p(1.0, -3.0) };
        let seen = ArcSiteSeen::SharingEndpoint { site: tangent, end: p(1.0, 0.0) };
        assert!(arc_left_degree(&ccw, seen).certainty().is_infinite());
        assert!(arc_left_degree(&ccw, seen).side() == crate::geometry::predicates::Orientation::Clockwise);
        assert!(in_cone(&ccw, p(0.3, 5.0)) && !in_cone(&ccw, p(0.3, -5.0)));
    }
}
