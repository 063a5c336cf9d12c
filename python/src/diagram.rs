//! `_native.Diagram`: a built diagram, read as numpy arrays. The Python
//! class `segvoronoi.Diagram` wraps it (shapely outputs, errors, docs).

use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use segvoronoi::{Diagram, EdgeEnd, EdgeId, Location, Point, SiteId, TopologyOptions};

use crate::curved::Pieces;
use crate::failure::FailureTuple;
use crate::outputs::{self, AxisOptions, Polygons};
use crate::{finish_pieces, finish_polygons, index_array, offsets_into, pieces_into, ravel2, PieceBatch, PolygonBatch};

/// The library's diagram; immutable and safe to read from many threads,
/// so the queries release the GIL where they loop.
#[pyclass(name = "Diagram", module = "segvoronoi._native", frozen)]
pub struct PyDiagram {
    inner: Diagram,
}

impl PyDiagram {
    pub fn new(inner: Diagram) -> PyDiagram {
        PyDiagram { inner }
    }
}

fn location_code(l: Option<Location>) -> i8 {
    match l {
        Some(Location::Inside) => 1,
        Some(Location::Outside) => -1,
        Some(Location::Boundary) => 0,
        None => -2,
    }
}

#[pymethods]
impl PyDiagram {
    fn counts(&self) -> (usize, usize, usize, usize) {
        let d = &self.inner;
        (d.site_count(), d.point_site_count(), d.vertex_count(), d.edge_count())
    }

    fn has_domain(&self) -> bool {
        self.inner.has_domain()
    }

    /// `(positions (V, 2), clearances (V,), sites (V, 3))`.
    fn vertex_arrays<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyArray2<f64>>, Bound<'py, PyArray1<f64>>, Bound<'py, PyArray2<i64>>)> {
        let d = &self.inner;
        let (mut pos, mut clearance, mut sites) = (Vec::new(), Vec::new(), Vec::new());
        for v in d.vertices() {
            pos.push([v.position.x, v.position.y]);
            clearance.push(v.clearance);
            sites.push(v.sites.map(|s| s.index() as i64));
        }
        let n = sites.len();
        let sites = sites.into_iter().flatten().collect::<Vec<i64>>().into_pyarray(py).reshape([n, 3])?;
        Ok((ravel2(py, pos)?, clearance.into_pyarray(py), sites))
    }

    /// `(sites (E, 2), vertices (E, 2) with -1 at infinity, directions
    /// (E, 2, 2) of the ends at infinity, NaN at finite ends)`.
    fn edge_arrays<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyArray2<i64>>, Bound<'py, PyArray2<i64>>, Bound<'py, PyArray3<f64>>)> {
        let d = &self.inner;
        let (mut sites, mut ends, mut dirs) = (Vec::new(), Vec::new(), Vec::new());
        for e in d.edges() {
            sites.extend(e.sites.map(|s| s.index() as i64));
            for end in e.ends {
                match end {
                    EdgeEnd::Vertex(v) => {
                        ends.push(v.index() as i64);
                        dirs.extend([f64::NAN, f64::NAN]);
                    }
                    EdgeEnd::Infinite { direction } => {
                        ends.push(-1);
                        dirs.extend([direction.x, direction.y]);
                    }
                }
            }
        }
        let n = d.edge_count();
        Ok((
            sites.into_pyarray(py).reshape([n, 2])?,
            ends.into_pyarray(py).reshape([n, 2])?,
            dirs.into_pyarray(py).reshape([n, 2, 2])?,
        ))
    }

    /// `(kinds (S,) 0 point / 1 segment / 2 arc, coordinates (S, 2, 2) (a
    /// point twice; an arc's start and end), segment input index (S,) or -1
    /// for points and arcs)`.
    fn site_arrays<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyArray1<i8>>, Bound<'py, PyArray3<f64>>, Bound<'py, PyArray1<i64>>)> {
        let d = &self.inner;
        let (mut kinds, mut coords, mut input) = (Vec::new(), Vec::new(), Vec::new());
        for s in d.site_ids() {
            match d.site(s).expect("a site id of the diagram") {
                segvoronoi::Site::Point(p) => {
                    kinds.push(0i8);
                    coords.extend([p.x, p.y, p.x, p.y]);
                }
                segvoronoi::Site::Segment { a, b } => {
                    kinds.push(1);
                    coords.extend([a.x, a.y, b.x, b.y]);
                }
                segvoronoi::Site::Arc(arc) => {
                    kinds.push(2);
                    let (a, b) = (arc.start(), arc.end());
                    coords.extend([a.x, a.y, b.x, b.y]);
                }
                // `Site` is non-exhaustive: a kind added later is named -1
                _ => {
                    kinds.push(-1);
                    coords.extend([f64::NAN; 4]);
                }
            }
            let segment = match d.site(s) {
                Some(segvoronoi::Site::Segment { .. }) => d.segment_input_index(s),
                _ => None,
            };
            input.push(segment.map_or(-1, |j| j as i64));
        }
        let n = kinds.len();
        Ok((kinds.into_pyarray(py), coords.into_pyarray(py).reshape([n, 2, 2])?, input.into_pyarray(py)))
    }

    /// `(arc input index (S,) or -1, circles (S, 4) of centre x, centre y,
    /// radius, bulge, NaN for sites that are not arcs)`.
    fn arc_arrays<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyArray1<i64>>, Bound<'py, PyArray2<f64>>)> {
        let d = &self.inner;
        let (mut input, mut circles) = (Vec::new(), Vec::new());
        for s in d.site_ids() {
            match d.site(s) {
                Some(segvoronoi::Site::Arc(arc)) => {
                    input.push(d.arc_input_index(s).map_or(-1, |j| j as i64));
                    let c = arc.centre();
                    circles.push([c.x, c.y, arc.radius(), arc.bulge()]);
                }
                _ => {
                    input.push(-1);
                    circles.push([f64::NAN; 4]);
                }
            }
        }
        Ok((input.into_pyarray(py), ravel2(py, circles)?))
    }

    /// The site of each input point (`site_of_input`), -1 for none.
    fn point_input_sites<'py>(&self, py: Python<'py>, count: usize) -> Bound<'py, PyArray1<i64>> {
        let d = &self.inner;
        (0..count).map(|i| d.site_of_input(i).map_or(-1, |s| s.index() as i64)).collect::<Vec<_>>().into_pyarray(py)
    }

    /// `(offsets (S+1,), edge ids)`: the edges around each cell,
    /// counter-clockwise.
    fn cell_arrays<'py>(&self, py: Python<'py>) -> (Bound<'py, PyArray1<i64>>, Bound<'py, PyArray1<i64>>) {
        let d = &self.inner;
        let (mut off, mut edges) = (vec![0usize], Vec::new());
        for cell in d.cells() {
            edges.extend(cell.edges().map(|e| e.index()));
            off.push(edges.len());
        }
        (index_array(py, off), index_array(py, edges))
    }

    /// Each edge as a polyline within `tolerance` (an empty array for an
    /// edge reaching infinity, which has no finite polyline).
    fn edge_polylines<'py>(&self, py: Python<'py>, tolerance: f64) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
        let d = &self.inner;
        let lines: Vec<Vec<[f64; 2]>> = py.detach(|| {
            (0..d.edge_count())
                .map(|e| {
                    d.edge_polyline(EdgeId::from_index(e), tolerance).unwrap_or_default().iter().map(|p| [p.x, p.y]).collect()
                })
                .collect()
        });
        lines.into_iter().map(|l| ravel2(py, l)).collect()
    }

    /// The nearest site of each point of `xy (n, 2)`, -1 for a non-finite
    /// point; each walk starts from the previous answer.
    fn nearest_sites<'py>(&self, py: Python<'py>, xy: PyReadonlyArray2<'py, f64>) -> Bound<'py, PyArray1<i64>> {
        let points: Vec<Point> = xy.as_array().rows().into_iter().map(|r| Point::new(r[0], r[1])).collect();
        let d = &self.inner;
        let out: Vec<i64> = py.detach(|| {
            let mut hint: Option<SiteId> = None;
            points
                .iter()
                .map(|&p| {
                    let s = d.nearest_site(p, hint);
                    hint = s.or(hint);
                    s.map_or(-1, |s| s.index() as i64)
                })
                .collect()
        });
        out.into_pyarray(py)
    }

    /// Where each point of `xy (n, 2)` is: 1 inside, 0 on the boundary,
    /// -1 outside, -2 no domain.
    fn locate<'py>(&self, py: Python<'py>, xy: PyReadonlyArray2<'py, f64>) -> Bound<'py, PyArray1<i8>> {
        let d = &self.inner;
        xy.as_array()
            .rows()
            .into_iter()
            .map(|r| location_code(d.locate_point(Point::new(r[0], r[1]))))
            .collect::<Vec<i8>>()
            .into_pyarray(py)
    }

    /// Where each vertex and each edge is (codes as `locate`).
    fn locations<'py>(&self, py: Python<'py>) -> (Bound<'py, PyArray1<i8>>, Bound<'py, PyArray1<i8>>) {
        let d = &self.inner;
        let v: Vec<i8> = d.vertices().map(|v| location_code(d.vertex_location(v.id))).collect();
        let e: Vec<i8> = d.edges().map(|e| location_code(d.edge_location(e.id))).collect();
        (v.into_pyarray(py), e.into_pyarray(py))
    }

    #[pyo3(signature = (voronoi_pairs=false, canonical_cuts=false))]
    fn topology(&self, py: Python<'_>, voronoi_pairs: bool, canonical_cuts: bool) -> String {
        let d = &self.inner;
        let options = TopologyOptions::default().with_voronoi_pairs(voronoi_pairs).with_canonical_cuts(canonical_cuts);
        py.detach(|| d.topology(options))
    }

    /// `(xyz, line_offsets)` of the medial axis.
    #[pyo3(signature = (tolerance, corner_angle, prune_spurs))]
    fn medial_axis<'py>(
        &self,
        py: Python<'py>,
        tolerance: Option<f64>,
        corner_angle: Option<f64>,
        prune_spurs: Option<f64>,
    ) -> PyResult<(Bound<'py, PyArray2<f64>>, Bound<'py, PyArray1<i64>>)> {
        let d = &self.inner;
        let mut lines = py.detach(|| outputs::medial_axis(d, AxisOptions { tolerance, corner_angle, prune_spurs }));
        lines.off.push(lines.xyz.len());
        Ok((ravel2(py, lines.xyz)?, index_array(py, lines.off)))
    }

    /// The largest disk of each component of the domain, largest first:
    /// `(k, 3)` rows of x, y, r.
    fn inscribed_circles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows: Vec<[f64; 3]> = self.inner.inscribed_circles().into_iter().map(|(c, r)| [c.x, c.y, r]).collect();
        ravel2(py, rows)
    }

    /// The offsets at `distances`, packed as `offsets_batch` packs them for
    /// one geometry; a failure is returned as the last element.
    #[pyo3(signature = (distances, tolerance))]
    fn offsets<'py>(
        &self,
        py: Python<'py>,
        distances: PyReadonlyArray1<'py, f64>,
        tolerance: Option<f64>,
    ) -> PyResult<PolygonBatch<'py>> {
        let distances: Vec<f64> = distances.as_array().iter().copied().collect();
        let d = &self.inner;
        let (mut polygons, mut multi) = (Polygons::default(), Vec::new());
        let result = py.detach(|| offsets_into(d, &distances, tolerance, &mut polygons, &mut multi));
        let errors: Vec<FailureTuple> = match result {
            Ok(()) => Vec::new(),
            Err(f) => {
                (polygons, multi) = (Polygons::default(), vec![0; distances.len()]);
                vec![f.to_tuple()]
            }
        };
        finish_polygons(py, polygons, multi, errors)
    }

    /// The offsets at `distances` as exact pieces, packed as
    /// `offset_pieces_batch` packs them for one geometry; a failure is
    /// returned as the last element.
    fn offset_pieces<'py>(&self, py: Python<'py>, distances: PyReadonlyArray1<'py, f64>) -> PyResult<PieceBatch<'py>> {
        let distances: Vec<f64> = distances.as_array().iter().copied().collect();
        let d = &self.inner;
        let mut pieces = Pieces::default();
        let errors: Vec<FailureTuple> = match py.detach(|| pieces_into(d, &distances, &mut pieces)) {
            Ok(()) => Vec::new(),
            Err(f) => {
                pieces = Pieces::default();
                pieces.push_empty(distances.len());
                vec![f.to_tuple()]
            }
        };
        finish_pieces(py, pieces, errors)
    }

    /// The build statistics, as a dict.
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let s = self.inner.stats();
        let out = PyDict::new(py);
        for (k, v) in [
            ("input_points", s.input_points),
            ("input_segments", s.input_segments),
            ("sites", s.sites),
            ("duplicate_points", s.duplicate_points),
            ("duplicate_segments", s.duplicate_segments),
            ("zero_length_segments", s.zero_length_segments),
            ("dropped_chain_points", s.dropped_chain_points),
            ("vertices", s.vertices),
            ("edges", s.edges),
            ("pieces", s.pieces),
            ("split_at_vertices", s.split_at_vertices),
            ("crossings", s.crossings),
            ("overlaps", s.overlaps),
            ("touchings", s.touchings),
            ("snap_rounds", s.snap_rounds),
            ("cancelled_ring_pieces", s.cancelled_ring_pieces),
        ] {
            out.set_item(k, v)?;
        }
        out.set_item("max_split_displacement", self.inner.max_split_displacement())?;
        Ok(out)
    }

    /// `validate()`: None, or the invariant that fails.
    fn validate(&self) -> Option<String> {
        self.inner.validate().err().map(|e| format!("{e:?}"))
    }
}
