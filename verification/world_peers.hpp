// SPDX-License-Identifier: BSL-1.0
#pragma once
// What a user of another library writes for the world's question (which
// pairs of posed bodies meet after each step), for the world's time study
// (src/world_bench.cpp). Each step poses every body (posing is part of every
// method's time) and returns the meeting pairs (i < j, not both fixed),
// sorted:
// - geos_world:   GEOS 3.11's C API: every body's posed polygon, an STRtree of
//                 them built anew each step (as its users do: the tree is
//                 immutable), each free body's candidates by a query,
//                 GEOSPreparedIntersects_r from the body prepared once per step;
// - boost_world:  Boost.Geometry 1.74: the posed polygons, a packed rtree of
//                 their boxes per step, bg::intersects per candidate;
// - box2d_world:  Box2D 2.4: a b2DynamicTree of fat boxes, each body's proxy
//                 moved (MoveProxy) every step, candidates by a query,
//                 b2TestOverlap (convex polygons of at most 8 vertices only,
//                 in float);
// - all_pairs:    the library without a broad phase: intersects<double> with
//                 both poses (query/both_posed.hpp) on every pair.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "influence2d/query/both_posed.hpp"
#include "influence2d/world/world.hpp"
#include "verification/peers.hpp"
#include "verification/world_scenes.hpp"

namespace influence2d::verification {

/// The parts of P, each its outer ring followed by the holes stored after
/// it (as closed-free vertex lists): a multipolygon for the peers.
inline std::vector<std::vector<std::vector<point<double>>>> peer_parts(const polygon& P) {
    std::vector<std::vector<std::vector<point<double>>>> parts;
    for (std::size_t r = 0; r < P.ring_count(); ++r) {
        std::vector<point<double>> ring;
        for (std::size_t i = P.ring_begin(r); i < P.ring_end(r); ++i) ring.push_back(P.vertex(i));
        if (P.role(r) == ring_role::outer || parts.empty())
            parts.push_back({std::move(ring)});
        else
            parts.back().push_back(std::move(ring));
    }
    return parts;
}

/// Boost.Geometry's multipolygon.
using bg_multi = boost::geometry::model::multi_polygon<bg_polygon>;

/// The parts posed by r as a Boost.Geometry multipolygon.
inline bg_multi bg_multi_posed(const std::vector<std::vector<std::vector<point<double>>>>& parts,
                               const rotation_pose& r) {
    bg_multi out;
    for (const auto& part : parts) out.push_back(bg_posed(part, r));
    return out;
}

#if INFLUENCE2D_HAVE_GEOS
/// The parts posed by r as a GEOS polygon (one part) or multipolygon; the
/// caller destroys it.
inline GEOSGeometry* geos_multi_posed(geos_builder& g,
                                      const std::vector<std::vector<std::vector<point<double>>>>& parts,
                                      const rotation_pose& r) {
    if (parts.size() == 1) return g.make(parts[0], r);
    std::vector<GEOSGeometry*> polygons;
    for (const auto& part : parts) polygons.push_back(g.make(part, r));
    GEOSGeometry* m =
        GEOSGeom_createCollection_r(g.ctx, GEOS_MULTIPOLYGON, polygons.data(), static_cast<unsigned>(polygons.size()));
    if (!m) throw std::runtime_error("geos: cannot build a multipolygon: " + g.error);
    return m;
}
#endif

namespace world_peers_detail {

inline std::vector<body_pair> sorted(std::vector<body_pair> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

inline body_pair ordered(std::size_t i, std::size_t j) {
    return {static_cast<std::uint32_t>(std::min(i, j)), static_cast<std::uint32_t>(std::max(i, j))};
}

}  // namespace world_peers_detail

/// The library's all-pairs loop of one-shot queries.
class all_pairs_world {
public:
    explicit all_pairs_world(const world_scene& s) : s_(s) {}
    std::vector<body_pair> step(const std::vector<pose>& at) {
        std::vector<body_pair> out;
        for (std::size_t i = 0; i < at.size(); ++i)
            for (std::size_t j = i + 1; j < at.size(); ++j) {
                if (s_.fixed[i] && s_.fixed[j]) continue;
                if (intersects<double>(s_.shapes[s_.shape_of[i]], at[i], s_.shapes[s_.shape_of[j]], at[j]))
                    out.push_back(world_peers_detail::ordered(i, j));
            }
        return out;
    }

private:
    const world_scene& s_;
};

/// Boost.Geometry: packed rtree of posed boxes per step, bg::intersects.
class boost_world {
public:
    explicit boost_world(const world_scene& s) : s_(s) {
        for (const polygon& p : s.shapes) rings_.push_back(peer_parts(p));
    }
    std::vector<body_pair> step(const std::vector<pose>& at) {
        namespace bg = boost::geometry;
        namespace bgi = boost::geometry::index;
        using bbox = bg::model::box<bg_point>;
        std::vector<bg_multi> posed;
        posed.reserve(at.size());
        std::vector<std::pair<bbox, std::uint32_t>> boxes;
        boxes.reserve(at.size());
        for (std::size_t b = 0; b < at.size(); ++b) {
            posed.push_back(bg_multi_posed(rings_[s_.shape_of[b]], rotation_pose(at[b])));
            boxes.emplace_back(bg::return_envelope<bbox>(posed.back()), static_cast<std::uint32_t>(b));
        }
        const bgi::rtree<std::pair<bbox, std::uint32_t>, bgi::quadratic<16>> tree(boxes.begin(), boxes.end());
        std::vector<body_pair> out;
        std::vector<std::pair<bbox, std::uint32_t>> found;
        for (std::size_t i = 0; i < at.size(); ++i) {
            if (s_.fixed[i]) continue;
            found.clear();
            tree.query(bgi::intersects(boxes[i].first), std::back_inserter(found));
            for (const auto& f : found) {
                const std::size_t j = f.second;
                if (j == i || (!s_.fixed[j] && j < i)) continue;  // each free pair once
                if (bg::intersects(posed[i], posed[j])) out.push_back(world_peers_detail::ordered(i, j));
            }
        }
        return world_peers_detail::sorted(std::move(out));
    }

private:
    const world_scene& s_;
    std::vector<std::vector<std::vector<std::vector<point<double>>>>> rings_;
};

#if INFLUENCE2D_HAVE_GEOS
/// GEOS: STRtree of the posed polygons per step, prepared intersects.
class geos_world {
public:
    explicit geos_world(const world_scene& s) : s_(s) {
        for (const polygon& p : s.shapes) rings_.push_back(peer_parts(p));
    }
    std::vector<body_pair> step(const std::vector<pose>& at) {
        GEOSContextHandle_t ctx = g_.ctx;
        std::vector<GEOSGeometry*> posed;
        posed.reserve(at.size());
        for (std::size_t b = 0; b < at.size(); ++b)
            posed.push_back(geos_multi_posed(g_, rings_[s_.shape_of[b]], rotation_pose(at[b])));
        GEOSSTRtree* tree = GEOSSTRtree_create_r(ctx, 10);
        for (std::size_t b = 0; b < at.size(); ++b)
            GEOSSTRtree_insert_r(ctx, tree, posed[b], reinterpret_cast<void*>(static_cast<std::uintptr_t>(b)));
        std::vector<body_pair> out;
        struct query {
            std::size_t i;
            std::vector<std::size_t>* found;
        };
        std::vector<std::size_t> found;
        for (std::size_t i = 0; i < at.size(); ++i) {
            if (s_.fixed[i]) continue;
            found.clear();
            query q{i, &found};
            GEOSSTRtree_query_r(
                ctx, tree, posed[i],
                [](void* item, void* user) {
                    static_cast<query*>(user)->found->push_back(reinterpret_cast<std::uintptr_t>(item));
                },
                &q);
            const GEOSPreparedGeometry* prepared = nullptr;
            for (std::size_t j : found) {
                if (j == i || (!s_.fixed[j] && j < i)) continue;
                if (!prepared) prepared = GEOSPrepare_r(ctx, posed[i]);
                if (g_.answer(GEOSPreparedIntersects_r(ctx, prepared, posed[j]), "GEOSPreparedIntersects_r"))
                    out.push_back(world_peers_detail::ordered(i, j));
            }
            if (prepared) GEOSPreparedGeom_destroy_r(ctx, prepared);
        }
        GEOSSTRtree_destroy_r(ctx, tree);
        for (GEOSGeometry* p : posed) GEOSGeom_destroy_r(ctx, p);
        return world_peers_detail::sorted(std::move(out));
    }

private:
    const world_scene& s_;
    std::vector<std::vector<std::vector<std::vector<point<double>>>>> rings_;
    geos_builder g_;
};
#endif

#if INFLUENCE2D_HAVE_BOX2D
/// Box2D: a dynamic tree of fat boxes, moved proxies, b2TestOverlap.
class box2d_world {
public:
    static bool applies(const world_scene& s) { return s.convex_only; }

    explicit box2d_world(const world_scene& s) : s_(s) {
        for (const polygon& p : s.shapes) shapes_.push_back(box2d_peer::shape(box2d_peer::vertices(p)));
    }
    std::vector<body_pair> step(const std::vector<pose>& at) {
        if (proxies_.empty()) {
            for (std::size_t b = 0; b < at.size(); ++b)
                proxies_.push_back(
                    tree_.CreateProxy(aabb(b, at[b]), reinterpret_cast<void*>(static_cast<std::uintptr_t>(b))));
            last_ = at;
        } else {
            for (std::size_t b = 0; b < at.size(); ++b)
                tree_.MoveProxy(
                    proxies_[b], aabb(b, at[b]),
                    b2Vec2(static_cast<float>(at[b].tx - last_[b].tx), static_cast<float>(at[b].ty - last_[b].ty)));
            last_ = at;
        }
        std::vector<body_pair> out;
        struct query {
            const b2DynamicTree* tree;
            std::vector<std::size_t> found;
            bool QueryCallback(int32 id) {
                found.push_back(reinterpret_cast<std::uintptr_t>(tree->GetUserData(id)));
                return true;
            }
        } q{&tree_, {}};
        for (std::size_t i = 0; i < at.size(); ++i) {
            if (s_.fixed[i]) continue;
            q.found.clear();
            tree_.Query(&q, aabb(i, at[i]));
            const b2Transform ti = transform(at[i]);
            for (std::size_t j : q.found) {
                if (j == i || (!s_.fixed[j] && j < i)) continue;
                if (b2TestOverlap(&shapes_[s_.shape_of[i]], 0, &shapes_[s_.shape_of[j]], 0, ti, transform(at[j])))
                    out.push_back(world_peers_detail::ordered(i, j));
            }
        }
        return world_peers_detail::sorted(std::move(out));
    }

private:
    static b2Transform transform(const pose& q) {
        b2Transform t;
        t.Set(b2Vec2(static_cast<float>(q.tx), static_cast<float>(q.ty)), static_cast<float>(q.theta));
        return t;
    }
    b2AABB aabb(std::size_t b, const pose& q) const {
        b2AABB box;
        shapes_[s_.shape_of[b]].ComputeAABB(&box, transform(q), 0);
        return box;
    }

    const world_scene& s_;
    std::vector<b2PolygonShape> shapes_;
    b2DynamicTree tree_;
    std::vector<int32> proxies_;
    std::vector<pose> last_;
};
#endif

}  // namespace influence2d::verification
