#pragma once
// The orientation predicate: the one sign question everything else is made of.

#include "influence2d/core/point.hpp"
#include "influence2d/number/traits.hpp"

namespace influence2d {

/// Sign of the signed area [a b c]: +1 when c lies left of the directed line
/// a->b (counter-clockwise turn), -1 when right, 0 when the three are collinear.
/// Exact when NT's ring operations are exact.
template <class NT>
int orientation(const point<NT>& a, const point<NT>& b, const point<NT>& c) {
    return number_traits<NT>::sign((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

/// Whether p, known to be collinear with a and b, lies on the closed segment [a, b].
template <class NT>
bool within_collinear_segment(const point<NT>& p, const point<NT>& a, const point<NT>& b) {
    const bool in_x = (a.x <= p.x && p.x <= b.x) || (b.x <= p.x && p.x <= a.x);
    const bool in_y = (a.y <= p.y && p.y <= b.y) || (b.y <= p.y && p.y <= a.y);
    return in_x && in_y;
}

/// Whether p lies on the closed segment [a, b] (a == b allowed).
template <class NT>
bool on_segment(const point<NT>& p, const point<NT>& a, const point<NT>& b) {
    return orientation(a, b, p) == 0 && within_collinear_segment(p, a, b);
}

}  // namespace influence2d
