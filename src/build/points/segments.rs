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
//! and ask `geometry::segment_predicates` (conflict depth, left-degree,
//! strip, the margin of an edge cut twice) and `geometry::vertex_placement`.
//!
//! A vertex at infinity `(x, y, ∞)` conflicts with `e` exactly when
//! `{x, y} = {a, b}` (then `e` is a convex-hull edge): decided without
//! numbers, so the symbolic point at infinity needs no far-away sites.
//!
//! Inputs whose points are all collinear never come here: their diagram is
//! a ladder of parallel lines with the segments as rungs
//! (`start_collinear_with_segments`).

mod growth;
mod path;
#[cfg(test)]
mod tests;

use super::{infinite_rotation, PointDiagram, INFINITE};
use crate::diagram::{HalfEdgeId, SiteId, VertexId, NONE};
use crate::geometry::predicates::CirclePosition;
use crate::geometry::segment_predicates::{self, AtEndpoint, Contact, LeftDegree, SegmentDepth, SiteSeen};
use crate::geometry::site::Site;
use crate::geometry::Point;

impl PointDiagram {
    /// Whether any of the sites is an open segment.
    #[inline]
    pub(super) fn has_segment(&self, sites: [SiteId; 3]) -> bool {
        sites.iter().any(|&s| self.is_segment(s))
    }

    #[inline]
    fn is_segment(&self, s: SiteId) -> bool {
        s.0 >= self.first_segment
    }

    /// The endpoint sites of `s`, if it is a segment.
    #[inline]
    fn ends_of(&self, s: SiteId) -> Option<[SiteId; 2]> {
        self.is_segment(s).then(|| self.segment_ends[(s.0 - self.first_segment) as usize])
    }

    /// The other endpoint of `s`, if it is a segment ending at `end`.
    fn far_end(&self, s: SiteId, end: SiteId) -> Option<SiteId> {
        match self.ends_of(s)? {
            [x, y] if x == end => Some(y),
            [x, y] if y == end => Some(x),
            _ => None,
        }
    }

    /// The geometry of a real site (not the point at infinity).
    pub(super) fn site_geometry(&self, s: SiteId) -> Site {
        match self.ends_of(s) {
            Some([a, b]) => Site::Segment { a: self.sites[a.index()], b: self.sites[b.index()] },
            None => Site::Point(self.sites[s.index()]),
        }
    }

    /// The coordinates of the endpoint sites `a` and `b` of a new segment.
    #[inline]
    fn segment_between(&self, a: SiteId, b: SiteId) -> (Point, Point) {
        (self.sites[a.index()], self.sites[b.index()])
    }

    /// Adds the open segment between the point sites `a` and `b`; every
    /// point must be in already. `Err` with the segment's site when no path
    /// of P4 exists: the diagram then holds the segment but is not valid
    /// (the numbers have put `a` and `b` on different sides of a closed
    /// chain of segments; see `build::construct`).
    pub(crate) fn insert_segment(&mut self, a: SiteId, b: SiteId) -> Result<SiteId, SiteId> {
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

    /// The diagram of points on one line, given in order along it (at least
    /// two, distinct), and segments each joining chain points `k` and `k + 1`
    /// for `k` in `between`: a ladder in which every segment is one more rung
    /// between its endpoints (its separators are the perpendiculars there).
    /// Returns the point sites in chain order and the segment sites in the
    /// order of `between`.
    pub(crate) fn start_collinear_with_segments(
        &mut self,
        chain: &[Point],
        between: &[usize],
    ) -> (Vec<SiteId>, Vec<SiteId>) {
        let ids: Vec<SiteId> = chain.iter().map(|&p| self.add_site(p)).collect();
        let mut after: Vec<Option<SiteId>> = vec![None; chain.len()];
        let mut segment_sites = Vec::with_capacity(between.len());
        for &k in between {
            let e = self.add_segment_site(ids[k], ids[(k + 1).min(ids.len() - 1)]);
            segment_sites.push(e);
            if let Some(slot @ None) = after.get_mut(k) {
                *slot = Some(e);
            }
        }
        let mut sequence = Vec::with_capacity(ids.len() + between.len());
        for (k, &id) in ids.iter().enumerate() {
            sequence.push(id);
            sequence.extend(after[k]);
        }
        self.build_ladder(&sequence);
        (ids, segment_sites)
    }

    fn add_segment_site(&mut self, a: SiteId, b: SiteId) -> SiteId {
        let s = SiteId::from_index(self.sites.len());
        if self.first_segment == u32::MAX {
            self.first_segment = s.0;
        }
        self.segment_ends.push([a, b]);
        self.sites.push(Point::new(f64::NAN, f64::NAN));
        self.store.cell_edge.push(NONE);
        self.cell_mark.push(0);
        s
    }

    /// How far inside the circle of the finite vertex `v` the open segment
    /// `ab` reaches (`segment_predicates::segment_depth`), from which of
    /// `a` and `b` are among its sites.
    fn segment_depth(&self, v: VertexId, a: SiteId, b: SiteId) -> SegmentDepth {
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

    /// Whether `h` runs between an existing segment and one of its
    /// endpoints. Such an edge is never deleted whole (both of its vertices
    /// in the tree): every segment keeps exactly one separator with each
    /// endpoint, if only of zero length where many segments meet at a point.
    pub(super) fn is_separator(&self, h: HalfEdgeId) -> bool {
        let (l, r) = (self.store.left(h), self.store.right(h));
        self.ends_of(l).is_some_and(|e| e.contains(&r)) || self.ends_of(r).is_some_and(|e| e.contains(&l))
    }

    /// Whether `v` may join the walk: not at infinity unless it conflicts.
    fn walkable(&self, v: VertexId, a: SiteId, b: SiteId) -> bool {
        !self.store.is_at_infinity(v) || self.segment_conflict(v, a, b)
    }
}
