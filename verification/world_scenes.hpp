// SPDX-License-Identifier: BSL-1.0
#pragma once
// Scenes of many bodies for the world's time study (src/world_bench.cpp): the
// shapes, which bodies are fixed, and every body's pose at every step. Each
// scene is made from a seed alone; no method sees it before the timed loop.
//
// - falling:   convex 8-gons and non-convex stars fall onto a fixed comb-shaped
//              floor, turning slowly, each stopping at its own depth and then
//              resting (its pose unchanged): coherent.
// - parcels:   a grid of quadrilateral parcels sharing their corners exactly
//              (neighbours touch exactly); a third of them drift by steps of
//              2^-10 (snapped: touching is kept, lost and regained exactly).
// - random:    fresh random poses every step in a square sized for about two
//              contacts per body: no coherence at all.
// - mixed:     sizes log-uniform over two decades (0.1 to 10), drifting
//              slowly.
// - far:       `falling` moved by (1e7, -1e7).
// - convex:    `falling` with convex 8-gons only, onto a slab (the scene Box2D
//              can take).

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"

namespace influence2d::verification {

struct world_scene {
    std::string name;
    std::vector<polygon> shapes;
    std::vector<std::uint32_t> shape_of;   ///< each body's shape
    std::vector<bool> fixed;               ///< each body fixed or free
    std::vector<std::vector<pose>> steps;  ///< steps[s][b]: body b's pose at step s
    bool convex_only = false;              ///< every shape convex with at most 8 vertices
};

namespace world_scenes_detail {

inline polygon regular(int n, double r, double phase = 0) {
    ring_input ring;
    for (int k = 0; k < n; ++k) {
        const double a = phase + 2 * M_PI * k / n;
        ring.vertices.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return polygon({ring});
}

inline polygon star(int n, double r_in, double r_out) {
    ring_input ring;
    for (int k = 0; k < 2 * n; ++k) {
        const double a = M_PI * k / n, r = k % 2 ? r_in : r_out;
        ring.vertices.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return polygon({ring});
}

/// A comb: a bar along [0, width] x [0, 1] with teeth 2 high every 4 units.
inline polygon comb(double width) {
    ring_input ring;
    ring.vertices.push_back({0, 0});
    ring.vertices.push_back({width, 0});
    ring.vertices.push_back({width, 1});
    for (double x = width - 1; x >= 1; x -= 4) {
        ring.vertices.push_back({x, 1});
        ring.vertices.push_back({x, 3});
        ring.vertices.push_back({x - 1, 3});
        ring.vertices.push_back({x - 1, 1});
    }
    ring.vertices.push_back({0, 1});
    return polygon({ring});
}

inline double snap(double x) { return std::round(x * 1024) / 1024; }

}  // namespace world_scenes_detail

/// The scene `name` (falling, parcels, random, mixed, far, convex) with about
/// `bodies` bodies and `steps` steps, from `seed`.
inline world_scene make_world_scene(const std::string& name, std::size_t bodies, std::size_t steps,
                                    std::uint64_t seed) {
    namespace d = world_scenes_detail;
    std::mt19937_64 g(seed);
    const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g); };
    world_scene s;
    s.name = name;
    if (name == "falling" || name == "far" || name == "convex") {
        // Columns of bodies 2.5 apart above a floor as wide as the columns.
        const std::size_t columns =
            std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(bodies) * 4.0)));
        const double width = 2.5 * static_cast<double>(columns) + 2;
        s.convex_only = name == "convex";
        ring_input slab;  // the convex scene's floor: a slab as high as the comb
        slab.vertices = {{0, 0}, {width, 0}, {width, 3}, {0, 3}};
        s.shapes = {s.convex_only ? polygon({slab}) : d::comb(width), d::regular(8, 1, 0.1)};
        if (!s.convex_only) s.shapes.push_back(d::star(5, 0.5, 1.1));
        const point<double> shift = name == "far" ? point<double>{1e7, -1e7} : point<double>{0, 0};
        s.shape_of.push_back(0);
        s.fixed.push_back(true);
        std::vector<double> x0, y0, stop, speed, spin;
        for (std::size_t b = 0; b + 1 < bodies; ++b) {
            const std::size_t column = b % columns, row = b / columns;
            s.shape_of.push_back(s.convex_only || g() % 2 ? 1 : 2);
            s.fixed.push_back(false);
            x0.push_back(2 + 2.5 * static_cast<double>(column) + uniform(-0.2, 0.2));
            y0.push_back(4 + 2.5 * static_cast<double>(row) + uniform(0, 1));
            stop.push_back(2.5 + 2.3 * static_cast<double>(row) +
                           uniform(-0.3, 0.3));  // each row rests on the one below
            speed.push_back(uniform(0.05, 0.2));
            spin.push_back(uniform(-0.02, 0.02));
        }
        for (std::size_t t = 0; t < steps; ++t) {
            std::vector<pose> at{{shift.x, shift.y, 0}};
            const double time = static_cast<double>(t);
            for (std::size_t b = 0; b < x0.size(); ++b)
                // A body at rest stops turning (it sleeps, as a physics
                // engine's would): its pose stays.
                at.push_back({shift.x + x0[b], shift.y + std::max(stop[b], y0[b] - speed[b] * time),
                              spin[b] * std::min(time, (y0[b] - stop[b]) / speed[b])});
            s.steps.push_back(std::move(at));
        }
    } else if (name == "parcels") {
        // A k x k grid of quadrilaterals over jittered grid points: each
        // parcel a polygon of its own, neighbours sharing corners exactly.
        const std::size_t k = std::max<std::size_t>(2, static_cast<std::size_t>(std::sqrt(double(bodies))));
        std::vector<std::vector<point<double>>> corner(k + 1, std::vector<point<double>>(k + 1));
        for (std::size_t i = 0; i <= k; ++i)
            for (std::size_t j = 0; j <= k; ++j)
                corner[i][j] = {d::snap(10.0 * static_cast<double>(i) + uniform(-2, 2)),
                                d::snap(10.0 * static_cast<double>(j) + uniform(-2, 2))};
        std::vector<bool> drifts;
        for (std::size_t i = 0; i < k; ++i)
            for (std::size_t j = 0; j < k; ++j) {
                ring_input r;
                r.vertices = {corner[i][j], corner[i + 1][j], corner[i + 1][j + 1], corner[i][j + 1]};
                s.shapes.push_back(polygon({r}));
                s.shape_of.push_back(static_cast<std::uint32_t>(s.shapes.size() - 1));
                const bool moves = g() % 3 == 0;
                s.fixed.push_back(!moves);
                drifts.push_back(moves);
            }
        std::vector<pose> at(s.shapes.size());
        for (std::size_t t = 0; t < steps; ++t) {
            for (std::size_t b = 0; b < at.size(); ++b)
                if (drifts[b] && t > 0) {
                    const int dir = static_cast<int>(g() % 5);  // stay, or one of four grid steps
                    at[b].tx += dir == 1 ? 0x1p-10 : dir == 2 ? -0x1p-10 : 0;
                    at[b].ty += dir == 3 ? 0x1p-10 : dir == 4 ? -0x1p-10 : 0;
                }
            s.steps.push_back(at);
        }
    } else if (name == "random" || name == "mixed") {
        const bool mixed = name == "mixed";
        s.shapes = {d::regular(8, 1, 0.1), d::star(5, 0.5, 1.1), d::star(12, 3, 4)};
        std::vector<double> size_of;
        if (mixed) {
            s.shapes.clear();
            for (int k = 0; k < 12; ++k) {
                const double r = std::exp(uniform(std::log(0.1), std::log(10.0)));
                s.shapes.push_back(k % 2 ? d::star(6 + k, 0.6 * r, r) : d::regular(8, r, 0.05 * k));
                size_of.push_back(r);
            }
        }
        // A square in which about two bodies meet each body.
        const double extent = std::sqrt(static_cast<double>(bodies)) * (mixed ? 4.0 : 2.2);
        for (std::size_t b = 0; b < bodies; ++b) {
            s.shape_of.push_back(static_cast<std::uint32_t>(g() % s.shapes.size()));
            s.fixed.push_back(false);
        }
        std::vector<pose> at(bodies);
        for (pose& q : at) q = {uniform(0, extent), uniform(0, extent), uniform(-M_PI, M_PI)};
        for (std::size_t t = 0; t < steps; ++t) {
            for (pose& q : at)
                q = mixed
                        ? pose{q.tx + uniform(-0.05, 0.05), q.ty + uniform(-0.05, 0.05), q.theta + uniform(-0.01, 0.01)}
                        : pose{uniform(0, extent), uniform(0, extent), uniform(-M_PI, M_PI)};
            s.steps.push_back(at);
        }
    }
    return s;
}

}  // namespace influence2d::verification
