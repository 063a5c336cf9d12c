//! The writers of `--medial-axis`: the chains sampled as one WKT
//! `MULTILINESTRING Z` (z the clearance), or exactly as JSON, written by
//! hand (the program has no dependencies besides the library).
//!
//! Numbers are written with Rust's shortest round-trip formatting (`{}` on
//! `f64`), which never uses an exponent: every WKT and JSON reader takes it,
//! and it reads back to the same `f64`.

use std::fmt::Write;

use segvoronoi::{Chain, Diagram, EdgeEnd, EdgeShape, MedialAxis, Point};

/// The sampled points `[x, y, clearance]` of a chain within `tolerance`.
/// The pieces that reach infinity (only without a domain) are cut off: they
/// can only start or end a chain (an end at infinity has no other edges),
/// so the rest is one connected path, or nothing.
pub fn sample(diagram: &Diagram, chain: &Chain, tolerance: f64) -> Option<Vec<[f64; 3]>> {
    let finite = |end: &EdgeEnd| matches!(end, EdgeEnd::Vertex(_));
    let pieces: Vec<_> = chain.pieces.iter().filter(|p| p.ends.iter().all(finite)).copied().collect();
    if pieces.is_empty() {
        return None;
    }
    diagram.sample_chain(&Chain { pieces, closed: chain.closed }, tolerance)
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
/// each piece `{"edge": id, "kind": "line" | "parabola", "reversed": bool,
/// "ends": [end, end], "clearance": [r, r], "focus": [x, y],
/// "directrix": [[x, y], [x, y]]}` (the last two for a parabola only), an
/// end `{"vertex": id, "point": [x, y]}` or `{"direction": [dx, dy]}` (at
/// infinity, where the clearance is `null`).
pub fn json(diagram: &Diagram, axis: &MedialAxis) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{{\"domain\": {}, \"chains\": [", diagram.has_domain());
    for (c, chain) in axis.chains.iter().enumerate() {
        let _ = writeln!(out, "  {{\"closed\": {}, \"pieces\": [", chain.closed);
        for (k, piece) in chain.pieces.iter().enumerate() {
            let ends = piece.ends.map(|end| match end {
                EdgeEnd::Vertex(v) => {
                    let at = diagram.vertex(v).map_or(Point::new(f64::NAN, f64::NAN), |v| v.position);
                    format!("{{\"vertex\": {}, \"point\": {}}}", v.index(), point(at))
                }
                EdgeEnd::Infinite { direction } => format!("{{\"direction\": {}}}", point(direction)),
            });
            let kind = match diagram.edge_shape(piece.edge).unwrap_or(EdgeShape::Line) {
                EdgeShape::Parabola { focus, directrix: [a, b] } => {
                    format!("\"parabola\", \"focus\": {}, \"directrix\": [{}, {}]", point(focus), point(a), point(b))
                }
                EdgeShape::Line => "\"line\"".into(),
                // `EdgeShape` may grow (curved sites); no such edge exists yet.
                _ => "\"other\"".into(),
            };
            let _ = write!(
                out,
                "    {{\"edge\": {}, \"reversed\": {}, \"ends\": [{}, {}], \"clearance\": [{}, {}], \"kind\": {kind}}}",
                piece.edge.index(),
                piece.reversed,
                ends[0],
                ends[1],
                number(piece.clearance[0]),
                number(piece.clearance[1]),
            );
            out.push_str(if k + 1 < chain.pieces.len() { ",\n" } else { "\n" });
        }
        out.push_str(if c + 1 < axis.chains.len() { "  ]},\n" } else { "  ]}\n" });
    }
    out.push_str("]}\n");
    out
}

/// A JSON number, `null` when not finite (JSON has no infinity).
pub fn number(v: f64) -> String {
    if v.is_finite() {
        v.to_string()
    } else {
        "null".into()
    }
}

/// A JSON point `[x, y]` (see [`number`]).
pub fn point(p: Point) -> String {
    format!("[{}, {}]", number(p.x), number(p.y))
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
        let json = json(&d, &d.medial_axis());
        assert_eq!(json.matches("\"direction\"").count(), 3, "{json}");
        assert_eq!(json.matches("null").count(), 3, "{json}");
    }

    #[test]
    fn json_names_parabolas_by_focus_and_directrix() {
        // A point above a segment: one parabolic edge between them.
        let mut b = Builder::new();
        b.add_point([2.0, 2.0]).unwrap();
        b.add_segment([[0.0, 0.0], [4.0, 0.0]]).unwrap();
        let d = b.build().unwrap();
        let text = json(&d, &d.medial_axis());
        assert!(text.starts_with("{\"domain\": false, \"chains\": [\n") && text.ends_with("]}\n"), "{text}");
        assert!(text.contains("\"kind\": \"parabola\", \"focus\": [2, 2], \"directrix\": [[0, 0], [4, 0]]"), "{text}");
        assert!(!text.contains("NaN") && !text.contains("inf"), "{text}");
    }
}
