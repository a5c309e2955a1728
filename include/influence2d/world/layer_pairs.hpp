// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which polygons of a layer meet, or which of one layer meet which of
/// another, all at their own coordinates: the spatial join of an audit or a
/// GIS check (docs/world.md, "Layers").

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/core/shortest_decimal.hpp"
#include "influence2d/detect/convex_pair.hpp"
#include "influence2d/predicates/convexity.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/shared_vertex.hpp"
#include "influence2d/query/batch.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"
#include "influence2d/world/box_sweep.hpp"
#include "influence2d/world/box_tree.hpp"
#include "influence2d/world/narrow_phase.hpp"
#include "influence2d/world/projections_apart.hpp"
#include "influence2d/world/world.hpp"

namespace influence2d {

/// What a join did besides its answer, for audits and precision studies
/// (layer_pairs' `statistics`).
struct layer_statistics {
    std::size_t candidates = 0;   ///< pairs whose grown boxes meet: each tested (layer_pairs' pseudocode)
    std::size_t exact_pairs = 0;  ///< candidates answered again in the Exact type (a sign NT could not settle)
    bool swept = false;           ///< the candidates found by sorting the boxes along x (swept_pairs), not by box trees
};

/// A join's tests run on one thread when its candidates hold fewer
/// vertices than this, both polygons of each counted (and its questions of
/// shared vertices and separating directions when the candidates asked them
/// do): a parallel pass costs some tens of microseconds in waking the
/// other threads and in their caches, which a small join does not repay.
/// Measured on the real layers of docs/world.md (one thread against every
/// thread with oneTBB, 101 joins each way, taking turns, medians, alone):
/// with the tests on two threads whenever there were 128 candidates or
/// more, the wheat plots' join (about 15,000 vertices over its candidates)
/// ran 0.92x to 0.97x as fast as on one thread and the NC counties'
/// (14,000) 0.67x; above this bound the Boston tracts (55,000) run 1.15x to
/// 1.26x, the countries (90,000) 0.96x to 1.21x and the Olinda blocks
/// (106,000) 1.33x to 1.52x.
inline constexpr std::size_t join_parallel_vertices = 32768;

namespace layer_pairs_detail {

/// What a join reads of each polygon of a layer outside its tests, read in
/// one pass over the polygons: its own box and its number of vertices. The
/// join's passes over its candidates then read these arrays rather than
/// the polygons, whose objects lie apart in memory. Reading each polygon's
/// box and size again in every pass, the wheat plots' join of
/// docs/world.md missed the first-level cache 7,793 times a join in
/// reading (callgrind's cache model, each join run after GEOS's, as in the
/// time study); 4,609 times with these arrays and the sweep's columns
/// (boxes_along_x, world/box_sweep.hpp).
struct layer_summary {
    std::vector<box> bounds;           ///< each polygon's own box
    std::vector<std::uint32_t> sizes;  ///< each polygon's number of vertices
    double largest = 0;                ///< the largest absolute coordinate of the layer
};

/// The layer's summary; throws invalid_input naming an empty polygon.
inline layer_summary summary_of(const std::vector<polygon>& layer, const char* which) {
    if (layer.size() >= 0xffffffffu)
        throw invalid_input(std::string("layer_pairs: the ") + which + " layer is too large");
    layer_summary out;
    out.bounds.reserve(layer.size());
    out.sizes.reserve(layer.size());
    for (std::size_t k = 0; k < layer.size(); ++k) {
        if (layer[k].size() == 0)
            throw invalid_input(std::string("layer_pairs: polygon ") + std::to_string(k) + " of the " + which +
                                " layer is empty (it has no ring)");
        out.bounds.push_back(layer[k].bounds());
        out.sizes.push_back(static_cast<std::uint32_t>(layer[k].size()));
        out.largest = std::max(out.largest, largest_coordinate(out.bounds.back()));
    }
    return out;
}

/// The boxes a join's broad phase meets: each polygon's own box grown by
/// half the distance, with room for the rounding of that sum and for the
/// filters' placing margin; and their ids.
template <class NT>
void boxes_of(const layer_summary& layer, double within, std::vector<box>& boxes, std::vector<std::uint32_t>& ids) {
    boxes.reserve(layer.bounds.size());
    ids.reserve(layer.bounds.size());
    for (std::size_t k = 0; k < layer.bounds.size(); ++k) {
        const box& b = layer.bounds[k];
        boxes.push_back(b.inflated(placing_margin<NT>(largest_coordinate(b)) + within / 2 * (1 + sum_widening)));
        ids.push_back(static_cast<std::uint32_t>(k));
    }
}

/// Each polygon of the layer checked against NT's range when NT's is below
/// double's (accepted_polygon); throws invalid_input naming the first
/// vertex beyond it.
template <class NT>
void accept_range(const std::vector<polygon>& layer, const char* which) {
    if constexpr (range_below_double_v<NT>)
        for (const polygon& p : layer) accepted_polygon<NT>(p, which);
    (void)layer;
    (void)which;
}

/// The candidates (or polygons) a thread takes at a time in a join: a
/// pair's test costs from tens of nanoseconds to microseconds (a polygon of
/// many rings inside the box of another of many runs), and the costly ones
/// gather where the sorted pairs name the same large polygon, so that one
/// contiguous block per thread leaves one thread with most of the work.
/// Sixteen keeps the handing out (a few atomic steps a chunk) far below the
/// tests' cost.
inline constexpr std::size_t join_grain = 16;

/// Two convex polygons whose sizes' product is at most this take the
/// separating-edge test on their doubles as given in a join (d = 0), where
/// bodies_within would place them. On the real layers of docs/world.md
/// (callgrind, one join each): the wheat plots, rectangles of four
/// vertices whose neighbours touch or overlap by a unit in the last place,
/// 1.97 -> 1.77 million instructions in double and 2.54 -> 1.74 certified;
/// allowing larger pairs (up to 256, the detector's convex_pair_limit) cost
/// the Olinda blocks, the Boston tracts and the NC counties 1% to 2% more
/// than bodies_within (touching neighbours: the test refutes every edge of
/// both, where bodies_within finds a shared vertex on the other's boundary).
inline constexpr std::size_t join_convex_limit = 16;

/// A join's candidate whose two polygons have at most this many vertices
/// each is first asked whether they share a vertex (share_a_vertex: then
/// they meet, and neither is placed for it). Past it, the scan of a large
/// polygon's vertices costs more than the one-shot test it may spare. On the
/// real layers of docs/world.md (callgrind, three joins each, double): with
/// the bound at 64, 256, 1,024 and none, the countries' join took 1.77,
/// 1.77, 1.99 and 1.99 million instructions (1.87 without the question),
/// the blocks' 3.76, 3.69, 3.69 and 3.69 (4.61), the tracts' 2.52, 2.51,
/// 2.51 and 2.51 (3.46), the boroughs' (thousands of vertices each) 3.02,
/// 3.02, 3.02 and 3.06 (3.02).
inline constexpr std::size_t join_shared_vertex_limit = 256;

/// A join's candidate (d = 0) that shares no vertex, whose two polygons
/// have at most this many vertices together, is then asked whether some
/// direction certainly separates their vertices (projections_apart: then
/// they do not meet, and neither is placed for it). Each of the search's
/// steps passes over both polygons, and a pair that meets takes them all;
/// past the bound that costs more than the one-shot test it spares. On the
/// real layers of docs/world.md (callgrind, three joins each, double; the
/// sum of the sizes at most 64, 96, 128 and 256): the countries' join took
/// 1.76, 1.77, 1.82 and 1.89 million instructions (1.76 without the
/// question), the counties' 0.317, 0.296, 0.296 and 0.296 (0.413), the
/// blocks' 3.02, 2.89, 2.91 and 2.91 (3.69), the tracts' 1.71, 1.69, 1.68
/// and 1.68 (2.50).
inline constexpr std::size_t join_apart_limit = 96;

/// The placings of the polygons of a layer that some candidate names, each
/// found by the polygon's index (4 bytes for a polygon no candidate names),
/// in place in a deque's blocks of a few hundred bytes (no allocation of its
/// own per polygon). Not one vector: a block of 64 KiB or more freed at the
/// end of a join makes glibc's free return the top of the heap to the
/// system (M_TRIM_THRESHOLD, 128 KiB), and the next join faults all its
/// working memory in again (the 506 tracts of docs/world.md: 513 us a join
/// with one vector, 295 us without, alone on this machine).
template <class NT>
class placed_polygons {
public:
    /// Each polygon of `layer` that `named` names, placed where it stands,
    /// with its run boxes and, for several rings, its ring boxes; every
    /// vertex in NT made too when NT's placings keep them and `threads`
    /// (not 1) threads will read them. On the calling thread: placed on two
    /// threads (the tests too), the countries' join (docs/world.md) ran 0.85x
    /// and 0.86x as fast as on one thread, with the placings on one 0.92x to
    /// 1.21x; the blocks' and tracts' joins gained nothing from placing on
    /// two (101 joins each way, taking turns, medians, four runs).
    placed_polygons(const std::vector<polygon>& layer, const std::vector<char>& named, unsigned threads)
        : slot_(layer.size(), 0) {
        for (std::size_t k = 0; k < layer.size(); ++k) {
            if (!named[k]) continue;
            slot_[k] = static_cast<std::uint32_t>(placed_.size());
            placed_polygon<NT>& p = placed_.emplace_back(layer[k]);
            p.make_run_bounds();
            p.make_ring_bounds();
            if constexpr (!placed_polygon<NT>::by_value)
                if (threads != 1) p.all();
        }
    }

    /// The placing of polygon k, which `named` named.
    placed_polygon<NT>& operator[](std::size_t k) { return placed_[slot_[k]]; }

private:
    std::vector<std::uint32_t> slot_;        // polygon index -> index in placed_
    std::deque<placed_polygon<NT>> placed_;  // the named polygons' placings, in index order
};

/// What a join knows of a polygon's shape, for the routes of its pairs:
/// not asked yet, neither of the two below, convex (is_convex_polygon), or
/// its own box (fills_its_box; convex too).
enum class join_shape : signed char { unknown, other, convex, box };

/// The shape of polygon k of `layer`, decided once: `known[k]` holds it.
inline join_shape shape_as_known(const std::vector<polygon>& layer, std::vector<join_shape>& known, std::size_t k) {
    if (known[k] == join_shape::unknown)
        known[k] = fills_its_box(layer[k])       ? join_shape::box
                   : is_convex_polygon(layer[k]) ? join_shape::convex
                                                 : join_shape::other;
    return known[k];
}

/// The route a join's candidate takes: bodies_within on the two placings,
/// the separating-edge test on the doubles as given (a convex pair), the
/// two closed boxes (two polygons that fill their boxes), a vertex the two
/// share (they meet), or a direction that certainly separates their
/// vertices (they do not); neither placed for the last two.
enum class join_route : char { placed, convex, boxes, shared_vertex, apart };

/// The candidates' answers (in parallel chunks) and the pairs within d;
/// `same` when both layers are one. Counts into `statistics` when given.
template <class NT, class Exact>
std::vector<body_pair> within_of(const std::vector<polygon>& first, const layer_summary& first_summary,
                                 const std::vector<polygon>& second, const layer_summary& second_summary, bool same,
                                 const std::vector<body_pair>& candidates, double within, unsigned threads,
                                 layer_statistics* statistics) {
    // For d = 0: two polygons that fill their boxes are answered by the
    // boxes, two convex polygons of join_convex_limit at most by the
    // separating-edge test; for any d, two that share a vertex meet; for
    // d = 0, two whose vertices a direction certainly separates do not;
    // neither placed for it.
    std::vector<join_shape> shape_first(within == 0 ? first.size() : 0, join_shape::unknown),
        shape_second(within == 0 && !same ? second.size() : 0, join_shape::unknown);
    std::vector<join_shape>& second_shape = same ? shape_first : shape_second;
    std::vector<join_route> route(candidates.size(), join_route::placed);
    std::vector<char> meets(candidates.size(), 0), in_exact(candidates.size(), 0);
    // The routes by shape (one thread: each polygon's shape decided once; a
    // pair of boxes answered at once), then those by vertices (on threads
    // when their scans are long: each candidate's route its own). A layer
    // of rectangles (the wheat plots of docs/world.md) is done after the
    // first pass.
    // (The counts, sizes and boxes read through locals: the stores of the
    // answers, chars, may alias anything, and the vectors' own fields would
    // be read again after each.)
    std::size_t scanned = 0;  // (the vertices the routes by vertices scan at most)
    std::size_t left = 0;     // (the candidates the first pass leaves)
    const std::size_t count = candidates.size();
    const body_pair* const pairs = candidates.data();
    const std::uint32_t *const first_sizes = first_summary.sizes.data(), *const second_sizes =
                                                                             second_summary.sizes.data();
    const box *const first_bounds = first_summary.bounds.data(), *const second_bounds = second_summary.bounds.data();
    char* const answer = meets.data();
    for (std::size_t k = 0; k < count; ++k) {
        const body_pair c = pairs[k];
        const std::size_t na = first_sizes[c.first], nb = second_sizes[c.second];
        if (within == 0 && na * nb <= join_convex_limit) {
            const join_shape sa = shape_as_known(first, shape_first, c.first);
            const join_shape sb = sa == join_shape::other ? sa : shape_as_known(second, second_shape, c.second);
            if (sa == join_shape::box && sb == join_shape::box) {
                route[k] = join_route::boxes;
                answer[k] = boxes_overlap(first_bounds[c.first], second_bounds[c.second]) ? 1 : 0;
                continue;
            }
            ++left;
            if (sa != join_shape::other && sb != join_shape::other) {
                route[k] = join_route::convex;
                continue;
            }
        } else {
            ++left;
        }
        if (na <= join_shared_vertex_limit && nb <= join_shared_vertex_limit) scanned += na + nb;
    }
    if (left > 0) {
        run_in_chunks(candidates.size(), scanned < join_parallel_vertices ? 1u : threads, join_grain,
                      [&](std::size_t lo, std::size_t hi) {
                          for (std::size_t k = lo; k < hi; ++k) {
                              if (route[k] != join_route::placed) continue;
                              const polygon &a = first[candidates[k].first], &b = second[candidates[k].second];
                              const std::size_t na = a.size(), nb = b.size();
                              if (na > join_shared_vertex_limit || nb > join_shared_vertex_limit) continue;
                              if (share_a_vertex(a, b))
                                  route[k] = join_route::shared_vertex;
                              else if (within == 0 && na + nb <= join_apart_limit && projections_apart(a, b))
                                  route[k] = join_route::apart;
                          }
                      });
        std::vector<char> named_first(first.size(), 0), named_second(second.size(), 0);
        std::size_t vertices = 0;
        for (std::size_t k = 0; k < candidates.size(); ++k) {
            if (route[k] != join_route::placed) continue;
            const body_pair& c = candidates[k];
            named_first[c.first] = 1;
            (same ? named_first : named_second)[c.second] = 1;
            vertices += first_summary.sizes[c.first] + second_summary.sizes[c.second];
        }
        const unsigned pair_threads = vertices < join_parallel_vertices ? 1u : threads;
        placed_polygons<NT> placed_first(first, named_first, pair_threads);
        placed_polygons<NT> placed_second(second, named_second, pair_threads);  // none named when same
        placed_polygons<NT>& second_placed = same ? placed_first : placed_second;
        run_in_chunks(candidates.size(), pair_threads, join_grain, [&](std::size_t lo, std::size_t hi) {
            const rotation_pose here(pose{});
            for (std::size_t k = lo; k < hi; ++k) {
                const body_pair& c = candidates[k];
                if (route[k] == join_route::shared_vertex) {
                    meets[k] = 1;
                    continue;
                }
                if (route[k] == join_route::apart || route[k] == join_route::boxes) continue;  // (answered)
                const polygon &a = first[c.first], &b = second[c.second];
                if (route[k] == join_route::convex) {
                    meets[k] = convex_polygons_meet_as_given(a, b) ? 1 : 0;
                    continue;
                }
                placed_polygon<NT>&pa = placed_first[c.first], &pb = second_placed[c.second];
                const body_view<NT> va{&a, here, largest_coordinate(first_summary.bounds[c.first]), &pa},
                    vb{&b, here, largest_coordinate(second_summary.bounds[c.second]), &pb};
                bool exact = false;
                const meeting m =
                    bodies_within<NT, Exact>(meeting{}, va, vb, within, nullptr, witness_preference::cheapest, &exact);
                meets[k] = m ? 1 : 0;
                in_exact[k] = exact ? 1 : 0;
            }
        });
    }
    // Each candidate written, kept by moving past it (no branch on its
    // answer); room for one more.
    const std::size_t kept = static_cast<std::size_t>(std::count(meets.begin(), meets.end(), 1));
    std::vector<body_pair> out(kept + 1);
    for (std::size_t k = 0, at = 0; k < count; ++k) {
        out[at] = pairs[k];
        at += static_cast<std::size_t>(answer[k]);
    }
    out.pop_back();
    sort_body_pairs(out, std::max(first.size(), second.size()));
    if (statistics != nullptr) {
        statistics->candidates = candidates.size();
        statistics->exact_pairs = static_cast<std::size_t>(std::count(in_exact.begin(), in_exact.end(), 1));
    }
    return out;
}

/// The distance, checked.
inline double checked_distance(double within) {
    if (!(within >= 0) || !std::isfinite(within))
        throw invalid_input("layer_pairs: the distance " + shortest_decimal(within) + " is not a finite number >= 0");
    return within;
}

/// The shift of a join in NT (range_shift of the largest coordinate of the
/// layers' polygons).
template <class NT>
int layers_shift(const layer_summary& first, const layer_summary& second) {
    if constexpr (!scaled_into_range_v<NT>) {
        (void)first;
        (void)second;
        return 0;
    } else {
        return range_shift<NT>(std::max(first.largest, second.largest));
    }
}

/// Each polygon of the layer scaled by 2^k.
inline std::vector<polygon> scaled_layer(const std::vector<polygon>& layer, int k) {
    std::vector<polygon> out;
    out.reserve(layer.size());
    for (const polygon& p : layer) out.push_back(p.scaled_by_power_of_two(k));
    return out;
}

}  // namespace layer_pairs_detail

/// Every pair (i, j), i < j, of the layer's polygons whose closed regions
/// come within `within` of each other (0: meet; touching counts), sorted.
/// Exact when NT is, or with Exact not void (certified_layer_pairs in
/// exact/certified_world.hpp): the answers of intersects on each pair.
///
///   summary <- each polygon's box and size, read once (layer_summary)
///   float, double, long double far from 1 in scale: every polygon and the
///   distance scaled by a power of two first (core/range_scaling.hpp; the
///   same answer)
///   boxes <- each polygon's box, grown by within / 2 (and the filters'
///            margin)
///   candidates <- the pairs whose boxes meet, in the order found:
///     by sorting the boxes along x and sweeping (swept_pairs) when that
///     tests at most sweep_tests_per_box pairs a box; else by a box tree
///     over them joined with itself (box_tree::self_join)
///   for d = 0, of two polygons whose sizes' product is at most
///   join_convex_limit: two that fill their boxes (fills_its_box) are a
///   pair of boxes, answered by whether the closed boxes share a point
///   (boxes_overlap); else two convex ones (is_convex_polygon) a convex pair
///   every candidate a pair of boxes (a layer of rectangles): the pairs that
///   meet, sorted (sort_body_pairs), returned
///   of the other candidates, on `threads` threads taking join_grain
///   candidates at a time when those of at most join_shared_vertex_limit
///   vertices each hold join_parallel_vertices vertices or more, else on
///   one: two polygons of at most join_shared_vertex_limit vertices each
///   that share a vertex (share_a_vertex) meet: within any d; else for
///   d = 0, two of at most join_apart_limit vertices together whose vertices
///   a direction certainly separates (projections_apart) do not meet
///   each polygon some other candidate names placed where it stands, once
///   for all its pairs, with its run boxes and, for several rings, its ring
///   boxes (placed_polygons)
///   each candidate not a pair of boxes, on `threads` threads (0: every
///   hardware thread) taking join_grain candidates at a time, or on one
///   when the other candidates hold fewer than join_parallel_vertices
///   vertices: a convex pair by the separating-edge test on its doubles as
///   given (convex_polygons_meet_as_given), the others by bodies_within on
///   the two placings
///   the candidates that meet, sorted (sort_body_pairs)
///
/// `statistics`, when given, receives the number of candidates, of those
/// answered again in Exact, and whether the sweep found them. Throws
/// invalid_input for an empty polygon (naming it), one beyond NT's range,
/// or a distance that is negative, NaN or infinite.
template <class NT, class Exact = void>
std::vector<body_pair> layer_pairs(const std::vector<polygon>& layer, double within = 0, unsigned threads = 1,
                                   layer_statistics* statistics = nullptr) {
    within = layer_pairs_detail::checked_distance(within);
    const layer_pairs_detail::layer_summary summary = layer_pairs_detail::summary_of(layer, "first");
    if (const int k = layer_pairs_detail::layers_shift<NT>(summary, summary))
        return layer_pairs<NT, Exact>(layer_pairs_detail::scaled_layer(layer, k), scaled_length(within, k), threads,
                                      statistics);
    layer_pairs_detail::accept_range<NT>(layer, "first");
    std::vector<box> boxes;
    std::vector<std::uint32_t> ids;
    layer_pairs_detail::boxes_of<NT>(summary, within, boxes, ids);
    std::vector<body_pair> candidates;
    const bool swept = swept_pairs(boxes, sweep_tests_per_box * boxes.size(), candidates);
    if (!swept) {
        box_tree tree;
        tree.rebuild(boxes, ids);
        tree.self_join([&](std::uint32_t i, std::uint32_t j) {
            candidates.push_back({std::min(i, j), std::max(i, j)});
        });
    }
    if (statistics != nullptr) statistics->swept = swept;
    return layer_pairs_detail::within_of<NT, Exact>(layer, summary, layer, summary, true, candidates, within, threads,
                                                    statistics);
}

/// Every pair (i, j) of a polygon i of `first` and a polygon j of `second`
/// whose closed regions come within `within` of each other, sorted; as the
/// one-layer form otherwise (the two layers' boxes swept together, or a box
/// tree over each layer, the two joined).
template <class NT, class Exact = void>
std::vector<body_pair> layer_pairs(const std::vector<polygon>& first, const std::vector<polygon>& second,
                                   double within = 0, unsigned threads = 1, layer_statistics* statistics = nullptr) {
    within = layer_pairs_detail::checked_distance(within);
    const layer_pairs_detail::layer_summary first_summary = layer_pairs_detail::summary_of(first, "first"),
                                            second_summary = layer_pairs_detail::summary_of(second, "second");
    if (const int k = layer_pairs_detail::layers_shift<NT>(first_summary, second_summary))
        return layer_pairs<NT, Exact>(layer_pairs_detail::scaled_layer(first, k),
                                      layer_pairs_detail::scaled_layer(second, k), scaled_length(within, k), threads,
                                      statistics);
    layer_pairs_detail::accept_range<NT>(first, "first");
    layer_pairs_detail::accept_range<NT>(second, "second");
    std::vector<box> a_boxes, b_boxes;
    std::vector<std::uint32_t> a_ids, b_ids;
    layer_pairs_detail::boxes_of<NT>(first_summary, within, a_boxes, a_ids);
    layer_pairs_detail::boxes_of<NT>(second_summary, within, b_boxes, b_ids);
    std::vector<body_pair> candidates;
    const bool swept =
        swept_pairs(a_boxes, b_boxes, sweep_tests_per_box * (a_boxes.size() + b_boxes.size()), candidates);
    if (!swept) {
        box_tree a_tree, b_tree;
        a_tree.rebuild(a_boxes, a_ids);
        b_tree.rebuild(b_boxes, b_ids);
        a_tree.join(b_tree, [&](std::uint32_t i, std::uint32_t j) { candidates.push_back({i, j}); });
    }
    if (statistics != nullptr) statistics->swept = swept;
    return layer_pairs_detail::within_of<NT, Exact>(first, first_summary, second, second_summary, false, candidates,
                                                    within, threads, statistics);
}

}  // namespace influence2d
