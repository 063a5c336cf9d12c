//! The half-edge arrays and the navigation on them.

use super::ids::{HalfEdgeId, SiteId, VertexId, NONE};
use crate::geometry::Point;

/// The half-edge store. See the module documentation for the layout.
#[derive(Clone, Debug)]
pub(crate) struct Store {
    /// Per half-edge `3v+i`: the cell on its right (`s_i` of vertex `v`).
    pub right: Vec<SiteId>,
    /// Per half-edge: its twin.
    pub twin: Vec<HalfEdgeId>,
    /// Per vertex: its position, or for a vertex at infinity the unit
    /// direction of its edges.
    pub position: Vec<Point>,
    /// Per vertex: the distance to its sites (`f64::INFINITY` at infinity).
    pub clearance: Vec<f64>,
    /// Per site: one half-edge with the site's cell on its left, or `NONE`
    /// when the site has no cell boundary (fewer than two sites).
    pub cell_edge: Vec<u32>,
    /// The id of the point at infinity.
    pub infinite_site: SiteId,
}

impl Store {
    /// An empty store for `site_count` sites (the point at infinity among
    /// them), with room for about `vertex_hint` vertices.
    pub fn new(site_count: usize, infinite_site: SiteId, vertex_hint: usize) -> Store {
        Store {
            right: Vec::with_capacity(3 * vertex_hint),
            twin: Vec::with_capacity(3 * vertex_hint),
            position: Vec::with_capacity(vertex_hint),
            clearance: Vec::with_capacity(vertex_hint),
            cell_edge: vec![NONE; site_count],
            infinite_site,
        }
    }

    #[inline]
    pub fn vertex_count(&self) -> usize {
        self.position.len()
    }

    #[inline]
    pub fn site_count(&self) -> usize {
        self.cell_edge.len()
    }

    /// Appends a vertex with placeholder contents and returns its id.
    pub fn push_vertex(&mut self) -> VertexId {
        let v = VertexId::from_index(self.position.len());
        self.right.extend_from_slice(&[SiteId(NONE); 3]);
        self.twin.extend_from_slice(&[HalfEdgeId(NONE); 3]);
        self.position.push(Point::default());
        self.clearance.push(0.0);
        v
    }

    #[inline]
    pub fn twin(&self, h: HalfEdgeId) -> HalfEdgeId {
        self.twin[h.index()]
    }

    /// The cell on the right of `h`.
    #[inline]
    pub fn right(&self, h: HalfEdgeId) -> SiteId {
        self.right[h.index()]
    }

    /// The cell on the left of `h`.
    #[inline]
    pub fn left(&self, h: HalfEdgeId) -> SiteId {
        self.right[h.rotate(1).index()]
    }

    /// The cell of vertex `v` that `h` (leaving `v`) does not border.
    #[inline]
    pub fn opposite(&self, h: HalfEdgeId) -> SiteId {
        self.right[h.rotate(2).index()]
    }

    /// The vertex `h` runs to.
    #[inline]
    pub fn target(&self, h: HalfEdgeId) -> VertexId {
        self.twin(h).origin()
    }

    /// The next half-edge along the boundary of the cell on the left of `h`.
    #[inline]
    pub fn next(&self, h: HalfEdgeId) -> HalfEdgeId {
        self.twin(h).rotate(2)
    }

    /// The previous half-edge along the boundary of the cell on the left of `h`.
    #[inline]
    #[allow(dead_code)]
    pub fn prev(&self, h: HalfEdgeId) -> HalfEdgeId {
        self.twin(h.rotate(1))
    }

    /// The three cells around `v`, counter-clockwise.
    #[inline]
    pub fn sites_of(&self, v: VertexId) -> [SiteId; 3] {
        let b = 3 * v.index();
        [self.right[b], self.right[b + 1], self.right[b + 2]]
    }

    /// `true` when the point at infinity is one of the vertex's sites.
    #[inline]
    pub fn is_at_infinity(&self, v: VertexId) -> bool {
        self.sites_of(v).contains(&self.infinite_site)
    }

    /// One half-edge with `site`'s cell on its left, if the cell has a boundary.
    #[inline]
    pub fn cell_edge(&self, site: SiteId) -> Option<HalfEdgeId> {
        let h = self.cell_edge[site.index()];
        (h != NONE).then_some(HalfEdgeId(h))
    }

    /// The half-edges around `site`'s cell, counter-clockwise, cell on the left.
    pub fn cell_boundary(&self, site: SiteId) -> CellBoundary<'_> {
        let start = self.cell_edge(site);
        CellBoundary { store: self, start, current: start, limit: self.twin.len() }
    }

    /// Greedy descent over neighbouring cells: from `start`, move to a
    /// neighbour that is `closer` than the current site while there is one,
    /// at most `limit` moves. `distance` is a rounded measure computed once
    /// per site and handed to `closer((q, dq), (best, d_best))`, which
    /// decides. The store reads no coordinate. In a Voronoi diagram, with an
    /// exact `closer`, the descent ends at a site nearest to the point it
    /// measures from (greedy routing succeeds on a Delaunay graph).
    pub fn descend(
        &self,
        start: SiteId,
        limit: usize,
        distance: impl Fn(SiteId) -> f64,
        closer: impl Fn((SiteId, f64), (SiteId, f64)) -> bool,
    ) -> SiteId {
        let mut current = (start, distance(start));
        for _ in 0..limit {
            let mut best = current;
            for h in self.cell_boundary(current.0) {
                let q = self.right(h);
                if q != self.infinite_site {
                    let candidate = (q, distance(q));
                    if closer(candidate, best) {
                        best = candidate;
                    }
                }
            }
            if best.0 == current.0 {
                break;
            }
            current = best;
        }
        current.0
    }

    /// Joins two half-edges as twins.
    #[inline]
    pub fn link(&mut self, a: HalfEdgeId, b: HalfEdgeId) {
        self.twin[a.index()] = b;
        self.twin[b.index()] = a;
    }

    /// Exchanges the slots of vertices `a` and `b`, keeping every edge.
    pub fn swap_vertices(&mut self, a: VertexId, b: VertexId) {
        if a == b {
            return;
        }
        // Record the outside twins, then move contents, then relink.
        let map = |h: HalfEdgeId| -> HalfEdgeId {
            let o = h.origin();
            if o == a {
                b.half_edge(h.slot())
            } else if o == b {
                a.half_edge(h.slot())
            } else {
                h
            }
        };
        let mut links = [(HalfEdgeId(0), HalfEdgeId(0)); 6];
        for (k, v) in [a, b].into_iter().enumerate() {
            for s in 0..3 {
                let h = v.half_edge(s);
                links[3 * k + s as usize] = (map(h), map(self.twin(h)));
            }
        }
        // Only the cells around a and b can name their half-edges.
        let mut cells = [SiteId(NONE); 6];
        cells[..3].copy_from_slice(&self.sites_of(a));
        cells[3..].copy_from_slice(&self.sites_of(b));
        for s in 0..3 {
            let (ha, hb) = (a.half_edge(s).index(), b.half_edge(s).index());
            self.right.swap(ha, hb);
        }
        self.position.swap(a.index(), b.index());
        self.clearance.swap(a.index(), b.index());
        for (h, t) in links {
            self.link(h, t);
        }
        let mut done = [SiteId(NONE); 6];
        for (k, c) in cells.into_iter().enumerate() {
            if c.0 == NONE || done[..k].contains(&c) {
                continue;
            }
            done[k] = c;
            let e = &mut self.cell_edge[c.index()];
            if *e != NONE {
                *e = map(HalfEdgeId(*e)).0;
            }
        }
    }
}

/// Iterator over the half-edges of one cell boundary.
pub(crate) struct CellBoundary<'a> {
    store: &'a Store,
    start: Option<HalfEdgeId>,
    current: Option<HalfEdgeId>,
    /// Guards against a corrupt store: never more steps than half-edges.
    limit: usize,
}

impl Iterator for CellBoundary<'_> {
    type Item = HalfEdgeId;

    #[inline]
    fn next(&mut self) -> Option<HalfEdgeId> {
        let h = self.current?;
        if self.limit == 0 {
            self.current = None;
            return None;
        }
        self.limit -= 1;
        let n = self.store.next(h);
        self.current = if Some(n) == self.start { None } else { Some(n) };
        Some(h)
    }
}
