// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>

#include <CGAL/Cartesian.h>

#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "support/random.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

using test_shapes::pt;

namespace {
using rational_kernel = CGAL::Cartesian<exact_rational>;
}  // namespace

TEMPLATE_TEST_CASE("orientation: left, right, collinear", "[orientation]", INFLUENCE2D_NUMBER_TYPES) {
    const auto a = pt<TestType>(0, 0), b = pt<TestType>(4, 0);
    CHECK(orientation(a, b, pt<TestType>(1, 1)) == 1);
    CHECK(orientation(a, b, pt<TestType>(1, -1)) == -1);
    CHECK(orientation(a, b, pt<TestType>(9, 0)) == 0);
    CHECK(orientation(a, a, pt<TestType>(9, 3)) == 0);  // degenerate segment
}

TEST_CASE("orientation: the precision cliff, exact type against double", "[orientation]") {
    // The exact sign comes from CGAL's own kernel on exact rationals, not from
    // the library's determinant.
    const auto exact_sign = [](double ax, double ay, double bx, double by, double cx, double cy) {
        using P = rational_kernel::Point_2;
        return static_cast<int>(CGAL::orientation(P(ax, ay), P(bx, by), P(cx, cy)));
    };
    const auto both = [](auto ax, auto ay, auto bx, auto by, auto cx, auto cy, auto type) {
        using NT = decltype(type);
        return orientation(pt<NT>(ax, ay), pt<NT>(bx, by), pt<NT>(cx, cy));
    };

    SECTION("far from the cliff: c 2^-26 off a line at magnitude 1e8, double is right") {
        //   a = (1e8 + 0.5, 1e8) --- b (+3750, +1250) --- c (+7500 + 2^-26, +2500)
        // Every difference and product of the determinant is exact in double
        // here (c.x - a.x = 7500 + 2^-26 needs 39 bits), so the rounded
        // determinant is the exact one: -1250 * 2^-26.
        const double ax = 100000000.5, ay = 100000000.0, bx = 100003750.5, by = 100001250.0;
        const double cx = 100007500.5 + 0x1p-26, cy = 100002500.0;
        REQUIRE(cx - 100007500.5 == 0x1p-26);  // c.x is a double at that offset
        CHECK(exact_sign(ax, ay, bx, by, cx, cy) == -1);
        CHECK(both(ax, ay, bx, by, cx, cy, exact_rational{}) == -1);
        CHECK(both(ax, ay, bx, by, cx, cy, double{}) == -1);
        CHECK(both(ax, ay, bx, by, cx, cy, certified{}) == -1);
        // Without the offset the three are collinear.
        CHECK(exact_sign(ax, ay, bx, by, 100007500.5, cy) == 0);
        CHECK(both(ax, ay, bx, by, 100007500.5, cy, exact_rational{}) == 0);
        CHECK(both(ax, ay, bx, by, 100007500.5, cy, double{}) == 0);
    }

    SECTION("past the cliff: a few ulps off the diagonal near (0.5, 0.5), double is wrong") {
        //   c = (24, 24)
        //        /
        //   b = (12, 12)
        //      /
        //   a = (0.5 + 41u, 0.5 + 48u), u = 2^-53: a little above the diagonal
        //       y = x, so c lies left of a->b: (b - a) x (c - a) > 0
        // (Kettner et al., "Classroom examples of robustness problems in
        // geometric computations"): the differences 12 - a.x and 24 - a.x are
        // rounded, and the rounded determinant has the wrong sign. The header
        // says so of floating types: "the sign of the rounded determinant,
        // which can be wrong for nearly collinear points".
        const double u = 0x1p-53;
        const double ax = 0.5 + 41 * u, ay = 0.5 + 48 * u;
        REQUIRE(ax - 0.5 == 41 * u);  // a's coordinates are the doubles meant
        REQUIRE(ay - 0.5 == 48 * u);
        const int exact = exact_sign(ax, ay, 12, 12, 24, 24);
        CHECK(exact == 1);
        CHECK(both(ax, ay, 12.0, 12.0, 24.0, 24.0, exact_rational{}) == exact);
        // The types that claim the exact sign: certified settles it exactly on
        // input doubles (exact_double_fallback); interval answers exactly or
        // throws uncertain_sign.
        CHECK(both(ax, ay, 12.0, 12.0, 24.0, 24.0, certified{}) == exact);
        int interval_sign = 2;  // 2: uncertain_sign thrown
        try {
            interval_sign = both(ax, ay, 12.0, 12.0, 24.0, 24.0, interval{});
        } catch (const uncertain_sign&) {}
        CHECK((interval_sign == exact || interval_sign == 2));
        // double gets the sign of its rounded determinant: the cliff is real
        // here, which is what makes this case a test of the exact types.
        CHECK(both(ax, ay, 12.0, 12.0, 24.0, 24.0, double{}) == -exact);
    }
}

TEST_CASE("orientation<double> agrees with the exact sign wherever the determinant is far from 0", "[orientation]") {
    // The rounded determinant (b.x - a.x)(c.y - a.y) - (b.y - a.y)(c.x - a.x)
    // of doubles errs by less than 4u (|l| + |r|) + O(u^2) (u = 2^-53; l, r
    // the exact products: a rounded difference, a rounded product per term,
    // then a rounded subtraction). Where the exact determinant exceeds
    // 8u (|l| + |r|), computed exactly, double's sign must be the exact one.
    // Random points at many scales, half of them nearly collinear (c on the
    // line a-b, then moved a few ulps), so that both sides of the bound occur.
    test_random::rng r(20260402);
    using P = rational_kernel::Point_2;
    const exact_rational eight_u(0x1p-50);
    std::size_t far = 0, near = 0;
    for (int k = 0; k < 20000; ++k) {
        const double scale = std::ldexp(1.0, static_cast<int>(r.index(120)) - 60);
        const double ax = scale * r.signed_unit(), ay = scale * r.signed_unit();
        const double bx = scale * r.signed_unit(), by = scale * r.signed_unit();
        double cx = scale * r.signed_unit(), cy = scale * r.signed_unit();
        if (r.chance(0.5)) {
            const double f = r.uniform(-2, 2);
            cx = ax + f * (bx - ax);
            cy = ay + f * (by - ay);
            for (int steps = static_cast<int>(r.index(4)); steps > 0; --steps)
                cy = std::nextafter(cy, r.chance(0.5) ? HUGE_VAL : -HUGE_VAL);
        }
        const exact_rational l = (exact_rational(bx) - ax) * (exact_rational(cy) - ay);
        const exact_rational rr = (exact_rational(by) - ay) * (exact_rational(cx) - ax);
        const exact_rational det = l - rr;
        const int exact = static_cast<int>(CGAL::orientation(P(ax, ay), P(bx, by), P(cx, cy)));
        REQUIRE(exact == static_cast<int>(CGAL::sign(det)));  // the two exact routes agree
        if (CGAL::abs(det) > eight_u * (CGAL::abs(l) + CGAL::abs(rr))) {
            ++far;
            INFO("a = (" << ax << ", " << ay << "), b = (" << bx << ", " << by << "), c = (" << cx << ", " << cy
                         << ")");
            CHECK(orientation(pt<double>(ax, ay), pt<double>(bx, by), pt<double>(cx, cy)) == exact);
        } else {
            ++near;
        }
        CHECK(orientation(pt<exact_rational>(ax, ay), pt<exact_rational>(bx, by), pt<exact_rational>(cx, cy)) == exact);
    }
    // Both regimes were visited.
    CHECK(far > 5000);
    CHECK(near > 1000);
}

TEMPLATE_TEST_CASE("on_segment: closed segment, ends included", "[orientation]", INFLUENCE2D_NUMBER_TYPES) {
    const auto a = pt<TestType>(0, 0), b = pt<TestType>(2, 2);
    CHECK(on_segment(pt<TestType>(1, 1), a, b));
    CHECK(on_segment(a, a, b));
    CHECK(on_segment(b, a, b));
    CHECK_FALSE(on_segment(pt<TestType>(3, 3), a, b));
    CHECK_FALSE(on_segment(pt<TestType>(1, 1.5), a, b));
}

TEST_CASE("orientation_of_doubles: the exact sign on nearly collinear and tiny inputs", "[orientation]") {
    // Points on a line, moved by a few units in the last place, at scales
    // from the subnormal range to 2^500: the filter in double either gives
    // the exact sign (CGAL's exact orientation) or leaves it to the exact
    // sum; both ways the answer is exact. Some calls must be settled by each
    // way for the test to show both.
    test_random::rng g(77);
    const rational_kernel::Orientation_2 exact_orientation;
    std::size_t by_filter = 0, by_sum = 0;
    for (int k = 0; k < 20000; ++k) {
        const int e = -1074 + static_cast<int>(g.index(1600));
        const double scale = std::ldexp(1.0, e);
        const double ax = scale * g.signed_unit(), ay = scale * g.signed_unit();
        const double dx = scale * g.signed_unit(), dy = scale * g.signed_unit();
        const double t = g.uniform(-2, 2);
        double cx = ax + t * dx, cy = ay + t * dy;
        for (int n = static_cast<int>(g.index(4)); n > 0; --n)
            cx = std::nextafter(cx, g.chance(0.5) ? HUGE_VAL : -HUGE_VAL);
        const double bx = ax + dx, by = ay + dy;
        if (!std::isfinite(bx) || !std::isfinite(by) || !std::isfinite(cx) || !std::isfinite(cy)) continue;
        const int got = orientation_of_doubles(ax, ay, bx, by, cx, cy);
        const int want = static_cast<int>(exact_orientation(
            rational_kernel::Point_2(ax, ay), rational_kernel::Point_2(bx, by), rational_kernel::Point_2(cx, cy)));
        REQUIRE(got == want);
        const double left = (bx - ax) * (cy - ay), right = (by - ay) * (cx - ax);
        const double bound = orientation_relative_bound * (std::fabs(left) + std::fabs(right)) + orientation_underflow;
        (std::fabs(left - right) > bound ? by_filter : by_sum) += 1;
    }
    CHECK(by_filter > 1000);
    CHECK(by_sum > 1000);
}

TEST_CASE("orientation_of_doubles: axis-parallel and nearly axis-parallel triples, exactly", "[orientation]") {
    // A grid's corners, each coordinate taken from a few values and their
    // neighbours one or two units in the last place away (as neighbouring
    // cells of a real grid store their shared sides): many triples share an
    // abscissa or an ordinate, so that a product of the determinant has a
    // zero factor, and the sign comes from the other product's differences.
    // At scales from 2^-1000 to 2^1000; CGAL's exact orientation decides.
    test_random::rng g(78);
    const rational_kernel::Orientation_2 exact_orientation;
    std::size_t zero_factor = 0, zeros = 0;
    for (int k = 0; k < 20000; ++k) {
        const double scale = std::ldexp(1.0, static_cast<int>(g.index(2000)) - 1000);
        const auto coordinate = [&] {
            double x = scale * (1 + static_cast<double>(g.index(4)) * 0.7);
            for (int n = static_cast<int>(g.index(3)); n > 0; --n)
                x = std::nextafter(x, g.chance(0.5) ? HUGE_VAL : -HUGE_VAL);
            return g.chance(0.2) ? -x : x;
        };
        const double ax = coordinate(), ay = coordinate(), bx = coordinate(), by = coordinate(), cx = coordinate(),
                     cy = coordinate();
        const int got = orientation_of_doubles(ax, ay, bx, by, cx, cy);
        const int want = static_cast<int>(exact_orientation(
            rational_kernel::Point_2(ax, ay), rational_kernel::Point_2(bx, by), rational_kernel::Point_2(cx, cy)));
        INFO(ax << " " << ay << " " << bx << " " << by << " " << cx << " " << cy);
        REQUIRE(got == want);
        zero_factor += (bx == ax || cy == ay || by == ay || cx == ax) ? 1 : 0;
        zeros += want == 0 ? 1 : 0;
    }
    CHECK(zero_factor > 3000);
    CHECK(zeros > 250);
}
