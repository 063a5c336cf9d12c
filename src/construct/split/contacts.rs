//! Every place where the current pieces meet other than at a common
//! endpoint (crossings, overlaps, an endpoint or a point inside a segment),
//! as the pixels that must become hot, counted by kind.
//!
//! Candidate pairs come from the uniform grid (`construct::grid`): two
//! pieces are tested in the first cell they share, a point against the
//! pieces of its cell. Each test is the exact contact test of
//! `geometry::segment_contact`.

use super::Layout;
use crate::construct::grid::bounding_box;
use crate::geometry::segment_contact::{inside_segment, segment_contact, SegmentContact};
use crate::geometry::snap::{Pixel, PixelGrid};
use crate::geometry::Point;

/// How many contacts of each kind one search found.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct ContactCounts {
    pub crossings: usize,
    pub overlaps: usize,
    /// An endpoint or an isolated point inside a segment.
    pub touchings: usize,
}

impl ContactCounts {
    pub(super) fn total(&self) -> usize {
        self.crossings + self.overlaps + self.touchings
    }
}

/// The pixels where the pieces of `layout` and its points meet other than
/// at common endpoints, appended to `hot` (with repeats), and the counts.
pub(super) fn contact_pixels(layout: &Layout, pixels: &PixelGrid, hot: &mut Vec<Pixel>) -> ContactCounts {
    let mut counts = ContactCounts::default();
    let Some((grid, cells)) = &layout.grid else { return counts };
    let segments: Vec<[Point; 2]> = layout.proper.iter().map(|&(_, s)| s).collect();
    let points = &layout.lone;
    let m = segments.len();
    let mut items: Vec<(u64, usize)> = Vec::with_capacity(cells.cells.len() + points.len());
    for i in 0..m {
        items.extend(cells.of(i as u32).iter().map(|&c| (c, i)));
    }
    let (lo, hi) = bounding_box(&layout.proper);
    for (k, &q) in points.iter().enumerate() {
        if lo.x <= q.x && q.x <= hi.x && lo.y <= q.y && q.y <= hi.y {
            items.push((grid.cell_of(q), m + k));
        }
    }
    items.sort_unstable();
    for group in items.chunk_by(|x, y| x.0 == y.0) {
        let cell = group[0].0;
        let split = group.partition_point(|&(_, item)| item < m);
        let (in_cell, points_in_cell) = (&group[..split], &group[split..]);
        for (k, &(_, i)) in in_cell.iter().enumerate() {
            for &(_, j) in &in_cell[k + 1..] {
                if cells.first_common(i as u32, j as u32) == Some(cell) {
                    pair_pixels(segments[i], segments[j], pixels, hot, &mut counts);
                }
            }
        }
        for &(_, p) in points_in_cell {
            let q = points[p - m];
            for &(_, s) in in_cell {
                if inside_segment(q, segments[s]) {
                    counts.touchings += 1;
                    hot.push(pixels.pixel_of(q));
                }
            }
        }
    }
    counts
}

/// The hot pixels of one pair of segments, if they meet other than at a
/// common endpoint.
fn pair_pixels(s: [Point; 2], t: [Point; 2], pixels: &PixelGrid, hot: &mut Vec<Pixel>, counts: &mut ContactCounts) {
    let Some(contact) = segment_contact(s, t) else { return };
    match contact {
        SegmentContact::Cross => {
            counts.crossings += 1;
            hot.push(pixels.crossing_pixel(s, t));
            return;
        }
        SegmentContact::Overlap => counts.overlaps += 1,
        SegmentContact::EndpointOfFirstOnSecond | SegmentContact::EndpointOfSecondOnFirst => counts.touchings += 1,
    }
    // An overlap or a touching: every endpoint inside the other segment
    // (for an overlap one or two of the four).
    for (end, other) in [(s[0], t), (s[1], t), (t[0], s), (t[1], s)] {
        if inside_segment(end, other) {
            hot.push(pixels.pixel_of(end));
        }
    }
}
