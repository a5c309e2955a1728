// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// How long a motion whose angle is linear in time certainly keeps every
/// vertex of each polygon farther than a margin from every edge of the
/// other: the time conservative advancement may skip (docs/sweep.md,
/// "Motions that turn").

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/influence/bounds.hpp"

#include "influence2d/motion/motion.hpp"
#include "influence2d/motion/swept_boxes.hpp"
#include "influence2d/motion/translation_events.hpp"

namespace influence2d {

namespace sweep {

/// How many parts of equal time each window of boundaries_near is boxed
/// over first (a window turns by at most a quarter turn).
inline constexpr std::size_t apart_parts = 4;

/// How many parts each of those is cut into where a vertex's box meets an
/// edge's: a sixteenth of a quarter turn, pi / 32, bulges by less than
/// 0.25% of its radius.
inline constexpr std::size_t apart_subparts = 4;

/// The most windows of at most a quarter turn boundaries_near boxes:
/// a motion that turns by more is not looked at.
inline constexpr std::size_t apart_windows = 64;

/// The relative bound of the rounding of a pose at a part's end against
/// the exact angle-linear motion (motion_pose's three roundings of the
/// angle and of each translation, std::cos and std::sin within an ulp),
/// for a point at distance at most 2 s from the turn's origin, s the
/// motion's scale (motion_scale: both polygons' largest coordinates and the
/// translations; a vertex of B, or a vertex of A less the translation):
/// below 2^-51 (2 s (|theta0| + |theta1| + 1) + |T0|_1 + |T1|_1), as
/// motion_rounding derives; 2^-48 leaves a factor of eight.
inline constexpr double apart_pose_rounding = 0x1p-48;

/// The poses of the angle-linear motion from `from` to `to` at Parts + 1
/// times of equal steps over [t0, t1] (t1 itself last), as motion_pose
/// makes them: the turn's cosine and sine and the translation; and the
/// bulge factor 1 - cos(theta / 2) = 2 sin^2(theta / 4) of the parts' arcs,
/// theta the largest part's turn.
template <std::size_t Parts>
struct motion_ends {
    std::array<double, Parts + 1> tau;           ///< the times
    std::array<double, Parts + 1> cos;           ///< the turn's cosine at each
    std::array<double, Parts + 1> sin;           ///< the turn's sine at each
    std::array<point<double>, Parts + 1> shift;  ///< the translation at each
    double bulge = 0;                            ///< the parts' bulge factor
};

/// The motion_ends of [t0, t1].
template <std::size_t Parts>
inline motion_ends<Parts> motion_ends_of(const pose& from, const pose& to, double t0, double t1) {
    motion_ends<Parts> out;
    for (std::size_t j = 0; j <= Parts; ++j) {
        out.tau[j] = j == Parts ? t1 : t0 + (t1 - t0) * (static_cast<double>(j) / Parts);
        const pose p = motion_pose(from, to, out.tau[j]);
        out.cos[j] = std::cos(p.theta);
        out.sin[j] = std::sin(p.theta);
        out.shift[j] = {p.tx, p.ty};
    }
    double longest = 0;
    for (std::size_t k = 0; k < Parts; ++k) longest = std::max(longest, out.tau[k + 1] - out.tau[k]);
    const double quarter = std::sin(std::fabs(to.theta - from.theta) * longest / 4);
    out.bulge = 2 * quarter * quarter;
    return out;
}

/// The swept_frame of the motion over the Parts parts whose ends are every
/// Ends / Parts-th of `ends` (Parts divides Ends; the bulge of the whole
/// window's Parts parts, `bulge`), for B's vertices in A's frame or
/// (`inverse`) A's vertices in B's; `slack` every box's absolute slack.
template <std::size_t Parts, std::size_t Ends>
inline swept_frame<Parts> angle_linear_frame(const motion_ends<Ends>& ends, double bulge, bool inverse, double slack) {
    static_assert(Ends % Parts == 0);
    constexpr std::size_t stride = Ends / Parts;
    swept_frame<Parts> out;
    out.slack = slack;
    std::array<point<double>, Parts + 1> shift;
    for (std::size_t j = 0; j <= Parts; ++j) {
        out.tau[j] = ends.tau[j * stride];
        out.cos[j] = ends.cos[j * stride];
        out.sin[j] = inverse ? -ends.sin[j * stride] : ends.sin[j * stride];
        shift[j] = ends.shift[j * stride];
    }
    out.bulge.fill(bulge);
    add_translation(out, inverse, shift);
    return out;
}

/// What boundaries_near finds along an angle-linear motion.
struct near_boundaries {
    /// A time before which every vertex of each polygon stays farther than
    /// the margin from every edge of the other; +infinity when that holds
    /// over the whole motion; 0 when the motion was not looked at.
    double start = 0;
    /// The vertex-edge pairs that may come within the margin (their boxes
    /// over a part meet), in order (site_before), when `all`.
    std::vector<contact_site> pairs;
    bool all = false;  ///< `pairs` holds every such pair (at most the limit)
};

/// The near_boundaries of the angle-linear motion of B from `from` to `to`
/// with `margin`, its pairs when at most `limit`. The motion is not looked
/// at when it turns by more than apart_windows quarter turns or a
/// coordinate lies outside double's safe window.
///
///   k <- the least power of two with |theta1 - theta0| / k <= pi / 2
///   for each of the k windows of equal time, in order:
///     for each vertex of B and edge of A, in A's frame, and each vertex
///     of A and edge of B, in B's frame, whose boxes over the window
///     (apart_parts parts, grown by the margin) meet (for_each_swept_pair):
///       for each part whose box meets the edge's, in order:
///         the first of its apart_subparts parts whose box meets the
///         edge's, if any: the pair kept (while at most `limit`), start
///         <- min(start, that part's start)
///     start found and more than `limit` pairs:       start, no pairs
///   start (+infinity if none found), the pairs kept
///
/// Two polygons apart at time 0 whose boundaries never come within the
/// margin before `start` stay apart until then: the distance between
/// disjoint boundaries is a vertex's distance from an edge; and while they
/// are apart, their distance is the least of their kept pairs' when that
/// is at most the margin.
inline near_boundaries boundaries_near(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                       double margin, std::size_t limit) {
    near_boundaries out;
    if (range_shift<double>(a, b, from, to) != 0) return out;
    const double turn = std::fabs(to.theta - from.theta);
    constexpr double quarter = 1.5707963267948966;  // pi / 2 rounded
    std::size_t windows = 1;
    while (turn / static_cast<double>(windows) > quarter) {
        windows *= 2;
        if (windows > apart_windows) return out;
    }
    const double scale = motion_scale(a, b, from, to);
    const double slack =
        apart_pose_rounding * (2 * scale * (std::fabs(from.theta) + std::fabs(to.theta) + 1) + std::fabs(from.tx) +
                               std::fabs(from.ty) + std::fabs(to.tx) + std::fabs(to.ty)) +
        arc_box_slack * scale + margin + std::numeric_limits<double>::min();
    const boundary_groups ga = boundary_groups_of(a), gb = boundary_groups_of(b);
    out.start = std::numeric_limits<double>::infinity();
    out.all = true;
    constexpr std::size_t fine_parts = apart_parts * apart_subparts;
    swept_scratch<apart_parts> scratch;
    std::vector<std::uint32_t> slot;
    std::vector<std::array<box, fine_parts>> fine_boxes;
    for (std::size_t w = 0; w < windows; ++w) {
        const double t0 = static_cast<double>(w) / static_cast<double>(windows),
                     t1 = static_cast<double>(w + 1) / static_cast<double>(windows);
        const motion_ends<fine_parts> ends = motion_ends_of<fine_parts>(from, to, t0, t1);
        // A coarse part's arc: apart_subparts fine ones, each turning by at
        // most theta; 1 - cos(n theta / 2) <= n^2 (1 - cos(theta / 2))
        // (|sin(n x)| <= n |sin(x)|).
        const double coarse_bulge = ends.bulge * (apart_subparts * apart_subparts);
        for (const bool moving : {true, false}) {
            const polygon &vertices = moving ? b : a, &edges = moving ? a : b;
            const boundary_groups& eg = moving ? ga : gb;
            const swept_frame<apart_parts> coarse = angle_linear_frame<apart_parts>(ends, coarse_bulge, !moving, slack);
            // The fine parts' frame, made when first asked, and the fine
            // parts' boxes of a vertex likewise (slot[v] into fine_boxes).
            std::optional<swept_frame<fine_parts>> fine;
            for_each_swept_pair(
                coarse, vertices, moving ? gb : ga, edges, eg, -std::numeric_limits<double>::infinity(),
                [&](std::size_t v, std::size_t e, const std::array<box, apart_parts>& parts) {
                    for (std::size_t k = 0; k < apart_parts; ++k) {
                        if (!boxes_overlap(parts[k], eg.edges[e])) continue;
                        if (!fine) {
                            fine = angle_linear_frame<fine_parts>(ends, ends.bulge, !moving, slack);
                            slot.assign(vertices.size(), unmade);
                            fine_boxes.clear();
                        }
                        if (slot[v] == unmade) {
                            slot[v] = static_cast<std::uint32_t>(fine_boxes.size());
                            fine_boxes.push_back(swept_parts(*fine, vertices.vertex(v)));
                        }
                        for (std::size_t j = k * apart_subparts; j < (k + 1) * apart_subparts; ++j)
                            if (boxes_overlap(fine_boxes[slot[v]][j], eg.edges[e])) {
                                out.start = std::min(out.start, fine->tau[j]);
                                if (out.all)
                                    out.pairs.push_back(
                                        {moving, static_cast<std::uint32_t>(v), static_cast<std::uint32_t>(e)});
                                return;
                            }
                    }
                },
                scratch);
        }
        if (out.pairs.size() > limit) out.all = false;
        if (!out.all && out.start <= 1) break;
    }
    if (!out.all) {
        out.pairs.clear();
        return out;
    }
    std::sort(out.pairs.begin(), out.pairs.end(), site_before);
    out.pairs.erase(std::unique(out.pairs.begin(), out.pairs.end(),
                                [](const contact_site& x, const contact_site& y) {
                                    return x.moving_vertex == y.moving_vertex && x.vertex == y.vertex &&
                                           x.edge == y.edge;
                                }),
                    out.pairs.end());
    out.all = out.pairs.size() <= limit;
    if (!out.all) out.pairs.clear();
    return out;
}

}  // namespace sweep

}  // namespace influence2d
