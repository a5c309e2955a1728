// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// What the detectors precompute for the static polygon, and the moving
/// polygon posed in NT for a frame.

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/influence/bounds.hpp"
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

/// The static polygon A: its covering from its centroid, its influence areas
/// and its bounding radius. Immutable once built, so detectors share it.
template <class NT>
struct static_scene {
    /// Builds everything from A (O(n log n) for n edges); throws invalid_input
    /// for an empty polygon or one beyond NT's range (see accepted_polygon).
    explicit static_scene(const polygon& a)
        : shape(accepted_polygon<NT>(a, "static")),
          covering(shape, shape.centroid()),
          areas(covering),
          radius(bounding_radius(shape, shape.centroid())),
          scale(coordinate_scale(shape)) {}
    static_scene(const static_scene&) = delete;
    static_scene& operator=(const static_scene&) = delete;

    polygon shape;                   ///< A as given (rings reoriented)
    triangle_covering<NT> covering;  ///< refers to `shape`
    influence_areas<NT> areas;       ///< refers to `covering`
    double radius;                   ///< bounds the distance from the centroid to A
    double scale;                    ///< largest absolute coordinate of A
};

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
    explicit posed_polygon(const polygon& b)
        : shape_(accepted_polygon<NT>(b, "moving")), local_centroid_(b.centroid()), radius_(bounding_radius(b, b.centroid())) {
        vertices_.resize(b.size());
        approximate_.resize(b.size());
        stamp_.assign(b.size(), 0);
        approximate_stamp_.assign(b.size(), 0);
    }

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
    /// Bytes of the heap blocks held (capacities of the per-vertex arrays).
    std::size_t heap_bytes() const {
        return shape_.heap_bytes() + vertices_.capacity() * sizeof(point<NT>) +
               approximate_.capacity() * sizeof(point<double>) +
               (stamp_.capacity() + approximate_stamp_.capacity()) * sizeof(std::uint64_t);
    }
    /// Every vertex posed in NT.
    const std::vector<point<NT>>& vertices() {
        for (std::size_t j = 0; j < vertices_.size(); ++j) vertex(j);
        return vertices_;
    }

private:
    polygon shape_;
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

/// p rounded to double, coordinate by coordinate (number_traits::to_double).
template <class NT>
point<double> to_double_point(const point<NT>& p) {
    return {number_traits<NT>::to_double(p.x), number_traits<NT>::to_double(p.y)};
}

}  // namespace influence2d
