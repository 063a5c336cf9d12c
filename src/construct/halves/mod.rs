//! The parallel build (issue 33): the input cut in two halves at the
//! median x, each half built apart on its own thread by the sequential
//! construction, and the two diagrams glued into one.
//!
//! Why this way: the sequential build inserts each site where the last
//! one worked (BRIO rounds along a Hilbert curve), so consecutive sites
//! touch the same vertices and cannot be inserted at once (the study in
//! `docs/studies/parallel-build.md` measured 1.3 commits per round for
//! deterministic reservations). Two halves built apart keep that locality
//! and run all of the insertion work in parallel; the diagram does not
//! depend on the insertion order, so the glued diagram is the one a single
//! thread builds (the canonical topology text byte for byte, vertex
//! positions bit for bit: `vertex_placement` places a vertex from its
//! sites alone).
//!
//! Each half is built with a halo: the other half's sites within a band
//! beside the cut (and the endpoints of every segment it holds). A cell of
//! a site the half owns is then final when no site left out can come
//! nearer to any of its points (`geometry::seam`, asked of every vertex of
//! such a cell). The glue (`glue.rs`) takes the owned cells of each half:
//! every vertex with a site the left half owns from the left, every other
//! from the right, and links each edge across to the other half's edge
//! between the same two cells. Where a check fails, the band is widened
//! once to what the failing vertices need; where it fails again, or the
//! halves' edges do not pair up (two edges across between the same cells,
//! or a degenerate vertex cut two ways and split between the halves'
//! keeps), the build starts over on one thread. So the answer is always
//! the single thread's (a degenerate vertex on the cut may be cut as the
//! other half would have: the canonical text, which cuts them one way,
//! is the same); only the time differs.
//!
//! With four threads or more, a half whose thread may start another is
//! built in halves in turn (`insert_all_nested`: the same plan, cut and
//! glue on its local input, its own halves on the threads its budget
//! holds), so the input is built in vertical strips glued pairwise. The
//! glued half is the diagram of its local input, as the sequential build
//! of it is, and goes on to its checks and the outer glue unchanged;
//! where its own halves fail, it is built on its thread.

mod glue;
mod neighbours;

use super::insert_point::{insert_points, PointStage};
use super::restart::{insert_all_from, Outcome};
use super::state::{infinite_rotation, Construction, INFINITE};
use super::threads::run_beside;
use crate::diagram::{SiteId, VertexId, NONE};
use crate::geometry::left_out::LeftOut;
use crate::geometry::seam::{edge_to_infinity_clears, vertex_stays_short_of, Enclosure, Extremes};
use crate::geometry::skyline::Skyline;
use crate::geometry::Point;

/// From this many sites on (points and segments), a build with a spare
/// thread runs in halves: below, the second thread and the glue cost more
/// than they save.
const HALVES_FROM: usize = 60_000;

/// The first band's width, in mean spacings of the sites (the side of the
/// square each site would have if they covered the bounding box evenly).
/// Cells beside the cut reach a few spacings across it on uniform data.
const FIRST_BAND: f64 = 8.0;

/// The width of the input's boundary that both halves hold, in mean
/// spacings: the circles of the cells along the hull are huge, but dip
/// below its sides by less than a spacing on uniform data. Where the
/// input's last row stops short of the others (a step one spacing or two
/// deep: a grid whose count is not a square), those above the step dip by
/// the step's depth. With two spacings (and the test by one side alone),
/// grids of 100k and 300k short segments were not glued and 2,000 took a
/// second attempt (`threads.rs::grids_with_a_step_glue_from_halves`);
/// with three, and the test against the enclosure's inside
/// (`Enclosure::vertex_misses`, which also passes the disks round its
/// corners), none of 100k to 500k, for 0.4 % more sites held at 1M points.
///
/// Where the input thins out toward a side (the ends of segments sticking
/// out of a dense region, as crossing roads split do), the rim is as deep
/// as holds the points these three spacings hold at the mean density
/// (`Enclosure::depth_holding`): with three spacings alone, random
/// crossing segments five to ten spacings long failed their first
/// attempt, and a build on two threads took 1.3 times as long as on one.
const RIM: f64 = 3.0;

/// The most points the rim's depth is measured on (`Plan::of`): an
/// even spread puts about a hundred of them in the rim at a million sites.
const RIM_SAMPLE: usize = 1 << 15;

/// Whether [`set_halves_from`] set the threshold: then the halves run
/// whatever they cost (tests), only a failed check or glue stops them.
fn forced() -> bool {
    HALVES_FROM_HERE.with(|h| h.get()).is_some()
}

/// Whether a build of this many sites (points and segments) runs in
/// halves: from [`HALVES_FROM`] on (or what [`set_halves_from`] set), with
/// a spare thread.
pub(super) fn worth_it(sites: usize) -> bool {
    sites >= HALVES_FROM_HERE.with(|h| h.get()).unwrap_or(HALVES_FROM) && super::threads::spare() > 0
}

thread_local! {
    static HALVES_FROM_HERE: std::cell::Cell<Option<usize>> = const { std::cell::Cell::new(None) };
    static LEFT_SHARE_HERE: std::cell::Cell<Option<f64>> = const { std::cell::Cell::new(None) };
    static LAST_REPORT: std::cell::Cell<Option<HalvesReport>> = const { std::cell::Cell::new(None) };
}

/// Builds on this thread run in halves from this many sites (points and
/// segments) on, when they may start a thread; `None` restores the
/// default (60,000). For tests, which exercise the halves on small
/// inputs, and benchmarks.
pub fn set_halves_from(sites: Option<usize>) {
    HALVES_FROM_HERE.with(|h| h.set(sites));
}

/// Builds on this thread cut their halves with this share of the points
/// on the left (clamped to 0.05..0.95); `None` restores the default
/// (0.45 where the left half also checks the input, else 0.5). For tests
/// and studies of where the cut falls.
pub fn set_halves_left_share(share: Option<f64>) {
    LEFT_SHARE_HERE.with(|h| h.set(share));
}

/// How the last build on this thread that tried halves went (taken: the
/// next call returns `None` until another build tries).
pub fn take_halves_report() -> Option<HalvesReport> {
    LAST_REPORT.with(|r| r.take())
}

/// What a build in halves did ([`take_halves_report`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct HalvesReport {
    /// The sites of the whole input (points, with each segment's ends, and
    /// segments).
    pub sites: usize,
    /// The sites each half held in its last attempt (its own and its halo).
    pub held: [usize; 2],
    /// Attempts: 1, or 2 when the first band was too narrow.
    pub attempts: u32,
    /// Whether the halves were glued; otherwise the build ran again on one
    /// thread.
    pub glued: bool,
    /// Per half (left, right): whether it was built in halves in turn, and
    /// glued (with threads to spare: four or more in all).
    pub nested: [bool; 2],
    /// Whether both halves held the input's skyline and a shallow rim
    /// instead of a deep rim (a lumpy boundary: a sheet of parts, a coast).
    pub skyline: bool,
    /// Wall time of the plan (the cut, the sites both halves hold), of the
    /// halves' builds (with the input check beside them), and of the glue.
    pub times: [std::time::Duration; 3],
}

fn report(update: impl FnOnce(&mut HalvesReport)) {
    LAST_REPORT.with(|r| {
        let mut current = r.get().unwrap_or_default();
        update(&mut current);
        r.set(Some(current));
    });
}

/// A build's result: the construction, the site of each input point, the
/// site of each segment, and how it ended (as `restart::insert_all_from`).
pub(super) type Built = (Construction, Vec<SiteId>, Vec<SiteId>, Outcome);

/// The diagram of `points` and `segments` (pairs of indices into
/// `points`; distinct, not crossing, no point inside one) built in two
/// halves on two threads; `None` when there is no spare thread, the input
/// is small, or the halves could not be glued (the caller builds on one
/// thread).
pub(super) fn insert_all_in_halves(points: &[Point], segments: &[[usize; 2]]) -> Option<Built> {
    if !worth_it(points.len() + segments.len()) {
        return None;
    }
    insert_all_in_halves_after(points, segments, true, || Some(segments.to_vec()))
}

/// [`insert_all_in_halves`] of the segments that `check` returns (`None`:
/// none may be built), run first on the left half's thread while this one
/// inserts its half's points: an input check that runs beside the build.
/// `raw` are all segments the check may return (their ends are held by
/// the halves from the start). `check` runs exactly once, unless there is
/// no spare thread, the input is small or the plan finds that halves
/// would not pay (then not at all). `light`: the check only normalises
/// (no search for conflicts: a split's pieces).
pub(super) fn insert_all_in_halves_after(
    points: &[Point],
    raw: &[[usize; 2]],
    light: bool,
    check: impl FnOnce() -> Option<Vec<[usize; 2]>> + Send,
) -> Option<Built> {
    // The left half also runs the check, so it takes fewer sites.
    let default = if raw.is_empty() || light { 0.5 } else { LEFT_SHARE_BESIDE_THE_CHECK };
    let left_share = LEFT_SHARE_HERE.with(|h| h.get()).map_or(default, |share| share.clamp(0.05, 0.95));
    insert_all_in_halves_with(points, raw, check, left_share)
}

/// [`insert_all_in_halves_after`] with the left half taking `left_share`
/// of the points.
fn insert_all_in_halves_with(
    points: &[Point],
    raw: &[[usize; 2]],
    check: impl FnOnce() -> Option<Vec<[usize; 2]>> + Send,
    left_share: f64,
) -> Option<Built> {
    if !worth_it(points.len() + raw.len()) {
        return None;
    }
    report(|r| *r = HalvesReport { sites: points.len() + raw.len(), ..HalvesReport::default() });
    let started = std::time::Instant::now();
    let plan = Plan::of(points, raw, left_share);
    report(|r| r.times[0] = started.elapsed());
    // (halves would not pay: the check is left to the caller, which runs
    // it beside the point insertions)
    let plan = plan?;
    report(|r| r.skyline = plan.skyline);
    let started = std::time::Instant::now();
    let (tx, rx) = std::sync::mpsc::channel::<Option<std::sync::Arc<Vec<[usize; 2]>>>>();
    let shared_plan = &plan;
    let halves_from = HALVES_FROM_HERE.with(|h| h.get());
    // The left half, whose store the glue grows into the diagram, is built
    // on the other thread, and runs the check. With glibc, the pages of a
    // diagram freed where it was made go back to the system, and the next
    // build there faults them in afresh (two microseconds a page here);
    // freed into a helper's arena, more of them are kept. (Repeated builds
    // of 1M points: with the left half here, it faults 24,000 pages and
    // the right 9,500, 47,000 to 50,000 in the build; beside, 13,600 to
    // 15,600 and 16,200 to 17,800, 38,000 to 40,000 in all. The halves
    // end together, about 20 ms sooner.)
    let (left, right) = run_beside(
        move || {
            set_halves_from(halves_from);
            let segments = check().map(std::sync::Arc::new);
            // (the other thread stops at its points when the send fails or sends none)
            let _ = tx.send(segments.clone());
            let segments = segments?;
            let plan = shared_plan;
            let half = Half::select(points, raw, plan, (plan.band, &plan.outside), Side::Left);
            let built = half.build(points, &segments);
            Some((segments, built))
        },
        || {
            let half = Half::select(points, raw, &plan, (plan.band, &plan.outside), Side::Right);
            // (its points first, while the other thread checks the input,
            // unless the half is built in halves in turn)
            let stage = (!half.nests()).then(|| half.insert_points(points, raw.len()));
            let segments = rx.recv().ok().flatten()?;
            half.finish(stage, points, &segments)
        },
    );
    let (segments, left) = left?;
    let (left, right) = (left?, right?);
    report(|r| {
        r.times[1] = started.elapsed();
        r.attempts = 1;
        r.held = [left.held_sites(), right.held_sites()];
        r.nested = [left.nested, right.nested];
    });
    let band = match (left.needed_band, right.needed_band) {
        (None, None) => return glued(left, right, points.len(), segments.len()),
        (l, r) => 1.25 * l.unwrap_or(0.0).max(r.unwrap_or(0.0)),
    };
    drop((left, right));
    // Once more with the band the failing cells need, if that is worth it.
    if !(band.is_finite() && (band < plan.band * WIDEST_BAND || forced())) {
        return None;
    }
    let outside = Outside::at(points, &plan.both, plan.cut, band);
    let (left, right) = super::threads::run_beside(
        || {
            set_halves_from(halves_from);
            Half::select(points, &segments, &plan, (band, &outside), Side::Left).build(points, &segments)
        },
        || Half::select(points, &segments, &plan, (band, &outside), Side::Right).build(points, &segments),
    );
    let (left, right) = (left?, right?);
    report(|r| {
        r.attempts = 2;
        r.held = [left.held_sites(), right.held_sites()];
        r.nested = [left.nested, right.nested];
    });
    match (left.needed_band, right.needed_band) {
        (None, None) => glued(left, right, points.len(), segments.len()),
        _ => None,
    }
}

/// A half's diagram (of its local `points` and `segments`) built in halves
/// in turn, on the threads its own thread may start: `None` when it may
/// start none, the half is small (`insert_all_in_halves_with` asks), or
/// its halves could not be glued (the caller builds it on its thread).
/// Its halves take equal shares (the input is checked already), and the
/// build's report stays the outer build's.
fn insert_all_nested(points: &[Point], segments: &[[usize; 2]]) -> Option<Built> {
    let outer = LAST_REPORT.with(|r| r.take());
    let built = insert_all_in_halves_with(points, segments, || Some(segments.to_vec()), 0.5);
    LAST_REPORT.with(|r| r.set(outer));
    built
}

/// The halves glued (`glue::glue`), recorded in the report.
fn glued(left: BuiltHalf, right: BuiltHalf, points: usize, segments: usize) -> Option<Built> {
    let started = std::time::Instant::now();
    let built = glue::glue(left, right, points, segments);
    report(|r| {
        r.glued = built.is_some();
        r.times[2] = started.elapsed();
    });
    built
}

/// The widest first band, as a share of the input's width: each half
/// then holds over five eighths of it, and the glue costs as much as the
/// second thread saves.
const WIDEST_FIRST_BAND: f64 = 1.0 / 8.0;

/// How far beyond the cut `x = cut` the segments with an end left of it
/// (the left half's) reach, at most (0 for none). Both halves hold their
/// cells: a band narrower fails the left half's check.
fn reach_across(points: &[Point], segments: &[[usize; 2]], cut: f64) -> f64 {
    let reach = |part: &[[usize; 2]]| {
        part.iter().fold(0.0, |reach: f64, &[a, b]| {
            let (xa, xb) = (points[a].x, points[b].x);
            let (low, high) = if xa < xb { (xa, xb) } else { (xb, xa) };
            if low < cut && high - cut > reach {
                high - cut
            } else {
                reach
            }
        })
    };
    if segments.is_empty() {
        return 0.0;
    }
    let (low, high) = segments.split_at(segments.len() / 2);
    let (reach_high, reach_low) = run_beside(|| reach(high), || reach(low));
    reach_high.max(reach_low)
}

/// The share of the sites the left half takes when it runs the input
/// check first (the check costs about a tenth of a build with segments).
const LEFT_SHARE_BESIDE_THE_CHECK: f64 = 0.45;

/// The widest band a second attempt may take, in first bands: wider, the
/// halves overlap so much that one thread is as fast.
const WIDEST_BAND: f64 = 8.0;

/// Where the halves are cut, and what both hold.
struct Plan {
    cut: f64,
    band: f64,
    rim: f64,
    enclosure: Enclosure,
    /// What holds every point not within `rim` of the enclosure
    /// (`Enclosure::inside`; `None`: not known).
    inside: Option<Vec<Point>>,
    /// Per point: held by both halves, whatever the band: every point that
    /// may be a vertex of the hull (so that the edges to infinity of both
    /// halves are the whole diagram's) and every point within `rim` of the
    /// input's `enclosure` (cells along the hull reach along it, far across
    /// the cut: their huge circles are checked against the enclosure);
    /// along a lumpy boundary also every point near its skyline.
    both: Vec<bool>,
    /// Both hold the skyline (`Plan::along_a_lumpy_boundary`).
    skyline: bool,
    /// What each half leaves out at the first band (`Outside::at`), per
    /// [`Side`] (left, right).
    outside: [Option<Outside>; 2],
}

impl Plan {
    /// `None` when halves would not pay (points all on a line, too many
    /// on the boundary, or segments reaching far across the cut).
    fn of(points: &[Point], segments: &[[usize; 2]], left_share: f64) -> Option<Plan> {
        // two passes over the points, each on both threads by halves
        let (low, high) = points.split_at(points.len() / 2);
        let bounds = |part: &[Point]| (Enclosure::of(part), Extremes::of(part));
        let ((enclosure_high, extremes_high), (enclosure_low, extremes_low)) = run_beside(|| bounds(high), || bounds(low));
        let (enclosure, extremes) = (enclosure_low.merge(enclosure_high), extremes_low.merge(extremes_high));
        let spacing = (enclosure.box_area() / (points.len() + segments.len()) as f64).sqrt();
        if !(spacing.is_finite() && spacing > 0.0) {
            return None;
        }
        // (the seam's margins, of the coordinates' magnitude, wider than
        // the points' spacing: its checks would fail along the whole cut,
        // after both halves were built; a width a billionth of the
        // distance from the origin, 2^30 out)
        if enclosure.slack() > spacing && !forced() {
            return None;
        }
        // (the rim deeper where the input thins out toward its boundary)
        let stride = points.len().div_ceil(RIM_SAMPLE).max(1);
        let sample: Vec<Point> = points.iter().step_by(stride).copied().collect();
        let rim = enclosure.depth_holding(&sample, RIM * spacing);
        let cut = quantile_x(points, left_share)?;
        // (the band reaches as far beyond the cut as the left's segments
        // do: their cells are the left's, and reach as far)
        let band = FIRST_BAND * spacing + reach_across(points, segments, cut);
        let (lowest, highest) = extremes.x_range();
        if band > (highest - lowest) * WIDEST_FIRST_BAND && !forced() {
            return None;
        }
        let (octagon, near_rim) = (extremes.octagon(), enclosure.near_sides(rim));
        // (with the extremes of what each half leaves out at the first
        // band, in the same pass: see `Outside::at`)
        let held = |part: &[Point]| -> (Vec<bool>, usize, usize, [Extremes; 2]) {
            let (mut on_hull, mut count, mut beyond) = (0, 0, [Extremes::NONE; 2]);
            let both = part
                .iter()
                .map(|&p| {
                    let hull = octagon.may_hold_on_its_boundary(p);
                    let held = hull || near_rim.holds(p);
                    on_hull += usize::from(hull);
                    count += usize::from(held);
                    Outside::add(&mut beyond, p, held, cut, band);
                    held
                })
                .collect();
            (both, on_hull, count, beyond)
        };
        let ((both_high, hull_high, count_high, beyond_high), (mut both, hull_low, count_low, beyond_low)) =
            run_beside(|| held(high), || held(low));
        both.extend_from_slice(&both_high);
        // Both halves hold these: too many, and halves would not pay.
        if hull_low + hull_high > points.len() / 64 || count_low + count_high > points.len() / 16 {
            // (a rim as deep as the boundary's dips: its skyline instead)
            let hull = |p: Point| octagon.may_hold_on_its_boundary(p);
            return Plan::along_a_lumpy_boundary((points, segments), (cut, band, spacing), enclosure, hull);
        }
        let beyond = [0, 1].map(|k| beyond_low[k].merge(beyond_high[k]));
        let outside = Outside::from_extremes(points, &both, cut, band, beyond);
        let inside = enclosure.inside(rim);
        Some(Plan { cut, band, rim, enclosure, inside, both, outside, skyline: false })
    }
}

/// The rim of a lumpy boundary, in mean spacings: the skyline (`Plan::along_a_lumpy_boundary`)
/// follows the bumps, so a shallow rim is enough.
const LUMPY_RIM: f64 = 1.0;

/// The skyline's buckets, in mean spacings.
const SKYLINE_BUCKET: f64 = 2.0;

/// The share of the points that both halves may hold along a lumpy
/// boundary (a deep rim may hold a sixteenth).
const LUMPY_SHARE: f64 = 1.0 / 8.0;

impl Plan {
    /// The plan where a rim of even depth would hold too many points: the
    /// boundary is lumpy (a sheet of parts, a coast), and the circles of
    /// the cells along the hull dip between its bumps. Both halves then
    /// hold a shallow rim and every point near the skyline (within the
    /// rim's depth of the outermost point of its column or row of the
    /// bounding box: `Skyline`); the disks the seam's tests cannot clear
    /// are asked of the sites left out themselves (`Half::band_needed`).
    /// The band reaches as far across the cut as the neighbours of the
    /// sites beside it lie (`neighbours`: across a gap between parts, a
    /// band of spacings fell short and the first attempt was wasted). `None` where
    /// that would still hold too many, or the band would be wider than
    /// [`WIDEST_FIRST_BAND`] (the cut runs through an ocean, a hole).
    fn along_a_lumpy_boundary(
        (points, segments): (&[Point], &[[usize; 2]]),
        (cut, band, spacing): (f64, f64, f64),
        enclosure: Enclosure,
        hull: impl Fn(Point) -> bool + Sync,
    ) -> Option<Plan> {
        let (lo, hi) = enclosure.bounding_box();
        let widest = (hi.x - lo.x) * WIDEST_FIRST_BAND;
        let wanted = band.max(neighbours::reach_across(points, segments, cut, (lo, hi), spacing, widest));
        // (forced, too wide a band is left at its spacings: the checks decide)
        let band = match wanted <= widest {
            true => wanted,
            false if forced() => band,
            false => return None,
        };
        let rim = LUMPY_RIM * spacing;
        let (low, high) = points.split_at(points.len() / 2);
        let skyline_of = |part: &[Point]| {
            let mut skyline = Skyline::empty(lo, hi, SKYLINE_BUCKET * spacing);
            skyline.add(part);
            skyline
        };
        let (skyline_high, skyline_low) = run_beside(|| skyline_of(high), || skyline_of(low));
        let skyline = skyline_low.merge(&skyline_high);
        let near_rim = enclosure.near_sides(rim);
        let held = |part: &[Point]| -> Vec<bool> {
            part.iter().map(|&p| hull(p) || near_rim.holds(p) || skyline.near(p, rim)).collect()
        };
        let (both_high, mut both) = run_beside(|| held(high), || held(low));
        both.extend_from_slice(&both_high);
        let count = both.iter().filter(|&&b| b).count();
        if count as f64 > LUMPY_SHARE * points.len() as f64 && !forced() {
            return None;
        }
        let outside = Outside::at(points, &both, cut, band);
        let inside = enclosure.inside(rim);
        Some(Plan { cut, band, rim, enclosure, inside, both, outside, skyline: true })
    }
}

/// Which half: the left one owns the points with x below the cut and the
/// segments with an end below it; the right one owns the rest.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Side {
    Left,
    Right,
}

impl Side {
    /// Whether a site with these points (a point's once, a segment's two
    /// ends) belongs to this side of the cut `x = cut`.
    fn owns(self, points: &[Point], cut: f64) -> bool {
        let lowest = points.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
        (lowest < cut) == (self == Side::Left)
    }

    /// `1.0` for the left half (whose outside lies to the right), `-1.0`.
    fn toward_outside(self) -> f64 {
        match self {
            Side::Left => 1.0,
            Side::Right => -1.0,
        }
    }
}

/// One half's input: what it owns and its halo.
struct Half<'a> {
    side: Side,
    plan: &'a Plan,
    band: f64,
    /// Input points it holds (indices into the build's points).
    points: Vec<u32>,
    /// Segments it holds (indices into the build's segments).
    segments: Vec<u32>,
    /// What it leaves out at its band.
    outside: Option<&'a Outside>,
}

/// What a half knows of the sites it leaves out: every one lies at or
/// beyond `line` (on the far side from the half), and `hull` holds their
/// points that may be vertices of their convex hull.
struct Outside {
    line: f64,
    hull: Vec<Point>,
}

impl Outside {
    /// What each half (left, right) leaves out at `band`, or more: the
    /// points not held by both (`both`) that lie beyond the band on the
    /// other side of the cut (`Half::beyond_band`). Every site a half
    /// leaves out has all its points there (a segment left out has both
    /// ends beyond the band); the ends there of segments it holds only make
    /// its checks stricter. `None` for a half that leaves nothing out.
    /// Two passes over the points, each on both threads by halves (the
    /// plan does the first in its own pass: `Outside::add`).
    fn at(points: &[Point], both: &[bool], cut: f64, band: f64) -> [Option<Outside>; 2] {
        let middle = points.len() / 2;
        let ((points_low, points_high), (both_low, both_high)) = (points.split_at(middle), both.split_at(middle));
        let extremes = |part: &[Point], both: &[bool]| {
            let mut beyond = [Extremes::NONE; 2];
            part.iter().zip(both).for_each(|(&p, &both)| Outside::add(&mut beyond, p, both, cut, band));
            beyond
        };
        let (e_high, e_low) = run_beside(|| extremes(points_high, both_high), || extremes(points_low, both_low));
        Outside::from_extremes(points, both, cut, band, [0, 1].map(|k| e_low[k].merge(e_high[k])))
    }

    /// Adds point `p` (held by both halves or not) to the extremes of what
    /// each half leaves out ([`Outside::at`]).
    #[inline]
    fn add(beyond: &mut [Extremes; 2], p: Point, both: bool, cut: f64, band: f64) {
        // (the sets are disjoint: `p` is added to the one that may hold
        // it, as NaN, extreme in no direction, when neither does; selects,
        // where branches would be taken at random)
        let (k, member) = Outside::which(p, both, cut, band);
        beyond[k].add(if member { p } else { Point::new(f64::NAN, f64::NAN) });
    }

    /// Which half's set of [`Outside::at`] may hold `p` (0: the left's, 1:
    /// the right's), and whether it does.
    #[inline]
    fn which(p: Point, both: bool, cut: f64, band: f64) -> (usize, bool) {
        let left = Half::beyond_band(Side::Left, cut, band, p);
        (usize::from(!left), !both & (left | Half::beyond_band(Side::Right, cut, band, p)))
    }

    /// [`Outside::at`] from the extremes of each half's set: the second
    /// pass, for the points of each that may be vertices of its hull.
    fn from_extremes(points: &[Point], both: &[bool], cut: f64, band: f64, beyond: [Extremes; 2]) -> [Option<Outside>; 2] {
        let octagons = beyond.map(|e| e.octagon());
        let candidates = |part: &[Point], both: &[bool]| {
            let mut kept = [Vec::new(), Vec::new()];
            for (&p, &both) in part.iter().zip(both) {
                let (k, member) = Outside::which(p, both, cut, band);
                if octagons[k].may_hold_on_its_boundary(p) & member {
                    kept[k].push(p);
                }
            }
            kept
        };
        let middle = points.len() / 2;
        let (high, mut low) =
            run_beside(|| candidates(&points[middle..], &both[middle..]), || candidates(&points[..middle], &both[..middle]));
        // (per side, 0 the left's: the line is its set's least x, the
        // right's its greatest)
        [0, 1].map(|k| {
            let mut kept = std::mem::take(&mut low[k]);
            kept.extend_from_slice(&high[k]);
            let (least, greatest) = beyond[k].x_range();
            let line = if k == 0 { least } else { greatest };
            line.is_finite().then(|| Outside { line, hull: beyond[k].hull_candidates(kept) })
        })
    }
}

/// A half built: its construction, per held point and segment its site,
/// and the band its checks found wanting (`None`: every owned cell final).
pub(super) struct BuiltHalf {
    side: Side,
    construction: Construction,
    points: Vec<u32>,
    segments: Vec<u32>,
    site_of_point: Vec<SiteId>,
    site_of_segment: Vec<SiteId>,
    /// Per site of the construction: whether this half owns it.
    owned: Vec<bool>,
    needed_band: Option<f64>,
    /// Built in halves in turn (`insert_all_nested`).
    nested: bool,
}

impl BuiltHalf {
    fn held_sites(&self) -> usize {
        self.points.len() + self.segments.len()
    }

    /// Its construction, the rest dropped.
    fn into_construction(self) -> Construction {
        self.construction
    }
}

impl Half<'_> {
    /// The points `side` owns, and the other side's within `band` of the
    /// cut, with both ends of each of `segments` that it holds (a segment
    /// of the other side is held when its end nearest the cut is in the
    /// band, or an end is held by both halves).
    fn select<'a>(
        points: &[Point],
        segments: &[[usize; 2]],
        plan: &'a Plan,
        (band, outside): (f64, &'a [Option<Outside>; 2]),
        side: Side,
    ) -> Half<'a> {
        let mut held: Vec<bool> =
            points.iter().zip(&plan.both).map(|(&p, &both)| both | Half::near_point(side, plan.cut, band, p)).collect();
        let mut chosen = Vec::new();
        for (k, &[a, b]) in segments.iter().enumerate() {
            if Half::holds_segment(side, plan, band, points, [a, b]) {
                chosen.push(k as u32);
                held[a] = true;
                held[b] = true;
            }
        }
        let held_points = indices_of(&held);
        let outside = outside[usize::from(side == Side::Right)].as_ref();
        Half { side, plan, band, points: held_points, segments: chosen, outside }
    }

    /// Whether a site with these points is `side`'s, or within `band` of
    /// the cut on the other side (a segment by its end nearest the cut).
    fn near(side: Side, plan: &Plan, band: f64, points: &[Point]) -> bool {
        side.owns(points, plan.cut) || points.iter().any(|&p| !Half::beyond_band(side, plan.cut, band, p))
    }

    /// [`near`](Self::near) of a point, without a branch: about half the
    /// points are the side's, in no order.
    #[inline]
    fn near_point(side: Side, cut: f64, band: f64, p: Point) -> bool {
        ((p.x < cut) == (side == Side::Left)) | !Half::beyond_band(side, cut, band, p)
    }

    /// Whether `p` lies beyond `band` of the cut on the far side from
    /// `side` (then it is not `side`'s).
    #[inline]
    fn beyond_band(side: Side, cut: f64, band: f64, p: Point) -> bool {
        let t = side.toward_outside();
        !(p.x * t < cut * t + band)
    }

    fn holds_segment(side: Side, plan: &Plan, band: f64, points: &[Point], [a, b]: [usize; 2]) -> bool {
        Half::near(side, plan, band, &[points[a], points[b]]) || plan.both[a] || plan.both[b]
    }

    /// The half's points inserted (the left's with room for the right
    /// half's vertices: its store is the glued one, and grows in place).
    /// Returns them too, in the half's order (its local points).
    fn insert_points(&self, points: &[Point], segments: usize) -> (PointStage, Vec<Point>) {
        let local = self.local_points(points);
        (insert_points(&local, self.room(&local, points.len(), segments)), local)
    }

    /// The room its store makes for sites after its `local` points (of
    /// `points` in all, with `segments`): see `insert_points`.
    fn room(&self, local: &[Point], points: usize, segments: usize) -> usize {
        // Room for the sites to come: its segments, and on the left what
        // the glue appends: the right half's vertices but those of the
        // left's cells, about two per site the right holds (its sites, and
        // its halo, taken as large as the left's); the left's own halo's
        // vertices stay in the store until the glue fills their slots. A
        // store of n sites has room for 2n + 2 vertices, the most a
        // diagram of them has. No more: an array past the allocator's
        // threshold for its own mapping (32 MB in glibc) is mapped afresh
        // and its pages faulted in at every build.
        match self.side {
            Side::Left => {
                let owned = local.iter().filter(|&&p| self.side.owns(&[p], self.plan.cut)).count();
                let halo = local.len() - owned;
                // (the sites the right holds: all but those the left owns, and a halo)
                points + segments - owned + halo + halo / 16
            }
            Side::Right => segments,
        }
    }

    /// The points it holds, in its order (its local points).
    fn local_points(&self, points: &[Point]) -> Vec<Point> {
        self.points.iter().map(|&i| points[i as usize]).collect()
    }

    /// Whether this half is built in halves in turn: it is large, and its
    /// thread may start another.
    fn nests(&self) -> bool {
        worth_it(self.held_sites())
    }

    fn held_sites(&self) -> usize {
        self.points.len() + self.segments.len()
    }

    /// Builds the half on this thread (in halves in turn where it
    /// [`nests`](Self::nests)) and checks its owned cells; `None` when its
    /// construction restarted or gave up (the single thread's build then
    /// decides what to report).
    fn build(self, points: &[Point], segments: &[[usize; 2]]) -> Option<BuiltHalf> {
        let stage = (!self.nests()).then(|| self.insert_points(points, segments.len()));
        self.finish(stage, points, segments)
    }

    /// [`build`](Self::build) after the points where `stage` has them (else
    /// in halves in turn, or all here when those fail): the segments it
    /// holds of `segments` (which `select` saw, or fewer), then the checks.
    fn finish(mut self, stage: Option<(PointStage, Vec<Point>)>, points: &[Point], segments: &[[usize; 2]]) -> Option<BuiltHalf> {
        self.segments = (0..segments.len() as u32)
            .filter(|&k| Half::holds_segment(self.side, self.plan, self.band, points, segments[k as usize]))
            .collect();
        let mut pairs = Vec::with_capacity(self.segments.len());
        if !self.segments.is_empty() {
            let mut local_of = vec![NONE; points.len()];
            self.points.iter().enumerate().for_each(|(local, &i)| local_of[i as usize] = local as u32);
            for &k in &self.segments {
                let [a, b] = segments[k as usize].map(|i| local_of[i]);
                if a == NONE || b == NONE {
                    return None; // (an end not held: `segments` was not what `select` saw)
                }
                pairs.push([a as usize, b as usize]);
            }
        }
        // (a half built in halves in turn makes no room for the glue: its
        // glued store grows there)
        let ((construction, site_of_point, site_of_segment, outcome), nested) = match stage {
            Some((stage, local)) => (insert_all_from(stage, &local, &pairs), false),
            None => {
                let local = self.local_points(points);
                match insert_all_nested(&local, &pairs) {
                    Some(built) => (built, true),
                    None => {
                        let room = self.room(&local, points.len(), segments.len());
                        (insert_all_from(insert_points(&local, room), &local, &pairs), false)
                    }
                }
            }
        };
        if outcome.restarts > 0 || outcome.stuck.is_some() {
            return None;
        }
        let owned = self.owned_sites(&construction);
        let needed_band = self.outside.and_then(|outside| self.band_needed(&construction, &owned, outside, points, segments));
        Some(BuiltHalf {
            side: self.side,
            construction,
            points: self.points,
            segments: self.segments,
            site_of_point,
            site_of_segment,
            owned,
            needed_band,
            nested,
        })
    }

    /// Per site of its construction: whether this half owns it (never the
    /// point at infinity). Asked of each of a vertex's sites by the checks
    /// and by the glue: a table of a bit a site stays in cache, where the
    /// sites' coordinates do not.
    fn owned_sites(&self, c: &Construction) -> Vec<bool> {
        (0..c.store().site_count())
            .map(SiteId::from_index)
            .map(|s| {
                let (points, n) = c.site_points(s);
                s != INFINITE && self.side.owns(&points[..n], self.plan.cut)
            })
            .collect()
    }

    /// `None` when every cell this half owns is final (no site left out
    /// can come nearer to any of its points); otherwise the band that the
    /// failing vertices would need (infinite when no band helps: an edge
    /// to infinity whose supporting line a site left out reaches).
    /// `points` and `segments` are the build's (those `finish` took).
    fn band_needed(
        &self,
        c: &Construction,
        owned: &[bool],
        outside: &Outside,
        points: &[Point],
        segments: &[[usize; 2]],
    ) -> Option<f64> {
        let t = self.side.toward_outside();
        // (the sites left out, asked of the disks that the quick tests
        // below cannot clear; gathered at the first such disk)
        let mut left_out: Option<LeftOut> = None;
        let mut left_out_holds = |position: Point, clearance: f64| {
            left_out.get_or_insert_with(|| self.left_out(points, segments)).disk_may_hold_one(position, clearance)
        };
        let owned = |s: SiteId| owned[s.index()];
        let store = c.store();
        let mut needed: Option<f64> = None;
        for v in (0..store.vertex_count()).map(VertexId::from_index) {
            let sites = store.sites_of(v);
            if !sites.iter().any(|&s| owned(s)) {
                continue;
            }
            let (position, clearance) = (store.position[v.index()], store.clearance[v.index()]);
            let want = match infinite_rotation(sites) {
                Some((x, y)) => {
                    let ((px, nx), (py, ny)) = (c.site_points(x), c.site_points(y));
                    let both = [px[0], px[1], py[0], py[1]];
                    let touching = [&both[..nx], &both[2..2 + ny]].concat();
                    (!edge_to_infinity_clears(position, &touching, &outside.hull)).then_some(f64::INFINITY)
                }
                None => (!vertex_stays_short_of(position, clearance, outside.line, t)
                    && !self.plan.enclosure.vertex_beyond_a_side(position, clearance, self.plan.rim)
                    && !self.plan.enclosure.vertex_misses(self.plan.inside.as_deref(), position, clearance)
                    && left_out_holds(position, clearance))
                .then_some((position.x - self.plan.cut) * t + clearance),
            };
            if let Some(want) = want {
                needed = Some(needed.map_or(want, |w: f64| w.max(want)));
            }
        }
        needed
    }

    /// The sites of the build (its `points`, and its `segments` by their
    /// ends) that this half does not hold.
    fn left_out(&self, points: &[Point], segments: &[[usize; 2]]) -> LeftOut {
        let mut held = vec![false; points.len()];
        self.points.iter().for_each(|&i| held[i as usize] = true);
        let mut sites: Vec<[Point; 2]> = (0..points.len()).filter(|&i| !held[i]).map(|i| [points[i]; 2]).collect();
        let mut held = vec![false; segments.len()];
        self.segments.iter().for_each(|&k| held[k as usize] = true);
        sites.extend((0..segments.len()).filter(|&k| !held[k]).map(|k| segments[k].map(|i| points[i])));
        LeftOut::new(sites)
    }
}

/// The indices of the `true` flags, in order, without a branch a flag
/// (the held points of a half come in no order: a branch on each would be
/// mispredicted half the time).
fn indices_of(flags: &[bool]) -> Vec<u32> {
    // (counted first: the list lives as long as the half, and room for
    // every flag was megabytes more at the peak of a build)
    let count = flags.iter().filter(|&&f| f).count();
    let mut indices = vec![0u32; count + 1];
    let mut n = 0;
    for (i, &f) in flags.iter().enumerate() {
        indices[n] = i as u32;
        n += usize::from(f);
    }
    indices.truncate(n);
    indices
}

/// The x that about `share` of the points lie left of (the cut): the
/// quantile of a sample of at most [`CUT_SAMPLE`] points at an even
/// stride, which balances the halves as well as the exact one (any cut
/// gives the same diagram). `None` when it would leave one half empty
/// (every point at or right of it).
fn quantile_x(points: &[Point], share: f64) -> Option<f64> {
    let stride = points.len().div_ceil(CUT_SAMPLE).max(1);
    let mut xs: Vec<f64> = points.iter().step_by(stride).map(|p| p.x).collect();
    let middle = ((xs.len() as f64 * share) as usize).min(xs.len() - 1);
    let (_, &mut cut, _) = xs.select_nth_unstable_by(middle, f64::total_cmp);
    points.iter().any(|p| p.x < cut).then_some(cut)
}

/// The most points [`quantile_x`] looks at: within a tenth of a percent
/// of the share on uniform input.
const CUT_SAMPLE: usize = 1 << 18;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    /// Points: uniform, a lattice with repeats (ties on the band's edges),
    /// and a line of points on the cut.
    fn inputs() -> Vec<Vec<Point>> {
        let mut rng = SplitMix64(33);
        let uniform: Vec<Point> = (0..20_000).map(|_| Point::new(rng.unit(), rng.unit())).collect();
        let lattice: Vec<Point> = (0..20_000).map(|i| Point::new((i % 150) as f64, ((i / 150) % 90) as f64)).collect();
        let mut on_the_cut = uniform.clone();
        on_the_cut.extend((0..500).map(|i| Point::new(0.5, i as f64 / 500.0)));
        vec![uniform, lattice, on_the_cut]
    }

    /// The points a half leaves out (of points alone: those it does not
    /// select), as `Half::select` decides.
    fn left_out(points: &[Point], plan: &Plan, band: f64, side: Side) -> Vec<Point> {
        let outside = [None, None];
        let half = Half::select(points, &[], plan, (band, &outside), side);
        let mut held = vec![false; points.len()];
        half.points.iter().for_each(|&i| held[i as usize] = true);
        (0..points.len()).filter(|&i| !held[i]).map(|i| points[i]).collect()
    }

    #[test]
    fn a_point_is_near_as_a_site_of_one_point_is() {
        let cut = 0.5;
        let band = 0.125;
        let mut xs = vec![f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 0.0, -0.0, cut, cut + band, cut - band, 1.0, -1.0];
        xs.extend([cut, cut + band, cut - band].iter().flat_map(|&x| [x.next_up(), x.next_down()]));
        let mut rng = crate::splitmix::SplitMix64(9);
        xs.extend((0..1000).map(|_| rng.unit()));
        set_halves_from(Some(1)); // (a plan whatever the boundary holds)
        let plan = Plan::of(&inputs()[0], &[], 0.5).expect("halves pay");
        set_halves_from(None);
        let plan = Plan { cut, band, ..plan };
        // (with no band too, where only the side's own test answers)
        for band in [band, 0.0] {
            for &x in &xs {
                let p = Point::new(x, 0.25);
                for side in [Side::Left, Side::Right] {
                    assert_eq!(Half::near_point(side, cut, band, p), Half::near(side, &plan, band, &[p]), "{x} {side:?}");
                }
            }
        }
    }

    /// `reach_across` is the furthest x beyond the cut of the segments the
    /// left half owns (as `Side::owns` decides), either way round, none
    /// counted that lie wholly at or right of the cut.
    #[test]
    fn the_reach_across_the_cut_is_the_left_segments_furthest() {
        let mut rng = SplitMix64(41);
        let points: Vec<Point> = (0..3000).map(|_| Point::new(rng.unit(), rng.unit())).collect();
        let mut segments: Vec<[usize; 2]> = (0..1000).map(|k| [3 * k, 3 * k + 1]).collect();
        segments.extend((0..500).map(|k| [3 * k + 2, 3 * k + 1])); // reversed ends
        for cut in [0.5, 0.0, 1.0, points[7].x, points[8].x] {
            let plain = segments
                .iter()
                .filter(|&&[a, b]| Side::Left.owns(&[points[a], points[b]], cut))
                .map(|&[a, b]| points[a].x.max(points[b].x) - cut)
                .fold(0.0, f64::max);
            assert_eq!(reach_across(&points, &segments, cut), plain, "cut {cut}");
        }
        assert_eq!(reach_across(&points, &[], 0.5), 0.0);
        // a segment from the cut rightward is the right's: no reach
        let on_cut = [Point::new(0.5, 0.0), Point::new(0.9, 0.0)];
        assert_eq!(reach_across(&on_cut, &[[0, 1]], 0.5), 0.0);
        assert!((reach_across(&on_cut, &[[1, 0]], 0.6) - 0.3).abs() < 1e-15);
    }

    #[test]
    fn indices_of_flags_are_those_a_filter_takes() {
        let mut rng = crate::splitmix::SplitMix64(4);
        for (n, share) in [(0, 0.5), (1, 1.0), (1, 0.0), (1000, 0.5), (1000, 0.99), (1000, 0.0)] {
            let flags: Vec<bool> = (0..n).map(|_| rng.unit() < share).collect();
            let plain: Vec<u32> = (0..n as u32).filter(|&i| flags[i as usize]).collect();
            assert_eq!(indices_of(&flags), plain);
        }
    }

    #[test]
    fn what_a_half_leaves_out_is_known_exactly() {
        set_halves_from(Some(1)); // (a plan whatever the boundary holds)
        for points in inputs() {
            let plan = Plan::of(&points, &[], 0.5).expect("halves pay");
            for band in [plan.band, 3.0 * plan.band] {
                let at = Outside::at(&points, &plan.both, plan.cut, band);
                if band == plan.band {
                    // the plan's own pass gives the same
                    for (a, b) in at.iter().zip(&plan.outside) {
                        assert_eq!(a.as_ref().map(|o| (o.line, o.hull.clone())), b.as_ref().map(|o| (o.line, o.hull.clone())));
                    }
                }
                for (side, outside) in [Side::Left, Side::Right].into_iter().zip(&at) {
                    let out = left_out(&points, &plan, band, side);
                    let Some(outside) = outside else {
                        assert!(out.is_empty());
                        continue;
                    };
                    let xs = out.iter().map(|p| p.x);
                    let line = match side {
                        Side::Left => xs.fold(f64::INFINITY, f64::min),
                        Side::Right => xs.fold(f64::NEG_INFINITY, f64::max),
                    };
                    assert_eq!(outside.line, line);
                    assert!(outside.hull.iter().all(|p| out.contains(p)));
                    // every vertex of their hull is kept: each is the
                    // farthest along some direction, and so is a kept one
                    for k in 0..720 {
                        let a = std::f64::consts::TAU * k as f64 / 720.0;
                        let along = |p: &Point| p.x * a.cos() + p.y * a.sin();
                        let farthest = out.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
                        let kept = outside.hull.iter().map(along).fold(f64::NEG_INFINITY, f64::max);
                        assert_eq!(kept, farthest, "direction {k}");
                    }
                }
            }
        }
    }
}
