//! Splitting an input that crosses itself into one the strict check
//! accepts (`Builder::split_crossings`): crossings, overlaps, T-junctions
//! and points inside segments become shared endpoints, by iterated snap
//! rounding.
//!
//! # The method
//! The plane is cut into square pixels of side δ (`geometry::input::snap`: δ is
//! 2^-46 of the power of two above the largest coordinate, so that centres
//! are exact doubles). A pixel is *hot* when two items meet inside it other
//! than at a common endpoint: the pixel holding a crossing point (decided
//! exactly, though the point itself is not a double), and the pixel of an
//! endpoint or a point that lies inside a segment. A round of snapping moves every endpoint and
//! point in a hot pixel to its centre, and cuts every piece that meets a
//! hot pixel (exactly: the closed segment against the closed square) and
//! bends it through the centre. Pieces that come out equal merge (so
//! overlapping collinear segments share their common part). Then the
//! exact contact search runs again on the pieces; where something still
//! meets, its pixels are hot too and another round runs, with every pixel
//! hot so far (iterated snap rounding: a piece is bent through every hot
//! pixel it meets, not only those of its own contacts).
//!
//! This is the hot-pixel snap rounding of Hobby and of Greene and Yao, as
//! GEOS and CGAL's `Snap_rounding_2` use it, with two differences that keep
//! the input as it was wherever nothing crosses: only pixels with a contact
//! are hot (an endpoint alone does not make its pixel hot, so endpoints away
//! from every contact keep their exact coordinates), and the result is
//! verified by the exact contact search rather than trusted to a proof.
//!
//! # Guarantees
//! - The result is accepted by the strict check: the loop ends only when the
//!   exact search finds no contact (after at most [`MAX_ROUNDS`] rounds,
//!   else an internal error; none is known).
//! - Every piece lies within `rounds · δ/√2` of each input segment it came
//!   from (a bend moves a piece at most from a point of a pixel to its
//!   centre); `Diagram::max_split_displacement` reports the largest
//!   distance actually found, measured at the pieces' endpoints (the
//!   distance to a segment is convex, so that is the largest along them).
//! - The topology of the arrangement is kept except for features smaller
//!   than a pixel: a piece shorter than a pixel inside a hot pixel becomes a
//!   point, and two pieces that pass within a pixel of each other at a
//!   contact may be joined there.
//! - Each piece keeps the sorted input indices of every segment it came
//!   from.

pub(crate) mod arcs;
mod build;
mod contacts;
mod pixel_tree;
mod rings;
mod route;

use crate::error::{Error, ErrorKind};
use crate::geometry::input::snap::PixelGrid;
use crate::geometry::scale::Scale;
use crate::geometry::{Point, Site};
pub(crate) use build::diagram_of_split;
use contacts::{contact_pixels, ContactCounts};
pub(crate) use rings::{split_rings, split_rings_with_arcs};
use route::{route, HotPixels};

/// Most rounds of snapping before giving up (an internal error): on every
/// input tried, two or three rounds suffice.
pub(crate) const MAX_ROUNDS: usize = 16;

/// A piece while it is being split: its ends (internal coordinates) and
/// the input segments it came from.
#[derive(Clone, Debug)]
pub(crate) struct Piece {
    pub ends: [Point; 2],
    pub origins: Vec<u32>,
}

/// The input after splitting, in input coordinates.
#[derive(Clone, Debug)]
pub(crate) struct SplitInput {
    /// The input points, same indices; those in a hot pixel moved to its
    /// centre.
    pub points: Vec<Point>,
    /// The pieces with the input segments each came from. Zero-length input
    /// segments stay (as zero-length pieces, snapped like points).
    pub pieces: Vec<Piece>,
    /// Contacts found in the input as given.
    pub crossings: usize,
    pub overlaps: usize,
    pub touchings: usize,
    /// Rounds of snapping run (0 when nothing met).
    pub rounds: usize,
    /// The pixel side, in input coordinates.
    pub pixel: f64,
    /// The largest distance from a piece to an input segment it came from,
    /// in input coordinates.
    pub max_displacement: f64,
    /// The coordinates in which the last contact search found the pieces
    /// and points meeting only at common endpoints: those of this scale,
    /// into which `points` and `pieces` go back exactly. `None` where one
    /// does not (saturated past `f64::MAX`, or rounded below the normal
    /// numbers): then the build checks them afresh.
    pub contact_free_in: Option<Scale>,
}

/// Splits `segments` (finite coordinates) against each other and against
/// `points`; see the module documentation.
pub(crate) fn split(points: &[Point], segments: &[[Point; 2]]) -> Result<SplitInput, Error> {
    let scale = Scale::for_coordinates(points.iter().chain(segments.iter().flatten()).flat_map(|p| [p.x, p.y]));
    let internal = |p: Point| p.scaled(scale.to_internal).canonical_zero();
    let max_abs =
        points.iter().chain(segments.iter().flatten()).map(|p| internal(*p)).fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    let pixels = PixelGrid::for_magnitude(max_abs);
    let mut pieces: Vec<Piece> =
        segments.iter().enumerate().map(|(i, s)| Piece { ends: s.map(internal), origins: vec![i as u32] }).collect();
    let mut moved: Vec<Point> = points.iter().map(|&p| internal(p)).collect();
    let mut hot = HotPixels::new();
    let mut first: Option<ContactCounts> = None;
    let mut rounds = 0;
    loop {
        let layout = Layout::of(&pieces, &moved);
        let mut found = Vec::new();
        let counts = contact_pixels(&layout, &pixels, &mut found);
        first.get_or_insert(counts);
        if counts.total() == 0 {
            break;
        }
        if rounds == MAX_ROUNDS {
            return Err(not_converged(counts.total()));
        }
        hot.extend(found);
        pieces = route(pieces, &hot, &pixels);
        moved = moved.into_iter().map(|p| hot.snap(&pixels, p)).collect();
        rounds += 1;
    }
    let max_displacement = max_displacement(&pieces, segments, internal) * scale.to_input;
    // A point snapped to the grid's last line beyond the input's largest
    // coordinate can lie past f64::MAX (an input reaching f64::MAX); the
    // nearest representable point is f64::MAX, within the pixel as every
    // snapped point is.
    let external = |p: Point| scale.point_to_input(p);
    let counts = first.unwrap_or_default();
    let contact_free_in = contact_free_in(scale, &moved, &pieces);
    Ok(SplitInput {
        points: moved.into_iter().map(external).collect(),
        pieces: pieces.into_iter().map(|p| Piece { ends: p.ends.map(external), origins: p.origins }).collect(),
        crossings: counts.crossings,
        overlaps: counts.overlaps,
        touchings: counts.touchings,
        rounds,
        pixel: pixels.size() * scale.to_input,
        max_displacement,
        contact_free_in,
    })
}

/// `Some(scale)` when every one of `points` and of the `pieces`' ends
/// (internal coordinates of `scale`, where the last contact search found
/// nothing) comes back to itself from input coordinates: the build then
/// works on exactly what was searched (`SplitInput::contact_free_in`).
fn contact_free_in(scale: Scale, points: &[Point], pieces: &[Piece]) -> Option<Scale> {
    // (as the result is made: saturated at f64::MAX)
    let comes_back = |p: Point| scale.point_to_input(p).scaled(scale.to_internal).canonical_zero() == p;
    points.iter().copied().chain(pieces.iter().flat_map(|p| p.ends)).all(comes_back).then_some(scale)
}

/// The error for `contacts` still found after [`MAX_ROUNDS`] rounds.
pub(super) fn not_converged(contacts: usize) -> Error {
    Error::new(
        ErrorKind::Internal,
        format!(
            "splitting crossings did not converge: {contacts} contacts remain after {MAX_ROUNDS} rounds of snapping; please report this input"
        ),
        Vec::new(),
    )
}

/// The largest distance from a piece's endpoint to an input segment it
/// came from, in internal coordinates (where squares cannot overflow): the
/// distance to a segment is convex, so no point of the piece is farther.
pub(super) fn max_displacement(pieces: &[Piece], segments: &[[Point; 2]], internal: impl Fn(Point) -> Point) -> f64 {
    let mut worst = 0.0f64;
    for piece in pieces {
        for &i in &piece.origins {
            let [a, b] = segments[i as usize].map(&internal);
            let origin = Site::Segment { a, b };
            worst = piece.ends.iter().map(|&q| origin.distance(q)).fold(worst, f64::max);
        }
    }
    worst
}

/// The pieces of one round as both its steps (the contact search and the
/// routing) see them, laid out once: those of nonzero length, by their
/// index; and the points (isolated ones and zero-length pieces).
pub(super) struct Layout {
    pub proper: Vec<(usize, [Point; 2])>,
    pub lone: Vec<Point>,
}

impl Layout {
    fn of(pieces: &[Piece], points: &[Point]) -> Layout {
        let mut proper = Vec::with_capacity(pieces.len());
        let mut lone = points.to_vec();
        for (k, p) in pieces.iter().enumerate() {
            if p.ends[0] == p.ends[1] {
                lone.push(p.ends[0]);
            } else {
                proper.push((k, p.ends));
            }
        }
        Layout { proper, lone }
    }
}

#[cfg(test)]
mod tests;
