//! The builds being compared, each timed from a borrowed slice of the input
//! in the form its library takes to the finished diagram (or triangulation).
//! So every timed region includes the library copying the input in, and none
//! includes generating it or freeing the result.
//!
//! Points: segvoronoi, boost-cpp, boostvoronoi, spade. Segments:
//! segvoronoi, cgal, boost-cpp and boostvoronoi (spade triangulates points
//! only; cgal is run on segments only).

use std::hint::black_box;
use std::time::Instant;

use spade::{DelaunayTriangulation, Point2, Triangulation};

use crate::input::{float_points, grid_points, SEED};
use crate::segments::Seg;

/// A library under test.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Contender {
    Segvoronoi,
    Boostvoronoi,
    /// Boost.Polygon's C++ original, compiled in by build.rs when the Boost
    /// headers are there.
    BoostCpp,
    Spade,
    /// CGAL's segment Delaunay graph (`cpp/cgal_sdg.cpp`), compiled in by
    /// build.rs when the CGAL headers are there.
    Cgal,
}

impl Contender {
    pub const ALL: [Contender; 5] =
        [Contender::Segvoronoi, Contender::Cgal, Contender::BoostCpp, Contender::Boostvoronoi, Contender::Spade];

    /// The contenders this binary can run (boost-cpp and cgal only when
    /// compiled in).
    pub fn available() -> Vec<Contender> {
        Contender::ALL
            .into_iter()
            .filter(|c| match c {
                Contender::BoostCpp => cfg!(has_boost_cpp),
                Contender::Cgal => cfg!(has_cgal),
                _ => true,
            })
            .collect()
    }

    pub fn name(self) -> &'static str {
        match self {
            Contender::Segvoronoi => "segvoronoi",
            Contender::Boostvoronoi => "boostvoronoi",
            Contender::BoostCpp => "boost-cpp",
            Contender::Spade => "spade",
            Contender::Cgal => "cgal",
        }
    }

    pub fn parse(name: &str) -> Option<Contender> {
        Contender::ALL.into_iter().find(|c| c.name() == name)
    }

    /// Whether it takes line segments.
    pub fn takes_segments(self) -> bool {
        self != Contender::Spade
    }

    /// Whether it is benchmarked on points (CGAL's segment Delaunay graph
    /// is here for the segment workloads of issue 11 only).
    pub fn takes_points(self) -> bool {
        self != Contender::Cgal
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
    /// Voronoi edges, each counted once (not per half-edge), infinite ones
    /// included (Delaunay edges for spade).
    pub edges: usize,
    /// Sum of the finite vertices' x and of their y (compensated, so the
    /// order of the vertices does not matter): two diagrams with the same
    /// vertices give the same sums up to the rounding of the vertices
    /// themselves. NaN for spade, which has no Voronoi vertices.
    pub vertex_sum: [f64; 2],
}

/// The output sizes of one build.
pub struct Counts {
    pub sites: usize,
    pub vertices: usize,
    pub edges: usize,
    pub vertex_sum: [f64; 2],
}

/// Neumaier's compensated sum of `(x, y)` pairs.
fn coordinate_sum(points: impl Iterator<Item = [f64; 2]>) -> [f64; 2] {
    let mut sum = [0.0f64; 2];
    let mut carry = [0.0f64; 2];
    for p in points {
        for k in 0..2 {
            let t = sum[k] + p[k];
            carry[k] += if sum[k].abs() >= p[k].abs() { (sum[k] - t) + p[k] } else { (p[k] - t) + sum[k] };
            sum[k] = t;
        }
    }
    [sum[0] + carry[0], sum[1] + carry[1]]
}

/// Builds `runs` times on the `n`-point input and reports the times and the
/// output sizes of the last run.
pub fn measure(contender: Contender, n: usize, runs: usize) -> Measured {
    match contender {
        Contender::Segvoronoi => {
            let points = float_points(n, SEED);
            time_runs(runs, || segvoronoi_build(&points), segvoronoi_counts)
        }
        Contender::Boostvoronoi => {
            let points = grid_points(n, SEED);
            time_runs(runs, || boostvoronoi_build(&points), boostvoronoi_counts)
        }
        Contender::BoostCpp => {
            let points = grid_points(n, SEED);
            time_runs(runs, || boost_cpp::Diagram::build(&points), boost_cpp::Diagram::counts)
        }
        Contender::Cgal => fail("cgal is benchmarked on segments only".into()),
        Contender::Spade => {
            let points = float_points(n, SEED);
            time_runs(
                runs,
                || spade_build(&points),
                |t| Counts {
                    sites: t.num_vertices(),
                    vertices: t.num_inner_faces(),
                    edges: t.num_undirected_edges(),
                    vertex_sum: [f64::NAN; 2],
                },
            )
        }
    }
}

/// Builds `runs` times on the segments in `file` (see `segments.rs`), read
/// into the form the contender takes. A segvoronoi input error ends the
/// child with the error's text.
pub fn measure_segments(contender: Contender, file: &std::path::Path, runs: usize) -> Measured {
    let read_error = |e: std::io::Error| -> ! { fail(format!("cannot read {}: {e}", file.display())) };
    match contender {
        Contender::Segvoronoi => {
            let segments = crate::segments::read_file(file, crate::segments::to_float).unwrap_or_else(|e| read_error(e));
            time_runs(runs, || segvoronoi_segments(&segments), segvoronoi_counts)
        }
        Contender::Boostvoronoi => {
            let segments = crate::segments::read_file(file, |s| s).unwrap_or_else(|e| read_error(e));
            time_runs(runs, || boostvoronoi_segments(&segments), boostvoronoi_counts)
        }
        Contender::BoostCpp => {
            let segments = crate::segments::read_file(file, |s| s).unwrap_or_else(|e| read_error(e));
            time_runs(runs, || boost_cpp::Diagram::build_segments(&segments), boost_cpp::Diagram::counts)
        }
        Contender::Cgal => {
            let segments = crate::segments::read_file(file, |s| s).unwrap_or_else(|e| read_error(e));
            time_runs(runs, || cgal::Graph::build_segments(&segments), cgal::Graph::counts)
        }
        Contender::Spade => fail("spade takes no line segments".into()),
    }
}

/// The environment variable that sets `Builder::threads` of segvoronoi's
/// builds here (unset: the default, every core).
pub const THREADS_VARIABLE: &str = "SEGVORONOI_BENCH_THREADS";

fn bench_threads() -> usize {
    std::env::var(THREADS_VARIABLE).ok().and_then(|v| v.parse().ok()).unwrap_or(0)
}

/// Ends a child with a message for the parent's report.
pub fn fail(message: String) -> ! {
    eprintln!("{message}");
    std::process::exit(1)
}

fn segvoronoi_counts(d: &segvoronoi::Diagram) -> Counts {
    Counts {
        sites: d.site_count(),
        vertices: d.vertex_count(),
        edges: d.edge_count(),
        vertex_sum: coordinate_sum(d.vertices().map(|v| [v.position.x, v.position.y])),
    }
}

fn boostvoronoi_counts(d: &boostvoronoi::prelude::Diagram) -> Counts {
    Counts {
        sites: d.cells().len(),
        vertices: d.vertices().len(),
        edges: d.edges().len() / 2,
        vertex_sum: coordinate_sum(d.vertices().iter().map(|v| [v.x(), v.y()])),
    }
}

fn segvoronoi_segments(segments: &[[[f64; 2]; 2]]) -> segvoronoi::Diagram {
    let mut builder = segvoronoi::Builder::new();
    builder.threads(bench_threads());
    builder.add_segments(segments.iter().copied()).expect("finite input");
    builder.build().unwrap_or_else(|e| {
        fail(format!(
            "segvoronoi build failed on {} segments: {:?}: {} (input indices {:?})",
            segments.len(),
            e.kind(),
            e.message(),
            e.indices()
        ))
    })
}

/// boostvoronoi takes `Line<i32>`, made from each `[x1, y1, x2, y2]` as it
/// reads them.
fn boostvoronoi_segments(segments: &[Seg]) -> boostvoronoi::prelude::Diagram {
    boostvoronoi::prelude::Builder::<i32>::default()
        .with_segments(segments.iter())
        .expect("segments")
        .build()
        .unwrap_or_else(|e| fail(format!("boostvoronoi build failed on {} segments: {e:?}", segments.len())))
}

fn segvoronoi_build(points: &[[f64; 2]]) -> segvoronoi::Diagram {
    let mut builder = segvoronoi::Builder::new();
    builder.threads(bench_threads());
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
        fn boost_polygon_voronoi_build_segments(xyxy: *const i32, n: usize) -> *mut c_void;
        fn boost_polygon_voronoi_cells(diagram: *const c_void) -> usize;
        fn boost_polygon_voronoi_vertices(diagram: *const c_void) -> usize;
        fn boost_polygon_voronoi_half_edges(diagram: *const c_void) -> usize;
        fn boost_polygon_voronoi_vertex(diagram: *const c_void, i: usize, xy: *mut f64);
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

        pub fn build_segments(segments: &[[i32; 4]]) -> Diagram {
            // SAFETY: `segments` is `4 * len` contiguous i32, read during the call only.
            let raw = unsafe { boost_polygon_voronoi_build_segments(segments.as_ptr().cast(), segments.len()) };
            if raw.is_null() {
                super::fail(format!("Boost.Polygon build failed (exception) on {} segments", segments.len()));
            }
            Diagram(raw)
        }

        /// Cells, vertices, edges (half-edges / 2), vertex sums.
        pub fn counts(&self) -> super::Counts {
            // SAFETY: a live diagram from `build`; vertex indices below its count.
            unsafe {
                let vertices = boost_polygon_voronoi_vertices(self.0);
                let vertex = |i: usize| {
                    let mut xy = [0.0f64; 2];
                    boost_polygon_voronoi_vertex(self.0, i, xy.as_mut_ptr());
                    xy
                };
                super::Counts {
                    sites: boost_polygon_voronoi_cells(self.0),
                    vertices,
                    edges: boost_polygon_voronoi_half_edges(self.0) / 2,
                    vertex_sum: super::coordinate_sum((0..vertices).map(vertex)),
                }
            }
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
        pub fn build_segments(_: &[[i32; 4]]) -> Diagram {
            panic!("boost-cpp was not compiled in (Boost headers missing at build time)")
        }
        pub fn counts(&self) -> super::Counts {
            super::Counts { sites: 0, vertices: 0, edges: 0, vertex_sum: [f64::NAN; 2] }
        }
    }
}

/// CGAL's segment Delaunay graph through the C interface of `cpp/cgal_sdg.cpp`.
mod cgal {
    use std::ffi::c_void;

    #[cfg(has_cgal)]
    extern "C" {
        fn cgal_sdg_build_segments(xyxy: *const i32, n: usize) -> *mut c_void;
        fn cgal_sdg_sites(sdg: *const c_void) -> usize;
        fn cgal_sdg_vertices(sdg: *const c_void) -> usize;
        fn cgal_sdg_edges(sdg: *const c_void) -> usize;
        fn cgal_sdg_vertex_positions(sdg: *const c_void, xy: *mut f64);
        fn cgal_sdg_free(sdg: *mut c_void);
    }

    /// An owned C++ `Segment_Delaunay_graph_2`.
    pub struct Graph(*mut c_void);

    #[cfg(has_cgal)]
    impl Graph {
        pub fn build_segments(segments: &[[i32; 4]]) -> Graph {
            // SAFETY: `segments` is `4 * len` contiguous i32, read during the call only.
            let raw = unsafe { cgal_sdg_build_segments(segments.as_ptr().cast(), segments.len()) };
            if raw.is_null() {
                super::fail(format!("CGAL build failed (exception) on {} segments", segments.len()));
            }
            Graph(raw)
        }

        /// Sites, finite faces (Voronoi vertices, a degree-k vertex counted
        /// k - 2 times), edges, vertex sums.
        pub fn counts(&self) -> super::Counts {
            // SAFETY: a live graph from `build_segments`; the buffer holds
            // two doubles per finite face.
            unsafe {
                let vertices = cgal_sdg_vertices(self.0);
                let mut xy = vec![0.0f64; 2 * vertices];
                cgal_sdg_vertex_positions(self.0, xy.as_mut_ptr());
                super::Counts {
                    sites: cgal_sdg_sites(self.0),
                    vertices,
                    edges: cgal_sdg_edges(self.0),
                    vertex_sum: super::coordinate_sum(xy.chunks_exact(2).map(|c| [c[0], c[1]])),
                }
            }
        }
    }

    #[cfg(has_cgal)]
    impl Drop for Graph {
        fn drop(&mut self) {
            // SAFETY: built by `build_segments`, freed once.
            unsafe { cgal_sdg_free(self.0) }
        }
    }

    #[cfg(not(has_cgal))]
    impl Graph {
        pub fn build_segments(_: &[[i32; 4]]) -> Graph {
            panic!("cgal was not compiled in (CGAL headers missing at build time)")
        }
        pub fn counts(&self) -> super::Counts {
            super::Counts { sites: 0, vertices: 0, edges: 0, vertex_sum: [f64::NAN; 2] }
        }
    }
}

fn time_runs<T>(runs: usize, mut build: impl FnMut() -> T, counts: impl Fn(&T) -> Counts) -> Measured {
    let mut seconds = Vec::with_capacity(runs);
    let mut last = Counts { sites: 0, vertices: 0, edges: 0, vertex_sum: [f64::NAN; 2] };
    for _ in 0..runs {
        let start = Instant::now();
        let output = black_box(build());
        seconds.push(start.elapsed().as_secs_f64());
        last = counts(&output);
        // Dropped here, outside the timed region, before the next run starts,
        // so at most one output is alive at a time.
        drop(output);
    }
    Measured { seconds, sites: last.sites, vertices: last.vertices, edges: last.edges, vertex_sum: last.vertex_sum }
}
