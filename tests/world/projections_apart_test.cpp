// SPDX-License-Identifier: BSL-1.0
// projections_apart: a direction along which every vertex of one polygon
// lies beyond every vertex of the other, certified in double
// (projections_certainly_apart), against CGAL's exact regions.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "influence2d/predicates/filters.hpp"
#include "influence2d/world/projections_apart.hpp"
#include "support/effort.hpp"
#include "support/exact_regions.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

using namespace influence2d;
using test_scenes::rng;

TEST_CASE("projections apart: the filter's bound, from the subnormals to the largest coordinates",
          "[world][projections_apart]") {
    // Apart by a unit at the coordinates of one unit: certain.
    CHECK(projections_certainly_apart(1, 0, 1, 0, 1));
    CHECK_FALSE(projections_certainly_apart(0, 1, 1, 0, 1));
    CHECK_FALSE(projections_certainly_apart(1, 1, 1, 0, 1));
    // A unit apart among coordinates of 2^52: each projection may have
    // rounded by a unit in the last place, so undecided; so are eight units
    // (the bound is 2^-50 of (|vx| + |vy|) times the reach, 8 here); sixteen
    // are certain.
    const double big = 0x1p52;
    CHECK_FALSE(projections_certainly_apart(big + 1, big, 1, 0, 2 * big));
    CHECK_FALSE(projections_certainly_apart(big + 2, big, 0.6, 0.8, 2 * big));
    CHECK_FALSE(projections_certainly_apart(big + 8, big, 1, 0, 2 * big));
    CHECK(projections_certainly_apart(big + 16, big, 1, 0, 2 * big));
    // Far below double's normal range: the floor decides.
    CHECK_FALSE(projections_certainly_apart(0x1p-1070, 0, 1, 0, 0x1p-1070));
    CHECK(projections_certainly_apart(0x1p-1050, 0, 1, 0, 0x1p-1050));
    // Not finite: never certain.
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(projections_certainly_apart(inf, 0, 1, 0, 1));
    CHECK_FALSE(projections_certainly_apart(0, -inf, 1, 0, 1));
    CHECK_FALSE(projections_certainly_apart(nan, 0, 1, 0, 1));
    CHECK_FALSE(projections_certainly_apart(1, 0, nan, 0, 1));
}

TEST_CASE("projections apart: random polygons apart, touching and overlapping, against the exact regions",
          "[world][projections_apart]") {
    // Random multipolygons (holes, islands, parts of mixed sizes) and messy
    // rings (self-crossing, repeated vertices), B moved by a random grid
    // offset, or so that one of its vertices lies on the midpoint of an edge
    // of A (touching there, or overlapping past it), or a grid step past
    // that; all of it scaled by a power of two (exact) from 2^-500 to 2^500
    // and shifted far from the origin, where the projections round. A pair
    // said apart must have regions that do not meet; either order.
    rng g(61206);
    std::size_t said_apart = 0, meeting = 0, touching_by_construction = 0;
    const int rounds = test_effort::scaled(1500);
    for (int round = 0; round < rounds; ++round) {
        const polygon a0 = g.chance(0.5) ? test_scenes::random_multi(g, 6, 4).to_polygon()
                                         : polygon(test_scenes::random_messy(g, 5, 3));
        const polygon b0 = g.chance(0.5) ? test_scenes::random_multi(g, 6, 4).to_polygon()
                                         : polygon(test_scenes::random_messy(g, 5, 3));
        double dx = test_scenes::snap(g.uniform(-16, 16)), dy = test_scenes::snap(g.uniform(-16, 16));
        if (g.chance(0.5)) {
            // B's vertex j onto the midpoint of A's edge i (exact on the grid's half).
            const std::size_t i = g.index(a0.size()), j = g.index(b0.size());
            const point<double> p = a0.vertex(i), q = a0.vertex(a0.next(i)), v = b0.vertex(j);
            dx = (p.x + q.x) / 2 - v.x;
            dy = (p.y + q.y) / 2 - v.y;
            if (g.chance(0.3))
                (g.chance(0.5) ? dx : dy) += test_scenes::grid * (g.chance(0.5) ? 1 : -1);
            else
                ++touching_by_construction;
        }
        const int k = std::vector<int>{-500, -20, 0, 0, 30, 500}[g.index(6)];
        const double shift = g.chance(0.5) ? std::ldexp(1.0, 36) : 0.0;
        const auto moved = [&](const polygon& p, double mx, double my) {
            std::vector<ring_input> rings;
            for (std::size_t r = 0; r < p.ring_count(); ++r) {
                ring_input ring{{}, p.role(r)};
                for (std::size_t v = p.ring_begin(r); v < p.ring_end(r); ++v)
                    ring.vertices.push_back(
                        {std::ldexp(p.vertex(v).x + mx + shift, k), std::ldexp(p.vertex(v).y + my - shift, k)});
                rings.push_back(ring);
            }
            return polygon(rings);
        };
        const polygon a = moved(a0, 0, 0), b = moved(b0, dx, dy);
        const bool apart_ab = projections_apart(a, b), apart_ba = projections_apart(b, a);
        const bool meet = test_exact::regions_meet(test_exact::place(a, 0, 0, 0), test_exact::place(b, 0, 0, 0));
        INFO("round " << round << ", scale 2^" << k << ", shift " << shift);
        if (meet) CHECK_FALSE((apart_ab || apart_ba));
        said_apart += apart_ab ? 1 : 0;
        meeting += meet ? 1 : 0;
    }
    // Not vacuous: many pairs said apart, many that meet, many built to
    // touch.
    CHECK(said_apart > static_cast<std::size_t>(rounds) / 10);
    CHECK(meeting > static_cast<std::size_t>(rounds) / 5);
    CHECK(touching_by_construction > static_cast<std::size_t>(rounds) / 5);
}

TEST_CASE("projections apart: triangles touching at the midpoint of an edge, where the projections round",
          "[world][projections_apart]") {
    // Near 1e15, where a projection rounds by a few units: B's vertex on
    // the exact midpoint of A's edge, A's apex and B's other vertices on
    // either side of the edge's line. The two touch there, so that along the
    // edge's normal the least projection of A and the greatest of B are
    // equal exactly; rounded, one may come out above the other, and only
    // the certificate keeps such a pair from being said apart: taking
    // lo > hi as apart says 22 of these 400,000 apart. Every hundredth
    // pair is checked to meet by the exact regions.
    rng g(1215);
    std::size_t built = 0;
    const int rounds = test_effort::scaled(400000);
    for (int round = 0; round < rounds; ++round) {
        const double x = 1e15 * (1 + 0.1 * g.signed_unit()), y = 1e15 * (1 + 0.1 * g.signed_unit());
        const double ex = 1000 * g.signed_unit(), ey = 1000 * g.signed_unit();
        const point<double> a1{x - ex, y - ey}, a2{x + ex, y + ey};
        const point<double> m{(a1.x + a2.x) / 2, (a1.y + a2.y) / 2};
        if (m.x - a1.x != a2.x - m.x || m.y - a1.y != a2.y - m.y) continue;  // the midpoint not a double
        const point<double> apex{m.x - ey * (1 + 0.5 * g.signed_unit()), m.y + ex * (1 + 0.5 * g.signed_unit())};
        const point<double> b1{m.x + ey + ex * g.signed_unit(), m.y - ex + ey * g.signed_unit()},
            b2{m.x + 2 * ey + ex * g.signed_unit(), m.y - 2 * ex + ey * g.signed_unit()};
        const polygon a({test_shapes::ring({a1, a2, apex})}), b({test_shapes::ring({m, b1, b2})});
        ++built;
        const bool apart = projections_apart(a, b) || projections_apart(b, a);
        if (apart || built % 100 == 0) {
            INFO("round " << round);
            REQUIRE(test_exact::regions_meet(test_exact::place(a, 0, 0, 0), test_exact::place(b, 0, 0, 0)));
            CHECK_FALSE(apart);
        }
    }
    CHECK(built > static_cast<std::size_t>(rounds) / 2);
}
