//! Helpers shared by the integration tests: the brute-force geometric
//! checks, and the input generators of testgen/ re-exported.
#![allow(dead_code)]

use segvoronoi::{Builder, Diagram, EdgeEnd, Point};

// The generated inputs live in testgen/ with every other generator of the
// tests, the bench and the CGAL cross-check.
#[allow(unused_imports)] // each test uses some
pub use segvoronoi_testgen::shapes::{polygon, segment_grid, snake, star_ring, uniform, unit_segment_lattice};
#[allow(unused_imports)]
pub use segvoronoi_testgen::Rng;

pub fn build(points: &[[f64; 2]]) -> Diagram {
    let mut b = Builder::new();
    b.add_points(points.iter().copied()).unwrap();
    let d = b.build().unwrap();
    d.validate().unwrap_or_else(|e| panic!("{e}"));
    d
}

/// Every vertex is equidistant from its three sites (within `tol` of the
/// input scale) and no site is closer than those (empty circle), with
/// distances to segment sites measured to the closed segment.
pub fn check_empty_circles(d: &Diagram, tol: f64) {
    let scale = d.extent().max(f64::MIN_POSITIVE);
    for v in d.vertices() {
        let r: Vec<f64> = v.sites.iter().map(|&s| d.site(s).unwrap().distance(v.position)).collect();
        for &ri in &r {
            assert!((ri - v.clearance).abs() <= tol * scale, "vertex {} not equidistant: {r:?} vs {}", v.id, v.clearance);
        }
        for s in d.site_ids() {
            let dist = d.site(s).unwrap().distance(v.position);
            assert!(dist >= v.clearance - tol * scale, "site {s} inside the circle of vertex {}", v.id);
        }
    }
}

/// The site whose cell contains `q`, found by brute force, has `q` within
/// its cell in the diagram too: every edge of the cell keeps `q` on the
/// cell's side of the bisector (checked on all neighbours).
pub fn check_nearest_sites(d: &Diagram, queries: &[Point], tol: f64) {
    let scale = d.extent().max(f64::MIN_POSITIVE);
    if d.site_count() == 0 {
        return;
    }
    for &q in queries {
        let best = d.site_ids().map(|s| d.site(s).unwrap().distance(q)).fold(f64::INFINITY, f64::min);
        // the brute-force nearest sites (ties allowed)
        let nearest: Vec<_> = d.site_ids().filter(|&s| d.site(s).unwrap().distance(q) <= best + tol * scale).collect();
        // q lies in the cell of s iff no Voronoi neighbour of s is closer
        let inside = nearest.iter().any(|&s| {
            d.cell(s).unwrap().neighbors().all(|n| d.site(n).unwrap().distance(q) >= d.site(s).unwrap().distance(q) - tol * scale)
        });
        assert!(inside, "query {q:?}: no nearest site {nearest:?} has it in its cell");
    }
}

/// Number of rays (edges with one end at infinity).
pub fn ray_count(d: &Diagram) -> usize {
    d.edges()
        .filter(|e| {
            matches!(e.ends, [EdgeEnd::Vertex(_), EdgeEnd::Infinite { .. }] | [EdgeEnd::Infinite { .. }, EdgeEnd::Vertex(_)])
        })
        .count()
}

/// The diagram of points and segments, validated.
pub fn build_sites(points: &[[f64; 2]], segments: &[[[f64; 2]; 2]]) -> Diagram {
    let mut b = Builder::new();
    b.add_points(points.iter().copied()).unwrap();
    b.add_segments(segments.iter().copied()).unwrap();
    let d = b.build().unwrap_or_else(|e| panic!("{e}"));
    d.validate().unwrap_or_else(|e| panic!("{e}"));
    d
}

/// Whether an edge is longer than 1e-9 of the diagram's extent (rays and
/// lines always are): the edges every valid answer on degenerate input
/// shares.
pub fn has_positive_length(d: &Diagram, e: &segvoronoi::Edge) -> bool {
    match e.ends {
        [EdgeEnd::Vertex(a), EdgeEnd::Vertex(b)] => {
            d.vertex(a).unwrap().position.distance(d.vertex(b).unwrap().position) > 1e-9 * d.extent()
        }
        _ => true,
    }
}

/// `check_empty_circles` with a tolerance per vertex of `tol` times the
/// larger of the input extent and the vertex's clearance: far-away vertices
/// (nearly parallel or collinear segments put them 1e15 times the extent
/// out) carry the rounding of their own magnitude, and vertices of three
/// segments come from double-precision solvers whose error grows with the
/// conditioning. Still fails on a site inside a circle by more than that,
/// i.e. on a wrong topology, and on a vertex far from its sites.
pub fn check_empty_circles_relative(d: &Diagram, tol: f64) {
    let extent = d.extent().max(f64::MIN_POSITIVE);
    // A vertex beyond the range of f64 (infinite clearance, saturated
    // position) cannot be checked in f64; the library's own audit
    // (`every_small_fixture_passes_the_audit`) checks it in big floats.
    for v in d.vertices().filter(|v| v.clearance.is_finite()) {
        let slack = tol * extent.max(v.clearance);
        let r: Vec<f64> = v.sites.iter().map(|&s| d.site(s).unwrap().distance(v.position)).collect();
        for &ri in &r {
            assert!((ri - v.clearance).abs() <= slack, "vertex {} not equidistant: {r:?} vs {}", v.id, v.clearance);
        }
        for s in d.site_ids() {
            let dist = d.site(s).unwrap().distance(v.position);
            assert!(
                dist >= v.clearance - slack,
                "site {s} inside the circle of vertex {} (sites {:?}) by {:e} (clearance {:e})",
                v.id,
                v.sites,
                v.clearance - dist,
                v.clearance
            );
        }
    }
}

/// A plain even-odd test of `p` against closed rings, in floating point:
/// the reference for inputs where no tested point is near a ring.
pub fn even_odd(rings: &[Vec<[f64; 2]>], p: Point) -> bool {
    let mut inside = false;
    for ring in rings {
        for k in 0..ring.len() {
            let ([ax, ay], [bx, by]) = (ring[k], ring[(k + 1) % ring.len()]);
            if (ay > p.y) != (by > p.y) && p.x < ax + (p.y - ay) * (bx - ax) / (by - ay) {
                inside = !inside;
            }
        }
    }
    inside
}

/// The segments of closed rings, as sites.
pub fn ring_segments(rings: &[Vec<[f64; 2]>]) -> Vec<segvoronoi::Site> {
    rings
        .iter()
        .flat_map(|r| {
            (0..r.len()).map(move |k| {
                let (a, b) = (r[k], r[(k + 1) % r.len()]);
                segvoronoi::Site::Segment { a: Point::new(a[0], a[1]), b: Point::new(b[0], b[1]) }
            })
        })
        .collect()
}

/// Vertices, edges and connected components of the medial axis as a graph:
/// every finite piece an edge between its two vertices (pieces reaching
/// infinity are left out).
pub fn axis_graph(axis: &segvoronoi::MedialAxis) -> (usize, usize, usize) {
    let mut index = std::collections::HashMap::new();
    let mut edges = Vec::new();
    for piece in axis.chains.iter().flat_map(|c| &c.pieces) {
        let [EdgeEnd::Vertex(a), EdgeEnd::Vertex(b)] = piece.ends else { continue };
        let ids = [a, b].map(|v| {
            let next = index.len();
            *index.entry(v).or_insert(next)
        });
        edges.push(ids);
    }
    let mut parent: Vec<usize> = (0..index.len()).collect();
    fn root(parent: &mut [usize], mut v: usize) -> usize {
        while parent[v] != v {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        v
    }
    let mut components = index.len();
    for &[a, b] in &edges {
        let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
        if ra != rb {
            parent[ra] = rb;
            components -= 1;
        }
    }
    (index.len(), edges.len(), components)
}
