//! CGAL's segment Delaunay graph with intersections (`cpp/cgal_split.cpp`,
//! compiled in by build.rs as cfg `has_cgal_split`): CGAL splits crossing
//! segments at their exact intersection points itself.

extern "C" {
    fn cgal_split_bench(xy: *const f64, n: usize, sites: *mut usize, crossings: *mut usize, vertices: *mut usize) -> i32;
}

/// CGAL's graph of the segments: (sites, intersection points, faces).
pub fn build(input: &[[[f64; 2]; 2]]) -> (usize, usize, usize) {
    let xy: Vec<f64> = input.iter().flatten().flatten().copied().collect();
    let (mut sites, mut crossings, mut vertices) = (0, 0, 0);
    // SAFETY: xy holds 4 n doubles; three out-parameters.
    let status = unsafe { cgal_split_bench(xy.as_ptr(), input.len(), &mut sites, &mut crossings, &mut vertices) };
    assert_eq!(status, 0, "CGAL threw");
    (sites, crossings, vertices)
}
