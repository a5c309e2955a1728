// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Number traits for quadruple precision: Boost.Multiprecision's
/// cpp_bin_float_quad (header-only, 113-bit significand) and, where the compiler
/// has it, GCC's built-in __float128 (its +, -, * and comparisons come from the
/// compiler's runtime; no extra library is linked).
///
/// Both are floating types: every operation rounds (to 113 bits), so their
/// answers, like those of double, may differ from the exact ones near contact,
/// only much closer to it. Conversions from double are exact.
///
/// Boost's own `boost::multiprecision::float128` (the `number<>` wrapper around
/// __float128) is deliberately not supported here: its conversions call
/// libquadmath (isnanq, isinfq), so every program using it would have to link
/// -lquadmath. The built-in type below gives the same arithmetic without it.

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "influence2d/number/traits.hpp"

namespace influence2d {

/// Boost's IEEE-like quadruple precision in software (113-bit significand,
/// 15-bit exponent): ring operations round once to 113 bits.
using quad = boost::multiprecision::cpp_bin_float_quad;

/// The traits of quad: rounded arithmetic.
template <>
struct number_traits<quad> {
    static constexpr number_category category = number_category::floating;  ///< rounded
    static constexpr const char* name = "quad";                             ///< "quad"
    /// x exactly.
    static quad from_double(double x) { return quad(x); }
    /// x rounded to double.
    static double to_double(const quad& x) { return x.convert_to<double>(); }
    /// -1, 0 or +1, of the rounded value.
    static int sign(const quad& x) { return x.sign(); }
    /// Decisions are within a few 2^-113 relative ulps of the exact ones; the
    /// double-evaluated filters need only cover their own rounding (2^-53)
    /// with room to spare.
    static constexpr double filter_slack = 1e-12;
};

#if defined(__SIZEOF_FLOAT128__) && !defined(INFLUENCE2D_NO_FLOAT128)
/// GCC's built-in binary128 type (software arithmetic on x86-64). Defined,
/// with INFLUENCE2D_HAS_FLOAT128, only where the compiler has __float128 and
/// INFLUENCE2D_NO_FLOAT128 is not defined.
__extension__ typedef __float128 float128;

/// The traits of float128: rounded arithmetic. A full specialisation: it
/// takes precedence over the one for std::is_floating_point types, which
/// matches __float128 in GNU modes.
template <>
struct number_traits<float128> {
    static constexpr number_category category = number_category::floating;  ///< rounded
    static constexpr const char* name = "float128";                         ///< "float128"
    /// x exactly.
    static float128 from_double(double x) { return static_cast<float128>(x); }
    /// x rounded to double.
    static double to_double(const float128& x) { return static_cast<double>(x); }
    /// -1, 0 or +1, of the rounded value; 0 for NaN.
    static int sign(const float128& x) { return (x > 0) - (x < 0); }
    /// As for quad: the filters need only cover their own rounding.
    static constexpr double filter_slack = 1e-12;
};
/// Defined to 1 when float128 and its traits are available.
#define INFLUENCE2D_HAS_FLOAT128 1
#endif

}  // namespace influence2d
