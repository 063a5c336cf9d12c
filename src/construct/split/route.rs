//! One round of snapping: every endpoint and point in a hot pixel moves to
//! the pixel's centre, and every piece that meets a hot pixel is cut there
//! and bent through its centre. Pieces that come out equal merge, keeping
//! the input segments of both.

use std::collections::{HashMap, HashSet};

use super::{Layout, Piece};
use crate::construct::grid::{Grid, SegmentCells};
use crate::geometry::snap::{Pixel, PixelGrid};
use crate::geometry::Point;

/// The hot pixels, and where to find them.
pub(super) struct HotPixels {
    set: HashSet<Pixel>,
}

impl HotPixels {
    pub(super) fn new() -> HotPixels {
        HotPixels { set: HashSet::new() }
    }

    /// Adds pixels; returns how many were new.
    pub(super) fn extend(&mut self, pixels: impl IntoIterator<Item = Pixel>) -> usize {
        pixels.into_iter().filter(|&p| self.set.insert(p)).count()
    }

    /// `p` moved to its pixel's centre if that pixel is hot.
    pub(super) fn snap(&self, pixels: &PixelGrid, p: Point) -> Point {
        let pixel = pixels.pixel_of(p);
        if self.set.contains(&pixel) {
            pixels.centre(pixel)
        } else {
            p
        }
    }
}

/// The pieces after one round of snapping through `hot`.
/// `layout` is the pieces' layout of this round.
pub(super) fn route(pieces: Vec<Piece>, layout: &Layout, hot: &HotPixels, pixels: &PixelGrid) -> Vec<Piece> {
    let proper = &layout.proper;
    let mut out = Merged::default();
    // The grid is built here, not with the layout: the last round's
    // contact search finds nothing and routes nothing.
    let Some((grid, cells)) = (!proper.is_empty()).then(|| {
        let grid = Grid::for_segments(proper);
        let cells = SegmentCells::new(&grid, proper);
        (grid, cells)
    }) else {
        for piece in pieces {
            let q = hot.snap(pixels, piece.ends[0]);
            out.push([q, q], piece.origins);
        }
        return out.pieces;
    };
    // each hot pixel in every cell its square overlaps: a segment meeting
    // the square has a point in one of those cells, and its cover holds it
    let half = pixels.size() / 2.0;
    let mut by_cell: HashMap<u64, Vec<Pixel>> = HashMap::new();
    for &pixel in &hot.set {
        let c = pixels.centre(pixel);
        let mut keys: Vec<u64> = [(-half, -half), (half, -half), (half, half), (-half, half)]
            .iter()
            .map(|&(dx, dy)| grid.cell_of(Point::new(c.x + dx, c.y + dy)))
            .collect();
        keys.sort_unstable();
        keys.dedup();
        for key in keys {
            by_cell.entry(key).or_default().push(pixel);
        }
    }
    let mut position = 0;
    let mut met: Vec<Pixel> = Vec::new();
    for (k, piece) in pieces.into_iter().enumerate() {
        let [a, b] = piece.ends;
        if a == b {
            let q = hot.snap(pixels, a);
            out.push([q, q], piece.origins);
            continue;
        }
        let own = cells.of(position as u32);
        debug_assert_eq!(proper[position].0, k);
        position += 1;
        met.clear();
        let (pa, pb) = (pixels.pixel_of(a), pixels.pixel_of(b));
        for cell in own {
            if let Some(list) = by_cell.get(cell) {
                met.extend(list.iter().filter(|&&x| x != pa && x != pb && pixels.meets(x, a, b)));
            }
        }
        let (a2, b2) = (hot.snap(pixels, a), hot.snap(pixels, b));
        if met.is_empty() {
            if a2 != b2 {
                out.push([a2, b2], piece.origins);
            }
            continue;
        }
        met.sort_unstable();
        met.dedup();
        // along the piece, by the projection of each centre
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let along = |q: Point| (q.x - a.x) * dx + (q.y - a.y) * dy;
        let mut route: Vec<Point> = met.iter().map(|&x| pixels.centre(x)).collect();
        route.sort_by(|p, q| along(*p).total_cmp(&along(*q)));
        route.insert(0, a2);
        route.push(b2);
        route.dedup();
        for w in route.windows(2) {
            out.push([w[0], w[1]], piece.origins.clone());
        }
    }
    out.pieces
}

/// Pieces with equal ends (either direction) merged.
#[derive(Default)]
struct Merged {
    pieces: Vec<Piece>,
    index: HashMap<[u64; 4], usize>,
}

impl Merged {
    fn push(&mut self, ends: [Point; 2], origins: Vec<u32>) {
        let full = Point::segment_key(ends[0], ends[1]);
        match self.index.get(&full) {
            Some(&k) => {
                let merged = &mut self.pieces[k].origins;
                merged.extend(origins);
                merged.sort_unstable();
                merged.dedup();
            }
            None => {
                self.index.insert(full, self.pieces.len());
                self.pieces.push(Piece { ends, origins });
            }
        }
    }
}
