// SPDX-License-Identifier: BSL-1.0
#pragma once
// Poses of B against A for the detector tests: random poses near contact
// (influence2d::random_poses about A's centroid, within the reach of the two
// bounding circles), exact touching poses with their one-ulp neighbours, and
// a deterministic approach from apart to overlapping.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "support/random.hpp"

namespace test_poses {

using influence2d::point;
using influence2d::polygon;
using influence2d::pose;

/// The largest distance from c to a vertex of p.
inline double radius(const polygon& p, const point<double>& c) {
    double r = 0;
    for (const auto& v : p.vertices()) r = std::max(r, std::hypot(v.x - c.x, v.y - c.y));
    return r;
}

/// The distance between the centroids beyond which B, however turned, is
/// farther than `margin` from A: the sum of the bounding radii about the
/// centroids, plus the margin.
inline double reach(const polygon& a, const polygon& b, double margin = 0) {
    return radius(a, a.centroid()) + radius(b, b.centroid()) + margin;
}

/// `count` independent random poses with B's centroid between
/// inner_share * R and R from A's centroid (R = reach(a, b, margin)), in a
/// random direction, B turned at random: with inner_share about 0.6, most
/// of them are close calls near contact.
inline std::vector<pose> near_contact(const polygon& a, const polygon& b, std::size_t count, double inner_share,
                                      double margin, std::uint64_t seed) {
    const double r = reach(a, b, margin);
    return influence2d::random_poses(a, b, count, inner_share * r, r, seed);
}

/// `count` poses at theta = 0 that put B against a point of A's boundary (a
/// vertex, or the midpoint of an edge), B's extreme vertex against the
/// outward normal there on it; each is followed by the pose with tx, then
/// the pose with ty, one ulp away. On coordinates on a binary grid the
/// touching poses are exact, and most of them touch.
inline std::vector<pose> touching(const polygon& a, const polygon& b, test_random::rng& r, std::size_t count) {
    std::vector<pose> out;
    const double inf = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t i = r.index(a.size());
        const point<double> v0 = a.vertex(i), v1 = a.vertex(a.next(i));
        point<double> at, n;
        if (r.index(2) == 0) {
            // A vertex: the sum of the outward normals of its two edges.
            at = v0;
            std::size_t prev = i;
            while (a.next(prev) != i) prev = a.next(prev);
            const point<double> u = a.vertex(prev);
            n = {(v1.y - v0.y) + (v0.y - u.y), -(v1.x - v0.x) - (v0.x - u.x)};
        } else {
            at = {(v0.x + v1.x) / 2, (v0.y + v1.y) / 2};
            n = {v1.y - v0.y, -(v1.x - v0.x)};
        }
        std::size_t j = 0;
        double best = 0;
        for (std::size_t m = 0; m < b.size(); ++m) {
            const double dot = b.vertex(m).x * n.x + b.vertex(m).y * n.y;
            if (m == 0 || dot < best) {
                best = dot;
                j = m;
            }
        }
        const point<double> q = b.vertex(j);
        const pose touch{at.x - q.x, at.y - q.y, 0};
        out.push_back(touch);
        out.push_back({std::nextafter(touch.tx, k % 2 ? inf : -inf), touch.ty, 0});
        out.push_back({touch.tx, std::nextafter(touch.ty, k % 2 ? -inf : inf), 0});
    }
    return out;
}

/// The path of an approach, in fractions f = k / frames of the way.
struct approach_path {
    double heading = 0;  ///< the direction from A's centroid to B's at f = 0
    double veer = 0;     ///< added to the direction at f = 1
    double turn = 0;     ///< B's angle at f = 0
    double spin = 0;     ///< added to B's angle at f = 1
};

/// `frames` poses bringing B's centroid from 1.2 times the sum of the
/// bounding radii away from A's centroid (apart) to it (overlapping), along
/// the path: apart, then near contact, then overlapping.
inline std::vector<pose> approach(const polygon& a, const polygon& b, std::size_t frames, const approach_path& path) {
    const point<double> ca = a.centroid(), cb = b.centroid();
    const double start = 1.2 * (radius(a, ca) + radius(b, cb));
    std::vector<pose> out;
    for (std::size_t k = 0; k < frames; ++k) {
        const double f = static_cast<double>(k) / static_cast<double>(frames);
        const double dist = start * (1 - f), phi = path.heading + path.veer * f, theta = path.turn + path.spin * f;
        const double c = std::cos(theta), s = std::sin(theta);
        out.push_back({ca.x + dist * std::cos(phi) - (c * cb.x - s * cb.y),
                       ca.y + dist * std::sin(phi) - (s * cb.x + c * cb.y), theta});
    }
    return out;
}

}  // namespace test_poses
