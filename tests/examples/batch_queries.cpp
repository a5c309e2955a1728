// SPDX-License-Identifier: BSL-1.0
// One query without a detector, many poses of one pair on all cores, and many
// pairs asked once each: the README's "One query, many poses, many pairs".
#include <cstdio>
#include <vector>

#include <influence2d/detect/detector.hpp>
#include <influence2d/exact/certified_detector.hpp>
#include <influence2d/exact/certified_intersects.hpp>
#include <influence2d/motion/trajectory.hpp>
#include <influence2d/query/batch.hpp>

using namespace influence2d;

int main() {
    const polygon a({ring_input{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
    const polygon b({ring_input{{{0, 0}, {1, 0}, {0, 1}}, ring_role::outer}});

    const bool hit = intersects<double>(a, b, pose{3, 1, 0.3});     // one query, no detector
    const bool sure = certified_intersects(a, b, pose{3, 1, 0.3});  // the exact answer

    // Many poses of one pair: A and B prepared once, one detector per thread.
    const auto A = prepare_static<double>(a);
    const auto B = prepare_moving<double>(b);
    std::vector<pose> poses;
    for (int k = 0; k < 1000; ++k) poses.push_back({-2 + 0.008 * k, 1, 0.001 * k});  // B crosses A
    const std::vector<frame_result> r = collide_batch(poses, [&] { return detector<double>(A, B); });
    std::size_t frames_met = 0;
    for (const frame_result& f : r) frames_met += f.collides;

    // The same poses in one loop: the batch gives the same answers.
    detector<double> serial(A, B);
    std::size_t same = 0;
    for (std::size_t k = 0; k < poses.size(); ++k) same += serial.collide(poses[k]).collides == r[k].collides;

    // Many pairs, one query each.
    std::vector<pair_query> pairs = {{&a, &b, {3, 1, 0.3}}, {&a, &b, {9, 9, 0}}, {&b, &a, {-4.5, 0, 0}}};
    const std::vector<char> met = intersects_batch(pairs, certified_intersects);

    std::printf("one query: %d %d; batch: %zu of %zu frames meet, %zu as the serial loop; pairs: %d %d %d\n",
                hit ? 1 : 0, sure ? 1 : 0, frames_met, poses.size(), same, met[0], met[1], met[2]);
    return hit && sure && same == poses.size() && frames_met > 0 && frames_met < poses.size() && met[0] && !met[1] &&
                   !met[2]
               ? 0
               : 1;
}
