// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which boxes of a set meet, or which of one set meet which of another, by
/// sorting them along x and sweeping: the broad phase of a layer's join
/// when few of the boxes' x-intervals overlap (docs/world.md, "Layers").

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/scene/edge_boxes.hpp"

namespace influence2d {

/// The x-interval overlaps a sweep may test per box before a join takes the
/// box tree instead (world/box_tree.hpp). The sweep costs a few
/// nanoseconds an overlap it tests (its sort and count included), the
/// tree's rebuild and self-join 50 to 200 ns a box. Measured on whole joins
/// (docs/world.md, "Layers": two budgets in one process, joins taking
/// turns, so that the machine's slow spells fall on both): 32 against 16
/// made the join of the wheat plots (500 polygons, 28.7 overlaps a box)
/// 1.106x as fast and of 300 generated parcels (21.2) 1.057x, moved the
/// Boston tracts (506, 31.8) 0.993x and the Olinda blocks (470, 24.2)
/// 1.008x, and left the layers above it (1,000 parcels, 40.9) to the tree
/// as before. Before, sweeps and trees timed apart from the joins put the
/// two level between 12 and 41 overlaps a box. Compact boxes spread over a
/// plane overlap along x about as many others as a column holds, which
/// grows as the square root of their number.
inline constexpr std::size_t sweep_tests_per_box = 32;

/// The boxes (each finite, not empty) as edge_box entries whose `edge` is
/// the box's index in `boxes`, sorted by min_x, then by index.
inline std::vector<edge_box> sorted_along_x(const std::vector<box>& boxes) {
    std::vector<edge_box> out;
    out.reserve(boxes.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        const box& b = boxes[k];
        out.push_back({b.min_x, b.max_x, b.min_y, b.max_y, static_cast<std::uint32_t>(k)});
    }
    std::sort(out.begin(), out.end(), [](const edge_box& l, const edge_box& r) {
        return l.min_x < r.min_x || (l.min_x == r.min_x && l.edge < r.edge);
    });
    return out;
}

/// The number of entries of `sorted` (sorted by min_x) from `from` on
/// whose min_x is at most x.
inline std::size_t starting_by(const std::vector<edge_box>& sorted, std::size_t from, double x) {
    const auto end = std::upper_bound(sorted.begin() + static_cast<std::ptrdiff_t>(from), sorted.end(), x,
                                      [](double v, const edge_box& b) { return v < b.min_x; });
    return static_cast<std::size_t>(end - sorted.begin()) - from;
}

/// The index of the first entry of `sorted` (sorted by min_x) whose min_x
/// is at least x.
inline std::size_t first_from(const std::vector<edge_box>& sorted, double x) {
    return static_cast<std::size_t>(
        std::lower_bound(sorted.begin(), sorted.end(), x, [](const edge_box& s, double v) { return s.min_x < v; }) -
        sorted.begin());
}

/// Calls found(i, j), i < j, for every pair of boxes of `boxes` that meet
/// (closed: touching counts), in no particular order, and returns true; or,
/// when the sweep would test more than `budget` pairs, calls nothing and
/// returns false. Each box finite and not empty.
///
///   sorted <- the boxes sorted by min_x (sorted_along_x)
///   row(l) <- for each box l, the boxes after it whose min_x is at most
///             its max_x (a binary search each, starting_by)
///   more than budget in all: false
///   for each box l, each box r of row(l): r's y-interval overlaps l's:
///   (l, r) kept
///   found for each pair kept
///
/// Two boxes meet exactly when both intervals overlap; the later of the two
/// in min_x order starts inside the earlier's x-interval. Each pair tested
/// is written, and kept by moving past it when the y-intervals overlap: no
/// branch on that test, whose answer (one or two pairs in ten on the real
/// layers of docs/world.md) a processor cannot foresee, nor on which of the
/// two indices is the smaller. Measured on those layers' joins (docs/world.md,
/// "Layers"), against a branch on each.
template <class Found>
bool swept_pairs(const std::vector<box>& boxes, std::size_t budget, Found&& found) {
    const std::vector<edge_box> sorted = sorted_along_x(boxes);
    // The end of each box's row: the boxes from a + 1 to before end[a] start
    // inside its x-interval.
    std::vector<std::uint32_t> end(sorted.size());
    std::size_t tests = 0;
    for (std::size_t a = 0; a < sorted.size() && tests <= budget; ++a) {
        const std::size_t row = starting_by(sorted, a + 1, sorted[a].max_x);
        end[a] = static_cast<std::uint32_t>(a + 1 + row);
        tests += row;
    }
    if (tests > budget) return false;
    // The positions in `sorted` of the boxes kept, those kept with the box
    // at position a from kept[start[a]] on; room for every test, left
    // uninitialised.
    const std::unique_ptr<std::uint32_t[]> kept(new std::uint32_t[tests]);
    std::vector<std::uint32_t> start(sorted.size() + 1, 0);
    std::size_t count = 0;
    for (std::size_t a = 0; a < sorted.size(); ++a) {
        const edge_box& l = sorted[a];
        start[a] = static_cast<std::uint32_t>(count);
        for (std::size_t b = a + 1; b < end[a]; ++b) {
            kept[count] = static_cast<std::uint32_t>(b);
            count += static_cast<std::size_t>((sorted[b].min_y <= l.max_y) & (l.min_y <= sorted[b].max_y));
        }
    }
    start[sorted.size()] = static_cast<std::uint32_t>(count);
    for (std::size_t a = 0; a < sorted.size(); ++a)
        for (std::size_t k = start[a]; k < start[a + 1]; ++k) {
            const std::uint32_t i = sorted[a].edge, j = sorted[kept[k]].edge;
            // (the smaller index first, by masks: a branch would fail half the time)
            const std::uint32_t swap = (i ^ j) & (0u - static_cast<std::uint32_t>(j < i));
            found(i ^ swap, j ^ swap);
        }
    return true;
}

/// Calls found(i, j) for every box i of `first` and box j of `second` that
/// meet, in no particular order, and returns true; or, when the sweep would
/// test more than `budget` pairs, calls nothing and returns false. As the
/// one-set form, the two sets sorted apart and merged (sweep_along_x): a
/// pair is tested from the box that starts first, from `first`'s on a tie.
///
///   a, b <- each set sorted by min_x (sorted_along_x)
///   tests <- for each box of a, the boxes of b starting in [its min_x,
///            its max_x]; for each of b, those of a starting in (its min_x,
///            its max_x] (binary searches: starting_by, first_from)
///   tests > budget: false
///   sweep_along_x(a, b): found for each pair whose boxes overlap
template <class Found>
bool swept_pairs(const std::vector<box>& first, const std::vector<box>& second, std::size_t budget, Found&& found) {
    const std::vector<edge_box> a = sorted_along_x(first), b = sorted_along_x(second);
    std::size_t tests = 0;
    for (const edge_box& l : a)
        if (tests <= budget) tests += starting_by(b, first_from(b, l.min_x), l.max_x);
    for (const edge_box& r : b)
        if (tests <= budget) tests += starting_by(a, starting_by(a, 0, r.min_x), r.max_x);
    if (tests > budget) return false;
    sweep_along_x(
        a, 0, a.size(), b, 0, b.size(), [](const edge_box& e) -> const edge_box& { return e; },
        [&](std::size_t i, std::size_t j) {
            found(a[i].edge, b[j].edge);
            return false;
        });
    return true;
}

}  // namespace influence2d
