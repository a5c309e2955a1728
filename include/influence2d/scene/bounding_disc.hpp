// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which disc holds a polygon, and which box holds that disc once the
/// polygon is posed: a box that does not grow when the polygon turns.

#include <algorithm>
#include <cmath>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"

namespace influence2d {

/// A closed disc: every point within `radius` of `centre`.
struct disc {
    point<double> centre{0, 0};  ///< its centre
    double radius = 0;           ///< its radius (0 for a point, NaN when unknown)
};

/// The relative widening of bounding_disc's radius: each distance is
/// std::hypot of two differences, each difference rounded once (relative
/// error u = 2^-53) and hypot within one ulp (2u) in glibc, so the
/// computed distance is within 4u of the exact one; 2^-48 = 32u leaves a
/// factor of eight, which also covers the one rounding of the product with
/// rotation_stretch in posed_disc_box.
inline constexpr double disc_radius_widening = 0x1p-48;

/// A disc holding p's closed region: centred on the centre of p's box, its
/// radius the greatest distance from that centre to a vertex, widened by
/// disc_radius_widening (every vertex lies in the disc, so its hull does,
/// and the region with it). hypot neither overflows nor underflows on the
/// differences; a radius that does overflow is +infinity, and a NaN
/// coordinate gives a NaN radius (posed_disc_box then gives no box). An
/// empty polygon gives radius 0 at NaN.
inline disc bounding_disc(const polygon& p) {
    disc d;
    d.centre = p.bounds().centre();
    for (std::size_t k = 0; k < p.size(); ++k) {
        const point<double>& v = p.vertex(k);
        const double r = std::hypot(v.x - d.centre.x, v.y - d.centre.y);
        d.radius = r != r ? r : std::max(d.radius, r);
        if (d.radius != d.radius) break;
    }
    d.radius *= 1 + disc_radius_widening;
    return d;
}

/// An upper bound of sqrt(c^2 + s^2) for the pose's doubles c and s, the
/// factor by which the pose stretches every length (its map is c^2 + s^2
/// times a rotation's, up to the square root). c^2 + s^2 rounds three times
/// in double, so its exact value is within (1 + 2^-51) of the computed one;
/// sqrt(x) <= max(1, x) for every x >= 0.
inline double rotation_stretch(const rotation_pose& q) {
    return std::max(1.0, (q.c * q.c + q.s * q.s) * (1 + 0x1p-51));
}

/// The box of disc d posed by q (the disc of q's image of the centre whose
/// radius is d's stretched by rotation_stretch), the centre posed in
/// double: the posed region of a polygon that d holds lies in it once it
/// is widened by the posing's error on the centre (placing_margin of the
/// polygon's scale, predicates/filters.hpp). Empty when a bound is not
/// finite (a NaN or infinite radius or centre, or a sum that overflows):
/// the caller then keeps its other bound.
inline box posed_disc_box(const disc& d, const rotation_pose& q) {
    const point<double> c = q.apply<double>(d.centre);
    const double r = d.radius * rotation_stretch(q);
    const box out{c.x - r, c.y - r, c.x + r, c.y + r};
    if (!std::isfinite(out.min_x) || !std::isfinite(out.min_y) || !std::isfinite(out.max_x) ||
        !std::isfinite(out.max_y))
        return box{};
    return out;
}

}  // namespace influence2d
