// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The one-shot question answered exactly at nearly double's cost: the query
/// in `certified`, and again in exact rationals only when one of its signs is
/// not certain.

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/fallback.hpp"
#include "influence2d/query/intersects.hpp"

namespace influence2d {

/// The exact answer of intersects(a, b, q) (query/intersects.hpp) at nearly
/// double's cost: the query in `certified`, its doubts noted rather than
/// raised (noted_fallback: the one-shot query's loops run over edges and
/// rings, and it keeps nothing), and asked again in exact rationals when one
/// was.
inline bool certified_intersects(const polygon& a, const polygon& b, const pose& q) {
    return noted_fallback::run([&] { return intersects<certified>(a, b, q); },
                               [&] { return intersects<exact_rational>(a, b, q); });
}

}  // namespace influence2d
