//! Where the construction puts a new vertex, from its sites only: the
//! solvers' circle (`solvers` for three points, `segment_solvers`, polished
//! by `oracle`, as soon as a segment is among them), the direction of a
//! vertex at infinity, and the fallbacks that keep the topology when the
//! numbers find no circle. The position is stored as the fault-injection
//! build perturbs it (`as_stored`).

use super::fault;
use super::oracle;
use super::point::Point;
use super::segment_solvers;
use super::site::Site;
use super::solvers::{circumcircle, left_normal};

/// The centre and radius of the vertex of three point sites `a`, `b`, `c`.
pub(crate) fn circle_of_points(a: Point, b: Point, c: Point) -> (Point, f64) {
    // No circle (only when the predicates were made to lie): keep the
    // topology, put the vertex at the centroid.
    circumcircle(a, b, c).unwrap_or_else(|| among_sites(&[Site::Point(a), Site::Point(b), Site::Point(c)]))
}

/// The centre and radius of the vertex of three sites, some of them
/// segments.
#[inline]
pub(crate) fn circle_of_sites(sites: &[Site; 3]) -> (Point, f64) {
    // No circle: keep the topology, place the vertex among its sites.
    solved_circle(sites).unwrap_or_else(|| among_sites(sites))
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
    } else {
        oracle::polish_vertex(sites, solved, ill_conditioned).or(solved)
    }
}

/// The condition (see `segment_solvers::Solved`) above which a solver's
/// `f64` circle is solved again in double-double: an error above about
/// 2e-13 of the configuration's size. Such an error moves a vertex along
/// directions in which its distances to its sites barely change (a far
/// vertex of nearly parallel lines slides along them), so the sites'
/// residuals alone do not show it.
const ILL_CONDITIONED: f64 = 1000.0;

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
