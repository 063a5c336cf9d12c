//! The three builds being compared, each timed from a borrowed slice of the
//! input in the form its library takes to the finished diagram (or
//! triangulation). So every timed region includes the library copying the
//! input in, and none includes generating it or freeing the result.

use std::hint::black_box;
use std::time::Instant;

use spade::{DelaunayTriangulation, Point2, Triangulation};

use crate::input::{float_points, grid_points, SEED};

/// A library under test.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Contender {
    Segvoronoi,
    Boostvoronoi,
    /// Boost.Polygon's C++ original, compiled in by build.rs when the Boost
    /// headers are there.
    BoostCpp,
    Spade,
}

impl Contender {
    pub const ALL: [Contender; 4] =
        [Contender::Segvoronoi, Contender::BoostCpp, Contender::Boostvoronoi, Contender::Spade];

    /// The contenders this binary can run (boost-cpp only when compiled in).
    pub fn available() -> Vec<Contender> {
        Contender::ALL.into_iter().filter(|c| *c != Contender::BoostCpp || cfg!(has_boost_cpp)).collect()
    }

    pub fn name(self) -> &'static str {
        match self {
            Contender::Segvoronoi => "segvoronoi",
            Contender::Boostvoronoi => "boostvoronoi",
            Contender::BoostCpp => "boost-cpp",
            Contender::Spade => "spade",
        }
    }

    pub fn parse(name: &str) -> Option<Contender> {
        Contender::ALL.into_iter().find(|c| c.name() == name)
    }
}

/// What one (contender, size) child measured.
#[derive(Clone, Debug)]
pub struct Measured {
    /// Wall time of each run, in seconds.
    pub seconds: Vec<f64>,
    /// Distinct sites in the output (Delaunay vertices for spade).
    pub sites: usize,
    /// Finite Voronoi vertices (Delaunay triangles for spade: one per
    /// Voronoi vertex when no four points are cocircular).
    pub vertices: usize,
}

/// Builds `runs` times on the `n`-point input and reports the times and the
/// output sizes of the last run.
pub fn measure(contender: Contender, n: usize, runs: usize) -> Measured {
    match contender {
        Contender::Segvoronoi => {
            let points = float_points(n, SEED);
            time_runs(runs, || segvoronoi_build(&points), |d| (d.site_count(), d.vertex_count()))
        }
        Contender::Boostvoronoi => {
            let points = grid_points(n, SEED);
            time_runs(runs, || boostvoronoi_build(&points), |d| (d.cells().len(), d.vertices().len()))
        }
        Contender::BoostCpp => {
            let points = grid_points(n, SEED);
            time_runs(runs, || boost_cpp::Diagram::build(&points), |d| (d.cells(), d.vertices()))
        }
        Contender::Spade => {
            let points = float_points(n, SEED);
            time_runs(runs, || spade_build(&points), |t| (t.num_vertices(), t.num_inner_faces()))
        }
    }
}

fn segvoronoi_build(points: &[[f64; 2]]) -> segvoronoi::Diagram {
    let mut builder = segvoronoi::Builder::new();
    builder.add_points(points.iter().copied()).expect("finite input");
    builder.build().expect("segvoronoi build")
}

/// boostvoronoi merges repeated points itself (it sorts and dedups its site
/// events), so it gets the input as is, duplicates included.
fn boostvoronoi_build(points: &[[i32; 2]]) -> boostvoronoi::prelude::Diagram {
    boostvoronoi::prelude::Builder::<i32>::default()
        .with_vertices(points.iter())
        .expect("points before segments")
        .build()
        .expect("boostvoronoi build")
}

/// `bulk_load` is spade's fastest way to build from a point set; it takes an
/// owned `Vec`, so making that `Vec` is part of the timed work, as copying the
/// input in is for the other two.
fn spade_build(points: &[[f64; 2]]) -> DelaunayTriangulation<Point2<f64>> {
    let vertices = points.iter().map(|&[x, y]| Point2::new(x, y)).collect();
    DelaunayTriangulation::bulk_load(vertices).expect("spade bulk_load")
}

/// The C++ builder through the C interface of `cpp/boost_polygon.cpp`.
mod boost_cpp {
    use std::ffi::c_void;

    #[cfg(has_boost_cpp)]
    extern "C" {
        fn boost_polygon_voronoi_build(xy: *const i32, n: usize) -> *mut c_void;
        fn boost_polygon_voronoi_cells(diagram: *const c_void) -> usize;
        fn boost_polygon_voronoi_vertices(diagram: *const c_void) -> usize;
        fn boost_polygon_voronoi_free(diagram: *mut c_void);
    }

    /// An owned C++ `voronoi_diagram<double>`.
    pub struct Diagram(*mut c_void);

    #[cfg(has_boost_cpp)]
    impl Diagram {
        pub fn build(points: &[[i32; 2]]) -> Diagram {
            // SAFETY: `points` is `2 * len` contiguous i32, read during the call only.
            let raw = unsafe { boost_polygon_voronoi_build(points.as_ptr().cast(), points.len()) };
            assert!(!raw.is_null(), "Boost.Polygon build failed");
            Diagram(raw)
        }

        pub fn cells(&self) -> usize {
            // SAFETY: a live diagram from `build`.
            unsafe { boost_polygon_voronoi_cells(self.0) }
        }

        pub fn vertices(&self) -> usize {
            // SAFETY: a live diagram from `build`.
            unsafe { boost_polygon_voronoi_vertices(self.0) }
        }
    }

    #[cfg(has_boost_cpp)]
    impl Drop for Diagram {
        fn drop(&mut self) {
            // SAFETY: built by `build`, freed once.
            unsafe { boost_polygon_voronoi_free(self.0) }
        }
    }

    #[cfg(not(has_boost_cpp))]
    impl Diagram {
        pub fn build(_: &[[i32; 2]]) -> Diagram {
            panic!("boost-cpp was not compiled in (Boost headers missing at build time)")
        }
        pub fn cells(&self) -> usize {
            0
        }
        pub fn vertices(&self) -> usize {
            0
        }
    }
}

fn time_runs<T>(runs: usize, mut build: impl FnMut() -> T, counts: impl Fn(&T) -> (usize, usize)) -> Measured {
    let mut seconds = Vec::with_capacity(runs);
    let mut last = (0, 0);
    for _ in 0..runs {
        let start = Instant::now();
        let output = black_box(build());
        seconds.push(start.elapsed().as_secs_f64());
        last = counts(&output);
        // Dropped here, outside the timed region, before the next run starts,
        // so at most one output is alive at a time.
        drop(output);
    }
    Measured { seconds, sites: last.0, vertices: last.1 }
}
