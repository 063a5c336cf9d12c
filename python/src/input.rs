//! The input of a call: many geometries packed into flat arrays (the
//! Python side packs them, see `segvoronoi/_pack.py`), copied out of numpy
//! once so that the worker threads can read them without the GIL.
//!
//! Geometry `g` is its points `pt_xy[gpt[g]..gpt[g+1]]`, its free segments
//! `seg[gseg[g]..gseg[g+1]]`, its polygons `gpoly[g]..gpoly[g+1]` (polygon
//! `p` is the rings `poly_off[p]..poly_off[p+1]`, ring `r` the points
//! `poly_xy[ring_off[r]..ring_off[r+1]]`) and its polylines
//! `gline[g]..gline[g+1]` (line `l` the points
//! `line_xy[line_off[l]..line_off[l+1]]`), and its curved polygons
//! (`segvoronoi.CurvedPolygon`) `gcurve[g]..gcurve[g+1]` (curved polygon
//! `c` is the rings `curve_poly_off[c]..curve_poly_off[c+1]`, ring `r` the
//! rows `curve_xyb[curve_ring_off[r]..curve_ring_off[r+1]]` of x, y and
//! the bulge of the piece to the next row).

use numpy::{PyReadonlyArray1, PyReadonlyArray2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use segvoronoi::Builder;

use crate::curved::PieceNames;
use crate::failure::Failure;

/// The packed arrays, owned.
pub struct Batch {
    pt_xy: Vec<[f64; 2]>,
    gpt: Vec<usize>,
    seg: Vec<[[f64; 2]; 2]>,
    gseg: Vec<usize>,
    poly_xy: Vec<[f64; 2]>,
    ring_off: Vec<usize>,
    poly_off: Vec<usize>,
    gpoly: Vec<usize>,
    line_xy: Vec<[f64; 2]>,
    line_off: Vec<usize>,
    gline: Vec<usize>,
    curve_xyb: Vec<([f64; 2], f64)>,
    curve_ring_off: Vec<usize>,
    curve_poly_off: Vec<usize>,
    gcurve: Vec<usize>,
}

/// The arrays as Python passes them, in the order of `_pack.Packed`.
#[derive(FromPyObject)]
pub struct PackedArgs<'py> {
    pt_xy: PyReadonlyArray2<'py, f64>,
    gpt: PyReadonlyArray1<'py, i64>,
    seg: PyReadonlyArray2<'py, f64>,
    gseg: PyReadonlyArray1<'py, i64>,
    poly_xy: PyReadonlyArray2<'py, f64>,
    ring_off: PyReadonlyArray1<'py, i64>,
    poly_off: PyReadonlyArray1<'py, i64>,
    gpoly: PyReadonlyArray1<'py, i64>,
    line_xy: PyReadonlyArray2<'py, f64>,
    line_off: PyReadonlyArray1<'py, i64>,
    gline: PyReadonlyArray1<'py, i64>,
    curve_xyb: PyReadonlyArray2<'py, f64>,
    curve_ring_off: PyReadonlyArray1<'py, i64>,
    curve_poly_off: PyReadonlyArray1<'py, i64>,
    gcurve: PyReadonlyArray1<'py, i64>,
}

fn xy(a: &PyReadonlyArray2<'_, f64>, name: &str, width: usize) -> PyResult<Vec<f64>> {
    let view = a.as_array();
    if view.ncols() != width && view.nrows() != 0 {
        return Err(PyValueError::new_err(format!("{name}: expected {width} columns, got {}", view.ncols())));
    }
    // any strides: `iter` walks the logical order
    Ok(view.iter().copied().collect())
}

/// Offsets into an array of `len` items: non-negative, non-decreasing,
/// ending within it. The packer makes them so; checked because a wrong one
/// would index out of bounds in a worker thread.
fn offsets(a: &PyReadonlyArray1<'_, i64>, name: &str, len: usize) -> PyResult<Vec<usize>> {
    let v: Vec<i64> = a.as_array().iter().copied().collect();
    let ok = !v.is_empty() && v[0] >= 0 && v.windows(2).all(|w| w[0] <= w[1]) && (*v.last().unwrap() as usize) <= len;
    if !ok {
        return Err(PyValueError::new_err(format!("{name}: malformed offsets")));
    }
    Ok(v.into_iter().map(|x| x as usize).collect())
}

fn pairs(flat: Vec<f64>) -> Vec<[f64; 2]> {
    flat.chunks_exact(2).map(|c| [c[0], c[1]]).collect()
}

impl Batch {
    pub fn from_args(a: &PackedArgs<'_>) -> PyResult<Batch> {
        let pt_xy = pairs(xy(&a.pt_xy, "points", 2)?);
        let seg: Vec<[[f64; 2]; 2]> = xy(&a.seg, "segments", 4)?.chunks_exact(4).map(|c| [[c[0], c[1]], [c[2], c[3]]]).collect();
        let poly_xy = pairs(xy(&a.poly_xy, "polygon points", 2)?);
        let line_xy = pairs(xy(&a.line_xy, "line points", 2)?);
        let ring_off = offsets(&a.ring_off, "ring offsets", poly_xy.len())?;
        let poly_off = offsets(&a.poly_off, "polygon offsets", ring_off.len() - 1)?;
        let line_off = offsets(&a.line_off, "line offsets", line_xy.len())?;
        let curve_xyb: Vec<([f64; 2], f64)> =
            xy(&a.curve_xyb, "curved polygon rows", 3)?.chunks_exact(3).map(|c| ([c[0], c[1]], c[2])).collect();
        let curve_ring_off = offsets(&a.curve_ring_off, "curved ring offsets", curve_xyb.len())?;
        let curve_poly_off = offsets(&a.curve_poly_off, "curved polygon offsets", curve_ring_off.len() - 1)?;
        let batch = Batch {
            gpt: offsets(&a.gpt, "geometry point offsets", pt_xy.len())?,
            gseg: offsets(&a.gseg, "geometry segment offsets", seg.len())?,
            gpoly: offsets(&a.gpoly, "geometry polygon offsets", poly_off.len() - 1)?,
            gline: offsets(&a.gline, "geometry line offsets", line_off.len() - 1)?,
            gcurve: offsets(&a.gcurve, "geometry curved polygon offsets", curve_poly_off.len() - 1)?,
            pt_xy,
            seg,
            poly_xy,
            ring_off,
            poly_off,
            line_xy,
            line_off,
            curve_xyb,
            curve_ring_off,
            curve_poly_off,
        };
        let g = batch.len();
        if [batch.gseg.len(), batch.gpoly.len(), batch.gline.len(), batch.gcurve.len()].iter().any(|&n| n != g + 1) {
            return Err(PyValueError::new_err("geometry offsets of different lengths"));
        }
        Ok(batch)
    }

    /// Number of geometries.
    pub fn len(&self) -> usize {
        self.gpt.len() - 1
    }

    /// A builder holding geometry `g`: its points, then its free segments
    /// (so their input indices are the caller's), then `extra` (the arcs of
    /// `voronoi(arcs=...)`, so their input indices are its rows), then its
    /// polygons (one `add_polygon` each, so the library's messages name
    /// them by their index in the geometry), its curved polygons (one
    /// `add_bulged_polygon` each, numbered after the polygons), then its
    /// polylines. With it, where each piece of the curved polygons came
    /// from, to name them in the errors of the build.
    pub fn builder(
        &self,
        g: usize,
        split_crossings: bool,
        extra: impl FnOnce(&mut Builder) -> Result<(), Failure>,
    ) -> Result<(Builder, PieceNames), Failure> {
        let fail = |e: segvoronoi::Error| Failure::of(&e, None, None);
        let mut b = Builder::new();
        b.split_crossings(split_crossings);
        b.add_points(self.pt_xy[self.gpt[g]..self.gpt[g + 1]].iter().copied()).map_err(fail)?;
        b.add_segments(self.seg[self.gseg[g]..self.gseg[g + 1]].iter().copied()).map_err(fail)?;
        extra(&mut b)?;
        for p in self.gpoly[g]..self.gpoly[g + 1] {
            let rings: Vec<&[[f64; 2]]> =
                (self.poly_off[p]..self.poly_off[p + 1]).map(|r| &self.poly_xy[self.ring_off[r]..self.ring_off[r + 1]]).collect();
            b.add_polygon(&rings).map_err(fail)?;
        }
        let mut names = PieceNames::default();
        for (k, c) in (self.gcurve[g]..self.gcurve[g + 1]).enumerate() {
            let rings: Vec<&[([f64; 2], f64)]> = (self.curve_poly_off[c]..self.curve_poly_off[c + 1])
                .map(|r| &self.curve_xyb[self.curve_ring_off[r]..self.curve_ring_off[r + 1]])
                .collect();
            let made = b.add_bulged_polygon(&rings).map_err(fail)?;
            names.add(self.gpoly[g + 1] - self.gpoly[g] + k, &rings, &made);
        }
        for l in self.gline[g]..self.gline[g + 1] {
            b.add_polyline(&self.line_xy[self.line_off[l]..self.line_off[l + 1]]).map_err(fail)?;
        }
        Ok((b, names))
    }
}
