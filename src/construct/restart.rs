//! The restarts for closed chains: segments that share endpoints can close
//! a chain, and a closed chain walls off its inside (no path of P4 crosses
//! a separator). When lying numbers leave a segment without a path, the
//! construction starts over with that segment first (`insert_all_from`),
//! a bounded number of times, and otherwise reports how it ended
//! ([`Outcome`]) for `construct::accept` to turn into an error.

use super::insert_point::{insert_points, PointStage};
use super::insert_segment::insert_segments;
use super::state::Construction;
use crate::diagram::SiteId;
use crate::geometry::Point;

/// How many times the construction starts over when a segment finds no
/// path (see [`insert_all_from`]).
const MAX_RESTARTS: usize = 16;

/// A segment that found no path in the last attempt of a construction.
#[derive(Clone, Copy, Debug)]
pub(super) struct Stuck {
    /// Its first endpoint, as an index into the construction's points.
    pub(super) endpoint: usize,
    /// It already went first in that attempt (restarting cannot help).
    pub(super) inserted_first: bool,
}

/// How the construction ended.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Outcome {
    /// Times it started over.
    pub(super) restarts: usize,
    /// It gave up: this segment found no path in the last attempt.
    pub(super) stuck: Option<Stuck>,
}

#[cfg(feature = "fault-injection")]
thread_local! {
    static RESTART_BUDGET: std::cell::Cell<usize> = const { std::cell::Cell::new(MAX_RESTARTS) };
}

/// Sets how many times a construction on this thread may start over before
/// it gives up with [`ErrorKind::Internal`] (16 unless set; test builds with
/// the `fault-injection` feature only, to reach that error on purpose).
#[cfg(feature = "fault-injection")]
pub fn set_restart_budget(restarts: usize) {
    RESTART_BUDGET.with(|b| b.set(restarts));
}

fn restart_budget() -> usize {
    #[cfg(feature = "fault-injection")]
    return RESTART_BUDGET.with(|b| b.get());
    #[cfg(not(feature = "fault-injection"))]
    MAX_RESTARTS
}

/// Runs the insertions: every point, then every segment (given by the
/// indices of its two endpoints in `points`; distinct, non-crossing). Returns
/// the diagram in internal site ids, per input point the internal site it
/// became, and per segment its internal site.
pub(super) fn insert_all(points: &[Point], segments: &[[usize; 2]]) -> (Construction, Vec<SiteId>, Vec<SiteId>, Outcome) {
    insert_all_from(insert_points(points, segments.len()), points, segments)
}

/// [`insert_all`] after its first stage, [`insert_points`].
///
/// Segments that share endpoints can form closed chains, and a closed chain
/// walls off its inside: no path of P4 crosses it. With numbers that lie
/// (fault injection; conceivably a near-degenerate input) a chain can end
/// up around a site that is outside it, and a later segment from that site
/// then finds no path. The construction then starts over with that segment
/// inserted before the others (it cannot be walled off before the chain is
/// closed), at most `MAX_RESTARTS` times. With sound numbers it never
/// happens; if it keeps happening (or the stuck segment already went
/// first), the construction gives up: the last attempt is returned with an
/// [`Outcome`] that tells [`Builder::build`] to discard it for an
/// [`ErrorKind::Internal`] error (none of the test suites, fault injection
/// included, gets there with the full budget).
pub(super) fn insert_all_from(
    mut stage: PointStage,
    points: &[Point],
    segments: &[[usize; 2]],
) -> (Construction, Vec<SiteId>, Vec<SiteId>, Outcome) {
    let budget = restart_budget();
    let mut first = Vec::new();
    loop {
        let (diagram, site_of, segment_sites, stuck) = insert_segments(stage, points, segments, &first);
        let outcome = match stuck {
            None => Outcome { restarts: first.len(), stuck: None },
            Some(k) if first.len() < budget && !first.contains(&k) => {
                first.push(k);
                stage = insert_points(points, segments.len());
                continue;
            }
            Some(k) => Outcome {
                restarts: first.len(),
                stuck: Some(Stuck { endpoint: segments[k][0], inserted_first: first.contains(&k) }),
            },
        };
        return (diagram, site_of, segment_sites, outcome);
    }
}
