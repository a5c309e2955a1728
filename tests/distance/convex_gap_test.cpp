// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

#include <CGAL/convex_hull_2.h>

#include "influence2d/core/pose.hpp"
#include "influence2d/distance/convex_gap.hpp"
#include "support/effort.hpp"
#include "support/exact_distance.hpp"
#include "support/random.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

namespace {

using test_exact::exact_point;
using test_exact::Q;
using test_shapes::ellipse_points;

/// The exact convex hull of doubles, counter-clockwise (CGAL's, on exact
/// rationals).
std::vector<exact_point> hull(const std::vector<point<double>>& v) {
    std::vector<exact_point> in, out;
    for (const point<double>& p : v) in.push_back(test_exact::exact(p));
    CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(out), test_exact::kernel());
    return out;
}

/// Whether an edge of hull p has every point of q strictly outside its
/// line (exact).
bool separated_by_an_edge_of(const std::vector<exact_point>& p, const std::vector<exact_point>& q) {
    if (p.size() < 3) return false;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const exact_point &a = p[i], &b = p[(i + 1) % p.size()];
        bool all_right = true;
        for (const exact_point& x : q) all_right = all_right && CGAL::orientation(a, b, x) == CGAL::RIGHT_TURN;
        if (all_right) return true;
    }
    return false;
}

/// The exact squared distance between the convex hulls of two sets of
/// doubles: 0 when no edge of either separates them (they meet), else the
/// least squared distance from a hull vertex to an edge of the other hull
/// (CGAL's kernel; nothing of the library).
Q hull_squared_distance(const std::vector<point<double>>& a, const std::vector<point<double>>& b) {
    const std::vector<exact_point> ha = hull(a), hb = hull(b);
    if (!separated_by_an_edge_of(ha, hb) && !separated_by_an_edge_of(hb, ha)) return Q(0);
    Q best(-1);
    const auto take = [&](const std::vector<exact_point>& p, const std::vector<exact_point>& q) {
        for (const exact_point& x : p)
            for (std::size_t i = 0; i < q.size(); ++i) {
                const Q d = test_exact::squared_distance(x, q[i], q[(i + 1) % q.size()]);
                if (best < 0 || d < best) best = d;
            }
    };
    take(ha, hb);
    take(hb, ha);
    return best;
}

double coordinate_bound(const std::vector<point<double>>& v) {
    double s = 0;
    for (const point<double>& p : v) s = std::max({s, std::fabs(p.x), std::fabs(p.y)});
    return s;
}

/// The gap's bounds against the exact hull distance, and whether it
/// converged; both orders of the two sets.
struct gap_tally {
    std::size_t pairs = 0, apart = 0, converged = 0, near = 0;
};

void check_gap(const std::vector<point<double>>& a, const std::vector<point<double>>& b, gap_tally& t) {
    const Q d2 = hull_squared_distance(a, b);
    const double scale = coordinate_bound(a) + coordinate_bound(b);
    for (const bool swapped : {false, true}) {
        const std::vector<point<double>>&p = swapped ? b : a, &q = swapped ? a : b;
        const double tolerance = 0x1p-42 * scale;
        const convex_gap_result g = convex_gap(p.data(), p.size(), q.data(), q.size(), scale, tolerance, {});
        // Started from a simplex of another search (any vertex pairs): the
        // same guarantees.
        convex_gap_result seed;
        seed.points = 2;
        seed.simplex[0] = {static_cast<std::uint32_t>(p.size() - 1), 0, {}};
        seed.simplex[1] = {0, static_cast<std::uint32_t>(q.size() - 1), {}};
        const convex_gap_result h = convex_gap(p.data(), p.size(), q.data(), q.size(), scale, tolerance, seed);
        CHECK(test_exact::at_most_root(Q(h.lower), d2));
        CHECK(test_exact::at_least_root(Q(h.upper), d2));
        if (d2 > 0 && CGAL::to_double(d2) > 1e-20 * scale * scale) CHECK(h.converged);
        ++t.pairs;
        INFO("swapped " << swapped << ", lower " << g.lower << ", upper " << g.upper << ", exact "
                        << std::sqrt(CGAL::to_double(d2)));
        CHECK(test_exact::at_most_root(Q(g.lower), d2));
        CHECK(test_exact::at_least_root(Q(g.upper), d2));
        if (g.converged) {
            CHECK(g.upper - g.lower <= tolerance);
            ++t.converged;
        }
        if (d2 > 0) {
            ++t.apart;
            // Apart: the search converges (its bounds meet within the
            // tolerance) but where the simplex nearly holds the origin.
            if (CGAL::to_double(d2) > 1e-20 * scale * scale) CHECK(g.converged);
            // The axis points from p towards q: the lower bound is the gap
            // of their projections on it.
            const double n = std::hypot(g.axis.x, g.axis.y);
            double reach = -HUGE_VAL, least = HUGE_VAL;
            for (const point<double>& x : p) reach = std::max(reach, (g.axis.x * x.x + g.axis.y * x.y) / n);
            for (const point<double>& x : q) least = std::min(least, (g.axis.x * x.x + g.axis.y * x.y) / n);
            CHECK(g.lower <= least - reach + 0x1p-45 * scale);
        }
    }
}

/// The points of a and of b nearest each other, found in double over every
/// vertex of one against every edge of the other (for placing test cases).
std::pair<point<double>, point<double>> nearest_points(const std::vector<point<double>>& a,
                                                       const std::vector<point<double>>& b) {
    double best = HUGE_VAL;
    std::pair<point<double>, point<double>> out;
    const auto take = [&](const std::vector<point<double>>& p, const std::vector<point<double>>& q, bool swapped) {
        for (const point<double>& x : p)
            for (std::size_t i = 0; i < q.size(); ++i) {
                const point<double>&u = q[i], &v = q[(i + 1) % q.size()];
                const double dx = v.x - u.x, dy = v.y - u.y;
                double l = ((x.x - u.x) * dx + (x.y - u.y) * dy) / (dx * dx + dy * dy);
                l = std::clamp(l, 0.0, 1.0);
                const point<double> y{u.x + l * dx, u.y + l * dy};
                const double d = std::hypot(x.x - y.x, x.y - y.y);
                if (d < best) {
                    best = d;
                    out = swapped ? std::make_pair(y, x) : std::make_pair(x, y);
                }
            }
    };
    take(a, b, false);
    take(b, a, true);
    return out;
}

}  // namespace

TEST_CASE("convex gap: bounds of the hulls' distance against CGAL's exact one", "[distance][convex]") {
    test_random::rng r(0xc0a7ULL);
    gap_tally t;
    const int pairs = test_effort::scaled(400);
    for (int k = 0; k < pairs; ++k) {
        const double size = std::ldexp(1.0, static_cast<int>(r.uniform(-20, 20)));
        const std::size_t n = 3 + static_cast<std::size_t>(r.uniform(0, 14)),
                          m = 3 + static_cast<std::size_t>(r.uniform(0, 14));
        const std::vector<point<double>> a = ellipse_points(r, n, {0, 0}, size, size * r.uniform(0.05, 1));
        // B turned and moved by a random pose, some far off, some within a
        // hair of A (along a random direction from A's centre).
        const std::vector<point<double>> local =
            ellipse_points(r, m, {0, 0}, size * r.uniform(0.1, 2), size * r.uniform(0.02, 1));
        const double angle = r.uniform(0, 6.283185307179586), reach = size * r.uniform(0.5, 4);
        const rotation_pose place(pose{reach * std::cos(angle), reach * std::sin(angle), r.uniform(-4, 4)});
        std::vector<point<double>> b;
        for (const point<double>& p : local) b.push_back(place.apply<double>(p));
        check_gap(a, b, t);
        // B moved towards A along their nearest points' direction, to a
        // hair's distance relative to their size (the search's axis must
        // then be good to far better than the rounding of the large
        // coordinates over the short distance).
        if (hull_squared_distance(a, b) > 0) {
            const auto [pa, pb] = nearest_points(a, b);
            const double d = std::hypot(pb.x - pa.x, pb.y - pa.y);
            for (const double hair : {1e-3, 1e-6, 1e-9}) {
                const double move = d - hair * size;
                std::vector<point<double>> closer;
                for (const point<double>& p : b)
                    closer.push_back({p.x - move * (pb.x - pa.x) / d, p.y - move * (pb.y - pa.y) / d});
                check_gap(a, closer, t);
                t.near += hull_squared_distance(a, closer) > 0;
            }
        }
    }
    CHECK(t.near > t.pairs / 20);
    CHECK(t.apart > t.pairs / 4);
    CHECK(t.converged > t.pairs / 4);
}

TEST_CASE("convex gap: touching, a hair apart, parallel edges, far from the origin", "[distance][convex]") {
    gap_tally t;
    const std::vector<point<double>> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    for (const double gap : {0.0, 1e-300, 1e-12, 3e-9, 0.25}) {
        // Edge on edge (parallel), corner on edge, corner on corner.
        check_gap(square, {{5, 4 + gap}, {6, 4 + gap}, {6, 5}, {5, 5}}, t);
        check_gap(square, {{1, 4 + gap}, {3, 4 + gap}, {3, 6}, {1, 6}}, t);
        check_gap(square, {{2, 4 + gap}, {3, 5}, {2, 6}, {1, 5}}, t);
        check_gap(square, {{4 + gap, 4 + gap}, {5, 4.5}, {4.5, 5}}, t);
    }
    // Overlapping, and one inside the other.
    check_gap(square, {{3, 3}, {6, 3}, {6, 6}, {3, 6}}, t);
    check_gap(square, {{1, 1}, {2, 1}, {2, 2}}, t);
    // Far from the origin: the bounds scale with the coordinates.
    const double far = 1e6;
    check_gap({{far, far}, {far + 1, far}, {far + 1, far + 1}, {far, far + 1}},
              {{far + 1 + 1e-7, far}, {far + 2, far + 0.5}, {far + 1 + 1e-7, far + 1}}, t);
    CHECK(t.apart > 0);
}
