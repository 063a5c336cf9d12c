//! The offsets' peers, compiled in by build.rs when their libraries are
//! there: GEOS's buffer (`cpp/geos_buffer.cpp`, cfg `has_geos`) and
//! Clipper's offset (`cpp/clipper_offset.cpp`, cfg `has_clipper`), each
//! behind a handle made outside the timed region. Both are asked for the
//! same chord tolerance as ours: GEOS through its quadrant segments
//! (`quadsegs_within`), Clipper through its arc tolerance.

use std::f64::consts::PI;

/// GEOS's quadrant segments for tolerance `tolerance` at `d` (the fewest
/// whose chords stay within it), and the tolerance they give.
pub fn quadsegs_within(d: f64, tolerance: f64) -> (i32, f64) {
    let r = d.abs();
    let q = (PI / (4.0 * (1.0 - (tolerance / r).min(1.0)).acos())).ceil().max(1.0);
    (q as i32, r * (1.0 - (PI / (4.0 * q)).cos()))
}

#[cfg(has_geos)]
pub mod geos {
    use super::quadsegs_within;
    use std::ffi::c_void;

    extern "C" {
        fn geos_bench_new(xy: *const f64, lengths: *const usize, rings: *const usize, n_polygons: usize) -> *mut c_void;
        fn geos_bench_buffer(input: *mut c_void, distance: f64, quadsegs: i32, vertices: *mut usize, rings: *mut usize) -> i32;
        fn geos_bench_free(input: *mut c_void);
    }

    /// The input as one GEOS MultiPolygon.
    pub struct Input(*mut c_void);

    impl Input {
        /// Polygons, each its outer ring and then its holes.
        pub fn new<P: AsRef<[Vec<[f64; 2]>]>>(input: &[P]) -> Input {
            let xy: Vec<f64> = input.iter().flat_map(|p| p.as_ref().iter().flatten().flatten().copied()).collect();
            let lengths: Vec<usize> = input.iter().flat_map(|p| p.as_ref().iter().map(Vec::len)).collect();
            let rings: Vec<usize> = input.iter().map(|p| p.as_ref().len()).collect();
            // SAFETY: the arrays hold what the lengths say; GEOS copies them.
            let raw = unsafe { geos_bench_new(xy.as_ptr(), lengths.as_ptr(), rings.as_ptr(), input.len()) };
            assert!(!raw.is_null(), "GEOS input");
            Input(raw)
        }

        /// Buffer at `d` within `tolerance`: (vertices, rings).
        pub fn buffer_within(&self, d: f64, tolerance: f64) -> (usize, usize) {
            let (mut vertices, mut rings) = (0, 0);
            // SAFETY: a live handle and two out-parameters.
            let status = unsafe { geos_bench_buffer(self.0, d, quadsegs_within(d, tolerance).0, &mut vertices, &mut rings) };
            assert_eq!(status, 0, "GEOS buffer failed");
            (vertices, rings)
        }
    }

    impl Drop for Input {
        fn drop(&mut self) {
            // SAFETY: made by geos_bench_new, freed once.
            unsafe { geos_bench_free(self.0) }
        }
    }
}

#[cfg(has_clipper)]
pub mod clipper {
    use std::ffi::c_void;

    extern "C" {
        fn clipper_bench_new(xy: *const i64, lengths: *const usize, n_rings: usize) -> *mut c_void;
        fn clipper_bench_offset(
            paths: *const c_void,
            delta: f64,
            arc_tolerance: f64,
            vertices: *mut usize,
            rings: *mut usize,
        ) -> i32;
        fn clipper_bench_free(paths: *mut c_void);
    }

    /// The input's rings on Clipper's integer grid (2^28 over the extent).
    pub struct Input {
        paths: *mut c_void,
        scale: f64,
    }

    impl Input {
        /// Polygons, each its outer ring and then its holes, the holes
        /// oriented against the outer rings.
        pub fn new<P: AsRef<[Vec<[f64; 2]>]>>(input: &[P]) -> Input {
            let points = || input.iter().flat_map(|p| p.as_ref().iter().flatten());
            let (lo, hi) = points().fold(([f64::MAX; 2], [f64::MIN; 2]), |(lo, hi), p| {
                ([lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])])
            });
            let scale = 2f64.powi(28) / (hi[0] - lo[0]).max(hi[1] - lo[1]);
            let xy: Vec<i64> = points()
                .flat_map(|p| [((p[0] - lo[0]) * scale).round() as i64, ((p[1] - lo[1]) * scale).round() as i64])
                .collect();
            let lengths: Vec<usize> = input.iter().flat_map(|p| p.as_ref().iter().map(Vec::len)).collect();
            // SAFETY: the arrays hold what the lengths say; Clipper copies them.
            let paths = unsafe { clipper_bench_new(xy.as_ptr(), lengths.as_ptr(), lengths.len()) };
            Input { paths, scale }
        }

        /// Offset at `d` with arcs within `tolerance` (both in input
        /// units): (vertices, rings).
        pub fn offset(&self, d: f64, tolerance: f64) -> (usize, usize) {
            let (mut vertices, mut rings) = (0, 0);
            // SAFETY: a live handle and two out-parameters.
            let status =
                unsafe { clipper_bench_offset(self.paths, d * self.scale, tolerance * self.scale, &mut vertices, &mut rings) };
            assert_eq!(status, 0, "Clipper offset failed");
            (vertices, rings)
        }
    }

    impl Drop for Input {
        fn drop(&mut self) {
            // SAFETY: made by clipper_bench_new, freed once.
            unsafe { clipper_bench_free(self.paths) }
        }
    }
}
