//! The insertion of an open arc: the segments' walk and growth (P3-P5 kept
//! the same way, by the same code), asking the arcs' predicates
//! (`geometry::arcs::arc_predicates`) while `Construction::inserting_arc`
//! is set. Arcs go in after every segment.

use crate::construct::state::{Construction, INFINITE};
use crate::diagram::{SiteId, VertexId};
use crate::geometry::arcs::arc_predicates::{self, ArcContact, ArcSiteSeen};
use crate::geometry::segments::segment_predicates::{LeftDegree, SegmentDepth};
use crate::geometry::{CircularArc, Point, Site};

/// Why an arc could not go in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(in crate::construct) enum ArcStuck {
    /// No path of P4 (lying numbers).
    NoPath,
    /// Its cell would take every direction at infinity.
    AroundEverything,
}

impl Construction {
    /// Adds the open arc from the point site `a` (its start) to `b` (its
    /// end); every point and segment must be in already. `Err` when no
    /// path of P4 exists (see `insert_segment`; the diagram then holds the
    /// arc but is not valid), or, with nothing changed, when the arc's cell
    /// would take every direction at infinity of the diagram so far.
    pub(in crate::construct) fn insert_arc(&mut self, a: SiteId, b: SiteId, arc: CircularArc) -> Result<SiteId, ArcStuck> {
        self.inserting_arc = Some(arc);
        // The cell of the point at infinity must keep a piece of its
        // boundary (the deleted set is a tree): an arc whose cone reaches
        // past every hull edge (a major arc around a few small sites) would
        // replace all of it, which one tree cannot say.
        let hull: Vec<VertexId> = self.store.cell_boundary(INFINITE).map(|h| h.origin()).collect();
        if !hull.is_empty() && hull.iter().all(|&v| self.segment_conflict(v, a, b)) {
            self.inserting_arc = None;
            return Err(ArcStuck::AroundEverything);
        }
        let e = self.add_arc_site(a, b, arc);
        self.fresh_epoch();
        let found = self.find_segment_path(a, b);
        self.grow_segment_tree(a, b);
        self.replace_tree(e);
        self.inserting_arc = None;
        if found {
            Ok(e)
        } else {
            Err(ArcStuck::NoPath)
        }
    }

    /// How far the new arc reaches into the circle of the finite vertex
    /// `v` (`arc_predicates::arc_depth`).
    pub(super) fn arc_depth(&self, v: VertexId, a: SiteId, b: SiteId, arc: &CircularArc) -> SegmentDepth {
        let sites = self.store.sites_of(v);
        let contact = match (sites.contains(&a), sites.contains(&b)) {
            (true, true) => ArcContact::BothEnds,
            (true, false) => self.arc_contact_at(a, sites),
            (false, true) => self.arc_contact_at(b, sites),
            (false, false) => ArcContact::NoEnd,
        };
        let (centre, radius) = (self.store.position[v.index()], self.store.clearance[v.index()]);
        arc_predicates::arc_depth(arc, contact, centre, radius)
    }

    /// The contact of a vertex with sites `sites` at the arc's endpoint
    /// `end`: the directions of the pieces beside `end` that end there.
    fn arc_contact_at(&self, end: SiteId, sites: [SiteId; 3]) -> ArcContact {
        let k = sites.iter().position(|&s| s == end).unwrap_or(0);
        let at = self.sites[end.index()];
        let direction = |s: SiteId| {
            self.far_end(s, end)?;
            arc_predicates::piece_direction(&self.site_geometry(s), at)
        };
        ArcContact::OneEnd { end: at, after: direction(sites[(k + 1) % 3]), before: direction(sites[(k + 2) % 3]) }
    }

    /// Whether the vertex at infinity `v` between the hull sites `x → y`
    /// conflicts with the new arc: where `{x, y}` are its endpoints, when
    /// the arc bulges to the side of infinity (a counter-clockwise arc lies
    /// right of its chord); else when the edge's direction lies in the
    /// arc's span and the arc reaches further out that way than the two
    /// sites do (their support along it).
    pub(super) fn arc_conflict_at_infinity(&self, v: VertexId, (x, y): (SiteId, SiteId), a: SiteId, b: SiteId) -> bool {
        let arc = self.inserting_arc.expect("asked while an arc goes in");
        if (x, y) == (a, b) {
            return !arc.is_counter_clockwise();
        }
        if (x, y) == (b, a) {
            return arc.is_counter_clockwise();
        }
        let d = self.store.position[v.index()];
        let c = arc.centre();
        let far = Point::new(c.x + d.x, c.y + d.y);
        if !(d.x.is_finite() && d.y.is_finite()) || (d.x == 0.0 && d.y == 0.0) || !arc.spans(far) {
            return false;
        }
        let support = |s: SiteId| -> f64 {
            let along = |p: Point| d.x * (p.x - c.x) + d.y * (p.y - c.y);
            match self.site_geometry(s) {
                Site::Arc(other) if other.spans(Point::new(other.centre().x + d.x, other.centre().y + d.y)) => {
                    along(other.centre()) + other.radius()
                }
                site => {
                    let [p, q] = site.ends();
                    along(p).max(along(q))
                }
            }
        };
        // along a tangent join the arc reaches exactly as far out as the
        // piece it continues, in the direction of their common separator:
        // a tie, which is no conflict; rounding must not make it one
        let reach = arc.radius() * d.x.hypot(d.y);
        let support = support(x).max(support(y));
        let size = reach.abs() + support.abs() + (d.x * c.x).abs() + (d.y * c.y).abs();
        reach - support > 1e-12 * size
    }

    /// The left-degree of site `g` seen from `v` against the new arc
    /// (`arc_predicates::arc_left_degree`).
    pub(super) fn arc_left_degree(&self, v: VertexId, g: SiteId, (a, b): (SiteId, SiteId), arc: &CircularArc) -> LeftDegree {
        let seen = if g == INFINITE {
            ArcSiteSeen::Infinity
        } else if self.far_end(g, a).is_some() {
            ArcSiteSeen::SharingEndpoint { site: self.site_geometry(g), end: self.sites[a.index()] }
        } else if self.far_end(g, b).is_some() {
            ArcSiteSeen::SharingEndpoint { site: self.site_geometry(g), end: self.sites[b.index()] }
        } else {
            let from = (!self.store.is_at_infinity(v)).then(|| self.store.position[v.index()]);
            ArcSiteSeen::Other { site: self.site_geometry(g), from }
        };
        arc_predicates::arc_left_degree(arc, seen)
    }
}
