//! Voronoi edges as curves: the parabolic arc between a point and a
//! segment (`parabola`), a finite edge as a straight piece or such an arc
//! between two parameters (`edge_curve`, walked by the construction's
//! middle margin and by the queries), and an edge as a track for the
//! offsets, with the distance from its sites along it (`edge_track`).
//! Arcs among the sites will add their conic curves here.

pub(crate) mod bisector;
pub(crate) mod edge_curve;
pub(crate) mod edge_track;
pub(crate) mod parabola;
