// SPDX-License-Identifier: BSL-1.0
#pragma once
// Polygons as WKB (what shapely's `.wkb` and GeoPandas' `to_wkb` give):
// POLYGON and MULTIPOLYGON, either byte order, ISO or extended WKB with an
// SRID; no Z or M coordinates (as the WKT reader takes x and y only).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "influence2d/core/invalid_input.hpp"
#include "influence2d/io/wkt.hpp"

namespace influence2d::python {

/// Reads WKB bytes into rings as given (closing points included), numbered
/// as the WKT reader numbers them: every ring of every part in order, each
/// part's first ring outer. Throws invalid_input starting with `source` for
/// bytes that are not WKB of a polygon (truncated, another geometry type, Z
/// or M coordinates, trailing bytes, an empty geometry).
class wkb_reader {
public:
    wkb_reader(const char* data, std::size_t size, std::string source)
        : p_(data), n_(size), source_(std::move(source)) {}

    std::vector<wkt_ring> rings() {
        std::vector<wkt_ring> out;
        const std::uint32_t type = header();
        if (type == 3) {
            polygon_body(out);
        } else if (type == 6) {
            const std::uint32_t parts = count("polygons");
            for (std::uint32_t k = 0; k < parts; ++k) {
                if (header() != 3) fail("part " + std::to_string(k) + " of the MULTIPOLYGON is not a POLYGON");
                polygon_body(out);
            }
        } else {
            fail("expected a WKB POLYGON (3) or MULTIPOLYGON (6), found geometry type " + std::to_string(type));
        }
        if (at_ != n_) fail(std::to_string(n_ - at_) + " bytes after the geometry");
        if (out.empty()) fail("the geometry is empty");
        return out;
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw invalid_input(source_ + ": " + what); }

    void need(std::size_t bytes) const {
        if (n_ - at_ < bytes)
            fail("truncated WKB: " + std::to_string(bytes) + " bytes needed at byte " + std::to_string(at_) + " of " +
                 std::to_string(n_));
    }

    std::uint32_t u32() {
        need(4);
        unsigned char b[4];
        std::memcpy(b, p_ + at_, 4);
        at_ += 4;
        return little_ ? std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 | std::uint32_t{b[2]} << 16 |
                             std::uint32_t{b[3]} << 24
                       : std::uint32_t{b[3]} | std::uint32_t{b[2]} << 8 | std::uint32_t{b[1]} << 16 |
                             std::uint32_t{b[0]} << 24;
    }

    double f64() {
        need(8);
        unsigned char b[8];
        std::memcpy(b, p_ + at_, 8);
        at_ += 8;
        std::uint64_t bits = 0;
        for (int i = 0; i < 8; ++i) bits |= std::uint64_t{b[little_ ? i : 7 - i]} << (8 * i);
        double x;
        std::memcpy(&x, &bits, 8);
        return x;
    }

    /// The byte order and the geometry type (an SRID skipped).
    std::uint32_t header() {
        need(1);
        const auto order = static_cast<unsigned char>(p_[at_++]);
        if (order > 1)
            fail("byte " + std::to_string(at_ - 1) + ": byte order " + std::to_string(order) + " is not 0 or 1");
        little_ = order == 1;
        std::uint32_t type = u32();
        if (type & 0x20000000u) {  // extended WKB: an SRID follows
            type &= ~0x20000000u;
            u32();
        }
        if ((type & 0xC0000000u) || type >= 1000)
            fail("geometry type " + std::to_string(type) + " has Z or M coordinates: x and y only");
        return type;
    }

    /// A count, checked against the bytes left (each element at least `least` bytes).
    std::uint32_t count(const char* what, std::size_t least = 4) {
        const std::uint32_t c = u32();
        if (static_cast<std::size_t>(c) > (n_ - at_) / least)
            fail(std::to_string(c) + " " + what + " announced, more than the " + std::to_string(n_ - at_) +
                 " bytes left hold");
        return c;
    }

    void polygon_body(std::vector<wkt_ring>& out) {
        const std::uint32_t rings = count("rings");
        for (std::uint32_t r = 0; r < rings; ++r) {
            wkt_ring ring;
            ring.role = r == 0 ? ring_role::outer : ring_role::hole;
            const std::uint32_t points = count("points", 16);
            ring.points.reserve(points);
            for (std::uint32_t k = 0; k < points; ++k) {
                const double x = f64();
                ring.points.push_back({x, f64()});
            }
            out.push_back(std::move(ring));
        }
    }

    const char* p_;
    std::size_t n_;
    std::size_t at_ = 0;
    bool little_ = true;
    std::string source_;
};

}  // namespace influence2d::python
