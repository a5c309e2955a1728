// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The orientation predicate: the one sign question everything else is made of.

#include <cmath>
#include <type_traits>

#include "influence2d/core/point.hpp"
#include "influence2d/number/exact_sum.hpp"
#include "influence2d/number/traits.hpp"

namespace influence2d {

namespace orientation_detail {
template <class NT, class = void>
struct has_exact_double_fallback : std::false_type {};
template <class NT>
struct has_exact_double_fallback<NT, std::void_t<decltype(number_traits<NT>::exact_double_fallback)>>
    : std::bool_constant<number_traits<NT>::exact_double_fallback> {};
}  // namespace orientation_detail

/// The relative error bound of the orientation determinant evaluated in
/// double on input doubles, (b.x - a.x)(c.y - a.y) - (b.y - a.y)(c.x - a.x):
/// its rounded value errs from the exact one by at most (3 + 16 u) u times
/// the sum of the two products' magnitudes, u = 2^-53 (the two differences
/// of each product, the products and the last difference rounded once
/// each, and the bound's own evaluation; Shewchuk's ccwerrboundA, Adaptive
/// Precision Floating-Point Arithmetic and Fast Robust Geometric
/// Predicates, 1997), as long as no product underflows.
inline constexpr double orientation_relative_bound = (3 + 16 * 0x1p-53) * 0x1p-53;
/// What a product that underflows may add to that error: each of the two
/// products loses at most 2^-1075 (half the least subnormal); the bound
/// takes twice their sum.
inline constexpr double orientation_underflow = 0x1p-1072;

/// The sign of left - right for two products, each of two factors that are
/// rounded differences of doubles (the orientation determinant's form), when
/// the rounded difference exceeds its error bound (orientation_relative_bound
/// on the two products' magnitudes, orientation_underflow); 0 when it does
/// not (the sign is then left to an exact evaluation).
inline int certain_products_sign(double left, double right) {
    const double det = left - right;
    const double bound = orientation_relative_bound * (std::fabs(left) + std::fabs(right)) + orientation_underflow;
    if (det > bound) return 1;
    if (det < -bound) return -1;
    return 0;
}

/// The sign of the orientation determinant of three points given as
/// doubles, exactly: in double when the rounded determinant exceeds its
/// error bound (certain_products_sign), which settles nearly every
/// call at the cost of a few multiplications; else 0 when two of the points
/// are the same; else by the signs of the differences when one product has
/// a zero factor; else by the exact sum (number/exact_sum.hpp).
inline int orientation_of_doubles(double ax, double ay, double bx, double by, double cx, double cy) {
    if (const int sign = certain_products_sign((bx - ax) * (cy - ay), (by - ay) * (cx - ax))) return sign;
    // Two of the points the same (a vertex shared by two polygons, say):
    // collinear, without the sum.
    if ((ax == bx && ay == by) || (ax == cx && ay == cy) || (bx == cx && by == cy)) return 0;
    // A product with a zero factor (two equal coordinates: an axis-parallel
    // edge, a shared abscissa or ordinate) is 0 exactly, and the
    // determinant then has the sign of the other product, that of its two
    // differences: a rounded difference of doubles has the sign of the exact
    // one, and is 0 only when the two are equal. Grids and rectangles come
    // here, without the exact sum.
    using tr = number_traits<double>;
    if (bx == ax || cy == ay) return -tr::sign(by - ay) * tr::sign(cx - ax);
    if (by == ay || cx == ax) return tr::sign(bx - ax) * tr::sign(cy - ay);
    return exact_sum::orientation_sign(ax, ay, bx, by, cx, cy);
}

/// Sign of the signed area [a b c]: +1 when c lies left of the directed line
/// a->b (counter-clockwise turn), -1 when right, 0 when the three are collinear.
/// Two coinciding points are collinear with any third. The determinant is
/// evaluated in NT, its sign taken by number_traits::sign: exact when NT's
/// ring operations are exact. For a filtered NT the sign is exact, or the
/// call throws uncertain_sign (certified, interval); a type with
/// `exact_double_fallback` takes the sign of three points that are input
/// doubles (a polygon where it stands, its centroid) from
/// orientation_of_doubles instead: exact, and at double's cost. In a
/// floating NT it is the sign of the rounded determinant, which can be
/// wrong for nearly collinear points.
template <class NT>
int orientation(const point<NT>& a, const point<NT>& b, const point<NT>& c) {
    using tr = number_traits<NT>;
    if constexpr (orientation_detail::has_exact_double_fallback<NT>::value) {
        if (tr::exact(a.x) && tr::exact(a.y) && tr::exact(b.x) && tr::exact(b.y) && tr::exact(c.x) && tr::exact(c.y))
            return orientation_of_doubles(tr::to_double(a.x), tr::to_double(a.y), tr::to_double(b.x),
                                          tr::to_double(b.y), tr::to_double(c.x), tr::to_double(c.y));
    }
    return tr::sign((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

/// Whether p and q are the same point: both coordinates equal by
/// compare_values (so a filtered NT raises uncertain_sign when it cannot
/// tell). Exact when NT's ring operations are.
template <class NT>
bool same_point(const point<NT>& p, const point<NT>& q) {
    return compare_values(p.x, q.x) == 0 && compare_values(p.y, q.y) == 0;
}

/// Whether the value p lies between the values a and b, both included, in
/// either order: a - p and p - b do not have opposite signs (two calls of
/// compare_values).
template <class NT>
bool between(const NT& p, const NT& a, const NT& b) {
    return compare_values(a, p) * compare_values(p, b) >= 0;
}

/// Whether p, known to be collinear with a and b, lies on the closed segment
/// [a, b] (endpoints included; for a == b, whether p is that point). Compares
/// coordinates only (through compare_values), so the result is meaningless
/// when p is not collinear.
template <class NT>
bool within_collinear_segment(const point<NT>& p, const point<NT>& a, const point<NT>& b) {
    return between(p.x, a.x, b.x) && between(p.y, a.y, b.y);
}

/// Whether p lies on the closed segment [a, b] (endpoints included; a == b
/// allowed, then p must be that point). Exact when orientation() is.
template <class NT>
bool on_segment(const point<NT>& p, const point<NT>& a, const point<NT>& b) {
    return orientation(a, b, p) == 0 && within_collinear_segment(p, a, b);
}

}  // namespace influence2d
