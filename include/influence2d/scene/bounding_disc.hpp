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
#include "influence2d/predicates/filters.hpp"

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
/// factor of eight, which also covers the one rounding of the product in
/// posed_disc.
inline constexpr double disc_radius_widening = 0x1p-48;

/// A disc holding p's closed region: centred on the centre of p's box, its
/// radius the greatest distance from that centre to a vertex, widened by
/// disc_radius_widening (every vertex lies in the disc, so its hull does,
/// and the region with it). hypot neither overflows nor underflows on the
/// differences; a radius that does overflow is +infinity, and a NaN
/// coordinate gives a NaN radius (disc_box then gives no box). An
/// empty polygon gives radius 0 at NaN.
inline disc bounding_disc(const polygon& p) {
    disc d;
    d.centre = p.bounds().centre();
    for (const point<double>& v : p.vertices()) {
        const double r = std::hypot(v.x - d.centre.x, v.y - d.centre.y);
        if (std::isnan(r)) return {d.centre, r};
        d.radius = std::max(d.radius, r);
    }
    d.radius *= 1 + disc_radius_widening;
    return d;
}

/// Disc d posed by q: its centre posed in double, its radius widened by
/// pose_scale_widening (q's map is sqrt(c^2 + s^2) times a rotation, for
/// its doubles c and s: predicates/filters.hpp). The posed region of a
/// polygon that d holds lies in the disc about the exactly posed centre
/// with that radius; the centre in double errs from it by the posing's
/// error (less than placing_margin of the polygon's scale), which the
/// caller allows for.
inline disc posed_disc(const disc& d, const rotation_pose& q) {
    return {q.apply<double>(d.centre), d.radius * (1 + pose_scale_widening)};
}

/// The box of disc d, each side rounded to nearest (within an ulp of
/// |centre| + radius, which the caller's margin covers); empty when a
/// bound is not finite (a NaN or infinite radius or centre, or a sum that
/// overflows): the caller then keeps its other bounds.
inline box disc_box(const disc& d) {
    const box out{d.centre.x - d.radius, d.centre.y - d.radius, d.centre.x + d.radius, d.centre.y + d.radius};
    if (!std::isfinite(out.min_x) || !std::isfinite(out.min_y) || !std::isfinite(out.max_x) ||
        !std::isfinite(out.max_y))
        return box{};
    return out;
}

}  // namespace influence2d
