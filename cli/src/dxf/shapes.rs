//! The DXF geometry as the shapes the rest of the program takes (those of
//! WKT), in file order, each with the name of its entities:
//! - POINT: a point;
//! - a polyline (LWPOLYLINE, POLYLINE) of segments only: a polygon ring
//!   when closed (by its flag, or by ending where it starts), else a
//!   linestring;
//! - a polyline with arcs, a CIRCLE: a chain of segments and arcs, a
//!   polygon ring (bounding the domain) when closed, else an obstacle;
//! - LINEs and ARCs (and open polylines of one piece): closed groups
//!   become polygon rings (see `rings`), the others single segments and
//!   arcs (obstacles).

use segvoronoi::CircularArc;

use super::entities::{Item, Raw};
use super::rings::rings;
use crate::wkt::{Shape, Step, Xy};

/// The shapes, a name for each, and notes on what was dropped.
pub struct Made {
    pub shapes: Vec<Shape>,
    pub names: Vec<String>,
    pub notes: Vec<String>,
}

pub fn shapes(items: &[Item]) -> Result<Made, String> {
    let mut made = Made { shapes: Vec::new(), names: Vec::new(), notes: Vec::new() };
    // the LINEs and ARCs (and open polylines of one piece): ends and bulge
    let pieces: Vec<(usize, [Xy; 2], f64)> = items
        .iter()
        .enumerate()
        .filter_map(|(k, item)| match &item.raw {
            Raw::Line(ends) => Some((k, *ends, 0.0)),
            Raw::Chain { vertices, closed: false } if vertices.len() == 2 => {
                Some((k, [vertices[0].0, vertices[1].0], vertices[0].1))
            }
            _ => None,
        })
        .collect();
    let joined = rings(&pieces.iter().map(|&(_, ends, bulge)| (ends, bulge)).collect::<Vec<_>>());
    // what each piece becomes: the first piece of a ring stands for it
    let mut ring_at: std::collections::HashMap<usize, usize> = Default::default();
    let mut in_ring = std::collections::HashSet::new();
    for (r, ring) in joined.rings.iter().enumerate() {
        let first = ring.lines.iter().map(|&l| pieces[l].0).min().expect("a ring has pieces");
        ring_at.insert(first, r);
        in_ring.extend(ring.lines.iter().map(|&l| pieces[l].0));
    }
    if !joined.dropped.is_empty() {
        let names: Vec<&str> = joined.dropped.iter().map(|&l| items[pieces[l].0].name.as_str()).collect();
        made.notes.push(format!(
            "left out {} LINE{} or ARC{} of zero length or drawn twice: {}",
            names.len(),
            if names.len() == 1 { "" } else { "s" },
            if names.len() == 1 { "" } else { "s" },
            list(&names)
        ));
    }
    let dropped: std::collections::HashSet<usize> = joined.dropped.iter().map(|&l| pieces[l].0).collect();
    for (k, item) in items.iter().enumerate() {
        check_finite(item)?;
        if let Some(&r) = ring_at.get(&k) {
            let ring = &joined.rings[r];
            let names: Vec<&str> = ring.lines.iter().map(|&l| items[pieces[l].0].name.as_str()).collect();
            let what = if ring.points.iter().any(|&(_, b)| b != 0.0) { "LINEs and ARCs" } else { "LINEs" };
            let name = format!("the ring of {what} {}", list(&names));
            let shape = chain(&ring.points, true, &name)?.expect("a ring has two vertices or more");
            made.push(shape, name);
            continue;
        }
        if in_ring.contains(&k) || dropped.contains(&k) {
            continue;
        }
        match &item.raw {
            Raw::Point(p) => made.push(Shape::Point(*p), item.name.clone()),
            Raw::Line(ends) => made.push(Shape::LineString(ends.to_vec()), item.name.clone()),
            Raw::Chain { vertices, closed } => match chain(vertices, *closed, &item.name)? {
                Some(shape) => made.push(shape, item.name.clone()),
                None => made.notes.push(format!("left out {}: fewer than two distinct vertices", item.name)),
            },
        }
    }
    Ok(made)
}

impl Made {
    fn push(&mut self, shape: Shape, name: String) {
        self.shapes.push(shape);
        self.names.push(name);
    }
}

/// A coordinate or bulge that is not finite (a file may spell `nan` or
/// `1e999`), refused naming the entity rather than by the library's index.
fn check_finite(item: &Item) -> Result<(), String> {
    let finite = |p: &Xy| p.iter().all(|c| c.is_finite());
    let ok = match &item.raw {
        Raw::Point(p) => finite(p),
        Raw::Line(ends) => ends.iter().all(finite),
        Raw::Chain { vertices, .. } => vertices.iter().all(|(p, b)| finite(p) && b.is_finite()),
    };
    if ok {
        Ok(())
    } else {
        Err(format!("{}: a coordinate or bulge is not finite", item.name))
    }
}

/// Names joined by `; `, at most the first five and a count of the rest.
fn list(names: &[&str]) -> String {
    let mut text = names.iter().take(5).copied().collect::<Vec<_>>().join("; ");
    if names.len() > 5 {
        text.push_str(&format!(" and {} more", names.len() - 5));
    }
    text
}

/// A polyline's shape, `None` with fewer than two distinct vertices.
fn chain(vertices: &[(Xy, f64)], closed: bool, name: &str) -> Result<Option<Shape>, String> {
    // A repeated vertex ends a piece of zero length: drop the first copy,
    // so that the piece after it keeps its bulge.
    let mut kept: Vec<(Xy, f64)> = Vec::with_capacity(vertices.len());
    for &(p, bulge) in vertices {
        match kept.last_mut() {
            Some(last) if last.0 == p => *last = (p, bulge),
            _ => kept.push((p, bulge)),
        }
    }
    // Ending where it starts closes it, flag or not; the piece of zero
    // length back to the start is dropped.
    let mut closed = closed;
    if kept.len() > 2 && kept.first().map(|v| v.0) == kept.last().map(|v| v.0) {
        kept.pop();
        closed = true;
    }
    if kept.len() < 2 {
        return Ok(None);
    }
    let pieces = if closed { kept.len() } else { kept.len() - 1 };
    let piece = |k: usize| (kept[k].0, kept[(k + 1) % kept.len()].0, kept[k].1);
    let points: Vec<Xy> = kept.iter().map(|v| v.0).collect();
    if (0..pieces).all(|k| piece(k).2 == 0.0) {
        return Ok(Some(match (closed, points.len()) {
            (true, 3..) => Shape::Polygon(vec![points]),
            // two vertices closed: a segment there and back, an obstacle
            _ => Shape::LineString(points),
        }));
    }
    let mut steps = Vec::with_capacity(pieces);
    for k in 0..pieces {
        let (from, to, bulge) = piece(k);
        steps.push(if bulge == 0.0 {
            Step::Segment([from, to])
        } else {
            Step::Arc(CircularArc::from_bulge(from, to, bulge).map_err(|e| format!("{name}, piece {k}: {e}"))?)
        });
    }
    Ok(Some(if closed { Shape::CurveRings(vec![steps]) } else { Shape::Curve(steps) }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn item(raw: Raw, name: &str) -> Item {
        Item { raw, name: name.into() }
    }

    #[test]
    fn closed_polylines_of_segments_are_polygons() {
        let square = vec![([0.0, 0.0], 0.0), ([1.0, 0.0], 0.0), ([1.0, 1.0], 0.0), ([0.0, 1.0], 0.0)];
        let made = shapes(&[item(Raw::Chain { vertices: square.clone(), closed: true }, "a")]).unwrap();
        assert_eq!(made.shapes, [Shape::Polygon(vec![vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]])]);
        // open, but back at its start: closed too
        let mut back = square.clone();
        back.push(([0.0, 0.0], 0.0));
        let made = shapes(&[item(Raw::Chain { vertices: back, closed: false }, "b")]).unwrap();
        assert!(matches!(&made.shapes[0], Shape::Polygon(r) if r[0].len() == 4));
        // open: a linestring
        let made = shapes(&[item(Raw::Chain { vertices: square, closed: false }, "c")]).unwrap();
        assert!(matches!(&made.shapes[0], Shape::LineString(p) if p.len() == 4));
    }

    #[test]
    fn bulges_make_arcs_and_rings_of_lines_are_named() {
        let slot = vec![([0.0, 0.0], 0.0), ([2.0, 0.0], 1.0), ([2.0, 2.0], 0.0), ([0.0, 2.0], 1.0)];
        let items = [
            item(Raw::Chain { vertices: slot, closed: true }, "entity 0"),
            item(Raw::Line([[5.0, 0.0], [6.0, 0.0]]), "entity 1"),
            item(Raw::Line([[6.0, 0.0], [5.0, 1.0]]), "entity 2"),
            item(Raw::Line([[5.0, 1.0], [5.0, 0.0]]), "entity 3"),
            item(Raw::Point([9.0, 9.0]), "entity 4"),
        ];
        let made = shapes(&items).unwrap();
        assert_eq!(made.shapes.len(), 3);
        let Shape::CurveRings(rings) = &made.shapes[0] else { panic!("{:?}", made.shapes[0]) };
        assert_eq!(rings[0].len(), 4);
        assert!(matches!(rings[0][1], Step::Arc(a) if a.centre() == segvoronoi::Point::new(2.0, 1.0)));
        assert!(matches!(&made.shapes[1], Shape::Polygon(r) if r[0].len() == 3));
        assert_eq!(made.names[1], "the ring of LINEs entity 1; entity 2; entity 3");
        assert_eq!(made.names[2], "entity 4");
    }

    #[test]
    fn bad_numbers_name_the_entity() {
        let bad = vec![([0.0, 0.0], f64::INFINITY), ([1.0, 0.0], 0.0)];
        let e = shapes(&[item(Raw::Chain { vertices: bad, closed: false }, "entity 7 (LWPOLYLINE, layer \"0\")")]).err().unwrap();
        assert_eq!(e, "entity 7 (LWPOLYLINE, layer \"0\"): a coordinate or bulge is not finite");
        let e = shapes(&[item(Raw::Line([[0.0, f64::NAN], [1.0, 0.0]]), "entity 2 (LINE, layer \"0\")")]).err().unwrap();
        assert!(e.starts_with("entity 2 (LINE"), "{e}");
        // a bulge so large its circle leaves f64: the library's word, with the piece
        let huge = vec![([0.0, 0.0], 1e300), ([1e-300, 0.0], 0.0)];
        if let Err(e) = shapes(&[item(Raw::Chain { vertices: huge, closed: false }, "entity 3")]) {
            assert!(e.starts_with("entity 3, piece 0: "), "{e}");
        }
    }
}
