// SPDX-License-Identifier: BSL-1.0
// The decisions of verification/decisions.hpp: every number type agrees with
// the exact reference on easy inputs; at the precision cliff double does not,
// and the certified evaluation (certified, then exact rationals) does.

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "influence2d/number/cgal.hpp"
#include "verification/decisions.hpp"

namespace {

using namespace influence2d;
using namespace influence2d::verification;

using certified_evaluator = evaluator<certified, exact_rational>;
using interval_evaluator = evaluator<interval, exact_rational>;

polygon make(std::vector<point<double>> v) { return polygon({ring_input{std::move(v), ring_role::outer}}); }

const double cliff = 1e8;                            // magnitude of the cliff cases
const double below_half_ulp = std::ldexp(1.0, -28);  // lost when added to cliff in double (ulp 2^-26)

/// A: the rectangle [cliff - 2, cliff] x [-1, 1]; its right edge (edge 1) lies on x = cliff.
polygon cliff_static() { return make({{cliff - 2, -1}, {cliff, -1}, {cliff, 1}, {cliff - 2, 1}}); }

/// B: a triangle pointing left, its tip 2^-28 right of its origin. Posed at
/// (cliff, 0), the tip is 2^-28 right of A's edge: apart. In double cliff + 2^-28
/// rounds to cliff: the tip lies on the edge, and every decision sees contact.
polygon cliff_moving() { return make({{below_half_ulp, 0}, {1, -0.5}, {1, 0.5}}); }

const pose cliff_pose{cliff, 0, 0};

}  // namespace

TEST_CASE("decisions: double, long double, certified, interval and exact agree with the reference on easy inputs",
          "[verification][decisions]") {
    //   +-------+ (4,4)       A: the square [0,4]^2, centroid (2,2)
    //   |   A   |  /|         B: a right triangle, posed overlapping A's
    //   |       | / |            right side, clear of it, or inside A
    //   +-------+---+
    const polygon a = make({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
    const polygon b = make({{0, 0}, {1, 0}, {1, 1}});
    reference_decisions ref(a, b, 0);
    evaluator<double> in_double(a, b, 0);
    evaluator<long double> in_long_double(a, b, 0);
    certified_evaluator in_certified(a, b, 0);
    interval_evaluator in_interval(a, b, 0);
    evaluator<exact_rational> in_exact(a, b, 0);
    const std::vector<point<double>> points = {{3, 2.5}, {2.5, 3.5}, {-7, 1}, {1, -9}, {100, 3}};
    const std::vector<pose> poses = {{3.5, 1.5, 0}, {10, 10, 0.3}, {1.5, 1.5, 0.2}, {4.5, 1, 0}};
    std::size_t answers = 0;
    for (decision_kind k : all_decision_kinds) {
        for (std::size_t i = 0; i < points.size() && i < poses.size(); ++i) {
            const query q{points[i], poses[i]};
            const answer expected = ref.decide(k, q);
            INFO(decision_name(k) << ", " << i);
            CHECK(in_double.decide(k, q) == expected);
            CHECK(in_long_double.decide(k, q) == expected);
            CHECK(in_certified.decide(k, q) == expected);
            CHECK(in_interval.decide(k, q) == expected);
            CHECK(in_exact.decide(k, q) == expected);
            ++answers;
        }
    }
    CHECK(answers == 36);
    // Spot checks of the answers themselves.
    const query inside{{3, 2.5}, {1.5, 1.5, 0.2}};
    CHECK(ref.decide(decision_kind::cone_membership, {{3, 2.5}, {}}) == answer{1});  // the right side's cone
    CHECK(ref.decide(decision_kind::collides, inside) == answer{1});
    CHECK(ref.decide(decision_kind::pairs, inside).empty());  // B wholly inside A
    CHECK(ref.decide(decision_kind::containment, inside) == answer{2, 0});
    CHECK(ref.decide(decision_kind::collides, {{}, {10, 10, 0.3}}) == answer{0});
}

TEST_CASE("decisions: a pose at the precision cliff, 2^-28 apart at magnitude 1e8", "[verification][decisions]") {
    //        A          x = 1e8
    //   +---------+ |        B's tip at 1e8 + 2^-28: apart;
    //   |         |<|  B     in double the tip rounds onto the edge
    //   +---------+ |
    const polygon a = cliff_static(), b = cliff_moving();
    reference_decisions ref(a, b, 0);
    evaluator<double> in_double(a, b, 0);
    evaluator<long double> in_long_double(a, b, 0);
    certified_evaluator in_certified(a, b, 0);
    interval_evaluator in_interval(a, b, 0);
    const query q{{}, cliff_pose};

    CHECK(ref.decide(decision_kind::alpha_selection, q).empty());
    CHECK(in_double.decide(decision_kind::alpha_selection, q) == answer{1});
    CHECK(ref.decide(decision_kind::pairs, q).empty());
    CHECK(in_double.decide(decision_kind::pairs, q) == answer{1, 0, 1, 2});  // edge 1 against the tip's edges 0 and 2
    CHECK(ref.decide(decision_kind::containment, q) == answer{0, 0});
    CHECK(in_double.decide(decision_kind::containment, q) == answer{1, 0});  // the tip on A's boundary
    for (decision_kind k : {decision_kind::collides, decision_kind::collides_brute_force}) {
        CHECK(ref.decide(k, q) == answer{0});
        CHECK(in_double.decide(k, q) == answer{1});
    }
    // long double holds 1e8 + 2^-28 exactly; the certified evaluation falls
    // back to exact rationals where double cannot decide.
    for (decision_kind k : all_decision_kinds) {
        if (asks_point(k)) continue;
        INFO(decision_name(k));
        CHECK(in_long_double.decide(k, q) == ref.decide(k, q));
        CHECK(in_certified.decide(k, q) == ref.decide(k, q));
        CHECK(in_interval.decide(k, q) == ref.decide(k, q));
    }
    CHECK(in_certified.fallbacks() > 0);
    CHECK(in_interval.fallbacks() > 0);
}

TEST_CASE("decisions: a query point at the precision cliff of a cone boundary", "[verification][decisions]") {
    //         (-1,3)
    //            +           A: a square turned about the origin, its centroid;
    //           /   \  . . P   P lies 2^-26 (in y, at 1e8) clockwise of the ray
    //  (-3,-1) +  O  + (3,1)   from O through V = (3, 1). In double 3 * P.y rounds
    //           \   /          and P lands on the ray: in both cones at V.
    //            + (1,-3)
    const polygon a = make({{3, 1}, {-1, 3}, {-3, -1}, {1, -3}});
    REQUIRE(a.centroid() == point<double>{0, 0});
    const polygon b = make({{0, 0}, {1, 0}, {0, 1}});
    reference_decisions ref(a, b, 0);
    evaluator<double> in_double(a, b, 0);
    evaluator<long double> in_long_double(a, b, 0);
    certified_evaluator in_certified(a, b, 0);
    interval_evaluator in_interval(a, b, 0);
    const query q{{3 * cliff + std::ldexp(1.0, -24), cliff + std::ldexp(1.0, -26)}, {}};
    for (decision_kind k : {decision_kind::cone_membership, decision_kind::mask}) {
        INFO(decision_name(k));
        CHECK(ref.decide(k, q) == answer{3});  // the cone of edge 3, (1,-3) -> (3,1), alone
        CHECK(in_double.decide(k, q) == answer{0, 3});
        CHECK(in_long_double.decide(k, q) == answer{3});
        CHECK(in_certified.decide(k, q) == answer{3});
        CHECK(in_interval.decide(k, q) == answer{3});
    }
}

TEST_CASE("decisions: extended-area candidates at the precision cliff", "[verification][decisions]") {
    // B, a square about a centroid 2^-28 right of its origin, posed so that
    // its centroid is just beyond the reach n = r_B of A's edge x = 1e8 while
    // the rounded one (2^-28 lost) is just within it. Such a pose needs the
    // fraction of n on the 2^-26 grid to fall below 2^-28: the half size h of
    // the square is stepped until it does.
    const polygon a = cliff_static();
    bool found = false;
    for (int step = 0; step < 64 && !found; ++step) {
        const double h = 0.5 + step * std::ldexp(1.0, -10), d = below_half_ulp;
        const polygon b = make({{d - h, -h}, {d + h, -h}, {d + h, h}, {d - h, h}});
        if (b.centroid() != point<double>{d, 0}) continue;
        const double n = moving_reach(bounding_radius(b, b.centroid()), 0);
        const double grid = std::ldexp(1.0, -26);
        const double tx = cliff + std::floor(n / grid) * grid;  // tx - cliff <= n < tx - cliff + 2^-28
        if (!(n - (tx - cliff) < d)) continue;
        reference_decisions ref(a, b, 0);
        evaluator<double> in_double(a, b, 0);
        certified_evaluator in_certified(a, b, 0);
        interval_evaluator in_interval(a, b, 0);
        const query q{{}, {tx, 0, 0}};
        for (decision_kind k : {decision_kind::capsule_candidates, decision_kind::band_candidates}) {
            INFO(decision_name(k) << ", h = " << h);
            CHECK(ref.decide(k, q).empty());
            CHECK(in_double.decide(k, q) == answer{1});
            CHECK(in_certified.decide(k, q).empty());
            CHECK(in_interval.decide(k, q).empty());
        }
        found = true;
    }
    CHECK(found);
}

TEST_CASE("decisions: edges collinear with the centroid: the filtered types answer exactly",
          "[verification][decisions]") {
    //        +-----+          A: the square (0,0)-(4,4) with two tabs; its centroid
    //   +----+     |          O = (2,2) lies on the line of edges 4 and 10: their
    //   +====+  O  +====+     covering signs are exactly 0
    //        |     +----+
    //        +-----+
    const polygon a =
        make({{0, 0}, {4, 0}, {4, 1}, {6, 1}, {6, 2}, {4, 2}, {4, 4}, {0, 4}, {0, 3}, {-2, 3}, {-2, 2}, {0, 2}});
    const polygon b = make({{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}});
    reference_decisions ref(a, b, 0);
    certified_evaluator in_certified(a, b, 0);
    interval_evaluator in_interval(a, b, 0);
    for (const query& q : {query{{7, 2}, {6.5, 2, 0}}, query{{-5, 2}, {-2.5, 2.5, 0}}, query{{2, 2}, {2, 2, 0.5}}}) {
        for (decision_kind k : all_decision_kinds) {
            INFO(decision_name(k) << " at " << q.placement.tx << ", " << q.placement.ty);
            CHECK(in_certified.decide(k, q) == ref.decide(k, q));
            CHECK(in_interval.decide(k, q) == ref.decide(k, q));
        }
    }
    CHECK(ref.decide(decision_kind::collides, {{}, {6.5, 2, 0}}) == answer{1});
}

TEST_CASE("decisions: query points cover the cone boundaries, the boundary of A and far away",
          "[verification][decisions]") {
    const polygon a = make({{3, 1}, {-1, 3}, {-3, -1}, {1, -3}});
    const std::vector<point<double>> points = cone_query_points(a, 70, 1);
    REQUIRE(points.size() == 70);
    std::size_t vertices = 0, far = 0;
    for (const auto& p : points) {
        for (const auto& v : a.vertices()) vertices += p == v;
        far += std::hypot(p.x, p.y) > 30;
    }
    CHECK(vertices >= 5);
    CHECK(far >= 15);
    CHECK(cone_query_points(a, 70, 1) == points);  // deterministic
}
