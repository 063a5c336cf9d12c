//! The finished diagram as the library hands it out: the store, renumbered
//! to public ids, plus the sites and the build statistics. Its accessors live
//! in `query`.

use super::ids::{HalfEdgeId, SiteId};
use super::store::Store;

/// Counts from one build. More counts may come: read the fields, but do not
/// build or destructure the struct whole outside this crate.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct BuildStats {
    /// Points given to the builder.
    pub input_points: usize,
    /// Segments given to the builder.
    pub input_segments: usize,
    /// Circular arcs given to the builder.
    pub input_arcs: usize,
    /// Distinct sites in the diagram: points (isolated ones and segment
    /// endpoints) and open segments.
    pub sites: usize,
    /// Input points that repeated an earlier point (or, with segments, any
    /// segment endpoint) and were merged into it.
    pub duplicate_points: usize,
    /// Input segments that repeated an earlier one (either direction) and
    /// were merged into it.
    pub duplicate_segments: usize,
    /// Input segments of zero length, which became points.
    pub zero_length_segments: usize,
    /// Points of polygons and polylines (`Builder::add_polygon`,
    /// `add_polyline`) that repeated the point before them and were dropped
    /// (a ring's closing point that repeats its first is not counted).
    pub dropped_chain_points: usize,
    /// Voronoi vertices (finite ones; vertices at infinity are not counted).
    pub vertices: usize,
    /// Voronoi edges between two sites, rays and lines included.
    pub edges: usize,
    /// Segments the diagram was built from: the input segments, or the
    /// pieces they were split into (at input vertices inside them,
    /// [`BuildStats::split_at_vertices`], or with
    /// [`Builder::split_crossings`](crate::Builder::split_crossings)).
    pub pieces: usize,
    /// Without `split_crossings`: input vertices (segment endpoints,
    /// zero-length segments, isolated points) that lay in the open
    /// interior of an input segment, which was split there exactly, at the
    /// vertex itself (a T-junction, a hole touching its shell inside an
    /// edge, a point on a line); counted per (vertex, segment) pair, so
    /// also the number of pieces beyond one per segment. With
    /// `split_crossings` such touchings are counted in `touchings`
    /// instead. Since 0.2.
    pub split_at_vertices: usize,
    /// With `split_crossings`: pairs of input segments that crossed (at a
    /// point inside both).
    pub crossings: usize,
    /// With `split_crossings`: pairs of collinear input segments that
    /// shared more than a point.
    pub overlaps: usize,
    /// With `split_crossings`: endpoints and isolated points that lay inside
    /// a segment (T-junctions), counted per (point, segment) pair.
    pub touchings: usize,
    /// With `split_crossings`: rounds of snapping run (0 when nothing met).
    pub snap_rounds: usize,
    /// Without `split_crossings`: pieces of polygon rings dropped because
    /// they cancelled in pairs, two copies of one stretch (rings sharing an
    /// edge or part of one, a spike out and back along itself: the
    /// even-odd domain is the same without them). Always even: two
    /// squares sharing an edge give 2. Since 0.2.
    pub cancelled_ring_pieces: usize,
}

/// A Voronoi diagram. Immutable; reading it from many threads at once is safe.
///
/// Site ids are public and dense: site `k < point_site_count()` is the
/// `k`-th distinct point in order of first appearance, reading the isolated
/// points first and then each segment's first and second endpoint; the open
/// segments follow, in input order. Vertex ids `0..vertex_count()` are the
/// finite vertices. Edge ids `0..edge_count()` are the edges between two
/// sites.
#[derive(Clone, Debug)]
pub struct Diagram {
    /// Sites `0..sites.len()` are the real ones; the point at infinity is
    /// `sites.len()`. Vertices `0..finite_vertices` are finite, the rest at
    /// infinity.
    pub(crate) store: Store,
    /// Each site in input coordinates: the points first, then the segments.
    pub(crate) sites: super::SiteTable,
    /// Number of point sites (`sites[..point_sites]`).
    pub(crate) point_sites: usize,
    /// Per segment site (id minus `point_sites`): its input index.
    pub(crate) segment_input: Vec<u32>,
    /// Per segment site: its two endpoint sites.
    pub(crate) segment_ends: Vec<[SiteId; 2]>,
    /// Per input segment: the site it became (a repeat: the first one; a
    /// zero-length segment: its point).
    pub(crate) segment_site: Vec<SiteId>,
    /// Number of arc sites, the last ones (`sites[sites.len() - arcs..]`);
    /// their endpoints follow the segments' in `segment_ends`.
    pub(crate) arc_sites: usize,
    /// Per arc site (id minus the first arc site's): its input index.
    pub(crate) arc_input: Vec<u32>,
    /// Per input arc: the site it became.
    pub(crate) arc_site: Vec<SiteId>,
    pub(crate) finite_vertices: usize,
    /// Per public edge: its canonical half-edge.
    pub(crate) edges: Vec<HalfEdgeId>,
    /// Per half-edge: its public edge id, or `NONE` for edges along the
    /// point at infinity. Made on first use: only cell walks need it.
    pub(crate) edge_of_half_edge: std::sync::OnceLock<Vec<u32>>,
    /// Per input point: the site it became.
    pub(crate) input_site: Vec<SiteId>,
    pub(crate) stats: BuildStats,
    /// Diagonal of the input's bounding box, the scale of "zero length".
    pub(crate) extent: f64,
    /// The power-of-two factor that brings the input into the range where
    /// squared distances cannot overflow (used by queries).
    pub(crate) scale: crate::geometry::scale::Scale,
    /// Where each vertex, edge and cell lies against the polygons' rings,
    /// when polygons were added (`query::domain`).
    pub(crate) domain: Option<crate::query::Domain>,
    /// With `split_crossings`: the pieces' input segments.
    pub(crate) split: Option<Box<super::pieces::SplitPieces>>,
    /// With `split_crossings` and arcs: the arc pieces' input arcs.
    pub(crate) split_arcs: Option<Box<super::pieces::SplitPieces>>,
}
