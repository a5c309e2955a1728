// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// What a detector answers for one frame, and the options every detector takes.

#include <cstddef>
#include <vector>

#include "influence2d/predicates/extended_area.hpp"

namespace influence2d {

/// An involved pair of features: static edge and moving edge, each numbered in
/// the input order of its polygon's vertices, ring after ring (edge k runs
/// from vertex k to the next vertex of its ring).
struct edge_pair {
    std::size_t static_edge = 0;  ///< the edge of the static polygon A, in A's input numbering
    std::size_t moving_edge = 0;  ///< the edge of the moving polygon B, in B's input numbering
};

/// Whether both edge numbers are equal.
inline bool operator==(const edge_pair& a, const edge_pair& b) {
    return a.static_edge == b.static_edge && a.moving_edge == b.moving_edge;
}
/// Lexicographic order: static edge first, then moving edge (the order of
/// frame_result::pairs).
inline bool operator<(const edge_pair& a, const edge_pair& b) {
    return a.static_edge != b.static_edge ? a.static_edge < b.static_edge : a.moving_edge < b.moving_edge;
}

/// What a detector is asked per frame. Every option changes only the cost of
/// a frame except `distance` and `witness`, which change the question.
struct detector_options {
    /// Separation distance d >= 0 (finite): a frame collides when the closed
    /// regions are at distance <= d. 0 asks for intersection (touching
    /// counts). Needs features::distance when > 0.
    double distance = 0;
    /// Report every (static edge, moving edge) pair at distance <= d. Needs
    /// features::witness.
    bool witness = false;
    /// The shape of the extended areas that select candidate edges; both give
    /// the same answers (the band keeps more candidates).
    extended_area shape = extended_area::capsule;
    /// Reuse candidate edges between frames while the moving centroid stays
    /// within a skin distance of where they were gathered. No effect on the
    /// answers; none on a detector built without features::coherence.
    bool temporal_coherence = true;
};

/// The answer for one frame. `pairs` is filled, sorted and free of repeats,
/// only when witnesses were asked for; a collision by containment alone (no
/// boundary pair within d) has collides == true and no pairs.
struct frame_result {
    bool collides = false;         ///< whether the closed regions are at distance <= d
    std::vector<edge_pair> pairs;  ///< with witnesses: every edge pair at distance <= d
};

}  // namespace influence2d
