//! Inputs that are exactly cocircular by construction (issue 27, part 4):
//! stacks and hatches of equal parallel segments with aligned ends, rows
//! of collinear segments on a lattice, stacks staggered by exact
//! multiples. Hatching, PCB buses, floor plans, rasterised outlines and
//! lines of text look like this. Every family is deterministic (no seed),
//! has small integer endpoints (`i32`, as Boost.Polygon takes them), and
//! is legal by construction: no two segments touch.
//!
//! Their Voronoi vertices are mostly exactly degenerate: the circle
//! through the aligned ends of two neighbouring segments is tangent to
//! the segments between them, four or more sites lie on one circle, and
//! the bisector of two parallel segments is a line halfway between them.

use crate::bench::Seg;

/// The families, by name (the benchmark's `--input` names).
pub const FAMILIES: [&str; 6] = ["stack", "vstack", "hatch", "rows", "staggered", "bus"];

/// The family `name` at about `n` segments, `None` for an unknown name.
pub fn family(name: &str, n: usize) -> Option<Vec<Seg>> {
    Some(match name {
        "stack" => stack(n),
        "vstack" => vertical_stack(n),
        "hatch" => hatch(n),
        "rows" => rows(n),
        "staggered" => staggered(n),
        "bus" => bus(n),
        _ => return None,
    })
}

/// `n` equal horizontal segments with aligned ends, one unit apart:
/// `(0, k) – (40, k)`.
pub fn stack(n: usize) -> Vec<Seg> {
    (0..n as i32).map(|k| [0, k, 40, k]).collect()
}

/// The [`stack`] turned a quarter: `(k, 0) – (k, 40)`.
pub fn vertical_stack(n: usize) -> Vec<Seg> {
    (0..n as i32).map(|k| [k, 0, k, 40]).collect()
}

/// `n` equal segments at 45 degrees, 3 units apart along x:
/// `(3k, 0) – (3k + 20, 20)`.
pub fn hatch(n: usize) -> Vec<Seg> {
    (0..n as i32).map(|k| [3 * k, 0, 3 * k + 20, 20]).collect()
}

/// About `n` horizontal segments in rows of collinear ones on a lattice,
/// as a floor plan's or a text's lines: `⌈√n⌉` per row, segment `j` of
/// row `i` from `(5j, 2i)` to `(5j + 3, 2i)` (gaps of 2 along a row, rows
/// 2 apart: many points and segments on one circle).
pub fn rows(n: usize) -> Vec<Seg> {
    let per_row = (n as f64).sqrt().ceil().max(1.0) as usize;
    (0..n)
        .map(|k| {
            let (i, j) = ((k / per_row) as i32, (k % per_row) as i32);
            [5 * j, 2 * i, 5 * j + 3, 2 * i]
        })
        .collect()
}

/// A [`stack`] staggered by exact multiples: segment `k` from
/// `(4 (k mod 5), k)` to `(4 (k mod 5) + 40, k)`.
pub fn staggered(n: usize) -> Vec<Seg> {
    (0..n as i32)
        .map(|k| {
            let x = 4 * (k % 5);
            [x, k, x + 40, k]
        })
        .collect()
}

/// A bus of `n` long horizontal tracks two units apart, each ending at a
/// pad column 100 units on (a PCB bus): `(0, 2k) – (1000, 2k)`, and the
/// ends stepped back by 2 every 16 tracks, so groups of aligned ends.
pub fn bus(n: usize) -> Vec<Seg> {
    (0..n as i32)
        .map(|k| {
            let step = 2 * ((k / 16) % 8);
            [step, 2 * k, 1000 - step, 2 * k]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::intersect;

    /// No two segments of any family touch (brute force on small sizes).
    #[test]
    fn every_family_is_legal() {
        for name in FAMILIES {
            let s = family(name, 150).unwrap();
            assert!(s.len() >= 150, "{name}");
            for i in 0..s.len() {
                assert!(s[i][0] != s[i][2] || s[i][1] != s[i][3], "{name}: {:?}", s[i]);
                for j in i + 1..s.len() {
                    assert!(!intersect(s[i], s[j]), "{name}: {:?} {:?}", s[i], s[j]);
                }
            }
        }
    }
}
