// SPDX-License-Identifier: BSL-1.0
// Scenes whose coordinate products leave double's range. Ring orientation was
// once decided with double products there, so a hole could be stored with the
// outer ring's orientation and the exact detectors reported B, inside the hole,
// as colliding; the CGAL reference said it does not.

#include <catch2/catch.hpp>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/io/wkt.hpp"
#include "verification/cgal_reference.hpp"

using namespace influence2d;

namespace {

struct scene {
    const char* name;
    const char* a;
    const char* b;
    pose p;
};

//  +-------------+
//  |  +-------+  |   B, a small triangle, in the middle of the square hole
//  |  |  |\   |  |
//  |  |  |_\  |  |
//  |  +-------+  |
//  +-------------+
const scene scenes[] = {
    {"1e200",
     "POLYGON((0 0,1e200 0,1e200 1e200,0 1e200,0 0),(2e199 2e199,2e199 8e199,8e199 8e199,8e199 2e199,2e199 2e199))",
     "POLYGON((0 0,1e199 0,0 1e199,0 0))",
     {4.0000000000000004e+199, 4.0000000000000004e+199, 0}},
    {"subnormal, both rings clockwise",
     "POLYGON((0 0,0 4.9406564584124654e-322,4.9406564584124654e-322 4.9406564584124654e-322,"
     "4.9406564584124654e-322 0,0 0),(9.8813129168249309e-323 9.8813129168249309e-323,9.8813129168249309e-323 "
     "3.9525251667299724e-322,3.9525251667299724e-322 3.9525251667299724e-322,3.9525251667299724e-322 "
     "9.8813129168249309e-323,9.8813129168249309e-323 9.8813129168249309e-323))",
     "POLYGON((0 0,4.9406564584124654e-323 0,0 4.9406564584124654e-323,0 0))",
     {1.9762625833649862e-322, 1.9762625833649862e-322, 0}},
    {"1e-170, clockwise outer ring",
     "POLYGON((0 0,0 1e-170,1e-170 1e-170,1e-170 0,0 0),(2e-171 2e-171,2e-171 8e-171,8e-171 8e-171,8e-171 "
     "2e-171,2e-171 "
     "2e-171))",
     "POLYGON((0 0,1e-171 0,0 1e-171,0 0))",
     {3.9999999999999999e-171, 3.9999999999999999e-171, 0}},
};

}  // namespace

TEST_CASE("extreme range: B inside a hole at 1e200, 1e-170 and subnormal scale", "[detector][extreme]") {
    for (const scene& s : scenes) {
        INFO(s.name);
        const polygon a = read_wkt(s.a), b = read_wkt(s.b);
        CHECK_FALSE(verification::cgal_reference(a, b).collide(s.p).collides);
        CHECK_FALSE(detector<exact_rational>(a, b).collide(s.p).collides);
        CHECK_FALSE(brute_force_detector<exact_rational>(a, b).collide(s.p).collides);
        CHECK_FALSE(certified_detector<detector>(a, b).collide(s.p).collides);
    }
}

TEST_CASE("extreme range: float detectors refuse polygons beyond float's range", "[detector][extreme]") {
    const polygon small = read_wkt("POLYGON((0 0, 1 0, 0 1, 0 0))");
    const polygon huge = read_wkt("POLYGON((0 0, 1e39 0, 0 1e39, 0 0))");
    CHECK_THROWS_WITH(detector<float>(huge, small), Catch::Contains("static polygon") && Catch::Contains("float"));
    CHECK_THROWS_WITH(detector<float>(small, huge), Catch::Contains("moving polygon") && Catch::Contains("float"));
    CHECK_THROWS_AS(brute_force_detector<float>(huge, small), invalid_input);
    // The vertex named as the file has it, in the fewest digits that read
    // back to it (not a fixed six decimals: 40 digits for 1e39, and 0.000000
    // for a tiny coordinate).
    CHECK_THROWS_WITH(detector<float>(huge, small), Catch::Contains("vertex (1e+39, 0)"));
    const polygon tiny_and_huge = read_wkt("POLYGON((1e-30 0, 1e39 0, 0 1e39, 1e-30 0))");
    CHECK_THROWS_WITH(detector<float>(tiny_and_huge, small), Catch::Contains("vertex (1e+39, 0)"));
    CHECK_THROWS_WITH(detector<float>(read_wkt("POLYGON((1e-30 -3e39, 1 0, 0 1, 1e-30 -3e39))"), small),
                      Catch::Contains("vertex (1e-30, -3e+39)"));
    // double and exact take them; a translation beyond float's range poses B
    // at infinity in float, defined behaviour.
    CHECK_FALSE(detector<double>(huge, small).collide({2e39, 0, 0}).collides);
    CHECK(number_traits<float>::from_double(1e39) == std::numeric_limits<float>::infinity());
    CHECK(number_traits<float>::from_double(-1e39) == -std::numeric_limits<float>::infinity());
    CHECK(number_traits<float>::from_double(0.5) == 0.5f);
}
