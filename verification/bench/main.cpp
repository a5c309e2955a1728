// SPDX-License-Identifier: BSL-1.0
// The influence2d benchmarks (Google Benchmark): predicates and detectors per
// number type, the detector's compile-time features, and the separation and
// first-contact queries against GEOS and Box2D. See predicates_bench.cpp,
// detector_bench.cpp, features_bench.cpp and queries_bench.cpp; scripts/bench.sh
// runs them and prints the certified/double and exact/double ratios per scene.

#include <benchmark/benchmark.h>

namespace influence2d::bench {
void register_predicate_benchmarks();
void register_detector_benchmarks();
void register_features_benchmarks();
void register_query_benchmarks();
}  // namespace influence2d::bench

int main(int argc, char** argv) {
    influence2d::bench::register_predicate_benchmarks();
    influence2d::bench::register_detector_benchmarks();
    influence2d::bench::register_features_benchmarks();
    influence2d::bench::register_query_benchmarks();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
