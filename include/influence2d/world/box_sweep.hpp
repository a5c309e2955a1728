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

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "influence2d/core/box.hpp"

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

/// A set of boxes sorted by min_x (then by index), held as columns: a
/// sweep reads min_x in its binary searches and the y-bounds in its tests,
/// each from an array of its own. `index[p]` is the place in the input of
/// the box at position p.
struct boxes_along_x {
    std::vector<double> min_x;         ///< each box's least x, ascending
    std::vector<double> max_x;         ///< each box's greatest x
    std::vector<double> min_y;         ///< each box's least y
    std::vector<double> max_y;         ///< each box's greatest y
    std::vector<std::uint32_t> index;  ///< each box's place in the input

    /// The boxes (each finite, not empty) sorted. The sort moves a key of
    /// 16 bytes (min_x and the index) rather than a whole box: the wheat
    /// plots' sweep of docs/world.md (500 boxes) took 394,000 instructions
    /// a join so, 409,000 sorting boxes (callgrind).
    explicit boxes_along_x(const std::vector<box>& boxes) {
        struct key {
            double min_x;
            std::uint32_t index;
        };
        std::vector<key> keys;
        keys.reserve(boxes.size());
        for (std::size_t k = 0; k < boxes.size(); ++k) keys.push_back({boxes[k].min_x, static_cast<std::uint32_t>(k)});
        std::sort(keys.begin(), keys.end(), [](const key& l, const key& r) {
            return l.min_x < r.min_x || (l.min_x == r.min_x && l.index < r.index);
        });
        const std::size_t n = boxes.size();
        min_x.resize(n);
        max_x.resize(n);
        min_y.resize(n);
        max_y.resize(n);
        index.resize(n);
        for (std::size_t p = 0; p < n; ++p) {
            const box& b = boxes[keys[p].index];
            min_x[p] = b.min_x;
            max_x[p] = b.max_x;
            min_y[p] = b.min_y;
            max_y[p] = b.max_y;
            index[p] = keys[p].index;
        }
    }

    /// The number of boxes.
    std::size_t size() const { return index.size(); }

    /// The number of boxes from position `from` on whose min_x is at most x.
    std::size_t starting_by(std::size_t from, double x) const {
        return static_cast<std::size_t>(
                   std::upper_bound(min_x.begin() + static_cast<std::ptrdiff_t>(from), min_x.end(), x) -
                   min_x.begin()) -
               from;
    }

    /// The position of the first box whose min_x is at least x.
    std::size_t first_from(double x) const {
        return static_cast<std::size_t>(std::lower_bound(min_x.begin(), min_x.end(), x) - min_x.begin());
    }
};

/// 1 when the closed interval [lo, hi] meets [other_lo, other_hi], else 0
/// (finite bounds): both comparisons made, with no branch between them, so
/// that a sweep adds the answer where it would branch on it. overlap_along_y
/// (scene/edge_boxes.hpp) gives the same answer for finite bounds, true for
/// a NaN one, as the edge sweeps need; its form written without a branch,
/// !((a < b) | (c < d)), made the joins of docs/world.md 1.03x to 1.08x
/// slower than this one (blocks, tracts, plots).
inline std::size_t intervals_meet(double lo, double hi, double other_lo, double other_hi) {
    return static_cast<std::size_t>((other_lo <= hi) & (lo <= other_hi));
}

/// Of the positions p in [from, to), those whose interval [min_y[p],
/// max_y[p]] meets [lo, hi] (intervals_meet), written in order from `out`
/// on; returns how many. Every position tested is written and kept by
/// moving past it, so `out` has room for to - from. With SSE2 two
/// positions are tested at once (their four comparisons in two
/// instructions, a mask of their two answers): against one at a time, the
/// joins of docs/world.md took the wheat plots 658,900 -> 618,600
/// instructions, the Boston tracts 1,811,400 -> 1,765,900, the Olinda
/// blocks 3,101,900 -> 3,070,400 (callgrind, three joins); the plots'
/// tests alone, both ways in each run, 13.2 to 22.5 us one at a time and
/// 9.2 to 14.9 us two at a time, 0.58x to 0.71x (a scratch harness, six
/// runs, medians of 201 sweeps each).
inline std::size_t kept_meeting(double lo, double hi, const double* min_y, const double* max_y, std::size_t from,
                                std::size_t to, std::uint32_t* out) {
    std::size_t count = 0, p = from;
#if defined(__SSE2__)
    const __m128d low = _mm_set1_pd(lo), high = _mm_set1_pd(hi);
    for (; p + 2 <= to; p += 2) {
        const __m128d other_lo = _mm_loadu_pd(min_y + p), other_hi = _mm_loadu_pd(max_y + p);
        const unsigned both = static_cast<unsigned>(
            _mm_movemask_pd(_mm_and_pd(_mm_cmple_pd(other_lo, high), _mm_cmple_pd(low, other_hi))));
        out[count] = static_cast<std::uint32_t>(p);
        count += both & 1u;
        out[count] = static_cast<std::uint32_t>(p + 1);
        count += both >> 1;
    }
#endif
    for (; p < to; ++p) {
        out[count] = static_cast<std::uint32_t>(p);
        count += intervals_meet(lo, hi, min_y[p], max_y[p]);
    }
    return count;
}

/// Appends to `pairs` a Pair{i, j}, i < j, for every pair of boxes of
/// `boxes` that meet (closed: touching counts), in no particular order, and
/// returns true; or, when the sweep would test more than `budget` pairs,
/// appends nothing and returns false. Each box finite and not empty; Pair
/// is made of two std::uint32_t (body_pair, std::pair).
///
///   sorted <- the boxes sorted by min_x (boxes_along_x)
///   row(l) <- for each box l, the boxes after it whose min_x is at most
///             its max_x (a binary search each, starting_by)
///   more than budget in all: false
///   for each box l, each box r of row(l): r's y-interval overlaps l's:
///   (l, r) kept (kept_meeting)
///   each pair kept appended, by its boxes' places in the input
///
/// Two boxes meet exactly when both intervals overlap; the later of the two
/// in min_x order starts inside the earlier's x-interval. Each pair tested
/// is written, and kept by moving past it when the y-intervals overlap: no
/// branch on that test, whose answer (one or two pairs in ten on the real
/// layers of docs/world.md) a processor cannot foresee, nor on which of the
/// two indices is the smaller. Measured on those layers' joins (docs/world.md,
/// "Layers"), against a branch on each. The pairs are written in place,
/// their number known, where a caller's function appended them one at a
/// time (docs/world.md, "Layers").
template <class Pair>
bool swept_pairs(const std::vector<box>& boxes, std::size_t budget, std::vector<Pair>& pairs) {
    const boxes_along_x sorted(boxes);
    const std::size_t n = sorted.size();
    // The end of each box's row: the boxes from a + 1 to before end[a] start
    // inside its x-interval.
    std::vector<std::uint32_t> end(n);
    std::size_t tests = 0;
    for (std::size_t a = 0; a < n && tests <= budget; ++a) {
        const std::size_t row = sorted.starting_by(a + 1, sorted.max_x[a]);
        end[a] = static_cast<std::uint32_t>(a + 1 + row);
        tests += row;
    }
    if (tests > budget) return false;
    // The positions in `sorted` of the boxes kept, those kept with the box
    // at position a from kept[start[a]] on; room for every test, left
    // uninitialised.
    const std::unique_ptr<std::uint32_t[]> kept(new std::uint32_t[tests]);
    std::vector<std::uint32_t> start(n + 1);
    std::size_t count = 0;
    for (std::size_t a = 0; a < n; ++a) {
        start[a] = static_cast<std::uint32_t>(count);
        count += kept_meeting(sorted.min_y[a], sorted.max_y[a], sorted.min_y.data(), sorted.max_y.data(), a + 1, end[a],
                              kept.get() + count);
    }
    start[n] = static_cast<std::uint32_t>(count);
    std::size_t at = pairs.size();
    pairs.resize(at + count);
    for (std::size_t a = 0; a < n; ++a) {
        const std::uint32_t i = sorted.index[a];
        for (std::size_t k = start[a]; k < start[a + 1]; ++k) {
            const std::uint32_t j = sorted.index[kept[k]];
            // (the smaller index first, by masks: a branch would fail half the time)
            const std::uint32_t swap = (i ^ j) & (0u - static_cast<std::uint32_t>(j < i));
            pairs[at++] = Pair{i ^ swap, j ^ swap};
        }
    }
    return true;
}

/// Appends to `pairs` a Pair{i, j} for every box i of `first` and box j of
/// `second` that meet, in no particular order, and returns true; or, when
/// the sweep would test more than `budget` pairs, appends nothing and
/// returns false. As the one-set form, the two sets sorted apart: a pair is
/// tested from the box that starts first, from `first`'s on a tie.
///
///   a, b <- each set sorted by min_x (boxes_along_x)
///   row(l) <- for each box l of a, the boxes of b starting in [its min_x,
///             its max_x]; row(r) <- for each box r of b, those of a
///             starting in (its min_x, its max_x] (binary searches:
///             starting_by, first_from)
///   more than budget in all: false
///   for each box, each box of its row: their y-intervals overlap: the
///   pair kept (kept_meeting)
///   each pair kept appended, by its boxes' places in the inputs
template <class Pair>
bool swept_pairs(const std::vector<box>& first, const std::vector<box>& second, std::size_t budget,
                 std::vector<Pair>& pairs) {
    const boxes_along_x a(first), b(second);
    // Each box's row [from, to) in the other set.
    std::vector<std::uint32_t> a_from(a.size()), a_to(a.size()), b_from(b.size()), b_to(b.size());
    std::size_t tests = 0;
    for (std::size_t k = 0; k < a.size() && tests <= budget; ++k) {
        const std::size_t from = b.first_from(a.min_x[k]), to = from + b.starting_by(from, a.max_x[k]);
        a_from[k] = static_cast<std::uint32_t>(from);
        a_to[k] = static_cast<std::uint32_t>(to);
        tests += to - from;
    }
    for (std::size_t k = 0; k < b.size() && tests <= budget; ++k) {
        const std::size_t from = a.starting_by(0, b.min_x[k]), to = from + a.starting_by(from, b.max_x[k]);
        b_from[k] = static_cast<std::uint32_t>(from);
        b_to[k] = static_cast<std::uint32_t>(to);
        tests += to - from;
    }
    if (tests > budget) return false;
    // The positions in a and in b of the pairs kept; room for every test,
    // left uninitialised.
    const std::unique_ptr<std::uint32_t[]> kept_a(new std::uint32_t[tests]), kept_b(new std::uint32_t[tests]);
    std::size_t count = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        const std::size_t kept = kept_meeting(a.min_y[k], a.max_y[k], b.min_y.data(), b.max_y.data(), a_from[k],
                                              a_to[k], kept_b.get() + count);
        std::fill_n(kept_a.get() + count, kept, static_cast<std::uint32_t>(k));
        count += kept;
    }
    for (std::size_t k = 0; k < b.size(); ++k) {
        const std::size_t kept = kept_meeting(b.min_y[k], b.max_y[k], a.min_y.data(), a.max_y.data(), b_from[k],
                                              b_to[k], kept_a.get() + count);
        std::fill_n(kept_b.get() + count, kept, static_cast<std::uint32_t>(k));
        count += kept;
    }
    std::size_t at = pairs.size();
    pairs.resize(at + count);
    for (std::size_t k = 0; k < count; ++k) pairs[at++] = Pair{a.index[kept_a[k]], b.index[kept_b[k]]};
    return true;
}

}  // namespace influence2d
