// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Number traits for CGAL's exact number types, and for its interval
/// arithmetic. The only header of the library that needs CGAL; include it to
/// run the detector exactly.

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/number_utils.h>

#include "influence2d/number/certified.hpp"
#include "influence2d/number/traits.hpp"

namespace influence2d {

/// The exact reference number type: rationals from GMP through CGAL. Every
/// ring operation and comparison is exact; the cost grows with the bit
/// length of the numbers.
using exact_rational = CGAL::Exact_rational;

/// The traits of exact_rational: exact.
template <>
struct number_traits<exact_rational> {
    static constexpr number_category category = number_category::exact;  ///< exact
    static constexpr const char* name = "exact";                         ///< "exact"
    /// x exactly (x must be finite).
    static exact_rational from_double(double x) { return exact_rational(x); }
    /// A double near x (CGAL::to_double, not necessarily the nearest).
    static double to_double(const exact_rational& x) { return CGAL::to_double(x); }
    /// The exact sign.
    static int sign(const exact_rational& x) { return static_cast<int>(CGAL::sign(x)); }
    /// The filters in double need cover only their own rounding.
    static constexpr double filter_slack = 1e-9;
};

/// The traits of CGAL's lazy exact numbers (the field type of Epeck, ET its
/// exact type): interval arithmetic first, exact recomputation inside the
/// type when an interval cannot decide a sign. Every sign and comparison is
/// exact and none throws, so the detectors run on it directly.
template <class ET>
struct number_traits<CGAL::Lazy_exact_nt<ET>> {
    static constexpr number_category category = number_category::filtered;  ///< filtered
    static constexpr const char* name = "lazy exact";                       ///< "lazy exact"
    /// x exactly.
    static CGAL::Lazy_exact_nt<ET> from_double(double x) { return CGAL::Lazy_exact_nt<ET>(x); }
    /// A double near x, from its interval.
    static double to_double(const CGAL::Lazy_exact_nt<ET>& x) { return CGAL::to_double(x); }
    /// The exact sign (recomputed exactly when the interval contains 0).
    static int sign(const CGAL::Lazy_exact_nt<ET>& x) { return static_cast<int>(CGAL::sign(x)); }
    /// The filters in double need cover only their own rounding.
    static constexpr double filter_slack = 1e-9;
};

/// CGAL's interval arithmetic, each operation rounding its bounds outward
/// (`Interval_nt<true>` switches the rounding mode itself; CGAL's CMake target
/// adds the -frounding-math that GCC needs for it). An interval always contains
/// the exact value of the same ring operations on the input doubles, so a sign
/// it decides is the exact sign; one it cannot decide raises uncertain_sign,
/// as the certified type does. Its own comparisons are CGAL's: `a < b` is an
/// `Uncertain<bool>` whose conversion to bool throws
/// CGAL::Uncertain_conversion_exception when the intervals overlap. The
/// predicates never use them (they compare through compare_values, so through
/// sign); run a detector on intervals through interval_detector
/// (exact/interval_detector.hpp), which answers the frames it cannot decide
/// in exact rationals.
using interval = CGAL::Interval_nt<true>;

/// The traits of interval: a filtered type whose undecided signs throw.
template <>
struct number_traits<interval> {
    static constexpr number_category category = number_category::filtered;  ///< exact signs or none
    static constexpr const char* name = "interval";                         ///< "interval"
    /// The point interval [x, x]: exact.
    static interval from_double(double x) { return interval(x); }  // a point: exact
    /// The interval's midpoint (CGAL::to_double).
    static double to_double(const interval& x) { return CGAL::to_double(x); }
    /// -1, 0 or +1 when the interval decides it: wholly positive, wholly
    /// negative, or exactly {0}. Otherwise (it contains 0 and more, or a
    /// bound is NaN) throws uncertain_sign.
    static int sign(const interval& x) {
        if (x.inf() > 0) return 1;
        if (x.sup() < 0) return -1;
        if (x.inf() == 0 && x.sup() == 0) return 0;
        throw uncertain_sign();
    }
    /// The filters in double need cover only their own rounding.
    static constexpr double filter_slack = 1e-9;
};

}  // namespace influence2d
