// SPDX-License-Identifier: BSL-1.0
// The nearest pair of two convex polygons proven from convex_gap's simplex
// (distance/convex_nearest.hpp), against CGAL's kernel over exact rationals
// (every vertex of each posed polygon against every edge of the other, the
// least squared distance and how many vertex-edge pairs reach it; nothing
// of the library but the posing convention) and against the exact
// separation query's features. Where the proof answers, the pair is the
// unique nearest one: the separation reports the same features, and the
// squared distance is CGAL's least; where the nearest pair is not unique
// (parallel edges, a vertex pair met by two edges), it declines.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "influence2d/core/pose.hpp"
#include "influence2d/distance/convex_nearest.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/motion/turning.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/double_word.hpp"
#include "influence2d/predicates/certain_nearest.hpp"
#include "influence2d/predicates/convexity.hpp"
#include "support/effort.hpp"
#include "support/exact_distance.hpp"
#include "support/random.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

namespace {

using test_exact::exact_point;
using test_exact::Q;

/// B's vertices posed by q exactly, by the library's convention: the cosine
/// and sine of q.theta in double, then exact products and sums.
std::vector<exact_point> posed(const polygon& b, const pose& q) {
    const Q c(std::cos(q.theta)), s(std::sin(q.theta));
    std::vector<exact_point> out;
    for (const point<double>& v : b.vertices())
        out.emplace_back(c * Q(v.x) - s * Q(v.y) + Q(q.tx), s * Q(v.x) + c * Q(v.y) + Q(q.ty));
    return out;
}

bool same_feature(const feature& f, const feature& g) { return f.kind == g.kind && f.index == g.index; }

std::vector<exact_point> standing(const polygon& a) {
    std::vector<exact_point> out;
    for (const point<double>& v : a.vertices()) out.push_back(test_exact::exact(v));
    return out;
}

/// The least squared distance between the vertices of each set and the
/// edges of the other (closed rings), and how many vertex-edge pairs reach
/// it (a unique nearest pair of a vertex and an edge's interior counts 1;
/// of two vertices, 4: each vertex with the other's two edges).
struct least {
    Q squared{-1};
    int pairs = 0;
};

least least_distance(const std::vector<exact_point>& p, const std::vector<exact_point>& q) {
    least out;
    const auto take = [&](const std::vector<exact_point>& x, const std::vector<exact_point>& y) {
        for (const exact_point& v : x)
            for (std::size_t i = 0; i < y.size(); ++i) {
                const Q d = test_exact::squared_distance(v, y[i], y[(i + 1) % y.size()]);
                if (out.squared < 0 || d < out.squared) {
                    out.squared = d;
                    out.pairs = 1;
                } else if (d == out.squared) {
                    ++out.pairs;
                }
            }
    };
    take(p, q);
    take(q, p);
    return out;
}

struct nearest_tally {
    std::size_t poses = 0, proven = 0, vertex_pairs = 0, declined_ties = 0, wrong_hints = 0, wrong_declined = 0;
};

/// A hint of one vertex pair (i, j), or of two sharing one of them.
convex_gap_result hint_of(std::size_t i0, std::size_t j0, std::size_t i1, std::size_t j1, bool two) {
    convex_gap_result h;
    h.points = two ? 2 : 1;
    h.simplex[0] = {static_cast<std::uint32_t>(i0), static_cast<std::uint32_t>(j0), {}};
    h.simplex[1] = {static_cast<std::uint32_t>(i1), static_cast<std::uint32_t>(j1), {}};
    return h;
}

/// Any candidate (a hint that is not convex_gap's): when the proof takes it,
/// it is the nearest pair CGAL finds, reached by that pair alone.
void check_candidate(const polygon& a, const polygon& b, const pose& q, const convex_gap_result& hint, const least& l,
                     nearest_tally& t) {
    ++t.wrong_hints;
    const std::optional<convex_nearest> e = nearest_convex_pair<exact_rational>(a, b, q, hint);
    if (!e) {
        ++t.wrong_declined;
        return;
    }
    CHECK(nearest_pair_squared<exact_rational>(a, b, q, *e) == l.squared);
    CHECK((l.pairs == 1 || l.pairs == 4));
}

void check(const polygon& a, const polygon& b, const pose& q, nearest_tally& t) {
    INFO("pose (" << q.tx << ", " << q.ty << ", " << q.theta << ")");
    ++t.poses;
    const rotation_pose placed(q);
    std::vector<point<double>> av(a.vertices().begin(), a.vertices().end()), bv;
    for (const point<double>& v : b.vertices()) bv.push_back(placed.apply<double>(v));
    const double scale = 64;
    const convex_gap_result hint = convex_gap(av.data(), av.size(), bv.data(), bv.size(), scale, 0x1p-44 * scale, {});
    const std::optional<convex_nearest> e = nearest_convex_pair<exact_rational>(a, b, q, hint);
    // The filtered type answers as the exact one, or not at all.
    try {
        const std::optional<convex_nearest> c = nearest_convex_pair<certified>(a, b, q, hint);
        REQUIRE(c.has_value() == e.has_value());
        if (c) {
            CHECK(same_feature(c->static_feature, e->static_feature));
            CHECK(same_feature(c->moving_feature, e->moving_feature));
        }
    } catch (const uncertain_sign&) {}
    const least l = least_distance(standing(a), posed(b, q));
    const bool unique = l.squared > 0 && (l.pairs == 1 || l.pairs == 4);
    // Every vertex pair, and every vertex against each edge at it, as a
    // candidate.
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) {
            check_candidate(a, b, q, hint_of(i, j, i, j, false), l, t);
            check_candidate(a, b, q, hint_of(i, j, a.next(i), j, true), l, t);
            check_candidate(a, b, q, hint_of(i, j, i, b.next(j), true), l, t);
        }
    if (!e) {
        t.declined_ties += l.squared > 0 && !unique;
        return;
    }
    ++t.proven;
    // Proven: the polygons apart, the nearest pair unique, its distance the
    // least, and the separation's features the same.
    REQUIRE(l.squared > 0);
    CHECK(unique);
    const Q squared = nearest_pair_squared<exact_rational>(a, b, q, *e);
    CHECK(squared == l.squared);
    if (e->static_feature.kind == feature_kind::vertex && e->moving_feature.kind == feature_kind::vertex) {
        ++t.vertex_pairs;
        CHECK(l.pairs == 4);
    } else {
        CHECK(l.pairs == 1);
    }
    const separation_result<exact_rational> s = separation<exact_rational>(a, b, q);
    CHECK(s.squared_distance == squared);
    CHECK(same_feature(s.static_feature, e->static_feature));
    CHECK(same_feature(s.moving_feature, e->moving_feature));
    // In double words: the same value, rounded as the exact one.
    double rounded;
    if (certain_nearest(nearest_pair_squared<double_word>(a, b, q, *e), rounded))
        CHECK(rounded == nearest_double(squared));
}

polygon convex_ring(test_random::rng& g, double size) {
    for (;;) {
        const polygon p({test_shapes::ring(
            test_shapes::ellipse_points(g, 3 + g.index(12), {0, 0}, size, size * g.uniform(0.2, 1)))});
        if (is_convex_polygon(p)) return p;
    }
}

}  // namespace

TEST_CASE("convex nearest pair: random convex pairs and poses against CGAL and the exact separation",
          "[convex_nearest]") {
    test_random::rng g(0x5eaULL);
    nearest_tally t;
    for (int scene = 0; scene < test_effort::scaled(60); ++scene) {
        const polygon a = convex_ring(g, g.uniform(1, 4)), b = convex_ring(g, g.uniform(0.5, 3));
        for (int k = 0; k < 20; ++k) {
            const double reach = g.uniform(3, 9), angle = g.uniform(0, 6.283185307179586);
            check(a, b, {reach * std::cos(angle), reach * std::sin(angle), g.uniform(-3, 3)}, t);
        }
    }
    WARN("convex nearest: " << t.poses << " poses, " << t.proven << " proven (" << t.vertex_pairs << " vertex pairs), "
                            << t.declined_ties << " ties declined; other candidates " << t.wrong_hints << ", "
                            << t.wrong_declined << " declined");
    CHECK(t.proven > t.poses / 2);
    CHECK(t.vertex_pairs > 0);
    CHECK(t.wrong_declined > t.wrong_hints / 2);
}

TEST_CASE("convex nearest pair: ties are declined, touching and meeting too", "[convex_nearest]") {
    nearest_tally t;
    const polygon square = test_shapes::square(-1, -1, 2);
    // Parallel edges one above the other: every point of a stretch is
    // nearest; shifted sideways, still a stretch; turned by a hair, one
    // vertex-edge pair.
    for (const double dx : {0.0, 0.75, 1.5}) {
        check(square, square, {dx, 3, 0}, t);
        CHECK(t.proven == 0);
    }
    check(square, square, {0.25, 3, 1e-9}, t);
    CHECK(t.proven == 1);
    // Corner against corner along the diagonal: a vertex pair, unique.
    check(square, square, {2.5, 2.5, 0.785398163397448}, t);
    // Touching along an edge, at a corner, and overlapping: nothing proven.
    const std::size_t before = t.proven;
    for (const pose q : {pose{2, 0, 0}, pose{2, 2, 0}, pose{1.5, 0.5, 0.3}}) check(square, square, q, t);
    CHECK(t.proven == before);
    CHECK(t.declined_ties >= 3);
}

TEST_CASE("certified convex probe: the exact distance, or a bound of it where the caller stops", "[convex_nearest]") {
    // Random convex pairs and poses, the caller stopping at distances up
    // to a threshold on either side of the exact distance (rounded as
    // distance_of rounds it): the probe's distance is that rounded
    // distance, or an upper bound of the exact one at which the caller
    // stops, as it does at the exact one; the features are the exact
    // separation's.
    test_random::rng g(0x5ebULL);
    std::size_t bounded = 0, exact = 0;
    for (int scene = 0; scene < test_effort::scaled(40); ++scene) {
        const polygon a = convex_ring(g, g.uniform(1, 4)), b = convex_ring(g, g.uniform(0.5, 3));
        for (int k = 0; k < 10; ++k) {
            const double reach = g.uniform(3, 9), angle = g.uniform(0, 6.283185307179586);
            const pose q{reach * std::cos(angle), reach * std::sin(angle), g.uniform(-3, 3)};
            INFO("pose (" << q.tx << ", " << q.ty << ", " << q.theta << ")");
            const separation_result<exact_rational> s = separation<exact_rational>(a, b, q);
            if (s.squared_distance == 0) continue;
            const double d = distance_of<exact_rational>(s.squared_distance);
            for (const double factor : {0.5, 1 - 1e-9, 1 - 0x1p-50, 1.0, 1 + 0x1p-50, 1 + 1e-9, 2.0}) {
                const double threshold = d * factor;
                const auto stops = [&](double x) { return x <= threshold; };
                const std::optional<sweep::probe_result> r =
                    sweep::certified_convex_probe<exact_rational>(a, b, q, 64, stops);
                if (!r) continue;
                CHECK(same_feature(r->static_feature, s.static_feature));
                CHECK(same_feature(r->moving_feature, s.moving_feature));
                if (r->distance == d) {
                    ++exact;
                    continue;
                }
                ++bounded;
                CHECK(Q(r->distance) * Q(r->distance) >= s.squared_distance);
                CHECK(stops(r->distance));
                CHECK(stops(d));
            }
        }
    }
    WARN("certified convex probe: " << exact << " exact distances, " << bounded << " bounds where the caller stops");
    CHECK(exact > 0);
    CHECK(bounded > 0);
}
