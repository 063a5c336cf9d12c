//! Helpers shared by the integration tests: the brute-force geometric
//! checks, and the input generators of testgen/ re-exported.
#![allow(dead_code)]

pub mod arc_inputs;
pub mod curved_rings;

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
/// input scale, or of its clearance where that is larger: a vertex of
/// nearly collinear points lies far out, where the distances themselves
/// round by more than the input's scale) and no site is closer than those
/// (empty circle), with distances to segment sites measured to the closed
/// segment.
pub fn check_empty_circles(d: &Diagram, tol: f64) {
    let scale = d.extent().max(f64::MIN_POSITIVE);
    for v in d.vertices() {
        let within = tol * scale.max(v.clearance);
        let r: Vec<f64> = v.sites.iter().map(|&s| d.site(s).unwrap().distance(v.position)).collect();
        for &ri in &r {
            assert!((ri - v.clearance).abs() <= within, "vertex {} not equidistant: {r:?} vs {}", v.id, v.clearance);
        }
        for s in d.site_ids() {
            let dist = d.site(s).unwrap().distance(v.position);
            assert!(dist >= v.clearance - within, "site {s} inside the circle of vertex {}", v.id);
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

/// An input segment, `[[x0, y0], [x1, y1]]`.
pub type Segment = [[f64; 2]; 2];

/// The distance from `q` to the closed segment (computed in units of the
/// largest difference, so that 1e-200 does not underflow).
pub fn distance_to_segment(q: Point, [a, b]: Segment) -> f64 {
    let unit = (b[0] - a[0]).abs().max((b[1] - a[1]).abs()).max((q.x - a[0]).abs()).max((q.y - a[1]).abs());
    if unit == 0.0 {
        return 0.0;
    }
    let (dx, dy) = ((b[0] - a[0]) / unit, (b[1] - a[1]) / unit);
    let (qx, qy) = ((q.x - a[0]) / unit, (q.y - a[1]) / unit);
    let len2 = dx * dx + dy * dy;
    let t = if len2 == 0.0 { 0.0 } else { ((qx * dx + qy * dy) / len2).clamp(0.0, 1.0) };
    unit * (qx - t * dx).hypot(qy - t * dy)
}

pub fn piece_distance(q: Point, [a, b]: [Point; 2]) -> f64 {
    distance_to_segment(q, [[a.x, a.y], [b.x, b.y]])
}

/// The guarantees of splitting mode on a diagram built from `segments`
/// with `split_crossings`, checked by brute force per piece against its own
/// inputs: the diagram is valid; the pieces, given to a new builder, pass
/// the strict check; the piece map is consistent both ways; every piece
/// lies within `max_split_displacement()` of each input segment it came
/// from, and that within the stated bound (a pixel's half-diagonal per
/// snap round); every input longer than twice the bound is covered by its
/// pieces up to the bound (21 samples along it), but where an even number
/// of inputs lie and ring pieces cancelled.
pub fn check_pieces(d: &Diagram, segments: &[Segment]) {
    d.validate().unwrap_or_else(|e| panic!("{e}"));
    let stats = d.stats();
    assert_eq!(stats.input_segments, segments.len());
    assert_eq!(stats.pieces, d.piece_count());
    check_pieces_are_strict(d);
    let extent = segments.iter().flatten().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    let slack = 1e-13 * extent;
    let bound = stats.snap_rounds as f64 * d.split_pixel_size() * std::f64::consts::FRAC_1_SQRT_2;
    assert!(d.max_split_displacement() <= bound * (1.0 + 1e-9) + slack, "{} > {bound}", d.max_split_displacement());
    let reach = d.max_split_displacement() * (1.0 + 1e-9) + slack;
    for (i, &s) in segments.iter().enumerate() {
        let pieces: Vec<usize> = d.pieces_of_input(i).collect();
        assert!(pieces.windows(2).all(|w| w[0] < w[1]));
        for &p in &pieces {
            assert!(d.inputs_of_piece(p).any(|j| j == i), "piece {p} of {i} does not name it");
            let ends = d.piece(p).unwrap();
            for q in ends {
                let off = distance_to_segment(q, s);
                assert!(off <= reach, "piece {p} is {off} from input {i} (reported {})", d.max_split_displacement());
            }
        }
        // covered: every point of the input is near one of its pieces
        let length = (s[1][0] - s[0][0]).hypot(s[1][1] - s[0][1]);
        if length <= 2.0 * bound + slack {
            continue;
        }
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            let q = Point::new(s[0][0] + t * (s[1][0] - s[0][0]), s[0][1] + t * (s[1][1] - s[0][1]));
            let near = pieces.iter().map(|&p| piece_distance(q, d.piece(p).unwrap())).fold(f64::INFINITY, f64::min);
            // (where an even number of inputs lie along each other, rings'
            // copies cancel: even-odd, and their piece is dropped)
            let along = |o: &Segment| {
                let (u, v) = ([s[1][0] - s[0][0], s[1][1] - s[0][1]], [o[1][0] - o[0][0], o[1][1] - o[0][1]]);
                (u[0] * v[1] - u[1] * v[0]).abs() <= 1e-9 * u[0].hypot(u[1]) * v[0].hypot(v[1])
            };
            let copies = segments.iter().filter(|&o| along(o) && distance_to_segment(q, *o) <= bound + slack).count();
            let cancelled = stats.cancelled_ring_pieces > 0 && copies % 2 == 0;
            assert!(near <= bound + slack || cancelled, "input {i} not covered at {q:?} ({near} > {bound})");
        }
    }
    for p in 0..d.piece_count() {
        assert!(d.inputs_of_piece(p).len() >= 1);
        for i in d.inputs_of_piece(p) {
            assert!(d.pieces_of_input(i).any(|q| q == p));
        }
    }
}

/// The pieces as a new input pass the strict check: each distinct piece
/// once (a piece may repeat an earlier one, see `Diagram::piece`), a piece
/// of zero length as a point, with the diagram's point sites (the isolated
/// points among them must not lie on a piece either).
fn check_pieces_are_strict(d: &Diagram) {
    let mut seen = std::collections::HashSet::new();
    let mut b = Builder::new();
    for s in d.site_ids() {
        if let segvoronoi::Site::Point(p) = d.site(s).unwrap() {
            b.add_point(p).unwrap();
        }
    }
    for p in 0..d.piece_count() {
        let [u, v] = d.piece(p).unwrap();
        let key = if (u.x, u.y) <= (v.x, v.y) { [u, v] } else { [v, u] }.map(|q| (q.x.to_bits(), q.y.to_bits()));
        if !seen.insert(key) {
            continue;
        }
        if u == v {
            b.add_point(u).unwrap();
        } else {
            b.add_segment([u, v]).unwrap();
        }
    }
    b.check().unwrap_or_else(|e| panic!("the pieces do not pass the strict check: {e}"));
}

/// The rings with about `share` of their edges cut at one to three points
/// exactly on them (straight vertices), each then moved one ulp off the
/// line when `nudge` (nearly straight), after snapping to the grid that
/// makes such points exact (testgen's `straight` transform); `share` 0 gives
/// the snapped rings alone, the same domain as every cut of them.
pub fn cut_rings(rings: &[Vec<[f64; 2]>], share: f64, nudge: bool, seed: u64) -> Vec<Vec<[f64; 2]>> {
    use segvoronoi_testgen::straight::{cut_rings, variant_rng, Straight};
    let straight = Straight { share, min_cuts: 1, max_cuts: 3, nudge, snap_bits: 36 };
    cut_rings(rings, &straight, &mut variant_rng(seed))
}

/// Sets this thread's restart budget for as long as it lives.
#[cfg(feature = "fault-injection")]
pub struct RestartBudget;

#[cfg(feature = "fault-injection")]
impl RestartBudget {
    pub fn set(restarts: usize) -> RestartBudget {
        segvoronoi::fault_injection::set_restart_budget(restarts);
        RestartBudget
    }
}

#[cfg(feature = "fault-injection")]
impl Drop for RestartBudget {
    fn drop(&mut self) {
        segvoronoi::fault_injection::set_restart_budget(16);
    }
}

/// Closed chains around a point at the centre of a lattice square (on the
/// circle of its four corners, equidistant from its four sides) and one
/// elsewhere: the ties make lying numbers misplace the points against the
/// chains, so several seeds need a restart (`construct::restart::insert_all_from`).
pub fn closed_chains() -> (Vec<[f64; 2]>, Vec<[[f64; 2]; 2]>) {
    (vec![[0.5, 0.5], [2.3, 1.7]], unit_segment_lattice(6))
}
