// SPDX-License-Identifier: BSL-1.0
#pragma once
// The precision study's rows (verification/study.hpp) summed per number type:
// over the final answers, over the predicates, or over any rows chosen.

#include <map>
#include <string>

#include "verification/study.hpp"

namespace influence2d::verification {

/// Sums of the rows that pass `keep`, per number type.
template <class Keep>
std::map<std::string, decision_tally> totals_by_type(const study_result& r, Keep keep) {
    std::map<std::string, decision_tally> t;
    for (const study_row& row : r.rows) {
        if (!keep(row)) continue;
        decision_tally& s = t[row.number_type];
        s.cases += row.tally.cases;
        s.disagreements += row.tally.disagreements;
        s.nanoseconds += row.tally.nanoseconds;
    }
    return t;
}

/// Whether the row counts the final answer, collides.
inline bool asks_collides(const study_row& row) { return row.decision == "collides"; }
/// Whether the row counts one of the predicates (neither detector's final answer).
inline bool asks_predicate(const study_row& row) {
    return row.decision != "collides" && row.decision != "collides_brute_force";
}

}  // namespace influence2d::verification
