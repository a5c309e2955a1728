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

/// 1 when the closed y-intervals of two boxes overlap, else 0 (finite
/// bounds): both comparisons made, with no branch between them, so that a
/// sweep adds the answer where it would branch on it. overlap_along_y
/// (scene/edge_boxes.hpp) gives the same answer for finite bounds, true for
/// a NaN one, as the edge sweeps need; its form written without a branch,
/// !((a < b) | (c < d)), made the joins of docs/world.md 1.03x to 1.08x
/// slower than this one (blocks, tracts, plots).
inline std::size_t y_intervals_meet(const edge_box& l, const edge_box& r) {
    return static_cast<std::size_t>((r.min_y <= l.max_y) & (l.min_y <= r.max_y));
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
            count += y_intervals_meet(l, sorted[b]);
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
/// one-set form, the two sets sorted apart: a pair is tested from the box
/// that starts first, from `first`'s on a tie.
///
///   a, b <- each set sorted by min_x (sorted_along_x)
///   row(l) <- for each box l of a, the boxes of b starting in [its min_x,
///             its max_x]; row(r) <- for each box r of b, those of a
///             starting in (its min_x, its max_x] (binary searches:
///             starting_by, first_from)
///   more than budget in all: false
///   for each box, each box of its row: their y-intervals overlap: the
///   pair kept
///   found for each pair kept
///
/// As the one-set form, each pair tested is written and kept by moving
/// past it, without a branch on the test.
template <class Found>
bool swept_pairs(const std::vector<box>& first, const std::vector<box>& second, std::size_t budget, Found&& found) {
    const std::vector<edge_box> a = sorted_along_x(first), b = sorted_along_x(second);
    // Each box's row [from, to) in the other set.
    std::vector<std::uint32_t> a_from(a.size()), a_to(a.size()), b_from(b.size()), b_to(b.size());
    std::size_t tests = 0;
    for (std::size_t k = 0; k < a.size() && tests <= budget; ++k) {
        const std::size_t from = first_from(b, a[k].min_x), to = from + starting_by(b, from, a[k].max_x);
        a_from[k] = static_cast<std::uint32_t>(from);
        a_to[k] = static_cast<std::uint32_t>(to);
        tests += to - from;
    }
    for (std::size_t k = 0; k < b.size() && tests <= budget; ++k) {
        const std::size_t from = starting_by(a, 0, b[k].min_x), to = from + starting_by(a, from, b[k].max_x);
        b_from[k] = static_cast<std::uint32_t>(from);
        b_to[k] = static_cast<std::uint32_t>(to);
        tests += to - from;
    }
    if (tests > budget) return false;
    // The positions in a and in b of the pairs kept; room for every test,
    // left uninitialised.
    const std::unique_ptr<std::uint32_t[]> kept_a(new std::uint32_t[tests]), kept_b(new std::uint32_t[tests]);
    std::size_t count = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
        for (std::size_t j = a_from[k]; j < a_to[k]; ++j) {
            kept_a[count] = static_cast<std::uint32_t>(k);
            kept_b[count] = static_cast<std::uint32_t>(j);
            count += y_intervals_meet(a[k], b[j]);
        }
    for (std::size_t k = 0; k < b.size(); ++k)
        for (std::size_t i = b_from[k]; i < b_to[k]; ++i) {
            kept_a[count] = static_cast<std::uint32_t>(i);
            kept_b[count] = static_cast<std::uint32_t>(k);
            count += y_intervals_meet(a[i], b[k]);
        }
    for (std::size_t k = 0; k < count; ++k) found(a[kept_a[k]].edge, b[kept_b[k]].edge);
    return true;
}

}  // namespace influence2d
