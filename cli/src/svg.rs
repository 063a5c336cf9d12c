//! The SVG picture: the sites' bounding box plus a margin, fitted into about
//! 800 pixels, y axis up; edges as thin lines, parabolic arcs as the exact
//! quadratic Bézier curves the library gives (`<path d="M .. Q .. .."/>`),
//! rays and lines clipped to the picture; vertices as small dots, point
//! sites as bigger dots of another colour, segment sites as thick lines of
//! that colour (their endpoints are point sites: dots), arc sites as thick
//! SVG arcs (`A`) of that colour. Edges beside an arc site (conics) are
//! drawn as the library's polylines within a quarter pixel; a conic edge
//! that reaches infinity, which has no polyline from the library, is traced
//! here from its vertex along the points equidistant from its two sites
//! until it leaves the picture (`trace_conic_ray`). With a domain
//! (polygons) also, beneath the edges, its inside lightly shaded (the rings
//! filled even-odd, as the library's domain), and above them the medial
//! axis, thick, each sampled stretch coloured by its clearance (a linear
//! ramp in RGB from teal at clearance 0 to magenta at the largest), and the
//! largest inscribed circle, dashed. Offsets (`--offset`), above those, as
//! one path per loop, exact: `L` for line pieces, `A` for arcs. With a
//! positive distance the picture grows by it on every side, so that the
//! grown loops (whose bounding box is the sites' grown by the distance)
//! are in it.
//!
//! All geometry is done in "normalised" coordinates, the input multiplied by
//! an exact power of two that brings the largest magnitude near 1, so that
//! inputs near the ends of the `f64` range neither overflow nor underflow on
//! the way to pixels. Anything that still is not finite is left out of the
//! picture rather than written as `NaN`.

use std::f64::consts::PI;
use std::fmt::Write;

use segvoronoi::{CircularArc, Diagram, Edge, EdgeEnd, EdgeShape, MedialAxis, Offset, OffsetLoop, OffsetPiece, Point, Site};

use crate::medial_output;
use crate::wkt::Step;

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
/// Stroke width of segment sites, in pixels.
const SEGMENT_WIDTH: f64 = 3.0;
const DOMAIN_FILL: &str = "#e4ecf4";
/// The clearance ramp's ends: clearance 0 and the largest.
const RAMP: [[f64; 3]; 2] = [[0.0, 158.0, 158.0], [200.0, 0.0, 125.0]];
/// Stroke width of the medial axis where its clearance is the largest, in
/// pixels; it thins towards clearance 0 down to `AXIS_THINNEST` of that,
/// so that on a detailed outline the branches into its many corners do not
/// bury the outline and the offsets near it.
const AXIS_WIDTH: f64 = 3.5;
const AXIS_THINNEST: f64 = 0.3;
const CIRCLE_COLOUR: &str = "#444444";
/// One colour per offset distance, in the order given (repeating after
/// eight): distinct hues that stand apart from the axis ramp (teal to
/// magenta, so no green-blue, purple or crimson here) and the shade.
const OFFSET_COLOURS: [&str; 8] = ["#e8590c", "#1864ab", "#f59f00", "#343a40", "#e03131", "#5c940d", "#8d5524", "#4263eb"];
/// The domain's outline and the obstacles when the diagram is not drawn.
const OUTLINE_COLOUR: &str = "#495057";
/// Steps of the clearance ramp: consecutive stretches of one step share a
/// polyline, which keeps a large axis to a few elements per chain.
const RAMP_STEPS: f64 = 32.0;
/// Stroke width of the offset loops, in pixels.
const OFFSET_WIDTH: f64 = 1.8;

/// What the picture adds when the input has polygons.
pub struct Domain<'a> {
    /// Every ring of every polygon, segments and arcs.
    pub rings: &'a [Vec<Step>],
    /// The medial axis to draw (filtered as the command line asks).
    pub axis: &'a MedialAxis,
    /// Chord tolerance of its samples, in input units.
    pub tolerance: f64,
    /// The linestrings and open curves, and the points, of the input
    /// (obstacles), drawn when the diagram is not.
    pub lines: &'a [Vec<Step>],
    pub points: &'a [[f64; 2]],
}

/// What the picture explains itself with. `Look::default()` is the bare
/// picture (the tests' frame); the program always gives a title.
#[derive(Clone, Debug, Default)]
pub struct Look {
    /// With a title: a band below the picture with the title, the legend
    /// and a scale bar.
    pub title: Option<String>,
    /// The name of the input's unit, for the scale bar (`None`: "units").
    pub units: Option<String>,
    /// Draw the Voronoi diagram (edges, vertices, sites) also with a
    /// domain; without one it is always drawn, being all there is.
    pub diagram: bool,
}

/// The exact power of two `2^-e` with `2^e <= max_abs < 2^(e+1)`, `e`
/// clamped to the normal exponents so that the factor itself is finite
/// (subnormal inputs then land a little below 1); 1 for zero or a value
/// that is not finite. Multiplying by it is exact, so the picture's
/// geometry is the input's, only nearer 1.
fn to_unit(max_abs: f64) -> f64 {
    if max_abs == 0.0 || !max_abs.is_finite() {
        return 1.0;
    }
    // The biased exponent field; a subnormal has 0 there and its leading
    // bit among the 52 fraction bits.
    let bits = max_abs.abs().to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let e = if biased == 0 { 63 - bits.leading_zeros() as i32 - 1074 } else { biased - 1023 };
    let e = e.clamp(-1022, 1022);
    // 2^-e built from its bits: a normal number for every clamped e.
    f64::from_bits(((1023 - e) as u64) << 52)
}

/// Maps input coordinates to normalised ones and those to pixels.
struct Frame {
    /// Exact power of two: input × `to_unit` = normalised.
    to_unit: f64,
    /// The visible rectangle, normalised: lower-left and upper-right corner.
    low: Point,
    high: Point,
    /// Pixels per normalised unit.
    px: f64,
    /// The longer side in pixels.
    size_px: f64,
    /// Factor of every stroke width and dot radius: below 1 where the
    /// sites are so dense that full-width strokes would cover each other.
    stroke: f64,
}

impl Frame {
    fn new(sites: &[Point]) -> Frame {
        Frame::sized(sites, SIZE_PX)
    }

    /// A frame whose longer side is `size_px` pixels.
    fn sized(sites: &[Point], size_px: f64) -> Frame {
        let max_abs = sites.iter().fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        let to_unit = to_unit(max_abs);
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
            px: size_px / (2.0 * hx.max(hy)),
            size_px,
            stroke: 1.0,
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

    /// Whether the bounding box of `points` meets the visible rectangle. A
    /// Bézier curve lies in the hull of its control points, so one whose
    /// box misses the picture is invisible.
    fn touches_hull(&self, points: &[Point]) -> bool {
        let fold = |f: fn(f64, f64) -> f64, start: f64, c: fn(&Point) -> f64| points.iter().map(c).fold(start, f);
        let (lx, hx) = (fold(f64::min, f64::INFINITY, |p| p.x), fold(f64::max, f64::NEG_INFINITY, |p| p.x));
        let (ly, hy) = (fold(f64::min, f64::INFINITY, |p| p.y), fold(f64::max, f64::NEG_INFINITY, |p| p.y));
        lx <= self.high.x && hx >= self.low.x && ly <= self.high.y && hy >= self.low.y
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

/// A point of the line that an edge with both ends at infinity lies on (all
/// sites collinear): the midpoint of two point sites, or the point itself
/// when the other site is a segment ending there (a separator).
fn line_anchor(diagram: &Diagram, edge: &Edge) -> Point {
    match edge.sites.map(|s| diagram.site(s).expect("edge sites are sites of the diagram")) {
        [Site::Point(p), Site::Point(q)] => Point::new(p.x / 2.0 + q.x / 2.0, p.y / 2.0 + q.y / 2.0),
        [Site::Point(p), s] | [s, Site::Point(p)] if s.has_endpoint(p) => p,
        // Not expected on collinear input; a site's middle keeps it drawable.
        [a, _] => site_middle(a),
    }
}

/// How an edge is drawn, normalised: a straight piece, a quadratic Bézier
/// curve `[start, control, end]` or a polyline.
enum Piece {
    Line(Point, Point),
    Curve([Point; 3]),
    Polyline(Vec<Point>),
}

/// The visible piece of an edge, normalised, or `None` if it misses the
/// picture. Finite parabolic arcs are the library's exact Bézier curves
/// (left to the SVG viewport to clip); rays and lines start at their vertex
/// (or a point of the line) and run in the library's direction at infinity.
fn visible_piece(diagram: &Diagram, frame: &Frame, edge: &Edge) -> Option<Piece> {
    let vertex = |v| frame.unit(diagram.vertex(v).expect("edge ends are vertices of the diagram").position);
    match edge.ends {
        [EdgeEnd::Vertex(a), EdgeEnd::Vertex(b)] => {
            if let Some(curve) = diagram.edge_bezier(edge.id) {
                let curve = curve.map(|p| frame.unit(p));
                return frame.touches_hull(&curve).then_some(Piece::Curve(curve));
            }
            if matches!(diagram.edge_shape(edge.id), Some(EdgeShape::Conic { .. })) {
                // a quarter pixel, in input units
                let tolerance = 0.25 / (frame.px * frame.to_unit);
                if let Some(line) = diagram.edge_polyline(edge.id, tolerance).filter(|l| l.len() > 2) {
                    let line: Vec<Point> = line.into_iter().map(|p| frame.unit(p)).collect();
                    return frame.touches_hull(&line).then_some(Piece::Polyline(line));
                }
            }
            let (p, q) = (vertex(a), vertex(b));
            frame.clip(p, Point::new(q.x - p.x, q.y - p.y), 0.0, 1.0).map(|(p, q)| Piece::Line(p, q))
        }
        // Both directions point away from the finite end, towards infinity.
        [EdgeEnd::Vertex(a), EdgeEnd::Infinite { direction }] | [EdgeEnd::Infinite { direction }, EdgeEnd::Vertex(a)] => {
            if matches!(diagram.edge_shape(edge.id), Some(EdgeShape::Conic { .. })) {
                if let Some(line) = trace_conic_ray(diagram, frame, edge, a, direction) {
                    return Some(Piece::Polyline(line));
                }
            }
            frame.clip(vertex(a), direction, 0.0, f64::INFINITY).map(|(p, q)| Piece::Line(p, q))
        }
        [EdgeEnd::Infinite { .. }, EdgeEnd::Infinite { direction }] => frame
            .clip(frame.unit(line_anchor(diagram, edge)), direction, f64::NEG_INFINITY, f64::INFINITY)
            .map(|(p, q)| Piece::Line(p, q)),
    }
}

/// The distance from `p` to a site and its gradient there (the unit
/// vector from the site's nearest point).
fn distance_and_gradient(site: Site, p: Point) -> Option<(f64, Point)> {
    let q = site.nearest_point(p);
    let d = q.distance(p);
    (d > 0.0 && d.is_finite()).then(|| (d, Point::new((p.x - q.x) / d, (p.y - q.y) / d)))
}

/// A conic ray (an edge beside an arc with one end at infinity, for which
/// the library gives no polyline), traced in the picture: from its vertex
/// along the curve of points equidistant from its two sites, in steps of
/// two pixels, each step corrected back onto the curve by Newton's method
/// on the difference of the two distances, until it leaves the picture.
/// Normalised coordinates; `None` where the tracing loses the curve (the
/// caller then draws the straight ray).
fn trace_conic_ray(
    diagram: &Diagram,
    frame: &Frame,
    edge: &Edge,
    from: segvoronoi::VertexId,
    direction: Point,
) -> Option<Vec<Point>> {
    let vertex = diagram.vertex(from)?;
    let [first, second] = edge.sites.map(|s| diagram.site(s));
    let (first, second) = (first?, second?);
    let third = vertex.sites.iter().find(|s| !edge.sites.contains(s)).and_then(|&s| diagram.site(s));
    let step = 2.0 / (frame.px * frame.to_unit);
    let scale = vertex.clearance.max(step);
    // the difference of the distances and its gradient
    let f = |p: Point| -> Option<(f64, Point)> {
        let ((d1, g1), (d2, g2)) = (distance_and_gradient(first, p)?, distance_and_gradient(second, p)?);
        Some((d1 - d2, Point::new(g1.x - g2.x, g1.y - g2.y)))
    };
    let onto_curve = |mut p: Point| -> Option<Point> {
        for _ in 0..8 {
            let (value, g) = f(p)?;
            let g2 = g.x * g.x + g.y * g.y;
            if g2 < 1e-12 {
                return None;
            }
            p = Point::new(p.x - value / g2 * g.x, p.y - value / g2 * g.y);
            if value.abs() <= 1e-12 * scale {
                return Some(p);
            }
        }
        let (value, _) = f(p)?;
        (value.abs() <= 1e-6 * scale).then_some(p)
    };
    let tangent = |p: Point, like: Point| -> Option<Point> {
        let (_, g) = f(p)?;
        let n = g.x.hypot(g.y);
        let t = Point::new(-g.y / n, g.x / n);
        if !t.x.is_finite() || !t.y.is_finite() {
            return None;
        }
        Some(if t.x * like.x + t.y * like.y < 0.0 { Point::new(-t.x, -t.y) } else { t })
    };
    // one step along the curve from `p` in about the direction `t`
    let advance = |p: Point, t: Point| -> Option<(Point, Point)> {
        let next = onto_curve(Point::new(p.x + step * t.x, p.y + step * t.y))?;
        Some((next, tangent(next, t)?))
    };
    // Which way the edge leaves its vertex: into the side where the
    // vertex's third site is farther than the edge's two, judged a few
    // steps along each way (at the vertex itself the third site may be
    // tangent to the curve); without one, the side of the direction at
    // infinity.
    let mut p = vertex.position;
    let mut t = tangent(p, direction)?;
    if let Some(third) = third {
        let margin = |t: Point| -> Option<f64> {
            let (mut q, mut t) = (p, t);
            for _ in 0..8 {
                (q, t) = advance(q, t)?;
            }
            Some(third.distance(q) - first.distance(q))
        };
        let back = Point::new(-t.x, -t.y);
        if let (forward, Some(backward)) = (margin(t), margin(back)) {
            if forward.is_none_or(|forward| backward > forward) {
                t = back;
            }
        }
    }
    let mut line = vec![frame.unit(p)];
    let limit = (4.0 * frame.size_px) as usize;
    for _ in 0..limit {
        (p, t) = advance(p, t)?;
        let u = frame.unit(p);
        line.push(u);
        let (w, h) = (frame.high.x - frame.low.x, frame.high.y - frame.low.y);
        if u.x < frame.low.x - 0.1 * w
            || u.x > frame.high.x + 0.1 * w
            || u.y < frame.low.y - 0.1 * h
            || u.y > frame.high.y + 0.1 * h
        {
            return Some(line);
        }
    }
    // still in the picture after all those steps: draw what was traced,
    // then straight on
    let (a, b) = frame.clip(frame.unit(p), direction, 0.0, f64::INFINITY)?;
    line.extend([a, b]);
    Some(line)
}

/// The middle of a site: the point, or a segment's midpoint.
fn site_middle(site: Site) -> Point {
    match site {
        Site::Point(p) => p,
        Site::Segment { a, b } => Point::new(a.x / 2.0 + b.x / 2.0, a.y / 2.0 + b.y / 2.0),
        Site::Arc(arc) => arc.midpoint(),
        other => unreachable!("a site kind this drawing does not know: {other:?}"),
    }
}

/// The SVG document for a diagram, with its domain when there is one and
/// the offset loops of `offsets`.
pub fn render(diagram: &Diagram, domain: Option<&Domain>, offsets: &[Offset], look: &Look) -> String {
    let show_diagram = look.diagram || domain.is_none();
    // The picture frames every point site; segment endpoints are point sites.
    let points: Vec<Point> = diagram.site_ids().filter_map(|s| diagram.site(s)?.as_point()).collect();
    let segments: Vec<(Point, Point)> = diagram
        .site_ids()
        .filter_map(|s| match diagram.site(s)? {
            Site::Segment { a, b } => Some((a, b)),
            _ => None,
        })
        .collect();
    let arcs: Vec<CircularArc> = diagram
        .site_ids()
        .filter_map(|s| match diagram.site(s)? {
            Site::Arc(arc) => Some(arc),
            _ => None,
        })
        .collect();
    // The frame holds the arcs' bulges too (sixteen points along each; the
    // margin covers the rest).
    let framed: Vec<Point> =
        points.iter().copied().chain(arcs.iter().flat_map(|a| (1..16).map(|k| a.point_at(f64::from(k) / 16.0)))).collect();
    let mut frame = Frame::new(&grown_box(&framed, offsets));
    if look.title.is_some() {
        // Sized by what it shows: about 16 pixels between neighbouring
        // sites where that fits in 4000 pixels, at least 800; the strokes
        // thinner where even that is too dense. (The bare picture of the
        // tests keeps 800 pixels and full strokes.)
        let spacing = |size: f64| size / (points.len().max(1) as f64).sqrt();
        let size = (16.0 * SIZE_PX / spacing(SIZE_PX)).clamp(SIZE_PX, 5.0 * SIZE_PX);
        frame = Frame::sized(&grown_box(&framed, offsets), size);
        frame.stroke = (spacing(size) / 16.0).clamp(0.25, 1.0);
    }
    let (width, picture_height) = (frame.width(), frame.height());
    let band = look.title.as_ref().map(|title| Band::new(title, &frame, diagram, domain, offsets, show_diagram, look));
    let height = picture_height + band.as_ref().map_or(0.0, |b| b.height);
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}">"#
    );
    let _ = writeln!(
        out,
        "<!-- segvoronoi: {} sites ({} segments{}), {} vertices, {} edges -->",
        diagram.site_count(),
        segments.len(),
        if arcs.is_empty() { String::new() } else { format!(", {} arcs", arcs.len()) },
        diagram.vertex_count(),
        diagram.edge_count()
    );
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
    if let Some(title) = &look.title {
        let _ = writeln!(out, "<title>{}</title>", escape(title));
    }
    if domain.is_some() {
        // The clearance ramp as a gradient, for the legend's swatch.
        let _ = writeln!(
            out,
            r#"<defs><linearGradient id="clearance-ramp"><stop offset="0" stop-color="{}"/><stop offset="1" stop-color="{}"/></linearGradient></defs>"#,
            ramp(0.0),
            ramp(1.0)
        );
    }
    if let Some(domain) = domain {
        write_domain(&mut out, &frame, domain.rings, !show_diagram);
    }
    if show_diagram {
        write_diagram(&mut out, &frame, diagram);
    } else if let Some(domain) = domain {
        write_obstacles(&mut out, &frame, domain);
    }
    if let Some(domain) = domain {
        write_axis(&mut out, &frame, diagram, domain);
    }
    write_offsets(&mut out, &frame, offsets);
    if show_diagram {
        write_sites(&mut out, &frame, &points, &segments, &arcs);
    }
    if let Some(band) = band {
        band.write(&mut out, picture_height, width);
    }
    out.push_str("</svg>\n");
    out
}

/// The Voronoi edges: lines and rays clipped to the picture, parabolic arcs
/// as quadratic Béziers; then the vertices in the picture.
fn write_diagram(out: &mut String, frame: &Frame, diagram: &Diagram) {
    let _ = writeln!(out, r#"<g id="edges" stroke="{EDGE_COLOUR}" stroke-width="1.2" stroke-linecap="round" fill="none">"#);
    for edge in diagram.edges() {
        match visible_piece(diagram, frame, &edge) {
            Some(Piece::Line(p, q)) => {
                if let (Some((x1, y1)), Some((x2, y2))) = (frame.pixel(p), frame.pixel(q)) {
                    let _ = writeln!(out, r#"<line x1="{x1:.2}" y1="{y1:.2}" x2="{x2:.2}" y2="{y2:.2}"/>"#);
                }
            }
            Some(Piece::Curve([p, c, q])) => {
                if let (Some((x0, y0)), Some((cx, cy)), Some((x1, y1))) = (frame.pixel(p), frame.pixel(c), frame.pixel(q)) {
                    let _ = writeln!(out, r#"<path d="M {x0:.2} {y0:.2} Q {cx:.2} {cy:.2} {x1:.2} {y1:.2}"/>"#);
                }
            }
            Some(Piece::Polyline(line)) => {
                let pixels: Option<Vec<(f64, f64)>> = line.iter().map(|&p| frame.pixel(p)).collect();
                if let Some(pixels) = pixels {
                    let points: Vec<String> = pixels.iter().map(|(x, y)| format!("{x:.2},{y:.2}")).collect();
                    let _ = writeln!(out, r#"<polyline points="{}"/>"#, points.join(" "));
                }
            }
            None => {}
        }
    }
    let _ = writeln!(out, "</g>");
    let _ = writeln!(out, r#"<g id="vertices" fill="{VERTEX_COLOUR}">"#);
    for v in diagram.vertices() {
        let p = frame.unit(v.position);
        if frame.contains(p) {
            write_dot(out, frame, p, VERTEX_RADIUS * frame.stroke);
        }
    }
    let _ = writeln!(out, "</g>");
}

/// The sites: segments as thick lines, arcs as thick SVG arcs, points as
/// dots.
fn write_sites(out: &mut String, frame: &Frame, points: &[Point], segments: &[(Point, Point)], arcs: &[CircularArc]) {
    let _ = writeln!(
        out,
        r#"<g id="segments" stroke="{SITE_COLOUR}" stroke-width="{}" stroke-linecap="round">"#,
        SEGMENT_WIDTH * frame.stroke
    );
    for &(a, b) in segments {
        if let (Some((x1, y1)), Some((x2, y2))) = (frame.pixel(frame.unit(a)), frame.pixel(frame.unit(b))) {
            let _ = writeln!(out, r#"<line x1="{x1:.2}" y1="{y1:.2}" x2="{x2:.2}" y2="{y2:.2}"/>"#);
        }
    }
    let _ = writeln!(out, "</g>");
    if !arcs.is_empty() {
        let _ = writeln!(
            out,
            r#"<g id="arcs" stroke="{SITE_COLOUR}" stroke-width="{}" stroke-linecap="round" fill="none">"#,
            SEGMENT_WIDTH * frame.stroke
        );
        for arc in arcs {
            if let Some(d) = arc_path(frame, arc) {
                let _ = writeln!(out, r#"<path d="{d}"/>"#);
            }
        }
        let _ = writeln!(out, "</g>");
    }

    let _ = writeln!(out, r#"<g id="sites" fill="{SITE_COLOUR}">"#);
    for &p in points {
        write_dot(out, frame, frame.unit(p), SITE_RADIUS * frame.stroke);
    }
    let _ = writeln!(out, "</g>");
}

/// Without the diagram: the input's linestrings as one thin path and its
/// points as dots (the rings are the domain's outline).
fn write_obstacles(out: &mut String, frame: &Frame, domain: &Domain) {
    let d: String = domain.lines.iter().map(|line| chain_data(frame, line)).collect();
    let _ = writeln!(
        out,
        r#"<path id="obstacles" fill="none" stroke="{OUTLINE_COLOUR}" stroke-width="1.5" stroke-linejoin="round" d="{}"/>"#,
        d.trim_end()
    );
    let _ = writeln!(out, r#"<g id="points" fill="{OUTLINE_COLOUR}">"#);
    for &[x, y] in domain.points {
        write_dot(out, frame, frame.unit(Point::new(x, y)), SITE_RADIUS * frame.stroke);
    }
    let _ = writeln!(out, "</g>");
}

/// `M x y` at a chain's start, then `L x y` along its segments and `A ...`
/// along its arcs, in pixels, pieces that are not finite there left out;
/// empty for an empty chain.
fn chain_data(frame: &Frame, chain: &[Step]) -> String {
    let pixel = |p: [f64; 2]| frame.pixel(frame.unit(p.into())).map(|(x, y)| format!("{x:.2} {y:.2}"));
    let Some(start) = chain.first().and_then(|s| pixel(s.start())) else { return String::new() };
    let mut d = format!("M {start}");
    for step in chain {
        let to = match step {
            Step::Segment([_, b]) => pixel(*b).map(|b| format!(" L {b}")),
            Step::Arc(arc) => arc_to(frame, arc),
        };
        d.push_str(&to.unwrap_or_default());
    }
    d.push(' ');
    d
}

/// The band below the picture: the title on its first row with the scale
/// bar at the right, then the legend, its entries wrapped into rows as wide
/// as the picture.
struct Band {
    title: String,
    /// Entries: a swatch (SVG drawn in a 24 × 12 box at the origin) and a
    /// label.
    entries: Vec<(String, String)>,
    /// The scale bar: its length in pixels and its label.
    scale: Option<(f64, String)>,
    /// Rows of entries: the index of each row's first entry.
    rows: Vec<usize>,
    /// In the picture's pixels: the band is laid out for an 800-pixel
    /// picture and drawn `zoom` times as large, so that a larger picture
    /// (a large input) shows it at the same size when fitted to a screen.
    height: f64,
    zoom: f64,
}

/// Pixels per character of the 12 px labels, a safe estimate for
/// sans-serif text (no font metrics in a plain SVG writer).
const CHAR_PX: f64 = 6.6;
const ROW_PX: f64 = 20.0;
const TITLE_PX: f64 = 30.0;

impl Band {
    fn new(
        title: &str,
        frame: &Frame,
        diagram: &Diagram,
        domain: Option<&Domain>,
        offsets: &[Offset],
        show_diagram: bool,
        look: &Look,
    ) -> Band {
        let mut entries = Vec::new();
        if let Some(domain) = domain {
            entries.push((
                format!(r#"<rect x="1" y="1" width="22" height="10" fill="{DOMAIN_FILL}" stroke="{OUTLINE_COLOUR}" stroke-width="0.8"/>"#),
                "domain".to_string(),
            ));
            let top = domain_top(diagram, domain);
            entries.push((
                r#"<rect x="0" y="3" width="24" height="6" fill="url(#clearance-ramp)"/>"#.to_string(),
                format!("medial axis, clearance 0 to {}", short(top)),
            ));
            if let Some((_, r)) = diagram.max_inscribed_circle() {
                entries.push((
                    format!(r#"<circle cx="12" cy="6" r="5" fill="none" stroke="{CIRCLE_COLOUR}" stroke-width="1.5" stroke-dasharray="3 2"/>"#),
                    format!("largest inscribed circle, r = {}", short(r)),
                ));
            }
        }
        for (k, offset) in offsets.iter().enumerate() {
            let colour = OFFSET_COLOURS[k % OFFSET_COLOURS.len()];
            entries.push((
                format!(r#"<line x1="0" y1="6" x2="24" y2="6" stroke="{colour}" stroke-width="{OFFSET_WIDTH}"/>"#),
                format!("offset {}", short(offset.distance)),
            ));
        }
        if show_diagram {
            entries.push((
                format!(r#"<line x1="0" y1="6" x2="24" y2="6" stroke="{EDGE_COLOUR}" stroke-width="1.2"/>"#),
                "Voronoi edges".to_string(),
            ));
            entries.push((format!(r#"<circle cx="12" cy="6" r="{SITE_RADIUS}" fill="{SITE_COLOUR}"/>"#), "sites".to_string()));
        }
        // Rows: an entry is 24 px of swatch, 6 of gap, its label, 16 after.
        let zoom = frame.size_px / SIZE_PX;
        let width = frame.width() / zoom;
        let mut rows = vec![0];
        let mut x = 10.0;
        for (k, (_, label)) in entries.iter().enumerate() {
            let w = 30.0 + CHAR_PX * label.chars().count() as f64 + 16.0;
            if x + w > width && k > *rows.last().unwrap() {
                rows.push(k);
                x = 10.0;
            }
            x += w;
        }
        let units = look.units.clone().unwrap_or_else(|| "units".into());
        let scale = scale_bar(frame, width / 4.0 * zoom).map(|(px, length)| (px / zoom, format!("{} {units}", short(length))));
        let rows_used = if entries.is_empty() { 0 } else { rows.len() };
        Band { title: title.to_string(), entries, scale, rows, height: (TITLE_PX + ROW_PX * rows_used as f64 + 8.0) * zoom, zoom }
    }

    /// Draws the band from `top` on, `width` pixels wide.
    fn write(&self, out: &mut String, top: f64, width: f64) {
        let _ = writeln!(
            out,
            r##"<g id="legend" font-family="sans-serif" font-size="12" fill="#212529" transform="translate(0 {top}) scale({})">"##,
            self.zoom
        );
        // From here on the band's own coordinates.
        let (y0, width) = (0.0, width / self.zoom);
        let _ = writeln!(out, r##"<rect x="0" y="{y0}" width="{width}" height="{}" fill="#f8f9fa"/>"##, self.height / self.zoom);
        let _ = writeln!(
            out,
            r#"<text x="10" y="{:.1}" font-size="15" font-weight="bold">{}</text>"#,
            y0 + 21.0,
            escape(&self.title)
        );
        if let Some((px, label)) = &self.scale {
            // Right-aligned on the title row: the bar, ticks at both ends,
            // the length above.
            let (x1, x2, y) = (width - 10.0 - px, width - 10.0, y0 + 22.0);
            let _ = writeln!(
                out,
                r##"<g id="scale-bar" stroke="#212529" stroke-width="1.5"><line x1="{x1:.2}" y1="{y:.1}" x2="{x2:.2}" y2="{y:.1}"/><line x1="{x1:.2}" y1="{:.1}" x2="{x1:.2}" y2="{y:.1}"/><line x1="{x2:.2}" y1="{:.1}" x2="{x2:.2}" y2="{y:.1}"/></g>"##,
                y - 5.0,
                y - 5.0
            );
            let _ = writeln!(
                out,
                r#"<text x="{:.2}" y="{:.1}" text-anchor="middle">{}</text>"#,
                (x1 + x2) / 2.0,
                y - 7.0,
                escape(label)
            );
        }
        for (r, &first) in self.rows.iter().enumerate() {
            let end = self.rows.get(r + 1).copied().unwrap_or(self.entries.len());
            let y = y0 + TITLE_PX + ROW_PX * r as f64;
            let mut x = 10.0;
            for (swatch, label) in &self.entries[first..end] {
                let _ = writeln!(out, r#"<g transform="translate({x:.1} {y:.1})">{swatch}</g>"#);
                let _ = writeln!(out, r#"<text x="{:.1}" y="{:.1}">{}</text>"#, x + 30.0, y + 10.5, escape(label));
                x += 30.0 + CHAR_PX * label.chars().count() as f64 + 16.0;
            }
        }
        let _ = writeln!(out, "</g>");
    }
}

/// A round length (1, 2 or 5 times a power of ten, in input units) whose
/// bar is at most `max_px` long, and that bar's pixels.
fn scale_bar(frame: &Frame, max_px: f64) -> Option<(f64, f64)> {
    let px_per_unit = frame.to_unit * frame.px;
    let most = max_px / px_per_unit;
    if !(most.is_finite() && most > 0.0) {
        return None;
    }
    let power = 10f64.powf(most.log10().floor());
    let length = [5.0, 2.0, 1.0].into_iter().map(|m| m * power).find(|&l| l <= most)?;
    let px = length * px_per_unit;
    (px.is_finite() && px > 0.0).then_some((px, length))
}

/// A number for a label: four significant digits, no trailing zeros,
/// scientific notation outside 1e-3 .. 1e6.
fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor();
    if !(-3.0..6.0).contains(&magnitude) {
        return format!("{v:.3e}");
    }
    let decimals = (3.0 - magnitude).max(0.0) as usize;
    let text = format!("{v:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// Text for an SVG text node.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// The top of the clearance ramp: the largest clearance of the drawn axis,
/// and at least the largest inscribed circle's.
fn domain_top(diagram: &Diagram, domain: &Domain) -> f64 {
    let circle = diagram.max_inscribed_circle();
    domain
        .axis
        .chains
        .iter()
        .filter_map(|c| medial_output::sample(diagram, c, domain.tolerance))
        .flatten()
        .fold(circle.map_or(0.0, |(_, r)| r), |m, p| m.max(p[2]))
}

/// The domain's inside: one path of every ring (`L` along its segments,
/// `A` along its arcs), filled even-odd. With `outline` (the diagram,
/// whose sites would show the rings, is not drawn) also its boundary, thin.
fn write_domain(out: &mut String, frame: &Frame, rings: &[Vec<Step>], outline: bool) {
    let mut d = String::new();
    for ring in rings.iter().map(|ring| chain_data(frame, ring)).filter(|d| !d.is_empty()) {
        d.push_str(&ring);
        d.push_str("Z ");
    }
    let stroke = if outline {
        format!(r#"stroke="{OUTLINE_COLOUR}" stroke-width="0.8" stroke-linejoin="round""#)
    } else {
        r#"stroke="none""#.into()
    };
    let _ = writeln!(out, r#"<path id="domain" fill="{DOMAIN_FILL}" fill-rule="evenodd" {stroke} d="{}"/>"#, d.trim_end());
}

/// The medial axis, sampled as `--medial-axis` samples it (rays cut), each
/// stretch between two samples coloured by the clearance at its middle;
/// then the largest inscribed circle.
fn write_axis(out: &mut String, frame: &Frame, diagram: &Diagram, domain: &Domain) {
    let circle = diagram.max_inscribed_circle();
    let chains: Vec<Vec<[f64; 3]>> =
        domain.axis.chains.iter().filter_map(|c| medial_output::sample(diagram, c, domain.tolerance)).collect();
    // The ramp's top: the largest clearance drawn, and at least the
    // circle's, so that the centre of the largest disk is always magenta.
    let top = chains.iter().flatten().fold(circle.map_or(0.0, |(_, r)| r), |m, p| m.max(p[2]));
    let _ = writeln!(
        out,
        r#"<g id="medial-axis" stroke-width="{}" stroke-linecap="round" stroke-linejoin="round" fill="none" data-max-clearance="{top}">"#,
        AXIS_WIDTH * frame.stroke
    );
    // Runs of stretches whose clearance falls in one ramp step, each a
    // polyline (the runs share their end points), gathered by step: one
    // group per step with its colour and width, the lowest clearance first
    // so that the axis's trunk lies on top of its branches.
    let mut by_step: Vec<Vec<String>> = vec![Vec::new(); RAMP_STEPS as usize];
    for points in &chains {
        let step = |w: &[[f64; 3]]| {
            let t = if top > 0.0 { (w[0][2] + w[1][2]) / 2.0 / top } else { 0.0 };
            (t.clamp(0.0, 1.0) * RAMP_STEPS).floor().min(RAMP_STEPS - 1.0)
        };
        let mut k = 0;
        while k + 1 < points.len() {
            let level = step(&points[k..k + 2]);
            let mut end = k + 1;
            while end + 1 < points.len() && step(&points[end..end + 2]) == level {
                end += 1;
            }
            let run: Vec<String> = points[k..=end]
                .iter()
                .filter_map(|p| frame.pixel(frame.unit(Point::new(p[0], p[1]))))
                .map(|(x, y)| format!("{x:.2},{y:.2}"))
                .collect();
            if run.len() >= 2 {
                by_step[level as usize].push(run.join(" "));
            }
            k = end;
        }
    }
    for (level, runs) in by_step.iter().enumerate().filter(|(_, runs)| !runs.is_empty()) {
        let t = (level as f64 + 0.5) / RAMP_STEPS;
        let width = AXIS_WIDTH * frame.stroke * (AXIS_THINNEST + (1.0 - AXIS_THINNEST) * t);
        let _ = writeln!(out, r#"<g stroke="{}" stroke-width="{width:.2}">"#, ramp(t));
        for run in runs {
            let _ = writeln!(out, r#"<polyline points="{run}"/>"#);
        }
        let _ = writeln!(out, "</g>");
    }
    let _ = writeln!(out, "</g>");
    if let Some((centre, r)) = circle {
        if let Some((x, y)) = frame.pixel(frame.unit(centre)) {
            let r = r * frame.to_unit * frame.px;
            let _ = writeln!(
                out,
                r#"<circle id="inscribed-circle" cx="{x:.2}" cy="{y:.2}" r="{r:.2}" fill="none" stroke="{CIRCLE_COLOUR}" stroke-width="1.5" stroke-dasharray="6 4"/>"#
            );
        }
    }
}

/// The points to frame: the sites, and with a positive offset distance the
/// corners of their bounding box grown by the largest (left out if they
/// overflow).
fn grown_box(points: &[Point], offsets: &[Offset]) -> Vec<Point> {
    let mut framed = points.to_vec();
    let grow = offsets.iter().map(|o| o.distance).filter(|&d| d > 0.0).fold(0.0f64, f64::max);
    if let (Some(&first), true) = (points.first(), grow > 0.0) {
        let (mut low, mut high) = (first, first);
        for p in points {
            (low.x, low.y, high.x, high.y) = (low.x.min(p.x), low.y.min(p.y), high.x.max(p.x), high.y.max(p.y));
        }
        let corners = [Point::new(low.x - grow, low.y - grow), Point::new(high.x + grow, high.y + grow)];
        if corners.iter().all(|c| c.x.is_finite() && c.y.is_finite()) {
            framed.extend(corners);
        }
    }
    framed
}

/// The offset loops, a path each, tagged with their distance.
fn write_offsets(out: &mut String, frame: &Frame, offsets: &[Offset]) {
    if offsets.is_empty() {
        return;
    }
    let _ =
        writeln!(out, r#"<g id="offsets" stroke-width="{}" stroke-linejoin="round" fill="none">"#, OFFSET_WIDTH * frame.stroke);
    for (k, offset) in offsets.iter().enumerate() {
        let colour = OFFSET_COLOURS[k % OFFSET_COLOURS.len()];
        for l in &offset.loops {
            if let Some(d) = loop_path(frame, l) {
                let _ = writeln!(out, r#"<path stroke="{colour}" data-distance="{}" d="{d}"/>"#, offset.distance);
            }
        }
    }
    let _ = writeln!(out, "</g>");
}

/// A loop as SVG path data: `M`, then `L` to the end of each line piece and
/// `A` along each arc, then `Z`; `None` when a point is not finite.
///
/// The picture's y axis points down, so an arc counter-clockwise in the
/// input is clockwise on the screen: sweep flag 0 (SVG's "negative
/// angle" direction). The large-arc flag is set for an arc over more than
/// half a turn. An arc whose ends fall on the same pixel coordinates
/// (a whole circle, or nearly) would be dropped by SVG, which draws
/// nothing between equal ends: over more than half a turn it is drawn as
/// two half circles through the point opposite its start, and below that
/// it is too small to see and left out.
fn loop_path(frame: &Frame, l: &OffsetLoop) -> Option<String> {
    let pixel = |p: Point| frame.pixel(frame.unit(p)).map(|(x, y)| format!("{x:.2} {y:.2}"));
    let mut d = format!("M {}", pixel(l.pieces.first()?.from())?);
    for piece in &l.pieces {
        match *piece {
            OffsetPiece::Arc { centre, radius, from, to, counter_clockwise, .. } => {
                let r = radius * frame.to_unit * frame.px;
                if !r.is_finite() {
                    return None;
                }
                let turn = piece.sweep().expect("an arc");
                let (start, end) = (pixel(from)?, pixel(to)?);
                let flag = u8::from(!counter_clockwise);
                if start != end {
                    let _ = write!(d, " A {r:.2} {r:.2} 0 {} {flag} {end}", u8::from(turn > PI));
                } else if turn > PI {
                    let opposite = pixel(Point::new(2.0 * centre.x - from.x, 2.0 * centre.y - from.y))?;
                    let _ = write!(d, " A {r:.2} {r:.2} 0 0 {flag} {opposite} A {r:.2} {r:.2} 0 0 {flag} {end}");
                }
            }
            // a line, or a piece of a kind not drawn yet: straight to its end
            _ => {
                let _ = write!(d, " L {}", pixel(piece.to())?);
            }
        }
    }
    d.push_str(" Z");
    Some(d)
}

/// An arc site as an SVG path `M start A r r 0 large sweep end` (see
/// [`arc_to`]); `None` if not finite in pixels.
fn arc_path(frame: &Frame, arc: &CircularArc) -> Option<String> {
    let start = frame.pixel(frame.unit(arc.start())).map(|(x, y)| format!("{x:.2} {y:.2}"))?;
    Some(format!("M {start}{}", arc_to(frame, arc)?))
}

/// The path command that goes along an arc from its start: ` A r r 0
/// large sweep end`, flagged as `loop_path` flags the arcs of offsets (y
/// down: counter-clockwise in the input is sweep flag 0); `None` if not
/// finite in pixels. Ends on one pixel position (an arc too small to see)
/// are ` L end`, a dot's worth of line, which SVG shows, rather than an
/// arc it would drop.
fn arc_to(frame: &Frame, arc: &CircularArc) -> Option<String> {
    let pixel = |p: Point| frame.pixel(frame.unit(p)).map(|(x, y)| format!("{x:.2} {y:.2}"));
    let (start, end) = (pixel(arc.start())?, pixel(arc.end())?);
    let r = arc.radius() * frame.to_unit * frame.px;
    if !r.is_finite() {
        return None;
    }
    if start == end {
        return Some(format!(" L {end}"));
    }
    let large = u8::from(arc.sweep().abs() > PI);
    let sweep = u8::from(!arc.is_counter_clockwise());
    Some(format!(" A {r:.2} {r:.2} 0 {large} {sweep} {end}"))
}

/// The colour at `t` in `[0, 1]` of the clearance ramp (`RAMP`).
fn ramp(t: f64) -> String {
    let t = if t.is_finite() { t.clamp(0.0, 1.0) } else { 1.0 };
    let [r, g, b] = [0, 1, 2].map(|k| (RAMP[0][k] + t * (RAMP[1][k] - RAMP[0][k])).round() as u8);
    format!("#{r:02x}{g:02x}{b:02x}")
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

    /// Polygon rings as the domain's chains of segments.
    fn steps(rings: &[Vec<[f64; 2]>]) -> Vec<Vec<Step>> {
        rings.iter().map(|ring| crate::wkt::ring_steps(ring)).collect()
    }

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

    /// The text of the group with this id (with the groups inside it).
    fn group<'a>(svg: &'a str, id: &str) -> &'a str {
        let start = svg.find(&format!(r#"<g id="{id}""#)).unwrap_or_else(|| panic!("no group {id}"));
        let mut depth = 0;
        let mut at = start;
        loop {
            let (open, close) = (svg[at + 1..].find("<g ").map(|i| i + at + 1), svg[at..].find("</g>").map(|i| i + at));
            match (open, close) {
                (Some(o), Some(c)) if o < c => {
                    depth += 1;
                    at = o;
                }
                (_, Some(c)) if depth > 0 => {
                    depth -= 1;
                    at = c + 4;
                }
                (_, Some(c)) => return &svg[start..c],
                _ => panic!("group {id} is not closed"),
            }
        }
    }

    /// The straight edges: `<line>` elements of the edges group.
    fn lines(svg: &str) -> Vec<[f64; 4]> {
        numbers_of(group(svg, "edges"), "<line")
    }

    /// The first four numbers in the quoted attributes of each element
    /// starting with `tag`.
    fn numbers_of(text: &str, tag: &str) -> Vec<[f64; 4]> {
        text.lines()
            .filter(|l| l.starts_with(tag))
            .map(|l| {
                let v: Vec<f64> = l.split('"').skip(1).step_by(2).filter_map(|a| a.parse().ok()).collect();
                [v[0], v[1], v[2], v[3]]
            })
            .collect()
    }

    /// The parabolic arcs: `[x0, y0, cx, cy, x1, y1]` of each `<path>`.
    fn curves(svg: &str) -> Vec<[f64; 6]> {
        group(svg, "edges")
            .lines()
            .filter_map(|l| l.strip_prefix(r#"<path d=""#))
            .map(|d| {
                let d = d.trim_end_matches(r#""/>"#);
                let words: Vec<&str> = d.split(' ').collect();
                assert_eq!((words.len(), words[0], words[3]), (8, "M", "Q"), "{d}");
                let v: Vec<f64> = words.iter().filter_map(|a| a.parse().ok()).collect();
                [v[0], v[1], v[2], v[3], v[4], v[5]]
            })
            .collect()
    }

    fn with_segments(points: &[[f64; 2]], segments: &[[[f64; 2]; 2]]) -> Diagram {
        let mut b = Builder::new();
        b.add_points(points.iter().copied()).unwrap();
        b.add_segments(segments.iter().copied()).unwrap();
        b.build().unwrap()
    }

    #[test]
    fn rays_follow_the_library_direction() {
        // The segment (0,0)-(4,0) under the point (2,2): below the segment
        // its cell is the strip 0 < x < 4, bounded by the separators, two
        // vertical rays down from (0,2) and (4,2). A direction made up from
        // the sites' middles would tilt them.
        let d = with_segments(&[[2.0, 2.0]], &[[[0.0, 0.0], [4.0, 0.0]]]);
        let svg = render(&d, None, &[], &Look::default());
        check_numbers(&svg);
        let height: f64 = svg.split('"').nth(5).unwrap().parse().unwrap();
        let vertical: Vec<[f64; 4]> = lines(&svg).into_iter().filter(|l| (l[0] - l[2]).abs() < 1e-9).collect();
        assert_eq!(vertical.len(), 2, "{svg}");
        for l in &vertical {
            // From the vertex down to the bottom border (rounded up to whole pixels).
            assert!((l[1].max(l[3]) - height).abs() < 1.0, "{l:?} of {height}");
        }
        let frame = Frame::new(&[Point::new(2.0, 2.0), Point::new(0.0, 0.0), Point::new(4.0, 0.0)]);
        let four_units = 4.0 * frame.to_unit * frame.px;
        assert!(((vertical[0][0] - vertical[1][0]).abs() - four_units).abs() < 0.02, "{vertical:?}");
    }

    #[test]
    fn parabolic_arcs_are_bezier_paths_from_vertex_to_vertex() {
        let d = with_segments(&[[2.0, 2.0], [6.0, 3.0]], &[[[0.0, 0.0], [4.0, 0.0]], [[1.0, 4.0], [3.0, 5.5]]]);
        let svg = render(&d, None, &[], &Look::default());
        check_numbers(&svg);
        let arcs: Vec<[Point; 3]> = d.edges().filter_map(|e| d.edge_bezier(e.id)).collect();
        assert!(arcs.len() >= 2);
        let drawn = curves(&svg);
        assert_eq!(drawn.len(), arcs.len(), "{svg}");
        let points: Vec<Point> = d.site_ids().filter_map(|s| d.site(s)?.as_point()).collect();
        let frame = Frame::new(&points);
        for (c, arc) in drawn.iter().zip(arcs) {
            for (k, p) in arc.into_iter().enumerate() {
                let (x, y) = frame.pixel(frame.unit(p)).unwrap();
                assert!((c[2 * k] - x).abs() <= 0.005 && (c[2 * k + 1] - y).abs() <= 0.005, "{c:?} vs {p:?}");
            }
        }
        // Each segment site is one thick line; every point site a dot.
        assert_eq!(numbers_of(group(&svg, "segments"), "<line").len(), 2);
        assert_eq!(group(&svg, "sites").matches("<circle").count(), d.point_site_count());
        assert_eq!(lines(&svg).len() + drawn.len(), d.edge_count(), "every edge of this small input is visible");
    }

    #[test]
    fn rays_reach_the_border_and_segments_stay_inside() {
        let svg = render(&diagram(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 1.0]]), None, &[], &Look::default());
        check_numbers(&svg);
        let (w, h) = (SIZE_PX, SIZE_PX);
        let on_border = |x: f64, y: f64| x.abs() < 0.01 || y.abs() < 0.01 || (x - w).abs() < 0.01 || (y - h).abs() < 0.01;
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
            let svg = render(&d, None, &[], &Look::default());
            assert!(svg.starts_with("<svg"), "{svg}");
            check_numbers(&svg);
            assert_eq!(svg.matches("<circle").count(), d.site_count() + d.vertex_count(), "{points:?}: {svg}");
            // Every edge of these small inputs is visible.
            assert_eq!(lines(&svg).len(), d.edge_count(), "{points:?}: {svg}");
        }
    }

    #[test]
    fn a_domain_adds_its_shade_axis_and_circle() {
        let rings = vec![vec![[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]], vec![[1.0, 0.5], [1.5, 0.5], [1.5, 1.0]]];
        let mut b = Builder::new();
        b.add_polygon(&rings).unwrap();
        let d = b.build().unwrap();
        let axis = d.medial_axis();
        let svg = render(
            &d,
            Some(&Domain { rings: &steps(&rings), axis: &axis, tolerance: 1e-3, lines: &[], points: &[] }),
            &[],
            &Look::default(),
        );
        check_numbers(&svg);
        let path = svg.lines().find(|l| l.starts_with(r#"<path id="domain""#)).expect(&svg);
        assert!(path.contains(r#"fill-rule="evenodd""#) && path.matches('M').count() == 2 && path.matches('Z').count() == 2);
        let drawn = group(&svg, "medial-axis").matches(',').count();
        assert!(drawn > axis.chains.len(), "{drawn} stretches");
        // the largest disk touches the hole or the outer ring: radius below 1
        let circle = svg.lines().find(|l| l.starts_with(r#"<circle id="inscribed-circle""#)).expect(&svg);
        let (_, r) = d.max_inscribed_circle().unwrap();
        let frame = Frame::new(&d.site_ids().filter_map(|s| d.site(s)?.as_point()).collect::<Vec<_>>());
        assert!(circle.contains(&format!(r#"r="{:.2}""#, r * frame.to_unit * frame.px)), "{circle}");
        assert_eq!((ramp(0.0), ramp(1.0), ramp(f64::NAN)), ("#009e9e".into(), "#c8007d".into(), "#c8007d".into()));
    }

    /// The commands of each path of the offsets group: `(letter, numbers)`.
    fn offset_paths(svg: &str) -> Vec<Vec<(char, Vec<f64>)>> {
        group(svg, "offsets")
            .lines()
            .filter_map(|l| l.split(r#" d=""#).nth(1))
            .map(|d| {
                let mut commands: Vec<(char, Vec<f64>)> = Vec::new();
                for word in d.trim_end_matches(r#""/>"#).split(' ') {
                    match word.parse::<f64>() {
                        Ok(v) => commands.last_mut().expect(d).1.push(v),
                        Err(_) => commands.push((word.chars().next().unwrap(), Vec::new())),
                    }
                }
                commands
            })
            .collect()
    }

    /// The centre and the turn (signed, y down) of an SVG arc of radius `r`
    /// from `p` to `q` with these flags (the SVG spec's conversion, F.6.5,
    /// for a circle).
    fn svg_arc(p: [f64; 2], q: [f64; 2], r: f64, large: bool, sweep: bool) -> ([f64; 2], f64) {
        let h = [(p[0] - q[0]) / 2.0, (p[1] - q[1]) / 2.0];
        let h2 = h[0] * h[0] + h[1] * h[1];
        let k = ((r * r - h2).max(0.0) / h2).sqrt() * if large != sweep { 1.0 } else { -1.0 };
        let c = [k * h[1] + (p[0] + q[0]) / 2.0, -k * h[0] + (p[1] + q[1]) / 2.0];
        let angle = |v: [f64; 2]| (v[1] - c[1]).atan2(v[0] - c[0]);
        let turn = (angle(q) - angle(p)).rem_euclid(std::f64::consts::TAU);
        (c, if sweep { turn } else { turn - std::f64::consts::TAU })
    }

    /// Checks every arc of the drawn loops against the loops: same centre,
    /// same turn (counter-clockwise in the input is negative on screen).
    fn check_arcs(frame: &Frame, svg: &str, loops: &[&OffsetLoop]) -> usize {
        let paths = offset_paths(svg);
        assert_eq!(paths.len(), loops.len(), "{svg}");
        let mut arcs = 0;
        for (commands, l) in paths.iter().zip(loops) {
            assert_eq!((commands[0].0, commands.last().unwrap().0), ('M', 'Z'), "{commands:?}");
            let pixel = |p: Point| frame.pixel(frame.unit(p)).unwrap();
            let mut at = [commands[0].1[0], commands[0].1[1]];
            let mut drawn = commands[1..commands.len() - 1].iter();
            for piece in &l.pieces {
                match *piece {
                    OffsetPiece::Arc { centre, radius, counter_clockwise, .. } => {
                        let turn = piece.sweep().expect("an arc");
                        let (mut total, c) = (0.0, pixel(centre));
                        for _ in 0..if turn == std::f64::consts::TAU { 2 } else { 1 } {
                            let (letter, v) = drawn.next().unwrap();
                            assert_eq!((*letter, v.len()), ('A', 7), "{commands:?}");
                            assert!((v[0] - radius * frame.to_unit * frame.px).abs() < 0.006 && v[0] == v[1] && v[2] == 0.0);
                            let (centre_px, t) = svg_arc(at, [v[5], v[6]], v[0], v[3] == 1.0, v[4] == 1.0);
                            assert!(
                                (centre_px[0] - c.0).abs() < 0.05 && (centre_px[1] - c.1).abs() < 0.05,
                                "{centre_px:?} vs {c:?}"
                            );
                            total += t;
                            at = [v[5], v[6]];
                        }
                        let expected = if counter_clockwise { -turn } else { turn };
                        assert!((total - expected).abs() < 1e-2, "turns {total} on screen, {expected} expected");
                        arcs += 1;
                    }
                    _ => {
                        let (letter, v) = drawn.next().unwrap();
                        assert_eq!(*letter, 'L');
                        at = [v[0], v[1]];
                    }
                }
                let end = pixel(piece.to());
                assert!((at[0] - end.0).abs() <= 0.005 && (at[1] - end.1).abs() <= 0.005, "{at:?} vs {end:?}");
            }
            assert!(drawn.next().is_none(), "{commands:?}");
        }
        arcs
    }

    #[test]
    fn arc_sites_are_svg_arcs_with_their_flags() {
        let frame = Frame::new(&[Point::new(-2.0, -2.0), Point::new(2.0, 2.0)]);
        let pixel = |p: Point| frame.pixel(frame.unit(p)).unwrap();
        let arcs = [
            // a quarter counter-clockwise, three quarters clockwise, a half
            CircularArc::from_bulge([1.0, 0.0], [0.0, 1.0], (PI / 8.0).tan()).unwrap(),
            CircularArc::through([0.0, 1.0], [1.0, 0.0], [-1.0, 0.0]).unwrap(),
            CircularArc::from_bulge([-1.0, 0.0], [1.0, 0.0], 1.0).unwrap(),
        ];
        let mut out = String::new();
        write_sites(&mut out, &frame, &[], &[], &arcs);
        let drawn = group(&out, "arcs");
        assert!(drawn.contains(r#"fill="none""#), "{drawn}");
        let paths: Vec<Vec<f64>> = drawn
            .split("<path d=\"")
            .skip(1)
            .map(|d| d.split('"').next().unwrap().split(' ').filter_map(|t| t.parse().ok()).collect())
            .collect();
        assert_eq!(paths.len(), 3);
        for (v, arc) in paths.iter().zip(&arcs) {
            assert_eq!(v.len(), 9, "{v:?}");
            let start = pixel(arc.start());
            assert!((v[0] - start.0).abs() < 0.006 && (v[1] - start.1).abs() < 0.006);
            assert!((v[2] - arc.radius() * frame.to_unit * frame.px).abs() < 0.006 && v[2] == v[3]);
            let (centre, turn) = svg_arc([v[0], v[1]], [v[7], v[8]], v[2], v[5] == 1.0, v[6] == 1.0);
            let c = pixel(arc.centre());
            assert!((centre[0] - c.0).abs() < 0.05 && (centre[1] - c.1).abs() < 0.05, "{centre:?} vs {c:?}");
            // counter-clockwise in the input turns negative on screen
            assert!((turn + arc.sweep()).abs() < 1e-2, "{turn} on screen for a sweep of {}", arc.sweep());
        }
    }

    #[test]
    fn conic_rays_are_traced_along_their_curve() {
        // a circle and a segment; a slot, a point off its round end (the
        // arc's endpoint tangent to the curve at the vertex) and an arc
        let circle = |b: &mut Builder| {
            b.add_arc(CircularArc::from_bulge([1.0, 0.0], [3.0, 0.0], 1.0).unwrap()).unwrap();
            b.add_arc(CircularArc::from_bulge([3.0, 0.0], [1.0, 0.0], 1.0).unwrap()).unwrap();
            b.add_segment([[4.0, -1.0], [5.0, 1.0]]).unwrap();
        };
        let slot = |b: &mut Builder| {
            b.add_segment([[0.0, 0.0], [4.0, 0.0]]).unwrap();
            b.add_arc(CircularArc::through([4.0, 0.0], [5.0, 1.0], [4.0, 2.0]).unwrap()).unwrap();
            b.add_segment([[4.0, 2.0], [0.0, 2.0]]).unwrap();
            b.add_arc(CircularArc::through([0.0, 2.0], [-1.0, 1.0], [0.0, 0.0]).unwrap()).unwrap();
            b.add_point([6.0, 3.0]).unwrap();
            b.add_arc(CircularArc::through([-2.0, 3.0], [-1.0, 4.0], [0.0, 4.5]).unwrap()).unwrap();
        };
        let adders: [&dyn Fn(&mut Builder); 2] = [&circle, &slot];
        for (k, add) in adders.into_iter().enumerate() {
            let mut b = Builder::new();
            add(&mut b);
            let d = b.build().unwrap();
            let framed: Vec<Point> = [(-2.0, -2.0), (6.0, 4.5)].map(Point::from).to_vec();
            let frame = Frame::new(&framed);
            let sites: Vec<Site> = d.site_ids().map(|s| d.site(s).unwrap()).collect();
            let mut traced = 0;
            for e in d.edges().filter(|e| e.is_infinite() && matches!(d.edge_shape(e.id), Some(EdgeShape::Conic { .. }))) {
                let (v, direction) = match e.ends {
                    [EdgeEnd::Vertex(v), EdgeEnd::Infinite { direction }]
                    | [EdgeEnd::Infinite { direction }, EdgeEnd::Vertex(v)] => (v, direction),
                    _ => continue,
                };
                let line = trace_conic_ray(&d, &frame, &e, v, direction).expect("traced");
                assert!(line.len() > 10, "{line:?}");
                let [first, second] = e.sites.map(|s| d.site(s).unwrap());
                for u in &line {
                    // on the curve, and no site nearer: on the edge
                    let p = Point::new(u.x / frame.to_unit, u.y / frame.to_unit);
                    let r = first.distance(p);
                    assert!((r - second.distance(p)).abs() < 1e-9, "input {k}: {p:?} off the curve of edge {}", e.id);
                    assert!(sites.iter().all(|s| s.distance(p) >= r - 1e-9), "input {k}: {p:?} off edge {}", e.id);
                }
                // it ends outside the picture
                let last = line.last().unwrap();
                assert!(!frame.contains(*last), "{last:?}");
                traced += 1;
            }
            assert!(traced > 0, "input {k}");
        }
    }

    #[test]
    fn offsets_are_lines_and_arcs_with_their_flags() {
        // A square with a square hole and a point obstacle: grown, the outer
        // ring's corners are quarter arcs; shrunk, the hole's corners are
        // quarter arcs turning the other way; and the point's circle.
        let rings =
            vec![vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]], vec![[2.0, 2.0], [5.0, 2.0], [5.0, 5.0], [2.0, 5.0]]];
        let mut b = Builder::new();
        b.add_polygon(&rings).unwrap();
        b.add_point([7.5, 7.5]).unwrap();
        let d = b.build().unwrap();
        let offsets = d.offsets(&[1.0, -0.5, -1.0]).unwrap();
        let axis = d.medial_axis();
        let svg = render(
            &d,
            Some(&Domain { rings: &steps(&rings), axis: &axis, tolerance: 1e-3, lines: &[], points: &[] }),
            &offsets,
            &Look::default(),
        );
        check_numbers(&svg);
        let frame = Frame::new(&grown_box(&d.site_ids().filter_map(|s| d.site(s)?.as_point()).collect::<Vec<_>>(), &offsets));
        let loops: Vec<&OffsetLoop> = offsets.iter().flat_map(|o| &o.loops).collect();
        assert_eq!(
            check_arcs(&frame, &svg, &loops),
            loops.iter().flat_map(|l| &l.pieces).filter(|p| matches!(p, OffsetPiece::Arc { .. })).count()
        );
        // both directions of arcs, and a whole circle (two half arcs), occur
        let flags: Vec<&str> = svg.split(" A ").skip(1).map(|a| a.split(' ').nth(4).unwrap()).collect();
        assert!(flags.contains(&"0") && flags.contains(&"1"), "{flags:?}");
        // grown: the outer ring and the smaller hole (the point is inside)
        assert_eq!(group(&svg, "offsets").matches(r#"data-distance="1""#).count(), 2, "{svg}");
        // the grown loop is inside the picture: the box grows by 1
        let (w, h) = (frame.width(), frame.height());
        for commands in offset_paths(&svg) {
            for (_, v) in commands {
                for xy in v.chunks(2).filter(|c| c.len() == 2) {
                    assert!((0.0..=w).contains(&xy[0]) && (0.0..=h).contains(&xy[1]), "{xy:?} outside {w} × {h}");
                }
            }
        }
        assert!(!render(&d, None, &[], &Look::default()).contains("offsets"));
    }

    #[test]
    fn a_whole_circle_is_two_half_arcs() {
        let d = diagram(&[[0.0, 0.0], [10.0, 0.0]]);
        let offsets = d.offsets(&[1.0]).unwrap();
        assert_eq!(offsets[0].loops.len(), 2);
        let svg = render(&d, None, &offsets, &Look::default());
        let frame = Frame::new(&grown_box(&[Point::new(0.0, 0.0), Point::new(10.0, 0.0)], &offsets));
        let loops: Vec<&OffsetLoop> = offsets[0].loops.iter().collect();
        assert_eq!(check_arcs(&frame, &svg, &loops), 2);
        for path in offset_paths(&svg) {
            assert_eq!(path.iter().map(|c| c.0).collect::<String>(), "MAAZ", "{svg}");
        }
    }

    #[test]
    fn collinear_bisectors_cross_the_whole_picture() {
        // Sites on the x axis: bisectors are vertical lines, top to bottom.
        let svg = render(&diagram(&[[0.0, 0.0], [2.0, 0.0], [6.0, 0.0]]), None, &[], &Look::default());
        let ls = lines(&svg);
        assert_eq!(ls.len(), 2);
        let height: f64 = svg.split('"').nth(5).unwrap().parse().unwrap();
        for l in ls {
            assert!((l[0] - l[2]).abs() < 1e-6, "not vertical: {l:?}");
            // The picture's size is rounded up to whole pixels.
            assert!((l[1] - l[3]).abs() >= height - 1.0, "not full height: {l:?} of {height}");
        }
    }

    #[test]
    fn the_program_s_picture_explains_itself() {
        let rings = vec![vec![[0.0, 0.0], [10.0, 0.0], [10.0, 4.0], [0.0, 4.0]]];
        let mut b = Builder::new();
        b.add_polygon(&rings).unwrap();
        let d = b.build().unwrap();
        let axis = d.medial_axis();
        let offsets = d.offsets(&[-0.5, -1.0, 1.0]).unwrap();
        let domain = Domain { rings: &steps(&rings), axis: &axis, tolerance: 1e-3, lines: &[], points: &[[5.0, 2.0]] };
        let look = Look { title: Some("box <1>".into()), units: Some("m".into()), diagram: false };
        let svg = render(&d, Some(&domain), &offsets, &look);
        check_numbers(&svg);
        assert!(svg.contains("<title>box &lt;1&gt;</title>") && svg.contains(r#"id="legend""#), "{svg}");
        // The scale bar: a round length, at most a quarter of the picture.
        assert!(svg.contains(">2 m</text>"), "{svg}");
        for label in ["domain", "medial axis, clearance 0 to 2", "largest inscribed circle, r = 2", "offset -0.5", "offset 1"] {
            assert!(svg.contains(&format!(">{label}</text>")), "no {label}: {svg}");
        }
        // The diagram is off by default with a domain, on when asked.
        assert!(!svg.contains(r#"id="edges""#) && !svg.contains("Voronoi edges") && svg.contains(r#"id="points""#), "{svg}");
        let with = render(&d, Some(&domain), &offsets, &Look { diagram: true, ..look.clone() });
        assert!(with.contains(r#"id="edges""#) && with.contains(">Voronoi edges</text>"));
        // Each distance its own colour.
        let colours: std::collections::BTreeSet<&str> =
            group(&svg, "offsets").lines().filter_map(|l| l.split(r#"stroke=""#).nth(1)?.split('"').next()).collect();
        assert_eq!(colours.len(), 3, "{svg}");
        // The band lies below the picture: the document is taller.
        let bare = render(&d, Some(&domain), &offsets, &Look::default());
        let height = |svg: &str| svg.split('"').nth(5).unwrap().parse::<f64>().unwrap();
        assert!(height(&svg) > height(&bare) + 40.0);
    }

    #[test]
    fn labels_and_scale_lengths_are_round() {
        assert_eq!(
            (short(68.8234), short(0.5), short(-15.0), short(1234567.0)),
            ("68.82".into(), "0.5".into(), "-15".into(), "1.235e6".into())
        );
        let frame = Frame::new(&[Point::new(0.0, 0.0), Point::new(1000.0, 0.0)]);
        let (px, length) = scale_bar(&frame, 200.0).unwrap();
        assert_eq!(length, 200.0);
        assert!(px <= 200.0 && px > 100.0, "{px}");
    }
}

#[cfg(test)]
mod normalisation_tests {
    use super::to_unit;

    #[test]
    fn to_unit_brings_the_largest_magnitude_into_one_to_two() {
        for v in [1.0, 1.5, 3.0, 1e300, 1e-300, f64::MIN_POSITIVE, 0.75] {
            let u = v * to_unit(v);
            assert!((1.0..2.0).contains(&u), "{v}: {u}");
            assert_eq!(to_unit(v).to_bits() & ((1 << 52) - 1), 0, "{v}: a power of two");
        }
        // The top exponent is clamped too (2^-1023 is subnormal): below 4.
        assert_eq!(f64::MAX * to_unit(f64::MAX), 4.0 - 2f64.powi(-51));
        // Subnormals: clamped, a little below 1 but not zero.
        let tiny = f64::MIN_POSITIVE / 8.0;
        assert_eq!(tiny * to_unit(tiny), 0.125);
        assert_eq!(to_unit(0.0), 1.0);
        assert_eq!(to_unit(f64::INFINITY), 1.0);
    }
}
