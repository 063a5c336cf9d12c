/* Tests of segvoronoi's C API: every exported function, every status code a
 * caller can provoke, NULL arguments and the ownership rules.
 *
 * Built two ways: by c_tests/CMakeLists.txt as a downstream consumer of the
 * installed package (run by ctest, under valgrind and AddressSanitizer), and
 * by the cargo crate in c_tests/cargo through the `cc` crate, which defines
 * SEGVORONOI_C_TESTS_NO_MAIN and calls segvoronoi_run_c_tests() itself.
 *
 * Plain C99; no test framework, so that it builds anywhere the header does. */

#include "segvoronoi.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int segvoronoi_run_c_tests(void);

static int failures = 0;
static int checks = 0;

#define CHECK(cond)                                                            \
    do {                                                                       \
        ++checks;                                                              \
        if (!(cond)) {                                                         \
            ++failures;                                                        \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__,   \
                    #cond);                                                    \
        }                                                                      \
    } while (0)

#define CHECK_STATUS(call, expected)                                           \
    do {                                                                       \
        segvoronoi_status got_ = (call);                                       \
        ++checks;                                                              \
        if (got_ != (expected)) {                                              \
            ++failures;                                                        \
            fprintf(stderr, "%s:%d: %s returned %d (%s), expected %s\n",       \
                    __FILE__, __LINE__, #call, (int)got_,                      \
                    segvoronoi_status_str(got_), #expected);                   \
        }                                                                      \
    } while (0)

/* Deterministic PRNG (SplitMix64) so failures reproduce. */
static uint64_t rng_state = 0x5eed5eedULL;

static double rng_uniform(void) {
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

/* Builds the diagram of `n` points from `xy`; NULL (and a failed check) on error. */
static segvoronoi_diagram *build_diagram(const double *xy, size_t n) {
    segvoronoi_builder *builder = segvoronoi_builder_new();
    segvoronoi_diagram *diagram = NULL;
    CHECK(builder != NULL);
    if (builder == NULL) return NULL;
    CHECK_STATUS(segvoronoi_builder_add_points(builder, xy, n), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(builder, &diagram), SEGVORONOI_STATUS_OK);
    segvoronoi_builder_free(builder); /* the diagram outlives its builder */
    return diagram;
}

static double distance(double ax, double ay, double bx, double by) {
    return hypot(ax - bx, ay - by);
}

/* Checks everything the accessors promise about one diagram:
 * validate(), Euler's relation E = V + S - 1 (connected cells, one vertex at
 * infinity), vertices equidistant from their counter-clockwise sites with no
 * site closer, edges consistent with their end vertices, cells listing each
 * edge from both sides, and nearest_site against brute force. */
static void check_diagram(const segvoronoi_diagram *diagram) {
    size_t sites = segvoronoi_diagram_site_count(diagram);
    size_t vertices = segvoronoi_diagram_vertex_count(diagram);
    size_t edges = segvoronoi_diagram_edge_count(diagram);
    size_t i, k;
    double min_x = DBL_MAX, max_x = -DBL_MAX, min_y = DBL_MAX, max_y = -DBL_MAX, scale;
    size_t *cell_sides = NULL;
    size_t cell_side_total = 0;
    segvoronoi_site *site_xy = NULL;
    uint32_t last_answer = SEGVORONOI_NO_SITE;

    CHECK_STATUS(segvoronoi_diagram_validate(diagram), SEGVORONOI_STATUS_OK);
    if (sites > 0) CHECK(edges == vertices + sites - 1);

    site_xy = (segvoronoi_site *)calloc(sites + 1, sizeof *site_xy);
    cell_sides = (size_t *)calloc(edges + 1, sizeof *cell_sides);
    CHECK(site_xy != NULL && cell_sides != NULL);
    if (site_xy == NULL || cell_sides == NULL) goto done;

    for (i = 0; i < sites; ++i) {
        CHECK_STATUS(segvoronoi_diagram_site(diagram, i, &site_xy[i]), SEGVORONOI_STATUS_OK);
        if (site_xy[i].x < min_x) min_x = site_xy[i].x;
        if (site_xy[i].x > max_x) max_x = site_xy[i].x;
        if (site_xy[i].y < min_y) min_y = site_xy[i].y;
        if (site_xy[i].y > max_y) max_y = site_xy[i].y;
    }
    scale = sites > 0 ? fmax(fmax(fabs(min_x), fabs(max_x)), fmax(fabs(min_y), fabs(max_y))) : 1.0;
    if (scale == 0.0) scale = 1.0;

    for (i = 0; i < vertices; ++i) {
        segvoronoi_vertex v;
        const segvoronoi_site *a, *b, *c;
        double orient;
        CHECK_STATUS(segvoronoi_diagram_vertex(diagram, i, &v), SEGVORONOI_STATUS_OK);
        CHECK(v.sites[0] < sites && v.sites[1] < sites && v.sites[2] < sites);
        if (!(v.sites[0] < sites && v.sites[1] < sites && v.sites[2] < sites)) continue;
        a = &site_xy[v.sites[0]];
        b = &site_xy[v.sites[1]];
        c = &site_xy[v.sites[2]];
        orient = (b->x - a->x) * (c->y - a->y) - (b->y - a->y) * (c->x - a->x);
        CHECK(orient > 0.0);
        for (k = 0; k < 3; ++k) {
            const segvoronoi_site *s = &site_xy[v.sites[k]];
            CHECK(fabs(distance(v.x, v.y, s->x, s->y) - v.clearance) <= 1e-9 * (v.clearance + scale));
        }
        for (k = 0; k < sites; ++k) { /* empty circle */
            CHECK(distance(v.x, v.y, site_xy[k].x, site_xy[k].y) >= v.clearance * (1.0 - 1e-9) - 1e-12 * scale);
        }
    }

    for (i = 0; i < edges; ++i) {
        segvoronoi_edge e;
        CHECK_STATUS(segvoronoi_diagram_edge(diagram, i, &e), SEGVORONOI_STATUS_OK);
        CHECK(e.sites[0] < sites && e.sites[1] < sites && e.sites[0] != e.sites[1]);
        for (k = 0; k < 2; ++k) {
            const segvoronoi_edge_end *end = &e.ends[k];
            if (end->vertex == SEGVORONOI_NO_VERTEX) {
                CHECK(fabs(hypot(end->x, end->y) - 1.0) < 1e-12);
            } else {
                segvoronoi_vertex v;
                CHECK_STATUS(segvoronoi_diagram_vertex(diagram, end->vertex, &v), SEGVORONOI_STATUS_OK);
                CHECK(v.x == end->x && v.y == end->y);
                CHECK((v.sites[0] == e.sites[0] || v.sites[1] == e.sites[0] || v.sites[2] == e.sites[0]) &&
                      (v.sites[0] == e.sites[1] || v.sites[1] == e.sites[1] || v.sites[2] == e.sites[1]));
            }
        }
    }

    for (i = 0; i < sites; ++i) {
        size_t needed = 0, written = 0;
        uint32_t *ids;
        segvoronoi_status st = segvoronoi_diagram_cell_edges(diagram, i, NULL, 0, &needed);
        CHECK(st == (sites > 1 ? SEGVORONOI_STATUS_BUFFER_TOO_SMALL : SEGVORONOI_STATUS_OK));
        CHECK(sites == 1 || needed > 0);
        ids = (uint32_t *)malloc((needed + 1) * sizeof *ids);
        CHECK(ids != NULL);
        if (ids == NULL) continue;
        CHECK_STATUS(segvoronoi_diagram_cell_edges(diagram, i, ids, needed + 1, &written), SEGVORONOI_STATUS_OK);
        CHECK(written == needed);
        for (k = 0; k < written; ++k) {
            segvoronoi_edge e;
            CHECK(ids[k] < edges);
            if (ids[k] >= edges) continue;
            CHECK_STATUS(segvoronoi_diagram_edge(diagram, ids[k], &e), SEGVORONOI_STATUS_OK);
            CHECK(e.sites[0] == i || e.sites[1] == i);
            cell_sides[ids[k]]++;
        }
        cell_side_total += written;
        free(ids);
    }
    CHECK(cell_side_total == 2 * edges);
    for (i = 0; i < edges; ++i) CHECK(cell_sides[i] == 2);

    for (i = 0; sites > 0 && i < 200; ++i) {
        double w = (max_x - min_x) + (max_y - min_y) + scale * 1e-3;
        double qx = min_x - 0.1 * w + 1.2 * w * rng_uniform();
        double qy = min_y - 0.1 * w + 1.2 * w * rng_uniform();
        double best = DBL_MAX;
        uint32_t answer = SEGVORONOI_NO_SITE;
        /* Alternate between no hint and the previous answer as the hint. */
        uint32_t hint = (i % 2 == 0) ? SEGVORONOI_NO_SITE : last_answer;
        CHECK_STATUS(segvoronoi_diagram_nearest_site(diagram, qx, qy, hint, &answer), SEGVORONOI_STATUS_OK);
        CHECK(answer < sites);
        if (answer >= sites) continue;
        for (k = 0; k < sites; ++k) best = fmin(best, distance(qx, qy, site_xy[k].x, site_xy[k].y));
        CHECK(distance(qx, qy, site_xy[answer].x, site_xy[answer].y) <= best * (1.0 + 1e-12));
        last_answer = answer;
    }

done:
    free(site_xy);
    free(cell_sides);
}

static void test_version_and_status_strings(void) {
    char expected[64];
    int s, t;
    CHECK(strcmp(segvoronoi_version(), SEGVORONOI_VERSION_STRING) == 0);
    snprintf(expected, sizeof expected, "%d.%d.%d", SEGVORONOI_VERSION_MAJOR, SEGVORONOI_VERSION_MINOR,
             SEGVORONOI_VERSION_PATCH);
    CHECK(strcmp(segvoronoi_version(), expected) == 0);

    /* The numbers are part of the ABI. */
    CHECK(SEGVORONOI_STATUS_OK == 0 && SEGVORONOI_STATUS_NULL_ARGUMENT == 1 &&
          SEGVORONOI_STATUS_INVALID_COORDINATE == 2 && SEGVORONOI_STATUS_INTERSECTING == 3 &&
          SEGVORONOI_STATUS_OUT_OF_RANGE == 4 && SEGVORONOI_STATUS_BUFFER_TOO_SMALL == 5 &&
          SEGVORONOI_STATUS_TOO_LARGE == 6 && SEGVORONOI_STATUS_INVALID_ARGUMENT == 7 &&
          SEGVORONOI_STATUS_INTERNAL == 8);
    for (s = 0; s <= SEGVORONOI_STATUS_INTERNAL; ++s) {
        const char *text = segvoronoi_status_str(s);
        CHECK(text != NULL && text[0] != '\0');
        CHECK(strcmp(text, "unknown status") != 0);
        for (t = 0; t < s; ++t) CHECK(strcmp(text, segvoronoi_status_str(t)) != 0);
    }
    CHECK(strcmp(segvoronoi_status_str(SEGVORONOI_STATUS_INTERNAL + 1), "unknown status") == 0);
    CHECK(strcmp(segvoronoi_status_str(-1), "unknown status") == 0);
}

static void test_free_rules_and_nulls(void) {
    segvoronoi_diagram *diagram = (segvoronoi_diagram *)&diagram; /* must be overwritten */
    segvoronoi_site site;
    segvoronoi_vertex vertex;
    segvoronoi_edge edge;
    segvoronoi_stats stats;
    uint32_t id = 7, ids[4];
    size_t count = 0;
    char *text = (char *)&text;
    double xy[2] = {1.0, 2.0};
    segvoronoi_builder *builder = segvoronoi_builder_new();

    /* _free(NULL) does nothing. */
    segvoronoi_builder_free(NULL);
    segvoronoi_diagram_free(NULL);
    segvoronoi_string_free(NULL);

    /* A NULL handle gives NULL_ARGUMENT, or 0 from the counters. */
    CHECK_STATUS(segvoronoi_builder_add_point(NULL, 1.0, 2.0), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_builder_add_points(NULL, xy, 1), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK(segvoronoi_builder_point_count(NULL) == 0);
    CHECK(segvoronoi_builder_last_error(NULL) != NULL);
    CHECK_STATUS(segvoronoi_builder_build(NULL, &diagram), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK(diagram == NULL); /* *out is cleared on every error */
    CHECK(segvoronoi_diagram_site_count(NULL) == 0);
    CHECK(segvoronoi_diagram_vertex_count(NULL) == 0);
    CHECK(segvoronoi_diagram_edge_count(NULL) == 0);
    CHECK_STATUS(segvoronoi_diagram_validate(NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_site(NULL, 0, &site), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_site_of_input(NULL, 0, &id), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_vertex(NULL, 0, &vertex), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_edge(NULL, 0, &edge), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_cell_edges(NULL, 0, ids, 4, &count), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_nearest_site(NULL, 0.0, 0.0, SEGVORONOI_NO_SITE, &id),
                 SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_stats(NULL, &stats), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_topology(NULL, 0, &text, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK(text == NULL);

    /* NULL output pointers on a live handle. */
    CHECK(builder != NULL);
    CHECK_STATUS(segvoronoi_builder_add_points(builder, NULL, 1), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_builder_add_points(builder, NULL, 0), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_add_points(builder, xy, 1), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(builder, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_builder_build(builder, &diagram), SEGVORONOI_STATUS_OK);
    CHECK(diagram != NULL);
    CHECK_STATUS(segvoronoi_diagram_site(diagram, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_site_of_input(diagram, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_vertex(diagram, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_edge(diagram, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_cell_edges(diagram, 0, ids, 4, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_cell_edges(diagram, 0, NULL, 4, &count), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_nearest_site(diagram, 0.0, 0.0, SEGVORONOI_NO_SITE, NULL),
                 SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_stats(diagram, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_topology(diagram, 0, NULL, &count), SEGVORONOI_STATUS_NULL_ARGUMENT);

    /* A diagram stays valid after its builder is freed. */
    segvoronoi_builder_free(builder);
    CHECK(segvoronoi_diagram_site_count(diagram) == 1);
    CHECK_STATUS(segvoronoi_diagram_site(diagram, 0, &site), SEGVORONOI_STATUS_OK);
    CHECK(site.x == 1.0 && site.y == 2.0);
    segvoronoi_diagram_free(diagram);
}

static void test_invalid_input_leaves_builder_unchanged(void) {
    segvoronoi_builder *builder = segvoronoi_builder_new();
    double good[6] = {0.0, 0.0, 1.0, 0.0, 0.0, 1.0};
    double bad[6] = {2.0, 2.0, 3.0, 3.0, 4.0, 0.0};
    segvoronoi_diagram *diagram = NULL;
    CHECK(builder != NULL);
    if (builder == NULL) return;
    CHECK(strcmp(segvoronoi_builder_last_error(builder), "") == 0);

    CHECK_STATUS(segvoronoi_builder_add_points(builder, good, 3), SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_builder_point_count(builder) == 3);

    /* One bad point: nothing is added, the message names input index 4. */
    bad[3] = NAN;
    CHECK_STATUS(segvoronoi_builder_add_points(builder, bad, 3), SEGVORONOI_STATUS_INVALID_COORDINATE);
    CHECK(segvoronoi_builder_point_count(builder) == 3);
    CHECK(strstr(segvoronoi_builder_last_error(builder), "point 4 ") != NULL);

    CHECK_STATUS(segvoronoi_builder_add_point(builder, INFINITY, 0.0), SEGVORONOI_STATUS_INVALID_COORDINATE);
    CHECK(strstr(segvoronoi_builder_last_error(builder), "point 3 ") != NULL);
    CHECK_STATUS(segvoronoi_builder_add_point(builder, 0.0, -INFINITY), SEGVORONOI_STATUS_INVALID_COORDINATE);
    CHECK(segvoronoi_builder_point_count(builder) == 3);

    /* More points than the library can hold: refused before `xy` is read
     * (only one point's worth of memory is behind the pointer). */
    CHECK_STATUS(segvoronoi_builder_add_points(builder, good, SIZE_MAX / 4), SEGVORONOI_STATUS_TOO_LARGE);
    CHECK(segvoronoi_builder_point_count(builder) == 3);
    CHECK(strstr(segvoronoi_builder_last_error(builder), "at most") != NULL);

    /* A successful call clears the message. */
    CHECK_STATUS(segvoronoi_builder_add_point(builder, 5.0, 5.0), SEGVORONOI_STATUS_OK);
    CHECK(strcmp(segvoronoi_builder_last_error(builder), "") == 0);
    CHECK(segvoronoi_builder_point_count(builder) == 4);

    /* The builder is not consumed: build, add, build again. */
    CHECK_STATUS(segvoronoi_builder_build(builder, &diagram), SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_diagram_site_count(diagram) == 4);
    check_diagram(diagram);
    segvoronoi_diagram_free(diagram);
    CHECK_STATUS(segvoronoi_builder_add_point(builder, 5.0, 0.0), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(builder, &diagram), SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_diagram_site_count(diagram) == 5);
    check_diagram(diagram);
    segvoronoi_diagram_free(diagram);
    segvoronoi_builder_free(builder);
}

static void test_small_and_degenerate_diagrams(void) {
    segvoronoi_diagram *d;
    uint32_t id;
    size_t count = 99;
    segvoronoi_site site;
    segvoronoi_edge edge;
    segvoronoi_stats stats;
    double one[2] = {3.0, 4.0};
    double two[4] = {0.0, 0.0, 2.0, 0.0};
    double collinear[8] = {0.0, 0.0, 3.0, 3.0, 1.0, 1.0, 2.0, 2.0};
    double equal[8] = {1.5, -2.0, 1.5, -2.0, 1.5, -2.0, 1.5, -2.0};
    double zeros[4] = {0.0, -0.0, -0.0, 0.0}; /* -0 equals +0 */

    /* No points: an empty, valid diagram. */
    d = build_diagram(NULL, 0);
    CHECK(d != NULL && segvoronoi_diagram_site_count(d) == 0 && segvoronoi_diagram_edge_count(d) == 0);
    CHECK_STATUS(segvoronoi_diagram_validate(d), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_diagram_nearest_site(d, 0.0, 0.0, SEGVORONOI_NO_SITE, &id), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_site(d, 0, &site), SEGVORONOI_STATUS_OUT_OF_RANGE);
    segvoronoi_diagram_free(d);

    /* One point: one cell, no edges. */
    d = build_diagram(one, 1);
    CHECK(segvoronoi_diagram_site_count(d) == 1 && segvoronoi_diagram_edge_count(d) == 0);
    CHECK_STATUS(segvoronoi_diagram_cell_edges(d, 0, NULL, 0, &count), SEGVORONOI_STATUS_OK);
    CHECK(count == 0);
    check_diagram(d);
    segvoronoi_diagram_free(d);

    /* Two points: one edge, a whole line (both ends at infinity). */
    d = build_diagram(two, 2);
    CHECK(segvoronoi_diagram_edge_count(d) == 1 && segvoronoi_diagram_vertex_count(d) == 0);
    CHECK_STATUS(segvoronoi_diagram_edge(d, 0, &edge), SEGVORONOI_STATUS_OK);
    CHECK(edge.ends[0].vertex == SEGVORONOI_NO_VERTEX && edge.ends[1].vertex == SEGVORONOI_NO_VERTEX);
    CHECK(fabs(edge.ends[0].x) < 1e-15 && fabs(fabs(edge.ends[0].y) - 1.0) < 1e-15);
    CHECK(edge.ends[0].y == -edge.ends[1].y);
    CHECK_STATUS(segvoronoi_diagram_edge(d, 1, &edge), SEGVORONOI_STATUS_OUT_OF_RANGE);
    check_diagram(d);
    segvoronoi_diagram_free(d);

    /* Collinear points: parallel lines, no vertex. */
    d = build_diagram(collinear, 4);
    CHECK(segvoronoi_diagram_edge_count(d) == 3 && segvoronoi_diagram_vertex_count(d) == 0);
    check_diagram(d);
    segvoronoi_diagram_free(d);

    /* All points equal: one site, the repeats merged and counted. */
    d = build_diagram(equal, 4);
    CHECK(segvoronoi_diagram_site_count(d) == 1);
    CHECK_STATUS(segvoronoi_diagram_stats(d, &stats), SEGVORONOI_STATUS_OK);
    CHECK(stats.input_points == 4 && stats.sites == 1 && stats.duplicate_points == 3);
    CHECK_STATUS(segvoronoi_diagram_site_of_input(d, 3, &id), SEGVORONOI_STATUS_OK);
    CHECK(id == 0);
    CHECK_STATUS(segvoronoi_diagram_site_of_input(d, 4, &id), SEGVORONOI_STATUS_OUT_OF_RANGE);
    segvoronoi_diagram_free(d);

    d = build_diagram(zeros, 2);
    CHECK(segvoronoi_diagram_site_count(d) == 1);
    segvoronoi_diagram_free(d);
}

static void test_square_with_centre(void) {
    /* Four corners and the centre: by hand, 4 Voronoi vertices (one per
     * triangle centre-corner-corner, at the midpoint of a side: clearance 1),
     * 8 edges (4 hull sides, 4 spokes), the
     * centre's cell a square with 4 edges, each corner's cell 3 edges. */
    double xy[10] = {0.0, 0.0, 2.0, 0.0, 2.0, 2.0, 0.0, 2.0, 1.0, 1.0};
    segvoronoi_diagram *d = build_diagram(xy, 5);
    segvoronoi_stats stats;
    uint32_t centre, ids[8];
    size_t count = 0, i;
    char *text = NULL;
    size_t length = 0;
    CHECK(d != NULL);
    if (d == NULL) return;
    check_diagram(d);
    CHECK(segvoronoi_diagram_vertex_count(d) == 4 && segvoronoi_diagram_edge_count(d) == 8);
    CHECK_STATUS(segvoronoi_diagram_stats(d, &stats), SEGVORONOI_STATUS_OK);
    CHECK(stats.input_points == 5 && stats.sites == 5 && stats.duplicate_points == 0 && stats.vertices == 4 &&
          stats.edges == 8);

    /* Sites are numbered in order of first appearance. */
    CHECK_STATUS(segvoronoi_diagram_site_of_input(d, 4, &centre), SEGVORONOI_STATUS_OK);
    CHECK(centre == 4);
    for (i = 0; i < 4; ++i) {
        segvoronoi_vertex v;
        CHECK_STATUS(segvoronoi_diagram_vertex(d, i, &v), SEGVORONOI_STATUS_OK);
        CHECK(fabs(v.clearance - 1.0) < 1e-15);
        CHECK(v.sites[0] == centre || v.sites[1] == centre || v.sites[2] == centre);
    }
    CHECK_STATUS(segvoronoi_diagram_vertex(d, 4, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    {
        segvoronoi_vertex v;
        CHECK_STATUS(segvoronoi_diagram_vertex(d, 4, &v), SEGVORONOI_STATUS_OUT_OF_RANGE);
    }

    /* Cell buffers: too small reports the size needed and fills what fits. */
    CHECK_STATUS(segvoronoi_diagram_cell_edges(d, centre, ids, 2, &count), SEGVORONOI_STATUS_BUFFER_TOO_SMALL);
    CHECK(count == 4);
    CHECK_STATUS(segvoronoi_diagram_cell_edges(d, centre, ids, 8, &count), SEGVORONOI_STATUS_OK);
    CHECK(count == 4);
    CHECK_STATUS(segvoronoi_diagram_cell_edges(d, 0, ids, 8, &count), SEGVORONOI_STATUS_OK);
    CHECK(count == 3);
    CHECK_STATUS(segvoronoi_diagram_cell_edges(d, 5, ids, 8, &count), SEGVORONOI_STATUS_OUT_OF_RANGE);

    /* Queries. */
    CHECK_STATUS(segvoronoi_diagram_nearest_site(d, 1.1, 0.9, SEGVORONOI_NO_SITE, &centre), SEGVORONOI_STATUS_OK);
    CHECK(centre == 4);
    CHECK_STATUS(segvoronoi_diagram_nearest_site(d, 1.9, 1.95, 0, &centre), SEGVORONOI_STATUS_OK);
    CHECK(centre == 2);
    CHECK_STATUS(segvoronoi_diagram_nearest_site(d, 1.0, 1.0, 5, &centre), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_nearest_site(d, NAN, 1.0, SEGVORONOI_NO_SITE, &centre),
                 SEGVORONOI_STATUS_INVALID_COORDINATE);

    /* Canonical topology. */
    CHECK_STATUS(segvoronoi_diagram_topology(d, 0, &text, &length), SEGVORONOI_STATUS_OK);
    CHECK(text != NULL && strlen(text) == length);
    CHECK(text != NULL && strncmp(text, "EDGES 8\n", 8) == 0);
    CHECK(text != NULL && strstr(text, "\nFACES 4\n") != NULL && strstr(text, "\nP0 P1 P4\n") != NULL);
    CHECK(text != NULL && strstr(text, "VPAIRS") == NULL);
    segvoronoi_string_free(text);
    CHECK_STATUS(segvoronoi_diagram_topology(d, SEGVORONOI_TOPOLOGY_VORONOI_PAIRS, &text, NULL), SEGVORONOI_STATUS_OK);
    CHECK(text != NULL && strstr(text, "\nVPAIRS 8\n") != NULL && strstr(text, "\nVVERTICES 4\n") != NULL);
    segvoronoi_string_free(text);
    text = (char *)&text;
    CHECK_STATUS(segvoronoi_diagram_topology(d, 0x80u, &text, &length), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    CHECK(text == NULL);
    segvoronoi_diagram_free(d);
}

/* A cocircular, regular input: a 12 x 12 lattice, where every square's four
 * corners share a circle. VPAIRS/VVERTICES merge the zero-length edges. */
static void test_lattice(void) {
    double xy[2 * 144];
    size_t i;
    segvoronoi_diagram *d;
    char *text = NULL;
    for (i = 0; i < 144; ++i) {
        xy[2 * i] = (double)(i % 12);
        xy[2 * i + 1] = (double)(i / 12);
    }
    d = build_diagram(xy, 144);
    check_diagram(d);
    CHECK_STATUS(segvoronoi_diagram_topology(d, SEGVORONOI_TOPOLOGY_VORONOI_PAIRS, &text, NULL), SEGVORONOI_STATUS_OK);
    /* 11 x 11 squares, one Voronoi vertex each; 2 * 11 * 12 lattice edges. */
    CHECK(text != NULL && strstr(text, "\nVVERTICES 121\n") != NULL && strstr(text, "\nVPAIRS 264\n") != NULL);
    segvoronoi_string_free(text);
    segvoronoi_diagram_free(d);
}

/* Random points at several magnitudes, including a huge offset (1e150, not
 * more: the checks here square coordinates in plain doubles). */
static void test_random_inputs(void) {
    static const double scales[4] = {1.0, 1e-9, 1e12, 1e150};
    static const double offsets[4] = {0.0, 1.0, -1e15, 0.0};
    size_t n = 600, i, r;
    double *xy = (double *)malloc(2 * n * sizeof *xy);
    CHECK(xy != NULL);
    if (xy == NULL) return;
    for (r = 0; r < 4; ++r) {
        segvoronoi_diagram *d;
        for (i = 0; i < 2 * n; ++i) xy[i] = offsets[r] + scales[r] * rng_uniform();
        d = build_diagram(xy, n);
        CHECK(d != NULL);
        if (d == NULL) continue;
        CHECK(segvoronoi_diagram_site_count(d) <= n);
        check_diagram(d);
        segvoronoi_diagram_free(d);
    }
    free(xy);
}

int segvoronoi_run_c_tests(void) {
    failures = 0;
    checks = 0;
    test_version_and_status_strings();
    test_free_rules_and_nulls();
    test_invalid_input_leaves_builder_unchanged();
    test_small_and_degenerate_diagrams();
    test_square_with_centre();
    test_lattice();
    test_random_inputs();
    fprintf(stderr, "segvoronoi C API tests: %d checks, %d failed\n", checks, failures);
    return failures;
}

#ifndef SEGVORONOI_C_TESTS_NO_MAIN
int main(void) {
    return segvoronoi_run_c_tests() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
#endif
