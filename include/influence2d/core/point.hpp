// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// A point of the plane with coordinates of number type T, and its
/// conversions between double and a number type.

#include "influence2d/number/traits.hpp"

namespace influence2d {

/// A point (x, y). `T` is `double` for input geometry and the detector's number
/// type `NT` for everything it evaluates.
template <class T>
struct point {
    T x{};  ///< abscissa
    T y{};  ///< ordinate
};

/// Whether both coordinates compare equal with T's `==`: exact for exact T;
/// for floating T, +0 equals -0 and a NaN coordinate equals nothing; for
/// `certified` and `interval` it throws when the comparison is undecided.
template <class T>
bool operator==(const point<T>& a, const point<T>& b) {
    return a.x == b.x && a.y == b.y;
}

/// The negation of `a == b`.
template <class T>
bool operator!=(const point<T>& a, const point<T>& b) {
    return !(a == b);
}

/// The point of doubles p in NT, coordinate by coordinate
/// (number_traits::from_double: exact in every number type of the library
/// but float).
template <class NT>
point<NT> to_point(const point<double>& p) {
    return {number_traits<NT>::from_double(p.x), number_traits<NT>::from_double(p.y)};
}

/// p rounded to double, coordinate by coordinate (number_traits::to_double).
template <class NT>
point<double> to_double_point(const point<NT>& p) {
    return {number_traits<NT>::to_double(p.x), number_traits<NT>::to_double(p.y)};
}

}  // namespace influence2d
