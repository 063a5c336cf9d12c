//! The writer of `--diagram`: the whole diagram as JSON, for any input
//! (points, segments, arcs), one site, vertex or edge a line:
//!
//! ```text
//! {"sites": [
//! {"id": 0, "name": "P0", "kind": "point", "position": [x, y], "inputs": [i, ...]},
//! {"id": 4, "name": "S0", "kind": "segment", "start": [x, y], "end": [x, y], "input": j, "endpoints": [a, b]},
//! {"id": 9, "name": "A0", "kind": "arc", "start": [x, y], "end": [x, y], "centre": [x, y],
//!  "radius": r, "bulge": b, "ccw": true, "input": j, "endpoints": [a, b]}
//! ],
//! "vertices": [
//! {"id": 0, "position": [x, y], "clearance": r, "sites": [s, t, u]}
//! ],
//! "edges": [
//! {"id": 0, "kind": "line", "sites": [s, t], "separator": false, "ends": [{"vertex": v}, {"direction": [dx, dy]}]},
//! {"id": 1, "kind": "parabola", "sites": [s, t], "separator": false, "ends": [{"vertex": v}, {"vertex": w}],
//!  "bezier": {"points": [[x, y], [x, y], [x, y]], "weight": 1.0}}
//! ]}
//! ```
//!
//! Site names are the topology text's (`P<id>`, `S<j>`, `A<j>`); a point
//! site's `inputs` are the input points it stands for (several when
//! repeated, none for an endpoint only); `endpoints` are the endpoint
//! sites of a segment (`start`, `end`) or an arc. A vertex's `sites` are
//! the three whose cells meet there, counter-clockwise, and `clearance` its
//! distance to each (`null` beyond the range of `f64`). An edge's `sites`
//! are the one on its left and on its right walking from `ends[0]` to
//! `ends[1]`; an end is a finite vertex or, at infinity, the unit direction
//! the edge runs off in. A finite curved edge has `bezier`: the rational
//! quadratic Bézier curve that it is, from the position of `ends[0]` to
//! that of `ends[1]`, its control point's weight 1 for a parabola (below 1
//! for an ellipse, above for a hyperbola; absent for a conic piece that
//! turns by half a turn or more). Numbers are `serde_json`'s shortest
//! round-trip decimals.

use std::fmt::Write;

use segvoronoi::{Diagram, EdgeEnd, EdgeShape, Site, SiteId};
use serde_json::{json, Value};

use crate::json_values::{number, point};

/// The diagram as JSON (see the module doc), ending with a newline.
/// `input_points` is how many points the builder was given.
pub fn json(diagram: &Diagram, input_points: usize) -> String {
    let mut inputs: Vec<(usize, usize)> =
        (0..input_points).filter_map(|i| Some((diagram.site_of_input(i)?.index(), i))).collect();
    inputs.sort_unstable();
    let sites = diagram.site_ids().map(|site| {
        let at = inputs.partition_point(|&(s, _)| s < site.index());
        let mine: Vec<usize> = inputs[at..].iter().take_while(|&&(s, _)| s == site.index()).map(|&(_, i)| i).collect();
        site_json(diagram, site, &mine)
    });
    let vertices = diagram.vertices().map(|v| {
        let sites = v.sites.map(SiteId::index);
        json!({"id": v.id.index(), "position": point(v.position), "clearance": number(v.clearance), "sites": sites})
    });
    let edges = diagram.edges().map(|e| {
        let kind = match diagram.edge_shape(e.id) {
            Some(EdgeShape::Line) => "line",
            Some(EdgeShape::Parabola { .. }) => "parabola",
            Some(EdgeShape::Conic { .. }) => "conic",
            _ => "curve",
        };
        let ends = e.ends.map(|end| match end {
            EdgeEnd::Vertex(v) => json!({"vertex": v.index()}),
            EdgeEnd::Infinite { direction } => json!({"direction": point(direction)}),
        });
        let mut edge = json!({
            "id": e.id.index(),
            "kind": kind,
            "sites": e.sites.map(SiteId::index),
            "separator": diagram.is_separator(e.id).unwrap_or(false),
            "ends": ends,
        });
        if let Some((points, weight)) = diagram.edge_rational_bezier(e.id) {
            edge["bezier"] = json!({"points": points.map(point), "weight": number(weight)});
        }
        edge
    });
    let mut out = String::from("{");
    section(&mut out, "sites", sites);
    out.push_str(",\n");
    section(&mut out, "vertices", vertices);
    out.push_str(",\n");
    section(&mut out, "edges", edges);
    out.push_str("}\n");
    out
}

/// `"title": [` and the items, one a line, then `]`: each item is
/// serialised as it comes, so that no tree of the whole diagram is held.
fn section(out: &mut String, title: &str, items: impl Iterator<Item = Value>) {
    let _ = write!(out, "\"{title}\": [");
    for (k, value) in items.enumerate() {
        let _ = write!(out, "{}\n{value}", if k == 0 { "" } else { "," });
    }
    out.push_str("\n]");
}

/// One site (see the module doc); `inputs`: the input points of a point site.
pub fn site_json(diagram: &Diagram, site: SiteId, inputs: &[usize]) -> Value {
    let id = site.index();
    let endpoints = diagram.segment_endpoints(site).map(|e| e.map(SiteId::index));
    match diagram.site(site) {
        Some(Site::Point(p)) => {
            json!({"id": id, "name": format!("P{id}"), "kind": "point", "position": point(p), "inputs": inputs})
        }
        Some(Site::Segment { a, b }) => {
            let j = diagram.segment_input_index(site);
            json!({
                "id": id,
                "name": j.map(|j| format!("S{j}")),
                "kind": "segment",
                "start": point(a),
                "end": point(b),
                "input": j,
                "endpoints": endpoints,
            })
        }
        Some(Site::Arc(arc)) => {
            let j = diagram.arc_input_index(site);
            json!({
                "id": id,
                "name": j.map(|j| format!("A{j}")),
                "kind": "arc",
                "start": point(arc.start()),
                "end": point(arc.end()),
                "centre": point(arc.centre()),
                "radius": number(arc.radius()),
                "bulge": number(arc.bulge()),
                "ccw": arc.is_counter_clockwise(),
                "input": j,
                "endpoints": endpoints,
            })
        }
        // a site kind this writer does not know yet: its id and nothing more
        _ => json!({"id": id, "kind": "unknown"}),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use segvoronoi::Builder;

    #[test]
    fn points_and_a_segment() {
        let mut b = Builder::new();
        b.add_points([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0], [0.0, 4.0]]).unwrap();
        b.add_segment([[1.0, 1.0], [3.0, 2.0]]).unwrap();
        let d = b.build().unwrap();
        let text = json(&d, b.point_count());
        let v: Value = serde_json::from_str(&text).unwrap();
        let sites = v["sites"].as_array().unwrap();
        assert_eq!(sites.len(), d.site_count());
        // the repeated point: one site, two inputs
        let repeated = sites.iter().find(|s| s["position"] == json!([0.0, 4.0])).unwrap();
        assert_eq!(repeated["inputs"], json!([2, 3]));
        let segment = sites.iter().find(|s| s["kind"] == "segment").unwrap();
        assert_eq!((segment["name"].as_str(), segment["input"].as_u64()), (Some("S0"), Some(0)));
        let ends: Vec<usize> = segment["endpoints"].as_array().unwrap().iter().map(|e| e.as_u64().unwrap() as usize).collect();
        assert_eq!(sites[ends[0]]["position"], json!([1.0, 1.0]));
        assert_eq!(sites[ends[1]]["position"], json!([3.0, 2.0]));
        assert!(sites[ends[0]]["inputs"].as_array().unwrap().is_empty());
        let vertices = v["vertices"].as_array().unwrap();
        assert_eq!(vertices.len(), d.vertex_count());
        for (k, vertex) in vertices.iter().enumerate() {
            assert_eq!(vertex["id"], json!(k));
            assert_eq!(vertex["sites"].as_array().unwrap().len(), 3);
            assert!(vertex["clearance"].as_f64().unwrap() >= 0.0);
        }
        let edges = v["edges"].as_array().unwrap();
        assert_eq!(edges.len(), d.edge_count());
        assert!(edges.iter().any(|e| e["kind"] == "parabola") && edges.iter().any(|e| e["separator"] == true));
        assert!(edges.iter().any(|e| e["ends"][1]["direction"].is_array()));
        for e in edges.iter().filter(|e| e["kind"] == "parabola") {
            let bezier = &e["bezier"];
            assert_eq!((bezier["points"].as_array().unwrap().len(), bezier["weight"].as_f64()), (3, Some(1.0)), "{e}");
            let start = &v["vertices"][e["ends"][0]["vertex"].as_u64().unwrap() as usize]["position"];
            assert_eq!(&bezier["points"][0], start);
        }
        assert!(edges.iter().filter(|e| e["kind"] == "line").all(|e| e.get("bezier").is_none()));
        // one item a line
        assert_eq!(text.lines().count(), 6 + d.site_count() + d.vertex_count() + d.edge_count());
    }

    #[test]
    fn an_empty_diagram() {
        let d = Builder::new().build().unwrap();
        let v: Value = serde_json::from_str(&json(&d, 0)).unwrap();
        assert_eq!(v, json!({"sites": [], "vertices": [], "edges": []}));
    }
}
