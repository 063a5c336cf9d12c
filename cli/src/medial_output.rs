//! The writers of `--medial-axis`: the chains sampled as one WKT
//! `MULTILINESTRING Z` (z the clearance), or exactly as JSON through
//! `serde_json`.
//!
//! WKT numbers are written with Rust's shortest round-trip formatting (`{}`
//! on `f64`), which never uses an exponent: every WKT reader takes it, and
//! it reads back to the same `f64`; `serde_json`'s numbers (`ryu`) read
//! back to the same `f64` too.

use segvoronoi::{Chain, Diagram, EdgeEnd, EdgeShape, MedialAxis, Point};
use serde_json::{json, Value};

use crate::diagram_output;
use crate::json_values::{number, point, pretty};

/// The sampled points `[x, y, clearance]` of a chain within `tolerance`.
/// The pieces that reach infinity (only without a domain) are cut off: they
/// can only start or end a chain (an end at infinity has no other edges),
/// so the rest is one connected path, or nothing. A point equal to the one
/// before is left out: the centre of a concave arc of the boundary is
/// where several vertices meet, joined by pieces of zero length.
pub fn sample(diagram: &Diagram, chain: &Chain, tolerance: f64) -> Option<Vec<[f64; 3]>> {
    let finite = |end: &EdgeEnd| matches!(end, EdgeEnd::Vertex(_));
    let pieces: Vec<_> = chain.pieces.iter().filter(|p| p.ends.iter().all(finite)).copied().collect();
    if pieces.is_empty() {
        return None;
    }
    let mut points = diagram.sample_chain(&Chain { pieces, closed: chain.closed }, tolerance)?;
    points.dedup_by(|p, q| p[..2] == q[..2]);
    Some(points)
}

/// One `MULTILINESTRING Z`, a linestring per chain (see [`sample`]),
/// `EMPTY` when no chain has a finite piece; ends with a newline.
pub fn wkt(diagram: &Diagram, axis: &MedialAxis, tolerance: f64) -> String {
    let lines: Vec<String> = axis
        .chains
        .iter()
        .filter_map(|chain| sample(diagram, chain, tolerance))
        .map(|points| {
            let points: Vec<String> = points.iter().map(|[x, y, r]| format!("{x} {y} {r}")).collect();
            format!("({})", points.join(", "))
        })
        .collect();
    if lines.is_empty() {
        return "MULTILINESTRING Z EMPTY\n".into();
    }
    format!("MULTILINESTRING Z ({})\n", lines.join(", "))
}

/// The exact chains as JSON:
/// `{"domain": bool, "chains": [{"closed": bool, "pieces": [piece, ...]}, ...]}`,
/// each piece `{"edge": id, "reversed": bool, "ends": [end, end],
/// "clearance": [r, r], "kind": "line" | "parabola" | "conic", ...}`, an
/// end `{"vertex": id, "point": [x, y]}` or `{"direction": [dx, dy]}` (at
/// infinity, where the clearance is `null`). A parabola (between a point
/// and a segment) adds `"focus": [x, y], "directrix": [[x, y], [x, y]]`; a
/// conic (beside a circular arc: a line, parabola, ellipse or hyperbola
/// piece) adds `"sites"`, its two sites as `--diagram` writes them (the
/// one on its left first, in the piece's direction), and, when finite and
/// less than half a turn, `"bezier": {"points": [start, control, end],
/// "weight": w}`, the rational quadratic Bézier curve it is, from the
/// piece's first end to its last.
pub fn json(diagram: &Diagram, axis: &MedialAxis) -> String {
    let chains: Vec<Value> = axis
        .chains
        .iter()
        .map(|chain| {
            let pieces: Vec<Value> = chain
                .pieces
                .iter()
                .map(|piece| {
                    let ends = piece.ends.map(|end| match end {
                        EdgeEnd::Vertex(v) => {
                            let at = diagram.vertex(v).map_or(Point::new(f64::NAN, f64::NAN), |v| v.position);
                            json!({"vertex": v.index(), "point": point(at)})
                        }
                        EdgeEnd::Infinite { direction } => json!({"direction": point(direction)}),
                    });
                    let mut piece_json = json!({
                        "edge": piece.edge.index(),
                        "reversed": piece.reversed,
                        "ends": ends,
                        "clearance": [number(piece.clearance[0]), number(piece.clearance[1])],
                    });
                    let fields = piece_json.as_object_mut().expect("an object");
                    match diagram.edge_shape(piece.edge).unwrap_or(EdgeShape::Line) {
                        EdgeShape::Parabola { focus, directrix: [a, b] } => {
                            fields.insert("kind".into(), json!("parabola"));
                            fields.insert("focus".into(), point(focus));
                            fields.insert("directrix".into(), json!([point(a), point(b)]));
                        }
                        EdgeShape::Line => {
                            fields.insert("kind".into(), json!("line"));
                        }
                        EdgeShape::Conic { .. } => {
                            fields.insert("kind".into(), json!("conic"));
                            let sites = piece.sites.map(|s| diagram_output::site_json(diagram, s, &[]));
                            fields.insert("sites".into(), json!(sites));
                            if let Some((mut points, weight)) = diagram.edge_rational_bezier(piece.edge) {
                                if piece.reversed {
                                    points.reverse();
                                }
                                fields.insert("bezier".into(), json!({"points": points.map(point), "weight": number(weight)}));
                            }
                        }
                        // `EdgeShape` may grow; no other edge exists yet.
                        _ => {
                            fields.insert("kind".into(), json!("other"));
                        }
                    }
                    piece_json
                })
                .collect();
            json!({"closed": chain.closed, "pieces": pieces})
        })
        .collect();
    pretty(&json!({"domain": diagram.has_domain(), "chains": chains}))
}

#[cfg(test)]
mod tests {
    use super::*;
    use segvoronoi::Builder;

    fn rectangle() -> Diagram {
        let mut b = Builder::new();
        b.add_polygon(&[vec![[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]]).unwrap();
        b.build().unwrap()
    }

    #[test]
    fn rectangle_wkt_is_its_five_pieces() {
        let d = rectangle();
        let text = wkt(&d, &d.medial_axis(), 1e-3);
        assert!(text.starts_with("MULTILINESTRING Z ((") && text.ends_with("))\n"), "{text}");
        // straight pieces only: each chain is its vertices, five pieces in all
        let points = text.matches(',').count() + 1;
        let chains = text.matches('(').count() - 1;
        assert_eq!(points - chains, 5, "{text}");
        // z is the distance to the nearest side
        let numbers = text.trim_start_matches("MULTILINESTRING Z ").replace(['(', ')'], "");
        for point in numbers.trim().split(", ") {
            let [x, y, z]: [f64; 3] = point.split(' ').map(|v| v.parse().unwrap()).collect::<Vec<_>>().try_into().unwrap();
            assert!((z - x.min(4.0 - x).min(y).min(2.0 - y)).abs() < 1e-12, "{point}");
        }
    }

    #[test]
    fn rays_are_cut_and_lines_left_out() {
        // Two points: one line, both ends at infinity: nothing finite.
        let mut b = Builder::new();
        b.add_points([[0.0, 0.0], [2.0, 0.0]]).unwrap();
        let d = b.build().unwrap();
        assert_eq!(wkt(&d, &d.medial_axis(), 1e-3), "MULTILINESTRING Z EMPTY\n");
        // Three points: three rays from one vertex, three chains of one
        // infinite piece each.
        let mut b = Builder::new();
        b.add_points([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]]).unwrap();
        let d = b.build().unwrap();
        assert_eq!(wkt(&d, &d.medial_axis(), 1e-3), "MULTILINESTRING Z EMPTY\n");
        let json: Value = serde_json::from_str(&json(&d, &d.medial_axis())).unwrap();
        let pieces: Vec<&Value> = json["chains"].as_array().unwrap().iter().map(|c| &c["pieces"][0]).collect();
        assert_eq!(pieces.len(), 3, "{json}");
        for piece in pieces {
            // one end a vertex, the other at infinity, where the clearance is null
            let directions = piece["ends"].as_array().unwrap().iter().filter(|e| e.get("direction").is_some()).count();
            assert_eq!(directions, 1, "{piece}");
            assert_eq!(piece["clearance"].as_array().unwrap().iter().filter(|c| c.is_null()).count(), 1, "{piece}");
        }
    }

    #[test]
    fn json_names_parabolas_by_focus_and_directrix() {
        // A point above a segment: one parabolic edge between them.
        let mut b = Builder::new();
        b.add_point([2.0, 2.0]).unwrap();
        b.add_segment([[0.0, 0.0], [4.0, 0.0]]).unwrap();
        let d = b.build().unwrap();
        let text = json(&d, &d.medial_axis());
        assert!(text.ends_with("}\n") && !text.contains("NaN") && !text.contains("inf"), "{text}");
        let value: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(value["domain"], json!(false));
        let parabolas: Vec<&Value> = value["chains"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|c| c["pieces"].as_array().unwrap())
            .filter(|p| p["kind"] == "parabola")
            .collect();
        assert!(!parabolas.is_empty(), "{text}");
        for p in parabolas {
            assert_eq!((&p["focus"], &p["directrix"]), (&json!([2.0, 2.0]), &json!([[0.0, 0.0], [4.0, 0.0]])), "{p}");
        }
    }
}
