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
#include <stdbool.h>
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

/* The point of a site nearest to (x, y): the point itself, or for a segment
 * site the nearest point of the closed segment (the distance to the open
 * segment is the same number). */
static void nearest_point_of_site(const segvoronoi_site *s, double x, double y, double *px, double *py) {
    double dx = s->x2 - s->x, dy = s->y2 - s->y, len2 = dx * dx + dy * dy, t;
    if (s->kind != SEGVORONOI_SITE_SEGMENT || len2 == 0.0) {
        *px = s->x;
        *py = s->y;
        return;
    }
    t = ((x - s->x) * dx + (y - s->y) * dy) / len2;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    *px = s->x + t * dx;
    *py = s->y + t * dy;
}

static double site_distance(const segvoronoi_site *s, double x, double y) {
    double px, py;
    nearest_point_of_site(s, x, y, &px, &py);
    return distance(x, y, px, py);
}

/* A segment site's endpoints are the point sites at its two ends, and its
 * input index leads back to it; a point site has neither. */
static void check_segment_site(const segvoronoi_diagram *diagram, size_t i, const segvoronoi_site *s) {
    uint32_t ends[2] = {SEGVORONOI_NO_SITE, SEGVORONOI_NO_SITE}, back = SEGVORONOI_NO_SITE;
    size_t input = SIZE_MAX, k;
    if (s->kind != SEGVORONOI_SITE_SEGMENT) {
        CHECK_STATUS(segvoronoi_diagram_segment_endpoints(diagram, i, ends), SEGVORONOI_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(segvoronoi_diagram_segment_input_index(diagram, i, &input), SEGVORONOI_STATUS_INVALID_ARGUMENT);
        CHECK(ends[0] == SEGVORONOI_NO_SITE && input == SIZE_MAX); /* untouched on error */
        return;
    }
    CHECK_STATUS(segvoronoi_diagram_segment_endpoints(diagram, i, ends), SEGVORONOI_STATUS_OK);
    CHECK(ends[0] < segvoronoi_diagram_point_site_count(diagram) &&
          ends[1] < segvoronoi_diagram_point_site_count(diagram) && ends[0] != ends[1]);
    for (k = 0; k < 2; ++k) {
        segvoronoi_site end = {.struct_size = sizeof(segvoronoi_site)};
        CHECK_STATUS(segvoronoi_diagram_site(diagram, ends[k], &end), SEGVORONOI_STATUS_OK);
        CHECK(end.kind == SEGVORONOI_SITE_POINT);
        CHECK(k == 0 ? (end.x == s->x && end.y == s->y) : (end.x == s->x2 && end.y == s->y2));
    }
    CHECK_STATUS(segvoronoi_diagram_segment_input_index(diagram, i, &input), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_diagram_site_of_segment(diagram, input, &back), SEGVORONOI_STATUS_OK);
    CHECK(back == i);
}

/* Half-edge navigation (h = 2 * edge + side): next and prev undo each other
 * and stay around one cell, a finite target is where the next half-edge
 * starts, the walk around each cell is its list of half-edges, the three
 * half-edges of a vertex leave it, and each segment has exactly one
 * separator with each of its endpoints. */
static void check_navigation(const segvoronoi_diagram *diagram) {
    size_t sites = segvoronoi_diagram_site_count(diagram);
    size_t point_sites = segvoronoi_diagram_point_site_count(diagram);
    size_t vertices = segvoronoi_diagram_vertex_count(diagram);
    size_t edges = segvoronoi_diagram_edge_count(diagram);
    size_t i, k, separators = 0;
    uint32_t h, out, back, cell, next_cell, three[3];

    for (h = 0; h < 2 * edges; ++h) {
        segvoronoi_edge e = {.struct_size = sizeof(segvoronoi_edge)}, n = {.struct_size = sizeof(segvoronoi_edge)};
        CHECK_STATUS(segvoronoi_diagram_edge(diagram, h / 2, &e), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_diagram_half_edge_cell(diagram, h, &cell), SEGVORONOI_STATUS_OK);
        CHECK(cell == e.sites[h & 1]);
        CHECK_STATUS(segvoronoi_diagram_half_edge_next(diagram, h, &out), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_diagram_half_edge_prev(diagram, out, &back), SEGVORONOI_STATUS_OK);
        CHECK(back == h);
        CHECK_STATUS(segvoronoi_diagram_half_edge_cell(diagram, out, &next_cell), SEGVORONOI_STATUS_OK);
        CHECK(next_cell == cell);
        CHECK_STATUS(segvoronoi_diagram_edge(diagram, out / 2, &n), SEGVORONOI_STATUS_OK);
        /* the target of h is ends[1 - side]; the origin of the next is ends[its side] */
        CHECK(e.ends[1 - (h & 1)].vertex == n.ends[out & 1].vertex);
        if (h % 2 == 0 && e.is_separator) ++separators;
    }
    CHECK(separators == 2 * (sites - point_sites));
    CHECK_STATUS(segvoronoi_diagram_half_edge_next(diagram, (uint32_t)(2 * edges), &out), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_half_edge_next(diagram, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    for (i = 0; i < vertices; ++i) {
        CHECK_STATUS(segvoronoi_diagram_vertex_half_edges(diagram, i, three), SEGVORONOI_STATUS_OK);
        for (k = 0; k < 3; ++k) {
            segvoronoi_edge e = {.struct_size = sizeof(segvoronoi_edge)};
            CHECK_STATUS(segvoronoi_diagram_edge(diagram, three[k] / 2, &e), SEGVORONOI_STATUS_OK);
            CHECK(e.ends[three[k] & 1].vertex == i);
        }
    }
    CHECK_STATUS(segvoronoi_diagram_vertex_half_edges(diagram, vertices, three), SEGVORONOI_STATUS_OUT_OF_RANGE);
    for (i = 0; i < sites; ++i) {
        size_t count = 0, edge_count = 0, j;
        uint32_t *around;
        CHECK_STATUS(segvoronoi_diagram_cell_half_edges(diagram, i, NULL, 0, &count), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_diagram_cell_edges(diagram, i, NULL, 0, &edge_count), SEGVORONOI_STATUS_OK);
        CHECK(count == edge_count);
        if (count == 0) continue;
        around = malloc(count * sizeof *around);
        CHECK(around != NULL);
        CHECK_STATUS(segvoronoi_diagram_cell_half_edges(diagram, i, around, count, &count), SEGVORONOI_STATUS_OK);
        for (j = 0; j < count; ++j) {
            CHECK_STATUS(segvoronoi_diagram_half_edge_next(diagram, around[j], &out), SEGVORONOI_STATUS_OK);
            CHECK(out == around[(j + 1) % count]);
        }
        free(around);
    }
}

/* Checks everything the accessors promise about one diagram of points and
 * segments: validate(), Euler's relation E = V + S - 1 (connected cells, one
 * vertex at infinity), point sites before segment sites, vertices
 * equidistant from their sites, whose nearest points lie counter-clockwise
 * around the vertex, with no site closer (empty circle; the distance to a
 * segment site is the distance to the closed segment), edges consistent with
 * their end vertices, cells listing each edge from both sides, and
 * nearest_site against brute force. */
static void check_diagram(const segvoronoi_diagram *diagram) {
    size_t sites = segvoronoi_diagram_site_count(diagram);
    size_t point_sites = segvoronoi_diagram_point_site_count(diagram);
    size_t vertices = segvoronoi_diagram_vertex_count(diagram);
    size_t edges = segvoronoi_diagram_edge_count(diagram);
    size_t i, k;
    double min_x = DBL_MAX, max_x = -DBL_MAX, min_y = DBL_MAX, max_y = -DBL_MAX, scale;
    size_t *cell_sides = NULL;
    size_t cell_side_total = 0;
    segvoronoi_site *site_xy = NULL;
    uint32_t last_answer = SEGVORONOI_NO_SITE;

    CHECK_STATUS(segvoronoi_diagram_validate(diagram), SEGVORONOI_STATUS_OK);
    check_navigation(diagram);
    if (sites > 0) CHECK(edges == vertices + sites - 1);
    CHECK(point_sites <= sites);

    site_xy = (segvoronoi_site *)calloc(sites + 1, sizeof *site_xy);
    cell_sides = (size_t *)calloc(edges + 1, sizeof *cell_sides);
    CHECK(site_xy != NULL && cell_sides != NULL);
    if (site_xy == NULL || cell_sides == NULL) goto done;

    for (i = 0; i < sites; ++i) {
        segvoronoi_site *s = &site_xy[i];
        s->struct_size = sizeof *s;
        CHECK_STATUS(segvoronoi_diagram_site(diagram, i, s), SEGVORONOI_STATUS_OK);
        /* Points first, then open segments (of positive length). */
        CHECK(s->kind == (i < point_sites ? SEGVORONOI_SITE_POINT : SEGVORONOI_SITE_SEGMENT));
        if (s->kind == SEGVORONOI_SITE_POINT) CHECK(s->x2 == s->x && s->y2 == s->y);
        if (s->kind == SEGVORONOI_SITE_SEGMENT) CHECK(s->x2 != s->x || s->y2 != s->y);
        check_segment_site(diagram, i, s);
        min_x = fmin(min_x, fmin(s->x, s->x2));
        max_x = fmax(max_x, fmax(s->x, s->x2));
        min_y = fmin(min_y, fmin(s->y, s->y2));
        max_y = fmax(max_y, fmax(s->y, s->y2));
    }
    scale = sites > 0 ? fmax(fmax(fabs(min_x), fabs(max_x)), fmax(fabs(min_y), fabs(max_y))) : 1.0;
    if (scale == 0.0) scale = 1.0;

    for (i = 0; i < vertices; ++i) {
        segvoronoi_vertex v = {.struct_size = sizeof(segvoronoi_vertex)};
        double tx[3], ty[3], orient, apart;
        CHECK_STATUS(segvoronoi_diagram_vertex(diagram, i, &v), SEGVORONOI_STATUS_OK);
        CHECK(v.sites[0] < sites && v.sites[1] < sites && v.sites[2] < sites);
        if (!(v.sites[0] < sites && v.sites[1] < sites && v.sites[2] < sites)) continue;
        CHECK(v.clearance >= 0.0);
        for (k = 0; k < 3; ++k) {
            const segvoronoi_site *s = &site_xy[v.sites[k]];
            nearest_point_of_site(s, v.x, v.y, &tx[k], &ty[k]);
            CHECK(fabs(distance(v.x, v.y, tx[k], ty[k]) - v.clearance) <= 1e-9 * (v.clearance + scale));
        }
        /* The sites' nearest points lie on the circle in the order of the
         * cells around the vertex, counter-clockwise. Two sites may touch
         * the circle at one point (a segment and its endpoint; all three at
         * a shared endpoint, clearance 0): then the order says nothing. */
        apart = 1e-6 * v.clearance;
        if (distance(tx[0], ty[0], tx[1], ty[1]) > apart && distance(tx[1], ty[1], tx[2], ty[2]) > apart &&
            distance(tx[2], ty[2], tx[0], ty[0]) > apart) {
            orient = (tx[1] - tx[0]) * (ty[2] - ty[0]) - (ty[1] - ty[0]) * (tx[2] - tx[0]);
            CHECK(orient > 0.0);
        }
        for (k = 0; k < sites; ++k) { /* empty circle */
            CHECK(site_distance(&site_xy[k], v.x, v.y) >= v.clearance * (1.0 - 1e-9) - 1e-12 * scale);
        }
    }

    for (i = 0; i < edges; ++i) {
        segvoronoi_edge e = {.struct_size = sizeof(segvoronoi_edge)};
        CHECK_STATUS(segvoronoi_diagram_edge(diagram, i, &e), SEGVORONOI_STATUS_OK);
        CHECK(e.sites[0] < sites && e.sites[1] < sites && e.sites[0] != e.sites[1]);
        CHECK(e.struct_size == sizeof e);
        CHECK(e.is_infinite == (e.ends[0].vertex == SEGVORONOI_NO_VERTEX || e.ends[1].vertex == SEGVORONOI_NO_VERTEX));
        for (k = 0; k < 2; ++k) {
            const segvoronoi_edge_end *end = &e.ends[k];
            if (end->vertex == SEGVORONOI_NO_VERTEX) {
                CHECK(fabs(hypot(end->x, end->y) - 1.0) < 1e-12);
            } else {
                segvoronoi_vertex v = {.struct_size = sizeof(segvoronoi_vertex)};
                CHECK_STATUS(segvoronoi_diagram_vertex(diagram, end->vertex, &v), SEGVORONOI_STATUS_OK);
                CHECK(v.x == end->x && v.y == end->y);
                CHECK((v.sites[0] == e.sites[0] || v.sites[1] == e.sites[0] || v.sites[2] == e.sites[0]) &&
                      (v.sites[0] == e.sites[1] || v.sites[1] == e.sites[1] || v.sites[2] == e.sites[1]));
            }
        }
    }

    for (i = 0; i < sites; ++i) {
        size_t needed = 0, written = 0, neighbor_count = 0;
        uint32_t *ids, *neighbors;
        bool unbounded = false, reaches_infinity = sites == 1;
        /* (NULL, 0) only counts; a buffer one short is too small. */
        CHECK_STATUS(segvoronoi_diagram_cell_edges(diagram, i, NULL, 0, &needed), SEGVORONOI_STATUS_OK);
        CHECK(sites == 1 || needed > 0);
        if (needed > 0) {
            uint32_t first = SEGVORONOI_NO_SITE;
            /* A buffer, even of capacity 0, is no count query. */
            CHECK_STATUS(segvoronoi_diagram_cell_edges(diagram, i, &first, 0, &written),
                         SEGVORONOI_STATUS_BUFFER_TOO_SMALL);
            CHECK(written == needed && first == SEGVORONOI_NO_SITE);
        }
        ids = (uint32_t *)malloc((needed + 1) * sizeof *ids);
        neighbors = (uint32_t *)malloc((needed + 1) * sizeof *neighbors);
        CHECK(ids != NULL && neighbors != NULL);
        if (ids == NULL || neighbors == NULL) {
            free(ids);
            free(neighbors);
            continue;
        }
        CHECK_STATUS(segvoronoi_diagram_cell_edges(diagram, i, ids, needed + 1, &written), SEGVORONOI_STATUS_OK);
        CHECK(written == needed);
        /* One neighbour per edge, in the same order: the edge's other site. */
        CHECK_STATUS(segvoronoi_diagram_cell_neighbors(diagram, i, NULL, 0, &neighbor_count), SEGVORONOI_STATUS_OK);
        CHECK(neighbor_count == needed);
        CHECK_STATUS(segvoronoi_diagram_cell_neighbors(diagram, i, neighbors, needed + 1, &neighbor_count),
                     SEGVORONOI_STATUS_OK);
        CHECK(neighbor_count == needed);
        for (k = 0; k < written; ++k) {
            segvoronoi_edge e = {.struct_size = sizeof(segvoronoi_edge)};
            CHECK(ids[k] < edges);
            if (ids[k] >= edges) continue;
            CHECK_STATUS(segvoronoi_diagram_edge(diagram, ids[k], &e), SEGVORONOI_STATUS_OK);
            CHECK(e.sites[0] == i || e.sites[1] == i);
            CHECK(k >= neighbor_count || neighbors[k] == (e.sites[0] == i ? e.sites[1] : e.sites[0]));
            if (e.is_infinite) reaches_infinity = true;
            cell_sides[ids[k]]++;
        }
        /* A cell is unbounded exactly when a ray or line bounds it. */
        CHECK_STATUS(segvoronoi_diagram_cell_is_unbounded(diagram, i, &unbounded), SEGVORONOI_STATUS_OK);
        CHECK(unbounded == reaches_infinity);
        cell_side_total += written;
        free(ids);
        free(neighbors);
    }
    if (sites > 0) {
        bool unbounded = false;
        uint32_t ends[2];
        size_t n = 0, input = 0;
        CHECK_STATUS(segvoronoi_diagram_cell_is_unbounded(diagram, sites, &unbounded), SEGVORONOI_STATUS_OUT_OF_RANGE);
        CHECK_STATUS(segvoronoi_diagram_cell_neighbors(diagram, sites, NULL, 0, &n), SEGVORONOI_STATUS_OUT_OF_RANGE);
        CHECK_STATUS(segvoronoi_diagram_segment_endpoints(diagram, sites, ends), SEGVORONOI_STATUS_OUT_OF_RANGE);
        CHECK_STATUS(segvoronoi_diagram_segment_input_index(diagram, sites, &input), SEGVORONOI_STATUS_OUT_OF_RANGE);
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
        for (k = 0; k < sites; ++k) best = fmin(best, site_distance(&site_xy[k], qx, qy));
        CHECK(site_distance(&site_xy[answer], qx, qy) <= best * (1.0 + 1e-12));
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
    CHECK(SEGVORONOI_VERSION_NUMBER ==
          SEGVORONOI_VERSION_MAJOR * 10000 + SEGVORONOI_VERSION_MINOR * 100 + SEGVORONOI_VERSION_PATCH);
    CHECK(segvoronoi_version_number() == SEGVORONOI_VERSION_NUMBER);

    /* The numbers are part of the ABI. */
    CHECK(SEGVORONOI_STATUS_OK == 0 && SEGVORONOI_STATUS_NULL_ARGUMENT == 1 &&
          SEGVORONOI_STATUS_INVALID_COORDINATE == 2 && SEGVORONOI_STATUS_INTERSECTING == 3 &&
          SEGVORONOI_STATUS_OUT_OF_RANGE == 4 && SEGVORONOI_STATUS_BUFFER_TOO_SMALL == 5 &&
          SEGVORONOI_STATUS_TOO_LARGE == 6 && SEGVORONOI_STATUS_INVALID_ARGUMENT == 7 &&
          SEGVORONOI_STATUS_INTERNAL == 8 && SEGVORONOI_STATUS_INVALID_POLYGON == 9);
    CHECK(SEGVORONOI_STATUS_OUT_OF_MEMORY == 10 && SEGVORONOI_STATUS_UNSUPPORTED_RANGE == 11);
    CHECK(SEGVORONOI_STATUS_INVALID_ARC == 12);
    for (s = 0; s <= SEGVORONOI_STATUS_INVALID_ARC; ++s) {
        const char *text = segvoronoi_status_str(s);
        CHECK(text != NULL && text[0] != '\0');
        CHECK(strcmp(text, "unknown status") != 0);
        for (t = 0; t < s; ++t) CHECK(strcmp(text, segvoronoi_status_str(t)) != 0);
    }
    /* A build that cannot complete a valid diagram returns INTERNAL (with
       *out NULL and the message in segvoronoi_builder_last_error), never an
       invalid diagram; tests/fault_injection.rs gets there on purpose. */
    CHECK(strstr(segvoronoi_status_str(SEGVORONOI_STATUS_INTERNAL), "internal") != NULL);
    CHECK(strcmp(segvoronoi_status_str(SEGVORONOI_STATUS_INVALID_ARC + 1), "unknown status") == 0);
    CHECK(strcmp(segvoronoi_status_str(-1), "unknown status") == 0);
}

static void test_free_rules_and_nulls(void) {
    segvoronoi_diagram *diagram = (segvoronoi_diagram *)&diagram; /* must be overwritten */
    segvoronoi_site site = {.struct_size = sizeof(segvoronoi_site)};
    segvoronoi_vertex vertex = {.struct_size = sizeof(segvoronoi_vertex)};
    segvoronoi_edge edge = {.struct_size = sizeof(segvoronoi_edge)};
    segvoronoi_stats stats = {.struct_size = sizeof(segvoronoi_stats)};
    uint32_t id = 7, ids[4];
    size_t count = 0;
    char *text = (char *)&text;
    double xy[2] = {1.0, 2.0}, bezier[6];
    bool flag = false;
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
    CHECK_STATUS(segvoronoi_builder_check(NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK(diagram == NULL); /* *out is cleared on every error */
    CHECK(segvoronoi_diagram_site_count(NULL) == 0);
    CHECK(segvoronoi_diagram_vertex_count(NULL) == 0);
    CHECK(segvoronoi_diagram_edge_count(NULL) == 0);
    CHECK(segvoronoi_diagram_point_site_count(NULL) == 0);
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
    CHECK_STATUS(segvoronoi_diagram_segment_endpoints(NULL, 0, ids), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_segment_input_index(NULL, 0, &count), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_cell_neighbors(NULL, 0, ids, 4, &count), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_cell_is_unbounded(NULL, 0, &flag), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_edge_bezier(NULL, 0, bezier), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_extent(NULL, bezier), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_builder_last_error_indices(NULL, NULL, 0, &count), SEGVORONOI_STATUS_NULL_ARGUMENT);

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
    CHECK_STATUS(segvoronoi_diagram_segment_endpoints(diagram, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_segment_input_index(diagram, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_cell_neighbors(diagram, 0, ids, 4, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_cell_neighbors(diagram, 0, NULL, 4, &count), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_cell_is_unbounded(diagram, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_edge_bezier(diagram, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_extent(diagram, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    /* One point: no edges, and its cell is the whole plane. */
    CHECK_STATUS(segvoronoi_diagram_edge_bezier(diagram, 0, bezier), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_cell_is_unbounded(diagram, 0, &flag), SEGVORONOI_STATUS_OK);
    CHECK(flag);
    CHECK_STATUS(segvoronoi_diagram_extent(diagram, bezier), SEGVORONOI_STATUS_OK);
    CHECK(bezier[0] == 0.0);
    CHECK_STATUS(segvoronoi_builder_last_error_indices(builder, NULL, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_builder_last_error_indices(builder, NULL, 1, &count), SEGVORONOI_STATUS_NULL_ARGUMENT);

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
    segvoronoi_site site = {.struct_size = sizeof(segvoronoi_site)};
    segvoronoi_edge edge = {.struct_size = sizeof(segvoronoi_edge)};
    segvoronoi_stats stats = {.struct_size = sizeof(segvoronoi_stats)};
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
    segvoronoi_stats stats = {.struct_size = sizeof(segvoronoi_stats)};
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

    {
        double extent = 0.0;
        CHECK_STATUS(segvoronoi_diagram_extent(d, &extent), SEGVORONOI_STATUS_OK);
        CHECK(fabs(extent - 2.0 * sqrt(2.0)) < 1e-15);
    }

    /* Sites are numbered in order of first appearance. */
    CHECK_STATUS(segvoronoi_diagram_site_of_input(d, 4, &centre), SEGVORONOI_STATUS_OK);
    CHECK(centre == 4);
    for (i = 0; i < 4; ++i) {
        segvoronoi_vertex v = {.struct_size = sizeof(segvoronoi_vertex)};
        CHECK_STATUS(segvoronoi_diagram_vertex(d, i, &v), SEGVORONOI_STATUS_OK);
        CHECK(fabs(v.clearance - 1.0) < 1e-15);
        CHECK(v.sites[0] == centre || v.sites[1] == centre || v.sites[2] == centre);
    }
    CHECK_STATUS(segvoronoi_diagram_vertex(d, 4, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    {
        segvoronoi_vertex v = {.struct_size = sizeof(segvoronoi_vertex)};
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

/* Zero length is exact by default: four points 1e-12 from cocircular have
 * two Voronoi vertices 1e-12 apart, merged only with the tolerance flag. */
static void test_zero_length_is_exact(void) {
    const double xy[8] = {0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0 + 1e-12};
    segvoronoi_diagram *d = build_diagram(xy, 4);
    char *text = NULL;
    check_diagram(d);
    CHECK_STATUS(segvoronoi_diagram_topology(d, SEGVORONOI_TOPOLOGY_VORONOI_PAIRS, &text, NULL), SEGVORONOI_STATUS_OK);
    CHECK(text != NULL && strstr(text, "\nVPAIRS 5\n") != NULL && strstr(text, "\nVVERTICES 2\n") != NULL);
    segvoronoi_string_free(text);
    CHECK_STATUS(segvoronoi_diagram_topology(d, SEGVORONOI_TOPOLOGY_VORONOI_PAIRS | SEGVORONOI_TOPOLOGY_ZERO_LENGTH_TOLERANCE,
                                             &text, NULL),
                 SEGVORONOI_STATUS_OK);
    CHECK(text != NULL && strstr(text, "\nVPAIRS 4\n") != NULL && strstr(text, "\nVVERTICES 1\n") != NULL);
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

/* Whether `text` contains the number `k` as a whole word (not inside a
 * longer number): error messages name input indices. */
static int names_index(const char *text, size_t k) {
    char digits[32];
    const char *at = text;
    size_t len;
    snprintf(digits, sizeof digits, "%lu", (unsigned long)k);
    len = strlen(digits);
    while ((at = strstr(at, digits)) != NULL) {
        int before = at > text && at[-1] >= '0' && at[-1] <= '9';
        int after = at[len] >= '0' && at[len] <= '9';
        if (!before && !after) return 1;
        at += len;
    }
    return 0;
}

/* Builds the diagram of `np` points and `ns` segments ({x1, y1, x2, y2} each);
 * NULL (and a failed check) on error. */
static segvoronoi_diagram *build_with_segments(const double *xy, size_t np, const double *seg, size_t ns) {
    segvoronoi_builder *builder = segvoronoi_builder_new();
    segvoronoi_diagram *diagram = NULL;
    segvoronoi_status st;
    CHECK(builder != NULL);
    if (builder == NULL) return NULL;
    CHECK_STATUS(segvoronoi_builder_add_points(builder, xy, np), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_add_segments(builder, seg, ns), SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_builder_segment_count(builder) == ns);
    st = segvoronoi_builder_build(builder, &diagram);
    CHECK_STATUS(st, SEGVORONOI_STATUS_OK);
    if (st != SEGVORONOI_STATUS_OK) fprintf(stderr, "  build: %s\n", segvoronoi_builder_last_error(builder));
    segvoronoi_builder_free(builder);
    return diagram;
}

/* NULL rules, non-finite coordinates and the size limit for segments. */
static void test_segment_input_rules(void) {
    segvoronoi_builder *builder = segvoronoi_builder_new();
    segvoronoi_diagram *diagram = (segvoronoi_diagram *)&diagram;
    double good[8] = {0.0, 0.0, 1.0, 0.0, 2.0, 2.0, 3.0, 1.0};
    double bad[12] = {5.0, 5.0, 6.0, 5.0, 7.0, 7.0, 8.0, 7.0, 9.0, 9.0, 9.5, 9.0};
    uint32_t id = 7;
    CHECK(builder != NULL);
    if (builder == NULL) return;

    /* NULL handles and buffers. */
    CHECK_STATUS(segvoronoi_builder_add_segment(NULL, 0.0, 0.0, 1.0, 1.0), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_builder_add_segments(NULL, good, 1), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_builder_add_segments(builder, NULL, 1), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_builder_add_segments(builder, NULL, 0), SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_builder_segment_count(NULL) == 0);
    CHECK(segvoronoi_builder_segment_count(builder) == 0);
    CHECK(segvoronoi_diagram_point_site_count(NULL) == 0);
    CHECK_STATUS(segvoronoi_diagram_site_of_segment(NULL, 0, &id), SEGVORONOI_STATUS_NULL_ARGUMENT);

    CHECK_STATUS(segvoronoi_builder_add_segments(builder, good, 2), SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_builder_segment_count(builder) == 2);
    CHECK(segvoronoi_builder_point_count(builder) == 0);

    /* A NaN in the second of three: nothing added, the message names the
     * index that segment would have had (3), not the point counter. */
    bad[5] = NAN;
    CHECK_STATUS(segvoronoi_builder_add_segments(builder, bad, 3), SEGVORONOI_STATUS_INVALID_COORDINATE);
    CHECK(segvoronoi_builder_segment_count(builder) == 2);
    CHECK(strstr(segvoronoi_builder_last_error(builder), "segment") != NULL);
    CHECK(names_index(segvoronoi_builder_last_error(builder), 3));
    CHECK(!names_index(segvoronoi_builder_last_error(builder), 2));
    {
        size_t index = 0, n = 0;
        CHECK_STATUS(segvoronoi_builder_last_error_indices(builder, &index, 1, &n), SEGVORONOI_STATUS_OK);
        CHECK(n == 1 && index == 3);
    }
    bad[5] = 7.0;
    bad[10] = -INFINITY; /* the third */
    CHECK_STATUS(segvoronoi_builder_add_segments(builder, bad, 3), SEGVORONOI_STATUS_INVALID_COORDINATE);
    CHECK(names_index(segvoronoi_builder_last_error(builder), 4));
    CHECK(segvoronoi_builder_segment_count(builder) == 2);
    CHECK_STATUS(segvoronoi_builder_add_segment(builder, 0.0, INFINITY, 1.0, 1.0), SEGVORONOI_STATUS_INVALID_COORDINATE);
    CHECK(strstr(segvoronoi_builder_last_error(builder), "segment") != NULL);
    CHECK(names_index(segvoronoi_builder_last_error(builder), 2));
    CHECK_STATUS(segvoronoi_builder_add_segment(builder, 0.0, 0.0, NAN, 1.0), SEGVORONOI_STATUS_INVALID_COORDINATE);
    CHECK(segvoronoi_builder_segment_count(builder) == 2);

    /* Too many: refused before `xy` is read (only two segments' worth of
     * memory is behind the pointer). Each segment counts as two points
     * towards the 600 million: 300,000,001 segments are one too many. */
    CHECK_STATUS(segvoronoi_builder_add_segments(builder, good, SIZE_MAX / 8), SEGVORONOI_STATUS_TOO_LARGE);
    CHECK(strstr(segvoronoi_builder_last_error(builder), "at most") != NULL);
    CHECK_STATUS(segvoronoi_builder_add_segments(builder, good, (size_t)300000001), SEGVORONOI_STATUS_TOO_LARGE);
    CHECK(segvoronoi_builder_segment_count(builder) == 2);

    /* A successful call clears the message and the indices; the builder still builds. */
    CHECK_STATUS(segvoronoi_builder_add_segment(builder, 4.0, 0.0, 4.0, 1.0), SEGVORONOI_STATUS_OK);
    CHECK(strcmp(segvoronoi_builder_last_error(builder), "") == 0);
    {
        size_t n = 99;
        CHECK_STATUS(segvoronoi_builder_last_error_indices(builder, NULL, 0, &n), SEGVORONOI_STATUS_OK);
        CHECK(n == 0);
    }
    CHECK(segvoronoi_builder_segment_count(builder) == 3);
    CHECK_STATUS(segvoronoi_builder_build(builder, &diagram), SEGVORONOI_STATUS_OK);
    CHECK(diagram != NULL);
    if (diagram != NULL) {
        CHECK(segvoronoi_diagram_site_count(diagram) == 9); /* 6 endpoints, 3 open segments */
        CHECK(segvoronoi_diagram_point_site_count(diagram) == 6);
        CHECK_STATUS(segvoronoi_diagram_site_of_segment(diagram, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
        CHECK_STATUS(segvoronoi_diagram_site_of_segment(diagram, 3, &id), SEGVORONOI_STATUS_OUT_OF_RANGE);
        CHECK(id == 7);
        check_diagram(diagram);
        segvoronoi_diagram_free(diagram);
    }
    segvoronoi_builder_free(builder);
}

/* Builds and expects INTERSECTING naming both indices; *out cleared, the
 * builder unchanged (its counts, and a later successful build after it). */
static void expect_intersecting(const double *xy, size_t np, const double *seg, size_t ns, size_t first,
                                size_t second) {
    segvoronoi_builder *builder = segvoronoi_builder_new();
    segvoronoi_diagram *diagram = (segvoronoi_diagram *)&diagram;
    const char *message;
    CHECK(builder != NULL);
    if (builder == NULL) return;
    CHECK_STATUS(segvoronoi_builder_add_points(builder, xy, np), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_add_segments(builder, seg, ns), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(builder, &diagram), SEGVORONOI_STATUS_INTERSECTING);
    CHECK(diagram == NULL);
    message = segvoronoi_builder_last_error(builder);
    CHECK(message[0] != '\0');
    CHECK(names_index(message, first) && names_index(message, second));
    if (!(names_index(message, first) && names_index(message, second))) {
        fprintf(stderr, "  message '%s' should name %lu and %lu\n", message, (unsigned long)first,
                (unsigned long)second);
    }
    {
        /* The same indices as numbers: (NULL, 0) counts, a short buffer gets the first. */
        size_t indices[2] = {SIZE_MAX, SIZE_MAX}, n = 0;
        CHECK_STATUS(segvoronoi_builder_last_error_indices(builder, NULL, 0, &n), SEGVORONOI_STATUS_OK);
        CHECK(n == 2);
        CHECK_STATUS(segvoronoi_builder_last_error_indices(builder, indices, 1, &n), SEGVORONOI_STATUS_BUFFER_TOO_SMALL);
        CHECK(n == 2 && indices[1] == SIZE_MAX);
        CHECK_STATUS(segvoronoi_builder_last_error_indices(builder, indices, 2, &n), SEGVORONOI_STATUS_OK);
        CHECK(n == 2);
        CHECK((indices[0] == first && indices[1] == second) || (indices[0] == second && indices[1] == first));
    }
    CHECK(segvoronoi_builder_point_count(builder) == np && segvoronoi_builder_segment_count(builder) == ns);
    {
        /* The check alone gives the same status, message and indices. */
        char built[256];
        size_t indices[2] = {SIZE_MAX, SIZE_MAX}, n = 0;
        snprintf(built, sizeof built, "%s", segvoronoi_builder_last_error(builder));
        CHECK_STATUS(segvoronoi_builder_check(builder), SEGVORONOI_STATUS_INTERSECTING);
        CHECK(strcmp(segvoronoi_builder_last_error(builder), built) == 0);
        CHECK_STATUS(segvoronoi_builder_last_error_indices(builder, indices, 2, &n), SEGVORONOI_STATUS_OK);
        CHECK(n == 2);
        CHECK((indices[0] == first && indices[1] == second) || (indices[0] == second && indices[1] == first));
    }
    /* Same again: the builder kept its input. */
    CHECK_STATUS(segvoronoi_builder_build(builder, &diagram), SEGVORONOI_STATUS_INTERSECTING);
    segvoronoi_builder_free(builder);
}

static void test_intersecting_segments(void) {
    /* Segments 1 and 3 cross; 0 and 2 are far away. */
    const double crossing[16] = {10, 10, 11, 10, 0, 0, 2, 2, 20, 0, 21, 1, 0, 2, 2, 0};
    /* T-junction: an endpoint of segment 2 inside segment 0 (no error:
     * segment 0 is split there, exactly). */
    const double tee[12] = {0, 0, 4, 0, -5, -5, -4, -5, 2, 0, 2, 3};
    /* Collinear overlap of segments 0 and 1. */
    const double overlap[8] = {0, 0, 2, 0, 1, 0, 3, 0};
    /* Point 3 inside segment 1 (split there too; point 0 equals an endpoint). */
    const double points[8] = {0, 0, 9, 9, 8, 9, 2, 0};
    const double lines[8] = {5, 5, 6, 6, 0, 0, 4, 0};
    expect_intersecting(NULL, 0, crossing, 4, 1, 3);
    expect_intersecting(NULL, 0, overlap, 2, 0, 1);
    {
        /* Touching input builds: one cut each, one more piece. */
        const double *inputs[2][2] = {{NULL, tee}, {points, lines}};
        const size_t counts[2][2] = {{0, 3}, {4, 2}};
        int k;
        for (k = 0; k < 2; ++k) {
            segvoronoi_builder *builder = segvoronoi_builder_new();
            segvoronoi_diagram *diagram = NULL;
            segvoronoi_stats stats = {.struct_size = sizeof stats};
            CHECK_STATUS(segvoronoi_builder_add_points(builder, inputs[k][0], counts[k][0]), SEGVORONOI_STATUS_OK);
            CHECK_STATUS(segvoronoi_builder_add_segments(builder, inputs[k][1], counts[k][1]), SEGVORONOI_STATUS_OK);
            CHECK_STATUS(segvoronoi_builder_check(builder), SEGVORONOI_STATUS_OK);
            CHECK_STATUS(segvoronoi_builder_build(builder, &diagram), SEGVORONOI_STATUS_OK);
            CHECK_STATUS(segvoronoi_diagram_validate(diagram), SEGVORONOI_STATUS_OK);
            CHECK_STATUS(segvoronoi_diagram_stats(diagram, &stats), SEGVORONOI_STATUS_OK);
            CHECK(stats.split_at_vertices == 1 && stats.pieces == counts[k][1] + 1);
            CHECK(segvoronoi_diagram_piece_count(diagram) == counts[k][1] + 1);
            segvoronoi_diagram_free(diagram);
            segvoronoi_builder_free(builder);
        }
    }
    {
        /* A star and a path sharing endpoints: the check passes and clears
         * the last error; the builder still builds. */
        const double fine[16] = {0, 0, 1, 0, 0, 0, 0, 1, -1, -1, 0, 0, 1, 0, 1, 1};
        segvoronoi_builder *builder = segvoronoi_builder_new();
        segvoronoi_diagram *diagram = NULL;
        CHECK(builder != NULL);
        if (builder == NULL) return;
        CHECK_STATUS(segvoronoi_builder_check(builder), SEGVORONOI_STATUS_OK); /* empty */
        CHECK_STATUS(segvoronoi_builder_add_segments(builder, fine, 4), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_builder_add_point(builder, NAN, 0.0), SEGVORONOI_STATUS_INVALID_COORDINATE);
        CHECK_STATUS(segvoronoi_builder_check(builder), SEGVORONOI_STATUS_OK);
        CHECK(segvoronoi_builder_last_error(builder)[0] == '\0');
        CHECK_STATUS(segvoronoi_builder_build(builder, &diagram), SEGVORONOI_STATUS_OK);
        segvoronoi_diagram_free(diagram);
        segvoronoi_builder_free(builder);
    }
}

/* One segment, points around it, a repeated segment (reversed), a
 * zero-length segment and a repeated point: sites, kinds, site_of_segment,
 * stats and the S<j> names. */
static void test_segment_sites_and_stats(void) {
    const double points[6] = {1.0, 2.0, 3.0, -1.5, 1.0, 2.0};
    const double segs[12] = {0.0, 0.0, 4.0, 0.0, 4.0, 0.0, 0.0, 0.0, 7.0, 7.0, 7.0, 7.0};
    segvoronoi_diagram *d = build_with_segments(points, 3, segs, 3);
    segvoronoi_stats stats = {.struct_size = sizeof(segvoronoi_stats)};
    segvoronoi_site site = {.struct_size = sizeof(segvoronoi_site)};
    uint32_t s0 = 99, s1 = 99, s2 = 99, p = 99;
    char *text = NULL;
    size_t length = 0;
    CHECK(d != NULL);
    if (d == NULL) return;
    check_diagram(d);
    /* Points (1,2), (3,-1.5), endpoints (0,0), (4,0), the point (7,7); S0. */
    CHECK(segvoronoi_diagram_site_count(d) == 6);
    CHECK(segvoronoi_diagram_point_site_count(d) == 5);
    CHECK_STATUS(segvoronoi_diagram_site_of_segment(d, 0, &s0), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_diagram_site_of_segment(d, 1, &s1), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_diagram_site_of_segment(d, 2, &s2), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_diagram_site_of_segment(d, 3, &p), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK(s0 == 5 && s1 == s0); /* the repeat shares the first one's site */
    CHECK_STATUS(segvoronoi_diagram_site(d, s0, &site), SEGVORONOI_STATUS_OK);
    CHECK(site.kind == SEGVORONOI_SITE_SEGMENT && site.x == 0.0 && site.y == 0.0 && site.x2 == 4.0 && site.y2 == 0.0);
    CHECK(s2 < 5); /* zero length: a point site */
    CHECK_STATUS(segvoronoi_diagram_site(d, s2, &site), SEGVORONOI_STATUS_OK);
    CHECK(site.kind == SEGVORONOI_SITE_POINT && site.x == 7.0 && site.y == 7.0 && site.x2 == 7.0 && site.y2 == 7.0);
    /* Points are named in the order isolated points, then endpoints. */
    CHECK_STATUS(segvoronoi_diagram_site_of_input(d, 2, &p), SEGVORONOI_STATUS_OK);
    CHECK(p == 0);
    CHECK_STATUS(segvoronoi_diagram_site_of_input(d, 3, &p), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_site(d, 2, &site), SEGVORONOI_STATUS_OK);
    CHECK(site.kind == SEGVORONOI_SITE_POINT && site.x == 0.0 && site.y == 0.0);
    CHECK_STATUS(segvoronoi_diagram_site(d, 3, &site), SEGVORONOI_STATUS_OK);
    CHECK(site.kind == SEGVORONOI_SITE_POINT && site.x == 4.0 && site.y == 0.0);

    CHECK_STATUS(segvoronoi_diagram_stats(d, &stats), SEGVORONOI_STATUS_OK);
    CHECK(stats.input_points == 3 && stats.input_segments == 3 && stats.sites == 6);
    CHECK(stats.duplicate_points == 1 && stats.duplicate_segments == 1 && stats.zero_length_segments == 1);
    CHECK(stats.vertices == segvoronoi_diagram_vertex_count(d) && stats.edges == segvoronoi_diagram_edge_count(d));

    /* Nearest site: just above the middle of the segment, and at an end. */
    CHECK_STATUS(segvoronoi_diagram_nearest_site(d, 2.0, 0.1, SEGVORONOI_NO_SITE, &p), SEGVORONOI_STATUS_OK);
    CHECK(p == s0);
    CHECK_STATUS(segvoronoi_diagram_nearest_site(d, 4.5, -0.1, 0, &p), SEGVORONOI_STATUS_OK);
    CHECK(p == 3);

    /* Topology: S0 borders its endpoints P2 and P3 (the separators); the
     * repeat and the zero-length segment have no name of their own. */
    CHECK_STATUS(segvoronoi_diagram_topology(d, SEGVORONOI_TOPOLOGY_VORONOI_PAIRS, &text, &length),
                 SEGVORONOI_STATUS_OK);
    CHECK(text != NULL && strlen(text) == length);
    CHECK(text != NULL && strstr(text, "\nP2 S0\n") != NULL && strstr(text, "\nP3 S0\n") != NULL);
    CHECK(text != NULL && strstr(text, "S1") == NULL && strstr(text, "S2") == NULL);
    segvoronoi_string_free(text);
    segvoronoi_diagram_free(d);
}

/* Shapes with shared endpoints and a few disjoint segments: every diagram
 * passes check_diagram (empty circles measured to closed segments). */
static void test_segment_shapes(void) {
    /* A square with its centre point. */
    const double square[16] = {0, 0, 2, 0, 2, 0, 2, 2, 2, 2, 0, 2, 0, 2, 0, 0};
    const double centre[2] = {1.0, 0.7};
    /* A square with a rotated, off-centre square hole. */
    double holed[32];
    /* A regular 12-gon. */
    double gon[48];
    /* An open polyline (a zigzag) and two isolated points. */
    const double zigzag[16] = {0, 0, 1, 1, 1, 1, 2, 0, 2, 0, 3, 1.5, 3, 1.5, 4, 0.2};
    const double around[4] = {2.0, 1.5, 1.0, -1.0};
    /* Four disjoint segments, all on one line, and a point off the line. */
    const double ladder[16] = {0, 0, 1, 1, 2, 2, 3, 3, 5, 5, 4, 4, 7, 7, 8, 8};
    const double off[2] = {0.0, 5.0};
    /* Four disjoint segments in general position. */
    const double loose[16] = {0.5665615751722809, 0.74578175726270113, 0.97100275358679622, 0.44435921705577208,
                              0.28550868439696664, 0.79399660566230557, 0.40414216905022571, 0.60542036897532914,
                              0.45493790747028962, 0.53007899750158893, 0.43596539982472504, 0.16703498914055104,
                              0.64533464021950604, 0.81535058336809974, 0.68170497338058855, 0.88432456353978983};
    segvoronoi_diagram *d;
    size_t k;
    char *text = NULL;

    d = build_with_segments(centre, 1, square, 4);
    if (d != NULL) {
        check_diagram(d);
        CHECK(segvoronoi_diagram_site_count(d) == 9 && segvoronoi_diagram_point_site_count(d) == 5);
        segvoronoi_diagram_free(d);
    }

    for (k = 0; k < 4; ++k) {
        const double outer[8] = {0, 0, 10, 0, 10, 10, 0, 10};
        double angle = 0.3 + 1.5707963267948966 * (double)k, next = angle + 1.5707963267948966;
        holed[4 * k] = outer[2 * k];
        holed[4 * k + 1] = outer[2 * k + 1];
        holed[4 * k + 2] = outer[(2 * k + 2) % 8];
        holed[4 * k + 3] = outer[(2 * k + 3) % 8];
        holed[16 + 4 * k] = 4.3 + 2.0 * cos(angle);
        holed[16 + 4 * k + 1] = 5.7 + 2.0 * sin(angle);
        holed[16 + 4 * k + 2] = 4.3 + 2.0 * cos(next);
        holed[16 + 4 * k + 3] = 5.7 + 2.0 * sin(next);
    }
    /* Close the inner square exactly: the last side ends where the first begins. */
    holed[30] = holed[16];
    holed[31] = holed[17];
    d = build_with_segments(NULL, 0, holed, 8);
    if (d != NULL) {
        check_diagram(d);
        CHECK(segvoronoi_diagram_site_count(d) == 16);
        segvoronoi_diagram_free(d);
    }

    for (k = 0; k < 12; ++k) {
        double a = 6.283185307179586 * (double)k / 12.0;
        gon[4 * k] = cos(a);
        gon[4 * k + 1] = sin(a);
    }
    for (k = 0; k < 12; ++k) {
        gon[4 * k + 2] = gon[4 * ((k + 1) % 12)];
        gon[4 * k + 3] = gon[4 * ((k + 1) % 12) + 1];
    }
    d = build_with_segments(NULL, 0, gon, 12);
    if (d != NULL) {
        check_diagram(d);
        CHECK(segvoronoi_diagram_site_count(d) == 24);
        /* Every side touches the inscribed circle up to rounding (cos and
         * sin are rounded, so exactly the centre is several vertices a few
         * ulps apart): with the tolerance, one merged vertex of all twelve
         * segments at the centre. */
        CHECK_STATUS(segvoronoi_diagram_topology(
                         d, SEGVORONOI_TOPOLOGY_VORONOI_PAIRS | SEGVORONOI_TOPOLOGY_ZERO_LENGTH_TOLERANCE, &text, NULL),
                     SEGVORONOI_STATUS_OK);
        CHECK(text != NULL && strstr(text, "\nS0 S1 S2 S3 S4 S5 S6 S7 S8 S9 S10 S11\n") != NULL);
        segvoronoi_string_free(text);
        segvoronoi_diagram_free(d);
    }

    d = build_with_segments(around, 2, zigzag, 4);
    if (d != NULL) {
        check_diagram(d);
        CHECK(segvoronoi_diagram_site_count(d) == 11);
        segvoronoi_diagram_free(d);
    }

    d = build_with_segments(NULL, 0, ladder, 4);
    if (d != NULL) {
        check_diagram(d);
        CHECK(segvoronoi_diagram_vertex_count(d) == 0 && segvoronoi_diagram_site_count(d) == 12);
        segvoronoi_diagram_free(d);
    }
    d = build_with_segments(off, 1, ladder, 4);
    if (d != NULL) {
        check_diagram(d);
        segvoronoi_diagram_free(d);
    }

    d = build_with_segments(NULL, 0, loose, 4);
    if (d != NULL) {
        check_diagram(d);
        CHECK(segvoronoi_diagram_site_count(d) == 12);
        segvoronoi_diagram_free(d);
    }
}

/* Edge geometry: a point above a segment's middle gives parabolic arcs; a
 * polyline of one follows the buffer rules and stays equidistant from its
 * two sites; straight edges have two points. */
static void test_edge_geometry(void) {
    const double seg[4] = {0.0, 0.0, 4.0, 0.0};
    segvoronoi_builder *builder = segvoronoi_builder_new();
    segvoronoi_diagram *d = NULL;
    size_t e, parabolas = 0, lines = 0;
    CHECK(builder != NULL);
    if (builder == NULL) return;
    CHECK_STATUS(segvoronoi_builder_add_segments(builder, seg, 1), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_add_point(builder, 2.0, 2.0), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_add_point(builder, 1.0, -3.0), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(builder, &d), SEGVORONOI_STATUS_OK);
    segvoronoi_builder_free(builder);
    if (d == NULL) return;
    for (e = 0; e < segvoronoi_diagram_edge_count(d); ++e) {
        segvoronoi_edge_shape shape = {.struct_size = sizeof(segvoronoi_edge_shape)};
        segvoronoi_edge edge = {.struct_size = sizeof(segvoronoi_edge)};
        size_t needed = 0, got = 0, k;
        double *xy, bezier[6] = {0};
        CHECK_STATUS(segvoronoi_diagram_edge_shape(d, e, &shape), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_diagram_edge(d, e, &edge), SEGVORONOI_STATUS_OK);
        if (edge.is_infinite) {
            CHECK_STATUS(segvoronoi_diagram_edge_polyline(d, e, 1e-3, NULL, 0, &needed),
                         SEGVORONOI_STATUS_INVALID_ARGUMENT);
            CHECK_STATUS(segvoronoi_diagram_edge_bezier(d, e, bezier), SEGVORONOI_STATUS_INVALID_ARGUMENT);
            continue;
        }
        CHECK_STATUS(segvoronoi_diagram_edge_polyline(d, e, 0.0, NULL, 0, &needed), SEGVORONOI_STATUS_INVALID_ARGUMENT);
        CHECK_STATUS(segvoronoi_diagram_edge_polyline(d, e, 1e-3, NULL, 1, &needed), SEGVORONOI_STATUS_NULL_ARGUMENT);
        CHECK_STATUS(segvoronoi_diagram_edge_polyline(d, e, 1e-3, NULL, 0, &needed), SEGVORONOI_STATUS_OK);
        xy = (double *)malloc(2 * (needed + 1) * sizeof *xy);
        CHECK(xy != NULL);
        if (xy == NULL) continue;
        CHECK_STATUS(segvoronoi_diagram_edge_polyline(d, e, 1e-3, xy, needed + 1, &got), SEGVORONOI_STATUS_OK);
        CHECK(got == needed && got >= 2);
        CHECK(xy[0] == edge.ends[0].x && xy[1] == edge.ends[0].y);
        CHECK(xy[2 * (got - 1)] == edge.ends[1].x && xy[2 * got - 1] == edge.ends[1].y);
        if (shape.kind == SEGVORONOI_EDGE_PARABOLA) {
            ++parabolas;
            /* The Bézier runs from end to end, through points equidistant
             * from the focus and the directrix (the x axis). */
            CHECK_STATUS(segvoronoi_diagram_edge_bezier(d, e, bezier), SEGVORONOI_STATUS_OK);
            CHECK(bezier[0] == edge.ends[0].x && bezier[1] == edge.ends[0].y);
            CHECK(bezier[4] == edge.ends[1].x && bezier[5] == edge.ends[1].y);
            for (k = 1; k < 4; ++k) {
                double u = 0.25 * (double)k, a = (1 - u) * (1 - u), b = 2 * u * (1 - u), c = u * u;
                double bx = a * bezier[0] + b * bezier[2] + c * bezier[4];
                double by = a * bezier[1] + b * bezier[3] + c * bezier[5];
                CHECK(fabs(hypot(bx - shape.focus_x, by - shape.focus_y) - fabs(by)) < 1e-9);
            }
            for (k = 0; k < got; ++k) { /* focus and directrix (the x axis here) equidistant */
                double to_focus = hypot(xy[2 * k] - shape.focus_x, xy[2 * k + 1] - shape.focus_y);
                CHECK(fabs(to_focus - fabs(xy[2 * k + 1])) < 1e-9);
            }
        } else {
            CHECK(shape.kind == SEGVORONOI_EDGE_LINE);
            CHECK(got == 2);
            CHECK_STATUS(segvoronoi_diagram_edge_bezier(d, e, bezier), SEGVORONOI_STATUS_INVALID_ARGUMENT);
            ++lines;
        }
        free(xy);
    }
    CHECK(parabolas >= 2 && lines >= 1);
    {
        segvoronoi_edge_shape shape = {.struct_size = sizeof(segvoronoi_edge_shape)};
        size_t n = 0;
        double bezier[6];
        CHECK_STATUS(segvoronoi_diagram_edge_shape(NULL, 0, &shape), SEGVORONOI_STATUS_NULL_ARGUMENT);
        CHECK_STATUS(segvoronoi_diagram_edge_shape(d, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
        CHECK_STATUS(segvoronoi_diagram_edge_shape(d, 1000, &shape), SEGVORONOI_STATUS_OUT_OF_RANGE);
        CHECK_STATUS(segvoronoi_diagram_edge_polyline(d, 1000, 1e-3, NULL, 0, &n), SEGVORONOI_STATUS_OUT_OF_RANGE);
        CHECK_STATUS(segvoronoi_diagram_edge_polyline(d, 0, 1e-3, NULL, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
        CHECK_STATUS(segvoronoi_diagram_edge_bezier(d, 1000, bezier), SEGVORONOI_STATUS_OUT_OF_RANGE);
    }
    segvoronoi_diagram_free(d);
}

/* The medial axis of a diagram with a domain: its pieces are exactly the
 * inside edges that are not separators, consecutive pieces meet, and every
 * sampled point has a clearance between 0 and the largest disk's radius. */
static void check_medial_axis(const segvoronoi_diagram *d, double max_r) {
    segvoronoi_medial_axis *axis = NULL;
    size_t chains, c, k, pieces_total = 0, inside_edges = 0, e;
    CHECK_STATUS(segvoronoi_diagram_medial_axis(d, &axis), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_diagram_medial_axis(d, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    chains = segvoronoi_medial_axis_chain_count(axis);
    CHECK(chains > 0);
    for (e = 0; e < segvoronoi_diagram_edge_count(d); ++e) {
        segvoronoi_edge edge = {.struct_size = sizeof edge};
        uint32_t at = 99;
        CHECK_STATUS(segvoronoi_diagram_edge(d, e, &edge), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_diagram_edge_location(d, e, &at), SEGVORONOI_STATUS_OK);
        if (at == SEGVORONOI_LOCATION_INSIDE && !edge.is_separator) ++inside_edges;
    }
    for (c = 0; c < chains; ++c) {
        size_t n = 0, points = 0, needed = 0;
        bool closed = false;
        double *xyr;
        segvoronoi_piece previous = {.struct_size = sizeof previous};
        CHECK_STATUS(segvoronoi_medial_axis_chain(axis, c, &n, &closed), SEGVORONOI_STATUS_OK);
        CHECK(n > 0);
        for (k = 0; k < n; ++k) {
            segvoronoi_piece p = {.struct_size = sizeof p};
            CHECK_STATUS(segvoronoi_medial_axis_piece(axis, c, k, &p), SEGVORONOI_STATUS_OK);
            CHECK(p.struct_size == sizeof p);
            if (k > 0) CHECK(previous.ends[1].vertex == p.ends[0].vertex);
            { /* its sites are its edge's, in the chain's direction */
                segvoronoi_edge edge = {.struct_size = sizeof edge};
                CHECK_STATUS(segvoronoi_diagram_edge(d, p.edge, &edge), SEGVORONOI_STATUS_OK);
                CHECK(p.sites[0] == edge.sites[p.reversed] && p.sites[1] == edge.sites[!p.reversed]);
            }
            { /* the ends of the piece at t = 0 and 1, its clearance in between */
                double at0[3], at1[3], mid[3];
                CHECK_STATUS(segvoronoi_medial_axis_piece_at(axis, c, k, 0.0, at0), SEGVORONOI_STATUS_OK);
                CHECK_STATUS(segvoronoi_medial_axis_piece_at(axis, c, k, 1.0, at1), SEGVORONOI_STATUS_OK);
                CHECK_STATUS(segvoronoi_medial_axis_piece_at(axis, c, k, 0.5, mid), SEGVORONOI_STATUS_OK);
                CHECK(at0[0] == p.ends[0].x && at0[1] == p.ends[0].y && at1[0] == p.ends[1].x && at1[1] == p.ends[1].y);
                CHECK(fabs(at0[2] - p.clearance[0]) < 1e-12 && fabs(at1[2] - p.clearance[1]) < 1e-12);
                CHECK(mid[2] >= 0.0 && mid[2] <= max_r + 1e-12);
                CHECK_STATUS(segvoronoi_medial_axis_piece_at(axis, c, k, 1.5, mid), SEGVORONOI_STATUS_INVALID_ARGUMENT);
            }
            previous = p;
        }
        pieces_total += n;
        CHECK_STATUS(segvoronoi_medial_axis_sample_chain(axis, c, 1e-3, NULL, 0, &needed), SEGVORONOI_STATUS_OK);
        CHECK(needed >= n + 1);
        xyr = malloc(3 * needed * sizeof *xyr);
        CHECK(xyr != NULL);
        CHECK_STATUS(segvoronoi_medial_axis_sample_chain(axis, c, 1e-3, xyr, needed, &points), SEGVORONOI_STATUS_OK);
        for (k = 0; k < points; ++k) CHECK(xyr[3 * k + 2] >= 0.0 && xyr[3 * k + 2] <= max_r + 1e-12);
        CHECK_STATUS(segvoronoi_medial_axis_sample_chain(axis, c, 0.0, xyr, needed, &points),
                     SEGVORONOI_STATUS_INVALID_ARGUMENT);
        free(xyr);
    }
    CHECK(pieces_total == inside_edges);
    CHECK_STATUS(segvoronoi_medial_axis_chain(axis, chains, &k, &(bool){false}), SEGVORONOI_STATUS_OUT_OF_RANGE);
    segvoronoi_medial_axis_free(axis);
    segvoronoi_medial_axis_free(NULL);
}

/* The filters on the medial axis of the square with a square hole: a zeroed
 * filter (and NULL) leaves the whole axis; the corner filter at 80 degrees
 * takes the four branches into the outer square's right-angled corners,
 * nothing else; a NaN or a struct_size below the first version is refused. */
static void check_medial_axis_filters(const segvoronoi_diagram *d) {
    segvoronoi_medial_axis *full = NULL, *same = NULL, *cut = NULL, *untouched = NULL;
    segvoronoi_medial_axis_filter filter = {.struct_size = sizeof filter};
    size_t c, n, pieces[3] = {0, 0, 0};
    bool closed = false;
    CHECK_STATUS(segvoronoi_diagram_medial_axis_filtered(d, NULL, &full), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_diagram_medial_axis_filtered(d, &filter, &same), SEGVORONOI_STATUS_OK);
    filter.corner_filter = true;
    filter.corner_angle = 80.0;
    CHECK_STATUS(segvoronoi_diagram_medial_axis_filtered(d, &filter, &cut), SEGVORONOI_STATUS_OK);
    for (c = 0; c < segvoronoi_medial_axis_chain_count(full); ++c) {
        CHECK_STATUS(segvoronoi_medial_axis_chain(full, c, &n, &closed), SEGVORONOI_STATUS_OK);
        pieces[0] += n;
    }
    for (c = 0; c < segvoronoi_medial_axis_chain_count(same); ++c) {
        CHECK_STATUS(segvoronoi_medial_axis_chain(same, c, &n, &closed), SEGVORONOI_STATUS_OK);
        pieces[1] += n;
    }
    for (c = 0; c < segvoronoi_medial_axis_chain_count(cut); ++c) {
        CHECK_STATUS(segvoronoi_medial_axis_chain(cut, c, &n, &closed), SEGVORONOI_STATUS_OK);
        pieces[2] += n;
    }
    CHECK(pieces[0] == pieces[1] && pieces[2] == pieces[0] - 4);
    /* what is left is the cycle around the hole */
    CHECK(segvoronoi_medial_axis_chain_count(cut) == 1);
    CHECK_STATUS(segvoronoi_medial_axis_chain(cut, 0, &n, &closed), SEGVORONOI_STATUS_OK);
    CHECK(closed);
    filter.spur_filter = true;
    filter.spur_factor = NAN;
    CHECK_STATUS(segvoronoi_diagram_medial_axis_filtered(d, &filter, &untouched), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    filter.spur_factor = 1.0;
    filter.struct_size = sizeof(size_t);
    CHECK_STATUS(segvoronoi_diagram_medial_axis_filtered(d, &filter, &untouched), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    CHECK(untouched == NULL);
    CHECK_STATUS(segvoronoi_diagram_medial_axis_filtered(d, NULL, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    segvoronoi_medial_axis_free(full);
    segvoronoi_medial_axis_free(same);
    segvoronoi_medial_axis_free(cut);
}

/* Polygons and the domain: a square with a square hole, both rings in either
 * orientation; locations of points, vertices and cells; the largest disk;
 * the input rules (a ring of two points names polygon and ring, leaves the
 * builder unchanged); no polygon, no domain. */
static void test_polygon_domain(void) {
    const double xy[] = {0, 0, 10, 0, 10, 10, 0, 10, /* outer, counter-clockwise */
                         4, 4, 4, 6, 6, 6, 6, 4};    /* hole, clockwise */
    const size_t lengths[] = {4, 4};
    const double bad[] = {0, 0, 1, 1, 1, 1};
    const size_t bad_length = 3;
    const double line[] = {20, 20, 21, 20, 21, 20, 21, 21}; /* one repeated point */
    segvoronoi_builder *b = segvoronoi_builder_new();
    segvoronoi_diagram *d = NULL;
    uint32_t where = 99;
    size_t i, indices[4] = {0}, n_indices = 0, inside = 0;
    double x = 0, y = 0, r = 0;

    CHECK(b != NULL);
    CHECK_STATUS(segvoronoi_builder_add_polygon(b, xy, lengths, 2), SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_builder_segment_count(b) == 8);
    CHECK_STATUS(segvoronoi_builder_add_polygon(b, bad, &bad_length, 1), SEGVORONOI_STATUS_INVALID_POLYGON);
    CHECK_STATUS(segvoronoi_builder_last_error_indices(b, indices, 4, &n_indices), SEGVORONOI_STATUS_OK);
    CHECK(n_indices == 2 && indices[0] == 1 && indices[1] == 0); /* polygon 1, ring 0 */
    CHECK(segvoronoi_builder_segment_count(b) == 8);
    CHECK_STATUS(segvoronoi_builder_add_polygon(b, NULL, lengths, 2), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_builder_add_polyline(b, line, 4), SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_builder_segment_count(b) == 10);
    CHECK_STATUS(segvoronoi_builder_build(b, &d), SEGVORONOI_STATUS_OK);
    check_diagram(d);
    CHECK(segvoronoi_diagram_has_domain(d));
    CHECK_STATUS(segvoronoi_diagram_locate_point(d, 1, 1, &where), SEGVORONOI_STATUS_OK);
    CHECK(where == SEGVORONOI_LOCATION_INSIDE);
    CHECK_STATUS(segvoronoi_diagram_locate_point(d, 5, 5, &where), SEGVORONOI_STATUS_OK);
    CHECK(where == SEGVORONOI_LOCATION_OUTSIDE);
    CHECK_STATUS(segvoronoi_diagram_locate_point(d, 10, 3, &where), SEGVORONOI_STATUS_OK);
    CHECK(where == SEGVORONOI_LOCATION_BOUNDARY);
    for (i = 0; i < segvoronoi_diagram_vertex_count(d); ++i) {
        segvoronoi_vertex v = {.struct_size = sizeof v};
        uint32_t at = 99;
        CHECK_STATUS(segvoronoi_diagram_vertex(d, i, &v), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_diagram_vertex_location(d, i, &at), SEGVORONOI_STATUS_OK);
        if (at == SEGVORONOI_LOCATION_INSIDE) {
            ++inside;
            /* strictly inside the ring between the squares */
            CHECK(v.x > 0 && v.x < 10 && v.y > 0 && v.y < 10 && !(v.x > 4 && v.x < 6 && v.y > 4 && v.y < 6));
        }
    }
    CHECK(inside > 0);
    CHECK_STATUS(segvoronoi_diagram_vertex_location(d, segvoronoi_diagram_vertex_count(d), &where),
                 SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_edge_location(d, 0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    /* the polyline's first point (20, 20), site 8 after the rings' eight
       corners, is an obstacle outside */
    CHECK_STATUS(segvoronoi_diagram_cell_location(d, 8, &where), SEGVORONOI_STATUS_OK);
    CHECK(where == SEGVORONOI_LOCATION_OUTSIDE);
    CHECK_STATUS(segvoronoi_diagram_max_inscribed_circle(d, &x, &y, &r), SEGVORONOI_STATUS_OK);
    /* at a corner of the ring between the squares: (t, t) as far from the
       outer sides as from the hole's corner (4, 4), t = 8 - 4 sqrt 2 */
    CHECK(fabs(r - (8.0 - 4.0 * sqrt(2.0))) < 1e-12);
    CHECK(fabs(fmin(fmin(x, y), fmin(10 - x, 10 - y)) - r) < 1e-12); /* r from the outer square */
    check_medial_axis(d, r);
    check_medial_axis_filters(d);
    {
        segvoronoi_stats stats = {.struct_size = sizeof stats};
        double circles[6] = {0};
        size_t n_circles = 0;
        CHECK_STATUS(segvoronoi_diagram_stats(d, &stats), SEGVORONOI_STATUS_OK);
        CHECK(stats.dropped_chain_points == 1);
        /* one component: its disk is the largest one */
        CHECK_STATUS(segvoronoi_diagram_inscribed_circles(d, NULL, 0, &n_circles), SEGVORONOI_STATUS_OK);
        CHECK(n_circles == 1);
        CHECK_STATUS(segvoronoi_diagram_inscribed_circles(d, circles, 2, &n_circles), SEGVORONOI_STATUS_OK);
        CHECK(circles[0] == x && circles[1] == y && circles[2] == r);
        CHECK_STATUS(segvoronoi_diagram_inscribed_circles(d, NULL, 2, &n_circles), SEGVORONOI_STATUS_NULL_ARGUMENT);
    }
    segvoronoi_diagram_free(d);
    segvoronoi_builder_free(b);

    b = segvoronoi_builder_new();
    CHECK_STATUS(segvoronoi_builder_add_point(b, 1, 2), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_add_point(b, 3, 1), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(b, &d), SEGVORONOI_STATUS_OK);
    CHECK(!segvoronoi_diagram_has_domain(d));
    CHECK_STATUS(segvoronoi_diagram_locate_point(d, 1, 1, &where), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_max_inscribed_circle(d, &x, &y, &r), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    segvoronoi_diagram_free(d);
    segvoronoi_builder_free(b);
}

/* The versioned structs: a struct_size below the first version is refused
 * with nothing written; a larger one (a caller from a newer header) gets the
 * fields this library has, with struct_size saying how many bytes those are,
 * and the bytes beyond untouched. */
static void test_versioned_structs(void) {
    const double xy[8] = {0.0, 0.0, 2.0, 0.0, 1.0, 2.0, 1.0, 0.7};
    segvoronoi_diagram *d = build_diagram(xy, 4);
    struct {
        segvoronoi_vertex v;
        unsigned char later_fields[24];
    } newer;
    segvoronoi_vertex v = {.struct_size = sizeof(segvoronoi_vertex)};
    segvoronoi_site site = {.struct_size = sizeof(segvoronoi_site)};
    segvoronoi_edge edge = {.struct_size = sizeof(segvoronoi_edge)};
    segvoronoi_stats stats = {.struct_size = sizeof(segvoronoi_stats)};
    segvoronoi_edge_shape shape = {.struct_size = sizeof(segvoronoi_edge_shape)};
    size_t k;
    CHECK(d != NULL);
    if (d == NULL) return;

    /* Filled in whole: struct_size stays sizeof. */
    CHECK_STATUS(segvoronoi_diagram_vertex(d, 0, &v), SEGVORONOI_STATUS_OK);
    CHECK(v.struct_size == sizeof v && v.clearance > 0.0);
    CHECK_STATUS(segvoronoi_diagram_site(d, 0, &site), SEGVORONOI_STATUS_OK);
    CHECK(site.struct_size == sizeof site);
    CHECK_STATUS(segvoronoi_diagram_edge(d, 0, &edge), SEGVORONOI_STATUS_OK);
    CHECK(edge.struct_size == sizeof edge);
    CHECK_STATUS(segvoronoi_diagram_stats(d, &stats), SEGVORONOI_STATUS_OK);
    CHECK(stats.struct_size == sizeof stats && stats.input_points == 4);
    CHECK_STATUS(segvoronoi_diagram_edge_shape(d, 0, &shape), SEGVORONOI_STATUS_OK);
    CHECK(shape.struct_size == sizeof shape && shape.kind == SEGVORONOI_EDGE_LINE);

    /* Too small (0: not set; 8: only struct_size itself): refused, untouched. */
    memset(&v, 0x5a, sizeof v);
    v.struct_size = 0;
    CHECK_STATUS(segvoronoi_diagram_vertex(d, 0, &v), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    CHECK(v.struct_size == 0 && v.sites[2] == 0x5a5a5a5aU);
    v.struct_size = sizeof(size_t);
    CHECK_STATUS(segvoronoi_diagram_vertex(d, 0, &v), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    site.struct_size = sizeof site - 1;
    CHECK_STATUS(segvoronoi_diagram_site(d, 0, &site), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    edge.struct_size = 0;
    CHECK_STATUS(segvoronoi_diagram_edge(d, 0, &edge), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    stats.struct_size = 0;
    CHECK_STATUS(segvoronoi_diagram_stats(d, &stats), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    shape.struct_size = 0;
    CHECK_STATUS(segvoronoi_diagram_edge_shape(d, 0, &shape), SEGVORONOI_STATUS_INVALID_ARGUMENT);

    /* A caller whose struct is larger: the library writes what it has. */
    memset(&newer, 0xa5, sizeof newer);
    newer.v.struct_size = sizeof newer;
    CHECK_STATUS(segvoronoi_diagram_vertex(d, 0, &newer.v), SEGVORONOI_STATUS_OK);
    CHECK(newer.v.struct_size == sizeof(segvoronoi_vertex));
    CHECK(newer.v.clearance > 0.0 && newer.v.sites[0] < 4);
    for (k = 0; k < sizeof newer.later_fields; ++k) CHECK(newer.later_fields[k] == 0xa5);
    segvoronoi_diagram_free(d);
}

/* Offsets of the square 10 x 10 with a square hole 2 x 2 in its middle:
 * shrunk by 1, an 8 x 8 square with a hole grown by 1 (the 4 x 4 square
 * with rounded corners); grown by 1, the 12 x 12 rounded square with a hole
 * of 0 x 0 (gone). Loops close, holes run clockwise, pieces say their kind,
 * polylines stay within the tolerance of the exact area, bad calls fail. */
/* Splitting mode: two crossing segments and a collinear overlap are refused
 * by default and split when asked; the piece map both ways, the stats, the
 * pieces' coordinates and the displacement. */
static void test_split_crossings(void) {
    /* 0 and 1 cross at (1, 1); 2 overlaps 3 on y = 5 over [2, 3] */
    const double xy[16] = {0, 0, 2, 2, 0, 2, 2, 0, 0, 5, 3, 5, 2, 5, 6, 5};
    segvoronoi_builder *b = segvoronoi_builder_new();
    segvoronoi_diagram *d = NULL;
    segvoronoi_stats stats = {.struct_size = sizeof stats};
    uint32_t list[8];
    size_t n = 0, p, shared = 0;
    double ends[4], moved = -1.0;
    CHECK_STATUS(segvoronoi_builder_add_segments(b, xy, 4), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(b, &d), SEGVORONOI_STATUS_INTERSECTING);
    CHECK_STATUS(segvoronoi_builder_set_split_crossings(NULL, 1), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_builder_set_split_crossings(b, 1), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(b, &d), SEGVORONOI_STATUS_OK);
    segvoronoi_builder_free(b);
    CHECK_STATUS(segvoronoi_diagram_validate(d), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_diagram_stats(d, &stats), SEGVORONOI_STATUS_OK);
    CHECK(stats.input_segments == 4 && stats.crossings == 1 && stats.overlaps == 1 && stats.touchings == 0);
    /* 4 pieces of the cross; [0, 2], [2, 3] (shared), [3, 6] on y = 5 */
    CHECK(segvoronoi_diagram_piece_count(d) == 7 && stats.pieces == 7);
    CHECK_STATUS(segvoronoi_diagram_pieces_of_input(d, 0, NULL, 0, &n), SEGVORONOI_STATUS_OK);
    CHECK(n == 2);
    CHECK_STATUS(segvoronoi_diagram_pieces_of_input(d, 0, list, 1, &n), SEGVORONOI_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(segvoronoi_diagram_pieces_of_input(d, 4, list, 8, &n), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_pieces_of_input(d, 2, list, 8, &n), SEGVORONOI_STATUS_OK);
    CHECK(n == 2);
    for (p = 0; p < segvoronoi_diagram_piece_count(d); ++p) {
        CHECK_STATUS(segvoronoi_diagram_inputs_of_piece(d, p, list, 8, &n), SEGVORONOI_STATUS_OK);
        if (n == 2) {
            ++shared;
            CHECK(list[0] == 2 && list[1] == 3);
            CHECK_STATUS(segvoronoi_diagram_piece(d, p, ends), SEGVORONOI_STATUS_OK);
            CHECK(fmin(ends[0], ends[2]) == 2.0 && fmax(ends[0], ends[2]) == 3.0 && ends[1] == 5.0 && ends[3] == 5.0);
        }
    }
    CHECK(shared == 1);
    CHECK_STATUS(segvoronoi_diagram_inputs_of_piece(d, 7, list, 8, &n), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_piece(d, 7, ends), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_max_split_displacement(d, &moved), SEGVORONOI_STATUS_OK);
    CHECK(moved == 0.0); /* (1, 1) and the overlap's ends are pixel centres */
    segvoronoi_diagram_free(d);
}

/* Splitting with arcs: a half circle crossed by a segment through its
 * top becomes two arc pieces; the map between arc pieces and input arcs
 * both ways, each piece's site and back, and out-of-range ids. */
static void test_split_arcs(void) {
    segvoronoi_builder *b = segvoronoi_builder_new();
    segvoronoi_diagram *d = NULL;
    segvoronoi_stats stats = {.struct_size = sizeof stats};
    segvoronoi_arc arc = {.struct_size = sizeof arc};
    uint32_t list[8], site = 0;
    size_t n = 0, p, index = 99;
    CHECK_STATUS(segvoronoi_builder_add_arc(b, 0, 0, 4, 0, 1, NULL), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_add_segment(b, 2, 1, 2, -3), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(b, &d), SEGVORONOI_STATUS_INTERSECTING);
    CHECK_STATUS(segvoronoi_builder_set_split_crossings(b, 1), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(b, &d), SEGVORONOI_STATUS_OK);
    segvoronoi_builder_free(b);
    CHECK_STATUS(segvoronoi_diagram_validate(d), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_diagram_stats(d, &stats), SEGVORONOI_STATUS_OK);
    CHECK(stats.input_arcs == 1 && stats.crossings == 1);
    CHECK(segvoronoi_diagram_arc_site_count(d) == 2);
    CHECK_STATUS(segvoronoi_diagram_arc_pieces_of_input(d, 0, NULL, 0, &n), SEGVORONOI_STATUS_OK);
    CHECK(n == 2);
    CHECK_STATUS(segvoronoi_diagram_arc_pieces_of_input(d, 0, list, 1, &n), SEGVORONOI_STATUS_BUFFER_TOO_SMALL);
    CHECK_STATUS(segvoronoi_diagram_arc_pieces_of_input(d, 0, list, 8, &n), SEGVORONOI_STATUS_OK);
    CHECK(n == 2 && list[0] == 0 && list[1] == 1);
    CHECK_STATUS(segvoronoi_diagram_arc_pieces_of_input(d, 1, list, 8, &n), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_arc_pieces_of_input(NULL, 0, list, 8, &n), SEGVORONOI_STATUS_NULL_ARGUMENT);
    for (p = 0; p < 2; ++p) {
        CHECK_STATUS(segvoronoi_diagram_inputs_of_arc_piece(d, p, list, 8, &n), SEGVORONOI_STATUS_OK);
        CHECK(n == 1 && list[0] == 0);
        /* the piece's site, its arc (one end on the segment, at x = 2), and back */
        CHECK_STATUS(segvoronoi_diagram_site_of_arc(d, p, &site), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_diagram_arc(d, site, &arc), SEGVORONOI_STATUS_OK);
        CHECK(arc.start[0] == 2.0 || arc.end[0] == 2.0);
        CHECK_STATUS(segvoronoi_diagram_arc_input_index(d, site, &index), SEGVORONOI_STATUS_OK);
        CHECK(index == p);
    }
    CHECK_STATUS(segvoronoi_diagram_inputs_of_arc_piece(d, 2, list, 8, &n), SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(segvoronoi_diagram_site_of_arc(d, 2, &site), SEGVORONOI_STATUS_OUT_OF_RANGE);
    segvoronoi_diagram_free(d);
}

/* segvoronoi_builder_set_threads: the same topology text at 1 thread (no
 * thread started) and at the machine's cores, on 30,000 segments (90,000
 * sites: with two cores the build runs in halves), their ends on a grid of
 * eighths (cocircular sites: the text cuts them one way,
 * SEGVORONOI_TOPOLOGY_CANONICAL_CUTS). */
static void test_threads(void) {
    enum { SIDE = 200, COUNT = SIDE * 150 };
    double *xy = malloc(sizeof(double) * 4 * COUNT);
    char *text[2] = {NULL, NULL};
    size_t k, length[2] = {0, 0};
    uint32_t seed = 12345u;
    int t;
    CHECK(xy != NULL);
    if (xy == NULL) {
        return;
    }
    for (k = 0; k < COUNT; ++k) {
        /* one short segment in each unit cell, its ends at random eighths */
        double x = (double)(k % SIDE), y = (double)(k / SIDE);
        double v[4];
        int j;
        for (j = 0; j < 4; ++j) {
            seed = seed * 1103515245u + 12345u;
            v[j] = (double)((seed >> 16) % 7 + 1) / 8.0;
        }
        xy[4 * k] = x + v[0];
        xy[4 * k + 1] = y + v[1];
        xy[4 * k + 2] = x + v[2];
        xy[4 * k + 3] = y + v[3] + (v[1] == v[3] && v[0] == v[2] ? 0.0625 : 0.0);
    }
    CHECK_STATUS(segvoronoi_builder_set_threads(NULL, 1), SEGVORONOI_STATUS_NULL_ARGUMENT);
    for (t = 0; t < 2; ++t) {
        segvoronoi_builder *b = segvoronoi_builder_new();
        segvoronoi_diagram *d = NULL;
        CHECK_STATUS(segvoronoi_builder_add_segments(b, xy, COUNT), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_builder_set_threads(b, t == 0 ? 1 : 0), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_builder_build(b, &d), SEGVORONOI_STATUS_OK);
        CHECK_STATUS(segvoronoi_diagram_topology(d, SEGVORONOI_TOPOLOGY_CANONICAL_CUTS | SEGVORONOI_TOPOLOGY_VORONOI_PAIRS,
                                                 &text[t], &length[t]),
                     SEGVORONOI_STATUS_OK);
        segvoronoi_diagram_free(d);
        segvoronoi_builder_free(b);
    }
    CHECK(text[0] != NULL && text[1] != NULL && length[0] == length[1] && length[0] > 0 &&
          memcmp(text[0], text[1], length[0]) == 0);
    segvoronoi_string_free(text[0]);
    segvoronoi_string_free(text[1]);
    free(xy);
}

static void test_offsets(void) {
    const double xy[] = {0, 0, 10, 0, 10, 10, 0, 10, 4, 4, 4, 6, 6, 6, 6, 4};
    const size_t lengths[] = {4, 4};
    const double distances[] = {-1.0, 1.0, -2.0};
    const double pi = 3.14159265358979323846;
    segvoronoi_builder *b = segvoronoi_builder_new();
    segvoronoi_diagram *d = NULL;
    segvoronoi_offset *offsets[3] = {NULL, NULL, NULL}, *untouched = NULL;
    size_t k, l, p;
    CHECK_STATUS(segvoronoi_builder_add_polygon(b, xy, lengths, 2), SEGVORONOI_STATUS_OK);
    CHECK_STATUS(segvoronoi_builder_build(b, &d), SEGVORONOI_STATUS_OK);
    segvoronoi_builder_free(b);
    CHECK_STATUS(segvoronoi_diagram_offsets(d, distances, 3, offsets), SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_offset_distance(offsets[0]) == -1.0);
    /* 64 - (4 + 4 x 2 + pi) */
    CHECK(fabs(segvoronoi_offset_area(offsets[0]) - (64.0 - (4.0 + 8.0 + pi))) < 1e-9);
    CHECK(segvoronoi_offset_loop_count(offsets[0]) == 2);
    CHECK(fabs(segvoronoi_offset_area(offsets[1]) - (100.0 + 40.0 + pi)) < 1e-9); /* the hole filled */
    CHECK(segvoronoi_offset_loop_count(offsets[1]) == 1);
    /* 2 in: the 6 x 6 square less the hole grown by 2 leaves four corners */
    CHECK(segvoronoi_offset_loop_count(offsets[2]) == 4);
    for (k = 0; k < 3; ++k) {
        for (l = 0; l < segvoronoi_offset_loop_count(offsets[k]); ++l) {
            segvoronoi_loop loop = {.struct_size = sizeof loop};
            segvoronoi_loop_piece first = {.struct_size = sizeof first}, last = {.struct_size = sizeof last};
            size_t n = 0, got = 0;
            double *points, shoelace = 0.0;
            CHECK_STATUS(segvoronoi_offset_loop(offsets[k], l, &loop), SEGVORONOI_STATUS_OK);
            CHECK(loop.piece_count > 0);
            CHECK(loop.hole == (loop.signed_area < 0.0));
            CHECK(loop.hole == (loop.parent != SEGVORONOI_NO_PARENT));
            CHECK(loop.parent == SEGVORONOI_NO_PARENT || loop.parent < l);
            for (p = 0; p < loop.piece_count; ++p) {
                segvoronoi_loop_piece piece = {.struct_size = sizeof piece};
                CHECK_STATUS(segvoronoi_offset_piece(offsets[k], l, p, &piece), SEGVORONOI_STATUS_OK);
                CHECK(piece.kind == SEGVORONOI_OFFSET_LINE || piece.kind == SEGVORONOI_OFFSET_ARC);
                if (piece.kind == SEGVORONOI_OFFSET_ARC) CHECK(piece.radius == fabs(distances[k]));
                if (p > 0) CHECK(piece.from[0] == last.to[0] && piece.from[1] == last.to[1]);
                if (p == 0) first = piece;
                last = piece;
            }
            CHECK(first.from[0] == last.to[0] && first.from[1] == last.to[1]);
            CHECK_STATUS(segvoronoi_offset_piece(offsets[k], l, loop.piece_count, &last), SEGVORONOI_STATUS_OUT_OF_RANGE);
            CHECK_STATUS(segvoronoi_offset_loop_polyline(offsets[k], l, 1e-4, NULL, 0, &n), SEGVORONOI_STATUS_OK);
            CHECK(n >= loop.piece_count);
            points = malloc(2 * n * sizeof *points);
            CHECK(points != NULL);
            CHECK_STATUS(segvoronoi_offset_loop_polyline(offsets[k], l, 1e-4, points, n, &got), SEGVORONOI_STATUS_OK);
            CHECK(got == n);
            for (p = 0; p < n; ++p) {
                size_t q = (p + 1) % n;
                shoelace += (points[2 * p] * points[2 * q + 1] - points[2 * q] * points[2 * p + 1]) / 2.0;
            }
            CHECK(fabs(shoelace - loop.signed_area) < 1e-4 * 100.0);
            CHECK_STATUS(segvoronoi_offset_loop_polyline(offsets[k], l, 1e-4, points, n - 1, &got),
                         SEGVORONOI_STATUS_BUFFER_TOO_SMALL);
            CHECK_STATUS(segvoronoi_offset_loop_polyline(offsets[k], l, -1.0, points, n, &got),
                         SEGVORONOI_STATUS_INVALID_ARGUMENT);
            free(points);
        }
        CHECK_STATUS(segvoronoi_offset_loop(offsets[k], 99, &(segvoronoi_loop){.struct_size = 0}),
                     SEGVORONOI_STATUS_OUT_OF_RANGE);
    }
    CHECK_STATUS(segvoronoi_diagram_offset(d, 0.0, &untouched), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_offset(d, NAN, &untouched), SEGVORONOI_STATUS_INVALID_ARGUMENT);
    CHECK(untouched == NULL);
    CHECK_STATUS(segvoronoi_diagram_offset(NULL, 1.0, &untouched), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(segvoronoi_diagram_offset(d, 1.0, NULL), SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK(segvoronoi_offset_loop_count(NULL) == 0 && isnan(segvoronoi_offset_area(NULL)));
    /* an offset outlives its diagram */
    segvoronoi_diagram_free(d);
    CHECK(segvoronoi_offset_loop_count(offsets[1]) == 1);
    for (k = 0; k < 3; ++k) segvoronoi_offset_free(offsets[k]);
    segvoronoi_offset_free(NULL);
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
    test_zero_length_is_exact();
    test_random_inputs();
    test_segment_input_rules();
    test_intersecting_segments();
    test_segment_sites_and_stats();
    test_segment_shapes();
    test_edge_geometry();
    test_versioned_structs();
    test_polygon_domain();
    test_offsets();
    test_split_crossings();
    test_split_arcs();
    test_threads();
    fprintf(stderr, "segvoronoi C API tests: %d checks, %d failed\n", checks, failures);
    return failures;
}

#ifndef SEGVORONOI_C_TESTS_NO_MAIN
int main(void) {
    return segvoronoi_run_c_tests() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
#endif
