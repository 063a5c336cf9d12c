//! The diagram's sites in input coordinates, each kind in its own array:
//! the points first, then the open segments, then the open arcs (the order
//! of the public site ids).
//!
//! Why not one `Vec<Site>`: a [`Site`] is as large as its largest kind (an
//! arc, 88 bytes), so a million point sites would take 88 MB where their
//! coordinates take 16; the table hands out each site by value instead.

use crate::geometry::{CircularArc, Point, Site};

/// Sites by public id: points `0..points.len()`, then segments, then arcs.
#[derive(Clone, Debug, Default)]
pub(crate) struct SiteTable {
    points: Vec<Point>,
    segments: Vec<[Point; 2]>,
    arcs: Vec<CircularArc>,
}

impl SiteTable {
    /// The table of these sites: points, segments, arcs (each in id order).
    pub(crate) fn from_parts(points: Vec<Point>, segments: Vec<[Point; 2]>, arcs: Vec<CircularArc>) -> SiteTable {
        SiteTable { points, segments, arcs }
    }

    /// The number of sites.
    pub(crate) fn len(&self) -> usize {
        self.points.len() + self.segments.len() + self.arcs.len()
    }

    /// The point sites' coordinates.
    pub(crate) fn points(&self) -> &[Point] {
        &self.points
    }

    /// Site `i`, or `None` beyond the last.
    pub(crate) fn get(&self, i: usize) -> Option<Site> {
        let j = i.checked_sub(self.points.len());
        match j {
            None => Some(Site::Point(self.points[i])),
            Some(j) => match self.segments.get(j) {
                Some(&[a, b]) => Some(Site::Segment { a, b }),
                None => self.arcs.get(j - self.segments.len()).map(|&arc| Site::Arc(arc)),
            },
        }
    }

    /// Site `i`; panics beyond the last, like indexing (callers hold ids
    /// of this diagram).
    pub(crate) fn at(&self, i: usize) -> Site {
        match self.get(i) {
            Some(site) => site,
            None => panic!("site {i} of {}", self.len()),
        }
    }

    /// Every site, by id.
    pub(crate) fn iter(&self) -> impl Iterator<Item = Site> + '_ {
        let points = self.points.iter().map(|&p| Site::Point(p));
        let segments = self.segments.iter().map(|&[a, b]| Site::Segment { a, b });
        points.chain(segments).chain(self.arcs.iter().map(|&arc| Site::Arc(arc)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sites_come_back_by_id_in_kind_order() {
        let (p, q, r) = (Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(0.0, 1.0));
        let arc = CircularArc::through(q, Point::new(0.6, 0.8), r).expect("an arc");
        let t = SiteTable::from_parts(vec![p, q], vec![[p, r]], vec![arc]);
        assert_eq!(t.len(), 4);
        let all: Vec<Site> = t.iter().collect();
        assert_eq!(all, vec![Site::Point(p), Site::Point(q), Site::Segment { a: p, b: r }, Site::Arc(arc)]);
        assert_eq!((0..4).map(|i| t.at(i)).collect::<Vec<_>>(), all);
        assert_eq!(t.get(4), None);
        assert_eq!(t.points(), &[p, q]);
    }
}
