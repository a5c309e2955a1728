// SPDX-License-Identifier: BSL-1.0
// Witness pairs: with detector_options::witness the detector also reports
// which edges are in contact, as (static edge, moving edge) pairs. Edges are
// numbered in the input order of the vertices, ring after ring: edge k goes
// from vertex k to vertex k + 1 (the last one back to vertex 0), whatever
// orientation the library stores the ring in.
#include <cstdio>
#include <vector>

#include <influence2d/influence2d.hpp>

using namespace influence2d;

/// The input vertices, kept by the caller to name the edges.
const std::vector<point<double>> room_input{{0, 0}, {0, 4}, {4, 4}, {4, 0}};  // clockwise: stored reversed
const std::vector<point<double>> wedge_input{{0, 0}, {2, 0}, {0, 2}};

void print_edge(const char* what, const std::vector<point<double>>& ring, std::size_t k) {
    const point<double>& a = ring[k];
    const point<double>& b = ring[(k + 1) % ring.size()];
    std::printf("%s edge %zu: (%g, %g) -> (%g, %g)", what, k, a.x, a.y, b.x, b.y);
}

std::vector<edge_pair> report(detector<double>& d, const pose& q) {
    const frame_result r = d.collide(q);
    std::printf("pose (%g, %g, %g): collides = %d, %zu pair(s)\n", q.tx, q.ty, q.theta, r.collides ? 1 : 0,
                r.pairs.size());
    for (const edge_pair& p : r.pairs) {
        std::printf("  ");
        print_edge("static", room_input, p.static_edge);
        std::printf("  meets  ");
        print_edge("moving", wedge_input, p.moving_edge);
        std::printf("\n");
    }
    return r.pairs;
}

int main() {
    const polygon room({ring_input{room_input, ring_role::outer}});
    const polygon wedge({ring_input{wedge_input, ring_role::outer}});
    detector_options options;
    options.witness = true;
    detector<double> d(room, wedge, options);

    // The wedge pokes through the room's right side (input edge 2, from (4, 4)
    // to (4, 0)): its edges 0 and 1 cross it; edge 2 lies inside the room and
    // touches nothing.
    const std::vector<edge_pair> crossing = report(d, pose{3.5, 1, 0});
    // Turned by -0.5 rad and moved so that only its vertex 0 touches that side
    // at (4, 1): both edges at that vertex (0 and 2) are in contact.
    const std::vector<edge_pair> corner = report(d, pose{4, 1, -0.5});
    // Far away: no collision, no pairs.
    const std::vector<edge_pair> apart = report(d, pose{8, 1, 0});

    const bool ok = crossing == std::vector<edge_pair>{{2, 0}, {2, 1}} &&
                    corner == std::vector<edge_pair>{{2, 0}, {2, 2}} && apart.empty();
    std::printf("%s\n", ok ? "witness pairs as expected" : "unexpected witness pairs");
    return ok ? 0 : 1;
}
