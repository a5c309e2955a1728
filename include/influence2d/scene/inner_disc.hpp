// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which disc about a polygon's box centre lies in its closed region: a
/// point certainly in that disc, once the polygon is posed, lies in the
/// posed region without a locate.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/predicates/distance.hpp"
#include "influence2d/scene/bounding_disc.hpp"

namespace influence2d {

/// The radius of a closed disc about the centre m of p's box (box::centre)
/// that lies in p's closed region, or 0 when there is none to use: m is in
/// the region's interior (locate_by_crossings in `certified`, exact on the
/// input doubles), and the radius is a lower bound of the least distance
/// from m to an edge of any ring: each distance from point_segment_estimate
/// less its proven error, the least of them shrunk by bound_rounding for
/// that difference's own rounding (then every point within the radius of m
/// lies off every edge, on m's side: in the region). 0 also for an empty
/// polygon, a distance not known, and a radius below the least normal
/// double.
inline double inner_radius(const polygon& p) {
    if (p.size() == 0) return 0;
    const point<double> m = p.bounds().centre();
    try {
        const doubt_raising raised;  // (what is built here outlives any doubt_noting)
        std::vector<point<certified>> v;
        v.reserve(p.size());
        for (const point<double>& w : p.vertices()) v.push_back({certified(w.x), certified(w.y)});
        if (locate_by_crossings(p, v, point<certified>{certified(m.x), certified(m.y)}) != location::inside) return 0;
    } catch (const uncertain_sign&) {
        return 0;
    }
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const estimate d = point_segment_estimate(m, p.vertex(i), p.vertex(p.next(i)));
        least = std::min(least, d.value - d.error);
    }
    const double r = least * (1 - bound_rounding);
    return std::isfinite(r) && r >= std::numeric_limits<double>::min() ? r : 0;
}

/// The disc about the centre of p's box of radius inner_radius(p), in p's
/// closed region (radius 0: none).
inline disc inner_disc(const polygon& p) { return {p.bounds().centre(), inner_radius(p)}; }

}  // namespace influence2d
