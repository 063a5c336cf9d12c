//! The public entry: [`Builder`] collects points and segments (its adders
//! check each coordinate and the size limit, all or none) and builds their
//! diagram (`construct::diagram_of`). Polygons and polylines become chains
//! of segments here too; the rings of polygons are remembered
//! (`polygon_input`) so that the diagram can tell the domain they bound.

use crate::diagram::Diagram;
use crate::error::{Error, ErrorKind};
use crate::geometry::arc::straight_within_rounding;
use crate::geometry::{CircularArc, Point};

use super::polygon_input::{name_rings, ChainPiece, RingInput};

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
    /// Circular arcs (`add_arc`), each with its own input index.
    arcs: Vec<CircularArc>,
    /// The rings of the polygons added (`polygon_input`), which bound the
    /// domain, and how many polygons there are.
    pub(super) rings: Vec<RingInput>,
    pub(super) polygons: usize,
    /// Points of polygons and polylines dropped because they repeated the
    /// point before them (`BuildStats::dropped_chain_points`).
    pub(super) dropped_chain_points: usize,
    /// Whether `build` splits crossings first (`split_crossings`).
    split_crossings: bool,
    /// Most threads a build runs at once (`threads`); 0 for the cores.
    threads: usize,
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

    /// Number of circular arcs added so far.
    pub fn arc_count(&self) -> usize {
        self.arcs.len()
    }

    /// The arc with input index `index`, as added; `None` past the end.
    pub fn arc(&self, index: usize) -> Option<CircularArc> {
        self.arcs.get(index).copied()
    }

    /// Adds a circular arc and returns its input index (the number of arcs
    /// added before it; arcs are numbered apart from points and segments).
    /// Its endpoints are input points like a segment's, shared exactly with
    /// the segments and arcs that continue it.
    ///
    /// Arcs may share endpoints with any number of segments and arcs;
    /// whether they cross, overlap or touch inside is checked by
    /// [`Builder::build`]. Fails with [`ErrorKind::TooLarge`] when its
    /// endpoints would pass [`MAX_POINTS`], and with
    /// [`ErrorKind::InvalidArc`] for an arc straight to within the
    /// rounding of its centre (a minor arc whose radius is over 2^40 times
    /// its chord, a bulge below about 2^-42: add it as a segment); the
    /// builder is then unchanged.
    ///
    /// ```
    /// use segvoronoi::{Builder, CircularArc, ErrorKind};
    /// let mut b = Builder::new();
    /// let flat = CircularArc::from_bulge([0.0, 0.0], [10.0, 0.0], 1e-17)?;
    /// assert_eq!(b.add_arc(flat).unwrap_err().kind(), ErrorKind::InvalidArc);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    ///
    /// ```
    /// use segvoronoi::{Builder, CircularArc, Site};
    /// let mut b = Builder::new();
    /// // a slot: two half circles joined by two segments
    /// b.add_segment([[0.0, 0.0], [4.0, 0.0]])?;
    /// b.add_arc(CircularArc::from_bulge([4.0, 0.0], [4.0, 2.0], 1.0)?)?;
    /// b.add_segment([[4.0, 2.0], [0.0, 2.0]])?;
    /// b.add_arc(CircularArc::from_bulge([0.0, 2.0], [0.0, 0.0], 1.0)?)?;
    /// let d = b.build()?;
    /// let arc = d.site_of_arc(1).unwrap();
    /// assert!(matches!(d.site(arc), Some(Site::Arc(_))));
    /// assert!(d.validate().is_ok());
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn add_arc(&mut self, arc: CircularArc) -> Result<usize, Error> {
        if arc.is_straight_within_rounding() {
            let (a, b) = (arc.start(), arc.end());
            return Err(Error::new(
                ErrorKind::InvalidArc,
                format!(
                    "arc ({:?}, {:?}) - ({:?}, {:?}) is straight to within the rounding of its centre (its radius {:e} is \
                     over 2^40 times its chord {:e}); add it as a segment",
                    a.x,
                    a.y,
                    b.x,
                    b.y,
                    arc.radius(),
                    a.distance(b)
                ),
                Vec::new(),
            ));
        }
        let endpoints = self.points.len().saturating_add(2 * (self.segments.len() + self.arcs.len() + 1));
        check_capacity(endpoints)?;
        self.arcs.try_reserve(1).map_err(|_| out_of_memory("arcs", 1, std::mem::size_of::<CircularArc>()))?;
        self.arcs.push(arc);
        Ok(self.arcs.len() - 1)
    }

    /// Adds a chain of vertices with a bulge each, as DXF's LWPOLYLINE
    /// holds it: the piece from vertex `k` to vertex `k + 1` is a segment
    /// where `bulge` is 0 and an arc with that bulge otherwise; `closed`
    /// joins the last vertex to the first with the last bulge. Repeated
    /// consecutive vertices are dropped (with their piece). Returns what
    /// each piece became, in order. A polyline is an obstacle: it does not
    /// bound the domain.
    ///
    /// A piece whose bulge is so small that its arc is straight to within
    /// the rounding of its centre (below about 2^-42, as
    /// [`Builder::add_arc`] refuses) is a segment.
    ///
    /// Errors, with nothing added: a non-finite coordinate or bulge
    /// ([`ErrorKind::InvalidCoordinate`], naming the vertex), or
    /// [`ErrorKind::TooLarge`].
    ///
    /// ```
    /// use segvoronoi::{Builder, ChainPiece};
    /// let mut b = Builder::new();
    /// // a rounded rectangle's outline: four sides, four quarter arcs
    /// let q = (std::f64::consts::PI / 8.0).tan();
    /// let made = b.add_bulged_polyline(
    ///     &[([1.0, 0.0], 0.0), ([3.0, 0.0], q), ([4.0, 1.0], 0.0), ([4.0, 2.0], q),
    ///       ([3.0, 3.0], 0.0), ([1.0, 3.0], q), ([0.0, 2.0], 0.0), ([0.0, 1.0], q)],
    ///     true,
    /// )?;
    /// assert_eq!(made.len(), 8);
    /// assert_eq!(made[1], ChainPiece::Arc(0));
    /// assert_eq!((b.segment_count(), b.arc_count()), (4, 4));
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn add_bulged_polyline<P: Into<Point> + Copy>(
        &mut self,
        vertices: &[(P, f64)],
        closed: bool,
    ) -> Result<Vec<ChainPiece>, Error> {
        let mut chain: Vec<(Point, f64)> = Vec::new();
        chain
            .try_reserve(vertices.len())
            .map_err(|_| out_of_memory("polyline vertices", vertices.len(), std::mem::size_of::<(Point, f64)>()))?;
        for (k, &(p, bulge)) in vertices.iter().enumerate() {
            let p: Point = p.into();
            if !p.is_finite() || !bulge.is_finite() {
                return Err(Error::new(
                    ErrorKind::InvalidCoordinate,
                    format!("polyline vertex {k} has a non-finite coordinate or bulge ({}, {}) bulge {bulge}", p.x, p.y),
                    vec![k],
                ));
            }
            match chain.last_mut() {
                // a repeat: its piece has no length; the bulge after it counts
                Some(last) if last.0 == p => last.1 = bulge,
                _ => chain.push((p, bulge)),
            }
        }
        if closed && chain.len() > 1 && chain.first().map(|f| f.0) == chain.last().map(|l| l.0) {
            chain.pop();
        }
        let pieces = if closed && chain.len() > 2 { chain.len() } else { chain.len().saturating_sub(1) };
        straighten(&mut chain, pieces);
        let mut made = Vec::new();
        made.try_reserve(pieces).map_err(|_| out_of_memory("polyline pieces", pieces, std::mem::size_of::<ChainPiece>()))?;
        let (segments, arcs) = (self.segments.len(), self.arcs.len());
        let dropped = vertices.len() - chain.len();
        for k in 0..pieces {
            let ((p, bulge), (q, _)) = (chain[k], chain[(k + 1) % chain.len()]);
            let piece = if bulge == 0.0 {
                self.add_segment([p, q]).map(ChainPiece::Segment)
            } else {
                CircularArc::from_bulge(p, q, bulge)
                    .map_err(|e| Error::new(e.kind(), format!("polyline vertex {k}: {}", e.message()), vec![k]))
                    .and_then(|arc| self.add_arc(arc).map(ChainPiece::Arc))
            };
            match piece {
                Ok(piece) => made.push(piece),
                Err(e) => {
                    self.segments.truncate(segments);
                    self.arcs.truncate(arcs);
                    return Err(e);
                }
            }
        }
        self.dropped_chain_points += dropped;
        Ok(made)
    }

    /// The point with input index `index`, as added; `None` past the end.
    pub fn point(&self, index: usize) -> Option<Point> {
        self.points.get(index).copied()
    }

    /// The segment with input index `index` (also those that polygons and
    /// polylines made), as added; `None` past the end. With the indices an
    /// error names, this says where the offending segments are.
    pub fn segment(&self, index: usize) -> Option<[Point; 2]> {
        self.segments.get(index).copied()
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
        append_checked(&mut self.segments, segments, check_segment, |n| {
            check_capacity(points.saturating_add(n.saturating_mul(2)))
        })
    }

    /// Makes room for `additional` more points, or fails with
    /// [`ErrorKind::TooLarge`] (the builder unchanged) when the points and
    /// segment endpoints together would exceed [`MAX_POINTS`], or with
    /// [`ErrorKind::OutOfMemory`] when the room cannot be allocated (the
    /// count comes from the caller, so this must not abort the process).
    pub fn reserve_points(&mut self, additional: usize) -> Result<(), Error> {
        check_capacity(self.points.len().saturating_add(additional).saturating_add(2 * self.segments.len()))?;
        self.points.try_reserve(additional).map_err(|_| out_of_memory("points", additional, std::mem::size_of::<Point>()))
    }

    /// Makes room for `additional` more segments, or fails with
    /// [`ErrorKind::TooLarge`] (the builder unchanged) when the points and
    /// segment endpoints together would exceed [`MAX_POINTS`], or with
    /// [`ErrorKind::OutOfMemory`] when the room cannot be allocated.
    pub fn reserve_segments(&mut self, additional: usize) -> Result<(), Error> {
        let points = self.points.len().saturating_add(self.segments.len().saturating_add(additional).saturating_mul(2));
        check_capacity(points)?;
        self.segments
            .try_reserve(additional)
            .map_err(|_| out_of_memory("segments", additional, std::mem::size_of::<[Point; 2]>()))
    }

    /// Whether [`Builder::build`] splits the input where it crosses itself
    /// (off by default: crossings are then an error, naming both segments).
    ///
    /// When on, crossings, collinear overlaps, endpoints inside segments
    /// (T-junctions) and points inside segments are made shared endpoints
    /// before the build, by iterated snap rounding to a grid of pixels
    /// 2^-46 of the largest coordinate's power of two wide. The diagram is
    /// then that of the *pieces*: each a part of one or more input segments,
    /// within [`Diagram::max_split_displacement`] of each of them (at most
    /// a pixel per round of snapping, [`BuildStats::snap_rounds`]).
    /// Segments and points that meet nothing keep their exact coordinates.
    /// [`Diagram::pieces_of_input`] and [`Diagram::inputs_of_piece`] map
    /// between the two, so attributes of the input segments can be carried
    /// to the pieces' cells; [`Diagram::site_of_segment`] and
    /// [`Diagram::segment_input_index`] then speak of piece indices.
    /// Polygons split the same way: the domain is the even-odd region of
    /// the split rings. [`BuildStats`] counts the crossings, overlaps and
    /// touchings found and the pieces.
    ///
    /// Circular arcs are split too (crossing, touching or overlapping
    /// segments, arcs and points): an arc is cut where something meets it
    /// into arcs through the pixel centres, each a hair flatter than its
    /// circle, and coinciding pieces merge. As for segments,
    /// [`Diagram::site_of_arc`] and [`Diagram::arc_input_index`] then speak
    /// of arc pieces, and [`Diagram::arc_pieces_of_input`] and
    /// [`Diagram::inputs_of_arc_piece`] map between the input arcs and
    /// them; [`BuildStats`] counts a pair with an arc once however often it
    /// meets. Polygons with arcs (rings of [`Builder::add_bulged_polygon`],
    /// and plain rings beside arcs) split the same way: the domain is the
    /// even-odd region of the split rings, arcs and segments pieces alike,
    /// and a shell and a hole that cross, or rings that share a stretch,
    /// bound what the even-odd rule says. Where the arcs'
    /// construction cannot place the pieces (an end a hair from another
    /// piece, as the cuts put them), the build is refused with
    /// [`ErrorKind::Internal`] by its own checks, never answered wrong.
    ///
    /// ```
    /// use segvoronoi::{Builder, CircularArc};
    /// let mut b = Builder::new();
    /// // a half circle and a line across it
    /// b.add_arc(CircularArc::from_bulge([0.0, 0.0], [4.0, 0.0], 1.0)?)?;
    /// b.add_segment([[2.0, 1.0], [2.0, -3.0]])?;
    /// assert!(b.build().is_err()); // they cross
    /// let d = b.split_crossings(true).build()?;
    /// assert_eq!((d.stats().crossings, d.arc_site_count()), (1, 2));
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    ///
    /// ```
    /// use segvoronoi::Builder;
    /// let mut b = Builder::new();
    /// b.add_segments([[[0.0, 0.0], [2.0, 2.0]], [[0.0, 2.0], [2.0, 0.0]]])?;
    /// assert!(b.build().is_err()); // they cross
    /// let d = b.split_crossings(true).build()?;
    /// assert_eq!((d.stats().crossings, d.piece_count()), (1, 4));
    /// assert_eq!(d.pieces_of_input(0).collect::<Vec<_>>(), vec![0, 1]);
    /// assert_eq!(d.inputs_of_piece(3).collect::<Vec<_>>(), vec![1]);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    ///
    /// [`Diagram::max_split_displacement`]: crate::Diagram::max_split_displacement
    /// [`Diagram::pieces_of_input`]: crate::Diagram::pieces_of_input
    /// [`Diagram::inputs_of_piece`]: crate::Diagram::inputs_of_piece
    /// [`Diagram::site_of_segment`]: crate::Diagram::site_of_segment
    /// [`Diagram::segment_input_index`]: crate::Diagram::segment_input_index
    /// [`Diagram::arc_input_index`]: crate::Diagram::arc_input_index
    /// [`Diagram::site_of_arc`]: crate::Diagram::site_of_arc
    /// [`Diagram::arc_pieces_of_input`]: crate::Diagram::arc_pieces_of_input
    /// [`Diagram::inputs_of_arc_piece`]: crate::Diagram::inputs_of_arc_piece
    /// [`ErrorKind::Internal`]: crate::ErrorKind::Internal
    /// [`BuildStats`]: crate::BuildStats
    /// [`BuildStats::snap_rounds`]: crate::BuildStats::snap_rounds
    pub fn split_crossings(&mut self, on: bool) -> &mut Builder {
        self.split_crossings = on;
        self
    }

    /// At most `n` threads running at once in [`build`](Self::build), the
    /// calling one included; `0` (the default) for as many as the machine
    /// has cores. The diagram is the same for every `n`: the same sites
    /// and edges (the canonical topology text,
    /// [`TopologyOptions::canonical_cuts`](crate::TopologyOptions::canonical_cuts),
    /// byte for byte), every vertex at the same position, bit for bit;
    /// vertices and edges may be numbered otherwise, and a degenerate
    /// vertex (four sites or more on one empty circle) cut into its
    /// degree-3 parts another way (the canonical text cuts it one way).
    ///
    /// With a second thread, a build of 60,000 sites or more without arcs
    /// runs in two halves, cut at a vertical line, each built on its own
    /// thread and then glued (about 1.6 to 1.8 times faster on two cores);
    /// with four threads or more, each half of 60,000 sites or more is
    /// built in halves in turn (vertical strips, glued pairwise: four
    /// strips with four threads, eight with eight). Smaller builds and
    /// arcs use a second thread for parts of their work (the input check
    /// beside the point insertions, the sort of the insertion order, the
    /// check of the arcs' vertices). `threads(1)` starts none, for callers
    /// that run many builds on threads of their own.
    ///
    /// ```
    /// use segvoronoi::{Builder, TopologyOptions};
    /// let mut b = Builder::new();
    /// b.add_segment([[0.0, 0.0], [1.0, 0.0]])?;
    /// b.add_point([0.5, 1.0])?;
    /// let one = b.threads(1).build()?.topology(TopologyOptions::default());
    /// let all = b.threads(0).build()?.topology(TopologyOptions::default());
    /// assert_eq!(one, all);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn threads(&mut self, n: usize) -> &mut Builder {
        self.threads = n;
        self
    }

    /// Builds the diagram. The builder is not consumed: more points may be
    /// added and the diagram built again.
    ///
    /// For 100,000 points or more, part of the work (sorting the insertion
    /// order) runs on a second, short-lived thread; the result is the same.
    ///
    /// With segments, the input is checked first: segments that cross or
    /// overlap give [`ErrorKind::Intersecting`] naming both input indices
    /// (but polygon rings may share stretches, which cancel: see
    /// [`Builder::add_polygon`]).
    /// An input vertex (a segment's endpoint, a zero-length segment or an
    /// isolated point) inside another segment is fine: that segment is
    /// split there, exactly (the vertex is the cut point, nothing moves),
    /// and the diagram is that of the pieces, numbered as with
    /// [`Builder::split_crossings`] ([`Diagram::pieces_of_input`],
    /// [`Diagram::inputs_of_piece`]; [`Diagram::site_of_segment`] and
    /// [`Diagram::segment_input_index`] then speak of pieces, and
    /// [`BuildStats::split_at_vertices`] counts the cuts). A polygon's ring
    /// cut so is still that ring, with one more corner: a hole touching
    /// its shell, or rings touching at a point, bound the same domain as
    /// the OGC polygon.
    ///
    /// ```
    /// use segvoronoi::{Builder, Location, Point};
    /// let mut b = Builder::new();
    /// // a hole touching its shell at (0, 5), inside the shell's edge 3
    /// b.add_polygon(&[
    ///     vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]],
    ///     vec![[0.0, 5.0], [3.0, 4.0], [3.0, 6.0]],
    /// ])?;
    /// let d = b.build()?;
    /// assert_eq!(d.stats().split_at_vertices, 1);
    /// assert_eq!(d.pieces_of_input(3).collect::<Vec<_>>(), vec![3, 4]);
    /// assert_eq!(d.locate_point(Point::new(2.0, 5.0)), Some(Location::Outside)); // in the hole
    /// assert_eq!(d.locate_point(Point::new(1.0, 2.0)), Some(Location::Inside));
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    ///
    /// [`Diagram::pieces_of_input`]: crate::Diagram::pieces_of_input
    /// [`Diagram::inputs_of_piece`]: crate::Diagram::inputs_of_piece
    /// [`Diagram::site_of_segment`]: crate::Diagram::site_of_segment
    /// [`Diagram::segment_input_index`]: crate::Diagram::segment_input_index
    /// [`BuildStats::split_at_vertices`]: crate::BuildStats::split_at_vertices
    ///
    /// [`Builder::check`] runs the input check alone.
    ///
    /// A diagram that could not be completed is never returned: that is
    /// [`ErrorKind::Internal`], a bug in segvoronoi (none is known; with
    /// sound arithmetic it does not happen), with a message saying what
    /// failed. An input whose coordinates span more than the exact range
    /// (its largest magnitude over `2^480` times its smallest nonzero
    /// magnitude or difference) is built and its result checked; when it
    /// does not check out the error is [`ErrorKind::UnsupportedRange`]
    /// instead. A build whose estimated peak memory (about 256 bytes a
    /// point and 1 KiB a segment) the allocator refuses is not started:
    /// [`ErrorKind::OutOfMemory`] (under a memory limit such as `ulimit -v`;
    /// see `construct/headroom.rs` for what that cannot cover). The builder
    /// stays as it was.
    pub fn build(&self) -> Result<Diagram, Error> {
        super::headroom::ensure_headroom(self.points.len(), self.segments.len())?;
        super::threads::with_threads(self.threads, || {
            super::exact_range::checked_build(&self.points, &self.segments, || self.build_at_any_span())
        })
    }

    /// `build` without the check of inputs beyond the exact range.
    fn build_at_any_span(&self) -> Result<Diagram, Error> {
        // (rings of `add_bulged_polygon` are split with the arcs' rings, as
        // chains of pieces, even where every bulge was zero)
        let bulged_rings = self.rings.iter().any(|r| r.pieces.is_some());
        if !self.arcs.is_empty() || (self.split_crossings && bulged_rings) {
            return super::with_arcs::diagram_with_arcs(
                &self.points,
                &self.segments,
                &self.arcs,
                self.split_crossings,
                &self.rings,
            );
        }
        if self.split_crossings && !self.segments.is_empty() {
            let mut diagram = super::split::diagram_of_split(&self.points, &self.segments, &self.rings)?;
            diagram.stats.dropped_chain_points = self.dropped_chain_points;
            return Ok(diagram);
        }
        let name = |e| name_rings(e, &self.rings);
        let mut diagram = super::diagram_of(&self.points, &self.segments, &self.rings).map_err(name)?;
        diagram.stats.dropped_chain_points = self.dropped_chain_points;
        Ok(diagram)
    }

    /// Checks the input as [`Builder::build`] does first, without building:
    /// `Ok` when no two segments cross or overlap (segments may share
    /// endpoints, any number at one point, and an input vertex inside a
    /// segment only splits it), else the same [`ErrorKind::Intersecting`]
    /// error `build` would give,
    /// naming both input indices. When several conflicts exist it names the
    /// one whose first common point (by `x`, then `y`) is lexicographically
    /// smallest, whatever the input order.
    ///
    /// The check is exact and takes O(n log n) expected time for n segments
    /// and points, whatever their shape (a sweep). Polygon rings that share
    /// a stretch pass, as in `build` (they cancel there, see
    /// [`Builder::add_polygon`]); an obstacle that overlaps a ring, or
    /// another obstacle, does not.
    ///
    /// ```
    /// use segvoronoi::{Builder, ErrorKind};
    ///
    /// let mut builder = Builder::new();
    /// builder.add_segments([[[0.0, 0.0], [4.0, 0.0]], [[4.0, 0.0], [4.0, 4.0]]])?;
    /// assert!(builder.check().is_ok()); // a common endpoint is fine
    /// builder.add_segment([[2.0, -1.0], [2.0, 1.0]])?;
    /// let error = builder.check().unwrap_err();
    /// assert_eq!(error.kind(), ErrorKind::Intersecting);
    /// assert_eq!(error.indices(), [0, 2]);
    /// assert_eq!(error.message(), "segments 0 and 2 cross");
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn check(&self) -> Result<(), Error> {
        if !self.arcs.is_empty() {
            super::input_check::arcs::check_arcs(&self.points, &self.segments, &self.arcs)?;
            // with arcs, rings share no stretches (`with_arcs`): checked
            // as the build checks them, as obstacles' segments
            return super::check_input(&self.points, &self.segments, &[]).map_err(|e| name_rings(e, &self.rings));
        }
        super::check_input(&self.points, &self.segments, &self.rings).map_err(|e| name_rings(e, &self.rings))
    }

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
            self.rings.push(RingInput { polygon, ring, segments, pieces: None });
            next += chain.len();
        }
        let closed = chains.iter().flat_map(|c| (0..c.len()).map(move |k| [c[k], c[(k + 1) % c.len()]]));
        // finite, distinct and within capacity: checked above
        self.add_segments(closed).expect("checked points");
        self.polygons += 1;
        self.dropped_chain_points += dropped;
        Ok(made)
    }

    /// Adds a polygon whose rings are closed chains of segments and
    /// circular arcs, as DXF's closed LWPOLYLINE holds them: each ring a
    /// list of vertices with a bulge each, the piece from vertex `k` to
    /// vertex `k + 1` (the last to the first) a segment where the bulge is
    /// 0 and otherwise an arc with that bulge (`tan` of a quarter of its
    /// signed sweep, positive counter-clockwise; see
    /// [`CircularArc::from_bulge`]). Returns, per ring, what each piece
    /// became, in ring order.
    ///
    /// The rings bound the domain by the even-odd rule, as those of
    /// [`Builder::add_polygon`] do (and with them: plain and bulged rings
    /// may be mixed); the domain's location, medial axis and offsets then
    /// follow the arcs. Repeated consecutive vertices are dropped (with
    /// their piece), and a repeated closing vertex too.
    ///
    /// Errors, with nothing added, naming the polygon, the ring and the
    /// vertex: a non-finite coordinate or bulge
    /// ([`ErrorKind::InvalidCoordinate`]); a ring of fewer than three
    /// distinct vertices, unless it has two and an arc between them
    /// ([`ErrorKind::InvalidPolygon`]); a bulge that makes no arc
    /// ([`ErrorKind::InvalidArc`]); [`ErrorKind::TooLarge`]. Rings with arcs
    /// may touch others only at points, and share no stretches with them
    /// (an overlap is [`ErrorKind::Intersecting`] at build time), unless
    /// [`Builder::split_crossings`] cuts them where they meet. A piece
    /// whose bulge is so small that its arc is straight to within the
    /// rounding of its centre (below about 2^-42, as [`Builder::add_arc`]
    /// refuses) is a segment.
    ///
    /// ```
    /// use segvoronoi::{Builder, ChainPiece, Location, Point};
    /// let mut b = Builder::new();
    /// let q = (std::f64::consts::PI / 8.0).tan(); // a quarter turn
    /// // a 4 × 3 rounded rectangle (corner radius 1) with a round hole
    /// let made = b.add_bulged_polygon(&[
    ///     vec![([1.0, 0.0], 0.0), ([3.0, 0.0], q), ([4.0, 1.0], 0.0), ([4.0, 2.0], q),
    ///          ([3.0, 3.0], 0.0), ([1.0, 3.0], q), ([0.0, 2.0], 0.0), ([0.0, 1.0], q)],
    ///     vec![([1.5, 1.5], 1.0), ([2.5, 1.5], 1.0)], // two half circles
    /// ])?;
    /// assert_eq!(made[1], vec![ChainPiece::Arc(4), ChainPiece::Arc(5)]);
    /// let d = b.build()?;
    /// assert_eq!(d.locate_point(Point::new(0.2, 0.2)), Some(Location::Outside)); // cut off by the corner arc
    /// assert_eq!(d.locate_point(Point::new(0.5, 1.5)), Some(Location::Inside));
    /// assert_eq!(d.locate_point(Point::new(2.0, 1.5)), Some(Location::Outside)); // in the hole
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn add_bulged_polygon<P: Into<Point> + Copy, R: AsRef<[(P, f64)]>>(
        &mut self,
        rings: &[R],
    ) -> Result<Vec<Vec<ChainPiece>>, Error> {
        let polygon = self.polygons;
        // validate everything before adding anything
        let mut chains: Vec<Vec<(Point, f64)>> = Vec::with_capacity(rings.len());
        let mut dropped = 0;
        for (ring, vertices) in rings.iter().enumerate() {
            let vertices = vertices.as_ref();
            let chain = bulged_ring(polygon, ring, vertices)?;
            dropped += vertices.len() - chain.len();
            chains.push(chain);
        }
        let (segments, arcs, points) = (self.segments.len(), self.arcs.len(), self.points.len());
        let undo = |b: &mut Builder| {
            b.segments.truncate(segments);
            b.arcs.truncate(arcs);
            b.points.truncate(points);
        };
        let mut made = Vec::with_capacity(chains.len());
        for (ring, chain) in chains.iter().enumerate() {
            let n = chain.len();
            let mut pieces = Vec::with_capacity(n);
            for k in 0..n {
                let ((p, bulge), (q, _)) = (chain[k], chain[(k + 1) % n]);
                let piece = if bulge == 0.0 {
                    self.add_segment([p, q]).map(ChainPiece::Segment)
                } else {
                    CircularArc::from_bulge(p, q, bulge)
                        .map_err(|e| {
                            Error::new(
                                e.kind(),
                                format!("polygon {polygon}, ring {ring}, vertex {k}: {}", e.message()),
                                vec![polygon, ring, k],
                            )
                        })
                        .and_then(|arc| self.add_arc(arc).map(ChainPiece::Arc))
                };
                match piece {
                    Ok(piece) => pieces.push(piece),
                    Err(e) => {
                        undo(self);
                        return Err(e);
                    }
                }
            }
            made.push(pieces);
        }
        let first = self.segment_count();
        for (ring, pieces) in made.iter().enumerate() {
            self.rings.push(RingInput { polygon, ring, segments: first..first, pieces: Some(pieces.clone()) });
        }
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

/// The vertices of ring `ring` of polygon `polygon` (`add_bulged_polygon`)
/// with repeated consecutive ones dropped (the bulge after a repeat
/// counts) and a repeated closing vertex too, or the error naming the
/// vertex or ring.
fn bulged_ring<P: Into<Point> + Copy>(polygon: usize, ring: usize, vertices: &[(P, f64)]) -> Result<Vec<(Point, f64)>, Error> {
    let mut chain: Vec<(Point, f64)> = Vec::new();
    chain.try_reserve(vertices.len()).map_err(|_| out_of_memory("ring vertices", vertices.len(), 24))?;
    for (k, &(p, bulge)) in vertices.iter().enumerate() {
        let p: Point = p.into();
        if !p.is_finite() || !bulge.is_finite() {
            return Err(Error::new(
                ErrorKind::InvalidCoordinate,
                format!(
                    "polygon {polygon}, ring {ring}: vertex {k} has a non-finite coordinate or bulge ({}, {}) bulge {bulge}",
                    p.x, p.y
                ),
                vec![polygon, ring, k],
            ));
        }
        match chain.last_mut() {
            Some(last) if last.0 == p => last.1 = bulge,
            _ => chain.push((p, bulge)),
        }
    }
    if chain.len() > 1 && chain.first().map(|f| f.0) == chain.last().map(|l| l.0) {
        // the closing vertex repeats the first: its bulge is the last piece's
        let (_, bulge) = chain.pop().expect("two or more");
        if let Some(last) = chain.last_mut() {
            if last.1 == 0.0 {
                last.1 = bulge;
            }
        }
    }
    let pieces = chain.len();
    straighten(&mut chain, pieces);
    let arcs = chain.iter().filter(|(_, b)| *b != 0.0).count();
    // two vertices close a ring with an arc between them (a half circle
    // and its diameter, a circle as two halves); one never does
    if chain.len() < 2 || (chain.len() == 2 && arcs == 0) {
        return Err(Error::new(
            ErrorKind::InvalidPolygon,
            format!(
                "polygon {polygon}, ring {ring} has {} distinct vertices and {arcs} arcs; a ring needs three vertices, \
                 or two and an arc",
                chain.len()
            ),
            vec![polygon, ring],
        ));
    }
    Ok(chain)
}

/// The first `pieces` bulges of a chain (piece `k` from vertex `k` to the
/// next, around) set to zero where their arc is straight to within the
/// rounding of its centre (`straight_within_rounding`: a DXF bulge of
/// 1e-17): those pieces are segments.
fn straighten(chain: &mut [(Point, f64)], pieces: usize) {
    for (_, bulge) in chain.iter_mut().take(pieces) {
        if *bulge != 0.0 && straight_within_rounding(*bulge) {
            *bulge = 0.0;
        }
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

fn out_of_memory(what: &str, count: usize, size: usize) -> Error {
    let bytes = count.saturating_mul(size);
    Error::new(ErrorKind::OutOfMemory, format!("out of memory: no room for {count} more {what} ({bytes} bytes)"), Vec::new())
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
