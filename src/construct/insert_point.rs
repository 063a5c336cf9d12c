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
//! `insert_points` inserts them all, in `insertion_order.rs`'s order,
//! after the first three (two distinct and a third off their line; with no
//! such third, `collinear.rs`); the tree is replaced in `deletion_tree.rs`.
//!
//! Every number comes from `geometry` (`predicates`, `point_predicates`,
//! `vertex_placement`); this module only decides what to ask.

use super::insertion_order::insertion_order;
use super::state::{infinite_rotation, Construction};
use crate::diagram::{SiteId, VertexId, NONE};
use crate::geometry::predicates::point_predicates::{self, VertexCircle};
use crate::geometry::predicates::{
    in_circle, in_half_plane_circle, orientation, strictly_closer_given, CirclePosition, Orientation,
};
use crate::geometry::Point;

/// How far the fallback seed search may look beyond the nearest cell.
const SEED_SEARCH_LIMIT: usize = 4096;

/// What became of an inserted point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Inserted {
    /// A new site with this id.
    New(SiteId),
    /// The point equals this existing site.
    Duplicate(SiteId),
}

/// The diagram of the points alone, ready for segments.
pub(super) enum PointStage {
    /// Every point inserted: the diagram, and the site each point became.
    Inserted(Construction, Vec<SiteId>),
    /// At most one distinct point: no segment is possible; done.
    Trivial(Construction, Vec<SiteId>),
    /// All points on one line: built with the segments as a ladder.
    Collinear,
}

/// Inserts every point (with room for `segment_count` segments after them).
pub(super) fn insert_points(points: &[Point], segment_count: usize) -> PointStage {
    // (where fault injection makes the predicates lie, seeds are chosen by
    // their circles, which are then placed as they come: see `seed_vertex`)
    insert_points_placing(points, segment_count, !crate::geometry::fault::active())
}

/// [`insert_points`], placing the vertices once all points are in
/// (`defer`) or as they come.
fn insert_points_placing(points: &[Point], segment_count: usize, defer: bool) -> PointStage {
    let n = points.len();
    let mut site_of = vec![SiteId(NONE); n];
    let mut diagram = Construction::new(n + segment_count);
    let order = insertion_order(points);
    let Some(&first) = order.first() else {
        return PointStage::Trivial(diagram, site_of);
    };
    let pa = points[first as usize];
    let Some(b_pos) = order.iter().position(|&i| points[i as usize] != pa) else {
        // one distinct point
        let s = diagram.add_lone_site(pa);
        site_of.iter_mut().for_each(|x| *x = s);
        return PointStage::Trivial(diagram, site_of);
    };
    let second = order[b_pos];
    let pb = points[second as usize];
    let third = order[b_pos + 1..].iter().copied().find(|&i| orientation(pa, pb, points[i as usize]) != Orientation::Collinear);
    let Some(third) = third else {
        return PointStage::Collinear;
    };

    let ids = diagram.start_collinear(&[pa, pb]);
    site_of[first as usize] = ids[0];
    site_of[second as usize] = ids[1];
    let mut last = ids[1];
    // Gather the points into insertion order first: the loads are
    // independent here and overlap, where inside the loop each would be a
    // cache miss waiting behind a whole insertion.
    let rest: Vec<(u32, Point)> = std::iter::once(third)
        .chain(order.iter().copied().filter(|&i| i != first && i != second && i != third))
        .map(|i| (i, points[i as usize]))
        .collect();
    drop(order);
    diagram.placement_deferred = defer;
    for (i, p) in rest {
        match diagram.insert(p, last) {
            Inserted::New(s) => {
                site_of[i as usize] = s;
                last = s;
            }
            Inserted::Duplicate(s) => site_of[i as usize] = s,
        }
    }
    diagram.place_deferred();
    PointStage::Inserted(diagram, site_of)
}

impl Construction {
    /// The diagram of a single site: it has a cell but no boundary.
    fn add_lone_site(&mut self, p: Point) -> SiteId {
        debug_assert!(self.sites.len() == 1);
        self.add_site(p)
    }

    /// Inserts `p`, starting the nearest-site walk at `start`.
    pub(super) fn insert(&mut self, p: Point, start: SiteId) -> Inserted {
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
    /// checked exactly; else the first of the cell in conflict; if the
    /// numbers found none on `g`'s cell (the walk stopped one cell short),
    /// a bounded search around it.
    ///
    /// While placement is deferred (the circles are not known yet), no
    /// deepest one is asked: with exact predicates any vertex in conflict
    /// seeds the same tree (the set of vertices whose circles strictly
    /// contain `p`, connected); the choice by depth only matters where the
    /// predicates lie (fault injection).
    fn seed_vertex(&mut self, g: SiteId, p: Point) -> VertexId {
        let deepest = if self.placement_deferred { None } else { self.deepest_on_cell(g, p) };
        if let Some(v) = deepest.filter(|&v| self.in_conflict(v, p)) {
            return v;
        }
        if let Some(v) = self.store.cell_boundary(g).map(|h| h.origin()).find(|&v| self.in_conflict(v, p)) {
            return v;
        }
        // Breadth-first search outwards from g's cell, bounded; it uses the
        // vertex marks, so a fresh round follows it.
        let found = self.search_seed_around(g, p);
        self.fresh_epoch();
        // None only when the predicates lie: the topology still decides.
        let first = || self.store.cell_boundary(g).next().map(|h| h.origin());
        found.or(deepest).or_else(first).expect("a cell with a boundary has vertices")
    }

    /// The vertex of `g`'s cell whose circle holds `p` deepest, by the
    /// numbers (`None` for a cell without a boundary).
    fn deepest_on_cell(&self, g: SiteId, p: Point) -> Option<VertexId> {
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
        best
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
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    /// Each vertex by its sites (rotated to start at the least), with its
    /// position and clearance bit for bit: the same for the same diagram
    /// however its vertices are numbered.
    fn vertices_by_sites(c: &Construction) -> Vec<([SiteId; 3], [u64; 3])> {
        let store = c.store();
        let mut vertices: Vec<_> = (0..store.vertex_count())
            .map(VertexId::from_index)
            .map(|v| {
                let mut sites = store.sites_of(v);
                let k = (0..3).min_by_key(|&k| sites[k]).unwrap_or(0);
                sites.rotate_left(k);
                let (p, r) = (store.position[v.index()], store.clearance[v.index()]);
                (sites, [p.x.to_bits(), p.y.to_bits(), r.to_bits()])
            })
            .collect();
        vertices.sort();
        vertices
    }

    /// Vertices placed once the points are in are the diagram's placed as
    /// they come, bit for bit, and the first-in-conflict seeds grow the
    /// same diagram as the deepest: on points in general position, on a
    /// lattice with repeats (four and more on a circle everywhere), on
    /// points all on one circle, and far from the origin.
    #[test]
    fn deferred_placement_places_as_at_creation() {
        let mut rng = SplitMix64(21);
        let uniform: Vec<Point> = (0..6000).map(|_| Point::new(rng.unit(), rng.unit())).collect();
        let lattice: Vec<Point> = (0..4000).map(|i| Point::new((i % 70) as f64, ((i / 70) % 45) as f64)).collect();
        let circle: Vec<Point> = (0..720)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / 720.0;
                Point::new((1e6 * a.cos()).round(), (1e6 * a.sin()).round())
            })
            .collect();
        let far: Vec<Point> = uniform.iter().map(|p| Point::new(p.x + 1e9, p.y - 3e8)).collect();
        for (name, points) in [("uniform", uniform), ("lattice", lattice), ("circle", circle), ("far", far)] {
            let (PointStage::Inserted(eager, eager_sites), PointStage::Inserted(deferred, deferred_sites)) =
                (insert_points_placing(&points, 0, false), insert_points_placing(&points, 0, true))
            else {
                panic!("{name}: not built by insertions");
            };
            assert!(!deferred.placement_deferred, "{name}: placement still deferred");
            assert_eq!(eager_sites, deferred_sites, "{name}");
            assert_eq!(eager.store().vertex_count(), deferred.store().vertex_count(), "{name}");
            assert!(vertices_by_sites(&eager) == vertices_by_sites(&deferred), "{name}: another diagram");
        }
    }
}
