// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The first contact of a motion that turns, by conservative advancement on
/// the separation query (docs/sweep.md, "Motions that turn").

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "influence2d/core/feature.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/fallback.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/query/intersects.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/edge_boxes.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

#include "influence2d/motion/motion.hpp"

namespace influence2d {

namespace sweep {

/// The relative bound of the rounding of a motion's pose at time t in
/// double (motion_pose), against the exact motion: the angle
/// theta0 + t (theta1 - theta0) takes three roundings (the difference, the
/// product, the sum), each below 2^-53 times |theta0| + |theta1| (t <= 1),
/// and its cosine and sine are within 2^-52 (std::cos and std::sin are
/// within an ulp), which moves a point of B at distance r from its origin
/// by less than (2^-51 (|theta0| + |theta1|) + 2^-51) r; the translation's
/// three roundings move it by less than 2^-51 (|T0| + |T1|) per
/// coordinate. 2^-48 times r (|theta0| + |theta1| + 1) + |T0|_1 + |T1|_1
/// covers both with a factor of four.
inline constexpr double motion_rounding = 0x1p-48;

/// The relative widening of the speed bound |T1 - T0| + |theta1 - theta0| r:
/// the differences and std::hypot round by an ulp or two each (relative
/// 2^-52), r is already an upper bound (bounding_radius); 2^-48 covers the
/// few roundings of the sum with room.
inline constexpr double speed_widening = 0x1p-48;

/// The relative shrinking that turns a distance within one unit in the last
/// place of the true one (distance_of in an exact NT, certified_separation)
/// into a lower bound of it: 2^-50 > 2^-52, with room for the rounding of
/// the product itself.
inline constexpr double distance_shrinking = 0x1p-50;

/// The bound of the error of separation<NT>'s distance against the exact
/// distance at the same pose, given the scene's size `scale` (the largest
/// coordinates of A and of B plus the translations): 0 for an exact NT (its
/// distance is exact before distance_of rounds it); for a binary floating NT
/// at least as fine as double whose std::numeric_limits give its p
/// significand bits (double, long double, quad) the bound
/// distance/separation.hpp states for double, 2^-40 scale = 8192 u scale,
/// in NT's own unit u = 2^-p: 2^(13 - p) scale (docs/separation.md: the
/// posing and the products round by multiples of u, about 45u scale in
/// all); for another floating NT (float; GCC's __float128, whose
/// std::numeric_limits strict C++ does not give) its filters' margin,
/// posing_margin (four times filter_slack times scale: 4e-12 for
/// __float128, 4e-4 for float).
template <class NT>
double separation_error(double scale) {
    using tr = number_traits<NT>;
    using limits = std::numeric_limits<NT>;
    if constexpr (tr::category != number_category::floating) {
        return 0;
    } else if constexpr (limits::is_specialized && limits::radix == 2 &&
                         limits::digits >= std::numeric_limits<double>::digits) {
        return std::ldexp(scale, 13 - limits::digits);
    } else {
        return posing_margin<NT>(scale);
    }
}

/// The distance at one time of a turning motion, with the features that
/// realise it (separation's).
struct probe_result {
    double distance = 0;       ///< within one ulp of the separation's distance
    feature static_feature{};  ///< A's feature at that distance
    feature moving_feature{};  ///< B's feature at that distance
};

/// Where conservative advancement stopped: at a contact (`contact`), at the
/// step limit (`limited`, no contact up to t), or at t = 1 without contact.
struct advance_result {
    bool contact = false;  ///< the distance came within the tolerance at t
    bool limited = false;  ///< the step limit stopped it at t, undecided after
    double t = 0;          ///< where it stopped
    probe_result at{};     ///< the probe at t (with contact)
};

/// The earliest time of conservative advancement along the motion from
/// `from` to `to` (docs/sweep.md, "Motions that turn"). A probe gives the
/// distance between A and B posed by a pose (within one unit in the last
/// place of a value within its error of the exact distance there) and its
/// features: `coarse` (error `coarse_error`) takes the steps; when it would
/// stop and `refine` is set, `fine` (error `fine_error`) is asked at the
/// same time and takes the remaining steps, so that the stop is decided
/// within the fine error.
///
///   r <- B's vertices' largest distance from its origin (an upper bound)
///   v <- (|T1 - T0| + |theta1 - theta0| r) widened: no point of B is faster
///   delta <- the rounding of the pose at t against the exact motion
///   resolution <- 4 (delta + v 2^-52) + 2 fine error; tol <- max(tolerance, resolution)
///   t <- 0
///   loop:
///       L <- probe(motion_pose(t)) shrunk by an ulp, minus its error and delta
///           (a lower bound of the exact motion's distance at t)
///       if L <= tol:  if coarse and refining: switch to fine, again at t
///                     else contact at t
///       if t = 1:     none
///       if max_steps probes taken (max_steps > 0):  limited at t
///       t <- min(1, t + (L - resolution / 2) / v, rounded down)
///
/// Until the returned t the distance stays above resolution / 2 > 0: no
/// step passes a contact. Each step advances by at least 2^-51.
template <class Coarse, class Fine>
advance_result advance(const polygon& b, const pose& from, const pose& to, double tolerance, std::size_t max_steps,
                       double coarse_error, Coarse&& coarse, bool refine, double fine_error, Fine&& fine) {
    const double r = bounding_radius(b, {0, 0});
    const double turn = std::fabs(to.theta - from.theta);
    const double v = (std::hypot(to.tx - from.tx, to.ty - from.ty) + turn * r) * (1 + speed_widening);
    const double delta = motion_rounding * (r * (std::fabs(from.theta) + std::fabs(to.theta) + 1) + std::fabs(from.tx) +
                                            std::fabs(from.ty) + std::fabs(to.tx) + std::fabs(to.ty));
    const double resolution = 4 * (delta + v * 0x1p-52) + 2 * (refine ? fine_error : coarse_error);
    const double tol = std::max(tolerance, resolution);
    bool fine_stage = false;
    double t = 0;
    for (std::size_t probes = 1;; ++probes) {
        const pose p = motion_pose(from, to, t);
        probe_result at = fine_stage ? fine(p) : coarse(p);
        const double lower = at.distance * (1 - distance_shrinking) - (fine_stage ? fine_error : coarse_error) - delta;
        if (lower <= tol) {
            if (refine && !fine_stage) {
                fine_stage = true;
                continue;
            }
            return {true, false, t, at};
        }
        if (t == 1) return {};
        if (max_steps != 0 && probes >= max_steps) return {false, true, t, {}};
        const double step = (lower - resolution / 2) / v * (1 - distance_shrinking);
        t = std::min(1.0, t + step);
    }
}

/// The scene's size for separation_error: the polygons' largest
/// coordinates and both translations of the motion.
inline double motion_scale(const polygon& a, const polygon& b, const pose& from, const pose& to) {
    return coordinate_scale(a) + coordinate_scale(b) + std::fabs(from.tx) + std::fabs(from.ty) + std::fabs(to.tx) +
           std::fabs(to.ty);
}

/// A probe on a separation query in NT: its distance (distance_of) and
/// features.
template <class NT>
probe_result probe_of(separation_query<NT>& query, const pose& p) {
    const separation_result<NT> s = query(p);
    return {distance_of<NT>(s.squared_distance), s.static_feature, s.moving_feature};
}

/// A probe on the coarse separation query in double that falls back to
/// `fine` at a pose where double cannot hold the squared distance (the
/// query's std::range_error: the polygons' coordinates outside double's safe
/// window, and their distance underflowing or overflowing once scaled back).
/// The fine probe's error is at most the coarse one's, so advance's bounds
/// hold for either.
template <class Fine>
probe_result coarse_probe(separation_query<double>& coarse, const pose& p, Fine&& fine) {
    try {
        return probe_of(coarse, p);
    } catch (const std::range_error&) {
        return fine(p);
    }
}

/// The result of a turning motion from advance's answer.
template <class NT>
contact_result<NT> turning_result(const advance_result& found) {
    contact_result<NT> r;
    r.step_limit = found.limited;
    if (found.limited) r.time = number_traits<NT>::from_double(found.t);
    if (!found.contact) return r;
    r.contact = true;
    r.time = number_traits<NT>::from_double(found.t);
    r.static_feature = found.at.static_feature;
    r.moving_feature = found.at.moving_feature;
    return r;
}

/// The first contact of a motion that turns, in NT: conservative
/// advancement on separation queries (both polygons prepared once, each
/// search started from the last closest pair). A floating NT steps on its
/// own query. An exact NT steps on the query in double (with its error
/// bound; coarse_probe) and, once that would stop, on its own exact query:
/// the stop is decided on exact distances. A motion whose largest coordinate
/// lies outside double's safe window is answered there on its input scaled
/// by a power of two, the tolerance with it, when every coordinate scales
/// exactly (as filtered_first_contact does, so that both take the same
/// steps).
template <class NT>
contact_result<NT> turning_first_contact(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                         const sweep_options& options) {
    const double scale = motion_scale(a, b, from, to);
    if constexpr (number_traits<NT>::category == number_category::floating) {
        separation_query<NT> query(a, b);
        const auto probe = [&](const pose& p) { return probe_of(query, p); };
        return turning_result<NT>(advance(b, from, to, options.tolerance, options.max_steps,
                                          separation_error<NT>(scale), probe, false, 0, probe));
    } else {
        if (const int k = range_shift<double>(a, b, from, to); k != 0 && scales_exactly(a, b, k, from, to)) {
            sweep_options scaled = options;
            scaled.tolerance = scaled_length(options.tolerance, k);
            return turning_first_contact<NT>(a.scaled_by_power_of_two(k), b.scaled_by_power_of_two(k),
                                             scaled_by_power_of_two(from, k), scaled_by_power_of_two(to, k), scaled);
        }
        separation_query<double> coarse(a, b);
        std::optional<separation_query<NT>> fine_query;
        const auto fine = [&](const pose& p) {
            if (!fine_query) fine_query.emplace(a, b);
            return probe_of(*fine_query, p);
        };
        return turning_result<NT>(advance(
            b, from, to, options.tolerance, options.max_steps, separation_error<double>(scale),
            [&](const pose& p) { return coarse_probe(coarse, p, fine); }, true, 0, fine));
    }
}

/// As turning_first_contact in the exact field Exact, the fine probe being
/// separation<Exact> on the polygons (the exact distance within one ulp and
/// the exact features, its phase 3 filtered): the same steps, so the same
/// answer.
template <class Exact>
contact_result<double> filtered_turning_first_contact(const polygon& a, const polygon& b, const pose& from,
                                                      const pose& to, const sweep_options& options) {
    separation_query<double> coarse(a, b);
    const auto fine = [&](const pose& p) {
        const separation_result<Exact> s = separation<Exact>(a, b, p);
        return probe_result{distance_of<Exact>(s.squared_distance), s.static_feature, s.moving_feature};
    };
    return turning_result<double>(advance(
        b, from, to, options.tolerance, options.max_steps, separation_error<double>(motion_scale(a, b, from, to)),
        [&](const pose& p) { return coarse_probe(coarse, p, fine); }, true, 0, fine));
}

}  // namespace sweep

}  // namespace influence2d
