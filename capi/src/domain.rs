//! The domain and the medial axis's largest disk in C: where a vertex,
//! edge, cell or point lies (`SEGVORONOI_LOCATION_*`), and the maximum
//! inscribed circle, over the domain and per component. Delegates to
//! `Diagram::vertex_location`, `edge_location`, `cell_location`,
//! `locate_point`, `max_inscribed_circle` and `inscribed_circles`.

use super::diagram::{count, segvoronoi_diagram, with_diagram};
use super::out::{require_buffer, write_buffer, write_out};
use super::plumbing::{fail, out_of_range, require_non_null, segvoronoi_status};
use segvoronoi::{Diagram, EdgeId, Location, Point, SiteId, VertexId};

/// In the domain's interior.
pub const SEGVORONOI_LOCATION_INSIDE: u32 = 0;
/// Outside the domain.
pub const SEGVORONOI_LOCATION_OUTSIDE: u32 = 1;
/// On its boundary: a vertex at a ring corner, the cell of a ring's segment
/// or corner.
pub const SEGVORONOI_LOCATION_BOUNDARY: u32 = 2;

fn code(location: Location) -> u32 {
    match location {
        Location::Inside => SEGVORONOI_LOCATION_INSIDE,
        Location::Outside => SEGVORONOI_LOCATION_OUTSIDE,
        Location::Boundary => SEGVORONOI_LOCATION_BOUNDARY,
    }
}

/// Writes where `ask` says something lies: `INVALID_ARGUMENT` without a
/// domain; `ask`'s own status (with its message) past the ids.
fn locate(
    diagram: *const segvoronoi_diagram,
    out: *mut u32,
    ask: impl FnOnce(&Diagram) -> Result<Location, segvoronoi_status>,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| {
        if !d.has_domain() {
            return no_domain();
        }
        match ask(d) {
            Ok(location) => write_out(out, code(location)),
            Err(status) => status,
        }
    })
}

/// `INVALID_ARGUMENT`: the diagram has no polygon, so nothing has a location.
fn no_domain() -> segvoronoi_status {
    fail(segvoronoi_status::InvalidArgument, "the diagram has no domain: no polygon was added")
}

/// The location of id `index` below `count`, or `OUT_OF_RANGE`.
fn located(
    what: &str,
    index: usize,
    count: usize,
    location: impl FnOnce() -> Option<Location>,
) -> Result<Location, segvoronoi_status> {
    (index < count).then(location).flatten().ok_or_else(|| out_of_range(what, index, count))
}

/// Whether polygons were added (then vertices, edges and cells have a
/// location); false for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_has_domain(diagram: *const segvoronoi_diagram) -> bool {
    // as the counts: no status, so the last error stays as it was
    count(diagram, |d| usize::from(d.has_domain())) != 0
}

/// Where vertex `vertex` lies, a `SEGVORONOI_LOCATION_*`, in `*out`.
///
/// Errors: `NULL_ARGUMENT`, `INVALID_ARGUMENT` (no polygon was added),
/// `OUT_OF_RANGE`; then `*out` is untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_vertex_location(
    diagram: *const segvoronoi_diagram,
    vertex: usize,
    out: *mut u32,
) -> segvoronoi_status {
    locate(diagram, out, |d| located("vertex", vertex, d.vertex_count(), || d.vertex_location(VertexId::from_index(vertex))))
}

/// Where edge `edge` lies (all of it), in `*out`. Errors: as
/// `segvoronoi_diagram_vertex_location`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_edge_location(
    diagram: *const segvoronoi_diagram,
    edge: usize,
    out: *mut u32,
) -> segvoronoi_status {
    locate(diagram, out, |d| located("edge", edge, d.edge_count(), || d.edge_location(EdgeId::from_index(edge))))
}

/// Where the cell of site `site` lies, in `*out`. Errors: as
/// `segvoronoi_diagram_vertex_location`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_cell_location(
    diagram: *const segvoronoi_diagram,
    site: usize,
    out: *mut u32,
) -> segvoronoi_status {
    locate(diagram, out, |d| located("site", site, d.site_count(), || d.cell_location(SiteId::from_index(site))))
}

/// Where the point `(x, y)` lies, exactly (even-odd over every ring), in
/// `*out`. Errors: `NULL_ARGUMENT`, `INVALID_ARGUMENT` (no polygon was
/// added), `INVALID_COORDINATE` (`x` or `y` is NaN or infinite, as for
/// `segvoronoi_diagram_nearest_site`; before 0.2 such a point was
/// answered).
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_locate_point(
    diagram: *const segvoronoi_diagram,
    x: f64,
    y: f64,
    out: *mut u32,
) -> segvoronoi_status {
    let p = Point::new(x, y);
    locate(diagram, out, |d| {
        if !p.is_finite() {
            return Err(fail(segvoronoi_status::InvalidCoordinate, format!("the query point ({x}, {y}) is not finite")));
        }
        d.locate_point(p).ok_or_else(no_domain)
    })
}

/// The largest disk inside the domain: its centre in `*x, *y` and radius in
/// `*r`.
///
/// Errors: `NULL_ARGUMENT`, `INVALID_ARGUMENT` (no polygon was added, or
/// nothing is inside); then the outputs are untouched.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_max_inscribed_circle(
    diagram: *const segvoronoi_diagram,
    x: *mut f64,
    y: *mut f64,
    r: *mut f64,
) -> segvoronoi_status {
    require_non_null!(x, y, r);
    with_diagram(diagram, |d| match d.max_inscribed_circle() {
        Some((centre, radius)) => {
            write_out(x, centre.x);
            write_out(y, centre.y);
            write_out(r, radius)
        }
        None if !d.has_domain() => no_domain(),
        None => fail(segvoronoi_status::InvalidArgument, "nothing is inside the domain"),
    })
}

/// The largest disk inside each connected component of the domain, largest
/// first, each `{x, y, r}`: up to `capacity` circles (`3 * capacity`
/// doubles) to `xyr`, their full number to `*count` (0 without a polygon);
/// `xyr = NULL, capacity = 0` only counts (`OK`).
///
/// Errors: `NULL_ARGUMENT`, `BUFFER_TOO_SMALL` (then `*count` holds the
/// number needed and the first `capacity` circles are written).
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_inscribed_circles(
    diagram: *const segvoronoi_diagram,
    xyr: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    require_buffer!(xyr, capacity, count);
    with_diagram(diagram, |d| {
        let circles = d.inscribed_circles().into_iter().map(|(c, r)| [c.x, c.y, r]);
        // three consecutive doubles per circle: the alignment of an array of them
        write_buffer(circles, xyr.cast::<[f64; 3]>(), capacity, count)
    })
}
