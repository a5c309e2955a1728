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

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/number/cgal.hpp"
#include "verification/cgal_reference.hpp"

namespace {

struct bytes {
    const std::uint8_t* data;
    std::size_t size, at = 0;
    std::uint8_t next() { return at < size ? data[at++] : 0; }
    double signed_over(double d) { return static_cast<std::int8_t>(next()) / d; }
};

influence2d::polygon make(bytes& in, int e) {
    std::vector<influence2d::ring_input> rings(1 + in.next() % 3);
    for (std::size_t r = 0; r < rings.size(); ++r) {
        const bool hole = in.next() % 3 == 0 && r > 0;
        rings[r].role = hole ? influence2d::ring_role::hole : influence2d::ring_role::outer;
        const std::size_t n = 3 + in.next() % 6;
        const double ox = in.signed_over(4), oy = in.signed_over(4);
        for (std::size_t k = 0; k < n; ++k) {
            const double x = in.signed_over(16) + ox, y = in.signed_over(16) + oy;
            rings[r].vertices.push_back({std::ldexp(x, e), std::ldexp(y, e)});
        }
    }
    return influence2d::polygon(std::move(rings));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace influence2d;
    bytes in{data, size};
    const int e = static_cast<std::int8_t>(in.next()) % 64;  // a scale of 2^e, |e| < 64
    try {
        const polygon a = make(in, e), b = make(in, e);
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
