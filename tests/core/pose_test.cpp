// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/pose.hpp"

using namespace influence2d;

namespace {

// Whether two doubles are the same bits (a sign of zero included).
bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

}  // namespace

TEST_CASE("pose: the rotation's doubles are std::cos and std::sin of theta, zero's sign kept", "[pose]") {
    const double tiny = std::numeric_limits<double>::denorm_min();
    for (const double theta : {0.0, -0.0, tiny, -tiny, 1e-300, 0.5, -2.0, 3.0, 1e6}) {
        INFO(theta);
        const rotation_pose r(pose{1, -2, theta});
        CHECK(same_bits(r.c, std::cos(theta)));
        CHECK(same_bits(r.s, std::sin(theta)));
        CHECK(r.tx == 1);
        CHECK(r.ty == -2);
    }
    CHECK(std::signbit(rotation_pose(pose{0, 0, -0.0}).s));
    CHECK_THROWS_AS(rotation_pose(pose{0, 0, std::nan("")}), invalid_input);
    CHECK_THROWS_AS(rotation_pose(pose{std::numeric_limits<double>::infinity(), 0, 0}), invalid_input);
}

TEST_CASE("pose: the rotation's doubles are std::cos and std::sin bit for bit on millions of angles", "[pose]") {
    // Angles of every kind a pose takes: small turns, a few turns, scaled
    // by up to 2^60, and doubles of random bits (every exponent).
    std::mt19937_64 random(20261205);
    std::uniform_real_distribution<double> turns(-4, 4), small(-1e-3, 1e-3);
    long differing = 0, angles = 0;
    const auto compare = [&](double theta) {
        if (!std::isfinite(theta)) return;
        const rotation_pose r(pose{0, 0, theta});
        if (!same_bits(r.c, std::cos(theta)) || !same_bits(r.s, std::sin(theta))) {
            if (differing < 5) UNSCOPED_INFO("theta = " << std::hexfloat << theta);
            ++differing;
        }
        ++angles;
    };
    for (int k = 0; k < 1000000; ++k) {
        compare(turns(random));
        compare(small(random));
        compare(std::ldexp(turns(random), static_cast<int>(random() % 61)));
        const std::uint64_t bits = random();
        double theta;
        std::memcpy(&theta, &bits, sizeof theta);
        compare(theta);
    }
    CHECK(angles > 3900000);
    CHECK(differing == 0);
}
