// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Both polygons posed in the world, answered exactly at nearly double's
/// cost: the query in `certified`, and again in exact rationals only when one
/// of its signs is not certain.

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/fallback.hpp"
#include "influence2d/query/both_posed.hpp"

namespace influence2d {

/// The exact answer of intersects(a, pose_a, b, pose_b), both polygons posed
/// in the world (query/both_posed.hpp), at nearly double's cost (its doubts
/// noted, noted_fallback, as certified_intersects).
inline bool certified_intersects(const polygon& a, const pose& pose_a, const polygon& b, const pose& pose_b) {
    return noted_fallback::run([&] { return intersects<certified>(a, pose_a, b, pose_b); },
                               [&] { return intersects<exact_rational>(a, pose_a, b, pose_b); });
}

}  // namespace influence2d
