// SPDX-License-Identifier: BSL-1.0
// An adapter from outside the library: polygons from std::array points
// (<influence2d/adapters/traits.hpp>), a closed ring and an open one.
#include <array>
#include <cstdio>
#include <vector>

#include <influence2d/adapters/traits.hpp>
#include <influence2d/influence2d.hpp>

int main() {
    using xy = std::array<double, 2>;
    const influence2d::polygon a = influence2d::make_polygon(std::vector<xy>{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}});
    const influence2d::polygon b = influence2d::make_polygon(std::vector<xy>{{0, 0}, {1, 0}, {0, 1}});
    influence2d::detector<double> d(a, b);
    const bool touching = d.collide(influence2d::pose{4, 1, 0}).collides;  // B's corner on A's right side
    std::printf("adapters: %zu and %zu vertices, touching = %d\n", a.size(), b.size(), touching ? 1 : 0);
    return a.size() == 4 && b.size() == 3 && touching ? 0 : 1;
}
