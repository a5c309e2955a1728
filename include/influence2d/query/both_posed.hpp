// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether two polygons meet when both are placed in one frame: by vertices
/// given in NT, or each by its own pose in the world (docs/sweep.md, "Both
/// polygons moving").

#include <algorithm>
#include <cmath>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/query/intersects.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d {

/// Whether the closed regions of A and B meet, given their vertices already
/// placed in one frame in NT (`a_vertices[i]` is A's stored vertex i, in the
/// polygon's stored order; likewise for B): the one-shot query's steps
/// (intersects in query/intersects.hpp) after its posing. Touching counts; one
/// inside a hole of the other does not meet it. Exact when NT is (the edge
/// pairs whose boxes overlap tested exactly, and one vertex per ring
/// located in the other polygon); a filtered NT may throw uncertain_sign.
///
/// The filters run on number_traits<NT>::to_double of the vertices, widened
/// by filter_slack times `scale`: `scale` must bound the magnitudes the
/// vertices were computed from (their rounding is relative to it). The
/// default, 0, takes the largest coordinate of the vertices themselves,
/// which holds for exact values and for values rounded once; pass the scale
/// of the inputs for values a filtered NT computed through cancellations
/// (a translation far larger than the polygon it moves).
///
/// In float, double and long double, vertices far from 1 in scale are
/// answered scaled by a power of two (core/range_scaling.hpp), `scale` with
/// them. Throws invalid_input for an empty polygon or a count of vertices
/// that is not the polygon's.
template <class NT>
bool regions_meet(const polygon& a, const std::vector<point<NT>>& a_vertices, const polygon& b,
                  const std::vector<point<NT>>& b_vertices, double scale = 0) {
    accepted_polygon<NT>(a, "first");
    accepted_polygon<NT>(b, "second");
    if (a_vertices.size() != a.size() || b_vertices.size() != b.size())
        throw invalid_input("regions_meet: the vertices given are not as many as the polygon's");
    if constexpr (scaled_into_range_v<NT>) {
        double largest = std::max(largest_coordinate(a), largest_coordinate(b));
        for (const std::vector<point<NT>>* vs : {&a_vertices, &b_vertices})
            for (const point<NT>& v : *vs)
                largest = std::max({largest, static_cast<double>(std::fabs(v.x)), static_cast<double>(std::fabs(v.y))});
        if (const int k = range_shift<NT>(largest)) {
            const auto scaled = [k](const std::vector<point<NT>>& vs) {
                std::vector<point<NT>> out;
                out.reserve(vs.size());
                for (const point<NT>& v : vs) out.push_back({std::ldexp(v.x, k), std::ldexp(v.y, k)});
                return out;
            };
            return regions_meet<NT>(a.scaled_by_power_of_two(k), scaled(a_vertices), b.scaled_by_power_of_two(k),
                                    scaled(b_vertices), scaled_length(scale, k));
        }
    }
    placed_polygon<NT> pa(a, a_vertices), pb(b, b_vertices);
    if (!(scale > 0)) {
        for (const box& w : {pa.bounds(), pb.bounds()})
            scale = std::max({scale, std::fabs(w.min_x), std::fabs(w.max_x), std::fabs(w.min_y), std::fabs(w.max_y)});
    }
    return static_cast<bool>(placed_meet(pa, pb, posing_margin<NT>(scale)));
}

/// Whether the closed regions of A posed by pose_a and of B posed by pose_b
/// meet, both moving in the world frame. Each polygon is posed exactly in NT
/// by its own pose (c, s and translation as for intersects), so that the
/// answer in an exact NT is the exact answer for that pair of poses: no
/// relative pose is formed and rounded. Exact when NT is; a filtered NT may
/// throw uncertain_sign. In float, double and long double a query far from 1
/// in scale is answered on its input scaled into the type's range
/// (core/range_scaling.hpp). Throws invalid_input for an empty polygon or a pose
/// component that is NaN or infinite.
///
///   float, double, long double far from 1 in scale: both polygons and
///   translations scaled by a power of two first (the same answer)
///   pose A's and B's vertices in double; e <- their rounding margin
///   the one-shot query's steps on both (boxes, one located vertex per
///   ring, the edge pairs whose boxes overlap), each vertex posed in NT
///   when a decision asks for it
template <class NT>
bool intersects(const polygon& a, const pose& pose_a, const polygon& b, const pose& pose_b) {
    accepted_polygon<NT>(a, "first");
    accepted_polygon<NT>(b, "second");
    const rotation_pose ta(pose_a), tb(pose_b);
    if (const int k = range_shift<NT>(a, b, pose_a, pose_b))
        return intersects<NT>(a.scaled_by_power_of_two(k), scaled_by_power_of_two(pose_a, k),
                              b.scaled_by_power_of_two(k), scaled_by_power_of_two(pose_b, k));
    placed_polygon<NT> pa(a, ta), pb(b, tb);
    const double e = placing_margin<NT>(coordinate_scale(a) + coordinate_scale(b) + std::fabs(pose_a.tx) +
                                        std::fabs(pose_a.ty) + std::fabs(pose_b.tx) + std::fabs(pose_b.ty));
    return static_cast<bool>(placed_meet(pa, pb, e));
}

/// B's pose in A's frame, for a query that takes one moving polygon:
/// theta = theta_b - theta_a, translation R(-theta_a) (t_b - t_a), all in
/// double and so ROUNDED (the cosine and sine of theta_a, the products and
/// the differences): intersects(a, b, relative_pose(pose_a, pose_b)) answers
/// for a B placed within a few ulps of its place relative to A, not exactly
/// at it. The two-pose intersects above answers exactly. Throws
/// invalid_input for a component that is NaN or infinite.
inline pose relative_pose(const pose& pose_a, const pose& pose_b) {
    const rotation_pose ta(pose_a), tb(pose_b);  // (validates both)
    const double dx = pose_b.tx - pose_a.tx, dy = pose_b.ty - pose_a.ty;
    return {ta.c * dx + ta.s * dy, -ta.s * dx + ta.c * dy, pose_b.theta - pose_a.theta};
}

}  // namespace influence2d
