//! Gluing the two halves' diagrams into one (integer bookkeeping only).
//!
//! Site ids of the glued construction: the point at infinity, the points
//! the left half owns (in its order), those the right half owns, then the
//! left half's segments and the right half's. Vertices: the glued store is
//! the left diagram's with the right's appended whole (its ids moved by the
//! left's count, a copy with no look-up). Every vertex of the left diagram
//! with a site the left half owns is kept, and every vertex of the right
//! diagram without one; the others (each half's halo's alone, a few in a
//! hundred) are dropped, their slots filled from the end. An edge between
//! a kept vertex and a dropped one leads across the cut: it is relinked to
//! the other half's edge between the same two cells, the other way round
//! (from the vertex that half keeps).
//!
//! Why edges and not vertices: a degenerate vertex (four sites or more on
//! one circle, as in every lattice) is cut into degree-3 vertices in the
//! order the half inserted its sites, and the two halves may cut one on
//! the cut two ways, so a vertex of one half may have no copy in the
//! other. The edges out of such a cluster separate the same cells
//! whatever the cut, and the cluster comes whole from one half (the
//! glued cut is that half's). Where two edges across separate the same
//! two cells (a segment and its endpoint may share two), or an edge has
//! no partner (a cluster split across the halves' keeps, cut two ways),
//! the halves are not glued.
//!
//! Each step that is linear in the diagram runs on both threads at once,
//! one per half; what is sequential is linear in the cut's length (the
//! pairing across it) or in the halos' vertices (the dropped slots).

use super::super::restart::Outcome;
use super::super::state::{Construction, INFINITE};
use super::super::threads::run_beside;
use super::{Built, BuiltHalf, Side};
use crate::diagram::{HalfEdgeId, SiteId, Store, VertexId, NONE};
use crate::geometry::Point;
use std::collections::HashMap;

/// The two halves glued; `None` when their edges across the cut do not
/// pair up (then the caller builds on one thread).
pub(super) fn glue(left: BuiltHalf, right: BuiltHalf, points: usize, segments: usize) -> Option<Built> {
    debug_assert!(left.side == Side::Left && right.side == Side::Right);
    let (owned_right, owned_left) = run_beside(|| Owned::of(&right), || Owned::of(&left));
    let ranges = Ranges::of(&owned_left, &owned_right);
    let (names_right, names_left) =
        run_beside(|| owned_right.name(&right, &ranges, Side::Right), || owned_left.name(&left, &ranges, Side::Left));
    let (of_point, of_segment) = inputs_named(points, segments, [&names_left, &names_right])?;

    // Held sites of the other side take the names their owner gave them;
    // then each half renames its cells and finds what it keeps.
    let (lc, rc) = (left.into_construction(), right.into_construction());
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
            let map = names_right.complete(of_point_ref, of_segment_ref)?;
            write_geometry(&rc, &map, ranges_ref, Side::Right, right_points, right_ends);
            let store = rc.into_parts().store;
            Some(Renamed::of(store, map, ranges_ref, Side::Right))
        },
        move || {
            let map = names_left.complete(of_point_ref, of_segment_ref)?;
            write_geometry(&lc, &map, ranges_ref, Side::Left, left_points, left_ends);
            let store = lc.into_parts().store;
            Some(Renamed::of(store, map, ranges_ref, Side::Left))
        },
    );
    let (mut left, right) = (left_side?, right_side?);

    // Pair the edges across the cut: each is the edge between the same
    // two sites in both halves (a degenerate vertex on the cut may be cut
    // one way in one half and another in the other: its edges still pair
    // up, and the glued cut is the one of whichever half keeps them).
    let crossings = left.crossing.len();
    if crossings != right.crossing.len() {
        return None;
    }
    for (&[a, b], &h) in &left.crossing {
        match right.crossing.get(&[b, a]) {
            Some(&t) if t.0 != NONE && h.0 != NONE => {}
            _ => return None,
        }
    }

    // The left store grown by the right's whole store, its dropped
    // vertices too (a few in a hundred: its halo's), on both threads (each
    // array written once): sites, positions and clearances as they are,
    // twins moved past the left's `n1` vertices. Then the edges across the
    // cut relinked both ways; the dropped vertices' slots are filled last.
    // (every edge across the cut listed: never otherwise with sound halves)
    if left.edges_to_dropped != crossings || right.edges_to_dropped != crossings {
        return None;
    }
    let n1 = left.store.vertex_count();
    let total = n1 + right.store.vertex_count();
    let offset = u32::try_from(3 * n1).ok().filter(|_| 3 * total < NONE as usize)?;
    let Store { right: cells, twin, position, clearance, .. } = &mut left.store;
    // (each array grown exactly, should the room the left half made fall
    // short: they are hundreds of megabytes on large inputs, and doubled
    // they would take as much again)
    fn grown<T>(v: &mut Vec<T>, len: usize) -> &mut Vec<T> {
        v.reserve_exact(len.saturating_sub(v.len()));
        v
    }
    run_beside(
        || {
            grown(position, total).extend_from_slice(&right.store.position);
            grown(clearance, total).extend_from_slice(&right.store.clearance);
        },
        || {
            grown(cells, 3 * total).extend_from_slice(&right.store.right);
            // (a half-edge's twin within the right half: the same, moved)
            let moved = right.store.twin.iter().map(|t| HalfEdgeId(t.0.wrapping_add(offset)));
            grown(twin, 3 * total).extend(moved);
        },
    );
    let mut from_right = Vec::with_capacity(crossings);
    let mut from_left = Vec::with_capacity(crossings);
    for (&[a, b], &h) in &left.crossing {
        let t = right.appended(*right.crossing.get(&[b, a])?, n1);
        left.store.link(h, t);
        from_left.push(h);
        from_right.push(t);
    }

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
                *slot = right.cell_edge_glued(HalfEdgeId(h), SiteId(f), n1, &left)?.0;
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
    // (what the glued store keeps: the left's kept vertices, then the right's)
    let mut keep = left.keep;
    keep.extend_from_slice(&right.keep);
    cell_edge[INFINITE.index()] = (0..left.store.twin.len())
        .map(HalfEdgeId::from_index)
        .find(|&h| keep[h.origin().index()] && left.store.left(h) == INFINITE)
        .map_or(NONE, |h| h.0);
    let mut store = left.store;
    store.cell_edge = cell_edge;

    // Every edge relinked across the cut leads back (those within a half
    // are the half's own, moved one to one). (The right's store is freed
    // meanwhile on the other thread: 50 MB at 1M points.)
    let kept = |v: usize| keep[v];
    let keep = &keep;
    let ((), glued) = run_beside(
        move || drop(right),
        || {
            let back = |h: &HalfEdgeId| {
                let t = store.twin(*h);
                t.0 != NONE && kept(t.origin().index()) && store.twin(t) == *h
            };
            let glued = from_right.iter().chain(&from_left).all(back);
            if glued {
                drop_vertices(&mut store, keep);
            }
            glued
        },
    );
    if !glued {
        return None;
    }

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

    #[inline]
    fn owned(&self, s: SiteId, side: Side) -> bool {
        // (without a branch: asked of each site of every vertex; a
        // wrapping difference is below a range's length only inside it)
        let within = |start: u32, end: u32| s.0.wrapping_sub(start) < end.wrapping_sub(start);
        let left = within(1, self.left_points_end) | within(self.first_segment, self.left_segments_end);
        let real = (s.0 != INFINITE.0) & (s.0 != NONE);
        real & (left == (side == Side::Left))
    }

    /// The first id of `side`'s points and of its segments.
    fn starts(&self, side: Side) -> (u32, u32) {
        match side {
            Side::Left => (1, self.first_segment),
            Side::Right => (self.left_points_end, self.left_segments_end),
        }
    }
}

/// How many points and segments a half owns (which ones:
/// `BuiltHalf::owned`).
struct Owned {
    points: u32,
    segments: u32,
}

impl Owned {
    fn of(half: &BuiltHalf) -> Owned {
        let c = &half.construction;
        let (mut points, mut segments) = (0, 0);
        for (s, _) in half.owned.iter().enumerate().filter(|(_, &owned)| owned) {
            if c.ends_of(SiteId::from_index(s)).is_none() {
                points += 1;
            } else {
                segments += 1;
            }
        }
        Owned { points, segments }
    }

    /// Final ids for the owned sites, in local order: a map per local site
    /// (`NONE` for the others yet).
    fn name(&self, half: &BuiltHalf, ranges: &Ranges, side: Side) -> Names {
        let c = &half.construction;
        let (mut next_point, mut next_segment) = ranges.starts(side);
        let mut map = vec![NONE; half.owned.len()];
        map[INFINITE.index()] = INFINITE.0;
        for (local, _) in half.owned.iter().enumerate().filter(|(_, &o)| o) {
            let next = if c.ends_of(SiteId::from_index(local)).is_none() { &mut next_point } else { &mut next_segment };
            map[local] = *next;
            *next += 1;
        }
        let (named_points, halo_points) = named(&half.points, &half.site_of_point, &map);
        let (named_segments, halo_segments) = named(&half.segments, &half.site_of_segment, &map);
        Names { map, named_points, named_segments, halo_points, halo_segments }
    }
}

/// The inputs (points or segments) a half holds: those with an owned site
/// as (input, the site's final id), the others (its halo) as (input, its
/// site). One pass: the sites are in the half's insertion order, so each
/// look-up in `map` is a cache miss on large inputs.
#[allow(clippy::type_complexity)]
fn named(inputs: &[u32], site_of: &[SiteId], map: &[u32]) -> (Vec<(u32, u32)>, Vec<(u32, SiteId)>) {
    let (mut owned, mut halo) = (Vec::with_capacity(inputs.len()), Vec::new());
    for (&i, &s) in inputs.iter().zip(site_of) {
        match map.get(s.index()) {
            Some(&f) if f != NONE => owned.push((i, f)),
            _ => halo.push((i, s)),
        }
    }
    (owned, halo)
}

/// A half's final ids so far.
struct Names {
    map: Vec<u32>,
    named_points: Vec<(u32, u32)>,
    named_segments: Vec<(u32, u32)>,
    halo_points: Vec<(u32, SiteId)>,
    halo_segments: Vec<(u32, SiteId)>,
}

impl Names {
    /// The map with the held sites of the other side (the halo) named
    /// too; `None` when a held input has no site.
    fn complete(self, of_point: &[SiteId], of_segment: &[SiteId]) -> Option<Vec<u32>> {
        let mut map = self.map;
        for (halo, of) in [(&self.halo_points, of_point), (&self.halo_segments, of_segment)] {
            for &(i, s) in halo {
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
    /// Left: its kept vertices with a site of the right (the cut's).
    across: Vec<u32>,
    /// The edges across the cut: each half-edge from a kept vertex to a
    /// dropped one, by its cells (on its right, on its left); `NONE` where
    /// two have the same cells (then the halves are not glued).
    crossing: HashMap<[SiteId; 2], HalfEdgeId>,
    /// How many half-edges lead from a vertex it keeps to one it drops
    /// (counted here, on the half's own thread: a scan of the store).
    edges_to_dropped: usize,
}

impl Renamed {
    fn of(mut store: Store, map: Vec<u32>, ranges: &Ranges, side: Side) -> Renamed {
        let count = store.vertex_count();
        // One pass: each vertex's sites renamed, and whether it has a site
        // of the left (then it is the left's) and one of the right.
        let (mut lefts, mut rights, mut on_the_cut) = (Vec::with_capacity(count), Vec::with_capacity(count), Vec::new());
        for (v, cells) in store.right.chunks_exact_mut(3).enumerate() {
            cells.iter_mut().for_each(|r| *r = SiteId(map[r.index()]));
            let any_left = cells.iter().fold(false, |any, &s| any | ranges.owned(s, Side::Left));
            let any_right = cells.iter().fold(false, |any, &s| any | ranges.owned(s, Side::Right));
            lefts.push(any_left);
            rights.push(any_right);
            if any_left && any_right {
                on_the_cut.push(v);
            }
        }
        // A degenerate vertex (its parts at one position and clearance, but
        // for the rounding of each part's own three sites) is the left's
        // whole when one part has a site of the left: the halves may cut it
        // two ways, and its edges out pair up only when it comes from one
        // half. A part without a site of the left next to one with is on
        // the cut: it has a site of the right. (Taking a true vertex that
        // close as a part is sound: its disk is the part's but for those
        // roundings, far below the margins of `geometry::seam`, so it is
        // final in the left half too; parts the rounding put further apart
        // are not found, and then the edges do not pair up.)
        while let Some(v) = on_the_cut.pop() {
            for k in 0..3 {
                let w = store.twin(VertexId::from_index(v).half_edge(k)).origin().index();
                if !lefts[w] && same_place(&store, v, w) {
                    lefts[w] = true;
                    on_the_cut.push(w);
                }
            }
        }
        // (left: its kept vertices with a site of the right; right: its
        // dropped ones with a site of its own; either end of every edge
        // across the cut is one of them: see `crossing_edges`)
        // (what the side keeps: `lefts` itself on the left, negated in place on the right)
        let mut across = Vec::new();
        let mut keep = lefts;
        for (v, (kept, &has_right)) in keep.iter_mut().zip(&rights).enumerate() {
            if has_right && *kept {
                across.push(v as u32);
            }
            if side == Side::Right {
                *kept = !*kept;
            }
        }
        let crossing = crossing_edges(&store, &keep, &across, side);
        if side == Side::Right {
            across = Vec::new();
        }
        let edges_to_dropped = edges_to_dropped(&store, &keep);
        Renamed { store, map, keep, across, crossing, edges_to_dropped }
    }

    /// Right: the glued id of its half-edge `h` (its store appended after
    /// the left's `n1` vertices).
    fn appended(&self, h: HalfEdgeId, n1: usize) -> HalfEdgeId {
        VertexId::from_index(n1 + h.origin().index()).half_edge(h.slot())
    }

    /// Right: the glued edge of its site `site`'s cell, from its half-edge
    /// `h` there: the first along the cell whose origin it keeps, else
    /// (every vertex of the cell has a site of the left) one of the
    /// left's, on the cut.
    fn cell_edge_glued(&self, h: HalfEdgeId, site: SiteId, n1: usize, left: &Renamed) -> Option<HalfEdgeId> {
        // (at most every half-edge once: a cell's boundary is a cycle)
        let mut g = h;
        for _ in 0..self.store.twin.len() {
            if self.keep[g.origin().index()] {
                return Some(self.appended(g, n1));
            }
            g = self.store.next(g);
            if g == h {
                break;
            }
        }
        let on_the_cut = left.across.iter().flat_map(|&v| (0..3).map(move |k| VertexId(v).half_edge(k)));
        on_the_cut.into_iter().find(|&g| left.store.left(g) == site)
    }
}

/// How many half-edges of `store` lead from a vertex it keeps to one it
/// drops (counted from the dropped vertices' side: the twins of theirs).
fn edges_to_dropped(store: &Store, keep: &[bool]) -> usize {
    let dropped = keep.iter().enumerate().filter(|(_, &k)| !k);
    let into = |(v, _): (usize, &bool)| (0..3).map(move |k| VertexId::from_index(v).half_edge(k));
    dropped.flat_map(into).filter(|&h| keep[store.twin(h).origin().index()]).count()
}

/// Whether finite vertices `v` and `w` are at one place: their positions
/// and clearances within 16 roundings of their size.
fn same_place(store: &Store, v: usize, w: usize) -> bool {
    let (p, q) = (store.position[v], store.position[w]);
    let (r, s) = (store.clearance[v], store.clearance[w]);
    let size = p.x.abs() + p.y.abs() + r;
    let within = 16.0 * f64::EPSILON * size;
    size.is_finite() && (p.x - q.x).abs() <= within && (p.y - q.y).abs() <= within && (r - s).abs() <= within
}

/// A half's edges across the cut (`Renamed::crossing`): on the left from
/// its kept vertices on the cut (`candidates`: its kept vertices with a
/// site of the right), on the right to its dropped vertices with a site
/// of its own (`candidates`). Such an edge separates two sites that both
/// its ends have, so neither is the left's (its right end has none): one
/// is the right's (the other may be the point at infinity), and both its
/// ends have a site of the right.
fn crossing_edges(store: &Store, keep: &[bool], candidates: &[u32], side: Side) -> HashMap<[SiteId; 2], HalfEdgeId> {
    let mut crossing = HashMap::with_capacity(candidates.len());
    for &v in candidates {
        for k in 0..3 {
            // (the half-edge from the kept end)
            let h = match side {
                Side::Left => VertexId(v).half_edge(k),
                Side::Right => store.twin(VertexId(v).half_edge(k)),
            };
            if !keep[h.origin().index()] || keep[store.twin(h).origin().index()] {
                continue;
            }
            let slot = crossing.entry([store.right(h), store.left(h)]).or_insert(h);
            if *slot != h {
                *slot = HalfEdgeId(NONE); // two edges between the same cells: ambiguous
            }
        }
    }
    crossing
}

/// Removes the glued store's vertices not kept (`keep`, per vertex below
/// its length; those after it are all kept), filling each slot with the
/// last kept vertex and relinking its edges and cells.
fn drop_vertices(store: &mut Store, keep: &[bool]) {
    let is_hole = |v: usize| v < keep.len() && !keep[v];
    let mut count = store.vertex_count();
    // Holes in increasing order, each filled with the last vertex kept:
    // that one always lies beyond every hole filled so far. (The holes at
    // the end are passed over, down to the one being filled: those below
    // it are filled already.)
    for hole in (0..keep.len()).filter(|&v| !keep[v]) {
        while count > hole + 1 && is_hole(count - 1) {
            count -= 1;
        }
        if hole + 1 >= count {
            // (this hole is the last slot or beyond it, and so is every other)
            count = count.min(hole);
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

#[cfg(test)]
mod tests {
    use super::*;

    /// `Ranges::owned` without branches answers as the plain comparisons.
    #[test]
    fn owned_ids_are_those_of_the_plain_comparisons() {
        let plain = |r: &Ranges, s: SiteId, side: Side| {
            let left = (s.0 >= 1 && s.0 < r.left_points_end) || (s.0 >= r.first_segment && s.0 < r.left_segments_end);
            let real = s.0 != INFINITE.0 && s.0 != NONE;
            real && (left == (side == Side::Left))
        };
        // (owned counts: left points, right points, left segments, right segments; some empty)
        for (lp, rp, ls, rs) in [(3, 4, 5, 6), (0, 4, 0, 6), (3, 0, 5, 0), (0, 0, 0, 0), (7, 7, 0, 0), (1, 1, 1, 1)] {
            let r = Ranges::of(&Owned { points: lp, segments: ls }, &Owned { points: rp, segments: rs });
            let ids = (0..r.count as u32 + 3).chain([NONE - 1, NONE]);
            for s in ids.map(SiteId) {
                for side in [Side::Left, Side::Right] {
                    assert_eq!(r.owned(s, side), plain(&r, s, side), "{s:?} {side:?} in {lp} {rp} {ls} {rs}");
                }
            }
        }
    }

    /// Dropping vertices keeps exactly the kept ones, with their edges,
    /// sites and cells, wherever the holes are (at the start, between,
    /// at the end, all of them, none).
    #[test]
    fn dropped_vertices_leave_the_kept_ones_linked_as_they_were() {
        let mut rng = crate::splitmix::SplitMix64(11);
        let mut patterns: Vec<Vec<bool>> = vec![
            vec![false, false, true, true],
            vec![true, true, false, false],
            vec![false, true, false, true, false, false],
            vec![false; 6],
            vec![true; 6],
        ];
        for share in [0.03, 0.5, 0.97] {
            patterns.extend((0..20).map(|k| (0..4 + 30 * k).map(|_| rng.unit() > share).collect()));
        }
        for mut keep in patterns {
            // (an even count of kept half-edges, paired among themselves)
            if keep.iter().filter(|&&k| k).count() % 2 == 1 {
                keep.push(true);
            }
            let n = keep.len();
            let mut store = Store::new(3 * n, SiteId(0), n);
            store.right = (0..3 * n as u32).map(SiteId).collect();
            store.position = (0..n).map(|v| Point::new(v as f64, 0.0)).collect();
            store.clearance = (0..n).map(|v| v as f64).collect();
            store.twin = vec![HalfEdgeId(NONE); 3 * n];
            for part in [true, false] {
                let mut ends: Vec<usize> = (0..3 * n).filter(|&h| keep[h / 3] == part).collect();
                // (shuffled, then paired in order: twins from anywhere)
                for i in (1..ends.len()).rev() {
                    ends.swap(i, (rng.next_u64() % (i as u64 + 1)) as usize);
                }
                for pair in ends.chunks_exact(2) {
                    store.link(HalfEdgeId::from_index(pair[0]), HalfEdgeId::from_index(pair[1]));
                }
            }
            for h in (0..3 * n).filter(|&h| keep[h / 3]).map(HalfEdgeId::from_index) {
                let cell = store.left(h).index();
                store.cell_edge[cell] = h.0;
            }
            let before = store.clone();
            drop_vertices(&mut store, &keep);

            // Each vertex left is a kept one (its position says which), once.
            let kept: Vec<usize> = (0..n).filter(|&v| keep[v]).collect();
            let mut old_of: Vec<usize> = store.position.iter().map(|p| p.x as usize).collect();
            assert_eq!(store.vertex_count(), kept.len(), "{keep:?}");
            assert_eq!(store.twin.len(), 3 * kept.len());
            assert_eq!(store.right.len(), 3 * kept.len());
            assert_eq!(store.clearance, old_of.iter().map(|&v| v as f64).collect::<Vec<_>>());
            let old = |h: HalfEdgeId| VertexId::from_index(old_of[h.origin().index()]).half_edge(h.slot());
            for h in (0..store.twin.len()).map(HalfEdgeId::from_index) {
                assert_eq!(store.right(h), before.right(old(h)));
                assert_eq!(old(store.twin(h)), before.twin(old(h)), "{keep:?}");
                assert_eq!(store.cell_edge[store.left(h).index()], h.0);
            }
            old_of.sort_unstable();
            assert_eq!(old_of, kept);
        }
    }
}
