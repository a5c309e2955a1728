#pragma once
// What a detector answers for one frame, and the options every detector takes.

#include <cstddef>
#include <vector>

namespace influence2d {

/// An involved pair of features: static edge and moving edge, each numbered in
/// the input order of its polygon's vertices, ring after ring.
struct edge_pair {
    std::size_t static_edge = 0;
    std::size_t moving_edge = 0;
};

inline bool operator==(const edge_pair& a, const edge_pair& b) {
    return a.static_edge == b.static_edge && a.moving_edge == b.moving_edge;
}
inline bool operator<(const edge_pair& a, const edge_pair& b) {
    return a.static_edge != b.static_edge ? a.static_edge < b.static_edge
                                          : a.moving_edge < b.moving_edge;
}

/// The shape used for the extended influence area of an edge (method.md 5).
enum class extended_area {
    capsule,  ///< points within n of the edge segment
    band      ///< the paper's band between parallels at distance n, axis-parallel caps
};

struct detector_options {
    /// Separation distance d >= 0: a frame collides when the closed regions
    /// are at distance <= d. 0 asks for intersection (touching counts).
    double distance = 0;
    /// Report every (static edge, moving edge) pair at distance <= d.
    bool witness = false;
    extended_area shape = extended_area::capsule;
    /// Reuse candidate edges between frames while the moving centroid stays
    /// within a skin distance of where they were gathered.
    bool temporal_coherence = true;
};

/// The answer for one frame. `pairs` is filled, sorted and free of repeats,
/// only when witnesses were asked for; a collision by containment alone (no
/// boundary pair within d) has collides == true and no pairs.
struct frame_result {
    bool collides = false;
    std::vector<edge_pair> pairs;
};

}  // namespace influence2d
