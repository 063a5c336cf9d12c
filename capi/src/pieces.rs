//! The pieces a diagram was built from and the input segments and arcs
//! they came from (`Builder::split_crossings`; without splitting, piece
//! `i` is input segment `i`, arc piece `i` input arc `i`).

use super::diagram::{count, segvoronoi_diagram, with_diagram};
use super::out::{require_buffer, write_buffer, write_out};
use super::plumbing::{out_of_range, require_non_null, segvoronoi_status};
use segvoronoi::{Diagram, Indices};

/// The number of segments the diagram was built from: the pieces of a split
/// input, else the input segments. 0 for NULL.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_piece_count(diagram: *const segvoronoi_diagram) -> usize {
    count(diagram, Diagram::piece_count)
}

/// The pieces (ascending indices below `segvoronoi_diagram_piece_count`)
/// that input segment `input` became: none (it shrank below a snapping
/// pixel) or more with splitting, else `input` itself. Writes up to
/// `capacity` to `pieces` and their number to `*count`; `pieces = NULL,
/// capacity = 0` only counts.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (`input` is not an input
/// segment), `BUFFER_TOO_SMALL` (then `*count` holds the number and the
/// first `capacity` are written).
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_pieces_of_input(
    diagram: *const segvoronoi_diagram,
    input: usize,
    pieces: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    // SAFETY: passed on from the caller.
    unsafe {
        write_list(
            diagram,
            input,
            ("input segment", |d| d.stats().input_segments),
            Diagram::pieces_of_input,
            pieces,
            capacity,
            count,
        )
    }
}

/// The input segments (ascending) that piece `piece` came from: one, or
/// several where collinear input segments overlapped. Buffer rules as for
/// `segvoronoi_diagram_pieces_of_input`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (`piece >= piece_count`),
/// `BUFFER_TOO_SMALL`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_inputs_of_piece(
    diagram: *const segvoronoi_diagram,
    piece: usize,
    inputs: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    // SAFETY: passed on from the caller.
    unsafe { write_list(diagram, piece, ("piece", Diagram::piece_count), Diagram::inputs_of_piece, inputs, capacity, count) }
}

/// The arc pieces (ascending indices below
/// `segvoronoi_diagram_arc_site_count`, as `segvoronoi_diagram_site_of_arc`
/// takes them) that input arc `input` became: with splitting none (it
/// shrank to a point), one or more where it was cut, else `input` itself.
/// Buffer rules as for `segvoronoi_diagram_pieces_of_input`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (`input` is not an input arc),
/// `BUFFER_TOO_SMALL`.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_arc_pieces_of_input(
    diagram: *const segvoronoi_diagram,
    input: usize,
    pieces: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    // SAFETY: passed on from the caller.
    unsafe {
        write_list(diagram, input, ("input arc", |d| d.stats().input_arcs), Diagram::arc_pieces_of_input, pieces, capacity, count)
    }
}

/// The input arcs (ascending) that arc piece `piece` came from: one, or
/// several where input arcs coincided. Buffer rules as for
/// `segvoronoi_diagram_pieces_of_input`.
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE` (`piece >=
/// segvoronoi_diagram_arc_site_count`), `BUFFER_TOO_SMALL`.
/// Thread safety: reads the diagram only; safe from many threads at once.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_inputs_of_arc_piece(
    diagram: *const segvoronoi_diagram,
    piece: usize,
    inputs: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    // SAFETY: passed on from the caller.
    unsafe {
        write_list(diagram, piece, ("arc piece", Diagram::arc_site_count), Diagram::inputs_of_arc_piece, inputs, capacity, count)
    }
}

/// The endpoints of piece `piece` in `out[0..4]` as `x0, y0, x1, y1`
/// (input coordinates, as built).
///
/// Errors: `NULL_ARGUMENT`, `OUT_OF_RANGE`; then nothing is written.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_piece(
    diagram: *const segvoronoi_diagram,
    piece: usize,
    out: *mut f64,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| match d.piece(piece) {
        Some([a, b]) => {
            for (k, v) in [a.x, a.y, b.x, b.y].into_iter().enumerate() {
                // SAFETY: `out` is non-null (checked above) and the caller
                // passes room for four doubles; k < 4.
                unsafe { out.add(k).write(v) };
            }
            segvoronoi_status::Ok
        }
        None => out_of_range("piece", piece, d.piece_count()),
    })
}

/// With splitting: the largest distance from a piece to an input segment it
/// came from, in `*out` (0 when nothing was split, and without splitting).
///
/// Errors: `NULL_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn segvoronoi_diagram_max_split_displacement(
    diagram: *const segvoronoi_diagram,
    out: *mut f64,
) -> segvoronoi_status {
    require_non_null!(out);
    with_diagram(diagram, |d| write_out(out, d.max_split_displacement()))
}

/// The indices `list(d, index)` for entry `index` of a kind named `what`,
/// of which the diagram has `bound(d)`, by the buffer rules of
/// `segvoronoi_diagram_pieces_of_input`.
///
/// # Safety
/// As the calls above: `diagram` NULL or from `segvoronoi_builder_build`,
/// `out` valid for `capacity` writes (or NULL with `capacity` 0), `count`
/// NULL or valid.
unsafe fn write_list(
    diagram: *const segvoronoi_diagram,
    index: usize,
    (what, bound): (&str, impl Fn(&Diagram) -> usize),
    list: impl for<'a> Fn(&'a Diagram, usize) -> Indices<'a>,
    out: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> segvoronoi_status {
    require_buffer!(out, capacity, count);
    with_diagram(diagram, |d| {
        let n = bound(d);
        if index >= n {
            return out_of_range(what, index, n);
        }
        write_buffer(list(d, index).map(|i| i as u32), out, capacity, count)
    })
}
