// SPDX-License-Identifier: BSL-1.0
// Jumps answered by a vertex of one polygon deep in the other's region
// (detector::vertices_deep_inside, scene/interior_cells.hpp): every frame
// against CGAL's exact answer (verification::cgal_reference, which tests
// every edge pair and locates every ring itself), in exact rationals and
// certified, at d = 0 and d > 0, both roles, on random multipolygons with
// holes and islands, a long shared border, the time study's families and
// all of them far from the origin; the route answers many of the frames.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/random_scenes.hpp"
#include "support/reference_frames.hpp"
#include "support/shapes.hpp"

#include <cmath>
#include <vector>

#include "influence2d/detect/detector.hpp"
#include "influence2d/number/cgal.hpp"
#include "verification/cgal_reference.hpp"
#include "verification/families.hpp"

using namespace influence2d;
using test_scenes::rng;

namespace {

/// The region below the wiggly border of n edges (side -1) or above it
/// (side +1).
polygon border_side(std::size_t n, double side) {
    return test_shapes::border_side(test_shapes::wiggly_border(n), side);
}

/// Random poses (independent: every frame a jump) that move B by up to
/// `shift` and turn it by up to `turn` about the origin.
std::vector<pose> scattered(rng& g, std::size_t count, double shift, double turn) {
    std::vector<pose> out;
    for (std::size_t k = 0; k < count; ++k)
        out.push_back({g.uniform(-shift, shift), g.uniform(-shift, shift), g.uniform(-turn, turn)});
    return out;
}

}  // namespace

TEST_CASE("deep vertices: jumps of overlapping polygons answer as the exact reference", "[detect][exact]") {
    rng g(2612);
    std::size_t deep = 0, frames = 0, by_pairs = 0;
    const int rounds = test_effort::scaled(16);
    for (int round = 0; round < rounds; ++round) {
        polygon a, b;
        double shift = 3, turn = 0.05;
        switch (round % 4) {
        case 0:  // a long shared border, the moving side shifted across it
            a = border_side(300, -1);
            b = border_side(300, 1);
            break;
        case 1:  // random multipolygons (holes, islands in holes) in one range
            a = test_scenes::random_multi(g, 12, 12).to_polygon();
            b = test_scenes::random_multi(g, 12, 12).to_polygon();
            shift = 6;
            turn = 3;
            break;
        case 2:  // the families, 1024 x 64 and 64 x 1024
        {
            const verification::family f = verification::all_families[round / 4 % 5];
            a = verification::make_family_polygon(f, round % 8 < 4 ? 1024 : 64, 11 + round);
            b = verification::make_family_polygon(f, round % 8 < 4 ? 64 : 1024, 12 + round);
            shift = 0.5;
            turn = 3;
            break;
        }
        default:  // a swallower and a multipolygon
            a = test_scenes::random_swallower(g).to_polygon();
            b = test_scenes::random_multi(g, 8, 8).to_polygon();
            shift = 8;
            turn = 3;
        }
        // Every other round far from the origin: A moved by 2^20, the poses
        // with it.
        std::vector<pose> poses = scattered(g, 60, shift, turn);
        if (round % 2 == 1) {
            const point<double> far{0x1p20, -0x1p19};
            a = test_shapes::translated(a, far.x, far.y);
            for (pose& p : poses) {
                p.tx += far.x;
                p.ty += far.y;
            }
        }
        for (const bool swapped : {false, true}) {
            for (const double d : {0.0, 0.05}) {
                INFO("round " << round << " swapped " << swapped);
                const bool built = d == 0;
                const detector_statistics counted =
                    (swapped ? test_frames::run_against_reference(b, a, poses, d, built)
                             : test_frames::run_against_reference(a, b, poses, d, built))
                        .exact_counters;
                deep += counted.interior_frames;
                by_pairs += counted.last_pair_frames;
                frames += poses.size();
            }
        }
    }
    // The route answers a good share of the frames that the pairs which met
    // lately (asked first, last_pair_meets) leave to the search: 888 of the
    // 3,733 left (and 186 of 942 at a quarter of the effort, the sanitizer
    // run's), where a route that never answered would give none.
    INFO(deep << " of " << frames << " frames answered by a deep vertex, " << by_pairs << " by pairs that met lately");
    CHECK(deep * 6 > frames - by_pairs);
}

TEST_CASE("deep vertices: not asked with witnesses, which need edge pairs", "[detect]") {
    const polygon a = border_side(200, -1), b = border_side(200, 1);
    rng g(2613);
    const std::vector<pose> poses = scattered(g, 40, 3, 0.05);
    detector_options o;
    o.witness = true;
    detector<exact_rational> witnessed(a, b, o);
    const verification::cgal_reference ref(a, b, 0, true);
    for (const pose& p : poses) {
        const frame_result want = ref.collide(p);
        const frame_result got = witnessed.collide(p);
        REQUIRE(got.collides == want.collides);
        REQUIRE(got.pairs == want.pairs);
    }
    CHECK(witnessed.statistics().interior_frames == 0);
}
