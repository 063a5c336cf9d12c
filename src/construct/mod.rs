//! Construction: from the builder's input to a finished [`Diagram`], by the
//! topology-oriented method (DESIGN §2). The steps, each in its own file:
//!
//! 1. `builder.rs`: [`Builder`] collects the input (finite coordinates,
//!    the size limit); `headroom.rs` refuses a build whose memory the
//!    allocator will not grant, before it starts.
//! 2. Here, [`diagram_of`]: scale (one power of two for the whole input,
//!    `geometry::scale`) → check (`input_check/`: normalisation, the
//!    classification of a pair, the candidate search; on large inputs beside
//!    the point insertions) → insert → renumber → accept (never an invalid
//!    diagram).
//! 3. Insert (`restart.rs`, with the restarts for closed chains): every
//!    point (`insert_point.rs`: nearest-site walk, seed, growth of P1/P2;
//!    in `insertion_order.rs`'s order), then every segment
//!    (`insert_segment/`: the path of P4, the growth of P3/P5); all points
//!    on one line instead as a ladder (`collinear.rs`). Both insertions
//!    delete a tree and replace it by the new cell (`deletion_tree.rs`), on
//!    the state of `state.rs` (the store, the sites and their kinds, the
//!    marks).
//! 4. Renumber (`renumber.rs`): internal ids to public ones, positions back
//!    to input coordinates.
//!
//! Nothing here does arithmetic on coordinates to decide anything: every
//! numerical question goes to `geometry`, and integer bookkeeping keeps the
//! diagram valid whatever the answers.

mod builder;
mod collinear;
mod deletion_tree;
mod exact_range;
pub(crate) mod halves;
mod headroom;
mod input_check;
mod insert_point;
mod insert_segment;
mod insertion_order;
pub(crate) mod polygon_input;
mod renumber;
mod restart;
mod shared_stretches;
mod split;
mod state;
mod status_treap;
mod threads;
mod with_arcs;

pub use builder::{Builder, MAX_POINTS};
pub use halves::{set_halves_from, set_halves_left_share, take_halves_report, HalvesReport};
pub use polygon_input::ChainPiece;
#[cfg(feature = "fault-injection")]
pub use restart::set_restart_budget;

use crate::diagram::Diagram;
use crate::error::{Error, ErrorKind};
use crate::geometry::input::segment_contact;
use crate::geometry::scale::Scale;
use crate::geometry::{CircularArc, Point};
pub(crate) use input_check::Conflict;
use input_check::{check_segments, first_conflict, CheckedInput, Vertex};
use insert_point::insert_points;
use polygon_input::RingInput;
use renumber::SegmentSites;
use restart::{insert_all, insert_all_from, Outcome, Stuck};
use std::borrow::Cow;
pub(crate) use threads::run_beside;

/// The diagram of the builder's input, with the domain of `rings` (over
/// the input segments; none: no domain), or the error that
/// [`Builder::build`] returns (see there).
pub(super) fn diagram_of(points: &[Point], segments: &[[Point; 2]], rings: &[RingInput]) -> Result<Diagram, Error> {
    diagram_of_known(points, segments, rings, None)
}

/// [`diagram_of`] the pieces and points of a split (no rings), known to
/// meet only at common endpoints in the coordinates that `contact_free_in`
/// makes (`split::SplitInput::contact_free_in`): where the build works in
/// those, its check only normalises (the search for conflicts would find
/// none), and a build in halves shares the input evenly.
pub(crate) fn diagram_of_contact_free(
    points: &[Point],
    segments: &[[Point; 2]],
    contact_free_in: Option<Scale>,
) -> Result<Diagram, Error> {
    diagram_of_known(points, segments, &[], contact_free_in)
}

/// [`diagram_of`], the input known free of contacts in the coordinates of
/// `contact_free_in` (see [`diagram_of_contact_free`]; `None`: not known).
fn diagram_of_known(
    points: &[Point],
    segments: &[[Point; 2]],
    rings: &[RingInput],
    contact_free_in: Option<Scale>,
) -> Result<Diagram, Error> {
    if segments.is_empty() {
        let (diagram, outcome) = build_points(points);
        return accept(diagram, outcome, points, segments);
    }
    let ring = polygon_input::ring_segments(rings, segments.len());
    let (diagram, outcome) = match build_sites(points, segments, &ring, contact_free_in)? {
        Sites::Built(diagram, outcome) => (*diagram, outcome),
        Sites::Shared(checked, pieces) => {
            return shared_stretches::diagram_of_shared(points, segments, rings, &checked, pieces);
        }
    };
    let mut diagram = accept(diagram, outcome, points, segments)?;
    if !rings.is_empty() {
        // Rings cut at vertices of others are still those rings, over the pieces.
        diagram.set_domain(&polygon_input::rings_over_pieces(&diagram, rings));
    }
    Ok(diagram)
}

/// The input check of [`diagram_of`] alone (scale, normalise, search for a
/// conflict): the [`ErrorKind::Intersecting`] error the build would give,
/// without building.
pub(super) fn check_input(points: &[Point], segments: &[[Point; 2]], rings: &[RingInput]) -> Result<(), Error> {
    if segments.is_empty() {
        return Ok(()); // distinct or repeated points never conflict
    }
    let ring = polygon_input::ring_segments(rings, segments.len());
    match first_conflict(points, segments, &ring, input_scale(points, segments)) {
        Some(c) => Err(conflict_error(&c, segments)),
        None => Ok(()),
    }
}

/// The Voronoi diagram of finite points, and how its construction ended
/// (checked by [`accept`]).
fn build_points(input: &[Point]) -> (Diagram, Outcome) {
    let scale = input_scale(input, &[]);
    let points = to_internal(input, scale);
    // in halves on two threads when large and a thread is spare
    let built = halves::insert_all_in_halves(&points, &[]).unwrap_or_else(|| insert_all(&points, &[]));
    let (diagram, site_of_input, _, outcome) = built;
    (renumber::renumber(diagram, &site_of_input, input, SegmentSites::NONE, &[], scale), outcome)
}

/// What [`build_sites`] made.
enum Sites {
    /// The diagram, and how its construction ended (checked by [`accept`]);
    /// boxed, as the diagram's header is large beside the other variant.
    Built(Box<Diagram>, Outcome),
    /// Nothing yet: ring segments share stretches, which cancel
    /// (`shared_stretches`); the checked input and its pieces.
    Shared(CheckedInput, Vec<split::Piece>),
}

/// The diagram of points and segments, and how its construction ended;
/// or, where ring segments (`ring`, per input segment; empty for none)
/// share a stretch, the pieces that cancel; `Err` for input that crosses
/// itself.
///
/// Check the input (beside the point insertions, on large inputs), list
/// every point in the naming order (isolated points, then each segment's
/// first and second endpoint), insert the points and then the segments,
/// renumber.
///
/// `contact_free_in`: the coordinates in which the input is known to meet
/// only at common endpoints (a split's pieces), if any.
fn build_sites(points: &[Point], segments: &[[Point; 2]], ring: &[bool], contact_free_in: Option<Scale>) -> Result<Sites, Error> {
    build_sites_and_arcs(points, segments, ring, (&[], &|| Ok(())), contact_free_in)
}

/// [`build_sites`] with circular arcs too, inserted after the segments:
/// `points` ends with each arc's start and end (`with_arcs`).
/// `check_arcs` is the arcs' input check, run beside the point insertions
/// with the segments' (its error first: it is the check asked first).
#[allow(clippy::type_complexity)]
fn build_sites_and_arcs(
    points: &[Point],
    segments: &[[Point; 2]],
    ring: &[bool],
    (arcs, check_arcs): (&[CircularArc], &(dyn Fn() -> Result<(), Error> + Sync)),
    contact_free_in: Option<Scale>,
) -> Result<Sites, Error> {
    // P<k> numbers the distinct points of this list by first appearance;
    // the construction takes it scaled (the list itself where scaling
    // changes no point, the usual case: see `to_internal`).
    let scale = input_scale(points, segments);
    let mut all: Vec<Point> = Vec::with_capacity(points.len() + 2 * segments.len());
    all.extend_from_slice(points);
    segments.iter().for_each(|s| all.extend_from_slice(s));
    let scaled = to_internal(&all, scale);
    // (a split's pieces, in the coordinates its contact search verified:
    // the check only normalises them)
    let contact_free = contact_free_in == Some(scale);
    let check_or_normalise = || {
        if contact_free {
            Ok(input_check::normalise_contact_free(points, segments, scale))
        } else {
            check_segments(points, segments, ring, scale)
        }
    };

    // With a spare thread and no arcs, a large build runs in halves
    // (`halves/`): the check runs first on one thread, while the other
    // inserts its half's points.
    let kept_pairs = |checked: &CheckedInput| -> Vec<[usize; 2]> {
        checked.segments.iter().map(|&(j, _)| endpoint_index(points.len(), j)).collect()
    };
    let mut checked_beside_halves = None;
    let built_in_halves = if arcs.is_empty() && halves::worth_it(scaled.len() + segments.len()) {
        let raw: Vec<[usize; 2]> = (0..segments.len()).map(|j| endpoint_index(points.len(), j)).collect();
        halves::insert_all_in_halves_after(&scaled, &raw, contact_free, || {
            let checked = check_or_normalise();
            let shared = checked.as_ref().ok().and_then(|c| shared_stretches::shared_pieces(c, points, segments, ring));
            // only plain input goes on in halves: no error, shared stretches or split
            let plain = match &checked {
                Ok(c) if shared.is_none() && c.splits.is_empty() => Some(kept_pairs(c)),
                _ => None,
            };
            checked_beside_halves = Some((checked, shared));
            plain
        })
    } else {
        None
    };

    // The points go in whatever the input check finds (a repeated or
    // zero-length segment only repeats points), so on large inputs the
    // check runs on a second thread meanwhile; an error discards the points.
    let check = || (check_arcs(), check_or_normalise());
    let ((arcs_checked, checked), stage, shared) = match checked_beside_halves {
        Some((checked, shared)) => ((check_arcs(), checked), None, Some(shared)),
        None if built_in_halves.is_none() && segments.len() + arcs.len() >= PARALLEL_CHECK_FROM => {
            let (checked, stage) = run_beside(check, || insert_points(&scaled, segments.len()));
            (checked, Some(stage), None)
        }
        None => (check(), None, None),
    };
    arcs_checked?;
    let checked = checked.map_err(|c| conflict_error(&c, segments))?;
    let shared = shared.unwrap_or_else(|| shared_stretches::shared_pieces(&checked, points, segments, ring));
    if let Some(pieces) = shared {
        // (the points inserted beside the check are dropped: the diagram is
        // built of the pieces left)
        return Ok(Sites::Shared(checked, pieces));
    }
    let kept: Vec<usize> = checked.segments.iter().map(|&(j, _)| j).collect();
    let (mut built, site_of_input, segment_sites, outcome) = match built_in_halves {
        Some(built) => built,
        None => {
            let stage = stage.unwrap_or_else(|| insert_points(&scaled, segments.len()));
            if !checked.splits.is_empty() {
                let (diagram, outcome) = build_split(stage, &checked, points, segments, &all, &scaled, scale, arcs)?;
                return Ok(Sites::Built(Box::new(diagram), outcome));
            }
            insert_all_from(stage, &scaled, &kept_pairs(&checked))
        }
    };
    let arc_sites = with_arcs::insert_arcs(&mut built, &site_of_input, points.len() - 2 * arcs.len(), arcs, scale, &outcome)?;
    let input_and_ends = |k: usize| (kept[k], segments[kept[k]]);
    let described = SegmentSites { internal: &segment_sites, input_and_ends: &input_and_ends };
    let mut diagram = renumber::renumber(built, &site_of_input, &all, described, &arc_sites, scale);
    renumber::number_segment_inputs(&mut diagram, &checked, points.len(), segments.len());
    Ok(Sites::Built(Box::new(diagram), outcome))
}

/// The diagram when input vertices lie inside segments
/// ([`CheckedInput::splits`]): each such segment is cut into pieces at
/// them, exactly (the cut points are input vertices, already inserted with
/// the points of `stage`), and the diagram is that of the pieces. Piece
/// numbering as with [`Builder::split_crossings`]: the pieces of input
/// segment 0 from its first end to its second, then those of segment 1,
/// and so on (an input segment not split is one piece; a zero-length one a
/// zero-length piece); `Diagram::pieces_of_input` and `inputs_of_piece`
/// map between the two.
#[allow(clippy::too_many_arguments)]
fn build_split(
    stage: insert_point::PointStage,
    checked: &CheckedInput,
    points: &[Point],
    segments: &[[Point; 2]],
    all: &[Point],
    scaled: &[Point],
    scale: Scale,
    arcs: &[CircularArc],
) -> Result<(Diagram, Outcome), Error> {
    let pieces = Pieces::of(checked, points.len(), segments);
    let pairs: Vec<[usize; 2]> = pieces.kept.iter().map(|&p| pieces.ends[p]).collect();
    let (mut built, site_of_input, segment_sites, outcome) = insert_all_from(stage, scaled, &pairs);
    let arc_sites = with_arcs::insert_arcs(&mut built, &site_of_input, points.len() - 2 * arcs.len(), arcs, scale, &outcome)?;
    let input_and_ends = |k: usize| {
        let p = pieces.kept[k];
        (p, pieces.ends[p].map(|i| all[i]))
    };
    let described = SegmentSites { internal: &segment_sites, input_and_ends: &input_and_ends };
    let mut diagram = renumber::renumber(built, &site_of_input, all, described, &arc_sites, scale);
    let first_segment_site = diagram.point_sites;
    diagram.segment_site = (0..pieces.ends.len())
        .map(|p| match pieces.kept_of[p] {
            Some(k) => crate::diagram::SiteId::from_index(first_segment_site + k),
            None => diagram.input_site[pieces.ends[p][0]],
        })
        .collect();
    diagram.input_site.truncate(points.len());
    let origins: Vec<Vec<u32>> =
        (0..segments.len()).flat_map(|j| (pieces.start[j]..pieces.start[j + 1]).map(move |_| vec![j as u32])).collect();
    diagram.split = Some(Box::new(crate::diagram::SplitPieces::new(&origins, segments.len(), 0.0, 0.0)));
    let stats = &mut diagram.stats;
    stats.input_points = points.len();
    stats.input_segments = segments.len();
    stats.pieces = pieces.ends.len();
    stats.duplicate_points = checked.duplicate_points;
    stats.duplicate_segments = checked.duplicate_segments;
    stats.zero_length_segments = checked.degenerate_segments;
    stats.split_at_vertices = checked.splits.len();
    Ok((diagram, outcome))
}

/// The pieces of the input segments cut at the input vertices inside them.
struct Pieces {
    /// Input segment `j` became pieces `start[j]..start[j + 1]`.
    start: Vec<usize>,
    /// Per piece, its ends in the construction's point list, in the
    /// direction of its input segment.
    ends: Vec<[usize; 2]>,
    /// Per piece: the kept piece it is or repeats (a position in `kept`);
    /// `None` for a zero-length one.
    kept_of: Vec<Option<usize>>,
    /// The pieces built, each once: those of the kept input segments.
    kept: Vec<usize>,
}

impl Pieces {
    fn of(checked: &CheckedInput, points: usize, segments: &[[Point; 2]]) -> Pieces {
        let vertex = |v: Vertex| match v {
            Vertex::Point(i) => i,
            Vertex::End { segment, end } => endpoint_index(points, segment)[end],
        };
        // Per kept segment, its cut points along it from its
        // lexicographically smaller end (`splits` is sorted so).
        let mut cuts: Vec<Vec<usize>> = vec![Vec::new(); checked.segments.len()];
        for split in &checked.splits {
            cuts[split.segment].push(vertex(split.at));
        }
        let mut out = Pieces { start: vec![0], ends: Vec::new(), kept_of: Vec::new(), kept: Vec::new() };
        for (j, s) in segments.iter().enumerate() {
            let [e0, e1] = endpoint_index(points, j);
            let Some(k) = checked.kept_of_input[j] else {
                out.ends.push([e0, e0]);
                out.kept_of.push(None);
                out.start.push(out.ends.len());
                continue;
            };
            let along = &cuts[k];
            let forward = segment_contact::lex_cmp(s[0], s[1]) == std::cmp::Ordering::Less;
            let mut chain = Vec::with_capacity(along.len() + 2);
            chain.push(e0);
            if forward {
                chain.extend(along.iter().copied());
            } else {
                chain.extend(along.iter().rev().copied());
            }
            chain.push(e1);
            let original = checked.segments[k].0;
            let first = out.ends.len();
            for (m, w) in chain.windows(2).enumerate() {
                out.ends.push([w[0], w[1]]);
                if original == j {
                    out.kept_of.push(Some(out.kept.len()));
                    out.kept.push(first + m);
                } else {
                    // a repeat of an earlier segment, in its direction or
                    // the other: the same pieces, in that order or reversed
                    let same_way = segments[original][0] == s[0];
                    let at = if same_way { m } else { chain.len() - 2 - m };
                    out.kept_of.push(out.kept_of[out.start[original] + at]);
                }
            }
            out.start.push(out.ends.len());
        }
        out
    }
}

/// The indices in the construction's point list of input segment `j`'s two
/// endpoints: isolated points first, then each segment's first and second
/// endpoint.
fn endpoint_index(points: usize, j: usize) -> [usize; 2] {
    [points + 2 * j, points + 2 * j + 1]
}

/// From this many segments on, the input check runs beside the point
/// insertions (below, a thread costs more than it saves).
const PARALLEL_CHECK_FROM: usize = 20_000;

/// The one power-of-two scale of a build (`Scale::for_points` of every
/// coordinate, points and segment endpoints): the input check and the
/// insertions both work in the coordinates it makes.
fn input_scale(points: &[Point], segments: &[[Point; 2]]) -> Scale {
    Scale::for_points(points.iter().chain(segments.iter().flatten()))
}

/// `input` in the construction's coordinates (scaled, with `-0` made
/// `+0`): the input itself where that changes nothing (the identity
/// scale, and no `-0`), which spares a copy as large as the input and
/// its fresh pages (16 MB and 5 ms at a million points).
fn to_internal(input: &[Point], scale: Scale) -> Cow<'_, [Point]> {
    // (one pass without a branch; `-0.0 == 0.0`, hence the bits)
    const NEGATIVE_ZERO: u64 = 1 << 63;
    let negative_zero = |p: &Point| (p.x.to_bits() == NEGATIVE_ZERO) | (p.y.to_bits() == NEGATIVE_ZERO);
    if scale.is_identity() && !input.iter().fold(false, |any, p| any | negative_zero(p)) {
        Cow::Borrowed(input)
    } else {
        Cow::Owned(input.iter().map(|p| p.scaled(scale.to_internal).canonical_zero()).collect())
    }
}

/// The builder's error for an input conflict, naming both input indices
/// (`segments`: the input segments).
pub(crate) fn conflict_error(conflict: &Conflict, segments: &[[Point; 2]]) -> Error {
    Error::new(ErrorKind::Intersecting, conflict.message(segments), conflict.segments().to_vec())
}

/// `diagram`, or [`ErrorKind::Internal`] when the construction did not
/// complete (a segment without a path after the last restart) or, where
/// the diagram is checked, it fails [`Diagram::validate`].
///
/// The check is the whole combinatorial validation, which costs about a
/// quarter of the build itself (1M random points: 0.7 s against 2.8 s;
/// 1M points and 300k short segments: 1.5 s against 6.9 s), so release
/// builds run it only where something went wrong on the way (the
/// construction started over) and under fault injection; debug builds
/// always.
fn accept(diagram: Diagram, outcome: Outcome, points: &[Point], segments: &[[Point; 2]]) -> Result<Diagram, Error> {
    if let Some(stuck) = outcome.stuck {
        return Err(stuck_error(stuck, outcome.restarts, points, segments));
    }
    let check = cfg!(debug_assertions) || outcome.restarts > 0 || crate::geometry::fault::active();
    if check {
        if let Err(e) = diagram.validate() {
            let after = match outcome.restarts {
                0 => String::new(),
                1 => " (after 1 restart)".to_string(),
                n => format!(" (after {n} restarts)"),
            };
            return Err(Error::new(
                ErrorKind::Internal,
                format!(
                    "construction could not complete: the finished diagram is invalid{after}: {}; please report this input",
                    e.0
                ),
                Vec::new(),
            ));
        }
    }
    Ok(diagram)
}

/// The error for a segment that found no path in the last attempt.
fn stuck_error(stuck: Stuck, restarts: usize, points: &[Point], segments: &[[Point; 2]]) -> Error {
    // Endpoint `i` of the construction's point list is input segment
    // `(i - points) / 2`'s (isolated points first, then each segment's
    // two endpoints: see `endpoint_index`).
    let segment = stuck.endpoint.checked_sub(points.len()).map(|i| i / 2).filter(|&j| j < segments.len());
    let which = match segment {
        Some(j) => {
            let [a, b] = segments[j];
            format!("segment {j} ({}, {}) - ({}, {})", a.x, a.y, b.x, b.y)
        }
        None => "a segment".to_string(),
    };
    let plural = if restarts == 1 { "" } else { "s" };
    let when = if stuck.inserted_first {
        format!("even when inserted first, after {restarts} restart{plural}")
    } else {
        format!("after {restarts} restart{plural}")
    };
    Error::new(
        ErrorKind::Internal,
        format!("construction could not complete: {which} found no path {when}; please report this input"),
        segment.into_iter().collect(),
    )
}
