// SPDX-License-Identifier: BSL-1.0
#pragma once
// The exact reference answer of a frame (docs/method.md section 1), built only on
// CGAL's exact kernel (Epeck) and its own predicates, independently of the
// library's predicates, coverings and filters. It is slow and simple on
// purpose: the detectors are tested against it.
//
// How it decides:
// - Pose: c = std::cos(theta), s = std::sin(theta) as doubles; every vertex q of
//   B goes to (c*qx - s*qy + tx, s*qx + c*qy + ty) evaluated in Epeck::FT, so B
//   is posed exactly.
// - Boundary pairs: every (static edge, moving edge) pair is tested; with d == 0
//   by CGAL::do_intersect, with d > 0 by CGAL::squared_distance <= d*d (exact).
//   A zero-length edge (repeated vertex) is tested as a Point_2. Box tests in
//   double come first (against B's whole box, then each edge's); they can only drop pairs whose boxes are more than d
//   apart on one axis (rounding of a difference is monotone, so the double
//   comparison never drops a pair that the exact test would keep).
// - Regions: the library's rule, closed. A point is in a region when it lies
//   on an edge of one of its rings, or when the sum of the rings' winding
//   numbers around it (outer rings counter-clockwise, holes clockwise, as the
//   polygon stores them; the orientation is checked here on exact areas) is
//   not zero. The winding number is counted by ray crossings decided with
//   CGAL::orientation, without the library's coverings or cone index.
// - Collision: some boundary pair exists, or (no pair within d, so the
//   boundaries are more than d apart and each ring lies wholly on one side of
//   the other polygon's boundary) the first vertex of some ring of B lies in
//   region A or the first vertex of some ring of A lies in region B: that
//   region holds the whole ring, and the regions intersect. Every ring of
//   both polygons is located: no box or circle decides anything here.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <CGAL/Bbox_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/squared_distance_2.h>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/detect/result.hpp"

namespace influence2d::verification {

class cgal_reference {
public:
    using kernel = CGAL::Exact_predicates_exact_constructions_kernel;
    using FT = kernel::FT;
    using point_2 = kernel::Point_2;
    using segment_2 = kernel::Segment_2;

    /// A is static, B moves; `distance` is d >= 0; with `witness` every pair
    /// within d is reported (input numbering, sorted).
    cgal_reference(const polygon& A, const polygon& B, double distance = 0, bool witness = false)
        : a_(A), b_(B), distance_(distance), witness_(witness) {
        if (!(distance >= 0) || !std::isfinite(distance))
            throw std::invalid_argument("cgal_reference: distance must be finite and >= 0");
        squared_distance_ = FT(distance) * FT(distance);
        std::vector<point_2> pts;
        pts.reserve(a_.size());
        for (const auto& v : a_.vertices()) pts.emplace_back(v.x, v.y);
        a_edges_ = make_edges(a_, pts);
        for (const edge& e : a_edges_) a_boxes_.push_back(e.box);
        a_rings_ = make_rings(a_, pts);
    }

    /// Whether A's closed region holds the point (x, y), exactly (the rule
    /// of in_region below, on CGAL's predicates).
    bool static_region_holds(double x, double y) const { return in_region(a_rings_, point_2(x, y)); }

    frame_result collide(const pose& p) const {
        const FT c(std::cos(p.theta)), s(std::sin(p.theta)), tx(p.tx), ty(p.ty);
        std::vector<point_2> pts;
        pts.reserve(b_.size());
        for (const auto& q : b_.vertices()) {
            const FT qx(q.x), qy(q.y);
            pts.emplace_back(c * qx - s * qy + tx, s * qx + c * qy + ty);
        }
        const std::vector<edge> b_edges = make_edges(b_, pts);

        CGAL::Bbox_2 b_box;  // encloses every edge of B
        for (const edge& f : b_edges) b_box += f.box;
        frame_result out;
        for (std::size_t i = 0; i < a_edges_.size(); ++i) {
            if (!boxes_near(a_boxes_[i], b_box)) continue;  // then no edge of B is near it either
            const edge& e = a_edges_[i];
            for (const edge& f : b_edges) {
                if (!within(e, f)) continue;
                out.collides = true;
                if (!witness_) return out;
                out.pairs.push_back(edge_pair{e.source, f.source});
            }
        }
        if (out.collides) {
            std::sort(out.pairs.begin(), out.pairs.end());
            out.pairs.erase(std::unique(out.pairs.begin(), out.pairs.end()), out.pairs.end());
            return out;
        }
        // No boundary pair within d: no ring of one polygon meets the other's
        // boundary, so each ring lies wholly inside or wholly outside the
        // other's region, and one vertex of each ring tells which.
        const std::vector<ring> b_rings = make_rings(b_, pts);
        for (const ring& g : b_rings) {
            if (!g.points.empty() && in_region(a_rings_, g.points.front())) {
                out.collides = true;
                return out;
            }
        }
        for (const ring& g : a_rings_) {
            if (!g.points.empty() && in_region(b_rings, g.points.front())) {
                out.collides = true;
                return out;
            }
        }
        return out;
    }

private:
    struct edge {
        point_2 from, to;
        bool degenerate = false;  ///< zero length: tested as the point `from`
        CGAL::Bbox_2 box;
        std::size_t source = 0;  ///< input numbering
    };

    struct ring {
        std::vector<point_2> points;  ///< consecutive repeats removed
        bool hole = false;
    };

    static std::vector<edge> make_edges(const polygon& P, const std::vector<point_2>& pts) {
        std::vector<edge> edges;
        edges.reserve(P.size());
        for (std::size_t i = 0; i < P.size(); ++i) {
            const std::size_t j = P.next(i);
            edge e;
            e.from = pts[i];
            e.to = pts[j];
            e.degenerate = P.vertex(i) == P.vertex(j);  // same input doubles, same posed point
            e.box = pts[i].bbox() + pts[j].bbox();      // encloses the exact points
            e.source = P.source_edge(i);
            edges.push_back(e);
        }
        return edges;
    }

    static std::vector<ring> make_rings(const polygon& P, const std::vector<point_2>& pts) {
        std::vector<ring> rings;
        for (std::size_t r = 0; r < P.ring_count(); ++r) {
            ring g;
            g.hole = P.role(r) == ring_role::hole;
            for (std::size_t i = P.ring_begin(r); i < P.ring_end(r); ++i) {
                if (P.vertex(i) != P.vertex(P.next(i))) g.points.push_back(pts[i]);
            }
            // The polygon's stored orientation, checked here exactly: an outer
            // ring of non-zero area turns counter-clockwise, a hole clockwise.
            const CGAL::Sign area = g.points.size() < 3 ? CGAL::ZERO : signed_area_sign(g.points);
            if (area != CGAL::ZERO && (area == CGAL::POSITIVE) != !g.hole)
                throw std::logic_error("cgal_reference: ring " + std::to_string(r) +
                                       " is stored with the wrong orientation");
            rings.push_back(std::move(g));
        }
        return rings;
    }

    /// The library's region rule, decided here on CGAL's exact predicates: q
    /// is in the closed region when it lies on an edge of some ring, or when
    /// the sum over the rings of their winding numbers around q is not zero.
    /// Rings come as the polygon stores them (outer rings counter-clockwise,
    /// holes clockwise; checked in make_rings), so a hole outside every outer
    /// ring is region (winding -1) and nested outer rings add nothing new.
    static bool in_region(const std::vector<ring>& rings, const point_2& q) {
        long winding = 0;
        for (const ring& g : rings) {
            const std::size_t n = g.points.size();
            for (std::size_t i = 0; i < n; ++i) {
                const point_2& a = g.points[i];
                const point_2& b = g.points[(i + 1) % n];
                const CGAL::Orientation side = CGAL::orientation(a, b, q);
                if (side == CGAL::COLLINEAR && CGAL::collinear_are_ordered_along_line(a, q, b)) return true;
                // Crossings of the horizontal ray from q towards +x: upward
                // edges with q on their left count +1, downward edges with q
                // on their right count -1 (each edge half-open in y).
                if (a.y() <= q.y()) {
                    if (b.y() > q.y() && side == CGAL::LEFT_TURN) ++winding;
                } else if (b.y() <= q.y() && side == CGAL::RIGHT_TURN) {
                    --winding;
                }
            }
        }
        return winding != 0;
    }

    /// The exact sign of a ring's signed area (shoelace sum in FT).
    static CGAL::Sign signed_area_sign(const std::vector<point_2>& pts) {
        FT twice = 0;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const point_2& a = pts[i];
            const point_2& b = pts[(i + 1) % pts.size()];
            twice += a.x() * b.y() - a.y() * b.x();
        }
        return CGAL::sign(twice);
    }

    /// Conservative: false only when the boxes are more than d apart on an axis.
    bool boxes_near(const CGAL::Bbox_2& a, const CGAL::Bbox_2& b) const {
        return b.xmin() - a.xmax() <= distance_ && a.xmin() - b.xmax() <= distance_ &&
               b.ymin() - a.ymax() <= distance_ && a.ymin() - b.ymax() <= distance_;
    }

    bool within(const edge& e, const edge& f) const {
        if (!boxes_near(e.box, f.box)) return false;
        if (distance_ == 0) {
            if (e.degenerate && f.degenerate) return e.from == f.from;
            if (e.degenerate) return CGAL::do_intersect(e.from, segment_2(f.from, f.to));
            if (f.degenerate) return CGAL::do_intersect(f.from, segment_2(e.from, e.to));
            return CGAL::do_intersect(segment_2(e.from, e.to), segment_2(f.from, f.to));
        }
        FT sq;
        if (e.degenerate && f.degenerate)
            sq = CGAL::squared_distance(e.from, f.from);
        else if (e.degenerate)
            sq = CGAL::squared_distance(e.from, segment_2(f.from, f.to));
        else if (f.degenerate)
            sq = CGAL::squared_distance(f.from, segment_2(e.from, e.to));
        else
            sq = CGAL::squared_distance(segment_2(e.from, e.to), segment_2(f.from, f.to));
        return sq <= squared_distance_;
    }

    polygon a_, b_;
    double distance_ = 0;
    bool witness_ = false;
    FT squared_distance_;
    std::vector<edge> a_edges_;
    std::vector<CGAL::Bbox_2> a_boxes_;  ///< a_edges_[i].box, stored densely for the scan
    std::vector<ring> a_rings_;
};

}  // namespace influence2d::verification
