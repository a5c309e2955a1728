// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The exit distance: how far B must translate along a direction to leave A
/// (the directional penetration depth; docs/sweep.md, "Exit distance").

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "influence2d/assert.hpp"
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
#include "influence2d/predicates/certain_nearest.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/predicates/segments.hpp"
#include "influence2d/query/intersects.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/edge_boxes.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

#include "influence2d/motion/translation_events.hpp"

namespace influence2d {

namespace exit_distance_detail {

using namespace sweep;

/// Throws invalid_input naming a component of the direction that is NaN or
/// infinite, or a direction of length zero.
inline void check_direction(double dx, double dy) {
    for (const auto& [name, v] : {std::pair<const char*, double>{"dx", dx}, {"dy", dy}})
        if (!std::isfinite(v))
            throw invalid_input(std::string("direction: ") + name + " is " +
                                (std::isnan(v) ? "NaN"
                                 : v > 0       ? "+infinity"
                                               : "-infinity") +
                                ", not a finite number");
    if (dx == 0 && dy == 0) throw invalid_input("direction: (0, 0) has no direction");
}

/// The direction scaled by a power of two 2^shift (exactly) to a largest
/// component in [1, 2): the windows of s, kept in double, then neither
/// overflow nor underflow; s for (dx, dy) is 2^shift times s for the scaled
/// one. Throws invalid_input when the components' magnitudes are too far
/// apart for both to scale exactly.
struct unit_direction {
    double dx = 0;  ///< the scaled direction's components
    double dy = 0;
    int shift = 0;  ///< the power of two applied

    unit_direction(double x, double y) : shift(-std::ilogb(std::max(std::fabs(x), std::fabs(y)))) {
        dx = std::ldexp(x, shift);
        dy = std::ldexp(y, shift);
        if (std::ldexp(dx, -shift) != x || std::ldexp(dy, -shift) != y)
            throw invalid_input("direction: the components' magnitudes are too far apart to scale exactly");
    }

    /// 2^shift in NT, exactly in an exact NT (two factors, each a double).
    template <class NT>
    NT factor() const {
        using tr = number_traits<NT>;
        return tr::from_double(std::ldexp(1.0, shift / 2)) * tr::from_double(std::ldexp(1.0, shift - shift / 2));
    }
};

/// A double s_max such that B, its box `bb` (in double, within e of its
/// place in NT) moved by s (dx, dy) for any s > s_max, lies beyond A's box
/// `ab` on one axis: the least over the axes that move of the s at which
/// B's box has crossed A's, with 4e of room and widened by
/// quotient_widening relative (the difference of the box sides rounds by
/// far less than e).
inline double exit_reach(const box& ab, const box& bb, double dx, double dy, double e) {
    double s = std::numeric_limits<double>::infinity();
    if (dx > 0) s = std::min(s, (ab.max_x - bb.min_x + 4 * e) / dx);
    if (dx < 0) s = std::min(s, (ab.min_x - bb.max_x - 4 * e) / dx);
    if (dy > 0) s = std::min(s, (ab.max_y - bb.min_y + 4 * e) / dy);
    if (dy < 0) s = std::min(s, (ab.min_y - bb.max_y - 4 * e) / dy);
    return std::max(0.0, s) * (1 + quotient_widening) + std::numeric_limits<double>::min();
}

/// A double x with s0 < x < s1, certainly (the comparisons exact, or
/// certain in a filtered NT), if the doubles of the two times have one
/// between them: their mean, or none.
template <class NT>
std::optional<double> double_between(const time_fraction<NT>& s0, const time_fraction<NT>& s1) {
    using tr = number_traits<NT>;
    const double lo = tr::to_double(s0.num) / tr::to_double(s0.den);
    const double hi = tr::to_double(s1.num) / tr::to_double(s1.den);
    const double x = lo + (hi - lo) / 2;
    if (!std::isfinite(x)) return std::nullopt;
    const NT nx = tr::from_double(x);
    if constexpr (has_try_sign<NT>::value) {
        // (A sign the bound leaves in doubt only leaves the other route:
        // asked with try_sign, which notes no doubt, so that a meeting test
        // in a doubt_noting scope is not dropped for it.)
        int below = 0, above = 0;
        if (tr::try_sign(s0.num - nx * s0.den, below) && below < 0 && tr::try_sign(s1.num - nx * s1.den, above) &&
            above > 0)
            return x;
    } else {
        try {
            if (compare_values<NT>(s0.num, nx * s0.den) < 0 && compare_values<NT>(s1.num, nx * s1.den) > 0) return x;
        } catch (const uncertain_sign&) {}
    }
    return std::nullopt;
}

/// The places of A's and B's vertices at one s strictly between the events
/// s0 < s1, in ring operations: at a double x between them (double_between),
/// A where it stands and B's vertices p + x d; else at s = (s0 + s1) / 2 on
/// both polygons scaled by D = 2 s0.den s1.den > 0 (which changes no
/// answer), B's vertices D p + N d with N = s0.num s1.den + s1.num s0.den.
/// The first keeps the coordinates' size (a filtered NT's bounds stay those
/// of the posing far from the origin, where D's own error times the
/// coordinates would swamp them); the second serves two events too close
/// for a double between them.
template <class NT>
class places_between {
public:
    places_between(translation_frame<NT>& f, const time_fraction<NT>& s0, const time_fraction<NT>& s1) : f_(f) {
        using tr = number_traits<NT>;
        if (const std::optional<double> x = double_between(s0, s1)) {
            const NT nx = tr::from_double(*x);
            shift_ = {nx * f.d.x, nx * f.d.y};
            shift_size_ = std::fabs(*x);
            return;
        }
        const NT half = s0.den * s1.den;
        const NT n = s0.num * s1.den + s1.num * s0.den;
        shift_ = {n * f.d.x, n * f.d.y};
        shift_size_ = std::fabs(tr::to_double(n));
        factor_ = half + half;
        factor_size_ = std::fabs(tr::to_double(*factor_));
    }
    /// A's vertex i.
    point<NT> a(std::size_t i) const {
        if (!factor_) return f_.a[i];
        return {*factor_ * f_.a[i].x, *factor_ * f_.a[i].y};
    }
    /// B's vertex j.
    point<NT> b(std::size_t j) const {
        if (!factor_) return {f_.b[j].x + shift_.x, f_.b[j].y + shift_.y};
        return {*factor_ * f_.b[j].x + shift_.x, *factor_ * f_.b[j].y + shift_.y};
    }
    /// A bound of the coordinates' magnitudes, for inputs within `scale`
    /// and a direction of |dx| + |dy| = `reach`.
    double magnitude(double scale, double reach) const { return factor_size_ * scale + shift_size_ * reach; }

private:
    translation_frame<NT>& f_;
    std::optional<NT> factor_;
    point<NT> shift_;
    double factor_size_ = 1, shift_size_ = 0;
};

/// Whether A and B, placed at an s strictly between two events (`at`),
/// meet, with what showed it (placed_meet). `scale` bounds the magnitudes
/// of the inputs (the polygons and B's translation), `reach` |dx| + |dy|.
template <class NT>
meeting meeting_between(translation_frame<NT>& f, const places_between<NT>& at, double scale, double reach) {
    const polygon &as = f.a.shape(), &bs = f.b.shape();
    std::vector<point<NT>> av(as.size()), bv(bs.size());
    for (std::size_t i = 0; i < as.size(); ++i) av[i] = at.a(i);
    for (std::size_t j = 0; j < bs.size(); ++j) bv[j] = at.b(j);
    placed_polygon<NT> pa(as, av), pb(bs, bv);
    return placed_meet(pa, pb, placing_margin<NT>(at.magnitude(scale, reach)));
}

/// A witness of the meeting at an s strictly between the events s0 < s1
/// (`at`) among the edge pairs next to the site `s` (its vertex's two
/// edges against its edge and that edge's two neighbours); none when none
/// of them meets. After an event at s0 that touched the witness, the edges
/// at that event are the likeliest to show the meeting on (s0, s1): a
/// vertex that entered the other polygon there has edges that cross the
/// one it passed. Six segment tests, where meeting_between tests the whole
/// polygons.
template <class NT>
meeting witness_near(const translation_frame<NT>& f, const places_between<NT>& at, const contact_site& s) {
    const polygon &as = f.a.shape(), &bs = f.b.shape();
    const polygon &vs = s.moving_vertex ? bs : as, &es = s.moving_vertex ? as : bs;
    const std::size_t vertex_edges[2] = {vs.previous(s.vertex), s.vertex};
    const std::size_t edges[3] = {es.previous(s.edge), s.edge, es.next(s.edge)};
    for (const std::size_t v : vertex_edges)
        for (const std::size_t e : edges) {
            const std::size_t i = s.moving_vertex ? e : v, j = s.moving_vertex ? v : e;
            if (segments_intersect(at.a(i), at.a(as.next(i)), at.b(j), at.b(bs.next(j))))
                return {meeting::kind::edges, i, j, location::boundary};
        }
    return {};
}

/// What shows the meeting at an s strictly between the events s0 < s1
/// (places_between): an edge pair next to `last`, the site of the event at
/// s0, when given (witness_near), else the meeting there (meeting_between);
/// none when they do not meet there.
template <class NT>
meeting witness_between(translation_frame<NT>& f, const time_fraction<NT>& s0, const time_fraction<NT>& s1,
                        const contact_site* last, double scale, double reach) {
    const places_between<NT> at(f, s0, s1);
    const meeting w = last != nullptr ? witness_near(f, at, *last) : meeting{};
    return w ? w : meeting_between(f, at, scale, reach);
}

/// Whether an event at `s` can change what the witness `w` shows: it
/// puts one of the witness's features in contact. A vertex located in the
/// other polygon stays there until it reaches that polygon's boundary (an
/// event of that vertex); an edge pair keeps meeting or not until an end of
/// one reaches the other (an event of the pair).
inline bool touches(const meeting& w, const contact_site& s, const polygon& a, const polygon& b) {
    switch (w.how) {
    case meeting::kind::b_vertex_in_a: return s.moving_vertex && s.vertex == w.b_index;
    case meeting::kind::a_vertex_in_b: return !s.moving_vertex && s.vertex == w.a_index;
    case meeting::kind::edges:
        if (s.moving_vertex) return s.edge == w.a_index && (s.vertex == w.b_index || s.vertex == b.next(w.b_index));
        return s.edge == w.b_index && (s.vertex == w.a_index || s.vertex == a.next(w.a_index));
    default: return true;
    }
}

/// What shows the meeting at an s strictly between `last` and the window's
/// end w, after the window's last event (witness_between, tried first on
/// the edges next to `last_site`, that event's site, when given; none of
/// the window's events comes on (last, w], so the answer holds on all of
/// it): none when `last` is not certainly before w, or the test's bound
/// leaves a sign in doubt (noted_fallback); then the search loads the next
/// window as if it had not been asked.
template <class NT>
std::optional<meeting> meeting_before_window_end(translation_frame<NT>& f, const time_fraction<NT>& last, double w,
                                                 const contact_site* last_site, double scale, double reach) {
    using tr = number_traits<NT>;
    const time_fraction<NT> end{tr::from_double(w), NT(1)};
    return noted_fallback::run(
        [&]() -> std::optional<meeting> {
            if (compare_times(last, end) >= 0) return std::nullopt;
            return witness_between(f, last, end, last_site, scale, reach);
        },
        [] { return std::optional<meeting>(); });
}

/// An event of the exit search: its time, its site, and which of the site's
/// contact times it is (translation_frame::times' order, the same in every
/// NT whose signs are exact).
template <class NT>
struct timed_site {
    time_fraction<NT> time;
    contact_site site;
    int which = 0;
    /// The vertices it passes through exactly, when the frame names them
    /// (translation_frame::given).
    std::optional<vertex_passage> passage;
    /// The time's double, to sort by (sort_by_time; a NaN quotient of two
    /// times beyond double's range is infinity); 0 in a floating NT, which
    /// sorts by its times themselves.
    double estimate = 0;
    /// The sign of this time minus the previous event's in the sorted list
    /// (0 or 1), when sort_by_time asked it.
    std::optional<int> after_previous;

    timed_site(time_fraction<NT> t, const contact_site& s, int w, std::optional<vertex_passage> p = std::nullopt)
        : time(std::move(t)), site(s), which(w), passage(p) {
        using tr = number_traits<NT>;
        if constexpr (tr::category != number_category::floating) {
            const double q = tr::to_double(time.num) / tr::to_double(time.den);
            estimate = std::isnan(q) ? std::numeric_limits<double>::infinity() : q;
        }
    }
};

/// The search in NT alone (exit_search's `settle` and `redo`): a doubt of a
/// filtered NT's bound raises uncertain_sign.
struct nt_alone {
    template <class NT>
    int operator()(const timed_site<NT>&, const timed_site<NT>&) const {
        throw uncertain_sign();
    }
    template <class NT>
    int operator()(const timed_site<NT>&) const {
        throw uncertain_sign();
    }
    template <class NT>
    meeting operator()(const timed_site<NT>*, const timed_site<NT>*) const {
        throw uncertain_sign();
    }
};

/// The sign of l's time minus r's (compare_times in NT); in a filtered NT
/// with try_sign, when the bound cannot settle it, `settle(l, r)` (the
/// sign found otherwise, or uncertain_sign).
template <class NT, class Settle>
int compare_events(const timed_site<NT>& l, const timed_site<NT>& r, Settle&& settle) {
    if constexpr (has_try_sign<NT>::value) {
        if (const std::optional<int> o = certain_time_order(l.time, r.time)) return *o;
        return settle(l, r);
    } else {
        return compare_times(l.time, r.time);
    }
}

/// The sign of e's time (its comparison with 0); in a filtered NT with
/// try_sign, when the bound cannot settle it, `settle(e)`.
template <class NT, class Settle>
int sign_of_time(const timed_site<NT>& e, Settle&& settle) {
    if constexpr (has_try_sign<NT>::value) {
        int sign = 0;
        if (number_traits<NT>::try_sign(e.time.num, sign)) return sign;
        return settle(e);
    } else {
        return number_traits<NT>::sign(e.time.num);
    }
}

/// Sorts the events by time (compare_events in NT). For a type other than
/// the floating ones: by the doubles of their times first, then checked
/// pair of neighbours by pair of neighbours in NT, and sorted by NT's
/// comparisons only when one pair is out of order. A comparison sort
/// compares every two neighbours of its result, so the check asks no sign
/// that sorting by NT alone would not, and asks n - 1 where the sort asks
/// about n log n (each a product of two times in `certified` or exact
/// rationals). The check keeps each sign it found (after_previous): the
/// search asks it again when it passes the events of one time, and a tie a
/// filtered NT cannot settle costs an exact test.
template <class NT, class Settle>
void sort_by_time(std::vector<timed_site<NT>>& events, Settle&& settle) {
    using tr = number_traits<NT>;
    if constexpr (tr::category != number_category::floating) {
        std::sort(events.begin(), events.end(),
                  [](const timed_site<NT>& l, const timed_site<NT>& r) { return l.estimate < r.estimate; });
        bool ordered = true;
        for (std::size_t k = 1; k < events.size() && ordered; ++k) {
            const int sign = compare_events(events[k], events[k - 1], settle);
            ordered = sign >= 0;
            events[k].after_previous = sign;
        }
        if (ordered) return;
        for (timed_site<NT>& x : events) x.after_previous.reset();
    }
    std::sort(events.begin(), events.end(),
              [&](const timed_site<NT>& l, const timed_site<NT>& r) { return compare_events(l, r, settle) < 0; });
}

/// The sweep, in placing margins of the inputs' scale, up to which the exit
/// search takes B's whole reach s_max as one window: B's box then overlaps
/// A's by at most a few dozen margins along the direction (neighbours that
/// share a border, or overlap by rounding). Windows pay where B sweeps far
/// (each holds few of the sites); over so short a sweep every window holds
/// the same sites, and a meeting test inside one, in a filtered type, is in
/// doubt. 64 margins: four of exit_reach's own room, sixteen times over.
inline constexpr double short_sweep = 64;

/// The exit search of exit_distance (its pseudocode) for B posed by t and
/// translated by s (dx, dy), the direction's largest component in [1, 2);
/// `scale` bounds the magnitudes of the polygons and of t's translation.
/// Returns the event at the exit, whose time is the exit in units of
/// (dx, dy); none when the exit is 0 (the regions do not meet at q, or no
/// event comes after it). `settle(l, r)` orders two events where a filtered
/// NT's bound cannot (compare_events), `settle(e)` gives the sign of one's
/// time (sign_of_time); `redo(last, following)` finds the
/// witness between two events (last none: 0), or at 0 (both none), where
/// its bound leaves a meeting test in doubt. In `certified`, with B not turned, the sides its
/// bound leaves in doubt are decided exactly (translation_frame::given).
template <class NT, class Settle, class Redo>
std::optional<timed_site<NT>> exit_search(const polygon& a, const polygon& b, const rotation_pose& t, double dx,
                                          double dy, double scale, Settle&& settle, Redo&& redo) {
    using namespace sweep;
    using tr = number_traits<NT>;
    translation_frame<NT> f(a, b, t, {tr::from_double(dx), tr::from_double(dy)});
    if (std::is_same_v<NT, certified> && t.c == 1 && t.s == 0)
        f.given = given_translation{{t.tx, t.ty}, {0, 0}, {dx, dy}, std::nullopt};
    const double reach = std::fabs(dx) + std::fabs(dy);
    const double e0 = placing_margin<NT>(scale);
    const time_fraction<NT> zero{NT(0), NT(1)};
    std::optional<timed_site<NT>> exit;
    // (A filtered NT's doubt in a meeting test is noted, not raised, and
    // the test redone: noted_fallback.)
    meeting witness = noted_fallback::run(
        [&] { return placed_meet(f.a, f.b, e0); },
        [&] { return redo(static_cast<const timed_site<NT>*>(nullptr), static_cast<const timed_site<NT>*>(nullptr)); });
    if (!witness) return exit;
    const double s_max = exit_reach(a.bounds(), f.b.bounds(), dx, dy, e0);
    const double e = placing_margin<NT>(scale + s_max * reach);
    const auto beyond = [](const time_fraction<NT>& s, double x) {
        return compare_values<NT>(s.num, tr::from_double(x) * s.den) > 0;
    };
    // The events of the window (w_low, w] of s, sorted. In an exact NT a
    // site is first tried in certified: one that certainly has no event
    // costs no exact arithmetic.
    constexpr bool exact = tr::category == number_category::exact;
    std::optional<translation_frame<certified>> fast;
    if constexpr (exact) fast.emplace(a, b, t, point<certified>{certified(dx), certified(dy)});
    std::vector<timed_site<NT>> events;
    const auto load = [&](double w_low, double w) {
        events.clear();
        const point<double> from{std::max(w_low, 0.0) * dx, std::max(w_low, 0.0) * dy}, to{w * dx, w * dy};
        candidate_sites(a, b, f.b.approx(), f.b.bounds(), from, to, e, [&](const contact_site& site) {
            // (A site whose path over the window misses its edge has no
            // event there.)
            if (!site_may_meet(a, b, f.b.approx(), from, to, e, site)) return;
            if constexpr (exact) {
                try {
                    time_fraction<certified> none[2];
                    if (fast->times(site, false, none) == 0) return;
                } catch (const uncertain_sign&) {}
            }
            time_fraction<NT> times[2];
            std::optional<vertex_passage> passages[2];
            const int k = f.times(site, false, times, passages);
            for (int i = 0; i < k; ++i)
                if ((w_low < 0 || beyond(times[i], w_low)) && !beyond(times[i], w))
                    events.emplace_back(std::move(times[i]), site, i, passages[i]);
        });
        sort_by_time(events, settle);
    };
    double w_low = -1, w = s_max * reach <= short_sweep * e0 ? s_max : std::min(s_max, s_max * first_window);
    load(w_low, w);
    std::size_t next = 0;
    bool stale = false;  // an event at the exit so far touches the witness
    for (;;) {
        // The other events at the exit so far (some may come at 0). (The
        // event taken as the exit is not compared with itself: a filtered
        // NT cannot tell a value from itself.)
        // (Past the first event of a window, the exit's time is the previous
        // event's: its sign against it, when sorting found it, is the one
        // asked.)
        const time_fraction<NT>& last = exit ? exit->time : zero;
        const auto at_last = [&](const timed_site<NT>& x, bool after_exit) {
            if (after_exit && x.after_previous) return *x.after_previous <= 0;
            return (exit ? compare_events(x, *exit, settle) : sign_of_time(x, settle)) <= 0;
        };
        for (; next < events.size() && at_last(events[next], exit && next > 0); ++next)
            if (touches(witness, events[next].site, a, b)) stale = true;
        while (next == events.size() && w < s_max) {
            // (No event comes on (last, w]: a stale witness is asked there
            // before the next window is loaded.)
            if (stale)
                if (const std::optional<meeting> m =
                        meeting_before_window_end(f, last, w, exit ? &exit->site : nullptr, scale, reach)) {
                    if (!*m) return exit;
                    witness = *m;
                    stale = false;
                }
            w_low = w;
            w = std::min(s_max, 2 * w);
            load(w_low, w);
            next = 0;
        }
        if (next == events.size()) return exit;  // after the last event, apart
        timed_site<NT> following = events[next++];
        if (stale) {
            witness = noted_fallback::run(
                [&] { return witness_between(f, last, following.time, exit ? &exit->site : nullptr, scale, reach); },
                [&] { return redo(exit ? &*exit : nullptr, &following); });
            if (!witness) return exit;
        }
        stale = touches(witness, following.site, a, b);
        exit = std::move(following);
    }
}

}  // namespace exit_distance_detail

/// The directional penetration depth: with B posed by q and then translated
/// by s (dx, dy), the end of the interval of s >= 0, starting at 0, during
/// which the closed regions of A and B meet; 0 when they do not meet at q.
/// In units of (dx, dy): a distance when it is a unit vector. At the
/// returned s the regions touch, and for s a little larger they do not.
/// Exact in an exact NT (NT needs division, as for first_contact).
///
///   w <- the one-shot query at q (what shows they meet); apart:  0
///   s_max <- beyond it B's box has left A's box along d (double, widened)
///   the events (every time s >= 0 a vertex starts or stops lying on an
///   edge: contact_times, both ends of a sliding contact), gathered by
///   windows (0, s_max / 64], then doubled (one window (0, s_max] when
///   B sweeps within short_sweep margins), from the sites whose boxes
///   overlap, B's swept over the window, and whose vertex's path over it
///   may meet the edge (site_may_meet); sorted (sort_by_time: by their
///   doubles, the order checked in NT): s_1 < s_2 < ... < s_K
///   last <- 0
///   loop:
///       if an event at `last` touches w's features (a located vertex
///       reaching an edge, an end of w's edge pair reaching the other):
///           w <- at a double between `last` and `next` (else at their
///           midpoint, both polygons scaled to keep ring operations;
///           places_between): an edge pair next to the event at `last`
///           that meets (witness_near), else the meeting there (the
///           one-shot query's steps)
///           apart there:                              last
///           (the window's events all passed while w is stale: w <- at
///           a double between `last` and the window's end, as above; apart
///           there: last; a doubt there: the next window loaded as before)
///       no next event:                                last (then apart)
///       last <- the next event
///
/// Between two consecutive events no vertex reaches or leaves an edge, so
/// whether the regions meet does not change, and neither does what a
/// witness shows unless an event at its start touches it (docs/sweep.md,
/// "Exit distance"). Time O((n + m) log(n + m) + k log k) for k events up to
/// the exit, plus O((n + m) log(n + m)) for each event that touches the
/// witness and whose neighbouring edge pairs show no meeting. In float,
/// double or long double, a query whose largest coordinate lies outside
/// NT's safe window is answered on its polygons and pose scaled by a power
/// of two 2^k, and the distance found scaled back by 2^-k
/// (core/range_scaling.hpp), rounded as NT's range allows. Throws
/// invalid_input for an empty polygon, a NaN or infinite component of q or
/// of the direction, a direction (0, 0), or one whose components differ by
/// more than double's range (2^1022 times).
template <class NT>
NT exit_distance(const polygon& a, const polygon& b, const pose& q, double dx, double dy) {
    using namespace exit_distance_detail;
    accepted_polygon<NT>(a, "static");
    accepted_polygon<NT>(b, "moving");
    const rotation_pose t(q);
    check_direction(dx, dy);
    if constexpr (scaled_into_range_v<NT>) {
        if (const int k = range_shift<NT>(a, b, q))
            return std::ldexp(exit_distance<NT>(a.scaled_by_power_of_two(k), b.scaled_by_power_of_two(k),
                                                scaled_by_power_of_two(q, k), dx, dy),
                              -k);
    }
    const unit_direction u(dx, dy);
    const double scale = coordinate_scale(a) + coordinate_scale(b) + std::fabs(q.tx) + std::fabs(q.ty);
    const std::optional<timed_site<NT>> exit = exit_search<NT>(a, b, t, u.dx, u.dy, scale, nt_alone{}, nt_alone{});
    if (!exit) return NT(0);
    return exit->time.num / exit->time.den * u.factor<NT>();
}

/// The exit distance of exit_distance<Exact>, rounded to the nearest double,
/// at nearly double's cost: the exit search run in `certified` (the events'
/// times, their order and the meeting tests, each sign certain or raising
/// uncertain_sign), then the one event at the exit evaluated again from its
/// site's three vertices and rounded, in double words where their bound
/// settles the rounding, else in Exact (nearest_site_time). The search takes
/// the exact search's every branch, so its exit is the exact exit. When B is
/// not turned (its rotation's doubles exactly 1 and 0), the signs its bound
/// leaves in doubt where a shared border moves along itself are decided on
/// the doubles as given: a vertex's side against another's line of motion
/// and a time's numerator (translation_frame::given), two events of one
/// time (a vertex passing through a vertex, same_passage_time; vertices
/// reaching parallel lines together, same_reaching_time). Two events it
/// cannot order otherwise are ordered on their sites' times in double
/// words, else in Exact (`settle`); a meeting test it leaves in doubt is
/// done again in double words at the events' times in double words, else in
/// Exact at their exact times (`redo`). Any other sign
/// that `certified` cannot settle (coordinates far from 1 in scale, say)
/// sends the query to exit_search<Exact> whole. Throws as exit_distance.
/// `*by_filter`, when given, says whether the search in `certified`
/// answered (no sign sent the whole query to exit_search<Exact>).
/// certified_exit_distance (exact/certified_exit_distance.hpp) is this query
/// in exact rationals.
///
///   (exit, event) <- exit_search<certified> (B not turned: the doubles as
///                    given decide the sides, numerators and ties above;
///                    other doubtful orders and meeting tests in double
///                    words or Exact), or on uncertain_sign
///                    exit_search<Exact>
///   no event:                      0
///   the event's time times 2^shift, rounded to the nearest double: in
///   double words (site_reaching_time, else the site's contact_times), or in
///   Exact when their bound leaves it in doubt
template <class Exact>
double filtered_exit_distance(const polygon& a, const polygon& b, const pose& q, double dx, double dy,
                              bool* by_filter = nullptr) {
    using namespace exit_distance_detail;
    accepted_polygon<Exact>(a, "static");
    accepted_polygon<Exact>(b, "moving");
    const rotation_pose t(q);
    check_direction(dx, dy);
    const unit_direction u(dx, dy);
    const double scale = coordinate_scale(a) + coordinate_scale(b) + std::fabs(q.tx) + std::fabs(q.ty);
    if (by_filter != nullptr) *by_filter = false;
    // An event's time in W, from its site's three vertices posed alone
    // (site_times, the event's own of them), times 2^shift when `scaled`.
    const auto event_time = [&](auto tag, const timed_site<certified>& e, bool scaled) {
        using W = decltype(tag);
        using wt = number_traits<W>;
        time_fraction<W> times[2];
        const int k = site_times(a, b, t, point<W>{wt::from_double(u.dx), wt::from_double(u.dy)}, e.site, false, times);
        // (In double words the site may lack the time only after a doubt
        // noted on the way, whose answer is dropped: raised then.)
        if constexpr (wt::category != number_category::exact)
            if (e.which >= k) throw uncertain_sign();
        INFLUENCE2D_ASSERT(e.which < k, "an event is not one of its site's times");
        if (scaled) times[e.which].num *= u.factor<W>();
        return std::move(times[e.which]);
    };
    // An event's time in double words, kept once computed (events a few
    // units in the last place apart are each compared with several others
    // while their window is sorted, and bound the meeting tests between
    // them); none when the bound leaves a sign in doubt, kept as none too.
    using event_key = std::tuple<bool, std::uint32_t, std::uint32_t, int>;
    std::map<event_key, std::optional<time_fraction<double_word>>> word_times;
    const auto word_time = [&](const timed_site<certified>& e) -> const time_fraction<double_word>* {
        const event_key key{e.site.moving_vertex, e.site.vertex, e.site.edge, e.which};
        auto kept = word_times.find(key);
        if (kept == word_times.end()) {
            std::optional<time_fraction<double_word>> x = noted_fallback::run(
                [&] { return std::optional<time_fraction<double_word>>(event_time(double_word{}, e, false)); },
                [] { return std::optional<time_fraction<double_word>>(); });
            kept = word_times.emplace(key, std::move(x)).first;
        }
        return kept->second ? &*kept->second : nullptr;
    };
    const bool unturned = t.c == 1 && t.s == 0;
    const pose along{u.dx, u.dy, 0};
    // Two events that certified cannot order: one time when the doubles as
    // given show it, else ordered in double words, else in Exact; one
    // event's time against 0 likewise (r none).
    const auto order_of = [&](const timed_site<certified>& l, const timed_site<certified>* r) -> int {
        if (r != nullptr && unturned &&
            (l.passage && r->passage ? same_passage_time(a, b, {0, 0}, {u.dx, u.dy}, *l.passage, *r->passage)
                                     : same_reaching_time(a, b, pose{}, along, l.site, r->site)))
            return 0;
        const time_fraction<double_word> zero{double_word(0), double_word(1)};
        const time_fraction<double_word>*x = word_time(l), *y = r ? word_time(*r) : &zero;
        if (x != nullptr && y != nullptr)
            if (const std::optional<int> o = certain_time_order(*x, *y)) return *o;
        const time_fraction<Exact> exact_zero{Exact(0), Exact(1)};
        return compare_times(event_time(Exact{}, l, false), r ? event_time(Exact{}, *r, false) : exact_zero);
    };
    struct settler {
        const decltype(order_of)& order;
        int operator()(const timed_site<certified>& l, const timed_site<certified>& r) const { return order(l, &r); }
        int operator()(const timed_site<certified>& e) const { return order(e, nullptr); }
    } settle{order_of};
    // The witness between two events (last none: 0), or at 0 (both none),
    // in W: A and B placed in W once (`frame`), the events' times in W.
    const auto witness_in = [&](auto tag, auto& frame, const timed_site<certified>* last,
                                const timed_site<certified>* following) {
        using W = decltype(tag);
        using wt = number_traits<W>;
        if (!frame) frame.emplace(a, b, t, point<W>{wt::from_double(u.dx), wt::from_double(u.dy)});
        if (following == nullptr) return placed_meet(frame->a, frame->b, placing_margin<W>(scale));
        // (In double words the kept times; one missing is a doubt, raised.)
        const auto time_of = [&](const timed_site<certified>& e) {
            if constexpr (std::is_same_v<W, double_word>) {
                const time_fraction<double_word>* x = word_time(e);
                if (x == nullptr) throw uncertain_sign();
                return *x;
            } else {
                return event_time(tag, e, false);
            }
        };
        const time_fraction<W> s0 = last ? time_of(*last) : time_fraction<W>{W(0), W(1)};
        return witness_between(*frame, s0, time_of(*following), last ? &last->site : nullptr, scale,
                               std::fabs(u.dx) + std::fabs(u.dy));
    };
    // Where certified leaves a meeting test in doubt (B between two events
    // a few units in the last place apart, within rounding of touching A):
    // the same tests in double words, else in Exact. (A frame placed in a
    // test whose doubt was noted is dropped with its answer.)
    std::optional<translation_frame<double_word>> word_frame;
    std::optional<translation_frame<Exact>> exact_frame;
    const auto redo = [&](const timed_site<certified>* last, const timed_site<certified>* following) {
        const std::optional<meeting> in_words = noted_fallback::run(
            [&] { return std::optional<meeting>(witness_in(double_word{}, word_frame, last, following)); },
            [&] {
                word_frame.reset();
                return std::optional<meeting>();
            });
        return in_words ? *in_words : witness_in(Exact{}, exact_frame, last, following);
    };
    return fallback<>::run(
        [&] {
            const std::optional<timed_site<certified>> exit =
                exit_search<certified>(a, b, t, u.dx, u.dy, scale, settle, redo);
            if (by_filter != nullptr) *by_filter = true;
            if (!exit) return 0.0;
            const point<double_word> d{double_word(u.dx), double_word(u.dy)};
            double x = 0;
            if (certain_nearest(site_reaching_time(a, b, t, d, exit->site) * u.factor<double_word>(), x)) return x;
            return nearest_site_time<Exact>([&](auto tag) { return event_time(tag, *exit, true); });
        },
        [&] {
            const std::optional<timed_site<Exact>> exit =
                exit_search<Exact>(a, b, t, u.dx, u.dy, scale, nt_alone{}, nt_alone{});
            return exit ? nearest_double(time_fraction<Exact>{exit->time.num * u.factor<Exact>(), exit->time.den})
                        : 0.0;
        });
}

}  // namespace influence2d
