// SPDX-License-Identifier: BSL-1.0
// certified_detector<detector> and certified_detector<brute_force_detector>
// give the answers of detector<exact_rational>, witness pairs included.
//
// Polygons: data/families/<family>_<n>.wkt, the five families at sizes 8 to 64,
// every ordered pair of families twice with the sizes varying over the pairs.
// Frames, with fixed seeds:
//   - generic: B's centroid in the outer 40% of the reach R_A + r_B + 4 from
//     A's centroid (where the close calls are), in a random direction, with a
//     random rotation; nothing in them is exactly degenerate, so the certified
//     type decides every sign and the exact fallback must never run;
//   - touching: theta = 0 and t = a - q, a a vertex of A or the midpoint of an
//     edge of A, q B's extreme vertex against the outward normal at a: the
//     family coordinates lie on a 2^-20 grid, so these poses are exact and
//     most of them touch, deciding exact zeros of posed coordinates, which the
//     certified type cannot certify: the fallback must run;
//   - one ulp: each touching pose with tx, then ty, moved by one ulp.
// At d = 0 and at d = 0.5 (fewer frames: exact distance tests cost more).

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/families.hpp"
#include "support/poses.hpp"
#include "support/random.hpp"

namespace {

using namespace influence2d;

constexpr std::array<std::size_t, 4> certified_family_sizes = {8, 16, 32, 64};

struct certified_shape {
    std::string name;
    const polygon* poly;
};

certified_shape certified_family(std::size_t f, std::size_t s) {
    const verification::family which = verification::all_families[f];
    return {verification::family_name(which) + "_" + std::to_string(certified_family_sizes[s]),
            &test_families::load(which, certified_family_sizes[s])};
}

struct certified_family_pair {
    certified_shape a;
    certified_shape b;
    std::uint64_t seed;
};

std::vector<certified_family_pair> certified_family_pairs() {
    std::vector<certified_family_pair> out;
    constexpr std::size_t families = std::size(verification::all_families);
    std::uint64_t k = 0;
    for (std::size_t fa = 0; fa < families; ++fa)
        for (std::size_t fb = 0; fb < families; ++fb, ++k)
            for (std::size_t r = 0; r < 2; ++r) {
                const std::size_t combo = (2 * k + r + 5) % 16;
                out.push_back({certified_family(fa, combo % 4), certified_family(fb, (combo / 4 + fb) % 4),
                               0xce271f1edULL + 104729 * (2 * k + r)});
            }
    return out;
}

std::string certified_pairs_text(const frame_result& r) {
    std::ostringstream o;
    o << (r.collides ? "collides" : "apart") << " {";
    for (const auto& e : r.pairs) o << " (" << e.static_edge << "," << e.moving_edge << ")";
    o << " }";
    return o.str();
}

bool same_frame(const frame_result& x, const frame_result& y) { return x.collides == y.collides && x.pairs == y.pairs; }

struct certified_tally {
    std::size_t frames = 0, collisions = 0, mismatches = 0;
    std::size_t generic_frames = 0, generic_fallbacks = 0;
    std::size_t touching_frames = 0, touching_fallbacks = 0, brute_touching_fallbacks = 0;
};

/// Checks one set of frames against the exact detector; the certified
/// detectors are the caller's, so that their fallbacks can be counted per kind.
void check_certified_frames(const certified_family_pair& fp, const std::vector<pose>& frames, double d,
                            detector<exact_rational>& exact, certified_detector<detector>& cert,
                            certified_detector<brute_force_detector>& cert_brute,
                            certified_detector<detector>& cert_plain, certified_detector<detector>& cert_into,
                            certified_tally& t) {
    std::size_t reported = 0;
    std::vector<edge_pair> pairs;  // cert_into's witnesses, the vector kept across frames
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const pose& p = frames[k];
        ++t.frames;
        const frame_result want = exact.collide(p);
        const frame_result got = cert.collide(p);
        const frame_result brute = cert_brute.collide(p);
        const bool plain = cert_plain.collide(p).collides;
        const bool into = cert_into.collide(p, pairs);
        t.collisions += want.collides;
        if (same_frame(got, want) && same_frame(brute, want) && plain == want.collides &&
            same_frame({into, pairs}, want))
            continue;
        ++t.mismatches;
        if (++reported > 3) continue;
        std::ostringstream o;
        o.precision(17);
        o << "A = " << fp.a.name << ", B = " << fp.b.name << ", d = " << d << ", frame " << k << ", pose tx = " << p.tx
          << ", ty = " << p.ty << ", theta = " << p.theta;
        INFO(o.str());
        INFO("detector<exact>:                " << certified_pairs_text(want));
        INFO("certified<detector>:            " << certified_pairs_text(got));
        INFO("certified<brute_force>:         " << certified_pairs_text(brute));
        INFO("certified<detector>, no witness: " << (plain ? "collides" : "apart"));
        INFO("certified<detector>, into a vector: " << certified_pairs_text({into, pairs}));
        FAIL_CHECK("certified detectors disagree with the exact detector");
    }
}

certified_tally run_all(double d, std::size_t generic_count, std::size_t touching_count) {
    certified_tally t;
    for (const certified_family_pair& fp : certified_family_pairs()) {
        const polygon& A = *fp.a.poly;
        const polygon& B = *fp.b.poly;
        detector_options wit;
        wit.distance = d;
        wit.witness = true;
        detector_options plain;
        plain.distance = d;
        detector<exact_rational> exact(A, B, wit);
        test_random::rng r(fp.seed);

        {
            certified_detector<detector> cert(A, B, wit), cert_plain(A, B, plain), cert_into(A, B, wit);
            certified_detector<brute_force_detector> cert_brute(A, B, wit);
            const std::vector<pose> frames = test_poses::near_contact(A, B, generic_count, 0.6, 4, r.gen());
            check_certified_frames(fp, frames, d, exact, cert, cert_brute, cert_plain, cert_into, t);
            t.generic_frames += frames.size();
            t.generic_fallbacks +=
                cert.exact_frames() + cert_brute.exact_frames() + cert_plain.exact_frames() + cert_into.exact_frames();
        }
        {
            certified_detector<detector> cert(A, B, wit), cert_plain(A, B, plain), cert_into(A, B, wit);
            certified_detector<brute_force_detector> cert_brute(A, B, wit);
            const std::vector<pose> frames = test_poses::touching(A, B, r, touching_count);
            check_certified_frames(fp, frames, d, exact, cert, cert_brute, cert_plain, cert_into, t);
            t.touching_frames += frames.size();
            t.touching_fallbacks += cert.exact_frames();
            t.brute_touching_fallbacks += cert_brute.exact_frames();
        }
    }
    return t;
}

void report(const certified_tally& t) {
    INFO("frames " << t.frames << " (collisions " << t.collisions << "), generic " << t.generic_frames
                   << " with fallbacks " << t.generic_fallbacks << ", touching and one-ulp " << t.touching_frames
                   << " with fallbacks " << t.touching_fallbacks << " (detector), " << t.brute_touching_fallbacks
                   << " (brute force)");
    CHECK(t.mismatches == 0);
    // The fallback is exercised on the exact contacts, and never needed on
    // generic frames. Most touching frames are translations whose posed
    // coordinates are doubles, whose exact zeros certified settles in double
    // (orientation_of_doubles); the turned ones still need the fallback.
    CHECK(t.generic_fallbacks == 0);
    CHECK(t.touching_fallbacks * 20 >= t.touching_frames);
    CHECK(t.brute_touching_fallbacks * 20 >= t.touching_frames);
    CHECK(t.collisions >= t.frames / 4);
    CHECK(t.frames - t.collisions >= t.frames / 10);
}

}  // namespace

TEST_CASE("certified detectors equal the exact detector, d = 0", "[detect][certified]") {
    const certified_tally t = run_all(0, 30, 10);
    CHECK(t.frames >= 3000);
    report(t);
}

TEST_CASE("certified detectors equal the exact detector, d = 0.5", "[detect][certified]") {
    const certified_tally t = run_all(0.5, 12, 4);
    CHECK(t.frames >= 1000);
    report(t);
}
