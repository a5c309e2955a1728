// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Extended influence areas of length n (docs/method.md section 5): exact membership
/// of a point, in either shape. Both contain every point within n of the edge.

#include <algorithm>
#include <cmath>

#include "influence2d/core/point.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/segments.hpp"

namespace influence2d {

/// The shape used for the extended influence area of an edge (docs/method.md section 5).
enum class extended_area {
    capsule,  ///< points within n of the edge segment
    band      ///< the paper's band between parallels at distance n, axis-parallel caps
};

/// The ideal area: points within n of the segment [a, b] (a closed capsule;
/// a disk for a == b). `n2` is n squared. Exact when NT is.
template <class NT>
bool in_capsule(const point<NT>& p, const point<NT>& a, const point<NT>& b, const NT& n2) {
    return point_segment_within(p, a, b, n2);
}

/// The paper's area: the band between the two parallels to [a, b] at distance n,
/// cut by two axis-parallel lines at distance n beyond the end vertices:
/// vertical ones when |slope| <= 1, horizontal ones otherwise. Closed, and a
/// superset of the capsule. For a == b no band is defined: the test keeps
/// the vertical strip |x - a.x| <= n (conservative). `n2` is n squared.
/// Exact when NT is.
template <class NT>
bool in_band(const point<NT>& p, const point<NT>& a, const point<NT>& b, const NT& n, const NT& n2) {
    const NT abx = b.x - a.x, aby = b.y - a.y;
    if (!point_line_within(p, a, abx, aby, n2)) return false;
    const bool vertical_caps = compare_values<NT>(aby * aby, abx * abx) <= 0;
    const NT& pa = vertical_caps ? a.x : a.y;
    const NT& pb = vertical_caps ? b.x : b.y;
    const NT& pp = vertical_caps ? p.x : p.y;
    const bool a_first = compare_values(pa, pb) < 0;
    const NT& lo = a_first ? pa : pb;
    const NT& hi = a_first ? pb : pa;
    return compare_values<NT>(pp, lo - n) >= 0 && compare_values<NT>(pp, hi + n) <= 0;
}

/// Membership in the chosen shape of extended area of length n >= 0 (closed:
/// the boundary counts). Exact when NT is.
template <class NT>
bool in_extended_area(extended_area shape, const point<NT>& p, const point<NT>& a, const point<NT>& b, const NT& n) {
    const NT n2 = n * n;
    return shape == extended_area::capsule ? in_capsule(p, a, b, n2) : in_band(p, a, b, n, n2);
}

/// Whether p may lie in the extended area of length n of [a, b], evaluated in
/// double for a filter: coordinates are taken relative to a and scaled by a
/// power of two to magnitude ~1 first, so that no square overflows or
/// underflows; non-finite differences keep the edge, as does p == a == b
/// with n == 0. Rounded: callers widen n by their rounding margin.
inline bool may_be_in_extended_area(extended_area shape, const point<double>& p, const point<double>& a,
                                    const point<double>& b, double n) {
    const double big =
        std::max({std::fabs(b.x - a.x), std::fabs(b.y - a.y), std::fabs(p.x - a.x), std::fabs(p.y - a.y), n});
    if (!std::isfinite(big)) return true;
    if (big == 0) return true;
    // Within this range no square over- or underflows: no scaling needed.
    if (big > square_safe_low && big < square_safe_high) return in_extended_area(shape, p, a, b, n);
    const int e = std::ilogb(big);
    const auto scaled = [&](const point<double>& q) {
        return point<double>{std::ldexp(q.x - a.x, -e), std::ldexp(q.y - a.y, -e)};
    };
    return in_extended_area(shape, scaled(p), point<double>{0, 0}, scaled(b), std::ldexp(n, -e));
}

}  // namespace influence2d
