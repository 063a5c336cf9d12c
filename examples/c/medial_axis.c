#include <segvoronoi.h>
#include <stdio.h>

/* The pieces of a medial axis, in all its chains. */
static size_t count_pieces(const segvoronoi_medial_axis *axis) {
    size_t total = 0;
    for (size_t c = 0; c < segvoronoi_medial_axis_chain_count(axis); c++) {
        size_t n = 0;
        bool closed = false;
        segvoronoi_medial_axis_chain(axis, c, &n, &closed);
        total += n;
    }
    return total;
}

int main(void) {
    const double rectangle[] = {0, 0, 4, 0, 4, 2, 0, 2}; /* one ring, either orientation */
    const size_t ring_lengths[] = {4};
    segvoronoi_builder *b = segvoronoi_builder_new();
    segvoronoi_diagram *d = NULL;
    if (segvoronoi_builder_add_polygon(b, rectangle, ring_lengths, 1) != SEGVORONOI_STATUS_OK ||
        segvoronoi_builder_build(b, &d) != SEGVORONOI_STATUS_OK) {
        fprintf(stderr, "segvoronoi: %s\n", segvoronoi_builder_last_error(b));
        segvoronoi_builder_free(b);
        return 1;
    }
    double x, y, r;
    segvoronoi_diagram_max_inscribed_circle(d, &x, &y, &r);
    printf("largest disk: r=%g\n", r);

    segvoronoi_medial_axis *axis = NULL;
    segvoronoi_diagram_medial_axis(d, &axis);
    printf("medial axis: %zu pieces\n", count_pieces(axis));
    segvoronoi_medial_axis_free(axis);

    /* without the leaf branches shorter than 1.5 times their junction's
       clearance: the four into the corners go, the middle line stays */
    segvoronoi_medial_axis_filter filter = {.struct_size = sizeof filter};
    filter.spur_filter = true;
    filter.spur_factor = 1.5;
    segvoronoi_diagram_medial_axis_filtered(d, &filter, &axis);
    printf("pruned: %zu pieces\n", count_pieces(axis));
    segvoronoi_medial_axis_free(axis); /* before the diagram it refers to */

    segvoronoi_diagram_free(d);
    segvoronoi_builder_free(b);
    return 0;
}
