// libFuzzer target: the detector on arbitrary small polygons and poses. The
// bytes give A and B (3 to 8 vertices each, coordinates k / 16 for k in
// -128..127, sometimes scaled by a power of two), a pose and a distance; the
// sound detector in exact rationals and in certified arithmetic must answer
// as the brute-force reference in exact rationals, witnesses included.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/certified_detector.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/number/cgal.hpp"

namespace {

struct bytes {
    const std::uint8_t* data;
    std::size_t size, at = 0;
    std::uint8_t next() { return at < size ? data[at++] : 0; }
};

influence2d::polygon make(bytes& in, double scale) {
    const std::size_t n = 3 + in.next() % 6;
    std::vector<influence2d::point<double>> v;
    for (std::size_t k = 0; k < n; ++k) {
        const double x = static_cast<std::int8_t>(in.next()) / 16.0, y = static_cast<std::int8_t>(in.next()) / 16.0;
        v.push_back({std::ldexp(x, static_cast<int>(scale)), std::ldexp(y, static_cast<int>(scale))});
    }
    return influence2d::polygon({influence2d::ring_input{v, influence2d::ring_role::outer}});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace influence2d;
    bytes in{data, size};
    const int e = static_cast<std::int8_t>(in.next()) % 64;  // a scale of 2^e, |e| < 64
    try {
        const polygon a = make(in, e), b = make(in, e);
        const pose p{std::ldexp(static_cast<std::int8_t>(in.next()) / 8.0, e),
                     std::ldexp(static_cast<std::int8_t>(in.next()) / 8.0, e),
                     static_cast<std::int8_t>(in.next()) / 32.0};
        detector_options o;
        o.witness = true;
        o.distance = (in.next() % 4 == 0) ? std::ldexp((in.next() % 8) / 8.0, e) : 0.0;
        const frame_result want = brute_force_detector<exact_rational>(a, b, o).collide(p);
        const frame_result exact = detector<exact_rational>(a, b, o).collide(p);
        const frame_result certified = certified_detector<detector>(a, b, o).collide(p);
        if (exact.collides != want.collides || exact.pairs != want.pairs) std::abort();
        if (certified.collides != want.collides || certified.pairs != want.pairs) std::abort();
    } catch (const invalid_input&) {
        // fewer than three distinct vertices: refused, as it must be
    }
    return 0;
}
