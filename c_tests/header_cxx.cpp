// The C header used from C++17: it must compile warning-free, link, and give
// C++ callers the same types and constants.
#include "segvoronoi.h"

#include <cstdio>
#include <cstring>
#include <type_traits>

static_assert(std::is_standard_layout<segvoronoi_vertex>::value, "plain C struct");
static_assert(SEGVORONOI_STATUS_INTERNAL == 8, "status numbers are stable");

int main() {
    segvoronoi_builder* builder = segvoronoi_builder_new();
    const double xy[] = {0.0, 0.0, 1.0, 0.0, 0.0, 1.0};
    segvoronoi_diagram* diagram = nullptr;
    int failed = builder == nullptr;
    failed |= segvoronoi_builder_add_points(builder, xy, 3) != SEGVORONOI_STATUS_OK;
    failed |= segvoronoi_builder_build(builder, &diagram) != SEGVORONOI_STATUS_OK;
    failed |= segvoronoi_diagram_vertex_count(diagram) != 1;
    failed |= std::strcmp(segvoronoi_version(), SEGVORONOI_VERSION_STRING) != 0;
    segvoronoi_diagram_free(diagram);
    segvoronoi_builder_free(builder);
    std::printf("header_cxx: %s\n", failed ? "FAILED" : "ok");
    return failed;
}
