// SPDX-License-Identifier: BSL-1.0
// The usage example of the README, built and run by the tests.
#include <cstdio>

#include <influence2d/influence2d.hpp>

int main() {
    using namespace influence2d;
    const polygon a({ring_input{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
    const polygon b({ring_input{{{0, 0}, {1, 0}, {0, 1}}, ring_role::outer}});
    detector_options options;
    options.witness = true;                 // also report the edge pairs in contact
    detector<double> d(a, b, options);      // detector<exact_rational> with <influence2d/number/cgal.hpp>
    for (double x = 6; x >= 3; x -= 0.5) {  // B slides towards A, turned by 0.3 rad
        const frame_result r = d.collide(pose{x, 1, 0.3});
        std::printf("x = %.1f  collides = %d  pairs = %zu\n", x, r.collides ? 1 : 0, r.pairs.size());
    }
}
