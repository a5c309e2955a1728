// SPDX-License-Identifier: BSL-1.0
// libFuzzer target: the certified separation and first contact on arbitrary
// small multipolygons. The bytes give A and B as detector_fuzz makes them
// (1 to 3 rings of 3 to 8 vertices k / 16 about offsets of their own, all
// scaled by 2^e, |e| < 64), B's pose and a translation of B. Against the
// independent exact reference (tests/support: both polygons placed on
// CGAL's kernel over exact rationals, its own predicates and squared
// distances, and every vertex-edge contact time solved as a segment
// intersection):
// - certified_separation: whether they meet, the squared distance rounded
//   to the nearest double, the distance within a unit in the last place of
//   the exact one;
// - certified_first_contact of B translated from its pose: whether it
//   meets A and the earliest time rounded to the nearest double.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <vector>

#include <CGAL/squared_distance_2.h>

#include "fuzz_input.hpp"
#include "influence2d/exact/certified_first_contact.hpp"
#include "influence2d/exact/certified_separation.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/exact_distance.hpp"
#include "support/exact_regions.hpp"

namespace {

// The exact squared distance between two placed polygons: 0 when their
// regions meet, else the least over their edge pairs.
test_exact::FT squared_gap(const test_exact::placed_shape& a, const test_exact::placed_shape& b) {
    if (test_exact::regions_meet(a, b)) return 0;
    std::optional<test_exact::FT> least;
    for (std::size_t i = 0; i < a.v.size(); ++i)
        for (std::size_t j = 0; j < b.v.size(); ++j) {
            const test_exact::FT d2 = CGAL::squared_distance(test_exact::segment_2(a.v[i], a.end(i)),
                                                             test_exact::segment_2(b.v[j], b.end(j)));
            if (!least || d2 < *least) least = d2;
        }
    return *least;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace influence2d;
    fuzz_input::bytes in{data, size};
    const int e = static_cast<std::int8_t>(in.next()) % 64;  // a scale of 2^e, |e| < 64
    try {
        const polygon a = fuzz_input::polygon(in, e), b = fuzz_input::polygon(in, e);
        const pose from{std::ldexp(in.signed_over(4), e), std::ldexp(in.signed_over(4), e),
                        in.next() % 2 == 0 ? 0.0 : in.signed_over(32)};
        const pose to{from.tx + std::ldexp(in.signed_over(2), e), from.ty + std::ldexp(in.signed_over(2), e),
                      from.theta};
        const test_exact::placed_shape pa = test_exact::place(a, pose{}), pb = test_exact::place(b, from);

        const test_exact::FT d2 = squared_gap(pa, pb);
        const certified_separation_result s = certified_separation(a, b, from);
        if (s.meet != (d2 == 0) || s.squared_distance != test_exact::nearest_double(d2)) std::abort();
        const double up = std::nextafter(s.distance, std::numeric_limits<double>::infinity()),
                     down = std::nextafter(s.distance, 0.0);
        if (!test_exact::at_least_root(test_exact::Q(up), d2) || !test_exact::at_most_root(test_exact::Q(down), d2))
            std::abort();

        if (to.tx == from.tx && to.ty == from.ty) return 0;  // no motion
        const test_exact::vector_2 m(test_exact::FT(to.tx) - test_exact::FT(from.tx),
                                     test_exact::FT(to.ty) - test_exact::FT(from.ty));
        const std::optional<test_exact::FT> want = test_exact::first_contact(pa, pb, m);
        const contact_result<double> got = certified_first_contact(a, b, from, to);
        if (got.contact != want.has_value()) std::abort();
        if (want && got.time != test_exact::nearest_double(*want)) std::abort();
    } catch (const invalid_input&) {
        // fewer than three distinct vertices: refused, as it must be
    }
    return 0;
}
