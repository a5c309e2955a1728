// SPDX-License-Identifier: BSL-1.0
// Two large polygons along a long shared border (a parcel layer's or two
// neighbouring countries' case), the moving one walked in small steps: the
// detector answers as the brute-force reference, and a frame in which they
// overlap pays for the pairs that show it, not for the whole border within
// the moving polygon's reach.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "support/shapes.hpp"

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/number/cgal.hpp"
#include "verification/cgal_reference.hpp"

using namespace influence2d;

namespace {

/// A random walk of small steps about the shared position: translations
/// within 0.3, turns about the origin within 0.002 rad.
std::vector<pose> walk_border(std::size_t count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> step(-0.03, 0.03);
    const auto within = [](double x) { return std::clamp(x, -1.0, 1.0); };
    double u = 0, v = 0, w = 0;
    std::vector<pose> out;
    for (std::size_t k = 0; k < count; ++k) {
        u = within(u + step(rng));
        v = within(v + step(rng));
        w = within(w + step(rng));
        out.push_back({0.3 * u, 0.3 * v, 0.002 * w});
    }
    return out;
}

/// The border moved to x = 2^40, where the polygons' deep cells are too
/// small against the coordinates' rounding to be built.
std::vector<point<double>> moved_far(std::vector<point<double>> border) {
    for (point<double>& v : border) v.x += 0x1p40;
    return border;
}

/// The poses, each turning about (2^40, 0) instead of the origin when far.
std::vector<pose> posed_about(std::vector<pose> poses, bool far) {
    if (far)
        for (pose& p : poses) {
            p.tx += 0x1p40 - std::cos(p.theta) * 0x1p40;
            p.ty -= std::sin(p.theta) * 0x1p40;
        }
    return poses;
}

}  // namespace

TEST_CASE(
    "shared border: a coherent walk of two large polygons answers as the reference and pays for the pairs it "
    "needs",
    "[detect][coherence]") {
    const std::vector<point<double>> b = test_shapes::wiggly_border(1000);
    const polygon below = test_shapes::border_side(b, -1), above = test_shapes::border_side(b, 1);
    const std::vector<pose> poses = walk_border(120, 7);
    for (const bool roles_swapped : {false, true}) {
        const polygon& a = roles_swapped ? above : below;
        const polygon& m = roles_swapped ? below : above;
        detector<double> det(a, m);
        brute_force_detector<double> ref(a, m);
        certified_detector<detector> certified(a, m);
        brute_force_detector<exact_rational> exact(a, m);
        std::size_t met = 0, met_edges = 0;
        for (std::size_t k = 0; k < poses.size(); ++k) {
            INFO("roles swapped " << roles_swapped << " frame " << k << " pose " << poses[k].tx << ", " << poses[k].ty
                                  << ", " << poses[k].theta);
            const std::size_t before = det.statistics().candidate_edges;
            const bool want = ref.collide(poses[k]).collides;
            REQUIRE(det.collide(poses[k]).collides == want);
            if (k % 20 == 0) REQUIRE(certified.collide(poses[k]).collides == exact.collide(poses[k]).collides);
            if (want) {
                ++met;
                met_edges += det.statistics().candidate_edges - before;
            }
        }
        // Both answers occur; a frame that meets tests fewer edge pairs than
        // a fifth of the border's edges on average, where the candidates
        // within B's reach are the whole border (1,000 edges) at every frame.
        CHECK(met >= poses.size() / 5);
        CHECK(met < poses.size());
        CHECK(met_edges * 5 < met * 1000);
    }
}

TEST_CASE("shared border: the edge pair that met last answers the frames after it while it meets, as the reference",
          "[detect][coherence]") {
    // The upper side walked about a pose that overlaps the lower one (0.25
    // down): most frames cross the border at the edges they crossed at
    // before. Each frame against CGAL's exact answer (cgal_reference, which
    // tests every pair and containment itself), at d = 0 and d = 0.05.
    // Near the origin a vertex of one side deep in the other
    // (vertices_deep_inside) answers the frames the trees' search would, and
    // the last pair then has none to answer; both sides moved to x = 2^40,
    // where their cells are too small against the coordinates' rounding to
    // be built, the last pair answers them.
    const std::vector<point<double>> near = test_shapes::wiggly_border(400), moved = moved_far(near);
    std::vector<pose> poses = walk_border(150, 11);
    for (pose& p : poses) p.ty -= 0.25;
    // Two jumps among the steps: the pair kept from before a jump is not
    // asked after it (p moved more than the skin).
    poses[50].tx += 40;
    poses[100].ty += 30;
    for (const bool far : {false, true})
        for (const double d : {0.0, 0.05}) {
            const polygon below = test_shapes::border_side(far ? moved : near, -1),
                          above = test_shapes::border_side(far ? moved : near, 1);
            const std::vector<pose> posed = posed_about(poses, far);
            INFO("far " << far);
            const verification::cgal_reference ref(below, above, d);
            detector_options yes_no, no_coherence, witnesses;
            yes_no.distance = no_coherence.distance = witnesses.distance = d;
            no_coherence.temporal_coherence = false;
            witnesses.witness = true;
            detector<exact_rational> exact(below, above, yes_no);
            detector<exact_rational> fresh(below, above, no_coherence);
            detector<exact_rational> witnessed(below, above, witnesses);
            detector<double> fast(below, above, yes_no);
            brute_force_detector<double> fast_ref(below, above, yes_no);
            certified_detector<detector> certified(below, above, yes_no);
            std::size_t met = 0;
            for (std::size_t k = 0; k < poses.size(); ++k) {
                INFO("d " << d << " frame " << k << " pose " << posed[k].tx << ", " << posed[k].ty << ", "
                          << posed[k].theta);
                const bool want = ref.collide(posed[k]).collides;
                met += want;
                REQUIRE(exact.collide(posed[k]).collides == want);
                REQUIRE(fresh.collide(posed[k]).collides == want);
                REQUIRE(witnessed.collide(posed[k]).collides == want);
                REQUIRE(certified.collide(posed[k]).collides == want);
                REQUIRE(fast.collide(posed[k]).collides == fast_ref.collide(posed[k]).collides);
            }
            // Most frames meet; most of those are answered by the last pair
            // (near the origin, by it or a deep vertex), and none by the last
            // pair without coherence or with witnesses asked for.
            CHECK(met * 10 >= poses.size() * 9);
            CHECK(met < poses.size());
            const detector_statistics& st = exact.statistics();
            CHECK((far ? st.last_pair_frames : st.last_pair_frames + st.interior_frames) * 2 >= met);
            CHECK(st.last_pair_frames < met);
            if (far) CHECK(st.interior_frames == 0);
            CHECK(fresh.statistics().last_pair_frames == 0);
            CHECK(witnessed.statistics().last_pair_frames == 0);
            // With witnesses every pair that meets is found, but the filters
            // pass only the pairs near the border's crossings: fewer than 4
            // per edge of A a frame, at 2^40 as near the origin (where a
            // margin of 4e-9 times the coordinates, some 10,000, passed all
            // 160,000 pairs).
            CHECK(witnessed.statistics().candidate_edges < poses.size() * 4 * below.size());
        }
}

TEST_CASE("shared border: poses shuffled about the border are answered by the pairs that met last, as the reference",
          "[detect][coherence]") {
    // The walk of the test above, shuffled: each pose within the skin of the
    // last, but crossing the border at other edges than the last frame's.
    // The detector tries the pair that met last, then the pairs that met
    // before it (recent_met_pairs), latest first; each answer against CGAL's exact
    // one, and in double against the brute-force detector. Far from the
    // origin (no deep cells: the pairs alone answer what the search would).
    const std::vector<point<double>> near = test_shapes::wiggly_border(400), moved = moved_far(near);
    std::vector<pose> poses = walk_border(150, 13);
    for (pose& p : poses) p.ty -= 0.25;
    std::shuffle(poses.begin(), poses.end(), std::mt19937_64(5));
    for (const bool far : {false, true}) {
        const polygon below = test_shapes::border_side(far ? moved : near, -1),
                      above = test_shapes::border_side(far ? moved : near, 1);
        const std::vector<pose> posed = posed_about(poses, far);
        for (const bool swapped : {false, true}) {
            const polygon& a = swapped ? above : below;
            const polygon& m = swapped ? below : above;
            INFO("far " << far << " roles swapped " << swapped);
            const verification::cgal_reference ref(a, m, 0);
            detector<exact_rational> exact(a, m);
            detector<double> fast(a, m);
            brute_force_detector<double> fast_ref(a, m);
            certified_detector<detector> certified(a, m);
            std::size_t met = 0;
            for (std::size_t k = 0; k < posed.size(); ++k) {
                // (Swapped, the upper side is static and the lower one is
                // moved up by as much.)
                const pose q{posed[k].tx, swapped ? posed[k].ty + 0.5 : posed[k].ty, posed[k].theta};
                INFO("frame " << k << " pose " << q.tx << ", " << q.ty << ", " << q.theta);
                const bool want = ref.collide(q).collides;
                met += want;
                REQUIRE(exact.collide(q).collides == want);
                REQUIRE(certified.collide(q).collides == want);
                REQUIRE(fast.collide(q).collides == fast_ref.collide(q).collides);
            }
            CHECK(met * 10 >= posed.size() * 9);
            const detector_statistics& st = exact.statistics();
            UNSCOPED_INFO("met " << met << " last pairs " << st.last_pair_frames << " deep " << st.interior_frames);
            CHECK((far ? st.last_pair_frames : st.last_pair_frames + st.interior_frames) * 10 >= met * 9);
            if (far) CHECK(st.interior_frames == 0);
        }
    }
}
