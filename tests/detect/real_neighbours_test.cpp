// SPDX-License-Identifier: BSL-1.0
// Real neighbours (data/real/neighbours.wkt: Chile, Argentina, Indonesia and
// Malaysia from Natural Earth's 1:110m map, multipolygons that share their
// border vertices exactly) at their own coordinates and moved far from the
// origin, where the coordinates' rounding is of the order of the features:
// the exact modes answer as CGAL's exact reference, double as its brute
// force, on poses that touch exactly, move by a few units in the last place,
// turn slightly about the pair, or jump.

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "support/effort.hpp"
#include "support/neighbours.hpp"
#include "support/random.hpp"
#include "support/shapes.hpp"

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/number/cgal.hpp"
#include "verification/cgal_reference.hpp"

using namespace influence2d;

namespace {

/// Poses about the point o: the identity (the shared border touches), a
/// translation by a few of o's units in the last place, a turn by up to
/// 1e-3 or 1e-9 rad about o, a jump of up to 0.5 degrees with a turn.
std::vector<pose> poses_about(point<double> o, std::size_t count, std::uint64_t seed) {
    test_random::rng r(seed);
    const double ulp = std::nextafter(std::fabs(o.x), HUGE_VAL) - std::fabs(o.x);
    std::vector<pose> out{{0, 0, 0}};
    for (std::size_t k = 1; k < count; ++k) {
        const std::size_t kind = k % 4;
        const double theta = kind == 1 ? 0 : r.uniform(-1e-3, 1e-3) * (kind == 2 ? 1e-6 : 1);
        double tx = kind == 1 ? std::round(r.uniform(-4, 4)) * ulp : r.uniform(-0.5, 0.5);
        double ty = kind == 1 ? std::round(r.uniform(-4, 4)) * ulp : r.uniform(-0.5, 0.5);
        tx += o.x - (std::cos(theta) * o.x - std::sin(theta) * o.y);
        ty += o.y - (std::sin(theta) * o.x + std::cos(theta) * o.y);
        out.push_back({tx, ty, theta});
    }
    return out;
}

}  // namespace

TEST_CASE("real neighbours: exact modes answer as the exact reference at their coordinates and far from the origin",
          "[detect][real]") {
    const std::vector<polygon> layer = test_data::neighbours();
    REQUIRE(layer.size() == 4);
    const std::size_t count = static_cast<std::size_t>(test_effort::scaled(301));
    std::size_t met = 0, apart = 0, asked = 0;
    for (const double offset : {0.0, 1e7, 0x1p40})
        for (const auto& [i, j] : {std::pair<int, int>{0, 1}, {1, 0}, {2, 3}, {3, 2}}) {
            const point<double> o{offset, offset / 2};
            // Each coordinate the double nearest to its sum with o, so that the
            // vertices the neighbours share stay shared.
            const polygon a = test_shapes::translated(layer[i], o.x, o.y),
                          b = test_shapes::translated(layer[j], o.x, o.y);
            const std::vector<pose> poses = poses_about(o, count, 17 + static_cast<std::uint64_t>(4 * i + j));
            for (const double d : {0.0, 0.005}) {
                detector_options options;
                options.distance = d;
                const verification::cgal_reference reference(a, b, d);
                certified_detector<detector> certified(a, b, options);
                detector<exact_rational> exact(a, b, options);
                detector<double> fast(a, b, options);
                brute_force_detector<double> fast_reference(a, b, options);
                for (std::size_t k = 0; k < poses.size(); ++k) {
                    INFO("offset " << offset << " polygons " << i << ", " << j << " d " << d << " pose " << k << ": "
                                   << poses[k].tx << ", " << poses[k].ty << ", " << poses[k].theta);
                    const bool want = reference.collide(poses[k]).collides;
                    (want ? met : apart) += 1;
                    ++asked;
                    REQUIRE(certified.collide(poses[k]).collides == want);
                    REQUIRE(exact.collide(poses[k]).collides == want);
                    REQUIRE(fast.collide(poses[k]).collides == fast_reference.collide(poses[k]).collides);
                    // Each pair shares a border: it touches at the identity.
                    if (k == 0) REQUIRE(want);
                }
            }
        }
    // Both answers occur.
    CHECK(met > asked / 2);
    CHECK(apart > 0);
}
