// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// The findings of audits kind by kind: for one polygon, each kind once, with
/// how often it occurs and its first places (a kind found at many vertices,
/// such as inexact_in_float, is one group); for a layer of polygons, each
/// kind with the number of polygons it affects and its occurrences, and how
/// many polygons the library accepts.
///
///     for (const kind_findings& g : findings_by_kind(report))   // g.kind, g.count, g.first
///         ...
///     const layer_findings t = findings_over_layer(reports);    // t.kinds, t.accepted, t.refused

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "influence2d/audit/audit.hpp"

namespace influence2d {

/// The findings of one kind in one audit_report.
struct kind_findings {
    /// A group of kind k with no finding yet.
    explicit kind_findings(finding_kind k) : kind(k) {}
    finding_kind kind;  ///< what the findings are
    /// How many the report has of the kind, listed or not (audit_report::counts).
    std::size_t count = 0;
    /// The first listed findings of the kind, in report order: their places,
    /// points and texts.
    std::vector<finding> first;
    std::string what;    ///< the `what` of the kind's first listed finding ("" when none is listed)
    std::string effect;  ///< the `effect` of the kind's first listed finding ("" when none is listed)
    /// Every listed finding of the kind has the `what` and `effect` above
    /// (false when the texts name their places, or differ otherwise).
    bool same_text = true;
    bool rejects = false;  ///< a listed finding of the kind makes the library refuse the input
};

/// The report's findings grouped by kind: one group for each kind the report
/// counts (audit_report::counts), holding its count and at most `places` of
/// its listed findings. The groups come in the order of each kind's first
/// listed finding, which is the order the checks run (see audit_rings);
/// kinds counted but not listed (audit_options::max_per_kind 0) follow, in
/// the order of finding_kind.
inline std::vector<kind_findings> findings_by_kind(const audit_report& r, std::size_t places = 3) {
    std::vector<kind_findings> groups;
    std::array<bool, finding_kind_count> seen{};
    std::array<std::size_t, finding_kind_count> group_of{};
    for (const finding& f : r.findings) {
        const auto k = static_cast<std::size_t>(f.kind);
        if (k >= finding_kind_count) continue;
        if (!seen[k]) {
            seen[k] = true;
            group_of[k] = groups.size();
            groups.emplace_back(f.kind);
            groups.back().count = r.counts[k];
            groups.back().what = f.what;
            groups.back().effect = f.effect;
        }
        kind_findings& g = groups[group_of[k]];
        if (g.first.size() < places) g.first.push_back(f);
        g.same_text = g.same_text && f.what == g.what && f.effect == g.effect;
        g.rejects = g.rejects || f.rejects;
    }
    for (std::size_t k = 0; k < finding_kind_count; ++k)
        if (!seen[k] && r.counts[k] > 0) {
            groups.emplace_back(static_cast<finding_kind>(k));
            groups.back().count = r.counts[k];
        }
    return groups;
}

/// One kind of finding over the polygons of a layer.
struct layer_kind_count {
    /// The count of kind k over no polygon yet.
    explicit layer_kind_count(finding_kind k) : kind(k) {}
    finding_kind kind;            ///< what the findings are
    std::size_t polygons = 0;     ///< the polygons with at least one finding of the kind
    std::size_t occurrences = 0;  ///< its findings over all the polygons, listed or not
};

/// The audits of a layer's polygons, counted: how many the library accepts
/// and refuses, and each kind found.
struct layer_findings {
    std::size_t polygons = 0;  ///< the polygons audited
    std::size_t accepted = 0;  ///< those the library accepts (audit_report::accepted)
    std::size_t refused = 0;   ///< those it refuses
    /// Every kind found in at least one polygon, in the order of
    /// finding_kind.
    std::vector<layer_kind_count> kinds;
};

/// The counts over the audits of a layer's polygons, one report per polygon
/// (occurrences from audit_report::counts, so findings not listed count too).
inline layer_findings findings_over_layer(const std::vector<audit_report>& reports) {
    layer_findings t;
    std::array<std::size_t, finding_kind_count> polygons{}, occurrences{};
    for (const audit_report& r : reports) {
        ++t.polygons;
        ++(r.accepted ? t.accepted : t.refused);
        for (std::size_t k = 0; k < finding_kind_count; ++k) {
            if (r.counts[k] > 0) ++polygons[k];
            occurrences[k] += r.counts[k];
        }
    }
    for (std::size_t k = 0; k < finding_kind_count; ++k)
        if (polygons[k] > 0) {
            t.kinds.emplace_back(static_cast<finding_kind>(k));
            t.kinds.back().polygons = polygons[k];
            t.kinds.back().occurrences = occurrences[k];
        }
    return t;
}

}  // namespace influence2d
