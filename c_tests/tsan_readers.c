/* Concurrent readers of one diagram (issue 28, item 6): the header promises
 * that a diagram, a medial axis and an offset are immutable and may be read
 * from many threads at once. One diagram (a polygon with holes, points and
 * segments inside) is built with its medial axis and offsets, then 8 threads
 * released together by a barrier call every read-only entry point on them,
 * and make their own medial axes and offsets from the shared diagram. Each
 * thread folds what it reads into a checksum; all must agree with a run on
 * the main thread afterwards.
 *
 * Meant for a race detector: built with -fsanitize=thread (which sees the
 * C side and, when the library is built with -Zsanitizer=thread, the Rust
 * side too) or run under valgrind --tool=helgrind (which sees every memory
 * access of the uninstrumented library). The diagram is fresh when the
 * threads start, so lazily built tables (the edge of each half-edge) are
 * first built while all threads race for them.
 *
 *   tsan_readers [sites_per_side]     (default 12: about 200 sites)
 *
 * Plain C99 plus POSIX threads; reads only the public header. */

#define _POSIX_C_SOURCE 200809L

#include "segvoronoi.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define THREADS 8

static segvoronoi_diagram *diagram;
static segvoronoi_medial_axis *axis;
static segvoronoi_offset *offsets[3];
static const double distances[3] = {-0.05, -0.2, 0.3};
static pthread_barrier_t start;
static int failures = 0; /* written only by the main thread */

/* FNV-1a over the bytes of what a reader saw. */
typedef struct { uint64_t h; unsigned long calls, errors; } sum;
static void mix(sum *s, const void *p, size_t n) {
    const unsigned char *b = p;
    for (size_t i = 0; i < n; ++i) s->h = (s->h ^ b[i]) * 0x100000001B3ULL;
}
static void status(sum *s, segvoronoi_status st) {
    s->calls++;
    if (st != SEGVORONOI_STATUS_OK && st != SEGVORONOI_STATUS_BUFFER_TOO_SMALL) s->errors++;
    mix(s, &st, sizeof st);
}
#define MIX(s, v) mix((s), &(v), sizeof(v))

static void read_axis(sum *s, const segvoronoi_medial_axis *ax) {
    size_t nc = segvoronoi_medial_axis_chain_count(ax);
    double xyr[3 * 4096];
    MIX(s, nc);
    for (size_t c = 0; c < nc; ++c) {
        size_t np = 0, count = 0;
        bool closed = false;
        status(s, segvoronoi_medial_axis_chain(ax, c, &np, &closed));
        MIX(s, np), MIX(s, closed);
        for (size_t p = 0; p < np; ++p) {
            segvoronoi_piece pc = {.struct_size = sizeof pc};
            double at[3] = {0, 0, 0};
            status(s, segvoronoi_medial_axis_piece(ax, c, p, &pc));
            MIX(s, pc.edge), MIX(s, pc.ends[0].x), MIX(s, pc.ends[1].y), MIX(s, pc.clearance[0]);
            status(s, segvoronoi_medial_axis_piece_at(ax, c, p, 0.5, at));
            mix(s, at, sizeof at);
        }
        if (segvoronoi_medial_axis_sample_chain(ax, c, 1e-3, NULL, 0, &count) == SEGVORONOI_STATUS_OK && count <= 4096) {
            status(s, segvoronoi_medial_axis_sample_chain(ax, c, 1e-3, xyr, 4096, &count));
            mix(s, xyr, 3 * count * sizeof(double));
        }
    }
}

static void read_offset(sum *s, const segvoronoi_offset *o) {
    size_t nl = segvoronoi_offset_loop_count(o);
    double area = segvoronoi_offset_area(o), dist = segvoronoi_offset_distance(o);
    double xy[2 * 8192];
    MIX(s, nl), MIX(s, area), MIX(s, dist);
    for (size_t l = 0; l < nl; ++l) {
        segvoronoi_loop lp = {.struct_size = sizeof lp};
        size_t count = 0;
        status(s, segvoronoi_offset_loop(o, l, &lp));
        MIX(s, lp.piece_count), MIX(s, lp.parent), MIX(s, lp.signed_area);
        for (size_t p = 0; p < lp.piece_count; ++p) {
            segvoronoi_loop_piece pc = {.struct_size = sizeof pc};
            status(s, segvoronoi_offset_piece(o, l, p, &pc));
            MIX(s, pc.kind), MIX(s, pc.from[0]), MIX(s, pc.to[1]), MIX(s, pc.radius);
        }
        if (segvoronoi_offset_loop_polyline(o, l, 1e-3, NULL, 0, &count) == SEGVORONOI_STATUS_OK && count <= 8192) {
            status(s, segvoronoi_offset_loop_polyline(o, l, 1e-3, xy, 8192, &count));
            mix(s, xy, 2 * count * sizeof(double));
        }
    }
}

/* Every read-only entry point, in an order that depends on `who` so that
 * the threads do not walk in step. */
static void read_all(sum *s, int who) {
    const segvoronoi_diagram *d = diagram;
    size_t ns = segvoronoi_diagram_site_count(d), nv = segvoronoi_diagram_vertex_count(d);
    size_t ne = segvoronoi_diagram_edge_count(d), np = segvoronoi_diagram_point_site_count(d);
    uint32_t ids[4096];
    double xy[2 * 4096];
    size_t count;
    MIX(s, ns), MIX(s, nv), MIX(s, ne), MIX(s, np);
    for (size_t k = 0; k < ns; ++k) {
        size_t i = (k + (size_t)who * 7) % ns, idx = 0;
        segvoronoi_site site = {.struct_size = sizeof site};
        uint32_t loc = 0, ends[2] = {0, 0};
        bool unb = false;
        status(s, segvoronoi_diagram_cell_edges(d, i, ids, 4096, &count)), mix(s, ids, count * 4);
        status(s, segvoronoi_diagram_cell_half_edges(d, i, ids, 4096, &count)), mix(s, ids, count * 4);
        status(s, segvoronoi_diagram_cell_neighbors(d, i, ids, 4096, &count)), mix(s, ids, count * 4);
        status(s, segvoronoi_diagram_site(d, i, &site)), MIX(s, site.x), MIX(s, site.y2);
        status(s, segvoronoi_diagram_cell_is_unbounded(d, i, &unb)), MIX(s, unb);
        status(s, segvoronoi_diagram_cell_location(d, i, &loc)), MIX(s, loc);
        if (i >= np) {
            status(s, segvoronoi_diagram_segment_endpoints(d, i, ends)), mix(s, ends, sizeof ends);
            status(s, segvoronoi_diagram_segment_input_index(d, i, &idx)), MIX(s, idx);
        }
    }
    for (size_t k = 0; k < nv; ++k) {
        size_t i = (k + (size_t)who * 13) % nv;
        segvoronoi_vertex v = {.struct_size = sizeof v};
        uint32_t he[3] = {0, 0, 0}, loc = 0;
        status(s, segvoronoi_diagram_vertex(d, i, &v)), MIX(s, v.x), MIX(s, v.clearance), mix(s, v.sites, sizeof v.sites);
        status(s, segvoronoi_diagram_vertex_half_edges(d, i, he)), mix(s, he, sizeof he);
        status(s, segvoronoi_diagram_vertex_location(d, i, &loc)), MIX(s, loc);
    }
    for (size_t k = 0; k < ne; ++k) {
        size_t i = (k + (size_t)who * 17) % ne;
        segvoronoi_edge e = {.struct_size = sizeof e};
        segvoronoi_edge_shape sh = {.struct_size = sizeof sh};
        uint32_t h = (uint32_t)(2 * i), out = 0, loc = 0;
        double bz[6] = {0};
        status(s, segvoronoi_diagram_edge(d, i, &e)), MIX(s, e.sites), MIX(s, e.ends[0].x), MIX(s, e.is_infinite);
        status(s, segvoronoi_diagram_edge_shape(d, i, &sh)), MIX(s, sh.kind), MIX(s, sh.focus_x);
        if (sh.kind == SEGVORONOI_EDGE_PARABOLA && !e.is_infinite) status(s, segvoronoi_diagram_edge_bezier(d, i, bz)), mix(s, bz, sizeof bz);
        if (!e.is_infinite) status(s, segvoronoi_diagram_edge_polyline(d, i, 1e-3, xy, 4096, &count)), mix(s, xy, 2 * count * sizeof(double));
        status(s, segvoronoi_diagram_edge_location(d, i, &loc)), MIX(s, loc);
        status(s, segvoronoi_diagram_half_edge_next(d, h, &out)), MIX(s, out);
        status(s, segvoronoi_diagram_half_edge_prev(d, h ^ 1, &out)), MIX(s, out);
        status(s, segvoronoi_diagram_half_edge_cell(d, h, &out)), MIX(s, out);
    }
    uint32_t hint = SEGVORONOI_NO_SITE;
    for (int k = 0; k < 200; ++k) {
        double x = 0.5 + 0.45 * cos(k * 0.7 + who), y = 0.5 + 0.45 * sin(k * 1.3), mx = 0, my = 0, r = 0, disp = 0, ext = 0;
        uint32_t site = 0, loc = 0;
        status(s, segvoronoi_diagram_nearest_site(d, x, y, hint, &site)), MIX(s, site);
        hint = (k % 3) ? site : SEGVORONOI_NO_SITE;
        status(s, segvoronoi_diagram_locate_point(d, x, y, &loc)), MIX(s, loc);
        if (k % 50 == 0) {
            status(s, segvoronoi_diagram_max_inscribed_circle(d, &mx, &my, &r)), MIX(s, mx), MIX(s, r);
            status(s, segvoronoi_diagram_inscribed_circles(d, xy, 1000, &count)), mix(s, xy, 3 * (count < 1000 ? count : 1000) * sizeof(double));
            status(s, segvoronoi_diagram_max_split_displacement(d, &disp)), MIX(s, disp);
            status(s, segvoronoi_diagram_extent(d, &ext)), MIX(s, ext);
        }
    }
    segvoronoi_stats st = {.struct_size = sizeof st};
    status(s, segvoronoi_diagram_stats(d, &st)), MIX(s, st.vertices), MIX(s, st.edges);
    for (size_t i = 0; i < segvoronoi_diagram_piece_count(d); ++i) {
        double p[4] = {0};
        uint32_t site = 0;
        status(s, segvoronoi_diagram_piece(d, i, p)), mix(s, p, sizeof p);
        status(s, segvoronoi_diagram_inputs_of_piece(d, i, ids, 4096, &count)), mix(s, ids, count * 4);
        if (i < st.input_segments) status(s, segvoronoi_diagram_pieces_of_input(d, i, ids, 4096, &count)), mix(s, ids, count * 4);
        status(s, segvoronoi_diagram_site_of_segment(d, i, &site)), MIX(s, site);
    }
    {
        char *text = NULL;
        size_t len = 0;
        uint32_t site = 0;
        status(s, segvoronoi_diagram_site_of_input(d, 0, &site)), MIX(s, site);
        status(s, segvoronoi_diagram_topology(d, SEGVORONOI_TOPOLOGY_VORONOI_PAIRS, &text, &len));
        if (text) mix(s, text, len);
        segvoronoi_string_free(text);
        status(s, segvoronoi_diagram_validate(d));
        bool dom = segvoronoi_diagram_has_domain(d);
        MIX(s, dom);
    }
    /* the shared medial axis and offsets, then this thread's own */
    read_axis(s, axis);
    for (int k = 0; k < 3; ++k) read_offset(s, offsets[(k + who) % 3]);
    {
        segvoronoi_medial_axis *mine = NULL;
        segvoronoi_medial_axis_filter f = {.struct_size = sizeof f, .corner_filter = true, .corner_angle = 120, .spur_filter = false, .spur_factor = 0};
        segvoronoi_offset *own[3] = {NULL, NULL, NULL};
        status(s, segvoronoi_diagram_medial_axis_filtered(d, &f, &mine));
        if (mine) read_axis(s, mine);
        segvoronoi_medial_axis_free(mine);
        status(s, segvoronoi_diagram_offsets(d, distances, 3, own));
        for (int k = 0; k < 3; ++k) {
            if (own[k]) read_offset(s, own[k]);
            segvoronoi_offset_free(own[k]);
        }
    }
}

static void *reader(void *arg) {
    sum *s = arg;
    pthread_barrier_wait(&start);
    read_all(s, 0); /* who = 0: every thread folds the same sequence */
    return NULL;
}

static segvoronoi_diagram *build(int n) {
    segvoronoi_builder *b = segvoronoi_builder_new();
    segvoronoi_diagram *d = NULL;
    double *xy = malloc(sizeof(double) * 2 * (size_t)(4 * n + 16));
    size_t rings[3];
    size_t k = 0;
    if (!b || !xy) return NULL;
    /* outer square [0,1]^2 with n points per side, two holes */
    for (int i = 0; i < n; ++i) xy[2 * k] = (double)i / n, xy[2 * k + 1] = 0, ++k;
    for (int i = 0; i < n; ++i) xy[2 * k] = 1, xy[2 * k + 1] = (double)i / n, ++k;
    for (int i = 0; i < n; ++i) xy[2 * k] = 1 - (double)i / n, xy[2 * k + 1] = 1, ++k;
    for (int i = 0; i < n; ++i) xy[2 * k] = 0, xy[2 * k + 1] = 1 - (double)i / n, ++k;
    rings[0] = k;
    {
        const double hole1[] = {0.2, 0.2, 0.2, 0.4, 0.4, 0.4, 0.4, 0.2};
        const double hole2[] = {0.6, 0.6, 0.65, 0.8, 0.8, 0.7};
        memcpy(xy + 2 * k, hole1, sizeof hole1), k += 4, rings[1] = 4;
        memcpy(xy + 2 * k, hole2, sizeof hole2), k += 3, rings[2] = 3;
    }
    if (segvoronoi_builder_add_polygon(b, xy, rings, 3) != SEGVORONOI_STATUS_OK) return NULL;
    for (int i = 0; i < n; ++i) {
        double x = 0.1 + 0.8 * (i * 0.618033988749895 - floor(i * 0.618033988749895)), y = 0.5 + 0.3 * sin(i * 2.1);
        if ((x > 0.15 && x < 0.45 && y > 0.15 && y < 0.45) || (x > 0.55 && y > 0.55)) continue;
        segvoronoi_builder_add_point(b, x, y);
    }
    segvoronoi_builder_add_segment(b, 0.5, 0.1, 0.55, 0.3);
    segvoronoi_builder_add_segment(b, 0.55, 0.3, 0.45, 0.5);
    if (segvoronoi_builder_build(b, &d) != SEGVORONOI_STATUS_OK) {
        fprintf(stderr, "build failed: %s\n", segvoronoi_builder_last_error(b));
        d = NULL;
    }
    segvoronoi_builder_free(b);
    free(xy);
    return d;
}

int main(int argc, char **argv) {
    int n = argc > 1 ? atoi(argv[1]) : 12;
    pthread_t t[THREADS];
    sum sums[THREADS], ref;
    if (n < 2) n = 2;
    diagram = build(n);
    if (!diagram) return 1;
    if (segvoronoi_diagram_medial_axis(diagram, &axis) != SEGVORONOI_STATUS_OK ||
        segvoronoi_diagram_offsets(diagram, distances, 3, offsets) != SEGVORONOI_STATUS_OK) {
        fprintf(stderr, "medial axis or offsets failed\n");
        return 1;
    }
    pthread_barrier_init(&start, NULL, THREADS);
    for (int i = 0; i < THREADS; ++i) {
        memset(&sums[i], 0, sizeof sums[i]);
        sums[i].h = 0xcbf29ce484222325ULL;
        if (pthread_create(&t[i], NULL, reader, &sums[i]) != 0) { fprintf(stderr, "pthread_create failed\n"); return 1; }
    }
    for (int i = 0; i < THREADS; ++i) pthread_join(t[i], NULL);
    pthread_barrier_destroy(&start);
    memset(&ref, 0, sizeof ref);
    ref.h = 0xcbf29ce484222325ULL;
    read_all(&ref, 0);
    for (int i = 0; i < THREADS; ++i)
        if (sums[i].h != ref.h || sums[i].calls != ref.calls) {
            fprintf(stderr, "thread %d read something else: %016llx / %lu calls, alone %016llx / %lu calls\n", i,
                    (unsigned long long)sums[i].h, sums[i].calls, (unsigned long long)ref.h, ref.calls);
            ++failures;
        }
    if (ref.errors) fprintf(stderr, "%lu calls failed\n", ref.errors), ++failures;
    printf("tsan_readers: %zu sites, %zu vertices, %zu edges; %d threads x %lu calls, checksum %016llx: %s\n",
           segvoronoi_diagram_site_count(diagram), segvoronoi_diagram_vertex_count(diagram), segvoronoi_diagram_edge_count(diagram),
           THREADS, ref.calls, (unsigned long long)ref.h, failures ? "FAILED" : "all agree");
    for (int k = 0; k < 3; ++k) segvoronoi_offset_free(offsets[k]);
    segvoronoi_medial_axis_free(axis);
    segvoronoi_diagram_free(diagram);
    return failures ? 1 : 0;
}
