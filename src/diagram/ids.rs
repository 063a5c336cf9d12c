//! Typed ids, so that a vertex id can never be passed where an edge id is
//! expected.

macro_rules! typed_id {
    ($(#[$doc:meta])* $name:ident) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub struct $name(pub(crate) u32);

        impl $name {
            /// The id as an index into the diagram's arrays.
            #[inline]
            pub fn index(self) -> usize {
                self.0 as usize
            }

            #[inline]
            /// The id of the given array index.
            pub fn from_index(i: usize) -> Self {
                debug_assert!(i < u32::MAX as usize);
                $name(i as u32)
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                write!(f, "{}", self.0)
            }
        }
    };
}

typed_id!(
    /// A site, and the cell (Voronoi region) that belongs to it.
    SiteId
);
typed_id!(
    /// A Voronoi vertex.
    VertexId
);
typed_id!(
    /// A Voronoi edge between two sites (a segment, a ray or a whole line).
    EdgeId
);
typed_id!(
    /// A directed half of a Voronoi edge.
    HalfEdgeId
);

impl VertexId {
    /// The `slot`-th half-edge leaving this vertex (`slot` in `0..3`).
    #[inline]
    pub(crate) fn half_edge(self, slot: u32) -> HalfEdgeId {
        HalfEdgeId(self.0 * 3 + slot)
    }
}

impl HalfEdgeId {
    /// The vertex this half-edge leaves.
    #[inline]
    pub(crate) fn origin(self) -> VertexId {
        VertexId(self.0 / 3)
    }

    /// Its position among the three half-edges of its origin.
    #[inline]
    pub(crate) fn slot(self) -> u32 {
        self.0 % 3
    }

    /// The half-edge of the same origin `k` steps counter-clockwise.
    #[inline]
    pub(crate) fn rotate(self, k: u32) -> HalfEdgeId {
        debug_assert!(k < 3);
        let s = self.slot();
        // (s + k) mod 3 without a second division: this sits on every hot path.
        let t = if s + k >= 3 { s + k - 3 } else { s + k };
        HalfEdgeId(self.0 - s + t)
    }
}

/// Marks an absent id in the flat arrays.
pub(crate) const NONE: u32 = u32::MAX;
