// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Distances between points and closed segments: the exact squared distances
/// and closest points in a field NT (the decisions: every sign through
/// number_traits, directly or through orientation() and compare_values()),
/// the rounding of an exact value to the nearest double, and the bounds in
/// double that the separation query's search prunes with (filters, each
/// constant with its derivation). docs/separation.md says how they combine.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/exact_doubles.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/predicates/segments.hpp"

namespace influence2d {

// ---------------------------------------------------------------------------
// Exact values (decisions)
// ---------------------------------------------------------------------------

/// Where on a segment [a, b] a point lies: at a, at b, or strictly between.
enum class segment_part : std::uint8_t {
    start,    ///< the segment's first end a (also the point of a zero-length segment)
    end,      ///< its second end b
    interior  ///< strictly between a and b
};

/// The point of a closed segment nearest to a given point, and their squared
/// distance.
template <class NT>
struct segment_point {
    NT squared{};                             ///< the squared distance
    point<NT> at;                             ///< the nearest point of the segment
    segment_part part = segment_part::start;  ///< where `at` lies on the segment
};

namespace distance_detail {

/// The foot a + (t / L) ab of a point on the line of [a, b] and its squared
/// distance (ab x ap)^2 / L, for ab = b - a, ap = p - a, t = ab.ap and
/// L = |ab|^2 > 0.
template <class NT>
segment_point<NT> foot(const point<NT>& a, const NT& abx, const NT& aby, const NT& apx, const NT& apy, const NT& t,
                       const NT& length2) {
    const NT cross = abx * apy - aby * apx;
    const NT f = t / length2;
    return {NT(cross * cross / length2), point<NT>{NT(a.x + f * abx), NT(a.y + f * aby)}, segment_part::interior};
}

}  // namespace distance_detail

/// The point of the closed segment [a, b] nearest to p, with t = (b - a).(p - a)
/// and L = |b - a|^2: a when t <= 0 or L = 0 (a zero-length segment is the
/// point a), b when t >= L, else a + (t / L)(b - a), at squared distance
/// ((b - a) x (p - a))^2 / L. Three signs taken by number_traits; one
/// division. Exact in an exact field NT (exact_rational): the squared distance
/// and the point are the true ones; rounded in a floating NT.
template <class NT>
segment_point<NT> closest_on_segment(const point<NT>& p, const point<NT>& a, const point<NT>& b) {
    using tr = number_traits<NT>;
    const NT abx = b.x - a.x, aby = b.y - a.y;
    const NT apx = p.x - a.x, apy = p.y - a.y;
    const NT t = abx * apx + aby * apy;
    const NT length2 = abx * abx + aby * aby;
    if (tr::sign(length2) == 0 || tr::sign(t) <= 0) return {NT(apx * apx + apy * apy), a, segment_part::start};
    if (compare_values(t, length2) >= 0) {
        const NT bpx = p.x - b.x, bpy = p.y - b.y;
        return {NT(bpx * bpx + bpy * bpy), b, segment_part::end};
    }
    return distance_detail::foot(a, abx, aby, apx, apy, t, length2);
}

/// The point of [a, b] nearest to p when it lies strictly inside the segment
/// (closest_on_segment's interior case, 0 < t < L, which the caller knows):
/// a + (t / L)(b - a), at squared distance ((b - a) x (p - a))^2 / L; one
/// division, no sign.
template <class NT>
segment_point<NT> foot_inside(const point<NT>& p, const point<NT>& a, const point<NT>& b) {
    const NT abx = b.x - a.x, aby = b.y - a.y;
    const NT apx = p.x - a.x, apy = p.y - a.y;
    return distance_detail::foot(a, abx, aby, apx, apy, NT(abx * apx + aby * apy), NT(abx * abx + aby * aby));
}

/// Squared distance between two NT points.
template <class NT>
NT squared_distance(const point<NT>& a, const point<NT>& b) {
    const NT dx = a.x - b.x, dy = a.y - b.y;
    return dx * dx + dy * dy;
}

/// The squared distance from p to the closed segment [a, b] (closest_on_segment).
template <class NT>
NT point_segment_squared_distance(const point<NT>& p, const point<NT>& a, const point<NT>& b) {
    return closest_on_segment(p, a, b).squared;
}

/// The sign of d1 - d2 for two squared distances (compare_values): which of
/// two pairs is nearer.
template <class NT>
int compare_squared(const NT& d1, const NT& d2) {
    return compare_values(d1, d2);
}

/// Whether a squared distance is 0: the two sets meet (the sign of the value,
/// by number_traits).
template <class NT>
bool at_contact(const NT& squared) {
    return number_traits<NT>::sign(squared) == 0;
}

/// Whether q lies strictly beyond p along the direction d: (q - p).d > 0,
/// the sign by number_traits.
template <class NT>
bool strictly_beyond(const point<NT>& p, const point<NT>& q, const point<NT>& d) {
    return number_traits<NT>::sign(NT(NT(q.x - p.x) * d.x + NT(q.y - p.y) * d.y)) > 0;
}

/// Where a point lies on [a, b], given that it lies on it: start when it is
/// a, end when it is b (and not a), else interior. Exact when NT is.
template <class NT>
segment_part part_of(const point<NT>& x, const point<NT>& a, const point<NT>& b) {
    if (same_point(x, a)) return segment_part::start;
    if (same_point(x, b)) return segment_part::end;
    return segment_part::interior;
}

/// The closest points of two closed segments and their squared distance.
template <class NT>
struct segment_pair_closest {
    NT squared{};         ///< the squared distance; 0 when the segments meet
    point<NT> on_first;   ///< the point of the first segment (the common point when they meet)
    point<NT> on_second;  ///< the point of the second segment (equal to on_first when they meet)
    segment_part first_part = segment_part::start;   ///< where on_first lies on the first segment
    segment_part second_part = segment_part::start;  ///< where on_second lies on the second segment
};

namespace distance_detail {

/// The point where [u, v] crosses the line of [a, b], for u and v strictly
/// on either side of it: u + (c_u / (c_u - c_v))(v - u), c_u = (b - a) x
/// (u - a), c_v = (b - a) x (v - a).
template <class NT>
point<NT> crossing(const point<NT>& a, const point<NT>& b, const point<NT>& u, const point<NT>& v) {
    const NT abx = b.x - a.x, aby = b.y - a.y;
    const NT cu = abx * (u.y - a.y) - aby * (u.x - a.x);
    const NT cv = abx * (v.y - a.y) - aby * (v.x - a.x);
    const NT f = cu / (cu - cv);
    return {NT(u.x + f * (v.x - u.x)), NT(u.y + f * (v.y - u.y))};
}

/// The common point of [a, b] and [u, v], which meet (ou, ov: the
/// orientations of u and v against [a, b]); see closest_between_segments.
template <class NT>
segment_pair_closest<NT> meeting_point(const point<NT>& a, const point<NT>& b, const point<NT>& u, const point<NT>& v,
                                       int ou, int ov) {
    point<NT> x;
    if (ou == 0 && ov == 0) {
        // Collinear (or a == b): one of the four ends lies on the other segment.
        x = on_segment(a, u, v) ? a : on_segment(b, u, v) ? b : on_segment(u, a, b) ? u : v;
    } else if (ou == 0 || ov == 0) {
        x = ou == 0 ? u : v;  // the one point of [u, v] on the line of [a, b]
    } else {
        const int oa = orientation(u, v, a), ob = orientation(u, v, b);
        x = oa == 0 ? a : ob == 0 ? b : crossing(a, b, u, v);
    }
    return {number_traits<NT>::from_double(0), x, x, part_of(x, a, b), part_of(x, u, v)};
}

/// The part of [a, b] its second end b is: end, or start when the segment
/// has length 0 (b is a). Exact when NT is; b is never compared with itself.
template <class NT>
segment_part end_part(const point<NT>& a, const point<NT>& b) {
    return same_point(b, a) ? segment_part::start : segment_part::end;
}

/// The end-to-segment candidate k of [a, b] and [u, v] (0: a to [u, v], 1:
/// b to [u, v], 2: u to [a, b], 3: v to [a, b]): that end, the nearest point
/// of the other segment (closest_on_segment), their squared distance and
/// where both points lie.
template <class NT>
segment_pair_closest<NT> end_candidate(int k, const point<NT>& a, const point<NT>& b, const point<NT>& u,
                                       const point<NT>& v) {
    const point<NT>& p = k == 0 ? a : k == 1 ? b : k == 2 ? u : v;
    segment_point<NT> c = k < 2 ? closest_on_segment(p, u, v) : closest_on_segment(p, a, b);
    const segment_part first = k == 0 ? segment_part::start : k == 1 ? end_part(a, b) : c.part;
    const segment_part second = k == 2 ? segment_part::start : k == 3 ? end_part(u, v) : c.part;
    if (k < 2) return {std::move(c.squared), p, std::move(c.at), first, second};
    return {std::move(c.squared), std::move(c.at), p, first, second};
}

/// For [a, b] and [u, v] that do not meet: the least of the end-to-segment
/// candidates k (end_candidate) for which may_be_least(k), the first of them
/// on a tie. A candidate left out must not be the least nor tie with it. Two
/// candidates whose closest points are the same parts of both segments (a to
/// u found from a and from u) join the same points: their distances are
/// equal without comparing them, and the first is kept (a filtered NT could
/// not tell two equal values apart).
template <class NT, class MayBeLeast>
segment_pair_closest<NT> least_end_distance(const point<NT>& a, const point<NT>& b, const point<NT>& u,
                                            const point<NT>& v, MayBeLeast&& may_be_least) {
    segment_pair_closest<NT> best;
    bool found = false;
    for (int k = 0; k < 4; ++k) {
        if (!may_be_least(k)) continue;
        segment_pair_closest<NT> c = end_candidate(k, a, b, u, v);
        if (found && ((c.first_part == best.first_part && c.second_part == best.second_part &&
                       c.first_part != segment_part::interior && c.second_part != segment_part::interior) ||
                      compare_squared(c.squared, best.squared) >= 0))
            continue;
        found = true;
        best = std::move(c);
    }
    return best;
}

}  // namespace distance_detail

/// A closest pair of points of the closed segments [a, b] and [u, v]
/// (zero-length segments allowed), in a field NT.
///
/// When they meet (segments_intersect), the squared distance is 0 and the
/// point is a common one: for collinear segments the first of a, b, u, v that
/// lies on the other segment; when u (or v) lies on the line of [a, b], u
/// (or v); when a (or b) lies on the line of [u, v], a (or b); otherwise the
/// crossing u + (c_u / (c_u - c_v))(v - u) with c_u = (b - a) x (u - a) and
/// c_v = (b - a) x (v - a), of opposite signs. A common point is a vertex of
/// one of the segments or their crossing: rational in the coordinates.
///
/// When they do not meet, the distance is attained at an end of one of them:
/// the least of closest_on_segment(a; u, v), (b; u, v), (u; a, b), (v; a, b),
/// the first of these on a tie. Exact (the distance, the points and their
/// parts) in an exact field NT.
template <class NT>
segment_pair_closest<NT> closest_between_segments(const point<NT>& a, const point<NT>& b, const point<NT>& u,
                                                  const point<NT>& v) {
    const int ou = orientation(a, b, u), ov = orientation(a, b, v);
    if (segments_intersect(ou, ov, a, b, u, v)) return distance_detail::meeting_point(a, b, u, v, ou, ov);
    return distance_detail::least_end_distance(a, b, u, v, [](int) { return true; });
}

/// The squared distance between the closed segments [a, b] and [u, v]
/// (closest_between_segments): 0 when they meet.
template <class NT>
NT segment_squared_distance(const point<NT>& a, const point<NT>& b, const point<NT>& u, const point<NT>& v) {
    return closest_between_segments(a, b, u, v).squared;
}

// ---------------------------------------------------------------------------
// Rounding an exact value to double
// ---------------------------------------------------------------------------

/// scaled_nearest's window for the double y: [1 / nearest_window,
/// nearest_window], where y, its neighbours and half their gap are normal
/// doubles.
inline constexpr double nearest_window = 0x1p900;
/// scaled_nearest's step towards that window, 2^nearest_step_bits, a power
/// of two by which NT scales exactly: eight steps reach the window from any
/// squared distance of doubles (2^-2148 to 2^2050), and a step from outside
/// never overshoots it (2^600 is below the window's width, 2^1800).
inline constexpr int nearest_step_bits = 600;
/// The same step as a double: 2^nearest_step_bits.
inline constexpr double nearest_step = 0x1p600;

/// A double and a power of two: the value y * 2^exponent.
struct scaled_double {
    double mantissa = 0;  ///< y, a double of magnitude in [1 / nearest_window, nearest_window] (or 0)
    int exponent = 0;     ///< an even power of two (a multiple of nearest_step_bits)
};

/// For x >= 0 in an exact NT: x = y 2^k, k a multiple of nearest_step_bits
/// (even), with y the double nearest to x 2^-k (ties to even), y in
/// [1 / nearest_window, nearest_window] or 0.
/// Scaling by powers of two is exact in NT, so the only rounding is the
/// nearest one of a value in double's normal range, whatever the magnitude of
/// x (a squared distance of doubles lies between 2^-2148 and 2^2050).
/// number_traits::to_double must give a double d within a few units in the
/// last place of the value (CGAL's rationals do: within one); the nearest is
/// then found by exact signs: the offset x 2^-k - d against half the gap to
/// the neighbour on its side (a power of two), one subtraction and one
/// comparison a step, no division.
template <class NT>
scaled_double scaled_nearest(const NT& x) {
    using tr = number_traits<NT>;
    if (at_contact(x)) return {};
    NT y = x;
    int k = 0;
    double d = tr::to_double(y);
    for (int step = 0; step < 8 && !(d >= 1 / nearest_window); ++step) {
        y = NT(y * tr::from_double(nearest_step));
        k -= nearest_step_bits;
        d = tr::to_double(y);
    }
    for (int step = 0; step < 8 && !(d <= nearest_window); ++step) {
        y = NT(y * tr::from_double(1 / nearest_step));
        k += nearest_step_bits;
        d = tr::to_double(y);
    }
    const auto odd = [](double value) {
        std::uint64_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        return (bits & 1) != 0;
    };
    for (int step = 0; step < 64; ++step) {
        const NT offset = y - tr::from_double(d);
        const int side = tr::sign(offset);
        if (side == 0) break;
        const double neighbour = std::nextafter(d, side > 0 ? HUGE_VAL : 0.0);
        const double half = (neighbour - d) / 2;  // exact: a power of two
        const int beyond = compare_values<NT>(offset, tr::from_double(half)) * side;
        if (beyond < 0 || (beyond == 0 && !odd(d))) break;
        d = neighbour;
    }
    return {d, k};
}

/// The double nearest to x in an exact NT (ties to even; in double's
/// subnormal range, within one unit of the last place), its sign included:
/// scaled_nearest of |x|, scaled back. Beyond double's range, infinity.
template <class NT>
double nearest_double(const NT& x) {
    using tr = number_traits<NT>;
    const int s = tr::sign(x);
    const scaled_double r = scaled_nearest<NT>(s < 0 ? NT(tr::from_double(0) - x) : x);
    return std::ldexp(s < 0 ? -r.mantissa : r.mantissa, r.exponent);
}

// ---------------------------------------------------------------------------
// Bounds in double (filters)
// ---------------------------------------------------------------------------

/// The relative bound of posing_error. A coordinate posed in double,
/// x = fl(fl(fl(c qx) - fl(s qy)) + tx), |c|, |s| <= 1, errs from
/// c qx - s qy + tx (the exact pose with the same doubles c and s) by at most
/// u |c qx| + u |s qy| (the products), u (1 + u)(|c qx| + |s qy|) (the
/// difference) and u (1 + u)^2 (|c qx| + |s qy| + |tx|) (the sum), u = 2^-53:
/// below 3.01 u (|qx| + |qy|) + 1.01 u |tx| <= 6.02 u scale + 1.01 u |tx| for
/// |qx|, |qy| <= scale. 2^-50 = 8u times (scale + |tx| + |ty|) covers it and
/// the two roundings of that sum (a fused multiply-add rounds once: less).
inline constexpr double pose_rounding = 0x1p-50;
/// What underflow may add to posing_error: each of the two products may lose
/// 2^-1075 when subnormal (sums of subnormals are exact).
inline constexpr double pose_underflow = 0x1p-1072;

/// A bound, per coordinate, of the distance between a point of B (a vertex,
/// or any point of its box: a node centre of its edge tree) posed in double by
/// rotation_pose::apply<double> and the same point posed exactly, for B's
/// largest absolute coordinate `moving_scale` and the translation (tx, ty).
/// See pose_rounding.
inline double posing_error(double moving_scale, double tx, double ty) {
    return pose_rounding * (moving_scale + std::fabs(tx) + std::fabs(ty)) + pose_underflow;
}

/// A posed point within e of its exact place on each coordinate is within
/// e sqrt 2 of it; 1.5 > sqrt 2 covers that and the rounding of 1.5 e.
inline constexpr double posing_spread = 1.5;

/// The relative bound of point_segment_estimate, on |ap|_1 + |ab|_1 (u =
/// 2^-53). With the differences ab = b - a, ap = p - a rounded once each
/// (relative u), t~ the computed (clamped) fraction and r = ap - t~ ab (exact
/// differences), q = a + t~ (b - a) is a point of the segment:
///   - the value: r~ = fl(ap~ - fl(t~ ab~)) errs from r by at most
///     u |ap| + 2.01 u |ab| + u |r~| per coordinate (t~ <= 1), and
///     filter_length adds 2.01 u |r~|; with |r|_1 <= |ap|_1 + |ab|_1, the value
///     is within E1 = 4.03 u |ap|_1 + 5.04 u |ab|_1 of |p - q|;
///   - the fraction: the dot product and |ab|^2 carry relative errors below
///     4.01 u, so t~ (before clamping) errs from t0 = ab.ap / |ab|^2 by at
///     most 5.01 u |ap| / |ab| + 12.01 u |t0| / 2 for |t0| <= 2 (beyond 2 both
///     clamp to the same end); clamping is 1-Lipschitz, so
///     |q - q*| <= Delta = 5.01 u |ap| + 12.01 u |ab| for the nearest point q*;
///   - the distance D = |p - q*| <= |p - q| <= D + Delta.
/// In all |value - D| <= E1 + Delta < 18 u (|ap|_1 + |ab|_1) < 2^-48 (...).
/// 2^-47 doubles that for the rounding of the bound itself. Underflow: the
/// differences are first brought to magnitudes within [2^-200, 2^200] (an
/// exact scaling by a power of two when they are not), where a lost
/// subnormal bit is below 2^-470 of the largest difference, far inside the
/// room left; an edge shorter than degenerate_edge_share of the largest
/// difference is taken as its end a, adding its length |ab|_1 to the bound.
inline constexpr double point_segment_rounding = 0x1p-47;
/// See point_segment_rounding: differences whose largest magnitude lies
/// outside [1 / point_segment_window, point_segment_window] are first scaled
/// into it by a power of two, so that their squares and products stay far
/// inside double's normal range.
inline constexpr double point_segment_window = 0x1p200;
/// See point_segment_rounding: below this share of the largest difference,
/// |ab|^2 might underflow; the edge is taken as the point a.
inline constexpr double degenerate_edge_share = 0x1p-100;

/// A value in double with a bound of its distance to the exact one.
struct estimate {
    double value = 0;  ///< the value computed in double
    double error = 0;  ///< bounds |value - exact| (infinity: nothing known)
};

/// The distance from p to the closed segment [a, b], every point an exact
/// double, computed in double, with a proven bound of its error (see
/// point_segment_rounding). A difference that overflows gives value 0 and an
/// infinite error.
inline estimate point_segment_estimate(const point<double>& p, const point<double>& a, const point<double>& b) {
    double abx = b.x - a.x, aby = b.y - a.y, apx = p.x - a.x, apy = p.y - a.y;
    // (Not finite, or so large that their sum overflows: nothing known.)
    if (!std::isfinite(abx + aby + apx + apy)) return {0, HUGE_VAL};
    const double big = std::max({std::fabs(abx), std::fabs(aby), std::fabs(apx), std::fabs(apy)});
    if (big == 0) return {0, 0};  // (a difference of doubles is 0 only when they are equal)
    int e = 0;
    if (!(big >= 1 / point_segment_window && big <= point_segment_window)) {
        e = std::ilogb(big);
        abx = std::ldexp(abx, -e), aby = std::ldexp(aby, -e), apx = std::ldexp(apx, -e), apy = std::ldexp(apy, -e);
    }
    const double ab1 = std::fabs(abx) + std::fabs(aby), ap1 = std::fabs(apx) + std::fabs(apy);
    double t = 0, extra = 0;
    if (ab1 < degenerate_edge_share * std::max(ab1, ap1)) {
        extra = ab1;
    } else {
        t = (abx * apx + aby * apy) / (abx * abx + aby * aby);
        t = std::min(1.0, std::max(0.0, t));
    }
    const double d = filter_length(apx - t * abx, apy - t * aby);
    const double error = point_segment_rounding * (ab1 + ap1) + extra;
    if (e == 0) return {d, error};
    return {std::ldexp(d, e), std::ldexp(error, e)};
}

/// The relative widening of the sums and differences that turn estimates into
/// the bounds of segment_distance_range and node_gap_lower: each of them
/// rounds a few times (relative u = 2^-53 each); 2^-50 = 8u covers them.
inline constexpr double bound_rounding = 0x1p-50;

/// A lower and an upper bound of a distance.
struct distance_range {
    double lower = 0;         ///< at most the distance
    double upper = HUGE_VAL;  ///< at least the distance
};

/// Bounds of the distance between the closed segment [a, b] (exact doubles)
/// and a segment whose exact ends lie within `delta` per coordinate of u and
/// v (B's edge, posed in double; delta from posing_error).
///
/// Write D for the distance to the exact segment and D~ for the distance
/// between [a, b] and [u, v] as doubles. Moving each end by at most
/// delta sqrt 2 moves every point of a segment by at most that (a convex
/// combination), so |D - D~| <= delta sqrt 2 < posing_spread delta. D~ is at
/// most each of the four end-to-segment distances m_k (point_segment_estimate,
/// within error E_k), and equal to their least when the segments do not meet:
///   - upper: min_k m_k + max_k E_k + 1.5 delta; and when [u, v] certainly
///     crosses [a, b] (certain_side on both lines, exact signs of the double
///     points), D~ = 0 and the upper bound is 1.5 delta;
///   - lower: when the double segments certainly do not meet
///     (segments_may_meet with no margin is false), min_k m_k - max_k E_k -
///     1.5 delta; otherwise the gap between their boxes (a distance is at least
///     its projection on an axis) less 1.5 delta; never below 0.
/// Every bound is widened by bound_rounding for its own rounding.
inline distance_range segment_distance_range(const point<double>& a, const point<double>& b, const point<double>& u,
                                             const point<double>& v, double delta) {
    // (A posed end beyond double's range: nothing known.)
    if (!std::isfinite(u.x + u.y + v.x + v.y)) return {};
    const double spread = posing_spread * delta * (1 + bound_rounding);
    // Certain crossing of the double segments: D~ = 0.
    const double dx = b.x - a.x, dy = b.y - a.y;
    const int su = certain_side(a, dx, dy, u, 0), sv = certain_side(a, dx, dy, v, 0);
    if (su != 0 && sv == -su) {
        const double ex = v.x - u.x, ey = v.y - u.y;
        const int sa = certain_side(u, ex, ey, a, 0), sb = certain_side(u, ex, ey, b, 0);
        if (sa != 0 && sb == -sa) return {0, spread};
    }
    const estimate ms[4] = {point_segment_estimate(a, u, v), point_segment_estimate(b, u, v),
                            point_segment_estimate(u, a, b), point_segment_estimate(v, a, b)};
    double least = ms[0].value, error = ms[0].error;
    for (const estimate& m : ms) {
        least = std::min(least, m.value);
        error = std::max(error, m.error);
    }
    distance_range r;
    r.upper = (least + error) * (1 + bound_rounding) + spread;
    double lower;
    if (!segments_may_meet(a, b, u, v, 0)) {
        lower = least * (1 - bound_rounding) - error * (1 + bound_rounding);
    } else {
        const double gx =
            std::max({0.0, std::min(u.x, v.x) - std::max(a.x, b.x), std::min(a.x, b.x) - std::max(u.x, v.x)});
        const double gy =
            std::max({0.0, std::min(u.y, v.y) - std::max(a.y, b.y), std::min(a.y, b.y) - std::max(u.y, v.y)});
        lower = std::max(gx, gy) * (1 - bound_rounding);
    }
    lower -= spread;
    // (NaN: nothing known.)
    r.lower = lower > 0 ? lower : 0;
    if (!(r.upper >= 0)) r.upper = HUGE_VAL;
    return r;
}

/// Whether [a, b] (exact doubles) and every segment whose ends lie within
/// `delta` per coordinate of the doubles u and v (B's edge, posed) are
/// certainly farther apart than `upper`, by a line that separates them:
/// segments_may_meet with the margin e = (upper + s) / 2 (1 + bound_rounding),
/// s = posing_spread delta (1 + bound_rounding). segments_may_meet is false
/// when both ends of one segment lie on one side of the other's line by an
/// exact cross product above its slack 2e |d|_1 as computed (certain_side
/// bounds the product's own rounding, the direction d's included), which is
/// at least 2e |d| (1 - u)^3 since |d|_1 >= |d|: both ends then lie farther
/// than 2e (1 - u)^3 >= (upper + s)(1 + 8u)(1 - u)^4 >= upper + s from that
/// line (the sum and the halving round once more). So [a, b] and [u, v] lie
/// farther apart than upper + s, and a segment whose ends lie within
/// delta sqrt 2 < s of u and v farther than upper. False when the bounds
/// cannot tell, and for a pair whose ends lie on both sides of each line
/// (a crossing), whatever upper.
inline bool segments_apart_beyond(const point<double>& a, const point<double>& b, const point<double>& u,
                                  const point<double>& v, double upper, double delta) {
    const double spread = posing_spread * delta * (1 + bound_rounding);
    return !segments_may_meet(a, b, u, v, 0.5 * (upper + spread) * (1 + bound_rounding));
}

/// Whether [a, b] (exact doubles) and the exact segment [U, V], whose ends
/// lie within `delta` per coordinate of the doubles u and v, certainly cross
/// at one point strictly inside both:
///   - U and V lie strictly on either side of the line through a and b: u
///     and v do, farther from it than 2 delta > delta sqrt 2 (certain_side
///     with slack 2 delta |b - a|_1 >= 2 delta |b - a|);
///   - a and b lie strictly on either side of the line through U and V: for
///     p = a or b, (V - U) x (p - U) differs from (v - u) x (p - u) by at
///     most |e_v - e_u| |p - u| + |v - u| |e_u| + |e_v - e_u| |e_u| <=
///     2 sqrt 2 delta |p - u| + sqrt 2 delta |v - u| + 4 delta^2 (|e| <=
///     delta sqrt 2 for each end's error e), below the slack
///     delta (3 |p - u|_1 + 2 |v - u|_1) + 4 delta^2, widened by
///     bound_rounding for its own rounding.
/// False whenever the bounds cannot tell.
inline bool segments_must_cross(const point<double>& a, const point<double>& b, const point<double>& u,
                                const point<double>& v, double delta) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double line_slack = 2 * delta * (std::fabs(dx) + std::fabs(dy)) * (1 + bound_rounding);
    const int su = certain_side(a, dx, dy, u, line_slack);
    if (su == 0 || certain_side(a, dx, dy, v, line_slack) != -su) return false;
    const double ex = v.x - u.x, ey = v.y - u.y, e1 = std::fabs(ex) + std::fabs(ey);
    const auto slack = [&](const point<double>& p) {
        return (delta * (3 * (std::fabs(p.x - u.x) + std::fabs(p.y - u.y)) + 2 * e1) + 4 * delta * delta) *
               (1 + bound_rounding);
    };
    const int sa = certain_side(u, ex, ey, a, slack(a));
    return sa != 0 && certain_side(u, ex, ey, b, slack(b)) == -sa;
}

/// closest_between_segments of [A, B] and [U, V] known to cross at one
/// point strictly inside both (segments_must_cross held for their doubles):
/// that point, distance_detail's crossing, at distance 0, with no sign
/// evaluated in NT.
template <class NT>
segment_pair_closest<NT> crossing_closest(const point<NT>& A, const point<NT>& B, const point<NT>& U,
                                          const point<NT>& V) {
    const point<NT> x = distance_detail::crossing(A, B, U, V);
    return {number_traits<NT>::from_double(0), x, x, segment_part::interior, segment_part::interior};
}

/// Bounds of the four end-to-segment distances of [a, b] (exact doubles)
/// and the exact segment within `delta` per coordinate of [u, v] (in
/// end_candidate's order): each point_segment_estimate less or plus its error
/// and posing_spread delta, widened by bound_rounding; and `cut`, the least
/// upper bound. A candidate whose lower bound exceeds the cut is neither the
/// least nor tied with it.
struct end_bounds {
    double lower[4];        ///< at most candidate k's distance
    double upper[4];        ///< at least candidate k's distance
    double cut = HUGE_VAL;  ///< the least upper bound

    /// The bounds of [a, b] and [u, v].
    end_bounds(const point<double>& a, const point<double>& b, const point<double>& u, const point<double>& v,
               double delta) {
        const estimate ms[4] = {point_segment_estimate(a, u, v), point_segment_estimate(b, u, v),
                                point_segment_estimate(u, a, b), point_segment_estimate(v, a, b)};
        const double spread = posing_spread * delta * (1 + bound_rounding);
        for (int k = 0; k < 4; ++k) {
            lower[k] = ms[k].value * (1 - bound_rounding) - ms[k].error * (1 + bound_rounding) - spread;
            upper[k] = (ms[k].value + ms[k].error) * (1 + bound_rounding) + spread;
            cut = std::min(cut, upper[k]);
        }
    }
    /// Whether candidate k may be the least (also for NaN bounds).
    bool may_be_least(int k) const { return !(lower[k] > cut); }
};

/// closest_between_segments of A, B (exact doubles a, b in NT) and U, V (in
/// NT, within `delta` per coordinate of the doubles u, v: B's edge posed
/// exactly and in double), with the same answer at less cost in an exact NT:
/// segments that certainly cross (segments_must_cross) meet at their
/// crossing, strictly inside both, with no sign evaluated in NT; when
/// segments_may_meet(a, b, u, v, delta) is false the exact segments do
/// not meet, and an end-to-segment candidate whose lower bound (its
/// point_segment_estimate on the doubles, less its error and posing_spread
/// delta) exceeds another's upper bound is neither the least nor tied with
/// it, so it is not evaluated in NT. Otherwise, closest_between_segments.
template <class NT>
segment_pair_closest<NT> closest_between_segments(const point<double>& a, const point<double>& b,
                                                  const point<double>& u, const point<double>& v, double delta,
                                                  const point<NT>& A, const point<NT>& B, const point<NT>& U,
                                                  const point<NT>& V) {
    if (segments_must_cross(a, b, u, v, delta)) return crossing_closest(A, B, U, V);
    if (segments_may_meet(a, b, u, v, delta)) return closest_between_segments(A, B, U, V);
    const end_bounds bounds(a, b, u, v, delta);
    return distance_detail::least_end_distance(A, B, U, V, [&](int k) { return bounds.may_be_least(k); });
}

/// Where the point of the exact segment [A, B] nearest to the exact point P
/// lies (closest_on_segment's part), when the doubles p, a, b, each within e
/// of P, A, B on each coordinate, settle it: start when (B - A).(P - A) < 0,
/// end when (B - A).(P - B) > 0, interior when both signs are certainly the
/// other (certain_ahead_within); nothing when a sign is in doubt, as for a
/// projection on an end. (A sign settled nonzero also settles B != A.)
inline std::optional<segment_part> settled_part(const point<double>& p, const point<double>& a, const point<double>& b,
                                                double e) {
    const int from_start = certain_ahead_within(a, b, p, e);
    if (from_start < 0) return segment_part::start;
    if (from_start == 0) return std::nullopt;
    const int from_end = -certain_ahead_within(b, a, p, e);  // the sign of (B - A).(P - B)
    if (from_end > 0) return segment_part::end;
    if (from_end == 0) return std::nullopt;
    return segment_part::interior;
}

/// closest_on_segment's part for a point and a segment one of which is
/// translated by t (B's, when its pose is a translation), decided exactly
/// on the doubles as given: A's point p against B's segment [u + t, v + t]
/// (`moving_segment`), or B's point p + t against A's segment [u, v].
/// Start when (V - U).(P - U) <= 0, end when (V - U).(P - V) >= 0, else
/// interior (exact_offsets_along: a translation keeps V - U, and P - U is
/// p - u less or plus t).
inline segment_part translated_part(const point<double>& p, const point<double>& u, const point<double>& v,
                                    const point<double>& t, bool moving_segment) {
    const point<double> origin{0, 0};
    const auto ahead_of = [&](const point<double>& end) {  // the sign of (V - U).(P - end)
        return moving_segment ? exact_offsets_along(u, v, p, end, t, origin)
                              : -exact_offsets_along(u, v, end, p, t, origin);
    };
    if (ahead_of(u) <= 0) return segment_part::start;
    if (ahead_of(v) >= 0) return segment_part::end;
    return segment_part::interior;
}

/// The closest points of two segments apart, settled in double: where the
/// two points closest_between_segments picks lie, and bounds of the distance.
struct settled_closest {
    segment_part first_part = segment_part::start;   ///< where the point of the first segment lies
    segment_part second_part = segment_part::start;  ///< where the point of the second segment lies
    double lower = 0;                                ///< at most the distance
    double upper = HUGE_VAL;                         ///< at least the distance
};

/// closest_between_segments of [a, b] (exact doubles) and the exact segment
/// [U, V] (within `delta` per coordinate of the doubles u, v; U = V only when
/// u = v, as for B's edge posed exactly and in double) decided in double,
/// or nothing when the bounds cannot decide it. Settled when:
///   - the segments are certainly apart (segments_may_meet false), so the
///     distance is the least end-to-segment candidate's;
///   - among the candidates that may be least (each one's bounds from its
///     point_segment_estimate, as in the filtered closest_between_segments),
///     every one has its parts settled (settled_part; the end part of
///     [u, v] needs u != v), and either every other one has the first one's
///     parts, neither an interior (the same two points, at the same
///     distance, which the first of them wins: least_end_distance), or the
///     segments are exactly parallel (exactly_parallel(), asked only then)
///     and one of them has a part inside a segment: the first such one wins.
///     An end whose foot lies inside the other segment is at the distance
///     between the two parallel lines, the least any two points have; an end
///     whose foot lies beyond the other segment (its part there settled as
///     an end) is farther.
/// A part the bounds leave in doubt is asked of `exact_part(k)` when given
/// (candidate k: a, b against [u, v], then u, v against [a, b]; the part
/// decided exactly, or none); and a candidate whose points are both ends,
/// as the first's, counts as the first's when `same_end_distance(first's
/// parts, its parts)` (when given) shows the two distances equal exactly.
/// The bounds are the winner's.
template <class ExactlyParallel, class ExactPart = std::nullptr_t, class SameEndDistance = std::nullptr_t>
std::optional<settled_closest> settled_closest_between(const point<double>& a, const point<double>& b,
                                                       const point<double>& u, const point<double>& v, double delta,
                                                       ExactlyParallel&& exactly_parallel,
                                                       ExactPart exact_part = nullptr,
                                                       SameEndDistance same_end_distance = nullptr) {
    if (segments_may_meet(a, b, u, v, delta)) return std::nullopt;
    const end_bounds bounds(a, b, u, v, delta);
    const auto parts = [&](int k) -> std::optional<std::pair<segment_part, segment_part>> {
        std::optional<segment_part> p =
            k < 2 ? settled_part(k == 0 ? a : b, u, v, delta) : settled_part(k == 2 ? u : v, a, b, delta);
        if constexpr (!std::is_same_v<ExactPart, std::nullptr_t>) {
            if (!p) p = exact_part(k);
        }
        if (!p) return std::nullopt;
        if (k == 0) return std::make_pair(segment_part::start, *p);
        if (k == 1) return std::make_pair(a == b ? segment_part::start : segment_part::end, *p);
        if (k == 2) return std::make_pair(*p, segment_part::start);
        if (u == v) return std::nullopt;
        return std::make_pair(*p, segment_part::end);
    };
    std::optional<settled_closest> first, first_inside;
    bool same_ends = true;  // every candidate after the first has its parts, neither an interior
    for (int k = 0; k < 4; ++k) {
        // (NaN bounds: in doubt.)
        if (!bounds.may_be_least(k)) continue;
        const auto p = parts(k);
        if (!p || !(bounds.upper[k] < HUGE_VAL)) return std::nullopt;
        const settled_closest here{p->first, p->second, std::max(bounds.lower[k], 0.0), bounds.upper[k]};
        const bool inside = p->first == segment_part::interior || p->second == segment_part::interior;
        if (inside && !first_inside) first_inside = here;
        if (!first) {
            first = here;
            continue;
        }
        if (p->first == first->first_part && p->second == first->second_part && !inside) continue;
        // (Other ends at the first's distance exactly: the first wins too.)
        if constexpr (!std::is_same_v<SameEndDistance, std::nullptr_t>) {
            const bool first_inside_parts =
                first->first_part == segment_part::interior || first->second_part == segment_part::interior;
            if (!inside && !first_inside_parts &&
                same_end_distance(std::make_pair(first->first_part, first->second_part), *p))
                continue;
        }
        same_ends = false;
    }
    if (same_ends) return first;
    if (first_inside && a != b && u != v && exactly_parallel()) return first_inside;
    return std::nullopt;
}

/// settled_closest_between with no parallel segments known.
inline std::optional<settled_closest> settled_closest_between(const point<double>& a, const point<double>& b,
                                                              const point<double>& u, const point<double>& v,
                                                              double delta) {
    return settled_closest_between(a, b, u, v, delta, [] { return false; });
}

/// A distance from a point to the line through two others, all as given:
/// the moving polygon's points before its pose, which translates them.
struct point_line_distance {
    point<double> at;        ///< the point
    point<double> from;      ///< one point of the line
    point<double> to;        ///< another (the line's direction: to - from)
    bool at_moving = false;  ///< whether `at` is B's (the line then A's), else A's (the line B's)
};

/// Whether two point-to-line distances between A and B, B translated, are
/// equal by their points alone, decided exactly on the doubles as given (a
/// translation keeps every difference of B's points, and every side of
/// B's points against B's lines). Equal when:
///   - the two points are of one polygon and the lines of the other: the
///     lines are one (x's from and to, and y's, collinear) and the points'
///     difference is parallel to it, so both lie on one parallel;
///   - x's point is A's and y's B's: the lines are parallel, x's point lies
///     on y's line and y's point on x's, so both are the distance between
///     the two lines.
/// False otherwise, whether or not the distances are equal (a line of two
/// equal points included).
inline bool equal_point_line_distances(const point_line_distance& x, const point_line_distance& y) {
    if (x.from == x.to || y.from == y.to) return false;
    if (x.at_moving == y.at_moving)
        return exact_orientation(x.from, x.to, y.from) == 0 && exact_orientation(x.from, x.to, y.to) == 0 &&
               exact_cross_sign(x.at, y.at, x.from, x.to) == 0;
    return exact_cross_sign(x.from, x.to, y.from, y.to) == 0 && exact_orientation(y.from, y.to, x.at) == 0 &&
           exact_orientation(x.from, x.to, y.at) == 0;
}

/// closest_between_segments of [a, b] and [u, v], apart, from the parts of
/// their closest points (settled_closest_between's): a point at an end is
/// that end; a point inside one segment is the foot (foot_inside) of the
/// other point on it. end(i) gives the ends in NT (0: a, 1: b, 2: u, 3: v);
/// only those the parts need are asked. Exact in an exact field NT.
template <class NT, class End>
segment_pair_closest<NT> closest_at_parts(segment_part first, segment_part second, End&& end) {
    const auto first_end = [&] { return end(first == segment_part::start ? 0 : 1); };
    const auto second_end = [&] { return end(second == segment_part::start ? 2 : 3); };
    segment_pair_closest<NT> r;
    r.first_part = first;
    r.second_part = second;
    if (first == segment_part::interior) {
        r.on_second = second_end();
        segment_point<NT> c = foot_inside(r.on_second, end(0), end(1));
        r.squared = std::move(c.squared);
        r.on_first = std::move(c.at);
    } else if (second == segment_part::interior) {
        r.on_first = first_end();
        segment_point<NT> c = foot_inside(r.on_first, end(2), end(3));
        r.squared = std::move(c.squared);
        r.on_second = std::move(c.at);
    } else {
        r.on_first = first_end();
        r.on_second = second_end();
        r.squared = squared_distance(r.on_first, r.on_second);
    }
    return r;
}

/// The relative bound of node_gap_lower on g + r (u = 2^-53): the gap g~
/// from the posed centre to the box is within 3.2 u g of its true value (a
/// rounded difference per axis, then filter_length); the radius grows by the
/// pose's scale sqrt(c^2 + s^2) < 1 + 2^-52; the three roundings of
/// g - r - bound add 3 u (g + r) at most. In all below 6.3 u (g + r):
/// 2^-49 = 16 u covers it.
inline constexpr double node_gap_rounding = 0x1p-49;

/// A lower bound of the distance between the box `bounds` (exact) and every
/// point within `radius` of a centre whose exact posed place lies within
/// `delta` per coordinate of `center` (a node of B's edge tree, its centre
/// posed in double): the distance from center to the box, less the radius,
/// less posing_spread delta, less node_gap_rounding (g + r). May be negative;
/// -infinity when the centre is not finite.
inline double node_gap_lower(const box& bounds, const point<double>& center, double radius, double delta) {
    if (!std::isfinite(center.x + center.y)) return -HUGE_VAL;
    const double gx = std::max({bounds.min_x - center.x, 0.0, center.x - bounds.max_x});
    const double gy = std::max({bounds.min_y - center.y, 0.0, center.y - bounds.max_y});
    const double g = filter_length(gx, gy);
    return g - radius - (node_gap_rounding * (g + radius) + posing_spread * delta * (1 + bound_rounding));
}

/// The distance between two boxes (0 when they meet), rounded down: a lower
/// bound of the distance between any point of one and any of the other.
inline double box_gap_lower(const box& p, const box& q) {
    const double gx = std::max({0.0, q.min_x - p.max_x, p.min_x - q.max_x});
    const double gy = std::max({0.0, q.min_y - p.max_y, p.min_y - q.max_y});
    return std::max(gx, gy) * (1 - bound_rounding);
}

}  // namespace influence2d
