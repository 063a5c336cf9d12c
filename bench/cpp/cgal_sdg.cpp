// CGAL's segment Delaunay graph behind a small C interface, so the benchmark
// can time it in the same process and the same way as the other contenders:
// build from a borrowed array of integer segments, read the counts and the
// Voronoi vertices, free outside the timed region.
//
// Traits: Segment_Delaunay_graph_filtered_traits_without_intersections_2
// over Simple_cartesian<double> with Field_with_sqrt_tag, the same as the
// project's exact cross-check (c_tests/cgal_crosscheck.cpp): interval
// arithmetic first, exact (GMP) predicates when the filter fails, so every
// decision is exact; "without intersections", because the input is
// non-crossing (and the library refuses crossing input). This is CGAL's
// usual choice for speed on non-crossing input.
//
// Insertion: `insert_segments(points, index pairs)`, which CGAL documents as
// the fast way: it spatially sorts the endpoints, inserts them with the
// previous vertex as the location hint, then inserts each segment between
// its two endpoint vertices (no point location for the segments at all).
// The plain Segment_Delaunay_graph_2, not the hierarchy: `insert_segments`
// exists only there. The segments go in a random order (fixed seed), as
// CGAL's own `insert(first, beyond, Tag_true)` shuffles its sites: in input
// order a stack of long parallel segments is quadratic (each new segment
// re-draws the whole boundary of the previous one's cell against the
// endpoints still to come: 2,048 of them took 0.7 s, 16,384 took 18 s).

#include <CGAL/Segment_Delaunay_graph_2.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace {
using K = CGAL::Simple_cartesian<double>;
using Gt = CGAL::Segment_Delaunay_graph_filtered_traits_without_intersections_2<K, CGAL::Field_with_sqrt_tag>;
using Sdg = CGAL::Segment_Delaunay_graph_2<Gt>;
}  // namespace

extern "C" {

// Builds the graph of `n` segments `xyxy = {x1, y1, x2, y2, ...}`; NULL on
// failure (out of memory or an exception from CGAL). A zero-length segment
// is inserted as its point (CGAL skips a segment whose two vertices are one).
void* cgal_sdg_build_segments(const std::int32_t* xyxy, std::size_t n) {
    try {
        std::vector<K::Point_2> points;
        points.reserve(2 * n);
        std::vector<std::pair<std::size_t, std::size_t>> indices;
        indices.reserve(n);
        for (std::size_t i = 0; i < n; ++i) {
            points.emplace_back(xyxy[4 * i], xyxy[4 * i + 1]);
            points.emplace_back(xyxy[4 * i + 2], xyxy[4 * i + 3]);
            indices.emplace_back(2 * i, 2 * i + 1);
        }
        std::mt19937_64 random(0x5EED);
        std::shuffle(indices.begin(), indices.end(), random);
        Sdg* sdg = new Sdg;
        sdg->insert_segments(points, indices.begin(), indices.end());
        return sdg;
    } catch (...) {
        return nullptr;
    }
}

// Sites (vertices of the graph: distinct points and the open segments).
std::size_t cgal_sdg_sites(const void* sdg) { return static_cast<const Sdg*>(sdg)->number_of_vertices(); }

// Finite faces: one per Voronoi vertex (a vertex of degree k > 3 shows as
// k - 2 faces with the same centre).
std::size_t cgal_sdg_vertices(const void* sdg) {
    const Sdg& g = *static_cast<const Sdg*>(sdg);
    std::size_t faces = 0;
    for (auto f = g.finite_faces_begin(); f != g.finite_faces_end(); ++f) ++faces;
    return faces;
}

// Voronoi edges: the edges of the graph but those to the infinite vertex
// (an edge between two hull sites is an infinite Voronoi edge, one to the
// infinite vertex has no Voronoi edge).
std::size_t cgal_sdg_edges(const void* sdg) {
    const Sdg& g = *static_cast<const Sdg*>(sdg);
    std::size_t edges = 0;
    for (auto e = g.all_edges_begin(); e != g.all_edges_end(); ++e) {
        auto f = e->first;
        int i = e->second;
        if (!g.is_infinite(f->vertex(g.cw(i))) && !g.is_infinite(f->vertex(g.ccw(i)))) ++edges;
    }
    return edges;
}

// The Voronoi vertices (circle centres of the finite faces) into `xy`, two
// doubles each, `cgal_sdg_vertices` of them, in CGAL's face order.
void cgal_sdg_vertex_positions(const void* sdg, double* xy) {
    const Sdg& g = *static_cast<const Sdg*>(sdg);
    std::size_t i = 0;
    for (auto f = g.finite_faces_begin(); f != g.finite_faces_end(); ++f, ++i) {
        K::Point_2 c = g.primal(f);
        xy[2 * i] = c.x();
        xy[2 * i + 1] = c.y();
    }
}

void cgal_sdg_free(void* sdg) { delete static_cast<Sdg*>(sdg); }
}
