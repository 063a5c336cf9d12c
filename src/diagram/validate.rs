//! The invariant checker. Purely combinatorial: it reads no coordinate, so it
//! holds under fault injection too.

use super::ids::{HalfEdgeId, SiteId, VertexId, NONE};
use super::store::Store;

/// A broken invariant of the diagram store, in words.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ValidationError(pub String);

impl std::fmt::Display for ValidationError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "invalid diagram: {}", self.0)
    }
}

impl std::error::Error for ValidationError {}

macro_rules! ensure {
    ($cond:expr, $($msg:tt)+) => {
        if !$cond {
            return Err(ValidationError(format!($($msg)+)));
        }
    };
}

impl Store {
    /// Checks every topological invariant:
    /// - array sizes agree; every id is in range;
    /// - twins are mutual, distinct, on different vertices, and see the same
    ///   two cells from opposite sides (so the cyclic order of edges around
    ///   each vertex matches the cell structure);
    /// - every vertex has degree 3 and three distinct cells, a finite
    ///   position and a clearance that is not NaN or negative;
    /// - the graph is connected and Euler's formula `V - E + F = 2` holds,
    ///   with `F` the number of face cycles;
    /// - every site with a cell has exactly one face cycle, which is its
    ///   whole boundary (one connected region per site), and `cell_edge`
    ///   names a half-edge of it;
    /// - with two or more sites every site has a cell; with fewer there are
    ///   no vertices.
    pub fn validate(&self) -> Result<(), ValidationError> {
        let nv = self.vertex_count();
        let nh = 3 * nv;
        let ns = self.site_count();
        ensure!(self.right.len() == nh && self.twin.len() == nh, "array sizes disagree");
        ensure!(self.clearance.len() == nv, "clearance array size");
        ensure!(self.infinite_site.index() < ns, "infinite site out of range");

        if ns <= 2 {
            // the point at infinity and at most one real site: no boundary at all
            ensure!(nv == 0, "{nv} vertices with fewer than two real sites");
            ensure!(self.cell_edge.iter().all(|&e| e == NONE), "cell edge without vertices");
            return Ok(());
        }

        for h in (0..nh).map(HalfEdgeId::from_index) {
            let t = self.twin(h);
            ensure!(t.index() < nh, "half-edge {h} has twin {t} out of range");
            ensure!(self.twin(t) == h, "twin of twin of {h} is not {h}");
            ensure!(t.origin() != h.origin(), "half-edge {h} is a loop");
            let r = self.right(h);
            ensure!(r.index() < ns, "half-edge {h} names site {r} out of range");
            ensure!(
                self.left(h) == self.right(t) && self.right(h) == self.left(t),
                "half-edge {h} and its twin {t} disagree on their cells"
            );
        }
        for v in (0..nv).map(VertexId::from_index) {
            let [a, b, c] = self.sites_of(v);
            ensure!(a != b && b != c && a != c, "vertex {v} repeats a cell: {a} {b} {c}");
            if !self.is_at_infinity(v) {
                // saturated at ±f64::MAX beyond the range of f64, never
                // infinite or NaN (clearance: infinite there, never NaN)
                let (p, r) = (self.position[v.index()], self.clearance[v.index()]);
                ensure!(p.x.is_finite() && p.y.is_finite(), "vertex {v} is at ({}, {})", p.x, p.y);
                ensure!((0.0..=f64::INFINITY).contains(&r), "vertex {v} has clearance {r}");
            }
        }

        // Face cycles of `next`; each must carry a single site, and each site one cycle.
        let mut seen = vec![false; nh];
        let mut cycles_of_site = vec![0u32; ns];
        let mut faces = 0usize;
        for start in 0..nh {
            if seen[start] {
                continue;
            }
            faces += 1;
            let site = self.left(HalfEdgeId::from_index(start));
            let mut h = HalfEdgeId::from_index(start);
            let mut steps = 0usize;
            loop {
                ensure!(!seen[h.index()], "face cycle through {start} is not simple");
                seen[h.index()] = true;
                ensure!(self.left(h) == site, "cell {site} boundary reaches cell {}", self.left(h));
                h = self.next(h);
                steps += 1;
                ensure!(steps <= nh, "face cycle through {start} does not close");
                if h.index() == start {
                    break;
                }
            }
            ensure!(steps >= 2, "cell {site} has a boundary of {steps} edge");
            cycles_of_site[site.index()] += 1;
        }
        for (s, &k) in cycles_of_site.iter().enumerate() {
            ensure!(k == 1, "site {s} has {k} boundary cycles (must be exactly one)");
            let e = self.cell_edge[s];
            ensure!(e != NONE && (e as usize) < nh, "site {s} has no cell edge");
            ensure!(self.left(HalfEdgeId(e)) == SiteId::from_index(s), "cell edge of site {s} borders another cell");
        }

        // Connectivity, then Euler on the sphere.
        let mut reached = vec![false; nv];
        let mut stack = vec![0usize];
        reached[0] = true;
        let mut count = 1usize;
        while let Some(v) = stack.pop() {
            for s in 0..3 {
                let w = self.target(VertexId::from_index(v).half_edge(s)).index();
                if !reached[w] {
                    reached[w] = true;
                    count += 1;
                    stack.push(w);
                }
            }
        }
        ensure!(count == nv, "graph is not connected: {count} of {nv} vertices reached");
        let edges = nh / 2;
        ensure!(nv as i64 - edges as i64 + faces as i64 == 2, "Euler's formula fails: V={nv} E={edges} F={faces}");
        Ok(())
    }
}
