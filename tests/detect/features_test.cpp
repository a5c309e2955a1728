// SPDX-License-Identifier: BSL-1.0
// Compile-time features of the detector: every feature set answers as the
// brute-force reference on what it supports, a detector without a feature
// stores less and refuses what needs it, and without coherence it gathers
// candidates every frame.

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/shapes.hpp"
#include "verification/families.hpp"

using namespace influence2d;

namespace {

template <unsigned Bits>
using only = feature_set<Bits>;
template <unsigned Bits>
using all_but = feature_set<features::all & ~Bits>;

/// A random walk of B through and around A: small steps, some jumps.
std::vector<pose> walk(const polygon& a, std::uint64_t seed, int frames) {
    std::mt19937_64 rng(seed);
    const box& bb = a.bounds();
    const double w = bb.max_x - bb.min_x, h = bb.max_y - bb.min_y;
    double x = bb.min_x - 0.2 * w, y = bb.min_y + 0.5 * h, th = 0;
    std::vector<pose> out;
    for (int k = 0; k < frames; ++k) {
        const double step = (k % 97 == 0) ? 0.5 : 0.02;
        const auto u = [&] { return static_cast<double>(rng() % 2001) / 1000 - 1; };
        x = std::clamp(x + step * w * u(), bb.min_x - 0.5 * w, bb.max_x + 0.5 * w);
        y = std::clamp(y + step * h * u(), bb.min_y - 0.5 * h, bb.max_y + 0.5 * h);
        th += 0.01;
        out.push_back({x, y, th});
    }
    return out;
}

/// Runs detector<NT, F> and the brute-force reference over the walk; returns
/// the colliding frames (and checks every frame).
template <class NT, class F>
int check_walk(const polygon& a, const polygon& b, const detector_options& o, const std::vector<pose>& poses) {
    detector<NT, F> d(a, b, o);
    // The same frames asked with the witnesses written into one vector kept
    // across frames (collide(q, pairs)).
    detector<NT, F> into(a, b, o);
    std::vector<edge_pair> pairs{{7, 7}};  // (cleared by every frame)
    brute_force_detector<NT> ref(a, b, o);
    int collisions = 0;
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const frame_result got = d.collide(poses[k]);
        const frame_result want = ref.collide(poses[k]);
        INFO("frame " << k << " features " << F::bits << " d " << o.distance << " witness " << o.witness);
        REQUIRE(got.collides == want.collides);
        REQUIRE(got.pairs == want.pairs);
        REQUIRE(into.collide(poses[k], pairs) == want.collides);
        REQUIRE(pairs == want.pairs);
        collisions += want.collides;
    }
    return collisions;
}

polygon small_b() { return polygon({test_shapes::ring({{0, 0}, {0.5, 0}, {0.5, 0.25}, {0.25, 0.5}, {0, 0.25}})}); }

}  // namespace

TEMPLATE_TEST_CASE("features: every feature set answers as the reference", "[detector][features]", double,
                   influence2d::exact_rational) {
    using NT = TestType;
    const polygon a = test_shapes::c_shape(), b = small_b();
    const std::vector<pose> poses = walk(a, 5, 1500);
    const detector_options plain;  // yes/no, d = 0 (coherence option on: ignored where not built in)
    detector_options witness;
    witness.witness = true;
    detector_options near;
    near.distance = 0.125;
    detector_options everything = witness;
    everything.distance = 0.125;

    const int plain_hits = check_walk<NT, minimal_features>(a, b, plain, poses);
    CHECK(plain_hits > 100);
    CHECK(plain_hits < 1400);
    CHECK(check_walk<NT, only<features::coherence>>(a, b, plain, poses) == plain_hits);
    CHECK(check_walk<NT, only<features::statistics>>(a, b, plain, poses) == plain_hits);
    CHECK(check_walk<NT, only<features::holes>>(a, b, plain, poses) == plain_hits);
    CHECK(check_walk<NT, all_features>(a, b, plain, poses) == plain_hits);
    CHECK(check_walk<NT, only<features::witness>>(a, b, witness, poses) == plain_hits);
    CHECK(check_walk<NT, only<features::witness | features::coherence>>(a, b, witness, poses) == plain_hits);
    const int near_hits = check_walk<NT, only<features::distance>>(a, b, near, poses);
    CHECK(near_hits > plain_hits);
    CHECK(check_walk<NT, all_but<features::witness>>(a, b, near, poses) == near_hits);
    CHECK(check_walk<NT, all_but<features::statistics>>(a, b, everything, poses) == near_hits);
    CHECK(check_walk<NT, all_features>(a, b, everything, poses) == near_hits);
}

TEST_CASE("features: holes only with features::holes", "[detector][features]") {
    using verification::family;
    const polygon a(verification::make_family_rings(family::with_hole, 32, 7));
    const polygon b(verification::make_family_rings(family::convex, 8, 8));
    REQUIRE(a.ring_count() > 1);
    CHECK_THROWS_AS((detector<double, minimal_features>(a, b)), invalid_input);
    CHECK_THROWS_AS((detector<double, minimal_features>(b, a)), invalid_input);
    CHECK_THROWS_WITH((detector<double, all_but<features::holes>>(a, b)), Catch::Contains("static polygon has"));
    // With holes: B wanders over the hole and across the rings.
    const std::vector<pose> poses = walk(a, 9, 1500);
    const int hits = check_walk<double, only<features::holes>>(a, b, {}, poses);
    CHECK(hits > 0);
    CHECK(hits < 1500);
    CHECK(check_walk<exact_rational, only<features::holes | features::coherence>>(a, b, {}, poses) == hits);
}

TEST_CASE("features: options a detector was built without are refused", "[detector][features]") {
    const polygon a = test_shapes::square(0, 0, 4), b = test_shapes::square(0, 0, 1);
    detector_options o;
    o.witness = true;
    CHECK_THROWS_AS((detector<double, all_but<features::witness>>(a, b, o)), std::invalid_argument);
    CHECK_NOTHROW((detector<double, only<features::witness>>(a, b, o)));
    o = {};
    o.distance = 0.5;
    CHECK_THROWS_AS((detector<double, all_but<features::distance>>(a, b, o)), std::invalid_argument);
    CHECK_NOTHROW((detector<double, only<features::distance>>(a, b, o)));
    o.distance = -1;
    CHECK_THROWS_AS((detector<double>(a, b, o)), std::invalid_argument);
    o.distance = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS((detector<double>(a, b, o)), std::invalid_argument);
}

TEST_CASE("features: a detector without a feature stores less", "[detector][features]") {
    // Every feature with state makes the detector larger; holes has code only.
    STATIC_REQUIRE(sizeof(detector<double, minimal_features>) < sizeof(detector<double>));
    CHECK(sizeof(detector<double, all_but<features::witness>>) < sizeof(detector<double>));
    CHECK(sizeof(detector<double, all_but<features::distance>>) < sizeof(detector<double>));
    CHECK(sizeof(detector<double, all_but<features::coherence>>) < sizeof(detector<double>));
    CHECK(sizeof(detector<double, all_but<features::statistics>>) < sizeof(detector<double>));
    CHECK(sizeof(detector<exact_rational, minimal_features>) < sizeof(detector<exact_rational>));

    // The same scene run by both: the full detector also holds the witness
    // pairs it collected.
    const polygon a = test_shapes::c_shape(), b = small_b();
    detector_options o;
    o.witness = true;
    detector<double, minimal_features> minimal(a, b);
    detector<double> full(a, b, o);
    for (const pose& p : walk(a, 3, 500)) {
        minimal.collide(p);
        full.collide(p);
    }
    CHECK(minimal.state_bytes() < full.state_bytes());
    CHECK(minimal.state_bytes() >= sizeof(minimal));
}

TEST_CASE("features: without coherence every frame takes the edge trees", "[detector][features]") {
    // B orbits A close by in small steps: most frames can reuse candidates.
    const polygon a = test_shapes::c_shape(), b = small_b();
    const std::vector<pose> poses = circular_trajectory(a, b, 2000, 0.05);
    detector<double, only<features::statistics>> fresh(a, b);
    detector<double, only<features::statistics | features::coherence>> coherent(a, b);
    for (const pose& p : poses) {
        fresh.collide(p);
        coherent.collide(p);
    }
    const detector_statistics& s = fresh.statistics();
    CHECK(s.frames == poses.size());
    CHECK(s.circle_rejections < s.frames / 2);
    CHECK(s.candidate_rebuilds == 0);
    CHECK(s.jump_frames == s.frames - s.circle_rejections);
    // With coherence only the first two frames (no steps seen yet) jump, and
    // candidates gathered serve many frames each.
    const detector_statistics& c = coherent.statistics();
    CHECK(c.jump_frames <= 2);
    CHECK(c.candidate_rebuilds > 0);
    CHECK(c.candidate_rebuilds < (c.frames - c.circle_rejections) / 4);
}
