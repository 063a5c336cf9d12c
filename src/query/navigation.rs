//! Half-edge navigation: each edge walked in either direction, with the
//! cell on its left; twins, the next and previous edge around a cell, the
//! edges around a vertex; and which edges are separators.
//!
//! A [`HalfEdge`] is one side of a public edge: `e.half_edges()[0]` runs
//! from `ends[0]` to `ends[1]` with `sites[0]` on its left, `[1]` is its
//! twin. Walking `next` from any half-edge goes counter-clockwise around the
//! cell on its left, and gets back to where it started; around an unbounded
//! cell it steps from the ray that leaves to infinity straight to the ray
//! that comes back (the store's edge along the point at infinity is not an
//! edge of the diagram).

use crate::diagram::{Diagram, EdgeId, HalfEdgeId, SiteId, Store, VertexId, NONE};
use crate::query::EdgeEnd;

/// One side of an edge of the diagram: the edge walked with one of its two
/// cells on the left. Dense ids: `2 × edge + side`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct HalfEdge(u32);

impl HalfEdge {
    /// The half-edge with this index (`2 × edge id + side`).
    #[inline]
    pub fn from_index(i: usize) -> HalfEdge {
        debug_assert!(i < u32::MAX as usize);
        HalfEdge(i as u32)
    }

    /// Its index: `2 × edge id + side`.
    #[inline]
    pub fn index(self) -> usize {
        self.0 as usize
    }

    /// The edge it is a side of.
    #[inline]
    pub fn edge(self) -> EdgeId {
        EdgeId(self.0 / 2)
    }

    /// `false` for the side that runs from the edge's `ends[0]` to
    /// `ends[1]` (with `sites[0]` on its left), `true` for its twin.
    #[inline]
    pub fn is_reversed(self) -> bool {
        self.0 % 2 == 1
    }

    /// The other side of the same edge.
    #[inline]
    pub fn twin(self) -> HalfEdge {
        HalfEdge(self.0 ^ 1)
    }
}

impl std::fmt::Display for HalfEdge {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.0)
    }
}

impl Diagram {
    /// The two sides of an edge: `[0]` from `ends[0]` to `ends[1]`, `[1]` the
    /// other way; `None` if the id is out of range.
    pub fn half_edges(&self, edge: EdgeId) -> Option<[HalfEdge; 2]> {
        (edge.index() < self.edges.len()).then(|| [HalfEdge(2 * edge.0), HalfEdge(2 * edge.0 + 1)])
    }

    /// The site whose cell is on the left of `h`; `None` out of range.
    pub fn half_edge_cell(&self, h: HalfEdge) -> Option<SiteId> {
        Some(self.store.left(self.inner(h)?))
    }

    /// Where `h` starts (its end at infinity has the direction `h` comes
    /// from, reversed); `None` out of range.
    pub fn half_edge_origin(&self, h: HalfEdge) -> Option<EdgeEnd> {
        let e = self.edge(h.edge())?;
        Some(e.ends[usize::from(h.is_reversed())])
    }

    /// Where `h` ends; `None` out of range.
    pub fn half_edge_target(&self, h: HalfEdge) -> Option<EdgeEnd> {
        self.half_edge_origin(h.twin())
    }

    /// The half-edge after `h` around the cell on its left,
    /// counter-clockwise; `None` out of range.
    pub fn next_half_edge(&self, h: HalfEdge) -> Option<HalfEdge> {
        self.step_around_cell(h, |store, k| store.next(k))
    }

    /// The half-edge before `h` around the cell on its left; `None` out of
    /// range.
    pub fn prev_half_edge(&self, h: HalfEdge) -> Option<HalfEdge> {
        self.step_around_cell(h, |store, k| store.prev(k))
    }

    /// The three half-edges leaving a finite vertex, counter-clockwise;
    /// `None` out of range. (The cells between them are the vertex's
    /// `sites`: the one on the left of `[k]` is `sites[(k + 1) % 3]`.)
    pub fn vertex_half_edges(&self, v: VertexId) -> Option<[HalfEdge; 3]> {
        if v.index() >= self.finite_vertices {
            return None;
        }
        // A finite vertex's three cells are real sites, so each of its
        // half-edges is on an edge of the diagram.
        Some([0, 1, 2].map(|slot| self.outer(v.half_edge(slot)).expect("an edge of a finite vertex")))
    }

    /// The half-edges around the cell of `site`, counter-clockwise, the cell
    /// on their left; empty for an id out of range or a lone site.
    pub fn cell_half_edges(&self, site: SiteId) -> impl Iterator<Item = HalfEdge> + '_ {
        let boundary = (site.index() < self.sites.len()).then(|| self.store.cell_boundary(site));
        boundary.into_iter().flatten().filter_map(move |h| self.outer(h))
    }

    /// Whether an edge is a separator: between a segment and one of its own
    /// endpoints (a straight piece of the perpendicular at that endpoint;
    /// Boost.Polygon's "secondary" edge). The medial axis leaves them out.
    /// `None` out of range.
    pub fn is_separator(&self, edge: EdgeId) -> Option<bool> {
        let &h = self.edges.get(edge.index())?;
        let (left, right) = (self.store.left(h), self.store.right(h));
        // segment sites follow the points; their ends in either order
        let own_endpoint = |segment: SiteId, point: SiteId| {
            segment
                .index()
                .checked_sub(self.point_sites)
                .and_then(|k| self.segment_ends.get(k))
                .is_some_and(|ends| ends.contains(&point))
        };
        Some(own_endpoint(left, right) || own_endpoint(right, left))
    }

    /// The store's half-edge of `h`.
    fn inner(&self, h: HalfEdge) -> Option<HalfEdgeId> {
        let &canonical = self.edges.get(h.edge().index())?;
        Some(if h.is_reversed() { self.store.twin(canonical) } else { canonical })
    }

    /// The public half-edge of a store half-edge; `None` for one along the
    /// point at infinity.
    fn outer(&self, h: HalfEdgeId) -> Option<HalfEdge> {
        let e = self.edge_of_half_edge()[h.index()];
        (e != NONE).then(|| HalfEdge(2 * e + u32::from(self.edges[e as usize] != h)))
    }

    /// One step of `step` around the cell on the left of `h`, past the
    /// store's edges along the point at infinity (at most one between two
    /// rays; the bound only guards a corrupt store).
    fn step_around_cell(&self, h: HalfEdge, step: impl Fn(&Store, HalfEdgeId) -> HalfEdgeId) -> Option<HalfEdge> {
        let mut k = self.inner(h)?;
        for _ in 0..4 {
            k = step(&self.store, k);
            if let Some(outer) = self.outer(k) {
                return Some(outer);
            }
        }
        None
    }
}
