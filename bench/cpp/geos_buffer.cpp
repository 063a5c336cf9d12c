// GEOS's buffer (its reentrant C API, Debian's libgeos-dev) behind a small C
// interface for the offsets benchmark: the input is made into one GEOS
// MultiPolygon once, outside the timed region; each call buffers it with
// round joins and reports the output's size, then frees the output.

#include <geos_c.h>

#include <cstddef>
#include <vector>

namespace {
struct Input {
    GEOSContextHandle_t ctx;
    GEOSGeometry* geometry;
};

GEOSGeometry* ring(GEOSContextHandle_t ctx, const double* xy, std::size_t n) {
    GEOSCoordSequence* s = GEOSCoordSeq_create_r(ctx, static_cast<unsigned>(n + 1), 2);
    for (std::size_t i = 0; i <= n; ++i) GEOSCoordSeq_setXY_r(ctx, s, static_cast<unsigned>(i), xy[2 * (i % n)], xy[2 * (i % n) + 1]);
    return GEOSGeom_createLinearRing_r(ctx, s);
}
}  // namespace

extern "C" {

// The MultiPolygon of `n_polygons` polygons; polygon k has `rings[k]` rings
// (the first its shell, the others its holes), ring j has `lengths[j]`
// points (not repeated at the end), all points one after another in `xy`.
// NULL on failure.
void* geos_bench_new(const double* xy, const std::size_t* lengths, const std::size_t* rings, std::size_t n_polygons) {
    GEOSContextHandle_t ctx = GEOS_init_r();
    std::vector<GEOSGeometry*> polygons;
    std::size_t r = 0;
    for (std::size_t k = 0; k < n_polygons; ++k) {
        GEOSGeometry* shell = ring(ctx, xy, lengths[r]);
        xy += 2 * lengths[r++];
        std::vector<GEOSGeometry*> holes;
        for (std::size_t h = 1; h < rings[k]; ++h) {
            holes.push_back(ring(ctx, xy, lengths[r]));
            xy += 2 * lengths[r++];
        }
        polygons.push_back(GEOSGeom_createPolygon_r(ctx, shell, holes.data(), static_cast<unsigned>(holes.size())));
    }
    GEOSGeometry* g = GEOSGeom_createCollection_r(ctx, GEOS_MULTIPOLYGON, polygons.data(), static_cast<unsigned>(polygons.size()));
    if (!g) {
        GEOS_finish_r(ctx);
        return nullptr;
    }
    return new Input{ctx, g};
}

// Buffers the input by `distance` (round joins and caps, `quadsegs`
// segments per quarter circle). Writes the number of vertices (each ring's
// closing point not counted) and rings of the output; 0 on success.
int geos_bench_buffer(void* input, double distance, int quadsegs, std::size_t* vertices, std::size_t* rings) {
    Input* in = static_cast<Input*>(input);
    GEOSGeometry* b =
        GEOSBufferWithStyle_r(in->ctx, in->geometry, distance, quadsegs, GEOSBUF_CAP_ROUND, GEOSBUF_JOIN_ROUND, 5.0);
    if (!b) return 1;
    std::size_t count = 0;
    for (int i = 0, n = GEOSGetNumGeometries_r(in->ctx, b); i < n; ++i) {
        const GEOSGeometry* p = GEOSGetGeometryN_r(in->ctx, b, i);
        if (GEOSisEmpty_r(in->ctx, p)) continue;
        count += 1 + static_cast<std::size_t>(GEOSGetNumInteriorRings_r(in->ctx, p));
    }
    *rings = count;
    *vertices = static_cast<std::size_t>(GEOSGetNumCoordinates_r(in->ctx, b)) - count;
    GEOSGeom_destroy_r(in->ctx, b);
    return 0;
}

void geos_bench_free(void* input) {
    Input* in = static_cast<Input*>(input);
    if (!in) return;
    GEOSGeom_destroy_r(in->ctx, in->geometry);
    GEOS_finish_r(in->ctx);
    delete in;
}

}  // extern "C"
