#pragma once
// The paper's trajectories (method.md section 8) as sequences of poses.

#include <cmath>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/influence/bounds.hpp"

namespace influence2d {

/// B orbits A's centroid O_A: frame k is the rigid rotation by phi_k = 2 pi k / frames
/// about O_A of B placed with its centroid at distance rho = R_A + r_B + gap to
/// the right of O_A (R_A, r_B the bounding radii about the centroids). B turns
/// with the orbit; the last frame is one step before the start. With gap > 0
/// the bounding circles never meet, so no frame collides.
inline std::vector<pose> circular_trajectory(const polygon& a, const polygon& b, std::size_t frames = 90000,
                                             double gap = 9.0) {
    const point<double> o = a.centroid(), cb = b.centroid();
    const double rho = bounding_radius(a, o) + bounding_radius(b, cb) + gap;
    std::vector<pose> poses;
    poses.reserve(frames);
    for (std::size_t k = 0; k < frames; ++k) {
        const double phi = 2 * 3.141592653589793 * static_cast<double>(k) / static_cast<double>(frames);
        const double c = std::cos(phi), s = std::sin(phi);
        // Centroid to O_A + rho (cos phi, sin phi): t = that - R(phi) c_B.
        poses.push_back({o.x + rho * c - (c * cb.x - s * cb.y), o.y + rho * s - (s * cb.x + c * cb.y), phi});
    }
    return poses;
}

/// A point well inside A: the first vertex a_k (in stored order) for which
/// a_k + (O_A - a_k) / 20 is inside A, that point; A's first vertex if none is.
inline point<double> interior_target(const polygon& a) {
    const point<double> o = a.centroid();
    for (std::size_t k = 0; k < a.size(); ++k) {
        const point<double>& v = a.vertex(k);
        const point<double> t{v.x + (o.x - v.x) / 20, v.y + (o.y - v.y) / 20};
        if (locate(a, a.vertices(), o, t) == location::inside) return t;
    }
    return a.vertex(0);
}

/// B approaches A along a straight line without turning (theta = 0): the last
/// frame puts B's first vertex on a point well inside A (interior_target), so
/// the trajectory ends in collision; the first frame is that pose moved back by
/// 2 (R_A + r_B) + gap along the direction from O_A to the target, where the
/// bounding circles are at least `gap` apart. Frames are evenly spaced.
inline std::vector<pose> linear_trajectory(const polygon& a, const polygon& b, std::size_t frames = 9000,
                                           double gap = 9.0) {
    const point<double> o = a.centroid();
    const point<double> target = interior_target(a);
    double ux = target.x - o.x, uy = target.y - o.y;
    const double len = std::hypot(ux, uy);
    if (len > 0) {
        ux /= len;
        uy /= len;
    } else {
        ux = 1;
        uy = 0;
    }
    const double back = 2 * (bounding_radius(a, o) + bounding_radius(b, b.centroid())) + gap;
    const point<double> end{target.x - b.vertex(0).x, target.y - b.vertex(0).y};
    const point<double> start{end.x + ux * back, end.y + uy * back};
    std::vector<pose> poses;
    poses.reserve(frames);
    for (std::size_t k = 0; k < frames; ++k) {
        if (k + 1 == frames) {
            poses.push_back({end.x, end.y, 0});
            break;
        }
        const double f = static_cast<double>(k) / static_cast<double>(frames - 1);
        poses.push_back({start.x + (end.x - start.x) * f, start.y + (end.y - start.y) * f, 0});
    }
    return poses;
}

}  // namespace influence2d
