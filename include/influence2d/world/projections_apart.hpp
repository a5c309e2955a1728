// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether two polygons at their own coordinates are certainly apart along
/// some direction, found by a short search: a join's proof that two
/// polygons whose boxes overlap do not meet, before either is placed.

#include <algorithm>
#include <cstddef>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/predicates/filters.hpp"

namespace influence2d {

/// The steps of projections_apart's search after its first direction. On
/// the real layers of docs/world.md, of the candidates apart whose boxes
/// overlap (blocks 474, tracts 336, countries 176, counties 35), the first
/// direction alone showed 334, 263, 72 and 30 apart, four steps 425, 322,
/// 106 and 34, eight 430, 327, 111 and 34, sixteen 433, 328, 113 and 34;
/// the convex hulls of 442, 331, 121 and 35 are apart (shapely). Each step
/// costs a pass over both polygons' vertices, and a pair that meets takes
/// them all.
inline constexpr int projection_steps = 4;

namespace projections_apart_detail {

/// The vertex of v farthest along (dx, dy) and its projection, in double.
struct support {
    std::size_t index;
    double projection;
};

inline support farthest_along(const std::vector<point<double>>& v, double dx, double dy) {
    support s{0, dx * v[0].x + dy * v[0].y};
    for (std::size_t k = 1; k < v.size(); ++k) {
        const double p = dx * v[k].x + dy * v[k].y;
        if (p > s.projection) s = {k, p};
    }
    return s;
}

}  // namespace projections_apart_detail

/// Whether every vertex of a lies strictly beyond every vertex of b along
/// some direction v that the search below finds, certified
/// (projections_certainly_apart): then the closed regions of a and b, inside
/// the convex hulls of their vertices, do not meet. False when no such
/// direction was found (they may meet or not). A search for the point of
/// the difference set A - B nearest the origin (Gilbert's iteration on the
/// two vertex sets, each step a segment):
///
///   v <- the centre of a's box minus the centre of b's
///   up to 1 + projection_steps times:
///     a* <- a's vertex least along v, b* <- b's vertex farthest along v
///     (lo = v.a*, hi = v.b*: one pass over each polygon's vertices)
///     lo > hi: apart iff projections_certainly_apart(lo, hi, v)
///     w <- a* - b*; v <- the point of the segment [v, w] nearest the
///     origin (v = 0, or no such point: not found)
///   not found
///
/// The direction is any; only the certificate decides, so that the
/// search's own roundings cannot make a wrong answer. Linear in the two
/// polygons' vertices per step.
inline bool projections_apart(const polygon& a, const polygon& b) {
    using projections_apart_detail::farthest_along;
    const std::vector<point<double>>&av = a.vertices(), &bv = b.vertices();
    if (av.empty() || bv.empty()) return false;
    const point<double> ca = a.bounds().centre(), cb = b.bounds().centre();
    double vx = ca.x - cb.x, vy = ca.y - cb.y;
    const double reach = largest_coordinate(a) + largest_coordinate(b);
    for (int step = 0;; ++step) {
        const auto sa = farthest_along(av, -vx, -vy), sb = farthest_along(bv, vx, vy);
        const double lo = -sa.projection, hi = sb.projection;
        if (lo > hi) return projections_certainly_apart(lo, hi, vx, vy, reach);
        if (step == projection_steps) return false;
        const double wx = av[sa.index].x - bv[sb.index].x, wy = av[sa.index].y - bv[sb.index].y;
        const double dx = wx - vx, dy = wy - vy, dd = dx * dx + dy * dy;
        if (!(dd > 0)) return false;
        const double t = std::min(1.0, std::max(0.0, -(vx * dx + vy * dy) / dd));
        vx += t * dx;
        vy += t * dy;
        if (vx == 0 && vy == 0) return false;
    }
}

}  // namespace influence2d
