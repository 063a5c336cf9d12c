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

/// Position of grid cell `(x, y)` along the Hilbert curve of side
/// `2^GRID_BITS`: two bits of each coordinate at a time, through
/// [`HILBERT_STEPS`]. (The curve's own recursion, one bit at a time with
/// a branch on each, kept in the tests as the reference, spent more on
/// mispredicted branches than the whole sort of the keys.)
fn hilbert_index(x: u32, y: u32) -> u64 {
    let (mut d, mut state) = (0u64, 0usize);
    for level in (0..GRID_BITS / 2).rev() {
        let bits = (((x >> (2 * level)) & 3) << 2 | ((y >> (2 * level)) & 3)) as usize;
        let (digits, next) = HILBERT_STEPS[state << 4 | bits];
        d = d << 4 | digits as u64;
        state = next as usize;
    }
    d
}

/// The Hilbert curve's recursion two levels at a time. The curve's
/// orientation in a cell is one of four states, which say how the cell's
/// coordinates are seen: swapped (bit 0), both complemented (bit 1). Per
/// state and two bits each of `x` and `y` (`state << 4 | x1 x0 y1 y0`):
/// the two base-4 digits of the position along the curve, and the state
/// of the sub-cell reached.
const HILBERT_STEPS: [(u8, u8); 64] = hilbert_steps();

const fn hilbert_steps() -> [(u8, u8); 64] {
    // One level: in state (swap, complement), the cell's bits (bx, by) seen
    // as (rx, ry); the digit is 3·rx xor ry; the lower left and lower
    // right quarters (ry = 0) turn the curve: swap, and complement too on
    // the right (rx = 1).
    const fn one_level(state: usize, bx: usize, by: usize) -> (usize, usize) {
        let (swap, complement) = (state & 1, state >> 1);
        let (ax, ay) = if swap == 1 { (by, bx) } else { (bx, by) };
        let (rx, ry) = (ax ^ complement, ay ^ complement);
        let digit = (3 * rx) ^ ry;
        let next = if ry == 0 { (swap ^ 1) | ((complement ^ rx) << 1) } else { state };
        (digit, next)
    }
    let mut table = [(0u8, 0u8); 64];
    let mut i = 0;
    while i < 64 {
        let (state, x2, y2) = (i >> 4, (i >> 2) & 3, i & 3);
        let (high, middle) = one_level(state, x2 >> 1, y2 >> 1);
        let (low, next) = one_level(middle, x2 & 1, y2 & 1);
        table[i] = ((high << 2 | low) as u8, next as u8);
        i += 1;
    }
    table
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

    /// The curve's recursion one bit at a time, as first written.
    fn hilbert_index_by_bits(mut x: u32, mut y: u32) -> u64 {
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

    #[test]
    fn hilbert_by_two_bits_is_the_curve_by_one() {
        // every cell of a 256 x 256 grid at each of three scales, and
        // random cells of the whole grid
        for shift in [0, 4, 8] {
            for x in 0..256u32 {
                for y in 0..256u32 {
                    let (x, y) = (x << shift | (x & 7), y << shift | (y * 5 & 7));
                    assert_eq!(hilbert_index(x, y), hilbert_index_by_bits(x, y), "cell ({x}, {y})");
                }
            }
        }
        let mut random = SplitMix64(42);
        for _ in 0..100_000 {
            let r = random.next_u64();
            let (x, y) = ((r as u32) & 0xFFFF, ((r >> 32) as u32) & 0xFFFF);
            assert_eq!(hilbert_index(x, y), hilbert_index_by_bits(x, y), "cell ({x}, {y})");
        }
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
