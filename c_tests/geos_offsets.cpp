// segvoronoi_geos_offsets: offsets of polygons with holes (issue 10) checked
// against two independent implementations, GEOS's buffer with round joins
// (its reentrant C API) and, when built with SEGVORONOI_HAVE_CLIPPER,
// Clipper's ClipperOffset (jtRound, etClosedPolygon).
//
//   segvoronoi_geos_offsets [--glyphs DIR] [--cut straight|nudged] [--verbose] [--dump NAME D]
//
// Inputs, generated here from fixed seeds (nobody tuned them): random
// star-shaped polygons (random radii around a centre; some convex, some
// very non-convex) with 0..5 random star-shaped holes placed so that they
// touch neither each other nor the outer ring; regular n-gons; a disk-like
// 4096-gon; and, with --glyphs DIR, the glyph outlines DIR/glyph_{B,8,g}.rings
// and the country and island outlines DIR/dcw_*.rings, gshhg_islands_*.rings (km)
// (the rings format: "rings R", then per ring its point count K and K lines
// "x y"; '#' starts a comment; the region is the even-odd one). Each at
// fixed fractions of its size, negative (shrinking, up to beyond the
// inscribed radius, where parts or all of it vanish) and positive. With
// --cut, every edge of every input is cut at points exactly on it
// (straight vertices), or nudged one ulp off (see cut_edges).
//
// For each input and distance d: the tolerance t is 1e-4 of the input's
// bounding-box diagonal; GEOS gets quadsegs = the smallest q with
// t2 = |d| (1 - cos(pi / (4 q))) <= t, and ours is sampled at t1 = t2, so the
// vertex counts compare at one tolerance (Clipper's ArcTolerance is t1 too).
// Ours is the region of the loops: one polygon per loop that is not a hole,
// with the holes whose parent it is. Checked:
//   - our polylines form a valid GEOS geometry (GEOSisValid_r), each hole's
//     parent is a loop that is not a hole, and a loop is a hole exactly when
//     its signed area is negative;
//   - area(symdiff(ours, GEOS)) < 2 (t1 + t2) (perimeter ours + perimeter
//     GEOS) =: bound, and |our exact area (segvoronoi_offset_area) - GEOS's
//     area| < bound (the chords of both lie inside the arcs, within their
//     tolerances, so the two regions differ by a band of about t1 + t2 along
//     the boundary);
//   - our number of loops equals GEOS's number of rings; or they are equal
//     once the thin rings (area < (t1 + t2) perimeter) are left out of both
//     (counts_thin); or ours has GEOS's number somewhere within
//     d +- 2 (t1 + t2) (counts_within_band). Loops that touch, pinch or
//     vanish within the tolerances of d may do so on either side of d in an
//     approximation. Where they differ otherwise, GEOS's rings are tested
//     by brute force (a point inside each polygon and each hole, against
//     its distance to the input); a ring that is on the wrong side by more
//     than 2 (t1 + t2), with Clipper agreeing with ours, is GEOS's error
//     (printed "GEOS WRONG:", counted as geos_wrong; GEOS 3.11 makes such
//     rings from offset curves that invert, JTS #472 / GEOS ticket 1101,
//     fixed by a heuristic that does not catch every case);
//   - the same against Clipper, with t3 = 2.25 t1 for its tolerance (it
//     rounds the number of chords of a join), coordinates scaled to
//     integers up to 2^28 (where its arithmetic stays in 64 bits); left out
//     for the 4096-gon shrunk by more than 0.9 of its radius, where it is
//     quadratic.
// And segvoronoi_diagram_offsets at all distances of an input at once gives
// the same loop counts and areas as segvoronoi_diagram_offset at each.
// Known library failures are named cases in main, skipped with a "KNOWN:"
// line (none at present). Prints one line per failure and a summary
// "geos_offsets: cases=..." (vertex counts of the three at the same
// tolerance, seconds spent in each); exit status 0 when every case agrees,
// 1 otherwise, 2 bad usage or input. --verbose prints every case; --dump
// NAME D prints the input NAME (rings format) and the loops, pieces and
// rings of ours, GEOS and Clipper at D (D need not be one of its distances).

#include <segvoronoi.h>

#include <geos_c.h>
#ifdef SEGVORONOI_HAVE_CLIPPER
#include <polyclipping/clipper.hpp>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Point = std::array<double, 2>;
using Ring = std::vector<Point>;
const double pi = 3.14159265358979323846;

struct Input {
  std::string name;
  std::vector<Ring> rings;     // even-odd region
  std::vector<double> distances;
  // Clipper is left out below this distance (see disk4096).
  double clipper_from = -INFINITY;
};

// A known library failure: skipped, printed with "KNOWN:".
struct Known {
  std::string name;
  std::vector<Ring> rings;
  double distance;
  std::string what;
};

// splitmix64: the same numbers with every compiler and standard library.
struct Rng {
  uint64_t s;
  explicit Rng(uint64_t seed) : s(seed) {}
  uint64_t next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * ((next() >> 11) * 0x1.0p-53); }
  int range(int lo, int hi) { return lo + int(next() % uint64_t(hi - lo + 1)); }
};

double ring_signed_area(const Ring &r) {
  double a = 0;
  for (size_t i = 0, n = r.size(); i < n; ++i) {
    const Point &p = r[i], &q = r[(i + 1) % n];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return a / 2;
}

double point_segment_distance(const Point &p, const Point &a, const Point &b) {
  double dx = b[0] - a[0], dy = b[1] - a[1];
  double t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy);
  t = std::max(0.0, std::min(1.0, t));
  return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

double point_ring_distance(const Point &p, const Ring &r) {
  double best = INFINITY;
  for (size_t i = 0; i < r.size(); ++i) best = std::min(best, point_segment_distance(p, r[i], r[(i + 1) % r.size()]));
  return best;
}

bool point_in_ring(const Point &p, const Ring &r) {
  bool in = false;
  for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
    if ((r[i][1] > p[1]) != (r[j][1] > p[1]) &&
        p[0] < (r[j][0] - r[i][0]) * (p[1] - r[i][1]) / (r[j][1] - r[i][1]) + r[i][0])
      in = !in;
  }
  return in;
}

// A star-shaped polygon around (cx, cy): n corners at jittered angles, radii
// uniform in [rmin, rmax] (rmin = rmax: convex, inscribed in a circle).
Ring star(Rng &rng, double cx, double cy, double rmin, double rmax, int n, bool clockwise) {
  Ring r;
  for (int k = 0; k < n; ++k) {
    double a = 2 * pi * (k + rng.uniform(-0.3, 0.3)) / n;
    double rad = rng.uniform(rmin, rmax);
    r.push_back({cx + rad * std::cos(a), cy + rad * std::sin(a)});
  }
  if (clockwise) std::reverse(r.begin(), r.end());
  return r;
}

// Outer star of radius up to 100 with 8..max_corners corners and up to
// `holes` star holes (3..40 corners), each of
// radius at most 0.35 of its gap to the outer ring and to the other holes.
Input star_with_holes(uint64_t seed, bool convex, double rmin_frac, int holes, int max_corners) {
  Rng rng(seed);
  Input in;
  int n = rng.range(8, max_corners);
  in.rings.push_back(star(rng, 0, 0, convex ? 100 : 100 * rmin_frac, 100, n, false));
  struct Disk { Point c; double r; };
  std::vector<Disk> placed;
  for (int tries = 0; int(placed.size()) < holes && tries < 2000; ++tries) {
    Point c = {rng.uniform(-90, 90), rng.uniform(-90, 90)};
    if (!point_in_ring(c, in.rings[0])) continue;
    double room = point_ring_distance(c, in.rings[0]);
    for (const Disk &d : placed) room = std::min(room, std::hypot(c[0] - d.c[0], c[1] - d.c[1]) - d.r);
    if (room < 4) continue;
    double r = rng.uniform(0.3, 0.7) * room;
    placed.push_back({c, r});
    bool hole_convex = rng.range(0, 2) == 0;
    in.rings.push_back(star(rng, c[0], c[1], hole_convex ? r : r * rng.uniform(0.2, 0.7), r, rng.range(3, 40), true));
  }
  char name[96];
  std::snprintf(name, sizeof name, "star%s-%d-holes%zu-seed%llu", convex ? "-convex" : "", n, placed.size(),
                (unsigned long long)seed);
  in.name = name;
  // inscribed radius of the outer ring is below 100; the last ones vanish.
  in.distances = {-0.5, -2, -5, -12, -25, -50, -110, 0.5, 3, 10, 40, 150};
  return in;
}

Input regular(int n) {
  Input in;
  Ring r;
  for (int k = 0; k < n; ++k) r.push_back({std::cos(2 * pi * k / n), std::sin(2 * pi * k / n)});
  in.rings.push_back(r);
  in.name = "regular-" + std::to_string(n) + "-gon";
  double inscribed = std::cos(pi / n);
  in.distances = {-0.05 * inscribed, -0.5 * inscribed, -0.95 * inscribed, -1.5 * inscribed, 0.1, 1, 5};
  return in;
}

Input disk4096() {
  Input in;
  Ring r;
  const int n = 4096;
  for (int k = 0; k < n; ++k) r.push_back({1000 * std::cos(2 * pi * k / n), 1000 * std::sin(2 * pi * k / n)});
  in.rings.push_back(r);
  in.name = "disk-4096-gon";
  in.distances = {-1, -10, -100, -500, -900, -999, -1001, 1, 100, 1000};
  // Clipper's offset is quadratic when thousands of edges collapse: 5 s at
  // -999, 47 s at -1001.
  in.clipper_from = -900;
  return in;
}

bool read_rings(const std::string &path, std::vector<Ring> &rings) {
  std::ifstream f(path);
  if (!f) return false;
  std::string line, word;
  std::vector<double> numbers;
  while (std::getline(f, line)) {
    if (!line.empty() && line[0] == '#') continue;
    std::istringstream s(line);
    while (s >> word) {
      if (word == "rings") continue;
      numbers.push_back(std::strtod(word.c_str(), nullptr));
    }
  }
  size_t i = 0;
  if (numbers.empty()) return false;
  size_t count = size_t(numbers[i++]);
  for (size_t r = 0; r < count; ++r) {
    if (i >= numbers.size()) return false;
    size_t k = size_t(numbers[i++]);
    Ring ring;
    for (size_t p = 0; p < k; ++p, i += 2) {
      if (i + 1 >= numbers.size()) return false;
      ring.push_back({numbers[i], numbers[i + 1]});
    }
    if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    rings.push_back(ring);
  }
  return true;
}

// The rings of the even-odd region's boundary: country outlines share
// borders edge for edge (the polygons of a MultiPolygon, an enclave given
// as a polygon and as a hole), and two copies of an edge cancel by the
// even-odd rule, which segvoronoi does (issue 27). GEOS and the brute force
// need the region's own boundary: the edges that occur an odd number of
// times, walked into simple rings (at a point where more than two meet,
// they are paired in angular order, so that the rings touch without
// crossing; a walk that comes back to a point is cut there). Rings that
// share no edge come back as they are.
std::vector<Ring> even_odd_boundary(const std::vector<Ring> &rings) {
  using Edge = std::array<Point, 2>;
  std::map<Edge, int> count;
  for (const Ring &r : rings)
    for (size_t k = 0; k < r.size(); ++k) {
      Edge e{r[k], r[(k + 1) % r.size()]};
      if (e[1] < e[0]) std::swap(e[0], e[1]);
      ++count[e];
    }
  bool shared = false;
  for (const auto &c : count) shared = shared || c.second > 1;
  if (!shared) return rings;
  std::vector<Edge> edges;
  for (const auto &c : count)
    if (c.second % 2 == 1) edges.push_back(c.first);
  // per point, its edges in angular order, paired (0, 1), (2, 3), ...
  std::map<Point, std::vector<size_t>> at;
  for (size_t i = 0; i < edges.size(); ++i) {
    at[edges[i][0]].push_back(i);
    at[edges[i][1]].push_back(i);
  }
  std::map<std::pair<Point, size_t>, size_t> partner;
  for (auto &[p, list] : at) {
    auto angle = [&, q = p](size_t i) {
      const Point &o = edges[i][0] == q ? edges[i][1] : edges[i][0];
      return std::atan2(o[1] - q[1], o[0] - q[0]);
    };
    std::sort(list.begin(), list.end(), [&](size_t a, size_t b) { return angle(a) < angle(b); });
    for (size_t k = 0; k + 1 < list.size(); k += 2) {
      partner[{p, list[k]}] = list[k + 1];
      partner[{p, list[k + 1]}] = list[k];
    }
  }
  std::vector<Ring> out;
  std::vector<bool> used(edges.size(), false);
  for (size_t start = 0; start < edges.size(); ++start) {
    if (used[start]) continue;
    Ring walk;
    size_t e = start;
    Point from = edges[start][0];
    while (!used[e]) {
      used[e] = true;
      walk.push_back(from);
      Point to = edges[e][0] == from ? edges[e][1] : edges[e][0];
      auto next = partner.find({to, e});
      if (next == partner.end()) break;
      from = to;
      e = next->second;
    }
    // cut where the walk comes back to a point
    Ring stack;
    std::map<Point, size_t> seen;
    for (const Point &p : walk) {
      auto s = seen.find(p);
      if (s != seen.end()) {
        Ring loop(stack.begin() + long(s->second), stack.end());
        for (const Point &q : loop) seen.erase(q);
        stack.resize(s->second);
        if (loop.size() >= 3) out.push_back(loop);
      }
      seen[p] = stack.size();
      stack.push_back(p);
    }
    if (stack.size() >= 3) out.push_back(stack);
  }
  return out;
}

// ---- GEOS -------------------------------------------------------------------

GEOSContextHandle_t ctx;

void geos_message(const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  std::fprintf(stderr, "GEOS: ");
  std::vfprintf(stderr, fmt, ap);
  std::fprintf(stderr, "\n");
  va_end(ap);
}

GEOSGeometry *linear_ring(const Ring &r) {
  GEOSCoordSequence *s = GEOSCoordSeq_create_r(ctx, unsigned(r.size() + 1), 2);
  for (size_t i = 0; i <= r.size(); ++i) {
    const Point &p = r[i % r.size()];
    GEOSCoordSeq_setXY_r(ctx, s, unsigned(i), p[0], p[1]);
  }
  return GEOSGeom_createLinearRing_r(ctx, s);
}

// Polygons from shells, each with its holes.
struct Shell {
  Ring shell;
  std::vector<Ring> holes;
};

GEOSGeometry *multipolygon(const std::vector<Shell> &shells) {
  std::vector<GEOSGeometry *> polys;
  for (const Shell &s : shells) {
    std::vector<GEOSGeometry *> holes;
    for (const Ring &h : s.holes) holes.push_back(linear_ring(h));
    polys.push_back(GEOSGeom_createPolygon_r(ctx, linear_ring(s.shell), holes.data(), unsigned(holes.size())));
  }
  return GEOSGeom_createCollection_r(ctx, GEOS_MULTIPOLYGON, polys.data(), unsigned(polys.size()));
}

// The even-odd region of rings as shells with holes (by nesting depth).
std::vector<Shell> even_odd_shells(const std::vector<Ring> &rings) {
  size_t n = rings.size();
  std::vector<int> depth(n, 0);
  std::vector<long> parent(n, -1);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = 0; j < n; ++j)
      if (i != j && point_in_ring(rings[i][0], rings[j])) {
        ++depth[i];
        if (parent[i] < 0 || std::fabs(ring_signed_area(rings[j])) < std::fabs(ring_signed_area(rings[parent[i]])))
          parent[i] = long(j);
      }
  std::vector<Shell> shells;
  std::vector<long> shell_of(n, -1);
  for (size_t i = 0; i < n; ++i)
    if (depth[i] % 2 == 0) {
      shell_of[i] = long(shells.size());
      shells.push_back({rings[i], {}});
    }
  for (size_t i = 0; i < n; ++i)
    if (depth[i] % 2 == 1) shells[size_t(shell_of[size_t(parent[i])])].holes.push_back(rings[i]);
  return shells;
}

size_t geos_ring_count(const GEOSGeometry *g) {
  size_t count = 0;
  for (int i = 0, n = GEOSGetNumGeometries_r(ctx, g); i < n; ++i) {
    const GEOSGeometry *p = GEOSGetGeometryN_r(ctx, g, i);
    if (GEOSGeomTypeId_r(ctx, p) != GEOS_POLYGON || GEOSisEmpty_r(ctx, p)) continue;
    count += 1 + size_t(GEOSGetNumInteriorRings_r(ctx, p));
  }
  return count;
}

double geos_area(const GEOSGeometry *g) {
  double a = 0;
  GEOSArea_r(ctx, g, &a);
  return a;
}

double geos_length(const GEOSGeometry *g) {
  double l = 0;
  GEOSLength_r(ctx, g, &l);
  return l;
}

size_t geos_vertices(const GEOSGeometry *g) {
  // GEOS repeats each ring's first point at its end; count distinct corners.
  return size_t(GEOSGetNumCoordinates_r(ctx, g)) - geos_ring_count(g);
}

double symdiff_area(const GEOSGeometry *a, const GEOSGeometry *b) {
  GEOSGeometry *d = GEOSSymDifference_r(ctx, a, b);
  if (!d) return INFINITY;
  double area = geos_area(d);
  GEOSGeom_destroy_r(ctx, d);
  return area;
}

// ---- ours -------------------------------------------------------------------

bool verbose = false;
bool dump_pieces = false;

struct Ours {
  bool ok = true;
  std::string error;
  double exact_area = 0;
  size_t loops = 0;
  size_t vertices = 0;
  std::vector<Shell> shells;
};

Ours our_offset(const segvoronoi_diagram *diagram, double d, double tolerance, double &seconds) {
  Ours out;
  segvoronoi_offset *off = nullptr;
  auto t0 = std::chrono::steady_clock::now();
  segvoronoi_status st = segvoronoi_diagram_offset(diagram, d, &off);
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (st != SEGVORONOI_STATUS_OK) {
    out.ok = false;
    out.error = std::string("segvoronoi_diagram_offset: ") + segvoronoi_status_str(st);
    return out;
  }
  out.exact_area = segvoronoi_offset_area(off);
  out.loops = segvoronoi_offset_loop_count(off);
  std::vector<segvoronoi_loop> loops(out.loops);
  std::vector<Ring> polylines(out.loops);
  std::vector<long> shell_of(out.loops, -1);
  for (size_t l = 0; l < out.loops && out.ok; ++l) {
    loops[l].struct_size = sizeof loops[l];
    size_t n = 0, got = 0;
    if (segvoronoi_offset_loop(off, l, &loops[l]) != SEGVORONOI_STATUS_OK ||
        segvoronoi_offset_loop_polyline(off, l, tolerance, nullptr, 0, &n) != SEGVORONOI_STATUS_OK) {
      out.ok = false;
      out.error = "loop or polyline query failed";
      break;
    }
    std::vector<double> xy(2 * n);
    if (segvoronoi_offset_loop_polyline(off, l, tolerance, xy.data(), n, &got) != SEGVORONOI_STATUS_OK || got != n) {
      out.ok = false;
      out.error = "polyline query failed";
      break;
    }
    for (size_t p = 0; p < n; ++p) polylines[l].push_back({xy[2 * p], xy[2 * p + 1]});
    if (dump_pieces) {
      std::printf("  ours loop %zu: %zu pieces, parent %u, hole %d, signed area %.12g\n", l, loops[l].piece_count,
                  loops[l].parent, int(loops[l].hole), loops[l].signed_area);
      for (size_t p = 0; p < loops[l].piece_count; ++p) {
        segvoronoi_loop_piece piece{};
        piece.struct_size = sizeof piece;
        segvoronoi_offset_piece(off, l, p, &piece);
        std::printf("    %s site %u (%.17g, %.17g) -> (%.17g, %.17g)", piece.kind == SEGVORONOI_OFFSET_ARC ? "arc " : "line",
                    piece.site, piece.from[0], piece.from[1], piece.to[0], piece.to[1]);
        if (piece.kind == SEGVORONOI_OFFSET_ARC)
          std::printf(" centre (%.17g, %.17g) r %.17g %s", piece.centre[0], piece.centre[1], piece.radius,
                      piece.counter_clockwise ? "ccw" : "cw");
        std::printf("\n");
      }
    }
    out.vertices += n;
    if (n < 3) {
      out.ok = false;
      out.error = "loop " + std::to_string(l) + " has a polyline of " + std::to_string(n) + " points";
    }
    if (loops[l].hole != (loops[l].signed_area < 0)) {
      out.ok = false;
      out.error = "loop " + std::to_string(l) + ": hole flag and signed area disagree";
    }
  }
  for (size_t l = 0; l < out.loops && out.ok; ++l)
    if (!loops[l].hole) {
      shell_of[l] = long(out.shells.size());
      out.shells.push_back({polylines[l], {}});
    }
  for (size_t l = 0; l < out.loops && out.ok; ++l)
    if (loops[l].hole) {
      uint32_t p = loops[l].parent;
      if (p == SEGVORONOI_NO_PARENT || p >= l || shell_of[p] < 0) {
        out.ok = false;
        out.error = "hole loop " + std::to_string(l) + " has parent " + std::to_string(p) + ", not a loop before it that is no hole";
        break;
      }
      out.shells[size_t(shell_of[p])].holes.push_back(polylines[l]);
    }
  segvoronoi_offset_free(off);
  return out;
}

double ring_length(const Ring &r) {
  double l = 0;
  for (size_t i = 0; i < r.size(); ++i) l += std::hypot(r[(i + 1) % r.size()][0] - r[i][0], r[(i + 1) % r.size()][1] - r[i][1]);
  return l;
}

// The rings that are not thin: area at least `width` times the perimeter
// (a disk of radius 2 width is thin).
size_t thick_rings(const std::vector<Shell> &shells, double width) {
  size_t n = 0;
  auto thick = [&](const Ring &r) { return std::fabs(ring_signed_area(r)) >= width * ring_length(r); };
  for (const Shell &s : shells) {
    n += thick(s.shell);
    for (const Ring &h : s.holes) n += thick(h);
  }
  return n;
}

size_t ring_count(const std::vector<Shell> &shells) {
  size_t n = 0;
  for (const Shell &s : shells) n += 1 + s.holes.size();
  return n;
}

enum class Counts { Equal, ThinRings, WithinBand, Differ };

// Where p is against the exact offset region at d of the even-odd region of
// `rings`, by brute force: the region is {s >= -d} for both signs of d, s
// the distance to the rings, positive inside. +1: inside by more than
// `margin`, -1: outside by more than it, 0: within it.
int exact_side(const std::vector<Ring> &rings, const Point &p, double d, double margin) {
  bool inside = false;
  double dist = INFINITY;
  for (const Ring &r : rings) {
    if (point_in_ring(p, r)) inside = !inside;
    dist = std::min(dist, point_ring_distance(p, r));
  }
  double v = (inside ? dist : -dist) + d;
  return v > margin ? 1 : v < -margin ? -1 : 0;
}

// The rings of GEOS's buffer that the brute force contradicts: a point on
// the surface of a polygon (inside it) that is outside the exact region by
// more than `margin`, or a point inside a hole (and outside the result)
// that is inside it by more than `margin`. Each such ring is printed.
int geos_wrong_rings(const std::vector<Ring> &rings, const GEOSGeometry *geos, double d, double margin,
                     const std::string &name) {
  int wrong = 0;
  auto witness = [&](const GEOSGeometry *area, int expect, const char *what) {
    GEOSGeometry *pt = GEOSPointOnSurface_r(ctx, area);
    if (!pt || GEOSisEmpty_r(ctx, pt)) {
      if (pt) GEOSGeom_destroy_r(ctx, pt);
      return;
    }
    double x = 0, y = 0;
    GEOSGeomGetX_r(ctx, pt, &x);
    GEOSGeomGetY_r(ctx, pt, &y);
    GEOSGeom_destroy_r(ctx, pt);
    int side = exact_side(rings, {x, y}, d, margin);
    if (side == -expect) {
      ++wrong;
      double a = geos_area(area);
      std::printf("GEOS WRONG: %s d=%.17g: GEOS has a %s of area %.6g around (%.17g, %.17g), which is %s the exact region "
                  "by more than %.3g (brute-force distance to the input)\n",
                  name.c_str(), d, what, a, x, y, expect > 0 ? "outside" : "inside", margin);
    }
  };
  for (int i = 0, n = GEOSGetNumGeometries_r(ctx, geos); i < n; ++i) {
    const GEOSGeometry *poly = GEOSGetGeometryN_r(ctx, geos, i);
    if (GEOSGeomTypeId_r(ctx, poly) != GEOS_POLYGON || GEOSisEmpty_r(ctx, poly)) continue;
    witness(poly, 1, "polygon");
    for (int h = 0; h < GEOSGetNumInteriorRings_r(ctx, poly); ++h) {
      GEOSGeometry *ring = GEOSGeom_clone_r(ctx, GEOSGetInteriorRingN_r(ctx, poly, h));
      GEOSGeometry *hole = GEOSGeom_createPolygon_r(ctx, ring, nullptr, 0);
      GEOSGeometry *open = GEOSDifference_r(ctx, hole, geos);
      if (open) witness(open, -1, "hole");
      if (open) GEOSGeom_destroy_r(ctx, open);
      GEOSGeom_destroy_r(ctx, hole);
    }
  }
  return wrong;
}

// Whether the number of rings of `theirs` agrees with our loops at d:
// equal; or equal once the rings thinner than t (ours at tolerance t and
// theirs within t' of the exact curve: t = t1 + t') are left out of both
// (they may appear or vanish within the tolerances); or what ours has
// somewhere in [d - 2t, d + 2t] (33 distances, none crossing 0): loops
// that touch, pinch or vanish within the tolerances of d may do so on
// either side of d in an approximation.
Counts compare_counts(const segvoronoi_diagram *diagram, double d, double t, const std::vector<Shell> &ours,
                      const std::vector<Shell> &theirs) {
  size_t mine = ring_count(ours), other = ring_count(theirs);
  if (mine == other) return Counts::Equal;
  if (thick_rings(ours, t) == thick_rings(theirs, t)) return Counts::ThinRings;
  const double band = 2 * t;
  std::vector<double> ds;
  for (int k = -16; k <= 16; ++k) {
    double e = d + band * k / 16;
    if (k != 0 && (e > 0) == (d > 0) && e != 0) ds.push_back(e);
  }
  std::vector<segvoronoi_offset *> offs(ds.size(), nullptr);
  size_t lo = mine, hi = mine;
  if (segvoronoi_diagram_offsets(diagram, ds.data(), ds.size(), offs.data()) == SEGVORONOI_STATUS_OK) {
    for (segvoronoi_offset *o : offs) {
      size_t n = segvoronoi_offset_loop_count(o);
      lo = std::min(lo, n), hi = std::max(hi, n);
      segvoronoi_offset_free(o);
    }
  }
  return lo <= other && other <= hi ? Counts::WithinBand : Counts::Differ;
}

// ---- Clipper ----------------------------------------------------------------

#ifdef SEGVORONOI_HAVE_CLIPPER
struct Scale {
  double cx, cy, s;
  ClipperLib::IntPoint to(const Point &p) const {
    return ClipperLib::IntPoint(ClipperLib::cInt(std::llround((p[0] - cx) * s)), ClipperLib::cInt(std::llround((p[1] - cy) * s)));
  }
  Point from(const ClipperLib::IntPoint &p) const { return {double(p.X) / s + cx, double(p.Y) / s + cy}; }
};

// Clipper's offset as shells with holes (from its PolyTree).
void clipper_shells(const ClipperLib::PolyNode &node, const Scale &sc, std::vector<Shell> &out) {
  for (const ClipperLib::PolyNode *outer : node.Childs) {
    Shell s;
    for (const ClipperLib::IntPoint &p : outer->Contour) s.shell.push_back(sc.from(p));
    for (const ClipperLib::PolyNode *hole : outer->Childs) {
      Ring h;
      for (const ClipperLib::IntPoint &p : hole->Contour) h.push_back(sc.from(p));
      s.holes.push_back(h);
      clipper_shells(*hole, sc, out);
    }
    out.push_back(s);
  }
}

std::vector<Shell> clipper_offset(const std::vector<Ring> &rings, const Scale &sc, double d, double tolerance) {
  ClipperLib::Paths paths, normalised;
  for (const Ring &r : rings) {
    ClipperLib::Path p;
    for (const Point &q : r) p.push_back(sc.to(q));
    paths.push_back(p);
  }
  // even-odd region with Clipper's orientations (outer positive, holes negative)
  ClipperLib::Clipper c;
  c.AddPaths(paths, ClipperLib::ptSubject, true);
  c.Execute(ClipperLib::ctUnion, normalised, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
  ClipperLib::ClipperOffset o(2.0, tolerance * sc.s);
  o.AddPaths(normalised, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  ClipperLib::PolyTree tree;
  o.Execute(tree, d * sc.s);
  std::vector<Shell> shells;
  clipper_shells(tree, sc, shells);
  return shells;
}
#endif

// ---- the comparison ---------------------------------------------------------

struct Stats {
  int cases = 0, failed = 0, known = 0, count_in_band = 0, count_thin = 0, geos_wrong = 0;
  double max_ratio = 0, max_area_ratio = 0, max_clipper_ratio = 0;
  size_t ours_vertices = 0, geos_vertices = 0, clipper_vertices = 0;
  double ours_seconds = 0, geos_seconds = 0, clipper_seconds = 0;
};

std::string dump_name;  // --dump NAME D: the rings of all three results of that case
double dump_distance = 0;

void dump_ring(const char *who, const char *kind, const Ring &r) {
  double minx = INFINITY, miny = INFINITY, maxx = -INFINITY, maxy = -INFINITY;
  for (const Point &p : r) {
    minx = std::min(minx, p[0]), maxx = std::max(maxx, p[0]);
    miny = std::min(miny, p[1]), maxy = std::max(maxy, p[1]);
  }
  std::printf("  %s %s: %zu points, area %.9g, box [%.9g %.9g] x [%.9g %.9g]\n", who, kind, r.size(),
              std::fabs(ring_signed_area(r)), minx, maxx, miny, maxy);
}

void dump_shells(const char *who, const std::vector<Shell> &shells) {
  for (const Shell &s : shells) {
    dump_ring(who, "shell", s.shell);
    for (const Ring &h : s.holes) dump_ring(who, " hole", h);
  }
}

std::vector<Shell> geos_shells(const GEOSGeometry *g) {
  std::vector<Shell> out;
  auto ring = [](const GEOSGeometry *r) {
    Ring ring;
    const GEOSCoordSequence *s = GEOSGeom_getCoordSeq_r(ctx, r);
    unsigned n = 0;
    GEOSCoordSeq_getSize_r(ctx, s, &n);
    for (unsigned i = 0; i + 1 < n; ++i) {
      double x, y;
      GEOSCoordSeq_getXY_r(ctx, s, i, &x, &y);
      ring.push_back({x, y});
    }
    return ring;
  };
  for (int i = 0, n = GEOSGetNumGeometries_r(ctx, g); i < n; ++i) {
    const GEOSGeometry *p = GEOSGetGeometryN_r(ctx, g, i);
    if (GEOSGeomTypeId_r(ctx, p) != GEOS_POLYGON || GEOSisEmpty_r(ctx, p)) continue;
    Shell s{ring(GEOSGetExteriorRing_r(ctx, p)), {}};
    for (int h = 0; h < GEOSGetNumInteriorRings_r(ctx, p); ++h) s.holes.push_back(ring(GEOSGetInteriorRingN_r(ctx, p, h)));
    out.push_back(s);
  }
  return out;
}

bool check_one(const std::string &name, const std::vector<Ring> &rings, const segvoronoi_diagram *diagram,
               const GEOSGeometry *input, double size, double d, bool with_clipper, Stats &st) {
  ++st.cases;
  const double t = 1e-4 * size;
  int quadsegs = std::max(1, int(std::ceil(pi / (4 * std::acos(1 - std::min(1.0, t / std::fabs(d)))))));
  double t2 = std::fabs(d) * (1 - std::cos(pi / (4 * quadsegs)));
  double t1 = t2;
  std::string why;
  char buf[512];

  dump_pieces = name == dump_name && d == dump_distance;
  Ours ours = our_offset(diagram, d, t1, st.ours_seconds);
  auto t0 = std::chrono::steady_clock::now();
  GEOSGeometry *geos = GEOSBufferWithStyle_r(ctx, input, d, quadsegs, GEOSBUF_CAP_ROUND, GEOSBUF_JOIN_ROUND, 5.0);
  st.geos_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!ours.ok) {
    why = ours.error;
  } else if (!geos) {
    why = "GEOS buffer failed";
  } else {
    GEOSGeometry *mine = multipolygon(ours.shells);
    bool dump = name == dump_name && d == dump_distance;
    if (dump) {
      std::printf("dump %s d=%.17g t1=t2=%.6g quadsegs=%d\n", name.c_str(), d, t1, quadsegs);
      dump_shells("ours", ours.shells);
      dump_shells("GEOS", geos_shells(geos));
    }
    double ga = geos_area(geos), sd = symdiff_area(mine, geos);
    double bound = 2 * (t1 + t2) * (geos_length(mine) + geos_length(geos));
    size_t grings = geos_ring_count(geos);
    st.ours_vertices += ours.vertices;
    st.geos_vertices += geos_vertices(geos);
    double ratio = bound > 0 ? sd / bound : (sd > 0 ? INFINITY : 0);
    double area_ratio = bound > 0 ? std::fabs(ours.exact_area - ga) / bound : (ours.exact_area != ga ? INFINITY : 0);
    st.max_ratio = std::max(st.max_ratio, ratio);
    st.max_area_ratio = std::max(st.max_area_ratio, area_ratio);
    if (!GEOSisValid_r(ctx, mine)) {
      char *reason = GEOSisValidReason_r(ctx, mine);
      why += std::string("our polylines are not valid (") + reason + "); ";
      GEOSFree_r(ctx, reason);
    }
    if (!(ratio < 1)) {
      std::snprintf(buf, sizeof buf, "area(symdiff with GEOS) %.6g >= bound %.6g; ", sd, bound);
      why += buf;
    }
    if (!(area_ratio < 1)) {
      std::snprintf(buf, sizeof buf, "exact area %.12g vs GEOS %.12g (bound %.3g); ", ours.exact_area, ga, bound);
      why += buf;
    }
    Counts gc = compare_counts(diagram, d, t1 + t2, ours.shells, geos_shells(geos));
    int geos_wrong = gc == Counts::Differ ? geos_wrong_rings(rings, geos, d, 2 * (t1 + t2), name) : 0;
    std::vector<Counts> counts = {gc};
#ifdef SEGVORONOI_HAVE_CLIPPER
    if (with_clipper) {
      double minx = INFINITY, miny = INFINITY, maxx = -INFINITY, maxy = -INFINITY;
      for (const Ring &r : rings)
        for (const Point &p : r) {
          minx = std::min(minx, p[0]), maxx = std::max(maxx, p[0]);
          miny = std::min(miny, p[1]), maxy = std::max(maxy, p[1]);
        }
      double reach = std::max(maxx - minx, maxy - miny) / 2 + std::max(0.0, d);
      Scale sc{(minx + maxx) / 2, (miny + maxy) / 2, double(1 << 28) / reach};
      auto c0 = std::chrono::steady_clock::now();
      std::vector<Shell> cs = clipper_offset(rings, sc, d, t1);
      double cs_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
      st.clipper_seconds += cs_seconds;
      if (verbose && cs_seconds > 0.2) std::printf("  %s d=%g: Clipper %.2f s\n", name.c_str(), d, cs_seconds);
      GEOSGeometry *clip = multipolygon(cs);
      if (dump) dump_shells("Clipper", cs);
      size_t crings = geos_ring_count(clip);
      // Clipper rounds the number of chords of each join (at least one), so
      // a chord may span 1.5 times the angle asked for: 2.25 times the
      // tolerance; plus the rounding to integers.
      double t3 = 2.25 * t1 + 1 / sc.s;
      double cbound = 2 * (t1 + t3) * (geos_length(mine) + geos_length(clip));
      double csd = symdiff_area(mine, clip);
      double cratio = cbound > 0 ? csd / cbound : (csd > 0 ? INFINITY : 0);
      st.max_clipper_ratio = std::max(st.max_clipper_ratio, cratio);
      st.clipper_vertices += size_t(GEOSGetNumCoordinates_r(ctx, clip)) - crings;
      if (!(cratio < 1)) {
        std::snprintf(buf, sizeof buf, "area(symdiff with Clipper) %.6g >= bound %.6g; ", csd, cbound);
        why += buf;
      }
      Counts cc = compare_counts(diagram, d, t1 + t3, ours.shells, cs);
      counts.push_back(cc);
      if (cc == Counts::Differ) {
        std::snprintf(buf, sizeof buf, "%zu loops, Clipper %zu rings; ", ours.loops, crings);
        why += buf;
      }
      GEOSGeom_destroy_r(ctx, clip);
    }
#else
    (void)with_clipper;
#endif
    // A count that differs where the brute force shows GEOS wrong (and
    // Clipper agrees with ours) is GEOS's; any other is a failure.
    if (gc == Counts::Differ) {
      bool clipper_agrees = counts.size() < 2 || counts[1] != Counts::Differ;
      if (geos_wrong > 0 && clipper_agrees) {
        ++st.geos_wrong;
      } else {
        std::snprintf(buf, sizeof buf, "%zu loops, GEOS %zu rings; ", ours.loops, grings);
        why += buf;
      }
    }
    for (Counts c : counts) {
      if (c == Counts::ThinRings) ++st.count_thin;
      if (c == Counts::WithinBand) ++st.count_in_band;
      if (verbose && (c == Counts::ThinRings || c == Counts::WithinBand))
        std::printf("  %s d=%.17g: ring counts differ, %s\n", name.c_str(), d,
                    c == Counts::ThinRings ? "by thin rings" : "as ours within the band");
    }
    if (verbose)
      std::printf("  %s d=%g: loops=%zu geos_rings=%zu area=%.10g geos=%.10g symdiff/bound=%.3g vertices %zu/%zu\n",
                  name.c_str(), d, ours.loops, grings, ours.exact_area, ga, ratio, ours.vertices, geos_vertices(geos));
    GEOSGeom_destroy_r(ctx, mine);
  }
  if (geos) GEOSGeom_destroy_r(ctx, geos);
  if (!why.empty()) {
    ++st.failed;
    std::printf("FAIL: %s d=%.17g: %s\n", name.c_str(), d, why.c_str());
    return false;
  }
  return true;
}

bool build_diagram(const std::vector<Ring> &rings, segvoronoi_diagram **out) {
  std::vector<double> xy;
  std::vector<size_t> lengths;
  for (const Ring &r : rings) {
    for (const Point &p : r) xy.insert(xy.end(), {p[0], p[1]});
    lengths.push_back(r.size());
  }
  segvoronoi_builder *b = segvoronoi_builder_new();
  segvoronoi_status st = segvoronoi_builder_add_polygon(b, xy.data(), lengths.data(), lengths.size());
  if (st == SEGVORONOI_STATUS_OK) st = segvoronoi_builder_build(b, out);
  if (st != SEGVORONOI_STATUS_OK) std::printf("build failed: %s: %s\n", segvoronoi_status_str(st), segvoronoi_builder_last_error(b));
  segvoronoi_builder_free(b);
  return st == SEGVORONOI_STATUS_OK;
}

double diagonal(const std::vector<Ring> &rings) {
  double minx = INFINITY, miny = INFINITY, maxx = -INFINITY, maxy = -INFINITY;
  for (const Ring &r : rings)
    for (const Point &p : r) {
      minx = std::min(minx, p[0]), maxx = std::max(maxx, p[0]);
      miny = std::min(miny, p[1]), maxy = std::max(maxy, p[1]);
    }
  return std::hypot(maxx - minx, maxy - miny);
}

// --cut straight|nudged (issue 27): every edge of every input cut at
// points exactly on it, straight vertices, as users' polygons have them;
// nudged: each cut point then moved one ulp off the edge's line (across
// its main direction; a zero coordinate is left alone, an ulp of it is a
// subnormal). The rings are first snapped to the dyadic grid of 2^-30 of
// the power of two above their largest coordinate, so the cut points, at
// parameters j/4 (edge k gets 1 + k % 3 of them: 1/4, 1/2, 3/4), are
// exact: the endpoints' differences, their products with j/4 and the sums
// all fit in 53 bits. The names get the suffix "+straight" or "+nudged".
void cut_edges(Input &in, bool nudge) {
  double largest = 0.0;
  for (const Ring &r : in.rings)
    for (const Point &p : r) largest = std::max({largest, std::abs(p[0]), std::abs(p[1])});
  const int shift = 30 - std::ilogb(largest);
  const auto snap = [shift](double v) { return std::ldexp(std::nearbyint(std::ldexp(v, shift)), -shift); };
  std::size_t k = 0;
  for (Ring &r : in.rings) {
    Ring snapped;
    for (const Point &p : r) {
      const Point q{snap(p[0]), snap(p[1])};
      if (snapped.empty() || snapped.back() != q) snapped.push_back(q);
    }
    while (snapped.size() > 1 && snapped.front() == snapped.back()) snapped.pop_back();
    Ring out;
    for (std::size_t i = 0; i < snapped.size(); ++i, ++k) {
      const Point a = snapped[i], b = snapped[(i + 1) % snapped.size()];
      out.push_back(a);
      const int cuts = 1 + int(k % 3);
      for (int j = 1; j <= cuts; ++j) {
        const double t = (cuts == 2 ? 2 * j - 1 : j) / 4.0;  // 1/2; 1/4 3/4; 1/4 1/2 3/4
        Point c{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
        if (nudge) {
          int across = std::abs(b[0] - a[0]) >= std::abs(b[1] - a[1]) ? 1 : 0;
          if (c[across] == 0.0) across = 1 - across;
          if (c[across] != 0.0) c[across] = std::nextafter(c[across], (k + j) % 2 ? INFINITY : -INFINITY);
        }
        out.push_back(c);
      }
    }
    r = out;
  }
  in.name += nudge ? "+nudged" : "+straight";
}

void run_input(const Input &in, const std::vector<Known> &known, Stats &st) {
  segvoronoi_diagram *diagram = nullptr;
  if (!build_diagram(in.rings, &diagram)) {
    ++st.cases;
    ++st.failed;
    std::printf("FAIL: %s: the diagram was not built\n", in.name.c_str());
    return;
  }
  // segvoronoi gets the rings as they are; GEOS, Clipper and the brute
  // force the boundary of their even-odd region
  const std::vector<Ring> boundary = even_odd_boundary(in.rings);
  GEOSGeometry *input = multipolygon(even_odd_shells(boundary));
  double size = diagonal(in.rings);
  std::vector<double> distances = in.distances;
  if (in.name == dump_name) {
    std::printf("input %s (rings format):\nrings %zu\n", in.name.c_str(), in.rings.size());
    for (const Ring &r : in.rings) {
      std::printf("%zu\n", r.size());
      for (const Point &p : r) std::printf("%.17g %.17g\n", p[0], p[1]);
    }
  }
  if (in.name == dump_name && std::find(distances.begin(), distances.end(), dump_distance) == distances.end())
    distances.push_back(dump_distance);
  for (double d : distances) {
    bool skip = false;
    for (const Known &k : known)
      if (k.name == in.name && k.distance == d) skip = true;
    if (!skip) check_one(in.name, boundary, diagram, input, size, d, d >= in.clipper_from, st);
  }
  // segvoronoi_diagram_offsets at all the distances at once (one shared
  // index) must give what segvoronoi_diagram_offset gives at each.
  std::vector<segvoronoi_offset *> batch(distances.size(), nullptr);
  if (segvoronoi_diagram_offsets(diagram, distances.data(), distances.size(), batch.data()) != SEGVORONOI_STATUS_OK) {
    ++st.failed;
    std::printf("FAIL: %s: segvoronoi_diagram_offsets failed\n", in.name.c_str());
  } else {
    for (size_t k = 0; k < distances.size(); ++k) {
      segvoronoi_offset *single = nullptr;
      segvoronoi_diagram_offset(diagram, distances[k], &single);
      if (segvoronoi_offset_loop_count(single) != segvoronoi_offset_loop_count(batch[k]) ||
          segvoronoi_offset_area(single) != segvoronoi_offset_area(batch[k])) {
        ++st.failed;
        std::printf("FAIL: %s d=%.17g: segvoronoi_diagram_offsets gives %zu loops of area %.17g, "
                    "segvoronoi_diagram_offset %zu of %.17g\n",
                    in.name.c_str(), distances[k], segvoronoi_offset_loop_count(batch[k]),
                    segvoronoi_offset_area(batch[k]), segvoronoi_offset_loop_count(single), segvoronoi_offset_area(single));
      }
      segvoronoi_offset_free(single);
      segvoronoi_offset_free(batch[k]);
    }
  }
  GEOSGeom_destroy_r(ctx, input);
  segvoronoi_diagram_free(diagram);
}

}  // namespace

int main(int argc, char **argv) {
  std::string glyphs, cut;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--glyphs" && i + 1 < argc) glyphs = argv[++i];
    else if (a == "--cut" && i + 1 < argc && (std::string(argv[i + 1]) == "straight" || std::string(argv[i + 1]) == "nudged")) cut = argv[++i];
    else if (a == "--verbose") verbose = true;
    else if (a == "--dump" && i + 2 < argc) {
      dump_name = argv[++i];
      dump_distance = std::strtod(argv[++i], nullptr);
    }
    else {
      std::fprintf(stderr, "usage: %s [--glyphs DIR] [--cut straight|nudged] [--verbose] [--dump NAME D]\n", argv[0]);
      return 2;
    }
  }
  auto start = std::chrono::steady_clock::now();
  ctx = GEOS_init_r();
  GEOSContext_setNoticeHandler_r(ctx, geos_message);
  GEOSContext_setErrorHandler_r(ctx, geos_message);

  std::vector<Input> inputs;
  // random polygons with holes: convex, mildly and very non-convex
  for (uint64_t seed = 1; seed <= 100; ++seed) {
    bool convex = seed % 5 == 1;
    double rmin = seed % 3 == 0 ? 0.1 : 0.5;
    inputs.push_back(star_with_holes(seed, convex, rmin, int(seed % 6), seed % 10 == 7 ? 600 : 200));
  }
  for (int n : {3, 4, 5, 6, 7, 8, 12, 17, 64, 255}) inputs.push_back(regular(n));
  inputs.push_back(disk4096());
  if (!glyphs.empty()) {
    for (const char *g : {"B", "8", "g"}) {
      Input in;
      in.name = std::string("glyph-") + g;
      if (!read_rings(glyphs + "/glyph_" + g + ".rings", in.rings)) {
        std::fprintf(stderr, "cannot read %s/glyph_%s.rings\n", glyphs.c_str(), g);
        return 2;
      }
      // font units (2048/em): strokes are about 180 units wide
      in.distances = {-5, -20, -50, -89, -150, 5, 30, 100, 400};
      inputs.push_back(in);
    }
    // Country outlines in km (scripts/country_rings.py: the Digital Chart
    // of the World, gmt-dcw), with their straight and nearly straight
    // vertices, enclaves and islands, and GSHHG's islands of a sea
    // (scripts/island_rings.py): every dcw_*.rings and gshhg_islands_*.rings
    // beside the glyphs.
    std::vector<std::string> countries;
    for (const auto &entry : std::filesystem::directory_iterator(glyphs)) {
      std::string file = entry.path().filename().string();
      if ((file.rfind("dcw_", 0) == 0 || file.rfind("gshhg_islands_", 0) == 0) && file.size() > 6 && file.substr(file.size() - 6) == ".rings") countries.push_back(file);
    }
    std::sort(countries.begin(), countries.end());
    for (const std::string &file : countries) {
      Input in;
      in.name = file.substr(0, file.size() - 6);
      if (!read_rings(glyphs + "/" + file, in.rings)) {
        std::fprintf(stderr, "cannot read %s/%s\n", glyphs.c_str(), file.c_str());
        return 2;
      }
      in.distances = {-0.5, -3, -15, -40, 0.5, 3, 20, 150};
      inputs.push_back(in);
    }
  } else {
    std::printf("note: no --glyphs DIR, the glyph and country outlines are left out\n");
  }

  if (!cut.empty()) {
    // a quarter of the random polygons, the regular ones and the glyphs
    // (cut, they have about three times the vertices; the 4096-gon is
    // left out): about a third of the time of the uncut run
    std::vector<Input> kept;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const bool random = inputs[i].name.rfind("star", 0) == 0;
      if ((random && i % 4 == 0) || (!random && inputs[i].rings.size() == 1 && inputs[i].rings[0].size() < 4096) ||
          inputs[i].name.rfind("glyph", 0) == 0)
        kept.push_back(inputs[i]);
    }
    inputs = kept;
    for (Input &in : inputs) cut_edges(in, cut == "nudged");
  }

  std::vector<Known> known;  // none known
  for (const Known &k : known) std::printf("KNOWN: %s d=%.17g: %s\n", k.name.c_str(), k.distance, k.what.c_str());

  Stats st;
  for (const Input &in : inputs) run_input(in, known, st);
  st.known = int(known.size());
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "geos_offsets: cases=%d failed=%d known=%d counts_thin=%d counts_within_band=%d geos_wrong=%d max_symdiff/bound=%.3g max_area_diff/bound=%.3g"
#ifdef SEGVORONOI_HAVE_CLIPPER
      " clipper_max_symdiff/bound=%.3g"
#endif
      " vertices ours=%zu geos=%zu"
#ifdef SEGVORONOI_HAVE_CLIPPER
      " clipper=%zu"
#endif
      " seconds ours=%.2f geos=%.2f"
#ifdef SEGVORONOI_HAVE_CLIPPER
      " clipper=%.2f"
#endif
      " total=%.1f (GEOS %s)\n",
      st.cases, st.failed, st.known, st.count_thin, st.count_in_band, st.geos_wrong, st.max_ratio, st.max_area_ratio,
#ifdef SEGVORONOI_HAVE_CLIPPER
      st.max_clipper_ratio,
#endif
      st.ours_vertices, st.geos_vertices,
#ifdef SEGVORONOI_HAVE_CLIPPER
      st.clipper_vertices,
#endif
      st.ours_seconds, st.geos_seconds,
#ifdef SEGVORONOI_HAVE_CLIPPER
      st.clipper_seconds,
#endif
      seconds, GEOSversion());
  GEOS_finish_r(ctx);
  return st.failed == 0 ? 0 : 1;
}
