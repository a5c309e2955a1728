// SPDX-License-Identifier: BSL-1.0
#pragma once
// The precision study's advice on choosing a number type: which type was the
// fastest, how often each answered wrongly and at what cost, which types with
// no wrong answer are still not exact, and the fastest type with no
// disagreement, from the totals of a run (verification/study_totals.hpp).

#include <algorithm>
#include <string>
#include <vector>

#include "verification/report_text.hpp"
#include "verification/study.hpp"
#include "verification/study_totals.hpp"

namespace influence2d::verification {

/// The paragraph on choosing a number type, from the totals of the run.
inline std::string number_type_advice(const study_result& r) {
    const auto collides = totals_by_type(r, asks_collides);
    const auto predicates = totals_by_type(r, asks_predicate);
    const auto all = totals_by_type(r, [](const study_row&) { return true; });
    const auto ns = [&](const std::string& t) { return collides.at(t).ns_per_query(); };
    std::vector<const type_summary*> asked;
    for (const type_summary& t : r.summaries)
        if (collides.count(t.number_type) && collides.at(t.number_type).cases > 0) asked.push_back(&t);
    if (asked.empty()) return "No collision question was asked in this run.\n";
    const type_summary* fastest = *std::min_element(
        asked.begin(), asked.end(), [&](auto* x, auto* y) { return ns(x->number_type) < ns(y->number_type); });
    const auto times = [&](const std::string& t) {
        return general(ns(t) / std::max(ns(fastest->number_type), 1e-9), 3) + " times " + fastest->number_type;
    };
    const decision_tally& f = collides.at(fastest->number_type);
    std::string s = "For the final answer (collides) the fastest type was " + fastest->number_type + ", at " +
                    fixed(f.ns_per_query(), 0) + " ns per frame; it answered " + std::to_string(f.disagreements) +
                    " of " + std::to_string(f.cases) + " frames wrongly (" + percent(f.rate()) + ").";
    std::string sound_floats;
    for (const type_summary* t : asked) {
        if (t == fastest || t->claims_exact) continue;
        const decision_tally& c = collides.at(t->number_type);
        s += " " + t->number_type + ": " + percent(c.rate()) + " wrong at " + fixed(c.ns_per_query(), 0) + " ns (" +
             times(t->number_type) + ").";
        if (c.disagreements == 0 && predicates.count(t->number_type))  // (predicates asked)
            sound_floats += (sound_floats.empty() ? "" : ", ") + t->number_type + " (" +
                            percent(predicates.at(t->number_type).rate()) + ")";
    }
    if (!sound_floats.empty())
        s += " The floating types with no wrong final answer in this run are still not exact: their predicates "
             "disagreed with the reference on a share of the questions: " +
             sound_floats + "; more precision moves the cliff closer to contact, it does not remove it.";
    const type_summary* fastest_exact = nullptr;
    for (const type_summary* t : asked) {
        if (!t->claims_exact) continue;
        const decision_tally& a = all.at(t->number_type);
        s += " " + t->number_type + " (claims exactness): " + fixed(ns(t->number_type), 0) + " ns per frame (" +
             times(t->number_type) + ")";
        if (t->fallbacks > 0)
            s += ", " + percent(static_cast<double>(t->fallbacks) / static_cast<double>(t->questions)) +
                 " of its questions answered in its exact fallback";
        s += a.disagreements == 0 ? ", no disagreement."
                                  : ", " + std::to_string(a.disagreements) +
                                        " disagreements: library bugs, kept as reproducible cases (below).";
        if (a.disagreements == 0 && (!fastest_exact || ns(t->number_type) < ns(fastest_exact->number_type)))
            fastest_exact = t;
    }
    if (fastest_exact)
        s += " The fastest type with no disagreement on any decision was " + fastest_exact->number_type + ".";
    s += " The inputs are aimed at the precision cliff (contacts within ulps, points on cone boundaries, extreme "
         "offsets and scales), so the rates are those of near-degenerate work, far above those of typical frames; "
         "a filtered type's cost grows with the share of such inputs. Choose a floating type where a wrong answer "
         "within rounding of contact is acceptable, and the fastest type without disagreement where it is not.";
    return s + "\n";
}

}  // namespace influence2d::verification
