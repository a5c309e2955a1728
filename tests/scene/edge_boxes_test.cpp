// SPDX-License-Identifier: BSL-1.0
// The edge pairs offered to the one-shot tests (scene/edge_boxes.hpp): the
// sort and sweep of whole edge lists (edges_meeting, overlapping_pairs) and
// the sweep of runs first (overlapping_run_pairs) offer exactly the pairs a
// double loop over every edge pair finds, each once, on random
// multipolygons of many runs at random offsets, and stop at the first pair
// accepted.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/random_scenes.hpp"

#include <algorithm>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "influence2d/scene/edge_boxes.hpp"

namespace {

using namespace influence2d;
using test_scenes::rng;
using index_pair = std::pair<std::uint32_t, std::uint32_t>;

/// The box of edge e of the polygon whose vertices are v, grown by `grow`.
box grown_edge(const polygon& p, const std::vector<point<double>>& v, std::size_t e, double grow) {
    box b;
    b.add(v[e]);
    b.add(v[p.next(e)]);
    return b.inflated(grow);
}

bool boxes_meet(const box& l, const box& r) {
    return !(l.max_x < r.min_x || r.max_x < l.min_x || l.max_y < r.min_y || r.max_y < l.min_y);
}

/// The polygon's vertices moved by (dx, dy).
std::vector<point<double>> moved(const polygon& p, double dx, double dy) {
    std::vector<point<double>> out;
    for (const point<double>& q : p.vertices()) out.push_back({q.x + dx, q.y + dy});
    return out;
}

/// The pairs of A's edges and B's edges whose boxes, grown, meet each other
/// and their windows: a double loop over every pair.
std::set<index_pair> pairs_by_double_loop(const polygon& a, const std::vector<point<double>>& av, const polygon& b,
                                          const std::vector<point<double>>& bv, const box& a_window,
                                          const box& b_window, double grow) {
    std::set<index_pair> want;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) {
            const box bi = grown_edge(a, av, i, grow), bj = grown_edge(b, bv, j, grow);
            if (boxes_meet(bi, a_window) && boxes_meet(bj, b_window) && boxes_meet(bi, bj))
                want.insert({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        }
    return want;
}

/// Checks that search(meet) offers meet each pair of `want` once and no
/// other, and that the pair meet accepts ends the search (a pair of `want`
/// drawn by g); returns whether a search was stopped so.
template <class Search>
bool offers_exactly(Search&& search, const std::set<index_pair>& want, rng& g) {
    std::multiset<index_pair> got;
    CHECK_FALSE(search([&](std::uint32_t i, std::uint32_t j) {
        got.insert({i, j});
        return false;
    }));
    CHECK(std::set<index_pair>(got.begin(), got.end()) == want);
    CHECK(got.size() == want.size());
    if (want.empty()) return false;
    const index_pair target = *std::next(want.begin(), static_cast<std::ptrdiff_t>(g.index(want.size())));
    std::size_t calls = 0;
    bool seen_after = false, found = false;
    CHECK(search([&](std::uint32_t i, std::uint32_t j) {
        seen_after = seen_after || found;
        ++calls;
        found = found || index_pair{i, j} == target;
        return index_pair{i, j} == target;
    }));
    CHECK(found);
    CHECK_FALSE(seen_after);
    CHECK(calls <= want.size());
    return true;
}

}  // namespace

TEST_CASE("edge boxes: the pairs offered are those of a double loop, once each", "[scene]") {
    rng g(900);
    std::size_t offered = 0, runs_seen = 0;
    for (int round = 0; round < test_effort::scaled(60); ++round) {
        const polygon a = test_scenes::random_multi(g, 8, 24).to_polygon();
        const polygon b = test_scenes::random_multi(g, 8, 24).to_polygon();
        const std::vector<point<double>> av = moved(a, 0, 0), bv = moved(b, g.uniform(-6, 6), g.uniform(-6, 6));
        const double grow = round % 3 == 0 ? 0 : g.uniform(0, 0.3);
        box a_bounds, b_bounds;
        for (const point<double>& v : av) a_bounds.add(v);
        for (const point<double>& v : bv) b_bounds.add(v);
        // As the one-shot tests ask: A's edges near B's box, B's near A's.
        const box a_window = b_bounds.inflated(grow), b_window = a_bounds.inflated(grow);
        const std::set<index_pair> want = pairs_by_double_loop(a, av, b, bv, a_window, b_window, grow);
        offered += want.size();
        INFO("round " << round << ": " << a.size() << " x " << b.size() << " edges");

        std::vector<box> a_runs, b_runs;
        edge_run_boxes(a, av, a_runs);
        edge_run_boxes(b, bv, b_runs);
        runs_seen += a_runs.size() + b_runs.size();
        offers_exactly(
            [&](auto&& meet) {
                return overlapping_run_pairs({a, av, a_runs, a_window}, {b, bv, b_runs, b_window}, grow, meet);
            },
            want, g);

        std::vector<edge_box> a_edges, b_edges;
        edges_meeting(a, av, a_window, grow, a_edges);
        edges_meeting(b, bv, b_window, grow, b_edges);
        std::multiset<index_pair> by_lists;
        CHECK_FALSE(overlapping_pairs(a_edges, b_edges, [&](std::uint32_t i, std::uint32_t j) {
            by_lists.insert({i, j});
            return false;
        }));
        CHECK(std::set<index_pair>(by_lists.begin(), by_lists.end()) == want);
        CHECK(by_lists.size() == want.size());
    }
    // Not vacuous: many pairs, polygons of several runs.
    CHECK(offered > 1000);
    CHECK(runs_seen > 200);
}

TEST_CASE("edge boxes: two polygons of one run each, the pairs of a double loop, once each", "[scene]") {
    // few_edge_pairs: two small polygons (at most edge_run_length edges, one
    // or two rings, close together or apart), against the double loop, and
    // the first pair accepted ends the search.
    rng g(901);
    std::size_t offered = 0, stopped_runs = 0;
    for (int round = 0; round < test_effort::scaled(400); ++round) {
        const auto small = [&](point<double> c) {
            std::vector<ring_input> rings;
            const std::size_t k = 4 + g.index(edge_run_length - 3);
            rings.push_back({test_scenes::star(g, c, 0.5, 2, k), ring_role::outer});
            if (k <= edge_run_length - 4 && g.index(3) == 0)
                rings.push_back({test_scenes::star(g, c, 0.1, 0.3, 4), ring_role::hole});
            return polygon(rings);
        };
        const polygon a = small({0, 0}), b = small({g.uniform(-4, 4), g.uniform(-4, 4)});
        REQUIRE(a.size() <= edge_run_length);
        REQUIRE(b.size() <= edge_run_length);
        const std::vector<point<double>> av = moved(a, 0, 0), bv = moved(b, 0, 0);
        const double grow = round % 3 == 0 ? 0 : g.uniform(0, 0.3);
        box a_bounds, b_bounds;
        for (const point<double>& v : av) a_bounds.add(v);
        for (const point<double>& v : bv) b_bounds.add(v);
        // The one-shot tests' windows (each the other polygon's box, grown),
        // or in odd rounds a random window each, which the pair tests alone
        // would not imply.
        box a_window = b_bounds.inflated(grow), b_window = a_bounds.inflated(grow);
        if (round % 2 == 1) {
            const auto random_window = [&] {
                const double x = g.uniform(-3, 3), y = g.uniform(-3, 3);
                return box{x, y, x + g.uniform(0, 3), y + g.uniform(0, 3)};
            };
            a_window = random_window();
            b_window = random_window();
        }
        const std::set<index_pair> want = pairs_by_double_loop(a, av, b, bv, a_window, b_window, grow);
        offered += want.size();
        INFO("round " << round << ": " << a.size() << " x " << b.size() << " edges");
        std::vector<box> a_runs, b_runs;
        edge_run_boxes(a, av, a_runs);
        edge_run_boxes(b, bv, b_runs);
        const runs_side as{a, av, a_runs, a_window}, bs{b, bv, b_runs, b_window};
        if (offers_exactly([&](auto&& meet) { return few_edge_pairs(as, bs, grow, meet); }, want, g)) ++stopped_runs;
    }
    // Not vacuous: many pairs offered, and many searches stopped.
    CHECK(offered > static_cast<std::size_t>(test_effort::scaled(500)));
    CHECK(stopped_runs > static_cast<std::size_t>(test_effort::scaled(50)));
}
