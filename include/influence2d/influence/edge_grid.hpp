// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// A uniform grid over the static polygon, in its own (fixed) frame, listing for
/// each cell the edges that may come within a reach of a point of the cell. It
/// answers "which edges can be within the reach of p" without a scan of all
/// edges; a conservative filter in double, never a decision.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/predicates/filters.hpp"

namespace influence2d {

/// A read-only view of a run of edge indices, valid while the edge_grid that
/// gave it lives and is not assigned to. Default: empty.
struct edge_list {
    const std::uint32_t* first = nullptr;  ///< the first index
    const std::uint32_t* last = nullptr;   ///< one past the last index
    /// The first index, for range-for.
    const std::uint32_t* begin() const { return first; }
    /// One past the last index, for range-for.
    const std::uint32_t* end() const { return last; }
    /// Whether the run holds no index.
    bool empty() const { return first == last; }
    /// How many indices the run holds.
    std::size_t size() const { return static_cast<std::size_t>(last - first); }
};

/// A uniform grid over a polygon's box grown by the reach, each cell listing
/// the edges that may come within the reach of one of its points. Cells are
/// about as wide as the reach, but no more than about 8 per edge in all and
/// 4096 per axis; a query costs one cell lookup. The lists are conservative:
/// they may hold edges farther away, never miss a near one. In double.
class edge_grid {
public:
    /// An empty grid: every query gives no edge.
    edge_grid() = default;

    /// Indexes the edges of `shape` for queries of reach `reach`: a point p
    /// whose distance to an edge is at most `reach` finds that edge in the list
    /// of its cell. `slack` is an absolute margin added for double rounding.
    /// Zero-length edges are indexed as points. When the extents overflow
    /// double, one cell holds every edge. Time proportional to the edges plus
    /// the cells their grown boxes cover; `shape` is not kept.
    edge_grid(const polygon& shape, double reach, double slack) {
        const double r = reach + slack;
        area_ = shape.bounds().inflated(r);
        if (!std::isfinite(area_.max_x - area_.min_x) || !std::isfinite(area_.max_y - area_.min_y)) {
            // Extents beyond double's range: one cell holding every edge.
            area_ = box{-std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                        std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
            nx_ = ny_ = 1;
            offsets_ = {0, static_cast<std::uint32_t>(shape.size())};
            edges_.resize(shape.size());
            for (std::size_t e = 0; e < shape.size(); ++e) edges_[e] = static_cast<std::uint32_t>(e);
            return;
        }
        const double w = area_.max_x - area_.min_x, h = area_.max_y - area_.min_y;
        const double n = static_cast<double>(shape.size());
        // Cells about as wide as the reach, but no more than ~8 per edge.
        double cell = std::max({r, std::sqrt(w * h / (8 * n)), std::max(w, h) / 4096});
        if (!(cell > 0) || !std::isfinite(cell)) cell = std::max(w, h) > 0 ? std::max(w, h) : 1;
        nx_ = static_cast<std::size_t>(std::clamp(std::ceil(w / cell), 1.0, 4096.0));
        ny_ = static_cast<std::size_t>(std::clamp(std::ceil(h / cell), 1.0, 4096.0));
        sx_ = w > 0 ? static_cast<double>(nx_) / w : 0;
        sy_ = h > 0 ? static_cast<double>(ny_) / h : 0;
        const double cw = w / static_cast<double>(nx_), ch = h / static_cast<double>(ny_);
        const double half_diagonal = 0.5 * std::hypot(cw, ch);

        // Two passes (count, fill) into one compressed array.
        std::vector<std::uint32_t> count(nx_ * ny_ + 1, 0);
        auto for_each_cell = [&](std::size_t e, auto&& visit) {
            const point<double>& a = shape.vertex(e);
            const point<double>& b = shape.vertex(shape.next(e));
            box eb;
            eb.add(a);
            eb.add(b);
            eb = eb.inflated(r);
            const std::size_t x0 = cell_x(eb.min_x), x1 = cell_x(eb.max_x);
            const std::size_t y0 = cell_y(eb.min_y), y1 = cell_y(eb.max_y);
            for (std::size_t y = y0; y <= y1; ++y)
                for (std::size_t x = x0; x <= x1; ++x) {
                    const point<double> c{area_.min_x + (static_cast<double>(x) + 0.5) * cw,
                                          area_.min_y + (static_cast<double>(y) + 0.5) * ch};
                    // Points of the cell are within half a diagonal of its centre.
                    if (may_be_within(c, a, b, r + half_diagonal * (1 + sqrt_widening) + slack)) visit(y * nx_ + x);
                }
        };
        for (std::size_t e = 0; e < shape.size(); ++e) for_each_cell(e, [&](std::size_t c) { ++count[c + 1]; });
        for (std::size_t c = 0; c < nx_ * ny_; ++c) count[c + 1] += count[c];
        offsets_ = count;
        edges_.resize(offsets_.back());
        for (std::size_t e = 0; e < shape.size(); ++e)
            for_each_cell(e, [&](std::size_t c) { edges_[count[c]++] = static_cast<std::uint32_t>(e); });
    }

    /// The edges that may lie within the reach of p (none when p is outside
    /// the indexed area, which is the polygon's box grown by the reach).
    edge_list query(const point<double>& p) const {
        if (offsets_.empty() || !area_.contains(p)) return {};
        const std::size_t c = cell_y(p.y) * nx_ + cell_x(p.x);
        return {edges_.data() + offsets_[c], edges_.data() + offsets_[c + 1]};
    }

    /// The number of cells (0 for a default grid).
    std::size_t cell_count() const { return nx_ * ny_; }
    /// The number of (cell, edge) entries over all cells: the grid's size.
    std::size_t entry_count() const { return edges_.size(); }

private:
    std::size_t cell_x(double x) const { return cell_index(std::floor((x - area_.min_x) * sx_), nx_); }
    std::size_t cell_y(double y) const { return cell_index(std::floor((y - area_.min_y) * sy_), ny_); }
    static std::size_t cell_index(double f, std::size_t count) {
        if (!(f > 0)) return 0;  // also NaN, from coordinates beyond double's range
        return f < static_cast<double>(count - 1) ? static_cast<std::size_t>(f) : count - 1;
    }

    box area_;
    std::size_t nx_ = 0, ny_ = 0;
    double sx_ = 0, sy_ = 0;
    std::vector<std::uint32_t> offsets_;
    std::vector<std::uint32_t> edges_;
};

}  // namespace influence2d
