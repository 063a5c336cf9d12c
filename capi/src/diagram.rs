//! `segvoronoi_diagram`: read access to a built diagram.

use std::ffi::c_char;
use std::sync::Arc;

use super::out::{require_buffer, versioned, write_buffer, write_out, write_versioned};
use super::plumbing::{
    fail, guard, guard_or, into_c_string, out_of_range, require_non_null, segvoronoi_status, try_box, unknown_variant,
};
use segvoronoi::ZERO_LENGTH;
use segvoronoi::{Diagram, EdgeEnd, EdgeId, Site, SiteId, TopologyOptions, VertexId};

/// Marks an edge end at infinity in `segvoronoi_edge_end::vertex`.
pub const SEGVORONOI_NO_VERTEX: u32 = u32::MAX;

/// "No site": pass as the hint of `segvoronoi_diagram_nearest_site` to start
/// anywhere.
pub const SEGVORONOI_NO_SITE: u32 = u32::MAX;

/// Flag for `segvoronoi_diagram_topology`: add the `VPAIRS` and `VVERTICES`
/// sections (positive-length edges; vertices merged across zero-length edges).
pub const SEGVORONOI_TOPOLOGY_VORONOI_PAIRS: u32 = 1;

/// Flag for `segvoronoi_diagram_topology`: in `VPAIRS` and `VVERTICES`, also
/// take edges shorter than 1e-9 of the input's bounding-box diagonal as
/// zero-length (by default only edges whose sites are exactly cocircular).
pub const SEGVORONOI_TOPOLOGY_ZERO_LENGTH_TOLERANCE: u32 = 2;

/// Flag for `segvoronoi_diagram_topology`: in `EDGES` and `FACES`, cut every
/// degenerate vertex (four or more sites on one circle) one way, the same
/// whatever the input's order or the build's thread count (by default they
/// list the diagram's own vertices, which depend on both).
pub const SEGVORONOI_TOPOLOGY_CANONICAL_CUTS: u32 = 4;

/// A built Voronoi diagram. Opaque and immutable. Free with
/// `segvoronoi_diagram_free`.
///
/// Thread safety: any number of threads may read one diagram at once
/// (every query takes `const segvoronoi_diagram *` and changes nothing);
/// `segvoronoi_diagram_free` must not overlap any other call on it. A
/// medial axis made from it shares it (see `segvoronoi_medial_axis`), so the
/// diagram may be freed first.
pub struct segvoronoi_diagram {
    /// Shared with the medial axes made from it, which outlive this handle.
    inner: Arc<Diagram>,
}

// The promise above, checked: the diagram may be read from many threads,
// and a shared medial axis may drop the last reference on any thread.
const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<Diagram>();
};

impl segvoronoi_diagram {
    /// A new handle for C; `None` when there is no memory for it.
    pub(crate) fn into_raw(d: Diagram) -> Option<*mut segvoronoi_diagram> {
        try_box(segvoronoi_diagram { inner: Arc::new(d) })
    }

    /// The diagram, shared (for a medial axis that keeps it alive).
    pub(super) fn shared(&self) -> Arc<Diagram> {
        Arc::clone(&self.inner)
    }
}

/// A site: a point, an open segment or an open circular arc. Versioned: set
/// `struct_size` before the call (see the header's introduction).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct segvoronoi_site {
    /// Set by the caller to `sizeof(segvoronoi_site)`; the library writes
    /// the fields that fit and sets it to the number of bytes written.
    pub struct_size: usize,
    /// `SEGVORONOI_SITE_POINT`, `SEGVORONOI_SITE_SEGMENT` or
    /// `SEGVORONOI_SITE_ARC`; more kinds may come, so treat an unknown one
    /// as "none of these".
    pub kind: u32,
    /// The point, or the segment's first endpoint, or the arc's start, in
    /// input coordinates.
    pub x: f64,
    /// The point, or the segment's first endpoint, or the arc's start, in
    /// input coordinates.
    pub y: f64,
    /// The segment's second endpoint or the arc's end (the point again for
    /// a point site).
    pub x2: f64,
    /// The segment's second endpoint or the arc's end (the point again for
    /// a point site).
    pub y2: f64,
}
versioned!(segvoronoi_site, y2: f64);

/// `segvoronoi_site.kind` of a point site.
pub const SEGVORONOI_SITE_POINT: u32 = 0;
/// `segvoronoi_site.kind` of an open-segment site (its endpoints are point
/// sites of their own).
pub const SEGVORONOI_SITE_SEGMENT: u32 = 1;
/// `segvoronoi_site.kind` of an open circular-arc site (its endpoints are
/// point sites of their own; `segvoronoi_diagram_arc` gives its circle).
/// Arc sites are the last ids, after the open segments. Since 0.2.
pub const SEGVORONOI_SITE_ARC: u32 = 2;

/// A finite Voronoi vertex. Versioned: set `struct_size` before the call
/// (see the header's introduction).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct segvoronoi_vertex {
    /// Set by the caller to `sizeof(segvoronoi_vertex)`; the library writes
    /// the fields that fit and sets it to the number of bytes written.
    pub struct_size: usize,
    /// Position, in input coordinates.
    pub x: f64,
    /// Position, in input coordinates.
    pub y: f64,
    /// Distance from the vertex to each of its sites. Infinite for a
    /// vertex whose position lies beyond the range of `double` (inputs
    /// whose magnitudes span nearly all of it, such as 5e-324 beside
    /// ordinary coordinates): `x` and `y` are then the nearest `double`
    /// point, each coordinate beyond the range saturated at `±DBL_MAX`.
    pub clearance: f64,
    /// The three sites whose cells meet here, counter-clockwise.
    pub sites: [u32; 3],
}
versioned!(segvoronoi_vertex, sites: [u32; 3]);

/// One end of an edge: a finite vertex, or a direction to infinity. Part of
/// `segvoronoi_edge`; this struct never gains fields.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default)]
pub struct segvoronoi_edge_end {
    /// The vertex id, or `SEGVORONOI_NO_VERTEX` if this end is at infinity.
    pub vertex: u32,
    /// The vertex position, or the unit direction of the edge at infinity.
    pub x: f64,
    /// The vertex position, or the unit direction of the edge at infinity.
    pub y: f64,
}

/// A Voronoi edge between two sites: a segment, a ray (one end at infinity)
/// or a whole line (both ends at infinity; all sites collinear). Versioned:
/// set `struct_size` before the call (see the header's introduction).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct segvoronoi_edge {
    /// Set by the caller to `sizeof(segvoronoi_edge)`; the library writes
    /// the fields that fit and sets it to the number of bytes written.
    pub struct_size: usize,
    /// The site on the left and the site on the right, going from
    /// `ends[0]` to `ends[1]`.
    pub sites: [u32; 2],
    /// Start and end.
    pub ends: [segvoronoi_edge_end; 2],
    /// `true` when the edge is unbounded: a ray or a line, with an end at
    /// infinity (`vertex == SEGVORONOI_NO_VERTEX`).
    pub is_infinite: bool,
    /// `true` when the edge is a separator: between a segment or an arc and
    /// one of its own endpoints (the medial axis leaves these out). Since 0.2.
    pub is_separator: bool,
}
versioned!(segvoronoi_edge, is_infinite: bool);

/// Counts from the build. Versioned: set `struct_size` before the call (see
/// the header's introduction); more counts may come.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct segvoronoi_stats {
    /// Set by the caller to `sizeof(segvoronoi_stats)`; the library writes
    /// the fields that fit and sets it to the number of bytes written.
    pub struct_size: usize,
    /// Points given to the builder.
    pub input_points: usize,
    /// Segments given to the builder.
    pub input_segments: usize,
    /// Distinct sites in the diagram (points, then open segments, then open
    /// arcs).
    pub sites: usize,
    /// Input points merged into an equal earlier point or segment endpoint.
    pub duplicate_points: usize,
    /// Input segments merged into an equal earlier segment.
    pub duplicate_segments: usize,
    /// Input segments of zero length (they became points).
    pub zero_length_segments: usize,
    /// Finite Voronoi vertices.
    pub vertices: usize,
    /// Voronoi edges between two sites.
    pub edges: usize,
    /// Points of polygons and polylines dropped because they repeated the
    /// point before them (a ring's repeated closing point is not counted).
    pub dropped_chain_points: usize,
    /// Segments the diagram was built from: the input segments, or with
    /// splitting the pieces.
    pub pieces: usize,
    /// With splitting: pairs of input segments that crossed.
    pub crossings: usize,
    /// With splitting: pairs of collinear input segments that overlapped.
    pub overlaps: usize,
    /// With splitting: endpoints and points that lay inside a segment.
    pub touchings: usize,
    /// With splitting: rounds of snapping run.
    pub snap_rounds: usize,
    /// Without splitting: input vertices (segment endpoints, zero-length
    /// segments, isolated points) that lay inside an input segment, which
    /// was cut there exactly, per (vertex, segment) pair. Since 0.2.
    pub split_at_vertices: usize,
    /// Without splitting: pieces of polygon rings dropped because they
    /// cancelled in pairs (two copies of one shared stretch; always even).
    /// Since 0.2.
    pub cancelled_ring_pieces: usize,
    /// Arcs given to the builder (`segvoronoi_builder_add_arc` and the arcs
    /// of bulged polylines). Since 0.2.
    pub input_arcs: usize,
    /// Open-arc sites in the diagram: the last `arc_sites` site ids. Since 0.2.
    pub arc_sites: usize,
}
versioned!(segvoronoi_stats, edges: usize);

/// Runs `f` on the diagram behind a checked, non-null pointer.
pub(super) fn with_diagram(
    diagram: *const segvoronoi_diagram,
    f: impl FnOnce(&Diagram) -> segvoronoi_status,
) -> segvoronoi_status {
    require_non_null!(diagram);
    // SAFETY: non-null, and the caller passes a live diagram (not freed);
    // it is only read, which any number of threads may do at once.
    guard(|| f(&unsafe { &*diagram }.inner))
}

pub(super) fn count(diagram: *const segvoronoi_diagram, f: impl FnOnce(&Diagram) -> usize) -> usize {
    if diagram.is_null() {
        return 0;
    }
    // SAFETY: non-null live diagram, only read.
    guard_or(0, || f(&unsafe { &*diagram }.inner))
}

/// Frees a diagram. NULL does nothing. Medial axes made from it stay valid
/// (they share the diagram); offsets hold copies of their own.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_free(diagram: *mut segvoronoi_diagram) {
    if diagram.is_null() {
        return;
    }
    // SAFETY: the caller passes a diagram from `segvoronoi_builder_build`
    // (made by `try_box`, which `Box::from_raw` may free), not freed yet and
    // in use by no other call. Medial axes keep their own `Arc` of it.
    guard_or((), || drop(unsafe { Box::from_raw(diagram) }))
}

/// Checks every topological invariant. `SEGVORONOI_STATUS_OK` for every
/// diagram the library builds; `SEGVORONOI_STATUS_INTERNAL` would be a bug.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_validate(diagram: *const segvoronoi_diagram) -> segvoronoi_status {
    with_diagram(diagram, |d| match d.validate() {
        Ok(()) => segvoronoi_status::Ok,
        Err(e) => fail(segvoronoi_status::Internal, format!("the diagram is invalid ({e:?}); please report the input")),
    })
}

/// Number of sites (distinct points, then open segments, then open arcs); 0
/// for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_site_count(diagram: *const segvoronoi_diagram) -> usize {
    count(diagram, Diagram::site_count)
}

/// Number of point sites; sites `0..point_site_count` are points, the rest
/// open segments and then open arcs (`segvoronoi_diagram_arc_site_count`).
/// 0 for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_point_site_count(diagram: *const segvoronoi_diagram) -> usize {
    count(diagram, Diagram::point_site_count)
}

/// Number of finite Voronoi vertices; 0 for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_vertex_count(diagram: *const segvoronoi_diagram) -> usize {
    count(diagram, Diagram::vertex_count)
}

/// Number of Voronoi edges; 0 for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_edge_count(diagram: *const segvoronoi_diagram) -> usize {
    count(diagram, Diagram::edge_count)
}

/// Site `index` (`0 <= index < site_count`) in `*out`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`, `INVALID_ARGUMENT`
/// (`out->struct_size` too small); then `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_site(
    diagram: *const segvoronoi_diagram,
    index: usize,
    out: *mut segvoronoi_site,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| {
        let Some(site) = site_id(d, index).and_then(|s| d.site(s)) else {
            return out_of_range("site", index, d.site_count());
        };
        let (kind, [a, b]) = match site {
            Site::Point(p) => (SEGVORONOI_SITE_POINT, [p, p]),
            Site::Segment { a, b } => (SEGVORONOI_SITE_SEGMENT, [a, b]),
            Site::Arc(arc) => (SEGVORONOI_SITE_ARC, [arc.start(), arc.end()]),
            _ => return unknown_variant("a site kind"),
        };
        write_versioned(out, segvoronoi_site { kind, x: a.x, y: a.y, x2: b.x, y2: b.y, ..Default::default() })
    })
}

/// An edge's end as C sees it: the vertex and its position, or
/// `SEGVORONOI_NO_VERTEX` and the unit direction to infinity.
pub(super) fn edge_end(d: &Diagram, end: EdgeEnd) -> segvoronoi_edge_end {
    match end {
        EdgeEnd::Vertex(v) => {
            let p = d.vertex(v).map(|v| v.position).unwrap_or_default();
            segvoronoi_edge_end { vertex: v.index() as u32, x: p.x, y: p.y }
        }
        EdgeEnd::Infinite { direction } => segvoronoi_edge_end { vertex: SEGVORONOI_NO_VERTEX, x: direction.x, y: direction.y },
    }
}

/// The site id of a C index, if in range.
pub(super) fn site_id(d: &Diagram, index: usize) -> Option<SiteId> {
    (index < d.site_count()).then(|| SiteId::from_index(index))
}

/// Runs `f` on the cell of site `site`: `OUT_OF_RANGE` past the sites.
fn with_cell(
    d: *const segvoronoi_diagram,
    site: usize,
    f: impl FnOnce(segvoronoi::Cell<'_>) -> segvoronoi_status,
) -> segvoronoi_status {
    with_diagram(d, |d| match site_id(d, site).and_then(|s| d.cell(s)) {
        Some(cell) => f(cell),
        None => out_of_range("site", site, d.site_count()),
    })
}

/// The id of segment or arc site `index`: `OUT_OF_RANGE` past the sites,
/// `INVALID_ARGUMENT` for a point site, and for an arc site unless
/// `arcs_too`.
fn segment_site_id(d: &Diagram, index: usize, arcs_too: bool) -> Result<SiteId, segvoronoi_status> {
    match site_id(d, index) {
        None => Err(out_of_range("site", index, d.site_count())),
        Some(_) if index < d.point_site_count() => Err(fail(
            segvoronoi_status::InvalidArgument,
            format!("site {index} is a point site, not a segment (sites 0..{} are points)", d.point_site_count()),
        )),
        Some(s) if !arcs_too && matches!(d.site(s), Some(Site::Arc(_))) => Err(fail(
            segvoronoi_status::InvalidArgument,
            format!("site {index} is an arc site, not a segment (see segvoronoi_diagram_arc_input_index)"),
        )),
        Some(s) => Ok(s),
    }
}

/// The two endpoint sites of segment or arc site `site` in
/// `out_endpoints[0]` and `out_endpoints[1]` (`out_endpoints` points to two
/// `uint32_t`): the point sites at `(x, y)` and at `(x2, y2)` of its
/// `segvoronoi_site` (an arc's start and end).
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (`site >= site_count`),
/// `INVALID_ARGUMENT` (a point site); then nothing is written.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_segment_endpoints(
    diagram: *const segvoronoi_diagram,
    site: usize,
    out_endpoints: *mut u32,
) -> segvoronoi_status {
    require_non_null!(out_endpoints);
    with_diagram(diagram, |d| {
        let ends = match segment_site_id(d, site, true).map(|s| d.segment_endpoints(s)) {
            Ok(Some(ends)) => ends,
            Ok(None) => {
                return fail(
                    segvoronoi_status::Internal,
                    format!("segment site {site} has no endpoints; please report the input"),
                )
            }
            Err(status) => return status,
        };
        write_out(out_endpoints.cast::<[u32; 2]>(), ends.map(|s| s.index() as u32))
    })
}

/// The input index of segment site `site` in `*out_index`: which
/// `segvoronoi_builder_add_segment(s)` input it is (the first of its
/// repeats; what the topology text calls `S<j>`). An arc site's input index
/// is `segvoronoi_diagram_arc_input_index`'s.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (`site >= site_count`),
/// `INVALID_ARGUMENT` (a point or arc site); then nothing is written.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_segment_input_index(
    diagram: *const segvoronoi_diagram,
    site: usize,
    out_index: *mut usize,
) -> segvoronoi_status {
    require_non_null!(out_index);
    with_diagram(diagram, |d| match segment_site_id(d, site, false).map(|s| d.segment_input_index(s)) {
        Ok(Some(j)) => write_out(out_index, j),
        Ok(None) => fail(segvoronoi_status::Internal, format!("segment site {site} has no input index; please report the input")),
        Err(status) => status,
    })
}

/// The site that input point `input_index` became (equal points share a site).
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_site_of_input(
    diagram: *const segvoronoi_diagram,
    input_index: usize,
    out_site: *mut u32,
) -> segvoronoi_status {
    require_non_null!(out_site);
    with_diagram(diagram, |d| match d.site_of_input(input_index) {
        Some(s) => write_out(out_site, s.index() as u32),
        None => out_of_range("input point", input_index, d.stats().input_points),
    })
}

/// The site that input segment `input_index` became: its open segment (a
/// repeated segment shares the first one's), or for a zero-length segment
/// the point site it is. With splitting (`segvoronoi_builder_set_split_crossings`)
/// the index is a piece's (see `segvoronoi_diagram_pieces_of_input`).
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_site_of_segment(
    diagram: *const segvoronoi_diagram,
    input_index: usize,
    out_site: *mut u32,
) -> segvoronoi_status {
    require_non_null!(out_site);
    with_diagram(diagram, |d| match d.site_of_segment(input_index) {
        Some(s) => write_out(out_site, s.index() as u32),
        None => out_of_range("segment", input_index, d.piece_count()),
    })
}

/// Vertex `index` (`0 <= index < vertex_count`) in `*out`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`, `INVALID_ARGUMENT`
/// (`out->struct_size` too small); then `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_vertex(
    diagram: *const segvoronoi_diagram,
    index: usize,
    out: *mut segvoronoi_vertex,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| {
        let Some(v) = (index < d.vertex_count()).then(|| d.vertex(VertexId::from_index(index))).flatten() else {
            return out_of_range("vertex", index, d.vertex_count());
        };
        let sites = v.sites.map(|s| s.index() as u32);
        let (x, y, clearance) = (v.position.x, v.position.y, v.clearance);
        write_versioned(out, segvoronoi_vertex { x, y, clearance, sites, ..Default::default() })
    })
}

/// Edge `index` (`0 <= index < edge_count`) in `*out`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`, `INVALID_ARGUMENT`
/// (`out->struct_size` too small); then `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_edge(
    diagram: *const segvoronoi_diagram,
    index: usize,
    out: *mut segvoronoi_edge,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| {
        let Some(e) = (index < d.edge_count()).then(|| d.edge(EdgeId::from_index(index))).flatten() else {
            return out_of_range("edge", index, d.edge_count());
        };
        let (sites, ends) = (e.sites.map(|s| s.index() as u32), e.ends.map(|end| edge_end(d, end)));
        let is_separator = d.is_separator(e.id).unwrap_or(false);
        write_versioned(out, segvoronoi_edge { sites, ends, is_infinite: e.is_infinite(), is_separator, ..Default::default() })
    })
}

/// The ids of the edges around the cell of site `site`, counter-clockwise
/// (an unbounded cell has two rays or lines among them).
/// Writes up to `capacity` ids to `edges` and the full number to `*count`;
/// `edges = NULL, capacity = 0` only counts (`OK`).
///
/// Errors: `NULL_ARGUMENT` (`count` NULL, or `edges` NULL with
/// `capacity > 0`), `OUT_OF_RANGE`, `BUFFER_TOO_SMALL` (then `*count` holds
/// the number needed and the first `capacity` ids are written).
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_cell_edges(
    diagram: *const segvoronoi_diagram,
    site: usize,
    edges: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    require_buffer!(edges, capacity, count);
    with_cell(diagram, site, |cell| write_buffer(cell.edges().map(|e| e.index() as u32), edges, capacity, count))
}

/// The sites whose cells border the cell of site `site`, counter-clockwise,
/// one per edge of `segvoronoi_diagram_cell_edges` and in its order.
/// Buffer rules as there: up to `capacity` ids to `sites`, the full number
/// to `*count`; `sites = NULL, capacity = 0` only counts (`OK`).
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`, `BUFFER_TOO_SMALL`.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_cell_neighbors(
    diagram: *const segvoronoi_diagram,
    site: usize,
    sites: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    require_buffer!(sites, capacity, count);
    with_cell(diagram, site, |cell| write_buffer(cell.neighbors().map(|s| s.index() as u32), sites, capacity, count))
}

/// Whether the cell of site `site` is unbounded (reaches infinity: the site
/// is on the convex hull of the input), in `*out`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_cell_is_unbounded(
    diagram: *const segvoronoi_diagram,
    site: usize,
    out: *mut bool,
) -> segvoronoi_status {
    require_non_null!(out);
    with_cell(diagram, site, |cell| write_out(out, cell.is_unbounded()))
}

/// The site nearest to `(x, y)` (whose cell contains the point; on a cell
/// boundary any of the tied sites) in `*out_site`. The search walks the
/// diagram from site `hint` (`SEGVORONOI_NO_SITE` for none); the answer of a
/// previous query near `(x, y)` makes a good hint.
///
/// Errors: `NULL_ARGUMENT`, `INVALID_COORDINATE` (`x` or `y` not finite),
/// `OUT_OF_RANGE` (the diagram has no sites, or `hint` is neither a site nor
/// `SEGVORONOI_NO_SITE`).
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_nearest_site(
    diagram: *const segvoronoi_diagram,
    x: f64,
    y: f64,
    hint: u32,
    out_site: *mut u32,
) -> segvoronoi_status {
    require_non_null!(out_site);
    with_diagram(diagram, |d| {
        let p = segvoronoi::Point::new(x, y);
        if !p.is_finite() {
            return fail(segvoronoi_status::InvalidCoordinate, format!("the query point ({x}, {y}) is not finite"));
        }
        let hint = match hint {
            SEGVORONOI_NO_SITE => None,
            h => match site_id(d, h as usize) {
                Some(s) => Some(s),
                None => return out_of_range("hint site", h as usize, d.site_count()),
            },
        };
        match d.nearest_site(p, hint) {
            Some(s) => write_out(out_site, s.index() as u32),
            None => fail(segvoronoi_status::OutOfRange, "the diagram has no sites"),
        }
    })
}

/// Counts from the build in `*out`.
///
/// Errors: `NULL_ARGUMENT`, `INVALID_ARGUMENT` (`out->struct_size` too
/// small); then `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_stats(
    diagram: *const segvoronoi_diagram,
    out: *mut segvoronoi_stats,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| {
        let s = d.stats();
        write_versioned(
            out,
            segvoronoi_stats {
                struct_size: 0,
                input_points: s.input_points,
                input_segments: s.input_segments,
                sites: s.sites,
                duplicate_points: s.duplicate_points,
                duplicate_segments: s.duplicate_segments,
                zero_length_segments: s.zero_length_segments,
                vertices: s.vertices,
                edges: s.edges,
                dropped_chain_points: s.dropped_chain_points,
                pieces: s.pieces,
                crossings: s.crossings,
                overlaps: s.overlaps,
                touchings: s.touchings,
                snap_rounds: s.snap_rounds,
                split_at_vertices: s.split_at_vertices,
                cancelled_ring_pieces: s.cancelled_ring_pieces,
                input_arcs: s.input_arcs,
                arc_sites: d.arc_site_count(),
            },
        )
    })
}

/// The diagonal of the input's bounding box, in input units, in `*out`: the
/// scale of `SEGVORONOI_TOPOLOGY_ZERO_LENGTH_TOLERANCE` (0 for fewer than
/// two distinct points).
///
/// Errors: `NULL_ARGUMENT`.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_extent(diagram: *const segvoronoi_diagram, out: *mut f64) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| write_out(out, d.extent()))
}

/// The canonical topology text (`EDGES`, `FACES`, and with
/// `SEGVORONOI_TOPOLOGY_VORONOI_PAIRS` in `flags` also `VPAIRS`,
/// `VVERTICES`, with zero length decided exactly unless
/// `SEGVORONOI_TOPOLOGY_ZERO_LENGTH_TOLERANCE` is set too; with
/// `SEGVORONOI_TOPOLOGY_CANONICAL_CUTS`, degenerate vertices cut one way):
/// NUL-terminated in `*text`, its length without the NUL in `*length`
/// (`length` may be NULL).
///
/// Ownership: the caller owns `*text` and frees it with
/// `segvoronoi_string_free`. On error `*text` is set to NULL.
/// Errors: `NULL_ARGUMENT`, `INVALID_ARGUMENT` (unknown flag bits).
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_topology(
    diagram: *const segvoronoi_diagram,
    flags: u32,
    text: *mut *mut c_char,
    length: *mut usize,
) -> segvoronoi_status {
    require_non_null!(text);
    // SAFETY: text is non-null and writable.
    unsafe { *text = std::ptr::null_mut() };
    let known =
        SEGVORONOI_TOPOLOGY_VORONOI_PAIRS | SEGVORONOI_TOPOLOGY_ZERO_LENGTH_TOLERANCE | SEGVORONOI_TOPOLOGY_CANONICAL_CUTS;
    let unknown = flags & !known;
    if unknown != 0 {
        return fail(segvoronoi_status::InvalidArgument, format!("unknown flag bits {unknown:#x} in `flags`"));
    }
    with_diagram(diagram, |d| {
        let options = TopologyOptions::default()
            .with_voronoi_pairs(flags & SEGVORONOI_TOPOLOGY_VORONOI_PAIRS != 0)
            .with_zero_length_tolerance((flags & SEGVORONOI_TOPOLOGY_ZERO_LENGTH_TOLERANCE != 0).then_some(ZERO_LENGTH))
            .with_canonical_cuts(flags & SEGVORONOI_TOPOLOGY_CANONICAL_CUTS != 0);
        let (ptr, len) = into_c_string(d.topology(options));
        if !length.is_null() {
            write_out(length, len);
        }
        write_out(text, ptr)
    })
}
