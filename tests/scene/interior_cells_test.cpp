// SPDX-License-Identifier: BSL-1.0
// The cells deep in a polygon's region and deep outside it
// (scene/interior_cells.hpp), against CGAL's exact rationals: every point
// the grid holds lies in the closed region with every point within the
// margin of it (the point inside, each edge of each ring at least the margin
// away, exactly), and every point it excludes lies outside with every point
// within the margin of it, on random
// multipolygons, messy rings and the time study's families at scales from
// 2^-600 to 2^500 and far from the origin, on points anywhere in the box and
// just off the boundary, and on boundaries that run exactly along the
// cells' sides.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/exact_regions.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "influence2d/scene/interior_cells.hpp"
#include "verification/families.hpp"

namespace {

using namespace influence2d;
using test_scenes::rng;
using Q = exact_rational;

/// What one polygon's check found.
struct cells_tally {
    std::size_t asked = 0, inside = 0, held = 0;  ///< the random points of the box
    std::size_t excluded = 0;                     ///< of them, those the grid excludes
};

/// Whether every point within m of q lies in p's closed region, exactly: q
/// in the region and every edge at least m from it.
/// With `inside` false: whether every point within m of q lies outside it,
/// exactly.
bool disc_in_region(const test_exact::placed_shape& p, const point<double>& q, double m, bool inside = true) {
    const test_exact::point_2 x(Q(q.x), Q(q.y));
    if (test_exact::in_region(p, x) != inside) return false;
    const Q m2 = Q(m) * Q(m);
    for (std::size_t i = 0; i < p.v.size(); ++i) {
        const Q d2 = p.v[i] == p.end(i) ? CGAL::squared_distance(x, p.v[i])
                                        : CGAL::squared_distance(x, test_exact::segment_2(p.v[i], p.end(i)));
        if (d2 < m2) return false;
    }
    return true;
}

/// Asks the grid of p about `count` random points of its box and points
/// just off each edge (on either side, at fractions of a cell's side), each
/// with the largest margin holds() takes; every point held must pass
/// disc_in_region.
cells_tally check_cells(const polygon& p, rng& g, std::size_t count) {
    const interior_cells cells(p);
    const test_exact::placed_shape exact = test_exact::place(p, pose{});
    const double m = cells.cell_side() / 2;
    cells_tally t;
    std::size_t excluded = 0;
    const auto ask = [&](const point<double>& q) {
        const bool held = cells.holds(q, m), out = cells.excludes(q, m);
        excluded += out ? 1 : 0;
        if (!held && !out) return false;
        INFO("point (" << q.x << ", " << q.y << "), margin " << m << ", " << p.size() << " vertices");
        CHECK_FALSE((held && out));
        CHECK(disc_in_region(exact, q, m, held));
        return held;
    };
    const box& b = p.bounds();
    for (std::size_t k = 0; k < count; ++k) {
        const point<double> q{g.uniform(b.min_x, b.max_x), g.uniform(b.min_y, b.max_y)};
        // And every fourth time one about the box, out to half its size
        // beyond it.
        const double w = b.max_x - b.min_x, h = b.max_y - b.min_y;
        if (k % 4 == 0) ask({g.uniform(b.min_x - w / 2, b.max_x + w / 2), g.uniform(b.min_y - h / 2, b.max_y + h / 2)});
        ++t.asked;
        t.inside += test_exact::in_region(exact, test_exact::point_2(Q(q.x), Q(q.y))) ? 1 : 0;
        t.held += ask(q) ? 1 : 0;
    }
    t.excluded = excluded;
    const double side = cells.cell_side();
    for (std::size_t e = 0; e < p.size(); e += 1 + p.size() / 64) {
        const point<double>&u = p.vertex(e), &v = p.vertex(p.next(e));
        const double dx = v.x - u.x, dy = v.y - u.y, length = std::hypot(dx, dy);
        if (!(length > 0)) continue;
        for (const double f : {0.25, 0.5, 1.0, 1.5, 2.0})
            for (const double sign : {-1.0, 1.0}) {
                const double off = sign * f * side / length;
                ask({u.x / 2 + v.x / 2 - off * dy, u.y / 2 + v.y / 2 + off * dx});
            }
    }
    // Not with a margin beyond half a side, nor a NaN one, nor a NaN point.
    const point<double> c = b.centre();
    CHECK_FALSE(cells.holds(c, std::nextafter(m, 1e300)));
    CHECK_FALSE(cells.holds(c, std::nan("")));
    CHECK_FALSE(cells.holds({std::nan(""), c.y}, 0));
    CHECK_FALSE(cells.excludes({b.min_x, b.min_y}, std::nextafter(m, 1e300)));
    CHECK_FALSE(cells.excludes({std::nan(""), c.y}, 0));
    // Beyond the box: excluded when farther than the margin, on every side.
    const double w = b.max_x - b.min_x, h = b.max_y - b.min_y;
    for (const double f : {0.001, 0.5, 3.0}) {
        for (const point<double> q : {point<double>{b.min_x - f * w - 2 * m, c.y},
                                      {b.max_x + f * w + 2 * m, c.y},
                                      {c.x, b.min_y - f * h - 2 * m},
                                      {c.x, b.max_y + f * h + 2 * m}}) {
            INFO("beyond the box at (" << q.x << ", " << q.y << ")");
            CHECK(cells.excludes(q, m));
            CHECK(disc_in_region(exact, q, m, false));
        }
    }
    // Within the margin of the box: not.
    CHECK_FALSE(cells.excludes({b.min_x - m / 2, c.y}, m));
    CHECK_FALSE(cells.excludes({c.x, b.max_y + m / 2}, m));
    CHECK_FALSE(cells.excludes({-std::numeric_limits<double>::infinity(), c.y}, m));
    return t;
}

}  // namespace

TEST_CASE("interior_cells: every point held lies in the region with its margin, against exact regions", "[scene]") {
    rng g(2611);
    cells_tally all;
    const int rounds = test_effort::scaled(120);
    for (int round = 0; round < rounds; ++round) {
        const int k = std::array<int, 5>{0, -600, -40, 7, 500}[static_cast<std::size_t>(round % 5)];
        polygon base = test_scenes::random_multi(g, 10 + round % 30, 2 + round % 6).to_polygon();
        if (round % 4 == 1) base = test_scenes::random_swallower(g).to_polygon();
        if (round % 4 == 2) base = polygon(test_scenes::random_messy(g, 8 + round % 10));
        if (round % 4 == 3) {
            const verification::family f = verification::all_families[round / 4 % 5];
            base = verification::make_family_polygon(f, std::array<std::size_t, 3>{8, 64, 1024}[round % 3], 7 + round);
        }
        polygon p = base.scaled_by_power_of_two(k);
        // Every seventh far from the origin: the cells then shrink against
        // the coordinates' rounding.
        if (round % 7 == 6) p = test_shapes::translated(base, 0x1p20, -0x1p19);
        INFO("round " << round << " at 2^" << k);
        const cells_tally t = check_cells(p, g, 200);
        all.asked += t.asked;
        all.inside += t.inside;
        all.held += t.held;
        all.excluded += t.excluded;
    }
    // Not empty: the grid holds most random points of the regions, and
    // excludes many of the others.
    INFO(all.held << " held of " << all.inside << " inside, " << all.excluded << " excluded, " << all.asked
                  << " asked");
    CHECK(all.held * 2 > all.inside);
    CHECK(all.excluded * 4 > all.asked - all.inside);
}

TEST_CASE("interior_cells: boundaries along the cells' sides, touching parts and a slit", "[scene]") {
    // 64 x 64 boxes of at most 8 edges get 1,024 cells of side 2: these
    // boundaries run exactly along cell sides.
    const std::vector<polygon> shapes{
        // Two squares sharing the side x = 32.
        polygon({test_shapes::ring({{0, 0}, {32, 0}, {32, 64}, {0, 64}}),
                 test_shapes::ring({{32, 0}, {64, 0}, {64, 64}, {32, 64}})}),
        // A square with a square hole whose sides are cell sides.
        polygon({test_shapes::square_ring(0, 0, 64), test_shapes::square_ring(16, 16, 32, ring_role::hole)}),
        // A slit of width 0 from the top down to y = 20 along x = 30: the
        // two sides of the slit are the same line.
        polygon({test_shapes::ring({{0, 0}, {64, 0}, {64, 64}, {30, 64}, {30, 20}, {30, 64}, {0, 64}})}),
        // A U whose arms are one cell wide (none of their cells deep).
        polygon({test_shapes::ring({{0, 0}, {64, 0}, {64, 64}, {62, 64}, {62, 16}, {2, 16}, {2, 64}, {0, 64}})}),
    };
    std::size_t excluded = 0;  // over the shapes: the hole and the U's inside
    for (std::size_t s = 0; s < shapes.size(); ++s) {
        const polygon& p = shapes[s];
        const interior_cells cells(p);
        const test_exact::placed_shape exact = test_exact::place(p, pose{});
        INFO("shape " << s << ", cell side " << cells.cell_side());
        CHECK(cells.cell_side() == 2);
        std::size_t held = 0;
        // Every lattice point, cell centre and quarter point: sides, corners
        // and centres (every half point under a reduced effort, which
        // still holds the lattice points and cell centres).
        const int per_unit = test_effort::effort() < 1 ? 2 : 4;
        for (int i = 0; i <= 64 * per_unit; ++i)
            for (int j = 0; j <= 64 * per_unit; ++j) {
                const point<double> q{i / static_cast<double>(per_unit), j / static_cast<double>(per_unit)};
                const bool in = cells.holds(q, 1), out = cells.excludes(q, 1);
                if (!in && !out) continue;
                held += in ? 1 : 0;
                excluded += out ? 1 : 0;
                INFO("point (" << q.x << ", " << q.y << ")");
                CHECK_FALSE((in && out));
                CHECK(disc_in_region(exact, q, 1, in));
            }
        CHECK(held > 0);
    }
    CHECK(excluded > 0);
}

TEST_CASE("interior_cells: none for a flat box or cells below the coordinates' rounding", "[scene]") {
    // A sliver 2^-30 as high as wide: fewer than three rows of cells.
    const polygon flat({test_shapes::ring({{0, 0}, {4, 0}, {2, 0x1p-28}})});
    CHECK(interior_cells(flat).empty());
    // A unit square at 2^40: a side of 1/32 is below 8 slacks (2^-40 of
    // 2^40 each).
    const interior_cells far(test_shapes::square(0x1p40, 0x1p40, 1));
    CHECK(far.empty());
    CHECK_FALSE(far.holds({0x1p40 + 0.5, 0x1p40 + 0.5}, 0));
    // A default grid holds nothing.
    CHECK_FALSE(interior_cells().holds({0, 0}, 0));
    // The square itself near the origin: most of its 1,024 cells are deep.
    const interior_cells near(test_shapes::square(0, 0, 1));
    CHECK(near.deep_cells() > 700);
    CHECK(near.holds({0.5, 0.5}, 0.001));
    CHECK(near.deep_outside_cells() == 0);  // its box is its region
    // A square with a square hole: the hole's middle is deep outside.
    const interior_cells holed(
        polygon({test_shapes::square_ring(0, 0, 64), test_shapes::square_ring(16, 16, 32, ring_role::hole)}));
    CHECK(holed.excludes({32, 32}, 1));
    CHECK_FALSE(holed.holds({32, 32}, 1));
    CHECK(holed.holds({8, 32}, 1));
}
