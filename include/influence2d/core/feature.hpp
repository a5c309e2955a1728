// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Features of a polygon: a vertex, an edge or the interior, by number.

#include <cstddef>
#include <cstdint>

#include "influence2d/core/polygon.hpp"

namespace influence2d {

/// What part of a polygon a feature is.
enum class feature_kind : std::uint8_t {
    vertex,   ///< a vertex, by its input number
    edge,     ///< an edge, by its input number (edge i starts at vertex i)
    interior  ///< the region off the boundary (index unused)
};

/// A part of a polygon: its kind and its number in the input order.
struct feature {
    feature_kind kind;  ///< vertex, edge or interior
    std::size_t index;  ///< the input number of the vertex or edge
};

/// The input number of the polygon's stored vertex i: a ring stored reversed
/// (polygon's constructor reorients it) numbers its vertices backwards.
inline std::size_t input_vertex(const polygon& shape, std::size_t i) {
    std::size_t lo = 0, hi = shape.ring_count();  // the ring of i: the last r with ring_begin(r) <= i
    while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        (shape.ring_begin(mid) <= i ? lo : hi) = mid;
    }
    const std::size_t begin = shape.ring_begin(lo), n = shape.ring_end(lo) - begin;
    return shape.source_edge(begin) == begin ? i : begin + (n - 1 - (i - begin));
}

}  // namespace influence2d
