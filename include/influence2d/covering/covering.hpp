#pragma once
// The signed triangle covering of a polygon and the barycentric signs of a
// point in its triangles (method.md sections 2 and 3).

#include <cstdint>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/predicates/orientation.hpp"

namespace influence2d {

/// Signs of the barycentric coordinates of a point P in the covering triangle
/// T_i = (O, V_i, V_i+1): alpha for O, beta for V_i, gamma for V_i+1. Each is the
/// sign of a signed area times sigma_i, so no division is ever made. All three
/// are 0 for a degenerate triangle (sigma_i == 0).
struct barycentric_signs {
    int alpha = 0;  ///< > 0: P on O's side of the edge's line; < 0: beyond it
    int beta = 0;   ///< >= 0 together with gamma >= 0: P in the edge's cone
    int gamma = 0;
};

/// The covering triangles of a polygon's edges from one origin O: triangle i is
/// (O, V_i, V_next(i)) with sign sigma_i = orientation(O, V_i, V_next(i)).
/// Vertices are held in NT; the topology (rings, next) is the polygon's.
template <class NT>
class triangle_covering {
public:
    triangle_covering() = default;

    /// Covering of `shape` (its vertices converted to NT) from `origin`.
    triangle_covering(const polygon& shape, const point<double>& origin) : shape_(&shape) {
        using tr = number_traits<NT>;
        vertices_.reserve(shape.size());
        for (const auto& v : shape.vertices()) vertices_.push_back({tr::from_double(v.x), tr::from_double(v.y)});
        origin_ = {tr::from_double(origin.x), tr::from_double(origin.y)};
        sigma_.resize(shape.size());
        for (std::size_t i = 0; i < shape.size(); ++i)
            sigma_[i] = static_cast<std::int8_t>(orientation(origin_, start(i), end(i)));
    }

    const polygon& shape() const { return *shape_; }
    const point<NT>& origin() const { return origin_; }
    const std::vector<point<NT>>& vertices() const { return vertices_; }
    std::size_t size() const { return vertices_.size(); }
    const point<NT>& start(std::size_t i) const { return vertices_[i]; }
    const point<NT>& end(std::size_t i) const { return vertices_[shape_->next(i)]; }
    /// orientation(O, V_i, V_i+1): +1, -1, or 0 for an edge collinear with O.
    int sigma(std::size_t i) const { return sigma_[i]; }

    /// Barycentric signs of P in triangle i.
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
