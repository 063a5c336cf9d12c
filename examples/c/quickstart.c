#include <segvoronoi.h>
#include <stdio.h>

int main(void) {
    const double xy[] = {0, 0, 2, 0, 1, 2, 1, 0.7};
    segvoronoi_builder *b = segvoronoi_builder_new();
    segvoronoi_diagram *d = NULL;
    if (segvoronoi_builder_add_points(b, xy, 4) != SEGVORONOI_STATUS_OK ||
        segvoronoi_builder_build(b, &d) != SEGVORONOI_STATUS_OK) {
        fprintf(stderr, "segvoronoi: %s\n", segvoronoi_builder_last_error(b));
        segvoronoi_builder_free(b);
        return 1;
    }
    for (size_t i = 0; i < segvoronoi_diagram_vertex_count(d); i++) {
        segvoronoi_vertex v = {.struct_size = sizeof v}; /* see "Versioned structs" */
        segvoronoi_diagram_vertex(d, i, &v);
        printf("vertex %zu: (%g, %g) r=%g\n", i, v.x, v.y, v.clearance);
    }
    segvoronoi_diagram_free(d);
    segvoronoi_builder_free(b);
    return 0;
}
