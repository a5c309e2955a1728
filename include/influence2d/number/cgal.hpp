#pragma once
// Number traits for CGAL's exact number types, and for its interval
// arithmetic. The only header of the library that needs CGAL; include it to
// run the detector exactly.

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/number_utils.h>

#include "influence2d/number/certified.hpp"
#include "influence2d/number/traits.hpp"

namespace influence2d {

/// The exact reference number type: rationals from GMP through CGAL.
using exact_rational = CGAL::Exact_rational;

template <>
struct number_traits<exact_rational> {
    static constexpr number_category category = number_category::exact;
    static constexpr const char* name = "exact";
    static exact_rational from_double(double x) { return exact_rational(x); }
    static double to_double(const exact_rational& x) { return CGAL::to_double(x); }
    static int sign(const exact_rational& x) { return static_cast<int>(CGAL::sign(x)); }
    static constexpr double filter_slack = 1e-9;
};

/// CGAL's lazy exact numbers (the field type of Epeck): interval arithmetic
/// first, exact recomputation when an interval cannot decide a sign.
template <class ET>
struct number_traits<CGAL::Lazy_exact_nt<ET>> {
    static constexpr number_category category = number_category::filtered;
    static constexpr const char* name = "lazy exact";
    static CGAL::Lazy_exact_nt<ET> from_double(double x) { return CGAL::Lazy_exact_nt<ET>(x); }
    static double to_double(const CGAL::Lazy_exact_nt<ET>& x) { return CGAL::to_double(x); }
    static int sign(const CGAL::Lazy_exact_nt<ET>& x) { return static_cast<int>(CGAL::sign(x)); }
    static constexpr double filter_slack = 1e-9;
};

/// CGAL's interval arithmetic, each operation rounding its bounds outward
/// (Interval_nt<true> switches the rounding mode itself; CGAL's CMake target
/// adds the -frounding-math that GCC needs for it). An interval always contains
/// the exact value of the same ring operations on the input doubles, so a sign
/// it decides is the exact sign; one it cannot decide raises uncertain_sign,
/// as the certified type does. Comparisons are CGAL's own: `a < b` is an
/// Uncertain<bool> whose conversion to bool throws
/// CGAL::Uncertain_conversion_exception when the intervals overlap. The library
/// compares NT values directly in a few places (segment extents, distance
/// bounds), so a detector on intervals raises either exception; run it through
/// interval_detector (detect/interval_detector.hpp), which answers such frames
/// in exact rationals.
using interval = CGAL::Interval_nt<true>;

template <>
struct number_traits<interval> {
    static constexpr number_category category = number_category::filtered;
    static constexpr const char* name = "interval";
    static interval from_double(double x) { return interval(x); }  // a point: exact
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
    static constexpr double filter_slack = 1e-9;
};

}  // namespace influence2d
