//! The domain bounded by the polygons' rings (even-odd rule), and where
//! every vertex, edge and cell of the diagram lies: inside, outside, or on
//! its boundary.
//!
//! The classification never looks at a rounded vertex position. Voronoi
//! edges never cross an input segment, so each edge lies on one side of
//! the boundary, and which side follows from the topology and exact
//! orientation tests on input points:
//! - in the cell of a ring segment `s = a → b`, the boundary walked
//!   counter-clockwise runs below `s` from `a` to `b`, up the separator at
//!   `b`, above `s` back to `a`, and down the separator at `a`: the edges
//!   after the separator at `b` and before the one at `a` are on the left
//!   of `a → b`, the others on its right;
//! - the cell of a ring corner lies on the corner's reflex side (it is the
//!   wedge between the perpendiculars of its two segments), decided by the
//!   exact turn at the corner; a straight corner's cell has no interior: it
//!   lies on the perpendicular, and so do its separators, on one side of
//!   the ring where they end at a vertex at the corner, on both where they
//!   pass through it (see [`Diagram::edge_location`]); where more segments
//!   meet (rings touching at the corner, an obstacle ending there), the
//!   cell lies in the one wedge between consecutive segments of at least a
//!   half turn, on that side of a ring segment bounding it (exact
//!   orientations);
//! - the cell of an obstacle (an isolated point, a polyline or free
//!   segment) lies where the obstacle lies: an exact even-odd test of one
//!   of its points against the rings;
//! - which side of a ring is inside: its orientation (the exact turn at its
//!   lowest-leftmost vertex) and how many other rings contain it.
//!
//! Vertices take the location of their edges, except the vertices of
//! radius zero at ring corners, which are on the boundary; cells of ring
//! segments and corners are on the boundary.

use crate::construct::polygon_input::RingInput;
use crate::diagram::{Diagram, EdgeId, SiteId, VertexId};
use crate::geometry::arcs::exact_join;
use crate::geometry::predicates::Orientation;
use crate::geometry::{Point, Site};
use crate::query::EdgeEnd;

/// Where a vertex, edge or cell lies relative to the domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Location {
    /// In the domain's interior.
    Inside,
    /// Outside the domain.
    Outside,
    /// On its boundary: a vertex at a ring corner, an edge of length zero
    /// there, the cell of a ring's segment or corner (which lies on both
    /// sides), and an edge that passes through a straight corner (a
    /// separator on the perpendicular there, partly inside and partly
    /// outside).
    Boundary,
}

/// The classification, made once per build.
#[derive(Clone, Debug, Default)]
pub(crate) struct Domain {
    rings: Vec<Ring>,
    vertex: Vec<Location>,
    edge: Vec<Location>,
    cell: Vec<Location>,
    /// The edges that pass through a straight ring corner, by id, each with
    /// which of its ends (`Edge::ends`) lies inside.
    through: Vec<(EdgeId, usize)>,
    /// The edges along the normal of a tangent join of a curved ring
    /// (between two of its sites), sorted: what the separators are at a
    /// straight corner of segments, kept out of the medial axis.
    join_normals: Vec<EdgeId>,
}

/// A ring as the diagram sees it: its corners and segments as sites, in
/// ring order (segment `k` from corner `k` to corner `k + 1`).
#[derive(Clone, Debug)]
struct Ring {
    corners: Vec<SiteId>,
    /// Its pieces: segment sites, and arc sites for a ring of
    /// `add_bulged_polygon`.
    segments: Vec<SiteId>,
    /// Whether an arc is among its pieces (`ring_arcs` then answers what
    /// the exact tests of straight rings do).
    curved: bool,
    /// Whether the domain is on the left of the ring's direction.
    left_inside: bool,
    /// The bounding box of its corners: a ring can hold a point, or
    /// another ring, only inside it (which keeps the tests of many small
    /// rings near-linear).
    bounds: Bounds,
    /// How many rings contain it, and the innermost of them.
    depth: usize,
    parent: Option<usize>,
}

/// An axis-parallel box `[min x, min y, max x, max y]`.
#[derive(Clone, Copy, Debug)]
struct Bounds([f64; 4]);

impl Bounds {
    fn of(points: impl Iterator<Item = Point>) -> Bounds {
        Bounds(points.fold([f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY], |[x0, y0, x1, y1], p| {
            [x0.min(p.x), y0.min(p.y), x1.max(p.x), y1.max(p.y)]
        }))
    }

    fn holds_point(&self, p: Point) -> bool {
        let [x0, y0, x1, y1] = self.0;
        (x0..=x1).contains(&p.x) && (y0..=y1).contains(&p.y)
    }

    fn holds(&self, other: &Bounds) -> bool {
        let [x0, y0, x1, y1] = other.0;
        self.holds_point(Point::new(x0, y0)) && self.holds_point(Point::new(x1, y1))
    }
}

/// What a site is to the domain.
#[derive(Clone, Copy)]
enum Role {
    /// Segment `k` of a ring: is the domain on the left of its site's
    /// `a → b`?
    RingSegment { left_inside: bool },
    /// A ring corner: where its cell lies.
    RingCorner { cell: Location },
    /// An obstacle (or a point of no ring).
    Obstacle,
}

impl Diagram {
    /// Classifies the diagram against the rings of its polygons (called
    /// only when polygons were added; no rings left, where every piece
    /// cancelled, is an empty domain: everything outside).
    pub(crate) fn set_domain(&mut self, rings: &[RingInput]) {
        self.domain = Some(self.classify(rings));
    }

    /// Whether polygons were added: then every vertex, edge and cell has a
    /// [`Location`].
    pub fn has_domain(&self) -> bool {
        self.domain.is_some()
    }

    /// Where a vertex lies; `None` without a domain or out of range.
    pub fn vertex_location(&self, v: VertexId) -> Option<Location> {
        self.domain.as_ref()?.vertex.get(v.index()).copied()
    }

    /// Where an edge lies; `None` without a domain or out of range. An
    /// edge never crosses a ring's segment, so it lies on one side of the
    /// boundary, with one exception: at a straight corner (a ring vertex
    /// between two collinear segments) the corner's cell is a piece of the
    /// perpendicular, and a separator there may run from a vertex inside
    /// through the corner to one outside; such an edge is
    /// [`Location::Boundary`].
    pub fn edge_location(&self, e: EdgeId) -> Option<Location> {
        self.domain.as_ref()?.edge.get(e.index()).copied()
    }

    /// For an edge that passes through a straight ring corner (see
    /// [`Diagram::edge_location`]), which of its ends (an index into
    /// `Edge::ends`) lies inside the domain; `None` for every other edge.
    pub(crate) fn inside_end_through_corner(&self, e: EdgeId) -> Option<usize> {
        inside_end(&self.domain.as_ref()?.through, e)
    }

    /// Whether edge `e` lies along the normal of a tangent join of a
    /// curved ring (between two of the join's sites): no part of the
    /// medial axis, as a separator is not.
    pub(crate) fn is_join_normal(&self, e: EdgeId) -> bool {
        self.domain.as_ref().is_some_and(|d| d.join_normals.binary_search(&e).is_ok())
    }

    /// Where a cell lies; `None` without a domain or out of range.
    pub fn cell_location(&self, site: SiteId) -> Option<Location> {
        self.domain.as_ref()?.cell.get(site.index()).copied()
    }

    /// Whether `p` (input coordinates) is in the domain, exactly (even-odd
    /// rule over every ring); `None` without a domain, and for a point with
    /// a NaN or infinite coordinate, which is nowhere (as for
    /// [`Diagram::nearest_site`]; the exact tests would answer it as if it
    /// were a number).
    pub fn locate_point(&self, p: Point) -> Option<Location> {
        if !p.is_finite() {
            return None;
        }
        Some(self.point_location(&self.domain.as_ref()?.rings, p))
    }

    /// The rings as the offsets need them: per ring, its sites (corners
    /// and segments), how many rings contain it, and the innermost of them
    /// (an index into the same list). Empty without a domain.
    pub(crate) fn ring_nesting(&self) -> Vec<(Vec<SiteId>, usize, Option<usize>)> {
        let Some(domain) = &self.domain else { return Vec::new() };
        domain.rings.iter().map(|r| (r.corners.iter().chain(&r.segments).copied().collect(), r.depth, r.parent)).collect()
    }

    fn classify(&self, inputs: &[RingInput]) -> Domain {
        let rings = self.rings_of(inputs);
        let mut role = vec![Role::Obstacle; self.sites.len()];
        for (r, ring) in rings.iter().enumerate() {
            let n = ring.corners.len();
            for k in 0..n {
                let s = ring.segments[k];
                // forward when the site runs from corner k to corner k + 1
                let forward = self.segment_endpoints(s).is_some_and(|[a, _]| a == ring.corners[k]);
                role[s.index()] = Role::RingSegment { left_inside: ring.left_inside == forward };
                let [prev, here, next] = [ring.corners[(k + n - 1) % n], ring.corners[k], ring.corners[(k + 1) % n]];
                let turn = if ring.curved {
                    self.corner_turn(ring.segments[(k + n - 1) % n], here, ring.segments[k])
                } else {
                    self.turn(self.point_of(prev), self.point_of(here), self.point_of(next))
                };
                // the reflex side: right of a left turn, left of a right turn
                let cell = match turn {
                    Orientation::Collinear => Location::Boundary,
                    Orientation::CounterClockwise => inside_if(!rings[r].left_inside),
                    Orientation::Clockwise => inside_if(rings[r].left_inside),
                };
                role[here.index()] = Role::RingCorner { cell };
            }
        }
        // A corner where more than two segments meet (rings touching there,
        // or an obstacle ending at it): its cell lies in the wedge between
        // consecutive segments that is at least a half turn, not on one
        // ring's reflex side.
        let mut meeting: std::collections::HashMap<SiteId, Vec<SiteId>> = std::collections::HashMap::new();
        for s in (self.point_sites..self.sites.len()).map(SiteId::from_index) {
            for end in self.segment_endpoints(s).into_iter().flatten() {
                if matches!(role[end.index()], Role::RingCorner { .. }) {
                    meeting.entry(end).or_default().push(s);
                }
            }
        }
        for (p, segments) in meeting.into_iter().filter(|(_, segments)| segments.len() > 2) {
            role[p.index()] = Role::RingCorner { cell: self.shared_corner_cell(p, &segments, &role) };
        }
        let obstacle_location: Vec<Option<Location>> = (0..self.sites.len())
            .map(|s| match role[s] {
                Role::Obstacle => Some(self.obstacle_location(&rings, SiteId::from_index(s))),
                _ => None,
            })
            .collect();
        let cell: Vec<Location> = (0..self.sites.len()).map(|s| obstacle_location[s].unwrap_or(Location::Boundary)).collect();
        let (side_of, mut through) = self.ring_segment_sides(&role);
        let joins = if rings.iter().any(|r| r.curved) { self.tangent_join_edges(&rings, &role) } else { Vec::new() };
        through.retain(|(e, _)| !joins.iter().any(|(j, _)| j == e));
        through.extend(joins.iter().filter_map(|&(e, j)| match j.at {
            JoinAt::Through(inside) => Some((e, inside)),
            JoinAt::Side(_) => None,
        }));
        through.sort_unstable();
        through.dedup_by_key(|&mut (e, _)| e);
        // A kinked corner that a separator passes through (see
        // `ring_segment_sides`) has its cell on both sides: it tells none.
        // (a mask by site: asked for every edge, and a curved part can have
        // thousands of such corners)
        let mut split_corner = vec![false; self.sites.len()];
        for s in through.iter().filter_map(|&(e, _)| self.edge(e)).flat_map(|edge| edge.sites) {
            if matches!(role[s.index()], Role::RingCorner { cell } if cell != Location::Boundary) {
                split_corner[s.index()] = true;
            }
        }
        // The location an edge has seen from the cell on the left of its
        // half-edge `h`, where that cell tells.
        let seen_from = |h: crate::HalfEdge| -> Option<Location> {
            let s = self.half_edge_cell(h)?;
            match role[s.index()] {
                Role::RingSegment { left_inside } => side_of[h.index()].map(|left| inside_if(left == left_inside)),
                Role::RingCorner { cell } => (cell != Location::Boundary && !split_corner[s.index()]).then_some(cell),
                Role::Obstacle => obstacle_location[s.index()],
            }
        };
        let mut edge: Vec<Location> = (0..self.edges.len())
            .map(|e| {
                let [h, t] = self.half_edges(EdgeId::from_index(e)).expect("in range");
                seen_from(h).or_else(|| seen_from(t)).unwrap_or(Location::Boundary)
            })
            .collect();
        // an edge through a corner lies on both sides of it (at a kinked
        // corner, its cell would say one)
        for &(e, _) in &through {
            edge[e.index()] = Location::Boundary;
        }
        for &(e, j) in &joins {
            edge[e.index()] = match j.at {
                JoinAt::Through(_) => Location::Boundary,
                JoinAt::Side(l) => l,
            };
        }
        let on_ring: Vec<bool> =
            (0..self.finite_vertices).map(|v| self.is_ring_corner_vertex(VertexId::from_index(v), &role)).collect();
        let mut vertex: Vec<Location> = (0..self.finite_vertices)
            .map(|v| {
                if on_ring[v] {
                    return Location::Boundary;
                }
                let out = self.vertex_half_edges(VertexId::from_index(v)).expect("a finite vertex");
                out.iter().map(|h| edge[h.edge().index()]).find(|&l| l != Location::Boundary).unwrap_or(Location::Boundary)
            })
            .collect();
        // Edges that no cell locates (between the cells of two straight
        // corners, which are lines) take the location of an end vertex off
        // the rings, and such vertices that of their edges: a vertex off
        // the rings lies strictly on one side, and so does every edge from
        // it that does not pass through a straight corner.
        let is_through = |e: usize| inside_end(&through, EdgeId::from_index(e)).is_some();
        // A vertex off the rings that only edges through straight corners
        // reach (the centre of a circle of two arcs, where the separators
        // at its two tangent joins meet) takes the side of those edges it
        // ends.
        for v in 0..vertex.len() {
            if vertex[v] != Location::Boundary || on_ring[v] {
                continue;
            }
            for h in self.vertex_half_edges(VertexId::from_index(v)).expect("a finite vertex") {
                if let Some(inside) = inside_end(&through, h.edge()) {
                    // h starts at v: v is the edge's end 0 unless h is reversed
                    vertex[v] = inside_if(usize::from(h.is_reversed()) == inside);
                    break;
                }
            }
        }
        let mut queue: Vec<usize> = (0..vertex.len()).filter(|&v| vertex[v] != Location::Boundary).collect();
        while let Some(v) = queue.pop() {
            for h in self.vertex_half_edges(VertexId::from_index(v)).expect("a finite vertex") {
                let e = h.edge().index();
                if edge[e] != Location::Boundary || is_through(e) {
                    continue;
                }
                edge[e] = vertex[v];
                if let Some(u) = self.target_of(h).filter(|&u| !on_ring[u] && vertex[u] == Location::Boundary) {
                    vertex[u] = vertex[v];
                    queue.push(u);
                }
            }
        }
        // The domain is bounded: an edge to infinity located inside (by an
        // obstacle's cell: a stub that a split left 1e-11 inside a circle,
        // whose free end the structure treats as on the circle, LibreCAD's
        // Relay) leaves the domain at its finite end, to rounding, and is
        // taken as passing through the boundary there. Located inside
        // alone, the offsets outside never crossed it and a loop stayed
        // open.
        let unbounded_inside: Vec<(EdgeId, usize)> = (0..edge.len())
            .filter(|&e| edge[e] == Location::Inside && !is_through(e))
            .filter_map(|e| {
                let ends = self.edge(EdgeId::from_index(e))?.ends;
                let finite = ends.iter().position(|end| matches!(end, crate::EdgeEnd::Vertex(_)))?;
                ends.iter().any(|end| matches!(end, crate::EdgeEnd::Infinite { .. })).then_some((EdgeId::from_index(e), finite))
            })
            .collect();
        if !unbounded_inside.is_empty() {
            for &(e, _) in &unbounded_inside {
                edge[e.index()] = Location::Boundary;
            }
            through.extend(unbounded_inside);
            through.sort_unstable();
        }
        let mut join_normals: Vec<EdgeId> = joins.iter().filter(|(_, j)| j.normal).map(|&(e, _)| e).collect();
        join_normals.sort_unstable();
        Domain { rings, vertex, edge, cell, through, join_normals }
    }

    /// Per half-edge on the boundary of a ring segment's cell (that cell on
    /// its left): `Some(true)` when it is on the left of the site's
    /// `a → b`, `Some(false)` on the right, `None` for the separators and
    /// every other half-edge (see the module doc). A separator at a
    /// straight corner gets the side where it lies, and when it passes
    /// through the corner it is listed, with its end on the domain's side,
    /// in the second result.
    fn ring_segment_sides(&self, role: &[Role]) -> (Vec<Option<bool>>, Vec<(EdgeId, usize)>) {
        let mut side = vec![None; 2 * self.edges.len()];
        let mut through = Vec::new();
        let straight = |p: SiteId| matches!(role[p.index()], Role::RingCorner { cell: Location::Boundary });
        for (s, r) in role.iter().enumerate() {
            let Role::RingSegment { left_inside } = *r else { continue };
            let s = SiteId::from_index(s);
            let Some([a, b]) = self.segment_endpoints(s) else { continue };
            let around: Vec<crate::HalfEdge> = self.cell_half_edges(s).collect();
            let across = |h: &crate::HalfEdge| self.half_edge_cell(h.twin());
            // At a tangent join with an arc the corner's cell may be
            // missing (thinner than nothing): the edge between the two
            // pieces then passes through the corner where the separator
            // would, and stands for it.
            let separator_at = |corner: SiteId| {
                around.iter().position(|h| across(h) == Some(corner)).or_else(|| self.join_edge(s, corner, &around, role))
            };
            let (Some(at_a), Some(at_b)) = (separator_at(a), separator_at(b)) else {
                continue;
            };
            let n = around.len();
            // after the separator at b, up to the one at a: the left
            let mut k = (at_b + 1) % n;
            while k != at_a {
                side[around[k].index()] = Some(true);
                k = (k + 1) % n;
            }
            let mut k = (at_a + 1) % n;
            while k != at_b {
                side[around[k].index()] = Some(false);
                k = (k + 1) % n;
            }
            // The separator at b is walked from the right of a → b to its
            // left, the one at a from the left to the right: one that starts
            // at the corner lies on the side it goes to, one that ends there
            // on the side it comes from, and one that does neither passes
            // through the corner.
            for (h, corner, to_left) in [(around[at_b], b, true), (around[at_a], a, false)] {
                let at_corner = |end: Option<EdgeEnd>| match end {
                    Some(EdgeEnd::Vertex(v)) => self.touches_only(v, corner),
                    _ => false,
                };
                let (from, to) = (at_corner(self.half_edge_origin(h)), at_corner(self.half_edge_target(h)));
                if !straight(corner) {
                    // A corner kinked by a rounding between an arc and the
                    // next piece (ends written to 8 decimals: 1e-9 rad) has
                    // a cell of no width on its reflex side, but the
                    // construction may give it as a line through the
                    // corner, in to the centre of the arc's circle: that
                    // separator passes through the corner as at a
                    // straight one, located by its ends
                    let arc = matches!(self.sites.at(s.index()), Site::Arc(_));
                    let at = self.point_of(corner);
                    let through = arc
                        && !from
                        && !to
                        && self.edge_end_points(h.edge(), at).is_some_and(|p| either_side_of(at, self.toward(s, corner), p));
                    if !through {
                        continue;
                    }
                }
                match (from, to) {
                    (true, false) => side[h.index()] = Some(to_left),
                    (false, true) => side[h.index()] = Some(!to_left),
                    (false, false) => {
                        // the end where h goes is on the left (to_left) or right
                        let target_end = usize::from(!h.is_reversed());
                        let target_inside = to_left == left_inside;
                        through.push((h.edge(), if target_inside { target_end } else { 1 - target_end }));
                    }
                    (true, true) => {}
                }
            }
        }
        (side, through)
    }

    /// The edges near the tangent joins of curved rings (a straight corner
    /// where an arc ends), located by geometry rather than by the order
    /// around the cells: at such a join the corner's cell has no width,
    /// and the construction may give it as a sliver anywhere along the
    /// normal there, so that the separators need not reach the corner and
    /// the edge between the two pieces may pass through it instead. Each
    /// edge between two of the join's sites (its corner and the pieces
    /// ending there) that passes through the corner (to 1e-7 of the
    /// extent, the arcs' vertex solver's precision with room) is a through
    /// edge, its inside end the one whose vertex lies inside (even-odd,
    /// `point_location`); one that does not lies where its end farther
    /// from the corner lies.
    fn tangent_join_edges(&self, rings: &[Ring], role: &[Role]) -> Vec<(EdgeId, JoinEdge)> {
        let tolerance = 1e-7 * self.extent.max(f64::MIN_POSITIVE);
        let arc = |t: SiteId| matches!(self.sites.at(t.index()), Site::Arc(_));
        // per site: the tangent-join corner it belongs to
        let mut join_of: std::collections::HashMap<SiteId, Vec<SiteId>> = std::collections::HashMap::new();
        for ring in rings.iter().filter(|r| r.curved) {
            let n = ring.corners.len();
            for k in 0..n {
                let (c, before, after) = (ring.corners[k], ring.segments[(k + n - 1) % n], ring.segments[k]);
                let straight = matches!(role[c.index()], Role::RingCorner { cell: Location::Boundary });
                if straight && (arc(before) || arc(after)) {
                    for s in [c, before, after] {
                        join_of.entry(s).or_default().push(c);
                    }
                }
            }
        }
        let mut out = Vec::new();
        for e in (0..self.edges.len()).map(EdgeId::from_index) {
            let Some(edge) = self.edge(e) else { continue };
            let [u, v] = edge.sites;
            let (Some(cu), Some(cv)) = (join_of.get(&u), join_of.get(&v)) else { continue };
            // two arcs of one circle share both their ends: the corner
            // the edge reaches (ends at or passes through)
            let Some(&corner) = cu
                .iter()
                .filter(|c| cv.contains(c))
                .min_by(|&&a, &&b| self.edge_reach(e, self.point_of(a)).total_cmp(&self.edge_reach(e, self.point_of(b))))
            else {
                continue;
            };
            let at = self.point_of(corner);
            let ends = edge.ends.map(|end| match end {
                EdgeEnd::Vertex(w) => Some(self.store.position[w.index()]),
                EdgeEnd::Infinite { .. } => None,
            });
            let near = |p: Option<Point>| p.is_some_and(|p| p.distance(at) <= tolerance);
            if near(ends[0]) && near(ends[1]) {
                continue; // an edge of no length at the corner
            }
            let Some([p0, p1]) = self.edge_end_points(e, at) else { continue };
            // A separator (the corner and a piece ending there) lies on a
            // line through the corner: it passes through it when its ends
            // lie either side along that line. That is sure where the
            // chord to a far end is not (a vertex far out is placed only
            // to its solver's precision, which at 1e16 is no direction).
            let along_separator = [u, v].iter().find_map(|&t| {
                let other = if t == u { v } else { u };
                (other == corner).then(|| self.toward(t, corner))
            });
            let either_side = along_separator.map(|q| either_side_of(at, q, [p0, p1]));
            let passes = !near(ends[0]) && !near(ends[1]) && either_side.unwrap_or_else(|| self.edge_reach(e, at) <= tolerance);
            // along the join's normal: the line from an arc's centre there
            let normal = [u, v].iter().find_map(|&t| match self.sites.at(t.index()) {
                Site::Arc(a) => Some(a.centre()),
                _ => None,
            });
            let off_line = |p: Point, c: Point| {
                let (dx, dy) = (at.x - c.x, at.y - c.y);
                ((p.x - at.x) * dy - (p.y - at.y) * dx).abs() / dx.hypot(dy)
            };
            let normal = normal.is_some_and(|c| off_line(p0, c) <= tolerance && off_line(p1, c) <= tolerance);
            let location = |p: Point| self.point_location(rings, p);
            if passes {
                let inside = if location(p0) == Location::Inside { 0 } else { 1 };
                out.push((e, JoinEdge { at: JoinAt::Through(inside), normal }));
            } else {
                // off the corner: where its end away from the corner lies
                let away = if p0.distance(at) >= p1.distance(at) { p0 } else { p1 };
                let l = location(away);
                if l != Location::Boundary {
                    out.push((e, JoinEdge { at: JoinAt::Side(l), normal }));
                }
            }
        }
        out
    }

    /// A point standing for each end of edge `e`: its vertex, or for an end
    /// at infinity a point far out toward it (beyond the extent and the
    /// other end's distance from `at`). `None` for an edge infinite at
    /// both ends.
    fn edge_end_points(&self, e: EdgeId, at: Point) -> Option<[Point; 2]> {
        let edge = self.edge(e)?;
        let ends = edge.ends.map(|end| match end {
            EdgeEnd::Vertex(w) => Some(self.store.position[w.index()]),
            EdgeEnd::Infinite { .. } => None,
        });
        let far = |k: usize| match (ends[k], edge.ends[k], ends[1 - k]) {
            (Some(p), _, _) => Some(p),
            (None, EdgeEnd::Infinite { direction }, Some(q)) => {
                let reach = 4.0 * self.extent.max(q.distance(at));
                Some(Point::new(q.x + reach * direction.x, q.y + reach * direction.y))
            }
            _ => None,
        };
        Some([far(0)?, far(1)?])
    }

    /// Among the half-edges `around` the cell of ring piece `s`, the one
    /// across to another ring piece ending at `corner` that passes nearest
    /// to it (two arcs of one circle meet at both its ends); only where an
    /// arc is among the two (segments always leave the corner's cell
    /// between them). `None` when there is none.
    fn join_edge(&self, s: SiteId, corner: SiteId, around: &[crate::HalfEdge], role: &[Role]) -> Option<usize> {
        let arc = |t: SiteId| matches!(self.sites.at(t.index()), Site::Arc(_));
        let at = self.point_of(corner);
        let candidates = around.iter().enumerate().filter_map(|(k, h)| {
            let t = self.half_edge_cell(h.twin())?;
            let joined = t != s
                && matches!(role[t.index()], Role::RingSegment { .. })
                && (arc(s) || arc(t))
                && self.segment_endpoints(t).is_some_and(|e| e.contains(&corner));
            joined.then(|| (k, self.edge_reach(h.edge(), at)))
        });
        candidates.min_by(|x, y| x.1.total_cmp(&y.1)).map(|(k, _)| k)
    }

    /// How near edge `e` passes to `p`: the distance from `p` to the chord
    /// between its end vertices (a ray from its finite end at infinity).
    fn edge_reach(&self, e: EdgeId, p: Point) -> f64 {
        let Some(edge) = self.edge(e) else { return f64::INFINITY };
        let position = |end: EdgeEnd| match end {
            EdgeEnd::Vertex(v) => Some(self.store.position[v.index()]),
            EdgeEnd::Infinite { .. } => None,
        };
        let to_segment = |a: Point, b: Point| {
            let (dx, dy) = (b.x - a.x, b.y - a.y);
            let length = dx * dx + dy * dy;
            let t = if length > 0.0 { (((p.x - a.x) * dx + (p.y - a.y) * dy) / length).clamp(0.0, 1.0) } else { 0.0 };
            p.distance(Point::new(a.x + t * dx, a.y + t * dy))
        };
        match (position(edge.ends[0]), position(edge.ends[1]), edge.ends) {
            (Some(a), Some(b), _) => to_segment(a, b),
            (Some(a), None, [_, EdgeEnd::Infinite { direction }]) | (None, Some(a), [EdgeEnd::Infinite { direction }, _]) => {
                let far = self.extent.max(a.distance(p)) * 4.0;
                to_segment(a, Point::new(a.x + far * direction.x, a.y + far * direction.y))
            }
            _ => f64::INFINITY,
        }
    }

    /// The finite vertex where `h` ends.
    fn target_of(&self, h: crate::HalfEdge) -> Option<usize> {
        match self.half_edge_target(h)? {
            EdgeEnd::Vertex(v) => Some(v.index()),
            EdgeEnd::Infinite { .. } => None,
        }
    }

    /// Whether every site of vertex `v` is the point site `p` or a segment
    /// ending there: `v` lies at `p`, at clearance zero.
    fn touches_only(&self, v: VertexId, p: SiteId) -> bool {
        let sites = self.store.sites_of(v);
        let ends_there = sites.iter().all(|&s| s == p || self.segment_endpoints(s).is_some_and(|e| e.contains(&p)));
        // Two arcs can share both ends (a circle of two halves), and an
        // arc's concave side has vertices among its own ends away from
        // them (the circle's centre): with an arc, the vertex must also be
        // at the corner (to the arcs' vertex solver's precision).
        let arc = sites.iter().any(|s| matches!(self.sites.at(s.index()), Site::Arc(_)));
        ends_there
            && (!arc || self.store.position[v.index()].distance(self.point_of(p)) <= 1e-9 * self.extent.max(f64::MIN_POSITIVE))
    }

    /// Where the cell of corner `p` lies, where `segments` (more than two)
    /// end: in the one wedge between consecutive segments around `p` that is
    /// at least a half turn, on the side of a ring segment bounding it
    /// (exact orientations); `Boundary` when there are two such wedges (a
    /// straight corner) or none, or only obstacles bound it.
    fn shared_corner_cell(&self, p: SiteId, segments: &[SiteId], role: &[Role]) -> Location {
        let here = self.point_of(p);
        let mut around: Vec<(SiteId, Point)> = segments
            .iter()
            .filter_map(|&s| {
                self.segment_endpoints(s)?;
                Some((s, self.toward(s, p)))
            })
            .collect();
        around.sort_by(|x, y| crate::geometry::predicates::compare_directions(here, x.1, y.1));
        // The side of ring segment `s` leaving `p`: its left, or its right.
        let side = |s: SiteId, left: bool| match role[s.index()] {
            Role::RingSegment { left_inside } => {
                let from_p = self.segment_endpoints(s).is_some_and(|[a, _]| a == p);
                Some(inside_if((left == from_p) == left_inside))
            }
            _ => None,
        };
        let n = around.len();
        let mut cell = None;
        for k in 0..n {
            let ((u, to_u), (v, to_v)) = (around[k], around[(k + 1) % n]);
            if self.turn(here, to_u, to_v) == Orientation::CounterClockwise {
                continue; // less than a half turn from u to v
            }
            if cell.is_some() {
                return Location::Boundary;
            }
            // counter-clockwise from u to v: left of u, right of v
            cell = Some(side(u, true).or_else(|| side(v, false)).unwrap_or(Location::Boundary));
        }
        cell.unwrap_or(Location::Boundary)
    }

    /// A vertex of radius zero at a ring corner: a corner and two segments
    /// that both end there.
    fn is_ring_corner_vertex(&self, v: VertexId, role: &[Role]) -> bool {
        let sites = self.store.sites_of(v);
        sites.iter().any(|&p| matches!(role[p.index()], Role::RingCorner { .. }) && self.touches_only(v, p))
    }

    /// The rings with their corners, direction and inside side.
    fn rings_of(&self, inputs: &[RingInput]) -> Vec<Ring> {
        let mut rings: Vec<Ring> = inputs
            .iter()
            .map(|input| {
                let segments: Vec<SiteId> = match &input.pieces {
                    Some(pieces) => pieces
                        .iter()
                        .map(|&p| match p {
                            crate::ChainPiece::Segment(j) => self.segment_site[j],
                            crate::ChainPiece::Arc(k) => self.arc_site[k],
                        })
                        .collect(),
                    None => input.segments.clone().map(|j| self.segment_site[j]).collect(),
                };
                let curved = segments.iter().any(|s| matches!(self.sites.at(s.index()), Site::Arc(_)));
                let n = segments.len();
                // corner k joins segment k - 1 and segment k
                let corners = (0..n)
                    .map(|k| {
                        let (before, here) = (segments[(k + n - 1) % n], segments[k]);
                        let ends = self.segment_endpoints(here).unwrap_or([here, here]);
                        let shared = self.segment_endpoints(before).unwrap_or([before, before]);
                        // (the pieces of a bulged ring run forward, from
                        // their corner; a ring of two pieces shares both ends)
                        if input.pieces.is_some() || shared.contains(&ends[0]) {
                            ends[0]
                        } else {
                            ends[1]
                        }
                    })
                    .collect();
                let corners: Vec<SiteId> = corners;
                // an arc may bulge beyond its corners: its own box (not its
                // circle's, which may reach far beyond the ring: a shallow
                // arc of a hole would then seem to stick out of its shell)
                let reach = segments.iter().filter_map(|s| self.arc_of(*s)).flat_map(|arc| {
                    let [x0, x1, y0, y1] = crate::geometry::input::arc_contact::arc_box(&arc);
                    [Point::new(x0, y0), Point::new(x1, y1)]
                });
                let bounds = Bounds::of(corners.iter().map(|&c| self.point_of(c)).chain(reach));
                Ring { corners, segments, curved, left_inside: false, bounds, depth: 0, parent: None }
            })
            .collect();
        let counter_clockwise: Vec<bool> = rings.iter().map(|r| self.is_counter_clockwise(r)).collect();
        let enclosing: Vec<Vec<usize>> = (0..rings.len()).map(|r| self.enclosing_rings(&rings, r)).collect();
        for r in 0..rings.len() {
            let depth = enclosing[r].len();
            rings[r].left_inside = counter_clockwise[r] == (depth % 2 == 0);
            rings[r].depth = depth;
            // rings are nested in a chain: the innermost encloser is the deepest
            rings[r].parent = enclosing[r].iter().copied().max_by_key(|&o| enclosing[o].len());
        }
        rings
    }

    /// The orientation of a ring, from the exact turn at its lowest-leftmost
    /// corner (an extreme corner of a simple ring turns the ring's way).
    fn is_counter_clockwise(&self, ring: &Ring) -> bool {
        if ring.curved {
            return self.curved_ring_area(ring) > 0.0;
        }
        let n = ring.corners.len();
        let key = |k: usize| {
            let p = self.point_of(ring.corners[k]);
            (p.x, p.y)
        };
        let low = (0..n).min_by(|&i, &j| key(i).partial_cmp(&key(j)).expect("finite")).unwrap_or(0);
        let [prev, here, next] = [(low + n - 1) % n, low, (low + 1) % n].map(|k| self.point_of(ring.corners[k]));
        self.turn(prev, here, next) == Orientation::CounterClockwise
    }

    /// The other rings that contain ring `r` (rings neither cross nor
    /// overlap, so one corner of `r` not on another ring tells). A ring
    /// that contains `r` holds its corners: their box, exact, is what the
    /// other's box (its arcs' widened) must hold.
    fn enclosing_rings(&self, rings: &[Ring], r: usize) -> Vec<usize> {
        let corners = &rings[r].corners;
        let n = corners.len();
        let corner_box = Bounds::of(corners.iter().map(|&c| self.point_of(c)));
        (0..rings.len())
            .filter(|&other| other != r && rings[other].bounds.holds(&corner_box))
            .filter(|&other| {
                let by_corner = corners
                    .iter()
                    .map(|&c| self.ring_location(&rings[other], self.point_of(c)))
                    .find(|&l| l != Location::Boundary)
                    .map(|l| l == Location::Inside);
                // every corner on the other ring (a hole touching its shell
                // at all its corners, each a corner of both after the
                // exact split): where a side of `r` leaves its corner
                by_corner.or_else(|| {
                    (0..n).find_map(|k| {
                        let (p, q) = (self.point_of(corners[k]), self.point_of(corners[(k + 1) % n]));
                        self.ring_holds_direction(&rings[other], p, q)
                    })
                }) == Some(true)
            })
            .collect()
    }

    /// Where an obstacle lies. A point, or a segment with an end off the
    /// rings: where that point is. A segment between two ring corners (it
    /// touches the rings only there): where it leaves its first end, by
    /// exact orientations against the rings' corners there.
    fn obstacle_location(&self, rings: &[Ring], s: SiteId) -> Location {
        if let Site::Arc(arc) = self.sites.at(s.index()) {
            // an arc obstacle meets the rings at its ends at most
            return [arc.midpoint(), arc.start(), arc.end()]
                .into_iter()
                .map(|p| self.point_location(rings, p))
                .find(|&l| l != Location::Boundary)
                .unwrap_or(Location::Boundary);
        }
        let Site::Segment { a, b } = self.sites.at(s.index()) else { return self.point_location(rings, self.point_of(s)) };
        for p in [a, b] {
            let at = self.point_location(rings, p);
            if at != Location::Boundary {
                return at;
            }
        }
        self.direction_location(rings, a, b)
    }

    /// Whether the segment from the ring corner `p` towards `q` starts
    /// inside the domain: the parity of the rings whose region holds that
    /// direction at `p` (`ring_holds_direction` at the rings `p` is a
    /// corner of, `ring_location` of `p` for the others). Collinear with a
    /// ring's side (an overlap the input check refuses): the boundary.
    fn direction_location(&self, rings: &[Ring], p: Point, q: Point) -> Location {
        let mut inside = false;
        for ring in rings.iter().filter(|r| r.bounds.holds_point(p)) {
            if !ring.corners.iter().any(|&c| self.point_of(c) == p) {
                // `p` is a corner of another ring only: this one holds the
                // direction where it holds `p` (a segment from a hole's
                // corner to its shell's crosses the shell's region)
                match self.ring_location(ring, p) {
                    Location::Inside => inside = !inside,
                    Location::Outside => {}
                    Location::Boundary => return Location::Boundary,
                }
                continue;
            }
            match self.ring_holds_direction(ring, p, q) {
                Some(holds) => inside ^= holds,
                None => return Location::Boundary,
            }
        }
        inside_if(inside)
    }

    /// Whether the direction from `p` towards `q` enters the region of
    /// `ring` (inside it) at `p`, as parity over the ring's corners at `p`
    /// (a ring's region is the wedge at a corner on its inside, the left of
    /// a counter-clockwise ring; false where `p` is no corner); `None` when
    /// the direction runs along a side.
    fn ring_holds_direction(&self, ring: &Ring, p: Point, q: Point) -> Option<bool> {
        let n = ring.corners.len();
        let mut inside = false;
        for k in (0..n).filter(|&k| self.point_of(ring.corners[k]) == p) {
            if ring.curved {
                inside ^= self.curved_corner_holds(ring, k, p, q)?;
                continue;
            }
            let (before, after) = (self.point_of(ring.corners[(k + n - 1) % n]), self.point_of(ring.corners[(k + 1) % n]));
            // the region's wedge runs counter-clockwise from `from` to `to`
            let (from, to) = if self.is_counter_clockwise(ring) { (after, before) } else { (before, after) };
            let (turn_from, turn_to) = (self.turn(p, from, q), self.turn(p, q, to));
            if turn_from == Orientation::Collinear || turn_to == Orientation::Collinear {
                return None;
            }
            let ccw = Orientation::CounterClockwise;
            let holds = if self.turn(p, from, to) == ccw {
                turn_from == ccw && turn_to == ccw
            } else {
                // a reflex wedge: all but the convex one the other way
                !(turn_from != ccw && turn_to != ccw)
            };
            inside ^= holds;
        }
        Some(inside)
    }

    /// Whether the region of the curved `ring` holds the direction from its
    /// corner `k` (at `p`) toward `q`, as the pieces a hair from the corner
    /// see it: by exact turns, and where the direction runs along a piece's
    /// tangent by the piece's curve (`exact_join::turn_between`; a segment
    /// from a circle's top along its tangent lies outside it). `None` where
    /// even that ties (the segment along a segment of the ring: an overlap)
    /// or out of range.
    fn curved_corner_holds(&self, ring: &Ring, k: usize, p: Point, q: Point) -> Option<bool> {
        let n = ring.corners.len();
        let piece = |s: SiteId| self.sites.at(s.index());
        let (before, after) = (piece(ring.segments[(k + n - 1) % n]), piece(ring.segments[k]));
        // the region's wedge runs counter-clockwise from `from` to `to`
        let (from, to) = if self.is_counter_clockwise(ring) { (after, before) } else { (before, after) };
        let query = Site::Segment { a: p, b: q };
        let turn = |u: &Site, v: &Site| exact_join::turn_between(u, v, p);
        let (turn_from, turn_to) = (turn(&from, &query)?, turn(&query, &to)?);
        if turn_from == 0 || turn_to == 0 {
            return None;
        }
        Some(if turn(&from, &to)? > 0 {
            turn_from > 0 && turn_to > 0
        } else {
            // a reflex wedge: all but the convex one the other way
            turn_from > 0 || turn_to > 0
        })
    }

    /// The even-odd location of `p` against all rings.
    fn point_location(&self, rings: &[Ring], p: Point) -> Location {
        let mut inside = false;
        for ring in rings.iter().filter(|ring| ring.bounds.holds_point(p)) {
            match self.ring_location(ring, p) {
                Location::Boundary => return Location::Boundary,
                Location::Inside => inside = !inside,
                Location::Outside => {}
            }
        }
        inside_if(inside)
    }

    /// Whether `p` is inside one ring, exactly: a ray to the right crosses
    /// an edge that runs upward with `p` on its left, or downward with `p`
    /// on its right (half-open in `y`, so a corner is counted once).
    fn ring_location(&self, ring: &Ring, p: Point) -> Location {
        if ring.curved {
            return self.curved_ring_location(ring, p);
        }
        let n = ring.corners.len();
        let mut inside = false;
        for k in 0..n {
            let (a, b) = (self.point_of(ring.corners[k]), self.point_of(ring.corners[(k + 1) % n]));
            let turn = self.turn(a, b, p);
            if turn == Orientation::Collinear
                && p.x >= a.x.min(b.x)
                && p.x <= a.x.max(b.x)
                && p.y >= a.y.min(b.y)
                && p.y <= a.y.max(b.y)
            {
                return Location::Boundary;
            }
            let upward = a.y <= p.y && p.y < b.y;
            let downward = b.y <= p.y && p.y < a.y;
            if (upward && turn == Orientation::CounterClockwise) || (downward && turn == Orientation::Clockwise) {
                inside = !inside;
            }
        }
        inside_if(inside)
    }

    /// The arc of an arc site; `None` for any other.
    fn arc_of(&self, s: SiteId) -> Option<crate::geometry::CircularArc> {
        match self.sites.at(s.index()) {
            Site::Arc(arc) => Some(arc),
            _ => None,
        }
    }

    /// A point in the direction in which piece `s` (a segment or an arc)
    /// leaves its endpoint `corner`: a segment's other end (exact), or a
    /// point along an arc's tangent there, as far out as its chord is long.
    fn toward(&self, s: SiteId, corner: SiteId) -> Point {
        let at = self.point_of(corner);
        match self.sites.at(s.index()) {
            Site::Arc(arc) => {
                let t = arc.tangent_into(at);
                let length = arc.start().distance(arc.end());
                Point::new(at.x + length * t.x, at.y + length * t.y)
            }
            Site::Segment { a, b } => {
                if a == at {
                    b
                } else {
                    a
                }
            }
            _ => at,
        }
    }

    /// The turn of a curved ring at corner `here` from piece `before` into
    /// piece `after`: the turn of their tangents there (floating point). A
    /// join is straight (tangent) to within what rounding its input can
    /// do: 1e-10 of a radian, or the angle of a few ulps of the corner's
    /// coordinates across the shorter piece's chord (a fillet written an
    /// ulp off tangent far from the origin is a tangent join to its user,
    /// and gets no branch of the medial axis). Where the tangents are
    /// opposite (a cusp), the turn of the chords decides.
    fn corner_turn(&self, before: SiteId, here: SiteId, after: SiteId) -> Orientation {
        let at = self.point_of(here);
        let unit = |q: Point| {
            let (dx, dy) = (q.x - at.x, q.y - at.y);
            let n = dx.hypot(dy);
            Point::new(dx / n, dy / n)
        };
        let (back, ahead) = (unit(self.toward(before, here)), unit(self.toward(after, here)));
        // arriving along -back, leaving along ahead
        let cross = -back.x * ahead.y + back.y * ahead.x;
        let dot = -back.x * ahead.x - back.y * ahead.y;
        let chord = |s: SiteId| {
            let [a, b] = self.sites.at(s.index()).ends();
            a.distance(b)
        };
        let rounding = 8.0 * f64::EPSILON * at.x.abs().max(at.y.abs()) / chord(before).min(chord(after));
        if cross.abs() > rounding.max(1e-10) {
            return if cross > 0.0 { Orientation::CounterClockwise } else { Orientation::Clockwise };
        }
        if dot > 0.0 {
            return Orientation::Collinear;
        }
        let other = |s: SiteId| {
            let [a, b] = self.sites.at(s.index()).ends();
            if a == at {
                b
            } else {
                a
            }
        };
        self.turn(other(before), at, other(after))
    }

    /// The signed area of a curved ring (positive counter-clockwise): the
    /// polygon of its corners and, per arc, the circular segment between
    /// its chord and it, `r²/2 (θ - sin θ)` for its signed sweep `θ` in the
    /// ring's direction.
    fn curved_ring_area(&self, ring: &Ring) -> f64 {
        let n = ring.corners.len();
        let origin = self.point_of(ring.corners[0]);
        let mut area = 0.0;
        for k in 0..n {
            let (a, b) = (self.point_of(ring.corners[k]), self.point_of(ring.corners[(k + 1) % n]));
            area += ((a.x - origin.x) * (b.y - origin.y) - (b.x - origin.x) * (a.y - origin.y)) / 2.0;
            if let Some(arc) = self.arc_of(ring.segments[k]) {
                let theta = if arc.start() == a { arc.sweep() } else { -arc.sweep() };
                area += arc.radius() * arc.radius() / 2.0 * (theta - theta.sin());
            }
        }
        area
    }

    /// Whether `p` is inside a curved ring: the even-odd test of the
    /// polygon of its chords, changed by each arc's circular segment (the
    /// region between its chord and it) that holds `p`. Which side of a
    /// chord `p` lies on is exact; whether it is inside an arc's circle is
    /// floating point (the centre is rounded), with `p` within `1e-12` of
    /// the radius on the arc counted as on the boundary. A point on a
    /// chord's line is moved up by an infinitesimal (then right by a
    /// smaller one) for both tests: the same side of every chord.
    fn curved_ring_location(&self, ring: &Ring, p: Point) -> Location {
        let n = ring.corners.len();
        if ring.corners.iter().any(|&c| self.point_of(c) == p) {
            return Location::Boundary;
        }
        let mut inside = false;
        for k in 0..n {
            let (a, b) = (self.point_of(ring.corners[k]), self.point_of(ring.corners[(k + 1) % n]));
            let mut turn = self.turn(a, b, p);
            let within = p.x >= a.x.min(b.x) && p.x <= a.x.max(b.x) && p.y >= a.y.min(b.y) && p.y <= a.y.max(b.y);
            match self.arc_of(ring.segments[k]) {
                Some(arc) => {
                    // a counter-clockwise arc from a to b bulges to the right of a → b
                    let bulge_right = arc.is_counter_clockwise() == (arc.start() == a);
                    let bulge_side = if bulge_right { Orientation::Clockwise } else { Orientation::CounterClockwise };
                    if turn == Orientation::Collinear {
                        // on the chord's line: the side of p moved up by an
                        // infinitesimal (and right by a smaller one), the
                        // same for every chord (two arcs on one chord, a
                        // circle of two halves, must see p on one side)
                        let (dx, dy) = (b.x - a.x, b.y - a.y);
                        let left = if dx != 0.0 { dx > 0.0 } else { dy < 0.0 };
                        turn = if left { Orientation::CounterClockwise } else { Orientation::Clockwise };
                    }
                    if turn == bulge_side {
                        let off = arc.centre().distance(p) - arc.radius();
                        if off.abs() <= 1e-12 * arc.radius() {
                            return Location::Boundary;
                        }
                        inside ^= off < 0.0;
                    }
                }
                None if turn == Orientation::Collinear && within => return Location::Boundary,
                None => {}
            }
            let upward = a.y <= p.y && p.y < b.y;
            let downward = b.y <= p.y && p.y < a.y;
            if (upward && turn == Orientation::CounterClockwise) || (downward && turn == Orientation::Clockwise) {
                inside = !inside;
            }
        }
        inside_if(inside)
    }

    /// The coordinates of a point site.
    fn point_of(&self, s: SiteId) -> Point {
        match self.sites.at(s.index()) {
            other => other.ends()[0],
        }
    }
}

/// An edge near a tangent join of a curved ring
/// (`Diagram::tangent_join_edges`): where it lies, and whether along the
/// join's normal.
#[derive(Clone, Copy, Debug)]
struct JoinEdge {
    at: JoinAt,
    normal: bool,
}

/// Where an edge near a tangent join lies.
#[derive(Clone, Copy, Debug)]
enum JoinAt {
    /// It passes through the corner; the end (an index into `Edge::ends`)
    /// inside the domain.
    Through(usize),
    /// It lies on one side.
    Side(Location),
}

/// The inside end of `e` in the sorted list of edges through straight
/// corners (`Domain::through`); `None` when `e` is not one.
fn inside_end(through: &[(EdgeId, usize)], e: EdgeId) -> Option<usize> {
    through.binary_search_by_key(&e, |&(edge, _)| edge).ok().map(|k| through[k].1)
}

/// Whether `ends` lie either side of the line through `at` across the
/// direction from `at` to `toward` (a piece's direction at its end `at`,
/// across which its separator there runs).
fn either_side_of(at: Point, toward: Point, [p0, p1]: [Point; 2]) -> bool {
    let (dx, dy) = (toward.x - at.x, toward.y - at.y);
    let side = |p: Point| (p.x - at.x) * dy - (p.y - at.y) * dx;
    side(p0) * side(p1) < 0.0
}

fn inside_if(inside: bool) -> Location {
    if inside {
        Location::Inside
    } else {
        Location::Outside
    }
}
