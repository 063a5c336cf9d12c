//! The polygon input of the medial-axis, offsets and headline benchmarks:
//! a sheet of star-shaped parts with a hole each (testgen's `star_sheet`,
//! random radii, so no two corners are cocircular by construction), 400
//! corners outside (radii 0.8..1) and 100 around the hole (radii
//! 0.2..0.35), 2.2 apart on a square grid, disjoint. The wall between hole
//! and outer ring is 0.45 to 0.8 wide, so the inscribed radius is at most
//! 0.4.

use segvoronoi_testgen::shapes::star_sheet;

/// Corners of a part's outer ring.
pub const OUTER: usize = 400;
/// Corners of a part's hole.
pub const HOLE: usize = 100;

/// One part: its outer ring (counter-clockwise) and its hole (clockwise,
/// as Clipper wants holes).
pub type Polygon = [Vec<[f64; 2]>; 2];

/// `polygons` parts on a square grid (testgen's `star_sheet`).
pub fn polygons(polygons: usize, seed: u64) -> Vec<Polygon> {
    star_sheet(polygons, OUTER, HOLE, seed)
}

/// The parts for about `segments` segments in all (rounded up to whole
/// parts), with seed 1 as every benchmark uses.
pub fn for_segments(segments: usize) -> Vec<Polygon> {
    polygons(segments.div_ceil(OUTER + HOLE), 1)
}
