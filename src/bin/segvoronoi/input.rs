//! The input: read from the demo, standard input or a file, in
//! Boost.Polygon's text format (`segvoronoi::boost_text`) or as WKT
//! (`wkt`), and added to a builder.

use std::io::Read;

use segvoronoi::{boost_text, Builder, Error};

use crate::args::Source;
use crate::wkt::{self, Shape, Xy};
use crate::{bad_input, demo, Failure};

/// The input in either format.
pub enum Input {
    Boost(boost_text::Input),
    Wkt(Vec<Shape>),
}

/// The chosen input and a name for it in messages. WKT when the file name
/// ends in `.wkt` or the text starts with a WKT keyword; Boost.Polygon's
/// text format otherwise.
pub fn read(source: &Source) -> Result<(String, Input), Failure> {
    let (name, bytes, wkt_name) = match source {
        Source::Demo => return Ok(("demo input".into(), Input::Boost(demo::input()))),
        Source::Stdin => {
            let mut bytes = Vec::new();
            std::io::stdin().read_to_end(&mut bytes).map_err(|e| bad_input(format!("cannot read standard input: {e}")))?;
            ("standard input".to_string(), bytes, false)
        }
        Source::File(path) => {
            let bytes = std::fs::read(path).map_err(|e| bad_input(format!("cannot read {}: {e}", path.display())))?;
            let wkt_name = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("wkt"));
            (path.display().to_string(), bytes, wkt_name)
        }
    };
    // Invalid UTF-8 becomes U+FFFD and so a parse error at the right place.
    let text = String::from_utf8_lossy(&bytes);
    let input = if wkt_name || wkt::looks_like_wkt(&text) {
        wkt::parse(&text).map(Input::Wkt).map_err(|e| e.to_string())
    } else {
        boost_text::parse(&text).map(Input::Boost)
    };
    let input = input.map_err(|e| bad_input(format!("{name}: {e}")))?;
    Ok((name, input))
}

impl Input {
    /// Adds everything to `builder`: WKT polygons one `add_polygon` each
    /// (so that the domain is theirs), linestrings as polylines.
    pub fn add_to(&self, builder: &mut Builder) -> Result<(), Error> {
        match self {
            Input::Boost(input) => {
                builder.add_points(input.points.iter().copied())?;
                builder.add_segments(input.segments.iter().map(|&[x1, y1, x2, y2]| [[x1, y1], [x2, y2]]))?;
            }
            Input::Wkt(shapes) => {
                for shape in shapes {
                    match shape {
                        Shape::Point(p) => {
                            builder.add_point(*p)?;
                        }
                        Shape::LineString(points) => {
                            builder.add_polyline(points)?;
                        }
                        Shape::Polygon(rings) => {
                            builder.add_polygon(rings)?;
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// Every ring of every polygon (none in Boost.Polygon's format): the
    /// domain, even-odd, for the picture.
    pub fn rings(&self) -> Vec<Vec<Xy>> {
        match self {
            Input::Boost(_) => Vec::new(),
            Input::Wkt(shapes) => shapes
                .iter()
                .flat_map(|s| match s {
                    Shape::Polygon(rings) => rings.clone(),
                    _ => Vec::new(),
                })
                .collect(),
        }
    }
}
