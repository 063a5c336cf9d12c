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
//! # Which conflict is reported
//! The least by (kind, arc index, other index), kinds in the order
//! arc–point, arc–segment, arc–arc, and for two arcs the smaller index
//! first: "the point with the smallest index on the arc with the smallest
//! index", whatever order the sweep meets the pairs in. A pair that could
//! not beat the best conflict found so far is not tested.

// The build with arcs (`construct::with_arcs`) is being written beside this
// check and will call it; until then only the tests do.
#![cfg_attr(not(test), allow(dead_code))]

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
/// are handled exactly.
pub(crate) fn first_arc_conflict(points: &[Point], segments: &[[Point; 2]], arcs: &[CircularArc]) -> Option<ArcConflict> {
    if arcs.is_empty() {
        return None;
    }
    let exact: Vec<ExactArc> = arcs.iter().map(ExactArc::new).collect();
    let mut items: Vec<Item> = Vec::with_capacity(points.len() + segments.len() + arcs.len());
    items.extend(points.iter().enumerate().map(|(i, p)| Item { kind: Kind::Point, index: i, bx: [p.x, p.x, p.y, p.y] }));
    items.extend(segments.iter().enumerate().map(|(i, [a, b])| Item {
        kind: Kind::Segment,
        index: i,
        bx: [a.x.min(b.x), a.x.max(b.x), a.y.min(b.y), a.y.max(b.y)],
    }));
    items.extend(arcs.iter().zip(&exact).enumerate().map(|(i, (arc, x))| Item {
        kind: Kind::Arc,
        index: i,
        bx: arc_box(arc, x),
    }));
    for item in &mut items {
        // +0.0 for -0.0, so that the bit-keyed orders below are numeric
        for v in &mut item.bx {
            *v += 0.0;
        }
    }
    let mut best: Option<ArcConflict> = None;
    box_sweep(&items, |i, j| {
        let (a, b) = (&items[i], &items[j]);
        let (arc, other) = if a.kind == Kind::Arc && (b.kind != Kind::Arc || a.index < b.index) { (a, b) } else { (b, a) };
        let rank = match other.kind {
            Kind::Point => (0, arc.index, other.index),
            Kind::Segment => (1, arc.index, other.index),
            Kind::Arc => (2, arc.index, other.index),
        };
        if best.is_some_and(|c| c.rank() <= rank) {
            return;
        }
        let x = &exact[arc.index];
        let found = match other.kind {
            Kind::Point => {
                x.contains_point(points[other.index]).then_some(ArcConflict::PointOnArc { point: other.index, arc: arc.index })
            }
            Kind::Segment => segment_arc_contact(x, segments[other.index]).map(|contact| ArcConflict::ArcSegment {
                arc: arc.index,
                segment: other.index,
                contact,
            }),
            Kind::Arc => arc_arc_contact(x, &exact[other.index]).map(|contact| ArcConflict::Arcs {
                first: arc.index,
                second: other.index,
                contact,
            }),
        };
        if found.is_some() {
            best = found;
        }
    });
    best
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

/// Calls `pair(i, j)` once for every pair of items whose closed boxes
/// overlap and of which at least one is an arc (see the module
/// documentation).
fn box_sweep(items: &[Item], mut pair: impl FnMut(usize, usize)) {
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
        }
        let [lo, hi] = ranks[i];
        found.clear();
        // an arc meets everything; the rest meet only the arcs
        let searched: &[usize] = if items[i].kind == Kind::Arc { &[1, 0] } else { &[1] };
        for &g in searched {
            groups[g].overlapping(lo, hi, &alive, &mut found);
        }
        for &j in &found {
            pair(j as usize, i);
        }
        groups[group_of(i)].insert(i as u32, lo, hi);
        alive[i] = true;
        by_end.push(Reverse((key(items[i].bx[1]), i as u32)));
    }
}

/// The active `y` ranges (as ranks) of one group: a segment tree holding
/// each range in its canonical nodes (removal is lazy: dead items are
/// dropped from a node when a query passes it), and the ranges ordered by
/// their lower end.
struct YStructure {
    size: usize,
    nodes: Vec<Vec<u32>>,
    by_low: BTreeSet<(u32, u32)>,
}

impl YStructure {
    fn new(leaves: usize) -> YStructure {
        let size = leaves.max(1).next_power_of_two();
        YStructure { size, nodes: vec![Vec::new(); 2 * size], by_low: BTreeSet::new() }
    }

    fn insert(&mut self, item: u32, lo: u32, hi: u32) {
        let (mut l, mut r) = (lo as usize + self.size, hi as usize + self.size + 1);
        while l < r {
            if l & 1 == 1 {
                self.nodes[l].push(item);
                l += 1;
            }
            if r & 1 == 1 {
                r -= 1;
                self.nodes[r].push(item);
            }
            l >>= 1;
            r >>= 1;
        }
        self.by_low.insert((lo, item));
    }

    fn remove(&mut self, item: u32, lo: u32) {
        self.by_low.remove(&(lo, item));
    }

    /// Appends to `out` the live items whose range meets `[lo, hi]`: those
    /// containing `lo` (the stabbing query), and those starting in
    /// `(lo, hi]`; each once.
    fn overlapping(&mut self, lo: u32, hi: u32, alive: &[bool], out: &mut Vec<u32>) {
        let mut node = lo as usize + self.size;
        while node >= 1 {
            let list = &mut self.nodes[node];
            list.retain(|&j| alive[j as usize]);
            out.extend_from_slice(list);
            node >>= 1;
        }
        if hi > lo {
            out.extend(self.by_low.range((lo + 1, 0)..=(hi, u32::MAX)).map(|&(_, j)| j));
        }
    }
}
