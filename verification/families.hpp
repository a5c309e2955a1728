// SPDX-License-Identifier: BSL-1.0
#pragma once
// The paper's five polygon families (docs/method.md section 8): convex, starred,
// irregular, irregular contour and with hole, for any vertex count n >= 8,
// all enclosed in the same size: every vertex within radius 50 of (0, 0) and
// vertex 0 at (50, 0) exactly.
//
// Portable and deterministic: std::mt19937_64 (its output sequence is fixed by
// the standard) turned into doubles by hand, and every coordinate truncated
// towards zero onto the grid of 2^-20, so that the last bits of std::cos and
// std::sin, which differ between C libraries, do not reach the output (short
// of a value falling within an ulp of a grid line, about one chance in 10^8
// per coordinate; the committed files are checked against the generator).
// Truncation towards zero never moves a point away from the origin, so the
// radius bound survives the rounding.
//
// Simplicity holds by construction: each ring visits its vertices at strictly
// monotone angles about the origin with every angular gap below pi (the ring
// is star-shaped from the origin), or, for the contour, is a union of
// quadrilaterals in disjoint angular sectors. At n = 1024 edges are longer
// than 0.1 and convex turns lift their vertex by more than 1e-4, far above
// the 2^-20 (about 1e-6) rounding; tests/data/families_test.cpp checks the
// simplicity of every committed polygon exactly.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/io/wkt.hpp"
#include "verification/seeded_draws.hpp"

namespace influence2d::verification {

enum class family { convex, starred, irregular, contour, with_hole };

inline constexpr family all_families[] = {family::convex, family::starred, family::irregular, family::contour,
                                          family::with_hole};

/// The seed of the committed data/families files.
inline constexpr std::uint64_t default_family_seed = 20040202;

/// The vertex counts of the committed files: 8, 16, ..., 1024.
inline std::vector<std::size_t> default_family_sizes() {
    std::vector<std::size_t> sizes;
    for (std::size_t n = 8; n <= 1024; n *= 2) sizes.push_back(n);
    return sizes;
}

/// The family's name in file names: convex, starred, irregular, contour, hole.
inline std::string family_name(family f) {
    switch (f) {
    case family::convex: return "convex";
    case family::starred: return "starred";
    case family::irregular: return "irregular";
    case family::contour: return "contour";
    case family::with_hole: return "hole";
    }
    throw std::invalid_argument("family_name: unknown family");
}

/// The family of a name (family_name's inverse): convex, starred,
/// irregular, contour, hole. Throws std::invalid_argument for another name.
inline family family_of(const std::string& name) {
    for (family f : all_families)
        if (family_name(f) == name) return f;
    throw std::invalid_argument("unknown polygon type: " + name);
}

namespace family_detail {

constexpr double enclosing_radius = 50;

/// A vertex in polar form about the origin.
struct polar {
    double angle;
    double radius;
};

/// Onto the grid of 2^-20, towards zero; -0 becomes +0.
inline double to_grid(double v) { return std::ldexp(std::trunc(std::ldexp(v, 20)), -20) + 0.0; }

/// The rings in polar form, scaled so that the farthest vertex is at 50,
/// rotated so that it lies at angle 0 and made vertex 0 of its ring, then
/// converted to grid coordinates.
inline std::vector<ring_input> to_rings(std::vector<std::vector<polar>> rings, const std::vector<ring_role>& roles) {
    std::size_t far_ring = 0, far_vertex = 0;
    for (std::size_t r = 0; r < rings.size(); ++r)
        for (std::size_t k = 0; k < rings[r].size(); ++k)
            if (rings[r][k].radius > rings[far_ring][far_vertex].radius) {
                far_ring = r;
                far_vertex = k;
            }
    const polar far = rings[far_ring][far_vertex];
    const double scale = enclosing_radius / far.radius;
    std::vector<ring_input> out(rings.size());
    for (std::size_t r = 0; r < rings.size(); ++r) {
        const auto& ring = rings[r];
        const std::size_t n = ring.size(), first = r == far_ring ? far_vertex : 0;
        out[r].role = roles[r];
        out[r].vertices.reserve(n);
        for (std::size_t k = 0; k < n; ++k) {
            const polar& v = ring[(first + k) % n];
            const double a = v.angle - far.angle;
            const double radius = (r == far_ring && k == 0) ? enclosing_radius : v.radius * scale;
            out[r].vertices.push_back({to_grid(radius * std::cos(a)), to_grid(radius * std::sin(a))});
        }
    }
    return out;
}

/// Whether every turn of the ring is a strict left turn (exact: grid
/// coordinates of magnitude <= 50 are integers below 2^26 in units of 2^-20,
/// and their cross products fit in 64 bits).
inline bool strictly_convex(const std::vector<point<double>>& vs) {
    const std::size_t n = vs.size();
    auto unit = [](double v) { return static_cast<std::int64_t>(std::ldexp(v, 20)); };
    for (std::size_t k = 0; k < n; ++k) {
        const auto& a = vs[k];
        const auto& b = vs[(k + 1) % n];
        const auto& c = vs[(k + 2) % n];
        const std::int64_t cross =
            (unit(b.x) - unit(a.x)) * (unit(c.y) - unit(a.y)) - (unit(b.y) - unit(a.y)) * (unit(c.x) - unit(a.x));
        if (cross <= 0) return false;
    }
    return true;
}

/// Whether the ring's area centroid lies outside it and at least 1 away from
/// its boundary. For coarse contours (few vertices, long chords) the centroid
/// can fall into the material; such draws are redrawn. The margin makes the
/// double evaluation decisive.
inline bool centroid_clearly_outside(const std::vector<point<double>>& vs) {
    const point<double> c = polygon({ring_input{vs, ring_role::outer}}).centroid();
    bool inside = false;
    double nearest = enclosing_radius * 4;
    for (std::size_t k = 0; k < vs.size(); ++k) {
        const point<double>& a = vs[k];
        const point<double>& b = vs[(k + 1) % vs.size()];
        if ((a.y > c.y) != (b.y > c.y) && a.x + (c.y - a.y) * (b.x - a.x) / (b.y - a.y) > c.x) inside = !inside;
        const double dx = b.x - a.x, dy = b.y - a.y;
        const double t = std::fmax(0.0, std::fmin(1.0, ((c.x - a.x) * dx + (c.y - a.y) * dy) / (dx * dx + dy * dy)));
        nearest = std::fmin(nearest, std::hypot(c.x - a.x - t * dx, c.y - a.y - t * dy));
    }
    return !inside && nearest > 1;
}

/// A closed star-shaped ring: jittered angles, radii drawn by `radius(k)`.
template <class Radius>
std::vector<polar> star_ring(uniform_source& u, std::size_t n, double spread, Radius radius) {
    const std::vector<double> angles = jittered_angles(u, n, 0, 2 * pi, spread, true);
    std::vector<polar> ring(n);
    for (std::size_t k = 0; k < n; ++k) ring[k] = {angles[k], radius(k)};
    return ring;
}

/// Shortest distance from the origin to the ring's edges, as a bound for
/// the hole (in double: the margin it feeds is a fraction of the distance).
inline double inner_clearance(const std::vector<polar>& ring) {
    double best = enclosing_radius * 2;
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const polar& a = ring[k];
        const polar& b = ring[(k + 1) % ring.size()];
        const double ax = a.radius * std::cos(a.angle), ay = a.radius * std::sin(a.angle);
        const double bx = b.radius * std::cos(b.angle), by = b.radius * std::sin(b.angle);
        const double dx = bx - ax, dy = by - ay;
        const double t = std::fmax(0.0, std::fmin(1.0, -(ax * dx + ay * dy) / (dx * dx + dy * dy)));
        best = std::fmin(best, std::hypot(ax + t * dx, ay + t * dy));
    }
    return best;
}

}  // namespace family_detail

/// The rings of one family polygon with n vertices in total (see the file
/// comment for the guarantees). Angular gaps are proportional to weights drawn
/// uniformly in [1 - s, 1 + s]. Shapes, radii before the final scaling that
/// puts the farthest vertex at 50:
///   convex     n points on the circle of radius 50, s = 0.5 (every gap at
///              least a third of the mean gap).
///   starred    radii alternating between about 50 (in [47.5, 50]) and about
///              25 (in [22.5, 27.5]), s = 0.15.
///   irregular  radii uniform in [20, 50], s = 0.3; redrawn in the rare case
///              it comes out convex.
///   contour    a thick horseshoe over a span of 300 degrees: n/2 (rounded up)
///              outer vertices with radii 45 + 3 w(angle) + 2 v in [40, 50],
///              n/2 (rounded down) inner vertices at the same angles with radii
///              25 + 3 w'(angle) + 2 v' in [20, 30] (w, w' smooth wobbles, v, v'
///              uniform in [-1, 1]), s = 0.3, joined at both ends. Its area
///              centroid lies in the cavity, outside the polygon, so the polygon
///              is not star-shaped from it (coarse draws where it is not clearly
///              so are redrawn). For odd n the extra outer vertex sits mid-way
///              in the middle sector.
///   with_hole  an outer ring of n - n/2 vertices with radii in [42, 50] and a
///              hole of n/2 vertices (clockwise) with radii in [15, 25], shrunk
///              when needed to stay within 80% of the outer ring's distance
///              from the origin; s = 0.15 for both.
inline std::vector<ring_input> make_family_rings(family f, std::size_t n, std::uint64_t seed) {
    using namespace family_detail;
    if (n < 8) throw std::invalid_argument("make_family_rings: at least 8 vertices are needed");
    uniform_source u(mix(seed ^ mix((static_cast<std::uint64_t>(f) << 32) ^ n)));
    switch (f) {
    case family::convex: {
        const auto ring = star_ring(u, n, 0.5, [](std::size_t) { return enclosing_radius; });
        return to_rings({ring}, {ring_role::outer});
    }
    case family::starred: {
        const auto ring = star_ring(
            u, n, 0.15, [&](std::size_t k) { return k % 2 == 0 ? u.between(47.5, 50) : u.between(22.5, 27.5); });
        return to_rings({ring}, {ring_role::outer});
    }
    case family::irregular: {
        for (;;) {
            const auto ring = star_ring(u, n, 0.3, [&](std::size_t) { return u.between(20, 50); });
            auto rings = to_rings({ring}, {ring_role::outer});
            if (!strictly_convex(rings[0].vertices)) return rings;
        }
    }
    case family::contour: {
        const std::size_t inner = n / 2, outer = n - inner;
        const double span = 300 * pi / 180;
        for (;;) {
            const std::vector<double> angles = jittered_angles(u, inner, pi - span / 2, span, 0.3, false);
            const wobble w_out(u), w_in(u);
            std::vector<polar> ring;
            ring.reserve(n);
            for (std::size_t k = 0; k < inner; ++k) {
                ring.push_back({angles[k], 45 + 3 * w_out(angles[k]) + 2 * u.between(-1, 1)});
                if (outer > inner && k == inner / 2 - 1) {
                    const double mid = (angles[k] + angles[k + 1]) / 2;
                    ring.push_back({mid, 45 + 3 * w_out(mid) + 2 * u.between(-1, 1)});
                }
            }
            for (std::size_t k = inner; k-- > 0;)
                ring.push_back({angles[k], 25 + 3 * w_in(angles[k]) + 2 * u.between(-1, 1)});
            auto rings = to_rings({ring}, {ring_role::outer});
            if (centroid_clearly_outside(rings[0].vertices)) return rings;
        }
    }
    case family::with_hole: {
        const std::size_t hole = n / 2, outer = n - hole;
        const auto out_ring = star_ring(u, outer, 0.15, [&](std::size_t) { return u.between(42, 50); });
        const double shrink = std::fmin(1.0, 0.8 * inner_clearance(out_ring) / 25);
        auto hole_ring = star_ring(u, hole, 0.15, [&](std::size_t) { return shrink * u.between(15, 25); });
        std::reverse(hole_ring.begin() + 1, hole_ring.end());  // clockwise, as stored
        return to_rings({out_ring, hole_ring}, {ring_role::outer, ring_role::hole});
    }
    }
    throw std::invalid_argument("make_family_rings: unknown family");
}

/// The family polygon with n vertices in total.
inline polygon make_family_polygon(family f, std::size_t n, std::uint64_t seed) {
    return polygon(make_family_rings(f, n, seed));
}

/// The file name of a family polygon: <family>_<n>.wkt.
inline std::string family_file_name(family f, std::size_t n) {
    return family_name(f) + "_" + std::to_string(n) + ".wkt";
}

/// The exact text of a family file: its WKT and a newline.
inline std::string family_file_text(family f, std::size_t n, std::uint64_t seed) {
    return to_wkt(make_family_polygon(f, n, seed)) + "\n";
}

}  // namespace influence2d::verification
