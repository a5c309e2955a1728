// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The first contact of a motion that turns, by conservative advancement on
/// the separation query (docs/sweep.md, "Motions that turn").

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
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
#include "influence2d/distance/convex_gap.hpp"
#include "influence2d/distance/convex_nearest.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/double_word.hpp"
#include "influence2d/number/fallback.hpp"
#include "influence2d/predicates/certain_nearest.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/predicates/convexity.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/query/intersects.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/edge_boxes.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

#include "influence2d/motion/boundaries_apart.hpp"
#include "influence2d/motion/motion.hpp"
#include "influence2d/motion/translation_events.hpp"

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
/// the differences and their length (filter_length: sqrt(x^2 + y^2), three
/// roundings of the squares and the sum and one of the root) round by two
/// ulps or so each (relative 2^-52), r is already an upper bound
/// (bounding_radius); 2^-48 covers the few roundings of the sum with room.
inline constexpr double speed_widening = 0x1p-48;

/// The relative lowering of a vertex's derivative along an axis
/// (convex_probe::largest_step), in units of the speed bound v times
/// 1 + |theta0| + |theta1|: the probe's angle is within
/// 2^-51 (|theta0| + |theta1| + 1) of the exact motion's (motion_rounding),
/// which turns r_j, hence moves its derivative by that times v; a_j's own
/// evaluation rounds by a few ulps of v. 2^-48 covers both with a factor of
/// four.
inline constexpr double derivative_slack = 0x1p-48;

/// The relative shrinking of convex_probe::largest_step's root: its square
/// root, products and divisions round by at most 8 ulps in all; 2^-48 is
/// four times that.
inline constexpr double step_shrinking = 0x1p-48;

/// The most by which a time of the motion moves when it is rounded to a
/// double: a time in [0, 1] rounded to nearest moves by at most 2^-54, and
/// rounded down (the advance's next time) by at most an ulp of 1, 2^-52.
/// Times v, the speed bound, it bounds how far a point of B moves between
/// the time a probe is taken at and the time meant.
inline constexpr double time_rounding = 0x1p-52;

/// The relative widening of the farthest distance at which a probe may stop
/// the advance (advance_limits::stop_reach): undoing the probe's shrinking
/// (distance_shrinking) asks 2^-49, and the bound's own two sums and product
/// round by three units of 2^-53 more; 2^-48 covers both.
inline constexpr double stop_reach_widening = 0x1p-48;

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
    /// A direction n from A towards B along which `distance` is at most the
    /// gap between the projections of A and of posed B on n / |n| (within
    /// the probe's error), or (0, 0) when the probe knows none.
    point<double> axis{0, 0};
    /// The regions certainly meet at the probe's exact pose (two edges
    /// proven to cross there, the features): the distance is exactly 0,
    /// whatever probe asks again.
    bool meeting = false;
};

/// Where conservative advancement stopped: at a contact (`contact`), at the
/// step limit (`limited`, no contact up to t), or at t = 1 without contact.
struct advance_result {
    bool contact = false;  ///< the distance came within the tolerance at t
    bool limited = false;  ///< the step limit stopped it at t, undecided after
    double t = 0;          ///< where it stopped
    probe_result at{};     ///< the probe at t (with contact)
};

/// A bound of the speed at which the gap between the projections of A and
/// of B on the axis n / |n| (n from A towards B) shrinks along a motion
/// whose translation moves at `shift` (T1 - T0 per unit of its time), given
/// `sweep` (the turn's speed bound: |theta1 - theta0| r) and v (the speed
/// bound of every point of B): A stays; a point p of B moves at `shift`
/// plus the turn's part, below sweep in length, so its projection comes
/// towards A at most at sweep - n.shift / |n|. The roundings of that
/// difference (a few ulps of v) are covered by widening it and adding
/// speed_widening v; never more than v.
inline double approach_speed(const point<double>& n, const point<double>& shift, double sweep, double v) {
    const double along = (n.x * shift.x + n.y * shift.y) / filter_length(n.x, n.y);
    return std::max(0.0, sweep - along) * (1 + speed_widening) + speed_widening * v;
}

/// The bounds conservative advancement keeps along a motion (advance).
struct advance_limits {
    double r = 0;           ///< B's vertices' largest distance from its origin (an upper bound)
    double turn = 0;        ///< |theta1 - theta0|
    double v = 0;           ///< the speed bound |T1 - T0| + turn r, widened (speed_widening)
    double delta = 0;       ///< the rounding of the pose at t against the exact motion (motion_rounding)
    double resolution = 0;  ///< 4 (delta + v time_rounding) + 2 error (the error of the probes that decide the stop)
    double tol = 0;         ///< the stopping distance: max(tolerance, resolution)

    /// The limits of the motion of B from `from` to `to`.
    advance_limits(const polygon& b, const pose& from, const pose& to, double tolerance, double error)
        : r(bounding_radius(b, {0, 0})),
          turn(std::fabs(to.theta - from.theta)),
          v((filter_length(to.tx - from.tx, to.ty - from.ty) + turn * r) * (1 + speed_widening)),
          delta(motion_rounding * (r * (std::fabs(from.theta) + std::fabs(to.theta) + 1) + std::fabs(from.tx) +
                                   std::fabs(from.ty) + std::fabs(to.tx) + std::fabs(to.ty))),
          resolution(4 * (delta + v * time_rounding) + 2 * error),
          tol(std::max(tolerance, resolution)) {}

    /// The lower bound of the exact motion's distance at a probe's time
    /// from its distance (within one ulp of a value within `error` of the
    /// exact one): shrunk by an ulp, less the error and delta.
    double lower(double distance, double error) const { return distance * (1 - distance_shrinking) - error - delta; }

    /// Whether a probe's distance stops the advance there (lower <= tol):
    /// monotone in the distance, so that a probe whose exact distance is
    /// at most d stops wherever d does.
    bool stops(double distance, double error) const { return lower(distance, error) <= tol; }

    /// The farthest exact distance at which a probe with error `error` may
    /// stop the advance: its distance d (within an ulp of a value within
    /// error of the exact D) stops where d (1 - distance_shrinking) - error
    /// - delta <= tol, so D <= (tol + error + delta) (1 + 2^-49) + error;
    /// (tol + 2 error + delta) (1 + stop_reach_widening) covers that and its
    /// own roundings.
    double stop_reach(double error) const { return (tol + 2 * error + delta) * (1 + stop_reach_widening); }
};

/// Whether a coarse probe of type P bounds the step after its own probes
/// (convex_probe::largest_step).
template <class P, class = void>
struct steps_by_vertices : std::false_type {};
template <class P>
struct steps_by_vertices<P, std::void_t<decltype(std::declval<const std::decay_t<P>&>().largest_step(
                                0.0, std::declval<const pose&>(), std::declval<const pose&>(), 0.0, 0.0))>>
    : std::true_type {};

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
///   t <- start                   (the motion known free before it; advance_near)
///   loop:
///       L <- probe(motion_pose(t)) shrunk by an ulp, minus its error and delta
///           (a lower bound of the exact motion's distance at t)
///       if L <= tol:  if coarse, refining, and the probe did not prove the
///                       regions meeting: switch to fine, again at t
///                     else contact at t
///       if t = 1:     none
///       if max_steps probes taken (max_steps > 0):  limited at t
///       s <- v; with the probe's axis n:  s <- min(v, approach_speed(n))
///       h <- (L - resolution / 2) / s
///       with the axis, a coarse probe that bounds its own step
///           (convex_probe::largest_step):  h <- max(h, its step)
///       t <- min(1, t + h, rounded down)
///
/// Until the returned t the distance stays above resolution / 2 > 0: no
/// step passes a contact. With an axis n, L bounds the gap of the
/// projections on n, which bounds the distance from below at every time and
/// shrinks no faster than approach_speed(n); largest_step keeps that gap
/// above resolution / 2 too. Each step advances by at least 2^-51.
template <class Coarse, class Fine>
advance_result advance(const polygon& b, const pose& from, const pose& to, double tolerance, std::size_t max_steps,
                       double coarse_error, Coarse&& coarse, bool refine, double fine_error, Fine&& fine,
                       double start = 0) {
    const advance_limits limits(b, from, to, tolerance, refine ? fine_error : coarse_error);
    const double r = limits.r, turn = limits.turn, v = limits.v, resolution = limits.resolution;
    bool fine_stage = false;
    double t = start;
    for (std::size_t probes = 1;; ++probes) {
        const pose p = motion_pose(from, to, t);
        probe_result at = fine_stage ? fine(p) : coarse(p);
        const double error = fine_stage ? fine_error : coarse_error;
        const double lower = limits.lower(at.distance, error);
        if (limits.stops(at.distance, error)) {
            if (refine && !fine_stage && !at.meeting) {
                fine_stage = true;
                continue;
            }
            return {true, false, t, at};
        }
        if (t == 1) return {};
        if (max_steps != 0 && probes >= max_steps) return {false, true, t, {}};
        const bool axis = at.axis.x != 0 || at.axis.y != 0;
        const double speed =
            axis ? std::min(v, approach_speed(at.axis, {to.tx - from.tx, to.ty - from.ty}, turn * r, v)) : v;
        double step = (lower - resolution / 2) / speed * (1 - distance_shrinking);
        if constexpr (steps_by_vertices<Coarse>::value)
            if (axis && !fine_stage)
                step = std::max(step, coarse.largest_step(at.distance - lower + resolution / 2, from, to, r, v));
        t = std::min(1.0, t + step);
    }
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

/// The most vertices of either polygon for which conservative advancement
/// probes a pair of convex polygons by convex_gap: its support points take
/// every vertex (linear in the vertices per iteration), which beyond a few
/// dozen vertices costs more than the separation query's trees.
inline constexpr std::size_t convex_probe_vertices = 64;

/// The most edge pairs convex_probe searches for a certain crossing where
/// convex_gap finds the polygons meeting (a few orientation tests each);
/// the separation query it saves is prepared and searched in about 2 us on
/// 8-gons (the turning study's convex motions that meet at their start took
/// 2.3 us in double with the query, 0.56 us with the search).
inline constexpr std::size_t crossing_search_pairs = 256;

/// The first edge of A and the first of B (in that order) that certainly
/// cross (segments_must_cross) when B's vertices posed in double (`posed`)
/// lie within delta of their exact places, as a probe at distance 0 with
/// those edges, proven meeting (the exact regions cross there); none when
/// none crosses for certain (one polygon inside the other, or edges that
/// only touch), or when there are more than crossing_search_pairs edge
/// pairs. `av` holds A's vertices.
inline std::optional<probe_result> certain_crossing(const polygon& a, const std::vector<point<double>>& av,
                                                    const polygon& b, const std::vector<point<double>>& posed,
                                                    double delta) {
    if (av.size() * posed.size() > crossing_search_pairs) return std::nullopt;
    for (std::size_t i = 0; i < av.size(); ++i) {
        const point<double>&a0 = av[i], &a1 = av[a.next(i)];
        for (std::size_t j = 0; j < posed.size(); ++j)
            if (segments_must_cross(a0, a1, posed[j], posed[b.next(j)], delta))
                return probe_result{
                    0, {feature_kind::edge, a.source_edge(i)}, {feature_kind::edge, b.source_edge(j)}, {0, 0}, true};
    }
    return std::nullopt;
}

/// Whether A and B are shapes convex_probe takes: both one convex ring
/// (is_convex_polygon, exact) of at most convex_probe_vertices vertices.
inline bool convex_probe_shapes(const polygon& a, const polygon& b) {
    return a.size() <= convex_probe_vertices && b.size() <= convex_probe_vertices && is_convex_polygon(a) &&
           is_convex_polygon(b);
}

/// Whether the motion of B against A is probed by convex_probe: shapes it
/// takes (convex_probe_shapes), and every coordinate of the motion in
/// double's safe window (range_shift 0), where convex_gap's bounds hold
/// relative to the scene's size.
inline bool convex_probe_applies(const polygon& a, const polygon& b, const pose& from, const pose& to) {
    return range_shift<double>(a, b, from, to) == 0 && convex_probe_shapes(a, b);
}

/// A probe of conservative advancement for two convex polygons: B's
/// vertices posed in double, then convex_gap from the last search's simplex.
/// Its distance is convex_gap's lower bound, with the axis; the search
/// stops when its bounds come within a quarter of separation_error<double>
/// of each other, so that the distance is within separation_error<double>
/// of the exact one (the coarse error advance takes for the separation
/// query in double). Where the search does not converge with the polygons
/// apart (they meet or nearly: the triangle of the simplex holds the
/// origin; rounding stalls it), an edge pair that certainly crosses
/// (certain_crossing) gives distance 0; a pose where none does, or whose
/// nearest features are not two neighbouring vertices of one polygon
/// (collinear vertices), is asked of `general` (a probe on the separation
/// query) instead.
///
/// Features: a simplex of one vertex of B - A is a vertex pair; of two,
/// sharing A's vertex, that vertex and B's edge between the two (sharing
/// B's, the converse); of two that share neither, the two edges (parallel).
template <class General>
class convex_probe {
public:
    /// A probe for A and B (both convex; convex_probe_applies), `scale` the
    /// motion's size (motion_scale), `general` the probe where this one
    /// cannot answer.
    convex_probe(const polygon& a, const polygon& b, double scale, General general)
        : a_shape_(a), b_shape_(b), scale_(scale), b_scale_(coordinate_scale(b)), general_(std::move(general)) {
        a_ = a.vertices();
        posed_.resize(b.size());
    }

    /// The distance at pose p (see the class comment).
    probe_result operator()(const pose& p) {
        last_ = rotation_pose(p);
        for (std::size_t j = 0; j < posed_.size(); ++j) posed_[j] = last_.template apply<double>(b_shape_.vertex(j));
        const convex_gap_result g = convex_gap(a_.data(), a_.size(), posed_.data(), posed_.size(), scale_,
                                               separation_error<double>(scale_) / 4, last_gap_);
        if (!g.converged || !(g.lower > 0)) {
            if (const std::optional<probe_result> crossing =
                    certain_crossing(a_shape_, a_, b_shape_, posed_, posing_error(b_scale_, p.tx, p.ty)))
                return *crossing;
            return general_(p);
        }
        probe_result r;
        if (!features(g, r)) return general_(p);
        last_gap_ = g;
        r.distance = g.lower;
        r.axis = g.axis;
        return r;
    }

    /// After a probe that returned an axis n (unit n^ = n / |n|): a step h
    /// of the exact motion from the probe's time along which the gap of the
    /// projections on n^ stays above `slack` below its value there (slack:
    /// the probe's error, the posing's rounding and the margin advance
    /// keeps). Each vertex j of B, turned by the probe's angle to r_j,
    /// projects to f_j = n^.(T + r_j) - max_i n^.a_i; along the motion
    /// its derivative is a_j = n^.(T1 - T0) + (theta1 - theta0) n^.J r_j
    /// (J the right angle) and its second derivative
    /// -(theta1 - theta0)^2 n^.R r_j, at least -k with
    /// k = (theta1 - theta0)^2 r / 2 times two, r bounding |r_j|; so
    /// f_j(t + h) >= f_j(t) + a_j h - k h^2 (Taylor, with Lagrange's
    /// remainder), above f_j - e_j where e_j = f_j - slack > 0 as long as
    ///     h <= h_j = 2 e_j / (sqrt(a_j^2 + 4 k e_j) - a_j)
    /// (the larger root, in the form that does not cancel; infinite when
    /// k = 0 and a_j >= 0). The step is the least h_j shrunk by
    /// step_shrinking; a_j is lowered by derivative_slack (the roundings
    /// of a_j and of the probe's angle) and k raised by speed_widening.
    /// Unlike approach_speed's bound, the derivative is the vertex's own:
    /// a motion that turns towards A slowly steps far.
    double largest_step(double slack, const pose& from, const pose& to, double r, double v) const {
        const double turn = to.theta - from.theta;
        const point<double> shift{to.tx - from.tx, to.ty - from.ty};
        const point<double>& axis = last_gap_.axis;
        const double norm = filter_length(axis.x, axis.y);
        const point<double> n{axis.x / norm, axis.y / norm};
        double reach = -HUGE_VAL;
        for (const point<double>& a : a_) reach = std::max(reach, n.x * a.x + n.y * a.y);
        const double k = turn * turn * r / 2 * (1 + speed_widening);
        const double lowered = derivative_slack * v * (1 + std::fabs(from.theta) + std::fabs(to.theta));
        const double drift = n.x * shift.x + n.y * shift.y;
        double step = HUGE_VAL;
        for (std::size_t j = 0; j < posed_.size(); ++j) {
            const double e = n.x * posed_[j].x + n.y * posed_[j].y - reach - slack;
            if (!(e > 0)) return 0;
            const point<double>& b = b_shape_.vertex(j);
            const point<double> turned{last_.c * b.x - last_.s * b.y, last_.s * b.x + last_.c * b.y};
            const double a = drift + turn * (n.y * turned.x - n.x * turned.y) - lowered;
            const double below = std::sqrt(a * a + 4 * k * e) - a;
            if (below > 0) step = std::min(step, 2 * e / below);
        }
        return step * (1 - step_shrinking);
    }

private:
    // The features of g's simplex into r; false when two of its vertices on
    // one polygon are not neighbours.
    bool features(const convex_gap_result& g, probe_result& r) const {
        const difference_vertex &p = g.simplex[0], &q = g.simplex[g.points - 1];
        const auto side = [](const polygon& shape, std::uint32_t i, std::uint32_t j, feature& f) {
            if (i == j) {
                f = {feature_kind::vertex, input_vertex(shape, i)};
                return true;
            }
            const std::size_t e = shape.next(i) == j ? i : shape.next(j) == i ? j : shape.size();
            if (e == shape.size()) return false;
            f = {feature_kind::edge, shape.source_edge(e)};
            return true;
        };
        return side(a_shape_, p.i, q.i, r.static_feature) && side(b_shape_, p.j, q.j, r.moving_feature);
    }

    const polygon& a_shape_;
    const polygon& b_shape_;
    double scale_;
    double b_scale_;  // B's largest coordinate (posing_error)
    General general_;
    std::vector<point<double>> a_;
    std::vector<point<double>> posed_;  // B's vertices at the last probe
    rotation_pose last_{pose{}};        // the last probe's pose
    convex_gap_result last_gap_;        // the last converged search (its simplex starts the next; its axis)
};

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

/// The most vertex-edge pairs that may come near (boundaries_near) for
/// which conservative advancement probes them alone (pairs_probe) instead
/// of the separation query: on the turning study's contour 64-gons (half
/// their motions that come near have 18 near pairs or fewer, a tenth 60 or
/// more) the certified answer took 14.3, 12.7 and 12.9 us a motion with
/// limits of 48, 96 and 160.
inline constexpr std::size_t near_pairs_limit = 96;

/// The squared distance in NT from the vertex of a site to the other's
/// closed edge (closest_on_segment), in A's frame with B posed by `placed`,
/// and the features at that distance: the edge, or the end of it nearest.
template <class NT>
std::pair<NT, std::pair<feature, feature>> site_distance(const polygon& a, const polygon& b, const contact_site& s,
                                                         const rotation_pose& placed) {
    using tr = number_traits<NT>;
    const auto in_a = [&](std::size_t i) {
        return point<NT>{tr::from_double(a.vertex(i).x), tr::from_double(a.vertex(i).y)};
    };
    const auto in_b = [&](std::size_t j) { return placed.apply<NT>(b.vertex(j)); };
    const polygon& edges = s.moving_vertex ? a : b;
    const segment_point<NT> c = s.moving_vertex
                                    ? closest_on_segment(in_b(s.vertex), in_a(s.edge), in_a(a.next(s.edge)))
                                    : closest_on_segment(in_a(s.vertex), in_b(s.edge), in_b(b.next(s.edge)));
    const feature on_edge = c.part == segment_part::interior ? feature{feature_kind::edge, edges.source_edge(s.edge)}
                            : c.part == segment_part::start
                                ? feature{feature_kind::vertex, input_vertex(edges, s.edge)}
                                : feature{feature_kind::vertex, input_vertex(edges, edges.next(s.edge))};
    const feature vertex{feature_kind::vertex, input_vertex(s.moving_vertex ? b : a, s.vertex)};
    return {c.squared, s.moving_vertex ? std::pair{on_edge, vertex} : std::pair{vertex, on_edge}};
}

/// A probe on the vertex-edge pairs `pairs` alone (boundaries_near's), at
/// pose p: the least of their distances, each as distance_of rounds it
/// (`distance(site, placed)` gives it with its features), ties to the
/// first. While the polygons are apart and the pairs left out stay beyond
/// any probe's stop_reach, that is the polygons' distance wherever a probe
/// of it may stop, and otherwise above that reach, as theirs is: the
/// stop at each probe's time is the separation query's there, and each
/// step keeps every pair apart (the pairs left out stay apart by their
/// boxes).
template <class Distance>
probe_result pairs_probe(const std::vector<contact_site>& pairs, const pose& p, Distance&& distance) {
    const rotation_pose placed(p);
    probe_result best;
    best.distance = std::numeric_limits<double>::infinity();
    for (const contact_site& site : pairs) {
        const auto [d, features] = distance(site, placed);
        if (d < best.distance) {
            best.distance = d;
            std::tie(best.static_feature, best.moving_feature) = features;
        }
    }
    return best;
}

/// The distance of a site in a floating NT (site_distance), as distance_of
/// rounds it: within separation_error<NT> of the exact one (the posing and
/// the few products and one quotient of closest_on_segment round by less
/// than separation's own computations).
template <class NT>
std::pair<double, std::pair<feature, feature>> rounded_site_distance(const polygon& a, const polygon& b,
                                                                     const contact_site& s,
                                                                     const rotation_pose& placed) {
    const auto [squared, features] = site_distance<NT>(a, b, s, placed);
    return {distance_of<NT>(squared), features};
}

/// The exact distance of a site (site_distance in the exact field Exact) as
/// distance_of rounds it: in double words first, their value rounded by its
/// bound (certain_nearest) and its signs certain, else in Exact.
template <class Exact>
std::pair<double, std::pair<feature, feature>> exact_site_distance(const polygon& a, const polygon& b,
                                                                   const contact_site& s, const rotation_pose& placed) {
    return fallback<>::run(
        [&] {
            const auto [squared, features] = site_distance<double_word>(a, b, s, placed);
            double nearest;
            if (!certain_nearest(squared, nearest)) throw uncertain_sign();
            return std::pair{std::sqrt(nearest), features};
        },
        [&] { return rounded_site_distance<Exact>(a, b, s, placed); });
}

/// How advance runs for two polygons that are not both convex: where they
/// meet at `from` (`met`, exactly in an exact route), a contact at 0;
/// otherwise from where boundaries_near proves every vertex farther than
/// any probe's stop_reach from the other's edges until (no contact when
/// that is the whole motion): the polygons stay apart there, and no probe
/// there would stop; on their near pairs alone (pairs_probe, `coarse_pairs`
/// and `fine_pairs`) when there are at most near_pairs_limit, else on
/// `coarse` and `fine`. `error` is the coarse probes' error, `refine`
/// whether the fine ones decide the stop (error 0).
template <class Coarse, class Fine, class CoarsePairs, class FinePairs>
advance_result advance_near(const polygon& a, const polygon& b, const pose& from, const pose& to,
                            const sweep_options& options, const std::optional<std::pair<feature, feature>>& met,
                            double error, bool refine, Coarse&& coarse, Fine&& fine, CoarsePairs&& coarse_pairs,
                            FinePairs&& fine_pairs) {
    if (met) return {true, false, 0, {0, met->first, met->second}};
    const advance_limits limits(b, from, to, options.tolerance, refine ? 0 : error);
    const near_boundaries near = boundaries_near(a, b, from, to, limits.stop_reach(error), near_pairs_limit);
    if (near.start > 1) return {};
    if (near.all) {
        const auto coarse_probe = [&](const pose& p) { return pairs_probe(near.pairs, p, coarse_pairs); };
        const auto fine_probe = [&](const pose& p) { return pairs_probe(near.pairs, p, fine_pairs); };
        return advance(b, from, to, options.tolerance, options.max_steps, error, coarse_probe, refine, 0, fine_probe,
                       near.start);
    }
    return advance(b, from, to, options.tolerance, options.max_steps, error, coarse, refine, 0, fine, near.start);
}

/// Advance with a refining stage: the coarse probe `general` (on the
/// separation query in double, coarse_probe), or a convex_probe over it
/// when convex_probe_applies, then `fine`; other pairs by advance_near,
/// the meeting at the start and the near pairs' distances exact (in Exact
/// where double words leave a doubt).
template <class Exact, class General, class Fine>
advance_result advance_refined(const polygon& a, const polygon& b, const pose& from, const pose& to,
                               const sweep_options& options, General&& general, Fine&& fine) {
    const double scale = motion_scale(a, b, from, to), error = separation_error<double>(scale);
    if (convex_probe_applies(a, b, from, to))
        return advance(b, from, to, options.tolerance, options.max_steps, error,
                       convex_probe(a, b, scale, std::ref(general)), true, 0, fine);
    const auto met = fallback<>::run([&] { return meeting_at_start<certified>(a, b, from, rotation_pose(from)); },
                                     [&] { return meeting_at_start<Exact>(a, b, from, rotation_pose(from)); });
    return advance_near(
        a, b, from, to, options, met, error, true, general, fine,
        [&](const contact_site& s, const rotation_pose& placed) {
            return rounded_site_distance<double>(a, b, s, placed);
        },
        [&](const contact_site& s, const rotation_pose& placed) {
            return exact_site_distance<Exact>(a, b, s, placed);
        });
}

/// The first contact of a motion that turns, in NT: conservative
/// advancement on separation queries (both polygons prepared once, each
/// search started from the last closest pair), or for two small convex
/// polygons on convex_probe (the separation query where it does not
/// converge); other pairs by advance_near (from where their swept boxes
/// prove them apart, on their near pairs alone when few). A floating NT steps on its own query (double on convex_probe
/// where it applies). An exact NT steps on the query in double (with its
/// error bound; coarse_probe), or convex_probe, and, once that would stop,
/// on its own exact query: the stop is decided on exact distances (a probe
/// that proves two edges crossing is exact already: distance 0). A motion
/// whose largest coordinate lies outside double's safe window is answered
/// there on its input scaled by a power of two, the tolerance with it, when
/// every coordinate scales exactly (as filtered_first_contact does, so that
/// both take the same steps).
template <class NT>
contact_result<NT> turning_first_contact(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                         const sweep_options& options) {
    const double scale = motion_scale(a, b, from, to);
    if constexpr (number_traits<NT>::category == number_category::floating) {
        std::optional<separation_query<NT>> query;
        const auto probe = [&](const pose& p) {
            if (!query) query.emplace(a, b);
            return probe_of(*query, p);
        };
        if constexpr (std::is_same_v<NT, double>) {
            if (convex_probe_applies(a, b, from, to)) {
                convex_probe convex(a, b, scale, probe);
                return turning_result<NT>(advance(b, from, to, options.tolerance, options.max_steps,
                                                  separation_error<NT>(scale), convex, false, 0, convex));
            }
        }
        const auto site = [&](const contact_site& s, const rotation_pose& placed) {
            return rounded_site_distance<NT>(a, b, s, placed);
        };
        return turning_result<NT>(advance_near(a, b, from, to, options,
                                               meeting_at_start<NT>(a, b, from, rotation_pose(from)),
                                               separation_error<NT>(scale), false, probe, probe, site, site));
    } else {
        if (const int k = range_shift<double>(a, b, from, to); k != 0 && scales_exactly(a, b, k, from, to)) {
            sweep_options scaled = options;
            scaled.tolerance = scaled_length(options.tolerance, k);
            return turning_first_contact<NT>(a.scaled_by_power_of_two(k), b.scaled_by_power_of_two(k),
                                             scaled_by_power_of_two(from, k), scaled_by_power_of_two(to, k), scaled);
        }
        std::optional<separation_query<double>> coarse;
        std::optional<separation_query<NT>> fine_query;
        const auto fine = [&](const pose& p) {
            if (!fine_query) fine_query.emplace(a, b);
            return probe_of(*fine_query, p);
        };
        const auto general = [&](const pose& p) {
            if (!coarse) coarse.emplace(a, b);
            return coarse_probe(*coarse, p, fine);
        };
        return turning_result<NT>(advance_refined<NT>(a, b, from, to, options, general, fine));
    }
}

/// The exact distance at pose p between the convex A and B (convex_probe_applies)
/// and their nearest features, when convex_gap's nearest pair there is
/// proven the unique nearest one (nearest_convex_pair: in `certified`, in
/// Exact when a sign is in doubt); its squared distance in double words,
/// rounded by its bound as distance_of rounds the exact one
/// (certain_nearest, for values in [word_floor, word_ceiling]), or in Exact
/// when that rounding is in doubt. None when the proof fails (the polygons
/// meet or touch, the nearest pair is not unique or not the candidate): the
/// caller asks the separation then. When `stops` (the caller's test of a
/// distance, monotone: advance_limits::stops) holds for an upper bound of
/// the exact distance (convex_gap's upper bound at B posed in double, plus
/// the posing's rounding), that bound instead of the distance: the caller
/// stops there as at the exact distance, and the squared distance is not
/// evaluated.
template <class Exact, class Stops>
std::optional<probe_result> certified_convex_probe(const polygon& a, const polygon& b, const pose& p, double scale,
                                                   Stops&& stops) {
    std::vector<point<double>> av(a.size()), posed(b.size());
    const rotation_pose placed(p);
    for (std::size_t i = 0; i < a.size(); ++i) av[i] = a.vertex(i);
    for (std::size_t j = 0; j < b.size(); ++j) posed[j] = placed.apply<double>(b.vertex(j));
    const convex_gap_result hint =
        convex_gap(av.data(), av.size(), posed.data(), posed.size(), scale, separation_error<double>(scale) / 4, {});
    if (!hint.converged || !(hint.upper > 0)) return std::nullopt;
    const std::optional<convex_nearest> n =
        fallback<>::run([&] { return nearest_convex_pair<certified>(a, b, p, hint); },
                        [&] { return nearest_convex_pair<Exact>(a, b, p, hint); });
    if (!n) return std::nullopt;
    // (The exact B lies within posing_error of the posed one per coordinate:
    // the distance moves by at most posing_spread times it.)
    const double upper =
        (hint.upper + posing_spread * posing_error(coordinate_scale(b), p.tx, p.ty)) * (1 + distance_shrinking);
    if (stops(upper)) return probe_result{upper, n->static_feature, n->moving_feature};
    const double distance = fallback<>::run(
        [&] {
            double squared;
            if (!certain_nearest(nearest_pair_squared<double_word>(a, b, p, *n), squared)) throw uncertain_sign();
            return std::sqrt(squared);
        },
        [&] { return distance_of<Exact>(nearest_pair_squared<Exact>(a, b, p, *n)); });
    return probe_result{distance, n->static_feature, n->moving_feature};
}

/// As turning_first_contact in the exact field Exact, the fine probe being
/// `Fine{}(a, b, p)`, whose answer has the exact distance rounded as
/// distance_of rounds it (`distance`) and the exact features
/// (certified_separation_of, exact/certified_separation.hpp: the separation
/// in double words, in exact rationals where their bounds leave a sign in
/// doubt); with Fine void, separation<Exact> on the polygons. Either gives
/// the exact route's distances: the same steps, so the same answer. For
/// two convex polygons (convex_probe_applies) certified_convex_probe answers
/// first: a nearest pair proven unique is the one every exact route finds.
template <class Exact, class Fine = void>
contact_result<double> filtered_turning_first_contact(const polygon& a, const polygon& b, const pose& from,
                                                      const pose& to, const sweep_options& options) {
    std::optional<separation_query<double>> coarse;
    std::optional<bool> convex;            // (convex_probe_applies, asked on the first fine probe)
    std::optional<advance_limits> limits;  // (advance's, with the exact fine probe's error 0)
    const auto fine = [&](const pose& p) {
        if (!convex) convex = convex_probe_applies(a, b, from, to);
        if (*convex) {
            if (!limits) limits.emplace(b, from, to, options.tolerance, 0.0);
            if (const std::optional<probe_result> n = certified_convex_probe<Exact>(
                    a, b, p, motion_scale(a, b, from, to), [&](double d) { return limits->stops(d, 0); }))
                return *n;
        }
        if constexpr (std::is_void_v<Fine>) {
            const separation_result<Exact> s = separation<Exact>(a, b, p);
            return probe_result{distance_of<Exact>(s.squared_distance), s.static_feature, s.moving_feature};
        } else {
            const auto s = Fine{}(a, b, p);
            return probe_result{s.distance, s.static_feature, s.moving_feature};
        }
    };
    const auto general = [&](const pose& p) {
        if (!coarse) coarse.emplace(a, b);
        return coarse_probe(*coarse, p, fine);
    };
    return turning_result<double>(advance_refined<Exact>(a, b, from, to, options, general, fine));
}

}  // namespace sweep

}  // namespace influence2d
