// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The first contact along a motion (continuous collision detection;
/// docs/sweep.md): translations by their events, motions that turn by
/// conservative advancement.

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
#include "influence2d/query/intersects.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/edge_boxes.hpp"
#include "influence2d/scene/placed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

#include "influence2d/motion/motion.hpp"
#include "influence2d/motion/rational_apart.hpp"
#include "influence2d/motion/rational_turn.hpp"
#include "influence2d/motion/translation_events.hpp"
#include "influence2d/motion/turning.hpp"

namespace influence2d {

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
/// tolerance (docs/sweep.md, "Motions that turn"), or, with
/// sweep_options::model rational, in the rational model by the exact roots
/// of its contact cubics (rational_first_contact: exact when NT is, the
/// time rounded to the nearest double), two convex polygons that
/// rational_advance proves apart along the whole motion answered at once
/// (no contact, in every NT), and otherwise searched from where it stopped
/// (rational_start). NT needs division for
/// the time of the result (every number type of the library but certified
/// and interval: certified_first_contact is the filtered route). In
/// float, double or long double, a motion whose largest coordinate lies outside
/// NT's safe window is answered on its input scaled by a power of two, the
/// tolerance with it (core/range_scaling.hpp): the same time and features,
/// without overflow or underflow. Throws invalid_input for an empty polygon,
/// a NaN or infinite component of either pose, or a tolerance that is
/// negative, NaN or infinite.
template <class NT>
contact_result<NT> first_contact(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                 const sweep_options& options = {}) {
    using namespace sweep;
    motion::check<NT>(a, b, from, to, options);
    if constexpr (scaled_into_range_v<NT>) {
        if (const int k = range_shift<NT>(a, b, from, to)) {
            sweep_options scaled = options;
            scaled.tolerance = scaled_length(options.tolerance, k);
            return first_contact<NT>(a.scaled_by_power_of_two(k), b.scaled_by_power_of_two(k),
                                     scaled_by_power_of_two(from, k), scaled_by_power_of_two(to, k), scaled);
        }
    }
    if (from.theta != to.theta && options.model == turning_model::rational) {
        const contact_result<double> t = advanced_rational_first_contact<NT>(a, b, from, to);
        return {t.contact, number_traits<NT>::from_double(t.time), t.static_feature, t.moving_feature};
    }
    if (from.theta != to.theta) return turning_first_contact<NT>(a, b, from, to, options);
    const motion m(from, to);
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
/// time is rounded as the quotient of its doubles when `certified` holds
/// it without error (a time of 1, at the motion's end), else from its
/// site's three vertices in double words, or in Exact when their bound
/// leaves the rounding in doubt (nearest_site_time). For
/// a motion that turns: the answer of first_contact<Exact> (the same
/// steps, the stop decided on separation<Exact>'s exact distance;
/// docs/sweep.md); in the rational model rational_first_contact<Exact>,
/// whose pairs are sifted in `certified` first (after rational_advance, as
/// first_contact). A motion whose largest coordinate lies outside double's
/// safe window (core/range_scaling.hpp), where the filter's bounds in double
/// lose their hold (products near the subnormals, or beyond the range), is
/// answered on its input scaled by a power of two, the tolerance with it,
/// when every coordinate scales exactly (scales_exactly): the same question,
/// so the same exact time and features. Throws as first_contact.
/// certified_first_contact (exact/certified_first_contact.hpp) is this
/// query in exact rationals. `Fine` is the exact separation of a motion that
/// turns (filtered_turning_first_contact; void: separation<Exact>).
template <class Exact, class Fine = void>
contact_result<double> filtered_first_contact(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                              const sweep_options& options = {}) {
    using namespace sweep;
    motion::check<double>(a, b, from, to, options);
    if (const int k = range_shift<double>(a, b, from, to); k != 0 && scales_exactly(a, b, k, from, to)) {
        sweep_options scaled = options;
        scaled.tolerance = scaled_length(options.tolerance, k);
        return filtered_first_contact<Exact, Fine>(a.scaled_by_power_of_two(k), b.scaled_by_power_of_two(k),
                                                   scaled_by_power_of_two(from, k), scaled_by_power_of_two(to, k),
                                                   scaled);
    }
    if (from.theta != to.theta && options.model == turning_model::rational)
        return advanced_rational_first_contact<Exact>(a, b, from, to);
    if (from.theta != to.theta) return filtered_turning_first_contact<Exact, Fine>(a, b, from, to, options);
    const motion m(from, to);
    contact_result<double> r;
    // A and B placed once in certified, for the meeting at the start and the
    // search.
    translation_frame<certified> fast(a, b, m.start, displacement<certified>(from, to));
    const auto met = noted_fallback::run([&] { return meeting_at_start<certified>(fast.a, fast.b, from); },
                                         [&] { return meeting_at_start<Exact>(a, b, from, m.start); });
    if (met) {
        r.contact = true;
        std::tie(r.static_feature, r.moving_feature) = *met;
        return r;
    }
    if (from.tx == to.tx && from.ty == to.ty) return r;  // B stays where it was
    auto best = earliest_translation_event_filtered<Exact>(a, b, from, to, m.start, fast);
    if (!best) return r;
    r.contact = true;
    std::tie(r.static_feature, r.moving_feature) = site_features(a, b, best->site);
    // Rounding to the nearest double asks for the time's sign against the
    // midpoints between doubles, finer than certified's bound: in double
    // words (the quotient at which the vertex reaches the edge's line, else
    // the site's contact_times), exactly when their bound cannot tell.
    if (best->exact) {
        r.time = best->rounded;
        return r;
    }
    // A time whose numerator and denominator `certified` holds without
    // error (a time of 1 decided on the doubles as given: num = den = 1)
    // rounds as their quotient in double, IEEE 754's division being
    // correctly rounded, ties to even, as nearest_double.
    if (best->fast && best->fast->num.exact() && best->fast->den.exact()) {
        r.time = best->fast->num.value() / best->fast->den.value();
        return r;
    }
    if (certain_nearest(site_reaching_time(a, b, m.start, displacement<double_word>(from, to), best->site), r.time))
        return r;
    r.time = nearest_site_time<Exact>([&](auto tag) {
        using W = decltype(tag);
        std::optional<time_fraction<W>> t = site_time(a, b, m.start, displacement<W>(from, to), best->site);
        // (In double words the site may lack the time only after a doubt
        // noted on the way, whose answer is dropped: raised then.)
        if constexpr (number_traits<W>::category != number_category::exact)
            if (!t) throw uncertain_sign();
        INFLUENCE2D_ASSERT(t.has_value(), "the earliest event's site has no contact time");
        return std::move(*t);
    });
    return r;
}

}  // namespace influence2d
