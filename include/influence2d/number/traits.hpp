// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Number traits: what the library needs to know about a number type NT.
/// Specialise number_traits for your own type (see number/cgal.hpp).

#include <limits>
#include <type_traits>
#include <utility>

namespace influence2d {

/// How a number type evaluates the sign questions.
enum class number_category {
    floating,  ///< rounded arithmetic: answers may differ from the exact ones
    exact,     ///< ring operations are exact: answers are the exact ones
    /// Exact answers through a floating-point filter: a sign is either exact
    /// or not given. The type may fall back to exact arithmetic itself (CGAL's
    /// lazy numbers), or throw uncertain_sign so that filtered_detector
    /// answers the frame in exact rationals (certified, interval).
    filtered
};

namespace traits_detail {
/// False, but only once NT is known: a static_assert on it fires when its
/// template is instantiated, not when it is defined.
template <class NT>
struct dependent_false : std::false_type {};
}  // namespace traits_detail

/// What the library needs of a number type NT. The primary template serves
/// no type: naming a member of it stops the compilation with a static_assert
/// saying to specialise number_traits. A type is usable once it has a
/// specialisation, which provides
/// - `static constexpr number_category category;`
/// - `static constexpr const char* name;` a short name for output;
/// - `static NT from_double(double);` exact whenever category != floating;
/// - `static double to_double(const NT&);` the nearest or a near double, for
///   filters and output only;
/// - `static int sign(const NT&);` -1, 0 or +1 (a filtered type may throw
///   uncertain_sign instead);
/// - `static constexpr double filter_slack;` the relative widening that keeps
///   the double-evaluated filters conservative for decisions made in NT.
///
/// A filtered type may also set `static constexpr bool exact_double_fallback
/// = true` and provide `static bool try_sign(const NT&, int&)` (the sign when
/// certain) and `static bool exact(const NT&)` (whether the value is an input
/// double): orientation() then settles an uncertain sign on three input
/// points exactly instead of throwing. A type may provide `static NT
/// sum_of_products(double a, double b, double c, double d, double t)`, the
/// value a b + c d + t (exact in an exact type, within the type's bound in a
/// filtered one), which posing a point (rotation_pose::apply) then takes in
/// place of five conversions, two products and two sums. The detectors and the one-shot
/// questions need +, -, * and the comparisons of NT only, never a division or
/// a square root; the separation's closest points, the first contact's time
/// and the exit distance also divide (a field NT: every type of the library
/// but certified and interval, which reach them through the exact entry
/// points of exact/). No square root is asked of NT anywhere. `Enable`
/// serves partial specialisations through std::enable_if_t.
template <class NT, class Enable = void>
struct number_traits {
    static_assert(traits_detail::dependent_false<NT>::value,
                  "no number traits for this number type: specialise influence2d::number_traits for it "
                  "(see influence2d/number/traits.hpp)");
};

/// The traits of float, double and long double: rounded arithmetic.
template <class NT>
struct number_traits<NT, std::enable_if_t<std::is_floating_point_v<NT>>> {
    static constexpr number_category category = number_category::floating;  ///< rounded
    /// "float", "double" or "long double".
    static constexpr const char* name = std::is_same_v<NT, float>    ? "float"
                                        : std::is_same_v<NT, double> ? "double"
                                                                     : "long double";
    /// x converted. Exact for double and long double; float rounds it, and
    /// beyond float's range the conversion is undefined behaviour (an
    /// infinity in practice), so float suits inputs within that range only.
    static NT from_double(double x) {
        // Converting a double beyond NT's range is undefined: go to infinity
        // explicitly (detectors refuse such polygons; see accepted_polygon).
        if constexpr (std::numeric_limits<NT>::is_specialized &&
                      std::numeric_limits<NT>::max() < std::numeric_limits<double>::max()) {
            if (x > static_cast<double>(std::numeric_limits<NT>::max())) return std::numeric_limits<NT>::infinity();
            if (x < -static_cast<double>(std::numeric_limits<NT>::max())) return -std::numeric_limits<NT>::infinity();
        }
        return static_cast<NT>(x);
    }
    /// x converted: exact from float and double, rounded from long double.
    static double to_double(const NT& x) { return static_cast<double>(x); }
    /// -1, 0 or +1; 0 for NaN (neither above nor below 0).
    static int sign(const NT& x) { return (x > NT(0)) - (x < NT(0)); }
    /// 1e-4 for float, 1e-9 for double and long double. Filters run in
    /// double; decisions made in a coarser type can be wrong by a few of its
    /// ulps, so its filters widen by a margin well above that.
    static constexpr double filter_slack = std::numeric_limits<NT>::epsilon() > 1e-12 ? 1e-4 : 1e-9;
};

/// The sign of a - b (-1, 0 or +1), taken by number_traits<NT>::sign: the
/// one way the library compares two NT values, so that a filtered type
/// raises on an undecided comparison what it raises on an undecided sign
/// (uncertain_sign). Exact when NT's ring operations are; for a floating NT,
/// whose differences are rounded but keep their sign (gradual underflow), it
/// agrees with the built-in comparisons on finite values, and gives 0 when
/// either value is NaN. A built-in floating type is compared with its own
/// operators, which give the same answer on every input (two infinities of
/// one sign: 0 either way) without the subtraction. For an NT with expression
/// templates (GMP's, Boost's) name NT when an argument is an expression:
/// `compare_values<NT>(a * b, c)`.
template <class NT>
int compare_values(const NT& a, const NT& b) {
    if constexpr (std::is_floating_point_v<NT>) {
        return a > b ? 1 : (a < b ? -1 : 0);
    } else {
        return number_traits<NT>::sign(a - b);
    }
}

/// Whether number_traits<NT> provides try_sign (the sign when certain,
/// without a throw).
template <class NT, class = void>
struct has_try_sign : std::false_type {};
/// See has_try_sign.
template <class NT>
struct has_try_sign<NT,
                    std::void_t<decltype(number_traits<NT>::try_sign(std::declval<const NT&>(), std::declval<int&>()))>>
    : std::true_type {};

/// Whether number_traits<NT> provides sum_of_products.
template <class NT, class = void>
struct has_sum_of_products : std::false_type {};
/// See has_sum_of_products.
template <class NT>
struct has_sum_of_products<NT, std::void_t<decltype(number_traits<NT>::sum_of_products(0.0, 0.0, 0.0, 0.0, 0.0))>>
    : std::true_type {};

/// Whether NT's answers are the exact ones: true unless its category is
/// floating.
template <class NT>
inline constexpr bool is_exact_v = number_traits<NT>::category != number_category::floating;

}  // namespace influence2d
