//! Every place where the current pieces meet other than at a common
//! endpoint (crossings, overlaps, an endpoint or a point inside a segment),
//! as the pixels that must become hot, counted by kind.
//!
//! # A Bentley–Ottmann sweep
//! The sweep of the strict check (`input_check/sweep.rs`: lexicographic
//! order of points, a sweep line tilted by an infinitesimal clockwise
//! angle, each piece from its first point to its last, the status in a
//! treap), carried on past every conflict instead of stopping at the first:
//! its events are the input points and every crossing point found so far,
//! a rational point kept exactly (`segment_contact::ContactPoint`), in a
//! priority queue. At event `q`:
//! 1. the run of the status through `q` (pieces ending at `q` or with `q`
//!    inside), found by one descent with the exact side of `q` against each
//!    piece and steps to its neighbours, and the pieces just below and
//!    above it;
//! 2. every pair that meets at `q` other than at a common endpoint is a
//!    contact, classified exactly (`segment_contact`): a piece with `q`
//!    inside against every other piece or point at `q`, and pieces
//!    starting at `q` in one direction (an overlap);
//! 3. the run leaves the status, and the pieces with `q` inside and those
//!    starting at `q` enter in their order just past `q` (by exact turn of
//!    their directions; equal directions by id);
//! 4. every pair that has just become adjacent and crosses properly past
//!    `q` puts its crossing point in the queue.
//!
//! Between two events the order of the status is the true order along the
//! sweep line, since every crossing is an event: two pieces crossing at
//! `p` are adjacent just before `p` (those between them would cross one of
//! them first), so they became adjacent at an event before `p` and step 4
//! queued `p`. Every contact has a point where the two items meet, an
//! input point or a crossing, and so an event where step 2 sees it.
//!
//! # Cost
//! O((n + k) log n) expected for n pieces and points and k contacts: each
//! event costs one descent and O(log n) expected per piece entering or
//! leaving; each pair tested in step 2 is a contact (an overlap may be met
//! again at later events of its common part; a set keeps it counted once);
//! each pair's crossing is queued once (a set of the pairs queued), so at
//! most k crossings are in the queue. Compared with the uniform grid it
//! replaced, long nearly parallel pieces no longer meet in many shared
//! cells.

use std::cmp::{Ordering, Reverse};
use std::collections::{BinaryHeap, HashSet};

use super::Layout;
use crate::construct::status_treap::{Treap, NIL};
use crate::geometry::input::segment_contact::{inside_segment, lex_cmp, segment_contact, ContactPoint, SegmentContact};
use crate::geometry::input::snap::{Pixel, PixelGrid};
use crate::geometry::predicates::{exact_turn, Orientation};
use crate::geometry::Point;

/// How many contacts of each kind one search found.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct ContactCounts {
    pub crossings: usize,
    pub overlaps: usize,
    /// An endpoint or an isolated point inside a segment.
    pub touchings: usize,
}

impl ContactCounts {
    pub(super) fn total(&self) -> usize {
        self.crossings + self.overlaps + self.touchings
    }
}

/// From this many pieces and points on, a search (or a slab of one) with
/// a spare thread runs in two slabs (`in_slabs`): below, the second thread
/// costs more than it saves.
const SLABS_FROM: usize = 1 << 14;

/// The pixels where the pieces of `layout` and its points meet other than
/// at common endpoints, appended to `hot` (with repeats), and the counts.
/// Large searches with a spare thread run in slabs, with the same counts
/// and pixels.
pub(super) fn contact_pixels(layout: &Layout, pixels: &PixelGrid, hot: &mut Vec<Pixel>) -> ContactCounts {
    slab_search(first_point_first(layout), layout.lone.clone(), Slab::WHOLE, pixels, hot)
}

/// The pieces of nonzero length, each from its first point
/// (lexicographically).
pub(super) fn first_point_first(layout: &Layout) -> Vec<[Point; 2]> {
    let first_point_first = |[a, b]: [Point; 2]| if lex_cmp(a, b) == Ordering::Greater { [b, a] } else { [a, b] };
    layout.proper.iter().map(|&(_, s)| first_point_first(s)).collect()
}

/// The sweep's input: `segments` (first point first) in the order of their
/// first points, and the isolated points `lone` in order.
fn in_sweep_order(mut segments: Vec<[Point; 2]>, mut lone: Vec<Point>) -> (Vec<[Point; 2]>, Vec<Point>) {
    segments.sort_unstable_by(|s, t| lex_cmp(s[0], t[0]));
    lone.sort_unstable_by(|p, q| lex_cmp(*p, *q));
    (segments, lone)
}

/// The contacts of `slab`, among `segments` (first point first, in any
/// order) and the points `lone`, which it picks (`Slab::picks`,
/// `Slab::holds`): swept on this thread, or where the slab is large and a
/// thread is spare, in two slabs cut at about its middle first point, each
/// searched the same way on its own thread (so that a build with 2^k
/// threads searches in up to 2^k slabs).
pub(super) fn slab_search(
    segments: Vec<[Point; 2]>,
    lone: Vec<Point>,
    slab: Slab,
    pixels: &PixelGrid,
    hot: &mut Vec<Pixel>,
) -> ContactCounts {
    let large = segments.len() + lone.len() >= SLABS_FROM && crate::construct::threads::spare() > 0;
    match middle_first_point(&segments, slab).filter(|_| large) {
        Some(cut) => in_slabs(&segments, &lone, slab, cut, pixels, hot),
        None => {
            let (segments, lone) = in_sweep_order(segments, lone);
            sweep(segments, &lone, slab, pixels, hot)
        }
    }
}

/// The most first points [`middle_first_point`] looks at: the slabs then
/// differ by about a percent of the pieces.
const CUT_SAMPLE: usize = 1 << 14;

/// About the middle first point of the `segments` (first point first) that
/// start inside `slab`, in the sweep's order: the median of a sample at an
/// even stride. `None` where none starts inside it past its start (a cut
/// there would leave its low part empty).
fn middle_first_point(segments: &[[Point; 2]], slab: Slab) -> Option<Point> {
    let stride = segments.len().div_ceil(CUT_SAMPLE).max(1);
    let mut firsts: Vec<Point> = segments.iter().step_by(stride).map(|s| s[0]).filter(|&p| slab.after_its_start(p)).collect();
    let middle = firsts.len() / 2;
    (!firsts.is_empty()).then(|| *firsts.select_nth_unstable_by(middle, |p, q| lex_cmp(*p, *q)).1)
}

/// [`slab_search`] of `slab` cut in two at the point `cut` (inside it),
/// one part per thread: the events before `cut` (lexicographically) and
/// those from it on. `segments` (first point first) and `lone` hold at
/// least what `slab` picks. A contact is found at one event (an overlap at
/// the first of its common part): its part's.
///
/// Why the parts find the slab's contacts, no more and no fewer: the low
/// part sweeps the pieces that start before `cut`, up to it; every piece
/// through an event before `cut` starts before it. The high part sweeps
/// every piece that ends at `cut` or after, and the points from `cut` on,
/// from the first event of those pieces: every piece through an event at
/// or after `cut` ends there or later. A sweep of a subset of the pieces
/// orders them as the whole sweep does, and pairs two of them at the same
/// events. Before `cut` the high part counts nothing (the low part counts
/// those contacts) but notes the overlaps it meets, so that it does not
/// count again an overlap whose common part runs across `cut`. Its extra
/// work is the pieces running across `cut`, and their crossings before it:
/// few where pieces are short. Each part picks and sorts its own pieces.
pub(super) fn in_slabs(
    segments: &[[Point; 2]],
    lone: &[Point],
    slab: Slab,
    cut: Point,
    pixels: &PixelGrid,
    hot: &mut Vec<Pixel>,
) -> ContactCounts {
    let search = |part: Slab| {
        let picked = segments.iter().filter(|s| part.picks(s)).copied().collect();
        let lone = lone.iter().copied().filter(|&p| part.holds(p)).collect();
        let mut found = Vec::new();
        (slab_search(picked, lone, part, pixels, &mut found), found)
    };
    let ((high_counts, high_hot), (low_counts, low_hot)) = crate::construct::threads::run_beside(
        || search(Slab { from: Some(cut), ..slab }),
        || search(Slab { until: Some(cut), ..slab }),
    );
    hot.extend(low_hot);
    hot.extend(high_hot);
    ContactCounts {
        crossings: low_counts.crossings + high_counts.crossings,
        overlaps: low_counts.overlaps + high_counts.overlaps,
        touchings: low_counts.touchings + high_counts.touchings,
    }
}

/// The events a sweep counts: those from `from` on (the earlier ones only
/// keep its status and note overlaps), before `until` (where it stops).
#[derive(Clone, Copy, Debug)]
pub(super) struct Slab {
    pub(super) from: Option<Point>,
    pub(super) until: Option<Point>,
}

impl Slab {
    pub(super) const WHOLE: Slab = Slab { from: None, until: None };

    /// Whether the slab's sweep takes the piece `s` (first point first):
    /// it starts before the slab's end and ends at or after its start.
    pub(super) fn picks(&self, s: &[Point; 2]) -> bool {
        self.until.map_or(true, |u| lex_cmp(s[0], u) == Ordering::Less)
            && self.from.map_or(true, |f| lex_cmp(s[1], f) != Ordering::Less)
    }

    /// Whether the point `p` lies in the slab: at or after its start,
    /// before its end.
    pub(super) fn holds(&self, p: Point) -> bool {
        self.from.map_or(true, |f| lex_cmp(p, f) != Ordering::Less)
            && self.until.map_or(true, |u| lex_cmp(p, u) == Ordering::Less)
    }

    /// Whether `p` lies in the slab past its start.
    fn after_its_start(&self, p: Point) -> bool {
        self.holds(p) && self.from.map_or(true, |f| lex_cmp(p, f) == Ordering::Greater)
    }
}

/// The sweep of `segments` and `lone` (as [`in_sweep_order`] gives them) over
/// `slab`: its contacts' pixels appended to `hot`, and their counts.
fn sweep(segments: Vec<[Point; 2]>, lone: &[Point], slab: Slab, pixels: &PixelGrid, hot: &mut Vec<Pixel>) -> ContactCounts {
    let mut ends: Vec<u32> = (0..segments.len() as u32).collect();
    ends.sort_unstable_by(|&i, &j| lex_cmp(segments[i as usize][1], segments[j as usize][1]));
    let mut sweep = ContactSweep {
        status: Treap::new(segments.iter().copied()),
        segments,
        crossings: BinaryHeap::new(),
        queued: HashSet::new(),
        overlaps: HashSet::new(),
        known_on: Vec::new(),
        pixels,
        hot,
        counts: ContactCounts::default(),
        silent: false,
        through: Vec::new(),
        interior: Vec::new(),
        ending: Vec::new(),
        entering: Vec::new(),
    };
    let (mut next_start, mut next_end, mut next_lone) = (0, 0, 0);
    let m = sweep.segments.len();
    loop {
        let input_next = [
            sweep.segments.get(next_start).map(|s| s[0]),
            ends.get(next_end).map(|&k| sweep.segments[k as usize][1]),
            lone.get(next_lone).copied(),
        ]
        .into_iter()
        .flatten()
        .min_by(|p, q| lex_cmp(*p, *q));
        // the pieces of the crossings queued at q pass through it: their
        // side needs no exact evaluation
        sweep.known_on.clear();
        let q = match (input_next, sweep.crossings.peek()) {
            (None, None) => break,
            (Some(p), Some(Reverse(Queued(c, ..)))) if c.cmp(&ContactPoint::At(p)) != Ordering::Less => ContactPoint::At(p),
            (Some(p), None) => ContactPoint::At(p),
            (_, Some(_)) => {
                let Reverse(Queued(c, i, j)) = sweep.crossings.pop().expect("peeked");
                sweep.known_on.extend([sweep.segments[i as usize], sweep.segments[j as usize]]);
                c
            }
        };
        let before = |point: Option<Point>| point.is_some_and(|p| q.cmp(&ContactPoint::At(p)) == Ordering::Less);
        if slab.until.is_some() && !before(slab.until) {
            break;
        }
        sweep.silent = before(slab.from);
        while sweep.crossings.peek().is_some_and(|Reverse(Queued(c, ..))| c.cmp(&q) == Ordering::Equal) {
            let Reverse(Queued(_, i, j)) = sweep.crossings.pop().expect("peeked");
            sweep.known_on.extend([sweep.segments[i as usize], sweep.segments[j as usize]]);
        }
        let (starts, lone_here) = match &q {
            ContactPoint::At(p) => {
                let at = |r: Point| lex_cmp(r, *p) == Ordering::Equal;
                let first = next_start;
                while next_start < m && at(sweep.segments[next_start][0]) {
                    next_start += 1;
                }
                while next_end < m && at(sweep.segments[ends[next_end] as usize][1]) {
                    next_end += 1;
                }
                let lone_first = next_lone;
                while next_lone < lone.len() && at(lone[next_lone]) {
                    next_lone += 1;
                }
                (first as u32..next_start as u32, next_lone - lone_first)
            }
            ContactPoint::Crossing(_) => (0..0, 0),
        };
        sweep.event(&q, starts, lone_here);
    }
    sweep.counts
}

/// A crossing point in the queue, ordered exactly, and the two pieces
/// that cross there.
struct Queued(ContactPoint, u32, u32);

impl PartialEq for Queued {
    fn eq(&self, other: &Queued) -> bool {
        self.0.cmp(&other.0) == Ordering::Equal
    }
}

impl Eq for Queued {}

impl PartialOrd for Queued {
    fn partial_cmp(&self, other: &Queued) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Queued {
    fn cmp(&self, other: &Queued) -> Ordering {
        self.0.cmp(&other.0)
    }
}

struct ContactSweep<'a> {
    /// The pieces of nonzero length, first point first, in the order of
    /// their first points: node `k` of the status is piece `k`.
    segments: Vec<[Point; 2]>,
    /// The pieces the sweep line crosses, from below to above.
    status: Treap,
    /// Crossing points ahead of the sweep line (several pairs may cross
    /// at one point).
    crossings: BinaryHeap<Reverse<Queued>>,
    /// The pairs whose crossing has been queued: two pieces cross once, so
    /// each pair is queued at most once, however often it becomes adjacent.
    queued: HashSet<(u32, u32)>,
    /// The pieces known to pass through the current event point.
    known_on: Vec<[Point; 2]>,
    /// The overlapping pairs counted so far (an overlap meets at many
    /// points).
    overlaps: HashSet<(u32, u32)>,
    pixels: &'a PixelGrid,
    hot: &'a mut Vec<Pixel>,
    counts: ContactCounts,
    /// At an event before its slab (`Slab::from`): contacts are not
    /// counted, overlaps only noted.
    silent: bool,
    /// Scratch space, kept from event to event: the run through the event
    /// point, its pieces with the point inside and those ending there, the
    /// pieces entering.
    through: Vec<u32>,
    interior: Vec<u32>,
    ending: Vec<u32>,
    entering: Vec<u32>,
}

impl ContactSweep<'_> {
    fn segment(&self, k: u32) -> [Point; 2] {
        self.segments[k as usize]
    }

    /// Handles the event at `q` (steps 1 to 4 of the module documentation):
    /// `starts` are the pieces whose first point is `q`, `lone_here` the
    /// number of isolated points at `q`.
    fn event(&mut self, q: &ContactPoint, starts: std::ops::Range<u32>, lone_here: usize) {
        // Step 1: the run through q and its neighbours.
        let known_on = &self.known_on;
        let side = |s: [Point; 2]| if known_on.contains(&s) { Orientation::Collinear } else { q.side_of(s) };
        let on_q = |status: &Treap, k: u32| k != NIL && side(status.segment(k)) == Orientation::Collinear;
        let (below, above, on) = self.status.locate(side);
        self.through.clear();
        let (low, high) = if on == NIL {
            (below, above)
        } else {
            let (mut first, mut last) = (on, on);
            while on_q(&self.status, self.status.previous(first)) {
                first = self.status.previous(first);
            }
            while on_q(&self.status, self.status.next(last)) {
                last = self.status.next(last);
            }
            let mut k = first;
            loop {
                self.through.push(k);
                if k == last {
                    break;
                }
                k = self.status.next(k);
            }
            (self.status.previous(first), self.status.next(last))
        };
        let ends_at_q = |s: [Point; 2]| matches!(q, ContactPoint::At(p) if lex_cmp(s[1], *p) == Ordering::Equal);
        self.interior.clear();
        self.ending.clear();
        for &k in &self.through {
            if ends_at_q(self.segments[k as usize]) {
                self.ending.push(k);
            } else {
                self.interior.push(k);
            }
        }

        // Step 2: the contacts at q.
        for x in 0..self.interior.len() {
            let i = self.interior[x];
            if let (ContactPoint::At(p), false) = (q, self.silent) {
                for _ in 0..lone_here {
                    self.counts.touchings += 1;
                    self.hot.push(self.pixels.pixel_of(*p));
                }
            }
            for y in x + 1..self.interior.len() {
                self.pair(i, self.interior[y]);
            }
            for y in 0..self.ending.len() {
                self.pair(i, self.ending[y]);
            }
            for j in starts.clone() {
                self.pair(i, j);
            }
        }

        // Step 3: the run leaves; what goes on past q enters, by direction.
        for &k in &self.through {
            self.status.remove(k);
        }
        self.entering.clear();
        self.entering.extend_from_slice(&self.interior);
        self.entering.extend(starts.clone());
        let segments = &self.segments;
        self.entering.sort_unstable_by(|&i, &j| match turn_between(segments, i, j) {
            Orientation::CounterClockwise => Ordering::Less,
            Orientation::Clockwise => Ordering::Greater,
            Orientation::Collinear => i.cmp(&j),
        });
        // pieces starting at q in one direction overlap, pairwise
        let mut run_start = 0;
        for x in 1..=self.entering.len() {
            let same = x < self.entering.len()
                && turn_between(&self.segments, self.entering[x - 1], self.entering[x]) == Orientation::Collinear;
            if same {
                continue;
            }
            for y in run_start..x {
                for z in y + 1..x {
                    let (i, j) = (self.entering[y], self.entering[z]);
                    if starts.contains(&i) && starts.contains(&j) {
                        self.pair(i, j);
                    }
                }
            }
            run_start = x;
        }
        let mut previous = low;
        for x in 0..self.entering.len() {
            let k = self.entering[x];
            self.status.insert_after(previous, k);
            self.queue_crossing(previous, k, q);
            previous = k;
        }
        // Step 4 (the other new adjacencies were queued as they formed).
        self.queue_crossing(previous, high, q);
    }

    /// Counts the contact of pieces `i` and `j`, which meet at the current
    /// event other than at a common endpoint, and makes its pixels hot.
    fn pair(&mut self, i: u32, j: u32) {
        let (s, t) = (self.segment(i), self.segment(j));
        let Some(contact) = segment_contact(s, t) else { return };
        if (contact == SegmentContact::Overlap && !self.overlaps.insert((i.min(j), i.max(j)))) || self.silent {
            return;
        }
        pair_pixels(s, t, contact, self.pixels, self.hot, &mut self.counts);
    }

    /// Queues the crossing point of nodes `i` and `j` (either may be
    /// `NIL`) when they cross properly past `q`.
    fn queue_crossing(&mut self, i: u32, j: u32, q: &ContactPoint) {
        if i == NIL || j == NIL || self.queued.contains(&(i.min(j), i.max(j))) {
            return;
        }
        let (s, t) = (self.segment(i), self.segment(j));
        if segment_contact(s, t) != Some(SegmentContact::Cross) {
            return;
        }
        let crossing = ContactPoint::crossing(s, t);
        if crossing.cmp(q) == Ordering::Greater {
            self.queued.insert((i.min(j), i.max(j)));
            self.crossings.push(Reverse(Queued(crossing, i, j)));
        }
    }
}

/// The turn from the direction of piece `i` to that of piece `j`, exact.
fn turn_between(segments: &[[Point; 2]], i: u32, j: u32) -> Orientation {
    let ([a, b], [c, d]) = (segments[i as usize], segments[j as usize]);
    exact_turn(a, b, c, d)
}

/// The hot pixels of one pair of segments that meet as `contact` says.
pub(super) fn pair_pixels(
    s: [Point; 2],
    t: [Point; 2],
    contact: SegmentContact,
    pixels: &PixelGrid,
    hot: &mut Vec<Pixel>,
    counts: &mut ContactCounts,
) {
    match contact {
        SegmentContact::Cross => {
            counts.crossings += 1;
            hot.push(pixels.crossing_pixel(s, t));
            return;
        }
        SegmentContact::Overlap => counts.overlaps += 1,
        SegmentContact::EndpointOfFirstOnSecond | SegmentContact::EndpointOfSecondOnFirst => counts.touchings += 1,
    }
    // An overlap or a touching: every endpoint inside the other segment
    // (for an overlap one or two of the four).
    for (end, other) in [(s[0], t), (s[1], t), (t[0], s), (t[1], s)] {
        if inside_segment(end, other) {
            hot.push(pixels.pixel_of(end));
        }
    }
}
