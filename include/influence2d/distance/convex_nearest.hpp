// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which features of two convex polygons are nearest, decided exactly from
/// a candidate pair (convex_gap's simplex): the pair is proven the unique
/// nearest one, or nothing is said (docs/sweep.md, "Convex pairs").

#include <cstddef>
#include <optional>
#include <vector>

#include "influence2d/core/feature.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/distance/convex_gap.hpp"
#include "influence2d/predicates/distance.hpp"
#include "influence2d/predicates/orientation.hpp"

namespace influence2d {

/// The nearest pair of features of two convex polygons: each a vertex or an
/// edge, with its stored index (the edge from vertex `index` to the next).
struct convex_nearest {
    feature static_feature{};      ///< A's feature of the pair
    feature moving_feature{};      ///< B's feature of the pair
    std::size_t static_index = 0;  ///< A's vertex, or its edge's first vertex, stored numbering
    std::size_t moving_index = 0;  ///< B's, likewise
};

namespace convex_nearest_detail {

/// Whether every vertex of `points` but `except` lies strictly beyond `from`
/// along d.
template <class NT>
bool others_beyond(const std::vector<point<NT>>& points, std::size_t except, const point<NT>& from,
                   const point<NT>& d) {
    for (std::size_t k = 0; k < points.size(); ++k)
        if (k != except && !strictly_beyond(from, points[k], d)) return false;
    return true;
}

/// The pair of vertex v of `vertices` and the edge e of `edges` (both
/// counter-clockwise convex rings) when it is the unique nearest pair: v
/// strictly outside the edge's line, its foot strictly inside the edge, and
/// every other vertex of v's polygon strictly farther from that line (so
/// the strip between the edge's line and its parallel through v is empty,
/// and the edge's polygon lies on its own side of its line).
template <class NT>
bool vertex_edge(const std::vector<point<NT>>& vertices, std::size_t v, const std::vector<point<NT>>& edges,
                 std::size_t e, std::size_t next) {
    const point<NT>&p = vertices[v], &e0 = edges[e], &e1 = edges[next];
    if (orientation(e0, e1, p) >= 0) return false;
    const point<NT> along{NT(e1.x - e0.x), NT(e1.y - e0.y)}, back{NT(e0.x - e1.x), NT(e0.y - e1.y)};
    if (!strictly_beyond(e0, p, along) || !strictly_beyond(e1, p, back)) return false;
    const point<NT> outward{along.y, back.x};  // (the right normal: outside a counter-clockwise ring)
    return others_beyond(vertices, v, p, outward);
}

/// A's vertices as they stand and B's posed by q, in NT.
template <class NT>
void placed_vertices(const polygon& a, const polygon& b, const pose& q, std::vector<point<NT>>& av,
                     std::vector<point<NT>>& bv) {
    using tr = number_traits<NT>;
    const rotation_pose placed(q);
    av.clear();
    bv.clear();
    for (std::size_t i = 0; i < a.size(); ++i)
        av.push_back(point<NT>{tr::from_double(a.vertex(i).x), tr::from_double(a.vertex(i).y)});
    for (std::size_t j = 0; j < b.size(); ++j) bv.push_back(placed.apply<NT>(b.vertex(j)));
}

}  // namespace convex_nearest_detail

/// The nearest features of the convex polygons A (where it stands) and B
/// posed by q, when the candidate of `hint` (the simplex of a convex_gap
/// search on them: one vertex pair, or a vertex of one polygon and an edge
/// of the other) is proven in NT the unique nearest pair; none otherwise
/// (the polygons meet or touch, the nearest pair is another or not unique,
/// two parallel edges). A and B must be convex, one counter-clockwise ring
/// each (is_convex_polygon). The proof, every sign by number_traits (exact
/// in an exact NT; a filtered NT raises uncertain_sign when it cannot tell):
///
///   B's vertices posed in NT (rotation_pose(q).apply)
///   vertex a_i and vertex b_j:  every other vertex of A strictly behind a_i
///       along d = b_j - a_i, every other vertex of B strictly beyond b_j
///       (A and B then lie on either side of a strip of width |d| that each
///       touches at that vertex alone)
///   vertex of one, edge of the other:  convex_nearest_detail::vertex_edge
template <class NT>
std::optional<convex_nearest> nearest_convex_pair(const polygon& a, const polygon& b, const pose& q,
                                                  const convex_gap_result& hint) {
    namespace d = convex_nearest_detail;
    if (hint.points == 0) return std::nullopt;
    std::vector<point<NT>> av, bv;
    d::placed_vertices(a, b, q, av, bv);
    const difference_vertex &p = hint.simplex[0], &r = hint.simplex[hint.points - 1];
    if (p.i == r.i && p.j == r.j) {
        const point<NT> dir{NT(bv[p.j].x - av[p.i].x), NT(bv[p.j].y - av[p.i].y)};
        const point<NT> back{NT(-dir.x), NT(-dir.y)};
        if (!d::others_beyond(bv, p.j, bv[p.j], dir) || !d::others_beyond(av, p.i, av[p.i], back)) return std::nullopt;
        return convex_nearest{
            {feature_kind::vertex, input_vertex(a, p.i)}, {feature_kind::vertex, input_vertex(b, p.j)}, p.i, p.j};
    }
    if (p.j == r.j) {  // B's vertex and A's edge
        const std::size_t e = a.next(p.i) == r.i ? p.i : a.next(r.i) == p.i ? r.i : a.size();
        if (e == a.size() || !d::vertex_edge(bv, p.j, av, e, a.next(e))) return std::nullopt;
        return convex_nearest{
            {feature_kind::edge, a.source_edge(e)}, {feature_kind::vertex, input_vertex(b, p.j)}, e, p.j};
    }
    if (p.i == r.i) {  // A's vertex and B's edge
        const std::size_t e = b.next(p.j) == r.j ? p.j : b.next(r.j) == p.j ? r.j : b.size();
        if (e == b.size() || !d::vertex_edge(av, p.i, bv, e, b.next(e))) return std::nullopt;
        return convex_nearest{
            {feature_kind::vertex, input_vertex(a, p.i)}, {feature_kind::edge, b.source_edge(e)}, p.i, e};
    }
    return std::nullopt;  // two edges: parallel, the nearest pair not unique
}

/// The squared distance, in NT, between the features of a nearest pair
/// (nearest_convex_pair) at pose q: between the two vertices, or from the
/// vertex to the edge's line, (E x (p - e0))^2 / |E|^2 for the edge e0 + E
/// (its foot lies inside the edge: the pair's proof).
template <class NT>
NT nearest_pair_squared(const polygon& a, const polygon& b, const pose& q, const convex_nearest& n) {
    using tr = number_traits<NT>;
    const rotation_pose placed(q);
    const auto in_a = [&](std::size_t i) {
        return point<NT>{tr::from_double(a.vertex(i).x), tr::from_double(a.vertex(i).y)};
    };
    const auto in_b = [&](std::size_t j) { return placed.apply<NT>(b.vertex(j)); };
    const auto to_line = [](const point<NT>& p, const point<NT>& e0, const point<NT>& e1) {
        const NT ex = e1.x - e0.x, ey = e1.y - e0.y;
        const NT cross = ex * NT(p.y - e0.y) - ey * NT(p.x - e0.x);
        return NT(cross * cross / NT(ex * ex + ey * ey));
    };
    if (n.static_feature.kind == feature_kind::edge)
        return to_line(in_b(n.moving_index), in_a(n.static_index), in_a(a.next(n.static_index)));
    if (n.moving_feature.kind == feature_kind::edge)
        return to_line(in_a(n.static_index), in_b(n.moving_index), in_b(b.next(n.moving_index)));
    return squared_distance(in_a(n.static_index), in_b(n.moving_index));
}

}  // namespace influence2d
