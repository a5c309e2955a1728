// SPDX-License-Identifier: BSL-1.0
// Exact mode: the same loop as the README's example in exact rationals
// (CGAL), where "touching" means touching exactly: B slides along A's top
// side at heights 4 + 2^-k (k = 50..1, each a double) and at 4, and only the
// pose at height exactly 4 collides.
#include <cmath>
#include <cstdio>

#include <influence2d/influence2d.hpp>
#include <influence2d/number/cgal.hpp>

int main() {
    using namespace influence2d;
    const polygon a({ring_input{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
    const polygon b({ring_input{{{0, 0}, {1, 0}, {0, 1}}, ring_role::outer}});
    detector<exact_rational> d(a, b);
    int collisions = 0;
    for (int k = 50; k >= 0; --k) {                             // 4 + 2^-50 is the double after 4
        const double y = k == 0 ? 4 : 4 + std::ldexp(1.0, -k);  // 4 + 2^-k, then 4 itself
        if (d.collide(pose{2, y, 0}).collides) ++collisions;
    }
    std::printf("exact: %d collision(s), at height 4 only\n", collisions);
    return collisions == 1 ? 0 : 1;
}
