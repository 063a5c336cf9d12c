//! A library error as data for Python: its kind's name, message, indices,
//! and for two segments that meet, a point they share (none for a conflict
//! with a circular arc). The Python side (`segvoronoi/_errors.py`) turns
//! it into the exception class of its kind;
//! keeping the classes in Python keeps them documented, typed and picklable
//! (Dask ships exceptions between processes).

use segvoronoi::{Builder, Error, ErrorKind};

/// What Python gets: `(geometry, kind, message, indices, point)`;
/// `geometry` is the index in a vectorised call (-1 otherwise).
pub type FailureTuple = (i64, &'static str, String, Vec<usize>, Option<(f64, f64)>);

pub struct Failure {
    pub geometry: Option<usize>,
    pub kind: &'static str,
    pub message: String,
    pub indices: Vec<usize>,
    pub point: Option<[f64; 2]>,
}

impl Failure {
    /// The failure of geometry `geometry`, whose input was in `builder`
    /// (from which the point where two segments meet is found).
    pub fn of(error: &Error, builder: Option<&Builder>, geometry: Option<usize>) -> Failure {
        // a conflict with an arc names arcs (and points) by their own
        // indices: no common point of two segments to find
        let m = error.message();
        let with_arc = m.starts_with("arc") || m.contains(" arc ");
        let point = match (error.kind(), builder, error.indices()) {
            (ErrorKind::Intersecting, Some(b), &[i, j]) if !with_arc => b
                .segment(i)
                .zip(b.segment(j))
                .and_then(|(s, t)| common_point([[s[0].x, s[0].y], [s[1].x, s[1].y]], [[t[0].x, t[0].y], [t[1].x, t[1].y]])),
            _ => None,
        };
        Failure {
            geometry,
            kind: kind_name(error.kind()),
            message: error.message().to_string(),
            indices: error.indices().to_vec(),
            point,
        }
    }

    pub fn at(mut self, geometry: usize) -> Failure {
        self.geometry = Some(geometry);
        self
    }

    pub fn to_tuple(&self) -> FailureTuple {
        let geometry = self.geometry.map_or(-1, |g| g as i64);
        (geometry, self.kind, self.message.clone(), self.indices.clone(), self.point.map(|[x, y]| (x, y)))
    }
}

/// The names the Python exception classes are looked up by. `ErrorKind` is
/// non-exhaustive: a kind added later maps to the base class.
fn kind_name(kind: ErrorKind) -> &'static str {
    match kind {
        ErrorKind::InvalidCoordinate => "InvalidCoordinate",
        ErrorKind::TooLarge => "TooLarge",
        ErrorKind::Intersecting => "Intersecting",
        ErrorKind::InvalidPolygon => "InvalidPolygon",
        ErrorKind::InvalidArgument => "InvalidArgument",
        ErrorKind::OutOfMemory => "OutOfMemory",
        ErrorKind::Internal => "Internal",
        ErrorKind::UnsupportedRange => "UnsupportedRange",
        ErrorKind::InvalidArc => "InvalidArc",
        _ => "Unknown",
    }
}

/// A point two segments that cross or overlap share: where they cross, or
/// for collinear overlapping segments the lexicographically smallest point
/// of the overlap (the library names conflicts by that point too). Rounded
/// to `f64`; `None` when they are parallel and apart (which the library
/// does not report).
fn common_point(s: [[f64; 2]; 2], t: [[f64; 2]; 2]) -> Option<[f64; 2]> {
    let d = [s[1][0] - s[0][0], s[1][1] - s[0][1]];
    let e = [t[1][0] - t[0][0], t[1][1] - t[0][1]];
    let cross = d[0] * e[1] - d[1] * e[0];
    let w = [t[0][0] - s[0][0], t[0][1] - s[0][1]];
    if cross != 0.0 {
        let u = (w[0] * e[1] - w[1] * e[0]) / cross;
        let u = u.clamp(0.0, 1.0);
        return Some([s[0][0] + u * d[0], s[0][1] + u * d[1]]);
    }
    // collinear: the larger of the two lexicographic minima lies in both
    let lo = |a: [f64; 2], b: [f64; 2]| if (a[0], a[1]) <= (b[0], b[1]) { a } else { b };
    let (a, b) = (lo(s[0], s[1]), lo(t[0], t[1]));
    Some(if (a[0], a[1]) >= (b[0], b[1]) { a } else { b })
}
