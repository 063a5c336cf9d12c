//! The insertion of an open arc: the segments' walk and growth (P3-P5 kept
//! the same way, by the same code), asking the arcs' predicates
//! (`geometry::arcs::arc_predicates`) while `Construction::inserting_arc`
//! is set. Arcs go in after every segment.

use crate::construct::state::{Construction, INFINITE};
use crate::diagram::{HalfEdgeId, SiteId, VertexId};
use crate::geometry::arcs::arc_predicates::{self, ArcContact, ArcSiteSeen};
use crate::geometry::arcs::at_infinity;
use crate::geometry::segments::segment_predicates::{LeftDegree, MiddleMargin, SegmentDepth};
use crate::geometry::{CircularArc, Point, Site};

impl Construction {
    /// Adds the open arc from the point site `a` (its start) to `b` (its
    /// end); every point and segment must be in already. `Err` with the
    /// arc's site when no path of P4 exists (see `insert_segment`; the
    /// diagram then holds the arc but is not valid).
    ///
    /// Unlike a segment's, an arc's cell can reach infinity in a whole
    /// range of directions, and take the middle of another site's range
    /// there (a point beside an arc's convex side): the edge at infinity of
    /// that site is then cut twice, its middle kept
    /// (`arc_middle_at_infinity`).
    pub(in crate::construct) fn insert_arc(&mut self, a: SiteId, b: SiteId, arc: CircularArc) -> Result<SiteId, SiteId> {
        self.inserting_arc = Some(arc);
        let e = self.add_arc_site(a, b, arc);
        self.fresh_epoch();
        let found = self.find_segment_path(a, b);
        self.grow_segment_tree(a, b);
        self.replace_tree(e);
        self.inserting_arc = None;
        if found {
            Ok(e)
        } else {
            Err(e)
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
        arc_predicates::arc_depth(arc, contact, centre, radius, || sites.map(|s| self.site_geometry(s)))
    }

    /// The contact of a vertex with sites `sites` at the arc's endpoint
    /// `end`: the pieces beside `end` that end there.
    fn arc_contact_at(&self, end: SiteId, sites: [SiteId; 3]) -> ArcContact {
        let k = sites.iter().position(|&s| s == end).unwrap_or(0);
        let at = self.sites[end.index()];
        let piece = |s: SiteId| {
            self.far_end(s, end)?;
            Some(self.site_geometry(s))
        };
        ArcContact::OneEnd { end: at, after: piece(sites[(k + 1) % 3]), before: piece(sites[(k + 2) % 3]) }
    }

    /// Whether the vertex at infinity `v` between the hull sites `x → y`
    /// conflicts with the new arc: where `{x, y}` are its endpoints, when
    /// the arc bulges to the side of infinity (a counter-clockwise arc lies
    /// right of its chord); else as `at_infinity` decides from the
    /// direction and the two sites.
    pub(super) fn arc_conflict_at_infinity(&self, v: VertexId, (x, y): (SiteId, SiteId), a: SiteId, b: SiteId) -> bool {
        let arc = self.inserting_arc.expect("asked while an arc goes in");
        if (x, y) == (a, b) {
            return !arc.is_counter_clockwise();
        }
        if (x, y) == (b, a) {
            return arc.is_counter_clockwise();
        }
        let d = self.store.position[v.index()];
        // the far end of the edge between one of the arc's endpoints and a
        // piece ending there too
        for (end, piece) in [(x, y), (y, x)] {
            if (end == a || end == b) && self.far_end(piece, end).is_some() {
                let at = self.sites[end.index()];
                if let Some(answer) = at_infinity::beside_a_shared_end(&arc, d, at, &self.site_geometry(piece)) {
                    return answer;
                }
            }
        }
        at_infinity::arc_conflict_at_infinity(&arc, d, &self.site_geometry(x), &self.site_geometry(y))
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

    /// Whether `h` is an edge at infinity: between two vertices at
    /// infinity, along the cell of the point at infinity.
    pub(super) fn is_edge_at_infinity(&self, h: HalfEdgeId) -> bool {
        self.store.is_at_infinity(h.origin())
            && self.store.is_at_infinity(self.store.target(h))
            && (self.store.left(h) == INFINITE || self.store.right(h) == INFINITE)
    }

    /// How clearly the site of the edge at infinity `h` keeps a range of
    /// directions at infinity in the middle of its range when the new arc
    /// takes both ends: the largest excess of the site's reach over the
    /// arc's (support functions) at directions between the two ends,
    /// within the site's range (the side of the ends' middle where the
    /// site reaches further than its two hull neighbours).
    pub(super) fn arc_middle_at_infinity(&self, h: HalfEdgeId, arc: &CircularArc) -> MiddleMargin {
        let x = if self.store.left(h) == INFINITE { self.store.right(h) } else { self.store.left(h) };
        let (u, v) = (h.origin(), self.store.target(h));
        let (du, dv) = (self.store.position[u.index()], self.store.position[v.index()]);
        let neighbours: Vec<SiteId> =
            [u, v].iter().flat_map(|&w| self.store.sites_of(w)).filter(|&s| s != x && s != INFINITE).collect();
        let support = |s: SiteId, d: Point| self.site_geometry(s).support(d).0;
        let (au, av) = (du.y.atan2(du.x), dv.y.atan2(dv.x));
        // the two ways round from `du` to `dv`; the site's range is the one
        // whose middle it holds against its neighbours
        let mut sweep = (av - au).rem_euclid(2.0 * std::f64::consts::PI);
        let at = |t: f64, sweep: f64| {
            let a = au + t * sweep;
            Point::new(a.cos(), a.sin())
        };
        let holds = |d: Point| neighbours.iter().all(|&n| support(x, d) >= support(n, d));
        if !holds(at(0.5, sweep)) {
            sweep -= 2.0 * std::f64::consts::PI;
        }
        let new_arc = Site::Arc(*arc);
        // Sampled, and where the site's excess over the arc's circle is
        // largest: toward a point of it from the arc's centre (a point
        // a rounding outside the circle keeps a sliver of directions
        // around that one only).
        let c = arc.centre();
        let toward = self.site_geometry(x).ends().into_iter().filter_map(|q| {
            let t = ((q.y - c.y).atan2(q.x - c.x) - au).rem_euclid(2.0 * std::f64::consts::PI);
            let t = if sweep < 0.0 { t - 2.0 * std::f64::consts::PI } else { t };
            (t / sweep > 0.0 && t / sweep < 1.0).then_some(t / sweep)
        });
        let margin = (1..16)
            .map(|k| k as f64 / 16.0)
            .chain(toward)
            .map(|t| {
                let d = at(t, sweep);
                support(x, d) - new_arc.support(d).0
            })
            .fold(f64::NEG_INFINITY, f64::max);
        MiddleMargin::of(crate::geometry::fault::perturb(margin))
    }
}
