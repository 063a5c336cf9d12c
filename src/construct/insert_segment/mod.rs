//! Topology-oriented insertion of open segments (seed 000 algorithm 3,
//! DESIGN §2.2), into a diagram that already holds every point site.
//!
//! Inserting the open segment `e` between the point sites `a` and `b`
//! deletes a tree `T` of the current diagram and puts the cell of `e` in its
//! place. Kept exactly, by integer bookkeeping:
//! - P3: `T` is a tree (as P1 for points);
//! - P4: `T` contains a path from `R(a)`'s boundary to `R(b)`'s: it is found
//!   first, by a walk that keeps sites left of `e` on its left and sites
//!   right of `e` on its right (left-degree of seed 000), backtracking to
//!   its least certain decision (smallest `|L|`) when it is stuck;
//! - P5: `R(a)` and `R(b)` each lose exactly one connected piece of their
//!   boundary — no step of the walk or of the growth may reach a vertex whose
//!   third cell is `R(a)`, or `R(b)` once touched. Other cells may lose
//!   several pieces (seed 000 figure 2: unlike points, a segment's cell can
//!   wrap around a site's cell), and P3 keeps every cell from losing all of
//!   its boundary.
//!
//! - Every existing segment keeps exactly one separator edge with each of
//!   its endpoints: no separator is deleted whole (where segments share an
//!   endpoint, the separators there may shrink to zero length instead).
//!
//! The numbers only choose: the walk's direction, and which neighbours the
//! tree grows into (those whose circle the segment enters, seed criteria 1
//! and 2.3, never beyond a vertex outside the strip between the
//! perpendiculars at `a` and `b`, criterion 2.2). Then, as for points, every
//! edge leaving `T` gets a new vertex and the new vertices bound `e`'s cell;
//! the new edges shared with `R(a)` and `R(b)` are the separators.
//!
//! This module and its children do no arithmetic: they decide which vertex,
//! edge or site to ask about, fetch its sites and positions from the store,
//! and ask `geometry::segments::segment_predicates` (conflict depth, left-degree,
//! strip, the margin of an edge cut twice) and `geometry::segments::vertex_placement`.
//!
//! A vertex at infinity `(x, y, ∞)` conflicts with `e` exactly when
//! `{x, y} = {a, b}` (then `e` is a convex-hull edge): decided without
//! numbers, so the symbolic point at infinity needs no far-away sites.
//!
//! Inputs whose points are all collinear never come here: their diagram is
//! a ladder of parallel lines with the segments as rungs (`collinear.rs`).
//!
//! `insert_segments` inserts them all (in an order by midpoint), the
//! path of P4 is in `path.rs`, the growth of P3/P5 and the edges cut twice
//! in `growth.rs`; both end in `deletion_tree.rs`'s `replace_tree`.

mod arc_questions;
mod growth;
mod path;
#[cfg(test)]
mod tests;

use super::collinear;
use super::insert_point::PointStage;
use super::insertion_order::insertion_order;
use super::state::{infinite_rotation, Construction, INFINITE};
use crate::diagram::{SiteId, VertexId, NONE};
use crate::geometry::predicates::CirclePosition;
use crate::geometry::segments::segment_predicates::{self, AtEndpoint, Contact, LeftDegree, SegmentDepth, SiteSeen};
use crate::geometry::{Point, Site};

/// Inserts the segments into the diagram of the points; those listed in
/// `first_segments` go first, in that order. Also returns the first segment
/// that found no path.
pub(in crate::construct) fn insert_segments(
    stage: PointStage,
    points: &[Point],
    segments: &[[usize; 2]],
    first_segments: &[usize],
) -> (Construction, Vec<SiteId>, Vec<SiteId>, Option<usize>) {
    let (mut diagram, site_of) = match stage {
        PointStage::Inserted(diagram, site_of) => (diagram, site_of),
        PointStage::Trivial(diagram, site_of) => return (diagram, site_of, Vec::new(), None),
        PointStage::Collinear => {
            let mut diagram = Construction::new(points.len() + segments.len());
            let mut site_of = vec![SiteId(NONE); points.len()];
            let segment_sites = collinear::start_all_collinear(points, segments, &mut diagram, &mut site_of);
            return (diagram, site_of, segment_sites, None);
        }
    };
    // Segments go in the same order as points, by their midpoints: BRIO
    // rounds along a Hilbert curve (the result does not depend on it). The
    // curve keeps each insertion where the last one worked, in memory the
    // cache still holds; the random rounds keep the work near-linear where
    // segments are long against the gaps between them: inserted in sweep
    // order, each of n parallel segments would first take the cell of the
    // one before, which reaches across all the points (n parallel segments
    // of length n at unit spacing cost O(n^2) that way, O(n log n) in
    // random rounds).
    let midpoints: Vec<Point> = segments.iter().map(|&[i, j]| Site::Segment { a: points[i], b: points[j] }.midpoint()).collect();
    let mut segment_sites = vec![SiteId(NONE); segments.len()];
    let mut stuck = None;
    let by_midpoint = insertion_order(&midpoints);
    drop(midpoints);
    let rest = by_midpoint.into_iter().filter(|&k| !first_segments.contains(&(k as usize)));
    // Gather each segment's endpoint sites into insertion order first: the
    // loads are independent here and overlap, where inside the loop each
    // would be a cache miss waiting behind a whole insertion.
    let order: Vec<(u32, SiteId, SiteId)> = first_segments
        .iter()
        .map(|&k| k as u32)
        .chain(rest)
        .map(|k| {
            let [i, j] = segments[k as usize];
            (k, site_of[i], site_of[j])
        })
        .collect();
    for (k, a, b) in order {
        let k = k as usize;
        segment_sites[k] = diagram.insert_segment(a, b).unwrap_or_else(|e| {
            stuck = stuck.or(Some(k));
            e
        });
    }
    (diagram, site_of, segment_sites, stuck)
}

impl Construction {
    /// Adds the open segment between the point sites `a` and `b`; every
    /// point must be in already. `Err` with the segment's site when no path
    /// of P4 exists: the diagram then holds the segment but is not valid
    /// (the numbers have put `a` and `b` on different sides of a closed
    /// chain of segments; see `construct/restart.rs`).
    pub(in crate::construct) fn insert_segment(&mut self, a: SiteId, b: SiteId) -> Result<SiteId, SiteId> {
        let e = self.add_segment_site(a, b);
        self.fresh_epoch();
        let found = self.find_segment_path(a, b);
        self.grow_segment_tree(a, b);
        self.replace_tree(e);
        if found {
            Ok(e)
        } else {
            Err(e)
        }
    }

    /// How far inside the circle of the finite vertex `v` the open segment
    /// `ab` reaches (`segment_predicates::segment_depth`), from which of
    /// `a` and `b` are among its sites.
    fn segment_depth(&self, v: VertexId, a: SiteId, b: SiteId) -> SegmentDepth {
        if let Some(arc) = self.inserting_arc {
            return self.arc_depth(v, a, b, &arc);
        }
        let sites = self.store.sites_of(v);
        let contact = match (sites.contains(&a), sites.contains(&b)) {
            (true, true) => Contact::BothEnds,
            (true, false) => Contact::OneEnd(self.at_endpoint(a, b, sites)),
            (false, true) => Contact::OneEnd(self.at_endpoint(b, a, sites)),
            (false, false) => Contact::NoEnd,
        };
        let (centre, radius) = (self.store.position[v.index()], self.store.clearance[v.index()]);
        segment_predicates::segment_depth(self.segment_between(a, b), contact, centre, radius, || {
            sites.map(|s| self.site_geometry(s))
        })
    }

    /// A vertex with sites `sites` (counter-clockwise) among which is the
    /// endpoint `end` of the new segment `end → other`, with the segments
    /// among its sites just after and just before `end` that end there, by
    /// their far endpoints: the vertex then lies on their separator at
    /// `end`, and the order of its sites says on which side.
    #[inline]
    fn at_endpoint(&self, end: SiteId, other: SiteId, sites: [SiteId; 3]) -> AtEndpoint {
        let k = sites.iter().position(|&s| s == end).unwrap_or(0);
        let far = |s: SiteId| self.far_end(s, end).map(|f| self.sites[f.index()]);
        AtEndpoint {
            end: self.sites[end.index()],
            other: self.sites[other.index()],
            after: far(sites[(k + 1) % 3]),
            before: far(sites[(k + 2) % 3]),
        }
    }

    /// Whether the segment `ab` conflicts with `v` (see the module doc for
    /// vertices at infinity).
    fn segment_conflict(&self, v: VertexId, a: SiteId, b: SiteId) -> bool {
        match infinite_rotation(self.store.sites_of(v)) {
            Some((x, y)) if self.inserting_arc.is_some() => self.arc_conflict_at_infinity(v, (x, y), a, b),
            Some((x, y)) => (x == a && y == b) || (x == b && y == a),
            None => self.segment_depth(v, a, b).position() == CirclePosition::Inside,
        }
    }

    /// Seed 000's left-degree of site `g` seen from vertex `v` against the
    /// directed segment `a → b` (`segment_predicates::left_degree`): a
    /// segment sharing an endpoint with `ab` is seen by its other endpoint,
    /// any other site from `v`'s position, or as a whole from a vertex at
    /// infinity.
    fn left_degree(&self, v: VertexId, g: SiteId, (a, b): (SiteId, SiteId), segment: (Point, Point)) -> LeftDegree {
        if let Some(arc) = self.inserting_arc {
            return self.arc_left_degree(v, g, (a, b), &arc);
        }
        let seen = if g == INFINITE {
            SiteSeen::Infinity
        } else if let Some(o) = self.far_end(g, a).or_else(|| self.far_end(g, b)) {
            SiteSeen::SharingEndpoint { far: self.sites[o.index()] }
        } else {
            let from = (!self.store.is_at_infinity(v)).then(|| self.store.position[v.index()]);
            SiteSeen::Other { site: self.site_geometry(g), from }
        };
        segment_predicates::left_degree(segment, seen)
    }

    /// Whether `v` may join the walk: not at infinity unless it conflicts.
    fn walkable(&self, v: VertexId, a: SiteId, b: SiteId) -> bool {
        !self.store.is_at_infinity(v) || self.segment_conflict(v, a, b)
    }
}
