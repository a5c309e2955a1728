#pragma once
// Number traits: what the library needs to know about a number type NT.
// Specialise number_traits for your own type (see number/cgal.hpp).

#include <limits>
#include <type_traits>

namespace influence2d {

/// How a number type evaluates the sign questions.
enum class number_category {
    floating,  ///< rounded arithmetic: answers may differ from the exact ones
    exact,     ///< ring operations are exact: answers are the exact ones
    filtered   ///< exact answers through a floating-point filter with exact fallback
};

/// Primary template, left undefined: a type is usable once it has traits.
/// A specialisation provides:
///   static constexpr number_category category;
///   static constexpr const char* name;
///   static NT from_double(double);   exact whenever category != floating
///   static double to_double(const NT&);  nearest or near double
///   static int sign(const NT&);      -1, 0 or +1
///   static constexpr double filter_slack;  relative widening that keeps the
///       double-evaluated filters conservative for decisions made in NT
template <class NT, class Enable = void>
struct number_traits;

/// float, double, long double.
template <class NT>
struct number_traits<NT, std::enable_if_t<std::is_floating_point_v<NT>>> {
    static constexpr number_category category = number_category::floating;
    static constexpr const char* name = std::is_same_v<NT, float>    ? "float"
                                        : std::is_same_v<NT, double> ? "double"
                                                                     : "long double";
    static NT from_double(double x) { return static_cast<NT>(x); }
    static double to_double(const NT& x) { return static_cast<double>(x); }
    static int sign(const NT& x) { return (x > NT(0)) - (x < NT(0)); }
    // Filters run in double; decisions made in a coarser type can be wrong by a
    // few of its ulps, so its filters widen by a margin well above that.
    static constexpr double filter_slack =
        std::numeric_limits<NT>::epsilon() > 1e-12 ? 1e-4 : 1e-9;
};

template <class NT>
inline constexpr bool is_exact_v = number_traits<NT>::category != number_category::floating;

}  // namespace influence2d
