#pragma once
// Axis-aligned boxes in double coordinates, used only by conservative filters.

#include <algorithm>
#include <limits>

#include "influence2d/core/point.hpp"

namespace influence2d {

/// A closed axis-aligned box; empty when min > max.
struct box {
    double min_x = std::numeric_limits<double>::infinity();
    double min_y = std::numeric_limits<double>::infinity();
    double max_x = -std::numeric_limits<double>::infinity();
    double max_y = -std::numeric_limits<double>::infinity();

    bool empty() const { return min_x > max_x || min_y > max_y; }

    void add(const point<double>& p) {
        min_x = std::min(min_x, p.x);
        min_y = std::min(min_y, p.y);
        max_x = std::max(max_x, p.x);
        max_y = std::max(max_y, p.y);
    }

    /// The box grown by `margin` on every side.
    box inflated(double margin) const {
        return box{min_x - margin, min_y - margin, max_x + margin, max_y + margin};
    }

    bool contains(const point<double>& p) const {
        return p.x >= min_x && p.x <= max_x && p.y >= min_y && p.y <= max_y;
    }

    /// Whether b lies within this box (an empty b does).
    bool contains(const box& b) const {
        return b.empty() || (b.min_x >= min_x && b.max_x <= max_x && b.min_y >= min_y && b.max_y <= max_y);
    }
};

}  // namespace influence2d
