// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether two bodies, each a polygon at its own pose, come within a
/// distance of each other: tried first on what showed it at the last step
/// (docs/world.md, "Narrow phase and coherence").

#include <cmath>
#include <memory>
#include <type_traits>

#include "influence2d/core/feature.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/number/fallback.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/exact_doubles.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/segments.hpp"
#include "influence2d/query/placed_meet.hpp"
#include "influence2d/scene/placed_polygon.hpp"

namespace influence2d {

/// The features that show two bodies in contact, in each polygon's input
/// numbering: an edge of each (they meet, or are within the distance), or a
/// vertex of one and the other's region (feature_kind::interior: the vertex
/// lies in its closed region).
struct contact_witness {
    feature first;   ///< of the body of the smaller id
    feature second;  ///< of the other body
};

/// The witness of a meeting between placed polygons a and b, in input
/// numbering (meeting holds stored numbers).
inline contact_witness witness_of(const meeting& m, const polygon& a, const polygon& b) {
    const feature region{feature_kind::interior, 0};
    switch (m.how) {
    case meeting::kind::edges:
        return {{feature_kind::edge, a.source_edge(m.a_index)}, {feature_kind::edge, b.source_edge(m.b_index)}};
    case meeting::kind::a_vertex_in_b: return {{feature_kind::vertex, input_vertex(a, m.a_index)}, region};
    case meeting::kind::b_vertex_in_a: return {region, {feature_kind::vertex, input_vertex(b, m.b_index)}};
    default: return {region, region};
    }
}

/// One body of a pair test: its polygon, its pose, and the polygon placed at
/// that pose (vertices in double; in NT, every one of them already made when
/// NT is not double, so that several threads may read it at once).
template <class NT>
struct body_view {
    const polygon* shape;        ///< the body's polygon
    rotation_pose pose;          ///< where it stands
    double scale;                ///< shape's largest coordinate plus |tx| + |ty|
    placed_polygon<NT>* placed;  ///< shape placed by pose, shared between the body's pairs
};

/// d * d in NT, what the distance tests take for d > 0; 0 for d = 0, which
/// no test reads, without the product (in a type that bounds its error, a
/// product and its bound for every pair tested).
template <class NT>
NT squared_distance(double d) {
    if (!(d > 0)) return NT(0);
    const NT dt = number_traits<NT>::from_double(d);
    return dt * dt;
}

/// Whether the edges [p, q] and [u, v], posed in NT, come within d of each
/// other (d2 = d * d in NT): the exact distance test, or for d = 0 the
/// exact segment test.
template <class NT>
bool edges_within(const point<NT>& p, const point<NT>& q, const point<NT>& u, const point<NT>& v, double d,
                  const NT& d2) {
    return d > 0 ? segments_within(p, q, u, v, d2) : segments_intersect(p, q, u, v);
}

/// Whether vertex j of `guest` lies in the closed region of `host`, both
/// placed, the two bodies' scales summing to `scale`: certainly within the
/// host's inner disc (placed_polygon::in_inner), or else located
/// (locate_placed), exactly in NT.
template <class NT>
bool vertex_in(placed_polygon<NT>& host, placed_polygon<NT>& guest, std::size_t j, double scale) {
    const double e = placing_margin<NT>(scale);
    return host.in_inner(guest.approx()[j], e) ||
           locate_placed(host, guest.approx()[j], guest[j], e) != location::outside;
}

/// Vertices `which[0..count)` of a body of `shape` posed by `pose`, into
/// `out`, when the pose is a translation whose sums are doubles
/// (rotation_pose::translates_exactly): an exact or filtered NT then decides
/// on those doubles exactly (predicates/exact_doubles.hpp, by
/// orientation_of_doubles at about double's cost), as it would on the same
/// values in its own arithmetic. False, `out` unspecified, when NT is a
/// floating type (which decides on its own rounding), the pose turns, or a
/// sum is not a double.
template <class NT>
bool translated_exactly(const rotation_pose& pose, const polygon& shape, const std::size_t* which, std::size_t count,
                        point<double>* out) {
    if constexpr (number_traits<NT>::category == number_category::floating) {
        return false;
    } else {
        for (std::size_t k = 0; k < count; ++k)
            if (!pose.translates_exactly(shape.vertex(which[k]), out[k])) return false;
        return true;
    }
}

/// Whether what showed bodies a and b within d at the last step (`last`,
/// stored numbering) still does at their present poses, decided exactly in
/// NT: for two edges, the exact segment test (d = 0) or distance test on the
/// four vertices posed in NT, in a type other than double after a filter in
/// double (edges that certainly cross), and for bodies translated by sums
/// that are doubles on those doubles (translated_exactly); for a
/// located vertex, its location in the other polygon.
template <class NT>
bool witness_holds(const meeting& last, const body_view<NT>& a, const body_view<NT>& b, double d, const NT& d2) {
    const polygon &as = *a.shape, &bs = *b.shape;
    switch (last.how) {
    case meeting::kind::edges: {
        const std::size_t i = last.a_index, j = last.b_index;
        // (Bodies translated by sums that are doubles, as parcels that touch
        // exactly: the four vertices are doubles, the test exact on them.)
        const std::size_t ends_a[2] = {i, as.next(i)}, ends_b[2] = {j, bs.next(j)};
        point<double> ta[2], tb[2];
        if (d == 0 && translated_exactly<NT>(a.pose, as, ends_a, 2, ta) &&
            translated_exactly<NT>(b.pose, bs, ends_b, 2, tb))
            return segments_meet_exactly(ta[0], ta[1], tb[0], tb[1]);
        if constexpr (!std::is_same_v<NT, double>) {
            // Two edges that still cross clearly are settled in double, the
            // four vertices posed in double within the posing's margin of
            // their values in NT (segments_certainly_cross).
            if (d == 0 && segments_certainly_cross(a.pose.template apply<double>(as.vertex(i)),
                                                   a.pose.template apply<double>(as.vertex(as.next(i))),
                                                   b.pose.template apply<double>(bs.vertex(j)),
                                                   b.pose.template apply<double>(bs.vertex(bs.next(j))),
                                                   placing_margin<NT>(a.scale + b.scale)))
                return true;
        }
        const point<NT> p = a.pose.template apply<NT>(as.vertex(i)),
                        q = a.pose.template apply<NT>(as.vertex(as.next(i)));
        const point<NT> u = b.pose.template apply<NT>(bs.vertex(j)),
                        v = b.pose.template apply<NT>(bs.vertex(bs.next(j)));
        return edges_within(p, q, u, v, d, d2);
    }
    case meeting::kind::b_vertex_in_a: return vertex_in(*a.placed, *b.placed, last.b_index, a.scale + b.scale);
    case meeting::kind::a_vertex_in_b: return vertex_in(*b.placed, *a.placed, last.a_index, a.scale + b.scale);
    default: return false;
    }
}

/// Whether the two edges that showed bodies a and b within d at the last
/// step (`last`, of kind edges) still do at their present poses: the four
/// vertices posed in NT, no polygon placed (a and b need no placing). With
/// Exact not void, false when NT cannot settle a sign (the pair is then
/// answered by bodies_within, which falls back to Exact).
template <class NT, class Exact = void>
bool edge_witness_holds(const meeting& last, const body_view<NT>& a, const body_view<NT>& b, double d) {
    const auto test = [&] { return witness_holds(last, a, b, d, squared_distance<NT>(d)); };
    if constexpr (std::is_void_v<Exact>) {
        return test();
    } else {
        return fallback<>::run(test, [] { return false; });
    }
}

/// Two edges about the two of `last` (kind edges: A's edge i, B's edge j)
/// that meet (or come within d) at the bodies' present poses, or none: edge
/// i and the edges before and after it on its ring, against edge j and
/// its two, (i, j) first and only `with_last` (the caller may have found it
/// failing); their eight vertices posed in NT once, each pair tested
/// exactly as witness_holds tests two edges (for bodies translated by sums
/// that are doubles, on those doubles: translated_exactly). Bodies that slide or turn a
/// little along each other most often meet by such a pair. With Exact not
/// void, none when NT cannot settle a sign (the pair is then answered by
/// bodies_within).
template <class NT, class Exact = void>
meeting nearby_edges_meet(const meeting& last, bool with_last, const body_view<NT>& a, const body_view<NT>& b,
                          double d) {
    const auto test = [&] {
        const polygon &as = *a.shape, &bs = *b.shape;
        // A's edges previous(i), i, next(i) run through its vertices
        // ia[0..3], B's likewise.
        const std::size_t i = last.a_index, j = last.b_index;
        const std::size_t ia[4] = {as.previous(i), i, as.next(i), as.next(as.next(i))};
        const std::size_t jb[4] = {bs.previous(j), j, bs.next(j), bs.next(bs.next(j))};
        // Edge x of A's three against edge y of B's, (i, j) = (1, 1)
        // first, then the pairs keeping one of i and j, then the others.
        static constexpr int order[9][2] = {{1, 1}, {1, 0}, {1, 2}, {0, 1}, {2, 1}, {0, 0}, {0, 2}, {2, 0}, {2, 2}};
        const auto found = [&](int x, int y) {
            meeting m;
            m.how = meeting::kind::edges;
            m.a_index = ia[x];
            m.b_index = jb[y];
            return m;
        };
        // (Bodies translated by sums that are doubles: decided exactly on
        // the doubles, as witness_holds.)
        point<double> ta[4], tb[4];
        if (d == 0 && translated_exactly<NT>(a.pose, as, ia, 4, ta) && translated_exactly<NT>(b.pose, bs, jb, 4, tb)) {
            for (int n = with_last ? 0 : 1; n < 9; ++n) {
                const int x = order[n][0], y = order[n][1];
                if (segments_meet_exactly(ta[x], ta[x + 1], tb[y], tb[y + 1])) return found(x, y);
            }
            return meeting{};
        }
        point<NT> pa[4], pb[4];
        for (int k = 0; k < 4; ++k) {
            pa[k] = a.pose.template apply<NT>(as.vertex(ia[k]));
            pb[k] = b.pose.template apply<NT>(bs.vertex(jb[k]));
        }
        const NT d2 = squared_distance<NT>(d);
        for (int n = with_last ? 0 : 1; n < 9; ++n) {
            const int x = order[n][0], y = order[n][1];
            if (edges_within(pa[x], pa[x + 1], pb[y], pb[y + 1], d, d2)) return found(x, y);
        }
        return meeting{};
    };
    if constexpr (std::is_void_v<Exact>) {
        return test();
    } else {
        return fallback<>::run(test, [] { return meeting{}; });
    }
}

/// Whether bodies a and b come within d of each other (d = 0: their closed
/// regions meet), and what shows it, in stored numbering. `last` is what
/// showed it at the last step (kind none when they were apart or the pair
/// is new): it is tried first, then the one-shot test (placed_within,
/// seeking the witness `prefer` first); `*by_witness`, when given, says
/// whether `last` answered. Exact when NT is. With Exact not void, a sign
/// NT cannot settle (uncertain_sign) makes the pair answered again in
/// Exact, both bodies posed anew in it; `*in_exact`, when given, says
/// whether it was.
///
///   last still holds (witness_holds):    last
///   else placed_within on the placed bodies, with the margin of their
///   posing (placing_margin of the sum of their scales; none when both
///   placings' doubles are the decisions' own values, exact_in_double)
template <class NT, class Exact = void>
meeting bodies_within(const meeting& last, const body_view<NT>& a, const body_view<NT>& b, double d,
                      bool* by_witness = nullptr, witness_preference prefer = witness_preference::cheapest,
                      bool* in_exact = nullptr) {
    if (by_witness != nullptr) *by_witness = false;
    if (in_exact != nullptr) *in_exact = false;
    const auto in = [&](auto tag, placed_polygon<decltype(tag)>& pa, placed_polygon<decltype(tag)>& pb,
                        const meeting& witness, const body_view<decltype(tag)>* va,
                        const body_view<decltype(tag)>* vb) -> meeting {
        using T = decltype(tag);
        const T d2 = squared_distance<T>(d);
        if (va != nullptr && witness && witness_holds(witness, *va, *vb, d, d2)) {
            if (by_witness != nullptr) *by_witness = true;
            return witness;
        }
        const double margin = pa.exact_in_double() && pb.exact_in_double() ? 0.0 : placing_margin<T>(a.scale + b.scale);
        return placed_within(pa, pb, margin, d, d2, prefer);
    };
    const auto fast = [&] { return in(NT{}, *a.placed, *b.placed, last, &a, &b); };
    if constexpr (std::is_void_v<Exact>) {
        return fast();
    } else {
        return fallback<>::run(fast, [&] {
            if (in_exact != nullptr) *in_exact = true;
            placed_polygon<Exact> pa(*a.shape, a.pose), pb(*b.shape, b.pose);
            return in(Exact{}, pa, pb, meeting{}, static_cast<const body_view<Exact>*>(nullptr),
                      static_cast<const body_view<Exact>*>(nullptr));
        });
    }
}

}  // namespace influence2d
