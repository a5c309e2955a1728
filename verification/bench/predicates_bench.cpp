// SPDX-License-Identifier: BSL-1.0
// (a) The predicates per number type, on inputs taken from the contour_64
// polygon (static, converted from double) and the same polygon posed at random
// places over it (moving: every coordinate the result of NT operations, as in
// a detector's frame):
//   orientation        orientation(static edge start, end, moving vertex)
//   segments_intersect static edge against moving edge (closed segments)
//   locate             point in polygon through the influence-area index
//   mask               the influence mask of a point (its cones)
// Each benchmark runs over a fixed array of inputs per iteration; the time
// reported is per call (items = calls). A call that raises an uncertain sign
// (certified, interval: never on these generic inputs) is counted in the
// `uncertain` counter and skipped.

#include <benchmark/benchmark.h>

#include <CGAL/Uncertain.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/influence/influence_areas.hpp"
#include "influence2d/predicates/orientation.hpp"
#include "influence2d/predicates/segments.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d::bench {
namespace {

constexpr std::size_t input_count = 4096;

/// Inputs in NT, built once per type from the same doubles.
template <class NT>
struct predicate_inputs {
    std::unique_ptr<static_scene<NT>> scene;
    std::vector<point<NT>> sa, sb;  // static edges (start, end)
    std::vector<point<NT>> mc, md;  // moving edges, posed in NT
    std::vector<point<NT>> probes;  // posed points over A's box

    predicate_inputs() {
        const polygon& a = family("contour_64");
        const polygon& b = family("contour_64");
        scene = std::make_unique<static_scene<NT>>(a);
        std::mt19937_64 gen(20040203);
        auto unit = [&] { return std::ldexp(static_cast<double>(gen() >> 11), -53); };
        const box& ab = a.bounds();
        auto random_pose = [&] {
            return rotation_pose(pose{ab.min_x + (ab.max_x - ab.min_x) * unit(),
                                      ab.min_y + (ab.max_y - ab.min_y) * unit(),
                                      6.283185307179586 * unit() - 3.141592653589793});
        };
        const auto& cov = scene->covering;
        for (std::size_t k = 0; k < input_count; ++k) {
            const std::size_t i = static_cast<std::size_t>(gen() % a.size());
            const std::size_t j = static_cast<std::size_t>(gen() % b.size());
            sa.push_back(cov.start(i));
            sb.push_back(cov.end(i));
            // B posed so that its vertex j lands near A's edge i: the pairs then
            // straddle each other's lines about as often as they do in a frame.
            rotation_pose t = random_pose();
            const point<double> q = b.vertex(j), m = a.vertex(i);
            t.tx = m.x - (t.c * q.x - t.s * q.y) + 4 * (unit() - 0.5);
            t.ty = m.y - (t.s * q.x + t.c * q.y) + 4 * (unit() - 0.5);
            mc.push_back(t.apply<NT>(q));
            md.push_back(t.apply<NT>(b.vertex(b.next(j))));
            // A probe: a point of A's box (slightly grown), posed by a rotation
            // about itself so that it carries the rounding of a posed vertex.
            const rotation_pose r = random_pose();
            const double px = ab.min_x - 5 + (ab.max_x - ab.min_x + 10) * unit();
            const double py = ab.min_y - 5 + (ab.max_y - ab.min_y + 10) * unit();
            rotation_pose about = r;
            about.tx = px - (r.c * px - r.s * py);
            about.ty = py - (r.s * px + r.c * py);
            probes.push_back(about.apply<NT>(point<double>{px, py}));
        }
    }

    static const predicate_inputs& get() {
        static const predicate_inputs inputs;
        return inputs;
    }
};

/// Runs body(k) for k over the inputs, every iteration; counts the uncertain calls.
template <class Body>
void run_inputs(benchmark::State& state, Body&& body) {
    std::size_t uncertain = 0;
    for (auto _ : state) {
        for (std::size_t k = 0; k < input_count; ++k) {
            try {
                body(k);
            } catch (const uncertain_sign&) {
                ++uncertain;
            } catch (const CGAL::Uncertain_conversion_exception&) {
                ++uncertain;
            }
        }
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * input_count));
    state.counters["per_call"] = benchmark::Counter(
        static_cast<double>(input_count), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["uncertain"] = static_cast<double>(uncertain);
}

template <class NT>
void bench_orientation(benchmark::State& state) {
    const auto& in = predicate_inputs<NT>::get();
    run_inputs(state, [&](std::size_t k) { benchmark::DoNotOptimize(orientation(in.sa[k], in.sb[k], in.mc[k])); });
}

template <class NT>
void bench_segments(benchmark::State& state) {
    const auto& in = predicate_inputs<NT>::get();
    run_inputs(state, [&](std::size_t k) {
        benchmark::DoNotOptimize(segments_intersect(in.sa[k], in.sb[k], in.mc[k], in.md[k]));
    });
}

template <class NT>
void bench_locate(benchmark::State& state) {
    const auto& in = predicate_inputs<NT>::get();
    run_inputs(state, [&](std::size_t k) { benchmark::DoNotOptimize(in.scene->areas().locate(in.probes[k])); });
}

template <class NT>
void bench_mask(benchmark::State& state) {
    const auto& in = predicate_inputs<NT>::get();
    influence_mask mask(in.scene->shape.size());
    run_inputs(state, [&](std::size_t k) {
        in.scene->areas().mask(in.probes[k], mask);
        benchmark::DoNotOptimize(mask.any());
    });
}

}  // namespace

void register_predicate_benchmarks() {
    for_each_number_type([](auto tag) {
        using NT = typename decltype(tag)::type;
        const std::string t = type_name<NT>();
        benchmark::RegisterBenchmark(("predicate/orientation/" + t).c_str(), bench_orientation<NT>);
        benchmark::RegisterBenchmark(("predicate/segments_intersect/" + t).c_str(), bench_segments<NT>);
        benchmark::RegisterBenchmark(("predicate/locate/" + t).c_str(), bench_locate<NT>);
        benchmark::RegisterBenchmark(("predicate/mask/" + t).c_str(), bench_mask<NT>);
    });
}

}  // namespace influence2d::bench
