// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Axis-aligned boxes in double coordinates, used only by conservative filters.

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "influence2d/core/point.hpp"

namespace influence2d {

/// A closed axis-aligned box; empty when min > max (a default box is empty:
/// its minima are +infinity, its maxima -infinity). Points on the sides are
/// inside. Evaluated in double: boxes serve filters, never decisions.
struct box {
    double min_x = std::numeric_limits<double>::infinity();   ///< smallest x; +infinity in a default box
    double min_y = std::numeric_limits<double>::infinity();   ///< smallest y; +infinity in a default box
    double max_x = -std::numeric_limits<double>::infinity();  ///< largest x; -infinity in a default box
    double max_y = -std::numeric_limits<double>::infinity();  ///< largest y; -infinity in a default box

    /// Whether the box holds no point (min > max on some axis).
    bool empty() const { return min_x > max_x || min_y > max_y; }

    /// Grows the box to hold p. A NaN coordinate leaves that axis unchanged.
    void add(const point<double>& p) {
        min_x = std::min(min_x, p.x);
        min_y = std::min(min_y, p.y);
        max_x = std::max(max_x, p.x);
        max_y = std::max(max_y, p.y);
    }

    /// Grows the box to hold each point of [first, last): the box that add
    /// on each in turn makes (the minima and maxima of the same values, a
    /// NaN coordinate left out). With SSE2, both coordinates of a point at
    /// once and four points at a time on four pairs of boxes, then joined:
    /// each minimum and maximum waits on its own chain of a quarter of the
    /// points (one chain of all of them waits a comparison's latency, four
    /// cycles, per point).
    void add(const point<double>* first, const point<double>* last) {
#if defined(__SSE2__)
        // (minpd and maxpd give their second operand when either is NaN:
        // the point first, the box second, as add does.)
        const double inf = std::numeric_limits<double>::infinity();
        __m128d lo[4], hi[4];
        for (int k = 0; k < 4; ++k) {
            lo[k] = _mm_set1_pd(inf);
            hi[k] = _mm_set1_pd(-inf);
        }
        for (; last - first >= 4; first += 4)
            for (int k = 0; k < 4; ++k) {
                const __m128d p = _mm_loadu_pd(&first[k].x);
                lo[k] = _mm_min_pd(p, lo[k]);
                hi[k] = _mm_max_pd(p, hi[k]);
            }
        for (; first != last; ++first) {
            const __m128d p = _mm_loadu_pd(&first->x);
            lo[0] = _mm_min_pd(p, lo[0]);
            hi[0] = _mm_max_pd(p, hi[0]);
        }
        const __m128d l = _mm_min_pd(_mm_min_pd(lo[0], lo[1]), _mm_min_pd(lo[2], lo[3]));
        const __m128d h = _mm_max_pd(_mm_max_pd(hi[0], hi[1]), _mm_max_pd(hi[2], hi[3]));
        alignas(16) double out[4];
        _mm_store_pd(out, l);
        _mm_store_pd(out + 2, h);
        min_x = std::min(min_x, out[0]);
        min_y = std::min(min_y, out[1]);
        max_x = std::max(max_x, out[2]);
        max_y = std::max(max_y, out[3]);
#else
        for (; first != last; ++first) add(*first);
#endif
    }

    /// The box grown by `margin` on every side (shrunk when it is negative);
    /// a default box stays empty.
    box inflated(double margin) const { return box{min_x - margin, min_y - margin, max_x + margin, max_y + margin}; }

    /// The centre (NaN for an empty box or an infinite side).
    point<double> centre() const { return {min_x / 2 + max_x / 2, min_y / 2 + max_y / 2}; }

    /// Whether p lies in the closed box (on a side counts); false for NaN.
    bool contains(const point<double>& p) const { return p.x >= min_x && p.x <= max_x && p.y >= min_y && p.y <= max_y; }

    /// Whether b lies within this box (an empty b does).
    bool contains(const box& b) const {
        return b.empty() || (b.min_x >= min_x && b.max_x <= max_x && b.min_y >= min_y && b.max_y <= max_y);
    }
};

/// A closed box made ready to test many points against it: the answers of
/// box::contains (false for NaN), with SSE2 both coordinates of a point
/// compared at once and no branch but the answer's (half the instructions
/// of the four comparisons in turn, where a scan over a polygon's vertices
/// spends most of its time).
class box_membership {
public:
    /// Ready for b.
    explicit box_membership(const box& b)
#if defined(__SSE2__)
        : lo_(_mm_set_pd(b.min_y, b.min_x)),
          hi_(_mm_set_pd(b.max_y, b.max_x))
#else
        : b_(b)
#endif
    {
    }

    /// Whether p lies in the closed box (on a side counts); false for NaN.
    bool contains(const point<double>& p) const {
#if defined(__SSE2__)
        const __m128d v = _mm_loadu_pd(&p.x);  // (x, y)
        return _mm_movemask_pd(_mm_and_pd(_mm_cmpge_pd(v, lo_), _mm_cmple_pd(v, hi_))) == 3;
#else
        return b_.contains(p);
#endif
    }

private:
#if defined(__SSE2__)
    __m128d lo_, hi_;  // (min_x, min_y), (max_x, max_y)
#else
    box b_;
#endif
};

/// The largest magnitude of a box's coordinates: for a polygon's box, the
/// scale its coordinates' rounding errors are relative to.
inline double largest_coordinate(const box& b) {
    return std::max(std::max(std::fabs(b.min_x), std::fabs(b.max_x)), std::max(std::fabs(b.min_y), std::fabs(b.max_y)));
}

/// Whether two closed boxes share a point (false when either is empty or
/// has a NaN side).
inline bool boxes_overlap(const box& l, const box& r) {
    // (All four compared, without a branch for each.)
    return (l.min_x <= r.max_x) & (r.min_x <= l.max_x) & (l.min_y <= r.max_y) & (r.min_y <= l.max_y);
}

}  // namespace influence2d
