//! Insertion order: a biased randomised insertion order (BRIO) whose rounds
//! are each sorted along a Hilbert curve.
//!
//! Why: incremental construction is fast when every inserted site lands
//! near the previous one (short nearest-site walks, data in cache) and when
//! the sites inserted so far are spread evenly at every stage (small
//! conflict regions). Random rounds of doubling size give the second, the
//! Hilbert order inside each round gives the first. This plays the part of
//! the bucket quadtree order of Sugihara's survey (seed 004 §3.2).
//!
//! Large inputs are keyed and sorted in two halves on two threads and then
//! merged; the order is the same as on one thread.

use crate::geometry::Point;
use crate::splitmix::SplitMix64;

/// Bits of the Hilbert grid per axis: 65536 cells a side separate far more
/// points than one diagram holds; more bits only cost time.
const GRID_BITS: u32 = 16;
/// Number of BRIO rounds beyond the first.
const MAX_LEVEL: u64 = 30;

/// The order in which to insert `points` (indices into it). Deterministic.
pub(crate) fn insertion_order(points: &[Point]) -> Vec<u32> {
    insertion_order_threaded(points, PARALLEL_FROM)
}

/// [`insertion_order`], on two threads when there are `parallel_from`
/// points or more; the answer does not depend on it.
fn insertion_order_threaded(points: &[Point], parallel_from: usize) -> Vec<u32> {
    let n = points.len();
    if n == 0 {
        return Vec::new();
    }
    let (mut lo, mut hi) = (points[0], points[0]);
    for p in points {
        lo.x = lo.x.min(p.x);
        lo.y = lo.y.min(p.y);
        hi.x = hi.x.max(p.x);
        hi.y = hi.y.max(p.y);
    }
    let cells = (1u64 << GRID_BITS) as f64;
    let extent = (hi.x - lo.x).max(hi.y - lo.y);
    let to_grid = if extent > 0.0 { (cells - 1.0) / extent } else { 0.0 };
    let grid = |v: f64, o: f64| -> u32 {
        let g = ((v - o) * to_grid).floor();
        if g.is_nan() || g < 0.0 {
            0
        } else {
            g.min(cells - 1.0) as u32
        }
    };

    let seed = 0x5EED_5EED ^ n as u64;
    let key = |i: usize, p: &Point| -> (u64, u32) {
        // Level k with probability 2^-(k+1): half the points in the last
        // round. Drawn from the index alone, so any split of the work gives
        // the same order.
        let level = (SplitMix64(seed ^ (i as u64).wrapping_mul(0xD1B5_4A32_D192_ED03)).next_u64() | (1 << MAX_LEVEL))
            .trailing_zeros() as u64;
        let round = MAX_LEVEL - level;
        let mut h = hilbert_index(grid(p.x, lo.x), grid(p.y, lo.y));
        if round % 2 == 1 {
            // run the curve backwards so consecutive rounds meet end to start
            h = (1u64 << (2 * GRID_BITS)) - 1 - h;
        }
        ((round << (2 * GRID_BITS)) | h, i as u32)
    };
    let keyed_sorted = |start: usize, chunk: &[Point]| -> Vec<(u64, u32)> {
        let mut keyed: Vec<(u64, u32)> = chunk.iter().enumerate().map(|(k, p)| key(start + k, p)).collect();
        keyed.sort_unstable();
        keyed
    };
    // Large inputs: key and sort the two halves on two threads, then merge
    // (the construction itself is sequential; this is its one parallel step).
    if n < parallel_from {
        return keyed_sorted(0, points).into_iter().map(|(_, i)| i).collect();
    }
    let half = n / 2;
    let (second, first) = super::run_beside(|| keyed_sorted(half, &points[half..]), || keyed_sorted(0, &points[..half]));
    merge_indices(&first, &second)
}

/// Below this many points one thread orders faster than two.
const PARALLEL_FROM: usize = 100_000;

/// The indices of two sorted runs of `(key, index)`, merged by key.
fn merge_indices(a: &[(u64, u32)], b: &[(u64, u32)]) -> Vec<u32> {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        if b[j] < a[i] {
            out.push(b[j].1);
            j += 1;
        } else {
            out.push(a[i].1);
            i += 1;
        }
    }
    out.extend(a[i..].iter().map(|&(_, k)| k));
    out.extend(b[j..].iter().map(|&(_, k)| k));
    out
}

/// Position of grid cell `(x, y)` along the Hilbert curve of side `2^GRID_BITS`.
fn hilbert_index(mut x: u32, mut y: u32) -> u64 {
    let n: u32 = 1 << GRID_BITS;
    let mut d = 0u64;
    let mut s = n >> 1;
    while s > 0 {
        let rx = (x & s != 0) as u64;
        let ry = (y & s != 0) as u64;
        d += (s as u64) * (s as u64) * ((3 * rx) ^ ry);
        if ry == 0 {
            if rx == 1 {
                x = n - 1 - x;
                y = n - 1 - y;
            }
            std::mem::swap(&mut x, &mut y);
        }
        s >>= 1;
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn order_is_a_permutation() {
        let pts: Vec<Point> = (0..1000).map(|i| Point::new((i * 37 % 101) as f64, (i * 91 % 103) as f64)).collect();
        let mut o = insertion_order(&pts);
        o.sort_unstable();
        assert_eq!(o, (0..1000).collect::<Vec<u32>>());
    }

    #[test]
    fn hilbert_neighbours_are_adjacent_cells() {
        // consecutive indices on the curve are grid neighbours
        let mut cells: Vec<(u64, (u32, u32))> = Vec::new();
        for x in 0..8u32 {
            for y in 0..8u32 {
                cells.push((hilbert_index(x << (GRID_BITS - 3), y << (GRID_BITS - 3)), (x, y)));
            }
        }
        cells.sort_unstable();
        for w in cells.windows(2) {
            let ((_, (x0, y0)), (_, (x1, y1))) = (w[0], w[1]);
            assert_eq!(x0.abs_diff(x1) + y0.abs_diff(y1), 1);
        }
    }

    #[test]
    fn two_threads_give_the_single_thread_order() {
        let n = 5001;
        let pts: Vec<Point> = (0..n).map(|i| Point::new((i * 7919 % 10007) as f64, (i * 104729 % 9973) as f64)).collect();
        let one = insertion_order_threaded(&pts, usize::MAX);
        assert_eq!(insertion_order_threaded(&pts, 2), one);
        assert_eq!(insertion_order_threaded(&pts[..4], 2), insertion_order_threaded(&pts[..4], usize::MAX));
        let mut sorted = one;
        sorted.sort_unstable();
        assert_eq!(sorted, (0..n as u32).collect::<Vec<u32>>());
    }

    #[test]
    fn merge_keeps_key_order() {
        let a = [(1u64, 10u32), (4, 11), (9, 12)];
        let b = [(2u64, 20u32), (3, 21), (10, 22)];
        assert_eq!(merge_indices(&a, &b), vec![10, 20, 21, 11, 12, 22]);
        assert_eq!(merge_indices(&[], &b), vec![20, 21, 22]);
    }

    #[test]
    fn degenerate_extents_do_not_panic() {
        let same = vec![Point::new(1.0, 1.0); 10];
        assert_eq!(insertion_order(&same).len(), 10);
        assert!(insertion_order(&[]).is_empty());
    }
}
