// SPDX-License-Identifier: BSL-1.0
// `influence2d collide --threads`: the frames written are those of one thread,
// for random poses (each a jump) and a trajectory (small steps), with
// witnesses, in double, exact and certified; the summary names the threads;
// a bad count is refused.

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "influence2d/io/csv.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "support/process.hpp"

using namespace influence2d;
using namespace test_process;

namespace {

const std::string threads_data_dir = INFLUENCE2D_DATA_DIR;

std::string threads_poses_csv(const std::vector<pose>& poses) {
    std::ostringstream s;
    write_poses_csv(s, poses);
    return s.str();
}

}  // namespace

TEST_CASE("cli: collide --threads writes the frames of one thread", "[cli][threads]") {
    const temp_dir dir;
    const std::string a = threads_data_dir + "/families/hole_256.wkt",
                      b = threads_data_dir + "/families/irregular_32.wkt";
    const polygon pa = read_wkt_file(a), pb = read_wkt_file(b);
    const auto poses = dir.file("poses.csv", threads_poses_csv(random_poses(pa, pb, 400, 40, 110, 17)));
    for (const char* type : {"double", "exact", "certified"})
        for (const std::string& scene :
             {"--poses " + quote(poses.string()), std::string("--trajectory linear --trajectory-frames 900")}) {
            INFO(type << " " << scene);
            const std::string common = "collide --static " + quote(a) + " --moving " + quote(b) + " " + scene +
                                       " --witness --number-type " + type;
            const run_result one = run_cli(dir, common + " --threads 1 --out " + quote((dir / "one.csv").string()));
            REQUIRE(one.exit_code == 0);
            CHECK(one.out.find("threads:         1\n") != std::string::npos);
            const std::string frames = slurp(dir / "one.csv");
            CHECK(frames.find(",1,") != std::string::npos);  // some frame collides, with its pairs
            for (const char* threads : {"2", "3", "0"}) {
                const run_result many =
                    run_cli(dir, common + " --threads " + threads + " --out " + quote((dir / "many.csv").string()));
                REQUIRE(many.exit_code == 0);
                CHECK(many.out.find("time per frame:") != std::string::npos);
                CHECK(slurp(dir / "many.csv") == frames);
            }
        }
    const run_result bad =
        run_cli(dir, "collide --static " + quote(a) + " --moving " + quote(b) + " --trajectory linear --threads -2");
    CHECK(bad.exit_code != 0);
    CHECK(bad.err.find("--threads") != std::string::npos);
}
