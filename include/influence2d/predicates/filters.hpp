// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The conservative filters in double: every test that may keep too much but
/// never drops what an exact decision needs, with its constants and their
/// derivations. A filter named `may_be_...` or `..._may_...` answers true
/// whenever the exact answer could be true (also when its own arithmetic
/// cannot be trusted: overflow, underflow, NaN); `certain_side` answers a
/// side only when its rounding bound proves it. Decisions (exact signs) are
/// in the other headers of predicates/.

#include <algorithm>
#include <cmath>
#include <limits>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/number/traits.hpp"

namespace influence2d {

/// Within (square_safe_low, square_safe_high) a magnitude's square lies in
/// (2^-800, 2^800) and a sum of a few such squares in (2^-800, 2^803): far
/// from double's overflow (2^1024) and from its subnormal range (below
/// 2^-1022). Filters square coordinates only between these bounds and scale
/// by a power of two (exact) outside them.
inline constexpr double square_safe_low = 0x1p-400;
/// See square_safe_low.
inline constexpr double square_safe_high = 0x1p400;

/// The relative rounding bound of certain_side. Its value l - r, with
/// l = dx (q.y - a.y) and r = dy (q.x - a.x), takes a rounded difference and
/// a rounded product for each of l and r (relative error below 2u each, u =
/// 2^-53) and a rounded subtraction (below u (|l| + |r|)); the direction
/// (dx, dy), itself a rounded difference, moves the value by less than
/// u (|l| + |r|) more. In all below 6u (|l| + |r|) < 2^-50 (|l| + |r|);
/// 2^-48 leaves a factor of four.
inline constexpr double side_rounding = 0x1p-48;

/// The widening of segments_certainly_cross's slack for its own rounding:
/// the slack 2e (|dx| + |dy| + spread) + 8e^2 takes six rounded operations
/// on non-negative terms after the rounded differences dx, dy and spread
/// (each below u = 2^-53 relative, the differences' error below u of each
/// term), in all below 9u < 2^-49 relative; 1 + 2^-46 leaves a factor of
/// eight.
inline constexpr double crossing_slack_widening = 1 + 0x1p-46;

/// Below this a bound built from products may have lost its meaning to
/// underflow (a product of two magnitudes near 2^-450 is subnormal): a side
/// test whose bound is smaller is not trusted.
inline constexpr double side_bound_floor = 0x1p-900;

/// The relative widening of upper_sqrt: a long double square root rounded to
/// double is within 2^-53 + 2^-64 of the root; 1e-12 (about 2^-40) is far
/// above that, and the step to the next double makes the bound strict.
inline constexpr double sqrt_widening = 1e-12;

/// The relative widening of a posed radius: B posed with the rotation doubles
/// c = cos(theta), s = sin(theta), each correctly rounded, is B scaled by
/// sqrt(c^2 + s^2), which differs from 1 by less than 2^-52 < 2.3e-16; 1e-15
/// covers it with room.
inline constexpr double pose_scale_widening = 1e-15;

/// The relative error of rotation_pose::unapply_in_double, per coordinate,
/// against the exact preimage R^-1 (q - t) of the pose's doubles: with x, y
/// the differences q - t, the two subtractions round by u = 2^-53 of |x| and
/// |y|, the two products and their sum by about 2u of |x| + |y|, and taking
/// R^T for R^-1 errs by the scale factor c^2 + s^2, within 2u of 1: in all
/// less than 8u (|x| + |y|) = 2^-50 (|x| + |y|); 2^-49 doubles it.
inline constexpr double unapply_widening = 0x1p-49;

/// The widening, in radians, of a cone's angular range in the cone index
/// beyond NT's filter_slack: std::atan2 is within a few ulps (below 1e-15
/// rad) of the true angle of its rounded arguments; 1e-12 covers it.
inline constexpr double atan2_widening = 1e-12;

/// The cone index trusts the direction of a point from O only when the
/// offset exceeds this many times filter_slack times the coordinates' scale:
/// the offset's own rounding is at most filter_slack times that scale, so
/// its direction is then known to within about 1e-3 rad, far inside a
/// bucket's widened range.
inline constexpr double direction_trust_factor = 1e3;

/// The length of (x, y) in double, for filters only: sqrt(x^2 + y^2) where
/// the squares can neither overflow nor underflow (square_safe_low and
/// square_safe_high) or both are 0 (the length is then exactly 0, as a
/// point inside a box has it), std::hypot (slower, and safe at any
/// magnitude) elsewhere. Within about an ulp of the true length either way.
[[gnu::always_inline]] inline double filter_length(double x, double y) {
    const double big = std::max(std::fabs(x), std::fabs(y));
    if (big < square_safe_high && (big > square_safe_low || big == 0)) return std::sqrt(x * x + y * y);
    return std::hypot(x, y);
}

/// An upper bound of sqrt(x) for x >= 0 given in long double, as a double:
/// strictly above the root (sqrt_widening and one ulp). Infinity for an
/// infinite x (or one beyond double's range); NaN for x < 0 or NaN.
inline double upper_sqrt(long double x) {
    const double r = static_cast<double>(std::sqrt(x));
    return std::nextafter(r * (1 + sqrt_widening), std::numeric_limits<double>::infinity());
}

/// Distance from p to the segment [a, b] in double, for filters only. The
/// differences are first scaled by a power of two (exactly) to magnitude ~1,
/// so that squaring them neither overflows nor underflows at any scale.
/// Rounded (not a bound); 0 when all three points coincide, the distance to
/// a for a == b, infinity when a difference is not finite (overflow or NaN).
inline double segment_distance(const point<double>& p, const point<double>& a, const point<double>& b) {
    double abx = b.x - a.x, aby = b.y - a.y, apx = p.x - a.x, apy = p.y - a.y;
    const double big = std::max({std::fabs(abx), std::fabs(aby), std::fabs(apx), std::fabs(apy)});
    if (big == 0) return 0;
    if (!std::isfinite(big)) return std::numeric_limits<double>::infinity();
    const int e = big > square_safe_low && big < square_safe_high ? 0 : std::ilogb(big);
    if (e != 0)
        abx = std::ldexp(abx, -e), aby = std::ldexp(aby, -e), apx = std::ldexp(apx, -e), apy = std::ldexp(apy, -e);
    const double ab2 = abx * abx + aby * aby;
    double t = ab2 > 0 ? (abx * apx + aby * apy) / ab2 : 0;
    t = std::min(1.0, std::max(0.0, t));
    const double d = filter_length(apx - t * abx, apy - t * aby);
    return e != 0 ? std::ldexp(d, e) : d;
}

/// Whether the double distance from p to [a, b] may be at most `reach`: also
/// when it is not finite (coordinates whose differences overflow), so that a
/// filter built on it stays conservative. Callers widen `reach` by their
/// rounding margin.
inline bool may_be_within(const point<double>& p, const point<double>& a, const point<double>& b, double reach) {
    const double d = segment_distance(p, a, b);
    return d <= reach || !std::isfinite(d);
}

/// The side of q with respect to the line through a with direction (dx, dy),
/// when q certainly lies beyond `slack` / (|dx| + |dy|) from it: +1 (left),
/// -1 (right); else 0. Evaluated in double with the bound side_rounding on
/// its own rounding; 0 whenever the bound cannot be trusted (not finite, or
/// below side_bound_floor).
inline int certain_side(const point<double>& a, double dx, double dy, const point<double>& q, double slack) {
    const double l = dx * (q.y - a.y), r = dy * (q.x - a.x);
    const double o = l - r, bound = slack + side_rounding * (std::fabs(l) + std::fabs(r));
    if (!(bound >= side_bound_floor) || !(bound < HUGE_VAL) || !(std::fabs(o) > bound)) return 0;
    return o > 0 ? 1 : -1;
}

/// The slack of certain_side_for for the edges of one polygon, their ends
/// within ep of their doubles on each coordinate, and points r within er of
/// theirs, for every r with |r.x - p.x| + |r.y - p.y| <= spread (in
/// doubles) from the edge's start p: per_length (|dx| + |dy|) + fixed for
/// an edge of direction (dx, dy). With d = q - p and w = r - p, the value
/// d.x w.y - d.y w.x moves by at most (ep + er)(|d.x| + |d.y|) +
/// 2 ep (|w.x| + |w.y|) + 4 ep (ep + er) when the points move so (each
/// coordinate of w by at most ep + er, of d by at most 2 ep, and the two
/// cross terms by 2 ep (ep + er) each); spread stands for |w.x| + |w.y|.
/// Its own rounding adds less than 6u (|l| + |r|) (side_rounding), and
/// |l| + |r| <= (|dx| + |dy|) spread. The terms are computed once for all
/// the edges; an edge's slack is then one product and one sum, and each
/// point two products, three differences and two comparisons.
struct side_slack {
    double per_length = 0;  ///< ep + er + side_rounding spread
    double fixed = 0;       ///< 2 ep (spread + 2 (ep + er))

    /// The terms for ep, er and spread.
    side_slack(double ep, double er, double spread)
        : per_length(ep + er + side_rounding * spread), fixed(2 * ep * (spread + 2 * (ep + er))) {}
    /// The slack of an edge of direction (dx, dy).
    double of(double dx, double dy) const { return per_length * (std::fabs(dx) + std::fabs(dy)) + fixed; }
};

/// The side of r with respect to the line through p of direction (dx, dy)
/// given its side_slack: +1 (left) or -1 (right) when the value is beyond
/// it, else 0 (also for a NaN value or slack, and for an infinite slack).
inline int certain_side_for(const point<double>& p, double dx, double dy, const point<double>& r, double slack) {
    const double o = dx * (r.y - p.y) - dy * (r.x - p.x);
    return o > slack ? 1 : (o < -slack ? -1 : 0);
}

/// The share of a disc's radius times an edge's |dx| + |dy| that
/// disc_reaches_left counts as the disc's reach across the edge's line:
/// below 1 / sqrt 2 = 0.7071 (|d|_2 >= |d|_1 / sqrt 2) by 1%, which covers
/// the rounding of the reach's few operations (2^-52 each), of the
/// direction's differences, and the scale factor of a posed disc
/// (pose_scale_widening).
inline constexpr double disc_reach_share = 0.7;

/// The relative widening of a distance, a sum of radii or a slack before it
/// enters a short sum (a box grown by a margin and half a distance, a reach
/// of d plus 2e, a slack less a disc's reach) that a comparison then holds
/// to a conservative bound: each of the sum's roundings (at most four along
/// any of these) moves it by at most unit_roundoff of the result, so the
/// widening by 2^-50 = 8u covers them with room.
inline constexpr double sum_widening = 0x1p-50;

/// Whether some point of the closed disc of radius `radius` about c lies
/// certainly strictly left of the line through p of direction (dx, dy), the
/// points' doubles within ep (p, and the direction's ends) and er (c) of
/// them, given the edge's side_slack as certain_side_for takes it: the
/// value o of c is above slack minus the disc's reach. Why: slack bounds
/// o's distance from the exact value o* (side_slack), and the point c +
/// t n (n the unit normal to the left, 0 < t < radius) has value o* +
/// t |d*|_2 for the exact direction d*; so o* > -radius |d*|_2 puts some
/// point of the disc strictly left. |d*|_2 >= |d*|_1 / sqrt 2, and |d*|_1
/// >= |dx| + |dy| - 4 ep less the differences' rounding: the reach
/// disc_reach_share radius (|dx| + |dy| - 4 ep) is below radius |d*|_2.
/// The slack is widened by sum_widening for the final subtraction's
/// rounding relative to it (the reach's share is in disc_reach_share). False for a
/// NaN, and for a radius of 0 the test is certain_side_for's (c itself
/// strictly left).
inline bool disc_reaches_left(const point<double>& p, double dx, double dy, const point<double>& c, double radius,
                              double ep, double slack) {
    const double o = dx * (c.y - p.y) - dy * (c.x - p.x);
    const double reach = disc_reach_share * radius * std::max(std::fabs(dx) + std::fabs(dy) - 4 * ep, 0.0);
    return o > slack * (1 + sum_widening) - reach;
}

/// The widening of the room 2e that two boxes' gap must exceed
/// (segments_may_meet): the gap between two doubles, rounded once, is
/// within 2^-53 of itself, so a rounded gap above 2e (1 + 2^-50) is a true
/// gap above 2e; and a positive rounded difference of two doubles is a
/// positive one (e = 0).
inline constexpr double box_gap_widening = 1 + 0x1p-50;

/// Whether the segments [a, b] and [u, v] may meet, each point known only to
/// within e on each coordinate (the paper's detailed test, both ways, as a
/// filter): false when u and v lie certainly on one side of the line
/// through a and b farther than 2e from it, or a and b certainly on one
/// side of the line through u and v (an exact segment within e sqrt 2 < 2e
/// of its approximation), or, asked last, when their boxes lie apart by
/// more than 2e on an axis (box_gap_widening: the rounded gap is within
/// 2^-53 of itself; collinear segments apart along their line, which no
/// side separates). The slack of each side is 2e (|dx| + |dy|) >= 2e
/// |b - a|.
inline bool segments_may_meet(const point<double>& a, const point<double>& b, const point<double>& u,
                              const point<double>& v, double e) {
    const auto one_side = [e](const point<double>& p, const point<double>& q, const point<double>& s,
                              const point<double>& t) {
        const double dx = q.x - p.x, dy = q.y - p.y;
        const double slack = 2 * e * (std::fabs(dx) + std::fabs(dy));
        const int side = certain_side(p, dx, dy, s, slack);
        return side != 0 && certain_side(p, dx, dy, t, slack) == side;
    };
    if (one_side(a, b, u, v) || one_side(u, v, a, b)) return false;
    // (The boxes last: the callers' pairs have boxes that overlap already,
    // but for collinear segments.)
    const double room = 2 * e * box_gap_widening;
    const auto apart = [room](double p, double q, double s, double t) {
        return std::min(s, t) - std::max(p, q) > room || std::min(p, q) - std::max(s, t) > room;
    };
    return !apart(a.x, b.x, u.x, v.x) && !apart(a.y, b.y, u.y, v.y);
}

/// The slack of certain_side_within and certain_ahead_within, for
/// d = (dx, dy) = q - p and w = r - p: 2e (|d.x| + |d.y|) + 2e (|w.x| + |w.y|)
/// + 8e^2, widened by crossing_slack_widening (derived there).
inline double slack_within(double dx, double dy, const point<double>& p, const point<double>& r, double e) {
    const double spread = std::fabs(r.x - p.x) + std::fabs(r.y - p.y);
    return (2 * e * (std::fabs(dx) + std::fabs(dy) + spread) + 8 * e * e) * crossing_slack_widening;
}

/// The side of r with respect to the directed line through p and q: +1
/// (left) or -1 (right) when every point within e of r, on each coordinate,
/// lies on that side of the line through every two points within e of p
/// and q; else 0 (also when the arithmetic cannot be trusted,
/// certain_side). The slack: with d = q - p and w = r - p, the value
/// d.x w.y - d.y w.x moves by at most 2e (|d.x| + |d.y|) +
/// 2e (|w.x| + |w.y|) + 8e^2 when each point moves by e on each coordinate
/// (each coordinate of d and w moves by at most 2e, and the two cross terms
/// by (2e)^2 each); the sums in double are widened by
/// crossing_slack_widening for their own rounding, and certain_side adds
/// the value's.
inline int certain_side_within(const point<double>& p, const point<double>& q, const point<double>& r, double e) {
    const double dx = q.x - p.x, dy = q.y - p.y;
    return certain_side(p, dx, dy, r, slack_within(dx, dy, p, r, e));
}

/// The sign of the dot product (dx, dy).(q - a) when its magnitude certainly
/// exceeds `slack`: +1 (q lies ahead of a along the direction), -1 (behind);
/// else 0. It is certain_side for the direction turned a quarter, (dy, -dx):
/// dy (q.y - a.y) - (-dx)(q.x - a.x) is the dot product, with the same
/// roundings (a negation is exact), so the same bound.
inline int certain_ahead(const point<double>& a, double dx, double dy, const point<double>& q, double slack) {
    return certain_side(a, dy, -dx, q, slack);
}

/// The sign of (q - p).(r - p) when it is the same for every three points
/// within e of p, q and r on each coordinate: +1 or -1; else 0. The slack is
/// certain_side_within's (slack_within): d.x w.x + d.y w.y moves by at most
/// what d.x w.y - d.y w.x does (the same terms, summed).
inline int certain_ahead_within(const point<double>& p, const point<double>& q, const point<double>& r, double e) {
    const double dx = q.x - p.x, dy = q.y - p.y;
    return certain_ahead(p, dx, dy, r, slack_within(dx, dy, p, r, e));
}

/// Whether the segments [a, b] and [u, v] certainly cross, each point known
/// only to within e on each coordinate: u and v certainly on opposite sides
/// of the line through a and b, and a and b of the line through u and v,
/// whatever the exact points within e (certain_side_within; then the exact
/// segments cross at a point interior to both, and meet). False whenever
/// that is not certain.
inline bool segments_certainly_cross(const point<double>& a, const point<double>& b, const point<double>& u,
                                     const point<double>& v, double e) {
    const auto sides_differ = [e](const point<double>& p, const point<double>& q, const point<double>& s,
                                  const point<double>& t) {
        const int first = certain_side_within(p, q, s, e);
        return first != 0 && certain_side_within(p, q, t, e) == -first;
    };
    return sides_differ(a, b, u, v) && sides_differ(u, v, a, b);
}

/// The relative widening of certainly_farther's comparison, for its own
/// rounding: the sum r + 3e (two roundings) and its square (one), and
/// dx^2 + dy^2 (a rounded difference on each axis, two products, one sum:
/// below 5u = 5 2^-53 relative while the sum is a normal double) err in
/// all by less than 8u = 2^-50; 2^-47 leaves a factor of eight.
inline constexpr double farther_widening = 0x1p-47;

/// Whether every point within e of p and every point within e of q (on each
/// coordinate) lie more than r apart. Two such points lie at least
/// |p - q| - 2 sqrt(2) e apart, so |p - q| > r + 3e suffices; it is
/// compared squared in double, each side widened by farther_widening and
/// the right one by the least normal double as well (a sum of squares that
/// underflows errs by an absolute amount below it). False when a square
/// overflows and for a NaN.
inline bool certainly_farther(const point<double>& p, const point<double>& q, double r, double e) {
    const double dx = p.x - q.x, dy = p.y - q.y, reach = r + 3 * e;
    const double apart2 = dx * dx + dy * dy;
    return std::isfinite(apart2) && apart2 * (1 - farther_widening) >
                                        reach * reach * (1 + farther_widening) + std::numeric_limits<double>::min();
}

/// Whether every point within e of p and every point within e of q (on each
/// coordinate) lie less than r apart. Two such points lie at most
/// |p - q| + 2 sqrt(2) e apart, so |p - q| < r - 3e suffices; it is compared
/// squared in double, each side widened by farther_widening (the same
/// roundings as certainly_farther's) and the left one by the least normal
/// double as well. False when r - 3e is not positive and for a NaN.
inline bool certainly_nearer(const point<double>& p, const point<double>& q, double r, double e) {
    const double dx = p.x - q.x, dy = p.y - q.y, reach = r - 3 * e;
    if (!(reach > 0)) return false;
    const double apart2 = dx * dx + dy * dy;
    return apart2 * (1 + farther_widening) + std::numeric_limits<double>::min() <
           reach * reach * (1 - farther_widening);
}

/// Whether two discs certainly share a point: the disc of radius r about
/// the point whose double (within e on each coordinate) is p, and the disc
/// of radius s about the one whose double is q. Discs whose centres lie
/// less than r + s apart overlap; certainly_nearer decides that for the
/// exact centres. The sum r + s rounds by at most 2^-53 relative, which
/// adds 2^-52 to its square: within certainly_nearer's farther_widening
/// (2^-47), which covers its own eight roundings of 2^-53 (2^-50) with room
/// to spare. False when either radius is not positive and for a NaN.
inline bool discs_certainly_overlap(const point<double>& p, double r, const point<double>& q, double s, double e) {
    return r > 0 && s > 0 && certainly_nearer(p, q, r + s, e);
}

/// Whether some point of box b may lie within g of the line through u and v:
/// false only when every corner lies certainly on one side, beyond g, as
/// certain_side would find each (then no point within g of the segment
/// [u, v] lies in b). True for u == v and whenever the arithmetic cannot be
/// trusted.
///
/// The four corners in one pass: certain_side's value at corner (x, y) is
/// l - r with l = dx (y - u.y) and r = dy (x - u.x), so the corners' values
/// are l_i - r_j for the box's two heights i and two abscissas j, and the
/// least of them is min l - max r. Rounding is monotone, so fl(l_i - r_j) >=
/// fl(min l - max r) for every corner; and each corner's bound, slack +
/// side_rounding (|l_i| + |r_j|) rounded, lies between the same sum taken
/// with the smaller and with the larger magnitudes. So min l - max r beyond
/// the larger bound puts every corner certainly left, as certain_side
/// would (max l - min r below its negative, right), and the smaller bound
/// at least side_bound_floor keeps every corner's bound trusted. Each
/// corner's value is then the one certain_side computes, and the one bound
/// is at least each corner's: this test drops a box only where the four
/// certain_side calls would.
inline bool box_may_be_near_line(const box& b, const point<double>& u, const point<double>& v, double g) {
    const double dx = v.x - u.x, dy = v.y - u.y;
    // g |d|_1 >= g |d|_2: the distance beyond g, with room for the rounding.
    const double slack = g * (std::fabs(dx) + std::fabs(dy));
    const double l0 = dx * (b.min_y - u.y), l1 = dx * (b.max_y - u.y);
    const double r0 = dy * (b.min_x - u.x), r1 = dy * (b.max_x - u.x);
    const double al0 = std::fabs(l0), al1 = std::fabs(l1), ar0 = std::fabs(r0), ar1 = std::fabs(r1);
    // (A NaN or infinite term: not trusted, as in certain_side.)
    if (!(al0 + al1 + ar0 + ar1 < HUGE_VAL)) return true;
    const double larger = slack + side_rounding * (std::max(al0, al1) + std::max(ar0, ar1));
    const double smaller = slack + side_rounding * (std::min(al0, al1) + std::min(ar0, ar1));
    if (!(smaller >= side_bound_floor) || !(larger < HUGE_VAL)) return true;
    return !(std::min(l0, l1) - std::max(r0, r1) > larger) && !(std::max(l0, l1) - std::min(r0, r1) < -larger);
}

/// certain_crossing's answer when the doubles do not settle an edge.
inline constexpr int crossing_unknown = 3;

/// What the edge (a, b) adds to the winding number of the ray from P
/// towards +x (edge_crossing in covering/inclusion.hpp: +1, -1 or 0), when
/// the doubles settle it for points each within g / 2 of these on each
/// coordinate (two such coordinates differ by more than g from their
/// doubles' difference only when the doubles differ by less): the edge
/// both above P or both below it by more than g, or both left of it: 0;
/// both right of it by more than g with each end's height off P's by more
/// than g: its direction. Otherwise (an end within g of P's height, or the
/// edge's box within g of P) crossing_unknown. A NaN coordinate fails
/// every comparison: crossing_unknown.
inline int certain_crossing(const point<double>& a, const point<double>& b, const point<double>& p, double g) {
    const double above = p.y + g, below = p.y - g;
    if ((a.y > above && b.y > above) || (a.y < below && b.y < below)) return 0;
    if (a.x < p.x - g && b.x < p.x - g) return 0;
    if (a.x > p.x + g && b.x > p.x + g) {
        if (a.y < below && b.y > above) return 1;
        if (a.y > above && b.y < below) return -1;
    }
    return crossing_unknown;
}

/// What the edge (a, b), its ends exact in double, adds to the winding
/// number of the ray from P towards +x (edge_crossing in
/// covering/inclusion.hpp), for every point P within e of p on each
/// coordinate, when the doubles settle it; else crossing_unknown. Never
/// crossing_on_edge: an edge settled is certainly off every such P.
///   certain_crossing settles it (g = 2e): its answer
///   both ends' heights off p's by more than 2e, one above and one below
///   (the edge's direction the same for every such P): P's side of its
///   line, certain_side_within(a, b, p, e) (which lets the ends move by e
///   too, a bound that only widens), gives edge_crossing's +1 (upward, P
///   left), -1 (downward, P right) or 0
///   otherwise crossing_unknown
/// With e = 0 an answer is edge_crossing's on the doubles.
inline int certain_crossing_within(const point<double>& a, const point<double>& b, const point<double>& p, double e) {
    const double g = 2 * e;
    const int settled = certain_crossing(a, b, p, g);
    if (settled != crossing_unknown) return settled;
    const double above = p.y + g, below = p.y - g;
    const bool upward = a.y < below && b.y > above, downward = a.y > above && b.y < below;
    if (!upward && !downward) return crossing_unknown;
    const int side = certain_side_within(a, b, p, e);
    if (side == 0) return crossing_unknown;
    return upward ? (side > 0 ? 1 : 0) : (side < 0 ? -1 : 0);
}

/// Whether every edge with both ends in box b certainly adds nothing to the
/// crossings of the ray from P towards +x (certain_crossing's 0 for each,
/// with the same g): b lies above P or below it by more than g, or left of
/// it by more than g. False for an empty box or a NaN coordinate of P.
inline bool certainly_off_ray(const box& b, const point<double>& p, double g) {
    if (b.empty()) return false;
    return b.min_y > p.y + g || b.max_y < p.y - g || b.max_x < p.x - g;
}

/// The margin between points posed in double and the same points posed in
/// NT, for coordinates whose terms (the polygons' coordinates and the
/// translations) sum to at most `scale` in magnitude: each coordinate
/// c x - s y + t is a few rounded operations on such terms, in double and in
/// NT, so the two differ by less than filter_slack times the scale
/// (filter_slack >= 1e-9 is far above double's few ulps; float's 1e-4 above
/// its own); four times that, plus the least normal double for coordinates
/// that underflow. The filters of the detectors, of the one-shot questions and
/// of the sweep widen by it, which also covers their own few roundings. The
/// separation's bounds count each rounding in double separately and take the
/// tighter posing_error (predicates/distance.hpp) for the same posing.
template <class NT>
double posing_margin(double scale) {
    return number_traits<NT>::filter_slack * 4 * scale + std::numeric_limits<double>::min();
}

/// The relative margin of placing_margin. A coordinate posed in double by
/// rotation_pose errs from the exact c x - s y + t (the same doubles c and
/// s) by less than 8u = 2^-50 times the scale (pose_rounding in
/// predicates/distance.hpp derives it: 6.02u (|x| + |y|) + 1.01u |t|,
/// u = 2^-53), and the same point posed in an NT at least as fine as double
/// by as much again; the filters that widen by the margin round a few times
/// more (a sum with a coordinate, a box's side widened), each time by at
/// most u times the scale. 2^-46 = 128u leaves a factor of four over 32u.
inline constexpr double placing_slack = 0x1p-46;

/// Whether NT's posed values are the exact ones (an exact or filtered type)
/// or rounded at least as finely as double's: placing_margin's tight bound
/// holds for them.
template <class NT>
constexpr bool places_as_finely_as_double() {
    if constexpr (is_exact_v<NT>)
        return true;
    else if constexpr (std::numeric_limits<NT>::is_specialized && std::numeric_limits<NT>::radix == 2)
        return std::numeric_limits<NT>::digits >= std::numeric_limits<double>::digits;
    else
        return false;  // (a decimal type keeps posing_margin)
}

/// The margin between points placed in double by rotation_pose::apply (or
/// standing where they are) and the same points in NT, for coordinates
/// whose terms sum to at most `scale` in magnitude, as posing_margin: for a
/// type that places as finely as double (places_as_finely_as_double), the
/// roundings of the posings alone (placing_slack), some 2^18 times tighter
/// than posing_margin, so that the one-shot filters and the world's boxes
/// keep their power far from the origin; otherwise (float) posing_margin.
/// Plus the least normal double for coordinates that underflow
/// (pose_underflow, 2^-1072, is below it).
template <class NT>
double placing_margin(double scale) {
    if constexpr (places_as_finely_as_double<NT>())
        return placing_slack * scale + std::numeric_limits<double>::min();
    else
        return posing_margin<NT>(scale);
}

/// The relative rounding bound of projections_certainly_apart. A point p
/// with |px|, |py| <= r projects onto v as vx px + vy py: two rounded
/// products and a rounded sum, within gamma_2 (|vx px| + |vy py|) <=
/// gamma_2 (|vx| + |vy|) r of its value (gamma_2 = 2u / (1 - 2u), u =
/// 2^-53); the least projection of one set and the greatest of the other
/// together within gamma_2 (|vx| + |vy|) (r_a + r_b). The bound itself takes
/// five rounded operations on non-negative terms (the floor's sum among
/// them) and the difference lo - hi one more: 2^-50 = 8u, and
/// 8u (1 - u)^5 / (1 + u) > gamma_2 with a factor of nearly four to spare.
inline constexpr double projection_rounding = 0x1p-50;

/// The absolute floor of projections_certainly_apart's bound: a product
/// below double's normal range rounds by up to 2^-1075 in absolute terms,
/// four of them (two a projection) at most 2^-1073.
inline constexpr double projection_floor = 0x1p-1060;

/// Whether every point of a set A lies strictly beyond every point of a set
/// B along the direction v = (vx, vy), given lo, the least of the
/// projections vx ax + vy ay over A's points as computed in double, hi, the
/// greatest of B's, and `reach`, the sum of the two sets' largest
/// coordinate magnitudes: lo - hi above the projections' rounding
/// (projection_rounding). True only when certain; false when undecided or
/// when a value is not finite. Then the two sets' convex hulls are apart,
/// and any regions inside them.
inline bool projections_certainly_apart(double lo, double hi, double vx, double vy, double reach) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) return false;
    return lo - hi > projection_rounding * ((std::fabs(vx) + std::fabs(vy)) * reach) + projection_floor;
}

}  // namespace influence2d
