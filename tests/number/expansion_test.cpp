#include <catch2/catch.hpp>

#include "influence2d/number/expansion.hpp"

using influence2d::expansion::accumulator;

TEST_CASE("expansion: sign of a sum that cancels below double precision", "[expansion]") {
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

TEST_CASE("expansion: products keep their rounding error", "[expansion]") {
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
