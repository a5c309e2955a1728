// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Many bodies and layers answered exactly at nearly double's cost: each pair
/// in `certified`, and again in exact rationals only when one of its signs is
/// not certain.

#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/world/layer_pairs.hpp"
#include "influence2d/world/world.hpp"

namespace influence2d {

/// A world whose every answer is the exact one (each pair's answer that of
/// certified_intersects on the two posed bodies), at nearly double's cost.
using certified_world = world<certified, exact_rational>;

/// The exact answer of layer_pairs (world/layer_pairs.hpp) for one layer.
inline std::vector<body_pair> certified_layer_pairs(const std::vector<polygon>& layer, double within = 0,
                                                    unsigned threads = 1, layer_statistics* statistics = nullptr) {
    return layer_pairs<certified, exact_rational>(layer, within, threads, statistics);
}

/// The exact answer of layer_pairs for two layers.
inline std::vector<body_pair> certified_layer_pairs(const std::vector<polygon>& first,
                                                    const std::vector<polygon>& second, double within = 0,
                                                    unsigned threads = 1, layer_statistics* statistics = nullptr) {
    return layer_pairs<certified, exact_rational>(first, second, within, threads, statistics);
}

}  // namespace influence2d
