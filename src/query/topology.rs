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
//!
//! A degenerate vertex (four or more sites on one circle) is stored as
//! degree-3 vertices joined by zero-length edges, and which cut the
//! construction leaves depends on the insertion order. By default `EDGES`
//! and `FACES` list the diagram's own edges and vertices, as its arrays
//! hold them. With [`TopologyOptions::canonical_cuts`] they give each such
//! vertex one cut whatever the order: the fan from the site round it that
//! comes first by its coordinates (decided exactly, as above; arcs keep
//! the construction's cut). That text is the same for the input in any
//! order, names read as the sites they stand for, and for any order a
//! parallel build inserts in.

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
    /// Cut every degenerate vertex one way in `EDGES` and `FACES`, the
    /// same for the input in any order (see the module documentation).
    /// Off by default: then `FACES` lists the diagram's own vertices, as
    /// its arrays hold them.
    pub canonical_cuts: bool,
}

impl TopologyOptions {
    /// These options with [`TopologyOptions::voronoi_pairs`] set to `on`.
    pub fn with_voronoi_pairs(self, on: bool) -> TopologyOptions {
        TopologyOptions { voronoi_pairs: on, ..self }
    }

    /// These options with [`TopologyOptions::canonical_cuts`] set to `on`.
    pub fn with_canonical_cuts(self, on: bool) -> TopologyOptions {
        TopologyOptions { canonical_cuts: on, ..self }
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
        let (edges, faces) = if options.canonical_cuts {
            self.edges_and_faces()
        } else {
            let edges = self.edges().map(|e| vec![self.name(e.sites[0]), self.name(e.sites[1])]).collect();
            (edges, self.vertices().map(|v| v.sites.iter().map(|&s| self.name(s)).collect()).collect())
        };
        write_section(&mut out, "EDGES", edges);
        write_section(&mut out, "FACES", faces);
        if options.voronoi_pairs {
            self.write_voronoi_pairs(&mut out, options.zero_length_tolerance);
        }
        out
    }

    /// The `EDGES` and `FACES` lines, each degenerate vertex cut the same
    /// way whatever the insertion order and the order of the input
    /// (`canonical_cut`).
    fn edges_and_faces(&self) -> (Vec<Vec<Name>>, Vec<Vec<Name>>) {
        let pair = |e: &crate::query::Edge| vec![self.name(e.sites[0]), self.name(e.sites[1])];
        let names = |sites: &[SiteId]| sites.iter().map(|&s| self.name(s)).collect::<Vec<Name>>();
        let mut joined = Partition::new(self.vertex_count());
        let mut inside = vec![false; self.edges.len()];
        let mut degenerate = vec![false; self.vertex_count()];
        for e in self.edges() {
            if let Some((a, b)) = self.finite_vertices_of(&e) {
                if self.is_zero_length_edge(a, b) {
                    joined.join(a.index(), b.index());
                    inside[e.id.index()] = true;
                    degenerate[a.index()] = true;
                    degenerate[b.index()] = true;
                }
            }
        }
        let mut faces = Vec::with_capacity(self.vertex_count());
        // (cluster, vertex) for the vertices of zero-length edges, grouped
        let mut members: Vec<(usize, VertexId)> = Vec::new();
        for v in self.vertices() {
            if degenerate[v.id.index()] {
                members.push((joined.find(v.id.index()), v.id));
            } else {
                faces.push(names(&v.sites));
            }
        }
        members.sort_unstable_by_key(|&(root, v)| (root, v.index()));
        let mut diagonals = Vec::new();
        let mut kept = std::collections::HashSet::new();
        for cluster in members.chunk_by(|x, y| x.0 == y.0) {
            let root = cluster[0].0;
            let triangles: Vec<[SiteId; 3]> = cluster.iter().map(|&(_, v)| self.store.sites_of(v)).collect();
            // a cluster at a shared endpoint (radius 0): its cut is the
            // endpoint's separators', not a matter of cocircular sites
            let at_a_point = cluster.iter().any(|&(_, v)| self.store.clearance[v.index()] == 0.0);
            let cut = if at_a_point || !self.decided_at_every_scale(&triangles) {
                None
            } else {
                canonical_cut(&triangles, |s| self.sites.get(s.index()).map(|s| site_key(&s)))
            };
            match cut {
                Some((fan, cuts)) => {
                    faces.extend(fan.iter().map(|t| names(t)));
                    diagonals.extend(cuts.iter().map(|d| names(d)));
                }
                None => {
                    faces.extend(triangles.iter().map(|t| names(t)));
                    kept.insert(root);
                }
            }
        }
        let mut edges: Vec<Vec<Name>> = self
            .edges()
            .filter(|e| {
                !inside[e.id.index()] || self.finite_vertices_of(e).is_some_and(|(a, _)| kept.contains(&joined.find(a.index())))
            })
            .map(|e| pair(&e))
            .collect();
        edges.extend(diagonals);
        (edges, faces)
    }

    /// Whether the zero-length test of a cluster's edges gives one answer
    /// whatever the input's scale: its sites' nonzero coordinates span
    /// less than 2^150 (beyond, the exact test's products of four
    /// differences can fall below the range of `f64` at one scale and not
    /// at another, and a cluster found at one scale is missed at the
    /// other). Such a cluster keeps the construction's cut.
    fn decided_at_every_scale(&self, triangles: &[[SiteId; 3]]) -> bool {
        let (mut least, mut most) = (f64::INFINITY, 0f64);
        for s in triangles.iter().flatten() {
            for p in self.sites.at(s.index()).ends() {
                for c in [p.x.abs(), p.y.abs()].into_iter().filter(|&c| c > 0.0) {
                    least = least.min(c);
                    most = most.max(c);
                }
            }
        }
        !(most > least * 2f64.powi(150))
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
    ///
    /// Asked from the vertex whose sites, sorted, come first: near ties far
    /// from the origin are decided in floating point where the certified
    /// predicate cannot, and the question must not depend on how the
    /// diagram numbers its vertices (a build in halves numbers them
    /// otherwise than one thread).
    pub(crate) fn is_zero_length_edge(&self, a: VertexId, b: VertexId) -> bool {
        let (Some(va), Some(vb)) = (self.vertex(a), self.vertex(b)) else { return false };
        let sorted = |mut s: [SiteId; 3]| {
            s.sort();
            s
        };
        let (va, vb) = if sorted(vb.sites) < sorted(va.sites) { (vb, va) } else { (va, vb) };
        let Some(&fourth) = vb.sites.iter().find(|s| !va.sites.contains(s)) else {
            // the same three sites: two different circles touching them
            return false;
        };
        // Four sites on one circle can have two such circles (a segment
        // tangent at its endpoint, on either side): the vertices must also be
        // one point as far as rounding can tell.
        let near = va.position.distance(vb.position) <= 1e-6 * va.clearance.max(vb.clearance);
        let sites = va.sites.map(|s| self.sites.at(s.index()));
        near && oracle::on_circle(&sites, va.position, va.clearance, &self.sites.at(fourth.index()))
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

/// A site's place in an order that does not depend on how the input was
/// numbered: its coordinates (a point as a segment of no length, a
/// segment from its lesser end). `None` for an arc.
fn site_key(site: &crate::geometry::Site) -> Option<[f64; 4]> {
    use crate::geometry::Site;
    match *site {
        Site::Point(p) => Some([p.x, p.y, p.x, p.y]),
        Site::Segment { a, b } => {
            let (lo, hi) = if (a.x, a.y) <= (b.x, b.y) { (a, b) } else { (b, a) };
            Some([lo.x, lo.y, hi.x, hi.y])
        }
        Site::Arc(_) => None,
    }
}

/// One cut of a degenerate vertex into degree-3 ones, the same for every
/// cut given: from `triangles`, the sites of the vertices joined by
/// zero-length edges (each counter-clockwise), the sites round the point
/// they share, counter-clockwise, are the sides that no two triangles
/// share. The fan from the least of them by `key` (their coordinates: the
/// answer is the same for the input in any order): its triangles and its
/// diagonals (the zero-length edges). `None` where the sides do not close
/// into one ring of distinct sites (an arc can touch one circle twice) or
/// a site has no key (arcs, whose zero-length test is not exact).
fn canonical_cut(
    triangles: &[[SiteId; 3]],
    key: impl Fn(SiteId) -> Option<Option<[f64; 4]>>,
) -> Option<(Vec<[SiteId; 3]>, Vec<[SiteId; 2]>)> {
    let mut sides: Vec<(SiteId, SiteId)> = triangles.iter().flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])]).collect();
    sides.sort_unstable_by_key(|&(a, b)| (a.index(), b.index()));
    let key_of = |&(a, b): &(SiteId, SiteId)| (a.index(), b.index());
    let shared = |a: SiteId, b: SiteId| sides.binary_search_by_key(&(b.index(), a.index()), key_of).is_ok();
    // the ring's sides, sorted by their first site (as `sides` is)
    let next: Vec<(SiteId, SiteId)> = sides.iter().copied().filter(|&(a, b)| !shared(a, b)).collect();
    if next.windows(2).any(|w| w[0].0 == w[1].0) {
        return None;
    }
    let following = |a: SiteId| next.binary_search_by_key(&a.index(), |&(x, _)| x.index()).ok().map(|k| next[k].1);
    let ring_length = triangles.len() + 2;
    let keys: Vec<(SiteId, [f64; 4])> = next.iter().map(|&(s, _)| Some((s, key(s)??))).collect::<Option<_>>()?;
    let least = |x: &[f64; 4], y: &[f64; 4]| x.iter().zip(y).map(|(a, b)| a.total_cmp(b)).find(|o| o.is_ne());
    let (apex, apex_key) = *keys.iter().min_by(|x, y| least(&x.1, &y.1).unwrap_or(std::cmp::Ordering::Equal))?;
    // two sites with one key (a segment given twice): no order to go by
    if keys.iter().filter(|(_, k)| least(k, &apex_key).is_none()).count() > 1 {
        return None;
    }
    let mut ring = vec![apex];
    while ring.len() <= ring_length {
        let following = following(*ring.last()?)?;
        if following == apex {
            break;
        }
        ring.push(following);
    }
    if ring.len() != ring_length || next.len() != ring_length {
        return None;
    }
    let fan = (1..ring_length - 1).map(|k| [apex, ring[k], ring[k + 1]]).collect();
    let diagonals = (2..ring_length - 1).map(|k| [apex, ring[k]]).collect();
    Some((fan, diagonals))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_cuts_of_four_cocircular_sites_give_one_fan() {
        let s = SiteId::from_index;
        // the square's corners 1, 2, 3, 4 counter-clockwise, cut by either
        // diagonal; keys put site 3 first
        let key = |x: SiteId| Some(Some([[0.0; 4], [5.0; 4], [6.0; 4], [1.0; 4], [7.0; 4]][x.index()]));
        let one = canonical_cut(&[[s(1), s(2), s(3)], [s(1), s(3), s(4)]], key).unwrap();
        let other = canonical_cut(&[[s(2), s(3), s(4)], [s(2), s(4), s(1)]], key).unwrap();
        assert_eq!(one, other);
        assert_eq!(one.0, vec![[s(3), s(4), s(1)], [s(3), s(1), s(2)]]);
        assert_eq!(one.1, vec![[s(3), s(1)]]);
        // a side given twice is no ring: no cut
        assert!(canonical_cut(&[[s(1), s(2), s(3)], [s(1), s(2), s(4)]], key).is_none());
    }

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
