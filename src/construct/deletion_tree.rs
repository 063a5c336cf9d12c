//! The deletion tree that both insertions share (DESIGN §2.1 step 4,
//! §2.2 step 4): the marking rounds, which edges leave the tree (cut once,
//! at one end) and which are cut twice (both ends deleted, the middle
//! kept), and the replacement of the tree by the boundary of the new cell.
//!
//! The tree is kept a tree (P1 for points, P3 for segments) by integer
//! marks alone; `replace_tree` is purely combinatorial: one new vertex per
//! leaving edge, joined in a cycle, placed by `Construction::place_vertex`
//! (`state.rs`).
//!
//! Edges cut twice: unlike a point, a segment's new cell can wrap around
//! part of an old cell, so both ends of an old edge go while its middle
//! stays (`twice_cut`, chosen by the segment insertion); and every
//! separator between a segment and its endpoint is cut at both ends when
//! both of its vertices go (its circles all touch the endpoint, so its
//! middle never conflicts).

use super::state::Construction;
use crate::diagram::{HalfEdgeId, SiteId};
use crate::geometry::Point;

impl Construction {
    /// Starts a new marking round: no vertex or cell is marked afterwards.
    pub(super) fn fresh_epoch(&mut self) {
        self.epoch = self.epoch.wrapping_add(1);
        self.twice_cut.clear();
        if self.epoch == 0 {
            self.vertex_mark.iter_mut().for_each(|m| *m = 0);
            self.cell_mark.iter_mut().for_each(|m| *m = 0);
            self.epoch = 1;
        }
    }

    /// P1: whether the vertex `back` leaves (towards the tree, by `back`)
    /// can join the tree as a leaf: it is not in the tree, and neither of its
    /// other two edges leads into it (which would close a cycle), unless that
    /// edge is cut at both ends (see `leaves_tree`).
    pub(super) fn would_stay_a_tree(&self, back: HalfEdgeId) -> bool {
        self.vertex_mark[back.origin().index()] != self.epoch
            && !self.leads_into_tree(back.rotate(1))
            && !self.leads_into_tree(back.rotate(2))
    }

    /// Whether `h` is an edge of the tree itself: it ends in the tree and is
    /// not cut at both ends.
    pub(super) fn leads_into_tree(&self, h: HalfEdgeId) -> bool {
        self.vertex_mark[self.store.target(h).index()] == self.epoch && !self.is_separator(h) && !self.is_twice_cut(h)
    }

    /// Whether `h`, leaving a tree vertex, is cut by the new cell: it leads
    /// out of the tree, or both its ends are in the tree but its middle
    /// stays. That is so for every separator between a segment and its
    /// endpoint `p` (the circles centred on it all touch `p`, shrinking to
    /// nothing there, so its middle never conflicts), and for the edges a
    /// segment insertion chose to cut twice (`twice_cut`).
    pub(super) fn leaves_tree(&self, h: HalfEdgeId) -> bool {
        !self.leads_into_tree(h)
    }

    /// Whether the edge of `h` is one of `twice_cut`.
    pub(super) fn is_twice_cut(&self, h: HalfEdgeId) -> bool {
        !self.twice_cut.is_empty() && {
            let t = self.store.twin(h);
            self.twice_cut.iter().any(|&c| c == h || c == t)
        }
    }

    /// Whether `h` runs between an existing segment and one of its
    /// endpoints. Such an edge is never deleted whole (both of its vertices
    /// in the tree): every segment keeps exactly one separator with each
    /// endpoint, if only of zero length where many segments meet at a point.
    pub(super) fn is_separator(&self, h: HalfEdgeId) -> bool {
        let (l, r) = (self.store.left(h), self.store.right(h));
        self.ends_of(l).is_some_and(|e| e.contains(&r)) || self.ends_of(r).is_some_and(|e| e.contains(&l))
    }

    /// The next edge leaving the tree after `h` (which leaves it too), going
    /// around the tree so that the cell on the left of `h` is on the right of
    /// the result.
    fn next_cut(&self, h: HalfEdgeId) -> HalfEdgeId {
        let mut current = h;
        loop {
            let candidate = current.rotate(1);
            if self.leaves_tree(candidate) {
                return candidate;
            }
            current = self.store.twin(candidate);
        }
    }

    /// Replaces the tree by the boundary of the new cell of site `s`.
    pub(super) fn replace_tree(&mut self, s: SiteId) {
        let epoch = self.epoch;
        let start = self
            .tree
            .iter()
            .flat_map(|u| (0..3).map(move |k| u.half_edge(k)))
            .find(|&h| self.leaves_tree(h))
            .expect("a tree that is not the whole diagram has an edge leaving it");

        // Walk around the tree; each edge leaving it gets one new vertex.
        self.cuts.clear();
        let mut h = start;
        loop {
            self.cuts.push((h, self.store.right(h), self.store.left(h)));
            h = self.next_cut(h);
            if h == start {
                break;
            }
        }
        // What each new vertex's outward edge joins: the kept part of its
        // edge, or for a separator cut at both ends the other new vertex.
        let outside: Vec<Result<HalfEdgeId, usize>> = self
            .cuts
            .iter()
            .map(|&(h, _, _)| {
                let t = self.store.twin(h);
                if self.vertex_mark[t.origin().index()] != epoch {
                    Ok(t)
                } else {
                    Err(self.cuts.iter().position(|&(g, _, _)| g == t).unwrap_or(usize::MAX))
                }
            })
            .collect();

        // An arc's vertex solver can find more than one circle touching
        // the three sites in the order asked; the cut edges' ends, read
        // before their slots are reused, tell it which one lies on the edge.
        let cut_edges: Vec<Option<[Point; 2]>> = if self.inserting_arc.is_some() {
            self.cuts.iter().zip(&outside).map(|(&(h, _, _), link)| link.ok().and_then(|t| self.edge_ends(h, t))).collect()
        } else {
            Vec::new()
        };
        // New vertices reuse the tree's slots (a tree of m degree-3 vertices
        // has m + 2 leaving edges).
        self.new_vertices.clear();
        for j in 0..self.cuts.len() {
            let v = if j < self.tree.len() { self.tree[j] } else { self.push_vertex() };
            self.new_vertices.push(v);
        }
        let k = self.cuts.len();
        debug_assert_eq!(k, self.tree.len() + 2, "P1 keeps the deleted set a tree");
        for (j, &link) in outside.iter().enumerate() {
            let (_, right, left) = self.cuts[j];
            let v = self.new_vertices[j];
            let v_next = self.new_vertices[(j + 1) % k];
            self.set_sites(v, [right, left, s]);
            match link {
                Ok(t) => self.store.link(v.half_edge(0), t),
                Err(partner) => {
                    if let Some(&w) = self.new_vertices.get(partner) {
                        self.store.link(v.half_edge(0), w.half_edge(0));
                    }
                }
            }
            self.store.link(v.half_edge(1), v_next.half_edge(2));
            self.store.cell_edge[left.index()] = v.half_edge(0).0;
            self.vertex_mark[v.index()] = 0;
        }
        self.store.cell_edge[s.index()] = self.new_vertices[0].half_edge(1).0;
        if self.placement_deferred {
            return;
        }
        for j in 0..k {
            let on = cut_edges.get(j).copied().flatten();
            self.place_vertex_on(self.new_vertices[j], on);
        }
    }

    /// The ends of a cut edge: `h` leaving the tree's vertex, `t` its twin
    /// leaving the kept one; an end at infinity far out along its
    /// direction. `None` when both are at infinity.
    fn edge_ends(&self, h: HalfEdgeId, t: HalfEdgeId) -> Option<[Point; 2]> {
        let end = |v: crate::diagram::VertexId| (self.store.position[v.index()], self.store.clearance[v.index()]);
        let ((p, rp), (q, rq)) = (end(h.origin()), end(t.origin()));
        let far = |(from, r): (Point, f64), direction: Point| {
            let reach = 1e3 * (from.x.abs() + from.y.abs() + r + 1.0);
            Point::new(from.x + reach * direction.x, from.y + reach * direction.y)
        };
        match (rp.is_finite(), rq.is_finite()) {
            (true, true) => Some([p, q]),
            (true, false) => Some([p, far((p, rp), q)]),
            (false, true) => Some([far((q, rq), p), q]),
            (false, false) => None,
        }
    }
}
