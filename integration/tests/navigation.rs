//! Half-edge navigation and edge kinds through the public API
//! (`Diagram::half_edges`, `next_half_edge`, `prev_half_edge`,
//! `vertex_half_edges`, `cell_half_edges`, `is_separator`), on random,
//! degenerate and collinear inputs: every walk is checked against the
//! edges' own ends and sites, so a navigation that skipped, repeated or
//! mis-oriented an edge fails. (Their C counterparts:
//! `capi/tests/navigation.rs`.)

mod common;

use common::{build_sites, polygon, segment_grid, uniform, unit_segment_lattice};
use segvoronoi::{Diagram, EdgeEnd, HalfEdge, Site, SiteId, VertexId};

/// The two ends compare as vertices; ends at infinity only by kind.
fn same_vertex(a: EdgeEnd, b: EdgeEnd) -> bool {
    match (a, b) {
        (EdgeEnd::Vertex(u), EdgeEnd::Vertex(v)) => u == v,
        _ => false,
    }
}

fn check_navigation(d: &Diagram) {
    d.validate().expect("a valid diagram");
    let mut seen = vec![0usize; 2 * d.edge_count()];
    for e in d.edges() {
        let [h, t] = d.half_edges(e.id).unwrap();
        assert_eq!((h.edge(), t.edge()), (e.id, e.id));
        assert!(!h.is_reversed() && t.is_reversed());
        assert_eq!(h.twin(), t);
        assert_eq!(d.half_edge_cell(h), Some(e.sites[0]));
        assert_eq!(d.half_edge_cell(t), Some(e.sites[1]));
        assert_eq!(d.half_edge_origin(h), Some(e.ends[0]));
        assert_eq!(d.half_edge_target(h), Some(e.ends[1]));
        assert_eq!(d.half_edge_origin(t), Some(e.ends[1]));
        for x in [h, t] {
            let n = d.next_half_edge(x).unwrap();
            let p = d.prev_half_edge(x).unwrap();
            assert_eq!(d.prev_half_edge(n), Some(x), "prev(next(h)) = h");
            assert_eq!(d.next_half_edge(p), Some(x), "next(prev(h)) = h");
            assert_eq!(d.half_edge_cell(n), d.half_edge_cell(x), "next stays around one cell");
            let (target, next_origin) = (d.half_edge_target(x).unwrap(), d.half_edge_origin(n).unwrap());
            match target {
                // a finite end is where the next edge starts
                EdgeEnd::Vertex(_) => assert!(same_vertex(target, next_origin)),
                // past infinity the next edge comes back from infinity
                EdgeEnd::Infinite { .. } => assert!(matches!(next_origin, EdgeEnd::Infinite { .. })),
            }
        }
    }
    // Around each cell: the walk by `next` is the cell's boundary, each
    // half-edge once, in the order of `Cell::edges`.
    for site in (0..d.site_count()).map(SiteId::from_index) {
        let around: Vec<HalfEdge> = d.cell_half_edges(site).collect();
        let edges: Vec<_> = d.cell(site).unwrap().edges().collect();
        assert_eq!(around.iter().map(|h| h.edge()).collect::<Vec<_>>(), edges);
        for (k, &h) in around.iter().enumerate() {
            assert_eq!(d.half_edge_cell(h), Some(site));
            assert_eq!(d.next_half_edge(h), Some(around[(k + 1) % around.len()]));
            seen[h.index()] += 1;
        }
    }
    assert!(seen.iter().all(|&n| n == 1), "every half-edge bounds exactly one cell walk");
    for v in d.vertices() {
        let out = d.vertex_half_edges(v.id).unwrap();
        for (k, &h) in out.iter().enumerate() {
            assert!(same_vertex(d.half_edge_origin(h).unwrap(), EdgeEnd::Vertex(v.id)));
            assert_eq!(d.half_edge_cell(h), Some(v.sites[(k + 1) % 3]));
        }
    }
    assert_eq!(d.vertex_half_edges(VertexId::from_index(d.vertex_count())), None);
    // Separators: exactly one between each segment and each of its ends.
    let segments = d.site_count() - d.point_site_count();
    let separators: Vec<_> = d.edges().filter(|e| d.is_separator(e.id).unwrap()).collect();
    assert_eq!(separators.len(), 2 * segments);
    for e in separators {
        let [a, b] = e.sites.map(|s| d.site(s).unwrap());
        let (segment, point) =
            if matches!(a, Site::Segment { .. }) { (e.sites[0], e.sites[1]) } else { (e.sites[1], e.sites[0]) };
        assert!(d.segment_endpoints(segment).unwrap().contains(&point), "{a:?} {b:?}");
    }
}

#[test]
fn navigation_is_consistent_on_random_points_and_segments() {
    for seed in 0..20 {
        check_navigation(&build_sites(&uniform(40 + seed as usize, seed), &[]));
        let (points, segments) = segment_grid(6, seed, 0.6);
        check_navigation(&build_sites(&points, &segments));
    }
}

#[test]
fn navigation_is_consistent_on_degenerate_inputs() {
    // a grid of points (cocircular fours), a lattice of unit segments
    // sharing endpoints, a regular polygon (cocircular), collinear points
    // (a ladder of lines), two sites, one site
    let grid: Vec<[f64; 2]> = (0..36).map(|k| [(k % 6) as f64, (k / 6) as f64]).collect();
    check_navigation(&build_sites(&grid, &[]));
    check_navigation(&build_sites(&[], &unit_segment_lattice(4)));
    check_navigation(&build_sites(&[[0.0, 0.0]], &polygon(12, 5.0, 0.0, 0.0)));
    let line: Vec<[f64; 2]> = (0..7).map(|k| [k as f64, 2.0 * k as f64]).collect();
    check_navigation(&build_sites(&line, &[]));
    check_navigation(&build_sites(&[], &[[[0.0, 0.0], [1.0, 0.0]], [[2.0, 0.0], [3.0, 0.0]]]));
    check_navigation(&build_sites(&[[1.0, 1.0], [2.0, 3.0]], &[]));
    check_navigation(&build_sites(&[[1.0, 1.0]], &[]));
}

#[test]
fn out_of_range_ids_give_none() {
    let d = build_sites(&uniform(10, 3), &[]);
    let past = HalfEdge::from_index(2 * d.edge_count());
    assert_eq!(d.half_edge_cell(past), None);
    assert_eq!(d.next_half_edge(past), None);
    assert_eq!(d.prev_half_edge(past), None);
    assert_eq!(d.half_edge_origin(past), None);
    assert_eq!(d.half_edges(segvoronoi::EdgeId::from_index(d.edge_count())), None);
    assert_eq!(d.cell_half_edges(SiteId::from_index(d.site_count())).count(), 0);
    assert_eq!(d.is_separator(segvoronoi::EdgeId::from_index(d.edge_count())), None);
}
