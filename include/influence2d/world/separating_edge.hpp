// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which edge of one body's convex hull keeps another body out: the witness
/// of a pair of bodies apart, kept from step to step as the witness of a
/// contact is (docs/world.md, "Narrow phase and coherence").

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "influence2d/core/point.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/predicates/filters.hpp"

namespace influence2d {

/// A body of a pair, for the separating edge: the corners of its
/// polygon's convex hull (the vertices hull_vertices names, in its order:
/// counter-clockwise), its pose, its scale (the polygon's largest
/// coordinate plus |tx| + |ty|) and a point of it to aim from (the centre of
/// its polygon's box, posed in double).
struct hull_view {
    const point<double>* corners;  ///< the hull's corners, unposed: corners[0, count)
    std::uint32_t count;           ///< how many
    rotation_pose pose;            ///< where it stands
    double scale;                  ///< as the world's bodies'
    point<double> centre;          ///< where the body is aimed from, posed
};

/// An edge of one body's convex hull whose line leaves every corner of the
/// other body's hull strictly on its outer side, or none.
struct separating_edge {
    std::uint8_t side = 0;   ///< 0: none; 1: an edge of the first body's hull; 2: of the second body's
    std::uint32_t edge = 0;  ///< the hull edge from corner `edge` to the next one
    /// Whether there is one.
    explicit operator bool() const { return side != 0; }
};

/// Whether hull edge k of `inner` (corner k to corner k + 1) certainly
/// leaves every corner of `outer`'s hull strictly right of its directed
/// line, at the bodies' exact poses: the corners posed in double, each
/// within e of its exact place on each coordinate, and every one of
/// outer's certainly right of the line (certain_side_within). Then the two
/// bodies' closed regions are apart: `inner`'s region lies in its hull,
/// left of the line or on it, and `outer`'s in its hull, strictly right of
/// it (the posed corners are the posed bodies' hulls: hull_vertices). False
/// also when the doubles cannot tell: the caller then asks the one-shot
/// test, whose answer is exact. The same answer in every number type but
/// for e.
inline bool hull_edge_separates(const hull_view& inner, std::uint32_t k, const hull_view& outer, double e) {
    const point<double>* h = inner.corners;
    const point<double> p = inner.pose.apply<double>(h[k]),
                        q = inner.pose.apply<double>(h[k + 1 == inner.count ? 0 : k + 1]);
    for (std::uint32_t j = 0; j < outer.count; ++j)
        if (certain_side_within(p, q, outer.pose.apply<double>(outer.corners[j]), e) != -1) return false;
    return true;
}

/// Whether the separating edge s (not none) still keeps bodies a and b
/// apart at their present poses (hull_edge_separates, with NT's placing
/// margin for the two bodies: placing_margin; no polygon placed).
template <class NT>
bool separation_holds(const separating_edge& s, const hull_view& a, const hull_view& b) {
    const double e = placing_margin<NT>(a.scale + b.scale);
    return s.side == 1 ? hull_edge_separates(a, s.edge, b, e) : hull_edge_separates(b, s.edge, a, e);
}

/// A separating edge of bodies a and b at their present poses, or none:
///
///   for (inner, outer) in (a, b), (b, a):
///     k <- the hull edge of inner whose outward normal points most nearly
///          from inner's centre to outer's (inner's corners in double)
///     edge k of inner certainly separates (separation_holds): edge k
///   none
///
/// One edge per side is tried: bodies apart whose hulls overlap (one in
/// another's hollow, teeth between teeth) have none, and pay two passes
/// over their corners to learn it; so do bodies that meet.
template <class NT>
separating_edge seek_separating_edge(const hull_view& a, const hull_view& b) {
    for (std::uint8_t side = 1; side <= 2; ++side) {
        const hull_view &inner = side == 1 ? a : b, &outer = side == 1 ? b : a;
        const point<double>* h = inner.corners;
        const std::uint32_t n = inner.count;
        if (n < 2) continue;
        const point<double> dir{outer.centre.x - inner.centre.x, outer.centre.y - inner.centre.y};
        // The cosine's sign times its square, up to |dir|^2 (no root taken).
        std::uint32_t best = 0;
        double best_cos = -std::numeric_limits<double>::infinity();
        point<double> q = inner.pose.apply<double>(h[0]);
        for (std::uint32_t k = 0; k < n; ++k) {
            const point<double> p = q;
            q = inner.pose.apply<double>(h[k + 1 == n ? 0 : k + 1]);
            // The outward normal of a counter-clockwise hull edge p -> q.
            const double nx = q.y - p.y, ny = p.x - q.x, along = nx * dir.x + ny * dir.y;
            const double c = along * std::fabs(along) / (nx * nx + ny * ny);
            if (c > best_cos) {
                best_cos = c;
                best = k;
            }
        }
        const separating_edge s{side, best};
        if (separation_holds<NT>(s, a, b)) return s;
    }
    return {};
}

}  // namespace influence2d
