//! The sites one half of the parallel build leaves out, on a grid, for
//! the one question about them that the seam's tests (`seam`) cannot
//! always settle: may the disk of a vertex hold one of them?
//!
//! The seam's tests bound the left-out sites by a line and the input's
//! enclosure, which is quick and enough for most vertices. Where the input
//! is lumpy along its boundary (parts of a sheet, stars, coasts), the
//! circles of cells along the hull are huge and dip between the bumps far
//! deeper than any rim the halves could both hold; there they fail, though
//! the circle holds no site at all. Asking the left-out sites themselves
//! settles it: a disk that holds none is final, whatever its size.
//!
//! In floating point with a margin far above the rounding of a stored
//! vertex and of the distances: `true` is always allowed (the build then
//! takes a wider halo or one thread), `false` must never be wrong.

use crate::geometry::seam::MARGIN;
use crate::geometry::{Point, Site};

/// Left-out sites per cell of a grid: each point as a segment of length
/// zero, each segment in every cell its bounding box meets.
pub(crate) struct LeftOut {
    /// The grid's lower-left corner and its cells' side.
    origin: Point,
    cell: f64,
    columns: usize,
    rows: usize,
    /// Per cell (row by row), where its sites start in `sites`; one more
    /// at the end.
    starts: Vec<u32>,
    sites: Vec<[Point; 2]>,
    /// The segments whose bounding box meets more than [`LONG_SPAN`]
    /// cells, asked of every disk instead (a segment across the grid
    /// would fill every cell's list).
    long: Vec<[Point; 2]>,
    /// A margin above the rounding of a coordinate of any site.
    slack: f64,
}

/// The most cells a segment is listed in.
const LONG_SPAN: usize = 16;

impl LeftOut {
    /// The grid of `sites` (a point as `[p, p]`), with about two per cell.
    /// Sites with a coordinate that is not finite are kept apart: every
    /// disk may hold them.
    pub(crate) fn new(sites: Vec<[Point; 2]>) -> LeftOut {
        let finite = |s: &[Point; 2]| s.iter().all(|p| p.x.is_finite() && p.y.is_finite());
        let (mut lo, mut hi) = (Point::new(f64::INFINITY, f64::INFINITY), Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY));
        let mut size: f64 = 0.0;
        for s in &sites {
            for p in s {
                lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
                hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
                size = size.max(p.x.abs() + p.y.abs());
            }
        }
        let slack = MARGIN * size;
        let (width, height) = (hi.x - lo.x, hi.y - lo.y);
        let mut grid = LeftOut {
            origin: lo,
            cell: f64::INFINITY,
            columns: 1,
            rows: 1,
            starts: vec![0, 0],
            sites: Vec::new(),
            long: Vec::new(),
            slack,
        };
        if sites.is_empty() {
            return grid;
        }
        if !sites.iter().all(finite) || !(slack.is_finite() && width.is_finite() && height.is_finite()) {
            // (one cell that every disk is taken to reach)
            grid.cell = f64::NAN;
            grid.starts = vec![0, sites.len() as u32];
            grid.sites = sites;
            return grid;
        }
        // (cells of about two sites each, at most 2^11 a side)
        let area = (width * height).max(f64::MIN_POSITIVE);
        let side = (2.0 * area / sites.len() as f64).sqrt().max(width.max(height) / 2048.0);
        if side > 0.0 && side.is_finite() {
            grid.cell = side;
            grid.columns = ((width / side) as usize + 1).min(2048);
            grid.rows = ((height / side) as usize + 1).min(2048);
        }
        let spans: Vec<[usize; 4]> = sites.iter().map(|s| grid.cells_under(s)).collect();
        let listed = |&[c0, c1, r0, r1]: &[usize; 4]| (c1 - c0 + 1) * (r1 - r0 + 1) <= LONG_SPAN;
        grid.long = sites.iter().zip(&spans).filter(|(_, span)| !listed(span)).map(|(s, _)| *s).collect();
        let (sites, spans): (Vec<[Point; 2]>, Vec<[usize; 4]>) =
            sites.into_iter().zip(spans).filter(|(_, span)| listed(span)).unzip();
        let mut counts = vec![0u32; grid.columns * grid.rows + 1];
        for &[c0, c1, r0, r1] in &spans {
            for r in r0..=r1 {
                counts[r * grid.columns + c0..=r * grid.columns + c1].iter_mut().for_each(|n| *n += 1);
            }
        }
        let mut total = 0u32;
        for n in counts.iter_mut() {
            let here = *n;
            *n = total;
            total += here;
        }
        let mut filled = counts.clone();
        let mut placed = vec![[Point::new(0.0, 0.0); 2]; total as usize];
        for (s, &[c0, c1, r0, r1]) in sites.iter().zip(&spans) {
            for r in r0..=r1 {
                for c in c0..=c1 {
                    let slot = &mut filled[r * grid.columns + c];
                    placed[*slot as usize] = *s;
                    *slot += 1;
                }
            }
        }
        grid.starts = counts;
        grid.sites = placed;
        grid
    }

    /// The columns and rows (first and last of each) that `site`'s
    /// bounding box meets.
    fn cells_under(&self, site: &[Point; 2]) -> [usize; 4] {
        let column = |x: f64| (((x - self.origin.x) / self.cell) as usize).min(self.columns - 1);
        let row = |y: f64| (((y - self.origin.y) / self.cell) as usize).min(self.rows - 1);
        let [a, b] = *site;
        [column(a.x.min(b.x)), column(a.x.max(b.x)), row(a.y.min(b.y)), row(a.y.max(b.y))]
    }

    /// Whether the disk of centre `centre` and radius `radius` may hold a
    /// left-out site (a point of it nearer `centre` than `radius`, or not
    /// clearly farther).
    pub(crate) fn disk_may_hold_one(&self, centre: Point, radius: f64) -> bool {
        if self.sites.is_empty() && self.long.is_empty() {
            return false;
        }
        let finite = centre.x.is_finite() && centre.y.is_finite() && radius.is_finite() && radius >= 0.0;
        if !finite || self.cell.is_nan() {
            return true;
        }
        let size = centre.x.abs() + centre.y.abs();
        let reach = radius + self.slack + MARGIN * (size + radius.min(1.0)) + 1e-12 * radius;
        if self.long.iter().any(|s| distance_to(centre, s) < reach) {
            return true;
        }
        // (the cells the disk's box meets; none where it misses the grid)
        let (x0, x1) = (centre.x - reach - self.origin.x, centre.x + reach - self.origin.x);
        let (y0, y1) = (centre.y - reach - self.origin.y, centre.y + reach - self.origin.y);
        let (width, height) = (self.columns as f64 * self.cell, self.rows as f64 * self.cell);
        if x1 < 0.0 || y1 < 0.0 || (self.cell.is_finite() && (x0 > width || y0 > height)) {
            return false;
        }
        let index =
            |v: f64, count: usize| if self.cell.is_finite() { ((v.max(0.0) / self.cell) as usize).min(count - 1) } else { 0 };
        let (c0, c1, r0, r1) = (index(x0, self.columns), index(x1, self.columns), index(y0, self.rows), index(y1, self.rows));
        for r in r0..=r1 {
            for c in c0..=c1 {
                // (a cell wholly beyond the disk's reach is skipped)
                if self.cell.is_finite() {
                    let (left, bottom) = (self.origin.x + c as f64 * self.cell, self.origin.y + r as f64 * self.cell);
                    let dx = (left - centre.x).max(centre.x - (left + self.cell)).max(0.0);
                    let dy = (bottom - centre.y).max(centre.y - (bottom + self.cell)).max(0.0);
                    if dx.hypot(dy) > reach + self.cell * MARGIN {
                        continue;
                    }
                }
                let k = r * self.columns + c;
                let cell = &self.sites[self.starts[k] as usize..self.starts[k + 1] as usize];
                if cell.iter().any(|s| distance_to(centre, s) < reach) {
                    return true;
                }
            }
        }
        false
    }
}

/// The distance from `p` to `site` (a segment, or a point where its ends
/// are equal): [`Site::distance`].
fn distance_to(p: Point, &[a, b]: &[Point; 2]) -> f64 {
    let site = if a == b { Site::Point(a) } else { Site::Segment { a, b } };
    site.distance(p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix64;

    /// The plain answer: some site clearly nearer than the radius (then
    /// the grid must say `true`), or every site clearly farther (then it
    /// must say `false`); `None` in between, where either is allowed.
    fn plain(sites: &[[Point; 2]], centre: Point, radius: f64) -> Option<bool> {
        let nearest = sites.iter().map(|s| distance_to(centre, s)).fold(f64::INFINITY, f64::min);
        let doubt = 1e-6 * (radius + centre.x.abs() + centre.y.abs());
        if nearest < radius - doubt {
            Some(true)
        } else if nearest > radius + doubt {
            Some(false)
        } else {
            None
        }
    }

    fn random_sites(rng: &mut SplitMix64, n: usize, length: f64, at: Point, scale: f64) -> Vec<[Point; 2]> {
        (0..n)
            .map(|k| {
                let a = Point::new(at.x + scale * rng.unit(), at.y + scale * rng.unit());
                if k % 3 == 0 {
                    [a, a]
                } else {
                    let t = std::f64::consts::TAU * rng.unit();
                    [a, Point::new(a.x + scale * length * t.cos(), a.y + scale * length * t.sin())]
                }
            })
            .collect()
    }

    /// Against every site by brute force: small, large and huge disks,
    /// disks through a site (the answer there is `true`: not clearly
    /// farther), inside and far off the grid, at several scales and
    /// offsets; and sites that all lie on one point or one line.
    #[test]
    fn a_disk_holds_a_site_as_brute_force_finds() {
        let mut rng = SplitMix64(17);
        let mut cases: Vec<Vec<[Point; 2]>> = Vec::new();
        for (scale, at) in [(1.0, Point::new(0.0, 0.0)), (1e-9, Point::new(3e-9, -1e-9)), (1e6, Point::new(1e9, 1e9))] {
            cases.push(random_sites(&mut rng, 2000, 0.01, at, scale));
            cases.push(random_sites(&mut rng, 300, 0.3, at, scale));
        }
        cases.push(vec![[Point::new(0.5, 0.5); 2]; 20]);
        cases.push((0..100).map(|k| [Point::new(k as f64, 2.0), Point::new(k as f64 + 0.5, 2.0)]).collect());
        cases.push(Vec::new());
        // (long segments across the grid among short ones)
        let mut crossing = random_sites(&mut rng, 500, 0.01, Point::new(0.0, 0.0), 1.0);
        crossing.extend((0..40).map(|k| [Point::new(0.0, k as f64 / 40.0), Point::new(1.0, 1.0 - k as f64 / 40.0)]));
        cases.push(crossing);
        for sites in &cases {
            let grid = LeftOut::new(sites.clone());
            let (lo, hi) = sites
                .iter()
                .flatten()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| (lo.min(p.x.min(p.y)), hi.max(p.x.max(p.y))));
            let (lo, hi) = if lo.is_finite() { (lo, hi) } else { (0.0, 1.0) };
            let span = (hi - lo).max(1e-300);
            for k in 0..3000 {
                let centre = Point::new(lo + span * (3.0 * rng.unit() - 1.0), lo + span * (3.0 * rng.unit() - 1.0));
                let radius = match k % 4 {
                    0 => span * 0.01 * rng.unit(),
                    1 => span * rng.unit(),
                    2 => span * 1e6 * rng.unit(),
                    // (through the nearest site)
                    _ => sites.iter().map(|s| distance_to(centre, s)).fold(f64::INFINITY, f64::min),
                };
                let answer = grid.disk_may_hold_one(centre, radius);
                if k % 4 == 3 && !sites.is_empty() {
                    assert!(answer, "a disk through a site at {centre:?} r {radius}");
                }
                if let Some(expected) = plain(sites, centre, radius) {
                    assert_eq!(answer, expected, "centre {centre:?} radius {radius} of {} sites", sites.len());
                }
            }
        }
    }

    /// A disk that is not finite, or sites that are not, may always hold one.
    #[test]
    fn what_is_not_finite_may_hold_one() {
        let grid = LeftOut::new(vec![[Point::new(0.0, 0.0); 2]]);
        assert!(grid.disk_may_hold_one(Point::new(f64::NAN, 0.0), 1.0));
        assert!(grid.disk_may_hold_one(Point::new(5.0, 5.0), f64::INFINITY));
        let far = LeftOut::new(vec![[Point::new(f64::MAX, 0.0), Point::new(-f64::MAX, 0.0)]]);
        assert!(far.disk_may_hold_one(Point::new(0.0, 1e300), 1.0));
        let nan = LeftOut::new(vec![[Point::new(f64::NAN, 0.0); 2], [Point::new(1.0, 1.0); 2]]);
        assert!(nan.disk_may_hold_one(Point::new(-50.0, -50.0), 1.0));
        assert!(!LeftOut::new(Vec::new()).disk_may_hold_one(Point::new(0.0, 0.0), 1e300));
    }
}
