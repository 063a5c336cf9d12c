//! Diagrams with circular arcs among the sites.

use crate::diagram::Diagram;
use crate::error::{Error, ErrorKind};
use crate::geometry::{CircularArc, Point};

/// The diagram of points, segments and arcs.
pub(super) fn diagram_with_arcs(
    _points: &[Point],
    _segments: &[[Point; 2]],
    _arcs: &[CircularArc],
    _split: bool,
    _rings: bool,
) -> Result<Diagram, Error> {
    Err(Error::new(ErrorKind::Internal, "arcs: under construction".to_string(), Vec::new()))
}
