// SPDX-License-Identifier: BSL-1.0
// Small cases with known answers for the exact reference (verification/cgal_reference.hpp).
// Edge numbers are input numbers: edge k runs from input vertex k to vertex k+1.
// The unit square used below is input counter-clockwise:
//
//    3 (0,1) ---- 2 ---- (1,1) 2        vertices 0..3 at the corners,
//       |                  |            edge 0 bottom, 1 right,
//       3                  1            2 top, 3 left
//       |                  |
//    0 (0,0) ---- 0 ---- (1,0) 1

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "verification/cgal_reference.hpp"

namespace {

using influence2d::edge_pair;
using influence2d::frame_result;
using influence2d::point;
using influence2d::polygon;
using influence2d::pose;
using influence2d::ring_input;
using influence2d::ring_role;
using influence2d::verification::cgal_reference;

using pts = std::vector<point<double>>;

ring_input role_ring(pts vs, ring_role role = ring_role::outer) { return ring_input{std::move(vs), role}; }

/// Axis-parallel rectangle, input counter-clockwise from (x0, y0).
pts rect(double x0, double y0, double x1, double y1) { return pts{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

polygon unit_square() { return polygon({role_ring(rect(0, 0, 1, 1))}); }

frame_result run(const polygon& A, const polygon& B, pose p, double d = 0) {
    return cgal_reference(A, B, d, true).collide(p);
}

std::vector<edge_pair> pairs(std::vector<edge_pair> v) { return v; }

}  // namespace

TEST_CASE("reference: unit squares apart do not collide", "[reference]") {
    //  +--+  +--+
    //  |A |  |B |   B at tx = 2: gap 1
    //  +--+  +--+
    const auto r = run(unit_square(), unit_square(), pose{2, 0, 0});
    CHECK_FALSE(r.collides);
    CHECK(r.pairs.empty());
    // Without witnesses, the same answer.
    CHECK_FALSE(cgal_reference(unit_square(), unit_square()).collide(pose{2, 0, 0}).collides);
}

TEST_CASE("reference: squares touching at one vertex collide", "[reference]") {
    //        +--+
    //        |B |
    //     +--*--+    A's corner (1,1) is B's corner (0,0)
    //     |A |
    //     +--+
    const auto r = run(unit_square(), unit_square(), pose{1, 1, 0});
    CHECK(r.collides);
    CHECK(r.pairs == pairs({{1, 0}, {1, 3}, {2, 0}, {2, 3}}));
    // A hair further along the diagonal: apart.
    CHECK_FALSE(run(unit_square(), unit_square(), pose{1, 1 + std::ldexp(1.0, -30), 0}).collides);
}

TEST_CASE("reference: squares touching along an edge collide", "[reference]") {
    //     +--+--+
    //     |A |B |   A's right edge lies on B's left edge
    //     +--+--+
    const auto r = run(unit_square(), unit_square(), pose{1, 0, 0});
    CHECK(r.collides);
    // A edge 0 and 2 meet B at the shared corners, A edge 1 meets B edges 0, 2, 3.
    CHECK(r.pairs == pairs({{0, 0}, {0, 3}, {1, 0}, {1, 2}, {1, 3}, {2, 2}, {2, 3}}));
    CHECK_FALSE(run(unit_square(), unit_square(), pose{1 + std::ldexp(1.0, -20), 0, 0}).collides);
}

TEST_CASE("reference: overlapping squares collide with crossing pairs", "[reference]") {
    //        +----+
    //     +--|-+  |   B at (0.5, 0.5)
    //     |A +-|--+
    //     +----+
    const auto r = run(unit_square(), unit_square(), pose{0.5, 0.5, 0});
    CHECK(r.collides);
    // A's right edge crosses B's bottom edge, A's top edge crosses B's left edge.
    CHECK(r.pairs == pairs({{1, 0}, {2, 3}}));
}

TEST_CASE("reference: containment both ways collides without pairs", "[reference]") {
    //  +----------+
    //  |  A  +-+  |   B (unit) strictly inside A (10 x 10)
    //  |     |B|  |
    //  |     +-+  |
    //  +----------+
    const polygon big({role_ring(rect(0, 0, 10, 10))});
    const auto inside = run(big, unit_square(), pose{4, 4, 0});
    CHECK(inside.collides);
    CHECK(inside.pairs.empty());
    // A inside B: the roles swapped.
    const auto around = run(unit_square(), big, pose{-4, -4, 0});
    CHECK(around.collides);
    CHECK(around.pairs.empty());
    // And with a distance: still a collision, still no pair.
    const auto inside_d = run(big, unit_square(), pose{4, 4, 0}, 0.5);
    CHECK(inside_d.collides);
    CHECK(inside_d.pairs.empty());
    // Control: B outside the big square, 1 away from its right side.
    CHECK_FALSE(run(big, unit_square(), pose{11, 4, 0}).collides);
}

TEST_CASE("reference: B inside a hole of A does not collide", "[reference]") {
    //  +-----------+
    //  | A +-----+ |   hole [3,7]^2, B at (4.5, 4.5)
    //  |   | +-+ | |
    //  |   | |B| | |
    //  |   | +-+ | |
    //  |   +-----+ |
    //  +-----------+
    const polygon holed({role_ring(rect(0, 0, 10, 10)), role_ring(rect(3, 3, 7, 7), ring_role::hole)});
    const auto r = run(holed, unit_square(), pose{4.5, 4.5, 0});
    CHECK_FALSE(r.collides);
    CHECK(r.pairs.empty());
    // Within distance 1.5 of the hole boundary it does.
    CHECK(run(holed, unit_square(), pose{4.5, 4.5, 0}, 1.5).collides);
    CHECK_FALSE(run(holed, unit_square(), pose{4.5, 4.5, 0}, 1.25).collides);
    // The hole written clockwise (as stored) changes nothing.
    pts cw = rect(3, 3, 7, 7);
    std::reverse(cw.begin(), cw.end());
    const polygon holed_cw({role_ring(rect(0, 0, 10, 10)), role_ring(cw, ring_role::hole)});
    CHECK_FALSE(run(holed_cw, unit_square(), pose{4.5, 4.5, 0}).collides);
    // B inside the ring part (between outer ring and hole): collides, no pair.
    const auto in_band = run(holed, unit_square(), pose{1, 1, 0});
    CHECK(in_band.collides);
    CHECK(in_band.pairs.empty());
}

TEST_CASE("reference: B touching the hole boundary collides", "[reference]") {
    //  +-----------+
    //  | A +-----+ |   B's left edge on the hole's left side x = 3
    //  |   |     | |
    //  |   |+-+  | |
    //  |   ||B|  | |
    //  |   |+-+  | |
    //  |   +-----+ |
    //  +-----------+
    const polygon holed({role_ring(rect(0, 0, 10, 10)), role_ring(rect(3, 3, 7, 7), ring_role::hole)});
    const auto r = run(holed, unit_square(), pose{3, 4.5, 0});
    CHECK(r.collides);
    // The hole's left side is the polygon's input edge 7 ((3,7) to (3,3), the
    // hole's last edge, stored reversed); it meets B's left edge 3 along its
    // length and B's bottom and top edges at their ends.
    CHECK(r.pairs == pairs({{7, 0}, {7, 2}, {7, 3}}));
    CHECK_FALSE(run(holed, unit_square(), pose{3 + std::ldexp(1.0, -20), 4.5, 0}).collides);
}

TEST_CASE("reference: distance exactly d collides, a hair less does not", "[reference]") {
    //  +--+        +--+
    //  |A | <0.75> |B |   gap 0.75 along x
    //  +--+        +--+
    const double eps = std::ldexp(1.0, -20);
    const auto side = run(unit_square(), unit_square(), pose{1.75, 0, 0}, 0.75);
    CHECK(side.collides);
    // The same pairs as for touching along the edge, now at distance 0.75.
    CHECK(side.pairs == pairs({{0, 0}, {0, 3}, {1, 0}, {1, 2}, {1, 3}, {2, 2}, {2, 3}}));
    CHECK_FALSE(run(unit_square(), unit_square(), pose{1.75, 0, 0}, 0.75 - eps).collides);
    //                 +--+
    //                 |B |    B's corner (1.75, 2), A's corner (1, 1):
    //                 +--+    distance sqrt(0.75^2 + 1^2) = 1.25 exactly
    //  +--+
    //  |A |
    //  +--+
    const auto corner = run(unit_square(), unit_square(), pose{1.75, 2, 0}, 1.25);
    CHECK(corner.collides);
    CHECK(corner.pairs == pairs({{1, 0}, {1, 3}, {2, 0}, {2, 3}}));
    CHECK_FALSE(run(unit_square(), unit_square(), pose{1.75, 2, 0}, 1.25 - eps).collides);
}

TEST_CASE("reference: a rotated pose is evaluated exactly", "[reference]") {
    // theta = pi/2: c = cos(theta) is the double 6.1e-17, s = 1. B's vertex
    // (0,1) goes to (-s + tx, c) = (1, 6.1e-17) for tx = 2: exactly on A's
    // right edge, just above A's corner (1,0).
    //
    //     +--+--+
    //     |A |B |    B rotated a quarter turn about its origin, then moved to x = 2
    //     +--*--+    (B's corners move by about c: its vertex (0,1) lands at *, c above A's corner)
    const double half_pi = std::acos(-1.0) / 2;
    const auto r = run(unit_square(), unit_square(), pose{2, 0, half_pi});
    CHECK(r.collides);
    CHECK(r.pairs == pairs({{1, 2}, {1, 3}}));
    CHECK_FALSE(run(unit_square(), unit_square(), pose{2 + std::ldexp(1.0, -40), 0, half_pi}).collides);
    // theta = pi/4: B is a diamond standing on its vertex (0,0), posed exactly at (tx, ty).
    //        /\ B
    //        \/        B's bottom vertex on A's top edge
    //     +--*--+
    //     |  A  |
    const double quarter_pi = std::acos(-1.0) / 4;
    const polygon wide({role_ring(rect(0, 0, 2, 1))});
    const auto diamond = run(wide, unit_square(), pose{1, 1, quarter_pi});
    CHECK(diamond.collides);
    CHECK(diamond.pairs == pairs({{2, 0}, {2, 3}}));
    CHECK_FALSE(run(wide, unit_square(), pose{1, 1 + std::ldexp(1.0, -30), quarter_pi}).collides);
}

TEST_CASE("reference: input numbering of a clockwise ring and a repeated vertex", "[reference]") {
    // A given clockwise: (0,0) (0,1) (1,1) (1,0); its edges at the corner
    // (1,0) are input edges 2 and 3. B's corner (0,1) touches it.
    //     +--+
    //     |A |
    //     +--*--+
    //        |B |
    //        +--+
    const polygon cw({role_ring(pts{{0, 0}, {0, 1}, {1, 1}, {1, 0}})});
    const auto r = run(cw, unit_square(), pose{1, -1, 0});
    CHECK(r.collides);
    CHECK(r.pairs == pairs({{2, 2}, {2, 3}, {3, 2}, {3, 3}}));
    // A with the corner (1,1) repeated: input edge 2 has zero length and is
    // tested as a point; B's corner (0,0) touches it.
    const polygon rep({role_ring(pts{{0, 0}, {1, 0}, {1, 1}, {1, 1}, {0, 1}})});
    const auto t = run(rep, unit_square(), pose{1, 1, 0});
    CHECK(t.collides);
    CHECK(t.pairs == pairs({{1, 0}, {1, 3}, {2, 0}, {2, 3}, {3, 0}, {3, 3}}));
    // With a distance the point edge is measured as a point.
    const auto td = run(rep, unit_square(), pose{1.75, 2, 0}, 1.25);
    CHECK(td.pairs == pairs({{1, 0}, {1, 3}, {2, 0}, {2, 3}, {3, 0}, {3, 3}}));
}

TEST_CASE("reference: every part of a multipolygon is located in the other polygon", "[reference][multipolygon]") {
    //  +-----+
    //  | +-+ |        +-+       A: two unit squares, at x = 0 and x = 10
    //  | |A| |   ...  |A|       B: the square [-1, 2]^2, posed by a translation
    //  | +-+ |        +-+
    //  +-----+
    // B swallows one part of A without touching any edge: A's box does not
    // fit in B's, but that part does.
    const polygon A({role_ring(rect(0, 0, 1, 1)), role_ring(rect(10, 0, 11, 1))});
    const polygon B({role_ring(rect(-1, -1, 2, 2))});
    CHECK(run(A, B, pose{0, 0, 0}).collides);
    CHECK(run(A, B, pose{9.5, 0, 0}).collides);
    CHECK_FALSE(run(A, B, pose{5, 0, 0}).collides);
    // Roles swapped: the first or the second part of the moving polygon lies in A.
    CHECK(run(B, A, pose{0, 0, 0}).collides);
    CHECK(run(B, A, pose{-9.5, 0, 0}).collides);
    CHECK_FALSE(run(B, A, pose{-5, 0, 0}).collides);
}

TEST_CASE("reference: regions by winding number, a hole outside its shell and nested shells", "[reference][region]") {
    // A hole lying outside every outer ring has winding number -1 there: the
    // library counts it as region (a count by nesting depth would not).
    //   +--+
    //   |  |   [4,5]^2 given as a hole     outer [0,1]^2
    //   +--+
    const polygon stray({role_ring(rect(0, 0, 1, 1)), role_ring(rect(4, 4, 5, 5), ring_role::hole)});
    const polygon dot({role_ring(rect(0, 0, 0.25, 0.25))});
    CHECK(run(stray, dot, pose{4.5, 4.5, 0}).collides);  // inside the stray hole
    CHECK_FALSE(run(stray, dot, pose{2.5, 2.5, 0}).collides);
    CHECK(run(dot, stray, pose{-4.5, -4.5, 0}).collides);  // roles swapped: the stray hole holds A
    // Nested outer rings: winding 2 inside the inner one, 1 between: all region.
    const polygon nested({role_ring(rect(0, 0, 10, 10)), role_ring(rect(3, 3, 7, 7))});
    CHECK(run(nested, dot, pose{1, 1, 0}).collides);
    CHECK(run(nested, dot, pose{5, 5, 0}).collides);
    // A hole inside an inner shell: winding 2 - 1 = 1, still region.
    const polygon shell_hole(
        {role_ring(rect(0, 0, 10, 10)), role_ring(rect(3, 3, 7, 7)), role_ring(rect(4, 4, 6, 6), ring_role::hole)});
    CHECK(run(shell_hole, dot, pose{4.9, 4.9, 0}).collides);
    // An island inside a hole: region again; the hole around it is not.
    const polygon island(
        {role_ring(rect(0, 0, 10, 10)), role_ring(rect(2, 2, 8, 8), ring_role::hole), role_ring(rect(4, 4, 6, 6))});
    CHECK(run(island, dot, pose{4.9, 4.9, 0}).collides);
    CHECK_FALSE(run(island, dot, pose{2.5, 2.5, 0}).collides);
}

TEST_CASE("reference: a figure eight bounds both lobes", "[reference][region]") {
    //  (0,0) ---- (2,2)      the ring (0,0) (2,2) (2,0) (0,2) crosses itself at
    //     \  /               (1,1): winding +1 in one lobe, -1 in the other;
    //      \/                both are region.
    //      /\.
    const polygon bowtie({role_ring(pts{{0, 0}, {2, 2}, {2, 0}, {0, 2}})});
    const polygon dot({role_ring(rect(0, 0, 0.1, 0.1))});
    CHECK(run(bowtie, dot, pose{0.15, 0.95, 0}).collides);        // left lobe
    CHECK(run(bowtie, dot, pose{1.75, 0.95, 0}).collides);        // right lobe
    CHECK_FALSE(run(bowtie, dot, pose{0.95, 0.15, 0}).collides);  // below the crossing
}
