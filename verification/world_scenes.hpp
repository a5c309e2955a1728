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
// - trajectories: the paper's trajectories for many bodies (docs/method.md
//              section 8): cells far apart, each a fixed polygon A of the
//              paper's families and a polygon B that follows, 25 of the
//              paper's frames a step, either the circular trajectory (B
//              orbits A within the gap of 9, never touching) or the linear
//              one (B approaches A and ends inside it, then rests): coherent,
//              near but apart, and contacts that begin during the run.

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "verification/families.hpp"

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

/// Frames of the paper's trajectories for a world scene: its frame counts,
/// its gap, and the frames a scene step advances.
inline constexpr std::size_t circular_frames = 90000, linear_frames = 9000, frames_per_step = 25;
inline constexpr double trajectory_gap = 9.0;

/// Frame k of the circular trajectory that starts at `first` (frame 0 of
/// circular_trajectory): that pose turned by 2 pi k / circular_frames about
/// A's centroid `o`, as circular_trajectory makes each frame (the same
/// motion, without making all 90,000 frames of every cell).
inline pose circular_frame(const pose& first, const point<double>& o, std::size_t k) {
    const double phi = 2 * M_PI * static_cast<double>(k % circular_frames) / static_cast<double>(circular_frames);
    const double c = std::cos(phi), s = std::sin(phi), x = first.tx - o.x, y = first.ty - o.y;
    return {o.x + c * x - s * y, o.y + s * x + c * y, first.theta + phi};
}

/// Frame k of the linear trajectory from `start` to `end` (its first and
/// last frames), as linear_trajectory spaces them; past the last frame, the
/// last.
inline pose linear_frame(const pose& start, const pose& end, std::size_t k) {
    if (k + 1 >= linear_frames) return end;
    const double f = static_cast<double>(k) / static_cast<double>(linear_frames - 1);
    return {start.tx + (end.tx - start.tx) * f, start.ty + (end.ty - start.ty) * f, 0};
}

/// A pose given in a cell's frame (A at the origin, unturned) placed in the
/// world: turned by `turn` (cosine c, sine s) and moved to `at`.
inline pose in_cell(const pose& q, const point<double>& at, double turn, double c, double s) {
    return {at.x + c * q.tx - s * q.ty, at.y + s * q.tx + c * q.ty, q.theta + turn};
}

}  // namespace world_scenes_detail

/// The scene `name` (falling, parcels, random, mixed, far, convex, trajectories) with about
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
        // (Rings' vertices moved in as vectors, not assigned from braced
        // lists: GCC 12 at -O3 warns, wrongly, of a null argument to the
        // memmove of a list's copy.)
        ring_input slab;  // the convex scene's floor: a slab as high as the comb
        slab.vertices = std::vector<point<double>>{{0, 0}, {width, 0}, {width, 3}, {0, 3}};
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
                r.vertices =
                    std::vector<point<double>>{corner[i][j], corner[i + 1][j], corner[i + 1][j + 1], corner[i][j + 1]};
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
    } else if (name == "trajectories") {
        // Cells 700 apart on a grid (a linear B starts at most about 310
        // from A's centroid): in cell c, body 2c is A (fixed, turned by the
        // cell's angle) and body 2c + 1 is B, on the circular trajectory in
        // even cells, the linear one in odd cells. A circular B starts at a
        // frame anywhere on its orbit; a linear B within the last
        // 2 * frames_per_step * steps frames, so that about half of them meet
        // A during the run.
        const family families[] = {family::convex, family::starred, family::irregular, family::contour,
                                   family::with_hole};
        const std::size_t sizes[] = {8, 16, 32, 64};
        for (family f : families)
            for (std::size_t n : sizes) s.shapes.push_back(make_family_polygon(f, n, default_family_seed));
        const std::size_t cells = std::max<std::size_t>(1, bodies / 2);
        const std::size_t side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(cells))));
        struct cell {
            point<double> at;
            double turn, c, s;
            bool circular;
            std::size_t first;
            pose from, to;  // the circular trajectory's frame 0 (from); the linear one's first and last
            point<double> o;
        };
        std::vector<cell> all;
        for (std::size_t k = 0; k < cells; ++k) {
            const auto a = static_cast<std::uint32_t>(g() % s.shapes.size()),
                       b = static_cast<std::uint32_t>(g() % s.shapes.size());
            cell c;
            c.at = {700.0 * static_cast<double>(k % side), 700.0 * static_cast<double>(k / side)};
            c.turn = uniform(-M_PI, M_PI);
            c.c = std::cos(c.turn);
            c.s = std::sin(c.turn);
            c.circular = k % 2 == 0;
            c.o = s.shapes[a].centroid();
            if (c.circular) {
                c.first = static_cast<std::size_t>(g() % d::circular_frames);
                c.from = circular_trajectory(s.shapes[a], s.shapes[b], 1, d::trajectory_gap)[0];
            } else {
                const std::size_t window =
                    std::min(d::linear_frames, 2 * d::frames_per_step * std::max<std::size_t>(1, steps));
                c.first = d::linear_frames - 1 - static_cast<std::size_t>(g() % window);
                const std::vector<pose> ends = linear_trajectory(s.shapes[a], s.shapes[b], 2, d::trajectory_gap);
                c.from = ends[0];
                c.to = ends[1];
            }
            s.shape_of.push_back(a);
            s.fixed.push_back(true);
            s.shape_of.push_back(b);
            s.fixed.push_back(false);
            all.push_back(c);
        }
        for (std::size_t t = 0; t < steps; ++t) {
            std::vector<pose> at;
            for (const cell& c : all) {
                const std::size_t k = c.first + d::frames_per_step * t;
                const pose here = c.circular ? d::circular_frame(c.from, c.o, k) : d::linear_frame(c.from, c.to, k);
                at.push_back({c.at.x, c.at.y, c.turn});
                at.push_back(d::in_cell(here, c.at, c.turn, c.c, c.s));
            }
            s.steps.push_back(std::move(at));
        }
    }
    return s;
}

}  // namespace influence2d::verification
