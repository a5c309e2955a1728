// SPDX-License-Identifier: BSL-1.0
#pragma once
// The time study's report (bench.md): the tables and paragraphs that say what
// a run of verification/time_study.hpp measured, from its rows read cell by
// cell (verification/time_study_cells.hpp).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "verification/report_text.hpp"
#include "verification/time_study.hpp"
#include "verification/time_study_cells.hpp"

namespace influence2d::verification {

/// The head of a markdown table: `first` (its leading cells, e.g. "| method
/// | form |", with `lead` columns) and one right-aligned column per size,
/// named by label(size).
inline std::string table_head(const std::string& first, std::size_t lead, const std::vector<std::size_t>& sizes,
                              const std::function<std::string(std::size_t)>& label) {
    std::string s = first;
    for (std::size_t n : sizes) s += " " + label(n) + " |";
    s += "\n|";
    for (std::size_t i = 0; i < lead; ++i) s += "---|";
    for (std::size_t i = 0; i < sizes.size(); ++i) s += "---:|";
    return s + "\n";
}

/// A square cell's name: n x n.
inline std::string square(std::size_t n) { return std::to_string(n) + "x" + std::to_string(n); }

/// A table per type: static size down, moving size across, entry(rows) in
/// each cell of the workload ("-" where empty).
inline std::string grid_tables(const cell_table& cells, const time_study_options& o, const std::string& workload,
                               const std::function<std::string(const cell_rows&)>& entry) {
    std::string s;
    for (const std::string& t : o.types) {
        s += "\n### " + t + ", " + workload + "\n\n" +
             table_head("| static \\ moving |", 1, o.sizes, [](std::size_t m) { return std::to_string(m); });
        for (std::size_t n : o.sizes) {
            s += "| " + std::to_string(n) + " |";
            for (std::size_t m : o.sizes) {
                std::string e;
                for (const auto& [c, rows] : cells)
                    if (c.type == t && c.trajectory == workload && c.static_size == n && c.moving_size == m)
                        e = entry(rows);
                s += " " + (e.empty() ? std::string("-") : e) + " |";
            }
            s += "\n";
        }
    }
    return s;
}

/// The machine: its CPU and hardware threads.
inline std::string machine_line() {
    std::string cpu = "unknown CPU";
    std::ifstream info("/proc/cpuinfo");
    for (std::string line; std::getline(info, line);)
        if (line.rfind("model name", 0) == 0) {
            cpu = line.substr(line.find(':') + 2);
            break;
        }
    return cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads (one used)";
}

/// A duration in microseconds, with digits for small ones.
inline std::string micros(double seconds) {
    const double us = seconds * 1e6;
    return fixed(us, us < 10 ? 2 : us < 100 ? 1 : 0);
}

/// What each workload of the run asks.
inline std::string workloads_paragraph(const time_study_options& o) {
    std::string s = "Workloads (the `trajectory` column of bench.csv):";
    for (const std::string& j : o.trajectories) {
        if (j == "circular")
            s += "\n- circular: the paper's orbit, " + std::to_string(o.circular_frames) +
                 " poses, never colliding (gap " + general(o.gap) + ");";
        if (j == "linear")
            s +=
                "\n- linear: the paper's approach, " + std::to_string(o.linear_frames) + " poses, ending in collision;";
        if (j == "random")
            s += "\n- random: " + std::to_string(o.random_frames) +
                 " independent poses near contact (influence2d::random_poses, seed " + std::to_string(o.seed) +
                 "): B's centroid uniform in area in the annulus " + general(o.random_inner) + " to " +
                 general(o.random_outer) +
                 " times R_A + R_B about A's centroid (R: bounding radii about the "
                 "centroids; about 40 to 110 for the families), B's angle uniform; each method built once for the pair "
                 "and asked every pose;";
        if (j == "one-shot")
            s += "\n- one-shot: the random poses, each a query of its own with nothing kept between queries: "
                 "influence2d's `intersects<double>` (method double), `certified_intersects` (certified), "
                 "`intersects<exact_rational>` (exact), a `detector<double>` built and asked once "
                 "(double-detector); Boost.Geometry `intersects` with the posed B built fresh, GEOS building "
                 "both geometries and asking `GEOSIntersects` (not prepared), CGAL's `do_intersect` on the "
                 "polygons with holes (B posed fresh), Box2D building both shapes and asking `b2TestOverlap`; "
                 "no input validation is timed;";
    }
    return s + "\n\n";
}

/// Where a double frame's time goes, from its detector's counters: per frame
/// workload, the cells below the target with their work; for the random
/// workload, the grid of that work.
inline std::string frame_work_section(const time_study_result& r, const cell_table& cells,
                                      const time_study_options& o) {
    if (r.work.empty()) return "";
    std::string s =
        "\n## What a double frame does\n\nCounters of a `detector<double>` run over every pose of the cell "
        "(untimed; bench_work.csv has them all). Per workload, the cells where double is below " +
        fixed(peer_target, 0) +
        "x the fastest peer, and what a frame did there on average: edge pairs handed to the pair tests by the trees "
        "or the box test, segment-pair decisions (every candidate pair in double, where a filter in double "
        "would only repeat the decision's signs), containment "
        "tests (a vertex of each ring located in the other polygon), frames answered by the bounding circles "
        "alone, frames with no coherence to use (both edge trees traversed).\n\n"
        "| workload | cells below " +
        fixed(peer_target, 0) +
        "x | median speed-up there | candidate pairs per frame | segment tests per frame | "
        "containment tests per frame | circle rejections | jump frames | double ns per pose (median) | "
        "fastest peer ns per pose (median) |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const std::string& j : o.trajectories) {
        if (is_one_shot(j)) continue;
        std::size_t below = 0, all = 0;
        std::vector<double> speedup, pairs, tests, located, circles, jumps, ns, peer_ns;
        for (const auto& [c, rows] : cells) {
            const work_row* w = c.trajectory == j ? work_on_cell(r, c) : nullptr;
            const double x = w ? peer_speedup(rows) : 0;
            if (!(x > 0)) continue;
            ++all;
            if (x >= peer_target) continue;
            ++below;
            speedup.push_back(x);
            pairs.push_back(per_frame(w->statistics.candidate_edges, *w));
            tests.push_back(per_frame(w->statistics.segment_tests, *w));
            located.push_back(per_frame(w->statistics.containment_tests, *w));
            circles.push_back(per_frame(w->statistics.circle_rejections, *w));
            jumps.push_back(per_frame(w->statistics.jump_frames, *w));
            ns.push_back(rows.at("double")->ns_per_frame());
            peer_ns.push_back(fastest_peer(rows)->ns_per_frame());
        }
        if (all == 0) continue;
        s += "| " + j + " | " + std::to_string(below) + " of " + std::to_string(all) + " | " +
             (below ? fixed(median_of(speedup), 1) + "x" : "-") + " | " + (below ? fixed(median_of(pairs), 1) : "-") +
             " | " + (below ? fixed(median_of(tests), 1) : "-") + " | " + (below ? fixed(median_of(located), 2) : "-") +
             " | " + (below ? fixed(100 * median_of(circles), 0) + "%" : "-") + " | " +
             (below ? fixed(100 * median_of(jumps), 0) + "%" : "-") + " | " + (below ? fixed(median_of(ns), 0) : "-") +
             " | " + (below ? fixed(median_of(peer_ns), 0) : "-") + " |\n";
    }
    if (has_name(o.trajectories, "random")) {
        s += "\nPer random cell: candidate pairs per frame / segment tests per frame / containment tests per frame / "
             "share of frames the "
             "bounding circles answered.\n";
        s += grid_tables(cells, o, "random", [&](const cell_rows& rows) {
            const work_row* w = work_on_cell(r, rows.begin()->second->cell);
            if (!w) return std::string();
            return fixed(per_frame(w->statistics.candidate_edges, *w), 1) + " / " +
                   fixed(per_frame(w->statistics.segment_tests, *w), 1) + " / " +
                   fixed(per_frame(w->statistics.containment_tests, *w), 2) + " / " +
                   fixed(100 * per_frame(w->statistics.circle_rejections, *w), 0) + "%";
        });
    }
    return s;
}

/// The time study's report in markdown (bench.md): the machine, the command
/// and the workloads; per workload and method the cells, poses, disagreements
/// and geometric means; the targets; per cell the speed-up of double over the
/// fastest peer and certified over double; what a double frame does; one-shot
/// against each peer; the preparation; the peak heap memory.
inline std::string time_study_markdown(const time_study_result& r, const time_study_options& o,
                                       const std::string& command) {
    const cell_table cells = rows_by_cell(r);
    std::string s = "# Time study\n\n";
    s += "Machine: " + machine_line() + ". Command: `" + command + "` (" + fixed(r.seconds, 0) + " s).\n\n";
    s += workloads_paragraph(o);
    s += "Timing: influence2d's double, certified and paper detectors (and on one-shot its double, certified and "
         "double-detector queries) run in repeated passes on fresh objects, taking turns pass by pass (at least " +
         std::to_string(o.repeated_passes) + " and until " + general(o.repeat_seconds) +
         " s; bench.csv: passes), of which the median pass counts; a "
         "detector's pass is every pose in order, a one-shot pass every k-th pose (a pass about " +
         general(o.budget / 3) +
         " s). The exact mode, the all-pairs test and the peers run every k-th pose, k "
         "chosen so that a pass takes about " +
         general(o.budget / 3) +
         " s (bench.csv: stride), in 3 passes taking turns with the others' first three, the median pass "
         "counting. Preparation: building "
         "the method for the pair (the detector's constructor, GEOS's prepared geometry, Boost's and CGAL's "
         "polygons, ...; a one-shot form keeps only its input), the methods taking turns, the median of at least 3 "
         "builds (bench.csv: preparation_seconds, preparation_builds). Every answer is compared with the "
         "reference, the exact answers of the certified detector on every pose.\n\n";

    const std::vector<std::string> missing = missing_methods();
    if (!missing.empty())
        s += "Peers this build lacks (their libraries were not found when it was built): " + joined(missing) + ".\n\n";

    // Per workload and method: cells, poses, disagreements, geometric means.
    s += "## Methods\n";
    for (const std::string& j : o.trajectories) {
        s += "\n### " + j +
             "\n\n| method | form | cells | poses run | disagreements | geometric mean ns per pose | "
             "geometric mean preparation us |\n|---|---|---:|---:|---:|---:|---:|\n";
        for (const std::string& m : o.methods) {
            std::size_t n = 0, frames = 0, wrong = 0;
            double log_ns = 0, log_prep = 0;
            bool reference = false;
            for (const time_row& row : r.rows)
                if (row.method == m && row.cell.trajectory == j) {
                    ++n;
                    frames += row.frames;
                    wrong += row.disagreements;
                    reference = reference || row.reference;
                    log_ns += std::log(std::max(row.ns_per_frame(), 1e-3));
                    log_prep += std::log(std::max(row.preparation_seconds, 1e-12));
                }
            if (n == 0) continue;
            const method_info& info = method_of(m);
            s += "| " + m + " | " + (is_one_shot(j) ? info.one_shot : info.frames) + " | " + std::to_string(n) + " | " +
                 std::to_string(frames) + " | " + (reference ? std::string("reference") : std::to_string(wrong)) +
                 " | " + fixed(std::exp(log_ns / static_cast<double>(n)), 0) + " | " +
                 micros(std::exp(log_prep / static_cast<double>(n))) + " |\n";
        }
    }

    // The image-space baseline: its error against its resolution and time.
    std::vector<std::string> rasters;
    for (const std::string& m : o.methods)
        if (method_of(m).approximate) rasters.push_back(m);
    if (!rasters.empty()) {
        s += "\n## The image-space baseline\n\nThe paper's own comparison (PIVOT2D): both polygons rasterised on a "
             "grid of R pixels along the longer side of A's box, a contact where a pixel centre lies in both "
             "(verification/raster.hpp). Disagreements with the exact answers, against its time per pose, beside the "
             "certified detector's time on the same cells.\n\n| workload | method | poses run | disagreements | "
             "share of poses | geometric mean ns per pose | certified's, same cells "
             "|\n|---|---|---:|---:|---:|---:|---:|"
             "\n";
        for (const std::string& j : o.trajectories) {
            std::string first_exact;
            for (const std::string& m : rasters) {
                const approximate_summary a = approximate_over_cells(cells, j, m);
                if (a.cells == 0) continue;
                if (a.wrong == 0 && first_exact.empty()) first_exact = m;
                s += "| " + j + " | " + m + " | " + std::to_string(a.frames) + " | " + std::to_string(a.wrong) + " | " +
                     fixed(100.0 * a.share_wrong(), 3) + "% | " + fixed(a.ns, 0) + " | " + fixed(a.certified_ns, 0) +
                     " |\n";
            }
            s += "| " + j + " | first resolution right on every pose run | " +
                 (first_exact.empty() ? std::string("none") : first_exact) + " | | | | |\n";
        }
    }

    // Targets, per workload.
    s += "\n## Targets\n\n";
    for (const std::string& j : o.trajectories) {
        const ratio_stats peer = ratios_over_cells(cells, j, peer_speedup);
        if (peer.n > 0)
            s += "- " + j + ": double against the fastest peer of each cell: geometric mean speed-up " +
                 fixed(peer.mean(), 1) + "x over " + std::to_string(peer.n) + " cells; slowest cell " + peer.lo_cell +
                 ": " + fixed(peer.lo, 2) + "x; cells where double is not faster: " + std::to_string(peer.at_most_one) +
                 ".\n";
        const ratio_stats cert =
            ratios_over_cells(cells, j, [](const cell_rows& rows) { return ns_ratio(rows, "certified", "double"); });
        if (cert.n > 0)
            s += "- " + j + ": certified against double: at most " + fixed(cert.hi, 2) + "x (" + cert.hi_cell +
                 "), geometric mean " + fixed(cert.mean(), 2) + "x.\n";
        if (is_one_shot(j)) {
            const ratio_stats boost = ratios_over_cells(
                cells, j, [](const cell_rows& rows) { return ns_ratio(rows, "boost_geometry", "double"); });
            if (boost.n > 0)
                s += "- one-shot: intersects<double> against Boost.Geometry intersects: geometric mean speed-up " +
                     fixed(boost.mean(), 1) + "x; slowest cell " + boost.lo_cell + ": " + fixed(boost.lo, 2) +
                     "x; cells where it is not faster: " + std::to_string(boost.at_most_one) + ".\n";
            const ratio_stats built = ratios_over_cells(
                cells, j, [](const cell_rows& rows) { return ns_ratio(rows, "double-detector", "double"); });
            if (built.n > 0)
                s += "- one-shot: a detector<double> built for one query costs " + fixed(built.mean(), 1) +
                     " times intersects<double> in the geometric mean (" + fixed(built.lo, 2) + " to " +
                     fixed(built.hi, 2) + ").\n";
            continue;
        }
        const std::size_t lo = *std::min_element(o.sizes.begin(), o.sizes.end());
        const std::size_t hi = *std::max_element(o.sizes.begin(), o.sizes.end());
        if (hi == lo) continue;
        for (const std::string& t : o.types) {
            const time_row *small = nullptr, *corner = nullptr;
            for (const auto& [c, rows] : cells)
                if (c.type == t && c.trajectory == j && rows.count("double")) {
                    if (c.static_size == lo && c.moving_size == lo) small = rows.at("double");
                    if (c.static_size == hi && c.moving_size == lo) corner = rows.at("double");
                }
            if (small && corner)
                s += "- Weak corner, " + t + " " + j + ": double " + std::to_string(hi) + "x" + std::to_string(lo) +
                     " costs " + fixed(corner->ns_per_frame() / std::max(small->ns_per_frame(), 1e-3), 2) + " times " +
                     std::to_string(lo) + "x" + std::to_string(lo) + " per pose.\n";
        }
    }

    // Per cell: double over the fastest peer, certified over double.
    s += "\n## Speed-up of the double mode over the fastest peer\n\nRows: static vertices; columns: moving "
         "vertices. Each entry: the fastest peer's ns per pose / double's ns per pose (on one-shot: the one-shot "
         "forms).\n";
    for (const std::string& j : o.trajectories)
        s += grid_tables(cells, o, j, [](const cell_rows& rows) {
            const double x = peer_speedup(rows);
            return x > 0 ? fixed(x, 1) + " (" + fastest_peer(rows)->method + ")" : std::string();
        });
    if (has_name(o.methods, "certified") && has_name(o.methods, "double")) {
        s += "\n## Certified over double\n\nEach entry: certified's ns per pose / double's (on one-shot: "
             "certified_intersects / intersects<double>).\n";
        for (const std::string& j : o.trajectories)
            s += grid_tables(cells, o, j, [](const cell_rows& rows) {
                const double x = ns_ratio(rows, "certified", "double");
                return x > 0 ? fixed(x, 2) : std::string();
            });
    }

    s += frame_work_section(r, cells, o);

    // One-shot against each peer.
    if (has_name(o.trajectories, "one-shot") && has_name(o.methods, "double")) {
        s += "\n## One-shot against each peer\n\nThe peer's ns per query / intersects<double>'s: geometric mean over "
             "the cells of the type (the slowest cell's ratio in brackets).\n\n| against |";
        for (const std::string& t : o.types) s += " " + t + " |";
        s += "\n|---|";
        for (std::size_t i = 0; i < o.types.size(); ++i) s += "---:|";
        s += "\n";
        for (const std::string& m : o.methods) {
            if (m == "double" || !runs_on(m, "one-shot")) continue;
            std::string line = "| " + m + " |";
            bool any = false;
            for (const std::string& t : o.types) {
                const ratio_stats x = ratios_over_cells(
                    cells, "one-shot", [&](const cell_rows& rows) { return ns_ratio(rows, m, "double"); }, t);
                any = any || x.n > 0;
                line += " " + (x.n ? fixed(x.mean(), 2) + " (" + fixed(x.lo, 2) + ")" : std::string("-")) + " |";
            }
            if (any) s += line + "\n";
        }
        if (has_name(o.methods, "boost_geometry")) {
            s += "\nPer cell, Boost.Geometry intersects' ns per query / intersects<double>'s:\n";
            s += grid_tables(cells, o, "one-shot", [](const cell_rows& rows) {
                const double x = ns_ratio(rows, "boost_geometry", "double");
                return x > 0 ? fixed(x, 1) : std::string();
            });
        }
    }

    // Preparation: per method and form, square cells (n x n), the median over types and workloads.
    s += "\n## Preparation\n\nMedian build of each method for the pair, in microseconds (the median over polygon "
         "types and workloads of each cell's median build; every cell's figure is in bench.csv). A one-shot form "
         "keeps only its input.\n\n" +
         table_head("| method | form |", 2, o.sizes, square);
    for (const bool one_shot : {false, true})
        for (const std::string& m : o.methods) {
            std::string line = "| " + m + " | " + (one_shot ? "one-shot" : "frames") + " |";
            bool any = false;
            for (std::size_t n : o.sizes) {
                std::vector<double> v;
                for (const time_row& row : r.rows)
                    if (row.method == m && is_one_shot(row.cell.trajectory) == one_shot && row.cell.static_size == n &&
                        row.cell.moving_size == n)
                        v.push_back(row.preparation_seconds);
                any = any || !v.empty();
                line += " " + (v.empty() ? std::string("-") : micros(median_of(v))) + " |";
            }
            if (any) s += line + "\n";
        }
    if (has_name(o.trajectories, "random") && has_name(o.trajectories, "one-shot") && has_name(o.methods, "double")) {
        // Poses after which a detector built once beats one-shot queries:
        // preparation / (one-shot ns - detector's ns per pose), random poses.
        s += "\nQueries of one pair after which a detector<double> built once beats intersects<double> on the random "
             "poses (its preparation / (one-shot ns per query - the detector's ns per pose); the median over "
             "types):\n\n" +
             table_head("| |", 1, o.sizes, square) + "| queries |";
        for (std::size_t n : o.sizes) {
            std::vector<double> v;
            for (const std::string& t : o.types) {
                const time_row *frames = nullptr, *once = nullptr;
                for (const auto& [c, rows] : cells)
                    if (c.type == t && c.static_size == n && c.moving_size == n && rows.count("double")) {
                        if (c.trajectory == "random") frames = rows.at("double");
                        if (c.trajectory == "one-shot") once = rows.at("double");
                    }
                if (frames && once)
                    v.push_back(once->ns_per_frame() > frames->ns_per_frame()
                                    ? frames->preparation_seconds * 1e9 /
                                          (once->ns_per_frame() - frames->ns_per_frame())
                                    : HUGE_VAL);
            }
            const double q = median_of(v);
            s += " " + (v.empty() ? std::string("-") : std::isinf(q) ? std::string("never") : fixed(q, 0)) + " |";
        }
        s += "\n";
    }

    if (!r.memory.empty()) {
        const time_cell& c = r.memory.front().cell;
        s += "\n## Peak heap memory, " + cell_name(c) +
             "\n\nHeap bytes live at the peak, from building the method "
             "(A prepared, B read) to its last pose, over " +
             std::to_string(r.memory.front().frames) +
             " evenly spaced poses (operator new and GMP counted; Box2D's malloc is not).\n\n| method | peak heap |\n"
             "|---|---:|\n";
        for (const memory_row& m : r.memory)
            s += "| " + m.method + " | " + fixed(static_cast<double>(m.peak_bytes) / 1024.0, 1) + " KiB |\n";
    }
    return s;
}

}  // namespace influence2d::verification
