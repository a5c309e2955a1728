// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Closed segment-segment questions: intersection and distance bounds. All of
/// them use ring operations and signs taken by number_traits (directly, or
/// through orientation() and compare_values()) only, so they are exact when
/// NT's ring operations are; a filtered NT gives the exact answer or throws
/// uncertain_sign.

#include "influence2d/assert.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/orientation.hpp"

namespace influence2d {

/// Whether the closed segments [a, b] and [c, d] share a point, given
/// o_c = orientation(a, b, c) and o_d = orientation(a, b, d) already evaluated
/// (the detector has them from its straddle test). Touching counts: a shared
/// endpoint, an endpoint on the other segment, or a collinear overlap.
/// Degenerate segments (a == b or c == d: points) are allowed.
template <class NT>
bool segments_intersect(int o_c, int o_d, const point<NT>& a, const point<NT>& b, const point<NT>& c,
                        const point<NT>& d) {
    INFLUENCE2D_ASSERT(o_c == orientation(a, b, c) && o_d == orientation(a, b, d),
                       "the orientations given are not those of c and d against [a, b]");
    if (o_c * o_d > 0) return false;
    if (o_c == 0 && o_d == 0) {
        // [c, d] lies on the line of [a, b] (or a == b): compare extents, unless
        // a == b and that point is off the line of [c, d].
        if (orientation(c, d, a) != 0 || orientation(c, d, b) != 0) return false;
        const auto overlap = [](const NT& p0, const NT& p1, const NT& q0, const NT& q1) {
            const bool p_up = compare_values(p0, p1) < 0, q_up = compare_values(q0, q1) < 0;
            const NT& pmin = p_up ? p0 : p1;
            const NT& pmax = p_up ? p1 : p0;
            const NT& qmin = q_up ? q0 : q1;
            const NT& qmax = q_up ? q1 : q0;
            return compare_values(pmax, qmin) >= 0 && compare_values(qmax, pmin) >= 0;
        };
        return overlap(a.x, b.x, c.x, d.x) && overlap(a.y, b.y, c.y, d.y);
    }
    return orientation(c, d, a) * orientation(c, d, b) <= 0;
}

/// Whether the closed segments [a, b] and [c, d] share a point (touching
/// counts; degenerate segments allowed).
template <class NT>
bool segments_intersect(const point<NT>& a, const point<NT>& b, const point<NT>& c, const point<NT>& d) {
    return segments_intersect(orientation(a, b, c), orientation(a, b, d), a, b, c, d);
}

/// Whether p is within sqrt(d2) of the line through a with direction
/// (abx, aby) (d2 >= 0; equality counts): |ab x ap|^2 <= d2 |ab|^2, ring
/// operations only. For a direction (0, 0) every p is.
template <class NT>
bool point_line_within(const point<NT>& p, const point<NT>& a, const NT& abx, const NT& aby, const NT& d2) {
    const NT cross = abx * (p.y - a.y) - aby * (p.x - a.x);
    return compare_values<NT>(cross * cross, d2 * (abx * abx + aby * aby)) <= 0;
}

/// Whether p is within sqrt(d2) of the line through a and b (d2 >= 0;
/// equality counts), b - a taken as the direction. For a == b every p is
/// (the line is not defined: 0 <= 0).
template <class NT>
bool point_line_within(const point<NT>& p, const point<NT>& a, const point<NT>& b, const NT& d2) {
    return point_line_within(p, a, NT(b.x - a.x), NT(b.y - a.y), d2);
}

/// Whether dist(p, [a, b])^2 <= d2, for the closed segment and d2 >= 0 the
/// squared bound (equality counts). Ring operations only: beyond an end the
/// distance is to that end; in between it is |ab x ap|^2 / |ab|^2, compared
/// after multiplying by |ab|^2. For a == b, the distance to that point.
template <class NT>
bool point_segment_within(const point<NT>& p, const point<NT>& a, const point<NT>& b, const NT& d2) {
    using tr = number_traits<NT>;
    const NT abx = b.x - a.x, aby = b.y - a.y;
    const NT apx = p.x - a.x, apy = p.y - a.y;
    const NT t = abx * apx + aby * apy;
    const NT ab2 = abx * abx + aby * aby;
    if (tr::sign(t) <= 0 || tr::sign(ab2) == 0) return compare_values<NT>(apx * apx + apy * apy, d2) <= 0;
    if (compare_values(t, ab2) >= 0) {
        const NT bpx = p.x - b.x, bpy = p.y - b.y;
        return compare_values<NT>(bpx * bpx + bpy * bpy, d2) <= 0;
    }
    return point_line_within(p, a, abx, aby, d2);
}

/// Whether dist([a, b], [c, d])^2 <= d2 (d2 >= 0; equality counts): the
/// segments meet, or an endpoint of one is within the distance of the other.
/// Degenerate segments allowed.
template <class NT>
bool segments_within(const point<NT>& a, const point<NT>& b, const point<NT>& c, const point<NT>& d, const NT& d2) {
    return segments_intersect(a, b, c, d) || point_segment_within(a, c, d, d2) || point_segment_within(b, c, d, d2) ||
           point_segment_within(c, a, b, d2) || point_segment_within(d, a, b, d2);
}

}  // namespace influence2d
