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
//! Not yet with arcs (refused with a clear error rather than built wrong):
//! splitting crossings.

use super::polygon_input::RingInput;
use super::renumber::ArcSite;
use super::restart::Outcome;
use super::state::Construction;
use super::Sites;
use crate::diagram::{Diagram, SiteId};
use crate::error::{Error, ErrorKind};
use crate::geometry::scale::{Magnitudes, Scale, EXACT_SPAN};
use crate::geometry::{CircularArc, Point, Site};

/// Inputs with arcs whose coordinates span more than the exact range are
/// refused before any work: segments beyond it are attempted and checked
/// (`exact_range`), but the arcs' decisions are floating point relative
/// to the input's size, so an arc a hundred orders of magnitude smaller
/// than the coordinates around it has no answer at all (its endpoints
/// round together once the input is scaled).
fn refuse_beyond_the_exact_range(points: &[Point], segments: &[[Point; 2]], arcs: &[CircularArc]) -> Result<(), Error> {
    let ends: Vec<Point> = arcs.iter().flat_map(|a| [a.start(), a.end()]).collect();
    let magnitudes = Magnitudes::of_points(points.iter().chain(segments.iter().flatten()).chain(ends.iter()));
    if magnitudes.span() <= EXACT_SPAN {
        return Ok(());
    }
    // crossing segments first, as `Builder::check` reports them
    super::check_input(points, segments, &[])?;
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
        return Err(Error::new(
            ErrorKind::InvalidArgument,
            "splitting crossings is not supported with arcs yet: arcs must not cross".to_string(),
            Vec::new(),
        ));
    }
    // arcs against points, segments and arcs, exactly; segments against
    // segments (and the arcs' endpoints, as points) in `build_sites`
    super::input_check::arcs::check_arcs(points, segments, arcs)?;
    refuse_beyond_the_exact_range(points, segments, arcs)?;
    let mut all = Vec::with_capacity(points.len() + 2 * arcs.len());
    all.extend_from_slice(points);
    for arc in arcs {
        all.push(arc.start());
        all.push(arc.end());
    }
    let (mut diagram, outcome) = match super::build_sites_and_arcs(&all, segments, &[], arcs)? {
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
        vertices_touch_their_arcs(&diagram)?;
        arc_vertices_are_empty(&diagram)?;
    }
    let mut diagram = diagram;
    if !rings.is_empty() {
        // (rings with arcs share no stretches: their segments went in as
        // obstacles would, an overlap refused by the input check)
        diagram.set_domain(&super::polygon_input::rings_over_pieces(&diagram, rings));
    }
    Ok(diagram)
}

/// The check that stands in for the certified predicates arcs do not have
/// yet: every finite vertex with an arc among its sites is as far from
/// each of its three sites as its clearance says (to 1e-7 of the input's
/// extent). A vertex whose three sites have no common circle there is the
/// mark of a wrong decision in an arc's insertion; the build then fails
/// with [`ErrorKind::Internal`] rather than return a diagram that looks
/// valid and is not. (It does not see every wrong decision: a vertex can
/// touch its sites and still have another site nearer.)
fn vertices_touch_their_arcs(diagram: &Diagram) -> Result<(), Error> {
    let first_arc = diagram.sites.len() - diagram.arc_sites;
    for v in diagram.vertices() {
        if !v.sites.iter().any(|s| s.index() >= first_arc) || !v.clearance.is_finite() {
            continue;
        }
        let tolerance = 1e-7 * (diagram.extent + v.clearance);
        let miss =
            v.sites.iter().map(|&s| (diagram.sites[s.index()].distance(v.position) - v.clearance).abs()).fold(0.0, f64::max);
        if !(miss <= tolerance) {
            let arc = v.sites.iter().find(|s| s.index() >= first_arc).map_or(0, |s| s.index() - first_arc);
            let arc = diagram.arc_input.get(arc).copied().unwrap_or(0) as usize;
            return Err(Error::new(
                ErrorKind::Internal,
                format!(
                    "construction could not complete: a vertex of arc {arc} at ({}, {}) misses its sites by {miss:e}; \
                     please report this input",
                    v.position.x, v.position.y
                ),
                vec![arc],
            ));
        }
    }
    Ok(())
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
fn arc_vertices_are_empty(diagram: &Diagram) -> Result<(), Error> {
    let first_arc = diagram.sites.len() - diagram.arc_sites;
    let n = diagram.sites.len();
    // the neighbouring cells of every cell, in one array (`start[s]..start[s + 1]`)
    let mut start = vec![0usize; n + 1];
    for e in diagram.edges() {
        for s in e.sites.iter().filter(|s| s.index() < n) {
            start[s.index() + 1] += 1;
        }
    }
    for s in 0..n {
        start[s + 1] += start[s];
    }
    let mut neighbours = vec![SiteId::from_index(0); start[n]];
    let mut filled = start.clone();
    for e in diagram.edges() {
        let [a, b] = e.sites;
        if a.index() < n && b.index() < n {
            neighbours[filled[a.index()]] = b;
            filled[a.index()] += 1;
            neighbours[filled[b.index()]] = a;
            filled[b.index()] += 1;
        }
    }
    // whether `site` is nearer to `p` than `reach` (cheap bounds first:
    // most neighbours are far)
    let nearer = |site: &Site, p: Point, reach: f64| match *site {
        Site::Arc(arc) => {
            // off the ring between the circles of radius R ± reach: far
            let (c, r) = (arc.centre(), arc.radius());
            let squared = (c.x - p.x).powi(2) + (c.y - p.y).powi(2);
            let inner = (r - reach).max(0.0);
            squared < (r + reach).powi(2) && squared > inner * inner && arc.distance(p) < reach
        }
        _ => site.distance_squared(p) < reach * reach,
    };
    for v in diagram.vertices() {
        if !v.sites.iter().any(|s| s.index() >= first_arc) || !v.clearance.is_finite() {
            continue;
        }
        let reach = v.clearance - 1e-7 * (diagram.extent + v.clearance);
        if !(reach > 0.0) {
            continue;
        }
        let around = v.sites.iter().filter(|s| s.index() < n).flat_map(|s| &neighbours[start[s.index()]..start[s.index() + 1]]);
        let found = around.copied().find(|&t| !v.sites.contains(&t) && nearer(&diagram.sites[t.index()], v.position, reach));
        if let Some(t) = found {
            let arc = v.sites.iter().find(|s| s.index() >= first_arc).map_or(0, |s| s.index() - first_arc);
            let arc = diagram.arc_input.get(arc).copied().unwrap_or(0) as usize;
            let by = v.clearance - diagram.sites[t.index()].distance(v.position);
            return Err(Error::new(
                ErrorKind::Internal,
                format!(
                    "construction could not complete: a vertex of arc {arc} at ({}, {}) has another site {by:e} nearer \
                     than its own; please report this input",
                    v.position.x, v.position.y
                ),
                vec![arc],
            ));
        }
    }
    Ok(())
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
        let first_arc = diagram.sites.len() - diagram.arc_sites;
        let v = diagram.vertices().find(|v| v.sites.iter().any(|s| s.index() >= first_arc)).unwrap().id;
        // three times as far as it is from its sites: its neighbours nearer
        diagram.store.clearance[v.index()] *= 3.0;
        let e = arc_vertices_are_empty(&diagram).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::Internal);
        assert!(e.to_string().contains("nearer than its own"), "{e}");
    }
}
