//! Endpoints that should be one point, made one.
//!
//! A DXF file keeps each entity on its own: a LINE's end and the ARC that
//! follows it repeat the shared point, and the ARC's comes from its centre,
//! radius and angles, rounded (in the file's decimal text, then by the
//! cosine). The library takes chains as closed only where the points are
//! equal, so an endpoint within `SNAP` of the drawing's extent from one
//! seen before (in file order) is moved onto it.

use std::collections::HashMap;

use super::entities::{Item, Raw};
use crate::wkt::Xy;

/// How near, relative to the drawing's extent (the diagonal of its
/// vertices' box), two vertices must be to become one: far above the
/// rounding of a file's 16 digits, far below any feature a drawing means.
pub const SNAP: f64 = 1e-9;

/// Moves every vertex of `items` within `SNAP` × extent of a vertex seen
/// before onto that one; returns how many moved.
pub fn snap(items: &mut [Item]) -> usize {
    let tolerance = SNAP * extent(items);
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return 0;
    }
    let mut grid = Grid { tolerance, cells: HashMap::new() };
    let mut moved = 0;
    for item in items.iter_mut() {
        match &mut item.raw {
            Raw::Point(_) => {}
            Raw::Line(ends) => ends.iter_mut().for_each(|p| moved += usize::from(grid.snap(p))),
            Raw::Chain { vertices, .. } => vertices.iter_mut().for_each(|(p, _)| moved += usize::from(grid.snap(p))),
        }
    }
    moved
}

/// The diagonal of the box of every finite vertex (0 without any).
pub(super) fn extent(items: &[Item]) -> f64 {
    let (mut low, mut high) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    let mut add = |p: &Xy| {
        if p.iter().all(|c| c.is_finite()) {
            for i in 0..2 {
                low[i] = low[i].min(p[i]);
                high[i] = high[i].max(p[i]);
            }
        }
    };
    for item in items {
        match &item.raw {
            Raw::Point(p) => add(p),
            Raw::Line(ends) => ends.iter().for_each(&mut add),
            Raw::Chain { vertices, .. } => vertices.iter().for_each(|(p, _)| add(p)),
        }
    }
    if low[0] > high[0] {
        return 0.0;
    }
    (high[0] - low[0]).hypot(high[1] - low[1])
}

/// The vertices kept so far, by square cells as wide as the tolerance: a
/// vertex near `p` is in `p`'s cell or one of its eight neighbours.
struct Grid {
    tolerance: f64,
    cells: HashMap<(i64, i64), Vec<Xy>>,
}

impl Grid {
    /// Moves `p` onto a kept vertex within the tolerance (whether it moved
    /// by anything), or keeps it.
    fn snap(&mut self, p: &mut Xy) -> bool {
        if !p.iter().all(|c| c.is_finite()) {
            // the library names the entity with a non-finite coordinate
            return false;
        }
        // `as` saturates: far-off points share the edge cells, still correct
        let cell = ((p[0] / self.tolerance).floor() as i64, (p[1] / self.tolerance).floor() as i64);
        for dx in -1..=1 {
            for dy in -1..=1 {
                let near = (cell.0.saturating_add(dx), cell.1.saturating_add(dy));
                let found = self
                    .cells
                    .get(&near)
                    .and_then(|kept| kept.iter().find(|q| (q[0] - p[0]).hypot(q[1] - p[1]) <= self.tolerance).copied());
                if let Some(q) = found {
                    let moved = q != *p;
                    *p = q;
                    return moved;
                }
            }
        }
        self.cells.entry(cell).or_default().push(*p);
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(a: Xy, b: Xy) -> Item {
        Item { raw: Raw::Line([a, b]), name: String::new() }
    }

    #[test]
    fn near_ends_become_the_first_seen() {
        let mut items = vec![
            line([0.0, 0.0], [10.0, 0.0]),
            line([10.0 + 1e-12, 0.0], [10.0, 10.0]),
            Item {
                raw: Raw::Chain { vertices: vec![([10.0, 10.0 - 3e-12], 1.0), ([0.0, 10.0], 0.0)], closed: false },
                name: String::new(),
            },
            // far enough apart to stay apart
            line([0.0, 10.0], [0.0, 1e-6]),
        ];
        assert_eq!(snap(&mut items), 2);
        assert_eq!(items[1].raw, Raw::Line([[10.0, 0.0], [10.0, 10.0]]));
        let Raw::Chain { vertices, .. } = &items[2].raw else { panic!() };
        assert_eq!(vertices[0], ([10.0, 10.0], 1.0));
        assert_eq!(items[3].raw, Raw::Line([[0.0, 10.0], [0.0, 1e-6]]));
    }

    #[test]
    fn nothing_to_snap_in_a_point() {
        let mut items = vec![line([1.0, 1.0], [1.0, 1.0]), Item { raw: Raw::Point([f64::NAN, 0.0]), name: String::new() }];
        assert_eq!(snap(&mut items), 0);
    }
}
