//! The benchmark's inputs of issue 11, the two shapes that built slowly:
//! long nearly parallel segments ([`parallel`]) and axis-parallel staircase
//! outlines ([`staircase`]), both with integer endpoints (`i32`, as
//! Boost.Polygon takes them) and legal by construction: no two segments
//! cross, overlap or touch except where consecutive segments of one outline
//! share an endpoint. (The grid check of [`crate::bench::verify`] is not
//! used on them: it refuses shared endpoints, and long segments would fill
//! its grid.)

use crate::bench::Seg;
use crate::Rng;

/// Vertical distance between consecutive [`parallel`] segments, in integer
/// units; each end is jittered by less than half of it.
pub const PARALLEL_SPACING: i32 = 8;

/// How far the [`parallel`] segments' ends are spread along x (2¹⁶, a
/// thousandth of their length).
pub const PARALLEL_SPREAD: i32 = 1 << 16;

/// Length of the [`parallel`] segments: 2²⁶, far above the 8n of the
/// stack's height for every size benchmarked (n ≤ 2²⁰), so the segments
/// are long and their slopes below 4/2²⁶.
pub const PARALLEL_LENGTH: i32 = 1 << 26;

/// `n` long, nearly parallel segments: segment `i` runs from
/// `(c, 8i + a)` to `(2²⁶ - d, 8i + b)` with `a`, `b` uniform in `0..4`
/// and `c`, `d` in `0..2¹⁶`. Consecutive segments are 5 to 11 units apart
/// at every x, so they never cross. This is issue 11's "segment i from
/// (0, i + 0.5u) to (L, i + 0.5v), L ≫ n", scaled by 8 to integers, with
/// the ends spread along x: with every endpoint on the two lines x = 0 and
/// x = L, CGAL's exact fallback decides most of its questions (2,048
/// segments: 0.8 s against 0.23 s spread).
pub fn parallel(n: usize, seed: u64) -> Vec<Seg> {
    let mut rng = Rng(seed ^ 0x9A8A_11E1);
    let half = PARALLEL_SPACING as usize / 2;
    let spread = PARALLEL_SPREAD as usize;
    (0..n)
        .map(|i| {
            let y = PARALLEL_SPACING * i as i32;
            let (a, b) = (rng.below(half) as i32, rng.below(half) as i32);
            let (c, d) = (rng.below(spread) as i32, rng.below(spread) as i32);
            [c, y + a, PARALLEL_LENGTH - d, y + b]
        })
        .collect()
}

/// Segments per [`staircase`] polygon (about; the two closing sides and the
/// last run vary it by a few).
pub const STAIRCASE_POLYGON: usize = 4096;

/// Height of one [`staircase`] band: the lower chain lives in
/// `0..=STAIR_BAND / 2 - 2`, the upper one in `STAIR_BAND / 2 + 2..=STAIR_BAND`.
const STAIR_BAND: i32 = 64;

/// About `n` segments of closed rectilinear-looking polygons, like a
/// rasterised country border: each polygon is a lower and an upper
/// x-monotone chain closed by two vertical sides, and each chain a random
/// walk of steps of 1 to 4 units, drawn three eighths horizontal, three
/// eighths vertical and a quarter diagonal (never two horizontal or two
/// vertical steps in a row, so a run is one segment), which makes 65 % of
/// the segments axis-parallel (the outline had 64 %). Consecutive segments share
/// their endpoint; the polygons are stacked in bands 2 units apart, so
/// nothing else touches. Many points lie on one grid line and many four on
/// one circle: the exact degeneracies of rasterised data.
pub fn staircase(n: usize, seed: u64) -> Vec<Seg> {
    let mut rng = Rng(seed ^ 0x57A1_8CA5);
    let mut out = Vec::with_capacity(n + 8);
    let mut band = 0;
    while out.len() < n {
        let steps = (STAIRCASE_POLYGON.min(n - out.len() + 4) / 2).saturating_sub(1).max(1);
        let base = band * (STAIR_BAND + 2);
        let lower = chain(&mut rng, steps, base, base + STAIR_BAND / 2 - 2);
        let upper = chain(&mut rng, steps, base + STAIR_BAND / 2 + 2, base + STAIR_BAND);
        polygon(&mut out, lower, upper);
        band += 1;
    }
    out
}

/// Step kinds of a [`chain`].
#[derive(Clone, Copy, PartialEq, Eq)]
enum Step {
    Horizontal,
    Vertical,
    Diagonal,
}

/// The vertices of an x-monotone walk of `steps` steps from `(0, lo..=hi)`,
/// its y kept in `lo..=hi`.
fn chain(rng: &mut Rng, steps: usize, lo: i32, hi: i32) -> Vec<[i32; 2]> {
    let mut at = [0, lo + rng.below((hi - lo + 1) as usize) as i32];
    let mut points = vec![at];
    // Neither end step vertical: it would overlap the polygon's vertical
    // side there.
    let mut last = Step::Vertical;
    while points.len() <= steps || last == Step::Vertical {
        let kind = match rng.below(8) {
            0..=2 => Step::Horizontal,
            3..=5 => Step::Vertical,
            _ => Step::Diagonal,
        };
        if kind == last && kind != Step::Diagonal {
            continue;
        }
        let dx = if kind == Step::Vertical { 0 } else { 1 + rng.below(4) as i32 };
        let mut dy = if kind == Step::Horizontal { 0 } else { 1 + rng.below(4) as i32 };
        if rng.below(2) == 0 {
            dy = -dy;
        }
        if !(lo..=hi).contains(&(at[1] + dy)) {
            dy = -dy;
        }
        if !(lo..=hi).contains(&(at[1] + dy)) {
            continue;
        }
        at = [at[0] + dx, at[1] + dy];
        points.push(at);
        last = kind;
    }
    points
}

/// The closed polygon of two chains from x = 0: the lower chain forwards,
/// the shorter one extended by a horizontal run to the other's end, the
/// right side up, the upper chain backwards, the left side down.
fn polygon(out: &mut Vec<Seg>, mut lower: Vec<[i32; 2]>, mut upper: Vec<[i32; 2]>) {
    let end = lower.last().expect("a chain has points")[0].max(upper.last().expect("a chain has points")[0]);
    for chain in [&mut lower, &mut upper] {
        let last = *chain.last().expect("a chain has points");
        if last[0] < end {
            chain.push([end, last[1]]);
        }
    }
    let ring: Vec<[i32; 2]> = lower.iter().chain(upper.iter().rev()).copied().collect();
    for k in 0..ring.len() {
        let (p, q) = (ring[k], ring[(k + 1) % ring.len()]);
        out.push([p[0], p[1], q[0], q[1]]);
    }
}

/// The share of segments that are horizontal or vertical.
pub fn axis_parallel_share(segments: &[Seg]) -> f64 {
    let axis = segments.iter().filter(|s| s[0] == s[2] || s[1] == s[3]).count();
    axis as f64 / segments.len().max(1) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::intersect;

    /// Only consecutive segments of one outline touch (checked by brute
    /// force on a small input).
    #[test]
    fn staircase_is_legal() {
        let s = staircase(600, 7);
        for i in 0..s.len() {
            for j in i + 1..s.len() {
                let shared = [[s[i][0], s[i][1]], [s[i][2], s[i][3]]]
                    .iter()
                    .filter(|p| [[s[j][0], s[j][1]], [s[j][2], s[j][3]]].contains(p))
                    .count();
                if shared == 0 {
                    assert!(!intersect(s[i], s[j]), "{:?} {:?}", s[i], s[j]);
                } else {
                    assert_eq!(shared, 1, "{:?} {:?}", s[i], s[j]);
                    assert!(!overlap(s[i], s[j]) && !overlap(s[j], s[i]), "{:?} {:?}", s[i], s[j]);
                }
            }
        }
        let share = axis_parallel_share(&s);
        assert!((0.6..0.7).contains(&share), "{share}");
    }

    /// Whether an endpoint of `t` lies inside `s` (not at its ends).
    fn overlap(s: Seg, t: Seg) -> bool {
        let [x1, y1, x2, y2] = s.map(i64::from);
        [[t[0], t[1]], [t[2], t[3]]].iter().any(|p| {
            let [px, py] = p.map(i64::from);
            let cross = (x2 - x1) * (py - y1) - (y2 - y1) * (px - x1);
            let dot = (px - x1) * (x2 - x1) + (py - y1) * (y2 - y1);
            let len2 = (x2 - x1).pow(2) + (y2 - y1).pow(2);
            cross == 0 && dot > 0 && dot < len2
        })
    }

    #[test]
    fn parallel_is_legal() {
        let s = parallel(300, 7);
        for i in 0..s.len() {
            for j in i + 1..s.len() {
                assert!(!intersect(s[i], s[j]));
            }
        }
    }
}
