// SPDX-License-Identifier: BSL-1.0
// Comparisons of NT values in the predicates: all through number_traits::sign
// (compare_values), so that they agree with the built-in ones on ordinary
// values and a filtered type that cannot decide one raises uncertain_sign,
// never an exception of its own.

#include <catch2/catch.hpp>

#include <limits>

#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/predicates/segments.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

using test_shapes::pt;

TEMPLATE_TEST_CASE("compare_values, between and same_point", "[predicates][compare]", INFLUENCE2D_NUMBER_TYPES) {
    using NT = TestType;
    using tr = number_traits<NT>;
    const NT one = tr::from_double(1), two = tr::from_double(2), minus = tr::from_double(-0.5);
    CHECK(compare_values(one, two) == -1);
    CHECK(compare_values(two, one) == 1);
    CHECK(compare_values(minus, minus) == 0);
    CHECK(compare_values<NT>(one * two, two) == 0);  // an expression as argument
    // between: both ends included, either order.
    CHECK(between(one, minus, two));
    CHECK(between(one, two, minus));
    CHECK(between(two, minus, two));
    CHECK(between(one, one, one));
    CHECK_FALSE(between(two, minus, one));
    CHECK_FALSE(between(minus, two, one));
    CHECK(same_point(pt<NT>(1, 2), pt<NT>(1, 2)));
    CHECK_FALSE(same_point(pt<NT>(1, 2), pt<NT>(1, 3)));
    CHECK_FALSE(same_point(pt<NT>(1, 2), pt<NT>(0, 2)));
}

TEST_CASE("compare_values on double: the built-in comparisons, at the ends of the range", "[predicates][compare]") {
    const double tiny = std::numeric_limits<double>::denorm_min(), big = std::numeric_limits<double>::max();
    CHECK(compare_values(tiny, 0.0) == 1);  // the difference does not underflow to 0
    CHECK(compare_values(2 * tiny, tiny) == 1);
    CHECK(compare_values(big, -big) == 1);  // the difference overflows, its sign stays
    CHECK(compare_values(-big, big) == -1);
    CHECK(compare_values(0.0, -0.0) == 0);
}

TEST_CASE("predicates on intervals raise uncertain_sign only", "[predicates][compare][interval]") {
    // [1, 1 + 2^-52]: not known to be 1, nor known not to be.
    const interval one_ish = interval(0.1) * interval(10.0);
    const interval zero(0), one(1), two(2);
    CHECK_THROWS_AS(compare_values(one_ish, one), uncertain_sign);
    CHECK(compare_values(one_ish, two) == -1);

    // A collinear point whose place against an end is undecided.
    const point<interval> a{zero, zero}, b{one, zero}, p{one_ish, zero};
    CHECK_THROWS_AS(within_collinear_segment(p, a, b), uncertain_sign);
    CHECK_THROWS_AS(same_point(p, b), uncertain_sign);
    // Collinear segments whose extents may or may not touch.
    CHECK_THROWS_AS(segments_intersect(a, b, p, point<interval>{two, zero}), uncertain_sign);
    // A distance bound that may or may not hold: |p - b|^2 against 0.
    CHECK_THROWS_AS(point_segment_within(p, b, b, zero), uncertain_sign);
    // Decided cases answer.
    CHECK(segments_intersect(a, b, point<interval>{zero, zero}, point<interval>{two, zero}));
    CHECK_FALSE(point_segment_within(point<interval>{zero, one}, a, b, interval(0.25)));
}

TEST_CASE("predicates on certified values raise uncertain_sign when undecided", "[predicates][compare]") {
    const certified one_ish = certified(0.1) * certified(10.0);
    const point<certified> a{certified(0.0), certified(0.0)}, b{certified(1.0), certified(0.0)},
        p{one_ish, certified(0.0)};
    CHECK_THROWS_AS(within_collinear_segment(p, a, b), uncertain_sign);
    CHECK(within_collinear_segment(point<certified>{certified(0.5), certified(0.0)}, a, b));
}
