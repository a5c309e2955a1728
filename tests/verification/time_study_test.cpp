// SPDX-License-Identifier: BSL-1.0
// The time study (verification/time_study.hpp, `influence2d bench`): every
// method runs on the same frames of each cell, influence2d's modes agree with
// the reference on every frame, a peer's strided frames are counted, the
// largest cell gets its peak heap per method; the command writes its tables
// and heat maps and names bad arguments.

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/process.hpp"
#include "verification/time_study.hpp"

namespace {

namespace fs = std::filesystem;
using namespace influence2d;
using namespace influence2d::verification;
using test_process::lines_of;
using test_process::quote;
using test_process::run_cli;
using test_process::slurp;
using test_process::temp_dir;

}  // namespace

TEST_CASE("time study: every method on the same frames, answers against the reference", "[verification][bench]") {
    time_study_options o;
    o.types = {"convex", "contour"};
    o.sizes = {8, 32};
    o.circular_frames = 400;
    o.linear_frames = 200;
    o.budget = 0.002;
    o.memory_frames = 10;
    const time_study_result r = run_time_study(o);

    std::map<std::string, std::set<std::string>> methods_per_cell;
    for (const time_row& row : r.rows) {
        const std::string cell = row.cell.type + "/" + row.cell.trajectory + "/" + std::to_string(row.cell.static_size) +
                                 "x" + std::to_string(row.cell.moving_size);
        INFO(cell << " " << row.method);
        methods_per_cell[cell].insert(row.method);
        CHECK(row.trajectory_frames == (row.cell.trajectory == "circular" ? 400u : 200u));
        CHECK(row.frames == (row.trajectory_frames + row.stride - 1) / row.stride);  // every stride-th frame
        CHECK(row.seconds > 0);
        if (is_own_method(row.method) && row.method != "exact") CHECK(row.stride == 1);  // all frames, in order
        if (row.method == "double" || row.method == "exact") CHECK(row.disagreements == 0);
        CHECK(row.reference == (row.method == "certified"));
        if (row.cell.trajectory == "circular" && row.method == "certified") CHECK(row.collisions == 0);
        if (row.cell.trajectory == "linear" && row.method == "certified") CHECK(row.collisions > 0);
    }
    CHECK(methods_per_cell.size() == 2 * 2 * 2 * 2);
    for (const auto& [cell, methods] : methods_per_cell) {
        INFO(cell);
        // Box2D takes only the convex 8-gons; every other method every cell.
        const bool box2d = method_available("box2d") && cell.rfind("convex/", 0) == 0 &&
                           cell.find("/8x8") != std::string::npos;
        CHECK(methods.size() == time_study_methods().size() - (box2d || !method_available("box2d") ? 0 : 1));
        CHECK(methods.count("box2d") == (box2d ? 1u : 0u));
    }
    // The paper-literal variant's false answers show as disagreements.
    std::size_t paper_wrong = 0;
    for (const time_row& row : r.rows)
        if (row.method == "paper") paper_wrong += row.disagreements;
    CHECK(paper_wrong > 0);

    REQUIRE(r.memory.size() == time_study_methods().size() - 1);  // the largest cell: convex 32x32, no Box2D
    for (const memory_row& m : r.memory) {
        INFO(m.method);
        CHECK(m.cell.static_size == 32);
        CHECK(m.frames > 0);
        if (m.method != "box2d") CHECK(m.peak_bytes > 0);
    }
}

TEST_CASE("time study: the command writes the table, the summary and the heat maps", "[verification][bench][cli]") {
    const temp_dir dir;
    const auto r = run_cli(dir, "bench --quick --types convex --sizes 8,16 --trajectories linear --out " +
                                    quote((dir / "out").string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("## Targets") != std::string::npos);
    const std::vector<std::string> csv = lines_of(slurp(dir / "out" / "bench.csv"));
    REQUIRE(!csv.empty());
    CHECK(csv.front() ==
          "type,trajectory,static,moving,method,trajectory_frames,frames,stride,passes,total_seconds,ns_per_frame,"
          "collisions,disagreements");
    // 4 cells, every method but Box2D in each, Box2D in 8x8.
    CHECK(csv.size() == 1 + 4 * (time_study_methods().size() - 1) + 1);
    const std::string md = slurp(dir / "out" / "bench.md");
    CHECK(md.find("## Speed-up of the double mode over the fastest peer") != std::string::npos);
    CHECK(md.find("## Peak heap memory") != std::string::npos);
    if (std::system("command -v gnuplot > /dev/null 2>&1") == 0)
        CHECK(slurp(dir / "out" / "heatmap_double.png").substr(1, 3) == "PNG");
}

TEST_CASE("time study: bad arguments are named, exit code 2", "[verification][bench][cli]") {
    const temp_dir dir;
    const std::string out = " --out " + quote((dir / "out").string());
    const auto bad_size = run_cli(dir, "bench --sizes 8,100" + out);
    CHECK(bad_size.exit_code == 2);
    CHECK(bad_size.err.find("100") != std::string::npos);
    const auto bad_method = run_cli(dir, "bench --methods double,pivot2d" + out);
    CHECK(bad_method.exit_code == 2);
    CHECK(bad_method.err.find("pivot2d") != std::string::npos);
    CHECK(run_cli(dir, "bench --trajectories spiral" + out).exit_code == 2);
    CHECK(!fs::exists(dir / "out" / "bench.csv"));
}
