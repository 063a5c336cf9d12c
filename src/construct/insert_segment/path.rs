//! P4: the path from `R(a)`'s boundary to `R(b)`'s that starts the
//! deletion tree of a segment `ab` — the walk that keeps sites left of the
//! segment on its left (seed 000's left-degree), backtracking to its least
//! certain decision; the same walk through any vertices; a breadth-first
//! shortest path as the last resort.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashSet};
use std::hash::{BuildHasherDefault, Hash, Hasher};

use crate::construct::state::Construction;
use crate::diagram::{HalfEdgeId, SiteId, VertexId};
use crate::geometry::predicates::{CirclePosition, Orientation};
use crate::geometry::segments::segment_predicates::{EdgeMiddle, LeftDegree};
use crate::geometry::Point;

/// A path of P4: its vertices, and the half-edge by which each vertex after
/// the first was entered.
struct Path {
    vertices: Vec<VertexId>,
    entered_by: Vec<HalfEdgeId>,
}

impl Path {
    /// The half-edges from a path vertex to another (`on_path`) that are
    /// not the path's own edges: chords, and edges parallel to the path's
    /// (each from both of its ends).
    fn chords<'a>(
        &'a self,
        d: &'a Construction,
        on_path: impl Fn(VertexId) -> bool + 'a,
    ) -> impl Iterator<Item = HalfEdgeId> + 'a {
        self.vertices
            .iter()
            .enumerate()
            .flat_map(|(i, &v)| (0..3).map(move |k| (i, v.half_edge(k))))
            .filter(move |&(i, h)| {
                let to_predecessor = i > 0 && h == d.store.twin(self.entered_by[i - 1]);
                let to_successor = self.entered_by.get(i) == Some(&h);
                !to_predecessor && !to_successor && on_path(d.store.target(h))
            })
            .map(|(_, h)| h)
    }
}

/// The walk of P4 in progress: its vertices and the half-edges already tried.
struct PathWalk {
    vertices: Vec<VertexId>,
    /// The half-edge by which each vertex after the first was entered.
    entered_by: Vec<HalfEdgeId>,
    on_walk: SmallSet<VertexId>,
    tried: SmallSet<HalfEdgeId>,
    /// The edge to leave the first vertex by.
    first_move: HalfEdgeId,
    /// Only vertices in conflict with the segment may join.
    strict: bool,
    /// Alternatives not taken: (certainty, position on the path, vertex
    /// there, half-edge to take instead), least certain first.
    alternatives: BinaryHeap<Reverse<(u64, usize, VertexId, HalfEdgeId)>>,
}

impl Construction {
    /// Finds the path of P4 and makes it the start of the tree (marked with
    /// the current epoch); the edges between path vertices other than the
    /// path's own are cut twice. Returns `false` when no path was found
    /// (only possible when the numbers lie badly); the tree is then the
    /// walk's first vertex alone.
    pub(super) fn find_segment_path(&mut self, a: SiteId, b: SiteId) -> bool {
        // Where R(a) and R(b) meet, their whole common boundary is the
        // path. Otherwise first only through vertices the segment conflicts
        // with (where the true path runs); if the numbers leave no such path,
        // through any.
        let (found, path) = match self.shared_boundary(a, b).map(|path| (true, path)).unwrap_or_else(|| self.walk_to(a, b, true))
        {
            (true, path) => (true, path),
            _ => match self.walk_to(a, b, false) {
                (true, path) => (true, path),
                (false, start_only) => self.shortest_path(a, b).map_or((false, start_only), |path| (true, path)),
            },
        };
        let Path { vertices, entered_by } =
            if found { path } else { Path { vertices: path.vertices[..1].to_vec(), entered_by: Vec::new() } };
        let epoch = self.epoch;
        self.tree.clear();
        for &v in &vertices {
            self.vertex_mark[v.index()] = epoch;
            self.tree.push(v);
        }
        let path = Path { vertices, entered_by };
        let chords: Vec<HalfEdgeId> = path.chords(self, |v| self.vertex_mark[v.index()] == epoch).collect();
        for h in chords {
            if !self.is_separator(h) && !self.is_twice_cut(h) {
                self.twice_cut.push(h);
            }
        }
        found
    }

    /// The common boundary of `R(a)` and `R(b)` as a path, if they meet.
    /// Every point of it is nearer the open segment between them than `a`
    /// and `b` (no circle through both endpoints misses the segment), so all
    /// of it is deleted, exactly, whatever the numbers say: the two
    /// endpoints of a segment are never neighbours. With sound numbers the
    /// common boundary is one piece (the disks through `a` and `b` centred
    /// between two empty ones are empty too); if lying numbers made several,
    /// the longest is taken.
    fn shared_boundary(&self, a: SiteId, b: SiteId) -> Option<Path> {
        let boundary: Vec<HalfEdgeId> = self.store.cell_boundary(a).collect();
        let n = boundary.len();
        let shared = |i: usize| self.store.right(boundary[i % n]) == b;
        // The longest run of consecutive shared half-edges, cyclically.
        let mut best: Option<(usize, usize)> = None;
        for start in (0..n).filter(|&i| shared(i) && !shared(i + n - 1)) {
            let len = (start..start + n).take_while(|&i| shared(i)).count();
            if best.map_or(true, |(_, l)| len > l) {
                best = Some((start, len));
            }
        }
        let (start, len) = best?;
        let entered_by: Vec<HalfEdgeId> = (start..start + len).map(|i| boundary[i % n]).collect();
        let mut vertices: Vec<VertexId> = entered_by.iter().map(|h| h.origin()).collect();
        vertices.push(self.store.target(*entered_by.last()?));
        let distinct = vertices.iter().collect::<HashSet<_>>().len() == vertices.len();
        // (an arc's endpoints' bisector runs through its centre, beyond
        // which it stays theirs: only where all of it conflicts)
        let arc_conflicts = self.inserting_arc.is_none() || vertices.iter().all(|&v| self.segment_conflict(v, a, b));
        let usable = distinct && arc_conflicts && vertices.iter().all(|&v| self.walkable(v, a, b));
        usable.then_some(Path { vertices, entered_by })
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
        let path = Path { vertices, entered_by };
        let cuttable = path.chords(self, |v| on_path.contains(&v)).all(|h| self.is_separator(h) || self.may_cut_twice(h, a, b));
        cuttable.then_some(path)
    }

    /// The walk from `R(a)` to `R(b)`; `strict` admits only vertices in
    /// conflict with the segment. Returns whether `R(b)` was reached and the
    /// walk's vertices (at least the start).
    fn walk_to(&self, a: SiteId, b: SiteId, strict: bool) -> (bool, Path) {
        let (pa, pb) = self.segment_between(a, b);
        let (start, first_move) = self.path_start(a, b);
        if self.store.sites_of(start).contains(&b) {
            return (true, Path { vertices: vec![start], entered_by: Vec::new() });
        }
        let mut walk = PathWalk {
            vertices: Vec::new(),
            entered_by: Vec::new(),
            on_walk: SmallSet::default(),
            tried: SmallSet::default(),
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
        let ends = self.segment_between(a, b);
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
                (depth.position() == CirclePosition::Inside, depth.depth())
            };
            let conflict = if conflict { 1.0 } else { 0.0 };
            let key = if self.store.sites_of(v).contains(&b) && self.walkable(v, a, b) {
                (conflict, f64::INFINITY, f64::INFINITY)
            } else {
                let left = self.left_degree(v, self.store.left(out), (a, b), ends);
                let right = self.left_degree(v, self.store.right(out), (a, b), ends);
                (conflict, LeftDegree::separation(left, right), -depth)
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
                || (self.may_cut_twice(x, a, b) && (!walk.strict || self.middle_margin(x, a, b).middle() == EdgeMiddle::Stays))
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
    fn walk_step(&self, walk: &mut PathWalk, v: VertexId, a: SiteId, b: SiteId, pa: Point, pb: Point) -> Option<HalfEdgeId> {
        let pos = walk.vertices.len() - 1;
        let (preferred, other, certainty) = match walk.entered_by.last() {
            Some(&h) => {
                // Arrived by h; t leaves v back. The cell ahead, N, should
                // stay on the side of the walk it is on of the segment.
                let t = self.store.twin(h);
                let ahead = self.store.opposite(t);
                let l = self.left_degree(v, ahead, (a, b), (pa, pb));
                let (keep_left, keep_right) = (t.rotate(1), t.rotate(2));
                if l.side() == Orientation::CounterClockwise {
                    (keep_left, keep_right, l.certainty())
                } else {
                    (keep_right, keep_left, l.certainty())
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
        let option = |h: HalfEdgeId| self.walk_allows(walk, h, a, b).then(|| (!conflicts(h), h));
        let (chosen, alternative) = match (option(preferred), option(other)) {
            (None, None) => return None,
            (Some(x), None) | (None, Some(x)) => (x, None),
            // stable: rule order among equals
            (Some(x), Some(y)) if x.0 && !y.0 => (y, Some(x)),
            (Some(x), Some(y)) => (x, Some(y)),
        };
        if let Some((out_of_conflict, h)) = alternative {
            let c = if out_of_conflict { f64::INFINITY } else { certainty };
            walk.alternatives.push(Reverse((certainty_key(c), pos, v, h)));
        }
        Some(chosen.1)
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
}

/// A set of ids that is usually small: a list searched linearly, with a
/// hash set beside it once it grows beyond `SMALL_SET_LIMIT` (long walks).
struct SmallSet<T> {
    items: Vec<T>,
    large: Option<HashSet<T, BuildHasherDefault<IdHasher>>>,
}

/// Beyond this many items a [`SmallSet`] also keeps a hash set.
const SMALL_SET_LIMIT: usize = 32;

impl<T> Default for SmallSet<T> {
    fn default() -> Self {
        SmallSet { items: Vec::new(), large: None }
    }
}

impl<T: Copy + Eq + Hash> SmallSet<T> {
    fn contains(&self, x: &T) -> bool {
        match &self.large {
            Some(set) => set.contains(x),
            None => self.items.contains(x),
        }
    }

    fn insert(&mut self, x: T) {
        if self.contains(&x) {
            return;
        }
        self.items.push(x);
        match &mut self.large {
            Some(set) => {
                set.insert(x);
            }
            None if self.items.len() > SMALL_SET_LIMIT => self.large = Some(self.items.iter().copied().collect()),
            None => {}
        }
    }

    fn remove(&mut self, x: &T) {
        if let Some(k) = self.items.iter().rposition(|y| y == x) {
            self.items.swap_remove(k);
        }
        if let Some(set) = &mut self.large {
            set.remove(x);
        }
    }
}

/// A hasher for the 32-bit ids of the walk's sets (Fibonacci hashing; the
/// keys are not chosen by an adversary, only by the input's geometry).
#[derive(Default)]
struct IdHasher(u64);

impl Hasher for IdHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u32(&mut self, x: u32) {
        self.write_u64(u64::from(x));
    }

    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    }
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
