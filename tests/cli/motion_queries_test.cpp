// SPDX-License-Identifier: BSL-1.0
// The tool's queries beyond yes or no: `collide --continuous` (a square
// jumping across a thin wall between two poses is caught), `collide
// --separation` (the column equals the library's certified separation,
// written to 17 digits), `sweep` (CONTACTS.csv, the same contact in every
// number type), `collide --static-poses` (both polygons moving: the frames
// of the relative poses), `--motion rational` (turning motions exactly, the
// library's answer) and their refusals (exit 2, a message naming the
// place, no output file).

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/distance/separation.hpp"
#include "influence2d/exact/certified_first_contact.hpp"
#include "influence2d/exact/certified_separation.hpp"
#include "influence2d/io/csv.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "support/process.hpp"

using namespace influence2d;
using namespace test_process;

namespace {

const std::string data_dir = INFLUENCE2D_DATA_DIR;

const char* wall_wkt = "POLYGON((-0.05 -5, 0.05 -5, 0.05 5, -0.05 5, -0.05 -5))";
const char* square_wkt = "POLYGON((-1 -1, 1 -1, 1 1, -1 1, -1 -1))";
/// The square jumps from x = -3 to x = 3 across the wall (13/40 of the way
/// its right side reaches the wall's left side), then moves and turns clear.
const char* jump_csv = "tx,ty,theta\n-3,0,0\n3,0,0\n3,8,0.5\n";

std::string poses_csv(const std::vector<pose>& poses) {
    std::ostringstream s;
    write_poses_csv(s, poses);
    return s.str();
}

std::string seventeen(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

}  // namespace

TEST_CASE("cli: collide --continuous catches a square jumping across a wall", "[cli][sweep]") {
    const temp_dir dir;
    const auto wall = dir.file("wall.wkt", wall_wkt), square = dir.file("square.wkt", square_wkt);
    const auto poses = dir.file("poses.csv", jump_csv);
    const std::string common = "collide --static " + quote(wall.string()) + " --moving " + quote(square.string()) +
                               " --poses " + quote(poses.string()) + " --threads 1";
    for (const char* type : {"double", "long-double", "exact", "certified", "interval"}) {
        INFO(type);
        const run_result sampled = run_cli(dir, common + " --number-type " + type);
        REQUIRE(sampled.exit_code == 0);
        CHECK(sampled.out.find("collisions:      0\n") != std::string::npos);
        const run_result swept =
            run_cli(dir, common + " --number-type " + type + " --continuous --out " + quote((dir / "f.csv").string()));
        REQUIRE(swept.exit_code == 0);
        CHECK(swept.out.find("collisions:      1\n") != std::string::npos);
        CHECK(swept.out.find("first collision: frame 1\n") != std::string::npos);
        CHECK(swept.out.find("between poses:   1 frames") != std::string::npos);
        CHECK(slurp(dir / "f.csv") == "frame,collides,contact_t\n0,0,\n1,1," + seventeen(13.0 / 40) + "\n2,0,\n");
    }
}

TEST_CASE("cli: sweep writes the first contact of every motion", "[cli][sweep]") {
    const temp_dir dir;
    const auto wall = dir.file("wall.wkt", wall_wkt), square = dir.file("square.wkt", square_wkt);
    const auto poses = dir.file("poses.csv", jump_csv);
    const std::string common = "sweep --static " + quote(wall.string()) + " --moving " + quote(square.string()) +
                               " --poses " + quote(poses.string());
    for (const char* type : {"double", "exact", "certified", "interval", "quad"}) {
        INFO(type);
        const run_result r =
            run_cli(dir, common + " --number-type " + type + " --out " + quote((dir / "c.csv").string()));
        REQUIRE(r.exit_code == 0);
        CHECK(r.out.find("motions:         2\ncontacts:        1\nfirst contact:   motion 0 at t = " +
                         seventeen(13.0 / 40)) != std::string::npos);
        // The square's right side reaches the wall's left edge (e3) with both
        // its ends at once; the lower one (v1) is reported.
        CHECK(slurp(dir / "c.csv") ==
              "motion,contact,t,static_feature,moving_feature\n0,1," + seventeen(13.0 / 40) + ",e3,v1\n1,0,,,\n");
    }
    const run_result to_stdout = run_cli(dir, common + " --out -");
    REQUIRE(to_stdout.exit_code == 0);
    CHECK(to_stdout.out.rfind("motion,contact,t,static_feature,moving_feature\n", 0) == 0);
    CHECK(to_stdout.err.find("contacts:        1") != std::string::npos);
}

TEST_CASE("cli: sweep and collide --continuous --motion rational answer turning motions exactly", "[cli][sweep]") {
    const temp_dir dir;
    const char* bar_wkt = "POLYGON((-0.1 -2.5, 0.1 -2.5, 0.1 2.5, -0.1 2.5, -0.1 -2.5))";
    const char* far_wall_wkt = "POLYGON((2 -5, 3 -5, 3 5, 2 5, 2 -5))";
    const auto wall = dir.file("wall.wkt", far_wall_wkt), bar = dir.file("bar.wkt", bar_wkt);
    const std::vector<pose> turns = {{0, 0, 0}, {0.2, 0, -1}};
    const auto poses = dir.file("poses.csv", poses_csv(turns));
    // The library's answer: the bar's top reaches the wall's left side
    // while it turns by -1 radian.
    const polygon a = read_wkt(far_wall_wkt), b = read_wkt(bar_wkt);
    const sweep_options rational{1e-9, turning_model::rational};
    const contact_result<double> want = certified_first_contact(a, b, turns[0], turns[1], rational);
    REQUIRE(want.contact);
    const std::string common =
        "--static " + quote(wall.string()) + " --moving " + quote(bar.string()) + " --poses " + quote(poses.string());
    for (const char* type : {"exact", "certified", "interval", "double"}) {
        INFO(type);
        const run_result r = run_cli(dir, "sweep " + common + " --number-type " + type + " --motion rational --out " +
                                              quote((dir / "c.csv").string()));
        REQUIRE(r.exit_code == 0);
        CHECK(r.out.find("turning motion:  rational\n") != std::string::npos);
        const std::string csv = slurp(dir / "c.csv");
        if (std::string(type) != "double")
            CHECK(csv == "motion,contact,t,static_feature,moving_feature\n0,1," + seventeen(want.time) + ",e3,v2\n");
        else
            CHECK(csv.find("\n0,1,") != std::string::npos);  // (its time rounds)
        const run_result c =
            run_cli(dir, "collide " + common + " --number-type " + type +
                             " --threads 1 --continuous --motion rational --out " + quote((dir / "f.csv").string()));
        REQUIRE(c.exit_code == 0);
        if (std::string(type) != "double")
            CHECK(slurp(dir / "f.csv") == "frame,collides,contact_t\n0,0,\n1,1," + seventeen(want.time) + "\n");
    }
    // The angle-linear model answers within its tolerance: another time.
    const run_result linear = run_cli(dir, "sweep " + common + " --number-type exact --out -");
    REQUIRE(linear.exit_code == 0);
    CHECK(linear.out.find("0,1," + seventeen(want.time)) == std::string::npos);
}

TEST_CASE("cli: sweep and collide --continuous report a motion left undecided at --max-steps", "[cli][sweep]") {
    // A unit square slides 1.04e-9 above the top of a 4 x 4 square (notched
    // below, so not convex) while turning by 1e-12, just beyond where the
    // probes stop: conservative advancement would take billions of steps
    // (tests/motion/first_contact_test.cpp); the library's own answer at
    // 1,000 steps is the tool's.
    const temp_dir dir;
    const char* a_wkt = "POLYGON((0 0, 1.5 0, 1.5 1, 2.5 1, 2.5 0, 4 0, 4 4, 0 4, 0 0))";
    const char* b_wkt = "POLYGON((-0.5 -0.5, 0.5 -0.5, 0.5 0.5, -0.5 0.5, -0.5 -0.5))";
    const auto a_file = dir.file("a.wkt", a_wkt), b_file = dir.file("b.wkt", b_wkt);
    const std::vector<pose> motion = {{-2, 4.5 + 1.04e-9, 0}, {6, 4.5 + 1.04e-9, 1e-12}};
    const auto poses = dir.file("poses.csv", poses_csv(motion));
    sweep_options o;
    o.max_steps = 1000;
    const contact_result<double> want =
        certified_first_contact(read_wkt(a_wkt), read_wkt(b_wkt), motion[0], motion[1], o);
    REQUIRE(want.step_limit);
    const std::string common = "--static " + quote(a_file.string()) + " --moving " + quote(b_file.string()) +
                               " --poses " + quote(poses.string()) + " --max-steps 1000 --number-type certified";
    const run_result r = run_cli(dir, "sweep " + common + " --out " + quote((dir / "c.csv").string()));
    REQUIRE(r.exit_code == 0);
    CHECK(slurp(dir / "c.csv") ==
          "motion,contact,t,static_feature,moving_feature\n0,limit," + seventeen(want.time) + ",,\n");
    CHECK(r.out.find("step limit:      1 motion undecided after --max-steps 1000 steps") != std::string::npos);
    const run_result c = run_cli(dir, "collide " + common + " --continuous --out " + quote((dir / "f.csv").string()));
    REQUIRE(c.exit_code == 0);
    CHECK(slurp(dir / "f.csv") == "frame,collides,contact_t\n0,0,\n1,0,limit\n");
    CHECK(c.out.find("step limit:      1 motion") != std::string::npos);
    // Without the option the default limit (100,000 steps) stops it too.
    const run_result d = run_cli(dir, "sweep --static " + quote(a_file.string()) + " --moving " +
                                          quote(b_file.string()) + " --poses " + quote(poses.string()) + " --out -");
    REQUIRE(d.exit_code == 0);
    CHECK(d.out.find("\n0,limit,") != std::string::npos);
}

TEST_CASE("cli: sweep and collide --continuous refuse what they cannot answer", "[cli][sweep][input]") {
    const temp_dir dir;
    const auto wall = dir.file("wall.wkt", wall_wkt), square = dir.file("square.wkt", square_wkt);
    const std::string scene = "--static " + quote(wall.string()) + " --moving " + quote(square.string());
    const fs::path out = dir / "c.csv";
    const auto one = dir.file("one.csv", "tx,ty,theta\n1,2,0\n");
    const auto nan = dir.file("nan.csv", "tx,ty,theta\n1,2,0\n3,nan,0\n");
    const auto unclosed = dir.file("unclosed.wkt", "POLYGON((0 0, 1 0, 1 1");
    struct refusal {
        std::string args, message;
    };
    const std::vector<refusal> refusals = {
        {"sweep " + scene + " --poses " + quote(one.string()), "one.csv: 1 pose: a motion needs two"},
        {"sweep " + scene + " --poses " + quote(nan.string()), "nan.csv: line 3, column ty"},
        {"sweep --static " + quote(unclosed.string()) + " --moving " + quote(square.string()) + " --poses " +
             quote(nan.string()),
         "unclosed.wkt"},
        {"collide " + scene + " --poses " + quote(nan.string()) + " --continuous --distance 0.5",
         "--continuous asks whether the polygons meet between poses"},
        {"collide " + scene + " --trajectory linear --continuous --algorithm paper", "not --algorithm paper"},
        {"collide " + scene + " --trajectory linear --separation --algorithm paper", "not --algorithm paper"},
        {"sweep " + scene + " --poses " + quote(one.string()) + " --motion spiral", "--motion: Check spiral value"},
        {"collide " + scene + " --trajectory linear --motion rational", "--motion requires --continuous"},
        {"collide " + scene + " --trajectory linear --max-steps 10", "--max-steps requires --continuous"},
        {"sweep " + scene + " --poses " + quote(one.string()) + " --max-steps -1", "--max-steps"},
    };
    for (const refusal& r : refusals) {
        INFO(r.args);
        const run_result run = run_cli(dir, r.args + " --out " + quote(out.string()));
        CHECK(run.exit_code == 2);
        CHECK(run.err.find(r.message) != std::string::npos);
        CHECK(!fs::exists(out));
    }
}

TEST_CASE("cli: collide --separation writes the certified separation of every pose", "[cli][separation]") {
    const temp_dir dir;
    const std::string a = data_dir + "/families/hole_64.wkt", b = data_dir + "/families/irregular_16.wkt";
    const polygon pa = read_wkt_file(a), pb = read_wkt_file(b);
    const std::vector<pose> poses = random_poses(pa, pb, 60, 30, 110, 5);
    const auto poses_file = dir.file("poses.csv", poses_csv(poses));
    // The poses as the tool reads them back (17 digits: the same doubles).
    for (const char* type : {"certified", "exact", "double"}) {
        INFO(type);
        const run_result r = run_cli(dir, "collide --static " + quote(a) + " --moving " + quote(b) + " --poses " +
                                              quote(poses_file.string()) + " --separation --witness --number-type " +
                                              type + " --out " + quote((dir / "f.csv").string()));
        REQUIRE(r.exit_code == 0);
        CHECK(r.out.find("least separation: ") != std::string::npos);
        const std::vector<std::string> lines = lines_of(slurp(dir / "f.csv"));
        REQUIRE(lines.size() == poses.size() + 1);
        CHECK(lines[0] == "frame,collides,edges,separation,closest");
        std::size_t apart = 0;
        for (std::size_t k = 0; k < poses.size(); ++k) {
            const certified_separation_result s = certified_separation(pa, pb, poses[k]);
            std::istringstream row(lines[k + 1]);
            std::string frame, collides, edges, separation, closest;
            std::getline(row, frame, ',');
            std::getline(row, collides, ',');
            std::getline(row, edges, ',');
            std::getline(row, separation, ',');
            std::getline(row, closest, ',');
            INFO("frame " << k << ": " << lines[k + 1]);
            CHECK(collides == (s.meet ? "1" : "0"));
            if (std::string(type) == "double") {
                CHECK(std::stod(separation) == Approx(s.distance).margin(1e-12));
            } else {
                CHECK(separation == seventeen(s.distance));
                if (!s.meet) CHECK(closest.find(':') != std::string::npos);
            }
            apart += s.meet ? 0 : 1;
        }
        CHECK(apart > 5);
        CHECK(apart < poses.size());
    }
}

TEST_CASE("cli: collide --static-poses moves both polygons", "[cli][static-poses]") {
    const temp_dir dir;
    const std::string a = data_dir + "/families/contour_64.wkt", b = data_dir + "/families/starred_32.wkt";
    const polygon pa = read_wkt_file(a), pb = read_wkt_file(b);
    // Both polygons translated (and B turned): the relative pose is B's
    // translation minus A's, exact in double for these grid values.
    const std::vector<pose> relative = random_poses(pa, pb, 80, 20, 110, 9);
    std::vector<pose> a_poses, b_poses;
    for (std::size_t k = 0; k < relative.size(); ++k) {
        const double sx = std::ldexp(std::round(std::ldexp(static_cast<double>(k) * 3.5 - 100, 10)), -10);
        const double rx = std::ldexp(std::round(std::ldexp(relative[k].tx, 20)), -20);
        const double ry = std::ldexp(std::round(std::ldexp(relative[k].ty, 20)), -20);
        a_poses.push_back({sx, -sx, 0});
        b_poses.push_back({sx + rx, -sx + ry, relative[k].theta});
        REQUIRE(b_poses.back().tx - sx == rx);
        REQUIRE(b_poses.back().ty + sx == ry);
    }
    const auto a_file = dir.file("a_poses.csv", poses_csv(a_poses));
    const auto b_file = dir.file("b_poses.csv", poses_csv(b_poses));
    std::vector<pose> rel;
    for (const pose& p : b_poses)
        rel.push_back({p.tx - a_poses[rel.size()].tx, p.ty - a_poses[rel.size()].ty, p.theta});
    const auto rel_file = dir.file("rel.csv", poses_csv(rel));
    const std::string scene = "collide --static " + quote(a) + " --moving " + quote(b) + " --threads 1";
    const run_result reference =
        run_cli(dir, scene + " --poses " + quote(rel_file.string()) + " --number-type certified --out " +
                         quote((dir / "rel_frames.csv").string()));
    REQUIRE(reference.exit_code == 0);
    const std::string expected = slurp(dir / "rel_frames.csv");
    CHECK(expected.find(",1\n") != std::string::npos);
    CHECK(expected.find(",0\n") != std::string::npos);
    for (const char* type : {"exact", "certified", "interval", "double"}) {
        INFO(type);
        const run_result both =
            run_cli(dir, scene + " --poses " + quote(b_file.string()) + " --static-poses " + quote(a_file.string()) +
                             " --number-type " + type + " --out " + quote((dir / "both.csv").string()));
        REQUIRE(both.exit_code == 0);
        CHECK(slurp(dir / "both.csv") == expected);
    }
    // One pose too few, and an exact type asked for witnesses: refused.
    std::vector<pose> fewer(a_poses.begin(), a_poses.end() - 1);
    const auto fewer_file = dir.file("fewer.csv", poses_csv(fewer));
    const fs::path out = dir / "refused.csv";
    const run_result short_run = run_cli(dir, scene + " --poses " + quote(b_file.string()) + " --static-poses " +
                                                  quote(fewer_file.string()) + " --out " + quote(out.string()));
    CHECK(short_run.exit_code == 2);
    CHECK(short_run.err.find("fewer.csv: 79 poses of the static polygon for 80") != std::string::npos);
    const run_result witness =
        run_cli(dir, scene + " --poses " + quote(b_file.string()) + " --static-poses " + quote(a_file.string()) +
                         " --number-type exact --witness --out " + quote(out.string()));
    CHECK(witness.exit_code == 2);
    CHECK(witness.err.find("answers yes or no only") != std::string::npos);
    CHECK(!fs::exists(out));
}
