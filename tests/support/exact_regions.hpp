// SPDX-License-Identifier: BSL-1.0
#pragma once
// An exact reference for the sweep and two-pose tests, on CGAL's Cartesian
// kernel over exact rationals and its own predicates and intersections,
// sharing nothing with the library but the polygon's storage (rings, their
// stored orientation, next()): polygons placed exactly (posed, translated
// by rational amounts), whether two placed polygons meet (every edge pair,
// then one vertex per ring located by winding number), and every
// vertex-edge contact time of a translation solved as a segment
// intersection.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include <CGAL/Bbox_2.h>
#include <CGAL/Cartesian.h>
#include <CGAL/intersections.h>
#include <mpfr.h>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/number/cgal.hpp"

namespace test_exact {

using influence2d::exact_rational;
using influence2d::polygon;
using kernel = CGAL::Cartesian<exact_rational>;
using FT = kernel::FT;
using point_2 = kernel::Point_2;
using segment_2 = kernel::Segment_2;
using vector_2 = kernel::Vector_2;

/// A box that certainly holds the exact point (CGAL's outward intervals).
inline CGAL::Bbox_2 box_of(const point_2& p) {
    const auto x = CGAL::to_interval(p.x()), y = CGAL::to_interval(p.y());
    return {x.first, y.first, x.second, y.second};
}

/// A polygon placed exactly: its stored vertices as exact points (the
/// polygon gives the rings and next()).
struct placed_shape {
    const polygon* shape = nullptr;
    std::vector<point_2> v;
    std::vector<CGAL::Bbox_2> edge_box;
    CGAL::Bbox_2 box;  ///< the union of the edge boxes: holds every exact vertex

    placed_shape(const polygon& p, std::vector<point_2> pts) : shape(&p), v(std::move(pts)) {
        for (std::size_t i = 0; i < v.size(); ++i) {
            edge_box.push_back(box_of(v[i]) + box_of(v[p.next(i)]));
            box += edge_box.back();
        }
    }
    const point_2& end(std::size_t i) const { return v[shape->next(i)]; }
};

/// p posed by (c, s, tx, ty) exactly: c qx - s qy + tx, s qx + c qy + ty in FT.
inline placed_shape place(const polygon& p, double theta, double tx, double ty) {
    const FT c(std::cos(theta)), s(std::sin(theta));
    std::vector<point_2> pts;
    for (const auto& q : p.vertices()) pts.emplace_back(c * q.x - s * q.y + tx, s * q.x + c * q.y + ty);
    return placed_shape(p, std::move(pts));
}

/// p posed by q.
inline placed_shape place(const polygon& p, const influence2d::pose& q) { return place(p, q.theta, q.tx, q.ty); }

/// The placed polygon moved by the exact vector m.
inline placed_shape moved(const placed_shape& p, const vector_2& m) {
    std::vector<point_2> pts;
    for (const point_2& x : p.v) pts.push_back(x + m);
    return placed_shape(*p.shape, std::move(pts));
}

/// Whether the point lies on edge i (a zero-length edge: is that point).
inline bool on_edge(const placed_shape& p, std::size_t i, const point_2& x) {
    const point_2 &a = p.v[i], &b = p.end(i);
    if (a == b) return x == a;
    return segment_2(a, b).has_on(x);
}

/// Whether x lies in the closed region (the library's rule): on an edge, or
/// with a winding number other than 0 summed over all rings. The winding
/// number counts the edges that cross the horizontal line through x to its
/// right: upwards +1, downwards -1, each edge taken with its lower end and
/// without its upper end.
inline bool in_region(const placed_shape& p, const point_2& x) {
    long sum = 0;
    for (std::size_t i = 0; i < p.v.size(); ++i) {
        if (on_edge(p, i, x)) return true;
        const point_2 &a = p.v[i], &b = p.end(i);
        const bool a_below = a.y() <= x.y(), b_below = b.y() <= x.y();
        if (a_below == b_below) continue;
        const CGAL::Orientation o = CGAL::orientation(a, b, x);
        if (a_below && o == CGAL::LEFT_TURN) ++sum;
        if (!a_below && o == CGAL::RIGHT_TURN) --sum;
    }
    return sum != 0;
}

/// Whether edges i of p and j of q share a point.
inline bool edges_meet(const placed_shape& p, std::size_t i, const placed_shape& q, std::size_t j) {
    if (!CGAL::do_overlap(p.edge_box[i], q.edge_box[j])) return false;
    const point_2 &a = p.v[i], &b = p.end(i), &c = q.v[j], &d = q.end(j);
    if (a == b) return on_edge(q, j, a);
    if (c == d) return on_edge(p, i, c);
    return CGAL::do_intersect(segment_2(a, b), segment_2(c, d));
}

/// Whether the closed regions of two placed polygons meet: some edge pair
/// shares a point, or the first vertex of some ring of one lies in the
/// other's region.
inline bool regions_meet(const placed_shape& p, const placed_shape& q) {
    for (std::size_t i = 0; i < p.v.size(); ++i)
        for (std::size_t j = 0; j < q.v.size(); ++j)
            if (edges_meet(p, i, q, j)) return true;
    for (std::size_t r = 0; r < q.shape->ring_count(); ++r)
        if (in_region(p, q.v[q.shape->ring_begin(r)])) return true;
    for (std::size_t r = 0; r < p.shape->ring_count(); ++r)
        if (in_region(q, p.v[p.shape->ring_begin(r)])) return true;
    return false;
}

/// The earliest time t in [0, 1] (or t >= 0 up to `horizon` when given)
/// at which x + t m lies on edge i of p, found as the intersection of the
/// segment [x, x + horizon m] with the edge (a point, or a segment whose
/// ends both count).
inline std::vector<FT> contact_times(const point_2& x, const vector_2& m, const placed_shape& p, std::size_t i,
                                     const FT& horizon = FT(1)) {
    std::vector<FT> out;
    const segment_2 path(x, x + m * horizon);
    if (!CGAL::do_overlap(box_of(path.source()) + box_of(path.target()), p.edge_box[i])) return out;
    const FT mm = m * m;
    const auto time_of = [&](const point_2& y) { out.push_back(((y - x) * m) / mm); };
    const point_2 &a = p.v[i], &b = p.end(i);
    if (a == b) {
        if (path.has_on(a)) time_of(a);
        return out;
    }
    const auto hit = CGAL::intersection(path, segment_2(a, b));
    if (!hit) return out;
    if (const point_2* y = boost::get<point_2>(&*hit)) time_of(*y);
    if (const segment_2* s = boost::get<segment_2>(&*hit)) {
        time_of(s->source());
        time_of(s->target());
    }
    return out;
}

/// Every contact time of B (placed at the start) translated by m against A
/// (placed), t in [0, horizon]: each vertex of B against each edge of A,
/// each vertex of A (moving by -m relative to B) against each edge of B.
inline std::vector<FT> all_contact_times(const placed_shape& a, const placed_shape& b, const vector_2& m,
                                         const FT& horizon = FT(1)) {
    std::vector<FT> out;
    const auto add = [&out](std::vector<FT> ts) { out.insert(out.end(), ts.begin(), ts.end()); };
    for (std::size_t j = 0; j < b.v.size(); ++j)
        for (std::size_t i = 0; i < a.v.size(); ++i) add(contact_times(b.v[j], m, a, i, horizon));
    for (std::size_t i = 0; i < a.v.size(); ++i)
        for (std::size_t j = 0; j < b.v.size(); ++j) add(contact_times(a.v[i], -m, b, j, horizon));
    return out;
}

/// The earliest contact time of B translated by m against A, t in [0, 1]:
/// 0 when they meet at the start; none when they never meet.
inline std::optional<FT> first_contact(const placed_shape& a, const placed_shape& b, const vector_2& m) {
    if (regions_meet(a, b)) return FT(0);
    const std::vector<FT> ts = all_contact_times(a, b, m);
    if (ts.empty()) return std::nullopt;
    return *std::min_element(ts.begin(), ts.end());
}

/// GMP's rational inside exact_rational, which CGAL takes from gmpxx
/// (mpq_class) or from Boost.Multiprecision (gmp_rational).
template <class Q, class = void>
struct gmp_view {
    static mpq_srcptr of(const Q& q) { return q.backend().data(); }
};
template <class Q>
struct gmp_view<Q, std::void_t<decltype(std::declval<const Q&>().get_mpq_t())>> {
    static mpq_srcptr of(const Q& q) { return q.get_mpq_t(); }
};

/// The double nearest the exact value (ties to even), by MPFR.
inline double nearest_double(const exact_rational& q) {
    mpfr_t x;
    mpfr_init2(x, 53);
    mpfr_set_q(x, gmp_view<exact_rational>::of(q), MPFR_RNDN);
    const double d = mpfr_get_d(x, MPFR_RNDN);
    mpfr_clear(x);
    return d;
}

}  // namespace test_exact
