//! The pieces a diagram was built from, and the input segments they came
//! from: with [`Builder::split_crossings`](crate::Builder::split_crossings)
//! the split input, otherwise the input segments themselves (piece `i` is
//! input segment `i`).

use crate::diagram::Diagram;
use crate::geometry::Point;

/// Indices, as an iterator of `usize`: the pieces of an input segment, or
/// the input segments of a piece.
#[derive(Clone, Debug)]
pub struct Indices<'a> {
    list: std::slice::Iter<'a, u32>,
    /// Without splitting: the one index, once.
    single: Option<usize>,
}

impl Iterator for Indices<'_> {
    type Item = usize;

    fn next(&mut self) -> Option<usize> {
        self.single.take().or_else(|| self.list.next().map(|&k| k as usize))
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.list.len() + usize::from(self.single.is_some());
        (n, Some(n))
    }
}

impl ExactSizeIterator for Indices<'_> {}

impl<'a> Indices<'a> {
    /// With splitting, the list `map` reads from `split`; without, `index`
    /// itself where it is below `inputs` (piece `i` is input `i`).
    fn through(
        split: Option<&'a crate::diagram::SplitPieces>,
        map: impl FnOnce(&'a crate::diagram::SplitPieces) -> &'a [u32],
        index: usize,
        inputs: usize,
    ) -> Indices<'a> {
        match split {
            Some(split) => Indices { list: map(split).iter(), single: None },
            None => Indices { list: [].iter(), single: (index < inputs).then_some(index) },
        }
    }
}

impl Diagram {
    /// The number of segments the diagram was built from: the pieces of a
    /// split input, else the input segments.
    pub fn piece_count(&self) -> usize {
        match &self.split {
            Some(split) => split.piece_count(),
            None => self.stats.input_segments,
        }
    }

    /// The pieces (indices below [`Diagram::piece_count`], ascending) that
    /// input segment `input` became: with `split_crossings` none (it shrank
    /// to a point smaller than a snapping pixel) or more, else the segment
    /// itself. Empty out of range.
    ///
    /// ```
    /// use segvoronoi::Builder;
    /// let mut b = Builder::new();
    /// b.add_segments([[[0.0, 0.0], [4.0, 0.0]], [[2.0, -1.0], [2.0, 1.0]], [[1.0, 0.0], [3.0, 0.0]]])?;
    /// let d = b.split_crossings(true).build()?;
    /// // segment 0 is cut at x = 1, 2 and 3; [1, 2] and [2, 3] are shared with segment 2
    /// let pieces: Vec<usize> = d.pieces_of_input(0).collect();
    /// assert_eq!(pieces.len(), 4);
    /// let shared = pieces.iter().filter(|&&p| d.inputs_of_piece(p).len() == 2).count();
    /// assert_eq!(shared, 2);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn pieces_of_input(&self, input: usize) -> Indices<'_> {
        Indices::through(self.split.as_deref(), |s| s.pieces_of(input), input, self.stats.input_segments)
    }

    /// The input segments (ascending) that piece `piece` came from: one, or
    /// several where collinear input segments overlapped. Empty out of
    /// range.
    pub fn inputs_of_piece(&self, piece: usize) -> Indices<'_> {
        Indices::through(self.split.as_deref(), |s| s.inputs_of(piece), piece, self.stats.input_segments)
    }

    /// The arc pieces (indices of arc sites, as [`Diagram::site_of_arc`]
    /// takes them, ascending) that input arc `input` became: with
    /// `split_crossings` none (it shrank to a point), one or more, else the
    /// arc itself. Empty out of range.
    ///
    /// ```
    /// use segvoronoi::{Builder, CircularArc};
    /// let mut b = Builder::new();
    /// b.add_arc(CircularArc::from_bulge([0.0, 0.0], [4.0, 0.0], 1.0)?)?;
    /// b.add_segment([[2.0, 1.0], [2.0, -3.0]])?;
    /// let d = b.split_crossings(true).build()?;
    /// let pieces: Vec<usize> = d.arc_pieces_of_input(0).collect();
    /// assert_eq!(pieces, vec![0, 1]);
    /// assert_eq!(d.inputs_of_arc_piece(1).collect::<Vec<_>>(), vec![0]);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn arc_pieces_of_input(&self, input: usize) -> Indices<'_> {
        Indices::through(self.split_arcs.as_deref(), |s| s.pieces_of(input), input, self.stats.input_arcs)
    }

    /// The input arcs (ascending) that arc piece `piece` came from: one,
    /// or several where input arcs coincided. Empty out of range.
    pub fn inputs_of_arc_piece(&self, piece: usize) -> Indices<'_> {
        Indices::through(self.split_arcs.as_deref(), |s| s.inputs_of(piece), piece, self.stats.input_arcs)
    }

    /// The endpoints of piece `piece` (input coordinates), as built; `None`
    /// out of range. For a piece that repeats an earlier one or has zero
    /// length this is its own geometry, though the diagram has one site for
    /// both.
    pub fn piece(&self, piece: usize) -> Option<[Point; 2]> {
        let site = self.site_of_segment(piece)?;
        match self.site(site)? {
            site => Some(site.ends()),
        }
    }

    /// With `split_crossings`, the largest distance from a piece to an input
    /// segment it came from (0 when nothing had to be split, and without
    /// splitting).
    pub fn max_split_displacement(&self) -> f64 {
        self.split.as_ref().map_or(0.0, |s| s.max_displacement)
    }

    /// With `split_crossings`, the side of the pixels the crossings were
    /// snapped to (input units); 0 without splitting.
    pub fn split_pixel_size(&self) -> f64 {
        self.split.as_ref().map_or(0.0, |s| s.pixel)
    }
}
