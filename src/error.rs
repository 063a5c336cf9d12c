//! The error type of the builder.

/// What stopped a build or an insertion: a problem with the input, or
/// ([`ErrorKind::Internal`]) a bug in segvoronoi.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A coordinate is NaN or infinite.
    InvalidCoordinate,
    /// More sites than the 32-bit ids of the diagram can hold.
    TooLarge,
    /// Two segments cross or overlap, or a point lies inside a segment;
    /// [`Error::indices`] holds both input indices (segment indices, or the
    /// point's index and then the segment's).
    Intersecting,
    /// A polygon ring has fewer than three distinct points;
    /// [`Error::indices`] holds the polygon's and the ring's index.
    InvalidPolygon,
    /// A circular arc is not one: equal endpoints, a zero or non-finite
    /// bulge, three points on a line, or a circle beyond `f64`; the message
    /// says which.
    InvalidArc,
    /// An argument of a query is out of its domain (such as an offset
    /// distance that is NaN, infinite or zero); the message says which.
    InvalidArgument,
    /// Memory for a size the caller asked for (such as
    /// [`Builder::reserve_points`](crate::Builder::reserve_points)) could not
    /// be allocated, or the memory a build of this size needs at its peak
    /// was refused before it started; nothing was changed.
    OutOfMemory,
    /// The construction could not complete a valid diagram: a bug in
    /// segvoronoi, not in the input (none is known; with sound arithmetic it
    /// does not happen). The message says what failed; please report the
    /// input. [`Error::indices`] holds the input index of the segment that
    /// failed, when one did. No diagram is returned and the builder is
    /// unchanged.
    Internal,
    /// The input's coordinates span more than the range in which every
    /// sign is decided exactly in `f64` (their largest magnitude more than
    /// `2^480`, about `3e144`, times their smallest nonzero magnitude or
    /// difference: `1e300` beside `1`, say), and the construction at that
    /// span could not complete a valid diagram. The message names the two
    /// coordinates and the range; scaling cannot help (the ratio stays),
    /// rounding the smallest differences away or splitting the input in
    /// parts of narrower span can. Inputs of such a span that build are
    /// checked before they are returned.
    UnsupportedRange,
}

/// A build or insertion error: its kind, a message that names the
/// offending input indices, and those indices.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    kind: ErrorKind,
    message: String,
    indices: Vec<usize>,
}

impl Error {
    pub(crate) fn new(kind: ErrorKind, message: String, indices: Vec<usize>) -> Error {
        Error { kind, message, indices }
    }

    /// The kind of problem.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// The input indices involved (for points and segments: their index in
    /// the order they were added to the builder).
    pub fn indices(&self) -> &[usize] {
        &self.indices
    }

    /// The message, naming the offending input indices.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Error {}
