// SPDX-License-Identifier: BSL-1.0
#pragma once
// Poses of B against A for the detector tests: random poses near contact
// (influence2d::random_poses about A's centroid, within the reach of the two
// bounding circles), exact touching poses with their one-ulp neighbours, and
// a deterministic approach from apart to overlapping; and the pieces they are
// made of (a point of A's boundary with its outward normal, B's extreme
// vertex against it, the pose that puts B's centroid at a given place).

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

/// A point of A's boundary and the outward normal there (not of unit
/// length): a vertex with the sum of its two edges' outward normals, or the
/// midpoint of an edge with the edge's (the interior lies left of stored
/// edges). Two draws of r: the edge, then vertex or midpoint.
struct boundary_point {
    point<double> at;
    point<double> normal;
};

inline boundary_point random_boundary_point(const polygon& a, test_random::rng& r) {
    const std::size_t i = r.index(a.size());
    const point<double> v0 = a.vertex(i), v1 = a.vertex(a.next(i));
    if (r.index(2) == 0) {
        std::size_t prev = i;
        while (a.next(prev) != i) prev = a.next(prev);
        const point<double> u = a.vertex(prev);
        return {v0, {(v1.y - v0.y) + (v0.y - u.y), -(v1.x - v0.x) - (v0.x - u.x)}};
    }
    return {{(v0.x + v1.x) / 2, (v0.y + v1.y) / 2}, {v1.y - v0.y, -(v1.x - v0.x)}};
}

/// The vertex of B furthest against the direction n (the least dot product;
/// the first on a tie): B, put with it on a line normal to n, lies beyond
/// that line.
inline std::size_t extreme_vertex(const polygon& b, const point<double>& n) {
    std::size_t j = 0;
    double best = 0;
    for (std::size_t m = 0; m < b.size(); ++m) {
        const double dot = b.vertex(m).x * n.x + b.vertex(m).y * n.y;
        if (m == 0 || dot < best) {
            best = dot;
            j = m;
        }
    }
    return j;
}

/// The pose turned by theta that puts B's centroid cb (in B's frame) at
/// ca + dist (cos phi, sin phi).
inline pose centroid_at(const point<double>& ca, const point<double>& cb, double dist, double phi, double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    return {ca.x + dist * std::cos(phi) - (c * cb.x - s * cb.y), ca.y + dist * std::sin(phi) - (s * cb.x + c * cb.y),
            theta};
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
        const boundary_point at = random_boundary_point(a, r);
        const point<double> q = b.vertex(extreme_vertex(b, at.normal));
        const pose touch{at.at.x - q.x, at.at.y - q.y, 0};
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
        out.push_back(centroid_at(ca, cb, start * (1 - f), path.heading + path.veer * f, path.turn + path.spin * f));
    }
    return out;
}

}  // namespace test_poses
