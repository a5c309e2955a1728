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
#include <utility>
#include <vector>

#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/detect/certified_detector.hpp"
#include "influence2d/detect/feature.hpp"
#include "influence2d/detect/one_shot.hpp"
#include "influence2d/detect/posed_meet.hpp"
#include "influence2d/detect/scene.hpp"
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

namespace sweep_detail {

using one_shot_detail::meeting;
using one_shot_detail::placed;

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

/// The input number of the polygon's stored vertex i: a ring stored reversed
/// numbers its vertices backwards (its stored vertex i is the end of input
/// edge source_edge(i)).
inline std::size_t input_vertex(const polygon& shape, std::size_t i) {
    std::size_t r = 0;
    while (shape.ring_end(r) <= i) ++r;
    const std::size_t begin = shape.ring_begin(r), n = shape.ring_end(r) - begin;
    const bool reversed = shape.source_edge(begin) != begin;
    return reversed ? begin + (shape.source_edge(i) - begin + 1) % n : i;
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
std::pair<feature, feature> meeting_features(placed<NT>& a, placed<NT>& b, const meeting& m) {
    const polygon &as = a.shape(), &bs = b.shape();
    const auto edge_holding = [](placed<NT>& p, const point<NT>& v) {
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
    placed<NT> pa(a), pb(b, start);
    const meeting met = one_shot_detail::placed_meet(
        pa, pb,
        one_shot_detail::posing_margin<NT>(coordinate_scale(a) + coordinate_scale(b) + std::fabs(from.tx) +
                                           std::fabs(from.ty)));
    if (!met) return std::nullopt;
    return meeting_features(pa, pb, met);
}

/// Calls visit(site) for both sites of every pair of A's edge i and B's
/// edge j whose boxes overlap, B's edge box swept by `sweep` (double; B's
/// vertices at the start in `b_start`), every box grown by e: B's vertex j
/// against A's edge i, and A's vertex i against B's edge j. Every vertex of
/// B that reaches an edge of A during the sweep is the start of an edge of B
/// whose swept box meets that edge's box, and likewise for A's vertices: no
/// event is left out. Sort and sweep along x (one_shot_detail).
template <class Visit>
void candidate_sites(const polygon& a, const polygon& b, const std::vector<point<double>>& b_start,
                     const box& b_start_box, point<double> sweep, double e, Visit&& visit) {
    using namespace one_shot_detail;
    box swept = b_start_box;
    swept.add({b_start_box.min_x + sweep.x, b_start_box.min_y + sweep.y});
    swept.add({b_start_box.max_x + sweep.x, b_start_box.max_y + sweep.y});
    std::vector<edge_box> a_edges, b_edges;
    edges_meeting(a, a.vertices(), swept.inflated(e), e, a_edges);
    edges_meeting(b, b_start, a.bounds().inflated(e), e, b_edges, sweep);
    overlapping_pairs(a_edges, b_edges, [&](std::uint32_t i, std::uint32_t j) {
        visit(contact_site{true, j, i});
        visit(contact_site{false, i, j});
        return false;
    });
}

/// A translation in NT: A where it stands, B posed at the start, the
/// displacement d (and -d, A's motion relative to B).
template <class NT>
struct translation_frame {
    placed<NT> a, b;
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
        time_fraction<NT> t[2];
        const int k = times(s, true, t);
        if (k == 0) return std::nullopt;
        if (k == 2 && compare_times(t[1], t[0]) < 0) return t[1];
        return t[0];
    }
};

/// The validated parts of a motion: its start and end as rotation poses
/// (invalid_input for a NaN or infinite component of either).
struct motion {
    rotation_pose start, end;
    motion(const pose& from, const pose& to) : start(from), end(checked_end(to)) {}

    /// The motion of B from `from` to `to` against A, both polygons checked
    /// for NT (accepted_polygon).
    template <class NT>
    static motion accepted(const polygon& a, const polygon& b, const pose& from, const pose& to) {
        accepted_polygon<NT>(a, "static");
        accepted_polygon<NT>(b, "moving");
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
    return one_shot_detail::posing_margin<NT>(coordinate_scale(a) + coordinate_scale(b) + std::fabs(from.tx) +
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
    candidate_sites(a, b, f.b.approx(), f.b.bounds(), {to.tx - from.tx, to.ty - from.ty},
                    translation_margin<NT>(a, b, from, to), [&](const contact_site& s) {
                        std::optional<time_fraction<NT>> t = f.earliest(s);
                        if (!t) return;
                        if (best) {
                            const int c = compare_times(*t, best->time);
                            if (c > 0 || (c == 0 && !site_before(s, best->site))) return;
                        }
                        best = earliest_event<NT>{s, std::move(*t)};
                    });
    return best;
}

/// An event of the filtered search: its site, its time in `certified` when
/// every sign of it was certain, and its exact time once asked, with two
/// doubles around it.
struct filtered_event {
    contact_site site;
    std::optional<time_fraction<certified>> fast;        ///< the time in certified, when certain
    std::optional<time_fraction<exact_rational>> exact;  ///< the exact time, once asked
    double rounded = 0;                                  ///< the exact time's nearest double, with exact
    double below = 0, above = 0;                         ///< below <= exact time <= above, with exact

    /// Sets the exact time, its nearest double and the doubles next to it.
    void set_exact(time_fraction<exact_rational> t) {
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
template <class ExactTime>
int order(filtered_event& c, filtered_event& e, ExactTime&& exact_time) {
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
    for (filtered_event* x : {&c, &e})
        if (!x->exact) x->set_exact(*exact_time(x->site));
    return compare_times(*c.exact, *e.exact);
}

/// The earliest event as earliest_translation_event, exact, at nearly
/// double's cost: each site's time is computed and compared in
/// `certified`, and again in exact rationals only for the sites whose
/// signs the bound cannot settle (and, when a comparison is not certain,
/// the two compared).
inline std::optional<filtered_event> earliest_translation_event_filtered(const polygon& a, const polygon& b,
                                                                        const pose& from, const pose& to,
                                                                        const rotation_pose& start) {
    translation_frame<certified> fast(a, b, start, displacement<certified>(from, to));
    std::optional<translation_frame<exact_rational>> exact_frame;
    const auto exact_time = [&](const contact_site& s) {
        if (!exact_frame) exact_frame.emplace(a, b, start, displacement<exact_rational>(from, to));
        return exact_frame->earliest(s);
    };
    std::optional<filtered_event> best;
    candidate_sites(a, b, fast.b.approx(), fast.b.bounds(), {to.tx - from.tx, to.ty - from.ty},
                    translation_margin<certified>(a, b, from, to), [&](const contact_site& s) {
                        filtered_event c{s, std::nullopt, std::nullopt};
                        try {
                            c.fast = fast.earliest(s);
                            if (!c.fast) return;
                        } catch (const uncertain_sign&) {
                            std::optional<time_fraction<exact_rational>> t = exact_time(s);
                            if (!t) return;
                            c.set_exact(std::move(*t));
                        }
                        if (best) {
                            const int o = order(c, *best, exact_time);
                            if (o > 0 || (o == 0 && !site_before(s, best->site))) return;
                        }
                        best = std::move(c);
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
/// operations: both polygons scaled by D = 2 s0.den s1.den > 0 (which
/// changes no answer), B's vertices D p + N d with N = s0.num s1.den +
/// s1.num s0.den. `scale` bounds the magnitudes of the unscaled inputs (the
/// polygons and B's translation), `reach` |dx| + |dy|.
template <class NT>
bool meet_between(translation_frame<NT>& f, const time_fraction<NT>& s0, const time_fraction<NT>& s1, double scale,
                  double reach) {
    using tr = number_traits<NT>;
    const NT n = s0.num * s1.den + s1.num * s0.den, half = s0.den * s1.den, d = half + half;
    const polygon &as = f.a.shape(), &bs = f.b.shape();
    std::vector<point<NT>> av(as.size()), bv(bs.size());
    for (std::size_t i = 0; i < as.size(); ++i) av[i] = {d * f.a[i].x, d * f.a[i].y};
    const point<NT> nd{n * f.d.x, n * f.d.y};
    for (std::size_t j = 0; j < bs.size(); ++j) bv[j] = {d * f.b[j].x + nd.x, d * f.b[j].y + nd.y};
    const double big = std::fabs(tr::to_double(d)) * scale + std::fabs(tr::to_double(n)) * reach;
    return regions_meet(as, av, bs, bv, big);
}

/// The first contact of a motion that turns (docs/sweep.md, "Motions that
/// turn"): not answered yet; throws invalid_input.
template <class NT>
contact_result<NT> turning_first_contact(const polygon&, const polygon&, const pose&, const pose&,
                                         const sweep_options&) {
    throw invalid_input("first_contact: motions that turn (from.theta != to.theta) are not answered yet");
}

/// As turning_first_contact, certified.
inline contact_result<double> certified_turning_first_contact(const polygon& a, const polygon& b, const pose& from,
                                                              const pose& to, const sweep_options& options) {
    return turning_first_contact<double>(a, b, from, to, options);
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
/// invalid_input for an empty polygon or a NaN or infinite component of
/// either pose.
template <class NT>
contact_result<NT> first_contact(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                 const sweep_options& options = {}) {
    using namespace sweep_detail;
    const motion m = motion::accepted<NT>(a, b, from, to);
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

/// The exact first contact at nearly double's cost, for a translation: the
/// exact earliest time rounded to the nearest double, and the exact
/// features (those of first_contact<exact_rational>). The meeting at the
/// start is decided in `certified` with the one-shot query's exact
/// fallback; each event is computed and compared in `certified`, and again
/// in exact rationals only when its signs are not certain; the rounding of
/// the earliest time likewise.
inline contact_result<double> certified_first_contact(const polygon& a, const polygon& b, const pose& from,
                                                      const pose& to, const sweep_options& options = {}) {
    using namespace sweep_detail;
    const motion m = motion::accepted<double>(a, b, from, to);
    if (from.theta != to.theta) return certified_turning_first_contact(a, b, from, to, options);
    contact_result<double> r;
    const auto met = detail::fallback<>::run([&] { return meeting_at_start<certified>(a, b, from, m.start); },
                                             [&] { return meeting_at_start<exact_rational>(a, b, from, m.start); });
    if (met) {
        r.contact = true;
        std::tie(r.static_feature, r.moving_feature) = *met;
        return r;
    }
    if (from.tx == to.tx && from.ty == to.ty) return r;  // B stays where it was
    auto best = earliest_translation_event_filtered(a, b, from, to, m.start);
    if (!best) return r;
    r.contact = true;
    std::tie(r.static_feature, r.moving_feature) = site_features(a, b, best->site);
    r.time = detail::fallback<>::run(
        [&]() -> double {
            if (best->exact) return best->rounded;
            return nearest_double(*best->fast);
        },
        [&] {
            best->set_exact(*translation_frame<exact_rational>(a, b, m.start, displacement<exact_rational>(from, to))
                                 .earliest(best->site));
            return best->rounded;
        });
    return r;
}

/// The directional penetration depth: with B posed by q and then translated
/// by s (dx, dy), the end of the interval of s >= 0, starting at 0, during
/// which the closed regions of A and B meet; 0 when they do not meet at q.
/// In units of (dx, dy): a distance when it is a unit vector. At the
/// returned s the regions touch, and for s a little larger they do not.
/// Exact in an exact NT (NT needs division, as for first_contact).
///
///   regions do not meet at q (the one-shot query):      0
///   s_max <- beyond it B's box has left A's box along d (double, widened)
///   the events of every site whose boxes overlap, B's swept by s_max d:
///       every time s >= 0 a vertex starts or stops lying on an edge
///       (contact_times, both ends of a sliding contact)
///   sort and merge them: 0 < s_1 < s_2 < ... < s_K
///   for k = 0, 1, ..., K - 1 (s_0 = 0):
///       if the regions do not meet at (s_k + s_k+1) / 2:  s_k
///   s_K
///
/// Between two consecutive events no vertex reaches or leaves an edge, so
/// whether the regions meet does not change (docs/sweep.md, "Exit
/// distance"); after the last they do not meet. Time O((n + m) log(n + m)
/// + k log k + j (n + m) log(n + m)) for k events and j intervals tested.
/// Throws invalid_input for an empty polygon, a NaN or infinite component
/// of q or of the direction, or a direction (0, 0).
template <class NT>
NT exit_distance(const polygon& a, const polygon& b, const pose& q, double dx, double dy) {
    using namespace sweep_detail;
    using tr = number_traits<NT>;
    accepted_polygon<NT>(a, "static");
    accepted_polygon<NT>(b, "moving");
    const rotation_pose t(q);
    check_direction(dx, dy);
    translation_frame<NT> f(a, b, t, {tr::from_double(dx), tr::from_double(dy)});
    const double scale = coordinate_scale(a) + coordinate_scale(b) + std::fabs(q.tx) + std::fabs(q.ty);
    const double e0 = one_shot_detail::posing_margin<NT>(scale);
    if (!one_shot_detail::placed_meet(f.a, f.b, e0)) return NT(0);

    const double s_max = exit_reach(a.bounds(), f.b.bounds(), dx, dy, e0);
    const point<double> sweep{s_max * dx, s_max * dy};
    std::vector<time_fraction<NT>> events;
    candidate_sites(a, b, f.b.approx(), f.b.bounds(), sweep,
                    one_shot_detail::posing_margin<NT>(scale + std::fabs(sweep.x) + std::fabs(sweep.y)),
                    [&](const contact_site& s) {
                        time_fraction<NT> out[2];
                        const int k = f.times(s, false, out);
                        for (int i = 0; i < k; ++i) events.push_back(std::move(out[i]));
                    });
    std::sort(events.begin(), events.end(),
              [](const time_fraction<NT>& l, const time_fraction<NT>& r) { return compare_times(l, r) < 0; });

    time_fraction<NT> last{NT(0), NT(1)};
    for (const time_fraction<NT>& next : events) {
        if (compare_times(next, last) <= 0) continue;  // at 0, or the time just passed
        if (!meet_between(f, last, next, scale, std::fabs(dx) + std::fabs(dy))) break;
        last = next;
    }
    return last.num / last.den;
}

}  // namespace influence2d
