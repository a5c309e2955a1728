// SPDX-License-Identifier: BSL-1.0
#pragma once
// Small polygons for the unit tests.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/random.hpp"

namespace test_shapes {

using influence2d::point;
using influence2d::polygon;
using influence2d::ring_input;
using influence2d::ring_role;

/// Every number type the detector is tested with.
#define INFLUENCE2D_NUMBER_TYPES float, double, long double, influence2d::exact_rational

/// The point (x, y) in number type NT.
template <class NT>
point<NT> pt(double x, double y) {
    return {influence2d::number_traits<NT>::from_double(x), influence2d::number_traits<NT>::from_double(y)};
}

inline ring_input ring(std::vector<point<double>> v, ring_role role = ring_role::outer) {
    return ring_input{std::move(v), role};
}

/// The wiggly border y = 0.2 sin(3.1 x) + 0.1 sin(7.3 x) from x = 0 to 100,
/// n + 1 vertices (two large polygons' long shared border).
inline std::vector<point<double>> wiggly_border(std::size_t n) {
    std::vector<point<double>> out;
    for (std::size_t k = 0; k <= n; ++k) {
        const double x = 100.0 * static_cast<double>(k) / static_cast<double>(n);
        out.push_back({x, 0.2 * std::sin(3.1 * x) + 0.1 * std::sin(7.3 * x)});
    }
    return out;
}

/// The region below the border b (side -1) or above it (side +1), 10 deep.
inline polygon border_side(const std::vector<point<double>>& b, double side) {
    ring_input r;
    r.vertices = b;
    r.vertices.push_back({b.back().x, 10 * side});
    r.vertices.push_back({b.front().x, 10 * side});
    return polygon({r});
}

/// n points at sorted random angles on an ellipse about c (axes rx, ry),
/// turned by a random angle: a convex polygon's vertices, counter-clockwise,
/// but for the rounding of their doubles (is_convex_polygon decides).
inline std::vector<point<double>> ellipse_points(test_random::rng& r, std::size_t n, point<double> c, double rx,
                                                 double ry) {
    std::vector<double> angles(n);
    for (double& a : angles) a = r.uniform(0, 6.283185307179586);
    std::sort(angles.begin(), angles.end());
    const double phi = r.uniform(0, 3.14159);
    std::vector<point<double>> v;
    for (double a : angles) {
        const double x = rx * std::cos(a), y = ry * std::sin(a);
        v.push_back({c.x + std::cos(phi) * x - std::sin(phi) * y, c.y + std::sin(phi) * x + std::cos(phi) * y});
    }
    return v;
}

/// The axis-parallel square [x, x+s] x [y, y+s], counter-clockwise from (x, y).
inline ring_input square_ring(double x, double y, double s, ring_role role = ring_role::outer) {
    return ring({{x, y}, {x + s, y}, {x + s, y + s}, {x, y + s}}, role);
}

inline polygon square(double x, double y, double s) { return polygon({square_ring(x, y, s)}); }

/// A square [0,8]^2 with the square hole [2,6]^2.
inline polygon square_with_hole() { return polygon({square_ring(0, 0, 8), square_ring(2, 2, 4, ring_role::hole)}); }

/// A C shape whose centroid lies in its opening:
///   (0,6)+------+(6,6)
///        | +----+(6,5)
///        | |(1,5)
///        | |(1,1)
///        | +----+(6,1)
///   (0,0)+------+(6,0)
inline polygon c_shape() { return polygon({ring({{0, 0}, {6, 0}, {6, 1}, {1, 1}, {1, 5}, {6, 5}, {6, 6}, {0, 6}})}); }

/// p with every coordinate multiplied by 2^e, built anew from its rings
/// (their roles kept).
inline polygon scaled(const polygon& p, int e) {
    std::vector<ring_input> rings;
    for (std::size_t r = 0; r < p.ring_count(); ++r) {
        ring_input in{{}, p.role(r)};
        for (std::size_t i = p.ring_begin(r); i < p.ring_end(r); ++i)
            in.vertices.push_back({std::ldexp(p.vertex(i).x, e), std::ldexp(p.vertex(i).y, e)});
        rings.push_back(in);
    }
    return polygon(rings);
}

/// p translated by (dx, dy), built anew from its rings (their roles
/// kept): a layer's polygon where an unturned body of it stands.
inline polygon translated(const polygon& p, double dx, double dy) {
    std::vector<ring_input> rings;
    for (std::size_t r = 0; r < p.ring_count(); ++r) {
        ring_input in{{}, p.role(r)};
        for (std::size_t i = p.ring_begin(r); i < p.ring_end(r); ++i)
            in.vertices.push_back({p.vertex(i).x + dx, p.vertex(i).y + dy});
        rings.push_back(in);
    }
    return polygon(rings);
}

}  // namespace test_shapes
