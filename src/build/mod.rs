//! Construction: input checking, insertion order, point insertion, and the
//! renumbering of the result to public ids.

mod finish;
mod order;
mod points;
pub(crate) mod polygon_input;
mod segment_input;
mod sites;

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
/// builder.add_point([0.0, 0.0])?;
/// builder.add_points([[4.0, 0.0], [0.0, 4.0], [4.0, 4.0], [2.0, 1.0]])?;
/// let diagram = builder.build()?;
/// assert_eq!(diagram.site_count(), 5);
/// assert!(diagram.validate().is_ok());
/// # Ok::<(), segvoronoi::Error>(())
/// ```
#[derive(Clone, Debug, Default)]
pub struct Builder {
    points: Vec<Point>,
    segments: Vec<[Point; 2]>,
    /// The rings of the polygons added (`polygon_input`), which bound the
    /// domain, and how many polygons there are.
    rings: Vec<polygon_input::RingInput>,
    polygons: usize,
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

    /// Number of segments added so far (repeats and zero-length ones included).
    pub fn segment_count(&self) -> usize {
        self.segments.len()
    }

    /// Adds one point and returns its input index (the number of points
    /// added before it). A point is anything that converts into a
    /// [`Point`]: `[x, y]`, `(x, y)` or a `Point`, as for
    /// [`Builder::add_points`].
    ///
    /// Fails with [`ErrorKind::InvalidCoordinate`] when a coordinate is not
    /// finite, or [`ErrorKind::TooLarge`] past [`MAX_POINTS`]; the builder is
    /// then unchanged.
    pub fn add_point(&mut self, point: impl Into<Point>) -> Result<usize, Error> {
        self.add_points([point]).map(|added| added.start)
    }

    /// Adds many points, all or none, and returns their input indices. On
    /// error (the first non-finite coordinate, named by the index it would
    /// have had, or [`ErrorKind::TooLarge`]) nothing is added.
    pub fn add_points<P, I>(&mut self, points: I) -> Result<std::ops::Range<usize>, Error>
    where
        P: Into<Point>,
        I: IntoIterator<Item = P>,
    {
        let iter = points.into_iter();
        self.reserve_points(iter.size_hint().0)?;
        let endpoints = 2 * self.segments.len();
        append_checked(&mut self.points, iter.map(Into::into), check_point, |n| check_capacity(n.saturating_add(endpoints)))
    }

    /// Adds the line segment `[a, b]` and returns its input index (the
    /// number of segments added before it). Its endpoints are anything that
    /// converts into a [`Point`], as for [`Builder::add_segments`].
    ///
    /// Segments may share endpoints with any number of others; whether they
    /// cross or overlap is checked by [`Builder::build`]. A zero-length
    /// segment becomes a point. Fails with [`ErrorKind::InvalidCoordinate`]
    /// when a coordinate is not finite, or [`ErrorKind::TooLarge`] when its
    /// endpoints would pass [`MAX_POINTS`]; the builder is then unchanged.
    ///
    /// ```
    /// use segvoronoi::{Builder, Site};
    /// let mut b = Builder::new();
    /// b.add_segment([[0.0, 0.0], [4.0, 0.0]])?;
    /// b.add_points([[1.0, 2.0], [3.0, -1.5]])?;
    /// let d = b.build()?;
    /// assert_eq!(d.site_count(), 5); // two points, two endpoints, the open segment
    /// let s = d.site_of_segment(0).unwrap();
    /// assert!(matches!(d.site(s), Some(Site::Segment { .. })));
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn add_segment<P: Into<Point>>(&mut self, segment: [P; 2]) -> Result<usize, Error> {
        self.add_segments([segment]).map(|added| added.start)
    }

    /// Adds many segments, all or none, and returns their input indices. On
    /// error (the first non-finite coordinate, named by the index the
    /// segment would have had, or [`ErrorKind::TooLarge`]) nothing is added.
    pub fn add_segments<P, I>(&mut self, segments: I) -> Result<std::ops::Range<usize>, Error>
    where
        P: Into<Point>,
        I: IntoIterator<Item = [P; 2]>,
    {
        let iter = segments.into_iter();
        self.reserve_segments(iter.size_hint().0)?;
        let points = self.points.len();
        let segments = iter.map(|s| s.map(Into::into));
        append_checked(&mut self.segments, segments, check_segment, |n| check_capacity(points.saturating_add(n.saturating_mul(2))))
    }

    /// Makes room for `additional` more points, or fails with
    /// [`ErrorKind::TooLarge`] (the builder unchanged) when the points and
    /// segment endpoints together would exceed [`MAX_POINTS`].
    pub fn reserve_points(&mut self, additional: usize) -> Result<(), Error> {
        check_capacity(self.points.len().saturating_add(additional).saturating_add(2 * self.segments.len()))?;
        self.points.reserve(additional);
        Ok(())
    }

    /// Makes room for `additional` more segments, or fails with
    /// [`ErrorKind::TooLarge`] (the builder unchanged) when the points and
    /// segment endpoints together would exceed [`MAX_POINTS`].
    pub fn reserve_segments(&mut self, additional: usize) -> Result<(), Error> {
        let points = self.points.len().saturating_add(self.segments.len().saturating_add(additional).saturating_mul(2));
        check_capacity(points)?;
        self.segments.reserve(additional);
        Ok(())
    }

    /// Builds the diagram. The builder is not consumed: more points may be
    /// added and the diagram built again.
    ///
    /// For 100,000 points or more, part of the work (sorting the insertion
    /// order) runs on a second, short-lived thread; the result is the same.
    ///
    /// With segments, the input is checked first: segments that cross or
    /// overlap, or a point inside a segment, give
    /// [`ErrorKind::Intersecting`] naming both input indices.
    ///
    /// A diagram that could not be completed is never returned: that is
    /// [`ErrorKind::Internal`], a bug in segvoronoi (none is known; with
    /// sound arithmetic it does not happen), with a message saying what
    /// failed. The builder stays as it was.
    pub fn build(&self) -> Result<Diagram, Error> {
        let (mut diagram, outcome) = if self.segments.is_empty() {
            build_points(&self.points)
        } else {
            sites::build_sites(&self.points, &self.segments).map_err(|e| polygon_input::name_rings(e, &self.rings))?
        };
        diagram.set_domain(&self.rings);
        self.accept(diagram, outcome)
    }

    /// The diagram, or [`ErrorKind::Internal`] when the construction did not
    /// complete (a segment without a path after the last restart) or, where
    /// the diagram is checked, it fails [`Diagram::validate`].
    ///
    /// The check is the whole combinatorial validation, which costs about a
    /// quarter of the build itself (1M random points: 0.7 s against 2.8 s;
    /// 1M points and 300k short segments: 1.5 s against 6.9 s), so release
    /// builds run it only where something went wrong on the way (the
    /// construction started over) and under fault injection; debug builds
    /// always.
    fn accept(&self, diagram: Diagram, outcome: Outcome) -> Result<Diagram, Error> {
        if let Some(stuck) = outcome.stuck {
            return Err(self.stuck_error(stuck, outcome.restarts));
        }
        let check = cfg!(debug_assertions) || outcome.restarts > 0 || crate::geometry::fault::active();
        if check {
            if let Err(e) = diagram.validate() {
                let after = match outcome.restarts {
                    0 => String::new(),
                    1 => " (after 1 restart)".to_string(),
                    n => format!(" (after {n} restarts)"),
                };
                return Err(Error::new(
                    ErrorKind::Internal,
                    format!(
                        "construction could not complete: the finished diagram is invalid{after}: {}; please report this input",
                        e.0
                    ),
                    Vec::new(),
                ));
            }
        }
        Ok(diagram)
    }

    /// The error for a segment that found no path in the last attempt.
    fn stuck_error(&self, stuck: Stuck, restarts: usize) -> Error {
        // Endpoint `i` of the construction's point list is input segment
        // `(i - points) / 2`'s (isolated points first, then each segment's
        // two endpoints: see `sites.rs`).
        let segment = stuck.endpoint.checked_sub(self.points.len()).map(|i| i / 2).filter(|&j| j < self.segments.len());
        let which = match segment {
            Some(j) => {
                let [a, b] = self.segments[j];
                format!("segment {j} ({}, {}) - ({}, {})", a.x, a.y, b.x, b.y)
            }
            None => "a segment".to_string(),
        };
        let plural = if restarts == 1 { "" } else { "s" };
        let when = if stuck.inserted_first {
            format!("even when inserted first, after {restarts} restart{plural}")
        } else {
            format!("after {restarts} restart{plural}")
        };
        Error::new(
            ErrorKind::Internal,
            format!("construction could not complete: {which} found no path {when}; please report this input"),
            segment.into_iter().collect(),
        )
    }
}

/// Appends `items` to `list`, all or none, and returns their indices: each
/// passes `check` (with its index) and `room` (with the list's length after
/// it), or the list is cut back to where it was and the first error returned.
fn append_checked<T: Copy>(
    list: &mut Vec<T>,
    items: impl Iterator<Item = T>,
    check: fn(usize, T) -> Result<(), Error>,
    room: impl Fn(usize) -> Result<(), Error>,
) -> Result<std::ops::Range<usize>, Error> {
    let start = list.len();
    for item in items {
        let index = list.len();
        if let Err(e) = check(index, item).and_then(|()| room(index + 1)) {
            list.truncate(start);
            return Err(e);
        }
        list.push(item);
    }
    Ok(start..list.len())
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

fn check_segment(index: usize, [a, b]: [Point; 2]) -> Result<(), Error> {
    if a.is_finite() && b.is_finite() {
        return Ok(());
    }
    Err(Error::new(
        ErrorKind::InvalidCoordinate,
        format!("segment {index} has a non-finite coordinate ({}, {}) - ({}, {})", a.x, a.y, b.x, b.y),
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

/// The Voronoi diagram of finite points, and how its construction ended
/// (checked by `Builder::accept`).
fn build_points(input: &[Point]) -> (Diagram, Outcome) {
    let (scale, points) = to_internal(input);
    let (diagram, site_of_input, _, outcome) = construct(&points, &[]);
    (finish::finish(diagram, &site_of_input, input, &[], scale), outcome)
}

/// Runs `beside` on a second thread while `here` runs on this one, and
/// returns both results. When no thread can be had (resource limits) both
/// run here, one after the other. A panic in `beside` is passed on.
pub(crate) fn run_beside<A: Send, B>(beside: impl FnOnce() -> A + Send, here: impl FnOnce() -> B) -> (A, B) {
    // Whichever side gets to it runs the task: the thread, or this one if
    // the thread could not start.
    let task = std::sync::Mutex::new(Some(beside));
    let take_and_run = || task.lock().ok().and_then(|mut t| t.take()).map(|f| f());
    std::thread::scope(|scope| {
        let handle = std::thread::Builder::new().spawn_scoped(scope, take_and_run).ok();
        let b = here();
        let a = handle.and_then(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))).or_else(take_and_run);
        (a.expect("the task ran on one of the two threads"), b)
    })
}

/// The power-of-two scale for `input` and the input in the construction's
/// coordinates (scaled, with `-0` made `+0`).
fn to_internal(input: &[Point]) -> (Scale, Vec<Point>) {
    let scale = Scale::for_coordinates(input.iter().flat_map(|p| [p.x, p.y]));
    (scale, input.iter().map(|p| p.scaled(scale.to_internal).canonical_zero()).collect())
}

/// How many times the construction starts over when a segment finds no
/// path (see [`construct_from`]).
const MAX_RESTARTS: usize = 16;

/// A segment that found no path in the last attempt of a construction.
#[derive(Clone, Copy, Debug)]
struct Stuck {
    /// Its first endpoint, as an index into the construction's points.
    endpoint: usize,
    /// It already went first in that attempt (restarting cannot help).
    inserted_first: bool,
}

/// How the construction ended.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Outcome {
    /// Times it started over.
    restarts: usize,
    /// It gave up: this segment found no path in the last attempt.
    stuck: Option<Stuck>,
}

#[cfg(feature = "fault-injection")]
thread_local! {
    static RESTART_BUDGET: std::cell::Cell<usize> = const { std::cell::Cell::new(MAX_RESTARTS) };
}

/// Sets how many times a construction on this thread may start over before
/// it gives up with [`ErrorKind::Internal`] (16 unless set; test builds with
/// the `fault-injection` feature only, to reach that error on purpose).
#[cfg(feature = "fault-injection")]
pub fn set_restart_budget(restarts: usize) {
    RESTART_BUDGET.with(|b| b.set(restarts));
}

fn restart_budget() -> usize {
    #[cfg(feature = "fault-injection")]
    return RESTART_BUDGET.with(|b| b.get());
    #[cfg(not(feature = "fault-injection"))]
    MAX_RESTARTS
}

/// Runs the insertions: every point, then every segment (given by the
/// indices of its two endpoints in `points`; distinct, non-crossing). Returns
/// the diagram in internal site ids, per input point the internal site it
/// became, and per segment its internal site.
fn construct(points: &[Point], segments: &[[usize; 2]]) -> (PointDiagram, Vec<SiteId>, Vec<SiteId>, Outcome) {
    construct_from(insert_points(points, segments.len()), points, segments)
}

/// The diagram of the points alone, ready for segments.
enum PointStage {
    /// Every point inserted: the diagram, and the site each point became.
    Inserted(PointDiagram, Vec<SiteId>),
    /// At most one distinct point: no segment is possible; done.
    Trivial(PointDiagram, Vec<SiteId>),
    /// All points on one line: built with the segments as a ladder.
    Collinear,
}

/// [`construct`] after its first stage, [`insert_points`].
///
/// Segments that share endpoints can form closed chains, and a closed chain
/// walls off its inside: no path of P4 crosses it. With numbers that lie
/// (fault injection; conceivably a near-degenerate input) a chain can end
/// up around a site that is outside it, and a later segment from that site
/// then finds no path. The construction then starts over with that segment
/// inserted before the others (it cannot be walled off before the chain is
/// closed), at most `MAX_RESTARTS` times. With sound numbers it never
/// happens; if it keeps happening (or the stuck segment already went
/// first), the construction gives up: the last attempt is returned with an
/// [`Outcome`] that tells [`Builder::build`] to discard it for an
/// [`ErrorKind::Internal`] error (none of the test suites, fault injection
/// included, gets there with the full budget).
fn construct_from(
    mut stage: PointStage,
    points: &[Point],
    segments: &[[usize; 2]],
) -> (PointDiagram, Vec<SiteId>, Vec<SiteId>, Outcome) {
    let budget = restart_budget();
    let mut first = Vec::new();
    loop {
        let (diagram, site_of, segment_sites, stuck) = insert_segments(stage, points, segments, &first);
        let outcome = match stuck {
            None => Outcome { restarts: first.len(), stuck: None },
            Some(k) if first.len() < budget && !first.contains(&k) => {
                first.push(k);
                stage = insert_points(points, segments.len());
                continue;
            }
            Some(k) => Outcome {
                restarts: first.len(),
                stuck: Some(Stuck { endpoint: segments[k][0], inserted_first: first.contains(&k) }),
            },
        };
        return (diagram, site_of, segment_sites, outcome);
    }
}

/// Inserts every point (with room for `segment_count` segments after them).
fn insert_points(points: &[Point], segment_count: usize) -> PointStage {
    let n = points.len();
    let mut site_of = vec![SiteId(NONE); n];
    let mut diagram = PointDiagram::new(n + segment_count);
    let order = points::insertion_order(points);
    let Some(&first) = order.first() else {
        return PointStage::Trivial(diagram, site_of);
    };
    let pa = points[first as usize];
    let Some(b_pos) = order.iter().position(|&i| points[i as usize] != pa) else {
        // one distinct point
        let s = diagram.add_lone_site(pa);
        site_of.iter_mut().for_each(|x| *x = s);
        return PointStage::Trivial(diagram, site_of);
    };
    let second = order[b_pos];
    let pb = points[second as usize];
    let third = order[b_pos + 1..]
        .iter()
        .copied()
        .find(|&i| orientation(pa, pb, points[i as usize]) != Orientation::Collinear);
    let Some(third) = third else {
        return PointStage::Collinear;
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
    PointStage::Inserted(diagram, site_of)
}

/// Inserts the segments into the diagram of the points; those listed in
/// `first_segments` go first, in that order. Also returns the first segment
/// that found no path.
fn insert_segments(
    stage: PointStage,
    points: &[Point],
    segments: &[[usize; 2]],
    first_segments: &[usize],
) -> (PointDiagram, Vec<SiteId>, Vec<SiteId>, Option<usize>) {
    let (mut diagram, site_of) = match stage {
        PointStage::Inserted(diagram, site_of) => (diagram, site_of),
        PointStage::Trivial(diagram, site_of) => return (diagram, site_of, Vec::new(), None),
        PointStage::Collinear => {
            let mut diagram = PointDiagram::new(points.len() + segments.len());
            let mut site_of = vec![SiteId(NONE); points.len()];
            let segment_sites = start_all_collinear(points, segments, &mut diagram, &mut site_of);
            return (diagram, site_of, segment_sites, None);
        }
    };
    // Segments go in the same order as points, by their midpoints: BRIO
    // rounds along a Hilbert curve (the result does not depend on it). The
    // curve keeps each insertion where the last one worked, in memory the
    // cache still holds; the random rounds keep the work near-linear where
    // segments are long against the gaps between them: inserted in sweep
    // order, each of n parallel segments would first take the cell of the
    // one before, which reaches across all the points (n parallel segments
    // of length n at unit spacing cost O(n^2) that way, O(n log n) in
    // random rounds).
    let midpoints: Vec<Point> = segments
        .iter()
        .map(|&[i, j]| {
            let (p, q) = (points[i], points[j]);
            Point::new(0.5 * p.x + 0.5 * q.x, 0.5 * p.y + 0.5 * q.y)
        })
        .collect();
    let mut segment_sites = vec![SiteId(NONE); segments.len()];
    let mut stuck = None;
    let by_midpoint = points::insertion_order(&midpoints);
    drop(midpoints);
    let rest = by_midpoint.into_iter().filter(|&k| !first_segments.contains(&(k as usize)));
    // Gather each segment's endpoint sites into insertion order first: the
    // loads are independent here and overlap, where inside the loop each
    // would be a cache miss waiting behind a whole insertion.
    let order: Vec<(u32, SiteId, SiteId)> = first_segments
        .iter()
        .map(|&k| k as u32)
        .chain(rest)
        .map(|k| {
            let [i, j] = segments[k as usize];
            (k, site_of[i], site_of[j])
        })
        .collect();
    for (k, a, b) in order {
        let k = k as usize;
        segment_sites[k] = diagram.insert_segment(a, b).unwrap_or_else(|e| {
            stuck = stuck.or(Some(k));
            e
        });
    }
    (diagram, site_of, segment_sites, stuck)
}

/// All points on one line (at least two distinct): sort along the line,
/// merge repeats, and lay out the ladder of parallel bisectors directly, with
/// each segment (which joins two consecutive points: nothing lies inside a
/// segment) as one more rung between its endpoints. Returns the segments'
/// sites.
fn start_all_collinear(
    points: &[Point],
    segments: &[[usize; 2]],
    diagram: &mut PointDiagram,
    site_of: &mut [SiteId],
) -> Vec<SiteId> {
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
    let between: Vec<usize> = segments.iter().map(|&[i, j]| chain_index[i].min(chain_index[j])).collect();
    let (ids, segment_sites) = diagram.start_collinear_with_segments(&chain, &between);
    for (i, s) in site_of.iter_mut().enumerate() {
        *s = ids[chain_index[i]];
    }
    segment_sites
}
