// SPDX-License-Identifier: BSL-1.0
// Batches on several threads: the answers of the serial loop, for poses of
// one pair (detectors on shared prepared polygons) and for many pairs
// (one-shot queries); errors come back to the caller.

#include <catch2/catch.hpp>

#include "support/effort.hpp"

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/exact/certified_intersects.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/query/batch.hpp"
#include "verification/families.hpp"

namespace {

using namespace influence2d;
using namespace influence2d::verification;

/// A pose stream mixing jumps and small steps: random poses near contact,
/// each followed by a few steps.
std::vector<pose> mixed_poses(const polygon& a, const polygon& b, std::size_t count, std::uint64_t seed) {
    std::vector<pose> out;
    for (const pose& p : random_poses(a, b, count / 4 + 1, 40, 110, seed))
        for (int k = 0; k < 4 && out.size() < count; ++k) out.push_back({p.tx + 0.05 * k, p.ty, p.theta + 0.01 * k});
    return out;
}

}  // namespace

TEST_CASE("batch: many poses of one pair answer as the serial loop, on every thread count", "[batch]") {
    const std::size_t frames = static_cast<std::size_t>(test_effort::scaled(600));
    for (family f : {family::contour, family::with_hole, family::starred}) {
        const polygon a = make_family_polygon(f, 256, default_family_seed);
        const polygon b = make_family_polygon(f, 32, default_family_seed + 3);
        const std::vector<pose> poses = mixed_poses(a, b, frames, 5);
        const auto a_double = prepare_static<double>(a);
        const auto b_double = prepare_moving<double>(b);
        const auto a_exact = prepare_static<exact_rational>(a);
        const auto b_exact = prepare_moving<exact_rational>(b);
        detector_options witness;
        witness.witness = true;
        std::vector<frame_result> serial_double, serial_exact, reference;
        {
            detector<double> d(a_double, b_double, witness);
            detector<exact_rational> e(a_exact, b_exact, witness);
            brute_force_detector<exact_rational> r(a, b, witness);
            for (const pose& p : poses) {
                serial_double.push_back(d.collide(p));
                serial_exact.push_back(e.collide(p));
                reference.push_back(r.collide(p));
            }
        }
        std::size_t collisions = 0;
        for (std::size_t k = 0; k < poses.size(); ++k) {
            CHECK(serial_exact[k].collides == reference[k].collides);
            CHECK(serial_exact[k].pairs == reference[k].pairs);
            collisions += reference[k].collides;
        }
        CHECK(collisions > poses.size() / 5);
        CHECK(collisions < poses.size());
        // The split into blocks is the same for every type: the exact
        // detector, the slowest by far, is run on one uneven split.
        const auto got_exact = collide_batch(
            poses, [&] { return detector<exact_rational>(a_exact, b_exact, witness); }, 3u);
        REQUIRE(got_exact.size() == poses.size());
        for (std::size_t k = 0; k < poses.size(); ++k) {
            INFO(family_name(f) << ", threads 3, frame " << k);
            CHECK(got_exact[k].collides == reference[k].collides);
            CHECK(got_exact[k].pairs == reference[k].pairs);
        }
        for (unsigned threads : {1u, 2u, 3u, 7u, 0u}) {
            INFO(family_name(f) << ", threads " << threads);
            const auto got_double = collide_batch(
                poses, [&] { return detector<double>(a_double, b_double, witness); }, threads);
            const auto got_certified = collide_batch(
                poses, [&] { return certified_detector<detector>(a, b, witness); }, threads);
            REQUIRE(got_double.size() == poses.size());
            for (std::size_t k = 0; k < poses.size(); ++k) {
                INFO("frame " << k);
                CHECK(got_double[k].collides == serial_double[k].collides);
                CHECK(got_double[k].pairs == serial_double[k].pairs);
                CHECK(got_certified[k].collides == reference[k].collides);
                CHECK(got_certified[k].pairs == reference[k].pairs);
            }
        }
    }
}

TEST_CASE("batch: one prepared A serves many B and one B many A", "[batch]") {
    const auto a = prepare_static<exact_rational>(make_family_polygon(family::irregular, 128, default_family_seed));
    std::vector<polygon> others;
    for (std::size_t m : {8u, 16u, 64u}) others.push_back(make_family_polygon(family::convex, m, default_family_seed));
    for (const polygon& b : others) {
        const auto bs = prepare_moving<exact_rational>(b);
        const std::vector<pose> poses = random_poses(a->shape, b, 60, 40, 110, b.size());
        brute_force_detector<exact_rational> r(a->shape, b);
        const auto got = collide_batch(
            poses, [&] { return detector<exact_rational>(a, bs); }, 2);
        for (std::size_t k = 0; k < poses.size(); ++k) CHECK(got[k].collides == r.collide(poses[k]).collides);
        // B prepared once, as the moving polygon of another A.
        const polygon a2 = make_family_polygon(family::starred, 64, default_family_seed);
        brute_force_detector<exact_rational> r2(a2, b);
        detector<exact_rational> d2(prepare_static<exact_rational>(a2), bs);
        for (const pose& p : random_poses(a2, b, 40, 40, 110, 3))
            CHECK(d2.collide(p).collides == r2.collide(p).collides);
    }
}

TEST_CASE("batch: many pairs, one query each, as the serial loop", "[batch]") {
    std::vector<polygon> polygons;
    for (family f : all_families)
        for (std::size_t n : {8u, 64u}) polygons.push_back(make_family_polygon(f, n, default_family_seed + n));
    std::vector<pair_query> queries;
    std::uint64_t seed = 11;
    for (const polygon& a : polygons)
        for (const polygon& b : polygons)
            for (const pose& p : random_poses(a, b, 3, 40, 110, seed++)) queries.push_back({&a, &b, p});
    std::vector<char> serial;
    for (const pair_query& q : queries)
        serial.push_back(certified_intersects(*q.static_polygon, *q.moving_polygon, q.moving_pose) ? 1 : 0);
    std::size_t met = 0;
    for (char c : serial) met += c;
    CHECK(met > queries.size() / 5);
    CHECK(met < queries.size());
    for (unsigned threads : {1u, 2u, 5u}) {
        CHECK(intersects_batch(queries, certified_intersects, threads) == serial);
        CHECK(intersects_batch(queries, intersects<exact_rational>, threads) == serial);
    }
}

TEST_CASE("batch: errors reach the caller, and empty and tiny batches work", "[batch]") {
    const polygon a({ring_input{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, ring_role::outer}});
    const polygon b({ring_input{{{0, 0}, {1, 0}, {0, 1}}, ring_role::outer}});
    const auto make = [&] { return detector<double>(a, b); };
    CHECK(collide_batch({}, make, 4).empty());
    const std::vector<pose> one = {pose{1, 1, 0}};
    const auto r = collide_batch(one, make, 8);
    REQUIRE(r.size() == 1);
    CHECK(r[0].collides);
    std::vector<pose> poses(100, pose{10, 10, 0});
    poses[73].theta = std::nan("");
    CHECK_THROWS_AS(collide_batch(poses, make, 3), invalid_input);
    std::vector<pair_query> queries = {{&a, &b, {}}, {&a, nullptr, {}}};
    CHECK_THROWS_AS(intersects_batch(queries, intersects<double>, 2), invalid_input);
    CHECK_THROWS_AS(detector<double>(std::shared_ptr<const static_scene<double>>(), prepare_moving<double>(b)),
                    invalid_input);
    // 0: the machine's hardware threads, asked once and kept.
    CHECK(batch_threads(0) == std::max(1u, std::thread::hardware_concurrency()));
    CHECK(batch_threads(0) == hardware_threads());
    CHECK(batch_threads(3) == 3);
}
