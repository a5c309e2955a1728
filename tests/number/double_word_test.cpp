// SPDX-License-Identifier: BSL-1.0
// The double-word number type: its bound contains the exact value of the same
// operations (quotients included), a sign it gives is the exact sign, a value
// beyond its kept range is unknown, and certain_nearest gives the double
// nearest to the exact value (MPFR's rounding of the exact rational) or
// nothing.
//
// Every value is computed twice, in double_word and in exact rationals, over
// random chains of +, -, * and / of depth up to 6 on doubles of many
// magnitudes, with subexpressions reused so that chains cancel; then on the
// separation's own formulas (a posed point's distance to a segment, its
// projection, the crossing of two segments) near degeneracy.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/core/pose.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/double_word.hpp"
#include "influence2d/predicates/certain_nearest.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "support/exact_regions.hpp"
#include "support/number_chains.hpp"
#include "support/random.hpp"

namespace {

using namespace influence2d;

/// A value in double_word and the exact rational of the same operations
/// (none when a divisor was exactly 0).
struct word_tracked {
    double_word w;
    exact_rational x;
    bool defined = true;
};

word_tracked word_leaf(double v) { return {double_word(v), exact_rational(v)}; }
word_tracked operator+(const word_tracked& a, const word_tracked& b) {
    return {a.w + b.w, a.x + b.x, a.defined && b.defined};
}
word_tracked operator-(const word_tracked& a, const word_tracked& b) {
    return {a.w - b.w, a.x - b.x, a.defined && b.defined};
}
word_tracked operator*(const word_tracked& a, const word_tracked& b) {
    return {a.w * b.w, a.x * b.x, a.defined && b.defined};
}
word_tracked operator/(const word_tracked& a, const word_tracked& b) {
    if (!b.defined || CGAL::is_zero(b.x)) return {a.w / b.w, exact_rational(0), false};
    return {a.w / b.w, a.x / b.x, a.defined};
}

std::string show_word(const word_tracked& t) {
    std::ostringstream o;
    o.precision(17);
    o << "hi " << t.w.hi() << ", lo " << t.w.lo() << ", bound " << t.w.error() << ", exact ~"
      << (t.defined ? CGAL::to_double(t.x) : NAN);
    return o.str();
}

/// What the checks saw, and the first violation.
struct word_tally {
    std::size_t values = 0, known = 0, certain = 0, rounded = 0, unknown = 0, violations = 0;
    std::string first;

    void fail(const std::string& what, const word_tracked& t) {
        if (violations++ == 0) first = what + ": " + show_word(t);
    }

    /// For a known value: the bound holds (decided in exact rationals), the
    /// words are normalised, a certain sign is the exact sign (sign() agrees
    /// with try_sign), and a certain rounding is the nearest double. An
    /// unknown value has no certain sign and no rounding.
    void check(const word_tracked& t) {
        ++values;
        int s = 0;
        const bool is_certain = t.w.try_sign(s);
        bool threw = false;
        int from_sign = 0;
        try {
            from_sign = t.w.sign();
        } catch (const uncertain_sign&) {
            threw = true;
        }
        if (threw == is_certain || (is_certain && from_sign != s)) fail("sign() disagrees with try_sign()", t);
        double nearest = 0;
        const bool has_nearest = certain_nearest(t.w, nearest);
        if (!t.w.known()) {
            ++unknown;
            if (is_certain || has_nearest) fail("a sign or a rounding of an unknown value", t);
            return;
        }
        if (!t.defined) {
            fail("a quotient by an exact 0 is known", t);
            return;
        }
        ++known;
        if (!(t.w.error() >= 0)) fail("negative bound", t);
        if (t.w.hi() + t.w.lo() != t.w.hi()) fail("words not normalised", t);
        const exact_rational diff = t.x - (exact_rational(t.w.hi()) + exact_rational(t.w.lo()));
        if (CGAL::abs(diff) > exact_rational(t.w.error())) fail("exact value outside the bound", t);
        if (is_certain) {
            ++certain;
            if (s != static_cast<int>(CGAL::sign(t.x))) fail("certain sign differs from the exact sign", t);
        }
        if (has_nearest) {
            ++rounded;
            if (nearest != test_exact::nearest_double(t.x)) fail("certain rounding is not the nearest double", t);
        }
    }
};

using test_random::rng;

point<word_tracked> word_pose_point(const rotation_pose& t, const point<double>& q) {
    const point<double_word> w = t.apply<double_word>(q);
    const point<exact_rational> x = t.apply<exact_rational>(q);
    return {{w.x, x.x}, {w.y, x.y}};
}

}  // namespace

TEST_CASE("double_word: the bound contains the exact value on random chains of +, -, * and /", "[double_word]") {
    rng r(0xd0b1e3c7ULL);
    word_tally t;
    test_chains::chain_builder<word_tracked, word_tally, true> chains(r, t, word_leaf);
    for (int k = 0; k < 6000; ++k) chains.run(1 + k % 6);
    INFO(t.first);
    CHECK(t.violations == 0);
    INFO("values " << t.values << ", known " << t.known << ", certain " << t.certain << ", rounded " << t.rounded
                   << ", unknown " << t.unknown);
    CHECK(t.values > 50000);
    CHECK(t.known > t.values / 3);
    CHECK(t.certain > t.known / 2);
    CHECK(t.rounded > t.known / 2);
    CHECK(t.unknown > 1000);
}

TEST_CASE("double_word: distances, projections and crossings of posed points, near degeneracy", "[double_word]") {
    rng r(0x5e9a7d11ULL);
    word_tally t;
    for (int k = 0; k < 3000; ++k) {
        const int scale = std::vector<int>{-150, -20, 0, 20, 150}[r.index(5)];
        const double mag = std::ldexp(1.0, scale);
        const rotation_pose q(pose{mag * r.signed_unit(), mag * r.signed_unit(), 7 * r.signed_unit()});
        const point<double> b0{mag * r.signed_unit(), mag * r.signed_unit()};
        const point<double> b1{mag * r.signed_unit(), mag * r.signed_unit()};
        const point<word_tracked> u = word_pose_point(q, b0), v = word_pose_point(q, b1);
        // A's edge passing near the posed point u, down to 2^-60 of the
        // coordinates: the cancellation the bound must follow.
        const double gap = std::ldexp(1.0, -static_cast<int>(r.index(60)));
        const point<double> a0{CGAL::to_double(u.x.x) + gap * mag, CGAL::to_double(u.y.x) - mag * r.unit()};
        const point<double> a1{a0.x + mag * r.signed_unit(), a0.y + mag * (1 + r.unit())};
        const point<word_tracked> a{word_leaf(a0.x), word_leaf(a0.y)}, b{word_leaf(a1.x), word_leaf(a1.y)};
        const word_tracked abx = b.x - a.x, aby = b.y - a.y, apx = u.x - a.x, apy = u.y - a.y;
        const word_tracked dot = abx * apx + aby * apy, length2 = abx * abx + aby * aby, cross = abx * apy - aby * apx;
        const word_tracked f = dot / length2;
        for (const word_tracked& x : {abx, apx, apy, dot, length2, cross, cross * cross / length2, f, a.x + f * abx,
                                      a.y + f * aby, apx * apx + apy * apy})
            t.check(x);
        // The crossing of [a, b] and [u, v]: u + (c_u / (c_u - c_v))(v - u).
        const word_tracked cu = abx * (u.y - a.y) - aby * (u.x - a.x), cv = abx * (v.y - a.y) - aby * (v.x - a.x);
        const word_tracked g = cu / (cu - cv);
        t.check(u.x + g * (v.x - u.x));
        t.check(u.y + g * (v.y - u.y));
    }
    INFO(t.first);
    CHECK(t.violations == 0);
    INFO("values " << t.values << ", known " << t.known << ", rounded " << t.rounded);
    CHECK(t.known > t.values * 9 / 10);
    CHECK(t.rounded > t.known * 2 / 3);
}

TEST_CASE("double_word: exact operations, the kept range, and rounding at a midpoint", "[double_word]") {
    // Sums and products of two doubles are exact.
    const double_word s = double_word(1.0) + double_word(0x1p-80);
    CHECK(s.error() == 0);
    CHECK(s.hi() == 1.0);
    CHECK(s.lo() == 0x1p-80);
    const double_word p = double_word(1 + 0x1p-30) * double_word(1 - 0x1p-30);
    CHECK(p.error() == 0);
    CHECK(p.hi() == 1.0);
    CHECK(p.lo() == -0x1p-60);
    // 1 + 2^-53 is the midpoint between 1 and its successor: not settled,
    // while a hair above or below it is.
    double n = 0;
    CHECK_FALSE(certain_nearest(double_word(1.0) + double_word(0x1p-53), n));
    CHECK(certain_nearest(double_word(1.0) + double_word(0x1p-53) + double_word(0x1p-90), n));
    CHECK(n == 1 + 0x1p-52);
    CHECK(certain_nearest(double_word(1.0) + double_word(0x1p-53) - double_word(0x1p-90), n));
    CHECK(n == 1.0);
    // Below 2 the gap halves: 2 - 2^-53 is the midpoint below 2.
    CHECK_FALSE(certain_nearest(double_word(2.0) - double_word(0x1p-53), n));
    CHECK(certain_nearest(double_word(2.0) - double_word(0x1p-54), n));
    CHECK(n == 2.0);
    // Beyond the kept range, and underflow to 0: unknown, never a sign.
    CHECK_FALSE(double_word(0x1p-950).known());
    CHECK_FALSE(double_word(0x1p950).known());
    CHECK_FALSE((double_word(0x1p-600) * double_word(0x1p-600)).known());
    CHECK_FALSE((double_word(0x1p600) * double_word(0x1p600)).known());
    CHECK_FALSE((double_word(0x1p-800) / double_word(0x1p800)).known());
    CHECK_THROWS_AS((double_word(0x1p-600) * double_word(0x1p-600)).sign(), uncertain_sign);
    CHECK_FALSE(certain_nearest(double_word(0x1p-600) * double_word(0x1p-600), n));
    // An exact 0 is known and rounds to 0; a divisor in doubt is unknown.
    CHECK(certain_nearest(double_word(3.0) - double_word(3.0), n));
    CHECK(n == 0);
    const double_word third = double_word(1.0) / double_word(3.0);
    CHECK(third.known());
    CHECK_FALSE((double_word(1.0) / (third * double_word(3.0) - double_word(1.0))).known());
    // A product by an exact 0 is exactly 0, whatever the other factor's
    // bound: a point on an axis-parallel line, moved along it by a sum no
    // double holds, has a certain side of 0 against that line.
    CHECK(third.error() > 0);
    const double_word zero = double_word(67.35) - double_word(67.35);
    CHECK(zero.exact_zero());
    CHECK_FALSE(third.exact_zero());
    for (const double_word& z : {zero * third, third * zero, zero * double_word(-0.0), double_word(-0.0) * third}) {
        CHECK(z.error() == 0);
        CHECK(z.sign() == 0);
    }
    CHECK_THROWS_AS((third - third).sign(), uncertain_sign);  // a zero in doubt is no exact zero
    CHECK_THROWS_AS(((third - third) * third).sign(), uncertain_sign);
    const point<double_word> v{double_word(3.765), double_word(64.05) + double_word(-0.001)},
        d{double_word(-0.0), double_word(0.002)};
    const point<double_word> a{double_word(3.765), double_word(64.05)}, b{double_word(3.765), double_word(67.35)};
    CHECK(v.y.lo() != 0);
    CHECK(cross_from(d, v, a).sign() == 0);
    CHECK(cross_from(d, v, b).sign() == 0);
}

TEST_CASE("double_word: sum_of_products bounds a b + c d + t, with cancellation and at the kept range's ends",
          "[double_word]") {
    rng r(0x50f1d3a9ULL);
    word_tally t;
    std::size_t fell_back = 0;
    for (int k = 0; k < 20000; ++k) {
        const auto at = [&](int e) { return std::ldexp(r.signed_unit(), e); };
        const int e = std::vector<int>{-930, -600, -60, 0, 60, 450, 890}[r.index(7)];
        double a = at(e), b = at(r.chance(0.5) ? 0 : -e / 2), c = at(e), d = at(0), s = at(e);
        switch (r.index(6)) {
        case 0: c = -a * (1 + std::ldexp(r.signed_unit(), -static_cast<int>(r.index(60)))), d = b; break;
        case 1: s = -(a * b + c * d); break;  // t cancels the products, up to their rounding
        case 2: a = 0; break;
        case 3: d = 0, s = 0; break;
        case 4: b = std::ldexp(r.signed_unit(), -1000); break;  // a factor below the kept range
        default: break;
        }
        const double_word w = double_word::sum_of_products(a, b, c, d, s);
        const double_word generic = double_word(a) * double_word(b) + double_word(c) * double_word(d) + double_word(s);
        fell_back += w.known() != generic.known();
        t.check({w, exact_rational(a) * exact_rational(b) + exact_rational(c) * exact_rational(d) + exact_rational(s)});
    }
    INFO(t.first);
    CHECK(t.violations == 0);
    INFO("values " << t.values << ", known " << t.known << ", rounded " << t.rounded << ", unknown " << t.unknown
                   << ", known by one route only " << fell_back);
    CHECK(t.known > t.values / 2);
    CHECK(t.rounded > t.known / 2);
    CHECK(t.unknown > 500);
    // Exact inputs give an exact word; a product beyond the kept range is unknown.
    const double_word x = double_word::sum_of_products(3, 5, -2, 7, 1);
    CHECK(x.exact_double());
    CHECK(x.hi() == 2);
    CHECK_FALSE(double_word::sum_of_products(0x1p500, 0x1p500, 1, 1, 0).known());
    CHECK_FALSE(double_word::sum_of_products(0x1p-500, 0x1p-500, 0, 1, 0).known());
}
