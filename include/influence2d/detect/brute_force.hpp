// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The brute-force reference: every edge pair, then containment. No filter,
/// no coherence; the same predicates as the other detectors.

#include <memory>

#include "influence2d/detect/containment.hpp"
#include "influence2d/detect/pairs.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/predicates/segments.hpp"
#include "influence2d/scene/posed_polygon.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d {

/// The reference detector: every edge pair, then containment. Per frame each
/// (static edge, moving edge) pair gets the segment test (d == 0) or the
/// distance test (d > 0); when no pair meets, containment decides. It asks
/// detector's question (closed regions within d, touching counts, B inside a
/// hole of A does not) at O(n m) per frame for n static and m moving edges.
/// Exact when NT is; in a floating NT its decisions round. Zero-length edges
/// are tested as points; collinear runs, spikes and zero-area rings need no
/// special case.
template <class NT>
class brute_force_detector {
public:
    /// Copies both polygons and builds A's covering (linear time). Uses
    /// `options.distance` (finite and >= 0; not checked here) and
    /// `options.witness`; the other options concern filters and are ignored.
    /// A filtered NT may throw uncertain_sign here.
    brute_force_detector(const polygon& static_polygon, const polygon& moving_polygon, detector_options options = {})
        : a_(std::make_shared<const static_scene<NT>>(static_polygon)), b_(moving_polygon), options_(options) {}

    /// collides = some static edge and moving edge are within d (meet, for
    /// d == 0), or else one region contains a ring of the other. Without
    /// witnesses it stops at the first pair and `pairs` stays empty; with
    /// them every pair is listed, in input numbering, sorted, without repeats.
    /// A filtered NT may throw uncertain_sign (see filtered_detector).
    frame_result collide(const pose& p) {
        using tr = number_traits<NT>;
        const rotation_pose t(p);
        b_.place(t);
        const NT dn = tr::from_double(options_.distance);
        const NT d2 = dn * dn;
        const bool within = options_.distance > 0;
        pairs_.clear();
        const auto& cov = a_->covering;
        for (std::size_t i = 0; i < cov.size(); ++i) {
            for (std::size_t j = 0; j < b_.size(); ++j) {
                const bool meet = within ? segments_within(cov.start(i), cov.end(i), b_.vertex(j), b_.end(j), d2)
                                         : segments_intersect(cov.start(i), cov.end(i), b_.vertex(j), b_.end(j));
                if (!meet) continue;
                pairs_.add(i, j);
                if (!options_.witness) return {true, {}};
            }
        }
        frame_result r;
        if (!pairs_.empty()) {
            r.collides = true;
            r.pairs = pairs_.in_input_numbering(a_->shape, b_.shape());
            return r;
        }
        r.collides = one_contains_other(*a_, b_);
        return r;
    }

private:
    std::shared_ptr<const static_scene<NT>> a_;
    posed_polygon<NT> b_;
    detector_options options_;
    pair_collector pairs_;
};

}  // namespace influence2d
