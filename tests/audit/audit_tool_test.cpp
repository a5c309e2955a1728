// SPDX-License-Identifier: BSL-1.0
// The audit seen from outside the library: `influence2d audit`'s text, JSON
// and exit codes, and polygons GEOS calls valid getting no self-intersection.

#include <catch2/catch.hpp>

#include <string>

#include <nlohmann/json.hpp>

#include "influence2d/audit/audit.hpp"
#include "support/findings.hpp"
#include "support/process.hpp"

#if INFLUENCE2D_HAVE_GEOS
#include <geos_c.h>
#endif

namespace {

using namespace influence2d;
using test_findings::audit_wkt;
using test_findings::of;
using test_process::quote;
using test_process::run_cli;
using test_process::slurp;
using test_process::temp_dir;

}  // namespace

TEST_CASE("audit: the command, its text, JSON and exit codes", "[audit][cli]") {
    const temp_dir dir;
    const auto bow = dir.file("bow.wkt", "POLYGON((0 0, 4 4, 4 0, 0 4, 0 0))\n");
    const auto r = run_cli(dir, "audit " + quote(bow.string()) + " --json " + quote((dir / "bow.json").string()));
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("self_intersection") != std::string::npos);
    CHECK(r.out.find("ring 0, vertex 0 / ring 0, vertex 2") != std::string::npos);
    const auto j = nlohmann::json::parse(slurp(dir / "bow.json"));
    CHECK(j["accepted"] == true);
    bool bow_crossing = false;  // the bow tie also has zero area
    for (const auto& f : j["findings"])
        bow_crossing = bow_crossing || (f["kind"] == "self_intersection" && f["vertex"] == 0 && f["other_vertex"] == 2);
    CHECK(bow_crossing);

    const auto nan = dir.file("nan.wkt", "POLYGON((0 0, 4 0, nan 4, 0 4, 0 0))\n");
    const auto refused = run_cli(dir, "audit " + quote(nan.string()) + " --json -");
    CHECK(refused.exit_code == 1);
    const auto k = nlohmann::json::parse(refused.out);
    CHECK(k["accepted"] == false);
    CHECK(k["findings"][0]["kind"] == "non_finite");

    const auto bad = dir.file("bad.wkt", "POLYGON((0 0, 4 0, 4 4\n");
    const auto unreadable = run_cli(dir, "audit " + quote(bad.string()));
    CHECK(unreadable.exit_code == 2);
    CHECK(unreadable.err.find("bad.wkt") != std::string::npos);
    CHECK(run_cli(dir, "audit " + quote((dir / "missing.wkt").string())).exit_code == 2);
}

#if INFLUENCE2D_HAVE_GEOS
TEST_CASE("audit: a repeated vertex is not a self-intersection, and GEOS-valid polygons get none", "[audit][geos]") {
    // Edges on either side of a zero-length edge share its point by
    // construction. Every polygon here is valid for GEOS.
    GEOSContextHandle_t ctx = GEOS_init_r();
    GEOSWKTReader* reader = GEOSWKTReader_create_r(ctx);
    const char* valid[] = {
        "POLYGON((0 0, 4 0, 4 0, 4 4, 0 4, 0 0))",
        "POLYGON((0 0, 4 0, 4 0, 4 0, 4 4, 0 4, 0 4, 0 0))",
        "POLYGON((0 0, 0 0, 4 0, 4 4, 0 4, 0 0))",
        "POLYGON((0 0, 4 0, 4 4, 0 4, 0 0, 0 0))",
        "POLYGON((0 0, 4 0, 2 0.5, 2 0.5, 4 4, 0 4, 0 0))",
        "POLYGON((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 2, 4 2, 4 4, 2 4, 2 2))",
        "MULTIPOLYGON(((0 0, 1 0, 1 1, 0 0)), ((1 1, 2 1, 2 2, 2 2, 1 1)))",
    };
    for (const char* text : valid) {
        INFO(text);
        GEOSGeometry* g = GEOSWKTReader_read_r(ctx, reader, text);
        REQUIRE(g != nullptr);
        CHECK(GEOSisValid_r(ctx, g) == 1);
        GEOSGeom_destroy_r(ctx, g);
        const audit_report r = audit_wkt(text);
        CHECK(r.accepted);
        CHECK(of(r, finding_kind::self_intersection).empty());
    }
    GEOSWKTReader_destroy_r(ctx, reader);
    GEOS_finish_r(ctx);
}
#endif  // INFLUENCE2D_HAVE_GEOS
