//! Helpers shared by the integration tests: input generators and the
//! brute-force geometric checks.
#![allow(dead_code)]

use segvoronoi::{Builder, Diagram, EdgeEnd, Point};

/// A small deterministic generator.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

pub fn uniform(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut r = Rng(seed);
    (0..n).map(|_| [r.unit(), r.unit()]).collect()
}

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
    d.edges().filter(|e| matches!(e.ends, [EdgeEnd::Vertex(_), EdgeEnd::Infinite { .. }] | [EdgeEnd::Infinite { .. }, EdgeEnd::Vertex(_)])).count()
}

/// Points and short segments on a jittered grid, one item per cell (a
/// segment with probability `segment_share`): no two segments meet.
pub fn segment_grid(side: usize, seed: u64, segment_share: f64) -> (Vec<[f64; 2]>, Vec<[[f64; 2]; 2]>) {
    let mut rng = Rng(seed);
    let (mut pts, mut segs) = (Vec::new(), Vec::new());
    for i in 0..side {
        for j in 0..side {
            let (x, y) = (i as f64, j as f64);
            let a = [x + 0.1 + 0.8 * rng.unit(), y + 0.1 + 0.8 * rng.unit()];
            if rng.unit() < segment_share {
                segs.push([a, [x + 0.1 + 0.8 * rng.unit(), y + 0.1 + 0.8 * rng.unit()]]);
            } else {
                pts.push(a);
            }
        }
    }
    (pts, segs)
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

/// The sides of the regular `n`-gon of circumradius `r` centred at
/// `(cx, cy)`, each sharing its endpoints with its neighbours.
pub fn polygon(n: usize, r: f64, cx: f64, cy: f64) -> Vec<[[f64; 2]; 2]> {
    let corner = |k: usize| {
        let t = std::f64::consts::TAU * (k % n) as f64 / n as f64;
        [cx + r * t.cos(), cy + r * t.sin()]
    };
    (0..n).map(|k| [corner(k), corner(k + 1)]).collect()
}

/// A boustrophedon polyline through one jittered point per grid cell:
/// consecutive segments share endpoints, none cross.
pub fn snake(side: usize, seed: u64) -> Vec<[[f64; 2]; 2]> {
    let mut rng = Rng(seed);
    let mut path = Vec::new();
    for i in 0..side {
        for k in 0..side {
            let j = if i % 2 == 0 { k } else { side - 1 - k };
            path.push([i as f64 + 0.1 + 0.8 * rng.unit(), j as f64 + 0.1 + 0.8 * rng.unit()]);
        }
    }
    path.windows(2).map(|w| [w[0], w[1]]).collect()
}

/// Every line of the `n` by `n` unit grid split into unit segments:
/// degree-4 shared endpoints, collinear neighbours, cocircular everything.
pub fn unit_segment_lattice(n: usize) -> Vec<[[f64; 2]; 2]> {
    let mut segs = Vec::new();
    for i in 0..=n {
        for j in 0..n {
            let (x, y) = (i as f64, j as f64);
            segs.push([[x, y], [x, y + 1.0]]);
            segs.push([[y, x], [y + 1.0, x]]);
        }
    }
    segs
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
    for v in d.vertices() {
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
