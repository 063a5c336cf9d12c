//! # Which conflict is found, and every split: a Shamos–Hoey sweep
//! The kept segments and isolated points are swept in lexicographic order
//! of their points (by `x`, then by `y`): think of a vertical sweep line
//! tilted by an infinitesimal clockwise angle, so that no two distinct
//! points are ever met at once and a vertical segment runs, like any
//! other, from its first point (the lower end) to its last. A shear does
//! not change orientations, so every decision below is an exact
//! orientation sign of input points ([`exact_orientation`], never perturbed
//! by fault injection) or an exact coordinate comparison.
//!
//! Each segment is oriented from its lexicographically smaller end (its
//! *first* point) to its larger (*last*). The *status* holds the segments
//! the sweep line currently crosses, ordered from below to above, in a treap
//! with parent links (a node is a segment, numbered in the order of the
//! first points, so that the segments in the status at one time mostly lie
//! close together in memory). An *event* is one distinct point with
//! everything there: the segments starting there, those ending there, or one
//! isolated point (normalisation has made isolated points distinct from all
//! endpoints). At event `q`:
//! 1. the neighbours of `q` in the status. When segments end at `q`, they
//!    are taken out by their nodes (no comparison), and the neighbours are
//!    the nodes next to them that do not end at `q`. Otherwise the treap is
//!    descended by the sign of `orientation(first, last, q)` (`q` above,
//!    below or on the segment): the last node passed below `q` and the last
//!    passed above it;
//! 2. the segments with `q` in their open interior. The segments ending at
//!    `q` and those with `q` inside form one run of the status, so one of
//!    the latter, if any, is a neighbour of one of the former, where step 1
//!    looks; when nothing ends at `q`, the descent meets one (a search in a
//!    binary tree meets an equal key when there is one). From it, the run
//!    is walked (after the ending ones have left). Two segments through `q`
//!    cross there or overlap: a conflict at `q`, and the sweep stops,
//!    except for ring segments that share a stretch (allowed: see below).
//!    One alone, `t`, is a touching: `t` is *split* at `q` (a [`Split`] names
//!    `t` and the input vertex at `q`: the isolated point, or an end of the
//!    segment with the smallest index among those starting or ending there).
//!    From `q` on, `t` is what is left of it, from `q` to its last point:
//!    it leaves the status and enters again in step 3 with the segments
//!    starting at `q`, and the neighbours of `q` are its neighbours;
//! 3. the segments starting at `q` (and a split `t`), sorted by direction
//!    (`orientation(q, last_i, last_j)`, exact; ties, which are overlaps, by
//!    index), enter between the neighbours;
//! 4. every pair of segments that has just become adjacent is classified
//!    (`classify.rs`): the neighbour below with the lowest new one, each new
//!    one with the next, the highest new one with the neighbour above; or,
//!    when nothing starts at `q`, the two neighbours. A pair that meets only
//!    at an endpoint of one inside the other is no conflict (step 2 splits
//!    it when the sweep reaches that point).
//!
//! # Ring segments that share a stretch
//! Two collinear ring segments that overlap are no conflict when the
//! caller allows it (`Normalised::may_overlap`, for polygon rings, whose
//! shared stretches cancel by the even-odd rule): they are split at each
//! other's endpoints inside them, as touchings are, so that the shared
//! stretch becomes equal pieces. In the status, overlapping segments are
//! tied (neither is above the other), a group that every other segment
//! meets as it would meet one of them; they enter next to each other (a
//! tie in step 3 is sorted by index) and a run through `q` in step 2 may
//! hold several of them, all split at `q`. So the arguments below hold
//! with each such group in the place of one segment.
//!
//! # Which conflict is reported, and why it is seen
//! Every conflict found (a crossing or an overlap) is ranked by its
//! *contact point*, the lexicographically smallest point the two segments
//! share (`geometry::input::segment_contact::first_contact`; a crossing point is a
//! rational point, compared exactly); the smallest contact point wins, and
//! among conflicts found at the same contact point, the smaller pair of
//! input indices (smaller index first). The sweep stops at the first event
//! lexicographically past the best contact point found so far.
//!
//! Let `p*` be the smallest contact point of all conflicts. Before the
//! sweep reaches `p*`, no two active segments share a point left of the
//! sweep line other than a common endpoint or a touching (an endpoint of
//! one inside the other), neither of which changes their order, so the
//! status order is the true order along the sweep line, and "below `q`",
//! "through `q`", "above `q`" split it into three runs; a split segment
//! re-enters by its direction at `q`, as a segment starting there, so the
//! order stays true after `q`. Two cases:
//! - `p*` is an event point. Either two segments pass through `p*` (a
//!   crossing there, or an overlap: step 2 sees them, one run of the status
//!   next to where it looks), or one passes through it and the other starts
//!   there along it (an overlap: the split one re-enters with the starting
//!   ones, collinear with it, so they are neighbours in the sorted start
//!   list and step 4 sees them), or both start there in one direction (the
//!   same).
//! - `p*` is not an event point: two segments cross there properly. All
//!   segments through `p*` are active just left of it and, by continuity,
//!   contiguous in the status; any two of them cross at `p*` (an overlap
//!   would meet further left), so the lowest two, `g` and `h`, do. Between
//!   the last event before `p*` and `p*` the order does not change, so `g`
//!   and `h` became adjacent at some event before `p*`, and every new
//!   adjacency is classified (step 4).
//!
//! So a conflict at `p*` is found by the time the sweep has handled the
//! event `p*`, or the last event before it; the sweep never handles an event
//! past `p*`, and so it always works on a status whose order is right
//! (only the last event handled may leave it wrong, and the sweep stops
//! after it). Events past the best contact found so far are not needed:
//! a conflict with a smaller contact point `p` would be found at an event
//! no later than `p`.
//!
//! Every split is found: a vertex `q` inside a segment `t` is an event, `t`
//! is active and through `q` there, and with no conflict up to `q` it is
//! the only segment through `q`, which step 2 finds. A split costs one
//! walk step, a removal and an insertion, O(log n) expected.
//!
//! # Cost
//! Sorting the segments by first point (normalisation's sort, which finds
//! the repeated segments, gives that order), their last points and the
//! isolated points, O(n log n). Each event costs at most one descent of
//! the treap, plus, per segment starting there, its share of sorting them
//! and an insertion, and per segment ending there, two neighbour steps and
//! a removal, all O(log n) expected; plus one classification per segment
//! starting there and one more per event. So O(n log n) in all, for every
//! input: a star of k spokes costs one sort of k directions, long parallel
//! bundles cost what short segments cost. The expectation is over the
//! treap's priorities, a fixed pseudo-random sequence that the geometry
//! does not influence. (An AVL tree makes the bound deterministic and
//! passes fewer nodes per descent, but was slower here: 1.35 times on a
//! million parallel segments, whose insertions and removals at the ends of
//! the status rebalance all the way up, and no faster on a star.)
//! Comparing the best contact point with each later event is O(1): an
//! `f64` approximation with an error bound decides unless they are within
//! a few ulps, then big numbers of fixed size.
//!
//! Two shortcuts for hubs, where many segments meet: when every segment
//! in the status ends at an event, the status is emptied at once (no
//! neighbour steps, no removals; nothing can be through `q`); and more than
//! [`PRESORTED_FROM`] segments starting at one point are sorted by an
//! approximate angle before the exact sort, which, adaptive to runs in
//! order, then mostly confirms it (a hub's spokes come in any order).
//!
//! Measured (`bench --bin check`, figures in BENCHMARKS.md): from 10k to
//! 1M segments the instructions grow as n^1.02 to n^1.04 on every family;
//! on a star the time grows faster, because its status of half a million
//! spokes (32 MB of nodes) no longer fits the caches and the deepest levels
//! of each descent wait for memory.

use std::cmp::Ordering;

use super::classify::segment_conflict_at;
use super::normalise::Normalised;
use super::{Conflict, PointSource, Split, Vertex};
use crate::construct::status_treap::{Treap, NIL};
use crate::geometry::input::segment_contact::{lex_cmp, lex_key, segment_contact, ContactPoint};
use crate::geometry::predicates::{exact_orientation, Orientation};
use crate::geometry::Point;

/// The conflict whose contact point is lexicographically smallest (see
/// the module documentation for ties), or `None` when there is none.
pub(super) fn find_conflict(norm: &Normalised) -> Option<Conflict> {
    find_conflict_at(norm).map(|(c, _)| c)
}

/// [`find_conflict`] with the conflict's contact point.
pub(super) fn find_conflict_at(norm: &Normalised) -> Option<(Conflict, ContactPoint)> {
    sweep(norm).0
}

/// The sweep: the conflict whose contact point is smallest, with that
/// point; and every split (an input vertex in the open interior of a kept
/// segment), by segment and along it — all of them when there is no
/// conflict, else those left of the conflict.
pub(super) fn sweep(norm: &Normalised) -> (Option<(Conflict, ContactPoint)>, Vec<Split>) {
    if norm.segments.is_empty() {
        return (None, Vec::new()); // distinct points never conflict
    }
    let m = norm.segments.len();
    assert!(m < NIL as usize && norm.points.len() < NIL as usize, "item ids are 32-bit");
    let oriented = |[a, b]: [Point; 2]| if lex_cmp(a, b) == Ordering::Greater { [b, a] } else { [a, b] };
    // Node ids in the order of the first points (normalisation's sort):
    // the start events come in that order, and the segments in the status
    // at one time lie close together in memory.
    let kept = &norm.by_first_point;
    let status = Treap::new(kept.iter().map(|&k| oriented(norm.segments[k as usize].1)));
    let mut ends: Vec<(Key, u32)> = (0..m as u32).map(|k| (lex_key(status.segment(k)[1]), k)).collect();
    ends.sort_unstable();
    let mut lone: Vec<(Key, u32)> = norm.points.iter().enumerate().map(|(k, &(_, q))| (lex_key(q), k as u32)).collect();
    lone.sort_unstable();

    let mut sweep = Sweep {
        norm,
        status,
        kept,
        ending: vec![false; m],
        best: None,
        group: Group::default(),
        adjacent: Vec::new(),
        by_angle: Vec::new(),
        splits: Vec::new(),
    };
    let (mut next_start, mut next_end, mut next_lone) = (0, 0, 0);
    loop {
        // The next event: the smallest of the three streams' heads.
        let start_key = (next_start < m).then(|| sweep.first_key(next_start));
        let end_key = ends.get(next_end).map(|e| e.0);
        let lone_key = lone.get(next_lone).map(|e| e.0);
        let Some(key) = [start_key, end_key, lone_key].into_iter().flatten().min() else { break };
        let q = if start_key == Some(key) {
            sweep.status.segment(next_start as u32)[0]
        } else if end_key == Some(key) {
            sweep.status.segment(ends[next_end].1)[1]
        } else {
            norm.points[lone[next_lone].1 as usize].1
        };
        if sweep.best.as_ref().is_some_and(|best| best.1.cmp(&ContactPoint::At(q)) == Ordering::Less) {
            break; // past the best contact point
        }
        sweep.group.clear();
        while next_start < m && sweep.first_key(next_start) == key {
            sweep.group.starts.push(next_start as u32);
            next_start += 1;
        }
        while next_end < m && ends[next_end].0 == key {
            sweep.group.ends.push(ends[next_end].1);
            next_end += 1;
        }
        if next_lone < lone.len() && lone[next_lone].0 == key {
            sweep.group.lone = Some(lone[next_lone].1);
            next_lone += 1;
        }
        sweep.event(q);
    }
    // Found in the order of the events, so along each segment; a stable
    // sort by segment keeps that order.
    let mut splits = sweep.splits;
    splits.sort_by_key(|s| s.segment);
    (sweep.best, splits)
}

/// From how many segments starting at one event the exact sort by direction
/// is preceded by an approximate one.
pub(super) const PRESORTED_FROM: usize = 32;

/// A point's sort key ([`lex_key`]).
type Key = (u64, u64);

/// Everything at one event point: node ids of the segments starting and
/// ending there, or the isolated point.
#[derive(Default)]
struct Group {
    starts: Vec<u32>,
    ends: Vec<u32>,
    lone: Option<u32>,
}

impl Group {
    fn clear(&mut self) {
        self.starts.clear();
        self.ends.clear();
        self.lone = None;
    }
}

struct Sweep<'a> {
    norm: &'a Normalised,
    /// The segments the sweep line crosses, from below to above.
    status: Treap,
    /// Per node, its kept segment (position in `norm.segments`).
    kept: &'a [u32],
    /// Per node: it ends at the current event.
    ending: Vec<bool>,
    best: Option<(Conflict, ContactPoint)>,
    /// Scratch space, kept from event to event.
    group: Group,
    adjacent: Vec<(u32, u32)>,
    by_angle: Vec<(f64, u32)>,
    /// The splits found so far, in the order of the events.
    splits: Vec<Split>,
}

impl Sweep<'_> {
    /// The sort key of node `i`'s first point.
    fn first_key(&self, i: usize) -> Key {
        lex_key(self.status.segment(i as u32)[0])
    }

    /// Handles the event at `q` (steps 1 to 4 of the module documentation)
    /// with what `self.group` holds.
    fn event(&mut self, q: Point) {
        let side = |[a, b]: [Point; 2]| exact_orientation(a, b, q);
        // Steps 1 and 2: the neighbours of q, and a segment through q that
        // does not end there. The segments ending at q and those with q in
        // their interior are one run, so one of the latter, if any, is next
        // to one of the former; without the former, the descent meets one.
        let (mut below, mut above, mut interior) = (NIL, NIL, NIL);
        if self.group.ends.is_empty() {
            (below, above, interior) = self.status.locate(side);
        } else if self.group.ends.len() == self.status.len() {
            // All of the status ends here (a hub, or the last event of a
            // component): no neighbours and nothing through q, and the
            // status empties at once rather than node by node.
            self.status.clear();
        } else {
            for &e in &self.group.ends {
                self.ending[e as usize] = true;
            }
            for &e in &self.group.ends {
                let (p, n) = (self.status.previous(e), self.status.next(e));
                for (neighbour, slot) in [(p, &mut below), (n, &mut above)] {
                    if neighbour != NIL && !self.ending[neighbour as usize] {
                        *slot = neighbour;
                        if side(self.status.segment(neighbour)) == Orientation::Collinear {
                            interior = neighbour;
                        }
                    }
                }
            }
            for &e in &self.group.ends {
                self.ending[e as usize] = false;
                self.status.remove(e);
            }
        }
        if interior != NIL {
            // The segments through q (the ending ones have left): one run of
            // the status, from `t` up to `last`. Two of them cross at q or
            // overlap: a conflict at q, and the sweep stops here, unless
            // they are ring segments sharing a stretch, which are allowed
            // (`Normalised::may_overlap`: every two of the run are then
            // collinear, so checking neighbours suffices). The run is split
            // at q, and from q on it is ordered among the segments starting
            // there, as if it started there too.
            let mut t = interior;
            loop {
                let p = self.status.previous(t);
                if p == NIL || side(self.status.segment(p)) != Orientation::Collinear {
                    break;
                }
                t = p;
            }
            let mut last = t;
            loop {
                let other = self.status.next(last);
                if other == NIL || side(self.status.segment(other)) != Orientation::Collinear {
                    break;
                }
                let found = self.pair(last, other);
                if found.is_some() {
                    self.offer(found);
                    return; // a conflict at q: the sweep stops here
                }
                last = other;
            }
            let at = self.vertex_at(q);
            let mut k = t;
            loop {
                self.splits.push(Split { segment: self.kept[k as usize] as usize, at });
                if k == last {
                    break;
                }
                k = self.status.next(k);
            }
            if self.group.lone.is_some() {
                return; // nothing starts or ends at an isolated point
            }
            (below, above) = (self.status.previous(t), self.status.next(last));
            let mut k = t;
            loop {
                let next = self.status.next(k);
                self.status.remove(k);
                self.group.starts.push(k);
                if k == last {
                    break;
                }
                k = next;
            }
        }
        if self.group.lone.is_some() {
            return; // nothing starts or ends at an isolated point
        }

        // Step 3: those starting at q enter, by direction. Many of them (a
        // hub) are first sorted by an approximate angle, plain numbers
        // sorted fast, so that the exact sort, adaptive to runs already in
        // order, has little left to do.
        let (status, kept) = (&self.status, self.kept);
        if self.group.starts.len() > PRESORTED_FROM {
            let angle = |i: u32| {
                let last = status.segment(i)[1];
                let (dx, dy) = (last.x - q.x, last.y - q.y); // dx >= 0: last > q
                dy / (dx + dy.abs()) // increasing with the angle from -90° to 90°
            };
            self.by_angle.clear();
            self.by_angle.extend(self.group.starts.iter().map(|&i| (angle(i), i)));
            self.by_angle.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
            self.group.starts.clear();
            self.group.starts.extend(self.by_angle.iter().map(|&(_, i)| i));
        }
        self.group.starts.sort_by(|&i, &j| match exact_orientation(q, status.segment(i)[1], status.segment(j)[1]) {
            Orientation::CounterClockwise => Ordering::Less,
            Orientation::Clockwise => Ordering::Greater,
            Orientation::Collinear => kept[i as usize].cmp(&kept[j as usize]),
        });
        self.adjacent.clear();
        let mut previous = below;
        for &s in &self.group.starts {
            self.adjacent.push((previous, s));
            self.status.insert_after(previous, s);
            previous = s;
        }
        self.adjacent.push((previous, above));

        // Step 4: the new neighbours.
        for k in 0..self.adjacent.len() {
            let (i, j) = self.adjacent[k];
            if i != NIL && j != NIL {
                let found = self.pair(i, j);
                self.offer(found);
            }
        }
    }

    /// The input vertex at event `q`: the isolated point, or an end of the
    /// segment with the smallest index among those starting or ending there.
    fn vertex_at(&self, q: Point) -> Vertex {
        if let Some(p) = self.group.lone {
            return match self.norm.points[p as usize].0 {
                PointSource::Point(i) => Vertex::Point(i),
                PointSource::Segment(j) => Vertex::End { segment: j, end: 0 },
            };
        }
        let items = self.group.starts.iter().chain(&self.group.ends);
        let u = items.map(|&i| self.kept[i as usize]).min().expect("an event has an item");
        let (segment, [a, _]) = self.norm.segments[u as usize];
        Vertex::End { segment, end: usize::from(a != q) }
    }

    /// The conflict of the segments of nodes `i` and `j`, with its contact
    /// point.
    fn pair(&self, i: u32, j: u32) -> Option<(Conflict, ContactPoint)> {
        // Asked first of the nodes' own copies, which the sweep has just
        // read (the kept segments lie elsewhere in memory); the answer is
        // the same for either orientation of each segment.
        segment_contact(self.status.segment(i), self.status.segment(j))?;
        let (i, j) = (self.kept[i as usize], self.kept[j as usize]);
        segment_conflict_at(self.norm, i.min(j) as usize, i.max(j) as usize)
    }

    /// Keeps `found` if it beats the best so far.
    fn offer(&mut self, found: Option<(Conflict, ContactPoint)>) {
        let Some((conflict, contact)) = found else { return };
        let better = match &self.best {
            None => true,
            Some((best, at)) => match contact.cmp(at) {
                Ordering::Less => true,
                Ordering::Equal => rank(&conflict) < rank(best),
                Ordering::Greater => false,
            },
        };
        if better {
            self.best = Some((conflict, contact));
        }
    }
}

/// The order among conflicts at one contact point: the smaller pair of
/// input indices, smaller index first.
fn rank(conflict: &Conflict) -> (usize, usize) {
    let [a, b] = conflict.segments();
    (a.min(b), a.max(b))
}
