// SPDX-License-Identifier: BSL-1.0
// One-shot queries (intersects, certified_intersects) against the exact
// reference on CGAL's kernel, on poses nobody tuned: the families under
// random poses near contact, random multipolygons (parts inside the other
// polygon, swallowing polygons, both roles), rings nothing keeps apart, and
// the scenes scaled far from 1.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/exact/certified_intersects.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/query/intersects.hpp"
#include "verification/cgal_reference.hpp"
#include "verification/families.hpp"

namespace {

using namespace influence2d;
using verification::cgal_reference;

std::string describe_pose(const polygon& a, const polygon& b, const pose& p) {
    std::ostringstream s;
    s.precision(17);
    s << "static " << a.size() << " vertices, moving " << b.size() << ", pose " << p.tx << ',' << p.ty << ','
      << p.theta;
    return s.str();
}

/// Counts of the reference's answers, so that a run is seen not to be vacuous.
struct intersects_tally {
    std::size_t frames = 0, collide = 0;
};

/// Every one-shot mode on (a, b, p) against the reference; float and double
/// are checked only where their answers must be exact (never here): they run
/// for crashes and refusals.
void check_intersects_frame(const polygon& a, const polygon& b, const pose& p, intersects_tally& t) {
    const bool expected = cgal_reference(a, b).collide(p).collides;
    INFO(describe_pose(a, b, p));
    CHECK(intersects<exact_rational>(a, b, p) == expected);
    CHECK(certified_intersects(a, b, p) == expected);
    (void)intersects<double>(a, b, p);
    ++t.frames;
    t.collide += expected;
}

/// A survey grid's cell: a rectangle grid_width by grid_height whose corner
/// lies (x, y) from the grid's origin, far from 0 (a survey's metres).
constexpr double grid_width = 20.5, grid_height = 12.25;
polygon grid_rectangle(double x, double y) {
    const double x0 = 431234.5 + x, y0 = 6178901.25 + y, x1 = x0 + grid_width, y1 = y0 + grid_height;
    return polygon({ring_input{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, ring_role::outer}});
}

}  // namespace

TEST_CASE("one-shot: the families under random poses near contact", "[one_shot][reference]") {
    using namespace verification;
    intersects_tally t;
    const int frames = test_effort::scaled(40);
    for (family f : all_families)
        for (std::size_t n : {8u, 64u, 256u})
            for (std::size_t m : {8u, 64u}) {
                const polygon a = make_family_polygon(f, n, default_family_seed);
                const polygon b = make_family_polygon(f, m, default_family_seed + 1);
                for (const pose& p : random_poses(a, b, static_cast<std::size_t>(frames), 40, 110, n * 131 + m))
                    check_intersects_frame(a, b, p, t);
            }
    CHECK(t.collide > t.frames / 4);
    CHECK(t.collide < t.frames * 3 / 4 + t.frames / 5);
}

TEST_CASE("one-shot: random multipolygons, both roles, and rings nothing keeps apart", "[one_shot][reference]") {
    using test_scenes::rng;
    intersects_tally t;
    const int scenes = test_effort::scaled(36);
    for (int k = 0; k < scenes; ++k) {
        rng g(0x0517ULL + static_cast<std::uint64_t>(k));
        test_scenes::multi ma = test_scenes::random_multi(g, 30), mb = test_scenes::random_swallower(g);
        if (k % 2 == 1) std::swap(ma, mb);
        const polygon a = ma.to_polygon(), b = mb.to_polygon();
        const polygon messy_a(test_scenes::random_messy(g, 10)), messy_b(test_scenes::random_messy(g, 10));
        for (int f = 0; f < 12; ++f) {
            const test_scenes::part& pa = ma.parts[g.index(ma.parts.size())];
            const test_scenes::part& pb = mb.parts[g.index(mb.parts.size())];
            const double reach = pa.radius * g.uniform(0, 1.6) + pb.radius * g.uniform(0, 1.2);
            const double angle = g.uniform(0, 6.283185307179586);
            const point<double> target{pa.center.x + reach * std::cos(angle), pa.center.y + reach * std::sin(angle)};
            const double theta = g.chance(0.5) ? 0 : g.uniform(-3.2, 3.2);
            check_intersects_frame(a, b, test_scenes::aimed(pb.center, target, theta), t);
            check_intersects_frame(messy_a, messy_b,
                                   test_scenes::aimed({0, 0}, {g.uniform(-8, 8), g.uniform(-8, 8)}, theta), t);
        }
    }
    CHECK(t.collide > t.frames / 5);
    CHECK(t.collide < t.frames);
}

TEST_CASE("one-shot: far from 1 in scale, exact modes stay exact", "[one_shot][reference]") {
    using namespace verification;
    intersects_tally t;
    const polygon a0 = make_family_polygon(family::contour, 64, default_family_seed);
    const polygon b0 = make_family_polygon(family::starred, 16, default_family_seed);
    for (int e : {-600, -40, 40, 600}) {
        const auto scaled = [e](const polygon& p) {
            std::vector<ring_input> rings;
            for (std::size_t r = 0; r < p.ring_count(); ++r) {
                ring_input in;
                in.role = r == 0 ? ring_role::outer : ring_role::hole;
                for (std::size_t i = p.ring_begin(r); i < p.ring_end(r); ++i)
                    in.vertices.push_back({std::ldexp(p.vertex(i).x, e), std::ldexp(p.vertex(i).y, e)});
                rings.push_back(in);
            }
            return polygon(rings);
        };
        const polygon a = scaled(a0), b = scaled(b0);
        for (pose p : random_poses(a0, b0, static_cast<std::size_t>(test_effort::scaled(30)), 40, 110, 99)) {
            p.tx = std::ldexp(p.tx, e);
            p.ty = std::ldexp(p.ty, e);
            check_intersects_frame(a, b, p, t);
        }
    }
    CHECK(t.collide > 0);
    CHECK(t.collide < t.frames);
}

TEST_CASE("one-shot: a survey grid's neighbours moved along their shared lines by sums no double holds",
          "[one_shot][reference]") {
    // Rectangles of a grid far from the origin (a survey's metres), A and
    // its neighbour B to the right, above, or at a corner: their sides lie
    // on each other's lines. B translated along a shared line, or across it,
    // by steps whose sums with the coordinates are no doubles (1e-3, 0.1,
    // 1/3 of a side, and 1e-12, below half a unit in the last place of the
    // coordinates near 4e5 and 6e6, whose sums round back onto the line),
    // pushed in, out, or nudged across the line: the signs of touching are
    // exactly 0 or a rounding away from it, which the posing's rounding
    // hides from `certified`.
    intersects_tally t;
    const double w = grid_width, h = grid_height;
    const polygon a = grid_rectangle(0, 0);
    for (const point<double> at : {point<double>{w, 0}, point<double>{0, h}, point<double>{w, h}}) {
        const polygon b = grid_rectangle(at.x, at.y);
        for (const double step : {1e-3, 0.1, w / 3, 1e-12, -1e-3, -0.1, -w / 3, -1e-12})
            for (const double across : {0.0, 1e-3, -1e-3, 0x1p-30, -0x1p-30, 1e-12, -1e-12}) {
                // along x, then along y
                check_intersects_frame(a, b, pose{step, across, 0}, t);
                check_intersects_frame(a, b, pose{across, step, 0}, t);
                check_intersects_frame(b, a, pose{-step, -across, 0}, t);
            }
    }
    CHECK(t.collide > t.frames / 4);
    CHECK(t.collide < t.frames);
}

TEST_CASE("one-shot: a survey grid's neighbours stepped along one axis leave certified no doubt",
          "[one_shot][reference]") {
    // The grid of the test above, B stepped along x or along y alone (the
    // other component 0 or -0): the coordinate not stepped stays the input
    // double, so that every sign of touching along a shared line is a
    // product by an exact zero. `certified` settles each of them (no doubt
    // noted: no answer asked again in exact rationals) and agrees with the
    // reference, but for the steps of 1e-12, whose sums round back onto the
    // coordinates they left (a corner's ordinate 1e-12 above the other's
    // needs more than a double to tell).
    intersects_tally t;
    const double w = grid_width, h = grid_height;
    const polygon a = grid_rectangle(0, 0);
    std::size_t doubtful = 0;
    for (const point<double> at : {point<double>{w, 0}, point<double>{0, h}, point<double>{w, h}}) {
        const polygon b = grid_rectangle(at.x, at.y);
        for (const double step : {1e-3, 0.1, w / 3, 1e-12, -1e-3, -0.1, -w / 3, -1e-12})
            for (const double zero : {0.0, -0.0})
                for (const pose q : {pose{step, zero, 0}, pose{zero, step, 0}})
                    for (const bool swapped : {false, true}) {
                        const polygon &s = swapped ? b : a, &m = swapped ? a : b;
                        const pose p = swapped ? pose{-q.tx, -q.ty, 0} : q;
                        check_intersects_frame(s, m, p, t);
                        if (std::fabs(step) < 1e-9) continue;
                        const doubt_noting doubts;
                        const bool fast = intersects<certified>(s, m, p);
                        if (doubts.noted()) {
                            ++doubtful;
                            UNSCOPED_INFO("doubt noted: " << describe_pose(s, m, p));
                        } else {
                            CHECK(fast == intersects<exact_rational>(s, m, p));
                        }
                    }
    }
    CHECK(doubtful == 0);
    CHECK(t.collide > t.frames / 4);
    CHECK(t.collide < t.frames);
}

TEST_CASE("one-shot: bad input is refused", "[one_shot]") {
    const polygon a({ring_input{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
    CHECK_THROWS_AS(intersects<double>(a, polygon{}, pose{}), invalid_input);
    CHECK_THROWS_AS(intersects<double>(polygon{}, a, pose{}), invalid_input);
    CHECK_THROWS_AS(intersects<double>(a, a, pose{std::nan(""), 0, 0}), invalid_input);
    CHECK_THROWS_AS(certified_intersects(a, a, pose{0, HUGE_VAL, 0}), invalid_input);
    // Touching counts; a hole's inside does not.
    const polygon holed({ring_input{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, ring_role::outer},
                         ring_input{{{2, 2}, {8, 2}, {8, 8}, {2, 8}}, ring_role::hole}});
    const polygon small({ring_input{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, ring_role::outer}});
    CHECK(intersects<exact_rational>(a, small, pose{4, 0, 0}));
    CHECK_FALSE(intersects<exact_rational>(a, small, pose{4.5, 0, 0}));
    CHECK_FALSE(certified_intersects(holed, small, pose{4, 4, 0}));
    CHECK(certified_intersects(holed, small, pose{0.5, 0.5, 0}));
    CHECK(certified_intersects(small, holed, pose{-0.5, -0.5, 0}));
}

TEST_CASE("one-shot: the located vertex nearest the other's box, the same at every scale", "[one_shot]") {
    // ring_vertex_near: the L1-nearest vertex of a short ring, the first of
    // a long one; the same vertex for the ring and the point scaled by
    // 2^-1000 and 2^900 (squared distances would underflow and tie there).
    ring_input square;
    square.vertices = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    const polygon p({square});
    for (int e : {0, -1000, 900}) {
        const polygon q = p.scaled_by_power_of_two(e);
        const auto at = [e](double x, double y) { return point<double>{std::ldexp(x, e), std::ldexp(y, e)}; };
        INFO("scale 2^" << e);
        CHECK(ring_vertex_near(q, q.vertices(), 0, at(5, 5)) == q.ring_begin(0) + 2);
        CHECK(ring_vertex_near(q, q.vertices(), 0, at(-1, 3)) == q.ring_begin(0) + 3);
        CHECK(q.vertex(ring_vertex_near(q, q.vertices(), 0, at(3.9, 0.2))).x == std::ldexp(4.0, e));
    }
    ring_input circle;
    for (int k = 0; k < 40; ++k)
        circle.vertices.push_back({std::cos(k * 0.157079632679), std::sin(k * 0.157079632679)});
    const polygon round({circle});
    CHECK(ring_vertex_near(round, round.vertices(), 0, {-1, 0}) == round.ring_begin(0));  // past near_scan_limit
    // A small square with one corner, (2, 2), in a large one, its first
    // corner (-2, -2) outside it: the one-shot test names (2, 2) (the
    // smaller polygon's vertex nearest the other's centre), at every scale.
    const polygon big({test_shapes::square_ring(0, 0, 10)}), small({test_shapes::square_ring(-2, -2, 4)});
    for (int e : {0, -1000, 900}) {
        const polygon a = big.scaled_by_power_of_two(e), b = small.scaled_by_power_of_two(e);
        placed_polygon<double> pa(a, rotation_pose(pose{})), pb(b, rotation_pose(pose{}));
        const meeting m = placed_meet(pa, pb, 0);
        INFO("scale 2^" << e);
        REQUIRE(m.how == meeting::kind::b_vertex_in_a);
        CHECK(small.vertex(m.b_index).x == 2);
        CHECK(small.vertex(m.b_index).y == 2);
    }
}

TEST_CASE("one-shot: the nearest vertex of a long ring found by its run boxes is a whole scan's", "[one_shot]") {
    // ring_vertex_near with run boxes prunes runs by p's distance to their
    // boxes; it must name the vertex a scan of the whole ring names (the
    // first of the nearest), here written out as that scan. Rings on a
    // coarse grid give many ties; several rings, so that runs straddle
    // ring ends; points inside, outside and far off.
    std::mt19937_64 rng(1201);
    std::uniform_int_distribution<int> grid(-6, 6);
    std::uniform_real_distribution<double> off(-30, 30);
    std::size_t checked = 0, ties = 0;
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<ring_input> rings;
        const int count = 1 + trial % 3;
        for (int k = 0; k < count; ++k) {
            // A star-like ring of 20 to 120 vertices about (12 k, 0), its
            // radii on a grid of halves (ties in L1 distance).
            ring_input ring;
            const int n = 20 + (trial * 7 + k * 31) % 101;
            for (int j = 0; j < n; ++j) {
                const double angle = 2 * M_PI * j / n, radius = 3 + 0.5 * (grid(rng) + 6) / 6.0;
                ring.vertices.push_back({12.0 * k + std::round(2 * radius * std::cos(angle)) / 2,
                                         std::round(2 * radius * std::sin(angle)) / 2});
            }
            rings.push_back(ring);
        }
        const polygon q(rings);
        std::vector<box> runs;
        edge_run_boxes(q, q.vertices(), runs);
        for (int k = 0; k < 8; ++k) {
            const point<double> p = k % 2 ? point<double>{off(rng), off(rng)}
                                          : point<double>{grid(rng) * 0.5 + 12.0 * (k % count), grid(rng) * 0.5};
            for (std::size_t r = 0; r < q.ring_count(); ++r) {
                std::size_t whole = q.ring_begin(r), equal = 0;
                double best = std::numeric_limits<double>::infinity();
                for (std::size_t j = q.ring_begin(r); j < q.ring_end(r); ++j) {
                    const double d = std::fabs(q.vertex(j).x - p.x) + std::fabs(q.vertex(j).y - p.y);
                    if (d < best) {
                        best = d;
                        whole = j;
                        equal = 0;
                    } else if (d == best) {
                        ++equal;
                    }
                }
                ties += equal > 0 ? 1 : 0;
                ++checked;
                INFO("trial " << trial << " ring " << r << " point (" << p.x << ", " << p.y << ")");
                CHECK(ring_vertex_near(q, q.vertices(), r, p, runs) == whole);
            }
        }
    }
    CHECK(checked == 300 * 8 * 2);  // 1, 2 and 3 rings in turn: 2 on average
    CHECK(ties > 100);              // the grid gave ties to break
}
