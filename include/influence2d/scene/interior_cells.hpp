// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which points certainly lie in a polygon's closed region, and which
/// certainly outside it, answered by one look-up in a grid over its box: the
/// cells that hold no point of the boundary and lie in the region (or
/// outside it), with their eight neighbours.

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/influence/bounds.hpp"

namespace influence2d {

/// A grid of square cells over a polygon's box that marks the cells lying
/// deep in its closed region, and those lying deep outside it: a deep cell
/// and its eight neighbours hold no point of the boundary and lie all in
/// the region (all outside it). A point whose cell, found in double, is
/// deep inside lies in the region, and so does every point within half a
/// cell of it: holds() answers "certainly inside" with one look-up, and
/// false when it cannot tell; excludes() answers "certainly outside" so
/// from the cells deep outside. Built once per polygon (see
/// static_scene::interior), in time linear in the cells and the edges.
///
///   size the cells: about cells_per_edge cells per edge, square
///   mark every cell an edge may touch (closed cells: each edge's slabs
///     widened by the slack)
///   for each row, the edges crossing the horizontal line through its
///     cells' centres, by exact comparisons of y (half open, as for a
///     ray), each at its x in double with its direction
///   an unmarked cell is inside when the crossings left of its centre
///     wind about it (a sum of directions not zero), outside otherwise
///   a cell is deep inside (outside) when it and its eight neighbours are
///     inside (outside)
///
/// The one comparison in double, a crossing's x against a centre's, is
/// right for every unmarked cell: the edge meets the centre's line at a
/// point of the cell when it is within half a side of the centre, and the
/// cell is then marked, so an unmarked cell's crossings lie more than
/// half a side from its centre, far beyond the rounding of their x (below
/// the slack, which is at most an eighth of a side).
class interior_cells {
public:
    /// A grid with no cell: holds() is always false.
    interior_cells() = default;

    /// Builds the grid over `shape`. A polygon whose box is flat, or whose
    /// cells would be too small against the rounding of its coordinates,
    /// gets no deep cell.
    explicit interior_cells(const polygon& shape) {
        const box& b = shape.bounds();
        box_ = b;
        const double width = b.max_x - b.min_x, height = b.max_y - b.min_y;
        if (shape.size() < 3 || !(width > 0) || !(height > 0) || !std::isfinite(width * height)) return;
        const double wanted = std::clamp(static_cast<double>(shape.size()) * cells_per_edge, min_cells, max_cells);
        side_ = std::sqrt(width * height / wanted);
        const double columns = std::ceil(width / side_), rows = std::ceil(height / side_);
        slack_ = marking_slack * (coordinate_scale(shape) + side_);
        if (!(slack_ <= side_ * max_slack_per_side) || !(columns >= 3 && rows >= 3 && columns * rows <= 2 * max_cells))
            return;
        nx_ = static_cast<std::size_t>(columns);
        ny_ = static_cast<std::size_t>(rows);
        words_ = (nx_ + 63) / 64;
        x0_ = b.min_x;
        y0_ = b.min_y;
        inverse_side_ = 1 / side_;
        std::vector<std::uint64_t> marked(words_ * ny_, 0);
        for (std::size_t e = 0; e < shape.size(); ++e) mark(shape.vertex(e), shape.vertex(shape.next(e)), marked);
        const std::vector<std::uint64_t> inside = inside_cells(shape, marked);
        bits_ = deep_of(inside, deep_);
        // The unmarked cells that are not inside; bits past the last column
        // stay clear.
        std::vector<std::uint64_t> outside(words_ * ny_, 0);
        for (std::size_t j = 0; j < ny_; ++j)
            for (std::size_t w = 0; w < words_; ++w) {
                const std::size_t used = std::min<std::size_t>(64, nx_ - 64 * w);
                const std::uint64_t in_row = used == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << used) - 1;
                outside[j * words_ + w] = in_row & ~marked[j * words_ + w] & ~inside[j * words_ + w];
            }
        outside_bits_ = deep_of(outside, deep_outside_);
    }

    /// Whether every point within `margin` of q certainly lies in the
    /// polygon's closed region: q's cell (found in double) is deep and the
    /// margin is at most half a side. False for a point off the grid, a NaN
    /// coordinate, or a margin that is not a number.
    bool holds(const point<double>& q, double margin) const { return in_deep(bits_, q, margin); }

    /// Whether every point within `margin` of q certainly lies outside the
    /// polygon's closed region: q lies beyond the polygon's box by more
    /// than the margin (beyond_box), or q's cell (found in double) is deep
    /// outside and the margin is at most half a side. False for a NaN or
    /// infinite coordinate, or a margin that is not a number.
    bool excludes(const point<double>& q, double margin) const {
        return beyond_box(q, margin) || in_deep(outside_bits_, q, margin);
    }

    /// Whether no cell is deep inside (holds() is then always false).
    bool empty() const { return bits_.empty(); }
    /// The number of cells deep inside.
    std::size_t deep_cells() const { return deep_; }
    /// The number of cells deep outside.
    std::size_t deep_outside_cells() const { return deep_outside_; }
    /// The side of a cell (0 without a grid).
    double cell_side() const { return side_; }
    /// Bytes of the heap blocks held.
    std::size_t heap_bytes() const { return (bits_.capacity() + outside_bits_.capacity()) * sizeof(std::uint64_t); }

private:
    /// About 128 cells per edge (16 bytes of bits): fine enough that the
    /// thin parts of real polygons (a country a few cells wide) keep deep
    /// cells.
    static constexpr double cells_per_edge = 128;
    /// Bounds on the cells: at least 32 x 32 for a polygon of few edges (a
    /// few microseconds to build), at most 2^20 (128 KiB of bits) for one
    /// of many.
    static constexpr double min_cells = 1024, max_cells = 1048576;
    /// The widening of each edge's marked slabs, relative to the
    /// coordinates' scale plus a side. A cell's sides, x0 + i side, an
    /// edge's y over a slab (a difference, a product by the rounded
    /// reciprocal of the edge's dx clamped to [0, 1], a product and a sum),
    /// a crossing's x, and a point's cell index
    /// ((x - x0) / side, with the side's reciprocal rounded) are each within
    /// a few units in the last place (2^-52) of the scale plus a side; 2^-40
    /// covers them with room, so that every cell a closed edge touches is
    /// marked, both cells when it runs along their shared side, and a
    /// point's computed cell is within the slack of its own.
    static constexpr double marking_slack = 0x1p-40;
    /// beyond_box's widening: 2^-50 = 8u against the 2u or so of rounding
    /// it covers; and the least normal double for gaps that underflow.
    static constexpr double box_slack = 0x1p-50;
    static constexpr double min_normal = std::numeric_limits<double>::min();
    /// Cells smaller than 8 slacks are not built: the slack and a margin of
    /// half a side then stay below one side, so that every point within
    /// the margin of a point whose computed cell is c lies in c's 3 x 3
    /// block.
    static constexpr double max_slack_per_side = 0.125;

    /// Whether q lies beyond the polygon's box by more than `margin` on one
    /// axis: a gap g computed in double (one subtraction, within u = 2^-53
    /// of |q| plus the box's coordinate) exceeds the margin widened by
    /// box_slack of both. The widening covers the gap's rounding and the
    /// few of its own right side (each within u of it) with room.
    bool beyond_box(const point<double>& q, double margin) const {
        if (box_.empty()) return false;
        const auto beyond = [&](double gap, double x, double side) {
            return gap > margin + box_slack * (std::fabs(x) + std::fabs(side) + margin) + min_normal;
        };
        return beyond(box_.min_x - q.x, q.x, box_.min_x) || beyond(q.x - box_.max_x, q.x, box_.max_x) ||
               beyond(box_.min_y - q.y, q.y, box_.min_y) || beyond(q.y - box_.max_y, q.y, box_.max_y);
    }

    /// Whether q's cell (found in double) is set in `deep` and the margin
    /// is at most half a side (see holds).
    bool in_deep(const std::vector<std::uint64_t>& deep, const point<double>& q, double margin) const {
        if (deep.empty() || !(margin <= side_ / 2)) return false;
        const double u = (q.x - x0_) * inverse_side_, v = (q.y - y0_) * inverse_side_;
        if (!(u >= 0 && v >= 0 && u < static_cast<double>(nx_) && v < static_cast<double>(ny_))) return false;
        const auto i = static_cast<std::size_t>(u);
        return (deep[static_cast<std::size_t>(v) * words_ + i / 64] >> (i % 64)) & 1;
    }

    /// The cells of `cells` whose eight neighbours are in `cells` too, as
    /// bits of rows (no cell of the border rows or columns), counted in
    /// `count`; no block when none is.
    std::vector<std::uint64_t> deep_of(const std::vector<std::uint64_t>& cells, std::size_t& count) const {
        std::vector<std::uint64_t> deep(words_ * ny_, 0);
        std::vector<std::uint64_t> column(words_);
        count = 0;
        for (std::size_t j = 1; j + 1 < ny_; ++j) {
            const std::uint64_t* below = &cells[(j - 1) * words_];
            const std::uint64_t* row = &cells[j * words_];
            const std::uint64_t* above = &cells[(j + 1) * words_];
            // Column neighbours first (three rows), then row neighbours by
            // shifts across words; bits past the last column stay clear.
            for (std::size_t w = 0; w < words_; ++w) column[w] = below[w] & row[w] & above[w];
            for (std::size_t w = 0; w < words_; ++w) {
                const std::uint64_t from_left = (column[w] << 1) | (w > 0 ? column[w - 1] >> 63 : 0);
                const std::uint64_t from_right = (column[w] >> 1) | (w + 1 < words_ ? column[w + 1] << 63 : 0);
                const std::uint64_t d = column[w] & from_left & from_right;
                deep[j * words_ + w] = d;
                count += std::bitset<64>(d).count();
            }
        }
        if (count == 0) deep.clear();
        return deep;
    }

    /// The grid column (or row, with y0 for x0 and ny for nx) of coordinate
    /// x, clamped to [0, n - 1] (0 for a NaN). (The conversion truncates,
    /// which is the floor for the positive values it is given.)
    std::size_t cell_of(double x, double origin, std::size_t n) const {
        const double u = (x - origin) * inverse_side_;
        return !(u > 0) ? 0 : u >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(u);
    }
    /// The centre's coordinate of column (row) i.
    double centre_of(std::size_t i, double origin) const { return origin + (static_cast<double>(i) + 0.5) * side_; }

    /// Marks every cell the closed edge [a, b] may touch: over each column
    /// the edge's x range meets (widened by the slack), the rows of its y
    /// range over that column's slab (widened by the slack).
    void mark(const point<double>& a, const point<double>& b, std::vector<std::uint64_t>& marked) const {
        const double lo_x = std::min(a.x, b.x), hi_x = std::max(a.x, b.x);
        const double lo_y = std::min(a.y, b.y), hi_y = std::max(a.y, b.y);
        const std::size_t first = cell_of(lo_x - slack_, x0_, nx_), last = cell_of(hi_x + slack_, x0_, nx_);
        const double inverse_dx = a.x != b.x ? 1 / (b.x - a.x) : 0, dy = b.y - a.y;
        for (std::size_t i = first; i <= last; ++i) {
            const double l = std::max(lo_x, x0_ + static_cast<double>(i) * side_ - slack_);
            const double r = std::min(hi_x, x0_ + static_cast<double>(i + 1) * side_ + slack_);
            double y_l = lo_y, y_r = hi_y;
            if (a.x != b.x) {
                const double tl = std::clamp((l - a.x) * inverse_dx, 0.0, 1.0);
                const double tr = std::clamp((r - a.x) * inverse_dx, 0.0, 1.0);
                y_l = a.y + tl * dy;
                y_r = a.y + tr * dy;
            }
            const double bottom = std::max(lo_y, std::min(y_l, y_r)) - slack_;
            const double top = std::min(hi_y, std::max(y_l, y_r)) + slack_;
            const std::size_t row_end = cell_of(top, y0_, ny_);
            for (std::size_t j = cell_of(bottom, y0_, ny_); j <= row_end; ++j)
                marked[j * words_ + i / 64] |= std::uint64_t{1} << (i % 64);
        }
    }

    /// The unmarked cells whose centre the boundary winds about, as bits
    /// of rows (see the class comment). Each crossing adds its direction to
    /// the first cell of its row whose centre lies right of it; the sums
    /// along a row then count the crossings left of each centre. A
    /// crossing's cell found in double can be off only for the cells whose
    /// centre is within its rounding of the crossing, which are marked.
    std::vector<std::uint64_t> inside_cells(const polygon& shape, const std::vector<std::uint64_t>& marked) const {
        const std::size_t stride = nx_ + 1;
        std::vector<std::int32_t> delta(stride * ny_, 0);
        for (std::size_t e = 0; e < shape.size(); ++e) {
            const point<double>&a = shape.vertex(e), &b = shape.vertex(shape.next(e));
            if (a.y == b.y) continue;
            const double inverse_slope = (b.x - a.x) / (b.y - a.y);
            const std::size_t last = cell_of(std::max(a.y, b.y) + slack_, y0_, ny_);
            for (std::size_t j = cell_of(std::min(a.y, b.y) - slack_, y0_, ny_); j <= last; ++j) {
                const double y = centre_of(j, y0_);
                const int direction = a.y <= y && y < b.y ? 1 : b.y <= y && y < a.y ? -1 : 0;
                if (direction == 0) continue;
                const double x = a.x + (y - a.y) * inverse_slope;
                // The first centre right of x: column floor(v) + 1 for
                // v = (x - x0) / side - 1/2 (truncation for v >= 0).
                const double v = (x - x0_) * inverse_side_ - 0.5;
                const std::size_t i = !(v >= 0)                           ? 0
                                      : v >= static_cast<double>(nx_ - 1) ? nx_
                                                                          : static_cast<std::size_t>(v) + 1;
                delta[j * stride + i] += direction;
            }
        }
        std::vector<std::uint64_t> inside(words_ * ny_, 0);
        for (std::size_t j = 0; j < ny_; ++j) {
            const std::int32_t* d = &delta[j * stride];
            long long winding = 0;
            for (std::size_t w = 0; w < words_; ++w) {
                const std::size_t end = std::min<std::size_t>(64, nx_ - 64 * w);
                std::uint64_t wound = 0;
                for (std::size_t k = 0; k < end; ++k) {
                    winding += d[64 * w + k];
                    wound |= static_cast<std::uint64_t>(winding != 0) << k;
                }
                inside[j * words_ + w] = wound & ~marked[j * words_ + w];
            }
        }
        return inside;
    }

    box box_;  ///< the polygon's box (empty for an empty polygon)
    double x0_ = 0, y0_ = 0, side_ = 0, inverse_side_ = 0, slack_ = 0;
    std::size_t nx_ = 0, ny_ = 0, words_ = 0, deep_ = 0, deep_outside_ = 0;
    std::vector<std::uint64_t> bits_;          ///< row j's bits at j words_: bit i of the row is cell (i, j) deep
    std::vector<std::uint64_t> outside_bits_;  ///< the same for the cells deep outside
};

}  // namespace influence2d
