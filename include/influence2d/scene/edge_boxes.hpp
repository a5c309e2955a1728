// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The boxes of a polygon's edges in double, and the pairs of two polygons'
/// edges whose boxes overlap: the candidates of the one-shot questions.

#include <algorithm>
#include <cstdint>
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

/// The edges of a polygon whose vertices (in double) are `v` and whose box
/// meets `window`, each with its box grown by `grow`. With shifts, each box
/// is that of the edge translated by every point between `from` and `to`
/// (the union of its boxes shifted by both).
inline void edges_meeting(const polygon& shape, const std::vector<point<double>>& v, const box& window, double grow,
                          std::vector<edge_box>& out, point<double> from = {0, 0}, point<double> to = {0, 0}) {
    out.clear();
    out.reserve(shape.size());
    const double low_x = std::min(from.x, to.x) - grow, high_x = std::max(from.x, to.x) + grow;
    const double low_y = std::min(from.y, to.y) - grow, high_y = std::max(from.y, to.y) + grow;
    for (std::size_t e = 0; e < shape.size(); ++e) {
        const point<double>&a = v[e], &b = v[shape.next(e)];
        const edge_box k{std::min(a.x, b.x) + low_x, std::max(a.x, b.x) + high_x, std::min(a.y, b.y) + low_y,
                         std::max(a.y, b.y) + high_y, static_cast<std::uint32_t>(e)};
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

}  // namespace influence2d
