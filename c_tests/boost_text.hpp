// Boost.Polygon's voronoi text format, read and written by the CGAL
// cross-checks (cgal_crosscheck.cpp, cgal_split.cpp): P, then P lines
// "x y", then S, then S lines "x0 y0 x1 y1" (src/boost_text.rs is the
// library's reader). Templates over the input type, which has `points`
// (each with x and y) and `segments` (each with points a and b), so that
// each program keeps its own Input.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

// Writes the input with every digit needed to read back the same doubles:
// a minimised case becomes a file to debug with.
template <class Input>
void write_boost_text(std::FILE* out, const Input& input) {
    std::fprintf(out, "%zu\n", input.points.size());
    for (const auto& p : input.points) std::fprintf(out, "%.17g %.17g\n", p.x, p.y);
    std::fprintf(out, "%zu\n", input.segments.size());
    for (const auto& s : input.segments) std::fprintf(out, "%.17g %.17g %.17g %.17g\n", s.a.x, s.a.y, s.b.x, s.b.y);
}

template <class Input>
bool write_boost_file(const std::string& path, const Input& input) {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (out == nullptr) return false;
    write_boost_text(out, input);
    return std::fclose(out) == 0;
}

inline bool read_boost_number(std::FILE* in, double& v) { return std::fscanf(in, "%lf", &v) == 1 && std::isfinite(v); }

// Reads one input from `in`; the segment count may be left out at the end
// of a file.
template <class Input>
bool read_boost_text(std::FILE* in, Input& input, std::string& error) {
    std::size_t point_count = 0;
    if (std::fscanf(in, "%zu", &point_count) != 1) {
        error = "missing point count";
        return false;
    }
    input.points.resize(point_count);
    for (std::size_t i = 0; i < point_count; ++i) {
        auto& p = input.points[i];
        if (!read_boost_number(in, p.x) || !read_boost_number(in, p.y)) {
            error = "point " + std::to_string(i) + " is missing, malformed or not finite";
            return false;
        }
    }
    std::size_t segment_count = 0;
    if (std::fscanf(in, "%zu", &segment_count) != 1) segment_count = 0;
    input.segments.resize(segment_count);
    for (std::size_t i = 0; i < segment_count; ++i) {
        auto& s = input.segments[i];
        if (!read_boost_number(in, s.a.x) || !read_boost_number(in, s.a.y) || !read_boost_number(in, s.b.x) ||
            !read_boost_number(in, s.b.y)) {
            error = "segment " + std::to_string(i) + " is missing, malformed or not finite";
            return false;
        }
    }
    return true;
}

template <class Input>
bool read_boost_file(const std::string& path, Input& input, std::string& error) {
    std::FILE* in = std::fopen(path.c_str(), "r");
    if (in == nullptr) {
        error = "cannot open " + path;
        return false;
    }
    const bool ok = read_boost_text(in, input, error);
    std::fclose(in);
    return ok;
}
