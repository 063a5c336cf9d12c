//! A partition of `0..n` into sets: union–find with path halving, for the
//! connected components of the medial axis and the vertices joined by
//! zero-length edges in the canonical topology.

/// A partition of `0..n` into sets (union–find with path halving).
pub(crate) struct Partition(Vec<std::cell::Cell<usize>>);

impl Partition {
    pub(crate) fn new(n: usize) -> Partition {
        Partition((0..n).map(std::cell::Cell::new).collect())
    }

    /// The representative of `x`'s set.
    pub(crate) fn find(&self, mut x: usize) -> usize {
        while self.0[x].get() != x {
            let grandparent = self.0[self.0[x].get()].get();
            self.0[x].set(grandparent);
            x = grandparent;
        }
        x
    }

    pub(crate) fn join(&mut self, x: usize, y: usize) {
        let (x, y) = (self.find(x), self.find(y));
        self.0[x].set(y);
    }
}
