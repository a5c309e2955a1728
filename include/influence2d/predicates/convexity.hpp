// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether a polygon is one convex ring, or one ring that is its own box,
/// decided exactly on its doubles.

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

/// Whether p's closed region is its closed box: one ring of four vertices
/// whose edges are parallel to the axes in turn (consecutive vertices
/// differ in exactly one coordinate, and not in the one the edge before
/// changed). Then the vertices are (x0, y0), (x1, y0), (x1, y1), (x0, y1)
/// from some vertex on, or those taken along y first, with x0 != x1 and
/// y0 != y1: the four corners of p's box, joined along its sides, whichever
/// corner the ring starts at and whichever way round it goes. Exact
/// (comparisons of the doubles as given). Two such polygons meet exactly
/// where their closed boxes share a point (boxes_overlap), the test a join
/// asks of them.
inline bool fills_its_box(const polygon& p) {
    if (p.ring_count() != 1 || p.size() != 4) return false;
    // (One ring of four: the edge from vertex i goes to vertex i + 1, the
    // last back to the first; so without reading the polygon's links.)
    bool along_x[4];
    for (std::size_t i = 0; i < 4; ++i) {
        const point<double>&v = p.vertex(i), &w = p.vertex((i + 1) % 4);
        along_x[i] = v.y == w.y;
        if (along_x[i] == (v.x == w.x)) return false;
    }
    return along_x[0] != along_x[1] && along_x[1] != along_x[2] && along_x[2] != along_x[3];
}

}  // namespace influence2d
