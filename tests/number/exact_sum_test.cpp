// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "influence2d/number/cgal.hpp"
#include "influence2d/number/exact_sum.hpp"
#include "support/random.hpp"

using influence2d::exact_sum::accumulator;

TEST_CASE("exact_sum: sign of a sum that cancels below double precision", "[exact_sum]") {
    // 2^53 + 1 - 2^53 - 1 is 0, though in double (2^53 + 1) rounds to 2^53 and
    // the sum to -1; then + 2^-60 leaves only the last term.
    accumulator acc;
    acc.add_product(0x1p53, 1);
    acc.add(1);
    acc.add(-9007199254740992.0);
    acc.add(-1);
    CHECK(acc.sign() == 0);
    acc.add(0x1p-60);
    CHECK(acc.sign() == 1);
}

TEST_CASE("exact_sum: products keep their rounding error", "[exact_sum]") {
    // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60; the 2^-60 is lost in a double product.
    const double x = 1 + 0x1p-30;
    accumulator acc;
    acc.add_product(x, x);
    acc.add(-1);
    acc.add(-0x1p-29);
    CHECK(acc.sign() == 1);
    acc.add(-0x1p-60);
    CHECK(acc.sign() == 0);
    acc.add(-0x1p-100);
    CHECK(acc.sign() == -1);
}

TEST_CASE("exact_sum: exact over the whole range of double", "[exact_sum]") {
    // Products that overflow double (1e200 * 1e200) and that underflow it
    // (subnormal times subnormal) are still summed exactly.
    accumulator big;
    big.add_product(1e200, 1e200);
    big.add_product(-1e200, 1e200);
    CHECK(big.sign() == 0);
    big.add_product(0x1p-1074, 0x1p-1074);  // 2^-2148 beside 1e400-sized terms
    CHECK(big.sign() == 1);
    big.add_product(std::numeric_limits<double>::max(), -std::numeric_limits<double>::max());
    CHECK(big.sign() == -1);

    accumulator tiny;
    tiny.add_product(3 * 0x1p-1074, 0x1p-1074);
    tiny.add_product(-0x1p-1074, 0x1p-1074);
    tiny.add_product(-0x1p-1074, 2 * 0x1p-1074);
    CHECK(tiny.sign() == 0);
    tiny.add_product(-0x1p-1074, 0x1p-1074);
    CHECK(tiny.sign() == -1);
}

TEST_CASE("exact_sum: carries across words in the totals of either sign", "[exact_sum]") {
    // 2049 terms of 2^53 - 1 (all significand bits set) sum past 2^64: the
    // positive total carries into its next word; one product takes it all
    // back from the negative side; then the least product of two
    // subnormals, of either sign.
    const double ones = 0x1p53 - 1;
    for (const double side : {1.0, -1.0}) {
        accumulator acc;
        for (int k = 0; k < 2049; ++k) acc.add(side * ones);
        CHECK(acc.sign() == static_cast<int>(side));
        acc.add_product(-side * ones, 2049);
        CHECK(acc.sign() == 0);
        acc.add_product(side * 0x1p-1074, 0x1p-1074);
        CHECK(acc.sign() == static_cast<int>(side));
        acc.add_product(-side * 0x1p-1074, 2 * 0x1p-1074);
        CHECK(acc.sign() == -static_cast<int>(side));
    }
}

TEST_CASE("exact_sum: orientation of points at 1e200 and at subnormal scale", "[exact_sum]") {
    using influence2d::exact_sum::orientation_sign;
    CHECK(orientation_sign(0, 0, 1e200, 0, 1e200, 1e200) == 1);
    CHECK(orientation_sign(0, 0, 1e200, 0, 2e200, 0) == 0);
    CHECK(orientation_sign(0, 0, 0x1p-1070, 0, 0x1p-1070, 0x1p-1074) == 1);
    CHECK(orientation_sign(0, 0, 0x1p-1070, 0, 0x1p-1070, -0x1p-1074) == -1);
    // Many terms cancelling with carries through many words.
    accumulator acc;
    for (int k = 0; k < 1000; ++k) acc.add_product(std::ldexp(1.0, k - 500), std::ldexp(-1.0, 500 - k));
    acc.add(1000);
    CHECK(acc.sign() == 0);
}

TEST_CASE("exact_sum: signs of random sums of products equal those of exact rationals", "[exact_sum]") {
    test_random::rng rng(17);
    const auto any_double = [&] {
        // Random sign, mantissa and exponent over the whole finite range.
        const double m = rng.unit();
        const int e = static_cast<int>(rng.index(2098)) - 1074;
        return (rng.index(2) == 1 ? -1 : 1) * std::ldexp(m, e);
    };
    for (int trial = 0; trial < 3000; ++trial) {
        accumulator acc;
        influence2d::exact_rational sum(0);
        const int terms = 1 + static_cast<int>(rng.index(8));
        std::vector<std::pair<double, double>> products;
        for (int k = 0; k < terms; ++k) {
            double a = any_double(), b = any_double();
            if (k > 0 && rng.index(3) == 0) {  // cancel an earlier term exactly, or nearly
                a = -products[0].first;
                b = products[0].second;
            }
            products.emplace_back(a, b);
            acc.add_product(a, b);
            sum += influence2d::exact_rational(a) * influence2d::exact_rational(b);
        }
        INFO("trial " << trial);
        CHECK(acc.sign() == static_cast<int>(CGAL::sign(sum)));
    }
}

#if defined(__SIZEOF_INT128__)
TEST_CASE("exact_sum: orientation in 128-bit integers equals the accumulator and exact rationals", "[exact_sum]") {
    using influence2d::exact_sum::orientation_in_window;
    using influence2d::exact_sum::orientation_sign_accumulated;
    using influence2d::exact_sum::orientation_window_bits;
    test_random::rng rng(29);
    const auto exact_sign = [](const double(&c)[6]) {
        using q = influence2d::exact_rational;
        const q det = (q(c[2]) - q(c[0])) * (q(c[5]) - q(c[1])) - (q(c[3]) - q(c[1])) * (q(c[4]) - q(c[0]));
        return static_cast<int>(CGAL::sign(det));
    };
    int in_window = 0, outside = 0, zeros = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        // Coordinates of one data set: a common scale 2^s, each with a
        // random number of significant bits (1 to 53) and a random offset
        // within `span` bits, so that the six span from a few bits to
        // beyond the window; a third of the triples collinear (c on the
        // line through a and b at a dyadic step that keeps it exact), or
        // with repeated coordinates.
        const int s = static_cast<int>(rng.index(200)) - 100;
        const int span = 8 + static_cast<int>(rng.index(90));
        const auto coordinate = [&] {
            const int bits = 1 + static_cast<int>(rng.index(53));
            const double m = std::floor(rng.unit() * std::ldexp(1.0, bits));
            const int shift = static_cast<int>(rng.index(static_cast<std::size_t>(std::max(1, span - bits + 1))));
            return (rng.index(2) == 1 ? -1 : 1) * std::ldexp(m, s + shift);
        };
        double c[6];
        for (double& x : c) x = coordinate();
        switch (rng.index(4)) {
        case 0:  // c = a + 2^k (b - a), exact when the sums are
            c[4] = c[0] + std::ldexp(c[2] - c[0], static_cast<int>(rng.index(5)) - 2);
            c[5] = c[1] + std::ldexp(c[3] - c[1], static_cast<int>(rng.index(5)) - 2);
            break;
        case 1:  // a vertical or horizontal line through two of them
            c[4] = c[0];
            c[2] = c[0];
            break;
        default: break;
        }
        INFO("trial " << trial << ": " << c[0] << " " << c[1] << " " << c[2] << " " << c[3] << " " << c[4] << " "
                      << c[5]);
        const int expected = exact_sign(c);
        CHECK(orientation_sign_accumulated(c[0], c[1], c[2], c[3], c[4], c[5]) == expected);
        int sign = 2;
        if (orientation_in_window(c[0], c[1], c[2], c[3], c[4], c[5], sign)) {
            ++in_window;
            CHECK(sign == expected);
        } else {
            ++outside;
            CHECK(sign == 2);
        }
        zeros += expected == 0 ? 1 : 0;
    }
    // Both routes taken, and many exact zeros among them.
    CHECK(in_window > 5000);
    CHECK(outside > 2000);
    CHECK(zeros > 2000);
}

TEST_CASE("exact_sum: the 128-bit window at its edge", "[exact_sum]") {
    using influence2d::exact_sum::orientation_in_window;
    using influence2d::exact_sum::orientation_sign;
    // 61 bits from the unit 1 to the largest, 2^61 - 2^8 (53 bits set): the
    // differences reach 2^62 - 2^9 and the products 2^124; in the window.
    const double big = 0x1p61 - 0x1p8;
    int sign = 2;
    CHECK(orientation_in_window(-big, 1, big, -big, big, big, sign));
    CHECK(sign == 1);  // (2 big)(big - 1) - (-big - 1)(2 big) = 2 big (2 big) > 0
    CHECK(orientation_in_window(-big, -big, big, big, 1, 1, sign));
    CHECK(sign == 0);  // c on the diagonal
    CHECK(orientation_in_window(-big, -big, big, big, 1, 0, sign));
    CHECK(sign == -1);
    // One bit more (2^61 itself beside the unit 1): outside the window, and
    // the accumulator answers.
    sign = 2;
    CHECK_FALSE(orientation_in_window(-0x1p61, -0x1p61, 0x1p61, 0x1p61, 1, 1, sign));
    CHECK(sign == 2);
    CHECK(orientation_sign(-0x1p61, -0x1p61, 0x1p61, 0x1p61, 1, 1) == 0);
    CHECK(orientation_sign(-0x1p61, -0x1p61, 0x1p61, 0x1p61, 1, 0) == -1);
    // Zeros of either sign, and subnormals within one window.
    CHECK(orientation_in_window(0.0, -0.0, 0.0, 0.0, -0.0, 0.0, sign));
    CHECK(sign == 0);
    CHECK(orientation_in_window(0, 0, 0x1p-1070, 0, 0x1p-1070, 0x1p-1074, sign));
    CHECK(sign == 1);
    CHECK(orientation_in_window(0, 0, 0x1p-1070, 0, 3 * 0x1p-1070, -0x1p-1074, sign));
    CHECK(sign == -1);
}
#endif
