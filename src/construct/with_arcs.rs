//! Diagrams with circular arcs among the sites: the points, segments and
//! arcs' endpoints are built as before (`build_sites`, which splits
//! segments at arc endpoints inside them like at any input vertex), then
//! each arc goes in (`insert_segment::arc_questions`), then the diagram is
//! renumbered with the arcs as the last sites.
//!
//! Polygons go with arcs: their rings (plain, or of segments and arcs from
//! `Builder::add_bulged_polygon`) bound the domain (`query::domain`), set
//! once the diagram is built. Their segments go in as obstacles' do: rings
//! sharing a stretch are refused as overlapping rather than cancelled.
//!
//! Splitting crossings with arcs (`split::arcs`) builds the pieces here,
//! and with polygons the rings of their even-odd region over the pieces
//! (`split::rings`). Rings of `Builder::add_bulged_polygon` come here to be
//! split even without an arc among them.

use super::polygon_input::RingInput;
use super::renumber::ArcSite;
use super::restart::Outcome;
use super::state::Construction;
use super::Sites;
use crate::diagram::{Diagram, SiteId, VertexId};
use crate::error::{Error, ErrorKind};
use crate::geometry::scale::{Magnitudes, Scale, EXACT_SPAN};
use crate::geometry::{CircularArc, Point, Site};
use crate::query::Vertex;

/// Inputs with arcs whose coordinates span more than the exact range are
/// refused before any work: segments beyond it are attempted and checked
/// (`exact_range`), but the arcs' decisions are floating point relative
/// to the input's size, so an arc a hundred orders of magnitude smaller
/// than the coordinates around it has no answer at all (its endpoints
/// round together once the input is scaled).
fn refuse_beyond_the_exact_range(points: &[Point], segments: &[[Point; 2]], arcs: &[CircularArc]) -> Result<(), Error> {
    let Err(range) = within_the_exact_range(points, segments, arcs) else { return Ok(()) };
    // crossing segments first, as `Builder::check` reports them
    super::check_input(points, segments, &[])?;
    Err(range)
}

/// The range check of [`refuse_beyond_the_exact_range`] alone (with
/// splitting, crossings are no error).
fn within_the_exact_range(points: &[Point], segments: &[[Point; 2]], arcs: &[CircularArc]) -> Result<(), Error> {
    let ends: Vec<Point> = arcs.iter().flat_map(|a| [a.start(), a.end()]).collect();
    let magnitudes = Magnitudes::of_points(points.iter().chain(segments.iter().flatten()).chain(ends.iter()));
    if magnitudes.span() <= EXACT_SPAN {
        return Ok(());
    }
    Err(Error::new(
        ErrorKind::UnsupportedRange,
        format!(
            "the input's coordinates span {} bits, from a largest magnitude of {:e} down to a smallest nonzero \
             magnitude or difference of {:e}; with arcs they must span at most {EXACT_SPAN} bits (about 3e144). \
             Round the smallest differences away or build parts of narrower span separately",
            magnitudes.span(),
            magnitudes.max_abs,
            magnitudes.smallest
        ),
        Vec::new(),
    ))
}

/// The diagram of points, segments and arcs (`Builder::build` with arcs).
pub(super) fn diagram_with_arcs(
    points: &[Point],
    segments: &[[Point; 2]],
    arcs: &[CircularArc],
    split: bool,
    rings: &[RingInput],
) -> Result<Diagram, Error> {
    if split {
        return diagram_of_split_with_arcs(points, segments, arcs, rings);
    }
    // arcs against points, segments and arcs, exactly (beside the point
    // insertions on large inputs); segments against segments (and the
    // arcs' endpoints, as points) in `build_sites`
    let check_arcs = || super::input_check::arcs::check_arcs(points, segments, arcs);
    if let Err(range) = refuse_beyond_the_exact_range(points, segments, arcs) {
        // (crossing arcs are reported first, as the check asked first)
        check_arcs()?;
        return Err(range);
    }
    let mut all = Vec::with_capacity(points.len() + 2 * arcs.len());
    all.extend_from_slice(points);
    for arc in arcs {
        all.push(arc.start());
        all.push(arc.end());
    }
    let (mut diagram, outcome) = match super::build_sites_and_arcs(&all, segments, &[], (arcs, &check_arcs), None)? {
        Sites::Built(diagram, outcome) => (*diagram, outcome),
        Sites::Shared(..) => unreachable!("stretches are shared only by polygon rings"),
    };
    // the arcs' endpoints were input points of the construction only
    diagram.input_site.truncate(points.len());
    diagram.stats.input_points = points.len();
    diagram.stats.input_arcs = arcs.len();
    let first_arc = diagram.sites.len() - diagram.arc_sites;
    diagram.arc_site = (0..diagram.arc_sites).map(|k| SiteId::from_index(first_arc + k)).collect();
    let diagram = super::accept(diagram, outcome, &all, segments)?;
    // (not under fault injection, whose lying numbers misplace vertices on
    // purpose: there the topology is what is checked, by `accept`)
    if !crate::geometry::fault::active() {
        check_arc_vertices(&diagram)?;
        directions_at_infinity_turn_once(&diagram)?;
    }
    let mut diagram = diagram;
    if !rings.is_empty() {
        // (rings with arcs share no stretches: their segments went in as
        // obstacles would, an overlap refused by the input check)
        diagram.set_domain(&super::polygon_input::rings_over_pieces(&diagram, rings));
    }
    Ok(diagram)
}

/// The diagram of points, segments and arcs split where they meet
/// (`split::arcs`): the strict build of the pieces, then which input each
/// piece came from (the segments' as with `split_crossings` alone, the
/// arcs' likewise: `arc_input_index` and `site_of_arc` then speak of arc
/// pieces, `arc_pieces_of_input` and `inputs_of_arc_piece` map between).
fn diagram_of_split_with_arcs(
    points: &[Point],
    segments: &[[Point; 2]],
    arcs: &[CircularArc],
    rings: &[RingInput],
) -> Result<Diagram, Error> {
    // the arcs' range first, as without splitting (the cuts of an input
    // beyond it could land past the largest double)
    within_the_exact_range(points, segments, arcs)?;
    let super::split::arcs::SplitWithArcs { input: mut split, arcs: mut split_arcs } =
        super::split::arcs::split_with_arcs(points, segments, arcs)?;
    // the boundary of the rings' even-odd region, as rings of pieces
    let (mut split_rings, mut cancelled) = (Vec::new(), 0);
    if !rings.is_empty() {
        let (pieces, arc_pieces, over_pieces, dropped) = super::split::split_rings_with_arcs(
            std::mem::take(&mut split.pieces),
            std::mem::take(&mut split_arcs),
            rings,
            segments.len(),
            arcs.len(),
        );
        (split.pieces, split_arcs, split_rings, cancelled) = (pieces, arc_pieces, over_pieces, dropped);
    }
    let finite = |p: &Point| p.is_finite();
    let pieces_finite = split.points.iter().all(finite)
        && split.pieces.iter().all(|p| p.ends.iter().all(finite))
        && split_arcs
            .iter()
            .all(|a| [a.arc.start(), a.arc.end(), a.arc.centre()].iter().all(finite) && a.arc.radius().is_finite());
    if !pieces_finite {
        return Err(Error::new(
            ErrorKind::UnsupportedRange,
            "splitting crossings moved a piece beyond the range of doubles; scale the input down".to_string(),
            Vec::new(),
        ));
    }
    let ends: Vec<[Point; 2]> = split.pieces.iter().map(|p| p.ends).collect();
    let arc_pieces: Vec<CircularArc> = split_arcs.iter().map(|a| a.arc).collect();
    let mut diagram = diagram_with_arcs(&split.points, &ends, &arc_pieces, false, &[]).map_err(|e| {
        if e.kind() == ErrorKind::Intersecting {
            // (none is expected: the pieces passed the same exact tests)
            Error::new(
                ErrorKind::Internal,
                format!("construction could not complete: after splitting crossings, {}; please report this input", e.message()),
                Vec::new(),
            )
        } else {
            e
        }
    })?;
    if !rings.is_empty() {
        // (before the split's maps are set: the rings name pieces)
        diagram.set_domain(&super::polygon_input::rings_over_pieces(&diagram, &split_rings));
    }
    let origins: Vec<Vec<u32>> = split.pieces.iter().map(|p| p.origins.clone()).collect();
    diagram.split =
        Some(Box::new(crate::diagram::SplitPieces::new(&origins, segments.len(), split.max_displacement, split.pixel)));
    // (the arc sites are numbered by piece, as the segments' are:
    // `arc_pieces_of_input` maps the input arcs to them)
    let arc_origins: Vec<Vec<u32>> = split_arcs.iter().map(|a| a.origins.clone()).collect();
    diagram.split_arcs = Some(Box::new(crate::diagram::SplitPieces::new(&arc_origins, arcs.len(), 0.0, 0.0)));
    let stats = &mut diagram.stats;
    stats.input_segments = segments.len();
    stats.input_arcs = arcs.len();
    stats.pieces = split.pieces.len() + split_arcs.len();
    stats.crossings = split.crossings;
    stats.overlaps = split.overlaps;
    stats.touchings = split.touchings;
    stats.snap_rounds = split.rounds;
    stats.cancelled_ring_pieces = cancelled;
    Ok(diagram)
}

/// The checks that stand in for the certified predicates arcs do not
/// have yet, in one pass over the vertices with an arc among their sites
/// (`vertices_touch_their_arcs` and `arc_vertices_are_empty` say what
/// each asks). A vertex that misses its sites is reported before any
/// with a nearer site, and of each kind the one of lowest id, as when the
/// two ran one after the other. On large diagrams the two halves of the
/// vertices are checked on two threads: the check reads the diagram only,
/// and costs a fifth of an arcs' build (100k random arcs: 0.21 s of 1.1 s).
fn check_arc_vertices(diagram: &Diagram) -> Result<(), Error> {
    let around = Neighbourhoods::of(diagram);
    let check = |ids: std::ops::Range<usize>| {
        let mut nearer = None;
        for v in arc_vertices(diagram, ids) {
            if let Err(miss) = misses_its_sites(diagram, &v) {
                return (Some(miss), nearer);
            }
            if nearer.is_none() {
                nearer = has_a_nearer_site(diagram, &around, &v).err();
            }
        }
        (None, nearer)
    };
    let (n, half) = (diagram.finite_vertices, diagram.finite_vertices / 2);
    let ((first_miss, first_nearer), (second_miss, second_nearer)) = if n >= PARALLEL_VERTEX_CHECK_FROM {
        super::run_beside(|| check(0..half), || check(half..n))
    } else {
        (check(0..half), check(half..n))
    };
    first_miss.or(second_miss).or(first_nearer).or(second_nearer).map_or(Ok(()), Err)
}

/// From this many vertices on, the arcs' vertex check runs on two threads
/// (below, a thread costs more than it saves: the check takes about 0.4 µs
/// a vertex).
const PARALLEL_VERTEX_CHECK_FROM: usize = 50_000;

/// The finite vertices among `ids` with an arc among their sites.
fn arc_vertices(diagram: &Diagram, ids: std::ops::Range<usize>) -> impl Iterator<Item = Vertex> + '_ {
    let first_arc = diagram.sites.len() - diagram.arc_sites;
    ids.filter_map(|v| diagram.vertex(VertexId::from_index(v)))
        .filter(move |v| v.sites.iter().any(|s| s.index() >= first_arc) && v.clearance.is_finite())
}

/// The input arc of a vertex with an arc among its sites, for the errors.
/// The check of the diagram's edges to infinity that stands beside
/// `check_arc_vertices`. Each site whose cell reaches infinity owns the
/// directions in which it reaches furthest out (its support function is
/// the largest), so walking round the cell of the point at infinity:
/// - at each vertex there, the direction is one in which its two sites
///   reach equally far (their supports tie);
/// - the directions turn one way, once round.
///
/// A decision at infinity that kept a cell there where another site
/// reaches further breaks one of them: a point a hair off an arc's
/// circle whose cell at infinity was left behind when an arc ending on
/// it went in (the directions step back), or a stub's free end 1e-11
/// inside a circle given a cell at infinity beside the arc (its support
/// 0.024 short of the arc's there: LibreCAD's Relay, split). No vertex
/// check sees these: the finite vertices are right, the edges to
/// infinity between them are not. O(h) for h edges to infinity.
fn directions_at_infinity_turn_once(diagram: &Diagram) -> Result<(), Error> {
    let store = &diagram.store;
    let ring: Vec<(Point, [SiteId; 2])> = store
        .cell_boundary(store.infinite_site)
        .map(|h| {
            let v = h.origin();
            let mut real = store.sites_of(v).into_iter().filter(|&s| s != store.infinite_site);
            let x = real.next().unwrap_or(store.infinite_site);
            (store.position[v.index()], [x, real.next().unwrap_or(x)])
        })
        .collect();
    if ring.len() < 3 {
        return Ok(());
    }
    let refuse = |k: usize, what: &str| {
        let (d, [x, _]) = ring[k];
        let first_arc = diagram.sites.len() - diagram.arc_sites;
        let near = diagram.sites.get(x.index()).map_or(Point::new(0.0, 0.0), |s| s.midpoint());
        let arc = (first_arc..diagram.sites.len())
            .min_by(|&a, &b| diagram.sites.at(a).distance(near).total_cmp(&diagram.sites.at(b).distance(near)))
            .map_or(0, |s| diagram.arc_input.get(s - first_arc).copied().unwrap_or(0) as usize);
        Err(Error::new(
            ErrorKind::Internal,
            format!(
                "construction could not complete: an edge to infinity beside arc {arc} (toward ({}, {})) {what}: a decision \
                 at infinity went wrong; please report this input",
                d.x, d.y
            ),
            vec![arc],
        ))
    };
    for (k, &(d, [x, y])) in ring.iter().enumerate() {
        let (Some(x), Some(y)) = (diagram.sites.get(x.index()), diagram.sites.get(y.index())) else { continue };
        let (rx, ry) = (x.support(d).0, y.support(d).0);
        // (relative to the terms of an arc's support, the centre's far
        // out for a nearly straight arc)
        let size = |s: &Site| match *s {
            Site::Arc(arc) => (arc.centre().x * d.x).abs() + (arc.centre().y * d.y).abs() + arc.radius(),
            _ => s.support(d).0.abs(),
        };
        let tolerance = 1e-9 * (size(&x) + size(&y) + diagram.extent);
        if !((rx - ry).abs() <= tolerance) {
            return refuse(k, "has sites that do not reach equally far that way");
        }
    }
    // The walk with the point at infinity's cell on its left goes round
    // clockwise: each step turns clockwise by the directions the cell
    // between its ends owns, more than half a turn for a long arc's, and
    // the steps sum to one turn. Each step is read modulo a whole turn: a
    // step back reads as a turn of nearly a whole one and adds a turn to
    // the sum. Steps back within `BACK` are rounding: ties are common (the
    // separators of a segment's ends run parallel), and a point on an
    // arc's circle to 1e-9 of its radius meets the arc at infinity along
    // its radius, where the true ties may lie 4.5e-5 rad either side
    // (`arc_vertex::direction_at_infinity`). But so does the cell of an
    // arc of nearly a whole turn read, all but the sliver of directions its
    // ends' cells take (the fuzzer's case 0x5647c6b33fd94086). So the ring
    // is right when the sum is a whole number of turns, one more than at
    // most as many steps as read as nearly a whole turn; a step back
    // further than `BACK` adds a turn that none of those explains.
    const BACK: f64 = 1e-4;
    let full = std::f64::consts::TAU;
    let angle = |d: Point| d.y.atan2(d.x);
    let steps: Vec<f64> =
        (0..ring.len()).map(|k| (angle(ring[k].0) - angle(ring[(k + 1) % ring.len()].0)).rem_euclid(full)).collect();
    let nearly_whole = steps.iter().filter(|&&t| t > full - BACK).count();
    let total: f64 = steps.iter().sum();
    let turns = (total / full).round();
    if (total - turns * full).abs() <= 1e-6 * turns && turns >= 1.0 && turns <= (nearly_whole + 1) as f64 {
        return Ok(());
    }
    // the step back: the largest turn short of nearly a whole one
    let back = (0..steps.len()).filter(|&k| steps[k] <= full - BACK).max_by(|&i, &j| steps[i].total_cmp(&steps[j])).unwrap_or(0);
    refuse((back + 1) % ring.len(), "turns back from the one before")
}

fn arc_of(diagram: &Diagram, v: &Vertex) -> usize {
    let first_arc = diagram.sites.len() - diagram.arc_sites;
    let arc = v.sites.iter().find(|s| s.index() >= first_arc).map_or(0, |s| s.index() - first_arc);
    diagram.arc_input.get(arc).copied().unwrap_or(0) as usize
}

/// The check that stands in for the certified predicates arcs do not have
/// yet: every finite vertex with an arc among its sites is as far from
/// each of its three sites as its clearance says (to 1e-7 of the input's
/// extent). A vertex whose three sites have no common circle there is the
/// mark of a wrong decision in an arc's insertion; the build then fails
/// with [`ErrorKind::Internal`] rather than return a diagram that looks
/// valid and is not. (It does not see every wrong decision: a vertex can
/// touch its sites and still have another site nearer.)
#[cfg(test)]
fn vertices_touch_their_arcs(diagram: &Diagram) -> Result<(), Error> {
    arc_vertices(diagram, 0..diagram.finite_vertices).try_for_each(|v| misses_its_sites(diagram, &v))
}

/// `vertices_touch_their_arcs` at one vertex.
fn misses_its_sites(diagram: &Diagram, v: &Vertex) -> Result<(), Error> {
    // and a few roundings of the position's coordinates, which can be
    // larger than the whole input (an arc of an ulp's length at 0.5)
    let rounding = 8.0 * f64::EPSILON * (v.position.x.abs() + v.position.y.abs());
    let tolerance = 1e-7 * (diagram.extent + v.clearance) + rounding;
    let miss =
        v.sites.iter().map(|&s| (diagram.sites.at(s.index()).distance(v.position) - v.clearance).abs()).fold(0.0, f64::max);
    if miss <= tolerance {
        return Ok(());
    }
    let arc = arc_of(diagram, v);
    Err(Error::new(
        ErrorKind::Internal,
        format!(
            "construction could not complete: a vertex of arc {arc} at ({}, {}) misses its sites by {miss:e}; \
             please report this input",
            v.position.x, v.position.y
        ),
        vec![arc],
    ))
}

/// The other half of that check: no site whose cell borders one of the
/// three cells of a vertex with an arc among its sites is nearer to it
/// than its clearance (to the same tolerance). A wrong decision that
/// keeps a vertex (or places one at the wrong root of its sites) leaves
/// it touching its three sites with another nearer, and that site's cell
/// then borders theirs: LibreCAD's ed83 with its circle cut, a vertex at
/// the circle's centre with a chord's end 2 nearer, passed the touching
/// check and was answered. A site beyond the neighbouring cells could
/// only be nearer if those cells were wrong too.
#[cfg(test)]
fn arc_vertices_are_empty(diagram: &Diagram) -> Result<(), Error> {
    let around = Neighbourhoods::of(diagram);
    arc_vertices(diagram, 0..diagram.finite_vertices).try_for_each(|v| has_a_nearer_site(diagram, &around, &v))
}

/// `arc_vertices_are_empty` at one vertex.
fn has_a_nearer_site(diagram: &Diagram, around: &Neighbourhoods, v: &Vertex) -> Result<(), Error> {
    let reach = v.clearance - 1e-7 * (diagram.extent + v.clearance);
    if !(reach > 0.0) {
        return Ok(());
    }
    let n = diagram.sites.len();
    let neighbours = v.sites.iter().filter(|s| s.index() < n).flat_map(|s| around.of_cell(*s));
    let Some(t) = neighbours.copied().find(|&t| !v.sites.contains(&t) && around.nearer(diagram, t, v.position, reach)) else {
        return Ok(());
    };
    let arc = arc_of(diagram, v);
    let by = v.clearance - diagram.sites.at(t.index()).distance(v.position);
    Err(Error::new(
        ErrorKind::Internal,
        format!(
            "construction could not complete: a vertex of arc {arc} at ({}, {}) has another site {by:e} nearer \
             than its own; please report this input",
            v.position.x, v.position.y
        ),
        vec![arc],
    ))
}

/// The neighbouring cells of every cell, in one array
/// (`start[s]..start[s + 1]`), and where each site lies (`Bound`): what
/// the emptiness check reads for each of the millions of neighbours it
/// tests, in 32 bytes a site rather than a [`Site`]'s 96 (the check is
/// bound by memory, not arithmetic).
struct Neighbourhoods {
    start: Vec<usize>,
    neighbours: Vec<SiteId>,
    bounds: Vec<Bound>,
}

/// Where a site lies, for a cheap test that it is out of a vertex's reach.
#[derive(Clone, Copy)]
enum Bound {
    /// A point site: itself.
    Point(Point),
    /// A segment: within the radius of the centre (its midpoint, and the
    /// distance to its farther end, which the disk holds by convexity).
    Disk(Point, f64),
    /// An arc: on the circle.
    Circle(Point, f64),
}

impl Neighbourhoods {
    fn of(diagram: &Diagram) -> Neighbourhoods {
        let n = diagram.sites.len();
        let edges = || diagram.edges.iter().map(|&h| [diagram.store.left(h), diagram.store.right(h)]);
        let mut start = vec![0usize; n + 1];
        for sites in edges() {
            for s in sites.iter().filter(|s| s.index() < n) {
                start[s.index() + 1] += 1;
            }
        }
        for s in 0..n {
            start[s + 1] += start[s];
        }
        // (a slot for an edge to the point at infinity stays site 0:
        // tested, harmlessly, as it always was)
        let mut neighbours = vec![SiteId::from_index(0); start[n]];
        let mut filled = start.clone();
        for [a, b] in edges() {
            if a.index() < n && b.index() < n {
                neighbours[filled[a.index()]] = b;
                filled[a.index()] += 1;
                neighbours[filled[b.index()]] = a;
                filled[b.index()] += 1;
            }
        }
        let bounds = diagram.sites.iter().map(|s| Bound::of(&s)).collect();
        Neighbourhoods { start, neighbours, bounds }
    }

    fn of_cell(&self, s: SiteId) -> &[SiteId] {
        &self.neighbours[self.start[s.index()]..self.start[s.index() + 1]]
    }

    /// Whether site `t` is nearer to `p` than `reach`: out of reach by
    /// its bound (most neighbours are far), else by its distance.
    fn nearer(&self, diagram: &Diagram, t: SiteId, p: Point, reach: f64) -> bool {
        let site = || diagram.sites.at(t.index());
        // `squared` (a squared distance, normal: within a few roundings
        // of the true one) clearly beyond `r`
        let beyond = |squared: f64, r: f64| squared >= (r * r * (1.0 + 1e-9)).max(f64::MIN_POSITIVE);
        match self.bounds[t.index()] {
            Bound::Point(q) => !beyond(q.distance_squared(p), reach) && site().distance_squared(p) < reach * reach,
            Bound::Disk(m, r) => !beyond(m.distance_squared(p), reach + r) && site().distance_squared(p) < reach * reach,
            Bound::Circle(c, r) => {
                // off the ring between the circles of radius R ± reach: far
                let squared = (c.x - p.x).powi(2) + (c.y - p.y).powi(2);
                let inner = (r - reach).max(0.0);
                squared < (r + reach).powi(2) && squared > inner * inner && site().distance(p) < reach
            }
        }
    }
}

impl Bound {
    fn of(site: &Site) -> Bound {
        match *site {
            Site::Point(p) => Bound::Point(p),
            Site::Segment { a, b } => {
                let m = Point::new(0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y);
                Bound::Disk(m, m.distance(a).max(m.distance(b)))
            }
            Site::Arc(arc) => Bound::Circle(arc.centre(), arc.radius()),
        }
    }
}

/// Inserts the arcs into the construction of the points and segments;
/// arc `k`'s start and end are the construction's points
/// `first_end + 2k` and `first_end + 2k + 1`. Returns the arcs' sites for
/// the renumbering, or the error for an arc that found no path.
pub(super) fn insert_arcs(
    built: &mut Construction,
    site_of_input: &[SiteId],
    first_end: usize,
    arcs: &[CircularArc],
    scale: Scale,
    outcome: &Outcome,
) -> Result<Vec<ArcSite>, Error> {
    if arcs.is_empty() || outcome.stuck.is_some() {
        return Ok(Vec::new());
    }
    let mut sites = Vec::with_capacity(arcs.len());
    for (k, arc) in arcs.iter().enumerate() {
        let (a, b) = (site_of_input[first_end + 2 * k], site_of_input[first_end + 2 * k + 1]);
        let internal = built.insert_arc(a, b, arc.scaled(scale.to_internal)).map_err(|_| {
            let (s, e) = (arc.start(), arc.end());
            Error::new(
                ErrorKind::Internal,
                format!(
                    "construction could not complete: arc {k} ({}, {}) - ({}, {}) found no path; please report this input",
                    s.x, s.y, e.x, e.y
                ),
                vec![k],
            )
        })?;
        sites.push(ArcSite { input: k, internal, arc: *arc });
    }
    Ok(sites)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Builder;

    /// A vertex of an arc moved out along its edge (as a wrong decision
    /// leaves one: touching its three sites, another nearer) is caught.
    #[test]
    fn a_vertex_with_a_nearer_site_is_refused() {
        let mut b = Builder::new();
        b.add_arc(CircularArc::from_bulge([0.0, 0.0], [4.0, 0.0], 1.0).unwrap()).unwrap();
        b.add_point([2.0, -1.0]).unwrap();
        b.add_point([2.0, 3.0]).unwrap();
        let mut diagram = b.build().unwrap();
        assert!(arc_vertices_are_empty(&diagram).is_ok());
        assert!(vertices_touch_their_arcs(&diagram).is_ok() && check_arc_vertices(&diagram).is_ok());
        let first_arc = diagram.sites.len() - diagram.arc_sites;
        let v = diagram.vertices().find(|v| v.sites.iter().any(|s| s.index() >= first_arc)).unwrap().id;
        // three times as far as it is from its sites: its neighbours nearer
        diagram.store.clearance[v.index()] *= 3.0;
        let e = arc_vertices_are_empty(&diagram).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::Internal);
        assert!(e.to_string().contains("nearer than its own"), "{e}");
        // it misses its sites too, which the pass of both reports first
        let e = vertices_touch_their_arcs(&diagram).unwrap_err();
        assert!(e.to_string().contains("misses its sites"), "{e}");
        assert_eq!(check_arc_vertices(&diagram).unwrap_err().to_string(), e.to_string());
    }
}
