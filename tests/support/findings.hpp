// SPDX-License-Identifier: BSL-1.0
#pragma once
// The audit's findings of a polygon given as WKT, and those of one kind.

#include <string>
#include <vector>

#include "influence2d/audit/audit.hpp"
#include "influence2d/io/wkt.hpp"

namespace test_findings {

inline influence2d::audit_report audit_wkt(const std::string& wkt) {
    return influence2d::audit_rings(influence2d::read_wkt_rings(wkt));
}

/// The findings of one kind.
inline std::vector<influence2d::finding> of(const influence2d::audit_report& r, influence2d::finding_kind k) {
    std::vector<influence2d::finding> out;
    for (const influence2d::finding& f : r.findings)
        if (f.kind == k) out.push_back(f);
    return out;
}

}  // namespace test_findings
