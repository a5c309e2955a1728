// SPDX-License-Identifier: BSL-1.0
// A's edge tree: the edges near a segment are all visited, whatever the
// segment; the line test that prunes boxes holds exactly.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "influence2d/influence/edge_grid.hpp"
#include "influence2d/influence/edge_tree.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/segments.hpp"
#include "support/effort.hpp"
#include "support/random.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

namespace {

/// A star-shaped ring of n vertices at random radii in [0.3, 1] x scale around (cx, cy).
polygon random_star(test_random::rng& rng, std::size_t n, double scale, double cx, double cy) {
    std::vector<point<double>> v;
    for (std::size_t k = 0; k < n; ++k) {
        const double phi = 2 * std::acos(-1.0) * static_cast<double>(k) / static_cast<double>(n);
        const double r = rng.uniform(0.3, 1.0) * scale;
        v.push_back({cx + r * std::cos(phi), cy + r * std::sin(phi)});
    }
    return polygon({test_shapes::ring(v)});
}

/// Whether the segments [a, b] and [u, v] lie within g of each other:
/// exactly when they meet, else by the four end-to-segment distances in
/// double (the test leaves a relative margin for their rounding).
bool within(const point<double>& a, const point<double>& b, const point<double>& u, const point<double>& v, double g) {
    const auto ex = [](const point<double>& p) {
        return point<exact_rational>{exact_rational(p.x), exact_rational(p.y)};
    };
    if (segments_intersect(ex(a), ex(b), ex(u), ex(v))) return true;
    const double d = std::min(
        {segment_distance(a, u, v), segment_distance(b, u, v), segment_distance(u, a, b), segment_distance(v, a, b)});
    return d <= g * (1 - 1e-9);
}

std::vector<std::uint32_t> visited(const edge_tree& tree, const point<double>& u, const point<double>& v, double g) {
    std::vector<std::uint32_t> out;
    const bool stopped = tree.query(u, v, g, g, [&](std::uint32_t e) {
        out.push_back(e);
        return false;
    });
    CHECK_FALSE(stopped);
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST_CASE("edge tree: every edge within the reach of a segment is visited, once", "[tree]") {
    test_random::rng rng(11);
    const auto unit = [&] { return rng.uniform(-1.5, 1.5); };
    const auto share = [&] { return rng.unit(); };
    const int shapes = 12;  // not scaled by the test effort: the counts below need them all
    std::size_t near_total = 0, visited_total = 0;
    for (int s = 0; s < shapes; ++s) {
        const std::size_t n = std::size_t{3} << (s % 9);  // 3 to 768 edges
        const polygon p = s % 4 == 3 ? test_shapes::square_with_hole() : random_star(rng, n, 1.0, 0.25, -0.5);
        const edge_tree tree(p);
        const double span = s % 4 == 3 ? 8 : 1;
        for (int k = 0; k < 300; ++k) {
            point<double> u{0.25 + span * unit(), -0.5 + span * unit()};
            // Long, short and degenerate segments.
            const double len = k % 10 == 0 ? 0 : span * std::pow(share(), 3);
            const double phi = 7 * share();
            const point<double> v{u.x + len * std::cos(phi), u.y + len * std::sin(phi)};
            const double g = k % 3 == 0 ? 0 : span * 0.05 * share();
            const std::vector<std::uint32_t> got = visited(tree, u, v, g);
            CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());  // each edge at most once
            for (std::size_t e = 0; e < p.size(); ++e) {
                if (!within(p.vertex(e), p.vertex(p.next(e)), u, v, g)) continue;
                ++near_total;
                INFO("shape " << s << " edge " << e << " segment (" << u.x << ", " << u.y << ") (" << v.x << ", " << v.y
                              << ") g " << g);
                CHECK(std::binary_search(got.begin(), got.end(), static_cast<std::uint32_t>(e)));
            }
            visited_total += got.size();
        }
    }
    // The cases are not vacuous, and the tree prunes: it visits far fewer
    // than all edges.
    CHECK(near_total > 1000);
    CHECK(visited_total < 4 * near_total);
}

TEST_CASE("edge tree: stopping, empty trees and coordinates that are not finite", "[tree]") {
    const polygon c = test_shapes::c_shape();
    const edge_tree tree(c);
    CHECK(tree.node_count() > 1);
    std::size_t calls = 0;
    // A segment across the whole shape: the first edge visited stops the query.
    CHECK(tree.query({-100, -100}, {100, 100}, 1, 1, [&](std::uint32_t) { return ++calls == 1; }));
    CHECK(calls == 1);
    // Far away: nothing.
    calls = 0;
    CHECK_FALSE(tree.query({1000, 1000}, {1001, 1000}, 1, 1, [&](std::uint32_t) { return ++calls, false; }));
    CHECK(calls == 0);
    // Not finite: every edge, since nothing can be pruned.
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    for (const point<double> bad : {point<double>{inf, 0}, point<double>{nan, 1}, point<double>{0, -inf}}) {
        std::vector<std::uint32_t> got;
        CHECK_FALSE(tree.query(bad, {1000, 1000}, 1, 1, [&](std::uint32_t e) { return got.push_back(e), false; }));
        CHECK(got.size() == c.size());
    }
    CHECK_FALSE(edge_tree().query({0, 0}, {1, 1}, 1, 1, [](std::uint32_t) { return true; }));
    CHECK(edge_tree().node_count() == 0);
}

TEST_CASE("edge tree: a box beyond a line is so exactly", "[tree]") {
    // Nearly degenerate cases: lines through or grazing a box's corner, long
    // lines at scales from 1e-200 to 1e200; whenever the test says beyond,
    // each corner is farther than g from the line, on one side, exactly.
    test_random::rng rng(23);
    const auto unit = [&] { return rng.signed_unit(); };
    int beyond = 0, not_beyond = 0;
    const int cases = test_effort::scaled(20000);
    for (int k = 0; k < cases; ++k) {
        const double scale = std::ldexp(1.0, static_cast<int>(rng.index(1300)) - 650);
        box b;
        b.add({unit() * scale, unit() * scale});
        b.add({unit() * scale, unit() * scale});
        point<double> u{unit() * scale, unit() * scale};
        point<double> v{unit() * scale, unit() * scale};
        if (k % 3 == 0) v = {b.max_x + (b.max_x - u.x) * std::ldexp(1.0, -50) * unit(), b.min_y};  // grazing
        const double g = k % 2 == 0 ? 0 : std::fabs(unit()) * scale * 1e-3;
        if (box_may_be_near_line(b, u, v, g)) {
            ++not_beyond;
            continue;
        }
        ++beyond;
        using Q = exact_rational;
        const Q dx = Q(v.x) - Q(u.x), dy = Q(v.y) - Q(u.y), g2 = Q(g) * Q(g) * (dx * dx + dy * dy);
        int side = 0;
        for (double x : {b.min_x, b.max_x})
            for (double y : {b.min_y, b.max_y}) {
                const Q o = dx * (Q(y) - Q(u.y)) - dy * (Q(x) - Q(u.x));
                INFO("case " << k);
                CHECK(o * o > g2);  // distance o / |d| > g
                const int s = o > Q(0) ? 1 : -1;
                CHECK((side == 0 || s == side));
                side = s;
            }
    }
    CHECK(beyond > cases / 10);
    CHECK(not_beyond > cases / 10);
}
