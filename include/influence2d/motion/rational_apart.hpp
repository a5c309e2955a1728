// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// How much of a motion that turns in the rational model certainly keeps two
/// convex polygons apart: conservative advancement on convex_gap along each
/// piece (docs/sweep.md, "Convex pairs").

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "influence2d/core/feature.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/distance/convex_gap.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/predicates/distance.hpp"
#include "influence2d/predicates/filters.hpp"

#include "influence2d/motion/rational_turn.hpp"
#include "influence2d/motion/turning.hpp"

namespace influence2d {

namespace sweep {

/// The bound, per coordinate, of the distance between a vertex of B posed
/// in double at a piece's time tau (rational_advance's posing) and its place
/// on the exact motion at that tau, relative to r + |T0|_1 + |T1|_1 (r:
/// B's largest distance from its origin; T0, T1: the translations): u = w
/// tau rounds once (|w|, tau <= 1: 2^-53); the turn's cosine and sine
/// (1 - u^2) / (1 + u^2) and 2u / (1 + u^2) then round by a few ulps and
/// move with u by at most 2 |du|, so the turned vertex is within
/// 2^-49 r of the exact one; the base rotation (c, s), |c|, |s| <= 1, and
/// its roundings double that and add 3 ulps of r; the time
/// t0 + tau (t1 - t0) and the translation T0 + t (T1 - T0) round by
/// 2^-51 (|T0|_1 + |T1|_1). 2^-46 covers the sum with a factor of four.
inline constexpr double rational_pose_rounding = 0x1p-46;

/// The least distance, relative to the scene's size, at which rational_advance
/// still advances: a motion that comes closer is left to the exact search
/// (each step there advances by about the distance over the speed, so
/// following a contact down to the rounding would cost more probes than the
/// search saves).
inline constexpr double rational_apart_floor = 0x1p-10;

/// The most probes rational_advance takes per piece.
inline constexpr std::size_t rational_apart_probes = 64;

/// How far beyond where rational_advance stops the search looks first
/// (rational_start::until), in times the time the last gap takes to close
/// at the rate it closed between the last two probes (or at the speed
/// bound after one): the gap's closing accelerates little over so short a
/// time, so that the contact mostly lies within twice that.
inline constexpr double rational_window_reach = 2;

/// The share of the speed bound at which rational_advance takes a gap to
/// close when one probe alone measured it: the bound adds the whole turn's
/// sweep and the whole translation as if both went straight at A (on the
/// turning study's convex 8-gons, a quarter of the bound instead of the
/// whole put the contact in the window on 3 more of the 126 motions where
/// the advancement stops, 108 in all).
inline constexpr double rational_speed_share = 0.25;

/// A bound of (|theta''| + theta'^2) / w^2 over a piece, for its turn
/// theta(tau) = 2 atan(w tau), |w| <= 1: theta' = 2w / (1 + u^2) and
/// theta'' = -4 w^3 tau / (1 + u^2)^2 = -4 w^2 u / (1 + u^2)^2 (u = w tau), so
/// theta'^2 <= 4 w^2 and |theta''| <= 4 w^2 (3 sqrt 3 / 16) = 1.299 w^2 (the
/// largest of u / (1 + u^2)^2, at u^2 = 1 / 3); 5.3 rounds the sum up. A
/// point of B at distance r from its origin accelerates at most at that
/// times w^2 r in tau (the translation is linear in tau).
inline constexpr double rational_turn_acceleration = 5.3;

/// A step of a piece from tau along which every vertex of B stays beyond
/// A's support along the unit axis n by more than `slack` (rational_advance
/// after a probe at tau, in the piece's time): each posed vertex p_j
/// projects to f_j = n.p_j - max_i n.a_i; its derivative in tau is
/// a_j = n.D + theta'(tau) n.J t_j (D the translation's derivative over
/// the piece, t_j = p_j less the translation: the vertex turned, J the right
/// angle), lowered by `lowered` (its roundings), and its second derivative
/// is at least -2k, k = rational_turn_acceleration w^2 r / 2 widened; so
/// f_j(tau + h) >= f_j + a_j h - k h^2 (Taylor, with Lagrange's remainder),
/// above slack while h <= 2 e_j / (sqrt(a_j^2 + 4 k e_j) - a_j), e_j = f_j -
/// slack > 0 (the larger root, in the form that does not cancel; no limit
/// when k = 0 and a_j >= 0). The least over j, shrunk by step_shrinking; 0
/// when some e_j <= 0.
inline double rational_largest_step(const std::vector<point<double>>& av, const std::vector<point<double>>& posed,
                                    const point<double>& move, const point<double>& axis, double w, double tau,
                                    const point<double>& d, double r, double slack, double lowered) {
    // (|n| within 2^-51 of 1: any direction serves, and k's widening
    // covers the rest.)
    const double norm = std::sqrt(axis.x * axis.x + axis.y * axis.y);
    const point<double> n{axis.x / norm, axis.y / norm};
    double reach = -HUGE_VAL;
    for (const point<double>& a : av) reach = std::max(reach, n.x * a.x + n.y * a.y);
    const double u = w * tau, turn_speed = 2 * w / (1 + u * u);
    const double k = rational_turn_acceleration * w * w * r / 2 * (1 + speed_widening);
    const double drift = n.x * d.x + n.y * d.y;
    double step = HUGE_VAL;
    for (const point<double>& p : posed) {
        const double e = n.x * p.x + n.y * p.y - reach - slack;
        if (!(e > 0)) return 0;
        const point<double> turned{p.x - move.x, p.y - move.y};
        const double a = drift + turn_speed * (n.y * turned.x - n.x * turned.y) - lowered;
        const double below = std::sqrt(a * a + 4 * k * e) - a;
        if (below > 0) step = std::min(step, 2 * e / below);
    }
    return step * (1 - step_shrinking);
}

/// How far rational_advance took a rational motion: the whole of it proven
/// free, or where the search must start (rational_start: the motion proven
/// free before it).
struct rational_progress {
    bool apart = false;    ///< the motion certainly keeps A and B apart
    rational_start start;  ///< otherwise: free before this
    /// A's edge and B's that certainly cross at the motion's start, when
    /// the first probe proves so (certain_crossing): the contact at time 0.
    std::optional<std::pair<feature, feature>> crossing_at_start;
};

/// How far conservative advancement proves the rational motion of B from
/// `from` to `to` (rational_pieces) free, A and B convex and in double's
/// safe window (convex_probe_applies; a motion outside it that scales
/// exactly into it by a power of two is advanced so scaled; otherwise
/// nothing is proven): the
/// whole motion, or up to a place where they come within the floor; or a
/// meeting at the start proven by two edges crossing.
///
///   r <- B's vertices' largest distance from its origin
///   delta <- rational_pose_rounding (r + |T0|_1 + |T1|_1)
///   for each piece (c, s, w, t0, t1), tau from 0 to 1:
///       v <- |T1 - T0| (t1 - t0) + 2 |w| r, widened     (no point of B faster in tau:
///            the turn 2 atan(w tau) moves at most at 2 |w|, and (c, s) scales by
///            sqrt(c^2 + s^2) < 1 + 2^-52)
///       loop (at most rational_apart_probes times):
///           B's vertices posed in double at tau; g <- convex_gap from the last simplex
///           at the motion's start, g not converged or not above 0, and an edge of A
///               and one of B certainly crossing (certain_crossing):  meeting at the start
///           L <- g's lower bound - 1.5 delta - 4 v 2^-52   (a lower bound of the exact
///                motion's distance over [tau - the rounding of tau, tau])
///           if g did not converge or L <= floor:  free before (this piece, tau);
///               the contact guessed by tau + reach L / (the rate at which L fell
///               since the last probe, or s share after the first)  (rational_start::until)
///           s <- min(v, approach_speed along g's axis: 2 |w| r less B's translation towards A)
///           h <- L / s, a little less                   (free up to it: the distance
///                                                        falls by at most s a unit of tau)
///           tau + h >= 1:  next piece                   (free through its end)
///           h <- max(h, rational_largest_step along g's axis)   (each vertex's own
///                derivative and a bound of its acceleration keep it beyond A's support)
///           tau + h >= 1:  next piece
///           tau <- tau + h
///   apart
inline rational_progress rational_advance(const polygon& a, const polygon& b, const pose& from, const pose& to) {
    rational_progress out;
    if (from.theta == to.theta) return out;
    // Outside double's safe window, on the input scaled by a power of two
    // when every coordinate scales exactly: the same motion scaled, with
    // the same taus and features, so that every route advances alike
    // whether it scaled the motion itself or not.
    if (const int k = range_shift<double>(a, b, from, to); k != 0) {
        if (!scales_exactly(a, b, k, from, to)) return out;
        return rational_advance(a.scaled_by_power_of_two(k), b.scaled_by_power_of_two(k),
                                scaled_by_power_of_two(from, k), scaled_by_power_of_two(to, k));
    }
    if (!convex_probe_shapes(a, b)) return out;  // (convex_probe_applies, its range_shift known to be 0)
    const double r = bounding_radius(b, {0, 0});
    const double scale = motion_scale(a, b, from, to);
    const double delta =
        rational_pose_rounding * (r + std::fabs(from.tx) + std::fabs(from.ty) + std::fabs(to.tx) + std::fabs(to.ty));
    const double floor = rational_apart_floor * scale;
    // The roundings of a vertex's derivative along an axis
    // (rational_largest_step): its turned place is within 1.5 delta of the
    // exact one along the axis, and turns at most at 2 |w| <= 2 (3 delta);
    // the rest rounds by a few ulps of the speed bound (derivative_slack of
    // it, below).
    const double lowered_by_place = 2 * posing_spread * delta;
    const point<double> shift{to.tx - from.tx, to.ty - from.ty};
    const std::vector<point<double>>& av = a.vertices();
    std::vector<point<double>> posed(b.size());
    convex_gap_result last;
    const std::vector<rational_piece> pieces = rational_pieces(from, to);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const rational_piece& piece = pieces[k];
        const double span = piece.t1 - piece.t0, sweep = 2 * std::fabs(piece.w) * r * (1 + speed_widening);
        const double v = (filter_length(shift.x, shift.y) * span + sweep) * (1 + speed_widening);
        const double lowered = lowered_by_place + derivative_slack * v;
        double tau = 0, last_tau = 0, last_lower = 0;
        for (std::size_t probe = 0;; ++probe) {
            if (probe == rational_apart_probes) return out;
            const double u = piece.w * tau, h = 1 + u * u, c2 = (1 - u * u) / h, s2 = 2 * u / h;
            const double t = piece.t0 + tau * span;
            const point<double> move{from.tx + t * shift.x, from.ty + t * shift.y};
            for (std::size_t j = 0; j < posed.size(); ++j) {
                const point<double>& q = b.vertex(j);
                const double x = c2 * q.x - s2 * q.y, y = s2 * q.x + c2 * q.y;
                posed[j] = {piece.c * x - piece.s * y + move.x, piece.s * x + piece.c * y + move.y};
            }
            const convex_gap_result g = convex_gap(av.data(), av.size(), posed.data(), posed.size(), scale,
                                                   separation_error<double>(scale) / 4, last);
            if (k == 0 && probe == 0 && (!g.converged || !(g.lower > 0))) {
                // At the start B is posed as rotation_pose(from) poses it
                // (the turn's cosine 1 and sine 0 leave it exact).
                if (const std::optional<probe_result> crossing =
                        certain_crossing(a, av, b, posed, posing_error(coordinate_scale(b), from.tx, from.ty))) {
                    out.crossing_at_start.emplace(crossing->static_feature, crossing->moving_feature);
                    return out;
                }
            }
            const double lower = g.lower - posing_spread * delta - 4 * v * time_rounding;
            const auto speed = [&] {
                return std::min(v, approach_speed(g.axis, {shift.x * span, shift.y * span}, sweep, v));
            };
            if (!g.converged || !(lower > floor)) {
                if (g.converged && lower > 0) {
                    const double rate = probe > 0 && last_lower > lower ? (last_lower - lower) / (tau - last_tau)
                                                                        : speed() * rational_speed_share;
                    out.start.until = std::min(1.0, tau + rational_window_reach * lower / rate);
                }
                return out;
            }
            last = g;
            last_tau = tau;
            last_lower = lower;
            // The larger of the distance's step and the vertices' own
            // (rational_largest_step), each free of contact; a step that
            // reaches the piece's end proves the rest of it (no probe
            // there).
            const double by_distance = lower / speed() * (1 - distance_shrinking);
            if (tau + by_distance >= 1) break;
            const double step =
                std::max(by_distance,
                         rational_largest_step(av, posed, move, g.axis, piece.w, tau, {shift.x * span, shift.y * span},
                                               r, g.lower - lower + separation_error<double>(scale), lowered));
            if (tau + step >= 1) break;
            tau += step;
            out.start = {k, tau};
        }
        // (The next piece starts at another formula's pose: its start is
        // not proven.)
        out.start = {k + 1, 0};
    }
    out.apart = true;
    return out;
}

/// The first contact in the rational model (rational_first_contact<NT>),
/// conservative advancement first (rational_advance): time 0 with the two
/// edges when its first probe proves them crossing, no contact when it
/// proves the whole motion free, else the search from where it stopped.
template <class NT>
contact_result<double> advanced_rational_first_contact(const polygon& a, const polygon& b, const pose& from,
                                                       const pose& to) {
    const rational_progress free = rational_advance(a, b, from, to);
    if (free.crossing_at_start) {
        contact_result<double> r;
        r.contact = true;
        std::tie(r.static_feature, r.moving_feature) = *free.crossing_at_start;
        return r;
    }
    return free.apart ? contact_result<double>{} : rational_first_contact<NT>(a, b, from, to, free.start);
}

/// Whether the rational motion of B from `from` to `to` certainly keeps the
/// convex A and B apart (rational_advance proves all of it): false means
/// nothing (they may meet).
inline bool rational_apart(const polygon& a, const polygon& b, const pose& from, const pose& to) {
    return rational_advance(a, b, from, to).apart;
}

}  // namespace sweep

}  // namespace influence2d
