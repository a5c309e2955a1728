// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Interval detection: filtered_detector with CGAL's interval arithmetic as the
/// fast number type.
///
/// Why it catches one more exception type than certified_detector: the library decides
/// signs through number_traits::sign, which raises uncertain_sign for an
/// undecided interval, but it also compares NT values directly (segment
/// extents, distance bounds: `a < b`), and on intervals those comparisons are
/// CGAL's, whose undecided results raise CGAL::Uncertain_conversion_exception
/// when converted to bool. The traits cannot change what operator< does, so the
/// fallback has to catch both.

#include <CGAL/Uncertain.h>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/detect/filtered_detector.hpp"
#include "influence2d/number/cgal.hpp"

namespace influence2d {

/// The exact reference's answers through CGAL's intervals: every frame runs in `interval`,
/// and a frame with a sign or a comparison the intervals cannot settle is
/// answered again in exact rationals. D is detector or brute_force_detector.
template <template <class...> class D>
using interval_detector = filtered_detector<D, interval, CGAL::Uncertain_conversion_exception>;

}  // namespace influence2d
