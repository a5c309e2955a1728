// SPDX-License-Identifier: BSL-1.0
// Where a random-pose frame of detector<double> spends its instructions, for
// scripts/profile/random_frames.sh: each cell named on the command line
// (type:static:moving) runs the time study's random poses (the same seed and
// annulus as `influence2d-bench`), with a detector built with
// build_structures() and one frame asked before counting; callgrind counts
// only the frame loop of each cell (one dump per cell, named after it).

#include <cstdio>
#include <cstdlib>
#include <string>

#include <valgrind/callgrind.h>

#include "influence2d/detect/detector.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "verification/families.hpp"
#include "verification/time_study.hpp"

using namespace influence2d;
using namespace influence2d::verification;

int main(int argc, char** argv) {
    time_study_options o;
    int sink = 0;
    for (int k = 1; k < argc; ++k) {
        const std::string cell = argv[k];
        const std::size_t c1 = cell.find(':'), c2 = cell.find(':', c1 + 1);
        if (c1 == std::string::npos || c2 == std::string::npos) {
            std::fprintf(stderr, "random_frames: %s: give type:static:moving\n", cell.c_str());
            return 2;
        }
        const time_cell c{cell.substr(0, c1), "random", std::stoul(cell.substr(c1 + 1, c2 - c1 - 1)),
                          std::stoul(cell.substr(c2 + 1))};
        const family f = family_of(c.type);
        const polygon a = make_family_polygon(f, c.static_size, o.seed);
        const polygon b = make_family_polygon(f, c.moving_size, o.seed);
        const std::vector<pose> poses = time_study_poses(o, c, a, b);
        detector<double> d(a, b);
        d.build_structures();
        sink += d.collide(poses[0]).collides;
        CALLGRIND_ZERO_STATS;
        CALLGRIND_START_INSTRUMENTATION;
        for (const pose& p : poses) sink += d.collide(p).collides;
        CALLGRIND_STOP_INSTRUMENTATION;
        static std::string name;  // the dump keeps the pointer
        name = cell;
        CALLGRIND_DUMP_STATS_AT(name.c_str());
        std::printf("%s %zu frames\n", cell.c_str(), poses.size());
    }
    return sink < 0;
}
