// SPDX-License-Identifier: BSL-1.0
// The vertices reaching farthest in eight directions (scene/reaching_vertices.hpp)
// against a scan in exact rationals of every vertex's offset along each
// direction, on random multipolygons and swallowers far from and near the
// origin; the nearest direction against the angle of random vectors.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/random_scenes.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

#include "influence2d/number/cgal.hpp"
#include "influence2d/scene/reaching_vertices.hpp"

namespace {

using namespace influence2d;
using test_scenes::rng;
using Q = exact_rational;

/// Direction k's unit vector as the table rounds it: cos and sin of k pi / 4
/// in double.
std::pair<double, double> direction_of(std::size_t k) {
    const double a = static_cast<double>(k) * 0.78539816339744828;
    const double c = std::cos(a), s = std::sin(a);
    // Zero where cos or sin of a multiple of pi / 2 is zero (not 6e-17).
    return {std::fabs(c) < 1e-9 ? 0.0 : c, std::fabs(s) < 1e-9 ? 0.0 : s};
}

}  // namespace

TEST_CASE("reaching_vertices: each direction's vertex reaches farthest, by exact offsets", "[scene]") {
    rng g(2400);
    const int rounds = test_effort::scaled(200);
    std::size_t distinct = 0;
    for (int round = 0; round < rounds; ++round) {
        std::vector<ring_input> rings = round % 4 == 3
                                            ? test_scenes::random_swallower(g).rings()
                                            : test_scenes::random_multi(g, 10 + round % 30, 2 + round % 6).rings();
        // Far from the origin every other round: the offsets are differences.
        const double shift = round % 2 ? std::ldexp(1.0, 30 + round % 20) : 0.0;
        for (ring_input& ring : rings)
            for (point<double>& v : ring.vertices) v = {v.x + shift, v.y - shift};
        const polygon p(rings);
        REQUIRE(p.size() > 0);
        const point<double> c = p.centroid();
        const reaching_vertices table(p, c);
        std::set<std::uint32_t> chosen;
        for (std::size_t k = 0; k < reaching_vertices::directions; ++k) {
            const auto [dx, dy] = direction_of(k);
            // The table's vertex is the first one of largest offset up to the
            // rounding of the offsets (a few units in the last place of the
            // largest coordinate difference).
            const auto offset = [&](std::size_t j) -> Q {
                return Q(dx) * (Q(p.vertex(j).x) - Q(c.x)) + Q(dy) * (Q(p.vertex(j).y) - Q(c.y));
            };
            Q best = offset(0);
            double reach = 0;
            for (std::size_t j = 0; j < p.size(); ++j) {
                if (offset(j) > best) best = offset(j);
                reach = std::max({reach, std::fabs(p.vertex(j).x - c.x), std::fabs(p.vertex(j).y - c.y)});
            }
            // The unit vector's doubles differ from the true direction's, but
            // the reference uses the same doubles: only the offsets' rounding
            // (a difference, two products and a sum) separates the two.
            const double tolerance = 8 * std::numeric_limits<double>::epsilon() * reach;
            const std::uint32_t j = table.toward(dx, dy)[0];
            INFO("round " << round << ", direction " << k << ", vertex " << j);
            CHECK(offset(j) >= best - Q(tolerance));
            chosen.insert(j);
        }
        distinct += chosen.size();
    }
    CHECK(rounds > 0);
    // Not vacuous: most polygons have several distinct extreme vertices.
    CHECK(distinct > 3 * static_cast<std::size_t>(rounds));
}

TEST_CASE("reaching_vertices: the nearest direction and its neighbours", "[scene]") {
    rng g(2401);
    for (int k = 0; k < test_effort::scaled(20000); ++k) {
        const double angle = (2 * g.unit() - 1) * 3.14159265358979323846;
        const double length = std::ldexp(1.0, static_cast<int>(g.index(1200)) - 600);
        const double x = length * std::cos(angle), y = length * std::sin(angle);
        const std::size_t d = reaching_vertices::nearest_direction(x, y);
        REQUIRE(d < reaching_vertices::directions);
        // Within an eighth of a turn of the vector's angle, up to rounding.
        const double gap = std::remainder(angle - static_cast<double>(d) * 0.78539816339744828, 6.283185307179586);
        INFO("angle " << angle << ", direction " << d);
        CHECK(std::fabs(gap) <= 0.39269908169872414 + 1e-12);
    }
    // The axes and diagonals themselves.
    CHECK(reaching_vertices::nearest_direction(1, 0) == 0);
    CHECK(reaching_vertices::nearest_direction(1, 1) == 1);
    CHECK(reaching_vertices::nearest_direction(0, 1) == 2);
    CHECK(reaching_vertices::nearest_direction(-1, 1) == 3);
    CHECK(reaching_vertices::nearest_direction(-1, 0) == 4);
    CHECK(reaching_vertices::nearest_direction(-1, -1) == 5);
    CHECK(reaching_vertices::nearest_direction(0, -1) == 6);
    CHECK(reaching_vertices::nearest_direction(1, -1) == 7);
    // Any input, NaN and zero included, names a direction.
    const double nan_value = std::numeric_limits<double>::quiet_NaN();
    CHECK(reaching_vertices::nearest_direction(nan_value, 1) < reaching_vertices::directions);
    CHECK(reaching_vertices::nearest_direction(0, 0) < reaching_vertices::directions);
    CHECK(reaching_vertices::nearest_direction(-HUGE_VAL, HUGE_VAL) < reaching_vertices::directions);
    // toward: the nearest direction's vertex, then its neighbours'. On a
    // regular octagon about the origin, vertex k lies along direction k.
    std::vector<point<double>> octagon;
    for (std::size_t k = 0; k < 8; ++k) {
        const auto [dx, dy] = direction_of(k);
        octagon.push_back({dx, dy});
    }
    const polygon regular({ring_input{octagon}});
    const reaching_vertices table(regular, {0, 0});
    for (std::uint32_t k = 0; k < 8; ++k) {
        const auto [dx, dy] = direction_of(k);
        const auto three = table.toward(3 * dx, 3 * dy);
        CHECK(three[0] == k);
        CHECK(three[1] == (k + 1) % 8);
        CHECK(three[2] == (k + 7) % 8);
    }
}
