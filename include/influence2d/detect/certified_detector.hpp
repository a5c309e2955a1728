#pragma once
// Certified detection: the answers of the exact reference at nearly the cost
// of double. Each frame runs in the certified number type; a frame with a sign
// that double precision cannot certify is answered again in exact rationals.

#include <cstddef>
#include <optional>

#include "influence2d/core/pose.hpp"
#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"

namespace influence2d {

/// Wraps a detector template D (detector or brute_force_detector): D<certified>
/// answers every frame whose decisions are all certain, which is then the exact
/// answer (each decision is a sign known with certainty); a frame that raises
/// uncertain_sign is answered by D<exact_rational>. The certified detector's
/// own state stays valid after such a frame: its candidate cache is marked
/// valid only once complete, and it holds no other state between frames.
template <template <class> class D>
class certified_detector {
public:
    certified_detector(const polygon& static_polygon, const polygon& moving_polygon, detector_options options = {})
        : exact_(static_polygon, moving_polygon, options) {
        // Preprocessing decides signs too; if one is not certain in double
        // (a scene at the edge of double's range), every frame goes exact.
        try {
            fast_.emplace(static_polygon, moving_polygon, options);
        } catch (const uncertain_sign&) {
            fast_.reset();
        }
    }

    frame_result collide(const pose& p) {
        if (fast_) {
            try {
                return fast_->collide(p);
            } catch (const uncertain_sign&) {
            }
        }
        ++exact_frames_;
        return exact_.collide(p);
    }

    /// Frames answered in exact arithmetic so far.
    std::size_t exact_frames() const { return exact_frames_; }

private:
    std::optional<D<certified>> fast_;
    D<exact_rational> exact_;
    std::size_t exact_frames_ = 0;
};

}  // namespace influence2d
