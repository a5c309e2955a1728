// SPDX-License-Identifier: BSL-1.0
#pragma once
// The pairs of real polygons of the time study on real layers
// (src/real_bench.cpp, scripts/profile/real_frames.cpp): which polygons of
// which layer (scripts/real_layers.sh; src/world_input.hpp's named_polygon
// reads them), the range of their poses, the random walk through it, the
// walk's poses pushed just clear of the static polygon, and the four orders
// the study asks them in. Made from a seed alone; no method sees them before
// its timed loop.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/exact/certified_detector.hpp"

namespace influence2d::verification {

/// A pair of the study: the layer file (without .wkt), the names of the
/// static and the moving polygon in its .names file, and the range of the
/// poses: a translation of up to `shift` in each axis (the layer's units)
/// and a turn of up to `turn` radians about the origin.
struct real_pair {
    std::string layer, a, b;
    double shift = 0, turn = 0;
};

/// The study's pairs: four pairs of countries, two of New York City
/// boroughs and two of North Carolina counties.
inline const std::vector<real_pair>& study_pairs() {
    static const std::vector<real_pair> pairs = {
        {"countries", "Chile", "Argentina", 3, 0.03},
        {"countries", "Russia", "Kazakhstan", 3, 0.03},
        {"countries", "Canada", "United States of America", 3, 0.03},
        {"countries", "Indonesia", "Malaysia", 3, 0.03},
        // Feet, x near 1e6: a turn of 0.002 rad moves a borough by about
        // 2,000 feet, as far as the translation does.
        {"boroughs", "Brooklyn", "Queens", 2000, 0.002},
        {"boroughs", "Manhattan", "Bronx", 2000, 0.002},
        // Degrees near (-77, 35), counties about half a degree across, the
        // longest shared borders of the layer (they touch exactly where they
        // stand): a turn of 0.0005 rad moves a county by about 0.04 degrees.
        {"counties", "Northampton", "Halifax", 0.05, 0.0005},
        {"counties", "Jones", "Craven", 0.05, 0.0005},
    };
    return pairs;
}

/// `count` poses of a random walk within the pair's range: each step moves
/// by up to 1/50 of the range in each component, reflected at its bounds.
inline std::vector<pose> walk(const real_pair& p, std::size_t count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> step(-1.0 / 50, 1.0 / 50);
    const auto reflect = [](double x) { return x > 1 ? 2 - x : x < -1 ? -2 - x : x; };
    double u = 0, v = 0, w = 0;
    std::vector<pose> out;
    for (std::size_t k = 0; k < count; ++k) {
        u = reflect(u + step(rng));
        v = reflect(v + step(rng));
        w = reflect(w + step(rng));
        out.push_back({u * p.shift, v * p.shift, w * p.turn});
    }
    return out;
}

/// Each pose pushed by a translation along the direction from A's box centre
/// to B's posed box centre ((1, 0) where they coincide) just far enough to
/// leave A: the least push found apart by the certified detector (exact),
/// doubling from a 4096th of the pair's shift, then halving the step twelve
/// times between a push that meets and one that does not; the pose apart
/// (within about a 4096th of the shift of touching) is kept.
inline std::vector<pose> pushed_apart(const real_pair& p, const polygon& a, const polygon& b,
                                      const std::vector<pose>& poses) {
    certified_detector<detector> reference(a, b);
    const point<double> ca = a.bounds().centre(), cb = b.bounds().centre();
    std::vector<pose> out;
    for (const pose& q : poses) {
        const point<double> c = rotation_pose(q).apply<double>(cb);
        const double dx = c.x - ca.x, dy = c.y - ca.y, length = std::hypot(dx, dy);
        const point<double> u = length > 0 ? point<double>{dx / length, dy / length} : point<double>{1, 0};
        const auto at = [&](double t) { return pose{q.tx + t * u.x, q.ty + t * u.y, q.theta}; };
        double meets = 0, apart = p.shift / 4096;
        for (int k = 0; k < 60 && reference.collide(at(apart)).collides; ++k) {
            meets = apart;
            apart *= 2;
        }
        for (int k = 0; k < 12; ++k) {
            const double mid = (meets + apart) / 2;
            (reference.collide(at(mid)).collides ? meets : apart) = mid;
        }
        out.push_back(at(apart));
    }
    return out;
}

/// The study's four orders of one pair's poses, each named: the walk of
/// `count` poses from `seed`, the same poses shuffled (seed + 1), the walk's
/// poses pushed apart, and those shuffled (seed + 2).
inline std::vector<std::pair<std::string, std::vector<pose>>> pose_orders(const real_pair& p, const polygon& a,
                                                                          const polygon& b, std::size_t count,
                                                                          std::uint64_t seed) {
    std::vector<pose> poses = walk(p, count, seed);
    std::vector<pose> apart = pushed_apart(p, a, b, poses);
    std::vector<pose> shuffled = poses, apart_shuffled = apart;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937_64(seed + 1));
    std::shuffle(apart_shuffled.begin(), apart_shuffled.end(), std::mt19937_64(seed + 2));
    return {{"walk", std::move(poses)},
            {"shuffled", std::move(shuffled)},
            {"apart, walk", std::move(apart)},
            {"apart, shuffled", std::move(apart_shuffled)}};
}

}  // namespace influence2d::verification
