// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Where a polynomial of low degree vanishes in an interval, and the sign of
/// another polynomial there: the exact root questions of the rational
/// turning motions (motion/rational_turn.hpp, docs/sweep.md).
///
/// Roots are isolated by Sturm sequences (the number of distinct real roots
/// in (a, b] is the drop in sign changes of the sequence from a to b) and
/// bisection at the midpoints of the interval, so every decision is the
/// sign of a polynomial at a rational point. In an exact field NT every
/// answer is exact: a root is never computed, only bracketed, and two
/// polynomials share a root exactly when their greatest common divisor
/// vanishes there. In a filtered NT (double_word) every answer is the exact
/// one or uncertain_sign. In a floating NT the same steps round.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "influence2d/number/certified.hpp"
#include "influence2d/number/traits.hpp"

namespace influence2d {

/// A polynomial in one variable: c[k] is the coefficient of x^k; no
/// trailing zero coefficient (the zero polynomial has none).
template <class NT>
struct polynomial {
    std::vector<NT> c;  ///< coefficients, lowest degree first

    /// The degree; -1 for the zero polynomial.
    int degree() const { return static_cast<int>(c.size()) - 1; }

    /// The value at x (Horner).
    NT at(const NT& x) const {
        NT v = number_traits<NT>::from_double(0);
        for (std::size_t k = c.size(); k-- > 0;) v = NT(v * x + c[k]);
        return v;
    }

    /// The sign of the value at x.
    int sign_at(const NT& x) const { return c.empty() ? 0 : number_traits<NT>::sign(at(x)); }

    /// Drops trailing coefficients that are zero (exactly, in NT).
    polynomial& trimmed() {
        while (!c.empty() && number_traits<NT>::sign(c.back()) == 0) c.pop_back();
        return *this;
    }
};

/// The derivative.
template <class NT>
polynomial<NT> derivative(const polynomial<NT>& p) {
    polynomial<NT> d;
    for (std::size_t k = 1; k < p.c.size(); ++k) d.c.push_back(NT(p.c[k] * number_traits<NT>::from_double(double(k))));
    d.trimmed();
    return d;
}

/// The remainder of p divided by q (q not zero), in a field NT.
template <class NT>
polynomial<NT> remainder(polynomial<NT> p, const polynomial<NT>& q) {
    const int dq = q.degree();
    while (p.degree() >= dq) {
        const std::size_t shift = static_cast<std::size_t>(p.degree() - dq);
        const NT factor = p.c.back() / q.c.back();
        for (std::size_t k = 0; k < q.c.size(); ++k) p.c[k + shift] = NT(p.c[k + shift] - factor * q.c[k]);
        p.c.pop_back();  // (its coefficient is now zero, whatever rounding left)
        p.trimmed();
    }
    return p;
}

/// The quotient of p divided by q (q not zero), in a field NT: exact when q
/// divides p.
template <class NT>
polynomial<NT> quotient(polynomial<NT> p, const polynomial<NT>& q) {
    const int dq = q.degree();
    polynomial<NT> out;
    if (p.degree() < dq) return out;
    out.c.assign(static_cast<std::size_t>(p.degree() - dq + 1), number_traits<NT>::from_double(0));
    while (p.degree() >= dq) {
        const std::size_t shift = static_cast<std::size_t>(p.degree() - dq);
        const NT factor = p.c.back() / q.c.back();
        out.c[shift] = factor;
        for (std::size_t k = 0; k < q.c.size(); ++k) p.c[k + shift] = NT(p.c[k + shift] - factor * q.c[k]);
        p.c.pop_back();  // (its coefficient is now zero, whatever rounding left)
        p.trimmed();
    }
    out.trimmed();
    return out;
}

/// A greatest common divisor of p and q (Euclid's algorithm, in a field
/// NT): the zero polynomial when both are zero; a non-zero constant when
/// they share no root.
template <class NT>
polynomial<NT> common_divisor(polynomial<NT> p, polynomial<NT> q) {
    while (q.degree() >= 0) {
        polynomial<NT> r = remainder(p, q);
        p = std::move(q);
        q = std::move(r);
    }
    return p;
}

/// The Sturm sequence of p (not zero): p, p', then the negated remainders,
/// down to a greatest common divisor g of p and p'; when g is not a
/// constant (p has a multiple root), every member divided by g: the
/// sequence of p / g, which has p's roots, each once, and whose members
/// never all vanish at one point (at a multiple root of p they all would,
/// and the count of sign changes there would be lost).
template <class NT>
std::vector<polynomial<NT>> sturm_sequence(const polynomial<NT>& p) {
    std::vector<polynomial<NT>> s{p};
    polynomial<NT> d = derivative(p);
    while (d.degree() >= 0) {
        s.push_back(d);
        polynomial<NT> r = remainder(s[s.size() - 2], s.back());
        for (NT& x : r.c) x = NT(-x);
        d = std::move(r);
    }
    if (s.back().degree() >= 1) {
        const polynomial<NT> g = s.back();
        for (polynomial<NT>& member : s) member = quotient(member, g);
    }
    return s;
}

/// The number of sign changes of a Sturm sequence at x (zeros skipped).
template <class NT>
int sign_changes(const std::vector<polynomial<NT>>& s, const NT& x) {
    int changes = 0, last = 0;
    for (const polynomial<NT>& p : s) {
        const int v = p.sign_at(x);
        if (v == 0) continue;
        if (last != 0 && v != last) ++changes;
        last = v;
    }
    return changes;
}

/// The number of distinct real roots of s[0] in (a, b], a < b (Sturm's
/// theorem: it holds whether or not a and b are roots, s[0] having none of
/// multiplicity above one: sturm_sequence).
template <class NT>
int roots_between(const std::vector<polynomial<NT>>& s, const NT& a, const NT& b) {
    return sign_changes(s, a) - sign_changes(s, b);
}

/// How many times a bracket is halved at most in a floating NT, whose
/// rounded signs may never settle a question an exact NT would: double's
/// midpoints stop moving after some 2,100 halvings of [0, 1] (1,074 bits
/// below 1, and the exponents' range); beyond it, or once a halving leaves
/// the bracket as it was (halve), the answer is the one the bracket gives.
/// An exact NT halves until the question is settled, which it always is
/// (the roots compared differ, or are found equal); one whose signs may be in
/// doubt (double words) raises uncertain_sign instead of a rounded answer
/// (may_halve).
inline constexpr int rounded_halvings = 2200;

/// Whether NT's signs may be in doubt, raising uncertain_sign: a filtered
/// type whose traits tell a certain sign apart (try_sign: double_word,
/// certified). CGAL's lazy numbers, filtered too, settle their doubts
/// themselves, and halve as an exact field does.
template <class NT, class = void>
struct signs_may_be_in_doubt : std::false_type {};
template <class NT>
struct signs_may_be_in_doubt<NT, std::void_t<decltype(&number_traits<NT>::try_sign)>> : std::true_type {};

/// Whether a loop may halve its bracket for the k-th time (k from 0): always
/// in an exact type; below rounded_halvings in a floating one (its answer
/// then stands as the bracket gives it); in a type whose signs may be in
/// doubt below rounded_halvings, and then uncertain_sign: its answers must
/// be the exact ones, and it has not settled this one.
template <class NT>
bool may_halve(int k) {
    if constexpr (signs_may_be_in_doubt<NT>::value) {
        if (k < rounded_halvings) return true;
        throw uncertain_sign();
    } else if constexpr (number_traits<NT>::category == number_category::floating) {
        return k < rounded_halvings;
    } else {
        return true;
    }
}

/// A root of a polynomial bracketed alone: the only root of `sequence[0]`
/// in (low, high]. With `low_sign` not 0 the root is told apart from any
/// point of the bracket by sequence[0]'s sign there alone (root_at_or_below),
/// and sequence[0] is all the functions below ask of the sequence.
template <class NT>
struct isolated_root {
    NT low;   ///< excluded
    NT high;  ///< included
    /// The sign of sequence[0] at `low` when its signs at the two ends are
    /// certain and opposite (opposite_end_signs): the root then has odd
    /// multiplicity, and sequence[0] keeps this sign from `low` up to it
    /// and the other after it, however the bracket shrinks about it. 0:
    /// unknown, Sturm counts tell.
    int low_sign = 0;
};

/// The sign of s[0] at r.low when s[0] has strictly opposite signs at the
/// bracket's ends, certain ones in a filtered NT; 0 otherwise. Then a root
/// of s[0] lies between them, and when it is the only one there (an
/// isolated_root) it has odd multiplicity (isolated_root::low_sign).
template <class NT>
int opposite_end_signs(const std::vector<polynomial<NT>>& s, const NT& low, const NT& high) {
    try {
        const int at_low = s[0].sign_at(low);
        return at_low != 0 && at_low == -s[0].sign_at(high) ? at_low : 0;
    } catch (const uncertain_sign&) {
        return 0;
    }
}

/// The side of the root bracketed by r against x, r.low < x <= r.high: -1
/// when the root lies below x, 0 at x (s[0] vanishes there), +1 above; by
/// s[0]'s sign at x against r.low_sign when it is known, else by a Sturm
/// count.
template <class NT>
int root_side(const std::vector<polynomial<NT>>& s, const isolated_root<NT>& r, const NT& x) {
    const int at = s[0].sign_at(x);
    if (at == 0) return 0;
    if (r.low_sign != 0) return at == r.low_sign ? 1 : -1;
    return roots_between(s, r.low, x) > 0 ? -1 : 1;
}

/// Whether the root bracketed by r lies at or below x, r.low < x <= r.high:
/// s[0]'s sign at x is not r.low_sign's (0 there: x is the root) when that
/// is known, else a Sturm count over (r.low, x], which counts x itself.
template <class NT>
bool root_at_or_below(const std::vector<polynomial<NT>>& s, const isolated_root<NT>& r, const NT& x) {
    if (r.low_sign == 0) return roots_between(s, r.low, x) > 0;
    return s[0].sign_at(x) != r.low_sign;
}

/// Whether the root bracketed by r lies in (lo, hi], r.low <= lo < hi <=
/// r.high (root_at_or_below at both ends).
template <class NT>
bool root_within(const std::vector<polynomial<NT>>& s, const isolated_root<NT>& r, const NT& lo, const NT& hi) {
    if (r.low_sign == 0) return roots_between(s, lo, hi) > 0;
    return (compare_values<NT>(lo, r.low) <= 0 || !root_at_or_below(s, r, lo)) && root_at_or_below(s, r, hi);
}

/// Halves the bracket of the only root of s[0] in (r.low, r.high]: keeps
/// the half that holds it. False when the bracket did not change (a
/// floating NT's midpoint rounded to the end it replaces; never in an exact
/// NT, and uncertain_sign instead in one whose signs may be in doubt):
/// halving it again would not change it either.
template <class NT>
bool halve(const std::vector<polynomial<NT>>& s, isolated_root<NT>& r) {
    const NT mid = NT((r.low + r.high) * number_traits<NT>::from_double(0.5));
    NT& end = root_at_or_below(s, r, mid) ? r.high : r.low;
    const bool moved = compare_values<NT>(end, mid) != 0;
    if (!moved && signs_may_be_in_doubt<NT>::value) throw uncertain_sign();
    end = mid;
    return moved;
}

/// The roots of s[0] in (a, b], a < b, in increasing order, each bracketed
/// alone (bisection until each bracket holds one root), with its low_sign.
template <class NT>
std::vector<isolated_root<NT>> isolate_roots(const std::vector<polynomial<NT>>& s, const NT& a, const NT& b) {
    std::vector<isolated_root<NT>> out;
    std::vector<std::pair<isolated_root<NT>, int>> todo{{{a, b}, roots_between(s, a, b)}};
    // Depth first, the lower half first: brackets come out in order.
    while (!todo.empty()) {
        auto [r, n] = todo.back();
        todo.pop_back();
        if (n <= 0) continue;
        if (n == 1) {
            r.low_sign = opposite_end_signs(s, r.low, r.high);
            out.push_back(r);
            continue;
        }
        const NT mid = NT((r.low + r.high) * number_traits<NT>::from_double(0.5));
        if ((!is_exact_v<NT> || signs_may_be_in_doubt<NT>::value) &&
            (compare_values<NT>(mid, r.low) == 0 || compare_values<NT>(mid, r.high) == 0)) {
            // The bracket cannot be cut: rounded, it stands; in doubt, the
            // answer is not settled.
            if (signs_may_be_in_doubt<NT>::value) throw uncertain_sign();
            out.push_back(r);
            continue;
        }
        const int left = roots_between(s, r.low, mid);
        todo.push_back({{mid, r.high}, n - left});
        todo.push_back({{r.low, mid}, left});
    }
    return out;
}

/// How many Newton steps double_root_bracket takes at most before it
/// bisects what is left: from the secant's point a simple root of a cubic
/// is found to double's precision in four to six, the error squaring at
/// each step; steps that cannot find it (a root of several, or one whose
/// values drown in rounding) are cut off here, and bisection, which needs
/// no more than the signs, ends the search.
inline constexpr int narrowing_newton_steps = 8;

/// The rounding of Horner's rule on a polynomial of n coefficients at x,
/// relative to n times the sum of its terms' magnitudes: below 2 (n - 1) u
/// of that sum (u = 2^-53; Higham, Accuracy and Stability of Numerical
/// Algorithms, 5.1), so that below 2^-52 n; rounded_with_slope divides it by
/// the slope for how far the rounded root may lie from the exact one of the
/// rounded coefficients.
inline constexpr double narrowing_rounding = 0x1p-52;

/// How many times double_root_bracket looks for the bracket's signs about
/// its last guess, at 1, 8 and 64 times the root's rounding (its distance
/// from the root, and the coefficients' own rounding, add to it).
inline constexpr int narrowing_probes = 3;

/// The rounded coefficients of p, lowest degree first.
template <class NT>
std::vector<double> rounded_coefficients(const polynomial<NT>& p) {
    std::vector<double> c;
    c.reserve(p.c.size());
    for (const NT& x : p.c) c.push_back(number_traits<NT>::to_double(x));
    return c;
}

/// The value at x of the polynomial with coefficients c (lowest degree
/// first), in double (Horner's rule).
inline double rounded_value(const std::vector<double>& c, double x) {
    double v = 0;
    for (std::size_t k = c.size(); k-- > 0;) v = v * x + c[k];
    return v;
}

/// The polynomial with coefficients c at x, in double: its value and slope,
/// and how far rounding may move its root there (`spread`:
/// narrowing_rounding times the coefficients' count and the sum of the
/// terms' magnitudes, over the slope).
struct rounded_at {
    double value = 0;   ///< the value
    double slope = 0;   ///< the derivative's value
    double spread = 0;  ///< how far rounding may move a root near x
};

/// rounded_at for the coefficients c at x (Horner's rule for the value, the
/// derivative and the sum of the terms' magnitudes at once).
inline rounded_at rounded_with_slope(const std::vector<double>& c, double x) {
    double v = 0, slope = 0, size = 0;
    for (std::size_t k = c.size(); k-- > 0;) {
        slope = slope * x + v;
        v = v * x + c[k];
        size = size * std::fabs(x) + std::fabs(c[k]);
    }
    return {v, slope, narrowing_rounding * static_cast<double>(c.size()) * size / std::fabs(slope)};
}

/// The root of p in the bracket r sought in double, on p's coefficients
/// rounded: two neighbouring doubles at which p's rounded values have the
/// signs they have at r's ends; none when those differ not (p's values
/// lost in rounding there). A guess of where p's exact root lies, which
/// narrowed_about checks.
///
///   [lo, hi] <- r in double; p's rounded signs at its ends must differ
///   x <- the secant's point of [lo, hi]
///   at most narrowing_newton_steps times, while x lies inside (lo, hi):
///       the sign of p(x) moves lo or hi to x (0: x is kept as the guess)
///       x' <- x - p(x) / p'(x); x' = x: stop
///       x <- x', or the middle of [lo, hi] when x' is not inside it
///   x inside (lo, hi): for d = e, 8 e, 64 e, e how far rounding may move
///     the root (narrowing_rounding over the slope): x - d and x + d,
///     clipped to [lo, hi], become [lo, hi] when their rounded signs are
///     lo's and hi's (the first d that has them)
///   bisect [lo, hi] until its ends are neighbouring doubles
template <class NT>
std::optional<std::pair<double, double>> double_root_bracket(const polynomial<NT>& p, const isolated_root<NT>& r) {
    using tr = number_traits<NT>;
    const std::vector<double> c = rounded_coefficients(p);
    const auto value = [&c](double x) { return rounded_value(c, x); };
    double lo = tr::to_double(r.low), hi = tr::to_double(r.high);
    const double v_lo = value(lo), v_hi = value(hi);
    if (!(v_lo < 0 && v_hi > 0) && !(v_lo > 0 && v_hi < 0)) return std::nullopt;
    const bool rising = v_hi > 0;
    // Newton's steps, every value narrowing the bracket by its sign.
    double x = lo + (hi - lo) * (v_lo / (v_lo - v_hi)), spread = 0;
    for (int step = 0; step < narrowing_newton_steps && x > lo && x < hi; ++step) {
        const rounded_at at = rounded_with_slope(c, x);
        if (at.value != 0) ((at.value > 0) == rising ? hi : lo) = x;
        spread = at.spread;
        double next = x - at.value / at.slope;
        if (next == x) break;
        if (!(next > lo && next < hi)) next = lo + (hi - lo) / 2;  // (the step fails: the bracket's middle)
        x = next;
    }
    // The steps approach from one side, so that one end may not have moved:
    // the doubles either side of the last guess by as far as rounding may
    // move its root, eight and 64 times as far while the rounded signs there
    // are not the ends' (an end already nearer stays).
    if (x > lo && x < hi) {
        double reach = std::max(spread, std::nextafter(x, HUGE_VAL) - x);
        for (int probe = 0; probe < narrowing_probes; ++probe, reach *= 8) {
            const double below = std::max(lo, x - reach), above = std::min(hi, x + reach);
            const bool low_holds = below == lo || value(below) * (rising ? -1 : 1) > 0,
                       high_holds = above == hi || value(above) * (rising ? 1 : -1) > 0;
            if (low_holds && high_holds) {
                lo = below;
                hi = above;
                break;
            }
        }
    }
    for (;;) {
        const double mid = lo + (hi - lo) / 2;
        if (!(mid > lo && mid < hi)) break;
        (((value(mid) > 0) == rising) ? hi : lo) = mid;
    }
    return std::pair{lo, hi};
}

/// Narrows the bracket r of the only root of s[0] in it about the
/// neighbouring doubles lo < hi (double_root_bracket's guess): to a few
/// units in the last place when a bracket of them is checked exactly to
/// hold a root of s[0] (opposite_end_signs, else roots_between). False, r
/// unchanged, when no check holds.
///
///   widen [lo, hi] by four units each side, clipped to r; check it exactly
///   failing, by 128 units, and then by twice the root's rounding there
///     (each when wider than the last), and check again
template <class NT>
bool narrowed_about(const std::vector<polynomial<NT>>& s, isolated_root<NT>& r, double lo, double hi) {
    using tr = number_traits<NT>;
    // The exact root within a few units of [lo, hi] (double's root of the
    // rounded coefficients), else within 128, else within how far their
    // rounding and Horner's may move it (narrowing_rounding over the slope,
    // twice).
    const double unit = hi - lo;
    const double reach[] = {4 * unit, 128 * unit, 2 * rounded_with_slope(rounded_coefficients(s[0]), lo).spread};
    for (std::size_t attempt = 0; attempt < 3; ++attempt) {
        // (Not wider than the last, or NaN: the check would fail again.)
        if (attempt > 0 && !(reach[attempt] > reach[attempt - 1])) return false;
        const double wide_lo = lo - reach[attempt], wide_hi = hi + reach[attempt];
        const NT nlo = compare_values<NT>(tr::from_double(wide_lo), r.low) > 0 ? NT(tr::from_double(wide_lo)) : r.low;
        const NT nhi = compare_values<NT>(tr::from_double(wide_hi), r.high) < 0 ? NT(tr::from_double(wide_hi)) : r.high;
        if (compare_values<NT>(nlo, nhi) >= 0) return false;
        // (nlo, nhi] lies within r, whose only root it holds when s[0]
        // changes sign across it (opposite_end_signs); else by its Sturm
        // count (when r's low_sign is known, s[0] is all there is to ask:
        // then not at all).
        const int low_sign = opposite_end_signs(s, nlo, nhi);
        if (low_sign != 0 || (r.low_sign == 0 && roots_between(s, nlo, nhi) == 1)) {
            r = {nlo, nhi, low_sign};
            return true;
        }
    }
    return false;
}

/// Narrows the bracket r of the only root of s[0] in it to a few units in
/// the last place of double: the root sought in double
/// (double_root_bracket), then a narrow bracket about it checked exactly
/// (narrowed_about). False, r unchanged, when either fails.
template <class NT>
bool narrowed_by_double(const std::vector<polynomial<NT>>& s, isolated_root<NT>& r) {
    const std::optional<std::pair<double, double>> guess = double_root_bracket(s[0], r);
    return guess && narrowed_about(s, r, guess->first, guess->second);
}

/// The sign of q at the root bracketed by r when q's value at the bracket's
/// upper end exceeds what q can change across the bracket (its width times
/// the sum of k |q_k|, which bounds |q'| on [-1, 1]); none otherwise.
template <class NT>
std::optional<int> sign_by_slope(const polynomial<NT>& q, const isolated_root<NT>& r) {
    using tr = number_traits<NT>;
    if (q.degree() < 0) return 0;
    const NT v = q.at(r.high);
    const int sign = tr::sign(v);
    if (sign == 0) return std::nullopt;
    NT slope = tr::from_double(0);
    for (std::size_t k = 1; k < q.c.size(); ++k) {
        const NT ck = tr::sign(q.c[k]) < 0 ? NT(-q.c[k]) : q.c[k];
        slope = NT(slope + ck * tr::from_double(static_cast<double>(k)));
    }
    const NT change = NT(slope * NT(r.high - r.low));
    if (compare_values<NT>(sign < 0 ? NT(-v) : v, change) > 0) return sign;
    return std::nullopt;
}

/// Whether q vanishes at the root of s[0] bracketed by r: q and s[0] share
/// a root in the bracket (their greatest common divisor has one there).
template <class NT>
bool vanishes_at(const polynomial<NT>& q, const std::vector<polynomial<NT>>& s, const isolated_root<NT>& r) {
    if (q.degree() < 0) return true;
    const polynomial<NT> g = common_divisor(s[0], q);
    if (g.degree() < 1) return false;
    return roots_between(sturm_sequence(g), r.low, r.high) > 0;
}

/// The sign of q at the root of s[0] bracketed by r (-1, 0 or +1), for a
/// bracket within [-1, 1]: at once when q's value at the upper end
/// outweighs its slope across the bracket (sign_by_slope); else 0 when
/// they share it; else the bracket is halved until q has no root in it,
/// and q's sign at its upper end is q's sign at the root. `r` is left
/// narrowed.
template <class NT>
int sign_at_root(const polynomial<NT>& q, const std::vector<polynomial<NT>>& s, isolated_root<NT>& r) {
    if (const std::optional<int> quick = sign_by_slope(q, r)) return *quick;
    if (vanishes_at(q, s, r)) return 0;
    const std::vector<polynomial<NT>> sq = sturm_sequence(q);
    for (int k = 0; roots_between(sq, r.low, r.high) > 0 && may_halve<NT>(k); ++k)
        if (!halve(s, r)) break;
    return q.sign_at(r.high);
}

/// The halvings compare_roots tries in an exact type before it looks for a
/// root the two polynomials share: two distinct roots within a bracket of
/// each other most often part after a few dozen (two vertices of a shared
/// border coming back onto their twins a few units in the 30th decimal of
/// time apart, within brackets as wide as a double's unit), where a greatest
/// common divisor of two cubics with long rational coefficients costs more
/// than a hundred halvings' worth.
inline constexpr int parting_halvings = 64;

/// The sign of x - y for the roots x of s[0] bracketed by r and y of t[0]
/// bracketed by u (-1, 0 or +1): 0 when the polynomials share a root in
/// both brackets; else the brackets are halved until they are apart. In an
/// exact type both are first halved up to parting_halvings times, the
/// brackets compared after each. Both are left narrowed.
template <class NT>
int compare_roots(const std::vector<polynomial<NT>>& s, isolated_root<NT>& r, const std::vector<polynomial<NT>>& t,
                  isolated_root<NT>& u) {
    const auto below = [](const isolated_root<NT>& l, const isolated_root<NT>& h) {
        return compare_values<NT>(l.high, h.low) <= 0;
    };
    if (below(r, u)) return -1;
    if (below(u, r)) return 1;
    // Both brackets halved up to `times` times (while may_halve allows):
    // -1 or +1 once they part, 0 when they did not.
    const auto parted = [&](int times) {
        for (int k = 0; k < times && may_halve<NT>(k); ++k) {
            const bool moved = halve(s, r);
            if (!halve(t, u) && !moved) break;
            if (below(r, u)) return -1;
            if (below(u, r)) return 1;
        }
        return 0;
    };
    if constexpr (is_exact_v<NT> && !signs_may_be_in_doubt<NT>::value)
        if (const int order = parted(parting_halvings)) return order;
    const polynomial<NT> g = common_divisor(s[0], t[0]);
    if (g.degree() >= 1) {
        // A shared root in the overlap of the brackets is both roots.
        const NT lo = compare_values<NT>(r.low, u.low) >= 0 ? r.low : u.low;
        const NT hi = compare_values<NT>(r.high, u.high) <= 0 ? r.high : u.high;
        if (compare_values<NT>(lo, hi) < 0) {
            const std::vector<polynomial<NT>> sg = sturm_sequence(g);
            if (roots_between(sg, lo, hi) > 0 && root_within(s, r, lo, hi) && root_within(t, u, lo, hi)) {
                // x and y both lie in (lo, hi]; so does a root z of g, which
                // is a root of both: z = x and z = y, each being its
                // polynomial's only root in its bracket.
                return 0;
            }
        }
    }
    return parted(std::numeric_limits<int>::max());  // 0: rounded, the brackets stopped parting
}

}  // namespace influence2d
