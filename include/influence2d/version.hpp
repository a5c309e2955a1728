// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The library's version, the one place it is written (CMake reads it from
/// here for the package files).

/// The version as text: major.minor.patch.
#define INFLUENCE2D_VERSION "0.1.0"

namespace influence2d {

/// The version as text (INFLUENCE2D_VERSION).
inline constexpr const char* version = INFLUENCE2D_VERSION;

}  // namespace influence2d
