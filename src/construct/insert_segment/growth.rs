//! Growing the deletion tree of a segment `ab` from its path (P3, P5, the
//! conflict and strip criteria), with the edges whose two ends are deleted
//! but whose middle stays out of the new cell cut twice: which edge of each
//! closed cycle that is, by its margin (from the vertices the cuts would
//! create: `geometry::segments::segment_predicates::middle_margin`).

use crate::construct::state::{Construction, INFINITE};
use crate::diagram::{HalfEdgeId, SiteId, VertexId};
use crate::geometry::segments::segment_predicates::{self, in_strip, EdgeContact, EdgeMiddle, FiniteEdge, MiddleMargin};
use crate::geometry::Point;

impl Construction {
    /// Grows the tree from the path: P3, P5, the segment entering the
    /// circle (criteria 1, 2.3), never beyond a deleted vertex outside the
    /// strip (criterion 2.2). A vertex whose other edges lead into the tree
    /// too joins only if each cycle it closes has an edge whose middle the
    /// numbers keep (see `join_closing_cycles`).
    pub(super) fn grow_segment_tree(&mut self, a: SiteId, b: SiteId) {
        let epoch = self.epoch;
        let (pa, pb) = self.segment_between(a, b);
        let mut i = 0;
        while i < self.tree.len() {
            let u = self.tree[i];
            i += 1;
            if !self.vertex_in_strip(u, a, b, pa, pb) {
                continue;
            }
            for slot in 0..3 {
                let back = self.store.twin(u.half_edge(slot));
                let w = back.origin();
                if self.vertex_mark[w.index()] == epoch || self.is_separator(back) {
                    continue;
                }
                // P5: R(a) and R(b), touched by the path, must not lose a
                // second piece. A vertex whose third cell is one of them
                // touches it apart from the tree unless it closes a cycle
                // (the cell then keeps a middle piece somewhere instead);
                // that is checked by counting once the cycle is resolved.
                let third = self.store.opposite(back);
                let touches_end = third == a || third == b;
                if touches_end && !self.leads_into_tree(back.rotate(1)) && !self.leads_into_tree(back.rotate(2)) {
                    continue;
                }
                if !self.segment_conflict(w, a, b) {
                    continue;
                }
                self.vertex_mark[w.index()] = epoch;
                let saved = self.twice_cut.len();
                if self.join_closing_cycles(back, a, b)
                    && (!touches_end || (self.cell_visits(a, w) == 1 && self.cell_visits(b, w) == 1))
                {
                    self.tree.push(w);
                } else {
                    self.twice_cut.truncate(saved);
                    self.vertex_mark[w.index()] = 0;
                }
            }
        }
    }

    /// Whether the tree may grow beyond `u` (criterion 2.2): `u` is at
    /// infinity, or lies in the strip between the perpendiculars at `a` and
    /// `b`. A vertex of both `R(a)` and `R(b)` is on their bisector, in the
    /// strip exactly, whatever its rounded position says.
    fn vertex_in_strip(&self, u: VertexId, a: SiteId, b: SiteId, pa: Point, pb: Point) -> bool {
        if self.store.is_at_infinity(u) {
            return true;
        }
        if let Some(arc) = self.inserting_arc {
            return crate::geometry::arcs::arc_predicates::in_cone(&arc, self.store.position[u.index()]);
        }
        let sites = self.store.sites_of(u);
        (sites.contains(&a) && sites.contains(&b))
            || in_strip(self.store.position[u.index()], self.store.clearance[u.index()], (pa, pb), || {
                sites.map(|s| self.site_geometry(s))
            })
    }

    /// With `w = back.origin()` just marked as joining the tree by `back`:
    /// for each other edge of `w` into the tree, the cycle it closes must
    /// lose one edge, which is cut twice instead of deleted. The edge chosen
    /// is the one of the cycle whose middle most clearly stays out of the new
    /// cell (`middle_margin`), which with exact numbers is the true one: the
    /// edges deleted are then those whose middle is in the new cell, and they
    /// form a tree (an online minimum spanning tree by margin). Returns
    /// `false`, with nothing changed, when some cycle has no edge whose middle
    /// the numbers keep: then `w` stays.
    fn join_closing_cycles(&mut self, back: HalfEdgeId, a: SiteId, b: SiteId) -> bool {
        let saved = self.twice_cut.len();
        // Each closing edge in turn rejoins the tree, whose other closing
        // edges are meanwhile taken as cut, so the tree stays a tree.
        let closing = [back.rotate(1), back.rotate(2)].map(|h| self.leads_into_tree(h).then_some(h));
        let closing = closing.iter().flatten().copied();
        if closing.clone().next().is_none() {
            return true;
        }
        self.twice_cut.extend(closing.clone());
        for (k, edge) in closing.enumerate() {
            let slot = saved + k;
            let cycle = self.tree_path(self.store.target(edge), edge.origin());
            let mut candidates: Vec<(f64, HalfEdgeId)> = std::iter::once(edge)
                .chain(cycle)
                .filter(|&h| self.may_keep_middle(h))
                .map(|h| (self.middle_margin(h, a, b), h))
                .filter(|(margin, _)| margin.middle() == EdgeMiddle::Stays)
                .map(|(margin, h)| (margin.margin(), h))
                .collect();
            candidates.sort_by(|x, y| y.0.total_cmp(&x.0));
            // An edge of R(a) or R(b) may keep its middle only where the rest
            // of that cell's boundary is deleted: P5, one piece lost.
            let w = back.origin();
            let chosen = candidates.into_iter().map(|(_, h)| h).find(|&h| {
                self.twice_cut[slot] = h;
                let sides = [self.store.left(h), self.store.right(h)];
                !(sides.contains(&a) || sides.contains(&b)) || (self.cell_visits(a, w) == 1 && self.cell_visits(b, w) == 1)
            });
            if chosen.is_none() {
                self.twice_cut.truncate(saved);
                return false;
            }
        }
        true
    }

    /// How many separate pieces of the boundary of `cell` the tree (with
    /// `joining`, marked but not yet listed) deletes: the edges leaving it
    /// with `cell` on their left.
    fn cell_visits(&self, cell: SiteId, joining: VertexId) -> usize {
        self.tree
            .iter()
            .chain(std::iter::once(&joining))
            .flat_map(|&u| (0..3).map(move |k| u.half_edge(k)))
            .filter(|&h| self.store.left(h) == cell && self.leaves_tree(h))
            .count()
    }

    /// The half-edges of the tree's path from `from` to `to` (both in the
    /// tree), from `to` back to `from`, by a search over tree edges that
    /// never turns back: the tree edges form a tree, so nothing is reached
    /// twice and no visited set is needed (the search still stops after
    /// as many steps as the tree has vertices).
    fn tree_path(&self, from: VertexId, to: VertexId) -> Vec<HalfEdgeId> {
        // (vertex, index of the entry it was reached from, half-edge used)
        let mut reached: Vec<(VertexId, usize, Option<HalfEdgeId>)> = vec![(from, 0, None)];
        let mut next = 0;
        let mut found = None;
        while next < reached.len() && reached.len() <= self.tree.len() + 2 {
            let (v, _, came_by) = reached[next];
            if v == to {
                found = Some(next);
                break;
            }
            let back = came_by.map(|h| self.store.twin(h));
            for k in 0..3 {
                let h = v.half_edge(k);
                if Some(h) != back && self.leads_into_tree(h) {
                    reached.push((self.store.target(h), next, Some(h)));
                }
            }
            next += 1;
        }
        let mut path = Vec::new();
        let mut at = found;
        while let Some(k) = at {
            let (_, parent, came_by) = reached[k];
            match came_by {
                Some(h) => {
                    path.push(h);
                    at = Some(parent);
                }
                None => at = None,
            }
        }
        path
    }

    /// Whether the edge of `h` may be cut at both ends, its middle kept, by
    /// the path: not an edge of `R(a)` or `R(b)` (P5: they lose one piece
    /// each), and finite.
    pub(super) fn may_cut_twice(&self, h: HalfEdgeId, a: SiteId, b: SiteId) -> bool {
        let sides = [self.store.left(h), self.store.right(h)];
        !sides.contains(&a) && !sides.contains(&b) && self.may_keep_middle(h)
    }

    /// Whether the edge of `h` can keep a middle piece when both its ends
    /// are deleted: a finite edge; and for an arc (whose cell can reach
    /// infinity in a whole range of directions, splitting another site's),
    /// an edge at infinity too.
    fn may_keep_middle(&self, h: HalfEdgeId) -> bool {
        self.is_finite_edge(h)
            || (self.inserting_arc.is_some() && (self.is_edge_at_infinity(h) || self.is_ray(h) || self.is_line(h)))
    }

    /// Whether `h` is a whole bisector between two sites: both ends at
    /// infinity, neither side the point at infinity. An arc's end a hair
    /// outside another arc's circle has such a cell (no finite vertex: a
    /// sliver out to infinity round that circle's radius); an arc ending
    /// there and reaching further out takes both its vertices at infinity,
    /// and the end keeps the bisector's middle.
    fn is_line(&self, h: HalfEdgeId) -> bool {
        self.store.is_at_infinity(h.origin())
            && self.store.is_at_infinity(self.store.target(h))
            && self.store.left(h) != INFINITE
            && self.store.right(h) != INFINITE
    }

    /// Whether `h` is an unbounded edge between two sites: one end at
    /// infinity, the other not. An arc's cell can take a stretch of one
    /// out of its middle (an arc past the end of another arc, the edge of
    /// that end and the other arc running out to infinity beyond it).
    fn is_ray(&self, h: HalfEdgeId) -> bool {
        self.store.is_at_infinity(h.origin()) != self.store.is_at_infinity(self.store.target(h))
            && self.store.left(h) != INFINITE
            && self.store.right(h) != INFINITE
    }

    /// Whether neither end of `h` is at infinity.
    pub(super) fn is_finite_edge(&self, h: HalfEdgeId) -> bool {
        !self.store.is_at_infinity(h.origin()) && !self.store.is_at_infinity(self.store.target(h))
    }

    /// How clearly the middle of the (finite) edge of `h` stays out of the
    /// cell of the segment `ab` when both its ends are in it
    /// (`segment_predicates::middle_margin`), from the edge's sites and
    /// ends and which of `a` and `b` are among its sites.
    pub(super) fn middle_margin(&self, h: HalfEdgeId, a: SiteId, b: SiteId) -> MiddleMargin {
        if let Some(arc) = self.inserting_arc {
            if self.is_edge_at_infinity(h) {
                return self.arc_middle_at_infinity(h, &arc);
            }
            if self.is_line(h) {
                let sides = [self.store.left(h), self.store.right(h)].map(|s| self.site_geometry(s));
                let toward = [h.origin(), self.store.target(h)].map(|v| self.store.position[v.index()]);
                return crate::geometry::arcs::arc_predicates::arc_middle_margin_on_line(
                    (&sides[0], &sides[1]),
                    toward[0],
                    toward[1],
                    &arc,
                )
                .unwrap_or(MiddleMargin::of(f64::NEG_INFINITY));
            }
        }
        let sides = [self.store.left(h), self.store.right(h)];
        let contact = match (sides.contains(&a), sides.contains(&b)) {
            (true, true) => EdgeContact::BothEnds,
            (false, false) => EdgeContact::NoEnd,
            _ => EdgeContact::OneEnd,
        };
        let (left, right) = (self.site_geometry(sides[0]), self.site_geometry(sides[1]));
        let (from, to) = (self.store.position[h.origin().index()], self.store.position[self.store.target(h).index()]);
        if let Some(arc) = self.inserting_arc {
            if self.is_ray(h) {
                // from the finite end out to a point far along the direction
                let (end, direction, sites) = if self.store.is_at_infinity(h.origin()) {
                    (self.store.target(h), from, [right, left])
                } else {
                    (h.origin(), to, [left, right])
                };
                let (p, r) = (self.store.position[end.index()], self.store.clearance[end.index()]);
                let reach = 1e3 * (p.x.abs() + p.y.abs() + r + 1.0);
                let far = Point::new(p.x + reach * direction.x, p.y + reach * direction.y);
                let [left, right] = sites;
                let ray = FiniteEdge { left, right, from: p, to: far };
                return crate::geometry::arcs::arc_predicates::arc_middle_margin_on_ray(ray, &arc);
            }
            return crate::geometry::arcs::arc_predicates::arc_middle_margin(FiniteEdge { left, right, from, to }, contact, &arc);
        }
        segment_predicates::middle_margin(FiniteEdge { left, right, from, to }, contact, self.segment_between(a, b))
    }
}
