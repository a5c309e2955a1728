// SPDX-License-Identifier: BSL-1.0
// Frames of a large static polygon and a moving one of few edges, the case
// that finds its pairs through A's edge tree: the detector answers as the
// brute-force reference in the same number type, with witnesses and with a
// separation distance, and the frames do take the tree.

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/effort.hpp"

using namespace influence2d;

namespace {

polygon family_polygon(const std::string& id) {
    return read_wkt_file(std::string(INFLUENCE2D_DATA_DIR) + "/families/" + id + ".wkt");
}

/// The end of the time study's linear approach (the frames within the
/// bounding circles), then B's centroid at random points near A's vertices
/// with random rotations: many frames with edges of A close to B's.
std::vector<pose> frames_near(const polygon& a, const polygon& b, std::uint64_t seed, int count) {
    std::vector<pose> out;
    const std::vector<pose> line = linear_trajectory(a, b, 9000);
    for (int k = 0; k < count / 2; ++k)
        out.push_back(line[line.size() - 1 - static_cast<std::size_t>(k) * 700 / count]);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    const point<double> cb = b.centroid();
    double rb = 0;
    for (const auto& v : b.vertices()) rb = std::max(rb, std::hypot(v.x - cb.x, v.y - cb.y));
    while (static_cast<int>(out.size()) < count) {
        const point<double>& v = a.vertex(static_cast<std::size_t>(rng() % a.size()));
        const double theta = 3.2 * unit(rng), c = std::cos(theta), s = std::sin(theta);
        const point<double> at{v.x + rb * unit(rng), v.y + rb * unit(rng)};
        out.push_back({at.x - (c * cb.x - s * cb.y), at.y - (s * cb.x + c * cb.y), theta});
    }
    return out;
}

template <class NT>
void check_frames(const polygon& a, const polygon& b, const std::vector<pose>& poses, double d,
                  const std::string& what) {
    detector_options o;
    o.witness = true;
    o.distance = d;
    detector<NT> det(a, b, o);
    brute_force_detector<NT> ref(a, b, o);
    detector_options plain;
    plain.distance = d;
    detector<NT> yes_no(a, b, plain);
    std::size_t collisions = 0;
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const frame_result want = ref.collide(poses[k]);
        const frame_result got = det.collide(poses[k]);
        INFO(what << " " << number_traits<NT>::name << " d " << d << " frame " << k << " pose " << poses[k].tx << ", "
                  << poses[k].ty << ", " << poses[k].theta);
        REQUIRE(got.collides == want.collides);
        REQUIRE(got.pairs == want.pairs);
        REQUIRE(yes_no.collide(poses[k]).collides == want.collides);
        collisions += want.collides;
    }
    // Both answers occur, and most frames found their pairs through A's edge
    // tree: alone, or with B's for frames that jump (these poses all do); or,
    // for two small convex polygons, by the separating-edge test; or, for two
    // convex polygons without witnesses, by their inner discs.
    CHECK(collisions >= poses.size() / 5);
    CHECK(collisions < poses.size());
    for (const detector_statistics& s : {det.statistics(), yes_no.statistics()})
        CHECK((s.tree_frames + s.jump_frames + s.convex_frames + s.disc_frames) * 2 >= poses.size());
}

/// Every scene (static, moving family file names) on `frames` poses near
/// contact, at d = 0 and 0.5, in double and exact, against brute force.
void check_scenes(const std::vector<std::pair<std::string, std::string>>& scenes, int frames, std::uint64_t seed) {
    for (const auto& [an, bn] : scenes) {
        const polygon a = family_polygon(an), b = family_polygon(bn);
        const std::vector<pose> poses = frames_near(a, b, seed++, frames);
        for (double d : {0.0, 0.5}) {
            check_frames<double>(a, b, poses, d, an + " x " + bn);
            check_frames<exact_rational>(a, b, poses, d, an + " x " + bn);
        }
    }
}

}  // namespace

TEST_CASE("edge tree frames: a large A and a small B answer as the reference", "[detect][tree]") {
    check_scenes({{"contour_1024", "contour_8"},
                  {"convex_512", "convex_8"},
                  {"hole_1024", "hole_16"},
                  {"starred_256", "starred_8"},
                  {"irregular_1024", "irregular_8"}},
                 test_effort::scaled(40), 41);
}

TEST_CASE("edge tree frames: a small A and a large B answer as the reference", "[detect][tree]") {
    // B's edges outnumber A's: frames that jump traverse the trees in B's
    // frame, A placed there by the inverse pose.
    check_scenes({{"contour_8", "contour_1024"},
                  {"convex_8", "convex_512"},
                  {"hole_16", "hole_1024"},
                  {"starred_8", "starred_256"},
                  {"irregular_64", "irregular_1024"}},
                 test_effort::scaled(40), 141);
}

TEST_CASE("edge tree frames: two small polygons test every pair's boxes, as the reference", "[detect][tree]") {
    check_scenes({{"convex_8", "convex_8"},
                  {"starred_8", "starred_8"},
                  {"contour_8", "irregular_8"},
                  {"irregular_8", "convex_8"}},
                 test_effort::scaled(60), 241);
}

TEST_CASE("edge tree frames: a B of more than 2,048 edges takes the trees on small steps, as the reference",
          "[detect][tree]") {
    // B's chunks alone exceed the candidates' bound: each frame, small steps
    // of a trajectory included, goes to the trees without gathering
    // candidates (candidates_can_pay), and answers as brute force.
    std::mt19937_64 rng(2049);
    std::uniform_real_distribution<double> radius(0.6, 1.0);
    const std::size_t n = 2600;
    std::vector<point<double>> star(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double phi = 2 * std::acos(-1.0) * static_cast<double>(k) / static_cast<double>(n), r = 40 * radius(rng);
        star[k] = {r * std::cos(phi), r * std::sin(phi)};
    }
    const polygon b(std::vector<ring_input>{{star, ring_role::outer}});
    const polygon a = family_polygon("irregular_64");
    const std::vector<pose> line = linear_trajectory(a, b, 9000);
    // The last 400 frames (B reaches A among them), every one or, at a
    // lower effort, every few: small steps either way.
    const std::size_t stride = 400 / static_cast<std::size_t>(test_effort::scaled(400));
    std::vector<pose> poses;
    for (std::size_t k = line.size() - 400; k < line.size(); k += stride) poses.push_back(line[k]);
    for (double d : {0.0, 0.5}) {
        detector_options o;
        o.witness = true;
        o.distance = d;
        detector<double> det(a, b, o);
        brute_force_detector<double> ref(a, b, o);
        std::size_t collisions = 0;
        for (std::size_t k = 0; k < poses.size(); ++k) {
            const frame_result want = ref.collide(poses[k]);
            const frame_result got = det.collide(poses[k]);
            INFO("d " << d << " frame " << k);
            REQUIRE(got.collides == want.collides);
            REQUIRE(got.pairs == want.pairs);
            collisions += want.collides;
        }
        CHECK(collisions > 0);
        CHECK(collisions < poses.size());
        CHECK(det.statistics().candidate_rebuilds == 0);
        CHECK(det.statistics().jump_frames > 0);
    }
}
