// SPDX-License-Identifier: BSL-1.0
// `influence2d bench`: the paper's time study (verification/time_study.hpp)
// against the libraries a user would pick instead, on the paper's trajectories,
// on random poses near contact and as one-shot queries; writes bench.csv,
// bench.md (per workload: our speed-up over the fastest peer per cell,
// certified against double, one-shot against each peer, the preparation of
// each method, the targets, peak memory) and heat maps in the style of the
// paper's Figure 12.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "commands.hpp"
#include "report.hpp"
#include "verification/time_study.hpp"

namespace influence2d::cli {

namespace {

namespace fs = std::filesystem;
using namespace influence2d::verification;

struct bench_cli_options {
    std::vector<std::string> types, trajectories, methods;
    std::vector<std::size_t> sizes;
    std::size_t circular_frames = 90000, linear_frames = 9000, random_frames = 20000;
    double budget = 0.25;
    std::uint64_t seed = default_family_seed;
    std::string out = "bench";
    bool quick = false;
    bool progress = false;
};

std::string cell_name(const time_cell& c) {
    return c.type + "/" + c.trajectory + "/" + std::to_string(c.static_size) + "x" + std::to_string(c.moving_size);
}

std::string bench_csv(const time_study_result& r) {
    std::string s =
        "type,trajectory,static,moving,method,trajectory_frames,frames,stride,passes,total_seconds,ns_per_frame,"
        "collisions,disagreements,preparation_seconds,preparation_builds\n";
    for (const time_row& row : r.rows)
        s += row.cell.type + "," + row.cell.trajectory + "," + std::to_string(row.cell.static_size) + "," +
             std::to_string(row.cell.moving_size) + "," + row.method + "," + std::to_string(row.trajectory_frames) +
             "," + std::to_string(row.frames) + "," + std::to_string(row.stride) + "," + std::to_string(row.passes) +
             "," + general(row.seconds) + "," + fixed(row.ns_per_frame(), 1) + "," + std::to_string(row.collisions) +
             "," + (row.reference ? std::string("reference") : std::to_string(row.disagreements)) + "," +
             general(row.preparation_seconds) + "," + std::to_string(row.preparation_builds) + "\n";
    return s;
}

/// The rows of one cell, by method.
using cell_rows = std::map<std::string, const time_row*>;
using cells_t = std::vector<std::pair<time_cell, cell_rows>>;

cells_t by_cell(const time_study_result& r) {
    cells_t cells;
    for (const time_row& row : r.rows) {
        if (cells.empty() || cell_name(cells.back().first) != cell_name(row.cell)) cells.push_back({row.cell, {}});
        cells.back().second[row.method] = &row;
    }
    return cells;
}

/// The fastest peer of a cell (nullptr if no peer ran).
const time_row* fastest_peer(const cell_rows& rows) {
    const time_row* best = nullptr;
    for (const auto& [m, row] : rows)
        if (!is_own_method(m) && (!best || row->ns_per_frame() < best->ns_per_frame())) best = row;
    return best;
}

/// a's ns per pose over b's, or 0 when either is missing.
double ratio(const cell_rows& rows, const std::string& a, const std::string& b) {
    if (!rows.count(a) || !rows.count(b)) return 0;
    return rows.at(a)->ns_per_frame() / std::max(rows.at(b)->ns_per_frame(), 1e-3);
}

/// The fastest peer's ns per pose over double's, or 0.
double peer_speedup(const cell_rows& rows) {
    const time_row* peer = fastest_peer(rows);
    if (!peer || !rows.count("double")) return 0;
    return peer->ns_per_frame() / std::max(rows.at("double")->ns_per_frame(), 1e-3);
}

/// Ratios over cells: geometric mean, extremes and where, how many at most 1.
struct ratio_stats {
    std::size_t n = 0, at_most_one = 0;
    double log_sum = 0, lo = HUGE_VAL, hi = 0;
    std::string lo_cell, hi_cell;
    void add(double x, const std::string& where) {
        if (!(x > 0)) return;
        ++n;
        log_sum += std::log(x);
        at_most_one += x <= 1 ? 1 : 0;
        if (x < lo) lo = x, lo_cell = where;
        if (x > hi) hi = x, hi_cell = where;
    }
    double mean() const { return n ? std::exp(log_sum / static_cast<double>(n)) : 0; }
};

/// The ratios f(rows) over the cells of a workload (and type, if given).
ratio_stats stats_of(const cells_t& cells, const std::string& workload, const std::function<double(const cell_rows&)>& f,
                     const std::string& type = "") {
    ratio_stats s;
    for (const auto& [c, rows] : cells)
        if (c.trajectory == workload && (type.empty() || c.type == type)) s.add(f(rows), cell_name(c));
    return s;
}

/// The head of a markdown table: `first` (its leading cells, e.g. "| method
/// | form |", with `lead` columns) and one right-aligned column per size,
/// named by label(size).
std::string table_head(const std::string& first, std::size_t lead, const std::vector<std::size_t>& sizes,
                       const std::function<std::string(std::size_t)>& label) {
    std::string s = first;
    for (std::size_t n : sizes) s += " " + label(n) + " |";
    s += "\n|";
    for (std::size_t i = 0; i < lead; ++i) s += "---|";
    for (std::size_t i = 0; i < sizes.size(); ++i) s += "---:|";
    return s + "\n";
}

std::string square(std::size_t n) { return std::to_string(n) + "x" + std::to_string(n); }

/// A table per type: static size down, moving size across, entry(rows) in
/// each cell of the workload ("-" where empty).
std::string grid_tables(const cells_t& cells, const time_study_options& o, const std::string& workload,
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

std::string machine_line() {
    std::string cpu = "unknown CPU";
    std::ifstream info("/proc/cpuinfo");
    for (std::string line; std::getline(info, line);)
        if (line.rfind("model name", 0) == 0) {
            cpu = line.substr(line.find(':') + 2);
            break;
        }
    return cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads (one used)";
}

bool has(const std::vector<std::string>& v, const std::string& x) { return std::find(v.begin(), v.end(), x) != v.end(); }

/// A duration in microseconds, with digits for small ones.
std::string micros(double seconds) {
    const double us = seconds * 1e6;
    return fixed(us, us < 10 ? 2 : us < 100 ? 1 : 0);
}

/// The median of some values (0 for none).
double median_of(std::vector<double> v) {
    if (v.empty()) return 0;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

std::string workloads_paragraph(const time_study_options& o) {
    std::string s = "Workloads (the `trajectory` column of bench.csv):";
    for (const std::string& j : o.trajectories) {
        if (j == "circular")
            s += "\n- circular: the paper's orbit, " + std::to_string(o.circular_frames) + " poses, never colliding (gap " +
                 general(o.gap) + ");";
        if (j == "linear")
            s += "\n- linear: the paper's approach, " + std::to_string(o.linear_frames) + " poses, ending in collision;";
        if (j == "random")
            s += "\n- random: " + std::to_string(o.random_frames) +
                 " independent poses near contact (influence2d::random_poses, seed " + std::to_string(o.seed) +
                 "): B's centroid uniform in area in the annulus " + general(o.random_inner) + " to " +
                 general(o.random_outer) + " times R_A + R_B about A's centroid (R: bounding radii about the "
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

/// The double detector's counters on a cell (nullptr when it did not run there).
const work_row* work_of(const time_study_result& r, const time_cell& c) {
    for (const work_row& w : r.work)
        if (cell_name(w.cell) == cell_name(c)) return &w;
    return nullptr;
}

/// A counter per frame.
double per_frame(std::size_t count, const work_row& w) {
    return static_cast<double>(count) / static_cast<double>(std::max<std::size_t>(w.frames, 1));
}

/// The speed-up the time study aims at on every cell of a frame workload.
constexpr double peer_target = 10;

/// Where a double frame's time goes, from its detector's counters: per frame
/// workload, the cells below the target with their work; for the random
/// workload, the grid of that work.
std::string frame_work_section(const time_study_result& r, const cells_t& cells, const time_study_options& o) {
    if (r.work.empty()) return "";
    std::string s =
        "\n## What a double frame does\n\nCounters of a `detector<double>` run over every pose of the cell "
        "(untimed; bench_work.csv has them all). Per workload, the cells where double is below " +
        fixed(peer_target, 0) +
        "x the fastest peer, and what a frame did there on average: edge pairs handed to the pair tests by the trees or the box test, exact segment-pair tests (after "
        "the double filter), containment "
        "tests (a vertex of each ring located in the other polygon), frames answered by the bounding circles "
        "alone, frames with no coherence to use (both edge trees traversed).\n\n"
        "| workload | cells below " + fixed(peer_target, 0) + "x | median speed-up there | candidate pairs per frame | segment tests per frame | "
        "containment tests per frame | circle rejections | jump frames | double ns per pose (median) | "
        "fastest peer ns per pose (median) |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const std::string& j : o.trajectories) {
        if (is_one_shot(j)) continue;
        std::size_t below = 0, all = 0;
        std::vector<double> speedup, pairs, tests, located, circles, jumps, ns, peer_ns;
        for (const auto& [c, rows] : cells) {
            const work_row* w = c.trajectory == j ? work_of(r, c) : nullptr;
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
             " | " + (below ? fixed(median_of(tests), 1) : "-") +
             " | " + (below ? fixed(median_of(located), 2) : "-") + " | " +
             (below ? fixed(100 * median_of(circles), 0) + "%" : "-") + " | " +
             (below ? fixed(100 * median_of(jumps), 0) + "%" : "-") + " | " + (below ? fixed(median_of(ns), 0) : "-") +
             " | " + (below ? fixed(median_of(peer_ns), 0) : "-") + " |\n";
    }
    if (has(o.trajectories, "random")) {
        s += "\nPer random cell: candidate pairs per frame / segment tests per frame / containment tests per frame / share of frames the "
             "bounding circles answered.\n";
        s += grid_tables(cells, o, "random", [&](const cell_rows& rows) {
            const work_row* w = work_of(r, rows.begin()->second->cell);
            if (!w) return std::string();
            return fixed(per_frame(w->statistics.candidate_edges, *w), 1) + " / " +
                   fixed(per_frame(w->statistics.segment_tests, *w), 1) + " / " +
                   fixed(per_frame(w->statistics.containment_tests, *w), 2) + " / " +
                   fixed(100 * per_frame(w->statistics.circle_rejections, *w), 0) + "%";
        });
    }
    return s;
}

/// The double detector's counters per cell, as CSV.
std::string work_csv(const time_study_result& r) {
    std::string s =
        "type,trajectory,static,moving,frames,circle_rejections,jump_frames,tree_frames,candidate_rebuilds,"
        "candidate_edges,disc_rejections,segment_tests,containment_tests\n";
    for (const work_row& w : r.work) {
        const detector_statistics& t = w.statistics;
        s += w.cell.type + "," + w.cell.trajectory + "," + std::to_string(w.cell.static_size) + "," +
             std::to_string(w.cell.moving_size) + "," + std::to_string(w.frames) + "," +
             std::to_string(t.circle_rejections) + "," + std::to_string(t.jump_frames) + "," +
             std::to_string(t.tree_frames) + "," + std::to_string(t.candidate_rebuilds) + "," +
             std::to_string(t.candidate_edges) + "," + std::to_string(t.disc_rejections) + "," +
             std::to_string(t.segment_tests) + "," + std::to_string(t.containment_tests) + "\n";
    }
    return s;
}

std::string bench_md(const time_study_result& r, const time_study_options& o, const std::string& command) {
    const cells_t cells = by_cell(r);
    std::string s = "# Time study\n\n";
    s += "Machine: " + machine_line() + ". Command: `" + command + "` (" + fixed(r.seconds, 0) + " s).\n\n";
    s += workloads_paragraph(o);
    s += "Timing: influence2d's double, certified and paper detectors (and on one-shot its double, certified and "
         "double-detector queries) run in repeated passes on fresh objects, taking turns pass by pass (at least 3, "
         "until " + general(o.repeat_seconds) + " s; bench.csv: passes), of which the median pass counts; a "
         "detector's pass is every pose in order, a one-shot pass every k-th pose (a pass about " +
         general(o.budget / 3) + " s). The exact mode, the all-pairs test and the peers run every k-th pose, k "
         "chosen so that a run takes about " + general(o.budget) + " s (bench.csv: stride). Preparation: building "
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
        s += "\n### " + j + "\n\n| method | form | cells | poses run | disagreements | geometric mean ns per pose | "
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
            s += "| " + m + " | " + (is_one_shot(j) ? info.one_shot : info.frames) + " | " + std::to_string(n) +
                 " | " + std::to_string(frames) + " | " +
                 (reference ? std::string("reference") : std::to_string(wrong)) + " | " +
                 fixed(std::exp(log_ns / static_cast<double>(n)), 0) + " | " +
                 micros(std::exp(log_prep / static_cast<double>(n))) + " |\n";
        }
    }

    // Targets, per workload.
    s += "\n## Targets\n\n";
    for (const std::string& j : o.trajectories) {
        const ratio_stats peer = stats_of(cells, j, peer_speedup);
        if (peer.n > 0)
            s += "- " + j + ": double against the fastest peer of each cell: geometric mean speed-up " +
                 fixed(peer.mean(), 1) + "x over " + std::to_string(peer.n) + " cells; slowest cell " + peer.lo_cell +
                 ": " + fixed(peer.lo, 2) + "x; cells where double is not faster: " +
                 std::to_string(peer.at_most_one) + ".\n";
        const ratio_stats cert = stats_of(cells, j, [](const cell_rows& rows) { return ratio(rows, "certified", "double"); });
        if (cert.n > 0)
            s += "- " + j + ": certified against double: at most " + fixed(cert.hi, 2) + "x (" + cert.hi_cell +
                 "), geometric mean " + fixed(cert.mean(), 2) + "x.\n";
        if (is_one_shot(j)) {
            const ratio_stats boost =
                stats_of(cells, j, [](const cell_rows& rows) { return ratio(rows, "boost_geometry", "double"); });
            if (boost.n > 0)
                s += "- one-shot: intersects<double> against Boost.Geometry intersects: geometric mean speed-up " +
                     fixed(boost.mean(), 1) + "x; slowest cell " + boost.lo_cell + ": " + fixed(boost.lo, 2) +
                     "x; cells where it is not faster: " + std::to_string(boost.at_most_one) + ".\n";
            const ratio_stats built =
                stats_of(cells, j, [](const cell_rows& rows) { return ratio(rows, "double-detector", "double"); });
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
                     " costs " + fixed(corner->ns_per_frame() / std::max(small->ns_per_frame(), 1e-3), 2) +
                     " times " + std::to_string(lo) + "x" + std::to_string(lo) + " per pose.\n";
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
    if (has(o.methods, "certified") && has(o.methods, "double")) {
        s += "\n## Certified over double\n\nEach entry: certified's ns per pose / double's (on one-shot: "
             "certified_intersects / intersects<double>).\n";
        for (const std::string& j : o.trajectories)
            s += grid_tables(cells, o, j, [](const cell_rows& rows) {
                const double x = ratio(rows, "certified", "double");
                return x > 0 ? fixed(x, 2) : std::string();
            });
    }

    s += frame_work_section(r, cells, o);

    // One-shot against each peer.
    if (has(o.trajectories, "one-shot") && has(o.methods, "double")) {
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
                const ratio_stats x = stats_of(
                    cells, "one-shot", [&](const cell_rows& rows) { return ratio(rows, m, "double"); }, t);
                any = any || x.n > 0;
                line += " " + (x.n ? fixed(x.mean(), 2) + " (" + fixed(x.lo, 2) + ")" : std::string("-")) + " |";
            }
            if (any) s += line + "\n";
        }
        if (has(o.methods, "boost_geometry")) {
            s += "\nPer cell, Boost.Geometry intersects' ns per query / intersects<double>'s:\n";
            s += grid_tables(cells, o, "one-shot", [](const cell_rows& rows) {
                const double x = ratio(rows, "boost_geometry", "double");
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
    if (has(o.trajectories, "random") && has(o.trajectories, "one-shot") && has(o.methods, "double")) {
        // Poses after which a detector built once beats one-shot queries:
        // preparation / (one-shot ns - detector's ns per pose), random poses.
        s += "\nQueries of one pair after which a detector<double> built once beats intersects<double> on the random "
             "poses (its preparation / (one-shot ns per query - the detector's ns per pose); the median over "
             "types):\n\n" + table_head("| |", 1, o.sizes, square) + "| queries |";
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
                                    ? frames->preparation_seconds * 1e9 / (once->ns_per_frame() - frames->ns_per_frame())
                                    : HUGE_VAL);
            }
            const double q = median_of(v);
            s += " " + (v.empty() ? std::string("-") : std::isinf(q) ? std::string("never") : fixed(q, 0)) + " |";
        }
        s += "\n";
    }

    if (!r.memory.empty()) {
        const time_cell& c = r.memory.front().cell;
        s += "\n## Peak heap memory, " + cell_name(c) + "\n\nHeap bytes live at the peak, from building the method "
             "(A prepared, B read) to its last pose, over " + std::to_string(r.memory.front().frames) +
             " evenly spaced poses (operator new and GMP counted; Box2D's malloc is not).\n\n| method | peak heap |\n"
             "|---|---:|\n";
        for (const memory_row& m : r.memory)
            s += "| " + m.method + " | " + fixed(static_cast<double>(m.peak_bytes) / 1024.0, 1) + " KiB |\n";
    }
    return s;
}

/// The heat maps of the workloads `group`, one per method (file
/// heatmap_<prefix><method>.png): seconds for all the workload's poses (ns per
/// pose times its poses), a panel per type and workload, on one logarithmic
/// colour scale for every method of the group. Returns the gnuplot script.
std::string heat_maps(const time_study_result& r, const time_study_options& o, const fs::path& dir,
                      const std::vector<std::string>& group, const std::string& prefix) {
    std::vector<std::string> workloads;
    for (const std::string& j : o.trajectories)
        if (has(group, j)) workloads.push_back(j);
    const auto in_group = [&](const time_row& row) { return has(workloads, row.cell.trajectory); };
    double lo = HUGE_VAL, hi = 0;
    for (const time_row& row : r.rows) {
        const double t = row.ns_per_frame() * 1e-9 * static_cast<double>(row.trajectory_frames);
        if (in_group(row) && t > 0) {
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
    }
    if (!(hi > 0)) return "";
    std::string script;
    const std::size_t columns = o.types.size(), rows_n = workloads.size();
    for (const std::string& m : o.methods) {
        if (std::none_of(r.rows.begin(), r.rows.end(),
                         [&](const time_row& row) { return row.method == m && in_group(row); }))
            continue;
        const std::string what = workloads.size() == 1 && workloads[0] == "one-shot" ? "seconds per " +
                                                                                            std::to_string(o.random_frames) + " queries"
                                                                                      : "seconds per workload";
        script += "set terminal pngcairo size " + std::to_string(250 * columns + 120) + "," +
                  std::to_string(250 * rows_n + 60) + " font 'sans,9' background '#ffffff'\n";
        script += "set output '" + (dir / ("heatmap_" + prefix + m + ".png")).string() + "'\n";
        script += "set multiplot layout " + std::to_string(rows_n) + "," + std::to_string(columns) + " title '" + m +
                  ": " + what + " (log colour scale, the same for every method)'\n";
        script += "set logscale cb\nset format cb '%g'\nset cbrange [" + general(lo) + ":" + general(hi) + "]\n";
        script += "set palette defined (0 '#1a9850', 1 '#fee08b', 2 '#d73027')\nunset key\n";
        script += "set xlabel 'static vertices'\nset ylabel 'moving vertices'\n";
        std::string tics;
        for (std::size_t i = 0; i < o.sizes.size(); ++i)
            tics += (i ? ", " : "") + std::string("'") + std::to_string(o.sizes[i]) + "' " + std::to_string(i);
        script += "set xtics (" + tics + ") rotate by 90 right\nset ytics (" + tics + ")\n";
        script += "set xrange [-0.5:" + std::to_string(o.sizes.size()) + "-0.5]\nset yrange [-0.5:" +
                  std::to_string(o.sizes.size()) + "-0.5]\n";
        for (const std::string& j : workloads)
            for (const std::string& t : o.types) {
                // One colour box, beside the last panel of each row.
                script += std::string(t == o.types.back() ? "set colorbox\n" : "unset colorbox\n");
                script += "set title '" + t + ", " + j + "'\n$d << EOD\n";
                std::size_t points = 0;
                for (const time_row& row : r.rows) {
                    if (row.method != m || row.cell.type != t || row.cell.trajectory != j) continue;
                    const auto at = [&](std::size_t n) {
                        return std::find(o.sizes.begin(), o.sizes.end(), n) - o.sizes.begin();
                    };
                    const double secs =
                        std::max(row.ns_per_frame() * 1e-9 * static_cast<double>(row.trajectory_frames), lo);
                    script += std::to_string(at(row.cell.static_size)) + " " +
                              std::to_string(at(row.cell.moving_size)) + " " + general(secs) + "\n";
                    ++points;
                }
                script += "EOD\n";
                script += points ? "plot $d using 1:2:(0.5):(0.5):3 with boxxyerror fillstyle solid 1.0 noborder lc "
                                   "palette\n"
                                 : "set label 1 'not applicable' at graph 0.5, graph 0.5 center\nplot NaN\nunset label 1\n";
            }
        script += "unset multiplot\n";
    }
    return script;
}

/// Every heat map: the paper's trajectories together (heatmap_<method>.png),
/// random poses (heatmap_random_<method>.png), one-shot queries
/// (heatmap_one-shot_<method>.png).
void write_heat_maps(const time_study_result& r, const time_study_options& o, const fs::path& dir) {
    const std::string script = heat_maps(r, o, dir, {"circular", "linear"}, "") +
                               heat_maps(r, o, dir, {"random"}, "random_") +
                               heat_maps(r, o, dir, {"one-shot"}, "one-shot_");
    if (!script.empty()) plot_with_gnuplot(dir / "heatmaps.gp", script, "bench");
}

/// `given(name)`: whether the option was on the command line.
template <class Given>
void run_bench_command(bench_cli_options o, Given given, const std::string& command) {
    time_study_options so;
    check_names(o.types, so.types, "types");
    check_names(o.trajectories, known_trajectories(), "trajectories");
    check_names(o.methods, known_methods(), "methods");
    check_methods(o.methods);
    for (std::size_t n : o.sizes)
        if (n < 8 || n > 1024 || (n & (n - 1)) != 0)
            throw std::invalid_argument("--sizes: " + std::to_string(n) + " is not a power of two from 8 to 1024");
    if (o.quick) {
        so.sizes = {8, 1024};
        so.circular_frames = 9000;
        so.linear_frames = 900;
        so.random_frames = 2000;
        so.budget = 0.02;
        so.memory_frames = 100;
    }
    if (!o.types.empty()) so.types = o.types;
    if (!o.trajectories.empty()) so.trajectories = o.trajectories;
    if (!o.methods.empty()) so.methods = o.methods;
    if (!o.sizes.empty()) so.sizes = o.sizes;
    if (!o.quick || given("--circular-frames")) so.circular_frames = o.circular_frames;
    if (!o.quick || given("--linear-frames")) so.linear_frames = o.linear_frames;
    if (!o.quick || given("--random-frames")) so.random_frames = o.random_frames;
    if (!o.quick || given("--budget")) so.budget = o.budget;
    so.seed = o.seed;

    const fs::path dir = output_directory(o.out);
    if (auto report = progress_reporter(o.progress)) {
        so.progress = [report](const time_study_progress& p) {
            const bool done = p.cell == p.cells;
            report(done ? "bench: " + std::to_string(p.cells) + " cells done"
                        : "bench: cell " + std::to_string(p.cell + 1) + "/" + std::to_string(p.cells) + " (" +
                              cell_name(p.at) + ")",
                   done, p.cell % 16 == 0);
        };
    }
    const time_study_result r = run_time_study(so);
    write_atomically(dir / "bench.csv", bench_csv(r));
    if (!r.work.empty()) write_atomically(dir / "bench_work.csv", work_csv(r));
    const std::string md = bench_md(r, so, command);
    write_atomically(dir / "bench.md", md);
    write_heat_maps(r, so, dir);
    const std::size_t targets = md.find("## Targets"), end = md.find("\n## ", targets + 1);
    std::cout << md.substr(targets, end - targets) << "\nwritten: " << (dir / "bench.csv").string() << ", "
              << (dir / "bench.md").string() << ", heat maps " << (dir / "heatmap_*.png").string() << "\n";
}

/// The methods for --help, from the registry: name, forms, what it needs.
std::string methods_help() {
    std::string s = "Methods (frame form on circular, linear and random; one-shot form on one-shot):\n";
    for (const method_info& m : method_infos()) {
        s += "  " + std::string(m.name) + (m.own ? "" : " (peer)") + (m.available ? "" : " [not in this build]") +
             "\n";
        if (*m.frames) s += "      frames:   " + std::string(m.frames) + "\n";
        if (*m.one_shot) s += "      one-shot: " + std::string(m.one_shot) + "\n";
    }
    return s;
}

}  // namespace

void register_bench(CLI::App& app) {
    auto o = std::make_shared<bench_cli_options>();
    CLI::App* sub = app.add_subcommand(
        "bench",
        "The paper's time study against Boost.Geometry, GEOS, CGAL, Box2D and an all-pairs test, on the same "
        "poses: the paper's trajectories, random poses near contact and one-shot queries; DIR/bench.csv, "
        "DIR/bench.md (speed-ups, preparation, targets, peak memory) and heat maps (with gnuplot).");
    const time_study_options d;
    sub->add_option("--types", o->types, "Polygon types, separated by commas [default: " + joined(d.types) + "]")
        ->delimiter(',')
        ->type_name("LIST");
    sub->add_option("--trajectories", o->trajectories,
                    "Workloads, separated by commas: " + joined(known_trajectories()) +
                        " [default: all]; random and one-shot ask the same random poses")
        ->delimiter(',')
        ->type_name("LIST");
    sub->add_option("--methods", o->methods,
                    "Methods, separated by commas [default: " + joined(time_study_methods()) +
                        "]; the certified detector always runs, as the reference")
        ->delimiter(',')
        ->type_name("LIST");
    sub->add_option("--sizes", o->sizes, "Vertex counts, powers of two from 8 to 1024 [default: 8,16,...,1024]")
        ->delimiter(',')
        ->type_name("LIST");
    sub->add_option("--circular-frames", o->circular_frames, "Poses of the circular trajectory")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t{8}, std::size_t{1} << 30))
        ->type_name("N");
    sub->add_option("--linear-frames", o->linear_frames, "Poses of the linear trajectory")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t{8}, std::size_t{1} << 30))
        ->type_name("N");
    sub->add_option("--random-frames", o->random_frames, "Random poses (the random and the one-shot workloads)")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t{8}, std::size_t{1} << 30))
        ->type_name("N");
    sub->add_option("--budget", o->budget,
                    "Seconds per cell for the exact mode, the all-pairs test and each peer, which run every k-th "
                    "pose to fit")
        ->capture_default_str()
        ->check(CLI::Range(1e-3, 1e6))
        ->type_name("S");
    sub->add_option("--seed", o->seed, "Seed of the family polygons and of the random poses")
        ->capture_default_str()
        ->type_name("S");
    sub->add_option("--out", o->out, "Output directory, created if missing")->capture_default_str()->type_name("DIR");
    sub->add_flag("--quick", o->quick,
                  "A CI-sized run: sizes 8 and 1024, 9,000 circular, 900 linear and 2,000 random poses, budget "
                  "0.02 s (options given explicitly win)");
    sub->add_flag("--progress", o->progress, "Report progress on stderr even when it is not a terminal");
    sub->footer(methods_help());
    sub->callback([o, sub] {
        std::string command = "influence2d bench";
        for (const CLI::Option* opt : sub->get_options()) {
            if (opt->count() == 0 || opt->get_name() == "--help") continue;
            command += " " + opt->get_name();
            if (opt->get_type_size() == 0) continue;  // a flag
            for (const std::string& v : opt->results()) command += " " + v;
        }
        run_bench_command(*o, [sub](const std::string& name) { return sub->get_option(name)->count() > 0; }, command);
    });
}

}  // namespace influence2d::cli
