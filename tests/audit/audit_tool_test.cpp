// SPDX-License-Identifier: BSL-1.0
// The audit seen from outside the library: `influence2d audit`'s text, JSON
// and exit codes, on one polygon and on a layer of them (a summary line per
// polygon, its findings grouped by kind, the table of kinds, the same output
// on any number of threads), and polygons GEOS calls valid getting no
// self-intersection.

#include <catch2/catch.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

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
using test_process::lines_of;
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
    REQUIRE(j["polygons"].size() == 1);
    bool bow_crossing = false;  // the bow tie also has zero area
    for (const auto& g : j["polygons"][0]["findings"])
        for (const auto& f : g["first"])
            bow_crossing =
                bow_crossing || (g["kind"] == "self_intersection" && f["vertex"] == 0 && f["other_vertex"] == 2);
    CHECK(bow_crossing);

    const auto nan = dir.file("nan.wkt", "POLYGON((0 0, 4 0, nan 4, 0 4, 0 0))\n");
    const auto refused = run_cli(dir, "audit " + quote(nan.string()) + " --json -");
    CHECK(refused.exit_code == 1);
    const auto k = nlohmann::json::parse(refused.out);
    CHECK(k["accepted"] == false);
    CHECK(k["polygons"][0]["accepted"] == false);
    CHECK(k["polygons"][0]["findings"][0]["kind"] == "non_finite");

    const auto bad = dir.file("bad.wkt", "POLYGON((0 0, 4 0, 4 4\n");
    const auto unreadable = run_cli(dir, "audit " + quote(bad.string()));
    CHECK(unreadable.exit_code == 2);
    CHECK(unreadable.err.find("bad.wkt") != std::string::npos);
    CHECK(run_cli(dir, "audit " + quote((dir / "missing.wkt").string())).exit_code == 2);
}

namespace {

/// Three polygons on lines 1, 3 and 4: one clean, one whose six vertices are
/// all inexact in float, one refused (its ring is not closed).
const char* const three_polygons =
    "POLYGON((0 0, 4 0, 4 4, 0 4, 0 0))\n"
    "\n"
    "POLYGON((0.1 0.1, 4.1 0.3, 5.3 2.1, 4.1 4.3, 0.1 4.1, -1.3 2.1, 0.1 0.1))\n"
    "POLYGON((0 0, 4 0, 4 4, 0 4))\n";

/// The lines of `text` that contain `words`.
std::size_t lines_with(const std::string& text, const std::string& words) {
    std::size_t n = 0;
    for (const std::string& line : lines_of(text)) n += line.find(words) != std::string::npos ? 1 : 0;
    return n;
}

}  // namespace

TEST_CASE("audit: a layer, a summary per polygon, each kind once with its count, the table", "[audit][cli]") {
    const temp_dir dir;
    const auto layer = dir.file("layer.wkt", three_polygons);
    const std::string n = layer.string();
    const auto r = run_cli(dir, "audit " + quote(n) + " --json " + quote((dir / "layer.json").string()));
    INFO(r.err);
    CHECK(r.exit_code == 1);  // one polygon refused
    const std::vector<std::string> want = {
        n + ": polygon 0 (line 1): 1 ring(s), 4 vertices, 0 finding(s); accepted",
        n + ": polygon 1 (line 3): 1 ring(s), 6 vertices, 6 finding(s); accepted",
        n + ": polygon 1: inexact_in_float, 6 times, at ring 0, vertex 0; ring 0, vertex 1; ring 0, vertex 2; ...: "
            "a coordinate is not exact in float",
        "    -> float mode rounds it: its answers are for a moved vertex",
        n + ": polygon 2 (line 4): 1 ring(s), 4 vertices, 1 finding(s); refused: ring is not closed: last point (0 "
            "4) differs from the first (0 0)",
        n + ": polygon 2: unclosed_ring, once, at ring 0, vertex 3: ring is not closed: last point (0 4) differs "
            "from the first (0 0)",
        "    -> refused",
        n + ": 3 polygon(s): 2 accepted, 1 refused; findings by kind:",
        "    kind              polygons  occurrences",
        "    unclosed_ring            1            1",
        "    inexact_in_float         1            6",
    };
    CHECK(lines_of(r.out) == want);
    CHECK(lines_with(r.out, "not exact in float") == 1);  // six vertices, one line

    const auto j = nlohmann::json::parse(slurp(dir / "layer.json"));
    CHECK(j["file"] == n);
    CHECK(j["accepted"] == false);
    REQUIRE(j["polygons"].size() == 3);
    for (std::size_t k = 0; k < 3; ++k) CHECK(j["polygons"][k]["index"] == k);
    CHECK(j["polygons"][0]["line"] == 1);
    CHECK(j["polygons"][0]["findings"].empty());
    const auto& p = j["polygons"][1];
    CHECK(p["line"] == 3);
    CHECK(p["last_line"] == 3);
    CHECK(p["rings"] == 1);
    CHECK(p["vertices"] == 6);
    CHECK(p["total"] == 6);
    CHECK(p["accepted"] == true);
    CHECK_FALSE(p.contains("rejection"));
    REQUIRE(p["findings"].size() == 1);
    const auto& g = p["findings"][0];
    CHECK(g["kind"] == "inexact_in_float");
    CHECK(g["count"] == 6);
    CHECK(g["what"] == "a coordinate is not exact in float");
    CHECK(g["effect"] == "float mode rounds it: its answers are for a moved vertex");
    CHECK(g["same_text"] == true);
    CHECK(g["rejects"] == false);
    REQUIRE(g["first"].size() == 3);
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(g["first"][i]["ring"] == 0);
        CHECK(g["first"][i]["vertex"] == i);
        CHECK(g["first"][i]["at"].size() == 2);
    }
    CHECK(g["first"][0]["at"][0] == 0.1);
    const auto& refused = j["polygons"][2];
    CHECK(refused["accepted"] == false);
    CHECK(refused["rejection"] == "ring is not closed: last point (0 4) differs from the first (0 0)");
    CHECK(refused["findings"][0]["kind"] == "unclosed_ring");
    CHECK(refused["findings"][0]["rejects"] == true);
    const auto& t = j["layer"];
    CHECK(t["polygons"] == 3);
    CHECK(t["accepted"] == 2);
    CHECK(t["refused"] == 1);
    REQUIRE(t["kinds"].size() == 2);
    CHECK(t["kinds"][0] == nlohmann::json{{"kind", "unclosed_ring"}, {"polygons", 1}, {"occurrences", 1}});
    CHECK(t["kinds"][1] == nlohmann::json{{"kind", "inexact_in_float"}, {"polygons", 1}, {"occurrences", 6}});

    // --json -: the same JSON on standard output, instead of the lines.
    const auto to_stdout = run_cli(dir, "audit " + quote(n) + " --json -");
    CHECK(to_stdout.exit_code == 1);
    CHECK(nlohmann::json::parse(to_stdout.out) == j);
}

TEST_CASE("audit: a layer's exit codes, and a bad line named", "[audit][cli]") {
    const temp_dir dir;
    const auto clean = dir.file("clean.wkt",
                                "POLYGON((0 0, 4 0, 4 4, 0 4, 0 0))\n"
                                "POLYGON((0.1 0.1, 4.1 0.3, 5.3 2.1, 4.1 4.3, 0.1 4.1, -1.3 2.1, 0.1 0.1))\n");
    const auto ok = run_cli(dir, "audit " + quote(clean.string()));
    INFO(ok.err);
    CHECK(ok.exit_code == 0);  // findings, none refused
    const auto lines = lines_of(ok.out);
    REQUIRE(lines.size() >= 3);
    CHECK(lines[lines.size() - 3] == clean.string() + ": 2 polygon(s): 2 accepted, 0 refused; findings by kind:");
    CHECK(lines.back() == "    inexact_in_float         1            6");

    const auto bad = dir.file("bad.wkt",
                              "POLYGON((0 0, 4 0, 4 4, 0 4, 0 0))\n"
                              "\n"
                              "POLYGON((0 0, 4 0, 4 4\n"
                              "POLYGON((0 0, 4 0, 4 4, 0 4))\n"
                              "POINT(1 2)\n");
    const auto json = dir / "bad.json";
    const auto unreadable = run_cli(dir, "audit " + quote(bad.string()) + " --json " + quote(json.string()));
    CHECK(unreadable.exit_code == 2);
    CHECK(unreadable.out.empty());
    CHECK_FALSE(std::filesystem::exists(json));
    // The bad geometry on line 3 is polygon 1; POINT on line 5 continues polygon 2 (lines 4-5).
    CHECK(unreadable.err.find("influence2d: error: " + bad.string() + ": polygon 1 (line 3): parse error") !=
          std::string::npos);
    CHECK(unreadable.err.find(bad.string() + ": polygon 2 (lines 4-5): parse error") != std::string::npos);
    CHECK(unreadable.err.find("polygon 0") == std::string::npos);

    const auto empty = run_cli(dir, "audit " + quote(dir.file("empty.wkt", "\n  \n").string()));
    CHECK(empty.exit_code == 2);
    CHECK(empty.err.find("empty input") != std::string::npos);
}

TEST_CASE("audit: a geometry over several lines is one polygon, a keyword line starts the next", "[audit][cli]") {
    const temp_dir dir;
    const auto file = dir.file("multi.wkt",
                               "MULTIPOLYGON(\n"
                               "  ((0 0, 4 0, 4 4, 0 4, 0 0)),\n"
                               "\n"
                               "  ((10 10, 11 10, 11 11, 10 10)))\n"
                               "polygon ((0 0, 1 0, 1 1, 0 0))\n");
    const auto r = run_cli(dir, "audit " + quote(file.string()));
    INFO(r.err);
    CHECK(r.exit_code == 0);
    const auto lines = lines_of(r.out);
    REQUIRE(lines.size() == 3);
    CHECK(lines[0] == file.string() + ": polygon 0 (lines 1-4): 2 ring(s), 7 vertices, 0 finding(s); accepted");
    CHECK(lines[1] == file.string() + ": polygon 1 (line 5): 1 ring(s), 3 vertices, 0 finding(s); accepted");
    CHECK(lines[2] == file.string() + ": 2 polygon(s): 2 accepted, 0 refused; no finding");
}

TEST_CASE("audit: the same output on one thread and on several", "[audit][cli]") {
    const temp_dir dir;
    std::string text;
    for (int k = 0; k < 30; ++k) {
        const std::string s = std::to_string(k);
        switch (k % 4) {
        case 0: text += "POLYGON((0 0, " + s + ".1 0, " + s + ".1 4, 0 4, 0 0))\n"; break;
        case 1: text += "POLYGON((0 0, 4 4, 4 0, 0 4, 0 0))\n\n"; break;
        case 2: text += "POLYGON((0 0, 4 0, " + s + " 4, 0 4))\n"; break;
        default: text += "MULTIPOLYGON(((0 0, 9 0, 9 9, 0 9, 0 0)), ((1 1, 2 1, 2 2, 1 2, 1 1)))\n"; break;
        }
    }
    const auto file = dir.file("many.wkt", text);
    std::vector<test_process::run_result> runs;
    for (const char* threads : {"1", "2", "3", "0"}) {
        runs.push_back(run_cli(dir, "audit " + quote(file.string()) + " --threads " + threads));
        runs.push_back(run_cli(dir, "audit " + quote(file.string()) + " --json - --threads " + threads));
    }
    REQUIRE(runs[0].exit_code == 1);
    CHECK(lines_with(runs[0].out, ": polygon ") > 30);
    CHECK(nlohmann::json::parse(runs[1].out)["polygons"].size() == 30);
    for (std::size_t i = 2; i < runs.size(); ++i) {
        INFO("run " << i);
        CHECK(runs[i].exit_code == 1);
        CHECK(runs[i].out == runs[i % 2].out);
    }
    CHECK(run_cli(dir, "audit " + quote(file.string()) + " --threads -1").exit_code == 2);
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
