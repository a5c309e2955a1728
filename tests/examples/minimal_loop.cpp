// SPDX-License-Identifier: BSL-1.0
// The smallest useful program: a static polygon read from WKT text, a moving
// polygon built in code, a trajectory of poses, and the first frame at which
// the two collide.
#include <cstdio>

#include <influence2d/influence2d.hpp>
#include <influence2d/io/wkt.hpp>  // the WKT reader (needs Boost's headers)

int main() {
    using namespace influence2d;
    // An L-shaped room (WKT rings are closed: the first point comes again last).
    const polygon room = read_wkt("POLYGON((0 0, 10 0, 10 4, 4 4, 4 10, 0 10, 0 0))");
    // A crate of side 1 around its own origin: poses move that origin.
    const polygon crate({ring_input{{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}, ring_role::outer}});
    detector<double> d(room, crate);

    // The crate comes in from the right at height 7, a step of 1/8 per frame,
    // towards the room's upper arm (x <= 4). Touching counts as a collision:
    // its left side reaches x = 4 when its centre is at x = 4.5, frame 60.
    for (int frame = 0; frame <= 100; ++frame) {
        const pose q{12 - frame / 8.0, 7, 0};
        if (d.collide(q).collides) {
            std::printf("first collision at frame %d (crate at x = %g, y = %g)\n", frame, q.tx, q.ty);
            return 0;
        }
    }
    std::printf("no collision\n");
    return 1;
}
