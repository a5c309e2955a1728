// SPDX-License-Identifier: BSL-1.0
#pragma once
// Real neighbours (data/real/neighbours.wkt): Chile, Argentina, Indonesia and
// Malaysia from Natural Earth's 1:110m map, multipolygons that share their
// border vertices exactly.

#include <fstream>
#include <string>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/io/wkt.hpp"

namespace test_data {

/// The file's polygons, one per line: Chile, Argentina, Indonesia, Malaysia.
inline std::vector<influence2d::polygon> neighbours() {
    const std::string path = std::string(INFLUENCE2D_DATA_DIR) + "/real/neighbours.wkt";
    std::ifstream in(path);
    std::vector<influence2d::polygon> out;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) out.push_back(influence2d::read_wkt(line, path));
    return out;
}

}  // namespace test_data
