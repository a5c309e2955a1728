// SPDX-License-Identifier: BSL-1.0
#pragma once
// The paper's own comparison: an image-space test after PIVOT2D, on the CPU.
// Both polygons are rasterised on one grid of square pixels and the test
// asks whether a pixel is covered by both. A pixel is covered when its
// centre lies in the region (nonzero winding: the rings as the polygon
// stores them, outer counter-clockwise, holes clockwise).
//
// The grid covers A's bounding box with R pixels along its longer side: the
// common part of A and B lies in that box, so no pixel outside it matters.
// A's mask is made once, one bit per pixel; each pose poses B's vertices in
// double and scans B row by row inside the grid, stopping at the first run
// of pixels that holds one of A's. Approximate by design: a contact that
// only touches, or an overlap thinner than a pixel, is missed when no pixel
// centre falls in it. A contact it reports is a pixel centre in both
// regions, a common point, so up to the rounding of B's posing and of the
// crossings it invents none: its error is missed contacts.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"

namespace influence2d::verification {

/// A grid of square pixels: its lower left corner, the pixel's side, and
/// its columns and rows.
struct raster_grid {
    double x0 = 0, y0 = 0, pixel = 1;
    std::size_t columns = 1, rows = 1;

    /// The grid over box b with `resolution` pixels along its longer side
    /// (at least one pixel each way).
    static raster_grid over(const box& b, std::size_t resolution) {
        raster_grid g;
        const double w = b.max_x - b.min_x, h = b.max_y - b.min_y;
        const double side = std::max(w, h);
        g.x0 = b.min_x;
        g.y0 = b.min_y;
        g.pixel = side > 0 ? side / static_cast<double>(resolution) : 1;
        g.columns = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(w / g.pixel)));
        g.rows = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(h / g.pixel)));
        g.columns = std::min(g.columns, resolution);
        g.rows = std::min(g.rows, resolution);
        return g;
    }

    /// The first index k whose pixel centre c0 + (k + 1/2) pixel is >= v,
    /// clamped to [-1, count] (-1 also for a NaN), so that it converts to
    /// an integer whatever v is.
    static long first_centre_at_or_after(double v, double c0, double pixel, std::size_t count) {
        const double k = std::ceil((v - c0) / pixel - 0.5);
        if (!(k > -1)) return -1;
        if (k > static_cast<double>(count)) return static_cast<long>(count);
        return static_cast<long>(k);
    }
};

/// One crossing of a row's centre line by an edge: its row, where, and +1
/// for an edge going up, -1 going down.
struct raster_crossing {
    long row;
    double x;
    int direction;
    friend bool operator<(const raster_crossing& l, const raster_crossing& r) {
        return l.row != r.row ? l.row < r.row : l.x < r.x;
    }
};

/// Calls covered(row, first, last) for each run of pixels [first, last] of
/// grid g whose centres lie in the region bounded by the rings of `shape`
/// with vertices `v` (shape's vertices, posed), row by row from the bottom;
/// stops and returns true as soon as `covered` does. An edge counts for the
/// centre lines from its lower end up to (not including) its upper end, so
/// a vertex between two edges counts once. `crossings` is scratch space.
template <class Covered>
bool scan_region(const raster_grid& g, const polygon& shape, const std::vector<point<double>>& v,
                 std::vector<raster_crossing>& crossings, Covered&& covered) {
    crossings.clear();
    const long rows = static_cast<long>(g.rows), columns = static_cast<long>(g.columns);
    for (std::size_t i = 0; i < shape.size(); ++i) {
        const point<double>&a = v[i], &b = v[shape.next(i)];
        if (a.y == b.y) continue;
        const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
        const long first = std::max(0L, raster_grid::first_centre_at_or_after(lo, g.y0, g.pixel, g.rows));
        const long last = std::min(rows - 1, raster_grid::first_centre_at_or_after(hi, g.y0, g.pixel, g.rows) - 1);
        const double slope = (b.x - a.x) / (b.y - a.y);
        for (long r = first; r <= last; ++r) {
            const double y = g.y0 + (static_cast<double>(r) + 0.5) * g.pixel;
            crossings.push_back({r, a.x + (y - a.y) * slope, b.y > a.y ? 1 : -1});
        }
    }
    std::sort(crossings.begin(), crossings.end());
    int winding = 0;
    double start = 0;
    for (std::size_t k = 0; k < crossings.size(); ++k) {
        const raster_crossing& c = crossings[k];
        const int before = winding;
        winding += c.direction;
        if (before == 0 && winding != 0) start = c.x;
        if (before != 0 && winding == 0) {
            const long first = std::max(0L, raster_grid::first_centre_at_or_after(start, g.x0, g.pixel, g.columns));
            const long last =
                std::min(columns - 1, raster_grid::first_centre_at_or_after(c.x, g.x0, g.pixel, g.columns) - 1);
            if (first <= last && covered(static_cast<std::size_t>(c.row), static_cast<std::size_t>(first),
                                         static_cast<std::size_t>(last)))
                return true;
        }
        if (k + 1 == crossings.size() || crossings[k + 1].row != c.row) winding = 0;
    }
    return false;
}

/// One bit per pixel of a grid, each row in whole 64-bit words.
class raster_mask {
public:
    explicit raster_mask(const raster_grid& g)
        : words_per_row_((g.columns + 63) / 64), bits_(words_per_row_ * g.rows) {}

    /// Sets pixels [first, last] of a row.
    void set(std::size_t row, std::size_t first, std::size_t last) {
        for_words(row, first, last, [](std::uint64_t& w, std::uint64_t m) {
            w |= m;
            return false;
        });
    }
    /// Whether one of the pixels [first, last] of a row is set.
    bool any(std::size_t row, std::size_t first, std::size_t last) {
        return for_words(row, first, last, [](std::uint64_t& w, std::uint64_t m) { return (w & m) != 0; });
    }

private:
    template <class F>
    bool for_words(std::size_t row, std::size_t first, std::size_t last, F&& f) {
        std::uint64_t* words = bits_.data() + row * words_per_row_;
        for (std::size_t w = first / 64; w <= last / 64; ++w) {
            const std::size_t lo = w == first / 64 ? first % 64 : 0, hi = w == last / 64 ? last % 64 : 63;
            const std::uint64_t m =
                (hi == 63 ? ~std::uint64_t{0} : (std::uint64_t{1} << (hi + 1)) - 1) & ~((std::uint64_t{1} << lo) - 1);
            if (f(words[w], m)) return true;
        }
        return false;
    }

    std::size_t words_per_row_;
    std::vector<std::uint64_t> bits_;
};

/// The image-space test at `resolution` pixels along the longer side of A's
/// box: A's mask made once, B scanned at each pose (see the file comment).
class raster_test {
public:
    raster_test(const polygon& A, const polygon& B, std::size_t resolution)
        : b_(B), grid_(raster_grid::over(A.bounds(), std::max<std::size_t>(resolution, 1))), mask_(grid_) {
        box_ = A.bounds();
        scan_region(grid_, A, A.vertices(), crossings_, [&](std::size_t row, std::size_t first, std::size_t last) {
            mask_.set(row, first, last);
            return false;
        });
        posed_.resize(B.size());
    }

    /// Whether a pixel centre lies in A and in B posed by p.
    bool collide(const pose& p) {
        const rotation_pose t(p);
        box bb;
        for (std::size_t j = 0; j < b_.size(); ++j) {
            posed_[j] = t.apply<double>(b_.vertex(j));
            bb.add(posed_[j]);
        }
        if (bb.max_x < box_.min_x || bb.min_x > box_.max_x || bb.max_y < box_.min_y || bb.min_y > box_.max_y)
            return false;
        return scan_region(grid_, b_, posed_, crossings_, [&](std::size_t row, std::size_t first, std::size_t last) {
            return mask_.any(row, first, last);
        });
    }

private:
    polygon b_;
    raster_grid grid_;
    raster_mask mask_;
    box box_;
    std::vector<point<double>> posed_;
    std::vector<raster_crossing> crossings_;
};

/// The time study's method for resolution R (raster-R).
template <std::size_t R>
class raster_peer : public raster_test {
public:
    static_assert(R >= 1, "raster_peer: at least one pixel");
    static std::string name() { return "raster-" + std::to_string(R); }
    raster_peer(const polygon& A, const polygon& B) : raster_test(A, B, R) {}
};

}  // namespace influence2d::verification
