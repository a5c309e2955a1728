// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Certified detection: `D<certified>` with a per-frame exact fallback.

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/filtered_detector.hpp"
#include "influence2d/number/certified.hpp"

namespace influence2d {

/// The exact answers at nearly double's cost: every frame runs in `certified`
/// (a double with a running error bound), and a frame whose signs the bound
/// cannot settle is answered again in exact rationals: every answer is the
/// exact reference's (the fallback needs CGAL, number/cgal.hpp). D is detector or
/// brute_force_detector.
template <template <class...> class D>
using certified_detector = filtered_detector<D, certified>;

}  // namespace influence2d
