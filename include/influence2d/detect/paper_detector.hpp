// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Algorithm 3 of Jimenez, Segura and Feito (WSCG 2004) as published, kept to
/// reproduce the paper and to show where it fails (docs/method.md sections 6, 7).
/// It is NOT a correct detector: it misses collisions and reports false ones.

#include <memory>
#include <vector>

#include "influence2d/detect/pairs.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/influence/edge_grid.hpp"
#include "influence2d/influence/influence_areas.hpp"
#include "influence2d/predicates/distance.hpp"
#include "influence2d/predicates/extended_area.hpp"
#include "influence2d/scene/posed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d {

/// Per frame (r = B's bounding radius, n = r + d, p = B's centroid):
///   1. Move B. If the bounding circles do not meet: OUT.
///   2. Influence mask of p; if p left none of the previous frame's influence
///      areas: OUT (the first frame is always tested).
///   3. If p is in the influence area of length n of some edge whose area
///      contains it (on O's side of the edge, or within n beyond its line):
///      the candidate edges are those whose extended area (always the paper's
///      band, whatever options.shape says) contains p; an edge collides with the
///      moving edges whose ends change the sign of alpha. Else OUT.
/// No segment confirmation, no containment test: the literal algorithm. It
/// misses collisions (an approach along one cone, contacts the gate misses,
/// B inside A away from the lines of A's edges: it has no containment test;
/// when B holds A or a part of a multipolygon A, B's edges straddle the lines
/// of that part's edges and the straddle test says yes for that wrong reason) and reports false ones (B straddling an edge's line beyond
/// the segment); use detector for correct answers. Its signs are exact when
/// NT is, so its failures are the algorithm's, not rounding's.
template <class NT>
class paper_detector {
public:
    /// Copies both polygons, builds A's covering, influence areas and an edge
    /// grid for the band's reach. Uses `options.distance` (n = r + d) and
    /// `options.witness`; `options.shape` and `options.temporal_coherence`
    /// are ignored (always the band; the mask is the paper's coherence).
    paper_detector(const polygon& static_polygon, const polygon& moving_polygon, detector_options options = {})
        : a_(std::make_shared<const static_scene<NT>>(static_polygon)), b_(moving_polygon), options_(options) {
        reach_ = moving_reach(b_.radius(), options_.distance);
        // The band reaches up to (1 + sqrt 2 + 1) n from its edge at the caps' corners.
        grid_ = edge_grid(a_->shape, 3 * reach_, posing_margin<NT>(a_->scale + a_->radius + 3 * reach_));
        previous_ = influence_mask(a_->shape.size());
        current_ = influence_mask(a_->shape.size());
    }

    /// The literal algorithm's answer for the frame (steps above). It keeps
    /// the frame's influence mask for the next frame, so frames must come in
    /// trajectory order. With witnesses, the straddling (static, moving) edge
    /// pairs in input numbering: pairs whose moving edge has an end on the
    /// static edge's line or on both sides of it, not confirmed contacts.
    frame_result collide(const pose& q) {
        using tr = number_traits<NT>;
        const rotation_pose t(q);
        b_.place(t);
        const point<NT>& p = b_.centroid();
        const auto& cov = a_->covering;
        const NT n = tr::from_double(reach_);
        const NT n2 = n * n;

        // 1. Bounding circles.
        const NT outer = tr::from_double(a_->radius) + n;
        if (compare_values<NT>(squared_distance(p, cov.origin()), outer * outer) > 0) return {};

        // 2. Influence mask against the previous frame's.
        a_->areas().mask(p, current_);
        const bool left = first_frame_ || current_.left_some_area_of(previous_);
        std::swap(previous_, current_);
        first_frame_ = false;
        if (!left) return {};

        // 3. Influence area of length n, then the extended areas.
        bool gate = false;
        a_->areas().for_each_containing(p, [&](std::size_t i) {
            gate = gate || cov.signs(i, p).alpha >= 0 || point_line_within(p, cov.start(i), cov.end(i), n2);
        });
        if (!gate) return {};
        pairs_.clear();
        const polygon& bs = b_.shape();
        const std::size_t m = bs.size();
        std::vector<int> side(m);
        for (std::uint32_t e : grid_.query(to_double_point(p))) {
            if (!in_band(p, cov.start(e), cov.end(e), n, n2)) continue;
            for (std::size_t j = 0; j < m; ++j) side[j] = orientation(cov.start(e), cov.end(e), b_.vertex(j));
            for (std::size_t j = 0; j < m; ++j)
                if (side[j] * side[bs.next(j)] <= 0) pairs_.add(e, j);
        }
        frame_result r;
        r.collides = !pairs_.empty();
        if (options_.witness) r.pairs = pairs_.in_input_numbering(a_->shape, bs);
        return r;
    }

private:
    std::shared_ptr<const static_scene<NT>> a_;
    posed_polygon<NT> b_;
    detector_options options_;
    double reach_ = 0;
    edge_grid grid_;
    influence_mask previous_, current_;
    bool first_frame_ = true;
    pair_collector pairs_;
};

}  // namespace influence2d
