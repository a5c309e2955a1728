// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Whether two polygons at their own coordinates have a vertex in common,
/// decided exactly on their doubles: the proof that neighbours of a layer
/// whose shared border repeats the same vertices (a map's countries,
/// counties, blocks) meet.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"

namespace influence2d {

/// The slots of share_a_vertex's table (a power of two).
inline constexpr std::size_t shared_vertex_slots = 256;

/// The vertices share_a_vertex's table holds at most: half its slots, so
/// that an open-addressed probe stays short (a few slots) whatever the
/// coordinates. The candidates of the real layers of docs/world.md whose
/// polygons have at most 256 vertices each hold at most 23 (counties), 59
/// (blocks), 43 (tracts) and 90 (countries) such vertices of the smaller
/// polygon within the two boxes' overlap; a pair with more is not tried.
inline constexpr std::size_t shared_vertex_most = shared_vertex_slots / 2;

namespace shared_vertex_detail {

/// The slot of v (finite; -0 taken as +0, which `==` counts equal) in a
/// table of 2^bits slots: the top bits of a multiplicative hash of both
/// coordinates' bit patterns.
inline std::size_t slot_of(const point<double>& v, unsigned bits) {
    const double x = v.x + 0.0, y = v.y + 0.0;  // (-0 + 0 is +0)
    std::uint64_t bx = 0, by = 0;
    std::memcpy(&bx, &x, sizeof x);
    std::memcpy(&by, &y, sizeof y);
    const std::uint64_t h = bx * 0x9E3779B97F4A7C15ull ^ by * 0xC2B2AE3D27D4EB4Full;
    return static_cast<std::size_t>(h >> (64 - bits));
}

}  // namespace shared_vertex_detail

/// Whether a vertex of a equals a vertex of b (exactly: `==` on the doubles
/// as given), shown; false when none does, or when the smaller polygon has
/// more than shared_vertex_most vertices in the two boxes' overlap (not
/// tried). A shared vertex lies on both boundaries, so that the closed
/// regions meet; regions that meet elsewhere only are not found.
///
///   w <- the overlap of the two closed boxes (a shared vertex lies in it)
///   the smaller polygon's vertices in w into an open-addressed table
///   each vertex of the other in w looked up: found, shared
///   none shared
///
/// Linear in the two polygons' vertices, with no allocation.
inline bool share_a_vertex(const polygon& a, const polygon& b) {
    using shared_vertex_detail::slot_of;
    constexpr unsigned bits = 8;
    static_assert(std::size_t{1} << bits == shared_vertex_slots, "the table's slots are 2^bits");
    const box &ba = a.bounds(), &bb = b.bounds();
    const double min_x = std::max(ba.min_x, bb.min_x), max_x = std::min(ba.max_x, bb.max_x),
                 min_y = std::max(ba.min_y, bb.min_y), max_y = std::min(ba.max_y, bb.max_y);
    if (min_x > max_x || min_y > max_y) return false;
    const box_membership w(box{min_x, min_y, max_x, max_y});
    const polygon &small = a.size() <= b.size() ? a : b, &large = a.size() <= b.size() ? b : a;
    struct entry {
        double x, y;  // (no initialisation: only the slots marked used are read)
    };
    std::array<entry, shared_vertex_slots> table;
    std::array<unsigned char, shared_vertex_slots> used{};
    const std::size_t mask = shared_vertex_slots - 1;
    std::size_t count = 0;
    for (const point<double>& v : small.vertices()) {
        if (!w.contains(v)) continue;
        if (++count > shared_vertex_most) return false;
        std::size_t s = slot_of(v, bits);
        while (used[s] && !(table[s].x == v.x && table[s].y == v.y)) s = (s + 1) & mask;
        used[s] = 1;
        table[s] = {v.x, v.y};
    }
    if (count == 0) return false;
    for (const point<double>& v : large.vertices()) {
        if (!w.contains(v)) continue;
        for (std::size_t s = slot_of(v, bits); used[s]; s = (s + 1) & mask)
            if (table[s].x == v.x && table[s].y == v.y) return true;
    }
    return false;
}

}  // namespace influence2d
