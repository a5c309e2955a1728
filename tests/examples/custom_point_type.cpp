// SPDX-License-Identifier: BSL-1.0
// Your own point type: specialise influence2d::point_traits for it, then build
// polygons from any range of it with make_polygon (influence2d/adapters/).
#include <cstdio>
#include <vector>

#include <influence2d/adapters/traits.hpp>
#include <influence2d/influence2d.hpp>

// A game engine's vector, with its own field names and float coordinates.
struct vec2 {
    float u;
    float v;
};

// How the library reads it. Every float is a double, so nothing is rounded;
// a type whose coordinates might not be doubles should throw
// influence2d::invalid_input (influence2d::coordinate_to_double does).
template <>
struct influence2d::point_traits<vec2> {
    static double x(const vec2& p) { return p.u; }
    static double y(const vec2& p) { return p.v; }
};

int main() {
    using namespace influence2d;
    // A courtyard with a pond: rings may come closed (first point repeated)
    // or open, in either orientation.
    const std::vector<vec2> yard{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}};
    const std::vector<std::vector<vec2>> ponds{{{3, 3}, {3, 7}, {7, 7}, {7, 3}}};
    const polygon courtyard = make_polygon(yard, ponds);
    const polygon boat = make_polygon(std::vector<vec2>{{-1, -0.5f}, {1, -0.5f}, {1.5f, 0}, {1, 0.5f}, {-1, 0.5f}});

    detector<double> d(courtyard, boat);
    // The boat in the middle of the pond floats free; moved towards its bank
    // it runs aground (touching counts).
    int aground = -1;
    for (int step = 0; step <= 20; ++step) {
        const pose q{5 + step / 8.0, 5, 0};  // the bow reaches x = 7 at step 4
        if (d.collide(q).collides) {
            aground = step;
            break;
        }
    }
    std::printf("%zu rings, %zu vertices; the boat runs aground at step %d\n", courtyard.ring_count(), courtyard.size(),
                aground);

    // A ring the polygon cannot take (two distinct points) is refused, named.
    try {
        make_polygon(std::vector<vec2>{{0, 0}, {1, 0}, {1, 0}});
    } catch (const invalid_input& e) {
        std::printf("refused: %s\n", e.what());
    }
    return aground == 4 ? 0 : 1;
}
