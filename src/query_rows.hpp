// SPDX-License-Identifier: BSL-1.0
#pragma once
// What the queries beyond yes or no report per pose or motion, in every number
// type: the separation at every pose (`collide --separation`) and the first
// contact of every motion between consecutive poses (`sweep`,
// `collide --continuous`), and how the tool writes them. The queries
// themselves run in number_types.cpp, once per type.

#include <cstddef>
#include <string>
#include <vector>

#include "influence2d/core/feature.hpp"

namespace influence2d::cli {

/// One pose's separation as the tool reports it.
struct separation_row {
    double distance = 0;  ///< between the closed regions, 0 when they meet
    feature static_feature{feature_kind::vertex, 0};
    feature moving_feature{feature_kind::vertex, 0};
};

/// One motion's first contact as the tool reports it.
struct contact_row {
    bool contact = false;
    double t = 0;  ///< the earliest contact time (with contact), or where the step limit stopped
    feature static_feature{feature_kind::vertex, 0};
    feature moving_feature{feature_kind::vertex, 0};
    bool step_limit = false;  ///< undecided after t (contact_result::step_limit)
};

/// The summary line on the motions the step limit left undecided, written
/// `marked` in the output; empty when there are none.
inline std::string step_limit_line(const std::vector<contact_row>& rows, std::size_t max_steps,
                                   const std::string& marked) {
    std::size_t limited = 0;
    for (const contact_row& r : rows) limited += r.step_limit;
    if (!limited) return "";
    return "step limit:      " + std::to_string(limited) + " motion" + (limited == 1 ? "" : "s") +
           " undecided after --max-steps " + std::to_string(max_steps) + " steps (" + marked + " 'limit')\n";
}

/// A feature as the tool writes it: v<number> for a vertex, e<number> for an
/// edge (input numbering, rings one after another), "interior" for the region.
inline std::string feature_text(const feature& f) {
    switch (f.kind) {
    case feature_kind::vertex: return "v" + std::to_string(f.index);
    case feature_kind::edge: return "e" + std::to_string(f.index);
    case feature_kind::interior: break;
    }
    return "interior";
}

}  // namespace influence2d::cli
