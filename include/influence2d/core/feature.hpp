// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Features of a polygon: a vertex, an edge or the interior, by number.

#include <cstddef>
#include <cstdint>

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

}  // namespace influence2d
