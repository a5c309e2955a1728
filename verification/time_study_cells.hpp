// SPDX-License-Identifier: BSL-1.0
#pragma once
// The time study's results read cell by cell (verification/time_study.hpp):
// each cell's rows by method, the ratios between methods on a cell, and those
// ratios gathered over the cells of a workload.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "verification/report_text.hpp"
#include "verification/time_study.hpp"

namespace influence2d::verification {

/// A cell's name: type/workload/static x moving.
inline std::string cell_name(const time_cell& c) {
    return c.type + "/" + c.trajectory + "/" + std::to_string(c.static_size) + "x" + std::to_string(c.moving_size);
}

/// The rows of one cell, by method.
using cell_rows = std::map<std::string, const time_row*>;
/// The cells of a run with their rows, in the order they were run.
using cell_table = std::vector<std::pair<time_cell, cell_rows>>;

/// The rows of a run grouped by cell.
inline cell_table rows_by_cell(const time_study_result& r) {
    cell_table cells;
    for (const time_row& row : r.rows) {
        if (cells.empty() || cell_name(cells.back().first) != cell_name(row.cell)) cells.push_back({row.cell, {}});
        cells.back().second[row.method] = &row;
    }
    return cells;
}

/// The fastest peer of a cell (nullptr if no peer ran); the approximate
/// baselines (the raster test) do not count: they answer another question.
inline const time_row* fastest_peer(const cell_rows& rows) {
    const time_row* best = nullptr;
    for (const auto& [m, row] : rows)
        if (!is_own_method(m) && !method_of(m).approximate && (!best || row->ns_per_frame() < best->ns_per_frame()))
            best = row;
    return best;
}

/// a's ns per pose over b's, or 0 when either is missing.
inline double ns_ratio(const cell_rows& rows, const std::string& a, const std::string& b) {
    if (!rows.count(a) || !rows.count(b)) return 0;
    return rows.at(a)->ns_per_frame() / std::max(rows.at(b)->ns_per_frame(), 1e-3);
}

/// The speed-up of `method` over the fastest peer: the peer's ns per pose
/// over the method's, or 0.
inline double speedup_over_peer(const cell_rows& rows, const std::string& method) {
    const time_row* peer = fastest_peer(rows);
    if (!peer || !rows.count(method)) return 0;
    return peer->ns_per_frame() / std::max(rows.at(method)->ns_per_frame(), 1e-3);
}

/// The speed-up of double over the fastest peer, or 0.
inline double peer_speedup(const cell_rows& rows) { return speedup_over_peer(rows, "double"); }

/// The speed-up the time study aims at on every cell of a frame workload.
inline constexpr double peer_target = 10;

/// Ratios over cells: geometric mean, extremes and where, how many at most 1.
struct ratio_stats {
    std::size_t n = 0, at_most_one = 0;
    double log_sum = 0, lo = HUGE_VAL, hi = 0;
    std::string lo_cell, hi_cell;
    /// Counts x (at cell `where`) when it is positive.
    void add(double x, const std::string& where) {
        if (!(x > 0)) return;
        ++n;
        log_sum += std::log(x);
        at_most_one += x <= 1 ? 1 : 0;
        if (x < lo) lo = x, lo_cell = where;
        if (x > hi) hi = x, hi_cell = where;
    }
    /// The geometric mean (0 for no ratio).
    double mean() const { return n ? std::exp(log_sum / static_cast<double>(n)) : 0; }
};

/// The ratios f(rows) over the cells of a workload (and type, if given).
inline ratio_stats ratios_over_cells(const cell_table& cells, const std::string& workload,
                                     const std::function<double(const cell_rows&)>& f, const std::string& type = "") {
    ratio_stats s;
    for (const auto& [c, rows] : cells)
        if (c.trajectory == workload && (type.empty() || c.type == type)) s.add(f(rows), cell_name(c));
    return s;
}

/// An approximate baseline over the cells of a workload where it and
/// certified both ran: poses, wrong answers, and the geometric means of its
/// and certified's ns per pose.
struct approximate_summary {
    std::size_t cells = 0, frames = 0, wrong = 0;
    double ns = 0, certified_ns = 0;
    double share_wrong() const { return frames ? static_cast<double>(wrong) / static_cast<double>(frames) : 0; }
};

inline approximate_summary approximate_over_cells(const cell_table& cells, const std::string& workload,
                                                  const std::string& method) {
    approximate_summary a;
    double log_ns = 0, log_certified = 0;
    for (const auto& [c, rows] : cells)
        if (c.trajectory == workload && rows.count(method) && rows.count("certified")) {
            const time_row& row = *rows.at(method);
            ++a.cells;
            a.frames += row.frames;
            a.wrong += row.disagreements;
            log_ns += std::log(std::max(row.ns_per_frame(), 1e-3));
            log_certified += std::log(std::max(rows.at("certified")->ns_per_frame(), 1e-3));
        }
    if (a.cells) {
        a.ns = std::exp(log_ns / static_cast<double>(a.cells));
        a.certified_ns = std::exp(log_certified / static_cast<double>(a.cells));
    }
    return a;
}

/// The double detector's counters on a cell (nullptr when it did not run there).
inline const work_row* work_on_cell(const time_study_result& r, const time_cell& c) {
    for (const work_row& w : r.work)
        if (cell_name(w.cell) == cell_name(c)) return &w;
    return nullptr;
}

/// A counter of a cell's work per frame.
inline double per_frame(std::size_t count, const work_row& w) {
    return static_cast<double>(count) / static_cast<double>(std::max<std::size_t>(w.frames, 1));
}

}  // namespace influence2d::verification
