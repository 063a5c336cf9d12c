//! Boost.Polygon's voronoi text format, the one reader of it: the CLI's
//! input and the test fixtures (`c_tests/fixtures/`). Not part of the
//! stable API (hidden from the docs); it lives in the library because the
//! CLI can depend on nothing else.
//!
//! ```text
//! P            number of points
//! x y          P times
//! S            number of segments (may be missing at the end: 0)
//! x1 y1 x2 y2  S times
//! ```
//!
//! Like Boost's own reader, this one reads whitespace-separated tokens and
//! does not care how they are spread over lines, so blank lines and several
//! points on one line are fine; what it adds is a line number in every error.
//! Coordinates are parsed as `f64`, so `nan` and `inf` get through here and
//! are left to the library, which rejects them naming the point's index
//! (the fixtures' test rejects them itself).

/// The parsed input.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Input {
    /// The points, `[x, y]`, in input order.
    pub points: Vec<[f64; 2]>,
    /// The segments, `[x1, y1, x2, y2]`, in input order.
    pub segments: Vec<[f64; 4]>,
    /// The 1-based line of each point's first coordinate (empty for an
    /// input made in code), for messages.
    pub point_lines: Vec<usize>,
    /// The 1-based line of each segment's first coordinate, likewise.
    pub segment_lines: Vec<usize>,
}

/// Writes points and segments in this format, each coordinate as the
/// shortest decimal that reads back as the same `f64`.
pub fn write(points: &[[f64; 2]], segments: &[[f64; 4]]) -> String {
    use std::fmt::Write;
    let mut out = String::with_capacity(24 * (points.len() + 2 * segments.len()) + 16);
    let _ = writeln!(out, "{}", points.len());
    for [x, y] in points {
        let _ = writeln!(out, "{x:?} {y:?}");
    }
    let _ = writeln!(out, "{}", segments.len());
    for [x1, y1, x2, y2] in segments {
        let _ = writeln!(out, "{x1:?} {y1:?} {x2:?} {y2:?}");
    }
    out
}

/// A token and the 1-based line it is on.
struct Tokens<'a> {
    lines: std::iter::Enumerate<std::str::Lines<'a>>,
    current: Option<(usize, std::str::SplitWhitespace<'a>)>,
    /// The last line seen, for errors at the end of the input.
    last_line: usize,
}

impl<'a> Tokens<'a> {
    fn new(text: &'a str) -> Self {
        Tokens { lines: text.lines().enumerate(), current: None, last_line: 0 }
    }

    fn next(&mut self) -> Option<(usize, &'a str)> {
        loop {
            if let Some((line, words)) = &mut self.current {
                if let Some(w) = words.next() {
                    return Some((*line, w));
                }
            }
            let (i, text) = self.lines.next()?;
            self.last_line = i + 1;
            self.current = Some((i + 1, text.split_whitespace()));
        }
    }

    /// The next token, or an error saying what was expected.
    fn expect(&mut self, what: &dyn Fn() -> String) -> Result<(usize, &'a str), String> {
        self.next().ok_or_else(|| format!("line {}: expected {}, found the end of the input", self.last_line.max(1), what()))
    }

    fn count(line: usize, token: &str, what: &str) -> Result<usize, String> {
        token.parse::<usize>().map_err(|_| format!("line {line}: expected {what} (a non-negative integer), found {token:?}"))
    }

    fn number(&mut self, what: &dyn Fn() -> String) -> Result<f64, String> {
        self.number_on_line(what).map(|(_, x)| x)
    }

    /// A number and its line.
    fn number_on_line(&mut self, what: &dyn Fn() -> String) -> Result<(usize, f64), String> {
        let (line, token) = self.expect(what)?;
        token.parse::<f64>().map(|x| (line, x)).map_err(|_| format!("line {line}: expected {}, found {token:?}", what()))
    }
}

/// Parses the whole text. The error names the offending line.
pub fn parse(text: &str) -> Result<Input, String> {
    let mut tokens = Tokens::new(text);
    let mut input = Input::default();
    let (line, token) = tokens.expect(&|| "the number of points".into())?;
    let point_count = Tokens::count(line, token, "the number of points")?;
    // A wrong count must not allocate gigabytes before the text runs out.
    input.points.reserve(point_count.min(1 << 20));
    for i in 0..point_count {
        let (line, x) = tokens.number_on_line(&|| format!("the x coordinate of point {i}"))?;
        let y = tokens.number(&|| format!("the y coordinate of point {i}"))?;
        input.points.push([x, y]);
        input.point_lines.push(line);
    }
    // The segment count may be left out altogether.
    let segment_count = match tokens.next() {
        None => 0,
        Some((line, token)) => Tokens::count(line, token, "the number of segments")?,
    };
    input.segments.reserve(segment_count.min(1 << 20));
    for i in 0..segment_count {
        let mut s = [0.0; 4];
        for (k, name) in ["x1", "y1", "x2", "y2"].iter().enumerate() {
            let (line, x) = tokens.number_on_line(&|| format!("coordinate {name} of segment {i}"))?;
            if k == 0 {
                input.segment_lines.push(line);
            }
            s[k] = x;
        }
        input.segments.push(s);
    }
    if let Some((line, token)) = tokens.next() {
        return Err(format!("line {line}: unexpected {token:?} after {point_count} points and {segment_count} segments"));
    }
    Ok(input)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_and_segments() {
        let input = parse("3\n0 0\n1 2.5\n-3 1e3\n1\n0 0 1 1\n").unwrap();
        assert_eq!(input.points, vec![[0.0, 0.0], [1.0, 2.5], [-3.0, 1000.0]]);
        assert_eq!(input.segments, vec![[0.0, 0.0, 1.0, 1.0]]);
    }

    #[test]
    fn tolerant_of_layout_and_missing_segment_count() {
        let input = parse("\n\n2\n\n  0   0 \t 1 1\n\n").unwrap();
        assert_eq!(input.points, vec![[0.0, 0.0], [1.0, 1.0]]);
        assert!(input.segments.is_empty());
        assert_eq!(parse("0\n0\n").unwrap(), Input::default());
    }

    #[test]
    fn non_finite_tokens_are_left_to_the_library() {
        let input = parse("1\nnan inf\n").unwrap();
        assert!(input.points[0][0].is_nan() && input.points[0][1].is_infinite());
    }

    #[test]
    fn errors_name_the_line() {
        let err = parse("2\n0 0\n1 x\n").unwrap_err();
        assert!(err.starts_with("line 3:") && err.contains("y coordinate of point 1"), "{err}");
        let err = parse("3\n0 0\n1 1\n").unwrap_err();
        assert!(err.starts_with("line 3:") && err.contains("point 2") && err.contains("end of the input"), "{err}");
        let err = parse("-1\n").unwrap_err();
        assert!(err.starts_with("line 1:") && err.contains("number of points"), "{err}");
        let err = parse("1\n0 0\n\nzwei\n").unwrap_err();
        assert!(err.starts_with("line 4:") && err.contains("number of segments"), "{err}");
        let err = parse("1\n0 0\n0\n7\n").unwrap_err();
        assert!(err.starts_with("line 4:") && err.contains("unexpected"), "{err}");
        let err = parse("1\n0 0\n1\n0 0 1\n").unwrap_err();
        assert!(err.starts_with("line 4:") && err.contains("y2 of segment 0"), "{err}");
        let err = parse(" \n\n").unwrap_err();
        assert!(err.starts_with("line 2:") && err.contains("number of points"), "{err}");
    }

    #[test]
    fn lines_are_kept_and_what_is_written_reads_back() {
        let input = parse("2\n0 0\n\n0.1 1e-300\n2\n0 0\n1 1\n5 5 6 6\n").unwrap();
        assert_eq!((input.point_lines.clone(), input.segment_lines.clone()), (vec![2, 4], vec![6, 8]));
        let again = parse(&write(&input.points, &input.segments)).unwrap();
        assert_eq!((again.points, again.segments), (input.points, input.segments));
    }
}
