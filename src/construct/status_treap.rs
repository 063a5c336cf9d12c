//! The status of a plane sweep over segments: the segments the sweep line
//! crosses, from below to above, in a treap with parent links. Positions
//! are the caller's (a node goes in right after another and leaves by its
//! id, with no comparison); only [`Treap::locate`] compares, through the
//! caller's side function, so the same structure serves the strict check's
//! Shamos–Hoey sweep (`input_check/sweep.rs`) and the splitting's
//! Bentley–Ottmann sweep (`split/contacts.rs`), whose orders differ only in
//! how a point is compared with a segment.

use crate::geometry::predicates::Orientation;
use crate::geometry::Point;

/// No node.
pub(crate) const NIL: u32 = u32::MAX;

/// A node of the status: a segment (first point first) and its links, one
/// cache line (a descent reads one line per level).
#[derive(Clone, Copy)]
#[repr(align(64))]
struct Node {
    segment: [Point; 2],
    left: u32,
    right: u32,
    parent: u32,
    priority: u32,
}

/// A treap with parent links over the kept segments: node `i` is the
/// segment of node id `i`, in the status at most once. Positions are the
/// caller's: a node goes in right after another ([`Treap::insert_after`]),
/// and leaves by its id ([`Treap::remove`]), with no comparison; only
/// [`Treap::locate`] compares, through the caller's side function.
pub(crate) struct Treap {
    nodes: Vec<Node>,
    root: u32,
    /// The number of nodes in the tree.
    len: usize,
    /// xorshift state for the priorities.
    state: u32,
}

impl Treap {
    pub(crate) fn new(segments: impl Iterator<Item = [Point; 2]>) -> Treap {
        let nodes = segments.map(|segment| Node { segment, left: NIL, right: NIL, parent: NIL, priority: 0 }).collect();
        Treap { nodes, root: NIL, len: 0, state: 0x9e37_79b9 }
    }

    /// The number of nodes in the tree.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Takes every node out of the tree at once (they may go in again).
    pub(crate) fn clear(&mut self) {
        (self.root, self.len) = (NIL, 0);
    }

    pub(crate) fn segment(&self, i: u32) -> [Point; 2] {
        self.nodes[i as usize].segment
    }

    fn left(&self, i: u32) -> u32 {
        self.nodes[i as usize].left
    }

    fn right(&self, i: u32) -> u32 {
        self.nodes[i as usize].right
    }

    fn parent(&self, i: u32) -> u32 {
        self.nodes[i as usize].parent
    }

    fn leftmost(&self, mut t: u32) -> u32 {
        while self.left(t) != NIL {
            t = self.left(t);
        }
        t
    }

    fn rightmost(&self, mut t: u32) -> u32 {
        while self.right(t) != NIL {
            t = self.right(t);
        }
        t
    }

    /// The node before `i` in the order, or `NIL`.
    pub(crate) fn previous(&self, mut i: u32) -> u32 {
        if self.left(i) != NIL {
            return self.rightmost(self.left(i));
        }
        while self.parent(i) != NIL && self.left(self.parent(i)) == i {
            i = self.parent(i);
        }
        self.parent(i)
    }

    /// The node after `i` in the order, or `NIL`.
    pub(crate) fn next(&self, mut i: u32) -> u32 {
        if self.right(i) != NIL {
            return self.leftmost(self.right(i));
        }
        while self.parent(i) != NIL && self.right(self.parent(i)) == i {
            i = self.parent(i);
        }
        self.parent(i)
    }

    /// Where a query falls: descends by `side` (the query is above the
    /// node's segment: `CounterClockwise`; below: `Clockwise`; on it:
    /// `Collinear`) and returns the last node passed below the query, the
    /// last passed above it, and the first found on it (`NIL` for none).
    /// When the nodes below the query, on it and above it are runs in that
    /// order, these are the node before the query, the node after it, and
    /// one on it if any is.
    pub(crate) fn locate(&self, side: impl Fn([Point; 2]) -> Orientation) -> (u32, u32, u32) {
        let (mut below, mut above, mut on) = (NIL, NIL, NIL);
        let mut t = self.root;
        while t != NIL {
            match side(self.segment(t)) {
                Orientation::CounterClockwise => {
                    below = t;
                    t = self.right(t);
                }
                Orientation::Clockwise => {
                    above = t;
                    t = self.left(t);
                }
                Orientation::Collinear => {
                    if on == NIL {
                        on = t;
                    }
                    below = t;
                    t = self.right(t);
                }
            }
        }
        (below, above, on)
    }

    /// Links `child` where `old` was below `parent` (or as the root).
    fn replace_child(&mut self, parent: u32, old: u32, child: u32) {
        if parent == NIL {
            self.root = child;
        } else if self.left(parent) == old {
            self.nodes[parent as usize].left = child;
        } else {
            self.nodes[parent as usize].right = child;
        }
        if child != NIL {
            self.nodes[child as usize].parent = parent;
        }
    }

    /// Rotates `x` above its parent.
    fn rotate_up(&mut self, x: u32) {
        let p = self.parent(x);
        let g = self.parent(p);
        if self.left(p) == x {
            let b = self.right(x);
            self.nodes[p as usize].left = b;
            if b != NIL {
                self.nodes[b as usize].parent = p;
            }
            self.nodes[x as usize].right = p;
        } else {
            let b = self.left(x);
            self.nodes[p as usize].right = b;
            if b != NIL {
                self.nodes[b as usize].parent = p;
            }
            self.nodes[x as usize].left = p;
        }
        self.nodes[p as usize].parent = x;
        self.replace_child(g, p, x);
    }

    /// Puts node `n` (not in the tree) right after `anchor`, or first when
    /// `anchor` is `NIL`.
    pub(crate) fn insert_after(&mut self, anchor: u32, n: u32) {
        self.state ^= self.state << 13;
        self.state ^= self.state >> 17;
        self.state ^= self.state << 5;
        self.len += 1;
        let node = &mut self.nodes[n as usize];
        (node.left, node.right, node.parent, node.priority) = (NIL, NIL, NIL, self.state);
        if self.root == NIL {
            self.root = n;
            return;
        }
        let (parent, as_left) = if anchor == NIL {
            (self.leftmost(self.root), true)
        } else if self.right(anchor) == NIL {
            (anchor, false)
        } else {
            (self.leftmost(self.right(anchor)), true)
        };
        if as_left {
            self.nodes[parent as usize].left = n;
        } else {
            self.nodes[parent as usize].right = n;
        }
        self.nodes[n as usize].parent = parent;
        while self.parent(n) != NIL && self.nodes[n as usize].priority > self.nodes[self.parent(n) as usize].priority {
            self.rotate_up(n);
        }
    }

    /// Takes node `n` out of the tree.
    pub(crate) fn remove(&mut self, n: u32) {
        self.len -= 1;
        loop {
            let (l, r) = (self.left(n), self.right(n));
            if l == NIL || r == NIL {
                let child = if l == NIL { r } else { l };
                self.replace_child(self.parent(n), n, child);
                return;
            }
            let up = if self.nodes[l as usize].priority > self.nodes[r as usize].priority { l } else { r };
            self.rotate_up(up);
        }
    }
}
