#pragma once
// Interval detection: like certified_detector (detect/certified_detector.hpp),
// with CGAL's interval arithmetic as the fast number type. Each frame runs in
// intervals; a frame with a decision the intervals cannot make is answered
// again in exact rationals.
//
// Why a wrapper of its own rather than certified_detector: the library decides
// signs through number_traits<NT>::sign, which raises uncertain_sign for an
// undecided interval, but it also compares NT values directly (segment
// extents, distance bounds: `a < b`), and on intervals those comparisons are
// CGAL's, whose undecided results raise CGAL::Uncertain_conversion_exception
// when converted to bool. The traits cannot change what operator< does, so the
// fallback has to catch both; certified_detector catches only uncertain_sign.

#include <cstddef>
#include <optional>

#include <CGAL/Uncertain.h>

#include "influence2d/core/pose.hpp"
#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"

namespace influence2d {

/// Wraps a detector template D (detector or brute_force_detector): D<interval>
/// answers every frame whose decisions the intervals all make, which is then
/// the exact answer; a frame that raises uncertain_sign or
/// CGAL::Uncertain_conversion_exception is answered by D<exact_rational>.
/// The interval detector's state stays valid after such a frame, as for
/// certified_detector. Building D<interval> decides the orientation of every
/// covering triangle; when one of those is undecided (an edge collinear with
/// the centroid, say) every frame is answered exactly.
template <template <class> class D>
class interval_detector {
public:
    interval_detector(const polygon& static_polygon, const polygon& moving_polygon, detector_options options = {})
        : exact_(static_polygon, moving_polygon, options) {
        try {
            fast_.emplace(static_polygon, moving_polygon, options);
        } catch (const uncertain_sign&) {
            fast_.reset();
        } catch (const CGAL::Uncertain_conversion_exception&) {
            fast_.reset();
        }
    }

    frame_result collide(const pose& p) {
        if (fast_) {
            try {
                return fast_->collide(p);
            } catch (const uncertain_sign&) {
            } catch (const CGAL::Uncertain_conversion_exception&) {
            }
        }
        ++exact_frames_;
        return exact_.collide(p);
    }

    /// Frames answered in exact arithmetic so far.
    std::size_t exact_frames() const { return exact_frames_; }
    /// Whether the interval detector could be built (else every frame is exact).
    bool filtered() const { return fast_.has_value(); }

private:
    std::optional<D<interval>> fast_;
    D<exact_rational> exact_;
    std::size_t exact_frames_ = 0;
};

}  // namespace influence2d
