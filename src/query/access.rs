//! Iterators and accessors of [`Diagram`].

use crate::diagram::{BuildStats, Diagram, EdgeId, HalfEdgeId, SiteId, ValidationError, VertexId, NONE};
use crate::geometry::predicates::strictly_closer_given;
use crate::geometry::{Point, Site};

/// A finite Voronoi vertex. More fields may come (`#[non_exhaustive]`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Vertex {
    /// Its id.
    pub id: VertexId,
    /// Its position, in input coordinates.
    pub position: Point,
    /// Its distance to each of its three sites. Infinite for a vertex
    /// whose position lies beyond the range of `f64` (only for inputs
    /// whose magnitudes span nearly all of it, such as a coordinate of
    /// 5e-324 beside ordinary ones): `position` is then the nearest `f64`
    /// point, each coordinate beyond the range saturated at `±f64::MAX`.
    pub clearance: f64,
    /// The three sites whose cells meet here, counter-clockwise.
    pub sites: [SiteId; 3],
}

/// One end of an edge: a finite vertex or a direction to infinity, and
/// nothing else ever (so a `match` needs no wildcard arm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EdgeEnd {
    /// The edge ends at this finite vertex.
    Vertex(VertexId),
    /// The edge runs off to infinity in this unit direction.
    Infinite {
        /// Unit direction of the edge at infinity.
        direction: Point,
    },
}

/// A Voronoi edge between two sites: a segment between two vertices, a ray
/// (one end at infinity) or a whole line (both ends at infinity, when all
/// sites are collinear). More fields may come (`#[non_exhaustive]`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Edge {
    /// Its id.
    pub id: EdgeId,
    /// The site on its left and the site on its right, walking from
    /// `ends[0]` to `ends[1]`.
    pub sites: [SiteId; 2],
    /// Where it starts and where it ends.
    pub ends: [EdgeEnd; 2],
}

impl Edge {
    /// `true` when at least one end is at infinity.
    pub fn is_infinite(&self) -> bool {
        self.ends.iter().any(|e| matches!(e, EdgeEnd::Infinite { .. }))
    }
}

/// The cell (Voronoi region) of one site.
#[derive(Clone, Copy, Debug)]
pub struct Cell<'a> {
    diagram: &'a Diagram,
    site: SiteId,
}

impl<'a> Cell<'a> {
    /// The site the cell belongs to.
    pub fn site(&self) -> SiteId {
        self.site
    }

    /// The site.
    pub fn geometry(&self) -> Site {
        self.diagram.sites.at(self.site.index())
    }

    /// The edges around the cell, counter-clockwise. An unbounded cell has
    /// two rays (or lines) among them and no edge "at infinity".
    pub fn edges(&self) -> impl Iterator<Item = EdgeId> + 'a {
        let d = self.diagram;
        let edge_of = d.edge_of_half_edge();
        d.store.cell_boundary(self.site).filter_map(move |h| {
            let e = edge_of[h.index()];
            (e != NONE).then_some(EdgeId(e))
        })
    }

    /// The neighbouring sites, counter-clockwise, one per edge.
    pub fn neighbors(&self) -> impl Iterator<Item = SiteId> + 'a {
        let d = self.diagram;
        let infinite = d.store.infinite_site;
        d.store.cell_boundary(self.site).map(move |h| d.store.right(h)).filter(move |&s| s != infinite)
    }

    /// `true` when the cell reaches infinity (its site is on the convex hull).
    pub fn is_unbounded(&self) -> bool {
        let d = self.diagram;
        d.sites.len() <= 1 || d.store.cell_boundary(self.site).any(|h| d.store.right(h) == d.store.infinite_site)
    }
}

impl Diagram {
    /// Number of sites: distinct points (isolated ones and segment
    /// endpoints), then open segments.
    pub fn site_count(&self) -> usize {
        self.sites.len()
    }

    /// Number of point sites; ids `0..point_site_count()` are points, the
    /// rest open segments.
    pub fn point_site_count(&self) -> usize {
        self.point_sites
    }

    /// A site, in input coordinates, or `None` if the id is out of range.
    pub fn site(&self, site: SiteId) -> Option<Site> {
        self.sites.get(site.index())
    }

    /// The input index of a segment site (what the topology text calls
    /// `S<j>`), or `None` for a point site or an id out of range.
    pub fn segment_input_index(&self, site: SiteId) -> Option<usize> {
        let k = site.index().checked_sub(self.point_sites)?;
        self.segment_input.get(k).map(|&j| j as usize)
    }

    /// Number of arc sites: the last ids, after the open segments.
    pub fn arc_site_count(&self) -> usize {
        self.arc_sites
    }

    /// The input index of an arc site (what the topology text calls
    /// `A<j>`), or `None` for another site or an id out of range.
    pub fn arc_input_index(&self, site: SiteId) -> Option<usize> {
        let k = site.index().checked_sub(self.sites.len() - self.arc_sites)?;
        self.arc_input.get(k).map(|&j| j as usize)
    }

    /// The site that the `index`-th input arc became, or `None` if there is
    /// no such input arc.
    pub fn site_of_arc(&self, index: usize) -> Option<SiteId> {
        self.arc_site.get(index).copied()
    }

    /// The endpoint sites of a segment or arc site, in the order of its
    /// [`Site::Segment`] `a` and `b` (an arc's start and end); `None` for a
    /// point site or an id out of range.
    pub fn segment_endpoints(&self, site: SiteId) -> Option<[SiteId; 2]> {
        let k = site.index().checked_sub(self.point_sites)?;
        let [p, q] = *self.segment_ends.get(k)?;
        // The construction keeps the two ends in either order.
        let first_is_a = match self.sites.at(site.index()) {
            Site::Segment { a, .. } => self.sites.at(p.index()) == Site::Point(a),
            Site::Arc(arc) => self.sites.at(p.index()) == Site::Point(arc.start()),
            _ => true,
        };
        Some(if first_is_a { [p, q] } else { [q, p] })
    }

    /// The site that the `index`-th input segment became: its open segment,
    /// the first of its repeats, or for a zero-length segment the point it
    /// is; `None` if there is no such input segment.
    pub fn site_of_segment(&self, index: usize) -> Option<SiteId> {
        self.segment_site.get(index).copied()
    }

    /// All site ids.
    pub fn site_ids(&self) -> impl ExactSizeIterator<Item = SiteId> {
        (0..self.sites.len()).map(SiteId::from_index)
    }

    /// The site that the `index`-th input point became (repeated points share
    /// one site), or `None` if there is no such input point.
    pub fn site_of_input(&self, index: usize) -> Option<SiteId> {
        self.input_site.get(index).copied()
    }

    /// Number of finite Voronoi vertices.
    pub fn vertex_count(&self) -> usize {
        self.finite_vertices
    }

    /// A site nearest to `p` (the one whose cell contains `p`; on a cell
    /// boundary any of the tied sites), or `None` for an empty diagram.
    /// Walks the diagram from `hint`, or from site 0 without one: a hint near
    /// `p` (say the answer of the previous, nearby query) makes it fast.
    ///
    /// The walk moves to a closer neighbouring site while there is one. That
    /// ends at a nearest site with segments too: if `p` lay outside the cell
    /// of `s`, the straight path from the point of `s` nearest to `p` would
    /// leave that cell into a neighbour's at some `q`, and that neighbour is
    /// then at most `|q - x| + |p - q| = d(p, s)` from `p`. Where distances
    /// tie, the walk looks across the tied neighbours before stopping. With
    /// segment sites the distances are rounded (within an ulp or so of the
    /// nearest distance); among points only, the comparisons are exact.
    ///
    /// ```
    /// use segvoronoi::{Builder, Point, Site};
    /// let mut b = Builder::new();
    /// b.add_points([[0.0, 0.0], [10.0, 0.0], [5.0, 8.0]])?;
    /// let d = b.build()?;
    /// let s = d.nearest_site(Point::new(9.0, 1.0), None).unwrap();
    /// assert_eq!(d.site(s), Some(Site::Point(Point::new(10.0, 0.0))));
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn nearest_site(&self, p: Point, hint: Option<SiteId>) -> Option<SiteId> {
        let n = self.sites.len();
        if n == 0 || !p.is_finite() {
            return None;
        }
        let start = hint.filter(|h| h.index() < n).unwrap_or(SiteId(0));
        if n == 1 {
            return Some(start);
        }
        if self.point_sites < n {
            return Some(self.nearest_among_segments(p, start));
        }
        // Compare distances in the builder's scaled coordinates, where squares
        // of input-sized numbers cannot overflow (a query point far beyond
        // the input may still overflow there: then in input coordinates).
        let f = if p.scaled(self.scale.to_internal).is_finite() { self.scale.to_internal } else { 1.0 };
        let (sites, p) = (&self.sites, p.scaled(f));
        let site = |s: SiteId| match sites.at(s.index()) {
            Site::Point(q) => q.scaled(f),
            other => other.ends()[0].scaled(f), // not reached: points only here
        };
        Some(self.store.descend(
            start,
            n,
            |q| site(q).distance_squared(p),
            |(q, dq), (best, d_best)| strictly_closer_given(p, site(q), dq, site(best), d_best),
        ))
    }

    /// [`Diagram::nearest_site`] when there are segment sites: greedy
    /// descent by rounded distance, then a search across neighbours at the
    /// same distance for a way further down (each round strictly lowers the
    /// distance, so it ends).
    fn nearest_among_segments(&self, p: Point, start: SiteId) -> SiteId {
        let n = self.sites.len();
        let distance = |s: SiteId| {
            let d = self.sites.at(s.index()).distance(p);
            if d.is_nan() {
                f64::INFINITY
            } else {
                d
            }
        };
        let closer = |(_, dq): (SiteId, f64), (_, d_best): (SiteId, f64)| dq < d_best;
        let mut best = self.store.descend(start, n, distance, closer);
        // Usually no neighbour ties: then nothing is allocated.
        while let Some(t) = self.lower_across_ties(best, distance(best), distance) {
            best = self.store.descend(t, n, distance, closer);
        }
        best
    }

    /// A site nearer than `d_best` next to `best` or to a site reachable
    /// from it through neighbours exactly `d_best` away, if there is one.
    fn lower_across_ties(&self, best: SiteId, d_best: f64, distance: impl Fn(SiteId) -> f64) -> Option<SiteId> {
        let mut tied: Vec<SiteId> = Vec::new();
        let (mut at, mut next) = (best, 0);
        loop {
            for h in self.store.cell_boundary(at) {
                let t = self.store.right(h);
                if t == self.store.infinite_site {
                    continue;
                }
                let dt = distance(t);
                if dt < d_best {
                    return Some(t);
                }
                if dt == d_best && t != best && !tied.contains(&t) {
                    tied.push(t);
                }
            }
            at = *tied.get(next)?;
            next += 1;
        }
    }

    /// A finite vertex, or `None` if the id is out of range.
    pub fn vertex(&self, id: VertexId) -> Option<Vertex> {
        (id.index() < self.finite_vertices).then(|| Vertex {
            id,
            position: self.store.position[id.index()],
            clearance: self.store.clearance[id.index()],
            sites: self.store.sites_of(id),
        })
    }

    /// All finite vertices, by id.
    pub fn vertices(&self) -> impl ExactSizeIterator<Item = Vertex> + '_ {
        (0..self.finite_vertices).map(move |v| self.vertex(VertexId::from_index(v)).expect("in range"))
    }

    /// Number of edges between two sites.
    pub fn edge_count(&self) -> usize {
        self.edges.len()
    }

    /// An edge, or `None` if the id is out of range.
    pub fn edge(&self, id: EdgeId) -> Option<Edge> {
        let &h = self.edges.get(id.index())?;
        let t = self.store.twin(h);
        Some(Edge { id, sites: [self.store.left(h), self.store.right(h)], ends: [self.end_of(h), self.end_of(t)] })
    }

    /// Where half-edge `h` starts: its finite vertex, or the direction of
    /// its vertex at infinity.
    pub(super) fn end_of(&self, h: HalfEdgeId) -> EdgeEnd {
        let v = h.origin();
        if v.index() < self.finite_vertices {
            EdgeEnd::Vertex(v)
        } else {
            EdgeEnd::Infinite { direction: self.store.position[v.index()] }
        }
    }

    /// All edges, by id.
    pub fn edges(&self) -> impl ExactSizeIterator<Item = Edge> + '_ {
        (0..self.edges.len()).map(move |e| self.edge(EdgeId::from_index(e)).expect("in range"))
    }

    /// The cell of a site, or `None` if the id is out of range.
    pub fn cell(&self, site: SiteId) -> Option<Cell<'_>> {
        (site.index() < self.sites.len()).then_some(Cell { diagram: self, site })
    }

    /// All cells, by site id.
    pub fn cells(&self) -> impl ExactSizeIterator<Item = Cell<'_>> {
        (0..self.sites.len()).map(move |s| Cell { diagram: self, site: SiteId::from_index(s) })
    }

    /// Counts from the build.
    pub fn stats(&self) -> BuildStats {
        self.stats
    }

    /// Checks every topological invariant of the diagram (see the invariant
    /// checker in the `diagram` module). A diagram returned by the library
    /// always passes; tests call this on every diagram they build.
    pub fn validate(&self) -> Result<(), ValidationError> {
        self.store.validate()?;
        let is_inf = |v: usize| self.store.is_at_infinity(VertexId::from_index(v));
        if (0..self.store.vertex_count()).any(|v| is_inf(v) != (v >= self.finite_vertices)) {
            return Err(ValidationError("finite vertices are not numbered first".into()));
        }
        if self.store.site_count() != self.sites.len() + 1 {
            return Err(ValidationError("site count disagrees with the store".into()));
        }
        self.validate_separators()
    }

    /// Every segment's cell shares exactly one edge with each endpoint's cell
    /// (the separator, on the perpendicular there), and the two endpoints'
    /// cells share none: they lie beyond the two perpendiculars, on either
    /// side of the segment's strip, and can never touch (no circle through
    /// both endpoints misses the open segment between them). An arc's
    /// endpoints may be neighbours: their bisector runs through the arc's
    /// centre, and beyond it (on the side away from the arc's middle) stays
    /// theirs.
    fn validate_separators(&self) -> Result<(), ValidationError> {
        let first_arc = self.segment_ends.len() - self.arc_sites;
        for k in 0..self.segment_ends.len() {
            let s = SiteId::from_index(self.point_sites + k);
            let [a, b] = self.segment_ends[k];
            if k < first_arc && self.store.cell_boundary(a).any(|h| self.store.right(h) == b) {
                return Err(ValidationError(format!("the endpoints {a} and {b} of segment site {s} are neighbours")));
            }
            for end in self.segment_ends[k] {
                let shared = self.store.cell_boundary(s).filter(|&h| self.store.right(h) == end).count();
                if shared != 1 {
                    return Err(ValidationError(format!("segment site {s} shares {shared} edges with its endpoint {end}")));
                }
            }
        }
        Ok(())
    }

    /// Per half-edge its public edge id (`NONE` along the point at infinity).
    pub(crate) fn edge_of_half_edge(&self) -> &[u32] {
        self.edge_of_half_edge.get_or_init(|| {
            let mut map = vec![NONE; self.store.twin.len()];
            for (i, &h) in self.edges.iter().enumerate() {
                map[h.index()] = i as u32;
                map[self.store.twin(h).index()] = i as u32;
            }
            map
        })
    }

    /// The diagonal of the input's bounding box (saturated at `f64::MAX`
    /// for a box whose diagonal lies beyond it).
    pub fn extent(&self) -> f64 {
        self.extent
    }
}
