// SPDX-License-Identifier: BSL-1.0
// share_a_vertex: a vertex of one polygon equal to one of the other, on the
// doubles as given, against a comparison of every vertex with every vertex.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "influence2d/predicates/shared_vertex.hpp"
#include "support/effort.hpp"
#include "support/random.hpp"
#include "support/shapes.hpp"

using namespace influence2d;
using test_shapes::ring;

namespace {

polygon one_ring(std::vector<point<double>> v) { return polygon({ring(std::move(v))}); }

/// The reference: some vertex of a equal to some vertex of b, each pair
/// compared.
bool every_pair_shares(const polygon& a, const polygon& b) {
    for (const point<double>& p : a.vertices())
        for (const point<double>& q : b.vertices())
            if (p.x == q.x && p.y == q.y) return true;
    return false;
}

/// The vertices of the smaller polygon (a's when the sizes tie) inside the
/// overlap of the two boxes: more than shared_vertex_most and the pair is
/// not tried.
std::size_t smaller_in_overlap(const polygon& a, const polygon& b) {
    const box &ba = a.bounds(), &bb = b.bounds();
    const polygon& s = a.size() <= b.size() ? a : b;
    std::size_t n = 0;
    for (const point<double>& v : s.vertices())
        n += v.x >= std::max(ba.min_x, bb.min_x) && v.x <= std::min(ba.max_x, bb.max_x) &&
             v.y >= std::max(ba.min_y, bb.min_y) && v.y <= std::min(ba.max_y, bb.max_y);
    return n;
}

}  // namespace

TEST_CASE("shared vertex: exact equality of the doubles, not nearness", "[predicates][shared_vertex]") {
    const polygon unit = test_shapes::square(0, 0, 1);
    // A corner, a whole side, either order.
    CHECK(share_a_vertex(unit, test_shapes::square(1, 1, 1)));
    CHECK(share_a_vertex(test_shapes::square(1, 1, 1), unit));
    CHECK(share_a_vertex(unit, test_shapes::square(1, 0, 1)));
    // The corner a unit in the last place off, either coordinate: not
    // shared (those squares meet or not; that is for the other tests).
    const double up = std::nextafter(1.0, 2.0);
    CHECK_FALSE(share_a_vertex(unit, test_shapes::square(up, 1, 1)));
    CHECK_FALSE(share_a_vertex(unit, test_shapes::square(1, up, 1)));
    // A vertex on the other's side but none of its vertices: not a shared
    // vertex.
    CHECK_FALSE(share_a_vertex(unit, one_ring({{1, 0.5}, {2, 0}, {2, 1}})));
    // A vertex whose x is one of the other's and whose y another's.
    CHECK_FALSE(share_a_vertex(one_ring({{0, 0}, {2, 0}, {2, 3}}), one_ring({{2, 2}, {3, 2}, {3, 3}, {0, 5}})));
    // Two columns of vertices at the same x, a half apart in y: every
    // vertex of one finds entries of the same x in the table, none equal.
    std::vector<point<double>> column{{-1, 0}}, between{{1, 0.25}};
    for (int k = 0; k < 100; ++k) column.push_back({0, static_cast<double>(k)});
    for (int k = 0; k < 99; ++k) between.push_back({0, k + 0.5});
    CHECK_FALSE(share_a_vertex(one_ring(column), one_ring(between)));
    CHECK_FALSE(share_a_vertex(one_ring(between), one_ring(column)));
    between.push_back({0, 99});
    CHECK(share_a_vertex(one_ring(column), one_ring(between)));
    // -0 is +0.
    CHECK(share_a_vertex(one_ring({{-1, -1}, {-0.0, -1}, {-0.0, -0.0}, {-1, 0}}), test_shapes::square(0, 0, 1)));
    // A hole's corner shared with a polygon inside the hole.
    CHECK(share_a_vertex(test_shapes::square_with_hole(), test_shapes::square(2, 2, 1)));
    // Boxes apart, and a polygon with a vertex equal to the other's but
    // listed in its other ring.
    CHECK_FALSE(share_a_vertex(unit, test_shapes::square(3, 3, 1)));
    CHECK(share_a_vertex(polygon({test_shapes::square_ring(5, 5, 1), test_shapes::square_ring(-1, -1, 1)}), unit));
}

TEST_CASE("shared vertex: more than the table holds in the overlap is not tried", "[predicates][shared_vertex]") {
    // A polygon of shared_vertex_most + 1 vertices along a staircase, and
    // the same staircase shifted so that only its last vertex is shared.
    std::vector<point<double>> stair;
    for (std::size_t k = 0; k < shared_vertex_most; ++k)
        stair.push_back({static_cast<double>(k / 2 + k % 2), static_cast<double>(k / 2)});
    stair.push_back({0, static_cast<double>(shared_vertex_most)});
    const polygon a = one_ring(stair);
    REQUIRE(smaller_in_overlap(a, a) > shared_vertex_most);
    CHECK_FALSE(share_a_vertex(a, a));
    // With one vertex fewer in the overlap, tried and found.
    std::vector<point<double>> fewer(stair.begin() + 1, stair.end());
    const polygon b = one_ring(fewer);
    REQUIRE(smaller_in_overlap(b, b) <= shared_vertex_most);
    CHECK(share_a_vertex(b, b));
}

TEST_CASE("shared vertex: random polygons on a coarse lattice, against every pair of vertices",
          "[predicates][shared_vertex]") {
    // Vertices on a lattice of 9 x 9 points, some at -0, some a unit in the
    // last place off a lattice point, rings of 3 to 150 vertices (some
    // beyond the table), one or two rings.
    test_random::rng g(20261206);
    std::size_t shared = 0, apart = 0, not_tried = 0;
    const auto lattice = [&g]() {
        double x = static_cast<double>(g.index(9)) - 4, y = static_cast<double>(g.index(9)) - 4;
        if (g.chance(0.05)) x = std::nextafter(x, 10.0);
        if (g.chance(0.05)) y = std::nextafter(y, -10.0);
        if (x == 0 && g.chance(0.5)) x = -0.0;
        return point<double>{x, y};
    };
    // (A ring of fewer than three distinct vertices drawn again.)
    const auto random_ring = [&]() {
        for (;;) {
            std::vector<point<double>> v;
            const std::size_t n = g.chance(0.1) ? 130 + g.index(20) : 3 + g.index(12);
            for (std::size_t k = 0; k < n; ++k) v.push_back(lattice());
            std::vector<point<double>> distinct = v;
            std::sort(distinct.begin(), distinct.end(), [](const point<double>& p, const point<double>& q) {
                return p.x < q.x || (p.x == q.x && p.y < q.y);
            });
            if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() >= 3) return ring(v);
        }
    };
    const auto random_polygon = [&]() {
        std::vector<ring_input> rings;
        const std::size_t ring_count = 1 + g.index(2);
        for (std::size_t r = 0; r < ring_count; ++r) rings.push_back(random_ring());
        return polygon(rings);
    };
    const int rounds = test_effort::scaled(4000);
    for (int k = 0; k < rounds; ++k) {
        const polygon a = random_polygon(), b = random_polygon();
        const bool want = every_pair_shares(a, b);
        INFO("round " << k);
        if (smaller_in_overlap(a, b) > shared_vertex_most) {
            CHECK_FALSE(share_a_vertex(a, b));
            ++not_tried;
            continue;
        }
        CHECK(share_a_vertex(a, b) == want);
        CHECK(share_a_vertex(b, a) == want);
        (want ? shared : apart) += 1;
    }
    // Not vacuous: both answers, and pairs beyond the table.
    CHECK(shared > static_cast<std::size_t>(rounds) / 4);
    CHECK(apart > static_cast<std::size_t>(rounds) / 20);
    CHECK(not_tried > 0);
}
