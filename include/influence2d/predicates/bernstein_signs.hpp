// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether a cubic certainly keeps one strict sign over an interval, from
/// its Bernstein coefficients there, known in double within one bound for
/// all four: the sign tests of the rational model's sifting, with the
/// interval halved in double (de Casteljau at 1/2) and the bound carried
/// once per cubic instead of once per operation.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

namespace influence2d {

/// The relative bound of the rounding that a halving adds to each
/// coefficient, against the bound m of the coefficients' magnitudes: a
/// coefficient of a half is made by at most three rounded means (a + b) / 2
/// (the sum rounded, relative u = 2^-53; the halving exact), of values of
/// magnitude at most m, m (1 + u) and m (1 + u)^2 (a mean is no larger than
/// the larger of its two values, plus its own rounding), so they add at most
/// u m (1 + (1 + u) + (1 + u)^2) < 3.01 u m; 2^-51 m = 4 u m covers it.
inline constexpr double casteljau_rounding = 0x1p-51;
/// The growth of the bound of magnitudes over one halving: at most (1 + u)^3
/// < 1 + 2^-51.4 (three rounded means); 1 + 2^-50, and its product with m
/// rounded (relative 2^-53 at most), stays above it.
inline constexpr double casteljau_growth = 1 + 0x1p-50;
/// The largest bound of magnitudes a halving takes: below it no sum of two
/// coefficients overflows (2 x 2^1022 = 2^1023). Above it the halves' bound
/// is infinite.
inline constexpr double casteljau_ceiling = 0x1p1022;
/// What underflow may take from a halving or from the change of basis
/// (of_power): a sum whose result is subnormal is exact, so only the
/// products lose (2^-1075 each when subnormal): three halvings by 2 along a
/// coefficient's path in a halving, one product by 3 in the change of
/// basis; 3 x 2^-1075 < 2^-1072.
inline constexpr double basis_underflow = 0x1p-1072;
/// The relative bound of the rounding of the change of basis (of_power),
/// against the bound m of the power coefficients' magnitudes. The
/// coefficients, times 3, are 3 a0 = (a0 + a0) + a0, 3 a0 + a1,
/// ((3 a0 + a1) + a1) + a2 and (((a0 + a1) + a2) + a3) x 3, each operation
/// rounded (relative u) on a result of magnitude at most its terms' weights
/// times m: at most 3 u m for 3 a0, 7 u m for the second, 18 u m for the
/// third (3 + 4 + 5 + 6) and 3 (2 + 3 + 4) u m + 12 u m = 39 u m for the
/// last, each times (1 + u)^4 for the growth along the way: below 39.1 u m;
/// 2^-47 m = 64 u m covers it.
inline constexpr double basis_rounding = 0x1p-47;
/// The factor of the power coefficients' bound in the Bernstein ones' (the
/// largest sum of a coefficient's weights: 3 + 3 + 3 + 3 in the last).
inline constexpr double basis_weight = 12;
/// The relative widening of a bound for its own rounding (a few sums and
/// products, each relative 2^-53), as certified's.
inline constexpr double bound_widening = 1 + 0x1p-48;

/// Descartes' rule on a cubic's Bernstein coefficients from their signs
/// (-1, 0 or +1, each certain): when the signs change exactly once (zeros
/// skipped) and both ends are non-zero, the cubic has one root inside the
/// interval, a simple one (the roots there, with multiplicity, are at most
/// the changes and of their parity); then the first sign, else 0.
inline int single_sign_change_of(const std::array<int, 4>& signs) {
    int changes = 0, last = 0;
    for (const int sign : signs) {
        if (sign == 0) continue;
        changes += last != 0 && sign != last;
        last = sign;
    }
    return changes == 1 && signs[0] != 0 && signs[3] != 0 ? signs[0] : 0;
}

/// Four Bernstein coefficients of a cubic on an interval (times a positive
/// constant) in double, each within e of its exact value, all of magnitude
/// at most m. A NaN or infinite value or bound leaves every sign uncertain.
class bounded_bernstein {
public:
    /// The coefficients v, each within e of its exact value (the caller
    /// vouches for e). A NaN or infinite value or a NaN bound makes the
    /// bound infinite: no sign certain.
    bounded_bernstein(const std::array<double, 4>& v, double e)
        : v_(v), e_(e), m_(std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2]), std::fabs(v[3])})) {
        if (std::isnan(e) || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]) ||
            !std::isfinite(v[3]))
            e_ = HUGE_VAL;
    }

    /// The Bernstein coefficients on [0, 1], times 3, of the cubic a0 + a1 x
    /// + a2 x^2 + a3 x^3 whose coefficients a are each within e of their
    /// exact values: 3 a0, 3 a0 + a1, 3 a0 + 2 a1 + a2 and 3 (a0 + a1 + a2 +
    /// a3), in double, within basis_weight e plus their rounding
    /// (basis_rounding of the largest |a_k|, basis_underflow), widened.
    static bounded_bernstein of_power(const std::array<double, 4>& a, double e) {
        const double three_a0 = a[0] + a[0] + a[0], b1 = three_a0 + a[1];
        const double m = std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2]), std::fabs(a[3])});
        const double bound = (basis_weight * e + basis_rounding * m + basis_underflow) * bound_widening;
        return bounded_bernstein({three_a0, b1, b1 + a[1] + a[2], (a[0] + a[1] + a[2] + a[3]) * 3}, bound);
    }

    /// The coefficients in double.
    const std::array<double, 4>& values() const { return v_; }
    /// The bound of every coefficient's error.
    double error() const { return e_; }

    /// Whether every coefficient certainly has the strict sign `sign` (+1 or
    /// -1): beyond the bound (false for a NaN value or bound). Then the cubic
    /// has that sign throughout the interval (it lies in the hull of its
    /// coefficients).
    bool of_sign(int sign) const {
        for (const double x : v_)
            if (!(sign > 0 ? x > e_ : x < -e_)) return false;
        return true;
    }

    /// single_sign_change_of the coefficients' signs when every one is
    /// certain (beyond the bound, or 0 with a bound of 0); otherwise 0.
    int single_sign_change() const {
        std::array<int, 4> signs{};
        for (std::size_t i = 0; i < 4; ++i) {
            const double x = v_[i];
            if (x > e_) {
                signs[i] = 1;
            } else if (x < -e_) {
                signs[i] = -1;
            } else if (!(x == 0 && e_ == 0)) {
                return 0;
            }
        }
        return single_sign_change_of(signs);
    }

    /// The coefficients on the two halves of the interval (de Casteljau at
    /// 1/2), in double, with their bound: the means of values within e of
    /// exact ones lie within e of the exact means before their own rounding
    /// (casteljau_rounding of m), which underflow may add to
    /// (basis_underflow); the sum computed, then widened. Infinite for m
    /// above casteljau_ceiling (or NaN), where a mean may overflow.
    std::pair<bounded_bernstein, bounded_bernstein> halves() const {
        const auto mean = [](double x, double y) { return (x + y) * 0.5; };
        const double b01 = mean(v_[0], v_[1]), b12 = mean(v_[1], v_[2]), b23 = mean(v_[2], v_[3]);
        const double b012 = mean(b01, b12), b123 = mean(b12, b23), mid = mean(b012, b123);
        const double e =
            m_ <= casteljau_ceiling ? (e_ + casteljau_rounding * m_ + basis_underflow) * bound_widening : HUGE_VAL;
        const double m = m_ * casteljau_growth;
        return {bounded_bernstein({v_[0], b01, b012, mid}, e, m), bounded_bernstein({mid, b123, b23, v_[3]}, e, m)};
    }

private:
    /// v within e, of magnitudes at most m (the halves: their values are
    /// finite when the parent's are and m is at most casteljau_ceiling,
    /// and their bound infinite otherwise).
    bounded_bernstein(const std::array<double, 4>& v, double e, double m) : v_(v), e_(e), m_(m) {}

    std::array<double, 4> v_;
    double e_;
    double m_;  ///< at least every |v_[i]|
};

}  // namespace influence2d
