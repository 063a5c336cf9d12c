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
//! input segment `j`, `A<j>` for the open arc of input arc `j` (the
//! builder numbers arcs apart from segments). Names in a line are sorted
//! (`P` before `S` before `A`, then by index), and lines are sorted by
//! their sequence of names. Without arcs the text is the one the CGAL
//! cross-check compares, byte for byte.
//! An edge has zero length when its two vertices are one point: when the
//! fourth site (the one of the second vertex that the first lacks) lies
//! exactly on the first vertex's circle — cocircular sites. That is decided
//! from the sites, not from the rounded positions (true edges of 1e-15 of
//! the extent are common in real data): exactly for points
//! (`predicates::in_circle`), by the certified segment predicate
//! (`geometry::segments::oracle`) otherwise. [`ZERO_LENGTH`] is a tolerance a user may
//! ask for instead ([`TopologyOptions::zero_length_tolerance`]).

use crate::query::partition::Partition;
use std::fmt::Write;

use crate::diagram::{Diagram, SiteId, VertexId};
use crate::geometry::segments::oracle;

/// A relative length below which an edge may be taken as zero-length, for
/// users who want a tolerance ([`TopologyOptions::zero_length_tolerance`]).
pub const ZERO_LENGTH: f64 = 1e-9;

/// What the topology text contains beyond `EDGES` and `FACES`. More
/// options may come: outside this crate, start from
/// `TopologyOptions::default()` and set fields or use the `with_` methods.
///
/// ```
/// use segvoronoi::TopologyOptions;
/// let options = TopologyOptions::default().with_voronoi_pairs(true);
/// assert!(options.voronoi_pairs && options.zero_length_tolerance.is_none());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[non_exhaustive]
pub struct TopologyOptions {
    /// Add the `VPAIRS` and `VVERTICES` sections, which are the same for
    /// every valid answer on degenerate input.
    pub voronoi_pairs: bool,
    /// Take edges shorter than this times the input's bounding-box
    /// diagonal as zero-length too (`None`, the default: only edges whose
    /// sites are exactly cocircular).
    pub zero_length_tolerance: Option<f64>,
}

impl TopologyOptions {
    /// These options with [`TopologyOptions::voronoi_pairs`] set to `on`.
    pub fn with_voronoi_pairs(self, on: bool) -> TopologyOptions {
        TopologyOptions { voronoi_pairs: on, ..self }
    }

    /// These options with [`TopologyOptions::zero_length_tolerance`] set to
    /// `tolerance`.
    pub fn with_zero_length_tolerance(self, tolerance: Option<f64>) -> TopologyOptions {
        TopologyOptions { zero_length_tolerance: tolerance, ..self }
    }
}

/// A site name: kind (0 = point, 1 = segment, 2 = arc) and index.
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
            let letter = ['P', 'S', 'A'][usize::from(kind)];
            let _ = write!(out, "{sep}{letter}{index}");
            first = false;
        }
        out.push('\n');
    }
}

impl Diagram {
    fn name(&self, site: SiteId) -> Name {
        // arcs are the last sites: asked first, so that no arc is ever
        // taken for a segment
        if let Some(j) = self.arc_input_index(site) {
            return (2, j as u32);
        }
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
            self.write_voronoi_pairs(&mut out, options.zero_length_tolerance);
        }
        out
    }

    /// The two ends of an edge with two finite ends, or `None` for rays and
    /// lines.
    fn finite_vertices_of(&self, e: &crate::query::Edge) -> Option<(VertexId, VertexId)> {
        use crate::query::EdgeEnd::Vertex;
        match e.ends {
            [Vertex(a), Vertex(b)] => Some((a, b)),
            _ => None,
        }
    }

    /// Whether the finite vertices `a` and `b`, joined by an edge, are one
    /// point: the site of `b` that `a` lacks is exactly on `a`'s circle.
    pub(crate) fn is_zero_length_edge(&self, a: VertexId, b: VertexId) -> bool {
        let (Some(va), Some(vb)) = (self.vertex(a), self.vertex(b)) else { return false };
        let Some(&fourth) = vb.sites.iter().find(|s| !va.sites.contains(s)) else {
            // the same three sites: two different circles touching them
            return false;
        };
        // Four sites on one circle can have two such circles (a segment
        // tangent at its endpoint, on either side): the vertices must also be
        // one point as far as rounding can tell.
        let near = va.position.distance(vb.position) <= 1e-6 * va.clearance.max(vb.clearance);
        let sites = va.sites.map(|s| self.sites[s.index()]);
        near && oracle::on_circle(&sites, va.position, va.clearance, &self.sites[fourth.index()])
    }

    fn write_voronoi_pairs(&self, out: &mut String, tolerance: Option<f64>) {
        let threshold = tolerance.map_or(-1.0, |t| t * self.extent);
        let short = |a: VertexId, b: VertexId| {
            let (pa, pb) = (self.store.position[a.index()], self.store.position[b.index()]);
            let length = pa.distance(pb);
            length <= threshold || self.is_zero_length_edge(a, b)
        };
        let mut pairs = Vec::new();
        // the vertices joined by zero-length edges
        let mut joined = Partition::new(self.vertex_count());
        for e in self.edges() {
            match self.finite_vertices_of(&e) {
                Some((a, b)) if short(a, b) => joined.join(a.index(), b.index()),
                _ => pairs.push(vec![self.name(e.sites[0]), self.name(e.sites[1])]),
            }
        }
        write_section(out, "VPAIRS", pairs);
        let mut groups: std::collections::BTreeMap<usize, Vec<Name>> = Default::default();
        for v in self.vertices() {
            let g = groups.entry(joined.find(v.id.index())).or_default();
            for s in v.sites {
                if !g.contains(&self.name(s)) {
                    g.push(self.name(s));
                }
            }
        }
        write_section(out, "VVERTICES", groups.into_values().collect());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arcs_are_named_last() {
        let mut out = String::new();
        let lines = vec![vec![(2, 0), (0, 3)], vec![(2, 0), (1, 1)], vec![(1, 0), (0, 12)], vec![(2, 1), (2, 0), (0, 2)]];
        write_section(&mut out, "FACES", lines);
        assert_eq!(out, "FACES 4\nP2 A0 A1\nP3 A0\nP12 S0\nS1 A0\n");
    }

    #[test]
    fn a_slot_names_its_arcs_by_input_index() {
        use crate::{Builder, CircularArc};
        let mut b = Builder::new();
        b.add_segment([[0.0, 0.0], [4.0, 0.0]]).unwrap();
        b.add_arc(CircularArc::from_bulge([4.0, 0.0], [4.0, 2.0], 1.0).unwrap()).unwrap();
        b.add_segment([[4.0, 2.0], [0.0, 2.0]]).unwrap();
        b.add_arc(CircularArc::from_bulge([0.0, 2.0], [0.0, 0.0], 1.0).unwrap()).unwrap();
        let d = b.build().unwrap();
        let text = d.topology(TopologyOptions::default());
        let names: std::collections::BTreeSet<&str> =
            text.split(['\n', ' ']).filter(|w| w.starts_with(['P', 'S', 'A'])).collect();
        // four endpoints, two segments, two arcs: each named once, arcs
        // apart from segments
        let expected: std::collections::BTreeSet<&str> = ["P0", "P1", "P2", "P3", "S0", "S1", "A0", "A1"].into();
        assert_eq!(names, expected, "{text}");
        let faces = text.lines().find(|l| l.starts_with("FACES ")).unwrap();
        assert_eq!(faces, format!("FACES {}", d.vertex_count()));
    }
}
