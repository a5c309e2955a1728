// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include "influence2d/detect/detector.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

TEST_CASE("trajectory: circular orbit stays gap-close without colliding, and returns to the start", "[trajectory]") {
    const polygon a = test_shapes::c_shape(), b = test_shapes::square(0, 0, 1);
    const double gap = 0.5;
    const auto poses = circular_trajectory(a, b, 3600, gap);
    REQUIRE(poses.size() == 3600);
    // B's leftmost side is 0.5 from its centroid: the orbit radius is R_A + gap + 0.5.
    const double rho = bounding_radius(a, a.centroid()) + gap + 0.5;
    detector<exact_rational> sound(a, b);
    detector_options near;
    near.distance = gap * 1.01;
    detector<double> within(a, b, near);
    int close_frames = 0;
    for (std::size_t k = 0; k < poses.size(); k += 3) {
        const rotation_pose t(poses[k]);
        const auto c = t.apply<double>(b.centroid());
        CHECK(std::hypot(c.x - a.centroid().x, c.y - a.centroid().y) == Approx(rho).epsilon(1e-12));
        CHECK_FALSE(sound.collide(poses[k]).collides);
        close_frames += within.collide(poses[k]).collides;
    }
    CHECK(close_frames > 0);  // A's far corners sweep past within about the gap
    CHECK(poses.front().theta == 0);
    CHECK(poses.back().theta == Approx(2 * 3.141592653589793 * 3599 / 3600));
}

TEST_CASE("trajectory: linear approach starts apart and ends in collision", "[trajectory]") {
    for (const polygon& a : {test_shapes::c_shape(), test_shapes::square_with_hole()}) {
        const polygon b({test_shapes::ring({{0, 0}, {2, 0}, {1, 1.5}})});
        const auto poses = linear_trajectory(a, b, 500, 9.0);
        REQUIRE(poses.size() == 500);
        detector<exact_rational> sound(a, b);
        CHECK_FALSE(sound.collide(poses.front()).collides);
        CHECK(sound.collide(poses.back()).collides);
        // Evenly spaced along one line.
        const double dx = poses[1].tx - poses[0].tx, dy = poses[1].ty - poses[0].ty;
        CHECK(poses[250].tx - poses[249].tx == Approx(dx));
        CHECK(poses[250].ty - poses[249].ty == Approx(dy));
    }
}
