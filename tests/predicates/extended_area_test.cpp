// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include "influence2d/influence/edge_grid.hpp"
#include "influence2d/predicates/extended_area.hpp"
#include "support/random.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

TEMPLATE_TEST_CASE("extended areas: capsule and band", "[extended]", INFLUENCE2D_NUMBER_TYPES) {
    using NT = TestType;
    const point<NT> a{NT(0), NT(0)}, b{NT(4), NT(1)};  // |slope| <= 1: vertical caps
    const NT n(1), n2(1);
    auto P = [](double x, double y) { return point<NT>{NT(x), NT(y)}; };
    CHECK(in_capsule(P(2, 1), a, b, n2));
    CHECK(in_capsule(P(-1, 0), a, b, n2));               // exactly n from the end
    CHECK_FALSE(in_capsule(P(-0.75, -0.75), a, b, n2));  // 1.06 from the end
    CHECK(in_band(P(-0.75, -0.75), a, b, n, n2));        // but inside the band's corner
    CHECK_FALSE(in_band(P(-1.25, -0.25), a, b, n, n2));  // beyond the vertical cap
    CHECK_FALSE(in_band(P(2, 3), a, b, n, n2));          // beyond the parallel
}

TEST_CASE("extended areas: the band contains the capsule", "[extended]") {
    test_random::rng rng(3);
    auto u = [&] { return rng.uniform(-10, 10); };
    for (int k = 0; k < 20000; ++k) {
        const point<double> a{u(), u()}, b{u(), u()}, p{u(), u()};
        const double n = std::fabs(u()) / 2;
        if (in_capsule(p, a, b, n * n)) CHECK(in_band(p, a, b, n, n * n));
    }
}

TEST_CASE("edge grid: every edge within the reach is listed", "[grid]") {
    const polygon c = test_shapes::c_shape();
    const double reach = 0.7;
    const edge_grid grid(c, reach, 1e-9);
    test_random::rng rng(5);
    const auto coordinate = [&] { return static_cast<double>(rng.index(1001)) / 100 - 2; };
    for (int k = 0; k < 5000; ++k) {
        const point<double> p{coordinate(), coordinate()};
        const auto listed = grid.query(p);
        for (std::size_t e = 0; e < c.size(); ++e) {
            if (segment_distance(p, c.vertex(e), c.vertex(c.next(e))) > reach) continue;
            INFO("point " << p.x << ", " << p.y << " edge " << e);
            CHECK(std::find(listed.begin(), listed.end(), e) != listed.end());
        }
    }
}
