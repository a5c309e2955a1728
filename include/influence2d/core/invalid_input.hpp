// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The exception for input the library cannot interpret.

#include <stdexcept>

namespace influence2d {

/// Raised for input the library cannot interpret: by polygon's constructor,
/// the readers and writers in io/, detectors given polygons they do not take
/// (an empty polygon, several rings without features::holes) and poses with
/// a NaN or infinite component. `what()` names the place (ring and vertex,
/// the pose's component); the readers prefix the file or source name.
class invalid_input : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace influence2d
