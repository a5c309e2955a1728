#pragma once
// What the detectors precompute for the static polygon, and the moving
// polygon posed in NT for a frame.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/influence/influence_areas.hpp"

namespace influence2d {

/// The static polygon A: its covering from its centroid, its influence areas
/// and its bounding radius. Immutable once built, so detectors share it.
template <class NT>
struct static_scene {
    explicit static_scene(const polygon& a)
        : shape(a),
          covering(shape, shape.centroid()),
          areas(covering),
          radius(bounding_radius(shape, shape.centroid())),
          scale(coordinate_scale(shape)) {}
    static_scene(const static_scene&) = delete;
    static_scene& operator=(const static_scene&) = delete;

    polygon shape;
    triangle_covering<NT> covering;  ///< refers to `shape`
    influence_areas<NT> areas;       ///< refers to `covering`
    double radius;                   ///< bounds the distance from the centroid to A
    double scale;                    ///< largest absolute coordinate of A
};

/// The moving polygon B: given in its own frame, posed once per frame in NT.
template <class NT>
class posed_polygon {
public:
    explicit posed_polygon(const polygon& b)
        : shape_(b), local_centroid_(b.centroid()), radius_(bounding_radius(b, b.centroid())) {
        vertices_.resize(b.size());
    }

    const polygon& shape() const { return shape_; }
    /// Bounds the distance from the posed centroid to every posed vertex.
    double radius() const { return radius_; }
    const point<NT>& centroid() const { return centroid_; }
    const std::vector<point<NT>>& vertices() const { return vertices_; }
    const point<NT>& vertex(std::size_t j) const { return vertices_[j]; }
    const point<NT>& end(std::size_t j) const { return vertices_[shape_.next(j)]; }

    /// Poses the centroid only: all a frame needs until a filter passes.
    void place_centroid(const rotation_pose& t) { centroid_ = t.apply<NT>(local_centroid_); }
    /// Poses every vertex.
    void place_vertices(const rotation_pose& t) {
        for (std::size_t j = 0; j < vertices_.size(); ++j) vertices_[j] = t.apply<NT>(shape_.vertex(j));
    }

private:
    polygon shape_;
    point<double> local_centroid_;
    double radius_;
    point<NT> centroid_;
    std::vector<point<NT>> vertices_;
};

/// The reach of the moving polygon for a separation distance d: an upper
/// bound of r_B + d, the distance from B's centroid within which an edge of A
/// must lie to come within d of B.
inline double moving_reach(double moving_radius, double distance) {
    return std::nextafter((moving_radius + distance) * (1 + 1e-15), std::numeric_limits<double>::infinity());
}

/// Squared distance between two NT points.
template <class NT>
NT squared_distance(const point<NT>& a, const point<NT>& b) {
    const NT dx = a.x - b.x, dy = a.y - b.y;
    return dx * dx + dy * dy;
}

template <class NT>
point<double> to_double_point(const point<NT>& p) {
    return {number_traits<NT>::to_double(p.x), number_traits<NT>::to_double(p.y)};
}

}  // namespace influence2d
