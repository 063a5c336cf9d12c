// CGAL's segment Delaunay graph with intersections behind a small C
// interface for the split benchmark (bench/src/bin/split.rs): n segments
// given as doubles, inserted as they come into the hierarchy with
// Segment_Delaunay_graph_filtered_traits_2 (exact predicates, CGAL splits
// the crossings itself at exact intersection points). Compiled as
// c_tests/cgal.cmake compiles the CGAL cross-check: -O2, -frounding-math,
// linked to GMP and MPFR.

#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Segment_Delaunay_graph_hierarchy_2.h>
#include <CGAL/Simple_cartesian.h>

#include <cstddef>
#include <exception>

namespace {
using K = CGAL::Simple_cartesian<double>;
using Gt = CGAL::Segment_Delaunay_graph_filtered_traits_2<K, CGAL::Field_with_sqrt_tag>;
using Sdg = CGAL::Segment_Delaunay_graph_hierarchy_2<Gt>;
}  // namespace

extern "C" {

// Builds the graph of the `n` segments `xy` = {x1, y1, x2, y2, ...} and
// writes the number of its sites (points, intersection points and
// subsegments) to `*sites`, of intersection points to `*crossings`, and of
// its finite faces (Voronoi vertices) to `*vertices`. 0 on success, 1 if
// CGAL threw.
int cgal_split_bench(const double* xy, std::size_t n, std::size_t* sites, std::size_t* crossings,
                     std::size_t* vertices) {
    try {
        Sdg sdg;
        for (std::size_t i = 0; i < n; ++i) {
            const double* s = xy + 4 * i;
            sdg.insert(K::Point_2(s[0], s[1]), K::Point_2(s[2], s[3]));
        }
        *sites = sdg.number_of_vertices();
        std::size_t c = 0;
        for (auto v = sdg.finite_vertices_begin(); v != sdg.finite_vertices_end(); ++v) {
            if (v->site().is_point() && !v->site().is_input()) ++c;
        }
        *crossings = c;
        *vertices = sdg.number_of_faces();
        return 0;
    } catch (const std::exception&) {
        return 1;
    }
}

}  // extern "C"
