// SPDX-License-Identifier: BSL-1.0
// influence2d._core.study: the precision study (verification/study.hpp) of
// the method's decisions and the queries in every number type against the
// exact reference, run with the GIL released; its tables as lists of rows
// (dicts), which the package turns into pandas DataFrames.

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "verification/study.hpp"

namespace influence2d::python {

namespace {

using namespace influence2d::verification;

/// Throws invalid_input naming the first of `given` not in `known`.
void check_names(const std::vector<std::string>& given, const std::vector<std::string>& known, const char* what) {
    for (std::size_t k = 0; k < given.size(); ++k)
        if (std::find(known.begin(), known.end(), given[k]) == known.end()) {
            std::string list;
            for (const std::string& n : known) list += (list.empty() ? "" : ", ") + n;
            throw invalid_input(std::string(what) + "[" + std::to_string(k) + "] is '" + given[k] +
                                "': expected one of " + list);
        }
}

py::object optional_value(const std::optional<double>& x) {
    return x ? py::object(py::float_(*x)) : py::object(py::none());
}

py::dict tables(const study_result& r) {
    py::list decisions, queries, stability, summaries, examples;
    for (const study_row& row : r.rows)
        decisions.append(py::dict(py::arg("number_type") = row.number_type, py::arg("family") = row.family,
                                  py::arg("decision") = row.decision, py::arg("cases") = row.tally.cases,
                                  py::arg("disagreements") = row.tally.disagreements,
                                  py::arg("rate") = row.tally.rate(),
                                  py::arg("ns_per_query") = row.tally.ns_per_query()));
    for (const query_row& row : r.query_rows) {
        const query_tally& t = row.tally;
        queries.append(py::dict(py::arg("number_type") = row.number_type, py::arg("family") = row.family,
                                py::arg("query") = row.query, py::arg("questions") = t.questions,
                                py::arg("differing") = t.differing, py::arg("meeting_differs") = t.meeting_differs,
                                py::arg("features_differ") = t.features_differ,
                                py::arg("values_differ") = t.values_differ, py::arg("measured") = t.errors.size(),
                                py::arg("largest_error") = optional_value(t.largest_error()),
                                py::arg("median_error") = optional_value(t.median_error()),
                                py::arg("ns_per_question") = t.ns_per_question(), py::arg("errors") = t.errors));
    }
    for (const stability_row& row : r.stability)
        stability.append(py::dict(py::arg("number_type") = row.number_type, py::arg("sweep") = row.sweep,
                                  py::arg("magnitude") = row.magnitude, py::arg("cases") = row.tally.cases,
                                  py::arg("disagreements") = row.tally.disagreements,
                                  py::arg("rate") = row.tally.rate()));
    for (const type_summary& s : r.summaries)
        summaries.append(py::dict(py::arg("number_type") = s.number_type, py::arg("claims_exact") = s.claims_exact,
                                  py::arg("has_fallback") = s.has_fallback, py::arg("questions") = s.questions,
                                  py::arg("fallbacks") = s.fallbacks, py::arg("setup_fallbacks") = s.setup_fallbacks,
                                  py::arg("refused_scenes") = s.refused_scenes,
                                  py::arg("refused_query_scenes") = s.refused_query_scenes));
    for (const study_example& e : r.examples)
        examples.append(py::dict(py::arg("number_type") = e.number_type, py::arg("family") = e.family,
                                 py::arg("decision") = e.decision, py::arg("scene") = e.scene,
                                 py::arg("question") = e.question, py::arg("got") = e.got,
                                 py::arg("expected") = e.expected));
    py::dict out;
    out["decisions"] = decisions;
    out["queries"] = queries;
    out["stability"] = stability;
    out["summaries"] = summaries;
    out["examples"] = examples;
    out["cases"] = r.cases;
    out["seconds"] = r.seconds;
    return out;
}

py::dict study(const std::vector<std::string>& families, const std::vector<std::string>& types,
               const std::vector<std::string>& decisions, const std::vector<std::string>& queries, std::size_t cases,
               std::size_t frames, std::size_t query_frames, std::uint64_t seed, std::size_t first_scene,
               std::size_t end_scene) {
    study_options o;
    check_names(families, study_family_names(), "families");
    check_names(types, mode_names(study_modes{}), "types");
    std::vector<std::string> decision_names, query_names;
    for (decision_kind k : all_decision_kinds) decision_names.emplace_back(decision_name(k));
    for (query_kind k : all_query_kinds) query_names.emplace_back(query_name(k));
    check_names(decisions, decision_names, "decisions");
    check_names(queries, query_names, "queries");
    if (cases == 0 || frames == 0) throw invalid_input("cases and frames must be at least 1");
    if (!families.empty()) o.families = families;
    o.types = types;
    for (const std::string& d : decisions) o.decisions.push_back(*decision_from_name(d));
    o.queries.clear();
    for (const std::string& q : queries) o.queries.push_back(*query_from_name(q));
    o.cases = cases;
    o.frames = frames;
    o.query_frames = query_frames;
    o.seed = seed;
    o.first_scene = first_scene;
    o.end_scene = end_scene;
    study_result r;
    {
        py::gil_scoped_release release;
        r = run_study(o);
    }
    return tables(r);
}

}  // namespace

void bind_study(py::module_& m) {
    m.def("study", &study, py::arg("families"), py::arg("types"), py::arg("decisions"), py::arg("queries"),
          py::arg("cases"), py::arg("frames"), py::arg("query_frames"), py::arg("seed"), py::arg("first_scene") = 0,
          py::arg("end_scene") = std::numeric_limits<std::size_t>::max());
    m.def(
        "study_scene_sizes",
        [](const std::string& family, std::size_t cases, std::size_t frames, std::uint64_t seed) {
            check_names({family}, study_family_names(), "families");
            std::vector<std::size_t> sizes;
            {
                py::gil_scoped_release release;
                for (const study_case& c : make_study_cases(family, cases, frames, seed))
                    sizes.push_back(c.a.size() + c.b.size());
            }
            return sizes;
        },
        py::arg("family"), py::arg("cases"), py::arg("frames"), py::arg("seed"));
    m.def("study_names", [] {
        std::vector<std::string> decisions, queries;
        for (decision_kind k : all_decision_kinds) decisions.emplace_back(decision_name(k));
        for (query_kind k : all_query_kinds) queries.emplace_back(query_name(k));
        py::dict d;
        d["families"] = study_family_names();
        d["default_families"] = default_study_families();
        d["types"] = mode_names(study_modes{});
        d["decisions"] = decisions;
        d["queries"] = queries;
        return d;
    });
}

}  // namespace influence2d::python
