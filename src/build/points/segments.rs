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
use crate::geometry::oracle::{self, Reach};
use crate::geometry::predicates::{orientation, CirclePosition, Orientation};
use crate::geometry::segment_solvers;
use crate::geometry::point::norm;
use crate::geometry::site::Site;
use crate::geometry::solvers::left_normal;
use crate::geometry::{fault, Point};

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
    fn site_geometry(&self, s: SiteId) -> Site {
        match self.ends_of(s) {
            Some([a, b]) => Site::Segment { a: self.sites[a.index()], b: self.sites[b.index()] },
            None => Site::Point(self.sites[s.index()]),
        }
    }

    /// One point of a real site: the point, or a segment's midpoint.
    fn representative(&self, s: SiteId) -> Point {
        match self.site_geometry(s) {
            Site::Point(p) => p,
            Site::Segment { a, b } => Point::new(0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y),
        }
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
    /// `ab` reaches (negative: it enters), perturbed in fault injection.
    ///
    /// When `a` is one of `v`'s sites, `a` lies on the circle and the
    /// distance test would compare two equal numbers; the segment enters the
    /// circle exactly when it leaves `a` towards the centre, so the sign of
    /// `(b - a) · (c - a)` decides, with no cancellation (likewise for `b`);
    /// exactly, where `v` lies on a separator at `a` (`side_at_endpoint`).
    fn segment_depth(&self, v: VertexId, a: SiteId, b: SiteId) -> f64 {
        let sites = self.store.sites_of(v);
        let (pa, pb) = (self.sites[a.index()], self.sites[b.index()]);
        let c = self.store.position[v.index()];
        let entering = |from: Point, to: Point| {
            let (dx, dy) = (to.x - from.x, to.y - from.y);
            -((c.x - from.x) * dx + (c.y - from.y) * dy) / norm(dx, dy)
        };
        let r = self.store.clearance[v.index()];
        // The rounded depth, its sign certified from the sites (`oracle`).
        let certified = |question: Reach, depth: f64| {
            if fault::active() {
                return depth;
            }
            match oracle::reach(|| sites.map(|s| self.site_geometry(s)), c, r, question, depth) {
                Some(CirclePosition::Inside) => -depth.abs().max(f64::MIN_POSITIVE),
                Some(CirclePosition::Outside) => depth.abs().max(f64::MIN_POSITIVE),
                Some(CirclePosition::On) => 0.0,
                None => depth,
            }
        };
        let from_end = |end: SiteId, other: SiteId, from: Point, to: Point| match self.side_at_endpoint(end, other, sites) {
            EndpointSide::Numeric => certified(Reach::Entering { from, to }, entering(from, to)),
            side => side.apply(entering(from, to)),
        };
        let depth = match (sites.contains(&a), sites.contains(&b)) {
            // on the bisector of a and b: every point of it is nearer the
            // segment between them, exactly (the rounded position of a far
            // vertex of nearly collinear sites may say otherwise)
            (true, true) => EndpointSide::Enters.apply(entering(pa, pb)),
            (true, false) => from_end(a, b, pa, pb),
            (false, true) => from_end(b, a, pb, pa),
            (false, false) => certified(Reach::Distance { a: pa, b: pb }, Site::Segment { a: pa, b: pb }.distance(c) - r),
        };
        let depth = fault::perturb(depth);
        if depth.is_nan() {
            f64::INFINITY
        } else {
            depth
        }
    }

    /// For a vertex with sites `sites` (counter-clockwise) among which is
    /// the endpoint `end` of the new segment `end → other`: where the vertex
    /// also has a segment `s` ending at `end`, it lies on `s`'s separator at
    /// `end`, on the side of `s` given by the order of the sites (`s` just
    /// after `end`: left of `end → far`; just before: right), so whether the
    /// new segment leaves `end` towards it is the exact orientation of
    /// `other` against `end → far` (collinear: along the tangent, as where a
    /// chain goes straight on). Two such segments put the vertex at `end`
    /// itself (radius 0): then the sector it stands for decides
    /// (`sector_side`). `Numeric` where there is none.
    fn side_at_endpoint(&self, end: SiteId, other: SiteId, sites: [SiteId; 3]) -> EndpointSide {
        let k = sites.iter().position(|&s| s == end).unwrap_or(0);
        let (next, prev) = (sites[(k + 1) % 3], sites[(k + 2) % 3]);
        let far_end = |s: SiteId| self.far_end(s, end);
        let (pe, po) = (self.sites[end.index()], self.sites[other.index()]);
        let turn = |far: SiteId| orientation(pe, self.sites[far.index()], po);
        match (far_end(next), far_end(prev)) {
            (Some(from), Some(to)) => self.sector_side(pe, po, from, to),
            (Some(far), None) => EndpointSide::from_turn(turn(far), Orientation::CounterClockwise),
            (None, Some(far)) => EndpointSide::from_turn(turn(far), Orientation::Clockwise),
            (None, None) => EndpointSide::Numeric,
        }
    }

    /// For a vertex of radius 0 at the endpoint `pe`, between two segments
    /// ending there (`pe → from`, then `pe → to` counter-clockwise around
    /// `pe`): the vertex stands for the sector swept counter-clockwise from
    /// the first to the second, where their bisector leaves `pe`. The new
    /// segment `pe → po` splits that vertex exactly when it leaves `pe`
    /// strictly inside the sector (exact orientations; a sector of 180° or
    /// more only arises from lying numbers, and is decided the same way).
    fn sector_side(&self, pe: Point, po: Point, from: SiteId, to: SiteId) -> EndpointSide {
        let (pf, pt) = (self.sites[from.index()], self.sites[to.index()]);
        let after_from = orientation(pe, pf, po) == Orientation::CounterClockwise;
        let before_to = orientation(pe, po, pt) == Orientation::CounterClockwise;
        let inside = match orientation(pe, pf, pt) {
            Orientation::CounterClockwise => after_from && before_to,
            Orientation::Clockwise => after_from || before_to,
            Orientation::Collinear => after_from,
        };
        if inside {
            EndpointSide::Enters
        } else {
            EndpointSide::Misses
        }
    }

    /// Whether the segment `ab` conflicts with `v` (see the module doc for
    /// vertices at infinity).
    fn segment_conflict(&self, v: VertexId, a: SiteId, b: SiteId) -> bool {
        match infinite_rotation(self.store.sites_of(v)) {
            Some((x, y)) => (x == a && y == b) || (x == b && y == a),
            None => self.segment_depth(v, a, b) < 0.0,
        }
    }

    /// Seed 000's left-degree of site `g` seen from vertex `v` against the
    /// directed line `a → b`: positive when the projection of `v` on `g` is
    /// left of it. Only its sign and size guide the walk. A segment that
    /// shares an endpoint with `ab` lies on the side of its other endpoint,
    /// decided exactly (and reported as certain: infinite).
    fn left_degree(&self, v: VertexId, g: SiteId, (a, b): (SiteId, SiteId), (pa, pb): (Point, Point)) -> f64 {
        if g == INFINITE {
            return 0.0;
        }
        if let Some(o) = self.far_end(g, a).or_else(|| self.far_end(g, b)) {
            return match orientation(pa, pb, self.sites[o.index()]) {
                Orientation::CounterClockwise => f64::INFINITY,
                Orientation::Clockwise => f64::NEG_INFINITY,
                Orientation::Collinear => 0.0,
            };
        }
        let q = if self.store.is_at_infinity(v) {
            self.representative(g)
        } else {
            self.site_geometry(g).nearest_point(self.store.position[v.index()])
        };
        fault::perturb((pb.x - pa.x) * (q.y - pa.y) - (pb.y - pa.y) * (q.x - pa.x))
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

    /// Position and clearance of a vertex with a segment among its sites.
    pub(super) fn place_segment_vertex(&mut self, v: VertexId) {
        let sites = self.store.sites_of(v);
        if let Some((x, y)) = infinite_rotation(sites) {
            let (p, q) = self.hull_pair(x, y);
            self.set_position(v, left_normal(p, q).unwrap_or_default(), f64::INFINITY);
            return;
        }
        let [ga, gb, gc] = sites.map(|s| self.site_geometry(s));
        let solved = segment_solvers::vertex(&ga, &gb, &gc);
        // An ill-conditioned solve (nearly parallel lines, a circle far
        // larger than its sites) is polished against the sites themselves.
        let solved = match solved {
            Some((c, r)) if !fault::active() => Some(oracle::polish_vertex(&[ga, gb, gc], c, r).unwrap_or((c, r))),
            other => other,
        };
        let (pos, clearance) = solved.unwrap_or_else(|| {
            // No circle: keep the topology, place the vertex among its sites.
            let r = sites.map(|s| self.representative(s));
            let g = Point::new((r[0].x + r[1].x + r[2].x) / 3.0, (r[0].y + r[1].y + r[2].y) / 3.0);
            (g, ga.distance(g))
        });
        self.set_position(v, pos, clearance);
    }

    /// For consecutive hull sites `x → y` (the outside on the left), two
    /// points whose left normal is the direction of the edge between them at
    /// infinity: a segment stands for itself by its endpoints.
    fn hull_pair(&self, x: SiteId, y: SiteId) -> (Point, Point) {
        let (gx, gy) = (self.site_geometry(x), self.site_geometry(y));
        match (gx, gy) {
            (Site::Segment { .. }, Site::Point(q)) => (gx.other_endpoint(q).unwrap_or(self.representative(x)), q),
            (Site::Point(p), Site::Segment { .. }) => (p, gy.other_endpoint(p).unwrap_or(self.representative(y))),
            _ => (self.representative(x), self.representative(y)),
        }
    }
}

/// Whether the new segment enters the circle of a vertex through one of
/// its endpoints, decided exactly where the vertex is on a separator there
/// (`side_at_endpoint`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum EndpointSide {
    /// It enters.
    Enters,
    /// It leaves the endpoint away from the circle.
    Misses,
    /// It runs along the circle's tangent, or the circle has radius 0.
    OnCircle,
    /// No exact answer: the rounded position decides.
    Numeric,
}

impl EndpointSide {
    /// From the turn of the new segment against the separator's segment:
    /// `entering` is the turn that points into the circle.
    fn from_turn(turn: Orientation, entering: Orientation) -> EndpointSide {
        if turn == Orientation::Collinear {
            EndpointSide::OnCircle
        } else if turn == entering {
            EndpointSide::Enters
        } else {
            EndpointSide::Misses
        }
    }

    /// The depth with this sign: the numeric one's size (at least the
    /// smallest positive number, so the sign survives), or 0 on the circle.
    fn apply(self, numeric: f64) -> f64 {
        let size = numeric.abs().max(f64::MIN_POSITIVE);
        match self {
            EndpointSide::Enters => -size,
            EndpointSide::Misses => size,
            EndpointSide::OnCircle => 0.0,
            EndpointSide::Numeric => numeric,
        }
    }
}

