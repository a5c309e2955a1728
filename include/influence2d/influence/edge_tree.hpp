// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// A bounding-volume hierarchy over a polygon's edges in its own (fixed)
/// frame: it answers "which edges may come within g of the segment [u, v]"
/// in time that grows with the edges near the segment, not with all of them.
/// A conservative filter in double, never a decision.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/predicates/filters.hpp"

namespace influence2d {

/// A bounding-volume hierarchy of axis-aligned boxes over a polygon's edges,
/// built once in the polygon's own frame (valid for as long as the polygon
/// does not move; for a static polygon, always). Leaves hold up to 4 edges;
/// inner nodes split their edges at the median along the longer side of
/// their edges' midpoints. In double: boxes of input coordinates are exact.
class edge_tree {
public:
    /// An empty tree: every query visits nothing.
    edge_tree() = default;

    /// Builds the tree over the edges of `shape` (O(n log n)); `shape` is not kept.
    explicit edge_tree(const polygon& shape) {
        const std::size_t n = shape.size();
        if (n == 0) return;
        boxes_.resize(n);
        order_.resize(n);
        std::vector<point<double>> mid(n);
        for (std::size_t e = 0; e < n; ++e) {
            boxes_[e].add(shape.vertex(e));
            boxes_[e].add(shape.vertex(shape.next(e)));
            mid[e] = {boxes_[e].min_x / 2 + boxes_[e].max_x / 2, boxes_[e].min_y / 2 + boxes_[e].max_y / 2};
            order_[e] = static_cast<std::uint32_t>(e);
        }
        nodes_.reserve(2 * n / leaf_size + 2);
        nodes_.emplace_back();
        fill(0, 0, static_cast<std::uint32_t>(n), mid);
        // Leaves read their edges' boxes in tree order.
        std::vector<box> sorted(n);
        for (std::size_t k = 0; k < n; ++k) sorted[k] = boxes_[order_[k]];
        boxes_.swap(sorted);
        // Each node's bounding circle: its box's centre and half diagonal,
        // the latter rounded up (upper_sqrt), for the pairwise traversal.
        for (node& k : nodes_) {
            k.center = {k.bounds.min_x / 2 + k.bounds.max_x / 2, k.bounds.min_y / 2 + k.bounds.max_y / 2};
            const long double hx = static_cast<long double>(k.bounds.max_x) - k.center.x;
            const long double hy = static_cast<long double>(k.bounds.max_y) - k.center.y;
            const long double lx = static_cast<long double>(k.center.x) - k.bounds.min_x;
            const long double ly = static_cast<long double>(k.center.y) - k.bounds.min_y;
            const long double wx = std::max(hx, lx), wy = std::max(hy, ly);
            k.radius = upper_sqrt(wx * wx + wy * wy);
        }
    }

    /// Calls visit(e) for each edge e whose box meets the box of [u, v] grown
    /// by `grow` and whose box is not certainly farther than `line_grow` from
    /// the line through u and v (see box_may_be_near_line); inner nodes are pruned
    /// by the same two tests. A superset of the edges within min(grow,
    /// line_grow) of [u, v]. Stops and returns true as soon as visit returns
    /// true; returns false once every such edge was visited. When u or v is
    /// not finite every edge is visited.
    template <class Visit>
    bool query(const point<double>& u, const point<double>& v, double grow, double line_grow, Visit&& visit) const {
        return query_below(0, u, v, grow, line_grow, visit);
    }

    /// Calls visit(e) for each edge e whose box is not certainly off the ray
    /// from p towards +x by g (certainly_off_ray: above or below p by more
    /// than g, or left of it by more than g); inner nodes are pruned by the
    /// same test. Every edge that may add to the ray's crossings for a
    /// point within g of p is visited, in time that grows with the edges
    /// near the ray's line, not with all of them. Stops and returns true as
    /// soon as visit returns true; returns false once every such edge was
    /// visited. A NaN coordinate of p prunes nothing.
    template <class Visit>
    bool query_ray(const point<double>& p, double g, Visit&& visit) const {
        if (nodes_.empty()) return false;
        std::uint32_t stack[max_depth + 2];
        std::size_t top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const node& k = nodes_[stack[--top]];
            if (certainly_off_ray(k.bounds, p, g)) continue;
            if (k.count == 0) {
                stack[top++] = k.first + 1;
                stack[top++] = k.first;
                continue;
            }
            for (std::uint32_t i = k.first; i < k.first + k.count; ++i)
                if (!certainly_off_ray(boxes_[i], p, g) && visit(order_[i])) return true;
        }
        return false;
    }

    /// The rotation of a placing, by the absolute values of its cosine and
    /// sine doubles (the same for a pose and its inverse).
    struct turn_of {
        double abs_c = 1;  ///< |cos|: the absolute value of the cosine double
        double abs_s = 0;  ///< |sin|: the absolute value of the sine double
    };

    /// Calls visit(e, f) for each edge e of this tree (in its own frame) and
    /// edge f of `moving` (a tree of another polygon in that polygon's own
    /// frame, placed into this frame by place(point) -> point<double>, a
    /// rigid motion evaluated in double, turning as `turn` says) that may
    /// come within the distance the grows stand for. Pairs of nodes are
    /// pruned by the moving node's bounding circle, its centre placed in
    /// double, kept farther than its radius + `circle_grow` from the static
    /// node's box, or by the moving node's box turned about that centre
    /// (the box of the turned box, grown by `circle_grow`) missing the
    /// static box on one axis: a node of a long, thin chain of edges (a
    /// border) has a circle far wider than its box; below a moving
    /// leaf each of its edges, its ends posed by ends(f) (a pair of points in
    /// this frame), queries the static subtree as query() does with `grow`
    /// and `line_grow`. `circle_grow` must cover the separation distance and
    /// the rounding of a posed centre and of the pose's scale factor (the
    /// posed circle holds the posed edges up to it). Stops and returns true
    /// as soon as visit does. A centre that is not finite prunes nothing.
    ///
    ///   stack <- (root, root)
    ///   while stack: (s, m) <- pop
    ///       if dist(posed centre of m, box of s) > radius of m + circle_grow: prune
    ///       if m's box turned and grown misses the box of s: prune
    ///       m a leaf: each edge of m queries s's subtree with its posed ends
    ///       else split the node with the larger circle (m when s is a leaf)
    template <class Place, class Ends, class Visit>
    bool query_pairs(const edge_tree& moving, Place&& place, turn_of turn, double circle_grow, double grow,
                     double line_grow, Ends&& ends, Visit&& visit) const {
        if (nodes_.empty() || moving.nodes_.empty()) return false;
        struct pair_of {
            std::uint32_t s, m;
        };
        // Each pop pushes at most two pairs, each one level deeper in one of
        // the trees: the stack holds at most depth(s) + depth(m) + 1 pairs.
        pair_of stack[2 * max_depth + 2];
        std::size_t top = 0;
        stack[top++] = {0, 0};
        while (top > 0) {
            const pair_of p = stack[--top];
            const node& s = nodes_[p.s];
            const node& m = moving.nodes_[p.m];
            const point<double> c = place(m.center);
            const double dx = std::max({s.bounds.min_x - c.x, 0.0, c.x - s.bounds.max_x});
            const double dy = std::max({s.bounds.min_y - c.y, 0.0, c.y - s.bounds.max_y});
            // The moving node's box turned (turned_extents, written out here:
            // through the call g++ 12 made the countries' frames apart take
            // 1% to 2% more instructions), asked first: it needs no root.
            const double hx = (m.bounds.max_x - m.bounds.min_x) * 0.5, hy = (m.bounds.max_y - m.bounds.min_y) * 0.5;
            const double ex = (turn.abs_c * hx + turn.abs_s * hy) * (1 + turned_extent_slack) + circle_grow;
            const double ey = (turn.abs_s * hx + turn.abs_c * hy) * (1 + turned_extent_slack) + circle_grow;
            // (NaN: the comparisons fail and the pair stays.)
            if (dx > ex || dy > ey || filter_length(dx, dy) > m.radius + circle_grow) continue;
            if (m.count != 0) {
                for (std::uint32_t j = m.first; j < m.first + m.count; ++j) {
                    const std::uint32_t f = moving.order_[j];
                    const auto [u, v] = ends(f);
                    if (query_below(p.s, u, v, grow, line_grow, [&](std::uint32_t e) { return visit(e, f); }))
                        return true;
                }
            } else if (s.count == 0 && s.radius > m.radius) {
                stack[top++] = {s.first + 1, p.m};
                stack[top++] = {s.first, p.m};
            } else {
                stack[top++] = {p.s, m.first + 1};
                stack[top++] = {p.s, m.first};
            }
        }
        return false;
    }

    /// The box (in the frame `place` maps into) that holds every edge of this
    /// tree placed by place(point) -> point<double> (a rigid motion in double
    /// turning as `turn` says): the root's box turned about its centre placed
    /// (query_pairs' test of a moving node), grown by `grow`, which must cover
    /// what query_pairs' circle_grow covers (the rounding of the placed centre
    /// and the pose's scale factor). For a long polygon turned little
    /// (a country's border and its islands far apart) it is far narrower than
    /// the box of the placed bounding circle. Empty for an empty tree; NaN
    /// sides for a centre that is not finite.
    template <class Place>
    box placed_box(Place&& place, turn_of turn, double grow) const {
        if (nodes_.empty()) return box{};
        const node& root = nodes_[0];
        const point<double> c = place(root.center);
        const point<double> e = turned_extents(root.bounds, turn, grow);
        return box{c.x - e.x, c.y - e.y, c.x + e.x, c.y + e.y};
    }

    /// The bounding circle of all the edges: the root's (radius 0, centre the
    /// origin, for an empty tree).
    point<double> root_center() const { return nodes_.empty() ? point<double>{} : nodes_[0].center; }
    /// See root_center.
    double root_radius() const { return nodes_.empty() ? 0 : nodes_[0].radius; }

    /// The number of nodes (0 for an empty tree).
    std::size_t node_count() const { return nodes_.size(); }

    /// One node of the tree, read-only, for traversals of one's own (the
    /// separation query's branch and bound, distance/separation.hpp).
    struct node {
        box bounds;               ///< holds the boxes of the node's edges
        point<double> center;     ///< the centre of bounds
        double radius = 0;        ///< bounds every point of bounds from center
        std::uint32_t first = 0;  ///< leaf: first position in the tree order; inner: left child (right is first + 1)
        std::uint32_t count = 0;  ///< leaf: number of edges; inner: 0
    };
    /// Node k (0 is the root; requires k < node_count()).
    const node& node_at(std::uint32_t k) const { return nodes_[k]; }
    /// The edge at `position` in the tree order (a leaf holds the positions
    /// first to first + count - 1).
    std::uint32_t edge_at(std::uint32_t position) const { return order_[position]; }
    /// The box of the edge at `position` in the tree order.
    const box& edge_box_at(std::uint32_t position) const { return boxes_[position]; }
    /// Bytes of the heap blocks held.
    std::size_t heap_bytes() const {
        return nodes_.capacity() * sizeof(node) + boxes_.capacity() * sizeof(box) +
               order_.capacity() * sizeof(std::uint32_t);
    }

private:
    static constexpr std::uint32_t leaf_size = 4;
    /// The relative widening of a turned box's extents: a half side (a
    /// difference and a halving) rounds by u = 2^-53, the two products and
    /// their sum by 3u more; 2^-50 = 8u covers the 4u, and its own product
    /// with room. (The centre's placing and the distance's rounding are
    /// circle_grow's, as for the circles.)
    static constexpr double turned_extent_slack = 0x1p-50;
    /// Median splits over at most 2^32 edges in leaves of up to 4: at most 31
    /// levels below the root; 32 with room.
    static constexpr std::size_t max_depth = 32;

    /// The half sides of box b turned (by `turn`) about its centre, grown by
    /// `grow`: the turned points lie within |c| hx + |s| hy of the turned
    /// centre along x and |s| hx + |c| hy along y (hx, hy b's half sides),
    /// exactly for the pose's doubles c and s; turned_extent_slack covers
    /// the rounding of these extents.
    static point<double> turned_extents(const box& b, turn_of turn, double grow) {
        const double hx = (b.max_x - b.min_x) * 0.5, hy = (b.max_y - b.min_y) * 0.5;
        return {(turn.abs_c * hx + turn.abs_s * hy) * (1 + turned_extent_slack) + grow,
                (turn.abs_s * hx + turn.abs_c * hy) * (1 + turned_extent_slack) + grow};
    }

    static bool meets(const box& a, const box& b) {
        return a.min_x <= b.max_x && b.min_x <= a.max_x && a.min_y <= b.max_y && b.min_y <= a.max_y;
    }

    /// query() on the subtree of node `start`. When an end or the grown box
    /// is not finite, nothing is pruned.
    template <class Visit>
    bool query_below(std::uint32_t start, const point<double>& u, const point<double>& v, double grow, double line_grow,
                     Visit&& visit) const {
        if (nodes_.empty()) return false;
        // Pruning only when the ends and the grow are finite: their sum is
        // finite only then (finite terms whose sum overflows only turn the
        // pruning off). The ends are summed, not the grown box's sides, as
        // min and max may drop a NaN end; a side that overflows to infinity
        // only widens the box.
        const bool prune = std::isfinite(u.x + u.y + v.x + v.y + grow);
        const box q{std::min(u.x, v.x) - grow, std::min(u.y, v.y) - grow, std::max(u.x, v.x) + grow,
                    std::max(u.y, v.y) + grow};
        const bool lines = u.x != v.x || u.y != v.y;
        std::uint32_t stack[max_depth + 2];
        std::size_t top = 0;
        stack[top++] = start;
        while (top > 0) {
            const node& k = nodes_[stack[--top]];
            if (prune && (!meets(k.bounds, q) || (lines && !box_may_be_near_line(k.bounds, u, v, line_grow)))) continue;
            if (k.count == 0) {
                stack[top++] = k.first + 1;
                stack[top++] = k.first;
                continue;
            }
            for (std::uint32_t i = k.first; i < k.first + k.count; ++i)
                if ((!prune || meets(boxes_[i], q)) && visit(order_[i])) return true;
        }
        return false;
    }

    /// Builds the subtree of order_[first, last) into the reserved node `at`.
    /// Median splits keep the depth within log2(n / leaf_size) + 1, well
    /// inside the query's stack for any 32-bit edge count.
    void fill(std::uint32_t at, std::uint32_t first, std::uint32_t last, const std::vector<point<double>>& mid) {
        box bounds, centres;
        for (std::uint32_t i = first; i < last; ++i) {
            const box& b = boxes_[order_[i]];
            bounds.add({b.min_x, b.min_y});
            bounds.add({b.max_x, b.max_y});
            centres.add(mid[order_[i]]);
        }
        nodes_[at].bounds = bounds;
        if (last - first <= leaf_size) {
            nodes_[at].first = first;
            nodes_[at].count = last - first;
            return;
        }
        const bool along_x = centres.max_x - centres.min_x >= centres.max_y - centres.min_y;
        const std::uint32_t half = first + (last - first) / 2;
        std::nth_element(
            order_.begin() + first, order_.begin() + half, order_.begin() + last,
            [&](std::uint32_t a, std::uint32_t b) { return along_x ? mid[a].x < mid[b].x : mid[a].y < mid[b].y; });
        const auto left = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        nodes_.emplace_back();
        fill(left, first, half, mid);
        fill(left + 1, half, last, mid);
        nodes_[at].first = left;
        nodes_[at].count = 0;
    }

    std::vector<node> nodes_;
    std::vector<box> boxes_;            ///< edges' boxes, in tree order
    std::vector<std::uint32_t> order_;  ///< edge indices, in tree order
};

}  // namespace influence2d
