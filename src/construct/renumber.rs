//! From the construction's internal numbering to the public one: sites in
//! order of first appearance in the input, finite vertices first, positions
//! back in input coordinates, and the dense list of public edges.

use super::input_check::CheckedInput;
use super::state::{Construction, Parts, INFINITE};
use super::threads::run_beside;
use crate::diagram::{BuildStats, Diagram, HalfEdgeId, SiteId, SiteTable, VertexId, NONE};
use crate::geometry::point::bounding_box;
use crate::geometry::scale::Scale;
use crate::geometry::Point;

/// From this many vertices on, the renaming of the cells and the list of
/// edges run on two threads by halves (when the build may start one):
/// below, starting a thread costs more than it saves.
const PARALLEL_FROM: usize = 1 << 17;

/// The segment sites for the renumbering, in public order: each one's
/// internal id, and (asked of `input_and_ends` by position) its input
/// index and its endpoints in input coordinates. Asked, not gathered: a
/// million segments' copies took 48 MB and 20 ms.
pub(super) struct SegmentSites<'a> {
    pub internal: &'a [SiteId],
    pub input_and_ends: &'a (dyn Fn(usize) -> (usize, [Point; 2]) + Sync),
}

impl SegmentSites<'_> {
    /// No segment (a build of points).
    pub(super) const NONE: SegmentSites<'static> =
        SegmentSites { internal: &[], input_and_ends: &|_| (0, [Point::new(0.0, 0.0); 2]) };
}

/// An arc site for the renumbering: its input index, its internal id and
/// the arc in input coordinates.
pub(super) struct ArcSite {
    pub input: usize,
    pub internal: SiteId,
    pub arc: crate::geometry::CircularArc,
}

/// Renumbers `built` to public ids: point sites by first appearance in
/// `input` (whose `i`-th point became internal site `site_of_input[i]`),
/// then `segments` in the order given. The diagram's per-input maps are
/// left for the caller (`input_site` holds all of `input`).
pub(super) fn renumber(
    built: Construction,
    site_of_input: &[SiteId],
    input: &[Point],
    segments: SegmentSites<'_>,
    arcs: &[ArcSite],
    scale: Scale,
) -> Diagram {
    let Parts { mut store, sites: internal_sites, segment_ends: internal_ends } = built.into_parts();
    let first_internal_segment = internal_sites.len() - internal_ends.len();

    // Public site ids: points in order of first appearance in the input,
    // then the segments, then the arcs. Naming the points and naming the
    // segments touch disjoint parts of `public_of` (internal point ids
    // come before the segments'), so large builds name them on two
    // threads: the segments from 0, moved after the points once those are
    // counted.
    let large = store.vertex_count() >= PARALLEL_FROM;
    let mut public_of = vec![NONE; internal_sites.len()];
    let (point_ids, segment_ids) = public_of.split_at_mut(first_internal_segment);
    // Where every input point has a site of its own (no repeats: most
    // builds of points, and of disjoint segments), a point's public id is
    // its input index: the site table and the map are the input's
    // (`own_sites`), made beside the filling of `public_of` or after it.
    // (As many sites as inputs, none met twice: then each site has
    // exactly one input.)
    let distinct = point_ids.len() == site_of_input.len() + 1;
    let mut name_points = || {
        if distinct {
            let mut repeats = false;
            for (i, s) in site_of_input.iter().enumerate() {
                let slot = &mut point_ids[s.index()];
                repeats |= *slot != NONE;
                *slot = i as u32;
            }
            if !repeats {
                return None;
            }
            point_ids.fill(NONE);
        }
        let mut points = Vec::with_capacity(site_of_input.len().min(point_ids.len()));
        let mut input_site = Vec::with_capacity(input.len());
        for (i, s) in site_of_input.iter().enumerate() {
            let slot = &mut point_ids[s.index()];
            if *slot == NONE {
                *slot = points.len() as u32;
                points.push(input[i].canonical_zero());
            }
            input_site.push(SiteId(*slot));
        }
        Some((points, input_site))
    };
    let own_sites = || {
        if !distinct {
            return (Vec::new(), Vec::new());
        }
        let points: Vec<Point> = input.iter().map(|p| p.canonical_zero()).collect();
        (points, (0..input.len() as u32).map(SiteId).collect::<Vec<_>>())
    };
    let mut name_segments = || {
        let internals = segments.internal.iter().copied().chain(arcs.iter().map(|arc| arc.internal));
        for (k, internal) in internals.enumerate() {
            segment_ids[internal.index() - first_internal_segment] = k as u32;
        }
        let (ends, segment_input): (Vec<[Point; 2]>, Vec<u32>) = (0..segments.internal.len())
            .map(|k| {
                let (input, ends) = (segments.input_and_ends)(k);
                (ends.map(Point::canonical_zero), input as u32)
            })
            .unzip();
        let arc_input = arcs.iter().map(|arc| arc.input as u32).collect::<Vec<_>>();
        (ends, segment_input, arc_input)
    };
    // (the input's own tables beside the map, or after it where the
    // other thread names segments: whichever side has less to do)
    let own_beside = segments.internal.is_empty() && arcs.is_empty();
    let here = move || match name_points() {
        None if !own_beside => Some(own_sites()),
        named => named,
    };
    let (((segment_sites, segment_input, arc_input), own), named) =
        beside_if(large, move || (name_segments(), own_beside.then(own_sites)), here);
    let (point_sites, input_site) = named.or(own).unwrap_or_default();
    let point_count = point_sites.len() as u32;
    segment_ids.iter_mut().filter(|id| **id != NONE).for_each(|id| *id += point_count);
    let sites = SiteTable::from_parts(point_sites, segment_sites, arcs.iter().map(|arc| arc.arc).collect());
    let point_sites = point_count as usize;
    let internals = segments.internal.iter().copied().chain(arcs.iter().map(|arc| arc.internal));
    let segment_ends: Vec<[SiteId; 2]> = internals
        .map(|internal| internal_ends[internal.index() - first_internal_segment].map(|e| SiteId(public_of[e.index()])))
        .collect();
    let infinite = SiteId(sites.len() as u32);
    public_of[INFINITE.index()] = infinite.0;
    // (large stores on two threads, by halves, when the build may start one)
    let half = store.right.len() / 2;
    let (low, high) = store.right.split_at_mut(half);
    let rename = |part: &mut [SiteId]| part.iter_mut().for_each(|r| *r = SiteId(public_of[r.index()]));
    beside_if(large, || rename(high), || rename(low));
    let mut cell_edge = vec![NONE; internal_sites.len()];
    for (internal, &e) in store.cell_edge.iter().enumerate() {
        cell_edge[public_of[internal] as usize] = e;
    }
    store.cell_edge = cell_edge;
    store.infinite_site = infinite;

    // Vertices at infinity to the end (there are only as many as hull
    // edges): each one below the finite count, in increasing order, swaps
    // with the last finite vertex not yet swapped. Finding them reads every
    // vertex, on two threads for large stores.
    let count = store.vertex_count();
    let at_infinity = |range: std::ops::Range<usize>| -> Vec<usize> {
        range.filter(|&v| store.is_at_infinity(VertexId::from_index(v))).collect()
    };
    let (high, mut at_infinity_ids) = beside_if(large, || at_infinity(count / 2..count), || at_infinity(0..count / 2));
    at_infinity_ids.extend_from_slice(&high);
    let finite_vertices = count - at_infinity_ids.len();
    let mut last = count;
    for &v in at_infinity_ids.iter().take_while(|&&v| v < finite_vertices) {
        last -= 1;
        while store.is_at_infinity(VertexId::from_index(last)) {
            last -= 1;
        }
        store.swap_vertices(VertexId::from_index(v), VertexId::from_index(last));
    }

    // (large stores on two threads, by halves)
    let (positions, clearances) = (&mut store.position[..finite_vertices], &mut store.clearance[..finite_vertices]);
    let (low_positions, high_positions) = positions.split_at_mut(finite_vertices / 2);
    let (low_clearances, high_clearances) = clearances.split_at_mut(finite_vertices / 2);
    beside_if(large, || to_input(high_positions, high_clearances, scale), || to_input(low_positions, low_clearances, scale));

    // Public edges: one per pair of twins, between two real sites.
    // (`room`: the edges to make room for, the whole list's in the low
    // half's, which the high half's are appended to)
    let edges_in = |vertices: std::ops::Range<usize>, room: usize| -> Vec<HalfEdgeId> {
        let mut edges = Vec::with_capacity(room);
        // (a vertex's three half-edges at once, gathered without a branch
        // into a short buffer: whether a half-edge comes before its twin is
        // a coin toss, which a branch per half-edge would mispredict)
        const BATCH: usize = 32;
        let mut batch = [HalfEdgeId(NONE); 3 * BATCH];
        let (right, twin) =
            (&store.right[3 * vertices.start..3 * vertices.end], &store.twin[3 * vertices.start..3 * vertices.end]);
        let first = 3 * vertices.start;
        for (chunk, (right, twin)) in right.chunks(3 * BATCH).zip(twin.chunks(3 * BATCH)).enumerate() {
            let mut n = 0;
            for (v, (r, t)) in right.chunks_exact(3).zip(twin.chunks_exact(3)).enumerate() {
                let real = [r[0] != infinite, r[1] != infinite, r[2] != infinite];
                for k in 0..3 {
                    let h = HalfEdgeId((first + 3 * (chunk * BATCH + v) + k) as u32);
                    batch[n] = h;
                    // (the edge's left is the vertex's next cell)
                    n += usize::from((h < t[k]) & real[k] & real[(k + 1) % 3]);
                }
            }
            edges.extend_from_slice(&batch[..n]);
        }
        edges
    };
    let vertices = store.vertex_count();
    let (high, mut edges) = beside_if(
        large,
        || edges_in(vertices / 2..vertices, 3 * (vertices - vertices / 2) / 2),
        || edges_in(0..vertices / 2, 3 * vertices / 2),
    );
    edges.extend_from_slice(&high);

    let extent = bounding_box_diagonal(sites.points());
    let stats = BuildStats {
        input_points: input.len(),
        input_segments: 0,
        sites: sites.len(),
        duplicate_points: input.len() - point_sites,
        duplicate_segments: 0,
        zero_length_segments: 0,
        vertices: finite_vertices,
        edges: edges.len(),
        dropped_chain_points: 0,
        ..BuildStats::default()
    };
    Diagram {
        store,
        sites,
        point_sites,
        segment_input,
        segment_ends,
        segment_site: Vec::new(),
        arc_sites: arcs.len(),
        arc_input,
        arc_site: Vec::new(),
        finite_vertices,
        edges,
        edge_of_half_edge: Default::default(),
        input_site,
        stats,
        extent,
        scale,
        domain: None,
        split: None,
        split_arcs: None,
    }
}

/// `run_beside(beside, here)` when `parallel` (a large store), else both
/// here, one after the other: below [`PARALLEL_FROM`] starting a thread
/// costs more than it saves.
fn beside_if<A: Send, B>(parallel: bool, beside: impl FnOnce() -> A + Send, here: impl FnOnce() -> B) -> (A, B) {
    if parallel {
        run_beside(beside, here)
    } else {
        let b = here();
        (beside(), b)
    }
}

/// Finite vertices' positions and clearances back in input coordinates.
fn to_input(positions: &mut [Point], clearances: &mut [f64], scale: Scale) {
    for (position, clearance) in positions.iter_mut().zip(clearances) {
        // A vertex beyond the range of f64 keeps its coordinates saturated
        // at ±f64::MAX (internally too); one within it may still leave it when
        // scaled back (an input near f64::MAX scaled down), or have
        // overflowed on the way (an internal coordinate of ±∞), and
        // saturates the same way, with an infinite clearance.
        let p = *position;
        if scale.is_identity() && p.x.is_finite() && p.y.is_finite() {
            continue;
        }
        let unscaled = |x: f64| if x.abs() == f64::MAX { x } else { (x * scale.to_input).clamp(-f64::MAX, f64::MAX) };
        let q = Point::new(unscaled(p.x), unscaled(p.y));
        *position = q;
        *clearance *= scale.to_input;
        if clearance.is_nan() && (q.x.abs() == f64::MAX || q.y.abs() == f64::MAX) {
            *clearance = f64::INFINITY;
        }
    }
}

/// The diagonal of the points' bounding box (0 for none); large sets on
/// two threads, by halves.
fn bounding_box_diagonal(point_sites: &[Point]) -> f64 {
    let bounds = |part: &[Point]| bounding_box(part.iter().copied());
    let (low, high) = point_sites.split_at(point_sites.len() / 2);
    let ((lo_high, hi_high), (lo, hi)) = beside_if(point_sites.len() >= PARALLEL_FROM, || bounds(high), || bounds(low));
    if point_sites.is_empty() {
        return 0.0;
    }
    let (lo, hi) = (Point::new(lo.x.min(lo_high.x), lo.y.min(lo_high.y)), Point::new(hi.x.max(hi_high.x), hi.y.max(hi_high.y)));
    // halve first so that the extent of huge inputs does not overflow;
    // a diagonal beyond f64 (a box from -f64::MAX to f64::MAX) saturates
    let (dx, dy) = (hi.x / 2.0 - lo.x / 2.0, hi.y / 2.0 - lo.y / 2.0);
    (2.0 * dx.hypot(dy)).min(f64::MAX)
}

/// The per-input maps and statistics of a build with segments, after
/// [`renumber`] (whose `input` was the `points` isolated points followed by
/// each of the `segments` input segments' two endpoints).
pub(super) fn number_segment_inputs(diagram: &mut Diagram, checked: &CheckedInput, points: usize, segments: usize) {
    // Per input segment, its site: a kept one its own, a repeat the first
    // one's, a zero-length one the point it became.
    let first_segment_site = diagram.point_sites;
    diagram.segment_site = checked
        .kept_of_input
        .iter()
        .enumerate()
        .map(|(j, kept)| match *kept {
            Some(k) => SiteId::from_index(first_segment_site + k),
            None => diagram.input_site[super::endpoint_index(points, j)[0]],
        })
        .collect();
    diagram.input_site.truncate(points);
    diagram.stats.input_points = points;
    diagram.stats.input_segments = segments;
    diagram.stats.pieces = segments;
    diagram.stats.duplicate_points = checked.duplicate_points;
    diagram.stats.duplicate_segments = checked.duplicate_segments;
    diagram.stats.zero_length_segments = checked.degenerate_segments;
}
