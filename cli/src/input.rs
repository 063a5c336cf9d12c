//! The input: read from the demo, standard input or a file, in
//! Boost.Polygon's text format (`segvoronoi::boost_text`), as WKT or EWKT,
//! or as GeoJSON (`wkt`), and added to a builder.

use std::io::Read;
use std::ops::Range;

use segvoronoi::{boost_text, Builder, ChainPiece, Error};

use crate::args::Source;
use crate::wkt::{self, Shape, Shapes, Step, Xy};
use crate::{bad_input, demo, Failure};

/// Where the builder's input indices came from: lines of a Boost.Polygon
/// text file, or WKT geometries (0-based, in file order) and rings.
#[derive(Clone, Debug, Default)]
pub struct Origins {
    point_lines: Vec<usize>,
    segment_lines: Vec<usize>,
    /// (point index, geometry)
    wkt_points: Vec<(usize, usize)>,
    /// segment indices and where they came from
    wkt_segments: Vec<(Range<usize>, Place)>,
    /// arc indices and where they came from
    wkt_arcs: Vec<(Range<usize>, Place)>,
    /// A DXF input's name for each shape (its entities and layers),
    /// said instead of `geometry k`.
    names: Vec<String>,
}

/// A WKT geometry (its index among the shapes, what it is) and the ring of
/// a polygon.
#[derive(Clone, Copy, Debug)]
struct Place {
    geometry: usize,
    what: &'static str,
    ring: Option<usize>,
}

impl Place {
    /// `geometry 2 (a polygon), ring 0`, or the DXF entities' own name.
    fn describe(&self, names: &[String]) -> String {
        let Place { geometry, what, ring } = self;
        if let Some(name) = names.get(*geometry) {
            return name.clone();
        }
        match ring {
            Some(r) => format!("geometry {geometry} ({what}), ring {r}"),
            None => format!("geometry {geometry} ({what})"),
        }
    }
}

impl Origins {
    /// Where input segment `j` is, e.g. `line 7` or `geometry 2, ring 0`.
    fn of_segment(&self, j: usize) -> Option<String> {
        if let Some(line) = self.segment_lines.get(j) {
            return Some(format!("line {line}"));
        }
        let (_, place) = self.wkt_segments.iter().find(|(range, _)| range.contains(&j))?;
        Some(place.describe(&self.names))
    }

    /// A line for each site a message names ("arc 2", "segment 5",
    /// "point 1", "arcs 0 and 2"), once each: where it is in the file and
    /// its coordinates. With arcs an error's indices may be of either
    /// numbering, so the message's own words say which.
    fn named_places(&self, message: &str, builder: &Builder) -> String {
        let mut text = String::new();
        let mut named: Vec<(&str, usize)> = Vec::new();
        // the kind the last words named, kept over numbers and `and`
        let mut kind: Option<&str> = None;
        for word in message.split(|c: char| !c.is_ascii_alphanumeric()).filter(|w| !w.is_empty()) {
            let Ok(index) = word.parse::<usize>() else {
                kind = match word {
                    "arc" | "arcs" => Some("arc"),
                    "segment" | "segments" => Some("segment"),
                    "point" | "points" => Some("point"),
                    "and" => kind,
                    _ => None,
                };
                continue;
            };
            let Some(what) = kind else { continue };
            if named.contains(&(what, index)) {
                continue;
            }
            named.push((what, index));
            let (place, coordinates) = match what {
                "arc" => (
                    self.of_arc(index),
                    builder.arc(index).map(|a| {
                        let (s, e, c) = (a.start(), a.end(), a.centre());
                        format!("({}, {}) - ({}, {}) around ({}, {})", s.x, s.y, e.x, e.y, c.x, c.y)
                    }),
                ),
                "segment" => (
                    self.of_segment(index),
                    builder.segment(index).map(|[a, b]| format!("({}, {}) - ({}, {})", a.x, a.y, b.x, b.y)),
                ),
                _ => (self.of_point(index), builder.point(index).map(|p| format!("({}, {})", p.x, p.y))),
            };
            let place = place.map(|p| format!(", {p}")).unwrap_or_default();
            text.push_str(&format!("\n  {what} {index}{place}: {}", coordinates.unwrap_or_default()));
        }
        text
    }

    /// Where input arc `j` is, e.g. `geometry 2 (a curve polygon), ring 0`.
    pub fn of_arc(&self, j: usize) -> Option<String> {
        let (_, place) = self.wkt_arcs.iter().find(|(range, _)| range.contains(&j))?;
        Some(place.describe(&self.names))
    }

    fn of_point(&self, i: usize) -> Option<String> {
        if let Some(line) = self.point_lines.get(i) {
            return Some(format!("line {line}"));
        }
        self.wkt_points.iter().find(|&&(p, _)| p == i).map(|(_, k)| match self.names.get(*k) {
            Some(name) => name.clone(),
            None => format!("geometry {k} (a point)"),
        })
    }

    /// The library's error, and for crossing input each offending point or
    /// segment on a line of its own: where it is in the file and its
    /// coordinates.
    pub fn describe(&self, error: &Error, builder: &Builder) -> String {
        let mut text = error.to_string();
        if error.kind() != segvoronoi::ErrorKind::Intersecting {
            return text;
        }
        if builder.arc_count() > 0 && error.message().contains("arc") {
            text.push_str(&self.named_places(error.message(), builder));
            return text;
        }
        // A point inside a segment names the point first, then the segment;
        // every other conflict names two segments.
        let point_first = error.message().starts_with("point ");
        for (n, &index) in error.indices().iter().enumerate() {
            let (what, place, coordinates) = if n == 0 && point_first {
                let p = builder.point(index);
                ("point", self.of_point(index), p.map(|p| format!("({}, {})", p.x, p.y)))
            } else {
                let s = builder.segment(index);
                ("segment", self.of_segment(index), s.map(|[a, b]| format!("({}, {}) - ({}, {})", a.x, a.y, b.x, b.y)))
            };
            let place = place.map(|p| format!(", {p}")).unwrap_or_default();
            text.push_str(&format!("\n  {what} {index}{place}: {}", coordinates.unwrap_or_default()));
        }
        text.push_str("\n  (--split-crossings splits such input instead of refusing it)");
        text
    }
}

/// The input: Boost.Polygon's points and segments, or the shapes of a WKT,
/// EWKT or GeoJSON text, or of a DXF drawing with a name for each.
pub enum Input {
    Boost(boost_text::Input),
    Shapes(Shapes),
    Dxf(Shapes, Vec<String>),
}

/// The text formats, chosen by the file's extension or else its start.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Boost,
    Wkt,
    GeoJson,
    Dxf,
}

/// `.wkt`/`.ewkt`, `.geojson`/`.json` and `.dxf` decide; any other name
/// (and standard input) is judged by its first characters: DXF's `0` and
/// `SECTION` lines (or its binary sentinel), a WKT keyword or `SRID=`, a
/// `{`, else Boost.Polygon's numbers.
fn kind(extension: Option<&str>, text: &str) -> Kind {
    match extension.map(str::to_ascii_lowercase).as_deref() {
        Some("wkt" | "ewkt") => Kind::Wkt,
        Some("geojson" | "json") => Kind::GeoJson,
        Some("dxf") => Kind::Dxf,
        _ if crate::dxf::looks_like_dxf(text) => Kind::Dxf,
        _ if wkt::looks_like_wkt(text) => Kind::Wkt,
        _ if wkt::looks_like_json(text) => Kind::GeoJson,
        _ => Kind::Boost,
    }
}

/// The chosen input and a name for it in messages. WKT when the file name
/// ends in `.wkt` or the text starts with a WKT keyword; Boost.Polygon's
/// text format otherwise.
pub fn read(source: &Source) -> Result<(String, Input), Failure> {
    let (name, bytes, extension) = match source {
        Source::Demo => return Ok(("demo input".into(), Input::Boost(demo::input()))),
        Source::Stdin => {
            let mut bytes = Vec::new();
            std::io::stdin().read_to_end(&mut bytes).map_err(|e| bad_input(format!("cannot read standard input: {e}")))?;
            ("standard input".to_string(), bytes, None)
        }
        Source::File(path) => {
            let bytes = std::fs::read(path).map_err(|e| bad_input(format!("cannot read {}: {e}", path.display())))?;
            let extension = path.extension().and_then(|e| e.to_str()).map(str::to_string);
            (path.display().to_string(), bytes, extension)
        }
    };
    // Invalid UTF-8 becomes U+FFFD and so a parse error at the right place.
    let text = String::from_utf8_lossy(&bytes);
    let input = match kind(extension.as_deref(), &text) {
        Kind::Wkt => wkt::parse(&text).map(Input::Shapes).map_err(|e| e.to_string()),
        Kind::GeoJson => wkt::parse_geojson(&text).map(Input::Shapes).map_err(|e| e.to_string()),
        Kind::Boost => boost_text::parse(&text).map(Input::Boost),
        Kind::Dxf => crate::dxf::read(&bytes).map(|part| {
            for note in &part.notes {
                eprintln!("segvoronoi: {name}: note: {note}");
            }
            Input::Dxf(part.shapes, part.names)
        }),
    };
    let input = input.map_err(|e| bad_input(format!("{name}: {e}")))?;
    Ok((name, input))
}

impl Input {
    /// Adds everything to `builder`: WKT polygons one `add_polygon` each
    /// and curve polygons (rings with arcs) one `add_bulged_polygon` each,
    /// so that the domain is theirs (even-odd over all rings);
    /// linestrings as polylines, open curves piece by piece (obstacles).
    /// Returns where each input index came from, for messages; an error
    /// names the geometry (or DXF entity) the library refused.
    pub fn add_to(&self, builder: &mut Builder) -> Result<Origins, String> {
        let mut origins = Origins::default();
        match self {
            Input::Boost(input) => {
                let added = builder
                    .add_points(input.points.iter().copied())
                    .and_then(|_| builder.add_segments(input.segments.iter().map(|&[x1, y1, x2, y2]| [[x1, y1], [x2, y2]])));
                added.map_err(|e| e.to_string())?;
                origins.point_lines.clone_from(&input.point_lines);
                origins.segment_lines.clone_from(&input.segment_lines);
            }
            Input::Shapes(Shapes { shapes, .. }) | Input::Dxf(Shapes { shapes, .. }, _) => {
                if let Input::Dxf(_, names) = self {
                    origins.names.clone_from(names);
                }
                for (k, shape) in shapes.iter().enumerate() {
                    let place = |what: &'static str, ring: Option<usize>| Place { geometry: k, what, ring };
                    let refused = |what: &'static str, e: Error| format!("{}: {e}", place(what, None).describe(&origins.names));
                    match shape {
                        Shape::Point(p) => {
                            let i = builder.add_point(*p).map_err(|e| refused("a point", e))?;
                            origins.wkt_points.push((i, k));
                        }
                        Shape::LineString(points) => {
                            let made = builder.add_polyline(points).map_err(|e| refused("a linestring", e))?;
                            origins.wkt_segments.push((made, place("a linestring", None)));
                        }
                        Shape::Polygon(rings) => {
                            for (r, made) in
                                builder.add_polygon(rings).map_err(|e| refused("a polygon", e))?.into_iter().enumerate()
                            {
                                origins.wkt_segments.push((made, place("a polygon", Some(r))));
                            }
                        }
                        Shape::Curve(steps) => {
                            let (segments, arcs) = add_steps(builder, steps).map_err(|e| refused("a curve", e))?;
                            origins.wkt_segments.push((segments, place("a curve", None)));
                            origins.wkt_arcs.push((arcs, place("a curve", None)));
                        }
                        Shape::CurveRings(rings) => {
                            let bulged: Vec<Vec<(Xy, f64)>> = rings.iter().map(|steps| bulged_ring(steps)).collect();
                            let (mut segments, mut arcs) = (builder.segment_count(), builder.arc_count());
                            let made = builder.add_bulged_polygon(&bulged).map_err(|e| refused("a curve polygon", e))?;
                            for (r, pieces) in made.iter().enumerate() {
                                let arc_count = pieces.iter().filter(|p| matches!(p, ChainPiece::Arc(_))).count();
                                let place = place("a curve polygon", Some(r));
                                origins.wkt_segments.push((segments..segments + pieces.len() - arc_count, place));
                                origins.wkt_arcs.push((arcs..arcs + arc_count, place));
                                (segments, arcs) = (segments + pieces.len() - arc_count, arcs + arc_count);
                            }
                        }
                    }
                }
            }
        }
        Ok(origins)
    }

    /// Every ring of every polygon, plain or curved (none in
    /// Boost.Polygon's format): the domain, even-odd, for the picture.
    pub fn rings(&self) -> Vec<Vec<Step>> {
        self.shapes()
            .iter()
            .flat_map(|s| match s {
                Shape::Polygon(rings) => rings.iter().map(|ring| wkt::ring_steps(ring)).collect(),
                Shape::CurveRings(rings) => rings.clone(),
                _ => Vec::new(),
            })
            .collect()
    }

    /// The linestrings and open curves, and the points, of a WKT, GeoJSON
    /// or DXF input (the obstacles, drawn when the picture leaves the
    /// diagram out).
    pub fn obstacles(&self) -> (Vec<Vec<Step>>, Vec<Xy>) {
        let (mut lines, mut points) = (Vec::new(), Vec::new());
        for shape in self.shapes() {
            match shape {
                Shape::LineString(line) => lines.push(wkt::line_steps(line)),
                Shape::Curve(steps) => lines.push(steps.clone()),
                Shape::Point(p) => points.push(*p),
                Shape::Polygon(_) | Shape::CurveRings(_) => {}
            }
        }
        (lines, points)
    }

    /// The shapes (none in Boost.Polygon's format).
    fn shapes(&self) -> &[Shape] {
        match self {
            Input::Shapes(Shapes { shapes, .. }) | Input::Dxf(Shapes { shapes, .. }, _) => shapes,
            Input::Boost(_) => &[],
        }
    }

    /// The points and segments of Boost.Polygon's text (`None` for the
    /// other formats, whose shapes `rings` and `obstacles` give).
    pub fn boost_sites(&self) -> Option<(&[[f64; 2]], &[[f64; 4]])> {
        match self {
            Input::Boost(input) => Some((&input.points, &input.segments)),
            _ => None,
        }
    }

    /// Whether the input has a circular arc (a curve with one, open or a
    /// ring).
    pub fn has_arcs(&self) -> bool {
        self.shapes().iter().any(|s| matches!(s, Shape::Curve(_) | Shape::CurveRings(_)))
    }

    /// The SRID an EWKT input declared (its coordinates are used as they
    /// are: the diagram is planar).
    pub fn srid(&self) -> Option<i64> {
        match self {
            Input::Shapes(shapes) => shapes.srid,
            Input::Boost(_) | Input::Dxf(..) => None,
        }
    }
}

/// A closed ring of segments and arcs as `add_bulged_polygon` takes it:
/// each piece's start with its bulge (0 for a segment), so that the
/// vertices are the input's own coordinates, exactly; an arc given by a
/// third point (WKT's CIRCULARSTRING) gets the bulge of its sweep.
fn bulged_ring(steps: &[Step]) -> Vec<(Xy, f64)> {
    steps
        .iter()
        .map(|step| match step {
            Step::Segment([a, _]) => (*a, 0.0),
            Step::Arc(arc) => (step.start(), arc.bulge()),
        })
        .collect()
}

/// Adds a chain of segments and arcs piece by piece (an arc's endpoints
/// are the coordinates of the pieces around it, so the chain stays closed
/// exactly); returns the segment and arc indices it made.
fn add_steps(builder: &mut Builder, steps: &[Step]) -> Result<(Range<usize>, Range<usize>), Error> {
    let (segments, arcs) = (builder.segment_count(), builder.arc_count());
    for step in steps {
        match *step {
            Step::Segment(ends) => builder.add_segment(ends).map(drop)?,
            // (an arc straight to within the rounding of its centre, which
            // the builder refuses, is its chord)
            Step::Arc(arc) if arc.is_straight_within_rounding() => builder.add_segment([arc.start(), arc.end()]).map(drop)?,
            Step::Arc(arc) => builder.add_arc(arc).map(drop)?,
        }
    }
    Ok((segments..builder.segment_count(), arcs..builder.arc_count()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extension_decides_else_the_start() {
        assert_eq!(kind(Some("WKT"), "3\n0 0"), Kind::Wkt);
        assert_eq!(kind(Some("ewkt"), ""), Kind::Wkt);
        assert_eq!(kind(Some("GeoJSON"), "POINT (1 2)"), Kind::GeoJson);
        assert_eq!(kind(Some("json"), ""), Kind::GeoJson);
        assert_eq!(kind(Some("txt"), " SRID=4326;POINT (1 2)"), Kind::Wkt);
        assert_eq!(kind(None, "\n {\"type\": \"Point\"}"), Kind::GeoJson);
        assert_eq!(kind(None, "2\n0 0\n1 1\n"), Kind::Boost);
        assert_eq!(kind(None, "CircularString (0 0, 1 1, 2 0)"), Kind::Wkt);
        assert_eq!(kind(None, "SRID=4326;MULTISURFACE EMPTY"), Kind::Wkt);
        assert_eq!(kind(Some("DXF"), ""), Kind::Dxf);
        assert_eq!(kind(None, "  0\nSECTION\n  2\nHEADER\n"), Kind::Dxf);
        assert_eq!(kind(Some("txt"), "0\r\nSECTION\r\n"), Kind::Dxf);
        assert_eq!(kind(None, "0\n"), Kind::Boost);
    }

    #[test]
    fn an_error_naming_arcs_says_where_they_are() {
        let input = Input::Shapes(wkt::parse("LINESTRING (0 0, 1 0)\nCIRCULARSTRING (0 1, 1 2, 2 1)").unwrap());
        let mut b = Builder::new();
        let origins = input.add_to(&mut b).unwrap();
        let text = origins.named_places("arc 0 crosses segment 0", &b);
        assert!(text.contains("\n  arc 0, geometry 1 (a curve): (0, 1) - (2, 1) around (1, 1)"), "{text}");
        assert!(text.contains("\n  segment 0, geometry 0 (a linestring): (0, 0) - (1, 0)"), "{text}");
        // two arcs, each once
        let text = origins.named_places("arcs 0 and 0 touch (an end of arc 0 lies inside arc 0)", &b);
        assert_eq!(text.matches("\n  arc 0, geometry 1 (a curve)").count(), 1, "{text}");
    }

    #[test]
    fn curves_become_segments_and_arcs_sharing_their_ends() {
        let text =
            "POINT (7 7)\nCOMPOUNDCURVE((0 0, 4 0), CIRCULARSTRING(4 0, 5 1, 4 2), (4 2, 0 2), CIRCULARSTRING(0 2, -1 1, 0 0))\n\
                    CURVEPOLYGON(CIRCULARSTRING(10 0, 12 0, 10 0), (10.5 0, 11 0.5, 11.5 0, 10.5 0))";
        let input = Input::Shapes(wkt::parse(text).unwrap());
        assert!(input.has_arcs() && input.rings().len() == 2);
        let mut b = Builder::new();
        let origins = input.add_to(&mut b).unwrap();
        assert_eq!((b.point_count(), b.segment_count(), b.arc_count()), (1, 5, 4));
        let (s0, a0, s1, a1) = (b.segment(0).unwrap(), b.arc(0).unwrap(), b.segment(1).unwrap(), b.arc(1).unwrap());
        assert_eq!(
            (s0[1], a0.start(), a0.end(), s1[0]),
            ((4.0, 0.0).into(), (4.0, 0.0).into(), (4.0, 2.0).into(), (4.0, 2.0).into())
        );
        assert_eq!((a1.start(), a1.end(), s0[0]), ((0.0, 2.0).into(), (0.0, 0.0).into(), (0.0, 0.0).into()));
        assert_eq!((a0.centre(), a0.radius(), a0.is_counter_clockwise()), ((4.0, 1.0).into(), 1.0, true));
        // the circle: two half arcs through (12 0)
        let (a2, a3) = (b.arc(2).unwrap(), b.arc(3).unwrap());
        assert_eq!((a2.end(), a3.start(), a3.end()), ((12.0, 0.0).into(), (12.0, 0.0).into(), (10.0, 0.0).into()));
        assert_eq!(origins.of_arc(1).as_deref(), Some("geometry 1 (a curve)"));
        assert_eq!(origins.of_arc(3).as_deref(), Some("geometry 2 (a curve polygon), ring 0"));
        assert_eq!(origins.of_segment(4).as_deref(), Some("geometry 2 (a curve polygon), ring 1"));
        assert_eq!(origins.of_segment(0).as_deref(), Some("geometry 1 (a curve)"));
        assert_eq!(b.build().map(|d| d.has_domain()), Ok(true));
    }

    #[test]
    fn a_refused_ring_of_a_curve_polygon_is_named() {
        // ring 1 goes there and back: two distinct vertices, no arc
        let text = "POINT (9 9)\nCURVEPOLYGON(CIRCULARSTRING(0 0, 1 1, 2 0, 1 -1, 0 0), (0.5 0, 1.5 0, 0.5 0))";
        let input = Input::Shapes(wkt::parse(text).unwrap());
        let mut b = Builder::new();
        let e = input.add_to(&mut b).unwrap_err();
        assert!(e.starts_with("geometry 1 (a curve polygon): polygon 0, ring 1"), "{e}");
        assert_eq!((b.segment_count(), b.arc_count()), (0, 0), "nothing of the polygon added");
    }
}
