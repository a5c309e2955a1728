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
        std::set<index_pair> want;
        for (std::size_t i = 0; i < a.size(); ++i)
            for (std::size_t j = 0; j < b.size(); ++j) {
                const box bi = grown_edge(a, av, i, grow), bj = grown_edge(b, bv, j, grow);
                if (boxes_meet(bi, a_window) && boxes_meet(bj, b_window) && boxes_meet(bi, bj))
                    want.insert({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
            }
        offered += want.size();
        INFO("round " << round << ": " << a.size() << " x " << b.size() << " edges");

        std::vector<box> a_runs, b_runs;
        edge_run_boxes(a, av, a_runs);
        edge_run_boxes(b, bv, b_runs);
        runs_seen += a_runs.size() + b_runs.size();
        std::multiset<index_pair> by_runs;
        CHECK_FALSE(overlapping_run_pairs({a, av, a_runs, a_window}, {b, bv, b_runs, b_window}, grow,
                                          [&](std::uint32_t i, std::uint32_t j) {
                                              by_runs.insert({i, j});
                                              return false;
                                          }));
        CHECK(std::set<index_pair>(by_runs.begin(), by_runs.end()) == want);
        CHECK(by_runs.size() == want.size());

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

        // Stopping: the pair accepted ends the search, and is reported.
        if (!want.empty()) {
            const index_pair target = *std::next(want.begin(), static_cast<std::ptrdiff_t>(g.index(want.size())));
            std::size_t calls = 0;
            bool seen_after = false, found = false;
            const bool stopped = overlapping_run_pairs({a, av, a_runs, a_window}, {b, bv, b_runs, b_window}, grow,
                                                       [&](std::uint32_t i, std::uint32_t j) {
                                                           seen_after = seen_after || found;
                                                           ++calls;
                                                           found = found || index_pair{i, j} == target;
                                                           return index_pair{i, j} == target;
                                                       });
            CHECK(stopped);
            CHECK(found);
            CHECK_FALSE(seen_after);
            CHECK(calls <= want.size());
        }
    }
    // Not vacuous: many pairs, polygons of several runs.
    CHECK(offered > 1000);
    CHECK(runs_seen > 200);
}
