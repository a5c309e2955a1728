// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// How far apart two convex polygons are, bounded from below and above in
/// double: GJK on their vertices, its bounds proven whatever path the
/// rounding takes (docs/sweep.md, "Convex pairs").

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "influence2d/core/point.hpp"

namespace influence2d {

/// The rounding of convex_gap's bounds, relative to the scene's size S (a
/// bound on every coordinate of A and of posed B): with u = 2^-53, each
/// posed vertex of B is within 4u (|x| + |y| + |t|) <= 8u S of its exact
/// posing by the same cosine and sine per coordinate (two products, two
/// sums); a dot product n.p rounds by at most 2u |n|_1 |p|_inf, so
/// n.b for a posed vertex b is within (8u + 2u) sqrt(2) |n| S of the exact
/// one, n.a within 2u sqrt(2) |n| S, their difference within another
/// 4u sqrt(2) |n| S, and the division by the rounded |n| adds 3u of a value
/// below 3 S: the lower bound's error is below 32u S. The upper bound's
/// point v is a vertex P of B - A or the foot n (n.P) / (n.n) on the line of
/// P and Q (nearest_on_segment), P and Q rounded differences of posed
/// vertices (within 10u S per coordinate): the foot of the exact line moves
/// with them by at most as much, and its evaluation (n rounded by u |n|,
/// n.P by 3u |n| |P|, a division and a product, |P| <= 3 S) adds below
/// 20u S; its norm rounds by 2u of 3 S: below 50u S. 2^-45 S = 256u S
/// covers both with a factor of five.
inline constexpr double convex_gap_rounding = 0x1p-45;

/// The most iterations convex_gap takes per vertex of the two polygons:
/// in exact arithmetic GJK on polygons ends within one support point per
/// vertex pair of the Minkowski difference's boundary walked; rounding that
/// cycles is stopped here and reported as not converged.
inline constexpr std::size_t convex_gap_iterations_per_vertex = 2;

/// A vertex of the Minkowski difference B - A: vertex j of B minus vertex i
/// of A.
struct difference_vertex {
    std::uint32_t i = 0;  ///< A's vertex
    std::uint32_t j = 0;  ///< B's vertex
    point<double> w;      ///< b_j - a_i, rounded
};

/// What convex_gap found: bounds of the distance between the two convex
/// hulls, the axis of the lower bound, and the simplex of the upper bound
/// (one or two vertices of B - A whose segment holds the point nearest the
/// origin).
struct convex_gap_result {
    double lower = 0;  ///< at most the distance between the hulls
    double upper = 0;  ///< at least that distance
    /// A direction n from A towards B: lower is at most the gap between the
    /// projections of A and B on n / |n|.
    point<double> axis{0, 0};
    difference_vertex simplex[2];  ///< the simplex's vertices
    std::size_t points = 0;        ///< 1 or 2
    bool converged = false;        ///< upper - lower came within the tolerance
};

namespace convex_gap_detail {

inline double dot(const point<double>& p, const point<double>& q) { return p.x * q.x + p.y * q.y; }

/// The vertex of B - A least along n: A's vertex most along n, B's least.
inline difference_vertex support(const point<double>* a, std::size_t na, const point<double>* b, std::size_t nb,
                                 const point<double>& n) {
    std::size_t i = 0, j = 0;
    double best_a = dot(n, a[0]), best_b = dot(n, b[0]);
    for (std::size_t k = 1; k < na; ++k)
        if (const double d = dot(n, a[k]); d > best_a) best_a = d, i = k;
    for (std::size_t k = 1; k < nb; ++k)
        if (const double d = dot(n, b[k]); d < best_b) best_b = d, j = k;
    return {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), {b[j].x - a[i].x, b[j].y - a[i].y}};
}

/// The point of segment [p, q] nearest the origin, with its parameter l in
/// [0, 1] (p + l (q - p)): an end, or, strictly inside, the foot of the
/// perpendicular from the origin, n (n.p) / (n.n) for the normal
/// n = (q - p) turned by a right angle. (The foot taken as p + l (q - p)
/// would point in a direction wrong by the rounding of p over its length,
/// which for a short distance between large polygons turns the axis by far
/// more than the lower bound may lose; n's direction is good to an ulp.)
inline point<double> nearest_on_segment(const point<double>& p, const point<double>& q, double& l) {
    const point<double> d{q.x - p.x, q.y - p.y};
    const double dd = dot(d, d);
    l = dd > 0 ? -dot(p, d) / dd : 0;
    if (l <= 0) {
        l = 0;
        return p;
    }
    if (l >= 1) {
        l = 1;
        return q;
    }
    const point<double> n{-d.y, d.x};
    const double f = dot(n, p) / dd;
    return {f * n.x, f * n.y};
}

/// Whether the triangle p, q, s holds the origin, by the signs of the
/// rounded cross products (a guess: a wrong one only stops the search
/// unconverged).
inline bool holds_origin(const point<double>& p, const point<double>& q, const point<double>& s) {
    const double pq = p.x * q.y - p.y * q.x, qs = q.x * s.y - q.y * s.x, sp = s.x * p.y - s.y * p.x;
    return (pq >= 0 && qs >= 0 && sp >= 0) || (pq <= 0 && qs <= 0 && sp <= 0);
}

}  // namespace convex_gap_detail

/// Bounds of the distance between the convex hulls of A's vertices `a` and
/// of B's `b` (doubles), `scale` bounding their coordinates, starting from
/// the simplex of `from` (its vertex pairs; a search of the same polygons
/// at a nearby pose, whose simplex is likely to be the answer's; none when
/// from.points is 0). The bounds hold whatever the rounding: `lower` is the
/// gap of the projections on an axis (a lower bound for any two sets, minus
/// its rounding) and `upper` the length of a point of B - A (plus its
/// rounding). The distance between the hulls is the distance between A and
/// B when both are convex.
///
///   simplex <- from's vertex pairs at these coordinates, v its point
///              nearest the origin (its ends that v needs kept); with none,
///              the vertex of B - A least along a_0 - b_0
///   loop (at most convex_gap_iterations_per_vertex (|a| + |b|) times):
///       w <- the support point of B - A least along v
///       lower <- max(lower, v.w / |v|); upper <- |v|
///       if upper - lower <= tolerance:  converged
///       if v = 0, or w is in the simplex, or the origin lies in the
///          triangle of w and a two-point simplex:  stop (they meet, or
///          rounding stalls the search)
///       v <- the point nearest the origin of the segments from w to each
///            simplex vertex; simplex <- that segment's ends that v needs
///
inline convex_gap_result convex_gap(const point<double>* a, std::size_t na, const point<double>* b, std::size_t nb,
                                    double scale, double tolerance, const convex_gap_result& from) {
    namespace d = convex_gap_detail;
    convex_gap_result r;
    const double rounding = convex_gap_rounding * scale;
    point<double> v;
    if (from.points == 0) {
        r.simplex[0] = d::support(a, na, b, nb, {a[0].x - b[0].x, a[0].y - b[0].y});
        r.points = 1;
        v = r.simplex[0].w;
    } else {
        // The last simplex's vertex pairs at these coordinates.
        for (std::size_t k = 0; k < from.points; ++k) {
            const std::uint32_t i = from.simplex[k].i, j = from.simplex[k].j;
            r.simplex[k] = {i, j, {b[j].x - a[i].x, b[j].y - a[i].y}};
        }
        r.points = from.points;
        v = r.simplex[0].w;
        if (r.points == 2) {
            double l = 0;
            v = d::nearest_on_segment(r.simplex[0].w, r.simplex[1].w, l);
            if (l == 1) r.simplex[0] = r.simplex[1];
            if (l == 0 || l == 1) r.points = 1;
        }
    }
    double best = -HUGE_VAL;
    const std::size_t most = convex_gap_iterations_per_vertex * (na + nb);
    for (std::size_t k = 0; k < most; ++k) {
        const double length = std::sqrt(d::dot(v, v));
        r.upper = length + rounding;
        if (length == 0) break;
        const difference_vertex w = d::support(a, na, b, nb, v);
        if (const double gap = d::dot(v, w.w) / length; gap > best) {
            best = gap;
            r.axis = v;
        }
        r.lower = best - rounding;
        if (r.upper - r.lower <= tolerance) {
            r.converged = true;
            break;
        }
        bool known = false;
        for (std::size_t p = 0; p < r.points; ++p) known = known || (r.simplex[p].i == w.i && r.simplex[p].j == w.j);
        if (known) break;
        if (r.points == 2 && d::holds_origin(w.w, r.simplex[0].w, r.simplex[1].w)) break;
        // The nearest point of the segments from w to the simplex's
        // vertices (the new simplex holds w: in exact arithmetic the
        // nearest point moves towards the origin only through w).
        double l = 0;
        point<double> nearest = d::nearest_on_segment(w.w, r.simplex[0].w, l);
        difference_vertex other = r.simplex[0];
        double nearest_l = l;
        if (r.points == 2) {
            const point<double> second = d::nearest_on_segment(w.w, r.simplex[1].w, l);
            if (d::dot(second, second) < d::dot(nearest, nearest)) {
                nearest = second;
                other = r.simplex[1];
                nearest_l = l;
            }
        }
        v = nearest;
        if (nearest_l == 0) {
            r.simplex[0] = w;
            r.points = 1;
        } else if (nearest_l == 1) {
            r.simplex[0] = other;
            r.points = 1;
        } else {
            r.simplex[0] = w;
            r.simplex[1] = other;
            r.points = 2;
        }
    }
    return r;
}

}  // namespace influence2d
