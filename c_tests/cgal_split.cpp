// segvoronoi_cgal_split: cross-checks splitting mode (issue 11) against
// CGAL's own handling of crossings. For one generated input that crosses
// itself it builds
//   ours:   the original segments and points through the C API with
//           segvoronoi_builder_set_split_crossings(b, 1) (snap rounding to
//           pixels of side 2^-46 of the power of two above the largest
//           coordinate);
//   CGAL's: the same segments and points in the segment Delaunay graph
//           hierarchy with intersection-capable traits
//           (Segment_Delaunay_graph_filtered_traits_2<K, Field_with_sqrt_tag>,
//           exact predicates), which splits at crossings itself, at exact
//           intersection points (collinear overlaps resolved beforehand,
//           see without_overlaps: CGAL loses parts of them);
// and compares the Voronoi adjacency: the set of pairs of sites of the
// Voronoi edges of positive length (the Delaunay graph itself is not
// unique at a crossing, where five sites share one vertex of radius 0).
// CGAL's zero length is decided exactly (as segvoronoi_cgal_check does),
// ours as "both ends within 4 pixels".
//
//   segvoronoi_cgal_split --family NAME --n N [--seed S] [--min-agreement F] [--verbose]
//                         [--plain] [--cgal-of-pieces] [--write-pieces FILE]
//   segvoronoi_cgal_split --file FILE [--seed S] [options as above]
//   segvoronoi_cgal_split --list
//
// --file reads the input from FILE (Boost.Polygon's text format, e.g. the
// real coastlines, borders and rivers of tests/data/gshhg_*.txt) instead of
// generating it; its summary lines say family=file:NAME, NAME the file's
// base name; --seed then only shuffles.
//
// Our sites are first collapsed (see collapse): point sites within 3 pixels
// of each other become one point element, a piece inside such a cluster
// that point, pieces between two clusters one segment element. Each CGAL
// site is then mapped to an element: a point site (an input point or
// endpoint, or an intersection point: its exact rational coordinates
// rounded to double) to the element of our point site nearest to it within
// 2 pixels, a subsegment to the segment element of the images of its two
// endpoints. A CGAL site with no counterpart is unmapped (two crossings
// closer than a pixel that our snapping merged, a subsegment that our
// snapping bent through a nearby hot pixel), and so are its edges, and our
// elements that no CGAL site maps to. Pairs are compared where both are
// mapped: edges_agree pairs on both sides, only_cgal, only_ours, and
// cluster_separators, our pairs of a cluster and a piece ending in it (a
// point of a snapped cluster whose pieces all lie in a half-plane has a
// wedge-shaped cell, with separators of positive length, where CGAL's
// exact crossing has a cell of one point) and bent_continuations, our
// pairs of two pieces that continue each other in a straight line but for
// a snapped end (collinear input segments sharing an end, a crossing
// inside one of them snapped off the line: our pieces meet at a hair below
// 180 degrees and their cells share an edge on the concave side, CGAL's
// exactly collinear subsegments none), and the pairs of the thin wedge
// that is then the cell of their shared end on the convex side (CGAL's
// has no area); found on GSHHG data, see BENCHMARKS.md: explained, not
// counted in only_ours.
//
// Each input is run three times: as generated, every segment reversed, and
// with segments and points shuffled; one summary line each
//   family=... variant=... inputs=SEGMENTS+POINTS sites_cgal=... sites_ours=...
//   elements_ours=... mapped=... unmapped_cgal=... (counts of the split) edges_cgal=...
//   edges_ours=... edges_agree=... only_cgal=... only_ours=... cluster_separators=...
//   bent_continuations=... unmapped_edges_cgal=... unmapped_edges_ours=...
//   raw_agreement=... agreement=... ms_ours=... ms_cgal=... verdict=AGREE|DIFFER
// agreement = edges_agree / max(edges_cgal, edges_ours - cluster_separators
// - bent_continuations), raw_agreement the same with them. Without
// --min-agreement (the exact families, whose crossings are integers or
// halves so that our snapped points are CGAL's exact ones) a variant
// AGREEs when every site is mapped both ways and no pair is on one side
// only, explained or not; with it, when agreement >= F.
// --verbose prints the differences and the unmapped sites. --plain builds
// CGAL's graph without the hierarchy (see PlainSdg). --cgal-of-pieces (a
// diagnostic) gives CGAL our pieces instead of the original segments: a
// difference that stays is one between the two Voronoi builders on the
// same non-crossing input, one that goes away comes from the splitting.
// --write-pieces FILE writes our points and pieces of the as-is variant in
// Boost.Polygon's text format, for segvoronoi_cgal_check --file. Exit
// status: 0 all variants agree, 1 a difference, 2 bad usage, 3 a library
// error.

#include <CGAL/Gmpq.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Segment_Delaunay_graph_2.h>
#include <CGAL/Segment_Delaunay_graph_hierarchy_2.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <numeric>
#include <tuple>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "boost_text.hpp"
#include "cgal_rational.hpp"
#include "segvoronoi.h"

namespace {

struct Point {
    double x;
    double y;
};

struct Segment {
    Point a;
    Point b;
};

struct Input {
    std::vector<Point> points;
    std::vector<Segment> segments;
};

// ---------------------------------------------------------------------------
// Inputs
// ---------------------------------------------------------------------------

using Rng = std::mt19937_64;

long uniform_int(Rng& rng, long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); }

double uniform_real(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

// n axis-parallel segments with integer ends in [0, side]: every crossing,
// overlap and T-junction is at integers; a few integer points, some on
// segments.
Input grid(std::size_t n, Rng& rng) {
    const long side = 64;
    Input in;
    for (std::size_t i = 0; i < n; ++i) {
        const double c = double(uniform_int(rng, 0, side));
        double lo = double(uniform_int(rng, 0, side - 1));
        double hi = double(uniform_int(rng, long(lo) + 1, side));
        if (i % 2 == 0) {
            in.segments.push_back({{lo, c}, {hi, c}});
        } else {
            in.segments.push_back({{c, lo}, {c, hi}});
        }
    }
    for (std::size_t i = 0; i < n / 10; ++i) {
        in.points.push_back({double(uniform_int(rng, 0, side)), double(uniform_int(rng, 0, side))});
    }
    return in;
}

// Road-network-like and exact: long segments of slopes 0, infinite, 1 and
// -1 with integer ends, so every crossing is at integers or half-integers.
Input diagonal_grid(std::size_t n, Rng& rng) {
    const long side = 256;
    Input in;
    for (std::size_t i = 0; i < n; ++i) {
        const long x = uniform_int(rng, 0, side), y = uniform_int(rng, 0, side);
        const long len = uniform_int(rng, side / 8, side / 2);
        const int kind = int(i % 4);
        const long dx = kind == 1 ? 0 : len, dy = kind == 0 ? 0 : (kind == 3 ? -len : len);
        in.segments.push_back({{double(x), double(y)}, {double(x + dx), double(y + dy)}});
    }
    return in;
}

// n segments through the integer point (7, -3), each from c - d to c + k d
// with integer d and k in 1..3 (both ends integers): every crossing is the
// centre, and spokes of one direction overlap.
Input star(std::size_t n, Rng& rng) {
    Input in;
    const Point c{7.0, -3.0};
    for (std::size_t i = 0; i < n; ++i) {
        long dx, dy;
        do {
            dx = uniform_int(rng, -40, 40);
            dy = uniform_int(rng, -40, 40);
        } while (dx == 0 && dy == 0);
        const long k = uniform_int(rng, 1, 3);
        in.segments.push_back({{c.x - double(dx), c.y - double(dy)}, {c.x + double(k * dx), c.y + double(k * dy)}});
    }
    return in;
}

// Overlapping collinear segments on a few lines (horizontal, vertical and
// diagonal through integer points), integer ends.
Input collinear(std::size_t n, Rng& rng) {
    Input in;
    // (x0, y0, dx, dy): slopes 0, infinite, +-1, so crossings are at halves
    const long lines[][4] = {{0, 5, 1, 0}, {3, 0, 0, 1}, {0, 0, 1, 1}, {0, 40, 1, -1}, {0, 21, 1, 1}};
    for (std::size_t i = 0; i < n; ++i) {
        const long* l = lines[i % 5];
        long t0 = uniform_int(rng, 0, 30), t1 = uniform_int(rng, 0, 30);
        if (t0 == t1) t1 = t0 + 1;
        in.segments.push_back({{double(l[0] + t0 * l[2]), double(l[1] + t0 * l[3])},
                               {double(l[0] + t1 * l[2]), double(l[1] + t1 * l[3])}});
    }
    return in;
}

// T-junctions: horizontal segments at integer heights, and vertical ones
// that start on a horizontal one (inside it) and end below the next.
Input t_junctions(std::size_t n, Rng& rng) {
    Input in;
    const std::size_t rows = std::max<std::size_t>(2, n / 4);
    for (std::size_t r = 0; r < rows; ++r) {
        in.segments.push_back({{0.0, double(10 * r)}, {1000.0, double(10 * r)}});
    }
    for (std::size_t i = rows; i < n; ++i) {
        const long r = uniform_int(rng, 0, long(rows) - 1);
        const double x = double(uniform_int(rng, 1, 999));
        in.segments.push_back({{x, double(10 * r)}, {x, double(10 * r) + double(uniform_int(rng, 1, 9))}});
    }
    for (std::size_t i = 0; i < n / 8; ++i) {
        // points inside the horizontal segments
        in.points.push_back({double(uniform_int(rng, 1, 999)), double(10 * uniform_int(rng, 0, long(rows) - 1))});
    }
    return in;
}

// Random long segments with integer ends in [0, 1000]^2 (general rational
// crossings).
Input roads_int(std::size_t n, Rng& rng) {
    Input in;
    const double len = 2000.0 / std::sqrt(double(n));
    for (std::size_t i = 0; i < n; ++i) {
        const double x = uniform_real(rng, 0, 1000), y = uniform_real(rng, 0, 1000);
        const double a = uniform_real(rng, 0, 2 * M_PI);
        Segment s{{std::round(x), std::round(y)},
                  {std::round(std::clamp(x + len * std::cos(a), 0.0, 1000.0)),
                   std::round(std::clamp(y + len * std::sin(a), 0.0, 1000.0))}};
        if (s.a.x == s.b.x && s.a.y == s.b.y) s.b.x += 1.0;
        in.segments.push_back(s);
    }
    return in;
}

// The same with real coordinates in the unit square.
Input roads_real(std::size_t n, Rng& rng) {
    Input in;
    const double len = 2.0 / std::sqrt(double(n));
    for (std::size_t i = 0; i < n; ++i) {
        const double x = uniform_real(rng, 0, 1), y = uniform_real(rng, 0, 1);
        const double a = uniform_real(rng, 0, 2 * M_PI);
        in.segments.push_back({{x, y}, {x + len * std::cos(a), y + len * std::sin(a)}});
    }
    return in;
}

// x reflected into [0, side] (a walk clamped there would run along the
// border: collinear overlaps with real coordinates, which CGAL loses parts
// of; see without_overlaps).
double reflect(double x, double side) {
    if (x < 0) x = -x;
    if (x > side) x = 2 * side - x;
    return x;
}

// A closed ring of n vertices in [0, side]^2, a random walk with steps up to
// 3 side/sqrt(n) on each axis (reflected at the border): long and tangled,
// it crosses itself a few times per side. Integer vertices are rounded, and
// one that repeats the vertex before it is dropped.
Input tangled_ring(std::size_t n, Rng& rng, double side, bool integer) {
    Input in;
    std::vector<Point> ring;
    double x = side / 2, y = side / 2;
    const double step = 3 * side / std::sqrt(double(n));
    for (std::size_t i = 0; i < n; ++i) {
        x = reflect(x + uniform_real(rng, -step, step), side);
        y = reflect(y + uniform_real(rng, -step, step), side);
        const Point p = integer ? Point{std::round(x), std::round(y)} : Point{x, y};
        if (integer && !ring.empty() && ring.back().x == p.x && ring.back().y == p.y) continue;
        ring.push_back(p);
    }
    for (std::size_t i = 0; i < ring.size(); ++i) {
        in.segments.push_back({ring[i], ring[(i + 1) % ring.size()]});
    }
    return in;
}

Input polygon_cross(std::size_t n, Rng& rng) { return tangled_ring(n, rng, 1000.0, true); }

Input polygon_cross_real(std::size_t n, Rng& rng) { return tangled_ring(n, rng, 1.0, false); }

struct Family {
    const char* name;
    Input (*make)(std::size_t, Rng&);
    const char* about;
};

const Family families[] = {
    {"grid", grid, "axis-parallel segments, integer ends in [0,64], points (exact)"},
    {"diagonal-grid", diagonal_grid, "slopes 0, inf, +-1, integer ends (crossings at halves; exact)"},
    {"star", star, "segments through one integer point (exact)"},
    {"collinear", collinear, "overlapping collinear segments on 5 lines, integer ends (exact)"},
    {"t-junction", t_junctions, "vertical segments ending inside horizontal ones, points inside (exact)"},
    {"roads-int", roads_int, "random segments of length 2000/sqrt(n), integer ends in [0,1000]"},
    {"roads-real", roads_real, "random segments of length 2/sqrt(n) in the unit square"},
    {"polygon-cross", polygon_cross, "a tangled ring, integer vertices in [0,1000]"},
    {"polygon-cross-real", polygon_cross_real, "a tangled ring, real vertices in the unit square"},
};

// CGAL's segment Delaunay graph loses parts of collinear segments that
// overlap, depending on the insertion order (seen on star and collinear:
// a subsegment covered by the input missing, its neighbours adjacent across
// it; as-is and reversed give different site counts). So CGAL gets the
// overlaps resolved here, exactly, for integer input: the segments of one
// line are cut at every endpoint on the line inside their union into
// consecutive pieces, each once (collinear segments that only touch, as
// our pieces do). Crossings, T-junctions and points inside segments stay
// for CGAL to split. Inputs with a non-integer coordinate are returned as
// they are (the random real families have no overlaps).
Input without_overlaps(const Input& in) {
    for (const Segment& s : in.segments) {
        for (double c : {s.a.x, s.a.y, s.b.x, s.b.y}) {
            if (c != std::floor(c) || std::fabs(c) > 1e9) return in;
        }
    }
    struct Span {
        long lo, hi;
    };
    // line (dx, dy, c) with gcd(dx, dy) = 1, dx > 0 or dx = 0 < dy, and
    // c = dy x - dx y; position along it t = dx x + dy y
    std::map<std::tuple<long, long, long>, std::vector<Span>> lines;
    for (const Segment& s : in.segments) {
        long dx = long(s.b.x - s.a.x), dy = long(s.b.y - s.a.y);
        const long g = std::gcd(std::labs(dx), std::labs(dy));
        dx /= g;
        dy /= g;
        if (dx < 0 || (dx == 0 && dy < 0)) {
            dx = -dx;
            dy = -dy;
        }
        const long c = dy * long(s.a.x) - dx * long(s.a.y);
        long t0 = dx * long(s.a.x) + dy * long(s.a.y), t1 = dx * long(s.b.x) + dy * long(s.b.y);
        if (t0 > t1) std::swap(t0, t1);
        lines[{dx, dy, c}].push_back({t0, t1});
    }
    Input out;
    out.points = in.points;
    for (auto& line : lines) {
        const auto [dx, dy, c] = line.first;
        std::vector<Span>& spans = line.second;
        std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.lo < b.lo; });
        // the point at t on the line: solve dy x - dx y = c, dx x + dy y = t
        const double n = double(dx * dx + dy * dy);
        auto at = [&](long t) { return Point{double(c * dy + t * dx) / n, double(t * dy - c * dx) / n}; };
        for (std::size_t i = 0; i < spans.size();) {
            std::size_t j = i;
            long hi = spans[i].hi;
            std::vector<long> cuts;
            while (j < spans.size() && spans[j].lo < hi + (j == i ? 1 : 0)) {
                hi = std::max(hi, spans[j].hi);
                cuts.push_back(spans[j].lo);
                cuts.push_back(spans[j].hi);
                ++j;
            }
            std::sort(cuts.begin(), cuts.end());
            cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
            for (std::size_t k = 0; k + 1 < cuts.size(); ++k) out.segments.push_back({at(cuts[k]), at(cuts[k + 1])});
            i = j;
        }
    }
    return out;
}

// ---------------------------------------------------------------------------
// Ours
// ---------------------------------------------------------------------------

struct Ours {
    std::vector<Point> point_sites;                    // by site id (points first)
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> segment_of_ends;  // sorted ends -> element
    std::vector<std::pair<std::uint32_t, std::uint32_t>> site_pairs;  // positive-length edges by site ids
    std::vector<std::pair<std::uint32_t, std::uint32_t>> piece_ends;  // per segment site: its end sites
    // After clustering (collapse): element of each site, the elements'
    // pairs, and the segment element of two point elements.
    std::vector<std::uint32_t> element;
    std::size_t elements = 0;       // element ids are below this
    std::size_t live_elements = 0;  // how many are used
    std::vector<bool> cluster;      // a point element of more than one point site
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ends_of_element;  // of a segment element
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> pairs;
    std::size_t sites = 0;
    double pixel = 0.0;
    double build_ms = 0.0;
    segvoronoi_stats stats{};
    Input built;  // the input as built: points and pieces
};

void check(segvoronoi_status status, const char* what, const segvoronoi_builder* b = nullptr) {
    if (status != SEGVORONOI_STATUS_OK) {
        std::string message = std::string(what) + ": " + segvoronoi_status_str(status);
        if (b) message += std::string(" (") + segvoronoi_builder_last_error(b) + ")";
        throw std::runtime_error(message);
    }
}

std::pair<std::uint32_t, std::uint32_t> ordered(std::uint32_t a, std::uint32_t b) {
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}

// The pixel side of our snapping: 2^-46 of the power of two above the
// largest coordinate magnitude.
double pixel_size(const Input& in) {
    double m = 0.0;
    for (const Point& p : in.points) m = std::max({m, std::fabs(p.x), std::fabs(p.y)});
    for (const Segment& s : in.segments) m = std::max({m, std::fabs(s.a.x), std::fabs(s.a.y), std::fabs(s.b.x), std::fabs(s.b.y)});
    double top = std::ldexp(1.0, -1022 + 48);
    while (top <= m) top *= 2.0;
    return std::ldexp(top, -46);
}

Ours build_ours(const Input& in) {
    Ours ours;
    ours.pixel = pixel_size(in);
    segvoronoi_builder* b = segvoronoi_builder_new();
    if (!b) throw std::runtime_error("segvoronoi_builder_new: out of memory");
    std::vector<double> xy;
    for (const Point& p : in.points) xy.insert(xy.end(), {p.x, p.y});
    check(segvoronoi_builder_add_points(b, xy.data(), in.points.size()), "add_points", b);
    xy.clear();
    for (const Segment& s : in.segments) xy.insert(xy.end(), {s.a.x, s.a.y, s.b.x, s.b.y});
    check(segvoronoi_builder_add_segments(b, xy.data(), in.segments.size()), "add_segments", b);
    check(segvoronoi_builder_set_split_crossings(b, 1), "set_split_crossings", b);
    segvoronoi_diagram* d = nullptr;
    const auto start = std::chrono::steady_clock::now();
    const segvoronoi_status built = segvoronoi_builder_build(b, &d);
    ours.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    check(built, "build", b);
    segvoronoi_builder_free(b);
    check(segvoronoi_diagram_validate(d), "validate");
    ours.stats.struct_size = sizeof ours.stats;
    check(segvoronoi_diagram_stats(d, &ours.stats), "stats");

    ours.built.points = in.points;
    for (std::size_t j = 0; j < segvoronoi_diagram_piece_count(d); ++j) {
        double e[4];
        check(segvoronoi_diagram_piece(d, j, e), "piece");
        ours.built.segments.push_back({{e[0], e[1]}, {e[2], e[3]}});
    }
    ours.sites = segvoronoi_diagram_site_count(d);
    const std::size_t n_points = segvoronoi_diagram_point_site_count(d);
    for (std::size_t i = 0; i < ours.sites; ++i) {
        segvoronoi_site s{};
        s.struct_size = sizeof s;
        check(segvoronoi_diagram_site(d, i, &s), "site");
        if (i < n_points) {
            ours.point_sites.push_back({s.x, s.y});
        } else {
            std::uint32_t ends[2];
            check(segvoronoi_diagram_segment_endpoints(d, i, ends), "segment_endpoints");
            ours.piece_ends.emplace_back(ends[0], ends[1]);
        }
    }

    // The pairs of sites of the edges of positive length: both ends finite
    // and more than 4 pixels apart, or a ray. (Exact zero length, as the
    // topology's VPAIRS decides it, would keep the edges of pixel size at a
    // crossing snapped into a cluster of pixels, below, where CGAL's are
    // exactly zero; two vertices that are one point are computed far closer
    // than a pixel.)
    const std::size_t n_edges = segvoronoi_diagram_edge_count(d);
    for (std::size_t i = 0; i < n_edges; ++i) {
        segvoronoi_edge e{};
        e.struct_size = sizeof e;
        check(segvoronoi_diagram_edge(d, i, &e), "edge");
        if (!e.is_infinite &&
            std::hypot(e.ends[0].x - e.ends[1].x, e.ends[0].y - e.ends[1].y) <= 4.0 * ours.pixel) {
            continue;
        }
        ours.site_pairs.emplace_back(e.sites[0], e.sites[1]);
    }
    segvoronoi_diagram_free(d);
    return ours;
}

// Our point site within `tolerance` of (x, y), nearest; -1 if none. The
// grid's cells are `cell` wide, at least twice the tolerance.
struct PointIndex {
    double cell;
    std::map<std::pair<long, long>, std::vector<std::uint32_t>> cells;
    const std::vector<Point>* points;

    PointIndex(const std::vector<Point>& pts, double cell_side) : cell(cell_side), points(&pts) {
        for (std::uint32_t i = 0; i < pts.size(); ++i) cells[key(pts[i].x, pts[i].y)].push_back(i);
    }
    std::pair<long, long> key(double x, double y) const {
        return {long(std::floor(x / cell)), long(std::floor(y / cell))};
    }
    long find(double x, double y, double tolerance) const {
        const auto k = key(x, y);
        long best = -1;
        double best_d = tolerance;
        for (long dx = -1; dx <= 1; ++dx) {
            for (long dy = -1; dy <= 1; ++dy) {
                const auto it = cells.find({k.first + dx, k.second + dy});
                if (it == cells.end()) continue;
                for (std::uint32_t i : it->second) {
                    const double d = std::hypot((*points)[i].x - x, (*points)[i].y - y);
                    if (d <= best_d) {
                        best_d = d;
                        best = long(i);
                    }
                }
            }
        }
        return best;
    }
};

// Our snapping makes a crossing hot in every pixel within an eighth of a
// pixel of its computed point (up to four), and bends the crossing
// segments through each: a crossing can become a cluster of points a pixel
// apart joined by pieces of pixel length, where CGAL has one point. So our
// sites are collapsed before the comparison: point sites within 3 pixels of
// each other (transitively) become one point element, a piece with both
// ends in one cluster becomes that point, and a piece between two clusters
// the segment element of the two (pieces between the same two clusters
// are one element). Pairs are then compared as sets.
void collapse(Ours& ours) {
    const std::size_t n = ours.point_sites.size();
    std::vector<std::uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    const std::function<std::uint32_t(std::uint32_t)> root = [&](std::uint32_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    const double reach = 3.0 * ours.pixel;
    const PointIndex index(ours.point_sites, reach);
    for (const auto& cell : index.cells) {
        for (long dx = -1; dx <= 1; ++dx) {
            for (long dy = -1; dy <= 1; ++dy) {
                const auto it = index.cells.find({cell.first.first + dx, cell.first.second + dy});
                if (it == index.cells.end()) continue;
                for (std::uint32_t a : cell.second) {
                    for (std::uint32_t b : it->second) {
                        const Point &p = ours.point_sites[a], &q = ours.point_sites[b];
                        if (std::hypot(p.x - q.x, p.y - q.y) <= reach) parent[root(a)] = root(b);
                    }
                }
            }
        }
    }
    ours.element.assign(ours.sites, 0);
    for (std::uint32_t i = 0; i < n; ++i) ours.element[i] = root(i);
    std::uint32_t next = std::uint32_t(n);
    for (std::size_t j = 0; j < ours.piece_ends.size(); ++j) {
        const std::uint32_t a = root(ours.piece_ends[j].first), b = root(ours.piece_ends[j].second);
        std::uint32_t e = a;
        if (a != b) {
            const auto found = ours.segment_of_ends.emplace(ordered(a, b), next);
            if (found.second) ++next;
            e = found.first->second;
        }
        ours.element[n + j] = e;
    }
    ours.elements = next;
    ours.cluster.assign(next, false);
    for (std::uint32_t i = 0; i < n; ++i) {
        if (root(i) != i) ours.cluster[root(i)] = true;
    }
    ours.ends_of_element.assign(next, {0, 0});
    for (const auto& kv : ours.segment_of_ends) ours.ends_of_element[kv.second] = kv.first;
    ours.live_elements = next - n;
    for (std::uint32_t i = 0; i < n; ++i) ours.live_elements += root(i) == i;
    for (const auto& pr : ours.site_pairs) {
        const std::uint32_t a = ours.element[pr.first], b = ours.element[pr.second];
        if (a != b) ours.pairs[ordered(a, b)] = 1;
    }
}

// ---------------------------------------------------------------------------
// CGAL's side
// ---------------------------------------------------------------------------

using K = CGAL::Simple_cartesian<double>;
// Exact predicates (interval filter, then Gmpq) with intersections: CGAL
// splits crossing segments itself, at exact intersection points.
using Gt = CGAL::Segment_Delaunay_graph_filtered_traits_2<K, CGAL::Field_with_sqrt_tag>;
// The hierarchy, as segvoronoi_cgal_check uses; --plain: without it (CGAL
// 5.5's hierarchy crashes, a stack overflow in insert_point ->
// insert_segment_on_point, on star 200 seed 3: 200 segments through one
// point; the plain graph builds it, 4x slower).
using Sdg = CGAL::Segment_Delaunay_graph_hierarchy_2<Gt>;
using PlainSdg = CGAL::Segment_Delaunay_graph_2<Gt>;
using Site = Gt::Site_2;
using Q = CGAL::Gmpq;

// The exact point of a point site: an input point, or the crossing of its
// two supporting segments' lines solved in rationals.
QPoint exact_qpoint(const Site& s) {
    if (s.is_input()) return {Q(s.point().x()), Q(s.point().y())};
    const K::Point_2 &p1 = s.source_of_supporting_site(0), &p2 = s.target_of_supporting_site(0);
    const K::Point_2 &q1 = s.source_of_supporting_site(1), &q2 = s.target_of_supporting_site(1);
    const Q ax(p1.x()), ay(p1.y()), bx(p2.x()), by(p2.y());
    const Q cx(q1.x()), cy(q1.y()), dx(q2.x()), dy(q2.y());
    const Q rx = bx - ax, ry = by - ay, sx = dx - cx, sy = dy - cy;
    const Q den = rx * sy - ry * sx;
    if (den == 0) throw std::runtime_error("CGAL point site on two parallel supporting segments");
    const Q t = ((cx - ax) * sy - (cy - ay) * sx) / den;
    return {ax + t * rx, ay + t * ry};
}

// The same rounded to double.
Point exact_point(const Site& s) {
    const QPoint q = exact_qpoint(s);
    return {CGAL::to_double(q.x), CGAL::to_double(q.y)};
}

// Zero length decided as segvoronoi_cgal_check does (see
// is_zero_length_sites there: CGAL's is_degenerate_edge misses a circle
// tangent to a segment at one of the face's points), with exact rational
// points for the intersection sites: the Voronoi vertex of a face in
// rationals where it is rational (three points; two points and a segment
// from one of them; two points and a segment when the tangent circle is
// rational, cgal_rational.hpp), else CGAL's predicate.
bool rational_vertex(const Site& a, const Site& b, const Site& c, Q& x, Q& y) {
    std::vector<QPoint> points;
    const Site* segment = nullptr;
    const Site* order[3] = {&a, &b, &c};
    if (a.is_segment()) order[0] = &b, order[1] = &c, order[2] = &a;
    if (b.is_segment()) order[0] = &c, order[1] = &a, order[2] = &b;
    for (const Site* site : order) {
        if (site->is_point()) {
            points.push_back(exact_qpoint(*site));
        } else if (segment == nullptr) {
            segment = site;
        } else {
            return false;
        }
    }
    Q n1x, n1y, c1, n2x, n2y, c2;
    const auto bisector = [](const QPoint& p, const QPoint& q, Q& nx, Q& ny, Q& cc) {
        nx = q.x - p.x;
        ny = q.y - p.y;
        cc = (nx * (p.x + q.x) + ny * (p.y + q.y)) / Q(2);
    };
    bisector(points[0], points[1], n1x, n1y, c1);
    if (segment == nullptr) {
        bisector(points[0], points[2], n2x, n2y, c2);
    } else {
        const QPoint s0 = exact_qpoint(segment->source_site()), s1 = exact_qpoint(segment->target_site());
        const bool at_source = s0 == points[0] || s0 == points[1];
        const bool at_target = s1 == points[0] || s1 == points[1];
        if (at_source && at_target) return false;
        if (!at_source && !at_target) return rational_pps(points[0], points[1], s0, s1, x, y);
        const QPoint e = at_source ? s0 : s1, f = at_source ? s1 : s0;
        n2x = f.x - e.x;
        n2y = f.y - e.y;
        c2 = n2x * e.x + n2y * e.y;
    }
    const Q det = n1x * n2y - n1y * n2x;
    if (det == 0) return false;
    x = (c1 * n2y - c2 * n1y) / det;
    y = (n1x * c2 - n2x * c1) / det;
    return true;
}

bool is_zero_length_sites(const Gt& traits, const Site& p, const Site& q, const Site& r, const Site& s) {
    Q x1, y1, x2, y2;
    if (rational_vertex(p, q, r, x1, y1) && rational_vertex(q, p, s, x2, y2)) return x1 == x2 && y1 == y2;
    return traits.is_degenerate_edge_2_object()(p, q, r, s);
}

struct Cgal {
    std::size_t sites = 0;
    std::size_t intersection_points = 0;
    double build_ms = 0.0;
    // per finite CGAL vertex: its site, and its positive-length neighbours
    std::vector<Site> site;
    std::vector<std::pair<std::size_t, std::size_t>> pairs;  // VPAIRS by CGAL vertex number
};

template <class Sdg>
Cgal build_cgal(const Input& in) {
    Cgal cgal;
    Sdg sdg;
    const auto start = std::chrono::steady_clock::now();
    for (const Point& p : in.points) sdg.insert(K::Point_2(p.x, p.y));
    for (const Segment& s : in.segments) sdg.insert(K::Point_2(s.a.x, s.a.y), K::Point_2(s.b.x, s.b.y));
    cgal.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::map<const void*, std::size_t> number;
    for (auto v = sdg.finite_vertices_begin(); v != sdg.finite_vertices_end(); ++v) {
        number.emplace(&*v, cgal.site.size());
        cgal.site.push_back(v->site());
        if (v->site().is_point() && !v->site().is_input()) ++cgal.intersection_points;
    }
    cgal.sites = cgal.site.size();
    if (sdg.dimension() < 1) return cgal;
    const Gt& traits = sdg.geom_traits();
    for (auto e = sdg.finite_edges_begin(); e != sdg.finite_edges_end(); ++e) {
        const typename Sdg::Vertex_handle a = e->first->vertex(Sdg::ccw(e->second));
        const typename Sdg::Vertex_handle b = e->first->vertex(Sdg::cw(e->second));
        const bool finite = sdg.dimension() == 2 && !sdg.is_infinite(e->first) &&
                            !sdg.is_infinite(e->first->neighbor(e->second));
        if (finite) {
            const typename Sdg::Vertex_handle apex = e->first->vertex(e->second);
            const typename Sdg::Vertex_handle mirror = sdg.tds().mirror_vertex(e->first, e->second);
            if (apex != mirror &&
                is_zero_length_sites(traits, a->site(), b->site(), apex->site(), mirror->site())) {
                continue;  // zero length
            }
        }
        cgal.pairs.emplace_back(number.at(&*a), number.at(&*b));
    }
    return cgal;
}

// ---------------------------------------------------------------------------
// Comparison
// ---------------------------------------------------------------------------

// --write-pieces FILE: where to write our pieces of the as-is variant.
std::string write_pieces;
// --plain: CGAL's graph without the hierarchy.
bool plain = false;

std::string describe(const Point& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
    return buf;
}

bool compare(const std::string& family, const std::string& variant, const Input& in, double min_agreement,
             bool verbose, bool cgal_of_pieces) {
    Ours ours = build_ours(in);
    collapse(ours);
    if (!write_pieces.empty() && variant == "as-is" && !write_boost_file(write_pieces, ours.built)) {
        throw std::runtime_error("cannot write " + write_pieces);
    }
    const Input& for_cgal = cgal_of_pieces ? ours.built : without_overlaps(in);
    const Cgal cgal = plain ? build_cgal<PlainSdg>(for_cgal) : build_cgal<Sdg>(for_cgal);
    const double tolerance = 2.0 * ours.pixel;
    const PointIndex index(ours.point_sites, 2.0 * tolerance);

    // map CGAL vertices to our sites
    std::vector<long> image(cgal.sites, -1);
    std::vector<Point> where(cgal.sites);
    std::vector<std::size_t> unmapped;
    for (std::size_t i = 0; i < cgal.sites; ++i) {
        const Site& s = cgal.site[i];
        if (s.is_point()) {
            where[i] = exact_point(s);
            const long k = index.find(where[i].x, where[i].y, tolerance);
            if (k >= 0) image[i] = ours.element[std::size_t(k)];
        } else {
            const Point a = exact_point(s.source_site()), b = exact_point(s.target_site());
            where[i] = {a.x / 2 + b.x / 2, a.y / 2 + b.y / 2};
            const long ia = index.find(a.x, a.y, tolerance), ib = index.find(b.x, b.y, tolerance);
            if (ia >= 0 && ib >= 0) {
                const auto it = ours.segment_of_ends.find(
                    ordered(ours.element[std::size_t(ia)], ours.element[std::size_t(ib)]));
                if (it != ours.segment_of_ends.end()) image[i] = it->second;
            }
        }
        if (image[i] < 0) unmapped.push_back(i);
    }
    std::vector<bool> hit(ours.elements, false);
    std::size_t mapped = 0;
    for (long m : image) {
        if (m >= 0) {
            ++mapped;
            hit[std::size_t(m)] = true;
        }
    }

    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> theirs;
    std::size_t cgal_unmapped_edges = 0;
    for (const auto& pr : cgal.pairs) {
        if (image[pr.first] < 0 || image[pr.second] < 0) {
            ++cgal_unmapped_edges;
            continue;
        }
        if (image[pr.first] == image[pr.second]) {
            // two CGAL sites our snapping merged (reported as unmapped_cgal
            // when they are point and point)
            ++cgal_unmapped_edges;
            continue;
        }
        theirs[ordered(std::uint32_t(image[pr.first]), std::uint32_t(image[pr.second]))] = 1;
    }
    // Our edges touching a site that no CGAL site maps to are counted apart
    // too (the other side of the same unmapped feature).
    std::size_t edges_ours = 0, ours_unmapped_edges = 0, agree = 0, only_cgal = 0, only_ours = 0;
    std::size_t cluster_separators = 0, bent_continuations = 0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> diff_cgal, diff_ours, bent;
    // Two segment elements continuing each other (their shared end, or -1):
    // they share an end, point away from it in opposite directions, and the
    // far end of one is within 2 pixels of the other's line. Collinear input
    // segments that continue each other (a straight run of a polyline) have
    // no edge of positive length between them in CGAL's exact arrangement,
    // and their shared end a cell of no area; where a crossing inside one of
    // them was snapped, off the line by up to the displacement, our two
    // pieces meet at a hair below 180 degrees: on the concave side their
    // cells share an edge, on the convex side the shared end has a thin
    // wedge-shaped cell that may reach further sites.
    const auto continues = [&](std::uint32_t a, std::uint32_t b) -> long {
        const std::size_t points = ours.point_sites.size();
        if (a < points || b < points) return -1;
        const auto ea = ours.ends_of_element[a], eb = ours.ends_of_element[b];
        std::uint32_t c, u, w;
        if (ea.first == eb.first || ea.first == eb.second) {
            c = ea.first, u = ea.second, w = ea.first == eb.first ? eb.second : eb.first;
        } else if (ea.second == eb.first || ea.second == eb.second) {
            c = ea.second, u = ea.first, w = ea.second == eb.first ? eb.second : eb.first;
        } else {
            return -1;
        }
        const Point &pc = ours.point_sites[c], &pu = ours.point_sites[u], &pw = ours.point_sites[w];
        const double ux = pu.x - pc.x, uy = pu.y - pc.y, wx = pw.x - pc.x, wy = pw.y - pc.y;
        const double cross = std::fabs(ux * wy - uy * wx);
        const double off = cross / std::max(std::hypot(ux, uy), std::hypot(wx, wy));  // the nearer far end from the other line
        return ux * wx + uy * wy < 0 && off <= 2.0 * ours.pixel ? long(c) : -1;
    };
    // the shared ends of the bent continuations, and the pairs on our side
    // only that are not explained as they are found (one may be explained
    // later as the wedge of such an end)
    std::vector<bool> bent_end(ours.elements, false);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> unexplained;
    for (const auto& e : ours.pairs) {
        edges_ours += e.second;
        if (!hit[e.first.first] || !hit[e.first.second]) {
            ours_unmapped_edges += e.second;
            continue;
        }
        const auto it = theirs.find(e.first);
        const std::size_t c = it == theirs.end() ? 0 : it->second;
        agree += std::min(c, e.second);
        if (e.second > c) {
            // a separator at a cluster: the point element is an end of the
            // segment element and a cluster
            const std::uint32_t a = e.first.first, b = e.first.second;
            const auto is_end = [&](std::uint32_t p, std::uint32_t g) {
                return g >= ours.point_sites.size() && p < ours.point_sites.size() && ours.cluster[p] &&
                       (ours.ends_of_element[g].first == p || ours.ends_of_element[g].second == p);
            };
            if (is_end(a, b) || is_end(b, a)) {
                ++cluster_separators;
            } else if (const long end = continues(a, b); end >= 0) {
                ++bent_continuations;
                bent.push_back(e.first);
                bent_end[std::size_t(end)] = true;
            } else {
                unexplained.push_back(e.first);
            }
        }
    }
    for (const auto& e : unexplained) {
        if (bent_end[e.first] || bent_end[e.second]) {
            ++bent_continuations;  // the wedge of a bent continuation's shared end
            bent.push_back(e);
        } else {
            ++only_ours;
            diff_ours.push_back(e);
        }
    }
    for (const auto& e : theirs) {
        const auto it = ours.pairs.find(e.first);
        const std::size_t o = it == ours.pairs.end() ? 0 : it->second;
        if (e.second > o) {
            only_cgal += e.second - o;
            diff_cgal.push_back(e.first);
        }
    }
    const std::size_t edges_cgal = theirs.size() + cgal_unmapped_edges;
    // agreement leaves out the separators at clusters (explained above);
    // raw_agreement counts them as differences
    const double agreement = double(agree) / double(std::max<std::size_t>(
                                                 1, std::max(edges_cgal, edges_ours - cluster_separators - bent_continuations)));
    const double raw_agreement =
        double(agree) / double(std::max<std::size_t>(1, std::max(edges_cgal, edges_ours)));
    const bool ok = min_agreement > 0.0 ? agreement >= min_agreement
                                        : unmapped.empty() && only_cgal == 0 && only_ours == 0 &&
                                              cgal_unmapped_edges == 0 && ours_unmapped_edges == 0 && cluster_separators == 0 && bent_continuations == 0 &&
                                              std::count(hit.begin(), hit.end(), true) == long(ours.live_elements);
    std::printf(
        "family=%s variant=%s inputs=%zu+%zu sites_cgal=%zu sites_ours=%zu elements_ours=%zu mapped=%zu unmapped_cgal=%zu "
        "crossings_cgal=%zu pieces=%zu crossings=%zu overlaps=%zu touchings=%zu snap_rounds=%zu "
        "edges_cgal=%zu edges_ours=%zu edges_agree=%zu only_cgal=%zu only_ours=%zu cluster_separators=%zu bent_continuations=%zu "
        "unmapped_edges_cgal=%zu unmapped_edges_ours=%zu raw_agreement=%.6f agreement=%.6f ms_ours=%.1f ms_cgal=%.1f verdict=%s\n",
        family.c_str(), variant.c_str(), in.segments.size(), in.points.size(), cgal.sites, ours.sites, ours.live_elements, mapped,
        unmapped.size(), cgal.intersection_points, ours.stats.pieces, ours.stats.crossings, ours.stats.overlaps,
        ours.stats.touchings, ours.stats.snap_rounds, edges_cgal, edges_ours, agree, only_cgal, only_ours,
        cluster_separators, bent_continuations, cgal_unmapped_edges, ours_unmapped_edges, raw_agreement, agreement, ours.build_ms, cgal.build_ms, ok ? "AGREE" : "DIFFER");
    if (verbose || (!ok && min_agreement <= 0.0)) {
        std::size_t shown = 0;
        for (std::size_t i : unmapped) {
            if (++shown > 20) break;
            const Site& s = cgal.site[i];
            std::printf("  unmapped CGAL %s %s%s\n", s.is_point() ? "point" : "segment", describe(where[i]).c_str(),
                        s.is_point() && !s.is_input() ? " (intersection)" : "");
        }
        // an element by its coordinates
        const auto site_text = [&](std::uint32_t s) -> std::string {
            if (s < ours.point_sites.size()) return "P" + describe(ours.point_sites[s]);
            for (const auto& kv : ours.segment_of_ends) {
                if (kv.second == s) {
                    return "S" + describe(ours.point_sites[kv.first.first]) + "-" +
                           describe(ours.point_sites[kv.first.second]);
                }
            }
            return "?";
        };
        auto show = [&](const char* side, const std::pair<std::uint32_t, std::uint32_t>& e) {
            std::printf("  only %s: %s | %s\n", side, site_text(e.first).c_str(), site_text(e.second).c_str());
        };
        shown = 0;
        for (std::uint32_t s = 0; s < ours.elements; ++s) {
            if (hit[s] || (s < ours.point_sites.size() && ours.element[s] != s) || ++shown > 20) continue;
            std::printf("  ours without a CGAL site: %s\n", site_text(s).c_str());
        }
        shown = 0;
        for (const auto& e : diff_cgal) {
            if (++shown > 10) break;
            show("cgal", e);
        }
        shown = 0;
        for (const auto& e : diff_ours) {
            if (++shown > 10) break;
            show("ours", e);
        }
        shown = 0;
        for (const auto& e : bent) {
            if (++shown > 10) break;
            show("ours (bent continuation)", e);
        }
    }
    return ok;
}

int usage() {
    std::fprintf(stderr,
                 "usage: segvoronoi_cgal_split --family NAME --n N [--seed S] [--min-agreement F] [--verbose]\n"
                 "       segvoronoi_cgal_split --file FILE [--seed S] [--min-agreement F] [--verbose]\n"
                 "       segvoronoi_cgal_split --list\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::string family;
    std::string file;
    std::size_t n = 0;
    std::uint64_t seed = 1;
    double min_agreement = 0.0;
    bool verbose = false;
    bool pieces = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
            return argv[++i];
        };
        try {
            if (arg == "--list") {
                for (const Family& f : families) std::printf("%-20s %s\n", f.name, f.about);
                return 0;
            } else if (arg == "--family") {
                family = next();
            } else if (arg == "--file") {
                file = next();
            } else if (arg == "--n") {
                n = std::stoul(next());
            } else if (arg == "--seed") {
                seed = std::stoull(next());
            } else if (arg == "--min-agreement") {
                min_agreement = std::stod(next());
            } else if (arg == "--verbose") {
                verbose = true;
            } else if (arg == "--plain") {
                plain = true;
            } else if (arg == "--write-pieces") {
                write_pieces = next();
            } else if (arg == "--cgal-of-pieces") {
                pieces = true;
            } else {
                return usage();
            }
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s\n", e.what());
            return usage();
        }
    }
    Rng rng(seed);
    Input input;
    if (!file.empty()) {
        if (!family.empty() || n != 0) return usage();
        std::string error;
        if (!read_boost_file(file, input, error)) {
            std::fprintf(stderr, "%s: %s\n", file.c_str(), error.c_str());
            return 2;
        }
        family = "file:" + file.substr(file.find_last_of('/') + 1);
    } else {
        const Family* chosen = nullptr;
        for (const Family& f : families) {
            if (family == f.name) chosen = &f;
        }
        if (!chosen || n == 0) return usage();
        input = chosen->make(n, rng);
    }
    Input reversed = input;
    for (Segment& s : reversed.segments) std::swap(s.a, s.b);
    Input shuffled = input;
    std::shuffle(shuffled.segments.begin(), shuffled.segments.end(), rng);
    std::shuffle(shuffled.points.begin(), shuffled.points.end(), rng);
    bool ok = true;
    try {
        ok &= compare(family, "as-is", input, min_agreement, verbose, pieces);
        ok &= compare(family, "reversed", reversed, min_agreement, verbose, pieces);
        ok &= compare(family, "shuffled", shuffled, min_agreement, verbose, pieces);
    } catch (const std::exception& e) {
        std::printf("family=%s error: %s\n", family.c_str(), e.what());
        return 3;
    }
    return ok ? 0 : 1;
}
