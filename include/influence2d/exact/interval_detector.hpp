// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Interval detection: filtered_detector with CGAL's interval arithmetic as the
/// fast number type.
///
/// Every sign and comparison of NT values in the library goes through
/// number_traits (orientation(), compare_values()), which raises
/// uncertain_sign for an undecided interval: the fallback catches that one
/// type, as certified_detector's does.

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/filtered_detector.hpp"
#include "influence2d/number/cgal.hpp"

namespace influence2d {

/// The exact reference's answers through CGAL's intervals: every frame runs in `interval`,
/// and a frame with a sign or a comparison the intervals cannot settle is
/// answered again in exact rationals. D is detector or brute_force_detector.
template <template <class...> class D>
using interval_detector = filtered_detector<D, interval>;

}  // namespace influence2d
