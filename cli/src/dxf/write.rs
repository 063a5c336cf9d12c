//! Offsets and the medial axis as DXF drawings (R2000, ASCII), through
//! the `dxf` crate:
//! - offsets: each loop a closed LWPOLYLINE, its arcs as bulges
//!   (`tan(sweep/4)`, negative clockwise), a whole circle a CIRCLE, on a
//!   layer per distance (`OFFSET_0.5`, `OFFSET_-2`);
//! - the medial axis: each straight piece a LINE, each curved one an open
//!   LWPOLYLINE sampled within the tolerance, on the layer `MEDIAL_AXIS`.
//!
//! The crate writes numbers with 12 decimals: too few for small
//! drawings, whose coordinates would lose their last digits. The numbers
//! of the entities are therefore written again, after the crate, with
//! Rust's shortest round-trip formatting (`{}`), so that a reader gets
//! back the same `f64`s.

use std::collections::{BTreeSet, VecDeque};

use dxf::entities::{Circle, Entity, EntityType, Line, LwPolyline};
use dxf::enums::AcadVersion;
use dxf::tables::Layer;
use dxf::{Drawing, LwPolylineVertex};
use segvoronoi::{Diagram, EdgeShape, MedialAxis, Offset, Point};

use crate::medial_output::sample;
use crate::offset_arcs::{bulge, pieces, whole_circle, Piece};

/// The layer of the offsets at `distance`.
pub fn offset_layer(distance: f64) -> String {
    format!("OFFSET_{distance}")
}

/// The layer of the medial axis.
pub const MEDIAL_AXIS_LAYER: &str = "MEDIAL_AXIS";

/// The offsets as a DXF drawing, in the order given.
pub fn offsets(offsets: &[Offset]) -> String {
    let mut out = Out::new();
    for offset in offsets {
        let layer = offset_layer(offset.distance);
        out.layer(&layer);
        for lp in &offset.loops {
            if let Some((centre, radius)) = whole_circle(&lp.pieces) {
                out.circle(centre, radius, &layer);
                continue;
            }
            let vertices: Vec<(Point, f64)> = pieces(&lp.pieces)
                .iter()
                .map(|piece| match *piece {
                    Piece::Line { from, .. } => (from, 0.0),
                    Piece::Arc { centre, from, to, counter_clockwise, .. } => (from, bulge(centre, from, to, counter_clockwise)),
                })
                .collect();
            out.polyline(&vertices, true, &layer);
        }
    }
    out.finish()
}

/// The medial axis as a DXF drawing: per chain, per finite piece (see
/// [`sample`]), a LINE or an LWPOLYLINE within `tolerance`.
pub fn medial_axis(diagram: &Diagram, axis: &MedialAxis, tolerance: f64) -> String {
    let mut out = Out::new();
    out.layer(MEDIAL_AXIS_LAYER);
    for chain in &axis.chains {
        for piece in &chain.pieces {
            let one = segvoronoi::Chain { pieces: vec![*piece], closed: false };
            let Some(points) = sample(diagram, &one, tolerance) else { continue };
            let points: Vec<Point> = points.iter().map(|&[x, y, _]| Point::new(x, y)).collect();
            match (diagram.edge_shape(piece.edge), points.as_slice()) {
                (Some(EdgeShape::Line), &[a, .., b]) => out.line(a, b, MEDIAL_AXIS_LAYER),
                (_, [_, _, ..]) => {
                    let vertices: Vec<(Point, f64)> = points.iter().map(|&p| (p, 0.0)).collect();
                    out.polyline(&vertices, false, MEDIAL_AXIS_LAYER);
                }
                _ => {}
            }
        }
    }
    out.finish()
}

/// A drawing being made, and its entities' numbers in the order the
/// crate writes them (codes 10, 20, 11, 21, 40, 42), to write them again
/// exactly.
struct Out {
    drawing: Drawing,
    exact: VecDeque<f64>,
    layers: BTreeSet<String>,
}

impl Out {
    fn new() -> Out {
        let mut drawing = Drawing::new();
        // LWPOLYLINE is R14's; R2000 is what every reader takes.
        drawing.header.version = AcadVersion::R2000;
        Out { drawing, exact: VecDeque::new(), layers: BTreeSet::new() }
    }

    fn layer(&mut self, name: &str) {
        if self.layers.insert(name.to_string()) {
            self.drawing.add_layer(Layer { name: name.to_string(), ..Default::default() });
        }
    }

    fn add(&mut self, specific: EntityType, layer: &str) {
        let mut entity = Entity::new(specific);
        entity.common.layer = layer.to_string();
        self.drawing.add_entity(entity);
    }

    fn line(&mut self, a: Point, b: Point, layer: &str) {
        self.exact.extend([a.x, a.y, b.x, b.y]);
        self.add(EntityType::Line(Line::new(dxf::Point::new(a.x, a.y, 0.0), dxf::Point::new(b.x, b.y, 0.0))), layer);
    }

    fn circle(&mut self, centre: Point, radius: f64, layer: &str) {
        self.exact.extend([centre.x, centre.y, radius]);
        self.add(EntityType::Circle(Circle::new(dxf::Point::new(centre.x, centre.y, 0.0), radius)), layer);
    }

    /// Vertices with the bulge of the piece from each.
    fn polyline(&mut self, vertices: &[(Point, f64)], closed: bool, layer: &str) {
        let mut polyline = LwPolyline::default();
        for &(p, bulge) in vertices {
            self.exact.extend([p.x, p.y]);
            // the crate writes a bulge only when it is not 0
            if bulge != 0.0 {
                self.exact.push_back(bulge);
            }
            polyline.vertices.push(LwPolylineVertex { x: p.x, y: p.y, bulge, ..Default::default() });
        }
        polyline.set_is_closed(closed);
        self.add(EntityType::LwPolyline(polyline), layer);
    }

    /// The drawing's text, the entities' numbers exact.
    fn finish(self) -> String {
        let mut bytes = Vec::new();
        // Writing to memory fails only on a bug in the crate: then the
        // error is the file's text, which no reader takes.
        if let Err(e) = self.drawing.save(&mut bytes) {
            return format!("segvoronoi could not write the DXF drawing: {e}\n");
        }
        let text = String::from_utf8_lossy(&bytes).into_owned();
        exact_numbers(&text, self.exact).unwrap_or(text)
    }
}

/// The text with the values of codes 10, 20, 11, 21, 40 and 42 in the
/// ENTITIES section replaced, in order, by `exact` (each checked to be the
/// crate's rounding of it); `None` if they do not line up, where the
/// crate's own text is kept.
fn exact_numbers(text: &str, mut exact: VecDeque<f64>) -> Option<String> {
    let newline = if text.contains("\r\n") { "\r\n" } else { "\n" };
    let mut lines: Vec<String> = text.split(newline).map(str::to_string).collect();
    let mut in_entities = false;
    let mut k = 0;
    while k + 1 < lines.len() {
        let (code, value) = (lines[k].trim(), lines[k + 1].trim());
        match code {
            "2" if k >= 2 && lines[k - 1].trim() == "SECTION" => in_entities = value == "ENTITIES",
            "10" | "20" | "11" | "21" | "40" | "42" if in_entities => {
                let exact_value = exact.pop_front()?;
                let written: f64 = value.parse().ok()?;
                if (written - exact_value).abs() > 1e-12 * exact_value.abs().max(1.0) {
                    return None;
                }
                lines[k + 1] = number(exact_value);
            }
            _ => {}
        }
        k += 2;
    }
    exact.is_empty().then(|| lines.join(newline))
}

/// Shortest round-trip, with a decimal point as DXF's reals have.
fn number(v: f64) -> String {
    let text = format!("{v}");
    if text.contains('.') || !v.is_finite() {
        text
    } else {
        text + ".0"
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use segvoronoi::Builder;

    fn read(text: &str) -> Drawing {
        Drawing::load(&mut text.as_bytes()).unwrap()
    }

    #[test]
    fn a_grown_square_is_a_closed_polyline_with_quarter_bulges() {
        let mut b = Builder::new();
        b.add_polygon(&[vec![[0.0, 0.0], [1e-3, 0.0], [1e-3, 1e-3], [0.0, 1e-3]]]).unwrap();
        let d = b.build().unwrap();
        let offset = d.offset(1e-4 / 3.0).unwrap();
        let drawing = read(&offsets(std::slice::from_ref(&offset)));
        let entities: Vec<&Entity> = drawing.entities().collect();
        assert_eq!(entities.len(), 1);
        assert_eq!(entities[0].common.layer, offset_layer(1e-4 / 3.0));
        let EntityType::LwPolyline(p) = &entities[0].specific else { panic!("{:?}", entities[0]) };
        assert!(p.is_closed());
        let pieces = &offset.loops[0].pieces;
        assert_eq!(p.vertices.len(), pieces.len());
        for (v, piece) in p.vertices.iter().zip(pieces) {
            // exactly, not to 12 decimals
            assert_eq!((v.x, v.y), (piece.from().x, piece.from().y));
        }
        let quarter = (std::f64::consts::PI / 8.0).tan();
        assert_eq!(p.vertices.iter().filter(|v| (v.bulge - quarter).abs() < 1e-14).count(), 4);
        assert!(drawing.layers().any(|l| l.name == offset_layer(1e-4 / 3.0)));
    }

    #[test]
    fn a_point_grown_is_a_circle() {
        let mut b = Builder::new();
        b.add_point([0.1, 0.2]).unwrap();
        let d = b.build().unwrap();
        let drawing = read(&offsets(&[d.offset(0.3).unwrap()]));
        let e: Vec<&Entity> = drawing.entities().collect();
        let EntityType::Circle(c) = &e[0].specific else { panic!() };
        assert_eq!((c.center.x, c.center.y, c.radius), (0.1, 0.2, 0.3));
    }

    #[test]
    fn the_axis_of_a_rectangle_is_five_lines() {
        let mut b = Builder::new();
        b.add_polygon(&[vec![[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]]).unwrap();
        let d = b.build().unwrap();
        let drawing = read(&medial_axis(&d, &d.medial_axis(), 1e-3));
        let lines = drawing.entities().filter(|e| matches!(e.specific, EntityType::Line(_))).count();
        assert_eq!(lines, 5);
        assert!(drawing.entities().all(|e| e.common.layer == MEDIAL_AXIS_LAYER));
    }

    #[test]
    fn numbers_keep_a_decimal_point() {
        assert_eq!(number(5.0), "5.0");
        assert_eq!(number(1e-20), "0.00000000000000000001");
        assert_eq!(number(-0.25), "-0.25");
    }
}
