// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Bounding radii as upper bounds in double (docs/method.md section 9: radii carry
/// square roots, so filters use bounds, never the roots themselves).

#include <algorithm>
#include <cmath>
#include <limits>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/predicates/filters.hpp"

namespace influence2d {

/// An upper bound of the largest distance from `center` to a vertex of `shape`,
/// and so of the radius of the circle about `center` that encloses it. It
/// also bounds the radius of the polygon posed with rotation doubles c, s,
/// whose scale sqrt(c^2 + s^2) differs from 1 by less than pose_scale_widening. Time linear
/// in the number of vertices; since A's edges are segments between vertices,
/// the circle holds the whole closed region.
inline double bounding_radius(const polygon& shape, const point<double>& center) {
    long double r2 = 0;
    for (const auto& v : shape.vertices()) {
        const long double dx = static_cast<long double>(v.x) - center.x;
        const long double dy = static_cast<long double>(v.y) - center.y;
        r2 = std::max(r2, dx * dx + dy * dy);
    }
    return upper_sqrt(r2);
}

/// The largest absolute coordinate of the polygon: the scale that rounding
/// errors of its coordinates are relative to.
inline double coordinate_scale(const polygon& shape) { return largest_coordinate(shape.bounds()); }

}  // namespace influence2d
