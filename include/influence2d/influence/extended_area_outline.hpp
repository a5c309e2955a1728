// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The outline of an edge's extended influence area (predicates/extended_area.hpp),
/// in double, for drawing it: the corners of the band, or of the capsule's
/// straight part. The band's caps follow in_band's rule.

#include <algorithm>
#include <cmath>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/extended_area.hpp"

namespace influence2d {

/// Whether the band of the edge [a, b] has vertical caps (lines x = constant):
/// in_band's rule, vertical when |slope| <= 1 (a zero-length edge included),
/// horizontal otherwise.
template <class NT>
bool band_has_vertical_caps(const point<NT>& a, const point<NT>& b) {
    const NT abx = b.x - a.x, aby = b.y - a.y;
    return compare_values<NT>(aby * aby, abx * abx) <= 0;
}

/// The outline of the extended area of length n of an edge, as
/// outline_of_extended_area gives it.
struct extended_area_outline {
    /// A zero-length edge's capsule: the disc of radius n about the edge's
    /// point; `corners` is empty.
    bool disc = false;
    /// A zero-length edge's band: in_band keeps the vertical strip
    /// |x - a.x| <= n, unbounded in y; `corners` is empty.
    bool strip = false;
    /// The band's four corners in order round it (start cap, end cap); the
    /// capsule's straight part, [a, b] offset by n to its left and then to its
    /// right: a + n, b + n, b - n, a - n (its round ends, the half-discs of
    /// radius n about a and b away from the edge, are not in the list).
    std::vector<point<double>> corners;
};

/// The outline of the extended area of length n >= 0 of the edge [a, b] in
/// `shape`, computed in double (rounded: for drawing; membership is
/// in_extended_area's). The band is the one in_band tests: between the
/// parallels to [a, b] at distance n, cut by the caps at n beyond the ends,
/// vertical or horizontal by band_has_vertical_caps.
inline extended_area_outline outline_of_extended_area(extended_area shape, const point<double>& a,
                                                      const point<double>& b, double n) {
    extended_area_outline out;
    const double dx = b.x - a.x, dy = b.y - a.y;
    if (dx == 0 && dy == 0) {
        out.disc = shape == extended_area::capsule;
        out.strip = !out.disc;
        return out;
    }
    const double len = std::hypot(dx, dy);
    if (shape == extended_area::capsule) {
        const double nx = -dy / len * n, ny = dx / len * n;  // the left normal, of length n
        out.corners = {{a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}};
        return out;
    }
    // With vertical caps u is x and v is y, else the reverse; the parallels
    // are v = v(u) +- h, the caps u = lo - n and hi + n.
    const bool vertical = band_has_vertical_caps(a, b);
    const double au = vertical ? a.x : a.y, av = vertical ? a.y : a.x;
    const double bu = vertical ? b.x : b.y;
    const double du = vertical ? dx : dy, dv = vertical ? dy : dx;
    const double h = n * len / std::fabs(du);
    const double lo = std::min(au, bu) - n, hi = std::max(au, bu) + n;
    const auto corner = [&](double u, double side) {
        const double v = av + dv / du * (u - au) + side * h;
        return vertical ? point<double>{u, v} : point<double>{v, u};
    };
    out.corners = {corner(lo, -1), corner(hi, -1), corner(hi, 1), corner(lo, 1)};
    return out;
}

}  // namespace influence2d
