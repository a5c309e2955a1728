// SPDX-License-Identifier: BSL-1.0
#pragma once
// The time study (docs/method.md section 8): the paper's grid of cells, each method
// on the same frames, every answer counted against the exact reference.
//
//   for each polygon type, trajectory, static size n, moving size m (a cell):
//       A = family polygon (type, n), B = family polygon (type, m)
//       poses = circular (90,000, gap 9) or linear (9,000) trajectory
//       reference = certified mode on every frame, in order (exact answers:
//                   checked against CGAL's exact kernel by the long run);
//                   untimed, the certified row is a run of its own
//       for each method:
//           built once (not timed); then timed over its frames:
//             - influence2d's modes (double, certified, paper) run every frame
//               in order: temporal coherence is theirs to use; the pass is
//               repeated on fresh detectors (at least 3 passes, an odd
//               number, until `repeat_seconds` of passes) and the median
//               pass counts, so that a cell of a few milliseconds is not at
//               the mercy of one interruption; the modes take turns pass by
//               pass, so that a slower spell of the machine falls on all of
//               them alike and their ratios hold;
//             - exact mode and the peers, which are slow on large cells, run
//               every k-th frame, k chosen from a probe of 8 evenly spaced
//               frames so that the run takes about `budget` seconds (k = 1
//               when the whole trajectory fits);
//           answers compared with the reference on those frames.
//
// A row gives frames run, seconds, ns per frame, collisions and disagreements.
// The peak heap use of each method is measured on one cell (the largest).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/certified_detector.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/detect/paper_detector.hpp"
#include "influence2d/detect/trajectory.hpp"
#include "influence2d/number/cgal.hpp"
#include "verification/families.hpp"
#include "verification/heap_meter.hpp"
#include "verification/peers.hpp"

namespace influence2d::verification {

/// Whether GEOS and Box2D were found when this was built.
#if INFLUENCE2D_HAVE_GEOS
inline constexpr bool have_geos = true;
#else
inline constexpr bool have_geos = false;
#endif
#if INFLUENCE2D_HAVE_BOX2D
inline constexpr bool have_box2d = true;  ///< see have_geos
#else
inline constexpr bool have_box2d = false;  ///< see have_geos
#endif

/// Whether the peer library of a method was found when this was built (GEOS
/// and Box2D are optional; every other method is always there).
inline bool method_available(const std::string& m) {
    if (m == "geos") return have_geos;
    if (m == "box2d") return have_box2d;
    return true;
}

/// Every method the time study knows, ours first, available or not.
inline const std::vector<std::string>& known_methods() {
    static const std::vector<std::string> all = {"double", "certified", "exact",          "paper", "brute_force",
                                                 "boost_geometry", "geos",   "cgal", "box2d"};
    return all;
}

/// The methods of the time study, ours first: those this build has.
inline const std::vector<std::string>& time_study_methods() {
    static const std::vector<std::string> available = [] {
        std::vector<std::string> out;
        for (const std::string& m : known_methods())
            if (method_available(m)) out.push_back(m);
        return out;
    }();
    return available;
}

/// The peers this build lacks (their libraries were not found), for reports.
inline std::vector<std::string> missing_methods() {
    std::vector<std::string> out;
    for (const std::string& m : known_methods())
        if (!method_available(m)) out.push_back(m);
    return out;
}

/// Whether a method is one of influence2d's (else a peer).
inline bool is_own_method(const std::string& m) {
    return m == "double" || m == "certified" || m == "exact" || m == "paper";
}

struct time_cell {
    std::string type;        ///< family name: convex, starred, irregular, contour, hole
    std::string trajectory;  ///< circular or linear
    std::size_t static_size = 0, moving_size = 0;
};

struct time_row {
    time_cell cell;
    std::string method;
    std::size_t trajectory_frames = 0;  ///< frames of the trajectory
    std::size_t frames = 0;             ///< frames run (every stride-th)
    std::size_t stride = 1;
    std::size_t passes = 1;  ///< timed passes over the frames (the median counts)
    double seconds = 0;      ///< for the frames run (the median pass), set-up excluded
    std::size_t collisions = 0;
    std::size_t disagreements = 0;  ///< with the reference, on the frames run
    bool reference = false;         ///< this method's answers are the reference
    double ns_per_frame() const { return frames ? 1e9 * seconds / static_cast<double>(frames) : 0; }
};

struct memory_row {
    time_cell cell;
    std::string method;
    std::size_t frames = 0;
    std::size_t peak_bytes = 0;  ///< heap, from building the method to its last frame
};

struct time_study_progress {
    std::size_t cell = 0, cells = 0;  ///< cell == cells at the end
    time_cell at;
};

struct time_study_options {
    std::vector<std::string> types = {"convex", "starred", "irregular", "contour", "hole"};
    std::vector<std::string> trajectories = {"circular", "linear"};
    std::vector<std::size_t> sizes = {8, 16, 32, 64, 128, 256, 512, 1024};
    std::vector<std::string> methods = time_study_methods();
    std::size_t circular_frames = 90000, linear_frames = 9000;
    double gap = 9;
    double budget = 0.25;              ///< seconds per strided method and cell
    double repeat_seconds = 0.02;      ///< seconds of repeated passes per own every-frame mode and cell
    std::size_t memory_frames = 1000;  ///< frames of the memory pass (evenly spaced)
    std::uint64_t seed = default_family_seed;
    std::function<void(const time_study_progress&)> progress;
};

struct time_study_result {
    std::vector<time_row> rows;
    std::vector<memory_row> memory;
    double seconds = 0;
};

namespace time_study_detail {

using clock = std::chrono::steady_clock;

inline family family_of(const std::string& name) {
    for (family f : all_families)
        if (family_name(f) == name) return f;
    throw std::invalid_argument("unknown polygon type: " + name);
}

/// Calls f(detector) with the method's detector for A and B built.
template <class F>
void with_method(const std::string& m, const polygon& a, const polygon& b, F&& f) {
    if (m == "double") {
        detector<double> d(a, b);
        return f(d);
    }
    if (m == "certified") {
        certified_detector<detector> d(a, b);
        return f(d);
    }
    if (m == "exact") {
        detector<exact_rational> d(a, b);
        return f(d);
    }
    if (m == "paper") {
        paper_detector<double> d(a, b);
        return f(d);
    }
    if (m == "brute_force") {
        brute_force_detector<double> d(a, b);
        return f(d);
    }
    if (m == "boost_geometry") {
        boost_geometry_peer d(a, b);
        return f(d);
    }
#if INFLUENCE2D_HAVE_GEOS
    if (m == "geos") {
        geos_peer d(a, b);
        return f(d);
    }
#endif
    if (m == "cgal") {
        cgal_peer d(a, b);
        return f(d);
    }
#if INFLUENCE2D_HAVE_BOX2D
    if (m == "box2d") {
        box2d_peer d(a, b);
        return f(d);
    }
#endif
    if (!method_available(m)) throw std::invalid_argument("method " + m + ": its library was not found when this was built");
    throw std::invalid_argument("unknown method: " + m);
}

template <class D>
bool collides(D& d, const pose& p) {
    if constexpr (std::is_same_v<decltype(d.collide(p)), bool>)
        return d.collide(p);
    else
        return d.collide(p).collides;
}

/// Whether the method can take the cell (Box2D: convex, at most 8 vertices).
inline bool applies(const std::string& m, [[maybe_unused]] const polygon& a, [[maybe_unused]] const polygon& b) {
#if INFLUENCE2D_HAVE_BOX2D
    if (m == "box2d") return box2d_peer::applies(a, b);
#endif
    return method_available(m);
}

/// Runs d on poses[0], poses[stride], ...; answers into `answers` (one per
/// frame run); returns the seconds taken.
template <class D>
double run_frames(D& d, const std::vector<pose>& poses, std::size_t stride, std::vector<char>& answers) {
    answers.clear();
    answers.reserve(poses.size() / stride + 1);
    const auto t0 = clock::now();
    for (std::size_t k = 0; k < poses.size(); k += stride) answers.push_back(collides(d, poses[k]) ? 1 : 0);
    return std::chrono::duration<double>(clock::now() - t0).count();
}

/// The stride that keeps a run of d within `budget` seconds, from 8 evenly
/// spaced frames (1 when the whole trajectory fits).
template <class D>
std::size_t stride_for(D& d, const std::vector<pose>& poses, double budget) {
    const std::size_t probe = std::min<std::size_t>(8, poses.size());
    const auto t0 = clock::now();
    for (std::size_t k = 0; k < probe; ++k) (void)collides(d, poses[k * poses.size() / probe]);
    const double per_frame = std::chrono::duration<double>(clock::now() - t0).count() / static_cast<double>(probe);
    const double whole = per_frame * static_cast<double>(poses.size());
    if (whole <= budget) return 1;
    return static_cast<std::size_t>(std::ceil(whole / budget));
}

}  // namespace time_study_detail

/// The cells of a run, in the order they are run.
inline std::vector<time_cell> time_study_cells(const time_study_options& o) {
    std::vector<time_cell> cells;
    for (const std::string& t : o.types)
        for (const std::string& j : o.trajectories)
            for (std::size_t n : o.sizes)
                for (std::size_t m : o.sizes) cells.push_back({t, j, n, m});
    return cells;
}

/// The trajectory of a cell.
inline std::vector<pose> time_study_poses(const time_study_options& o, const time_cell& c, const polygon& a,
                                          const polygon& b) {
    if (c.trajectory == "circular") return circular_trajectory(a, b, o.circular_frames, o.gap);
    if (c.trajectory == "linear") return linear_trajectory(a, b, o.linear_frames, o.gap);
    throw std::invalid_argument("unknown trajectory: " + c.trajectory);
}

namespace time_study_detail {

/// The timed passes of one of influence2d's every-frame modes on a cell.
struct timed_passes {
    std::vector<char> answers;  ///< of the first pass
    std::size_t passes = 0;
    double median = 0;  ///< seconds of the median pass
};

/// Times influence2d's every-frame modes among o.methods (double, certified,
/// paper) on a cell: passes over every frame on fresh detectors, the modes
/// taking turns, until each has at least 3 passes (an odd number) and
/// `repeat_seconds` of them, or 101.
inline std::map<std::string, timed_passes> time_every_frame_modes(const time_study_options& o, const polygon& a,
                                                                  const polygon& b, const std::vector<pose>& poses) {
    std::vector<std::string> modes;
    for (const std::string& m : o.methods)
        if (is_own_method(m) && m != "exact" && applies(m, a, b)) modes.push_back(m);
    std::map<std::string, timed_passes> out;
    std::map<std::string, std::vector<double>> seconds;
    std::vector<char> repeated;
    for (std::size_t round = 0;; ++round) {
        bool more = round < 3 || round % 2 == 0;  // rounds done so far: at least 3, an odd number
        for (const std::string& m : modes) {
            double total = 0;
            for (double t : seconds[m]) total += t;
            more = more || (total < o.repeat_seconds && round < 101);
        }
        if (!more) break;
        for (const std::string& m : modes)
            with_method(m, a, b, [&](auto& fresh) {
                seconds[m].push_back(run_frames(fresh, poses, 1, round == 0 ? out[m].answers : repeated));
            });
    }
    for (const std::string& m : modes) {
        std::vector<double>& s = seconds[m];
        std::nth_element(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(s.size() / 2), s.end());
        out[m].passes = s.size();
        out[m].median = s[s.size() / 2];
    }
    return out;
}

}  // namespace time_study_detail

/// Runs the study.
inline time_study_result run_time_study(const time_study_options& o) {
    using namespace time_study_detail;
    for (const std::string& m : o.methods)
        if (std::find(time_study_methods().begin(), time_study_methods().end(), m) == time_study_methods().end())
            throw std::invalid_argument("unknown method: " + m);
    const auto start = clock::now();
    const std::vector<time_cell> cells = time_study_cells(o);
    time_study_result r;
    std::vector<char> reference, answers;
    for (std::size_t ci = 0; ci < cells.size(); ++ci) {
        const time_cell& c = cells[ci];
        if (o.progress) o.progress({ci, cells.size(), c});
        const family f = family_of(c.type);
        const polygon a = make_family_polygon(f, c.static_size, o.seed);
        const polygon b = make_family_polygon(f, c.moving_size, o.seed);
        const std::vector<pose> poses = time_study_poses(o, c, a, b);

        // The reference: the certified mode on every frame, in order (not
        // timed: the certified method's row is a run of its own, like every
        // other method's, after this pass has brought the poses into cache).
        with_method("certified", a, b, [&](auto& d) { (void)run_frames(d, poses, 1, reference); });
        const std::map<std::string, timed_passes> own = time_every_frame_modes(o, a, b, poses);
        for (const std::string& m : o.methods) {
            if (!applies(m, a, b)) continue;
            time_row row;
            row.cell = c;
            row.method = m;
            row.trajectory_frames = poses.size();
            row.reference = m == "certified";
            if (const auto t = own.find(m); t != own.end()) {
                answers = t->second.answers;
                row.passes = t->second.passes;
                row.seconds = t->second.median;
            } else {
                with_method(m, a, b, [&](auto& d) {
                    // The probe runs on a detector of its own: a detector with
                    // temporal coherence must start the timed run fresh.
                    with_method(m, a, b, [&](auto& probe) { row.stride = stride_for(probe, poses, o.budget); });
                    row.seconds = run_frames(d, poses, row.stride, answers);
                });
            }
            row.frames = answers.size();
            for (std::size_t k = 0; k < answers.size(); ++k) {
                row.collisions += answers[k] ? 1 : 0;
                row.disagreements += answers[k] != reference[k * row.stride] ? 1 : 0;
            }
            r.rows.push_back(row);
        }
    }

    // Peak heap per method on the largest cell: first type and trajectory,
    // largest sizes, memory_frames evenly spaced frames.
    if (heap_meter::available() && !cells.empty() && o.memory_frames > 0) {
        const std::size_t n = *std::max_element(o.sizes.begin(), o.sizes.end());
        const time_cell c{o.types.front(), o.trajectories.front(), n, n};
        const family f = family_of(c.type);
        const polygon a = make_family_polygon(f, c.static_size, o.seed);
        const polygon b = make_family_polygon(f, c.moving_size, o.seed);
        const std::vector<pose> poses = time_study_poses(o, c, a, b);
        const std::size_t stride = std::max<std::size_t>(1, poses.size() / o.memory_frames);
        for (const std::string& m : o.methods) {
            if (!applies(m, a, b)) continue;
            memory_row row{c, m, 0, 0};
            heap_meter::start();
            with_method(m, a, b, [&](auto& d) { (void)run_frames(d, poses, stride, answers); });
            row.peak_bytes = heap_meter::stop();
            row.frames = answers.size();
            r.memory.push_back(row);
        }
    }
    if (o.progress) o.progress({cells.size(), cells.size(), {}});
    r.seconds = std::chrono::duration<double>(clock::now() - start).count();
    return r;
}

}  // namespace influence2d::verification
