// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Feito's inclusion test on the signed triangle covering (docs/method.md section 2).

#include <algorithm>
#include <cstddef>
#include <vector>

#include "influence2d/assert.hpp"
#include "influence2d/core/box.hpp"
#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/covering/covering.hpp"
#include "influence2d/predicates/filters.hpp"
#include "influence2d/predicates/orientation.hpp"

namespace influence2d {

/// Where a point lies with respect to a closed polygonal region.
enum class location {
    outside,   ///< not in the region
    boundary,  ///< on an edge (a vertex, a zero-length edge, a spike included)
    inside     ///< off every edge, with a non-zero winding number
};

/// Feito's sum over the covering triangles from origin O, in doubled units:
///   for each edge (a, b) with sigma = orientation(O, a, b) != 0 and P in the
///   closed triangle (O, a, b):
///     P on the edge [a, b]          -> P is on the boundary: stop;
///     P on a side O-a or O-b        -> add sigma     (half a triangle);
///     P strictly inside             -> add 2 * sigma;
/// The total is twice the winding number of the rings around P (each half
/// count is the mean of the counts on the two sides of a shared side), and P is
/// inside when it is not zero. Precondition: P != O.
template <class NT>
location feito_locate(const polygon& shape, const std::vector<point<NT>>& v, const point<NT>& o, const point<NT>& p) {
    INFLUENCE2D_ASSERT(v.size() == shape.size(), "the vertices in NT are not the polygon's");
    long long doubled = 0;
    for (std::size_t i = 0; i < shape.size(); ++i) {
        const point<NT>& a = v[i];
        const point<NT>& b = v[shape.next(i)];
        const int pab = orientation(p, a, b);
        if (pab == 0 && within_collinear_segment(p, a, b)) return location::boundary;
        const int sigma = orientation(o, a, b);
        if (sigma == 0 || pab * sigma < 0) continue;
        const int beta = orientation(o, p, b) * sigma;
        if (beta < 0) continue;
        const int gamma = orientation(o, a, p) * sigma;
        if (gamma < 0) continue;
        doubled += (beta == 0 || gamma == 0) ? sigma : 2 * sigma;
    }
    return doubled != 0 ? location::inside : location::outside;
}

/// edge_crossing's answer when P lies on the edge.
inline constexpr int crossing_on_edge = 2;

/// What the edge (a, b) adds to the winding number of the closed ray from
/// P towards +x (Sunday's form of the crossing count), exactly when NT's
/// comparisons and orientations are: +1 or -1 for an edge the ray crosses
/// upward or downward, 0 for one it misses; `crossing_on_edge` when P lies
/// on the closed edge:
///   a and b both above P, or both below, or both left of it: 0
///   both right of it: its direction alone (upward: a.y <= P.y < b.y)
///   P on the closed edge [a, b]                      -> crossing_on_edge
///   upward edge, P left of it: +1; downward edge (b.y <= P.y < a.y), P
///   right of it: -1; else 0
/// An orientation is taken only for an edge whose box holds P.
template <class NT>
int edge_crossing(const point<NT>& a, const point<NT>& b, const point<NT>& p) {
    const int ay = compare_values(a.y, p.y), by = compare_values(b.y, p.y);
    if ((ay > 0 && by > 0) || (ay < 0 && by < 0)) return 0;  // no crossing, P not on it
    const int ax = compare_values(a.x, p.x), bx = compare_values(b.x, p.x);
    if (ax < 0 && bx < 0) return 0;  // wholly left: the ray misses it, P is not on it
    const bool upward = ay <= 0 && by > 0, downward = by <= 0 && ay > 0;
    if (ax > 0 && bx > 0) return upward ? 1 : downward ? -1 : 0;  // P left of an upward edge, right of a downward one
    const int side = orientation(a, b, p);
    if (side == 0 && within_collinear_segment(p, a, b)) return crossing_on_edge;
    return upward && side > 0 ? 1 : downward && side < 0 ? -1 : 0;
}

/// Locates P in the closed region of the polygon whose vertices, in NT, are
/// `v` (topology from `shape`) by the winding number of a ray from P towards
/// +x, without an origin: the sum of edge_crossing over the edges, the
/// boundary when P lies on one; inside when the sum is not zero. The same
/// region as feito_locate (the same winding numbers, the boundary closed),
/// exact when NT's comparisons and orientations are; time linear in the
/// number of edges, with a few comparisons per edge.
template <class NT>
location locate_by_crossings(const polygon& shape, const std::vector<point<NT>>& v, const point<NT>& p) {
    INFLUENCE2D_ASSERT(v.size() == shape.size(), "the vertices in NT are not the polygon's");
    long long winding = 0;
    for (std::size_t i = 0; i < shape.size(); ++i) {
        const int c = edge_crossing(v[i], v[shape.next(i)], p);
        if (c == crossing_on_edge) return location::boundary;
        winding += c;
    }
    return winding != 0 ? location::inside : location::outside;
}

/// locate_by_crossings with a filter in double: the polygon's vertices are
/// known in double (`approx`) and P (`p_approx`) to within e on each
/// coordinate, and in NT on demand (`vertex(i)`, P as `p`). `runs`, when
/// not empty, holds the boxes of the approx vertices of the runs of
/// `run_length` consecutive edges (run r: edges r run_length onwards),
/// every approx coordinate finite. The same answer as locate_by_crossings
/// on the vertices in NT, exact when NT is:
///   for each run (every edge one run when there are no runs):
///     the run's box certainly misses the ray (certainly_off_ray): its
///       edges add nothing
///     else for each edge: its crossing settled in double (certain_crossing)
///       or, when not, edge_crossing in NT (a vertex in NT made only there)
template <class NT, class Vertex>
location locate_by_crossings(const polygon& shape, const std::vector<point<double>>& approx,
                             const std::vector<box>& runs, std::size_t run_length, const point<double>& p_approx,
                             double e, const point<NT>& p, Vertex&& vertex) {
    INFLUENCE2D_ASSERT(approx.size() == shape.size(), "the vertices in double are not the polygon's");
    long long winding = 0;
    const auto edges = [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) {
            const std::size_t j = shape.next(i);
            int c = certain_crossing(approx[i], approx[j], p_approx, 2 * e);
            if (c == crossing_unknown) c = edge_crossing<NT>(vertex(i), vertex(j), p);
            if (c == crossing_on_edge) return false;
            winding += c;
        }
        return true;
    };
    if (runs.empty()) {
        if (!edges(0, shape.size())) return location::boundary;
    } else {
        for (std::size_t r = 0; r < runs.size(); ++r) {
            if (certainly_off_ray(runs[r], p_approx, 2 * e)) continue;
            if (!edges(r * run_length, std::min(shape.size(), (r + 1) * run_length))) return location::boundary;
        }
    }
    return winding != 0 ? location::inside : location::outside;
}

/// Locates P in the closed region of the polygon whose vertices, in NT, are
/// `v` (topology from `shape`), with the covering from origin `o`. When P is the
/// origin itself the sum is taken from the first vertex instead: any origin
/// gives the same winding number. Region as for polygon: boundary when P is on
/// an edge, inside when the winding number is not zero (a point inside a hole
/// is outside). Signs of orientations only: exact when NT is. Time linear in
/// the number of edges; influence_areas::locate visits only nearby cones.
template <class NT>
location locate(const polygon& shape, const std::vector<point<NT>>& v, const point<NT>& o, const point<NT>& p) {
    return feito_locate(shape, v, same_point(p, o) ? v.front() : o, p);
}

/// Locates P in the region covered by `cov` (as the overload above).
template <class NT>
location locate(const triangle_covering<NT>& cov, const point<NT>& p) {
    return locate(cov.shape(), cov.vertices(), cov.origin(), p);
}

}  // namespace influence2d
