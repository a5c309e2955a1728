// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Where the vertices of a turning motion can be over parts of its time:
/// each vertex's box over each part (its arc boxed by its ends and its
/// bulge over the chord, plus the translation), and the vertex-edge pairs
/// whose boxes meet, found through chains of vertices and runs of edges
/// (docs/sweep.md).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/scene/edge_boxes.hpp"

namespace influence2d {

namespace sweep {

/// The relative slack of the swept boxes (swept_parts): their corners
/// computed in double with a few roundings each (a turn's cosine and sine,
/// about 4u, or an ulp each from std::cos and std::sin; times a base
/// rotation, two products and a sum, 3u more; the point turned, 3u more;
/// the translation's share, about 6u; the bulge: a square root and a
/// quotient, or a sine and a square, about 4u), each at most u = 2^-53
/// times the magnitudes involved, below 2^-47 of the radius and the
/// translation; 2^-40 leaves a factor of 128. (The rounding of a turn's
/// angle itself is the frame's absolute slack.)
inline constexpr double arc_box_slack = 0x1p-40;

/// How many consecutive vertices make one chain, and consecutive edges one
/// run, of a boundary's boxes (boundary_groups): the boxes of a chain's
/// vertices over a part are made only where the chain's box over it (its
/// centre's, grown by its reach) meets a run's box. On the turning study's
/// contour 64-gons a free motion's vertices mostly sweep past A's edges far
/// from every one (1.6 of 128 vertices near an edge, per motion, in the
/// rational model), so that most of their boxes need not be made.
inline constexpr std::size_t group_length = 8;

/// What the boxes of every point over the Parts parts of a window of a
/// motion share (swept_parts): the parts' ends (tau, the time of the
/// window's own parametrisation); at each end j the whole turn (cos_j,
/// sin_j) of the point; over each part, the box the translation adds to
/// the place at its first and at its last end, the bulge factor 1 - cos(theta
/// / 2) of its arc of angle theta (theta <= pi / 2), and the most the
/// translation adds to a point's radius (|.|_1); and the absolute slack of
/// every box. For a vertex of A taken into B's frame the turn is the
/// transposed rotation and the point is q - T(tau): turned back at an end,
/// R_j^T q - R_j^T T with T over the part (its ends' box), as q - T lies
/// between q - T_k and q - T_k+1 and each point between two points turned
/// by the same angle lies between their turns.
template <std::size_t Parts>
struct swept_frame {
    std::array<double, Parts + 1> tau;             ///< the parts' ends
    std::array<double, Parts + 1> cos;             ///< the whole turn's cosine at each end
    std::array<double, Parts + 1> sin;             ///< the whole turn's sine at each end
    std::array<std::array<box, 2>, Parts> offset;  ///< per part, at its first and its last end
    std::array<double, Parts> bulge;               ///< per part, 1 - cos(theta / 2) for its turn theta
    std::array<double, Parts> radius_added;        ///< per part, the translation's share of a radius
    double slack = 0;                              ///< every box's absolute slack
};

/// Sets the translation's share of a frame whose turns are set (cos and
/// sin, transposed when `inverse`), from the translation at each end of
/// its parts (`shift`): over each part, the box it adds at the part's first
/// and last end, and the most it adds to a point's radius (swept_frame).
template <std::size_t Parts>
inline void add_translation(swept_frame<Parts>& frame, bool inverse,
                            const std::array<point<double>, Parts + 1>& shift) {
    for (std::size_t k = 0; k < Parts; ++k) {
        frame.radius_added[k] = 0;
        for (std::size_t side = 0; side < 2; ++side) {
            box& b = frame.offset[k][side];
            b = box{};
            if (!inverse) {
                b.add(shift[k]);
                b.add(shift[k + 1]);
                continue;
            }
            const double tc = frame.cos[k + side], ts = frame.sin[k + side];
            for (const point<double>& t : {shift[k], shift[k + 1]}) {
                b.add({-(tc * t.x - ts * t.y), -(ts * t.x + tc * t.y)});
                frame.radius_added[k] = std::max(frame.radius_added[k], std::fabs(t.x) + std::fabs(t.y));
            }
        }
    }
}

/// The boxes of the point p over the parts of a window (frame): over part
/// k, the box of p's places at the part's ends (p turned by the end's whole
/// turn, plus the translation's box there), grown by the arc's bulge over
/// its chord, r (1 - cos(theta / 2)) for r at least the radius of the
/// point turned (|p|_1, plus what the translation adds in B's frame), and
/// by the slack: arc_box_slack r plus the frame's absolute slack. (An arc
/// of angle theta <= pi lies within the sagitta r (1 - cos(theta / 2)) of
/// its chord, and projects onto the chord's line within the chord.)
template <std::size_t Parts>
inline std::array<box, Parts> swept_parts(const swept_frame<Parts>& frame, point<double> p) {
    std::array<point<double>, Parts + 1> turned;
    for (std::size_t j = 0; j <= Parts; ++j)
        turned[j] = {frame.cos[j] * p.x - frame.sin[j] * p.y, frame.sin[j] * p.x + frame.cos[j] * p.y};
    const double radius = std::fabs(p.x) + std::fabs(p.y);
    std::array<box, Parts> out;
    for (std::size_t k = 0; k < Parts; ++k) {
        const box &first = frame.offset[k][0], &second = frame.offset[k][1];
        const point<double>&e0 = turned[k], &e1 = turned[k + 1];
        const double r = radius + frame.radius_added[k];
        const double grow = r * frame.bulge[k] + arc_box_slack * r + frame.slack;
        out[k] = box{std::min(e0.x + first.min_x, e1.x + second.min_x) - grow,
                     std::min(e0.y + first.min_y, e1.y + second.min_y) - grow,
                     std::max(e0.x + first.max_x, e1.x + second.max_x) + grow,
                     std::max(e0.y + first.max_y, e1.y + second.max_y) + grow};
    }
    return out;
}

/// The union of the boxes of the parts that do not end by `known`.
template <std::size_t Parts>
inline box union_after(const swept_frame<Parts>& frame, const std::array<box, Parts>& parts, double known) {
    box out;
    for (std::size_t k = 0; k < Parts; ++k) {
        if (frame.tau[k + 1] <= known) continue;  // (free)
        out.add({parts[k].min_x, parts[k].min_y});
        out.add({parts[k].max_x, parts[k].max_y});
    }
    return out;
}

/// The start (tau) of the first part of the window whose box meets `edge`,
/// the parts that end at or before `known` (free) left out, or none.
template <std::size_t Parts>
inline std::optional<double> first_part_meeting(const swept_frame<Parts>& frame, const std::array<box, Parts>& parts,
                                                const box& edge, double known) {
    for (std::size_t k = 0; k < Parts; ++k)
        if (frame.tau[k + 1] > known && boxes_overlap(parts[k], edge)) return frame.tau[k];
    return std::nullopt;
}

/// A box as an entry of sweep_along_x, numbered k.
inline edge_box sweep_entry(const box& b, std::size_t k) {
    return {b.min_x, b.max_x, b.min_y, b.max_y, static_cast<std::uint32_t>(k)};
}

/// The box of a sweep entry.
inline box box_of(const edge_box& k) { return box{k.min_x, k.min_y, k.max_x, k.max_y}; }

/// Consecutive vertices of a polygon taken together (boundary_groups): a
/// centre and a reach bounding the distance of each of them from it.
struct vertex_chain {
    point<double> centre;  ///< the centre of the vertices' box
    double reach = 0;      ///< at least each vertex's distance from the centre
};

/// A polygon's boundary in groups of group_length (numbering: group g holds
/// the vertices, or edges, g L to g L + L - 1, L = group_length): its edges'
/// boxes, the runs of edges (their boxes' union, sorted by min_x for
/// sweep_along_x, `edge` naming the run) and the chains of vertices. None
/// depends on the motion: made once per query.
struct boundary_groups {
    std::vector<box> edges;            ///< each edge's box
    std::vector<edge_box> runs;        ///< the runs' boxes, sorted by min_x
    std::vector<vertex_chain> chains;  ///< the chains, in order
};

/// The groups of `shape`'s boundary (boundary_groups). A chain's reach is
/// the largest |dx| + |dy| (at least the distance) of its vertices from its
/// centre, rounded up by arc_box_slack (three roundings of 2^-53 each).
inline boundary_groups boundary_groups_of(const polygon& shape) {
    boundary_groups out;
    const std::size_t n = shape.size();
    out.edges.resize(n);
    for (std::size_t e = 0; e < n; ++e) {
        out.edges[e].add(shape.vertex(e));
        out.edges[e].add(shape.vertex(shape.next(e)));
    }
    for (std::size_t first = 0; first < n; first += group_length) {
        const std::size_t end = std::min(n, first + group_length);
        box run, vertices;
        for (std::size_t k = first; k < end; ++k) {
            run.add({out.edges[k].min_x, out.edges[k].min_y});
            run.add({out.edges[k].max_x, out.edges[k].max_y});
            vertices.add(shape.vertex(k));
        }
        out.runs.push_back(sweep_entry(run, first / group_length));
        vertex_chain chain{vertices.centre(), 0};
        for (std::size_t k = first; k < end; ++k) {
            const point<double>& v = shape.vertex(k);
            chain.reach = std::max(chain.reach, std::fabs(v.x - chain.centre.x) + std::fabs(v.y - chain.centre.y));
        }
        chain.reach += chain.reach * arc_box_slack;
        out.chains.push_back(chain);
    }
    std::sort(out.runs.begin(), out.runs.end(), [](const edge_box& l, const edge_box& m) { return l.min_x < m.min_x; });
    return out;
}

/// The mark of a vertex whose boxes are not made yet (for_each_swept_pair).
inline constexpr std::uint32_t unmade = ~std::uint32_t{0};

/// The working storage of for_each_swept_pair, kept by a caller that makes
/// many calls so that each reuses the last one's memory.
template <std::size_t Parts>
struct swept_scratch {
    std::vector<std::array<box, Parts>> chain_parts;  ///< each chain's boxes over the parts
    std::vector<edge_box> chain_order;                ///< the chains' boxes, sorted by min_x
    std::vector<std::uint32_t> slot;                  ///< each vertex's boxes' place, or unmade
    std::vector<std::array<box, Parts>> parts;        ///< the vertices' boxes made
    std::vector<box> vertex_box;                      ///< their unions over the parts
};

/// Calls pair(v, e, parts) for each vertex v of `vertices` (groups `vg`)
/// and edge e of `edges` (groups `eg`) whose boxes over the window (frame;
/// the union of swept_parts of the vertex over the parts not ending by
/// `known`, the edge's own box) meet, `parts` the vertex's swept_parts:
/// whether a part's box meets the edge's is the caller's. Each vertex's
/// boxes are made only where its chain's boxes over the parts (its
/// centre's, grown by its reach: each vertex of the chain turns by the same
/// angle about the same origin as the centre, keeping its distance from
/// it) meet a run's box in one part; the chains and runs whose boxes over
/// the window overlap are found by sort and sweep along x (sweep_along_x).
/// `scratch` is the calls' working storage.
template <std::size_t Parts, class Pair>
void for_each_swept_pair(const swept_frame<Parts>& frame, const polygon& vertices, const boundary_groups& vg,
                         const polygon& edges, const boundary_groups& eg, double known, Pair&& pair,
                         swept_scratch<Parts>& scratch) {
    auto &chain_parts = scratch.chain_parts, &parts = scratch.parts;
    auto& chain_order = scratch.chain_order;
    auto& slot = scratch.slot;
    auto& vertex_box = scratch.vertex_box;
    chain_parts.resize(vg.chains.size());
    chain_order.resize(vg.chains.size());
    for (std::size_t c = 0; c < vg.chains.size(); ++c) {
        chain_parts[c] = swept_parts(frame, vg.chains[c].centre);
        for (box& part : chain_parts[c]) part = part.inflated(vg.chains[c].reach);
        chain_order[c] = sweep_entry(union_after(frame, chain_parts[c], known), c);
    }
    std::sort(chain_order.begin(), chain_order.end(),
              [](const edge_box& l, const edge_box& m) { return l.min_x < m.min_x; });
    // The vertices' boxes, made when first asked (slot[v] into `parts` and
    // `vertex_box`; most vertices need none).
    slot.assign(vertices.size(), unmade);
    parts.clear();
    vertex_box.clear();
    parts.reserve(vertices.size());
    vertex_box.reserve(vertices.size());
    sweep_along_x(
        chain_order, 0, chain_order.size(), eg.runs, 0, eg.runs.size(),
        [](const edge_box& k) -> const edge_box& { return k; },
        [&](std::size_t i, std::size_t j) {
            const std::size_t chain = chain_order[i].edge, run = eg.runs[j].edge;
            const box run_box = box_of(eg.runs[j]);
            if (!first_part_meeting(frame, chain_parts[chain], run_box, known)) return false;
            const std::size_t v_end = std::min(vertices.size(), (chain + 1) * group_length),
                              e_end = std::min(edges.size(), (run + 1) * group_length);
            for (std::size_t v = chain * group_length; v < v_end; ++v) {
                if (slot[v] == unmade) {
                    slot[v] = static_cast<std::uint32_t>(parts.size());
                    parts.push_back(swept_parts(frame, vertices.vertex(v)));
                    vertex_box.push_back(union_after(frame, parts.back(), known));
                }
                const box& whole = vertex_box[slot[v]];
                if (!boxes_overlap(whole, run_box)) continue;
                for (std::size_t e = run * group_length; e < e_end; ++e)
                    if (boxes_overlap(whole, eg.edges[e])) pair(v, e, parts[slot[v]]);
            }
            return false;
        });
}

}  // namespace sweep

}  // namespace influence2d
