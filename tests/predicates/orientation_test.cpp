// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include "influence2d/predicates/orientation.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

using test_shapes::pt;

TEMPLATE_TEST_CASE("orientation: left, right, collinear", "[orientation]", INFLUENCE2D_NUMBER_TYPES) {
    const auto a = pt<TestType>(0, 0), b = pt<TestType>(4, 0);
    CHECK(orientation(a, b, pt<TestType>(1, 1)) == 1);
    CHECK(orientation(a, b, pt<TestType>(1, -1)) == -1);
    CHECK(orientation(a, b, pt<TestType>(9, 0)) == 0);
    CHECK(orientation(a, a, pt<TestType>(9, 3)) == 0);  // degenerate segment
}

TEST_CASE("orientation: the precision cliff, exact type against double", "[orientation]") {
    // c lies 2^-26 off the line a-b at magnitude 1e8: exact sees it, double
    // rounds the determinant to 0.
    const double ax = 100000000.5, ay = 100000000.0, bx = 100003750.5, by = 100001250.0;
    const double cx = 100007500.5 + 0x1p-26, cy = 100002500.0;
    CHECK(orientation(pt<exact_rational>(ax, ay), pt<exact_rational>(bx, by), pt<exact_rational>(cx, cy)) == -1);
    CHECK(orientation(pt<exact_rational>(ax, ay), pt<exact_rational>(bx, by),
                      pt<exact_rational>(100007500.5, cy)) == 0);
}

TEMPLATE_TEST_CASE("on_segment: closed segment, ends included", "[orientation]", INFLUENCE2D_NUMBER_TYPES) {
    const auto a = pt<TestType>(0, 0), b = pt<TestType>(2, 2);
    CHECK(on_segment(pt<TestType>(1, 1), a, b));
    CHECK(on_segment(a, a, b));
    CHECK(on_segment(b, a, b));
    CHECK_FALSE(on_segment(pt<TestType>(3, 3), a, b));
    CHECK_FALSE(on_segment(pt<TestType>(1, 1.5), a, b));
}
