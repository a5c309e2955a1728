// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <set>

#include "influence2d/influence/influence_areas.hpp"
#include "support/random.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

namespace {

template <class NT>
std::set<std::size_t> by_index(const influence_areas<NT>& areas, const point<NT>& p) {
    std::set<std::size_t> s;
    areas.for_each_containing(p, [&](std::size_t i) { s.insert(i); });
    return s;
}

template <class NT>
std::set<std::size_t> by_scan(const triangle_covering<NT>& cov, const point<NT>& p) {
    std::set<std::size_t> s;
    for (std::size_t i = 0; i < cov.size(); ++i)
        if (in_influence_area(cov, i, p)) s.insert(i);
    return s;
}

}  // namespace

TEMPLATE_TEST_CASE("influence areas: the square's four cones tile the plane", "[influence]", INFLUENCE2D_NUMBER_TYPES) {
    using NT = TestType;
    const polygon sq = test_shapes::square(0, 0, 4);
    const triangle_covering<NT> cov(sq, sq.centroid());
    const influence_areas<NT> areas(cov);
    auto P = [](double x, double y) { return point<NT>{NT(x), NT(y)}; };
    CHECK(by_index(areas, P(2, -10)) == std::set<std::size_t>{0});  // below: edge 0's cone
    CHECK(by_index(areas, P(10, 2)) == std::set<std::size_t>{1});
    CHECK(by_index(areas, P(7, 7)) == std::set<std::size_t>{1, 2});        // on the shared side
    CHECK(by_index(areas, P(2, 2)) == std::set<std::size_t>{0, 1, 2, 3});  // the origin
}

TEMPLATE_TEST_CASE("influence areas: the bucket lookup equals a scan of all cones", "[influence]", double,
                   influence2d::exact_rational) {
    using NT = TestType;
    // A C shape (overlapping cones) and a square with a hole.
    for (const polygon& p : {test_shapes::c_shape(), test_shapes::square_with_hole()}) {
        const triangle_covering<NT> cov(p, p.centroid());
        const influence_areas<NT> areas(cov);
        test_random::rng rng(7);
        for (int k = 0; k < 2000; ++k) {
            const double x = static_cast<double>(rng.index(4001)) / 200 - 6;
            const double y = static_cast<double>(rng.index(4001)) / 200 - 6;
            const point<NT> q{NT(x), NT(y)};
            INFO("point " << x << ", " << y);
            CHECK(by_index(areas, q) == by_scan(cov, q));
        }
        // Points on the lines from the origin through every vertex.
        for (std::size_t i = 0; i < p.size(); ++i) {
            const auto& v = p.vertex(i);
            const auto& o = p.centroid();
            const point<NT> q{NT(o.x + 2 * (v.x - o.x)), NT(o.y + 2 * (v.y - o.y))};
            CHECK(by_index(areas, q) == by_scan(cov, q));
        }
    }
}

TEST_CASE("influence areas: an edge collinear with the origin has an empty cone", "[influence]") {
    const polygon p({test_shapes::ring({{0, 0}, {4, 0}, {4, 4}, {2, 2}, {0, 4}})});
    const triangle_covering<double> cov(p, point<double>{1, 1});
    CHECK_FALSE(in_influence_area(cov, 2, point<double>{3, 3}));
    CHECK_FALSE(in_influence_area(cov, 2, point<double>{9, 9}));
}

TEST_CASE("influence mask: detects leaving an area", "[influence]") {
    influence_mask before(130), after(130);
    before.set(3);
    before.set(129);
    after.set(3);
    after.set(129);
    after.set(64);
    CHECK_FALSE(after.left_some_area_of(before));  // entering area 64 is not leaving
    influence_mask later(130);
    later.set(64);
    later.set(129);
    CHECK(later.left_some_area_of(after));  // left area 3
    CHECK(later.test(64));
    CHECK_FALSE(later.test(3));
}
