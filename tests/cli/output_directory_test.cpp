// SPDX-License-Identifier: BSL-1.0
// The commands that write a directory of files (generate, generate-stiff,
// study) write only where --out says: it is required, a bad argument or an
// --out that is not a directory is named, exit code 2, and nothing is written.

#include <catch2/catch.hpp>

#include "support/process.hpp"

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace test_process;

TEST_CASE("cli output directory: generate, generate-stiff and study require --out", "[cli]") {
    const temp_dir dir;
    for (const char* command : {"generate", "generate-stiff", "study --quick"}) {
        INFO(command);
        const auto r = run_cli(dir, command);
        CHECK(r.exit_code == 2);
        CHECK(r.err.find("--out is required") != std::string::npos);
        CHECK(r.out.empty());
    }
    const auto help = run_cli(dir, "study --help");
    CHECK(help.out.find("default: OUT/regressions") != std::string::npos);
}

TEST_CASE("cli output directory: generate writes the families into --out only", "[cli]") {
    const temp_dir dir;
    const auto out = dir / "families";
    const auto r = run_cli(dir, "generate --sizes 8,16 --out " + quote(out.string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out ==
          "generate: wrote 10 files (5 families x 2 sizes, 120 vertices, seed 20040202) to " + out.string() + "\n");
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(out)) {
        CHECK(entry.path().extension() == ".wkt");
        ++files;
    }
    CHECK(files == 10);
    // The bytes of the committed files, for the default seed.
    CHECK(slurp(out / "convex_8.wkt") == slurp(fs::path(INFLUENCE2D_DATA_DIR) / "families" / "convex_8.wkt"));
}

TEST_CASE("cli output directory: a bad argument or an --out that is a file: exit code 2, nothing written", "[cli]") {
    const temp_dir dir;
    const auto file = dir.file("taken", "a file\n");
    for (const char* command : {"generate --sizes 8 --out ", "generate-stiff --count 1 --out ",
                                "study --families convex --types double --cases 1 --frames 2 --out "}) {
        INFO(command);
        const auto r = run_cli(dir, command + quote(file.string()));
        CHECK(r.exit_code == 2);
        CHECK(r.err.find("influence2d: error: " + file.string() +
                         ": exists and is not a directory; --out names the output directory") != std::string::npos);
        CHECK(r.out.empty());
        CHECK(slurp(file) == "a file\n");
    }

    const auto out = dir / "out";
    for (const char* command :
         {"generate --sizes 8,4 --out ", "generate-stiff --count 0 --out ", "study --types double,decimal --out ",
          "study --families convex,round --out ", "study --decisions collides,guess --out "}) {
        INFO(command);
        const auto r = run_cli(dir, command + quote(out.string()));
        CHECK(r.exit_code == 2);
        CHECK(!r.err.empty());
        CHECK(r.out.empty());
        CHECK(!fs::exists(out));
    }
}
