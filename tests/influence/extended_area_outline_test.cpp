// SPDX-License-Identifier: BSL-1.0
// The outline of an edge's extended area against the membership tests
// (in_band, in_capsule): points just inside the outline are members, points
// just outside are not; and the candidate edges of a point.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/influence/candidate_edges.hpp"
#include "influence2d/influence/extended_area_outline.hpp"
#include "influence2d/predicates/extended_area.hpp"
#include "support/random.hpp"

using namespace influence2d;

namespace {

/// q moved away from (factor > 1) or towards (factor < 1) c.
point<double> scaled_about(const point<double>& c, const point<double>& q, double factor) {
    return {c.x + (q.x - c.x) * factor, c.y + (q.y - c.y) * factor};
}

/// The corners and the midpoints of the sides of a closed outline.
std::vector<point<double>> outline_points(const std::vector<point<double>>& corners) {
    std::vector<point<double>> points = corners;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const point<double>&u = corners[i], &v = corners[(i + 1) % corners.size()];
        points.push_back({u.x / 2 + v.x / 2, u.y / 2 + v.y / 2});
    }
    return points;
}

}  // namespace

TEST_CASE("extended area outline: the band's corners and sides bound in_band's points", "[extended]") {
    test_random::rng rng(11);
    const auto u = [&] { return rng.uniform(-10, 10); };
    // Slopes of every kind, |slope| = 1 (vertical caps by in_band's rule) and the axes included.
    std::vector<std::pair<point<double>, point<double>>> edges = {
        {{0, 0}, {4, 1}}, {{0, 0}, {1, 4}}, {{0, 0}, {3, 3}}, {{2, 1}, {-1, 4}}, {{0, 0}, {5, 0}}, {{1, 1}, {1, -3}}};
    for (int k = 0; k < 200; ++k) edges.push_back({{u(), u()}, {u(), u()}});
    for (const auto& [a, b] : edges) {
        const double n = 0.05 + std::fabs(u()) / 4;
        const extended_area_outline out = outline_of_extended_area(extended_area::band, a, b, n);
        REQUIRE_FALSE(out.disc);
        REQUIRE_FALSE(out.strip);
        REQUIRE(out.corners.size() == 4);
        const bool vertical = band_has_vertical_caps(a, b);
        CHECK(vertical == !(std::fabs(b.y - a.y) > std::fabs(b.x - a.x)));
        // The caps: two sides of the outline on the lines x (or y) = const.
        const auto along = [&](const point<double>& p) { return vertical ? p.x : p.y; };
        CHECK(along(out.corners[0]) == along(out.corners[3]));
        CHECK(along(out.corners[1]) == along(out.corners[2]));
        point<double> c{0, 0};
        for (const auto& q : out.corners) c = {c.x + q.x / 4, c.y + q.y / 4};
        for (const auto& q : outline_points(out.corners)) {
            INFO("edge (" << a.x << ", " << a.y << ") - (" << b.x << ", " << b.y << "), n = " << n << ", point (" << q.x
                          << ", " << q.y << ")");
            CHECK(in_band(scaled_about(c, q, 1 - 1e-6), a, b, n, n * n));
            CHECK_FALSE(in_band(scaled_about(c, q, 1 + 1e-6), a, b, n, n * n));
            CHECK(in_extended_area(extended_area::band, scaled_about(c, q, 1 - 1e-6), a, b, n));
        }
    }
}

TEST_CASE("extended area outline: the capsule's straight part lies n from the edge", "[extended]") {
    test_random::rng rng(12);
    const auto u = [&] { return rng.uniform(-10, 10); };
    for (int k = 0; k < 200; ++k) {
        const point<double> a{u(), u()}, b{u(), u()};
        const double n = 0.05 + std::fabs(u()) / 4;
        const extended_area_outline out = outline_of_extended_area(extended_area::capsule, a, b, n);
        REQUIRE(out.corners.size() == 4);
        const point<double> c{a.x / 2 + b.x / 2, a.y / 2 + b.y / 2};
        // The corners and the middles of the two long sides (the short sides
        // cross the capsule's round ends: their middles are a and b).
        std::vector<point<double>> points = out.corners;
        for (std::size_t i : {0, 2}) {
            const point<double>&from = out.corners[i], &to = out.corners[i + 1];
            points.push_back({from.x / 2 + to.x / 2, from.y / 2 + to.y / 2});
        }
        for (const auto& q : points) {
            CHECK(in_capsule(scaled_about(c, q, 1 - 1e-6), a, b, n * n));
            CHECK_FALSE(in_capsule(scaled_about(c, q, 1 + 1e-6), a, b, n * n));
        }
    }
}

TEST_CASE("extended area outline: a zero-length edge's disc and strip", "[extended]") {
    const point<double> a{2, -1};
    const double n = 0.5;
    const extended_area_outline disc = outline_of_extended_area(extended_area::capsule, a, a, n);
    CHECK(disc.disc);
    CHECK_FALSE(disc.strip);
    CHECK(disc.corners.empty());
    const extended_area_outline strip = outline_of_extended_area(extended_area::band, a, a, n);
    CHECK(strip.strip);
    CHECK_FALSE(strip.disc);
    CHECK(strip.corners.empty());
    // The strip |x - a.x| <= n, unbounded in y, as in_band keeps it.
    for (const double y : {-1e6, -1.0, 0.0, 1e6}) {
        CHECK(in_band(point<double>{a.x + n * (1 - 1e-9), y}, a, a, n, n * n));
        CHECK(in_band(point<double>{a.x - n * (1 - 1e-9), y}, a, a, n, n * n));
        CHECK_FALSE(in_band(point<double>{a.x + n * (1 + 1e-9), y}, a, a, n, n * n));
        CHECK_FALSE(in_band(point<double>{a.x - n * (1 + 1e-9), y}, a, a, n, n * n));
    }
}

TEST_CASE("candidate edges: the edges whose extended area holds the point", "[extended]") {
    const polygon square({ring_input{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
    const triangle_covering<double> cov(square, square.centroid());
    // The stored edge from (x0, y0) to (x1, y1).
    const auto edge = [&](double x0, double y0, double x1, double y1) {
        for (std::size_t i = 0; i < cov.size(); ++i)
            if (cov.start(i) == point<double>{x0, y0} && cov.end(i) == point<double>{x1, y1}) return i;
        FAIL("no such edge");
        return cov.size();
    };
    const std::size_t right = edge(4, 0, 4, 4), bottom = edge(0, 0, 4, 0);
    // (5, 2): 1 from the right edge, sqrt(5) from the bottom one.
    CHECK(edges_whose_extended_area_holds(extended_area::capsule, point<double>{5, 2}, cov, 1.5) ==
          std::vector<std::size_t>{right});
    // (4.5, -0.5): within 0.75 of the right and the bottom edges' corner.
    const std::vector<std::size_t> corner =
        edges_whose_extended_area_holds(extended_area::capsule, point<double>{4.5, -0.5}, cov, 0.75);
    CHECK(corner ==
          (right < bottom ? std::vector<std::size_t>{right, bottom} : std::vector<std::size_t>{bottom, right}));
    // (5.4, 5.4): outside every capsule of length 1.5 (1.98 from the corner), inside two bands' corners.
    CHECK(edges_whose_extended_area_holds(extended_area::capsule, point<double>{5.4, 5.4}, cov, 1.5).empty());
    CHECK(edges_whose_extended_area_holds(extended_area::band, point<double>{5.4, 5.4}, cov, 1.5).size() == 2);
    // Every answer is in_extended_area's, edge by edge.
    test_random::rng rng(13);
    for (int k = 0; k < 500; ++k) {
        const point<double> p{rng.uniform(-3, 7), rng.uniform(-3, 7)};
        for (const extended_area shape : {extended_area::capsule, extended_area::band}) {
            std::vector<std::size_t> expected;
            for (std::size_t i = 0; i < cov.size(); ++i)
                if (in_extended_area(shape, p, cov.start(i), cov.end(i), 1.0)) expected.push_back(i);
            CHECK(edges_whose_extended_area_holds(shape, p, cov, 1.0) == expected);
        }
    }
}
