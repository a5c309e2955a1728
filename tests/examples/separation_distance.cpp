// SPDX-License-Identifier: BSL-1.0
// Separation distance: with detector_options::distance = d > 0 a frame
// "collides" when the two polygons come within d of each other, for a safety
// margin around an obstacle. With d = 0 only touching or overlapping counts.
#include <cstdio>

#include <influence2d/influence2d.hpp>

int main() {
    using namespace influence2d;
    const polygon wall({ring_input{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
    const polygon cart({ring_input{{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}, ring_role::outer}});

    detector_options margin;
    margin.distance = 0.5;  // warn when the cart comes within 0.5 of the wall
    detector<double> with_margin(wall, cart, margin);
    detector<double> without_margin(wall, cart);  // distance 0: intersection only

    // The cart drives left at height 2, a step of 1/4 per frame; the gap
    // between its left side and the wall's right side (x = 4) is
    // (8 - frame / 4 - 0.5) - 4, so it is within 0.5 from frame 12 on and
    // touches from frame 14 on.
    int within = 0, touching = 0, first_within = -1, first_touching = -1;
    for (int frame = 0; frame <= 16; ++frame) {
        const pose q{8 - frame / 4.0, 2, 0};
        const bool is_near = with_margin.collide(q).collides;
        const bool is_touching = without_margin.collide(q).collides;
        if (is_near && first_within < 0) first_within = frame;
        if (is_touching && first_touching < 0) first_touching = frame;
        within += is_near;
        touching += is_touching;
        if (is_near)
            std::printf("frame %2d: gap %.2f, within d = 0.5: yes, d = 0: %s\n", frame, q.tx - 0.5 - 4,
                        is_touching ? "yes" : "no");
    }
    std::printf("within 0.5 from frame %d, touching from frame %d\n", first_within, first_touching);
    // Frame 13 (gap 0.25) is a near miss: within the margin, not touching.
    return first_within == 12 && first_touching == 14 && within == 5 && touching == 3 ? 0 : 1;
}
