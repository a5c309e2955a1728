// SPDX-License-Identifier: BSL-1.0
#pragma once
// The text of the studies' reports: numbers in a fixed or a general format,
// rates as percentages, lists of names, the median that summarises repeated
// timings.

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace influence2d::verification {

/// x with `digits` digits after the point.
inline std::string fixed(double x, int digits) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << x;
    return s.str();
}

/// x with `digits` significant digits.
inline std::string general(double x, int digits = 6) {
    std::ostringstream s;
    s.precision(digits);
    s << x;
    return s.str();
}

/// A rate as a percentage with 3 significant digits ("0" for none).
inline std::string percent(double rate) {
    if (rate == 0) return "0";
    return general(100 * rate, 3) + "%";
}

/// The names joined by commas.
inline std::string joined(const std::vector<std::string>& names) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ",") + n;
    return list;
}

/// Whether `name` is one of `names`.
inline bool has_name(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

/// The median of some values (0 for none).
inline double median_of(std::vector<double> v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

}  // namespace influence2d::verification
