// SPDX-License-Identifier: BSL-1.0
// Beyond yes or no: the distance and the closest features at a pose, the
// first contact along a motion (a square jumping across a thin wall between
// two poses), the exit distance along a direction, and both polygons moving:
// the README's "Distance, closest features, first contact".
#include <cstdio>

#include <influence2d/distance/separation.hpp>
#include <influence2d/exact/certified_both_posed.hpp>
#include <influence2d/exact/certified_detector.hpp>
#include <influence2d/exact/certified_exit_distance.hpp>
#include <influence2d/exact/certified_first_contact.hpp>
#include <influence2d/exact/certified_separation.hpp>
#include <influence2d/motion/exit_distance.hpp>
#include <influence2d/motion/first_contact.hpp>
#include <influence2d/query/both_posed.hpp>

using namespace influence2d;

int main() {
    const polygon wall({ring_input{{{-0.125, -5}, {0.125, -5}, {0.125, 5}, {-0.125, 5}}, ring_role::outer}});
    const polygon square({ring_input{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, ring_role::outer}});

    // Distance and closest features at a pose (exact in exact_rational;
    // certified: the exact features, the distance within one ulp).
    const separation_result<double> s = separation<double>(wall, square, pose{-3, 0, 0});
    const certified_separation_result c = certified_separation(wall, square, pose{-3, 0, 0});
    separation_query<double> near(wall, square);  // many poses of one pair
    const double d_next = distance_of<double>(near(pose{-2.5, 0, 0}).squared_distance);

    // The square jumps from x = -3 to x = 3: no pose meets the wall, the motion does.
    const bool at_poses =
        intersects<double>(wall, square, pose{-3, 0, 0}) || intersects<double>(wall, square, pose{3, 0, 0});
    const contact_result<double> hit = certified_first_contact(wall, square, pose{-3, 0, 0}, pose{3, 0, 0});
    const contact_result<exact_rational> exact_hit =
        first_contact<exact_rational>(wall, square, pose{-3, 0, 0}, pose{3, 0, 0});

    // How far the square, overlapping the wall at x = 0.5, must move along +x to leave it.
    const exact_rational out = exit_distance<exact_rational>(wall, square, pose{0.5, 0, 0}, 1, 0);
    const double out_fast = certified_exit_distance(wall, square, pose{0.5, 0, 0}, 1, 0);  // 0.625, rounded

    // Both moving: the wall shifted by 2, the square at 2.5: they meet, exactly posed in the world.
    const bool both = certified_intersects(wall, pose{2, 0, 0}, square, pose{2.5, 0, 0});

    std::printf(
        "distance %.4f (certified %.4f, next pose %.4f) between wall %s%zu and square %s%zu, "
        "at the poses: %d, first contact t = %.4f (exact %s), exit distance %s (certified %.4f), both moving: %d\n",
        distance_of<double>(s.squared_distance), c.distance, d_next,
        s.static_feature.kind == feature_kind::edge ? "edge " : "vertex ", s.static_feature.index,
        s.moving_feature.kind == feature_kind::edge ? "edge " : "vertex ", s.moving_feature.index, at_poses ? 1 : 0,
        hit.time, exact_hit.time == exact_rational(5) / 16 ? "5/16" : "?", out == exact_rational(5) / 8 ? "5/8" : "?",
        out_fast, both ? 1 : 0);
    return hit.contact && !at_poses && exact_hit.time == exact_rational(5) / 16 && out == exact_rational(5) / 8 &&
                   out_fast == 0.625 && both
               ? 0
               : 1;
}
