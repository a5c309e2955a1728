// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The exact exit distance (the directional penetration depth), rounded to
/// double, at nearly double's cost.

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/motion/exit_distance.hpp"
#include "influence2d/number/cgal.hpp"

namespace influence2d {

/// The exit distance of exit_distance<exact_rational>
/// (motion/exit_distance.hpp) rounded to the nearest double, at nearly
/// double's cost: filtered_exit_distance in exact rationals (the search in
/// `certified`, again in exact rationals only when a sign is in doubt; the
/// exit's one event evaluated exactly to round it). `*by_filter`, when
/// given, says whether the search in `certified` answered. Throws as
/// exit_distance.
inline double certified_exit_distance(const polygon& a, const polygon& b, const pose& q, double dx, double dy,
                                      bool* by_filter = nullptr) {
    return filtered_exit_distance<exact_rational>(a, b, q, dx, dy, by_filter);
}

}  // namespace influence2d
