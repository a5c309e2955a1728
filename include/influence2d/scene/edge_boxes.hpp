// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The boxes of a polygon's edges in double, and the pairs of two polygons'
/// edges whose boxes overlap: the candidates of the one-shot questions.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "influence2d/assert.hpp"
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
/// before its edges are (edge_run_boxes, overlapping_run_pairs), and runs of
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
    const std::size_t n = shape.size();
    out.assign((n + edge_run_length - 1) / edge_run_length, box{});
    // Each edge's first end, in one pass; then the far end of each run's
    // last edge, and the far end of each ring's last edge (its first
    // vertex): every other far end is the next edge's first end, in the
    // same run.
    for (std::size_t r = 0; r < out.size(); ++r) {
        const std::size_t end = std::min(n, (r + 1) * edge_run_length);
        box b;  // (a local box: kept in registers, where out[r] could alias v)
        b.add(v.data() + r * edge_run_length, v.data() + end);
        b.add(v[shape.next(end - 1)]);
        out[r] = b;
    }
    for (std::size_t k = 0; k < shape.ring_count(); ++k)
        out[(shape.ring_end(k) - 1) / edge_run_length].add(v[shape.ring_begin(k)]);
}

/// The box of each of the first `rings` rings of a polygon whose vertices
/// in double are `v` (a NaN coordinate is left out: box::add).
inline void ring_boxes(const polygon& shape, const std::vector<point<double>>& v, std::size_t rings,
                       std::vector<box>& out) {
    out.assign(rings, box{});
    for (std::size_t r = 0; r < rings; ++r) {
        box b;  // (a local box: the compiler keeps it in registers)
        b.add(v.data() + shape.ring_begin(r), v.data() + shape.ring_end(r));
        out[r] = b;
    }
}

/// Whether the entry's box meets the box `w` (an edge_box or a box; closed
/// boxes). A NaN bound fails every comparison: such an entry meets it.
template <class W>
bool meets_box(const edge_box& k, const W& w) {
    return !(k.max_x < w.min_x || k.min_x > w.max_x || k.max_y < w.min_y || k.min_y > w.max_y);
}

/// meets_box with its four comparisons all made, joined without a branch
/// (for loops over many boxes whose outcomes follow no pattern).
template <class W>
bool boxes_meet(const edge_box& k, const W& w) {
    return !((k.max_x < w.min_x) | (k.min_x > w.max_x) | (k.max_y < w.min_y) | (k.min_y > w.max_y));
}

/// Whether the y-intervals of two entries' boxes overlap (closed): with
/// their x-intervals known to overlap, whether the boxes meet.
inline bool overlap_along_y(const edge_box& l, const edge_box& r) { return !(l.max_y < r.min_y || r.max_y < l.min_y); }

/// The box of edge e of a polygon whose vertices (in double) are `v`, its
/// ends' box widened by `low` below and `high` above on each axis (x, then
/// y).
inline edge_box edge_box_of(const polygon& shape, const std::vector<point<double>>& v, std::size_t e, point<double> low,
                            point<double> high) {
    const point<double>&a = v[e], &b = v[shape.next(e)];
    return {std::min(a.x, b.x) + low.x, std::max(a.x, b.x) + high.x, std::min(a.y, b.y) + low.y,
            std::max(a.y, b.y) + high.y, static_cast<std::uint32_t>(e)};
}

/// The edges of a polygon whose vertices (in double) are `v` and whose box
/// meets `window`, each with its box grown by `grow`. With shifts, each box
/// is that of the edge translated by every point between `from` and `to`
/// (the union of its boxes shifted by both). (An edge with a NaN coordinate
/// is kept.)
inline void edges_meeting(const polygon& shape, const std::vector<point<double>>& v, const box& window, double grow,
                          std::vector<edge_box>& out, point<double> from = {0, 0}, point<double> to = {0, 0}) {
    out.clear();
    out.reserve(shape.size());
    const point<double> low{std::min(from.x, to.x) - grow, std::min(from.y, to.y) - grow},
        high{std::max(from.x, to.x) + grow, std::max(from.y, to.y) + grow};
    for (std::size_t e = 0; e < shape.size(); ++e) {
        const edge_box k = edge_box_of(shape, v, e, low, high);
        if (meets_box(k, window)) out.push_back(k);
    }
}

/// Calls pair(i, j) for each i in [a_first, a_end) of `as` and j in
/// [b_first, b_end) of `bs` whose boxes (`box_of`, edge_box bounds) overlap,
/// each range sorted by min_x, until pair returns true; returns whether it
/// did. Sort and sweep along x: the box that starts first meets the other
/// range's boxes that start before it ends.
template <class Seq, class BoxOf, class Pair>
bool sweep_along_x(const Seq& as, std::size_t a_first, std::size_t a_end, const Seq& bs, std::size_t b_first,
                   std::size_t b_end, BoxOf&& box_of, Pair&& pair) {
    std::size_t i = a_first, j = b_first;
    while (i < a_end && j < b_end) {
        const edge_box &ai = box_of(as[i]), &bj = box_of(bs[j]);
        if (ai.min_x <= bj.min_x) {
            for (std::size_t k = j; k < b_end && box_of(bs[k]).min_x <= ai.max_x; ++k)
                if (overlap_along_y(ai, box_of(bs[k])) && pair(i, k)) return true;
            ++i;
        } else {
            for (std::size_t k = i; k < a_end && box_of(as[k]).min_x <= bj.max_x; ++k)
                if (overlap_along_y(box_of(as[k]), bj) && pair(k, j)) return true;
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

/// One side of overlapping_run_pairs: a polygon's topology, its vertices in
/// double, its run boxes (edge_run_boxes of the same vertices), and the
/// window its edges must meet to be offered (the other polygon's box,
/// grown).
struct runs_side {
    const polygon& shape;                 ///< the topology
    const std::vector<point<double>>& v;  ///< the vertices in double
    const std::vector<box>& runs;         ///< edge_run_boxes of v
    box window;                           ///< what an offered edge's box must meet
};

/// Calls meet(i, j) for each edge i of A and edge j of B whose boxes, each
/// grown by `grow`, overlap and meet their windows, until meet returns
/// true; returns whether it did. Each pair is offered once. Runs first,
/// edges only inside two runs that overlap:
///
///   A's runs whose box (grown) meets A's window, and B's likewise, each
///   list sorted by min_x
///   for each run of A and run of B whose boxes overlap (sort and sweep,
///   sweep_along_x):
///     the run's edges whose box (grown) meets its window and the other
///     run's box, on each side (at most edge_run_length), sorted by min_x
///     and swept: meet on each two that overlap
///
/// An edge pair whose boxes overlap lies in two runs whose boxes overlap,
/// so the pairs offered are those of edges_meeting and overlapping_pairs;
/// the work on edges is confined to where the two boundaries come close,
/// and a meeting found there ends it. Only where every coordinate is finite
/// (a run box leaves NaN out).
template <class Meet>
bool overlapping_run_pairs(const runs_side& a, const runs_side& b, double grow, Meet&& meet) {
    // Run boxes grown, as edge_box entries whose `edge` is the run.
    const auto runs_meeting = [grow](const runs_side& s, std::vector<edge_box>& out) {
        out.clear();
        for (std::size_t r = 0; r < s.runs.size(); ++r) {
            const box& k = s.runs[r];
            const edge_box g{k.min_x - grow, k.max_x + grow, k.min_y - grow, k.max_y + grow,
                             static_cast<std::uint32_t>(r)};
            if (meets_box(g, s.window)) out.push_back(g);
        }
        std::sort(out.begin(), out.end(), [](const edge_box& l, const edge_box& r) { return l.min_x < r.min_x; });
    };
    // (Kept per thread: a layer or a world asks this for many pairs.)
    static thread_local std::vector<edge_box> a_runs, b_runs;
    runs_meeting(a, a_runs);
    if (a_runs.empty()) return false;
    runs_meeting(b, b_runs);
    if (b_runs.empty()) return false;
    // The two runs' edges: the edges of run r of side s whose grown box
    // meets s's window and `other` (a grown run box) are put in `found` from
    // `base` (A's from 0, B's from edge_run_length), their number returned.
    // They are then ordered by min_x through indices into `found` (an
    // insertion sort, stable, of at most edge_run_length one-byte entries;
    // the entries themselves, 40 bytes each, stay in place), and only when
    // both runs have some.
    static_assert(2 * edge_run_length <= 256, "an index into found fits in one byte");
    std::array<edge_box, 2 * edge_run_length> found;
    using run_order = std::array<std::uint8_t, edge_run_length>;
    const auto edges_in = [grow, &found](const runs_side& s, std::size_t r, const edge_box& other, std::size_t base) {
        std::size_t n = 0;
        const std::size_t first = r * edge_run_length, end = std::min(s.shape.size(), first + edge_run_length);
        for (std::size_t e = first; e < end; ++e) {
            const edge_box k = edge_box_of(s.shape, s.v, e, {-grow, -grow}, {grow, grow});
            if (meets_box(k, other) && meets_box(k, s.window)) found[base + n++] = k;
        }
        return n;
    };
    const auto by_min_x = [&found](std::size_t base, std::size_t n, run_order& order) {
        for (std::size_t k = 0; k < n; ++k) {
            const double x = found[base + k].min_x;
            std::size_t at = k;
            for (; at > 0 && found[order[at - 1]].min_x > x; --at) order[at] = order[at - 1];
            order[at] = static_cast<std::uint8_t>(base + k);
        }
    };
    const auto entry = [](const edge_box& e) -> const edge_box& { return e; };
    const auto found_entry = [&found](std::uint8_t k) -> const edge_box& { return found[k]; };
    run_order oa, ob;
    return sweep_along_x(a_runs, 0, a_runs.size(), b_runs, 0, b_runs.size(), entry, [&](std::size_t i, std::size_t j) {
        const std::size_t na = edges_in(a, a_runs[i].edge, b_runs[j], 0);
        if (na == 0) return false;
        const std::size_t nb = edges_in(b, b_runs[j].edge, a_runs[i], edge_run_length);
        if (nb == 0) return false;
        by_min_x(0, na, oa);
        by_min_x(edge_run_length, nb, ob);
        return sweep_along_x(oa, 0, na, ob, 0, nb, found_entry,
                             [&](std::size_t k, std::size_t l) { return meet(found[oa[k]].edge, found[ob[l]].edge); });
    });
}

/// overlapping_run_pairs for two polygons of at most edge_run_length edges
/// each (one run each): the same pairs offered, each once, in another
/// order, until meet returns true; returns whether it did. B's edges whose
/// grown box meets B's window are listed (the index always written, the
/// count advanced by the test: no branch a box), then each of A's edges
/// whose grown box meets A's window against that list. No run box, no
/// sort: for a pair of small polygons (a grid's cells, city blocks) the
/// runs' machinery costs more than the few box tests it saves. Only where
/// every coordinate is finite.
template <class Meet>
bool few_edge_pairs(const runs_side& a, const runs_side& b, double grow, Meet&& meet) {
    INFLUENCE2D_ASSERT(a.shape.size() <= edge_run_length && b.shape.size() <= edge_run_length,
                       "few_edge_pairs: more edges than one run");
    std::array<edge_box, edge_run_length> near_b;
    std::size_t count = 0;
    for (std::size_t j = 0; j < b.shape.size(); ++j) {
        near_b[count] = edge_box_of(b.shape, b.v, j, {-grow, -grow}, {grow, grow});
        count += boxes_meet(near_b[count], b.window) ? 1 : 0;
    }
    for (std::size_t i = 0; count > 0 && i < a.shape.size(); ++i) {
        const edge_box k = edge_box_of(a.shape, a.v, i, {-grow, -grow}, {grow, grow});
        if (!meets_box(k, a.window)) continue;
        for (std::size_t l = 0; l < count; ++l)
            if (boxes_meet(near_b[l], k) && meet(k.edge, near_b[l].edge)) return true;
    }
    return false;
}

}  // namespace influence2d
