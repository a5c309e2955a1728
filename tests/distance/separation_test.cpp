// SPDX-License-Identifier: BSL-1.0
// The separation query (distance/separation.hpp) against an exact reference
// on CGAL's Cartesian kernel over exact rationals, sharing nothing with the
// library but the polygon's storage (support/exact_regions.hpp places the
// polygons and decides meeting): B posed exactly with the same doubles
// c = cos(theta), s = sin(theta); the squared distance between every segment
// of A and every segment of posed B (CGAL::squared_distance, a zero-length
// edge taken as its point), their least; whether the regions meet by
// CGAL::do_intersect on every pair and, for boundaries apart, a winding
// count (CGAL::orientation) of the first vertex of every ring in the other
// polygon. Rounding to double is checked against MPFR's. Checked on the catalogue, the families (random poses near
// contact, touching poses and their one-ulp neighbours, slides along an edge
// at a hair's gap, far poses), random multipolygons whose parts lie inside
// the other polygon, and rings nothing keeps apart:
//   - exact_rational: the squared distance equals the reference's, the meeting
//     too, and the features and points realise it (each point on its
//     feature, their squared distance the reported one; a meeting names a
//     common point, or a vertex in the other's interior only when the
//     boundaries are apart);
//   - certified_separation: the exact features, points rounded to nearest,
//     distance within one ulp of the exact one, most poses answered in double
//     words (no pair evaluated exactly) and few pairs evaluated exactly when
//     not; certified_separation_query the same answers over pose sequences;
//   - double within 2^-40 S of the exact distance (S: the largest coordinates
//     of A and B plus |tx| + |ty|; docs/separation.md), long double and quad
//     too, float within 2^-16 S;
//   - the prepared overload and separation_query answer exactly as the
//     one-shot query; roles swapped under a translation and both polygons
//     translated give the same exact distance.

#include <catch2/catch.hpp>

#include "support/catalogue.hpp"
#include "support/effort.hpp"
#include "support/exact_regions.hpp"
#include "support/families.hpp"
#include "support/neighbours.hpp"
#include "support/poses.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/squared_distance_2.h>

#include "influence2d/distance/separation.hpp"
#include "influence2d/exact/certified_separation.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/multiprecision.hpp"
#include "influence2d/query/intersects.hpp"

namespace {

using namespace influence2d;
using ER = exact_rational;

// ---------------------------------------------------------------------------
// The reference
// ---------------------------------------------------------------------------

using test_exact::FT;
using P = test_exact::point_2;
using S = test_exact::segment_2;
using test_exact::placed_shape;

/// The squared distance between A's edge i and B's edge j: CGAL's, a
/// zero-length edge taken as its point.
FT pair_squared(const placed_shape& a, std::size_t i, const placed_shape& b, std::size_t j) {
    const P &x = a.v[i], &y = a.end(i), &u = b.v[j], &v = b.end(j);
    const bool first_point = x == y, second_point = u == v;
    if (first_point && second_point) return CGAL::squared_distance(x, u);
    if (first_point) return CGAL::squared_distance(x, S(u, v));
    if (second_point) return CGAL::squared_distance(u, S(x, y));
    return CGAL::squared_distance(S(x, y), S(u, v));
}

struct reference_answer {
    ER squared;           ///< 0 when the regions meet, else the boundaries' distance
    ER boundary_squared;  ///< the least squared distance over every edge pair
    bool meet = false;
    bool boundary_meet = false;
    placed_shape a, b;  ///< A, and B posed exactly
};

/// The reference answer: every edge pair's squared distance, their least;
/// the regions' meeting (test_exact::regions_meet: every edge pair by
/// CGAL::do_intersect, then one vertex per ring by winding number).
reference_answer reference(const polygon& a, const polygon& b, const pose& q) {
    reference_answer r{0, 0, false, false, test_exact::place(a, 0, 0, 0), test_exact::place(b, q)};
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) {
            const FT d = pair_squared(r.a, i, r.b, j);
            if ((i == 0 && j == 0) || d < r.boundary_squared) r.boundary_squared = d;
            r.boundary_meet = r.boundary_meet || test_exact::edges_meet(r.a, i, r.b, j);
        }
    REQUIRE(r.boundary_meet == CGAL::is_zero(r.boundary_squared));  // two decisions agree
    r.meet = test_exact::regions_meet(r.a, r.b);
    r.squared = r.meet ? ER(0) : r.boundary_squared;
    return r;
}

// ---------------------------------------------------------------------------
// Features
// ---------------------------------------------------------------------------

P to_p(const point<ER>& p) { return P(p.x, p.y); }

/// The stored edge that runs along input edge k.
std::size_t stored_edge(const polygon& shape, std::size_t k) {
    for (std::size_t i = 0; i < shape.size(); ++i)
        if (shape.source_edge(i) == k) return i;
    FAIL("no stored edge for input edge " << k);
    return 0;
}

/// Whether x is on the feature of the placed polygon. A vertex k is the
/// point common to input edges k - 1 and k (its ring's previous input edge
/// and its own): an end of both.
bool on_feature(const placed_shape& p, const feature& f, const P& x) {
    const polygon& shape = *p.shape;
    if (f.kind == feature_kind::edge) return test_exact::on_edge(p, stored_edge(shape, f.index), x);
    if (f.kind != feature_kind::vertex) return false;
    std::size_t r = 0;
    while (shape.ring_end(r) <= f.index) ++r;
    const std::size_t before = f.index == shape.ring_begin(r) ? shape.ring_end(r) - 1 : f.index - 1;
    const std::size_t i = stored_edge(shape, f.index), h = stored_edge(shape, before);
    return (x == p.v[i] || x == p.end(i)) && (x == p.v[h] || x == p.end(h));
}

/// The exact result realises the reference's answer.
void check_exact(const separation_result<ER>& e, const reference_answer& ref) {
    CHECK(e.squared_distance == ref.squared);
    CHECK(e.meet() == ref.meet);
    const P sp = to_p(e.static_point), mp = to_p(e.moving_point);
    CHECK(CGAL::squared_distance(sp, mp) == e.squared_distance);
    if (e.static_feature.kind == feature_kind::interior) {
        // Containment without boundary contact: B's vertex inside A.
        CHECK_FALSE(ref.boundary_meet);
        CHECK(e.moving_feature.kind == feature_kind::vertex);
        CHECK(on_feature(ref.b, e.moving_feature, mp));
        CHECK(test_exact::in_region(ref.a, mp));
        CHECK(sp == mp);
    } else if (e.moving_feature.kind == feature_kind::interior) {
        CHECK_FALSE(ref.boundary_meet);
        CHECK(e.static_feature.kind == feature_kind::vertex);
        CHECK(on_feature(ref.a, e.static_feature, sp));
        CHECK(test_exact::in_region(ref.b, sp));
        CHECK(sp == mp);
    } else {
        // Boundary features: on A and on posed B, at the least boundary distance.
        CHECK(e.squared_distance == ref.boundary_squared);
        CHECK(on_feature(ref.a, e.static_feature, sp));
        CHECK(on_feature(ref.b, e.moving_feature, mp));
    }
}

/// Whether d is within one ulp of sqrt(x): nextafter(d, 0)^2 < x <
/// nextafter(d, inf)^2 (or d^2 == x).
bool faithful_root(double d, const ER& x) {
    if (CGAL::is_zero(x)) return d == 0;
    const ER lo(std::nextafter(d, 0.0)), hi(std::nextafter(d, HUGE_VAL)), at(d);
    return (lo * lo < x && x < hi * hi) || at * at == x;
}

double scene_scale(const polygon& a, const polygon& b, const pose& q) {
    return coordinate_scale(a) + coordinate_scale(b) + std::fabs(q.tx) + std::fabs(q.ty);
}

/// The frame, its pose in hexadecimal (exact, to replay it).
std::string describe_separation(const polygon& a, const polygon& b, const pose& p) {
    std::ostringstream s;
    s << "A of " << a.size() << " edges, B of " << b.size() << " posed by " << std::hexfloat << p.tx << " " << p.ty
      << " " << p.theta;
    return s.str();
}

/// How many frames met, how many certified_separation answered in double
/// words (no pair evaluated exactly), how many pairs it evaluated exactly.
struct separation_tally {
    std::size_t frames = 0, meet = 0, interior = 0, in_words = 0, exact_pairs = 0, most_exact_pairs = 0;
    void count(const reference_answer& ref, const separation_result<ER>& e, std::size_t pairs) {
        ++frames;
        meet += ref.meet;
        interior += e.static_feature.kind == feature_kind::interior || e.moving_feature.kind == feature_kind::interior;
        in_words += pairs == 0;
        exact_pairs += pairs;
        most_exact_pairs = std::max(most_exact_pairs, pairs);
    }
};

/// A floating NT's distance within `share` S of the exact one.
template <class NT>
void check_floating(const polygon& a, const polygon& b, const pose& q, const reference_answer& ref, double share) {
    const separation_result<NT> r = separation<NT>(a, b, q);
    const double exact = std::sqrt(CGAL::to_double(ref.squared));
    INFO(number_traits<NT>::name);
    CHECK(std::fabs(distance_of(r.squared_distance) - exact) <= share * scene_scale(a, b, q));
}

/// certified_separation's answer: the exact one's features, its values
/// rounded.
void check_certified(const certified_separation_result& c, const separation_result<ER>& e,
                     const reference_answer& ref) {
    CHECK(c.meet == ref.meet);
    CHECK(c.static_feature.kind == e.static_feature.kind);
    CHECK(c.static_feature.index == e.static_feature.index);
    CHECK(c.moving_feature.kind == e.moving_feature.kind);
    CHECK(c.moving_feature.index == e.moving_feature.index);
    CHECK(faithful_root(c.distance, ref.squared));
    CHECK(c.squared_distance == test_exact::nearest_double(ref.squared));
    CHECK(c.static_point.x == test_exact::nearest_double(e.static_point.x));
    CHECK(c.static_point.y == test_exact::nearest_double(e.static_point.y));
    CHECK(c.moving_point.x == test_exact::nearest_double(e.moving_point.x));
    CHECK(c.moving_point.y == test_exact::nearest_double(e.moving_point.y));
}

/// Two certified answers are the same, field by field.
void check_same_separation(const certified_separation_result& c, const certified_separation_result& d) {
    CHECK(c.meet == d.meet);
    CHECK(c.static_feature.kind == d.static_feature.kind);
    CHECK(c.static_feature.index == d.static_feature.index);
    CHECK(c.moving_feature.kind == d.moving_feature.kind);
    CHECK(c.moving_feature.index == d.moving_feature.index);
    CHECK(c.distance == d.distance);
    CHECK(c.squared_distance == d.squared_distance);
    CHECK(c.static_point == d.static_point);
    CHECK(c.moving_point == d.moving_point);
}

/// Which floating types check_frame runs besides the exact modes.
enum class floating { none, double_only, all };

/// Every mode on one frame: exact_rational, certified_separation, and the
/// floating types asked.
void check_separation_frame(const polygon& a, const polygon& b, const pose& q, separation_tally& t,
                            floating types = floating::double_only) {
    INFO(describe_separation(a, b, q));
    const reference_answer ref = reference(a, b, q);
    const separation_result<ER> e = separation<ER>(a, b, q);
    check_exact(e, ref);
    const certified_separation_result c = certified_separation(a, b, q);
    check_certified(c, e, ref);
    if (types != floating::none) check_floating<double>(a, b, q, ref, 0x1p-40);
    if (types == floating::all) {
        // 8192 u in the type's own unit (motion/turning.hpp, separation_error).
        check_floating<long double>(a, b, q, ref, std::ldexp(1.0, 13 - std::numeric_limits<long double>::digits));
        check_floating<quad>(a, b, q, ref, 0x1p-100);
        check_floating<float>(a, b, q, ref, 0x1p-16);
    }
    t.count(ref, e, c.exact_pairs);
}

/// The families' polygons used here: (family, n) for A and B.
struct cell {
    verification::family fa;
    std::size_t n;
    verification::family fb;
    std::size_t m;
};

const cell family_cells[] = {
    {verification::family::convex, 8, verification::family::starred, 8},
    {verification::family::irregular, 64, verification::family::contour, 16},
    {verification::family::with_hole, 16, verification::family::irregular, 64},
    {verification::family::contour, 64, verification::family::with_hole, 32},
    {verification::family::starred, 256, verification::family::convex, 8},
    {verification::family::with_hole, 1024, verification::family::irregular, 8},
};

}  // namespace

TEST_CASE("separation: small cases by hand", "[separation]") {
    const polygon square({ring_input{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
    const polygon unit({ring_input{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, ring_role::outer}});
    const auto sd = [](const polygon& a, const polygon& b, pose q) { return separation<ER>(a, b, q); };

    SECTION("apart along x: edge against edge, the least pair of those at the distance") {
        const separation_result<ER> r = sd(square, unit, pose{6, 1, 0});
        CHECK(r.squared_distance == ER(4));
        CHECK_FALSE(r.meet());
        // A's right edge (1) is at distance 2 from B's edges 0, 2 and 3 (B's
        // left side and its ends): the least stored pair (1, 0) names A's
        // edge and B's vertex 0, at (6, 1).
        CHECK(r.static_feature.kind == feature_kind::edge);
        CHECK(r.static_feature.index == 1);
        CHECK(r.moving_feature.kind == feature_kind::vertex);
        CHECK(r.moving_feature.index == 0);
        CHECK(r.static_point.x == ER(4));
        CHECK(r.static_point.y == ER(1));
        CHECK(r.moving_point.x == ER(6));
        CHECK(r.moving_point.y == ER(1));
        CHECK(distance_of(r.squared_distance) == 2);
    }
    SECTION("vertex against vertex, diagonally") {
        const separation_result<ER> r = sd(square, unit, pose{5, 5, 0});
        CHECK(r.squared_distance == ER(2));
        CHECK(r.static_feature.kind == feature_kind::vertex);
        CHECK(r.static_feature.index == 2);
        CHECK(r.moving_feature.kind == feature_kind::vertex);
        CHECK(r.moving_feature.index == 0);
        CHECK(distance_of(r.squared_distance) == std::sqrt(2.0));
    }
    SECTION("touching at a corner, crossing, containment both ways") {
        const separation_result<ER> touch = sd(square, unit, pose{4, 4, 0});
        CHECK(touch.meet());
        CHECK(touch.static_feature.kind == feature_kind::vertex);
        CHECK(touch.static_point.x == ER(4));
        CHECK(touch.moving_point.y == ER(4));
        const separation_result<ER> cross = sd(square, unit, pose{3.5, 3.5, 0});
        CHECK(cross.meet());
        CHECK(cross.static_feature.kind != feature_kind::interior);
        const separation_result<ER> inside = sd(square, unit, pose{1.5, 1.5, 0.25});
        CHECK(inside.meet());
        CHECK(inside.static_feature.kind == feature_kind::interior);
        CHECK(inside.moving_feature.kind == feature_kind::vertex);
        CHECK(inside.moving_feature.index == 0);
        const separation_result<ER> around = sd(unit, square, pose{-1.5, -1.5, 0});
        CHECK(around.meet());
        CHECK(around.moving_feature.kind == feature_kind::interior);
        CHECK(around.static_feature.kind == feature_kind::vertex);
        CHECK(around.static_point.x == ER(0));
    }
    SECTION("inside a hole: the distance to the hole's boundary") {
        const polygon holed({ring_input{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, ring_role::outer},
                             ring_input{{{2, 2}, {8, 2}, {8, 8}, {2, 8}}, ring_role::hole}});
        const separation_result<ER> r = sd(holed, unit, pose{4, 3, 0});
        CHECK_FALSE(r.meet());
        CHECK(r.squared_distance == ER(1));
        CHECK(r.static_feature.kind == feature_kind::edge);
        CHECK(r.static_feature.index >= 4);  // an edge of the hole (input edges 4 to 7)
        CHECK(certified_separation(holed, unit, pose{4, 3, 0}).distance == 1);
        CHECK(separation<double>(holed, unit, pose{4, 3, 0}).squared_distance == 1);
    }
    SECTION("a repeated vertex: a zero-length edge keeps the numbering") {
        const polygon repeated({ring_input{{{0, 0}, {4, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
        const separation_result<ER> r = sd(repeated, unit, pose{5, -2, 0});
        CHECK(r.squared_distance == ER(2));
        CHECK(r.static_feature.kind == feature_kind::vertex);
        CHECK((r.static_feature.index == 1 || r.static_feature.index == 2));
        const separation_result<ER> s = sd(repeated, unit, pose{5, 1, 0});
        CHECK(s.squared_distance == ER(1));
        CHECK(s.static_feature.kind == feature_kind::edge);
        CHECK(s.static_feature.index == 2);  // from vertex 2 (4, 0) to vertex 3 (4, 4)
    }
    SECTION("a ring given clockwise: input numbering of vertices and edges") {
        const polygon cw({ring_input{{{0, 0}, {0, 4}, {4, 4}, {4, 0}}, ring_role::outer}});
        const separation_result<ER> r = sd(cw, unit, pose{5, 5, 0});
        CHECK(r.static_feature.kind == feature_kind::vertex);
        CHECK(r.static_feature.index == 2);  // (4, 4) is input vertex 2
        const separation_result<ER> s = sd(cw, unit, pose{6, 1, 0});
        CHECK(s.static_feature.kind == feature_kind::edge);
        CHECK(s.static_feature.index == 2);  // from (4, 4) to (4, 0)
    }
    SECTION("distance_of: perfect squares exactly, others within one ulp, any magnitude") {
        CHECK(distance_of(ER(9)) == 3);
        CHECK(distance_of(ER(0)) == 0);
        const ER two(2);
        CHECK(faithful_root(distance_of(two), two));
        const ER third = ER(1) / ER(3);
        CHECK(faithful_root(distance_of(third), third));
        const ER tiny = ER(std::ldexp(1.0, -1000)) * ER(std::ldexp(3.0, -100));  // 3 * 2^-1100: below double
        CHECK(faithful_root(distance_of(tiny), tiny));
        const ER huge = ER(std::ldexp(1.0, 1000)) * ER(std::ldexp(5.0, 600));  // beyond double
        CHECK(faithful_root(distance_of(huge), huge));
        CHECK(nearest_double(third) == 1.0 / 3);
        CHECK(nearest_double(ER(ER(-1) / ER(3))) == -1.0 / 3);
        CHECK(distance_of(4.0) == 2);
    }
    SECTION("bad input is refused, naming the value") {
        CHECK_THROWS_AS(separation<double>(square, polygon{}, pose{}), invalid_input);
        CHECK_THROWS_AS(separation<ER>(polygon{}, square, pose{}), invalid_input);
        CHECK_THROWS_AS(certified_separation(square, polygon{}, pose{}), invalid_input);
        CHECK_THROWS_WITH(separation<double>(square, unit, pose{std::nan(""), 0, 0}), Catch::Contains("tx is NaN"));
        CHECK_THROWS_WITH(certified_separation(square, unit, pose{0, HUGE_VAL, 0}), Catch::Contains("ty is +infinity"));
        separation_query<double> query(square, unit);
        CHECK_THROWS_WITH(query(pose{0, 0, -HUGE_VAL}), Catch::Contains("theta is -infinity"));
        CHECK_THROWS_AS(separation_query<double>(nullptr, prepare_moving<double>(unit)), invalid_input);
        const polygon far({ring_input{{{0, 0}, {1e300, 0}, {0, 1e300}}, ring_role::outer}});
        CHECK_THROWS_AS(separation<float>(far, unit, pose{}), invalid_input);
    }
}

TEST_CASE("separation: closest points of two segments on a small grid, degenerate ones included",
          "[separation][reference]") {
    // Ends on a 5 x 5 grid: many collinear, touching, overlapping and
    // zero-length segments. The plain and the filtered evaluation against
    // CGAL: the squared distance, each point on its segment at its part, the
    // points' squared distance; both evaluations give the same answer.
    test_random::rng g(0x5e9d);
    const auto grid_point = [&] {
        return point<double>{static_cast<double>(g.index(5)), static_cast<double>(g.index(5))};
    };
    const auto exact = [](const point<double>& p) { return point<ER>{ER(p.x), ER(p.y)}; };
    const auto on_part = [](const P& x, const P& a, const P& b, segment_part part) {
        if (part == segment_part::start) return x == a;
        if (part == segment_part::end) return x == b && !(a == b);
        return x != a && x != b && S(a, b).has_on(x);
    };
    std::size_t meet = 0;
    for (int k = 0; k < 4000; ++k) {
        const point<double> a = grid_point(), b = grid_point(), u = grid_point(), v = grid_point();
        INFO(a.x << ',' << a.y << ' ' << b.x << ',' << b.y << " / " << u.x << ',' << u.y << ' ' << v.x << ',' << v.y);
        const P pa(a.x, a.y), pb(b.x, b.y), pu(u.x, u.y), pv(v.x, v.y);
        const FT expected =
            pa == pb
                ? (pu == pv ? CGAL::squared_distance(pa, pu) : CGAL::squared_distance(pa, S(pu, pv)))
                : (pu == pv ? CGAL::squared_distance(pu, S(pa, pb)) : CGAL::squared_distance(S(pa, pb), S(pu, pv)));
        const segment_pair_closest<ER> plain = closest_between_segments(exact(a), exact(b), exact(u), exact(v));
        const segment_pair_closest<ER> filtered =
            closest_between_segments(a, b, u, v, 0.0, exact(a), exact(b), exact(u), exact(v));
        for (const segment_pair_closest<ER>* r : {&plain, &filtered}) {
            CHECK(r->squared == expected);
            CHECK(on_part(to_p(r->on_first), pa, pb, r->first_part));
            CHECK(on_part(to_p(r->on_second), pu, pv, r->second_part));
            CHECK(CGAL::squared_distance(to_p(r->on_first), to_p(r->on_second)) == r->squared);
        }
        CHECK(filtered.on_first == plain.on_first);
        CHECK(filtered.on_second == plain.on_second);
        meet += CGAL::is_zero(expected);
    }
    CHECK(meet > 400);
    CHECK(meet < 3600);
}

/// The closest points the tie rule names, from CGAL's numbers alone: the
/// least squared distance over every edge pair, ties to the least (A's
/// stored edge, B's stored edge); within that pair the first of its four end
/// candidates (A's start, A's end, B's start, B's end, each to the other
/// segment) at the least distance, the other point the end's nearest point
/// of the other segment. For boundaries apart.
std::pair<P, P> tie_rule_points(const placed_shape& a, const placed_shape& b) {
    const auto nearest_on = [](const P& p, const P& x, const P& y) {
        if (x == y) return x;
        const FT t = (p - x) * (y - x), l = (y - x) * (y - x);
        if (t <= 0) return x;
        if (t >= l) return y;
        return x + (y - x) * (t / l);
    };
    FT best = -1;
    std::pair<P, P> points;
    for (std::size_t i = 0; i < a.v.size(); ++i)
        for (std::size_t j = 0; j < b.v.size(); ++j) {
            const P &x = a.v[i], &y = a.end(i), &u = b.v[j], &v = b.end(j);
            const std::pair<P, P> ends[4] = {
                {x, nearest_on(x, u, v)}, {y, nearest_on(y, u, v)}, {nearest_on(u, x, y), u}, {nearest_on(v, x, y), v}};
            for (const auto& e : ends) {
                const FT d = CGAL::squared_distance(e.first, e.second);
                if (best < 0 || d < best) {
                    best = d;
                    points = e;
                }
            }
        }
    return points;
}

TEST_CASE("separation: exact ties between feature pairs go to the least edge pair, its first end candidate",
          "[separation][reference]") {
    // Axis-aligned and dyadic shapes and translations: parallel edges,
    // vertices level with vertices, every distance tied several ways.
    const std::vector<polygon> shapes = {
        test_shapes::square(0, 0, 2), test_shapes::c_shape(),
        polygon({test_shapes::ring({{0, 0}, {3, 0}, {1.5, 1.5}})}),
        polygon({test_shapes::ring({{0, 0}, {1, -1}, {2, 0}, {2, 2}, {1, 3}, {0, 2}})})};
    std::size_t apart = 0, ties = 0;
    for (const polygon& a : shapes)
        for (const polygon& b : shapes)
            for (int gx = -32; gx <= 32; gx += 3)
                for (int gy = -32; gy <= 32; gy += 5) {
                    const pose q{gx / 4.0, gy / 4.0, 0};
                    const reference_answer ref = reference(a, b, q);
                    if (ref.meet) continue;
                    ++apart;
                    const std::pair<P, P> expected = tie_rule_points(ref.a, ref.b);
                    const separation_result<ER> x = separation<ER>(a, b, q);
                    INFO("pose " << q.tx << ", " << q.ty);
                    REQUIRE(x.squared_distance == ref.squared);
                    CHECK(to_p(x.static_point) == expected.first);
                    CHECK(to_p(x.moving_point) == expected.second);
                    const certified_separation_result c = certified_separation(a, b, q);
                    CHECK((c.static_feature.kind == x.static_feature.kind &&
                           c.static_feature.index == x.static_feature.index));
                    CHECK((c.moving_feature.kind == x.moving_feature.kind &&
                           c.moving_feature.index == x.moving_feature.index));
                    CHECK(P(c.static_point.x, c.static_point.y) == expected.first);
                    CHECK(P(c.moving_point.x, c.moving_point.y) == expected.second);
                    // Ties: more than one edge pair at the least distance.
                    std::size_t at_least = 0;
                    for (std::size_t i = 0; i < a.size(); ++i)
                        for (std::size_t j = 0; j < b.size(); ++j)
                            at_least += pair_squared(ref.a, i, ref.b, j) == ref.boundary_squared;
                    ties += at_least > 1;
                }
    INFO("poses apart " << apart << ", with tied edge pairs " << ties);
    CHECK(apart > 1000);
    CHECK(ties > apart / 2);
}

TEST_CASE("separation: the catalogue against the exact reference", "[separation][reference]") {
    separation_tally t;
    for (const test_catalogue::test_case& c : test_catalogue::cases()) {
        INFO(c.name);
        for (const test_catalogue::frame& f : c.frames)
            check_separation_frame(c.fixed, c.moving, f.where, t, floating::all);
    }
    CHECK(t.meet > 0);
    CHECK(t.meet < t.frames);
    CHECK(t.interior > 0);
    INFO("certified: " << t.exact_pairs << " pairs evaluated exactly over " << t.frames << " frames");
    CHECK(t.exact_pairs <= 8 * t.frames);
}

TEST_CASE("separation: the families under random, touching, grazing, sliding and far poses",
          "[separation][reference]") {
    separation_tally t;
    test_random::rng g(0x5e9a);
    for (const cell& k : family_cells) {
        const polygon& a = test_families::load(k.fa, k.n);
        const polygon& b = test_families::load(k.fb, k.m);
        const std::size_t frames = static_cast<std::size_t>(test_effort::scaled(30));
        for (double inner : {0.4, 0.9})
            for (const pose& q : test_poses::near_contact(a, b, frames, inner, 0, k.n * 7 + k.m))
                check_separation_frame(a, b, q, t);
        // Touching (exact on the families' grid) and one ulp away: grazes.
        for (const pose& q : test_poses::touching(a, b, g, static_cast<std::size_t>(test_effort::scaled(6))))
            check_separation_frame(a, b, q, t);
        // Far: beyond both bounding circles.
        for (const pose& q : random_poses(a, b, 2, 2.5 * test_poses::reach(a, b), 4 * test_poses::reach(a, b), k.m))
            check_separation_frame(a, b, q, t);
        // A slide: B's extreme vertex along an edge of A, 2^-30 off it.
        const std::size_t i = g.index(a.size());
        const point<double> v0 = a.vertex(i), v1 = a.vertex(a.next(i));
        const double len = std::hypot(v1.x - v0.x, v1.y - v0.y);
        if (len == 0) continue;
        const point<double> dir{(v1.x - v0.x) / len, (v1.y - v0.y) / len}, out{dir.y, -dir.x};
        std::size_t lead = 0;
        for (std::size_t j = 1; j < b.size(); ++j)
            if (b.vertex(j).x * out.x + b.vertex(j).y * out.y < b.vertex(lead).x * out.x + b.vertex(lead).y * out.y)
                lead = j;
        for (int s = 0; s <= 4; ++s) {
            const double along = len * s / 4, gap = 0x1p-30;
            const pose q{v0.x + dir.x * along + out.x * gap - b.vertex(lead).x,
                         v0.y + dir.y * along + out.y * gap - b.vertex(lead).y, 0};
            check_separation_frame(a, b, q, t);
        }
    }
    CHECK(t.meet > t.frames / 5);
    CHECK(t.meet < t.frames);
    INFO("certified: " << t.in_words << " of " << t.frames << " frames in double words; " << t.exact_pairs
                       << " pairs evaluated exactly, at most " << t.most_exact_pairs);
    CHECK(t.exact_pairs <= 8 * t.frames);
    // Touching poses and slides at 2^-30 need the exact route; random ones
    // do not.
    CHECK(t.in_words * 10 > t.frames * 6);
}

TEST_CASE("separation: random multipolygons with parts inside the other, and rings nothing keeps apart",
          "[separation][reference]") {
    using test_scenes::rng;
    separation_tally t;
    const int scenes = test_effort::scaled(30);
    for (int k = 0; k < scenes; ++k) {
        rng g(0x5e9b + static_cast<std::uint64_t>(k));
        test_scenes::multi ma = test_scenes::random_multi(g, 30, 8), mb = test_scenes::random_swallower(g);
        if (k % 2 == 1) std::swap(ma, mb);
        const polygon a = ma.to_polygon(), b = mb.to_polygon();
        const polygon messy_a(test_scenes::random_messy(g, 10)), messy_b(test_scenes::random_messy(g, 10));
        for (int f = 0; f < 6; ++f) {
            // B's part about A's part (one inside the other, or around it),
            // a vertex of B's part on a vertex of A's part (touching at
            // theta = 0), or B's part just beyond the reach of A's (near
            // contact, often apart).
            const test_scenes::part& pa = ma.parts[g.index(ma.parts.size())];
            const test_scenes::part& pb = mb.parts[g.index(mb.parts.size())];
            const double theta = f % 2 == 0 ? 0 : g.uniform(-3.2, 3.2);
            const point<double> va = pa.outer[g.index(pa.outer.size())], vb = pb.outer[g.index(pb.outer.size())];
            const double spin = g.uniform(0, 6.283185307179586);
            const double off = f % 3 == 0 ? 0.3 * pa.radius * g.unit() : (pa.radius + pb.radius) * g.uniform(0.9, 1.3);
            const point<double> near{pa.center.x + off * std::cos(spin), pa.center.y + off * std::sin(spin)};
            const pose q = f % 3 == 1 ? test_scenes::aimed(vb, va, theta) : test_scenes::aimed(pb.center, near, theta);
            check_separation_frame(a, b, q, t);
            const point<double> wa = messy_a.vertex(g.index(messy_a.size())),
                                wb = messy_b.vertex(g.index(messy_b.size()));
            const double far = g.uniform(0, 16);
            check_separation_frame(
                messy_a, messy_b,
                test_scenes::aimed(wb, {wa.x + far * std::cos(spin), wa.y + far * std::sin(spin)}, theta), t);
        }
    }
    CHECK(t.meet > t.frames / 5);
    CHECK(t.meet < t.frames);
    CHECK(t.interior > 0);
}

TEST_CASE("separation: far from 1 in scale, the exact modes stay exact", "[separation][reference]") {
    separation_tally t;
    const polygon& a0 = test_families::load(verification::family::contour, 32);
    const polygon& b0 = test_families::load(verification::family::starred, 16);
    for (int e : {-600, -40, 40, 600}) {
        const polygon a = test_shapes::scaled(a0, e), b = test_shapes::scaled(b0, e);
        test_random::rng g(static_cast<std::uint64_t>(e + 1000));
        std::vector<pose> poses =
            test_poses::near_contact(a0, b0, static_cast<std::size_t>(test_effort::scaled(20)), 0.9, 0, 17);
        for (const pose& q : test_poses::touching(a0, b0, g, 2)) poses.push_back(q);
        for (pose q : poses) {
            q.tx = std::ldexp(q.tx, e);
            q.ty = std::ldexp(q.ty, e);
            // In double the squares of distances near 2^600 overflow and near
            // 2^-600 underflow: the exact modes only there.
            check_separation_frame(a, b, q, t, std::abs(e) < 500 ? floating::double_only : floating::none);
        }
    }
    CHECK(t.meet > 0);
    CHECK(t.meet < t.frames);
}

TEST_CASE("separation: prepared polygons and separation_query answer as the one-shot query", "[separation]") {
    const polygon& a = test_families::load(verification::family::contour, 64);
    const polygon& b = test_families::load(verification::family::starred, 16);
    const auto A = prepare_static<ER>(a);
    const auto B = prepare_moving<ER>(b);
    separation_query<ER> query(A, B);
    separation_query<double> fast(a, b);
    // An approach (apart, near contact, overlapping) and random jumps.
    std::vector<pose> poses = test_poses::approach(a, b, static_cast<std::size_t>(test_effort::scaled(60)),
                                                   test_poses::approach_path{0.3, 0.5, 0.1, 1.0});
    for (const pose& q : test_poses::near_contact(a, b, static_cast<std::size_t>(test_effort::scaled(40)), 0.4, 0, 3))
        poses.push_back(q);
    std::size_t meet = 0;
    for (const pose& q : poses) {
        INFO(describe_separation(a, b, q));
        const separation_result<ER> once = separation<ER>(a, b, q), prepared = separation<ER>(*A, *B, q),
                                    seeded = query(q);
        for (const separation_result<ER>* r : {&prepared, &seeded}) {
            CHECK(r->squared_distance == once.squared_distance);
            CHECK(r->static_feature.kind == once.static_feature.kind);
            CHECK(r->static_feature.index == once.static_feature.index);
            CHECK(r->moving_feature.kind == once.moving_feature.kind);
            CHECK(r->moving_feature.index == once.moving_feature.index);
            CHECK(r->static_point == once.static_point);
            CHECK(r->moving_point == once.moving_point);
        }
        const separation_result<double> d = fast(q);
        CHECK(std::fabs(distance_of(d.squared_distance) - distance_of(once.squared_distance)) <=
              0x1p-40 * scene_scale(a, b, q));
        meet += once.meet();
    }
    CHECK(meet > 0);
    CHECK(meet < poses.size());
}

TEST_CASE("separation: swapped roles and translated scenes give the same exact distance", "[separation]") {
    using test_scenes::rng;
    for (int k = 0; k < test_effort::scaled(20); ++k) {
        rng g(0x5e9c + static_cast<std::uint64_t>(k));
        const polygon a = test_scenes::random_multi(g, 12, 5).to_polygon();
        const polygon b = test_scenes::random_multi(g, 6, 3).to_polygon();
        for (int f = 0; f < 6; ++f) {
            // Translations on the scenes' grid: every posed coordinate exact.
            const double tx = test_scenes::snap(g.uniform(-20, 20)), ty = test_scenes::snap(g.uniform(-20, 20));
            INFO(describe_separation(a, b, pose{tx, ty, 0}));
            const separation_result<ER> ab = separation<ER>(a, b, pose{tx, ty, 0});
            const separation_result<ER> ba = separation<ER>(b, a, pose{-tx, -ty, 0});
            CHECK(ab.squared_distance == ba.squared_distance);
            CHECK(ab.meet() == ba.meet());
            // Both moved by v: A's vertices and the pose's translation.
            const double vx = test_scenes::snap(g.uniform(-50, 50)), vy = test_scenes::snap(g.uniform(-50, 50));
            std::vector<ring_input> moved;
            for (std::size_t r = 0; r < a.ring_count(); ++r) {
                ring_input in{{}, a.role(r)};
                for (std::size_t i = a.ring_begin(r); i < a.ring_end(r); ++i)
                    in.vertices.push_back({a.vertex(i).x + vx, a.vertex(i).y + vy});
                moved.push_back(in);
            }
            const double theta = g.chance(0.5) ? 0 : g.uniform(-3.2, 3.2);
            const pose q{tx, ty, theta}, qv{tx + vx, ty + vy, theta};
            CHECK(separation<ER>(a, b, q).squared_distance == separation<ER>(polygon(moved), b, qv).squared_distance);
        }
    }
}

TEST_CASE("separation: certified_separation_query answers as certified_separation over pose sequences",
          "[separation][reference]") {
    const auto run = [](const polygon& a, const polygon& b, const std::vector<pose>& poses, std::size_t& in_words) {
        certified_separation_query query(a, b);
        for (const pose& q : poses) {
            INFO(describe_separation(a, b, q));
            const certified_separation_result c = query(q);
            check_same_separation(c, certified_separation(a, b, q));
            in_words += c.exact_pairs == 0;
        }
    };
    std::size_t frames = 0, in_words = 0;
    for (const cell& k : family_cells) {
        const polygon& a = test_families::load(k.fa, k.n);
        const polygon& b = test_families::load(k.fb, k.m);
        // An approach (apart, near contact, overlapping), random jumps, and
        // touching poses with their one-ulp neighbours.
        std::vector<pose> poses = test_poses::approach(a, b, static_cast<std::size_t>(test_effort::scaled(20)),
                                                       test_poses::approach_path{0.3, 0.5, 0.1, 1.0});
        for (const pose& q :
             test_poses::near_contact(a, b, static_cast<std::size_t>(test_effort::scaled(20)), 0.4, 0, k.m))
            poses.push_back(q);
        test_random::rng g(k.n * 31 + k.m);
        for (const pose& q : test_poses::touching(a, b, g, 4)) poses.push_back(q);
        // The roles swapped, B static.
        run(a, b, poses, in_words);
        run(b, a, poses, in_words);
        frames += 2 * poses.size();
        // The exact reference on a few of them.
        separation_tally t;
        for (std::size_t i = 0; i < poses.size(); i += 7) check_separation_frame(a, b, poses[i], t, floating::none);
    }
    INFO(in_words << " of " << frames << " frames in double words");
    CHECK(in_words * 10 > frames * 6);
    CHECK(in_words < frames);
}

TEST_CASE(
    "separation: a closest vertex of B posed exactly halfway between two doubles is rounded without the "
    "exact query",
    "[separation][reference]") {
    // Poses of the time study's random annulus (seed 20040202) at which B's
    // closest feature is its vertex 0, (50, 0): its posed coordinates
    // c 50 + tx and s 50 + ty have a few bits more than a double, and one of
    // them lies exactly halfway between two doubles, which no bound of a
    // double word settles.
    struct halfway_case {
        verification::family fa;
        std::size_t n;
        verification::family fb;
        std::size_t m;
        pose q;
    };
    using verification::family;
    const halfway_case cases[] = {
        {family::convex, 8, family::convex, 8, {-75.682783025328149, -63.546403024480291, 0.69650661204877395}},
        {family::convex, 8, family::convex, 8, {40.550918511716688, 88.559525136646101, 4.3136131908219815}},
        {family::contour, 1024, family::contour, 8, {47.443710335022757, -104.77772572452697, 2.6757361172791891}},
        {family::contour, 1024, family::contour, 8, {-18.39952354201677, -92.3377329198795, 1.0484779024862194}},
        {family::starred, 256, family::starred, 256, {26.313732481525488, -96.662980968492846, 1.970558100051313}},
        {family::irregular,
         1024,
         family::irregular,
         1024,
         {-100.76338594592535, -28.625049736455882, 0.027593917517312373}},
    };
    // Whether x lies exactly halfway between the double nearest to it and
    // that double's neighbour on x's side.
    const auto halfway = [](const ER& x) {
        const double d = test_exact::nearest_double(x);
        const double beyond = std::nextafter(d, x > ER(d) ? HUGE_VAL : -HUGE_VAL);
        return x != ER(d) && (x - ER(d)) * 2 == ER(beyond) - ER(d);
    };
    for (const halfway_case& k : cases) {
        const polygon& a = test_families::load(k.fa, k.n);
        const polygon& b = test_families::load(k.fb, k.m);
        INFO(describe_separation(a, b, k.q));
        const separation_result<ER> e = separation<ER>(a, b, k.q);
        REQUIRE(e.moving_feature.kind == feature_kind::vertex);
        CHECK(e.moving_feature.index == 0);
        CHECK((halfway(e.moving_point.x) || halfway(e.moving_point.y)));
        const certified_separation_result c = certified_separation(a, b, k.q);
        check_certified(c, e, reference(a, b, k.q));
        CHECK(c.exact_pairs == 0);
        certified_separation_query query(a, b);
        const certified_separation_result d = query(k.q);
        check_same_separation(d, c);
        CHECK(d.exact_pairs == 0);
    }
}

/// Neighbours a and b (sharing border vertices exactly) with B pushed off A
/// by a translation, along the line from A's centroid to B's and along
/// `aside`, by the first of 1e-5, 2e-5, 4e-5, ... (below 8) that leaves
/// them apart (the exact query tells), and the roles swapped: each frame
/// checked (check_separation_frame), certified_separation's points against
/// the reference's tie rule; `ties` counts the frames whose least distance
/// several edge pairs share.
void check_pushed_apart(const polygon& a, const polygon& b, point<double> aside, separation_tally& t,
                        std::size_t& ties) {
    const point<double> ca = a.centroid(), cb = b.centroid();
    for (const point<double>& d : {point<double>{cb.x - ca.x, cb.y - ca.y}, aside}) {
        const double length = std::hypot(d.x, d.y);
        for (double push = 1e-5; push < 8; push *= 2) {
            const pose q{d.x / length * push, d.y / length * push, 0};
            if (separation<ER>(a, b, q).meet()) continue;
            for (const bool swapped : {false, true}) {
                const polygon &s = swapped ? b : a, &m = swapped ? a : b;
                const pose p = swapped ? pose{-q.tx, -q.ty, 0} : q;
                check_separation_frame(s, m, p, t, floating::none);
                const reference_answer ref = reference(s, m, p);
                const std::pair<P, P> expected = tie_rule_points(ref.a, ref.b);
                const certified_separation_result c = certified_separation(s, m, p);
                CHECK(c.static_point.x == test_exact::nearest_double(expected.first.x()));
                CHECK(c.static_point.y == test_exact::nearest_double(expected.first.y()));
                CHECK(c.moving_point.x == test_exact::nearest_double(expected.second.x()));
                CHECK(c.moving_point.y == test_exact::nearest_double(expected.second.y()));
                std::size_t at_least = 0;
                for (std::size_t e = 0; e < s.size(); ++e)
                    for (std::size_t f = 0; f < m.size(); ++f)
                        at_least += pair_squared(ref.a, e, ref.b, f) == ref.boundary_squared;
                ties += at_least > 1;
            }
            break;
        }
    }
}

TEST_CASE(
    "separation: real neighbours pushed apart by a translation are settled in double words, as the exact "
    "reference and its tie rule",
    "[separation][reference][real]") {
    // North Carolina's counties (data/real/nc_counties.wkt), which share
    // their border vertices exactly. B pushed off A by a translation, along
    // the line from A's centroid to B's and along a random direction, by the
    // first of 1e-5, 2e-5, 4e-5, ... degrees (below 8) that leaves them apart (the
    // exact query tells), and the roles swapped. A shared border so moved is
    // parallel to itself: its vertices lie at one distance from the other
    // polygon's edges, ties that no bound separates (docs/separation.md).
    const std::vector<polygon> layer = test_data::real_layer("nc_counties.wkt");
    REQUIRE(layer.size() == 100);
    // Neighbours: polygons that share a vertex.
    std::vector<std::vector<std::pair<double, double>>> vertices(layer.size());
    for (std::size_t i = 0; i < layer.size(); ++i) {
        for (const point<double>& v : layer[i].vertices()) vertices[i].push_back({v.x, v.y});
        std::sort(vertices[i].begin(), vertices[i].end());
    }
    const auto share_a_vertex = [&](std::size_t i, std::size_t j) {
        std::vector<std::pair<double, double>> common;
        std::set_intersection(vertices[i].begin(), vertices[i].end(), vertices[j].begin(), vertices[j].end(),
                              std::back_inserter(common));
        return !common.empty();
    };
    const std::size_t wanted = static_cast<std::size_t>(test_effort::scaled(10));
    test_random::rng g(0x6e63);
    separation_tally t;
    std::size_t pairs = 0, ties = 0;
    for (std::size_t i = 0; i < layer.size() && pairs < wanted; i += 7)
        for (std::size_t j = i + 1; j < layer.size() && pairs < wanted; ++j) {
            if (!share_a_vertex(i, j)) continue;
            ++pairs;
            const double angle = g.uniform(0, 6.283185307179586);
            check_pushed_apart(layer[i], layer[j], {std::cos(angle), std::sin(angle)}, t, ties);
        }
    INFO(pairs << " neighbours, " << t.frames << " frames apart, " << ties << " with tied edge pairs, " << t.in_words
               << " in double words");
    CHECK(pairs == wanted);
    CHECK(t.frames == 4 * pairs);
    CHECK(t.meet == 0);
    CHECK(ties * 2 > t.frames);
    CHECK(t.in_words * 10 >= t.frames * 9);
}

TEST_CASE("separation: a survey grid's neighbours pushed apart are settled in double words, as the exact reference",
          "[separation][reference]") {
    // Rectangles of a survey grid, 2.51 by 3.3 from (1.255, 64.05) (its
    // corners doubles no sum of the steps gives exactly, each computed once
    // and shared by the four plots that meet there). Neighbours pushed apart
    // along the line between their centroids (along a row or column, or
    // diagonally from a shared corner) and along a random direction: edges
    // on one line apart along it (boxes apart by far more than the bounds,
    // where no side separates them), feet of corners exactly at corners
    // (translated_part), corner pairs at one offset (same_offset).
    std::vector<double> xs, ys;
    for (int i = 0; i < 5; ++i) xs.push_back(1.255 + 2.51 * i);
    for (int j = 0; j < 4; ++j) ys.push_back(64.05 + 3.3 * j);
    std::vector<polygon> plots;
    for (int j = 0; j + 1 < 4; ++j)
        for (int i = 0; i + 1 < 5; ++i)
            plots.push_back(polygon({ring_input{
                {{xs[i], ys[j]}, {xs[i + 1], ys[j]}, {xs[i + 1], ys[j + 1]}, {xs[i], ys[j + 1]}}, ring_role::outer}}));
    test_random::rng g(0x9e1d);
    separation_tally t;
    std::size_t pairs = 0, ties = 0;
    for (std::size_t i = 0; i < plots.size(); ++i)
        for (std::size_t j = i + 1; j < plots.size(); ++j) {
            if (!intersects<ER>(plots[i], plots[j], pose{})) continue;
            ++pairs;
            const double angle = g.uniform(0, 6.283185307179586);
            check_pushed_apart(plots[i], plots[j], {std::cos(angle), std::sin(angle)}, t, ties);
        }
    INFO(pairs << " neighbours, " << t.frames << " frames apart, " << ties << " with tied edge pairs, " << t.in_words
               << " in double words");
    CHECK(pairs == 29);
    // (A random direction into A may need more than the pushes tried to
    // carry B through it: a few frames fewer.)
    CHECK(t.frames > 3 * pairs);
    CHECK(t.meet == 0);
    CHECK(ties * 2 > t.frames);
    CHECK(t.in_words * 10 >= t.frames * 9);
}

TEST_CASE("separation: under a translation, distances within each other's bounds but not equal are not taken as a tie",
          "[separation][reference]") {
    // A's two lowest features lie 1 and 1 + 2^-50 above B's, far closer than
    // any bound in double separates, and the farther one belongs to the
    // least edge pair: only an exact comparison names the nearer. First,
    // an edge of A all but parallel to an edge of B (its two ends' distances
    // within one edge pair); two teeth of A over one edge of B (both
    // distances from A's vertices to one line of B, in two edge pairs); a
    // tooth of A over a flat edge of B beside a flat edge of A over a peak
    // of B (a vertex of A to a line of B against a vertex of B to a line of
    // A). Each with the roles swapped.
    const double up = 1 + 0x1p-50;
    const polygon ramp({test_shapes::ring({{1, up}, {3, 1}, {4, 5}, {0, 5}})});
    const polygon teeth({test_shapes::ring({{1, up}, {2, 3}, {3, 1}, {4, 5}, {0, 5}})});
    const polygon slab({test_shapes::ring({{-10, -5}, {10, -5}, {10, 0}, {-10, 0}})});
    const polygon tooth_and_flat({test_shapes::ring({{1, up}, {3, 4}, {5, 1}, {8, 1}, {8, 6}, {0, 6}})});
    const polygon flat_and_peak(
        {test_shapes::ring({{-2, -5}, {10, -5}, {10, -3}, {6.5, 0}, {4, -3}, {2, 0}, {0, 0}, {-2, -3}})});
    separation_tally t;
    for (const auto& [a, b] :
         {std::pair<const polygon*, const polygon*>{&ramp, &slab}, {&teeth, &slab}, {&tooth_and_flat, &flat_and_peak}})
        for (const double tx : {0.0, 0.25})
            for (const bool swapped : {false, true}) {
                const polygon &s = swapped ? *b : *a, &m = swapped ? *a : *b;
                const pose p{swapped ? -tx : tx, 0, 0};
                check_separation_frame(s, m, p, t);
                const reference_answer ref = reference(s, m, p);
                REQUIRE(ref.squared == ER(1));
                const std::pair<P, P> expected = tie_rule_points(ref.a, ref.b);
                const separation_result<ER> e = separation<ER>(s, m, p);
                CHECK(to_p(e.static_point) == expected.first);
                CHECK(to_p(e.moving_point) == expected.second);
                const certified_separation_result c = certified_separation(s, m, p);
                CHECK(P(c.static_point.x, c.static_point.y) == expected.first);
                CHECK(P(c.moving_point.x, c.moving_point.y) == expected.second);
            }
    CHECK(t.frames == 12);
}
