// SPDX-License-Identifier: BSL-1.0
// libFuzzer target: the detector on arbitrary small multipolygons and poses.
// The bytes give A and B, each of 1 to 3 rings (ring 0 outer, the others
// outer or hole), each ring of 3 to 8 vertices k / 16 (k in -128..127) about
// an offset of its own in [-32, 32) (so that parts lie apart, inside one
// another or inside the other polygon), all scaled by 2^e with |e| < 64; then
// a pose and a distance. The sound detector in exact rationals and in
// certified arithmetic, and the brute force, must answer as the independent
// CGAL reference (verification/cgal_reference.hpp), witnesses included.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "fuzz_input.hpp"
#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/number/cgal.hpp"
#include "verification/cgal_reference.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace influence2d;
    fuzz_input::bytes in{data, size};
    const int e = static_cast<std::int8_t>(in.next()) % 64;  // a scale of 2^e, |e| < 64
    try {
        const polygon a = fuzz_input::polygon(in, e), b = fuzz_input::polygon(in, e);
        const pose p{std::ldexp(in.signed_over(4), e), std::ldexp(in.signed_over(4), e), in.signed_over(32)};
        detector_options o;
        o.witness = true;
        o.distance = (in.next() % 4 == 0) ? std::ldexp((in.next() % 8) / 8.0, e) : 0.0;
        const frame_result want = verification::cgal_reference(a, b, o.distance, true).collide(p);
        const frame_result brute = brute_force_detector<exact_rational>(a, b, o).collide(p);
        const frame_result exact = detector<exact_rational>(a, b, o).collide(p);
        const frame_result certified = certified_detector<detector>(a, b, o).collide(p);
        if (brute.collides != want.collides || brute.pairs != want.pairs) std::abort();
        if (exact.collides != want.collides || exact.pairs != want.pairs) std::abort();
        if (certified.collides != want.collides || certified.pairs != want.pairs) std::abort();
    } catch (const invalid_input&) {
        // fewer than three distinct vertices: refused, as it must be
    }
    return 0;
}
