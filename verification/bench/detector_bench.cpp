// SPDX-License-Identifier: BSL-1.0
// (b) The sound detector per number type on the paper's scenes: contour
// polygons (the paper's hardest family), A static and B moving, on the
// circular trajectory (90,000 frames, gap 9: B orbits A close by, no frame
// collides) and the linear one (9,000 frames, ending in collision); cells
// 64x64, 1024x8 and 8x1024 (static x moving vertices).
//
// One iteration is one whole pass over the trajectory, in order (temporal
// coherence depends on the order), with one detector built before the timing
// loop, so every number type answers the same frames. Counters:
//   frames          frames per pass
//   time_per_frame  seconds per frame (the console prints it with a unit)
//   collisions      colliding frames per pass
//   exact_frames    certified and interval: frames per pass answered again in
//                   exact rationals (undecided signs)
// The certified type runs as certified_detector<detector>, intervals as
// interval_detector<detector>, every other type as detector<NT>.

#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/exact/interval_detector.hpp"
#include "influence2d/motion/trajectory.hpp"

namespace influence2d::bench {
namespace {

struct scene {
    std::string trajectory;  // circular or linear
    int static_size;
    int moving_size;

    std::string name() const {
        return trajectory + "_" + std::to_string(static_size) + "x" + std::to_string(moving_size);
    }
    const polygon& a() const { return family("contour_" + std::to_string(static_size)); }
    const polygon& b() const { return family("contour_" + std::to_string(moving_size)); }
    std::vector<pose> poses() const {
        return trajectory == "circular" ? circular_trajectory(a(), b()) : linear_trajectory(a(), b());
    }
};

const std::vector<scene>& scenes() {
    static const std::vector<scene> all = {{"circular", 64, 64}, {"linear", 64, 64},    {"circular", 1024, 8},
                                           {"linear", 1024, 8},  {"circular", 8, 1024}, {"linear", 8, 1024}};
    return all;
}

/// The detector measured for NT.
template <class NT>
struct detector_for {
    using type = detector<NT>;
};
template <>
struct detector_for<certified> {
    using type = certified_detector<detector>;
};
template <>
struct detector_for<interval> {
    using type = interval_detector<detector>;
};

template <class D>
std::size_t exact_frames_of(const D&) {
    return 0;
}
template <template <class...> class D>
std::size_t exact_frames_of(const certified_detector<D>& d) {
    return d.exact_frames();
}
template <template <class...> class D>
std::size_t exact_frames_of(const interval_detector<D>& d) {
    return d.exact_frames();
}

template <class NT>
void bench_scene(benchmark::State& state, const scene& s) {
    const polygon& a = s.a();
    const polygon& b = s.b();
    const std::vector<pose> poses = s.poses();
    typename detector_for<NT>::type det(a, b, detector_options{});
    std::size_t collisions = 0;
    for (auto _ : state) {
        for (const pose& p : poses) collisions += det.collide(p).collides ? 1 : 0;
    }
    const double passes = static_cast<double>(state.iterations());
    const double frames = static_cast<double>(poses.size());
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(poses.size()));
    state.counters["frames"] = frames;
    state.counters["time_per_frame"] =
        benchmark::Counter(frames, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["collisions"] = static_cast<double>(collisions) / passes;
    state.counters["exact_frames"] = static_cast<double>(exact_frames_of(det)) / passes;
}

}  // namespace

void register_detector_benchmarks() {
    for (const scene& s : scenes()) {
        for_each_number_type([&s](auto tag) {
            using NT = typename decltype(tag)::type;
            benchmark::RegisterBenchmark(("detector/" + s.name() + "/" + type_name<NT>()).c_str(),
                                         [s](benchmark::State& state) { bench_scene<NT>(state, s); })
                ->Unit(benchmark::kMillisecond);
        });
    }
}

}  // namespace influence2d::bench
