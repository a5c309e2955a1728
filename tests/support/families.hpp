// SPDX-License-Identifier: BSL-1.0
#pragma once
// The family polygons of data/families (verification/families.hpp): each
// committed file read once and kept for the rest of the run.

#include <map>
#include <string>

#include "influence2d/core/polygon.hpp"
#include "influence2d/io/wkt.hpp"
#include "verification/families.hpp"

namespace test_families {

using influence2d::verification::family;

/// The path of data/families/<id>.wkt, id as in "convex_16".
inline std::string path(const std::string& id) {
    return std::string(INFLUENCE2D_DATA_DIR) + "/families/" + id + ".wkt";
}

/// The polygon of data/families/<id>.wkt, read on first use.
inline const influence2d::polygon& load(const std::string& id) {
    static std::map<std::string, influence2d::polygon> cache;
    auto it = cache.find(id);
    if (it == cache.end()) it = cache.emplace(id, influence2d::read_wkt_file(path(id))).first;
    return it->second;
}

/// The committed polygon of family f with n vertices.
inline const influence2d::polygon& load(family f, std::size_t n) {
    return load(influence2d::verification::family_name(f) + "_" + std::to_string(n));
}

}  // namespace test_families
