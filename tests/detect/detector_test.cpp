// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/detect/paper_detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/random.hpp"
#include "support/shapes.hpp"
#include "verification/cgal_reference.hpp"

using namespace influence2d;
using test_shapes::square;

namespace {

template <class NT>
struct answers {
    frame_result sound, sound_no_coherence, sound_band, brute;
};

/// Runs one pose through every configuration of the sound detector and the
/// brute-force reference (fresh detectors: no coherence carried in).
template <class NT>
answers<NT> ask(const polygon& a, const polygon& b, pose p, double d = 0) {
    detector_options o;
    o.witness = true;
    o.distance = d;
    answers<NT> r;
    r.sound = detector<NT>(a, b, o).collide(p);
    r.brute = brute_force_detector<NT>(a, b, o).collide(p);
    o.temporal_coherence = false;
    r.sound_no_coherence = detector<NT>(a, b, o).collide(p);
    o.shape = extended_area::band;
    r.sound_band = detector<NT>(a, b, o).collide(p);
    return r;
}

template <class NT>
void check_same(const answers<NT>& r) {
    CHECK(r.sound.collides == r.brute.collides);
    CHECK(r.sound.pairs == r.brute.pairs);
    CHECK(r.sound_no_coherence.pairs == r.brute.pairs);
    CHECK(r.sound_band.pairs == r.brute.pairs);
    CHECK(r.sound_no_coherence.collides == r.brute.collides);
    CHECK(r.sound_band.collides == r.brute.collides);
}

}  // namespace

TEMPLATE_TEST_CASE("detector: contacts between two squares", "[detector]", INFLUENCE2D_NUMBER_TYPES) {
    using NT = TestType;
    const polygon a = square(0, 0, 4), b = square(0, 0, 2);
    SECTION("apart") {
        const auto r = ask<NT>(a, b, {5, 0, 0});
        check_same(r);
        CHECK_FALSE(r.sound.collides);
    }
    SECTION("touching at a vertex") {
        //        +--+
        //        |B |
        //  +-----+--+  B's corner (0,0) on A's corner (4,4)
        //  |  A  |
        const auto r = ask<NT>(a, b, {4, 4, 0});
        check_same(r);
        CHECK(r.sound.collides);
        // A's edges 1 and 2 meet B's edges 3 and 0 at the shared corner.
        CHECK(r.sound.pairs == std::vector<edge_pair>{{1, 0}, {1, 3}, {2, 0}, {2, 3}});
    }
    SECTION("touching along an edge") {
        const auto r = ask<NT>(a, b, {4, 1, 0});
        check_same(r);
        CHECK(r.sound.collides);
    }
    SECTION("vertex on the interior of an edge") {
        // B rotated by 45 degrees would not be exact; use a triangle instead.
        const polygon t({test_shapes::ring({{0, 0}, {1, -1}, {1, 1}})});
        const auto r = ask<NT>(a, t, {4, 2, 0});  // its vertex (0,0) at (4,2)
        check_same(r);
        CHECK(r.sound.collides);
    }
    SECTION("B inside A, no boundary contact") {
        const auto r = ask<NT>(a, b, {1, 1, 0});
        check_same(r);
        CHECK(r.sound.collides);
        CHECK(r.sound.pairs.empty());
    }
    SECTION("A inside B") {
        const auto r = ask<NT>(square(0, 0, 1), square(0, 0, 6), {-2, -2, 0});
        check_same(r);
        CHECK(r.sound.collides);
        CHECK(r.sound.pairs.empty());
    }
}

TEMPLATE_TEST_CASE("detector: holes", "[detector]", INFLUENCE2D_NUMBER_TYPES) {
    using NT = TestType;
    const polygon a = test_shapes::square_with_hole();  // hole [2,6]^2
    const polygon b = square(0, 0, 2);
    SECTION("B inside the hole does not collide") {
        const auto r = ask<NT>(a, b, {3, 3, 0});
        check_same(r);
        CHECK_FALSE(r.sound.collides);
    }
    SECTION("B touching the hole's boundary from inside collides") {
        const auto r = ask<NT>(a, b, {4, 3, 0});
        check_same(r);
        CHECK(r.sound.collides);
    }
    SECTION("B across the hole's boundary") {
        const auto r = ask<NT>(a, b, {5, 3, 0});
        check_same(r);
        CHECK(r.sound.collides);
    }
    SECTION("separation distance inside the hole") {
        // B in [3,5]^2: 1 from every side of the hole.
        check_same(ask<NT>(a, b, {3, 3, 0}, 1.0));
        CHECK(ask<NT>(a, b, {3, 3, 0}, 1.0).sound.collides);
        CHECK_FALSE(ask<NT>(a, b, {3, 3, 0}, 0.75).sound.collides);
    }
}

TEMPLATE_TEST_CASE("detector: separation distance", "[detector]", INFLUENCE2D_NUMBER_TYPES) {
    using NT = TestType;
    const polygon a = square(0, 0, 4), b = square(0, 0, 2);
    // Gap of exactly 0.5 between x = 4 and x = 4.5.
    CHECK(ask<NT>(a, b, {4.5, 1, 0}, 0.5).sound.collides);
    CHECK_FALSE(ask<NT>(a, b, {4.5, 1, 0}, 0.25).sound.collides);
    CHECK_FALSE(ask<NT>(a, b, {4.5, 1, 0}, 0).sound.collides);
    check_same(ask<NT>(a, b, {4.5, 1, 0}, 0.5));
    // Diagonal gap: corner (4,4) to corner (5,5) is sqrt(2) apart.
    CHECK(ask<NT>(a, b, {5, 5, 0}, 1.5).sound.collides);
    CHECK_FALSE(ask<NT>(a, b, {5, 5, 0}, 1.25).sound.collides);
}

TEST_CASE("detector: a near miss by 2^-40 is not a collision, exactly", "[detector]") {
    const polygon a = square(0, 0, 4), b = square(0, 0, 2);
    const auto r = ask<exact_rational>(a, b, {4 + 0x1p-40, 1, 0});
    check_same(r);
    CHECK_FALSE(r.sound.collides);
    CHECK(ask<exact_rational>(a, b, {4 - 0x1p-40, 1, 0}).sound.collides);
}

TEMPLATE_TEST_CASE("detector: temporal coherence over a sequence equals the reference", "[detector]", double,
                   influence2d::exact_rational) {
    using NT = TestType;
    const polygon a = test_shapes::c_shape();
    const polygon b({test_shapes::ring({{0, 0}, {0.5, 0}, {0.5, 0.25}, {0.25, 0.5}, {0, 0.25}})});
    for (const double d : {0.0, 0.25}) {
        detector_options o;
        o.witness = true;
        o.distance = d;
        detector<NT> sound(a, b, o);
        brute_force_detector<NT> brute(a, b, o);
        // Everything built before the first frame: the same answers.
        detector<NT> built(a, b, o);
        const std::size_t lazy_bytes = built.state_bytes();
        built.build_structures();
        CHECK(built.state_bytes() > lazy_bytes);  // the edge grid
        certified_detector<detector> certified(a, b, o);
        certified.build_structures();
        test_random::rng rng(11);
        // A random walk through and around the C, small steps and jumps.
        double x = -1, y = 3, th = 0;
        int collisions = 0;
        for (int k = 0; k < 3000; ++k) {
            const double step = (k % 97 == 0) ? 3.0 : 0.05;
            x = std::clamp(x + step * (static_cast<double>(rng.index(2001)) / 1000 - 1), -2.0, 8.0);
            y = std::clamp(y + step * (static_cast<double>(rng.index(2001)) / 1000 - 1), -2.0, 8.0);
            th += 0.01;
            const pose p{x, y, th};
            const auto s = sound.collide(p);
            const auto r = brute.collide(p);
            INFO("frame " << k << " pose " << x << ", " << y << ", " << th << " d " << d);
            REQUIRE(s.collides == r.collides);
            REQUIRE(s.pairs == r.pairs);
            const auto e = built.collide(p);
            REQUIRE(e.collides == r.collides);
            REQUIRE(e.pairs == r.pairs);
            REQUIRE(certified.collide(p).collides == r.collides);
            collisions += r.collides;
        }
        CHECK(collisions > 300);
        CHECK(collisions < 2700);
        CHECK(sound.statistics().candidate_rebuilds < sound.statistics().frames);
    }
}

TEST_CASE("detector: exact at the ends of double's range", "[detector]") {
    // A square of side 4s and a triangle of side s, for scales s where squares of
    // coordinates overflow or underflow in double. The double filters once
    // dropped candidate edges here (their squares left double's range), so the
    // exact detector missed contacts that the brute-force reference found.
    for (const double s : {1e-300, 1e-160, 1.0, 1e160, 1e300, 1e307}) {
        const polygon a({test_shapes::ring({{0, 0}, {4 * s, 0}, {4 * s, 4 * s}, {0, 4 * s}})});
        const polygon b({test_shapes::ring({{0, 0}, {s, 0}, {0, s}})});
        for (const double x : {-2.0, -1.0, -0.5, 1.0, 4.0, 4.5}) {
            INFO("scale " << s << ", x " << x);
            const pose p{x * s, s, 0};
            const bool expected = x >= -1 && x <= 4;  // touching at x = -1 and x = 4
            const auto r = ask<exact_rational>(a, b, p);
            check_same(r);
            CHECK(r.brute.collides == expected);
        }
    }
}

TEST_CASE("detector: exact when the moving polygon's own coordinates are far from its origin", "[detector]") {
    // B is given around (2^50, 2^50) and posed back near A by a translation of
    // about -2^50: the double positions used by the filters are then off by up
    // to ulp(2^50) = 0.25, which the filters' margin must cover.
    const double far = 0x1p50;
    const polygon a = square(0, 0, 4);
    const polygon b({test_shapes::ring({{far, far}, {far + 1, far}, {far + 1, far + 1}, {far, far + 1}})});
    for (const double x : {-1.5, -1.0, -0.75, 0.0, 3.5, 4.0, 4.25}) {
        INFO("x " << x);
        const pose p{x - far, 1 - far, 0};
        const auto r = ask<exact_rational>(a, b, p);
        check_same(r);
        CHECK(r.brute.collides == (x >= -1 && x <= 4));
    }
    // Turned: the pose is then inexact in double, exact in the exact type.
    for (int k = 0; k < 200; ++k) {
        const double theta = 0.03 * k;
        const pose p{-far * std::cos(theta) + far * std::sin(theta) + 0.02 * k,
                     -far * std::sin(theta) - far * std::cos(theta) + 1, theta};
        check_same(ask<exact_rational>(a, b, p));
    }
}

TEST_CASE("detector: a large moving polygon passing close by, and one holding A, equal the reference", "[detector]") {
    // B is a long thin bar as long as A is wide: its bounding circle covers
    // most of A while its edges keep clear of A's circle (the filter of step
    // 3), or reach into it; then B grown into a frame around A (a square with
    // a hole) holds A without boundary contact (the containment of step 5).
    std::vector<point<double>> disc;  // a 64-gon of radius ~10 on a 2^-20 grid
    for (int k = 0; k < 64; ++k)
        disc.push_back({std::ldexp(std::round(std::ldexp(10 * std::cos(k * 0.09817477042468103), 20)), -20),
                        std::ldexp(std::round(std::ldexp(10 * std::sin(k * 0.09817477042468103), 20)), -20)});
    const polygon a({test_shapes::ring(disc)});
    // The bar has a dent, so that its frames take the steps above rather
    // than the separating-edge test of two small convex polygons.
    const polygon bar = read_wkt("POLYGON((-20 -0.5, 0 -0.4, 20 -0.5, 20 0.5, -20 0.5, -20 -0.5))");
    const polygon big = test_shapes::square(-30, -30, 60);
    const polygon frame = read_wkt(
        "POLYGON((-30 -30, 30 -30, 30 30, -30 30, -30 -30),"
        "(-12 -12, -12 12, 12 12, 12 -12, -12 -12))");
    for (const polygon* b : {&bar, &big, &frame}) {
        detector_options o;
        o.witness = true;
        detector<exact_rational> exact(a, *b, o);
        detector<double> fast(a, *b, o);
        verification::cgal_reference reference(a, *b, 0, true);
        for (int k = 0; k <= 400; ++k) {
            // bar: centre from 12 above A's centre (edges 1.5 clear of A's
            // circle) down through A; frame: small shifts about A.
            const double s = static_cast<double>(k) / 400;
            const pose p = b == &bar ? pose{0.01 * k, 12 - 15 * s, 0.001 * k} : pose{3 * s - 1.5, 1 - 2 * s, 0.1 * s};
            const frame_result want = reference.collide(p);
            const frame_result got = exact.collide(p);
            INFO("k = " << k << (b == &bar ? " (bar)" : b == &big ? " (big)" : " (frame)"));
            CHECK(got.collides == want.collides);
            CHECK(got.pairs == want.pairs);
            CHECK(fast.collide(p).collides == want.collides);
        }
        if (b == &bar) CHECK(exact.statistics().disc_rejections > 0);
        if (b == &big) CHECK(exact.collide({0, 0, 0}).collides);          // A inside B: the regions meet
        if (b == &frame) CHECK_FALSE(exact.collide({0, 0, 0}).collides);  // A in B's hole: they do not
    }
}

namespace {

/// The message of the invalid_input that f throws ("" when it throws none).
template <class F>
std::string refusal(F&& f) {
    try {
        f();
    } catch (const influence2d::invalid_input& e) {
        return e.what();
    }
    return "";
}

/// `sound`: the detector answers exactly as the reference (all but the
/// paper-literal one, kept to show its failures).
template <class Detector>
void check_refuses_bad_input(bool sound = true) {
    using influence2d::pose;
    const influence2d::polygon empty;
    const influence2d::polygon sq = test_shapes::square(0, 0, 1);
    CHECK(refusal([&] { Detector d(empty, sq); }) == "the static polygon is empty (it has no ring)");
    CHECK(refusal([&] { Detector d(sq, empty); }) == "the moving polygon is empty (it has no ring)");
    Detector d(sq, sq);
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    CHECK(refusal([&] { d.collide(pose{nan, 0, 0}); }) == "pose: tx is NaN, not a finite number");
    CHECK(refusal([&] { d.collide(pose{0, inf, 0}); }) == "pose: ty is +infinity, not a finite number");
    CHECK(refusal([&] { d.collide(pose{0, 0, -inf}); }) == "pose: theta is -infinity, not a finite number");
    CHECK(refusal([&] { d.collide(pose{nan, inf, 0}); }) == "pose: tx is NaN, not a finite number");
    // The detector is still usable after a refused pose: a refused pose
    // changes nothing, so its answers are those of a twin that was never
    // asked the refused poses; and a sound detector's are the exact
    // brute-force reference's.
    //   +--+--+          B = [0,1]^2 posed at (0.5, 0.5): overlaps A = [0,1]^2
    //   |A |B |
    //   +--+--+          at (3, 0), turned by any angle, B stays within
    //                    sqrt 2 of (3, 0): apart from A
    const auto reference = [&](const pose& p) {
        return influence2d::brute_force_detector<influence2d::exact_rational>(sq, sq).collide(p).collides;
    };
    const pose overlapping{0.5, 0.5, 0}, far_turned{3, 0, 1e300};  // a huge but finite angle is a pose
    REQUIRE(reference(overlapping));
    REQUIRE_FALSE(reference(far_turned));
    Detector twin(sq, sq);
    for (const pose& p : {overlapping, far_turned, pose{nan, 0, 0}, overlapping}) {
        INFO("pose " << p.tx << " " << p.ty << " " << p.theta);
        if (std::isnan(p.tx)) {
            CHECK(refusal([&] { d.collide(p); }) == "pose: tx is NaN, not a finite number");
            continue;
        }
        influence2d::frame_result answer;
        REQUIRE_NOTHROW(answer = d.collide(p));
        const influence2d::frame_result expected = twin.collide(p);
        CHECK(answer.collides == expected.collides);
        CHECK(answer.pairs == expected.pairs);
        if (sound) CHECK(answer.collides == reference(p));
    }
}

}  // namespace

TEST_CASE("detector: an empty polygon and a non-finite pose are refused with invalid_input", "[detector][input]") {
    check_refuses_bad_input<influence2d::detector<double>>();
    check_refuses_bad_input<influence2d::detector<float, influence2d::minimal_features>>();
    check_refuses_bad_input<influence2d::detector<influence2d::exact_rational>>();
    check_refuses_bad_input<influence2d::brute_force_detector<double>>();
    check_refuses_bad_input<influence2d::paper_detector<double>>(false);
    check_refuses_bad_input<influence2d::certified_detector<influence2d::detector>>();
}

TEST_CASE("detector: a ring of B inside A by less than its posing's rounding is located exactly", "[detector]") {
    // B (a small triangle far from its own origin, so that its posing in
    // double errs by about 1e-13) lies inside A, its first vertex exactly
    // posed at 1 - t with t > 0 tiny, where A's long right edge is x = 1,
    // and posed in double beyond 1: the boundaries do not meet, so
    // only the containment test answers, and a crossing settled in double
    // without B's posing margin would put the vertex right of A's edge,
    // outside A. A is not convex (a notch on its left), so that no
    // separating-edge route takes the frame; each pose gets a fresh detector
    // (no deep cells built).
    const auto one_ring_of = [](std::vector<point<double>> v) { return polygon({test_shapes::ring(std::move(v))}); };
    const polygon a = one_ring_of({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0.6}, {0.3, 0.5}, {0, 0.4}});
    test_random::rng r(20261202);
    using Q = exact_rational;
    int found = 0;
    for (int k = 0; k < 400000 && found < 20; ++k) {
        // B's first vertex q, posed by (tx, theta) to about x = 1.
        // (tx one ulp above 1 - (c qx - s qy) in double: the posed double is
        // then 1 plus that ulp, and the exact place is below 1 when the
        // products' roundings took c qx - s qy up by more than the ulp.)
        const double theta = r.uniform(-1, 1), qx = r.uniform(1000, 4000), qy = r.uniform(-4000, 4000);
        const rotation_pose t(pose{0, 0, theta});
        const double tx = std::nextafter(1 - (t.c * qx - t.s * qy), 2e4),
                     ty = r.uniform(0.2, 0.3) - (t.s * qx + t.c * qy);
        const Q x = Q(t.c) * Q(qx) - Q(t.s) * Q(qy) + Q(tx);
        const pose p{tx, ty, theta};
        if (!(x < Q(1) && rotation_pose(p).apply<double>({qx, qy}).x > 1)) continue;
        ++found;
        const polygon b = one_ring_of({{qx, qy}, {qx - 0.1, qy + 0.05}, {qx - 0.1, qy - 0.05}});
        const bool expected = verification::cgal_reference(a, b).collide(p).collides;
        CHECK(expected);  // inside A
        CHECK(detector<Q>(a, b).collide(p).collides == expected);
        CHECK(certified_detector<detector>(a, b).collide(p).collides == expected);
    }
    CHECK(found >= 20);
}
