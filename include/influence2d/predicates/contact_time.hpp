// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The sign decisions of a sweep (docs/sweep.md): when a point moving along a
/// line reaches a closed segment, as a fraction of two ring expressions, and
/// the comparisons of such times. Ring operations and signs taken by
/// number_traits only: exact when NT's ring operations are; a filtered NT
/// (certified) gives the exact answer or throws uncertain_sign.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "influence2d/core/point.hpp"
#include "influence2d/number/traits.hpp"

namespace influence2d {

/// A time t = num / den with den > 0, both NT ring expressions of the input.
template <class NT>
struct time_fraction {
    NT num{};  ///< numerator
    NT den{};  ///< denominator, positive
};

/// The cross product u x (w - p) of a direction u and the offset of w from p:
/// twice the signed area of (p, p + u, w), without forming p + u.
template <class NT>
NT cross_from(const point<NT>& u, const point<NT>& p, const point<NT>& w) {
    return u.x * (w.y - p.y) - u.y * (w.x - p.x);
}

/// The sign of t - u for two times with positive denominators:
/// sign(t.num u.den - u.num t.den) (cross-multiplication).
template <class NT>
int compare_times(const time_fraction<NT>& t, const time_fraction<NT>& u) {
    return compare_values<NT>(t.num * u.den, u.num * t.den);
}

/// The sign of t - u as compare_times, for a filtered NT whose traits give
/// try_sign (has_try_sign): when its bound settles it, else none, without a throw (ties
/// between events are common where shared borders move, and a throw costs
/// microseconds).
template <class NT>
std::optional<int> certain_time_order(const time_fraction<NT>& t, const time_fraction<NT>& u) {
    int sign = 0;
    if (number_traits<NT>::try_sign(t.num * u.den - u.num * t.den, sign)) return sign;
    return std::nullopt;
}

/// Whether t >= 0, and when `bounded` also t <= 1 (num <= den).
template <class NT>
bool time_in_range(const time_fraction<NT>& t, bool bounded) {
    using tr = number_traits<NT>;
    return tr::sign(t.num) >= 0 && (!bounded || compare_values(t.num, t.den) <= 0);
}

/// The sides of a segment's ends against a line of motion: alpha =
/// d x (a - p) and beta = d x (b - p) for the line through p with
/// direction d, with their signs.
template <class NT>
struct segment_sides {
    NT alpha;  ///< d x (a - p)
    NT beta;   ///< d x (b - p)
    int sa;    ///< the sign of alpha
    int sb;    ///< the sign of beta

    /// Whether the line meets the closed segment [a, b]: a and b not
    /// strictly on one side of it (the signs not both +1 nor both -1). For
    /// a point moving as p + t d, whether the place where it reaches the
    /// segment's line lies on the segment.
    bool meet() const { return sa * sb <= 0; }
    /// Whether the segment lies on the line (both ends on it; a point of it
    /// for a == b).
    bool on_line() const { return sa == 0 && sb == 0; }
};

/// The sides of a and b against the line through p with direction d.
template <class NT>
segment_sides<NT> sides_of(const point<NT>& p, const point<NT>& d, const point<NT>& a, const point<NT>& b) {
    using tr = number_traits<NT>;
    segment_sides<NT> s{cross_from(d, p, a), cross_from(d, p, b), 0, 0};
    s.sa = tr::sign(s.alpha);
    s.sb = tr::sign(s.beta);
    return s;
}

/// The time at which p moving as p + t d passes the point x of its own line
/// (the caller knows d x (x - p) = 0, and d != 0): t = d.(x - p) / d.d.
template <class NT>
time_fraction<NT> passing_time(const point<NT>& p, const point<NT>& d, const point<NT>& x) {
    return {d.x * (x.x - p.x) + d.y * (x.y - p.y), d.x * d.x + d.y * d.y};
}

/// contact_times with the sides of a and b against p's line of motion
/// given (`sides`: sides_of's values, their signs decided by the caller,
/// exactly). When `ends` is given, ends[k] says which end of the segment
/// p passes through at out[k]: 0 for a, 1 for b, -1 for neither (it
/// crosses the segment inside). When `numerator_sign` is given (an NT with
/// try_sign), a sign its bound leaves in doubt is taken from
/// `numerator_sign(formula, at_end)`, before the normalisation: with
/// at_end false, the numerator's (a time of 0: p on the segment's line at
/// the start), the exact sign of (b - a) x (a - p) for formula -1, of
/// d . (a - p) and d . (b - p) (the passing times) for 0 and 1; with at_end
/// true, the numerator minus the denominator's (a time of 1, when bounded:
/// p + d on the line, or passing the end, as the motion ends), which is the
/// same numerator with p + d for p: (b - a) x (a - (p + d)), since the
/// denominator is (b - a) x d, and d . (a - (p + d)), since it is d . d.
template <class NT, class NumeratorSign = std::nullptr_t>
int contact_times_on_sides(const segment_sides<NT>& sides, const point<NT>& p, const point<NT>& d, const point<NT>& a,
                           const point<NT>& b, bool bounded, time_fraction<NT> out[2], int* ends = nullptr,
                           NumeratorSign numerator_sign = nullptr) {
    using tr = number_traits<NT>;
    if (!sides.meet()) return 0;
    int count = 0;
    // flip: -1 when the numerator was negated with the denominator.
    const auto keep = [&](time_fraction<NT>&& t, int end, int formula, int flip) {
        int sign = 0, past_end = 0;
        if constexpr (!std::is_same_v<NumeratorSign, std::nullptr_t>) {
            if (!tr::try_sign(t.num, sign)) {
                sign = flip * numerator_sign(formula, false);
                if (sign == 0) t.num = NT(0);  // (then known exactly: a time of 0)
            }
            if (sign >= 0 && bounded && !tr::try_sign(t.num - t.den, past_end)) {
                past_end = flip * numerator_sign(formula, true);
                if (past_end == 0) t.num = t.den = NT(1);  // (then known exactly: a time of 1)
            }
        } else {
            sign = tr::sign(t.num);
            if (sign >= 0 && bounded) past_end = compare_values(t.num, t.den);
        }
        if (sign < 0 || past_end > 0) return;
        if (ends != nullptr) ends[count] = end;
        out[count++] = std::move(t);
    };
    if (!sides.on_line()) {
        const point<NT> e{b.x - a.x, b.y - a.y};
        NT num = cross_from(e, p, a), den = sides.alpha - sides.beta;
        int flip = 1;
        if (sides.sa < sides.sb) {  // den = alpha - beta < 0: both signs turned
            num = -num;
            den = -den;
            flip = -1;
        }
        keep({std::move(num), std::move(den)}, sides.sa == 0 ? 0 : sides.sb == 0 ? 1 : -1, -1, flip);
    } else {
        keep(passing_time(p, d, a), 0, 0, 1);
        keep(passing_time(p, d, b), 1, 1, 1);
    }
    return count;
}

/// The times at which a point p moving as p + t d (d != 0) starts or stops
/// lying on the closed segment [a, b], restricted to t >= 0 (and t <= 1 when
/// `bounded`): written to out[0..count), count returned (0, 1 or 2).
///
///   alpha <- d x (a - p), beta <- d x (b - p)   (sides of a and b against
///                                                p's line of motion)
///   if their signs are both +1 or both -1:       none
///   if not both 0 (the segment crosses the line at one point, on it):
///       t = (b - a) x (a - p) / (alpha - beta)   (alpha - beta = (b - a) x d,
///                                                 not 0), sign made positive
///   else (the segment lies on the line, or is a point of it):
///       the times p passes a and b: it lies on the segment between them
///   keep the times in range
///
/// The point lies on the segment exactly at these times or, in the
/// collinear case, during the closed interval between the two. Ring
/// operations only.
template <class NT>
int contact_times(const point<NT>& p, const point<NT>& d, const point<NT>& a, const point<NT>& b, bool bounded,
                  time_fraction<NT> out[2]) {
    return contact_times_on_sides(sides_of(p, d, a, b), p, d, a, b, bounded, out);
}

/// The time at which p moving as p + t d reaches the line through a and b,
/// ((b - a) x (a - p)) / ((b - a) x d), for (b - a) x d != 0. That
/// denominator is contact_times' alpha - beta, which is 0 when the segment
/// lies on p's line of motion: so when it is not 0, this quotient is
/// contact_times' one time whenever that time exists (its sign
/// normalisation divides out). A division: NT a field.
template <class NT>
NT line_reaching_time(const point<NT>& p, const point<NT>& d, const point<NT>& a, const point<NT>& b) {
    const point<NT> e{b.x - a.x, b.y - a.y};
    return cross_from(e, p, a) / (e.x * d.y - e.y * d.x);
}

/// The earliest time t in [0, 1] at which p moving as p + t d (d != 0)
/// lies on the closed segment [a, b], if any: the least of contact_times.
template <class NT>
std::optional<time_fraction<NT>> earliest_contact_time(const point<NT>& p, const point<NT>& d, const point<NT>& a,
                                                       const point<NT>& b) {
    time_fraction<NT> t[2];
    const int k = contact_times(p, d, a, b, true, t);
    if (k == 0) return std::nullopt;
    if (k == 2 && compare_times(t[1], t[0]) < 0) return std::move(t[1]);
    return std::move(t[0]);
}

/// Of two neighbouring doubles, the one whose last significand bit is 0.
inline double even_of(double x, double y) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    return (bits & 1) == 0 ? x : y;
}

/// The time t = num / den rounded to the nearest double (ties to the even
/// one), for 0 <= t below double's largest value. Starts from the quotient
/// of the doubles nearest num and den (or, when that overflows, from a
/// bisection over the doubles), then moves by single steps while t lies
/// beyond the midpoint with a neighbour, each midpoint compared exactly by
/// ring operations (2 num against (x + y) den, x + y computed in NT). Exact
/// when NT's ring operations are; a filtered NT throws uncertain_sign when
/// a comparison (always, at an exact tie) is not certain. In a floating NT,
/// the quotient of num and den converted to double.
template <class NT>
double nearest_double(const time_fraction<NT>& t) {
    using tr = number_traits<NT>;
    const double inf = std::numeric_limits<double>::infinity();
    const double num = tr::to_double(t.num), den = tr::to_double(t.den);
    double x = num / den;
    if constexpr (tr::category == number_category::floating) return x;  // its rounding is NT's
    // (A numerator or denominator whose double is subnormal or 0 has lost
    // its relative precision: their quotient may be off by any factor, and
    // the walks below by as many steps.)
    const auto normal = [inf](double v) { return v >= std::numeric_limits<double>::min() && v < inf; };
    if (!(x >= 0 && x < inf) || (tr::sign(t.num) != 0 && !normal(num)) || !normal(den)) {
        // The doubles nearest num and den overflowed (or underflowed): the
        // largest double x <= t by bisection on the ordered bit patterns of
        // the non-negative doubles.
        std::uint64_t lo = 0, hi = 0x7fefffffffffffffULL;
        const auto as_double = [](std::uint64_t bits) {
            double v = 0;
            std::memcpy(&v, &bits, sizeof v);
            return v;
        };
        while (lo < hi) {
            const std::uint64_t mid = lo + (hi - lo + 1) / 2;
            if (compare_values<NT>(t.num, tr::from_double(as_double(mid)) * t.den) >= 0)
                lo = mid;
            else
                hi = mid - 1;
        }
        x = as_double(lo);
    }
    const NT twice = t.num + t.num;
    // sign of t - (x + y) / 2
    const auto beyond_mid = [&](double x0, double y0) {
        return compare_values<NT>(twice, (tr::from_double(x0) + tr::from_double(y0)) * t.den);
    };
    for (;;) {
        const double up = std::nextafter(x, inf);
        const int s = beyond_mid(x, up);
        if (s > 0) {
            x = up;
            continue;
        }
        if (s == 0) return even_of(x, up);
        break;
    }
    for (;;) {
        const double down = std::nextafter(x, -inf);
        const int s = beyond_mid(down, x);
        if (s < 0) {
            x = down;
            continue;
        }
        if (s == 0) return even_of(down, x);
        return x;
    }
}

}  // namespace influence2d
