// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include "influence2d/adapters/traits.hpp"

#include "influence2d/core/polygon.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/random.hpp"
#include "support/shapes.hpp"

using namespace influence2d;
using test_shapes::ring;

TEST_CASE("polygon: outer rings are stored counter-clockwise, holes clockwise", "[polygon]") {
    // Outer given clockwise, hole given counter-clockwise: both are reversed.
    polygon p({ring({{0, 0}, {0, 4}, {4, 4}, {4, 0}}), ring({{1, 1}, {2, 1}, {2, 2}, {1, 2}}, ring_role::hole)});
    REQUIRE(p.ring_count() == 2);
    CHECK(p.area() == Approx(15.0));
    CHECK(p.vertex(0) == point<double>{4, 0});  // reversed: input vertex 3 first
    CHECK(p.vertex(1) == point<double>{4, 4});
    // Stored edge 0 runs (4,0)->(4,4): input edge 2 ((4,4)->(4,0)).
    CHECK(p.source_edge(0) == 2);
    CHECK(p.source_edge(3) == 3);  // (0,0)->(4,0) is input edge 3 ((4,0)->(0,0))
    CHECK(p.next(3) == 0);
    CHECK(p.ring_begin(1) == 4);
    CHECK(p.vertex(4) == point<double>{1, 2});
    CHECK(p.source_edge(4) == 4 + 2);
}

TEST_CASE("polygon: previous undoes next on every ring", "[polygon]") {
    // Three rings of 3, 5 and 4 vertices, the middle one a hole.
    polygon p({ring({{0, 0}, {9, 0}, {0, 9}}), ring({{1, 1}, {2, 1}, {3, 2}, {2, 3}, {1, 2}}, ring_role::hole),
               ring({{20, 0}, {24, 0}, {24, 4}, {20, 4}})});
    REQUIRE(p.size() == 12);
    for (std::size_t i = 0; i < p.size(); ++i) {
        INFO("vertex " << i);
        CHECK(p.previous(p.next(i)) == i);
        CHECK(p.next(p.previous(i)) == i);
    }
    CHECK(p.previous(0) == 2);
    CHECK(p.previous(3) == 7);
    CHECK(p.previous(8) == 11);
    CHECK(p.previous(9) == 8);
}

TEST_CASE("polygon: ring orientation is decided exactly for a sliver", "[polygon]") {
    // Three nearly collinear vertices far from the origin: the shoelace sum in
    // double is 0 here, the exact one is negative (clockwise), so the ring is
    // reversed and its last vertex comes first.
    //   a (1e8+0.5, 1e8) --- b (1e8+3750.5, 1e8+1250) --- c (1e8+7500.5+2^-26, 1e8+2500)
    const point<double> a{100000000.5, 100000000.0}, b{100003750.5, 100001250.0}, c{100007500.5 + 0x1p-26, 100002500.0};
    polygon p({ring({a, b, c})});
    CHECK(p.vertex(0) == c);
    polygon q({ring({c, b, a})});
    CHECK(q.vertex(0) == c);  // already counter-clockwise: kept
}

TEST_CASE("polygon: rejects what it cannot interpret", "[polygon]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(polygon({ring({{0, 0}, {1, nan}, {1, 1}})}), Catch::Contains("ring 0, vertex 1"));
    CHECK_THROWS_WITH(polygon({ring({{0, 0}, {1, 0}, {0, 0}, {1, 0}})}), Catch::Contains("fewer than three distinct"));
    CHECK_THROWS_AS(polygon(std::vector<ring_input>{}), invalid_input);
}

TEST_CASE("polygon: centroid is the area centroid, the vertex mean without area", "[polygon]") {
    polygon l({ring({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})});
    CHECK(l.centroid().x == Approx(5.0 / 6));
    CHECK(l.centroid().y == Approx(5.0 / 6));
    polygon flat({ring({{0, 0}, {1, 0}, {3, 0}})});
    CHECK(flat.centroid().x == Approx(4.0 / 3));
    CHECK(flat.centroid().y == 0);
}

TEST_CASE("polygon: repeated vertices stay as zero-length edges", "[polygon]") {
    polygon p({ring({{0, 0}, {1, 0}, {1, 0}, {1, 1}})});
    CHECK(p.size() == 4);
    CHECK(p.vertex(1) == p.vertex(2));
}

TEST_CASE("polygon: a closing copy of the first vertex is dropped, as make_polygon drops it", "[polygon]") {
    // The same ring closed and open numbers its edges the same way, here and
    // through the adapters.
    const polygon closed({ring({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}})});
    const polygon open({ring({{0, 0}, {1, 0}, {1, 1}, {0, 1}})});
    CHECK(closed.size() == 4);
    CHECK(closed.vertices() == open.vertices());
    const std::vector<point<double>> pts{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    const polygon adapted = influence2d::make_polygon(pts);
    CHECK(adapted.vertices() == closed.vertices());
    for (std::size_t i = 0; i < closed.size(); ++i) CHECK(adapted.source_edge(i) == closed.source_edge(i));
    // A repeat elsewhere stays.
    CHECK(polygon({ring({{0, 0}, {0, 0}, {1, 0}, {1, 1}, {0, 0}})}).size() == 4);
}

TEST_CASE("polygon: ring orientation is exact at 1e200 and at subnormal scale", "[polygon]") {
    // Products of such coordinates leave double's range; the shoelace sign must
    // not. Each ring is given clockwise and must be stored counter-clockwise.
    for (const double s : {1e200, 1e-170, 0x1p-1070}) {
        INFO("scale " << s);
        polygon p({ring({{0, 0}, {0, s}, {s, s}, {s, 0}})});
        CHECK(p.vertex(0) == point<double>{s, 0});  // reversed
        polygon h({ring({{0, 0}, {4 * s, 0}, {4 * s, 4 * s}, {0, 4 * s}}),
                   ring({{s, s}, {2 * s, s}, {2 * s, 2 * s}, {s, 2 * s}}, ring_role::hole)});
        CHECK(h.vertex(4) == point<double>{s, 2 * s});  // the hole reversed to clockwise
    }
}

namespace {

/// The sign of a ring's shoelace sum in CGAL's exact rationals: a reference
/// that shares nothing with the polygon's filter or its fixed-point sum.
int rational_area_sign(const std::vector<point<double>>& vs) {
    exact_rational sum = 0;
    for (std::size_t k = 0; k < vs.size(); ++k) {
        const point<double>& a = vs[k];
        const point<double>& b = vs[(k + 1) % vs.size()];
        sum += exact_rational(a.x) * exact_rational(b.y) - exact_rational(a.y) * exact_rational(b.x);
    }
    return CGAL::sign(sum);
}

/// A ring whose vertices lie on one line but for a few moved by an ulp or
/// two: its area is a few rounding errors of its coordinates, or zero.
std::vector<point<double>> nearly_flat_ring(test_random::rng& r, double scale, double offset) {
    const std::size_t n = 3 + r.index(10);
    const double dx = r.signed_unit(), dy = r.signed_unit();
    std::vector<point<double>> vs;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = r.signed_unit();
        point<double> q{offset + scale * t * dx, offset + scale * t * dy};
        if (r.chance(0.3)) q.x = std::nextafter(q.x, r.chance(0.5) ? HUGE_VAL : -HUGE_VAL);
        if (r.chance(0.3)) q.y = std::nextafter(q.y, r.chance(0.5) ? HUGE_VAL : -HUGE_VAL);
        vs.push_back(q);
    }
    return vs;
}

}  // namespace

TEST_CASE("polygon: the filtered ring orientation is the exact one on nearly flat rings", "[polygon]") {
    // The double shoelace sum decides only beyond its error bound; near zero
    // area the fixed-point sum decides. Either way the sign must be the exact
    // rational sum's, at every scale and far from the origin.
    test_random::rng r(20261126);
    std::size_t zero = 0, positive = 0, negative = 0;
    for (const double scale : {1.0, 1e-3, 1e6, 1e200, 1e-300, 0x1p-1060})
        for (const double offset : {0.0, 1.0, 1e6, 1e15}) {
            const double at = offset * (scale > 1e100 ? 1e200 : 1.0);
            for (int k = 0; k < 300; ++k) {
                const std::vector<point<double>> vs = nearly_flat_ring(r, scale, at);
                const int want = rational_area_sign(vs);
                INFO("scale " << scale << ", offset " << at << ", ring " << k);
                REQUIRE(polygon::signed_area_sign(vs) == want);
                REQUIRE(polygon::exact_signed_area_sign(vs) == want);
                (want == 0 ? zero : want > 0 ? positive : negative) += 1;
            }
        }
    // The rings hold every answer, so a filter that decided too early would be seen.
    CHECK(zero > 100);
    CHECK(positive > 1000);
    CHECK(negative > 1000);
}
