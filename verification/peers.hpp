// SPDX-License-Identifier: BSL-1.0
#pragma once
// The libraries a user would pick instead of influence2d, each behind the same
// small interface as the time study's own methods:
//
//   Peer p(A, B);          // A static, B moving; what can be prepared once is
//   bool hit = p.collide(pose);   // A and B posed by `pose` intersect
//
// Each is given its best shot on the frames of verification/time_study.hpp:
//   boost_geometry  bg::intersects(A, B) on bg::model::polygon (closed semantics:
//                   touching counts); B's rings are refilled in place each frame.
//   geos            A prepared once (GEOSPrepare_r); each frame builds B from a
//                   coordinate buffer and asks GEOSPreparedIntersects_r
//                   (closed semantics).
//   cgal            CGAL::do_intersect of two Polygon_with_holes_2 over the exact
//                   kernel (Boolean set operations): regularised, so polygons that
//                   only touch do not intersect. B is posed exactly (cos and sin as
//                   doubles, the rest in Epeck), like the reference.
//   box2d           b2TestOverlap of two b2PolygonShape (GJK in float) with the
//                   polygon skin set to zero; only convex polygons of at most
//                   b2_maxPolygonVertices (8) vertices, one ring each.
// Every peer but cgal poses B in double: x' = c x - s y + tx, y' = s x + c y + ty
// with c = cos(theta), s = sin(theta), the library's formula.

#if INFLUENCE2D_HAVE_BOX2D
#include <box2d/box2d.h>
#endif
#if INFLUENCE2D_HAVE_GEOS
#include <geos_c.h>
#endif

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"

namespace influence2d::verification {

namespace peer_detail {

/// The rings of P as closed-free vertex lists; ring 0 first. The peers take
/// polygons with one outer ring (ring 0) and holes, as every family polygon is.
inline std::vector<std::vector<point<double>>> rings_of(const polygon& P) {
    std::vector<std::vector<point<double>>> rings;
    for (std::size_t r = 0; r < P.ring_count(); ++r) {
        if ((P.role(r) == ring_role::hole) != (r > 0))
            throw std::invalid_argument("peers: the polygon must have one outer ring, first, and holes");
        std::vector<point<double>> ring;
        for (std::size_t i = P.ring_begin(r); i < P.ring_end(r); ++i) ring.push_back(P.vertex(i));
        rings.push_back(std::move(ring));
    }
    return rings;
}

/// B's vertex q posed in double.
inline point<double> posed(const rotation_pose& r, const point<double>& q) {
    return {r.c * q.x - r.s * q.y + r.tx, r.s * q.x + r.c * q.y + r.ty};
}

}  // namespace peer_detail

/// Boost.Geometry's intersects (closed semantics).
class boost_geometry_peer {
public:
    using point_type = boost::geometry::model::d2::point_xy<double>;
    using polygon_type = boost::geometry::model::polygon<point_type, false, true>;  // counter-clockwise, closed

    static const char* name() { return "boost_geometry"; }

    boost_geometry_peer(const polygon& A, const polygon& B) : b_rings_(peer_detail::rings_of(B)) {
        const auto a = peer_detail::rings_of(A);
        a_ = make(a);
        b_ = make(b_rings_);
        if (!boost::geometry::is_valid(a_)) throw std::invalid_argument("boost_geometry_peer: A is not a valid polygon");
    }

    bool collide(const pose& p) {
        const rotation_pose r(p);
        fill(b_.outer(), b_rings_[0], r);
        for (std::size_t k = 1; k < b_rings_.size(); ++k) fill(b_.inners()[k - 1], b_rings_[k], r);
        return boost::geometry::intersects(a_, b_);
    }

private:
    template <class Ring>
    static void fill(Ring& ring, const std::vector<point<double>>& from, const rotation_pose& r) {
        for (std::size_t i = 0; i < from.size(); ++i) {
            const point<double> q = peer_detail::posed(r, from[i]);
            ring[i] = point_type(q.x, q.y);
        }
        ring[from.size()] = ring[0];
    }

    static polygon_type make(const std::vector<std::vector<point<double>>>& rings) {
        polygon_type out;
        for (std::size_t k = 0; k < rings.size(); ++k) {
            auto& ring = k == 0 ? out.outer() : (out.inners().emplace_back(), out.inners().back());
            for (const auto& q : rings[k]) ring.push_back(point_type(q.x, q.y));
            ring.push_back(ring.front());
        }
        return out;
    }

    std::vector<std::vector<point<double>>> b_rings_;
    polygon_type a_, b_;
};

#if INFLUENCE2D_HAVE_GEOS
/// GEOS through its reentrant C API, the static polygon prepared.
class geos_peer {
public:
    static const char* name() { return "geos"; }

    geos_peer(const polygon& A, const polygon& B) : b_rings_(peer_detail::rings_of(B)) {
        ctx_ = GEOS_init_r();
        if (!ctx_) throw std::runtime_error("geos_peer: GEOS_init_r failed");
        GEOSContext_setErrorMessageHandler_r(ctx_, &on_error, &error_);
        a_ = make(peer_detail::rings_of(A), rotation_pose(pose{}));
        prepared_ = GEOSPrepare_r(ctx_, a_);
        if (!prepared_) throw std::runtime_error("geos_peer: GEOSPrepare_r failed: " + error_);
        std::size_t n = 0;
        for (const auto& r : b_rings_) n = std::max(n, r.size() + 1);
        buffer_.resize(2 * n);
    }
    geos_peer(const geos_peer&) = delete;
    geos_peer& operator=(const geos_peer&) = delete;
    ~geos_peer() {
        if (prepared_) GEOSPreparedGeom_destroy_r(ctx_, prepared_);
        if (a_) GEOSGeom_destroy_r(ctx_, a_);
        GEOS_finish_r(ctx_);
    }

    bool collide(const pose& p) {
        GEOSGeometry* b = make(b_rings_, rotation_pose(p));
        const char answer = GEOSPreparedIntersects_r(ctx_, prepared_, b);
        GEOSGeom_destroy_r(ctx_, b);
        if (answer == 2) throw std::runtime_error("geos_peer: GEOSPreparedIntersects_r failed: " + error_);
        return answer == 1;
    }

private:
    static void on_error(const char* message, void* user) { *static_cast<std::string*>(user) = message; }

    GEOSGeometry* ring(const std::vector<point<double>>& from, const rotation_pose& r) {
        for (std::size_t i = 0; i < from.size(); ++i) {
            const point<double> q = peer_detail::posed(r, from[i]);
            buffer_[2 * i] = q.x;
            buffer_[2 * i + 1] = q.y;
        }
        buffer_[2 * from.size()] = buffer_[0];
        buffer_[2 * from.size() + 1] = buffer_[1];
        GEOSCoordSequence* seq =
            GEOSCoordSeq_copyFromBuffer_r(ctx_, buffer_.data(), static_cast<unsigned>(from.size() + 1), 0, 0);
        if (!seq) throw std::runtime_error("geos_peer: cannot build a coordinate sequence: " + error_);
        GEOSGeometry* g = GEOSGeom_createLinearRing_r(ctx_, seq);
        if (!g) throw std::runtime_error("geos_peer: cannot build a ring: " + error_);
        return g;
    }

    GEOSGeometry* make(const std::vector<std::vector<point<double>>>& rings, const rotation_pose& r) {
        if (buffer_.size() < 2 * (rings[0].size() + 1)) {
            std::size_t n = 0;
            for (const auto& g : rings) n = std::max(n, g.size() + 1);
            buffer_.resize(2 * n);
        }
        GEOSGeometry* shell = ring(rings[0], r);
        std::vector<GEOSGeometry*> holes;
        for (std::size_t k = 1; k < rings.size(); ++k) holes.push_back(ring(rings[k], r));
        GEOSGeometry* g = GEOSGeom_createPolygon_r(ctx_, shell, holes.data(), static_cast<unsigned>(holes.size()));
        if (!g) throw std::runtime_error("geos_peer: cannot build a polygon: " + error_);
        return g;
    }

    GEOSContextHandle_t ctx_ = nullptr;
    std::string error_;
    std::vector<std::vector<point<double>>> b_rings_;
    std::vector<double> buffer_;
    GEOSGeometry* a_ = nullptr;
    const GEOSPreparedGeometry* prepared_ = nullptr;
};
#endif  // INFLUENCE2D_HAVE_GEOS

/// CGAL's Boolean-set do_intersect over the exact kernel (regularised: touching
/// is not an intersection).
class cgal_peer {
public:
    using kernel = CGAL::Exact_predicates_exact_constructions_kernel;
    using polygon_2 = CGAL::Polygon_2<kernel>;
    using polygon_with_holes_2 = CGAL::Polygon_with_holes_2<kernel>;

    static const char* name() { return "cgal"; }

    cgal_peer(const polygon& A, const polygon& B) : b_rings_(peer_detail::rings_of(B)) {
        const auto a = peer_detail::rings_of(A);
        a_ = make(a, [](const point<double>& q) { return kernel::Point_2(q.x, q.y); });
    }

    bool collide(const pose& p) {
        const kernel::FT c(std::cos(p.theta)), s(std::sin(p.theta)), tx(p.tx), ty(p.ty);
        const polygon_with_holes_2 b = make(b_rings_, [&](const point<double>& q) {
            const kernel::FT x(q.x), y(q.y);
            return kernel::Point_2(c * x - s * y + tx, s * x + c * y + ty);
        });
        return CGAL::do_intersect(a_, b);
    }

private:
    template <class Make>
    static polygon_with_holes_2 make(const std::vector<std::vector<point<double>>>& rings, Make point_of) {
        const auto ring = [&](const std::vector<point<double>>& from) {
            polygon_2 g;
            for (const auto& q : from) g.push_back(point_of(q));
            return g;
        };
        polygon_with_holes_2 out(ring(rings[0]));
        for (std::size_t k = 1; k < rings.size(); ++k) out.add_hole(ring(rings[k]));
        return out;
    }

    std::vector<std::vector<point<double>>> b_rings_;
    polygon_with_holes_2 a_;
};

#if INFLUENCE2D_HAVE_BOX2D
/// Box2D's convex polygon overlap test (b2TestOverlap, GJK in float).
class box2d_peer {
public:
    static const char* name() { return "box2d"; }

    /// Whether Box2D can take the pair: one ring each, convex, at most 8 vertices.
    static bool applies(const polygon& A, const polygon& B) { return fits(A) && fits(B); }

    box2d_peer(const polygon& A, const polygon& B) {
        if (!applies(A, B))
            throw std::invalid_argument("box2d_peer: Box2D takes convex polygons of at most 8 vertices");
        a_ = shape(A);
        b_ = shape(B);
    }

    bool collide(const pose& p) {
        b2Transform a_at, b_at;
        a_at.SetIdentity();
        b_at.Set(b2Vec2(static_cast<float>(p.tx), static_cast<float>(p.ty)), static_cast<float>(p.theta));
        return b2TestOverlap(&a_, 0, &b_, 0, a_at, b_at);
    }

private:
    static bool fits(const polygon& P) {
        if (P.ring_count() != 1 || P.size() > static_cast<std::size_t>(b2_maxPolygonVertices)) return false;
        for (std::size_t i = 0; i < P.size(); ++i) {  // every turn to the left: convex
            const point<double> u = P.vertex(i), v = P.vertex(P.next(i)), w = P.vertex(P.next(P.next(i)));
            if ((v.x - u.x) * (w.y - v.y) - (v.y - u.y) * (w.x - v.x) <= 0) return false;
        }
        return true;
    }

    static b2PolygonShape shape(const polygon& P) {
        std::vector<b2Vec2> v;
        for (std::size_t i = 0; i < P.size(); ++i)
            v.emplace_back(static_cast<float>(P.vertex(i).x), static_cast<float>(P.vertex(i).y));
        b2PolygonShape s;
        s.Set(v.data(), static_cast<int32>(v.size()));
        if (s.m_count != static_cast<int32>(v.size()))  // welded vertices or a changed hull
            throw std::invalid_argument("box2d_peer: b2PolygonShape::Set changed the polygon");
        s.m_radius = 0;  // no skin: the polygon itself
        return s;
    }

    b2PolygonShape a_, b_;
};
#endif  // INFLUENCE2D_HAVE_BOX2D

}  // namespace influence2d::verification
