// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The candidate edges of a point (docs/method.md section 5): the edges of the
/// static polygon whose extended area of length n holds it.

#include <cstddef>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/predicates/extended_area.hpp"

namespace influence2d {

/// The edges of `covering` (stored numbering, ascending) whose extended area
/// of length n in `shape` holds p, the boundary included (in_extended_area).
/// This is the set the sound detector's candidates must cover for B's
/// centroid p and n = r_B + d; the detector gathers it through a grid and
/// filters widened for rounding, this is its definition, one test per edge.
/// Exact when NT is.
template <class NT>
std::vector<std::size_t> edges_whose_extended_area_holds(extended_area shape, const point<NT>& p,
                                                         const triangle_covering<NT>& covering, const NT& n) {
    std::vector<std::size_t> edges;
    for (std::size_t i = 0; i < covering.size(); ++i)
        if (in_extended_area(shape, p, covering.start(i), covering.end(i), n)) edges.push_back(i);
    return edges;
}

}  // namespace influence2d
