// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether two convex polygons meet: the separating-edge test, exact in NT
/// with a filter in double.

#include <cstddef>
#include <cstdint>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/predicates/exact_doubles.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/scene/bounding_disc.hpp"

namespace influence2d {

/// A convex polygon as the separating-edge test sees it: `size` vertices
/// counter-clockwise (is_convex_polygon, predicates/convexity.hpp), vertex i
/// as a double within `error` of it on each coordinate (`approximate[i]`)
/// and in NT (`exact(i)`, asked only when the doubles cannot settle a sign).
template <class Exact>
struct convex_view {
    std::size_t size;                  ///< the number of vertices (and edges)
    const point<double>* approximate;  ///< vertex i within error of its double approximate[i]
    Exact exact;                       ///< i -> point<NT>, vertex i
    double error;                      ///< bounds |approximate[i] - vertex i| on each coordinate
    /// A disc in the region: every point within inner.radius of the point
    /// whose double (within error) is inner.centre lies in it; none when
    /// inner.radius is 0.
    disc inner;
};

/// A convex_view from its parts, without an inner disc or with one.
template <class Exact>
convex_view<Exact> make_convex_view(std::size_t size, const point<double>* approximate, Exact exact, double error,
                                    disc inner = {}) {
    return {size, approximate, exact, error, inner};
}

/// Whether right(j) holds for each of the m vertices j of a polygon (each
/// strictly right of an edge's line), asked from `start` round, stopping at
/// the first that is not, which becomes `start` (where the next edge's scan
/// starts: a vertex inside one edge's half-plane is likely inside the next
/// one's).
template <class Right>
bool every_vertex_right(std::size_t m, std::size_t& start, Right&& right) {
    std::size_t j = start;
    for (std::size_t k = 0; k < m; ++k) {
        if (!right(j)) {
            start = j;
            return false;
        }
        j = j + 1 == m ? 0 : j + 1;
    }
    return true;
}

/// The first edge of `poly` in [first, last) but `skip` whose line has
/// every vertex of `other` strictly on its right, that is, outside poly
/// (edge i runs from vertex i to vertex i + 1); `last` when none has. An
/// edge that other's inner disc certainly reaches across (some point of
/// other strictly left, disc_reaches_left; a convex region's least value
/// of a linear function is at a vertex, so some vertex is strictly left
/// too) separates nothing, at the cost of one side test. Otherwise each
/// vertex is placed by certain_side_for in double (the edge's side_slack
/// for points within `spread` of its start, in the L1 norm), and by
/// orientation in NT when the doubles cannot settle it. An edge's scan
/// stops at the first vertex on or left of its line, where the next edge's
/// scan starts (every_vertex_right).
template <class NT, class Poly, class Other>
std::size_t separating_edge_of(const Poly& poly, const Other& other, double spread, std::size_t first, std::size_t last,
                               std::size_t skip) {
    const point<double>* v = poly.approximate;
    const point<double>* w = other.approximate;
    const std::size_t n = poly.size, m = other.size;
    const side_slack slacks(poly.error, other.error, spread);
    std::size_t start = 0;
    for (std::size_t i = first; i < last; ++i) {
        if (i == skip) continue;
        const std::size_t i1 = i + 1 == n ? 0 : i + 1;
        const double dx = v[i1].x - v[i].x, dy = v[i1].y - v[i].y;
        const double slack = slacks.of(dx, dy);
        if (other.inner.radius > 0 &&
            disc_reaches_left(v[i], dx, dy, other.inner.centre, other.inner.radius, poly.error, slack))
            continue;
        const bool separates = every_vertex_right(m, start, [&](std::size_t j) {
            const int side = certain_side_for(v[i], dx, dy, w[j], slack);
            return side != 0 ? side < 0 : orientation(poly.exact(i), poly.exact(i1), other.exact(j)) < 0;
        });
        if (separates) return i;
    }
    return last;
}

/// Whether the closed regions of the convex polygons A and B meet (touching
/// counts). Exact in an exact NT; a certified NT raises uncertain_sign when
/// a sign is beyond it.
///
///   the edge kept from the last call first, then every edge of A, then
///   every edge of B (separating_edge_of):
///       if every vertex of the other polygon lies strictly outside the
///       edge's line:                     apart; keep that edge
///   no edge separates:                   they meet
///
/// Why: A and B are disjoint iff the origin lies outside their Minkowski
/// difference A - B, a convex polygon whose edges are the edges of A and
/// the edges of -B, each moved by a vertex of the other. The origin lies
/// outside a convex polygon iff it lies strictly outside the line of one
/// of its edges; for the edge from A's edge e that is every vertex of B
/// strictly outside e's line, for the edge from B's edge f every vertex
/// of A strictly outside f's line. `kept` numbers A's edges from 0 and B's
/// after them; any value is accepted. `spread` bounds |r.x - p.x| +
/// |r.y - p.y| for the doubles of every vertex r of one polygon and p of
/// the other. (A caller with inner discs can first ask whether they overlap,
/// discs_certainly_overlap, before it poses any vertex.)
template <class NT, class A, class B>
bool convex_regions_meet(const A& a, const B& b, double spread, std::uint32_t& kept) {
    const std::size_t na = a.size, nb = b.size;
    const std::size_t kept_a = kept < na ? kept : na, kept_b = kept >= na && kept < na + nb ? kept - na : nb;
    if (kept_a < na && separating_edge_of<NT>(a, b, spread, kept_a, kept_a + 1, na) == kept_a) return false;
    if (kept_b < nb && separating_edge_of<NT>(b, a, spread, kept_b, kept_b + 1, nb) == kept_b) return false;
    std::size_t e = separating_edge_of<NT>(a, b, spread, 0, na, kept_a);
    if (e < na) {
        kept = static_cast<std::uint32_t>(e);
        return false;
    }
    e = separating_edge_of<NT>(b, a, spread, 0, nb, kept_b);
    if (e < nb) {
        kept = static_cast<std::uint32_t>(na + e);
        return false;
    }
    return true;
}

/// Whether some edge of `poly` (one convex ring, counter-clockwise:
/// is_convex_polygon) has every vertex of `other` strictly on its right,
/// both polygons where they stand, every side exact on the doubles as
/// given (exact_orientation), scanned as separating_edge_of scans
/// (every_vertex_right).
inline bool separating_edge_as_given(const polygon& poly, const polygon& other) {
    const std::size_t n = poly.size(), m = other.size();
    std::size_t start = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const point<double>&v = poly.vertex(i), &v1 = poly.vertex(poly.next(i));
        if (every_vertex_right(m, start, [&](std::size_t j) { return exact_orientation(v, v1, other.vertex(j)) < 0; }))
            return true;
    }
    return false;
}

/// Whether the closed regions of two convex polygons meet where they stand
/// (touching counts), both is_convex_polygon, decided exactly on their
/// doubles as given whatever the number type of the caller: no edge of A
/// or of B separates (separating_edge_as_given; why an edge's line
/// suffices: convex_regions_meet). For two polygons of a layer at their own
/// coordinates, where no pose rounds a vertex.
inline bool convex_polygons_meet_as_given(const polygon& a, const polygon& b) {
    return !separating_edge_as_given(a, b) && !separating_edge_as_given(b, a);
}

/// Two convex polygons take the separating-edge test when the product of
/// their sizes is at most this. Measured on random poses near contact (the
/// time study's convex family, double and certified, the detector's
/// convex_pair_pays): 8 x 8 to 16 x 16 frames cost 10-25% less by it, 8 x
/// 32 ones 20% more.
inline constexpr std::size_t convex_pair_limit = 256;

}  // namespace influence2d
