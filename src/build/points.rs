//! Topology-oriented incremental insertion of point sites (seed 004 §3.2,
//! §5.2; DESIGN §2.1).
//!
//! To insert `p`: walk to the site `g` nearest to `p`; seed the set `T` of
//! vertices to delete with the vertex of `g`'s cell whose circle most clearly
//! contains `p`; grow `T` through neighbours whose circles contain `p`, but
//! only while
//! - P1: `T` stays a tree (a candidate has exactly one neighbour in `T`), and
//! - P2: every old cell loses one connected piece of its boundary and never
//!   all of it (the candidate's third cell must not be touched by `T` yet);
//!
//! then cut every edge leaving `T` with a new vertex, join the new vertices
//! into the cycle that bounds `p`'s cell, and reuse `T`'s slots.
//!
//! P1 and P2 are kept by integer bookkeeping alone, so the result is a valid
//! diagram whatever the predicates answer. With exact predicates the set
//! grown is exactly the set of vertices whose circles strictly contain `p`,
//! so the result is the exact diagram.
//!
//! Every number comes from `geometry` (`predicates`, `point_predicates`,
//! `vertex_placement`); this module only decides what to ask.

use crate::diagram::{HalfEdgeId, SiteId, VertexId};
use crate::diagram::Store;
use crate::geometry::point_predicates::{self, VertexCircle};
use crate::geometry::predicates::{in_circle, strictly_closer_given, in_half_plane_circle, CirclePosition};
use crate::geometry::vertex_placement;
use crate::geometry::Point;

pub(crate) use super::order::insertion_order;

mod segments;

/// The id of the point at infinity inside the construction.
pub(crate) const INFINITE: SiteId = SiteId(0);

/// How far the fallback seed search may look beyond the nearest cell.
const SEED_SEARCH_LIMIT: usize = 4096;

/// What became of an inserted point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Inserted {
    /// A new site with this id.
    New(SiteId),
    /// The point equals this existing site.
    Duplicate(SiteId),
}

/// What a finished construction hands on.
pub(crate) struct Parts {
    pub store: Store,
    pub sites: Vec<Point>,
    /// Per segment site, in id order after the points: its endpoint sites.
    pub segment_ends: Vec<[SiteId; 2]>,
}

/// The point diagram under construction, with the scratch space of insertion.
pub(crate) struct PointDiagram {
    store: Store,
    /// Coordinates per site id; entry 0 (the point at infinity) is unused.
    sites: Vec<Point>,
    vertex_mark: Vec<u32>,
    cell_mark: Vec<u32>,
    epoch: u32,
    tree: Vec<VertexId>,
    /// Per cut: the leaving half-edge and the cells on its right and left.
    cuts: Vec<(HalfEdgeId, SiteId, SiteId)>,
    new_vertices: Vec<VertexId>,
    /// Edges between two tree vertices that are cut at both ends, their
    /// middle kept (one half-edge of each): where a segment's cell wraps
    /// around part of a cell (see `segments`).
    twice_cut: Vec<HalfEdgeId>,
    /// Site ids from here on are open segments (`u32::MAX`: none yet).
    first_segment: u32,
    /// Per segment site (id minus `first_segment`): its two endpoint sites.
    segment_ends: Vec<[SiteId; 2]>,
}

impl PointDiagram {
    /// A diagram of the point at infinity alone, with room for `n` points.
    pub fn new(n: usize) -> PointDiagram {
        let mut store = Store::new(1, INFINITE, 2 * n + 2);
        store.cell_edge.reserve(n);
        let mut sites = Vec::with_capacity(n + 1);
        sites.push(Point::new(f64::NAN, f64::NAN));
        PointDiagram {
            store,
            sites,
            vertex_mark: Vec::with_capacity(2 * n + 2),
            cell_mark: Vec::with_capacity(n + 1),
            epoch: 0,
            tree: Vec::new(),
            cuts: Vec::new(),
            new_vertices: Vec::new(),
            twice_cut: Vec::new(),
            first_segment: u32::MAX,
            segment_ends: Vec::new(),
        }
        .with_marks()
    }

    fn with_marks(mut self) -> Self {
        self.cell_mark.push(0);
        self
    }

    /// The store and the site coordinates, scratch space dropped.
    pub fn into_parts(self) -> Parts {
        Parts { store: self.store, sites: self.sites, segment_ends: self.segment_ends }
    }

    /// The diagram of a single site: it has a cell but no boundary.
    pub fn add_lone_site(&mut self, p: Point) -> SiteId {
        debug_assert!(self.sites.len() == 1);
        self.add_site(p)
    }

    fn add_site(&mut self, p: Point) -> SiteId {
        let s = SiteId::from_index(self.sites.len());
        self.sites.push(p);
        self.store.cell_edge.push(crate::diagram::NONE);
        self.cell_mark.push(0);
        s
    }

    fn push_vertex(&mut self) -> VertexId {
        self.vertex_mark.push(0);
        self.store.push_vertex()
    }

    /// The diagram of points that all lie on one line, given in order along
    /// it (at least two, all distinct): a ladder of parallel bisectors,
    /// every vertex at infinity. Returns the new site ids in the same order.
    pub fn start_collinear(&mut self, chain: &[Point]) -> Vec<SiteId> {
        debug_assert!(chain.len() >= 2 && self.sites.len() == 1);
        let ids: Vec<SiteId> = chain.iter().map(|&p| self.add_site(p)).collect();
        self.build_ladder(&ids);
        ids
    }

    /// The ladder of parallel bisectors between consecutive sites of `ids`
    /// (added already, at least two), every vertex at infinity.
    fn build_ladder(&mut self, ids: &[SiteId]) {
        let m = ids.len();
        // U_i = (q_i, q_(i+1), inf) on the left of the chain, D_i = (q_(i+1), q_i, inf) on the right.
        let ups: Vec<VertexId> = (0..m - 1).map(|_| self.push_vertex()).collect();
        let downs: Vec<VertexId> = (0..m - 1).map(|_| self.push_vertex()).collect();
        for i in 0..m - 1 {
            self.set_sites(ups[i], [ids[i], ids[i + 1], INFINITE]);
            self.set_sites(downs[i], [ids[i + 1], ids[i], INFINITE]);
        }
        let st = &mut self.store;
        for i in 0..m - 1 {
            let (u, d) = (ups[i], downs[i]);
            st.link(u.half_edge(0), d.half_edge(0));
            if i + 1 < m - 1 {
                st.link(u.half_edge(1), ups[i + 1].half_edge(2));
                st.link(d.half_edge(2), downs[i + 1].half_edge(1));
            } else {
                st.link(u.half_edge(1), d.half_edge(2));
            }
        }
        st.link(ups[0].half_edge(2), downs[0].half_edge(1));
        for i in 0..m - 1 {
            st.cell_edge[ids[i].index()] = ups[i].half_edge(2).0;
        }
        st.cell_edge[ids[m - 1].index()] = ups[m - 2].half_edge(0).0;
        st.cell_edge[INFINITE.index()] = ups[0].half_edge(1).0;
        for v in ups.into_iter().chain(downs) {
            self.place_vertex(v);
        }
    }

    fn set_sites(&mut self, v: VertexId, sites: [SiteId; 3]) {
        let b = 3 * v.index();
        self.store.right[b..b + 3].copy_from_slice(&sites);
    }

    /// Computes the position and clearance of `v` from its three sites
    /// (`geometry::vertex_placement`): a vertex at infinity stores the
    /// direction of its edge and an infinite clearance.
    fn place_vertex(&mut self, v: VertexId) {
        let sites = self.store.sites_of(v);
        let (pos, clearance) = match infinite_rotation(sites) {
            Some((x, y)) => {
                let direction = vertex_placement::direction_at_infinity(self.site_geometry(x), self.site_geometry(y));
                (direction, f64::INFINITY)
            }
            None if self.has_segment(sites) => vertex_placement::circle_of_sites(&sites.map(|s| self.site_geometry(s))),
            None => {
                let [a, b, c] = sites.map(|s| self.sites[s.index()]);
                vertex_placement::circle_of_points(a, b, c)
            }
        };
        self.store.position[v.index()] = vertex_placement::as_stored(pos);
        self.store.clearance[v.index()] = clearance;
    }

    /// Inserts `p`, starting the nearest-site walk at `start`.
    pub fn insert(&mut self, p: Point, start: SiteId) -> Inserted {
        let g = self.nearest_site(start, p);
        if self.sites[g.index()] == p {
            return Inserted::Duplicate(g);
        }
        let s = self.add_site(p);
        self.fresh_epoch();
        let seed = self.seed_vertex(g, p);
        self.grow_tree(seed, p);
        self.replace_tree(s);
        Inserted::New(s)
    }

    /// Starts a new marking round: no vertex or cell is marked afterwards.
    fn fresh_epoch(&mut self) {
        self.epoch = self.epoch.wrapping_add(1);
        self.twice_cut.clear();
        if self.epoch == 0 {
            self.vertex_mark.iter_mut().for_each(|m| *m = 0);
            self.cell_mark.iter_mut().for_each(|m| *m = 0);
            self.epoch = 1;
        }
    }

    /// The site nearest to `p`, by a greedy walk from `start`. With exact
    /// distance comparisons it ends at the nearest site; the step bound only
    /// matters when the comparisons lie.
    fn nearest_site(&self, start: SiteId, p: Point) -> SiteId {
        let sites = &self.sites;
        self.store.descend(
            start,
            self.sites.len() + 8,
            |q| sites[q.index()].distance_squared(p),
            |(q, dq), (best, d_best)| strictly_closer_given(p, sites[q.index()], dq, sites[best.index()], d_best),
        )
    }

    /// Whether the circle of `v` strictly contains `p` (exact).
    fn in_conflict(&self, v: VertexId, p: Point) -> bool {
        let sites = self.store.sites_of(v);
        match infinite_rotation(sites) {
            Some((x, y)) => in_half_plane_circle(self.sites[x.index()], self.sites[y.index()], p),
            None => {
                let [a, b, c] = sites.map(|s| self.sites[s.index()]);
                in_circle(a, b, c, p) == CirclePosition::Inside
            }
        }
    }

    /// How deep `p` lies inside the circle of `v` (negative inside; see
    /// `point_predicates::conflict_depth`). Only used to choose among
    /// candidates.
    fn conflict_depth(&self, v: VertexId, p: Point) -> f64 {
        let position = self.store.position[v.index()];
        let circle = match infinite_rotation(self.store.sites_of(v)) {
            Some((x, _)) => VertexCircle::AtInfinity { x: self.sites[x.index()], direction: position },
            None => VertexCircle::Finite { centre: position, radius: self.store.clearance[v.index()] },
        };
        point_predicates::conflict_depth(circle, p)
    }

    /// The vertex of `g`'s cell whose circle most clearly contains `p`,
    /// checked exactly; if the numbers found none on `g`'s cell (the walk
    /// stopped one cell short), a bounded search around it.
    fn seed_vertex(&mut self, g: SiteId, p: Point) -> VertexId {
        let mut best = None;
        let mut best_depth = f64::INFINITY;
        for h in self.store.cell_boundary(g) {
            let v = h.origin();
            let d = self.conflict_depth(v, p);
            if best.is_none() || d < best_depth {
                best = Some(v);
                best_depth = d;
            }
        }
        let best = best.expect("a cell with a boundary has vertices");
        if self.in_conflict(best, p) {
            return best;
        }
        if let Some(v) = self.store.cell_boundary(g).map(|h| h.origin()).find(|&v| self.in_conflict(v, p)) {
            return v;
        }
        // Breadth-first search outwards from g's cell, bounded; it uses the
        // vertex marks, so a fresh round follows it.
        let found = self.search_seed_around(g, p);
        self.fresh_epoch();
        // None only when the predicates lie: the topology still decides.
        found.unwrap_or(best)
    }

    fn search_seed_around(&mut self, g: SiteId, p: Point) -> Option<VertexId> {
        self.fresh_epoch();
        let mut queue: Vec<VertexId> = Vec::new();
        for h in self.store.cell_boundary(g) {
            let v = h.origin();
            self.vertex_mark[v.index()] = self.epoch;
            queue.push(v);
        }
        let mut i = 0;
        while i < queue.len() && i < SEED_SEARCH_LIMIT {
            let v = queue[i];
            i += 1;
            if self.in_conflict(v, p) {
                return Some(v);
            }
            for s in 0..3 {
                let w = self.store.target(v.half_edge(s));
                if self.vertex_mark[w.index()] != self.epoch {
                    self.vertex_mark[w.index()] = self.epoch;
                    queue.push(w);
                }
            }
        }
        None
    }

    /// Grows the deletion tree from `seed`, keeping P1 and P2.
    fn grow_tree(&mut self, seed: VertexId, p: Point) {
        let epoch = self.epoch;
        self.tree.clear();
        self.tree.push(seed);
        self.vertex_mark[seed.index()] = epoch;
        for c in self.store.sites_of(seed) {
            self.cell_mark[c.index()] = epoch;
        }
        let mut i = 0;
        while i < self.tree.len() {
            let u = self.tree[i];
            i += 1;
            for slot in 0..3 {
                let back = self.store.twin(u.half_edge(slot));
                let w = back.origin();
                if !self.would_stay_a_tree(back) {
                    continue;
                }
                // P2: w's third cell must not have lost a piece already.
                let third = self.store.opposite(back);
                if self.cell_mark[third.index()] == epoch {
                    continue;
                }
                if !self.in_conflict(w, p) {
                    continue;
                }
                self.vertex_mark[w.index()] = epoch;
                self.cell_mark[third.index()] = epoch;
                self.tree.push(w);
            }
        }
    }

    /// P1: whether the vertex `back` leaves (towards the tree, by `back`)
    /// can join the tree as a leaf: it is not in the tree, and neither of its
    /// other two edges leads into it (which would close a cycle), unless that
    /// edge is cut at both ends (see `leaves_tree`).
    fn would_stay_a_tree(&self, back: HalfEdgeId) -> bool {
        self.vertex_mark[back.origin().index()] != self.epoch
            && !self.leads_into_tree(back.rotate(1))
            && !self.leads_into_tree(back.rotate(2))
    }

    /// Whether `h` is an edge of the tree itself: it ends in the tree and is
    /// not cut at both ends.
    fn leads_into_tree(&self, h: HalfEdgeId) -> bool {
        self.vertex_mark[self.store.target(h).index()] == self.epoch && !self.is_separator(h) && !self.is_twice_cut(h)
    }

    /// Whether `h`, leaving a tree vertex, is cut by the new cell: it leads
    /// out of the tree, or both its ends are in the tree but its middle
    /// stays. That is so for every separator between a segment and its
    /// endpoint `p` (the circles centred on it all touch `p`, shrinking to
    /// nothing there, so its middle never conflicts), and for the edges a
    /// segment insertion chose to cut twice (`twice_cut`).
    fn leaves_tree(&self, h: HalfEdgeId) -> bool {
        !self.leads_into_tree(h)
    }

    /// Whether the edge of `h` is one of `twice_cut`.
    fn is_twice_cut(&self, h: HalfEdgeId) -> bool {
        !self.twice_cut.is_empty() && {
            let t = self.store.twin(h);
            self.twice_cut.iter().any(|&c| c == h || c == t)
        }
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
    fn replace_tree(&mut self, s: SiteId) {
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
        for j in 0..k {
            self.place_vertex(self.new_vertices[j]);
        }
    }
}

/// For a vertex with the point at infinity among its sites `[a, b, c]`
/// (counter-clockwise), the other two `(x, y)` rotated so that the point at
/// infinity lies to the left of `x → y`.
#[inline]
fn infinite_rotation([a, b, c]: [SiteId; 3]) -> Option<(SiteId, SiteId)> {
    if c == INFINITE {
        Some((a, b))
    } else if a == INFINITE {
        Some((b, c))
    } else if b == INFINITE {
        Some((c, a))
    } else {
        None
    }
}
