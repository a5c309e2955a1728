// SPDX-License-Identifier: BSL-1.0
// The influence2d benchmarks (Google Benchmark): predicates and detectors per
// number type, and the detector's compile-time features. See
// predicates_bench.cpp, detector_bench.cpp and features_bench.cpp; scripts/bench.sh
// runs them and prints the certified/double and exact/double ratios per scene.

#include <benchmark/benchmark.h>

namespace influence2d::bench {
void register_predicate_benchmarks();
void register_detector_benchmarks();
void register_features_benchmarks();
}  // namespace influence2d::bench

int main(int argc, char** argv) {
    influence2d::bench::register_predicate_benchmarks();
    influence2d::bench::register_detector_benchmarks();
    influence2d::bench::register_features_benchmarks();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
