// SPDX-License-Identifier: BSL-1.0
// The disc that holds a polygon and the box of that disc posed
// (scene/bounding_disc.hpp), against exact rationals: every vertex within
// the radius, every vertex posed exactly inside the box once widened by
// the posing's margin, and the box no wider than the exact disc's.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "influence2d/influence/bounds.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/scene/bounding_disc.hpp"

namespace {

using namespace influence2d;
using test_scenes::rng;
using Q = exact_rational;

Q sq(const Q& x) { return x * x; }

}  // namespace

TEST_CASE("bounding_disc: every vertex within the radius, every posed vertex in the box", "[scene]") {
    rng g(2400);
    std::size_t vertices = 0, tight = 0;
    const int rounds = test_effort::scaled(200);
    for (int round = 0; round < rounds; ++round) {
        // Scales from subnormal-adjacent to near double's top, poses turned
        // anywhere, translations from none to far beyond the polygon.
        const int k = std::array<int, 6>{0, -1000, -520, 3, 300, 950}[static_cast<std::size_t>(round % 6)];
        const polygon base = round % 5 == 4 ? test_scenes::random_swallower(g).to_polygon()
                                            : test_scenes::random_multi(g, 1 + round % 40, 2 + round % 7).to_polygon();
        const polygon p = base.scaled_by_power_of_two(k);
        const disc d = bounding_disc(p);
        INFO("round " << round << ": " << p.size() << " vertices at 2^" << k);
        REQUIRE(std::isfinite(d.radius));
        const Q cx(d.centre.x), cy(d.centre.y), r2 = sq(Q(d.radius));
        Q farthest = 0;
        for (const point<double>& v : p.vertices()) {
            const Q dist2 = sq(Q(v.x) - cx) + sq(Q(v.y) - cy);
            CHECK(dist2 <= r2);
            if (dist2 > farthest) farthest = dist2;
        }
        // Widened by at most 2^-40 over the farthest vertex: not a loose bound.
        CHECK(r2 <= farthest * sq(Q(1 + 0x1p-40)));

        const double reach = std::ldexp(1.0, k) * std::array<double, 3>{0, 1, 1e6}[static_cast<std::size_t>(round % 3)];
        const pose q{g.uniform(-reach, reach), g.uniform(-reach, reach), g.uniform(-40, 40)};
        const rotation_pose rp(q);
        const box b = disc_box(posed_disc(d, rp));
        REQUIRE(!b.empty());
        const double margin = placing_margin<double>(coordinate_scale(p) + std::fabs(q.tx) + std::fabs(q.ty));
        const Q lo_x = Q(b.min_x) - Q(margin), hi_x = Q(b.max_x) + Q(margin), lo_y = Q(b.min_y) - Q(margin),
                hi_y = Q(b.max_y) + Q(margin);
        for (const point<double>& v : p.vertices()) {
            const Q x = Q(rp.c) * Q(v.x) - Q(rp.s) * Q(v.y) + Q(rp.tx),
                    y = Q(rp.s) * Q(v.x) + Q(rp.c) * Q(v.y) + Q(rp.ty);
            CHECK(lo_x <= x);
            CHECK(x <= hi_x);
            CHECK(lo_y <= y);
            CHECK(y <= hi_y);
            ++vertices;
        }
        // The box's side is the disc's diameter, to within 2^-40 and the
        // roundings of its ends (a few ulps of the translation).
        // (The distance taken at scale 1: its square would underflow.)
        const double unscale = std::ldexp(1.0, -k);
        const double side = std::ldexp(std::sqrt(CGAL::to_double(farthest * sq(Q(unscale)))), k) * 2 * (1 + 0x1p-40) +
                            0x1p-50 * (std::fabs(q.tx) + std::fabs(q.ty) + coordinate_scale(p));
        if (b.max_x - b.min_x <= side && b.max_y - b.min_y <= side) ++tight;
    }
    CHECK(rounds > 0);
    CHECK(vertices > 10 * static_cast<std::size_t>(rounds));  // not vacuous
    CHECK(tight == static_cast<std::size_t>(rounds));
}

TEST_CASE("bounding_disc: a radius or centre that is not finite gives no box", "[scene]") {
    const double big = std::numeric_limits<double>::max();
    // Corners at both ends of double's range: the differences overflow.
    const polygon wide({test_shapes::ring({{-big, -big}, {big, -big}, {big, big}, {-big, big}})});
    const disc d = bounding_disc(wide);
    CHECK(std::isinf(d.radius));
    CHECK(disc_box(posed_disc(d, rotation_pose(pose{0, 0, 0.5}))).empty());
    // A finite disc posed past double's range.
    const polygon unit({test_shapes::square_ring(0, 0, 1)});
    CHECK(disc_box(posed_disc(bounding_disc(unit), rotation_pose(pose{big, 0, 0}))).empty() == false);
    CHECK(disc_box(posed_disc(bounding_disc(unit), rotation_pose(pose{big, big, 0.3}))).empty() == false);
    const disc far{{big, 0}, 1e300};
    CHECK(disc_box(posed_disc(far, rotation_pose(pose{big, 0, 0}))).empty());
}
