// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Filtered detection: the answers of the exact reference at nearly the cost of
/// a floating-point type. Each frame runs in a fast filtered number type; a
/// frame with a sign that type cannot settle is answered again in exact
/// rationals.

#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/fallback.hpp"

namespace influence2d {

namespace filtered_detector_detail {

/// Whether D has build_structures().
template <class D, class = void>
struct has_build_structures : std::false_type {};
template <class D>
struct has_build_structures<D, std::void_t<decltype(std::declval<D&>().build_structures())>> : std::true_type {};

}  // namespace filtered_detector_detail

/// Wraps a detector template D (detector or brute_force_detector): `D<FastNT>`
/// answers every frame whose decisions it makes with certainty, which is then
/// the exact answer; a frame that raises uncertain_sign (or one of the
/// exception types Uncertain..., for number types whose comparisons raise
/// their own) is answered by `D<exact_rational>`, built by the first such
/// frame (a run with no frame in doubt pays for the fast detector alone).
/// The fast detector's state stays
/// valid after such a frame: its candidate cache is marked valid only once
/// complete, and it holds no other state between frames. Building `D<FastNT>`
/// decides signs too (the covering's triangles); if one of those is not
/// certain, every frame is answered exactly.
template <template <class...> class D, class FastNT, class... Uncertain>
class filtered_detector {
public:
    /// Builds the fast detector; the exact one is built by the first frame
    /// the fast one cannot settle (or at once, when building the fast one
    /// asks a sign it cannot settle), from copies of both polygons kept for
    /// that. Whatever D's constructor throws, other than an uncertain sign,
    /// propagates.
    filtered_detector(const polygon& static_polygon, const polygon& moving_polygon, detector_options options = {})
        : a_(static_polygon), b_(moving_polygon), options_(options) {
        fallback<Uncertain...>::run(
            [&] {
                fast_.emplace(a_, b_, options_);
                return 0;
            },
            [&] {
                fast_.reset();
                exact();
                return 0;
            });
    }

    /// The exact answer for the frame: the fast detector's, or the exact
    /// detector's when the fast one could not decide (counted in
    /// exact_frames()). Semantics as D::collide.
    frame_result collide(const pose& p) {
        const auto exactly = [&] {
            ++exact_frames_;
            return exact().collide(p);
        };
        if (!fast_) return exactly();
        return fallback<Uncertain...>::run([&] { return fast_->collide(p); }, exactly);
    }

    /// collide(p) with the witnesses written into `pairs` (D::collide(p,
    /// pairs): cleared first, its capacity kept from call to call), when D
    /// has that form: the same answer and pairs.
    bool collide(const pose& p, std::vector<edge_pair>& pairs) {
        const auto exactly = [&] {
            ++exact_frames_;
            return exact().collide(p, pairs);
        };
        if (!fast_) return exactly();
        return fallback<Uncertain...>::run([&] { return fast_->collide(p, pairs); }, exactly);
    }

    /// Builds now what the frames would build on first use, when D has such
    /// structures (detector::build_structures; a no-op for D without): the
    /// fast detector's, or the exact one's when building the fast one's asks
    /// a sign it cannot settle (every frame is then answered exactly, as when
    /// the fast detector cannot be built).
    void build_structures() {
        if constexpr (filtered_detector_detail::has_build_structures<D<FastNT>>::value) {
            if (!fast_) return exact().build_structures();
            fallback<Uncertain...>::run(
                [&] {
                    fast_->build_structures();
                    return 0;
                },
                [&] {
                    fast_.reset();
                    exact().build_structures();
                    return 0;
                });
        }
    }

    /// Frames answered in exact arithmetic so far.
    std::size_t exact_frames() const { return exact_frames_; }
    /// Whether the fast detector could be built (else every frame is exact).
    bool filtered() const { return fast_.has_value(); }

private:
    /// The exact detector, built on first use.
    D<exact_rational>& exact() {
        if (!exact_) exact_.emplace(a_, b_, options_);
        return *exact_;
    }

    polygon a_, b_;
    detector_options options_;
    std::optional<D<FastNT>> fast_;
    std::optional<D<exact_rational>> exact_;
    std::size_t exact_frames_ = 0;
};

}  // namespace influence2d
