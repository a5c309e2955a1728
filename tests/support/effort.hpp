// SPDX-License-Identifier: BSL-1.0
#pragma once
// How much of their full work the heavy tests do: 1 by default, less when the
// environment variable INFLUENCE2D_TEST_EFFORT says so (the sanitizer run, whose
// instrumented code is several times slower, uses 0.25). Cases and assertions
// stay the same; only the number of random frames shrinks.

#include <algorithm>
#include <cstdlib>
#include <string>

namespace test_effort {

inline double effort() {
    const char* s = std::getenv("INFLUENCE2D_TEST_EFFORT");
    if (s == nullptr) return 1.0;
    const double e = std::strtod(s, nullptr);
    return e > 0 ? std::min(e, 1.0) : 1.0;
}

/// `n` scaled by the effort, at least 1.
inline int scaled(int n) { return std::max(1, static_cast<int>(n * effort())); }

}  // namespace test_effort
