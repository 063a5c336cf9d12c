//! A drawing's entities as the plane geometry the builder takes: points,
//! line segments and bulged chains (LWPOLYLINE's form: each vertex with
//! the bulge of the piece that starts there), in the drawing's x and y,
//! each with a name for messages.
//!
//! LINE and POINT are in world coordinates; ARC, CIRCLE, LWPOLYLINE,
//! 2D POLYLINE and INSERT in their object coordinate system, from their
//! extrusion direction (see [`Transform::ocs`]). Z is ignored. Blocks are
//! walked through their INSERTs (location, scales, rotation, arrays), to
//! [`MAX_NESTING`] levels. Entities of other types (text, dimensions,
//! hatches, splines, ellipses, ...) and paper space are left out and
//! counted.

use std::collections::{BTreeMap, HashMap};

use dxf::entities::{Entity, EntityType};
use dxf::{Block, Drawing};

use super::transform::{cos_sin_degrees, Transform};
use crate::wkt::Xy;

/// How deep blocks may insert blocks: a block that inserts itself would
/// otherwise never end.
const MAX_NESTING: usize = 16;

/// The most copies one INSERT's array (columns × rows) may make.
const MAX_ARRAY: i64 = 100_000;

/// One entity's geometry, in the drawing's plane.
#[derive(Clone, Debug, PartialEq)]
pub enum Raw {
    Point(Xy),
    Line([Xy; 2]),
    /// Vertices with the bulge of the piece from each to the next (0: a
    /// segment); `closed` joins the last to the first with the last bulge.
    Chain {
        vertices: Vec<(Xy, f64)>,
        closed: bool,
    },
}

/// A piece of geometry and the entity it came from, e.g.
/// `entity 12 (LWPOLYLINE, layer "PART")`.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    pub raw: Raw,
    pub name: String,
}

/// Everything taken from a drawing, and the count of each entity type left out.
#[derive(Debug, Default)]
pub struct Collected {
    pub items: Vec<Item>,
    pub left_out: BTreeMap<String, usize>,
}

/// The model space's entities (counted from 0 in file order, a POLYLINE
/// with its VERTEXes one entity, as the `dxf` crate reads them).
pub fn collect(drawing: &Drawing) -> Result<Collected, String> {
    // AutoCAD's block names are case-insensitive.
    let blocks: HashMap<String, &Block> = drawing.blocks().map(|b| (b.name.to_uppercase(), b)).collect();
    let mut walker = Walker { blocks, out: Collected::default() };
    for (k, entity) in drawing.entities().enumerate() {
        if entity.common.is_in_paper_space {
            *walker.out.left_out.entry("paper space".into()).or_default() += 1;
            continue;
        }
        walker.entity(entity, &describe("entity", k, entity), &Transform::IDENTITY, 0)?;
    }
    Ok(walker.out)
}

/// `entity 12 (LWPOLYLINE, layer "PART")`. (No handle: the crate makes
/// up handles for files that have none, as R12 files may not.)
fn describe(what: &str, k: usize, entity: &Entity) -> String {
    format!("{what} {k} ({}, layer {:?})", type_name(&entity.specific), entity.common.layer)
}

/// The DXF type of an entity (and the block of an INSERT).
fn type_name(specific: &EntityType) -> String {
    match specific {
        EntityType::Line(_) => "LINE".into(),
        EntityType::ModelPoint(_) => "POINT".into(),
        EntityType::Arc(_) => "ARC".into(),
        EntityType::Circle(_) => "CIRCLE".into(),
        EntityType::LwPolyline(_) => "LWPOLYLINE".into(),
        EntityType::Polyline(_) => "POLYLINE".into(),
        EntityType::Insert(i) => format!("INSERT of block {:?}", i.name),
        // The crate has no public type string: its variant's name.
        other => {
            let debug = format!("{other:?}");
            debug.split(|c: char| !c.is_alphanumeric()).next().unwrap_or("?").to_uppercase()
        }
    }
}

fn xy(p: &dxf::Point) -> Xy {
    [p.x, p.y]
}

fn normal(v: &dxf::Vector) -> [f64; 3] {
    [v.x, v.y, v.z]
}

struct Walker<'a> {
    blocks: HashMap<String, &'a Block>,
    out: Collected,
}

impl Walker<'_> {
    fn push(&mut self, raw: Raw, name: &str) {
        self.out.items.push(Item { raw, name: name.to_string() });
    }

    fn left_out(&mut self, what: String) {
        *self.out.left_out.entry(what).or_default() += 1;
    }

    /// One entity, mapped by `outer` (its blocks' insertions).
    fn entity(&mut self, entity: &Entity, name: &str, outer: &Transform, depth: usize) -> Result<(), String> {
        let fail = |why: String| format!("{name}: {why}");
        // Its OCS, then the insertions around it.
        let placed = |n: &dxf::Vector| Transform::ocs(normal(n)).map(|t| t.then(outer)).map_err(fail);
        match &entity.specific {
            EntityType::Line(line) => self.push(Raw::Line([outer.apply(xy(&line.p1)), outer.apply(xy(&line.p2))]), name),
            EntityType::ModelPoint(point) => self.push(Raw::Point(outer.apply(xy(&point.location))), name),
            EntityType::Arc(arc) => {
                let t = placed(&arc.normal)?;
                let raw = arc_chain(xy(&arc.center), arc.radius, Some((arc.start_angle, arc.end_angle)), &t).map_err(fail)?;
                self.push(raw, name);
            }
            EntityType::Circle(circle) => {
                let t = placed(&circle.normal)?;
                self.push(arc_chain(xy(&circle.center), circle.radius, None, &t).map_err(fail)?, name);
            }
            EntityType::LwPolyline(p) => {
                let t = placed(&p.extrusion_direction)?;
                let vertices = p.vertices.iter().map(|v| ([v.x, v.y], v.bulge));
                self.push(chain(vertices, p.is_closed(), &t).map_err(fail)?, name);
            }
            EntityType::Polyline(p) => {
                if p.is_polyface_mesh() || p.is_3d_polygon_mesh() {
                    self.left_out("POLYLINE mesh".into());
                    return Ok(());
                }
                // A 3D polyline's vertices are in world coordinates (and
                // have no bulges); a 2D one's in its OCS.
                let t = if p.is_3d_polyline() { *outer } else { placed(&p.normal)? };
                let vertices = p
                    .vertices()
                    // a spline's frame is not on the curve; its fit vertices are
                    .filter(|v| !v.is_spline_frame_control_point())
                    .map(|v| (xy(&v.location), if p.is_3d_polyline() { 0.0 } else { v.bulge }));
                self.push(chain(vertices, p.is_closed(), &t).map_err(fail)?, name);
            }
            EntityType::Insert(insert) => self.insert(insert, name, outer, depth)?,
            other => self.left_out(type_name(other)),
        }
        Ok(())
    }

    /// A block's entities at each place of an INSERT (one, or its array's
    /// cells).
    fn insert(&mut self, insert: &dxf::entities::Insert, name: &str, outer: &Transform, depth: usize) -> Result<(), String> {
        let block = *self
            .blocks
            .get(&insert.name.to_uppercase())
            .ok_or_else(|| format!("{name}: the block {:?} is not in the drawing", insert.name))?;
        if depth >= MAX_NESTING {
            return Err(format!("{name}: blocks nested more than {MAX_NESTING} deep (a block that inserts itself?)"));
        }
        let ocs = Transform::ocs(normal(&insert.extrusion_direction)).map_err(|why| format!("{name}: {why}"))?;
        let (columns, rows) = (i64::from(insert.column_count.max(1)), i64::from(insert.row_count.max(1)));
        if columns * rows > MAX_ARRAY {
            return Err(format!("{name}: an array of {columns} × {rows} insertions (at most {MAX_ARRAY} are taken)"));
        }
        let scales = [insert.x_scale_factor, insert.y_scale_factor];
        for row in 0..rows {
            for column in 0..columns {
                let offset = [column as f64 * insert.column_spacing, row as f64 * insert.row_spacing];
                let here = Transform::insertion(xy(&block.base_point), xy(&insert.location), scales, insert.rotation, offset)
                    .then(&ocs)
                    .then(outer);
                let cell = if columns * rows > 1 { format!(" (row {row}, column {column})") } else { String::new() };
                for (j, entity) in block.entities.iter().enumerate() {
                    let inner = format!("{name}{cell}, {}", describe("block entity", j, entity));
                    self.entity(entity, &inner, &here, depth + 1)?;
                }
            }
        }
        Ok(())
    }
}

/// Why an arc cannot be mapped by `t`.
fn check_circles(t: &Transform) -> Result<(), String> {
    if t.keeps_circles() {
        return Ok(());
    }
    Err("its insertion scales x and y unequally, which makes its circular arcs ellipses: not supported (explode the block \
         in the CAD program, or insert it with equal scales)"
        .into())
}

/// An ARC (`angles` its start and end in degrees, counter-clockwise in
/// its OCS) or, without angles, a CIRCLE (two half circles): a chain of
/// its ends with their bulges, mapped by `t`. An ARC whose angles are
/// equal (modulo 360°) is the whole circle.
fn arc_chain(centre: Xy, radius: f64, angles: Option<(f64, f64)>, t: &Transform) -> Result<Raw, String> {
    if !(radius.is_finite() && radius > 0.0 && centre.iter().all(|c| c.is_finite())) {
        return Err(format!(
            "a circle around ({}, {}) of radius {radius}: needs a finite centre and a positive radius",
            centre[0], centre[1]
        ));
    }
    check_circles(t)?;
    let at = |degrees: f64| {
        let (cos, sin) = cos_sin_degrees(degrees);
        t.apply([centre[0] + radius * cos, centre[1] + radius * sin])
    };
    // A mirror turns counter-clockwise into clockwise.
    let sign = if t.mirrors() { -1.0 } else { 1.0 };
    let (start, end) = angles.unwrap_or((0.0, 0.0));
    let sweep = (end - start).rem_euclid(360.0);
    if !sweep.is_finite() {
        return Err(format!("its angles {start} and {end} are not finite"));
    }
    if sweep == 0.0 {
        // two half circles, counter-clockwise: bulge 1 each
        return Ok(Raw::Chain { vertices: vec![(at(start), sign), (at(start + 180.0), sign)], closed: true });
    }
    // tan(45°) is 0.9999999999999999 in f64: a half circle's is 1
    let bulge = if sweep == 180.0 { 1.0 } else { (sweep.to_radians() / 4.0).tan() };
    Ok(Raw::Chain { vertices: vec![(at(start), sign * bulge), (at(end), 0.0)], closed: false })
}

/// A polyline's vertices and bulges mapped by `t` (a mirror changes the
/// bulges' sign); arcs need a map that keeps circles.
fn chain(vertices: impl Iterator<Item = (Xy, f64)>, closed: bool, t: &Transform) -> Result<Raw, String> {
    let sign = if t.mirrors() { -1.0 } else { 1.0 };
    let vertices: Vec<(Xy, f64)> = vertices.map(|(p, bulge)| (t.apply(p), sign * bulge)).collect();
    if vertices.iter().any(|&(_, b)| b != 0.0) {
        check_circles(t)?;
    }
    Ok(Raw::Chain { vertices, closed })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_arc_is_its_ends_and_bulge() {
        let raw = arc_chain([10.0, 10.0], 5.0, Some((0.0, 90.0)), &Transform::IDENTITY).unwrap();
        let Raw::Chain { vertices, closed } = raw else { panic!() };
        assert!(!closed);
        assert_eq!((vertices[0].0, vertices[1].0), ([15.0, 10.0], [10.0, 15.0]));
        assert!((vertices[0].1 - (std::f64::consts::PI / 8.0).tan()).abs() < 1e-15);
        // the angles wrap: 270° to 90° is a half circle through 0°
        let Raw::Chain { vertices, .. } = arc_chain([0.0, 0.0], 1.0, Some((270.0, 90.0)), &Transform::IDENTITY).unwrap() else {
            panic!()
        };
        assert_eq!((vertices[0].0, vertices[1].0, vertices[0].1), ([0.0, -1.0], [0.0, 1.0], 1.0));
    }

    #[test]
    fn a_downward_normal_mirrors_x_and_turns_arcs_clockwise() {
        let down = Transform::ocs([0.0, 0.0, -1.0]).unwrap();
        let Raw::Chain { vertices, .. } = arc_chain([10.0, 0.0], 1.0, Some((0.0, 90.0)), &down).unwrap() else { panic!() };
        // OCS (11, 0) → (-11, 0), OCS (10, 1) → (-10, 1); clockwise
        assert_eq!((vertices[0].0, vertices[1].0), ([-11.0, 0.0], [-10.0, 1.0]));
        assert!(vertices[0].1 < 0.0);
    }

    #[test]
    fn circles_are_two_halves_and_bad_radii_are_refused() {
        let Raw::Chain { vertices, closed } = arc_chain([1.0, 2.0], 3.0, None, &Transform::IDENTITY).unwrap() else { panic!() };
        assert!(closed);
        assert_eq!(vertices, [([4.0, 2.0], 1.0), ([-2.0, 2.0], 1.0)]);
        assert!(arc_chain([0.0, 0.0], 0.0, None, &Transform::IDENTITY).unwrap_err().contains("positive radius"));
        assert!(arc_chain([0.0, 0.0], f64::NAN, None, &Transform::IDENTITY).is_err());
        let stretched = Transform::insertion([0.0, 0.0], [0.0, 0.0], [2.0, 1.0], 0.0, [0.0, 0.0]);
        assert!(arc_chain([0.0, 0.0], 1.0, None, &stretched).unwrap_err().contains("ellipses"));
        // a stretched polyline of segments is fine
        assert!(chain([([0.0, 0.0], 0.0), ([1.0, 0.0], 0.0)].into_iter(), false, &stretched).is_ok());
    }
}
