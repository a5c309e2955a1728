// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Exact decisions on points of finite doubles as given, with no number type:
/// the orientation by the exact fixed-point sum (number/exact_sum.hpp), and
/// what is built on it alone. For input that is not yet a polygon (the audit
/// of rings as read); the detectors decide in their number type instead
/// (orientation.hpp, segments.hpp).

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/number/double_word.hpp"
#include "influence2d/number/exact_sum.hpp"
#include "influence2d/predicates/orientation.hpp"

namespace influence2d {

/// The exact orientation of three points with finite double coordinates
/// (orientation_of_doubles: the determinant in double when it exceeds its
/// error bound, else exact_sum::orientation_sign; orientation() in double
/// rounds).
inline int exact_orientation(const point<double>& a, const point<double>& b, const point<double>& c) {
    return orientation_of_doubles(a.x, a.y, b.x, b.y, c.x, c.y);
}

/// The exact sign of the cross product (b - a) x (d - c) of the directions
/// of two segments with finite double coordinates: 0 when they are parallel
/// (or one has length 0). In double when the rounded product exceeds its
/// error bound (certain_products_sign: each of its two products has two
/// factors that are rounded differences of doubles, as in the orientation
/// determinant, whose bound holds for it alike); else the eight products of
/// its expansion, bx dy - bx cy - ax dy + ax cy - by dx + by cx + ay dx -
/// ay cx, summed exactly (exact_sum::accumulator): no difference is rounded.
inline int exact_cross_sign(const point<double>& a, const point<double>& b, const point<double>& c,
                            const point<double>& d) {
    if (const int sign = certain_products_sign((b.x - a.x) * (d.y - c.y), (b.y - a.y) * (d.x - c.x))) return sign;
    exact_sum::accumulator sum;
    sum.add_product(b.x, d.y);
    sum.add_product(-b.x, c.y);
    sum.add_product(-a.x, d.y);
    sum.add_product(a.x, c.y);
    sum.add_product(-b.y, d.x);
    sum.add_product(b.y, c.x);
    sum.add_product(a.y, d.x);
    sum.add_product(-a.y, c.x);
    return sum.sign();
}

/// x - y in `out`, returning whether it is exact (each coordinate's
/// difference a double: exact_sum::exact_double_sum).
inline bool exact_difference(const point<double>& x, const point<double>& y, point<double>& out) {
    return exact_sum::exact_double_sum(x.x, -y.x, out.x) && exact_sum::exact_double_sum(x.y, -y.y, out.y);
}

/// The exact sign of d x (a - (v + t)) for d = to - from, all finite
/// doubles as given: the side of the point a against the line through v + t
/// with direction d (a point v of a polygon translated by t, moving by
/// to - from). When the differences d, a - v and then a - v - t are
/// doubles (exact_difference; for a = v, a vertex two polygons share, a - v
/// is 0 and a - v - t is -t, without the two), the orientation of 0, d and
/// that point (orientation_of_doubles); else in double words when their
/// bound settles it (a point that passes within rounding of a vertex, not
/// through it: a side of about 2^-53 of the coordinates' products, which the
/// words' 2^-100 settle); else the twelve products of its expansion summed
/// exactly. The same sign is that of a against -d's line through v + t: a
/// vertex of the still polygon moving by -d relative to the other.
inline int exact_translated_side(const point<double>& from, const point<double>& to, const point<double>& a,
                                 const point<double>& v, const point<double>& t) {
    point<double> d, av, w{-t.x, -t.y};
    if (exact_difference(to, from, d) && (a == v || (exact_difference(a, v, av) && exact_difference(av, t, w))))
        return orientation_of_doubles(0, 0, d.x, d.y, w.x, w.y);  // d x w
    const double_word dx = double_word(to.x) - double_word(from.x), dy = double_word(to.y) - double_word(from.y);
    const double_word wx = double_word(a.x) - double_word(v.x) - double_word(t.x),
                      wy = double_word(a.y) - double_word(v.y) - double_word(t.y);
    if (int sign = 0; (dx * wy - dy * wx).try_sign(sign)) return sign;
    exact_sum::accumulator sum;
    for (const auto& [q, sign] : {std::pair<const point<double>*, double>{&a, 1}, {&v, -1}, {&t, -1}}) {
        sum.add_product(sign * to.x, q->y);
        sum.add_product(-sign * from.x, q->y);
        sum.add_product(-sign * to.y, q->x);
        sum.add_product(sign * from.y, q->x);
    }
    return sum.sign();
}

/// The exact sign of d . ((a - v) - (a2 - v2)) for d = to - from, all
/// finite doubles as given: 0 when the offsets a - v and a2 - v2 reach as
/// far along d. Two shared vertices (a = v and a2 = v2: both offsets 0)
/// give 0 at once. When d, the offsets and their difference g are doubles
/// (exact_difference), d . g as the orientation of 0, d and g turned a
/// quarter (orientation_of_doubles); else in double words when their bound
/// settles it; else its sixteen products summed exactly.
inline int exact_offsets_along(const point<double>& from, const point<double>& to, const point<double>& a,
                               const point<double>& v, const point<double>& a2, const point<double>& v2) {
    if (a == v && a2 == v2) return 0;
    point<double> d, o, o2, g;
    if (exact_difference(to, from, d) && exact_difference(a, v, o) && exact_difference(a2, v2, o2) &&
        exact_difference(o, o2, g))
        return orientation_of_doubles(0, 0, d.x, d.y, -g.y, g.x);  // d . g = d x (-g.y, g.x)
    const double_word dx = double_word(to.x) - double_word(from.x), dy = double_word(to.y) - double_word(from.y);
    const double_word gx = (double_word(a.x) - double_word(v.x)) - (double_word(a2.x) - double_word(v2.x)),
                      gy = (double_word(a.y) - double_word(v.y)) - (double_word(a2.y) - double_word(v2.y));
    if (int sign = 0; (dx * gx + dy * gy).try_sign(sign)) return sign;
    exact_sum::accumulator sum;
    for (const auto& [q, sign] : {std::pair<const point<double>*, double>{&a, 1}, {&v, -1}, {&a2, -1}, {&v2, 1}}) {
        sum.add_product(sign * to.x, q->x);
        sum.add_product(-sign * from.x, q->x);
        sum.add_product(sign * to.y, q->y);
        sum.add_product(-sign * from.y, q->y);
    }
    return sum.sign();
}

/// Whether a - v = a2 - v2 exactly, all finite doubles as given: two pairs
/// of points with one offset (the same distance, whatever translation t
/// moves v and v2 by). When the offsets are doubles (exact_difference),
/// compared as doubles; else each coordinate's four terms summed exactly.
inline bool same_offset(const point<double>& a, const point<double>& v, const point<double>& a2,
                        const point<double>& v2) {
    point<double> o, o2;
    if (exact_difference(a, v, o) && exact_difference(a2, v2, o2)) return o.x == o2.x && o.y == o2.y;
    exact_sum::accumulator x, y;
    for (const auto& [q, sign] : {std::pair<const point<double>*, double>{&a, 1}, {&v, -1}, {&a2, -1}, {&v2, 1}}) {
        x.add(sign * q->x);
        y.add(sign * q->y);
    }
    return x.sign() == 0 && y.sign() == 0;
}

/// Whether q lies on the closed segment [a, b] (exact).
inline bool on_segment_exactly(const point<double>& q, const point<double>& a, const point<double>& b) {
    return exact_orientation(a, b, q) == 0 && within_collinear_segment(q, a, b);
}

/// Whether the closed segments [a, b] and [c, d] meet (exact); a segment of
/// length 0 is its point.
inline bool segments_meet_exactly(const point<double>& a, const point<double>& b, const point<double>& c,
                                  const point<double>& d) {
    if (a == b) return on_segment_exactly(a, c, d);
    if (c == d) return on_segment_exactly(c, a, b);
    const int oc = exact_orientation(a, b, c), od = exact_orientation(a, b, d);
    if (oc == 0 && od == 0)
        return within_collinear_segment(c, a, b) || within_collinear_segment(d, a, b) ||
               within_collinear_segment(a, c, d) || within_collinear_segment(b, c, d);
    return oc * od <= 0 && exact_orientation(c, d, a) * exact_orientation(c, d, b) <= 0;
}

/// The winding number of a closed ring around q, as the ring is given (exact:
/// crossings of the ray from q towards +x, upward edges with q on their left
/// +1, downward edges with q on their right -1); empty when q lies on the ring.
inline std::optional<int> exact_winding(const point<double>& q, const std::vector<point<double>>& ring) {
    int w = 0;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const point<double>& a = ring[i];
        const point<double>& b = ring[(i + 1) % n];
        if (on_segment_exactly(q, a, b)) return std::nullopt;
        if (a.y <= q.y) {
            if (b.y > q.y && exact_orientation(a, b, q) > 0) ++w;
        } else if (b.y <= q.y && exact_orientation(a, b, q) < 0) {
            --w;
        }
    }
    return w;
}

}  // namespace influence2d
