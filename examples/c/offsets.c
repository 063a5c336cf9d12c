#include <segvoronoi.h>
#include <stdio.h>
#include <stdlib.h>

/* The area of a closed polyline of n points {x, y}, by the shoelace formula. */
static double shoelace(const double *xy, size_t n) {
    double twice = 0.0;
    for (size_t p = 0; p < n; p++) {
        size_t q = (p + 1) % n;
        twice += xy[2 * p] * xy[2 * q + 1] - xy[2 * q] * xy[2 * p + 1];
    }
    return twice / 2.0;
}

int main(void) {
    /* a 10 x 10 square with a 2 x 2 hole */
    const double rings[] = {0, 0, 10, 0, 10, 10, 0, 10, 4, 4, 4, 6, 6, 6, 6, 4};
    const size_t ring_lengths[] = {4, 4};
    const double distances[] = {-1, -2, 1}; /* shrink by 1 and by 2, grow by 1 */
    segvoronoi_builder *b = segvoronoi_builder_new();
    segvoronoi_diagram *d = NULL;
    if (segvoronoi_builder_add_polygon(b, rings, ring_lengths, 2) != SEGVORONOI_STATUS_OK ||
        segvoronoi_builder_build(b, &d) != SEGVORONOI_STATUS_OK) {
        fprintf(stderr, "segvoronoi: %s\n", segvoronoi_builder_last_error(b));
        segvoronoi_builder_free(b);
        return 1;
    }
    segvoronoi_builder_free(b);

    /* all three distances in one call, a handle each */
    segvoronoi_offset *offsets[3];
    if (segvoronoi_diagram_offsets(d, distances, 3, offsets) != SEGVORONOI_STATUS_OK) {
        segvoronoi_diagram_free(d);
        return 1;
    }
    for (size_t k = 0; k < 3; k++) {
        size_t loops = segvoronoi_offset_loop_count(offsets[k]);
        printf("d=%g: %zu loops, area %.4f\n", distances[k], loops, segvoronoi_offset_area(offsets[k]));
        for (size_t l = 0; l < loops; l++) {
            segvoronoi_loop loop = {.struct_size = sizeof loop};
            segvoronoi_offset_loop(offsets[k], l, &loop);
            size_t arcs = 0;
            for (size_t p = 0; p < loop.piece_count; p++) {
                segvoronoi_loop_piece piece = {.struct_size = sizeof piece};
                segvoronoi_offset_piece(offsets[k], l, p, &piece);
                arcs += piece.kind == SEGVORONOI_OFFSET_ARC;
            }
            /* within 0.01 of the exact loop: count the points, then fetch them */
            size_t n = 0;
            segvoronoi_offset_loop_polyline(offsets[k], l, 0.01, NULL, 0, &n);
            double *xy = malloc(2 * n * sizeof *xy);
            if (xy == NULL || segvoronoi_offset_loop_polyline(offsets[k], l, 0.01, xy, n, &n) != SEGVORONOI_STATUS_OK) {
                return 1;
            }
            printf("  loop %zu: %s, %zu pieces (%zu arcs), area %.4f, polyline area %.1f\n", l,
                   loop.hole ? "hole" : "outer", loop.piece_count, arcs, loop.signed_area, shoelace(xy, n));
            free(xy);
        }
    }
    /* an offset holds its own copy of its loops: it may outlive the diagram */
    segvoronoi_diagram_free(d);
    for (size_t k = 0; k < 3; k++) segvoronoi_offset_free(offsets[k]);
    return 0;
}
