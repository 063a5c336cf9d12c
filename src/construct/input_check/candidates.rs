//! # Which pairs are tested: a uniform grid
//! Candidate pairs come from a uniform grid over the bounding box of the
//! segments, stored sparsely (a sorted list of `(cell, item)` incidences, so
//! empty cells cost nothing). The cell side is the mean segment length
//! (`total length / number of segments`), which keeps the number of
//! (segment, cell) incidences at most a small constant times the number of
//! segments for *any* input; it is raised where needed so that no axis has
//! more than 2^24 cells. Each segment is registered in every cell it touches,
//! conservatively (see [`Grid::cover`]); each isolated point in its one cell.
//! Two items are tested only if they share a cell, and a segment pair only in
//! the first cell they share, so no pair is tested twice.
//!
//! Cost: hashing for the normalisation, O(n) expected; sorting the
//! incidences, O(n log n); plus the pairs sharing a cell.
//! For segments spread over the plane with bounded local density that is O(n)
//! pairs, so O(n log n) in all. Worst case O(n²): many segments through one
//! cell (a star of k segments at one point costs k²/2 tests, a dense bundle of
//! long parallel segments likewise; p points in a cell crossed by k segments
//! cost p·k). A Shamos–Hoey sweep would bound the crossing
//! test by O(n log n) always, but it needs exact comparisons of segments at a
//! sweep position and special handling of the shared endpoints that are the
//! normal case here; the grid needs only the orientation predicate.

use super::classify::{point_conflict, segment_conflict};
use super::normalise::Normalised;
use super::Conflict;
use crate::construct::grid::{bounding_box, Grid, SegmentCells};

/// The first conflict (segment pairs in input order first, then
/// (point, segment) pairs), found through the grid.
pub(super) fn find_conflict(norm: &Normalised) -> Option<Conflict> {
    if norm.segments.is_empty() {
        return None; // distinct points never conflict
    }
    let grid = Grid::for_segments(&norm.segments);
    let cells = SegmentCells::new(&grid, &norm.segments);
    let incidences = incidences(&grid, &cells, norm);
    let m = norm.segments.len() as u32;
    let mut best_segments: Option<(u32, u32)> = None;
    let mut best_point: Option<(u32, u32)> = None;
    for group in incidences.chunk_by(|x, y| x.0 == y.0) {
        let cell = group[0].0;
        let split = group.partition_point(|&(_, item)| item < m);
        let (segments, points) = (&group[..split], &group[split..]);
        for (k, &(_, i)) in segments.iter().enumerate() {
            for &(_, j) in &segments[k + 1..] {
                // Items are sorted, so i < j; test only in the first shared
                // cell, and only pairs that could beat the best so far.
                if best_segments.is_some_and(|best| (i, j) >= best) || cells.first_common(i, j) != Some(cell) {
                    continue;
                }
                if segment_conflict(norm, i as usize, j as usize).is_some() {
                    best_segments = Some((i, j));
                }
            }
        }
        if best_segments.is_some() {
            continue; // a segment conflict wins over any point conflict
        }
        for &(_, p) in points {
            for &(_, s) in segments {
                let pair = (p - m, s);
                if best_point.map_or(true, |best| pair < best) && point_conflict(norm, pair.0 as usize, s as usize).is_some() {
                    best_point = Some(pair);
                }
            }
        }
    }
    if let Some((i, j)) = best_segments {
        return segment_conflict(norm, i as usize, j as usize);
    }
    best_point.and_then(|(p, s)| point_conflict(norm, p as usize, s as usize))
}

/// All `(cell, item)` pairs sorted, where items `0..m` are the kept segments
/// and `m + p` is kept point `p`. Points outside the segments' bounding box
/// cannot touch a segment and are left out.
fn incidences(grid: &Grid, cells: &SegmentCells, norm: &Normalised) -> Vec<(u64, u32)> {
    let m = norm.segments.len();
    assert!(m + norm.points.len() <= u32::MAX as usize, "item ids are 32-bit");
    let mut out: Vec<(u64, u32)> = Vec::with_capacity(cells.cells.len() + norm.points.len());
    for i in 0..m as u32 {
        out.extend(cells.of(i).iter().map(|&c| (c, i)));
    }
    let (lo, hi) = bounding_box(&norm.segments);
    for (p, &(_, q)) in norm.points.iter().enumerate() {
        if lo.x <= q.x && q.x <= hi.x && lo.y <= q.y && q.y <= hi.y {
            out.push((grid.cell_of(q), (m + p) as u32));
        }
    }
    out.sort_unstable();
    out
}
