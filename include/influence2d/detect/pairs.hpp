// SPDX-License-Identifier: BSL-1.0
#pragma once
// Pair bookkeeping shared by the detectors.

#include <algorithm>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/detect/result.hpp"

namespace influence2d {

/// Collects (static edge, moving edge) pairs in stored numbering and hands
/// them out in input numbering, sorted and without repeats.
class pair_collector {
public:
    /// Forgets every pair (a new frame).
    void clear() { pairs_.clear(); }
    /// Adds the pair of A's stored edge i and B's stored edge j.
    void add(std::size_t i, std::size_t j) { pairs_.push_back({i, j}); }
    /// Whether no pair was added since the last clear().
    bool empty() const { return pairs_.empty(); }
    /// Bytes of the heap block held.
    std::size_t heap_bytes() const { return pairs_.capacity() * sizeof(edge_pair); }

    /// The pairs in A's and B's input numbering, sorted, without repeats.
    std::vector<edge_pair> in_input_numbering(const polygon& a, const polygon& b) const {
        std::vector<edge_pair> out;
        in_input_numbering(a, b, out);
        return out;
    }
    /// The same pairs written into `out` (cleared first; its capacity kept).
    void in_input_numbering(const polygon& a, const polygon& b, std::vector<edge_pair>& out) const {
        out.clear();
        out.reserve(pairs_.size());
        for (const auto& p : pairs_) out.push_back({a.source_edge(p.static_edge), b.source_edge(p.moving_edge)});
        // (A search that lists the pairs in order, as every_pair does for
        // polygons stored in their input order, needs neither pass.)
        if (std::adjacent_find(out.begin(), out.end(),
                               [](const edge_pair& x, const edge_pair& y) { return !(x < y); }) == out.end())
            return;
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

private:
    std::vector<edge_pair> pairs_;
};

}  // namespace influence2d
