//! `segvoronoi._native`: the compiled half of the Python package. It takes
//! packed arrays (`input`), runs the library on many geometries at once
//! with the GIL released (`parallel`), and hands back flat arrays
//! (`outputs`) and failures as data (`failure`); everything users see —
//! shapely geometries, exception classes, argument checks — is in the
//! Python modules of `segvoronoi/`.

use numpy::{IntoPyArray, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::prelude::*;
use segvoronoi::{Diagram, Offset};

mod curved;
mod diagram;
mod failure;
mod input;
mod outputs;
mod parallel;

use curved::Pieces;
use failure::{Failure, FailureTuple};
use input::{Batch, PackedArgs};
use outputs::{AxisOptions, Lines, Polygons};

/// Builds geometry `g` of `batch` (errors carry the geometry index when the
/// call is vectorised).
fn build_one(batch: &Batch, g: usize, split_crossings: bool, threads: usize) -> Result<Diagram, Failure> {
    build_with(batch, g, split_crossings, threads, |_| Ok(()))
}

/// The threads each build of a call may run at once (`Builder::threads`):
/// one where the call builds many geometries (its workers are the
/// parallelism, and a build that started threads of its own would
/// oversubscribe the cores), else what the call allows (0: the cores).
fn threads_per_build(geometries: usize, threads: Option<usize>) -> usize {
    if geometries > 1 {
        1
    } else {
        threads.unwrap_or(0)
    }
}

/// Builds geometry `g` of `batch` with `extra` added after its free
/// segments (see `Batch::builder`); an input conflict in a curved polygon
/// names the pieces by polygon, ring and vertex.
fn build_with(
    batch: &Batch,
    g: usize,
    split_crossings: bool,
    threads: usize,
    extra: impl FnOnce(&mut segvoronoi::Builder) -> Result<(), Failure>,
) -> Result<Diagram, Failure> {
    let (mut builder, names) = batch.builder(g, split_crossings, extra).map_err(|f| f.at(g))?;
    builder.threads(threads);
    builder.build().map_err(|e| {
        let mut f = Failure::of(&e, Some(&builder), Some(g));
        f.message = names.name(&e).unwrap_or(f.message);
        f
    })
}

fn panicked(g: usize, message: String) -> Failure {
    Failure {
        geometry: Some(g),
        kind: "Internal",
        message: format!("segvoronoi panicked: {message} (please report the input)"),
        indices: Vec::new(),
        point: None,
    }
}

/// Failures of a vectorised call, for the Python side to raise or keep.
fn failures<T>(results: &[Result<T, Failure>]) -> Vec<FailureTuple> {
    results.iter().filter_map(|r| r.as_ref().err()).map(Failure::to_tuple).collect()
}

pub(crate) fn ravel2<'py, const N: usize>(py: Python<'py>, rows: Vec<[f64; N]>) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let n = rows.len();
    let flat: Vec<f64> = rows.into_iter().flatten().collect();
    Ok(flat.into_pyarray(py).reshape([n, N])?)
}

pub(crate) fn index_array(py: Python<'_>, v: Vec<usize>) -> Bound<'_, PyArray1<i64>> {
    v.into_iter().map(|x| x as i64).collect::<Vec<i64>>().into_pyarray(py)
}

type AxisBatch<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray1<i64>>, Bound<'py, PyArray1<i64>>, Vec<FailureTuple>);

/// The medial axis of each geometry: `(xyz, line_offsets, geometry_offsets,
/// failures)`; a geometry that failed has no lines.
#[pyfunction]
#[pyo3(signature = (packed, tolerance, corner_angle, prune_spurs, split_crossings, threads))]
fn medial_axis_batch<'py>(
    py: Python<'py>,
    packed: PackedArgs<'py>,
    tolerance: Option<f64>,
    corner_angle: Option<f64>,
    prune_spurs: Option<f64>,
    split_crossings: bool,
    threads: Option<usize>,
) -> PyResult<AxisBatch<'py>> {
    let batch = Batch::from_args(&packed)?;
    let options = AxisOptions { tolerance, corner_angle, prune_spurs };
    let per_build = threads_per_build(batch.len(), threads);
    let job = |g: usize| build_one(&batch, g, split_crossings, per_build).map(|d| outputs::medial_axis(&d, options));
    let results = parallel::map(py, batch.len(), threads, job, |g, m| Err(panicked(g, m)))?;
    let errors = failures(&results);
    // geometry g's lines are geom[g]..geom[g+1]; a failed geometry has none
    let (mut all, mut geom) = (Lines::default(), vec![0usize]);
    for lines in results {
        if let Ok(lines) = lines {
            let base = all.xyz.len();
            all.off.extend(lines.off.iter().map(|o| o + base));
            all.xyz.extend(lines.xyz);
        }
        geom.push(all.off.len());
    }
    all.off.push(all.xyz.len());
    Ok((ravel2(py, all.xyz)?, index_array(py, all.off), index_array(py, geom), errors))
}

/// The largest inscribed circle of each geometry: `((G, 3) array of x, y,
/// r, NaN where there is none or the geometry failed), failures)`.
#[pyfunction]
#[pyo3(signature = (packed, split_crossings, threads))]
fn inscribed_circle_batch<'py>(
    py: Python<'py>,
    packed: PackedArgs<'py>,
    split_crossings: bool,
    threads: Option<usize>,
) -> PyResult<(Bound<'py, PyArray2<f64>>, Vec<FailureTuple>)> {
    let batch = Batch::from_args(&packed)?;
    let per_build = threads_per_build(batch.len(), threads);
    let job = |g: usize| {
        build_one(&batch, g, split_crossings, per_build)
            .map(|d| d.max_inscribed_circle().map_or([f64::NAN; 3], |(c, r)| [c.x, c.y, r]))
    };
    let results = parallel::map(py, batch.len(), threads, job, |g, m| Err(panicked(g, m)))?;
    let errors = failures(&results);
    let rows: Vec<[f64; 3]> = results.into_iter().map(|r| r.unwrap_or([f64::NAN; 3])).collect();
    Ok((ravel2(py, rows)?, errors))
}

pub(crate) type PolygonBatch<'py> = (
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<i64>>,
    Bound<'py, PyArray1<i64>>,
    Bound<'py, PyArray1<i64>>,
    Vec<FailureTuple>,
);

/// The offsets of one diagram at every distance, in order: `each(Some)`
/// per offset, `each(None)` for a negative distance without a domain
/// (empty, as shapely's buffer of a line is).
fn each_offset(diagram: &Diagram, distances: &[f64], mut each: impl FnMut(Option<&Offset>)) -> Result<(), Failure> {
    let asked: Vec<f64> = distances.iter().copied().filter(|&d| diagram.has_domain() || !(d < 0.0)).collect();
    let offsets = diagram.offsets(&asked).map_err(|e| Failure::of(&e, None, None))?;
    let mut next = offsets.iter();
    for &d in distances {
        each((diagram.has_domain() || !(d < 0.0)).then(|| next.next().expect("one per distance asked")));
    }
    Ok(())
}

/// The offsets of one diagram at every distance, into `out`, one
/// multipolygon per distance (`multi` gets its polygon offsets).
pub(crate) fn offsets_into(
    diagram: &Diagram,
    distances: &[f64],
    tolerance: Option<f64>,
    out: &mut Polygons,
    multi: &mut Vec<usize>,
) -> Result<(), Failure> {
    let tolerance = tolerance.unwrap_or_else(|| outputs::default_tolerance(diagram));
    each_offset(diagram, distances, |offset| {
        multi.push(out.poly_off.len());
        if let Some(offset) = offset {
            outputs::offset_polygons(offset, tolerance, out);
        }
    })
}

/// The offsets of one diagram at every distance as exact pieces.
pub(crate) fn pieces_into(diagram: &Diagram, distances: &[f64], out: &mut Pieces) -> Result<(), Failure> {
    each_offset(diagram, distances, |offset| match offset {
        Some(offset) => out.push(offset),
        None => out.push_empty(1),
    })
}

/// `job` on the diagram of each geometry, on up to `threads` threads: the
/// results in order, None where the geometry failed, and the failures.
fn per_geometry<T: Send>(
    py: Python<'_>,
    batch: &Batch,
    split_crossings: bool,
    threads: Option<usize>,
    job: impl Fn(&Diagram) -> Result<T, Failure> + Sync,
) -> PyResult<(Vec<Option<T>>, Vec<FailureTuple>)> {
    let per_build = threads_per_build(batch.len(), threads);
    let one = |g: usize| build_one(batch, g, split_crossings, per_build).and_then(|d| job(&d).map_err(|f| f.at(g)));
    let results = parallel::map(py, batch.len(), threads, one, |g, m| Err(panicked(g, m)))?;
    let errors = failures(&results);
    Ok((results.into_iter().map(Result::ok).collect(), errors))
}

pub(crate) fn finish_polygons(
    py: Python<'_>,
    mut all: Polygons,
    mut multi: Vec<usize>,
    errors: Vec<FailureTuple>,
) -> PyResult<PolygonBatch<'_>> {
    all.ring_off.push(all.xy.len());
    all.poly_off.push(all.ring_off.len() - 1);
    multi.push(all.poly_off.len() - 1);
    Ok((ravel2(py, all.xy)?, index_array(py, all.ring_off), index_array(py, all.poly_off), index_array(py, multi), errors))
}

/// The offsets of each geometry at each distance: `(xy, ring_offsets,
/// polygon_offsets, multipolygon_offsets, failures)` with `G * D`
/// multipolygons, geometry-major; a failed geometry's are empty.
#[pyfunction]
#[pyo3(signature = (packed, distances, tolerance, split_crossings, threads))]
fn offsets_batch<'py>(
    py: Python<'py>,
    packed: PackedArgs<'py>,
    distances: PyReadonlyArray1<'py, f64>,
    tolerance: Option<f64>,
    split_crossings: bool,
    threads: Option<usize>,
) -> PyResult<PolygonBatch<'py>> {
    let batch = Batch::from_args(&packed)?;
    let distances: Vec<f64> = distances.as_array().iter().copied().collect();
    let (results, errors) = per_geometry(py, &batch, split_crossings, threads, |diagram| {
        let (mut polygons, mut multi) = (Polygons::default(), Vec::new());
        offsets_into(diagram, &distances, tolerance, &mut polygons, &mut multi)?;
        Ok((polygons, multi))
    })?;
    let (mut all, mut multi) = (Polygons::default(), Vec::new());
    for r in results {
        match r {
            Some((p, m)) => {
                let (xy0, ring0, poly0) = (all.xy.len(), all.ring_off.len(), all.poly_off.len());
                all.xy.extend(p.xy);
                all.ring_off.extend(p.ring_off.iter().map(|o| o + xy0));
                all.poly_off.extend(p.poly_off.iter().map(|o| o + ring0));
                multi.extend(m.iter().map(|o| o + poly0));
            }
            None => multi.extend(std::iter::repeat(all.poly_off.len()).take(distances.len())),
        }
    }
    finish_polygons(py, all, multi, errors)
}

pub(crate) type PieceBatch<'py> = (
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray1<i64>>,
    Bound<'py, PyArray1<bool>>,
    Bound<'py, PyArray1<i64>>,
    Bound<'py, PyArray1<i64>>,
    Vec<FailureTuple>,
);

/// Exact pieces as arrays: `(rows (P, 9), loop_offsets, holes, parents,
/// offset_offsets, failures)` (see `curved::Pieces`).
pub(crate) fn finish_pieces(py: Python<'_>, mut all: Pieces, errors: Vec<FailureTuple>) -> PyResult<PieceBatch<'_>> {
    all.loop_off.push(all.rows.len());
    all.offset_off.push(all.loop_off.len() - 1);
    Ok((
        ravel2(py, all.rows)?,
        index_array(py, all.loop_off),
        all.hole.into_pyarray(py),
        all.parent.into_pyarray(py),
        index_array(py, all.offset_off),
        errors,
    ))
}

/// The offsets of each geometry at each distance as exact pieces (lines
/// and arcs): `G * D` offsets, geometry-major; a failed geometry's are
/// empty.
#[pyfunction]
#[pyo3(signature = (packed, distances, split_crossings, threads))]
fn offset_pieces_batch<'py>(
    py: Python<'py>,
    packed: PackedArgs<'py>,
    distances: PyReadonlyArray1<'py, f64>,
    split_crossings: bool,
    threads: Option<usize>,
) -> PyResult<PieceBatch<'py>> {
    let batch = Batch::from_args(&packed)?;
    let distances: Vec<f64> = distances.as_array().iter().copied().collect();
    let (results, errors) = per_geometry(py, &batch, split_crossings, threads, |diagram| {
        let mut pieces = Pieces::default();
        pieces_into(diagram, &distances, &mut pieces)?;
        Ok(pieces)
    })?;
    let mut all = Pieces::default();
    for r in results {
        match r {
            Some(pieces) => all.extend(pieces),
            None => all.push_empty(distances.len()),
        }
    }
    finish_pieces(py, all, errors)
}

/// Builds the diagram of one packed geometry: `(Diagram, None)` or
/// `(None, failure)`.
#[pyfunction]
#[pyo3(signature = (packed, split_crossings))]
fn build<'py>(
    py: Python<'py>,
    packed: PackedArgs<'py>,
    split_crossings: bool,
) -> PyResult<(Option<diagram::PyDiagram>, Option<FailureTuple>)> {
    let batch = Batch::from_args(&packed)?;
    let mut result =
        parallel::map(py, batch.len().min(1), Some(1), |g| build_one(&batch, g, split_crossings, 0), |g, m| Err(panicked(g, m)))?;
    match result.pop() {
        Some(Ok(d)) => Ok((Some(diagram::PyDiagram::new(d)), None)),
        Some(Err(mut f)) => {
            f.geometry = None;
            Ok((None, Some(f.to_tuple())))
        }
        None => Ok((
            Some(diagram::PyDiagram::new(
                segvoronoi::Builder::new().build().map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?,
            )),
            None,
        )),
    }
}

/// Builds the diagram of one packed geometry with circular arcs `arcs`
/// (`(k, 5)` rows `[start_x, start_y, end_x, end_y, bulge]`, added after
/// its points and free segments and before its polygons, so that their
/// input indices are the rows): `(Diagram,
/// None)` or `(None, failure)`. An invalid row fails with the library's
/// error and the row as its index.
#[pyfunction]
#[pyo3(signature = (packed, arcs, split_crossings))]
fn build_with_arcs<'py>(
    py: Python<'py>,
    packed: PackedArgs<'py>,
    arcs: PyReadonlyArray2<'py, f64>,
    split_crossings: bool,
) -> PyResult<(Option<diagram::PyDiagram>, Option<FailureTuple>)> {
    let batch = Batch::from_args(&packed)?;
    let view = arcs.as_array();
    if view.ncols() != 5 && view.nrows() != 0 {
        return Err(pyo3::exceptions::PyValueError::new_err(format!("arcs: expected 5 columns, got {}", view.ncols())));
    }
    let rows: Vec<[f64; 5]> = view.rows().into_iter().map(|r| [r[0], r[1], r[2], r[3], r[4]]).collect();
    let add_arcs = |builder: &mut segvoronoi::Builder| -> Result<(), Failure> {
        for (i, r) in rows.iter().enumerate() {
            let invalid = |e: &segvoronoi::Error| {
                let mut f = Failure::of(e, None, None);
                f.indices = vec![i];
                f.message = format!("arcs row {i}: {}", f.message);
                f
            };
            let arc = segvoronoi::CircularArc::from_bulge([r[0], r[1]], [r[2], r[3]], r[4]).map_err(|e| invalid(&e))?;
            builder.add_arc(arc).map_err(|e| invalid(&e))?;
        }
        Ok(())
    };
    let job = |_: usize| -> Result<Diagram, Failure> {
        if batch.len() == 0 {
            let mut builder = segvoronoi::Builder::new();
            builder.split_crossings(split_crossings);
            add_arcs(&mut builder)?;
            return builder.build().map_err(|e| Failure::of(&e, Some(&builder), None));
        }
        build_with(&batch, 0, split_crossings, 0, add_arcs)
    };
    let mut result = parallel::map(py, 1, Some(1), job, |g, m| Err(panicked(g, m)))?;
    match result.pop().expect("one job") {
        Ok(d) => Ok((Some(diagram::PyDiagram::new(d)), None)),
        Err(mut f) => {
            f.geometry = None;
            Ok((None, Some(f.to_tuple())))
        }
    }
}

/// The diagram of each geometry: a list of `(Diagram, None)` or
/// `(None, failure)`, built on up to `threads` threads.
#[pyfunction]
#[pyo3(signature = (packed, split_crossings, threads))]
fn build_batch<'py>(
    py: Python<'py>,
    packed: PackedArgs<'py>,
    split_crossings: bool,
    threads: Option<usize>,
) -> PyResult<Vec<(Option<diagram::PyDiagram>, Option<FailureTuple>)>> {
    let batch = Batch::from_args(&packed)?;
    let per_build = threads_per_build(batch.len(), threads);
    let built = parallel::map(
        py,
        batch.len(),
        threads,
        |g| build_one(&batch, g, split_crossings, per_build),
        |g, m| Err(panicked(g, m)),
    )?;
    Ok(built
        .into_iter()
        .map(|r| match r {
            Ok(d) => (Some(diagram::PyDiagram::new(d)), None),
            Err(f) => (None, Some(f.to_tuple())),
        })
        .collect())
}

/// The module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("VERSION", segvoronoi::VERSION)?;
    m.add_function(wrap_pyfunction!(medial_axis_batch, m)?)?;
    m.add_function(wrap_pyfunction!(inscribed_circle_batch, m)?)?;
    m.add_function(wrap_pyfunction!(offsets_batch, m)?)?;
    m.add_function(wrap_pyfunction!(offset_pieces_batch, m)?)?;
    m.add_function(wrap_pyfunction!(build, m)?)?;
    m.add_function(wrap_pyfunction!(build_batch, m)?)?;
    m.add_function(wrap_pyfunction!(build_with_arcs, m)?)?;
    m.add_class::<diagram::PyDiagram>()?;
    Ok(())
}
