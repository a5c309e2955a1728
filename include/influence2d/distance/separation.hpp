// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The separation distance between A and B posed by q: the distance between
/// the closed regions, the closest features and points, or a witness of
/// their meeting (docs/separation.md). The queries run in any field NT;
/// certified_separation (exact/certified_separation.hpp) is separation in
/// exact rationals rounded to double.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "influence2d/assert.hpp"
#include "influence2d/core/box.hpp"
#include "influence2d/core/feature.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/range_scaling.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/influence/edge_tree.hpp"
#include "influence2d/number/double_word.hpp"
#include "influence2d/number/unit_roundoff.hpp"
#include "influence2d/predicates/distance.hpp"
#include "influence2d/scene/posed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d {

/// The separation of A and B posed by a pose: the distance between their
/// closed regions and where it is attained, or a witness that they meet.
template <class NT>
struct separation_result {
    /// The squared distance between the closed regions; 0 when they meet.
    /// Exact in an exact NT.
    NT squared_distance{};
    /// A's feature: the vertex, edge (by input number) or, for B inside A
    /// without boundary contact, A's interior.
    feature static_feature{};
    /// B's feature, as static_feature.
    feature moving_feature{};
    /// The closest point of A (on static_feature), in A's frame.
    point<NT> static_point;
    /// The closest point of posed B (on moving_feature), in A's frame; equal
    /// to static_point when the regions meet.
    point<NT> moving_point;
    /// The edge pairs whose distance the query evaluated in NT.
    std::size_t evaluated_pairs = 0;
    /// Whether the regions meet (squared_distance is 0).
    bool meet() const { return at_contact(squared_distance); }
};

namespace separation_detail {

/// An edge pair that may realise the distance, with a lower bound of its
/// distance (phase 1). Stored edge numbers.
struct candidate {
    double lower = 0;
    std::uint32_t static_edge = 0, moving_edge = 0;
};

/// The order in which phase 2 evaluates candidates: lower bound, then A's
/// edge, then B's.
inline bool evaluated_before(const candidate& l, const candidate& r) {
    if (l.lower != r.lower) return l.lower < r.lower;
    if (l.static_edge != r.static_edge) return l.static_edge < r.static_edge;
    return l.moving_edge < r.moving_edge;
}

/// What phase 1 keeps between calls (its stack and candidates), so that a
/// query object allocates once.
struct search_space {
    struct entry {
        std::uint32_t s, m;  ///< A's node, B's node
        double lower;        ///< a lower bound of the distance between their edges
    };
    std::vector<entry> stack;
    std::vector<candidate> candidates;                                ///< phase 1's candidates, or
    std::optional<std::pair<std::uint32_t, std::uint32_t>> crossing;  ///< the first pair that certainly crosses
};

/// The trees, polygons and pose of one query, in double.
struct search_input {
    const polygon& a;
    const edge_tree& a_tree;
    const polygon& b;
    const edge_tree& b_tree;
    const rotation_pose& t;  ///< B's pose
    double delta;            ///< posing_error of B's points
};

/// The upper bound of one pair's distance (segment_distance_range), or
/// infinity for no pair: the coherence seed.
template <class Approx>
double pair_upper(const search_input& in, Approx& approx, std::optional<std::pair<std::uint32_t, std::uint32_t>> pair) {
    if (!pair || pair->first >= in.a.size() || pair->second >= in.b.size()) return HUGE_VAL;
    const std::size_t e = pair->first, f = pair->second;
    return segment_distance_range(in.a.vertex(e), in.a.vertex(in.a.next(e)), approx[f], approx[in.b.next(f)], in.delta)
        .upper;
}

/// Phase 1: the branch and bound over A's edge tree (A's frame) and B's
/// (its nodes' circles posed by the pose in double), in double with proven
/// bounds. Returns U, an upper bound of the distance between the
/// boundaries, and leaves in space.candidates every edge pair whose lower
/// bound is at most U, in the order evaluated_before: among them every pair
/// at the least distance. Stops at the first edge pair that certainly
/// crosses (segments_must_cross), left in space.crossing, returning 0: the
/// boundaries meet there. `upper` is a known upper bound (a seed) or
/// infinity. The order of the search depends on the pose alone, not on
/// `upper` (which only prunes node pairs and edge pairs farther than it, and
/// a crossing pair is never farther): the crossing found is the same
/// whatever the seed.
///
///   stack <- (A's root, B's root, lower bound)
///   while stack: (s, m, L) <- pop
///       L > U: prune (U may have dropped since the push)
///       both leaves: for each edge pair whose boxes are within U and
///       that no line proves farther than U (segments_apart_beyond):
///           certainly crossing: that pair; stop
///           [lo, hi] <- segment_distance_range; U <- min(U, hi)
///           lo <= U: candidate
///       else split the node of larger radius (the inner one): each child
///       pair's lower bound is node_gap_lower (A's box, B's posed circle);
///       push those <= U, the farther first (the nearer is searched first)
///   keep the candidates with lower bound <= U, sorted
template <class Approx>
double search_pairs(const search_input& in, Approx& approx, double upper, search_space& space) {
    space.stack.clear();
    space.candidates.clear();
    space.crossing.reset();
    const edge_tree &ta = in.a_tree, &tb = in.b_tree;
    if (ta.node_count() == 0 || tb.node_count() == 0) return upper;
    const double spread = posing_spread * in.delta * (1 + bound_rounding);
    const auto posed = [&](const edge_tree::node& m) { return in.t.apply<double>(m.center); };
    space.stack.push_back(
        {0, 0, node_gap_lower(ta.node_at(0).bounds, posed(tb.node_at(0)), tb.node_at(0).radius, in.delta)});
    while (!space.stack.empty()) {
        const search_space::entry p = space.stack.back();
        space.stack.pop_back();
        if (p.lower > upper) continue;
        const edge_tree::node &s = ta.node_at(p.s), &m = tb.node_at(p.m);
        if (s.count != 0 && m.count != 0) {
            for (std::uint32_t j = m.first; j < m.first + m.count; ++j) {
                const std::uint32_t f = tb.edge_at(j);
                const point<double>&u = approx[f], &v = approx[in.b.next(f)];
                box fb;
                fb.add(u);
                fb.add(v);
                if (box_gap_lower(s.bounds, fb) - spread > upper) continue;
                for (std::uint32_t i = s.first; i < s.first + s.count; ++i) {
                    if (box_gap_lower(ta.edge_box_at(i), fb) - spread > upper) continue;
                    const std::uint32_t e = ta.edge_at(i);
                    const point<double>&a0 = in.a.vertex(e), &a1 = in.a.vertex(in.a.next(e));
                    // Separated by a line: farther than U.
                    if (segments_apart_beyond(a0, a1, u, v, upper, in.delta)) continue;
                    if (segments_must_cross(a0, a1, u, v, in.delta)) {
                        space.crossing = std::make_pair(e, f);
                        return 0;
                    }
                    const distance_range r = segment_distance_range(a0, a1, u, v, in.delta);
                    upper = std::min(upper, r.upper);
                    if (r.lower <= upper) space.candidates.push_back({r.lower, e, f});
                }
            }
            continue;
        }
        search_space::entry near, far;
        if (s.count != 0 || (m.count == 0 && m.radius >= s.radius)) {
            const edge_tree::node &m0 = tb.node_at(m.first), &m1 = tb.node_at(m.first + 1);
            near = {p.s, m.first, node_gap_lower(s.bounds, posed(m0), m0.radius, in.delta)};
            far = {p.s, m.first + 1, node_gap_lower(s.bounds, posed(m1), m1.radius, in.delta)};
        } else {
            const point<double> c = posed(m);
            near = {s.first, p.m, node_gap_lower(ta.node_at(s.first).bounds, c, m.radius, in.delta)};
            far = {s.first + 1, p.m, node_gap_lower(ta.node_at(s.first + 1).bounds, c, m.radius, in.delta)};
        }
        if (far.lower < near.lower) std::swap(near, far);
        if (far.lower <= upper) space.stack.push_back(far);
        if (near.lower <= upper) space.stack.push_back(near);
    }
    auto& cs = space.candidates;
    cs.erase(std::remove_if(cs.begin(), cs.end(), [upper](const candidate& c) { return !(c.lower <= upper); }),
             cs.end());
    std::sort(cs.begin(), cs.end(), evaluated_before);
    return upper;
}

/// The relative widening of number_traits::to_double of an exact squared
/// distance in phase 2's stopping rule: to_double is "a near double" (for
/// CGAL's rationals within an ulp); 2^-40 takes it as within 2^-40 of the
/// value.
inline constexpr double to_double_widening = 0x1p-40;
/// The absolute widening of the same: a squared distance whose double
/// underflows (below 2^-1074, as small as 2^-2148) is below it, so its root is
/// below 2^-500; for distances above 2^-500 the floor changes nothing.
inline constexpr long double squared_floor = 0x1p-1000L;

/// An upper bound, in double, of the square root of the squared distance x
/// (for phase 2's stopping rule). A double word is below hi + |lo| + its
/// error, a sum rounded at most twice (2^-52 covers both).
template <class NT>
double upper_distance(const NT& x) {
    if constexpr (std::is_same_v<NT, double_word>) {
        return upper_sqrt((static_cast<long double>(x.hi()) + std::fabs(x.lo()) + x.error()) *
                              (1 + 2 * static_cast<long double>(unit_roundoff)) +
                          squared_floor);
    } else {
        const double d = number_traits<NT>::to_double(x);
        return upper_sqrt(static_cast<long double>(d) * (1 + to_double_widening) + squared_floor);
    }
}

/// The pair phase 2 chose, with its closest points.
template <class NT>
struct chosen_pair {
    segment_pair_closest<NT> closest;
    std::uint32_t static_edge = 0, moving_edge = 0;
    bool found = false;
};

/// The feature of the stored edge e that the part `part` of it is, as a key:
/// twice the stored vertex (start: e, end: the next one), or twice e plus 1
/// for the edge's interior. Two pairs whose closest points have the same
/// keys on both sides join the same vertices or edges: at the same distance.
inline std::uint64_t feature_key(const polygon& shape, std::uint32_t e, segment_part part) {
    switch (part) {
    case segment_part::start: return 2 * std::uint64_t{e};
    case segment_part::end: return 2 * std::uint64_t{shape.next(e)};
    default: return 2 * std::uint64_t{e} + 1;
    }
}

/// Phase 2: the pair that certainly crosses, if phase 1 found one (its
/// distance is 0). Otherwise the candidates evaluated in NT (evaluate(e,
/// f), the pair's closest_between_segments) in the order evaluated_before,
/// until the next
/// lower bound exceeds the best distance found (upper_distance); the least
/// squared distance wins, and among equal ones the least (A's edge, B's
/// edge). Every pair at the least distance has a lower bound at most that
/// distance, so all of them are evaluated and the choice does not depend on
/// how phase 1 found them. A pair at distance 0 ends the loop: every pair at
/// distance 0 has lower bound 0 and so comes, in edge order, before any
/// other. Two pairs whose closest points are the same vertices (the edges
/// about a vertex of A against those about a vertex of B: feature_key) are
/// at equal distance without a comparison, which a filtered NT could not
/// make. `evaluated` counts the pairs evaluated.
template <class NT, class Evaluate>
chosen_pair<NT> closest_candidate(const search_input& in, const search_space& space, Evaluate&& evaluate,
                                  std::size_t& evaluated) {
    chosen_pair<NT> best;
    if (space.crossing) {
        ++evaluated;
        best.static_edge = space.crossing->first;
        best.moving_edge = space.crossing->second;
        best.closest = evaluate(best.static_edge, best.moving_edge);
        best.found = true;
        return best;
    }
    const std::vector<candidate>& cs = space.candidates;
    double reach = HUGE_VAL;
    for (const candidate& c : cs) {
        if (best.found && c.lower > reach) break;
        ++evaluated;
        const std::uint32_t e = c.static_edge, f = c.moving_edge;
        segment_pair_closest<NT> d = evaluate(e, f);
        const auto same_features = [&] {
            return feature_key(in.a, e, d.first_part) == feature_key(in.a, best.static_edge, best.closest.first_part) &&
                   feature_key(in.b, f, d.second_part) == feature_key(in.b, best.moving_edge, best.closest.second_part);
        };
        const int order = !best.found ? -1 : same_features() ? 0 : compare_squared(d.squared, best.closest.squared);
        if (order < 0 || (order == 0 && (e < best.static_edge || (e == best.static_edge && f < best.moving_edge)))) {
            best.closest = std::move(d);
            best.static_edge = e;
            best.moving_edge = f;
            best.found = true;
            reach = upper_distance(best.closest.squared);
        }
        if (at_contact(best.closest.squared)) break;
    }
    return best;
}

/// A pair phase 2 chose in double, with the parts of its closest points and
/// bounds of its distance.
struct settled_pair {
    settled_closest closest;
    std::uint32_t static_edge = 0, moving_edge = 0;
};

/// The distance of a settled pair (stored edges e of A and f of B, apart)
/// as a point-to-line distance on the points as given, when one of its
/// closest points lies inside an edge; none when both are ends.
inline std::optional<point_line_distance> pair_point_line(const search_input& in, std::uint32_t e, std::uint32_t f,
                                                          const settled_closest& c) {
    const auto end = [](const polygon& p, std::uint32_t edge, segment_part part) {
        return p.vertex(part == segment_part::start ? edge : p.next(edge));
    };
    if (c.second_part == segment_part::interior && c.first_part != segment_part::interior)
        return point_line_distance{end(in.a, e, c.first_part), in.b.vertex(f), in.b.vertex(in.b.next(f)), false};
    if (c.first_part == segment_part::interior && c.second_part != segment_part::interior)
        return point_line_distance{end(in.b, f, c.second_part), in.a.vertex(e), in.a.vertex(in.a.next(e)), true};
    return std::nullopt;
}

/// Whether two settled pairs whose closest points are vertices (no part
/// inside an edge: pair_point_line gives none) are at one distance by their
/// vertices alone: A's vertex less B's the same offset in both, on the
/// points as given (same_offset; B translated keeps it).
inline bool pair_vertices_offset_alike(const search_input& in, std::uint32_t e, std::uint32_t f,
                                       const settled_closest& c, const settled_pair& other) {
    const auto end = [](const polygon& p, std::uint32_t edge, segment_part part) {
        return p.vertex(part == segment_part::start ? edge : p.next(edge));
    };
    for (const segment_part part : {c.first_part, c.second_part, other.closest.first_part, other.closest.second_part})
        if (part == segment_part::interior) return false;
    return same_offset(end(in.a, e, c.first_part), end(in.b, f, c.second_part),
                       end(in.a, other.static_edge, other.closest.first_part),
                       end(in.b, other.moving_edge, other.closest.second_part));
}

/// Phase 2 decided in double, for candidates and no pair certainly crossing:
/// the pair closest_candidate chooses, when the bounds settle it, or nothing.
/// Each candidate in the order evaluated_before is settled in double
/// (settled_closest_between: its bounds and the parts of its closest points);
/// against the best so far it is certainly nearer (its upper bound below the
/// best's lower bound), certainly farther, or at the same distance by its
/// points: the same features (the same points), or, when B's pose is a
/// translation, a point-to-line distance equal to the best's by
/// equal_point_line_distances (two edges of a shared border moved apart
/// are parallel: its vertices all lie at one distance from the other
/// polygon's edge); the least (A's edge, B's edge) is kept, as
/// closest_candidate keeps it. Anything else is in doubt. The loop stops
/// where closest_candidate's does, at a lower bound beyond the best's upper
/// bound. An exact NT then evaluates the chosen pair alone, from the parts
/// of its closest points (closest_at_parts), instead of every pair the
/// bounds leave near the best.
///
///   for each candidate c in order:
///       c.lower > best's upper bound: stop
///       settle c in double (parallel edges, and the parts of closest
///       points the bounds leave in doubt, known exactly when B is
///       translated: translated_part); in doubt: nothing
///       no best, or c certainly nearer: best <- c
///       c certainly farther: next
///       same features as best, or (translated) an equal point-to-line
///       distance: best <- the least of the two pairs
///       else: nothing
template <class Approx>
std::optional<settled_pair> settled_candidate(const search_input& in, Approx& approx, const search_space& space) {
    const bool translated = in.t.c == 1 && in.t.s == 0;
    std::optional<settled_pair> best;
    for (const candidate& c : space.candidates) {
        if (best && c.lower > best->closest.upper) break;
        const std::uint32_t e = c.static_edge, f = c.moving_edge;
        const point<double>&a0 = in.a.vertex(e), &a1 = in.a.vertex(in.a.next(e));
        const std::size_t f1 = in.b.next(f);
        const point<double>&b0 = in.b.vertex(f), &b1 = in.b.vertex(f1), t{in.t.tx, in.t.ty};
        const std::optional<settled_closest> d = settled_closest_between(
            a0, a1, approx[f], approx[f1], in.delta,
            [&] { return translated && exact_cross_sign(a0, a1, b0, b1) == 0; },
            [&](int k) -> std::optional<segment_part> {
                if (!translated) return std::nullopt;
                if (k < 2) return translated_part(k == 0 ? a0 : a1, b0, b1, t, true);
                return translated_part(k == 2 ? b0 : b1, a0, a1, t, false);
            },
            [&](std::pair<segment_part, segment_part> x, std::pair<segment_part, segment_part> y) {
                const auto at = [](const point<double>& s0, const point<double>& s1, segment_part part) {
                    return part == segment_part::start ? s0 : s1;
                };
                return translated && same_offset(at(a0, a1, x.first), at(b0, b1, x.second), at(a0, a1, y.first),
                                                 at(b0, b1, y.second));
            });
        if (!d) return std::nullopt;
        if (!best || d->upper < best->closest.lower) {
            best = settled_pair{*d, e, f};
            continue;
        }
        if (d->lower > best->closest.upper) continue;
        const bool same_features =
            feature_key(in.a, e, d->first_part) == feature_key(in.a, best->static_edge, best->closest.first_part) &&
            feature_key(in.b, f, d->second_part) == feature_key(in.b, best->moving_edge, best->closest.second_part);
        if (!same_features) {
            if (!translated) return std::nullopt;
            const std::optional<point_line_distance> x = pair_point_line(in, e, f, *d),
                                                     y = pair_point_line(in, best->static_edge, best->moving_edge,
                                                                         best->closest);
            const bool equal = x && y ? equal_point_line_distances(*x, *y)
                                      : !x && !y && pair_vertices_offset_alike(in, e, f, *d, *best);
            if (!equal) return std::nullopt;
        }
        if (e < best->static_edge || (e == best->static_edge && f < best->moving_edge)) best = settled_pair{*d, e, f};
    }
    return best;
}

/// Phase 2 in an exact or filtered NT without comparing NT values: the pair
/// phase 1 found certainly crossing, at its crossing point (crossing_closest:
/// no sign taken again), or the pair settled in double (settled_candidate)
/// with its closest points evaluated from their parts (closest_at_parts:
/// only the ends these need are asked of a_vertex and b_vertex). Not found
/// when the choice is in doubt. `evaluated` counts the pair evaluated.
template <class NT, class Approx, class AVertex, class BVertex>
chosen_pair<NT> settled_choice(const search_input& in, Approx& approx, const search_space& space, AVertex& a_vertex,
                               BVertex& b_vertex, std::size_t& evaluated) {
    chosen_pair<NT> best;
    std::optional<std::pair<std::uint32_t, std::uint32_t>> pair = space.crossing;
    std::optional<settled_pair> settled;
    if (!pair) {
        settled = settled_candidate(in, approx, space);
        if (!settled) return best;
        pair = std::make_pair(settled->static_edge, settled->moving_edge);
    }
    const std::uint32_t e = pair->first, f = pair->second;
    const std::size_t e2 = in.a.next(e), f2 = in.b.next(f);
    ++evaluated;
    if (!settled) {
        best.closest = crossing_closest(a_vertex(e), a_vertex(e2), b_vertex(f), b_vertex(f2));
    } else {
        best.closest = closest_at_parts<NT>(settled->closest.first_part, settled->closest.second_part, [&](int i) {
            return i == 0 ? a_vertex(e) : i == 1 ? a_vertex(e2) : b_vertex(i == 2 ? f : f2);
        });
    }
    best.static_edge = e;
    best.moving_edge = f;
    best.found = true;
    return best;
}

/// The closest points of A's edge e and B's edge f in NT, a_vertex(i) and
/// b_vertex(j) giving A's vertex and B's posed vertex in NT: in a floating
/// NT directly; in another, with the choice among the candidates made in
/// double where the bounds settle it (the filtered
/// closest_between_segments, on B's vertices posed in double by `approx`).
template <class NT, class Approx, class AVertex, class BVertex>
segment_pair_closest<NT> pair_closest(const search_input& in, Approx& approx, AVertex& a_vertex, BVertex& b_vertex,
                                      std::uint32_t e, std::uint32_t f) {
    const std::size_t e2 = in.a.next(e), f2 = in.b.next(f);
    if constexpr (number_traits<NT>::category == number_category::floating) {
        return closest_between_segments<NT>(a_vertex(e), a_vertex(e2), b_vertex(f), b_vertex(f2));
    } else {
        return closest_between_segments<NT>(in.a.vertex(e), in.a.vertex(e2), approx[f], approx[f2], in.delta,
                                            a_vertex(e), a_vertex(e2), b_vertex(f), b_vertex(f2));
    }
}

/// A ring's first vertex lying in the other polygon's closed region: B's
/// (moving) or A's.
struct inside_vertex {
    bool moving = true;
    std::size_t vertex = 0;  ///< stored number
};

/// Phase 3, for boundaries known apart: the first vertex of every ring of B,
/// then of A, located in the other polygon (b_in_a(j), a_in_b(i) give the
/// location); the first not outside. A vertex outside the other's window (its
/// box, grown by the rounding of the double positions) is outside without a
/// locate. Why one vertex per ring decides: detect/containment.hpp.
template <class BApprox, class BInA, class AInB>
std::optional<inside_vertex> ring_vertex_inside(const polygon& a, const polygon& b, const box& a_window,
                                                const box& b_window, BApprox& b_approx, BInA&& b_in_a, AInB&& a_in_b) {
    for (std::size_t r = 0; r < b.ring_count(); ++r) {
        const std::size_t j = b.ring_begin(r);
        const point<double>& v = b_approx[j];
        if (std::isfinite(v.x + v.y) && !a_window.contains(v)) continue;
        if (b_in_a(j) != location::outside) return inside_vertex{true, j};
    }
    for (std::size_t r = 0; r < a.ring_count(); ++r) {
        const std::size_t i = a.ring_begin(r);
        if (!b_window.contains(a.vertex(i))) continue;
        if (a_in_b(i) != location::outside) return inside_vertex{false, i};
    }
    return std::nullopt;
}

/// The box holding posed B: its tree's root circle, its centre posed in
/// double, grown by the pose's scale and the posing error. Everything when the
/// centre is not finite.
inline box posed_window(const search_input& in) {
    const point<double> c = in.t.apply<double>(in.b_tree.root_center());
    const double r =
        in.b_tree.root_radius() * (1 + node_gap_rounding) + posing_spread * in.delta * (1 + bound_rounding);
    if (!std::isfinite(c.x + c.y + r)) return box{-HUGE_VAL, -HUGE_VAL, HUGE_VAL, HUGE_VAL};
    return box{c.x - r, c.y - r, c.x + r, c.y + r};
}

/// A's window for B's vertices posed in double: A's box grown by their
/// posing error.
inline box static_window(const search_input& in) {
    return in.a.bounds().inflated(posing_spread * in.delta * (1 + bound_rounding));
}

/// The feature of the point at `part` of the stored edge e.
inline feature edge_feature(const polygon& shape, std::size_t e, segment_part part) {
    switch (part) {
    case segment_part::start: return {feature_kind::vertex, input_vertex(shape, e)};
    case segment_part::end: return {feature_kind::vertex, input_vertex(shape, shape.next(e))};
    default: return {feature_kind::edge, shape.source_edge(e)};
    }
}

/// The result of the chosen pair.
template <class NT>
separation_result<NT> pair_result(const polygon& a, const polygon& b, const chosen_pair<NT>& p) {
    separation_result<NT> r;
    r.squared_distance = p.closest.squared;
    r.static_feature = edge_feature(a, p.static_edge, p.closest.first_part);
    r.moving_feature = edge_feature(b, p.moving_edge, p.closest.second_part);
    r.static_point = p.closest.on_first;
    r.moving_point = p.closest.on_second;
    return r;
}

/// The result of a ring's vertex inside the other region, at `at`.
template <class NT>
separation_result<NT> inside_result(const polygon& a, const polygon& b, const inside_vertex& v, const point<NT>& at) {
    separation_result<NT> r;
    r.squared_distance = number_traits<NT>::from_double(0);
    const feature interior{feature_kind::interior, 0};
    if (v.moving) {
        r.static_feature = interior;
        r.moving_feature = {feature_kind::vertex, input_vertex(b, v.vertex)};
    } else {
        r.static_feature = {feature_kind::vertex, input_vertex(a, v.vertex)};
        r.moving_feature = interior;
    }
    r.static_point = at;
    r.moving_point = at;
    return r;
}

/// B's vertices posed in double by a posed_polygon, as phase 1 and the
/// windows read them (approx[j], all()).
template <class NT>
class posed_doubles {
public:
    explicit posed_doubles(posed_polygon<NT>& b) : b_(&b) {}
    /// Vertex j posed in double.
    const point<double>& operator[](std::size_t j) { return b_->approximate_now(j); }
    /// Every vertex posed in double.
    const std::vector<point<double>>& all() { return b_->approximate_all(); }

private:
    posed_polygon<NT>* b_;
};

/// What one query in NT keeps between frames: B posed (in double and in NT,
/// each vertex on first use), phase 1's space, the last frame's closest pair.
template <class NT>
struct workspace {
    explicit workspace(std::shared_ptr<const moving_scene<NT>> b) : b_posed(std::move(b)), approx(b_posed) {}
    workspace(const workspace&) = delete;
    workspace& operator=(const workspace&) = delete;

    posed_polygon<NT> b_posed;
    posed_doubles<NT> approx;  ///< b_posed's vertices in double
    search_space space;
    std::optional<std::pair<std::uint32_t, std::uint32_t>> last;  ///< the last frame's chosen pair
    std::size_t evaluated = 0;                                    ///< pairs evaluated in NT by the last query

    /// A new frame posed by t.
    void place(const rotation_pose& t) { b_posed.place(t); }
    /// B's vertex j posed in NT (in double: the filters' value, the same).
    const point<NT>& posed(std::size_t j) {
        if constexpr (std::is_same_v<NT, double>) {
            return b_posed.approximate_now(j);
        } else {
            return b_posed.vertex(j);
        }
    }
};

/// A's side of a query in NT: its vertices in NT (one, or all for a
/// locate), its locator for B's points. Prepared (a static_scene: its
/// covering's vertices and its cone index) or from the polygon alone
/// (vertices converted on demand, Feito's test over all of them).
template <class NT>
class static_side {
public:
    /// From the prepared scene.
    explicit static_side(const static_scene<NT>& a) : shape_(a.shape), scene_(&a) {}
    /// From the polygon alone.
    explicit static_side(const polygon& a) : shape_(a) {}

    /// Whether A is prepared (its cone index locates points).
    bool prepared() const { return scene_ != nullptr; }
    /// Vertex i in NT.
    point<NT> vertex(std::size_t i) const {
        if (scene_) return scene_->covering.start(i);
        return to_point<NT>(shape_.vertex(i));
    }
    /// Where p lies in A's closed region (exact when NT is).
    location locate_point(const point<NT>& p) {
        if (scene_) return scene_->areas().locate(p);
        if constexpr (std::is_same_v<NT, double>) {
            return locate(shape_, shape_.vertices(), shape_.centroid(), p);
        } else {
            if (all_.empty())
                for (std::size_t i = 0; i < shape_.size(); ++i) all_.push_back(vertex(i));
            return locate(shape_, all_, to_point<NT>(shape_.centroid()), p);
        }
    }

private:
    const polygon& shape_;
    const static_scene<NT>* scene_ = nullptr;
    std::vector<point<NT>> all_;
};

/// Phase 3 in NT: a ring's vertex inside the other region (ring_vertex_inside),
/// B's vertices given in double by `approx` and in NT by the posed polygon
/// `b` (the query's own), A's by `side`. In a floating NT the locations are
/// its own. In an exact or filtered NT they are exact and mostly settled in
/// double: B's vertices posed in double lie within in.delta of their exact
/// places on each coordinate and A's are exact, so a point is located by
/// its crossings (locate_by_crossings, the same region as Feito's test) with
/// that slack, evaluating in NT only the edges whose crossing the doubles
/// leave in doubt; B's vertex in a prepared A through its cone index in NT.
template <class NT, class Approx>
std::optional<inside_vertex> inside_in(static_side<NT>& side, const search_input& in, Approx& approx,
                                       posed_polygon<NT>& b) {
    const auto b_vertex = [&](std::size_t j) -> const point<NT>& {
        if constexpr (std::is_same_v<NT, double>) {
            return b.approximate_now(j);
        } else {
            return b.vertex(j);
        }
    };
    if constexpr (number_traits<NT>::category != number_category::floating) {
        const auto a_vertex = [&](std::size_t i) { return side.vertex(i); };
        return ring_vertex_inside(
            in.a, in.b, static_window(in), posed_window(in), approx,
            [&](std::size_t j) {
                if (side.prepared()) return side.locate_point(b_vertex(j));
                return locate_by_crossings(in.a, in.a.vertices(), {}, 0, approx[j], in.delta, b_vertex(j), a_vertex);
            },
            [&](std::size_t i) {
                return locate_by_crossings(in.b, approx.all(), {}, 0, in.a.vertex(i), in.delta, side.vertex(i),
                                           b_vertex);
            });
    } else {
        std::optional<point<NT>> b_origin;
        return ring_vertex_inside(
            in.a, in.b, static_window(in), posed_window(in), approx,
            [&](std::size_t j) { return side.locate_point(b_vertex(j)); },
            [&](std::size_t i) {
                if (!b_origin) b_origin = in.t.apply<NT>(in.b.centroid());
                if constexpr (std::is_same_v<NT, double>) {
                    return locate(in.b, b.approximate_all(), *b_origin, side.vertex(i));
                } else {
                    return locate(in.b, b.vertices(), *b_origin, side.vertex(i));
                }
            });
    }
}

/// The query in NT on A (its side and tree) and B (its tree, scale), for
/// the pose t: phase 1, phase 2, and phase 3 when the boundaries are apart.
///
///   U <- the last frame's pair re-evaluated at this pose (or infinity)
///   phase 1: candidates, or a pair certainly crossing <- search_pairs
///   phase 2: that pair; or, in an exact or filtered NT, the least
///       candidate settled in double (settled_candidate), its closest points
///       evaluated in NT from their parts; or the least candidate in NT
///       (closest_candidate)
///   distance 0: the regions meet at that pair's common point
///   phase 3: a ring's vertex inside the other region: they meet there
///   else: the distance is the pair's
template <class NT>
separation_result<NT> separate(static_side<NT>& side, const search_input& in, workspace<NT>& w) {
    w.place(in.t);
    const auto b_vertex = [&](std::size_t j) -> const point<NT>& { return w.posed(j); };
    const auto a_vertex = [&](std::size_t i) { return side.vertex(i); };
    search_pairs(in, w.approx, pair_upper(in, w.approx, w.last), w.space);
    w.evaluated = 0;
    chosen_pair<NT> best;
    if constexpr (number_traits<NT>::category != number_category::floating)
        best = settled_choice<NT>(in, w.approx, w.space, a_vertex, b_vertex, w.evaluated);
    if (!best.found)
        best = closest_candidate<NT>(
            in, w.space,
            [&](std::uint32_t e, std::uint32_t f) { return pair_closest<NT>(in, w.approx, a_vertex, b_vertex, e, f); },
            w.evaluated);
    INFLUENCE2D_ASSERT(best.found, "phase 1 left no candidate");
    w.last = std::make_pair(best.static_edge, best.moving_edge);
    if (at_contact(best.closest.squared)) {
        separation_result<NT> r = pair_result(in.a, in.b, best);
        r.evaluated_pairs = w.evaluated;
        return r;
    }
    const std::optional<inside_vertex> inside = inside_in(side, in, w.approx, w.b_posed);
    separation_result<NT> r =
        inside ? inside_result<NT>(in.a, in.b, *inside,
                                   inside->moving ? b_vertex(inside->vertex) : a_vertex(inside->vertex))
               : pair_result(in.a, in.b, best);
    r.evaluated_pairs = w.evaluated;
    return r;
}

/// The separation of a query answered on its input scaled by 2^k (NT float,
/// double or long double; core/range_scaling.hpp), in the input's units:
/// the points scaled by 2^-k, the squared distance by 2^-2k. Throws
/// std::range_error when that squared distance lies beyond NT's range
/// (overflows, or underflows to 0 for regions apart): NT cannot hold it.
template <class NT>
separation_result<NT> scaled_back(separation_result<NT> r, int k) {
    const NT d2 = std::ldexp(r.squared_distance, -2 * k);
    if (std::isinf(d2) || (d2 == 0 && r.squared_distance != 0))
        throw std::range_error(std::string("separation: the squared distance, about 2^") +
                               std::to_string(std::ilogb(r.squared_distance) - 2 * k) + ", lies beyond the range of " +
                               number_traits<NT>::name +
                               "; certified_separation or an exact number type answers this query");
    r.squared_distance = d2;
    r.static_point = {std::ldexp(r.static_point.x, -k), std::ldexp(r.static_point.y, -k)};
    r.moving_point = {std::ldexp(r.moving_point.x, -k), std::ldexp(r.moving_point.y, -k)};
    return r;
}

}  // namespace separation_detail

/// The separation of A and of B posed by q, from prepared polygons (their
/// lazily built edge trees, and A's cone index when a point of B must be
/// located): the squared distance between the closed regions, the closest
/// features and points, or, when the regions meet, a witness (below). Exact
/// in an exact field NT (exact_rational): the squared distance, the features
/// and the points are the true ones; in a floating NT (float, double, long
/// double, quad) they are rounded: the distance is within
/// 2^-40 (|A| + |B| + |tx| + |ty|) of the exact one for double (|P| the
/// largest absolute coordinate of P; docs/separation.md derives it).
///
/// The features realise the distance: static_point lies on static_feature,
/// moving_point on posed B's moving_feature, and their squared distance is
/// squared_distance. When several feature pairs do, the one of the least
/// stored (A's edge, B's edge) pair is reported; when some edge pairs
/// certainly cross (their bounds in double prove it), the first of them the
/// search meets, in an order that depends on the pose alone. So every query
/// in an exact NT (this one, the one on polygons, separation_query,
/// certified_separation) names the same features. When the regions meet: a
/// vertex or edge of each sharing a point when the boundaries meet (a
/// vertex of one on the other,
/// or two edges crossing at a rational point); otherwise one contains a ring
/// of the other, and the witness is that ring's first vertex (its feature
/// vertex) and the other's interior (feature_kind::interior), both points
/// that vertex. Throws invalid_input for a pose with a NaN or infinite
/// component.
///
/// Cost: the branch and bound visits the node pairs that may hold the
/// closest edges (about log n log m near a single closest pair) and
/// evaluates in NT the few pairs its bounds cannot separate; a pose without
/// boundary contact within the polygons' boxes adds the location of one
/// vertex per ring (docs/separation.md).
template <class NT>
separation_result<NT> separation(const static_scene<NT>& a, const moving_scene<NT>& b, const pose& q) {
    const rotation_pose t(q);
    // (b outlives the query: a pointer that does not own it.)
    separation_detail::workspace<NT> w(std::shared_ptr<const moving_scene<NT>>(std::shared_ptr<void>(), &b));
    separation_detail::static_side<NT> side(a);
    const separation_detail::search_input in{a.shape,  a.tree(), b.shape,
                                             b.tree(), t,        posing_error(b.scale, q.tx, q.ty)};
    return separation_detail::separate(side, in, w);
}

/// The separation of A and of B posed by q (as the overload on prepared
/// polygons), from the polygons alone: it builds both edge trees (O(n log n
/// + m log m)) and locates points by their crossings of the polygon's edges
/// (in an exact or filtered NT settled in double, in NT only for an edge in
/// doubt: inside_in). In float, double or long double, a query whose
/// largest coordinate lies outside NT's safe window is answered on its
/// input scaled by a power of two, its lengths scaled back
/// (core/range_scaling.hpp). Throws invalid_input for an empty polygon, one
/// beyond NT's range, or a pose with a NaN or infinite component, and
/// std::range_error when the squared distance lies beyond NT's range.
template <class NT>
separation_result<NT> separation(const polygon& a, const polygon& b, const pose& q) {
    accepted_polygon<NT>(a, "static");
    accepted_polygon<NT>(b, "moving");
    const rotation_pose t(q);
    if constexpr (scaled_into_range_v<NT>) {
        if (const int k = range_shift<NT>(a, b, q))
            return separation_detail::scaled_back(
                separation<NT>(a.scaled_by_power_of_two(k), b.scaled_by_power_of_two(k), scaled_by_power_of_two(q, k)),
                k);
    }
    const edge_tree ta(a), tb(b);
    separation_detail::workspace<NT> w(prepare_moving<NT>(b));
    separation_detail::static_side<NT> side(a);
    const double scale = w.b_posed.scene().scale;
    const separation_detail::search_input in{a, ta, b, tb, t, posing_error(scale, q.tx, q.ty)};
    return separation_detail::separate(side, in, w);
}

/// Many poses of one pair: the prepared polygons are kept (and may be shared
/// with detectors and other queries, in any number of threads), and each
/// query starts its search from the last one's closest edge pair, evaluated
/// at the new pose: for poses close to each other it bounds the search at
/// once. One object per thread (it keeps the frame's state). Answers as
/// separation() on the prepared polygons, exactly so in an exact NT.
template <class NT>
class separation_query {
public:
    /// Prepares A and B (prepare_static, prepare_moving). In float, double
    /// or long double, polygons whose largest coordinate lies outside NT's safe
    /// window are prepared scaled by a power of two 2^k, each pose's
    /// translation with them, and the answers' lengths scaled back
    /// (core/range_scaling.hpp; std::range_error for a squared distance
    /// beyond NT's range). Throws invalid_input for an empty polygon or one
    /// beyond NT's range.
    separation_query(const polygon& static_polygon, const polygon& moving_polygon)
        : separation_query(range_shift<NT>(accepted_polygon<NT>(static_polygon, "static"),
                                           accepted_polygon<NT>(moving_polygon, "moving")),
                           static_polygon, moving_polygon) {}

    /// On prepared polygons, shared. Throws invalid_input for a null pointer.
    separation_query(std::shared_ptr<const static_scene<NT>> static_polygon,
                     std::shared_ptr<const moving_scene<NT>> moving_polygon)
        : a_(checked(std::move(static_polygon), "static")),
          b_(checked(std::move(moving_polygon), "moving")),
          w_(b_),
          side_(*a_) {}

    /// The separation at pose q (separation()). Throws invalid_input for a
    /// pose with a NaN or infinite component.
    separation_result<NT> operator()(const pose& q) {
        if constexpr (scaled_into_range_v<NT>) {
            if (shift_ != 0) return separation_detail::scaled_back(at(scaled_by_power_of_two(q, shift_)), shift_);
        }
        return at(q);
    }

    /// The number of edge pairs the last query evaluated in NT.
    std::size_t evaluated_pairs() const { return w_.evaluated; }

private:
    /// The query on polygons scaled by 2^shift.
    separation_query(int shift, const polygon& static_polygon, const polygon& moving_polygon)
        : separation_query(prepare_static<NT>(static_polygon, shift), prepare_moving<NT>(moving_polygon, shift)) {
        shift_ = shift;
    }

    /// The separation at q, in the prepared polygons' units.
    separation_result<NT> at(const pose& q) {
        const rotation_pose t(q);
        const separation_detail::search_input in{a_->shape,  a_->tree(), b_->shape,
                                                 b_->tree(), t,          posing_error(b_->scale, q.tx, q.ty)};
        return separation_detail::separate(side_, in, w_);
    }

    template <class Scene>
    static std::shared_ptr<const Scene> checked(std::shared_ptr<const Scene> s, const char* which) {
        if (!s)
            throw invalid_input(std::string("separation_query: no prepared ") + which + " polygon (a null pointer)");
        return s;
    }

    std::shared_ptr<const static_scene<NT>> a_;
    std::shared_ptr<const moving_scene<NT>> b_;
    separation_detail::workspace<NT> w_;
    separation_detail::static_side<NT> side_;
    int shift_ = 0;  ///< the polygons and poses scaled by 2^shift_
};

/// The distance as a double from a squared distance. In an exact NT the
/// squared distance is first rounded to the nearest double (scaled_nearest:
/// relative error at most 2^-53, whatever its magnitude), whose root is then
/// rounded once: the first rounding moves the root by a relative 2^-54 at
/// most, below half a unit in the last place of the root, and the second by
/// at most half a unit, so the result is within one unit in the last place
/// of the true root (one of the two doubles around it). In another NT, the
/// square root of number_traits::to_double.
template <class NT>
double distance_of(const NT& squared_distance) {
    using tr = number_traits<NT>;
    if constexpr (tr::category == number_category::exact) {
        const scaled_double r = scaled_nearest(squared_distance);
        return std::ldexp(std::sqrt(r.mantissa), r.exponent / 2);
    } else {
        return std::sqrt(tr::to_double(squared_distance));
    }
}

}  // namespace influence2d
