#pragma once
// A point of the plane with coordinates of number type T.

namespace influence2d {

/// A point (x, y). `T` is `double` for input geometry and the detector's number
/// type `NT` for everything it evaluates.
template <class T>
struct point {
    T x{};
    T y{};
};

template <class T>
bool operator==(const point<T>& a, const point<T>& b) { return a.x == b.x && a.y == b.y; }

template <class T>
bool operator!=(const point<T>& a, const point<T>& b) { return !(a == b); }

}  // namespace influence2d
