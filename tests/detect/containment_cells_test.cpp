// SPDX-License-Identifier: BSL-1.0
// Containment that drops a ring by a vertex deep outside the other polygon
// (detector::contains_within, interior_cells::excludes): every frame against
// CGAL's exact answer (verification::cgal_reference, which locates every ring
// itself), in exact rationals and certified, at d = 0 and d > 0, both roles,
// with the cells built first and built by the detector on its own, on two
// polygons along a long shared border whose islands lie in the other's lakes
// (poses just apart by 2^-30 to 0.1, and crossing), with an island in the
// other's land in some rounds, and on random multipolygons at 2^20 from the
// origin, and on real neighbours (data/real/neighbours.wkt: Chile and
// Argentina, Indonesia and Malaysia, multipolygons of many islands) pushed
// apart along the line between their boxes' centres until they just miss
// or just meet, as CGAL's reference decides; the cells drop many rings.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/neighbours.hpp"
#include "support/random_scenes.hpp"
#include "support/reference_frames.hpp"
#include "support/shapes.hpp"

#include <cmath>
#include <vector>

#include "influence2d/detect/detector.hpp"
#include "verification/cgal_reference.hpp"

using namespace influence2d;
using test_scenes::rng;

namespace {

/// The side of the wiggly border of n edges below it (side -1) or above it
/// (side +1), with `lakes` square holes of side 1.5 at depth 5, and in each
/// of the other side's lakes an island of side 0.5 at its middle (the other
/// side's lakes lie at the same x, mirrored). With `landed`, one more island
/// on the other side's land, between its lakes.
polygon coast(std::size_t n, double side, std::size_t lakes, bool landed) {
    const std::vector<point<double>> border = test_shapes::wiggly_border(n);
    std::vector<ring_input> rings;
    ring_input land;
    land.vertices = border;
    land.vertices.push_back({border.back().x, 10 * side});
    land.vertices.push_back({border.front().x, 10 * side});
    rings.push_back(land);
    for (std::size_t k = 0; k < lakes; ++k) {
        const double x = 5 + 90.0 * static_cast<double>(k) / static_cast<double>(lakes);
        rings.push_back(test_shapes::square_ring(x, 5 * side - 0.75, 1.5, ring_role::hole));
        rings.push_back(test_shapes::square_ring(x + 0.5, -5 * side - 0.25, 0.5));
    }
    if (landed) rings.push_back(test_shapes::square_ring(3, -5 * side - 0.25, 0.5));
    return polygon(rings);
}

/// Poses of B about A: a random turn about B's box centre and shift, then
/// B pushed along the line from A's box centre to its own until CGAL's
/// reference finds it apart, and the push halved 20 times between the last
/// push that met and the first apart: the pose just apart and the pose just
/// meeting, for each of `count` starts.
std::vector<pose> pushed_apart(const polygon& a, const polygon& b, std::size_t count, rng& g) {
    const verification::cgal_reference ref(a, b, 0);
    const point<double> ca = a.bounds().centre(), cb = b.bounds().centre();
    std::vector<pose> out;
    for (std::size_t k = 0; k < count; ++k) {
        const double theta = g.uniform(-0.02, 0.02);
        pose q{g.uniform(-0.5, 0.5), g.uniform(-0.5, 0.5), theta};
        q.tx += cb.x - (std::cos(theta) * cb.x - std::sin(theta) * cb.y);
        q.ty += cb.y - (std::sin(theta) * cb.x + std::cos(theta) * cb.y);
        const double dx = cb.x - ca.x, dy = cb.y - ca.y, length = std::hypot(dx, dy);
        const auto at = [&](double t) { return pose{q.tx + t * dx / length, q.ty + t * dy / length, theta}; };
        double meets = 0, apart = 0.01;
        while (ref.collide(at(apart)).collides) {
            meets = apart;
            apart *= 2;
        }
        for (int i = 0; i < 20; ++i) {
            const double m = (meets + apart) / 2;
            (ref.collide(at(m)).collides ? meets : apart) = m;
        }
        out.push_back(at(apart));
        out.push_back(at(meets));
    }
    return out;
}

}  // namespace

TEST_CASE("containment cells: rings dropped by a vertex deep outside answer as the exact reference",
          "[detect][exact]") {
    rng g(2631);
    std::size_t frames = 0, met = 0, excluded = 0, tree_located = 0;
    const int rounds = test_effort::scaled(12);
    for (int round = 0; round < rounds; ++round) {
        polygon a, b;
        std::vector<pose> poses;
        if (round % 3 != 2) {
            // Two coasts: B just above A (apart), just below (crossing the
            // border), and moved a little in any way.
            const bool landed = round % 3 == 1;
            a = coast(160, -1, 6, landed);
            b = coast(160, 1, 6, false);
            for (const double up : {0x1p-30, 1e-6, 1e-3, 0.1}) {
                poses.push_back({0, up, 0});
                poses.push_back({0, -up, 0});
            }
            for (int k = 0; k < 8; ++k)
                poses.push_back({g.uniform(-0.3, 0.3), g.uniform(-0.2, 0.4), g.uniform(-2e-3, 2e-3)});
        } else {
            // Random multipolygons (holes, islands in holes), far from the
            // origin: A moved by 2^20, the poses with it.
            a = test_shapes::translated(test_scenes::random_multi(g, 12, 14).to_polygon(), 0x1p20, -0x1p19);
            b = test_scenes::random_multi(g, 12, 14).to_polygon();
            for (int k = 0; k < 24; ++k)
                poses.push_back({0x1p20 + g.uniform(-8, 8), -0x1p19 + g.uniform(-8, 8), g.uniform(-3, 3)});
        }
        for (const bool swapped : {false, true})
            for (const double d : {0.0, 0.05})
                for (const bool built : {true, false}) {
                    INFO("round " << round << " swapped " << swapped << " built " << built);
                    const test_frames::reference_run run =
                        swapped ? test_frames::run_against_reference(b, a, poses, d, built)
                                : test_frames::run_against_reference(a, b, poses, d, built);
                    frames += poses.size();
                    met += run.met;
                    excluded += run.exact_counters.containment_rings_excluded;
                    tree_located += run.exact_counters.containment_tree_locates;
                }
    }
    // Both answers occur, the cells drop many rings (those off B's turned
    // box dropped before them), and the edge trees locate others (every
    // answer above checked).
    INFO(met << " of " << frames << " frames met, " << excluded << " rings excluded, " << tree_located
             << " located through a tree");
    CHECK(met * 5 > frames);
    CHECK((frames - met) * 5 > frames);
    CHECK(excluded * 2 > frames);
    CHECK(tree_located > 0);
}

TEST_CASE("containment cells: real neighbours pushed just apart answer as the exact reference",
          "[detect][exact][real]") {
    const std::vector<polygon> layer = test_data::neighbours();
    REQUIRE(layer.size() == 4);
    rng g(2632);
    const std::size_t count = static_cast<std::size_t>(test_effort::scaled(6));
    std::size_t frames = 0, met = 0, excluded = 0, tree_located = 0;
    for (const auto& [i, j] : {std::pair<int, int>{0, 1}, {1, 0}, {2, 3}, {3, 2}}) {
        const std::vector<pose> poses = pushed_apart(layer[i], layer[j], count, g);
        for (const bool built : {true, false}) {
            INFO("polygons " << i << ", " << j << " built " << built);
            const test_frames::reference_run run =
                test_frames::run_against_reference(layer[i], layer[j], poses, 0, built);
            frames += poses.size();
            met += run.met;
            excluded += run.exact_counters.containment_rings_excluded;
            tree_located += run.exact_counters.containment_tree_locates;
        }
    }
    // Half the poses just apart; most of the others just meeting (a start
    // already apart gives two poses apart); the cells drop rings (those off
    // B's turned box dropped before them), the edge trees locate others.
    INFO(met << " of " << frames << " frames met, " << excluded << " rings excluded, " << tree_located
             << " located through a tree");
    CHECK(met * 4 > frames);
    CHECK((frames - met) * 2 >= frames);
    CHECK(excluded * 4 > frames);
    CHECK(tree_located > 0);
}

TEST_CASE("containment cells: an island by a corner of a long polygon turned a little answers as the exact reference",
          "[detect][exact]") {
    // B: a strip 100 long and 4 wide (its long sides in 100 edges each, so
    // that the frames take the edge trees) and an island of it far above,
    // which makes B's bounding circle far wider than its turned box. A: an
    // island near a random corner of the strip (inside it or just off its
    // end), one between the strip and B's island and one past the strip's
    // end; B turned by up to 0.03 rad about its box's centre, which moves the
    // strip's ends by up to about 1.6 across: the corner island ends inside
    // B, outside it or across its border, and a turned box too narrow for
    // the turn drops it as outside while it lies in B.
    std::vector<point<double>> strip;
    for (int k = 0; k <= 100; ++k) strip.push_back({static_cast<double>(k), 0});
    for (int k = 100; k >= 0; --k) strip.push_back({static_cast<double>(k), 4});
    const polygon b({test_shapes::ring(strip), test_shapes::square_ring(48, 40, 4)});
    const point<double> cb = b.bounds().centre();
    rng g(2633);
    std::size_t frames = 0, met = 0, excluded = 0;
    const int rounds = test_effort::scaled(16);
    for (int round = 0; round < rounds; ++round) {
        const bool right = round % 2 == 1, top = round % 4 >= 2;
        const double x = right ? g.uniform(98.6, 100.4) : g.uniform(-0.9, 0.9);
        const double y = top ? g.uniform(2.6, 3.4) : g.uniform(0.1, 0.9);
        const polygon a({test_shapes::square_ring(x, y, 0.5), test_shapes::square_ring(30, 20, 1),
                         test_shapes::square_ring(right ? -3 : 103, 1.5, 0.5)});
        std::vector<pose> poses;
        for (int k = 0; k < 12; ++k) {
            const double theta = g.uniform(-0.03, 0.03), c = std::cos(theta), s = std::sin(theta);
            poses.push_back({cb.x - (c * cb.x - s * cb.y) + g.uniform(-0.3, 0.3),
                             cb.y - (s * cb.x + c * cb.y) + g.uniform(-0.3, 0.3), theta});
        }
        for (const bool swapped : {false, true})
            for (const double d : {0.0, 0.05}) {
                INFO("round " << round << " swapped " << swapped << " island at " << x << ", " << y);
                const test_frames::reference_run run = swapped
                                                           ? test_frames::run_against_reference(b, a, poses, d, true)
                                                           : test_frames::run_against_reference(a, b, poses, d, true);
                frames += poses.size();
                met += run.met;
                excluded += run.exact_counters.containment_rings_excluded;
            }
    }
    // Both answers occur (every answer above checked).
    INFO(met << " of " << frames << " frames met, " << excluded << " rings excluded");
    CHECK(met * 5 > frames);
    CHECK((frames - met) * 5 > frames);
}
