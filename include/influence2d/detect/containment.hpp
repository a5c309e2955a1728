// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Containment without boundary contact (docs/method.md, "Containment").

#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "influence2d/covering/inclusion.hpp"
#include "influence2d/predicates/distance.hpp"
#include "influence2d/scene/posed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d {

/// What a ring filter of one_contains_other knows of a ring before it is
/// located: that it lies outside the other polygon, or inside it, or
/// neither (the ring is then located). A filter may return a bool instead:
/// true for unknown, false for outside.
enum class ring_fate : std::uint8_t {
    outside,  ///< the ring certainly lies outside the other polygon's region
    inside,   ///< the ring certainly lies in the other polygon's closed region
    unknown   ///< the ring is to be located
};

/// A ring filter's answer as a ring_fate.
template <class Verdict>
ring_fate fate_of(Verdict verdict) {
    if constexpr (std::is_same_v<Verdict, bool>)
        return verdict ? ring_fate::unknown : ring_fate::outside;
    else
        return verdict;
}

/// A ring filter that keeps every ring: each is located.
struct every_ring {
    /// Always true: ring r may lie in the other polygon.
    bool operator()(std::size_t) const { return true; }
};

/// Where the point v (exact in double, as A's vertices are) lies in the
/// posed B: Feito's test on B's vertices in NT, or the filtered crossings
/// of one_contains_other's `b_margin`.
template <class NT>
location located_in(posed_polygon<NT>& b, std::optional<double> b_margin, const point<NT>& v) {
    if constexpr (number_traits<NT>::category != number_category::floating)
        if (b_margin)
            return locate_by_crossings<NT>(b.shape(), b.approximate_all(), {}, 0, to_double_point(v), *b_margin, v,
                                           [&](std::size_t i) -> const point<NT>& { return b.vertex(i); });
    return locate(b.shape(), b.vertices(), b.centroid(), v);
}

/// The most edges of A for which an exact NT locates B's vertex by the
/// filtered crossings of a ray over A's edges (located_in_a) rather than in
/// A's cone index. Measured (callgrind, exact rationals, B's two rings
/// located in Chile's 112 edges, a real-layer frame): the cone index took
/// about 250k instructions a locate (its orientations in rationals), the
/// scan about 26 an edge, its crossings settled in double. The scan pays
/// up to about 9,600 edges; 4096 keeps a margin of two.
inline constexpr std::size_t crossings_scan_limit = 4096;

/// Where B's vertex j lies in A: in an exact NT given `b_margin` and an A
/// of at most crossings_scan_limit edges, by the crossings of a ray settled
/// in double (A's vertices are exact in double, B's posed in double within
/// b_margin) and taken in NT only where the doubles cannot tell
/// (locate_by_crossings); else through A's cone index in NT.
template <class NT>
location located_in_a(const static_scene<NT>& a, posed_polygon<NT>& b, std::optional<double> b_margin, std::size_t j) {
    if constexpr (number_traits<NT>::category == number_category::exact)
        if (b_margin && a.shape.size() <= crossings_scan_limit)
            return locate_by_crossings<NT>(a.shape, a.shape.vertices(), {}, 0, b.approximate(j), *b_margin, b.vertex(j),
                                           [&](std::size_t i) -> const point<NT>& { return a.covering.start(i); });
    return a.areas().locate(b.vertex(j));
}

/// Whether the closed regions of A and the posed B meet, given that their
/// boundaries do not (the caller found no boundary pair).
///
///   for each ring r of B, by b_ring_may_be_in_a's fate:
///       outside: skip; inside: meet
///       unknown: if B's ring r's first vertex is not outside A: meet
///   for each ring r of A, by a_ring_may_be_in_b's fate:
///       outside: skip; inside: meet
///       unknown: if its first vertex is farther than reach from B's
///           centroid: skip
///           if A's ring r's first vertex is not outside B: meet
///   disjoint
///
/// Why one vertex per ring suffices: no ring of one polygon meets a ring of
/// the other, so every ring lies within one face of the other polygon's
/// rings, where the winding number is constant: the ring lies wholly inside
/// or wholly outside the other region. And if the regions meet, the part
/// they share is bounded and its boundary lies on some ring of A or of B,
/// which then lies in the other region. Every ring of both polygons is
/// accounted for: a multipolygon's part inside the other polygon is found
/// whichever part it is. B inside a hole of A does not meet A.
///
/// The filters are the caller's shortcuts and must be valid per ring: a ring
/// they drop must certainly lie outside the other polygon, one they call
/// inside certainly in its closed region (a ring_fate, or a bool: false for
/// outside). `reach`, when
/// given, bounds the distance from B's centroid to every point of B (with any
/// rounding margin). Exact when NT is; a ring of B costs a locate in A
/// (located_in_a: A's cone index, or in an exact NT given `b_margin` the
/// filtered crossings below over A's edges), a ring of A a scan of B's
/// edges: Feito's test on
/// B's vertices posed in NT, or, in an exact or filtered NT given
/// `b_margin` (B's vertices posed in double are within it of their values
/// in NT, on each coordinate), the crossings of a ray settled in double and
/// taken in NT only where the doubles cannot tell (locate_by_crossings), so
/// that B is not posed in NT whole. With MultiRing false both polygons are
/// taken to have one ring.
template <class NT, bool MultiRing = true, class AFilter = every_ring, class BFilter = every_ring>
bool one_contains_other(const static_scene<NT>& a, posed_polygon<NT>& b, std::optional<double> reach = std::nullopt,
                        AFilter a_ring_may_be_in_b = {}, BFilter b_ring_may_be_in_a = {},
                        std::optional<double> b_margin = std::nullopt) {
    const polygon& bs = b.shape();
    for (std::size_t r = 0; r < (MultiRing ? bs.ring_count() : 1); ++r) {
        const ring_fate fate = fate_of(b_ring_may_be_in_a(r));
        if (fate == ring_fate::inside) return true;
        if (fate == ring_fate::unknown && located_in_a(a, b, b_margin, bs.ring_begin(r)) != location::outside)
            return true;
    }
    const NT reach_nt = number_traits<NT>::from_double(reach.value_or(0));
    const NT reach2 = reach_nt * reach_nt;
    const polygon& as = a.shape;
    for (std::size_t r = 0; r < (MultiRing ? as.ring_count() : 1); ++r) {
        const ring_fate fate = fate_of(a_ring_may_be_in_b(r));
        if (fate == ring_fate::inside) return true;
        if (fate == ring_fate::outside) continue;
        const point<NT>& v = a.covering.start(as.ring_begin(r));
        if (reach && compare_values<NT>(squared_distance(v, b.centroid()), reach2) > 0) continue;
        if (located_in(b, b_margin, v) != location::outside) return true;
    }
    return false;
}

}  // namespace influence2d
