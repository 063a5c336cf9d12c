//! Gluing the two halves' diagrams into one (integer bookkeeping only).
//!
//! Site ids of the glued construction: the point at infinity, the points
//! the left half owns (in its order), those the right half owns, then the
//! left half's segments and the right half's. Vertices: the glued store is
//! the left diagram's, grown. Every vertex of the left diagram with a site
//! the left half owns keeps its id; every vertex of the right diagram
//! without one is appended; the left diagram's other vertices (its halo's
//! alone) are dropped, their slots filled from the end. An edge between a
//! kept vertex and a dropped one leads across the cut: it is relinked to
//! the twin that the other half's copy of the kept vertex (the vertex of
//! the same three sites, counter-clockwise in the same order) has there.
//!
//! Each step that is linear in the diagram runs on both threads at once,
//! one per half; what is sequential (the pairing across the cut, the
//! dropped slots) is linear in the cut's length.

use super::super::restart::Outcome;
use super::super::state::{Construction, INFINITE};
use super::super::threads::run_beside;
use super::{Built, BuiltHalf, Side};
use crate::diagram::{HalfEdgeId, SiteId, Store, VertexId, NONE};
use crate::geometry::Point;
use std::collections::HashMap;

/// The two halves glued; `None` when their vertices across the cut do not
/// pair up (then the caller builds on one thread).
pub(super) fn glue(left: BuiltHalf, right: BuiltHalf, points: usize, segments: usize, cut: f64) -> Option<Built> {
    debug_assert!(left.side == Side::Left && right.side == Side::Right);
    let (owned_right, owned_left) = run_beside(|| Owned::of(&right, cut), || Owned::of(&left, cut));
    let ranges = Ranges::of(&owned_left, &owned_right);
    let (names_right, names_left) =
        run_beside(|| owned_right.name(&right, &ranges, Side::Right), || owned_left.name(&left, &ranges, Side::Left));
    let (of_point, of_segment) = inputs_named(points, segments, [&names_left, &names_right])?;

    // Held sites of the other side take the names their owner gave them;
    // then each half renames its cells and finds what it keeps.
    let BuiltHalf { construction: lc, points: lp, segments: ls, site_of_point: lsp, site_of_segment: lss, .. } = left;
    let BuiltHalf { construction: rc, points: rp, segments: rs, site_of_point: rsp, site_of_segment: rss, .. } = right;
    // Both halves write their owned sites' geometry into their own ranges.
    let mut sites = vec![Point::new(f64::NAN, f64::NAN); ranges.count];
    let mut segment_ends = vec![[SiteId(NONE); 2]; ranges.count - ranges.first_segment as usize];
    let (left_points, rest) = sites.split_at_mut(ranges.left_points_end as usize);
    let right_points = &mut rest[..(ranges.first_segment - ranges.left_points_end) as usize];
    let (left_ends, right_ends) = segment_ends.split_at_mut((ranges.left_segments_end - ranges.first_segment) as usize);
    let ranges_ref = &ranges;
    let (of_point_ref, of_segment_ref) = (&of_point, &of_segment);
    let (right_side, left_side) = run_beside(
        move || {
            let map = names_right.complete(&rp, &rsp, &rs, &rss, of_point_ref, of_segment_ref)?;
            write_geometry(&rc, &map, ranges_ref, Side::Right, right_points, right_ends);
            let store = rc.into_parts().store;
            Some(Renamed::of(store, map, ranges_ref, Side::Right))
        },
        move || {
            let map = names_left.complete(&lp, &lsp, &ls, &lss, of_point_ref, of_segment_ref)?;
            write_geometry(&lc, &map, ranges_ref, Side::Left, left_points, left_ends);
            let store = lc.into_parts().store;
            Some(Renamed::of(store, map, ranges_ref, Side::Left))
        },
    );
    let (mut left, right) = (left_side?, right_side?);

    // Pair the vertices on both sides of the cut.
    let mut partner_of_left: HashMap<u32, u32> = HashMap::with_capacity(left.across.len());
    let mut partner_of_right: HashMap<u32, u32> = HashMap::with_capacity(left.across.len());
    for &v in &left.across {
        match right.across_by_sites.get(&key(left.store.sites_of(VertexId(v)))) {
            Some(&w) if w != NONE => {
                partner_of_left.insert(v, w);
                partner_of_right.insert(w, v);
            }
            _ => return None,
        }
    }

    // The left store grown by the right's kept vertices: its arrays grown
    // on both threads, two each, then the right's vertices written by
    // halves, one per thread; then the few edges from the left across.
    let n1 = left.store.vertex_count();
    let total = n1 + right.kept_count;
    let Store { right: cells, twin, position, clearance, .. } = &mut left.store;
    run_beside(
        || {
            position.resize(total, Point::default());
            clearance.resize(total, 0.0);
        },
        || {
            cells.resize(3 * total, SiteId(NONE));
            twin.resize(3 * total, HalfEdgeId(NONE));
        },
    );
    let (sites_low, sites_high) = cells.split_at_mut(3 * n1);
    let sites_low: &[SiteId] = sites_low;
    let twin_high = &mut twin[3 * n1..];
    let (position_high, clearance_high) = (&mut position[n1..], &mut clearance[n1..]);
    let middle = right.store.vertex_count() / 2;
    let split = right.keep[..middle].iter().filter(|&&k| k).count();
    let (sites_a, sites_b) = sites_high.split_at_mut(3 * split);
    let (twin_a, twin_b) = twin_high.split_at_mut(3 * split);
    let (position_a, position_b) = position_high.split_at_mut(split);
    let (clearance_a, clearance_b) = clearance_high.split_at_mut(split);
    let (from_b, from_a) = run_beside(
        || {
            let out = Appended { sites: sites_b, twin: twin_b, position: position_b, clearance: clearance_b };
            right.fill(middle..right.store.vertex_count(), split, sites_low, n1, &partner_of_right, out)
        },
        || {
            let out = Appended { sites: sites_a, twin: twin_a, position: position_a, clearance: clearance_a };
            right.fill(0..middle, 0, sites_low, n1, &partner_of_right, out)
        },
    );
    let mut from_right = from_a?;
    from_right.extend_from_slice(&from_b?);
    let from_left = relink_left(&left.keep, &left.across, &left.store.right, &mut left.store.twin, &partner_of_left, &right, n1)?;

    // Cells: each site's edge from the half that owns it, both at once.
    let mut cell_edge = vec![NONE; ranges.count];
    let (left_low, rest) = cell_edge.split_at_mut(ranges.left_points_end as usize);
    let (right_low, rest) = rest.split_at_mut((ranges.first_segment - ranges.left_points_end) as usize);
    let (left_high, right_high) = rest.split_at_mut((ranges.left_segments_end - ranges.first_segment) as usize);
    let cells_of_right = || -> Option<()> {
        let (low, high) = (ranges.left_points_end, ranges.left_segments_end);
        for (local, &f) in right.map.iter().enumerate() {
            if ranges.owned(SiteId(f), Side::Right) {
                let h = *right.store.cell_edge.get(local).filter(|&&h| h != NONE)?;
                let slot = if f < ranges.first_segment {
                    &mut right_low[(f - low) as usize]
                } else {
                    &mut right_high[(f - high) as usize]
                };
                *slot = right.across_to(HalfEdgeId(h), n1, &partner_of_right, &left.store)?.0;
            }
        }
        Some(())
    };
    let cells_of_left = || -> Option<()> {
        for (local, &f) in left.map.iter().enumerate() {
            if ranges.owned(SiteId(f), Side::Left) {
                let h = left.store.cell_edge[local];
                if h == NONE || !left.keep[HalfEdgeId(h).origin().index()] {
                    return None;
                }
                let slot = if f < ranges.first_segment {
                    &mut left_low[f as usize]
                } else {
                    &mut left_high[(f - ranges.first_segment) as usize]
                };
                *slot = h;
            }
        }
        Some(())
    };
    let (right_cells, left_cells) = run_beside(cells_of_right, cells_of_left);
    right_cells?;
    left_cells?;
    let n1_kept_any = |h: HalfEdgeId| h.origin().index() >= n1 || left.keep[h.origin().index()];
    cell_edge[INFINITE.index()] = (0..left.store.twin.len())
        .map(HalfEdgeId::from_index)
        .find(|&h| n1_kept_any(h) && left.store.left(h) == INFINITE)
        .map_or(NONE, |h| h.0);
    drop(right);
    let mut store = left.store;
    store.cell_edge = cell_edge;

    // Every edge relinked across the cut leads back (those within a half
    // are the half's own, renumbered one to one).
    let keep = &left.keep;
    let kept = |v: usize| v >= n1 || keep[v];
    let back = |h: &HalfEdgeId| {
        let t = store.twin(*h);
        t.0 != NONE && kept(t.origin().index()) && store.twin(t) == *h
    };
    if !from_right.iter().chain(&from_left).all(back) {
        return None;
    }
    drop_vertices(&mut store, keep);

    let first_segment = if ranges.first_segment as usize == ranges.count { u32::MAX } else { ranges.first_segment };
    let construction = Construction::assembled(store, sites, first_segment, segment_ends);
    Some((construction, of_point, of_segment, Outcome::default()))
}

/// The glued build's ranges of site ids.
struct Ranges {
    /// Points the left half owns: `1..left_points_end`; the right half's
    /// up to `first_segment`.
    left_points_end: u32,
    first_segment: u32,
    /// Segments the left half owns: `first_segment..left_segments_end`;
    /// the right half's up to `count`.
    left_segments_end: u32,
    count: usize,
}

impl Ranges {
    fn of(left: &Owned, right: &Owned) -> Ranges {
        let left_points_end = 1 + left.points;
        let first_segment = left_points_end + right.points;
        let left_segments_end = first_segment + left.segments;
        Ranges { left_points_end, first_segment, left_segments_end, count: (left_segments_end + right.segments) as usize }
    }

    fn owned(&self, s: SiteId, side: Side) -> bool {
        let left = (s.0 >= 1 && s.0 < self.left_points_end) || (s.0 >= self.first_segment && s.0 < self.left_segments_end);
        let real = s.0 != INFINITE.0 && s.0 != NONE;
        real && (left == (side == Side::Left))
    }

    /// The first id of `side`'s points and of its segments.
    fn starts(&self, side: Side) -> (u32, u32) {
        match side {
            Side::Left => (1, self.first_segment),
            Side::Right => (self.left_points_end, self.left_segments_end),
        }
    }
}

/// Which of a half's sites it owns.
struct Owned {
    /// Per local site.
    owned: Vec<bool>,
    points: u32,
    segments: u32,
}

impl Owned {
    fn of(half: &BuiltHalf, cut: f64) -> Owned {
        let c = &half.construction;
        let count = c.store().site_count();
        let mut owned = vec![false; count];
        let (mut points, mut segments) = (0, 0);
        for s in (1..count).map(SiteId::from_index) {
            let (pts, n) = c.site_points(s);
            if half.side.owns(&pts[..n], cut) {
                owned[s.index()] = true;
                if n == 1 {
                    points += 1;
                } else {
                    segments += 1;
                }
            }
        }
        Owned { owned, points, segments }
    }

    /// Final ids for the owned sites, in local order: a map per local site
    /// (`NONE` for the others yet).
    fn name(&self, half: &BuiltHalf, ranges: &Ranges, side: Side) -> Names {
        let c = &half.construction;
        let (mut next_point, mut next_segment) = ranges.starts(side);
        let mut map = vec![NONE; self.owned.len()];
        map[INFINITE.index()] = INFINITE.0;
        for (local, _) in self.owned.iter().enumerate().filter(|(_, &o)| o) {
            let next = if c.ends_of(SiteId::from_index(local)).is_none() { &mut next_point } else { &mut next_segment };
            map[local] = *next;
            *next += 1;
        }
        let named_points = named(&half.points, &half.site_of_point, &map);
        let named_segments = named(&half.segments, &half.site_of_segment, &map);
        Names { map, named_points, named_segments }
    }
}

/// Per input (point or segment) a half holds, with an owned site: the
/// input's index and the site's final id.
fn named(inputs: &[u32], site_of: &[SiteId], map: &[u32]) -> Vec<(u32, u32)> {
    inputs.iter().zip(site_of).filter(|(_, s)| s.0 != NONE && map[s.index()] != NONE).map(|(&i, s)| (i, map[s.index()])).collect()
}

/// A half's final ids so far.
struct Names {
    map: Vec<u32>,
    named_points: Vec<(u32, u32)>,
    named_segments: Vec<(u32, u32)>,
}

impl Names {
    /// The map with the held sites of the other side named too; `None`
    /// when a held input has no site.
    fn complete(
        self,
        points: &[u32],
        site_of_point: &[SiteId],
        segments: &[u32],
        site_of_segment: &[SiteId],
        of_point: &[SiteId],
        of_segment: &[SiteId],
    ) -> Option<Vec<u32>> {
        let mut map = self.map;
        for (inputs, site_of, of) in [(points, site_of_point, of_point), (segments, site_of_segment, of_segment)] {
            for (&i, &s) in inputs.iter().zip(site_of) {
                let slot = map.get_mut(s.index())?;
                if *slot == NONE {
                    *slot = of[i as usize].0;
                }
            }
        }
        Some(map)
    }
}

/// Per input point and per segment, its final site; `None` when one has
/// none (a half that lost an input: never with sound halves).
fn inputs_named(points: usize, segments: usize, names: [&Names; 2]) -> Option<(Vec<SiteId>, Vec<SiteId>)> {
    let mut of_point = vec![SiteId(NONE); points];
    let mut of_segment = vec![SiteId(NONE); segments];
    for n in names {
        n.named_points.iter().for_each(|&(i, f)| of_point[i as usize] = SiteId(f));
        n.named_segments.iter().for_each(|&(k, f)| of_segment[k as usize] = SiteId(f));
    }
    if of_point.iter().chain(&of_segment).any(|s| s.0 == NONE) {
        return None;
    }
    Some((of_point, of_segment))
}

/// Writes a half's owned sites' coordinates into `points` (its owned
/// points' range of the site table, from its first id) and its owned
/// segments' ends into `ends` (its range of the segments' ends).
fn write_geometry(c: &Construction, map: &[u32], ranges: &Ranges, side: Side, points: &mut [Point], ends: &mut [[SiteId; 2]]) {
    let (first_point, first_segment) = ranges.starts(side);
    // (the left's points start at the point at infinity's slot: 0)
    let first_point = if side == Side::Left { 0 } else { first_point };
    for (local, &f) in map.iter().enumerate().skip(1) {
        if !ranges.owned(SiteId(f), side) {
            continue;
        }
        let s = SiteId::from_index(local);
        match c.ends_of(s) {
            Some(e) => ends[(f - first_segment) as usize] = e.map(|e| SiteId(map[e.index()])),
            None => points[(f - first_point) as usize] = c.site_points(s).0[0],
        }
    }
}

/// A half's store renamed to final ids, with what the glue keeps of it.
struct Renamed {
    store: Store,
    map: Vec<u32>,
    /// Per vertex: kept (left: has an owned site; right: has none of the left's).
    keep: Vec<bool>,
    kept_count: usize,
    /// Right: the new id of each kept vertex, from 0 (offset by the left
    /// store's length when appended).
    rank: Vec<u32>,
    /// Left: its kept vertices with a site of the right (the cut's).
    across: Vec<u32>,
    /// Right: its dropped vertices with a site of its own, by their sites
    /// (`NONE`: two of them have the same).
    across_by_sites: HashMap<[SiteId; 3], u32>,
}

impl Renamed {
    fn of(mut store: Store, map: Vec<u32>, ranges: &Ranges, side: Side) -> Renamed {
        let count = store.vertex_count();
        let (mut keep, mut rank) = (Vec::with_capacity(count), Vec::with_capacity(if side == Side::Right { count } else { 0 }));
        let (mut across, mut across_by_sites) = (Vec::new(), HashMap::new());
        let mut kept_count = 0;
        // one pass: each vertex's sites renamed, then what the glue keeps of it
        for (v, cells) in store.right.chunks_exact_mut(3).enumerate() {
            cells.iter_mut().for_each(|r| *r = SiteId(map[r.index()]));
            let sites = [cells[0], cells[1], cells[2]];
            let any_left = sites.iter().any(|&s| ranges.owned(s, Side::Left));
            let has_right = sites.iter().any(|&s| ranges.owned(s, Side::Right));
            let kept = any_left == (side == Side::Left);
            match side {
                Side::Left if kept && has_right => across.push(v as u32),
                Side::Right if !kept && has_right => {
                    let slot = across_by_sites.entry(key(sites)).or_insert(v as u32);
                    if *slot != v as u32 {
                        *slot = NONE; // two vertices of these sites: ambiguous
                    }
                }
                _ => {}
            }
            if side == Side::Right {
                rank.push(if kept { kept_count as u32 } else { NONE });
            }
            keep.push(kept);
            kept_count += usize::from(kept);
        }
        Renamed { store, map, keep, kept_count, rank, across, across_by_sites }
    }

    /// Right: the glued half-edge for its half-edge `h`: its own, appended
    /// after the left's `n1` vertices, or the left partner's with the same
    /// cell on the right (`left_sites`: the left store's cells).
    fn across_to(&self, h: HalfEdgeId, n1: usize, partner: &HashMap<u32, u32>, left: &Store) -> Option<HalfEdgeId> {
        self.across_to_sites(h, n1, partner, &left.right)
    }

    fn across_to_sites(
        &self,
        h: HalfEdgeId,
        n1: usize,
        partner: &HashMap<u32, u32>,
        left_sites: &[SiteId],
    ) -> Option<HalfEdgeId> {
        let v = h.origin().index();
        if self.keep[v] {
            return Some(VertexId(n1 as u32 + self.rank[v]).half_edge(h.slot()));
        }
        let w = *partner.get(&(v as u32))?;
        let site = self.store.right(h);
        let slot = (0..3).find(|&k| left_sites[3 * w as usize + k as usize] == site)?;
        Some(VertexId(w).half_edge(slot))
    }

    /// Right: writes its kept vertices among `vertices` into their part of
    /// the glued store's appended arrays (which starts at the kept vertex
    /// of rank `first_rank`). Returns the half-edges it linked to the
    /// left's vertices.
    fn fill(
        &self,
        vertices: std::ops::Range<usize>,
        first_rank: usize,
        left_sites: &[SiteId],
        n1: usize,
        partner: &HashMap<u32, u32>,
        out: Appended<'_>,
    ) -> Option<Vec<HalfEdgeId>> {
        let mut across = Vec::new();
        for v in vertices.filter(|&v| self.keep[v]) {
            let at = self.rank[v] as usize - first_rank;
            let from = VertexId::from_index(v);
            out.sites[3 * at..3 * at + 3].copy_from_slice(&self.store.sites_of(from));
            out.position[at] = self.store.position[v];
            out.clearance[at] = self.store.clearance[v];
            for k in 0..3 {
                let t = self.store.twin(from.half_edge(k));
                out.twin[3 * at + k as usize] = self.across_to_sites(t, n1, partner, left_sites)?;
                if !self.keep[t.origin().index()] {
                    across.push(VertexId::from_index(n1 + first_rank + at).half_edge(k));
                }
            }
        }
        Some(across)
    }
}

/// The appended part of the glued store's arrays.
struct Appended<'a> {
    sites: &'a mut [SiteId],
    twin: &'a mut [HalfEdgeId],
    position: &'a mut [Point],
    clearance: &'a mut [f64],
}

/// Left: relinks the edges from its kept vertices into dropped ones, to
/// the right partner's twins there. Such an edge separates two sites of
/// the dropped vertex, neither the left's, so its kept end has a site of
/// the right: it is one of `across`.
fn relink_left(
    keep: &[bool],
    across: &[u32],
    sites: &[SiteId],
    twin: &mut [HalfEdgeId],
    partner: &HashMap<u32, u32>,
    right: &Renamed,
    n1: usize,
) -> Option<Vec<HalfEdgeId>> {
    let mut relinked = Vec::new();
    for &v in across {
        for k in 0..3 {
            let h = 3 * v as usize + k;
            if keep[twin[h].origin().index()] {
                continue;
            }
            let w = *partner.get(&v)?;
            let j = (0..3).find(|&j| right.store.right(VertexId(w).half_edge(j)) == sites[h])?;
            let t = right.store.twin(VertexId(w).half_edge(j));
            if !right.keep[t.origin().index()] {
                return None;
            }
            twin[h] = VertexId(n1 as u32 + right.rank[t.origin().index()]).half_edge(t.slot());
            relinked.push(HalfEdgeId::from_index(h));
        }
    }
    Some(relinked)
}

/// A vertex's sites, rotated to start at the smallest id (counter-clockwise
/// order kept): the same key for the same vertex in both halves.
fn key(sites: [SiteId; 3]) -> [SiteId; 3] {
    let k = (0..3).min_by_key(|&k| sites[k]).unwrap_or(0);
    [sites[k], sites[(k + 1) % 3], sites[(k + 2) % 3]]
}

/// Removes the left diagram's vertices not kept (`keep`, per vertex below
/// its length; those after it are all kept), filling each slot with the
/// last kept vertex and relinking its edges and cells.
fn drop_vertices(store: &mut Store, keep: &[bool]) {
    let is_hole = |v: usize| v < keep.len() && !keep[v];
    let mut count = store.vertex_count();
    // Holes in increasing order, each filled with the last vertex kept:
    // that one always lies beyond every hole filled so far.
    for hole in (0..keep.len()).filter(|&v| !keep[v]) {
        while count > 0 && is_hole(count - 1) {
            count -= 1;
        }
        if hole >= count {
            break;
        }
        move_vertex(store, VertexId::from_index(count - 1), VertexId::from_index(hole));
        count -= 1;
    }
    store.right.truncate(3 * count);
    store.twin.truncate(3 * count);
    store.position.truncate(count);
    store.clearance.truncate(count);
}

/// Moves vertex `from` into the free slot `to`, relinking its three edges
/// and the cells that name one of its half-edges.
fn move_vertex(store: &mut Store, from: VertexId, to: VertexId) {
    for k in 0..3 {
        let (h, g) = (from.half_edge(k), to.half_edge(k));
        store.right[g.index()] = store.right[h.index()];
        let t = store.twin(h);
        store.link(g, t);
    }
    for k in 0..3 {
        let (h, g) = (from.half_edge(k), to.half_edge(k));
        let left = store.left(g);
        if store.cell_edge[left.index()] == h.0 {
            store.cell_edge[left.index()] = g.0;
        }
    }
    store.position[to.index()] = store.position[from.index()];
    store.clearance[to.index()] = store.clearance[from.index()];
}
