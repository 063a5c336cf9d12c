//! WKT curves as PostGIS writes them (`ST_AsText`, `ST_AsEWKT`), which the
//! `wkt` crate does not read: `CIRCULARSTRING`, `COMPOUNDCURVE`,
//! `CURVEPOLYGON`, `MULTICURVE` and `MULTISURFACE`, also inside a
//! `GEOMETRYCOLLECTION` beside the linear geometries. A geometry that names
//! one of them anywhere is read here whole, by a small recursive-descent
//! reader over its tokens; every other geometry still goes through the
//! crate, as before.
//!
//! A `CIRCULARSTRING` holds its points in threes: start, a point on the
//! arc, end; each further arc takes two more points and starts where the
//! one before ends. Each arc becomes [`CircularArc::through`] its three
//! points, so that its endpoints are the input's own coordinates and the
//! arcs and segments of a chain share them exactly. Two cases are not
//! arcs:
//! - three points on one line (decided exactly), the middle one between
//!   the others: the segment from start to end;
//! - start equal to end: a full circle, PostGIS's way (the middle point
//!   is the one opposite the start): two half circles, start to middle
//!   and back, both counter-clockwise (bulge 1), the middle point an exact
//!   endpoint of both.
//!
//! Ordinates past the second (`Z`, `M`, `ZM`, declared or not) are read
//! and ignored, as the crate's reader does; a declared dimension fixes the
//! count of numbers per point.

use segvoronoi::geometry::predicates::{orientation, strictly_between, Orientation};
use segvoronoi::CircularArc;

use super::{line_and_column, quote, ParseError, Shape, Xy};

/// The keywords read here only.
pub const CURVE_KEYWORDS: [&str; 5] = ["CIRCULARSTRING", "COMPOUNDCURVE", "CURVEPOLYGON", "MULTICURVE", "MULTISURFACE"];

/// Every keyword this reader knows.
const NAMES: [&str; 12] = [
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

/// One piece of a chain of segments and arcs, in order along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Step {
    Segment([Xy; 2]),
    Arc(CircularArc),
}

impl Step {
    pub fn start(&self) -> Xy {
        match self {
            Step::Segment([a, _]) => *a,
            Step::Arc(arc) => [arc.start().x, arc.start().y],
        }
    }

    pub fn end(&self) -> Xy {
        match self {
            Step::Segment([_, b]) => *b,
            Step::Arc(arc) => [arc.end().x, arc.end().y],
        }
    }
}

/// Whether the geometry text (already checked token by token) names a
/// curve type anywhere, and so is read here.
pub fn has_curve(piece: &str) -> bool {
    let upper = piece.to_ascii_uppercase();
    CURVE_KEYWORDS.iter().any(|k| upper.contains(k))
}

/// Reads the one geometry of `text[start..end]` and appends its shapes.
pub fn parse_geometry(text: &str, start: usize, end: usize, out: &mut Vec<Shape>) -> Result<(), ParseError> {
    let mut reader = Reader { text, tokens: tokenize(text, start, end), next: 0, end };
    reader.geometry(None, out)?;
    if reader.next < reader.tokens.len() {
        return Err(reader.error(reader.at(), "text after the end of this geometry".into()));
    }
    Ok(())
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Token<'a> {
    Word(&'a str),
    Number(f64),
    Open,
    Close,
    Comma,
}

/// The tokens of `text[start..end]` with their byte offsets.
fn tokenize(text: &str, start: usize, end: usize) -> Vec<(usize, Token<'_>)> {
    let separator = |c: char| c.is_whitespace() || "(),".contains(c);
    let mut tokens = Vec::new();
    let mut chars = text[start..end].char_indices().map(|(i, c)| (start + i, c)).peekable();
    while let Some((at, c)) = chars.next() {
        match c {
            '(' => tokens.push((at, Token::Open)),
            ')' => tokens.push((at, Token::Close)),
            ',' => tokens.push((at, Token::Comma)),
            c if c.is_whitespace() => {}
            _ => {
                let mut stop = end;
                while let Some(&(i, c)) = chars.peek() {
                    if separator(c) {
                        stop = i;
                        break;
                    }
                    chars.next();
                }
                let word = &text[at..stop];
                tokens.push((at, word.parse().map_or(Token::Word(word), Token::Number)));
            }
        }
    }
    tokens
}

/// A point and the byte offset where it starts, for messages.
type Located = (usize, Xy);

/// A chain read from the text: its pieces and its first and last points
/// (none for an empty one), and where it starts.
struct Chain {
    at: usize,
    steps: Vec<Step>,
    ends: Option<(Xy, Xy)>,
}

struct Reader<'a> {
    text: &'a str,
    tokens: Vec<(usize, Token<'a>)>,
    next: usize,
    end: usize,
}

impl<'a> Reader<'a> {
    fn error(&self, at: usize, message: String) -> ParseError {
        let (line, column) = line_and_column(self.text, at);
        ParseError { line, column: Some(column), message, near: quote(self.text, at) }
    }

    fn peek(&self) -> Option<Token<'a>> {
        self.tokens.get(self.next).map(|&(_, t)| t)
    }

    /// The offset of the next token (the end of the geometry after the last).
    fn at(&self) -> usize {
        self.tokens.get(self.next).map_or(self.end, |&(at, _)| at)
    }

    fn expect(&mut self, wanted: Token<'a>, what: &str) -> Result<(), ParseError> {
        if self.peek() == Some(wanted) {
            self.next += 1;
            return Ok(());
        }
        Err(self.unexpected(what))
    }

    fn unexpected(&self, what: &str) -> ParseError {
        let found = match self.peek() {
            None => "the end of the geometry".to_string(),
            Some(Token::Word(w)) => format!("'{w}'"),
            Some(Token::Number(_)) => "a number".to_string(),
            Some(Token::Open) => "'('".to_string(),
            Some(Token::Close) => "')'".to_string(),
            Some(Token::Comma) => "','".to_string(),
        };
        self.error(self.at(), format!("expected {what}, found {found}"))
    }

    /// `EMPTY`, if it comes next (and is taken).
    fn empty(&mut self) -> bool {
        if matches!(self.peek(), Some(Token::Word(w)) if w.eq_ignore_ascii_case("EMPTY")) {
            self.next += 1;
            return true;
        }
        false
    }

    /// Calls `item` for each member of a parenthesised, comma-separated
    /// list; `EMPTY` instead of the list is no member.
    fn list(&mut self, what: &str, mut item: impl FnMut(&mut Self) -> Result<(), ParseError>) -> Result<(), ParseError> {
        if self.empty() {
            return Ok(());
        }
        self.expect(Token::Open, &format!("'(' or EMPTY to start {what}"))?;
        loop {
            item(self)?;
            match self.peek() {
                Some(Token::Comma) => self.next += 1,
                Some(Token::Close) => {
                    self.next += 1;
                    return Ok(());
                }
                _ => return Err(self.unexpected(&format!("',' or ')' in {what}"))),
            }
        }
    }

    /// A keyword (with its dimension glued on or after it): its name in
    /// upper case, its offset, and the numbers per point it declares.
    fn keyword(&mut self, inherited: Option<usize>) -> Result<(&'static str, usize, Option<usize>), ParseError> {
        let at = self.at();
        let Some(Token::Word(word)) = self.peek() else { return Err(self.unexpected("a WKT geometry keyword")) };
        let upper = word.to_ascii_uppercase();
        let dimension = |suffix: &str| match suffix {
            "Z" | "M" => Some(Some(3)),
            "ZM" => Some(Some(4)),
            "" => Some(None),
            _ => None,
        };
        let found = NAMES.iter().find_map(|&name| Some((name, dimension(upper.strip_prefix(name)?)?)));
        let Some((name, mut declared)) = found else {
            return Err(self.error(at, format!("'{word}' is not a WKT geometry keyword")));
        };
        self.next += 1;
        if declared.is_none() {
            if let Some(Token::Word(w)) = self.peek() {
                if let Some(d) = dimension(&w.to_ascii_uppercase()).flatten() {
                    declared = Some(d);
                    self.next += 1;
                }
            }
        }
        Ok((name, at, declared.or(inherited)))
    }

    /// One geometry, any type, appended to `out` as shapes.
    fn geometry(&mut self, inherited: Option<usize>, out: &mut Vec<Shape>) -> Result<(), ParseError> {
        let (name, at, dim) = self.keyword(inherited)?;
        match name {
            "POINT" => {
                let points = self.points(dim, "a POINT")?;
                if points.len() > 1 {
                    return Err(self.error(points[1].0, "a POINT has one position".into()));
                }
                out.extend(points.first().map(|&(_, p)| Shape::Point(p)));
            }
            "MULTIPOINT" => self.list("a MULTIPOINT", |r| {
                // PostGIS writes `MULTIPOINT((1 2),(3 4))`; `(1 2, 3 4)` too
                if r.peek() == Some(Token::Open) {
                    out.extend(r.points(dim, "a point of a MULTIPOINT")?.into_iter().map(|(_, p)| Shape::Point(p)));
                } else if !r.empty() {
                    out.push(Shape::Point(r.coordinate(dim)?.1));
                }
                Ok(())
            })?,
            "LINESTRING" => out.push(Shape::LineString(plain(&self.points(dim, "a LINESTRING")?))),
            "MULTILINESTRING" => self.list("a MULTILINESTRING", |r| {
                out.push(Shape::LineString(plain(&r.points(dim, "a linestring of a MULTILINESTRING")?)));
                Ok(())
            })?,
            "POLYGON" => out.push(self.polygon(dim)?),
            "MULTIPOLYGON" => self.list("a MULTIPOLYGON", |r| {
                out.push(r.polygon(dim)?);
                Ok(())
            })?,
            "GEOMETRYCOLLECTION" => self.list("a GEOMETRYCOLLECTION", |r| r.geometry(dim, out))?,
            "CIRCULARSTRING" => {
                let chain = self.circular(at, dim)?;
                out.extend(curve_shape(chain));
            }
            "COMPOUNDCURVE" => {
                let chain = self.compound(at, dim)?;
                out.extend(curve_shape(chain));
            }
            "MULTICURVE" => self.list("a MULTICURVE", |r| {
                let chain = r.curve(dim, "a MULTICURVE")?;
                out.extend(curve_shape(chain));
                Ok(())
            })?,
            "CURVEPOLYGON" => out.push(self.curve_polygon(dim)?),
            "MULTISURFACE" => self.list("a MULTISURFACE", |r| {
                let shape = match r.peek() {
                    Some(Token::Open) => r.polygon(dim)?,
                    _ => match r.keyword(dim)? {
                        ("POLYGON", _, d) => r.polygon(d)?,
                        ("CURVEPOLYGON", _, d) => r.curve_polygon(d)?,
                        (other, at, _) => {
                            return Err(r.error(at, format!("a MULTISURFACE holds polygons and CURVEPOLYGONs, not {other}")))
                        }
                    },
                };
                out.push(shape);
                Ok(())
            })?,
            _ => unreachable!("every name has its arm"),
        }
        Ok(())
    }

    /// One position: two to four numbers, as many as a declared dimension says.
    fn coordinate(&mut self, dim: Option<usize>) -> Result<Located, ParseError> {
        let at = self.at();
        let mut numbers = Vec::with_capacity(4);
        while let Some(Token::Number(v)) = self.peek() {
            numbers.push(v);
            self.next += 1;
        }
        let count_ok = match dim {
            Some(d) => numbers.len() == d,
            None => (2..=4).contains(&numbers.len()),
        };
        if numbers.is_empty() {
            return Err(self.unexpected("a position (numbers)"));
        }
        if !count_ok {
            let wanted = dim.map_or("2 to 4".to_string(), |d| d.to_string());
            return Err(self.error(at, format!("a position here has {wanted} numbers, this one {}", numbers.len())));
        }
        Ok((at, [numbers[0], numbers[1]]))
    }

    /// `(x y, x y, ...)` or `EMPTY`.
    fn points(&mut self, dim: Option<usize>, what: &str) -> Result<Vec<Located>, ParseError> {
        let mut points = Vec::new();
        self.list(what, |r| {
            points.push(r.coordinate(dim)?);
            Ok(())
        })?;
        Ok(points)
    }

    /// A polygon's body: `((ring), (ring), ...)` or `EMPTY`.
    fn polygon(&mut self, dim: Option<usize>) -> Result<Shape, ParseError> {
        let mut rings = Vec::new();
        self.list("a polygon", |r| {
            rings.push(plain(&r.points(dim, "a ring of a polygon")?));
            Ok(())
        })?;
        Ok(Shape::Polygon(rings))
    }

    /// A CIRCULARSTRING's body (the keyword at `at` already read).
    fn circular(&mut self, at: usize, dim: Option<usize>) -> Result<Chain, ParseError> {
        let points = self.points(dim, "a CIRCULARSTRING")?;
        if points.is_empty() {
            return Ok(Chain { at, steps: Vec::new(), ends: None });
        }
        if points.len() < 3 || points.len() % 2 == 0 {
            return Err(self.error(
                at,
                format!(
                    "a CIRCULARSTRING has 3, 5, 7, ... points (start, a point on the arc, end; two more for each further arc), this one {}",
                    points.len()
                ),
            ));
        }
        let mut steps = Vec::with_capacity(points.len() / 2);
        for (k, triple) in points.windows(3).enumerate().step_by(2) {
            let [(where_, s), (_, m), (_, e)] = [triple[0], triple[1], triple[2]];
            arc_steps(s, m, e, &mut steps).map_err(|why| {
                let arc = k / 2;
                self.error(where_, format!("arc {arc} of this CIRCULARSTRING (points {k} to {}): {why}", k + 2))
            })?;
        }
        let ends = Some((points[0].1, points[points.len() - 1].1));
        Ok(Chain { at, steps, ends })
    }

    /// A COMPOUNDCURVE's body: linestrings (bare or named) and
    /// CIRCULARSTRINGs, each starting where the one before ends.
    fn compound(&mut self, at: usize, dim: Option<usize>) -> Result<Chain, ParseError> {
        let mut chain = Chain { at, steps: Vec::new(), ends: None };
        let mut index = 0;
        self.list("a COMPOUNDCURVE", |r| {
            let piece_at = r.at();
            let piece = match r.peek() {
                Some(Token::Open) => linear(piece_at, &r.points(dim, "a linestring of a COMPOUNDCURVE")?),
                _ => match r.keyword(dim)? {
                    ("LINESTRING", _, d) => linear(piece_at, &r.points(d, "a LINESTRING")?),
                    ("CIRCULARSTRING", at, d) => r.circular(at, d)?,
                    (other, at, _) => {
                        return Err(r.error(at, format!("a COMPOUNDCURVE holds linestrings and CIRCULARSTRINGs, not {other}")))
                    }
                },
            };
            if let (Some((_, last)), Some((first, _))) = (chain.ends, piece.ends) {
                if first != last {
                    return Err(r.error(
                        piece_at,
                        format!(
                            "piece {index} of this COMPOUNDCURVE starts at ({} {}), not where piece {} ends ({} {})",
                            first[0],
                            first[1],
                            index - 1,
                            last[0],
                            last[1]
                        ),
                    ));
                }
            }
            index += 1;
            chain.ends = match (chain.ends, piece.ends) {
                (Some((first, _)), Some((_, last))) => Some((first, last)),
                (ends, None) | (None, ends) => ends,
            };
            chain.steps.extend(piece.steps);
            Ok(())
        })?;
        Ok(chain)
    }

    /// A curve as a member of a MULTICURVE or a ring of a CURVEPOLYGON: a
    /// bare linestring, a LINESTRING, a CIRCULARSTRING or a COMPOUNDCURVE.
    fn curve(&mut self, dim: Option<usize>, of: &str) -> Result<Chain, ParseError> {
        let at = self.at();
        if self.peek() == Some(Token::Open) {
            return Ok(linear(at, &self.points(dim, &format!("a linestring of {of}"))?));
        }
        match self.keyword(dim)? {
            ("LINESTRING", _, d) => Ok(linear(at, &self.points(d, "a LINESTRING")?)),
            ("CIRCULARSTRING", at, d) => self.circular(at, d),
            ("COMPOUNDCURVE", at, d) => self.compound(at, d),
            (other, at, _) => {
                Err(self.error(at, format!("{of} holds linestrings, CIRCULARSTRINGs and COMPOUNDCURVEs, not {other}")))
            }
        }
    }

    /// A CURVEPOLYGON's body: closed curves. With an arc among them its
    /// rings are chains of segments and arcs (a polygon bounded by arcs);
    /// without, it is a polygon like any other.
    fn curve_polygon(&mut self, dim: Option<usize>) -> Result<Shape, ParseError> {
        let mut rings: Vec<Chain> = Vec::new();
        self.list("a CURVEPOLYGON", |r| {
            let ring = r.curve(dim, "a CURVEPOLYGON")?;
            if let Some((first, last)) = ring.ends {
                if first != last {
                    return Err(r.error(
                        ring.at,
                        format!(
                            "ring {} of this CURVEPOLYGON is not closed: it starts at ({} {}) and ends at ({} {})",
                            rings.len(),
                            first[0],
                            first[1],
                            last[0],
                            last[1]
                        ),
                    ));
                }
            }
            rings.push(ring);
            Ok(())
        })?;
        let has_arc = rings.iter().any(|ring| ring.steps.iter().any(|s| matches!(s, Step::Arc(_))));
        Ok(if has_arc {
            Shape::CurveRings(rings.into_iter().map(|ring| ring.steps).collect())
        } else {
            Shape::Polygon(rings.iter().map(|ring| chain_points(&ring.steps)).collect())
        })
    }
}

/// The coordinates without their offsets.
fn plain(points: &[Located]) -> Vec<Xy> {
    points.iter().map(|&(_, p)| p).collect()
}

/// A linestring as a chain (see [`line_steps`]).
fn linear(at: usize, points: &[Located]) -> Chain {
    let steps = line_steps(&plain(points));
    let ends = points.first().zip(points.last()).map(|(&(_, a), &(_, b))| (a, b));
    Chain { at, steps, ends }
}

/// A closed ring of points (its first point repeated at the end or not)
/// as a chain of segments back to its start.
pub fn ring_steps(points: &[Xy]) -> Vec<Step> {
    let closing = points.first().filter(|first| points.last() != Some(first));
    line_steps(&points.iter().chain(closing).copied().collect::<Vec<_>>())
}

/// A linestring as a chain: a segment between each two distinct
/// consecutive points.
pub fn line_steps(points: &[Xy]) -> Vec<Step> {
    points.windows(2).filter(|w| w[0] != w[1]).map(|w| Step::Segment([w[0], w[1]])).collect()
}

/// The points along a chain of segments: its start, then each end.
fn chain_points(steps: &[Step]) -> Vec<Xy> {
    steps.first().map(Step::start).into_iter().chain(steps.iter().map(Step::end)).collect()
}

/// A chain with an arc is a curve; one without is a linestring (a
/// CIRCULARSTRING whose points are all on lines, say); an empty one is
/// nothing.
fn curve_shape(chain: Chain) -> Option<Shape> {
    if chain.steps.is_empty() {
        // a chain of one point repeated: nothing to add
        return None;
    }
    Some(if chain.steps.iter().any(|s| matches!(s, Step::Arc(_))) {
        Shape::Curve(chain.steps)
    } else {
        Shape::LineString(chain_points(&chain.steps))
    })
}

/// The pieces of the arc from `s` through `m` to `e`: an arc, a segment
/// (three points on one line), or two half circles (`s == e`: a full
/// circle, `m` opposite `s`).
fn arc_steps(s: Xy, m: Xy, e: Xy, steps: &mut Vec<Step>) -> Result<(), String> {
    let library = |e: segvoronoi::Error| e.message().to_string();
    if s == e {
        if m == s {
            return Err("all three points are equal".into());
        }
        steps.push(Step::Arc(CircularArc::from_bulge(s, m, 1.0).map_err(library)?));
        steps.push(Step::Arc(CircularArc::from_bulge(m, s, 1.0).map_err(library)?));
        return Ok(());
    }
    if m == s || m == e {
        return Err("the middle point repeats an endpoint".into());
    }
    if orientation(s.into(), m.into(), e.into()) == Orientation::Collinear {
        if strictly_between(s.into(), e.into(), m.into()) {
            steps.push(Step::Segment([s, e]));
            return Ok(());
        }
        return Err("the three points are on one line, the middle one not between the others".into());
    }
    steps.push(Step::Arc(CircularArc::through(s, m, e).map_err(library)?));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::parse;
    use super::*;

    fn arc(shape: &Shape, k: usize) -> CircularArc {
        match shape {
            Shape::Curve(steps) => match steps[k] {
                Step::Arc(a) => a,
                other => panic!("step {k} is {other:?}"),
            },
            other => panic!("not a curve: {other:?}"),
        }
    }

    #[test]
    fn circularstring_postgis() {
        // ST_AsText(ST_GeomFromText('CIRCULARSTRING(0 0, 1 1, 1 0)'))
        let s = parse("CIRCULARSTRING(0 0,1 1,1 0)").unwrap();
        assert_eq!(s.shapes.len(), 1);
        let a = arc(&s.shapes[0], 0);
        assert_eq!((a.start(), a.end()), ((0.0, 0.0).into(), (1.0, 0.0).into()));
        assert_eq!(a.via(), Some((1.0, 1.0).into()));
        assert!(!a.is_counter_clockwise());
        assert_eq!(a.centre(), (0.5, 0.5).into());
        // two arcs sharing (2 0); Z ignored
        let s = parse("CIRCULARSTRING Z (0 0 1,1 1 1,2 0 1,3 -1 1,4 0 1)").unwrap();
        let [a, b] = [0, 1].map(|k| arc(&s.shapes[0], k));
        assert_eq!(a.end(), b.start());
        assert!(!a.is_counter_clockwise() && b.is_counter_clockwise());
        assert_eq!(parse("CIRCULARSTRING EMPTY").unwrap().shapes, []);
    }

    #[test]
    fn collinear_arcs_are_segments_and_a_closed_one_is_a_circle() {
        let s = parse("CIRCULARSTRING(0 0, 1 1, 2 2)").unwrap();
        assert_eq!(s.shapes, [Shape::LineString(vec![[0.0, 0.0], [2.0, 2.0]])]);
        let s = parse("CIRCULARSTRING(0 0, 1 1, 2 0, 3 0, 4 0)").unwrap();
        let Shape::Curve(steps) = &s.shapes[0] else { panic!() };
        assert_eq!(steps[1], Step::Segment([[2.0, 0.0], [4.0, 0.0]]));
        // PostGIS's full circle: start = end, the middle point opposite
        let s = parse("CIRCULARSTRING(1 0, 3 0, 1 0)").unwrap();
        let [a, b] = [0, 1].map(|k| arc(&s.shapes[0], k));
        assert_eq!((a.start(), a.end(), b.end()), ((1.0, 0.0).into(), (3.0, 0.0).into(), (1.0, 0.0).into()));
        assert_eq!((a.centre(), b.centre(), a.radius()), ((2.0, 0.0).into(), (2.0, 0.0).into(), 1.0));
        assert!(a.is_counter_clockwise() && b.is_counter_clockwise());
    }

    #[test]
    fn compoundcurve_postgis() {
        // the PostGIS manual's example
        let s = parse("COMPOUNDCURVE(CIRCULARSTRING(0 0, 1 1, 1 0),(1 0, 0 1))").unwrap();
        let Shape::Curve(steps) = &s.shapes[0] else { panic!("{:?}", s.shapes) };
        assert_eq!(steps.len(), 2);
        assert_eq!(steps[1], Step::Segment([[1.0, 0.0], [0.0, 1.0]]));
        let s = parse("COMPOUNDCURVE Z ((2 0 1, 3 0 1), CIRCULARSTRING Z (3 0 1, 4 1 1, 5 0 1), LINESTRING Z (5 0 1, 6 0 1))")
            .unwrap();
        let Shape::Curve(steps) = &s.shapes[0] else { panic!() };
        assert_eq!(steps.len(), 3);
        let e = parse("COMPOUNDCURVE((0 0, 1 0), CIRCULARSTRING(2 0, 3 1, 4 0))").unwrap_err();
        assert!(e.message.contains("piece 1") && e.message.contains("(2 0)") && e.message.contains("(1 0)"), "{e}");
        assert_eq!((e.line, e.column), (1, Some(27)), "{e}");
    }

    #[test]
    fn curvepolygon_postgis() {
        // the PostGIS manual's examples
        let s = parse("CURVEPOLYGON(CIRCULARSTRING(0 0, 4 0, 4 4, 0 4, 0 0),(1 1, 3 3, 3 1, 1 1))").unwrap();
        let Shape::CurveRings(rings) = &s.shapes[0] else { panic!("{:?}", s.shapes) };
        assert_eq!((rings.len(), rings[0].len(), rings[1].len()), (2, 2, 3));
        let s = parse("CURVEPOLYGON(COMPOUNDCURVE(CIRCULARSTRING(0 0,2 0, 2 1, 2 3, 4 3),(4 3, 4 5, 1 4, 0 0)), CIRCULARSTRING(1.7 1, 1.4 0.4, 1.6 0.4, 1.6 0.5, 1.7 1))").unwrap();
        let Shape::CurveRings(rings) = &s.shapes[0] else { panic!() };
        assert_eq!(rings.len(), 2);
        // without arcs: a polygon (a domain)
        let s = parse("CURVEPOLYGON((0 0, 4 0, 4 4, 0 0))").unwrap();
        assert_eq!(s.shapes, [Shape::Polygon(vec![vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 0.0]]])]);
        let e = parse("CURVEPOLYGON(CIRCULARSTRING(0 0, 1 1, 2 0))").unwrap_err();
        assert!(e.message.contains("ring 0") && e.message.contains("not closed"), "{e}");
    }

    #[test]
    fn multicurve_and_multisurface_postgis() {
        let s = parse("MULTICURVE((0 0, 5 5),CIRCULARSTRING(4 0, 4 4, 8 4))").unwrap();
        assert_eq!(s.shapes[0], Shape::LineString(vec![[0.0, 0.0], [5.0, 5.0]]));
        assert!(matches!(&s.shapes[1], Shape::Curve(steps) if steps.len() == 1));
        let s = parse(
            "MULTISURFACE(CURVEPOLYGON(CIRCULARSTRING(0 0, 4 0, 4 4, 0 4, 0 0),(1 1, 3 3, 3 1, 1 1)),((10 10, 14 12, 11 10, 10 10),(11 11, 11.5 11, 11 11.5, 11 11)))",
        )
        .unwrap();
        assert!(matches!(&s.shapes[0], Shape::CurveRings(r) if r.len() == 2));
        assert!(matches!(&s.shapes[1], Shape::Polygon(r) if r.len() == 2 && r[1][1] == [11.5, 11.0]));
        let s = parse("SRID=4326;GEOMETRYCOLLECTION(POINT(9 9),CIRCULARSTRING(0 0,1 1,1 0),MULTIPOINT((1 5),(2 5)))").unwrap();
        assert_eq!(s.srid, Some(4326));
        assert_eq!(s.shapes.len(), 4);
        assert_eq!((s.shapes[0].clone(), s.shapes[3].clone()), (Shape::Point([9.0, 9.0]), Shape::Point([2.0, 5.0])));
    }

    #[test]
    fn errors_name_the_geometry_and_position() {
        let e = parse("POINT (0 0)\nCIRCULARSTRING(0 0, 1 1, 2 0, 3 0)").unwrap_err();
        assert_eq!((e.line, e.column), (2, Some(1)), "{e}");
        assert!(e.message.contains("CIRCULARSTRING") && e.message.contains("this one 4"), "{e}");
        let e = parse("CIRCULARSTRING(0 0, 1 1, 2 0, 5 0, 3 0)").unwrap_err();
        assert!(e.message.contains("arc 1") && e.message.contains("points 2 to 4") && e.message.contains("on one line"), "{e}");
        assert_eq!(e.column, Some(26), "{e}");
        let e = parse("CIRCULARSTRING(0 0, 0 0, 1 0)").unwrap_err();
        assert!(e.message.contains("repeats an endpoint"), "{e}");
        let e = parse("CIRCULARSTRING Z (0 0, 1 1, 2 0)").unwrap_err();
        assert!(e.message.contains("3 numbers, this one 2"), "{e}");
        let e = parse("MULTICURVE(POINT(1 1))").unwrap_err();
        assert!(e.message.contains("not POINT"), "{e}");
        let e = parse("MULTISURFACE(CIRCULARSTRING(0 0, 1 1, 1 0))").unwrap_err();
        assert!(e.message.contains("not CIRCULARSTRING"), "{e}");
    }
}
