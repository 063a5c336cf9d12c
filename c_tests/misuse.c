/* The misuse table of issue 28: every kind of wrong call through the C API,
 * each checked for its status AND for segvoronoi_last_error_message(), which
 * must be non-empty and name the problem (the argument, the id, the value).
 * Then what a table cannot say: the last error after success, the order in
 * which handles are freed, flag bytes other than 0 and 1 in the versioned
 * filter struct, and memory limits (in a child process under setrlimit:
 * refusals with a status, never an abort).
 *
 * Built by c_tests/CMakeLists.txt against the installed package (shared,
 * static and under AddressSanitizer) and by c_tests/cargo through `cc`,
 * which defines SEGVORONOI_C_TESTS_NO_MAIN and calls
 * segvoronoi_run_misuse_tests() itself; the memory-limit part needs a
 * process of its own (fork), so it runs only in the CMake builds without a
 * sanitizer.
 *
 * Plain C99 plus POSIX (fork, setrlimit) for that part. */

#if !defined(SEGVORONOI_C_TESTS_NO_MAIN)
#define _POSIX_C_SOURCE 200809L
#endif

#include "segvoronoi.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if !defined(SEGVORONOI_C_TESTS_NO_MAIN)
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

/* AddressSanitizer reserves terabytes of address space: a memory limit
 * would stop it, not the library. */
#if defined(__SANITIZE_ADDRESS__)
#define SEGVORONOI_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SEGVORONOI_UNDER_ASAN 1
#endif
#endif

int segvoronoi_run_misuse_tests(void);

static int failures = 0;
static int checks = 0;

#define CHECK(cond)                                                                      \
    do {                                                                                 \
        ++checks;                                                                        \
        if (!(cond)) {                                                                   \
            ++failures;                                                                  \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);     \
        }                                                                                \
    } while (0)

/* Everything the cases call on: a builder with a polygon (a 20-gon with a
 * square hole), its diagram, medial axis and offset, and output slots. */
typedef struct {
    segvoronoi_builder *builder;
    segvoronoi_diagram *diagram;
    segvoronoi_medial_axis *axis;
    segvoronoi_offset *offset;
    size_t big_loop; /* the offset's loop with the most pieces */
    segvoronoi_diagram *made;
    segvoronoi_medial_axis *made_axis;
    segvoronoi_offset *made_offset;
    segvoronoi_site site;
    segvoronoi_vertex vertex;
    segvoronoi_edge edge;
    segvoronoi_loop loop;
    segvoronoi_loop_piece loop_piece;
    segvoronoi_piece piece;
    segvoronoi_medial_axis_filter filter;
    double xy[8];
    size_t lengths[2];
    double distances[2];
    uint32_t ids[4];
    size_t count;
    bool flag;
    double x, y, r;
    char *text;
} fixture;

#define N_GON 20

static void fixture_init(fixture *f) {
    double ring[2 * N_GON + 8];
    size_t lengths[2] = {N_GON, 4}, k, best = 0, n;
    const double pi = 3.14159265358979323846;
    memset(f, 0, sizeof *f);
    for (k = 0; k < N_GON; ++k) {
        ring[2 * k] = 10.0 * cos(2.0 * pi * (double)k / N_GON);
        ring[2 * k + 1] = 10.0 * sin(2.0 * pi * (double)k / N_GON);
    }
    {
        const double hole[8] = {-2, -2, 2, -2, 2, 2, -2, 2};
        memcpy(ring + 2 * N_GON, hole, sizeof hole);
    }
    f->builder = segvoronoi_builder_new();
    CHECK(segvoronoi_builder_add_polygon(f->builder, ring, lengths, 2) == SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_builder_add_point(f->builder, 5.0, 0.5) == SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_builder_build(f->builder, &f->diagram) == SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_diagram_medial_axis(f->diagram, &f->axis) == SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_diagram_offset(f->diagram, 0.5, &f->offset) == SEGVORONOI_STATUS_OK);
    for (k = 0; k < segvoronoi_offset_loop_count(f->offset); ++k) {
        segvoronoi_loop l = {.struct_size = sizeof l};
        CHECK(segvoronoi_offset_loop(f->offset, k, &l) == SEGVORONOI_STATUS_OK);
        n = l.piece_count;
        if (n > best) {
            best = n;
            f->big_loop = k;
        }
    }
    f->site.struct_size = sizeof f->site;
    f->vertex.struct_size = sizeof f->vertex;
    f->edge.struct_size = sizeof f->edge;
    f->loop.struct_size = sizeof f->loop;
    f->loop_piece.struct_size = sizeof f->loop_piece;
    f->piece.struct_size = sizeof f->piece;
    f->filter.struct_size = sizeof f->filter;
    f->lengths[0] = 3;
    f->lengths[1] = 3;
    f->distances[0] = 1.0;
}

static void fixture_free(fixture *f) {
    segvoronoi_offset_free(f->offset);
    segvoronoi_offset_free(f->made_offset);
    segvoronoi_medial_axis_free(f->axis);
    segvoronoi_medial_axis_free(f->made_axis);
    segvoronoi_diagram_free(f->diagram);
    segvoronoi_diagram_free(f->made);
    segvoronoi_builder_free(f->builder);
    segvoronoi_string_free(f->text);
}

/* One row: a call, the status it must return, and a piece of text the last
 * error must contain. */
typedef struct {
    const char *name;
    segvoronoi_status (*call)(fixture *f);
    segvoronoi_status expected;
    const char *needle;
} misuse_case;

#define CASE(fn, expr) \
    static segvoronoi_status fn(fixture *f) { (void)f; return (expr); }

/* NULL in every kind of pointer argument */
CASE(null_builder_add_point, segvoronoi_builder_add_point(NULL, 1, 2))
CASE(null_builder_add_points_xy, segvoronoi_builder_add_points(f->builder, NULL, 3))
CASE(null_builder_add_segments_xy, segvoronoi_builder_add_segments(f->builder, NULL, 1))
CASE(null_builder_add_polygon_lengths, segvoronoi_builder_add_polygon(f->builder, f->xy, NULL, 1))
CASE(null_builder_add_polyline_xy, segvoronoi_builder_add_polyline(f->builder, NULL, 2))
CASE(null_builder_build_out, segvoronoi_builder_build(f->builder, NULL))
CASE(null_builder_build_builder, segvoronoi_builder_build(NULL, &f->made))
CASE(null_builder_check, segvoronoi_builder_check(NULL))
CASE(null_builder_split, segvoronoi_builder_set_split_crossings(NULL, 1))
CASE(null_builder_threads, segvoronoi_builder_set_threads(NULL, 1))
CASE(null_builder_indices_count, segvoronoi_builder_last_error_indices(f->builder, NULL, 0, NULL))
CASE(null_diagram_site, segvoronoi_diagram_site(NULL, 0, &f->site))
CASE(null_diagram_site_out, segvoronoi_diagram_site(f->diagram, 0, NULL))
CASE(null_diagram_vertex_out, segvoronoi_diagram_vertex(f->diagram, 0, NULL))
CASE(null_diagram_edge, segvoronoi_diagram_edge(NULL, 0, &f->edge))
CASE(null_cell_edges_buffer, segvoronoi_diagram_cell_edges(f->diagram, 0, NULL, 4, &f->count))
CASE(null_cell_edges_count, segvoronoi_diagram_cell_edges(f->diagram, 0, f->ids, 4, NULL))
CASE(null_nearest_out, segvoronoi_diagram_nearest_site(f->diagram, 0, 0, SEGVORONOI_NO_SITE, NULL))
CASE(null_topology_text, segvoronoi_diagram_topology(f->diagram, 0, NULL, NULL))
CASE(null_stats_out, segvoronoi_diagram_stats(f->diagram, NULL))
CASE(null_medial_axis_out, segvoronoi_diagram_medial_axis(f->diagram, NULL))
CASE(null_medial_axis_diagram, segvoronoi_diagram_medial_axis(NULL, &f->made_axis))
CASE(null_offset_out, segvoronoi_diagram_offset(f->diagram, 1.0, NULL))
CASE(null_offsets_distances, segvoronoi_diagram_offsets(f->diagram, NULL, 2, &f->made_offset))
CASE(null_offset_loop, segvoronoi_offset_loop(NULL, 0, &f->loop))
CASE(null_offset_polyline_count, segvoronoi_offset_loop_polyline(f->offset, 0, 0.1, NULL, 0, NULL))
CASE(null_chain_count, segvoronoi_medial_axis_chain(f->axis, 0, NULL, &f->flag))
CASE(null_sample_chain_axis, segvoronoi_medial_axis_sample_chain(NULL, 0, 0.1, NULL, 0, &f->count))
CASE(null_locate_out, segvoronoi_diagram_locate_point(f->diagram, 1, 1, NULL))
CASE(null_inscribed_x, segvoronoi_diagram_max_inscribed_circle(f->diagram, NULL, &f->y, &f->r))
CASE(null_piece_out, segvoronoi_diagram_piece(f->diagram, 0, NULL))
CASE(null_half_edge_out, segvoronoi_diagram_half_edge_next(f->diagram, 0, NULL))
CASE(null_edge_polyline_xy, segvoronoi_diagram_edge_polyline(f->diagram, 0, 0.1, NULL, 3, &f->count))
CASE(null_edge_shape, segvoronoi_diagram_edge_shape(NULL, 0, NULL))

/* ids out of range */
CASE(bad_site, segvoronoi_diagram_site(f->diagram, 1000000, &f->site))
CASE(bad_vertex, segvoronoi_diagram_vertex(f->diagram, SIZE_MAX, &f->vertex))
CASE(bad_edge, segvoronoi_diagram_edge(f->diagram, 123456789, &f->edge))
CASE(bad_cell, segvoronoi_diagram_cell_edges(f->diagram, 99999, NULL, 0, &f->count))
CASE(bad_half_edge, segvoronoi_diagram_half_edge_next(f->diagram, 0xFFFFFFFEu, f->ids))
CASE(bad_hint, segvoronoi_diagram_nearest_site(f->diagram, 0, 0, 999999, f->ids))
CASE(bad_vertex_location, segvoronoi_diagram_vertex_location(f->diagram, 999999, f->ids))
CASE(bad_chain, segvoronoi_medial_axis_chain(f->axis, 99999, &f->count, &f->flag))
CASE(bad_axis_piece, segvoronoi_medial_axis_piece(f->axis, 0, 99999, &f->piece))
CASE(bad_loop, segvoronoi_offset_loop(f->offset, 9999, &f->loop))
CASE(bad_loop_piece, segvoronoi_offset_piece(f->offset, 0, 99999, &f->loop_piece))
CASE(bad_input_segment, segvoronoi_diagram_pieces_of_input(f->diagram, 9999, NULL, 0, &f->count))
CASE(bad_input_arc, segvoronoi_diagram_arc_pieces_of_input(f->diagram, 9999, NULL, 0, &f->count))
CASE(bad_arc_piece, segvoronoi_diagram_inputs_of_arc_piece(f->diagram, 9999, NULL, 0, &f->count))
CASE(bad_segment_site, segvoronoi_diagram_segment_endpoints(f->diagram, 0, f->ids))
CASE(bad_edge_polyline, segvoronoi_diagram_edge_polyline(f->diagram, 777777, 0.1, NULL, 0, &f->count))
CASE(bad_topology_flags, segvoronoi_diagram_topology(f->diagram, 0x100, &f->text, NULL))
CASE(bad_struct_size, (f->vertex.struct_size = 0, segvoronoi_diagram_vertex(f->diagram, 0, &f->vertex)))

/* non-finite and out-of-domain arguments */
CASE(nan_add_point, segvoronoi_builder_add_point(f->builder, NAN, 0))
CASE(inf_add_segment, segvoronoi_builder_add_segment(f->builder, 0, 0, INFINITY, 1))
CASE(nan_locate, segvoronoi_diagram_locate_point(f->diagram, NAN, 5, f->ids))
CASE(inf_locate, segvoronoi_diagram_locate_point(f->diagram, 0, -INFINITY, f->ids))
CASE(nan_nearest, segvoronoi_diagram_nearest_site(f->diagram, NAN, 0, SEGVORONOI_NO_SITE, f->ids))
CASE(nan_offset, segvoronoi_diagram_offset(f->diagram, NAN, &f->made_offset))
CASE(inf_offsets, (f->distances[1] = INFINITY, segvoronoi_diagram_offsets(f->diagram, f->distances, 2, &f->made_offset)))
CASE(nan_edge_tolerance, segvoronoi_diagram_edge_polyline(f->diagram, 0, NAN, NULL, 0, &f->count))
CASE(zero_loop_tolerance, segvoronoi_offset_loop_polyline(f->offset, 0, 0.0, NULL, 0, &f->count))
CASE(negative_chain_tolerance, segvoronoi_medial_axis_sample_chain(f->axis, 0, -1.0, NULL, 0, &f->count))
CASE(nan_piece_at, segvoronoi_medial_axis_piece_at(f->axis, 0, 0, NAN, f->xy))
CASE(nan_filter, (f->filter.corner_filter = 1, f->filter.corner_angle = NAN,
                  segvoronoi_diagram_medial_axis_filtered(f->diagram, &f->filter, &f->made_axis)))

/* huge counts and outputs */
CASE(huge_add_points, segvoronoi_builder_add_points(f->builder, f->xy, SIZE_MAX))
CASE(huge_add_segments, segvoronoi_builder_add_segments(f->builder, f->xy, SIZE_MAX / 4))
CASE(huge_polygon_rings, segvoronoi_builder_add_polygon(f->builder, f->xy, f->lengths, SIZE_MAX))
CASE(huge_polygon_lengths, (f->lengths[0] = SIZE_MAX, segvoronoi_builder_add_polygon(f->builder, f->xy, f->lengths, 2)))
CASE(huge_offsets, segvoronoi_diagram_offsets(f->diagram, f->distances, SIZE_MAX, &f->made_offset))
CASE(huge_loop_polyline, segvoronoi_offset_loop_polyline(f->offset, f->big_loop, DBL_MIN, NULL, 0, &f->count))
CASE(small_buffer, segvoronoi_diagram_cell_edges(f->diagram, 0, f->ids, 1, &f->count))

#define ROW(fn, status, needle) {#fn, fn, SEGVORONOI_STATUS_##status, needle}

static const misuse_case table[] = {
    ROW(null_builder_add_point, NULL_ARGUMENT, "`builder`"),
    ROW(null_builder_add_points_xy, NULL_ARGUMENT, "`xy`"),
    ROW(null_builder_add_segments_xy, NULL_ARGUMENT, "`xy`"),
    ROW(null_builder_add_polygon_lengths, NULL_ARGUMENT, "`ring_lengths`"),
    ROW(null_builder_add_polyline_xy, NULL_ARGUMENT, "`xy`"),
    ROW(null_builder_build_out, NULL_ARGUMENT, "`out`"),
    ROW(null_builder_build_builder, NULL_ARGUMENT, "`builder`"),
    ROW(null_builder_check, NULL_ARGUMENT, "`builder`"),
    ROW(null_builder_split, NULL_ARGUMENT, "`builder`"),
    ROW(null_builder_threads, NULL_ARGUMENT, "`builder`"),
    ROW(null_builder_indices_count, NULL_ARGUMENT, "`count`"),
    ROW(null_diagram_site, NULL_ARGUMENT, "`diagram`"),
    ROW(null_diagram_site_out, NULL_ARGUMENT, "`out`"),
    ROW(null_diagram_vertex_out, NULL_ARGUMENT, "`out`"),
    ROW(null_diagram_edge, NULL_ARGUMENT, "`diagram`"),
    ROW(null_cell_edges_buffer, NULL_ARGUMENT, "`edges`"),
    ROW(null_cell_edges_count, NULL_ARGUMENT, "`count`"),
    ROW(null_nearest_out, NULL_ARGUMENT, "`out_site`"),
    ROW(null_topology_text, NULL_ARGUMENT, "`text`"),
    ROW(null_stats_out, NULL_ARGUMENT, "`out`"),
    ROW(null_medial_axis_out, NULL_ARGUMENT, "`out`"),
    ROW(null_medial_axis_diagram, NULL_ARGUMENT, "`diagram`"),
    ROW(null_offset_out, NULL_ARGUMENT, "`out`"),
    ROW(null_offsets_distances, NULL_ARGUMENT, "`distances`"),
    ROW(null_offset_loop, NULL_ARGUMENT, "`offset`"),
    ROW(null_offset_polyline_count, NULL_ARGUMENT, "`count`"),
    ROW(null_chain_count, NULL_ARGUMENT, "`count`"),
    ROW(null_sample_chain_axis, NULL_ARGUMENT, "`axis`"),
    ROW(null_locate_out, NULL_ARGUMENT, "`out`"),
    ROW(null_inscribed_x, NULL_ARGUMENT, "`x`"),
    ROW(null_piece_out, NULL_ARGUMENT, "`out`"),
    ROW(null_half_edge_out, NULL_ARGUMENT, "`out`"),
    ROW(null_edge_polyline_xy, NULL_ARGUMENT, "`xy`"),
    ROW(null_edge_shape, NULL_ARGUMENT, "is NULL"),

    ROW(bad_site, OUT_OF_RANGE, "site 1000000 is out of range"),
    ROW(bad_vertex, OUT_OF_RANGE, "vertex 18446744073709551615"),
    ROW(bad_edge, OUT_OF_RANGE, "edge 123456789"),
    ROW(bad_cell, OUT_OF_RANGE, "site 99999"),
    ROW(bad_half_edge, OUT_OF_RANGE, "half-edge 4294967294"),
    ROW(bad_hint, OUT_OF_RANGE, "hint site 999999"),
    ROW(bad_vertex_location, OUT_OF_RANGE, "vertex 999999"),
    ROW(bad_chain, OUT_OF_RANGE, "chain 99999"),
    ROW(bad_axis_piece, OUT_OF_RANGE, "piece 99999"),
    ROW(bad_loop, OUT_OF_RANGE, "loop 9999"),
    ROW(bad_loop_piece, OUT_OF_RANGE, "piece 99999"),
    ROW(bad_input_segment, OUT_OF_RANGE, "input segment 9999"),
    ROW(bad_input_arc, OUT_OF_RANGE, "input arc 9999"),
    ROW(bad_arc_piece, OUT_OF_RANGE, "arc piece 9999"),
    ROW(bad_segment_site, INVALID_ARGUMENT, "site 0 is a point site"),
    ROW(bad_edge_polyline, OUT_OF_RANGE, "edge 777777"),
    ROW(bad_topology_flags, INVALID_ARGUMENT, "0x100"),
    ROW(bad_struct_size, INVALID_ARGUMENT, "struct_size of the segvoronoi_vertex is 0"),

    ROW(nan_add_point, INVALID_COORDINATE, "non-finite"),
    ROW(inf_add_segment, INVALID_COORDINATE, "non-finite"),
    ROW(nan_locate, INVALID_COORDINATE, "(NaN, 5) is not finite"),
    ROW(inf_locate, INVALID_COORDINATE, "not finite"),
    ROW(nan_nearest, INVALID_COORDINATE, "not finite"),
    ROW(nan_offset, INVALID_ARGUMENT, "offset distance NaN"),
    ROW(inf_offsets, INVALID_ARGUMENT, "offset distance inf"),
    ROW(nan_edge_tolerance, INVALID_ARGUMENT, "tolerance NaN"),
    ROW(zero_loop_tolerance, INVALID_ARGUMENT, "tolerance 0"),
    ROW(negative_chain_tolerance, INVALID_ARGUMENT, "tolerance -1"),
    ROW(nan_piece_at, INVALID_ARGUMENT, "t = NaN"),
    ROW(nan_filter, INVALID_ARGUMENT, "NaN"),

    ROW(huge_add_points, TOO_LARGE, "at most"),
    ROW(huge_add_segments, TOO_LARGE, "at most"),
    ROW(huge_polygon_rings, TOO_LARGE, "rings are too many"),
    ROW(huge_polygon_lengths, TOO_LARGE, "SIZE_MAX"),
    ROW(huge_offsets, TOO_LARGE, "count 18446744073709551615"),
    ROW(huge_loop_polyline, TOO_LARGE, "SEGVORONOI_MAX_POLYLINE_POINTS"),
    ROW(small_buffer, BUFFER_TOO_SMALL, "the buffer holds 1 items"),
};

/* Runs every row on a fresh fixture: the status, and the message. Each row
 * follows a successful call, so a message left over from before cannot
 * pass for the row's own. */
static void test_table(void) {
    size_t k;
    for (k = 0; k < sizeof table / sizeof table[0]; ++k) {
        fixture f;
        segvoronoi_status got;
        const char *message;
        fixture_init(&f);
        CHECK(segvoronoi_diagram_validate(f.diagram) == SEGVORONOI_STATUS_OK);
        CHECK(strcmp(segvoronoi_last_error_message(), "") == 0);
        got = table[k].call(&f);
        message = segvoronoi_last_error_message();
        ++checks;
        if (got != table[k].expected || message == NULL || message[0] == '\0' ||
            strstr(message, table[k].needle) == NULL) {
            ++failures;
            fprintf(stderr, "misuse %s: status %d (%s), expected %d; message \"%s\", expected to contain \"%s\"\n",
                    table[k].name, (int)got, segvoronoi_status_str(got), (int)table[k].expected,
                    message ? message : "(NULL)", table[k].needle);
        }
        /* outputs untouched on error */
        CHECK(f.made == NULL && f.made_axis == NULL && f.made_offset == NULL);
        fixture_free(&f);
    }
}

/* The last error is current after every call: set by a failure, cleared by
 * the next success, kept by calls without a status, and per thread. */
static void test_last_error_lifecycle(void) {
    fixture f;
    fixture_init(&f);
    CHECK(segvoronoi_diagram_site(f.diagram, 1u << 30, &f.site) == SEGVORONOI_STATUS_OUT_OF_RANGE);
    CHECK(strstr(segvoronoi_last_error_message(), "site 1073741824") != NULL);
    /* no status: the message stays */
    CHECK(segvoronoi_diagram_site_count(f.diagram) > 0);
    CHECK(segvoronoi_diagram_site_count(NULL) == 0);
    segvoronoi_string_free(NULL);
    CHECK(strstr(segvoronoi_last_error_message(), "site 1073741824") != NULL);
    /* a success clears it */
    CHECK(segvoronoi_diagram_site(f.diagram, 0, &f.site) == SEGVORONOI_STATUS_OK);
    CHECK(strcmp(segvoronoi_last_error_message(), "") == 0);
    /* the builder's own message agrees, and is set for NULL_ARGUMENT too */
    CHECK(segvoronoi_builder_add_points(f.builder, NULL, 2) == SEGVORONOI_STATUS_NULL_ARGUMENT);
    CHECK(strcmp(segvoronoi_builder_last_error(f.builder), segvoronoi_last_error_message()) == 0);
    CHECK(segvoronoi_builder_add_polygon(f.builder, f.xy, f.lengths, SIZE_MAX) == SEGVORONOI_STATUS_TOO_LARGE);
    CHECK(strstr(segvoronoi_builder_last_error(f.builder), "rings") != NULL);
    /* reading the indices reads the error: it stays */
    CHECK(segvoronoi_builder_last_error_indices(f.builder, NULL, 0, &f.count) == SEGVORONOI_STATUS_OK);
    CHECK(strstr(segvoronoi_last_error_message(), "rings") != NULL);
    /* a Rust error's own text, from a diagram query */
    CHECK(segvoronoi_diagram_offset(f.diagram, 0.0, &f.made_offset) == SEGVORONOI_STATUS_INVALID_ARGUMENT);
    CHECK(strstr(segvoronoi_last_error_message(), "offset distance 0") != NULL);
    CHECK(f.made_offset == NULL);
    fixture_free(&f);
}

/* A medial axis keeps its diagram: freed first, the diagram's answers
 * through the axis stay the same (AddressSanitizer and valgrind watch the
 * reads). */
static void test_free_order(void) {
    fixture f;
    size_t chains, pieces = 0, samples = 0, after = 0, k;
    double before[3] = {0, 0, 0}, again[3] = {1, 1, 1};
    segvoronoi_piece p1 = {.struct_size = sizeof p1}, p2 = {.struct_size = sizeof p2};
    fixture_init(&f);
    chains = segvoronoi_medial_axis_chain_count(f.axis);
    CHECK(chains > 0);
    CHECK(segvoronoi_medial_axis_chain(f.axis, 0, &pieces, &f.flag) == SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_medial_axis_piece(f.axis, 0, 0, &p1) == SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_medial_axis_sample_chain(f.axis, 0, 1e-3, NULL, 0, &samples) == SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_medial_axis_piece_at(f.axis, 0, 0, 0.5, before) == SEGVORONOI_STATUS_OK);

    segvoronoi_diagram_free(f.diagram);
    f.diagram = NULL;
    segvoronoi_builder_free(f.builder);
    f.builder = NULL;

    CHECK(segvoronoi_medial_axis_chain_count(f.axis) == chains);
    CHECK(segvoronoi_medial_axis_piece(f.axis, 0, 0, &p2) == SEGVORONOI_STATUS_OK);
    CHECK(p1.edge == p2.edge && p1.ends[0].x == p2.ends[0].x && p1.ends[1].y == p2.ends[1].y &&
          p1.clearance[0] == p2.clearance[0] && p1.sites[1] == p2.sites[1]);
    CHECK(segvoronoi_medial_axis_sample_chain(f.axis, 0, 1e-3, NULL, 0, &after) == SEGVORONOI_STATUS_OK);
    CHECK(after == samples);
    CHECK(segvoronoi_medial_axis_piece_at(f.axis, 0, 0, 0.5, again) == SEGVORONOI_STATUS_OK);
    for (k = 0; k < 3; ++k) CHECK(before[k] == again[k]);
    /* the offset holds its own copy */
    CHECK(segvoronoi_offset_loop_count(f.offset) > 0);
    CHECK(segvoronoi_offset_loop(f.offset, 0, &f.loop) == SEGVORONOI_STATUS_OK);
    fixture_free(&f);
}

/* The filter's flags are integers: 2, 0x80 and all bits set mean "on" as 1
 * does (a C bool's bytes, memset, another language's -1). */
static void test_flag_bytes(void) {
    fixture f;
    const uint32_t ons[] = {1u, 2u, 0x80u, 0xFFFFFFFFu};
    size_t plain, filtered_one = 0, k;
    segvoronoi_medial_axis *axis = NULL;
    segvoronoi_medial_axis_filter filter;
    fixture_init(&f);
    plain = segvoronoi_medial_axis_chain_count(f.axis);
    for (k = 0; k < sizeof ons / sizeof ons[0]; ++k) {
        size_t chains;
        memset(&filter, 0xFF, sizeof filter); /* every byte nonzero, the floats NaN */
        filter.struct_size = sizeof filter;
        filter.corner_filter = ons[k];
        filter.corner_angle = 100.0; /* the 20-gon's corners are 162 degrees */
        filter.spur_filter = 0;
        filter.spur_factor = 0.0;
        CHECK(segvoronoi_diagram_medial_axis_filtered(f.diagram, &filter, &axis) == SEGVORONOI_STATUS_OK);
        chains = segvoronoi_medial_axis_chain_count(axis);
        if (k == 0) filtered_one = chains;
        CHECK(chains == filtered_one);
        segvoronoi_medial_axis_free(axis);
        axis = NULL;
    }
    /* "on" took branches away */
    CHECK(filtered_one < plain);
    /* 0 is off whatever the other bytes */
    memset(&filter, 0, sizeof filter);
    filter.struct_size = sizeof filter;
    filter.corner_angle = NAN; /* ignored while the filter is off */
    CHECK(segvoronoi_diagram_medial_axis_filtered(f.diagram, &filter, &axis) == SEGVORONOI_STATUS_OK);
    CHECK(segvoronoi_medial_axis_chain_count(axis) == plain);
    segvoronoi_medial_axis_free(axis);
    fixture_free(&f);
}

#if !defined(SEGVORONOI_C_TESTS_NO_MAIN) && !defined(SEGVORONOI_UNDER_ASAN)
/* Under a 1 GiB address-space limit (ulimit -v), in a child process: a count
 * the builder cannot hold in memory (below the point cap) is OUT_OF_MEMORY,
 * not an abort, and the builder still works; a polyline count at DBL_MIN
 * allocates nothing and is TOO_LARGE. Exit status 0 when all held. */
static int limited_child(void) {
    const struct rlimit limit = {1u << 30, 1u << 30};
    fixture f;
    double xy[2] = {1, 2};
    size_t n = 0;
    int bad = 0;
    fixture_init(&f);
    if (setrlimit(RLIMIT_AS, &limit) != 0) return 2;
    /* 500 million points are 8 GB: reserved before xy is read */
    if (segvoronoi_builder_add_points(f.builder, xy, 500000000) != SEGVORONOI_STATUS_OUT_OF_MEMORY) bad |= 4;
    if (strstr(segvoronoi_last_error_message(), "out of memory") == NULL) bad |= 8;
    if (segvoronoi_builder_add_segments(f.builder, xy, 250000000) != SEGVORONOI_STATUS_OUT_OF_MEMORY) bad |= 16;
    if (segvoronoi_builder_add_points(f.builder, xy, 1) != SEGVORONOI_STATUS_OK) bad |= 32;
    if (segvoronoi_offset_loop_polyline(f.offset, f.big_loop, DBL_MIN, NULL, 0, &n) != SEGVORONOI_STATUS_TOO_LARGE)
        bad |= 64;
    {
        /* a chain's count allocates nothing either: its points, or the cap */
        segvoronoi_status st = segvoronoi_medial_axis_sample_chain(f.axis, 0, DBL_MIN, NULL, 0, &n);
        if (st != SEGVORONOI_STATUS_OK && st != SEGVORONOI_STATUS_TOO_LARGE) bad |= 128;
    }
    fixture_free(&f);
    return bad;
}

static void test_memory_limit(void) {
    int status = 0;
    pid_t child;
    fflush(stderr);
    child = fork();
    if (child == 0) _exit(limited_child());
    CHECK(child > 0);
    if (child <= 0) return;
    CHECK(waitpid(child, &status, 0) == child);
    CHECK(WIFEXITED(status)); /* not killed by an abort */
    if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
        fprintf(stderr, "memory-limit child failed: code %d\n", WEXITSTATUS(status));
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}
#endif

int segvoronoi_run_misuse_tests(void) {
    test_table();
    test_last_error_lifecycle();
    test_free_order();
    test_flag_bytes();
#if !defined(SEGVORONOI_C_TESTS_NO_MAIN) && !defined(SEGVORONOI_UNDER_ASAN)
    test_memory_limit();
#endif
    fprintf(stderr, "segvoronoi misuse tests: %d checks, %d failed\n", checks, failures);
    return failures;
}

#if !defined(SEGVORONOI_C_TESTS_NO_MAIN)
int main(void) { return segvoronoi_run_misuse_tests() == 0 ? 0 : 1; }
#endif
