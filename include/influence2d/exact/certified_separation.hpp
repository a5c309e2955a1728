// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The exact separation rounded to double, at about double's cost.

#include <cmath>
#include <cstddef>

#include "influence2d/core/feature.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/distance.hpp"

namespace influence2d {

/// The separation of certified_separation: the exact answer's features, its
/// points and its distance rounded to double.
struct certified_separation_result {
    double distance = 0;          ///< within one unit in the last place of the exact distance (distance_of)
    double squared_distance = 0;  ///< the exact squared distance rounded to the nearest double
    feature static_feature{};     ///< as separation_result, exactly
    feature moving_feature{};     ///< as separation_result, exactly
    point<double> static_point;   ///< the exact closest point of A, each coordinate rounded to the nearest double
    point<double> moving_point;   ///< the exact closest point of posed B, rounded likewise
    bool meet = false;            ///< whether the regions meet (exact)
    std::size_t exact_pairs = 0;  ///< edge pairs evaluated in exact rationals
};

/// The exact separation, separation<exact_rational>(a, b, q) on the polygons
/// (distance/separation.hpp), rounded to double: the same features, its
/// points and distance rounded. It costs about double's: the search runs in
/// double with proven bounds (phase 1), only the candidate pairs those bounds
/// cannot separate from the least are evaluated in exact rationals (usually
/// the one or few pairs at the least distance), and a ring's vertex is
/// located in `certified`, again in exact rationals only when a sign is in
/// doubt (phase 3 of an exact field on unprepared polygons). Throws
/// invalid_input for an empty polygon or a pose with a NaN or infinite
/// component.
inline certified_separation_result certified_separation(const polygon& a, const polygon& b, const pose& q) {
    const separation_result<exact_rational> exact = separation<exact_rational>(a, b, q);
    certified_separation_result r;
    const scaled_double squared = scaled_nearest(exact.squared_distance);  // (distance_of's rounding)
    r.squared_distance = std::ldexp(squared.mantissa, squared.exponent);
    r.distance = std::ldexp(std::sqrt(squared.mantissa), squared.exponent / 2);
    r.static_feature = exact.static_feature;
    r.moving_feature = exact.moving_feature;
    r.static_point = {nearest_double(exact.static_point.x), nearest_double(exact.static_point.y)};
    r.meet = exact.meet();
    // (Meeting: one point.)
    r.moving_point = r.meet ? r.static_point
                            : point<double>{nearest_double(exact.moving_point.x), nearest_double(exact.moving_point.y)};
    r.exact_pairs = exact.evaluated_pairs;
    return r;
}

}  // namespace influence2d
