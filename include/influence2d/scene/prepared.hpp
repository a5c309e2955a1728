// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// What the detectors precompute for the static polygon, and the moving
/// polygon posed in NT for a frame.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/influence/edge_tree.hpp"
#include "influence2d/influence/influence_areas.hpp"

namespace influence2d {

/// The polygon p, checked to be one a detector in NT can take: not empty (a
/// default-constructed polygon has no ring), and within the range of a
/// floating NT narrower than double (float). Throws invalid_input saying
/// which polygon (`which`) is empty, or naming its first vertex beyond
/// NT's range. Other types take every finite double.
template <class NT>
const polygon& accepted_polygon(const polygon& p, const char* which) {
    if (p.size() == 0) throw invalid_input(std::string("the ") + which + " polygon is empty (it has no ring)");
    if constexpr (std::is_floating_point_v<NT> && std::numeric_limits<NT>::is_specialized) {
        constexpr double top = static_cast<double>(std::numeric_limits<NT>::max());
        if constexpr (top < std::numeric_limits<double>::max()) {
            for (const point<double>& v : p.vertices())
                if (std::fabs(v.x) > top || std::fabs(v.y) > top)
                    throw invalid_input(std::string("the ") + which + " polygon's vertex (" + std::to_string(v.x) +
                                        ", " + std::to_string(v.y) + ") is beyond the range of " +
                                        number_traits<NT>::name);
        }
    }
    return p;
}

/// A structure built by the first call that asks for it and then kept:
/// callers from several threads at once get the one value, built once
/// (std::call_once). Neither copied nor moved.
template <class T>
class built_once {
public:
    built_once() = default;
    built_once(const built_once&) = delete;
    built_once& operator=(const built_once&) = delete;

    /// The value, built by make() if no call has built it yet.
    template <class Make>
    const T& get(Make&& make) const {
        std::call_once(once_, [&] {
            value_.emplace(make());
            built_.store(true, std::memory_order_release);
        });
        return *value_;
    }
    /// The value if it was built, else nullptr (never waits).
    const T* if_built() const { return built_.load(std::memory_order_acquire) ? &*value_ : nullptr; }

private:
    mutable std::once_flag once_;
    mutable std::optional<T> value_;
    mutable std::atomic<bool> built_{false};
};

/// The static polygon A prepared for detectors in NT: its covering from its
/// centroid and its bounding radius, built at once (linear time); its
/// influence areas (the cone index) and its edge tree, built by the first
/// frame that asks for them. Immutable to its users and safe to share: one
/// A serves detectors for many B, in any number of threads (see
/// prepare_static).
template <class NT>
struct static_scene {
    /// Takes A (linear time); throws invalid_input for an empty polygon or
    /// one beyond NT's range (see accepted_polygon).
    explicit static_scene(const polygon& a)
        : shape(accepted_polygon<NT>(a, "static")),
          covering(shape, shape.centroid()),
          radius(bounding_radius(shape, shape.centroid())),
          scale(coordinate_scale(shape)) {}
    static_scene(const static_scene&) = delete;
    static_scene& operator=(const static_scene&) = delete;

    polygon shape;                   ///< A as given (rings reoriented)
    triangle_covering<NT> covering;  ///< refers to `shape`
    double radius;                   ///< bounds the distance from the centroid to A
    double scale;                    ///< largest absolute coordinate of A

    /// A's influence areas, which index `covering` (built on first use, O(n)
    /// with n edges; thread-safe).
    const influence_areas<NT>& areas() const { return areas_.get([this] { return influence_areas<NT>(covering); }); }
    /// A's edge tree in A's frame (built on first use, O(n log n); thread-safe).
    const edge_tree& tree() const { return tree_.get([this] { return edge_tree(shape); }); }
    /// Bytes of the heap blocks held by the parts built so far (for an exact
    /// NT, the numbers' own limbs are not counted).
    std::size_t heap_bytes() const {
        std::size_t bytes = shape.heap_bytes() + covering.heap_bytes();
        if (const edge_tree* t = tree_.if_built()) bytes += t->heap_bytes();
        if (const influence_areas<NT>* i = areas_.if_built()) bytes += i->heap_bytes();
        return bytes;
    }

private:
    built_once<influence_areas<NT>> areas_;
    built_once<edge_tree> tree_;
};

/// The moving polygon B prepared in its own frame: its centroid and bounding
/// radius (linear time), and its edge tree built by the first frame that
/// asks for it. Immutable to its users and safe to share: one B serves
/// detectors for many A, in any number of threads (see prepare_moving).
template <class NT>
struct moving_scene {
    /// Takes B (linear time); throws invalid_input for an empty polygon or
    /// one beyond NT's range (see accepted_polygon).
    explicit moving_scene(const polygon& b)
        : shape(accepted_polygon<NT>(b, "moving")),
          centroid(shape.centroid()),
          radius(bounding_radius(shape, centroid)),
          scale(coordinate_scale(shape)) {}
    moving_scene(const moving_scene&) = delete;
    moving_scene& operator=(const moving_scene&) = delete;

    polygon shape;           ///< B in its own frame (rings reoriented)
    point<double> centroid;  ///< B's centroid in its own frame
    double radius;           ///< bounds the distance from the centroid to B
    double scale;            ///< largest absolute coordinate of B

    /// B's edge tree in B's own frame (built on first use; thread-safe).
    const edge_tree& tree() const { return tree_.get([this] { return edge_tree(shape); }); }
    /// Bytes of the heap blocks held by the parts built so far.
    std::size_t heap_bytes() const {
        const edge_tree* t = tree_.if_built();
        return shape.heap_bytes() + (t ? t->heap_bytes() : 0);
    }

private:
    built_once<edge_tree> tree_;
};

/// A prepared for detectors in NT, to be shared by many (detector's
/// constructor from prepared polygons). Throws as static_scene's constructor.
template <class NT>
std::shared_ptr<const static_scene<NT>> prepare_static(const polygon& a) {
    return std::make_shared<const static_scene<NT>>(a);
}
/// B prepared for detectors in NT, to be shared by many. Throws as
/// moving_scene's constructor.
template <class NT>
std::shared_ptr<const moving_scene<NT>> prepare_moving(const polygon& b) {
    return std::make_shared<const moving_scene<NT>>(b);
}

/// The moving polygon B: given in its own frame, posed once per frame. A frame
/// first poses the centroid in double; then, if a filter passes, every vertex
/// in double. These rounded positions serve conservative filters only. The NT
/// centroid and vertices are posed when a decision asks for them, so an exact
/// type pays only for what the frame's decisions need.
template <class NT>
class posed_polygon {
public:
    /// B in its own frame, not yet posed; throws invalid_input for a polygon
    /// empty or beyond NT's range (see accepted_polygon).
    explicit posed_polygon(const polygon& b) : posed_polygon(prepare_moving<NT>(b)) {}
    /// B prepared (shared with other detectors), not yet posed.
    explicit posed_polygon(std::shared_ptr<const moving_scene<NT>> b)
        : scene_(std::move(b)), shape_(scene_->shape), local_centroid_(scene_->centroid), radius_(scene_->radius) {
        vertices_.resize(shape_.size());
        approximate_.resize(shape_.size());
        stamp_.assign(shape_.size(), 0);
        approximate_stamp_.assign(shape_.size(), 0);
    }

    /// B as prepared (shared).
    const moving_scene<NT>& scene() const { return *scene_; }
    /// B in its own frame.
    const polygon& shape() const { return shape_; }
    /// B's number of vertices (and edges).
    std::size_t size() const { return vertices_.size(); }
    /// Bounds the distance from the posed centroid to every posed vertex.
    double radius() const { return radius_; }
    /// The posed centroid in NT.
    const point<NT>& centroid() {
        if (centroid_stamp_ != frame_) {
            centroid_ = pose_.apply<NT>(local_centroid_);
            centroid_stamp_ = frame_;
        }
        return centroid_;
    }
    /// The posed centroid in double (rounded; for filters only).
    const point<double>& approximate_centroid() const { return approximate_centroid_; }

    /// Sets the frame's pose and poses the centroid in double.
    void place(const rotation_pose& t) {
        pose_ = t;
        ++frame_;
        approximate_centroid_ = t.apply<double>(local_centroid_);
    }
    /// Poses every vertex in double (rounded; for conservative filters only).
    void place_approximate() {
        for (std::size_t j = 0; j < approximate_.size(); ++j) {
            approximate_[j] = pose_.apply<double>(shape_.vertex(j));
            approximate_stamp_[j] = frame_;
        }
    }
    /// Vertex j posed in double by the last place_approximate() (rounded).
    const point<double>& approximate(std::size_t j) const { return approximate_[j]; }
    /// Vertex j posed in double for this frame, posed now if it was not yet
    /// (for frames that look at a few vertices only).
    const point<double>& approximate_now(std::size_t j) {
        if (approximate_stamp_[j] != frame_) {
            approximate_[j] = pose_.apply<double>(shape_.vertex(j));
            approximate_stamp_[j] = frame_;
        }
        return approximate_[j];
    }

    /// Vertex j posed in NT.
    const point<NT>& vertex(std::size_t j) {
        if (stamp_[j] != frame_) {
            vertices_[j] = pose_.apply<NT>(shape_.vertex(j));
            stamp_[j] = frame_;
        }
        return vertices_[j];
    }
    /// The end vertex of edge j, posed in NT.
    const point<NT>& end(std::size_t j) { return vertex(shape_.next(j)); }
    /// Bytes of the heap blocks held for the frames (capacities of the
    /// per-vertex arrays; the prepared B is counted by its own heap_bytes).
    std::size_t heap_bytes() const {
        return vertices_.capacity() * sizeof(point<NT>) +
               approximate_.capacity() * sizeof(point<double>) +
               (stamp_.capacity() + approximate_stamp_.capacity()) * sizeof(std::uint64_t);
    }
    /// Every vertex posed in NT.
    const std::vector<point<NT>>& vertices() {
        for (std::size_t j = 0; j < vertices_.size(); ++j) vertex(j);
        return vertices_;
    }

private:
    std::shared_ptr<const moving_scene<NT>> scene_;
    const polygon& shape_;  ///< scene_->shape
    point<double> local_centroid_;
    double radius_;
    rotation_pose pose_{pose{}};
    std::uint64_t frame_ = 0;
    std::uint64_t centroid_stamp_ = 0;
    point<double> approximate_centroid_;
    point<NT> centroid_;
    std::vector<point<NT>> vertices_;
    std::vector<point<double>> approximate_;
    std::vector<std::uint64_t> stamp_;
    std::vector<std::uint64_t> approximate_stamp_;
};

/// The reach of the moving polygon for a separation distance d: an upper
/// bound of r_B + d, the distance from B's centroid within which an edge of A
/// must lie to come within d of B.
inline double moving_reach(double moving_radius, double distance) {
    return std::nextafter((moving_radius + distance) * (1 + pose_scale_widening), std::numeric_limits<double>::infinity());
}

/// Squared distance between two NT points.
template <class NT>
NT squared_distance(const point<NT>& a, const point<NT>& b) {
    const NT dx = a.x - b.x, dy = a.y - b.y;
    return dx * dx + dy * dy;
}

}  // namespace influence2d
