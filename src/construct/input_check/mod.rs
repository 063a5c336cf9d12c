//! The input checker for line-segment sites: normalisation and the
//! intersection rules of DESIGN §1, decided before any diagram is built.
//!
//! # What it does
//! - *Normalisation.* A zero-length segment is a point. A segment that repeats
//!   an earlier one (same endpoints, either direction) is dropped; so is a
//!   point that repeats an earlier point or any segment endpoint. All three are
//!   counted for the build statistics. Equality is coordinate equality, so
//!   `-0.0` equals `+0.0`.
//! - *Touchings are splits.* An input vertex (an endpoint of a segment, a
//!   zero-length segment, or an isolated point) in the open interior of a
//!   segment splits that segment there: a T-junction, a hole touching its
//!   shell inside an edge, two rings touching at a point, a point on a
//!   line. The split point is the input vertex itself, so nothing moves and
//!   nothing is rounded. Every such (segment, vertex) pair is listed in
//!   [`CheckedInput::splits`], by segment and along it; the builder builds
//!   the pieces (`construct::split_at_vertices`).
//! - *Shared stretches of rings.* Two collinear segments of polygon rings
//!   that share more than a point (two rings along one border, a spike
//!   out and back) are allowed when the caller says which segments are
//!   ring segments: the ends of the shared stretch are input vertices
//!   inside the segments, so they are splits as above, and the stretch
//!   becomes equal pieces, which the builder cancels in pairs
//!   (`construct::shared_stretches`).
//! - *Conflicts.* Apart from that, two segments may meet only at a common
//!   endpoint (exactly equal coordinates), any number of them at one point.
//!   Two segments that cross properly (at a point inside both) or that are
//!   collinear and share more than a point are a [`Conflict`] naming both
//!   input indices. When several conflicts exist, the one reported is the
//!   one whose *contact point* (the lexicographically smallest point, by
//!   `x` then `y`, that the two segments share) is smallest, whatever the
//!   input order; among conflicts at the same contact point, the smaller
//!   pair of input indices among those the sweep meets there (`sweep.rs`).
//!
//! # Exactness
//! Every decision is an exact orientation sign (never perturbed by fault
//! injection) or a coordinate comparison, made by `geometry::predicates`
//! and `geometry::input::segment_contact`; no epsilon anywhere. Crossing points
//! (to rank conflicts) are rational points compared exactly, in big
//! numbers wide enough never to round (`segment_contact::ContactPoint`). The checker works in
//! the builder's coordinates: the input multiplied by the build's one power
//! of two ([`Scale`], computed by `construct::input_scale`) so that 1e300
//! does not overflow and
//! 1e-300 does not underflow inside the predicates; the answers are those for
//! the coordinates the builder itself works with. Two limits, shared with the
//! point builder: the predicates are exact only while their products do not
//! underflow (points closer than about 1e-70 times the largest coordinate may
//! be misjudged), and an input spanning more than about 600 decimal orders of
//! magnitude loses its tiniest differences in the scaling.
//!
//! # Where
//! `normalise.rs` (zero-length, repeated), `sweep.rs` (the pairs worth
//! testing, the conflict reported and every split: a Shamos–Hoey sweep,
//! O(n log n) expected for every input), `classify.rs` (a pair's conflict,
//! named by input indices, and its contact point); the contact test itself
//! is `geometry::input::segment_contact`.

pub(crate) mod arcs;
mod classify;
mod normalise;
mod sweep;
#[cfg(test)]
mod tests;

use crate::geometry::input::segment_contact::lex_cmp;
use crate::geometry::scale::Scale;
use crate::geometry::Point;
use normalise::normalise;
use sweep::{find_conflict, sweep};

/// Where a point of the checked input came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PointSource {
    /// An isolated input point, by its index among the points.
    Point(usize),
    /// A zero-length input segment, by its index among the segments.
    Segment(usize),
}

/// The normalised input: what the builder inserts.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct CheckedInput {
    /// Distinct points that are not endpoints of a kept segment, in input
    /// order: isolated points first, then zero-length segments. Coordinates
    /// are the input ones with `-0.0` made `+0.0`.
    pub points: Vec<(PointSource, Point)>,
    /// The kept segments with their input index, in input order, endpoints as
    /// given (with `-0.0` made `+0.0`).
    pub segments: Vec<(usize, [Point; 2])>,
    /// Isolated points and zero-length segments dropped because they repeat
    /// an earlier point or any segment endpoint.
    pub duplicate_points: usize,
    /// Segments dropped because they repeat an earlier segment.
    pub duplicate_segments: usize,
    /// Zero-length segments (each became a point, or merged with one).
    pub degenerate_segments: usize,
    /// Per input segment: the index in `segments` of the kept segment it is
    /// or repeats; `None` for a zero-length segment.
    pub kept_of_input: Vec<Option<usize>>,
    /// Every input vertex in the open interior of a kept segment: the
    /// segment is split there. Sorted by segment (position in `segments`),
    /// and for one segment in the order of the points along it from its
    /// lexicographically smaller end.
    pub splits: Vec<Split>,
}

/// An input vertex in the open interior of a kept segment, which is split
/// there.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Split {
    /// The segment split (its position in [`CheckedInput::segments`]).
    pub segment: usize,
    /// The vertex it is split at.
    pub at: Vertex,
}

/// An input vertex, by where it comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Vertex {
    /// An isolated input point (index among the points).
    Point(usize),
    /// End `end` (0 or 1, as given; 0 for a zero-length segment) of input
    /// segment `segment`.
    End { segment: usize, end: usize },
}

/// Why the input cannot be built: the kind of intersection and the two input
/// segments involved (touchings are no conflict: they are [`Split`]s).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Conflict {
    /// Two segments cross at a point interior to both.
    SegmentsCross {
        /// The earlier segment (input index).
        first: usize,
        /// The later segment (input index).
        second: usize,
    },
    /// Two collinear segments share more than a point.
    SegmentsOverlap {
        /// The earlier segment (input index).
        first: usize,
        /// The later segment (input index).
        second: usize,
    },
}

impl Conflict {
    /// The two input segments, earlier first.
    pub(crate) fn segments(&self) -> [usize; 2] {
        match *self {
            Conflict::SegmentsCross { first, second } | Conflict::SegmentsOverlap { first, second } => [first, second],
        }
    }

    /// A sentence naming both input indices, for the error message; for an
    /// overlap, the stretch they share (`segments` are the input segments).
    pub(crate) fn message(&self, segments: &[[Point; 2]]) -> String {
        match *self {
            Conflict::SegmentsCross { first, second } => format!("segments {first} and {second} cross"),
            Conflict::SegmentsOverlap { first, second } => {
                let [a, b] = overlap_stretch(segments[first], segments[second]);
                format!("segments {first} and {second} are collinear and overlap from ({}, {}) to ({}, {})", a.x, a.y, b.x, b.y)
            }
        }
    }
}

/// The stretch two collinear overlapping segments share, from its
/// lexicographically smaller end: the middle two of their four endpoints
/// in the sweep's order (coordinate comparisons only).
pub(crate) fn overlap_stretch(s: [Point; 2], t: [Point; 2]) -> [Point; 2] {
    let mut ends = [s[0], s[1], t[0], t[1]];
    ends.sort_by(|&a, &b| lex_cmp(a, b));
    [ends[1], ends[2]]
}

/// Normalises and checks points and segments (finite coordinates, as the
/// builder guarantees), in the coordinates that `scale` makes (the
/// build's one scale). See the module documentation for the rules.
/// `ring` says, per input segment, whether a polygon's ring made it (empty:
/// none): ring segments may overlap each other, and are split at the ends
/// of the stretches they share.
pub(crate) fn check_segments(
    points: &[Point],
    segments: &[[Point; 2]],
    ring: &[bool],
    scale: Scale,
) -> Result<CheckedInput, Conflict> {
    let norm = normalise_scaled(points, segments, ring, scale);
    let (conflict, splits) = sweep(&norm);
    if let Some((conflict, _)) = conflict {
        return Err(conflict);
    }
    Ok(checked_input(norm, points, segments, splits))
}

/// [`check_segments`] of an input known to meet only at common endpoints
/// in the coordinates that `scale` makes, with no ring segments: the
/// pieces and points of a split, which its exact contact search found so
/// there (`split::SplitInput::contact_free_in`). Normalised alone: the
/// search for conflicts and splits would find none.
pub(crate) fn normalise_contact_free(points: &[Point], segments: &[[Point; 2]], scale: Scale) -> CheckedInput {
    checked_input(normalise_scaled(points, segments, &[], scale), points, segments, Vec::new())
}

/// The checked input of `points` and `segments` from their normalised
/// form and the splits found.
fn checked_input(norm: normalise::Normalised, points: &[Point], segments: &[[Point; 2]], splits: Vec<Split>) -> CheckedInput {
    CheckedInput {
        points: norm.points.iter().map(|&(src, _)| (src, input_point(points, segments, src))).collect(),
        segments: norm
            .segments
            .iter()
            .map(|&(i, _)| (i, [segments[i][0].canonical_zero(), segments[i][1].canonical_zero()]))
            .collect(),
        duplicate_points: norm.duplicate_points,
        duplicate_segments: norm.duplicate_segments,
        degenerate_segments: norm.degenerate_segments,
        kept_of_input: norm.kept_of_input,
        splits,
    }
}

/// The conflict [`check_segments`] would report, without building the
/// checked input (for [`Builder::check`](crate::Builder::check)).
pub(crate) fn first_conflict(points: &[Point], segments: &[[Point; 2]], ring: &[bool], scale: Scale) -> Option<Conflict> {
    find_conflict(&normalise_scaled(points, segments, ring, scale))
}

/// The input normalised in the coordinates that `scale` makes, with the
/// ring segments (`ring`, per input segment) allowed to overlap.
fn normalise_scaled(points: &[Point], segments: &[[Point; 2]], ring: &[bool], scale: Scale) -> normalise::Normalised {
    let mut norm = normalise(points, segments, |p: Point| p.scaled(scale.to_internal).canonical_zero());
    norm.allow_ring_overlaps(ring);
    norm
}

fn input_point(points: &[Point], segments: &[[Point; 2]], src: PointSource) -> Point {
    match src {
        PointSource::Point(i) => points[i].canonical_zero(),
        PointSource::Segment(i) => segments[i][0].canonical_zero(),
    }
}
