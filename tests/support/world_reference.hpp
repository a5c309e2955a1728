// SPDX-License-Identifier: BSL-1.0
#pragma once
// The exact contacts of many bodies, for the world's tests and its fuzz
// target: every pair of live bodies, not both fixed, placed exactly on
// CGAL's Cartesian kernel over exact rationals and tested by its own
// predicates (support/exact_regions.hpp; CGAL's squared_distance for a
// distance), never the world's broad phase, witnesses or the library's
// pair tests.

#include <CGAL/squared_distance_2.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/world/world.hpp"
#include "support/exact_regions.hpp"

namespace test_world {

/// A body as the reference sees it.
struct body_state {
    std::size_t shape = 0;
    influence2d::pose where;
    bool fixed = false;
    bool alive = true;
};

/// Whether two exactly placed polygons are within d (d = 0: meet): their
/// regions meet, or an edge pair is within d by CGAL's exact squared
/// distance. Edge boxes (which hold the exact edges) more than 2d apart on an
/// axis hold no pair within d, and two polygons whose boxes (the union of
/// their edge boxes) are so far apart are neither.
inline bool exact_within(const test_exact::placed_shape& a, const test_exact::placed_shape& b, double d) {
    const auto far = [&](const CGAL::Bbox_2& l, const CGAL::Bbox_2& r) {
        return l.xmin() - r.xmax() > 2 * d || r.xmin() - l.xmax() > 2 * d || l.ymin() - r.ymax() > 2 * d ||
               r.ymin() - l.ymax() > 2 * d;
    };
    if (far(a.box, b.box)) return false;
    if (test_exact::regions_meet(a, b)) return true;
    if (d == 0) return false;
    const test_exact::FT d2 = test_exact::FT(d) * test_exact::FT(d);
    for (std::size_t i = 0; i < a.v.size(); ++i)
        for (std::size_t j = 0; j < b.v.size(); ++j) {
            if (far(a.edge_box[i], b.edge_box[j])) continue;
            const test_exact::segment_2 s(a.v[i], a.end(i)), t(b.v[j], b.end(j));
            if (CGAL::squared_distance(s, t) <= d2) return true;
        }
    return false;
}

/// The reference contacts: every pair of live bodies, not both fixed.
inline std::vector<influence2d::body_pair> reference_contacts(const std::vector<influence2d::polygon>& shapes,
                                                              const std::vector<body_state>& bodies, double d) {
    std::vector<std::optional<test_exact::placed_shape>> placed(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].alive) placed[i] = test_exact::place(shapes[bodies[i].shape], bodies[i].where);
    std::vector<influence2d::body_pair> out;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            if (!bodies[i].alive || !bodies[j].alive || (bodies[i].fixed && bodies[j].fixed)) continue;
            if (exact_within(*placed[i], *placed[j], d))
                out.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
        }
    return out;
}

}  // namespace test_world
