//! The medial axis: the Voronoi edges inside the domain that are not
//! separators, as a graph of chains (maximal paths through vertices where
//! exactly two of its edges meet), each a list of exact pieces with the
//! clearance along them; and the largest disk inside the domain.
//!
//! Without a domain (no polygon was added) the chains cover every edge that
//! is not a separator, rays included: the ordinary segment Voronoi diagram
//! as a graph.

use crate::diagram::{Diagram, EdgeId, VertexId};
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
    /// Its curve: a straight piece, or an arc of the parabola of a point
    /// and a segment's line (the same shapes as [`Diagram::edge_shape`]).
    pub shape: EdgeShape,
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
        MedialAxis { chains: self.chains_of(&self.medial_axis_edges()) }
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
        let degrees = self.axis_degrees(in_axis);
        let degree = |end: EdgeEnd| degree_at(end, &degrees);
        let mut used = vec![false; self.edges.len()];
        let mut chains = Vec::new();
        // Open chains first: from every end whose degree is not two.
        let starts = (0..self.edges.len()).filter(|&e| in_axis[e]).flat_map(|e| {
            let [h, t] = self.half_edges(EdgeId::from_index(e)).expect("in range");
            [h, t]
        });
        for h in starts {
            if used[h.edge().index()] || self.origin_vertex(h).is_some_and(|v| degrees[v.index()] == 2) {
                continue;
            }
            chains.push(self.walk_chain(h, in_axis, &mut used, &degree));
        }
        // What is left are cycles through vertices of degree two.
        for e in 0..self.edges.len() {
            if in_axis[e] && !used[e] {
                let [h, _] = self.half_edges(EdgeId::from_index(e)).expect("in range");
                chains.push(self.walk_chain(h, in_axis, &mut used, &degree));
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
        inside && self.is_separator(e) == Some(false)
    }

    /// The chain that starts with half-edge `h`, through vertices of degree
    /// two, until a vertex of another degree, infinity, or back at the start.
    fn walk_chain(&self, first: HalfEdge, in_axis: &[bool], used: &mut [bool], degree: &impl Fn(EdgeEnd) -> usize) -> Chain {
        let mut pieces = Vec::new();
        let mut h = first;
        let mut closed = false;
        loop {
            used[h.edge().index()] = true;
            let piece = self.piece(h);
            let end = piece.ends[1];
            pieces.push(piece);
            let EdgeEnd::Vertex(v) = end else { break };
            if degree(end) != 2 {
                break;
            }
            let next = self.continue_at(v, h, in_axis);
            match next {
                Some(n) if n == first => {
                    closed = true;
                    break;
                }
                Some(n) if !used[n.edge().index()] => h = n,
                _ => break,
            }
        }
        Chain { pieces, closed }
    }

    /// The other medial-axis half-edge leaving `v` (of degree two), after
    /// arriving by `h`.
    fn continue_at(&self, v: VertexId, arrived: HalfEdge, in_axis: &[bool]) -> Option<HalfEdge> {
        let out = self.vertex_half_edges(v)?;
        out.into_iter().find(|o| in_axis[o.edge().index()] && o.edge() != arrived.edge())
    }

    /// The piece of half-edge `h`.
    fn piece(&self, h: HalfEdge) -> Piece {
        let edge = self.edge(h.edge()).expect("in range");
        let mut ends = edge.ends;
        if h.is_reversed() {
            ends.reverse();
        }
        let clearance = ends.map(|end| match end {
            EdgeEnd::Vertex(v) => self.store.clearance[v.index()],
            EdgeEnd::Infinite { .. } => f64::INFINITY,
        });
        let shape = self.shape_of(&edge);
        Piece { edge: h.edge(), reversed: h.is_reversed(), ends, clearance, shape }
    }

    /// The point of a finite piece at parameter `t` (0 at its start, 1 at
    /// its end, in the chain's direction; along the line of a straight
    /// piece, along the directrix of a parabolic one) and the clearance
    /// there: `[x, y, r]`. `None` for a piece reaching infinity or a `t`
    /// outside `[0, 1]`.
    pub fn piece_point_at(&self, piece: &Piece, t: f64) -> Option<[f64; 3]> {
        if !(0.0..=1.0).contains(&t) {
            return None;
        }
        let positions = piece.ends.map(|end| match end {
            EdgeEnd::Vertex(v) => self.vertex(v).map(|v| v.position),
            EdgeEnd::Infinite { .. } => None,
        });
        let [Some(from), Some(to)] = positions else { return None };
        let q = self.edge_curve(piece.edge, from, to)?.point(t).scaled(self.scale.to_input);
        // the ends exactly, as the vertices have them
        let q = if t == 0.0 {
            from
        } else if t == 1.0 {
            to
        } else {
            q
        };
        let left = self.sites[self.edge(piece.edge)?.sites[0].index()];
        Some([q.x, q.y, left.distance(q)])
    }

    /// The points of a finite piece within `tolerance` of its curve (as
    /// [`Diagram::edge_polyline`], in the piece's direction), each with its
    /// clearance: `[x, y, r]`. `None` for a piece reaching infinity or a
    /// tolerance that is not positive.
    pub fn sample_piece(&self, piece: &Piece, tolerance: f64) -> Option<Vec<[f64; 3]>> {
        let mut points = Vec::new();
        self.append_piece(piece, tolerance, &mut points)?;
        Some(points)
    }

    /// Appends the points of `sample_piece` to `out`, but for its first
    /// when `out` already ends there (the end of the previous piece).
    fn append_piece(&self, piece: &Piece, tolerance: f64, out: &mut Vec<[f64; 3]>) -> Option<()> {
        let skip = usize::from(!out.is_empty());
        let &canonical = self.edges.get(piece.edge.index())?;
        let site = self.sites[self.store.left(canonical).index()];
        let mut points = self.edge_polyline(piece.edge, tolerance)?;
        if piece.reversed {
            points.reverse();
        }
        out.extend(points.into_iter().skip(skip).map(|p| [p.x, p.y, site.distance(p)]));
        Some(())
    }

    /// The points of a chain within `tolerance` (see [`Diagram::sample_piece`]),
    /// shared ends once; `None` when a piece reaches infinity.
    pub fn sample_chain(&self, chain: &Chain, tolerance: f64) -> Option<Vec<[f64; 3]>> {
        let mut out: Vec<[f64; 3]> = Vec::with_capacity(chain.pieces.len() + 1);
        for piece in &chain.pieces {
            self.append_piece(piece, tolerance, &mut out)?;
        }
        Some(out)
    }

    /// The largest disk inside the domain: its centre and radius (the
    /// inside vertex of largest clearance: along an edge of the medial axis
    /// the clearance has no maximum inside the edge — linear between two
    /// segments, convex along a parabola or between two points). `None`
    /// without a domain or when nothing is inside.
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
        let components = self.axis_components(&self.medial_axis_edges());
        let mut largest: Vec<Option<(Point, f64)>> = vec![None; self.finite_vertices];
        for v in (0..self.finite_vertices).map(VertexId::from_index) {
            if self.vertex_location(v) != Some(Location::Inside) {
                continue;
            }
            let (position, clearance) = (self.store.position[v.index()], self.store.clearance[v.index()]);
            let best = &mut largest[components.find(v.index())];
            if best.map_or(true, |(_, r)| clearance > r) {
                *best = Some((position, clearance));
            }
        }
        let mut circles: Vec<(Point, f64)> = largest.into_iter().flatten().collect();
        circles.sort_by(|a, b| b.1.total_cmp(&a.1));
        circles
    }
}

/// The degree of an end in the axis (`axis_degrees`): zero at infinity.
pub(super) fn degree_at(end: EdgeEnd, degrees: &[u8]) -> usize {
    match end {
        EdgeEnd::Vertex(v) => usize::from(degrees[v.index()]),
        EdgeEnd::Infinite { .. } => 0,
    }
}
