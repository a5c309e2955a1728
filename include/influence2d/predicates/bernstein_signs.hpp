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
/// What underflow may take from a halving: each of the three means may lose
/// 2^-1075 when it is subnormal.
inline constexpr double casteljau_underflow = 0x1p-1072;
/// The relative widening of a bound for its own rounding (two sums and a
/// product, each relative 2^-53), as certified's.
inline constexpr double casteljau_widening = 1 + 0x1p-48;

/// Four Bernstein coefficients of a cubic on an interval (times a positive
/// constant) in double, each within e of its exact value, all of magnitude
/// at most m. A NaN or infinite value or bound leaves every sign uncertain.
class bounded_bernstein {
public:
    /// The coefficients v, each within e of its exact value (the caller
    /// vouches for e). A NaN or infinite value or a NaN bound makes the
    /// bound infinite: no sign certain.
    bounded_bernstein(const std::array<double, 4>& v, double e)
        : bounded_bernstein(v, e, std::max({std::fabs(v[0]), std::fabs(v[1]), std::fabs(v[2]), std::fabs(v[3])})) {}

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

    /// The coefficients on the two halves of the interval (de Casteljau at
    /// 1/2), in double, with their bound: the means of values within e of
    /// exact ones lie within e of the exact means before their own rounding
    /// (casteljau_rounding of m), which underflow may add to
    /// (casteljau_underflow); the sum computed, then widened.
    std::pair<bounded_bernstein, bounded_bernstein> halves() const {
        const auto mean = [](double x, double y) { return (x + y) * 0.5; };
        const double b01 = mean(v_[0], v_[1]), b12 = mean(v_[1], v_[2]), b23 = mean(v_[2], v_[3]);
        const double b012 = mean(b01, b12), b123 = mean(b12, b23), mid = mean(b012, b123);
        const double e = (e_ + casteljau_rounding * m_ + casteljau_underflow) * casteljau_widening;
        const double m = m_ * casteljau_growth;
        return {bounded_bernstein({v_[0], b01, b012, mid}, e, m), bounded_bernstein({mid, b123, b23, v_[3]}, e, m)};
    }

private:
    /// v within e, of magnitudes at most m; the bound infinite for a NaN
    /// or infinite value (an overflowed mean among them), a NaN bound or an
    /// infinite m.
    bounded_bernstein(const std::array<double, 4>& v, double e, double m) : v_(v), e_(e), m_(m) {
        if (std::isnan(e) || !std::isfinite(m) || !std::isfinite(v[0]) || !std::isfinite(v[1]) ||
            !std::isfinite(v[2]) || !std::isfinite(v[3]))
            e_ = HUGE_VAL;
    }

    std::array<double, 4> v_;
    double e_;
    double m_;  ///< at least every |v_[i]|
};

}  // namespace influence2d
