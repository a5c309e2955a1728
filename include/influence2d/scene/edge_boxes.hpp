// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The boxes of a polygon's edges in double, and the pairs of two polygons'
/// edges whose boxes overlap: the candidates of the one-shot questions.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"

namespace influence2d {

/// An edge's box in double (posed, for B) with its edge number.
struct edge_box {
    double min_x;        ///< the box's least abscissa
    double max_x;        ///< its greatest abscissa
    double min_y;        ///< its least ordinate
    double max_y;        ///< its greatest ordinate
    std::uint32_t edge;  ///< the edge (stored numbering)
};

/// Edges taken together: runs of consecutive edges, each tested as one box
/// before its edges are (edge_run_boxes, edges_meeting), and runs of
/// consecutive entries of an edges_meeting list swept as one box
/// (overlapping_pairs). Consecutive edges of a ring lie close together, so
/// that a run's box stays near the size of its edges' on curved
/// boundaries. Sixteen cuts the work on the boxes of a long boundary and
/// its sort sixteenfold, and makes a pair of small polygons one pair of
/// runs, tested without sorting.
inline constexpr std::size_t edge_run_length = 16;

/// The boxes of the runs of edge_run_length edges of a polygon whose
/// vertices in double are `v`: run r holds the edges (stored numbering)
/// r edge_run_length to (r + 1) edge_run_length - 1, its box both ends of
/// each (a NaN coordinate is left out: box::add).
inline void edge_run_boxes(const polygon& shape, const std::vector<point<double>>& v, std::vector<box>& out) {
    out.assign((shape.size() + edge_run_length - 1) / edge_run_length, box{});
    for (std::size_t e = 0; e < shape.size(); ++e) {
        box& b = out[e / edge_run_length];
        b.add(v[e]);
        b.add(v[shape.next(e)]);
    }
}

/// Appends to `out` each edge e in [first, end) of a polygon whose vertices
/// (in double) are `v` whose box, its ends' box widened by `low` below and
/// `high` above on each axis (x, then y), meets `window`.
inline void append_edges_meeting(const polygon& shape, const std::vector<point<double>>& v, std::size_t first,
                                 std::size_t end, const box& window, point<double> low, point<double> high,
                                 std::vector<edge_box>& out) {
    for (std::size_t e = first; e < end; ++e) {
        const point<double>&a = v[e], &b = v[shape.next(e)];
        const edge_box k{std::min(a.x, b.x) + low.x, std::max(a.x, b.x) + high.x, std::min(a.y, b.y) + low.y,
                         std::max(a.y, b.y) + high.y, static_cast<std::uint32_t>(e)};
        // (A NaN coordinate fails every comparison: such an edge is kept.)
        if (!(k.max_x < window.min_x || k.min_x > window.max_x || k.max_y < window.min_y || k.min_y > window.max_y))
            out.push_back(k);
    }
}

/// The edges of a polygon whose vertices (in double) are `v` and whose box
/// meets `window`, each with its box grown by `grow`. With shifts, each box
/// is that of the edge translated by every point between `from` and `to`
/// (the union of its boxes shifted by both).
inline void edges_meeting(const polygon& shape, const std::vector<point<double>>& v, const box& window, double grow,
                          std::vector<edge_box>& out, point<double> from = {0, 0}, point<double> to = {0, 0}) {
    out.clear();
    out.reserve(shape.size());
    append_edges_meeting(shape, v, 0, shape.size(), window,
                         {std::min(from.x, to.x) - grow, std::min(from.y, to.y) - grow},
                         {std::max(from.x, to.x) + grow, std::max(from.y, to.y) + grow}, out);
}

/// edges_meeting without shifts for a polygon whose run boxes are `runs`
/// (edge_run_boxes of the same vertices): a run whose box, grown, misses
/// the window is passed over whole. Only where every coordinate is finite
/// (a run's box leaves NaN out); callers widen the window to the whole
/// plane otherwise, which every run meets.
inline void edges_meeting(const polygon& shape, const std::vector<point<double>>& v, const std::vector<box>& runs,
                          const box& window, double grow, std::vector<edge_box>& out) {
    out.clear();
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const box& k = runs[r];
        if (k.max_x + grow < window.min_x || k.min_x - grow > window.max_x || k.max_y + grow < window.min_y ||
            k.min_y - grow > window.max_y)
            continue;
        const std::size_t first = r * edge_run_length;
        append_edges_meeting(shape, v, first, std::min(shape.size(), first + edge_run_length), window, {-grow, -grow},
                             {grow, grow}, out);
    }
}

/// Calls pair(i, j) for each i in [a_first, a_end) of `as` and j in
/// [b_first, b_end) of `bs` whose boxes (`box_of`, edge_box bounds) overlap,
/// each range sorted by min_x, until pair returns true; returns whether it
/// did. Sort and sweep along x: the box that starts first meets the other
/// range's boxes that start before it ends.
template <class T, class BoxOf, class Pair>
bool sweep_along_x(const std::vector<T>& as, std::size_t a_first, std::size_t a_end, const std::vector<T>& bs,
                   std::size_t b_first, std::size_t b_end, BoxOf&& box_of, Pair&& pair) {
    const auto overlap_y = [](const edge_box& l, const edge_box& r) {
        return !(l.max_y < r.min_y || r.max_y < l.min_y);
    };
    std::size_t i = a_first, j = b_first;
    while (i < a_end && j < b_end) {
        const edge_box &ai = box_of(as[i]), &bj = box_of(bs[j]);
        if (ai.min_x <= bj.min_x) {
            for (std::size_t k = j; k < b_end && box_of(bs[k]).min_x <= ai.max_x; ++k)
                if (overlap_y(ai, box_of(bs[k])) && pair(i, k)) return true;
            ++i;
        } else {
            for (std::size_t k = i; k < a_end && box_of(as[k]).min_x <= bj.max_x; ++k)
                if (overlap_y(box_of(as[k]), bj) && pair(k, j)) return true;
            ++j;
        }
    }
    return false;
}

/// Calls meet(i, j) for each pair of A's edge boxes and B's edge boxes that
/// overlap (or may: a NaN bound, made unbounded, overlaps everything), until
/// meet returns true; returns whether it did. Each pair is offered once.
/// Two levels of sort and sweep (sweep_along_x):
///
///   each list cut into runs of edge_run_length consecutive entries; each
///   run's entries sorted by min_x (in place), its box their union
///   the runs sorted by their boxes' min_x and swept
///   for each two runs whose boxes overlap: their entries swept
///
/// Two small polygons are one run each: their entries are swept, no run
/// made. A long boundary sorts sixteen times fewer runs than edges.
template <class Meet>
bool overlapping_pairs(std::vector<edge_box>& as, std::vector<edge_box>& bs, Meet&& meet) {
    struct run {
        edge_box bounds;           // the union of its entries' boxes
        std::uint32_t first, end;  // its entries
    };
    const auto by_min_x = [](const edge_box& l, const edge_box& r) { return l.min_x < r.min_x; };
    // Each run's entries made NaN-free and sorted; the runs too when `make`.
    const auto runs_of = [&](std::vector<edge_box>& list, bool make) {
        std::vector<run> runs;
        if (make) runs.reserve((list.size() + edge_run_length - 1) / edge_run_length);
        for (std::size_t first = 0; first < list.size(); first += edge_run_length) {
            const std::size_t end = std::min(list.size(), first + edge_run_length);
            // A NaN bound (from a NaN coordinate, which the callers' windows
            // keep) becomes unbounded on its side: such an entry, and its run,
            // meet whatever the sweeps pass, and the sorts see no NaN.
            const double inf = std::numeric_limits<double>::infinity();
            edge_box u{inf, -inf, inf, -inf, 0};
            for (std::size_t k = first; k < end; ++k) {
                edge_box& x = list[k];
                if (x.min_x != x.min_x) x.min_x = -inf;
                if (x.max_x != x.max_x) x.max_x = inf;
                if (x.min_y != x.min_y) x.min_y = -inf;
                if (x.max_y != x.max_y) x.max_y = inf;
                u.min_x = std::min(u.min_x, x.min_x);
                u.max_x = std::max(u.max_x, x.max_x);
                u.min_y = std::min(u.min_y, x.min_y);
                u.max_y = std::max(u.max_y, x.max_y);
            }
            std::sort(list.begin() + static_cast<std::ptrdiff_t>(first),
                      list.begin() + static_cast<std::ptrdiff_t>(end), by_min_x);
            if (make) runs.push_back({u, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(end)});
        }
        std::sort(runs.begin(), runs.end(), [](const run& l, const run& r) { return l.bounds.min_x < r.bounds.min_x; });
        return runs;
    };
    const auto entry = [](const edge_box& e) -> const edge_box& { return e; };
    const auto entries_meet = [&](std::size_t k, std::size_t l) { return meet(as[k].edge, bs[l].edge); };
    if (as.size() <= edge_run_length && bs.size() <= edge_run_length) {
        // One run each: their entries swept, no run made.
        for (std::vector<edge_box>* list : {&as, &bs}) runs_of(*list, false);
        return sweep_along_x(as, 0, as.size(), bs, 0, bs.size(), entry, entries_meet);
    }
    const std::vector<run> ra = runs_of(as, true), rb = runs_of(bs, true);
    return sweep_along_x(
        ra, 0, ra.size(), rb, 0, rb.size(), [](const run& r) -> const edge_box& { return r.bounds; },
        [&](std::size_t i, std::size_t j) {
            return sweep_along_x(as, ra[i].first, ra[i].end, bs, rb[j].first, rb[j].end, entry, entries_meet);
        });
}

}  // namespace influence2d
