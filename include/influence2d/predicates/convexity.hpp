// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether a polygon is one convex ring, decided exactly on its doubles.

#include <cstddef>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/predicates/exact_doubles.hpp"
#include "influence2d/predicates/orientation.hpp"

namespace influence2d {

/// Whether the direction from a to b (a != b) points into the upper half
/// of the circle of directions: angles in [0, pi), the direction +x
/// included and -x not. Exact (comparisons only).
inline bool direction_in_upper_half(const point<double>& a, const point<double>& b) {
    return b.y > a.y || (b.y == a.y && b.x > a.x);
}

/// Whether p is a single convex ring, stored counter-clockwise: no two
/// consecutive vertices equal; at every vertex a left turn, or a straight
/// step with the vertex strictly between its neighbours (no spike); at
/// least one left turn; and edge directions that go round exactly once.
/// Every sign is exact (exact_orientation and comparisons of the doubles as
/// given), so the answer holds for the polygon itself, and for its image
/// under any map x -> M x + t with det M > 0 (a rotation pose: det is
/// c^2 + s^2), which keeps every orientation sign.
///
/// Why the count of turns: with every turn left or straight, the edge
/// directions turn counter-clockwise by less than pi at each vertex, so
/// they pass from the lower half of the circle of directions into the
/// upper one (direction_in_upper_half) once per full turn. A ring that
/// winds twice (a pentagram) turns left everywhere and passes twice.
inline bool is_convex_polygon(const polygon& p) {
    if (p.ring_count() != 1 || p.size() < 3) return false;
    const std::size_t n = p.size();
    bool some_left_turn = false;
    std::size_t upward_passes = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const point<double>& a = p.vertex(i);
        const point<double>& b = p.vertex(p.next(i));
        const point<double>& c = p.vertex(p.next(p.next(i)));
        if (same_point(a, b)) return false;
        const int turn = exact_orientation(a, b, c);
        if (turn < 0) return false;
        if (turn == 0 && !(within_collinear_segment(b, a, c) && !same_point(b, c))) return false;
        some_left_turn = some_left_turn || turn > 0;
        if (!direction_in_upper_half(a, b) && direction_in_upper_half(b, c)) ++upward_passes;
    }
    return some_left_turn && upward_passes == 1;
}

}  // namespace influence2d
