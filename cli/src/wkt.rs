//! WKT and EWKT input through georust's `wkt` crate, and GeoJSON through
//! the `geojson` crate, both flattened into the shapes the builder takes.
//!
//! A WKT file may hold any number of geometries one after the other (one
//! per line or concatenated): `split` cuts the text into them by their
//! parentheses, and each is parsed alone, so that an error names the line
//! of the geometry it is in. EWKT's `SRID=n;` prefix (PostGIS's output) is
//! taken off and reported; the coordinates are used as they are.
//!
//! The crates' messages carry no position (`wkt`) or a line and column
//! (`serde_json`, below `geojson`): either way the error quotes at most
//! `QUOTE` characters of the text around the problem, never the whole file.

mod curves;

use std::fmt;

pub use curves::{line_steps, ring_steps, Step};

/// A position: the first two ordinates.
pub type Xy = [f64; 2];

/// One geometry as the builder takes it: multi-geometries, collections,
/// features and feature collections are flattened into their members.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Point(Xy),
    LineString(Vec<Xy>),
    /// Its rings, the outer one first (the domain is even-odd anyway).
    Polygon(Vec<Vec<Xy>>),
    /// A chain of segments and at least one arc (a CIRCULARSTRING or
    /// COMPOUNDCURVE, a member of a MULTICURVE, an open DXF polyline with
    /// bulges, an ARC): an obstacle.
    Curve(Vec<Step>),
    /// The closed rings of a CURVEPOLYGON with at least one arc (of a
    /// closed DXF polyline with bulges, a CIRCLE): a polygon, bounding the
    /// domain like any other (a CURVEPOLYGON without arcs is a `Polygon`).
    CurveRings(Vec<Vec<Step>>),
}

/// The shapes of a file and the SRID its EWKT declared, if any.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Shapes {
    pub shapes: Vec<Shape>,
    pub srid: Option<i64>,
}

/// The most characters an error quotes.
const QUOTE: usize = 80;

/// Where the text stops making sense: a line (1-based), a column when the
/// reader knows one, what is wrong and the text around it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseError {
    pub line: usize,
    pub column: Option<usize>,
    pub message: String,
    /// At most `QUOTE` characters of the input, on one line.
    pub near: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.column {
            Some(column) => write!(f, "line {}, column {column}: {}", self.line, self.message)?,
            None => write!(f, "line {}: {}", self.line, self.message)?,
        }
        write!(f, "\n  near: {}", self.near)
    }
}

/// At most `QUOTE` characters of `text` from byte `at` on (moved back to a
/// character boundary), a little before it for context, line breaks as
/// spaces, `...` where it is cut.
fn quote(text: &str, at: usize) -> String {
    let mut start = at.min(text.len()).saturating_sub(QUOTE / 4);
    while !text.is_char_boundary(start) {
        start -= 1;
    }
    let piece: String = text[start..].chars().take(QUOTE).collect();
    let cut = start + piece.len() < text.trim_end().len();
    let piece = piece.split_whitespace().collect::<Vec<_>>().join(" ");
    format!("{}{piece}{}", if start > 0 { "..." } else { "" }, if cut { "..." } else { "" })
}

/// 1-based line and column (in characters) of byte `at`.
fn line_and_column(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..at];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().unwrap_or("").chars().count() + 1;
    (line, column)
}

/// The WKT geometry keywords, upper case, also with a glued dimension
/// (the curve types are read by `curves`).
const KEYWORDS: [&str; 12] = [
    "POINT",
    "MULTIPOINT",
    "LINESTRING",
    "MULTILINESTRING",
    "POLYGON",
    "MULTIPOLYGON",
    "GEOMETRYCOLLECTION",
    "CIRCULARSTRING",
    "COMPOUNDCURVE",
    "CURVEPOLYGON",
    "MULTICURVE",
    "MULTISURFACE",
];

/// Whether the text starts (after white space) with a WKT keyword or an
/// EWKT `SRID=`.
pub fn looks_like_wkt(text: &str) -> bool {
    let first: String =
        text.trim_start().chars().take_while(|c| c.is_ascii_alphabetic()).collect::<String>().to_ascii_uppercase();
    first == "SRID" || KEYWORDS.iter().any(|k| first.strip_prefix(k).is_some_and(|rest| ["", "Z", "M", "ZM"].contains(&rest)))
}

/// Reads every geometry of a WKT or EWKT text.
pub fn parse(text: &str) -> Result<Shapes, ParseError> {
    let mut out = Shapes::default();
    for (start, end) in split(text)? {
        let mut piece = &text[start..end];
        let mut offset = start;
        // EWKT: `SRID=4326;` before a geometry (PostGIS writes one per
        // geometry; the first one is kept).
        if piece.get(..5).is_some_and(|s| s.eq_ignore_ascii_case("SRID=")) {
            let error = |message: &str| {
                let (line, column) = line_and_column(text, offset);
                ParseError { line, column: Some(column), message: message.into(), near: quote(text, offset) }
            };
            let semicolon = piece.find(';').ok_or_else(|| error("an EWKT SRID=n needs a ';' before its geometry"))?;
            let srid = piece[5..semicolon].trim().parse().map_err(|_| error("an EWKT SRID=n needs an integer n"))?;
            out.srid.get_or_insert(srid);
            offset += semicolon + 1;
            piece = &piece[semicolon + 1..];
        }
        check_tokens(text, offset, offset + piece.len())?;
        if curves::has_curve(piece) {
            let start = out.shapes.len();
            curves::parse_geometry(text, offset, offset + piece.len(), &mut out.shapes)?;
            drop_empty(&mut out.shapes, start);
            continue;
        }
        let geometry: wkt::Wkt<f64> = piece.parse().map_err(|message: &str| {
            let skipped = offset + (piece.len() - piece.trim_start().len());
            let (line, _) = line_and_column(text, skipped);
            ParseError { line, column: None, message: format!("not valid WKT ({message})"), near: quote(text, skipped) }
        })?;
        flatten_wkt(&geometry, &mut out.shapes);
    }
    Ok(out)
}

/// The byte ranges of the geometries one after the other: each runs from
/// its keyword (or `SRID=`) to the `)` that closes its first `(`, or to
/// `EMPTY`. Unbalanced parentheses are the error here, at the stray one.
fn split(text: &str) -> Result<Vec<(usize, usize)>, ParseError> {
    let error = |at: usize, message: &str| {
        let (line, column) = line_and_column(text, at);
        ParseError { line, column: Some(column), message: message.into(), near: quote(text, at) }
    };
    let bytes = text.as_bytes();
    let mut ranges = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i].is_ascii_whitespace() {
            i += 1;
            continue;
        }
        let start = i;
        let mut depth = 0usize;
        loop {
            if i == bytes.len() {
                if depth > 0 {
                    return Err(error(start, "a '(' of this geometry is never closed"));
                }
                break;
            }
            match bytes[i] {
                b'(' => depth += 1,
                b')' if depth == 0 => return Err(error(i, "a ')' closes nothing")),
                b')' => {
                    depth -= 1;
                    if depth == 0 {
                        i += 1;
                        break;
                    }
                }
                _ if depth == 0 && bytes[i..].get(..5).is_some_and(|w| w.eq_ignore_ascii_case(b"EMPTY")) => {
                    i += 5;
                    break;
                }
                _ => {}
            }
            i += 1;
        }
        ranges.push((start, i));
    }
    Ok(ranges)
}

/// A word that is neither a number, a keyword nor a dimension: named with
/// its line and column before the crate, which would only say "invalid".
fn check_tokens(text: &str, start: usize, end: usize) -> Result<(), ParseError> {
    let separator = |c: char| c.is_whitespace() || "(),".contains(c);
    let mut chars = text[start..end].char_indices().map(|(i, c)| (start + i, c)).peekable();
    while let Some(&(here, c)) = chars.peek() {
        if separator(c) {
            chars.next();
            continue;
        }
        let mut stop = end;
        while let Some(&(i, c)) = chars.peek() {
            if separator(c) {
                stop = i;
                break;
            }
            chars.next();
        }
        let token = &text[here..stop];
        let upper = token.to_ascii_uppercase();
        let known = token.parse::<f64>().is_ok() || looks_like_wkt(token) || ["Z", "M", "ZM", "EMPTY"].contains(&upper.as_str());
        if !known {
            let (line, column) = line_and_column(text, here);
            return Err(ParseError {
                line,
                column: Some(column),
                message: format!("expected a number or a WKT keyword, found '{token}'"),
                near: quote(text, here),
            });
        }
    }
    Ok(())
}

fn xy(c: &wkt::types::Coord<f64>) -> Xy {
    [c.x, c.y]
}

/// Appends the shapes of `geometry`; an EMPTY one adds nothing.
fn flatten_wkt(geometry: &wkt::Wkt<f64>, out: &mut Vec<Shape>) {
    use wkt::Wkt;
    let start = out.len();
    let polygon =
        |p: &wkt::types::Polygon<f64>| Shape::Polygon(p.rings().iter().map(|r| r.coords().iter().map(xy).collect()).collect());
    match geometry {
        Wkt::Point(p) => out.extend(p.coord().map(|c| Shape::Point(xy(c)))),
        Wkt::LineString(l) => out.push(Shape::LineString(l.coords().iter().map(xy).collect())),
        Wkt::Polygon(p) => out.push(polygon(p)),
        Wkt::MultiPoint(m) => out.extend(m.points().iter().filter_map(|p| p.coord().map(|c| Shape::Point(xy(c))))),
        Wkt::MultiLineString(m) => {
            out.extend(m.line_strings().iter().map(|l| Shape::LineString(l.coords().iter().map(xy).collect())))
        }
        Wkt::MultiPolygon(m) => out.extend(m.polygons().iter().map(polygon)),
        Wkt::GeometryCollection(c) => c.geometries().iter().for_each(|g| flatten_wkt(g, out)),
    }
    drop_empty(out, start);
}

/// Drops the shapes from `start` on that have no position (`POLYGON
/// EMPTY`, `[]` coordinates): they add nothing to the diagram.
fn drop_empty(out: &mut Vec<Shape>, start: usize) {
    let mut k = start;
    while k < out.len() {
        let empty = match &out[k] {
            Shape::Point(_) => false,
            Shape::LineString(points) => points.is_empty(),
            Shape::Polygon(rings) => rings.iter().all(Vec::is_empty),
            Shape::Curve(steps) => steps.is_empty(),
            Shape::CurveRings(rings) => rings.iter().all(Vec::is_empty),
        };
        if empty {
            out.remove(k);
        } else {
            k += 1;
        }
    }
}

/// Whether the text looks like JSON (GeoJSON is an object).
pub fn looks_like_json(text: &str) -> bool {
    text.trim_start().starts_with('{')
}

/// Reads a GeoJSON geometry, Feature or FeatureCollection: every polygon
/// and multipolygon becomes rings of the domain, lines polylines, points
/// points; a feature without a geometry adds nothing.
pub fn parse_geojson(text: &str) -> Result<Shapes, ParseError> {
    let value: serde_json::Value = serde_json::from_str(text).map_err(|e| {
        let at = byte_of(text, e.line(), e.column());
        // serde_json's message ends in its own "at line L column C".
        let message = e.to_string();
        let message = message.split(" at line ").next().unwrap_or(&message).to_string();
        ParseError {
            line: e.line(),
            column: Some(e.column()),
            message: format!("not valid JSON ({message})"),
            near: quote(text, at),
        }
    })?;
    let geojson: geojson::GeoJson = serde_json::from_value(value).map_err(|e| {
        // Valid JSON that is not GeoJSON: no position from the crate; quote
        // the object's start (its "type") rather than the file.
        let at = text.find("\"type\"").unwrap_or(0);
        let (line, _) = line_and_column(text, at);
        ParseError { line, column: None, message: format!("not valid GeoJSON ({e})"), near: quote(text, at) }
    })?;
    let mut out = Shapes::default();
    match &geojson {
        geojson::GeoJson::Geometry(g) => flatten_geojson(&g.value, &mut out.shapes),
        geojson::GeoJson::Feature(f) => f.geometry.iter().for_each(|g| flatten_geojson(&g.value, &mut out.shapes)),
        geojson::GeoJson::FeatureCollection(c) => {
            c.features.iter().flat_map(|f| &f.geometry).for_each(|g| flatten_geojson(&g.value, &mut out.shapes))
        }
    }
    Ok(out)
}

/// The byte offset of a 1-based line and column (serde_json counts the
/// column in bytes; 0 at the start of a line).
fn byte_of(text: &str, line: usize, column: usize) -> usize {
    let start: usize = text.split_inclusive('\n').take(line.saturating_sub(1)).map(str::len).sum();
    (start + column.saturating_sub(1)).min(text.len())
}

fn flatten_geojson(value: &geojson::GeometryValue, out: &mut Vec<Shape>) {
    use geojson::{GeometryValue as V, Position};
    let start = out.len();
    // A position has at least two ordinates (the crate checks); more are
    // heights, ignored as WKT's Z.
    let xy = |p: &Position| [p[0], p.as_slice().get(1).copied().unwrap_or(f64::NAN)];
    let line = |l: &Vec<Position>| l.iter().map(xy).collect::<Vec<_>>();
    let polygon = |p: &Vec<Vec<Position>>| Shape::Polygon(p.iter().map(line).collect());
    match value {
        V::Point { coordinates } => out.push(Shape::Point(xy(coordinates))),
        V::MultiPoint { coordinates } => out.extend(coordinates.iter().map(|p| Shape::Point(xy(p)))),
        V::LineString { coordinates } => out.push(Shape::LineString(line(coordinates))),
        V::MultiLineString { coordinates } => out.extend(coordinates.iter().map(|l| Shape::LineString(line(l)))),
        V::Polygon { coordinates } => out.push(polygon(coordinates)),
        V::MultiPolygon { coordinates } => out.extend(coordinates.iter().map(polygon)),
        V::GeometryCollection { geometries } => geometries.iter().for_each(|g| flatten_geojson(&g.value, out)),
    }
    drop_empty(out, start);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn several_geometries_one_after_the_other() {
        let s = parse(
            "POINT (1 2)\nLINESTRING (0 0, 1 1)POLYGON EMPTY\nMULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), ((5 5, 6 5, 5 6, 5 5)))",
        )
        .unwrap();
        assert_eq!(s.shapes.len(), 4);
        assert_eq!(s.shapes[0], Shape::Point([1.0, 2.0]));
        assert_eq!(s.shapes[1], Shape::LineString(vec![[0.0, 0.0], [1.0, 1.0]]));
        assert!(matches!(&s.shapes[3], Shape::Polygon(r) if r[0][0] == [5.0, 5.0]));
        assert_eq!(s.srid, None);
    }

    #[test]
    fn ewkt_srid_is_taken_off() {
        let s = parse("SRID=4326;POLYGON Z ((0 0 1, 1 0 1, 0 1 1, 0 0 1))").unwrap();
        assert_eq!(s.srid, Some(4326));
        assert_eq!(s.shapes, [Shape::Polygon(vec![vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]])]);
        assert!(looks_like_wkt("  srid=3857;POINT(1 2)") && looks_like_wkt("pointz (1 2 3)") && !looks_like_wkt("3\n0 0"));
        assert!(parse("SRID=x;POINT (1 2)").unwrap_err().message.contains("integer"));
    }

    #[test]
    fn errors_name_the_line_and_quote_only_nearby_text() {
        let long = format!("POINT (1 2)\nPOLYGON ((0 0, 4 0, 4 two, 0 0{}))\n", ", 1 1".repeat(200));
        let e = parse(&long).unwrap_err();
        assert_eq!((e.line, e.column), (2, Some(23)), "{e}");
        assert!(e.message.contains("'two'") && e.near.contains("4 two") && e.near.chars().count() <= QUOTE + 6, "{e}");
        let e = parse("POINT (1 2)\n\nPOINT (1 2").unwrap_err();
        assert_eq!(e.line, 3, "{e}");
        let e = parse("POINT (1 2))").unwrap_err();
        assert_eq!((e.line, e.column), (1, Some(12)), "{e}");
        let e = parse("POINT (1 2 3 4 5)").unwrap_err();
        assert!(e.to_string().starts_with("line 1: not valid WKT"), "{e}");
    }

    #[test]
    fn geojson_features_and_collections() {
        let text = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {"name": "a"}, "geometry": {"type": "MultiPolygon", "coordinates": [[[[0,0],[4,0],[4,4],[0,0]]], [[[9,9],[10,9],[10,10],[9,9]]]]}},
            {"type": "Feature", "properties": null, "geometry": null},
            {"type": "Feature", "properties": {}, "geometry": {"type": "GeometryCollection", "geometries": [
                {"type": "LineString", "coordinates": [[1,1,7],[2,1,7]]}, {"type": "Point", "coordinates": [3, 1]}]}}]}"#;
        let s = parse_geojson(text).unwrap();
        assert_eq!(s.shapes.len(), 4);
        assert!(matches!(&s.shapes[1], Shape::Polygon(r) if r[0].len() == 4 && r[0][1] == [10.0, 9.0]));
        assert_eq!(s.shapes[2], Shape::LineString(vec![[1.0, 1.0], [2.0, 1.0]]));
        assert_eq!(s.shapes[3], Shape::Point([3.0, 1.0]));
        let s = parse_geojson(r#"{"type": "Polygon", "coordinates": [[[0,0],[1,0],[0,1],[0,0]]]}"#).unwrap();
        assert_eq!(s.shapes.len(), 1);
    }

    #[test]
    fn geojson_errors_quote_only_nearby_text() {
        let text = format!("{{\"type\": \"MultiPoint\",\n \"coordinates\": [{} [1, x]]}}", "[0, 0], ".repeat(100));
        let e = parse_geojson(&text).unwrap_err();
        assert_eq!(e.line, 2, "{e}");
        assert!(e.near.contains("[1, x]") && e.near.chars().count() <= QUOTE + 6, "{e}");
        let e = parse_geojson(r#"{"type": "Polygon", "coordinates": 7}"#).unwrap_err();
        assert!(e.message.contains("GeoJSON"), "{e}");
    }
}
