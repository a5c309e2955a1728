// SPDX-License-Identifier: BSL-1.0
// Root isolation by Sturm sequences and bisection: exact in an exact field,
// and in double every loop stops once a halving leaves its bracket as it
// was, whatever the rounding does to the signs.

#include <catch2/catch.hpp>

#include <cmath>
#include <type_traits>
#include <vector>

#include "influence2d/number/cgal.hpp"
#include "influence2d/number/double_word.hpp"
#include "influence2d/predicates/polynomial_roots.hpp"
#include "support/random.hpp"

using namespace influence2d;

namespace {

/// The polynomial (x - r0)(x - r1)... with the roots given.
template <class NT>
polynomial<NT> with_roots(const std::vector<double>& roots) {
    polynomial<NT> p{{number_traits<NT>::from_double(1)}};
    for (const double r : roots) {
        polynomial<NT> q{std::vector<NT>(p.c.size() + 1, number_traits<NT>::from_double(0))};
        for (std::size_t k = 0; k < p.c.size(); ++k) {
            q.c[k + 1] = NT(q.c[k + 1] + p.c[k]);
            q.c[k] = NT(q.c[k] - p.c[k] * number_traits<NT>::from_double(r));
        }
        p = q;
    }
    return p;
}

}  // namespace

TEST_CASE("Sturm sequences isolate the roots of a cubic exactly", "[predicates][roots]") {
    using NT = exact_rational;
    const auto s = sturm_sequence(with_roots<NT>({0.25, 0.5, 0.75}));
    CHECK(roots_between<NT>(s, 0, 1) == 3);
    CHECK(roots_between<NT>(s, 0.25, 0.5) == 1);  // (a, b]: 0.5, not 0.25
    CHECK(roots_between<NT>(s, 0.5, 0.625) == 0);
    const auto roots = isolate_roots<NT>(s, 0, 1);
    REQUIRE(roots.size() == 3);
    const double expected[] = {0.25, 0.5, 0.75};
    for (std::size_t k = 0; k < 3; ++k) {
        CHECK(roots[k].low < NT(expected[k]));
        CHECK(roots[k].high >= NT(expected[k]));
        CHECK(roots_between(s, roots[k].low, roots[k].high) == 1);
    }
    // A double root counts once, and sign_at_root finds q = x - 1/2 zero
    // there and x - 1/4 positive.
    const auto d = sturm_sequence(with_roots<NT>({0.5, 0.5, 0.875}));
    CHECK(roots_between<NT>(d, 0, 1) == 2);
    auto twice = isolate_roots<NT>(d, 0, 1);
    REQUIRE(twice.size() == 2);
    CHECK(sign_at_root(with_roots<NT>({0.5}), d, twice[0]) == 0);
    CHECK(sign_at_root(with_roots<NT>({0.25}), d, twice[0]) == 1);
    CHECK(sign_at_root(with_roots<NT>({0.625}), d, twice[0]) == -1);
    // Two cubics sharing the root 1/2 compare equal; 1/2 before 0.5 + 2^-52.
    auto s1 = sturm_sequence(with_roots<NT>({0.5, 0.9}));
    auto s2 = sturm_sequence(with_roots<NT>({0.5, 0.1, 0.95}));
    auto s3 = sturm_sequence(with_roots<NT>({0.5 + std::ldexp(1.0, -52)}));
    auto r1 = isolate_roots<NT>(s1, 0.25, 0.75).at(0), r2 = isolate_roots<NT>(s2, 0.25, 0.75).at(0),
         r3 = isolate_roots<NT>(s3, 0.25, 0.75).at(0);
    CHECK(compare_roots(s1, r1, s2, r2) == 0);
    CHECK(compare_roots(s1, r1, s3, r3) == -1);
    CHECK(compare_roots(s3, r3, s2, r2) == 1);
}

TEST_CASE("halving in double stops once the bracket no longer moves", "[predicates][roots]") {
    // Exactly: every halving moves the bracket.
    const auto se = sturm_sequence(with_roots<exact_rational>({0.3}));
    isolated_root<exact_rational> re{0, 1};
    for (int k = 0; k < 80; ++k) REQUIRE(halve(se, re));
    CHECK(re.low < exact_rational(0.3));
    CHECK(re.high >= exact_rational(0.3));
    // In double: a bracket of two neighbouring doubles cannot be cut; halve
    // says so and leaves it.
    const auto s = sturm_sequence(with_roots<double>({0.3}));
    isolated_root<double> r{0, 1};
    int moved = 0;
    while (halve(s, r)) REQUIRE(++moved < 200);
    CHECK(moved >= 52);
    CHECK(std::nextafter(r.low, 1.0) == r.high);
    const isolated_root<double> stuck = r;
    CHECK_FALSE(halve(s, r));
    CHECK(r.low == stuck.low);
    CHECK(r.high == stuck.high);
    // compare_roots of two roots a rounding apart, which double's greatest
    // common divisor does not find shared (x - 0.3 and 3x - 0.9, its
    // constant rounded): the brackets are halved until they part or stop
    // moving, and then they hold neighbouring doubles.
    const auto t1 = sturm_sequence(with_roots<double>({0.3}));
    const auto t2 = sturm_sequence(polynomial<double>{{-0.3 * 3, 3}});
    REQUIRE(common_divisor(t1[0], t2[0]).degree() == 0);
    auto r1 = isolate_roots<double>(t1, 0.25, 0.5).at(0), r2 = isolate_roots<double>(t2, 0.25, 0.5).at(0);
    const int order = compare_roots(t1, r1, t2, r2);
    if (order == 0) {
        CHECK(std::nextafter(r1.low, 1.0) == r1.high);
        CHECK(std::nextafter(r2.low, 1.0) == r2.high);
    } else {
        CHECK((r1.high <= r2.low || r2.high <= r1.low));
    }
    CHECK(r1.high - r1.low < 1e-15);
}

TEST_CASE("a root's side by the sign where the bracket's ends differ, as by Sturm counts", "[predicates][roots]") {
    // Cubics with roots on a grid of 1/64 (simple, double and triple), each
    // root's bracket halved a few times (by Sturm counts, and by the signs
    // alone where isolate_roots found the ends' signs opposite: the same
    // halves); at every point of a finer grid in the bracket root_side with
    // the ends' signs gives the Sturm count's answer, with the sequence or
    // the cubic alone, in exact rationals and in double words. A root of even
    // multiplicity (no sign change) leaves opposite_end_signs 0; a double
    // root between two simple ones must not fool it. (In double words the
    // sides where the ends' signs tell, x rounded to a dyadic double.)
    using NT = exact_rational;
    std::size_t by_sign = 0, by_count = 0, in_doubt = 0, in_double_words = 0;
    for (int a = 1; a < 64; a += 5)
        for (int b = a; b < 64; b += 7)
            for (int c = b; c < 64; c += 11) {
                const std::vector<double> roots{a / 64.0, b / 64.0, c / 64.0};
                const auto s = sturm_sequence(with_roots<NT>(roots));
                // (In double words a multiple root's sequence may be in doubt.)
                std::vector<polynomial<double_word>> sw;
                try {
                    sw = sturm_sequence(with_roots<double_word>(roots));
                } catch (const uncertain_sign&) {
                    ++in_doubt;
                }
                const std::vector<polynomial<NT>> alone{s[0]};  // (no sequence: the signs must tell)
                for (isolated_root<NT> r : isolate_roots<NT>(s, 0, 1)) {
                    CHECK(r.low_sign == opposite_end_signs(s, r.low, r.high));
                    isolated_root<NT> halved = r;
                    for (int k = 0; k < 3; ++k) {
                        halve(s, r);
                        if (halved.low_sign != 0) {
                            halve(alone, halved);  // (by signs alone, the same halves)
                            CHECK(halved.low == r.low);
                            CHECK(halved.high == r.high);
                        }
                    }
                    r.low_sign = 0;  // (Sturm counts below)
                    const int low = opposite_end_signs(s, r.low, r.high);
                    isolated_root<double_word> rw{double_word(CGAL::to_double(r.low)),
                                                  double_word(CGAL::to_double(r.high))};
                    const int low_w = sw.empty() ? 0 : opposite_end_signs(sw, rw.low, rw.high);
                    rw.low_sign = low_w;
                    const isolated_root<NT> by_sign_r{r.low, r.high, low};
                    if (!sw.empty()) CHECK(low_w == low);  // (the ends are dyadic: both exact)
                    ++(low != 0 ? by_sign : by_count);
                    for (int i = 1; i <= 16; ++i) {
                        const NT x = r.low + (r.high - r.low) * NT(i) / NT(16);
                        const int sturm = s[0].sign_at(x) == 0 ? 0 : roots_between(s, r.low, x) > 0 ? -1 : 1;
                        CHECK(root_side(s, by_sign_r, x) == sturm);
                        CHECK(root_side(s, r, x) == sturm);
                        if (low != 0) CHECK(root_side(alone, by_sign_r, x) == sturm);
                        if (sw.empty() || low_w == 0) continue;
                        CHECK(root_side(sw, rw, double_word(CGAL::to_double(x))) == sturm);
                        ++in_double_words;
                    }
                }
            }
    WARN(by_sign << " brackets by their ends' signs, " << by_count << " by Sturm counts; " << in_double_words
                 << " sides in double words, " << in_doubt << " sequences in doubt there");
    CHECK(by_sign > 0);
    CHECK(by_count > 0);
    CHECK(in_double_words > 0);
}

TEST_CASE("narrowing by double leaves a few units about the root, checked exactly", "[predicates][roots]") {
    // Cubics with random coefficients of mixed magnitudes, and cubics built
    // from roots: simple ones, two within 2^-40 (one bracket each), a root
    // at an exact double (the cubic's value 0 there), one near an end of
    // [0, 1] behind a steep slope (Newton's first step leaves the bracket).
    // For every root isolate_roots brackets in exact rationals and in
    // double words: narrowed_by_double either leaves the bracket as it was
    // (false) or narrows it to a sub-bracket that holds the same root alone,
    // with low_sign its ends' signs, below 2^-32 wide (below 2^-44 for most:
    // a few units, unless the coefficients' rounding to double moved the
    // root further). Only the two roots 2^-40 apart are left.
    test_random::rng rng(20261128);
    std::vector<std::vector<double>> by_roots{{0.375},
                                              {0.375, 0.625, 0.875},
                                              {0.5, 0.5 + std::ldexp(1.0, -40), 0.8},
                                              {0.001, 0.999},
                                              {std::ldexp(1.0, -30), 0.75}};
    for (int k = 0; k < 40; ++k) by_roots.push_back({rng.unit(), rng.unit(), rng.unit()});
    std::vector<polynomial<exact_rational>> cubics;
    for (const std::vector<double>& roots : by_roots) cubics.push_back(with_roots<exact_rational>(roots));
    for (int k = 0; k < 200; ++k) {
        polynomial<exact_rational> p;
        for (int i = 0; i < 4; ++i)
            p.c.push_back(exact_rational(rng.signed_unit() * std::ldexp(1.0, int(rng.index(20)) - 10)));
        cubics.push_back(p.trimmed());
    }
    std::size_t narrowed = 0, narrow = 0, left = 0, in_doubt = 0;
    const auto check = [&](const auto& s, auto r) {
        using NT = std::decay_t<decltype(r.low)>;
        const auto before = r;
        if (!narrowed_by_double(s, r)) {
            CHECK(compare_values<NT>(r.low, before.low) == 0);
            CHECK(compare_values<NT>(r.high, before.high) == 0);
            ++left;
            return;
        }
        ++narrowed;
        CHECK(compare_values<NT>(r.low, before.low) >= 0);
        CHECK(compare_values<NT>(r.high, before.high) <= 0);
        const double width = number_traits<NT>::to_double(NT(r.high - r.low));
        CHECK(width < std::ldexp(1.0, -32));
        narrow += width < std::ldexp(1.0, -44);
        CHECK(roots_between(s, r.low, r.high) == 1);
        CHECK(r.low_sign == opposite_end_signs(s, r.low, r.high));
    };
    for (const polynomial<exact_rational>& p : cubics) {
        if (p.degree() < 1) continue;
        const auto s = sturm_sequence(p);
        for (const isolated_root<exact_rational>& r : isolate_roots<exact_rational>(s, 0, 1)) check(s, r);
        polynomial<double_word> pw;
        for (const exact_rational& c : p.c) pw.c.push_back(double_word(CGAL::to_double(c)));
        if (pw.trimmed().degree() < 1) continue;
        try {
            const auto sw = sturm_sequence(pw);
            for (const isolated_root<double_word>& r : isolate_roots<double_word>(sw, double_word(0), double_word(1)))
                check(sw, r);
        } catch (const uncertain_sign&) {
            ++in_doubt;
        }
    }
    WARN(narrowed << " brackets narrowed (" << narrow << " below 2^-44), " << left << " left, " << in_doubt
                  << " double-word sequences in doubt");
    CHECK(narrowed > 100 * left);
    CHECK(narrow * 4 > narrowed * 3);
}
