// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which boxes of a set meet a given box: a packed tree over boxes kept in
/// the order of their centres along a Hilbert curve, rebuilt bottom-up in
/// linear time when the boxes move (docs/world.md, "Broad phase").

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/world/hilbert_curve.hpp"

namespace influence2d {

/// A set of boxes, each with an id, answering which of them meet a query box.
///
///   rebuild(boxes):
///     key <- each box's centre's position along a Hilbert curve over the
///            centres' box (16 bits per axis)
///     sort the entries by key: insertion sort while the entries moved
///       little since the last rebuild (coherent scenes: linear), else a
///       radix sort (linear too)
///     leaves <- runs of `fan_out` consecutive entries; each level above
///       groups `fan_out` consecutive nodes of the level below, bottom-up,
///       each node's box the union of its children's
///   refit(id, b): the entry's box replaced, the nodes above it made anew
///     from their children, leaf to root
///   refit_all(ids): the entries' boxes replaced, every node made anew from
///     its children, level by level
///   query(q): descend from the root into the nodes whose box meets q
///
/// Consecutive entries along the curve are near each other, so the nodes'
/// boxes stay small; a query visits O(log n + k) nodes for k boxes that meet
/// q when the boxes are of similar sizes (a box much larger than its
/// neighbours widens the nodes above it). No box is ever missed: a node's
/// box holds its children's.
class box_tree {
public:
    /// The boxes and their ids; `boxes[k]` has id `ids[k]`. Keeps the order of
    /// the last rebuild as the start of this one. Boxes that are empty are
    /// kept and never met. Every buffer is the last rebuild's, refilled: a
    /// tree rebuilt step after step allocates only when it grows.
    void rebuild(const std::vector<box>& boxes, const std::vector<std::uint32_t>& ids) {
        const std::size_t n = boxes.size();
        box centres;
        for (const box& b : boxes) centres.add(b.centre());
        const double sx = scale_of(centres.min_x, centres.max_x), sy = scale_of(centres.min_y, centres.max_y);
        // Entries carried over from the last rebuild first (in their order),
        // then the new ones: a scene that changed little stays nearly sorted.
        std::vector<std::uint32_t>& where = spare_.where;
        where.assign(n_slots(ids), absent);
        for (std::size_t k = 0; k < n; ++k) where[ids[k]] = static_cast<std::uint32_t>(k);
        std::vector<entry>& next = spare_.entries;
        next.clear();
        next.reserve(n);
        for (const entry& e : entries_)
            if (e.id < where.size() && where[e.id] != absent) {
                next.push_back({boxes[where[e.id]], e.id, 0});
                where[e.id] = absent;
            }
        for (std::size_t k = 0; k < n; ++k)
            if (where[ids[k]] != absent) next.push_back({boxes[k], ids[k], 0});
        for (entry& e : next) {
            const point<double> c = e.bounds.centre();
            e.key = hilbert_position(quantized(c.x, centres.min_x, sx), quantized(c.y, centres.min_y, sy));
        }
        sort_by_key(next, spare_);
        entries_.swap(next);  // (the old entries' buffer kept for the next rebuild)
        slot_.assign(where.size(), absent);
        for (std::size_t k = 0; k < entries_.size(); ++k) slot_[entries_[k].id] = static_cast<std::uint32_t>(k);
        build_levels();
    }

    /// Whether the box of `id` is in the set (given at the last rebuild).
    bool holds(std::uint32_t id) const { return id < slot_.size() && slot_[id] != absent; }

    /// Replaces the box of `id` (holds(id)) by b, an empty box to drop it,
    /// and makes the nodes above it anew from their children: O(fan_out *
    /// log n). The order stays the last rebuild's, so the nodes widen as
    /// refitted boxes drift away from their neighbours along the curve.
    void refit(std::uint32_t id, const box& b) {
        std::size_t at = slot_[id];
        entries_[at].bounds = b;
        for (std::size_t level = 0; level < levels_.size(); ++level) {
            at /= fan_out;
            const auto [first, last] = children(level, at);
            box merged;
            for (std::size_t c = first; c < last; ++c)
                grow(merged, level == 0 ? entries_[c].bounds : levels_[level - 1][c]);
            levels_[level][at] = merged;
        }
    }

    /// Replaces the boxes of many ids at once (box_of(id) for each id of
    /// `ids`, each held; an empty box drops it) and makes every node anew
    /// from its children, level by level: O(n) in sequence for n boxes,
    /// where k calls of refit(id, b) make k * fan_out * log n unions at
    /// places scattered over the levels. The same nodes as those calls.
    template <class BoxOf>
    void refit_all(const std::vector<std::uint32_t>& ids, BoxOf&& box_of) {
        for (std::uint32_t id : ids) entries_[slot_[id]].bounds = box_of(id);
        build_levels();
    }

    /// Calls found(id) for every box that meets q (closed boxes: touching
    /// counts), in no particular order.
    template <class Found>
    void query(const box& q, Found&& found) const {
        if (levels_.empty()) return;
        visit(levels_.size() - 1, 0, q, found);
    }

    /// Calls found(i, j) once for every pair of distinct boxes of the set that
    /// meet, by their ids, in no particular order: the two trees' nodes
    /// descended together, a pair of nodes whose boxes are apart skipped
    /// whole. O(n + k) node pairs for boxes of similar sizes, k pairs found.
    template <class Found>
    void self_join(Found&& found) const {
        if (!levels_.empty()) join_within(levels_.size() - 1, 0, found);
    }

    /// Calls found(i, j) once for every box i of this set and box j of
    /// `other` that meet, by their ids, in no particular order.
    template <class Found>
    void join(const box_tree& other, Found&& found) const {
        if (!levels_.empty() && !other.levels_.empty())
            join_nodes(*this, levels_.size() - 1, 0, other, other.levels_.size() - 1, 0, found);
    }

    /// A part of a join: the pairs of boxes under one node of this tree
    /// (`within`), or the pairs of a box under a node of this tree and a box
    /// under a node of the other (a node of this tree again for a self
    /// join). Nodes by level (0: the leaves) and index.
    struct join_part {
        std::size_t la = 0;   ///< this tree's node: level
        std::size_t na = 0;   ///< this tree's node: index
        std::size_t lb = 0;   ///< the other node: level (unless within)
        std::size_t nb = 0;   ///< the other node: index (unless within)
        bool within = false;  ///< the pairs under (la, na) alone
    };

    /// self_join cut into parts that find each of its pairs once, for
    /// threads to share: the pairs under a node are those under each child
    /// and those between two children whose boxes meet; parts of the first
    /// kind are cut so, a level at a time, until there are at least `wanted`
    /// parts or they reach the leaves.
    std::vector<join_part> self_join_parts(std::size_t wanted) const {
        std::vector<join_part> parts;
        if (levels_.empty()) return parts;
        parts.push_back({levels_.size() - 1, 0, 0, 0, true});
        for (std::size_t level = levels_.size() - 1; level > 0 && parts.size() < wanted; --level) {
            std::vector<join_part> next;
            for (const join_part& p : parts) {
                if (!p.within) {
                    next.push_back(p);
                    continue;
                }
                const auto [first, last] = children(level, p.na);
                for (std::size_t c = first; c < last; ++c) {
                    next.push_back({level - 1, c, 0, 0, true});
                    for (std::size_t d = c + 1; d < last; ++d)
                        if (boxes_overlap(levels_[level - 1][c], levels_[level - 1][d]))
                            next.push_back({level - 1, c, level - 1, d, false});
                }
            }
            parts = std::move(next);
        }
        return parts;
    }

    /// join(other) cut into parts that find each of its pairs once: pairs
    /// of nodes whose boxes meet, the node of the higher level replaced by
    /// its children, a level at a time, until there are at least `wanted`
    /// parts or both nodes are leaves.
    std::vector<join_part> join_parts(const box_tree& other, std::size_t wanted) const {
        std::vector<join_part> parts;
        if (levels_.empty() || other.levels_.empty()) return parts;
        const std::size_t la = levels_.size() - 1, lb = other.levels_.size() - 1;
        if (boxes_overlap(levels_[la][0], other.levels_[lb][0])) parts.push_back({la, 0, lb, 0, false});
        bool split = true;
        while (split && !parts.empty() && parts.size() < wanted) {
            split = false;
            std::vector<join_part> next;
            for (const join_part& p : parts) {
                if (p.la == 0 && p.lb == 0) {
                    next.push_back(p);
                    continue;
                }
                split = true;
                if (p.la >= p.lb) {
                    const auto [first, last] = children(p.la, p.na);
                    for (std::size_t c = first; c < last; ++c)
                        if (boxes_overlap(levels_[p.la - 1][c], other.levels_[p.lb][p.nb]))
                            next.push_back({p.la - 1, c, p.lb, p.nb, false});
                } else {
                    const auto [first, last] = other.children(p.lb, p.nb);
                    for (std::size_t c = first; c < last; ++c)
                        if (boxes_overlap(levels_[p.la][p.na], other.levels_[p.lb - 1][c]))
                            next.push_back({p.la, p.na, p.lb - 1, c, false});
                }
            }
            parts = std::move(next);
        }
        return parts;
    }

    /// Calls found(i, j) for every pair of part p, by ids: p from
    /// self_join_parts (other: this tree) or from join_parts(other).
    template <class Found>
    void join_part_pairs(const join_part& p, const box_tree& other, Found&& found) const {
        if (p.within)
            join_within(p.la, p.na, found);
        else
            join_nodes(*this, p.la, p.na, other, p.lb, p.nb, found);
    }

    /// The number of boxes.
    std::size_t size() const { return entries_.size(); }

private:
    static constexpr std::size_t fan_out = 8;
    static constexpr std::uint32_t absent = 0xffffffffu;

    struct entry {
        box bounds;
        std::uint32_t id;
        std::uint32_t key;
    };

    static std::size_t n_slots(const std::vector<std::uint32_t>& ids) {
        std::uint32_t top = 0;
        for (std::uint32_t id : ids) top = std::max(top, id + 1);
        return top;
    }
    // The width of one of 2^16 cells along an axis spanning [lo, hi]
    // (1 for a point or an axis that is not finite).
    static double scale_of(double lo, double hi) {
        const double w = hi / 65536 - lo / 65536;
        return std::isfinite(w) && w > 0 ? w : 1;
    }
    static std::uint32_t quantized(double v, double lo, double cell) {
        const double q = (v / cell - lo / cell);
        if (!(q > 0)) return 0;  // (NaN too)
        return q >= 65535 ? 65535u : static_cast<std::uint32_t>(q);
    }
    // The buffers a rebuild fills, kept from one rebuild to the next.
    struct buffers {
        std::vector<std::uint32_t> where;     // each id's place among the boxes given
        std::vector<entry> entries;           // the entries in the making (the last rebuild's, emptied)
        std::vector<std::uint64_t> keys, by;  // the radix sort's (key, position) pairs and their next order
        std::vector<entry> sorted;            // the entries in the radix sort's order
    };

    // Insertion sort while it stays cheap (at most 8 moves per entry on
    // average: the entries were nearly in order), else a radix sort. A
    // first pass counts the descents: entries out of order in more than an
    // eighth of the places go to the radix sort at once.
    static void sort_by_key(std::vector<entry>& v, buffers& spare) {
        std::size_t descents = 0;
        for (std::size_t k = 1; k < v.size(); ++k) descents += v[k - 1].key > v[k].key ? 1 : 0;
        if (descents * 8 > v.size()) {
            radix_sort_by_key(v, spare);
            return;
        }
        const std::size_t budget = 8 * v.size() + 64;
        std::size_t moves = 0;
        for (std::size_t k = 1; k < v.size(); ++k) {
            entry e = v[k];
            std::size_t j = k;
            while (j > 0 && v[j - 1].key > e.key) {
                v[j] = v[j - 1];
                --j;
                if (++moves > budget) {
                    v[j] = e;
                    radix_sort_by_key(v, spare);
                    return;
                }
            }
            v[j] = e;
        }
    }

    // A stable sort by key in linear time: the (key, position) pairs sorted
    // by four passes of counting on one byte each, least significant
    // first, then the entries moved once into their order.
    static void radix_sort_by_key(std::vector<entry>& v, buffers& spare) {
        std::vector<std::uint64_t>&a = spare.keys, &b = spare.by;
        a.resize(v.size());
        b.resize(v.size());
        for (std::size_t k = 0; k < v.size(); ++k) a[k] = std::uint64_t{v[k].key} << 32 | k;
        for (int shift = 32; shift < 64; shift += 8) {
            std::size_t start[257] = {};
            for (std::uint64_t x : a) ++start[((x >> shift) & 0xff) + 1];
            for (std::size_t d = 0; d < 256; ++d) start[d + 1] += start[d];
            for (std::uint64_t x : a) b[start[(x >> shift) & 0xff]++] = x;
            a.swap(b);
        }
        std::vector<entry>& sorted = spare.sorted;
        sorted.resize(v.size());
        for (std::size_t k = 0; k < v.size(); ++k) sorted[k] = v[a[k] & 0xffffffffu];
        v.swap(sorted);
    }

    // Level `at` of the nodes emptied for a rebuild, its buffer the last
    // rebuild's.
    std::vector<box>& level_buffer(std::size_t at) {
        if (levels_.size() <= at) levels_.resize(at + 1);
        levels_[at].clear();
        return levels_[at];
    }
    void build_levels() {
        std::size_t height = 0;  // the levels made
        if (!entries_.empty()) {
            std::vector<box>& leaves = level_buffer(height++);
            leaves.reserve((entries_.size() + fan_out - 1) / fan_out);
            for (std::size_t k = 0; k < entries_.size(); k += fan_out) {
                box b;
                for (std::size_t j = k; j < std::min(k + fan_out, entries_.size()); ++j) grow(b, entries_[j].bounds);
                leaves.push_back(b);
            }
            while (levels_[height - 1].size() > 1) {
                std::vector<box>& above = level_buffer(height);  // (before `below`: it may move the levels)
                const std::vector<box>& below = levels_[height - 1];
                above.reserve((below.size() + fan_out - 1) / fan_out);
                for (std::size_t k = 0; k < below.size(); k += fan_out) {
                    box b;
                    for (std::size_t j = k; j < std::min(k + fan_out, below.size()); ++j) grow(b, below[j]);
                    above.push_back(b);
                }
                ++height;
            }
        }
        levels_.resize(height);
    }
    static void grow(box& b, const box& c) {
        if (c.empty()) return;
        b.min_x = std::min(b.min_x, c.min_x);
        b.min_y = std::min(b.min_y, c.min_y);
        b.max_x = std::max(b.max_x, c.max_x);
        b.max_y = std::max(b.max_y, c.max_y);
    }

    // Node `node` of level `level` (level 0: the leaves, whose children are
    // entries).
    template <class Found>
    void visit(std::size_t level, std::size_t node, const box& q, Found& found) const {
        if (!boxes_overlap(levels_[level][node], q)) return;
        const std::size_t first = node * fan_out;
        if (level == 0) {
            for (std::size_t j = first; j < std::min(first + fan_out, entries_.size()); ++j)
                if (boxes_overlap(entries_[j].bounds, q)) found(entries_[j].id);
            return;
        }
        for (std::size_t j = first; j < std::min(first + fan_out, levels_[level - 1].size()); ++j)
            visit(level - 1, j, q, found);
    }

    // The children of node `node` of level `level` > 0 (nodes of the level
    // below), or the entries of a leaf (level 0): [first, last).
    std::pair<std::size_t, std::size_t> children(std::size_t level, std::size_t node) const {
        const std::size_t first = node * fan_out;
        const std::size_t count = level == 0 ? entries_.size() : levels_[level - 1].size();
        return {first, std::min(first + fan_out, count)};
    }

    // The pairs of boxes under one node.
    template <class Found>
    void join_within(std::size_t level, std::size_t node, Found& found) const {
        const auto [first, last] = children(level, node);
        if (level == 0) {
            for (std::size_t i = first; i < last; ++i)
                for (std::size_t j = i + 1; j < last; ++j)
                    if (boxes_overlap(entries_[i].bounds, entries_[j].bounds)) found(entries_[i].id, entries_[j].id);
            return;
        }
        for (std::size_t c = first; c < last; ++c) {
            join_within(level - 1, c, found);
            for (std::size_t d = c + 1; d < last; ++d) join_nodes(*this, level - 1, c, *this, level - 1, d, found);
        }
    }

    // The pairs of a box under node (la, na) of a and a box under node
    // (lb, nb) of b: the node of the higher level descended first.
    template <class Found>
    static void join_nodes(const box_tree& a, std::size_t la, std::size_t na, const box_tree& b, std::size_t lb,
                           std::size_t nb, Found& found) {
        if (!boxes_overlap(a.levels_[la][na], b.levels_[lb][nb])) return;
        if (la == 0 && lb == 0) {
            const auto [ai, aj] = a.children(0, na);
            const auto [bi, bj] = b.children(0, nb);
            // B's entries that meet A's leaf's box listed first, without a
            // branch each, then A's entries that meet B's leaf's box tested
            // against them alone: sibling leaves of a crowded scene overlap
            // in a corner, and most of their 64 entry pairs lie outside it.
            std::uint32_t near[fan_out];
            std::size_t count = 0;
            for (std::size_t j = bi; j < bj; ++j) {
                near[count] = static_cast<std::uint32_t>(j);
                count += boxes_overlap(b.entries_[j].bounds, a.levels_[0][na]) ? 1 : 0;
            }
            for (std::size_t i = ai; i < aj && count > 0; ++i) {
                if (!boxes_overlap(a.entries_[i].bounds, b.levels_[0][nb])) continue;
                for (std::size_t k = 0; k < count; ++k)
                    if (boxes_overlap(a.entries_[i].bounds, b.entries_[near[k]].bounds))
                        found(a.entries_[i].id, b.entries_[near[k]].id);
            }
            return;
        }
        if (la >= lb && la > 0) {
            const auto [first, last] = a.children(la, na);
            for (std::size_t c = first; c < last; ++c) join_nodes(a, la - 1, c, b, lb, nb, found);
        } else {
            const auto [first, last] = b.children(lb, nb);
            for (std::size_t c = first; c < last; ++c) join_nodes(a, la, na, b, lb - 1, c, found);
        }
    }

    std::vector<entry> entries_;
    std::vector<std::uint32_t> slot_;       // slot_[id]: the entry of id, or absent
    std::vector<std::vector<box>> levels_;  // levels_[0]: one box per leaf of fan_out entries
    buffers spare_;                         // the rebuilds' buffers
};

}  // namespace influence2d
