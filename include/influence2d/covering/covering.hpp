// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The signed triangle covering of a polygon and the barycentric signs of a
/// point in its triangles (docs/method.md sections 2 and 3).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "influence2d/assert.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/predicates/orientation.hpp"

namespace influence2d {

/// Signs of the barycentric coordinates of a point P in the covering triangle
/// T_i = (O, V_i, V_i+1): alpha for O, beta for V_i, gamma for V_i+1. Each is the
/// sign of a signed area times sigma_i, so no division is ever made. All three
/// are 0 for a degenerate triangle (sigma_i == 0).
struct barycentric_signs {
    int alpha = 0;  ///< > 0: P on O's side of the edge's line; < 0: beyond it; 0: on it
    int beta = 0;   ///< sign of the coordinate of V_i; >= 0 with gamma >= 0: P in the edge's cone
    int gamma = 0;  ///< sign of the coordinate of V_i+1; P in T_i when all three are >= 0
};

namespace covering_detail {

/// Whether every ring of `shape` is stored with its interior on the left, as
/// the winding rule of the covering needs: no outer ring clockwise, no hole
/// counter-clockwise (exact signs of the rings' areas). Linear time; for
/// assertions.
inline bool rings_stored_interior_left(const polygon& shape) {
    std::vector<point<double>> ring;
    for (std::size_t r = 0; r < shape.ring_count(); ++r) {
        const auto first = shape.vertices().begin();
        ring.assign(first + static_cast<std::ptrdiff_t>(shape.ring_begin(r)),
                    first + static_cast<std::ptrdiff_t>(shape.ring_end(r)));
        const int turn = polygon::signed_area_sign(ring);
        if (shape.role(r) == ring_role::outer ? turn < 0 : turn > 0) return false;
    }
    return true;
}

}  // namespace covering_detail

/// The covering triangles of a polygon's edges from one origin O: triangle i is
/// (O, V_i, V_next(i)) with sign sigma_i = orientation(O, V_i, V_next(i)).
/// Vertices are held in NT; the topology (rings, next) is the polygon's.
/// Any origin is valid; an edge collinear with O (a zero-length edge
/// included) has sigma 0 and a flat triangle. Built in linear time: n
/// conversions and n orientation signs, exact when NT is.
template <class NT>
class triangle_covering {
public:
    /// An empty covering, to be assigned to.
    triangle_covering() = default;

    /// Covering of `shape` (its vertices converted to NT) from `origin`.
    /// Keeps a reference to `shape`, which must outlive the covering. For a
    /// filtered NT without exact fallback, may throw uncertain_sign.
    triangle_covering(const polygon& shape, const point<double>& origin) : shape_(&shape) {
        INFLUENCE2D_ASSERT(covering_detail::rings_stored_interior_left(shape),
                           "a ring is stored with its interior on the right: the winding numbers would be wrong");
        vertices_.reserve(shape.size());
        for (const auto& v : shape.vertices()) vertices_.push_back(to_point<NT>(v));
        origin_ = to_point<NT>(origin);
        sigma_.resize(shape.size());
        for (std::size_t i = 0; i < shape.size(); ++i)
            sigma_[i] = static_cast<std::int8_t>(orientation(origin_, start(i), end(i)));
    }

    /// The polygon covered.
    const polygon& shape() const { return *shape_; }
    /// The origin O in NT.
    const point<NT>& origin() const { return origin_; }
    /// The polygon's vertices in NT, in its stored order.
    const std::vector<point<NT>>& vertices() const { return vertices_; }
    /// Bytes of the heap blocks held (capacities; for an exact NT, the
    /// numbers' own limbs are not counted).
    std::size_t heap_bytes() const {
        return vertices_.capacity() * sizeof(point<NT>) + sigma_.capacity() * sizeof(std::int8_t);
    }
    /// The number of triangles, one per edge.
    std::size_t size() const { return vertices_.size(); }
    /// V_i, the start of edge i, in NT.
    const point<NT>& start(std::size_t i) const {
        INFLUENCE2D_ASSERT(i < size(), "edge index beyond the covering");
        return vertices_[i];
    }
    /// V_i+1, the end of edge i (the next vertex on its ring), in NT.
    const point<NT>& end(std::size_t i) const {
        INFLUENCE2D_ASSERT(i < size(), "edge index beyond the covering");
        return vertices_[shape_->next(i)];
    }
    /// orientation(O, V_i, V_i+1): +1, -1, or 0 for an edge collinear with O.
    int sigma(std::size_t i) const {
        INFLUENCE2D_ASSERT(i < size(), "edge index beyond the covering");
        return sigma_[i];
    }

    /// Barycentric signs of P in triangle i: three orientation signs times
    /// sigma_i, no division; all 0 when sigma_i is 0. Exact when NT is.
    barycentric_signs signs(std::size_t i, const point<NT>& p) const {
        const int s = sigma(i);
        if (s == 0) return {};
        return {orientation(p, start(i), end(i)) * s, orientation(origin_, p, end(i)) * s,
                orientation(origin_, start(i), p) * s};
    }

private:
    const polygon* shape_ = nullptr;
    std::vector<point<NT>> vertices_;
    point<NT> origin_;
    std::vector<std::int8_t> sigma_;
};

}  // namespace influence2d
