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
#include "influence2d/influence/bounds.hpp"
#include "influence2d/number/certified.hpp"

namespace influence2d {

/// The shrinking of inner_radius, times the polygon's scale (its largest
/// coordinate). The distances are taken on the polygon scaled by a power of
/// two to a scale in [1, 2) (exact but for coordinates that fall among the
/// subnormals, which move by less than 2^-1074 of the scale), so that no
/// square underflows or overflows (an edge shorter than 2^-500 of the
/// scale may still square to 0, and count as its first vertex, within its
/// length of the edge's distance). Each distance from the centre m to an
/// edge [a, b] is taken in double from differences of coordinates at most
/// twice the scale: to a
/// vertex, std::hypot of two rounded differences (within 4u of the exact
/// distance, u = 2^-53); to a line, |cross(b - a, m - a)| / |b - a| (a
/// cross product of rounded differences and a rounded root, within 24u of
/// the scale); the choice between them by the sign of a rounded dot product
/// errs only where the two agree within as much. So the computed least
/// distance is within 32u = 2^-48 of the scale of the exact one; 2^-40
/// leaves a factor of 256.
inline constexpr double inner_radius_slack = 0x1p-40;

/// The radius of a closed disc about the centre m of p's box (box::centre)
/// that lies in p's closed region, or 0 when there is none to use: m is in
/// the region's interior (locate_by_crossings in `certified`, exact on the
/// input doubles), and the radius is the least distance from m to an edge
/// of any ring, computed in double, less inner_radius_slack times p's
/// scale (then every point within the radius of m lies off every edge, on
/// m's side: in the region). 0 also for an empty polygon, a scale that is
/// 0 or not finite, and a radius below the least normal double.
inline double inner_radius(const polygon& p) {
    const double scale = coordinate_scale(p);
    if (p.size() == 0 || !(scale > 0) || !std::isfinite(scale)) return 0;
    const point<double> m = p.bounds().centre();
    try {
        std::vector<point<certified>> v;
        v.reserve(p.size());
        for (const point<double>& w : p.vertices()) v.push_back({certified(w.x), certified(w.y)});
        if (locate_by_crossings(p, v, point<certified>{certified(m.x), certified(m.y)}) != location::inside) return 0;
    } catch (const uncertain_sign&) {
        return 0;
    }
    // The distances on p scaled by 2^k, its scale brought into [1, 2).
    const int k = -std::ilogb(scale);
    const auto scaled = [k](const point<double>& v) { return point<double>{std::ldexp(v.x, k), std::ldexp(v.y, k)}; };
    const point<double> ms = scaled(m);
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const point<double> a = scaled(p.vertex(i)), b = scaled(p.vertex(p.next(i)));
        const double dx = b.x - a.x, dy = b.y - a.y, wx = ms.x - a.x, wy = ms.y - a.y;
        const double along = wx * dx + wy * dy, length2 = dx * dx + dy * dy;
        double d;
        if (!(along > 0) || !(length2 > 0))
            d = std::hypot(wx, wy);
        else if (along >= length2)
            d = std::hypot(ms.x - b.x, ms.y - b.y);
        else
            d = std::fabs(wx * dy - wy * dx) / std::sqrt(length2);
        least = std::min(least, d);
    }
    const double r = std::ldexp(least - inner_radius_slack * std::ldexp(scale, k), -k);
    return std::isfinite(r) && r >= std::numeric_limits<double>::min() ? r : 0;
}

}  // namespace influence2d
