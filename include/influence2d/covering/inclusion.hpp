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
