//! Construction: input checking, insertion order, point insertion, and the
//! renumbering of the result to public ids.

mod finish;
mod order;
mod points;
mod segment_input;

use crate::diagram::{Diagram, SiteId, NONE};
use crate::error::{Error, ErrorKind};
use crate::geometry::predicates::{orientation, Orientation};
use crate::geometry::scale::Scale;
use crate::geometry::Point;
use points::{Inserted, PointDiagram};

/// Most input points one diagram may have: every id must fit in 32 bits
/// (a diagram of n points has up to 2n vertices of 3 half-edges each).
pub const MAX_POINTS: usize = 600_000_000;

/// Collects input sites and builds their Voronoi diagram.
///
/// The contract: coordinates are finite `f64` values of any magnitude;
/// points may repeat (repeats are merged and counted in
/// [`BuildStats::duplicate_points`](crate::BuildStats)). A rejected call
/// leaves the builder exactly as it was.
///
/// ```
/// use segvoronoi::Builder;
///
/// let mut builder = Builder::new();
/// builder.add_point(0.0, 0.0)?;
/// builder.add_points([[4.0, 0.0], [0.0, 4.0], [4.0, 4.0], [2.0, 1.0]])?;
/// let diagram = builder.build()?;
/// assert_eq!(diagram.site_count(), 5);
/// assert!(diagram.validate().is_ok());
/// # Ok::<(), segvoronoi::Error>(())
/// ```
#[derive(Clone, Debug, Default)]
pub struct Builder {
    points: Vec<Point>,
}

impl Builder {
    /// An empty builder.
    pub fn new() -> Builder {
        Builder::default()
    }

    /// Number of points added so far (duplicates included).
    pub fn point_count(&self) -> usize {
        self.points.len()
    }

    /// Adds one point and returns its input index.
    ///
    /// Fails with [`ErrorKind::InvalidCoordinate`] when a coordinate is not
    /// finite; the builder is then unchanged.
    pub fn add_point(&mut self, x: f64, y: f64) -> Result<usize, Error> {
        let index = self.points.len();
        check_point(index, Point::new(x, y))?;
        check_capacity(index + 1)?;
        self.points.push(Point::new(x, y));
        Ok(index)
    }

    /// Makes room for `additional` more points, or fails with
    /// [`ErrorKind::TooLarge`] (the builder unchanged) when the total would
    /// exceed [`MAX_POINTS`].
    pub fn reserve(&mut self, additional: usize) -> Result<(), Error> {
        check_capacity(self.points.len().saturating_add(additional))?;
        self.points.reserve(additional);
        Ok(())
    }

    /// Adds many points, all or none: on error (the first non-finite
    /// coordinate, named by the index it would have had) nothing is added.
    pub fn add_points<P, I>(&mut self, points: I) -> Result<(), Error>
    where
        P: Into<Point>,
        I: IntoIterator<Item = P>,
    {
        let start = self.points.len();
        let iter = points.into_iter();
        self.reserve(iter.size_hint().0)?;
        for (k, p) in iter.enumerate() {
            let p = p.into();
            if let Err(e) = check_point(start + k, p).and_then(|_| check_capacity(start + k + 1)) {
                self.points.truncate(start);
                return Err(e);
            }
            self.points.push(p);
        }
        Ok(())
    }

    /// Builds the diagram. The builder is not consumed: more points may be
    /// added and the diagram built again.
    ///
    /// For 100,000 points or more, part of the work (sorting the insertion
    /// order) runs on a second, short-lived thread; the result is the same.
    pub fn build(&self) -> Result<Diagram, Error> {
        Ok(build_points(&self.points))
    }
}

fn check_point(index: usize, p: Point) -> Result<(), Error> {
    if p.is_finite() {
        return Ok(());
    }
    Err(Error::new(
        ErrorKind::InvalidCoordinate,
        format!("point {index} has a non-finite coordinate ({}, {})", p.x, p.y),
        vec![index],
    ))
}

fn check_capacity(count: usize) -> Result<(), Error> {
    if count <= MAX_POINTS {
        return Ok(());
    }
    Err(Error::new(
        ErrorKind::TooLarge,
        format!("point {MAX_POINTS} is one too many: a diagram holds at most {MAX_POINTS} points"),
        vec![MAX_POINTS],
    ))
}

/// The Voronoi diagram of finite points.
fn build_points(input: &[Point]) -> Diagram {
    let max_abs = input.iter().fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    let scale = Scale::for_max_abs(max_abs);
    let points: Vec<Point> = input.iter().map(|p| p.scaled(scale.to_internal).canonical_zero()).collect();
    let (diagram, site_of_input) = construct(&points);
    finish::finish(diagram, &site_of_input, input, scale)
}

/// Runs the insertions. Returns the diagram in internal site ids and, per
/// input point, the internal site it became.
fn construct(points: &[Point]) -> (PointDiagram, Vec<SiteId>) {
    let n = points.len();
    let mut site_of = vec![SiteId(NONE); n];
    let mut diagram = PointDiagram::new(n);
    let order = points::insertion_order(points);
    let Some(&first) = order.first() else {
        return (diagram, site_of);
    };
    let pa = points[first as usize];
    let Some(b_pos) = order.iter().position(|&i| points[i as usize] != pa) else {
        // one distinct point
        let s = diagram.add_lone_site(pa);
        site_of.iter_mut().for_each(|x| *x = s);
        return (diagram, site_of);
    };
    let second = order[b_pos];
    let pb = points[second as usize];
    let third = order[b_pos + 1..]
        .iter()
        .copied()
        .find(|&i| orientation(pa, pb, points[i as usize]) != Orientation::Collinear);
    let Some(third) = third else {
        start_all_collinear(points, &mut diagram, &mut site_of);
        return (diagram, site_of);
    };

    let ids = diagram.start_collinear(&[pa, pb]);
    site_of[first as usize] = ids[0];
    site_of[second as usize] = ids[1];
    let mut last = ids[1];
    // Gather the points into insertion order first: the loads are
    // independent here and overlap, where inside the loop each would be a
    // cache miss waiting behind a whole insertion.
    let rest: Vec<(u32, Point)> = std::iter::once(third)
        .chain(order.iter().copied().filter(|&i| i != first && i != second && i != third))
        .map(|i| (i, points[i as usize]))
        .collect();
    drop(order);
    for (i, p) in rest {
        match diagram.insert(p, last) {
            Inserted::New(s) => {
                site_of[i as usize] = s;
                last = s;
            }
            Inserted::Duplicate(s) => site_of[i as usize] = s,
        }
    }
    (diagram, site_of)
}

/// All points on one line (at least two distinct): sort along the line,
/// merge repeats, and lay out the ladder of parallel bisectors directly.
fn start_all_collinear(points: &[Point], diagram: &mut PointDiagram, site_of: &mut [SiteId]) {
    let mut by_position: Vec<u32> = (0..points.len() as u32).collect();
    // Lexicographic order is an order along any line.
    by_position.sort_unstable_by(|&i, &j| {
        let (p, q) = (points[i as usize], points[j as usize]);
        p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y))
    });
    let mut chain: Vec<Point> = Vec::new();
    let mut chain_index = vec![0usize; points.len()];
    for &i in &by_position {
        let p = points[i as usize];
        if chain.last() != Some(&p) {
            chain.push(p);
        }
        chain_index[i as usize] = chain.len() - 1;
    }
    let ids = diagram.start_collinear(&chain);
    for (i, s) in site_of.iter_mut().enumerate() {
        *s = ids[chain_index[i]];
    }
}
