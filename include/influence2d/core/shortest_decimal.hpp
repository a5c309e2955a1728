// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// How a double is written in a message or a file: in the fewest decimal
/// digits that read back to the same double.

#include <array>
#include <charconv>
#include <string>

namespace influence2d {

/// x written in the fewest decimal digits that read back to it
/// (std::to_chars): 1e-20 stays 1e-20 and 1e308 takes six characters, where
/// std::to_string writes a fixed six decimals (0.000000, and 309 digits).
/// NaN and the infinities are written nan (-nan with the sign bit set), inf
/// and -inf.
inline std::string shortest_decimal(double x) {
    std::array<char, 32> buf{};
    const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), x);
    return std::string(buf.data(), res.ptr);
}

}  // namespace influence2d
