// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Interval detection: filtered_detector with CGAL's interval arithmetic as the
/// fast number type.
///
/// Why it catches one more exception type than certified_detector: the
/// predicates take every sign and comparison through number_traits::sign
/// (orientation(), compare_values()), which raises uncertain_sign for an
/// undecided interval; but one test outside them still compares NT values
/// with `>` (the reach test of one_contains_other, detect/containment.hpp),
/// and on intervals that comparison is CGAL's, whose undecided result raises
/// CGAL::Uncertain_conversion_exception when converted to bool. Until that
/// test goes through compare_values too, the fallback catches both.

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
