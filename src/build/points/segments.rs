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

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashSet};

use super::{infinite_rotation, PointDiagram, INFINITE};
use crate::diagram::{HalfEdgeId, SiteId, VertexId, NONE};
use crate::geometry::predicates::{orientation, Orientation};
use crate::geometry::parabola::Parabola;
use crate::geometry::segment_solvers;
use crate::geometry::point::norm;
use crate::geometry::site::Site;
use crate::geometry::solvers::left_normal;
use crate::geometry::{fault, Point};

/// A path of P4: its vertices, and the half-edge by which each vertex after
/// the first was entered.
struct Path {
    vertices: Vec<VertexId>,
    entered_by: Vec<HalfEdgeId>,
}

/// The walk of P4 in progress: its vertices and the half-edges already tried.
struct PathWalk {
    vertices: Vec<VertexId>,
    /// The half-edge by which each vertex after the first was entered.
    entered_by: Vec<HalfEdgeId>,
    on_walk: HashSet<VertexId>,
    tried: HashSet<HalfEdgeId>,
    /// The edge to leave the first vertex by.
    first_move: HalfEdgeId,
    /// Only vertices in conflict with the segment may join.
    strict: bool,
    /// Alternatives not taken: (certainty, position on the path, vertex
    /// there, half-edge to take instead), least certain first.
    alternatives: BinaryHeap<Reverse<(u64, usize, VertexId, HalfEdgeId)>>,
}

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

    /// The geometry of a real site (not the point at infinity).
    fn site_geometry(&self, s: SiteId) -> Site {
        if self.is_segment(s) {
            let [a, b] = self.segment_ends[(s.0 - self.first_segment) as usize];
            Site::Segment { a: self.sites[a.index()], b: self.sites[b.index()] }
        } else {
            Site::Point(self.sites[s.index()])
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
        let depth = match (sites.contains(&a), sites.contains(&b)) {
            // on the bisector of a and b: every point of it is nearer the
            // segment between them
            (true, true) => entering(pa, pb),
            (true, false) => self.side_at_endpoint(a, b, sites).apply(entering(pa, pb)),
            (false, true) => self.side_at_endpoint(b, a, sites).apply(entering(pb, pa)),
            (false, false) => Site::Segment { a: pa, b: pb }.distance(c) - self.store.clearance[v.index()],
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
    /// itself (radius 0). `Numeric` where there is none.
    fn side_at_endpoint(&self, end: SiteId, other: SiteId, sites: [SiteId; 3]) -> EndpointSide {
        let k = sites.iter().position(|&s| s == end).unwrap_or(0);
        let (next, prev) = (sites[(k + 1) % 3], sites[(k + 2) % 3]);
        let far_end = |s: SiteId| {
            if !self.is_segment(s) {
                return None;
            }
            let [x, y] = self.segment_ends[(s.0 - self.first_segment) as usize];
            if x == end {
                Some(y)
            } else if y == end {
                Some(x)
            } else {
                None
            }
        };
        let (pe, po) = (self.sites[end.index()], self.sites[other.index()]);
        let turn = |far: SiteId| orientation(pe, self.sites[far.index()], po);
        match (far_end(next), far_end(prev)) {
            (Some(_), Some(_)) => EndpointSide::OnCircle,
            (Some(far), None) => EndpointSide::from_turn(turn(far), Orientation::CounterClockwise),
            (None, Some(far)) => EndpointSide::from_turn(turn(far), Orientation::Clockwise),
            (None, None) => EndpointSide::Numeric,
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
        if self.is_segment(g) {
            let [x, y] = self.segment_ends[(g.0 - self.first_segment) as usize];
            let other = if x == a || x == b {
                Some(y)
            } else if y == a || y == b {
                Some(x)
            } else {
                None
            };
            if let Some(o) = other {
                return match orientation(pa, pb, self.sites[o.index()]) {
                    Orientation::CounterClockwise => f64::INFINITY,
                    Orientation::Clockwise => f64::NEG_INFINITY,
                    Orientation::Collinear => 0.0,
                };
            }
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
        let ends_of = |s: SiteId| self.segment_ends[(s.0 - self.first_segment) as usize];
        (self.is_segment(l) && ends_of(l).contains(&r)) || (self.is_segment(r) && ends_of(r).contains(&l))
    }

    /// Whether `v` may join the walk: not at infinity unless it conflicts.
    fn walkable(&self, v: VertexId, a: SiteId, b: SiteId) -> bool {
        !self.store.is_at_infinity(v) || self.segment_conflict(v, a, b)
    }

    /// Finds the path of P4 and makes it the start of the tree (marked with
    /// the current epoch); the edges between path vertices other than the
    /// path's own are cut twice. Returns `false` when no path was found
    /// (only possible when the numbers lie badly); the tree is then the
    /// walk's first vertex alone.
    fn find_segment_path(&mut self, a: SiteId, b: SiteId) -> bool {
        // First only through vertices the segment conflicts with (where the
        // true path runs); if the numbers leave no such path, through any.
        let (found, path) = match self.walk_to(a, b, true) {
            (true, path) => (true, path),
            _ => match self.walk_to(a, b, false) {
                (true, path) => (true, path),
                (false, start_only) => self.shortest_path(a, b).map_or((false, start_only), |path| (true, path)),
            },
        };
        let Path { vertices, entered_by } = if found { path } else { Path { vertices: path.vertices[..1].to_vec(), entered_by: Vec::new() } };
        let epoch = self.epoch;
        self.tree.clear();
        for &v in &vertices {
            self.vertex_mark[v.index()] = epoch;
            self.tree.push(v);
        }
        for &v in &vertices {
            for k in 0..3 {
                let h = v.half_edge(k);
                let on_path = self.vertex_mark[self.store.target(h).index()] == epoch;
                let path_edge = entered_by.iter().any(|&g| g == h || self.store.twin(g) == h);
                if on_path && !path_edge && !self.is_separator(h) && !self.is_twice_cut(h) {
                    self.twice_cut.push(h);
                }
            }
        }
        found
    }

    /// The last resort when the numbers misled both walks: the path with
    /// fewest edges from `R(a)`'s boundary to `R(b)`'s, by breadth-first
    /// search without separators, vertices at infinity or vertices whose
    /// third cell is `R(a)`. A shortest path has no chord but edges parallel
    /// to its own (a cell with two edges between consecutive path vertices),
    /// touches `R(a)` and `R(b)` only at its ends, and so keeps P3 and P5
    /// whatever the numbers say, its parallel edges cut twice (a path with
    /// an edge that may not be cut twice is refused). `None` if there is no
    /// such path.
    fn shortest_path(&self, a: SiteId, b: SiteId) -> Option<Path> {
        let mut parent: std::collections::HashMap<VertexId, Option<HalfEdgeId>> = Default::default();
        let mut queue = std::collections::VecDeque::new();
        for h in self.store.cell_boundary(a) {
            let v = h.origin();
            if self.walkable(v, a, b) && parent.insert(v, None).is_none() {
                queue.push_back(v);
            }
        }
        let mut end = None;
        while let Some(v) = queue.pop_front() {
            if self.store.sites_of(v).contains(&b) {
                end = Some(v);
                break;
            }
            for k in 0..3 {
                let h = v.half_edge(k);
                let w = self.store.target(h);
                let third = self.store.opposite(self.store.twin(h));
                if parent.contains_key(&w) || self.is_separator(h) || third == a || !self.walkable(w, a, b) {
                    continue;
                }
                parent.insert(w, Some(h));
                queue.push_back(w);
            }
        }
        let mut vertices = vec![end?];
        let mut entered_by = Vec::new();
        while let Some(&Some(h)) = parent.get(vertices.last().expect("non-empty")) {
            entered_by.push(h);
            vertices.push(h.origin());
        }
        vertices.reverse();
        entered_by.reverse();
        let on_path: HashSet<VertexId> = vertices.iter().copied().collect();
        let cuttable = vertices.iter().all(|&v| {
            (0..3).all(|k| {
                let h = v.half_edge(k);
                let path_edge = entered_by.iter().any(|&g| g == h || self.store.twin(g) == h);
                path_edge || self.is_separator(h) || !on_path.contains(&self.store.target(h)) || self.may_cut_twice(h, a, b)
            })
        });
        cuttable.then_some(Path { vertices, entered_by })
    }

    /// The walk from `R(a)` to `R(b)`; `strict` admits only vertices in
    /// conflict with the segment. Returns whether `R(b)` was reached and the
    /// walk's vertices (at least the start).
    fn walk_to(&self, a: SiteId, b: SiteId, strict: bool) -> (bool, Path) {
        let (pa, pb) = (self.sites[a.index()], self.sites[b.index()]);
        let (start, first_move) = self.path_start(a, b);
        if self.store.sites_of(start).contains(&b) {
            return (true, Path { vertices: vec![start], entered_by: Vec::new() });
        }
        let mut walk = PathWalk {
            vertices: Vec::new(),
            entered_by: Vec::new(),
            on_walk: HashSet::new(),
            tried: HashSet::new(),
            first_move,
            strict,
            alternatives: BinaryHeap::new(),
        };
        self.walk_push(&mut walk, start, None);
        loop {
            let v = *walk.vertices.last().expect("the walk always holds its start");
            if self.store.sites_of(v).contains(&b) {
                return (true, Path { vertices: walk.vertices, entered_by: walk.entered_by });
            }
            match self.walk_step(&mut walk, v, a, b, pa, pb).or_else(|| self.walk_backtrack(&mut walk, a, b)) {
                Some(h) => {
                    walk.tried.insert(h);
                    let w = self.store.target(h);
                    self.walk_push(&mut walk, w, Some(h));
                }
                None => return (false, Path { vertices: walk.vertices, entered_by: walk.entered_by }),
            }
        }
    }

    /// The walk's first vertex, on `R(a)`'s boundary, and the edge to leave
    /// it by: among the vertices in conflict with the segment, one with `b`
    /// among its sites if there is one, else the one whose edge away from
    /// `R(a)` has a site left of the segment on its left and one right of it
    /// on its right (seed 000's characteristic 3), most clearly so, the
    /// deepest conflict breaking ties.
    fn path_start(&self, a: SiteId, b: SiteId) -> (VertexId, HalfEdgeId) {
        // R(a) and R(b) already meet (the usual case for a short segment): a
        // vertex of both is the whole path, and no other scores as high.
        for h in self.store.cell_boundary(a) {
            let v = h.origin();
            if self.store.sites_of(v).contains(&b) && self.walkable(v, a, b) && self.segment_conflict(v, a, b) {
                return (v, h.rotate(2));
            }
        }
        let ends = (self.sites[a.index()], self.sites[b.index()]);
        let mut best: Option<(VertexId, HalfEdgeId, (f64, f64, f64))> = None;
        for h in self.store.cell_boundary(a) {
            let v = h.origin();
            // h has R(a) on its left; the edge of v away from R(a):
            let out = h.rotate(2);
            // The start is deleted: it must conflict with the segment if any
            // vertex of R(a) does (one always does, exactly).
            let (conflict, depth) = if self.store.is_at_infinity(v) {
                (self.segment_conflict(v, a, b), f64::INFINITY)
            } else {
                let depth = self.segment_depth(v, a, b);
                (depth < 0.0, depth)
            };
            let conflict = if conflict { 1.0 } else { 0.0 };
            let key = if self.store.sites_of(v).contains(&b) && self.walkable(v, a, b) {
                (conflict, f64::INFINITY, f64::INFINITY)
            } else {
                let left = self.left_degree(v, self.store.left(out), (a, b), ends);
                let right = self.left_degree(v, self.store.right(out), (a, b), ends);
                let separation = left.min(-right);
                (conflict, if separation.is_nan() { f64::NEG_INFINITY } else { separation.min(f64::MAX) }, -depth)
            };
            if best.map_or(true, |(_, _, k)| key > k) {
                best = Some((v, out, key));
            }
        }
        best.map(|(v, out, _)| (v, out)).expect("a point site among others has a cell boundary")
    }

    fn walk_push(&self, walk: &mut PathWalk, v: VertexId, entered_by: Option<HalfEdgeId>) {
        walk.vertices.push(v);
        if let Some(h) = entered_by {
            walk.entered_by.push(h);
        }
        walk.on_walk.insert(v);
    }

    /// Shortens the walk to its first `len` vertices.
    fn walk_truncate(&self, walk: &mut PathWalk, len: usize) {
        while walk.vertices.len() > len {
            let v = walk.vertices.pop().expect("longer than len");
            walk.entered_by.pop();
            walk.on_walk.remove(&v);
        }
    }

    /// Whether leaving the walk's last vertex by `h` keeps the walk a path
    /// (P3) and `R(a)` touched in one piece (P5): the vertex reached is new,
    /// each of its other edges that leads back to the walk (a chord) may be
    /// cut twice (in the strict walk: the numbers also say its middle stays
    /// out of the new cell), its third cell is not `R(a)`, and it is not at
    /// infinity unless it conflicts.
    fn walk_allows(&self, walk: &PathWalk, h: HalfEdgeId, a: SiteId, b: SiteId) -> bool {
        if walk.tried.contains(&h) {
            return false;
        }
        let back = self.store.twin(h);
        let w = back.origin();
        let chord_ok = |x: HalfEdgeId| {
            self.is_separator(x)
                || !walk.on_walk.contains(&self.store.target(x))
                || (self.may_cut_twice(x, a, b) && (!walk.strict || self.middle_margin(x, a, b) > 0.0))
        };
        !self.is_separator(h)
            && !walk.on_walk.contains(&w)
            && self.store.opposite(back) != a
            && self.walkable(w, a, b)
            && (!walk.strict || self.segment_conflict(w, a, b))
            && chord_ok(back.rotate(1))
            && chord_ok(back.rotate(2))
    }

    /// The next half-edge to follow from `v`, by the left/right rule, with
    /// the other choice kept for backtracking; `None` when neither is open.
    fn walk_step(
        &self,
        walk: &mut PathWalk,
        v: VertexId,
        a: SiteId,
        b: SiteId,
        pa: Point,
        pb: Point,
    ) -> Option<HalfEdgeId> {
        let pos = walk.vertices.len() - 1;
        let (preferred, other, certainty) = match walk.entered_by.last() {
            Some(&h) => {
                // Arrived by h; t leaves v back. The cell ahead, N, should
                // stay on the side of the walk it is on of the segment.
                let t = self.store.twin(h);
                let ahead = self.store.opposite(t);
                let l = self.left_degree(v, ahead, (a, b), (pa, pb));
                let (keep_left, keep_right) = (t.rotate(1), t.rotate(2));
                if l > 0.0 {
                    (keep_left, keep_right, l.abs())
                } else {
                    (keep_right, keep_left, l.abs())
                }
            }
            None => {
                // At the start: away from R(a) first, along its boundary
                // only when that fails.
                let out = walk.first_move;
                let along = [out.rotate(1), out.rotate(2)];
                for h in along {
                    if self.walk_allows(walk, h, a, b) {
                        walk.alternatives.push(Reverse((certainty_key(f64::INFINITY), pos, v, h)));
                    }
                }
                return self.walk_allows(walk, out, a, b).then_some(out);
            }
        };
        // Only vertices the segment conflicts with belong on the path; the
        // left/right rule decides between two of them, and a vertex out of
        // conflict is taken only when nothing else is left (backtracking).
        let conflicts = |h: HalfEdgeId| self.segment_conflict(self.store.target(h), a, b);
        let mut options: Vec<(bool, HalfEdgeId)> = [preferred, other]
            .into_iter()
            .filter(|&h| self.walk_allows(walk, h, a, b))
            .map(|h| (!conflicts(h), h))
            .collect();
        options.sort_by_key(|&(out_of_conflict, _)| out_of_conflict); // stable: rule order among equals
        let (_, chosen) = *options.first()?;
        for &(out_of_conflict, h) in &options[1..] {
            let c = if out_of_conflict { f64::INFINITY } else { certainty };
            walk.alternatives.push(Reverse((certainty_key(c), pos, v, h)));
        }
        Some(chosen)
    }

    /// Goes back to the least certain open alternative; `None` when none is
    /// left.
    fn walk_backtrack(&self, walk: &mut PathWalk, a: SiteId, b: SiteId) -> Option<HalfEdgeId> {
        while let Some(Reverse((_, pos, v, h))) = walk.alternatives.pop() {
            if pos >= walk.vertices.len() || walk.vertices[pos] != v {
                continue;
            }
            self.walk_truncate(walk, pos + 1);
            if self.walk_allows(walk, h, a, b) {
                return Some(h);
            }
        }
        None
    }

    /// Grows the tree from the path: P3, P5, the segment entering the
    /// circle (criteria 1, 2.3), never beyond a deleted vertex outside the
    /// strip (criterion 2.2). A vertex whose other edges lead into the tree
    /// too joins only if each cycle it closes has an edge whose middle the
    /// numbers keep (see `join_closing_cycles`).
    fn grow_segment_tree(&mut self, a: SiteId, b: SiteId) {
        let epoch = self.epoch;
        let (pa, pb) = (self.sites[a.index()], self.sites[b.index()]);
        let mut i = 0;
        while i < self.tree.len() {
            let u = self.tree[i];
            i += 1;
            if !self.store.is_at_infinity(u) && !in_strip(self.store.position[u.index()], pa, pb) {
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
                .filter(|&h| self.is_finite_edge(h))
                .map(|h| (self.middle_margin(h, a, b), h))
                .filter(|&(margin, _)| margin > 0.0)
                .collect();
            candidates.sort_by(|x, y| y.0.total_cmp(&x.0));
            // An edge of R(a) or R(b) may keep its middle only where the rest
            // of that cell's boundary is deleted: P5, one piece lost.
            let w = back.origin();
            let chosen = candidates.into_iter().map(|(_, h)| h).find(|&h| {
                self.twice_cut[slot] = h;
                let sides = [self.store.left(h), self.store.right(h)];
                !(sides.contains(&a) || sides.contains(&b))
                    || (self.cell_visits(a, w) == 1 && self.cell_visits(b, w) == 1)
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
    /// tree), by breadth-first search over tree edges.
    fn tree_path(&self, from: VertexId, to: VertexId) -> Vec<HalfEdgeId> {
        let mut parent: std::collections::HashMap<VertexId, HalfEdgeId> = Default::default();
        let mut queue = std::collections::VecDeque::from([from]);
        while let Some(v) = queue.pop_front() {
            if v == to {
                break;
            }
            for k in 0..3 {
                let h = v.half_edge(k);
                let w = self.store.target(h);
                if w != from && self.leads_into_tree(h) && !parent.contains_key(&w) {
                    parent.insert(w, h);
                    queue.push_back(w);
                }
            }
        }
        let mut path = Vec::new();
        let mut v = to;
        while let Some(&h) = parent.get(&v) {
            path.push(h);
            v = h.origin();
        }
        path
    }

    /// Whether the edge of `h` may be cut at both ends, its middle kept, by
    /// the path: not an edge of `R(a)` or `R(b)` (P5: they lose one piece
    /// each), and finite.
    fn may_cut_twice(&self, h: HalfEdgeId, a: SiteId, b: SiteId) -> bool {
        let sides = [self.store.left(h), self.store.right(h)];
        !sides.contains(&a) && !sides.contains(&b) && self.is_finite_edge(h)
    }

    /// Whether neither end of `h` is at infinity.
    fn is_finite_edge(&self, h: HalfEdgeId) -> bool {
        !self.store.is_at_infinity(h.origin()) && !self.store.is_at_infinity(self.store.target(h))
    }

    /// How clearly the middle of the (finite) edge of `h` stays out of the
    /// cell of the segment `ab` when both its ends are in it (perturbed in
    /// fault injection). Positive: the edge keeps a middle piece.
    ///
    /// The new cell's boundary would cross the edge at the two vertices a
    /// cut at both ends creates: `[right, left, e]` near `h`'s origin and
    /// `[left, right, e]` near its target, each computed from the three sites
    /// by its solver. The middle stays when both exist, lie on the edge, and
    /// come in that order; the margin is then how much closer the point
    /// halfway between them is to its own sites than to `ab`. (Sampling the
    /// edge instead misses a middle piece that is short against the edge.)
    /// When a solver finds nothing, the edge is sampled instead.
    fn middle_margin(&self, h: HalfEdgeId, a: SiteId, b: SiteId) -> f64 {
        let sides = [self.store.left(h), self.store.right(h)];
        if sides.contains(&a) && sides.contains(&b) {
            // Every point of the bisector of a and b is closer to the open
            // segment between them (the midpoint is nearer than either end).
            return f64::NEG_INFINITY;
        }
        let excess = self.edge_excess(h, a, b);
        let [left, right] = sides.map(|s| self.site_geometry(s));
        let segment = Site::Segment { a: self.sites[a.index()], b: self.sites[b.index()] };
        let arc = self.edge_arc(h);
        let crossings = segment_solvers::vertex(&right, &left, &segment)
            .zip(segment_solvers::vertex(&left, &right, &segment))
            .map(|((near_origin, _), (near_target, _))| (arc.parameter(near_origin), arc.parameter(near_target)));
        let margin = match crossings {
            Some((t1, t2)) if 0.0 <= t1 && t1 < t2 && t2 <= 1.0 => excess(0.5 * (t1 + t2)),
            Some((t1, t2)) => -(t1 - t2).abs().max(f64::MIN_POSITIVE),
            None => sampled_maximum(&excess),
        };
        fault::perturb(margin)
    }

    /// The excess of the distance to the segment `ab` over the distance to
    /// the edge's own sites, at the point of the edge of `h` at parameter
    /// `t` (0 at its origin, 1 at its target); NaN gives `-∞`.
    fn edge_excess(&self, h: HalfEdgeId, a: SiteId, b: SiteId) -> impl Fn(f64) -> f64 {
        let sides = [self.store.left(h), self.store.right(h)];
        let touches_end = sides.contains(&a) || sides.contains(&b);
        let [left, right] = sides.map(|s| self.site_geometry(s));
        let (pa, pb) = (self.sites[a.index()], self.sites[b.index()]);
        let segment = Site::Segment { a: pa, b: pb };
        let arc = self.edge_arc(h);
        move |t: f64| {
            let q = arc.point(t);
            // On an edge of R(a) or R(b) the distances to the segment and to
            // its endpoint agree outside the strip, so the signed distance
            // beyond the perpendiculars decides, without cancellation.
            let e = if touches_end {
                let (dx, dy) = (pb.x - pa.x, pb.y - pa.y);
                let beyond_b = (q.x - pb.x) * dx + (q.y - pb.y) * dy;
                let beyond_a = (pa.x - q.x) * dx + (pa.y - q.y) * dy;
                beyond_a.max(beyond_b) / norm(dx, dy)
            } else {
                segment.distance(q) - 0.5 * (left.distance(q) + right.distance(q))
            };
            if e.is_nan() {
                f64::NEG_INFINITY
            } else {
                e
            }
        }
    }

    /// The finite edge of `h` as a curve from its origin (0) to its target (1).
    fn edge_arc(&self, h: HalfEdgeId) -> EdgeArc {
        let (left, right) = (self.site_geometry(self.store.left(h)), self.site_geometry(self.store.right(h)));
        let (from, to) = (self.store.position[h.origin().index()], self.store.position[self.store.target(h).index()]);
        match Parabola::of_sites(&left, &right) {
            Some(p) => EdgeArc::Parabola(p, p.parameter(from), p.parameter(to)),
            None => EdgeArc::Line(from, to),
        }
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
        let (pos, clearance) = segment_solvers::vertex(&ga, &gb, &gc).unwrap_or_else(|| {
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

/// A finite edge as a curve over `[0, 1]`: a straight piece, or an arc of
/// a parabola between two of its parameters.
enum EdgeArc {
    Line(Point, Point),
    Parabola(Parabola, f64, f64),
}

impl EdgeArc {
    fn point(&self, t: f64) -> Point {
        match *self {
            EdgeArc::Line(p, q) => Point::new(p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t),
            EdgeArc::Parabola(ref par, s0, s1) => par.point(s0 + (s1 - s0) * t),
        }
    }

    /// The parameter of the point of the curve nearest to `q` (exact for
    /// points on it, up to rounding); NaN for a curve of no length.
    fn parameter(&self, q: Point) -> f64 {
        match *self {
            EdgeArc::Line(p, r) => {
                let (dx, dy) = (r.x - p.x, r.y - p.y);
                ((q.x - p.x) * dx + (q.y - p.y) * dy) / (dx * dx + dy * dy)
            }
            EdgeArc::Parabola(ref par, s0, s1) => (par.parameter(q) - s0) / (s1 - s0),
        }
    }
}

/// The largest value of `f` over `[0, 1]` as far as sampling finds it:
/// evenly spaced samples, the best refined by golden-section search.
fn sampled_maximum(f: &impl Fn(f64) -> f64) -> f64 {
    const SAMPLES: usize = 16;
    const REFINEMENTS: usize = 40;
    let step = 1.0 / (SAMPLES + 1) as f64;
    let (mut best_t, mut best) = (0.5, f64::NEG_INFINITY);
    for k in 1..=SAMPLES {
        let t = k as f64 * step;
        let e = f(t);
        if e > best {
            (best_t, best) = (t, e);
        }
    }
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = ((best_t - step).max(0.0), (best_t + step).min(1.0));
    let (mut x1, mut x2) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
    let (mut e1, mut e2) = (f(x1), f(x2));
    for _ in 0..REFINEMENTS {
        if e1 < e2 {
            lo = x1;
            (x1, e1) = (x2, e2);
            x2 = lo + ratio * (hi - lo);
            e2 = f(x2);
        } else {
            hi = x2;
            (x2, e2) = (x1, e1);
            x1 = hi - ratio * (hi - lo);
            e1 = f(x1);
        }
    }
    best.max(e1).max(e2)
}

/// Whether `p` lies in the closed strip between the perpendiculars to `ab`
/// at `a` and at `b`.
fn in_strip(p: Point, a: Point, b: Point) -> bool {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let t = (p.x - a.x) * dx + (p.y - a.y) * dy;
    let t = fault::perturb(t);
    (0.0..=dx * dx + dy * dy).contains(&t)
}

/// A heap key for a non-negative certainty (NaN last): the bits of a
/// non-negative double order like the double.
fn certainty_key(c: f64) -> u64 {
    if c.is_nan() {
        u64::MAX
    } else {
        c.abs().to_bits()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Builds the point diagram of `points` (not all collinear), then
    /// inserts `segments` (pairs of indices into `points`).
    fn build(points: &[Point], segments: &[[usize; 2]]) -> PointDiagram {
        let mut d = PointDiagram::new(points.len() + segments.len());
        let ids = d.start_collinear(&points[..2]);
        let mut all = ids.clone();
        let mut last = ids[1];
        for &p in &points[2..] {
            match d.insert(p, last) {
                super::super::Inserted::New(s) => {
                    all.push(s);
                    last = s;
                }
                super::super::Inserted::Duplicate(_) => panic!("test points must be distinct"),
            }
        }
        for &[i, j] in segments {
            d.insert_segment(all[i], all[j]).expect("a path");
        }
        d
    }

    /// The finite vertices in use: id, sites, position, clearance.
    pub(super) fn finite_vertices(d: &PointDiagram) -> impl Iterator<Item = (usize, [SiteId; 3], Point, f64)> + '_ {
        (0..d.store.vertex_count()).filter_map(|vi| {
            let sites = d.store.sites_of(VertexId::from_index(vi));
            let unused_or_infinite = sites.contains(&INFINITE) || sites[0].0 == NONE;
            (!unused_or_infinite).then(|| (vi, sites, d.store.position[vi], d.store.clearance[vi]))
        })
    }

    /// Whether the vertex is equidistant from its three sites and no site
    /// is closer (brute force), within `tol` (or 1e-12 of its clearance,
    /// for far vertices: their distances are rounded at that size).
    pub(super) fn check_vertex(d: &PointDiagram, (vi, sites, pos, r): (usize, [SiteId; 3], Point, f64), tol: f64) -> Result<(), String> {
        let tol = tol.max(1e-12 * r);
        for s in (1..d.sites.len()).map(SiteId::from_index) {
            let dist = d.site_geometry(s).distance(pos);
            if dist < r - tol || (sites.contains(&s) && (dist - r).abs() > tol) {
                return Err(format!("vertex {vi} {sites:?} at {pos:?}: site {s:?} at {dist}, clearance {r}"));
            }
        }
        Ok(())
    }

    /// Every finite vertex passes `check_vertex`.
    fn check_geometry(d: &PointDiagram, tol: f64) {
        for v in finite_vertices(d) {
            check_vertex(d, v, tol).unwrap_or_else(|e| panic!("{e}"));
        }
    }

    fn validate(d: &PointDiagram) {
        d.store.validate().unwrap_or_else(|e| panic!("{e}"));
    }

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn one_segment_among_points() {
        let pts = [p(0.0, 0.0), p(4.0, 0.3), p(2.0, 3.0), p(1.5, -2.5), p(5.0, 4.0), p(-1.0, 3.5), p(2.2, 0.9)];
        let d = build(&pts, &[[0, 6]]);
        validate(&d);
        check_geometry(&d, 1e-9);
    }

    /// Points on a jittered grid; in some cells two points joined by a short
    /// segment that stays inside its cell, so no two segments meet.
    fn jittered(side: usize, seed: u64) -> (Vec<Point>, Vec<[usize; 2]>) {
        let mut rng = crate::build::order::SplitMix(seed);
        let mut unit = move || (rng.next() >> 11) as f64 / (1u64 << 53) as f64;
        let (mut pts, mut segs) = (Vec::new(), Vec::new());
        for i in 0..side {
            for j in 0..side {
                let (x, y) = (i as f64, j as f64);
                let a = p(x + 0.1 + 0.8 * unit(), y + 0.1 + 0.8 * unit());
                pts.push(a);
                if unit() < 0.5 {
                    let b = p(x + 0.1 + 0.8 * unit(), y + 0.1 + 0.8 * unit());
                    if b != a {
                        pts.push(b);
                        segs.push([pts.len() - 2, pts.len() - 1]);
                    }
                }
            }
        }
        (pts, segs)
    }

    #[test]
    fn random_disjoint_segments() {
        for seed in 0..40 {
            let (pts, segs) = jittered(6 + (seed as usize % 10), seed);
            let d = build(&pts, &segs);
            validate(&d);
            check_geometry(&d, 1e-9);
        }
    }

    /// Whether every segment so far has exactly one separator with each endpoint.
    #[cfg(feature = "fault-injection")]
    fn separators_ok(d: &PointDiagram) -> Result<(), String> {
        for (k, ends) in d.segment_ends.iter().enumerate() {
            let s = SiteId(d.first_segment + k as u32);
            for &e in ends {
                let n = d.store.cell_boundary(s).filter(|&h| d.store.right(h) == e).count();
                if n != 1 {
                    return Err(format!("segment {s:?} has {n} separators with {e:?}"));
                }
            }
        }
        Ok(())
    }

    /// Every insertion keeps every segment's separators, under random
    /// arithmetic; names the first insertion that does not.
    #[cfg(feature = "fault-injection")]
    #[test]
    fn separators_under_random_arithmetic() {
        for seed in 0..3 {
            let (pts, segs) = jittered(20, seed);
            crate::geometry::fault::set_fault_mode(crate::geometry::fault::FaultMode::Random, seed);
            let mut d = PointDiagram::new(pts.len() + segs.len());
            let ids = d.start_collinear(&pts[..2]);
            let mut all = ids.clone();
            let mut last = ids[1];
            for &p in &pts[2..] {
                if let super::super::Inserted::New(s) = d.insert(p, last) {
                    all.push(s);
                    last = s;
                } else {
                    panic!("distinct");
                }
            }
            for (k, &[i, j]) in segs.iter().enumerate() {
                d.fresh_epoch();
                let e = d.add_segment_site(all[i], all[j]);
                let found = d.find_segment_path(all[i], all[j]);
                let path = d.tree.clone();
                d.grow_segment_tree(all[i], all[j]);
                d.replace_tree(e);
                let ok = separators_ok(&d);
                if ok.is_err() {
                    crate::geometry::fault::set_fault_mode(crate::geometry::fault::FaultMode::Off, 0);
                }
                if let Err(msg) = ok {
                    panic!("seed {seed} segment {k} ({e:?}): path found {found}, path {}: {msg}", path.len());
                }
            }
            crate::geometry::fault::set_fault_mode(crate::geometry::fault::FaultMode::Off, 0);
        }
    }
}

#[cfg(test)]
mod replay {
    //! Inserts the segments of an input one at a time and checks the
    //! diagram after every insertion: valid, every surviving vertex's circle
    //! free of the new segment, every new vertex equidistant from its sites
    //! with no site closer. Names the first insertion that goes wrong.
    use super::*;
    use crate::build::order::SplitMix;
    use crate::build::Inserted;

    /// Tolerance relative to the largest coordinate.
    const TOLERANCE: f64 = 1e-9;

    /// Reads Boost.Polygon's text format (points, then segments).
    fn parse(text: &str) -> (Vec<Point>, Vec<[Point; 2]>) {
        let mut nums = text.split_whitespace().map(|t| t.parse::<f64>().expect("a number"));
        let mut next = || nums.next().expect("more numbers");
        let points = (0..next() as usize).map(|_| Point::new(next(), next())).collect();
        let segments = (0..next() as usize).map(|_| [Point::new(next(), next()), Point::new(next(), next())]).collect();
        (points, segments)
    }

    /// The first wrong insertion, if any (inputs whose points are not all
    /// collinear).
    fn replay(points: &[Point], segments: &[[Point; 2]]) -> Result<(), String> {
        let all: Vec<Point> = points.iter().copied().chain(segments.iter().flatten().copied()).collect();
        let tol = TOLERANCE * all.iter().fold(f64::MIN_POSITIVE, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        let mut d = PointDiagram::new(all.len() + segments.len());
        let mut ids = d.start_collinear(&all[..2]);
        let mut last = ids[1];
        for &p in &all[2..] {
            let id = match d.insert(p, last) {
                Inserted::New(s) => s,
                Inserted::Duplicate(s) => s,
            };
            ids.push(id);
            last = id;
        }
        for (n, k) in (0..segments.len()).enumerate() {
            let base = points.len() + 2 * k;
            let e = d.insert_segment(ids[base], ids[base + 1]).map_err(|_| format!("segment {n}: no path"))?;
            d.store.validate().map_err(|err| format!("segment {n}: {err}"))?;
            check_after(&d, e, tol).map_err(|err| format!("segment {n}: {err}"))?;
        }
        Ok(())
    }

    fn check_after(d: &PointDiagram, e: SiteId, tol: f64) -> Result<(), String> {
        let segment = d.site_geometry(e);
        for v @ (vi, sites, pos, r) in super::tests::finite_vertices(d) {
            if segment.distance(pos) < r - tol.max(1e-12 * r) {
                return Err(format!("vertex {vi} {sites:?} at {pos:?} kept with the new segment inside its circle (at {}, clearance {r})", segment.distance(pos)));
            }
            if sites.contains(&e) {
                super::tests::check_vertex(d, v, tol).map_err(|err| format!("new {err}"))?;
            }
        }
        Ok(())
    }

    /// Whether the closed segments `p` and `q` meet (exact orientations).
    fn meet(p: [Point; 2], q: [Point; 2]) -> bool {
        let side = |a: Point, b: Point, c: Point| orientation(a, b, c) as i32;
        let (d1, d2) = (side(p[0], p[1], q[0]), side(p[0], p[1], q[1]));
        let (d3, d4) = (side(q[0], q[1], p[0]), side(q[0], q[1], p[1]));
        d1 != d2 && d3 != d4 || [d1, d2, d3, d4].contains(&(Orientation::Collinear as i32))
    }

    /// Seed 000's first method: random endpoints in the unit square, a
    /// segment that meets an earlier one redrawn.
    fn random_segments(n: usize, seed: u64) -> Vec<[Point; 2]> {
        let mut rng = SplitMix(seed);
        let mut unit = move || (rng.next() >> 11) as f64 / (1u64 << 53) as f64;
        let mut out: Vec<[Point; 2]> = Vec::new();
        while out.len() < n {
            let s = [Point::new(unit(), unit()), Point::new(unit(), unit())];
            if !out.iter().any(|&t| meet(s, t)) {
                out.push(s);
            }
        }
        out
    }

    #[test]
    fn fixtures_are_right_after_every_insertion() {
        for (name, text) in [
            ("collinear_continuation", include_str!("../../../c_tests/fixtures/collinear_continuation.txt")),
            ("two_segments_near_endpoint", include_str!("../../../c_tests/fixtures/two_segments_near_endpoint.txt")),
        ] {
            let (points, segments) = parse(text);
            replay(&points, &segments).unwrap_or_else(|err| panic!("{name}: {err}"));
        }
    }

    /// Long random segments: cells wrapped around points and arcs cut twice
    /// (what first showed the need for edges cut at both ends).
    #[test]
    fn random_long_segments_are_right_after_every_insertion() {
        for seed in 0..12 {
            let segments = random_segments(60, seed);
            replay(&[], &segments).unwrap_or_else(|err| panic!("seed {seed}: {err}"));
        }
    }

    /// Debug aid: `SEGFILE=input.txt cargo test --lib replay_file -- --ignored`
    /// replays any input in Boost.Polygon's text format.
    #[test]
    #[ignore]
    fn replay_file() {
        let path = std::env::var("SEGFILE").expect("SEGFILE names the input to replay");
        let (points, segments) = parse(&std::fs::read_to_string(path).expect("a readable input"));
        replay(&points, &segments).unwrap_or_else(|err| panic!("{err}"));
    }
}
