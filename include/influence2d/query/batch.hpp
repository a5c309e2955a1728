// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Many queries at once on all cores: many poses of one pair, or many pairs
/// (docs/method.md, "Preparation and sharing").

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#if defined(INFLUENCE2D_USE_TBB)
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>
#endif

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/query/intersects.hpp"

namespace influence2d {

/// The machine's hardware threads (at least 1), asked of the system once:
/// std::thread::hardware_concurrency asks at every call (the GNU C library
/// reads /sys/devices/system/cpu/online), 6 to 8 us a call here (100,000
/// calls, twice, alone), where a parallel pass of a world's step or a
/// layer's join brings some hundred microseconds of work.
inline unsigned hardware_threads() {
    static const unsigned count = std::max(1u, std::thread::hardware_concurrency());
    return count;
}

/// The number of threads a batch uses for `threads`: itself when > 0, else
/// the machine's hardware threads (hardware_threads()).
inline unsigned batch_threads(unsigned threads) { return threads > 0 ? threads : hardware_threads(); }

namespace batch_detail {

/// A callable that does nothing, whatever it is given.
struct no_op {
    template <class... T>
    void operator()(T&&...) const {}
};

/// Calls task(k) for k in [0, tasks) on `threads` threads (at least 1, at
/// most tasks), the calling thread among them, and waits for all; task must
/// not throw. With INFLUENCE2D_USE_TBB (defined by the CMake target when
/// oneTBB is found) the threads are oneTBB's workers, which wait between
/// calls, so a call costs a few microseconds instead of a thread's start
/// and join (about 50 us here): the world calls this several times a step.
template <class Task>
void run_tasks(std::size_t tasks, std::size_t threads, Task&& task) {
    if (threads <= 1) {
        for (std::size_t k = 0; k < tasks; ++k) task(k);
        return;
    }
#if defined(INFLUENCE2D_USE_TBB)
    const auto loop = [&] {
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, tasks, 1),
            [&](const tbb::blocked_range<std::size_t>& r) {
                for (std::size_t k = r.begin(); k < r.end(); ++k) task(k);
            },
            tbb::simple_partitioner());
    };
    if (threads == static_cast<std::size_t>(tbb::this_task_arena::max_concurrency())) {
        loop();
    } else {
        tbb::task_arena arena(static_cast<int>(threads));
        arena.execute(loop);
    }
#else
    std::vector<std::thread> workers;
    workers.reserve(threads - 1);
    std::atomic<std::size_t> next{0};
    const auto run = [&] {
        for (std::size_t k = next++; k < tasks; k = next++) task(k);
    };
    for (std::size_t k = 1; k < threads; ++k) workers.emplace_back(run);
    run();
    for (std::thread& w : workers) w.join();
#endif
}

}  // namespace batch_detail

/// Runs block(first, last) over [0, count) cut into one contiguous block per
/// thread, `threads` of them (0: every hardware thread; never more than
/// count), the calling thread among them, and waits for all. The first
/// exception thrown, in block order, is rethrown after every thread ended.
template <class Block>
void run_in_blocks(std::size_t count, unsigned threads, Block&& block) {
    const std::size_t t = std::min<std::size_t>(batch_threads(threads), std::max<std::size_t>(count, 1));
    std::vector<std::exception_ptr> failed(t);
    batch_detail::run_tasks(t, t, [&](std::size_t k) {
        try {
            block(count * k / t, count * (k + 1) / t);
        } catch (...) {
            failed[k] = std::current_exception();
        }
    });
    for (const std::exception_ptr& e : failed)
        if (e) std::rethrow_exception(e);
}

/// Runs chunk(first, last) over [0, count) cut into chunks of `grain` items
/// (the last may be shorter), which `threads` threads (0: every hardware
/// thread; never more than the chunks) take in turn as each finishes its
/// last, the calling thread among them, and waits for all: work whose items
/// cost unevenly is shared evenly, whatever their order. Chunks run in no
/// fixed order, so chunk must only write what belongs to its items. The
/// exception of the first chunk that threw, in chunk order, is rethrown
/// after every thread ended.
template <class Chunk>
void run_in_chunks(std::size_t count, unsigned threads, std::size_t grain, Chunk&& chunk) {
    grain = std::max<std::size_t>(grain, 1);
    const std::size_t chunks = (count + grain - 1) / grain;
    const std::size_t t = std::min<std::size_t>(batch_threads(threads), std::max<std::size_t>(chunks, 1));
    std::mutex failing;
    std::size_t failed_at = chunks;
    std::exception_ptr failed;
    batch_detail::run_tasks(chunks, t, [&](std::size_t c) {
        try {
            chunk(c * grain, std::min(count, (c + 1) * grain));
        } catch (...) {
            const std::lock_guard<std::mutex> lock(failing);
            if (c < failed_at) {
                failed_at = c;
                failed = std::current_exception();
            }
        }
    });
    if (failed) std::rethrow_exception(failed);
}

/// The answers for every pose, in order, from detectors made by
/// `make_detector()` (one per thread, each answering a contiguous run of the
/// poses in order, so that a run keeps the coherence of consecutive poses).
/// Any detector type with `collide(const pose&)` returning frame_result
/// serves: detector<NT> (built on prepared polygons shared by all threads,
/// see prepare_static and prepare_moving), certified_detector, brute force.
///
/// The answers are the serial loop's: in exact and certified modes every
/// answer is the exact one whatever a detector's history; a floating NT
/// decides each frame's signs on the same posed values in every strategy,
/// so a different start of the coherence can change an answer only where
/// its own rounding makes the frame ambiguous. `threads` 0 uses every
/// hardware thread. `done(detector)`, when given, is called by each thread
/// with its detector after its last frame (to gather counters; calls from
/// different threads may overlap). The first exception a detector throws
/// (invalid_input for a non-finite pose) is rethrown after every thread
/// ended.
template <class MakeDetector, class Done = batch_detail::no_op>
std::vector<frame_result> collide_batch(const std::vector<pose>& poses, MakeDetector&& make_detector,
                                        unsigned threads = 0, Done&& done = {}) {
    std::vector<frame_result> out(poses.size());
    run_in_blocks(poses.size(), threads, [&](std::size_t first, std::size_t last) {
        if (first == last) return;
        auto d = make_detector();
        for (std::size_t k = first; k < last; ++k) out[k] = d.collide(poses[k]);
        done(d);
    });
    return out;
}

/// One query of a batch over many pairs: A, B and B's pose (the polygons are
/// referred to, not copied, and must outlive the call).
struct pair_query {
    const polygon* static_polygon = nullptr;  ///< A
    const polygon* moving_polygon = nullptr;  ///< B
    pose moving_pose;                         ///< B's pose
};

/// ask(A, B, pose) for every query, in order, on `threads` threads (0:
/// every hardware thread): an audit of many pairs, each asked once; `ask` is
/// a one-shot query such as `intersects<double>` or `certified_intersects`
/// (query/intersects.hpp, exact/certified_detector.hpp) and must be safe to call from
/// several threads (those are). 1 for a pair that meets, else 0. Throws
/// invalid_input for a null polygon, and the first exception `ask` throws
/// (in query order) after every thread ended.
template <class Ask>
std::vector<char> intersects_batch(const std::vector<pair_query>& queries, Ask&& ask, unsigned threads = 0) {
    std::vector<char> out(queries.size(), 0);
    run_in_blocks(queries.size(), threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
            const pair_query& q = queries[k];
            if (q.static_polygon == nullptr || q.moving_polygon == nullptr)
                throw invalid_input("intersects_batch: query " + std::to_string(k) + " has a null polygon");
            out[k] = ask(*q.static_polygon, *q.moving_polygon, q.moving_pose) ? 1 : 0;
        }
    });
    return out;
}

}  // namespace influence2d
