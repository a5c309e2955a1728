// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The moving polygon posed in NT for a frame of a detector: posed lazily, in
/// double for the filters and in NT for the decisions.

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d {

/// The moving polygon B: given in its own frame, posed once per frame, by the
/// detectors and by the separation query. A frame first poses the centroid in
/// double; then every vertex in double at once (place_approximate) or each
/// when asked (approximate_now). These rounded positions serve conservative
/// filters only (their error: posing_margin, or posing_error for the
/// separation's bounds). The NT centroid and vertices are posed when a
/// decision asks for them, so an exact type pays only for what the frame's
/// decisions need: in an exact NT not even a default value of a vertex is
/// made before it is asked (each costs allocations).
template <class NT>
class posed_polygon {
public:
    /// B in its own frame, not yet posed; throws invalid_input for a polygon
    /// empty or beyond NT's range (see accepted_polygon).
    explicit posed_polygon(const polygon& b) : posed_polygon(prepare_moving<NT>(b)) {}
    /// B prepared (shared with other detectors), not yet posed.
    explicit posed_polygon(std::shared_ptr<const moving_scene<NT>> b)
        : scene_(std::move(b)), shape_(scene_->shape), local_centroid_(scene_->centroid), radius_(scene_->radius) {
        slots_.resize(shape_.size());
        approximate_.resize(shape_.size());
        stamp_.assign(shape_.size(), 0);
        approximate_stamp_.assign(shape_.size(), 0);
    }

    /// B as prepared (shared).
    const moving_scene<NT>& scene() const { return *scene_; }
    /// B in its own frame.
    const polygon& shape() const { return shape_; }
    /// B's number of vertices (and edges).
    std::size_t size() const { return slots_.size(); }
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

    /// The frame's pose (the last place()).
    const rotation_pose& placement() const { return pose_; }

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

    /// Every vertex posed in double for this frame (those not yet posed now).
    const std::vector<point<double>>& approximate_all() {
        for (std::size_t j = 0; j < approximate_.size(); ++j) approximate_now(j);
        return approximate_;
    }

    /// Vertex j posed in NT. (In an exact NT the reference stays valid until
    /// the frame's first call of vertices(), which gathers the vertices.)
    const point<NT>& vertex(std::size_t j) {
        if constexpr (made_when_asked) {
            if (all_frame_ == frame_) return all_[j];
        }
        if (stamp_[j] != frame_) {
            slots_[j] = pose_.apply<NT>(shape_.vertex(j));
            stamp_[j] = frame_;
        }
        if constexpr (made_when_asked) {
            return *slots_[j];
        } else {
            return slots_[j];
        }
    }
    /// The end vertex of edge j, posed in NT.
    const point<NT>& end(std::size_t j) { return vertex(shape_.next(j)); }
    /// Bytes of the heap blocks held for the frames (capacities of the
    /// per-vertex arrays; the prepared B is counted by its own heap_bytes).
    std::size_t heap_bytes() const {
        return slots_.capacity() * sizeof(slot) + all_.capacity() * sizeof(point<NT>) +
               approximate_.capacity() * sizeof(point<double>) +
               (stamp_.capacity() + approximate_stamp_.capacity()) * sizeof(std::uint64_t);
    }
    /// Every vertex posed in NT.
    const std::vector<point<NT>>& vertices() {
        if constexpr (made_when_asked) {
            if (all_frame_ != frame_) {
                // The vertices made so far are moved, the others made.
                all_.clear();
                all_.reserve(slots_.size());
                for (std::size_t j = 0; j < slots_.size(); ++j) {
                    if (stamp_[j] == frame_) {
                        all_.push_back(std::move(*slots_[j]));
                    } else {
                        all_.push_back(pose_.apply<NT>(shape_.vertex(j)));
                    }
                    slots_[j].reset();
                }
                all_frame_ = frame_;
            }
            return all_;
        } else {
            for (std::size_t j = 0; j < slots_.size(); ++j) vertex(j);
            return slots_;
        }
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
    /// In an exact NT a vertex is made on first use only (see the class).
    static constexpr bool made_when_asked = number_traits<NT>::category == number_category::exact;
    using slot = std::conditional_t<made_when_asked, std::optional<point<NT>>, point<NT>>;
    std::vector<slot> slots_;
    std::vector<point<NT>> all_;  ///< every vertex, gathered by vertices() (exact NT)
    std::uint64_t all_frame_ = 0;
    std::vector<point<double>> approximate_;
    std::vector<std::uint64_t> stamp_;
    std::vector<std::uint64_t> approximate_stamp_;
};

/// The reach of the moving polygon for a separation distance d: an upper
/// bound of r_B + d, the distance from B's centroid within which an edge of A
/// must lie to come within d of B.
inline double moving_reach(double moving_radius, double distance) {
    return std::nextafter((moving_radius + distance) * (1 + pose_scale_widening),
                          std::numeric_limits<double>::infinity());
}

}  // namespace influence2d
