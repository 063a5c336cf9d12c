//! Polygons and polylines as input: each becomes a chain of segments, and
//! the rings of polygons are remembered so that the diagram can tell the
//! domain they bound (`query::domain`).

use super::builder::Builder;
use crate::error::{Error, ErrorKind};
use crate::geometry::Point;

/// One ring of a polygon as the builder keeps it: which polygon and ring
/// it is, and the input indices of its segments, in ring order.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct RingInput {
    pub polygon: usize,
    pub ring: usize,
    pub segments: std::ops::Range<usize>,
}

impl Builder {
    /// Adds a polygon: each ring a closed chain of points (the last joins
    /// the first; a repeated closing point is accepted), as segments.
    /// Returns, per ring, the input indices of the segments it made.
    ///
    /// The rings of all polygons bound the *domain* by the even-odd rule:
    /// their orientation does not matter, a ring inside a ring is a hole,
    /// islands in holes work, and several polygons may be added (see
    /// [`crate::Diagram::vertex_location`]). Repeated consecutive points are
    /// dropped. A ring with fewer than three distinct points, or a
    /// non-finite coordinate, is [`ErrorKind::InvalidPolygon`] /
    /// [`ErrorKind::InvalidCoordinate`] naming the polygon and the ring; the
    /// builder is then unchanged. Rings that cross themselves or each other
    /// are found by the build, as any crossing segments are
    /// ([`ErrorKind::Intersecting`], naming both segments, and the message
    /// the polygons and rings they belong to).
    /// Rings may touch at points, as OGC's valid polygons do: two squares
    /// sharing one corner, a checkerboard, a hole touching its outer ring at
    /// a corner or inside an edge, two holes touching. A ring touched
    /// inside an edge is cut there, exactly, at the touching vertex
    /// ([`Builder::build`]): the domain is the same.
    ///
    /// Rings may also share stretches (an edge or part of one: the polygons
    /// of a MultiPolygon along a common border, a spike that runs out and
    /// back along itself). By the even-odd rule two copies of a stretch
    /// cancel: the build cuts the rings at the ends of every shared stretch
    /// (input vertices, so nothing moves), drops the pieces that are equal
    /// in pairs, and the domain is that of the pieces left, exactly the
    /// even-odd region of the rings as given; two squares sharing an edge
    /// are their union rectangle, with the shared edge gone
    /// ([`BuildStats::cancelled_ring_pieces`](crate::BuildStats) counts the
    /// pieces dropped; the pieces are then numbered as with
    /// [`Builder::split_crossings`]).
    ///
    /// ```
    /// use segvoronoi::{Builder, Location};
    /// let mut b = Builder::new();
    /// // a square with a square hole
    /// let rings = b.add_polygon(&[
    ///     vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]],
    ///     vec![[4.0, 4.0], [4.0, 6.0], [6.0, 6.0], [6.0, 4.0]],
    /// ])?;
    /// assert_eq!(rings, vec![0..4, 4..8]);
    /// let d = b.build()?;
    /// assert!(d.has_domain());
    /// let inside = d.vertices().filter(|v| d.vertex_location(v.id) == Some(Location::Inside)).count();
    /// assert!(inside > 0);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn add_polygon<P: Into<Point> + Copy, R: AsRef<[P]>>(
        &mut self,
        rings: &[R],
    ) -> Result<Vec<std::ops::Range<usize>>, Error> {
        let polygon = self.polygons;
        let mut chains = Vec::with_capacity(rings.len());
        let mut dropped = 0;
        for (ring, points) in rings.iter().enumerate() {
            let points: Vec<Point> = points.as_ref().iter().map(|&p| p.into()).collect();
            let mut chain = distinct_chain(&points, |k| {
                let p = points[k];
                Error::new(
                    ErrorKind::InvalidCoordinate,
                    format!("polygon {polygon}, ring {ring}: point {k} has a non-finite coordinate ({}, {})", p.x, p.y),
                    vec![polygon, ring, k],
                )
            })?;
            let closing = chain.len() > 1 && chain.first() == chain.last();
            if closing {
                chain.pop();
            }
            // the conventional closing point is not counted as dropped (and
            // is subtracted last: `dropped` is unsigned)
            dropped += points.len() - chain.len() - usize::from(closing);
            if chain.len() < 3 {
                return Err(Error::new(
                    ErrorKind::InvalidPolygon,
                    format!("polygon {polygon}, ring {ring} has {} distinct points; a ring needs three", chain.len()),
                    vec![polygon, ring],
                ));
            }
            chains.push(chain);
        }
        let first = self.segment_count();
        let total: usize = chains.iter().map(Vec::len).sum();
        self.reserve_segments(total)?;
        let mut made = Vec::with_capacity(chains.len());
        let mut next = first;
        for (ring, chain) in chains.iter().enumerate() {
            let segments = next..next + chain.len();
            made.push(segments.clone());
            self.rings.push(RingInput { polygon, ring, segments });
            next += chain.len();
        }
        let closed = chains.iter().flat_map(|c| (0..c.len()).map(move |k| [c[k], c[(k + 1) % c.len()]]));
        // finite, distinct and within capacity: checked above
        self.add_segments(closed).expect("checked points");
        self.polygons += 1;
        self.dropped_chain_points += dropped;
        Ok(made)
    }

    /// Adds an open chain of points as segments (repeated consecutive
    /// points dropped) and returns their input indices. A polyline is an
    /// obstacle, like any segment: it does not bound the domain. Fewer than
    /// two distinct points add nothing.
    pub fn add_polyline<P: Into<Point> + Copy>(&mut self, points: &[P]) -> Result<std::ops::Range<usize>, Error> {
        let points: Vec<Point> = points.iter().map(|&p| p.into()).collect();
        let chain = distinct_chain(&points, |k| {
            let p = points[k];
            Error::new(
                ErrorKind::InvalidCoordinate,
                format!("polyline point {k} has a non-finite coordinate ({}, {})", p.x, p.y),
                vec![k],
            )
        })?;
        let made = self.add_segments(chain.windows(2).map(|w| [w[0], w[1]]))?;
        self.dropped_chain_points += points.len() - chain.len();
        Ok(made)
    }
}

/// The points with repeated consecutive ones dropped, or the error for the
/// first non-finite one.
fn distinct_chain(points: &[Point], non_finite: impl Fn(usize) -> Error) -> Result<Vec<Point>, Error> {
    let mut chain: Vec<Point> = Vec::with_capacity(points.len());
    for (k, &p) in points.iter().enumerate() {
        if !p.is_finite() {
            return Err(non_finite(k));
        }
        if chain.last() != Some(&p) {
            chain.push(p);
        }
    }
    Ok(chain)
}

/// The rings over the pieces the diagram was built from: a ring whose
/// segments were cut at input vertices inside them (`BuildStats::
/// split_at_vertices`) runs through the same points with one more corner
/// per cut, so each input segment's range becomes that of its pieces (in
/// its direction, as the pieces are numbered). Without cuts, the rings.
pub(crate) fn rings_over_pieces(diagram: &crate::Diagram, rings: &[RingInput]) -> Vec<RingInput> {
    rings
        .iter()
        .map(|r| {
            let first = diagram.pieces_of_input(r.segments.start).next();
            let last = diagram.pieces_of_input(r.segments.end - 1).last();
            let segments = match (first, last) {
                (Some(first), Some(last)) => first..last + 1,
                _ => r.segments.clone(), // (a ring has no zero-length segment)
            };
            RingInput { polygon: r.polygon, ring: r.ring, segments }
        })
        .collect()
}

/// Per input segment (`segments` of them), whether a ring of `rings` made
/// it; empty when there are no rings. Ring segments may share stretches,
/// which cancel (`construct::shared_stretches`).
pub(crate) fn ring_segments(rings: &[RingInput], segments: usize) -> Vec<bool> {
    if rings.is_empty() {
        return Vec::new();
    }
    let mut ring = vec![false; segments];
    for j in rings.iter().flat_map(|r| r.segments.clone()) {
        ring[j] = true;
    }
    ring
}

/// An input error with the polygons and rings of the segments it names
/// added to its message (a ring that crosses itself or another ring, or
/// a ring segment that an obstacle overlaps).
pub(crate) fn name_rings(error: Error, rings: &[RingInput]) -> Error {
    if error.kind() != ErrorKind::Intersecting || rings.is_empty() {
        return error;
    }
    let ring_of = |j: usize| rings.iter().find(|r| r.segments.contains(&j));
    let named: Vec<String> = error
        .indices()
        .iter()
        .filter_map(|&j| ring_of(j).map(|r| (j, r)))
        .map(|(j, r)| format!("segment {j} is in polygon {}, ring {}", r.polygon, r.ring))
        .collect();
    if named.is_empty() {
        return error;
    }
    let message = format!("{} ({})", error.message(), named.join("; "));
    Error::new(error.kind(), message, error.indices().to_vec())
}
