// SPDX-License-Identifier: BSL-1.0
#pragma once
// Shared pieces of the benchmarks: the number types measured, their names,
// and the polygon families read once.

#include <map>
#include <string>

#include "influence2d/core/polygon.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/multiprecision.hpp"

namespace influence2d::bench {

/// data/families/<id>.wkt, read once.
inline const polygon& family(const std::string& id) {
    static std::map<std::string, polygon> cache;
    auto it = cache.find(id);
    if (it == cache.end())
        it = cache.emplace(id, read_wkt_file(std::string(INFLUENCE2D_DATA_DIR) + "/families/" + id + ".wkt")).first;
    return it->second;
}

/// The name a number type goes by in benchmark names (no spaces).
template <class NT>
std::string type_name() {
    std::string n = number_traits<NT>::name;
    for (char& c : n)
        if (c == ' ') c = '-';
    return n;
}

template <class NT>
struct type_tag {
    using type = NT;
};

/// Calls f(type_tag<NT>{}) for every number type measured: the floating types,
/// then the certified, interval and exact ones.
template <class F>
void for_each_number_type(F&& f) {
    f(type_tag<float>{});
    f(type_tag<double>{});
    f(type_tag<long double>{});
    f(type_tag<quad>{});
#ifdef INFLUENCE2D_HAS_FLOAT128
    f(type_tag<float128>{});
#endif
    f(type_tag<certified>{});
    f(type_tag<interval>{});
    f(type_tag<exact_rational>{});
}

}  // namespace influence2d::bench
