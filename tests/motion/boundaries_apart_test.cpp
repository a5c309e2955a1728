// SPDX-License-Identifier: BSL-1.0
// The swept boxes of angle-linear motions (motion/boundaries_apart.hpp)
// against exact distances at sampled times: B posed at each sampled time as
// every query poses it, then every vertex's distance from every edge of the
// other polygon computed on CGAL's kernel over exact rationals. Before the
// reported start no vertex comes within the margin of an edge; over the
// whole motion no pair left out of the near pairs does. Scenes: the family
// polygons and random multipolygons with holes, turns up to four quarter
// turns, margins from 0 to a tenth of the scene.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "influence2d/motion/boundaries_apart.hpp"
#include "influence2d/motion/motion.hpp"
#include "support/effort.hpp"
#include "support/exact_distance.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"
#include "verification/families.hpp"

using namespace influence2d;

namespace {

/// B's vertex j at pose p in A's frame, posed in double as the queries
/// pose it.
point<double> posed_apart(const polygon& b, std::size_t j, const pose& p) {
    return rotation_pose(p).apply<double>(b.vertex(j));
}

/// Whether the vertex-edge pair `s` lies farther than `margin` from each
/// other at pose p, exactly (CGAL) where double's distance is within 1e-6
/// of the margin, and by double's distance otherwise; `fuzz` the posing's
/// own reach (B posed in double, not on the exact motion).
bool farther(const polygon& a, const polygon& b, const sweep::contact_site& s, const pose& p, double margin,
             double fuzz) {
    point<double> v, e0, e1;
    if (s.moving_vertex) {
        v = posed_apart(b, s.vertex, p);
        e0 = a.vertex(s.edge);
        e1 = a.vertex(a.next(s.edge));
    } else {
        v = a.vertex(s.vertex);
        e0 = posed_apart(b, s.edge, p);
        e1 = posed_apart(b, b.next(s.edge), p);
    }
    const double limit = std::max(0.0, margin - fuzz);
    // Double's distance, far from the limit, decides.
    const double ex = e1.x - e0.x, ey = e1.y - e0.y, l2 = ex * ex + ey * ey;
    const double u = l2 > 0 ? std::clamp(((v.x - e0.x) * ex + (v.y - e0.y) * ey) / l2, 0.0, 1.0) : 0.0;
    const double d = std::hypot(v.x - (e0.x + u * ex), v.y - (e0.y + u * ey));
    if (std::fabs(d - limit) > 1e-6 * (1 + std::fabs(v.x) + std::fabs(v.y) + std::fabs(e0.x) + std::fabs(e0.y)))
        return d > limit;
    const test_exact::Q d2 = test_exact::squared_distance(v, e0, e1);
    return d2 > test_exact::Q(limit) * test_exact::Q(limit) || (limit == 0 && d2 > 0);
}

/// Checks boundaries_near on one motion at `samples` times; returns
/// whether the motion had a start inside [0, 1).
bool check_motion(const polygon& a, const polygon& b, const pose& from, const pose& to, double margin, int samples,
                  const std::string& where) {
    const sweep::near_boundaries near = sweep::boundaries_near(a, b, from, to, margin, 1u << 30);
    INFO(where << " margin " << margin << " start " << near.start);
    REQUIRE(near.all);
    const double scale = coordinate_scale(a) + coordinate_scale(b) + std::fabs(from.tx) + std::fabs(from.ty) +
                         std::fabs(to.tx) + std::fabs(to.ty);
    const double fuzz = 1e-12 * scale;  // B posed in double at the sampled time
    std::vector<sweep::contact_site> all;
    for (std::uint32_t v = 0; v < b.size(); ++v)
        for (std::uint32_t e = 0; e < a.size(); ++e) all.push_back({true, v, e});
    for (std::uint32_t v = 0; v < a.size(); ++v)
        for (std::uint32_t e = 0; e < b.size(); ++e) all.push_back({false, v, e});
    const auto kept = [&](const sweep::contact_site& s) {
        return std::binary_search(near.pairs.begin(), near.pairs.end(), s, sweep::site_before);
    };
    for (int k = 0; k <= samples; ++k) {
        const double t = static_cast<double>(k) / samples;
        const pose p = motion_pose(from, to, t);
        for (const sweep::contact_site& s : all) {
            if ((t < near.start || !kept(s)) && !farther(a, b, s, p, margin, fuzz)) {
                FAIL_CHECK("pair " << s.moving_vertex << " " << s.vertex << " " << s.edge
                                   << " within the margin at t = " << t
                                   << (t < near.start ? " (before the start)" : " (left out)"));
                return false;
            }
        }
    }
    return near.start < 1;
}

}  // namespace

TEST_CASE("boundaries_near: no vertex near an edge before the start, none left out", "[sweep][turning]") {
    test_random::rng g(20261128);
    const int motions = test_effort::scaled(40);
    int started = 0, free = 0, total = 0;
    for (int m = 0; m < motions; ++m) {
        polygon a, b;
        if (m % 2 == 0) {
            const auto f = verification::all_families[static_cast<std::size_t>(m / 2) % 5];
            a = verification::make_family_polygon(f, 8 + g.index(9), 7 + static_cast<std::uint64_t>(m));
            b = verification::make_family_polygon(f, 8 + g.index(9), 11 + static_cast<std::uint64_t>(m));
        } else {
            a = test_scenes::random_multi(g, 6, 3).to_polygon();
            b = test_scenes::random_multi(g, 3, 2).to_polygon();
        }
        const double reach = 2 * (coordinate_scale(a) + coordinate_scale(b));
        const pose from{g.uniform(-reach, reach) / 2, g.uniform(-reach, reach) / 2, g.uniform(-4, 4)};
        const double turn = g.uniform(-2 * 3.14159, 2 * 3.14159);
        const pose to{from.tx + g.uniform(-reach, reach) / 2, from.ty + g.uniform(-reach, reach) / 2,
                      from.theta + turn};
        for (const double margin : {0.0, 1e-9, 0.01 * reach, 0.1 * reach}) {
            const bool inside = check_motion(a, b, from, to, margin, 96, "motion " + std::to_string(m));
            started += inside;
            ++total;
            free += sweep::boundaries_near(a, b, from, to, margin, 1u << 30).start > 1;
        }
    }
    WARN("boundaries_near: " << total << " motions and margins, " << started << " with a start in [0, 1), " << free
                             << " free throughout");
    CHECK(started > 0);
    CHECK(free > 0);
}

TEST_CASE("boundaries_near: an arc's bulge beyond its ends' box", "[sweep][turning]") {
    // B's vertex (R, 0) turns about B's origin through the angle 0, where it
    // reaches x = R; at the ends of the part (or of the coarse part) about
    // that angle it lies at x = R cos(theta / 2) only. A's edge at x = R (1 -
    // gap) lies between: only the arc's bulge over its chord shows the
    // vertex crossing it. Both at the middle of a sixteenth of a quarter turn
    // (the fine parts: gap 0.0006 < 1 - cos(pi / 64)) and of a quarter of it
    // (the coarse parts: gap 0.01 < 1 - cos(pi / 16), where the fine parts'
    // own bulge, summed but not scaled up, would not reach).
    const double r = 10, quarter = 1.5707963267948966;
    const polygon b({test_shapes::ring({{r, 0}, {r - 1, 0.2}, {r - 1, -0.2}})});
    for (const auto& [first_angle, gap] : {std::pair{-quarter / 32, 0.0006}, std::pair{-quarter / 8, 0.01}}) {
        const polygon a({test_shapes::ring({{r * (1 - gap), -1}, {r + 5, -1}, {r + 5, 1}, {r * (1 - gap), 1}})});
        const pose from{0, 0, first_angle}, to{0, 0, first_angle + quarter};
        INFO("first angle " << first_angle);
        check_motion(a, b, from, to, 1e-4 * r, 4096, "bulge");
        CHECK(sweep::boundaries_near(a, b, from, to, 1e-4 * r, 1u << 30).start < 0.05);
    }
}
