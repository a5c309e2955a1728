// SPDX-License-Identifier: BSL-1.0
// The sweep along x (world/box_sweep.hpp) against every pair of boxes
// tested directly: within one set and across two, each meeting pair found
// once; the pairs it tests counted exactly (a budget one below that count
// gives way, calling nothing). Boxes on a coarse grid (equal least
// abscissae, boxes touching at an edge or a corner), points, segments,
// repeated boxes and a few boxes across the whole set.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "influence2d/world/box_sweep.hpp"
#include "support/effort.hpp"
#include "support/random.hpp"

using namespace influence2d;

namespace {

using index_pair = std::pair<std::uint32_t, std::uint32_t>;

std::vector<box> grid_boxes(test_random::rng& g, std::size_t n) {
    // (Half-units on a grid of 100 cells a side: ties and exact touches.)
    const auto half = [&g](std::size_t cells) { return 0.5 * static_cast<double>(g.index(cells)); };
    std::vector<box> out;
    out.reserve(n);
    while (out.size() < n) {
        const bool again = !out.empty() && g.chance(0.05);
        const double x = half(100), y = half(100);
        const double w = g.chance(0.1) ? 0 : g.chance(0.03) ? 100 : half(8), h = g.chance(0.1) ? 0 : half(8);
        out.push_back(again ? out[g.index(out.size())] : box{x, y, x + w, y + h});  // again: the same box
    }
    return out;
}

bool x_overlap(const box& a, const box& b) { return a.min_x <= b.max_x && b.min_x <= a.max_x; }

}  // namespace

TEST_CASE("swept_pairs: every meeting pair once, the pairs tested counted exactly", "[box_sweep]") {
    const int rounds = test_effort::scaled(16);
    std::size_t self_pairs = 0, cross_pairs = 0, touching = 0;
    for (int round = 0; round < rounds; ++round) {
        test_random::rng g(static_cast<std::uint64_t>(1300 + round));
        // Every fourth round tiny, after the first (so that a run of few
        // rounds, at a low test effort, still meets the counts below).
        const bool tiny = round % 4 == 3;
        const std::size_t n = tiny ? 1 + g.index(6) : 200 + g.index(500),
                          m = tiny ? 1 + g.index(6) : 100 + g.index(300);
        const std::vector<box> a = grid_boxes(g, n), b = grid_boxes(g, m);

        std::vector<index_pair> want_self, want_cross;
        std::size_t x_self = 0, x_cross = 0;
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = i + 1; j < n; ++j) {
                x_self += x_overlap(a[i], a[j]) ? 1 : 0;
                if (boxes_overlap(a[i], a[j])) want_self.push_back({std::uint32_t(i), std::uint32_t(j)});
                touching += boxes_overlap(a[i], a[j]) && (a[i].max_x == a[j].min_x || a[i].max_y == a[j].min_y);
            }
            for (std::size_t j = 0; j < m; ++j) {
                x_cross += x_overlap(a[i], b[j]) ? 1 : 0;
                if (boxes_overlap(a[i], b[j])) want_cross.push_back({std::uint32_t(i), std::uint32_t(j)});
            }
        }
        self_pairs += want_self.size();
        cross_pairs += want_cross.size();

        INFO("round " << round << ", " << n << " and " << m << " boxes");
        std::vector<index_pair> got;
        REQUIRE(swept_pairs(a, x_self, got));
        std::sort(got.begin(), got.end());
        CHECK(got == want_self);
        for (const index_pair& p : got) CHECK(p.first < p.second);
        if (x_self > 0) {
            got.clear();
            CHECK_FALSE(swept_pairs(a, x_self - 1, got));
            CHECK(got.empty());
        }

        got.clear();
        REQUIRE(swept_pairs(a, b, x_cross, got));
        std::sort(got.begin(), got.end());
        CHECK(got == want_cross);
        if (x_cross > 0) {
            got.clear();
            CHECK_FALSE(swept_pairs(a, b, x_cross - 1, got));
            CHECK(got.empty());
        }
        // The roles swapped: the same pairs, each reversed.
        got.clear();
        REQUIRE(swept_pairs(b, a, x_cross, got));
        for (index_pair& p : got) std::swap(p.first, p.second);
        std::sort(got.begin(), got.end());
        CHECK(got == want_cross);
    }
    INFO("pairs: " << self_pairs << " within, " << cross_pairs << " across, " << touching << " touching");
    CHECK(self_pairs > 50 * static_cast<std::size_t>(rounds));
    CHECK(cross_pairs > 20 * static_cast<std::size_t>(rounds));
    CHECK(touching > static_cast<std::size_t>(rounds));
}

TEST_CASE("swept_pairs: no boxes, and one box, have no pairs, and pairs are appended", "[box_sweep]") {
    const std::vector<box> none, one = {box{0, 0, 1, 1}};
    std::vector<index_pair> found;
    CHECK(swept_pairs(none, 0, found));
    CHECK(swept_pairs(one, 0, found));
    CHECK(swept_pairs(one, none, 0, found));
    CHECK(swept_pairs(none, one, 0, found));
    CHECK(found.empty());
    // The same box twice: one pair, tested once.
    const std::vector<box> twice = {box{0, 0, 1, 1}, box{0, 0, 1, 1}};
    CHECK_FALSE(swept_pairs(twice, 0, found));
    CHECK(found.empty());
    CHECK(swept_pairs(twice, 1, found));
    CHECK(found == std::vector<index_pair>{{0, 1}});
    CHECK(swept_pairs(one, twice, 2, found));  // (after the pair already there)
    REQUIRE(found.size() == 3);
    std::sort(found.begin() + 1, found.end());
    CHECK(found == std::vector<index_pair>{{0, 1}, {0, 0}, {0, 1}});
}
