// SPDX-License-Identifier: BSL-1.0
// '-' for standard input and standard output, wherever the tool reads one file
// or writes one: the WKT and pose inputs of collide and render, audit's
// polygon, the --out files of collide and render. Standard input is read once,
// so two inputs given as '-' are refused; commands that write a directory of
// files refuse '-'.

#include <catch2/catch.hpp>

#include "support/process.hpp"

#include <filesystem>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using namespace test_process;

namespace {

const char* const unit_square_wkt = "POLYGON((0 0,1 0,1 1,0 1,0 0))\n";
// Overlapping, touching along x = 1, apart.
const char* const poses_text = "tx,ty,theta\n0.5,0,0\n1,0,0\n2.5,0,0\n";
const std::vector<std::string> three_frames{"frame,collides", "0,1", "1,1", "2,0"};

/// `args` with standard input read from `file`.
std::string from(const fs::path& file, const std::string& args) { return args + " <" + quote(file.string()); }

std::string collide(const std::string& a, const std::string& b) { return "collide --static " + a + " --moving " + b; }

}  // namespace

TEST_CASE("cli '-': collide reads either polygon or the poses from standard input", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square_wkt);
    const auto poses = dir.file("poses.csv", poses_text);
    const std::string file_a = quote(a.string()), file_poses = " --poses " + quote(poses.string());

    for (const auto& [what, args, input] : std::vector<std::tuple<std::string, std::string, fs::path>>{
             {"static", collide("-", file_a) + file_poses, a},
             {"moving", collide(file_a, "-") + file_poses, a},
             {"poses", collide(file_a, file_a) + " --poses -", poses}}) {
        INFO(what);
        const auto frames = dir / ("frames_" + what + ".csv");
        const auto r = run_cli(dir, from(input, args + " --out " + quote(frames.string())));
        INFO(r.err);
        REQUIRE(r.exit_code == 0);
        CHECK(r.out.find("collisions:      2\n") != std::string::npos);
        CHECK(lines_of(slurp(frames)) == three_frames);
    }
}

TEST_CASE("cli '-': collide --out - writes the frames to standard output, the summary to standard error", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square_wkt);
    const auto poses = dir.file("poses.csv", poses_text);
    const auto r =
        run_cli(dir, collide(quote(a.string()), quote(a.string())) + " --poses " + quote(poses.string()) + " --out -");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(lines_of(r.out) == three_frames);
    CHECK(r.err.find("collisions:      2\n") != std::string::npos);
    CHECK(r.err.find("frames written:  standard output\n") != std::string::npos);
    CHECK(!fs::exists(dir / "-"));

    // Poses in, frames out: a filter.
    const auto piped = run_cli(dir, from(poses, collide(quote(a.string()), quote(a.string())) + " --poses - --out -"));
    REQUIRE(piped.exit_code == 0);
    CHECK(lines_of(piped.out) == three_frames);
}

TEST_CASE("cli '-': bad input on standard input is named, exit code 2, nothing written", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square_wkt);
    const auto unclosed = dir.file("unclosed.wkt", "POLYGON((0 0,1 0,1 1,0 1))");
    const auto bad_poses = dir.file("bad.csv", "tx,ty,theta\n1,2,3\n1,2,abc\n");
    const auto frames = dir / "frames.csv";

    auto r = run_cli(
        dir, from(unclosed, collide("-", quote(a.string())) + " --poses " +
                                quote(dir.file("p.csv", poses_text).string()) + " --out " + quote(frames.string())));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("influence2d: error: standard input: ring 0 is not closed") != std::string::npos);
    CHECK(r.out.empty());
    CHECK(!fs::exists(frames));

    r = run_cli(dir, from(bad_poses, collide(quote(a.string()), quote(a.string())) + " --poses - --out -"));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("influence2d: error: standard input: line 3, column theta: \"abc\" is not a number") !=
          std::string::npos);
    CHECK(r.out.empty());  // no partial frames on standard output

    r = run_cli(dir, from(dir.file("empty.csv", ""), collide(quote(a.string()), quote(a.string())) + " --poses -"));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("standard input: empty file") != std::string::npos);
}

TEST_CASE("cli '-': two inputs from standard input are refused before anything is read", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square_wkt);
    const auto frames = dir / "frames.csv";
    for (const auto& [args, named] : std::vector<std::pair<std::string, std::string>>{
             {collide("-", "-") + " --trajectory linear", "--static and --moving"},
             {collide("-", quote(a.string())) + " --poses -", "--static and --poses"},
             {collide(quote(a.string()), "-") + " --poses -", "--moving and --poses"},
             {collide("-", "-") + " --poses -", "--static, --moving and --poses"}}) {
        INFO(args);
        for (const std::string& command : {args, "render" + args.substr(std::string("collide").size())}) {
            const auto r = run_cli(
                dir, from(a, command + " --out " + quote((dir / (command[0] == 'r' ? "x.svg" : "x.csv")).string())));
            CHECK(r.exit_code == 2);
            CHECK(r.err.find("influence2d: error: " + named +
                             (named.find(',') == std::string::npos ? " both" : " all") +
                             " name '-', standard input, which can be read only once") != std::string::npos);
            CHECK(r.out.empty());
        }
    }
    CHECK(!fs::exists(dir / "x.csv"));
    CHECK(!fs::exists(dir / "x.svg"));
}

TEST_CASE("cli '-': render reads from standard input and writes the picture to standard output", "[cli][render]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", "POLYGON((0 0,4 0,4 4,0 4,0 0))\n");
    const auto b = dir.file("B.wkt", "POLYGON((0 0,2 0,2 2,0 2,0 0))\n");
    const auto poses = dir.file("poses.csv", "tx,ty,theta\n10,10,0\n1,1,0\n");
    const auto svg = dir / "file.svg";
    const std::string scene = "render --static " + quote(a.string()) + " --moving - --poses " + quote(poses.string());

    const auto to_file = run_cli(dir, from(b, scene + " --out " + quote(svg.string())));
    INFO(to_file.err);
    REQUIRE(to_file.exit_code == 0);
    CHECK(to_file.out.empty());
    CHECK(slurp(svg).find("B: standard input (4 edges)") != std::string::npos);

    const auto to_stdout = run_cli(dir, from(b, scene + " --out -"));
    INFO(to_stdout.err);
    REQUIRE(to_stdout.exit_code == 0);
    CHECK(to_stdout.out == slurp(svg));
    CHECK(!fs::exists(dir / "-"));

    // A bad frame list: nothing on standard output.
    const auto bad = run_cli(dir, from(b, scene + " --frames 5 --out -"));
    CHECK(bad.exit_code == 2);
    CHECK(bad.out.empty());
}

TEST_CASE("cli '-': audit reads the polygon from standard input", "[cli]") {
    const temp_dir dir;
    const auto square = dir.file("square.wkt", unit_square_wkt);
    auto r = run_cli(dir, from(square, "audit -"));
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.out.rfind("standard input: polygon 0 (line 1): 1 ring(s), 4 vertices", 0) == 0);

    r = run_cli(dir, from(square, "audit - --json -"));
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("\"file\": \"standard input\"") != std::string::npos);
    CHECK(r.out.find("\"accepted\": true") != std::string::npos);

    r = run_cli(dir, from(dir.file("bad.wkt", "POLYGON((0 0,1 0"), "audit -"));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("influence2d: error: standard input: ") != std::string::npos);
}

TEST_CASE("cli '-': commands that write a directory of files refuse --out -", "[cli]") {
    const temp_dir dir;
    for (const char* command : {"generate --sizes 8 --out -", "generate-stiff --count 1 --out -",
                                "study --families convex --types double --cases 1 --frames 1 --out -"}) {
        INFO(command);
        const auto r = run_cli(dir, command);
        CHECK(r.exit_code == 2);
        CHECK(r.err.find("influence2d: error: --out -: this command writes several files into a directory") !=
              std::string::npos);
        CHECK(r.out.empty());
    }
    const auto r = run_cli(dir, "study --families convex --types double --cases 1 --frames 1 --out " +
                                    quote((dir / "study").string()) + " --regressions -");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--regressions -: reproducible cases are files in a directory") != std::string::npos);
    CHECK(!fs::exists(dir / "study"));
}
