// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The paper's trajectories (docs/method.md section 8) as sequences of poses.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/covering/inclusion.hpp"
#include "influence2d/influence/bounds.hpp"

namespace influence2d {

/// B orbits A's centroid O_A, turning with the orbit: frame k is the rigid
/// rotation by phi_k = 2 pi k / frames about O_A of B's starting placement, so
/// the last frame is one step before the start. At the start B is unrotated,
/// with its centroid on the horizontal through O_A, to the right, at the
/// distance where the point of B nearest to O_A's side (its leftmost vertex) is
/// R_A + gap from O_A (R_A: A's bounding radius about O_A). Seen from B, A turns
/// about O_A inside the disk of radius R_A, so with gap > 0 no frame collides,
/// and the polygons come within about `gap` whenever A's farthest vertices
/// sweep past B. `frames` == 0 gives no pose; the default 90,000 frames and
/// gap 9 are the paper's. Time linear in the frames and the vertices.
inline std::vector<pose> circular_trajectory(const polygon& a, const polygon& b, std::size_t frames = 90000,
                                             double gap = 9.0) {
    const point<double> o = a.centroid(), cb = b.centroid();
    double reach_left = 0;  // how far B extends to the left of its centroid
    for (const auto& v : b.vertices()) reach_left = std::max(reach_left, cb.x - v.x);
    const double rho = bounding_radius(a, o) + gap + reach_left;
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
/// a_k + (O_A - a_k) / 20 is inside A, that point; A's first vertex (on its
/// boundary) if none is. Located in double: for trajectories, not decisions.
/// Time up to quadratic in A's vertices (a locate per vertex tried).
inline point<double> interior_target(const polygon& a) {
    const point<double> o = a.centroid();
    for (std::size_t k = 0; k < a.size(); ++k) {
        const point<double>& v = a.vertex(k);
        const point<double> t{v.x + (o.x - v.x) / 20, v.y + (o.y - v.y) / 20};
        if (locate(a, a.vertices(), o, t) == location::inside) return t;
    }
    return a.vertex(0);
}

/// B approaches A along a straight line without turning (theta = 0), moving
/// in the direction -u, u the unit vector from O_A to a point well inside A
/// (interior_target). The last frame puts B's leading vertex (the one farthest
/// along -u from B's centroid) on that point, so the trajectory ends in
/// collision; the first frame is that pose moved back by 2 (R_A + r_B) + gap
/// along u, where the bounding circles are at least `gap` apart. Frames are
/// evenly spaced; `frames` == 1 gives the last pose alone, 0 no pose. The
/// defaults (9,000 frames, gap 9) are the paper's.
inline std::vector<pose> linear_trajectory(const polygon& a, const polygon& b, std::size_t frames = 9000,
                                           double gap = 9.0) {
    const point<double> o = a.centroid(), cb = b.centroid();
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
    std::size_t lead = 0;
    for (std::size_t j = 1; j < b.size(); ++j) {
        const auto along = [&](std::size_t k) { return (b.vertex(k).x - cb.x) * ux + (b.vertex(k).y - cb.y) * uy; };
        if (along(j) < along(lead)) lead = j;
    }
    const double back = 2 * (bounding_radius(a, o) + bounding_radius(b, cb)) + gap;
    const point<double> end{target.x - b.vertex(lead).x, target.y - b.vertex(lead).y};
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

/// Poses of B drawn independently (no coherence between frames): frame k puts
/// B's centroid at a point uniform in area in the annulus inner..outer about
/// A's centroid O_A and turns B by an angle uniform in [0, 2 pi). The way a
/// motion planner's sampler, a Monte Carlo study or a game with large steps
/// asks. Seeded and portable: the draws come from a splitmix64 sequence
/// (the top 53 bits of each word), never from a library distribution, so a
/// seed gives the same poses on every platform. Time linear in the frames.
/// Requires 0 <= inner <= outer.
inline std::vector<pose> random_poses(const polygon& a, const polygon& b, std::size_t frames, double inner,
                                      double outer, std::uint64_t seed) {
    const point<double> o = a.centroid(), cb = b.centroid();
    std::uint64_t state = seed;
    const auto uniform = [&state] {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        z ^= z >> 31;
        return static_cast<double>(z >> 11) * 0x1.0p-53;
    };
    const double two_pi = 2 * 3.141592653589793;
    std::vector<pose> poses;
    poses.reserve(frames);
    for (std::size_t k = 0; k < frames; ++k) {
        // Uniform in area: the radius's square is uniform between the bounds'.
        const double rho = std::sqrt(inner * inner + (outer * outer - inner * inner) * uniform());
        const double phi = two_pi * uniform(), theta = two_pi * uniform();
        const double c = std::cos(theta), s = std::sin(theta);
        const point<double> p{o.x + rho * std::cos(phi), o.y + rho * std::sin(phi)};
        // Centroid to p: t = p - R(theta) c_B.
        poses.push_back({p.x - (c * cb.x - s * cb.y), p.y - (s * cb.x + c * cb.y), theta});
    }
    return poses;
}

}  // namespace influence2d
