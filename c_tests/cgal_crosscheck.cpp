// segvoronoi_cgal_check: builds the Voronoi diagram of one set of points and
// line segments with segvoronoi (through its C API) and with CGAL's segment
// Delaunay graph (exact predicates), writes both in the canonical topology of
// src/query/topology.rs and compares them as multisets of lines.
//
//   segvoronoi_cgal_check <family> <n> [seed]
//   segvoronoi_cgal_check --file input.txt [--degenerate]
//   segvoronoi_cgal_check --search SECONDS [seed] [--generic] [--no-subnormal] [--out DIR]
//   segvoronoi_cgal_check --minimise input.txt [--degenerate]
//
// Point families: uniform, clustered, tiny, tiny-offset, huge (generic: EDGES
// and FACES must agree exactly) and lattice, circle, collinear, tiny-lattice,
// snapped (degenerate: only VPAIRS and VVERTICES are unique, so only they
// must agree). Segment families (n = number of segments, all non-crossing):
// seg-random1/2/3 (the three generators of seed 000 in [0,1]^2), seg-short
// (random short segments), polyline (a random non-crossing walk of
// random-length steps), square-hole (8 segments, n ignored), polygon-holes
// (a random polygon with random polygonal holes, n corners in all),
// letter-gap (the outline of a capital R, every segment shortened at both
// ends by its own amounts, n ignored) and near-vertical (segments whose x
// changes by 1e-9 of their length, half of them chained) are generic;
// polygon (regular n-gon), star (n segments from one point), tangent (n
// segments tangent to the unit circle), seg-lattice (the unit segments of an
// integer grid), parallel (n equal, equally spaced parallel segments) and
// letter (the R with shared endpoints and a font's aligned corners) are
// degenerate; inscribed, inscribed-jitter (n-gons inscribed in a circle of
// radius 1e-6 .. 1e6 by seed), fan (n equal spokes in random directions)
// kinked-chain (joints turning by 1e-8 .. 1e-15 rad by seed), ulp-off-line
// (short segments, each with a point one ulp off its line), ulp-ends (a
// chain whose joints are open by one ulp) and glyph (the two rings of an
// "O" flattened into chords at integer font units) are near-degenerate,
// compared as generic (as degenerate where CGAL finds an exact degeneracy).
// boost-split (n random segments on the integer grid of side 1e6, every
// crossing split at the crossing point rounded to the grid, as
// Boost.Polygon's benchmark data; about 2.4 n pieces) is generic. For faces
// with segments CGAL's Voronoi vertex is a double construction, so
// VPAIRS/VVERTICES of segment inputs decide zero length from rounded
// positions; they are checked for the degenerate families and informational
// otherwise (and left out of a generic run when CGAL's construction is not
// finite, as for nearly collinear segments). The file is in Boost.Polygon's
// text format: P, then P lines "x y", then S, then S lines "x1 y1 x2 y2". Exit
// status: 0 agreement and a valid diagram, 1 a difference or an invalid
// diagram, 2 bad usage or input, 3 a library error.
//
// --search runs small random inputs until SECONDS are up (seed: a new one
// each run unless given; printed first). Kinds, one drawn per input:
// integer junctions (2..40 segments in [0, 20|1000|1e6]^2, 30% of endpoints
// reused so that up to ten segments meet), stars (3..10 spokes pointing in
// or out, a few points), polylines (2..40 steps, sometimes closed), snapped
// floats (multiples of 2^-2..2^-6 with endpoint reuse), small boost-split
// inputs, and near-degenerate ones (small-grid junctions or snapped floats
// with points moved by a few ulps, zeros to subnormals, or by 1e-12 or
// 1e-9). Junctions in [0, 20]^2 and snapped floats are compared as
// degenerate, the rest as generic (--generic: only those, without the
// near-degenerate ones; --no-subnormal: without the zeros moved to
// subnormals); a generic input that CGAL finds exactly
// degenerate (a Voronoi edge of length zero) is compared as degenerate when
// the generic comparison differs. Each input is checked as generated, with
// every segment reversed and shuffled. A difference, an invalid diagram or
// a library error (an INTERSECTING status included: the generators only
// make legal inputs, checked exactly) is a failure: it is minimised (drop
// segments and points one at a time while it still fails, in a few orders,
// then turn reversed segments back) and printed in the input format (and
// written to DIR with --out). Ends with "search: inputs=N per_minute=M
// failures=K"; exit status 1 when K > 0. --minimise applies the same
// minimisation to a failing file.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Segment_Delaunay_graph_hierarchy_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "segvoronoi.h"

namespace {

// ---------------------------------------------------------------------------
// Input
// ---------------------------------------------------------------------------

struct Point {
    double x;
    double y;
};

struct Segment {
    Point a;
    Point b;
};

struct Input {
    std::string family;
    std::vector<Point> points;
    std::vector<Segment> segments;
    // Degenerate input has many valid Delaunay graphs: only the Voronoi
    // sections (positive-length edges, merged vertices) are unique.
    bool degenerate = false;
};

// splitmix64: tiny, and the same sequence on every platform (the standard
// library's distributions are implementation-defined).
class Rng {
  public:
    explicit Rng(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }

    // Uniform in [0, 1), 53 random bits.
    double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

    std::size_t below(std::size_t bound) { return static_cast<std::size_t>(next() % bound); }

    // Standard normal by Box-Muller (one of the pair is enough here).
    double normal() {
        const double u = 1.0 - unit();  // in (0, 1], so the log is finite
        const double v = unit();
        const double two_pi = 6.283185307179586;
        return std::sqrt(-2.0 * std::log(u)) * std::cos(two_pi * v);
    }

  private:
    std::uint64_t state_;
};

template <class T>
void shuffle(std::vector<T>& items, Rng& rng) {
    for (std::size_t i = items.size(); i > 1; --i) {
        std::swap(items[i - 1], items[rng.below(i)]);
    }
}

std::vector<Point> scaled_uniform(std::size_t n, Rng& rng, double offset, double size) {
    std::vector<Point> points(n);
    for (auto& p : points) {
        p.x = offset + size * rng.unit();
        p.y = offset + size * rng.unit();
    }
    return points;
}

// Gaussian clusters of different spreads around random centres.
std::vector<Point> clustered(std::size_t n, Rng& rng) {
    const std::size_t cluster_count = std::max<std::size_t>(1, n / 500);
    std::vector<Point> centres(cluster_count);
    std::vector<double> spreads(cluster_count);
    for (std::size_t c = 0; c < cluster_count; ++c) {
        centres[c] = {0.1 + 0.8 * rng.unit(), 0.1 + 0.8 * rng.unit()};
        spreads[c] = 0.001 + 0.02 * rng.unit();
    }
    std::vector<Point> points(n);
    for (auto& p : points) {
        const std::size_t c = rng.below(cluster_count);
        p.x = centres[c].x + spreads[c] * rng.normal();
        p.y = centres[c].y + spreads[c] * rng.normal();
    }
    return points;
}

// The integer grid side x side with side = floor(sqrt(n)), shuffled: every
// unit square is cocircular.
std::vector<Point> lattice(std::size_t n, Rng& rng) {
    std::size_t side = static_cast<std::size_t>(std::sqrt(static_cast<double>(n)));
    while ((side + 1) * (side + 1) <= n) ++side;
    std::vector<Point> points;
    points.reserve(side * side);
    for (std::size_t i = 0; i < side; ++i) {
        for (std::size_t j = 0; j < side; ++j) {
            points.push_back({static_cast<double>(i), static_cast<double>(j)});
        }
    }
    shuffle(points, rng);
    return points;
}

// Every integer point of x^2 + y^2 = R^2 for R = 5*13*17*29*37*41: R^2 is a
// product of six squared primes of the form 4k + 1, so it has 4 * 3^6 = 2916
// representations, all exactly cocircular (and R^2 < 2^53, so exact doubles).
// Shuffled; the first n are kept.
std::vector<Point> circle(std::size_t n, Rng& rng) {
    const std::int64_t radius = 5LL * 13 * 17 * 29 * 37 * 41;
    const std::int64_t r2 = radius * radius;
    std::vector<Point> points;
    for (std::int64_t x = 0; x <= radius; ++x) {
        const std::int64_t rest = r2 - x * x;
        std::int64_t y = static_cast<std::int64_t>(std::sqrt(static_cast<double>(rest)));
        while (y * y > rest) --y;
        while ((y + 1) * (y + 1) <= rest) ++y;
        if (y * y != rest) continue;
        // (x, y) with x >= 0, y >= 0 and its mirror images, each once.
        for (const std::int64_t sx : {1, -1}) {
            for (const std::int64_t sy : {1, -1}) {
                if ((sx < 0 && x == 0) || (sy < 0 && y == 0)) continue;
                points.push_back({static_cast<double>(sx * x), static_cast<double>(sy * y)});
            }
        }
    }
    shuffle(points, rng);
    if (points.size() > n) points.resize(n);
    return points;
}

// Points (i, 2i + 1) on one line, about a tenth of them repeated, shuffled.
std::vector<Point> collinear(std::size_t n, Rng& rng) {
    const std::size_t repeats = n / 10;
    const std::size_t distinct = n - repeats;
    std::vector<Point> points;
    points.reserve(n);
    for (std::size_t i = 0; i < distinct; ++i) {
        const double t = static_cast<double>(i);
        points.push_back({t, 2.0 * t + 1.0});
    }
    for (std::size_t k = 0; k < repeats && distinct > 0; ++k) {
        points.push_back(points[rng.below(distinct)]);
    }
    shuffle(points, rng);
    return points;
}

// The lattice scaled by 2^-600 (exact): Voronoi edges about 1e-181 long,
// whose squared lengths underflow. Exactly as degenerate as the lattice.
std::vector<Point> tiny_lattice(std::size_t n, Rng& rng) {
    std::vector<Point> points = lattice(n, rng);
    for (Point& p : points) p = {std::ldexp(p.x, -600), std::ldexp(p.y, -600)};
    return points;
}

// Coordinates drawn from a few values, some a hair apart (1e-20, 3e-17 next
// to 0 and 1): many repeats, collinear and cocircular points, and
// near-collinear triples whose Voronoi vertices are hard to place.
std::vector<Point> snapped(std::size_t n, Rng& rng) {
    const double values[] = {0.0, 1.0, -1.0, 1e-20, -1e-20, 2.0, 0.5, -3e-17};
    const std::size_t count = sizeof values / sizeof values[0];
    std::vector<Point> points(n);
    for (Point& p : points) p = {values[rng.below(count)], values[rng.below(count)]};
    return points;
}

// ---------------------------------------------------------------------------
// Segment families. Every crossing test is exact (CGAL's filtered
// orientation), so the generators never hand over two segments that the
// library's exact input check would call intersecting.
// ---------------------------------------------------------------------------

using Ek = CGAL::Exact_predicates_inexact_constructions_kernel;

CGAL::Orientation orient(const Point& a, const Point& b, const Point& c) {
    return CGAL::orientation(Ek::Point_2(a.x, a.y), Ek::Point_2(b.x, b.y), Ek::Point_2(c.x, c.y));
}

// c lies on the closed segment ab, given that a, b, c are collinear.
bool on_collinear_segment(const Point& a, const Point& b, const Point& c) {
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
           c.y <= std::max(a.y, b.y);
}

// The closed segments share at least one point.
bool closed_segments_meet(const Segment& s, const Segment& t) {
    const CGAL::Orientation o1 = orient(s.a, s.b, t.a), o2 = orient(s.a, s.b, t.b);
    const CGAL::Orientation o3 = orient(t.a, t.b, s.a), o4 = orient(t.a, t.b, s.b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == CGAL::COLLINEAR && on_collinear_segment(s.a, s.b, t.a)) ||
           (o2 == CGAL::COLLINEAR && on_collinear_segment(s.a, s.b, t.b)) ||
           (o3 == CGAL::COLLINEAR && on_collinear_segment(t.a, t.b, s.a)) ||
           (o4 == CGAL::COLLINEAR && on_collinear_segment(t.a, t.b, s.b));
}

// Segments sharing exactly one endpoint meet legally unless they overlap.
bool segments_conflict(const Segment& s, const Segment& t) {
    auto same = [](const Point& p, const Point& q) { return p.x == q.x && p.y == q.y; };
    const bool shared = same(s.a, t.a) || same(s.a, t.b) || same(s.b, t.a) || same(s.b, t.b);
    if (!shared) return closed_segments_meet(s, t);
    // Shared endpoint p: a conflict only if the other endpoint of one lies
    // on the other segment (collinear overlap, or a repeat).
    const Point& sp = same(s.a, t.a) || same(s.a, t.b) ? s.a : s.b;
    const Point& so = same(sp, s.a) ? s.b : s.a;
    const Point& to = same(sp, t.a) ? t.b : t.a;
    if (orient(sp, so, to) != CGAL::COLLINEAR) return false;
    return on_collinear_segment(sp, so, to) || on_collinear_segment(sp, to, so);
}

// Segments registered in every cell of their bounding box; a query walks
// along the segment in steps of at most one cell and visits the 3x3 cells
// around each step, which covers every cell the segment passes through.
class SegmentGrid {
  public:
    SegmentGrid(Point lo, Point hi, std::size_t side)
        : lo_(lo), side_(side), cells_(side * side),
          h_(std::max(hi.x - lo.x, hi.y - lo.y) / static_cast<double>(side)) {}

    void add(const Segment& s, std::size_t id) {
        const std::size_t x0 = cell(std::min(s.a.x, s.b.x) - lo_.x), x1 = cell(std::max(s.a.x, s.b.x) - lo_.x);
        const std::size_t y0 = cell(std::min(s.a.y, s.b.y) - lo_.y), y1 = cell(std::max(s.a.y, s.b.y) - lo_.y);
        for (std::size_t x = x0; x <= x1; ++x)
            for (std::size_t y = y0; y <= y1; ++y) cells_[x * side_ + y].push_back(id);
    }

    // Calls visit(id) once for every registered segment near s (a superset
    // of those meeting s) until visit returns true; returns whether it did.
    template <class Visit>
    bool any_near(const Segment& s, Visit visit) {
        ++stamp_;
        const double length = std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
        const std::size_t steps = 1 + static_cast<std::size_t>(length / h_);
        std::size_t last_x = SIZE_MAX, last_y = SIZE_MAX;
        for (std::size_t k = 0; k <= steps; ++k) {
            const double t = static_cast<double>(k) / static_cast<double>(steps);
            const std::size_t cx = cell(s.a.x + t * (s.b.x - s.a.x) - lo_.x);
            const std::size_t cy = cell(s.a.y + t * (s.b.y - s.a.y) - lo_.y);
            if (cx == last_x && cy == last_y) continue;
            last_x = cx;
            last_y = cy;
            for (std::size_t x = cx == 0 ? 0 : cx - 1; x <= std::min(cx + 1, side_ - 1); ++x) {
                for (std::size_t y = cy == 0 ? 0 : cy - 1; y <= std::min(cy + 1, side_ - 1); ++y) {
                    for (std::size_t id : cells_[x * side_ + y]) {
                        if (id >= seen_.size()) seen_.resize(id + 1, 0);
                        if (seen_[id] == stamp_) continue;
                        seen_[id] = stamp_;
                        if (visit(id)) return true;
                    }
                }
            }
        }
        return false;
    }

  private:
    std::size_t cell(double offset) const {
        if (!(offset > 0.0)) return 0;
        const double c = std::floor(offset / h_);
        return c >= static_cast<double>(side_ - 1) ? side_ - 1 : static_cast<std::size_t>(c);
    }

    Point lo_;
    std::size_t side_;
    std::vector<std::vector<std::size_t>> cells_;
    double h_;
    std::vector<std::uint64_t> seen_;
    std::uint64_t stamp_ = 0;
};

std::size_t grid_side(std::size_t n) {
    return std::max<std::size_t>(4, std::min<std::size_t>(2048, static_cast<std::size_t>(std::sqrt(static_cast<double>(n)))));
}

Segment random_unit_segment(Rng& rng) {
    Segment s;
    s.a = {rng.unit(), rng.unit()};
    s.b = {rng.unit(), rng.unit()};
    return s;
}

// Seed 000, method 1: draw a segment, redraw while it meets an earlier one.
std::vector<Segment> seg_random1(std::size_t n, Rng& rng) {
    std::vector<Segment> out;
    SegmentGrid grid({0.0, 0.0}, {1.0, 1.0}, grid_side(n));
    while (out.size() < n) {
        const Segment s = random_unit_segment(rng);
        if (grid.any_near(s, [&](std::size_t id) { return closed_segments_meet(s, out[id]); })) continue;
        grid.add(s, out.size());
        out.push_back(s);
    }
    return out;
}

// Seed 000, method 2: draw a segment; for each earlier segment in order that
// it crosses, move its second endpoint to the 1:9 point between the crossing
// and the first endpoint (90% of the way from the first endpoint).
std::vector<Segment> seg_random2(std::size_t n, Rng& rng) {
    std::vector<Segment> out;
    SegmentGrid grid({0.0, 0.0}, {1.0, 1.0}, grid_side(n));
    while (out.size() < n) {
        Segment s = random_unit_segment(rng);
        bool ok = false;
        // The new segment only ever shrinks along itself, so one pass in
        // index order suffices in exact arithmetic; the rounded new endpoint
        // may leave the line by an ulp, hence the re-check.
        for (int round = 0; round < 8 && !ok; ++round) {
            std::vector<std::size_t> near;
            grid.any_near(s, [&](std::size_t id) { near.push_back(id); return false; });
            std::sort(near.begin(), near.end());
            for (std::size_t id : near) {
                const Segment& t = out[id];
                if (!closed_segments_meet(s, t)) continue;
                const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
                const double ex = t.b.x - t.a.x, ey = t.b.y - t.a.y;
                const double den = dx * ey - dy * ex;
                double u = den != 0.0 ? ((t.a.x - s.a.x) * ey - (t.a.y - s.a.y) * ex) / den : 0.0;
                u = std::min(1.0, std::max(0.0, u));
                s.b = {s.a.x + 0.9 * u * dx, s.a.y + 0.9 * u * dy};
            }
            ok = !grid.any_near(s, [&](std::size_t id) { return closed_segments_meet(s, out[id]); });
        }
        if (!ok || (s.a.x == s.b.x && s.a.y == s.b.y)) continue;  // degenerate leftovers: draw again
        grid.add(s, out.size());
        out.push_back(s);
    }
    return out;
}

// Seed 000, method 3: draw n segments; test the pairs (i, j), i < j, in
// lexicographic order and swap the second endpoints of every crossing pair
// (which shortens the total length, so it ends), until no pair crosses.
std::vector<Segment> seg_random3(std::size_t n, Rng& rng) {
    std::vector<Segment> s(n);
    for (Segment& seg : s) seg = random_unit_segment(rng);
    auto box_apart = [](const Segment& p, const Segment& q) {
        return std::max(p.a.x, p.b.x) < std::min(q.a.x, q.b.x) || std::max(q.a.x, q.b.x) < std::min(p.a.x, p.b.x) ||
               std::max(p.a.y, p.b.y) < std::min(q.a.y, q.b.y) || std::max(q.a.y, q.b.y) < std::min(p.a.y, p.b.y);
    };
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = i + 1; j < n; ++j) {
                if (box_apart(s[i], s[j]) || !closed_segments_meet(s[i], s[j])) continue;
                std::swap(s[i].b, s[j].b);
                changed = true;
            }
        }
    }
    return s;
}

// Short segments: random position and direction, length 1/sqrt(n) of the
// unit square; a segment meeting an earlier one is dropped (and redrawn,
// until there are n).
std::vector<Segment> seg_short(std::size_t n, Rng& rng) {
    std::vector<Segment> out;
    const double length = 1.0 / std::sqrt(static_cast<double>(std::max<std::size_t>(n, 1)));
    SegmentGrid grid({-length, -length}, {1.0 + length, 1.0 + length}, grid_side(n));
    while (out.size() < n) {
        Segment s;
        s.a = {rng.unit(), rng.unit()};
        const double angle = 6.283185307179586 * rng.unit();
        s.b = {s.a.x + length * std::cos(angle), s.a.y + length * std::sin(angle)};
        if (grid.any_near(s, [&](std::size_t id) { return closed_segments_meet(s, out[id]); })) continue;
        grid.add(s, out.size());
        out.push_back(s);
    }
    return out;
}

// A random walk of n short steps in the unit square that never meets itself
// except where consecutive steps share their endpoint (a steps that would is
// redrawn; a walk that gets stuck restarts from a new random point).
std::vector<Segment> polyline(std::size_t n, Rng& rng) {
    std::vector<Segment> out;
    // Steps of random length: equal steps would make every sharp turn a
    // degenerate spike (the perpendiculars at both far ends meet the angle
    // bisector in one point), which the family is not meant to test.
    const double unit_length = 0.5 / std::sqrt(static_cast<double>(std::max<std::size_t>(n, 1)));
    SegmentGrid grid({-0.1, -0.1}, {1.1, 1.1}, grid_side(n));
    Point at{rng.unit(), rng.unit()};
    int stuck = 0;
    while (out.size() < n) {
        const double angle = 6.283185307179586 * rng.unit();
        const double length = unit_length * (0.5 + rng.unit());
        Segment s{at, {at.x + length * std::cos(angle), at.y + length * std::sin(angle)}};
        const bool outside = s.b.x < 0.0 || s.b.x > 1.0 || s.b.y < 0.0 || s.b.y > 1.0;
        // The previous step shares `at` with this one: only an overlap is a
        // conflict there; with any other segment, any contact is.
        auto conflict = [&](std::size_t id) {
            const bool previous = id + 1 == out.size() && out[id].b.x == at.x && out[id].b.y == at.y;
            return previous ? segments_conflict(s, out[id]) : closed_segments_meet(s, out[id]);
        };
        if (outside || grid.any_near(s, conflict)) {
            if (++stuck > 200) {
                at = {rng.unit(), rng.unit()};
                stuck = 0;
            }
            continue;
        }
        stuck = 0;
        grid.add(s, out.size());
        out.push_back(s);
        at = s.b;
    }
    return out;
}

// The regular n-gon on the unit circle (every side touches the inscribed
// circle: one Voronoi vertex of degree n at the centre).
std::vector<Segment> polygon(std::size_t n) {
    std::vector<Point> corners(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double angle = 6.283185307179586 * static_cast<double>(k) / static_cast<double>(n);
        corners[k] = {std::cos(angle), std::sin(angle)};
    }
    std::vector<Segment> out;
    for (std::size_t k = 0; k < n; ++k) out.push_back({corners[k], corners[(k + 1) % n]});
    return out;
}

// The scale of a near-degenerate family's seed-th run: 1e-6, 1e-3, 1, 1e3,
// 1e6 in turn, so that every magnitude meets the same shapes.
double seed_scale(std::uint64_t seed) {
    const double scales[] = {1e-6, 1e-3, 1.0, 1e3, 1e6};
    return scales[seed % 5];
}

// A polygon inscribed in a circle: n corners on the circle of radius
// seed_scale(seed) (rounded, so cocircular only to the last bit), at
// regular angles or, jittered, each moved along the circle by up to a third
// of the spacing. Issue 7's circles flattened into chords.
std::vector<Segment> inscribed(std::size_t n, std::uint64_t seed, Rng& rng, bool jitter) {
    const double radius = seed_scale(seed), spacing = 6.283185307179586 / static_cast<double>(n);
    std::vector<Point> corners(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double angle = spacing * (static_cast<double>(k) + (jitter ? (rng.unit() - 0.5) * 0.66 : 0.0));
        corners[k] = {radius * std::cos(angle), radius * std::sin(angle)};
    }
    std::vector<Segment> out;
    for (std::size_t k = 0; k < n; ++k) out.push_back({corners[k], corners[(k + 1) % n]});
    return out;
}

// n spokes of equal length from one point in random directions (at least
// 1e-3 rad apart): their far ends lie on one circle up to rounding.
std::vector<Segment> fan(std::size_t n, std::uint64_t seed, Rng& rng) {
    const double length = seed_scale(seed);
    std::vector<double> angles;
    while (angles.size() < n) {
        const double a = 6.283185307179586 * rng.unit();
        bool apart = true;
        for (double b : angles) {
            const double d = std::fabs(a - b);
            if (std::min(d, 6.283185307179586 - d) < 1e-3) apart = false;
        }
        if (apart) angles.push_back(a);
    }
    std::vector<Segment> out;
    for (double a : angles) out.push_back({{0.0, 0.0}, {length * std::cos(a), length * std::sin(a)}});
    return out;
}

// A chain of n segments of unit-ish length along a gentle curve whose
// every joint turns by 10^-(8 + seed % 8) rad, left or right at random:
// chains with kinks of 1e-8 .. 1e-15 rad.
std::vector<Segment> kinked_chain(std::size_t n, std::uint64_t seed, Rng& rng) {
    const double kink = std::pow(10.0, -8.0 - static_cast<double>(seed % 8));
    double heading = 6.283185307179586 * rng.unit();
    Point at = {0.0, 0.0};
    std::vector<Segment> out;
    for (std::size_t k = 0; k < n; ++k) {
        const double length = 0.5 + rng.unit();
        const Point next = {at.x + length * std::cos(heading), at.y + length * std::sin(heading)};
        out.push_back({at, next});
        at = next;
        heading += rng.unit() < 0.5 ? kink : -kink;
    }
    return out;
}

bool legal_addition(const std::vector<Segment>& segs, const Segment& s);
bool legal_point(const std::vector<Segment>& segs, const Point& p);
bool same_point(const Point& p, const Point& q);

// Short random segments in the cells of a grid (one per cell, scaled by
// seed_scale(seed)), and near each a point one ulp off its line, either
// side: on the line's extension beyond an end, or beside the segment at a
// third of its length (the point's y moved by one ulp from where the line
// passes; kept when legal: not inside a segment).
void ulp_off_line(std::size_t n, std::uint64_t seed, Rng& rng, Input& input) {
    const double scale = seed_scale(seed);
    const std::size_t side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    for (std::size_t k = 0; k < n; ++k) {
        const double cx = static_cast<double>(k % side) * 4.0, cy = static_cast<double>(k / side) * 4.0;
        const Point a = {scale * (cx + rng.unit()), scale * (cy + rng.unit())};
        const Point b = {scale * (cx + 1.5 + rng.unit()), scale * (cy + 1.5 + rng.unit())};
        input.segments.push_back({a, b});
    }
    for (const Segment& s : input.segments) {
        const double t = rng.unit() < 0.5 ? 1.0 / 3.0 : 1.5;
        const double x = s.a.x + t * (s.b.x - s.a.x);
        // where the line passes at x, rounded, then one ulp up or down
        const double y_line = s.a.y + (x - s.a.x) * (s.b.y - s.a.y) / (s.b.x - s.a.x);
        const double y = std::nextafter(y_line, rng.unit() < 0.5 ? INFINITY : -INFINITY);
        const Point p = {x, y};
        if (legal_point(input.segments, p) && !same_point(p, s.a) && !same_point(p, s.b)) input.points.push_back(p);
    }
}

// Chains whose consecutive segments do not meet: each starts one ulp (in x)
// from where the last ended, turned by a random angle (kept when legal).
std::vector<Segment> ulp_ends(std::size_t n, std::uint64_t seed, Rng& rng) {
    const double scale = seed_scale(seed);
    std::vector<Segment> out;
    Point at = {0.0, 0.0};
    double heading = 0.0;
    for (std::size_t tries = 0; out.size() < n && tries < 20 * n; ++tries) {
        heading += (rng.unit() - 0.5) * 2.5;
        const double length = scale * (0.5 + rng.unit());
        const Point start = {std::nextafter(at.x, rng.unit() < 0.5 ? INFINITY : -INFINITY), at.y};
        const Segment s = {start, {start.x + length * std::cos(heading), start.y + length * std::sin(heading)}};
        if (!legal_addition(out, s)) continue;
        out.push_back(s);
        at = s.b;
    }
    return out;
}

// Glyph-like outlines: the rings of an "O" (an outer and an inner ellipse,
// off-centre, a thin stroke on one side), each flattened into n / 2 chords
// at font-unit precision (corners rounded to integers, as TrueType glyphs
// are), the whole scaled by a power of two by seed.
std::vector<Segment> glyph(std::size_t n, std::uint64_t seed, Rng& rng) {
    const double unit = std::ldexp(1.0, static_cast<int>(seed % 5) * 4 - 8);
    const std::size_t chords = std::max<std::size_t>(n / 2, 3);
    std::vector<Segment> out;
    const double rings[2][4] = {{0.0, 0.0, 600.0, 720.0}, {40.0 + 20.0 * rng.unit(), 0.0, 470.0, 610.0}};
    for (const auto& ring : rings) {
        std::vector<Point> corners;
        for (std::size_t k = 0; k < chords; ++k) {
            const double angle = 6.283185307179586 * (static_cast<double>(k) + 0.3 * rng.unit()) / static_cast<double>(chords);
            const Point p = {unit * std::round(ring[0] + ring[2] * std::cos(angle)),
                             unit * std::round(ring[1] + ring[3] * std::sin(angle))};
            if (corners.empty() || !same_point(corners.back(), p)) corners.push_back(p);
        }
        while (corners.size() > 1 && same_point(corners.front(), corners.back())) corners.pop_back();
        for (std::size_t k = 0; k < corners.size(); ++k) {
            const Segment s = {corners[k], corners[(k + 1) % corners.size()]};
            if (legal_addition(out, s)) out.push_back(s);
        }
    }
    return out;
}

// n segments from the origin in evenly spaced directions, random lengths.
std::vector<Segment> star(std::size_t n, Rng& rng) {
    std::vector<Segment> out;
    for (std::size_t k = 0; k < n; ++k) {
        const double angle = 6.283185307179586 * static_cast<double>(k) / static_cast<double>(n);
        const double r = 0.5 + rng.unit();
        out.push_back({{0.0, 0.0}, {r * std::cos(angle), r * std::sin(angle)}});
    }
    return out;
}

// A square with a smaller, rotated, off-centre square hole: two closed
// polygons of four segments each.
std::vector<Segment> square_hole() {
    const Point outer[4] = {{0.0, 0.0}, {10.0, 0.0}, {10.0, 10.0}, {0.0, 10.0}};
    Point inner[4];
    for (int k = 0; k < 4; ++k) {
        const double angle = 0.3 + 1.5707963267948966 * k;
        inner[k] = {4.3 + 2.0 * std::cos(angle), 5.7 + 2.0 * std::sin(angle)};
    }
    std::vector<Segment> out;
    for (int k = 0; k < 4; ++k) out.push_back({outer[k], outer[(k + 1) % 4]});
    for (int k = 0; k < 4; ++k) out.push_back({inner[k], inner[(k + 1) % 4]});
    return out;
}

// The closed polygon through `corners` in order: one segment per corner.
void add_closed_polygon(const std::vector<Point>& corners, std::vector<Segment>& out) {
    for (std::size_t k = 0; k < corners.size(); ++k) out.push_back({corners[k], corners[(k + 1) % corners.size()]});
}

// A random polygon star-shaped around `centre`: m corners at increasing
// jittered angles (every angular gap is below pi, so the polygon is
// simple) and radii in [r_min, r_max].
std::vector<Point> random_star_polygon(Point centre, std::size_t m, double r_min, double r_max, Rng& rng) {
    const double two_pi = 6.283185307179586;
    const double start = two_pi * rng.unit();
    std::vector<Point> corners(m);
    for (std::size_t k = 0; k < m; ++k) {
        const double angle = start + two_pi * (static_cast<double>(k) + 0.5 * rng.unit()) / static_cast<double>(m);
        const double r = r_min + (r_max - r_min) * rng.unit();
        corners[k] = {centre.x + r * std::cos(angle), centre.y + r * std::sin(angle)};
    }
    return corners;
}

// A random simple polygon with holes, n corners (= segments) in all: an
// outer star-shaped polygon with radii in [0.9, 1] around the origin, and
// h holes, each a smaller random star-shaped polygon inside its own cell of
// a grid over [-0.55, 0.55]^2 (inside radius 0.78, so inside the outer
// polygon; one hole per cell, so the holes are disjoint). Random
// coordinates: generic.
std::vector<Segment> polygon_holes(std::size_t n, Rng& rng) {
    const std::size_t holes = std::max<std::size_t>(3, std::min<std::size_t>(32, n / 32));
    const std::size_t hole_corners = std::max<std::size_t>(3, n / (4 * holes));
    const std::size_t outer_corners = n > holes * hole_corners + 3 ? n - holes * hole_corners : 3;
    std::vector<Segment> out;
    add_closed_polygon(random_star_polygon({0.0, 0.0}, outer_corners, 0.9, 1.0, rng), out);
    std::size_t side = 1;
    while (side * side < holes) ++side;
    const double cell = 1.1 / static_cast<double>(side);
    std::vector<std::size_t> cells(side * side);
    std::iota(cells.begin(), cells.end(), 0);
    shuffle(cells, rng);
    for (std::size_t h = 0; h < holes; ++h) {
        const double cx = -0.55 + cell * (static_cast<double>(cells[h] % side) + 0.45 + 0.1 * rng.unit());
        const double cy = -0.55 + cell * (static_cast<double>(cells[h] / side) + 0.45 + 0.1 * rng.unit());
        const double r_max = cell * (0.3 + 0.1 * rng.unit());
        add_closed_polygon(random_star_polygon({cx, cy}, hole_corners, 0.5 * r_max, r_max, rng), out);
    }
    return out;
}

// The integer lattice side x side cut into unit segments: every horizontal
// and vertical unit segment between neighbouring lattice points, up to four
// segments per point, every unit square a cocircular cell (degenerate).
// side is the largest with 2 side (side - 1) <= n; shuffled, random
// directions.
std::vector<Segment> seg_lattice(std::size_t n, Rng& rng) {
    std::size_t side = 2;
    while (2 * (side + 1) * side <= n) ++side;
    std::vector<Segment> out;
    for (std::size_t i = 0; i < side; ++i) {
        for (std::size_t j = 0; j < side; ++j) {
            const double x = static_cast<double>(i), y = static_cast<double>(j);
            if (i + 1 < side) out.push_back({{x, y}, {x + 1.0, y}});
            if (j + 1 < side) out.push_back({{x, y}, {x, y + 1.0}});
        }
    }
    shuffle(out, rng);
    for (Segment& s : out) {
        if (rng.below(2) == 1) std::swap(s.a, s.b);
    }
    return out;
}

// Seed 000, figure 8 (3): n short segments tangent to the unit circle at
// the angles 2 pi k / n, each half as long as the gap to its neighbours'
// tangent lines allows (so none touch). The centre is equidistant from all
// of them (degenerate, up to the rounding of the coordinates).
std::vector<Segment> tangent(std::size_t n) {
    const double pi = 3.141592653589793;
    const double half = 0.5 * std::tan(pi / static_cast<double>(n));
    std::vector<Segment> out;
    for (std::size_t k = 0; k < n; ++k) {
        const double angle = 2.0 * pi * static_cast<double>(k) / static_cast<double>(n);
        const double c = std::cos(angle), s = std::sin(angle);
        out.push_back({{c + half * s, s - half * c}, {c - half * s, s + half * c}});
    }
    return out;
}

// Seed 000, figure 8 (4): n parallel segments (0, k)-(n, k), k = 0..n-1,
// regularly spaced with aligned endpoints: exactly degenerate (the
// endpoints lie on two lines, equally spaced).
std::vector<Segment> parallel(std::size_t n) {
    std::vector<Segment> out;
    const double length = static_cast<double>(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double y = static_cast<double>(k);
        out.push_back({{0.0, y}, {length, y}});
    }
    return out;
}

// Seed 000, figure 8 (5): the outline of a capital R on a 100 x 100 box,
// its bowl approximated by straight pieces: an outer polygon of 15
// segments and the counter (a hole) of 7, sharing endpoints at every
// corner. Hand-picked integer coordinates with a font's alignments (the
// stem's inner edge and the counter's left side on x = 20, the corners
// (20, 40) and (20, 58) aligned, parallel horizontal runs), so not
// generic. With `gaps`, segment k is shortened by its own amounts, between
// 0.2 and 0.7, at each end, so that no two segments touch (the seed's form
// of input) and no two pulled-apart endpoints line up again: equal gaps
// would put the two endpoints of a corner symmetric about its angle
// bisector, where both perpendiculars meet, a point equidistant from all
// four sites.
std::vector<Segment> letter_r(bool gaps) {
    const std::vector<Point> outer = {{0, 0},   {20, 0},  {20, 40}, {38, 40}, {63, 0},
                                      {88, 0},  {61, 44}, {71, 48}, {79, 55}, {84, 65},
                                      {85, 74}, {81, 84}, {73, 92}, {60, 100}, {0, 100}};
    const std::vector<Point> counter = {{20, 58}, {57, 58}, {63, 61}, {66, 69}, {65, 76}, {59, 82}, {20, 82}};
    std::vector<Segment> out;
    add_closed_polygon(outer, out);
    add_closed_polygon(counter, out);
    if (gaps) {
        for (std::size_t k = 0; k < out.size(); ++k) {
            Segment& s = out[k];
            const double golden = 0.6180339887498949 * static_cast<double>(k);
            const double silver = 0.41421356237309503 * static_cast<double>(k) + 0.3;
            const double start_gap = 0.2 + 0.5 * (golden - std::floor(golden));
            const double end_gap = 0.2 + 0.5 * (silver - std::floor(silver));
            const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
            const double length = std::hypot(dx, dy);
            const double t0 = start_gap / length, t1 = end_gap / length;
            s = {{s.a.x + t0 * dx, s.a.y + t0 * dy}, {s.b.x - t1 * dx, s.b.y - t1 * dy}};
        }
    }
    return out;
}

// Almost vertical segments (Boost.Polygon's Voronoi had bugs with vertical
// and nearly vertical input): n segments of random length about
// 1/sqrt(n) in the unit square whose x changes by at most 1e-9 of their
// length. Every other segment, where it fits, continues the previous one
// from its upper endpoint (a shared endpoint with a tiny kink); the rest
// start at random points. A segment meeting an earlier one is redrawn.
// Random coordinates: generic.
std::vector<Segment> near_vertical(std::size_t n, Rng& rng) {
    std::vector<Segment> out;
    const double unit_length = 1.0 / std::sqrt(static_cast<double>(std::max<std::size_t>(n, 1)));
    SegmentGrid grid({-0.1, -0.1}, {1.1, 2.1}, grid_side(n));
    while (out.size() < n) {
        const bool chain = !out.empty() && rng.below(2) == 1;
        const Point a = chain ? out.back().b : Point{rng.unit(), rng.unit()};
        const double length = unit_length * (0.5 + rng.unit());
        const double dx = (2.0 * rng.unit() - 1.0) * 1e-9 * length;
        const Segment s{a, {a.x + dx, a.y + length}};
        if (s.b.x == s.a.x || s.b.y > 2.0) continue;  // exactly vertical, or off the grid
        auto conflict = [&](std::size_t id) {
            const bool previous = chain && id + 1 == out.size();
            return previous ? segments_conflict(s, out[id]) : closed_segments_meet(s, out[id]);
        };
        if (grid.any_near(s, conflict)) continue;
        grid.add(s, out.size());
        out.push_back(s);
    }
    return out;
}

// ---------------------------------------------------------------------------
// Boost.Polygon's benchmark style: random segments on the integer grid, every
// crossing split at the crossing point rounded to the grid (what
// boost::polygon::intersect_segments does to the benchmark data).
// ---------------------------------------------------------------------------

bool same_point(const Point& p, const Point& q) { return p.x == q.x && p.y == q.y; }

// The pairs (i, j), i < j, of segments that the library would reject
// (crossing, overlapping, touching away from a shared endpoint), found
// through a grid over the bounding box (all pairs below 64 segments).
std::vector<std::pair<std::size_t, std::size_t>> conflicting_pairs(const std::vector<Segment>& segs) {
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    if (segs.size() < 64) {
        for (std::size_t i = 0; i < segs.size(); ++i)
            for (std::size_t j = i + 1; j < segs.size(); ++j)
                if (segments_conflict(segs[i], segs[j])) pairs.emplace_back(i, j);
        return pairs;
    }
    Point lo = segs[0].a, hi = segs[0].a;
    for (const Segment& s : segs) {
        for (const Point& p : {s.a, s.b}) {
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
        }
    }
    SegmentGrid grid(lo, {hi.x + 1.0, hi.y + 1.0}, grid_side(segs.size()));
    for (std::size_t j = 0; j < segs.size(); ++j) {
        grid.any_near(segs[j], [&](std::size_t i) {
            if (segments_conflict(segs[i], segs[j])) pairs.emplace_back(i, j);
            return false;
        });
        grid.add(segs[j], j);
    }
    return pairs;
}

// The crossing point of two properly crossing segments, rounded to the
// integer grid.
Point rounded_crossing(const Segment& s, const Segment& t) {
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    const double ex = t.b.x - t.a.x, ey = t.b.y - t.a.y;
    const double den = dx * ey - dy * ex;
    const double u = ((t.a.x - s.a.x) * ey - (t.a.y - s.a.y) * ex) / den;
    return {std::round(s.a.x + u * dx), std::round(s.a.y + u * dy)};
}

bool in_open_segment(const Segment& s, const Point& p) {
    return !same_point(p, s.a) && !same_point(p, s.b) && orient(s.a, s.b, p) == CGAL::COLLINEAR &&
           on_collinear_segment(s.a, s.b, p);
}

// Splits crossing segments at their rounded crossing points and segments
// touched inside by another's endpoint at that endpoint, round after round
// (rounding moves a crossing point off both lines, so the pieces can cross
// again); after `rounds` rounds, or for overlaps, the later segment of each
// remaining conflicting pair is dropped. Pieces keep their parent's
// direction; zero-length and repeated pieces are left out.
std::vector<Segment> split_at_rounded_crossings(std::vector<Segment> segs, int rounds = 12) {
    for (int round = 0; round < rounds; ++round) {
        const auto pairs = conflicting_pairs(segs);
        if (pairs.empty()) return segs;
        std::vector<std::vector<Point>> cuts(segs.size());
        std::vector<bool> drop(segs.size(), false);
        for (const auto& pair : pairs) {
            const Segment& s = segs[pair.first];
            const Segment& t = segs[pair.second];
            const CGAL::Orientation o1 = orient(s.a, s.b, t.a), o2 = orient(s.a, s.b, t.b);
            const CGAL::Orientation o3 = orient(t.a, t.b, s.a), o4 = orient(t.a, t.b, s.b);
            if (o1 * o2 < 0 && o3 * o4 < 0) {
                const Point q = rounded_crossing(s, t);
                cuts[pair.first].push_back(q);
                cuts[pair.second].push_back(q);
                continue;
            }
            bool touched = false;
            for (const Point& p : {t.a, t.b})
                if (in_open_segment(s, p)) cuts[pair.first].push_back(p), touched = true;
            for (const Point& p : {s.a, s.b})
                if (in_open_segment(t, p)) cuts[pair.second].push_back(p), touched = true;
            // Collinear overlap: no cut separates the two.
            if (o1 == CGAL::COLLINEAR && o2 == CGAL::COLLINEAR) drop[pair.second] = true;
            else if (!touched) drop[pair.second] = true;
        }
        std::vector<Segment> next;
        std::map<std::pair<std::pair<double, double>, std::pair<double, double>>, bool> seen;
        for (std::size_t i = 0; i < segs.size(); ++i) {
            if (drop[i]) continue;
            const Segment& s = segs[i];
            std::vector<Point>& c = cuts[i];
            const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
            auto along = [&](const Point& p) { return (p.x - s.a.x) * dx + (p.y - s.a.y) * dy; };
            std::sort(c.begin(), c.end(), [&](const Point& p, const Point& q) { return along(p) < along(q); });
            Point from = s.a;
            c.push_back(s.b);
            for (const Point& to : c) {
                if (same_point(from, to)) continue;
                std::pair<double, double> ka{from.x, from.y}, kb{to.x, to.y};
                if (kb < ka) std::swap(ka, kb);
                if (seen.emplace(std::make_pair(ka, kb), true).second) next.push_back({from, to});
                from = to;
            }
        }
        segs.swap(next);
    }
    const auto pairs = conflicting_pairs(segs);
    std::vector<bool> drop(segs.size(), false);
    for (const auto& pair : pairs) {
        if (!drop[pair.first]) drop[pair.second] = true;
    }
    std::vector<Segment> kept;
    for (std::size_t i = 0; i < segs.size(); ++i)
        if (!drop[i]) kept.push_back(segs[i]);
    return kept;
}

// n random segments with integer endpoints in [0, side]^2, lengths uniform
// in [0, 3 side / sqrt(n)] (about 1.4 crossings per segment), then split
// at the rounded crossings: many segments meeting at shared points, kinks
// of near-zero angle where a crossing point was rounded.
std::vector<Segment> boost_split(std::size_t n, Rng& rng, double side = 1e6) {
    const double max_length = 3.0 * side / std::sqrt(static_cast<double>(std::max<std::size_t>(n, 1)));
    std::vector<Segment> segs;
    segs.reserve(n);
    const double two_pi = 6.283185307179586;
    while (segs.size() < n) {
        const Point a{std::floor(rng.unit() * (side + 1.0)), std::floor(rng.unit() * (side + 1.0))};
        const double angle = two_pi * rng.unit(), length = max_length * rng.unit();
        const Point b{std::round(a.x + length * std::cos(angle)), std::round(a.y + length * std::sin(angle))};
        if (same_point(a, b) || b.x < 0.0 || b.y < 0.0 || b.x > side || b.y > side) continue;
        segs.push_back({a, b});
    }
    return split_at_rounded_crossings(std::move(segs));
}

bool make_family(const std::string& family, std::size_t n, std::uint64_t seed, Input& input) {
    Rng rng(seed);
    input.family = family;
    input.degenerate = false;
    if (family == "uniform") {
        input.points = scaled_uniform(n, rng, 0.0, 1.0);
    } else if (family == "clustered") {
        input.points = clustered(n, rng);
    } else if (family == "tiny") {
        input.points = scaled_uniform(n, rng, 0.0, 1e-9);
    } else if (family == "tiny-offset") {
        input.points = scaled_uniform(n, rng, 1.0, 1e-9);
    } else if (family == "huge") {
        input.points = scaled_uniform(n, rng, 0.0, 1e9);
    } else if (family == "lattice") {
        input.points = lattice(n, rng);
        input.degenerate = true;
    } else if (family == "circle") {
        input.points = circle(n, rng);
        input.degenerate = true;
    } else if (family == "collinear") {
        input.points = collinear(n, rng);
        input.degenerate = true;
    } else if (family == "tiny-lattice") {
        input.points = tiny_lattice(n, rng);
        input.degenerate = true;
    } else if (family == "snapped") {
        input.points = snapped(n, rng);
        input.degenerate = true;
    } else if (family == "seg-random1") {
        input.segments = seg_random1(n, rng);
    } else if (family == "seg-random2") {
        input.segments = seg_random2(n, rng);
    } else if (family == "seg-random3") {
        input.segments = seg_random3(n, rng);
    } else if (family == "seg-short") {
        input.segments = seg_short(n, rng);
    } else if (family == "polyline") {
        input.segments = polyline(n, rng);
    } else if (family == "square-hole") {
        input.segments = square_hole();
    } else if (family == "polygon") {
        if (n < 3) return false;
        input.segments = polygon(n);
        input.degenerate = true;
    } else if (family == "star") {
        input.segments = star(n, rng);
        input.degenerate = true;
    } else if (family == "polygon-holes") {
        if (n < 3 * 4 + 3) return false;
        input.segments = polygon_holes(n, rng);
    } else if (family == "seg-lattice") {
        if (n < 4) return false;
        input.segments = seg_lattice(n, rng);
        input.degenerate = true;
    } else if (family == "tangent") {
        if (n < 3) return false;
        input.segments = tangent(n);
        input.degenerate = true;
    } else if (family == "parallel") {
        if (n < 2) return false;
        input.segments = parallel(n);
        input.degenerate = true;
    } else if (family == "letter") {
        input.segments = letter_r(false);
        input.degenerate = true;
    } else if (family == "letter-gap") {
        input.segments = letter_r(true);
    } else if (family == "near-vertical") {
        input.segments = near_vertical(n, rng);
    } else if (family == "boost-split") {
        input.segments = boost_split(n, rng);
    } else if (family == "inscribed" || family == "inscribed-jitter") {
        if (n < 3) return false;
        input.segments = inscribed(n, seed, rng, family == "inscribed-jitter");
    } else if (family == "fan") {
        if (n < 2) return false;
        input.segments = fan(n, seed, rng);
    } else if (family == "kinked-chain") {
        if (n < 2) return false;
        input.segments = kinked_chain(n, seed, rng);
    } else if (family == "ulp-off-line") {
        if (n < 1) return false;
        ulp_off_line(n, seed, rng, input);
    } else if (family == "ulp-ends") {
        if (n < 2) return false;
        input.segments = ulp_ends(n, seed, rng);
    } else if (family == "glyph") {
        if (n < 6) return false;
        input.segments = glyph(n, seed, rng);
    } else {
        return false;
    }
    return true;
}

// Boost.Polygon text format: P, P lines "x y", S, S lines "x0 y0 x1 y1".
// Writes the input in the format read_file reads, with every digit needed to
// read back the same doubles: a generated case becomes a file to debug with.
void write_text(std::FILE* out, const Input& input) {
    std::fprintf(out, "%zu\n", input.points.size());
    for (const Point& p : input.points) std::fprintf(out, "%.17g %.17g\n", p.x, p.y);
    std::fprintf(out, "%zu\n", input.segments.size());
    for (const Segment& s : input.segments) {
        std::fprintf(out, "%.17g %.17g %.17g %.17g\n", s.a.x, s.a.y, s.b.x, s.b.y);
    }
}

bool write_file(const std::string& path, const Input& input) {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (out == nullptr) return false;
    write_text(out, input);
    return std::fclose(out) == 0;
}

bool read_file(const std::string& path, Input& input, std::string& error) {
    std::ifstream in(path);
    if (!in) {
        error = "cannot open " + path;
        return false;
    }
    std::size_t point_count = 0;
    if (!(in >> point_count)) {
        error = "missing point count";
        return false;
    }
    input.points.resize(point_count);
    for (std::size_t i = 0; i < point_count; ++i) {
        Point& p = input.points[i];
        if (!(in >> p.x >> p.y) || !std::isfinite(p.x) || !std::isfinite(p.y)) {
            error = "point " + std::to_string(i) + " is missing, malformed or not finite";
            return false;
        }
    }
    std::size_t segment_count = 0;
    if (!(in >> segment_count)) segment_count = 0;  // the segment count may be left out
    input.segments.resize(segment_count);
    for (std::size_t i = 0; i < segment_count; ++i) {
        Segment& s = input.segments[i];
        if (!(in >> s.a.x >> s.a.y >> s.b.x >> s.b.y) || !std::isfinite(s.a.x) || !std::isfinite(s.a.y) ||
            !std::isfinite(s.b.x) || !std::isfinite(s.b.y)) {
            error = "segment " + std::to_string(i) + " is missing, malformed or not finite";
            return false;
        }
    }
    input.family = "file";
    return true;
}

// ---------------------------------------------------------------------------
// Canonical topology: sections of lines, each line a sorted list of names.
// ---------------------------------------------------------------------------

// Kind (0 = point "P", 1 = segment "S") and index: the pair order is the
// canonical name order (P before S, then numerically).
using Name = std::pair<int, std::uint32_t>;
using Line = std::vector<Name>;
// Line -> multiplicity.
using Section = std::map<Line, std::size_t>;

const char* const kSectionTitles[] = {"EDGES", "FACES", "VPAIRS", "VVERTICES"};

struct Topology {
    std::map<std::string, Section> sections;

    void add(const std::string& title, Line line) {
        std::sort(line.begin(), line.end());
        ++sections[title][line];
    }

    std::size_t count(const std::string& title) const {
        auto it = sections.find(title);
        if (it == sections.end()) return 0;
        std::size_t total = 0;
        for (const auto& entry : it->second) total += entry.second;
        return total;
    }

    const Section& section(const std::string& title) const {
        static const Section empty;
        auto it = sections.find(title);
        return it == sections.end() ? empty : it->second;
    }
};

std::string format_line(const Line& line) {
    std::string text;
    for (const Name& name : line) {
        if (!text.empty()) text += ' ';
        text += name.first == 0 ? 'P' : 'S';
        text += std::to_string(name.second);
    }
    return text;
}

Name parse_name(const std::string& token) {
    if (token.size() < 2 || (token[0] != 'P' && token[0] != 'S')) {
        throw std::runtime_error("bad site name '" + token + "'");
    }
    std::size_t used = 0;
    const unsigned long index = std::stoul(token.substr(1), &used);
    if (used != token.size() - 1) throw std::runtime_error("bad site name '" + token + "'");
    return {token[0] == 'P' ? 0 : 1, static_cast<std::uint32_t>(index)};
}

// Parses the library's text: "TITLE count" headers, each followed by
// exactly count lines of names. Throws on anything else.
Topology parse_topology(const std::string& text) {
    Topology topology;
    std::istringstream in(text);
    std::string header;
    while (std::getline(in, header)) {
        std::istringstream words(header);
        std::string title;
        std::size_t count = 0;
        if (!(words >> title >> count)) throw std::runtime_error("bad section header '" + header + "'");
        topology.sections[title];  // an empty section is still a section
        for (std::size_t i = 0; i < count; ++i) {
            std::string row;
            if (!std::getline(in, row)) throw std::runtime_error("section " + title + " is short");
            std::istringstream tokens(row);
            Line line;
            std::string token;
            while (tokens >> token) line.push_back(parse_name(token));
            if (line.empty()) throw std::runtime_error("empty line in section " + title);
            topology.add(title, line);
        }
    }
    return topology;
}

// Sites in the library's naming order: P<k> is the k-th distinct point of
// the list "isolated points, then each segment's first and second endpoint"
// (equal coordinates, and -0 == +0, which the map's ordering already treats
// as equal, are one site); S<j> is input segment j as an open segment, a
// repeated segment (either direction) named by its first occurrence, a
// zero-length one being a point only.
struct Sites {
    using Key = std::pair<double, double>;
    std::vector<Point> distinct;
    std::map<Key, std::uint32_t> index_of;
    // Unordered endpoint pair -> input index of the first such segment.
    std::map<std::pair<Key, Key>, std::uint32_t> segment_of;
    // Input indices of the distinct segments, in input order.
    std::vector<std::uint32_t> distinct_segments;

    explicit Sites(const Input& input) {
        for (const Point& p : input.points) add_point(p);
        for (const Segment& s : input.segments) {
            add_point(s.a);
            add_point(s.b);
        }
        for (std::size_t j = 0; j < input.segments.size(); ++j) {
            const Segment& s = input.segments[j];
            if (s.a.x == s.b.x && s.a.y == s.b.y) continue;
            if (segment_of.emplace(segment_key(s.a, s.b), static_cast<std::uint32_t>(j)).second) {
                distinct_segments.push_back(static_cast<std::uint32_t>(j));
            }
        }
    }

    static std::pair<Key, Key> segment_key(const Point& a, const Point& b) {
        Key ka{a.x, a.y}, kb{b.x, b.y};
        if (kb < ka) std::swap(ka, kb);
        return {ka, kb};
    }

    void add_point(const Point& p) {
        auto inserted = index_of.emplace(std::make_pair(p.x, p.y), static_cast<std::uint32_t>(distinct.size()));
        if (inserted.second) distinct.push_back({p.x == 0.0 ? 0.0 : p.x, p.y == 0.0 ? 0.0 : p.y});
    }

    std::size_t count() const { return distinct.size() + distinct_segments.size(); }

    std::uint32_t index(double x, double y) const {
        auto it = index_of.find(std::make_pair(x, y));
        if (it == index_of.end()) throw std::runtime_error("CGAL vertex at a point that is not an input point");
        return it->second;
    }

    std::uint32_t segment(const Point& a, const Point& b) const {
        auto it = segment_of.find(segment_key(a, b));
        if (it == segment_of.end()) throw std::runtime_error("CGAL segment site that is not an input segment");
        return it->second;
    }

    // Bounding-box diagonal of all points (endpoints included), computed as
    // the library does (halved first so that huge inputs do not overflow):
    // the scale of "zero length".
    double extent() const {
        if (distinct.empty()) return 0.0;
        Point lo = distinct[0], hi = distinct[0];
        for (const Point& p : distinct) {
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
        }
        return 2.0 * std::hypot(hi.x / 2.0 - lo.x / 2.0, hi.y / 2.0 - lo.y / 2.0);
    }
};

class UnionFind {
  public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }

    std::size_t root(std::size_t v) {
        while (parent_[v] != v) {
            parent_[v] = parent_[parent_[v]];
            v = parent_[v];
        }
        return v;
    }

    void join(std::size_t a, std::size_t b) { parent_[root(a)] = root(b); }

  private:
    std::vector<std::size_t> parent_;
};

double elapsed_ms(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// ---------------------------------------------------------------------------
// Our side, through the C API
// ---------------------------------------------------------------------------

struct OursResult {
    Topology plain;  // flags 0: EDGES, FACES
    Topology full;   // SEGVORONOI_TOPOLOGY_VORONOI_PAIRS (with the tolerance): all four sections
    double build_ms = 0.0;
    std::vector<std::string> problems;  // validity and consistency failures
};

class LibraryError : public std::runtime_error {
  public:
    explicit LibraryError(const std::string& message, segvoronoi_status status = SEGVORONOI_STATUS_OK)
        : std::runtime_error(message), status(status) {}
    // The status of the failing call (OK when the error is not a status).
    segvoronoi_status status;
};

void check_status(segvoronoi_status status, const char* call, const segvoronoi_builder* builder = nullptr) {
    if (status == SEGVORONOI_STATUS_OK) return;
    std::string message = std::string(call) + ": " + segvoronoi_status_str(status);
    if (builder != nullptr) message += std::string(" (") + segvoronoi_builder_last_error(builder) + ")";
    throw LibraryError(message, status);
}

std::string topology_text(const segvoronoi_diagram* diagram, std::uint32_t flags) {
    char* text = nullptr;
    std::size_t length = 0;
    check_status(segvoronoi_diagram_topology(diagram, flags, &text, &length), "segvoronoi_diagram_topology");
    std::string copy(text, length);
    segvoronoi_string_free(text);
    return copy;
}

void check_ours_consistent(const segvoronoi_diagram* diagram, const Sites& sites, OursResult& ours) {
    if (segvoronoi_diagram_validate(diagram) != SEGVORONOI_STATUS_OK) {
        ours.problems.push_back("segvoronoi_diagram_validate failed");
    }
    for (const char* title : {"EDGES", "FACES"}) {
        if (ours.plain.section(title) != ours.full.section(title)) {
            ours.problems.push_back(std::string(title) + " differs between the two topology calls");
        }
    }
    if (segvoronoi_diagram_site_count(diagram) != sites.count()) {
        ours.problems.push_back("site count " + std::to_string(segvoronoi_diagram_site_count(diagram)) +
                                " != distinct points and segments " + std::to_string(sites.count()));
    }
    if (segvoronoi_diagram_point_site_count(diagram) != sites.distinct.size()) {
        ours.problems.push_back("point site count " + std::to_string(segvoronoi_diagram_point_site_count(diagram)) +
                                " != distinct points " + std::to_string(sites.distinct.size()));
    }
    if (segvoronoi_diagram_edge_count(diagram) != ours.plain.count("EDGES")) {
        ours.problems.push_back("edge count differs from the EDGES section");
    }
    if (segvoronoi_diagram_vertex_count(diagram) != ours.plain.count("FACES")) {
        ours.problems.push_back("vertex count differs from the FACES section");
    }
}

OursResult build_ours(const Input& input, const Sites& sites) {
    OursResult ours;
    std::vector<double> xy;
    xy.reserve(2 * input.points.size());
    for (const Point& p : input.points) {
        xy.push_back(p.x);
        xy.push_back(p.y);
    }
    std::vector<double> segment_xy;
    segment_xy.reserve(4 * input.segments.size());
    for (const Segment& s : input.segments) {
        segment_xy.insert(segment_xy.end(), {s.a.x, s.a.y, s.b.x, s.b.y});
    }
    segvoronoi_builder* builder = segvoronoi_builder_new();
    if (builder == nullptr) throw LibraryError("segvoronoi_builder_new returned NULL");
    segvoronoi_diagram* diagram = nullptr;
    try {
        const auto start = std::chrono::steady_clock::now();
        check_status(segvoronoi_builder_add_points(builder, xy.data(), input.points.size()),
                     "segvoronoi_builder_add_points", builder);
        check_status(segvoronoi_builder_add_segments(builder, segment_xy.data(), input.segments.size()),
                     "segvoronoi_builder_add_segments", builder);
        check_status(segvoronoi_builder_build(builder, &diagram), "segvoronoi_builder_build", builder);
        ours.build_ms = elapsed_ms(start);
        ours.plain = parse_topology(topology_text(diagram, 0));
        // Zero length exactly (four sites on one circle), as CGAL's side below.
        ours.full = parse_topology(topology_text(diagram, SEGVORONOI_TOPOLOGY_VORONOI_PAIRS));
        check_ours_consistent(diagram, sites, ours);
    } catch (...) {
        segvoronoi_diagram_free(diagram);
        segvoronoi_builder_free(builder);
        throw;
    }
    segvoronoi_diagram_free(diagram);
    segvoronoi_builder_free(builder);
    return ours;
}

// ---------------------------------------------------------------------------
// CGAL's side
// ---------------------------------------------------------------------------

using K = CGAL::Simple_cartesian<double>;
// Exact predicates (interval filter, then Gmpq) on double input; segments
// meet at most at common endpoints, so the cheaper traits without
// intersections suffice.
using Gt = CGAL::Segment_Delaunay_graph_filtered_traits_without_intersections_2<K, CGAL::Field_with_sqrt_tag>;
using Sdg = CGAL::Segment_Delaunay_graph_hierarchy_2<Gt>;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

struct CgalResult {
    Topology topology;
    double build_ms = 0.0;
    int dimension = 0;
    // Finite edges whose four points are exactly cocircular: where the
    // Delaunay graph is not unique (diagnostic for "generic" inputs).
    std::size_t cocircular_edges = 0;
    // Finite edges whose Voronoi edge has length zero exactly (CGAL's exact
    // is_degenerate_edge; four distinct sites on one empty circle), with
    // segments too: the input is not generic, its EDGES and FACES not unique.
    std::size_t degenerate_edges = 0;
    // Why VPAIRS and VVERTICES were left out (empty if they were not): on a
    // generic input they are informational, so a Voronoi vertex that CGAL's
    // double construction cannot place (not finite, for nearly collinear
    // segments) drops them instead of failing the comparison.
    std::string voronoi_skipped;
};

// The canonical name of a CGAL vertex: a point site by its coordinates, a
// segment site by its two endpoints (unordered) -> input index.
Name site_name(const Sdg::Vertex_handle& v, const Sites& sites) {
    if (v->site().is_point()) {
        const K::Point_2 p = v->site().point();
        return {0, sites.index(p.x(), p.y())};
    }
    const K::Segment_2 seg = v->site().segment();
    return {1, sites.segment({seg.source().x(), seg.source().y()}, {seg.target().x(), seg.target().y()})};
}

// The two sites of an edge (f, i): the vertices of f other than i. In
// dimension 1 the edges are (f, 2), and ccw(2) = 0, cw(2) = 1 are the two
// vertices of the segment f, so the same rule holds.
std::pair<Sdg::Vertex_handle, Sdg::Vertex_handle> edge_vertices(const Sdg::Edge& e) {
    return {e.first->vertex(Sdg::ccw(e.second)), e.first->vertex(Sdg::cw(e.second))};
}

Epick::Point_2 as_epick(const Sdg::Vertex_handle& v) {
    const K::Point_2 p = v->site().point();
    return {p.x(), p.y()};
}

// Every distinct point (endpoints included) along a Hilbert curve, then
// every distinct open segment, ordered along the curve by its midpoint.
void build_cgal_graph(const Sites& sites, const Input& input, Sdg& sdg, CgalResult& cgal) {
    std::vector<K::Point_2> points;
    points.reserve(sites.distinct.size());
    for (const Point& p : sites.distinct) points.emplace_back(p.x, p.y);
    std::vector<K::Point_2> midpoints;
    for (std::uint32_t j : sites.distinct_segments) {
        const Segment& s = input.segments[j];
        midpoints.emplace_back(s.a.x / 2.0 + s.b.x / 2.0, s.a.y / 2.0 + s.b.y / 2.0);
    }
    std::vector<std::size_t> segment_order(midpoints.size());
    std::iota(segment_order.begin(), segment_order.end(), 0);
    using Traits = CGAL::Spatial_sort_traits_adapter_2<K, CGAL::Pointer_property_map<K::Point_2>::const_type>;
    CGAL::spatial_sort(segment_order.begin(), segment_order.end(), Traits(CGAL::make_property_map(static_cast<const std::vector<K::Point_2>&>(midpoints))));

    const auto start = std::chrono::steady_clock::now();
    CGAL::spatial_sort(points.begin(), points.end());
    for (const K::Point_2& p : points) sdg.insert(p);
    for (std::size_t k : segment_order) {
        const Segment& s = input.segments[sites.distinct_segments[k]];
        sdg.insert(K::Point_2(s.a.x, s.a.y), K::Point_2(s.b.x, s.b.y));
    }
    cgal.build_ms = elapsed_ms(start);
    cgal.dimension = sdg.dimension();
    if (sdg.number_of_vertices() != sites.count()) {
        throw std::runtime_error("CGAL kept " + std::to_string(sdg.number_of_vertices()) + " of " +
                                 std::to_string(sites.count()) + " distinct points and segments");
    }
}

// EDGES and FACES: every finite Delaunay edge and face.
void add_delaunay_sections(const Sdg& sdg, const Sites& sites, Topology& topology) {
    topology.sections["EDGES"];
    topology.sections["FACES"];
    if (sdg.dimension() >= 1) {
        for (auto e = sdg.finite_edges_begin(); e != sdg.finite_edges_end(); ++e) {
            const auto ends = edge_vertices(*e);
            topology.add("EDGES", {site_name(ends.first, sites), site_name(ends.second, sites)});
        }
    }
    if (sdg.dimension() == 2) {
        for (auto f = sdg.finite_faces_begin(); f != sdg.finite_faces_end(); ++f) {
            topology.add("FACES", {site_name(f->vertex(0), sites), site_name(f->vertex(1), sites),
                                   site_name(f->vertex(2), sites)});
        }
    }
}

// Whether the rational q is the square of a rational, and if so its root.
bool rational_sqrt(const CGAL::Gmpq& q, CGAL::Gmpq& root) {
    if (q < 0) return false;
    mpz_t num, den;
    mpz_init_set(num, mpq_numref(q.mpq()));
    mpz_init_set(den, mpq_denref(q.mpq()));
    const bool square = mpz_perfect_square_p(num) && mpz_perfect_square_p(den);
    if (square) {
        mpz_sqrt(num, num);
        mpz_sqrt(den, den);
        root = CGAL::Gmpq(CGAL::Gmpz(num), CGAL::Gmpz(den));
    }
    mpz_clear(num);
    mpz_clear(den);
    return square;
}

// The circle through the points p, q tangent to the line of the segment s
// with p, q and the touching point counter-clockwise (the Voronoi vertex of
// the face (p, q, s)), when it is rational: the centre X = M + t d on the
// bisector of p and q solves a quadratic in t whose discriminant is then a
// square.
bool rational_pps(const K::Point_2& p, const K::Point_2& q, const K::Segment_2& s, CGAL::Gmpq& x, CGAL::Gmpq& y) {
    using Q = CGAL::Gmpq;
    const Q px(p.x()), py(p.y()), qx(q.x()), qy(q.y());
    const Q ax(s.source().x()), ay(s.source().y()), bx(s.target().x()), by(s.target().y());
    const Q nx = ay - by, ny = bx - ax, c = nx * ax + ny * ay, n2 = nx * nx + ny * ny;
    const Q mx = (px + qx) / Q(2), my = (py + qy) / Q(2);
    const Q dx = py - qy, dy = qx - px;
    const Q alpha = nx * mx + ny * my - c, beta = nx * dx + ny * dy;
    const Q mp2 = (mx - px) * (mx - px) + (my - py) * (my - py), d2 = dx * dx + dy * dy;
    const Q qa = n2 * d2 - beta * beta, qb = Q(-2) * alpha * beta, qc = n2 * mp2 - alpha * alpha;
    std::vector<Q> roots;
    if (qa == 0) {
        if (qb == 0) return false;
        roots.push_back(-qc / qb);
    } else {
        Q root;
        if (!rational_sqrt(qb * qb - Q(4) * qa * qc, root)) return false;
        roots.push_back((-qb + root) / (Q(2) * qa));
        roots.push_back((-qb - root) / (Q(2) * qa));
    }
    for (const Q& t : roots) {
        const Q cx = mx + t * dx, cy = my + t * dy;
        // the touching point: the foot of the centre on the line
        const Q k = (nx * cx + ny * cy - c) / n2;
        const Q tx = cx - k * nx, ty = cy - k * ny;
        if ((qx - px) * (ty - py) - (qy - py) * (tx - px) > 0) {
            x = cx;
            y = cy;
            return true;
        }
    }
    return false;
}

// The Voronoi vertex of the face (a, b, c) (counter-clockwise) exactly,
// where it is rational: three points (the circumcentre); two points p, q
// and a segment with an endpoint among them (the bisector of p and q meets
// the segment's perpendicular at that endpoint); two points and a segment
// when the circle through them tangent to its line is rational
// (rational_pps). False otherwise (square roots, or segments only).
bool rational_vertex(const Gt::Site_2& a, const Gt::Site_2& b, const Gt::Site_2& c, CGAL::Gmpq& x, CGAL::Gmpq& y) {
    using Q = CGAL::Gmpq;
    std::vector<K::Point_2> points;
    const Gt::Site_2* segment = nullptr;
    // rotated so that a segment comes last: the points then keep the face's order
    const Gt::Site_2* order[3] = {&a, &b, &c};
    if (a.is_segment()) order[0] = &b, order[1] = &c, order[2] = &a;
    if (b.is_segment()) order[0] = &c, order[1] = &a, order[2] = &b;
    for (const Gt::Site_2* site : order) {
        if (site->is_point()) {
            points.push_back(site->point());
        } else if (segment == nullptr) {
            segment = site;
        } else {
            return false;
        }
    }
    // the centre is on the lines n1 . X = c1 and n2 . X = c2
    Q n1x, n1y, c1, n2x, n2y, c2;
    const auto bisector = [](const K::Point_2& p, const K::Point_2& q, Q& nx, Q& ny, Q& cc) {
        nx = Q(q.x()) - Q(p.x());
        ny = Q(q.y()) - Q(p.y());
        cc = (nx * (Q(p.x()) + Q(q.x())) + ny * (Q(p.y()) + Q(q.y()))) / Q(2);
    };
    bisector(points[0], points[1], n1x, n1y, c1);
    if (segment == nullptr) {
        bisector(points[0], points[2], n2x, n2y, c2);
    } else {
        const K::Segment_2 seg = segment->segment();
        const bool at_source = seg.source() == points[0] || seg.source() == points[1];
        const bool at_target = seg.target() == points[0] || seg.target() == points[1];
        if (at_source && at_target) return false;
        if (!at_source && !at_target) return rational_pps(points[0], points[1], seg, x, y);
        const K::Point_2 e = at_source ? seg.source() : seg.target(), f = at_source ? seg.target() : seg.source();
        n2x = Q(f.x()) - Q(e.x());
        n2y = Q(f.y()) - Q(e.y());
        c2 = n2x * Q(e.x()) + n2y * Q(e.y());
    }
    const Q det = n1x * n2y - n1y * n2x;
    if (det == 0) return false;
    x = (c1 * n2y - c2 * n1y) / det;
    y = (n1x * c2 - n2x * c1) / det;
    return true;
}

// Whether the Voronoi edge of a finite Delaunay edge between two finite
// faces has length zero, exactly: the apex of the second face lies on the
// circle of the first, and the other way. Two faces of the
// same three sites (far apart, with segments) are two different circles, for
// which the predicate is trivially true, so they are excluded.
//
// CGAL's predicate (it asks both ways: each apex on the other face's
// circle) counts an open segment that touches a circle only at its
// endpoint as outside it, so where a face's circle is tangent to a segment
// at one of the face's points (the centre on the segment's perpendicular
// there), the two vertices are one point but the predicate says no; the
// library, deciding zero length geometrically, says yes. So edges whose two
// vertices are rational (rational_vertex) are compared as points in exact
// rationals; CGAL's predicate decides the rest. (A circle of three points
// that touches a segment only at its endpoint, another of the points, is
// not the segment's vertex with the other two: that one touches the open
// segment.) Still open: two vertices with square
// roots (a general point-point-segment circle) that coincide through such
// a touching.
bool is_zero_length_edge(const Sdg& sdg, const Sdg::Edge& e) {
    const Sdg::Vertex_handle apex = e.first->vertex(e.second);
    const Sdg::Vertex_handle mirror = sdg.tds().mirror_vertex(e.first, e.second);
    if (apex == mirror) return false;
    const auto ends = edge_vertices(e);
    const Gt::Site_2 &p = ends.first->site(), &q = ends.second->site(), &r = apex->site(), &s = mirror->site();
    CGAL::Gmpq x1, y1, x2, y2;
    if (rational_vertex(p, q, r, x1, y1) && rational_vertex(q, p, s, x2, y2)) return x1 == x2 && y1 == y2;
    return sdg.geom_traits().is_degenerate_edge_2_object()(p, q, r, s);
}

// VPAIRS and VVERTICES, zero length decided exactly (is_zero_length_edge),
// as the library does by default. An edge next to an infinite face is a ray
// (or a line), always of positive length.
void add_voronoi_sections(const Sdg& sdg, const Sites& sites, CgalResult& cgal) {
    Topology& topology = cgal.topology;
    topology.sections["VPAIRS"];
    topology.sections["VVERTICES"];
    if (sdg.dimension() < 1) return;

    std::unordered_map<const void*, std::size_t> face_number;
    std::vector<Sdg::Face_handle> faces;
    if (sdg.dimension() == 2) {
        for (auto f = sdg.finite_faces_begin(); f != sdg.finite_faces_end(); ++f) {
            face_number.emplace(&*f, faces.size());
            faces.push_back(f);
        }
    }

    UnionFind merged(faces.size());
    for (auto e = sdg.finite_edges_begin(); e != sdg.finite_edges_end(); ++e) {
        const auto ends = edge_vertices(*e);
        const Line pair = {site_name(ends.first, sites), site_name(ends.second, sites)};
        const bool finite = sdg.dimension() == 2 && !sdg.is_infinite(e->first) &&
                            !sdg.is_infinite(e->first->neighbor(e->second));
        if (!finite) {
            topology.add("VPAIRS", pair);
            continue;
        }
        const std::size_t a = face_number.at(&*e->first);
        const std::size_t b = face_number.at(&*e->first->neighbor(e->second));
        if (is_zero_length_edge(sdg, *e)) {
            merged.join(a, b);
        } else {
            topology.add("VPAIRS", pair);
        }
        const Sdg::Vertex_handle apex_a = e->first->vertex(e->second);
        const Sdg::Vertex_handle apex_b = sdg.tds().mirror_vertex(e->first, e->second);
        const bool all_points = ends.first->site().is_point() && ends.second->site().is_point() &&
                                apex_a->site().is_point() && apex_b->site().is_point();
        if (all_points && CGAL::side_of_oriented_circle(as_epick(ends.first), as_epick(ends.second),
                                                        as_epick(apex_a), as_epick(apex_b)) ==
                              CGAL::ON_ORIENTED_BOUNDARY) {
            ++cgal.cocircular_edges;
        }
    }

    std::map<std::size_t, Line> groups;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        Line& group = groups[merged.root(f)];
        for (int i = 0; i < 3; ++i) {
            const Name name = site_name(faces[f]->vertex(i), sites);
            if (std::find(group.begin(), group.end(), name) == group.end()) group.push_back(name);
        }
    }
    for (auto& entry : groups) topology.add("VVERTICES", entry.second);
}

// Only edges between two finite faces (is_zero_length_edge leaves out two
// faces of the same three sites).
void count_degenerate_edges(const Sdg& sdg, CgalResult& cgal) {
    if (sdg.dimension() < 2) return;
    for (auto e = sdg.finite_edges_begin(); e != sdg.finite_edges_end(); ++e) {
        const Sdg::Face_handle f = e->first, g = f->neighbor(e->second);
        if (sdg.is_infinite(f) || sdg.is_infinite(g)) continue;
        if (is_zero_length_edge(sdg, *e)) ++cgal.degenerate_edges;
    }
}

// Without `voronoi`, a generic input gets no VPAIRS and VVERTICES (they are
// informational there, and CGAL's exact vertex construction can divide by
// zero on a nearly degenerate face: GMP then raises SIGFPE).
CgalResult build_cgal(const Sites& sites, const Input& input, bool voronoi = true) {
    CgalResult cgal;
    Sdg sdg;
    build_cgal_graph(sites, input, sdg, cgal);
    add_delaunay_sections(sdg, sites, cgal.topology);
    count_degenerate_edges(sdg, cgal);
    if (!voronoi && !input.degenerate) {
        cgal.voronoi_skipped = "not computed";
        return cgal;
    }
    try {
        add_voronoi_sections(sdg, sites, cgal);
    } catch (const std::runtime_error& error) {
        if (input.degenerate) throw;  // there they are the comparison
        cgal.voronoi_skipped = error.what();
        cgal.topology.sections.erase("VPAIRS");
        cgal.topology.sections.erase("VVERTICES");
        cgal.cocircular_edges = 0;
    }
    return cgal;
}

// ---------------------------------------------------------------------------
// Comparison and report
// ---------------------------------------------------------------------------

struct SectionDiff {
    std::size_t matched = 0;
    std::size_t only_ours = 0;
    std::size_t only_cgal = 0;
    // (side, line) for the first differing lines.
    std::vector<std::pair<std::string, Line>> examples;
};

constexpr std::size_t kMaxExamples = 10;

void note_excess(SectionDiff& diff, const char* side, const Line& line, std::size_t excess, std::size_t& total) {
    total += excess;
    for (std::size_t k = 0; k < excess && diff.examples.size() < kMaxExamples; ++k) {
        diff.examples.emplace_back(side, line);
    }
}

// Multiset comparison: a line present m times in ours and c times in CGAL's
// matches min(m, c) times; the rest is excess on one side.
SectionDiff compare_section(const Section& ours, const Section& cgal) {
    SectionDiff diff;
    for (const auto& entry : ours) {
        auto it = cgal.find(entry.first);
        const std::size_t theirs = it == cgal.end() ? 0 : it->second;
        diff.matched += std::min(entry.second, theirs);
        if (entry.second > theirs) note_excess(diff, "only_ours", entry.first, entry.second - theirs, diff.only_ours);
    }
    for (const auto& entry : cgal) {
        auto it = ours.find(entry.first);
        const std::size_t mine = it == ours.end() ? 0 : it->second;
        if (entry.second > mine) note_excess(diff, "only_cgal", entry.first, entry.second - mine, diff.only_cgal);
    }
    return diff;
}

bool is_checked(const std::string& title, bool degenerate) {
    if (degenerate) return title == "VPAIRS" || title == "VVERTICES";
    return title == "EDGES" || title == "FACES";
}

struct Verdict {
    bool agree = false;
    bool valid = false;
    std::string text;  // the summary line and the details, as printed
    bool ok() const { return agree && valid; }
};

Verdict compare(const Input& input, const Sites& sites, const OursResult& ours, const CgalResult& cgal) {
    std::size_t matched = 0, only_ours = 0, only_cgal = 0;
    std::ostringstream details;
    for (const char* title : kSectionTitles) {
        const bool checked = is_checked(title, input.degenerate);
        if (!checked && !cgal.voronoi_skipped.empty() && cgal.topology.sections.count(title) == 0) {
            details << "  " << title << " (info): skipped, " << cgal.voronoi_skipped << "\n";
            continue;
        }
        const SectionDiff diff = compare_section(ours.full.section(title), cgal.topology.section(title));
        if (checked) {
            matched += diff.matched;
            only_ours += diff.only_ours;
            only_cgal += diff.only_cgal;
        }
        details << "  " << title << (checked ? " (checked)" : " (info)") << ": ours=" << ours.full.count(title)
                << " cgal=" << cgal.topology.count(title) << " matched=" << diff.matched
                << " only_ours=" << diff.only_ours << " only_cgal=" << diff.only_cgal << "\n";
        if (!checked) continue;
        for (const auto& example : diff.examples) {
            details << "    " << example.first << " " << title << ": " << format_line(example.second) << "\n";
        }
    }
    Verdict verdict;
    verdict.agree = only_ours == 0 && only_cgal == 0;
    verdict.valid = ours.problems.empty();
    char line[1024];
    std::snprintf(line, sizeof line,
                  "family=%s n=%zu segments=%zu sites=%zu degenerate=%s ours_edges=%zu cgal_edges=%zu ours_faces=%zu "
                  "cgal_faces=%zu matched=%zu only_ours=%zu only_cgal=%zu cgal_dimension=%d cocircular_edges=%zu "
                  "zero_length_edges=%zu ours_build_ms=%.1f cgal_build_ms=%.1f valid=%s verdict=%s\n",
                  input.family.c_str(), input.points.size() + input.segments.size(), input.segments.size(),
                  sites.count(), input.degenerate ? "yes" : "no", ours.full.count("EDGES"),
                  cgal.topology.count("EDGES"), ours.full.count("FACES"), cgal.topology.count("FACES"), matched,
                  only_ours, only_cgal, cgal.dimension, cgal.cocircular_edges, cgal.degenerate_edges, ours.build_ms, cgal.build_ms,
                  verdict.valid ? "yes" : "no", verdict.ok() ? "AGREE" : "DIFFER");
    verdict.text = line + details.str();
    for (const std::string& problem : ours.problems) verdict.text += "  invalid: " + problem + "\n";
    if (!input.degenerate && !verdict.agree && cgal.cocircular_edges > 0) {
        verdict.text += "  note: the input has " + std::to_string(cgal.cocircular_edges) +
                        " exactly cocircular Delaunay edges, so it is not generic\n";
    }
    if (!input.degenerate && !verdict.agree && cgal.degenerate_edges > 0) {
        verdict.text += "  note: CGAL has " + std::to_string(cgal.degenerate_edges) +
                        " Voronoi edges of length exactly zero (four sites on one circle), so the input is not "
                        "generic: compare with --degenerate\n";
    }
    return verdict;
}

// The degenerate comparison of a generic input that CGAL finds exactly
// degenerate (a Voronoi edge of length zero: EDGES and FACES are then not
// unique, only the Voronoi sections are), when the generic comparison
// `first` differs on a valid diagram. Empty when that does not apply, or
// when CGAL cannot build the Voronoi sections (the difference stands). The
// near-degenerate families (a 1,024-gon inscribed in a circle) and the
// search's generic kinds (an L of two equal perpendicular arms on the
// integer grid) make such inputs.
std::optional<Verdict> degenerate_retry(const Input& input, const Sites& sites, const OursResult& ours,
                                        const CgalResult& cgal, const Verdict& first) {
    if (first.ok() || !first.valid || input.degenerate || cgal.degenerate_edges == 0) return std::nullopt;
    Input as_degenerate = input;
    as_degenerate.degenerate = true;
    CgalResult again;
    try {
        again = build_cgal(sites, as_degenerate);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    return compare(as_degenerate, sites, ours, again);
}

int report(const Input& input, const Sites& sites, const OursResult& ours, const CgalResult& cgal) {
    const Verdict verdict = compare(input, sites, ours, cgal);
    std::fputs(verdict.text.c_str(), stdout);
    if (verdict.ok()) return 0;
    const std::optional<Verdict> second = degenerate_retry(input, sites, ours, cgal, verdict);
    if (!second) return 1;
    std::printf("as degenerate (CGAL has %zu edges of length zero):\n", cgal.degenerate_edges);
    std::fputs(second->text.c_str(), stdout);
    return second->ok() ? 0 : 1;
}

// ---------------------------------------------------------------------------
// Randomised search (--search SECONDS [seed]): small random inputs until the
// time is up, each cross-checked as generated, with every segment reversed
// and shuffled; every difference, invalid diagram or library error is
// minimised and printed in the input format.
// ---------------------------------------------------------------------------

enum class Outcome { Agree, Fail, CgalError };

struct RunResult {
    Outcome outcome = Outcome::Agree;
    std::string text;
    // Generic comparison differed on an exactly degenerate input, and the
    // degenerate comparison agreed.
    bool degenerate_fallback = false;
};

// Inputs are legal by construction (the generators filter exactly), so a
// library that rejects one as intersecting is a failure too.
// The input being checked, for the SIGFPE report.
const Input* g_current_input = nullptr;

extern "C" void report_sigfpe(int) {
    // Raised synchronously (GMP's division by zero calls raise()), so stdio
    // is usable here in practice.
    std::printf("CRASH: SIGFPE (GMP division by zero in a CGAL construction?) on this input:\n");
    if (g_current_input != nullptr) write_text(stdout, *g_current_input);
    std::fflush(stdout);
    std::_Exit(3);
}

RunResult run_one(const Input& input) {
    g_current_input = &input;
    RunResult result;
    const Sites sites(input);
    OursResult ours;
    try {
        ours = build_ours(input, sites);
    } catch (const std::exception& error) {
        result.outcome = Outcome::Fail;
        result.text = std::string("segvoronoi error: ") + error.what() + "\n";
        return result;
    }
    CgalResult cgal;
    try {
        cgal = build_cgal(sites, input, false);
    } catch (const std::exception& error) {
        result.outcome = Outcome::CgalError;
        result.text = std::string("cgal: ") + error.what() + "\n";
        return result;
    }
    const Verdict verdict = compare(input, sites, ours, cgal);
    result.outcome = verdict.ok() ? Outcome::Agree : Outcome::Fail;
    result.text = verdict.text;
    if (const std::optional<Verdict> second = degenerate_retry(input, sites, ours, cgal, verdict)) {
        if (second->ok()) {
            result.outcome = Outcome::Agree;
            result.degenerate_fallback = true;
        } else {
            result.text += "as degenerate:\n" + second->text;
        }
    }
    return result;
}

// A legal input: no segment crosses, overlaps or touches another except at
// a shared endpoint, no isolated point lies inside a segment, no segment
// has length zero.
bool legal_addition(const std::vector<Segment>& segs, const Segment& s) {
    if (same_point(s.a, s.b)) return false;
    for (const Segment& t : segs)
        if (segments_conflict(s, t)) return false;
    return true;
}

bool legal_point(const std::vector<Segment>& segs, const Point& p) {
    for (const Segment& s : segs)
        if (in_open_segment(s, p)) return false;
    return true;
}

struct SearchCase {
    Input input;
    std::string kind;
};

double random_int(Rng& rng, double range) { return std::floor(rng.unit() * (range + 1.0)); }

// A point that is an earlier endpoint with probability `reuse` (half of
// those from the first three distinct endpoints, the hubs, so that up to
// ten segments meet at a point), else a fresh one from `fresh`.
template <class Fresh>
Point pick_endpoint(const std::vector<Point>& ends, double reuse, Rng& rng, Fresh fresh) {
    if (!ends.empty() && rng.unit() < reuse) {
        const std::size_t hubs = std::min<std::size_t>(3, ends.size());
        return rng.below(2) == 0 ? ends[rng.below(hubs)] : ends[rng.below(ends.size())];
    }
    return fresh();
}

// Segments drawn one at a time (up to 40 tries each) and kept when legal.
template <class Draw>
std::vector<Segment> draw_segments(std::size_t n, Rng& rng, Draw draw) {
    std::vector<Segment> segs;
    for (std::size_t k = 0; k < n; ++k) {
        for (int attempt = 0; attempt < 40; ++attempt) {
            Segment s = draw(segs);
            if (rng.below(2) == 1) std::swap(s.a, s.b);
            if (legal_addition(segs, s)) {
                segs.push_back(s);
                break;
            }
        }
    }
    return segs;
}

std::vector<Point> endpoints_of(const std::vector<Segment>& segs) {
    std::vector<Point> ends;
    for (const Segment& s : segs) {
        for (const Point& p : {s.a, s.b}) {
            if (std::none_of(ends.begin(), ends.end(), [&](const Point& q) { return same_point(p, q); }))
                ends.push_back(p);
        }
    }
    return ends;
}

// 0..max isolated points, legal ones only (an endpoint repeated is legal).
template <class Fresh>
void add_points(Input& input, std::size_t max, Rng& rng, Fresh fresh) {
    const std::size_t count = rng.below(max + 1);
    for (std::size_t k = 0; k < count; ++k) {
        const Point p = fresh();
        if (legal_point(input.segments, p)) input.points.push_back(p);
    }
}

// Kind 0..4 (below); with `generic_only`, junctions never on the small grid,
// with `small_grid` always.
SearchCase random_case_of(std::size_t kind, Rng& rng, bool generic_only, bool small_grid) {
    SearchCase c;
    Input& input = c.input;
    const double two_pi = 6.283185307179586;
    if (kind == 0) {
        // Integer junctions: endpoints in [0, range]^2, 30% of them earlier
        // endpoints; short or long segments.
        const double ranges[] = {20.0, 1000.0, 1e6};
        const std::size_t r = small_grid ? 0 : generic_only ? 1 + rng.below(2) : rng.below(3);
        const double range = ranges[r];
        const std::size_t n = 2 + rng.below(39);
        const bool short_ones = rng.below(2) == 0;
        auto fresh = [&] { return Point{random_int(rng, range), random_int(rng, range)}; };
        input.segments = draw_segments(n, rng, [&](const std::vector<Segment>& segs) {
            const std::vector<Point> ends = endpoints_of(segs);
            const Point a = pick_endpoint(ends, 0.3, rng, fresh);
            const Point b = pick_endpoint(ends, 0.3, rng, [&] {
                if (!short_ones) return fresh();
                const double reach = std::max(2.0, range / 4.0);
                return Point{std::round(a.x + reach * (2.0 * rng.unit() - 1.0)),
                             std::round(a.y + reach * (2.0 * rng.unit() - 1.0))};
            });
            return Segment{a, b};
        });
        add_points(input, 3, rng, fresh);
        input.degenerate = range < 100.0;
        c.kind = "junctions-" + std::to_string(static_cast<long long>(range));
    } else if (kind == 1) {
        // A star: 3..10 spokes from one hub at random angles and lengths,
        // each pointing in or out at random, and a few random points.
        const bool integer = rng.below(2) == 0;
        const double range = integer ? 1e6 : 1.0;
        auto coordinate = [&](double v) { return integer ? std::round(v) : v; };
        const Point hub{coordinate(range * (0.25 + 0.5 * rng.unit())), coordinate(range * (0.25 + 0.5 * rng.unit()))};
        const std::size_t n = 3 + rng.below(8);
        input.segments = draw_segments(n, rng, [&](const std::vector<Segment>&) {
            const double angle = two_pi * rng.unit(), length = range * (0.05 + 0.25 * rng.unit());
            return Segment{hub, {coordinate(hub.x + length * std::cos(angle)), coordinate(hub.y + length * std::sin(angle))}};
        });
        add_points(input, 4, rng, [&] { return Point{coordinate(range * rng.unit()), coordinate(range * rng.unit())}; });
        c.kind = integer ? "star-int" : "star-double";
    } else if (kind == 2) {
        // A random polyline (sometimes closed) of 2..40 steps, each segment
        // in a random direction.
        const bool integer = rng.below(2) == 0;
        const double range = integer ? 1e6 : 1.0;
        auto coordinate = [&](double v) { return integer ? std::round(v) : v; };
        const std::size_t n = 2 + rng.below(39);
        const double step = range * 0.5 / std::sqrt(static_cast<double>(n));
        std::vector<Segment> segs;
        Point at{coordinate(range * rng.unit()), coordinate(range * rng.unit())};
        const Point first = at;
        for (std::size_t k = 0, tries = 0; k < n && tries < 40 * n; ++tries) {
            const double angle = two_pi * rng.unit(), length = step * (0.3 + rng.unit());
            const Point to{coordinate(at.x + length * std::cos(angle)), coordinate(at.y + length * std::sin(angle))};
            if (!legal_addition(segs, {at, to})) continue;
            segs.push_back({at, to});
            at = to;
            ++k;
        }
        if (segs.size() >= 2 && rng.below(3) == 0 && legal_addition(segs, {at, first})) segs.push_back({at, first});
        for (Segment& s : segs)
            if (rng.below(2) == 1) std::swap(s.a, s.b);
        input.segments = segs;
        add_points(input, 2, rng, [&] { return Point{coordinate(range * rng.unit()), coordinate(range * rng.unit())}; });
        c.kind = integer ? "polyline-int" : "polyline-double";
    } else if (kind == 3) {
        // Snapped floats: random doubles rounded to 2..6 bits after the
        // binary point in [0, 4)^2 (exact repeats, collinear and cocircular
        // sites), with endpoint reuse: degenerate.
        const int bits = 2 + static_cast<int>(rng.below(5));
        const double scale = std::ldexp(1.0, bits);
        auto snap = [&](double v) { return std::round(v * scale) / scale; };
        auto fresh = [&] { return Point{snap(4.0 * rng.unit()), snap(4.0 * rng.unit())}; };
        const std::size_t n = 2 + rng.below(24);
        input.segments = draw_segments(n, rng, [&](const std::vector<Segment>& segs) {
            const std::vector<Point> ends = endpoints_of(segs);
            const Point a = pick_endpoint(ends, 0.3, rng, fresh);
            const Point b = pick_endpoint(ends, 0.3, rng, [&] {
                return Point{snap(a.x + 2.0 * rng.unit() - 1.0), snap(a.y + 2.0 * rng.unit() - 1.0)};
            });
            return Segment{a, b};
        });
        add_points(input, 3, rng, fresh);
        input.degenerate = true;
        c.kind = "snapped-" + std::to_string(bits);
    } else {
        // Boost.Polygon's benchmark style, small: 2..30 random segments split
        // at their crossings rounded to the integer grid.
        const double side = rng.below(2) == 0 ? 1000.0 : 1e6;
        input.segments = boost_split(2 + rng.below(29), rng, side);
        for (Segment& s : input.segments)
            if (rng.below(2) == 1) std::swap(s.a, s.b);
        c.kind = "split-" + std::to_string(static_cast<long long>(side));
    }
    input.family = c.kind;
    return c;
}

// Near-degenerate: a small-grid junction or snapped input (exact
// coincidences everywhere) with every distinct point moved, with
// probability one half, in x, y or both (shared endpoints move together);
// segments and points that become illegal are left out. Compared as
// generic.
SearchCase nudged_case(Rng& rng) {
    SearchCase base = random_case_of(rng.below(2) == 0 ? 0 : 3, rng, false, true);
    // ulps: nonzero coordinates by 1..4 ulps (zero stays); denormal: zero
    // coordinates by 1..4 times the least subnormal (the rest stays);
    // 1e-12, 1e-9: any coordinate by up to that much of the extent.
    const std::size_t level = rng.below(4);
    const char* const level_names[] = {"ulps", "denormal", "1e-12", "1e-9"};
    const double extent = base.kind.rfind("junctions", 0) == 0 ? 20.0 : 4.0;
    std::map<std::pair<double, double>, Point> moved;
    auto shift = [&](double v) {
        if (level <= 1) {
            if ((v == 0.0) != (level == 1)) return v;
            const double toward = rng.below(2) == 0 ? HUGE_VAL : -HUGE_VAL;
            for (std::size_t k = 1 + rng.below(4); k > 0; --k) v = std::nextafter(v, toward);
            return v;
        }
        return v + (2.0 * rng.unit() - 1.0) * extent * (level == 2 ? 1e-12 : 1e-9);
    };
    auto nudge = [&](const Point& p) {
        auto it = moved.find({p.x, p.y});
        if (it != moved.end()) return it->second;
        Point q = p;
        if (rng.below(2) == 0) {
            const std::size_t axes = rng.below(3);
            if (axes != 1) q.x = shift(q.x);
            if (axes != 0) q.y = shift(q.y);
        }
        moved.emplace(std::make_pair(p.x, p.y), q);
        return q;
    };
    SearchCase c;
    for (const Segment& s : base.input.segments) {
        const Segment t{nudge(s.a), nudge(s.b)};
        if (legal_addition(c.input.segments, t)) c.input.segments.push_back(t);
    }
    for (const Point& p : base.input.points) {
        const Point q = nudge(p);
        if (legal_point(c.input.segments, q)) c.input.points.push_back(q);
    }
    c.kind = "nudged-" + base.kind.substr(0, base.kind.find('-')) + "-" + level_names[level];
    c.input.family = c.kind;
    return c;
}

// One input of a random kind; with `generic_only`, only the kinds compared
// as generic, and not the near-degenerate ones.
SearchCase random_case(Rng& rng, bool generic_only) {
    std::size_t kind = rng.below(6);
    if (generic_only && (kind == 3 || kind == 5)) kind = rng.below(2) == 0 ? 0 : 4;
    if (kind == 5) return nudged_case(rng);
    return random_case_of(kind, rng, generic_only, false);
}

// Greedy minimisation of a failing input: drop one segment, then one
// point, at a time while it still fails (until nothing can go); then turn
// each segment that `flipped` marks as reversed back while it still fails.
// The library's insertion order depends on the whole input, so a smaller
// input may fail only in another order: each candidate is also tried in
// `kOrders` random orders, and the first failing order is kept.
constexpr int kOrders = 6;

struct Candidate {
    Input input;
    std::vector<bool> flipped;  // per segment: reversed against the generated input
};

// Past `deadline` every candidate counts as passing, so that it returns
// the smallest input so far.
Input minimise(Input input, std::vector<bool> flipped, std::uint64_t seed, std::size_t& runs,
               std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max()) {
    Rng rng(seed);
    auto fails = [&](const Input& candidate) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        ++runs;
        return run_one(candidate).outcome == Outcome::Fail;
    };
    // The candidate, or one of its reorderings, that fails; false if none.
    auto fails_in_some_order = [&](Candidate& c) {
        if (fails(c.input)) return true;
        for (int k = 0; k < kOrders; ++k) {
            Candidate other = c;
            std::vector<std::size_t> order(c.input.segments.size());
            std::iota(order.begin(), order.end(), 0);
            shuffle(order, rng);
            for (std::size_t j = 0; j < order.size(); ++j) {
                other.input.segments[j] = c.input.segments[order[j]];
                other.flipped[j] = c.flipped[order[j]];
            }
            shuffle(other.input.points, rng);
            if (fails(other.input)) {
                c = other;
                return true;
            }
        }
        return false;
    };
    Candidate best{std::move(input), std::move(flipped)};
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t k = best.input.segments.size(); k-- > 0;) {
            if (k >= best.input.segments.size()) continue;
            Candidate smaller = best;
            smaller.input.segments.erase(smaller.input.segments.begin() + static_cast<std::ptrdiff_t>(k));
            smaller.flipped.erase(smaller.flipped.begin() + static_cast<std::ptrdiff_t>(k));
            if (smaller.input.segments.empty() && smaller.input.points.empty()) continue;
            if (fails_in_some_order(smaller)) {
                best = std::move(smaller);
                changed = true;
            }
        }
        for (std::size_t k = best.input.points.size(); k-- > 0;) {
            if (k >= best.input.points.size()) continue;
            Candidate smaller = best;
            smaller.input.points.erase(smaller.input.points.begin() + static_cast<std::ptrdiff_t>(k));
            if (smaller.input.segments.empty() && smaller.input.points.empty()) continue;
            if (fails_in_some_order(smaller)) {
                best = std::move(smaller);
                changed = true;
            }
        }
    }
    for (std::size_t k = 0; k < best.input.segments.size(); ++k) {
        if (!best.flipped[k]) continue;
        Input turned = best.input;
        std::swap(turned.segments[k].a, turned.segments[k].b);
        if (fails(turned)) {
            best.input = turned;
            best.flipped[k] = false;
        }
    }
    return best.input;
}

std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t k) {
    Rng rng(seed ^ (0xD1B54A32D192ED03ULL * (k + 1)));
    return rng.next();
}

int search(double seconds, std::uint64_t seed, bool generic_only, bool no_subnormal, const std::string& out_dir) {
    std::signal(SIGFPE, report_sigfpe);
    std::printf("search: seconds=%g seed=%llu%s%s\n", seconds, static_cast<unsigned long long>(seed),
                generic_only ? " generic" : "", no_subnormal ? " no-subnormal" : "");
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    std::size_t inputs = 0, runs = 0, failures = 0, cgal_errors = 0, empty = 0, fallbacks = 0;
    std::map<std::string, std::size_t> kinds;
    for (std::uint64_t k = 0; elapsed() < seconds; ++k) {
        const std::uint64_t case_seed = mix_seed(seed, k);
        Rng rng(case_seed);
        SearchCase c = random_case(rng, generic_only);
        // --no-subnormal: the kinds that move zeros to subnormals (known
        // to differ, see cgal.cmake) are drawn but not run
        if (no_subnormal && c.kind.find("denormal") != std::string::npos) continue;
        if (c.input.segments.empty()) {
            ++empty;
            continue;
        }
        ++inputs;
        ++kinds[c.kind];
        // The variants: as generated, every segment reversed, and points
        // and segments shuffled (with the reversal marks moved along).
        const std::size_t n = c.input.segments.size();
        Input reversed = c.input;
        for (Segment& s : reversed.segments) std::swap(s.a, s.b);
        Input shuffled = c.input;
        std::vector<std::size_t> order(n);
        std::iota(order.begin(), order.end(), 0);
        shuffle(order, rng);
        for (std::size_t j = 0; j < n; ++j) shuffled.segments[j] = c.input.segments[order[j]];
        shuffle(shuffled.points, rng);
        const struct {
            const char* name;
            const Input* input;
            std::vector<bool> flipped;
        } variants[] = {{"as generated", &c.input, std::vector<bool>(n, false)},
                        {"every segment reversed", &reversed, std::vector<bool>(n, true)},
                        {"shuffled", &shuffled, std::vector<bool>(n, false)}};
        for (const auto& variant : variants) {
            ++runs;
            const RunResult result = run_one(*variant.input);
            if (result.degenerate_fallback) ++fallbacks;
            if (result.outcome == Outcome::CgalError) {
                ++cgal_errors;
                break;
            }
            if (result.outcome != Outcome::Fail) continue;
            ++failures;
            // Minimising takes at most a second or two; all of it together
            // at most half the search time past its end.
            const auto deadline = start + std::chrono::milliseconds(static_cast<long long>(1500.0 * seconds));
            const Input smallest = minimise(*variant.input, variant.flipped, case_seed, runs, deadline);
            const RunResult again = run_one(smallest);
            std::printf("FAILURE %zu: kind=%s case_seed=%llu (search seed %llu, input %llu) variant=%s degenerate=%s "
                        "segments %zu -> %zu, points %zu -> %zu\n",
                        failures, c.kind.c_str(), static_cast<unsigned long long>(case_seed),
                        static_cast<unsigned long long>(seed), static_cast<unsigned long long>(k), variant.name,
                        smallest.degenerate ? "yes" : "no", variant.input->segments.size(), smallest.segments.size(),
                        variant.input->points.size(), smallest.points.size());
            std::printf("--- minimised input (Boost.Polygon text; compare with%s) ---\n",
                        smallest.degenerate ? " --degenerate" : "");
            write_text(stdout, smallest);
            std::printf("--- its comparison ---\n%s", again.text.c_str());
            std::printf("--- first result of the unminimised input ---\n%s---\n", result.text.c_str());
            if (!out_dir.empty()) {
                const std::string path = out_dir + "/search_" + std::to_string(case_seed) + "_" +
                                         std::to_string(failures) + (smallest.degenerate ? "_deg" : "") + ".txt";
                if (!write_file(path, smallest)) std::fprintf(stderr, "cannot write %s\n", path.c_str());
            }
            std::fflush(stdout);
            break;  // one failure per input is enough
        }
    }
    const double minutes = elapsed() / 60.0;
    std::string kind_counts;
    for (const auto& entry : kinds) kind_counts += " " + entry.first + "=" + std::to_string(entry.second);
    std::printf("search: kinds:%s; runs=%zu cgal_errors=%zu empty=%zu degenerate_fallbacks=%zu\n",
                kind_counts.c_str(), runs, cgal_errors, empty, fallbacks);
    std::printf("search: inputs=%zu per_minute=%.0f failures=%zu\n", inputs,
                minutes > 0.0 ? static_cast<double>(inputs) / minutes : 0.0, failures);
    return failures > 0 ? 1 : 0;
}

int usage() {
    std::fprintf(stderr,
                 "usage: segvoronoi_cgal_check <family> <n> [seed] [--write-input FILE]\n"
                 "       segvoronoi_cgal_check --file input.txt [--degenerate]\n"
                 "       segvoronoi_cgal_check --search SECONDS [seed] [--generic] [--out DIR]\n"
                 "       segvoronoi_cgal_check --minimise input.txt [--degenerate]\n"
                 "families: uniform clustered tiny tiny-offset huge (generic), lattice circle collinear "
                 "tiny-lattice snapped (degenerate); segments: seg-random1 seg-random2 seg-random3 seg-short "
                 "polyline square-hole polygon-holes letter-gap near-vertical (generic), polygon star tangent "
                 "seg-lattice parallel letter (degenerate), boost-split (generic)\n");
    return 2;
}

bool parse_count(const char* text, std::uint64_t& value) {
    char* end = nullptr;
    errno = 0;
    value = std::strtoull(text, &end, 10);
    return errno == 0 && end != text && *end == '\0' && text[0] != '-';
}

// Fills `input` from the command line; returns false after printing why not.
bool parse_arguments(int argc, char** argv, Input& input) {
    if (argc >= 3 && std::string(argv[1]) == "--file") {
        if (argc > 4 || (argc == 4 && std::string(argv[3]) != "--degenerate")) return usage(), false;
        std::string error;
        if (!read_file(argv[2], input, error)) {
            std::fprintf(stderr, "segvoronoi_cgal_check: %s: %s\n", argv[2], error.c_str());
            return false;
        }
        input.degenerate = argc == 4;
        return true;
    }
    std::string write_to;
    if (argc >= 5 && std::string(argv[argc - 2]) == "--write-input") {
        write_to = argv[argc - 1];
        argc -= 2;
    }
    std::uint64_t n = 0, seed = 1;
    if (argc < 3 || argc > 4 || !parse_count(argv[2], n) || (argc == 4 && !parse_count(argv[3], seed))) {
        return usage(), false;
    }
    if (!make_family(argv[1], static_cast<std::size_t>(n), seed, input)) return usage(), false;
    if (!write_to.empty() && !write_file(write_to, input)) {
        std::fprintf(stderr, "segvoronoi_cgal_check: cannot write %s\n", write_to.c_str());
        return false;
    }
    return true;
}

}  // namespace

// --minimise input.txt [--degenerate]: the search's minimisation of a
// failing file, printed in the input format.
int minimise_file(int argc, char** argv) {
    if (argc < 3 || argc > 4 || (argc == 4 && std::string(argv[3]) != "--degenerate")) return usage();
    Input input;
    std::string error;
    if (!read_file(argv[2], input, error)) {
        std::fprintf(stderr, "segvoronoi_cgal_check: %s: %s\n", argv[2], error.c_str());
        return 2;
    }
    input.degenerate = argc == 4;
    std::signal(SIGFPE, report_sigfpe);
    if (run_one(input).outcome != Outcome::Fail) {
        std::printf("minimise: the input does not fail\n");
        return 0;
    }
    std::size_t runs = 0;
    const std::vector<bool> flipped(input.segments.size(), false);
    const Input smallest = minimise(input, flipped, 1, runs);
    std::printf("minimise: segments %zu -> %zu, points %zu -> %zu, runs=%zu\n", input.segments.size(),
                smallest.segments.size(), input.points.size(), smallest.points.size(), runs);
    write_text(stdout, smallest);
    std::printf("%s", run_one(smallest).text.c_str());
    return 1;
}

// --search SECONDS [seed] [--generic] [--no-subnormal] [--out DIR] and --minimise; returns
// -1 when argv is neither.
int search_main(int argc, char** argv) {
    if (argc >= 2 && std::string(argv[1]) == "--minimise") return minimise_file(argc, argv);
    if (argc < 2 || std::string(argv[1]) != "--search") return -1;
    std::string out_dir;
    bool generic_only = false, no_subnormal = false;
    std::vector<std::string> numbers;
    for (int k = 2; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--out" && k + 1 < argc) {
            out_dir = argv[++k];
        } else if (arg == "--generic") {
            generic_only = true;
        } else if (arg == "--no-subnormal") {
            no_subnormal = true;
        } else {
            numbers.push_back(arg);
        }
    }
    std::uint64_t seconds = 0, seed = 0;
    if (numbers.empty() || numbers.size() > 2 || !parse_count(numbers[0].c_str(), seconds) ||
        (numbers.size() == 2 && !parse_count(numbers[1].c_str(), seed))) {
        return usage();
    }
    if (numbers.size() == 1) {
        // A new seed each run (printed first, so that any run can be repeated).
        seed = static_cast<std::uint64_t>(std::chrono::system_clock::now().time_since_epoch().count());
        seed = Rng(seed).next();
    }
    return search(static_cast<double>(seconds), seed, generic_only, no_subnormal, out_dir);
}

int main(int argc, char** argv) {
    const int searched = search_main(argc, argv);
    if (searched >= 0) return searched;
    Input input;
    if (!parse_arguments(argc, argv, input)) return 2;
    const Sites sites(input);
    OursResult ours;
    try {
        ours = build_ours(input, sites);
    } catch (const std::exception& error) {
        std::printf("family=%s n=%zu segments=%zu verdict=ERROR segvoronoi: %s\n", input.family.c_str(),
                    input.points.size() + input.segments.size(), input.segments.size(), error.what());
        return 3;
    }
    CgalResult cgal;
    try {
        cgal = build_cgal(sites, input);
    } catch (const std::exception& error) {
        std::printf("family=%s n=%zu segments=%zu verdict=ERROR cgal: %s\n", input.family.c_str(),
                    input.points.size() + input.segments.size(), input.segments.size(), error.what());
        return 3;
    }
    return report(input, sites, ours, cgal);
}
