// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// How far one rounding of a double moves a result: the unit roundoff, the
/// constant the filters' error bounds in double are written in.

#include <limits>

namespace influence2d {

/// The unit roundoff u of IEEE 754 binary64 under rounding to nearest: a
/// sum, difference, product, quotient or square root of doubles whose exact
/// result x lies in the normal range rounds to a double within u |x| of x,
/// u = 2^-53 (half the spacing 2^-52 of the doubles in [1, 2)). Two
/// roundings, or a value taken within an ulp (std::cos, std::sin), are
/// covered by 2u = 2^-52 to first order. A result below the normal range
/// rounds by at most 2^-1075 instead; each bound adds that separately.
inline constexpr double unit_roundoff = 0x1p-53;
static_assert(std::numeric_limits<double>::is_iec559 &&
                  std::numeric_limits<double>::round_style == std::round_to_nearest &&
                  unit_roundoff == std::numeric_limits<double>::epsilon() / 2,
              "the filters' bounds assume IEEE 754 binary64 doubles rounded to nearest");

}  // namespace influence2d
