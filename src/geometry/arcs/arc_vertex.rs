//! The Voronoi vertex of three sites among which is a circular arc: the
//! circle tangent to all three, touching them in the counter-clockwise
//! order given (Apollonius' problem and its mixed cases).
//!
//! Near a vertex, each site acts as one of three curves, and the vertex
//! `(x, t)` (centre `x`, radius `t`) satisfies one equation per site:
//! - a point `p`: `|x − p|² = t²`;
//! - a segment touched inside, on the side `σ = ±1` of its line (unit
//!   normal `n`): `n · (x − a) = σ t`;
//! - an arc's circle `(c, ρ)` touched from outside (`σ = +1`) or inside
//!   (`σ = −1`): `|x − c|² = (ρ + σ t)²`.
//!
//! Every quadratic equation has the same quadratic part `|x|² − t²`, so
//! the differences of two of them are linear: whatever the mix, the
//! system is two linear equations in `(x, y, t)` (a line of solutions)
//! and one quadratic along that line, up to two roots. Each choice of the
//! sides `σ` is solved; a candidate counts when `t ≥ 0`, every site is
//! touched within its own extent (a segment's foot inside it, an arc's
//! direction within its span) and the touching points lie around the
//! centre in the order given. The root chosen is the one that fits best
//! (the residuals of the true distances), so the answer is the circle
//! whose tangency pattern the topology asked for.
//!
//! Precision: floating point, relative to a local origin, then a few
//! Newton steps on the true distances. Not certified: the arcs' decisions
//! in `arc_predicates` compare these positions with tolerances.

use super::exact_join;
use crate::geometry::arithmetic::real::{norm, power_of_two, rounded_log2};
use crate::geometry::point::Point;
use crate::geometry::site::Site;

/// The circle of three sites of which at least one is an arc, in the
/// counter-clockwise order given; `None` when no candidate fits (the
/// caller falls back as for other sites).
#[cfg(test)]
pub(crate) fn arc_vertex(sites: &[Site; 3]) -> Option<(Point, f64)> {
    arc_vertex_on(sites, None)
}

/// [`arc_vertex`] for a vertex cut into the edge between the points `on`
/// (its ends: the one that goes, then the one kept; one far out for an
/// end at infinity), which tells apart two circles in the order asked
/// (`best_candidate`).
pub(crate) fn arc_vertex_on(sites: &[Site; 3], on: Option<[Point; 2]>) -> Option<(Point, f64)> {
    if let Some(vertex) = tangent_join_vertex(sites) {
        return Some(vertex);
    }
    if arcs_of_one_circle(sites) {
        if let Some(vertex) = centre_of_an_arc_touching_all(sites, true) {
            return Some(vertex);
        }
    }
    // near the origin and of size about 1 (a power of two: exact), so
    // that the tolerances below mean the same at every magnitude
    let origin = local_origin(sites);
    let size = sites.iter().map(|s| site_size(s, origin)).fold(0.0f64, f64::max);
    if !(size > 0.0 && size.is_finite()) {
        return None;
    }
    let unit = power_of_two(-(rounded_log2(size) as i32));
    let local: [Site; 3] = std::array::from_fn(|k| shifted(&sites[k], origin, unit));
    let on = on.map(|ends| ends.map(|p| Point::new((p.x - origin.x) * unit, (p.y - origin.y) * unit)));
    let scale = local.iter().map(|s| site_size(s, Point::new(0.0, 0.0))).fold(0.0f64, f64::max);
    // a piece is touched at an end only where another site of the
    // triple is that point or ends there (`equations_of`)
    let options: [[Option<Touching>; 4]; 3] = std::array::from_fn(|k| {
        let shared = |e: Point| (0..3).any(|j| j != k && (local[j].as_point() == Some(e) || local[j].has_endpoint(e)));
        let mut options = touchings(&local[k]).map(|t| t.filter(|t| !matches!(*t, Touching::AtEnd(e) if !shared(e))));
        // An arc's end that is a point site of the triple comes first: a
        // circle through that end touches the arc there (a circle tangent
        // to the arc's circle elsewhere would meet it twice), where the
        // sides inside give the same circle only as a double root, to the
        // square root of the rounding (`at_an_end_point`)
        if let Site::Arc(arc) = &local[k] {
            if let Some(first) = [arc.start(), arc.end()].into_iter().position(|e| is_a_point_site(&local, e)) {
                options[..3 + first].rotate_right(1);
            }
        }
        options
    });
    // Only where no candidate fits (scores of 10 and more: `fit`) is a
    // vertex sought far away (`Reach`).
    let best = match best_candidate(&local, &options, scale, Reach::Near, on) {
        Some(near) if near.0 < 10.0 => Some(near),
        near => {
            let best = [near, best_candidate(&local, &options, scale, Reach::Far, on)]
                .into_iter()
                .flatten()
                .min_by(|a, b| a.0.total_cmp(&b.0));
            if !best.is_some_and(|b| b.0 < 10.0) {
                // nothing fits: an arc's centre, where all three sites are
                // as far from it as the arc (a point on its circle, an arc
                // touching that circle at their common end), is a vertex of
                // all three that the solvers, seeing one circle touch
                // another where a third site is, do not single out
                if let Some(vertex) = centre_of_an_arc_touching_all(sites, false) {
                    return Some(vertex);
                }
            }
            best
        }
    };
    let (score, centre, radius) = best?;
    // a fit to within rounding needs no Newton steps (most of the cost)
    let (centre, radius) = if score.fract() > 1e-14 { polish(&local, centre, radius) } else { (centre, radius) };
    let back = 1.0 / unit;
    Some((Point::new(centre.x * back + origin.x, centre.y * back + origin.y), radius.max(0.0) * back))
}

/// Whether two or more of the sites are arcs of one circle: their
/// equations are then one equation, which leaves the solvers a plane of
/// solutions (every point of the circle is as near from its centre).
fn arcs_of_one_circle(sites: &[Site; 3]) -> bool {
    let mut arcs = sites.iter().filter_map(|s| if let Site::Arc(a) = s { Some(a) } else { None });
    let Some(first) = arcs.next() else { return false };
    let mut others = arcs.peekable();
    others.peek().is_some() && others.all(|a| a.has_circle(first.centre(), first.radius()))
}

/// The centre of an arc among the sites where all three are as far from
/// it as the arc is (a point on its circle, a segment touching it, an arc
/// on it or touching it at a common end), with that radius: a vertex of
/// the three. `in_order`: only if they touch it counter-clockwise round
/// in the order asked (`touched_from`). Two arcs a rounding off one
/// circle, meeting at a join, have the normal there for their bisector; a
/// third site touching the circle elsewhere is as far from the centre,
/// but the vertex asked for with the sites the other way round lies out
/// along that normal, and the centre need not even be empty (LibreCAD's
/// ed83). Where nothing else fits, the order is not asked: at a cusp of
/// two arcs whose stretch from the centre to the cusp ties them, the
/// centre holds two vertices, one of them with the sites in either order
/// (Chair-sofa-V).
///
/// Where nothing else fits, the sites are asked to touch the circle only
/// to 1e-7 of its radius: two arcs of circles a rounding apart (ends
/// written to 8 decimals), not sharing an end, have their vertices with a
/// third site on the circle in a cluster that close to the centre, where
/// the solvers' equations are one equation to rounding.
fn centre_of_an_arc_touching_all(sites: &[Site; 3], in_order: bool) -> Option<(Point, f64)> {
    let within = if in_order { 1e-9 } else { 1e-7 };
    sites.iter().find_map(|s| match s {
        Site::Arc(arc) => {
            let (c, r) = (arc.centre(), arc.radius());
            let touching = sites.iter().all(|t| (t.distance(c) - r).abs() <= within * r);
            (touching && !(in_order && clockwise_around(sites, c, r))).then_some((c, r))
        }
        _ => None,
    })
}

/// Whether the sites, each touching the circle of centre `c` and radius
/// `r`, touch it clockwise round in the order given (`touched_from`).
fn clockwise_around(sites: &[Site; 3], c: Point, r: f64) -> bool {
    let [p, q, w] = sites.each_ref().map(|s| touched_from(s, c));
    orientation_value(p, q, w) < -1e-9 * r * r
}

/// Where a vertex at `c` touches `site`: its nearest point, but for an arc
/// centred at `c` (within rounding), every point of which is as near, its
/// middle (arcs of one circle do not overlap, so their middles keep their
/// order round it).
fn touched_from(site: &Site, c: Point) -> Point {
    let spans = matches!(site, Site::Arc(arc) if arc.spans(c));
    touched_from_spanning(site, c, spans)
}

/// [`touched_from`] where whether an arc spans `c` is known already.
fn touched_from_spanning(site: &Site, c: Point, spans: bool) -> Point {
    match site {
        Site::Arc(arc) if arc.centre().distance(c) <= 1e-9 * arc.radius() => arc.midpoint(),
        Site::Arc(arc) => arc.nearest_point_spanning(c, spans),
        _ => site.nearest_point(c),
    }
}

/// How far from its sites a vertex is sought. `Near`: where the lines of
/// solutions are clearly apart from parallel (the vertex within about
/// 1e12 of the sites' size) and a segment's foot inside it to 1e-9.
/// `Far`: beyond, where two sites nearly in line (an arc's end a rounding
/// below the line of a segment, say) put it 1e15 away, a segment's foot
/// then moving along it with the rounding of the vertex's position. Far
/// is asked only where nothing near fits: its looser tests would take
/// the wrong circle where a near one exists.
#[derive(Clone, Copy, PartialEq)]
enum Reach {
    Near,
    Far,
}

/// The best fitting `(score, centre, radius)` among the candidates of
/// every tangency pattern in `options`: a fit to within rounding with
/// every site touched inside or at a point site is the answer, no other
/// candidate fits better (the sides inside come first, the most common
/// tangency).
fn best_candidate(
    local: &[Site; 3],
    options: &[[Option<Touching>; 4]; 3],
    scale: f64,
    reach: Reach,
    on: Option<[Point; 2]>,
) -> Option<(f64, Point, f64)> {
    let mut best: Option<(f64, Point, f64, [Touching; 3])> = None;
    let mut common_end = None;
    'patterns: for &t0 in options[0].iter().flatten() {
        for &t1 in options[1].iter().flatten() {
            for &t2 in options[2].iter().flatten() {
                let touch = [t0, t1, t2];
                let Some(equations) = equations_of(local, touch, scale) else { continue };
                for (centre, radius) in solve(&equations, reach).into_iter().flatten() {
                    let Some(score) = fit(local, touch, centre, radius, scale, reach) else { continue };
                    if on.is_some() && at_a_common_end(local, centre, radius, scale) {
                        // weighed against the others below, by the edge
                        common_end = common_end.or(Some((score, centre, radius, touch)));
                        continue;
                    }
                    if best.map_or(true, |(s, c, ..)| better(local, (score, centre), (s, c), on)) {
                        best = Some((score, centre, radius, touch));
                    }
                    // (a circle past the edge's kept end does not end the search)
                    if score < 1e-14 && past_kept_end(local, on, centre) != Some(true) {
                        break 'patterns;
                    }
                }
            }
        }
    }
    // Three pieces meeting at one end have a circle of radius zero there
    // that touches them in any order. Where another circle fits in the
    // order asked, the vertex is the one nearer the edge's end that goes
    // (the new site's region along the edge starts there): a line out of
    // a join of two arcs of one circle meets the other arc's cell on the
    // join's radius, not at the join.
    best = match (best, common_end, on) {
        (Some(other), Some(end), Some([going, _])) if other.0 < 10.0 => {
            Some(if end.1.distance(going) < other.1.distance(going) { end } else { other })
        }
        (None, end, _) => end,
        (other, _, _) => other,
    };
    let (score, centre, radius, touch) = best?;
    Some(at_an_end_point(local, touch, (centre, radius), options, scale, reach).unwrap_or((score, centre, radius)))
}

/// Whether the candidate `(score, centre)` is better than `than`: the
/// lower score; where both fit with as many pieces touched at an end with
/// nothing there (the same whole part of their scores, `fit`) and the
/// vertex is cut into an edge (`on`), the one on the edge
/// (`past_kept_end`), else the one nearer the edge's end that goes, where the
/// new site's region along the edge starts. Two such circles in the order
/// asked are a degenerate stretch (two arcs of one circle and a line out
/// of their join tie along the join's radius), or the other lies on the
/// same bisector past the edge's kept end (the edge of an arc's end a
/// hair outside another arc's circle runs round the end, and the new arc
/// ending there takes it from its far side), and only the one on the edge
/// is this vertex.
fn better(local: &[Site; 3], (score, centre): (f64, Point), (than, at): (f64, Point), on: Option<[Point; 2]>) -> bool {
    match on {
        Some([going, _]) if score < 10.0 && than < 10.0 && score.floor() == than.floor() => {
            if let (Some(past), Some(than_past)) = (past_kept_end(local, on, centre), past_kept_end(local, on, at)) {
                if past != than_past {
                    return !past;
                }
            }
            let (d, e) = (centre.distance(going), at.distance(going));
            d < e || d == e && score < than
        }
        _ => score < than,
    }
}

/// Whether `centre` lies past the kept end of the edge `on` (its end that
/// goes, then the one kept) into which the vertex of `local` is cut, when
/// the edge is that of a point and a segment or an arc: whether it takes
/// a greater turn round the point from the end that goes than the kept
/// end does. The vertex's sites are the edge's right and left ones, then
/// the new site (`Construction::replace_tree`), and the edge runs round
/// the point with its cell on the left (`bisector::round_point_site`).
/// `None` for other edges. (Signs of products, no angles: this is asked
/// of nearly every vertex an arc makes.)
fn past_kept_end(local: &[Site; 3], on: Option<[Point; 2]>, centre: Point) -> Option<bool> {
    let [going, kept] = on?;
    let (p, counter_clockwise) = match (local[0], local[1]) {
        (Site::Point(_), Site::Point(_)) => return None,
        (other, Site::Point(p)) if other.as_point().is_none() => (p, true),
        (Site::Point(p), _) => (p, false),
        _ => return None,
    };
    // directions from the point, mirrored for a clockwise turn
    let from = |q: Point| (q.x - p.x, if counter_clockwise { q.y - p.y } else { p.y - q.y });
    let (u, k, c) = (from(going), from(kept), from(centre));
    let cross = |a: (f64, f64), b: (f64, f64)| a.0 * b.1 - a.1 * b.0;
    let dot = |a: (f64, f64), b: (f64, f64)| a.0 * b.0 + a.1 * b.1;
    if dot(u, k) < 0.0 && cross(u, k).abs() <= 1e-9 * dot(u, k).abs() {
        // the ends half a turn apart round the point: the edge is a line
        // through it (the separator of a piece's free end and the piece),
        // and past its kept end means further along that line
        let along = (c.0 - k.0, c.1 - k.1);
        return Some(dot(along, (k.0 - u.0, k.1 - u.1)) > 0.0);
    }
    // the half turn a direction lies in, counter-clockwise from `u`
    let half = |v: (f64, f64)| u8::from(!(cross(u, v) > 0.0 || (cross(u, v) == 0.0 && dot(u, v) > 0.0)));
    Some(match half(c).cmp(&half(k)) {
        std::cmp::Ordering::Equal => cross(k, c) > 0.0,
        order => order == std::cmp::Ordering::Greater,
    })
}

/// Whether `(centre, radius)` is the circle of radius zero at an end all
/// three pieces share (no point site among them), to 1e-6 of their size:
/// the separators of two arcs of one circle there are one line, along
/// which the solvers place that circle only to the square root of the
/// rounding.
fn at_a_common_end(sites: &[Site; 3], centre: Point, radius: f64, scale: f64) -> bool {
    let near = 1e-6 * scale;
    if radius.abs() > near || sites.iter().any(|s| s.as_point().is_some()) {
        return false;
    }
    let [a, b] = sites[0].ends();
    let e = if a.distance(centre) <= b.distance(centre) { a } else { b };
    e.distance(centre) <= near && sites[1..].iter().all(|s| s.has_endpoint(e))
}

/// The same vertex solved again where `touch` has an arc touched inside
/// a hair from an end whose point is another of the three sites: there
/// the circle's distances to the arc and to the point agree to second
/// order, a double root the solvers place only to the square root of the
/// rounding (LibreCAD's Logic-NAND: 5e-8 off, which put a vertex outside
/// the new arc's cone and stopped its growth). With the end's separator
/// for the arc's equation (`Touching::AtEnd`) it is a simple root: the
/// solution of that pattern within 1e-6 of the first, if one fits.
fn at_an_end_point(
    local: &[Site; 3],
    touch: [Touching; 3],
    (centre, radius): (Point, f64),
    options: &[[Option<Touching>; 4]; 3],
    scale: f64,
    reach: Reach,
) -> Option<(f64, Point, f64)> {
    let near = 1e-6 * (scale + radius.abs());
    (0..3).find_map(|k| {
        let (Site::Arc(arc), Touching::Inside(_)) = (&local[k], touch[k]) else { return None };
        // (the ends that are point sites first: most arcs have none here,
        // and then no nearest point is sought)
        let ends = [arc.start(), arc.end()].map(|e| is_a_point_site(local, e).then_some(e));
        if ends == [None, None] {
            return None;
        }
        let q = arc.nearest_point(centre);
        let end = ends.into_iter().flatten().find(|&e| q.distance(e) <= near)?;
        if !options[k].contains(&Some(Touching::AtEnd(end))) {
            return None;
        }
        let mut again = touch;
        again[k] = Touching::AtEnd(end);
        let equations = equations_of(local, again, scale)?;
        solve(&equations, reach).into_iter().flatten().filter(|&(c, _)| c.distance(centre) <= near).find_map(|(c, r)| {
            let score = fit(local, again, c, r, scale, reach)?;
            (score < 1.0).then_some((score, c, r))
        })
    })
}

/// The vertex of a point `J` and two pieces ending at `J`, one of them at
/// least an arc: at `J`, of radius zero, unless their tangents there are
/// exactly parallel. A circle through `J` that touches a piece ending
/// there touches it at `J` (it would cut a segment's line or an arc's
/// circle at `J` and touch it again elsewhere: three meetings), so its
/// centre is on that piece's normal at `J`, and two normals that are not
/// one line meet only at `J`. The turn is exact (`exact_join`): at a join
/// an ulp off straight the floating-point solvers see the whole normal as
/// solutions. Two arcs continuing each other along one tangent (their
/// normals one line, every point of it a solution) meet there too; the
/// other parallel cases go to the solvers.
fn tangent_join_vertex(sites: &[Site; 3]) -> Option<(Point, f64)> {
    let k = (0..3).find(|&k| sites[k].as_point().is_some())?;
    let j = sites[k].as_point()?;
    let (after, before) = (sites[(k + 1) % 3], sites[(k + 2) % 3]);
    let arcs = [after, before].iter().filter(|s| matches!(s, Site::Arc(_))).count();
    if arcs == 0 || !(after.has_endpoint(j) && before.has_endpoint(j)) {
        return None;
    }
    // a clear turn in floating point needs no exact one
    let direction = |s: &Site| match *s {
        Site::Arc(arc) => Some(arc.tangent_into(j)),
        _ => s.other_endpoint(j).map(|f| Point::new(f.x - j.x, f.y - j.y)),
    };
    if let (Some(u), Some(v)) = (direction(&after), direction(&before)) {
        let cross = (u.x * v.y - u.y * v.x) / (norm(u.x, u.y) * norm(v.x, v.y));
        if cross.abs() > 1e-6 {
            return Some((j, 0.0));
        }
    }
    let (t_after, t_before) = (exact_join::leaving(&after, j)?, exact_join::leaving(&before, j)?);
    if exact_join::cross_sign(&t_after, &t_before)? != 0 {
        return Some((j, 0.0));
    }
    (arcs == 2 && exact_join::dot_sign(&t_after, &t_before)? < 0).then_some((j, 0.0))
}

/// Where a vertex may touch a site: a point at itself; a segment or an arc
/// inside, on one side (`σ`: left of a segment, outside an arc's circle,
/// when `+1`), or at one of its ends.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Touching {
    Itself,
    Inside(f64),
    AtEnd(Point),
}

fn touchings(site: &Site) -> [Option<Touching>; 4] {
    match *site {
        Site::Point(_) => [Some(Touching::Itself), None, None, None],
        _ => {
            let [a, b] = site.ends();
            [Touching::Inside(1.0), Touching::Inside(-1.0), Touching::AtEnd(a), Touching::AtEnd(b)].map(Some)
        }
    }
}

/// The equations of `sites` touched as `touch` says. Where two sites are
/// touched at one point (an endpoint they share, or a point site and a
/// piece ending there), the second's equation would repeat the first's;
/// the vertex then lies on the piece's separator there (its normal line),
/// which takes its place. `None` where the pattern has no vertex of its
/// own: an end touched with nothing else there, or two arcs of one circle
/// (to 1e-9 of `scale`) touched alike (`arcs_of_one_circle_touched_alike`).
fn equations_of(sites: &[Site; 3], touch: [Touching; 3], scale: f64) -> Option<[Equation; 3]> {
    if arcs_of_one_circle_touched_alike(sites, touch, 1e-9 * scale) {
        return None;
    }
    let point_of = |k: usize| match touch[k] {
        Touching::Itself => sites[k].as_point(),
        Touching::AtEnd(e) => Some(e),
        Touching::Inside(_) => None,
    };
    // A piece is touched at an end only on its separator there, which
    // takes a second site touched at that point to say: alone, an end
    // would be a circle through it tangent to nothing (another vertex).
    for k in 0..3 {
        if let Touching::AtEnd(e) = touch[k] {
            if !(0..3).any(|j| j != k && point_of(j) == Some(e)) {
                return None;
            }
        }
    }
    let mut equations = [Equation::Circle { c: Point::new(0.0, 0.0), rho: 0.0, sigma: 1.0 }; 3];
    for k in 0..3 {
        equations[k] = match touch[k] {
            Touching::Inside(sigma) => Equation::of(&sites[k], sigma),
            Touching::Itself | Touching::AtEnd(_) => {
                let e = point_of(k)?;
                let repeats = (0..k).any(|j| point_of(j) == Some(e));
                if repeats {
                    let normal = separator_normal(&sites[k], e)
                        .or_else(|| (0..k).find(|&j| point_of(j) == Some(e)).and_then(|j| separator_normal(&sites[j], e)))?;
                    Equation::Line { n: normal, offset: normal.x * e.x + normal.y * e.y, sigma: 0.0 }
                } else {
                    Equation::Circle { c: e, rho: 0.0, sigma: 1.0 }
                }
            }
        };
    }
    Some(equations)
}

/// Whether two arcs whose circles are one to `near` (centres and radii)
/// are touched inside from the same side: their two equations are then
/// one to that, and the solvers' roots are noise (the pattern is not
/// solved at all). Arcs of one circle that
/// do not overlap share no direction from its centre but at a common end,
/// where their vertices are the end's pattern (`Touching::AtEnd`, the
/// circle through the end on the separator there) or the centre's
/// (`centre_of_an_arc_touching_all`). Taken, such a root was a vertex
/// 5e12 away at the join of two arcs of one circle, one of them a piece
/// the split flattened, 4.6e-12 off its neighbour's circle (LibreCAD's
/// t7).
fn arcs_of_one_circle_touched_alike(sites: &[Site; 3], touch: [Touching; 3], near: f64) -> bool {
    (0..3).any(|j| {
        (j + 1..3).any(|k| match (&sites[j], &sites[k], touch[j], touch[k]) {
            (Site::Arc(x), Site::Arc(y), Touching::Inside(s), Touching::Inside(t)) => {
                s == t && x.centre().distance(y.centre()) <= near && (x.radius() - y.radius()).abs() <= near
            }
            _ => false,
        })
    })
}

/// For a piece ending at `e`: the unit direction along it there, which is
/// the normal of its separator at `e` (the line through `e` across it).
fn separator_normal(site: &Site, e: Point) -> Option<Point> {
    let (dx, dy) = match site {
        Site::Segment { a, b } => (b.x - a.x, b.y - a.y),
        Site::Arc(arc) => (-(e.y - arc.centre().y), e.x - arc.centre().x),
        _ => return None,
    };
    let n = norm(dx, dy);
    (n > 0.0 && n.is_finite()).then(|| Point::new(dx / n, dy / n))
}

/// One site's equation, in the local frame: quadratic
/// `|x|² − 2 c·x + |c|² − (ρ + σ t)² = 0`, or linear `n·x − n·a − σ t = 0`
/// (`σ = 0`: a line the centre lies on).
#[derive(Clone, Copy, Debug)]
enum Equation {
    Circle { c: Point, rho: f64, sigma: f64 },
    Line { n: Point, offset: f64, sigma: f64 },
}

impl Equation {
    fn of(site: &Site, sigma: f64) -> Equation {
        match site {
            &Site::Point(p) => Equation::Circle { c: p, rho: 0.0, sigma: 1.0 },
            &Site::Segment { a, b } => {
                let (dx, dy) = (b.x - a.x, b.y - a.y);
                let len = norm(dx, dy);
                let n = Point::new(-dy / len, dx / len);
                Equation::Line { n, offset: n.x * a.x + n.y * a.y, sigma }
            }
            Site::Arc(arc) => Equation::Circle { c: arc.centre(), rho: arc.radius(), sigma },
        }
    }

    /// As a linear form `[x, y, t, constant]`, for a line; for a circle,
    /// its part besides `|x|² − t²`.
    fn linear_part(&self) -> [f64; 4] {
        match *self {
            Equation::Circle { c, rho, sigma } => [-2.0 * c.x, -2.0 * c.y, -2.0 * rho * sigma, c.x * c.x + c.y * c.y - rho * rho],
            Equation::Line { n, offset, sigma } => [n.x, n.y, -sigma, -offset],
        }
    }

    fn is_circle(&self) -> bool {
        matches!(self, Equation::Circle { .. })
    }
}

/// The solutions `(centre, radius)` of three equations (at most two).
fn solve(equations: &[Equation; 3], reach: Reach) -> [Option<(Point, f64)>; 2] {
    let Some(q) = equations.iter().position(Equation::is_circle) else { return [None; 2] };
    let base = equations[q].linear_part();
    // two linear equations: lines as they are, circles minus the base one
    // (the other two in order, in an array: no allocation per pattern)
    let others = match q {
        0 => [1, 2],
        1 => [0, 2],
        _ => [0, 1],
    };
    let linear: [[f64; 4]; 2] = others.map(|k| {
        let e = equations[k].linear_part();
        if equations[k].is_circle() {
            std::array::from_fn(|i| e[i] - base[i])
        } else {
            e
        }
    });
    let (n1, n2) = ([linear[0][0], linear[0][1], linear[0][2]], [linear[1][0], linear[1][1], linear[1][2]]);
    let (d1, d2) = (-linear[0][3], -linear[1][3]);
    let d = cross3(n1, n2);
    let dd = dot3(d, d);
    let size = dot3(n1, n1).sqrt() * dot3(n2, n2).sqrt();
    let apart = if reach == Reach::Near { 1e-24 } else { 1e-40 };
    if !(dd > apart * size * size) {
        return [None; 2];
    }
    // the point of the line nearest the origin
    let (u, v) = (cross3(n2, d), cross3(d, n1));
    let p: [f64; 3] = std::array::from_fn(|i| (d1 * u[i] + d2 * v[i]) / dd);
    // along the line by a unit step, so that the test below for a lightlike
    // line (one root at infinity) does not depend on how long `d` came out
    let length = dd.sqrt();
    let d = d.map(|x| x / length);
    // the base quadratic along p + λ d: |x|² − t² + base · (x, y, t, 1)
    let quad = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] - a[2] * b[2];
    let qa = quad(d, d);
    let qb = 2.0 * quad(p, d) + base[0] * d[0] + base[1] * d[1] + base[2] * d[2];
    let qc = quad(p, p) + base[0] * p[0] + base[1] * p[1] + base[2] * p[2] + base[3];
    let at = |l: f64| (Point::new(p[0] + l * d[0], p[1] + l * d[1]), p[2] + l * d[2]);
    let mut roots = [None; 2];
    if qa.abs() <= 1e-14 {
        // Near, a slope within the rounding of the terms it is made of is
        // no slope: its root, 1/rounding away, is noise. (A line out of a
        // tangent join whose third circle is flattened by a hair: the
        // exact equations have no root, rounding gave one 1e15 away,
        // below the line, that fit every distance to rounding.)
        let terms = 2.0 * (p[0] * d[0]).abs()
            + 2.0 * (p[1] * d[1]).abs()
            + 2.0 * (p[2] * d[2]).abs()
            + (base[0] * d[0]).abs()
            + (base[1] * d[1]).abs()
            + (base[2] * d[2]).abs();
        let noise = if reach == Reach::Near { 1e-12 * terms } else { 0.0 };
        if qb.abs() > noise {
            roots[0] = Some(at(-qc / qb));
            // the other root, far out along the line (the roots sum to
            // −qb/qa): sought only far
            if reach == Reach::Far && qa != 0.0 {
                roots[1] = Some(at(-qb / qa + qc / qb));
            }
        }
        return roots;
    }
    let disc = qb * qb - 4.0 * qa * qc;
    // a discriminant within rounding of zero is a double root
    let disc = if disc < 0.0 && disc > -1e-12 * qb * qb { 0.0 } else { disc };
    if disc < 0.0 {
        return roots;
    }
    let s = disc.sqrt();
    // the stable pair of roots
    let w = -0.5 * (qb + s.copysign(qb));
    if w != 0.0 {
        roots = [Some(at(w / qa)), Some(at(qc / w))];
    } else {
        roots[0] = Some(at(0.0));
    }
    roots
}

/// How well `(centre, radius)` fits as the vertex of `sites` touched as
/// `touch` says (smaller is better); `None` when it is not one: a negative
/// radius, a site touched elsewhere than said, or the touching points in
/// the wrong order.
fn fit(sites: &[Site; 3], touch: [Touching; 3], centre: Point, radius: f64, scale: f64, reach: Reach) -> Option<f64> {
    if !centre.is_finite() || !radius.is_finite() {
        return None;
    }
    let slack = 1e-9 * (scale + radius.abs());
    if radius < -slack {
        return None;
    }
    // whether each arc spans the centre: asked once (for arcs, most of
    // the cost of what follows), in the loop (which rejects most roots
    // that do not fit, before the later arcs)
    let mut spans = [false; 3];
    for (k, (site, touching)) in sites.iter().zip(touch).enumerate() {
        if let Site::Arc(arc) = site {
            spans[k] = arc.spans(centre);
        }
        match (site, touching) {
            (&Site::Segment { a, b }, Touching::Inside(sigma)) => {
                // on the side σ (or on the line), the foot inside
                let (dx, dy) = (b.x - a.x, b.y - a.y);
                let cross = (dx * (centre.y - a.y) - dy * (centre.x - a.x)) / norm(dx, dy);
                if sigma * cross < -slack {
                    return None;
                }
                // (the foot of a vertex far away moves along the segment by
                // the rounding of its centre: `slack` along the segment)
                let t = crate::geometry::site::segment_parameter(a, b, centre);
                let along = if reach == Reach::Near { 1e-9 } else { 1e-9 + slack / norm(dx, dy) };
                if !(t > -along && t < 1.0 + along) {
                    return None;
                }
            }
            (Site::Arc(arc), Touching::Inside(sigma)) => {
                let d = arc.centre().distance(centre);
                if sigma < 0.0 && d > arc.radius() + slack || sigma > 0.0 && d < arc.radius() - slack {
                    return None;
                }
                // touched inside the span (or within rounding of an end):
                // a circle tangent to the arc's circle elsewhere is not a
                // vertex of the arc, even where it passes through an end.
                // The touching point moves with the centre's rounding
                // (`slack`) shrunk by the radius over the distance: a
                // vertex far out touches an arc within a millionth of its
                // radius of where its direction says (it was let touch an
                // arc 60 long 3.6 degrees past its end when 1e14 away,
                // a thousand slacks being 1.5e8: LibreCAD's door d2)
                if !spans[k] {
                    let c = arc.centre();
                    let k = arc.radius() / d;
                    let q = Point::new(c.x + k * (centre.x - c.x), c.y + k * (centre.y - c.y));
                    let moves = 1e3 * slack * k.min(1.0);
                    if q.distance(arc.start()).min(q.distance(arc.end())) > moves {
                        return None;
                    }
                }
            }
            (_, Touching::AtEnd(e)) => {
                // the nearest point is that end (or as near)
                if (site.distance(centre) - e.distance(centre)).abs() > 1e3 * slack {
                    return None;
                }
            }
            _ => {}
        }
    }
    // where two sites touch at one point (a piece at its end, beside that
    // end's point site or another piece ending there), the piece is taken
    // a hair along itself from there: the limit order of the touching
    // points as the vertex moves off the separator to its side
    let plain: [Point; 3] = std::array::from_fn(|k| touched_from_spanning(&sites[k], centre, spans[k]));
    let near = 1e-9 * (scale + radius.abs());
    let touching: [Point; 3] = std::array::from_fn(|k| {
        let [a, b] = sites[k].ends();
        // (the nearer end where both are within `near`: a vertex far away,
        // whose `near` spans the whole piece)
        let end = [a, b]
            .into_iter()
            .filter(|&e| within(plain[k], e, near) && (0..3).any(|j| j != k && within(plain[j], e, near)))
            .min_by(|&e, &f| plain[k].distance(e).total_cmp(&plain[k].distance(f)));
        match (sites[k], end) {
            (Site::Segment { .. }, Some(e)) => {
                let far = if e == a { b } else { a };
                Point::new(e.x + 1e-6 * (far.x - e.x), e.y + 1e-6 * (far.y - e.y))
            }
            (Site::Arc(arc), Some(e)) => {
                let t = arc.tangent_into(e);
                let step = 1e-6 * arc.radius().min(arc.start().distance(arc.end()));
                Point::new(e.x + step * t.x, e.y + step * t.y)
            }
            _ => plain[k],
        }
    });
    let order = orientation_value(touching[0], touching[1], touching[2]);
    // touching points apart and in clockwise order: the other circle
    if order < -1e-12 * scale * scale {
        return None;
    }
    // (after the order, which rejects one root of most patterns)
    let distance = |k: usize| match &sites[k] {
        Site::Arc(arc) => arc.distance_spanning(centre, spans[k]),
        site => site.distance(centre),
    };
    let residual: f64 = (0..3).map(|k| (distance(k) - radius.max(0.0)).abs()).sum();
    // Two pieces touched at their common end with no point site there
    // stand for that end's own vertex (a circle through it), which fits
    // the distances too; it is this triple's vertex only where nothing
    // else fits (a tangent join, where the two separators are one line).
    let unbacked = (0..3).filter(|&k| matches!(touch[k], Touching::AtEnd(e) if !is_a_point_site(sites, e))).count();
    let fitting = residual <= 1e-6 * (scale + radius.abs());
    Some(if fitting { unbacked as f64 + residual / (scale + radius.abs()) } else { 10.0 + residual })
}

/// `p.distance(q) <= near`, the same answer, without the square root (or
/// `hypot`, for equal points) where it is plain: equal points, or a
/// squared distance (normal, so within a few roundings of the true one)
/// clearly beyond `near`'s square. `fit` asks this of every end of every
/// site against every touching point, most of them far apart.
#[inline]
fn within(p: Point, q: Point, near: f64) -> bool {
    if p == q {
        return 0.0 <= near;
    }
    let squared = p.distance_squared(q);
    let reach = near * near;
    if squared.is_normal() && reach.is_normal() && squared > reach * (1.0 + 1e-9) {
        return false;
    }
    p.distance(q) <= near
}

fn orientation_value(a: Point, b: Point, c: Point) -> f64 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

/// The unit direction of the edge at infinity between hull sites `x → y`
/// (the outside on the left) when an arc is among them: where the two
/// reach equally far out (their support functions agree) and `x`'s
/// farthest point comes before `y`'s along the supporting line, the root
/// nearest `guess`. `None` when no root is found.
pub(crate) fn direction_at_infinity(x: &Site, y: &Site, guess: Point) -> Option<Point> {
    // an arc and its own endpoint: their separator, the radial ray out
    // through the endpoint (the support functions only touch there)
    for (s, t) in [(x, y), (y, x)] {
        if let (Site::Arc(arc), Some(e)) = (*s, t.as_point()) {
            if arc.start() == e || arc.end() == e {
                let (dx, dy) = (e.x - arc.centre().x, e.y - arc.centre().y);
                let n = norm(dx, dy);
                return (n > 0.0).then(|| Point::new(dx / n, dy / n));
            }
        }
    }
    if let Some(u) = beside_a_point_on_the_circle(x, y) {
        return Some(u);
    }
    let origin = local_origin(&[*x, *y, *x]);
    let (x, y) = (shifted(x, origin, 1.0), shifted(y, origin, 1.0));
    let support = |s: &Site, d: Point| s.support(d);
    let at = |theta: f64| Point::new(theta.cos(), theta.sin());
    let f = |theta: f64| support(&x, at(theta)).0 - support(&y, at(theta)).0;
    let tie = 1e-12 * (site_size(&x, Point::new(0.0, 0.0)) + site_size(&y, Point::new(0.0, 0.0)));
    const STEPS: usize = 2048;
    let step = 2.0 * std::f64::consts::PI / STEPS as f64;
    let mut best: Option<(f64, Point)> = None;
    // (each step's end is the next one's start: its value is kept, not
    // computed again, which halves the scan)
    let mut f_next = f(0.0);
    for k in 0..STEPS {
        let (mut lo, mut hi) = (k as f64 * step, (k + 1) as f64 * step);
        let (mut flo, fhi) = (f_next, f(hi));
        f_next = fhi;
        // a zero at a step, to within rounding, is a root itself (a tie
        // along an arc's end, as for two equal half circles facing each
        // other, where the sign may not change across the step's ends); a
        // zero at the step's far end is the next step's
        let root = if flo.abs() <= tie {
            lo
        } else if fhi.abs() <= tie || flo.signum() == fhi.signum() {
            continue;
        } else {
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                let fm = f(mid);
                if fm.signum() == flo.signum() {
                    lo = mid;
                    flo = fm;
                } else {
                    hi = mid;
                }
            }
            0.5 * (lo + hi)
        };
        let d = at(root);
        let (tx, ty) = (support(&x, d).1, support(&y, d).1);
        // d is the left normal of tx → ty (as for two points)
        let left = (ty.x - tx.x) * d.y - (ty.y - tx.y) * d.x;
        if left < 0.0 {
            continue; // infinity would lie right of x → y
        }
        let closeness = d.x * guess.x + d.y * guess.y;
        if best.map_or(true, |(c, _)| closeness > c) {
            best = Some((closeness, d));
        }
    }
    best.map(|(_, d)| d)
}

/// For an arc and a point on its circle to rounding (within 1e-9 of the
/// radius) whose direction from the centre the arc's cone holds (or
/// misses by a microradian at an end): that direction. The two support
/// functions only touch there: a hair outside the circle they cross
/// twice within `sqrt(2 · hair / radius)` of it (7e-6 rad for a point
/// 2e-11 off a circle of radius 1.8), which the scan's steps of 3e-3 rad
/// step over; a hair inside they tie to rounding and never cross. The
/// scan then found no root, and the edge went to infinity in the
/// caller's guess, 0.08 degrees or more off (LibreCAD's Relay, a line
/// ending where it touches a circle).
fn beside_a_point_on_the_circle(x: &Site, y: &Site) -> Option<Point> {
    [(x, y), (y, x)].into_iter().find_map(|(s, t)| {
        let (Site::Arc(arc), Some(p)) = (*s, t.as_point()) else { return None };
        let c = arc.centre();
        let (dx, dy) = (p.x - c.x, p.y - c.y);
        let n = norm(dx, dy);
        if !(n > 0.0 && (n - arc.radius()).abs() <= 1e-9 * arc.radius()) {
            return None;
        }
        let u = Point::new(dx / n, dy / n);
        let near_end = [arc.start(), arc.end()].into_iter().any(|e| {
            let (ex, ey) = (e.x - c.x, e.y - c.y);
            let m = norm(ex, ey);
            m > 0.0 && ((ex * u.y - ey * u.x) / m).abs() <= 1e-6 && ex * u.x + ey * u.y > 0.0
        });
        (arc.spans_direction(u) || near_end).then_some(u)
    })
}

/// A few Newton steps on the true distances `d_k(x) − t = 0`.
fn polish(sites: &[Site; 3], mut centre: Point, mut radius: f64) -> (Point, f64) {
    let residuals = |c: Point, r: f64| sites.map(|s| s.distance(c) - r);
    let mut f = residuals(centre, radius);
    let mut size: f64 = f.iter().map(|x| x.abs()).sum();
    for _ in 0..3 {
        if !(size > 0.0) {
            break;
        }
        // the gradient of the distance to a site is the unit vector from
        // its nearest point; numerically only where the centre is on it
        let h = 1e-7 * (radius.abs() + centre.x.abs().max(centre.y.abs())).max(1e-300);
        let grad = |s: &Site| {
            let q = s.nearest_point(centre);
            let (dx, dy) = (centre.x - q.x, centre.y - q.y);
            let n = norm(dx, dy);
            if n > 0.0 && n.is_finite() {
                return [dx / n, dy / n, -1.0];
            }
            let dx =
                (s.distance(Point::new(centre.x + h, centre.y)) - s.distance(Point::new(centre.x - h, centre.y))) / (2.0 * h);
            let dy =
                (s.distance(Point::new(centre.x, centre.y + h)) - s.distance(Point::new(centre.x, centre.y - h))) / (2.0 * h);
            [dx, dy, -1.0]
        };
        let j = [grad(&sites[0]), grad(&sites[1]), grad(&sites[2])];
        let Some(step) = solve3(j, [-f[0], -f[1], -f[2]]) else { break };
        let next = (Point::new(centre.x + step[0], centre.y + step[1]), radius + step[2]);
        let next_f = residuals(next.0, next.1);
        let next_size: f64 = next_f.iter().map(|x| x.abs()).sum();
        if !(next_size < size) || !next.0.is_finite() {
            break;
        }
        (centre, radius, f, size) = (next.0, next.1, next_f, next_size);
    }
    (centre, radius)
}

/// Cramer's rule for a 3×3 system; `None` when singular.
fn solve3(m: [[f64; 3]; 3], r: [f64; 3]) -> Option<[f64; 3]> {
    let det = |m: [[f64; 3]; 3]| dot3(m[0], cross3(m[1], m[2]));
    let d = det(m);
    if !(d.abs() > 1e-300) || !d.is_finite() {
        return None;
    }
    let column = |k: usize| {
        let mut c = m;
        for i in 0..3 {
            c[i][k] = r[i];
        }
        det(c) / d
    };
    Some([column(0), column(1), column(2)])
}

fn cross3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// A point near the sites, to compute relative to: the mean of their ends'
/// midpoints (any point near them will do; an arc's own midpoint would
/// cost trigonometry for an arc given through a point).
fn local_origin(sites: &[Site; 3]) -> Point {
    let m = sites.map(|s| {
        let [a, b] = s.ends();
        Point::new(0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y)
    });
    Point::new((m[0].x + m[1].x + m[2].x) / 3.0, (m[0].y + m[1].y + m[2].y) / 3.0)
}

/// Whether `e` is one of the point sites among `sites`.
fn is_a_point_site(sites: &[Site; 3], e: Point) -> bool {
    sites.iter().any(|s| s.as_point() == Some(e))
}

/// The site moved by `-o`, then scaled by `unit` (a power of two).
fn shifted(site: &Site, o: Point, unit: f64) -> Site {
    let s = |p: Point| Point::new((p.x - o.x) * unit, (p.y - o.y) * unit);
    match site {
        &Site::Point(p) => Site::Point(s(p)),
        &Site::Segment { a, b } => Site::Segment { a: s(a), b: s(b) },
        Site::Arc(arc) => Site::Arc(arc.transformed(o, unit)),
    }
}

/// How far a site reaches from `origin` (its ends, and an arc's radius),
/// without moving it there.
fn site_size(site: &Site, origin: Point) -> f64 {
    let [a, b] = site.ends();
    let far = |p: Point| (p.x - origin.x).abs().max((p.y - origin.y).abs());
    match site {
        Site::Arc(arc) => far(a).max(far(b)).max(arc.radius()),
        _ => far(a).max(far(b)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::CircularArc;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    fn check(sites: [Site; 3], centre: Point, radius: f64) {
        let (c, r) = arc_vertex(&sites).unwrap_or_else(|| panic!("no vertex for {sites:?}"));
        assert!(c.distance(centre) < 1e-9 && (r - radius).abs() < 1e-9, "{c:?} {r} against {centre:?} {radius}");
    }

    #[test]
    fn a_vertex_thousands_of_sizes_away() {
        // a corner arc, its own end and a point nearly level with that end
        // 10.7 units along: the vertex is on the arc's separator at the
        // end, 54,418 units below (the line of solutions is nearly along
        // the radius: it was once taken for a lightlike one, no root)
        let end = p(37.49520944453021, 3.0563224950002255);
        let far = p(48.20689749505568, 3.0552683093191235);
        let arc = CircularArc::from_bulge(end, p(37.7002343595738, 3.261347410043811), 0.41421356237309503).unwrap();
        let sites = [Site::Point(end), Site::Point(far), Site::Arc(arc)];
        let (c, r) = arc_vertex(&sites).expect("a vertex");
        for s in &sites {
            assert!((s.distance(c) - r).abs() < 1e-9 * r, "{s:?} at {c:?} {r}");
        }
        assert!((c.y + 54418.2207).abs() < 1e-3 && (c.x - end.x).abs() < 1e-6, "{c:?}");
    }

    #[test]
    fn edges_at_infinity_where_the_supports_tie_at_a_step() {
        // a point and the upper half circle beside it, reaching equally
        // far right (x = 5) exactly at θ = 0, a sample of the search; and
        // mirrored, where the tie at θ = π is within rounding of one
        let arc = Site::Arc(CircularArc::from_bulge([4.0, 0.0], [5.0, 0.0], -1.0).unwrap());
        let d = direction_at_infinity(&Site::Point(p(5.0, 2.0)), &arc, p(0.0, -1.0)).unwrap();
        assert!(d.distance(p(1.0, 0.0)) < 1e-12, "{d:?}");
        let arc = Site::Arc(CircularArc::from_bulge([-0.0, 0.0], [-1.0, 0.0], 1.0).unwrap());
        let d = direction_at_infinity(&arc, &Site::Point(p(-1.0, 2.0)), p(0.0, -1.0)).unwrap();
        assert!(d.distance(p(-1.0, 0.0)) < 1e-12, "{d:?}");
    }

    #[test]
    fn three_circles_of_apollonius() {
        // the upper half of the unit circle, and two points above it: the
        // circle through (-1, 3) and (1, 3) tangent to the arc from outside
        // is centred at (0, y) with √(1 + (3 − y)²) = y − 1: y = 9/4... (1 + 9 − 6y + y² = y² − 2y + 1 → y = 9/4)
        let arc = Site::Arc(CircularArc::from_bulge([1.0, 0.0], [-1.0, 0.0], 1.0).unwrap());
        check([Site::Point(p(1.0, 3.0)), Site::Point(p(-1.0, 3.0)), arc], p(0.0, 2.25), 1.25);
        // the other order: the circle inside, below the points? none for
        // points outside the circle touching from inside; the order picks
        assert!(arc_vertex(&[Site::Point(p(-1.0, 3.0)), Site::Point(p(1.0, 3.0)), arc]).map_or(true, |(c, _)| c.y < 2.0));
    }

    #[test]
    fn inside_an_arc_with_a_segment() {
        // a segment along y = 0 from -2 to 2, and the upper half circle of
        // radius 2: the circle tangent to both inside, touching the arc at
        // its top, centred at (0, 1) with radius 1; the third site a point
        // at (0, 0)... instead the tangency with a point on the x axis
        let arc = Site::Arc(CircularArc::from_bulge([2.0, 0.0], [-2.0, 0.0], 1.0).unwrap());
        let seg = Site::Segment { a: p(-1.5, 0.0), b: p(1.5, 0.0) };
        // with a point (1, 0)? on the segment; use the point (0, 1.9): the
        // circle tangent to the arc (inside), the line y = 0 and through
        // the point; solve numerically and check the tangencies
        let pt = Site::Point(p(0.5, 1.2));
        for sites in [[seg, arc, pt], [arc, pt, seg], [pt, seg, arc]] {
            if let Some((c, r)) = arc_vertex(&sites) {
                for s in &sites {
                    assert!((s.distance(c) - r).abs() < 1e-9, "{s:?} at {c:?} {r}");
                }
            }
        }
    }
}
