// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The first contact of a turning motion in the rational model, exactly
/// (docs/sweep.md, "The rational model"): B turns by a rotation whose
/// cosine and sine are rational functions of time, so that every contact
/// of a vertex with an edge is a root of a cubic whose coefficients are
/// exact in the input's doubles.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/feature.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/shortest_decimal.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/double_word.hpp"
#include "influence2d/number/exact_sum.hpp"
#include "influence2d/number/fallback.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/bernstein_signs.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/predicates/distance.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/polynomial_roots.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/edge_boxes.hpp"
#include "influence2d/scene/placed_polygon.hpp"

#include "influence2d/motion/contact_cubics.hpp"
#include "influence2d/motion/motion.hpp"
#include "influence2d/motion/swept_boxes.hpp"
#include "influence2d/motion/translation_events.hpp"

namespace influence2d {

/// One piece of a rational turning motion (rational_pieces): for t in
/// [t0, t1], with tau = (t - t0) / (t1 - t0) and u = w tau, B is turned by
/// R(c, s) M(u) / (1 + u^2), M(u) = [[1 - u^2, -2u], [2u, 1 - u^2]] (the
/// rotation by 2 atan(u) after the piece's base rotation (c, s)), and
/// translated by from + t (to - from).
struct rational_piece {
    double c = 1;   ///< cos of the piece's base angle, in double
    double s = 0;   ///< sin of the piece's base angle, in double
    double w = 0;   ///< tan of half the piece's turn, in double
    double t0 = 0;  ///< the piece's start: j / k
    double t1 = 1;  ///< the piece's end: (j + 1) / k
};

/// Where rational_first_contact's search starts: the motion is known to keep
/// the polygons apart before piece `piece`, and over [0, tau] of it when tau
/// > 0 (sweep::rational_advance proves so much for convex pairs); a guess
/// of where in that piece the contact lies, searched first.
struct rational_start {
    std::size_t piece = 0;  ///< the first piece searched
    double tau = 0;         ///< free through this tau of it (when > 0)
    /// A guess: the first contact, if any, by this tau of the piece (the
    /// window (tau, until] is searched first when until > tau; no guess
    /// otherwise). Only the work depends on it, not the answer.
    double until = 0;
};

/// The pieces of the rational motion from `from` to `to` (docs/sweep.md):
/// k pieces of equal turn, k the least power of two with |to.theta -
/// from.theta| / k <= pi / 2 (so that |w| <= 1); piece j starts at the
/// angle from.theta + j (to.theta - from.theta) / k (its cosine and sine in
/// double; piece 0's are rotation_pose(from)'s, so the motion starts at the
/// pose every other query takes for `from`) and turns by w = tan((to.theta
/// - from.theta) / 2k) in double. Times j / k are exact doubles. Throws
/// invalid_input for a turn of more than 2^20 quarter turns.
inline std::vector<rational_piece> rational_pieces(const pose& from, const pose& to) {
    const double turn = to.theta - from.theta;
    constexpr double quarter = 1.5707963267948966;  // pi / 2 rounded; a piece may turn by a hair more
    std::size_t k = 1;
    while (std::fabs(turn) / static_cast<double>(k) > quarter) {
        k *= 2;
        if (k > (std::size_t{1} << 20))
            throw invalid_input("first_contact: the motion turns by " + shortest_decimal(turn) +
                                " radians, more than the rational model's 2^20 quarter turns");
    }
    std::vector<rational_piece> out;
    out.reserve(k);
    const double step = turn / static_cast<double>(k);
    const double w = std::tan(step / 2);
    for (std::size_t j = 0; j < k; ++j) {
        const double angle = j == 0 ? from.theta : from.theta + static_cast<double>(j) * step;
        out.push_back({std::cos(angle), std::sin(angle), w, static_cast<double>(j) / static_cast<double>(k),
                       static_cast<double>(j + 1) / static_cast<double>(k)});
    }
    return out;
}

namespace rational_turn_detail {

template <class NT>
NT num(double x) {
    return number_traits<NT>::from_double(x);
}

/// The piece's translation from + t (to - from) at t = t0 + tau (t1 - t0):
/// a0 + a1 tau, exact in NT.
template <class NT>
struct piece_translation {
    point<NT> a0, a1;
};

template <class NT>
piece_translation<NT> translation_of(const rational_piece& piece, const pose& from, const pose& to) {
    const NT dx = NT(num<NT>(to.tx) - num<NT>(from.tx)), dy = NT(num<NT>(to.ty) - num<NT>(from.ty));
    const NT t0 = num<NT>(piece.t0), span = num<NT>(piece.t1 - piece.t0);  // (powers of two: exact)
    return {{NT(num<NT>(from.tx) + t0 * dx), NT(num<NT>(from.ty) + t0 * dy)}, {NT(span * dx), NT(span * dy)}};
}

/// B's vertex v in A's frame over the piece: R(c, s) M(w tau) v + h (a0 + a1 tau).
template <class NT>
moving_point<NT> moving_vertex(const rational_piece& piece, const piece_translation<NT>& t, const point<double>& v) {
    const NT w = num<NT>(piece.w), w2 = NT(w * w), c = num<NT>(piece.c), s = num<NT>(piece.s);
    const NT vx = num<NT>(v.x), vy = num<NT>(v.y);
    // M(u) v = (vx - 2 vy u - vx u^2, vy + 2 vx u - vy u^2), u = w tau.
    const NT mx[3] = {vx, NT(-(vy + vy) * w), NT(-vx * w2)};
    const NT my[3] = {vy, NT((vx + vx) * w), NT(-vy * w2)};
    moving_point<NT> m;
    const NT zero = num<NT>(0);
    for (int k = 0; k < 4; ++k) {
        m.x[k] = zero;
        m.y[k] = zero;
    }
    for (int k = 0; k < 3; ++k) {
        m.x[k] = NT(c * mx[k] - s * my[k]);
        m.y[k] = NT(s * mx[k] + c * my[k]);
    }
    // h (a0 + a1 tau) = a0 + a1 tau + w^2 a0 tau^2 + w^2 a1 tau^3.
    m.x[0] = NT(m.x[0] + t.a0.x);
    m.y[0] = NT(m.y[0] + t.a0.y);
    m.x[1] = NT(m.x[1] + t.a1.x);
    m.y[1] = NT(m.y[1] + t.a1.y);
    m.x[2] = NT(m.x[2] + w2 * t.a0.x);
    m.y[2] = NT(m.y[2] + w2 * t.a0.y);
    m.x[3] = NT(w2 * t.a1.x);
    m.y[3] = NT(w2 * t.a1.y);
    return m;
}

/// A's vertex q in B's frame over the piece, times h (c^2 + s^2): M(-w tau)
/// R(c, s)^T (q - a0 - a1 tau) (the adjugates of M and of R turn back).
template <class NT>
moving_point<NT> moving_static_vertex(const rational_piece& piece, const piece_translation<NT>& t,
                                      const point<double>& q) {
    const NT w = num<NT>(piece.w), w2 = NT(w * w), c = num<NT>(piece.c), s = num<NT>(piece.s);
    const NT qx = NT(num<NT>(q.x) - t.a0.x), qy = NT(num<NT>(q.y) - t.a0.y);
    // v(tau) = R^T (q - a0) - R^T a1 tau = v0 + v1 tau.
    const NT v0x = NT(c * qx + s * qy), v0y = NT(c * qy - s * qx);
    const NT v1x = NT(-(c * t.a1.x + s * t.a1.y)), v1y = NT(-(c * t.a1.y - s * t.a1.x));
    // M(-u) v = (vx + 2u vy - u^2 vx, vy - 2u vx - u^2 vy), u = w tau.
    const NT w_2 = NT(w + w);
    moving_point<NT> m;
    m.x[0] = v0x;
    m.x[1] = NT(v1x + w_2 * v0y);
    m.x[2] = NT(w_2 * v1y - w2 * v0x);
    m.x[3] = NT(-w2 * v1x);
    m.y[0] = v0y;
    m.y[1] = NT(v1y - w_2 * v0x);
    m.y[2] = NT(-w_2 * v1x - w2 * v0y);
    m.y[3] = NT(-w2 * v1y);
    return m;
}

/// A cubic's Bernstein coefficients on an interval (times a positive
/// constant): the cubic lies in their convex hull there, and equals the
/// first and the last at the interval's ends.
template <class Filter>
using bernstein = std::array<Filter, 4>;

/// The Bernstein coefficients on [0, 1], times 3, of the cubic a0 + a1 x +
/// a2 x^2 + a3 x^3: 3 a0, 3 a0 + a1, 3 a0 + 2 a1 + a2, 3 (a0 + a1 + a2 + a3).
template <class Filter>
bernstein<Filter> bernstein_of(const std::array<Filter, 4>& a) {
    const Filter &a0 = a[0], &a1 = a[1], &a2 = a[2], &a3 = a[3];
    const Filter three_a0 = Filter(a0 + a0 + a0);
    return {three_a0, Filter(three_a0 + a1), Filter(three_a0 + a1 + a1 + a2),
            Filter((a0 + a1 + a2 + a3) * num<Filter>(3))};
}

/// The cubic a(tau) (lowest degree first) as a cubic in x for tau = from
/// + d x, d = to - from, in Filter (Taylor's shift at `from`, scaled): a(from),
/// d a'(from), d^2 a''(from) / 2, d^3 a3; so that its Bernstein coefficients
/// on [0, 1] are a's on [from, to].
template <class Filter>
std::array<Filter, 4> on_window(const std::array<Filter, 4>& a, double from, double to) {
    const Filter k = num<Filter>(from), d = Filter(num<Filter>(to) - k), three = num<Filter>(3);
    const Filter a3k = Filter(three * a[3] * k);
    const Filter d2 = Filter(d * d);
    return {Filter(((a[3] * k + a[2]) * k + a[1]) * k + a[0]), Filter(d * ((a3k + a[2] + a[2]) * k + a[1])),
            Filter(d2 * (a3k + a[2])), Filter(d2 * d * a[3])};
}

/// The coefficients on the two halves of the interval (de Casteljau at 1/2).
template <class Filter>
std::pair<bernstein<Filter>, bernstein<Filter>> halves(const bernstein<Filter>& b) {
    const Filter half = num<Filter>(0.5);
    const Filter b01 = Filter((b[0] + b[1]) * half), b12 = Filter((b[1] + b[2]) * half),
                 b23 = Filter((b[2] + b[3]) * half);
    const Filter b012 = Filter((b01 + b12) * half), b123 = Filter((b12 + b23) * half);
    const Filter mid = Filter((b012 + b123) * half);
    return {{b[0], b01, b012, mid}, {mid, b123, b23, b[3]}};
}

/// Whether every coefficient certainly has the strict sign `sign` (a
/// filtered type's doubt: no).
template <class Filter>
bool all_of_sign(const bernstein<Filter>& b, int sign) {
    try {
        for (const Filter& x : b)
            if (number_traits<Filter>::sign(x) != sign) return false;
        return true;
    } catch (const uncertain_sign&) {
        return false;
    }
}

/// The Bernstein coefficients on [0, 1] (times 3) of the cubic whose power
/// coefficients certified holds, in double with one bound
/// (bounded_bernstein::of_power, from their largest bound; a NaN bound
/// infinite): made and halved in double, where certified bounds each
/// operation.
inline bounded_bernstein bounded_of(const std::array<certified, 4>& a) {
    double e = 0;
    for (const certified& x : a) e = std::isnan(x.error()) ? HUGE_VAL : std::max(e, x.error());
    return bounded_bernstein::of_power({a[0].value(), a[1].value(), a[2].value(), a[3].value()}, e);
}
/// Whether every coefficient certainly has the strict sign `sign`.
inline bool all_of_sign(const bounded_bernstein& b, int sign) { return b.of_sign(sign); }
/// The coefficients on the two halves of the interval, with their bound.
inline std::pair<bounded_bernstein, bounded_bernstein> halves(const bounded_bernstein& b) { return b.halves(); }
/// single_sign_change of the coefficients.
inline int single_sign_change(const bounded_bernstein& b) { return b.single_sign_change(); }

/// Where in [from, to] the cubics (their Bernstein coefficients there) may
/// show a contact, the interval cut in halves up to `depth` times: the
/// start of the first part in which f may vanish while lo and hi may both
/// be >= 0, the parts that end at or before `known` (free) left out; none
/// when no part may (f of one strict sign there, or lo or hi negative
/// throughout). Cubic: bernstein<Filter>, or bounded_bernstein (for
/// certified's coefficients).
template <class Cubic>
std::optional<double> first_possible(const Cubic& f, const Cubic& lo, const Cubic& hi, double from, double to,
                                     int depth, double known) {
    if (to <= known) return std::nullopt;
    if (all_of_sign(f, 1) || all_of_sign(f, -1) || all_of_sign(lo, -1) || all_of_sign(hi, -1)) return std::nullopt;
    if (depth == 0) return from;
    const double mid = from + (to - from) / 2;  // (dyadic: exact)
    const auto [f0, f1] = halves(f);
    const auto [lo0, lo1] = halves(lo);
    const auto [hi0, hi1] = halves(hi);
    if (const auto left = first_possible(f0, lo0, hi0, from, mid, depth - 1, known)) return left;
    return first_possible(f1, lo1, hi1, mid, to, depth - 1, known);
}

/// How many times first_possible halves [0, 1]: down to parts of 1/16 of a
/// piece, where a vertex that crosses an edge's line beyond the edge's ends
/// is mostly told apart (each halving costs the halves of three cubics).
inline constexpr int sifting_depth = 4;

/// How many parts of equal time the boxes of a piece's vertices are made
/// over (swept_parts) when the whole piece is searched: a quarter turn's arc
/// boxed whole is as wide as its radius; a quarter of it a quarter as wide,
/// so that fewer edges meet it.
inline constexpr std::size_t box_parts = 4;

/// The turn of a piece at the ends of Parts parts of equal time of a window
/// [from, to] of it (tau), the same for every point: the ends' taus; at u =
/// w tau, the cosine (1 - u^2) / (1 + u^2) and the sine 2u / (1 + u^2) of
/// the turn 2 atan(u); and each part's bulge factor 1 - 1 / sqrt(1 + v^2)
/// (swept_parts).
template <std::size_t Parts>
struct part_turns {
    std::array<double, Parts + 1> tau, cos, sin;
    std::array<double, Parts> bulge;
};

/// The part_turns of the window [from, to] of a piece (its last end `to`
/// itself; on [0, 1] the ends k / Parts, exact for a power of two).
template <std::size_t Parts>
inline part_turns<Parts> turns_of(const rational_piece& piece, double from, double to) {
    part_turns<Parts> out;
    for (std::size_t k = 0; k <= Parts; ++k) {
        out.tau[k] = k == Parts ? to : from + (to - from) * (double(k) / Parts);
        const double u = piece.w * out.tau[k], h = 1 + u * u;
        out.cos[k] = (1 - u * u) / h;
        out.sin[k] = 2 * u / h;
        if (k == 0) continue;
        const double ua = piece.w * out.tau[k - 1];
        const double v = std::fabs(u - ua) / (1 + ua * u);
        out.bulge[k - 1] = 1 - 1 / std::sqrt(1 + v * v);
    }
    return out;
}

/// The swept_frame of the window whose part_turns are `turns`, for B's
/// vertices in A's frame or (`inverse`) A's in B's; `shift` the piece's
/// translation in double, `slack` the absolute slack of every box.
template <std::size_t Parts>
inline sweep::swept_frame<Parts> swept_frame_of(const rational_piece& piece, const part_turns<Parts>& turns,
                                                bool inverse, const piece_translation<double>& shift, double slack) {
    sweep::swept_frame<Parts> out;
    out.slack = slack;
    out.tau = turns.tau;
    out.bulge = turns.bulge;
    std::array<point<double>, Parts + 1> ends;
    for (std::size_t j = 0; j <= Parts; ++j) {
        out.cos[j] = piece.c * turns.cos[j] - piece.s * turns.sin[j];
        out.sin[j] = (piece.s * turns.cos[j] + piece.c * turns.sin[j]) * (inverse ? -1 : 1);
        ends[j] = {shift.a0.x + turns.tau[j] * shift.a1.x, shift.a0.y + turns.tau[j] * shift.a1.y};
    }
    sweep::add_translation(out, inverse, ends);
    return out;
}

/// A pair of features that touch first, found in a piece: its site, its
/// cubic's Sturm sequence and the bracket of the root.
template <class NT>
struct piece_contact {
    sweep::contact_site site;
    std::vector<polynomial<NT>> sequence;
    isolated_root<NT> root;
};

/// The sign of the first of Bernstein coefficients b (of a cubic on a
/// window) when they change sign exactly once, the first and the last not
/// 0: then the cubic has one root inside the window, a simple one
/// (Descartes' rule of signs in the Bernstein basis: the count of roots in
/// the open interval, with multiplicity, is at most the changes and of
/// their parity). 0 otherwise, or when a sign is in doubt.
template <class T>
int single_sign_change(const bernstein<T>& b) {
    try {
        std::array<int, 4> signs{};
        for (std::size_t i = 0; i < 4; ++i) signs[i] = number_traits<T>::sign(b[i]);
        return single_sign_change_of(signs);
    } catch (const uncertain_sign&) {
        return 0;
    }
}

/// The sign of f at `from` when f's Bernstein coefficients on [from, to]
/// (on_window, in NT) change sign exactly once (single_sign_change): then f
/// has one root in (from, to), a simple one. 0 otherwise, or when a sign
/// is in doubt.
template <class NT>
int single_crossing(const polynomial<NT>& f, double from, double to) {
    std::array<NT, 4> a;
    for (std::size_t k = 0; k < 4; ++k) a[k] = k < f.c.size() ? f.c[k] : num<NT>(0);
    return single_sign_change(bernstein_of(on_window(a, from, to)));
}

/// The tau of the midpoint between the neighbouring doubles x < y of a
/// piece's time: (x - t0) / span + (y - x) / (2 span), the sum of two
/// doubles when both terms are (the second, a power of two, is unless it
/// falls below the subnormals' step), so that a double word holds it
/// exactly and two midpoints met twice compare equal; otherwise computed in
/// NT.
template <class NT>
NT tau_between(const rational_piece& piece, double x, double y) {
    const double inverse = 1 / (piece.t1 - piece.t0);  // (a power of two)
    const double gap = (y - x) * inverse, half_gap = gap / 2;
    double from_start;
    if (half_gap + half_gap == gap && exact_sum::exact_double_sum(x * inverse, -piece.t0 * inverse, from_start))
        return NT(num<NT>(from_start) + num<NT>(half_gap));
    return NT(NT(NT(NT(num<NT>(x) + num<NT>(y)) * num<NT>(0.5)) - num<NT>(piece.t0)) * num<NT>(inverse));
}

/// How many doubles narrowed_for_rounding tries for the root's rounded
/// time: double's guess of the root, rounded to a time, and then its
/// neighbours on the root's side, one at a time (on the turning study's
/// convex 8-gons, of 113 contacts found after the start 46 round to the
/// guess, 53 to a neighbour, 12 to the double two units away and 2 further).
inline constexpr int rounding_tries = 3;

/// Narrows the bracket r of the only root of s[0] in it, in a piece's tau,
/// about double's guess of the root (double_root_bracket). In an NT that is
/// not floating, when r's low_sign is known, to the midpoints either side
/// of the double d that the root's time rounds to (rounded_time then asks
/// no sign):
///
///   d <- the double nearest the guess's time
///   rounding_tries times, while the midpoints m-, m+ about d lie in r:
///     s[0]'s certain signs at m- and m+ differ:   (m-, m+], done
///     either is 0 (a tie), or in doubt:           stop
///     both low_sign's:  d <- its upper neighbour (the root lies above m+)
///     both the other:   d <- its lower neighbour
///
/// Else, or when the tries end, as narrowed_by_double does
/// (narrowed_about).
template <class NT>
void narrowed_for_rounding(const rational_piece& piece, const std::vector<polynomial<NT>>& s, isolated_root<NT>& r) {
    const std::optional<std::pair<double, double>> guess = double_root_bracket(s[0], r);
    if (!guess) return;
    if constexpr (number_traits<NT>::category != number_category::floating) {
        if (r.low_sign != 0) {
            const double tau = guess->first + (guess->second - guess->first) / 2;
            double d = piece.t0 + tau * (piece.t1 - piece.t0);
            NT lo = tau_between<NT>(piece, std::nextafter(d, -HUGE_VAL), d),
               hi = tau_between<NT>(piece, d, std::nextafter(d, HUGE_VAL));
            try {
                int at_lo = 2, at_hi = 2;  // (2: not asked yet)
                for (int k = 0; k < rounding_tries; ++k) {
                    // (Within r, whose only root a change of sign there is.)
                    if (compare_values<NT>(lo, r.low) < 0 || compare_values<NT>(hi, r.high) > 0) break;
                    if (at_lo == 2) at_lo = s[0].sign_at(lo);
                    if (at_hi == 2) at_hi = s[0].sign_at(hi);
                    if (at_lo == 0 || at_hi == 0) break;
                    if (at_lo != at_hi) {
                        r = {lo, hi, at_lo};
                        return;
                    }
                    if (at_lo == r.low_sign) {
                        d = std::nextafter(d, HUGE_VAL);
                        lo = hi;
                        at_lo = at_hi;
                        hi = tau_between<NT>(piece, d, std::nextafter(d, HUGE_VAL));
                        at_hi = 2;
                    } else {
                        d = std::nextafter(d, -HUGE_VAL);
                        hi = lo;
                        at_hi = at_lo;
                        lo = tau_between<NT>(piece, std::nextafter(d, -HUGE_VAL), d);
                        at_lo = 2;
                    }
                }
            } catch (const uncertain_sign&) {
                // (Left to narrowed_about.)
            }
        }
    }
    narrowed_about(s, r, guess->first, guess->second);
}

/// A vertex-edge pair of a piece that the sifting keeps: no contact of it at
/// or before `after` (a tau of the piece), and what the sifting learnt of
/// its cubics on the window searched.
struct kept_pair {
    sweep::contact_site site;  ///< the vertex and the edge
    double after;              ///< no contact of theirs at or before this tau
    /// single_crossing's answer for their f on (after, the window's end],
    /// when the sifting found it (its Bernstein coefficients there); 0 when
    /// unknown.
    int crossing = 0;
    bool lo_positive = false;  ///< lo > 0 throughout the window (its Bernstein coefficients all > 0)
    bool hi_positive = false;  ///< hi > 0 throughout the window (its Bernstein coefficients all > 0)
};

/// The earliest root in (after, end] of the cubics' f at which lo and hi
/// are >= 0 (in (after, end) when `open_end`: the next piece starts at end
/// = 1), bracketed (narrowed_for_rounding, in `piece`'s tau); none when
/// there is none (or f is identically zero: the point slides along the
/// segment's line, and reaches the segment only at an end, a vertex of the
/// polygon, where another pair's f finds the contact). What the sifting
/// learnt of the pair (kept_pair) is taken as found: the single crossing,
/// and lo or hi positive throughout.
template <class NT>
std::optional<std::pair<std::vector<polynomial<NT>>, isolated_root<NT>>> earliest_root(const rational_piece& piece,
                                                                                       const contact_cubics<NT>& k,
                                                                                       const kept_pair& sifted,
                                                                                       double end, bool open_end) {
    const double after = sifted.after;
    // lo and hi >= 0 at the root bracketed by r.
    const auto on_segment = [&](const std::vector<polynomial<NT>>& s, isolated_root<NT>& r) {
        return (sifted.lo_positive || sign_at_root(k.lo, s, r) >= 0) &&
               (sifted.hi_positive || sign_at_root(k.hi, s, r) >= 0);
    };
    if (k.f.degree() < 1) return std::nullopt;  // identically zero, or a non-zero constant
    if (const int low_sign = sifted.crossing != 0 ? sifted.crossing : single_crossing(k.f, after, end)) {
        // f's only root in the window, simple: f is all that is asked of
        // its sequence (isolated_root::low_sign).
        std::vector<polynomial<NT>> s{k.f};
        isolated_root<NT> r{num<NT>(after), num<NT>(end), low_sign};
        narrowed_for_rounding(piece, s, r);
        if (on_segment(s, r)) return std::make_pair(std::move(s), r);
        return std::nullopt;
    }
    std::vector<polynomial<NT>> s = sturm_sequence(k.f);
    const NT last = num<NT>(end);
    const bool root_at_end = open_end && k.f.sign_at(last) == 0;
    for (isolated_root<NT> r : isolate_roots(s, num<NT>(after), last)) {
        if (root_at_end && compare_values<NT>(r.high, last) == 0) break;  // (the bracket's root is end, its last)
        narrowed_for_rounding(piece, s, r);  // (cheap: the signs below and the rounding then take a step or two)
        if (on_segment(s, r)) return std::make_pair(std::move(s), r);
    }
    return std::nullopt;
}

/// The regions of A and of B at a piece's start (B's vertices given in NT)
/// meeting, with their features; none when apart.
template <class NT>
std::optional<std::pair<feature, feature>> meeting_at_piece_start(const polygon& a, const polygon& b,
                                                                  const rational_piece& piece,
                                                                  const piece_translation<NT>& t, double scale) {
    std::vector<point<NT>> vertices;
    vertices.reserve(b.size());
    const NT c = num<NT>(piece.c), s = num<NT>(piece.s);
    for (const point<double>& v : b.vertices()) {
        const NT x = num<NT>(v.x), y = num<NT>(v.y);
        vertices.push_back({NT(c * x - s * y + t.a0.x), NT(s * x + c * y + t.a0.y)});
    }
    placed_polygon<NT> pa(a), pb(b, vertices);
    const meeting met = placed_meet(pa, pb, posing_margin<NT>(scale));
    if (!met) return std::nullopt;
    return sweep::meeting_features(pa, pb, met);
}

/// How many times rounded_time steps to its guess's neighbour before it
/// takes the middle of the bracket left: the first guess, the middle of a
/// bracket from narrowed_about, is off by the rounding of the cubic's
/// coefficients and values in double, mostly by a unit or two
/// (rounding_tries).
inline constexpr int rounded_time_neighbours = 2;

/// The time t0 + tau (t1 - t0) of the root bracketed by r, rounded to the
/// nearest double (ties to even). In a floating NT, the bracket halved until
/// both its ends round to one double (or it stops moving). Otherwise
/// exactly, by the root's side of the midpoints around a guess:
///
///   d <- the double next to the bracket's middle, in time (to_double: a guess)
///   loop:
///     m-, m+ <- the midpoints between d and its two neighbours, as taus
///     the root at m- or at m+ (f vanishes there):     the even of the two doubles
///     the root between m- and m+:                     d
///     cut the bracket at m- or m+, on the root's side (halved when that
///       midpoint lies outside it)
///     d <- d's neighbour on the root's side, the first
///       rounded_time_neighbours times; then the new bracket's guess, or that
///       neighbour if the guess is not beyond it
///
/// A side is the cubic's sign at the midpoint against its sign at the
/// bracket's low end when its signs at the ends differ (root_side), else a
/// Sturm count within the bracket (or the bracket's own ends), so in double
/// words (a filtered NT) it is certain unless the root lies within their
/// bound of a midpoint; the bracket's ends are never rounded. A midpoint at
/// the bracket's high end, the ends' signs differing, lies above the root
/// with no sign asked: a bracket that narrowed_for_rounding left between
/// the midpoints about d is rounded to d at once.
template <class NT>
double rounded_time(const rational_piece& piece, const std::vector<polynomial<NT>>& s, isolated_root<NT> r) {
    using tr = number_traits<NT>;
    const NT t0 = num<NT>(piece.t0), span = num<NT>(piece.t1 - piece.t0);
    const auto time_of = [&](const NT& tau) { return NT(t0 + tau * span); };
    if constexpr (tr::category == number_category::floating) {
        for (int halvings = 0;; ++halvings) {
            const double lo = static_cast<double>(time_of(r.low)), hi = static_cast<double>(time_of(r.high));
            if (lo == hi) return lo;
            // (Rounded arithmetic: the bracket stopped shrinking.)
            if (!may_halve<NT>(halvings) || !halve(s, r)) return hi;
        }
    } else {
        const NT half = num<NT>(0.5);
        // The side of the root against tau: -1 below it, 0 at it, +1 above
        // (at the bracket's high end, below it when the ends' signs differ).
        if (r.low_sign == 0) r.low_sign = opposite_end_signs(s, r.low, r.high);
        const auto side = [&](const NT& tau) {
            if (compare_values<NT>(tau, r.low) <= 0) return 1;
            const int against_high = compare_values<NT>(tau, r.high);
            if (against_high > 0 || (against_high == 0 && r.low_sign != 0)) return -1;
            return root_side(s, r, tau);
        };
        const auto guess = [&] { return tr::to_double(time_of(NT(NT(r.low + r.high) * half))); };
        double d = guess();
        for (int k = 0;; ++k) {
            const double below = std::nextafter(d, -HUGE_VAL), above = std::nextafter(d, HUGE_VAL);
            const NT m_lo = tau_between<NT>(piece, below, d), m_hi = tau_between<NT>(piece, d, above);
            const int at_lo = side(m_lo), at_hi = side(m_hi);
            if (at_lo == 0) return even_of(below, d);
            if (at_hi == 0) return even_of(d, above);
            if (at_lo > 0 && at_hi < 0) return d;
            may_halve<NT>(k);  // (signs in doubt, not settled after so many: uncertain_sign)
            if (at_lo < 0 && compare_values<NT>(m_lo, r.high) < 0)
                r.high = m_lo;
            else if (at_hi > 0 && compare_values<NT>(m_hi, r.low) > 0)
                r.low = m_hi;
            else
                halve(s, r);
            // The next guess on the root's side of d: its neighbour after
            // the first two guesses (a bracket from narrowed_by_double holds
            // double's root of the rounded cubic, mostly a unit or two from the
            // exact one), then the bracket's middle (to_double may truncate:
            // its guess alone could stay at d).
            if (k < rounded_time_neighbours)
                d = at_lo < 0 ? below : above;
            else
                d = at_lo < 0 ? std::min(guess(), below) : std::max(guess(), above);
        }
    }
}

/// earliest_kept_contact's settle where no exact type orders its doubts.
struct no_settle {};

/// What the kept pairs' cubics share over a piece, in R: B's translation
/// (translation_of), the factor l of cubics_of (1 in A's frame, c^2 + s^2
/// in B's) and w^2.
template <class R>
struct piece_factors {
    piece_translation<R> t;
    R one, base, w2;
};

/// The piece's piece_factors in R.
template <class R>
piece_factors<R> factors_of(const rational_piece& piece, const pose& from, const pose& to) {
    return {translation_of<R>(piece, from, to), num<R>(1),
            R(num<R>(piece.c) * num<R>(piece.c) + num<R>(piece.s) * num<R>(piece.s)),
            R(num<R>(piece.w) * num<R>(piece.w))};
}

/// The contact of kept pair c in R: its cubic's earliest root after its
/// `after` at which lo and hi are >= 0 (earliest_root), with the pair's
/// site; none when it has no such root. `end` and `open_end` as for
/// earliest_root; k the piece's factors in R.
template <class R>
std::optional<piece_contact<R>> kept_contact(const polygon& a, const polygon& b, const rational_piece& piece,
                                             const piece_factors<R>& k, const kept_pair& c, double end, bool open_end) {
    const moving_point<R> m = c.site.moving_vertex ? moving_vertex<R>(piece, k.t, b.vertex(c.site.vertex))
                                                   : moving_static_vertex<R>(piece, k.t, a.vertex(c.site.vertex));
    const polygon& edges = c.site.moving_vertex ? a : b;
    auto found = earliest_root(piece,
                               cubics_of(m, k.w2, c.site.moving_vertex ? k.one : k.base, edges.vertex(c.site.edge),
                                         edges.vertex(edges.next(c.site.edge)), !c.lo_positive || !c.hi_positive),
                               c, end, open_end);
    if (!found) return std::nullopt;
    return piece_contact<R>{c.site, std::move(found->first), found->second};
}

/// The first contact among a piece's kept pairs, in R (sorted by `after`):
/// the pair whose cubic f has the earliest root after its `after`, at or
/// before `end` (before it when the piece is not the last and end is 1),
/// at which lo and hi are >= 0 (earliest_root; ties: site_before), with
/// that time rounded to the nearest double (rounded_time); none when no
/// pair has one. The pairs whose `after` lies beyond the best root found
/// are left. Two roots whose order R leaves in doubt (compare_roots raises
/// uncertain_sign: two pairs that touch at the same time, as the vertices
/// of a shared border do when a motion ends where a polygon stood) are
/// ordered by settle(x, y), the sign of x's root less y's for the kept
/// pairs x and y in an exact type; without it (R exact, or no settle) the
/// doubt goes on to the caller.
template <class R, class Settle>
std::optional<std::pair<sweep::contact_site, double>> earliest_kept_contact(
    const polygon& a, const polygon& b, const pose& from, const pose& to, const rational_piece& piece, bool last,
    double end, const std::vector<kept_pair>& kept, Settle&& settle) {
    const piece_factors<R> k = factors_of<R>(piece, from, to);
    std::optional<piece_contact<R>> best;
    const kept_pair* best_kept = nullptr;
    for (const kept_pair& c : kept) {
        if (best && compare_values<R>(num<R>(c.after), best->root.high) > 0) break;
        std::optional<piece_contact<R>> contact = kept_contact(a, b, piece, k, c, end, !last && end == 1);
        if (!contact) continue;
        if (best) {
            int order;
            if constexpr (std::is_invocable_r_v<int, Settle, const kept_pair&, const kept_pair&>) {
                try {
                    order = compare_roots(contact->sequence, contact->root, best->sequence, best->root);
                } catch (const uncertain_sign&) {
                    order = settle(c, *best_kept);
                }
            } else {
                order = compare_roots(contact->sequence, contact->root, best->sequence, best->root);
            }
            if (order > 0 || (order == 0 && !sweep::site_before(c.site, best->site))) continue;
        }
        best = std::move(contact);
        best_kept = &c;
    }
    if (!best) return std::nullopt;
    return std::pair{best->site, rounded_time(piece, best->sequence, best->root)};
}

/// The first contact of a piece in the window (known, to] (through `known`
/// the motion is free; from <= known < to), with its time rounded, or
/// none. The vertex-edge pairs whose boxes over one of Parts parts of equal
/// time of [from, to] (swept_parts) not ending by `known` meet are sifted
/// in Filter over [from, to] (their Bernstein coefficients there, halved
/// `depth` times: 0 unless the window is [0, 1], whose halves are exact
/// doubles), and the earliest root among those kept sought in double words
/// or in NT (rational_first_contact's pseudocode). `ga` and `gb` are A's and
/// B's boundary_groups.
template <class NT, class Filter, std::size_t Parts>
std::optional<std::pair<sweep::contact_site, double>> contact_within(const polygon& a, const polygon& b,
                                                                     const sweep::boundary_groups& ga,
                                                                     const sweep::boundary_groups& gb, const pose& from,
                                                                     const pose& to, const rational_piece& piece,
                                                                     bool last, double scale, double window_from,
                                                                     double window_to, double known, int depth) {
    const piece_translation<Filter> tf = translation_of<Filter>(piece, from, to);
    // The translation over the piece, in double (for the boxes).
    const piece_translation<double> td = translation_of<double>(piece, from, to);
    const double slack = sweep::arc_box_slack * scale + std::numeric_limits<double>::min();
    const part_turns<Parts> turns = turns_of<Parts>(piece, window_from, window_to);
    const bool whole = window_from == 0 && window_to == 1;
    const Filter wf = num<Filter>(piece.w), w2f = Filter(wf * wf);
    // The factor l of cubics_of: 1 in A's frame, c^2 + s^2 in B's.
    const Filter one_f = num<Filter>(1), base_f = Filter(num<Filter>(piece.c) * num<Filter>(piece.c) +
                                                         num<Filter>(piece.s) * num<Filter>(piece.s));

    // Each pair whose boxes over the window meet, sifted in Filter: where
    // in the window its contact may be (first_possible), or none.
    std::vector<kept_pair> kept;
    const auto sift = [&](const sweep::contact_site& site, const moving_point<Filter>& m, const Filter& l,
                          const point<double>& p, const point<double>& q, double from_box) {
        // The Bernstein coefficients of cubic i on the window: certified's
        // made in double with one bound per cubic (bounded_coefficients,
        // bounded_bernstein; on a part of the piece through on_window in
        // certified first), another Filter's in Filter.
        const auto k = [&] {
            if constexpr (std::is_same_v<Filter, certified>)
                return bounded_coefficients(m, w2f, l, p, q);
            else
                return coefficients_of(m, w2f, l, p, q);
        }();
        const auto on = [&](std::size_t i) {
            if constexpr (std::is_same_v<Filter, certified>) {
                if (whole) return bounded_bernstein::of_power(k.c[i], k.e[i]);
                std::array<certified, 4> c;
                for (std::size_t j = 0; j < 4; ++j) c[j] = certified(k.c[i][j], k.e[i]);
                return bounded_of(on_window(c, window_from, window_to));
            } else {
                return bernstein_of(whole ? k[i] : on_window(k[i], window_from, window_to));
            }
        };
        const auto f = on(0), lo = on(1), hi = on(2);
        const std::optional<double> at = first_possible(f, lo, hi, window_from, window_to, depth, known);
        if (at) {
            const double after = std::max({*at, from_box, known});
            // f's coefficients on the window are single_crossing's when the
            // search starts at the window's start.
            kept.push_back({site, after, after == window_from ? single_sign_change(f) : 0, all_of_sign(lo, 1),
                            all_of_sign(hi, 1)});
        }
    };
    // B's vertices against A's edges, in A's frame; A's vertices against
    // B's edges, in B's frame (q less the translation, turned back): the
    // pairs whose boxes over a part meet (for_each_swept_pair).
    sweep::swept_scratch<Parts> scratch;
    for (const bool moving : {true, false}) {
        const polygon &vertices = moving ? b : a, &edges = moving ? a : b;
        std::vector<std::optional<moving_point<Filter>>> mf(vertices.size());
        const sweep::swept_frame<Parts> frame = swept_frame_of(piece, turns, !moving, td, slack);
        sweep::for_each_swept_pair(
            frame, vertices, moving ? gb : ga, edges, moving ? ga : gb, known,
            [&](std::size_t v, std::size_t e, const std::array<box, Parts>& parts) {
                const std::optional<double> from_box =
                    sweep::first_part_meeting(frame, parts, (moving ? ga : gb).edges[e], known);
                if (!from_box) return;
                if (!mf[v])
                    mf[v] = moving ? moving_vertex<Filter>(piece, tf, vertices.vertex(v))
                                   : moving_static_vertex<Filter>(piece, tf, vertices.vertex(v));
                sift({moving, static_cast<std::uint32_t>(v), static_cast<std::uint32_t>(e)}, *mf[v],
                     moving ? one_f : base_f, edges.vertex(e), edges.vertex(edges.next(e)), *from_box);
            },
            scratch);
    }
    // The kept pairs in order of where their contact may start; the
    // earliest root among them (earliest_kept_contact): in double words
    // first when NT is an exact field (their signs exact or none), in NT
    // when one is in doubt.
    std::sort(kept.begin(), kept.end(), [](const kept_pair& x, const kept_pair& y) {
        return x.after != y.after ? x.after < y.after : sweep::site_before(x.site, y.site);
    });
    const no_settle none;
    if constexpr (number_traits<NT>::category == number_category::exact) {
        // Two roots that double words cannot order are ordered in NT, each
        // pair's contact made there once (the order of two roots only: the
        // rest of the search stays in double words).
        std::vector<std::optional<piece_contact<NT>>> exact(kept.size());
        std::optional<piece_factors<NT>> factors;
        const auto exact_contact = [&](const kept_pair& c) -> piece_contact<NT>& {
            std::optional<piece_contact<NT>>& made = exact[static_cast<std::size_t>(&c - kept.data())];
            if (!made) {
                if (!factors) factors = factors_of<NT>(piece, from, to);
                made = kept_contact(a, b, piece, *factors, c, window_to, !last && window_to == 1);
                // (Found in double words, whose signs were exact: found here.)
                if (!made) throw uncertain_sign();
            }
            return *made;
        };
        const auto settle = [&](const kept_pair& x, const kept_pair& y) {
            piece_contact<NT>&cx = exact_contact(x), &cy = exact_contact(y);
            return compare_roots(cx.sequence, cx.root, cy.sequence, cy.root);
        };
        return fallback<>::run(
            [&] { return earliest_kept_contact<double_word>(a, b, from, to, piece, last, window_to, kept, settle); },
            [&] { return earliest_kept_contact<NT>(a, b, from, to, piece, last, window_to, kept, none); });
    } else {
        return earliest_kept_contact<NT>(a, b, from, to, piece, last, window_to, kept, none);
    }
}

}  // namespace rational_turn_detail

/// The first contact of B moving from `from` to `to` against the static A
/// in the rational model (docs/sweep.md): the earliest time t in [0, 1] at
/// which the closed regions meet, with the features that touch then;
/// exact when NT is an exact field (the time rounded to the nearest
/// double), rounded in a floating NT. Filter decides which vertex-edge
/// pairs cannot touch in a piece (certified for an exact NT: its doubt
/// only keeps a pair).
///
///   pieces <- rational_pieces(from, to)
///   for each piece, in order, from `start` (the motion free before it):
///     known <- start.tau in start's piece, else 0    (free through it)
///     known = 0 and A and B at the piece's start meet (the one-shot query,
///       B's vertices posed exactly; in Filter first):
///                                               time t0, the features met
///     in start's piece, when start.until > known: the window (known, until]
///       first, as below with one box for its whole time and no halving:
///       a contact there is the first; else known <- until
///     for each vertex of B and edge of A, and each vertex of A and edge
///     of B (in B's frame), whose boxes over a quarter of the piece not
///     ending by `known` meet (swept_parts: arcs boxed by their ends and
///     bulge, plus the translation; first the chains of vertices and runs
///     of edges whose boxes meet, by sort and sweep along x, then within
///     each such two their vertices' and edges' boxes):
///       f, lo, hi <- the cubics of the vertex on the edge's line and
///            between its ends, in Filter; kept with the start of the first
///            sixteenth of the piece not ending by `known` where f may
///            vanish while lo and hi may be >= 0 (their Bernstein
///            coefficients, halved four times; certified's made and halved
///            in double with one bound per cubic, bounded_bernstein), of the first such quarter
///            whose box meets the edge, or `known`, the latest
///     for the kept pairs in order of that start, while it is not after
///     the best root found:
///       the earliest root of f after the start at which lo, hi >= 0
///       (Sturm sequences, bisection; exact signs); the best so far when
///       earlier (ties: site_before)
///     a best root:          the first contact, its time rounded (rounded_time)
///   (the roots, the comparisons and the rounding in double words first when
///   NT is an exact field; two roots whose order is in doubt there ordered
///   in NT, those two pairs' contacts made in NT; all of them again in NT
///   when another sign is in doubt)
///   none
///
/// NT needs division (exact_rational, or a floating type). Throws
/// invalid_input for a turn of more than 2^20 quarter turns.
template <class NT, class Filter = std::conditional_t<is_exact_v<NT>, certified, NT>>
contact_result<double> rational_first_contact(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                              const rational_start& start = {}) {
    using namespace rational_turn_detail;
    const double scale = sweep::motion_scale(a, b, from, to);
    contact_result<double> r;
    const auto contact_at = [&](const std::pair<sweep::contact_site, double>& found) {
        r.contact = true;
        r.time = found.second;
        std::tie(r.static_feature, r.moving_feature) = sweep::site_features(a, b, found.first);
        return r;
    };
    const std::vector<rational_piece> pieces = rational_pieces(from, to);
    // A's and B's boundary_groups, made when a piece is first searched.
    std::optional<std::pair<sweep::boundary_groups, sweep::boundary_groups>> groups;
    const auto groups_of = [&]() -> const std::pair<sweep::boundary_groups, sweep::boundary_groups>& {
        if (!groups) groups.emplace(sweep::boundary_groups_of(a), sweep::boundary_groups_of(b));
        return *groups;
    };
    for (std::size_t index = start.piece; index < pieces.size(); ++index) {
        const rational_piece& piece = pieces[index];
        const bool last = index + 1 == pieces.size();
        double known = index == start.piece ? start.tau : 0;
        if (known >= 1) continue;
        const auto met = [&]() -> std::optional<std::pair<feature, feature>> {
            if (known > 0) return std::nullopt;
            if constexpr (std::is_same_v<Filter, NT>) {
                return meeting_at_piece_start<NT>(a, b, piece, translation_of<NT>(piece, from, to), scale);
            } else {
                // In Filter first, in NT when a sign is in doubt.
                return fallback<>::run(
                    [&] {
                        return meeting_at_piece_start<Filter>(a, b, piece, translation_of<Filter>(piece, from, to),
                                                              scale);
                    },
                    [&] {
                        return meeting_at_piece_start<NT>(a, b, piece, translation_of<NT>(piece, from, to), scale);
                    });
            }
        }();
        if (met) {
            r.contact = true;
            r.time = piece.t0;
            std::tie(r.static_feature, r.moving_feature) = *met;
            return r;
        }
        if (index == start.piece && start.until > known) {
            // Where the advance expects the contact, first: its boxes are
            // narrow, so that few pairs are kept.
            const auto& [ga, gb] = groups_of();
            if (const auto found = contact_within<NT, Filter, 1>(a, b, ga, gb, from, to, piece, last, scale, known,
                                                                 start.until, known, 0))
                return contact_at(*found);
            known = start.until;
            if (known >= 1) continue;
        }
        const auto& [ga, gb] = groups_of();
        if (const auto found = contact_within<NT, Filter, box_parts>(a, b, ga, gb, from, to, piece, last, scale, 0, 1,
                                                                     known, sifting_depth))
            return contact_at(*found);
    }
    return r;
}

}  // namespace influence2d
