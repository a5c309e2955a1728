// SPDX-License-Identifier: BSL-1.0
// The distance bounds in double of predicates/distance.hpp (posing_error,
// point_segment_estimate, segment_distance_range, segments_must_cross, the
// filtered closest_between_segments, node_gap_lower, box_gap_lower) and the
// rounding of an exact value to double (nearest_double, scaled_nearest),
// each checked against distances computed independently on CGAL's exact
// kernel (CGAL::Cartesian<exact_rational>: squared_distance of Point_2 and
// Segment_2, support/exact_distance.hpp), for random segments at scales
// from 2^-600 to 2^600 and for degenerate ones (zero-length, collinear and
// overlapping, touching).

#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include "influence2d/core/box.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/distance.hpp"
#include "support/effort.hpp"
#include "support/exact_distance.hpp"
#include "support/random.hpp"

using namespace influence2d;
using test_exact::at_least_root;
using test_exact::at_most_root;
using test_exact::exact;
using test_exact::exact_point;
using test_exact::pow2;
using test_exact::Q;

namespace {

const double inf = std::numeric_limits<double>::infinity();

double at_scale(test_random::rng& r, int e) { return std::ldexp(r.signed_unit(), e); }

int count(int n) { return test_effort::scaled(n); }

/// A count of cases that must be reached, scaled like the samples drawn.
std::size_t at_least(int n) { return static_cast<std::size_t>(count(n)); }

/// A scale exponent: mostly within 2^-600..2^600, sometimes near the ends
/// of double's normal range (2^-1000..2^-980, 2^900..2^960). Subnormal
/// coordinates are left out: below about 2^-1025 the error terms of
/// point_segment_estimate, scaled back by a power of two, underflow to 0
/// while the value is rounded, and the bounds built on them no longer hold.
int random_exponent(test_random::rng& r) {
    if (r.chance(0.1))
        return r.chance(0.5) ? 900 + static_cast<int>(r.index(60)) : -980 - static_cast<int>(r.index(21));
    return static_cast<int>(r.index(1201)) - 600;
}

/// Whether the exact squared distance d2 lies within [lower, upper].
bool brackets(double lower, double upper, const Q& d2) {
    return at_most_root(Q(lower), d2) && (upper == inf || at_least_root(Q(upper), d2));
}

/// q posed exactly with the pose's own doubles c, s, tx, ty (computed here,
/// not by the library).
exact_point exactly_posed(const rotation_pose& p, const point<double>& q) {
    return {Q(p.c) * q.x - Q(p.s) * q.y + p.tx, Q(p.s) * q.x + Q(p.c) * q.y + p.ty};
}

/// A posed edge of B: its ends in double (the library's posing) and exact,
/// and the posing error bound for B's scale.
struct posed_edge {
    point<double> u, v;
    exact_point U, V;
    double delta;
};

posed_edge pose_edge(const point<double>& q0, const point<double>& q1, const pose& p) {
    const rotation_pose rp(p);
    const double scale = std::max({std::fabs(q0.x), std::fabs(q0.y), std::fabs(q1.x), std::fabs(q1.y)});
    return {rp.apply<double>(q0), rp.apply<double>(q1), exactly_posed(rp, q0), exactly_posed(rp, q1),
            posing_error(scale, p.tx, p.ty)};
}

/// An exact edge whose ends lie within delta per coordinate of the doubles
/// u and v: each end moved by k/8 of delta on each coordinate, k in -8..8
/// (exactly, in rationals), so that the filters' margins are used in full.
posed_edge perturbed_edge(test_random::rng& r, const point<double>& u, const point<double>& v, double delta) {
    const auto moved = [&](const point<double>& p) {
        return exact_point(Q(p.x) + Q(delta) * Q(static_cast<int>(r.index(17)) - 8) / 8,
                           Q(p.y) + Q(delta) * Q(static_cast<int>(r.index(17)) - 8) / 8);
    };
    return {u, v, moved(u), moved(v), delta};
}

/// The exact squared distance from the point c to the box (0 inside).
Q box_distance2(const box& b, const exact_point& c) {
    const Q gx = std::max<Q>({Q(Q(b.min_x) - c.x()), Q(0), Q(c.x() - Q(b.max_x))});
    const Q gy = std::max<Q>({Q(Q(b.min_y) - c.y()), Q(0), Q(c.y() - Q(b.max_y))});
    return gx * gx + gy * gy;
}

}  // namespace

TEST_CASE("distance bounds: posing_error bounds the double posing's error at every scale", "[distance][bounds]") {
    test_random::rng r(11);
    for (int k = 0; k < count(20000); ++k) {
        const int e = r.chance(0.05) ? -1060 - static_cast<int>(r.index(10)) : random_exponent(r);
        const int t = r.chance(0.5) ? e : random_exponent(r);  // a translation at another scale
        const point<double> q{at_scale(r, e), at_scale(r, e)};
        const pose p{r.chance(0.1) ? 0.0 : at_scale(r, t), r.chance(0.1) ? 0.0 : at_scale(r, t), r.uniform(-10, 10)};
        const rotation_pose rp(p);
        const point<double> posed = rp.apply<double>(q);
        const exact_point exact_posed = exactly_posed(rp, q);
        const double bound = posing_error(std::max(std::fabs(q.x), std::fabs(q.y)), p.tx, p.ty);
        INFO("q at 2^" << e << ", translation at 2^" << t);
        REQUIRE(std::isfinite(posed.x + posed.y));
        CHECK(CGAL::abs(Q(posed.x) - exact_posed.x()) <= Q(bound));
        CHECK(CGAL::abs(Q(posed.y) - exact_posed.y()) <= Q(bound));
    }
    // posing_spread covers the per-coordinate bound's diagonal: 1.5 > sqrt 2.
    CHECK(Q(posing_spread) * posing_spread > 2);
}

TEST_CASE("distance bounds: point_segment_estimate brackets the exact distance", "[distance][bounds]") {
    test_random::rng r(12);
    std::size_t degenerate = 0;
    for (int k = 0; k < count(30000); ++k) {
        const int e = random_exponent(r);
        point<double> a{at_scale(r, e), at_scale(r, e)};
        point<double> b{at_scale(r, e), at_scale(r, e)}, p{at_scale(r, e), at_scale(r, e)};
        const double kind = r.unit();
        if (kind < 0.1) {
            b = a;  // zero-length
        } else if (kind < 0.2) {
            // An edge shorter than 2^-100 of |p - a|, near the origin.
            a = {at_scale(r, e - 110), at_scale(r, e - 110)};
            b = {a.x + at_scale(r, e - 112), a.y};
        } else if (kind < 0.4) {
            const double f = r.uniform(-0.5, 1.5);  // near the line, often on the segment
            p = {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
        } else if (kind < 0.45) {
            p = r.chance(0.5) ? a : b;  // at an end
        }
        const double ab1 = std::fabs(b.x - a.x) + std::fabs(b.y - a.y);
        const double ap1 = std::fabs(p.x - a.x) + std::fabs(p.y - a.y);
        degenerate += ab1 > 0 && ab1 < degenerate_edge_share * std::max(ab1, ap1) ? 1 : 0;
        const estimate m = point_segment_estimate(p, a, b);
        INFO("scale 2^" << e << ", value " << m.value << ", error " << m.error);
        REQUIRE(std::isfinite(m.error));
        CHECK(m.error >= 0);
        CHECK(brackets(m.value - m.error, m.value + m.error, test_exact::squared_distance(p, a, b)));
    }
    CHECK(degenerate > at_least(100));
    // Named cases.
    //   p=a=b          all three coincide: exactly 0
    const estimate same = point_segment_estimate({2, 3}, {2, 3}, {2, 3});
    CHECK(same.value == 0);
    CHECK(same.error == 0);
    //   a-----p-----b  p on the segment: 0 within the error
    const estimate on = point_segment_estimate({1, 1}, {0, 0}, {2, 2});
    CHECK(brackets(on.value - on.error, on.value + on.error, Q(0)));
    //   p   a=b        a zero-length segment: the distance to a, 5
    const estimate to_point = point_segment_estimate({0, 0}, {3, 4}, {3, 4});
    CHECK(brackets(to_point.value - to_point.error, to_point.value + to_point.error, Q(25)));
    // A difference beyond double's range: nothing known.
    CHECK(point_segment_estimate({0, 0}, {-DBL_MAX, 0}, {DBL_MAX, 0}).error == inf);
}

TEST_CASE("distance bounds: segment_distance_range brackets the exact distance", "[distance][bounds]") {
    test_random::rng r(13);
    std::size_t crossing = 0, positive_lower = 0;
    // delta = 0: the doubles are the segments.
    for (int k = 0; k < count(20000); ++k) {
        const int e = random_exponent(r);
        const point<double> a{at_scale(r, e), at_scale(r, e)};
        point<double> b{at_scale(r, e), at_scale(r, e)}, u{at_scale(r, e), at_scale(r, e)},
            v{at_scale(r, e), at_scale(r, e)};
        const double kind = r.unit();
        if (kind < 0.1) {
            b = a;  // zero-length
        } else if (kind < 0.2) {
            u = {a.x + 0.5 * (b.x - a.x), a.y + 0.5 * (b.y - a.y)};  // u on or next to [a, b]
        } else if (kind < 0.3) {
            u = b;  // touching at an end
        } else if (kind < 0.4) {
            // collinear, overlapping or not: u and v on the line of [a, b]
            // (exactly when a and b are on a grid that the fractions keep)
            const double f = r.uniform(-1, 1), g = r.uniform(0, 2);
            u = {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
            v = {a.x + g * (b.x - a.x), a.y + g * (b.y - a.y)};
        }
        if (r.chance(0.05)) v = u;
        const distance_range d = segment_distance_range(a, b, u, v, 0);
        const Q d2 = test_exact::squared_distance(exact(a), exact(b), exact(u), exact(v));
        INFO("scale 2^" << e << ": [" << d.lower << ", " << d.upper << "]");
        CHECK(d.lower >= 0);
        CHECK(d.lower <= d.upper);
        CHECK(brackets(d.lower, d.upper, d2));
        crossing += d2 == 0 ? 1 : 0;
        positive_lower += d.lower > 0 ? 1 : 0;
    }
    CHECK(crossing > at_least(1000));
    CHECK(positive_lower > at_least(1000));

    // delta > 0: B's edge posed in double; the exact edge is the same edge
    // posed exactly, within posing_error of it.
    crossing = positive_lower = 0;
    for (int k = 0; k < count(20000); ++k) {
        const int e = random_exponent(r);
        const point<double> a{at_scale(r, e), at_scale(r, e)}, b{at_scale(r, e), at_scale(r, e)};
        const point<double> q0{at_scale(r, e), at_scale(r, e)}, q1{at_scale(r, e), at_scale(r, e)};
        const pose p{at_scale(r, e), at_scale(r, e), r.uniform(-4, 4)};
        const posed_edge s = pose_edge(q0, q1, p);
        if (!std::isfinite(s.u.x + s.u.y + s.v.x + s.v.y)) continue;
        const distance_range d = segment_distance_range(a, b, s.u, s.v, s.delta);
        const Q d2 = test_exact::squared_distance(exact(a), exact(b), s.U, s.V);
        INFO("scale 2^" << e << ": [" << d.lower << ", " << d.upper << "], delta " << s.delta);
        CHECK(brackets(d.lower, d.upper, d2));
        crossing += d2 == 0 ? 1 : 0;
        positive_lower += d.lower > 0 ? 1 : 0;
    }
    CHECK(crossing > at_least(1000));
    CHECK(positive_lower > at_least(1000));

    // A large delta (up to 2^-2 of the scale): the exact ends anywhere within
    // it, the doubles' segments near each other.
    for (int k = 0; k < count(20000); ++k) {
        const int e = random_exponent(r);
        const double delta = std::ldexp(r.unit(), e - 2 - static_cast<int>(r.index(20)));
        const point<double> a{at_scale(r, e), at_scale(r, e)}, b{at_scale(r, e), at_scale(r, e)};
        const double f = r.uniform(-0.2, 1.2);
        const point<double> u{a.x + f * (b.x - a.x) + r.uniform(-3, 3) * delta,
                              a.y + f * (b.y - a.y) + r.uniform(-3, 3) * delta};
        const point<double> v{u.x + at_scale(r, e), u.y + at_scale(r, e)};
        const posed_edge s = perturbed_edge(r, u, v, delta);
        const distance_range d = segment_distance_range(a, b, s.u, s.v, s.delta);
        INFO("scale 2^" << e << ": [" << d.lower << ", " << d.upper << "], delta " << s.delta);
        CHECK(brackets(d.lower, d.upper, test_exact::squared_distance(exact(a), exact(b), s.U, s.V)));
    }

    // Named cases.
    //   a====u====b====v   collinear, overlapping: distance 0
    const distance_range overlap = segment_distance_range({0, 0}, {2, 0}, {1, 0}, {3, 0}, 0);
    CHECK(overlap.lower == 0);
    CHECK(brackets(overlap.lower, overlap.upper, Q(0)));
    //   a-----b  u-----v   collinear, 1 apart
    const distance_range gap = segment_distance_range({0, 0}, {1, 0}, {2, 0}, {3, 0}, 0);
    CHECK(gap.lower > 0.99);
    CHECK(brackets(gap.lower, gap.upper, Q(1)));
    //   a-----b=u
    //          \       touching at an end
    //           v
    const distance_range touch = segment_distance_range({0, 0}, {2, 0}, {2, 0}, {3, 1}, 0);
    CHECK(touch.lower == 0);
    CHECK(brackets(touch.lower, touch.upper, Q(0)));
    //   u=v
    //    |  3          a point 3 above a segment
    //   a-----b
    const distance_range above = segment_distance_range({0, 0}, {4, 0}, {1, 3}, {1, 3}, 0);
    CHECK(above.lower > 2.99);
    CHECK(brackets(above.lower, above.upper, Q(9)));
    // A posed end beyond double's range: nothing known.
    const distance_range unknown = segment_distance_range({0, 0}, {1, 0}, {inf, 0}, {2, 0}, 0);
    CHECK(unknown.lower == 0);
    CHECK(unknown.upper == inf);
}

TEST_CASE("distance bounds: segments_must_cross only when the exact segments cross inside both", "[distance][bounds]") {
    test_random::rng r(14);
    std::size_t certain = 0;
    for (int k = 0; k < count(20000); ++k) {
        const int e = random_exponent(r);
        const point<double> a{at_scale(r, e), at_scale(r, e)}, b{at_scale(r, e), at_scale(r, e)};
        // B's edge through a point near [a, b], often through the segment.
        const double f = r.uniform(-0.2, 1.2);
        const point<double> m{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
        const point<double> w{at_scale(r, e - static_cast<int>(r.index(60))), at_scale(r, e)};
        const point<double> q0{m.x - w.x, m.y - w.y}, q1{m.x + w.x, m.y + w.y};
        const pose p =
            r.chance(0.5) ? pose{0, 0, 0} : pose{at_scale(r, e - 40), at_scale(r, e - 40), r.uniform(-1e-9, 1e-9)};
        const posed_edge s = pose_edge(q0, q1, p);
        if (!segments_must_cross(a, b, s.u, s.v, s.delta)) continue;
        ++certain;
        const exact_point A = exact(a), B = exact(b);
        INFO("scale 2^" << e);
        CHECK(CGAL::orientation(A, B, s.U) * CGAL::orientation(A, B, s.V) < 0);
        CHECK(CGAL::orientation(s.U, s.V, A) * CGAL::orientation(s.U, s.V, B) < 0);
    }
    CHECK(certain > at_least(1000));

    // Adversarial: the exact end U lies within a few delta of the line of
    // [a, b], on either side, and u is U moved within delta, so that u may
    // lie on the other side of the line than U.
    certain = 0;
    for (int k = 0; k < count(20000); ++k) {
        const int e = random_exponent(r);
        const double delta = std::ldexp(r.unit(), e - 4 - static_cast<int>(r.index(20)));
        const point<double> a{std::ldexp(-1.0, e), 0}, b{std::ldexp(1.0, e), 0};
        const point<double> U{at_scale(r, e - 1), r.uniform(-3, 3) * delta};
        const point<double> V{at_scale(r, e - 1), r.chance(0.5) ? std::ldexp(r.unit(), e) : -std::ldexp(r.unit(), e)};
        // u and v: U and V moved by up to delta on each coordinate.
        const point<double> u{U.x + r.signed_unit() * delta, U.y + r.signed_unit() * delta};
        const point<double> v{V.x + r.signed_unit() * delta, V.y + r.signed_unit() * delta};
        if (!(std::fabs(u.x - U.x) <= delta && std::fabs(u.y - U.y) <= delta && std::fabs(v.x - V.x) <= delta &&
              std::fabs(v.y - V.y) <= delta))
            continue;  // (rounding took a move beyond delta)
        if (!segments_must_cross(a, b, u, v, delta)) continue;
        ++certain;
        const exact_point A = exact(a), B = exact(b), EU = exact(U), EV = exact(V);
        INFO("scale 2^" << e << ", delta " << delta);
        CHECK(CGAL::orientation(A, B, EU) * CGAL::orientation(A, B, EV) < 0);
        CHECK(CGAL::orientation(EU, EV, A) * CGAL::orientation(EU, EV, B) < 0);
    }
    CHECK(certain > at_least(1000));
    //       v
    //       |
    //   a---+---b      a cross strictly inside both: certain
    //       |
    //       u
    CHECK(segments_must_cross({0, 0}, {2, 0}, {1, -1}, {1, 1}, 0));
    //   a-----b=u---v  touching at an end, collinear: no crossing inside both
    CHECK_FALSE(segments_must_cross({0, 0}, {2, 0}, {2, 0}, {3, 0}, 0));
    //         v
    //         |
    //   a-----u-----b  u on the interior of [a, b]: no strict crossing
    CHECK_FALSE(segments_must_cross({0, 0}, {2, 0}, {1, 0}, {1, 1}, 0));
    //       v
    //   a---+---b      a cross, but delta larger than the ends' distance to
    //       u          the line: not certain
    CHECK_FALSE(segments_must_cross({0, 0}, {2, 0}, {1, -0.1}, {1, 0.1}, 0.1));
}

TEST_CASE("distance bounds: segments_apart_beyond only when every segment near [u, v] lies farther than upper",
          "[distance][bounds]") {
    test_random::rng r(23);
    std::size_t apart = 0, within_delta = 0;
    for (int k = 0; k < count(20000); ++k) {
        const int e = static_cast<int>(r.index(1201)) - 600;
        // [a, b] along x, [u, v] above it, its end u nearest (over the
        // segment's interior, where the line test is tight) or beyond an end;
        // then the scene turned and shifted in double (the doubles are what
        // the predicate and the reference both take).
        const double h = std::ldexp(r.uniform(0.001, 1), e), x0 = r.uniform(-1.3, 1.3), x1 = r.uniform(-1.3, 1.3);
        const double rise = r.chance(0.3) ? 0 : std::ldexp(r.uniform(0, 1), e);
        // (Mostly a quarter turn, tilted a little: the line test's slack,
        // on |d|_1, is then near |d|; any angle otherwise.)
        const double turn = r.chance(0.8)
                                ? 1.5707963267948966 * static_cast<double>(r.index(4)) + r.uniform(-1e-6, 1e-6)
                                : r.uniform(0, 6.3);
        const double c = std::cos(turn), sn = std::sin(turn), n = std::hypot(c, sn);
        const double shift_x = at_scale(r, e), shift_y = at_scale(r, e);
        const auto place = [&](double x, double y) {
            return point<double>{(c * x - sn * y) / n + shift_x, (sn * x + c * y) / n + shift_y};
        };
        const point<double> a = place(-std::ldexp(1.0, e), 0), b = place(std::ldexp(1.0, e), 0);
        const point<double> u = place(std::ldexp(x0, e), h), v = place(std::ldexp(x1, e), h + rise);
        const double delta = std::ldexp(1.0, e - 8 - static_cast<int>(r.index(40)));
        // upper near the distance in double: often within delta below it,
        // where a margin without the posing's spread would call the pair apart.
        const double d =
            std::sqrt(CGAL::to_double(test_exact::squared_distance(exact(a), exact(b), exact(u), exact(v))));
        const double upper = std::max(0.0, d - delta * r.uniform(-0.5, 3));
        if (!segments_apart_beyond(a, b, u, v, upper, delta)) continue;
        ++apart;
        const Q dq(delta), upper2 = Q(upper) * Q(upper);
        const exact_point A = exact(a), B = exact(b);
        const auto moved = [&](const point<double>& p, int bits) {
            return exact_point(Q(p.x) + ((bits & 1) ? dq : -dq), Q(p.y) + ((bits & 2) ? dq : -dq));
        };
        bool near_bound = false;
        for (int corner = 0; corner < 16; ++corner) {
            const Q d2 = test_exact::squared_distance(A, B, moved(u, corner & 3), moved(v, corner >> 2));
            INFO("scale 2^" << e << ", corner " << corner << ", upper " << upper << ", delta " << delta);
            CHECK(d2 > upper2);
            near_bound = near_bound || d2 < (Q(upper) + 2 * dq) * (Q(upper) + 2 * dq);
        }
        if (near_bound) ++within_delta;
    }
    // Pairs called apart whose moved segments come within 2 delta of upper:
    // the margin is tested where it matters.
    CHECK(apart > at_least(1000));
    CHECK(within_delta > at_least(200));
    // A crossing pair is never apart, whatever upper.
    for (int k = 0; k < count(2000); ++k) {
        const int e = static_cast<int>(r.index(1201)) - 600;
        const point<double> a{-std::ldexp(1.0, e), at_scale(r, e)}, b{std::ldexp(1.0, e), at_scale(r, e)};
        const point<double> u{at_scale(r, e - 1), -std::ldexp(3.0, e)}, v{at_scale(r, e - 1), std::ldexp(3.0, e)};
        CHECK_FALSE(segments_apart_beyond(a, b, u, v, std::ldexp(r.uniform(0, 8), e), 0));
    }
}

TEST_CASE("distance bounds: the filtered closest_between_segments is the exact closest pair", "[distance][bounds]") {
    test_random::rng r(15);
    for (int k = 0; k < count(10000); ++k) {
        const int e = random_exponent(r);
        const point<double> a{at_scale(r, e), at_scale(r, e)},
            b = r.chance(0.1) ? a : point<double>{at_scale(r, e), at_scale(r, e)};
        const point<double> q0{at_scale(r, e), at_scale(r, e)}, q1{at_scale(r, e), at_scale(r, e)};
        const pose p{at_scale(r, e), at_scale(r, e), r.uniform(-4, 4)};
        // B's edge posed (delta from posing_error), or the exact ends
        // anywhere within a large delta of doubles near [a, b].
        posed_edge s = pose_edge(q0, q1, r.chance(0.2) ? pose{0, 0, 0} : p);
        if (r.chance(0.5)) {
            const double delta = std::ldexp(r.unit(), e - 2 - static_cast<int>(r.index(20)));
            const double f = r.uniform(-0.2, 1.2);
            const point<double> u{a.x + f * (b.x - a.x) + r.uniform(-3, 3) * delta,
                                  a.y + f * (b.y - a.y) + r.uniform(-3, 3) * delta};
            s = perturbed_edge(r, u, {u.x + at_scale(r, e), u.y + at_scale(r, e)}, delta);
        }
        if (!std::isfinite(s.u.x + s.u.y + s.v.x + s.v.y)) continue;
        const point<exact_rational> A{Q(a.x), Q(a.y)}, B{Q(b.x), Q(b.y)}, U{s.U.x(), s.U.y()}, V{s.V.x(), s.V.y()};
        const segment_pair_closest<exact_rational> c = closest_between_segments(a, b, s.u, s.v, s.delta, A, B, U, V);
        const Q d2 = test_exact::squared_distance(exact(a), exact(b), s.U, s.V);
        INFO("scale 2^" << e);
        CHECK(c.squared == d2);
        // The points realise it and lie on their segments.
        const exact_point p1(c.on_first.x, c.on_first.y), p2(c.on_second.x, c.on_second.y);
        CHECK(CGAL::squared_distance(p1, p2) == d2);
        CHECK(test_exact::squared_distance(p1, exact(a), exact(b)) == 0);
        CHECK(test_exact::squared_distance(p2, s.U, s.V) == 0);
    }
}

TEST_CASE("distance bounds: settled_closest_between settles only the exact closest pair's parts",
          "[distance][bounds]") {
    test_random::rng r(16);
    std::size_t settled = 0, ties = 0, interiors = 0;
    for (int k = 0; k < count(20000); ++k) {
        const int e = random_exponent(r);
        const point<double> a{at_scale(r, e), at_scale(r, e)},
            b = r.chance(0.05) ? a : point<double>{at_scale(r, e), at_scale(r, e)};
        point<double> q0{at_scale(r, e), at_scale(r, e)}, q1{at_scale(r, e), at_scale(r, e)};
        const double near = std::ldexp(1.0, e - 1 - static_cast<int>(r.index(50)));
        switch (r.index(5)) {
        case 0:  // B's start near a, B's edge nearly square to the offset: a projection near an end
            q0 = {a.x + near * r.signed_unit(), a.y + near * r.signed_unit()};
            q1 = {q0.x - (q0.y - a.y) * 1e3 + near * r.signed_unit(), q0.y + (q0.x - a.x) * 1e3};
            break;
        case 1:  // B's edge parallel to A's, shifted: ties between ends
            q0 = {a.x + near, a.y + near};
            q1 = {b.x + near, b.y + near};
            break;
        case 2:  // B's start beyond a on the line of [a, b]
            q0 = {a.x - (b.x - a.x) * r.unit(), a.y - (b.y - a.y) * r.unit()};
            break;
        default: break;
        }
        const bool posed = r.chance(0.5);
        const posed_edge s = posed ? pose_edge(q0, q1, pose{at_scale(r, e - 40), at_scale(r, e - 40), 0.5})
                                   : perturbed_edge(r, q0, q1, std::ldexp(r.unit(), e - 30));
        if (!std::isfinite(s.u.x + s.u.y + s.v.x + s.v.y) || s.u == s.v) continue;
        const std::optional<settled_closest> c = settled_closest_between(a, b, s.u, s.v, s.delta);
        if (!c) continue;
        ++settled;
        const point<exact_rational> A{Q(a.x), Q(a.y)}, B{Q(b.x), Q(b.y)}, U{s.U.x(), s.U.y()}, V{s.V.x(), s.V.y()};
        const Q d2 = test_exact::squared_distance(exact(a), exact(b), s.U, s.V);
        INFO("case " << k << ", scale 2^" << e);
        CHECK(d2 > 0);
        CHECK(brackets(c->lower, c->upper, d2));
        // The parts are those of the exact closest pair, and the points the
        // parts give realise the distance (CGAL's), each on its segment at
        // that part.
        const segment_pair_closest<exact_rational> x = closest_between_segments(A, B, U, V);
        CHECK(c->first_part == x.first_part);
        CHECK(c->second_part == x.second_part);
        const point<exact_rational> ends[4] = {A, B, U, V};
        const segment_pair_closest<exact_rational> y =
            closest_at_parts<exact_rational>(c->first_part, c->second_part, [&](int i) { return ends[i]; });
        CHECK(y.squared == d2);
        const exact_point p1(y.on_first.x, y.on_first.y), p2(y.on_second.x, y.on_second.y);
        CHECK(CGAL::squared_distance(p1, p2) == d2);
        CHECK(test_exact::squared_distance(p1, exact(a), exact(b)) == 0);
        CHECK(test_exact::squared_distance(p2, s.U, s.V) == 0);
        CHECK((p1 == exact(a)) == (c->first_part == segment_part::start));
        CHECK((p2 == s.U) == (c->second_part == segment_part::start));
        ties += c->first_part != segment_part::interior && c->second_part != segment_part::interior;
        interiors += c->first_part == segment_part::interior || c->second_part == segment_part::interior;
    }
    INFO("settled " << settled << ", vertex to vertex " << ties << ", vertex to edge " << interiors);
    CHECK(settled > at_least(8000));
    CHECK(ties > at_least(500));
    CHECK(interiors > at_least(3000));
    // By hand: a vertex of each, the four end candidates two by two on the
    // same points, settled; a crossing or a touch is not.
    const std::optional<settled_closest> corner = settled_closest_between({0, 0}, {1, 0}, {-1, -1}, {-2, -1}, 1e-12);
    REQUIRE(corner);
    CHECK(corner->first_part == segment_part::start);
    CHECK(corner->second_part == segment_part::start);
    CHECK_FALSE(settled_closest_between({0, 0}, {2, 0}, {1, -1}, {1, 1}, 1e-12));
    CHECK_FALSE(settled_closest_between({0, 0}, {2, 0}, {1, 0}, {1, 1}, 1e-12));
    //   u---v          parallel and overlapping in projection: the ends tie
    //   a-----b        with different parts, which double cannot order
    CHECK_FALSE(settled_closest_between({0, 0}, {2, 0}, {0.5, 1}, {1.5, 1}, 1e-12));
}

TEST_CASE("distance bounds: node_gap_lower and box_gap_lower are lower bounds", "[distance][bounds]") {
    test_random::rng r(16);
    std::size_t positive = 0;
    for (int k = 0; k < count(20000); ++k) {
        const int e = random_exponent(r);
        const double x0 = at_scale(r, e), y0 = at_scale(r, e);
        const box bounds{x0, y0, x0 + std::ldexp(r.unit(), e), y0 + std::ldexp(r.unit(), e)};
        // A node of B: its centre posed in double and exactly, a radius.
        const point<double> q{at_scale(r, e), at_scale(r, e)};
        const pose p{at_scale(r, e), at_scale(r, e), r.uniform(-4, 4)};
        const rotation_pose rp(p);
        const point<double> center = rp.apply<double>(q);
        const exact_point exact_center = exactly_posed(rp, q);
        const double delta = posing_error(std::max(std::fabs(q.x), std::fabs(q.y)), p.tx, p.ty);
        const double radius = r.chance(0.1) ? 0.0 : std::ldexp(r.unit(), e - static_cast<int>(r.index(8)));
        const double lower = node_gap_lower(bounds, center, radius, delta);
        // Every point within radius of the exact centre is at least lower
        // from the box: lower + radius <= the exact centre's distance.
        INFO("scale 2^" << e << ", lower " << lower);
        CHECK(at_most_root(Q(lower) + Q(radius), box_distance2(bounds, exact_center)));
        positive += lower > 0 ? 1 : 0;

        // Two boxes.
        const double x1 = at_scale(r, e), y1 = at_scale(r, e);
        const box other{x1, y1, x1 + std::ldexp(r.unit(), e), y1 + std::ldexp(r.unit(), e)};
        const Q gx = std::max<Q>({Q(0), Q(Q(other.min_x) - bounds.max_x), Q(Q(bounds.min_x) - other.max_x)});
        const Q gy = std::max<Q>({Q(0), Q(Q(other.min_y) - bounds.max_y), Q(Q(bounds.min_y) - other.max_y)});
        const double g = box_gap_lower(bounds, other);
        CHECK(g >= 0);
        CHECK(at_most_root(Q(g), gx * gx + gy * gy));
    }
    CHECK(positive > at_least(1000));
    // Named cases.
    //   +--+ +--+      boxes 1 apart along x: the gap is at most 1
    //   |  | |  |
    //   +--+ +--+
    CHECK(box_gap_lower({0, 0, 1, 1}, {2, 0, 3, 1}) <= 1);
    CHECK(box_gap_lower({0, 0, 1, 1}, {2, 0, 3, 1}) > 0.99);
    //   +--+--+        touching boxes: 0
    CHECK(box_gap_lower({0, 0, 1, 1}, {1, 0, 2, 1}) == 0);
    //   +--+   o       a node of radius 1 centred 3 right of the unit box,
    //   +--+           posed exactly: at most 2 from it
    CHECK(node_gap_lower({0, 0, 1, 1}, {4, 0.5}, 1, 0) <= 2);
    CHECK(node_gap_lower({0, 0, 1, 1}, {4, 0.5}, 1, 0) > 1.99);
    CHECK(node_gap_lower({0, 0, 1, 1}, {inf, 0}, 1, 0) == -inf);
}

TEST_CASE("distance bounds: nearest_double is the nearest double, scaled_nearest beyond double's range",
          "[distance][rounding]") {
    test_random::rng r(17);
    for (int k = 0; k < count(5000); ++k) {
        // x = m 2^e / n, not a double in general.
        const Q m(static_cast<double>(r.gen() >> 11) + 1), n(static_cast<double>(r.gen() >> 20) + 1);
        const int e = static_cast<int>(r.index(2000)) - 1040;  // up to 2^1013: finite
        const Q x = m * pow2(e) / n * (r.chance(0.5) ? 1 : -1);
        const double d = nearest_double(x);
        INFO("x = " << CGAL::to_double(x));
        REQUIRE(std::isfinite(d));
        const double up = std::nextafter(d, inf), down = std::nextafter(d, -inf);
        // In the normal range the nearest; in the subnormal range within one unit.
        if (std::fabs(d) >= DBL_MIN) {
            CHECK(CGAL::abs(x - Q(d)) <= CGAL::abs(x - Q(up)));
            CHECK(CGAL::abs(x - Q(d)) <= CGAL::abs(x - Q(down)));
        } else {
            CHECK(CGAL::abs(x - Q(d)) <= pow2(-1074));
        }
        // A squared distance beyond double's range: y 2^k within half an ulp of y.
        const Q big = CGAL::abs(x) * pow2(r.chance(0.5) ? 1500 : -1500);
        const scaled_double s = scaled_nearest(big);
        CHECK(s.exponent % 600 == 0);
        const Q y = big / pow2(s.exponent);
        CHECK(CGAL::abs(y - Q(s.mantissa)) <= CGAL::abs(y - Q(std::nextafter(s.mantissa, inf))));
        CHECK(CGAL::abs(y - Q(s.mantissa)) <= CGAL::abs(y - Q(std::nextafter(s.mantissa, 0.0))));
    }
    // A tie goes to the even neighbour: 1 + 2^-53 lies halfway between 1
    // and 1 + 2^-52.
    CHECK(nearest_double(Q(Q(1) + pow2(-53))) == 1);
    CHECK(nearest_double(Q(Q(1) + 3 * pow2(-53))) == 1 + 0x1p-51);
    CHECK(nearest_double(Q(0)) == 0);
    CHECK(nearest_double(pow2(1100)) == inf);
}

TEST_CASE("distance: translated_part names closest_on_segment's part exactly", "[distance]") {
    // A point and a segment one of which is translated by t (not a double
    // sum): the part closest_on_segment takes on the exact posed points,
    // in exact rationals, against translated_part on the doubles as given.
    // Feet exactly at an end: the point level with an end after the
    // translation, where no bound settles the part.
    test_random::rng g(0x7a47);
    int at_ends = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const point<double> u{g.uniform(-50, 50), g.uniform(-50, 50)}, v{g.uniform(-50, 50), g.uniform(-50, 50)};
        const point<double> t{g.uniform(-1, 1) * 1e-3, g.uniform(-1, 1) * 1e-3};
        const bool moving_segment = trial % 2 == 0;
        point<double> p{g.uniform(-50, 50), g.uniform(-50, 50)};
        if (g.chance(0.5)) p = g.chance(0.5) ? u : v;  // a shared vertex, then moved apart by t
        const auto Qp = [](const point<double>& x, const point<double>& shift, bool moved) {
            return exact_point(moved ? Q(x.x) + Q(shift.x) : Q(x.x), moved ? Q(x.y) + Q(shift.y) : Q(x.y));
        };
        const auto P = Qp(p, t, !moving_segment), U = Qp(u, t, moving_segment), V = Qp(v, t, moving_segment);
        const Q along = (V.x() - U.x()) * (P.x() - U.x()) + (V.y() - U.y()) * (P.y() - U.y());
        const Q length2 = (V.x() - U.x()) * (V.x() - U.x()) + (V.y() - U.y()) * (V.y() - U.y());
        const segment_part expected = along <= 0         ? segment_part::start
                                      : along >= length2 ? segment_part::end
                                                         : segment_part::interior;
        INFO("trial " << trial);
        CHECK(translated_part(p, u, v, t, moving_segment) == expected);
        at_ends += expected != segment_part::interior ? 1 : 0;
    }
    CHECK(at_ends > 300);
    // A's corner level with B's after B moved along A's side: the foot at
    // B's end exactly (start), and a unit in the last place inside.
    const point<double> a0{3.7649999999999997, 64.05}, t{1e-5, 0};
    CHECK(translated_part(a0, a0, {a0.x, 67.35000000000001}, t, true) == segment_part::start);
    CHECK(translated_part({a0.x, std::nextafter(a0.y, 100.0)}, a0, {a0.x, 67.35000000000001}, t, true) ==
          segment_part::interior);
}
