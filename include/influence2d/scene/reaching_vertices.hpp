// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which vertices of a polygon reach farthest from its centre towards a
/// given direction: the vertices worth looking up first in the deep cells
/// of another polygon that lies that way. A choice of probes, never a
/// decision: any vertex would be a sound probe.

#include <array>
#include <cmath>
#include <cstdint>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"

namespace influence2d {

/// For each of eight directions, 45 degrees apart (direction k at angle
/// k pi / 4), the vertex of a polygon (stored numbering) whose offset from
/// a centre c has the largest component along it, in double: the vertex
/// that reaches farthest that way. Two polygons that overlap by much of
/// their area most often have such a vertex of one deep inside the other,
/// where vertices spread along the rings lie mostly about the far side.
/// Built in linear time (eight dot products per vertex).
class reaching_vertices {
public:
    /// The directions' count.
    static constexpr std::size_t directions = 8;
    /// The vertices toward() returns.
    static constexpr std::size_t probes = 3;

    /// No vertex: toward() is not to be asked.
    reaching_vertices() = default;

    /// The table for p's vertices about c (p not kept; all zero for an
    /// empty polygon).
    reaching_vertices(const polygon& p, const point<double>& c) {
        std::array<double, directions> best;
        best.fill(-HUGE_VAL);
        for (std::size_t j = 0; j < p.size(); ++j) {
            const double x = p.vertex(j).x - c.x, y = p.vertex(j).y - c.y;
            for (std::size_t k = 0; k < directions; ++k) {
                const double along = unit[k][0] * x + unit[k][1] * y;
                if (along > best[k]) {
                    best[k] = along;
                    vertex_[k] = static_cast<std::uint32_t>(j);
                }
            }
        }
    }

    /// The vertices reaching farthest along the direction nearest to (x, y)
    /// and along its two neighbours, in that order (some may repeat). Any
    /// (x, y), NaN and (0, 0) included, gets three of the table's vertices.
    std::array<std::uint32_t, probes> toward(double x, double y) const {
        const std::size_t k = nearest_direction(x, y);
        return {vertex_[k], vertex_[(k + 1) % directions], vertex_[(k + directions - 1) % directions]};
    }

    /// The direction (0 to 7) nearest to (x, y): the axis when the other
    /// coordinate is within tan(pi / 8) of it, else the diagonal, mirrored
    /// into the quadrant of (x, y).
    static std::size_t nearest_direction(double x, double y) {
        const double ax = std::fabs(x), ay = std::fabs(y);
        std::size_t k = ay <= tan_eighth_turn * ax ? 0 : ax <= tan_eighth_turn * ay ? 2 : 1;
        if (x < 0) k = 4 - k;
        if (y < 0) k = (directions - k) % directions;
        return k;
    }

private:
    /// tan(pi / 8) = sqrt(2) - 1: half-way (in angle) between an axis and a diagonal.
    static constexpr double tan_eighth_turn = 0.41421356237309503;
    /// cos and sin of k pi / 4.
    static constexpr double half_root2 = 0.70710678118654757;
    static constexpr double unit[directions][2] = {
        {1, 0},  {half_root2, half_root2},   {0, 1},  {-half_root2, half_root2},
        {-1, 0}, {-half_root2, -half_root2}, {0, -1}, {half_root2, -half_root2}};
    std::array<std::uint32_t, directions> vertex_{};
};

}  // namespace influence2d
