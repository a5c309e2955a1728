// SPDX-License-Identifier: BSL-1.0
// CGAL's interval arithmetic as a number type: its traits decide a sign only
// when the interval does, and interval_detector, which falls back to exact
// rationals on both kinds of undecided results (uncertain_sign from the
// traits, CGAL::Uncertain_conversion_exception from a comparison), gives the
// answers of detector<exact_rational>.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/interval_detector.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "support/families.hpp"
#include "support/poses.hpp"

namespace {

using namespace influence2d;
using interval_traits = number_traits<interval>;

bool same_answer(const frame_result& x, const frame_result& y) {
    return x.collides == y.collides && x.pairs == y.pairs;
}

}  // namespace

TEST_CASE("interval traits: certain signs, and uncertain_sign otherwise", "[interval]") {
    CHECK(std::string(interval_traits::name) == "interval");
    CHECK(interval_traits::category == number_category::filtered);
    CHECK(interval_traits::sign(interval_traits::from_double(2.5)) == 1);
    CHECK(interval_traits::sign(interval_traits::from_double(-0x1p-1074)) == -1);
    CHECK(interval_traits::sign(interval_traits::from_double(0)) == 0);
    CHECK(interval_traits::to_double(interval_traits::from_double(0.1)) == 0.1);
    CHECK(interval_traits::sign(interval(1.0) - interval(1.0)) == 0);  // a point minus itself: exactly {0}

    // 0.1 * 10 - 1 (exactly 2^-54 on the input doubles): the interval
    // [0, 2^-52] holds 0 and more.
    const interval p = interval(0.1) * interval(10.0) - interval(1.0);
    CHECK(p.inf() == 0);
    CHECK(p.sup() > 0);
    CHECK_THROWS_AS(interval_traits::sign(p), uncertain_sign);
    CHECK_THROWS_AS(interval_traits::sign(interval(std::numeric_limits<double>::quiet_NaN())), uncertain_sign);
    // Overflow keeps a certain sign: [DBL_MAX, inf] is positive.
    CHECK(interval_traits::sign(interval(1e200) * interval(1e200)) == 1);

    // Comparisons are CGAL's: an undecided one throws its own exception.
    const interval one_ish = interval(0.1) * interval(10.0);
    CHECK_THROWS_AS(static_cast<bool>(one_ish > interval(1.0)), CGAL::Uncertain_conversion_exception);
    CHECK_THROWS_AS(static_cast<bool>(one_ish == interval(1.0)), CGAL::Uncertain_conversion_exception);
    CHECK(static_cast<bool>(interval(1.0) < interval(2.0)));
    CHECK(!static_cast<bool>(one_ish < interval(1.0)));  // [1, 1 + 2^-52] < 1: certainly not

    // The orientation predicate: decided, undecided (exactly collinear with an
    // inexact input).
    const point<interval> a{interval(0), interval(0)}, c{interval(2), interval(2)};
    CHECK(orientation(a, point<interval>{interval(1), interval(0)}, c) == 1);
    CHECK_THROWS_AS(orientation(a, point<interval>{one_ish, one_ish}, c), uncertain_sign);
}

TEST_CASE("interval_detector equals the exact detector", "[detect][interval]") {
    struct scene {
        const char* a;
        const char* b;
    };
    std::size_t frames = 0, collisions = 0, generic_fallbacks = 0, touching_fallbacks = 0, touching = 0;
    for (const scene& s : {scene{"contour_32", "starred_16"}, scene{"hole_16", "irregular_32"},
                           scene{"convex_64", "contour_8"}, scene{"starred_8", "hole_64"}}) {
        const polygon& A = test_families::load(s.a);
        const polygon& B = test_families::load(s.b);
        for (const double d : {0.0, 0.5}) {
            detector_options wit;
            wit.witness = true;
            wit.distance = d;
            detector<exact_rational> exact(A, B, wit);
            interval_detector<detector> fast(A, B, wit);
            interval_detector<brute_force_detector> brute(A, B, wit);
            REQUIRE(fast.filtered());
            // Generic: B's centroid approaching A's from beyond the bounding
            // circles to the centre, turning; touching: theta = 0 with a vertex
            // of B on a vertex of A (exact: coordinates on a 2^-20 grid), and
            // the same with tx one ulp larger.
            std::vector<pose> poses = test_poses::approach(A, B, 120, {0.7, 0.5, 0.1, 3});
            const std::size_t generic_count = poses.size();
            for (std::size_t i = 0; i < A.size(); i += 3) {
                const point<double> q = B.vertex((7 * i) % B.size()), v = A.vertex(i);
                poses.push_back({v.x - q.x, v.y - q.y, 0});
                poses.push_back({std::nextafter(v.x - q.x, 1e9), v.y - q.y, 0});
            }
            std::size_t before = fast.exact_frames() + brute.exact_frames();
            for (std::size_t k = 0; k < poses.size(); ++k) {
                if (k == generic_count) {
                    generic_fallbacks += fast.exact_frames() + brute.exact_frames() - before;
                    before = fast.exact_frames() + brute.exact_frames();
                }
                const frame_result want = exact.collide(poses[k]);
                INFO(s.a << " x " << s.b << ", d = " << d << ", frame " << k);
                CHECK(same_answer(fast.collide(poses[k]), want));
                CHECK(same_answer(brute.collide(poses[k]), want));
                ++frames;
                collisions += want.collides;
                if (k >= generic_count) ++touching;
            }
            touching_fallbacks += fast.exact_frames() + brute.exact_frames() - before;
        }
    }
    INFO("frames " << frames << ", collisions " << collisions << ", fallbacks: generic " << generic_fallbacks
                   << ", touching and one-ulp " << touching_fallbacks << " of " << 2 * touching);
    CHECK(collisions >= frames / 4);
    CHECK(generic_fallbacks == 0);
    // Posed at theta = 0, grid coordinates stay exact point intervals, so an
    // exact touch is decided without the fallback; a pose one ulp off rounds,
    // and some of those decisions straddle 0.
    CHECK(touching_fallbacks > 0);
}
