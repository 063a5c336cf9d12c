//! One round of snapping: every endpoint and point in a hot pixel moves to
//! the pixel's centre, and every piece that meets a hot pixel is cut there
//! and bent through its centre. Pieces that come out equal merge, keeping
//! the input segments of both.

use std::collections::{HashMap, HashSet};

use super::pixel_tree::PixelTree;
use super::Piece;
use crate::geometry::input::snap::{Pixel, PixelGrid};
use crate::geometry::Point;

/// The hot pixels of every round so far.
pub(super) struct HotPixels {
    pub(super) set: HashSet<Pixel>,
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
pub(super) fn route(pieces: Vec<Piece>, hot: &HotPixels, pixels: &PixelGrid) -> Vec<Piece> {
    route_also_through(pieces, hot, pixels, &HashMap::new())
}

/// From this many pieces on, a round (or a half of one) with a spare
/// thread routes them in two halves, one per thread.
const HALVES_FROM: usize = 1 << 13;

/// [`route`], each piece also bent through the centres of its pixels in
/// `also` (by piece index): a contact with an arc, whose pixel holds a
/// rounded point that the piece may pass a hair beside.
///
/// Large rounds with a spare thread route the first and the second half of
/// the pieces apart (each half in halves again while threads are spare)
/// and merge the second's into the first's: the pieces come out as from
/// one thread (in order of first appearance, merged ones with the sorted
/// union of their input segments).
pub(super) fn route_also_through(
    pieces: Vec<Piece>,
    hot: &HotPixels,
    pixels: &PixelGrid,
    also: &HashMap<usize, Vec<Pixel>>,
) -> Vec<Piece> {
    // Built here, per round that routes: the last round's contact search
    // finds nothing and routes nothing.
    let tree = PixelTree::new(hot.set.iter().copied().collect());
    routed(pieces, 0, &(hot, &tree), pixels, also, false).pieces
}

/// `pieces` (the first of them is piece `first` of the round) routed and
/// merged: on this thread, or in halves (see [`route_also_through`]).
/// `indexed`: every piece of the result is in its index, as merging
/// others into it needs (else those of a second half may not be).
fn routed(
    mut pieces: Vec<Piece>,
    first: usize,
    hot: &(&HotPixels, &PixelTree),
    pixels: &PixelGrid,
    also: &HashMap<usize, Vec<Pixel>>,
    indexed: bool,
) -> Merged {
    if pieces.len() < HALVES_FROM || crate::construct::threads::spare() == 0 {
        let mut out = Merged::default();
        route_into(&mut out, pieces, first, *hot, pixels, also);
        return out;
    }
    let middle = pieces.len() / 2;
    let second = pieces.split_off(middle);
    // (the first half's pieces are looked up by the second's: indexed)
    let (second, mut out) = crate::construct::threads::run_beside(
        || routed(second, first + middle, hot, pixels, also, false),
        || routed(pieces, first, hot, pixels, also, true),
    );
    out.append_merged(second, indexed);
    out
}

/// Routes `pieces` (the first of them is piece `first` of the round) into
/// `out`: each bent through the centres of the hot pixels it meets.
fn route_into(
    out: &mut Merged,
    pieces: Vec<Piece>,
    first: usize,
    (hot, tree): (&HotPixels, &PixelTree),
    pixels: &PixelGrid,
    also: &HashMap<usize, Vec<Pixel>>,
) {
    let mut met: Vec<Pixel> = Vec::new();
    for (k, piece) in pieces.into_iter().enumerate() {
        let [a, b] = piece.ends;
        if a == b {
            let q = hot.snap(pixels, a);
            out.push([q, q], piece.origins);
            continue;
        }
        met.clear();
        tree.met_by(pixels, a, b, &mut met);
        if let Some(extra) = also.get(&(first + k)) {
            met.extend(extra.iter().filter(|x| !met.contains(x)).copied().collect::<Vec<_>>());
        }
        let (pa, pb) = (pixels.pixel_of(a), pixels.pixel_of(b));
        met.retain(|&x| x != pa && x != pb);
        let (a2, b2) = (hot.snap(pixels, a), hot.snap(pixels, b));
        if met.is_empty() {
            if a2 != b2 {
                out.push([a2, b2], piece.origins);
            }
            continue;
        }
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
}

/// Pieces with equal ends (either direction) merged.
#[derive(Default)]
struct Merged {
    pieces: Vec<Piece>,
    index: HashMap<[u64; 4], usize>,
}

impl Merged {
    fn push(&mut self, ends: [Point; 2], origins: Vec<u32>) {
        self.add(Piece { ends, origins }, true);
    }

    /// The pieces of `later` (merged among themselves) pushed after these;
    /// its new pieces indexed only where `index` says (not for the last
    /// pushes: a look-up each is then all it costs).
    fn append_merged(&mut self, later: Merged, index: bool) {
        later.pieces.into_iter().for_each(|piece| self.add(piece, index));
    }

    /// `piece` merged into the equal one here, or added after the others
    /// (and indexed where `index` says).
    fn add(&mut self, piece: Piece, index: bool) {
        let key = Point::segment_key(piece.ends[0], piece.ends[1]);
        match self.index.get(&key) {
            Some(&k) => self.pieces[k].merge(piece.origins),
            None => {
                if index {
                    self.index.insert(key, self.pieces.len());
                }
                self.pieces.push(piece);
            }
        }
    }
}

impl Piece {
    /// Adds `origins` to the piece's input segments (sorted, each once).
    fn merge(&mut self, origins: Vec<u32>) {
        self.origins.extend(origins);
        self.origins.sort_unstable();
        self.origins.dedup();
    }
}
