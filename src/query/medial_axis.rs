//! The medial axis: the Voronoi edges inside the domain that are not
//! separators, as a graph of chains (maximal paths through vertices where
//! exactly two of its edges meet), each a list of exact pieces with the
//! clearance along them; and the largest disk inside the domain.
//!
//! Without a domain (no polygon was added) the chains cover every edge that
//! is not a separator, rays included: the ordinary segment Voronoi diagram
//! as a graph.

use crate::diagram::{Diagram, EdgeId, HalfEdgeId, SiteId, VertexId, NONE};
use crate::geometry::Point;
use crate::query::{EdgeEnd, EdgeShape, HalfEdge, Location};

/// One edge of the medial axis, walked in the chain's direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Piece {
    /// The Voronoi edge.
    pub edge: EdgeId,
    /// `true` when the chain walks the edge from its `ends[1]` to `ends[0]`.
    pub reversed: bool,
    /// Where the piece starts and ends, in the chain's direction.
    pub ends: [EdgeEnd; 2],
    /// The clearance (radius of the largest empty disk centred there) at
    /// both ends; infinite at an end at infinity.
    pub clearance: [f64; 2],
    /// The sites on its left and on its right, in the chain's direction:
    /// every point of the piece is as far from both, at its clearance.
    /// Its curve, a straight piece or an arc of the parabola of a point and
    /// a segment's line, is [`Diagram::edge_shape`] of `edge` (made on
    /// demand: the medial axis of a large domain has millions of pieces).
    pub sites: [SiteId; 2],
}

/// A maximal path of the medial axis through vertices of degree two: from
/// a vertex where it branches or ends (or infinity) to another, or a closed
/// cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct Chain {
    /// The pieces, in order; consecutive pieces share an end.
    pub pieces: Vec<Piece>,
    /// Whether the chain is a cycle (its last piece ends where the first
    /// starts and every vertex on it has degree two).
    pub closed: bool,
}

/// The medial axis as chains (see the module doc).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct MedialAxis {
    /// Every chain; each edge of the medial axis is in exactly one.
    pub chains: Vec<Chain>,
}

impl Diagram {
    /// The medial axis: the edges inside the domain that are not separators
    /// (every non-separator edge when there is no domain), as chains.
    ///
    /// ```
    /// use segvoronoi::Builder;
    /// let mut b = Builder::new();
    /// b.add_polygon(&[vec![[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]])?;
    /// let d = b.build()?;
    /// let axis = d.medial_axis();
    /// // a rectangle: the middle line and two forks to each end's corners
    /// let pieces: usize = axis.chains.iter().map(|c| c.pieces.len()).sum();
    /// assert_eq!(pieces, 5);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn medial_axis(&self) -> MedialAxis {
        MedialAxis { chains: self.chains_of_marks(&mut self.axis_marks()) }
    }

    /// Which edges belong to the medial axis, by edge index.
    pub(super) fn medial_axis_edges(&self) -> Vec<bool> {
        (0..self.edges.len()).map(|e| self.in_medial_axis(EdgeId::from_index(e))).collect()
    }

    /// Per finite vertex, how many of the edges marked in `in_axis` meet
    /// there.
    pub(super) fn axis_degrees(&self, in_axis: &[bool]) -> Vec<u8> {
        let mut degree = vec![0u8; self.finite_vertices];
        for (e, _) in in_axis.iter().enumerate().filter(|(_, &marked)| marked) {
            for v in self.end_vertices(EdgeId::from_index(e)).into_iter().flatten() {
                degree[v.index()] += 1;
            }
        }
        degree
    }

    /// The finite vertices at the two ends of an edge (in range).
    pub(super) fn end_vertices(&self, e: EdgeId) -> [Option<VertexId>; 2] {
        let [h, t] = self.half_edges(e).expect("in range");
        [self.origin_vertex(h), self.origin_vertex(t)]
    }

    /// The finite vertex where `h` starts (`None` at infinity).
    fn origin_vertex(&self, h: HalfEdge) -> Option<VertexId> {
        let canonical = self.edges[h.edge().index()];
        let v = if h.is_reversed() { self.store.twin(canonical) } else { canonical }.origin();
        (v.index() < self.finite_vertices).then_some(v)
    }

    /// The edges marked in `in_axis` as chains: maximal paths through
    /// vertices where two of them meet.
    pub(super) fn chains_of(&self, in_axis: &[bool]) -> Vec<Chain> {
        let mut marks = vec![UNMARKED; self.store.twin.len()];
        for (e, &h) in self.edges.iter().enumerate().filter(|&(e, _)| in_axis[e]) {
            marks[h.index()] = e as u32;
            marks[self.store.twin(h).index()] = e as u32;
        }
        self.chains_of_marks(&mut marks)
    }

    /// The marks (see `chains_of_marks`) of the edges of the medial axis.
    fn axis_marks(&self) -> Vec<u32> {
        let mut marks = vec![UNMARKED; self.store.twin.len()];
        for (e, &h) in self.edges.iter().enumerate() {
            if self.in_medial_axis(EdgeId::from_index(e)) {
                marks[h.index()] = e as u32;
                marks[self.store.twin(h).index()] = e as u32;
            }
        }
        marks
    }

    /// The marked edges as chains (as `chains_of`). `marks` holds, per
    /// half-edge of the store, the id of its public edge if that edge is to
    /// be chained, else `UNMARKED`; the walk sets `TAKEN` in the marks of
    /// the edges it has put in a chain.
    ///
    /// The chains come in the order of `chains_of`'s first description:
    /// open chains from the marked edges by id (the store keeps an edge's
    /// canonical half-edge, the lower of the two, in id order), each edge
    /// from its `ends[0]` before its `ends[1]`; then the cycles, from the
    /// `ends[0]` of their lowest edge. Working on the store's half-edges,
    /// the degree of a vertex is read from its own three marks, and the walk
    /// needs neither the public half-edge ids nor the edge records.
    fn chains_of_marks(&self, marks: &mut [u32]) -> Vec<Chain> {
        let twin = &self.store.twin;
        let canonical_marked = |marks: &[u32], h: usize| marks[h] != UNMARKED && h < twin[h].index();
        let mut chains = Vec::new();
        let mut scratch = Vec::new();
        // Open chains first: from every end whose degree is not two.
        for h in 0..marks.len() {
            if !canonical_marked(marks, h) {
                continue;
            }
            for start in [HalfEdgeId::from_index(h), twin[h]] {
                // both sides are taken at once: ask the side at hand, not
                // the far one
                if marks[h] & TAKEN != 0 {
                    break;
                }
                let v = start.origin();
                if v.index() < self.finite_vertices && marked_degree(marks, v) == 2 {
                    continue;
                }
                chains.push(self.walk_marks(start, marks, &mut scratch));
            }
        }
        // What is left are cycles through vertices of degree two.
        for h in 0..marks.len() {
            if canonical_marked(marks, h) && marks[h] & TAKEN == 0 {
                chains.push(self.walk_marks(HalfEdgeId::from_index(h), marks, &mut scratch));
            }
        }
        chains
    }

    /// Whether an edge belongs to the medial axis.
    fn in_medial_axis(&self, e: EdgeId) -> bool {
        let inside = match self.edge_location(e) {
            Some(location) => location == Location::Inside,
            None => true,
        };
        // (the edges along the normal of a curved ring's tangent join are
        // what separators are at a straight corner: no branch ends there)
        inside && self.is_separator(e) == Some(false) && !self.is_join_normal(e)
    }

    /// The chain that starts with the store's half-edge `first` (marked),
    /// through vertices of degree two, until a vertex of another degree,
    /// infinity, or back at the start. `scratch` is an empty buffer, left
    /// empty.
    fn walk_marks(&self, first: HalfEdgeId, marks: &mut [u32], scratch: &mut Vec<Piece>) -> Chain {
        let mut h = first;
        let mut closed = false;
        loop {
            let t = self.store.twin(h);
            let edge = marks[h.index()] & !TAKEN;
            marks[h.index()] |= TAKEN;
            marks[t.index()] |= TAKEN;
            scratch.push(self.piece_of(h, t, EdgeId::from_index(edge as usize)));
            let v = t.origin();
            if v.index() >= self.finite_vertices || marked_degree(marks, v) != 2 {
                break;
            }
            // the other marked half-edge leaving v (not the edge arrived by)
            let next = (0..3).map(|slot| v.half_edge(slot)).find(|&o| o != t && o != h && marks[o.index()] != UNMARKED);
            match next {
                Some(n) if n == first => {
                    closed = true;
                    break;
                }
                Some(n) if marks[n.index()] & TAKEN == 0 => h = n,
                _ => break,
            }
        }
        // exactly as long as it is: most chains have a piece or two
        let pieces = scratch.to_vec();
        scratch.clear();
        Chain { pieces, closed }
    }

    /// The piece of the store's half-edge `h` (twin `t`) of edge `edge`.
    fn piece_of(&self, h: HalfEdgeId, t: HalfEdgeId, edge: EdgeId) -> Piece {
        let ends = [self.end_of(h), self.end_of(t)];
        let clearance = ends.map(|end| match end {
            EdgeEnd::Vertex(v) => self.store.clearance[v.index()],
            EdgeEnd::Infinite { .. } => f64::INFINITY,
        });
        let sites = [self.store.left(h), self.store.right(h)];
        // an edge's canonical half-edge is the lower of its two
        Piece { edge, reversed: t < h, ends, clearance, sites }
    }

    /// The point of a finite piece at parameter `t` (0 at its start, 1 at
    /// its end, in the chain's direction; along the line of a straight
    /// piece, along the directrix of a parabolic one) and the clearance
    /// there: `[x, y, r]`. `None` for a piece reaching infinity or a `t`
    /// outside `[0, 1]`, and for a point that cannot be computed in `f64`
    /// (only on inputs beyond the exact range, see
    /// [`ErrorKind::UnsupportedRange`](crate::ErrorKind::UnsupportedRange)).
    pub fn piece_point_at(&self, piece: &Piece, t: f64) -> Option<[f64; 3]> {
        if !(0.0..=1.0).contains(&t) {
            return None;
        }
        let positions = piece.ends.map(|end| match end {
            EdgeEnd::Vertex(v) => self.vertex(v).map(|v| v.position),
            EdgeEnd::Infinite { .. } => None,
        });
        let [Some(from), Some(to)] = positions else { return None };
        // along the edge's own direction (a conic's points depend on it)
        let curve = self.edge_curve(piece.edge)?;
        let q = if piece.reversed { curve.point(1.0 - t) } else { curve.point(t) };
        let q = self.scale.point_to_input(q);
        if q.x.is_nan() || q.y.is_nan() {
            // the curve's parameters underflowed: an input beyond the exact
            // range (`ErrorKind::UnsupportedRange`), whose shortest edges
            // f64 cannot parameterise
            return None;
        }
        // the ends exactly, as the vertices have them
        let q = if t == 0.0 {
            from
        } else if t == 1.0 {
            to
        } else {
            q
        };
        let left = self.sites.at(self.edge(piece.edge)?.sites[0].index());
        Some([q.x, q.y, left.distance(q)])
    }

    /// The points of a finite piece within `tolerance` of its curve (as
    /// [`Diagram::edge_polyline`], in the piece's direction), each with its
    /// clearance: `[x, y, r]`. `None` for a piece reaching infinity or a
    /// tolerance that is not positive.
    pub fn sample_piece(&self, piece: &Piece, tolerance: f64) -> Option<Vec<[f64; 3]>> {
        let sampled = self.sampled_piece(piece, tolerance)?;
        let n = sampled.len(self);
        let mut points = vec![[0.0; 3]; n];
        sampled.for_each_point(self, n, |j, p| points[j] = p);
        Some(points)
    }

    /// A finite piece ready to sample, or `None` for a piece reaching
    /// infinity or a tolerance that is not positive.
    ///
    /// The curve is the one of the piece's ends and sites (those of its
    /// edge, for a piece of `medial_axis`: then the polyline is the edge's
    /// `edge_polyline`), and the clearance is measured from the site on the
    /// left of the edge, so that the edge itself is not looked up.
    fn sampled_piece(&self, piece: &Piece, tolerance: f64) -> Option<SampledPiece> {
        if tolerance.is_nan() || tolerance <= 0.0 || piece.edge.index() >= self.edges.len() {
            return None;
        }
        if piece.sites.iter().any(|s| s.index() >= self.sites.len()) {
            return None;
        }
        let vertex = |end: EdgeEnd| match end {
            EdgeEnd::Vertex(v) if v.index() < self.finite_vertices => Some(v.index()),
            _ => None,
        };
        // the edge's own direction: the polyline of a parabola depends on it
        let [start, end] = if piece.reversed { [piece.ends[1], piece.ends[0]] } else { piece.ends };
        let (first, last) = (vertex(start)?, vertex(end)?);
        // the edge's own sites in its own order: on its left first
        let sites = if piece.reversed { [piece.sites[1], piece.sites[0]] } else { piece.sites };
        let shape = self.shape_between(sites);
        Some(SampledPiece { shape, first, last, left: sites[0], reversed: piece.reversed, tolerance })
    }

    /// The points of a chain within `tolerance` (see [`Diagram::sample_piece`]),
    /// shared ends once; `None` when a piece reaches infinity.
    pub fn sample_chain(&self, chain: &Chain, tolerance: f64) -> Option<Vec<[f64; 3]>> {
        let n = self.chain_sample_len(chain, tolerance, usize::MAX)?;
        let mut out = vec![[0.0; 3]; n];
        self.for_each_chain_sample(chain, tolerance, |j, p| out[j] = p)?;
        Some(out)
    }

    /// How many points `sample_chain(chain, tolerance)` has, counted
    /// without making a list: `None` where `sample_chain` gives `None`. The
    /// count stops at the first piece that takes it past `limit` (then it
    /// is above `limit`, and the later pieces are not looked at), so that
    /// a tolerance that asks for too many points costs no more than `limit`.
    pub fn chain_sample_len(&self, chain: &Chain, tolerance: f64, limit: usize) -> Option<usize> {
        let mut total = 0usize;
        for (k, piece) in chain.pieces.iter().enumerate() {
            // each piece after the first starts where the one before ended
            total = total.saturating_add(self.sampled_piece(piece, tolerance)?.len(self) - usize::from(k > 0));
            if total > limit {
                break;
            }
        }
        Some(total)
    }

    /// Calls `emit(j, point)` with each point of `sample_chain(chain,
    /// tolerance)`, `j` its index there (a reversed piece's points come
    /// last first), allocating nothing; `None` where `sample_chain` gives
    /// `None`, found before anything is emitted only when
    /// `chain_sample_len` said so first.
    pub fn for_each_chain_sample(&self, chain: &Chain, tolerance: f64, mut emit: impl FnMut(usize, [f64; 3])) -> Option<usize> {
        let mut base = 0usize;
        for (k, piece) in chain.pieces.iter().enumerate() {
            let sampled = self.sampled_piece(piece, tolerance)?;
            let skip = usize::from(k > 0);
            let n = sampled.len(self);
            sampled.for_each_point(self, n, |j, p| {
                if j >= skip {
                    emit(base + j - skip, p);
                }
            });
            base += n - skip;
        }
        Some(base)
    }

    /// The largest disk inside the domain: its centre and radius (the
    /// inside vertex of largest clearance: along an edge of the medial axis
    /// between points and segments the clearance has no maximum inside the
    /// edge — linear between two segments, convex along a parabola or
    /// between two points; beside a circular arc it may, and such peaks
    /// count too, placed by bisection along the edge). `None` without a
    /// domain or when nothing is inside.
    ///
    /// ```
    /// use segvoronoi::Builder;
    /// let mut b = Builder::new();
    /// b.add_polygon(&[vec![[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]])?;
    /// let (centre, r) = b.build()?.max_inscribed_circle().unwrap();
    /// assert!((r - 1.0).abs() < 1e-12 && (centre.y - 1.0).abs() < 1e-12);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn max_inscribed_circle(&self) -> Option<(Point, f64)> {
        self.inscribed_circles().into_iter().next()
    }

    /// The largest disk inside each connected component of the domain
    /// (as [`Diagram::max_inscribed_circle`], per component: the
    /// components of the medial axis), largest first; empty without a
    /// domain.
    ///
    /// ```
    /// use segvoronoi::Builder;
    /// let square = |x: f64, s: f64| vec![[x, 0.0], [x + s, 0.0], [x + s, s], [x, s]];
    /// let mut b = Builder::new();
    /// b.add_polygon(&[square(0.0, 2.0)])?;
    /// b.add_polygon(&[square(5.0, 4.0)])?;
    /// let circles = b.build()?.inscribed_circles();
    /// let radii: Vec<f64> = circles.iter().map(|&(_, r)| r).collect();
    /// assert_eq!(radii, [2.0, 1.0]);
    /// # Ok::<(), segvoronoi::Error>(())
    /// ```
    pub fn inscribed_circles(&self) -> Vec<(Point, f64)> {
        if self.domain.is_none() {
            return Vec::new();
        }
        let in_axis = self.medial_axis_edges();
        let components = self.axis_components(&in_axis);
        let mut largest: Vec<Option<(Point, f64)>> = vec![None; self.finite_vertices];
        let mut offer = |v: VertexId, position: Point, clearance: f64| {
            let best = &mut largest[components.find(v.index())];
            if best.map_or(true, |(_, r)| clearance > r) {
                *best = Some((position, clearance));
            }
        };
        for v in (0..self.finite_vertices).map(VertexId::from_index) {
            if self.vertex_location(v) != Some(Location::Inside) {
                continue;
            }
            offer(v, self.store.position[v.index()], self.store.clearance[v.index()]);
        }
        // beside an arc the clearance can peak inside an edge
        if self.arc_sites > 0 {
            for e in (0..self.edges.len()).filter(|&e| in_axis[e]).map(EdgeId::from_index) {
                let Some(v) = self.end_vertices(e).into_iter().flatten().next() else { continue };
                for (position, clearance) in self.conic_peaks(e) {
                    offer(v, position, clearance);
                }
            }
        }
        let mut circles: Vec<(Point, f64)> = largest.into_iter().flatten().collect();
        circles.sort_by(|a, b| b.1.total_cmp(&a.1));
        circles
    }
}

/// The mark of a half-edge whose edge is not to be chained (`chains_of_marks`).
const UNMARKED: u32 = NONE;

/// Set in the marks of both half-edges of an edge once a chain has it (edge
/// ids stay below it: half-edge ids, twice as many, are `u32`).
const TAKEN: u32 = 1 << 31;

/// How many of the three half-edges leaving the finite vertex `v` are marked.
fn marked_degree(marks: &[u32], v: VertexId) -> usize {
    (0..3).filter(|&slot| marks[v.half_edge(slot).index()] != UNMARKED).count()
}

/// The degree of an end in the axis (`axis_degrees`): zero at infinity.
pub(super) fn degree_at(end: EdgeEnd, degrees: &[u8]) -> usize {
    match end {
        EdgeEnd::Vertex(v) => usize::from(degrees[v.index()]),
        EdgeEnd::Infinite { .. } => 0,
    }
}

/// A finite piece of the medial axis to sample ([`Diagram::sample_piece`]):
/// its edge's shape, end vertices and left site in the edge's own direction.
struct SampledPiece {
    shape: EdgeShape,
    /// The vertices at the edge's `ends[0]` and `ends[1]`.
    first: usize,
    last: usize,
    /// The site on the left of the edge.
    left: SiteId,
    /// Whether the piece runs from `last` to `first`.
    reversed: bool,
    tolerance: f64,
}

impl SampledPiece {
    /// How many points it has (at least two).
    fn len(&self, d: &Diagram) -> usize {
        if self.shape == EdgeShape::Line {
            return 2;
        }
        let mut n = 0usize;
        self.for_each_edge_point(d, |_| n += 1);
        n
    }

    /// The points of the edge's polyline from `first` to `last`.
    fn for_each_edge_point(&self, d: &Diagram, emit: impl FnMut(Point)) {
        d.for_each_polyline_point(self.shape, [self.first, self.last], self.tolerance, emit);
    }

    /// Calls `emit(j, [x, y, clearance])` for each of its `n` points
    /// (`n` from `len`), `j` the index in the piece's own direction. The ends
    /// are the vertices, with their stored clearance; the points between
    /// measure it from the left site.
    fn for_each_point(&self, d: &Diagram, n: usize, mut emit: impl FnMut(usize, [f64; 3])) {
        let at_vertex = |v: usize| {
            let p = d.store.position[v];
            [p.x, p.y, d.store.clearance[v]]
        };
        let site = d.sites.at(self.left.index());
        let mut k = 0usize;
        self.for_each_edge_point(d, |p| {
            let value = match k {
                0 => at_vertex(self.first),
                k if k + 1 == n => at_vertex(self.last),
                _ => [p.x, p.y, site.distance(p)],
            };
            emit(if self.reversed { n - 1 - k } else { k }, value);
            k += 1;
        });
    }
}
