// SPDX-License-Identifier: BSL-1.0
#pragma once
// Real layers (data/real): neighbours.wkt, Chile, Argentina, Indonesia and
// Malaysia from Natural Earth's 1:110m map, multipolygons that share their
// border vertices exactly; nc_counties.wkt, North Carolina's 100 counties,
// likewise.

#include <fstream>
#include <string>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/io/wkt.hpp"

namespace test_data {

/// The polygons of data/real/`file`, one per line.
inline std::vector<influence2d::polygon> real_layer(const std::string& file) {
    const std::string path = std::string(INFLUENCE2D_DATA_DIR) + "/real/" + file;
    std::ifstream in(path);
    std::vector<influence2d::polygon> out;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) out.push_back(influence2d::read_wkt(line, path));
    return out;
}

/// The file's polygons, one per line: Chile, Argentina, Indonesia, Malaysia.
inline std::vector<influence2d::polygon> neighbours() { return real_layer("neighbours.wkt"); }

}  // namespace test_data
