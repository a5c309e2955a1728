// SPDX-License-Identifier: BSL-1.0
// The box tree's joins (world/box_tree.hpp) against every pair of boxes
// tested directly: self_join and join find each meeting pair once, and so do
// their parts (self_join_parts, join_parts) however finely they are cut.
// Random boxes of mixed sizes, points, empty boxes and repeated boxes. The
// Hilbert positions the boxes are ordered by (world/hilbert_curve.hpp)
// against the curve's properties and its level-by-level walk.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <utility>
#include <vector>

#include "influence2d/world/box_tree.hpp"
#include "influence2d/world/hilbert_curve.hpp"
#include "support/effort.hpp"
#include "support/random.hpp"

using namespace influence2d;

namespace {

using id_pair = std::pair<std::uint32_t, std::uint32_t>;

std::vector<box> random_boxes(test_random::rng& g, std::size_t n) {
    std::vector<box> out;
    for (std::size_t k = 0; k < n; ++k) {
        if (g.chance(0.03)) {
            out.push_back(box{});  // empty: meets nothing
            continue;
        }
        if (k > 0 && g.chance(0.05)) {
            out.push_back(out[g.index(k)]);  // the same box again
            continue;
        }
        const double x = g.uniform(-100, 100), y = g.uniform(-100, 100);
        const double w = g.chance(0.1) ? 0 : g.chance(0.05) ? g.uniform(0, 80) : g.uniform(0, 6);
        const double h = g.chance(0.1) ? 0 : g.uniform(0, 6);
        out.push_back(box{x, y, x + w, y + h});
    }
    return out;
}

std::vector<std::uint32_t> ids_of(std::size_t n, std::uint32_t offset) {
    std::vector<std::uint32_t> ids(n);
    for (std::size_t k = 0; k < n; ++k) ids[k] = static_cast<std::uint32_t>(k) * 3 + offset;
    return ids;
}

id_pair ordered(std::uint32_t i, std::uint32_t j) { return {std::min(i, j), std::max(i, j)}; }

}  // namespace

TEST_CASE("box_tree: joins and their parts find each meeting pair once", "[box_tree]") {
    const int rounds = test_effort::scaled(12);
    std::size_t self_pairs = 0, cross_pairs = 0;
    for (int round = 0; round < rounds; ++round) {
        test_random::rng g(static_cast<std::uint64_t>(900 + round));
        // Every third round small (a tree of one or two levels), the others
        // of hundreds to thousands of boxes.
        const bool small = round % 3 == 2;
        const std::size_t n = small ? 1 + g.index(20) : 500 + g.index(2500),
                          m = small ? 1 + g.index(20) : 100 + g.index(400);
        const std::vector<box> a = random_boxes(g, n), b = random_boxes(g, m);
        const std::vector<std::uint32_t> a_ids = ids_of(n, 0), b_ids = ids_of(m, 1);
        box_tree ta, tb;
        ta.rebuild(a, a_ids);
        tb.rebuild(b, b_ids);

        std::vector<id_pair> want_self, want_cross;
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = i + 1; j < n; ++j)
                if (boxes_overlap(a[i], a[j])) want_self.push_back(ordered(a_ids[i], a_ids[j]));
            for (std::size_t j = 0; j < m; ++j)
                if (boxes_overlap(a[i], b[j])) want_cross.push_back({a_ids[i], b_ids[j]});
        }
        std::sort(want_self.begin(), want_self.end());
        std::sort(want_cross.begin(), want_cross.end());
        self_pairs += want_self.size();
        cross_pairs += want_cross.size();

        INFO("round " << round << ", " << n << " and " << m << " boxes");
        std::vector<id_pair> got;
        ta.self_join([&](std::uint32_t i, std::uint32_t j) { got.push_back(ordered(i, j)); });
        std::sort(got.begin(), got.end());
        CHECK(got == want_self);
        got.clear();
        ta.join(tb, [&](std::uint32_t i, std::uint32_t j) { got.push_back({i, j}); });
        std::sort(got.begin(), got.end());
        CHECK(got == want_cross);

        for (const std::size_t wanted :
             {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{64}, std::size_t{100000}}) {
            INFO("parts wanted " << wanted);
            const std::vector<box_tree::join_part> parts = ta.self_join_parts(wanted);
            got.clear();
            for (const box_tree::join_part& p : parts)
                ta.join_part_pairs(p, ta, [&](std::uint32_t i, std::uint32_t j) { got.push_back(ordered(i, j)); });
            std::sort(got.begin(), got.end());
            CHECK(got == want_self);
            if (n >= 8 * wanted) CHECK(parts.size() >= wanted);

            const std::vector<box_tree::join_part> cross = ta.join_parts(tb, wanted);
            got.clear();
            for (const box_tree::join_part& p : cross)
                ta.join_part_pairs(p, tb, [&](std::uint32_t i, std::uint32_t j) { got.push_back({i, j}); });
            std::sort(got.begin(), got.end());
            CHECK(got == want_cross);
        }
    }
    INFO("pairs: " << self_pairs << " within, " << cross_pairs << " across");
    CHECK(self_pairs > 200 * static_cast<std::size_t>(rounds));
    CHECK(cross_pairs > 20 * static_cast<std::size_t>(rounds));
}

TEST_CASE("box_tree: one tree rebuilt again and again, growing, shrinking and emptied, refitted between",
          "[box_tree]") {
    // A tree keeps its buffers from one rebuild to the next: every rebuild
    // must answer as a tree made anew. The sets change size by orders of
    // magnitude (its levels come and go), ids come and go, the boxes move
    // a little (the last order nearly right: insertion sort) or are drawn
    // anew (radix sort), and some are refitted between rebuilds.
    test_random::rng g(4242);
    box_tree tree;
    std::vector<box> boxes;
    std::vector<std::uint32_t> ids;
    const std::size_t sizes[] = {0, 1, 2000, 17, 0, 300, 4000, 3999, 5, 900, 1, 2500};
    std::size_t checked = 0;
    for (int round = 0; round < test_effort::scaled(24); ++round) {
        const std::size_t n = sizes[static_cast<std::size_t>(round) % std::size(sizes)];
        const bool moved_a_little = n == boxes.size() && g.chance(0.7);
        if (moved_a_little) {
            for (box& b : boxes) {
                const double dx = g.uniform(-0.5, 0.5), dy = g.uniform(-0.5, 0.5);
                if (!b.empty()) b = box{b.min_x + dx, b.min_y + dy, b.max_x + dx, b.max_y + dy};
            }
        } else {
            boxes = random_boxes(g, n);
            ids = ids_of(n, static_cast<std::uint32_t>(g.index(3)));
            if (g.chance(0.5)) std::reverse(ids.begin(), ids.end());
        }
        tree.rebuild(boxes, ids);
        // Some boxes refitted: moved, or dropped (an empty box); one by one
        // (refit), or in half the rounds all at once (refit_all), some of
        // them twice.
        const bool all_at_once = g.chance(0.5);
        std::vector<std::uint32_t> refitted;
        std::vector<std::size_t> place_of(ids.empty() ? 0 : *std::max_element(ids.begin(), ids.end()) + std::size_t{1});
        for (std::size_t k = 0; k < n; ++k) place_of[ids[k]] = k;
        for (std::size_t r = 0; n > 0 && r < n / 10; ++r) {
            const std::size_t k = g.index(n);
            const double x = g.uniform(-100, 100), y = g.uniform(-100, 100);
            boxes[k] = g.chance(0.2) ? box{} : box{x, y, x + g.uniform(0, 6), y + g.uniform(0, 6)};
            if (all_at_once)
                refitted.push_back(ids[k]);
            else
                tree.refit(ids[k], boxes[k]);
        }
        if (all_at_once) tree.refit_all(refitted, [&](std::uint32_t id) { return boxes[place_of[id]]; });
        INFO("round " << round << ", " << n << " boxes" << (moved_a_little ? ", moved a little" : "")
                      << (all_at_once ? ", refitted all at once" : ""));
        for (std::size_t k = 0; k < n; ++k) CHECK(tree.holds(ids[k]));
        std::vector<id_pair> want, got;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                if (boxes_overlap(boxes[i], boxes[j])) want.push_back(ordered(ids[i], ids[j]));
        std::sort(want.begin(), want.end());
        tree.self_join([&](std::uint32_t i, std::uint32_t j) { got.push_back(ordered(i, j)); });
        std::sort(got.begin(), got.end());
        CHECK(got == want);
        // Queries by a few boxes of the set and a box around everything.
        for (std::size_t q = 0; q < std::min<std::size_t>(n, 20); ++q) {
            const box& around = boxes[g.index(n)];
            std::vector<std::uint32_t> want_ids, got_ids;
            for (std::size_t k = 0; k < n; ++k)
                if (boxes_overlap(boxes[k], around)) want_ids.push_back(ids[k]);
            tree.query(around, [&](std::uint32_t id) { got_ids.push_back(id); });
            std::sort(want_ids.begin(), want_ids.end());
            std::sort(got_ids.begin(), got_ids.end());
            CHECK(got_ids == want_ids);
        }
        std::size_t all = 0;
        tree.query(box{-1000, -1000, 1000, 1000}, [&](std::uint32_t) { ++all; });
        CHECK(all == static_cast<std::size_t>(
                         std::count_if(boxes.begin(), boxes.end(), [](const box& b) { return !b.empty(); })));
        checked += want.size();
    }
    CHECK(checked > 1000);
}

TEST_CASE("box_tree: an empty tree has no parts", "[box_tree]") {
    box_tree empty, one;
    one.rebuild({box{0, 0, 1, 1}}, {7});
    CHECK(empty.self_join_parts(8).empty());
    CHECK(empty.join_parts(one, 8).empty());
    CHECK(one.join_parts(empty, 8).empty());
    const std::vector<box_tree::join_part> parts = one.self_join_parts(8);
    std::size_t found = 0;
    for (const box_tree::join_part& p : parts)
        one.join_part_pairs(p, one, [&](std::uint32_t, std::uint32_t) { ++found; });
    CHECK(found == 0);
}

namespace {

/// The classic rotate-and-flip walk of the Hilbert curve, one level at a
/// time (the definition hilbert_position's table steps are made from).
std::uint32_t walked_position(std::uint32_t x, std::uint32_t y) {
    std::uint32_t d = 0;
    for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
        const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
        d += s * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = s - 1 - (x & (s - 1)) + (x & ~(s - 1));
                y = s - 1 - (y & (s - 1)) + (y & ~(s - 1));
            }
            std::swap(x, y);
        }
    }
    return d;
}

}  // namespace

TEST_CASE("hilbert_position: the walk's positions, consecutive cells neighbours", "[box_tree]") {
    // Every aligned block of 256 x 256 cells is a run of 65,536 consecutive
    // positions along the curve, each cell next to the one before it.
    for (const auto& [x0, y0] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
             {0, 0}, {65280, 65280}, {256 * 97, 256 * 160}, {0, 65280}, {65280, 0}}) {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> at(65536, {0xffffffffu, 0});
        std::uint32_t first = 0xffffffffu;
        for (std::uint32_t x = x0; x < x0 + 256; ++x)
            for (std::uint32_t y = y0; y < y0 + 256; ++y) first = std::min(first, hilbert_position(x, y));
        REQUIRE(first % 65536 == 0);
        for (std::uint32_t x = x0; x < x0 + 256; ++x)
            for (std::uint32_t y = y0; y < y0 + 256; ++y) {
                const std::uint32_t k = hilbert_position(x, y) - first;
                REQUIRE(k < 65536);
                REQUIRE(at[k].first == 0xffffffffu);  // each position once
                at[k] = {x, y};
            }
        for (std::size_t k = 1; k < at.size(); ++k) {
            const auto dx = static_cast<long>(at[k].first) - static_cast<long>(at[k - 1].first);
            const auto dy = static_cast<long>(at[k].second) - static_cast<long>(at[k - 1].second);
            REQUIRE(std::abs(dx) + std::abs(dy) == 1);
        }
    }
    // The same positions as the walk, level by level, over the whole grid.
    test_random::rng g(16);
    for (int k = 0; k < 200000; ++k) {
        const auto x = static_cast<std::uint32_t>(g.uniform(0, 65536)),
                   y = static_cast<std::uint32_t>(g.uniform(0, 65536));
        REQUIRE(hilbert_position(x, y) == walked_position(x, y));
    }
    for (std::uint32_t v = 0; v < 65536; ++v)
        for (const std::uint32_t w : {0u, 1u, 32767u, 32768u, 65535u}) {
            REQUIRE(hilbert_position(v, w) == walked_position(v, w));
            REQUIRE(hilbert_position(w, v) == walked_position(w, v));
        }
}
