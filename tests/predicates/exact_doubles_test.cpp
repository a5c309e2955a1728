// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/exact_doubles.hpp"
#include "support/random.hpp"

namespace {

using influence2d::exact_rational;
using influence2d::point;

exact_rational q(double x) { return exact_rational(x); }

/// The sign of d x (a - v - t), d = to - from, in exact rationals.
int side_reference(point<double> from, point<double> to, point<double> a, point<double> v, point<double> t) {
    const exact_rational dx = q(to.x) - q(from.x), dy = q(to.y) - q(from.y);
    const exact_rational wx = q(a.x) - q(v.x) - q(t.x), wy = q(a.y) - q(v.y) - q(t.y);
    return static_cast<int>(CGAL::sign(dx * wy - dy * wx));
}

/// The sign of d . ((a - v) - (a2 - v2)), d = to - from, in exact rationals.
int offsets_reference(point<double> from, point<double> to, point<double> a, point<double> v, point<double> a2,
                      point<double> v2) {
    const exact_rational dx = q(to.x) - q(from.x), dy = q(to.y) - q(from.y);
    const exact_rational gx = q(a.x) - q(v.x) - q(a2.x) + q(v2.x), gy = q(a.y) - q(v.y) - q(a2.y) + q(v2.y);
    return static_cast<int>(CGAL::sign(dx * gx + dy * gy));
}

/// Random doubles of one scale (within 100) or of mixed scales from 2^-60
/// to 2^60, and a double moved by a unit in its last place or not.
struct random_doubles {
    test_random::rng g;
    explicit random_doubles(std::uint64_t seed) : g(seed) {}
    double coordinate(bool mixed) {
        const double x = g.uniform(-100, 100);
        return mixed ? std::ldexp(x, static_cast<int>(g.index(121)) - 60) : x;
    }
    point<double> any_point(bool mixed) {
        const double x = coordinate(mixed);
        return {x, coordinate(mixed)};
    }
    double nudged(double x) { return g.chance(0.5) ? x : std::nextafter(x, g.chance(0.5) ? 1e300 : -1e300); }
};

}  // namespace

TEST_CASE("exact doubles: a translated point's side and offsets along a motion against exact rationals",
          "[exact_doubles]") {
    // Coordinates of one scale (where the differences are doubles and the
    // 128-bit orientation answers) and of mixed scales from 2^-60 to 2^60
    // (where they round and the twelve or sixteen products are summed);
    // half the cases built to be 0 exactly: a = v + t with d along it, or
    // equal offsets, then one coordinate moved by a unit in its last place.
    random_doubles r(0x51de);
    test_random::rng& g = r.g;
    int zeros = 0, checked = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const bool mixed = trial % 2 == 1;
        point<double> from = g.chance(0.5) ? point<double>{0, 0} : r.any_point(mixed), to = r.any_point(mixed);
        point<double> a = r.any_point(mixed), v = r.any_point(mixed), t = r.any_point(mixed);
        if (g.chance(0.5)) {
            // a shared vertex (a = v) translated along the motion: t = -k d.
            v = a;
            const double k = g.chance(0.5) ? 1 : 0.5;
            t = {-k * (to.x - from.x), -k * (to.y - from.y)};
            t = {r.nudged(t.x), r.nudged(t.y)};
        }
        INFO("trial " << trial);
        const int side = influence2d::exact_translated_side(from, to, a, v, t);
        CHECK(side == side_reference(from, to, a, v, t));
        point<double> a2 = r.any_point(mixed), v2 = r.any_point(mixed);
        if (g.chance(0.5)) {
            // the same offset: a2 - v2 = a - v, a2 moved by a shift.
            const point<double> shift = r.any_point(false);
            a2 = {a.x + shift.x, a.y + shift.y};
            v2 = {v.x + shift.x, v.y + shift.y};
            a2 = {r.nudged(a2.x), r.nudged(a2.y)};
        }
        const int along = influence2d::exact_offsets_along(from, to, a, v, a2, v2);
        CHECK(along == offsets_reference(from, to, a, v, a2, v2));
        zeros += (side == 0) + (along == 0);
        checked += 2;
    }
    // Both branches of each predicate ran, zeros among them.
    INFO(zeros << " zeros of " << checked);
    CHECK(zeros > checked / 20);
}

TEST_CASE("exact doubles: a side decided below a unit in the last place", "[exact_doubles]") {
    // B's vertex v = a shared with A, B translated back by t = -d: its line
    // of motion holds a exactly (0); t one unit in its last place off that:
    // the side's sign follows the unit's.
    const point<double> d{0.1, 0.7}, a{-78.3, 35.9};
    CHECK(influence2d::exact_translated_side({0, 0}, d, a, a, {-d.x, -d.y}) == 0);
    CHECK(influence2d::exact_translated_side({0, 0}, d, a, a, {std::nextafter(-d.x, 1.0), -d.y}) == 1);
    CHECK(influence2d::exact_translated_side({0, 0}, d, a, a, {std::nextafter(-d.x, -1.0), -d.y}) == -1);
    // The same motion given as the difference of two far points.
    const point<double> from{1e6, -1e6}, to{1e6 + d.x, -1e6 + d.y};
    const point<double> dd{to.x - from.x, to.y - from.y};
    CHECK(influence2d::exact_translated_side(from, to, a, a, {-dd.x, -dd.y}) ==
          side_reference(from, to, a, a, {-dd.x, -dd.y}));
    // Offsets equal to the last bit, and one unit apart.
    const point<double> v{-78.25, 35.875}, a2{-77.0, 36.5};
    const point<double> v2{a2.x - (a.x - v.x), a2.y - (a.y - v.y)};
    CHECK(influence2d::exact_offsets_along({0, 0}, d, a, v, a2, v2) == 0);
    CHECK(influence2d::exact_offsets_along({0, 0}, d, a, v, a2, {std::nextafter(v2.x, 0.0), v2.y}) ==
          offsets_reference({0, 0}, d, a, v, a2, {std::nextafter(v2.x, 0.0), v2.y}));
}

TEST_CASE("exact doubles: two offsets equal to the last bit", "[exact_doubles]") {
    // Equal offsets of points of one scale and of mixed scales, and one
    // coordinate moved by a unit in its last place, against exact rationals.
    test_random::rng g(0x0ff5);
    int equal = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const bool mixed = trial % 2 == 1;
        const auto coordinate = [&] {
            const double x = g.uniform(-100, 100);
            return mixed ? std::ldexp(x, static_cast<int>(g.index(81)) - 40) : x;
        };
        const point<double> a{coordinate(), coordinate()}, v{coordinate(), coordinate()};
        const point<double> shift{coordinate(), coordinate()};
        point<double> a2{a.x + shift.x, a.y + shift.y}, v2{v.x + shift.x, v.y + shift.y};
        if (g.chance(0.5)) a2.y = std::nextafter(a2.y, 1e300);
        const bool expected = q(a.x) - q(v.x) == q(a2.x) - q(v2.x) && q(a.y) - q(v.y) == q(a2.y) - q(v2.y);
        INFO("trial " << trial);
        CHECK(influence2d::same_offset(a, v, a2, v2) == expected);
        equal += expected ? 1 : 0;
    }
    CHECK(equal > 100);
    CHECK(influence2d::same_offset({3.765, 64.05}, {3.765, 64.05}, {6.275, 67.35}, {6.275, 67.35}));
    CHECK_FALSE(
        influence2d::same_offset({3.765, 64.05}, {3.765, 64.05}, {6.275, 67.35}, {6.275, std::nextafter(67.35, 0.0)}));
}

TEST_CASE("exact doubles: the cross sign of two directions, nearly parallel, against exact rationals",
          "[exact_doubles]") {
    // (b - a) x (d - c): decided in double past its bound, else by the exact
    // sum. Half the cases parallel before one coordinate moves by a unit in
    // its last place (or none), at one scale and at mixed scales from 2^-60
    // to 2^60, where the rounded cross product often has the wrong sign.
    random_doubles r(0xc2055);
    test_random::rng& g = r.g;
    int zeros = 0, rounded_wrong = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const bool mixed = trial % 2 == 1;
        const point<double> a = r.any_point(mixed), b = r.any_point(mixed), c = r.any_point(mixed);
        point<double> d = r.any_point(mixed);
        if (g.chance(0.75)) {
            // d - c along b - a, scaled by a power of two or by 3.
            const double k = g.chance(0.5) ? std::ldexp(1.0, static_cast<int>(g.index(9)) - 4) : 3.0;
            d = {r.nudged(c.x + k * (b.x - a.x)), r.nudged(c.y + k * (b.y - a.y))};
        }
        const exact_rational cross = (q(b.x) - q(a.x)) * (q(d.y) - q(c.y)) - (q(b.y) - q(a.y)) * (q(d.x) - q(c.x));
        const int reference = static_cast<int>(CGAL::sign(cross));
        INFO("trial " << trial);
        const int sign = influence2d::exact_cross_sign(a, b, c, d);
        CHECK(sign == reference);
        const double rounded = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x);
        rounded_wrong += (rounded > 0) - (rounded < 0) != reference;
        zeros += reference == 0;
    }
    // Cases the double evaluation alone gets wrong were asked, and exact 0s.
    INFO(zeros << " zeros, " << rounded_wrong << " rounded to the wrong sign");
    CHECK(zeros > 200);
    CHECK(rounded_wrong > 200);
}

TEST_CASE("exact doubles: closed segments meet, points and collinear overlaps included, against exact rationals",
          "[exact_doubles]") {
    // Ends on a small grid scaled by 1/3 rounded (collinear points seldom
    // axis-aligned, their doubles seldom on one exact line), or a third of
    // the time c and d on the line of a and b (a and b on a grid of
    // quarters, c and d at half-integer multiples of b - a from a: exact);
    // a quarter of the segments of length 0. So crossings, touching ends,
    // collinear overlaps and gaps, points on and off segments. The
    // reference: orientations and extents in exact rationals.
    test_random::rng g(0x5e6);
    const auto grid = [&g](double unit) {
        return point<double>{static_cast<double>(g.index(7)) / unit, static_cast<double>(g.index(7)) / unit};
    };
    const auto orient = [](point<double> a, point<double> b, point<double> c) {
        return static_cast<int>(
            CGAL::sign((q(b.x) - q(a.x)) * (q(c.y) - q(a.y)) - (q(b.y) - q(a.y)) * (q(c.x) - q(a.x))));
    };
    // Whether c lies on the closed segment [a, b] (a == b: the point a).
    const auto on = [&](point<double> c, point<double> a, point<double> b) {
        return orient(a, b, c) == 0 && std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) &&
               std::min(a.y, b.y) <= c.y && c.y <= std::max(a.y, b.y);
    };
    int met = 0, points = 0, collinear = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const bool along = trial % 3 == 0;
        const point<double> a = grid(along ? 4 : 3), b = g.chance(0.25) ? a : grid(along ? 4 : 3);
        const auto on_line = [&] {
            const double k = (static_cast<double>(g.index(9)) - 2) / 2;
            return point<double>{a.x + k * (b.x - a.x), a.y + k * (b.y - a.y)};
        };
        const point<double> c = along ? on_line() : grid(3);
        const point<double> d = g.chance(0.25) ? c : along ? on_line() : grid(3);
        bool want;
        if (a == b || c == d) {
            want = a == b ? on(a, c, d) : on(c, a, b);
            ++points;
        } else {
            const int oc = orient(a, b, c), od = orient(a, b, d), oa = orient(c, d, a), ob = orient(c, d, b);
            if (oc == 0 && od == 0) {
                want = on(c, a, b) || on(d, a, b) || on(a, c, d) || on(b, c, d);
                ++collinear;
            } else {
                want = oc * od <= 0 && oa * ob <= 0;
            }
        }
        INFO("trial " << trial);
        CHECK(influence2d::segments_meet_exactly(a, b, c, d) == want);
        CHECK(influence2d::segments_meet_exactly(c, d, b, a) == want);
        met += want;
    }
    INFO(met << " meeting, " << points << " with a point, " << collinear << " collinear");
    CHECK(met > 4000);
    CHECK(points > 4000);
    CHECK(collinear > 500);
}
