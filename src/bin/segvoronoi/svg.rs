//! The SVG picture: the sites' bounding box plus a margin, fitted into about
//! 800 pixels, y axis up; edges as thin lines, rays and lines clipped to the
//! picture; vertices as small dots, sites as bigger dots of another colour.
//!
//! All geometry is done in "normalised" coordinates, the input multiplied by
//! an exact power of two that brings the largest magnitude near 1, so that
//! inputs near the ends of the `f64` range neither overflow nor underflow on
//! the way to pixels. Anything that still is not finite is left out of the
//! picture rather than written as `NaN`.

use std::fmt::Write;

use segvoronoi::{Diagram, Edge, EdgeEnd, Point};

/// The longer side of the picture, in pixels.
const SIZE_PX: f64 = 800.0;
/// Margin around the sites, as a fraction of the larger half-extent.
const MARGIN: f64 = 0.08;
/// No side shorter than this fraction of the longer one: a row of collinear
/// sites still gets room for its bisectors.
const MIN_ASPECT: f64 = 0.3;

const EDGE_COLOUR: &str = "#3b6ea5";
const VERTEX_COLOUR: &str = "#1d3f66";
const SITE_COLOUR: &str = "#d9480f";
const VERTEX_RADIUS: f64 = 2.0;
const SITE_RADIUS: f64 = 3.5;

/// Maps input coordinates to normalised ones and those to pixels.
struct Frame {
    /// Exact power of two: input × `to_unit` = normalised.
    to_unit: f64,
    /// The visible rectangle, normalised: lower-left and upper-right corner.
    low: Point,
    high: Point,
    /// Pixels per normalised unit.
    px: f64,
}

impl Frame {
    fn new(sites: &[Point]) -> Frame {
        let max_abs = sites.iter().fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        let to_unit = power_of_two_near_inverse(max_abs);
        let unit: Vec<Point> = sites.iter().map(|&p| Point::new(p.x * to_unit, p.y * to_unit)).collect();
        let (mut low, mut high) = (Point::new(-1.0, -1.0), Point::new(1.0, 1.0));
        if let Some(&first) = unit.first() {
            (low, high) = (first, first);
            for p in &unit {
                (low.x, low.y, high.x, high.y) = (low.x.min(p.x), low.y.min(p.y), high.x.max(p.x), high.y.max(p.y));
            }
        }
        let centre = Point::new((low.x + high.x) / 2.0, (low.y + high.y) / 2.0);
        let (mut hx, mut hy) = ((high.x - low.x) / 2.0, (high.y - low.y) / 2.0);
        // All sites equal: a unit square around them (normalised scale).
        let span = match hx.max(hy) {
            s if s > 0.0 => s,
            _ => 1.0,
        };
        hx = hx.max(MIN_ASPECT * span) + MARGIN * span;
        hy = hy.max(MIN_ASPECT * span) + MARGIN * span;
        Frame {
            to_unit,
            low: Point::new(centre.x - hx, centre.y - hy),
            high: Point::new(centre.x + hx, centre.y + hy),
            px: SIZE_PX / (2.0 * hx.max(hy)),
        }
    }

    fn unit(&self, p: Point) -> Point {
        Point::new(p.x * self.to_unit, p.y * self.to_unit)
    }

    fn width(&self) -> f64 {
        ((self.high.x - self.low.x) * self.px).ceil()
    }

    fn height(&self) -> f64 {
        ((self.high.y - self.low.y) * self.px).ceil()
    }

    /// Pixel coordinates of a normalised point (y flipped), or `None` if not
    /// finite.
    fn pixel(&self, p: Point) -> Option<(f64, f64)> {
        let (x, y) = ((p.x - self.low.x) * self.px, (self.high.y - p.y) * self.px);
        (x.is_finite() && y.is_finite()).then_some((x, y))
    }

    fn contains(&self, p: Point) -> bool {
        (self.low.x..=self.high.x).contains(&p.x) && (self.low.y..=self.high.y).contains(&p.y)
    }

    /// The part of `start + t·dir`, `t` in `[t0, t1]`, inside the visible
    /// rectangle (Liang–Barsky), or `None` if it misses it.
    fn clip(&self, start: Point, dir: Point, mut t0: f64, mut t1: f64) -> Option<(Point, Point)> {
        let sides = [
            (-dir.x, start.x - self.low.x),
            (dir.x, self.high.x - start.x),
            (-dir.y, start.y - self.low.y),
            (dir.y, self.high.y - start.y),
        ];
        for (p, q) in sides {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
                continue;
            }
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
        // NaN from non-finite input fails these comparisons too.
        if !(t0 <= t1 && t0.is_finite() && t1.is_finite()) {
            return None;
        }
        let at = |t: f64| Point::new(start.x + t * dir.x, start.y + t * dir.y);
        Some((at(t0), at(t1)))
    }
}

/// An exact power of two close to `1 / max_abs` (1 for zero or non-finite),
/// kept within the range where it and its use stay finite and normal.
fn power_of_two_near_inverse(max_abs: f64) -> f64 {
    if !(max_abs > 0.0 && max_abs.is_finite()) {
        return 1.0;
    }
    let exponent = max_abs.log2().floor().clamp(-1000.0, 1000.0) as i32;
    2f64.powi(-exponent)
}

/// The direction of travel along the bisector of `left` and `right` that
/// keeps `left` on the left: `left - right` turned a quarter clockwise. This
/// is how an edge runs from `ends[0]` to `ends[1]` (see [`Edge::sites`]).
fn walking_direction(left: Point, right: Point) -> Point {
    Point::new(left.y - right.y, -(left.x - right.x))
}

/// The visible piece of an edge, normalised.
fn visible_piece(diagram: &Diagram, frame: &Frame, edge: &Edge) -> Option<(Point, Point)> {
    let vertex = |v| frame.unit(diagram.vertex(v).expect("edge ends are vertices of the diagram").position);
    let (left, right) = (frame.unit(site_point(diagram, edge.sites[0])), frame.unit(site_point(diagram, edge.sites[1])));
    let dir = walking_direction(left, right);
    let back = Point::new(-dir.x, -dir.y);
    match edge.ends {
        [EdgeEnd::Vertex(a), EdgeEnd::Vertex(b)] => {
            let (p, q) = (vertex(a), vertex(b));
            frame.clip(p, Point::new(q.x - p.x, q.y - p.y), 0.0, 1.0)
        }
        [EdgeEnd::Vertex(a), EdgeEnd::Infinite { .. }] => frame.clip(vertex(a), dir, 0.0, f64::INFINITY),
        [EdgeEnd::Infinite { .. }, EdgeEnd::Vertex(b)] => frame.clip(vertex(b), back, 0.0, f64::INFINITY),
        [EdgeEnd::Infinite { .. }, EdgeEnd::Infinite { .. }] => {
            // A whole line (all sites collinear): through the sites' midpoint.
            let middle = Point::new((left.x + right.x) / 2.0, (left.y + right.y) / 2.0);
            frame.clip(middle, dir, f64::NEG_INFINITY, f64::INFINITY)
        }
    }
}

/// A point standing for a site: the point, or a segment's midpoint.
fn site_point(diagram: &Diagram, s: segvoronoi::SiteId) -> Point {
    match diagram.site(s) {
        segvoronoi::Site::Point(p) => p,
        segvoronoi::Site::Segment { a, b } => Point::new(a.x / 2.0 + b.x / 2.0, a.y / 2.0 + b.y / 2.0),
    }
}

/// The SVG document for a diagram.
pub fn render(diagram: &Diagram) -> String {
    let sites: Vec<Point> = diagram.site_ids().map(|s| site_point(diagram, s)).collect();
    let frame = Frame::new(&sites);
    let (width, height) = (frame.width(), frame.height());
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}">"#
    );
    let _ = writeln!(
        out,
        "<!-- segvoronoi: {} sites, {} vertices, {} edges -->",
        diagram.site_count(),
        diagram.vertex_count(),
        diagram.edge_count()
    );
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);

    let _ = writeln!(out, r#"<g stroke="{EDGE_COLOUR}" stroke-width="1.2" stroke-linecap="round">"#);
    for edge in diagram.edges() {
        let Some((p, q)) = visible_piece(diagram, &frame, &edge) else { continue };
        if let (Some((x1, y1)), Some((x2, y2))) = (frame.pixel(p), frame.pixel(q)) {
            let _ = writeln!(out, r#"<line x1="{x1:.2}" y1="{y1:.2}" x2="{x2:.2}" y2="{y2:.2}"/>"#);
        }
    }
    let _ = writeln!(out, "</g>");

    let _ = writeln!(out, r#"<g fill="{VERTEX_COLOUR}">"#);
    for v in diagram.vertices() {
        let p = frame.unit(v.position);
        if frame.contains(p) {
            write_dot(&mut out, &frame, p, VERTEX_RADIUS);
        }
    }
    let _ = writeln!(out, "</g>");

    let _ = writeln!(out, r#"<g fill="{SITE_COLOUR}">"#);
    for &s in &sites {
        write_dot(&mut out, &frame, frame.unit(s), SITE_RADIUS);
    }
    let _ = writeln!(out, "</g>");
    out.push_str("</svg>\n");
    out
}

fn write_dot(out: &mut String, frame: &Frame, p: Point, radius: f64) {
    if let Some((x, y)) = frame.pixel(p) {
        let _ = writeln!(out, r#"<circle cx="{x:.2}" cy="{y:.2}" r="{radius}"/>"#);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use segvoronoi::Builder;

    fn diagram(points: &[[f64; 2]]) -> Diagram {
        let mut b = Builder::new();
        b.add_points(points.iter().copied()).unwrap();
        b.build().unwrap()
    }

    /// Every number in the document, which must all be finite and, for the
    /// drawn elements, inside the picture.
    fn check_numbers(svg: &str) -> Vec<f64> {
        assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
        let mut values = Vec::new();
        for attr in svg.split('"').skip(1).step_by(2) {
            if let Ok(v) = attr.parse::<f64>() {
                assert!(v.is_finite());
                values.push(v);
            }
        }
        values
    }

    fn lines(svg: &str) -> Vec<[f64; 4]> {
        svg.lines()
            .filter(|l| l.starts_with("<line"))
            .map(|l| {
                let v: Vec<f64> = l.split('"').skip(1).step_by(2).map(|a| a.parse().unwrap()).collect();
                [v[0], v[1], v[2], v[3]]
            })
            .collect()
    }

    #[test]
    fn our_ray_direction_agrees_with_the_library() {
        let d = diagram(&[[0.0, 0.0], [4.0, 0.5], [1.0, 3.0], [3.0, 3.5], [2.0, 1.5], [-1.0, 2.0]]);
        let mut rays = 0;
        for e in d.edges() {
            let dir = walking_direction(site_point(&d, e.sites[0]), site_point(&d, e.sites[1]));
            for (k, end) in e.ends.iter().enumerate() {
                if let EdgeEnd::Infinite { direction } = *end {
                    // ends[1] lies ahead along the walk, ends[0] behind it.
                    let sign = if k == 1 { 1.0 } else { -1.0 };
                    let cos = sign * (dir.x * direction.x + dir.y * direction.y) / (dir.x.hypot(dir.y));
                    assert!((cos - 1.0).abs() < 1e-9, "edge {:?}: {dir:?} vs {direction:?}", e);
                    rays += 1;
                }
            }
        }
        assert!(rays >= 4);
    }

    #[test]
    fn rays_reach_the_border_and_segments_stay_inside() {
        let svg = render(&diagram(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0]]));
        check_numbers(&svg);
        let (w, h) = (SIZE_PX, SIZE_PX);
        let on_border =
            |x: f64, y: f64| x.abs() < 0.01 || y.abs() < 0.01 || (x - w).abs() < 0.01 || (y - h).abs() < 0.01;
        let ls = lines(&svg);
        assert_eq!(ls.len(), 8);
        let rays = ls.iter().filter(|l| on_border(l[0], l[1]) || on_border(l[2], l[3])).count();
        assert_eq!(rays, 4, "{svg}");
        // No edge comes near a site: the centre site is at the picture's centre.
        for l in &ls {
            let (d, c) = ([l[2] - l[0], l[3] - l[1]], [w / 2.0 - l[0], h / 2.0 - l[1]]);
            let t = ((c[0] * d[0] + c[1] * d[1]) / (d[0] * d[0] + d[1] * d[1])).clamp(0.0, 1.0);
            let gap = (c[0] - t * d[0]).hypot(c[1] - t * d[1]);
            assert!(gap > 100.0, "edge {l:?} passes {gap} px from the centre site");
        }
        assert_eq!(svg.matches("<circle").count(), 4 + 5);
    }

    #[test]
    fn degenerate_inputs_give_finite_pictures() {
        let cases: &[&[[f64; 2]]] = &[
            &[],
            &[[3.0, 4.0]],
            &[[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]],
            &[[0.0, 0.0], [1.0, 0.0]],
            &[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [5.0, 5.0]],
            &[[0.0, 0.0], [0.0, 1.0], [0.0, 3.0]],
            &[[1e300, -1e300], [-1e300, 1e300], [1e300, 1e300]],
            &[[1e-310, 0.0], [0.0, 1e-310], [2e-310, 3e-310]],
        ];
        for points in cases {
            let d = diagram(points);
            let svg = render(&d);
            assert!(svg.starts_with("<svg"), "{svg}");
            check_numbers(&svg);
            assert_eq!(svg.matches("<circle").count(), d.site_count() + d.vertex_count(), "{points:?}: {svg}");
            // Every edge of these small inputs is visible.
            assert_eq!(lines(&svg).len(), d.edge_count(), "{points:?}: {svg}");
        }
    }

    #[test]
    fn collinear_bisectors_cross_the_whole_picture() {
        // Sites on the x axis: bisectors are vertical lines, top to bottom.
        let svg = render(&diagram(&[[0.0, 0.0], [2.0, 0.0], [6.0, 0.0]]));
        let ls = lines(&svg);
        assert_eq!(ls.len(), 2);
        let height: f64 = svg.split('"').nth(5).unwrap().parse().unwrap();
        for l in ls {
            assert!((l[0] - l[2]).abs() < 1e-6, "not vertical: {l:?}");
            // The picture's size is rounded up to whole pixels.
            assert!((l[1] - l[3]).abs() >= height - 1.0, "not full height: {l:?} of {height}");
        }
    }
}
