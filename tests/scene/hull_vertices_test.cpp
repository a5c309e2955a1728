// SPDX-License-Identifier: BSL-1.0
// The corners of a polygon's convex hull (scene/hull_vertices.hpp) against
// CGAL's convex_hull_2 on an exact kernel: the same points, counter-clockwise,
// on random multipolygons, swallowers, grids of collinear points and
// degenerate inputs.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <iterator>
#include <utility>
#include <vector>

#include "influence2d/scene/hull_vertices.hpp"

namespace {

using namespace influence2d;
using test_scenes::rng;
using kernel = CGAL::Exact_predicates_exact_constructions_kernel;

/// The hull's corners as coordinates, from the lowest-leftmost one on, in
/// their order.
std::vector<std::pair<double, double>> from_lowest(std::vector<std::pair<double, double>> v) {
    if (v.empty()) return v;
    const auto lowest = std::min_element(v.begin(), v.end(), [](const auto& l, const auto& r) {
        return l.second < r.second || (l.second == r.second && l.first < r.first);
    });
    std::rotate(v.begin(), lowest, v.end());
    return v;
}

/// CGAL's hull of p's vertices (extreme points only), counter-clockwise.
std::vector<std::pair<double, double>> cgal_hull(const polygon& p) {
    std::vector<kernel::Point_2> in, out;
    for (const point<double>& v : p.vertices()) in.emplace_back(v.x, v.y);
    CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(out), kernel());
    std::vector<std::pair<double, double>> h;
    for (const kernel::Point_2& q : out) h.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
    return from_lowest(h);
}

std::vector<std::pair<double, double>> ours(const polygon& p) {
    std::vector<std::pair<double, double>> h;
    for (std::uint32_t k : hull_vertices(p)) h.emplace_back(p.vertex(k).x, p.vertex(k).y);
    return from_lowest(h);
}

}  // namespace

TEST_CASE("hull_vertices: CGAL's convex hull, corner for corner", "[scene]") {
    rng g(2200);
    std::size_t corners = 0;
    const int rounds = test_effort::scaled(300);
    for (int round = 0; round < rounds; ++round) {
        const polygon p = round % 5 == 4 ? test_scenes::random_swallower(g).to_polygon()
                                         : test_scenes::random_multi(g, 1 + round % 40, 2 + round % 7).to_polygon();
        INFO("round " << round << ": " << p.size() << " vertices");
        const auto want = cgal_hull(p), got = ours(p);
        CHECK(got == want);
        corners += got.size();
    }
    CHECK(rounds > 0);
    CHECK(corners > 5 * static_cast<std::size_t>(rounds));  // not vacuous: ten or so a polygon
}

TEST_CASE("hull_vertices: collinear points, repeated corners and tiny polygons", "[scene]") {
    // A square with a vertex in the middle of each side: those are no corners.
    const polygon sides({test_shapes::ring({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}})});
    CHECK(ours(sides) == cgal_hull(sides));
    CHECK(hull_vertices(sides).size() == 4);
    // Two squares sharing a corner (the corner stored twice).
    const polygon pair({test_shapes::square_ring(0, 0, 1), test_shapes::square_ring(1, 1, 1)});
    CHECK(ours(pair) == cgal_hull(pair));
    CHECK(hull_vertices(pair).size() == 6);
    // Corners one unit in the last place off a line: exact turns.
    const double e = 0x1p-52;
    const polygon thin({test_shapes::ring({{0, 0}, {1, 1 + e}, {2, 2}, {1, 1 - e}})});
    CHECK(ours(thin) == cgal_hull(thin));
    CHECK(hull_vertices(thin).size() == 4);
    const polygon flat({test_shapes::ring({{0, 0}, {1, 1}, {2, 2}, {3, 3 + 4 * e}})});
    CHECK(ours(flat) == cgal_hull(flat));
}
