//! Well-known text (WKT) input, read by hand: the CLI needs seven geometry
//! types and good error positions, which does not justify a dependency (and
//! the library's dependency list stays as it is).
//!
//! Accepted: `POINT`, `MULTIPOINT`, `LINESTRING`, `MULTILINESTRING`,
//! `POLYGON`, `MULTIPOLYGON`, `GEOMETRYCOLLECTION`, each possibly `EMPTY`,
//! keywords in any case, an optional dimension (`Z`, `M`, `ZM`, as a
//! separate word or glued to the keyword as in `POINTZ`) whose extra
//! ordinates are read and ignored, and any number of geometries one after
//! the other (one per line or concatenated). Without a dimension a
//! position may have two to four ordinates; with one it must have exactly
//! as many as the dimension says. Numbers are Rust's `f64` syntax
//! (`-1.5e-3`); a number too large for `f64` becomes infinite and is then
//! refused by the builder as any non-finite coordinate.

use std::fmt;

/// A position: the first two ordinates.
pub type Xy = [f64; 2];

/// One geometry as the builder takes it: multi-geometries and collections
/// are flattened into their members.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Point(Xy),
    LineString(Vec<Xy>),
    /// Its rings, the outer one first (the domain is even-odd anyway).
    Polygon(Vec<Vec<Xy>>),
}

/// Where the text stops making sense and what would have made sense there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseError {
    /// 1-based.
    pub line: usize,
    /// 1-based, in characters.
    pub column: usize,
    pub message: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}, column {}: {}", self.line, self.column, self.message)
    }
}

/// The geometry types.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Tag {
    Point,
    MultiPoint,
    LineString,
    MultiLineString,
    Polygon,
    MultiPolygon,
    Collection,
}

const TAGS: [(&str, Tag); 7] = [
    ("POINT", Tag::Point),
    ("MULTIPOINT", Tag::MultiPoint),
    ("LINESTRING", Tag::LineString),
    ("MULTILINESTRING", Tag::MultiLineString),
    ("POLYGON", Tag::Polygon),
    ("MULTIPOLYGON", Tag::MultiPolygon),
    ("GEOMETRYCOLLECTION", Tag::Collection),
];

/// How many ordinates a dimension word declares.
fn dimension(word: &str) -> Option<usize> {
    match word {
        "Z" | "M" => Some(3),
        "ZM" => Some(4),
        _ => None,
    }
}

/// A geometry keyword (upper case), possibly with its dimension glued on
/// (`POINTZ`, `LINESTRINGZM`): the tag and the declared ordinate count.
fn keyword(word: &str) -> Option<(Tag, Option<usize>)> {
    let tag = |w: &str| TAGS.iter().find(|(name, _)| *name == w).map(|&(_, t)| t);
    if let Some(t) = tag(word) {
        return Some((t, None));
    }
    // No tag ends in Z or M, so a glued suffix is never ambiguous.
    ["ZM", "Z", "M"].iter().find_map(|suffix| Some((tag(word.strip_suffix(suffix)?)?, dimension(suffix))))
}

/// Whether the text's first word is a geometry keyword: how the CLI tells
/// WKT from Boost.Polygon's text format (which starts with a number).
pub fn looks_like_wkt(text: &str) -> bool {
    let word: String = text.trim_start().chars().take_while(char::is_ascii_alphabetic).collect();
    keyword(&word.to_ascii_uppercase()).is_some()
}

/// Every geometry of the text, flattened, in order.
pub fn parse(text: &str) -> Result<Vec<Shape>, ParseError> {
    let mut parser = Parser { tokens: tokenize(text)?, next: 0 };
    let mut shapes = Vec::new();
    while parser.peek().kind != Kind::End {
        parser.geometry(&mut shapes)?;
    }
    Ok(shapes)
}

#[derive(Clone, Debug, PartialEq)]
enum Kind {
    /// Letters, upper-cased.
    Word(String),
    Number(f64),
    Open,
    Close,
    Comma,
    End,
}

#[derive(Clone, Debug)]
struct Token {
    kind: Kind,
    /// As written, for messages.
    text: String,
    line: usize,
    column: usize,
}

impl Token {
    /// The token as a message names it.
    fn describe(&self) -> String {
        match self.kind {
            Kind::End => "the end of the input".into(),
            _ => format!("'{}'", self.text),
        }
    }
}

/// The tokens of the text, ending with `Kind::End`; a character that
/// starts no token or a malformed number is an error at its position.
fn tokenize(text: &str) -> Result<Vec<Token>, ParseError> {
    let mut tokens = Vec::new();
    let (mut line, mut column) = (1, 1);
    let mut chars = text.chars().peekable();
    while let Some(&c) = chars.peek() {
        let (start_line, start_column) = (line, column);
        let mut word = String::new();
        // Moves the characters that `keep` accepts from `chars` to `word`.
        let mut take = |keep: &dyn Fn(char) -> bool| {
            while let Some(c) = chars.next_if(|&c| keep(c)) {
                word.push(c);
                column += 1;
            }
        };
        let kind = match c {
            '\n' => {
                chars.next();
                (line, column) = (line + 1, 1);
                continue;
            }
            c if c.is_whitespace() => {
                take(&|k: char| k.is_whitespace() && k != '\n');
                continue;
            }
            '(' | ')' | ',' => {
                chars.next();
                column += 1;
                word.push(c);
                match c {
                    '(' => Kind::Open,
                    ')' => Kind::Close,
                    _ => Kind::Comma,
                }
            }
            c if c.is_ascii_alphabetic() => {
                take(&|k: char| k.is_ascii_alphabetic());
                Kind::Word(word.to_ascii_uppercase())
            }
            c if c.is_ascii_digit() || matches!(c, '+' | '-' | '.') => {
                // Letters too, so that `1x` is one bad number rather than a
                // number and a surprising word.
                take(&|k: char| k.is_ascii_alphanumeric() || matches!(k, '+' | '-' | '.'));
                match word.parse::<f64>() {
                    // `parse` also takes `inf` and `nan`, which cannot start here,
                    // but `1e999` is infinite: the builder names it.
                    Ok(v) => Kind::Number(v),
                    Err(_) => {
                        return Err(ParseError {
                            line: start_line,
                            column: start_column,
                            message: format!("expected a number, found '{word}'"),
                        })
                    }
                }
            }
            other => {
                return Err(ParseError {
                    line: start_line,
                    column: start_column,
                    message: format!("unexpected character '{other}'"),
                })
            }
        };
        tokens.push(Token { kind, text: word, line: start_line, column: start_column });
    }
    tokens.push(Token { kind: Kind::End, text: String::new(), line, column });
    Ok(tokens)
}

struct Parser {
    tokens: Vec<Token>,
    next: usize,
}

impl Parser {
    fn peek(&self) -> &Token {
        &self.tokens[self.next]
    }

    fn advance(&mut self) -> Token {
        let token = self.tokens[self.next].clone();
        // `End` is never passed, so `peek` always has a token.
        if token.kind != Kind::End {
            self.next += 1;
        }
        token
    }

    /// An error at the next token: what was expected and what is there.
    fn expected<T>(&self, what: &str) -> Result<T, ParseError> {
        let token = self.peek();
        Err(ParseError {
            line: token.line,
            column: token.column,
            message: format!("expected {what}, found {}", token.describe()),
        })
    }

    /// Consumes the next token if it is `kind`.
    fn accept(&mut self, kind: &Kind) -> bool {
        let here = &self.peek().kind == kind;
        if here {
            self.advance();
        }
        here
    }

    fn accept_word(&mut self, word: &str) -> bool {
        self.accept(&Kind::Word(word.into()))
    }

    /// `( item, item, ... )`, at least one item.
    fn list<T>(&mut self, what: &str, mut item: impl FnMut(&mut Self) -> Result<T, ParseError>) -> Result<Vec<T>, ParseError> {
        if !self.accept(&Kind::Open) {
            return self.expected(&format!("'(' or EMPTY before {what}"));
        }
        let mut items = vec![item(self)?];
        loop {
            if self.accept(&Kind::Comma) {
                items.push(item(self)?);
            } else if self.accept(&Kind::Close) {
                return Ok(items);
            } else {
                return self.expected(&format!("',' or ')' after {what}"));
            }
        }
    }

    /// One geometry (a collection's members included) appended to `out`.
    fn geometry(&mut self, out: &mut Vec<Shape>) -> Result<(), ParseError> {
        const KEYWORDS: &str = "a geometry keyword (POINT, LINESTRING, POLYGON, MULTIPOINT, MULTILINESTRING, \
                                MULTIPOLYGON or GEOMETRYCOLLECTION)";
        let Kind::Word(word) = &self.peek().kind else { return self.expected(KEYWORDS) };
        let Some((tag, mut dims)) = keyword(word) else { return self.expected(KEYWORDS) };
        self.advance();
        if dims.is_none() {
            if let Kind::Word(word) = &self.peek().kind {
                dims = dimension(word);
                if dims.is_some() {
                    self.advance();
                }
            }
        }
        if self.accept_word("EMPTY") {
            return Ok(());
        }
        match tag {
            Tag::Point => out.push(Shape::Point(self.point(dims)?)),
            Tag::MultiPoint => {
                let points = self.list("a point", |p| p.multipoint_member(dims))?;
                out.extend(points.into_iter().flatten().map(Shape::Point));
            }
            Tag::LineString => out.push(Shape::LineString(self.positions(dims)?)),
            Tag::MultiLineString => {
                let lines = self.list("a linestring", |p| p.or_empty(|p| p.positions(dims)))?;
                out.extend(lines.into_iter().flatten().map(Shape::LineString));
            }
            Tag::Polygon => out.push(Shape::Polygon(self.rings(dims)?)),
            Tag::MultiPolygon => {
                let polygons = self.list("a polygon", |p| p.or_empty(|p| p.rings(dims)))?;
                out.extend(polygons.into_iter().flatten().map(Shape::Polygon));
            }
            Tag::Collection => {
                self.list("a geometry", |p| p.geometry(out))?;
            }
        }
        Ok(())
    }

    /// `EMPTY` (`None`) or what `body` reads.
    fn or_empty<T>(&mut self, body: impl FnOnce(&mut Self) -> Result<T, ParseError>) -> Result<Option<T>, ParseError> {
        if self.accept_word("EMPTY") {
            return Ok(None);
        }
        body(self).map(Some)
    }

    /// A member of a MULTIPOINT: `(x y)`, `x y` (both are in use) or EMPTY.
    fn multipoint_member(&mut self, dims: Option<usize>) -> Result<Option<Xy>, ParseError> {
        if self.accept_word("EMPTY") {
            return Ok(None);
        }
        if self.peek().kind == Kind::Open {
            return self.point(dims).map(Some);
        }
        self.position(dims).map(Some)
    }

    /// `(x y)`.
    fn point(&mut self, dims: Option<usize>) -> Result<Xy, ParseError> {
        if !self.accept(&Kind::Open) {
            return self.expected("'(' or EMPTY before a position");
        }
        let p = self.position(dims)?;
        if !self.accept(&Kind::Close) {
            return self.expected("')' after the point's position");
        }
        Ok(p)
    }

    /// `(x y, x y, ...)`.
    fn positions(&mut self, dims: Option<usize>) -> Result<Vec<Xy>, ParseError> {
        self.list("a position", |p| p.position(dims))
    }

    /// `((x y, ...), (x y, ...))`.
    fn rings(&mut self, dims: Option<usize>) -> Result<Vec<Vec<Xy>>, ParseError> {
        self.list("a ring", |p| p.positions(dims))
    }

    /// `x y` and the ordinates the dimension adds (two to four when none is
    /// declared), of which only `x y` are kept.
    fn position(&mut self, dims: Option<usize>) -> Result<Xy, ParseError> {
        const NAMES: [&str; 4] = ["x", "y", "the third ordinate", "the fourth ordinate"];
        let (least, most) = dims.map_or((2, 4), |n| (n, n));
        let mut xy = [0.0; 2];
        for (k, name) in NAMES.iter().enumerate().take(most) {
            match self.peek().kind {
                Kind::Number(v) => {
                    if k < 2 {
                        xy[k] = v;
                    }
                    self.advance();
                }
                _ if k >= least => break,
                _ => return self.expected(&format!("a number ({name})")),
            }
        }
        Ok(xy)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error(text: &str) -> ParseError {
        parse(text).expect_err(text)
    }

    #[test]
    fn every_geometry_type() {
        let shapes = parse(
            "POINT (1 2)\n\
             MULTIPOINT ((3 4), 5 6, EMPTY)\n\
             LINESTRING (0 0, 1 1, 2 0)\n\
             MULTILINESTRING ((0 0, 1 0), EMPTY, (2 2, 3 3))\n\
             POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 2 1, 2 2))\n\
             MULTIPOLYGON (((0 0, 1 0, 1 1)), EMPTY, ((5 5, 6 5, 6 6)))\n\
             GEOMETRYCOLLECTION (POINT (7 8), LINESTRING (9 9, 10 10), GEOMETRYCOLLECTION EMPTY)",
        )
        .unwrap();
        let line = |v: &[Xy]| Shape::LineString(v.to_vec());
        let polygon = |rings: &[&[Xy]]| Shape::Polygon(rings.iter().map(|r| r.to_vec()).collect());
        assert_eq!(
            shapes,
            vec![
                Shape::Point([1.0, 2.0]),
                Shape::Point([3.0, 4.0]),
                Shape::Point([5.0, 6.0]),
                line(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]),
                line(&[[0.0, 0.0], [1.0, 0.0]]),
                line(&[[2.0, 2.0], [3.0, 3.0]]),
                polygon(&[&[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [0.0, 0.0]], &[[1.0, 1.0], [2.0, 1.0], [2.0, 2.0]]]),
                polygon(&[&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]]),
                polygon(&[&[[5.0, 5.0], [6.0, 5.0], [6.0, 6.0]]]),
                Shape::Point([7.0, 8.0]),
                line(&[[9.0, 9.0], [10.0, 10.0]]),
            ]
        );
    }

    #[test]
    fn case_dimensions_empty_and_concatenation() {
        let shapes = parse(
            "point z (1 2 3)PoInT M(4 5 6) pointzm (7 8 9 10) POINTZ(1 1 1)\
             linestring(1e0 -2.5, +.5 3.)\tPOINT EMPTY POLYGON Z EMPTY POINT (1 2 3 4)",
        )
        .unwrap();
        assert_eq!(
            shapes,
            vec![
                Shape::Point([1.0, 2.0]),
                Shape::Point([4.0, 5.0]),
                Shape::Point([7.0, 8.0]),
                Shape::Point([1.0, 1.0]),
                Shape::LineString(vec![[1.0, -2.5], [0.5, 3.0]]),
                Shape::Point([1.0, 2.0]),
            ]
        );
        assert_eq!(parse("  \n ").unwrap(), vec![]);
    }

    #[test]
    fn recognised_by_the_first_word() {
        assert!(looks_like_wkt("\n  polygon ((0 0, 1 0, 1 1))"));
        assert!(looks_like_wkt("MULTIPOINTZM EMPTY"));
        assert!(!looks_like_wkt("3\n0 0\n"));
        assert!(!looks_like_wkt("CIRCLE (0 0)"));
        assert!(!looks_like_wkt(""));
    }

    #[test]
    fn errors_name_line_column_and_what_was_expected() {
        let e = error("POINT (1 2)\nLINESTRING (0 0, 1)");
        assert_eq!((e.line, e.column), (2, 19), "{e}");
        assert!(e.message.contains("a number (y)") && e.message.contains("')'"), "{e}");

        let e = error("POLYGON ((0 0, 1 0, 1 1)");
        assert_eq!((e.line, e.column), (1, 25), "{e}");
        assert!(e.message.contains("',' or ')'") && e.message.contains("end of the input"), "{e}");

        let e = error("CIRCLE (0 0 1)");
        assert_eq!((e.line, e.column), (1, 1), "{e}");
        assert!(e.message.contains("geometry keyword") && e.message.contains("'CIRCLE'"), "{e}");

        let e = error("POINT (1 two)");
        assert_eq!((e.line, e.column), (1, 10), "{e}");
        assert!(e.message.contains("a number (y)") && e.message.contains("'two'"), "{e}");

        let e = error("POINT (1 2x)");
        assert_eq!((e.line, e.column), (1, 10), "{e}");
        assert!(e.message.contains("expected a number, found '2x'"), "{e}");

        let e = error("\n\n  POINT Z (1 2)");
        assert_eq!((e.line, e.column), (3, 15), "{e}");
        assert!(e.message.contains("the third ordinate"), "{e}");

        let e = error("POINT (1 2 3 4 5)");
        assert_eq!((e.line, e.column), (1, 16), "{e}");
        assert!(e.message.contains("')'"), "{e}");

        let e = error("POINT (1 2, 3 4)");
        assert!(e.message.contains("')' after the point's position"), "{e}");

        let e = error("LINESTRING (0 0, 1 1,)");
        assert_eq!((e.line, e.column), (1, 22), "{e}");

        let e = error("POINT 1 2");
        assert!(e.message.contains("'(' or EMPTY"), "{e}");

        let e = error("POINT (1 2) ; POINT (3 4)");
        assert_eq!((e.line, e.column), (1, 13), "{e}");
        assert!(e.message.contains("unexpected character ';'"), "{e}");

        let e = error("GEOMETRYCOLLECTION (POINT (1 2), 7)");
        assert!(e.message.contains("geometry keyword") && e.message.contains("'7'"), "{e}");
        assert_eq!(e.to_string(), format!("line 1, column 34: {}", e.message));
    }
}
