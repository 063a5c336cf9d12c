//! Growing the deletion tree of a segment `ab` from its path (P3, P5, the
//! conflict and strip criteria), with the edges whose two ends are deleted
//! but whose middle stays out of the new cell cut twice: which edge of each
//! closed cycle that is, and its margin from the vertices the cuts would
//! create.

use super::super::PointDiagram;
use crate::diagram::{HalfEdgeId, SiteId, VertexId};
use crate::geometry::parabola::Parabola;
use crate::geometry::point::norm;
use crate::geometry::segment_predicates::in_strip;
use crate::geometry::segment_solvers;
use crate::geometry::site::Site;
use crate::geometry::{fault, Point};

/// How far, as a fraction of an edge, a computed crossing of the edge may
/// lie beyond one of its ends and still be taken as at that end.
const END_TOLERANCE: f64 = 1e-6;

impl PointDiagram {
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
        let sites = self.store.sites_of(u);
        (sites.contains(&a) && sites.contains(&b)) || in_strip(self.store.position[u.index()], pa, pb)
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
        !sides.contains(&a) && !sides.contains(&b) && self.is_finite_edge(h)
    }

    /// Whether neither end of `h` is at infinity.
    pub(super) fn is_finite_edge(&self, h: HalfEdgeId) -> bool {
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
    pub(super) fn middle_margin(&self, h: HalfEdgeId, a: SiteId, b: SiteId) -> f64 {
        let sides = [self.store.left(h), self.store.right(h)];
        if sides.contains(&a) && sides.contains(&b) {
            // Every point of the bisector of a and b is closer to the open
            // segment between them (the midpoint is nearer than either end).
            return f64::NEG_INFINITY;
        }
        let edge = self.edge_under(h, a, b);
        let crossings = segment_solvers::vertex(&edge.right, &edge.left, &edge.segment)
            .zip(segment_solvers::vertex(&edge.left, &edge.right, &edge.segment))
            .map(|((near_origin, _), (near_target, _))| (edge.arc.parameter(near_origin), edge.arc.parameter(near_target)));
        // Both ends of the edge are in conflict (certified), so a crossing
        // is inside the edge: one a rounding error beyond an end (the end
        // vertex almost on the new cell's boundary) is at that end.
        let crossings = crossings.map(|(t1, t2)| {
            let at_end = |t: f64, end: f64| if (t - end).abs() <= END_TOLERANCE { end } else { t };
            (at_end(t1, 0.0), at_end(t2, 1.0))
        });
        let margin = match crossings {
            Some((t1, t2)) if 0.0 <= t1 && t1 < t2 && t2 <= 1.0 => edge.excess(0.5 * (t1 + t2)),
            Some((t1, t2)) => -(t1 - t2).abs().max(f64::MIN_POSITIVE),
            None => sampled_maximum(&|t| edge.excess(t)),
        };
        fault::perturb(margin)
    }

    /// The edge of `h` with its two sites, its curve, and the new segment
    /// `ab`, for `middle_margin`.
    fn edge_under(&self, h: HalfEdgeId, a: SiteId, b: SiteId) -> EdgeUnderSegment {
        let sides = [self.store.left(h), self.store.right(h)];
        let [left, right] = sides.map(|s| self.site_geometry(s));
        let (pa, pb) = (self.sites[a.index()], self.sites[b.index()]);
        let (from, to) = (self.store.position[h.origin().index()], self.store.position[self.store.target(h).index()]);
        let arc = match Parabola::of_sites(&left, &right) {
            Some(p) => EdgeArc::Parabola(p, p.parameter(from), p.parameter(to)),
            None => EdgeArc::Line(from, to),
        };
        EdgeUnderSegment {
            left,
            right,
            arc,
            segment: Site::Segment { a: pa, b: pb },
            touches_end: sides.contains(&a) || sides.contains(&b),
        }
    }
}

/// An edge seen from a new segment (`PointDiagram::edge_under`).
struct EdgeUnderSegment {
    left: Site,
    right: Site,
    arc: EdgeArc,
    segment: Site,
    /// One of the edge's sites is an endpoint of the segment.
    touches_end: bool,
}

impl EdgeUnderSegment {
    /// The excess of the distance to the segment over the distance to the
    /// edge's own sites, at the point of the edge at parameter `t` (0 at its
    /// origin, 1 at its target); NaN gives `-∞`.
    fn excess(&self, t: f64) -> f64 {
        let q = self.arc.point(t);
        let e = match self.segment {
            // On an edge of R(a) or R(b) the distances to the segment and to
            // its endpoint agree outside the strip, so the signed distance
            // beyond the perpendiculars decides, without cancellation.
            Site::Segment { a: pa, b: pb } if self.touches_end => {
                let (dx, dy) = (pb.x - pa.x, pb.y - pa.y);
                let beyond_b = (q.x - pb.x) * dx + (q.y - pb.y) * dy;
                let beyond_a = (pa.x - q.x) * dx + (pa.y - q.y) * dy;
                beyond_a.max(beyond_b) / norm(dx, dy)
            }
            _ => self.segment.distance(q) - 0.5 * (self.left.distance(q) + self.right.distance(q)),
        };
        if e.is_nan() {
            f64::NEG_INFINITY
        } else {
            e
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
