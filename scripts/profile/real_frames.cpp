// SPDX-License-Identifier: BSL-1.0
// Where a frame of detector<double> on a pair of real polygons spends its
// instructions, for scripts/profile/real_frames.sh: each pair of the real
// layers' time study (verification/real_pairs.hpp, the same seed and poses
// as influence2d-real-bench) in each of its four orders (walk, shuffled,
// apart walk, apart shuffled), on a detector built with build_structures()
// and asked the order's first pose before counting; callgrind counts only
// the loop over the order's poses (one dump per pair and order, named after
// them). Prints, per dump, its name, the poses and the detector's counters
// over the counted loop (frames through the trees, candidate gathers,
// candidate edges, segment tests), tab-separated.
//   real_frames LAYERS_DIR [POSES]

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <valgrind/callgrind.h>

#include "influence2d/detect/detector.hpp"
#include "src/world_input.hpp"
#include "verification/real_pairs.hpp"

using namespace influence2d;
using namespace influence2d::verification;
using influence2d::cli::named_polygon;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: real_frames LAYERS_DIR [POSES]\n");
        return 2;
    }
    const std::string layers = argv[1];
    const std::size_t count = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 600;
    const std::uint64_t seed = 20040202;  // influence2d-real-bench's default
    int sink = 0;
    for (const real_pair& p : study_pairs()) {
        const polygon a = named_polygon(layers, p.layer, p.a), b = named_polygon(layers, p.layer, p.b);
        for (const auto& [order, list] : pose_orders(p, a, b, count, seed)) {
            detector<double> d(a, b);
            d.build_structures();
            sink += d.collide(list.front()).collides;
            const detector_statistics before = d.statistics();
            CALLGRIND_ZERO_STATS;
            CALLGRIND_START_INSTRUMENTATION;
            for (const pose& q : list) sink += d.collide(q).collides;
            CALLGRIND_STOP_INSTRUMENTATION;
            static std::string name;  // the dump keeps the pointer
            name = p.a + " x " + p.b + " / " + order;
            CALLGRIND_DUMP_STATS_AT(name.c_str());
            const detector_statistics& s = d.statistics();
            std::printf("%s\t%zu\t%zu\t%zu\t%zu\t%zu\n", name.c_str(), list.size(), s.jump_frames - before.jump_frames,
                        s.candidate_rebuilds - before.candidate_rebuilds, s.candidate_edges - before.candidate_edges,
                        s.segment_tests - before.segment_tests);
        }
    }
    return sink < 0;
}
