// SPDX-License-Identifier: BSL-1.0
#pragma once
// What the geometric fuzz targets make of their bytes: numbers read in
// turn (0 past the end) and small multipolygons of 1 to 3 rings (ring 0
// outer, the others outer or hole), each ring of 3 to 8 vertices k / 16
// (k in -128..127) about an offset of its own in [-32, 32) (so that parts
// lie apart, inside one another or inside the other polygon), all scaled by
// 2^e.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "influence2d/core/polygon.hpp"

namespace fuzz_input {

/// The bytes, read in turn.
struct bytes {
    const std::uint8_t* data;
    std::size_t size, at = 0;
    /// The next byte, 0 past the end.
    std::uint8_t next() { return at < size ? data[at++] : 0; }
    /// The next byte as a signed number over d.
    double signed_over(double d) { return static_cast<std::int8_t>(next()) / d; }
};

/// A multipolygon from the bytes (see the file's comment), scaled by 2^e;
/// its constructor throws invalid_input for a ring of fewer than three
/// distinct vertices.
inline influence2d::polygon polygon(bytes& in, int e) {
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

}  // namespace fuzz_input
