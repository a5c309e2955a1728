// SPDX-License-Identifier: BSL-1.0
// The contact cubics of the rational model in double with one bound per
// cubic (motion/contact_cubics.hpp, bounded_coefficients) against exact
// rationals: the cubics written here from their definition (docs/sweep.md:
// f = (q - p) x (P h l - p h l), lo = (q - p) . (P h l - p h l), hi =
// |q - p|^2 h l - lo, h = 1 + w^2 tau^2), on exact inputs within the bounds
// that certified gives the moving point, w^2 and l; every coefficient must
// lie within its cubic's bound.

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "influence2d/motion/contact_cubics.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/effort.hpp"
#include "support/random.hpp"

namespace {

using namespace influence2d;
using cubic = std::array<exact_rational, 4>;

/// A value in certified within its bound of an exact one: the certified
/// number and the exact value (somewhere in [v - e, v + e]).
struct near_value {
    certified c;
    exact_rational exact;
};

near_value near(test_random::rng& g, double v, double e) {
    const double offset = e * static_cast<double>(static_cast<int>(g.index(5)) - 2) / 2;  // -e .. e
    return {certified(v, e), exact_rational(v) + exact_rational(offset)};
}

}  // namespace

TEST_CASE("contact cubics: the coefficients in double lie within their cubic's bound", "[sweep][rational_turn]") {
    test_random::rng g(0xc0b1c5u);
    const int cases = test_effort::scaled(20000);
    std::size_t tight = 0;
    for (int n = 0; n < cases; ++n) {
        // Scales whose products of two coordinates stay in double's range (the
        // motions' safe window; beyond it a bound is infinite, and nothing is
        // claimed).
        const int scale = static_cast<int>(g.index(500)) - 250;
        const auto coordinate = [&] { return std::ldexp(g.signed_unit(), scale); };
        // The moving point's cubics, each coefficient exact or within a bound.
        moving_point<certified> m;
        cubic mx, my;
        for (int k = 0; k < 4; ++k)
            for (const bool is_x : {true, false}) {
                const double v = coordinate();
                const near_value t = near(g, v, g.chance(0.4) ? 0 : std::fabs(v) * std::ldexp(g.unit(), -45));
                (is_x ? m.x[k] : m.y[k]) = t.c;
                (is_x ? mx[k] : my[k]) = t.exact;
            }
        const double wv = g.unit();
        const near_value w2 = near(g, wv * wv, g.chance(0.5) ? 0 : std::ldexp(wv * wv, g.chance(0.5) ? -52 : -40));
        // l: 1 (B's vertex in A's frame) or c^2 + s^2 in certified (A's).
        near_value l{certified(1.0), exact_rational(1)};
        if (g.chance(0.2)) {
            l = near(g, 1, std::ldexp(1.0, -40));  // a looser l than any pose gives
        } else if (g.chance(0.5)) {
            const double angle = g.uniform(-3.2, 3.2), c = std::cos(angle), s = std::sin(angle);
            l = {certified(c) * certified(c) + certified(s) * certified(s),
                 exact_rational(c) * exact_rational(c) + exact_rational(s) * exact_rational(s)};
        }
        point<double> p{coordinate(), coordinate()}, q{coordinate(), coordinate()};
        if (g.chance(0.2)) q = {p.x + std::ldexp(g.signed_unit(), scale - 30), p.y};  // a short edge
        if (g.chance(0.3)) {
            // The moving point near p h l, exactly given: its terms P h l - p h
            // l small against the edge, so that hi's own terms (|q - p|^2 h l)
            // carry its bound.
            const double lv = l.c.value(), w2v = w2.c.value();
            for (int k = 0; k < 4; ++k) {
                const double hk = k == 0 ? 1 : (k == 2 ? w2v : 0);
                const double dx = std::ldexp(g.signed_unit(), scale - 40), dy = std::ldexp(g.signed_unit(), scale - 40);
                m.x[k] = certified(p.x * lv * hk + dx);
                m.y[k] = certified(p.y * lv * hk + dy);
                mx[k] = exact_rational(m.x[k].value());
                my[k] = exact_rational(m.y[k].value());
            }
        }
        const bounded_cubics b = bounded_coefficients(m, w2.c, l.c, p, q);

        // The definition in exact rationals: D = P h l - p h l per coefficient.
        const exact_rational ex = exact_rational(q.x) - exact_rational(p.x),
                             ey = exact_rational(q.y) - exact_rational(p.y);
        const cubic h = {exact_rational(1), exact_rational(0), w2.exact, exact_rational(0)};
        cubic f, lo, hi;
        for (std::size_t k = 0; k < 4; ++k) {
            const exact_rational dx = mx[k] - exact_rational(p.x) * l.exact * h[k];
            const exact_rational dy = my[k] - exact_rational(p.y) * l.exact * h[k];
            f[k] = ex * dy - ey * dx;
            lo[k] = ex * dx + ey * dy;
            hi[k] = (ex * ex + ey * ey) * h[k] * l.exact - lo[k];
        }
        INFO("case " << n << ", scale 2^" << scale);
        const cubic* exact[3] = {&f, &lo, &hi};
        for (std::size_t i = 0; i < 3; ++i) {
            INFO("cubic " << i << ", bound " << b.e[i]);
            REQUIRE(std::isfinite(b.e[i]));
            for (std::size_t k = 0; k < 4; ++k)
                CHECK(CGAL::abs((*exact[i])[k] - exact_rational(b.c[i][k])) <= exact_rational(b.e[i]));
        }
        // Tight enough to tell signs: the bound of f far below its largest coefficient.
        const double largest =
            std::max({std::fabs(b.c[0][0]), std::fabs(b.c[0][1]), std::fabs(b.c[0][2]), std::fabs(b.c[0][3])});
        tight += b.e[0] < std::ldexp(largest, -30);
    }
    WARN("bounded_coefficients: f's bound below 2^-30 of its largest coefficient in " << tight << " of " << cases);
    CHECK(tight > static_cast<std::size_t>(cases) / 2);
}

TEST_CASE("contact cubics: a NaN or infinite term gives infinite bounds", "[sweep][rational_turn]") {
    moving_point<certified> m;
    for (int k = 0; k < 4; ++k) m.x[k] = m.y[k] = certified(1.0);
    m.y[2] = certified(std::numeric_limits<double>::infinity());
    const bounded_cubics b = bounded_coefficients(m, certified(0.25), certified(1.0), {0, 0}, {1, 2});
    for (const double e : b.e) CHECK(e == HUGE_VAL);
    m.y[2] = certified(1.0, std::numeric_limits<double>::quiet_NaN());
    const bounded_cubics c = bounded_coefficients(m, certified(0.25), certified(1.0), {0, 0}, {1, 2});
    for (const double e : c.e) CHECK(e == HUGE_VAL);
}
