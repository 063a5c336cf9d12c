//! The canonical topology text: the same for the CLI, the C API and the CGAL
//! cross-check, so that two diagrams can be compared line by line.
//!
//! ```text
//! EDGES m        one line "A B" per Voronoi edge between two real sites
//! FACES f        one line "A B C" per finite Voronoi vertex
//! VPAIRS m       (option) one line per edge of positive length
//! VVERTICES k    (option) one line per vertex after merging zero-length edges:
//!                every site whose cell touches it
//! ```
//! Site names: `P<k>` for point site `k`, `S<j>` for the open segment of
//! input segment `j`. Names in a line are sorted (`P` before
//! `S`, then by index), and lines are sorted by their sequence of names.
//! Edges shorter than `1e-9` times the input's bounding-box diagonal count as
//! zero-length.

use std::fmt::Write;

use crate::diagram::{Diagram, SiteId, VertexId};

/// Relative length below which an edge counts as zero-length.
pub const ZERO_LENGTH: f64 = 1e-9;

/// What the topology text contains beyond `EDGES` and `FACES`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TopologyOptions {
    /// Add the `VPAIRS` and `VVERTICES` sections, which are the same for
    /// every valid answer on degenerate input.
    pub voronoi_pairs: bool,
}

/// A site name: kind (0 = point, 1 = segment) and index.
type Name = (u8, u32);

fn write_section(out: &mut String, title: &str, mut lines: Vec<Vec<Name>>) {
    for l in lines.iter_mut() {
        l.sort_unstable();
    }
    lines.sort_unstable();
    let _ = writeln!(out, "{title} {}", lines.len());
    for l in &lines {
        let mut first = true;
        for &(kind, index) in l {
            let sep = if first { "" } else { " " };
            let letter = if kind == 0 { 'P' } else { 'S' };
            let _ = write!(out, "{sep}{letter}{index}");
            first = false;
        }
        out.push('\n');
    }
}

impl Diagram {
    fn name(&self, site: SiteId) -> Name {
        match self.segment_input_index(site) {
            Some(j) => (1, j as u32),
            None => (0, site.0),
        }
    }

    /// The canonical topology text (see the module documentation).
    ///
    /// ```
    /// use segvoronoi::{Builder, TopologyOptions};
    /// let mut b = Builder::new();
    /// b.add_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])?;
    /// let text = b.build()?.topology(TopologyOptions::default());
    /// assert_eq!(text, "EDGES 3\nP0 P1\nP0 P2\nP1 P2\nFACES 1\nP0 P1 P2\n");
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn topology(&self, options: TopologyOptions) -> String {
        let mut out = String::new();
        let edges = self.edges().map(|e| vec![self.name(e.sites[0]), self.name(e.sites[1])]).collect();
        write_section(&mut out, "EDGES", edges);
        let faces = self.vertices().map(|v| v.sites.iter().map(|&s| self.name(s)).collect()).collect();
        write_section(&mut out, "FACES", faces);
        if options.voronoi_pairs {
            self.write_voronoi_pairs(&mut out);
        }
        out
    }

    /// Length of an edge with two finite ends, or `None` for rays and lines.
    fn finite_length(&self, e: &crate::query::Edge) -> Option<(VertexId, VertexId, f64)> {
        use crate::query::EdgeEnd::Vertex;
        match e.ends {
            [Vertex(a), Vertex(b)] => {
                let (pa, pb) = (self.store.position[a.index()], self.store.position[b.index()]);
                Some((a, b, pa.distance(pb)))
            }
            _ => None,
        }
    }

    fn write_voronoi_pairs(&self, out: &mut String) {
        let threshold = ZERO_LENGTH * self.extent;
        let mut pairs = Vec::new();
        let mut parent: Vec<u32> = (0..self.vertex_count() as u32).collect();
        fn root(parent: &mut [u32], mut v: u32) -> u32 {
            while parent[v as usize] != v {
                parent[v as usize] = parent[parent[v as usize] as usize];
                v = parent[v as usize];
            }
            v
        }
        for e in self.edges() {
            match self.finite_length(&e) {
                Some((a, b, len)) if len <= threshold || len.is_nan() => {
                    let (ra, rb) = (root(&mut parent, a.0), root(&mut parent, b.0));
                    parent[ra as usize] = rb;
                }
                _ => pairs.push(vec![self.name(e.sites[0]), self.name(e.sites[1])]),
            }
        }
        write_section(out, "VPAIRS", pairs);
        let mut groups: std::collections::BTreeMap<u32, Vec<Name>> = Default::default();
        for v in self.vertices() {
            let r = root(&mut parent, v.id.0);
            let g = groups.entry(r).or_default();
            for s in v.sites {
                if !g.contains(&self.name(s)) {
                    g.push(self.name(s));
                }
            }
        }
        write_section(out, "VVERTICES", groups.into_values().collect());
    }
}
