// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "influence2d/influence/edge_tree.hpp"
#include "influence2d/influence/located_through_tree.hpp"
#include "support/effort.hpp"
#include "support/neighbours.hpp"
#include "support/random_scenes.hpp"
#include "verification/cgal_reference.hpp"

using namespace influence2d;

namespace {

/// Points to locate in m's polygon: random points over its box and beyond,
/// its vertices, the midpoints of its edges (on the boundary), points at a
/// vertex's height (the ray through that vertex) and points just off an
/// edge's midpoint.
std::vector<point<double>> probe_points(test_scenes::rng& g, const polygon& p, std::size_t count) {
    std::vector<point<double>> out;
    const box b = p.bounds();
    const double wx = b.max_x - b.min_x, wy = b.max_y - b.min_y;
    for (std::size_t k = 0; k < count; ++k) {
        out.push_back(
            {g.uniform(b.min_x - 0.1 * wx, b.max_x + 0.1 * wx), g.uniform(b.min_y - 0.1 * wy, b.max_y + 0.1 * wy)});
        const std::size_t i = g.index(p.size());
        const point<double>& u = p.vertex(i);
        const point<double>& v = p.vertex(p.next(i));
        switch (k % 4) {
        case 0: out.push_back(u); break;
        case 1: out.push_back({u.x / 2 + v.x / 2, u.y / 2 + v.y / 2}); break;
        case 2: out.push_back({g.uniform(b.min_x - 1, b.max_x + 1), u.y}); break;
        default: out.push_back({u.x / 2 + v.x / 2 + 0x1p-30 * (v.y - u.y), u.y / 2 + v.y / 2 - 0x1p-30 * (v.x - u.x)});
        }
    }
    return out;
}

}  // namespace

TEST_CASE("edge_tree::query_ray visits every edge whose box may meet the ray", "[influence][edge_tree]") {
    test_scenes::rng g(20261202);
    for (int round = 0; round < test_effort::scaled(40); ++round) {
        const polygon p = test_scenes::random_multi(g, 20).to_polygon();
        const edge_tree tree(p);
        for (const point<double>& q : probe_points(g, p, 40)) {
            for (const double e : {0.0, 0x1p-20, 0.25}) {
                std::vector<std::uint32_t> seen;
                CHECK_FALSE(tree.query_ray(q, e, [&](std::uint32_t i) {
                    seen.push_back(i);
                    return false;
                }));
                std::sort(seen.begin(), seen.end());
                CHECK(std::adjacent_find(seen.begin(), seen.end()) == seen.end());  // each at most once
                for (std::size_t i = 0; i < p.size(); ++i) {
                    box b;
                    b.add(p.vertex(i));
                    b.add(p.vertex(p.next(i)));
                    if (!certainly_off_ray(b, q, e))
                        CHECK(std::binary_search(seen.begin(), seen.end(), static_cast<std::uint32_t>(i)));
                }
            }
        }
    }
}

TEST_CASE("certain_location_through_tree: every answer holds for every point within the margin (CGAL's exact region)",
          "[influence][locate]") {
    test_scenes::rng g(7741);
    std::size_t asked = 0, answered = 0, random_asked = 0, random_answered = 0;
    for (int round = 0; round < test_effort::scaled(60); ++round) {
        const polygon p = test_scenes::random_multi(g, 20).to_polygon();
        const edge_tree tree(p);
        const verification::cgal_reference reference(p, p);
        const std::vector<point<double>> points = probe_points(g, p, 60);
        for (std::size_t k = 0; k < points.size(); ++k) {
            const point<double>& q = points[k];
            for (const double e : {0.0, 0x1p-40, 0x1p-20, 0x1p-8}) {
                const std::optional<location> where = certain_location_through_tree(p, tree, q, e);
                ++asked;
                if (k % 2 == 0) ++random_asked;
                if (!where) continue;
                ++answered;
                if (k % 2 == 0) ++random_answered;
                REQUIRE(*where != location::boundary);
                const bool inside = *where == location::inside;
                // q itself and points e/2 off it on each coordinate (their
                // rounding far below e/2): each within e of q.
                const double h = e / 2;
                for (const point<double> d : {point<double>{0, 0}, point<double>{h, h}, point<double>{-h, h},
                                              point<double>{h, -h}, point<double>{-h, -h}}) {
                    INFO("round " << round << ", point " << k << " (" << q.x << ", " << q.y << "), e " << e);
                    CHECK(reference.static_region_holds(q.x + d.x, q.y + d.y) == inside);
                }
            }
        }
    }
    // The filter must answer: nearly every random point, the boundary's
    // points never (every answer above is checked).
    INFO("answered " << answered << " of " << asked << "; random points " << random_answered << " of " << random_asked);
    CHECK(random_answered * 100 >= random_asked * 95);
    CHECK(answered < asked);
}

TEST_CASE("certain_location_through_tree: a point on an edge or at a vertex is never settled", "[influence][locate]") {
    // A square with a square hole; its boundary points and the ray along
    // its bottom edge.
    const polygon p({ring_input{{{0, 0}, {8, 0}, {8, 8}, {0, 8}}, ring_role::outer},
                     ring_input{{{2, 2}, {2, 6}, {6, 6}, {6, 2}}, ring_role::hole}});
    const edge_tree tree(p);
    for (const point<double> q :
         {point<double>{4, 0}, point<double>{0, 0}, point<double>{2, 4}, point<double>{6, 6}, point<double>{8, 3}})
        CHECK_FALSE(certain_location_through_tree(p, tree, q, 0).has_value());
    CHECK(certain_location_through_tree(p, tree, {1, 1}, 0) == location::inside);
    CHECK(certain_location_through_tree(p, tree, {4, 4}, 0) == location::outside);  // in the hole
    CHECK(certain_location_through_tree(p, tree, {9, 4}, 0) == location::outside);
    CHECK(certain_location_through_tree(p, tree, {1, 1}, 0.25) == location::inside);
    CHECK_FALSE(certain_location_through_tree(p, tree, {1, 1}, 1).has_value());  // within 1 of the hole's corner
    // At a vertex's height: the ray runs along the hole's bottom edge.
    CHECK_FALSE(certain_location_through_tree(p, tree, {1, 2}, 0).has_value());
}

TEST_CASE("certain_location_through_tree: real neighbours' vertices, shared borders exactly, in each other",
          "[influence][locate][real]") {
    // Every vertex of one country located in its neighbour (Chile and
    // Argentina, Indonesia and Malaysia: border vertices shared exactly,
    // so many lie on the other's boundary), and the same vertices moved by
    // a small step, with and without a margin.
    const std::vector<polygon> layer = test_data::neighbours();
    REQUIRE(layer.size() == 4);
    std::size_t asked = 0, answered = 0;
    for (const auto& [host, guest] : {std::pair<int, int>{0, 1}, {1, 0}, {2, 3}, {3, 2}}) {
        const polygon& p = layer[host];
        const edge_tree tree(p);
        const verification::cgal_reference reference(p, p);
        const polygon& g = layer[guest];
        for (std::size_t i = 0; i < g.size(); ++i)
            for (const double step : {0.0, 1e-9, -1e-3})
                for (const double e : {0.0, 0x1p-40}) {
                    const point<double> q{g.vertex(i).x + step, g.vertex(i).y - step};
                    const std::optional<location> where = certain_location_through_tree(p, tree, q, e);
                    ++asked;
                    if (!where) continue;
                    ++answered;
                    INFO("host " << host << ", vertex " << i << " of " << guest << ", step " << step << ", e " << e);
                    CHECK(reference.static_region_holds(q.x, q.y) == (*where == location::inside));
                }
    }
    INFO("answered " << answered << " of " << asked);
    CHECK(answered * 2 > asked);
}
