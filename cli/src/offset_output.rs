//! The writers of `--offsets`: per distance, the region sampled as one WKT
//! `MULTIPOLYGON`, or the exact loops as JSON through `serde_json`, as
//! `medial_output` writes the medial axis (`null` where not finite).

use std::fmt::Write;

use segvoronoi::{Offset, OffsetPiece};

use serde_json::{json, Value};

use crate::json_values::{number, point, pretty};

/// One `MULTIPOLYGON` line per offset, in order: per outer loop (see
/// [`Offset::polygons`]) its ring and then its holes, each sampled within
/// `tolerance` (the library's polylines: within the tolerance of the exact
/// loops, simple and nested as they are) and closed by repeating its first
/// point. `MULTIPOLYGON EMPTY` when the region is empty. `tolerance` must be
/// positive.
pub fn wkt(offsets: &[Offset], tolerance: f64) -> String {
    let mut out = String::new();
    for offset in offsets {
        let polygons: Vec<String> = offset
            .polygons()
            .iter()
            .map(|loops| {
                let rings: Vec<String> =
                    loops.iter().map(|&k| ring(&offset.loops[k].polyline(tolerance).unwrap_or_default())).collect();
                format!("({})", rings.join(", "))
            })
            .collect();
        if polygons.is_empty() {
            out.push_str("MULTIPOLYGON EMPTY\n");
        } else {
            let _ = writeln!(out, "MULTIPOLYGON ({})", polygons.join(", "));
        }
    }
    out
}

/// A closed WKT ring: the points, then the first again.
fn ring(points: &[segvoronoi::Point]) -> String {
    let text: Vec<String> = points.iter().chain(points.first()).map(|p| format!("{} {}", p.x, p.y)).collect();
    format!("({})", text.join(", "))
}

/// The exact offsets as JSON:
/// `{"offsets": [{"distance": d, "area": a, "loops": [loop, ...]}, ...]}`,
/// in the order asked; `area` the region's, from the exact pieces. A loop
/// is `{"parent": index | null, "hole": bool, "signed_area": a,
/// "pieces": [piece, ...]}` (`parent` indexes the same `loops`, and comes
/// before its children; `signed_area` is positive for an outer,
/// counter-clockwise loop); a piece is `{"kind": "line" | "arc", "site": id,
/// "from": [x, y], "to": [x, y]}`, an arc adding `"centre": [x, y],
/// "radius": r, "counter_clockwise": bool` (a whole circle has `from` equal
/// to `to`). The region is on the left of every loop.
pub fn json(offsets: &[Offset]) -> String {
    let offsets: Vec<Value> = offsets
        .iter()
        .map(|offset| {
            let loops: Vec<Value> = offset
                .loops
                .iter()
                .map(|lp| {
                    let pieces: Vec<Value> = lp
                        .pieces
                        .iter()
                        .map(|piece| {
                            let (kind, arc) = match *piece {
                                OffsetPiece::Line { .. } => ("line", None),
                                OffsetPiece::Arc { centre, radius, counter_clockwise, .. } => (
                                    "arc",
                                    Some(json!({"centre": point(centre), "radius": number(radius), "counter_clockwise": counter_clockwise})),
                                ),
                                // `OffsetPiece` may grow (curved sites); no such piece exists yet.
                                _ => ("other", None),
                            };
                            let mut value = json!({
                                "kind": kind,
                                "site": piece.site().index(),
                                "from": point(piece.from()),
                                "to": point(piece.to()),
                            });
                            if let (Some(Value::Object(arc)), Some(fields)) = (arc, value.as_object_mut()) {
                                fields.extend(arc);
                            }
                            value
                        })
                        .collect();
                    json!({"parent": lp.parent, "hole": lp.hole, "signed_area": number(lp.signed_area()), "pieces": pieces})
                })
                .collect();
            json!({"distance": number(offset.distance), "area": number(offset.area()), "loops": loops})
        })
        .collect();
    pretty(&json!({ "offsets": offsets }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use segvoronoi::{Builder, Diagram};
    use std::f64::consts::PI;

    fn rectangle() -> Diagram {
        let mut b = Builder::new();
        b.add_polygon(&[vec![[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]]]).unwrap();
        b.build().unwrap()
    }

    /// A polygon: its rings, each a list of points.
    type Polygon = Vec<Vec<[f64; 2]>>;

    /// The polygons of each `MULTIPOLYGON` line, `None` for `EMPTY`.
    fn multipolygons(text: &str) -> Vec<Option<Vec<Polygon>>> {
        text.lines()
            .map(|line| {
                if line == "MULTIPOLYGON EMPTY" {
                    return None;
                }
                let body = line.strip_prefix("MULTIPOLYGON (((").and_then(|b| b.strip_suffix(")))")).expect(line);
                let polygons = body.split(")), ((").map(|polygon| {
                    polygon
                        .split("), (")
                        .map(|ring| {
                            ring.split(", ")
                                .map(|p| {
                                    let v: Vec<f64> = p.split(' ').map(|w| w.parse().expect(p)).collect();
                                    [v[0], v[1]]
                                })
                                .collect()
                        })
                        .collect()
                });
                Some(polygons.collect())
            })
            .collect()
    }

    /// The shoelace area of a closed ring.
    fn ring_area(ring: &[[f64; 2]]) -> f64 {
        ring.windows(2).map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1]).sum::<f64>() / 2.0
    }

    #[test]
    fn rectangle_grown_is_one_rounded_ring() {
        let d = rectangle();
        let tolerance = 1e-3;
        let text = wkt(&[d.offset(1.0).unwrap()], tolerance);
        let parsed = multipolygons(&text);
        assert_eq!(parsed.len(), 1, "{text}");
        let polygons = parsed[0].as_ref().expect(&text);
        assert_eq!((polygons.len(), polygons[0].len()), (1, 1), "one polygon, no hole: {text}");
        let ring = &polygons[0][0];
        assert_eq!(ring.first(), ring.last(), "closed: {text}");
        // the chords are inside the arcs, by at most the tolerance
        let (area, exact, perimeter) = (ring_area(ring), 8.0 + 12.0 + PI, 12.0 + 2.0 * PI);
        assert!(area <= exact + 1e-12 && exact - area <= tolerance * perimeter, "{area} vs {exact}");
        // every point is at distance 1 from the rectangle
        for &[x, y] in ring {
            let (dx, dy) = ((x - 2.0).abs() - 2.0, (y - 1.0).abs() - 1.0);
            let distance = dx.max(0.0).hypot(dy.max(0.0));
            assert!((distance - 1.0).abs() < 1e-12, "{x} {y}: {distance}");
        }
    }

    #[test]
    fn rectangle_shrunk_is_a_rectangle() {
        let d = rectangle();
        let text = wkt(&[d.offset(-0.5).unwrap()], 1e-3);
        let parsed = multipolygons(&text);
        let ring = &parsed[0].as_ref().expect(&text)[0][0];
        assert_eq!(ring.len(), 5, "four corners, closed: {text}");
        assert_eq!(ring.first(), ring.last());
        let mut corners: Vec<[f64; 2]> = ring[..4].to_vec();
        corners.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        assert_eq!(corners, [[0.5, 0.5], [0.5, 1.5], [3.5, 0.5], [3.5, 1.5]], "{text}");
        assert!((ring_area(ring) - 3.0).abs() < 1e-12, "counter-clockwise, 3 × 1: {text}");
    }

    #[test]
    fn lines_in_order_and_empty_regions() {
        let d = rectangle();
        // beyond the inscribed radius (1) nothing is left
        let text = wkt(&d.offsets(&[-0.5, -1.5, 2.0]).unwrap(), 1e-3);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 3, "{text}");
        assert!(lines[0].starts_with("MULTIPOLYGON (((") && lines[0].ends_with(")))"), "{text}");
        assert_eq!(lines[1], "MULTIPOLYGON EMPTY");
        assert!(lines[2].starts_with("MULTIPOLYGON ((("), "{text}");
        assert_eq!(wkt(&[], 1e-3), "");
    }

    #[test]
    fn holes_follow_their_outer_ring() {
        // A square with a 2 × 2 square hole, grown by 0.5: the hole shrinks
        // to a 1 × 1 square; shrunk by 0.5: the hole grows to a 3 × 3
        // square with rounded corners.
        let mut b = Builder::new();
        b.add_polygon(&[
            vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]],
            vec![[4.0, 4.0], [6.0, 4.0], [6.0, 6.0], [4.0, 6.0]],
        ])
        .unwrap();
        let d = b.build().unwrap();
        let text = wkt(&d.offsets(&[0.5, -0.5]).unwrap(), 1e-3);
        let rounded = 4.0 + 4.0 + PI / 4.0;
        for (polygons, hole_area) in multipolygons(&text).into_iter().zip([-1.0, -rounded]) {
            let polygons = polygons.expect(&text);
            assert_eq!((polygons.len(), polygons[0].len()), (1, 2), "{text}");
            assert!(ring_area(&polygons[0][0]) > 0.0, "outer ring counter-clockwise: {text}");
            // chords cut across the hole's rounded corners: a smaller hole,
            // by at most the tolerance × perimeter
            let hole = ring_area(&polygons[0][1]);
            assert!(hole >= hole_area - 1e-9 && hole - hole_area < 1e-3 * 12.0, "hole clockwise: {hole} vs {hole_area}: {text}");
        }
    }

    /// The pieces of every loop of every offset of a JSON document.
    fn pieces(value: &Value) -> Vec<&Value> {
        value["offsets"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|o| o["loops"].as_array().unwrap())
            .flat_map(|l| l["pieces"].as_array().unwrap())
            .collect()
    }

    #[test]
    fn json_names_pieces_and_nesting() {
        let d = rectangle();
        let text = json(&d.offsets(&[1.0, -0.5]).unwrap());
        assert!(text.ends_with("}\n") && !text.contains("NaN") && !text.contains("inf"), "{text}");
        let value: Value = serde_json::from_str(&text).unwrap();
        let offsets = value["offsets"].as_array().unwrap();
        assert_eq!((offsets[0]["distance"].as_f64(), offsets[1]["distance"].as_f64()), (Some(1.0), Some(-0.5)));
        assert_eq!(offsets[1]["area"].as_f64(), Some(3.0));
        // grown: four lines and four quarter circles around the corners
        let grown = pieces(&json!({"offsets": [offsets[0].clone()]})).into_iter().cloned().collect::<Vec<_>>();
        assert_eq!(grown.iter().filter(|p| p["kind"] == "line").count(), 4, "{text}");
        let arcs: Vec<&Value> = grown.iter().filter(|p| p["kind"] == "arc").collect();
        assert_eq!(arcs.len(), 4, "{text}");
        assert!(arcs.iter().any(|a| a["centre"] == json!([4.0, 2.0]) && a["radius"] == 1.0 && a["counter_clockwise"] == true));
        assert_eq!(pieces(&value).iter().filter(|p| p["kind"] == "line").count(), 4 + 4, "{text}");
        // one outer loop per distance, no parent
        for o in offsets {
            let loops = o["loops"].as_array().unwrap();
            assert_eq!(loops.len(), 1);
            assert!(loops[0]["parent"].is_null() && loops[0]["hole"] == false && loops[0]["signed_area"].as_f64().unwrap() > 0.0);
        }
        // site ids are the diagram's
        let sites: Vec<u64> = d.site_ids().map(|s| s.index() as u64).collect();
        for p in pieces(&value) {
            assert!(sites.contains(&p["site"].as_u64().unwrap()), "{p}");
        }
    }

    #[test]
    fn json_of_a_point_is_a_whole_circle() {
        let mut b = Builder::new();
        b.add_point([1.0, 2.0]).unwrap();
        let d = b.build().unwrap();
        let value: Value = serde_json::from_str(&json(&[d.offset(0.5).unwrap()])).unwrap();
        assert_eq!(
            pieces(&value),
            [
                &json!({"kind": "arc", "site": 0, "from": [1.5, 2.0], "to": [1.5, 2.0], "centre": [1.0, 2.0], "radius": 0.5, "counter_clockwise": true})
            ]
        );
        // the keys in the documented order
        assert!(json(&[d.offset(0.5).unwrap()]).contains("\"kind\": \"arc\",\n"));
        assert_eq!(serde_json::from_str::<Value>(&json(&[])).unwrap(), json!({"offsets": []}));
    }
}
