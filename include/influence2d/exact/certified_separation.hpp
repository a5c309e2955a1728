// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The exact separation rounded to double, at a few times double's cost: the
/// query in double words, rounded where their bounds settle the rounding,
/// and in exact rationals otherwise.

#include <cmath>
#include <cstddef>
#include <optional>

#include "influence2d/core/feature.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/double_word.hpp"
#include "influence2d/number/fallback.hpp"
#include "influence2d/predicates/certain_nearest.hpp"
#include "influence2d/predicates/distance.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d {

/// The separation of certified_separation: the exact answer's features, its
/// points and its distance rounded to double.
struct certified_separation_result {
    double distance = 0;          ///< within one unit in the last place of the exact distance (distance_of)
    double squared_distance = 0;  ///< the exact squared distance rounded to the nearest double
    feature static_feature{};     ///< as separation_result, exactly
    feature moving_feature{};     ///< as separation_result, exactly
    point<double> static_point;   ///< the exact closest point of A, each coordinate rounded to the nearest double
    point<double> moving_point;   ///< the exact closest point of posed B, rounded likewise
    bool meet = false;            ///< whether the regions meet (exact)
    /// Edge pairs evaluated in exact rationals: 0 when the query in double
    /// words settled every sign and rounding (nearly every pose).
    std::size_t exact_pairs = 0;
};

namespace certified_separation_detail {

/// The exact answer rounded: the squared distance by scaled_nearest (whatever
/// its magnitude), the distance as distance_of, the points coordinate by
/// coordinate.
inline certified_separation_result rounded(const separation_result<exact_rational>& exact) {
    certified_separation_result r;
    const scaled_double squared = scaled_nearest(exact.squared_distance);  // (distance_of's rounding)
    r.squared_distance = std::ldexp(squared.mantissa, squared.exponent);
    r.distance = std::ldexp(std::sqrt(squared.mantissa), squared.exponent / 2);
    r.static_feature = exact.static_feature;
    r.moving_feature = exact.moving_feature;
    r.static_point = {nearest_double(exact.static_point.x), nearest_double(exact.static_point.y)};
    r.meet = exact.meet();
    // (Meeting: one point.)
    r.moving_point = r.meet ? r.static_point
                            : point<double>{nearest_double(exact.moving_point.x), nearest_double(exact.moving_point.y)};
    r.exact_pairs = exact.evaluated_pairs;
    return r;
}

/// The double nearest to x's exact value; uncertain_sign when x's bound
/// cannot settle it (certain_nearest).
inline double nearest_of(const double_word& x) {
    double d;
    if (!certain_nearest(x, d)) throw uncertain_sign();
    return d;
}

/// The double nearest to each exact coordinate of a closest point of B,
/// when its double word cannot settle the rounding. A posed vertex's exact
/// coordinates c x - s y + tx and s x + c y + ty have a few bits more than
/// a double (those of the vertex's short coordinates, as 50 or 0.5, beyond
/// the 53 of c and s), and then lie exactly halfway between two doubles
/// often enough (about one in 2^k for k such bits) that no bound decides
/// them. Taken exactly in rationals, that vertex alone, posed by the query's
/// pose as the exact query poses it. Only a vertex: any other point raises
/// uncertain_sign (the whole pose then goes to exact rationals). (A's points
/// need none of this: a vertex of A is its input double, which its double
/// word holds exactly.)
struct vertex_rounding {
    const polygon* b;   ///< the moving polygon
    const pose* posed;  ///< B's pose
    /// The point `w` of the answer rounded, `at` B's feature there.
    point<double> operator()(const point<double_word>& w, const feature& at) const {
        point<double> r;
        if (certain_nearest(w.x, r.x) && certain_nearest(w.y, r.y)) return r;
        if (at.kind != feature_kind::vertex) throw uncertain_sign();
        const point<exact_rational> v =
            rotation_pose(*posed).apply<exact_rational>(b->vertex(input_vertex(*b, at.index)));
        return {nearest_double(v.x), nearest_double(v.y)};
    }
};

/// The answer in double words rounded as `rounded` rounds the exact one, or
/// uncertain_sign when a rounding is in doubt that vertex_rounding cannot
/// settle. Its features are the exact ones (every sign of the query was
/// certain). A squared distance in [word_floor, word_ceiling] is a double
/// of scaled_nearest's exponent 0, so the distance is the root of its
/// nearest double, as distance_of's. The static point is A's feature, or
/// B's vertex in A's interior; the moving point B's feature, or the static
/// point when they meet.
inline certified_separation_result rounded(const separation_result<double_word>& w, const vertex_rounding& vertex) {
    certified_separation_result r;
    r.squared_distance = nearest_of(w.squared_distance);
    r.distance = std::sqrt(r.squared_distance);
    r.static_feature = w.static_feature;
    r.moving_feature = w.moving_feature;
    r.meet = w.meet();
    r.static_point = w.static_feature.kind == feature_kind::interior
                         ? vertex(w.static_point, w.moving_feature)
                         : point<double>{nearest_of(w.static_point.x), nearest_of(w.static_point.y)};
    r.moving_point = r.meet ? r.static_point : vertex(w.moving_point, w.moving_feature);
    return r;
}

}  // namespace certified_separation_detail

/// The exact separation, separation<exact_rational>(a, b, q) on the polygons
/// (distance/separation.hpp), rounded to double: the same features, its
/// points and distance rounded. The query first runs in double words
/// (number/double_word.hpp): phase 1 in double as always, the candidate
/// pairs and the ring vertices' locations in double words whose signs are
/// exact or raise uncertain_sign, and the answer's values rounded where
/// their bounds settle the rounding (certain_nearest). A sign or a rounding
/// in doubt (exact touching, a value within its bound of a midpoint between
/// doubles, magnitudes beyond 2^+-900) sends the pose to exact rationals.
/// Both routes give the exact answer's rounding, so the answer does not
/// depend on which one ran. Throws invalid_input for an empty polygon or a
/// pose with a NaN or infinite component.
inline certified_separation_result certified_separation(const polygon& a, const polygon& b, const pose& q) {
    const certified_separation_detail::vertex_rounding vertex{&b, &q};
    return fallback<>::run(
        [&] { return certified_separation_detail::rounded(separation<double_word>(a, b, q), vertex); },
        [&] { return certified_separation_detail::rounded(separation<exact_rational>(a, b, q)); });
}

/// certified_separation as a function object.
struct certified_separation_of {
    /// certified_separation(a, b, q).
    certified_separation_result operator()(const polygon& a, const polygon& b, const pose& q) const {
        return certified_separation(a, b, q);
    }
};

/// certified_separation over many poses of one pair: A and B prepared once in
/// double words (their edge trees, A's cone index for the ring vertices'
/// locations), each pose's search seeded by the last closest pair
/// (separation_query), and the exact route prepared on the first pose that
/// needs it. One object per thread. Answers as certified_separation.
class certified_separation_query {
public:
    /// Prepares A and B. Throws invalid_input for an empty polygon.
    certified_separation_query(const polygon& static_polygon, const polygon& moving_polygon)
        : a_(accepted_polygon<exact_rational>(static_polygon, "static")),
          b_(accepted_polygon<exact_rational>(moving_polygon, "moving")) {
        // (A polygon whose preparation in double words meets a sign in
        // doubt is answered in exact rationals alone.)
        try {
            const doubt_raising raised;  // (what is built here outlives any doubt_noting)
            fast_.emplace(prepare_static<double_word>(a_), prepare_moving<double_word>(b_));
        } catch (const uncertain_sign&) {
            fast_.reset();
        }
    }

    /// The separation at pose q (certified_separation). Throws invalid_input
    /// for a pose with a NaN or infinite component.
    certified_separation_result operator()(const pose& q) {
        const auto in_rationals = [&] {
            if (!exact_) exact_.emplace(prepare_static<exact_rational>(a_), prepare_moving<exact_rational>(b_));
            certified_separation_result r = certified_separation_detail::rounded((*exact_)(q));
            r.exact_pairs = exact_->evaluated_pairs();
            return r;
        };
        if (!fast_) return in_rationals();
        const certified_separation_detail::vertex_rounding vertex{&b_, &q};
        return fallback<>::run([&] { return certified_separation_detail::rounded((*fast_)(q), vertex); }, in_rationals);
    }

private:
    polygon a_, b_;
    std::optional<separation_query<double_word>> fast_;
    std::optional<separation_query<exact_rational>> exact_;
};

}  // namespace influence2d
