// Clipper's ClipperOffset (Clipper 6, Debian's libpolyclipping-dev) behind a
// small C interface for the offsets benchmark: the input paths are built
// once, outside the timed region; each call offsets them (jtRound,
// etClosedPolygon) and reports the output's size.

#include <polyclipping/clipper.hpp>

#include <cstddef>
#include <cstdint>

extern "C" {

// The paths: `n_rings` rings of `lengths[j]` integer points each, one after
// another in `xy`. Outer rings and holes must have opposite orientations.
void* clipper_bench_new(const std::int64_t* xy, const std::size_t* lengths, std::size_t n_rings) {
    auto* paths = new ClipperLib::Paths(n_rings);
    for (std::size_t j = 0; j < n_rings; ++j) {
        for (std::size_t i = 0; i < lengths[j]; ++i) (*paths)[j].emplace_back(xy[2 * i], xy[2 * i + 1]);
        xy += 2 * lengths[j];
    }
    return paths;
}

// Offsets the paths by `delta` (integer units) with arcs within
// `arc_tolerance`; writes the number of vertices and rings; 0 on success.
int clipper_bench_offset(const void* paths, double delta, double arc_tolerance, std::size_t* vertices, std::size_t* rings) {
    try {
        ClipperLib::ClipperOffset offset(2.0, arc_tolerance);
        offset.AddPaths(*static_cast<const ClipperLib::Paths*>(paths), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
        ClipperLib::Paths out;
        offset.Execute(out, delta);
        std::size_t count = 0;
        for (const auto& p : out) count += p.size();
        *vertices = count;
        *rings = out.size();
        return 0;
    } catch (...) {
        return 1;
    }
}

void clipper_bench_free(void* paths) { delete static_cast<ClipperLib::Paths*>(paths); }

}  // extern "C"
