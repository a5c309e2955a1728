// SPDX-License-Identifier: BSL-1.0
#pragma once
// Exact distances for the tests of the filters and the distance bounds,
// computed on CGAL's own kernel over exact rationals (CGAL::Cartesian<
// exact_rational>, squared_distance of Point_2 and Segment_2), independent
// of the library's distance code; and exact comparisons of a double with the
// square root of an exact value.

#include <cmath>

#include <CGAL/Cartesian.h>

#include "influence2d/core/point.hpp"
#include "influence2d/number/cgal.hpp"

namespace test_exact {

using Q = influence2d::exact_rational;
using kernel = CGAL::Cartesian<Q>;
using exact_point = kernel::Point_2;
using exact_segment = kernel::Segment_2;

inline exact_point exact(const influence2d::point<double>& p) { return {Q(p.x), Q(p.y)}; }

/// 2^e exactly, for any e (beyond double's exponent range too).
inline Q pow2(int e) {
    Q r(1);
    const Q step(e < 0 ? 0x1p-512 : 0x1p512);
    int left = e < 0 ? -e : e;
    for (; left >= 512; left -= 512) r *= step;
    return r * Q(std::ldexp(1.0, e < 0 ? -left : left));
}

/// The squared distance from p to the closed segment [a, b] (a point when
/// a == b).
inline Q squared_distance(const exact_point& p, const exact_point& a, const exact_point& b) {
    if (a == b) return CGAL::squared_distance(p, a);
    return CGAL::squared_distance(p, exact_segment(a, b));
}

/// The squared distance between the closed segments [a, b] and [u, v] (either
/// may be a point).
inline Q squared_distance(const exact_point& a, const exact_point& b, const exact_point& u, const exact_point& v) {
    if (a == b) return squared_distance(a, u, v);
    if (u == v) return squared_distance(u, a, b);
    return CGAL::squared_distance(exact_segment(a, b), exact_segment(u, v));
}

inline Q squared_distance(const influence2d::point<double>& p, const influence2d::point<double>& a,
                          const influence2d::point<double>& b) {
    return squared_distance(exact(p), exact(a), exact(b));
}

/// Whether x <= sqrt(d2), exactly (d2 >= 0).
inline bool at_most_root(const Q& x, const Q& d2) { return x <= 0 || x * x <= d2; }
/// Whether x >= sqrt(d2), exactly (d2 >= 0).
inline bool at_least_root(const Q& x, const Q& d2) { return x >= 0 && x * x >= d2; }

}  // namespace test_exact
