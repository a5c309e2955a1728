// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Where a point known within a margin lies in a polygon fixed in its own
/// frame, by the crossings of a ray counted over the edges its edge tree
/// finds near the ray: a locate whose time grows with the edges near the
/// ray's line, not with all of them.

#include <cstdint>
#include <optional>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/influence/edge_tree.hpp"
#include "influence2d/predicates/filters.hpp"

namespace influence2d {

/// Where every point within e of p (on each coordinate) lies in the closed
/// region of `shape`, whose vertices are exact in double (a polygon in its
/// own frame), `tree` being shape's edge tree; nullopt when the doubles
/// cannot settle it for all of them.
///
///   winding <- 0
///   each edge whose box the tree finds not certainly off the ray from p
///   towards +x by 2e (edge_tree::query_ray; the others add nothing):
///       its crossing for every such point (certain_crossing_within):
///       unknown: nullopt; else add it to winding
///   inside when winding is not 0, else outside
///
/// An answer holds for every point within e of p: each crossing counted is
/// that point's, so the winding number (edge_crossing's sum, that of
/// locate_by_crossings) is. Never the boundary: an edge settled is
/// certainly off every such point. A point placed into the polygon's frame
/// by a rigid motion evaluated in double, within e of its exact placing,
/// is located so in the polygon posed by that motion: an orientation-
/// preserving similarity keeps winding numbers.
inline std::optional<location> certain_location_through_tree(const polygon& shape, const edge_tree& tree,
                                                             const point<double>& p, double e) {
    long long winding = 0;
    const bool unsettled = tree.query_ray(p, 2 * e, [&](std::uint32_t i) {
        const int c = certain_crossing_within(shape.vertex(i), shape.vertex(shape.next(i)), p, e);
        if (c == crossing_unknown) return true;
        winding += c;
        return false;
    });
    if (unsettled) return std::nullopt;
    return winding != 0 ? location::inside : location::outside;
}

}  // namespace influence2d
