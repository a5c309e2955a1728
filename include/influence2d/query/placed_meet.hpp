// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether two placed polygons meet, and what shows it: the steps of the
/// one-shot questions after their posing.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/segments.hpp"
#include "influence2d/scene/edge_boxes.hpp"
#include "influence2d/scene/placed_polygon.hpp"

namespace influence2d {

/// What showed that two placed polygons meet.
struct meeting {
    /// Which test answered.
    enum class kind : std::uint8_t {
        none,                            ///< they do not meet
        a_vertex_in_b,                   ///< A's vertex `a_index` lies in B (`where`: inside or on the boundary)
        b_vertex_in_a,                   ///< B's vertex `b_index` lies in A
        edges                            ///< A's edge `a_index` meets B's edge `b_index`
    } how = kind::none;                  ///< which test answered
    std::size_t a_index = 0;             ///< A's vertex or edge (stored numbering)
    std::size_t b_index = 0;             ///< B's vertex or edge (stored numbering)
    location where = location::outside;  ///< for a located vertex

    /// Whether the regions meet.
    explicit operator bool() const { return how != kind::none; }
};

/// Where P lies in the closed region of the placed polygon, P known in
/// double (`p_approx`) and in NT (`p`), every coordinate in double within
/// e of its value in NT (the filters' margin): locate_by_crossings, its
/// runs of edges (when made) and its edges settled in double where they can
/// be (a vertex in NT made only for the others; in double, whose doubles
/// are the decisions' own, with no margin). Exact when NT is.
template <class NT>
location locate_placed(placed_polygon<NT>& a, const point<double>& p_approx, const point<NT>& p, double e) {
    // (In double the doubles are the decisions' own: no margin.)
    const std::vector<box>& runs = a.finite_run_bounds();
    if constexpr (std::is_same_v<NT, double>) {
        if (runs.empty()) return locate_by_crossings(a.shape(), a.all(), p);
        const std::vector<point<double>>& v = a.approx();
        return locate_by_crossings(a.shape(), v, runs, edge_run_length, p_approx, 0.0, p,
                                   [&v](std::size_t i) -> const point<double>& { return v[i]; });
    } else {
        return locate_by_crossings(a.shape(), a.approx(), runs, edge_run_length, p_approx, e, p,
                                   [&a](std::size_t i) -> decltype(a[i]) { return a[i]; });
    }
}

/// Calls meet(i, j) for each edge i of A whose box (grown by `grow`) meets
/// `a_window` and edge j of B whose box meets `b_window`, the two boxes
/// overlapping, until meet returns true; returns whether it did. By the
/// two placings' run boxes when both have them and every coordinate is
/// finite (overlapping_run_pairs: edges only where two runs overlap; for two
/// polygons of one run each, few_edge_pairs); else
/// each edge list made whole (edges_meeting) and swept (overlapping_pairs).
template <class NT, class Meet>
bool edge_pairs_near(const placed_polygon<NT>& a, const placed_polygon<NT>& b, const box& a_window, const box& b_window,
                     double grow, Meet&& meet) {
    if (!a.run_bounds().empty() && !b.run_bounds().empty() && a.finite() && b.finite()) {
        const runs_side as{a.shape(), a.approx(), a.run_bounds(), a_window},
            bs{b.shape(), b.approx(), b.run_bounds(), b_window};
        if (a.shape().size() <= edge_run_length && b.shape().size() <= edge_run_length)
            return few_edge_pairs(as, bs, grow, meet);
        return overlapping_run_pairs(as, bs, grow, meet);
    }
    std::vector<edge_box> a_edges, b_edges;
    edges_meeting(a.shape(), a.approx(), a_window, grow, a_edges);
    edges_meeting(b.shape(), b.approx(), b_window, grow, b_edges);
    return overlapping_pairs(a_edges, b_edges, meet);
}

/// The rings at most this long are searched whole for the vertex nearest a
/// point (ring_vertex_near) when the placing has no run boxes; a longer ring
/// gives its first vertex. A scan of 32 vertices costs about as much as a
/// third of a locate in a polygon of that size, and the rings of the
/// world's compact bodies are shorter.
inline constexpr std::size_t near_scan_limit = 32;

/// The vertex of ring r of `shape` (its vertices in double: v) nearest to
/// p in the L1 norm, the first of those at the least distance; the ring's
/// first vertex when a distance is NaN, and for a ring longer than
/// near_scan_limit unless `runs` holds the run boxes of v (edge_run_boxes),
/// which prune the search (below). Only a choice: any vertex of the ring
/// serves a locate. Sums of differences, no squares: the same choice for
/// the polygons and p scaled by any power of two that keeps their
/// coordinates and differences normal (squares would underflow at
/// 2^-600), so that a query brought into double's range names the same
/// vertex as the query as given.
///
///   best <- none, at distance infinity
///   each run that holds vertices of the ring, in order: when p's L1
///   distance to the run's box (a bound below that of each of its
///   vertices) is below best's, each of its vertices in the ring, in
///   order: nearer than best, it is best
///
/// A run passed over holds no vertex nearer than best, and none as near
/// before it: the vertex a scan of the whole ring would give, at the cost
/// of a pass over the runs and the vertices of the few near p.
inline std::size_t ring_vertex_near(const polygon& shape, const std::vector<point<double>>& v, std::size_t r,
                                    const point<double>& p, const std::vector<box>& runs = {}) {
    const std::size_t first = shape.ring_begin(r), end = shape.ring_end(r);
    const bool long_ring = end - first > near_scan_limit;
    if (long_ring && runs.empty()) return first;
    std::size_t best = first;
    double best_d = std::numeric_limits<double>::infinity();
    const auto scan = [&](std::size_t from, std::size_t to) {
        for (std::size_t k = from; k < to; ++k) {
            const double d = std::fabs(v[k].x - p.x) + std::fabs(v[k].y - p.y);
            if (d < best_d) {
                best_d = d;
                best = k;
            }
        }
    };
    if (!long_ring) {
        scan(first, end);
        return best;
    }
    for (std::size_t run = first / edge_run_length; run * edge_run_length < end; ++run) {
        const box& b = runs[run];
        const double below =
            std::max({b.min_x - p.x, p.x - b.max_x, 0.0}) + std::max({b.min_y - p.y, p.y - b.max_y, 0.0});
        if (!(below < best_d)) continue;
        scan(std::max(first, run * edge_run_length), std::min(end, (run + 1) * edge_run_length));
    }
    return best;
}

/// Which witness placed_meet looks for first when both kinds may show a
/// meeting (the answer is the same; only the witness and the cost differ).
enum class witness_preference : std::uint8_t {
    cheapest,  ///< a ring's first vertex located first (linear), then the edges
    edges,     ///< two edges that meet first (four vertices to test again after a
               ///< small move, where a located vertex needs the other polygon whole);
               ///< a located vertex only when no edges meet
};

/// Whether the closed regions of the two placed polygons meet, and what
/// showed it; `e` bounds the distance between each coordinate in double
/// and in NT (the filters' margin). The steps of intersects below, after
/// the posing; `prefer` says which witness is sought first.
template <class NT>
meeting placed_meet(placed_polygon<NT>& a, placed_polygon<NT>& b, double e,
                    witness_preference prefer = witness_preference::cheapest) {
    const box& ab = a.bounds();
    box b_window = b.bounds().inflated(e), a_window = ab.inflated(e);
    // A coordinate beyond double's range (or NaN from inf - inf) leaves the
    // place open: no box shortcut, every edge a candidate.
    if (!a.finite() || !b.finite()) {
        const double inf = std::numeric_limits<double>::infinity();
        b_window = box{-inf, -inf, inf, inf};
        a_window = b_window;
    }
    if (b_window.max_x < ab.min_x || b_window.min_x > ab.max_x || b_window.max_y < ab.min_y ||
        b_window.min_y > ab.max_y)
        return {};

    // Containment first: one vertex of a ring located in the other polygon
    // (by its crossings, locate_by_crossings; containment.hpp says why that
    // decides the case of no boundary pair, whichever vertex of the ring is
    // taken).
    // A vertex in the other's closed region is a meeting point whatever the
    // boundaries do, and most poses that meet are answered here in linear
    // time, before any sorting. A vertex outside the other polygon's box
    // (widened) is outside it without a locate. Each locate reads the whole
    // other polygon, so only the first `early_rings` rings of each are
    // located before the boundaries are tested (none when edges are
    // preferred); the others after. The polygon whose box is the smaller
    // goes first, each of its rings by the vertex nearest the other's box
    // centre (ring_vertex_near, for a short ring): where the two overlap,
    // that vertex most likely lies inside the other. The other polygon's
    // rings go by their first vertex.
    const auto outside = [](const point<double>& v, const box& w) {
        return v.x < w.min_x || v.x > w.max_x || v.y < w.min_y || v.y > w.max_y;  // NaN: may be inside
    };
    // A vertex off the box of every ring of a host with ring boxes (widened
    // as the window) is outside it: a closed ring adds no crossing, and no
    // winding, about a point off its box.
    const auto off_every_ring = [&](const point<double>& v, const placed_polygon<NT>& host) {
        if (host.ring_bounds().empty() || !host.finite()) return false;
        for (const box& r : host.ring_bounds())
            if (!outside(v, r.inflated(e))) return false;
        return true;
    };
    const polygon &as = a.shape(), &bs = b.shape();
    // (Sizes by half perimeters, whose comparison is the same at every
    // scale: areas would underflow.)
    const box& bb = b.bounds();
    const auto size = [](const box& x) { return (x.max_x - x.min_x) + (x.max_y - x.min_y); };
    const bool b_first = size(bb) <= size(ab);
    const point<double> a_centre = ab.centre(), b_centre = bb.centre();
    // The rings [first, last) of `guest` (B when guest_is_b), each by one
    // vertex (ring_vertex_near when `near`, else its first), located in
    // `host` when within host_window.
    const auto rings_in = [&](placed_polygon<NT>& guest, placed_polygon<NT>& host, const box& host_window,
                              const point<double>& host_centre, bool guest_is_b, std::size_t first, std::size_t last,
                              bool near) -> meeting {
        const polygon& gs = guest.shape();
        const std::vector<box>& guest_runs = guest.finite_run_bounds();
        const std::vector<box>& guest_rings = guest.finite_ring_bounds();
        for (std::size_t r = first; r < std::min(last, gs.ring_count()); ++r) {
            // A ring whose box misses host_window has every vertex outside
            // it: whichever is taken would be passed over below.
            if (r < guest_rings.size() && !boxes_overlap(guest_rings[r], host_window)) continue;
            const std::size_t k =
                near ? ring_vertex_near(gs, guest.approx(), r, host_centre, guest_runs) : gs.ring_begin(r);
            if (outside(guest.approx()[k], host_window) || off_every_ring(guest.approx()[k], host)) continue;
            // (A vertex certainly in the host's inner disc lies in its
            // interior: no locate.)
            const location l = host.in_inner(guest.approx()[k], e)
                                   ? location::inside
                                   : locate_placed(host, guest.approx()[k], guest[k], e);
            if (l == location::outside) continue;
            return guest_is_b ? meeting{meeting::kind::b_vertex_in_a, 0, k, l}
                              : meeting{meeting::kind::a_vertex_in_b, k, 0, l};
        }
        return {};
    };
    const auto rings_inside = [&](std::size_t first, std::size_t last) -> meeting {
        const meeting m = b_first ? rings_in(b, a, a_window, a_centre, true, first, last, true)
                                  : rings_in(a, b, b_window, b_centre, false, first, last, true);
        if (m) return m;
        return b_first ? rings_in(a, b, b_window, b_centre, false, first, last, false)
                       : rings_in(b, a, a_window, a_centre, true, first, last, false);
    };
    const std::size_t early_rings = prefer == witness_preference::cheapest ? 2 : 0;
    if (meeting m = rings_inside(0, early_rings)) return m;

    // No ring inside the other polygon: the regions meet iff the boundaries
    // do. Candidate edges: those whose box meets the other polygon's box.
    meeting found;
    edge_pairs_near(a, b, b_window, a_window, e, [&](std::uint32_t i, std::uint32_t j) {
        const std::size_t i2 = as.next(i), j2 = bs.next(j);
        const point<double>&p = a.approx()[i], &q = a.approx()[i2], &u = b.approx()[j], &v = b.approx()[j2];
        if (!segments_may_meet(p, q, u, v, e)) return false;
        // (In double the doubles are the decision's own: no second filter.)
        const bool crossing = !std::is_same_v<NT, double> && segments_certainly_cross(p, q, u, v, e);
        if (!crossing && !segments_intersect(a[i], a[i2], b[j], b[j2])) return false;
        found = {meeting::kind::edges, i, j, location::boundary};
        return true;
    });
    if (found) return found;
    return rings_inside(early_rings, std::numeric_limits<std::size_t>::max());
}

/// Whether the closed regions of the two placed polygons come within
/// distance d of each other (d = 0: whether they meet, placed_meet), and
/// what showed it; `d2` is d * d in NT (exact when NT is and d is a double
/// whose square NT holds exactly), `e` the filters' margin as for
/// placed_meet, `prefer` the witness sought first. Exact when NT is.
///
///   the boxes (grown by d and e) apart:                        not within d
///   placed_meet (the regions meet):                            within d
///   the edges of each whose box (grown by d and e) meets the other's box;
///   each pair of those whose boxes overlap: exact distance test in NT
///   (segments_within):                                         within d
///   not within d
///
/// (Regions that do not meet are within d exactly when their boundaries
/// are: a point of one within d of the other's region is within d of its
/// boundary when outside it.)
template <class NT>
meeting placed_within(placed_polygon<NT>& a, placed_polygon<NT>& b, double e, double d, const NT& d2,
                      witness_preference prefer = witness_preference::cheapest) {
    if (!(d > 0)) return placed_meet(a, b, e, prefer);
    // (d's own share widened by sum_widening: the sums below round relative
    // to d.)
    const double reach = d * (1 + sum_widening) + 2 * e;
    box b_window = b.bounds().inflated(reach), a_window = a.bounds().inflated(reach);
    if (!a.finite() || !b.finite()) {
        const double inf = std::numeric_limits<double>::infinity();
        b_window = box{-inf, -inf, inf, inf};
        a_window = b_window;
    }
    const box& ab = a.bounds();
    if (b_window.max_x < ab.min_x || b_window.min_x > ab.max_x || b_window.max_y < ab.min_y ||
        b_window.min_y > ab.max_y)
        return {};
    if (meeting m = placed_meet(a, b, e, prefer)) return m;
    // Each edge's box grown by reach / 2 + e on its side: two edges within d
    // have boxes within d (exactly), within d + 2e in double.
    const double grow = reach / 2 + e;
    const polygon &as = a.shape(), &bs = b.shape();
    meeting found;
    edge_pairs_near(a, b, b_window, a_window, grow, [&](std::uint32_t i, std::uint32_t j) {
        if (!segments_within(a[i], a[as.next(i)], b[j], b[bs.next(j)], d2)) return false;
        found = {meeting::kind::edges, i, j, location::boundary};
        return true;
    });
    return found;
}

}  // namespace influence2d
