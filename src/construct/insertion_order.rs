//! Insertion order: a biased randomised insertion order (BRIO) whose rounds
//! are each sorted along a Hilbert curve.
//!
//! Why: incremental construction is fast when every inserted site lands
//! near the previous one (short nearest-site walks, data in cache) and when
//! the sites inserted so far are spread evenly at every stage (small
//! conflict regions). Random rounds of doubling size give the second, the
//! Hilbert order inside each round gives the first. This plays the part of
//! the bucket quadtree order of Sugihara's survey (seed 004 §3.2).

use crate::geometry::Point;
use crate::splitmix::SplitMix64;

/// Bits of the Hilbert grid per axis: 65536 cells a side separate far more
/// points than one diagram holds; more bits only cost time.
const GRID_BITS: u32 = 16;
/// Number of BRIO rounds beyond the first.
const MAX_LEVEL: u64 = 30;

/// The order in which to insert `points` (indices into it). Deterministic.
///
/// Each point gets a round (BRIO) and its position along that round's
/// curve; the order is by round, then position, then index. The points
/// are bucketed by round, and each round's are sorted by a radix sort of
/// position and index packed in one word. (A comparison sort of the keys
/// and the curve's branches took 7 % of a build of a million points; now
/// under 5 %, on one thread where the halves of a parallel build order
/// their points, each on its own.)
pub(crate) fn insertion_order(points: &[Point]) -> Vec<u32> {
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
    // Per point: its round, and as one word its position along the
    // round's curve (high half) and its index (low half).
    let (mut rounds, mut keys) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for (i, p) in points.iter().enumerate() {
        // Level k with probability 2^-(k+1): half the points in the last
        // round. Drawn from the index alone.
        let level = (SplitMix64(seed ^ (i as u64).wrapping_mul(0xD1B5_4A32_D192_ED03)).next_u64() | (1 << MAX_LEVEL))
            .trailing_zeros() as u64;
        let round = (MAX_LEVEL - level) as usize;
        let mut h = hilbert_index(grid(p.x, lo.x), grid(p.y, lo.y));
        if round % 2 == 1 {
            // run the curve backwards so consecutive rounds meet end to start
            h = (1u64 << (2 * GRID_BITS)) - 1 - h;
        }
        rounds.push(round as u8);
        keys.push(h << 32 | i as u64);
    }
    ordered(&rounds, keys)
}

/// The indices of `keys` (low halves) by round (`rounds`, per key), then
/// by key: bucketed by round in the keys' order, then each bucket sorted.
fn ordered(rounds: &[u8], mut keys: Vec<u64>) -> Vec<u32> {
    let mut per_round = [0usize; ROUNDS + 1];
    rounds.iter().for_each(|&r| per_round[r as usize + 1] += 1);
    for r in 0..ROUNDS {
        per_round[r + 1] += per_round[r];
    }
    let mut next = per_round;
    let mut bucketed = vec![0u64; keys.len()];
    for (&key, &round) in keys.iter().zip(rounds) {
        bucketed[next[round as usize]] = key;
        next[round as usize] += 1;
    }
    let scratch = &mut keys;
    for r in 0..ROUNDS {
        let (from, to) = (per_round[r], per_round[r + 1]);
        sort_keys(&mut bucketed[from..to], &mut scratch[from..to]);
    }
    bucketed.into_iter().map(|key| key as u32).collect()
}

/// Rounds of the BRIO: levels `0..=MAX_LEVEL`.
const ROUNDS: usize = MAX_LEVEL as usize + 1;

/// From this many keys on, [`sort_keys`] sorts by radix.
const RADIX_FROM: usize = 1 << 12;

/// Sorts `keys` (position along the curve, then index: see
/// [`insertion_order`]), using `scratch` (as long) as room. Long runs by
/// radix, a byte of the position at a time from the lowest (stable, and
/// the keys come in index order, so ties in position stay by index);
/// passes whose byte is the same for every key are skipped.
fn sort_keys(keys: &mut [u64], scratch: &mut [u64]) {
    if keys.len() < RADIX_FROM {
        keys.sort_unstable();
        return;
    }
    let mut in_scratch = false;
    for shift in [32, 40, 48, 56] {
        let (from, to): (&mut [u64], &mut [u64]) = if in_scratch { (scratch, keys) } else { (keys, scratch) };
        let mut count = [0usize; 256];
        from.iter().for_each(|&k| count[(k >> shift) as usize & 255] += 1);
        if count.contains(&from.len()) {
            continue;
        }
        let mut at = [0usize; 256];
        for d in 1..256 {
            at[d] = at[d - 1] + count[d - 1];
        }
        for &k in from.iter() {
            let d = (k >> shift) as usize & 255;
            to[at[d]] = k;
            at[d] += 1;
        }
        in_scratch = !in_scratch;
    }
    if in_scratch {
        keys.copy_from_slice(scratch);
    }
}

/// Position of grid cell `(x, y)` along the Hilbert curve of side
/// `2^GRID_BITS`: four bits of each coordinate at a time, through
/// [`HILBERT_STEPS`]. (The curve's own recursion, one bit at a time with
/// a branch on each, kept in the tests as the reference, spent more on
/// mispredicted branches than the whole sort of the keys.)
fn hilbert_index(x: u32, y: u32) -> u64 {
    let (mut d, mut state) = (0u64, 0usize);
    for level in (0..GRID_BITS / 4).rev() {
        let bits = (((x >> (4 * level)) & 15) << 4 | ((y >> (4 * level)) & 15)) as usize;
        let (digits, next) = HILBERT_STEPS[state << 8 | bits];
        d = d << 8 | digits as u64;
        state = next as usize;
    }
    d
}

/// The Hilbert curve's recursion four levels at a time. The curve's
/// orientation in a cell is one of four states, which say how the cell's
/// coordinates are seen: swapped (bit 0), both complemented (bit 1). Per
/// state and four bits each of `x` and `y` (`state << 8 | x3..x0 y3..y0`):
/// the four base-4 digits of the position along the curve, and the state
/// of the sub-cell reached.
const HILBERT_STEPS: [(u8, u8); 1024] = hilbert_steps();

const fn hilbert_steps() -> [(u8, u8); 1024] {
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
    let mut table = [(0u8, 0u8); 1024];
    let mut i = 0;
    while i < 1024 {
        let (mut state, x4, y4) = (i >> 8, (i >> 4) & 15, i & 15);
        let mut digits = 0;
        let mut bit = 4;
        while bit > 0 {
            bit -= 1;
            let (digit, next) = one_level(state, (x4 >> bit) & 1, (y4 >> bit) & 1);
            digits = digits << 2 | digit;
            state = next;
        }
        table[i] = (digits as u8, state as u8);
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
    fn hilbert_by_four_bits_is_the_curve_by_one() {
        // every cell of a 256 x 256 grid at each of three scales, and
        // random cells of the whole grid
        for shift in [0, 4, 8] {
            for x in 0..256u32 {
                for y in 0..256u32 {
                    let (x, y) = (x << shift | (x & 7), y << shift | ((y * 5) & 7));
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
    fn buckets_and_radix_give_the_order_of_a_plain_sort() {
        // keys with many ties in position (the index, in the low half,
        // breaks them), rounds skewed as the BRIO's are, below and above
        // the radix threshold
        let mut random = SplitMix64(7);
        for n in [0, 1, 5, 300, RADIX_FROM - 1, RADIX_FROM, 3 * RADIX_FROM + 17, 200_000] {
            let rounds: Vec<u8> =
                (0..n).map(|_| (ROUNDS as u32 - 1 - (random.next_u64() | 1 << 30).trailing_zeros().min(30)) as u8).collect();
            let spread = if n % 2 == 0 { 1 << 32 } else { 1000 };
            let keys: Vec<u64> = (0..n).map(|i| (random.next_u64() % spread) << 32 | i as u64).collect();
            let mut expected: Vec<(u8, u64)> = rounds.iter().copied().zip(keys.iter().copied()).collect();
            expected.sort_unstable();
            let expected: Vec<u32> = expected.into_iter().map(|(_, k)| k as u32).collect();
            assert_eq!(ordered(&rounds, keys), expected, "{n} keys");
        }
    }

    #[test]
    fn degenerate_extents_do_not_panic() {
        let same = vec![Point::new(1.0, 1.0); 10];
        assert_eq!(insertion_order(&same).len(), 10);
        assert!(insertion_order(&[]).is_empty());
    }
}
