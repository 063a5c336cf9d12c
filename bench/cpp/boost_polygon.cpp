// Boost.Polygon's C++ Voronoi builder behind a small C interface, so the
// benchmark can time it in the same process and the same way as the Rust
// contenders: build from a borrowed array of integer points or segments, read
// the counts, free outside the timed region.

#include <boost/polygon/voronoi.hpp>

#include <cstddef>
#include <cstdint>
#include <new>

using Diagram = boost::polygon::voronoi_diagram<double>;

extern "C" {

// Builds the diagram of `n` points `xy = {x0, y0, x1, y1, ...}`; NULL on
// failure (out of memory or an exception from Boost).
void* boost_polygon_voronoi_build(const std::int32_t* xy, std::size_t n) {
    try {
        boost::polygon::voronoi_builder<std::int32_t> builder;
        for (std::size_t i = 0; i < n; ++i) builder.insert_point(xy[2 * i], xy[2 * i + 1]);
        Diagram* diagram = new Diagram;
        builder.construct(diagram);
        return diagram;
    } catch (...) {
        return nullptr;
    }
}

// Builds the diagram of `n` segments `xyxy = {x1, y1, x2, y2, ...}` (first
// endpoint, second endpoint); NULL on failure. Boost splits each segment into
// its two endpoints and the open segment, as segvoronoi does, and expects
// segments that do not cross (it does not check).
void* boost_polygon_voronoi_build_segments(const std::int32_t* xyxy, std::size_t n) {
    try {
        boost::polygon::voronoi_builder<std::int32_t> builder;
        for (std::size_t i = 0; i < n; ++i)
            builder.insert_segment(xyxy[4 * i], xyxy[4 * i + 1], xyxy[4 * i + 2], xyxy[4 * i + 3]);
        Diagram* diagram = new Diagram;
        builder.construct(diagram);
        return diagram;
    } catch (...) {
        return nullptr;
    }
}

std::size_t boost_polygon_voronoi_cells(const void* diagram) {
    return static_cast<const Diagram*>(diagram)->num_cells();
}

std::size_t boost_polygon_voronoi_vertices(const void* diagram) {
    return static_cast<const Diagram*>(diagram)->num_vertices();
}

// Half-edges: two per edge.
std::size_t boost_polygon_voronoi_half_edges(const void* diagram) {
    return static_cast<const Diagram*>(diagram)->num_edges();
}

// The position of vertex `i` (below num_vertices) into `xy[0]`, `xy[1]`.
void boost_polygon_voronoi_vertex(const void* diagram, std::size_t i, double* xy) {
    const auto& v = static_cast<const Diagram*>(diagram)->vertices()[i];
    xy[0] = v.x();
    xy[1] = v.y();
}

void boost_polygon_voronoi_free(void* diagram) { delete static_cast<Diagram*>(diagram); }
}
