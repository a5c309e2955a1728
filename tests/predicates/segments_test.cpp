// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include "influence2d/predicates/segments.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

using test_shapes::pt;

TEMPLATE_TEST_CASE("segments_intersect: closed segments", "[segments]", INFLUENCE2D_NUMBER_TYPES) {
    using NT = TestType;
    const auto a = pt<NT>(0, 0), b = pt<NT>(4, 0);
    SECTION("proper crossing") { CHECK(segments_intersect(a, b, pt<NT>(2, -1), pt<NT>(2, 1))); }
    SECTION("T junction: an end on the other's interior") {
        //   (2,1)
        //     |
        // a---+---b
        CHECK(segments_intersect(a, b, pt<NT>(2, 0), pt<NT>(2, 1)));
    }
    SECTION("shared end") { CHECK(segments_intersect(a, b, b, pt<NT>(5, 3))); }
    SECTION("collinear overlap and collinear gap") {
        CHECK(segments_intersect(a, b, pt<NT>(3, 0), pt<NT>(6, 0)));
        CHECK(segments_intersect(a, b, pt<NT>(4, 0), pt<NT>(6, 0)));
        CHECK_FALSE(segments_intersect(a, b, pt<NT>(5, 0), pt<NT>(6, 0)));
    }
    SECTION("crossing the line beyond the segment's end") {
        CHECK_FALSE(segments_intersect(a, b, pt<NT>(5, -1), pt<NT>(5, 1)));
    }
    SECTION("parallel") { CHECK_FALSE(segments_intersect(a, b, pt<NT>(0, 1), pt<NT>(4, 1))); }
    SECTION("degenerate segments (repeated vertices)") {
        CHECK(segments_intersect(a, b, pt<NT>(1, 0), pt<NT>(1, 0)));
        CHECK_FALSE(segments_intersect(a, b, pt<NT>(1, 1), pt<NT>(1, 1)));
        CHECK_FALSE(segments_intersect(pt<NT>(5, 0), pt<NT>(5, 0), a, b));
        CHECK(segments_intersect(pt<NT>(1, 1), pt<NT>(1, 1), pt<NT>(1, 1), pt<NT>(1, 1)));
        CHECK_FALSE(segments_intersect(pt<NT>(1, 1), pt<NT>(1, 1), pt<NT>(1, 2), pt<NT>(1, 2)));
    }
}

TEST_CASE("segments_intersect: a touch at 2^-60 is seen exactly", "[segments]") {
    using NT = exact_rational;
    // The moving end lies 2^-60 below the segment's line, near its middle.
    const auto a = pt<NT>(0, 1), b = pt<NT>(3, 1 + 0x1p-50);
    const double y_mid = 1 + 0x1p-51;  // the line's height at x = 1.5
    CHECK(segments_intersect(a, b, pt<NT>(1.5, 2), pt<NT>(1.5, y_mid)));
    CHECK_FALSE(segments_intersect(a, b, pt<NT>(1.5, 2), pt<NT>(1.5, y_mid + 0x1p-52)));
}

TEMPLATE_TEST_CASE("segments_within: distance bounds, ends and interiors", "[segments]", INFLUENCE2D_NUMBER_TYPES) {
    using NT = TestType;
    const auto a = pt<NT>(0, 0), b = pt<NT>(4, 0);
    const NT one = NT(1), quarter = NT(0.25);
    // Parallel at distance 1.
    CHECK(segments_within(a, b, pt<NT>(1, 1), pt<NT>(3, 1), one));
    CHECK_FALSE(segments_within(a, b, pt<NT>(1, 1), pt<NT>(3, 1), quarter));
    // End to end: (4,0) to (4.5,0) is 0.5 apart: within 0.5 (d2 = 0.25), not within 0.25.
    CHECK(segments_within(a, b, pt<NT>(4.5, 0), pt<NT>(6, 0), quarter));
    CHECK_FALSE(segments_within(a, b, pt<NT>(4.5, 0), pt<NT>(6, 0), NT(0.0625)));
    // Crossing: distance 0.
    CHECK(segments_within(a, b, pt<NT>(2, -1), pt<NT>(2, 1), NT(0)));
    CHECK(point_segment_within(pt<NT>(2, 0.5), a, b, quarter));
    CHECK_FALSE(point_segment_within(pt<NT>(-0.5, 0.5), a, b, quarter));
}
