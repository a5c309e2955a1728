// SPDX-License-Identifier: BSL-1.0
#pragma once
// Poses run through the detectors in exact rationals, certified and double,
// each frame against CGAL's exact answer (verification::cgal_reference) and
// double's against the brute force in double: the check of the detect/
// tests whose routes answer frames by shortcuts (deep vertices, cells deep
// outside).

#include <catch2/catch.hpp>

#include <cstddef>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/number/cgal.hpp"
#include "verification/cgal_reference.hpp"

namespace test_frames {

using namespace influence2d;

/// What the frames of one run showed.
struct reference_run {
    std::size_t met = 0;                 ///< frames the reference answered as meeting
    detector_statistics exact_counters;  ///< the exact detector's statistics
};

/// Runs `poses` of B against A through detectors in exact rationals and
/// certified (REQUIREd equal to the reference at distance d) and in double
/// (equal to the brute force in double). With `built` the exact and double
/// detectors build their structures first; without, they build what pays
/// on their own.
inline reference_run run_against_reference(const polygon& a, const polygon& b, const std::vector<pose>& poses, double d,
                                           bool built) {
    const verification::cgal_reference ref(a, b, d);
    detector_options o;
    o.distance = d;
    detector<exact_rational> exact(a, b, o);
    certified_detector<detector> certified(a, b, o);
    detector<double> fast(a, b, o);
    brute_force_detector<double> fast_ref(a, b, o);
    if (built) {
        exact.build_structures();
        fast.build_structures();
    }
    reference_run run;
    for (std::size_t k = 0; k < poses.size(); ++k) {
        INFO("d " << d << " frame " << k << " pose " << poses[k].tx << ", " << poses[k].ty << ", " << poses[k].theta);
        const bool want = ref.collide(poses[k]).collides;
        REQUIRE(exact.collide(poses[k]).collides == want);
        REQUIRE(certified.collide(poses[k]).collides == want);
        REQUIRE(fast.collide(poses[k]).collides == fast_ref.collide(poses[k]).collides);
        run.met += want ? 1 : 0;
    }
    run.exact_counters = exact.statistics();
    return run;
}

}  // namespace test_frames
