// SPDX-License-Identifier: BSL-1.0
#pragma once
// The queries beyond yes or no that the tool runs per number type: the
// separation at every pose (`collide --separation`), the first contact of
// every motion between consecutive poses (`sweep`, `collide --continuous`),
// and, for the exact types, whether both polygons posed in the world meet
// (`collide --static-poses`).
// number_types.hpp's table points each type at its instantiation here.

#include <cstddef>
#include <string>
#include <vector>

#include "influence2d/core/feature.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/exact/certified_both_posed.hpp"
#include "influence2d/exact/certified_first_contact.hpp"
#include "influence2d/exact/certified_separation.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/query/both_posed.hpp"

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

/// A motion's row from its first contact (the time already a double).
template <class NT>
contact_row row_of(const contact_result<NT>& r, double time) {
    return {r.contact, r.contact || r.step_limit ? time : 0.0, r.static_feature, r.moving_feature, r.step_limit};
}

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

/// A time of NT as the nearest double (exactly rounded for an exact NT).
template <class NT>
double time_as_double(const NT& t) {
    return nearest_double(time_fraction<NT>{t, NT(1)});
}

/// The separation at every pose, in NT, one query object over the poses.
template <class NT>
std::vector<separation_row> separations_in(const polygon& a, const polygon& b, const std::vector<pose>& poses) {
    separation_query<NT> query(a, b);
    std::vector<separation_row> rows;
    rows.reserve(poses.size());
    for (const pose& p : poses) {
        const separation_result<NT> r = query(p);
        rows.push_back({distance_of<NT>(r.squared_distance), r.static_feature, r.moving_feature});
    }
    return rows;
}

/// The separation at every pose, certified: exact features, the distance
/// within one unit in the last place; one query object over the poses.
inline std::vector<separation_row> certified_separations(const polygon& a, const polygon& b,
                                                         const std::vector<pose>& poses) {
    certified_separation_query query(a, b);
    std::vector<separation_row> rows;
    rows.reserve(poses.size());
    for (const pose& p : poses) {
        const certified_separation_result r = query(p);
        rows.push_back({r.distance, r.static_feature, r.moving_feature});
    }
    return rows;
}

/// The first contact of each motion from poses[k] to poses[k + 1], in NT.
template <class NT>
std::vector<contact_row> contacts_in(const polygon& a, const polygon& b, const std::vector<pose>& poses,
                                     const sweep_options& options) {
    std::vector<contact_row> rows;
    for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
        const contact_result<NT> r = first_contact<NT>(a, b, poses[k], poses[k + 1], options);
        rows.push_back(row_of(r, time_as_double(r.time)));
    }
    return rows;
}

/// The first contact of each motion, certified.
inline std::vector<contact_row> certified_contacts(const polygon& a, const polygon& b, const std::vector<pose>& poses,
                                                   const sweep_options& options) {
    std::vector<contact_row> rows;
    for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
        const contact_result<double> r = certified_first_contact(a, b, poses[k], poses[k + 1], options);
        rows.push_back(row_of(r, r.time));
    }
    return rows;
}

/// Whether A posed by pose_a and B posed by pose_b meet, both posed exactly
/// in exact rationals (no rounded relative pose).
inline bool exact_meets_both(const polygon& a, const pose& pose_a, const polygon& b, const pose& pose_b) {
    return intersects<exact_rational>(a, pose_a, b, pose_b);
}

/// The same answer through the certified type, exact rationals for a pose in doubt.
inline bool certified_meets_both(const polygon& a, const pose& pose_a, const polygon& b, const pose& pose_b) {
    return certified_intersects(a, pose_a, b, pose_b);
}

}  // namespace influence2d::cli
