// SPDX-License-Identifier: BSL-1.0
#pragma once
// The queries of the precision study (verification/study.hpp runs them): the
// separation at a pose (distance/separation.hpp), the first contact along a
// translation, and the first contact along a motion that turns in each
// turning model (motion/first_contact.hpp), asked of each number type through
// the library's public API, as the tool asks them (src/motion_queries.hpp):
//
//   floating types, exact:  separation_query<NT> (A and B prepared once per
//                           scene, not timed), first_contact<NT>
//   certified, interval:    certified_separation_query (prepared once per
//                           scene, not timed), certified_first_contact
//                           (interval has no route of its own: as certified)
//
// and compared with the answers of exact rationals: separation<exact_rational>
// on the prepared polygons (without the seeded search of separation_query) and
// first_contact<exact_rational> in the same model. Per question:
//
//   separation            meet or not; the closest features; the relative
//                         error of the distance, |d - D| / D, over the
//                         questions with D > 0 (d the root of the type's
//                         squared distance, taken exactly)
//   first_contact         (a translation) contact or not; the first features
//   turning_rational      and the absolute error of the earliest time,
//   turning_angle_linear  |t - T|, when both touch (but not when both meet
//                         at the start, t = T = 0)
//
// The rational model's reference is its exact answer (the time rounded to the
// nearest double). The angle-linear model's is conservative advancement run in
// exact rationals: its contact means "within the tolerance 1e-9" and its time
// is never after the true first contact (docs/sweep.md); a type's difference
// from it is a difference in that question, not from the true motion.
//
// A type that claims the exact answer must also give the exact value or its
// documented rounding: the exact type the same squared distance, points and
// time; certified the distance distance_of gives, the exact points and the
// exact time rounded to the nearest double. Any difference is a library bug.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "influence2d/core/feature.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/exact/certified_first_contact.hpp"
#include "influence2d/exact/certified_separation.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/distance.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d::verification {

/// The queries of the study: the separation at a pose; the first contact
/// along a translation; along a motion that turns, in each turning model.
enum class query_kind : std::uint8_t { separation, first_contact, turning_rational, turning_angle_linear };

inline constexpr query_kind all_query_kinds[] = {query_kind::separation, query_kind::first_contact,
                                                 query_kind::turning_rational, query_kind::turning_angle_linear};

inline const char* query_name(query_kind k) {
    switch (k) {
    case query_kind::separation: return "separation";
    case query_kind::first_contact: return "first_contact";
    case query_kind::turning_rational: return "turning_rational";
    case query_kind::turning_angle_linear: return "turning_angle_linear";
    }
    return "";
}

/// Whether the query asks about a motion that turns.
inline bool asks_turn(query_kind k) {
    return k == query_kind::turning_rational || k == query_kind::turning_angle_linear;
}

/// The options of a motion query: the turning model of a turning query.
inline sweep_options sweep_options_of(query_kind k) {
    sweep_options o;
    o.model = k == query_kind::turning_rational ? turning_model::rational : turning_model::angle_linear;
    return o;
}

inline std::optional<query_kind> query_from_name(std::string_view name) {
    for (query_kind k : all_query_kinds)
        if (name == query_name(k)) return k;
    return std::nullopt;
}

/// A motion of B, from one pose to another: a translation when the angles
/// are equal (study_translations), a turn otherwise (study_turns).
struct translation {
    pose from, to;
};

/// The translations of a scene, `count` of them, about its poses (which lie
/// near contact, touching and grazing ones included), in turn:
///   - toward pose k along the ray from A's centroid through B's posed
///     centroid, from R_A + R_B farther out (bounding radii): a contact at or
///     before t = 1 when pose k meets A (at 1 when it touches), none when it
///     grazes A from outside and nothing else is in the way;
///   - from pose k away along that ray (contact at t = 0 or none);
///   - from pose k's place to pose k + 1 (the last wraps to pose 0), both at
///     pose k + 1's angle.
inline std::vector<translation> study_translations(const polygon& a, const polygon& b, const std::vector<pose>& poses,
                                                   std::size_t count) {
    std::vector<translation> out;
    if (poses.empty()) return out;
    count = std::min(count, poses.size());
    out.reserve(count);
    const point<double> ca = a.centroid(), cb = b.centroid();
    const double reach = bounding_radius(a, ca) + bounding_radius(b, cb);
    for (std::size_t k = 0; k < count; ++k) {
        const pose& near = poses[k];
        if (k % 3 == 2) {
            const pose& next = poses[(k + 1) % poses.size()];
            out.push_back({{near.tx, near.ty, next.theta}, next});
            continue;
        }
        const point<double> at = rotation_pose(near).apply<double>(cb);
        const double dx = at.x - ca.x, dy = at.y - ca.y, length = std::hypot(dx, dy);
        const double ux = length > 0 ? dx / length : 1, uy = length > 0 ? dy / length : 0;
        const pose away{near.tx + reach * ux, near.ty + reach * uy, near.theta};
        out.push_back(k % 3 == 0 ? translation{away, near} : translation{near, away});
    }
    return out;
}

/// The motions that turn of a scene, `count` of them, about its poses: as
/// study_translations, each turning by a turn of 0.3 to 2.8 radians (spread
/// by the golden ratio over k, alternating in sign; two pieces of the
/// rational model from pi / 2), with, in turn:
///   - a turn and a move toward pose k from R_A + R_B farther out, ending at
///     pose k (a contact at or before t = 1 when pose k meets A);
///   - a turn and a move from pose k away along that ray;
///   - a turn in place from pose k, about B's origin.
inline std::vector<translation> study_turns(const polygon& a, const polygon& b, const std::vector<pose>& poses,
                                            std::size_t count) {
    std::vector<translation> out = study_translations(a, b, poses, count);
    for (std::size_t k = 0; k < out.size(); ++k) {
        const double spread = static_cast<double>(k) * 0.6180339887498949;
        const double turn = (k % 2 == 0 ? 1 : -1) * (0.3 + 2.5 * (spread - std::floor(spread)));
        const pose& near = poses[k];
        if (k % 3 == 0)
            out[k].from.theta = near.theta - turn;
        else if (k % 3 == 1)
            out[k].to.theta = near.theta + turn;
        else
            out[k] = {near, {near.tx, near.ty, near.theta + turn}};
    }
    return out;
}

// --- Exact values of the answers --------------------------------------------

/// The exact value of a number of any type of the study; nullopt when it is
/// not finite. A value of a type wider than double is first scaled by powers
/// of two into double's normal range, then taken apart into doubles, each
/// the rounding of what remains: the remainder of a rounding to fewer bits
/// is representable in the type, so every step is exact.
template <class NT>
std::optional<exact_rational> exact_value(NT x) {
    if constexpr (std::is_same_v<NT, exact_rational>) {
        return x;
    } else if constexpr (std::is_same_v<NT, float> || std::is_same_v<NT, double>) {
        if (!std::isfinite(x)) return std::nullopt;
        return exact_rational(static_cast<double>(x));
    } else {
        using tr = number_traits<NT>;
        if (!(x - x == tr::from_double(0))) return std::nullopt;  // infinite or NaN
        const NT up = tr::from_double(0x1p600), down = tr::from_double(0x1p-600);
        const NT large = tr::from_double(0x1p900), small = tr::from_double(0x1p-900);
        int exponent = 0;  // x = value * 2^-exponent
        while (x != tr::from_double(0) && x < small && -x < small) {
            x = x * up;
            exponent += 600;
        }
        while (x > large || -x > large) {
            x = x * down;
            exponent -= 600;
        }
        exact_rational value(0);
        for (int part = 0; part < 4 && x != tr::from_double(0); ++part) {
            const double d = tr::to_double(x);
            value += exact_rational(d);
            x = x - tr::from_double(d);
        }
        for (; exponent > 0; exponent -= 600) value /= exact_rational(0x1p600);
        for (; exponent < 0; exponent += 600) value *= exact_rational(0x1p600);
        return value;
    }
}

/// The relative error |sqrt(s) - sqrt(S)| / sqrt(S) of a distance given by
/// its exact square s against the exact distance sqrt(S), S > 0: with
/// r = s / S - 1 exact, |r| / (sqrt(1 + r) + 1), evaluated in double.
inline double relative_distance_error(const exact_rational& s, const exact_rational& S) {
    const double r = CGAL::to_double(s / S - exact_rational(1));
    return std::fabs(r) / (std::sqrt(std::max(1 + r, 0.0)) + 1);
}

/// |t - T| for the exact time T; infinity for a time that is not finite.
template <class NT>
double absolute_time_error(const NT& t, const exact_rational& T) {
    const std::optional<exact_rational> v = exact_value(t);
    return v ? std::fabs(CGAL::to_double(*v - T)) : std::numeric_limits<double>::infinity();
}

inline bool same_feature(const feature& l, const feature& r) { return l.kind == r.kind && l.index == r.index; }

inline point<double> nearest_point(const point<exact_rational>& p) {
    return {nearest_double(p.x), nearest_double(p.y)};
}

// --- One question's comparison ----------------------------------------------

/// What a type's answer claims of its value: nothing (a floating type), the
/// exact value, or the exact value rounded as documented (certified).
enum class value_claim : std::uint8_t { none, exact, rounded };

/// How one answer compares with the exact one.
struct query_outcome {
    bool meeting_differs = false;  ///< meet (separation) or contact (first contact) or not
    bool features_differ = false;  ///< the closest (first) features
    bool value_differs = false;    ///< not the value the type claims (exact, or its rounding)
    std::optional<double> error;   ///< the relative distance error or the absolute time error, where measured
    bool differs() const { return meeting_differs || features_differ || value_differs; }
};

template <class NT>
query_outcome compare_answer(const separation_result<NT>& got, const separation_result<exact_rational>& exact,
                             value_claim claim) {
    query_outcome o;
    o.meeting_differs = got.meet() != exact.meet();
    o.features_differ = !same_feature(got.static_feature, exact.static_feature) ||
                        !same_feature(got.moving_feature, exact.moving_feature);
    if (!exact.meet()) {
        const std::optional<exact_rational> s = exact_value(got.squared_distance);
        o.error = s ? relative_distance_error(*s, exact.squared_distance) : std::numeric_limits<double>::infinity();
    }
    if constexpr (std::is_same_v<NT, exact_rational>)
        o.value_differs = claim == value_claim::exact &&
                          (got.squared_distance != exact.squared_distance ||
                           !(got.static_point == exact.static_point) || !(got.moving_point == exact.moving_point));
    return o;
}

inline query_outcome compare_answer(const certified_separation_result& got,
                                    const separation_result<exact_rational>& exact, value_claim) {
    query_outcome o;
    o.meeting_differs = got.meet != exact.meet();
    o.features_differ = !same_feature(got.static_feature, exact.static_feature) ||
                        !same_feature(got.moving_feature, exact.moving_feature);
    const exact_rational d(got.distance);
    if (!exact.meet()) o.error = relative_distance_error(d * d, exact.squared_distance);
    o.value_differs = got.distance != distance_of<exact_rational>(exact.squared_distance) ||
                      !(got.static_point == nearest_point(exact.static_point)) ||
                      !(got.moving_point == nearest_point(exact.moving_point));
    return o;
}

template <class NT>
query_outcome compare_answer(const contact_result<NT>& got, const contact_result<exact_rational>& exact,
                             value_claim claim) {
    query_outcome o;
    o.meeting_differs = got.contact != exact.contact;
    if (!got.contact || !exact.contact) return o;
    o.features_differ = !same_feature(got.static_feature, exact.static_feature) ||
                        !same_feature(got.moving_feature, exact.moving_feature);
    const bool both_at_start = number_traits<NT>::sign(got.time) == 0 && CGAL::sign(exact.time) == 0;
    if (!both_at_start) o.error = absolute_time_error(got.time, exact.time);  // (at the start no time is computed)
    if constexpr (std::is_same_v<NT, exact_rational>)
        o.value_differs = claim == value_claim::exact && got.time != exact.time;
    else if constexpr (std::is_same_v<NT, double>)
        o.value_differs = claim == value_claim::rounded && got.time != nearest_double(exact.time);
    return o;
}

// --- The routes --------------------------------------------------------------

/// How a number type answers the queries: in NT through separation_query<NT>
/// and first_contact<NT>, or, for a filtered type (Filtered), through
/// certified_separation_query and certified_first_contact. Throws invalid_input
/// when NT cannot hold the scene (float beyond its range).
template <class NT, bool Filtered>
class query_route {
public:
    static constexpr value_claim claim = is_exact_v<NT> ? value_claim::exact : value_claim::none;

    query_route(const polygon& a, const polygon& b) : a_(a), b_(b), separation_(a, b) {}

    /// The separation at q; a squared distance beyond NT's range (the
    /// query's std::range_error) is an answer whose squared distance is not
    /// finite, as the study reports it.
    separation_result<NT> separation(const pose& q) {
        if constexpr (scaled_into_range_v<NT>) {
            try {
                return separation_(q);
            } catch (const std::range_error&) {
                separation_result<NT> r;
                r.squared_distance = std::numeric_limits<NT>::infinity();
                return r;
            }
        }
        return separation_(q);
    }
    contact_result<NT> first_contact(const translation& m, query_kind k) {
        return influence2d::first_contact<NT>(a_, b_, m.from, m.to, sweep_options_of(k));
    }

private:
    const polygon& a_;
    const polygon& b_;
    separation_query<NT> separation_;
};

template <class NT>
class query_route<NT, true> {
public:
    static constexpr value_claim claim = value_claim::rounded;

    query_route(const polygon& a, const polygon& b) : a_(a), b_(b), separation_(a, b) {}

    certified_separation_result separation(const pose& q) { return separation_(q); }
    contact_result<double> first_contact(const translation& m, query_kind k) {
        return certified_first_contact(a_, b_, m.from, m.to, sweep_options_of(k));
    }

private:
    const polygon& a_;
    const polygon& b_;
    certified_separation_query separation_;
};

/// The exact answers of one scene: separation<exact_rational> on A and B
/// prepared once, first_contact<exact_rational> in the query's model.
class query_reference {
public:
    query_reference(const polygon& a, const polygon& b)
        : a_(a),
          b_(b),
          prepared_a_(prepare_static<exact_rational>(a)),
          prepared_b_(prepare_moving<exact_rational>(b)) {}

    separation_result<exact_rational> separation(const pose& q) const {
        return influence2d::separation<exact_rational>(*prepared_a_, *prepared_b_, q);
    }
    contact_result<exact_rational> first_contact(const translation& m, query_kind k) const {
        return influence2d::first_contact<exact_rational>(a_, b_, m.from, m.to, sweep_options_of(k));
    }

private:
    const polygon& a_;
    const polygon& b_;
    std::shared_ptr<const static_scene<exact_rational>> prepared_a_;
    std::shared_ptr<const moving_scene<exact_rational>> prepared_b_;
};

// --- Answers as text ----------------------------------------------------------

/// How an answer is written: its numbers as doubles (the study's examples)
/// or exactly (reproducible cases: an exact rational as p/q).
enum class digits : std::uint8_t { rounded, exact };

/// A number as text: an exact rational as p/q (digits::exact) or its nearest
/// double, any other number as its double; doubles with 17 digits.
template <class NT>
std::string number_text(const NT& x, digits d = digits::rounded) {
    std::ostringstream s;
    s.precision(17);
    if constexpr (std::is_same_v<NT, exact_rational>) {
        if (d == digits::exact)
            s << x;
        else
            s << nearest_double(x);
    } else {
        s << number_traits<NT>::to_double(x);
    }
    return s.str();
}

inline std::string feature_pair_text(const feature& a, const feature& b) {
    const auto one = [](const feature& f) {
        if (f.kind == feature_kind::interior) return std::string("interior");
        return (f.kind == feature_kind::vertex ? "v" : "e") + std::to_string(f.index);
    };
    return one(a) + ":" + one(b);
}

template <class NT>
std::string points_text(const point<NT>& p, const point<NT>& q, digits d) {
    return "points (" + number_text(p.x, d) + ", " + number_text(p.y, d) + ") (" + number_text(q.x, d) + ", " +
           number_text(q.y, d) + ")";
}

/// A separation as text: meet or apart, the features (A's:B's), the distance
/// (digits::rounded) or the squared distance and the points (digits::exact).
template <class NT>
std::string answer_text(const separation_result<NT>& r, digits d = digits::rounded) {
    const std::string s = (r.meet() ? "meet, " : "apart, ") + feature_pair_text(r.static_feature, r.moving_feature);
    if (d == digits::rounded) return s + ", distance " + number_text(distance_of<NT>(r.squared_distance));
    return s + ", squared distance " + number_text(r.squared_distance, d) + ", " +
           points_text(r.static_point, r.moving_point, d);
}

inline std::string answer_text(const certified_separation_result& r, digits d = digits::rounded) {
    const std::string s = (r.meet ? "meet, " : "apart, ") + feature_pair_text(r.static_feature, r.moving_feature) +
                          ", distance " + number_text(r.distance);
    return d == digits::rounded ? s : s + ", " + points_text(r.static_point, r.moving_point, d);
}

template <class NT>
std::string answer_text(const contact_result<NT>& r, digits d = digits::rounded) {
    if (!r.contact) return "no contact";
    return "contact at " + number_text(r.time, d) + ", " + feature_pair_text(r.static_feature, r.moving_feature);
}

// --- One question alone (reproducible cases) ---------------------------------

/// The exact answer to one question of a query, as text: the pose of a
/// separation is motion.from.
inline std::string exact_answer_text(const polygon& a, const polygon& b, query_kind k, const translation& motion) {
    const query_reference exact(a, b);
    if (k == query_kind::separation) return answer_text(exact.separation(motion.from), digits::exact);
    return answer_text(exact.first_contact(motion, k), digits::exact);
}

/// A route's answer to one question of a query on A and B alone (fresh
/// objects, no earlier question), compared with the exact one; and the
/// answer as text.
template <class Route>
std::pair<query_outcome, std::string> fresh_answer(const polygon& a, const polygon& b, query_kind k,
                                                   const translation& motion) {
    Route route(a, b);
    const query_reference exact(a, b);
    if (k == query_kind::separation) {
        const auto got = route.separation(motion.from);
        return {compare_answer(got, exact.separation(motion.from), Route::claim), answer_text(got, digits::exact)};
    }
    const auto got = route.first_contact(motion, k);
    return {compare_answer(got, exact.first_contact(motion, k), Route::claim), answer_text(got, digits::exact)};
}

}  // namespace influence2d::verification
