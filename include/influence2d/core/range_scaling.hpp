// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether a query in float, double or long double should first be scaled by a
/// power of two, and by which.
///
/// The predicates multiply coordinates: an orientation is a product of two
/// differences, a contact time a ratio of two such products, compared by
/// cross-multiplication, and the exit distance's meetings scale coordinates
/// by products of times. In double,
/// coordinates near 2^+-300 already make such products overflow to infinity
/// or underflow to zero, and the answers go wrong: a time that is NaN, a
/// distance of 0 for polygons apart, a collision where there is none.
///
/// Multiplying every coordinate of a query (both polygons, the poses'
/// translations, its lengths) by 2^k changes none of its answers but the
/// lengths, which scale by 2^k, and in binary floating point it is exact: the
/// rounded computation on the scaled input is the rounded computation on the
/// input, step by step, scaled, except where the latter overflowed or fell
/// among the subnormals. So a floating query whose largest coordinate lies
/// outside [2^-W, 2^W] is answered on its input scaled to a largest
/// coordinate in [1, 2); inside the window it runs as given, and its answers
/// are those it always had.
///
///   W = max_exponent / 16 (double: 64; float: 8; long double: 1024): a
///   product of ten coordinates below 2^W stays below 2^(10 W) <= 2^(5/8 of
///   the range), and one of ten above 2^-W above 2^(-10 W), far from the
///   subnormals.
///
/// The exact and filtered types need no scaling (their arithmetic has no
/// range to leave, or falls back to one that has none), nor do quad and
/// float128, whose exponents reach 2^+-16383: a product of ten doubles, from
/// 2^-10740 to 2^10240, stays within it.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "influence2d/core/box.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"

namespace influence2d {

/// Whether queries in NT are scaled into its range: float, double and long
/// double (not GCC's __float128, whose exponent reaches as far as quad's).
template <class NT>
inline constexpr bool scaled_into_range_v =
    std::is_same_v<NT, float> || std::is_same_v<NT, double> || std::is_same_v<NT, long double>;

/// W for NT (see the file comment): coordinates of magnitude in [2^-W, 2^W]
/// are answered as given.
template <class NT>
constexpr int unscaled_exponent_limit() {
    return std::numeric_limits<NT>::max_exponent / 16;
}

/// The largest magnitude of a polygon's coordinates (from its box).
inline double largest_coordinate(const polygon& p) { return largest_coordinate(p.bounds()); }

/// The largest magnitude of a pose's translation.
inline double largest_coordinate(const pose& q) { return std::max(std::fabs(q.tx), std::fabs(q.ty)); }

/// 2^e as a double, for e in [-1074, 1024) (a power of two is exact from
/// the least subnormal to the largest power below the overflow).
constexpr double exact_power_of_two(int e) {
    double x = 1;
    for (; e > 0; --e) x *= 2;
    for (; e < 0; ++e) x /= 2;
    return x;
}

/// The power of two 2^k by which a query in NT whose largest coordinate is
/// `largest` is scaled: 0 for a type other than float, double and long double, for
/// `largest` 0, not finite, or in [2^-W, 2^W]; else -ilogb(largest), which
/// brings it into [1, 2).
template <class NT>
int range_shift(double largest) {
    if constexpr (!scaled_into_range_v<NT>) {
        (void)largest;
        return 0;
    } else {
        constexpr int w = unscaled_exponent_limit<NT>();
        // (The window's doubles, exact: ilogb(largest) lies in [-w, w]
        // exactly when largest lies in [2^-w, 2^(w+1)); most queries do.)
        constexpr double low = exact_power_of_two(-w),
                         high = w + 1 < 1024 ? exact_power_of_two(w + 1) : std::numeric_limits<double>::infinity();
        if (largest >= low && largest < high) return 0;
        if (!(largest > 0) || !std::isfinite(largest)) return 0;
        const int e = std::ilogb(largest);
        return e > w || e < -w ? -e : 0;
    }
}

/// The shift of a query on polygons a and b at poses `poses` (range_shift of
/// their largest coordinate).
template <class NT, class... Poses>
int range_shift(const polygon& a, const polygon& b, const Poses&... poses) {
    if constexpr (!scaled_into_range_v<NT>) {
        return 0;
    } else {
        double largest = std::max(largest_coordinate(a), largest_coordinate(b));
        ((largest = std::max(largest, largest_coordinate(poses))), ...);
        return range_shift<NT>(largest);
    }
}

/// The shift of a batch: polygons a and b at each of `count` poses from
/// `poses` (range_shift of their largest coordinate).
template <class NT>
int batch_range_shift(const polygon& a, const polygon& b, const pose* poses, std::size_t count) {
    if constexpr (!scaled_into_range_v<NT>) {
        return 0;
    } else {
        double largest = std::max(largest_coordinate(a), largest_coordinate(b));
        for (std::size_t k = 0; k < count; ++k) largest = std::max(largest, largest_coordinate(poses[k]));
        return range_shift<NT>(largest);
    }
}

/// A length (a distance d, a tolerance) scaled by 2^k with its query: at
/// most the largest double, which exceeds every length of the scaled query
/// as the overflowing value would; a length that is not finite unchanged
/// (for its check to refuse it as given).
inline double scaled_length(double x, int k) {
    return std::isfinite(x) ? std::min(std::ldexp(x, k), std::numeric_limits<double>::max()) : x;
}

/// A pose with its translation scaled by 2^k; the angle unchanged.
inline pose scaled_by_power_of_two(const pose& q, int k) { return {std::ldexp(q.tx, k), std::ldexp(q.ty, k), q.theta}; }

/// A pose already turned into its cosine and sine with its translation
/// scaled by 2^k; c and s unchanged, so that every point it poses is the
/// same pose's point scaled by 2^k, rounding for rounding.
inline rotation_pose scaled_by_power_of_two(rotation_pose t, int k) {
    t.tx = std::ldexp(t.tx, k);
    t.ty = std::ldexp(t.ty, k);
    return t;
}

/// Whether x times 2^k is exact: it comes back from 2^k and 2^-k unchanged
/// (a product that overflows, or loses bits among the subnormals, does not).
inline bool scales_exactly(double x, int k) { return std::ldexp(std::ldexp(x, k), -k) == x; }

/// Whether scaling the polygons and the poses' translations by 2^k is exact,
/// coordinate by coordinate (scales_exactly): the scaled query is then the
/// same question, with the same exact answer scaled.
template <class... Poses>
bool scales_exactly(const polygon& a, const polygon& b, int k, const Poses&... poses) {
    const auto polygon_scales = [k](const polygon& p) {
        for (const point<double>& v : p.vertices())
            if (!scales_exactly(v.x, k) || !scales_exactly(v.y, k)) return false;
        return true;
    };
    return polygon_scales(a) && polygon_scales(b) &&
           (... && (scales_exactly(poses.tx, k) && scales_exactly(poses.ty, k)));
}

}  // namespace influence2d
