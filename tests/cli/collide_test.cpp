// SPDX-License-Identifier: BSL-1.0
// `influence2d collide`, run as a separate process on files in a temporary directory.

#include <catch2/catch.hpp>

#include "support/process.hpp"

#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace test_process;

namespace {

const char* const unit_square = "POLYGON((0 0,1 0,1 1,0 1,0 0))\n";
// Overlapping, touching along x = 1, apart.
const char* const three_poses = "tx,ty,theta\n0.5,0,0\n1,0,0\n2.5,0,0\n";

std::string scene_args(const fs::path& a, const fs::path& b) {
    return "collide --static " + quote(a.string()) + " --moving " + quote(b.string());
}

}  // namespace

TEST_CASE("cli collide: poses file gives a frames file with header and one row per pose", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square);
    const auto poses = dir.file("poses.csv", three_poses);
    const auto frames = dir / "frames.csv";

    const auto r =
        run_cli(dir, scene_args(a, a) + " --poses " + quote(poses.string()) + " --out " + quote(frames.string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
    CHECK(r.out.find("frames:          3\n") != std::string::npos);
    CHECK(r.out.find("collisions:      2\n") != std::string::npos);
    CHECK(r.out.find("first collision: frame 0\n") != std::string::npos);
    CHECK(r.out.find("number type:     double\n") != std::string::npos);
    CHECK(r.out.find("algorithm:       sound\n") != std::string::npos);
    CHECK(r.out.find("time per frame:  ") != std::string::npos);
    const auto lines = lines_of(slurp(frames));
    REQUIRE(lines.size() == 4);
    CHECK(lines[0] == "frame,collides");
    CHECK(lines[1] == "0,1");
    CHECK(lines[2] == "1,1");
    CHECK(lines[3] == "2,0");
    CHECK(!fs::exists(frames.string() + ".tmp"));
}

TEST_CASE("cli collide: trajectories give the requested number of frames", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", "POLYGON((0 0,10 0,10 10,0 10,0 0))");
    const auto b = dir.file("B.wkt", "POLYGON((0 0,2 0,1 2,0 0))");
    const auto frames = dir / "frames.csv";

    auto r = run_cli(dir, scene_args(a, b) + " --trajectory linear --trajectory-frames 40 --witness --out " +
                              quote(frames.string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    auto lines = lines_of(slurp(frames));
    REQUIRE(lines.size() == 41);
    CHECK(lines[0] == "frame,collides,edges");
    CHECK(lines[1] == "0,0,");               // starts apart
    CHECK(lines[40].rfind("39,1", 0) == 0);  // ends in collision

    r = run_cli(dir, scene_args(a, b) + " --trajectory circular --trajectory-frames 64 --gap 1 --out " +
                         quote(frames.string()));
    REQUIRE(r.exit_code == 0);
    lines = lines_of(slurp(frames));
    REQUIRE(lines.size() == 65);
    CHECK(r.out.find("collisions:      0\n") != std::string::npos);
    CHECK(r.out.find("first collision: none\n") != std::string::npos);
}

TEST_CASE("cli collide: the tiny scene for every number type with sound and brute-force", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square);
    const auto poses = dir.file("poses.csv", three_poses);
    const auto frames = dir / "frames.csv";
    const std::regex pair_list(R"(\d+:\d+(;\d+:\d+)*)");
    for (const char* type : {"float", "double", "long-double", "quad", "exact", "certified", "interval"}) {
        for (const char* algorithm : {"sound", "brute-force"}) {
            for (const bool witness : {false, true}) {
                INFO(type << " " << algorithm << (witness ? " --witness" : ""));
                const auto r = run_cli(dir, scene_args(a, a) + " --poses " + quote(poses.string()) + " --number-type " +
                                                type + " --algorithm " + algorithm + (witness ? " --witness" : "") +
                                                " --out " + quote(frames.string()));
                INFO(r.err);
                REQUIRE(r.exit_code == 0);
                CHECK(r.out.find(std::string("number type:     ") + type + "\n") != std::string::npos);
                CHECK(r.out.find(std::string("algorithm:       ") + algorithm + "\n") != std::string::npos);
                // Only the filtered types report their exact fallbacks.
                const bool filtered = std::string(type) == "certified" || std::string(type) == "interval";
                CHECK((r.out.find("exact fallbacks: ") != std::string::npos) == filtered);
                const auto lines = lines_of(slurp(frames));
                REQUIRE(lines.size() == 4);
                if (!witness) {
                    CHECK(lines[0] == "frame,collides");
                    CHECK(lines[1] == "0,1");
                    CHECK(lines[2] == "1,1");
                    CHECK(lines[3] == "2,0");
                    continue;
                }
                CHECK(lines[0] == "frame,collides,edges");
                REQUIRE(lines[1].rfind("0,1,", 0) == 0);
                CHECK(std::regex_match(lines[1].substr(4), pair_list));
                // Touching along x = 1: static edges 0 (bottom), 1 (right), 2 (top)
                // meet moving edges 0 (bottom), 2 (top), 3 (left, on x = 1).
                CHECK(lines[2] == "1,1,0:0;0:3;1:0;1:2;1:3;2:2;2:3");
                CHECK(lines[3] == "2,0,");
            }
        }
    }
}

TEST_CASE("cli collide: the paper's algorithm runs", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square);
    const auto poses = dir.file("poses.csv", three_poses);
    for (const char* shape : {"capsule", "band"}) {
        const auto r = run_cli(dir, scene_args(a, a) + " --poses " + quote(poses.string()) +
                                        " --algorithm paper --extended-area " + shape);
        INFO(r.err);
        CHECK(r.exit_code == 0);
        CHECK(r.out.find("algorithm:       paper\n") != std::string::npos);
    }
}

TEST_CASE("cli collide: certified counts its exact fallbacks, and the paper's algorithm refuses it", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square);
    const auto poses = dir.file("poses.csv", three_poses);
    const auto frames = dir / "frames.csv";
    const std::regex fallbacks(R"(exact fallbacks: (\d+) frames\n)");
    for (const char* algorithm : {"sound", "brute-force"}) {
        INFO(algorithm);
        auto r =
            run_cli(dir, scene_args(a, a) + " --poses " + quote(poses.string()) +
                             " --number-type certified --algorithm " + algorithm + " --out " + quote(frames.string()));
        INFO(r.err);
        REQUIRE(r.exit_code == 0);
        std::smatch m;
        REQUIRE(std::regex_search(r.out, m, fallbacks));
        // Frames 0 (overlapping along the bottom and top edges, collinear) and
        // 1 (touching along x = 1) decide exact zeros, but of translations
        // whose posed coordinates are doubles: certified knows them exactly
        // and settles those zeros in double (orientation_of_doubles).
        CHECK(std::stoi(m[1].str()) == 0);
        CHECK(lines_of(slurp(frames)) == std::vector<std::string>{"frame,collides", "0,1", "1,1", "2,0"});

        // Turned by a quarter (cos is 6e-17 in double, sin 1): moved by (2, 0)
        // the corner (0, 1) lands on (1, 6e-17), on A's side x = 1; moved by
        // (2, 1) the side from (1, 1 + 6e-17) to (2, 1) passes above A's
        // corner (1, 1) by 6e-17. The posed coordinates are rounded, their
        // exact zeros are in doubt, and each frame is answered again
        // exactly. (Squares turned onto A itself, overlapping, are settled
        // in double: the separating-edge test sees the other square's inner
        // disc reach across every edge.)
        const auto turned = dir.file("turned.csv", "tx,ty,theta\n2,0,1.5707963267948966\n2,1,1.5707963267948966\n");
        r = run_cli(dir, scene_args(a, a) + " --poses " + quote(turned.string()) +
                             " --number-type certified --algorithm " + algorithm + " --out " + quote(frames.string()));
        REQUIRE(r.exit_code == 0);
        REQUIRE(std::regex_search(r.out, m, fallbacks));
        CHECK(std::stoi(m[1].str()) == 2);
        CHECK(lines_of(slurp(frames)) == std::vector<std::string>{"frame,collides", "0,1", "1,0"});

        // Frames apart and turned decide nothing in doubt: no fallback.
        const auto apart = dir.file("apart.csv", "tx,ty,theta\n5,0.3,0.25\n0.2,-7,1\n");
        r = run_cli(dir, scene_args(a, a) + " --poses " + quote(apart.string()) +
                             " --number-type certified --algorithm " + algorithm);
        REQUIRE(r.exit_code == 0);
        CHECK(r.out.find("exact fallbacks: 0 frames\n") != std::string::npos);
        CHECK(r.out.find("collisions:      0\n") != std::string::npos);
    }

    for (const char* type : {"certified", "interval"}) {
        const auto r = run_cli(dir, scene_args(a, a) + " --poses " + quote(poses.string()) + " --number-type " + type +
                                        " --algorithm paper --out " + quote(frames.string()));
        CHECK(r.exit_code == 2);
        CHECK(r.err.find(std::string("influence2d: error: --number-type ") + type + " cannot run --algorithm paper") !=
              std::string::npos);
        CHECK(r.out.empty());
    }
    CHECK(!fs::exists(frames.string() + ".tmp"));
}

TEST_CASE("cli collide: bad WKT exits 2 naming the place and writes no output file", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square);
    const auto bad = dir.file("bad.wkt", "POLYGON((0 0,1 0,1 1,0 1))");
    const auto poses = dir.file("poses.csv", three_poses);
    const auto frames = dir / "frames.csv";
    const auto r =
        run_cli(dir, scene_args(a, bad) + " --poses " + quote(poses.string()) + " --out " + quote(frames.string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("influence2d: error: " + bad.string() + ": ring 0 is not closed") != std::string::npos);
    CHECK(r.out.empty());
    CHECK(!fs::exists(frames));
    CHECK(!fs::exists(frames.string() + ".tmp"));
}

TEST_CASE("cli collide: bad CSV exits 2 leaving the output untouched and reports every error", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square);
    const auto bad_wkt = dir.file("bad.wkt", "POLYGON((0 0,1 0,nan 1,0 0))");
    const auto poses = dir.file("poses.csv", "tx,ty,theta\n1,2,3\n1,2,abc\n");
    const auto frames = dir.file("frames.csv", "previous content\n");

    auto r = run_cli(dir, scene_args(a, a) + " --poses " + quote(poses.string()) + " --out " + quote(frames.string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("influence2d: error: " + poses.string() + ": line 3, column theta: \"abc\" is not a number") !=
          std::string::npos);
    CHECK(slurp(frames) == "previous content\n");
    CHECK(!fs::exists(frames.string() + ".tmp"));

    // Every bad input is reported in one run.
    r = run_cli(dir, scene_args(bad_wkt, a) + " --poses " + quote(poses.string()) + " --out " + quote(frames.string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(bad_wkt.string() + ": ring 0, vertex 2: coordinate is not a finite number") != std::string::npos);
    CHECK(r.err.find(poses.string() + ": line 3") != std::string::npos);
    CHECK(slurp(frames) == "previous content\n");

    // A missing poses file and an output directory that does not exist.
    r = run_cli(dir, scene_args(a, a) + " --poses " + quote((dir / "none.csv").string()) + " --out " +
                         quote((dir / "no_dir" / "f.csv").string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("none.csv: cannot open file") != std::string::npos);
    CHECK(r.err.find("does not exist") != std::string::npos);
    CHECK(!fs::exists(dir / "no_dir"));
}

TEST_CASE("cli collide: usage errors exit 2", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", unit_square);
    const auto poses = dir.file("poses.csv", three_poses);
    const std::string base = scene_args(a, a);
    const std::string p = " --poses " + quote(poses.string());
    CHECK(run_cli(dir, "").exit_code == 2);                                    // no subcommand
    CHECK(run_cli(dir, base).exit_code == 2);                                  // no poses
    CHECK(run_cli(dir, base + p + " --trajectory linear").exit_code == 2);     // both
    CHECK(run_cli(dir, base + p + " --trajectory-frames 10").exit_code == 2);  // frames w/o trajectory
    CHECK(run_cli(dir, base + " --trajectory spiral").exit_code == 2);
    CHECK(run_cli(dir, base + " --trajectory linear --trajectory-frames 0").exit_code == 2);
    CHECK(run_cli(dir, base + p + " --distance -1").exit_code == 2);
    CHECK(run_cli(dir, base + p + " --distance nan").exit_code == 2);
    CHECK(run_cli(dir, base + p + " --distance inf").exit_code == 2);
    CHECK(run_cli(dir, base + p + " --number-type int").exit_code == 2);
    CHECK(run_cli(dir, base + p + " --algorithm fast").exit_code == 2);
    CHECK(run_cli(dir, base + p + " --extended-area disk").exit_code == 2);
    CHECK(run_cli(dir, "collide --moving " + quote(a.string()) + p).exit_code == 2);
    // And the same arguments with a valid distance succeed.
    CHECK(run_cli(dir, base + p + " --distance 0.25").exit_code == 0);
}

TEST_CASE("cli collide: --help exits 0 and documents every option", "[cli]") {
    const temp_dir dir;
    const auto r = run_cli(dir, "collide --help");
    CHECK(r.exit_code == 0);
    for (const char* option :
         {"--static",        "--moving",      "--poses",     "--trajectory",    "--trajectory-frames",
          "--gap",           "--number-type", "--algorithm", "--extended-area", "--distance",
          "--witness",       "--out",         "circular",    "linear",          "float",
          "long-double",     "quad",          "exact",       "certified",       "interval",
          "exact fallbacks", "brute-force",   "paper",       "capsule",         "band"}) {
        INFO(option);
        CHECK(r.out.find(option) != std::string::npos);
    }
    const auto top = run_cli(dir, "--help");
    CHECK(top.exit_code == 0);
    CHECK(top.out.find("collide") != std::string::npos);
    CHECK(top.out.find("generate") != std::string::npos);
}

TEST_CASE("cli collide: --frames, the old name of --trajectory-frames, still works with a warning", "[cli]") {
    const temp_dir dir;
    const auto a = dir.file("A.wkt", "POLYGON((0 0,10 0,10 10,0 10,0 0))");
    const auto b = dir.file("B.wkt", "POLYGON((0 0,2 0,1 2,0 0))");
    const auto old_name = run_cli(dir, scene_args(a, b) + " --trajectory linear --frames 40");
    INFO(old_name.err);
    REQUIRE(old_name.exit_code == 0);
    CHECK(old_name.out.find("frames:          40\n") != std::string::npos);
    CHECK(old_name.err.find("influence2d: warning: --frames is the old name of --trajectory-frames") !=
          std::string::npos);
    const auto new_name = run_cli(dir, scene_args(a, b) + " --trajectory linear --trajectory-frames 40");
    REQUIRE(new_name.exit_code == 0);
    CHECK(new_name.err.empty());
    CHECK(new_name.out.find("frames:          40\n") != std::string::npos);
    // Not both, not without a trajectory, and out of the help.
    CHECK(run_cli(dir, scene_args(a, b) + " --trajectory linear --frames 40 --trajectory-frames 40").exit_code == 2);
    CHECK(run_cli(dir, scene_args(a, b) + " --poses " + quote(dir.file("p.csv", three_poses).string()) + " --frames 3")
              .exit_code == 2);
    CHECK(run_cli(dir, "collide --help").out.find("--frames") == std::string::npos);
}

TEST_CASE("cli collide: the help of --number-type lists every type with its answers", "[cli]") {
    const temp_dir dir;
    const auto r = run_cli(dir, "collide --help");
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("TYPE:{float,double,long-double,quad,exact,certified,interval}=double") != std::string::npos);
    for (const char* rounded : {"float", "double", "long-double", "quad"}) {
        INFO(rounded);
        CHECK(r.out.find(std::string(rounded) + " (rounded answers): ") != std::string::npos);
    }
    for (const char* exact : {"exact", "certified", "interval"}) {
        INFO(exact);
        CHECK(r.out.find(std::string(exact) + " (exact answers): ") != std::string::npos);
    }
    CHECK(r.out.find("certified and interval (exact fallback) run with --algorithm sound or brute-force only") !=
          std::string::npos);
}

TEST_CASE("cli collide: far from 1 in scale every type answers as certified (the scene scaled into range)", "[cli]") {
    // A wall and a square at 2^-599: clearly apart, overlapping, far apart.
    // Unscaled, double's products underflow and it reported the first pose
    // as a collision.
    const temp_dir dir;
    const auto a =
        dir.file("A.wkt", "POLYGON((0 -3.0e-180,6.1e-182 -3.0e-180,6.1e-182 3.0e-180,0 3.0e-180,0 -3.0e-180))\n");
    const auto b = dir.file("B.wkt",
                            "POLYGON((-6.1e-181 -6.1e-181,6.1e-181 -6.1e-181,6.1e-181 6.1e-181,-6.1e-181 6.1e-181,"
                            "-6.1e-181 -6.1e-181))\n");
    const auto poses =
        dir.file("poses.csv", "tx,ty,theta\n-6.5e-181,3e-181,0.01\n-6.0e-181,3e-181,0.01\n-5e-180,0,0\n");
    for (const char* type : {"double", "float", "long-double", "quad", "certified"}) {
        INFO(type);
        const auto r = run_cli(
            dir, scene_args(a, b) + " --poses " + quote(poses.string()) + " --number-type " + type + " --out -");
        CHECK(r.exit_code == 0);
        CHECK(r.out == "frame,collides\n0,0\n1,1\n2,0\n");
    }
}
