// SPDX-License-Identifier: BSL-1.0
// Random multipolygons against the exact reference, in every mode that claims
// exact answers (exact rationals, certified, interval, CGAL's lazy exact
// numbers), with both roles; and GEOS as a second, independent check on
// translated valid scenes.
//
// Scenes (tests/support/random_scenes.hpp), per seed one of:
//   - A a multipolygon of 2 to 20 parts (holes, islands in holes, radii from
//     0.4 to 12), B one large star that can swallow whole parts;
//   - the same with the roles swapped (B the multipolygon);
//   - both multipolygons.
// Frames aim B so that a chosen point of it (its centre, or a part's centre)
// lands near a chosen part of A: within the part, on its boundary or just
// beside it; half turn B by a random angle, half are translations on the grid.
// Every frame is asked of a fresh sequence of poses nobody tuned: the detector
// keeps its caches from frame to frame as a user's loop would.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/random_scenes.hpp"

#include <algorithm>
#include <string>
#include <vector>

#if INFLUENCE2D_HAVE_GEOS
#include <geos_c.h>
#endif

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/exact/interval_detector.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/cgal.hpp"
#include "verification/cgal_reference.hpp"

namespace {

using namespace influence2d;
using test_scenes::multi;
using test_scenes::rng;
using verification::cgal_reference;

/// A scene: the two polygons as parts, and frames aimed at parts of A.
struct scene {
    multi a, b;
    std::vector<pose> frames;
    std::string describe_multipolygon(std::size_t k) const {
        const pose& p = frames[k];
        std::ostringstream s;
        s.precision(17);
        s << "static " << a.wkt() << "\nmoving " << b.wkt() << "\npose " << p.tx << ',' << p.ty << ',' << p.theta;
        return s.str();
    }
};

/// The scene of one seed (kinds as in the file comment); `translations_only`
/// makes every frame a translation on the grid.
scene make_scene(std::uint64_t seed, std::size_t frames, bool translations_only) {
    rng g(seed);
    scene s;
    switch (seed % 3) {
    case 0:
        s.a = test_scenes::random_multi(g, 40);
        s.b = test_scenes::random_swallower(g);
        break;
    case 1:
        s.a = test_scenes::random_swallower(g);
        s.b = test_scenes::random_multi(g, 40);
        break;
    default:
        s.a = test_scenes::random_multi(g, 30);
        s.b = test_scenes::random_multi(g, 12, 8);
        break;
    }
    for (std::size_t k = 0; k < frames; ++k) {
        const test_scenes::part& pa = s.a.parts[g.index(s.a.parts.size())];
        const test_scenes::part& pb = s.b.parts[g.index(s.b.parts.size())];
        // Within the part, about its boundary, or beyond it.
        const double reach = pa.radius * g.uniform(0, 1.6) + pb.radius * g.uniform(0, 1.2);
        const double angle = g.uniform(0, 6.283185307179586);
        const point<double> target{pa.center.x + reach * std::cos(angle), pa.center.y + reach * std::sin(angle)};
        const double theta = translations_only || g.chance(0.5) ? 0 : g.uniform(-3.2, 3.2);
        s.frames.push_back(test_scenes::aimed(pb.center, target, theta));
    }
    return s;
}

std::string describe_multipolygon(const std::vector<edge_pair>& pairs) {
    std::ostringstream s;
    for (const edge_pair& p : pairs) s << '[' << p.static_edge << ',' << p.moving_edge << ']';
    return s.str();
}

/// How the reference answered a run's frames, for the checks that the run
/// was not vacuous.
struct frame_tally {
    std::size_t total = 0, collide = 0, by_containment = 0;
    void add(const frame_result& expected) {
        ++total;
        collide += expected.collides;
        by_containment += expected.collides && expected.pairs.empty();
    }
};

/// The witness detector's answer and pairs against the reference's.
void check_witnessed(const frame_result& got, const frame_result& expected) {
    CHECK(got.collides == expected.collides);
    CHECK(describe_multipolygon(got.pairs) == describe_multipolygon(expected.pairs));
}

}  // namespace

TEST_CASE("random multipolygons: every exact mode agrees with the exact reference", "[multipolygon][reference]") {
    const int scenes = test_effort::scaled(48);
    const std::size_t frames = 24;
    frame_tally tally;
    for (int k = 0; k < scenes; ++k) {
        const scene s = make_scene(0x5eed0000ULL + static_cast<std::uint64_t>(k), frames, false);
        const polygon A = s.a.to_polygon(), B = s.b.to_polygon();
        const cgal_reference reference(A, B, 0, true);
        const cgal_reference reference_within(A, B, 0.5);
        detector_options witness;
        witness.witness = true;
        detector_options within;
        within.distance = 0.5;
        detector<exact_rational> exact(A, B, witness);
        detector<exact_rational> exact_plain(A, B);
        detector<exact_rational, feature_set<features::holes>> exact_minimal(A, B);
        detector<exact_rational> exact_within(A, B, within);
        brute_force_detector<exact_rational> brute(A, B);
        certified_detector<detector> certified(A, B);
        certified_detector<detector> certified_within(A, B, within);
        certified_detector<brute_force_detector> certified_brute(A, B);
        interval_detector<detector> interval(A, B);
        detector<cgal_reference::FT> lazy(A, B);  // CGAL's lazy exact numbers, Epeck's field type
        for (std::size_t f = 0; f < s.frames.size(); ++f) {
            const pose& p = s.frames[f];
            const frame_result expected = reference.collide(p);
            INFO("scene " << k << ", frame " << f << "\n" << s.describe_multipolygon(f));
            tally.add(expected);
            check_witnessed(exact.collide(p), expected);
            CHECK(exact_plain.collide(p).collides == expected.collides);
            CHECK(exact_minimal.collide(p).collides == expected.collides);
            CHECK(brute.collide(p).collides == expected.collides);
            CHECK(certified.collide(p).collides == expected.collides);
            CHECK(certified_brute.collide(p).collides == expected.collides);
            CHECK(interval.collide(p).collides == expected.collides);
            if (f % 4 == 0) CHECK(lazy.collide(p).collides == expected.collides);
            if (f % 3 == 0) {
                const bool near = reference_within.collide(p).collides;
                CHECK(exact_within.collide(p).collides == near);
                CHECK(certified_within.collide(p).collides == near);
            }
        }
    }
    // The frames are not vacuous: many collide, and many of those only by
    // a whole part lying inside the other polygon.
    INFO(tally.total << " frames, " << tally.collide << " collide, " << tally.by_containment << " by containment only");
    CHECK(tally.collide * 5 > tally.total);
    CHECK(tally.by_containment * 10 > tally.total);
    CHECK(tally.collide < tally.total);
}

#if INFLUENCE2D_HAVE_GEOS
namespace {

/// GEOS's intersects on WKT text (closed semantics, as the library's).
class geos_check {
public:
    geos_check() : ctx_(GEOS_init_r()), reader_(GEOSWKTReader_create_r(ctx_)) {}
    ~geos_check() {
        GEOSWKTReader_destroy_r(ctx_, reader_);
        GEOS_finish_r(ctx_);
    }
    geos_check(const geos_check&) = delete;
    geos_check& operator=(const geos_check&) = delete;

    /// 1 or 0: GEOS's answer; -1: a geometry GEOS does not call valid.
    int intersects(const std::string& a, const std::string& b) {
        GEOSGeometry* ga = GEOSWKTReader_read_r(ctx_, reader_, a.c_str());
        GEOSGeometry* gb = GEOSWKTReader_read_r(ctx_, reader_, b.c_str());
        REQUIRE(ga != nullptr);
        REQUIRE(gb != nullptr);
        int answer = -1;
        if (GEOSisValid_r(ctx_, ga) == 1 && GEOSisValid_r(ctx_, gb) == 1) answer = GEOSIntersects_r(ctx_, ga, gb);
        GEOSGeom_destroy_r(ctx_, ga);
        GEOSGeom_destroy_r(ctx_, gb);
        REQUIRE(answer != 2);
        return answer;
    }

private:
    GEOSContextHandle_t ctx_;
    GEOSWKTReader* reader_;
};

}  // namespace

TEST_CASE("random multipolygons: the exact answer equals GEOS's on valid translated scenes", "[multipolygon][geos]") {
    // Translations by grid values: every posed coordinate is a double, so
    // GEOS reads the very polygons the detector poses.
    geos_check geos;
    const int scenes = test_effort::scaled(60);
    std::size_t checked = 0, invalid = 0, collide = 0;
    for (int k = 0; k < scenes; ++k) {
        const scene s = make_scene(0x6e05000ULL + static_cast<std::uint64_t>(k), 20, true);
        const polygon A = s.a.to_polygon(), B = s.b.to_polygon();
        certified_detector<detector> certified(A, B);
        detector<exact_rational> exact(A, B);
        const std::string a_wkt = s.a.wkt();
        for (std::size_t f = 0; f < s.frames.size(); ++f) {
            const pose& p = s.frames[f];
            const int expected = geos.intersects(a_wkt, s.b.wkt({p.tx, p.ty}));
            if (expected < 0) {
                ++invalid;
                continue;
            }
            INFO("scene " << k << ", frame " << f << "\n" << s.describe_multipolygon(f));
            ++checked;
            collide += expected;
            CHECK(exact.collide(p).collides == (expected == 1));
            CHECK(certified.collide(p).collides == (expected == 1));
        }
    }
    INFO(checked << " frames checked, " << collide << " collide, " << invalid << " skipped as invalid for GEOS");
    CHECK(invalid * 10 < checked);
    CHECK(collide * 5 > checked);
    CHECK(collide < checked);
}
#endif  // INFLUENCE2D_HAVE_GEOS

TEST_CASE("random rings under the winding rule: exact modes agree with the reference",
          "[multipolygon][reference][winding]") {
    // Overlapping and nested shells, holes outside every shell, self-crossing
    // rings, repeated vertices: the region is the winding rule's, and the
    // reference decides it on its own ray-crossing count.
    const int scenes = test_effort::scaled(60);
    frame_tally tally;
    for (int k = 0; k < scenes; ++k) {
        rng g(0x3e55000ULL + static_cast<std::uint64_t>(k));
        const polygon A(test_scenes::random_messy(g, 25));
        const polygon B(test_scenes::random_messy(g, 8, 4));
        const cgal_reference reference(A, B, 0, true);
        detector_options witness;
        witness.witness = true;
        detector<exact_rational> exact(A, B, witness);
        detector_options band;
        band.shape = extended_area::band;
        band.temporal_coherence = false;
        detector<exact_rational> exact_band(A, B, band);
        brute_force_detector<exact_rational> brute(A, B);
        certified_detector<detector> certified(A, B);
        for (int f = 0; f < 20; ++f) {
            const point<double> q = B.vertex(g.index(B.size()));
            const point<double> target = A.vertex(g.index(A.size()));
            const double spread = g.uniform(0, 12);
            const double theta = g.chance(0.5) ? 0 : g.uniform(-3.2, 3.2);
            const pose p = test_scenes::aimed(
                q, {target.x + spread * g.uniform(-1, 1), target.y + spread * g.uniform(-1, 1)}, theta);
            const frame_result expected = reference.collide(p);
            std::ostringstream where;
            where.precision(17);
            where << "static " << to_wkt(A) << "\nmoving " << to_wkt(B) << "\npose " << p.tx << ',' << p.ty << ','
                  << p.theta;
            INFO("scene " << k << ", frame " << f << "\n" << where.str());
            tally.add(expected);
            check_witnessed(exact.collide(p), expected);
            CHECK(exact_band.collide(p).collides == expected.collides);
            CHECK(brute.collide(p).collides == expected.collides);
            CHECK(certified.collide(p).collides == expected.collides);
        }
    }
    INFO(tally.total << " frames, " << tally.collide << " collide, " << tally.by_containment << " by containment only");
    CHECK(tally.collide * 5 > tally.total);
    CHECK(tally.by_containment * 40 > tally.total);
    CHECK(tally.collide < tally.total);
}
