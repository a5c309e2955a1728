#pragma once
// The sound detector: the paper's method with the defects of its literal form
// removed (method.md section 7).

#include <cmath>
#include <memory>
#include <vector>

#include "influence2d/covering/inclusion.hpp"
#include "influence2d/detect/containment.hpp"
#include "influence2d/detect/pairs.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/detect/scene.hpp"
#include "influence2d/influence/edge_grid.hpp"
#include "influence2d/influence/extended_area.hpp"
#include "influence2d/predicates/segments.hpp"

namespace influence2d {

/// Counters of the work a detector did, for studies of its filters.
struct detector_statistics {
    std::size_t frames = 0;
    std::size_t circle_rejections = 0;  ///< frames answered by the bounding circles
    std::size_t candidate_rebuilds = 0; ///< frames that gathered candidates anew
    std::size_t candidate_edges = 0;    ///< static edges inside their extended area
    std::size_t segment_tests = 0;      ///< exact segment-pair tests
    std::size_t containment_tests = 0;  ///< frames that ran the inclusion tests
};

/// Collision detection between a static polygon A and a moving polygon B, one
/// pose of B per frame. Exact when NT is (number_traits<NT>::category is not
/// floating); in floating types it answers as the brute-force reference in the
/// same type does, up to the rounding of its own decisions.
///
/// Per frame (n = r_B + d, p = B's posed centroid):
///   1. Pose p. If |p - O_A| > R_A + n: the bounding circles are apart: disjoint.
///   2. Candidates: the static edges within n + skin of p, gathered through the
///      edge grid and kept while p stays within `skin` of where they were
///      gathered (temporal coherence; sound because the skin is part of the
///      gathering radius).
///   3. Keep the candidates whose extended area of length n contains p (exact).
///      None: no edge of A comes within n of p, the disk of radius n about p is
///      wholly inside or outside A, and so is B: collides iff p is inside A.
///   4. Pose B. For each candidate edge, the sign of alpha of every moving vertex
///      (the paper's detailed test); a moving edge whose ends are not strictly
///      on one side is confirmed by the exact segment test (d == 0), or every
///      moving edge is tested for distance <= d (d > 0).
///   5. No pair: the regions meet iff one contains a ring of the other.
template <class NT>
class detector {
public:
    detector(const polygon& static_polygon, const polygon& moving_polygon, detector_options options = {})
        : a_(std::make_shared<const static_scene<NT>>(static_polygon)), b_(moving_polygon), options_(options) {
        using tr = number_traits<NT>;
        reach_ = moving_reach(b_.radius(), options_.distance);
        skin_ = options_.temporal_coherence ? 0.25 * reach_ : 0.0;
        margin_ = tr::filter_slack * 4 * (a_->scale + a_->radius + reach_ + skin_) +
                  std::numeric_limits<double>::min();
        grid_ = edge_grid(a_->shape, reach_ + skin_, margin_);
        distance_ = tr::from_double(options_.distance);
        distance2_ = distance_ * distance_;
    }

    frame_result collide(const pose& q) {
        using tr = number_traits<NT>;
        ++stats_.frames;
        const rotation_pose t(q);
        b_.place_centroid(t);
        const point<NT>& p = b_.centroid();
        const point<double> pd = to_double_point(p);
        // Rounding of the posed coordinates is relative to their magnitude.
        const double frame_margin = margin_ + tr::filter_slack * (std::fabs(pd.x) + std::fabs(pd.y));
        const double n = reach_ + frame_margin;
        const NT n_nt = tr::from_double(n);
        const NT n2 = n_nt * n_nt;

        // 1. Bounding circles.
        const NT outer = tr::from_double(a_->radius) + n_nt;
        if (squared_distance(p, a_->covering.origin()) > outer * outer) {
            ++stats_.circle_rejections;
            return {};
        }

        // 2. Candidates gathered within n + skin, reused while p moves < skin.
        if (!cache_valid_ || std::hypot(pd.x - cache_center_.x, pd.y - cache_center_.y) > skin_)
            gather(p, pd, frame_margin);

        // 3. Extended areas, decided exactly.
        candidates_.clear();
        const auto& cov = a_->covering;
        for (std::uint32_t e : cache_)
            if (in_extended_area(options_.shape, p, cov.start(e), cov.end(e), n_nt, n2)) candidates_.push_back(e);
        stats_.candidate_edges += candidates_.size();
        if (candidates_.empty()) {
            ++stats_.containment_tests;
            return {cache_.empty() ? cache_center_inside_ : locate(cov, p) == location::inside, {}};
        }

        // 4. Detailed test on the candidates.
        b_.place_vertices(t);
        pairs_.clear();
        for (std::uint32_t e : candidates_)
            if (test_edge(e) && !options_.witness) return {true, {}};
        frame_result r;
        if (!pairs_.empty()) {
            r.collides = true;
            r.pairs = pairs_.in_input_numbering(a_->shape, b_.shape());
            return r;
        }

        // 5. Containment.
        ++stats_.containment_tests;
        r.collides = one_contains_other(*a_, b_, std::optional<double>(n));
        return r;
    }

    const detector_statistics& statistics() const { return stats_; }
    const detector_options& options() const { return options_; }

private:
    /// Gathers the edges within reach + skin of p into the cache. When there
    /// are none, the disk of that radius about p holds no boundary of A, so
    /// every point within the skin of p is located as p is: that is cached too.
    void gather(const point<NT>& p, const point<double>& pd, double frame_margin) {
        ++stats_.candidate_rebuilds;
        cache_.clear();
        const double keep = reach_ + skin_ + frame_margin + margin_;
        const polygon& s = a_->shape;
        for (std::uint32_t e : grid_.query(pd))
            if (segment_distance(pd, s.vertex(e), s.vertex(s.next(e))) <= keep) cache_.push_back(e);
        cache_center_ = pd;
        cache_valid_ = options_.temporal_coherence;
        if (cache_.empty()) cache_center_inside_ = locate(a_->covering, p) == location::inside;
    }

    /// Tests static edge e against every moving edge; records the pairs found.
    bool test_edge(std::uint32_t e) {
        const auto& cov = a_->covering;
        const point<NT>& a = cov.start(e);
        const point<NT>& b = cov.end(e);
        const std::size_t m = b_.vertices().size();
        bool found = false;
        if (options_.distance > 0) {
            for (std::size_t j = 0; j < m; ++j) {
                ++stats_.segment_tests;
                if (segments_within(a, b, b_.vertex(j), b_.end(j), distance2_)) {
                    pairs_.add(e, j);
                    found = true;
                    if (!options_.witness) return true;
                }
            }
            return found;
        }
        // Sign of alpha for every moving vertex (up to the constant sigma_e).
        side_.resize(m);
        int positive = 0, negative = 0;
        for (std::size_t j = 0; j < m; ++j) {
            side_[j] = static_cast<std::int8_t>(orientation(a, b, b_.vertex(j)));
            positive += side_[j] > 0;
            negative += side_[j] < 0;
        }
        if (positive == static_cast<int>(m) || negative == static_cast<int>(m)) return false;
        const polygon& bs = b_.shape();
        for (std::size_t j = 0; j < m; ++j) {
            const std::size_t k = bs.next(j);
            if (side_[j] * side_[k] > 0) continue;
            ++stats_.segment_tests;
            if (segments_intersect(side_[j], side_[k], a, b, b_.vertex(j), b_.vertex(k))) {
                pairs_.add(e, j);
                found = true;
                if (!options_.witness) return true;
            }
        }
        return found;
    }

    std::shared_ptr<const static_scene<NT>> a_;
    posed_polygon<NT> b_;
    detector_options options_;
    double reach_ = 0, skin_ = 0, margin_ = 0;
    NT distance_, distance2_;
    edge_grid grid_;

    std::vector<std::uint32_t> cache_;
    point<double> cache_center_;
    bool cache_valid_ = false;
    bool cache_center_inside_ = false;
    std::vector<std::uint32_t> candidates_;
    std::vector<std::int8_t> side_;
    detail::pair_collector pairs_;
    detector_statistics stats_;
};

}  // namespace influence2d
