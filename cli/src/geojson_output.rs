//! `--medial-axis` and `--offsets` as GeoJSON (RFC 7946), through the
//! `geojson` crate: the same samples as the WKT writers, so a GIS reads
//! what the WKT says, with the clearance and the distance as properties.

use geojson::{Feature, FeatureCollection, Geometry, GeometryValue, JsonObject};
use segvoronoi::{Diagram, MedialAxis, Offset};
use serde_json::json;

use crate::medial_output;

/// The medial axis as one Feature: a MultiLineString of the chains sampled
/// within `tolerance` (the pieces to infinity cut off, as in WKT), each
/// position `[x, y, clearance]` (GeoJSON's third ordinate is a height, so a
/// reader that ignores it still draws the axis), and the property
/// `clearance`, one array per line, for readers that drop the third
/// ordinate. The geometry is `null` when nothing is finite (no chain).
pub fn medial_axis(diagram: &Diagram, axis: &MedialAxis, tolerance: f64) -> String {
    let lines: Vec<Vec<[f64; 3]>> =
        axis.chains.iter().filter_map(|chain| medial_output::sample(diagram, chain, tolerance)).collect();
    let clearance: Vec<Vec<f64>> = lines.iter().map(|line| line.iter().map(|p| p[2]).collect()).collect();
    let geometry = (!lines.is_empty())
        .then(|| Geometry::new(GeometryValue::new_multi_line_string(lines.iter().map(|line| line.iter().copied()))));
    let mut properties = JsonObject::new();
    properties.insert("kind".into(), json!("medial axis"));
    properties.insert("domain".into(), json!(diagram.has_domain()));
    properties.insert("clearance".into(), json!(clearance));
    let feature = Feature { geometry, properties: Some(properties), ..Feature::default() };
    format!("{}\n", geojson::GeoJson::Feature(feature))
}

/// The offsets as a FeatureCollection, a Feature per distance in the order
/// asked: a MultiPolygon (per outer loop its ring, counter-clockwise, then
/// its holes, clockwise, as RFC 7946 asks; the library's loops have the
/// region on their left, which is that orientation) sampled within
/// `tolerance` and closed, and the properties `distance` and `area` (the
/// exact region's). An empty region is an empty MultiPolygon.
pub fn offsets(offsets: &[Offset], tolerance: f64) -> String {
    let features = offsets
        .iter()
        .map(|offset| {
            let polygons: Vec<Vec<Vec<[f64; 2]>>> = offset
                .polygons()
                .iter()
                .map(|loops| {
                    loops
                        .iter()
                        .map(|&k| {
                            let points = offset.loops[k].polyline(tolerance).unwrap_or_default();
                            points.iter().chain(points.first()).map(|p| [p.x, p.y]).collect()
                        })
                        .collect()
                })
                .collect();
            let mut properties = JsonObject::new();
            properties.insert("distance".into(), json!(offset.distance));
            properties.insert("area".into(), json!(offset.area()));
            Feature {
                geometry: Some(Geometry::new(GeometryValue::new_multi_polygon(polygons))),
                properties: Some(properties),
                ..Feature::default()
            }
        })
        .collect();
    let collection = FeatureCollection { bbox: None, features, foreign_members: None };
    format!("{}\n", geojson::GeoJson::FeatureCollection(collection))
}
