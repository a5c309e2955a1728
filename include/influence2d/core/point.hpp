// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// A point of the plane with coordinates of number type T.

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
bool operator==(const point<T>& a, const point<T>& b) { return a.x == b.x && a.y == b.y; }

/// The negation of `a == b`.
template <class T>
bool operator!=(const point<T>& a, const point<T>& b) { return !(a == b); }

}  // namespace influence2d
