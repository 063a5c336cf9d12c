//! Circular arcs in C: adding them to a builder (by bulge, through a third
//! point, or as the pieces of a bulged polyline, DXF's LWPOLYLINE), and
//! reading the arc sites of a diagram. Delegates to `CircularArc`,
//! `Builder::add_arc`, `Builder::add_bulged_polyline`,
//! `Builder::add_bulged_polygon`,
//! `Diagram::arc_input_index` and `Diagram::site_of_arc`.
//!
//! An arc is three sites, as a segment is: its two endpoints (point sites)
//! and the open arc, a site of kind `SEGVORONOI_SITE_ARC`. Arc sites are the
//! last site ids, after the open segments. Arcs have input indices of their
//! own (the number of arcs added before), apart from points and segments.

use super::builder::segvoronoi_builder;
use super::diagram::{count, segvoronoi_diagram, site_id, with_diagram, SEGVORONOI_SITE_ARC, SEGVORONOI_SITE_SEGMENT};
use super::out::{versioned, write_out, write_versioned};
use super::plumbing::{fail, guard, guard_or, out_of_range, require_non_null, segvoronoi_status};
use segvoronoi::{Builder, ChainPiece, CircularArc, Diagram, Error, Site};

/// A circular arc, as added or as a diagram's arc site. Versioned: set
/// `struct_size` before the call (see the header's introduction).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct segvoronoi_arc {
    /// Set by the caller to `sizeof(segvoronoi_arc)`; the library writes
    /// the fields that fit and sets it to the number of bytes written.
    pub struct_size: usize,
    /// The first endpoint `{x, y}`, exactly as given.
    pub start: [f64; 2],
    /// The last endpoint `{x, y}`, exactly as given.
    pub end: [f64; 2],
    /// The centre of the circle `{x, y}`, rounded to `double` from the
    /// exact circle that the endpoints and the bulge (or third point) fix.
    pub centre: [f64; 2],
    /// The radius, rounded (the mean of the rounded centre's distances to
    /// the two endpoints).
    pub radius: f64,
    /// DXF's bulge, `tan(sweep / 4)`: as given to
    /// `segvoronoi_builder_add_arc`, or for an arc given through a point the
    /// bulge of that arc, rounded.
    pub bulge: f64,
    /// The signed angle swept from `start` to `end`, in radians, in
    /// `(-2π, 2π)`: positive counter-clockwise (`4 atan(bulge)` for an arc
    /// given by its bulge).
    pub sweep: f64,
    /// Whether the arc runs counter-clockwise from `start` to `end`.
    pub counter_clockwise: bool,
    /// Whether the arc was given through a third point
    /// (`segvoronoi_builder_add_arc_through`): `via` holds it.
    pub has_via: bool,
    /// The point the arc was given through `{x, y}`, exactly; `{0, 0}` when
    /// `has_via` is false.
    pub via: [f64; 2],
}
versioned!(segvoronoi_arc, via: [f64; 2]);

impl From<CircularArc> for segvoronoi_arc {
    fn from(arc: CircularArc) -> Self {
        let via = arc.via();
        // From the bulge as given, `4 atan(bulge)`, always within (-2π, 2π);
        // `CircularArc::sweep` measures the angles about the rounded centre,
        // which for an arc of a few ulps can make a half turn a whole one.
        let sweep = if via.is_none() { 4.0 * arc.bulge().atan() } else { arc.sweep() };
        segvoronoi_arc {
            start: arc.start().into(),
            end: arc.end().into(),
            centre: arc.centre().into(),
            radius: arc.radius(),
            bulge: arc.bulge(),
            sweep,
            counter_clockwise: arc.is_counter_clockwise(),
            has_via: via.is_some(),
            via: via.map_or([0.0; 2], Into::into),
            ..Default::default()
        }
    }
}

/// Adds the arc that `make` makes as input arc `arc_count`: a non-finite
/// coordinate is `INVALID_COORDINATE` (as for segments), an arc that is no
/// arc `INVALID_ARC`, both naming the arc's input index; the index to
/// `*index_out` (when not NULL) on success.
///
/// Safety: `builder` is NULL or a live builder used by this thread only;
/// `index_out` is NULL or writable.
unsafe fn add_one_arc(
    builder: *mut segvoronoi_builder,
    coords: &[f64],
    make: impl FnOnce() -> Result<CircularArc, Error>,
    index_out: *mut usize,
) -> segvoronoi_status {
    require_non_null!(builder);
    guard(|| {
        // SAFETY: non-null, and the caller passes a live builder used by this thread only.
        let b = unsafe { &mut *builder };
        let index = b.inner.arc_count();
        if !coords.iter().all(|c| c.is_finite()) {
            let list = coords.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(", ");
            let message = format!("arc {index} has a non-finite coordinate ({list})");
            return b.refuse_naming(segvoronoi_status::InvalidCoordinate, &message, vec![index]);
        }
        let arc = match make() {
            Ok(arc) => arc,
            Err(e) => {
                let message = format!("arc {index}: {}", e.message());
                return b.refuse_naming(segvoronoi_status::from(&e), &message, vec![index]);
            }
        };
        match b.inner.add_arc(arc) {
            Ok(i) => {
                let status = b.record(Ok(()));
                if !index_out.is_null() {
                    write_out(index_out, i);
                }
                status
            }
            Err(e) => b.record(Err(e)),
        }
    })
}

/// Adds the circular arc from `(sx, sy)` to `(ex, ey)` with DXF's `bulge`:
/// `tan(θ/4)` for the signed angle θ it sweeps (positive:
/// counter-clockwise; 1 is a half circle counter-clockwise, -1 clockwise;
/// the sweep nears a full turn as `|bulge|` grows). Its endpoints are exact
/// input points, shared with the segments and arcs that continue it. Its
/// input index (the number of arcs added before it; arcs are numbered
/// apart from points and segments) goes to `*index_out`. Crossings are
/// reported by `segvoronoi_builder_build` and `segvoronoi_builder_check`.
///
/// Ownership: `index_out` is caller-owned; it may be NULL (the index is
/// `segvoronoi_builder_arc_count` before the call) and is written only on
/// success.
/// Errors: `NULL_ARGUMENT` (`builder`), `INVALID_COORDINATE` (a coordinate
/// is NaN or infinite), `INVALID_ARC` (the bulge is 0, NaN or infinite, the
/// endpoints are equal, the circle is beyond the range of `double`, or the
/// arc is straight to within the rounding of its centre: a bulge below
/// about 2^-42, whose centre lies over 2^40 chords away; add a segment),
/// `TOO_LARGE`, `OUT_OF_MEMORY`. The builder is then unchanged, and
/// `segvoronoi_builder_last_error` and `_last_error_indices` name the
/// index the arc would have had.
/// Thread safety: one builder must not be used from two threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_add_arc(
    builder: *mut segvoronoi_builder,
    sx: f64,
    sy: f64,
    ex: f64,
    ey: f64,
    bulge: f64,
    index_out: *mut usize,
) -> segvoronoi_status {
    // SAFETY: passed on from the caller.
    unsafe { add_one_arc(builder, &[sx, sy, ex, ey], || CircularArc::from_bulge([sx, sy], [ex, ey], bulge), index_out) }
}

/// Adds the circular arc from `(sx, sy)` through `(vx, vy)` to `(ex, ey)`,
/// as `segvoronoi_builder_add_arc` does; the three points are kept exactly
/// (the circle is fixed by them, not by a rounded bulge).
///
/// Ownership: as `segvoronoi_builder_add_arc`.
/// Errors: `NULL_ARGUMENT` (`builder`), `INVALID_COORDINATE` (a coordinate
/// is NaN or infinite), `INVALID_ARC` (two of the points are equal, the
/// three are on one line, the circle is beyond the range of `double`, or
/// the arc is straight to within the rounding of its centre, as for
/// `segvoronoi_builder_add_arc`),
/// `TOO_LARGE`, `OUT_OF_MEMORY`; the builder is then unchanged and the
/// last error names the arc's index.
/// Thread safety: one builder must not be used from two threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_add_arc_through(
    builder: *mut segvoronoi_builder,
    sx: f64,
    sy: f64,
    vx: f64,
    vy: f64,
    ex: f64,
    ey: f64,
    index_out: *mut usize,
) -> segvoronoi_status {
    // SAFETY: passed on from the caller.
    unsafe { add_one_arc(builder, &[sx, sy, vx, vy, ex, ey], || CircularArc::through([sx, sy], [vx, vy], [ex, ey]), index_out) }
}

/// Adds a chain of `n` vertices with a bulge each, as DXF's LWPOLYLINE
/// holds it: vertex `k` is `(xy[2k], xy[2k+1])`, and the piece from vertex
/// `k` to vertex `k + 1` is a segment where `bulges[k]` is 0 and the arc
/// with that bulge otherwise (see `segvoronoi_builder_add_arc`). With
/// `closed`, the last vertex joins the first with the last bulge (a
/// repeated closing vertex is dropped); open, the last bulge is not used.
/// Repeated consecutive vertices are dropped with their piece. A polyline
/// is an obstacle: it does not bound the domain. Segments and arcs get the
/// next input indices of their own kind, in the chain's order. All or
/// nothing: on error nothing is added.
///
/// What each piece became, in the chain's order, when wanted: piece `j` is
/// `piece_kinds[j]` (`SEGVORONOI_SITE_SEGMENT` or `SEGVORONOI_SITE_ARC`)
/// with input index `piece_indices[j]` among the segments or the arcs; the
/// number of pieces, at most `n`, goes to `*piece_count`. (The counts alone
/// are also the differences of `segvoronoi_builder_segment_count` and
/// `_arc_count` across the call.)
///
/// Ownership: `xy` (`2 * n` doubles) and `bulges` (`n` doubles) are read
/// only during the call; either may be NULL when `n` is 0. `piece_kinds`
/// and `piece_indices` are each NULL (not wanted) or room for `n` items;
/// `piece_count` is NULL or writable. They are written only on success.
/// Errors: `NULL_ARGUMENT` (`builder`, or `xy` or `bulges` NULL with
/// `n > 0`); `INVALID_COORDINATE` (a non-finite coordinate) or
/// `INVALID_ARC` (a non-finite bulge, or a piece that is no arc: equal
/// endpoints cannot happen, a circle beyond `double` can; a bulge so small
/// that its arc is straight to within the rounding of its centre, below
/// about 2^-42, makes a segment), naming the
/// vertex (`segvoronoi_builder_last_error_indices`); `TOO_LARGE` (checked
/// before `xy` is read), `OUT_OF_MEMORY`. The builder is then unchanged.
/// Thread safety: one builder must not be used from two threads at once.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn segvoronoi_builder_add_bulged_polyline(
    builder: *mut segvoronoi_builder,
    xy: *const f64,
    bulges: *const f64,
    n: usize,
    closed: bool,
    piece_kinds: *mut u32,
    piece_indices: *mut usize,
    piece_count: *mut usize,
) -> segvoronoi_status {
    require_non_null!(builder);
    guard(|| {
        // SAFETY: non-null; the caller keeps the builder exclusive.
        let b = unsafe { &mut *builder };
        if n > 0 && xy.is_null() {
            return b.refuse(segvoronoi_status::NullArgument, "argument `xy` is NULL");
        }
        if n > 0 && bulges.is_null() {
            return b.refuse(segvoronoi_status::NullArgument, "argument `bulges` is NULL");
        }
        // The size limit (TOO_LARGE) and the room (OUT_OF_MEMORY) first:
        // `n` is the caller's number. Each piece has two endpoints, as a
        // segment has; this bounds `n` by the diagram's points.
        if let Err(e) = b.inner.reserve_segments(n) {
            return b.record(Err(e));
        }
        // SAFETY: non-null when n > 0 and valid for 2n and n reads (the
        // caller's promise); `reserve_segments` bounded n by MAX_POINTS, so
        // both slices span far less than isize::MAX bytes.
        let (coords, bulges): (&[f64], &[f64]) = if n == 0 {
            (&[], &[])
        } else {
            unsafe { (std::slice::from_raw_parts(xy, 2 * n), std::slice::from_raw_parts(bulges, n)) }
        };
        let mut chain: Vec<([f64; 2], f64)> = Vec::new();
        if chain.try_reserve(n).is_err() {
            return b.refuse(segvoronoi_status::OutOfMemory, &format!("out of memory: no room for {n} polyline vertices"));
        }
        for (k, (p, &bulge)) in coords.chunks_exact(2).zip(bulges).enumerate() {
            if !p[0].is_finite() || !p[1].is_finite() {
                let message = format!("polyline vertex {k} has a non-finite coordinate ({}, {})", p[0], p[1]);
                return b.refuse_naming(segvoronoi_status::InvalidCoordinate, &message, vec![k]);
            }
            if !bulge.is_finite() {
                let message = format!("polyline vertex {k} has a non-finite bulge ({bulge})");
                return b.refuse_naming(segvoronoi_status::InvalidArc, &message, vec![k]);
            }
            chain.push(([p[0], p[1]], bulge));
        }
        match b.inner.add_bulged_polyline(&chain, closed) {
            Ok(made) => {
                let status = b.record(Ok(()));
                for (j, piece) in made.iter().enumerate().take(n) {
                    let (kind, index) = match *piece {
                        ChainPiece::Segment(i) => (SEGVORONOI_SITE_SEGMENT, i),
                        ChainPiece::Arc(i) => (SEGVORONOI_SITE_ARC, i),
                    };
                    if !piece_kinds.is_null() {
                        // SAFETY: room for n items (the caller's promise); j < n.
                        unsafe { piece_kinds.add(j).write(kind) };
                    }
                    if !piece_indices.is_null() {
                        // SAFETY: as above.
                        unsafe { piece_indices.add(j).write(index) };
                    }
                }
                if !piece_count.is_null() {
                    write_out(piece_count, made.len());
                }
                status
            }
            Err(e) => b.record(Err(e)),
        }
    })
}

/// Adds a polygon whose rings are closed chains of segments and arcs, as
/// DXF's closed LWPOLYLINE holds them: `n_rings` rings, ring `r` of
/// `ring_lengths[r]` vertices, all vertices one after another, vertex `k`
/// at `(xy[2k], xy[2k+1])` with bulge `bulges[k]`. In each ring the piece
/// from a vertex to the next (the last to the first) is a segment where
/// the vertex's bulge is 0 and the arc with that bulge otherwise (see
/// `segvoronoi_builder_add_arc`). The rings bound the domain by the
/// even-odd rule, with those of `segvoronoi_builder_add_polygon`; the
/// domain's location, medial axis and offsets follow the arcs. Repeated
/// consecutive vertices are dropped with their piece, and a repeated
/// closing vertex too. Segments and arcs get the next input indices of
/// their own kind, ring by ring. All or nothing. (`Builder::
/// add_bulged_polygon` in Rust.)
///
/// Ownership: `xy` (`2 * total` doubles, `total` the sum of
/// `ring_lengths`), `bulges` (`total` doubles) and `ring_lengths`
/// (`n_rings` sizes) are read only during the call; each may be NULL when
/// its count is 0.
/// Errors: `NULL_ARGUMENT`; `INVALID_COORDINATE` (a non-finite coordinate
/// or bulge), `INVALID_POLYGON` (a ring of fewer than three distinct
/// vertices, unless two with an arc between them) or `INVALID_ARC` (a bulge
/// that makes no arc), naming the polygon, the ring and the vertex within
/// it (`segvoronoi_builder_last_error_indices`); `TOO_LARGE`,
/// `OUT_OF_MEMORY`. The builder is then unchanged. Rings that cross or
/// overlap are `INTERSECTING` from `segvoronoi_builder_build`; with
/// `segvoronoi_builder_set_split_crossings` they are cut where they meet
/// (arcs into arcs) and bound the even-odd region of the pieces.
/// Thread safety: one builder must not be used from two threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_add_bulged_polygon(
    builder: *mut segvoronoi_builder,
    xy: *const f64,
    bulges: *const f64,
    ring_lengths: *const usize,
    n_rings: usize,
) -> segvoronoi_status {
    require_non_null!(builder);
    guard(|| {
        // SAFETY: non-null; the caller keeps the builder exclusive.
        let b = unsafe { &mut *builder };
        if n_rings > 0 && ring_lengths.is_null() {
            return b.refuse(segvoronoi_status::NullArgument, "argument `ring_lengths` is NULL");
        }
        // Bound the count before it becomes a slice: a ring has a vertex,
        // and a diagram at most MAX_POINTS points.
        if n_rings > segvoronoi::MAX_POINTS {
            let message = format!("{n_rings} rings are too many: a diagram holds at most {} points", segvoronoi::MAX_POINTS);
            return b.refuse(segvoronoi_status::TooLarge, &message);
        }
        // SAFETY: non-null when n_rings > 0 and n_rings readable sizes (the
        // caller's promise), n_rings bounded above.
        let lengths: &[usize] = if n_rings == 0 { &[] } else { unsafe { std::slice::from_raw_parts(ring_lengths, n_rings) } };
        let Some(total) = lengths.iter().try_fold(0usize, |sum, &n| sum.checked_add(n)) else {
            return b.refuse(segvoronoi_status::TooLarge, "the ring lengths add up to more than SIZE_MAX vertices");
        };
        if total > 0 && xy.is_null() {
            return b.refuse(segvoronoi_status::NullArgument, "argument `xy` is NULL");
        }
        if total > 0 && bulges.is_null() {
            return b.refuse(segvoronoi_status::NullArgument, "argument `bulges` is NULL");
        }
        // Each piece has two endpoints, as a segment has: this bounds
        // `total` by the diagram's points before the slices are made.
        if let Err(e) = b.inner.reserve_segments(total) {
            return b.record(Err(e));
        }
        // SAFETY: valid for 2 total and total reads (the caller's promise);
        // `reserve_segments` bounded total by MAX_POINTS.
        let (coords, bulges): (&[f64], &[f64]) = if total == 0 {
            (&[], &[])
        } else {
            unsafe { (std::slice::from_raw_parts(xy, 2 * total), std::slice::from_raw_parts(bulges, total)) }
        };
        let mut rings: Vec<Vec<([f64; 2], f64)>> = Vec::new();
        if rings.try_reserve(lengths.len()).is_err() {
            return b.refuse(segvoronoi_status::OutOfMemory, &format!("out of memory: no room for {} rings", lengths.len()));
        }
        let mut at = 0;
        for &n in lengths {
            let ring = coords[2 * at..2 * (at + n)].chunks_exact(2).zip(&bulges[at..at + n]).map(|(p, &q)| ([p[0], p[1]], q));
            rings.push(ring.collect());
            at += n;
        }
        let r = b.inner.add_bulged_polygon(&rings);
        b.record(r.map(|_| ()))
    })
}

/// The number of arcs added so far (those of bulged polylines included);
/// 0 for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_arc_count(builder: *const segvoronoi_builder) -> usize {
    if builder.is_null() {
        return 0;
    }
    // SAFETY: non-null live builder.
    guard_or(0, || unsafe { &*builder }.inner.arc_count())
}

/// Input arc `index` (`0 <= index < segvoronoi_builder_arc_count`), as
/// added, in `*out`.
///
/// Ownership: `*out` is caller-owned, written only on success.
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`, `INVALID_ARGUMENT`
/// (`out->struct_size` too small); then `*out` is untouched. A success
/// leaves the builder's own last error (`segvoronoi_builder_last_error`) as
/// it was.
/// Thread safety: one builder must not be used from two threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_builder_arc(
    builder: *const segvoronoi_builder,
    index: usize,
    out: *mut segvoronoi_arc,
) -> segvoronoi_status {
    require_non_null!(builder, out);
    guard(|| {
        // SAFETY: non-null live builder, only read.
        let b: &Builder = &unsafe { &*builder }.inner;
        match b.arc(index) {
            Some(arc) => write_versioned(out, arc.into()),
            None => out_of_range("arc", index, b.arc_count()),
        }
    })
}

/// Number of arc sites: the last site ids, after the open segments
/// (`site_count - arc_site_count <= id < site_count`). 0 for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_arc_site_count(diagram: *const segvoronoi_diagram) -> usize {
    count(diagram, Diagram::arc_site_count)
}

/// The arc of the arc site `site` in `*out`: its endpoints (those of its
/// `segvoronoi_site`), circle, bulge, sweep and direction.
///
/// Ownership: `*out` is caller-owned, written only on success.
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (`site >= site_count`),
/// `INVALID_ARGUMENT` (a point or segment site, or `out->struct_size` too
/// small); then `*out` is untouched.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_arc(
    diagram: *const segvoronoi_diagram,
    site: usize,
    out: *mut segvoronoi_arc,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| match arc_of_site(d, site) {
        Ok(arc) => write_versioned(out, arc.into()),
        Err(status) => status,
    })
}

/// The input index of the arc site `site` in `*out_index`: which
/// `segvoronoi_builder_add_arc` (or `_add_arc_through`, or arc of a bulged
/// polyline) it is; with splitting, which arc piece
/// (`segvoronoi_diagram_inputs_of_arc_piece` gives its input arcs).
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (`site >= site_count`),
/// `INVALID_ARGUMENT` (a point or segment site); then nothing is written.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_arc_input_index(
    diagram: *const segvoronoi_diagram,
    site: usize,
    out_index: *mut usize,
) -> segvoronoi_status {
    require_non_null!(out_index);
    with_diagram(diagram, |d| {
        if let Err(status) = arc_of_site(d, site) {
            return status;
        }
        match site_id(d, site).and_then(|s| d.arc_input_index(s)) {
            Some(j) => write_out(out_index, j),
            None => fail(segvoronoi_status::Internal, format!("arc site {site} has no input index; please report the input")),
        }
    })
}

/// The site that input arc `input_index` became, in `*out_site`; with
/// splitting, the site of arc piece `input_index` (below
/// `segvoronoi_diagram_arc_site_count`; `segvoronoi_diagram_arc_pieces_of_input`
/// gives an input arc's pieces).
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (no such input arc or arc
/// piece); then nothing is written.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_site_of_arc(
    diagram: *const segvoronoi_diagram,
    input_index: usize,
    out_site: *mut u32,
) -> segvoronoi_status {
    require_non_null!(out_site);
    with_diagram(diagram, |d| match d.site_of_arc(input_index) {
        Some(s) => write_out(out_site, s.index() as u32),
        None => out_of_range("input arc (an arc piece, with splitting)", input_index, d.arc_site_count()),
    })
}

/// The arc of site `index`: `OUT_OF_RANGE` past the sites,
/// `INVALID_ARGUMENT` for a point or segment site.
pub(crate) fn arc_of_site(d: &Diagram, index: usize) -> Result<CircularArc, segvoronoi_status> {
    match site_id(d, index).and_then(|s| d.site(s)) {
        None => Err(out_of_range("site", index, d.site_count())),
        Some(Site::Arc(arc)) => Ok(arc),
        Some(other) => {
            let kind = if matches!(other, Site::Point(_)) { "a point" } else { "a segment" };
            let first = d.site_count() - d.arc_site_count();
            let arcs = match d.arc_site_count() {
                0 => "the diagram has no arc sites".to_string(),
                _ => format!("arc sites are {first} to {}", d.site_count() - 1),
            };
            Err(fail(segvoronoi_status::InvalidArgument, format!("site {index} is {kind} site, not an arc ({arcs})")))
        }
    }
}
