// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Which double is nearest to the exact value a double word bounds, when its
/// bound settles it: the rounding decision of the certified queries, made
/// without exact arithmetic whenever the value is not within its bound of a
/// midpoint between two doubles.

#include <cmath>
#include <cstdint>
#include <cstring>

#include "influence2d/number/double_word.hpp"

namespace influence2d {

/// The relative bound of the two differences certain_nearest compares: a
/// half gap (a power of two) less or plus the low word, rounded once
/// (relative 2^-53); 2^-52 covers it.
inline constexpr double nearest_margin_rounding = 0x1p-52;

/// Stores in `nearest` the double nearest to the exact value X of x and
/// returns true when the bound proves it; otherwise returns false. X lies in
/// [hi + lo - e, hi + lo + e] (e = x.error()), and hi is nearer to X than
/// both neighbours of hi exactly when -g_down / 2 < X - hi < g_up / 2, g_up
/// and g_down the gaps to the next double above and below hi (g_down = g_up
/// / 2 at a power of two going down). So the answer is hi when g_up / 2 - lo
/// and lo + g_down / 2, each rounded and taken nearest_margin_rounding
/// smaller, both exceed e. A value within e of a midpoint (a tie included)
/// is left undecided. Defined for hi of magnitude in [word_floor,
/// word_ceiling] (far from the subnormals, so the gaps are powers of two
/// above 2^-960) and for the exact 0; false otherwise.
inline bool certain_nearest(const double_word& x, double& nearest) {
    const double hi = x.hi(), lo = x.lo(), e = x.error();
    if (!x.known()) return false;
    if (hi == 0) {
        nearest = 0;
        return e == 0;
    }
    // The neighbours of hi: its bit pattern plus and minus one (the next
    // magnitude away from 0 and toward it; hi is normal, far from 0 and
    // infinity, so neither step leaves the normal doubles).
    std::uint64_t bits;
    std::memcpy(&bits, &hi, sizeof bits);
    const std::uint64_t away_bits = bits + 1, toward_bits = bits - 1;
    double away, toward;
    std::memcpy(&away, &away_bits, sizeof away);
    std::memcpy(&toward, &toward_bits, sizeof toward);
    const double up = (hi > 0 ? away : toward) - hi, down = hi - (hi > 0 ? toward : away);
    const double above = (up / 2 - lo) * (1 - nearest_margin_rounding);
    const double below = (lo + down / 2) * (1 - nearest_margin_rounding);
    if (!(above > e && below > e)) return false;
    nearest = hi;
    return true;
}

}  // namespace influence2d
