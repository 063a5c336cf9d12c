// segvoronoi_cgal_check: builds the Voronoi diagram of one set of points and
// line segments with segvoronoi (through its C API) and with CGAL's segment
// Delaunay graph (exact predicates), writes both in the canonical topology of
// src/query/topology.rs and compares them as multisets of lines. It reads its
// inputs; the generated ones come from segvoronoi-testgen (testgen/: every
// family, `segvoronoi-testgen --list`, and the search's cases).
//
//   segvoronoi_cgal_check --file input.txt [--degenerate] [--family NAME]
//   segvoronoi_cgal_check --search SECONDS [seed] [--generic] [--no-subnormal] [--out DIR] [--testgen PATH]
//   segvoronoi_cgal_check --minimise input.txt [--degenerate]
//   segvoronoi_cgal_check --polygon rings.txt [--family NAME]
//
// The file is in Boost.Polygon's text format: P, then P lines "x y", then S,
// then S lines "x1 y1 x2 y2" (S may be left out when zero). Generic input
// (the default): EDGES and FACES must agree exactly. Degenerate input
// (--degenerate: cocircular or collinear sites, where the Delaunay graph is
// not unique): only VPAIRS and VVERTICES are unique, so only they must agree.
// On CGAL's side their zero length is decided exactly: the two Voronoi
// vertices of an edge are constructed by CGAL (Construct_svd_vertex_2) in
// interval arithmetic, and where the intervals cannot tell them apart again
// in CORE::Expr (exact square roots) and compared exactly (same_vertex; the
// summary's exact_vertex_pairs counts those). The library's VPAIRS decide
// zero length exactly too. They are checked for degenerate inputs and
// informational otherwise. A generic input that CGAL finds
// exactly degenerate (a Voronoi edge of length zero) is compared again as
// degenerate when the generic comparison differs. --family names the input
// in the summary line (c_tests/cgal_family.cmake passes the family). Exit
// status: 0 agreement and a valid diagram, 1 a difference or an invalid
// diagram, 2 bad usage or input, 3 a library error.
//
// --search runs small random inputs until SECONDS are up (seed: a new one
// each run unless given; printed first). They come from `segvoronoi-testgen
// search SEED [--generic]` through a pipe (the kinds are described in
// testgen/src/search.rs; --generic: only those compared as generic, without
// the near-degenerate ones), one record per input: the input as generated
// and a shuffled copy (--no-subnormal: the kinds that move zeros to
// subnormals are skipped). Each input is checked as generated, with every
// segment reversed and shuffled. A difference, an invalid diagram or a
// library error (an INTERSECTING status included: the generator only makes
// legal inputs, checked exactly) is a failure: it is minimised (drop
// segments and points one at a time while it still fails, in a few orders,
// then turn reversed segments back) and printed in the input format (and
// written to DIR with --out). Ends with "search: inputs=N per_minute=M
// failures=K"; exit status 1 when K > 0. --minimise applies the same
// minimisation to a failing file. The generator is the one CMake built
// (SEGVORONOI_TESTGEN_PATH), or --testgen PATH.
//
// --polygon compares the medial axis of a polygon with holes (issue 9). The
// file is in the rings format (testgen/src/rings.rs writes it, and the
// glyph fixtures tests/data/glyph_*.rings use it): a line "rings R", then
// for each ring a line with its point count K and K lines "x y", the last
// point joining the first; lines starting with '#' are comments. The
// domain is the even-odd region of the rings. Ours: the rings through
// segvoronoi_builder_add_polygon; every edge whose location is INSIDE, not
// a separator, and of positive length (zero length decided exactly from the
// sites of its two vertices, by exact construction as for CGAL's edges).
// CGAL's: the ring segments in the segment Delaunay graph; the dual of
// every finite Delaunay edge that is not a separator and not of length
// zero, a ray counting as outside, a finite edge inside when a point
// strictly inside it (edge_middle) is, by the exact even-odd rule. The two
// multisets of site pairs (the canonical names) must be equal, and the
// library's medial axis must hold exactly its INSIDE non-separator edges.
// Prints "family=... mode=polygon ... verdict=AGREE|DIFFER"; exit status as
// for --file.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/CORE_Expr.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Segment_Delaunay_graph_traits_2.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Segment_Delaunay_graph_hierarchy_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "boost_text.hpp"
#include "segvoronoi.h"

#ifndef SEGVORONOI_TESTGEN_PATH
#define SEGVORONOI_TESTGEN_PATH "segvoronoi-testgen"
#endif

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

// Inputs are read and written in Boost.Polygon's text format (boost_text.hpp).
bool read_file(const std::string& path, Input& input, std::string& error) {
    input.family = "file";
    return read_boost_file(path, input, error);
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


// Voronoi vertices constructed exactly: CGAL's own construction
// (Construct_svd_vertex_2, the Voronoi vertex of three sites given
// counter-clockwise) over a kernel of intervals (the filter) and over one of
// CORE::Expr (exact real algebraic numbers with square roots: its == is
// decided exactly, by separation bounds where the numbers are equal).
using Ki = CGAL::Simple_cartesian<CGAL::Interval_nt<false>>;
using Gti = CGAL::Segment_Delaunay_graph_traits_without_intersections_2<Ki, CGAL::Field_with_sqrt_tag>;
using Kx = CGAL::Simple_cartesian<CORE::Expr>;
using Gtx = CGAL::Segment_Delaunay_graph_traits_without_intersections_2<Kx, CGAL::Field_with_sqrt_tag>;

// An input site (a point, or a segment by its endpoints; the traits
// without intersections make no other) in the kernel of G, exactly.
template <class G>
typename G::Site_2 convert_site(const Gt::Site_2& site) {
    using P = typename G::Point_2;
    if (site.is_point()) return G::Site_2::construct_site_2(P(site.point().x(), site.point().y()));
    const K::Segment_2 seg = site.segment();
    return G::Site_2::construct_site_2(P(seg.source().x(), seg.source().y()), P(seg.target().x(), seg.target().y()));
}

template <class G>
typename G::Point_2 construct_vertex(const Gt::Site_2& a, const Gt::Site_2& b, const Gt::Site_2& c) {
    return typename G::Construct_svd_vertex_2()(convert_site<G>(a), convert_site<G>(b), convert_site<G>(c));
}

// An input site in CORE::Expr, every coordinate multiplied by 2^k: exactly
// (in double where that is exact, else as a product of two Exprs).
Gtx::Site_2 convert_scaled(const Gt::Site_2& site, int k) {
    const auto scaled = [k](double v) {
        const double w = std::ldexp(v, k);
        if (std::isfinite(w) && std::ldexp(w, -k) == v) return CORE::Expr(w);
        return CORE::Expr(v) * CORE::Expr(std::ldexp(1.0, k / 2)) * CORE::Expr(std::ldexp(1.0, k - k / 2));
    };
    using P = Gtx::Point_2;
    if (site.is_point()) return Gtx::Site_2::construct_site_2(P(scaled(site.point().x()), scaled(site.point().y())));
    const K::Segment_2 seg = site.segment();
    return Gtx::Site_2::construct_site_2(P(scaled(seg.source().x()), scaled(seg.source().y())),
                                         P(scaled(seg.target().x()), scaled(seg.target().y())));
}

// The exact vertices constructed so far, by their three sites (each as
// kind and coordinates) and scale: a face is asked about once per edge, and
// CORE keeps the precision it has reached in the nodes of an Expr, so the
// second comparison of a vertex is much cheaper than the first. The key is the geometry itself, so
// entries never go stale; cleared for each input to bound the memory.
using ExactVertexKey = std::pair<std::array<double, 15>, int>;
std::map<ExactVertexKey, Kx::Point_2> g_exact_vertices;

void clear_exact_vertices() { g_exact_vertices.clear(); }

// The Voronoi vertex of the face (a, b, c) in CORE::Expr, every coordinate
// of the sites multiplied by 2^k; from g_exact_vertices when it was made
// before.
Kx::Point_2 exact_vertex(const Gt::Site_2& a, const Gt::Site_2& b, const Gt::Site_2& c, int k) {
    ExactVertexKey key{{}, k};
    std::size_t n = 0;
    for (const Gt::Site_2* site : {&a, &b, &c}) {
        if (site->is_point()) {
            for (double v : {0.0, site->point().x(), site->point().y(), 0.0, 0.0}) key.first[n++] = v;
        } else {
            const K::Segment_2 seg = site->segment();
            for (double v : {1.0, seg.source().x(), seg.source().y(), seg.target().x(), seg.target().y()}) {
                key.first[n++] = v;
            }
        }
    }
    const auto found = g_exact_vertices.find(key);
    if (found != g_exact_vertices.end()) return found->second;
    const Kx::Point_2 vertex =
        Gtx::Construct_svd_vertex_2()(convert_scaled(a, k), convert_scaled(b, k), convert_scaled(c, k));
    g_exact_vertices.emplace(key, vertex);
    return vertex;
}

// The largest and the least nonzero magnitude of a coordinate of the sites
// (0 when all are 0).
std::pair<double, double> coordinate_range(std::initializer_list<const Gt::Site_2*> sites) {
    double largest = 0.0, least = 0.0;
    const auto note = [&](double v) {
        v = std::abs(v);
        if (v == 0.0) return;
        largest = std::max(largest, v);
        least = least == 0.0 ? v : std::min(least, v);
    };
    for (const Gt::Site_2* site : sites) {
        if (site->is_point()) {
            note(site->point().x());
            note(site->point().y());
        } else {
            const K::Segment_2 seg = site->segment();
            for (double v : {seg.source().x(), seg.source().y(), seg.target().x(), seg.target().y()}) note(v);
        }
    }
    return {largest, least};
}

// How many vertex pairs needed the exact construction (the filter could
// not tell them apart), and how many of those were one point: reported on
// the summary line.
std::size_t g_exact_vertex_pairs = 0;
std::size_t g_exact_vertex_same = 0;

// How many exact constructions were not made (magnitudes that spread over
// more than 2^400) or that CGAL's formula could not make (a square root of
// a negative number: CORE then marks the result invalid instead of
// aborting, see same_vertex); those edges fall back to CGAL's
// Is_degenerate_edge_2 (exact_fallback on the summary line).
std::size_t g_exact_vertex_invalid = 0;

// Whether the Voronoi vertices of the faces (a1, a2, a3) and (b1, b2, b3)
// (each counter-clockwise) are one point, exactly. The construction in
// interval arithmetic (rounding upward, as CGAL's filtered predicates do)
// says "apart" when the two boxes are disjoint; where it cannot (boxes that
// overlap, or a branch inside the construction that the intervals cannot
// decide: CGAL throws Uncertain_conversion_exception) the vertices are
// constructed in CORE::Expr and compared exactly.
//
// CGAL's formulas take a square root of a negative number on some faces of
// nearly parallel segments and a point (compute_pll); CORE would abort the
// program there, so its abort flag is off and its invalid flag is read
// instead: std::nullopt then (the construction is not CGAL's vertex).
std::optional<bool> same_vertex(const Gt::Site_2& a1, const Gt::Site_2& a2, const Gt::Site_2& a3,
                                const Gt::Site_2& b1, const Gt::Site_2& b2, const Gt::Site_2& b3) {
    {
        CGAL::Protect_FPU_rounding<true> upward;
        try {
            const Ki::Point_2 u = construct_vertex<Gti>(a1, a2, a3), v = construct_vertex<Gti>(b1, b2, b3);
            if (!CGAL::possibly(u.x() == v.x()) || !CGAL::possibly(u.y() == v.y())) return false;
        } catch (const CGAL::Uncertain_conversion_exception&) {
            // undecided in intervals: exactly below
        }
    }
    ++g_exact_vertex_pairs;
    // CORE::Expr is not reliable where magnitudes spread wide (a
    // coordinate 2^-1074 beside 1: its BigFloat division reports a zero
    // divisor and exits): those pairs fall back
    const std::pair<double, double> range = coordinate_range({&a1, &a2, &a3, &b1, &b2, &b3});
    if (range.first > 0.0 && std::ilogb(range.first) - std::ilogb(range.second) > 400) {
        ++g_exact_vertex_invalid;
        return std::nullopt;
    }
    CORE::get_static_AbortFlag() = false;
    CORE::get_static_InvalidFlag() = 0;
    // scaled by a power of two so that the largest coordinate is about 1:
    // the answer is the same, and CORE's double filter, which underflows
    // at 1e-180 (its squares), then wrongly found divisions by zero
    // (cgal_tiny-lattice_2500)
    const int k = range.first > 0.0 ? -std::ilogb(range.first) : 0;
    const Kx::Point_2 u = exact_vertex(a1, a2, a3, k), v = exact_vertex(b1, b2, b3, k);
    if (CORE::get_static_InvalidFlag() != 0) {
        ++g_exact_vertex_invalid;
        return std::nullopt;
    }
    const bool same = u.x() == v.x() && u.y() == v.y();
    if (same) ++g_exact_vertex_same;
    return same;
}

// Whether the Voronoi edge of a finite Delaunay edge (p, q) between the
// faces (p, q, r) and (q, p, s) (each counter-clockwise) has length zero,
// exactly: its two vertices, constructed exactly, are one point. Two faces
// of the same three sites (far apart, with segments) are two different
// circles; callers leave them out (r == s).
//
// CGAL's own predicate (Is_degenerate_edge_2: each apex on the other
// face's circle) is not used: it is vacuous on the edges of a 2-gon, and
// it counts an open segment that touches a circle only at its endpoint as
// outside it, so where a face's circle is tangent to a segment at one of
// the face's points (a vertex of points P, Q and the segment ending at Q;
// every straight joint of a chain makes one) it says "not degenerate" for
// two vertices that are one point.
//
// The same test decides zero length for the library's edges in --polygon
// (from the sites of each edge's two vertices).
bool is_zero_length_sites(const Gt::Site_2& p, const Gt::Site_2& q, const Gt::Site_2& r, const Gt::Site_2& s) {
    if (const std::optional<bool> same = same_vertex(p, q, r, q, p, s)) return *same;
    return Gt().is_degenerate_edge_2_object()(p, q, r, s);
}

bool is_zero_length_edge(const Sdg& sdg, const Sdg::Edge& e) {
    const Sdg::Vertex_handle apex = e.first->vertex(e.second);
    const Sdg::Vertex_handle mirror = sdg.tds().mirror_vertex(e.first, e.second);
    if (apex == mirror) return false;
    const auto ends = edge_vertices(e);
    return is_zero_length_sites(ends.first->site(), ends.second->site(), apex->site(), mirror->site());
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
// informational there, and the search need not pay for them).
CgalResult build_cgal(const Sites& sites, const Input& input, bool voronoi = true) {
    clear_exact_vertices();
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
                  "zero_length_edges=%zu exact_vertex_pairs=%zu exact_fallback=%zu ours_build_ms=%.1f cgal_build_ms=%.1f valid=%s "
                  "verdict=%s\n",
                  input.family.c_str(), input.points.size() + input.segments.size(), input.segments.size(),
                  sites.count(), input.degenerate ? "yes" : "no", ours.full.count("EDGES"),
                  cgal.topology.count("EDGES"), ours.full.count("FACES"), cgal.topology.count("FACES"), matched,
                  only_ours, only_cgal, cgal.dimension, cgal.cocircular_edges, cgal.degenerate_edges, g_exact_vertex_pairs,
                  g_exact_vertex_invalid, ours.build_ms, cgal.build_ms,
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
// Randomised search (--search SECONDS [seed]): the generator's inputs until
// the time is up, each cross-checked as generated, with every segment
// reversed and shuffled; every difference, invalid diagram or library error
// is minimised and printed in the input format.
// ---------------------------------------------------------------------------

// The reorderings minimise tries (std::mt19937_64 is the same sequence on
// every platform; the distributions of <random> are not, so no std::shuffle).
template <class T>
void shuffle(std::vector<T>& items, std::mt19937_64& rng) {
    for (std::size_t i = items.size(); i > 1; --i) std::swap(items[i - 1], items[rng() % i]);
}

enum class Outcome { Agree, Fail, CgalError };

struct RunResult {
    Outcome outcome = Outcome::Agree;
    std::string text;
    // Generic comparison differed on an exactly degenerate input, and the
    // degenerate comparison agreed.
    bool degenerate_fallback = false;
};

// The input being checked, for the SIGFPE report.
const Input* g_current_input = nullptr;

extern "C" void report_sigfpe(int) {
    // Raised synchronously (GMP's division by zero calls raise()), so stdio
    // is usable here in practice.
    std::printf("CRASH: SIGFPE (GMP division by zero in a CGAL construction?) on this input:\n");
    if (g_current_input != nullptr) write_boost_text(stdout, *g_current_input);
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
    std::mt19937_64 rng(seed);
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


// One record of `segvoronoi-testgen search`: a line "input K CASE_SEED KIND
// DEGENERATE", the input as generated and its shuffled copy.
struct SearchRecord {
    unsigned long long k = 0;
    unsigned long long case_seed = 0;
    std::string kind;
    Input input;
    Input shuffled;
};

bool read_record(std::FILE* in, SearchRecord& record, std::string& error) {
    char kind[128];
    int degenerate = 0;
    if (std::fscanf(in, " input %llu %llu %127s %d", &record.k, &record.case_seed, kind, &degenerate) != 4) {
        error = "no record header";
        return false;
    }
    record.input = Input();
    record.shuffled = Input();
    if (!read_boost_text(in, record.input, error) || !read_boost_text(in, record.shuffled, error)) return false;
    record.kind = kind;
    record.input.family = record.shuffled.family = kind;
    record.input.degenerate = record.shuffled.degenerate = degenerate != 0;
    return true;
}

int search(double seconds, std::uint64_t seed, bool generic_only, bool no_subnormal, const std::string& out_dir,
           const std::string& testgen) {
    std::signal(SIGFPE, report_sigfpe);
    std::printf("search: seconds=%g seed=%llu%s%s\n", seconds, static_cast<unsigned long long>(seed),
                generic_only ? " generic" : "", no_subnormal ? " no-subnormal" : "");
    std::fflush(stdout);
    const std::string command =
        "'" + testgen + "' search " + std::to_string(seed) + (generic_only ? " --generic" : "");
    std::FILE* stream = popen(command.c_str(), "r");
    if (stream == nullptr) {
        std::fprintf(stderr, "segvoronoi_cgal_check: cannot run %s\n", command.c_str());
        return 2;
    }
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    std::size_t inputs = 0, runs = 0, failures = 0, cgal_errors = 0, empty = 0, fallbacks = 0;
    std::map<std::string, std::size_t> kinds;
    SearchRecord c;
    std::string error;
    bool stream_ok = true;
    while (elapsed() < seconds) {
        if (!read_record(stream, c, error)) {
            std::fprintf(stderr, "segvoronoi_cgal_check: %s: %s\n", command.c_str(), error.c_str());
            stream_ok = false;
            break;
        }
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
        // and segments shuffled.
        const std::size_t n = c.input.segments.size();
        Input reversed = c.input;
        for (Segment& s : reversed.segments) std::swap(s.a, s.b);
        const struct {
            const char* name;
            const Input* input;
            std::vector<bool> flipped;
        } variants[] = {{"as generated", &c.input, std::vector<bool>(n, false)},
                        {"every segment reversed", &reversed, std::vector<bool>(n, true)},
                        {"shuffled", &c.shuffled, std::vector<bool>(n, false)}};
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
            const Input smallest = minimise(*variant.input, variant.flipped, c.case_seed, runs, deadline);
            const RunResult again = run_one(smallest);
            std::printf("FAILURE %zu: kind=%s case_seed=%llu (search seed %llu, input %llu) variant=%s degenerate=%s "
                        "segments %zu -> %zu, points %zu -> %zu\n",
                        failures, c.kind.c_str(), c.case_seed, static_cast<unsigned long long>(seed), c.k,
                        variant.name, smallest.degenerate ? "yes" : "no", variant.input->segments.size(),
                        smallest.segments.size(), variant.input->points.size(), smallest.points.size());
            std::printf("--- minimised input (Boost.Polygon text; compare with%s) ---\n",
                        smallest.degenerate ? " --degenerate" : "");
            write_boost_text(stdout, smallest);
            std::printf("--- its comparison ---\n%s", again.text.c_str());
            std::printf("--- first result of the unminimised input ---\n%s---\n", result.text.c_str());
            if (!out_dir.empty()) {
                const std::string path = out_dir + "/search_" + std::to_string(c.case_seed) + "_" +
                                         std::to_string(failures) + (smallest.degenerate ? "_deg" : "") + ".txt";
                if (!write_boost_file(path, smallest)) std::fprintf(stderr, "cannot write %s\n", path.c_str());
            }
            std::fflush(stdout);
            break;  // one failure per input is enough
        }
    }
    pclose(stream);  // the generator ends on the closed pipe
    const double minutes = elapsed() / 60.0;
    std::string kind_counts;
    for (const auto& entry : kinds) kind_counts += " " + entry.first + "=" + std::to_string(entry.second);
    std::printf("search: kinds:%s; runs=%zu cgal_errors=%zu empty=%zu degenerate_fallbacks=%zu\n",
                kind_counts.c_str(), runs, cgal_errors, empty, fallbacks);
    std::printf("search: inputs=%zu per_minute=%.0f failures=%zu\n", inputs,
                minutes > 0.0 ? static_cast<double>(inputs) / minutes : 0.0, failures);
    if (!stream_ok) return 2;
    return failures > 0 ? 1 : 0;
}

int usage() {
    std::fprintf(stderr,
                 "usage: segvoronoi_cgal_check --file input.txt [--degenerate] [--family NAME]\n"
                 "       segvoronoi_cgal_check --search SECONDS [seed] [--generic] [--no-subnormal] [--out DIR] "
                 "[--testgen PATH]\n"
                 "       segvoronoi_cgal_check --minimise input.txt [--degenerate]\n"
                 "       segvoronoi_cgal_check --polygon rings.txt [--family NAME]\n"
                 "inputs of a family: segvoronoi-testgen FAMILY N [SEED] > input.txt (--list: the families, and "
                 "which are compared as degenerate)\n");
    return 2;
}

bool parse_count(const char* text, std::uint64_t& value) {
    char* end = nullptr;
    errno = 0;
    value = std::strtoull(text, &end, 10);
    return errno == 0 && end != text && *end == '\0' && text[0] != '-';
}

// --file PATH [--degenerate] [--family NAME]: fills `input`; returns false
// after printing why not.
bool parse_arguments(int argc, char** argv, Input& input) {
    if (argc < 3 || std::string(argv[1]) != "--file") return usage(), false;
    bool degenerate = false;
    std::string family;
    for (int k = 3; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--degenerate") {
            degenerate = true;
        } else if (arg == "--family" && k + 1 < argc) {
            family = argv[++k];
        } else {
            return usage(), false;
        }
    }
    std::string error;
    if (!read_file(argv[2], input, error)) {
        std::fprintf(stderr, "segvoronoi_cgal_check: %s: %s\n", argv[2], error.c_str());
        return false;
    }
    input.degenerate = degenerate;
    if (!family.empty()) input.family = family;
    return true;
}

// ---------------------------------------------------------------------------
// Medial axis (--polygon FILE): the pairs of sites of the Voronoi edges
// inside a polygon with holes, against CGAL's.
// ---------------------------------------------------------------------------

// Rings format: "rings R", then per ring its point count K and K lines
// "x y" (the last point joins the first); lines starting with '#' are
// comments. Repeated consecutive points and a repeated closing point are
// dropped, as segvoronoi_builder_add_polygon drops them, so that the
// segments here are the library's.
bool read_rings(const std::string& path, std::vector<std::vector<Point>>& rings, std::string& error) {
    std::FILE* in = std::fopen(path.c_str(), "r");
    if (in == nullptr) {
        error = "cannot open " + path;
        return false;
    }
    std::string text;
    char buffer[4096];
    for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, in)) > 0;) text.append(buffer, got);
    std::fclose(in);
    std::istringstream lines(text);
    std::string words, line;
    while (std::getline(lines, line)) {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first != std::string::npos && line[first] != '#') words += line + "\n";
    }
    std::istringstream tokens(words);
    std::string keyword;
    std::size_t ring_count = 0;
    if (!(tokens >> keyword) || keyword != "rings" || !(tokens >> ring_count)) {
        error = "expected `rings R` first";
        return false;
    }
    auto number = [&](double& v) {
        std::string token;
        if (!(tokens >> token)) return false;
        char* end = nullptr;
        v = std::strtod(token.c_str(), &end);
        return *end == '\0' && std::isfinite(v);
    };
    rings.assign(ring_count, {});
    for (std::size_t r = 0; r < ring_count; ++r) {
        std::size_t k = 0;
        if (!(tokens >> k)) {
            error = "ring " + std::to_string(r) + ": missing point count";
            return false;
        }
        for (std::size_t i = 0; i < k; ++i) {
            Point p{};
            if (!number(p.x) || !number(p.y)) {
                error = "ring " + std::to_string(r) + ", point " + std::to_string(i) + ": missing, malformed or not finite";
                return false;
            }
            if (rings[r].empty() || rings[r].back().x != p.x || rings[r].back().y != p.y) rings[r].push_back(p);
        }
        while (rings[r].size() > 1 && rings[r].front().x == rings[r].back().x && rings[r].front().y == rings[r].back().y) {
            rings[r].pop_back();
        }
    }
    std::string rest;
    if (tokens >> rest) {
        error = "text after the last ring";
        return false;
    }
    return true;
}

// Whether (x, y) lies inside the even-odd region of the rings: the
// crossings of a ray to +x (half-open in y), each decided by an exact
// orientation. Asked at points off the rings only.
bool even_odd_inside(const std::vector<std::vector<Point>>& rings, double x, double y) {
    const Epick::Point_2 q(x, y);
    bool inside = false;
    for (const std::vector<Point>& ring : rings) {
        for (std::size_t k = 0; k < ring.size(); ++k) {
            const Point& a = ring[k];
            const Point& b = ring[(k + 1) % ring.size()];
            if ((a.y > y) == (b.y > y)) continue;
            const Point& lo = a.y < b.y ? a : b;
            const Point& hi = a.y < b.y ? b : a;
            if (CGAL::orientation(Epick::Point_2(lo.x, lo.y), Epick::Point_2(hi.x, hi.y), q) == CGAL::LEFT_TURN) {
                inside = !inside;
            }
        }
    }
    return inside;
}

// One side's medial axis as pairs of site names (with multiplicity).
struct AxisResult {
    Section pairs;
    // Edges that are not separators, of length zero (anywhere; left out),
    // and of positive length outside the domain (rays included). The
    // Voronoi diagram decides both, so they agree when the diagrams do
    // (informational: a note when not).
    std::size_t zero_length = 0;
    std::size_t outside = 0;
    // CGAL's: finite edges whose middle point is within 1e-12 of the
    // extent from its sites, so that its rounding might move it across a
    // ring segment (then a difference may be the harness's; none so far).
    std::size_t close_middles = 0;
    double build_ms = 0.0;
    std::vector<std::string> problems;  // ours: validity and consistency failures
};

void add_pair(Section& section, Name a, Name b) {
    Line line{a, b};
    std::sort(line.begin(), line.end());
    ++section[line];
}

// Our side: every edge INSIDE the domain that is not a separator and has
// positive length, decided exactly by the harness from the sites of its two
// vertices (the library's zero length is in the topology text only): with
// p, q the edge's sites, r the third site at one end and s at the other,
// the faces are (p, q, r) and (q, p, s) counter-clockwise, as CGAL's. The
// medial axis (segvoronoi_diagram_medial_axis) must hold exactly these
// edges, zero-length ones included, each once.
AxisResult axis_ours(const std::vector<std::vector<Point>>& rings, const Sites& sites) {
    AxisResult ours;
    std::vector<double> xy;
    std::vector<std::size_t> lengths;
    for (const std::vector<Point>& ring : rings) {
        for (const Point& p : ring) xy.insert(xy.end(), {p.x, p.y});
        lengths.push_back(ring.size());
    }
    segvoronoi_builder* builder = segvoronoi_builder_new();
    if (builder == nullptr) throw LibraryError("segvoronoi_builder_new returned NULL");
    segvoronoi_diagram* diagram = nullptr;
    segvoronoi_medial_axis* axis = nullptr;
    try {
        const auto start = std::chrono::steady_clock::now();
        check_status(segvoronoi_builder_add_polygon(builder, xy.data(), lengths.data(), lengths.size()),
                     "segvoronoi_builder_add_polygon", builder);
        check_status(segvoronoi_builder_build(builder, &diagram), "segvoronoi_builder_build", builder);
        ours.build_ms = elapsed_ms(start);
        if (segvoronoi_diagram_validate(diagram) != SEGVORONOI_STATUS_OK) {
            ours.problems.push_back("segvoronoi_diagram_validate failed");
        }
        const std::size_t site_count = segvoronoi_diagram_site_count(diagram);
        std::vector<Name> names;
        std::vector<Gt::Site_2> cgal_sites;
        for (std::size_t k = 0; k < site_count; ++k) {
            segvoronoi_site site{};
            site.struct_size = sizeof site;
            check_status(segvoronoi_diagram_site(diagram, k, &site), "segvoronoi_diagram_site");
            const K::Point_2 a(site.x, site.y), b(site.x2, site.y2);
            if (site.kind == SEGVORONOI_SITE_POINT) {
                names.push_back({0, sites.index(site.x, site.y)});
                cgal_sites.push_back(Gt::Site_2::construct_site_2(a));
            } else {
                names.push_back({1, sites.segment({site.x, site.y}, {site.x2, site.y2})});
                cgal_sites.push_back(Gt::Site_2::construct_site_2(a, b));
            }
        }
        const std::size_t edge_count = segvoronoi_diagram_edge_count(diagram);
        std::vector<bool> in_axis(edge_count, false);
        auto vertex = [&](std::uint32_t id) {
            segvoronoi_vertex v{};
            v.struct_size = sizeof v;
            check_status(segvoronoi_diagram_vertex(diagram, id, &v), "segvoronoi_diagram_vertex");
            return v;
        };
        // The site after `first, second` counter-clockwise around `v`, if
        // they follow each other there.
        auto third = [](const segvoronoi_vertex& v, std::uint32_t first, std::uint32_t second, std::uint32_t& out) {
            for (int i = 0; i < 3; ++i) {
                if (v.sites[i] == first && v.sites[(i + 1) % 3] == second) {
                    out = v.sites[(i + 2) % 3];
                    return true;
                }
            }
            return false;
        };
        for (std::size_t e = 0; e < edge_count; ++e) {
            segvoronoi_edge edge{};
            edge.struct_size = sizeof edge;
            check_status(segvoronoi_diagram_edge(diagram, e, &edge), "segvoronoi_diagram_edge");
            std::uint32_t location = 0;
            check_status(segvoronoi_diagram_edge_location(diagram, e, &location), "segvoronoi_diagram_edge_location");
            if (edge.is_separator) continue;
            in_axis[e] = location == SEGVORONOI_LOCATION_INSIDE;
            if (edge.is_infinite) {
                if (in_axis[e]) ours.problems.push_back("edge " + std::to_string(e) + " is inside and reaches infinity");
                ++ours.outside;
                continue;
            }
            const segvoronoi_vertex start_vertex = vertex(edge.ends[0].vertex), end_vertex = vertex(edge.ends[1].vertex);
            std::uint32_t p = edge.sites[0], q = edge.sites[1], r = 0, s = 0;
            if (!third(end_vertex, p, q, r)) std::swap(p, q);
            if (!third(end_vertex, p, q, r) || !third(start_vertex, q, p, s)) {
                ours.problems.push_back("edge " + std::to_string(e) + ": its sites are not those of its vertices");
                continue;
            }
            // two vertices of the same three sites are two circles: apart
            if (r != s && is_zero_length_sites(cgal_sites[p], cgal_sites[q], cgal_sites[r], cgal_sites[s])) {
                ++ours.zero_length;
            } else if (in_axis[e]) {
                add_pair(ours.pairs, names[p], names[q]);
            } else {
                ++ours.outside;
            }
        }
        check_status(segvoronoi_diagram_medial_axis(diagram, &axis), "segvoronoi_diagram_medial_axis");
        std::vector<std::size_t> seen(edge_count, 0);
        for (std::size_t c = 0; c < segvoronoi_medial_axis_chain_count(axis); ++c) {
            std::size_t pieces = 0;
            bool closed = false;
            check_status(segvoronoi_medial_axis_chain(axis, c, &pieces, &closed), "segvoronoi_medial_axis_chain");
            for (std::size_t k = 0; k < pieces; ++k) {
                segvoronoi_piece piece{};
                piece.struct_size = sizeof piece;
                check_status(segvoronoi_medial_axis_piece(axis, c, k, &piece), "segvoronoi_medial_axis_piece");
                if (piece.edge < edge_count) ++seen[piece.edge];
            }
        }
        for (std::size_t e = 0; e < edge_count; ++e) {
            if (seen[e] != (in_axis[e] ? 1u : 0u)) {
                ours.problems.push_back("the medial axis has edge " + std::to_string(e) + " " + std::to_string(seen[e]) +
                                        " times, expected " + (in_axis[e] ? "once" : "never"));
                break;
            }
        }
    } catch (...) {
        segvoronoi_medial_axis_free(axis);
        segvoronoi_diagram_free(diagram);
        segvoronoi_builder_free(builder);
        throw;
    }
    segvoronoi_medial_axis_free(axis);
    segvoronoi_diagram_free(diagram);
    segvoronoi_builder_free(builder);
    return ours;
}

// A point strictly inside the Voronoi edge from v1 to v2 (both finite)
// between the sites a and b, in double: the middle of the two vertices for
// a straight edge (two points, two segments), and for a parabolic one (a
// point and a segment not its endpoint) the point of the parabola above
// the middle of the vertices' feet on the segment's line. A positive-length
// Voronoi edge meets no input segment in its interior, so one such point
// says on which side of the rings all of it is; it errs only if its
// rounding moves it across a segment, by more than its clearance.
K::Point_2 edge_middle(const Gt::Site_2& a, const Gt::Site_2& b, const K::Point_2& v1, const K::Point_2& v2) {
    const bool parabola = a.is_point() != b.is_point();
    if (!parabola) return K::Point_2(v1.x() / 2.0 + v2.x() / 2.0, v1.y() / 2.0 + v2.y() / 2.0);
    const K::Point_2 focus = a.is_point() ? a.point() : b.point();
    const K::Segment_2 seg = a.is_point() ? b.segment() : a.segment();
    const double ax = seg.source().x(), ay = seg.source().y();
    double ux = seg.target().x() - ax, uy = seg.target().y() - ay;
    const double length = std::hypot(ux, uy);
    ux /= length;
    uy /= length;
    const double t1 = (v1.x() - ax) * ux + (v1.y() - ay) * uy, t2 = (v2.x() - ax) * ux + (v2.y() - ay) * uy;
    const double t = (t1 + t2) / 2.0;
    const double fx = ax + t * ux, fy = ay + t * uy;
    // the unit normal toward the focus
    double nx = -uy, ny = ux;
    if ((focus.x() - fx) * nx + (focus.y() - fy) * ny < 0.0) nx = -nx, ny = -ny;
    // |f + h n - focus| = h
    const double dx = focus.x() - fx, dy = focus.y() - fy;
    const double h = (dx * dx + dy * dy) / (2.0 * (dx * nx + dy * ny));
    return K::Point_2(fx + h * nx, fy + h * ny);
}

// The Voronoi vertex of the finite face f, to within 1e-9 of the extent:
// CGAL's construction in interval arithmetic where its box is that small,
// else the exact one (as in same_vertex) rounded; throws where neither can. (CGAL's double
// construction, sdg.primal, is ill-conditioned next to a joint an ulp from
// straight: its vertices there were off by far more than their clearance,
// or not finite, and put edges' middles on the wrong side of the rings.)
K::Point_2 face_vertex(const Sdg::Face_handle& f, double extent) {
    const Gt::Site_2 &a = f->vertex(0)->site(), &b = f->vertex(1)->site(), &c = f->vertex(2)->site();
    {
        CGAL::Protect_FPU_rounding<true> upward;
        try {
            const Ki::Point_2 box = construct_vertex<Gti>(a, b, c);
            const double tolerance = 1e-9 * extent;
            if (box.x().sup() - box.x().inf() <= tolerance && box.y().sup() - box.y().inf() <= tolerance) {
                return K::Point_2(CGAL::to_double(box.x()), CGAL::to_double(box.y()));
            }
        } catch (const CGAL::Uncertain_conversion_exception&) {
            // undecided in intervals: exactly below
        }
    }
    // (not sdg.primal as the last resort: on faces at joints an ulp from
    // straight its exact stage divides by zero in GMP, a SIGFPE)
    const std::pair<double, double> range = coordinate_range({&a, &b, &c});
    if (range.first > 0.0 && std::ilogb(range.first) - std::ilogb(range.second) > 400) {
        throw std::runtime_error("a Voronoi vertex whose coordinates spread over more than 2^400 (not constructed)");
    }
    const int k = range.first > 0.0 ? -std::ilogb(range.first) : 0;
    CORE::get_static_AbortFlag() = false;
    CORE::get_static_InvalidFlag() = 0;
    const Kx::Point_2 exact = exact_vertex(a, b, c, k);
    if (CORE::get_static_InvalidFlag() != 0) {
        throw std::runtime_error("a Voronoi vertex that CGAL's exact construction cannot make (CORE invalid)");
    }
    return K::Point_2(std::ldexp(CGAL::to_double(exact.x()), -k), std::ldexp(CGAL::to_double(exact.y()), -k));
}

// CGAL's side: every finite Delaunay edge that is not a separator (a
// segment and one of its own endpoints); its dual is a ray (next to an
// infinite face: unbounded, so outside the bounded domain), of length zero
// (is_zero_length_edge: left out), or a finite edge inside or outside as
// the point edge_middle says by the exact even-odd rule.
AxisResult axis_cgal(const std::vector<std::vector<Point>>& rings, const Sites& sites, const Input& input) {
    AxisResult cgal;
    Sdg sdg;
    CgalResult built;
    build_cgal_graph(sites, input, sdg, built);
    cgal.build_ms = built.build_ms;
    if (sdg.dimension() < 2) throw std::runtime_error("the rings are collinear");
    const double extent = sites.extent();
    auto is_separator = [](const Gt::Site_2& a, const Gt::Site_2& b) {
        if (a.is_point() == b.is_point()) return false;
        const K::Point_2 p = a.is_point() ? a.point() : b.point();
        const K::Segment_2 seg = a.is_point() ? b.segment() : a.segment();
        return p == seg.source() || p == seg.target();
    };
    for (auto e = sdg.finite_edges_begin(); e != sdg.finite_edges_end(); ++e) {
        const auto ends = edge_vertices(*e);
        const Gt::Site_2 &a = ends.first->site(), &b = ends.second->site();
        if (is_separator(a, b)) continue;
        const Sdg::Face_handle f = e->first, g = f->neighbor(e->second);
        if (sdg.is_infinite(f) || sdg.is_infinite(g)) {
            ++cgal.outside;
            continue;
        }
        if (is_zero_length_edge(sdg, *e)) {
            ++cgal.zero_length;
            continue;
        }
        const K::Point_2 middle = edge_middle(a, b, face_vertex(f, extent), face_vertex(g, extent));
        if (!std::isfinite(middle.x()) || !std::isfinite(middle.y())) {
            throw std::runtime_error("a Voronoi edge whose middle CGAL's double construction cannot place");
        }
        // its distance to site a is the clearance there (it is on a's cell)
        const double clearance = a.is_point() ? std::hypot(middle.x() - a.point().x(), middle.y() - a.point().y())
                                              : std::sqrt(CGAL::to_double(CGAL::squared_distance(middle, a.segment())));
        if (!(clearance > 1e-12 * extent)) ++cgal.close_middles;
        if (!even_odd_inside(rings, middle.x(), middle.y())) {
            ++cgal.outside;
            continue;
        }
        add_pair(cgal.pairs, site_name(ends.first, sites), site_name(ends.second, sites));
    }
    return cgal;
}

// --polygon FILE [--family NAME]: the medial axis of the rings in FILE,
// ours against CGAL's. Exit status as --file.
int polygon_main(int argc, char** argv) {
    if (argc < 3) return usage();
    std::string family = "file";
    for (int k = 3; k < argc; ++k) {
        if (std::string(argv[k]) == "--family" && k + 1 < argc) {
            family = argv[++k];
        } else {
            return usage();
        }
    }
    std::vector<std::vector<Point>> rings;
    std::string error;
    if (!read_rings(argv[2], rings, error)) {
        std::fprintf(stderr, "segvoronoi_cgal_check: %s: %s\n", argv[2], error.c_str());
        return 2;
    }
    Input input;
    input.family = family;
    for (const std::vector<Point>& ring : rings) {
        for (std::size_t k = 0; k < ring.size(); ++k) input.segments.push_back({ring[k], ring[(k + 1) % ring.size()]});
    }
    const Sites sites(input);
    std::signal(SIGFPE, report_sigfpe);
    g_current_input = &input;
    clear_exact_vertices();
    AxisResult ours, cgal;
    try {
        ours = axis_ours(rings, sites);
    } catch (const std::exception& e) {
        std::printf("family=%s mode=polygon segments=%zu verdict=ERROR segvoronoi: %s\n", family.c_str(),
                    input.segments.size(), e.what());
        return 3;
    }
    try {
        cgal = axis_cgal(rings, sites, input);
    } catch (const std::exception& e) {
        std::printf("family=%s mode=polygon segments=%zu verdict=ERROR cgal: %s\n", family.c_str(),
                    input.segments.size(), e.what());
        return 3;
    }
    const SectionDiff diff = compare_section(ours.pairs, cgal.pairs);
    std::size_t ours_count = 0, cgal_count = 0;
    for (const auto& entry : ours.pairs) ours_count += entry.second;
    for (const auto& entry : cgal.pairs) cgal_count += entry.second;
    const bool agree = diff.only_ours == 0 && diff.only_cgal == 0, valid = ours.problems.empty();
    std::printf("family=%s mode=polygon rings=%zu segments=%zu ours_axis=%zu cgal_axis=%zu matched=%zu only_ours=%zu "
                "only_cgal=%zu ours_zero_length=%zu cgal_zero_length=%zu ours_outside=%zu cgal_outside=%zu "
                "close_middles=%zu exact_vertex_pairs=%zu exact_fallback=%zu ours_build_ms=%.1f cgal_build_ms=%.1f valid=%s verdict=%s\n",
                family.c_str(), rings.size(), input.segments.size(), ours_count, cgal_count, diff.matched,
                diff.only_ours, diff.only_cgal, ours.zero_length, cgal.zero_length, ours.outside, cgal.outside,
                cgal.close_middles, g_exact_vertex_pairs, g_exact_vertex_invalid, ours.build_ms, cgal.build_ms, valid ? "yes" : "no", agree && valid ? "AGREE" : "DIFFER");
    for (const auto& example : diff.examples) {
        std::printf("    %s AXIS: %s\n", example.first.c_str(), format_line(example.second).c_str());
    }
    for (const std::string& problem : ours.problems) std::printf("  invalid: %s\n", problem.c_str());
    if (ours.zero_length != cgal.zero_length || ours.outside != cgal.outside) {
        std::printf("  note: the counts of zero-length or outside edges differ\n");
    }
    if (!agree && cgal.close_middles > 0) {
        std::printf("  note: %zu of CGAL's edges were located at a point within rounding of a ring segment\n",
                    cgal.close_middles);
    }
    return agree && valid ? 0 : 1;
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
    write_boost_text(stdout, smallest);
    std::printf("%s", run_one(smallest).text.c_str());
    return 1;
}

// --search SECONDS [seed] [--generic] [--no-subnormal] [--out DIR] [--testgen PATH] and --minimise; returns
// -1 when argv is neither.
int search_main(int argc, char** argv) {
    if (argc >= 2 && std::string(argv[1]) == "--minimise") return minimise_file(argc, argv);
    if (argc < 2 || std::string(argv[1]) != "--search") return -1;
    std::string out_dir, testgen = SEGVORONOI_TESTGEN_PATH;
    bool generic_only = false, no_subnormal = false;
    std::vector<std::string> numbers;
    for (int k = 2; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--out" && k + 1 < argc) {
            out_dir = argv[++k];
        } else if (arg == "--testgen" && k + 1 < argc) {
            testgen = argv[++k];
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
        seed = std::mt19937_64(std::chrono::system_clock::now().time_since_epoch().count())();
    }
    return search(static_cast<double>(seconds), seed, generic_only, no_subnormal, out_dir, testgen);
}

int main(int argc, char** argv) {
    if (argc >= 2 && std::string(argv[1]) == "--polygon") return polygon_main(argc, argv);
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
