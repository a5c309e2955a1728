#pragma once
// Number traits for CGAL's exact number types. The only header of the library
// that needs CGAL; include it to run the detector exactly.

#include <CGAL/Exact_rational.h>
#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/number_utils.h>

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

}  // namespace influence2d
