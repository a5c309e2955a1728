#pragma once
/// \file
/// Containment without boundary contact (method.md section 7).

#include <optional>

#include "influence2d/covering/inclusion.hpp"
#include "influence2d/detect/scene.hpp"

namespace influence2d {

/// Whether the closed regions of A and the posed B meet, given that their
/// boundaries do not (the caller found no boundary pair). B inside a hole of
/// A does not meet A. Each ring of B then lies wholly inside or outside A,
/// and each ring of A wholly inside or outside B, and the regions meet exactly
/// when one vertex of some ring of one lies in the other region. Exact when NT
/// is; a ring of B costs a locate in A through A's cone index, a ring of A a
/// scan of B's edges. Given `reach` (a bound
/// of B's radius, with any rounding margin), a ring of A whose first vertex is
/// farther than that from B's centroid is skipped without a test; with
/// `a_may_be_inside_b` false (the caller knows A does not fit in B) no ring of
/// A is tested, and with `b_may_be_inside_a` false no ring of B. With
/// MultiRing false both polygons are taken to have one ring.
template <class NT, bool MultiRing = true>
bool one_contains_other(const static_scene<NT>& a, posed_polygon<NT>& b, std::optional<double> reach = std::nullopt,
                        bool a_may_be_inside_b = true, bool b_may_be_inside_a = true) {
    const polygon& bs = b.shape();
    for (std::size_t r = 0; r < (MultiRing ? bs.ring_count() : 1) && b_may_be_inside_a; ++r)
        if (a.areas.locate(b.vertex(bs.ring_begin(r))) != location::outside) return true;
    if (!a_may_be_inside_b) return false;
    const NT reach_nt = number_traits<NT>::from_double(reach.value_or(0));
    const NT reach2 = reach_nt * reach_nt;
    const polygon& as = a.shape;
    for (std::size_t r = 0; r < (MultiRing ? as.ring_count() : 1); ++r) {
        const point<NT>& v = a.covering.start(as.ring_begin(r));
        if (reach && squared_distance(v, b.centroid()) > reach2) continue;
        if (locate(bs, b.vertices(), b.centroid(), v) != location::outside) return true;
    }
    return false;
}

}  // namespace influence2d
