// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// First contact along a motion (continuous collision detection) and the
/// exit distance along a direction (docs/sweep.md).

#include <algorithm>
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

#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/fallback.hpp"
#include "influence2d/core/feature.hpp"
#include "influence2d/query/intersects.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/edge_boxes.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/predicates/orientation.hpp"

namespace influence2d {

/// The first contact of a motion.
template <class NT>
struct contact_result {
    /// Whether the closed regions meet at some time in [0, 1] (for a motion
    /// that turns: come within the tolerance of sweep_options).
    bool contact = false;
    /// The earliest such time: 0 when they meet at the start; exact in an
    /// exact NT for a translation; 0 when there is no contact.
    NT time{};
    /// A's feature that B touches first: an edge (B's vertex on it), a
    /// vertex (on B's edge), or, when the regions already meet at the start
    /// without boundary contact, the interior (B's vertex lies inside A).
    /// Input numbering; meaningful only with `contact`.
    feature static_feature{};
    /// B's feature in that contact, as static_feature.
    feature moving_feature{};
};

/// Options of first_contact.
struct sweep_options {
    /// For motions that turn: contact is reported at the first step where
    /// the distance between the regions is at most this (absolute, in the
    /// polygons' units; raised to the motion's resolution in double when
    /// smaller, see docs/sweep.md). 1e-9: far below any modelling
    /// tolerance of polygons of size 1 to 10^4, and far above the rounding
    /// of the posing (about 10^-16 times the scene's size) for them.
    double tolerance = 1e-9;
};

/// The pose of B at time t of the motion from `from` to `to`, as
/// first_contact computes it for a motion that turns: each component
/// from + t (to - from), in double.
inline pose motion_pose(const pose& from, const pose& to, double t) {
    return {from.tx + t * (to.tx - from.tx), from.ty + t * (to.ty - from.ty),
            from.theta + t * (to.theta - from.theta)};
}

namespace sweep_detail {


/// A contact event's place: B's vertex `vertex` reaching A's edge `edge`
/// (moving_vertex), or A's vertex `vertex` reaching B's edge `edge`.
/// Stored numbering.
struct contact_site {
    bool moving_vertex = true;  ///< whose vertex: B's (true) or A's
    std::uint32_t vertex = 0;   ///< the vertex
    std::uint32_t edge = 0;     ///< the other polygon's edge
};

/// The order that breaks ties between events of one time, so that every
/// mode names the same features: B's vertices first, then by vertex, then
/// by edge.
inline bool site_before(const contact_site& l, const contact_site& r) {
    if (l.moving_vertex != r.moving_vertex) return l.moving_vertex;
    if (l.vertex != r.vertex) return l.vertex < r.vertex;
    return l.edge < r.edge;
}


/// The site's features in input numbering: (A's, B's).
inline std::pair<feature, feature> site_features(const polygon& a, const polygon& b, const contact_site& s) {
    if (s.moving_vertex)
        return {{feature_kind::edge, a.source_edge(s.edge)}, {feature_kind::vertex, input_vertex(b, s.vertex)}};
    return {{feature_kind::vertex, input_vertex(a, s.vertex)}, {feature_kind::edge, b.source_edge(s.edge)}};
}

/// The features of a meeting at the start (meeting from placed_meet): a
/// vertex inside the other region meets its interior; a vertex on the
/// other's boundary meets the first edge (stored order) holding it; an edge
/// pair names a vertex of one on the other's edge when there is one, else
/// both edges (they cross). Exact when NT is.
template <class NT>
std::pair<feature, feature> meeting_features(placed_polygon<NT>& a, placed_polygon<NT>& b, const meeting& m) {
    const polygon &as = a.shape(), &bs = b.shape();
    const auto edge_holding = [](placed_polygon<NT>& p, const point<NT>& v) {
        const polygon& s = p.shape();
        for (std::size_t e = 0; e < s.size(); ++e)
            if (on_segment(v, p[e], p[s.next(e)])) return feature{feature_kind::edge, s.source_edge(e)};
        return feature{feature_kind::interior, 0};  // (not reached: the vertex was located on the boundary)
    };
    switch (m.how) {
    case meeting::kind::b_vertex_in_a: {
        const feature fb{feature_kind::vertex, input_vertex(bs, m.b_index)};
        if (m.where == location::inside) return {{feature_kind::interior, 0}, fb};
        return {edge_holding(a, b[m.b_index]), fb};
    }
    case meeting::kind::a_vertex_in_b: {
        const feature fa{feature_kind::vertex, input_vertex(as, m.a_index)};
        if (m.where == location::inside) return {fa, {feature_kind::interior, 0}};
        return {fa, edge_holding(b, a[m.a_index])};
    }
    default: {
        const std::size_t i = m.a_index, i2 = as.next(i), j = m.b_index, j2 = bs.next(j);
        const feature ea{feature_kind::edge, as.source_edge(i)}, eb{feature_kind::edge, bs.source_edge(j)};
        if (on_segment(b[j], a[i], a[i2])) return {ea, {feature_kind::vertex, input_vertex(bs, j)}};
        if (on_segment(b[j2], a[i], a[i2])) return {ea, {feature_kind::vertex, input_vertex(bs, j2)}};
        if (on_segment(a[i], b[j], b[j2])) return {{feature_kind::vertex, input_vertex(as, i)}, eb};
        if (on_segment(a[i2], b[j], b[j2])) return {{feature_kind::vertex, input_vertex(as, i2)}, eb};
        return {ea, eb};
    }
    }
}

/// The features of the meeting of A and of B posed at the motion's start,
/// decided in NT; none when they do not meet there (the one-shot query).
template <class NT>
std::optional<std::pair<feature, feature>> meeting_at_start(const polygon& a, const polygon& b, const pose& from,
                                                            const rotation_pose& start) {
    placed_polygon<NT> pa(a), pb(b, start);
    const meeting met = placed_meet(
        pa, pb,
        posing_margin<NT>(coordinate_scale(a) + coordinate_scale(b) + std::fabs(from.tx) +
                                           std::fabs(from.ty)));
    if (!met) return std::nullopt;
    return meeting_features(pa, pb, met);
}

/// Calls visit(site) for both sites of every pair of A's edge i and B's
/// edge j whose boxes overlap, B's edge box swept from its place at the
/// start (vertices `b_start` in double) shifted by `from` to that place
/// shifted by `to`, every box grown by e: B's vertex j against A's edge i,
/// and A's vertex i against B's edge j. Every vertex of B that reaches an
/// edge of A during that part of the motion is the start of an edge of B
/// whose swept box meets that edge's box, and likewise for A's vertices: no
/// event of that part is left out. Sort and sweep along x (scene/edge_boxes.hpp).
template <class Visit>
void candidate_sites(const polygon& a, const polygon& b, const std::vector<point<double>>& b_start,
                     const box& b_start_box, point<double> from, point<double> to, double e, Visit&& visit) {
    box swept;
    for (const point<double>& shift : {from, to}) {
        swept.add({b_start_box.min_x + shift.x, b_start_box.min_y + shift.y});
        swept.add({b_start_box.max_x + shift.x, b_start_box.max_y + shift.y});
    }
    std::vector<edge_box> a_edges, b_edges;
    edges_meeting(a, a.vertices(), swept.inflated(e), e, a_edges);
    edges_meeting(b, b_start, a.bounds().inflated(e), e, b_edges, from, to);
    overlapping_pairs(a_edges, b_edges, [&](std::uint32_t i, std::uint32_t j) {
        visit(contact_site{true, j, i});
        visit(contact_site{false, i, j});
        return false;
    });
}

/// A lower bound, in double, of the first t >= 0 at which B's box `bb`
/// (within e of its place in NT) moved by t `sweep` meets A's box `ab`:
/// the latest of the axes' entry times, with 4e of room and shrunk by
/// 2^-40 relative (the quotients' roundings are below 2^-50 relative);
/// infinity when an axis that does not move keeps the boxes apart.
inline double box_entry(const box& ab, const box& bb, point<double> sweep, double e) {
    double t = 0;
    const auto axis = [&](double a_min, double a_max, double b_min, double b_max, double d) {
        if (b_max + 4 * e >= a_min && b_min - 4 * e <= a_max) return;  // overlapping already
        if (d == 0) t = std::numeric_limits<double>::infinity();
        else if (b_max < a_min) t = std::max(t, d > 0 ? (a_min - b_max - 4 * e) / d : std::numeric_limits<double>::infinity());
        else t = std::max(t, d < 0 ? (a_max - b_min + 4 * e) / d : std::numeric_limits<double>::infinity());
    };
    axis(ab.min_x, ab.max_x, bb.min_x, bb.max_x, sweep.x);
    axis(ab.min_y, ab.max_y, bb.min_y, bb.max_y, sweep.y);
    return t * (1 - 0x1p-40);
}

/// The first window of a translation's search, as a fraction of the
/// motion after B's box first meets A's: 1/64, doubled while no event is
/// found (at most seven windows).
inline constexpr double first_window = 1.0 / 64;

/// Calls visit(site) for the candidate sites (candidate_sites) of
/// consecutive windows of time [w0, w1], growing, stopping once the
/// earliest event is known:
///
///   enter <- when B's box first meets A's (box_entry); beyond 1: none
///   [w0, w1] <- [enter, enter + first_window]
///   loop:
///       visit the sites of B swept over [w0, w1]
///       (every event at a time in [w0, w1] is among them)
///       u <- best_upper(): a double above the least event found, if any
///       if u <= w1 or w1 = 1:  done
///       next window: [w1, min(u, 1)] (then done) if there is a u,
///       else [w1, enter + 2 (w1 - enter)], at most 1
///
/// Events before w0 were all found in the earlier windows (none before
/// enter), so the earliest event found once a window reaches it is the
/// first contact; events found beyond a window are true events too, and
/// bound the last window.
template <class Visit, class Upper>
void windowed_sites(const polygon& a, const polygon& b, const std::vector<point<double>>& b_start,
                    const box& b_start_box, point<double> sweep, double e, Visit&& visit, Upper&& best_upper) {
    const double enter = box_entry(a.bounds(), b_start_box, sweep, e);
    if (!(enter <= 1)) return;
    double w0 = enter, w1 = std::min(1.0, enter + first_window);
    for (bool last = false;;) {
        candidate_sites(a, b, b_start, b_start_box, {w0 * sweep.x, w0 * sweep.y}, {w1 * sweep.x, w1 * sweep.y}, e,
                        visit);
        if (last || w1 >= 1) return;
        w0 = w1;
        if (const std::optional<double> u = best_upper()) {
            if (*u <= w1) return;
            w1 = std::min(1.0, *u);
            last = true;
        } else {
            w1 = std::min(1.0, enter + 2 * (w1 - enter));
        }
    }
}

/// A double above the time num / den (exact or floating NT): the quotient of
/// their nearest doubles (within 2^-50 relative) widened by 2^-40.
template <class NT>
double time_above(const time_fraction<NT>& t) {
    using tr = number_traits<NT>;
    const double q = tr::to_double(t.num) / tr::to_double(t.den);
    return std::isfinite(q) ? q * (1 + 0x1p-40) + 0x1p-1000 : std::numeric_limits<double>::infinity();
}

/// A translation in NT: A where it stands, B posed at the start, the
/// displacement d (and -d, A's motion relative to B).
template <class NT>
struct translation_frame {
    placed_polygon<NT> a, b;
    point<NT> d, minus_d;

    translation_frame(const polygon& as, const polygon& bs, const rotation_pose& start, point<NT> dd)
        : a(as), b(bs, start), d(dd), minus_d{-dd.x, -dd.y} {}

    /// The site's contact times in range (t in [0, 1] when bounded, t >= 0
    /// otherwise): at most two (contact_times).
    int times(const contact_site& s, bool bounded, time_fraction<NT> out[2]) {
        if (s.moving_vertex)
            return contact_times(b[s.vertex], d, a[s.edge], a[a.shape().next(s.edge)], bounded, out);
        return contact_times(a[s.vertex], minus_d, b[s.edge], b[b.shape().next(s.edge)], bounded, out);
    }

    /// The site's earliest contact time in [0, 1], if any.
    std::optional<time_fraction<NT>> earliest(const contact_site& s) {
        if (s.moving_vertex) return earliest_contact_time(b[s.vertex], d, a[s.edge], a[a.shape().next(s.edge)]);
        return earliest_contact_time(a[s.vertex], minus_d, b[s.edge], b[b.shape().next(s.edge)]);
    }
};

/// The earliest contact time of one site in [0, 1] in NT, posing only the
/// site's three vertices (B's by `start`; `d` the displacement in NT): the
/// filtered search's exact evaluation of a site, without the whole frame.
template <class NT>
std::optional<time_fraction<NT>> site_time(const polygon& a, const polygon& b, const rotation_pose& start,
                                           const point<NT>& d, const contact_site& s) {
    const auto in_a = [&](std::size_t i) { return to_point<NT>(a.vertex(i)); };
    const auto in_b = [&](std::size_t j) { return start.apply<NT>(b.vertex(j)); };
    if (s.moving_vertex) return earliest_contact_time(in_b(s.vertex), d, in_a(s.edge), in_a(a.next(s.edge)));
    return earliest_contact_time(in_a(s.vertex), point<NT>{-d.x, -d.y}, in_b(s.edge), in_b(b.next(s.edge)));
}

/// The validated parts of a motion: its start and end as rotation poses
/// (invalid_input for a NaN or infinite component of either).
struct motion {
    rotation_pose start, end;
    motion(const pose& from, const pose& to) : start(from), end(checked_end(to)) {}

    /// The motion of B from `from` to `to` against A, both polygons checked
    /// for NT (accepted_polygon) and the options' tolerance (finite, >= 0).
    template <class NT>
    static motion accepted(const polygon& a, const polygon& b, const pose& from, const pose& to,
                           const sweep_options& options) {
        accepted_polygon<NT>(a, "static");
        accepted_polygon<NT>(b, "moving");
        if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
            throw invalid_input("sweep_options: tolerance is " + std::to_string(options.tolerance) +
                                ", not a finite number >= 0");
        return motion(from, to);
    }

private:
    static rotation_pose checked_end(const pose& to) {
        try {
            return rotation_pose(to);
        } catch (const invalid_input& e) {
            throw invalid_input(std::string("end ") + e.what());
        }
    }
};

/// The filters' margin for a translation from `from` to `to`: the posing
/// margin of one_shot with both translations in the scale (B's vertices in
/// double at any time of the motion are within it of their NT values).
template <class NT>
double translation_margin(const polygon& a, const polygon& b, const pose& from, const pose& to) {
    return posing_margin<NT>(coordinate_scale(a) + coordinate_scale(b) + std::fabs(from.tx) +
                                              std::fabs(from.ty) + std::fabs(to.tx) + std::fabs(to.ty));
}

/// The displacement of a translation in NT: to - from on the input doubles.
template <class NT>
point<NT> displacement(const pose& from, const pose& to) {
    using tr = number_traits<NT>;
    return {tr::from_double(to.tx) - tr::from_double(from.tx), tr::from_double(to.ty) - tr::from_double(from.ty)};
}

/// The earliest event of a translation in one NT: its site and time.
template <class NT>
struct earliest_event {
    contact_site site;
    time_fraction<NT> time;
};

/// The earliest contact event of B translated from `from` to `to` (same
/// angle) against A, in NT: every candidate site's earliest time in [0, 1],
/// the least by time then by site_before. None when no vertex reaches an
/// edge (the caller has found that the regions do not meet at the start).
template <class NT>
std::optional<earliest_event<NT>> earliest_translation_event(const polygon& a, const polygon& b, const pose& from,
                                                             const pose& to, const rotation_pose& start) {
    translation_frame<NT> f(a, b, start, displacement<NT>(from, to));
    std::optional<earliest_event<NT>> best;
    windowed_sites(
        a, b, f.b.approx(), f.b.bounds(), {to.tx - from.tx, to.ty - from.ty}, translation_margin<NT>(a, b, from, to),
        [&](const contact_site& s) {
            std::optional<time_fraction<NT>> t = f.earliest(s);
            if (!t) return;
            if (best) {
                const int c = compare_times(*t, best->time);
                if (c > 0 || (c == 0 && !site_before(s, best->site))) return;
            }
            best = earliest_event<NT>{s, std::move(*t)};
        },
        [&]() -> std::optional<double> {
            if (!best) return std::nullopt;
            return time_above(best->time);
        });
    return best;
}

/// An event of the filtered search: its site, its time in `certified` when
/// every sign of it was certain, and its time in the exact field Exact once
/// asked, with two doubles around it.
template <class Exact>
struct filtered_event {
    contact_site site;
    std::optional<time_fraction<certified>> fast;        ///< the time in certified, when certain
    std::optional<time_fraction<Exact>> exact;  ///< the exact time, once asked
    double rounded = 0;                                  ///< the exact time's nearest double, with exact
    double below = 0, above = 0;                         ///< below <= exact time <= above, with exact

    /// A double above the time: from the exact time's neighbours, else from
    /// the certified time's bounds (num at most its value plus its error,
    /// den at least its value minus its error), widened by 2^-40.
    double time_above() const {
        if (exact) return above;
        const double num = fast->num.value() + fast->num.error(), den = fast->den.value() - fast->den.error();
        const double q = num / den;
        return den > 0 && std::isfinite(q) ? q * (1 + 0x1p-40) + 0x1p-1000 : std::numeric_limits<double>::infinity();
    }

    /// Sets the exact time, its nearest double and the doubles next to it.
    void set_exact(time_fraction<Exact> t) {
        const double x = nearest_double(t);
        rounded = x;
        below = std::nextafter(x, -std::numeric_limits<double>::infinity());
        above = std::nextafter(x, std::numeric_limits<double>::infinity());
        exact = std::move(t);
    }
};

/// The sign of the time t (in certified) minus the double x; throws
/// uncertain_sign when not certain.
inline int compare_time_with(const time_fraction<certified>& t, double x) {
    return compare_values<certified>(t.num, certified(x) * t.den);
}

/// The sign of c's time minus e's: in certified when both have one and the
/// bound settles it; else c's certified time against the doubles around
/// e's exact time; else exactly (`exact_time` computes a site's exact
/// time: it exists, both events having one).
template <class Exact, class ExactTime>
int order(filtered_event<Exact>& c, filtered_event<Exact>& e, ExactTime&& exact_time) {
    if (c.fast && e.fast) {
        try {
            return compare_times(*c.fast, *e.fast);
        } catch (const uncertain_sign&) {
        }
    }
    if (c.fast && e.exact) {
        try {
            if (compare_time_with(*c.fast, e.above) > 0) return 1;
            if (compare_time_with(*c.fast, e.below) < 0) return -1;
        } catch (const uncertain_sign&) {
        }
    }
    for (filtered_event<Exact>* x : {&c, &e})
        if (!x->exact) x->set_exact(*exact_time(x->site));
    return compare_times(*c.exact, *e.exact);
}

/// The earliest event as earliest_translation_event, exact, at nearly
/// double's cost: each site's time is computed and compared in
/// `certified`, and again in the exact field Exact only for the sites whose
/// signs the bound cannot settle (and, when a comparison is not certain,
/// the two compared).
template <class Exact>
std::optional<filtered_event<Exact>> earliest_translation_event_filtered(const polygon& a, const polygon& b,
                                                                         const pose& from, const pose& to,
                                                                         const rotation_pose& start) {
    translation_frame<certified> fast(a, b, start, displacement<certified>(from, to));
    std::optional<point<Exact>> exact_d;
    const auto exact_time = [&](const contact_site& s) {
        if (!exact_d) exact_d = displacement<Exact>(from, to);
        return site_time(a, b, start, *exact_d, s);
    };
    std::optional<filtered_event<Exact>> best;
    windowed_sites(
        a, b, fast.b.approx(), fast.b.bounds(), {to.tx - from.tx, to.ty - from.ty},
        translation_margin<certified>(a, b, from, to),
        [&](const contact_site& s) {
            filtered_event<Exact> c{s, std::nullopt, std::nullopt};
            try {
                c.fast = fast.earliest(s);
                if (!c.fast) return;
            } catch (const uncertain_sign&) {
                std::optional<time_fraction<Exact>> t = exact_time(s);
                if (!t) return;
                c.set_exact(std::move(*t));
            }
            if (best) {
                const int o = order(c, *best, exact_time);
                if (o > 0 || (o == 0 && !site_before(s, best->site))) return;
            }
            best = std::move(c);
        },
        [&]() -> std::optional<double> {
            if (!best) return std::nullopt;
            return best->time_above();
        });
    return best;
}

/// Throws invalid_input naming a component of the direction that is NaN or
/// infinite, or a direction of length zero.
inline void check_direction(double dx, double dy) {
    for (const auto& [name, v] : {std::pair<const char*, double>{"dx", dx}, {"dy", dy}})
        if (!std::isfinite(v))
            throw invalid_input(std::string("direction: ") + name + " is " +
                                (std::isnan(v) ? "NaN" : v > 0 ? "+infinity" : "-infinity") + ", not a finite number");
    if (dx == 0 && dy == 0) throw invalid_input("direction: (0, 0) has no direction");
}

/// A double s_max such that B, its box `bb` (in double, within e of its
/// place in NT) moved by s (dx, dy) for any s > s_max, lies beyond A's box
/// `ab` on one axis: the least over the axes that move of the s at which
/// B's box has crossed A's, with 4e of room and widened by 2^-40 relative
/// (the few roundings of the quotient are below 2^-50 relative, and the
/// difference of the box sides rounds by far less than e).
inline double exit_reach(const box& ab, const box& bb, double dx, double dy, double e) {
    double s = std::numeric_limits<double>::infinity();
    if (dx > 0) s = std::min(s, (ab.max_x - bb.min_x + 4 * e) / dx);
    if (dx < 0) s = std::min(s, (ab.min_x - bb.max_x - 4 * e) / dx);
    if (dy > 0) s = std::min(s, (ab.max_y - bb.min_y + 4 * e) / dy);
    if (dy < 0) s = std::min(s, (ab.min_y - bb.max_y - 4 * e) / dy);
    return std::max(0.0, s) * (1 + 0x1p-40) + std::numeric_limits<double>::min();
}

/// Whether A and B translated by s = (s0 + s1) / 2 times d meet, in ring
/// operations, with what showed it (placed_meet): both polygons scaled by
/// D = 2 s0.den s1.den > 0 (which changes no answer), B's vertices
/// D p + N d with N = s0.num s1.den + s1.num s0.den. `scale` bounds the
/// magnitudes of the unscaled inputs (the polygons and B's translation),
/// `reach` |dx| + |dy|.
template <class NT>
meeting meeting_between(translation_frame<NT>& f, const time_fraction<NT>& s0, const time_fraction<NT>& s1,
                        double scale, double reach) {
    using tr = number_traits<NT>;
    const NT n = s0.num * s1.den + s1.num * s0.den, half = s0.den * s1.den, d = half + half;
    const polygon &as = f.a.shape(), &bs = f.b.shape();
    std::vector<point<NT>> av(as.size()), bv(bs.size());
    for (std::size_t i = 0; i < as.size(); ++i) av[i] = {d * f.a[i].x, d * f.a[i].y};
    const point<NT> nd{n * f.d.x, n * f.d.y};
    for (std::size_t j = 0; j < bs.size(); ++j) bv[j] = {d * f.b[j].x + nd.x, d * f.b[j].y + nd.y};
    const double big = std::fabs(tr::to_double(d)) * scale + std::fabs(tr::to_double(n)) * reach;
    placed_polygon<NT> pa(as, av), pb(bs, bv);
    return placed_meet(pa, pb, posing_margin<NT>(big));
}

/// Whether an event at `s` can change what the witness `w` shows: it
/// puts one of the witness's features in contact. A vertex located in the
/// other polygon stays there until it reaches that polygon's boundary (an
/// event of that vertex); an edge pair keeps meeting or not until an end of
/// one reaches the other (an event of the pair).
inline bool touches(const meeting& w, const contact_site& s, const polygon& a, const polygon& b) {
    switch (w.how) {
    case meeting::kind::b_vertex_in_a:
        return s.moving_vertex && s.vertex == w.b_index;
    case meeting::kind::a_vertex_in_b:
        return !s.moving_vertex && s.vertex == w.a_index;
    case meeting::kind::edges:
        if (s.moving_vertex) return s.edge == w.a_index && (s.vertex == w.b_index || s.vertex == b.next(w.b_index));
        return s.edge == w.b_index && (s.vertex == w.a_index || s.vertex == a.next(w.a_index));
    default:
        return true;
    }
}

/// An event of the exit search: its time and site.
template <class NT>
struct timed_site {
    time_fraction<NT> time;
    contact_site site;
};

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
/// distance is exact before distance_of rounds it); for double the bound
/// distance/separation.hpp states, 2^-40 scale; for another floating NT its
/// filters' margin, posing_margin (four times filter_slack times scale: 1e-9
/// for long double and quad, far above their rounding; 1e-4 for float).
template <class NT>
double separation_error(double scale) {
    using tr = number_traits<NT>;
    if constexpr (tr::category != number_category::floating) return 0;
    if constexpr (std::is_same_v<NT, double>) return 0x1p-40 * scale;
    return posing_margin<NT>(scale);
}

/// The distance at one time of a turning motion, with the features that
/// realise it (separation's).
struct probe_result {
    double distance = 0;  ///< within one ulp of the separation's distance
    feature static_feature{};
    feature moving_feature{};
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
///       t <- min(1, t + (L - resolution / 2) / v, rounded down)
///
/// Until the returned t the distance stays above resolution / 2 > 0: no
/// step passes a contact. Each step advances by at least 2^-51.
template <class Coarse, class Fine>
std::optional<std::pair<double, probe_result>> advance(const polygon& b, const pose& from, const pose& to,
                                                       double tolerance, double coarse_error, Coarse&& coarse,
                                                       bool refine, double fine_error, Fine&& fine) {
    const double r = bounding_radius(b, {0, 0});
    const double turn = std::fabs(to.theta - from.theta);
    const double v = (std::hypot(to.tx - from.tx, to.ty - from.ty) + turn * r) * (1 + speed_widening);
    const double delta =
        motion_rounding * (r * (std::fabs(from.theta) + std::fabs(to.theta) + 1) + std::fabs(from.tx) +
                           std::fabs(from.ty) + std::fabs(to.tx) + std::fabs(to.ty));
    const double resolution = 4 * (delta + v * 0x1p-52) + 2 * (refine ? fine_error : coarse_error);
    const double tol = std::max(tolerance, resolution);
    bool fine_stage = false;
    double t = 0;
    for (;;) {
        const pose p = motion_pose(from, to, t);
        probe_result at = fine_stage ? fine(p) : coarse(p);
        const double lower = at.distance * (1 - distance_shrinking) - (fine_stage ? fine_error : coarse_error) - delta;
        if (lower <= tol) {
            if (refine && !fine_stage) {
                fine_stage = true;
                continue;
            }
            return std::make_pair(t, at);
        }
        if (t == 1) return std::nullopt;
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

/// The result of a turning motion from advance's answer.
template <class NT>
contact_result<NT> turning_result(const std::optional<std::pair<double, probe_result>>& found) {
    contact_result<NT> r;
    if (!found) return r;
    r.contact = true;
    r.time = number_traits<NT>::from_double(found->first);
    r.static_feature = found->second.static_feature;
    r.moving_feature = found->second.moving_feature;
    return r;
}

/// The first contact of a motion that turns, in NT: conservative
/// advancement on separation queries (both polygons prepared once, each
/// search started from the last closest pair). A floating NT steps on its
/// own query. An exact NT steps on the query in double (with its error
/// bound) and, once that would stop, on its own exact query: the stop is
/// decided on exact distances.
template <class NT>
contact_result<NT> turning_first_contact(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                         const sweep_options& options) {
    const double scale = motion_scale(a, b, from, to);
    if constexpr (number_traits<NT>::category == number_category::floating) {
        separation_query<NT> query(a, b);
        const auto probe = [&](const pose& p) { return probe_of(query, p); };
        return turning_result<NT>(
            advance(b, from, to, options.tolerance, separation_error<NT>(scale), probe, false, 0, probe));
    } else {
        separation_query<double> coarse(a, b);
        std::optional<separation_query<NT>> fine;
        return turning_result<NT>(advance(
            b, from, to, options.tolerance, separation_error<double>(scale),
            [&](const pose& p) { return probe_of(coarse, p); }, true, 0, [&](const pose& p) {
                if (!fine) fine.emplace(a, b);
                return probe_of(*fine, p);
            }));
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
    return turning_result<double>(advance(
        b, from, to, options.tolerance, separation_error<double>(motion_scale(a, b, from, to)),
        [&](const pose& p) { return probe_of(coarse, p); }, true, 0, [&](const pose& p) {
            const separation_result<Exact> s = separation<Exact>(a, b, p);
            return probe_result{distance_of<Exact>(s.squared_distance), s.static_feature, s.moving_feature};
        }));
}

}  // namespace sweep_detail

/// The first contact of B moving from pose `from` to pose `to` against the
/// static A: the earliest time t in [0, 1] at which the closed regions
/// meet, with the features that touch then. B's motion: translation linear
/// in time, angle linear in time.
///
/// A translation (from.theta == to.theta) is answered by its events, exactly
/// when NT is exact (docs/sweep.md):
///
///   pose B at the start (exact in NT)
///   regions meet at the start (the one-shot query):  time 0, features met
///   d <- to - from (in NT); for every pair of A's edge and B's edge whose
///   boxes overlap, B's swept by d (sort and sweep along x):
///       B's vertex against A's edge, moving by d;
///       A's vertex against B's edge, moving by -d:
///           the earliest time in [0, 1] it lies on the closed segment
///           (contact_times: a crossing, or the passage of an endpoint
///           when it moves along the segment's line)
///   the earliest of these times (ties: site_before):  the first contact
///
/// Time O((n + m) log(n + m) + k) for k pairs of overlapping swept boxes.
/// A motion that turns is answered by conservative advancement with a
/// tolerance (docs/sweep.md, "Motions that turn"). NT needs division for
/// the time of the result (every number type of the library but certified
/// and interval: certified_first_contact is the filtered route). Throws
/// invalid_input for an empty polygon, a NaN or infinite component of
/// either pose, or a tolerance that is negative, NaN or infinite.
template <class NT>
contact_result<NT> first_contact(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                 const sweep_options& options = {}) {
    using namespace sweep_detail;
    const motion m = motion::accepted<NT>(a, b, from, to, options);
    if (from.theta != to.theta) return turning_first_contact<NT>(a, b, from, to, options);
    contact_result<NT> r;
    if (const auto met = meeting_at_start<NT>(a, b, from, m.start)) {
        r.contact = true;
        r.time = NT(0);
        std::tie(r.static_feature, r.moving_feature) = *met;
        return r;
    }
    if (from.tx == to.tx && from.ty == to.ty) return r;  // B stays where it was
    const auto best = earliest_translation_event<NT>(a, b, from, to, m.start);
    if (!best) return r;
    r.contact = true;
    r.time = best->time.num / best->time.den;
    std::tie(r.static_feature, r.moving_feature) = site_features(a, b, best->site);
    return r;
}

/// The first contact in the exact field Exact (first_contact<Exact>) at
/// nearly double's cost, for a translation: the exact earliest time rounded
/// to the nearest double, and the exact features. The meeting at the
/// start is decided in `certified` with the one-shot query's exact
/// fallback; each event is computed and compared in `certified`, and again
/// in Exact only when its signs are not certain; the earliest
/// time is rounded from its exact value (one site evaluated exactly). For
/// a motion that turns: the answer of first_contact<Exact> (the same
/// steps, the stop decided on separation<Exact>'s exact distance;
/// docs/sweep.md). Throws as first_contact. certified_first_contact
/// (exact/certified_first_contact.hpp) is this query in exact rationals.
template <class Exact>
contact_result<double> filtered_first_contact(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                              const sweep_options& options = {}) {
    using namespace sweep_detail;
    const motion m = motion::accepted<double>(a, b, from, to, options);
    if (from.theta != to.theta) return filtered_turning_first_contact<Exact>(a, b, from, to, options);
    contact_result<double> r;
    const auto met = fallback<>::run([&] { return meeting_at_start<certified>(a, b, from, m.start); },
                                     [&] { return meeting_at_start<Exact>(a, b, from, m.start); });
    if (met) {
        r.contact = true;
        std::tie(r.static_feature, r.moving_feature) = *met;
        return r;
    }
    if (from.tx == to.tx && from.ty == to.ty) return r;  // B stays where it was
    auto best = earliest_translation_event_filtered<Exact>(a, b, from, to, m.start);
    if (!best) return r;
    r.contact = true;
    std::tie(r.static_feature, r.moving_feature) = site_features(a, b, best->site);
    // Rounding to the nearest double asks for the time's sign against the
    // midpoints between doubles, finer than certified's bound: exactly.
    if (!best->exact) best->set_exact(*site_time(a, b, m.start, displacement<Exact>(from, to), best->site));
    r.time = best->rounded;
    return r;
}

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
///   windows (0, s_max / 64], then doubled, from the sites whose boxes
///   overlap, B's swept over the window; sorted: s_1 < s_2 < ... < s_K
///   last <- 0
///   loop:
///       if an event at `last` touches w's features (a located vertex
///       reaching an edge, an end of w's edge pair reaching the other):
///           w <- the meeting at (last + next) / 2 (the one-shot query's
///           steps on both polygons scaled to keep ring operations)
///           apart there:                              last
///       no next event:                                last (then apart)
///       last <- the next event
///
/// Between two consecutive events no vertex reaches or leaves an edge, so
/// whether the regions meet does not change, and neither does what a
/// witness shows unless an event at its start touches it (docs/sweep.md,
/// "Exit distance"). Time O((n + m) log(n + m) + k log k) for k events up to
/// the exit, plus O((n + m) log(n + m)) for each event that touches the
/// witness. Throws invalid_input for an empty polygon, a NaN or infinite
/// component of q or of the direction, a direction (0, 0), or one whose
/// components differ by more than double's range (2^1022 times).
template <class NT>
NT exit_distance(const polygon& a, const polygon& b, const pose& q, double dx, double dy) {
    using namespace sweep_detail;
    using tr = number_traits<NT>;
    accepted_polygon<NT>(a, "static");
    accepted_polygon<NT>(b, "moving");
    const rotation_pose t(q);
    check_direction(dx, dy);
    // The direction scaled by a power of two 2^shift (exactly) to a largest
    // component in [1, 2): the windows of s, kept in double, then neither
    // overflow nor underflow; s for (dx, dy) is 2^shift times s for the
    // scaled one.
    const int shift = -std::ilogb(std::max(std::fabs(dx), std::fabs(dy)));
    const double ux = std::ldexp(dx, shift), uy = std::ldexp(dy, shift);
    if (std::ldexp(ux, -shift) != dx || std::ldexp(uy, -shift) != dy)
        throw invalid_input("direction: the components' magnitudes are too far apart to scale exactly");
    const NT unit_scale =
        tr::from_double(std::ldexp(1.0, shift / 2)) * tr::from_double(std::ldexp(1.0, shift - shift / 2));
    dx = ux;
    dy = uy;
    translation_frame<NT> f(a, b, t, {tr::from_double(dx), tr::from_double(dy)});
    const double scale = coordinate_scale(a) + coordinate_scale(b) + std::fabs(q.tx) + std::fabs(q.ty);
    const double reach = std::fabs(dx) + std::fabs(dy);
    const double e0 = posing_margin<NT>(scale);
    meeting witness = placed_meet(f.a, f.b, e0);
    if (!witness) return NT(0);

    const double s_max = exit_reach(a.bounds(), f.b.bounds(), dx, dy, e0);
    const double e = posing_margin<NT>(scale + s_max * reach);
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
        candidate_sites(a, b, f.b.approx(), f.b.bounds(), {std::max(w_low, 0.0) * dx, std::max(w_low, 0.0) * dy},
                        {w * dx, w * dy}, e, [&](const contact_site& site) {
            if constexpr (exact) {
                try {
                    time_fraction<certified> none[2];
                    if (fast->times(site, false, none) == 0) return;
                } catch (const uncertain_sign&) {
                }
            }
            time_fraction<NT> out[2];
            const int k = f.times(site, false, out);
            for (int i = 0; i < k; ++i)
                if ((w_low < 0 || beyond(out[i], w_low)) && !beyond(out[i], w)) events.push_back({std::move(out[i]), site});
        });
        std::sort(events.begin(), events.end(), [](const timed_site<NT>& l, const timed_site<NT>& r) {
            return compare_times(l.time, r.time) < 0;
        });
    };
    double w_low = -1, w = std::min(s_max, s_max * first_window);
    load(w_low, w);
    std::size_t next = 0;
    time_fraction<NT> last{NT(0), NT(1)};
    for (;;) {
        // The events at `last` (some may come at 0): do they touch the witness?
        bool stale = false;
        for (; next < events.size() && compare_times(events[next].time, last) <= 0; ++next)
            if (touches(witness, events[next].site, a, b)) stale = true;
        while (next == events.size() && w < s_max) {
            w_low = w;
            w = std::min(s_max, 2 * w);
            load(w_low, w);
            next = 0;
        }
        if (next == events.size()) return last.num / last.den * unit_scale;  // after the last event, apart
        const time_fraction<NT>& following = events[next].time;
        if (stale) {
            witness = meeting_between(f, last, following, scale, reach);
            if (!witness) return last.num / last.den * unit_scale;
        }
        last = following;
    }
}

}  // namespace influence2d
