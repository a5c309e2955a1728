// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// What the detectors and queries precompute for the static polygon A and
/// the moving polygon B, shared by many of them in any number of threads.

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
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
#include "influence2d/core/shortest_decimal.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/influence/edge_tree.hpp"
#include "influence2d/influence/influence_areas.hpp"
#include "influence2d/predicates/convexity.hpp"
#include "influence2d/scene/inner_disc.hpp"
#include "influence2d/scene/interior_cells.hpp"
#include "influence2d/scene/reaching_vertices.hpp"

namespace influence2d {

/// Whether NT is a floating type whose largest value is below double's
/// (float): the vertices of a polygon NT takes are then checked against
/// its range (accepted_polygon). A floating type that std::numeric_limits
/// does not describe (GCC's __float128 in its GNU mode, whose limits are
/// all 0) is not.
template <class NT>
inline constexpr bool range_below_double_v = [] {
    if constexpr (std::is_floating_point_v<NT> && std::numeric_limits<NT>::is_specialized)
        return static_cast<double>(std::numeric_limits<NT>::max()) < std::numeric_limits<double>::max();
    else
        return false;
}();

/// The polygon p, checked to be one a detector in NT can take: not empty (a
/// default-constructed polygon has no ring), and within the range of a
/// floating NT narrower than double (float). Throws invalid_input saying
/// which polygon (`which`) is empty, or naming its first vertex beyond
/// NT's range. Other types take every finite double.
template <class NT>
const polygon& accepted_polygon(const polygon& p, const char* which) {
    if (p.size() == 0) throw invalid_input(std::string("the ") + which + " polygon is empty (it has no ring)");
    if constexpr (range_below_double_v<NT>) {
        constexpr double top = static_cast<double>(std::numeric_limits<NT>::max());
        for (const point<double>& v : p.vertices())
            if (std::fabs(v.x) > top || std::fabs(v.y) > top)
                throw invalid_input(std::string("the ") + which + " polygon's vertex (" + shortest_decimal(v.x) + ", " +
                                    shortest_decimal(v.y) + ") is beyond the range of " + number_traits<NT>::name);
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
          scale(coordinate_scale(shape)),
          convex(is_convex_polygon(shape)) {}
    static_scene(const static_scene&) = delete;
    static_scene& operator=(const static_scene&) = delete;

    polygon shape;                   ///< A as given (rings reoriented)
    triangle_covering<NT> covering;  ///< refers to `shape`
    double radius;                   ///< bounds the distance from the centroid to A
    double scale;                    ///< largest absolute coordinate of A
    bool convex;                     ///< A is one convex ring (is_convex_polygon, exact)

    /// A's influence areas, which index `covering` (built on first use, O(n)
    /// with n edges; thread-safe).
    const influence_areas<NT>& areas() const {
        return areas_.get([this] { return influence_areas<NT>(covering); });
    }
    /// A's edge tree in A's frame (built on first use, O(n log n); thread-safe).
    const edge_tree& tree() const {
        return tree_.get([this] { return edge_tree(shape); });
    }
    /// The edge tree if some caller built it, else nullptr (never builds).
    const edge_tree* tree_if_built() const { return tree_.if_built(); }
    /// The cells deep in A's region, in A's frame (built on first use;
    /// thread-safe).
    const interior_cells& interior() const {
        return interior_.get([this] { return interior_cells(shape); });
    }
    /// The deep cells if some caller built them, else nullptr (never builds).
    const interior_cells* interior_if_built() const { return interior_.if_built(); }
    /// A's vertices reaching farthest from its centroid in each of eight
    /// directions (built on first use, linear time; thread-safe).
    const reaching_vertices& reaching() const {
        return reaching_.get([this] { return reaching_vertices(shape, shape.centroid()); });
    }
    /// A disc about the centre of A's box in A's closed region (inner_disc;
    /// radius 0: none), in A's frame (built on first use, linear time;
    /// thread-safe).
    const disc& inner() const {
        return inner_.get([this] { return inner_disc(shape); });
    }
    /// Bytes of the heap blocks held by the parts built so far (for an exact
    /// NT, the numbers' own limbs are not counted).
    std::size_t heap_bytes() const {
        std::size_t bytes = shape.heap_bytes() + covering.heap_bytes();
        if (const edge_tree* t = tree_.if_built()) bytes += t->heap_bytes();
        if (const influence_areas<NT>* i = areas_.if_built()) bytes += i->heap_bytes();
        if (const interior_cells* c = interior_.if_built()) bytes += c->heap_bytes();
        return bytes;
    }

private:
    built_once<influence_areas<NT>> areas_;
    built_once<edge_tree> tree_;
    built_once<interior_cells> interior_;
    built_once<reaching_vertices> reaching_;
    built_once<disc> inner_;
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
          scale(coordinate_scale(shape)),
          convex(is_convex_polygon(shape)) {}
    moving_scene(const moving_scene&) = delete;
    moving_scene& operator=(const moving_scene&) = delete;

    polygon shape;           ///< B in its own frame (rings reoriented)
    point<double> centroid;  ///< B's centroid in its own frame
    double radius;           ///< bounds the distance from the centroid to B
    double scale;            ///< largest absolute coordinate of B
    bool convex;             ///< B is one convex ring (is_convex_polygon, exact)

    /// B's edge tree in B's own frame (built on first use; thread-safe).
    const edge_tree& tree() const {
        return tree_.get([this] { return edge_tree(shape); });
    }
    /// The edge tree if some caller built it, else nullptr (never builds).
    const edge_tree* tree_if_built() const { return tree_.if_built(); }
    /// The cells deep in B's region, in B's own frame (built on first use;
    /// thread-safe).
    const interior_cells& interior() const {
        return interior_.get([this] { return interior_cells(shape); });
    }
    /// The deep cells if some caller built them, else nullptr (never builds).
    const interior_cells* interior_if_built() const { return interior_.if_built(); }
    /// B's vertices reaching farthest from its centroid in each of eight
    /// directions, in B's own frame (built on first use, linear time;
    /// thread-safe).
    const reaching_vertices& reaching() const {
        return reaching_.get([this] { return reaching_vertices(shape, centroid); });
    }
    /// A disc about the centre of B's box in B's closed region (inner_disc;
    /// radius 0: none), in B's own frame (built on first use, linear time;
    /// thread-safe).
    const disc& inner() const {
        return inner_.get([this] { return inner_disc(shape); });
    }
    /// Bytes of the heap blocks held by the parts built so far.
    std::size_t heap_bytes() const {
        const edge_tree* t = tree_.if_built();
        const interior_cells* c = interior_.if_built();
        return shape.heap_bytes() + (t ? t->heap_bytes() : 0) + (c ? c->heap_bytes() : 0);
    }

private:
    built_once<edge_tree> tree_;
    built_once<interior_cells> interior_;
    built_once<reaching_vertices> reaching_;
    built_once<disc> inner_;
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
/// A prepared scaled by 2^shift (core/range_scaling.hpp); as given for 0.
template <class NT>
std::shared_ptr<const static_scene<NT>> prepare_static(const polygon& a, int shift) {
    return shift ? prepare_static<NT>(a.scaled_by_power_of_two(shift)) : prepare_static<NT>(a);
}
/// B prepared scaled by 2^shift (core/range_scaling.hpp); as given for 0.
template <class NT>
std::shared_ptr<const moving_scene<NT>> prepare_moving(const polygon& b, int shift) {
    return shift ? prepare_moving<NT>(b.scaled_by_power_of_two(shift)) : prepare_moving<NT>(b);
}

}  // namespace influence2d
