// SPDX-License-Identifier: BSL-1.0
// Quadruple precision number types (number/multiprecision.hpp): traits, and
// the detector in them agreeing with the exact one on frames with no exact
// degeneracy (they round, at 113 bits).

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "influence2d/detect/detector.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/multiprecision.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "support/families.hpp"
#include "support/poses.hpp"

namespace {

using namespace influence2d;

template <class NT>
void check_traits(const char* name) {
    using tr = number_traits<NT>;
    CHECK(std::string(tr::name) == name);
    CHECK(tr::category == number_category::floating);
    CHECK(tr::to_double(tr::from_double(0.1)) == 0.1);
    CHECK(tr::to_double(tr::from_double(0x1p-1074)) == 0x1p-1074);
    CHECK(tr::sign(tr::from_double(-3)) == -1);
    CHECK(tr::sign(tr::from_double(0)) == 0);
    // 0.1 * 3 - 0.3 on the input doubles is exactly 2^-55: within 113 bits
    // (double says 2^-54).
    const NT x = tr::from_double(0.1) * tr::from_double(3) - tr::from_double(0.3);
    CHECK(tr::to_double(x) == 0x1p-55);
    // A determinant double gets wrong: (1 + 2^-30)^2 - 1 - 2^-29 = 2^-60.
    const NT y = tr::from_double(1 + 0x1p-30);
    CHECK(tr::sign(y * y - tr::from_double(1) - tr::from_double(0x1p-29)) == 1);
    CHECK(tr::filter_slack > 0);
    CHECK(tr::filter_slack < 1e-9);
}

template <class NT>
void check_detector() {
    std::size_t frames = 0, collisions = 0;
    for (const char* pair : {"contour_32 starred_16", "hole_16 irregular_32", "convex_64 contour_8"}) {
        const std::string p(pair);
        const polygon& A = test_families::load(p.substr(0, p.find(' ')));
        const polygon& B = test_families::load(p.substr(p.find(' ') + 1));
        detector_options wit;
        wit.witness = true;
        detector<exact_rational> exact(A, B, wit);
        detector<NT> quad_det(A, B, wit);
        // B's centroid moving from beyond the bounding circles to A's
        // centroid, turning: apart, near contact, overlapping.
        for (const pose& q : test_poses::approach(A, B, 150, {2.1, -1, 0.2, 2.5})) {
            const frame_result want = exact.collide(q), got = quad_det.collide(q);
            INFO(pair << ": tx = " << q.tx << ", ty = " << q.ty << ", theta = " << q.theta);
            CHECK(got.collides == want.collides);
            CHECK(got.pairs == want.pairs);
            ++frames;
            collisions += want.collides;
        }
    }
    CHECK(collisions >= frames / 4);
}

}  // namespace

TEST_CASE("quad: traits", "[multiprecision]") { check_traits<quad>("quad"); }

TEST_CASE("quad: the detector agrees with the exact one on generic frames", "[multiprecision][detect]") {
    check_detector<quad>();
}

#ifdef INFLUENCE2D_HAS_FLOAT128
TEST_CASE("float128: traits", "[multiprecision]") { check_traits<float128>("float128"); }

TEST_CASE("float128: the detector agrees with the exact one on generic frames", "[multiprecision][detect]") {
    check_detector<float128>();
}
#endif
