// SPDX-License-Identifier: BSL-1.0
#pragma once
// The libraries a user would pick instead of influence2d, each behind the same
// small interface as the time study's own methods:
//
//   Peer p(A, B);          // A static, B moving; what can be prepared once is
//   bool hit = p.collide(pose);   // A and B posed by `pose` intersect
//
// Two forms per library. The frame form (`*_peer`) is given its best shot on
// many poses of one pair (verification/time_study.hpp's trajectories and
// random poses):
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
//   box2d-manifold  b2CollidePolygons of the same shapes: the contact manifold
//                   Box2D's narrow phase makes (separating axes, then the
//                   incident edge clipped to the reference face, in float);
//                   the pair meets when the manifold has a point.
// The one-shot form (`*_one_shot`) is what a user writes for a single query,
// nothing kept from one pose to the next but the input itself, and no
// validation of it:
//   boost_geometry  A kept as a bg polygon; B posed into a bg polygon built
//                   fresh; bg::intersects.
//   geos            both geometries built from their coordinates (B posed),
//                   GEOSIntersects_r (not prepared), both destroyed.
//   cgal            the frame form already is one (A kept as a polygon with
//                   holes, B posed fresh, do_intersect): cgal_peer serves both.
//   box2d           both b2PolygonShape built (Set: the hull and the normals),
//                   b2TestOverlap.
//   box2d-manifold  both built, b2CollidePolygons.
// A library that was not found when this was built is a missing_peer: listed by
// the time study, never run.
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

/// The rings of P as closed-free vertex lists; ring 0 first. The peers take
/// polygons with one outer ring (ring 0) and holes, as every family polygon is.
inline std::vector<std::vector<point<double>>> peer_rings(const polygon& P) {
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
inline point<double> posed_vertex(const rotation_pose& r, const point<double>& q) {
    return {r.c * q.x - r.s * q.y + r.tx, r.s * q.x + r.c * q.y + r.ty};
}

/// Boost.Geometry's point and polygon (counter-clockwise, closed) for the peers.
using bg_point = boost::geometry::model::d2::point_xy<double>;
using bg_polygon = boost::geometry::model::polygon<bg_point, false, true>;  // counter-clockwise, closed

/// The rings posed by r as a Boost.Geometry polygon, each ring closed.
inline bg_polygon bg_posed(const std::vector<std::vector<point<double>>>& rings, const rotation_pose& r) {
    bg_polygon out;
    out.inners().resize(rings.size() - 1);
    for (std::size_t k = 0; k < rings.size(); ++k) {
        auto& ring = k == 0 ? out.outer() : out.inners()[k - 1];
        ring.reserve(rings[k].size() + 1);
        for (const auto& q : rings[k]) {
            const point<double> v = posed_vertex(r, q);
            ring.push_back(bg_point(v.x, v.y));
        }
        ring.push_back(ring.front());
    }
    return out;
}

/// Boost.Geometry's intersects (closed semantics), frame form.
class boost_geometry_peer {
public:
    static const char* name() { return "boost_geometry"; }

    /// Whether both polygons are valid for Boost.Geometry (checked once per
    /// cell by the time study, outside every timing).
    static bool applies(const polygon& A, const polygon& B) {
        const rotation_pose identity{pose{}};
        return boost::geometry::is_valid(bg_posed(peer_rings(A), identity)) &&
               boost::geometry::is_valid(bg_posed(peer_rings(B), identity));
    }

    boost_geometry_peer(const polygon& A, const polygon& B) : b_rings_(peer_rings(B)) {
        const rotation_pose identity{pose{}};
        a_ = bg_posed(peer_rings(A), identity);
        b_ = bg_posed(b_rings_, identity);
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
            const point<double> q = posed_vertex(r, from[i]);
            ring[i] = bg_point(q.x, q.y);
        }
        ring[from.size()] = ring[0];
    }

    std::vector<std::vector<point<double>>> b_rings_;
    bg_polygon a_, b_;
};

/// Boost.Geometry's intersects, one-shot form: B posed into a polygon built
/// fresh for the query.
class boost_geometry_one_shot {
public:
    static bool applies(const polygon& A, const polygon& B) { return boost_geometry_peer::applies(A, B); }

    boost_geometry_one_shot(const polygon& A, const polygon& B)
        : a_(bg_posed(peer_rings(A), rotation_pose(pose{}))), b_rings_(peer_rings(B)) {}

    bool collide(const pose& p) const { return boost::geometry::intersects(a_, bg_posed(b_rings_, rotation_pose(p))); }

private:
    bg_polygon a_;
    std::vector<std::vector<point<double>>> b_rings_;
};

/// Stands for a peer whose library was not found when this was built: the
/// time study lists it and never runs it.
struct missing_peer {
    static bool applies(const polygon&, const polygon&) { return false; }
    missing_peer(const polygon&, const polygon&) {
        throw std::logic_error("missing_peer: the library was not found when this was built");
    }
    bool collide(const pose&) const { return false; }
};

#if INFLUENCE2D_HAVE_GEOS
/// A GEOS context (reentrant C API) with its error message and a coordinate
/// buffer: builds polygons from rings, posed.
class geos_builder {
public:
    geos_builder() {
        ctx = GEOS_init_r();
        if (!ctx) throw std::runtime_error("geos: GEOS_init_r failed");
        GEOSContext_setErrorMessageHandler_r(ctx, &on_error, &error);
    }
    geos_builder(const geos_builder&) = delete;
    geos_builder& operator=(const geos_builder&) = delete;
    ~geos_builder() { GEOS_finish_r(ctx); }

    /// A new polygon of the rings posed by r (the caller destroys it).
    GEOSGeometry* make(const std::vector<std::vector<point<double>>>& rings, const rotation_pose& r) {
        GEOSGeometry* shell = ring(rings[0], r);
        holes_.clear();
        for (std::size_t k = 1; k < rings.size(); ++k) holes_.push_back(ring(rings[k], r));
        GEOSGeometry* g = GEOSGeom_createPolygon_r(ctx, shell, holes_.data(), static_cast<unsigned>(holes_.size()));
        if (!g) throw std::runtime_error("geos: cannot build a polygon: " + error);
        return g;
    }

    /// The answer of a GEOS predicate (0, 1; 2 on failure).
    bool answer(char a, const char* what) const {
        if (a == 2) throw std::runtime_error(std::string("geos: ") + what + " failed: " + error);
        return a == 1;
    }

    GEOSContextHandle_t ctx = nullptr;
    std::string error;

private:
    static void on_error(const char* message, void* user) { *static_cast<std::string*>(user) = message; }

    GEOSGeometry* ring(const std::vector<point<double>>& from, const rotation_pose& r) {
        buffer_.resize(2 * (from.size() + 1));
        for (std::size_t i = 0; i < from.size(); ++i) {
            const point<double> q = posed_vertex(r, from[i]);
            buffer_[2 * i] = q.x;
            buffer_[2 * i + 1] = q.y;
        }
        buffer_[2 * from.size()] = buffer_[0];
        buffer_[2 * from.size() + 1] = buffer_[1];
        GEOSCoordSequence* seq =
            GEOSCoordSeq_copyFromBuffer_r(ctx, buffer_.data(), static_cast<unsigned>(from.size() + 1), 0, 0);
        if (!seq) throw std::runtime_error("geos: cannot build a coordinate sequence: " + error);
        GEOSGeometry* g = GEOSGeom_createLinearRing_r(ctx, seq);
        if (!g) throw std::runtime_error("geos: cannot build a ring: " + error);
        return g;
    }

    std::vector<double> buffer_;
    std::vector<GEOSGeometry*> holes_;
};

/// GEOS, frame form: the static polygon prepared once.
class geos_peer {
public:
    static const char* name() { return "geos"; }
    static bool applies(const polygon&, const polygon&) { return true; }

    geos_peer(const polygon& A, const polygon& B) : b_rings_(peer_rings(B)) {
        a_ = g_.make(peer_rings(A), rotation_pose(pose{}));
        prepared_ = GEOSPrepare_r(g_.ctx, a_);
        if (!prepared_) throw std::runtime_error("geos_peer: GEOSPrepare_r failed: " + g_.error);
    }
    geos_peer(const geos_peer&) = delete;
    geos_peer& operator=(const geos_peer&) = delete;
    ~geos_peer() {
        if (prepared_) GEOSPreparedGeom_destroy_r(g_.ctx, prepared_);
        if (a_) GEOSGeom_destroy_r(g_.ctx, a_);
    }

    bool collide(const pose& p) {
        GEOSGeometry* b = g_.make(b_rings_, rotation_pose(p));
        const char verdict = GEOSPreparedIntersects_r(g_.ctx, prepared_, b);
        GEOSGeom_destroy_r(g_.ctx, b);
        return g_.answer(verdict, "GEOSPreparedIntersects_r");
    }

private:
    geos_builder g_;
    std::vector<std::vector<point<double>>> b_rings_;
    GEOSGeometry* a_ = nullptr;
    const GEOSPreparedGeometry* prepared_ = nullptr;
};

/// GEOS, one-shot form: both geometries built for the query, GEOSIntersects_r.
class geos_one_shot {
public:
    static bool applies(const polygon&, const polygon&) { return true; }

    geos_one_shot(const polygon& A, const polygon& B) : a_rings_(peer_rings(A)), b_rings_(peer_rings(B)) {}

    bool collide(const pose& p) {
        GEOSGeometry* a = g_.make(a_rings_, rotation_pose(pose{}));
        GEOSGeometry* b = g_.make(b_rings_, rotation_pose(p));
        const char verdict = GEOSIntersects_r(g_.ctx, a, b);
        GEOSGeom_destroy_r(g_.ctx, b);
        GEOSGeom_destroy_r(g_.ctx, a);
        return g_.answer(verdict, "GEOSIntersects_r");
    }

private:
    geos_builder g_;
    std::vector<std::vector<point<double>>> a_rings_, b_rings_;
};
#else
using geos_peer = missing_peer;
using geos_one_shot = missing_peer;
#endif  // INFLUENCE2D_HAVE_GEOS

/// CGAL's Boolean-set do_intersect over the exact kernel (regularised: touching
/// is not an intersection).
class cgal_peer {
public:
    using kernel = CGAL::Exact_predicates_exact_constructions_kernel;
    using polygon_2 = CGAL::Polygon_2<kernel>;
    using polygon_with_holes_2 = CGAL::Polygon_with_holes_2<kernel>;

    static const char* name() { return "cgal"; }
    static bool applies(const polygon&, const polygon&) { return true; }

    cgal_peer(const polygon& A, const polygon& B) : b_rings_(peer_rings(B)) {
        const auto a = peer_rings(A);
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
/// Box2D's convex polygon overlap test (b2TestOverlap, GJK in float), frame
/// form: both shapes built once.
class box2d_peer {
public:
    static const char* name() { return "box2d"; }

    /// Whether Box2D can take the pair: one ring each, convex, at most 8 vertices.
    static bool applies(const polygon& A, const polygon& B) { return fits(A) && fits(B); }

    box2d_peer(const polygon& A, const polygon& B) {
        if (!applies(A, B))
            throw std::invalid_argument("box2d_peer: Box2D takes convex polygons of at most 8 vertices");
        a_ = shape(vertices(A));
        b_ = shape(vertices(B));
    }

    bool collide(const pose& p) const { return overlap(a_, b_, p); }

    /// The vertices of a one-ring polygon in float.
    static std::vector<b2Vec2> vertices(const polygon& P) {
        std::vector<b2Vec2> v;
        for (std::size_t i = 0; i < P.size(); ++i)
            v.emplace_back(static_cast<float>(P.vertex(i).x), static_cast<float>(P.vertex(i).y));
        return v;
    }

    /// The shape of those vertices, without skin.
    static b2PolygonShape shape(const std::vector<b2Vec2>& v) {
        b2PolygonShape s;
        s.Set(v.data(), static_cast<int32>(v.size()));
        if (s.m_count != static_cast<int32>(v.size()))  // welded vertices or a changed hull
            throw std::invalid_argument("box2d_peer: b2PolygonShape::Set changed the polygon");
        s.m_radius = 0;  // no skin: the polygon itself
        return s;
    }

    /// Box2D's transform of pose p, in float.
    static b2Transform transform(const pose& p) {
        b2Transform t;
        t.Set(b2Vec2(static_cast<float>(p.tx), static_cast<float>(p.ty)), static_cast<float>(p.theta));
        return t;
    }

    /// The identity transform (A unmoved), without a sine and cosine.
    static b2Transform identity() {
        b2Transform t;
        t.SetIdentity();
        return t;
    }

    /// Whether a (unmoved) and b posed by p overlap.
    static bool overlap(const b2PolygonShape& a, const b2PolygonShape& b, const pose& p) {
        return b2TestOverlap(&a, 0, &b, 0, identity(), transform(p));
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

    b2PolygonShape a_, b_;
};

/// Box2D, one-shot form: both shapes built for the query, b2TestOverlap.
class box2d_one_shot {
public:
    static bool applies(const polygon& A, const polygon& B) { return box2d_peer::applies(A, B); }

    box2d_one_shot(const polygon& A, const polygon& B) : a_(box2d_peer::vertices(A)), b_(box2d_peer::vertices(B)) {}

    bool collide(const pose& p) const { return box2d_peer::overlap(box2d_peer::shape(a_), box2d_peer::shape(b_), p); }

private:
    std::vector<b2Vec2> a_, b_;
};

/// Box2D's contact manifold of two convex polygons (b2CollidePolygons), frame
/// form: both shapes built once; the pair meets when the manifold has a point
/// (no skin: a point at separation <= 0).
class box2d_manifold_peer {
public:
    static bool applies(const polygon& A, const polygon& B) { return box2d_peer::applies(A, B); }

    box2d_manifold_peer(const polygon& A, const polygon& B)
        : a_(box2d_peer::shape(box2d_peer::vertices(A))), b_(box2d_peer::shape(box2d_peer::vertices(B))) {}

    bool collide(const pose& p) const { return touching(a_, b_, p); }

    /// Whether the manifold of a (unmoved) and b posed by p has a point.
    static bool touching(const b2PolygonShape& a, const b2PolygonShape& b, const pose& p) {
        b2Manifold m;
        b2CollidePolygons(&m, &a, box2d_peer::identity(), &b, box2d_peer::transform(p));
        return m.pointCount > 0;
    }

private:
    b2PolygonShape a_, b_;
};

/// Box2D's contact manifold, one-shot form: both shapes built for the query,
/// b2CollidePolygons.
class box2d_manifold_one_shot {
public:
    static bool applies(const polygon& A, const polygon& B) { return box2d_peer::applies(A, B); }

    box2d_manifold_one_shot(const polygon& A, const polygon& B)
        : a_(box2d_peer::vertices(A)), b_(box2d_peer::vertices(B)) {}

    bool collide(const pose& p) const {
        return box2d_manifold_peer::touching(box2d_peer::shape(a_), box2d_peer::shape(b_), p);
    }

private:
    std::vector<b2Vec2> a_, b_;
};
#else
using box2d_peer = missing_peer;
using box2d_one_shot = missing_peer;
using box2d_manifold_peer = missing_peer;
using box2d_manifold_one_shot = missing_peer;
#endif  // INFLUENCE2D_HAVE_BOX2D

}  // namespace influence2d::verification
