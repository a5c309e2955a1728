// SPDX-License-Identifier: BSL-1.0
// The sign tests of a cubic's Bernstein coefficients known within one bound
// (predicates/bernstein_signs.hpp) against exact rationals: four levels of
// halving (the rational model's sifting depth) from coefficients at scales
// from the subnormals to 2^1000, exact or within a bound, with cancellation;
// every exact coefficient must stay within the bound, and every sign said to
// be certain must be the exact one.

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/bernstein_signs.hpp"
#include "support/effort.hpp"
#include "support/random.hpp"

namespace {

using namespace influence2d;
using exact4 = std::array<exact_rational, 4>;

/// The exact de Casteljau halves of x.
std::pair<exact4, exact4> exact_halves(const exact4& x) {
    const exact_rational half(0.5);
    const exact_rational b01 = (x[0] + x[1]) * half, b12 = (x[1] + x[2]) * half, b23 = (x[2] + x[3]) * half;
    const exact_rational b012 = (b01 + b12) * half, b123 = (b12 + b23) * half, mid = (b012 + b123) * half;
    return {{x[0], b01, b012, mid}, {mid, b123, b23, x[3]}};
}

struct halving_tally {
    std::size_t nodes = 0, decided = 0;
};

/// Checks b against the exact coefficients x, then their halves, `depth`
/// levels down.
void check_node(const bounded_bernstein& b, const exact4& x, int depth, halving_tally& t) {
    ++t.nodes;
    const exact_rational e(b.error());
    for (std::size_t i = 0; i < 4; ++i) {
        INFO("coefficient " << i << " at depth " << depth << ": " << b.values()[i] << ", bound " << b.error());
        CHECK(CGAL::abs(x[i] - exact_rational(b.values()[i])) <= e);
    }
    for (const int sign : {1, -1})
        if (b.of_sign(sign)) {
            ++t.decided;
            for (const exact_rational& xi : x) CHECK(CGAL::sign(xi) == sign);
        }
    if (depth == 0) return;
    const auto [l, r] = b.halves();
    const auto [xl, xr] = exact_halves(x);
    check_node(l, xl, depth - 1, t);
    check_node(r, xr, depth - 1, t);
}

}  // namespace

TEST_CASE("bernstein signs: halving in double keeps every exact coefficient within the bound", "[predicates]") {
    test_random::rng g(0xb3u);
    halving_tally t;
    const int cases = test_effort::scaled(3000);
    for (int k = 0; k < cases; ++k) {
        // A scale from the subnormals (2^-1074 is the least double) to 2^1000.
        const int scale =
            g.chance(0.2) ? -1074 + static_cast<int>(g.index(60)) : static_cast<int>(g.index(2000)) - 1000;
        std::array<double, 4> v{};
        for (double& c : v) c = std::ldexp(g.signed_unit(), scale);
        if (g.chance(0.3)) v[1] = -v[0] + std::ldexp(g.signed_unit(), scale - 30);  // cancellation
        if (g.chance(0.3)) {  // one sign throughout, near 0 at an end
            for (double& c : v) c = std::fabs(c);
            v[3] = std::ldexp(g.unit(), scale - 40);
        }
        // The exact coefficients: exact inputs, or within e of v.
        const double e = g.chance(0.5) ? 0 : std::ldexp(g.unit(), scale - 45);
        exact4 x;
        for (std::size_t i = 0; i < 4; ++i) {
            const double offset = e * static_cast<double>(static_cast<int>(g.index(5)) - 2) / 2;  // -e .. e
            x[i] = exact_rational(v[i]) + exact_rational(offset);
        }
        INFO("case " << k << ", scale 2^" << scale);
        check_node(bounded_bernstein(v, e), x, 4, t);
    }
    WARN("bounded_bernstein: " << t.decided << " signs decided over " << t.nodes << " nodes");
    CHECK(t.decided > t.nodes / 4);
}

TEST_CASE("bernstein signs: the change of basis from power coefficients keeps the bound, one sign change is one",
          "[predicates]") {
    // Power coefficients a_k within e of exact ones A_k; the Bernstein
    // coefficients (times 3) of_power makes must lie within its bound of
    // 3 A0, 3 A0 + A1, 3 A0 + 2 A1 + A2 and 3 (A0 + A1 + A2 + A3), and a
    // single sign change it reports must be the exact coefficients' (every
    // one's sign, zeros skipped, one change, both ends non-zero).
    test_random::rng g(0xba515u);
    std::size_t decided = 0;
    const int cases = test_effort::scaled(20000);
    for (int k = 0; k < cases; ++k) {
        const int scale =
            g.chance(0.1) ? -1074 + static_cast<int>(g.index(60)) : static_cast<int>(g.index(2000)) - 1000;
        std::array<double, 4> a{};
        for (double& c : a) c = std::ldexp(g.signed_unit(), scale - static_cast<int>(g.index(8)));
        if (g.chance(0.3)) a[1] = -3 * a[0] + std::ldexp(g.signed_unit(), scale - 40);  // cancellation in 3 a0 + a1
        const double e = g.chance(0.5) ? 0 : std::ldexp(g.unit(), scale - 45);
        exact4 x;
        for (std::size_t i = 0; i < 4; ++i)
            x[i] = exact_rational(a[i]) +
                   exact_rational(e * static_cast<double>(static_cast<int>(g.index(5)) - 2) / 2);  // -e .. e
        const exact_rational three(3);
        const exact4 b = {three * x[0], three * x[0] + x[1], three * x[0] + x[1] + x[1] + x[2],
                          three * (x[0] + x[1] + x[2] + x[3])};
        const bounded_bernstein bb = bounded_bernstein::of_power(a, e);
        INFO("case " << k << ", scale 2^" << scale);
        for (std::size_t i = 0; i < 4; ++i)
            CHECK(CGAL::abs(b[i] - exact_rational(bb.values()[i])) <= exact_rational(bb.error()));
        if (const int first = bb.single_sign_change()) {
            ++decided;
            int changes = 0, last = 0;
            for (const exact_rational& c : b) {
                const int sign = CGAL::sign(c);
                if (sign == 0) continue;
                changes += last != 0 && sign != last;
                last = sign;
            }
            CHECK(changes == 1);
            CHECK(CGAL::sign(b[0]) == first);
            CHECK(CGAL::sign(b[3]) == -first);
        }
    }
    WARN("of_power: " << decided << " single sign changes decided in " << cases << " cubics");
    CHECK(decided > static_cast<std::size_t>(cases) / 20);
}

TEST_CASE("bernstein signs: a NaN or infinite coefficient or a NaN bound decides no sign", "[predicates]") {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(bounded_bernstein({1, 2, 3, 4}, 0.5).of_sign(1));
    CHECK_FALSE(bounded_bernstein({1, 2, 3, 4}, 0.5).of_sign(-1));
    CHECK_FALSE(bounded_bernstein({1, 2, 3, 4}, 1).of_sign(1));  // 1 is within the bound of 0
    CHECK_FALSE(bounded_bernstein({inf, 2, 3, 4}, 0).of_sign(1));
    CHECK_FALSE(bounded_bernstein({-inf, -2, -3, -4}, 0).of_sign(-1));
    CHECK_FALSE(bounded_bernstein({1, nan, 3, 4}, 0).of_sign(1));
    CHECK_FALSE(bounded_bernstein({1, 2, 3, 4}, nan).of_sign(1));
    // Means that overflow (huge values of one sign) leave no sign certain.
    const double huge = std::numeric_limits<double>::max();
    for (const auto& half : {bounded_bernstein({huge, huge, -huge, -huge}, 0).halves().first,
                             bounded_bernstein({1, 2, 3, 4}, nan).halves().second})
        CHECK_FALSE(half.of_sign(1));
}
