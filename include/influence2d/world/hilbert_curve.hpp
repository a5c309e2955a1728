// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Where a cell of a 2^16 x 2^16 grid lies along a Hilbert curve: the order
/// in which the box trees keep their boxes (world/box_tree.hpp).

#include <array>
#include <cstdint>

namespace influence2d {

namespace hilbert_detail {

/// The walk down the curve's quadrants, four levels at a time. The classic
/// walk reads one bit of x and of y per level, from the top: the quadrant's
/// digit is (3 rx) ^ ry, and when ry = 0 the lower bits are turned for the
/// levels below: complemented (both coordinates) when rx = 1, then x and y
/// swapped. Complementing both and swapping commute, so the turns met so far
/// are one of four: a state of two bits (bit 0: complement, bit 1: swap),
/// each level's turn xor-ed in. Entry (state, 4 bits of x, 4 bits of y)
/// holds the four levels' digits (8 bits) and the state after them (2 bits):
/// digits << 2 | state.
constexpr std::array<std::uint16_t, 4 * 16 * 16> four_level_steps() {
    std::array<std::uint16_t, 4 * 16 * 16> out{};
    for (unsigned state = 0; state < 4; ++state)
        for (unsigned nx = 0; nx < 16; ++nx)
            for (unsigned ny = 0; ny < 16; ++ny) {
                unsigned s = state, digits = 0;
                for (int bit = 3; bit >= 0; --bit) {
                    unsigned rx = (nx >> bit) & 1u, ry = (ny >> bit) & 1u;
                    if (s & 2u) {
                        const unsigned t = rx;
                        rx = ry;
                        ry = t;
                    }
                    if (s & 1u) {
                        rx ^= 1u;
                        ry ^= 1u;
                    }
                    digits = digits << 2 | ((3 * rx) ^ ry);
                    if (ry == 0) s ^= (rx == 1 ? 1u : 0u) | 2u;
                }
                out[(state * 16 + nx) * 16 + ny] = static_cast<std::uint16_t>(digits << 2 | s);
            }
    return out;
}

inline constexpr std::array<std::uint16_t, 4 * 16 * 16> steps = four_level_steps();

}  // namespace hilbert_detail

/// The position of cell (x, y), x and y below 2^16, along the Hilbert curve
/// over 2^16 x 2^16 cells that starts at cell (0, 0) and first leaves the
/// lowest quadrant along y. Consecutive positions are neighbouring cells, so
/// boxes sorted by the positions of their centres' cells keep near boxes
/// together. Four table steps of four levels each (hilbert_detail::steps)
/// instead of sixteen levels with two unpredictable branches each.
inline std::uint32_t hilbert_position(std::uint32_t x, std::uint32_t y) {
    std::uint32_t d = 0, state = 0;
    for (int shift = 12; shift >= 0; shift -= 4) {
        const std::uint16_t e = hilbert_detail::steps[(state * 16 + ((x >> shift) & 15u)) * 16 + ((y >> shift) & 15u)];
        d = d << 8 | static_cast<std::uint32_t>(e >> 2);
        state = e & 3u;
    }
    return d;
}

}  // namespace influence2d
