// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// One query without a detector: whether A and B posed by q meet, at the cost
/// of reading both polygons once (docs/method.md, "One-shot queries").

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/detect/scene.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/segments.hpp"

namespace influence2d {

namespace one_shot_detail {

/// An edge's box in double (posed, for B) with its edge number.
struct edge_box {
    double min_x, max_x, min_y, max_y;
    std::uint32_t edge;
};

/// The edges of a polygon whose vertices (in double) are `v` and whose box
/// meets `window`, each with its box grown by `grow`.
inline void edges_meeting(const polygon& shape, const std::vector<point<double>>& v, const box& window, double grow,
                          std::vector<edge_box>& out) {
    out.clear();
    out.reserve(shape.size());
    for (std::size_t e = 0; e < shape.size(); ++e) {
        const point<double>&a = v[e], &b = v[shape.next(e)];
        const edge_box k{std::min(a.x, b.x) - grow, std::max(a.x, b.x) + grow, std::min(a.y, b.y) - grow,
                         std::max(a.y, b.y) + grow, static_cast<std::uint32_t>(e)};
        // (A NaN coordinate fails every comparison: such an edge is kept.)
        if (!(k.max_x < window.min_x || k.min_x > window.max_x || k.max_y < window.min_y || k.min_y > window.max_y))
            out.push_back(k);
    }
}

/// Calls meet(i, j) for each pair of A's edge boxes and B's edge boxes that
/// overlap (sort and sweep along x), until meet returns true; returns whether
/// it did. Both lists are sorted in place by min_x.
template <class Meet>
bool overlapping_pairs(std::vector<edge_box>& as, std::vector<edge_box>& bs, Meet&& meet) {
    const auto by_min_x = [](const edge_box& l, const edge_box& r) { return l.min_x < r.min_x; };
    std::sort(as.begin(), as.end(), by_min_x);
    std::sort(bs.begin(), bs.end(), by_min_x);
    const auto overlap_y = [](const edge_box& l, const edge_box& r) {
        return !(l.max_y < r.min_y || r.max_y < l.min_y);
    };
    std::size_t i = 0, j = 0;
    while (i < as.size() && j < bs.size()) {
        if (as[i].min_x <= bs[j].min_x) {
            // A's box i starts first: it meets B's boxes starting before it ends.
            for (std::size_t k = j; k < bs.size() && bs[k].min_x <= as[i].max_x; ++k)
                if (overlap_y(as[i], bs[k]) && meet(as[i].edge, bs[k].edge)) return true;
            ++i;
        } else {
            for (std::size_t k = i; k < as.size() && as[k].min_x <= bs[j].max_x; ++k)
                if (overlap_y(as[k], bs[j]) && meet(as[k].edge, bs[j].edge)) return true;
            ++j;
        }
    }
    return false;
}

}  // namespace one_shot_detail

/// Whether the closed regions of A and of B posed by q meet (touching
/// counts; B inside a hole of A does not meet A): the question a detector
/// answers for one frame with distance 0, without building one. Exact when NT
/// is; a filtered NT may throw uncertain_sign (certified_intersects in
/// certified_detector.hpp answers exactly through it). Throws invalid_input
/// for an empty polygon, one beyond NT's range, or a pose with a NaN or
/// infinite component.
///
///   pose B's vertices in double; e <- their rounding margin
///   if the boxes of A and of posed B (grown by e) are apart:   disjoint
///   for one vertex of every ring of each polygon, within the other's box:
///       located in the other polygon (exact), not outside:     meet
///   A's edges whose box meets B's box, B's edges whose box meets A's box
///   for each pair of those whose boxes overlap (sort and sweep along x):
///       filter in double: the paper's detailed test both ways (segments_may_meet)
///       exact segment test in NT on the posed vertices:       meet
///   disjoint
///
/// Time O((n + m) log(n + m) + k) for n and m edges and k overlapping boxes
/// (linear for most poses that meet: a located vertex answers them);
/// no structure outlives the call. For many poses of one pair a detector is
/// faster (it keeps A's precomputation and the last frame's candidates).
template <class NT>
bool intersects(const polygon& a, const polygon& b, const pose& q) {
    using namespace one_shot_detail;
    using tr = number_traits<NT>;
    accepted_polygon<NT>(a, "static");
    accepted_polygon<NT>(b, "moving");
    const rotation_pose t(q);

    // B posed in double, for the filters. Each coordinate c x - s y + t is a
    // few rounded operations on terms bounded by B's scale and |t|: its error
    // is below filter_slack times their sum (filter_slack >= 1e-9, far above
    // double's few ulps).
    std::vector<point<double>> bv(b.size());
    box bb;
    bool finite = true;
    for (std::size_t j = 0; j < b.size(); ++j) {
        bv[j] = t.apply<double>(b.vertex(j));
        finite = finite && std::isfinite(bv[j].x) && std::isfinite(bv[j].y);
        bb.add(bv[j]);
    }
    const double e = tr::filter_slack * 4 * (coordinate_scale(b) + coordinate_scale(a) + std::fabs(q.tx) + std::fabs(q.ty)) +
                     std::numeric_limits<double>::min();
    const box& ab = a.bounds();
    box b_window = bb.inflated(e), a_window = ab.inflated(e);
    // A posed coordinate beyond double's range (or NaN from inf - inf) leaves
    // B's place open: no box shortcut, every edge a candidate.
    if (!finite) {
        const double inf = std::numeric_limits<double>::infinity();
        b_window = box{-inf, -inf, inf, inf};
        a_window = b_window;
    }
    if (b_window.max_x < ab.min_x || b_window.min_x > ab.max_x || b_window.max_y < ab.min_y ||
        b_window.min_y > ab.max_y)
        return false;

    // B's vertices posed in NT when a decision asks for them (in double,
    // the filters' own values: the same operations on the same doubles).
    constexpr bool in_double = std::is_same_v<NT, double>;
    std::vector<point<NT>> posed(in_double ? 0 : b.size());
    std::vector<char> have(in_double ? 0 : b.size(), 0);
    const auto b_vertex = [&](std::size_t j) -> const point<NT>& {
        if constexpr (in_double) {
            return bv[j];
        } else {
            if (!have[j]) {
                posed[j] = t.apply<NT>(b.vertex(j));
                have[j] = 1;
            }
            return posed[j];
        }
    };
    const auto a_vertex = [&](std::size_t i) {
        return point<NT>{tr::from_double(a.vertex(i).x), tr::from_double(a.vertex(i).y)};
    };

    // Containment first: one vertex of every ring located in the other
    // polygon (containment.hpp says why that decides the case of no
    // boundary pair). A vertex in the other's closed region is a meeting
    // point whatever the boundaries do, and most poses that meet are
    // answered here in linear time, before any sorting. A vertex outside the
    // other polygon's box (widened) is outside it without a locate.
    const auto outside = [](const point<double>& v, const box& w) {
        return v.x < w.min_x || v.x > w.max_x || v.y < w.min_y || v.y > w.max_y;  // NaN: may be inside
    };
    std::vector<point<NT>> av;  // A's vertices in NT (A's own, in double)
    const auto a_vertices = [&]() -> const std::vector<point<NT>>& {
        if constexpr (in_double) {
            return a.vertices();
        } else {
            if (av.empty())
                for (std::size_t i = 0; i < a.size(); ++i) av.push_back(a_vertex(i));
            return av;
        }
    };
    const auto b_vertices = [&]() -> const std::vector<point<NT>>& {
        if constexpr (in_double) {
            return bv;
        } else {
            for (std::size_t j = 0; j < b.size(); ++j) b_vertex(j);
            return posed;
        }
    };
    const point<NT> a_origin{tr::from_double(a.centroid().x), tr::from_double(a.centroid().y)};
    for (std::size_t r = 0; r < b.ring_count(); ++r) {
        const std::size_t j = b.ring_begin(r);
        if (outside(bv[j], a_window)) continue;
        if (locate(a, a_vertices(), a_origin, b_vertex(j)) != location::outside) return true;
    }
    std::optional<point<NT>> b_origin;  // B's posed centroid, once a ring of A asks
    for (std::size_t r = 0; r < a.ring_count(); ++r) {
        const std::size_t i = a.ring_begin(r);
        if (outside(a.vertex(i), b_window)) continue;
        if (!b_origin) b_origin = t.apply<NT>(b.centroid());
        if (locate(b, b_vertices(), *b_origin, a_vertex(i)) != location::outside) return true;
    }

    // No ring inside the other polygon: the regions meet iff the boundaries
    // do. Candidate edges: those whose box meets the other polygon's box.
    std::vector<edge_box> a_edges, b_edges;
    edges_meeting(a, a.vertices(), b_window, e, a_edges);
    edges_meeting(b, bv, a_window, e, b_edges);
    return overlapping_pairs(a_edges, b_edges, [&](std::uint32_t i, std::uint32_t j) {
        const std::size_t i2 = a.next(i), j2 = b.next(j);
        if (!segments_may_meet(a.vertex(i), a.vertex(i2), bv[j], bv[j2], e)) return false;
        return segments_intersect(a_vertex(i), a_vertex(i2), b_vertex(j), b_vertex(j2));
    });
}

}  // namespace influence2d
