// SPDX-License-Identifier: BSL-1.0
#pragma once
// Stiff and extreme scenes for the precision study: polygons and poses built so
// that many frames lie within a few ulps of contact, on geometry that strains
// double precision (near-collinear runs, slivers, needles, tiny edges beside
// huge ones, large offsets, extreme scales, subnormal coordinates, grazing and
// exact touching, centroids on edge lines, very large rings, deep combs and
// spirals). Every scene has frames that collide and frames that do not.
//
// Deterministic: std::mt19937_64 seeded through splitmix64, doubles made by
// hand from its top 53 bits (the conventions of families.hpp), no library
// distribution. Translations that bring B within ulps of A are computed with
// error-free transformations (fma) in double, never in long double, so the
// output depends only on IEEE double arithmetic and on the C library's
// std::cos, std::sin, std::atan2, std::hypot and std::pow (B is posed with the
// rotation doubles std::cos(theta), std::sin(theta), as the library poses it).
// The committed data/stiff files are checked against this generator.
//
// Every ring is given in the polygon's stored orientation (outer rings
// counter-clockwise, holes clockwise), so that files list the vertices as
// generated, and every ring is simple by construction (checked exactly in
// tests/verification/stiff_cases_test.cpp).
//
// How the frames are made (all families but touching): a contact site is a
// point p on A's boundary (on an edge, or a convex vertex) with an outward
// normal n. For a rotation theta, B's vertex q extreme against n is posed
// onto p: t = p - R(theta) q from the exact products, rounded about once (p
// itself, when inside an edge, is rounded: B lands within an ulp or two of
// A). A group of eight frames follows from that contact: t itself, t moved by
// k ulps per coordinate away from A (k > 0) or into it (k < 0) for k = 1, -1,
// one of 2..4, one of -2..-4 and one of -4..4, and two frames well apart and
// well into A (moved by 5% to 50% of B's size along n). The grazing family has only the
// eight frames k = +-1..4. The rotation of a group is, depending on the
// family, 0, small (10^-9..10^-2 rad), any, or "aligned": an edge of B turned
// antiparallel to the edge of A at the site.

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/io/csv.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/exact_sum.hpp"
#include "verification/families.hpp"
#include "verification/seeded_draws.hpp"

namespace influence2d::verification {

enum class stiff_family {
    near_collinear,
    sliver,
    needle,
    tiny_beside_huge,
    offset,
    scaled,
    subnormal,
    grazing,
    touching,
    centroid_on_edge_line,
    large,
    comb,
    spiral
};

/// The family's name in scene and file names: "near_collinear", "offset", ...
inline std::string stiff_family_name(stiff_family f) {
    switch (f) {
    case stiff_family::near_collinear: return "near_collinear";
    case stiff_family::sliver: return "sliver";
    case stiff_family::needle: return "needle";
    case stiff_family::tiny_beside_huge: return "tiny_beside_huge";
    case stiff_family::offset: return "offset";
    case stiff_family::scaled: return "scaled";
    case stiff_family::subnormal: return "subnormal";
    case stiff_family::grazing: return "grazing";
    case stiff_family::touching: return "touching";
    case stiff_family::centroid_on_edge_line: return "centroid_on_edge_line";
    case stiff_family::large: return "large";
    case stiff_family::comb: return "comb";
    case stiff_family::spiral: return "spiral";
    }
    throw std::invalid_argument("stiff_family_name: unknown family");
}

/// Every family, in declaration order.
inline const std::vector<stiff_family>& all_stiff_families() {
    static const std::vector<stiff_family> all{stiff_family::near_collinear, stiff_family::sliver,
                                               stiff_family::needle,         stiff_family::tiny_beside_huge,
                                               stiff_family::offset,         stiff_family::scaled,
                                               stiff_family::subnormal,      stiff_family::grazing,
                                               stiff_family::touching,       stiff_family::centroid_on_edge_line,
                                               stiff_family::large,          stiff_family::comb,
                                               stiff_family::spiral};
    return all;
}

/// One scene: a static polygon A, a moving polygon B (in its own frame) and
/// the poses of B to test.
struct stiff_scene {
    std::string name;  ///< unique within one call, file-name safe: "offset_1e09_003"
    stiff_family family = stiff_family::near_collinear;
    double magnitude = 0;  ///< the offset or the scale; 0 for the other families
    polygon a, b;
    std::vector<pose> poses;
};

/// The seed of the committed data/stiff files.
inline constexpr std::uint64_t default_stiff_seed = 20040205;
/// Scenes per family in the committed data/stiff files (one for `large`).
inline constexpr std::size_t default_stiff_count = 3;

/// The offsets of the offset family: 1e3, 1e4, ..., 1e15.
inline std::vector<double> offset_magnitudes() {
    return {1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
}

/// The scales of the scaled family: 1e-150, 1e-120, ..., 1, ..., 1e120, 1e150.
inline std::vector<double> scale_magnitudes() {
    return {1e-150, 1e-120, 1e-90, 1e-60, 1e-30, 1.0, 1e30, 1e60, 1e90, 1e120, 1e150};
}

namespace stiff_detail {

using dpoint = point<double>;
constexpr double infinity = std::numeric_limits<double>::infinity();

inline std::uint64_t scene_seed(std::uint64_t seed, stiff_family f, std::size_t index) {
    return mix(seed ^
               mix(0x5354494646000000ULL ^ (static_cast<std::uint64_t>(f) << 32) ^ static_cast<std::uint64_t>(index)));
}

// ---------------------------------------------------------------- drawing

/// Uniform integer in [lo, hi].
inline std::int64_t integer(uniform_source& u, std::int64_t lo, std::int64_t hi) {
    const double span = static_cast<double>(hi - lo) + 1;
    const auto k = static_cast<std::int64_t>(std::floor(u.next() * span));
    return lo + std::min(k, hi - lo);
}

inline std::size_t draw_index(uniform_source& u, std::size_t n) {
    return static_cast<std::size_t>(integer(u, 0, static_cast<std::int64_t>(n) - 1));
}

inline bool coin(uniform_source& u) { return u.next() < 0.5; }

/// 16, 32 or 64 vertices, as a shift of 16.
inline int size_shift(uniform_source& u) { return static_cast<int>(integer(u, 0, 2)); }

/// 10^x for x uniform in [lo, hi).
inline double log_uniform(uniform_source& u, double lo, double hi) { return std::pow(10.0, u.between(lo, hi)); }

/// A 64-bit seed drawn from the stream.
inline std::uint64_t draw_seed(uniform_source& u) {
    return static_cast<std::uint64_t>(u.next() * 0x1p53) ^ 0x9e3779b97f4a7c15ULL;
}

// ---------------------------------------------------------------- arithmetic

/// x moved by |k| ulps, towards +infinity for k > 0 and -infinity for k < 0.
inline double step(double x, int k) {
    const double to = k > 0 ? infinity : -infinity;
    for (int i = 0; i < (k > 0 ? k : -k); ++i) x = std::nextafter(x, to);
    return x;
}

/// a + b = s + e exactly.
inline void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double bv = s - a;
    const double av = s - bv;
    e = (a - av) + (b - bv);
}

/// a * b = p + e exactly (barring underflow).
inline void two_product(double a, double b, double& p, double& e) {
    p = a * b;
    e = std::fma(a, b, -p);
}

/// p - (c * qx - s * qy) for x, p - (s * qx + c * qy) for y: the translation
/// that poses q onto p, from the exact products, rounded about once.
inline dpoint contact_translation(const dpoint& p, const dpoint& q, double c, double s) {
    auto sum = [](std::array<double, 5> terms) {
        double total = 0, error = 0;
        for (double x : terms) {
            double t, e;
            two_sum(total, x, t, e);
            total = t;
            error += e;
        }
        return total + error;
    };
    double p1, e1, p2, e2, p3, e3, p4, e4;
    two_product(c, q.x, p1, e1);
    two_product(s, q.y, p2, e2);
    two_product(s, q.x, p3, e3);
    two_product(c, q.y, p4, e4);
    return {sum({p.x, -p1, p2, -e1, e2}), sum({p.y, -p3, -p4, -e3, -e4})};
}

/// The unit vector along (x, y) (scaled first, so that subnormal and huge
/// components keep their direction); (1, 0) for the zero vector.
inline dpoint direction(double x, double y) {
    const double m = std::max(std::fabs(x), std::fabs(y));
    if (!(m > 0)) return {1, 0};
    x /= m;
    y /= m;
    const double l = std::sqrt(x * x + y * y);
    return {x / l, y / l};
}

inline double cross(const dpoint& a, const dpoint& b) { return a.x * b.y - a.y * b.x; }

// ---------------------------------------------------------------- lattice rings

/// A point of the integer lattice.
struct lpoint {
    std::int64_t x = 0;
    std::int64_t y = 0;
};

/// The sign of a.x * b.y - a.y * b.x, exact for coordinates below 2^52 in
/// magnitude (products evaluated as floating-point expansions).
inline int cross(const lpoint& a, const lpoint& b) {
    exact_sum::accumulator acc;
    acc.add_product(static_cast<double>(a.x), static_cast<double>(b.y));
    acc.add_product(-static_cast<double>(a.y), static_cast<double>(b.x));
    return acc.sign();
}
/// Exact for coordinates below 2^31 in magnitude.
inline std::int64_t dot(const lpoint& a, const lpoint& b) { return a.x * b.x + a.y * b.y; }
inline lpoint operator-(const lpoint& a, const lpoint& b) { return {a.x - b.x, a.y - b.y}; }

/// Whether the ring turns strictly counter-clockwise about the origin from
/// each vertex to the next and goes round once: then it is star-shaped from
/// the origin, counter-clockwise and simple (the turns are decided exactly;
/// the total angle, about 2 pi or at least 4 pi, in double).
inline bool winds_once(const std::vector<lpoint>& ring) {
    double turn = 0;
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const lpoint& a = ring[k];
        const lpoint& b = ring[(k + 1) % ring.size()];
        if (cross(a, b) <= 0) return false;
        const double ax = static_cast<double>(a.x), ay = static_cast<double>(a.y);
        const double bx = static_cast<double>(b.x), by = static_cast<double>(b.y);
        turn += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
    }
    return turn < 3 * pi;
}

/// A simple counter-clockwise lattice ring of m vertices, star-shaped from
/// the origin: jittered angles, radii uniform in [rmin, rmax], rounded to the
/// lattice; redrawn until winds_once holds.
inline std::vector<lpoint> lattice_star(uniform_source& u, std::size_t m, double rmin, double rmax,
                                        double spread = 0.3) {
    for (int attempt = 0; attempt < 10000; ++attempt) {
        const std::vector<double> angles = jittered_angles(u, m, u.between(0, 2 * pi), 2 * pi, spread, true);
        std::vector<lpoint> ring(m);
        for (std::size_t k = 0; k < m; ++k) {
            const double r = u.between(rmin, rmax);
            ring[k] = {std::llround(r * std::cos(angles[k])), std::llround(r * std::sin(angles[k]))};
        }
        if (winds_once(ring)) return ring;
    }
    throw std::logic_error("lattice_star: no valid ring drawn");
}

/// The convex hull, counter-clockwise, without collinear vertices (exact).
inline std::vector<lpoint> lattice_hull(std::vector<lpoint> pts) {
    std::sort(pts.begin(), pts.end(),
              [](const lpoint& a, const lpoint& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
    std::vector<lpoint> hull(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0) --k;
        hull[k++] = pts[i];
    }
    hull.resize(k - 1);
    return hull;
}

/// origin + unit * p for each lattice point (exact when unit is a power of
/// two and the results are representable).
inline std::vector<dpoint> from_lattice(const std::vector<lpoint>& ring, double unit, dpoint origin = {0, 0}) {
    std::vector<dpoint> out;
    out.reserve(ring.size());
    for (const lpoint& p : ring)
        out.push_back({origin.x + static_cast<double>(p.x) * unit, origin.y + static_cast<double>(p.y) * unit});
    return out;
}

/// A star-shaped counter-clockwise ring of m >= 3 vertices about the origin
/// in double: jittered angles (every gap below pi), radii in [0.6, 1] * radius.
inline std::vector<dpoint> small_star(uniform_source& u, std::size_t m, double radius) {
    const std::vector<double> angles = jittered_angles(u, m, u.between(0, 2 * pi), 2 * pi, 0.2, true);
    std::vector<dpoint> ring(m);
    for (std::size_t k = 0; k < m; ++k) {
        const double r = radius * u.between(0.6, 1);
        ring[k] = {r * std::cos(angles[k]), r * std::sin(angles[k])};
    }
    return ring;
}

inline polygon make_polygon(std::vector<dpoint> outer) {
    return polygon({ring_input{std::move(outer), ring_role::outer}});
}

/// The polygon's rings as input (stored orientation and order).
inline std::vector<ring_input> rings_of(const polygon& p) {
    std::vector<ring_input> rings(p.ring_count());
    for (std::size_t r = 0; r < p.ring_count(); ++r) {
        rings[r].role = p.role(r);
        for (std::size_t i = p.ring_begin(r); i < p.ring_end(r); ++i) rings[r].vertices.push_back(p.vertex(i));
    }
    return rings;
}

/// Every coordinate multiplied by m (rounded once).
inline polygon scaled_polygon(const polygon& p, double m) {
    std::vector<ring_input> rings = rings_of(p);
    for (auto& ring : rings)
        for (auto& v : ring.vertices) v = {v.x * m, v.y * m};
    return polygon(std::move(rings));
}

// ---------------------------------------------------------------- contact sites

/// A point p on A's boundary, A's outward unit normal n there and the
/// direction of the edge (for aligned rotations).
struct site {
    dpoint p;
    dpoint n;
    dpoint dir;
};

/// The edges and vertices of A where B is posed into contact.
struct site_pool {
    std::vector<std::size_t> edges;       ///< non-degenerate edges
    std::vector<std::size_t> vertices;    ///< convex or nearly flat vertices
    std::vector<std::size_t> favourites;  ///< edges drawn half of the time, if any
    double vertex_share = 0.3;
};

inline std::size_t previous(const polygon& a, std::size_t i) {
    for (std::size_t r = 0; r < a.ring_count(); ++r)
        if (i >= a.ring_begin(r) && i < a.ring_end(r)) return i == a.ring_begin(r) ? a.ring_end(r) - 1 : i - 1;
    throw std::logic_error("previous: vertex out of range");
}

inline dpoint edge_direction(const polygon& a, std::size_t i) {
    const dpoint& s = a.vertex(i);
    const dpoint& e = a.vertex(a.next(i));
    return direction(e.x - s.x, e.y - s.y);
}

/// The outward normal at vertex i, when the vertex is convex or within 1e-6
/// rad of flat (and its edges are not degenerate).
inline bool vertex_normal(const polygon& a, std::size_t i, dpoint& n) {
    const std::size_t h = previous(a, i), j = a.next(i);
    if (a.vertex(h) == a.vertex(i) || a.vertex(i) == a.vertex(j)) return false;
    const dpoint u1 = edge_direction(a, h), u2 = edge_direction(a, i);
    if (cross(u1, u2) < -1e-6) return false;
    // Outward bisector: rot(u1 + u2) by -90 degrees, or u1 - u2 at sharp tips
    // (the same direction for a convex turn; the larger is the more accurate).
    const dpoint sum{u1.x + u2.x, u1.y + u2.y}, diff{u1.x - u2.x, u1.y - u2.y};
    n = std::hypot(sum.x, sum.y) >= std::hypot(diff.x, diff.y) ? direction(sum.y, -sum.x) : direction(diff.x, diff.y);
    return true;
}

/// Every non-degenerate edge, every convex or nearly flat vertex.
inline site_pool auto_pool(const polygon& a, double vertex_share = 0.3) {
    site_pool pool;
    pool.vertex_share = vertex_share;
    dpoint n;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a.vertex(i) != a.vertex(a.next(i))) pool.edges.push_back(i);
        if (vertex_normal(a, i, n)) pool.vertices.push_back(i);
    }
    return pool;
}

inline site edge_site(const polygon& a, std::size_t i, double lambda) {
    const dpoint& s = a.vertex(i);
    const dpoint& e = a.vertex(a.next(i));
    const double dx = e.x - s.x, dy = e.y - s.y;
    return {{s.x + lambda * dx, s.y + lambda * dy}, direction(dy, -dx), direction(dx, dy)};
}

inline site draw_site(const polygon& a, const site_pool& pool, uniform_source& u) {
    const double which = u.next();
    const double lambda = u.between(0.05, 0.95);
    const double pick = u.next();
    auto at = [&](const std::vector<std::size_t>& list) {
        return list[std::min(list.size() - 1, static_cast<std::size_t>(pick * static_cast<double>(list.size())))];
    };
    if (!pool.favourites.empty() && which < 0.5) return edge_site(a, at(pool.favourites), lambda);
    if (!pool.vertices.empty() && u.next() < pool.vertex_share) {
        const std::size_t i = at(pool.vertices);
        site s{a.vertex(i), {1, 0}, edge_direction(a, i)};
        vertex_normal(a, i, s.n);
        return s;
    }
    return edge_site(a, at(pool.edges), lambda);
}

// ---------------------------------------------------------------- poses

/// How a group of frames turns B.
enum class turn { zero, small, any, aligned };

/// B's vertex whose rotated position is extreme against n (smallest dot
/// product with n), evaluated on coordinates scaled by a power of two so that
/// neither subnormal nor huge coordinates lose it.
inline std::size_t extreme_vertex(const polygon& b, int exponent, double c, double s, const dpoint& n) {
    std::size_t best = 0;
    double lowest = infinity;
    for (std::size_t j = 0; j < b.size(); ++j) {
        const double qx = std::ldexp(b.vertex(j).x, -exponent), qy = std::ldexp(b.vertex(j).y, -exponent);
        const double d = (c * qx - s * qy) * n.x + (s * qx + c * qy) * n.y;
        if (d < lowest) {
            lowest = d;
            best = j;
        }
    }
    return best;
}

/// B's size about its own origin: the largest absolute coordinate.
inline double size_of(const polygon& b) {
    double m = 0;
    for (const dpoint& v : b.vertices()) m = std::max({m, std::fabs(v.x), std::fabs(v.y)});
    return m;
}

inline double normalise_angle(double t) {
    while (t > pi) t -= 2 * pi;
    while (t <= -pi) t += 2 * pi;
    return t;
}

inline double draw_theta(turn k, const site& st, const polygon& b, uniform_source& u, bool grazing) {
    const double sign = coin(u) ? 1 : -1;
    const double magnitude = grazing ? log_uniform(u, -12, -4) : log_uniform(u, -9, -2);
    const double any = u.between(-pi, pi);
    const std::size_t j = draw_index(u, b.size());
    switch (k) {
    case turn::zero: return 0;
    case turn::small: return sign * magnitude;
    case turn::any: return any;
    case turn::aligned: {
        const dpoint d = edge_direction(b, b.vertex(j) == b.vertex(b.next(j)) ? b.next(j) : j);
        return normalise_angle(std::atan2(st.dir.y, st.dir.x) - std::atan2(d.y, d.x) + pi);
    }
    }
    return 0;
}

/// t moved by k ulps in each coordinate along which n points (away from A
/// for k > 0: the move has a positive component along n).
inline dpoint shift_ulps(dpoint t, const dpoint& n, int k) {
    if (k == 0) return t;
    if (n.x != 0) t.x = step(t.x, n.x > 0 ? k : -k);
    if (n.y != 0) t.y = step(t.y, n.y > 0 ? k : -k);
    return t;
}

/// One group of frames about the contact of B with A at `st` (see the file
/// comment), appended while out holds fewer than `limit` poses.
inline void add_group(std::vector<pose>& out, std::size_t limit, const site& st, const polygon& b, double theta,
                      bool grazing, uniform_source& u) {
    const double c = std::cos(theta), s = std::sin(theta);
    const double size = size_of(b);
    const dpoint q = b.vertex(extreme_vertex(b, std::ilogb(size), c, s, st.n));
    const dpoint t0 = contact_translation(st.p, q, c, s);
    std::vector<int> ulps;
    std::vector<double> moves;
    if (grazing) {
        ulps = {1, -1, 2, -2, 3, -3, 4, -4};
    } else {
        const int k1 = static_cast<int>(integer(u, 2, 4)), k2 = static_cast<int>(integer(u, 2, 4));
        const int k3 = static_cast<int>(integer(u, -4, 4));
        ulps = {0, 1, -1, k1, -k2, k3};
        const double apart = u.between(0.05, 0.5), into = u.between(0.05, 0.5);
        moves = {apart, -into};
    }
    for (int k : ulps) {
        if (out.size() >= limit) return;
        const dpoint t = shift_ulps(t0, st.n, k);
        out.push_back({t.x, t.y, theta});
    }
    for (double m : moves) {
        if (out.size() >= limit) return;
        out.push_back({t0.x + m * size * st.n.x, t0.y + m * size * st.n.y, theta});
    }
}

/// A scene before its poses: the polygons, where contacts are made and how
/// groups turn B (cycled group after group).
struct plan {
    polygon a, b;
    site_pool pool;
    std::vector<turn> turns{turn::zero, turn::small, turn::any, turn::aligned};
    bool grazing = false;
};

inline std::vector<pose> plan_poses(const plan& p, std::size_t frames, uniform_source& u) {
    std::vector<pose> out;
    out.reserve(frames);
    for (std::size_t g = 0; out.size() < frames; ++g) {
        const site st = draw_site(p.a, p.pool, u);
        const double theta = draw_theta(p.turns[g % p.turns.size()], st, p.b, u, p.grazing);
        add_group(out, frames, st, p.b, theta, p.grazing, u);
    }
    return out;
}

// ---------------------------------------------------------------- families

/// Each lattice edge of `base` (times unit, a power of two) cut into 2, 4 or
/// 8 (up to 2^max_split) equal pieces: the cut points are exactly collinear,
/// then each is moved by 1 to 4 ulps in x or in y, either way.
inline std::vector<dpoint> collinear_runs(uniform_source& u, const std::vector<lpoint>& base, int unit_exponent,
                                          int max_split) {
    std::vector<dpoint> out;
    for (std::size_t k = 0; k < base.size(); ++k) {
        const lpoint& a = base[k];
        const lpoint& b = base[(k + 1) % base.size()];
        const int split = static_cast<int>(integer(u, 1, max_split));
        const std::int64_t pieces = std::int64_t{1} << split;
        for (std::int64_t j = 0; j < pieces; ++j) {
            dpoint p{std::ldexp(static_cast<double>(a.x * pieces + (b.x - a.x) * j), unit_exponent - split),
                     std::ldexp(static_cast<double>(a.y * pieces + (b.y - a.y) * j), unit_exponent - split)};
            if (j > 0) {
                const int k_abs = static_cast<int>(integer(u, 1, 4));
                const int k_ulps = coin(u) ? k_abs : -k_abs;
                if (coin(u))
                    p.x = step(p.x, k_ulps);
                else
                    p.y = step(p.y, k_ulps);
            }
            out.push_back(p);
        }
    }
    return out;
}

inline plan near_collinear_plan(uniform_source& u) {
    plan p;
    const auto base_a = lattice_star(u, static_cast<std::size_t>(integer(u, 4, 7)), 20, 48);
    p.a = make_polygon(collinear_runs(u, base_a, -2, 3));
    const auto base_b = lattice_star(u, static_cast<std::size_t>(integer(u, 3, 5)), 8, 16);
    p.b = make_polygon(collinear_runs(u, base_b, -3, 2));
    p.pool = auto_pool(p.a, 0.6);
    p.turns = {turn::zero, turn::aligned, turn::small, turn::any};
    return p;
}

/// A sliver of length `length` along the x axis about the origin with height
/// aspect * length: a triangle (apex above) or a flat quadrilateral.
inline std::vector<dpoint> sliver_ring(uniform_source& u, double length, double aspect, bool quad) {
    const double h = aspect * length;
    if (!quad) return {{-length / 2, 0}, {length / 2, 0}, {u.between(-length / 4, length / 4), h}};
    return {{-length / 2, 0},
            {u.between(-length / 4, length / 4), -h / 2},
            {length / 2, 0},
            {u.between(-length / 4, length / 4), h / 2}};
}

/// The ring turned by phi and moved by (cx, cy) (rounded).
inline std::vector<dpoint> placed(std::vector<dpoint> ring, double phi, double cx, double cy) {
    const double c = std::cos(phi), s = std::sin(phi);
    for (dpoint& v : ring) v = {c * v.x - s * v.y + cx, s * v.x + c * v.y + cy};
    return ring;
}

inline plan sliver_plan(uniform_source& u) {
    plan p;
    const double length = log_uniform(u, 0, 2), aspect = log_uniform(u, -14, -8);
    const bool quad = coin(u);
    const auto ring = sliver_ring(u, length, aspect, quad);
    const double phi = u.between(0, 2 * pi);
    const double cx = u.between(-length / 8, length / 8), cy = u.between(-length / 8, length / 8);
    p.a = make_polygon(placed(ring, phi, cx, cy));
    if (coin(u)) {
        p.b = make_polygon(small_star(u, 3, length * u.between(0.05, 0.3)));
    } else {
        const double b_length = length * u.between(0.2, 0.8);
        p.b = make_polygon(sliver_ring(u, b_length, log_uniform(u, -14, -8), false));
    }
    p.pool = auto_pool(p.a, 0.3);
    return p;
}

inline plan needle_plan(uniform_source& u) {
    plan p;
    const std::size_t body = static_cast<std::size_t>(integer(u, 5, 9));
    const std::size_t spikes = static_cast<std::size_t>(integer(u, 2, 5));
    const std::size_t slots = body + spikes, every = slots / spikes;
    const std::vector<double> angles = jittered_angles(u, slots, u.between(0, 2 * pi), 2 * pi, 0.2, true);
    std::vector<dpoint> ring;
    std::size_t made = 0;
    for (std::size_t k = 0; k < slots; ++k) {
        const double a = angles[k];
        if (k % every == 0 && made < spikes) {
            ++made;
            // Width 1e-10 of the length at the base (radius 0.8).
            const double length = u.between(10, 100), base = 0.8;
            const double half = 0.5e-10 * length / base;
            ring.push_back({base * std::cos(a - half), base * std::sin(a - half)});
            ring.push_back({(base + length) * std::cos(a), (base + length) * std::sin(a)});
            ring.push_back({base * std::cos(a + half), base * std::sin(a + half)});
        } else {
            const double r = u.between(0.8, 1);
            ring.push_back({r * std::cos(a), r * std::sin(a)});
        }
    }
    p.a = make_polygon(std::move(ring));
    if (coin(u)) {
        const std::size_t m = static_cast<std::size_t>(integer(u, 3, 6));
        p.b = make_polygon(small_star(u, m, u.between(0.05, 0.5)));
    } else {
        const double length = u.between(1, 5), w = 1e-10 * length;
        p.b = make_polygon({{-length / 2, -w / 2}, {length / 2, 0}, {-length / 2, w / 2}});
    }
    p.pool = auto_pool(p.a, 0.4);
    return p;
}

inline plan tiny_beside_huge_plan(uniform_source& u) {
    plan p;
    const std::size_t m = static_cast<std::size_t>(integer(u, 5, 8));
    const double radius = u.between(600, 900);
    const std::vector<double> angles = jittered_angles(u, m, u.between(0, 2 * pi), 2 * pi, 0.2, true);
    std::vector<dpoint> big(m);
    for (std::size_t k = 0; k < m; ++k) {
        const double r = radius * u.between(0.8, 1);
        big[k] = {r * std::cos(angles[k]), r * std::sin(angles[k])};
    }
    // At most vertices, a micro zigzag of edges about 1e-9 long: V - 2e u1,
    // a bump of e out of or into the incoming edge, V, a bump on the outgoing
    // edge, V + 2e u2; its first and last edges meet edges about 1e3 long.
    std::vector<dpoint> ring;
    for (std::size_t k = 0; k < m; ++k) {
        const dpoint& v = big[k];
        const dpoint& prev = big[(k + m - 1) % m];
        const dpoint& next = big[(k + 1) % m];
        if (u.next() < 0.25) {
            ring.push_back(v);
            continue;
        }
        const dpoint u1 = direction(v.x - prev.x, v.y - prev.y), u2 = direction(next.x - v.x, next.y - v.y);
        const dpoint n1{u1.y, -u1.x}, n2{u2.y, -u2.x};
        const double e = 1e-9 * u.between(1, 4);
        const double s1 = coin(u) ? e : -e, s2 = coin(u) ? e : -e;
        ring.push_back({v.x - 2 * e * u1.x, v.y - 2 * e * u1.y});
        ring.push_back({v.x - e * u1.x + s1 * n1.x, v.y - e * u1.y + s1 * n1.y});
        ring.push_back(v);
        ring.push_back({v.x + e * u2.x + s2 * n2.x, v.y + e * u2.y + s2 * n2.y});
        ring.push_back({v.x + 2 * e * u2.x, v.y + 2 * e * u2.y});
    }
    p.a = make_polygon(std::move(ring));
    const std::size_t b_vertices = static_cast<std::size_t>(integer(u, 3, 6));
    p.b = make_polygon(small_star(u, b_vertices, log_uniform(u, -9.5, 0)));
    p.pool = auto_pool(p.a, 0.4);
    return p;
}

/// The lattice step of the offset family: 2^-16 (features of 64 steps, about
/// 1e-3 across), doubled until the coordinates near the offset, which are
/// multiples of it, are exactly representable. From offsets of about 7e10 on
/// the 1e-3 features would collapse onto the double grid (at 1e15 the spacing
/// is 0.125: a 1e-3 feature has fewer than 3 distinct vertices), so they are
/// enlarged instead: the shape stays the same lattice shape, 64 ulps of the
/// offset across.
inline double offset_unit(double offset) {
    double unit = 0x1p-16;
    for (;;) {
        const double far = offset + 128 * unit;
        const double spacing = std::ldexp(1.0, std::ilogb(far) - 52);
        if (spacing <= unit) return unit;
        unit *= 2;
    }
}

inline plan offset_plan(uniform_source& u, double offset) {
    plan p;
    const double unit = offset_unit(offset);
    const double alpha = u.between(0, 2 * pi);
    const dpoint centre{std::round(offset * std::cos(alpha) / unit) * unit,
                        std::round(offset * std::sin(alpha) / unit) * unit};
    auto a_ring = lattice_star(u, static_cast<std::size_t>(integer(u, 5, 10)), 16, 32);
    if (coin(u)) a_ring = lattice_hull(a_ring);
    auto b_ring = lattice_star(u, static_cast<std::size_t>(integer(u, 3, 8)), 8, 24);
    if (coin(u)) b_ring = lattice_hull(b_ring);
    p.a = make_polygon(from_lattice(a_ring, unit, centre));
    p.b = make_polygon(from_lattice(b_ring, unit));
    p.pool = auto_pool(p.a, 0.3);
    return p;
}

inline plan scaled_base_plan(uniform_source& u, std::size_t index) {
    plan p;
    static constexpr family kinds[] = {family::irregular, family::contour, family::starred, family::with_hole,
                                       family::convex};
    const family fa = kinds[index % 5];
    const std::size_t n = std::size_t{16} << size_shift(u);
    p.a = make_family_polygon(fa, n, draw_seed(u));
    static constexpr family b_kinds[] = {family::convex, family::starred, family::irregular};
    const std::size_t b_vertices = coin(u) ? 8 : 16;
    const polygon b = make_family_polygon(b_kinds[index % 3], b_vertices, draw_seed(u));
    p.b = scaled_polygon(b, 0.125);
    p.pool = auto_pool(p.a, 0.3);
    return p;
}

inline plan subnormal_plan(uniform_source& u) {
    plan p;
    const double unit = std::numeric_limits<double>::denorm_min();  // 2^-1074
    const int e = static_cast<int>(integer(u, 4, 40));
    const double radius = std::ldexp(1.0, e);
    const std::size_t m = static_cast<std::size_t>(std::min<std::int64_t>(integer(u, 5, 12), std::max(3, e * 2)));
    auto a_ring = lattice_star(u, m, radius / 2, radius);
    if (coin(u)) a_ring = lattice_hull(a_ring);
    const double b_radius = std::ldexp(radius, -static_cast<int>(integer(u, 0, 3)));
    auto b_ring = lattice_star(u, static_cast<std::size_t>(integer(u, 3, 6)), b_radius / 2, b_radius);
    // The centre at up to 2^42 units (coordinates stay below 2^-1030), or at 0.
    const double reach = std::ldexp(1.0, static_cast<int>(integer(u, 0, 42)));
    const double cx = coin(u) ? 0 : std::round(u.between(-reach, reach));
    const double cy = std::round(u.between(-reach, reach));
    p.a = make_polygon(from_lattice(a_ring, unit, {cx * unit, cy * unit}));
    p.b = make_polygon(from_lattice(b_ring, unit));
    p.pool = auto_pool(p.a, 0.4);
    p.turns = {turn::zero};
    return p;
}

inline plan grazing_plan(uniform_source& u, std::size_t index) {
    plan p;
    static constexpr family kinds[] = {family::irregular, family::convex, family::starred, family::contour,
                                       family::with_hole};
    const std::size_t n = std::size_t{16} << size_shift(u);
    p.a = make_family_polygon(kinds[index % 5], n, draw_seed(u));
    p.pool = auto_pool(p.a, 0.3);
    if (coin(u)) {
        p.b = scaled_polygon(make_family_polygon(family::convex, 8, draw_seed(u)), 0.125);
    } else {
        // A triangle with an edge antiparallel to edge i0 of A (a quarter of
        // its length; exact on the 2^-20 grid): at theta = 0 that edge lies
        // parallel to A's edge, k ulps away.
        const std::size_t i0 = p.pool.edges[draw_index(u, p.pool.edges.size())];
        const dpoint& a0 = p.a.vertex(i0);
        const dpoint& a1 = p.a.vertex(p.a.next(i0));
        const double ex = a1.x - a0.x, ey = a1.y - a0.y;
        p.b = make_polygon({{0, 0}, {-ex / 4, -ey / 4}, {-ex / 8 + ey / 4, -ey / 8 - ex / 4}});
        p.pool.favourites = {i0};
    }
    p.turns = {turn::zero, turn::small, turn::aligned, turn::small};
    p.grazing = true;
    return p;
}

/// A pinwheel on the lattice: symmetric under the half turn about the origin
/// (so its area centroid is the origin), with radial edges (both ends on one
/// ray from the origin), whose lines pass through the centroid. Appends the
/// indices of the radial edges to `radial`.
inline std::vector<lpoint> pinwheel(uniform_source& u, std::vector<std::size_t>& radial) {
    for (int attempt = 0; attempt < 10000; ++attempt) {
        const std::size_t k = static_cast<std::size_t>(integer(u, 3, 8));
        std::vector<double> angles = jittered_angles(u, k + 1, u.between(0, pi), pi, 0.3, false);
        angles.pop_back();
        const double reach = u.between(8, 24);
        std::vector<lpoint> dirs(k);
        for (std::size_t j = 0; j < k; ++j)
            dirs[j] = {std::llround(reach * std::cos(angles[j])), std::llround(reach * std::sin(angles[j]))};
        bool ok = cross(dirs[k - 1], lpoint{-dirs[0].x, -dirs[0].y}) > 0;
        for (std::size_t j = 0; ok && j + 1 < k; ++j) ok = cross(dirs[j], dirs[j + 1]) > 0;
        if (!ok) continue;
        std::vector<lpoint> half;
        std::vector<std::size_t> radial_half;
        for (std::size_t j = 0; j < k; ++j) {
            const std::int64_t r1 = integer(u, 2, 8);
            if (coin(u) || (j + 1 == k && radial_half.empty())) {
                std::int64_t r2 = integer(u, 2, 7);
                if (r2 >= r1) ++r2;
                radial_half.push_back(half.size());
                half.push_back({r1 * dirs[j].x, r1 * dirs[j].y});
                half.push_back({r2 * dirs[j].x, r2 * dirs[j].y});
            } else {
                half.push_back({r1 * dirs[j].x, r1 * dirs[j].y});
            }
        }
        std::vector<lpoint> ring = half;
        for (const lpoint& v : half) ring.push_back({-v.x, -v.y});
        radial.clear();
        for (std::size_t i : radial_half) {
            radial.push_back(i);
            radial.push_back(i + half.size());
        }
        return ring;
    }
    throw std::logic_error("pinwheel: no valid ring drawn");
}

inline plan centroid_plan(uniform_source& u) {
    plan p;
    std::vector<std::size_t> radial;
    std::vector<lpoint> ring = pinwheel(u, radial);
    const lpoint shift{integer(u, -512, 512), integer(u, -512, 512)};
    for (lpoint& v : ring) v = {v.x + shift.x, v.y + shift.y};
    const int e = static_cast<int>(integer(u, -20, 0));
    const double unit = std::ldexp(1.0, e);
    p.a = make_polygon(from_lattice(ring, unit));
    if (coin(u)) {
        std::vector<std::size_t> unused;
        p.b = make_polygon(from_lattice(pinwheel(u, unused), unit / 4));
    } else {
        p.b = make_polygon(from_lattice(lattice_star(u, static_cast<std::size_t>(integer(u, 3, 7)), 8, 32), unit));
    }
    p.pool = auto_pool(p.a, 0.3);
    p.pool.favourites = radial;
    return p;
}

inline plan large_plan(uniform_source& u) {
    plan p;
    const std::size_t n = static_cast<std::size_t>(integer(u, 100000, 131072));
    const double radius = 0x1p20;
    for (int attempt = 0;; ++attempt) {
        const wobble w(u);
        const std::vector<double> angles = jittered_angles(u, n, 0, 2 * pi, 0.5, true);
        std::vector<lpoint> ring(n);
        for (std::size_t k = 0; k < n; ++k) {
            const double r = radius * (0.75 + 0.15 * w(angles[k])) + u.between(-16, 16);
            ring[k] = {std::llround(r * std::cos(angles[k])), std::llround(r * std::sin(angles[k]))};
        }
        if (winds_once(ring)) {
            p.a = make_polygon(from_lattice(ring, 1));
            break;
        }
        if (attempt > 100) throw std::logic_error("large: no valid ring drawn");
    }
    p.b = make_polygon(from_lattice(lattice_star(u, static_cast<std::size_t>(integer(u, 3, 8)), 16, 64), 1));
    p.pool = auto_pool(p.a, 0.3);
    p.turns = {turn::zero, turn::any};
    return p;
}

inline plan comb_plan(uniform_source& u) {
    plan p;
    const std::size_t teeth = static_cast<std::size_t>(integer(u, 50, 500));
    const double length = 1, width = 1e-3 * length, gap = width * u.between(3, 10), bar = 0.05;
    std::vector<double> x(teeth), h(teeth);
    for (std::size_t k = 0; k < teeth; ++k) {
        x[k] = gap + static_cast<double>(k) * (width + gap);
        h[k] = length * u.between(0.7, 1);
    }
    const double right = x[teeth - 1] + width + gap;
    std::vector<dpoint> ring{{0, -bar}, {right, -bar}, {right, 0}};
    for (std::size_t k = teeth; k-- > 0;) {
        ring.push_back({x[k] + width, 0});
        ring.push_back({x[k] + width, h[k]});
        ring.push_back({x[k], h[k]});
        ring.push_back({x[k], 0});
    }
    ring.push_back({0, 0});
    p.a = make_polygon(coin(u) ? placed(std::move(ring), u.between(0, 2 * pi), 0, 0) : std::move(ring));
    const std::size_t b_vertices = static_cast<std::size_t>(integer(u, 3, 7));
    p.b = make_polygon(small_star(u, b_vertices, gap * u.between(0.15, 0.35)));
    p.pool = auto_pool(p.a, 0.2);
    return p;
}

inline plan spiral_plan(uniform_source& u) {
    plan p;
    const std::int64_t turns = integer(u, 5, 20), per_turn = integer(u, 48, 64);
    const double pitch = 1, thickness = u.between(0.4, 0.6), r0 = u.between(1, 2);
    const std::int64_t steps = turns * per_turn;
    std::vector<dpoint> ring;
    auto at = [&](std::int64_t k, double r_base) {
        const double phi = 2 * pi * static_cast<double>(k) / static_cast<double>(per_turn);
        const double r = r_base + pitch * static_cast<double>(k) / static_cast<double>(per_turn);
        ring.push_back({r * std::cos(phi), r * std::sin(phi)});
    };
    for (std::int64_t k = 0; k <= steps; ++k) at(k, r0 + thickness);
    for (std::int64_t k = steps; k >= 0; --k) at(k, r0);
    p.a = make_polygon(std::move(ring));
    const std::size_t b_vertices = static_cast<std::size_t>(integer(u, 3, 7));
    p.b = make_polygon(small_star(u, b_vertices, (pitch - thickness) * u.between(0.15, 0.3)));
    p.pool = auto_pool(p.a, 0.3);
    return p;
}

/// Touching scenes: lattice polygons times 2^e, theta = 0. Frames in pairs:
/// an exact contact (t = a - q with a A's extreme vertex along an integer
/// direction n and q B's extreme vertex against it, or t = midpoint(e) - q
/// for an edge e of A's convex hull with outward normal n), then the same
/// pose moved one ulp along n in x (or in y when n is vertical). Every
/// difference is exact, so frame 2i touches and frame 2i + 1 is apart.
inline void touching_scene(uniform_source& u, std::size_t frames, polygon& a, polygon& b, std::vector<pose>& poses) {
    std::vector<lpoint> la = lattice_star(u, static_cast<std::size_t>(integer(u, 5, 12)), 64, 1024);
    if (coin(u)) la = lattice_hull(la);
    for (lpoint& v : la) v = {4 * v.x, 4 * v.y};
    std::vector<lpoint> lb;
    if (coin(u)) {
        for (const lpoint& v : la) lb.push_back({-v.x / 4, -v.y / 4});  // half turn: edges antiparallel to A's
    } else {
        lb = lattice_star(u, static_cast<std::size_t>(integer(u, 3, 8)), 16, 256);
        if (coin(u)) lb = lattice_hull(lb);
    }
    const int e = static_cast<int>(integer(u, -40, 20));
    const double unit = std::ldexp(1.0, e);
    a = make_polygon(from_lattice(la, unit));
    b = make_polygon(from_lattice(lb, unit));

    std::vector<std::size_t> hull_edges;
    for (std::size_t i = 0; i < la.size(); ++i) {
        const lpoint& p0 = la[i];
        const lpoint d = la[(i + 1) % la.size()] - p0;
        bool supporting = true;
        for (const lpoint& v : la) supporting = supporting && cross(d, v - p0) >= 0;
        if (supporting) hull_edges.push_back(i);
    }
    auto extreme = [](const std::vector<lpoint>& ring, const lpoint& n, bool highest) {
        std::size_t best = 0;
        for (std::size_t j = 1; j < ring.size(); ++j) {
            const std::int64_t d = dot(ring[j], n), b0 = dot(ring[best], n);
            if (highest ? d > b0 : d < b0) best = j;
        }
        return ring[best];
    };
    poses.clear();
    while (poses.size() < frames) {
        lpoint n, contact;
        const bool vertex_contact = coin(u);
        if (vertex_contact || hull_edges.empty()) {
            do n = {integer(u, -64, 64), integer(u, -64, 64)};
            while (n.x == 0 && n.y == 0);
            contact = extreme(la, n, true);
            contact = {2 * contact.x, 2 * contact.y};  // in half units, as midpoints are
        } else {
            const std::size_t i = hull_edges[draw_index(u, hull_edges.size())];
            const lpoint& p0 = la[i];
            const lpoint& p1 = la[(i + 1) % la.size()];
            n = {p1.y - p0.y, p0.x - p1.x};
            contact = {p0.x + p1.x, p0.y + p1.y};
        }
        const lpoint q = extreme(lb, n, false);
        // A's coordinates are multiples of 4, so contact / 2 is on the lattice.
        const dpoint t{std::ldexp(static_cast<double>(contact.x / 2 - q.x), e),
                       std::ldexp(static_cast<double>(contact.y / 2 - q.y), e)};
        poses.push_back({t.x, t.y, 0});
        if (poses.size() >= frames) break;
        dpoint apart = t;
        if (n.x != 0)
            apart.x = step(t.x, n.x > 0 ? 1 : -1);
        else
            apart.y = step(t.y, n.y > 0 ? 1 : -1);
        poses.push_back({apart.x, apart.y, 0});
    }
}

/// The position in `list` of scene i of `count`, spread over the list
/// (first and last included); the middle for a single scene.
inline double spread_pick(const std::vector<double>& list, std::size_t i, std::size_t count) {
    if (count <= 1) return list[list.size() / 2];
    return list[(i * (list.size() - 1)) / (count - 1)];
}

/// A magnitude in names: "1e09", "1e-150", "1e00"; other values in %.6g with
/// '.' written 'p' and no '+'.
inline std::string magnitude_tag(double m) {
    if (m == 0) return "0";
    char buf[48];
    const int e = static_cast<int>(std::lround(std::log10(std::fabs(m))));
    std::snprintf(buf, sizeof buf, "1e%d", e);
    if (m > 0 && std::strtod(buf, nullptr) == m) {
        std::snprintf(buf, sizeof buf, e < 0 ? "1e-%02d" : "1e%02d", e < 0 ? -e : e);
        return buf;
    }
    std::snprintf(buf, sizeof buf, "%.6g", m);
    std::string s;
    for (const char* c = buf; *c; ++c) {
        if (*c == '.')
            s += 'p';
        else if (*c != '+')
            s += *c;
    }
    return s;
}

inline std::string scene_name(stiff_family f, double magnitude, std::size_t index) {
    char number[16];
    std::snprintf(number, sizeof number, "%03zu", index);
    std::string name = stiff_family_name(f) + "_";
    if (f == stiff_family::offset || f == stiff_family::scaled) name += magnitude_tag(magnitude) + "_";
    return name + number;
}

/// Scene `index` of family f (its shapes depend on seed, f and index only,
/// not on the magnitude).
inline stiff_scene make_scene(stiff_family f, double magnitude, std::size_t index, std::uint64_t seed,
                              std::size_t frames) {
    uniform_source u(scene_seed(seed, f, index));
    stiff_scene s;
    s.name = scene_name(f, magnitude, index);
    s.family = f;
    s.magnitude = magnitude;
    plan p;
    switch (f) {
    case stiff_family::near_collinear: p = near_collinear_plan(u); break;
    case stiff_family::sliver: p = sliver_plan(u); break;
    case stiff_family::needle: p = needle_plan(u); break;
    case stiff_family::tiny_beside_huge: p = tiny_beside_huge_plan(u); break;
    case stiff_family::offset: p = offset_plan(u, magnitude); break;
    case stiff_family::scaled: {
        p = scaled_base_plan(u, index);
        s.poses = plan_poses(p, frames, u);
        for (pose& q : s.poses) q = {q.tx * magnitude, q.ty * magnitude, q.theta};
        s.a = scaled_polygon(p.a, magnitude);
        s.b = scaled_polygon(p.b, magnitude);
        return s;
    }
    case stiff_family::subnormal: p = subnormal_plan(u); break;
    case stiff_family::grazing: p = grazing_plan(u, index); break;
    case stiff_family::touching: touching_scene(u, frames, s.a, s.b, s.poses); return s;
    case stiff_family::centroid_on_edge_line: p = centroid_plan(u); break;
    case stiff_family::large: p = large_plan(u); break;
    case stiff_family::comb: p = comb_plan(u); break;
    case stiff_family::spiral: p = spiral_plan(u); break;
    }
    s.poses = plan_poses(p, frames, u);
    s.a = std::move(p.a);
    s.b = std::move(p.b);
    return s;
}

// Magnitudes are limited to where products of two coordinates (up to 1e300)
// and their sums stay normal doubles, so that the study's floating types
// measure rounding, not overflow. The library is not limited there: its ring
// orientation sums products exactly over the whole range of double (a
// fixed-point accumulator, number/exact_sum.hpp), and the exact and certified
// modes are tested at 1e200, 1e-170 and subnormal scale (tests/detect).
inline void check_offset(double offset) {
    if (!(offset >= 1 && offset <= 1e150))
        throw std::invalid_argument("make_offset_scenes: the offset must be in [1, 1e150]");
}

inline void check_scale(double scale) {
    if (!(scale >= 1e-150 && scale <= 1e150))
        throw std::invalid_argument("make_scaled_scenes: the scale must be in [1e-150, 1e150]");
}

}  // namespace stiff_detail

/// `count` scenes of family f (at most 2 for `large`), each with
/// `frames_per_scene` poses. The offset and scaled
/// families spread their scenes over offset_magnitudes() and
/// scale_magnitudes() (first and last included when count >= 2). Scene i is
/// the same for any count. Families:
///   near_collinear    lattice star rings whose edges are cut in 2..8 exactly
///                     collinear pieces, each cut point moved 1..4 ulps; B the
///                     same, smaller; B's vertices posed onto the cut points
///                     and the runs, B's edges also aligned with them.
///   sliver            A a triangle or flat quadrilateral of aspect ratio
///                     1e-14..1e-8 (length 1..100, any direction), B a small
///                     fat triangle or another sliver.
///   needle            a body of radius ~1 with 2..5 spikes 10..100 long whose
///                     base width is 1e-10 of their length; B small or a needle.
///   tiny_beside_huge  a 5..8-gon of radius ~800 (edges ~1e3) whose vertices
///                     carry zigzags of edges 1e-9..4e-9 long; B of size
///                     1e-9.5..1.
///   offset            lattice polygons (step 2^-16, about 1e-3 across) centred
///                     at distance `magnitude` from the origin, B alike (see
///                     stiff_detail::offset_unit for offsets >= ~7e10).
///   scaled            a family polygon (16..64 vertices) and one of 8 or 16
///                     vertices at 1/8 size, posed near contact, then every
///                     coordinate and every translation times `magnitude`.
///   subnormal         lattice polygons in units of 2^-1074 (radius 2^4..2^40
///                     units, centre within 2^42 units), theta = 0.
///   grazing           a family polygon; B a small convex family polygon or a
///                     triangle with an edge antiparallel to one of A's; only
///                     frames 1..4 ulps outside and inside, theta 0 or tiny.
///   touching          see stiff_detail::touching_scene: even frames touch
///                     exactly, odd frames are the previous one moved one ulp
///                     away.
///   centroid_on_edge_line  a half-turn symmetric lattice pinwheel (times 2^e,
///                     moved) with radial edges: those edges' lines pass
///                     exactly through polygon::centroid().
///   large             a star ring of 100,000..131,072 integer vertices
///                     (radius ~2^20, edges ~50), B a small lattice polygon.
///   comb              a bar with 50..500 teeth of length 0.7..1 and width
///                     1e-3, gaps 3..10 widths (turned by a random angle half
///                     of the time); B 0.3..0.7 of a gap across, slid between
///                     the teeth.
///   spiral            a band of thickness 0.4..0.6 winding 5..20 times with
///                     pitch 1 (48..64 vertices a turn); B within the gap.
inline std::vector<stiff_scene> make_stiff_scenes(stiff_family f, std::size_t count, std::uint64_t seed,
                                                  std::size_t frames_per_scene = 64) {
    if (f == stiff_family::large) count = std::min<std::size_t>(count, 2);
    std::vector<stiff_scene> scenes;
    scenes.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        double magnitude = 0;
        if (f == stiff_family::offset) magnitude = stiff_detail::spread_pick(offset_magnitudes(), i, count);
        if (f == stiff_family::scaled) magnitude = stiff_detail::spread_pick(scale_magnitudes(), i, count);
        scenes.push_back(stiff_detail::make_scene(f, magnitude, i, seed, frames_per_scene));
    }
    return scenes;
}

/// `count` offset scenes at one offset (in [1, 1e150]); scene i has the same
/// shapes and relative poses at every offset.
inline std::vector<stiff_scene> make_offset_scenes(double offset, std::size_t count, std::uint64_t seed,
                                                   std::size_t frames_per_scene = 64) {
    stiff_detail::check_offset(offset);
    std::vector<stiff_scene> scenes;
    for (std::size_t i = 0; i < count; ++i)
        scenes.push_back(stiff_detail::make_scene(stiff_family::offset, offset, i, seed, frames_per_scene));
    return scenes;
}

/// `count` scaled scenes at one scale (in [1e-150, 1e150]); scene i is the
/// same base scene at every scale.
inline std::vector<stiff_scene> make_scaled_scenes(double scale, std::size_t count, std::uint64_t seed,
                                                   std::size_t frames_per_scene = 64) {
    stiff_detail::check_scale(scale);
    std::vector<stiff_scene> scenes;
    for (std::size_t i = 0; i < count; ++i)
        scenes.push_back(stiff_detail::make_scene(stiff_family::scaled, scale, i, seed, frames_per_scene));
    return scenes;
}

/// Poses per scene of `large` in the committed data/stiff.
inline constexpr std::size_t large_data_frames = 16;

/// The scenes of the committed data/stiff: `count` per family (64 poses
/// each), one for large (large_data_frames poses).
inline std::vector<stiff_scene> stiff_data_scenes(std::uint64_t seed = default_stiff_seed,
                                                  std::size_t count = default_stiff_count) {
    std::vector<stiff_scene> scenes;
    for (stiff_family f : all_stiff_families()) {
        const bool large = f == stiff_family::large;
        auto some =
            make_stiff_scenes(f, large ? std::min<std::size_t>(count, 1) : count, seed, large ? large_data_frames : 64);
        for (auto& s : some) scenes.push_back(std::move(s));
    }
    return scenes;
}

/// A file of the stiff data set: its name in the directory and its text.
struct stiff_file {
    std::string name;
    std::string text;
};

/// The files of a scene set: <name>_a.wkt, <name>_b.wkt (WKT and a newline),
/// <name>_poses.csv (tx,ty,theta) for each scene, then manifest.csv with the
/// header name,family,magnitude,a,b,poses and one line per scene. Numbers in
/// their shortest form that reads back to the same double.
inline std::vector<stiff_file> stiff_data_files(const std::vector<stiff_scene>& scenes) {
    std::vector<stiff_file> files;
    std::string manifest = "name,family,magnitude,a,b,poses\n";
    for (const stiff_scene& s : scenes) {
        const std::string a = s.name + "_a.wkt", b = s.name + "_b.wkt", poses = s.name + "_poses.csv";
        files.push_back({a, to_wkt(s.a) + "\n"});
        files.push_back({b, to_wkt(s.b) + "\n"});
        std::ostringstream csv;
        write_poses_csv(csv, s.poses);
        files.push_back({poses, csv.str()});
        std::array<char, 32> buf{};
        const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), s.magnitude);
        manifest += s.name + "," + stiff_family_name(s.family) + "," + std::string(buf.data(), res.ptr) + "," + a +
                    "," + b + "," + poses + "\n";
    }
    files.push_back({"manifest.csv", manifest});
    return files;
}

}  // namespace influence2d::verification
