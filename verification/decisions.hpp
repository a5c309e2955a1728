// SPDX-License-Identifier: BSL-1.0
#pragma once
// The method's decisions, one at a time, in any number type NT, on the same
// input doubles (docs/method.md section 9), with answers that compare across types:
//
//   cone_membership       the influence areas containing a query point
//                         (influence_areas<NT>::for_each_containing), sorted
//   mask                  the influence mask of the point (influence_areas<NT>::mask)
//   alpha_selection       for a pose of B: the static edges, all of them, whose
//                         sign of alpha changes or is zero among B's posed
//                         vertices (orientation(V_i, V_i+1, q_j) over every j)
//   capsule_candidates    the static edges whose capsule of length n = r_B + d
//                         contains B's posed centroid (in_capsule in NT)
//   band_candidates       the same with the paper's band (in_band in NT)
//   pairs                 every (static edge, moving edge) pair that meets
//                         (segments_intersect; segments_within for d > 0),
//                         in input numbering
//   containment           where the first vertex of each ring of B lies in A
//                         (influence_areas::locate) and the first vertex of
//                         each ring of A in B (locate on B's covering)
//   collides              detector<NT>::collide
//   collides_brute_force  brute_force_detector<NT>::collide
//
// An answer is a list of integers: edge numbers, flattened pairs, locations
// (0 outside, 1 boundary, 2 inside) or 0/1. The exact reference of each
// decision (reference_decisions) is independent of the method where an
// independent computation exists: a scan of every cone for the cone decisions,
// cgal_reference for the pairs and the collision; elsewhere the same decision
// evaluated in exact_rational.
//
// A number type can be evaluated with a fallback: evaluator<certified,
// exact_rational> answers each question in `certified` and, when that raises
// uncertain_sign, again in exact_rational, as certified_detector does (and
// likewise evaluator<interval, exact_rational>).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/influence/influence_areas.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/extended_area.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/predicates/segments.hpp"
#include "influence2d/scene/posed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"
#include "verification/cgal_reference.hpp"

namespace influence2d::verification {

enum class decision_kind : std::uint8_t {
    cone_membership,
    mask,
    alpha_selection,
    capsule_candidates,
    band_candidates,
    pairs,
    containment,
    collides,
    collides_brute_force
};

inline constexpr decision_kind all_decision_kinds[] = {
    decision_kind::cone_membership,     decision_kind::mask,
    decision_kind::alpha_selection,     decision_kind::capsule_candidates,
    decision_kind::band_candidates,     decision_kind::pairs,
    decision_kind::containment,         decision_kind::collides,
    decision_kind::collides_brute_force};

inline const char* decision_name(decision_kind k) {
    switch (k) {
    case decision_kind::cone_membership: return "cone_membership";
    case decision_kind::mask: return "mask";
    case decision_kind::alpha_selection: return "alpha_selection";
    case decision_kind::capsule_candidates: return "capsule_candidates";
    case decision_kind::band_candidates: return "band_candidates";
    case decision_kind::pairs: return "pairs";
    case decision_kind::containment: return "containment";
    case decision_kind::collides: return "collides";
    case decision_kind::collides_brute_force: return "collides_brute_force";
    }
    return "unknown";
}

inline std::optional<decision_kind> decision_from_name(std::string_view name) {
    for (decision_kind k : all_decision_kinds)
        if (name == decision_name(k)) return k;
    return std::nullopt;
}

/// Whether the decision is asked of a query point (else of a pose of B).
inline bool asks_point(decision_kind k) { return k == decision_kind::cone_membership || k == decision_kind::mask; }

/// One question: a point for the point decisions, a pose of B for the others.
struct query {
    point<double> at;
    pose placement;
};

/// The answer to one question, comparable across number types.
using answer = std::vector<long>;

/// A number type's name as the tool spells it: number_traits' name with '-'
/// for spaces ("long-double").
template <class NT>
std::string number_type_name() {
    std::string s = number_traits<NT>::name;
    std::replace(s.begin(), s.end(), ' ', '-');
    return s;
}

/// Every decision of the method in number type NT for one scene: static A,
/// moving B, separation distance d. Answers are appended to `out`.
template <class NT>
class decision_context {
public:
    decision_context(const polygon& a, const polygon& b, double distance)
        : scene_(a),
          b_(b),
          distance_(distance),
          detector_(a, b, options(distance)),
          brute_(a, b, options(distance)),
          mask_(a.size()),
          posed_(b.size()) {
        using tr = number_traits<NT>;
        n_ = tr::from_double(moving_reach(bounding_radius(b, b.centroid()), distance));
        n2_ = n_ * n_;
        const NT dn = tr::from_double(distance);
        d2_ = dn * dn;
    }
    decision_context(const decision_context&) = delete;
    decision_context& operator=(const decision_context&) = delete;

    const static_scene<NT>& scene() const { return scene_; }

    void decide(decision_kind k, const query& q, answer& out) {
        switch (k) {
        case decision_kind::cone_membership: return cone_membership(q.at, out);
        case decision_kind::mask: return mask(q.at, out);
        case decision_kind::alpha_selection: return alpha_selection(q.placement, out);
        case decision_kind::capsule_candidates: return candidates(q.placement, extended_area::capsule, out);
        case decision_kind::band_candidates: return candidates(q.placement, extended_area::band, out);
        case decision_kind::pairs: return pairs(q.placement, out);
        case decision_kind::containment: return containment(q.placement, out);
        case decision_kind::collides: return out.push_back(detector_.collide(q.placement).collides ? 1 : 0);
        case decision_kind::collides_brute_force: return out.push_back(brute_.collide(q.placement).collides ? 1 : 0);
        }
    }

    void cone_membership(const point<double>& q, answer& out) const {
        const std::size_t first = out.size();
        scene_.areas().for_each_containing(to_nt(q), [&](std::size_t i) { out.push_back(static_cast<long>(i)); });
        std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
    }

    void mask(const point<double>& q, answer& out) {
        scene_.areas().mask(to_nt(q), mask_);
        for (std::size_t i = 0; i < scene_.shape.size(); ++i)
            if (mask_.test(i)) out.push_back(static_cast<long>(i));
    }

    void alpha_selection(const pose& p, answer& out) {
        pose_vertices(p);
        const auto& cov = scene_.covering;
        for (std::size_t i = 0; i < cov.size(); ++i) {
            bool positive = false, negative = false, selected = false;
            for (const point<NT>& v : posed_) {
                const int s = orientation(cov.start(i), cov.end(i), v);
                positive = positive || s > 0;
                negative = negative || s < 0;
                if (s == 0 || (positive && negative)) {
                    selected = true;
                    break;
                }
            }
            if (selected) out.push_back(static_cast<long>(i));
        }
    }

    void candidates(const pose& p, extended_area shape, answer& out) const {
        const point<NT> c = rotation_pose(p).apply<NT>(b_.centroid());
        const auto& cov = scene_.covering;
        for (std::size_t i = 0; i < cov.size(); ++i) {
            const bool in = shape == extended_area::capsule ? in_capsule(c, cov.start(i), cov.end(i), n2_)
                                                            : in_band(c, cov.start(i), cov.end(i), n_, n2_);
            if (in) out.push_back(static_cast<long>(i));
        }
    }

    void pairs(const pose& p, answer& out) {
        pose_vertices(p);
        const auto& cov = scene_.covering;
        found_.clear();
        for (std::size_t i = 0; i < cov.size(); ++i)
            for (std::size_t j = 0; j < b_.size(); ++j) {
                const point<NT>& u = posed_[j];
                const point<NT>& v = posed_[b_.next(j)];
                const bool meet = distance_ > 0 ? segments_within(cov.start(i), cov.end(i), u, v, d2_)
                                                : segments_intersect(cov.start(i), cov.end(i), u, v);
                if (meet) found_.push_back({scene_.shape.source_edge(i), b_.source_edge(j)});
            }
        std::sort(found_.begin(), found_.end());
        for (const edge_pair& e : found_) {
            out.push_back(static_cast<long>(e.static_edge));
            out.push_back(static_cast<long>(e.moving_edge));
        }
    }

    void containment(const pose& p, answer& out) {
        pose_vertices(p);
        for (std::size_t r = 0; r < b_.ring_count(); ++r)
            out.push_back(static_cast<long>(scene_.areas().locate(posed_[b_.ring_begin(r)])));
        const point<NT> c = rotation_pose(p).apply<NT>(b_.centroid());
        const polygon& as = scene_.shape;
        for (std::size_t r = 0; r < as.ring_count(); ++r)
            out.push_back(static_cast<long>(locate(b_, posed_, c, scene_.covering.start(as.ring_begin(r)))));
    }

private:
    static detector_options options(double distance) {
        detector_options o;
        o.distance = distance;
        return o;
    }

    static point<NT> to_nt(const point<double>& q) {
        return {number_traits<NT>::from_double(q.x), number_traits<NT>::from_double(q.y)};
    }

    void pose_vertices(const pose& p) {
        const rotation_pose t(p);
        for (std::size_t j = 0; j < b_.size(); ++j) posed_[j] = t.apply<NT>(b_.vertex(j));
    }

    static_scene<NT> scene_;
    polygon b_;
    double distance_;
    NT n_, n2_, d2_;
    detector<NT> detector_;
    brute_force_detector<NT> brute_;
    influence_mask mask_;
    std::vector<point<NT>> posed_;
    std::vector<edge_pair> found_;
};

/// Evaluates the decisions in NT; with a Fallback type other than NT, a
/// question whose evaluation in NT raises uncertain_sign (or a scene whose
/// set-up in NT does) is answered again in Fallback: every decision compares
/// through number_traits, so CGAL's intervals raise that too, never CGAL's
/// own Uncertain_conversion_exception. This is the evaluation of the
/// filtered types: evaluator<certified, exact_rational>, as certified_detector
/// does, and evaluator<interval, exact_rational>, as interval_detector does.
template <class NT, class Fallback = NT>
class evaluator {
public:
    static constexpr bool has_fallback = !std::is_same_v<NT, Fallback>;

    evaluator(const polygon& a, const polygon& b, double distance) {
        if constexpr (has_fallback) {
            try {
                primary_.emplace(a, b, distance);
            } catch (const uncertain_sign&) {
                setup_fell_back_ = true;
            }
            fallback_.emplace(a, b, distance);
        } else {
            primary_.emplace(a, b, distance);
        }
    }

    void decide(decision_kind k, const query& q, answer& out) {
        if constexpr (has_fallback) {
            if (primary_) {
                const std::size_t mark = out.size();
                try {
                    primary_->decide(k, q, out);
                    return;
                } catch (const uncertain_sign&) {
                    out.resize(mark);
                }
            }
            ++fallbacks_;
            fallback_->decide(k, q, out);
        } else {
            primary_->decide(k, q, out);
        }
    }

    /// The answer to one question, as a fresh list.
    answer decide(decision_kind k, const query& q) {
        answer out;
        decide(k, q, out);
        return out;
    }

    /// Questions answered in Fallback so far.
    std::size_t fallbacks() const { return fallbacks_; }
    /// Whether the scene could not be set up in NT (every answer then comes from Fallback).
    bool setup_fell_back() const { return setup_fell_back_; }

private:
    std::optional<decision_context<NT>> primary_;
    std::optional<decision_context<Fallback>> fallback_;
    std::size_t fallbacks_ = 0;
    bool setup_fell_back_ = false;
};

/// The exact answer of every decision for one scene.
class reference_decisions {
public:
    reference_decisions(const polygon& a, const polygon& b, double distance)
        : exact_(a, b, distance), witnesses_(a, b, distance, true), collision_(a, b, distance, false) {}

    void decide(decision_kind k, const query& q, answer& out) {
        switch (k) {
        case decision_kind::cone_membership:
        case decision_kind::mask: {
            // Every cone, without the angular index.
            const auto& cov = exact_.scene().covering;
            const point<exact_rational> p{exact_rational(q.at.x), exact_rational(q.at.y)};
            for (std::size_t i = 0; i < cov.size(); ++i)
                if (in_influence_area(cov, i, p)) out.push_back(static_cast<long>(i));
            return;
        }
        case decision_kind::pairs:
            for (const edge_pair& e : witnesses_.collide(q.placement).pairs) {
                out.push_back(static_cast<long>(e.static_edge));
                out.push_back(static_cast<long>(e.moving_edge));
            }
            return;
        case decision_kind::collides:
        case decision_kind::collides_brute_force:
            return out.push_back(collision_.collide(q.placement).collides ? 1 : 0);
        default: return exact_.decide(k, q, out);
        }
    }

    answer decide(decision_kind k, const query& q) {
        answer out;
        decide(k, q, out);
        return out;
    }

private:
    decision_context<exact_rational> exact_;
    cgal_reference witnesses_;
    cgal_reference collision_;
};

/// Query points for the cone decisions about the static polygon A, where the
/// answers are hardest and easiest, in turn:
///   - on a ray from the centroid O through a vertex V (O + t (V - O), t in
///     [0.25, 4], rounded once), and the same point 1 ulp off in x or y;
///   - a vertex itself (on two cone boundaries and on A's boundary), 1 ulp off;
///   - near an edge: a point of the edge moved along its normal by 2^-k times
///     A's size (k in 4..50);
///   - far away: along a ray (t up to 1e6) or in a random direction up to 1e9
///     times A's size.
inline std::vector<point<double>> cone_query_points(const polygon& a, std::size_t count, std::uint64_t seed) {
    std::mt19937_64 gen(seed);
    const auto unit = [&] { return std::ldexp(static_cast<double>(gen() >> 11), -53); };
    const auto index = [&](std::size_t n) { return static_cast<std::size_t>(gen() % n); };
    const auto ulp_off = [&](point<double> p) {
        const double to = (gen() & 1) ? HUGE_VAL : -HUGE_VAL;
        if (gen() & 1)
            p.x = std::nextafter(p.x, to);
        else
            p.y = std::nextafter(p.y, to);
        return p;
    };
    const point<double> o = a.centroid();
    const double size = std::max(bounding_radius(a, o), 1e-300);
    std::vector<point<double>> out;
    out.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        const point<double>& v = a.vertex(index(a.size()));
        switch (k % 7) {
        case 0:
        case 1: {
            const double t = 0.25 + 3.75 * unit();
            const point<double> p{o.x + t * (v.x - o.x), o.y + t * (v.y - o.y)};
            out.push_back(k % 7 == 0 ? p : ulp_off(p));
            break;
        }
        case 2: out.push_back(v); break;
        case 3: out.push_back(ulp_off(v)); break;
        case 4: {
            const std::size_t i = index(a.size());
            const point<double> s = a.vertex(i), e = a.vertex(a.next(i));
            const double t = unit(), h = std::ldexp(size, -4 - static_cast<int>(index(47)));
            const double len = std::max(std::hypot(e.x - s.x, e.y - s.y), 1e-300);
            const double side = (gen() & 1) ? h : -h;
            out.push_back(
                {s.x + t * (e.x - s.x) + side * (e.y - s.y) / len, s.y + t * (e.y - s.y) - side * (e.x - s.x) / len});
            break;
        }
        case 5: {
            const double t = std::pow(10.0, 1 + 5 * unit());
            out.push_back({o.x + t * (v.x - o.x), o.y + t * (v.y - o.y)});
            break;
        }
        default: {
            const double r = size * std::pow(10.0, 1 + 8 * unit());
            const double phi = 6.283185307179586 * unit();
            out.push_back({o.x + r * std::cos(phi), o.y + r * std::sin(phi)});
            break;
        }
        }
    }
    return out;
}

}  // namespace influence2d::verification
