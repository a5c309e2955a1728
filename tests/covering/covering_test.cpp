// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include "influence2d/covering/covering.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

using test_shapes::pt;

TEMPLATE_TEST_CASE("covering: triangle signs and barycentric signs", "[covering]", INFLUENCE2D_NUMBER_TYPES) {
    using NT = TestType;
    const polygon sq = test_shapes::square(0, 0, 4);
    const triangle_covering<NT> cov(sq, sq.centroid());  // origin (2,2)
    for (std::size_t i = 0; i < 4; ++i) CHECK(cov.sigma(i) == 1);
    // Edge 0 is (0,0)->(4,0).
    auto s = cov.signs(0, pt<NT>(2, 1));  // inside T_0
    CHECK((s.alpha == 1 && s.beta == 1 && s.gamma == 1));
    s = cov.signs(0, pt<NT>(2, -1));  // beyond the edge, inside its cone
    CHECK((s.alpha == -1 && s.beta == 1 && s.gamma == 1));
    s = cov.signs(0, pt<NT>(-3, -3));  // on the line O-V_0 (gamma == 0), beyond the edge
    CHECK((s.alpha == -1 && s.gamma == 0 && s.beta == 1));
    s = cov.signs(0, pt<NT>(5, 1));  // outside the cone, past V_1's side
    CHECK(s.beta == -1);
}

TEST_CASE("covering: an edge collinear with the origin has sigma 0", "[covering]") {
    //   (0,4)+         +(4,4)
    //        | \     / |
    //        |  (2,2)   |      edge 2 runs (4,4)->(2,2), on the line y = x
    //        |  O=(1,1) |      through the origin chosen here
    //   (0,0)+----------+(4,0)
    const polygon p({test_shapes::ring({{0, 0}, {4, 0}, {4, 4}, {2, 2}, {0, 4}})});
    const triangle_covering<double> cov(p, point<double>{1, 1});  // any origin is valid
    CHECK(cov.sigma(2) == 0);
    CHECK(cov.sigma(0) == 1);
    const auto s = cov.signs(2, point<double>{3, 3});
    CHECK((s.alpha == 0 && s.beta == 0 && s.gamma == 0));
}
