// SPDX-License-Identifier: BSL-1.0
#pragma once
// Random scenes that the detector's own design does not produce: multipolygons
// of 2 to 20 star-shaped parts of very different sizes, some with holes and
// islands inside the holes, against polygons large enough to swallow whole
// parts; poses aimed at a part, so that whole parts end up inside the other
// polygon. Coordinates lie on a grid of 2^-10, so translations by grid values
// are exact in double.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "support/random.hpp"

namespace test_scenes {

using influence2d::point;
using influence2d::polygon;
using influence2d::pose;
using influence2d::ring_input;
using influence2d::ring_role;

/// The tests' random source (support/random.hpp).
using test_random::rng;

/// The grid every generated coordinate lies on.
inline constexpr double grid = 0x1p-10;

inline double snap(double x) { return std::round(x / grid) * grid; }
inline point<double> snap(point<double> p) { return {snap(p.x), snap(p.y)}; }

using ring_points = std::vector<point<double>>;

/// One part: an outer ring and its holes (each hole strictly inside it).
struct part {
    ring_points outer;
    std::vector<ring_points> holes;
    point<double> center;  ///< the star's centre, strictly inside the outer ring
    double radius = 0;     ///< bounds the distance from the centre to the part
};

/// A multipolygon: parts whose closed regions are pairwise disjoint (an
/// island lies strictly inside a hole of another part), so the scene is
/// valid for GEOS too.
struct multi {
    std::vector<part> parts;

    /// The library's polygon: each part's outer ring, then its holes.
    polygon to_polygon() const { return polygon(rings()); }

    /// The rings in that order.
    std::vector<ring_input> rings() const {
        std::vector<ring_input> out;
        for (const part& p : parts) {
            out.push_back({p.outer, ring_role::outer});
            for (const ring_points& h : p.holes) out.push_back({h, ring_role::hole});
        }
        return out;
    }

    /// MULTIPOLYGON WKT of the parts moved by `offset` (exact on the grid).
    std::string wkt(point<double> offset = {0, 0}) const {
        std::ostringstream s;
        s.precision(17);
        const auto ring = [&](const ring_points& r) {
            s << '(';
            for (const point<double>& v : r) s << v.x + offset.x << ' ' << v.y + offset.y << ',';
            s << r.front().x + offset.x << ' ' << r.front().y + offset.y << ')';
        };
        s << "MULTIPOLYGON(";
        for (std::size_t k = 0; k < parts.size(); ++k) {
            s << (k ? ",(" : "(");
            ring(parts[k].outer);
            for (const ring_points& h : parts[k].holes) {
                s << ',';
                ring(h);
            }
            s << ')';
        }
        s << ')';
        return s.str();
    }
};

/// A star-shaped ring about c: k >= 4 vertices at increasing angles (no gap
/// of pi or more, so c lies inside), at distances in [lo, hi] from c, snapped
/// to the grid. Simple for lo large against the grid (callers keep lo >= 0.1).
inline ring_points star(rng& g, point<double> c, double lo, double hi, std::size_t k) {
    ring_points r;
    k = std::max<std::size_t>(k, 4);
    const double phase = g.uniform(0, 6.283185307179586);
    for (std::size_t i = 0; i < k; ++i) {
        const double a = phase + 6.283185307179586 * (static_cast<double>(i) + 0.5 * g.unit()) / static_cast<double>(k);
        const double d = g.uniform(lo, hi);
        r.push_back(snap(point<double>{c.x + d * std::cos(a), c.y + d * std::sin(a)}));
    }
    return r;
}

/// The distance from c to the nearest point of the ring (in double: callers
/// keep a margin far above its rounding).
inline double inner_radius(const ring_points& r, point<double> c) {
    double best = HUGE_VAL;
    for (std::size_t i = 0; i < r.size(); ++i) {
        const point<double> a = r[i], b = r[(i + 1) % r.size()];
        const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
        const double t = len2 > 0 ? std::clamp(((c.x - a.x) * dx + (c.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(a.x + t * dx - c.x, a.y + t * dy - c.y));
    }
    return best;
}

/// A random multipolygon of 2 to `max_parts` parts within [-extent, extent]^2:
/// radii log-uniform in [0.4, 12] (parts of very different sizes), a third of
/// the larger parts with a hole, half of those with an island in the hole.
inline multi random_multi(rng& g, double extent, std::size_t max_parts = 20) {
    multi m;
    const std::size_t wanted = 2 + g.index(max_parts - 1);
    for (int tries = 0; m.parts.size() < wanted && tries < 400; ++tries) {
        const double radius = 0.4 * std::exp(g.uniform(0, std::log(30.0)));
        const point<double> c = snap(point<double>{g.uniform(-extent, extent), g.uniform(-extent, extent)});
        bool clear = true;
        for (const part& p : m.parts)
            clear = clear && std::hypot(c.x - p.center.x, c.y - p.center.y) > radius + p.radius + 0.05;
        if (!clear) continue;
        part p;
        p.center = c;
        p.radius = radius;
        p.outer = star(g, c, 0.55 * radius, radius, 3 + g.index(14));
        if (radius >= 1 && g.chance(0.35)) {
            // A hole well inside the outer ring, an island well inside the hole.
            const double h = 0.8 * inner_radius(p.outer, c) * g.uniform(0.6, 1.0);
            p.holes.push_back(star(g, c, 0.6 * h, h, 3 + g.index(8)));
            if (g.chance(0.5)) {
                part island;
                const double i = 0.8 * inner_radius(p.holes.back(), c);
                island.center = c;
                island.radius = i;
                island.outer = star(g, c, 0.5 * i, i, 3 + g.index(6));
                m.parts.push_back(std::move(p));
                m.parts.push_back(std::move(island));
                continue;
            }
        }
        m.parts.push_back(std::move(p));
    }
    return m;
}

/// One polygon large enough to swallow whole parts: a star about the origin
/// of radius in [4, 30], nearly convex, sometimes with a hole.
inline multi random_swallower(rng& g) {
    multi m;
    part p;
    p.center = {0, 0};
    p.radius = g.uniform(4, 30);
    p.outer = star(g, p.center, 0.7 * p.radius, p.radius, 5 + g.index(36));
    if (g.chance(0.3)) {
        const double h = inner_radius(p.outer, p.center) * g.uniform(0.2, 0.5);
        p.holes.push_back(star(g, p.center, 0.6 * h, h, 3 + g.index(8)));
    }
    m.parts.push_back(std::move(p));
    return m;
}

/// A pose of B that puts B's point `q` (in B's own frame) at `target`, turned
/// by theta: t = target - R(theta) q, taken with the same cosine and sine as
/// the detectors. With theta = 0 the translation is snapped to the grid, so
/// that every posed coordinate is exact in double.
inline pose aimed(point<double> q, point<double> target, double theta) {
    if (theta == 0) return {snap(target.x - q.x), snap(target.y - q.y), 0};
    const double c = std::cos(theta), s = std::sin(theta);
    return {target.x - (c * q.x - s * q.y), target.y - (s * q.x + c * q.y), theta};
}

}  // namespace test_scenes

namespace test_scenes {

/// A polygon of rings nothing keeps apart, the region then being the
/// library's winding rule: 1 to `max_rings` rings about random centres in
/// [-extent, extent]^2, each outer or hole at random (holes may lie outside
/// every outer ring, shells may nest or overlap), some with their vertices
/// in random order (self-crossing rings, figure eights), some with repeated
/// vertices and collinear midpoints.
inline std::vector<ring_input> random_messy(rng& g, double extent, std::size_t max_rings = 8) {
    std::vector<ring_input> rings;
    const std::size_t count = 1 + g.index(max_rings);
    for (std::size_t r = 0; r < count; ++r) {
        const double radius = 0.5 * std::exp(g.uniform(0, std::log(20.0)));
        const point<double> c = snap(point<double>{g.uniform(-extent, extent), g.uniform(-extent, extent)});
        ring_points v = star(g, c, 0.3 * radius, radius, 4 + g.index(10));
        if (g.chance(0.2)) std::shuffle(v.begin(), v.end(), g.gen);
        if (g.chance(0.2)) {
            const std::size_t k = g.index(v.size());
            v.insert(v.begin() + static_cast<std::ptrdiff_t>(k), v[k]);
        }
        if (g.chance(0.2)) {
            const std::size_t k = g.index(v.size());
            const point<double> a = v[k], b = v[(k + 1) % v.size()];
            v.insert(v.begin() + static_cast<std::ptrdiff_t>(k + 1), point<double>{(a.x + b.x) / 2, (a.y + b.y) / 2});
        }
        rings.push_back({std::move(v), r == 0 || g.chance(0.6) ? ring_role::outer : ring_role::hole});
    }
    return rings;
}

}  // namespace test_scenes
