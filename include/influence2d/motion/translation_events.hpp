// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The contact events of a translating polygon: which vertex reaches which
/// edge and when, found over the pairs of edges whose swept boxes overlap,
/// exactly in NT or filtered through `certified` (motion/first_contact.hpp,
/// motion/exit_distance.hpp).

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

#include "influence2d/core/feature.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/shortest_decimal.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/double_word.hpp"
#include "influence2d/number/fallback.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/predicates/exact_doubles.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/query/intersects.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/edge_boxes.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

#include "influence2d/motion/motion.hpp"

namespace influence2d {

/// The steps the motion queries share (motion/first_contact.hpp,
/// motion/exit_distance.hpp): contact sites and their times, the windows
/// of a translation, conservative advancement. Not an interface of their
/// own: their contracts are those of the queries built on them.
namespace sweep {

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

/// Whether two sites are the same vertex against the same edge.
inline bool same_site(const contact_site& l, const contact_site& r) {
    return l.moving_vertex == r.moving_vertex && l.vertex == r.vertex && l.edge == r.edge;
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

/// The features of the meeting of A placed `pa` and of B placed `pb` at the
/// motion's start `from`, decided in NT; none when they do not meet there
/// (the one-shot query).
template <class NT>
std::optional<std::pair<feature, feature>> meeting_at_start(placed_polygon<NT>& pa, placed_polygon<NT>& pb,
                                                            const pose& from) {
    const meeting met = placed_meet(pa, pb,
                                    placing_margin<NT>(coordinate_scale(pa.shape()) + coordinate_scale(pb.shape()) +
                                                       std::fabs(from.tx) + std::fabs(from.ty)));
    if (!met) return std::nullopt;
    return meeting_features(pa, pb, met);
}

/// The features of the meeting of A and of B posed at the motion's start,
/// decided in NT; none when they do not meet there (the one-shot query).
template <class NT>
std::optional<std::pair<feature, feature>> meeting_at_start(const polygon& a, const polygon& b, const pose& from,
                                                            const rotation_pose& start) {
    placed_polygon<NT> pa(a), pb(b, start);
    return meeting_at_start(pa, pb, from);
}

/// Calls visit(site) for both sites of every pair of A's edge i and B's
/// edge j whose boxes overlap, B's edge box swept from its place at the
/// start (vertices `b_start` in double) shifted by `from` to that place
/// shifted by `to`, every box grown by e: B's vertex j against A's edge i,
/// and A's vertex i against B's edge j. Every vertex of B that reaches an
/// edge of A during that part of the motion is the start of an edge of B
/// whose swept box meets that edge's box, and likewise for A's vertices: no
/// event of that part is left out. Sort and sweep along x
/// (scene/edge_boxes.hpp).
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

/// The relative widening of a time or a reach along a motion computed in
/// double as one quotient (box_entry, time_above, exit_reach): its numerator
/// and denominator are within 2^-50 relative of the values meant (a
/// difference of box sides with room for it, a double near an exact value),
/// and the quotient rounds by 2^-53 more, below 2^-49 in all; 2^-40 leaves
/// a factor of 500.
inline constexpr double quotient_widening = 0x1p-40;

/// The absolute widening of a time's upper bound (time_above): a quotient
/// that underflows rounds by up to 2^-1075 absolutely, which no relative
/// widening covers; 2^-1000 does, and adds nothing to a time of 2^-946 or
/// more.
inline constexpr double quotient_floor = 0x1p-1000;

/// A lower bound, in double, of the first t >= 0 at which B's box `bb`
/// (within e of its place in NT) moved by t `sweep` meets A's box `ab`:
/// the latest of the axes' entry times, with 4e of room and shrunk by
/// quotient_widening relative; infinity when an axis that does not move
/// keeps the boxes apart.
inline double box_entry(const box& ab, const box& bb, point<double> sweep, double e) {
    double t = 0;
    const auto axis = [&](double a_min, double a_max, double b_min, double b_max, double d) {
        if (b_max + 4 * e >= a_min && b_min - 4 * e <= a_max) return;  // overlapping already
        if (d == 0)
            t = std::numeric_limits<double>::infinity();
        else if (b_max < a_min)
            t = std::max(t, d > 0 ? (a_min - b_max - 4 * e) / d : std::numeric_limits<double>::infinity());
        else
            t = std::max(t, d < 0 ? (a_max - b_min + 4 * e) / d : std::numeric_limits<double>::infinity());
    };
    axis(ab.min_x, ab.max_x, bb.min_x, bb.max_x, sweep.x);
    axis(ab.min_y, ab.max_y, bb.min_y, bb.max_y, sweep.y);
    return t * (1 - quotient_widening);
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
/// their nearest doubles (within 2^-50 relative) widened by
/// quotient_widening and quotient_floor.
template <class NT>
double time_above(const time_fraction<NT>& t) {
    using tr = number_traits<NT>;
    const double q = tr::to_double(t.num) / tr::to_double(t.den);
    return std::isfinite(q) ? q * (1 + quotient_widening) + quotient_floor : std::numeric_limits<double>::infinity();
}

/// A contact at which a site's vertex passes exactly through a vertex of
/// the other polygon (its line of motion holds an end of the edge: the one
/// time when the edge crosses that line there, either time when the edge
/// lies on it): A's vertex and B's, stored numbering. Its time is that at
/// which B's vertex, translated, sits on A's.
struct vertex_passage {
    std::uint32_t a_vertex = 0;  ///< A's vertex
    std::uint32_t b_vertex = 0;  ///< B's vertex
};

/// A translation as given in double, for B not turned: B posed by the
/// translation t, displaced by to - from.
struct given_translation {
    point<double> t;     ///< B's translation at the start
    point<double> from;  ///< the displacement's start: it is to - from
    point<double> to;    ///< the displacement's end
    /// B's translation at the motion's end, t + (to - from), when a search
    /// bounded by the end asks for it: the first contact's `to` (its t is
    /// from); none for the exit search, which runs past any end.
    std::optional<point<double>> end;
};

/// A translation in NT: A where it stands, B posed at the start, the
/// displacement d (and -d, A's motion relative to B).
template <class NT>
struct translation_frame {
    placed_polygon<NT> a;  ///< A where it stands
    placed_polygon<NT> b;  ///< B posed at the start
    point<NT> d;           ///< B's displacement over the motion
    point<NT> minus_d;     ///< A's displacement relative to B
    /// For NT = certified and B not turned, the translation as given: the
    /// sides that the bound leaves in doubt are then decided exactly on its
    /// doubles (exact_translated_side), and a side of exactly 0 names a
    /// vertex_passage (times).
    std::optional<given_translation> given;

    /// A and B placed for the translation of B by dd from `start`.
    translation_frame(const polygon& as, const polygon& bs, const rotation_pose& start, point<NT> dd)
        : a(as), b(bs, start), d(dd), minus_d{-dd.x, -dd.y} {}

    /// The site's contact times in range (t in [0, 1] when bounded, t >= 0
    /// otherwise): at most two (contact_times). With `given`, passages[k]
    /// (when asked: an array of two) names the vertices out[k] passes
    /// through exactly, or none.
    int times(const contact_site& s, bool bounded, time_fraction<NT> out[2],
              std::optional<vertex_passage>* passages = nullptr) {
        const polygon &as = a.shape(), &bs = b.shape();
        if (passages != nullptr) passages[0] = passages[1] = std::nullopt;
        if constexpr (std::is_same_v<NT, certified>) {
            if (given) return times_given(s, bounded, out, passages);
        }
        if (s.moving_vertex) return contact_times(b[s.vertex], d, a[s.edge], a[as.next(s.edge)], bounded, out);
        return contact_times(a[s.vertex], minus_d, b[s.edge], b[bs.next(s.edge)], bounded, out);
    }

    /// The site's earliest contact time in [0, 1], if any. With `given`,
    /// `*passage` (when asked) names the vertices it passes through exactly,
    /// or none.
    std::optional<time_fraction<NT>> earliest(const contact_site& s, std::optional<vertex_passage>* passage = nullptr) {
        if (passage != nullptr) passage->reset();
        if constexpr (std::is_same_v<NT, certified>) {
            if (given) {
                time_fraction<NT> t[2];
                std::optional<vertex_passage> passages[2];
                const int k = times_given(s, true, t, passages);
                if (k == 0) return std::nullopt;
                const int first = k == 2 && compare_times(t[1], t[0]) < 0 ? 1 : 0;
                if (passage != nullptr) *passage = passages[first];
                return std::move(t[first]);
            }
        }
        if (s.moving_vertex) return earliest_contact_time(b[s.vertex], d, a[s.edge], a[a.shape().next(s.edge)]);
        return earliest_contact_time(a[s.vertex], minus_d, b[s.edge], b[b.shape().next(s.edge)]);
    }

private:
    /// times for `given`: each side's sign, and each time's numerator's,
    /// in certified when its bound settles it, else exactly on the doubles
    /// as given (a vertex of A against B's moving line and a vertex of B's
    /// edge against A's vertex's line relative to B have the one sign
    /// exact_translated_side takes; a passing time's numerator is a dot
    /// product, exact_offsets_along).
    int times_given(const contact_site& s, bool bounded, time_fraction<NT> out[2],
                    std::optional<vertex_passage>* passages) {
        const polygon &as = a.shape(), &bs = b.shape();
        const std::uint32_t e1 = static_cast<std::uint32_t>(s.moving_vertex ? as.next(s.edge) : bs.next(s.edge));
        const point<NT> p = s.moving_vertex ? b[s.vertex] : a[s.vertex];
        const point<NT>& dd = s.moving_vertex ? d : minus_d;
        const point<NT> q0 = s.moving_vertex ? a[s.edge] : b[s.edge], q1 = s.moving_vertex ? a[e1] : b[e1];
        // The pair (A's vertex, B's vertex) of the site's vertex with the
        // edge's end `end`.
        const auto pair_with = [&](std::uint32_t end) {
            return s.moving_vertex ? vertex_passage{end, s.vertex} : vertex_passage{s.vertex, end};
        };
        // (A side found 0 exactly is then known exactly.)
        const auto side = [&](NT& x, std::uint32_t end) {
            int sign = 0;
            if (x.try_sign(sign)) return sign;
            const vertex_passage v = pair_with(end);
            sign =
                exact_translated_side(given->from, given->to, as.vertex(v.a_vertex), bs.vertex(v.b_vertex), given->t);
            if (sign == 0) x = NT(0);
            return sign;
        };
        segment_sides<NT> sides{cross_from(dd, p, q0), cross_from(dd, p, q1), 0, 0};
        sides.sa = side(sides.alpha, s.edge);
        sides.sb = side(sides.beta, e1);
        // A time's numerator on the doubles as given (contact_times_on_sides'
        // formulas): the edge's ends u0, u1 and the vertex w as given, B's
        // among them translated by t, or at the motion's end by given->end.
        const point<double> u0 = (s.moving_vertex ? as : bs).vertex(s.edge),
                            u1 = (s.moving_vertex ? as : bs).vertex(e1),
                            w = (s.moving_vertex ? bs : as).vertex(s.vertex), origin{0, 0};
        const auto numerator_sign = [&](int formula, bool at_end) {
            const point<double>& t = at_end ? given->end.value() : given->t;
            if (formula < 0)  // (u1 - u0) x (u0 - p)
                return s.moving_vertex ? exact_translated_side(u0, u1, u0, w, t)
                                       : -exact_translated_side(u0, u1, w, u0, t);
            const point<double>& u = formula == 0 ? u0 : u1;  // dd . (u - p)
            return s.moving_vertex ? exact_offsets_along(given->from, given->to, u, w, t, origin)
                                   : exact_offsets_along(given->from, given->to, w, u, t, origin);
        };
        int ends[2] = {-1, -1};
        const int k = contact_times_on_sides(sides, p, dd, q0, q1, bounded, out, ends, numerator_sign);
        if (passages != nullptr)
            for (int i = 0; i < k; ++i)
                if (ends[i] >= 0) passages[i] = pair_with(ends[i] == 0 ? s.edge : e1);
        return k;
    }
};

/// A site in NT, posing only its three vertices (B's by `start`; `d` the
/// displacement in NT): the moving vertex p, its displacement (d for B's
/// vertex, -d for A's) and the ends of the edge. The filtered searches'
/// evaluation of one site, without the whole frame.
template <class NT>
struct posed_site {
    point<NT> p;   ///< the moving vertex at the start
    point<NT> d;   ///< its displacement over the motion
    point<NT> e0;  ///< the edge's start
    point<NT> e1;  ///< the edge's end

    /// The site s of A and B, B posed by `start` and displaced by dd.
    posed_site(const polygon& a, const polygon& b, const rotation_pose& start, const point<NT>& dd,
               const contact_site& s) {
        const auto in_a = [&](std::size_t i) { return to_point<NT>(a.vertex(i)); };
        const auto in_b = [&](std::size_t j) { return start.apply<NT>(b.vertex(j)); };
        if (s.moving_vertex) {
            p = in_b(s.vertex), d = dd, e0 = in_a(s.edge), e1 = in_a(a.next(s.edge));
        } else {
            p = in_a(s.vertex), d = {-dd.x, -dd.y}, e0 = in_b(s.edge), e1 = in_b(b.next(s.edge));
        }
    }
};

/// The contact times of one site in NT (contact_times: t in [0, 1] when
/// bounded, t >= 0 otherwise; at most two), its vertices posed alone
/// (posed_site).
template <class NT>
int site_times(const polygon& a, const polygon& b, const rotation_pose& start, const point<NT>& d,
               const contact_site& s, bool bounded, time_fraction<NT> out[2]) {
    const posed_site<NT> q(a, b, start, d, s);
    return contact_times(q.p, q.d, q.e0, q.e1, bounded, out);
}

/// The earliest contact time of one site in [0, 1] in NT, its vertices
/// posed alone (posed_site).
template <class NT>
std::optional<time_fraction<NT>> site_time(const polygon& a, const polygon& b, const rotation_pose& start,
                                           const point<NT>& d, const contact_site& s) {
    const posed_site<NT> q(a, b, start, d, s);
    return earliest_contact_time(q.p, q.d, q.e0, q.e1);
}

/// The nearest double (ties to even) of an exact time that `time(tag)`
/// computes in the number type of `tag` (a site's time from site_times,
/// say): in double words when their bounds settle every sign on the way
/// and the rounding (nearest_double), else in the exact field Exact. A
/// double word's signs are the exact ones or raise uncertain_sign, so the
/// computation takes the exact one's branches and names the same time.
template <class Exact, class Time>
double nearest_site_time(Time&& time) {
    return noted_fallback::run([&] { return nearest_double(time(double_word{})); },
                               [&] { return nearest_double(time(Exact{})); });
}

/// The validated parts of a motion: its start and end as rotation poses
/// (invalid_input for a NaN or infinite component of either).
struct motion {
    rotation_pose start;  ///< B's pose at time 0
    rotation_pose end;    ///< B's pose at time 1
    /// The motion from `from` to `to`; throws invalid_input for a NaN or
    /// infinite component of either.
    motion(const pose& from, const pose& to) : start(from), end(checked_end(to)) {}

    /// Checks the arguments of a motion query of B from `from` to `to`
    /// against A: both polygons for NT (accepted_polygon), the options'
    /// tolerance (finite, >= 0) and both poses (finite), without taking
    /// their cosines and sines (the motions that turn pose B by their own
    /// formulas; a translation builds its motion after).
    template <class NT>
    static void check(const polygon& a, const polygon& b, const pose& from, const pose& to,
                      const sweep_options& options) {
        accepted_polygon<NT>(a, "static");
        accepted_polygon<NT>(b, "moving");
        if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
            throw invalid_input("sweep_options: tolerance is " + shortest_decimal(options.tolerance) +
                                ", not a finite number >= 0");
        rotation_pose::check(from);
        named_end([&] { rotation_pose::check(to); });
    }

private:
    /// f(), its invalid_input said of the end pose.
    template <class F>
    static auto named_end(F&& f) {
        try {
            return f();
        } catch (const invalid_input& e) {
            throw invalid_input(std::string("end ") + e.what());
        }
    }
    static rotation_pose checked_end(const pose& to) {
        return named_end([&] { return rotation_pose(to); });
    }
};

/// The filters' margin for a translation from `from` to `to`: the placing
/// margin of the one-shot query (intersects) with both translations in the
/// scale. B's vertices in double at any time of the motion are within it of
/// their NT values: the posing at the start rounds by a few units of
/// double's last place of that scale, the displacement to - from, its
/// product by a time in [0, 1] and the sum with a vertex by one each, all
/// inside placing_slack (2^-46 = 128 units) of it; a float keeps
/// posing_margin (placing_margin).
template <class NT>
double translation_margin(const polygon& a, const polygon& b, const pose& from, const pose& to) {
    return placing_margin<NT>(coordinate_scale(a) + coordinate_scale(b) + std::fabs(from.tx) + std::fabs(from.ty) +
                              std::fabs(to.tx) + std::fabs(to.ty));
}

/// The displacement of a translation in NT: to - from on the input doubles.
template <class NT>
point<NT> displacement(const pose& from, const pose& to) {
    using tr = number_traits<NT>;
    return {tr::from_double(to.tx) - tr::from_double(from.tx), tr::from_double(to.ty) - tr::from_double(from.ty)};
}

/// The time at which a site's vertex reaches its edge's line, in double
/// words (B posed by `start`; B's vertex displaced by d, A's by -d): the
/// site's three vertices posed alone (posed_site) and line_reaching_time, the
/// site's one contact time when the quotient's bound proves its denominator
/// not 0 (unknown otherwise). With certain_nearest, the nearest double of an
/// event's time in two cross products and a division: no side taken, no
/// midpoint walked as contact_times and nearest_double would.
inline double_word site_reaching_time(const polygon& a, const polygon& b, const rotation_pose& start,
                                      const point<double_word>& d, const contact_site& s) {
    const posed_site<double_word> q(a, b, start, d, s);
    return line_reaching_time(q.p, q.d, q.e0, q.e1);
}

/// The earliest event of a translation in one NT: its site and time.
template <class NT>
struct earliest_event {
    contact_site site;       ///< where the event happens
    time_fraction<NT> time;  ///< when
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

/// Whether the site may have an event while B moves from its place at the
/// start shifted by `from` to that place shifted by `to`, in double: whether
/// the path of its vertex over that part of the motion (a segment: B's
/// vertex from `b_start` by the shifts; A's vertex by their negatives
/// against B's edge at the start) may meet the edge (segments_may_meet),
/// every point within e of its exact place on each coordinate (the margin
/// of the motion's filters holds B's vertices at any time of it). False
/// only when the exact path and edge are apart, and then the site has no
/// contact time in that part.
inline bool site_may_meet(const polygon& a, const polygon& b, const std::vector<point<double>>& b_start,
                          point<double> from, point<double> to, double e, const contact_site& s) {
    if (s.moving_vertex) {
        const point<double> p = b_start[s.vertex];
        return segments_may_meet({p.x + from.x, p.y + from.y}, {p.x + to.x, p.y + to.y}, a.vertex(s.edge),
                                 a.vertex(a.next(s.edge)), e);
    }
    const point<double> p = a.vertex(s.vertex);
    return segments_may_meet({p.x - from.x, p.y - from.y}, {p.x - to.x, p.y - to.y}, b_start[s.edge],
                             b_start[b.next(s.edge)], e);
}

/// An event of the filtered search: its site, its time in `certified` when
/// every sign of it was certain, and its time in the exact field Exact once
/// asked, with two doubles around it.
template <class Exact>
struct filtered_event {
    contact_site site;                             ///< where the event happens
    std::optional<time_fraction<certified>> fast;  ///< the time in certified, when certain
    std::optional<vertex_passage> passage;         ///< the vertices it passes through, when the frame names them
    std::optional<time_fraction<Exact>> exact;     ///< the exact time, once asked
    /// The time in double words, once asked with no sign in doubt, or the
    /// time in certified when it is held exactly (none when a sign was in
    /// doubt, or not yet asked: `words_asked`).
    std::optional<time_fraction<double_word>> words;
    bool words_asked = false;  ///< whether `words` was asked
    double rounded = 0;        ///< the exact time's nearest double, with exact
    double below = 0;          ///< a double at most the exact time, with exact
    double above = 0;          ///< a double at least the exact time, with exact

    /// A double above the time: from the exact time's neighbours, else from
    /// the certified time's bounds (num at most its value plus its error,
    /// den at least its value minus its error), widened by quotient_widening
    /// and quotient_floor.
    double time_above() const {
        if (exact) return above;
        const double num = fast->num.value() + fast->num.error(), den = fast->den.value() - fast->den.error();
        const double q = num / den;
        return den > 0 && std::isfinite(q) ? q * (1 + quotient_widening) + quotient_floor
                                           : std::numeric_limits<double>::infinity();
    }

    /// Whether the time in certified holds its exact value (num and den
    /// without error: a time of 1 settled on the doubles as given, which
    /// the same time in double words leaves in doubt against the end).
    bool held_exactly() const { return fast && fast->num.exact() && fast->den.exact(); }

    /// The time in certified, held exactly, as double words (exact too).
    time_fraction<double_word> fast_as_words() const {
        return {double_word(fast->num.value()), double_word(fast->den.value())};
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

/// The sign of the time t (in certified) minus the double x when the bound
/// settles it, else none (certain_time_order).
inline std::optional<int> compare_time_with(const time_fraction<certified>& t, double x) {
    return certain_time_order(t, time_fraction<certified>{certified(x), certified(1)});
}

/// The site's vertex and edge as a point-to-line distance on the points as
/// given (equal_point_line_distances).
inline point_line_distance site_point_line(const polygon& a, const polygon& b, const contact_site& s) {
    if (s.moving_vertex) return {b.vertex(s.vertex), a.vertex(s.edge), a.vertex(a.next(s.edge)), true};
    return {a.vertex(s.vertex), b.vertex(s.edge), b.vertex(b.next(s.edge)), false};
}

/// Whether the events of two sites (both with a time) come at one time
/// when B, not turned (its rotation's doubles exactly 1 and 0), translates
/// from `from` to `to`, shown by exact signs on the points as given.
/// Neither edge is parallel to the displacement (exact_cross_sign of the
/// edge and the segment from (from.tx, from.ty) to (to.tx, to.ty)): each
/// event is then its vertex crossing its edge's line, once. And the two
/// vertex-line pairs are related as equal_point_line_distances relates
/// them: two vertices of one polygon on a parallel to one line of the
/// other reach it together; a vertex of B on a line of B's parallel to a
/// line of A holding a vertex of A reaches A's line when B's line reaches
/// A's vertex, both when the two lines coincide. Two polygons that share
/// a border and translate back onto it meet along all of it at once.
inline bool same_reaching_time(const polygon& a, const polygon& b, const pose& from, const pose& to,
                               const contact_site& l, const contact_site& r) {
    const point<double> start{from.tx, from.ty}, end{to.tx, to.ty};
    const point_line_distance x = site_point_line(a, b, l), y = site_point_line(a, b, r);
    return exact_cross_sign(x.from, x.to, start, end) != 0 && exact_cross_sign(y.from, y.to, start, end) != 0 &&
           equal_point_line_distances(x, y);
}

/// Whether two vertex passages come at one time when B, not turned,
/// translates by d = to - from (doubles as given): B's vertex v, translated
/// by t, sits on A's vertex a when v + t + s d = a, at s = d . (a - v - t) /
/// d . d (A's vertex moving by -d relative to B passes B's at the same s);
/// two such times are equal when d . ((a - v) - (a2 - v2)) = 0, whatever t
/// (exact_offsets_along). Two polygons that share their border's vertices
/// and translate back onto it pass them all at once.
inline bool same_passage_time(const polygon& a, const polygon& b, point<double> from, point<double> to,
                              const vertex_passage& l, const vertex_passage& r) {
    return exact_offsets_along(from, to, a.vertex(l.a_vertex), b.vertex(l.b_vertex), a.vertex(r.a_vertex),
                               b.vertex(r.b_vertex)) == 0;
}

/// The sign of c's time minus e's: in certified when both have one and the
/// bound settles it; else 0 when `same_time(c, e)` shows them
/// equal; else c's certified time against the doubles around e's exact
/// time; else in double words when their bound settles it (`word_time`
/// computes a site's time in double words, none when a sign is in doubt;
/// a certified time held exactly is its own; each event's kept); else
/// exactly (`exact_time` computes a site's exact
/// time: it exists, both events having one).
template <class Exact, class SameTime, class WordTime, class ExactTime>
int order(filtered_event<Exact>& c, filtered_event<Exact>& e, SameTime&& same_time, WordTime&& word_time,
          ExactTime&& exact_time) {
    if (c.fast && e.fast)
        if (const std::optional<int> o = certain_time_order(*c.fast, *e.fast)) return *o;
    if (same_time(c, e)) return 0;
    if (c.fast && e.exact) {
        const std::optional<int> above = compare_time_with(*c.fast, e.above);
        if (above && *above > 0) return 1;
        const std::optional<int> below = compare_time_with(*c.fast, e.below);
        if (below && *below < 0) return -1;
    }
    if (!c.exact || !e.exact) {
        for (filtered_event<Exact>* x : {&c, &e})
            if (!x->words_asked) {
                x->words = x->held_exactly() ? x->fast_as_words() : word_time(x->site);
                x->words_asked = true;
            }
        if (c.words && e.words)
            if (const std::optional<int> o = certain_time_order(*c.words, *e.words)) return *o;
    }
    for (filtered_event<Exact>* x : {&c, &e})
        if (!x->exact) x->set_exact(*exact_time(x->site));
    return compare_times(*c.exact, *e.exact);
}

/// A site's time in double, to order the sites of a window: the earliest
/// contact time of its vertex posed in double (`b_start` for B's) moving by
/// `sweep` against its edge; infinity when double finds none. An estimate
/// only: it orders the work, never decides.
inline double estimated_time(const polygon& a, const polygon& b, const std::vector<point<double>>& b_start,
                             point<double> sweep, const contact_site& s) {
    std::optional<time_fraction<double>> t =
        s.moving_vertex ? earliest_contact_time(b_start[s.vertex], sweep, a.vertex(s.edge), a.vertex(a.next(s.edge)))
                        : earliest_contact_time(a.vertex(s.vertex), point<double>{-sweep.x, -sweep.y}, b_start[s.edge],
                                                b_start[b.next(s.edge)]);
    const double q = t ? t->num / t->den : std::numeric_limits<double>::infinity();
    return std::isnan(q) ? std::numeric_limits<double>::infinity() : q;
}

/// The earliest event as earliest_translation_event, exact, at nearly
/// double's cost:
///
///   each window's sites (windowed_sites) whose vertex path over the
///   motion may meet their edge (site_may_meet), in the order of their
///   times in double (estimated_time):
///       a site whose path up to the best event's time (a double above
///       it, time_above) certainly misses its edge (site_may_meet) comes
///       later: skipped
///       else its time in `certified`, in the exact field Exact when its
///       signs are not certain; compared with the best in certified, or
///       when the bound cannot settle the order, equal when B is not turned
///       and same_reaching_time shows it, else in double words, else
///       exactly (order)
///
/// The double times order the sites so that the earliest is met first and
/// most others are then skipped by their paths alone; neither the order
/// nor the skips change the answer, the least time by site_before.
template <class Exact>
std::optional<filtered_event<Exact>> earliest_translation_event_filtered(const polygon& a, const polygon& b,
                                                                         const pose& from, const pose& to,
                                                                         const rotation_pose& start,
                                                                         translation_frame<certified>& fast) {
    const bool unturned = start.c == 1 && start.s == 0;
    if (unturned)
        fast.given =
            given_translation{{start.tx, start.ty}, {from.tx, from.ty}, {to.tx, to.ty}, point<double>{to.tx, to.ty}};
    std::optional<point<Exact>> exact_d;
    const auto exact_time = [&](const contact_site& s) {
        if (!exact_d) exact_d = displacement<Exact>(from, to);
        return site_time(a, b, start, *exact_d, s);
    };
    // (A doubt in double words noted, not raised: the time is then none.)
    const point<double_word> word_d = displacement<double_word>(from, to);
    const auto word_time = [&](const contact_site& s) {
        return noted_fallback::run([&] { return site_time(a, b, start, word_d, s); },
                                   [] { return std::optional<time_fraction<double_word>>(); });
    };
    std::optional<filtered_event<Exact>> best;
    const std::vector<point<double>>& b_start = fast.b.approx();
    const point<double> sweep{to.tx - from.tx, to.ty - from.ty};
    const double e = translation_margin<certified>(a, b, from, to);
    const auto evaluate = [&](const contact_site& s) {
        if (best) {
            // A site met again in a later window has the time it had: the
            // filter cannot tell a time from itself, so it is not compared.
            if (same_site(s, best->site)) return;
            // (u = 1: the whole motion's path, which the site passed to be
            // pending.)
            const double u = std::min(1.0, best->time_above());
            if (u < 1 && !site_may_meet(a, b, b_start, {0, 0}, {u * sweep.x, u * sweep.y}, e, s)) return;
        }
        filtered_event<Exact> c{};
        c.site = s;
        // (A doubt of the site's time in certified noted, not raised:
        // noted_fallback.)
        const bool certain = noted_fallback::run(
            [&] {
                c.fast = fast.earliest(s, &c.passage);
                return true;
            },
            [] { return false; });
        if (certain && !c.fast) return;
        if (!certain) {
            c.fast.reset();
            c.passage.reset();
            std::optional<time_fraction<Exact>> t = exact_time(s);
            if (!t) return;
            c.set_exact(std::move(*t));
        }
        if (best) {
            const int o = order(
                c, *best,
                [&](const filtered_event<Exact>& l, const filtered_event<Exact>& r) {
                    if (!unturned) return false;
                    if (l.passage && r.passage)
                        return same_passage_time(a, b, {from.tx, from.ty}, {to.tx, to.ty}, *l.passage, *r.passage);
                    return same_reaching_time(a, b, from, to, l.site, r.site);
                },
                word_time, exact_time);
            if (o > 0 || (o == 0 && !site_before(s, best->site))) return;
        }
        best = std::move(c);
    };
    // The window's sites, by their times in double, evaluated in that order.
    // (Kept per thread: a query is one of many; left as a thrown sign left
    // it, so emptied first.)
    static thread_local std::vector<std::pair<double, contact_site>> pending;
    pending.clear();
    const auto settle = [&] {
        std::sort(pending.begin(), pending.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
        for (const auto& [when, s] : pending) evaluate(s);
        pending.clear();
    };
    windowed_sites(
        a, b, b_start, fast.b.bounds(), sweep, e,
        [&](const contact_site& s) {
            if (best && same_site(s, best->site)) return;
            if (!site_may_meet(a, b, b_start, {0, 0}, sweep, e, s)) return;
            pending.push_back({estimated_time(a, b, b_start, sweep, s), s});
        },
        [&]() -> std::optional<double> {
            settle();
            if (!best) return std::nullopt;
            return best->time_above();
        });
    settle();
    return best;
}

}  // namespace sweep

}  // namespace influence2d
