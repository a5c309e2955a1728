// SPDX-License-Identifier: BSL-1.0
// The conservative filters in double (predicates/filters.hpp), each constant
// and bound checked against exact arithmetic: CGAL's exact rationals (the
// kernel CGAL::Cartesian<exact_rational> for distances and intersections,
// support/exact_distance.hpp) and MPFR for the angles. A filter that may keep
// too much must never drop what the exact decision keeps (soundness), on
// random inputs at many scales and on adversarial ones built to sit at the
// filter's edge; each test also counts that both of its answers occur.

#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <mpfr.h>

#include "influence2d/core/box.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/traits.hpp"
#include "influence2d/predicates/filters.hpp"
#include "support/effort.hpp"
#include "support/exact_distance.hpp"
#include "support/random.hpp"

using namespace influence2d;
using test_exact::at_least_root;
using test_exact::at_most_root;
using test_exact::exact;
using test_exact::pow2;
using test_exact::Q;

namespace {

const double infinity = std::numeric_limits<double>::infinity();
const double nan_value = std::numeric_limits<double>::quiet_NaN();

/// A double of magnitude about 2^e, either sign.
double filter_scale(test_random::rng& r, int e) { return std::ldexp(r.signed_unit(), e); }

/// The exact side value (b - a) x (q - a).
Q exact_side(const point<double>& a, const point<double>& b, const point<double>& q) {
    return (Q(b.x) - a.x) * (Q(q.y) - a.y) - (Q(b.y) - a.y) * (Q(q.x) - a.x);
}

int sign_of(const Q& x) { return static_cast<int>(CGAL::sign(x)); }

/// A point near the line a-b: a + f (b - a) rounded, then moved a few ulps.
point<double> near_line(test_random::rng& r, const point<double>& a, const point<double>& b) {
    const double f = r.uniform(-0.5, 1.5);
    point<double> q{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
    for (int k = static_cast<int>(r.index(4)); k > 0; --k)
        q.y = std::nextafter(q.y, r.chance(0.5) ? infinity : -infinity);
    for (int k = static_cast<int>(r.index(3)); k > 0; --k)
        q.x = std::nextafter(q.x, r.chance(0.5) ? infinity : -infinity);
    return q;
}

/// |angle(y, x) - t| computed by MPFR at 256 bits, t a double.
double atan2_error(double y, double x, double t) {
    mpfr_t a, yy, xx;
    mpfr_inits2(256, a, yy, xx, static_cast<mpfr_ptr>(nullptr));
    mpfr_set_d(yy, y, MPFR_RNDN);
    mpfr_set_d(xx, x, MPFR_RNDN);
    mpfr_atan2(a, yy, xx, MPFR_RNDN);
    mpfr_sub_d(a, a, t, MPFR_RNDN);
    const double e = std::fabs(mpfr_get_d(a, MPFR_RNDN));
    mpfr_clears(a, yy, xx, static_cast<mpfr_ptr>(nullptr));
    return e;
}

int filter_count(int n) { return test_effort::scaled(n); }

/// A count of cases that must be reached, scaled like the samples drawn.
std::size_t filter_at_least(int n) { return static_cast<std::size_t>(filter_count(n)); }

}  // namespace

TEST_CASE("filters: square_safe_low and square_safe_high keep squares and their sums in double's normal range",
          "[filters]") {
    const Q low(square_safe_low), high(square_safe_high);
    CHECK(low * low == pow2(-800));
    CHECK(high * high == pow2(800));
    CHECK(low * low > Q(DBL_MIN));           // far from the subnormals
    CHECK(Q(8) * high * high < Q(DBL_MAX));  // a sum of eight squares: below 2^803
    CHECK(Q(8) * high * high <= pow2(803));

    // filter_length within about an ulp of the exact length at every
    // magnitude, inside the safe range (squares) and outside it (hypot).
    test_random::rng r(1);
    std::size_t inside = 0, outside = 0;
    for (int k = 0; k < filter_count(20000); ++k) {
        const int e = static_cast<int>(r.index(2090)) - 1070;
        const double x = filter_scale(r, e),
                     y = r.chance(0.2) ? 0.0 : filter_scale(r, e - static_cast<int>(r.index(60)));
        const double f = filter_length(x, y);
        const double big = std::max(std::fabs(x), std::fabs(y));
        (big > square_safe_low && big < square_safe_high ? inside : outside) += 1;
        INFO("x = " << x << ", y = " << y << ", filter_length = " << f);
        REQUIRE(std::isfinite(f));
        const Q l2 = Q(x) * x + Q(y) * y;
        const Q tiny = pow2(-1074);
        CHECK(at_most_root(Q(f) * (1 - Q(0x1p-51)) - tiny, l2));
        CHECK(at_least_root(Q(f) * (1 + Q(0x1p-51)) + tiny, l2));
    }
    CHECK(inside > filter_at_least(1000));
    CHECK(outside > filter_at_least(1000));
    // Exact lengths at the ends of the range.
    CHECK(filter_length(3 * 0x1p-1074, 4 * 0x1p-1074) == 5 * 0x1p-1074);
    CHECK(filter_length(0x1.8p1000, 0x1p1001) == 0x1.4p1001);  // 3, 4, 5 times 2^999
    // Zero (a point inside a box) by the squares, and both signs of it.
    CHECK(filter_length(0.0, 0.0) == 0);
    CHECK(filter_length(-0.0, 0.0) == 0);
    CHECK(std::isnan(filter_length(std::nan(""), 0.0)));
    CHECK(std::isnan(filter_length(0.0, std::nan(""))));
}

TEST_CASE("filters: upper_sqrt is strictly above the root, by sqrt_widening and an ulp at most", "[filters]") {
    test_random::rng r(2);
    for (int k = 0; k < filter_count(20000); ++k) {
        // x = (hi + lo) 2^e with 64 significant bits, e within +-2000 (a
        // long double beyond double's range, whose root is in it).
        const double hi = r.uniform(1, 2), lo = r.chance(0.5) ? std::ldexp(r.signed_unit(), -60) : 0.0;
        const int e = static_cast<int>(r.index(4000)) - 2000;
        const long double x = std::ldexp(static_cast<long double>(hi) + static_cast<long double>(lo), e);
        const Q exact_x = (Q(hi) + Q(lo)) * pow2(e);
        const double up = upper_sqrt(x);
        INFO("x = " << static_cast<double>(x) << " (2^" << e << ")");
        REQUIRE(std::isfinite(up));
        CHECK(Q(up) * up > exact_x);
        // Not looser than sqrt_widening (and the roundings) allow.
        CHECK(Q(up) * up < exact_x * (1 + Q(4 * sqrt_widening)));
    }
    // Named cases: a perfect square, zero, and what is not a root.
    CHECK(upper_sqrt(4.0L) > 2);
    CHECK(upper_sqrt(0.0L) > 0);
    CHECK(upper_sqrt(std::numeric_limits<long double>::infinity()) == infinity);
    CHECK(upper_sqrt(0x1p5000L) == infinity);  // root 2^2500: beyond double
    CHECK(std::isnan(upper_sqrt(-1.0L)));
    CHECK(std::isnan(upper_sqrt(std::numeric_limits<long double>::quiet_NaN())));
    // The constant is far above the rounding it covers: a long double root
    // rounded to double is within 2^-53 + 2^-64 of the root.
    CHECK(Q(sqrt_widening) > 2 * (Q(0x1p-53) + Q(0x1p-64)));
}

TEST_CASE("filters: pose_scale_widening covers sqrt(c^2 + s^2) of the rounded cosine and sine", "[filters]") {
    test_random::rng r(3);
    const Q w(pose_scale_widening);
    const Q below = (1 - w) * (1 - w), above = (1 + w) * (1 + w);
    std::size_t off_one = 0;
    const auto check = [&](double theta) {
        const double c = std::cos(theta), s = std::sin(theta);
        const Q n = Q(c) * c + Q(s) * s;
        INFO("theta = " << theta);
        CHECK(n > below);
        CHECK(n < above);
        off_one += n != 1 ? 1 : 0;
    };
    for (int k = 0; k < filter_count(20000); ++k) check(filter_scale(r, static_cast<int>(r.index(40)) - 20));
    // Near the multiples of pi/4, where one of c, s is tiny or both equal;
    // huge angles, whose reduction is the library's.
    for (int k = -64; k <= 64; ++k) {
        const double t = k * 0.78539816339744830962;
        check(t);
        check(std::nextafter(t, infinity));
        check(std::nextafter(t, -infinity));
    }
    for (double t : {1e300, -1e300, 1e22, 0x1p1023, 3.0e-300, 0.0}) check(t);
    CHECK(off_one > filter_at_least(100));  // c^2 + s^2 is not 1 in general: the widening is needed
}

TEST_CASE("filters: atan2_widening covers std::atan2's error on doubles", "[filters]") {
    test_random::rng r(4);
    double worst = 0;
    for (int k = 0; k < filter_count(20000); ++k) {
        const int e = static_cast<int>(r.index(200)) - 100;
        double x = filter_scale(r, e), y = filter_scale(r, e + static_cast<int>(r.index(80)) - 40);
        if (r.chance(0.1)) x = 0;
        if (r.chance(0.1)) y = std::ldexp(x, -60);  // near an axis
        if (x == 0 && y == 0) continue;
        const double t = std::atan2(y, x);
        const double err = atan2_error(y, x, t);
        worst = std::max(worst, err);
        INFO("atan2(" << y << ", " << x << ") = " << t);
        CHECK(err < atan2_widening);
    }
    CHECK(worst < 1e-15);  // "within a few ulps (below 1e-15 rad)"
}

TEST_CASE("filters: direction_trust_factor keeps a trusted offset's direction within about 1e-3 rad", "[filters]") {
    // An offset o of the cone index, computed with an error below
    // filter_slack * scale per coordinate, is trusted when |o|_1 exceeds
    // direction_trust_factor * filter_slack * scale; its direction is then
    // within asin(2 / direction_trust_factor) of the exact one (the error
    // vector is at most sqrt 2 times the per-coordinate bound, |o|_2 at least
    // |o|_1 / sqrt 2).
    const double slack = number_traits<double>::filter_slack;
    test_random::rng r(5);
    const double limit = std::asin(2 / direction_trust_factor);
    CHECK(limit < 2.1e-3);
    for (int k = 0; k < filter_count(5000); ++k) {
        const double scale = std::ldexp(1.0, static_cast<int>(r.index(100)) - 50);
        const double bound = slack * scale;
        // At the threshold, in a random direction.
        const double phi = r.uniform(-3.14159, 3.14159);
        const double l1 =
            direction_trust_factor * bound * (1 + 1e-9) / (std::fabs(std::cos(phi)) + std::fabs(std::sin(phi)));
        const double ox = l1 * std::cos(phi), oy = l1 * std::sin(phi);
        if (!(std::fabs(ox) + std::fabs(oy) > direction_trust_factor * bound)) continue;
        // The exact offset: the worst corners of the error box, and a random one.
        const double ex = r.chance(0.5) ? bound : -bound, ey = r.chance(0.5) ? bound : -bound;
        const double tx = ox + ex * r.signed_unit(), ty = oy + ey * r.signed_unit();
        const double seen = std::atan2(oy, ox);
        double err = atan2_error(ty, tx, seen);
        if (err > 3.14159) err = 2 * 3.14159265358979 - err;
        CHECK(err < limit);
    }
}

TEST_CASE("filters: segment_distance is the distance within its rounding, at any scale", "[filters]") {
    test_random::rng r(6);
    for (int k = 0; k < filter_count(20000); ++k) {
        const int e = static_cast<int>(r.index(2000)) - 1000;
        const point<double> a{filter_scale(r, e), filter_scale(r, e)};
        const point<double> b = r.chance(0.1) ? a : point<double>{filter_scale(r, e), filter_scale(r, e)};
        const point<double> p =
            r.chance(0.3) ? near_line(r, a, b) : point<double>{filter_scale(r, e), filter_scale(r, e)};
        const double d = segment_distance(p, a, b);
        INFO("scale 2^" << e);
        REQUIRE(std::isfinite(d));
        const Q d2 = test_exact::squared_distance(p, a, b);
        const Q room = Q(0x1p-45) * (CGAL::abs(Q(b.x) - a.x) + CGAL::abs(Q(b.y) - a.y) + CGAL::abs(Q(p.x) - a.x) +
                                     CGAL::abs(Q(p.y) - a.y)) +
                       pow2(-1074);
        CHECK(at_most_root(Q(d) - room, d2));
        CHECK(at_least_root(Q(d) + room, d2));
    }
    // Named cases.
    //   p = a = b: all three coincide
    CHECK(segment_distance({1, 1}, {1, 1}, {1, 1}) == 0);
    //   p . . . a=b    a zero-length segment: the distance to a
    CHECK(segment_distance({0, 0}, {3, 4}, {3, 4}) == 5);
    //   a-----p-----b  p on the segment
    CHECK(segment_distance({1, 1}, {0, 0}, {2, 2}) == 0);
    //   a <- 2^1024 -> b: the difference overflows
    CHECK(segment_distance({0, 0}, {-DBL_MAX, 0}, {DBL_MAX, 0}) == infinity);
}

TEST_CASE("filters: may_be_within never drops a point within reach", "[filters]") {
    // Sound with the callers' margin: a point at exact distance D <= reach
    // passes with reach widened by 2^-45 (|b - a|_1 + |p - a|_1), above
    // segment_distance's rounding. reach is set at the edge: the nearest
    // double to D, moved a few ulps either way.
    test_random::rng r(7);
    std::size_t kept = 0, dropped = 0;
    for (int k = 0; k < filter_count(20000); ++k) {
        const int e = static_cast<int>(r.index(2000)) - 1000;
        const point<double> a{filter_scale(r, e), filter_scale(r, e)};
        const point<double> b = r.chance(0.1) ? a : point<double>{filter_scale(r, e), filter_scale(r, e)};
        const point<double> p =
            r.chance(0.3) ? near_line(r, a, b) : point<double>{filter_scale(r, e), filter_scale(r, e)};
        const Q d2 = test_exact::squared_distance(p, a, b);
        double reach = std::sqrt(CGAL::to_double(d2 * pow2(-2 * e))) * std::ldexp(1.0, e);
        for (int s = static_cast<int>(r.index(7)) - 3; s != 0; s += s > 0 ? -1 : 1)
            reach = std::nextafter(reach, s > 0 ? infinity : 0.0);
        if (r.chance(0.2)) reach *= r.uniform(0, 2);
        const double margin =
            0x1p-45 * (std::fabs(b.x - a.x) + std::fabs(b.y - a.y) + std::fabs(p.x - a.x) + std::fabs(p.y - a.y)) +
            0x1p-1074;
        const bool within = at_least_root(Q(reach), d2);
        const bool answer = may_be_within(p, a, b, reach + margin);
        if (within) {
            INFO("scale 2^" << e << ", reach " << reach);
            CHECK(answer);
        }
        (answer ? kept : dropped) += 1;
    }
    CHECK(kept > filter_at_least(1000));
    CHECK(dropped > filter_at_least(1000));
    // Named cases.
    //   a-----p-----b  p on the segment: within reach 0
    CHECK(may_be_within({1, 1}, {0, 0}, {2, 2}, 0));
    //   p
    //   |  1           p at distance 1 above a horizontal segment
    //   a-----b
    CHECK(may_be_within({0.5, 1}, {0, 0}, {2, 0}, 1));
    CHECK_FALSE(may_be_within({0.5, 1}, {0, 0}, {2, 0}, std::nextafter(1.0, 0.0)));
    // A difference that overflows: kept whatever the reach.
    CHECK(may_be_within({0, 0}, {-DBL_MAX, 0}, {DBL_MAX, 0}, 0));
}

TEST_CASE("filters: certain_side answers only sides that exact arithmetic confirms, beyond the slack", "[filters]") {
    // Callers pass the direction as the rounded difference b - a; the answer
    // must hold for the exact line through a and b: the exact (b - a) x
    // (q - a) has the answered sign and exceeds the slack. Random triples at
    // many scales, half of them within a few ulps of the line.
    test_random::rng r(8);
    std::size_t answered = 0, refused = 0;
    for (int k = 0; k < filter_count(40000); ++k) {
        const int e = static_cast<int>(r.index(1600)) - 800;
        const point<double> a{filter_scale(r, e), filter_scale(r, e)}, b{filter_scale(r, e), filter_scale(r, e)};
        const point<double> q =
            r.chance(0.5) ? near_line(r, a, b) : point<double>{filter_scale(r, e), filter_scale(r, e)};
        const double dx = b.x - a.x, dy = b.y - a.y;
        double slack = 0;
        if (r.chance(0.5)) slack = std::ldexp(r.unit(), 2 * e - static_cast<int>(r.index(40)));
        const int side = certain_side(a, dx, dy, q, slack);
        if (side == 0) {
            ++refused;
            continue;
        }
        ++answered;
        const Q exact_value = exact_side(a, b, q);
        INFO("scale 2^" << e << ", slack " << slack);
        CHECK(sign_of(exact_value) == side);
        CHECK(CGAL::abs(exact_value) > Q(slack));
        // And with the direction as given.
        const Q given = Q(dx) * (Q(q.y) - a.y) - Q(dy) * (Q(q.x) - a.x);
        CHECK(sign_of(given) == side);
    }
    CHECK(answered > filter_at_least(10000));
    CHECK(refused > filter_at_least(1000));

    // Named cases.
    //   a-----q-----b   q on the line: no side
    CHECK(certain_side({0, 0}, 2, 2, {1, 1}, 0) == 0);
    //         q
    //   a-----------b   q above, 1 from the line: left, unless the slack reaches it
    CHECK(certain_side({0, 0}, 4, 0, {2, 1}, 0) == 1);
    CHECK(certain_side({0, 0}, 4, 0, {2, -1}, 0) == -1);
    CHECK(certain_side({0, 0}, 4, 0, {2, 1}, 4) == 0);  // |o| = 4 is not beyond slack 4
    // A product of 2^-920: its bound, 2^-968, is below side_bound_floor and
    // not trusted, although the exact side is +1; a product of 2^-840 has the
    // bound 2^-888, trusted.
    const double t = 0x1p-460;
    CHECK(sign_of(exact_side({0, 0}, {t, 0}, {0, t})) == 1);
    CHECK(certain_side({0, 0}, t, 0, {0, t}, 0) == 0);
    CHECK(certain_side({0, 0}, 0x1p-420, 0, {0, 0x1p-420}, 0) == 1);
    // Overflow and NaN: no side.
    CHECK(certain_side({0, 0}, DBL_MAX, DBL_MAX, {-DBL_MAX, DBL_MAX}, 0) == 0);
    CHECK(certain_side({0, 0}, 1, 0, {0, nan_value}, 0) == 0);
}

TEST_CASE("filters: segments_may_meet never drops segments that meet, with or without an error e", "[filters]") {
    test_random::rng r(9);
    using test_exact::exact_segment;
    std::size_t meeting = 0, apart = 0;

    // e = 0: the doubles are the segments; CGAL's exact do_intersect decides.
    for (int k = 0; k < filter_count(20000); ++k) {
        const int e = static_cast<int>(r.index(1200)) - 600;
        const point<double> a{filter_scale(r, e), filter_scale(r, e)}, b{filter_scale(r, e), filter_scale(r, e)};
        point<double> u{filter_scale(r, e), filter_scale(r, e)}, v{filter_scale(r, e), filter_scale(r, e)};
        if (r.chance(0.5)) u = near_line(r, a, b);     // u at the line of [a, b], often on it
        if (r.chance(0.2)) v = near_line(r, a, b);     // both: nearly collinear
        if (r.chance(0.1)) u = r.chance(0.5) ? a : b;  // a shared end
        const bool meet = CGAL::do_intersect(exact_segment(exact(a), exact(b)), exact_segment(exact(u), exact(v)));
        const bool answer = segments_may_meet(a, b, u, v, 0);
        if (meet) {
            ++meeting;
            INFO("scale 2^" << e);
            CHECK(answer);
        }
        apart += answer ? 0 : 1;
    }
    CHECK(meeting > filter_at_least(1000));
    CHECK(apart > filter_at_least(1000));

    // e > 0: exact segments whose ends lie within e of the doubles on each
    // coordinate, pushed towards each other by up to e: whenever those meet,
    // the filter must answer true.
    meeting = apart = 0;
    for (int k = 0; k < filter_count(20000); ++k) {
        const int s = static_cast<int>(r.index(1200)) - 600;
        const double scale = std::ldexp(1.0, s);
        const double e = scale * std::ldexp(1.0, -static_cast<int>(r.index(30)) - 2);
        const point<double> a{filter_scale(r, s), filter_scale(r, s)}, b{filter_scale(r, s), filter_scale(r, s)};
        // v near the line of [a, b], a few e off it; u away from it.
        const point<double> on = near_line(r, a, b);
        const double gap = r.uniform(0, 4) * e;
        const point<double> v{on.x + (r.chance(0.5) ? gap : -gap), on.y + (r.chance(0.5) ? gap : -gap)};
        const point<double> u{v.x + filter_scale(r, s), v.y + filter_scale(r, s)};
        // Each end moved within e on each coordinate (k/8 of e, exactly).
        const auto moved = [&](const point<double>& p) {
            return test_exact::exact_point(Q(p.x) + Q(e) * Q(static_cast<int>(r.index(17)) - 8) / 8,
                                           Q(p.y) + Q(e) * Q(static_cast<int>(r.index(17)) - 8) / 8);
        };
        const bool meet = CGAL::do_intersect(exact_segment(moved(a), moved(b)), exact_segment(moved(u), moved(v)));
        const bool answer = segments_may_meet(a, b, u, v, e);
        if (meet) {
            ++meeting;
            INFO("scale 2^" << s << ", e " << e);
            CHECK(answer);
        }
        apart += answer ? 0 : 1;
    }
    CHECK(meeting > filter_at_least(500));
    CHECK(apart > filter_at_least(1000));

    // Named cases, e = 0.
    //   a-----b=u
    //          \        a shared end
    //           v
    CHECK(segments_may_meet({0, 0}, {2, 0}, {2, 0}, {3, 1}, 0));
    //   a====u====b====v   collinear, overlapping on [u, b]
    CHECK(segments_may_meet({0, 0}, {2, 0}, {1, 0}, {3, 0}, 0));
    //         v
    //         |
    //   a-----u-----b      u on the interior of [a, b] (a T)
    CHECK(segments_may_meet({0, 0}, {2, 0}, {1, 0}, {1, 1}, 0));
    //   a-----b  u-----v   collinear, 1 apart: no line of either separates
    //                      the other's ends, their boxes do: apart for e = 0
    //                      and e = 0.2 (2e < 1), maybe meeting for e = 0.6
    CHECK_FALSE(segments_may_meet({0, 0}, {1, 0}, {2, 0}, {3, 0}, 0));
    CHECK_FALSE(segments_may_meet({0, 0}, {1, 0}, {2, 0}, {3, 0}, 0.2));
    CHECK(segments_may_meet({0, 0}, {1, 0}, {2, 0}, {3, 0}, 0.6));
    //   a-----b            the same, apart by exactly 2e on x: may meet (the
    //          u-----v     exact ends, each moved by e, touch)
    CHECK(segments_may_meet({0, 0}, {1, 0}, {1.5, 0}, {3, 0}, 0.25));
    CHECK_FALSE(segments_may_meet({0, 0}, {1, 0}, {1.5, 0}, {3, 0}, 0.24));
    //             v
    //            /
    //           u          u and v both above the line of [a, b]: apart
    //   a-----b
    CHECK_FALSE(segments_may_meet({0, 0}, {1, 0}, {2, 0.5}, {3, 2}, 0));
    //   u-----v
    //                      parallel, 1 apart: apart for e = 0.2 (2e < 1),
    //   a-----b            maybe meeting for e = 0.6 (the exact ends may close the gap)
    CHECK_FALSE(segments_may_meet({0, 0}, {2, 0}, {0, 1}, {2, 1}, 0.2));
    CHECK(segments_may_meet({0, 0}, {2, 0}, {0, 1}, {2, 1}, 0.6));
    // Non-finite: may meet.
    CHECK(segments_may_meet({0, 0}, {1, 0}, {nan_value, 0}, {2, 0}, 0));
}

TEST_CASE("filters: segments_certainly_cross answers only segments whose every exact version within e crosses",
          "[filters]") {
    test_random::rng r(19);
    using test_exact::exact_segment;
    std::size_t crossing = 0, unsure = 0;
    for (int k = 0; k < filter_count(20000); ++k) {
        const int s = static_cast<int>(r.index(1200)) - 600;
        const double scale = std::ldexp(1.0, s);
        const double e = r.chance(0.2) ? 0 : scale * std::ldexp(1.0, -static_cast<int>(r.index(40)) - 2);
        const point<double> a{filter_scale(r, s), filter_scale(r, s)}, b{filter_scale(r, s), filter_scale(r, s)};
        // u and v about the line of [a, b], a few e off it or far from it;
        // sometimes an end of [u, v] on [a, b] itself.
        const point<double> on = near_line(r, a, b);
        const double gap = r.chance(0.5) ? r.uniform(0, 8) * e : filter_scale(r, s);
        const point<double> u{on.x + gap, on.y + (r.chance(0.5) ? gap : -gap)};
        const point<double> v = r.chance(0.1) ? on : point<double>{2 * on.x - u.x, 2 * on.y - u.y};
        const bool answer = segments_certainly_cross(a, b, u, v, e);
        if (!answer) {
            ++unsure;
            continue;
        }
        ++crossing;
        // Every end moved within e on each coordinate (k/8 of e, exactly),
        // and the corners of that square: the segments still meet.
        for (int trial = 0; trial < 4; ++trial) {
            const auto moved = [&](const point<double>& p) {
                const int i = trial < 2 ? (trial == 0 ? 8 : -8) : static_cast<int>(r.index(17)) - 8;
                const int j = trial < 2 ? (trial == 0 ? -8 : 8) : static_cast<int>(r.index(17)) - 8;
                return test_exact::exact_point(Q(p.x) + Q(e) * Q(i) / 8, Q(p.y) + Q(e) * Q(j) / 8);
            };
            INFO("scale 2^" << s << ", e " << e);
            CHECK(CGAL::do_intersect(exact_segment(moved(a), moved(b)), exact_segment(moved(u), moved(v))));
        }
    }
    CHECK(crossing > filter_at_least(1000));
    CHECK(unsure > filter_at_least(1000));
    // Named cases: a clear cross; a T (an end on the other segment) is not
    // certain; parallel; a cross closer than the slack for e = 0.3.
    CHECK(segments_certainly_cross({0, 0}, {2, 0}, {1, -1}, {1, 1}, 0));
    CHECK_FALSE(segments_certainly_cross({0, 0}, {2, 0}, {1, 0}, {1, 1}, 0));
    CHECK_FALSE(segments_certainly_cross({0, 0}, {2, 0}, {0, 1}, {2, 1}, 0));
    CHECK(segments_certainly_cross({0, 0}, {2, 0}, {1, -1}, {1, 1}, 0.01));
    CHECK_FALSE(segments_certainly_cross({0, 0}, {2, 0}, {1, -0.1}, {1, 1}, 0.3));
    CHECK_FALSE(segments_certainly_cross({0, 0}, {1, 0}, {nan_value, -1}, {0.5, 1}, 0));
}

TEST_CASE("filters: certainly_farther answers only points whose every exact version within e is farther than r",
          "[filters]") {
    test_random::rng r(24);
    std::size_t farther = 0, unsure = 0, close_calls = 0;
    // The exact least distance squared between a point within e of p and one
    // within e of q (on each coordinate): each axis's gap shrunk by 2e.
    const auto least2 = [](const point<double>& p, const point<double>& q, double e) -> Q {
        const auto gap = [&](double a, double b) -> Q {
            Q d = Q(a) - Q(b);
            if (d < 0) d = -d;
            d -= Q(2) * Q(e);
            return d > 0 ? d : Q(0);
        };
        const Q gx = gap(p.x, q.x), gy = gap(p.y, q.y);
        return gx * gx + gy * gy;
    };
    for (int k = 0; k < filter_count(20000); ++k) {
        // Scales from subnormal to near the top of the range.
        const int s = static_cast<int>(r.index(2000)) - 1070;
        // q sometimes at a smaller scale: p - q then rounds.
        const int t = r.chance(0.5) ? s : s - static_cast<int>(r.index(30));
        const point<double> p{filter_scale(r, s), filter_scale(r, s)}, q{filter_scale(r, t), filter_scale(r, t)};
        const double d = std::hypot(p.x - q.x, p.y - q.y);
        const double e = r.chance(0.3) ? 0 : std::ldexp(d, -static_cast<int>(r.index(60)) - 2);
        // r at the edge (d - 3e), near it (less up to 2^-40 of it), each then
        // moved a few ulps either way, or anywhere below d.
        const std::size_t where = r.index(3);
        double reach = where == 0   ? d - 3 * e
                       : where == 1 ? (d - 3 * e) * (1 - std::ldexp(r.unit(), -40))
                                    : d * r.unit();
        for (int n = static_cast<int>(r.index(9)) - 4; n != 0; n += n > 0 ? -1 : 1)
            reach = std::nextafter(reach, n > 0 ? infinity : -infinity);
        if (!(reach >= 0) || !std::isfinite(d)) continue;
        const bool answer = certainly_farther(p, q, reach, e);
        if (!answer) {
            ++unsure;
            continue;
        }
        ++farther;
        close_calls += reach > (d - 3 * e) * (1 - 0x1p-39) ? 1 : 0;
        INFO("scale 2^" << s << ", e " << e << ", r " << reach);
        CHECK(least2(p, q, e) > Q(reach) * Q(reach));
    }
    CHECK(farther > filter_at_least(1000));
    CHECK(unsure > filter_at_least(1000));
    CHECK(close_calls > filter_at_least(100));  // answers within 2^-39 of the edge were checked
    // Named cases: points 3 apart, r = 2 clear, r = 3 not; e = 0.2 leaves
    // 2.6 > 2, e = 0.4 leaves 3.2 (r + 3e) over 3; NaN and overflow answer
    // false.
    CHECK(certainly_farther({0, 0}, {3, 0}, 2, 0));
    CHECK_FALSE(certainly_farther({0, 0}, {3, 0}, 3, 0));
    CHECK(certainly_farther({0, 0}, {3, 0}, 2, 0.2));
    CHECK_FALSE(certainly_farther({0, 0}, {3, 0}, 2, 0.4));
    CHECK_FALSE(certainly_farther({0, 0}, {nan_value, 0}, 1, 0));
    CHECK_FALSE(certainly_farther({-DBL_MAX, 0}, {DBL_MAX, 0}, 1, 0));
    CHECK_FALSE(certainly_farther({0, 0}, {0x1p-1074, 0}, 0, 0));
}

TEST_CASE(
    "filters: discs_certainly_overlap answers only discs whose every exact centre within e lies nearer than "
    "the radii's sum",
    "[filters]") {
    test_random::rng r(25);
    std::size_t overlap = 0, unsure = 0, close_calls = 0;
    // The exact greatest distance squared between a point within e of p and
    // one within e of q (on each coordinate): each axis's gap grown by 2e.
    const auto most2 = [](const point<double>& p, const point<double>& q, double e) -> Q {
        const auto gap = [&](double a, double b) -> Q {
            Q d = Q(a) - Q(b);
            if (d < 0) d = -d;
            return d + Q(2) * Q(e);
        };
        const Q gx = gap(p.x, q.x), gy = gap(p.y, q.y);
        return gx * gx + gy * gy;
    };
    for (int k = 0; k < filter_count(20000); ++k) {
        // Scales from subnormal to near the top of the range.
        const int sc = static_cast<int>(r.index(2000)) - 1070;
        // q sometimes at a smaller scale: p - q then rounds.
        const int t = r.chance(0.5) ? sc : sc - static_cast<int>(r.index(30));
        const point<double> p{filter_scale(r, sc), filter_scale(r, sc)}, q{filter_scale(r, t), filter_scale(r, t)};
        const double d = std::hypot(p.x - q.x, p.y - q.y);
        const double e = r.chance(0.3) ? 0 : std::ldexp(d, -static_cast<int>(r.index(60)) - 2);
        // The radii's sum at the edge (d + 3e), near it (more by up to 2^-40
        // of it), each then moved a few ulps either way, or anywhere above d;
        // split in two at random (the split rounds too).
        const std::size_t where = r.index(3);
        double sum = where == 0   ? d + 3 * e
                     : where == 1 ? (d + 3 * e) * (1 + std::ldexp(r.unit(), -40))
                                  : d * (1 + 4 * r.unit());
        for (int n = static_cast<int>(r.index(9)) - 4; n != 0; n += n > 0 ? -1 : 1)
            sum = std::nextafter(sum, n > 0 ? infinity : -infinity);
        const double first = sum * r.unit(), second = sum - first;
        if (!(first > 0) || !(second > 0) || !std::isfinite(d) || !std::isfinite(sum)) continue;
        const bool answer = discs_certainly_overlap(p, first, q, second, e);
        if (!answer) {
            ++unsure;
            continue;
        }
        ++overlap;
        close_calls += first + second < (d + 3 * e) * (1 + 0x1p-39) ? 1 : 0;
        INFO("scale 2^" << sc << ", e " << e << ", radii " << first << " " << second);
        CHECK(most2(p, q, e) < (Q(first) + Q(second)) * (Q(first) + Q(second)));
    }
    CHECK(overlap > filter_at_least(1000));
    CHECK(unsure > filter_at_least(1000));
    CHECK(close_calls > filter_at_least(100));  // answers within 2^-39 of the edge were checked
    // Named cases: centres 3 apart, radii 2 and 2 overlap, 1 and 2 touch
    // (not strictly nearer: false); e = 0.2 leaves 3.6 < 4, e = 0.4 leaves
    // 4.2 (3 + 3e) over 4; a radius of 0, NaN and overflow answer false.
    CHECK(discs_certainly_overlap({0, 0}, 2, {3, 0}, 2, 0));
    CHECK_FALSE(discs_certainly_overlap({0, 0}, 1, {3, 0}, 2, 0));
    CHECK(discs_certainly_overlap({0, 0}, 2, {3, 0}, 2, 0.2));
    CHECK_FALSE(discs_certainly_overlap({0, 0}, 2, {3, 0}, 2, 0.4));
    CHECK_FALSE(discs_certainly_overlap({0, 0}, 0, {0, 0}, 2, 0));
    CHECK_FALSE(discs_certainly_overlap({0, 0}, 2, {nan_value, 0}, 2, 0));
    CHECK_FALSE(discs_certainly_overlap({-DBL_MAX, 0}, DBL_MAX, {DBL_MAX, 0}, DBL_MAX, 0));
}

TEST_CASE("filters: box_may_be_near_line never drops a box within g of the line", "[filters]") {
    test_random::rng r(10);
    std::size_t near = 0, far = 0;
    for (int k = 0; k < filter_count(20000); ++k) {
        const int s = static_cast<int>(r.index(1200)) - 600;
        const double x0 = filter_scale(r, s), y0 = filter_scale(r, s);
        const box bx{x0, y0, x0 + std::ldexp(r.unit(), s - static_cast<int>(r.index(10))),
                     y0 + std::ldexp(r.unit(), s - static_cast<int>(r.index(10)))};
        point<double> u{filter_scale(r, s), filter_scale(r, s)}, v{filter_scale(r, s), filter_scale(r, s)};
        if (r.chance(0.3)) {
            // The line just past a corner.
            const point<double> c{r.chance(0.5) ? bx.min_x : bx.max_x, r.chance(0.5) ? bx.min_y : bx.max_y};
            u = {c.x + filter_scale(r, s), c.y + filter_scale(r, s)};
            v = near_line(r, u, c);
        }
        const double g = r.chance(0.2) ? 0.0 : std::ldexp(r.unit(), s - static_cast<int>(r.index(20)));
        // Exact: the box is within g of the line when the corners are not all
        // strictly on one side, or the nearest corner is within g.
        const point<double> corners[4] = {
            {bx.min_x, bx.min_y}, {bx.max_x, bx.min_y}, {bx.min_x, bx.max_y}, {bx.max_x, bx.max_y}};
        int side = 0;
        bool crossed = false;
        Q nearest = -1;
        for (const point<double>& c : corners) {
            const Q o = exact_side(u, v, c);
            const int sg = sign_of(o);
            if (sg == 0 || (side != 0 && sg != side)) crossed = true;
            side = sg;
            if (nearest < 0 || CGAL::abs(o) < nearest) nearest = CGAL::abs(o);
        }
        const Q length2 = (Q(v.x) - u.x) * (Q(v.x) - u.x) + (Q(v.y) - u.y) * (Q(v.y) - u.y);
        const bool within = crossed || nearest * nearest <= Q(g) * g * length2;
        const bool answer = box_may_be_near_line(bx, u, v, g);
        if (within) {
            ++near;
            INFO("scale 2^" << s << ", g " << g);
            CHECK(answer);
        }
        far += answer ? 0 : 1;
    }
    CHECK(near > filter_at_least(1000));
    CHECK(far > filter_at_least(1000));
    // Named cases.
    //   +--+  |          the box [0,1]^2 and the line x = 2: 1 apart
    //   |  |  |
    //   +--+  |
    CHECK_FALSE(box_may_be_near_line({0, 0, 1, 1}, {2, -1}, {2, 5}, 0.5));
    CHECK(box_may_be_near_line({0, 0, 1, 1}, {2, -1}, {2, 5}, 1));  // exactly g away: kept
    //   +--+
    //   | /|             a line through the box
    //   +--+
    CHECK(box_may_be_near_line({0, 0, 1, 1}, {0, 0}, {1, 1}, 0));
    //   u=v              no line: kept
    CHECK(box_may_be_near_line({0, 0, 1, 1}, {5, 5}, {5, 5}, 0));
}

TEST_CASE("filters: disc_reaches_left only when a point of the disc lies left of every line the points may make",
          "[filters]") {
    // Exact reference: the disc of radius rho about c* has a point strictly
    // left of the line p* q* when (q* - p*) x (c* - p*) > -rho |q* - p*|,
    // checked at random corners of the points' error boxes in rationals.
    test_random::rng r(12);
    std::size_t reached = 0, beyond_centre = 0;
    for (int k = 0; k < filter_count(20000); ++k) {
        const int s = static_cast<int>(r.index(1000)) - 500;
        const point<double> p{filter_scale(r, s), filter_scale(r, s)};
        // Directions near a diagonal half of the time: there |d|_1 = sqrt 2 |d|_2 and
        // the reach is tightest.
        const double angle = r.chance(0.5)
                                 ? r.uniform(-3.2, 3.2)
                                 : 0.785398 * static_cast<double>(2 * r.index(4) + 1) + r.uniform(-1e-3, 1e-3);
        const double length = std::ldexp(r.uniform(0.5, 1), s);
        const point<double> q{p.x + length * std::cos(angle), p.y + length * std::sin(angle)};
        const double rho = r.chance(0.1) ? 0.0 : length * r.uniform(0.01, 2);
        // c right of the line at about rho (within 3%), along the edge.
        const double t = r.uniform(-1, 2), gap = rho * r.uniform(0.97, 1.03) + length * r.uniform(-1e-3, 1e-3);
        const point<double> c{p.x + t * (q.x - p.x) + gap * std::sin(angle),
                              p.y + t * (q.y - p.y) - gap * std::cos(angle)};
        // Errors from none to a sixteenth of the edge's length.
        const int e_low = r.chance(0.5) ? 4 : 20;
        const double ep = r.chance(0.3) ? 0.0 : std::ldexp(r.unit(), s - e_low - static_cast<int>(r.index(30)));
        const double er = r.chance(0.3) ? 0.0 : std::ldexp(r.unit(), s - e_low - static_cast<int>(r.index(30)));
        const double spread =
            1.5 * (std::fabs(c.x - p.x) + std::fabs(c.y - p.y) + std::fabs(q.x - p.x) + std::fabs(q.y - p.y));
        const double dx = q.x - p.x, dy = q.y - p.y;
        const bool answer = disc_reaches_left(p, dx, dy, c, rho, ep, side_slack(ep, er, spread).of(dx, dy));
        if (!answer) continue;
        ++reached;
        beyond_centre += exact_side(p, q, c) < 0 ? 1 : 0;
        for (int corner = 0; corner < 16; ++corner) {
            const auto moved = [&](const point<double>& x, double e) {
                return point<Q>{Q(x.x) + (r.chance(0.5) ? Q(e) : Q(-e)), Q(x.y) + (r.chance(0.5) ? Q(e) : Q(-e))};
            };
            const point<Q> ps = moved(p, ep), qs = moved(q, ep), cs = moved(c, er);
            const Q ddx = qs.x - ps.x, ddy = qs.y - ps.y;
            const Q o = ddx * (cs.y - ps.y) - ddy * (cs.x - ps.x);
            const bool left = o > 0 || (rho > 0 && o * o < Q(rho) * Q(rho) * (ddx * ddx + ddy * ddy));
            INFO("scale 2^" << s << ", rho " << rho << ", ep " << ep << ", er " << er);
            CHECK(left);
        }
    }
    // Not vacuous: many answers, most of them with c itself right of the line.
    CHECK(reached > filter_at_least(2000));
    CHECK(beyond_centre > filter_at_least(1000));
    // NaN: no answer.
    CHECK_FALSE(disc_reaches_left({0, 0}, 1, 0, {0, nan_value}, 1, 0, 0));
    CHECK_FALSE(disc_reaches_left({0, 0}, 1, 0, {0, -0.5}, nan_value, 0, 0));
    // The unit disc about (0, -0.5) crosses the x axis; about (0, -2) it does not.
    CHECK(disc_reaches_left({0, 0}, 1, 0, {0, -0.5}, 1, 0, 0));
    CHECK_FALSE(disc_reaches_left({0, 0}, 1, 0, {0, -2}, 1, 0, 0));
    // An edge from (0, 0) to (1, 1) whose ends are known within 1: both may
    // be (0.5, 0.5), a line of no direction, left of which nothing lies. A
    // disc of radius 100 about a centre just below the slack lies across
    // the line of the doubles themselves, not across every line the points
    // may make: no.
    const double slack = side_slack(1, 0, 4).of(1, 1);
    const point<double> centre{0, std::nextafter(slack, 0.0)};
    REQUIRE(centre.y > 0);
    CHECK_FALSE(disc_reaches_left({0, 0}, 1, 1, centre, 100, 1, slack));
}

TEST_CASE("filters: box_may_be_near_line drops a box only where certain_side puts all four corners on one side",
          "[filters]") {
    // The one-pass test against its definition: certain_side at each corner.
    test_random::rng r(11);
    std::size_t dropped = 0, dropped_by_corners = 0;
    for (int k = 0; k < filter_count(100000); ++k) {
        const int s = static_cast<int>(r.index(1200)) - 600;
        const double x0 = filter_scale(r, s), y0 = filter_scale(r, s);
        const box bx{x0, y0, x0 + std::ldexp(r.unit(), s - static_cast<int>(r.index(30))),
                     y0 + std::ldexp(r.unit(), s - static_cast<int>(r.index(30)))};
        const point<double> u{filter_scale(r, s), filter_scale(r, s)};
        const point<double> v =
            r.chance(0.2) ? near_line(r, u, {x0, y0}) : point<double>{filter_scale(r, s), filter_scale(r, s)};
        const double g = r.chance(0.2) ? 0.0 : std::ldexp(r.unit(), s - static_cast<int>(r.index(40)));
        const double dx = v.x - u.x, dy = v.y - u.y, slack = g * (std::fabs(dx) + std::fabs(dy));
        int side = 0;
        bool apart = true;
        for (double x : {bx.min_x, bx.max_x})
            for (double y : {bx.min_y, bx.max_y}) {
                const int c = certain_side(u, dx, dy, {x, y}, slack);
                apart = apart && c != 0 && (side == 0 || c == side);
                side = c;
            }
        const bool kept = box_may_be_near_line(bx, u, v, g);
        INFO("scale 2^" << s << ", g " << g);
        if (!kept) CHECK(apart);
        dropped += kept ? 0 : 1;
        dropped_by_corners += apart ? 1 : 0;
    }
    // Its one bound is at least each corner's, and differs by 2^-48 of the
    // terms at most: it keeps almost nothing that the corners would drop.
    CHECK(dropped > filter_at_least(10000));
    CHECK(dropped_by_corners - dropped <= dropped_by_corners / 1000);
    // Coordinates that are not finite: kept.
    CHECK(box_may_be_near_line({0, 0, 1, 1}, {2, nan_value}, {2, 5}, 0.5));
    CHECK(box_may_be_near_line({0, 0, 1, 1}, {2, -1}, {2, 5}, nan_value));
    CHECK(box_may_be_near_line({0, 0, HUGE_VAL, 1}, {2, -1}, {2, 5}, 0.5));
    // A vertical line (dx = 0) and an infinite height: 0 times infinity at
    // two corners, NaN, whatever min and max would make of it.
    CHECK(box_may_be_near_line({0, 0, 1, HUGE_VAL}, {2, -1}, {2, 5}, 0.5));
    CHECK(box_may_be_near_line({0, 0, 1, 1}, {DBL_MAX, -DBL_MAX}, {-DBL_MAX, DBL_MAX}, 0.5));
}

namespace {

/// An NT value exactly as a rational (a long double as the sum of two doubles).
Q to_exact(float x) { return Q(static_cast<double>(x)); }
Q to_exact(double x) { return Q(x); }
Q to_exact(long double x) {
    const double hi = static_cast<double>(x);
    return Q(hi) + Q(static_cast<double>(x - static_cast<long double>(hi)));
}
Q to_exact(const exact_rational& x) { return x; }

/// posing_margin<NT> bounds, per coordinate, the distance between points
/// posed in double and in NT, for terms summing to at most the scale.
template <class NT>
void check_posing_margin(int lowest, int highest, std::uint64_t seed) {
    test_random::rng r(seed);
    for (int k = 0; k < filter_count(5000); ++k) {
        const int e = lowest + static_cast<int>(r.index(static_cast<std::size_t>(highest - lowest + 1)));
        const int t =
            r.chance(0.5) ? e : lowest + static_cast<int>(r.index(static_cast<std::size_t>(highest - lowest + 1)));
        const point<double> q{filter_scale(r, e), filter_scale(r, e)};
        const pose p{filter_scale(r, t), filter_scale(r, t), r.uniform(-10, 10)};
        const rotation_pose rp(p);
        const point<double> in_double = rp.apply<double>(q);
        const point<NT> in_nt = rp.apply<NT>(q);
        const double scale = std::fabs(q.x) + std::fabs(q.y) + std::fabs(p.tx) + std::fabs(p.ty);
        const Q margin(posing_margin<NT>(scale));
        INFO("q at 2^" << e << ", translation at 2^" << t);
        CHECK(CGAL::abs(Q(in_double.x) - to_exact(in_nt.x)) < margin);
        CHECK(CGAL::abs(Q(in_double.y) - to_exact(in_nt.y)) < margin);
    }
}

}  // namespace

TEST_CASE("filters: posing_margin covers the posing in double against the posing in NT", "[filters]") {
    check_posing_margin<float>(-60, 60, 21);
    check_posing_margin<double>(-1070, 1000, 22);
    check_posing_margin<long double>(-1070, 1000, 23);
    check_posing_margin<exact_rational>(-1070, 1000, 24);
    // The margin is NT's filter slack times the scale, widened.
    CHECK(posing_margin<double>(1) > 4 * 0x1p-53);
    CHECK(posing_margin<double>(0) > 0);  // coordinates that underflow
}
