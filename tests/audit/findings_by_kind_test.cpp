// SPDX-License-Identifier: BSL-1.0
// The audit's findings kind by kind (include/influence2d/audit/findings_by_kind.hpp):
// one group per kind with its count and first places, and the counts over a
// layer of polygons. The command that prints them: audit_tool_test.cpp.

#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "influence2d/audit/audit.hpp"
#include "influence2d/audit/findings_by_kind.hpp"
#include "influence2d/io/wkt.hpp"
#include "support/findings.hpp"

namespace {

using namespace influence2d;
using test_findings::audit_wkt;

/// A hexagon whose every coordinate is inexact in float, and nothing else.
const char* const inexact_hexagon = "POLYGON((0.1 0.1, 4.1 0.3, 5.3 2.1, 4.1 4.3, 0.1 4.1, -1.3 2.1, 0.1 0.1))";

/// A pentagram: five pairs of edges cross.
const char* const pentagram = "POLYGON((0 0, 2 6, 4 0, -1 4, 5 4, 0 0))";

}  // namespace

TEST_CASE("audit: findings by kind: the report counts every kind, listed or not", "[audit]") {
    audit_options o;
    o.max_per_kind = 2;
    const audit_report r = audit_rings(read_wkt_rings(inexact_hexagon), o);
    CHECK(r.counts[static_cast<std::size_t>(finding_kind::inexact_in_float)] == 6);
    CHECK(r.total == 6);
    CHECK(r.findings.size() == 2);
    std::size_t sum = 0;
    for (std::size_t c : r.counts) sum += c;
    CHECK(sum == r.total);
}

TEST_CASE("audit: findings by kind: a kind at many vertices is one group with its count and first places", "[audit]") {
    const audit_report r = audit_wkt(inexact_hexagon);
    REQUIRE(r.accepted);
    const std::vector<kind_findings> groups = findings_by_kind(r);
    REQUIRE(groups.size() == 1);
    const kind_findings& g = groups[0];
    CHECK(g.kind == finding_kind::inexact_in_float);
    CHECK(g.count == 6);
    REQUIRE(g.first.size() == 3);
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(g.first[i].ring == 0);
        CHECK(g.first[i].vertex == i);
    }
    CHECK(g.what == "a coordinate is not exact in float");
    CHECK(g.effect == r.findings[0].effect);
    CHECK(g.same_text);
    CHECK_FALSE(g.rejects);

    CHECK(findings_by_kind(r, 1).at(0).first.size() == 1);
    CHECK(findings_by_kind(r, 10).at(0).first.size() == 6);
    CHECK(findings_by_kind(audit_wkt("POLYGON((0 0, 4 0, 4 4, 0 4, 0 0))")).empty());
}

TEST_CASE("audit: findings by kind: groups come in the order the checks report them", "[audit]") {
    // A clockwise ring of float-inexact coordinates with a repeated vertex:
    // the vertex checks, then the orientation, then the number ranges.
    const audit_report r = audit_wkt("POLYGON((0.1 0.1, 0.1 4.1, 0.1 4.1, 4.1 4.1, 4.1 0.1, 0.1 0.1))");
    const std::vector<kind_findings> groups = findings_by_kind(r);
    REQUIRE(groups.size() == 3);
    CHECK(groups[0].kind == finding_kind::repeated_vertex);
    CHECK(groups[0].count == 1);
    CHECK(groups[1].kind == finding_kind::reversed_orientation);
    CHECK(groups[2].kind == finding_kind::inexact_in_float);
    CHECK(groups[2].count == 5);
}

TEST_CASE("audit: findings by kind: texts that name their places are not the same", "[audit]") {
    const std::vector<kind_findings> groups = findings_by_kind(audit_wkt(pentagram));
    const kind_findings* crossings = nullptr;
    for (const kind_findings& g : groups)
        if (g.kind == finding_kind::self_intersection) crossings = &g;
    REQUIRE(crossings != nullptr);
    CHECK(crossings->count == 5);
    REQUIRE(crossings->first.size() == 3);
    CHECK_FALSE(crossings->same_text);
    CHECK(crossings->what == crossings->first[0].what);
}

TEST_CASE("audit: findings by kind: a refusing kind, and kinds counted but not listed", "[audit]") {
    const audit_report refused = audit_wkt("POLYGON((0 0, 4 0, nan 4, 0 4, 0 0))");
    const std::vector<kind_findings> groups = findings_by_kind(refused);
    REQUIRE(!groups.empty());
    CHECK(groups[0].kind == finding_kind::non_finite);
    CHECK(groups[0].rejects);

    audit_options none;
    none.max_per_kind = 0;
    const audit_report r = audit_rings(read_wkt_rings(inexact_hexagon), none);
    REQUIRE(r.findings.empty());
    const std::vector<kind_findings> counted = findings_by_kind(r);
    REQUIRE(counted.size() == 1);
    CHECK(counted[0].kind == finding_kind::inexact_in_float);
    CHECK(counted[0].count == 6);
    CHECK(counted[0].first.empty());
    CHECK(counted[0].what.empty());
}

TEST_CASE("audit: findings over a layer: polygons affected and occurrences per kind, verdicts", "[audit]") {
    const std::vector<audit_report> reports = {
        audit_wkt("POLYGON((0 0, 4 0, 4 4, 0 4, 0 0))"),          // clean
        audit_wkt(inexact_hexagon),                               // 6 inexact
        audit_wkt("POLYGON((0 0, 4 0, 4 4, 0 4))"),               // refused: unclosed
        audit_wkt("POLYGON((0 0, 0.1 0, 0.1 0.1, 0 0.1, 0 0))"),  // 3 inexact (the vertices with 0.1)
    };
    const layer_findings t = findings_over_layer(reports);
    CHECK(t.polygons == 4);
    CHECK(t.accepted == 3);
    CHECK(t.refused == 1);
    REQUIRE(t.kinds.size() == 2);
    CHECK(t.kinds[0].kind == finding_kind::unclosed_ring);  // in the order of finding_kind
    CHECK(t.kinds[0].polygons == 1);
    CHECK(t.kinds[0].occurrences == 1);
    CHECK(t.kinds[1].kind == finding_kind::inexact_in_float);
    CHECK(t.kinds[1].polygons == 2);
    CHECK(t.kinds[1].occurrences == 9);

    const layer_findings empty = findings_over_layer({});
    CHECK(empty.polygons == 0);
    CHECK(empty.kinds.empty());
}
