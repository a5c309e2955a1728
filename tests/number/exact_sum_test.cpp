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
