//! From the construction's internal numbering to the public one: sites in
//! order of first appearance in the input, finite vertices first, positions
//! back in input coordinates, and the dense list of public edges.

use super::points::{Parts, PointDiagram, INFINITE};
use crate::diagram::{BuildStats, Diagram, HalfEdgeId, SiteId, VertexId, NONE};
use crate::geometry::scale::Scale;
use crate::geometry::Point;

pub(super) fn finish(built: PointDiagram, site_of_input: &[SiteId], input: &[Point], scale: Scale) -> Diagram {
    let Parts { mut store, sites: internal_sites } = built.into_parts();

    // Public site ids: order of first appearance in the input.
    let mut public_of = vec![NONE; internal_sites.len()];
    let mut sites: Vec<Point> = Vec::with_capacity(internal_sites.len().saturating_sub(1));
    let mut input_site = Vec::with_capacity(input.len());
    for (i, s) in site_of_input.iter().enumerate() {
        let slot = &mut public_of[s.index()];
        if *slot == NONE {
            *slot = sites.len() as u32;
            sites.push(input[i].canonical_zero());
        }
        input_site.push(SiteId(*slot));
    }
    let infinite = SiteId(sites.len() as u32);
    public_of[INFINITE.index()] = infinite.0;
    for r in store.right.iter_mut() {
        *r = SiteId(public_of[r.index()]);
    }
    let mut cell_edge = vec![NONE; internal_sites.len()];
    for (internal, &e) in store.cell_edge.iter().enumerate() {
        cell_edge[public_of[internal] as usize] = e;
    }
    store.cell_edge = cell_edge;
    store.infinite_site = infinite;

    // Vertices at infinity to the end (there are only as many as hull edges).
    let mut end = store.vertex_count();
    let mut v = 0;
    while v < end {
        if store.is_at_infinity(VertexId::from_index(v)) {
            end -= 1;
            while end > v && store.is_at_infinity(VertexId::from_index(end)) {
                end -= 1;
            }
            store.swap_vertices(VertexId::from_index(v), VertexId::from_index(end));
        }
        v += 1;
    }
    let finite_vertices = (0..store.vertex_count())
        .find(|&v| store.is_at_infinity(VertexId::from_index(v)))
        .unwrap_or(store.vertex_count());

    if !scale.is_identity() {
        for v in 0..finite_vertices {
            store.position[v] = store.position[v].scaled(scale.to_input);
            store.clearance[v] *= scale.to_input;
        }
    }

    // Public edges: one per pair of twins, between two real sites.
    let mut edges = Vec::with_capacity(store.twin.len() / 2);
    for h in (0..store.twin.len()).map(HalfEdgeId::from_index) {
        let t = store.twin(h);
        if h < t && store.left(h) != infinite && store.right(h) != infinite {
            edges.push(h);
        }
    }

    let extent = bounding_box_diagonal(&sites);
    let stats = BuildStats {
        input_points: input.len(),
        sites: sites.len(),
        duplicate_points: input.len() - sites.len(),
        vertices: finite_vertices,
        edges: edges.len(),
    };
    let diagram = Diagram { store, sites, finite_vertices, edges, edge_of_half_edge: Default::default(), input_site, stats, extent, scale };
    debug_assert_eq!(diagram.validate(), Ok(()));
    diagram
}

fn bounding_box_diagonal(points: &[Point]) -> f64 {
    let Some(&first) = points.first() else { return 0.0 };
    let (mut lo, mut hi) = (first, first);
    for p in points {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    // halve first so that the extent of huge inputs does not overflow
    let (dx, dy) = (hi.x / 2.0 - lo.x / 2.0, hi.y / 2.0 - lo.y / 2.0);
    2.0 * dx.hypot(dy)
}
