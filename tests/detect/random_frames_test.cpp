// SPDX-License-Identifier: BSL-1.0
// Agreement of the detectors with the exact CGAL reference on many frames.
//
// Polygons: data/families/<family>_<n>.wkt, families convex, starred,
// irregular, contour, hole and sizes 8 to 64; every ordered pair of families
// with sizes varying over the pairs. Frames, with fixed seeds:
//   - random: B's centroid at a random distance from A's centroid, in a random
//     direction, with a random rotation; the distance is uniform in
//     [0, R_A + r_B + 4] for a quarter of them, in its outer 40% for the rest;
//   - contact: theta = 0 and t = a - q, a a vertex of A or the midpoint of an
//     edge of A, q a vertex of B (exact: the coordinates lie on a 2^-20 grid).
//     Three in four take q as B's extreme vertex against the outward normal
//     at a, which makes them touch for most shapes; the others a random q;
//   - hair apart: each contact frame pushed 2^-20 along that outward normal.
// 4200 frames for d = 0 (1200 contacts, of which about 45% touch: collide,
// yet are apart a hair further out) and 1050 for each of d = 0.5 and d = 3.
// Some frames of a large A and a small B take A's edge tree (checked: both
// ways of finding the pairs are exercised). Checks, with witnesses:
//   detector<exact_rational> == brute_force_detector<exact_rational> ==
//   cgal_reference (collides and pairs), the detector without witnesses and
//   with the band areas and no coherence on collides, and
//   detector<double> == brute_force_detector<double> (collides and pairs).

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/effort.hpp"
#include "support/families.hpp"
#include "support/poses.hpp"
#include "support/random.hpp"
#include "verification/cgal_reference.hpp"

namespace {

using namespace influence2d;
using verification::cgal_reference;

using verification::all_families;
constexpr std::array<std::size_t, 4> family_sizes = {8, 16, 32, 64};

/// Frames per family pair: random ones, and contact ones each followed by its
/// hair-apart frame. Fewer for d > 0, where exact distance tests cost more.
struct frame_counts {
    int random;
    int contact;
};
const frame_counts counts_touching{test_effort::scaled(36), test_effort::scaled(24)};
const frame_counts counts_distance{test_effort::scaled(9), test_effort::scaled(6)};

struct shape {
    std::string name;
    const polygon* poly;
};

/// Family f of all_families with family_sizes[s] vertices (data/families).
shape frame_family(std::size_t f, std::size_t s) {
    const std::size_t n = family_sizes[s];
    return {verification::family_name(all_families[f]) + "_" + std::to_string(n),
            &test_families::load(all_families[f], n)};
}

/// One ordered pair of polygons: A static, B moving.
struct family_pair {
    shape a;
    shape b;
    std::uint64_t seed;
};

/// Every ordered pair of families; the sizes run through all 16 combinations
/// as the pairs go, so each family meets each size as A and as B.
std::vector<family_pair> family_pairs() {
    std::vector<family_pair> out;
    std::uint64_t k = 0;
    for (std::size_t fa = 0; fa < std::size(all_families); ++fa)
        for (std::size_t fb = 0; fb < std::size(all_families); ++fb, ++k)
            for (std::size_t r = 0; r < 2; ++r) {
                const std::size_t combo = (2 * k + r) % 16;
                out.push_back({frame_family(fa, combo % 4), frame_family(fb, (combo / 4 + fa) % 4),
                               0x1f2e3d4c5b6a7988ULL + 7919 * (2 * k + r)});
            }
    return out;
}

enum class frame_kind { random, contact, hair_apart };

struct random_frame {
    pose p;
    frame_kind kind;
};

/// The frames of one family pair, the same for every distance.
/// The first frames of a smaller count are those of a larger one.
std::vector<random_frame> make_frames(const family_pair& fp, frame_counts counts) {
    const polygon& A = *fp.a.poly;
    const polygon& B = *fp.b.poly;
    test_random::rng r(fp.seed);
    std::vector<random_frame> frames;
    const double pi = std::acos(-1.0);
    const point<double> ca = A.centroid(), cb = B.centroid();
    const double reach = test_poses::reach(A, B, 4);
    for (int k = 0; k < counts.random; ++k) {
        // A quarter anywhere within the reach (deep overlaps, containment),
        // the rest in its outer part, where the close calls are.
        const double dist = reach * (k % 4 == 0 ? r.unit() : 0.6 + 0.4 * r.unit());
        const double phi = 2 * pi * r.unit();
        const double theta = 2 * pi * r.unit() - pi;
        frames.push_back({test_poses::centroid_at(ca, cb, dist, phi, theta), frame_kind::random});
    }
    r = test_random::rng(fp.seed + 1);  // contacts do not depend on the number of random frames
    for (int k = 0; k < counts.contact; ++k) {
        // A point a on A's boundary (a vertex or an edge midpoint, exact) and
        // the outward normal there, made of unit length.
        const test_poses::boundary_point a = test_poses::random_boundary_point(A, r);
        point<double> n = a.normal;
        const double len = std::hypot(n.x, n.y);
        if (len > 0) n = {n.x / len, n.y / len};
        std::size_t j = r.index(B.size());
        // Three in four: B's vertex furthest against n, so that B lies beyond
        // the line through a; the others a random vertex.
        if (k % 4 != 3) j = test_poses::extreme_vertex(B, n);
        const point<double> q = B.vertex(j);
        const pose touch{a.at.x - q.x, a.at.y - q.y, 0};
        frames.push_back({touch, frame_kind::contact});
        const double hair = std::ldexp(1.0, -20);
        frames.push_back({pose{touch.tx + hair * n.x, touch.ty + hair * n.y, 0}, frame_kind::hair_apart});
    }
    return frames;
}

std::string describe_frame(const family_pair& fp, std::size_t index, const random_frame& f, double d) {
    std::ostringstream o;
    o << std::setprecision(17) << "A = " << fp.a.name << ", B = " << fp.b.name << ", d = " << d << ", frame " << index
      << " ("
      << (f.kind == frame_kind::random    ? "random"
          : f.kind == frame_kind::contact ? "contact"
                                          : "hair apart")
      << "), pose tx = " << f.p.tx << ", ty = " << f.p.ty << ", theta = " << f.p.theta;
    return o.str();
}

std::string pairs_text(const frame_result& r) {
    std::ostringstream o;
    o << (r.collides ? "collides" : "apart") << " {";
    for (const auto& e : r.pairs) o << " (" << e.static_edge << "," << e.moving_edge << ")";
    o << " }";
    return o.str();
}

bool same_counts(const frame_result& x, const frame_result& y) {
    return x.collides == y.collides && x.pairs == y.pairs;
}

struct tally {
    std::size_t frames = 0, contact = 0, touching = 0, collisions = 0, mismatches = 0;
    /// Strategies taken by detector<exact_rational>: frames of jumps (both
    /// edge trees) and, for the detector led to each frame in small steps,
    /// A's edge tree and the cached candidates.
    std::size_t jump_frames = 0, jump_frames_past_circles = 0;
    std::size_t tree_frames = 0, steady_frames_past_circles = 0;
};

/// Runs every frame of every family pair at distance d; counts and checks.
tally run_all_frames(double d, frame_counts counts) {
    tally t;
    for (const family_pair& fp : family_pairs()) {
        const polygon& A = *fp.a.poly;
        const polygon& B = *fp.b.poly;
        detector_options wit;
        wit.distance = d;
        wit.witness = true;
        detector_options plain;
        plain.distance = d;
        plain.shape = extended_area::band;
        plain.temporal_coherence = false;
        detector<exact_rational> det_exact(A, B, wit);
        detector<exact_rational> det_plain(A, B, plain);
        // Led to each frame by two small steps, so that the frame uses
        // coherence (cached candidates or A's edge tree) instead of a jump's
        // strategy.
        detector<exact_rational> det_steady(A, B, wit);
        brute_force_detector<exact_rational> bf_exact(A, B, wit);
        detector<double> det_double(A, B, wit);
        brute_force_detector<double> bf_double(A, B, wit);
        const cgal_reference ref(A, B, d, true);
        const cgal_reference ref_touch(A, B, 0, false);

        const std::vector<random_frame> frames = make_frames(fp, counts);
        std::size_t reported = 0;
        for (std::size_t k = 0; k < frames.size(); ++k) {
            const random_frame& f = frames[k];
            ++t.frames;
            const frame_result expected = ref.collide(f.p);
            const frame_result got = det_exact.collide(f.p);
            for (double lead : {2e-3, 1e-3}) (void)det_steady.collide(pose{f.p.tx - lead, f.p.ty, f.p.theta});
            const detector_statistics before = det_steady.statistics();
            const frame_result steady = det_steady.collide(f.p);
            const detector_statistics& after = det_steady.statistics();
            t.tree_frames += after.tree_frames - before.tree_frames;
            t.steady_frames_past_circles += after.circle_rejections == before.circle_rejections;
            const frame_result brute = bf_exact.collide(f.p);
            const bool got_plain = det_plain.collide(f.p).collides;
            const frame_result got_double = det_double.collide(f.p);
            const frame_result brute_double = bf_double.collide(f.p);
            t.collisions += expected.collides;
            if (f.kind == frame_kind::contact) {
                ++t.contact;
                // Touching: collides here, apart once pushed a hair outwards.
                if (d == 0 && expected.collides && !ref_touch.collide(frames[k + 1].p).collides) ++t.touching;
            }
            const bool ok = same_counts(got, expected) && same_counts(steady, expected) &&
                            same_counts(brute, expected) && got_plain == expected.collides &&
                            same_counts(got_double, brute_double);
            if (ok) continue;
            ++t.mismatches;
            if (++reported > 3) continue;  // enough to reproduce; the count says the rest
            INFO(describe_frame(fp, k, f, d));
            INFO("reference:                     " << pairs_text(expected));
            INFO("detector<exact>:               " << pairs_text(got));
            INFO("detector<exact> led in steps:  " << pairs_text(steady));
            INFO("brute_force<exact>:            " << pairs_text(brute));
            INFO("detector<exact> band, no coh.: " << (got_plain ? "collides" : "apart"));
            INFO("detector<double>:              " << pairs_text(got_double));
            INFO("brute_force<double>:           " << pairs_text(brute_double));
            FAIL_CHECK("detectors disagree");
        }
        const detector_statistics& st = det_exact.statistics();
        t.jump_frames += st.jump_frames;
        t.jump_frames_past_circles += st.frames - st.circle_rejections;
    }
    return t;
}

}  // namespace

TEST_CASE("random frames: detectors agree with the CGAL reference, d = 0", "[detect][reference][random]") {
    const tally t = run_all_frames(0, counts_touching);
    CHECK(t.mismatches == 0);
    CHECK(t.frames >= static_cast<std::size_t>(4000 * test_effort::effort()));
    // The frames must exercise both answers, and the exact contacts must
    // mostly be real touching (collide, yet apart a hair further out).
    CHECK(t.collisions >= t.frames / 4);
    CHECK(t.frames - t.collisions >= t.frames / 5);
    CHECK(t.touching * 3 >= t.contact);
    // Every way of finding the pairs is exercised: frames that jump take both
    // edge trees; frames reached in small steps take A's edge tree (a large
    // A, a small B; more of those in edge_tree_frames_test.cpp) or the cached
    // candidates.
    CHECK(t.jump_frames * 10 >= t.jump_frames_past_circles * 9);
    CHECK(t.tree_frames >= t.steady_frames_past_circles / 100);
    CHECK(t.tree_frames * 2 <= t.steady_frames_past_circles);
}

TEST_CASE("random frames: detectors agree with the CGAL reference, d = 0.5", "[detect][reference][random]") {
    const tally t = run_all_frames(0.5, counts_distance);
    CHECK(t.mismatches == 0);
    CHECK(t.frames >= static_cast<std::size_t>(800 * test_effort::effort()));  // 1050 at full effort
    CHECK(t.collisions >= t.frames / 4);
    CHECK(t.frames - t.collisions >= t.frames / 10);
}

TEST_CASE("random frames: detectors agree with the CGAL reference, d = 3", "[detect][reference][random]") {
    const tally t = run_all_frames(3, counts_distance);
    CHECK(t.mismatches == 0);
    CHECK(t.frames >= static_cast<std::size_t>(800 * test_effort::effort()));  // 1050 at full effort
    CHECK(t.collisions >= t.frames / 4);
    CHECK(t.frames - t.collisions >= t.frames / 10);
}
