// SPDX-License-Identifier: BSL-1.0
// The disc about a polygon's box centre that lies in its closed region
// (scene/inner_disc.hpp), against CGAL's exact rationals: the centre in the
// region, every edge of every ring at least the radius from it (exact
// squared distances), and the radius no smaller than the exact least
// distance by more than 2^-39 of the scale; none where the centre is outside,
// on the boundary, or in a hole.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/exact_regions.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

#include <array>
#include <cmath>

#include "influence2d/influence/bounds.hpp"
#include "influence2d/scene/inner_disc.hpp"

namespace {

using namespace influence2d;
using test_scenes::rng;
using Q = exact_rational;

/// The exact least squared distance from m to an edge of p (placed as it
/// stands).
Q least_distance2(const test_exact::placed_shape& p, const test_exact::point_2& m) {
    Q least = -1;
    for (std::size_t i = 0; i < p.v.size(); ++i) {
        const Q d2 = p.v[i] == p.end(i) ? CGAL::squared_distance(m, p.v[i])
                                        : CGAL::squared_distance(m, test_exact::segment_2(p.v[i], p.end(i)));
        if (least < 0 || d2 < least) least = d2;
    }
    return least;
}

/// Checks inner_radius(p) against the exact region; returns it.
double check_inner(const polygon& p) {
    const double r = inner_radius(p);
    const test_exact::placed_shape exact = test_exact::place(p, pose{});
    const point<double> c = p.bounds().centre();
    const test_exact::point_2 m(Q(c.x), Q(c.y));
    const Q least = least_distance2(exact, m);
    const bool inside = test_exact::in_region(exact, m) && least > 0;
    // (2^-39 of the scale: far above point_segment_estimate's proven
    // errors, 2^-47 of sums of differences at most eight times the scale.)
    const Q slack = Q(0x1p-39) * Q(coordinate_scale(p));
    INFO(p.size() << " vertices, radius " << r);
    CHECK(r >= 0);
    if (r > 0) {
        CHECK(inside);
        CHECK(Q(r) * Q(r) <= least);  // every edge at least r away: the disc lies in the region
    }
    // Not loose: an interior centre farther than the slack from every edge
    // gets a radius within the slack of that distance.
    if (inside && least > slack * slack) CHECK((Q(r) + slack) * (Q(r) + slack) >= least);
    return r;
}

}  // namespace

TEST_CASE("inner_radius: a disc in the region, against exact distances", "[scene]") {
    rng g(2500);
    std::size_t with_disc = 0;
    const int rounds = test_effort::scaled(200);
    for (int round = 0; round < rounds; ++round) {
        const int k = std::array<int, 5>{0, -600, -40, 7, 500}[static_cast<std::size_t>(round % 5)];
        // Multipolygons (their box centre often between parts or in a
        // hole), swallowers, and stars about a random point (their centre
        // mostly inside, sometimes in a spike's notch).
        polygon base = test_scenes::random_swallower(g).to_polygon();
        if (round % 4 < 2) {
            base = test_scenes::random_multi(g, 10 + round % 30, 2 + round % 4).to_polygon();
        } else if (round % 4 == 2) {
            const std::size_t n = 3 + g.index(30);
            const point<double> c{g.uniform(-5, 5), g.uniform(-5, 5)};
            std::vector<point<double>> v = test_shapes::ellipse_points(g, 2 * n, c, g.uniform(1, 4), g.uniform(1, 4));
            const double dent = g.uniform(0.2, 1);
            for (std::size_t i = 1; i < v.size(); i += 2)
                v[i] = {c.x + dent * (v[i].x - c.x), c.y + dent * (v[i].y - c.y)};
            base = polygon({test_shapes::ring(v)});
        }
        INFO("round " << round << " at 2^" << k);
        with_disc += check_inner(base.scaled_by_power_of_two(k)) > 0 ? 1 : 0;
    }
    CHECK(with_disc * 4 > static_cast<std::size_t>(rounds));  // the route is taken often
}

TEST_CASE("inner_radius: the regular octagon's inradius, none about a hole or outside a C", "[scene]") {
    ring_input octagon;
    for (int k = 0; k < 8; ++k) {
        const double a = M_PI * k / 4 + 0.1;
        octagon.vertices.push_back({std::cos(a), std::sin(a)});
    }
    const polygon p({octagon});
    // The box centre is not quite the octagon's; the disc still reaches
    // nearly to the nearest edge.
    const double r = check_inner(p);
    CHECK(r > 0.85);
    CHECK(r < std::cos(M_PI / 8));
    CHECK(check_inner(test_shapes::square_with_hole()) == 0);  // the centre is in the hole
    CHECK(check_inner(test_shapes::c_shape()) == 0);           // the centre is outside the C
    // A centre on an edge: two outer rings [0, 1] x [0, 2] and [1, 2] x
    // [0, 2] sharing the segment x = 1, the box centre (1, 1) on it.
    const polygon halves(
        {test_shapes::ring({{0, 0}, {1, 0}, {1, 2}, {0, 2}}), test_shapes::ring({{1, 0}, {2, 0}, {2, 2}, {1, 2}})});
    CHECK(check_inner(halves) == 0);
    CHECK(check_inner(test_shapes::square(-3, -3, 6)) == Approx(3).epsilon(1e-9));
}
