//! The hot pixels a piece meets, found through a kd-tree over the pixels
//! (built once per round of snapping, for the routing).
//!
//! A uniform grid of cells, which this replaces, costs what the cells a
//! piece crosses hold: where the pieces are long and the hot pixels crowd
//! a few cells (long parallel segments crossed by a few others: every
//! crossing lies on a few lines), every piece tested thousands of pixels.
//! The tree adapts to where the pixels are: a piece descends only into
//! the boxes it meets, so a piece passing a column of crossings visits
//! O(log h) boxes plus those next to the pixels it meets, wherever the
//! pixels lie and however long the piece is.
//!
//! Pruning is exact: a box (the closed union of its pixels' squares, with
//! corners on the exact half-pixel lattice) is skipped only when the
//! segment misses its bounding box or all four corners lie strictly on one
//! side of the segment's line (exact orientations); a pixel in a leaf is
//! met when [`PixelGrid::meets`] says so. The tree decides nothing itself.

use crate::geometry::input::snap::{Pixel, PixelGrid};
use crate::geometry::predicates::{exact_orientation, Orientation};
use crate::geometry::Point;

/// Pixels per leaf: below this, testing each is cheaper than descending.
const LEAF: usize = 8;

/// A box of the tree: the pixel indices it covers (inclusive, per axis)
/// and its pixels `start..end` in [`PixelTree::pixels`]; an inner node's
/// two children follow as `children`.
struct Node {
    lo: Pixel,
    hi: Pixel,
    start: u32,
    end: u32,
    children: Option<[u32; 2]>,
}

/// A kd-tree over a set of pixels.
pub(super) struct PixelTree {
    pixels: Vec<Pixel>,
    nodes: Vec<Node>,
}

impl PixelTree {
    /// The tree over `pixels` (any order, each once).
    pub(super) fn new(pixels: Vec<Pixel>) -> PixelTree {
        let mut tree = PixelTree { pixels, nodes: Vec::new() };
        if !tree.pixels.is_empty() {
            let len = tree.pixels.len();
            tree.build(0, len);
        }
        tree
    }

    /// Builds the node over `pixels[start..end]` (not empty), split at the
    /// median of its longer axis; returns its index.
    fn build(&mut self, start: usize, end: usize) -> u32 {
        let items = &mut self.pixels[start..end];
        let mut lo = items[0];
        let mut hi = items[0];
        for p in items.iter() {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let index = self.nodes.len() as u32;
        self.nodes.push(Node { lo, hi, start: start as u32, end: end as u32, children: None });
        if items.len() > LEAF {
            let axis = usize::from(hi[1] - lo[1] > hi[0] - lo[0]);
            let middle = items.len() / 2;
            items.select_nth_unstable_by_key(middle, |p| p[axis]);
            let left = self.build(start, start + middle);
            let right = self.build(start + middle, end);
            self.nodes[index as usize].children = Some([left, right]);
        }
        index
    }

    /// Appends to `out` every pixel of the tree that the closed segment
    /// `ab` meets ([`PixelGrid::meets`]), in no particular order.
    pub(super) fn met_by(&self, grid: &PixelGrid, a: Point, b: Point, out: &mut Vec<Pixel>) {
        if self.nodes.is_empty() {
            return;
        }
        // Depth first: the stack holds at most one sibling per level and
        // the tree, split at medians, has fewer than 64 levels.
        let mut stack = [0u32; 66];
        let mut len = 1;
        while len > 0 {
            len -= 1;
            let node = &self.nodes[stack[len] as usize];
            if !box_may_meet(grid, node, a, b) {
                continue;
            }
            match node.children {
                Some([left, right]) => {
                    stack[len] = right;
                    stack[len + 1] = left;
                    len += 2;
                }
                None => {
                    let pixels = &self.pixels[node.start as usize..node.end as usize];
                    out.extend(pixels.iter().filter(|&&p| grid.meets(p, a, b)));
                }
            }
        }
    }
}

/// Whether the closed segment `ab` may meet a pixel of `node`: it meets
/// the closed box of the node's squares (exactly; false only when it
/// certainly does not).
fn box_may_meet(grid: &PixelGrid, node: &Node, a: Point, b: Point) -> bool {
    // the box's corners, on the half-pixel lattice: exact doubles
    let half = grid.size() / 2.0;
    let (c0, c1) = (grid.centre(node.lo), grid.centre(node.hi));
    let (x0, y0, x1, y1) = (c0.x - half, c0.y - half, c1.x + half, c1.y + half);
    if a.x.max(b.x) < x0 || a.x.min(b.x) > x1 || a.y.max(b.y) < y0 || a.y.min(b.y) > y1 {
        return false;
    }
    let corners = [Point::new(x0, y0), Point::new(x1, y0), Point::new(x1, y1), Point::new(x0, y1)];
    let sides = corners.map(|q| exact_orientation(a, b, q));
    let all = |o: Orientation| sides.iter().all(|&s| s == o);
    !(all(Orientation::CounterClockwise) || all(Orientation::Clockwise))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(500))]
        /// The tree finds exactly the pixels a brute-force test of every
        /// pixel finds: pixels crowded on a small lattice (columns, rows,
        /// clusters), segments of every length and direction through them,
        /// ends on pixel corners and centres included.
        #[test]
        fn the_tree_finds_what_testing_every_pixel_finds(
            raw in prop::collection::vec((-12i64..12, -12i64..12), 0..200),
            ends in prop::collection::vec((-60i32..60, -60i32..60, -60i32..60, -60i32..60), 1..20),
            scale in prop::sample::select(vec![1e-200, 1.0, 1e200]),
        ) {
            let grid = PixelGrid::for_magnitude(scale);
            let mut pixels: Vec<Pixel> = raw.iter().map(|&(x, y)| [x, y]).collect();
            pixels.sort_unstable();
            pixels.dedup();
            let tree = PixelTree::new(pixels.clone());
            // segment ends in quarter pixels: on centres, edges and corners
            let quarter = grid.size() / 4.0;
            for &(ax, ay, bx, by) in &ends {
                let a = Point::new(f64::from(ax) * quarter, f64::from(ay) * quarter);
                let b = Point::new(f64::from(bx) * quarter, f64::from(by) * quarter);
                let mut found = Vec::new();
                tree.met_by(&grid, a, b, &mut found);
                found.sort_unstable();
                let expected: Vec<Pixel> = pixels.iter().copied().filter(|&p| grid.meets(p, a, b)).collect();
                prop_assert_eq!(found, expected);
            }
        }
    }
}
