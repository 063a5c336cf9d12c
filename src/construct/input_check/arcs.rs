//! The input check for circular arcs: every pair of inputs of which at
//! least one is an arc (arc–point, arc–segment, arc–arc), decided exactly
//! by `geometry::input::arc_contact`. Segment–segment pairs stay with the
//! segment check (`sweep.rs`).
//!
//! # The rules
//! An arc may share its endpoints with any number of points, segments and
//! arcs, tangent or not (a segment or arc continuing it along the same
//! tangent, a full circle as two arcs). An endpoint of an arc strictly
//! inside a segment is fine too: the build splits the segment there. Any
//! other common point of the open arc with another input is a conflict:
//! an isolated point on the open arc, a segment or arc crossing or
//! tangent to it, an endpoint of a segment or of another arc on it, or
//! another arc of the same circle sharing more than a point with it
//! (identical arcs included).
//!
//! # Which pairs are tested
//! A sweep over boxes: each input gets a box (a point its own, a segment
//! its endpoints', an arc a conservative one from `arc_contact::arc_box`,
//! widened beyond the rounding of its centre and radius), and only the
//! pairs whose closed boxes overlap, with an arc among them, are tested
//! exactly. The sweep goes by `x_min`; the boxes whose `x` range the sweep
//! line still meets are *active*, kept per group (arcs, the rest) in a
//! structure on `y`: a segment tree over the sorted `y` bounds holds each
//! active `y` range in its canonical nodes (a stabbing query at `y_min` of
//! the new box finds the ranges that contain it), and an ordered set of
//! the `y_min`s finds those that start inside `(y_min, y_max]` of the new
//! box. A new arc is compared with both groups, anything else with the
//! arcs only, so pairs of segments cost nothing. With `k` pairs of
//! overlapping boxes, the sweep costs O((n + k) log n) for `n` inputs.
//!
//! # Cost
//! An arc's box comes from its circle in `f64` (for a third point, from a
//! few exact products rounded once). Its exact form (the circle's equation
//! in big numbers) is made at its first exact test and dropped when the
//! sweep has passed it, so the memory is that of the arcs the sweep line
//! meets. Each pair is first put to `f64` filters with proven slack (a
//! point clearly off the circle, a segment clearly missing it, disjoint
//! circles) and to rational shortcuts for a common endpoint; exact
//! big-number work remains for pieces that really meet. Measured in
//! release (the ignored test `cost_of_the_check`, best of three on a
//! 2-core machine shared with other builds): 100k half circles in a tangent-continuous chain, 0.17 s
//! (1.7 µs an arc); 100k shallow arcs in a chain beside 100k segments,
//! 0.40 s; 100k random arcs given by three points with a point at each
//! centre, 0.25 s.
//!
//! # Which conflict is reported
//! The least by (kind, arc index, other index), kinds in the order
//! arc–point, arc–segment, arc–arc, and for two arcs the smaller index
//! first: "the point with the smallest index on the arc with the smallest
//! index", whatever order the sweep meets the pairs in. A pair that could
//! not beat the best conflict found so far is not tested.

// The build with arcs (`construct::with_arcs`) is being written beside this
// check and will call it; until then only the tests do.

use std::cmp::Reverse;
use std::collections::{BTreeSet, BinaryHeap};

use crate::error::{Error, ErrorKind};
use crate::geometry::input::arc_contact::{
    arc_arc_contact, arc_box, cmp_f64, segment_arc_contact, ArcArcContact, ExactArc, SegmentArcContact,
};
use crate::geometry::{CircularArc, Point};

/// Why an input with arcs cannot be built: the kind of contact and the two
/// inputs, by input index (points, segments and arcs are numbered apart).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ArcConflict {
    /// An isolated point lies on the open arc.
    PointOnArc {
        /// The point (input index among the points).
        point: usize,
        /// The arc.
        arc: usize,
    },
    /// A segment meets the open arc.
    ArcSegment {
        /// The arc.
        arc: usize,
        /// The segment (input index among the segments).
        segment: usize,
        /// How they meet.
        contact: SegmentArcContact,
    },
    /// Two arcs meet in the open part of one of them.
    Arcs {
        /// The arc with the smaller index.
        first: usize,
        /// The arc with the larger index.
        second: usize,
        /// How they meet (`EndOfSecondOnFirst`: an endpoint of `second`
        /// lies inside `first`).
        contact: ArcArcContact,
    },
}

impl ArcConflict {
    /// The two input indices, in the order the message names them.
    pub(crate) fn indices(&self) -> [usize; 2] {
        match *self {
            ArcConflict::PointOnArc { point, arc } => [point, arc],
            ArcConflict::ArcSegment { arc, segment, .. } => [arc, segment],
            ArcConflict::Arcs { first, second, .. } => [first, second],
        }
    }

    /// A sentence naming both inputs by kind and input index.
    pub(crate) fn message(&self) -> String {
        match *self {
            ArcConflict::PointOnArc { point, arc } => format!("point {point} lies on arc {arc}"),
            ArcConflict::ArcSegment { arc, segment, contact } => match contact {
                SegmentArcContact::Cross => format!("arc {arc} and segment {segment} cross"),
                SegmentArcContact::Tangent => {
                    format!("arc {arc} and segment {segment} touch (the segment is tangent to the arc inside both)")
                }
                SegmentArcContact::EndOnArc => {
                    format!("arc {arc} and segment {segment} touch (an end of the segment lies inside the arc)")
                }
            },
            ArcConflict::Arcs { first, second, contact } => match contact {
                ArcArcContact::Cross => format!("arcs {first} and {second} cross"),
                ArcArcContact::Overlap => format!("arcs {first} and {second} overlap"),
                ArcArcContact::Tangent => format!("arcs {first} and {second} touch (tangent inside both)"),
                ArcArcContact::EndOfSecondOnFirst => {
                    format!("arcs {first} and {second} touch (an end of arc {second} lies inside arc {first})")
                }
                ArcArcContact::EndOfFirstOnSecond => {
                    format!("arcs {first} and {second} touch (an end of arc {first} lies inside arc {second})")
                }
            },
        }
    }

    /// The order in which conflicts are preferred (smallest first).
    fn rank(&self) -> (u8, usize, usize) {
        match *self {
            ArcConflict::PointOnArc { point, arc } => (0, arc, point),
            ArcConflict::ArcSegment { arc, segment, .. } => (1, arc, segment),
            ArcConflict::Arcs { first, second, .. } => (2, first, second),
        }
    }
}

/// The builder's error for `c`: [`ErrorKind::Intersecting`], with the
/// message of [`ArcConflict::message`] and its two indices.
pub(crate) fn arc_conflict_error(c: &ArcConflict) -> Error {
    Error::new(ErrorKind::Intersecting, c.message(), c.indices().to_vec())
}

/// The check of the pairs with an arc, as a result: what a
/// [`Builder::check`](crate::Builder::check)-style caller returns (the
/// segment–segment pairs are the segment check's).
pub(crate) fn check_arcs(points: &[Point], segments: &[[Point; 2]], arcs: &[CircularArc]) -> Result<(), Error> {
    match first_arc_conflict(points, segments, arcs) {
        Some(c) => Err(arc_conflict_error(&c)),
        None => Ok(()),
    }
}

/// The conflict of the input with arcs that the module documentation
/// says is reported, if any: over all pairs with at least one arc.
/// Coordinates must be finite (the builder's rule); any finite values
/// are handled exactly. Fewer than `2^32` inputs in all (the builder's
/// 32-bit ids).
pub(crate) fn first_arc_conflict(points: &[Point], segments: &[[Point; 2]], arcs: &[CircularArc]) -> Option<ArcConflict> {
    let best: std::cell::Cell<Option<ArcConflict>> = std::cell::Cell::new(None);
    // (a pair that could not beat the best conflict found so far is not
    // tested)
    let wanted = |rank: (u8, usize, usize)| best.get().map_or(true, |c| rank < c.rank());
    for_each_arc_conflict(points, segments, arcs, wanted, |found| best.set(Some(found)));
    best.get()
}

/// Every conflict of a pair with an arc among them, in the sweep's order:
/// `found` is called for each pair that `wanted` (asked with the pair's
/// rank, as [`ArcConflict::rank`] gives it) lets through and that meets.
pub(crate) fn for_each_arc_conflict(
    points: &[Point],
    segments: &[[Point; 2]],
    arcs: &[CircularArc],
    wanted: impl Fn((u8, usize, usize)) -> bool,
    mut found: impl FnMut(ArcConflict),
) {
    if arcs.is_empty() {
        return;
    }
    let mut items: Vec<Item> = Vec::with_capacity(points.len() + segments.len() + arcs.len());
    items.extend(points.iter().enumerate().map(|(i, p)| Item { kind: Kind::Point, index: i, bx: [p.x, p.x, p.y, p.y] }));
    items.extend(segments.iter().enumerate().map(|(i, [a, b])| Item {
        kind: Kind::Segment,
        index: i,
        bx: [a.x.min(b.x), a.x.max(b.x), a.y.min(b.y), a.y.max(b.y)],
    }));
    items.extend(arcs.iter().enumerate().map(|(i, arc)| Item { kind: Kind::Arc, index: i, bx: arc_box(arc) }));
    for item in &mut items {
        // +0.0 for -0.0, so that the bit-keyed orders below are numeric
        for v in &mut item.bx {
            *v += 0.0;
        }
    }
    // The exact form of an arc, made at its first exact test and dropped
    // when the sweep has passed it: the memory is that of the active arcs.
    let mut exact: Vec<Option<ExactArc>> = (0..arcs.len()).map(|_| None).collect();
    box_sweep(&items, |event| {
        let (i, j) = match event {
            Event::Pair(i, j) => (i, j),
            Event::Retire(i) => {
                if items[i].kind == Kind::Arc {
                    exact[items[i].index] = None;
                }
                return;
            }
        };
        let (a, b) = (&items[i], &items[j]);
        let (arc, other) = if a.kind == Kind::Arc && (b.kind != Kind::Arc || a.index < b.index) { (a, b) } else { (b, a) };
        let rank = match other.kind {
            Kind::Point => (0, arc.index, other.index),
            Kind::Segment => (1, arc.index, other.index),
            Kind::Arc => (2, arc.index, other.index),
        };
        if !wanted(rank) {
            return;
        }
        let mut prepare = |k: usize| {
            exact[k].get_or_insert_with(|| ExactArc::new(&arcs[k]));
        };
        prepare(arc.index);
        if other.kind == Kind::Arc {
            prepare(other.index);
        }
        let Some(x) = exact[arc.index].as_ref() else { return };
        let conflict = match other.kind {
            Kind::Point => {
                x.contains_point(points[other.index]).then_some(ArcConflict::PointOnArc { point: other.index, arc: arc.index })
            }
            Kind::Segment => segment_arc_contact(x, segments[other.index]).map(|contact| ArcConflict::ArcSegment {
                arc: arc.index,
                segment: other.index,
                contact,
            }),
            Kind::Arc => exact[other.index].as_ref().and_then(|y| arc_arc_contact(x, y)).map(|contact| ArcConflict::Arcs {
                first: arc.index,
                second: other.index,
                contact,
            }),
        };
        if let Some(conflict) = conflict {
            found(conflict);
        }
    });
}

/// What the sweep reports.
#[derive(Clone, Copy, Debug)]
enum Event {
    /// Two items (positions in the item list) whose boxes overlap, one of
    /// them an arc; reported once.
    Pair(usize, usize),
    /// An item the sweep line has passed: no pair with it follows.
    Retire(usize),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Point,
    Segment,
    Arc,
}

/// An input and its closed box `[x_min, x_max, y_min, y_max]`.
#[derive(Clone, Copy, Debug)]
struct Item {
    kind: Kind,
    index: usize,
    bx: [f64; 4],
}

/// A key whose unsigned order is the numeric order of `v` (no NaN, no
/// `-0.0`).
fn key(v: f64) -> u64 {
    let bits = v.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | (1 << 63)
    }
}

/// Reports ([`Event::Pair`]) once every pair of items whose closed boxes
/// overlap and of which at least one is an arc (see the module
/// documentation), and each item that no later pair involves
/// ([`Event::Retire`]).
fn box_sweep(items: &[Item], mut visit: impl FnMut(Event)) {
    // the y bounds, compressed to ranks: equal values, equal ranks
    let mut ys: Vec<f64> = items.iter().flat_map(|it| [it.bx[2], it.bx[3]]).collect();
    ys.sort_unstable_by(|a, b| cmp_f64(*a, *b));
    ys.dedup();
    let rank = |v: f64| ys.partition_point(|&y| y < v) as u32;
    let ranks: Vec<[u32; 2]> = items.iter().map(|it| [rank(it.bx[2]), rank(it.bx[3])]).collect();

    let mut order: Vec<u32> = (0..items.len() as u32).collect();
    order.sort_unstable_by_key(|&i| (key(items[i as usize].bx[0]), i));
    let mut groups = [YStructure::new(ys.len()), YStructure::new(ys.len())];
    let group_of = |i: usize| usize::from(items[i].kind == Kind::Arc);
    let mut alive = vec![false; items.len()];
    // the active items by x_max, to retire those the sweep line has passed
    let mut by_end: BinaryHeap<Reverse<(u64, u32)>> = BinaryHeap::new();
    let mut found: Vec<u32> = Vec::new();
    for &i in &order {
        let i = i as usize;
        let x_min = items[i].bx[0];
        while let Some(&Reverse((end, j))) = by_end.peek() {
            if end >= key(x_min) {
                break;
            }
            by_end.pop();
            alive[j as usize] = false;
            groups[group_of(j as usize)].remove(j, ranks[j as usize][0]);
            visit(Event::Retire(j as usize));
        }
        let [lo, hi] = ranks[i];
        found.clear();
        // an arc meets everything; the rest meet only the arcs
        let searched: &[usize] = if items[i].kind == Kind::Arc { &[1, 0] } else { &[1] };
        for &g in searched {
            groups[g].overlapping(lo, hi, &alive, &mut found);
        }
        for &j in &found {
            visit(Event::Pair(j as usize, i));
        }
        groups[group_of(i)].insert(i as u32, lo, hi);
        alive[i] = true;
        by_end.push(Reverse((key(items[i].bx[1]), i as u32)));
    }
}

/// The active `y` ranges (as ranks) of one group: a segment tree holding
/// each range in its canonical nodes, and the ranges ordered by their lower
/// end. The tree has one leaf per rank (bottom-up, any number of leaves);
/// a node's items are a linked list in one arena (4 bytes a node, 8 an
/// entry, where a `Vec` per node would cost 24 bytes a node for the many
/// empty ones). Removal is lazy: a dead item is unlinked from a node when a
/// query passes it, so each entry is dropped at most once.
struct YStructure {
    leaves: usize,
    /// The first entry of each node's list, or [`NONE`].
    head: Vec<u32>,
    /// `(item, next entry)`.
    entries: Vec<(u32, u32)>,
    by_low: BTreeSet<(u32, u32)>,
}

/// The end of a list.
const NONE: u32 = u32::MAX;

impl YStructure {
    fn new(leaves: usize) -> YStructure {
        let leaves = leaves.max(1);
        YStructure { leaves, head: vec![NONE; 2 * leaves], entries: Vec::new(), by_low: BTreeSet::new() }
    }

    fn insert(&mut self, item: u32, lo: u32, hi: u32) {
        let (mut l, mut r) = (lo as usize + self.leaves, hi as usize + self.leaves + 1);
        while l < r {
            if l & 1 == 1 {
                self.push(l, item);
                l += 1;
            }
            if r & 1 == 1 {
                r -= 1;
                self.push(r, item);
            }
            l >>= 1;
            r >>= 1;
        }
        self.by_low.insert((lo, item));
    }

    fn push(&mut self, node: usize, item: u32) {
        self.entries.push((item, self.head[node]));
        self.head[node] = (self.entries.len() - 1) as u32;
    }

    fn remove(&mut self, item: u32, lo: u32) {
        self.by_low.remove(&(lo, item));
    }

    /// Appends to `out` the live items whose range meets `[lo, hi]`: those
    /// containing `lo` (on the path from its leaf to the root), and those
    /// starting in `(lo, hi]`; each once.
    fn overlapping(&mut self, lo: u32, hi: u32, alive: &[bool], out: &mut Vec<u32>) {
        let mut node = lo as usize + self.leaves;
        while node >= 1 {
            let (mut previous, mut entry) = (NONE, self.head[node]);
            while entry != NONE {
                let (item, next) = self.entries[entry as usize];
                if alive[item as usize] {
                    out.push(item);
                    previous = entry;
                } else if previous == NONE {
                    self.head[node] = next;
                } else {
                    self.entries[previous as usize].1 = next;
                }
                entry = next;
            }
            node >>= 1;
        }
        if hi > lo {
            out.extend(self.by_low.range((lo + 1, 0)..=(hi, u32::MAX)).map(|&(_, j)| j));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    fn bulged(s: [f64; 2], e: [f64; 2], bulge: f64) -> CircularArc {
        CircularArc::from_bulge(s, e, bulge).unwrap()
    }

    fn through(s: [f64; 2], via: [f64; 2], e: [f64; 2]) -> CircularArc {
        CircularArc::through(s, via, e).unwrap()
    }

    /// Every pair with an arc, tested exactly, the least by rank: what the
    /// sweep must find.
    fn brute_force(points: &[Point], segments: &[[Point; 2]], arcs: &[CircularArc]) -> Option<ArcConflict> {
        let exact: Vec<ExactArc> = arcs.iter().map(ExactArc::new).collect();
        let mut all = Vec::new();
        for (a, x) in exact.iter().enumerate() {
            for (i, &q) in points.iter().enumerate() {
                if x.contains_point(q) {
                    all.push(ArcConflict::PointOnArc { point: i, arc: a });
                }
            }
            for (i, &s) in segments.iter().enumerate() {
                if let Some(contact) = segment_arc_contact(x, s) {
                    all.push(ArcConflict::ArcSegment { arc: a, segment: i, contact });
                }
            }
            for (b, y) in exact.iter().enumerate().skip(a + 1) {
                if let Some(contact) = arc_arc_contact(x, y) {
                    all.push(ArcConflict::Arcs { first: a, second: b, contact });
                }
            }
        }
        all.into_iter().min_by_key(|c| c.rank())
    }

    #[test]
    fn messages_and_indices_name_both_inputs() {
        let circle = [bulged([0.0, -5.0], [0.0, 5.0], 1.0), bulged([0.0, 5.0], [0.0, -5.0], 1.0)];
        assert_eq!(first_arc_conflict(&[p(7.0, 0.0)], &[[p(5.0, -1.0), p(6.0, 9.0)]], &circle), None);

        let c = first_arc_conflict(&[p(1.0, 1.0), p(1.0, 2.0), p(-3.0, -4.0)], &[], &circle).unwrap();
        assert_eq!(c, ArcConflict::PointOnArc { point: 2, arc: 1 });
        let e = arc_conflict_error(&c);
        assert_eq!((e.kind(), e.message(), e.indices()), (ErrorKind::Intersecting, "point 2 lies on arc 1", &[2, 1][..]));

        let segments = [[p(9.0, 9.0), p(9.0, 10.0)], [p(5.0, -1.0), p(5.0, 1.0)], [p(0.0, 0.0), p(10.0, 0.0)]];
        let c = first_arc_conflict(&[], &segments, &circle).unwrap();
        assert_eq!(c, ArcConflict::ArcSegment { arc: 0, segment: 1, contact: SegmentArcContact::Tangent });
        assert!(c.message().starts_with("arc 0 and segment 1 touch"), "{}", c.message());
        assert_eq!(arc_conflict_error(&c).indices(), [0, 1]);
        let c = first_arc_conflict(&[], &segments[2..], &circle).unwrap();
        assert_eq!(c.message(), "arc 0 and segment 0 cross");
        let c = first_arc_conflict(&[], &[[p(0.0, 0.0), p(4.0, 3.0)]], &circle).unwrap();
        assert_eq!(c.message(), "arc 0 and segment 0 touch (an end of the segment lies inside the arc)");

        let mut arcs = circle.to_vec();
        arcs.push(through([3.0, 4.0], [6.0, 5.0], [11.0, 0.0]));
        arcs.push(circle[1].reversed());
        let c = first_arc_conflict(&[], &[], &arcs).unwrap();
        assert_eq!(c.message(), "arcs 0 and 2 touch (an end of arc 2 lies inside arc 0)");
        assert_eq!(check_arcs(&[], &[], &arcs).unwrap_err().indices(), [0, 2]);
        let c = first_arc_conflict(&[], &[], &[arcs[1], arcs[3]]).unwrap();
        assert_eq!((c.message(), c.indices()), ("arcs 0 and 1 overlap".to_string(), [0, 1]));
        let crossing = through([6.0, 5.0], [1.0, 0.0], [6.0, -5.0]);
        let c = first_arc_conflict(&[], &[], &[crossing, circle[0]]).unwrap();
        assert_eq!(c.message(), "arcs 0 and 1 cross");
        assert!(check_arcs(&[p(0.0, 5.0)], &[[p(0.0, 5.0), p(-7.0, 5.0)]], &circle).is_ok(), "shared ends, tangent");
    }

    #[test]
    fn the_least_conflict_is_reported_whatever_the_order() {
        // point 1 on arc 2 and on arc 0; segment 0 crosses arc 0; arcs 1 and 2 cross
        let arcs = [
            bulged([0.0, -5.0], [0.0, 5.0], 1.0),
            through([6.0, 5.0], [1.0, 0.0], [6.0, -5.0]),
            bulged([0.0, 5.0], [0.0, -5.0], -1.0),
        ];
        let points = [p(20.0, 20.0), p(5.0, 0.0)];
        let segments = [[p(0.0, 0.0), p(9.0, 1.0)]];
        let expected = ArcConflict::PointOnArc { point: 1, arc: 0 };
        assert_eq!(first_arc_conflict(&points, &segments, &arcs), Some(expected));
        assert_eq!(brute_force(&points, &segments, &arcs), Some(expected));
        assert_eq!(
            first_arc_conflict(&[], &segments, &arcs),
            Some(ArcConflict::ArcSegment { arc: 0, segment: 0, contact: SegmentArcContact::Cross })
        );
        assert_eq!(first_arc_conflict(&[], &[], &arcs).map(|c| c.indices()), Some([0, 1]));
        assert_eq!(first_arc_conflict(&[], &[], &arcs[1..]).map(|c| c.indices()), Some([0, 1]));
    }

    #[test]
    fn chains_and_circles_pass() {
        // a rounded rectangle (sides and quarter arcs, tangent-continuous), a
        // full circle as two arcs inside it, a slot, and points at centres
        let mut segments = vec![];
        let mut arcs = vec![];
        let q = (std::f64::consts::PI / 8.0).tan();
        let corners =
            [([10.0, 0.0], [12.0, 2.0]), ([12.0, 8.0], [10.0, 10.0]), ([0.0, 10.0], [-2.0, 8.0]), ([-2.0, 2.0], [0.0, 0.0])];
        for (k, (a, b)) in corners.iter().enumerate() {
            arcs.push(bulged(*a, *b, q));
            let next = corners[(k + 1) % 4].0;
            segments.push([p(b[0], b[1]), p(next[0], next[1])]);
        }
        arcs.push(bulged([3.0, 5.0], [7.0, 5.0], 1.0));
        arcs.push(bulged([7.0, 5.0], [3.0, 5.0], 1.0));
        // the slot's caps bulge outward: clockwise as the ring runs
        arcs.push(bulged([1.0, 8.0], [1.0, 9.0], -1.0));
        arcs.push(bulged([4.0, 9.0], [4.0, 8.0], -1.0));
        segments.push([p(1.0, 9.0), p(4.0, 9.0)]);
        segments.push([p(4.0, 8.0), p(1.0, 8.0)]);
        let points = [p(5.0, 5.0), p(10.0, 2.0), p(0.0, 2.0)];
        assert_eq!(first_arc_conflict(&points, &segments, &arcs), None);
        assert_eq!(brute_force(&points, &segments, &arcs), None);
        // the slot's end touched from outside by a tangent segment: a conflict
        let mut more = segments.clone();
        more.push([p(4.5, 7.0), p(4.5, 10.0)]);
        assert_eq!(
            first_arc_conflict(&points, &more, &arcs),
            Some(ArcConflict::ArcSegment { arc: 7, segment: 6, contact: SegmentArcContact::Tangent })
        );
    }

    /// Boxes of random items, with every pair the sweep reports against
    /// the O(n²) list of overlapping boxes with an arc among them.
    #[test]
    fn the_sweep_reports_exactly_the_overlapping_boxes() {
        let mut rng = SplitMix64(31);
        for round in 0..200 {
            let n = 1 + (rng.next_u64() % if round % 10 == 0 { 500 } else { 40 }) as usize;
            let grid = 1 + rng.next_u64() % if round % 10 == 0 { 200 } else { 12 };
            let coordinate = |rng: &mut SplitMix64| (rng.next_u64() % grid) as f64 - 3.0;
            let items: Vec<Item> = (0..n)
                .map(|i| {
                    let kind = [Kind::Point, Kind::Segment, Kind::Arc][(rng.next_u64() % 3) as usize];
                    let (x0, y0) = (coordinate(&mut rng), coordinate(&mut rng));
                    let (x1, y1) = if kind == Kind::Point { (x0, y0) } else { (coordinate(&mut rng), coordinate(&mut rng)) };
                    Item { kind, index: i, bx: [x0.min(x1), x0.max(x1), y0.min(y1), y0.max(y1)] }
                })
                .collect();
            let mut swept = Vec::new();
            let mut retired = vec![false; n];
            box_sweep(&items, |event| match event {
                Event::Pair(i, j) => {
                    assert!(!retired[i] && !retired[j], "round {round}: a pair after retirement");
                    swept.push((i.min(j), i.max(j)));
                }
                Event::Retire(i) => {
                    assert!(!retired[i]);
                    retired[i] = true;
                }
            });
            swept.sort_unstable();
            let mut expected = Vec::new();
            for i in 0..n {
                for j in i + 1..n {
                    let (a, b) = (items[i].bx, items[j].bx);
                    let overlap = a[0] <= b[1] && b[0] <= a[1] && a[2] <= b[3] && b[2] <= a[3];
                    if overlap && (items[i].kind == Kind::Arc || items[j].kind == Kind::Arc) {
                        expected.push((i, j));
                    }
                }
            }
            assert_eq!(swept, expected, "round {round}");
        }
    }

    /// Random small inputs on a grid, full of exact degeneracies (points on
    /// circles, shared endpoints, tangencies, arcs of one circle): the
    /// sweep finds what testing every pair finds, at every power-of-two
    /// scale and far from the origin; and every arc lies inside its box.
    #[test]
    fn the_sweep_agrees_with_every_pair_on_random_grids() {
        let mut rng = SplitMix64(2026);
        let bulges = [0.5, -0.5, 1.0, -1.0, 2.0, -2.0, 0.25, -3.0, 1.0 / 3.0];
        let mut conflicts = 0;
        for round in 0..400 {
            let grid = 3 + rng.next_u64() % 6;
            let mut coordinate = || (rng.next_u64() % grid) as f64 * 2.0 - grid as f64;
            let mut pts = Vec::new();
            for _ in 0..12 {
                pts.push(p(coordinate(), coordinate()));
            }
            let (scale, offset) =
                [(1.0, 0.0), (f64::from_bits(24 << 52), 0.0), (2f64.powi(900), 0.0), (1.0, 2f64.powi(30))][round % 4];
            let place = |q: Point| p(q.x * scale + offset, q.y * scale - offset);
            let mut next = 0;
            let mut take = |k: usize| {
                next += 1;
                place(pts[(next * 7 + k) % pts.len()])
            };
            let points: Vec<Point> = (0..(round % 3)).map(&mut take).collect();
            let segments: Vec<[Point; 2]> = (0..(round % 4)).map(|k| [take(k), take(k + 1)]).collect();
            let mut arcs = Vec::new();
            for k in 0..2 + round % 4 {
                let (s, e, m) = (take(k), take(k + 2), take(k + 5));
                let arc = if k % 2 == 0 {
                    CircularArc::from_bulge(s, e, bulges[(k + round) % bulges.len()])
                } else {
                    CircularArc::through(s, m, e)
                };
                arcs.extend(arc.ok());
            }
            let found = first_arc_conflict(&points, &segments, &arcs);
            assert_eq!(found, brute_force(&points, &segments, &arcs), "round {round}: {points:?} {segments:?} {arcs:?}");
            conflicts += usize::from(found.is_some());
            // the same figure reversed, mirrored, or scaled by 2^∓600: the
            // same conflict (mirroring flips each arc's turn, not its set)
            let reversed: Vec<CircularArc> = arcs.iter().map(|a| a.reversed()).collect();
            assert_eq!(first_arc_conflict(&points, &segments, &reversed), found, "round {round}: reversed");
            let mirror = |q: Point| p(-q.x, q.y);
            let mirrored_arcs: Vec<CircularArc> = arcs
                .iter()
                .map(|a| match a.datum() {
                    (Some(b), _) => CircularArc::from_bulge(mirror(a.start()), mirror(a.end()), -b).unwrap(),
                    (_, via) => CircularArc::through(mirror(a.start()), mirror(via.unwrap()), mirror(a.end())).unwrap(),
                })
                .collect();
            let mirrored_points: Vec<Point> = points.iter().map(|&q| mirror(q)).collect();
            let mirrored_segments: Vec<[Point; 2]> = segments.iter().map(|s| [mirror(s[0]), mirror(s[1])]).collect();
            assert_eq!(
                first_arc_conflict(&mirrored_points, &mirrored_segments, &mirrored_arcs),
                found,
                "round {round}: mirrored"
            );
            // 2^-600, or 2^600 for the inputs already near 2^-1000
            let tiny = f64::from_bits(if scale < 1.0 { 1623 << 52 } else { 423 << 52 });
            let scaled_arcs: Vec<CircularArc> = arcs.iter().map(|a| a.scaled(tiny)).collect();
            let scaled_points: Vec<Point> = points.iter().map(|q| q.scaled(tiny)).collect();
            let scaled_segments: Vec<[Point; 2]> = segments.iter().map(|s| [s[0].scaled(tiny), s[1].scaled(tiny)]).collect();
            assert_eq!(first_arc_conflict(&scaled_points, &scaled_segments, &scaled_arcs), found, "round {round}: scaled");
            for arc in &arcs {
                let bx = arc_box(arc);
                for i in 0..=64 {
                    let q = arc.point_at(i as f64 / 64.0);
                    let slack = 1e-9 * arc.radius();
                    let inside = q.x >= bx[0] - slack && q.x <= bx[1] + slack && q.y >= bx[2] - slack && q.y <= bx[3] + slack;
                    assert!(inside, "round {round}: {q:?} outside {bx:?} of {arc:?}");
                }
            }
        }
        assert!(conflicts > 100 && conflicts < 390, "{conflicts} conflicts: the inputs should mix both");
    }

    /// Extreme finite inputs: nothing panics, and the sweep still agrees
    /// with testing every pair.
    #[test]
    fn extreme_inputs_do_not_panic() {
        let mut rng = SplitMix64(7);
        let magnitudes = [1e308, -1e308, 1e-308, 5e-324, 0.0, 1.0, -3.5, 1e154, 1e-160, f64::MAX, -f64::MAX];
        let bulges = [1e308, -1e300, 1e-300, 1e150, -1e-150, 1.0, 2f64.powi(60), -(2f64.powi(-60))];
        let (mut accepted, mut conflicts) = (0, 0);
        for round in 0..300 {
            let mut value = || {
                let m = magnitudes[(rng.next_u64() % magnitudes.len() as u64) as usize];
                m * (1.0 + (rng.next_u64() % 4) as f64 / 4.0).min(if m.abs() > 1e300 { 1.0 } else { 2.0 })
            };
            let mut pts: Vec<Point> = (0..8).map(|_| p(value(), value())).collect();
            pts.push(p(0.0, 0.0));
            let pick = |k: usize| pts[k % pts.len()];
            let mut arcs = Vec::new();
            for k in 0..4 {
                let b = bulges[(round + k) % bulges.len()];
                arcs.extend(CircularArc::from_bulge(pick(round + k), pick(round + 3 * k + 1), b).ok());
                arcs.extend(CircularArc::through(pick(round + k), pick(round + 2 * k + 5), pick(round + 3 * k + 1)).ok());
            }
            let segments = [[pick(round), pick(round + 1)], [pick(round + 2), pick(round + 2)]];
            let points = [pick(round + 3), pick(round + 4)];
            let found = first_arc_conflict(&points, &segments, &arcs);
            assert_eq!(found, brute_force(&points, &segments, &arcs), "round {round}");
            accepted += arcs.len();
            conflicts += usize::from(found.is_some());
        }
        assert!(accepted > 200 && conflicts > 20, "{accepted} arcs, {conflicts} conflicts");
        // arcs that only the crate's own scaling into underflow can make
        // (endpoints merged, or the third point on the chord): no panic
        let under = f64::from_bits(1); // 2^-1074
        let degenerate = [
            bulged([0.0, 0.0], [1.0, 0.0], 1.0).scaled(under / 2.0),
            through([0.0, 0.0], [3.0, 1e-300], [6.0, 0.0]).scaled(under),
            bulged([1.0, 1.0], [3.0, 1.0], 0.5),
        ];
        let _ = first_arc_conflict(&[p(0.0, 0.0)], &[[p(-1.0, 0.0), p(1.0, 0.0)]], &degenerate);
    }

    /// The cost of the check on 100k arcs (run with `--ignored
    /// --nocapture`, in release): a tangent-continuous chain of half
    /// circles, a chain of shallow arcs with a segment beside each, and
    /// separate random arcs on a grid with a point at each centre.
    #[test]
    #[ignore]
    fn cost_of_the_check() {
        let n = 100_000;
        let time = |name: &str, points: &[Point], segments: &[[Point; 2]], arcs: &[CircularArc]| {
            let start = std::time::Instant::now();
            let found = first_arc_conflict(points, segments, arcs);
            let took = start.elapsed();
            eprintln!(
                "{name}: {} arcs, {} segments, {} points: {:?} ({:.2} µs per arc)",
                arcs.len(),
                segments.len(),
                points.len(),
                took,
                took.as_secs_f64() * 1e6 / arcs.len() as f64
            );
            assert_eq!(found, None, "{name}");
        };
        let chain: Vec<CircularArc> =
            (0..n).map(|i| bulged([i as f64, 0.0], [i as f64 + 1.0, 0.0], if i % 2 == 0 { 1.0 } else { -1.0 })).collect();
        time("tangent chain", &[], &[], &chain);
        let shallow: Vec<CircularArc> =
            (0..n).map(|i| bulged([i as f64 * 0.75, 0.5], [i as f64 * 0.75 + 0.75, 0.5], 0.3)).collect();
        let beside: Vec<[Point; 2]> = (0..n).map(|i| [p(i as f64 * 0.75, -1.0), p(i as f64 * 0.75 + 0.75, -1.0)]).collect();
        time("shallow chain beside segments", &[], &beside, &shallow);
        let mut rng = SplitMix64(5);
        let mut random = Vec::new();
        let mut centres = Vec::new();
        for i in 0..n {
            let (cx, cy) = ((i % 316) as f64 * 4.0, (i / 316) as f64 * 4.0);
            let a = rng.unit() * 6.0;
            let b = a + 0.2 + rng.unit() * 5.0;
            let r = 0.5 + rng.unit();
            let at = |t: f64| [cx + r * t.cos(), cy + r * t.sin()];
            random.push(through(at(a), at(0.5 * (a + b)), at(b)));
            centres.push(p(cx, cy));
        }
        time("random arcs, a point at each centre", &centres, &[], &random);
    }
}
