// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The contact cubics of the rational model (docs/sweep.md, "The rational
/// model"): a vertex moving over one piece of a rational turning motion,
/// its coordinates cubics over a common positive factor, against a fixed
/// segment: when it lies on the segment's line (f) and between its ends (lo,
/// hi), as cubics in the piece's time; their coefficients in NT, or in double
/// with one bound per cubic for certified's terms (bounded_coefficients).

#include <algorithm>
#include <array>
#include <cmath>

#include "influence2d/core/point.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/number/unit_roundoff.hpp"
#include "influence2d/predicates/bernstein_signs.hpp"
#include "influence2d/predicates/polynomial_roots.hpp"

namespace influence2d {

/// A point moving over a piece, scaled by h(tau) = 1 + w^2 tau^2 (> 0):
/// x(tau) / h(tau), y(tau) / h(tau) its coordinates; x and y cubics.
template <class NT>
struct moving_point {
    NT x[4];  ///< x(tau)'s coefficients, lowest degree first
    NT y[4];  ///< y(tau)'s coefficients, lowest degree first
};

/// The cubics of a contact of a moving point P = (x, y) / (h l) with the
/// fixed segment from p to q, l > 0 a constant: f = (q - p) x (P h l - p h
/// l) (zero when P is on the segment's line), and the two conditions that P
/// lies between the ends: lo = (q - p) . (P h l - p h l) >= 0, hi = |q -
/// p|^2 h l - lo >= 0. (l is 1 for B's vertex in A's frame; for A's vertex
/// in B's frame it is c^2 + s^2 of the piece's base rotation, which the
/// doubles c and s leave a hair off 1: the frame is turned back by the
/// adjugate R^T = (c^2 + s^2) R^-1, exactly.)
template <class NT>
struct contact_cubics {
    polynomial<NT> f;   ///< zero when P is on the segment's line
    polynomial<NT> lo;  ///< >= 0 when P is not before the segment's start
    polynomial<NT> hi;  ///< >= 0 when P is not beyond its end
};

/// The coefficients of f, lo and hi (contact_cubics), lowest degree first,
/// untrimmed.
template <class NT>
using cubic_coefficients = std::array<std::array<NT, 4>, 3>;

/// The coefficients of the cubics of m on the segment from p to q
/// (contact_cubics); lo's and hi's left 0 unless `ends`.
template <class NT>
cubic_coefficients<NT> coefficients_of(const moving_point<NT>& m, const NT& w2, const NT& l, const point<double>& p,
                                       const point<double>& q, bool ends = true) {
    using tr = number_traits<NT>;
    const NT ex = tr::from_double(q.x) - tr::from_double(p.x), ey = tr::from_double(q.y) - tr::from_double(p.y);
    const NT px = NT(tr::from_double(p.x) * l), py = NT(tr::from_double(p.y) * l);
    cubic_coefficients<NT> out;
    NT yx[4], yy[4];
    for (int k = 0; k < 4; ++k) {
        yx[k] = m.x[k];
        yy[k] = m.y[k];
    }
    // P h l - p h l, h = 1 + w^2 tau^2.
    yx[0] = NT(yx[0] - px);
    yy[0] = NT(yy[0] - py);
    yx[2] = NT(yx[2] - w2 * px);
    yy[2] = NT(yy[2] - w2 * py);
    for (std::size_t k = 0; k < 4; ++k) out[0][k] = NT(ex * yy[k] - ey * yx[k]);
    if (!ends) return out;
    const NT e2 = NT((ex * ex + ey * ey) * l);
    for (std::size_t k = 0; k < 4; ++k) {
        out[1][k] = NT(ex * yx[k] + ey * yy[k]);
        out[2][k] = NT(-out[1][k]);
    }
    out[2][0] = NT(out[2][0] + e2);
    out[2][2] = NT(out[2][2] + w2 * e2);
    return out;
}

/// The relative bound of the rounding of a coefficient of f or lo made in
/// double from the edge's direction (ex, ey) = q - p, rounded, and the
/// moving point's terms yx_k, yy_k (bounded_coefficients), against S Y, S =
/// |ex| + |ey| and Y the largest |yx_k|, |yy_k|: the direction's rounding
/// (relative u = 2^-53 each) moves ex yy_k - ey yx_k by at most u S (Y + E),
/// the two products' rounding by u S Y, the sum's by u S Y (1 + u): 3.01 u S
/// Y beyond the terms' own error S E (1 + u); 2^-51 S Y covers the first.
inline constexpr double cubic_rounding = 0x1p-51;
/// The same for e2 = (ex^2 + ey^2) l against s2 |l|, s2 the sum computed:
/// each square is within u (2 + u) of the exact direction's square, each
/// rounds by u, the sum by u s2, so that s2 is within 4.02 u s2 of the exact
/// sum of squares; the product with l's value adds u s2 |l| and l's error
/// el adds s2 el (1 + 4.02 u): 5.02 u s2 |l| + s2 el (1 + 4.02 u), which
/// 2^-50 s2 |l| + s2 el, widened, covers.
inline constexpr double squared_length_rounding = 0x1p-50;
/// What underflow may take from the products of a coefficient (at most
/// three, 2^-1075 each when subnormal; a sum whose result is subnormal is
/// exact): 3 x 2^-1075 < 2^-1072.
inline constexpr double cubic_underflow = 0x1p-1072;

/// The coefficients of the contact cubics f, lo and hi (coefficients_of)
/// in double, with one bound of the error for each cubic's four.
struct bounded_cubics {
    cubic_coefficients<double> c{};  ///< f's, lo's and hi's coefficients, lowest degree first
    std::array<double, 3> e{};       ///< the bound of each cubic's coefficients' errors
};

/// coefficients_of for certified's moving point m (and w^2, l), made in
/// double with one bound per cubic instead of certified's bound on each
/// operation: the terms yx_k, yy_k of P h l - p h l in certified (their
/// largest error E, their largest magnitude Y), then in double
///   f_k  = ex yy_k - ey yx_k          within S (E + cubic_rounding Y)
///   lo_k = ex yx_k + ey yy_k          within the same
///   hi_k = -lo_k, plus e2 at k = 0 and w^2 e2 at k = 2, e2 = s2 l
///         (squared_length_rounding), within lo's bound, the larger of the
///         two added terms' bounds and u of the larger sum
/// each bound widened for its own rounding (bound_widening) and given
/// cubic_underflow. A NaN or infinite term or bound makes them infinite.
inline bounded_cubics bounded_coefficients(const moving_point<certified>& m, const certified& w2, const certified& l,
                                           const point<double>& p, const point<double>& q) {
    const certified px = certified(p.x) * l, py = certified(p.y) * l;
    const certified yx[4] = {m.x[0] - px, m.x[1], m.x[2] - w2 * px, m.x[3]};
    const certified yy[4] = {m.y[0] - py, m.y[1], m.y[2] - w2 * py, m.y[3]};
    double e_y = 0, y = 0;
    for (const certified* t : {yx, yy})
        for (int k = 0; k < 4; ++k) {
            const bool known = !std::isnan(t[k].error()) && std::isfinite(t[k].value());
            e_y = known ? std::max(e_y, t[k].error()) : HUGE_VAL;
            y = std::max(y, std::fabs(t[k].value()));
        }
    const double ex = q.x - p.x, ey = q.y - p.y, s = std::fabs(ex) + std::fabs(ey);
    bounded_cubics out;
    auto &f = out.c[0], &lo = out.c[1], &hi = out.c[2];
    for (int k = 0; k < 4; ++k) {
        f[k] = ex * yy[k].value() - ey * yx[k].value();
        lo[k] = ex * yx[k].value() + ey * yy[k].value();
        hi[k] = -lo[k];
    }
    const double e_f = (s * (e_y + cubic_rounding * y) + cubic_underflow) * bound_widening;
    // e2 = (ex^2 + ey^2) l and w^2 e2, each with its bound.
    const double s2 = ex * ex + ey * ey, lv = l.value(), wv = w2.value();
    const double e2 = s2 * lv, term = wv * e2;
    const double e_e2 = (s2 * (squared_length_rounding * std::fabs(lv) + l.error()) + cubic_underflow) * bound_widening;
    const double e_term = (w2.error() * (std::fabs(e2) + e_e2) + std::fabs(wv) * e_e2 +
                           unit_roundoff * std::fabs(wv) * std::fabs(e2) + cubic_underflow) *
                          bound_widening;
    hi[0] = hi[0] + e2;
    hi[2] = hi[2] + term;
    const double sums = std::max(std::fabs(hi[0]), std::fabs(hi[2]));
    const double e_hi = (e_f + std::max(e_e2, e_term) + unit_roundoff * sums) * bound_widening;
    out.e = {e_f, e_f, e_hi};
    for (double& e : out.e)
        if (std::isnan(e)) e = HUGE_VAL;
    return out;
}

/// The cubics of m on the segment from p to q, trimmed; lo and hi left
/// empty unless `ends` (when the sifting found both positive).
template <class NT>
contact_cubics<NT> cubics_of(const moving_point<NT>& m, const NT& w2, const NT& l, const point<double>& p,
                             const point<double>& q, bool ends = true) {
    const cubic_coefficients<NT> k = coefficients_of(m, w2, l, p, q, ends);
    contact_cubics<NT> out;
    for (auto [poly, c] : {std::pair{&out.f, &k[0]}, std::pair{&out.lo, &k[1]}, std::pair{&out.hi, &k[2]}}) {
        if (poly != &out.f && !ends) break;
        poly->c.assign(c->begin(), c->end());
        poly->trimmed();
    }
    return out;
}

}  // namespace influence2d
