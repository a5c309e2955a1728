// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Feito's inclusion test on the signed triangle covering (docs/method.md section 2).

#include <cstddef>
#include <vector>

#include "influence2d/assert.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/predicates/orientation.hpp"

namespace influence2d {

/// Where a point lies with respect to a closed polygonal region.
enum class location {
    outside,   ///< not in the region
    boundary,  ///< on an edge (a vertex, a zero-length edge, a spike included)
    inside     ///< off every edge, with a non-zero winding number
};

/// Feito's sum over the covering triangles from origin O, in doubled units:
///   for each edge (a, b) with sigma = orientation(O, a, b) != 0 and P in the
///   closed triangle (O, a, b):
///     P on the edge [a, b]          -> P is on the boundary: stop;
///     P on a side O-a or O-b        -> add sigma     (half a triangle);
///     P strictly inside             -> add 2 * sigma;
/// The total is twice the winding number of the rings around P (each half
/// count is the mean of the counts on the two sides of a shared side), and P is
/// inside when it is not zero. Precondition: P != O.
template <class NT>
location feito_locate(const polygon& shape, const std::vector<point<NT>>& v, const point<NT>& o, const point<NT>& p) {
    INFLUENCE2D_ASSERT(v.size() == shape.size(), "the vertices in NT are not the polygon's");
    long long doubled = 0;
    for (std::size_t i = 0; i < shape.size(); ++i) {
        const point<NT>& a = v[i];
        const point<NT>& b = v[shape.next(i)];
        const int pab = orientation(p, a, b);
        if (pab == 0 && within_collinear_segment(p, a, b)) return location::boundary;
        const int sigma = orientation(o, a, b);
        if (sigma == 0 || pab * sigma < 0) continue;
        const int beta = orientation(o, p, b) * sigma;
        if (beta < 0) continue;
        const int gamma = orientation(o, a, p) * sigma;
        if (gamma < 0) continue;
        doubled += (beta == 0 || gamma == 0) ? sigma : 2 * sigma;
    }
    return doubled != 0 ? location::inside : location::outside;
}

/// Locates P in the closed region of the polygon whose vertices, in NT, are
/// `v` (topology from `shape`) by the winding number of a ray from P towards
/// +x, without an origin (Sunday's form of the crossing count):
///   for each edge (a, b):
///     a and b both above P, or both below, or both left of it: skip
///     P on the closed edge [a, b]                -> boundary: stop
///     upward edge (a.y <= P.y < b.y), P left of it   -> winding + 1
///     downward edge (b.y <= P.y < a.y), P right of it -> winding - 1
///   inside when the winding number is not zero
/// An edge wholly right of P decides its crossing by its end's heights
/// alone; an orientation is taken only for the few edges whose box holds P.
/// The same region as feito_locate (the same winding numbers, the boundary
/// closed), exact when NT's comparisons and orientations are; time linear in
/// the number of edges, with a few comparisons per edge.
template <class NT>
location locate_by_crossings(const polygon& shape, const std::vector<point<NT>>& v, const point<NT>& p) {
    INFLUENCE2D_ASSERT(v.size() == shape.size(), "the vertices in NT are not the polygon's");
    long long winding = 0;
    for (std::size_t i = 0; i < shape.size(); ++i) {
        const point<NT>& a = v[i];
        const point<NT>& b = v[shape.next(i)];
        const int ay = compare_values(a.y, p.y), by = compare_values(b.y, p.y);
        if ((ay > 0 && by > 0) || (ay < 0 && by < 0)) continue;  // no crossing, P not on it
        const int ax = compare_values(a.x, p.x), bx = compare_values(b.x, p.x);
        if (ax < 0 && bx < 0) continue;  // wholly left: the ray misses it, P is not on it
        const bool upward = ay <= 0 && by > 0, downward = by <= 0 && ay > 0;
        if (ax > 0 && bx > 0) {
            // Wholly right of P: P lies left of an upward edge and right of a
            // downward one.
            winding += upward ? 1 : downward ? -1 : 0;
            continue;
        }
        const int side = orientation(a, b, p);
        if (side == 0 && within_collinear_segment(p, a, b)) return location::boundary;
        if (upward && side > 0) ++winding;
        if (downward && side < 0) --winding;
    }
    return winding != 0 ? location::inside : location::outside;
}

/// Locates P in the closed region of the polygon whose vertices, in NT, are
/// `v` (topology from `shape`), with the covering from origin `o`. When P is the
/// origin itself the sum is taken from the first vertex instead: any origin
/// gives the same winding number. Region as for polygon: boundary when P is on
/// an edge, inside when the winding number is not zero (a point inside a hole
/// is outside). Signs of orientations only: exact when NT is. Time linear in
/// the number of edges; influence_areas::locate visits only nearby cones.
template <class NT>
location locate(const polygon& shape, const std::vector<point<NT>>& v, const point<NT>& o, const point<NT>& p) {
    return feito_locate(shape, v, same_point(p, o) ? v.front() : o, p);
}

/// Locates P in the region covered by `cov` (as the overload above).
template <class NT>
location locate(const triangle_covering<NT>& cov, const point<NT>& p) {
    return locate(cov.shape(), cov.vertices(), cov.origin(), p);
}

}  // namespace influence2d
