// SPDX-License-Identifier: BSL-1.0
// (c) What the detector's compile-time features cost on a scene that does not
// use them: the scenes of (b) but 8x1024, in double (and in exact rationals on
// 64x64), yes/no answers at d = 0, in four builds of the detector:
//   minimal        detector<NT, minimal_features>: no feature at all
//   coherence      detector<NT, feature_set<features::coherence>>: only what
//                  these scenes use (candidates kept between frames)
//   all_unused     detector<NT> (every feature built in), options asking for
//                  none but coherence: the price of carrying unused features
//   all_witness    detector<NT> with witnesses asked for: the price of using one
// One iteration is one pass over the trajectory, as in (b).

#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/number/cgal.hpp"

namespace influence2d::bench {
namespace {

struct features_scene {
    std::string trajectory;
    int static_size, moving_size;
    std::string name() const {
        return trajectory + "_" + std::to_string(static_size) + "x" + std::to_string(moving_size);
    }
};

template <class D>
void run_passes(benchmark::State& state, const features_scene& s, const detector_options& o) {
    const polygon& a = family("contour_" + std::to_string(s.static_size));
    const polygon& b = family("contour_" + std::to_string(s.moving_size));
    const std::vector<pose> poses = s.trajectory == "circular" ? circular_trajectory(a, b) : linear_trajectory(a, b);
    D det(a, b, o);
    std::size_t collisions = 0;
    for (auto _ : state)
        for (const pose& p : poses) collisions += det.collide(p).collides ? 1 : 0;
    const double frames = static_cast<double>(poses.size());
    state.counters["frames"] = frames;
    state.counters["time_per_frame"] =
        benchmark::Counter(frames, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["collisions"] = static_cast<double>(collisions) / static_cast<double>(state.iterations());
    state.counters["state_bytes"] = static_cast<double>(det.state_bytes());
}

template <class NT>
void register_scene(const features_scene& s) {
    const auto add = [&](const std::string& config, auto run) {
        benchmark::RegisterBenchmark(("features/" + s.name() + "/" + type_name<NT>() + "/" + config).c_str(),
                                     [s, run](benchmark::State& state) { run(state, s); })
            ->Unit(benchmark::kMillisecond);
    };
    detector_options witness;
    witness.witness = true;
    add("minimal",
        [](benchmark::State& st, const features_scene& sc) { run_passes<detector<NT, minimal_features>>(st, sc, {}); });
    add("coherence", [](benchmark::State& st, const features_scene& sc) {
        run_passes<detector<NT, feature_set<features::coherence>>>(st, sc, {});
    });
    add("all_unused", [](benchmark::State& st, const features_scene& sc) { run_passes<detector<NT>>(st, sc, {}); });
    add("all_witness",
        [witness](benchmark::State& st, const features_scene& sc) { run_passes<detector<NT>>(st, sc, witness); });
}

}  // namespace

void register_features_benchmarks() {
    const std::vector<features_scene> scenes = {
        {"circular", 64, 64}, {"linear", 64, 64}, {"circular", 1024, 8}, {"linear", 1024, 8}};
    for (const features_scene& s : scenes) {
        register_scene<double>(s);
        // Exact rationals without coherence regather hundreds of candidates
        // per frame on the 1024x8 cells: seconds per pass; 64x64 only.
        if (s.static_size == s.moving_size) register_scene<exact_rational>(s);
    }
}

}  // namespace influence2d::bench
