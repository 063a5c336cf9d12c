//! Where the construction puts a new vertex, from its sites only: the
//! solvers' circle (`solvers` for three points, `segment_solvers`, polished
//! by `oracle`, as soon as a segment is among them), the direction of a
//! vertex at infinity, and the fallbacks that keep the topology when the
//! numbers find no circle. The position is stored as the fault-injection
//! build perturbs it (`as_stored`).

use super::oracle;
use crate::geometry::arithmetic::bigfloat::BigFloat;
use crate::geometry::fault;
use crate::geometry::point::Point;
use crate::geometry::site::Site;
use crate::geometry::solvers::segment_solvers;
use crate::geometry::solvers::{circumcircle, left_normal};

/// The centre and radius of the vertex of three point sites `a`, `b`, `c`.
pub(crate) fn circle_of_points(a: Point, b: Point, c: Point) -> (Point, f64) {
    // No circle in `f64`: one beyond its range, or (only when the
    // predicates were made to lie) none; then keep the topology, put the
    // vertex at the centroid.
    let sites = [Site::Point(a), Site::Point(b), Site::Point(c)];
    circumcircle(a, b, c).or_else(|| beyond_range(&sites)).unwrap_or_else(|| among_sites(&sites))
}

/// The centre and radius of the vertex of three sites, some of them
/// segments.
///
/// `on`: for a vertex cut into an edge, that edge's ends before, by which
/// an arc's solver picks among circles in the same order the one on that
/// edge (`arcs::arc_vertex`).
#[inline]
pub(crate) fn circle_of_sites_on(sites: &[Site; 3], on: Option<[Point; 2]>) -> (Point, f64) {
    if sites.iter().any(|s| matches!(s, Site::Arc(_))) {
        // arcs: their own solver, in floating point (`arcs::arc_vertex`)
        return crate::geometry::arcs::arc_vertex::arc_vertex_on(sites, on)
            .or_else(|| on.and_then(|on| along_the_edge(sites, on)))
            .or_else(|| by_the_tangent_at_an_end(sites))
            .unwrap_or_else(|| among_sites(sites));
    }
    // No circle in `f64`: one beyond its range, or (only when the
    // predicates were made to lie) none; then keep the topology, place the
    // vertex among its sites.
    solved_circle(sites).or_else(|| beyond_range(sites)).unwrap_or_else(|| among_sites(sites))
}

/// The stored form of a vertex whose circle lies beyond the range of
/// `f64`, as big floats find it (an input whose magnitudes span more than
/// `f64`'s exponents: a point the least subnormal off a segment's line,
/// beside ordinary coordinates): the nearest `f64` point to its centre
/// (each coordinate beyond the range saturated at `±f64::MAX`) and an
/// infinite radius ([`oracle::is_beyond_range`]), by which the predicates
/// know to decide it from its sites alone. `None` when big floats find no circle either,
/// and in fault injection.
fn beyond_range(sites: &[Site; 3]) -> Option<(Point, f64)> {
    if fault::active() {
        // lying numbers find no circle for triples that have none; the
        // fallback among the sites is what the fault suite exercises
        return None;
    }
    let lift = |x: f64| BigFloat::from_f64(x, oracle::BEYOND_RANGE_BITS);
    let [x, y, r] = segment_solvers::vertex_in_any_range(sites, &lift)?;
    (r.to_f64() > f64::MAX).then(|| (Point::new(x.to_f64_saturated(), y.to_f64_saturated()), f64::INFINITY))
}

/// The circle of three sites, some of them segments, as accurately as the
/// construction places vertices; `None` when no arithmetic finds one.
pub(crate) fn solved_circle(sites: &[Site; 3]) -> Option<(Point, f64)> {
    let [ga, gb, gc] = sites;
    let solved = segment_solvers::vertex_and_condition(ga, gb, gc);
    let ill_conditioned = solved.map_or(true, |(_, _, condition)| condition > ILL_CONDITIONED);
    let solved = solved.map(|(c, r, _)| (c, r));
    // An ill-conditioned solve (nearly parallel lines, a circle far
    // larger than its sites), or none where rounding lost the circle, is
    // solved again finer and polished against the sites themselves.
    if fault::active() {
        solved
    } else if ill_conditioned {
        // Certainly polished, at a few microseconds; the same circle is
        // asked for again and again while one segment goes in (the path
        // search and the growth both ask for the two crossings of an edge,
        // and the placement for the vertex they become), so the answers
        // are remembered. A pure function of the sites, so the memo never
        // changes an answer.
        POLISHED.with(|memo| memo.borrow_mut().get_or_insert(sites, || oracle::polish_vertex(sites, solved).or(solved)))
    } else if solved.is_some_and(|(centre, radius)| !oracle::misses_its_sites(sites, centre, radius)) {
        // the common case, checked here so that it stays inline
        solved
    } else {
        oracle::polish_vertex(sites, solved).or(solved)
    }
}

thread_local! {
    /// The last polished circles, by their sites (see `solved_circle`).
    static POLISHED: std::cell::RefCell<Memo> = std::cell::RefCell::new(Memo::new());
}

/// Slots of the [`Memo`] (a power of two): enough for the crossings one
/// long segment's insertion asks about (each slot about 130 bytes).
const MEMO_SLOTS: usize = 512;

/// A direct-mapped memo from three sites (their kinds and coordinates, bit
/// for bit) to a circle: each triple has one slot, a later triple with the
/// same slot replaces it.
struct Memo(Vec<Option<Remembered>>);

/// Three sites bit for bit (see [`Memo::key`]) and their circle.
type Remembered = ([u64; 13], Option<(Point, f64)>);

impl Memo {
    fn new() -> Memo {
        Memo(vec![None; MEMO_SLOTS])
    }

    /// The circle remembered for `sites`, or `solve()`, then remembered.
    fn get_or_insert(&mut self, sites: &[Site; 3], solve: impl FnOnce() -> Option<(Point, f64)>) -> Option<(Point, f64)> {
        let key = Memo::key(sites);
        // FxHash's multiply-and-rotate over the key's words
        let hash = key.iter().fold(0u64, |h, &w| (h.rotate_left(5) ^ w).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95));
        let slot = &mut self.0[(hash >> 32) as usize & (MEMO_SLOTS - 1)];
        match slot {
            Some((k, circle)) if *k == key => *circle,
            _ => {
                let circle = solve();
                *slot = Some((key, circle));
                circle
            }
        }
    }

    /// The sites as words: per site its kind, then four coordinates (a
    /// point's twice), so no two different triples share a key.
    fn key(sites: &[Site; 3]) -> [u64; 13] {
        let mut key = [0u64; 13];
        for (k, site) in sites.iter().enumerate() {
            let (kind, a, b) = match *site {
                Site::Point(p) => (1, p, p),
                Site::Segment { a, b } => (2, a, b),
                // (not reached: arcs are placed by `arcs::arc_vertex`)
                Site::Arc(arc) => (3, arc.start(), arc.end()),
            };
            key[0] |= kind << (8 * k);
            key[1 + 4 * k..5 + 4 * k].copy_from_slice(&[a.x, a.y, b.x, b.y].map(f64::to_bits));
        }
        key
    }
}

/// The condition (see `segment_solvers::Solved`) above which a solver's
/// `f64` circle is solved again in double-double: an error above about
/// 2e-13 of the configuration's size. Such an error moves a vertex along
/// directions in which its distances to its sites barely change (a far
/// vertex of nearly parallel lines slides along them), so the sites'
/// residuals alone do not show it.
const ILL_CONDITIONED: f64 = 1000.0;

/// Where the arcs' solver finds no circle for a vertex cut into an edge
/// (`on`: its end that goes, then the one kept): the point of that edge
/// where the new site (the third) is as near as the edge's own two, by
/// bisection along the edge; `None` where the edge's ends are not on
/// either side of that point. The topology has decided that the vertex
/// is there; this keeps it on its edge, within rounding of its sites,
/// where the equations are too degenerate for the solver (an arc's end
/// a hair from the centre of another arc's circle: the separators of the
/// two meet at a tangent, a double root the solver places only to the
/// square root of the rounding, or misses).
fn along_the_edge(sites: &[Site; 3], [going, kept]: [Point; 2]) -> Option<(Point, f64)> {
    if !(going.is_finite() && kept.is_finite()) || going == kept {
        return None;
    }
    // the vertex's sites are the edge's right and left ones, then the new
    // site (`Construction::replace_tree`)
    let [right, left, new] = sites;
    let at = |t: f64| crate::geometry::curves::bisector::bisector_point_on_edge(left, right, going, kept, t);
    let gap = |q: Point| new.distance(q) - 0.5 * (left.distance(q) + right.distance(q));
    if !(gap(at(0.0)) <= 0.0 && gap(at(1.0)) > 0.0) {
        return None;
    }
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..64 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if gap(at(mid)) <= 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let q = at(0.5 * (lo + hi));
    let distances = sites.map(|s| s.distance(q));
    let radius = (distances[0] + distances[1] + distances[2]) / 3.0;
    let spread = distances.iter().map(|d| (d - radius).abs()).fold(0.0f64, f64::max);
    (q.is_finite() && spread <= 1e-9 * (radius + going.distance(kept))).then_some((q, radius))
}

/// Where the arcs' solver finds no circle for an arc, a point site at one
/// of its ends and a point or segment: the circle through that end
/// touching the arc there has its centre on the arc's normal at the end,
/// as one touching the arc's tangent there does, so it is the vertex of
/// the point, the other site and a segment along that tangent, which the
/// segments' solvers (with their big floats for far vertices) find. A
/// segment nearly along the normal of an arc's end leaves that circle far
/// away, 1e16 and more, beyond the arcs' solver (LibreCAD's LA-2: a line
/// 1.8e-16 rad off the tangent of a half circle's end, the vertex 6.5e16
/// out). Accepted where the three distances agree to 1e-9 of the radius.
fn by_the_tangent_at_an_end(sites: &[Site; 3]) -> Option<(Point, f64)> {
    let k = sites.iter().position(|s| matches!(s, Site::Arc(_)))?;
    let Site::Arc(arc) = sites[k] else { return None };
    if sites.iter().enumerate().any(|(j, s)| j != k && matches!(s, Site::Arc(_))) {
        return None;
    }
    let is_a_point_site = |e: Point| sites.contains(&Site::Point(e));
    let end = [arc.start(), arc.end()].into_iter().find(|&e| is_a_point_site(e))?;
    // a segment along the tangent at `end`, the arc's way (leaving its
    // start, arriving at its end), as long as the arc's chord
    let length = arc.start().distance(arc.end());
    let t = arc.tangent_into(end);
    let along = Point::new(end.x + length * t.x, end.y + length * t.y);
    let tangent = if end == arc.start() { Site::Segment { a: end, b: along } } else { Site::Segment { a: along, b: end } };
    let mut substituted = *sites;
    substituted[k] = tangent;
    let (centre, radius) = solved_circle(&substituted).or_else(|| beyond_range(&substituted))?;
    let spread = sites.iter().map(|s| (s.distance(centre) - radius).abs()).fold(0.0f64, f64::max);
    (centre.is_finite() && radius.is_finite() && spread <= 1e-9 * radius).then_some((centre, radius))
}

/// The fallback position of a vertex no solver can place: the centroid of
/// the points standing for its sites ([`Site::midpoint`]), the radius its
/// distance from the first site.
fn among_sites(sites: &[Site; 3]) -> (Point, f64) {
    let r = sites.map(|s| s.midpoint());
    let g = Point::new((r[0].x + r[1].x + r[2].x) / 3.0, (r[0].y + r[1].y + r[2].y) / 3.0);
    (g, sites[0].distance(g))
}

/// The unit direction of the edge at infinity between consecutive hull
/// sites `x → y` (the outside on the left): the left normal of two points
/// of theirs, a segment standing for itself by its endpoints (the one it
/// shares with a point site, then its other one); the zero vector when
/// they coincide.
pub(crate) fn direction_at_infinity(x: Site, y: Site) -> Point {
    if matches!(x, Site::Arc(_)) || matches!(y, Site::Arc(_)) {
        let guess = left_normal(x.midpoint(), y.midpoint()).unwrap_or_default();
        return crate::geometry::arcs::arc_vertex::direction_at_infinity(&x, &y, guess).unwrap_or(guess);
    }
    let (p, q) = match (x, y) {
        (Site::Segment { .. }, Site::Point(q)) => (x.other_endpoint(q).unwrap_or(x.midpoint()), q),
        (Site::Point(p), Site::Segment { .. }) => (p, y.other_endpoint(p).unwrap_or(y.midpoint())),
        _ => (x.midpoint(), y.midpoint()),
    };
    left_normal(p, q).unwrap_or_default()
}

/// A computed position as the store keeps it: itself, or in the
/// fault-injection build perturbed (so that every later question about
/// the vertex sees lying numbers).
#[inline]
pub(crate) fn as_stored(pos: Point) -> Point {
    if fault::active() {
        Point::new(fault::perturb(pos.x), fault::perturb(pos.y))
    } else {
        pos
    }
}
