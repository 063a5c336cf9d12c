//! What one diagram gives, as flat arrays that `shapely.from_ragged_array`
//! turns into geometries without a Python loop: the medial axis as lines
//! of `(x, y, clearance)`, offsets as polygons of rings.

use segvoronoi::{Chain, Diagram, EdgeEnd, MedialAxisFilter, Offset};

/// Lines of 3-d points: line `l` is `xyz[off[l]..off[l+1]]`.
#[derive(Default)]
pub struct Lines {
    pub xyz: Vec<[f64; 3]>,
    pub off: Vec<usize>,
}

/// Polygons: ring `r` is `xy[ring_off[r]..ring_off[r+1]]` (closed: the
/// first point repeated last, as shapely wants), polygon `p` the rings
/// `poly_off[p]..poly_off[p+1]`, the outer one first.
#[derive(Default)]
pub struct Polygons {
    pub xy: Vec<[f64; 2]>,
    pub ring_off: Vec<usize>,
    pub poly_off: Vec<usize>,
}

/// The chord tolerance the CLI uses when none is given: 1e-4 of the
/// input's bounding-box diagonal.
pub fn default_tolerance(diagram: &Diagram) -> f64 {
    match diagram.extent() {
        e if e.is_infinite() => 1e-4 * f64::MAX,
        e if e > 0.0 => 1e-4 * e,
        _ => 1e-4,
    }
}

/// The medial-axis options of a call.
#[derive(Clone, Copy)]
pub struct AxisOptions {
    pub tolerance: Option<f64>,
    pub corner_angle: Option<f64>,
    pub prune_spurs: Option<f64>,
}

/// The medial axis sampled within the tolerance, a line per chain. Pieces
/// that reach infinity (only without a domain) are cut off, as the CLI
/// does: they can only start or end a chain, so the rest stays one line.
pub fn medial_axis(diagram: &Diagram, options: AxisOptions) -> Lines {
    let mut filter = MedialAxisFilter::new();
    if let Some(degrees) = options.corner_angle {
        filter = filter.with_corner_angle(degrees);
    }
    if let Some(k) = options.prune_spurs {
        filter = filter.with_spur_pruning(k);
    }
    let axis = diagram.medial_axis_filtered(&filter);
    let tolerance = options.tolerance.unwrap_or_else(|| default_tolerance(diagram));
    let mut out = Lines::default();
    for chain in &axis.chains {
        let finite = |end: &EdgeEnd| matches!(end, EdgeEnd::Vertex(_));
        let pieces: Vec<_> = chain.pieces.iter().filter(|p| p.ends.iter().all(finite)).copied().collect();
        if pieces.is_empty() {
            continue;
        }
        if let Some(mut points) = diagram.sample_chain(&Chain { pieces, closed: chain.closed }, tolerance) {
            // pieces of no length (where the axis meets an arc's centre,
            // or a vertex of more than three sites) repeat a point
            points.dedup();
            if points.len() >= 2 {
                out.off.push(out.xyz.len());
                out.xyz.extend(points);
            }
        }
    }
    out
}

/// An offset's region as polygons (`Offset::polygons`: each outer loop
/// and its holes), every loop cut into chords within `tolerance`.
pub fn offset_polygons(offset: &Offset, tolerance: f64, out: &mut Polygons) {
    for loops in offset.polygons() {
        out.poly_off.push(out.ring_off.len());
        for k in loops {
            let points = offset.loops[k].polyline(tolerance).unwrap_or_default();
            out.ring_off.push(out.xy.len());
            out.xy.extend(points.iter().map(|p| [p.x, p.y]));
            if let Some(first) = points.first() {
                out.xy.push([first.x, first.y]);
            }
        }
    }
}
