//! The two filters of the medial axis, off by default: the corner filter
//! drops the branch into a convex corner whose interior angle is above a
//! threshold (the spurs of curves flattened into chords), the spur filter
//! a leaf branch shorter than `k` times the clearance at its junction.
//! Pictures: `docs/medial_axis_filters.svg`. (The clearance changes no
//! faster than the length along the axis, and a branch into a corner
//! starts at clearance 0, so it is at least as long as its junction's
//! clearance: useful factors are above 1. A rectangle's corners have
//! branches `sqrt(2)` times it, the spokes of a circle flattened into
//! chords barely more than 1.)
//!
//! A *branch* is a chain of the unfiltered medial axis from a leaf (a vertex
//! where only that chain ends) to a junction (a vertex where three or more
//! chains meet). Both filters look at the branches of the unfiltered axis,
//! once: what a removal leaves is not filtered again, so a filter never eats
//! its way down a whole tree. The remaining edges are chained again, so two
//! chains that met at a junction that has lost its other chains become
//! one. A connected component of the axis all of whose edges of positive
//! length would be removed (the star of a regular polygon, every spoke of
//! which is a branch into a corner) is kept whole.

use crate::diagram::{Diagram, EdgeId, VertexId};
use crate::query::medial_axis::degree_at;
use crate::query::partition::Partition;
use crate::query::{Chain, EdgeEnd, MedialAxis};
use crate::Site;

/// Which branches of the medial axis [`Diagram::medial_axis_filtered`]
/// leaves out (see the module documentation of the rules). The default
/// leaves out nothing.
///
/// ```
/// use segvoronoi::{Builder, MedialAxisFilter};
/// let mut b = Builder::new();
/// b.add_polygon(&[vec![[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]])?;
/// let d = b.build()?;
/// // The four branches into the corners are sqrt(2) long, the clearance
/// // at their junctions 1: pruned at k = 2, the middle line is left.
/// let axis = d.medial_axis_filtered(&MedialAxisFilter::new().with_spur_pruning(2.0));
/// assert_eq!(axis.chains.len(), 1);
/// assert_eq!(axis.chains[0].pieces.len(), 1);
/// # Ok::<(), segvoronoi::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct MedialAxisFilter {
    /// Branches into a convex corner whose interior angle, in degrees, is
    /// above this are left out. 180 (the default) leaves out none: a convex
    /// corner's angle is below 180 (a reflex corner has no branch).
    pub corner_angle: f64,
    /// Leaf branches shorter than this times the clearance at their
    /// junction are left out. 0 (the default) leaves out none.
    pub spur_factor: f64,
}

impl Default for MedialAxisFilter {
    fn default() -> Self {
        MedialAxisFilter { corner_angle: 180.0, spur_factor: 0.0 }
    }
}

impl MedialAxisFilter {
    /// The filter that leaves out nothing.
    pub fn new() -> Self {
        Self::default()
    }

    /// Leave out the branches into convex corners of interior angle above
    /// `degrees` (NaN: none).
    pub fn with_corner_angle(mut self, degrees: f64) -> Self {
        self.corner_angle = degrees;
        self
    }

    /// Leave out the leaf branches shorter than `k` times the clearance at
    /// their junction (NaN or `k <= 0`: none).
    pub fn with_spur_pruning(mut self, k: f64) -> Self {
        self.spur_factor = k;
        self
    }
}

impl Diagram {
    /// The medial axis without the branches `filter` leaves out (see
    /// [`MedialAxisFilter`]); the same as [`Diagram::medial_axis`] with the
    /// default filter.
    pub fn medial_axis_filtered(&self, filter: &MedialAxisFilter) -> MedialAxis {
        let mut in_axis = self.medial_axis_edges();
        let chains = self.chains_of(&in_axis);
        let degrees = self.axis_degrees(&in_axis);
        let removed: Vec<&Chain> = chains.iter().filter(|c| self.filter_removes(c, filter, &degrees)).collect();
        if removed.is_empty() {
            return MedialAxis { chains };
        }
        let mut out = vec![false; self.edges.len()];
        for piece in removed.iter().flat_map(|c| &c.pieces) {
            out[piece.edge.index()] = true;
        }
        // a component that would lose every edge of positive length keeps
        // them all
        let components = self.axis_components(&in_axis);
        let mut keeps_some = vec![false; self.finite_vertices];
        for (e, _) in in_axis.iter().enumerate().filter(|&(e, &marked)| marked && !out[e]) {
            let ends = self.end_vertices(EdgeId::from_index(e));
            let Some(v) = ends.into_iter().flatten().next() else { continue };
            let component = components.find(v.index());
            // the exact zero-length test only where it can matter
            if !keeps_some[component] && !matches!(ends, [Some(a), Some(b)] if self.is_zero_length_edge(a, b)) {
                keeps_some[component] = true;
            }
        }
        for (e, marked) in in_axis.iter_mut().enumerate() {
            if *marked && out[e] {
                let ends = self.end_vertices(EdgeId::from_index(e));
                *marked = ends.into_iter().flatten().all(|v| !keeps_some[components.find(v.index())]);
            }
        }
        MedialAxis { chains: self.chains_of(&in_axis) }
    }

    /// Whether `filter` leaves out `chain`: a branch (see the module doc)
    /// into a corner above the angle, or shorter than the spur factor
    /// times its junction's clearance.
    fn filter_removes(&self, chain: &Chain, filter: &MedialAxisFilter, degrees: &[u8]) -> bool {
        let (Some(first), Some(last)) = (chain.pieces.first(), chain.pieces.last()) else { return false };
        if chain.closed {
            return false;
        }
        let (start, end) = (first.ends[0], last.ends[1]);
        let degree = |end: EdgeEnd| degree_at(end, degrees);
        let (leaf, leaf_piece, junction) = match (degree(start), degree(end)) {
            (1, d) if d >= 3 => (start, first, end),
            (d, 1) if d >= 3 => (end, last, start),
            _ => return false,
        };
        let (EdgeEnd::Vertex(leaf), EdgeEnd::Vertex(junction)) = (leaf, junction) else { return false };
        let into_flat_corner = self.corner_angle_at(leaf, leaf_piece.edge).is_some_and(|angle| angle > filter.corner_angle);
        let short = filter.spur_factor > 0.0 && {
            let clearance = self.store.clearance[junction.index()];
            self.chain_length(chain, clearance) < filter.spur_factor * clearance
        };
        into_flat_corner || short
    }

    /// The interior angle, in degrees, of the corner where the edge `e`
    /// ends at `v`: the angle between its two sites, segments sharing the
    /// endpoint `v` is at (the edge is their bisector, inside the angle).
    /// `None` when `v` is not such a corner.
    fn corner_angle_at(&self, v: VertexId, e: EdgeId) -> Option<f64> {
        if self.store.clearance.get(v.index()) != Some(&0.0) {
            return None;
        }
        let [s, t] = self.edge(e)?.sites.map(|s| self.site(s));
        let (Some(Site::Segment { a, b }), Some(Site::Segment { a: c, b: d })) = (s, t) else { return None };
        let corner = [a, b].into_iter().find(|&p| p == c || p == d)?;
        let far = |x: crate::Point, y: crate::Point| if x == corner { y } else { x };
        let (p, q) = (far(a, b), far(c, d));
        let (u, w) = (crate::Point::new(p.x - corner.x, p.y - corner.y), crate::Point::new(q.x - corner.x, q.y - corner.y));
        let (cross, dot) = (u.x * w.y - u.y * w.x, u.x * w.x + u.y * w.y);
        Some(cross.abs().atan2(dot).to_degrees())
    }

    /// The length of a chain, measured on its points within a thousandth
    /// of `clearance` (a filter's threshold is a multiple of it); infinite
    /// when a piece reaches infinity.
    fn chain_length(&self, chain: &Chain, clearance: f64) -> f64 {
        let tolerance = if clearance > 0.0 { 1e-3 * clearance } else { f64::MIN_POSITIVE };
        self.sample_chain(chain, tolerance)
            .map_or(f64::INFINITY, |points| points.windows(2).map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])).sum())
    }

    /// The connected components of the edges marked in `in_axis`, as a
    /// partition of the vertices.
    pub(super) fn axis_components(&self, in_axis: &[bool]) -> Partition {
        let mut components = Partition::new(self.finite_vertices);
        for (e, &marked) in in_axis.iter().enumerate() {
            if let (true, [Some(v), Some(w)]) = (marked, self.end_vertices(EdgeId::from_index(e))) {
                components.join(v.index(), w.index());
            }
        }
        components
    }
}
