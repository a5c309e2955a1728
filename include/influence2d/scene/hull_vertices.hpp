// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which vertices of a polygon span its convex hull, decided exactly on its
/// doubles.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/predicates/exact_doubles.hpp"

namespace influence2d {

/// The vertices (stored numbering) at the corners of the convex hull of all
/// of p's vertices, counter-clockwise, each corner once and no vertex
/// strictly inside a hull edge: two vertices when all of them lie on one
/// line, one when they coincide, none for an empty polygon. Andrew's
/// monotone chain: the vertices sorted by x, then y; the lower chain and
/// the upper chain each kept turning left (a vertex that makes a right turn
/// or a straight step with the last two is dropped). Every turn is decided
/// by exact_orientation, so the hull is exact: every vertex of p lies in
/// the closed half-plane left of each hull edge's directed line, and so
/// does p's closed region (each ring lies in the hull of its vertices).
/// The same holds for the images under any map x -> M x + t with det M > 0
/// (a rotation pose: det is c^2 + s^2), which keeps every orientation
/// sign: the hull's corners posed are the posed polygon's hull.
inline std::vector<std::uint32_t> hull_vertices(const polygon& p) {
    std::vector<std::uint32_t> order(p.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<std::uint32_t>(k);
    const auto at = [&p](std::uint32_t k) -> const point<double>& { return p.vertex(k); };
    std::sort(order.begin(), order.end(), [&](std::uint32_t l, std::uint32_t r) {
        return at(l).x < at(r).x || (at(l).x == at(r).x && at(l).y < at(r).y);
    });
    // One copy of each point: a vertex repeated (rings sharing a corner)
    // would make a straight step of length 0.
    order.erase(std::unique(order.begin(), order.end(),
                            [&](std::uint32_t l, std::uint32_t r) { return at(l).x == at(r).x && at(l).y == at(r).y; }),
                order.end());
    if (order.size() < 3) return order;
    std::vector<std::uint32_t> hull;
    // The lower chain left to right, then the upper chain right to left;
    // each chain's last corner is the next one's first.
    for (int chain = 0; chain < 2; ++chain) {
        const std::size_t base = hull.size();
        for (std::size_t n = 0; n < order.size(); ++n) {
            const std::uint32_t k = chain == 0 ? order[n] : order[order.size() - 1 - n];
            while (hull.size() >= base + 2 && exact_orientation(at(hull[hull.size() - 2]), at(hull.back()), at(k)) <= 0)
                hull.pop_back();
            hull.push_back(k);
        }
        hull.pop_back();
    }
    return hull;
}

}  // namespace influence2d
