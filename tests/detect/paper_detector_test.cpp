// SPDX-License-Identifier: BSL-1.0
// The paper-literal variant fails exactly where docs/method.md section 7 says it
// must; the sound detector answers each of these cases correctly.

#include <catch2/catch.hpp>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/detect/paper_detector.hpp"
#include "support/shapes.hpp"

using namespace influence2d;
using test_shapes::square;

TEMPLATE_TEST_CASE("paper-literal: an unchanged mask skips the test and misses the collision", "[paper]", double,
                   influence2d::exact_rational) {
    using NT = TestType;
    // B slides left along y = 2 into A, its centroid always in the cone of A's
    // right edge: the mask never changes after the first tested frame.
    //   +------+
    //   |  A   |      <-- [B]
    //   +------+
    const polygon a = square(0, 0, 4), b = square(0, 0, 1);
    paper_detector<NT> paper(a, b);
    detector<NT> sound(a, b);
    bool paper_hit = false, sound_hit = false;
    for (int k = 0; k <= 70; ++k) {
        const pose p{10 - 0.1 * k, 1.5, 0};  // ends with B over [3,4] x [1.5,2.5]
        paper_hit = paper.collide(p).collides;
        sound_hit = sound.collide(p).collides;
    }
    CHECK(sound_hit);
    CHECK_FALSE(paper_hit);
}

TEMPLATE_TEST_CASE("paper-literal: the length-r gate misses a contact on a non-convex polygon", "[paper]", double,
                   influence2d::exact_rational) {
    using NT = TestType;
    // B overlaps the end of the C's lower arm, its centroid in the opening,
    // where no influence area of the C reaches (the cones leave the opening bare).
    //   +------+
    //   | +----+
    //   | |
    //   | +---[B]
    //   +------+
    const polygon a = test_shapes::c_shape(), b = square(0, 0, 0.4);
    const pose p{5.9, 0.9, 0};  // B = [5.9,6.3] x [0.9,1.3]
    CHECK(brute_force_detector<NT>(a, b).collide(p).collides);
    CHECK(detector<NT>(a, b).collide(p).collides);
    CHECK_FALSE(paper_detector<NT>(a, b).collide(p).collides);
}

TEMPLATE_TEST_CASE("paper-literal: straddling an edge's line beyond its end is a false collision", "[paper]", double,
                   influence2d::exact_rational) {
    using NT = TestType;
    //          [B]  B = [4.3,4.5] x [3.5,4.5] crosses the line y = 4 at x > 4
    //   +------+ ....
    //   |  A   |
    const polygon a = square(0, 0, 4);
    const polygon b({test_shapes::ring({{0, 0}, {0.2, 0}, {0.2, 1}, {0, 1}})});
    const pose p{4.3, 3.5, 0};
    CHECK_FALSE(brute_force_detector<NT>(a, b).collide(p).collides);
    CHECK_FALSE(detector<NT>(a, b).collide(p).collides);
    CHECK(paper_detector<NT>(a, b).collide(p).collides);
}

TEMPLATE_TEST_CASE("paper-literal: containment without boundary contact is missed", "[paper]", double,
                   influence2d::exact_rational) {
    using NT = TestType;
    const polygon a = square(0, 0, 4), b = square(0, 0, 1);
    const pose p{1.5, 1.5, 0};  // B in the middle of A
    CHECK(detector<NT>(a, b).collide(p).collides);
    CHECK_FALSE(paper_detector<NT>(a, b).collide(p).collides);
}

TEMPLATE_TEST_CASE("paper-literal: where its premises hold it answers correctly", "[paper]", double,
                   influence2d::exact_rational) {
    using NT = TestType;
    const polygon a = square(0, 0, 4), b = square(0, 0, 1);
    // Far away: the circles reject; crossing the right edge on the first frame.
    CHECK_FALSE(paper_detector<NT>(a, b).collide({9, 1.5, 0}).collides);
    CHECK(paper_detector<NT>(a, b).collide({3.5, 1.5, 0}).collides);
}

TEMPLATE_TEST_CASE("paper-literal: a multipolygon part held by B is found only by the straddle defect",
                   "[paper][multipolygon]", double, influence2d::exact_rational) {
    // A: unit squares at x = 0 and x = 10; B: the square [-1, 2]^2 holding
    // the second part at tx = 9.5, with no boundary contact. The sound
    // detector answers by containment (no pair). The literal algorithm has
    // no containment test: its yes comes from B's edges straddling the lines
    // of the held part's edges, pairs whose segments do not meet.
    using NT = TestType;
    const polygon a({test_shapes::square_ring(0, 0, 1), test_shapes::square_ring(10, 0, 1)});
    const polygon b = square(-1, -1, 3);
    const pose p{9.5, 0, 0};
    detector_options o;
    o.witness = true;
    const frame_result sound = detector<NT>(a, b, o).collide(p);
    CHECK(sound.collides);
    CHECK(sound.pairs.empty());
    const frame_result literal = paper_detector<NT>(a, b, o).collide(p);
    CHECK(literal.collides);
    CHECK_FALSE(literal.pairs.empty());
}
