//! A static centred interval tree: which of `n` intervals hold a value, in
//! `O(log n + k)` for `k` answers. The offsets use it to find the edges
//! whose clearance range holds a distance without looking at the others.

/// Intervals `[low, high]` (either end may be infinite, never NaN) with
/// their payloads.
#[derive(Clone, Debug, Default)]
pub(crate) struct IntervalTree {
    nodes: Vec<Node>,
    /// Per node, its intervals by `low` ascending, then the same by `high`
    /// descending: `(low, high, payload)`.
    by_low: Vec<(f64, f64, u32)>,
    by_high: Vec<(f64, f64, u32)>,
}

#[derive(Clone, Copy, Debug)]
struct Node {
    centre: f64,
    /// Its intervals' range in `by_low` and `by_high`.
    start: u32,
    end: u32,
    below: u32,
    above: u32,
}

const NO_NODE: u32 = u32::MAX;

impl IntervalTree {
    /// The tree of `intervals` (`(low, high, payload)`, `low <= high`).
    pub(crate) fn new(mut intervals: Vec<(f64, f64, u32)>) -> IntervalTree {
        let mut tree = IntervalTree::default();
        let n = intervals.len();
        tree.build(&mut intervals[..n]);
        tree
    }

    /// Builds the subtree of `intervals` (reordered in place); its root's
    /// index, or `NO_NODE` when empty.
    fn build(&mut self, intervals: &mut [(f64, f64, u32)]) -> u32 {
        if intervals.is_empty() {
            return NO_NODE;
        }
        // the median of the lower ends: at least that interval holds it
        let middle = intervals.len() / 2;
        intervals.select_nth_unstable_by(middle, |a, b| a.0.total_cmp(&b.0));
        let centre = intervals[middle].0;
        // below | holding | above
        let mut holding: Vec<(f64, f64, u32)> = Vec::new();
        let mut below = 0;
        let mut above = intervals.len();
        let mut k = 0;
        while k < above {
            let iv = intervals[k];
            if iv.1 < centre {
                intervals.swap(k, below);
                below += 1;
                k += 1;
            } else if iv.0 > centre {
                above -= 1;
                intervals.swap(k, above);
            } else {
                holding.push(iv);
                k += 1;
            }
        }
        // the holding ones sit between `below` and `above` in any order
        let start = self.by_low.len() as u32;
        holding.sort_by(|a, b| a.0.total_cmp(&b.0));
        self.by_low.extend_from_slice(&holding);
        holding.sort_by(|a, b| b.1.total_cmp(&a.1));
        self.by_high.extend_from_slice(&holding);
        let end = self.by_low.len() as u32;
        let index = self.nodes.len() as u32;
        self.nodes.push(Node { centre, start, end, below: NO_NODE, above: NO_NODE });
        let (lower, rest) = intervals.split_at_mut(below);
        let upper = &mut rest[above - below..];
        let b = self.build(lower);
        let a = self.build(upper);
        self.nodes[index as usize].below = b;
        self.nodes[index as usize].above = a;
        index
    }

    /// The payloads of the intervals that hold `value`, in the sense of
    /// `holds(low, high)`: a predicate that is true only where
    /// `starts(low)` (falling as `low` grows) and `!starts(high)` hold,
    /// with `starts(x)` true for every `x < value` and false for every
    /// `x > value` (the ends may count either way at `value` itself).
    pub(crate) fn stab(&self, value: f64, starts: impl Fn(f64) -> bool, out: &mut Vec<u32>) {
        let mut node = if self.nodes.is_empty() { NO_NODE } else { 0 };
        while node != NO_NODE {
            let n = self.nodes[node as usize];
            let range = n.start as usize..n.end as usize;
            if value <= n.centre {
                // every interval here reaches the centre, so above `value`
                for &(_, high, payload) in self.by_low[range].iter().take_while(|iv| starts(iv.0)) {
                    if !starts(high) {
                        out.push(payload);
                    }
                }
                node = if value < n.centre { n.below } else { NO_NODE };
            } else {
                for &(low, _, payload) in self.by_high[range].iter().take_while(|iv| !starts(iv.1)) {
                    if starts(low) {
                        out.push(payload);
                    }
                }
                node = n.above;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    #[test]
    fn stabbing_agrees_with_a_scan() {
        let mut rng = SplitMix64(7);
        for round in 0..50 {
            let n = 1 + (round * 7) % 200;
            let intervals: Vec<(f64, f64, u32)> = (0..n)
                .map(|k| {
                    let a = (rng.unit() * 20.0).floor();
                    let b = if rng.unit() < 0.1 { f64::INFINITY } else { a + (rng.unit() * 8.0).floor() };
                    (a, b, k as u32)
                })
                .collect();
            let tree = IntervalTree::new(intervals.clone());
            for q in 0..50 {
                let value = q as f64 * 0.5;
                for closed in [false, true] {
                    let starts = |x: f64| if closed { x <= value } else { x < value };
                    let mut got = Vec::new();
                    tree.stab(value, starts, &mut got);
                    got.sort_unstable();
                    let mut want: Vec<u32> = intervals.iter().filter(|iv| starts(iv.0) && !starts(iv.1)).map(|iv| iv.2).collect();
                    want.sort_unstable();
                    assert_eq!(got, want, "round {round} value {value} closed {closed}");
                }
            }
        }
    }
}
