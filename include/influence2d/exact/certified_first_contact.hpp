// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The exact first contact along a motion, rounded to double, at nearly
/// double's cost.

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/exact/certified_separation.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/number/cgal.hpp"

namespace influence2d {

/// The first contact of first_contact<exact_rational> (motion/first_contact.hpp),
/// its time rounded to the nearest double, with its exact features, at
/// nearly double's cost: filtered_first_contact in exact rationals (each
/// event computed and compared in `certified`, and again exactly only when
/// its signs are not certain; a motion that turns decided on
/// certified_separation, the exact separation in double words where their
/// bounds settle it). Throws as first_contact.
inline contact_result<double> certified_first_contact(const polygon& a, const polygon& b, const pose& from,
                                                      const pose& to, const sweep_options& options = {}) {
    return filtered_first_contact<exact_rational, certified_separation_of>(a, b, from, to, options);
}

}  // namespace influence2d
