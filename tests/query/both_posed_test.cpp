// SPDX-License-Identifier: BSL-1.0
// Both polygons placed in one frame (query/both_posed.hpp): the two-pose
// intersects against the one-pose reference (verification/cgal_reference)
// when the relative pose is exact, and against an independent exact
// placing of both polygons (support/exact_regions.hpp) for any poses;
// regions_meet on vertices given in NT; relative_pose.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/exact_regions.hpp"
#include "support/families.hpp"
#include "support/random_scenes.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/exact/certified_both_posed.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/query/both_posed.hpp"
#include "verification/cgal_reference.hpp"

namespace {

using namespace influence2d;

std::string describe_both_posed(const pose& pa, const pose& pb) {
    std::ostringstream s;
    s.precision(17);
    s << "A posed " << pa.tx << ',' << pa.ty << ',' << pa.theta << ", B posed " << pb.tx << ',' << pb.ty << ','
      << pb.theta;
    return s.str();
}

/// A random pose near `at` (within `spread`), turned at random or not.
pose random_both_pose(test_scenes::rng& g, point<double> at, double spread, bool turn) {
    return test_scenes::aimed({0, 0}, {at.x + g.uniform(-spread, spread), at.y + g.uniform(-spread, spread)},
                              turn ? g.uniform(-3.2, 3.2) : 0);
}

/// The polygon's vertices placed by p, exactly, as exact_rational points.
std::vector<point<exact_rational>> placed_exactly(const polygon& shape, const pose& p) {
    const exact_rational c(std::cos(p.theta)), s(std::sin(p.theta));
    std::vector<point<exact_rational>> out;
    for (const point<double>& v : shape.vertices()) {
        const exact_rational x(v.x), y(v.y);
        out.push_back({c * x - s * y + exact_rational(p.tx), s * x + c * y + exact_rational(p.ty)});
    }
    return out;
}

}  // namespace

TEST_CASE("both moving: pure translations equal the relative one-pose scene", "[posed_meet][reference]") {
    // With both poses translations on the grid, B's pose in A's frame is
    // the exact difference, and the one-pose reference answers the scene.
    const int scenes = test_effort::scaled(40);
    std::size_t meet = 0, frames = 0;
    for (int k = 0; k < scenes; ++k) {
        test_scenes::rng g(0xb07ULL + static_cast<std::uint64_t>(k));
        const test_scenes::multi ma = test_scenes::random_multi(g, 20, 8), mb = test_scenes::random_swallower(g);
        const polygon a = ma.to_polygon(), b = mb.to_polygon();
        const verification::cgal_reference reference(a, b);
        for (int f = 0; f < 10; ++f) {
            const pose pa = random_both_pose(g, {0, 0}, 30, false), pb = random_both_pose(g, {pa.tx, pa.ty}, 40, false);
            const pose relative{pb.tx - pa.tx, pb.ty - pa.ty, 0};
            INFO(describe_both_posed(pa, pb));
            const bool expected = reference.collide(relative).collides;
            CHECK(intersects<exact_rational>(a, pa, b, pb) == expected);
            CHECK(certified_intersects(a, pa, b, pb) == expected);
            CHECK(intersects<exact_rational>(a, b, relative_pose(pa, pb)) == expected);
            (void)intersects<double>(a, pa, b, pb);
            ++frames;
            meet += expected;
        }
    }
    CHECK(meet > frames / 5);
    CHECK(meet < frames);
}

TEST_CASE("both moving: random poses against both polygons placed exactly", "[posed_meet][reference]") {
    using test_families::family;
    const int poses = test_effort::scaled(48);
    std::size_t meet = 0, frames = 0, double_agrees = 0;
    test_scenes::rng g(0x2b0ULL);
    const auto check = [&](const polygon& a, const polygon& b, const pose& pa, const pose& pb) {
        INFO(describe_both_posed(pa, pb));
        const bool expected = test_exact::regions_meet(test_exact::place(a, pa), test_exact::place(b, pb));
        CHECK(intersects<exact_rational>(a, pa, b, pb) == expected);
        CHECK(certified_intersects(a, pa, b, pb) == expected);
        // Given in exact rationals, placed by the test.
        CHECK(regions_meet(a, placed_exactly(a, pa), b, placed_exactly(b, pb)) == expected);
        double_agrees += intersects<double>(a, pa, b, pb) == expected;
        ++frames;
        meet += expected;
    };
    for (family f : verification::all_families)
        for (std::size_t n : {8u, 64u, 256u}) {
            const polygon& a = test_families::load(f, n);
            const polygon& b = test_families::load(f, 8);
            const double reach = 50 + 50;  // every family vertex lies within 50 of the origin
            for (int k = 0; k < poses; ++k) {
                const pose pa = random_both_pose(g, {g.uniform(-100, 100), g.uniform(-100, 100)}, 0, true);
                const double phi = g.uniform(0, 6.283185307179586), rho = reach * g.uniform(0.3, 1.1);
                check(a, b, pa,
                      random_both_pose(g, {pa.tx + rho * std::cos(phi), pa.ty + rho * std::sin(phi)}, 0, true));
            }
        }
    for (int k = 0; k < test_effort::scaled(30); ++k) {
        const test_scenes::multi ma = test_scenes::random_multi(g, 20, 8), mb = test_scenes::random_swallower(g);
        const polygon a = ma.to_polygon(), b = mb.to_polygon();
        for (int f = 0; f < 6; ++f) {
            const pose pa = random_both_pose(g, {0, 0}, 50, true);
            check(a, b, pa, random_both_pose(g, {pa.tx, pa.ty}, 30, true));
            check(b, a, pa, random_both_pose(g, {pa.tx, pa.ty}, 30, true));
        }
    }
    CHECK(meet > frames / 5);
    CHECK(meet < frames);
    // Double rounds only near contact: random poses almost never are.
    CHECK(double_agrees + frames / 50 >= frames);
}

TEST_CASE("regions_meet: vertices given in double and in exact rationals", "[posed_meet]") {
    const polygon a({ring_input{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
    const polygon holed({ring_input{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, ring_role::outer},
                         ring_input{{{2, 2}, {8, 2}, {8, 8}, {2, 8}}, ring_role::hole}});
    const auto moved = [](const polygon& p, double dx, double dy) {
        std::vector<point<double>> v;
        for (const point<double>& x : p.vertices()) v.push_back({x.x + dx, x.y + dy});
        return v;
    };
    CHECK(regions_meet(a, a.vertices(), a, moved(a, 4, 4)));                // corner to corner
    CHECK_FALSE(regions_meet(a, a.vertices(), a, moved(a, 4.5, 0)));        // apart
    CHECK(regions_meet(holed, holed.vertices(), a, moved(a, 1, 1)));        // overlapping
    CHECK_FALSE(regions_meet(holed, holed.vertices(), a, moved(a, 3, 3)));  // in the hole
    CHECK(regions_meet(a, moved(a, 7, 7), holed, holed.vertices()));        // across the hole's corner
    // Scaled by 3 in exact rationals (1/3 is no double): scaling changes no answer.
    const auto thirds = [](const std::vector<point<double>>& v) {
        std::vector<point<exact_rational>> out;
        for (const point<double>& x : v) out.push_back({exact_rational(x.x) / 3, exact_rational(x.y) / 3});
        return out;
    };
    CHECK(regions_meet(a, thirds(a.vertices()), a, thirds(moved(a, 4, 0))));
    CHECK_FALSE(regions_meet(a, thirds(a.vertices()), a, thirds(moved(a, 4, 0.25 + 4))));
    CHECK_FALSE(regions_meet(holed, thirds(holed.vertices()), a, thirds(moved(a, 3, 3))));
    CHECK_THROWS_AS(regions_meet(a, a.vertices(), a, std::vector<point<double>>(3)), invalid_input);
}

TEST_CASE("relative_pose: B's pose in A's frame, rounded", "[posed_meet]") {
    const pose r = relative_pose({1, 2, 1.5707963267948966}, {1, 5, 2});
    CHECK(r.tx == Approx(3).margin(1e-15));
    CHECK(r.ty == Approx(0).margin(1e-15));
    CHECK(r.theta == Approx(2 - 1.5707963267948966));
    const pose same = relative_pose({3, 4, 0}, {5, 7, 0.5});
    CHECK(same.tx == 2);
    CHECK(same.ty == 3);
    CHECK(same.theta == 0.5);
    const polygon a({ring_input{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
    CHECK_THROWS_AS(relative_pose({std::nan(""), 0, 0}, {}), invalid_input);
    CHECK_THROWS_AS(intersects<double>(a, pose{0, 0, HUGE_VAL}, a, pose{}), invalid_input);
    CHECK_THROWS_AS(certified_intersects(a, pose{}, polygon{}, pose{}), invalid_input);
    // Both turned by the same angle about different places: the relative
    // scene in double agrees with the exact two-pose answer away from contact.
    CHECK(intersects<exact_rational>(a, {10, 10, 0.7}, a, {12, 12, 0.7}));
    CHECK(intersects<double>(a, a, relative_pose({10, 10, 0.7}, {12, 12, 0.7})));
    CHECK_FALSE(intersects<exact_rational>(a, {10, 10, 0.7}, a, {20, 10, 0.7}));
    CHECK_FALSE(intersects<double>(a, a, relative_pose({10, 10, 0.7}, {20, 10, 0.7})));
}
