// SPDX-License-Identifier: BSL-1.0
// Many bodies stepped pose by pose, and all meeting pairs of a layer: the
// README's "Many bodies and layers".
#include <cstdio>
#include <vector>

#include <influence2d/exact/certified_world.hpp>
#include <influence2d/world/layer_pairs.hpp>
#include <influence2d/world/world.hpp>

using namespace influence2d;

int main() {
    // A non-convex floor (a U-shaped trough), fixed, and five squares falling
    // into it side by side, one unit lower each step.
    const polygon floor({ring_input{{{0, 0}, {12, 0}, {12, 6}, {11, 6}, {11, 1}, {1, 1}, {1, 6}, {0, 6}}}});
    const polygon square({ring_input{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}});

    world_options options;
    options.threads = 0;  // the narrow phase on every core; the answers are the serial run's
    certified_world w(options);
    const auto floor_shape = w.add_shape(floor), square_shape = w.add_shape(square);
    w.add_body(floor_shape, pose{}, /*fixed=*/true);
    for (int k = 0; k < 5; ++k) w.add_body(square_shape, pose{1.0 + 2 * k, 9, 0});

    int step = 0, floor_touch = -1;
    std::size_t begun = 0;
    for (; step < 12; ++step) {
        for (std::uint32_t b = 1; b <= 5; ++b) w.move(b, pose{1.0 + 2 * (b - 1), 9.0 - step, 0});
        const std::vector<body_pair>& contacts = w.step();  // sorted pairs, first < second
        for (const contact_event& e : w.events()) begun += e.begins;
        if (floor_touch < 0 && !contacts.empty() && contacts.front().first == 0) floor_touch = step;
        if (contacts.size() == 4 + 5) break;  // side by side, every square on the floor
    }
    // The squares touch each other from the start (shared sides, 4 pairs);
    // the outer two touch the trough's inner walls from step 3 (their
    // bottoms at y = 6, the walls' tops), and all five its bottom at step 8.

    // A layer: a 3 x 3 grid of unit squares sharing sides and corners.
    std::vector<polygon> layer;
    for (int i = 0; i < 9; ++i) {
        const double x = i % 3, y = i / 3;
        layer.push_back(polygon({ring_input{{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}}}));
    }
    const std::vector<body_pair> pairs = certified_layer_pairs(layer);    // every pair that meets
    const std::vector<body_pair> near = layer_pairs<double>(layer, 1.2);  // every pair within 1.2

    std::printf(
        "the floor touched at step %d, %zu contacts at step %d (%zu begun); layer: %zu pairs meet, %zu "
        "within 1.2\n",
        floor_touch, w.contacts().size(), step, begun, pairs.size(), near.size());
    return floor_touch == 3 && step == 8 && w.contacts().size() == 9 && pairs.size() == 20 && near.size() == 34 ? 0 : 1;
}
