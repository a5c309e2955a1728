// SPDX-License-Identifier: BSL-1.0
// The tool's commands on many polygons: `world` (bodies moved step by step:
// the contacts of a hand-made scene, and of a random one against the exact
// two-pose intersects of every pair) and `pairs` (a layer of touching
// squares, two layers, a distance); --threads 2 writes what --threads 1
// does; and their refusals (exit 2, a message naming the file and the line,
// no output file).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "influence2d/io/wkt.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/query/both_posed.hpp"
#include "support/process.hpp"
#include "support/random.hpp"

using namespace influence2d;
using namespace test_process;

namespace {

const std::string world_data_dir = INFLUENCE2D_DATA_DIR;

/// Shape 0 a unit square, shape 1 a 2 x 1 rectangle, after a blank line
/// (skipped: shape ids count the geometries).
const char* hand_shapes = "POLYGON((0 0, 1 0, 1 1, 0 1, 0 0))\n\nPOLYGON((0 0, 2 0, 2 1, 0 1, 0 0))\n";
/// Step 0: squares 10 and 20 share an edge, rectangle 5 is far. Step 1: 20
/// moves one unit right (apart from 10), 5 comes to touch 20's right side.
/// Step 3 (no step 2): 10 turns a quarter about its origin. Step 4: 10 back,
/// 20 touches it at a corner and leaves 5.
const char* hand_steps =
    "step,body,shape,tx,ty,theta\n"
    "0,10,0,0,0,0\n"
    "0,20,0,1,0,0\n"
    "0,5,1,5,5,0\n"
    "1,20,0,2,0,0\n"
    "1,5,1,3,0,0\n"
    "3,10,0,0,0,1.5707963267948966\n"
    "4,10,0,0,0,0\n"
    "4,20,0,1,1,0\n";

std::string world_seventeen(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

/// The summary's line `time per step: X us`, X a number.
bool has_time_per_step(const std::string& summary) {
    const std::size_t at = summary.find("\ntime per step: ");
    if (at == std::string::npos) return false;
    const std::size_t end = summary.find('\n', at + 1);
    const std::string value = summary.substr(at + 16, end - at - 16);
    return value.size() > 3 && value.compare(value.size() - 3, 3, " us") == 0 &&
           value.find_first_not_of("0123456789.") == value.size() - 3;
}

/// A row of STEPS.csv.
struct step_row {
    std::size_t step;
    std::uint64_t body;
    std::size_t shape;
    pose where;
};

std::string steps_csv(const std::vector<step_row>& rows) {
    std::string s = "step,body,shape,tx,ty,theta\n";
    for (const step_row& r : rows)
        s += std::to_string(r.step) + "," + std::to_string(r.body) + "," + std::to_string(r.shape) + "," +
             world_seventeen(r.where.tx) + "," + world_seventeen(r.where.ty) + "," + world_seventeen(r.where.theta) +
             "\n";
    return s;
}

/// The contacts and events of the rows by the exact two-pose intersects on
/// every pair of bodies at each step (`step,a,b` and `step,a,b,event`).
std::pair<std::string, std::string> reference_rows(const std::vector<polygon>& shapes,
                                                   const std::vector<step_row>& rows) {
    std::map<std::uint64_t, std::pair<std::size_t, pose>> bodies;
    std::set<std::pair<std::uint64_t, std::uint64_t>> last;
    std::string contacts = "step,a,b\n", events = "step,a,b,event\n";
    for (std::size_t k = 0; k < rows.size();) {
        const std::size_t step = rows[k].step;
        for (; k < rows.size() && rows[k].step == step; ++k) bodies[rows[k].body] = {rows[k].shape, rows[k].where};
        std::set<std::pair<std::uint64_t, std::uint64_t>> now;
        for (auto i = bodies.begin(); i != bodies.end(); ++i)
            for (auto j = std::next(i); j != bodies.end(); ++j)
                if (intersects<exact_rational>(shapes[i->second.first], i->second.second, shapes[j->second.first],
                                               j->second.second))
                    now.insert({i->first, j->first});
        std::set<std::pair<std::uint64_t, std::uint64_t>> changed;
        for (const auto& p : now) {
            contacts += std::to_string(step) + "," + std::to_string(p.first) + "," + std::to_string(p.second) + "\n";
            if (!last.count(p)) changed.insert(p);
        }
        for (const auto& p : last)
            if (!now.count(p)) changed.insert(p);
        for (const auto& p : changed)
            events += std::to_string(step) + "," + std::to_string(p.first) + "," + std::to_string(p.second) +
                      (now.count(p) ? ",begin\n" : ",end\n");
        last = now;
    }
    return {contacts, events};
}

/// A layer of n x n unit squares sharing their sides, square j * n + i at
/// [i, i + 1] x [j, j + 1], one WKT per line.
std::string grid_layer(int n) {
    std::string s;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::string x0 = std::to_string(i), x1 = std::to_string(i + 1), y0 = std::to_string(j),
                              y1 = std::to_string(j + 1);
            s += "POLYGON((" + x0 + " " + y0 + ", " + x1 + " " + y0 + ", " + x1 + " " + y1 + ", " + x0 + " " + y1 +
                 ", " + x0 + " " + y0 + "))\n";
        }
    return s;
}

/// PAIRS.csv of the n x n grid (and a far square numbered n * n): the
/// squares at distance <= d, found from their gaps.
std::string grid_pairs(int n, int d) {
    std::string s = "a,b\n";
    for (int a = 0; a < n * n; ++a)
        for (int b = a + 1; b < n * n; ++b) {
            const int gx = std::max(0, std::abs(a % n - b % n) - 1), gy = std::max(0, std::abs(a / n - b / n) - 1);
            if (gx * gx + gy * gy <= d * d) s += std::to_string(a) + "," + std::to_string(b) + "\n";
        }
    return s;
}

}  // namespace

TEST_CASE("cli: world writes the contacts and events of a hand-made scene", "[cli][world_tool]") {
    const temp_dir dir;
    const auto shapes = dir.file("shapes.wkt", hand_shapes), steps = dir.file("steps.csv", hand_steps);
    const fs::path out = dir / "contacts.csv";
    const std::string common = "world --shapes " + quote(shapes.string()) + " --steps " + quote(steps.string()) +
                               " --out " + quote(out.string());
    for (const char* type : {"certified", "exact", "double", "float", "long-double", "quad"}) {
        INFO(type);
        const run_result r = run_cli(dir, common + " --number-type " + type);
        REQUIRE(r.exit_code == 0);
        CHECK(slurp(out) == "step,a,b\n0,10,20\n1,5,20\n3,5,20\n4,10,20\n");
        CHECK(r.out.find("bodies:        3\nsteps:         4\ncontacts:      4\nevents:        5\n") !=
              std::string::npos);
        CHECK(r.out.find(std::string("number type:   ") + type + "\n") != std::string::npos);
        CHECK(r.out.find("\ncandidates:    ") != std::string::npos);
        if (std::string(type) != "certified") CHECK(r.out.find(", again in exact rationals 0)\n") != std::string::npos);
        CHECK(has_time_per_step(r.out));
        const run_result e = run_cli(dir, common + " --number-type " + type + " --events");
        REQUIRE(e.exit_code == 0);
        CHECK(slurp(out) == "step,a,b,event\n0,10,20,begin\n1,5,20,begin\n1,10,20,end\n4,5,20,end\n4,10,20,begin\n");
    }
    // Within one unit: 10 and 20 one apart at step 1, 5 and 20 at step 4.
    for (const char* type : {"certified", "exact", "double"}) {
        INFO(type);
        const run_result r = run_cli(dir, common + " --within 1 --number-type " + type);
        REQUIRE(r.exit_code == 0);
        CHECK(slurp(out) == "step,a,b\n0,10,20\n1,5,20\n1,10,20\n3,5,20\n4,5,20\n4,10,20\n");
    }
    // Standard output: the rows there, the summary on standard error.
    const run_result to_stdout = run_cli(
        dir, "world --shapes " + quote(shapes.string()) + " --steps " + quote(steps.string()) + " --events --out -");
    REQUIRE(to_stdout.exit_code == 0);
    CHECK(to_stdout.out.rfind("step,a,b,event\n0,10,20,begin\n", 0) == 0);
    CHECK(has_time_per_step(to_stdout.err));
}

TEST_CASE("cli: world's fixed column keeps two fixed bodies untested", "[cli][world_tool]") {
    const temp_dir dir;
    const auto shapes = dir.file("shapes.wkt", hand_shapes);
    // Fixed 1 and 2 overlap, never reported; free 3 touches 2, then moves
    // onto 1 alone.
    const auto steps = dir.file("steps.csv",
                                "step,body,shape,tx,ty,theta,fixed\n"
                                "0,1,0,0,0,0,1\n"
                                "0,2,0,0.5,0,0,1\n"
                                "0,3,0,1.5,0,0,0\n"
                                "1,3,0,-0.75,0.5,0,0\n");
    const fs::path out = dir / "contacts.csv";
    const run_result r = run_cli(dir, "world --shapes " + quote(shapes.string()) + " --steps " + quote(steps.string()) +
                                          " --out " + quote(out.string()));
    REQUIRE(r.exit_code == 0);
    CHECK(slurp(out) == "step,a,b\n0,2,3\n1,1,3\n");
}

TEST_CASE("cli: world's contacts are the exact intersects of every pair of bodies", "[cli][world_tool]") {
    const temp_dir dir;
    std::vector<polygon> shapes;
    std::string shapes_text;
    for (const char* name : {"hole_16", "irregular_16", "starred_16", "convex_8", "contour_16"}) {
        const std::string line = to_wkt(read_wkt_file(world_data_dir + "/families/" + name + ".wkt"));
        shapes_text += line + "\n";
        shapes.push_back(read_wkt(line));
    }
    // 24 bodies (user ids 1000, 997, ...: not the world's order) in a square
    // of side 400, about half of them moved at each of 8 steps (numbered 0,
    // 3, 6, ...).
    test_random::rng rng(20240611);
    std::vector<step_row> rows;
    const auto random_pose = [&] { return pose{rng.uniform(0, 400), rng.uniform(0, 400), rng.uniform(-3.2, 3.2)}; };
    std::vector<std::size_t> shape_of(24);
    for (std::size_t b = 0; b < 24; ++b) {
        shape_of[b] = rng.index(shapes.size());
        rows.push_back({0, 1000 - 3 * b, shape_of[b], random_pose()});
    }
    for (std::size_t s = 1; s < 8; ++s)
        for (std::size_t b = 0; b < 24; ++b)
            if (rng.chance(0.5)) rows.push_back({3 * s, 1000 - 3 * b, shape_of[b], random_pose()});
    const auto shapes_file = dir.file("shapes.wkt", shapes_text);
    const auto steps_file = dir.file("steps.csv", steps_csv(rows));
    const auto [contacts, events] = reference_rows(shapes, rows);
    CHECK(std::count(contacts.begin(), contacts.end(), '\n') > 10);
    const fs::path out = dir / "contacts.csv";
    const std::string common = "world --shapes " + quote(shapes_file.string()) + " --steps " +
                               quote(steps_file.string()) + " --out " + quote(out.string());
    for (const char* type : {"certified", "exact"}) {
        INFO(type);
        REQUIRE(run_cli(dir, common + " --number-type " + type).exit_code == 0);
        CHECK(slurp(out) == contacts);
        REQUIRE(run_cli(dir, common + " --number-type " + type + " --events").exit_code == 0);
        CHECK(slurp(out) == events);
    }
}

TEST_CASE("cli: world and pairs write the same with two threads as with one", "[cli][world_tool]") {
    const temp_dir dir;
    // 150 octagons in a square of side 600, moved three times: enough
    // candidate pairs per step for the threads to share them.
    const std::string octagon = to_wkt(read_wkt_file(world_data_dir + "/families/convex_8.wkt"));
    const auto shapes = dir.file("shapes.wkt", octagon + "\n");
    test_random::rng rng(7);
    std::vector<step_row> rows;
    for (std::size_t s = 0; s < 3; ++s)
        for (std::uint64_t b = 0; b < 150; ++b)
            rows.push_back({s, b, 0, pose{rng.uniform(0, 600), rng.uniform(0, 600), rng.uniform(-3.2, 3.2)}});
    const auto steps = dir.file("steps.csv", steps_csv(rows));
    const auto layer = dir.file("grid.wkt", grid_layer(30));
    for (const char* type : {"certified", "double"}) {
        INFO(type);
        std::string world_file[2], pairs_file[2];
        for (int t = 0; t < 2; ++t) {
            const std::string threads = std::string(" --threads ") + (t == 0 ? "1" : "2");
            const fs::path out = dir / "out.csv";
            REQUIRE(run_cli(dir, "world --shapes " + quote(shapes.string()) + " --steps " + quote(steps.string()) +
                                     " --number-type " + type + threads + " --out " + quote(out.string()))
                        .exit_code == 0);
            world_file[t] = slurp(out);
            REQUIRE(run_cli(dir, "pairs --layer " + quote(layer.string()) + " --number-type " + type + threads +
                                     " --out " + quote(out.string()))
                        .exit_code == 0);
            pairs_file[t] = slurp(out);
        }
        CHECK(std::count(world_file[0].begin(), world_file[0].end(), '\n') > 100);
        CHECK(world_file[1] == world_file[0]);
        CHECK(pairs_file[0] == grid_pairs(30, 0));
        CHECK(pairs_file[1] == pairs_file[0]);
    }
}

TEST_CASE("cli: pairs finds the touching squares of a layer, of two layers, and within a distance",
          "[cli][world_tool]") {
    const temp_dir dir;
    // A 3 x 3 grid, a blank line, then a far square: number 9.
    const auto layer = dir.file("grid.wkt", grid_layer(3) + "\n   \nPOLYGON((10 10, 11 10, 11 11, 10 11, 10 10))\n");
    const fs::path out = dir / "pairs.csv";
    for (const char* type : {"certified", "exact", "double", "float", "long-double", "quad"}) {
        INFO(type);
        const run_result r = run_cli(
            dir, "pairs --layer " + quote(layer.string()) + " --number-type " + type + " --out " + quote(out.string()));
        REQUIRE(r.exit_code == 0);
        CHECK(slurp(out) == grid_pairs(3, 0));
        CHECK(r.out.find("polygons:      10\npairs:         20\n") != std::string::npos);
        CHECK(r.out.find("\ntime: ") != std::string::npos);
        // The candidates: the pairs of squares whose boxes meet, 20 (the
        // far square's box meets none).
        CHECK(r.out.find("\ncandidates:    20 (again in exact rationals ") != std::string::npos);
        if (std::string(type) != "certified") CHECK(r.out.find(" (again in exact rationals 0)\n") != std::string::npos);
    }
    for (const char* type : {"certified", "exact"}) {
        INFO(type);
        REQUIRE(run_cli(dir, "pairs --layer " + quote(layer.string()) + " --within 1 --number-type " + type +
                                 " --out " + quote(out.string()))
                    .exit_code == 0);
        CHECK(slurp(out) == grid_pairs(3, 1));
    }
    // The other layer: 0 touches squares 2 (a side) and 5 (a corner), 1
    // lies inside square 4, 2 is far.
    const auto other = dir.file("other.wkt",
                                "POLYGON((3 0, 4 0, 4 1, 3 1, 3 0))\n"
                                "POLYGON((1.25 1.25, 1.75 1.25, 1.75 1.75, 1.25 1.75, 1.25 1.25))\n"
                                "MULTIPOLYGON(((20 20, 21 20, 21 21, 20 21, 20 20)))\n");
    for (const char* type : {"certified", "exact", "double"}) {
        INFO(type);
        const run_result r =
            run_cli(dir, "pairs --layer " + quote(layer.string()) + " --other " + quote(other.string()) +
                             " --number-type " + type + " --out " + quote(out.string()));
        REQUIRE(r.exit_code == 0);
        CHECK(slurp(out) == "a,b\n2,0\n4,1\n5,0\n");
        CHECK(r.out.find("polygons:      10 and 3\npairs:         3\n") != std::string::npos);
    }
    // Within 14.2: the far square of the first layer (9 sqrt 2 from the
    // other's far one) reaches it.
    REQUIRE(run_cli(dir, "pairs --layer " + quote(layer.string()) + " --other " + quote(other.string()) +
                             " --within 14.2 --out " + quote(out.string()))
                .exit_code == 0);
    CHECK(slurp(out).find("\n9,2\n") != std::string::npos);
}

TEST_CASE("cli: world and pairs refuse bad input with the file and line, writing nothing", "[cli][world_tool][input]") {
    const temp_dir dir;
    const auto shapes = dir.file("shapes.wkt", hand_shapes), steps = dir.file("steps.csv", hand_steps);
    const auto bad_wkt = dir.file("bad.wkt", "POLYGON((0 0, 1 0, 1 1, 0 1, 0 0))\n\nPOLYGON((0 0, 1 0, 1 1\n");
    const auto no_shape = dir.file("none.wkt", "\n  \n");
    const std::string header = "step,body,shape,tx,ty,theta\n";
    const auto csv = [&](const std::string& name, const std::string& text) { return dir.file(name, text).string(); };
    const std::string world_shapes = "world --shapes " + quote(shapes.string());
    struct refusal {
        std::string args, message;
    };
    const std::vector<refusal> refusals = {
        {"world --shapes " + quote(bad_wkt.string()) + " --steps " + quote(steps.string()), "bad.wkt: line 3: "},
        {"world --shapes " + quote(no_shape.string()) + " --steps " + quote(steps.string()), "none.wkt: no polygon"},
        {world_shapes + " --steps " + quote(csv("header.csv", "step,body,shape,x,y,theta\n0,1,0,0,0,0\n")),
         "header.csv: line 1: expected the header"},
        {world_shapes + " --steps " + quote(csv("field.csv", header + "0,1,0,0,0,0\n0,2,0,abc,0,0\n")),
         "field.csv: line 3, column tx: \"abc\" is not a number"},
        {world_shapes + " --steps " + quote(csv("columns.csv", header + "0,1,0,0,0\n")),
         "columns.csv: line 2: 5 columns, expected 6"},
        {world_shapes + " --steps " + quote(csv("nan.csv", header + "0,1,0,0,nan,0\n")),
         "nan.csv: line 2, column ty: \"nan\" is not a finite number"},
        {world_shapes + " --steps " + quote(csv("inf.csv", header + "0,1,0,0,0,inf\n")),
         "inf.csv: line 2, column theta: \"inf\" is not a finite number"},
        {world_shapes + " --steps " + quote(csv("body.csv", header + "0,-1,0,0,0,0\n")),
         "body.csv: line 2, column body: \"-1\" is not an integer >= 0"},
        {world_shapes + " --steps " + quote(csv("back.csv", header + "0,1,0,0,0,0\n2,1,0,1,0,0\n1,1,0,2,0,0\n")),
         "back.csv: line 4: step 1 after step 2"},
        {world_shapes + " --steps " + quote(csv("range.csv", header + "0,1,0,0,0,0\n0,2,2,0,0,0\n")),
         "range.csv: line 3, column shape: no shape 2"},
        {world_shapes + " --steps " + quote(csv("twice.csv", header + "0,1,0,0,0,0\n0,1,0,1,0,0\n")),
         "twice.csv: line 3: body 1 is listed twice in step 0 (also line 2)"},
        {world_shapes + " --steps " + quote(csv("reshape.csv", header + "0,1,0,0,0,0\n1,1,1,0,0,0\n")),
         "reshape.csv: line 3, column shape: body 1 has shape 0 since line 2"},
        {world_shapes + " --steps " +
             quote(csv("fixed.csv", header.substr(0, header.size() - 1) + ",fixed\n0,1,0,0,0,0,1\n1,1,0,0,0,0,2\n")),
         "fixed.csv: line 3, column fixed: \"2\" is not 0 or 1"},
        {world_shapes + " --steps " + quote(steps.string()) + " --number-type interval",
         "--number-type interval: world does not run in this type"},
        {"pairs --layer " + quote(bad_wkt.string()), "bad.wkt: line 3: "},
        {"pairs --layer " + quote(shapes.string()) + " --other " + quote(bad_wkt.string()), "bad.wkt: line 3: "},
        {"pairs --layer " + quote(shapes.string()) + " --number-type interval",
         "--number-type interval: pairs does not run in this type"},
        {"pairs --layer " + quote(shapes.string()) + " --within -1", "--within"},
    };
    const fs::path out = dir / "out.csv";
    for (const refusal& r : refusals) {
        INFO(r.args);
        const run_result run = run_cli(dir, r.args + " --out " + quote(out.string()));
        CHECK(run.exit_code == 2);
        CHECK(run.err.find(r.message) != std::string::npos);
        CHECK(run.out.empty());
        CHECK(!fs::exists(out));
        CHECK(!fs::exists(dir / "out.csv.tmp"));
    }
    // Every bad row is named, not only the first.
    const run_result many = run_cli(
        dir, world_shapes + " --steps " + quote(csv("many.csv", header + "0,1,0,x,0,0\n0,2,0,0,0,0\n0,2,0,1,0,0\n")) +
                 " --out " + quote(out.string()));
    CHECK(many.exit_code == 2);
    CHECK(many.err.find("many.csv: line 2, column tx") != std::string::npos);
    CHECK(many.err.find("many.csv: line 4: body 2 is listed twice") != std::string::npos);
    CHECK(!fs::exists(out));
}
