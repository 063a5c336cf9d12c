// Exact rational helpers shared by the CGAL cross-checks
// (cgal_crosscheck.cpp, cgal_split.cpp): whether a rational is a square,
// and the Voronoi vertex of two points and a segment's line when it is
// rational. Header-only; include after <CGAL/Gmpq.h>.
#pragma once

#include <CGAL/Gmpq.h>
#include <gmp.h>

#include <vector>

// A point with rational coordinates.
struct QPoint {
    CGAL::Gmpq x, y;
    bool operator==(const QPoint& o) const { return x == o.x && y == o.y; }
};

// Whether the rational q is the square of a rational, and if so its root.
inline bool rational_sqrt(const CGAL::Gmpq& q, CGAL::Gmpq& root) {
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

// The circle through the points p, q tangent to the line a-b with p, q and
// the touching point counter-clockwise (the Voronoi vertex of the face
// (p, q, segment ab)), when it is rational: the centre X = M + t d on the
// bisector of p and q solves a quadratic in t whose discriminant is then a
// square.
inline bool rational_pps(const QPoint& p, const QPoint& q, const QPoint& a, const QPoint& b, CGAL::Gmpq& x, CGAL::Gmpq& y) {
    using Q = CGAL::Gmpq;
    const Q nx = a.y - b.y, ny = b.x - a.x, c = nx * a.x + ny * a.y, n2 = nx * nx + ny * ny;
    const Q mx = (p.x + q.x) / Q(2), my = (p.y + q.y) / Q(2);
    const Q dx = p.y - q.y, dy = q.x - p.x;
    const Q alpha = nx * mx + ny * my - c, beta = nx * dx + ny * dy;
    const Q mp2 = (mx - p.x) * (mx - p.x) + (my - p.y) * (my - p.y), d2 = dx * dx + dy * dy;
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
        if ((q.x - p.x) * (ty - p.y) - (q.y - p.y) * (tx - p.x) > 0) {
            x = cx;
            y = cy;
            return true;
        }
    }
    return false;
}
