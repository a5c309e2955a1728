// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// One query without a detector: whether A and B posed by q meet, at the cost
/// of reading both polygons once (docs/method.md, "One-shot queries").

#include <cmath>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d {

/// Whether the closed regions of A and of B posed by q meet (touching
/// counts; B inside a hole of A does not meet A): the question a detector
/// answers for one frame with distance 0, without building one. Exact when NT
/// is; a filtered NT may throw uncertain_sign (certified_intersects in
/// exact/certified_intersects.hpp answers exactly through it). Throws invalid_input
/// for an empty polygon, one beyond NT's range, or a pose with a NaN or
/// infinite component.
///
///   NT float, double or long double, outside its safe window: the query scaled by a
///   power of two first (core/range_scaling.hpp; the same answer)
///   pose B's vertices in double; e <- their rounding margin
///   if the boxes of A and of posed B (grown by e) are apart:   disjoint
///   for one vertex of each of the first two rings of each polygon (the
///   polygon with the smaller box first, each ring of it by its vertex
///   nearest the other's box centre: ring_vertex_near), within the other's
///   box: located in the other polygon (exact), not outside: meet
///   A's edges whose box meets B's box, B's edges whose box meets A's box
///   for each pair of those whose boxes overlap (sort and sweep along x):
///       filter in double: the paper's detailed test both ways (segments_may_meet)
///       exact segment test in NT on the posed vertices:       meet
///   the same location for one vertex of every other ring:    meet
///   disjoint
///
/// Time O((n + m) log(n + m) + k + r (n + m)) for n and m edges, k
/// overlapping boxes and r rings located (linear for most poses that meet:
/// a located vertex answers them);
/// no structure outlives the call. For many poses of one pair a detector is
/// faster (it keeps A's precomputation and the last frame's candidates).
template <class NT>
bool intersects(const polygon& a, const polygon& b, const pose& q) {
    accepted_polygon<NT>(a, "static");
    accepted_polygon<NT>(b, "moving");
    const rotation_pose t(q);
    if (const int k = range_shift<NT>(a, b, q))
        return intersects<NT>(a.scaled_by_power_of_two(k), b.scaled_by_power_of_two(k), scaled_by_power_of_two(q, k));
    placed_polygon<NT> pa(a), pb(b, t);
    const double e = placing_margin<NT>(coordinate_scale(b) + coordinate_scale(a) + std::fabs(q.tx) + std::fabs(q.ty));
    return static_cast<bool>(placed_meet(pa, pb, e));
}

}  // namespace influence2d
