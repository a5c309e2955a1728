// SPDX-License-Identifier: BSL-1.0
// `influence2d bench`: the paper's time study (verification/time_study.hpp)
// against the libraries a user would pick instead; writes bench.csv, bench.md
// (our speed-up over the fastest peer per cell, the targets, peak memory) and
// one heat map per method in the style of the paper's Figure 12.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
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
    std::size_t circular_frames = 90000, linear_frames = 9000;
    double budget = 0.25;
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
        "collisions,disagreements\n";
    for (const time_row& row : r.rows)
        s += row.cell.type + "," + row.cell.trajectory + "," + std::to_string(row.cell.static_size) + "," +
             std::to_string(row.cell.moving_size) + "," + row.method + "," + std::to_string(row.trajectory_frames) +
             "," + std::to_string(row.frames) + "," + std::to_string(row.stride) + "," + std::to_string(row.passes) + "," +
             general(row.seconds) + "," +
             fixed(row.ns_per_frame(), 1) + "," + std::to_string(row.collisions) + "," +
             (row.reference ? std::string("reference") : std::to_string(row.disagreements)) + "\n";
    return s;
}

/// The rows of one cell, by method.
using cell_rows = std::map<std::string, const time_row*>;

std::vector<std::pair<time_cell, cell_rows>> by_cell(const time_study_result& r) {
    std::vector<std::pair<time_cell, cell_rows>> cells;
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

std::string bench_md(const time_study_result& r, const time_study_options& o, const std::string& command) {
    const auto cells = by_cell(r);
    std::string s = "# Time study\n\n";
    s += "Machine: " + machine_line() + ". Command: `" + command + "` (" + fixed(r.seconds, 0) + " s).\n\n";
    s += "Frames: the circular trajectory has " + std::to_string(o.circular_frames) + " poses (never colliding, gap " +
         general(o.gap) + "), the linear one " + std::to_string(o.linear_frames) +
         " (ending in collision). influence2d's double, certified and paper modes run every frame in order, in "
         "repeated passes on fresh detectors, taking turns pass by pass (at least 3, until " + general(o.repeat_seconds) +
         " s; bench.csv: passes), of which the median pass counts; the exact mode and the peers run every k-th frame, k chosen so that a run takes about " + general(o.budget) +
         " s (bench.csv: stride). Every answer is compared with the reference, the certified mode's exact answers.\n\n";

    // Per method: cells run, disagreements, geometric mean of ns per frame.
    const std::vector<std::string> missing = missing_methods();
    if (!missing.empty())
        s += "Peers this build lacks (their libraries were not found when it was built): " + joined(missing) + ".\n\n";
    s += "## Methods\n\n| method | cells | frames run | disagreements | geometric mean ns per frame |\n|---|---:|---:|---:|---:|\n";
    for (const std::string& m : o.methods) {
        std::size_t n = 0, frames = 0, wrong = 0;
        double log_sum = 0;
        bool reference = false;
        for (const time_row& row : r.rows)
            if (row.method == m) {
                ++n;
                frames += row.frames;
                wrong += row.disagreements;
                reference = reference || row.reference;
                log_sum += std::log(std::max(row.ns_per_frame(), 1e-3));
            }
        if (n == 0) continue;
        s += "| " + m + " | " + std::to_string(n) + " | " + std::to_string(frames) + " | " +
             (reference ? std::string("reference") : std::to_string(wrong)) + " | " +
             fixed(std::exp(log_sum / static_cast<double>(n)), 0) + " |\n";
    }

    // Targets.
    double log_speedup = 0, worst_speedup = HUGE_VAL, worst_certified = 0;
    std::size_t compared = 0, slower = 0;
    std::string worst_cell, worst_certified_cell;
    for (const auto& [c, rows] : cells) {
        const time_row* peer = fastest_peer(rows);
        if (rows.count("double") && peer) {
            const double x = peer->ns_per_frame() / std::max(rows.at("double")->ns_per_frame(), 1e-3);
            log_speedup += std::log(x);
            ++compared;
            if (x <= 1) ++slower;
            if (x < worst_speedup) {
                worst_speedup = x;
                worst_cell = cell_name(c) + " (fastest peer " + peer->method + ")";
            }
        }
        if (rows.count("double") && rows.count("certified")) {
            const double x = rows.at("certified")->ns_per_frame() / std::max(rows.at("double")->ns_per_frame(), 1e-3);
            if (x > worst_certified) {
                worst_certified = x;
                worst_certified_cell = cell_name(c);
            }
        }
    }
    s += "\n## Targets\n\n";
    if (compared > 0)
        s += "- Double mode against the fastest peer of each cell: geometric mean speed-up " +
             fixed(std::exp(log_speedup / static_cast<double>(compared)), 1) + "x over " + std::to_string(compared) +
             " cells; slowest cell " + worst_cell + ": " + fixed(worst_speedup, 2) + "x; cells where double is not "
             "faster: " + std::to_string(slower) + ".\n";
    if (worst_certified > 0)
        s += "- Certified mode against double: at most " + fixed(worst_certified, 2) + "x (" + worst_certified_cell +
             ").\n";
    for (const std::string& t : o.types)
        for (const std::string& j : o.trajectories) {
            const auto find = [&](std::size_t n, std::size_t m) -> const time_row* {
                for (const time_row& row : r.rows)
                    if (row.method == "double" && row.cell.type == t && row.cell.trajectory == j &&
                        row.cell.static_size == n && row.cell.moving_size == m)
                        return &row;
                return nullptr;
            };
            const std::size_t lo = *std::min_element(o.sizes.begin(), o.sizes.end());
            const std::size_t hi = *std::max_element(o.sizes.begin(), o.sizes.end());
            const time_row *small = find(lo, lo), *corner = find(hi, lo);
            if (small && corner && hi != lo)
                s += "- Weak corner, " + t + " " + j + ": double " + std::to_string(hi) + "x" + std::to_string(lo) +
                     " costs " + fixed(corner->ns_per_frame() / std::max(small->ns_per_frame(), 1e-3), 2) +
                     " times " + std::to_string(lo) + "x" + std::to_string(lo) + " per frame.\n";
        }

    // Speed-up tables: one per type and trajectory, static size down, moving across.
    s += "\n## Speed-up of the double mode over the fastest peer\n\nRows: static vertices; columns: moving "
         "vertices. Each entry: the fastest peer's ns per frame / double's ns per frame.\n";
    for (const std::string& t : o.types)
        for (const std::string& j : o.trajectories) {
            s += "\n### " + t + ", " + j + "\n\n| static \\ moving |";
            for (std::size_t m : o.sizes) s += " " + std::to_string(m) + " |";
            s += "\n|---:|";
            for (std::size_t i = 0; i < o.sizes.size(); ++i) s += "---:|";
            s += "\n";
            for (std::size_t n : o.sizes) {
                s += "| " + std::to_string(n) + " |";
                for (std::size_t m : o.sizes) {
                    std::string entry = "-";
                    for (const auto& [c, rows] : cells)
                        if (c.type == t && c.trajectory == j && c.static_size == n && c.moving_size == m &&
                            rows.count("double")) {
                            if (const time_row* peer = fastest_peer(rows))
                                entry = fixed(peer->ns_per_frame() / std::max(rows.at("double")->ns_per_frame(), 1e-3),
                                              1) + " (" + peer->method + ")";
                        }
                    s += " " + entry + " |";
                }
                s += "\n";
            }
        }

    if (!r.memory.empty()) {
        const time_cell& c = r.memory.front().cell;
        s += "\n## Peak heap memory, " + cell_name(c) + "\n\nHeap bytes live at the peak, from building the method "
             "(A prepared, B read) to its last frame, over " + std::to_string(r.memory.front().frames) +
             " evenly spaced frames (operator new and GMP counted; Box2D's malloc is not).\n\n| method | peak heap |\n"
             "|---|---:|\n";
        for (const memory_row& m : r.memory)
            s += "| " + m.method + " | " + fixed(static_cast<double>(m.peak_bytes) / 1024.0, 1) + " KiB |\n";
    }
    return s;
}

/// One heat map per method: seconds for the whole trajectory (ns per frame
/// times the trajectory's frames), a panel per type and trajectory, on the
/// same logarithmic colour scale for every method.
void write_heat_maps(const time_study_result& r, const time_study_options& o, const fs::path& dir) {
    double lo = HUGE_VAL, hi = 0;
    for (const time_row& row : r.rows) {
        const double t = row.ns_per_frame() * 1e-9 * static_cast<double>(row.trajectory_frames);
        if (t > 0) {
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
    }
    if (!(hi > 0)) return;
    std::string script;
    const std::size_t columns = o.types.size(), rows_n = o.trajectories.size();
    for (const std::string& m : o.methods) {
        if (std::none_of(r.rows.begin(), r.rows.end(), [&](const time_row& row) { return row.method == m; })) continue;
        script += "set terminal pngcairo size " + std::to_string(250 * columns + 120) + "," +
                  std::to_string(250 * rows_n + 60) + " font 'sans,9' background '#ffffff'\n";
        script += "set output '" + (dir / ("heatmap_" + m + ".png")).string() + "'\n";
        script += "set multiplot layout " + std::to_string(rows_n) + "," + std::to_string(columns) + " title '" + m +
                  ": seconds per trajectory (log colour scale, the same for every method)'\n";
        script += "set logscale cb\nset format cb '%g'\nset cbrange [" + general(lo) + ":" + general(hi) + "]\n";
        script += "set palette defined (0 '#1a9850', 1 '#fee08b', 2 '#d73027')\nunset key\n";
        script += "set xlabel 'static vertices'\nset ylabel 'moving vertices'\n";
        std::string tics;
        for (std::size_t i = 0; i < o.sizes.size(); ++i)
            tics += (i ? ", " : "") + std::string("'") + std::to_string(o.sizes[i]) + "' " + std::to_string(i);
        script += "set xtics (" + tics + ") rotate by 90 right\nset ytics (" + tics + ")\n";
        script += "set xrange [-0.5:" + std::to_string(o.sizes.size()) + "-0.5]\nset yrange [-0.5:" +
                  std::to_string(o.sizes.size()) + "-0.5]\n";
        for (const std::string& j : o.trajectories)
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
                    const double secs = std::max(row.ns_per_frame() * 1e-9 * static_cast<double>(row.trajectory_frames), lo);
                    script += std::to_string(at(row.cell.static_size)) + " " + std::to_string(at(row.cell.moving_size)) +
                              " " + general(secs) + "\n";
                    ++points;
                }
                script += "EOD\n";
                script += points ? "plot $d using 1:2:(0.5):(0.5):3 with boxxyerror fillstyle solid 1.0 noborder lc palette\n"
                                 : "set label 1 'not applicable' at graph 0.5, graph 0.5 center\nplot NaN\nunset label 1\n";
            }
        script += "unset multiplot\n";
    }
    plot_with_gnuplot(dir / "heatmaps.gp", script, "bench");
}

/// `given(name)`: whether the option was on the command line.
template <class Given>
void run_bench_command(bench_cli_options o, Given given, const std::string& command) {
    time_study_options so;
    check_names(o.types, so.types, "types");
    check_names(o.trajectories, so.trajectories, "trajectories");
    check_names(o.methods, time_study_methods(), "methods");
    for (std::size_t n : o.sizes)
        if (n < 8 || n > 1024 || (n & (n - 1)) != 0)
            throw std::invalid_argument("--sizes: " + std::to_string(n) + " is not a power of two from 8 to 1024");
    if (o.quick) {
        so.sizes = {8, 1024};
        so.circular_frames = 9000;
        so.linear_frames = 900;
        so.budget = 0.02;
        so.memory_frames = 100;
    }
    if (!o.types.empty()) so.types = o.types;
    if (!o.trajectories.empty()) so.trajectories = o.trajectories;
    if (!o.methods.empty()) so.methods = o.methods;
    if (!o.sizes.empty()) so.sizes = o.sizes;
    if (!o.quick || given("--circular-frames")) so.circular_frames = o.circular_frames;
    if (!o.quick || given("--linear-frames")) so.linear_frames = o.linear_frames;
    if (!o.quick || given("--budget")) so.budget = o.budget;

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
    const std::string md = bench_md(r, so, command);
    write_atomically(dir / "bench.md", md);
    write_heat_maps(r, so, dir);
    const std::size_t targets = md.find("## Targets"), end = md.find("\n## ", targets + 1);
    std::cout << md.substr(targets, end - targets) << "\nwritten: " << (dir / "bench.csv").string() << ", "
              << (dir / "bench.md").string() << ", heat maps " << (dir / "heatmap_*.png").string() << "\n";
}

}  // namespace

void register_bench(CLI::App& app) {
    auto o = std::make_shared<bench_cli_options>();
    CLI::App* sub = app.add_subcommand(
        "bench",
        "The paper's time study against Boost.Geometry, GEOS, CGAL, Box2D and an all-pairs test, on the same "
        "frames: DIR/bench.csv, DIR/bench.md (speed-ups, targets, peak memory) and heat maps (with gnuplot).");
    const time_study_options d;
    sub->add_option("--types", o->types, "Polygon types, separated by commas [default: " + joined(d.types) + "]")
        ->delimiter(',')
        ->type_name("LIST");
    sub->add_option("--trajectories", o->trajectories,
                    "Trajectories, separated by commas [default: " + joined(d.trajectories) + "]")
        ->delimiter(',')
        ->type_name("LIST");
    sub->add_option("--methods", o->methods,
                    "Methods, separated by commas [default: " + joined(time_study_methods()) +
                        "]; the certified mode always runs, as the reference")
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
    sub->add_option("--budget", o->budget,
                    "Seconds per cell for the exact mode and each peer, which run every k-th frame to fit")
        ->capture_default_str()
        ->check(CLI::Range(1e-3, 1e6))
        ->type_name("S");
    sub->add_option("--out", o->out, "Output directory, created if missing")->capture_default_str()->type_name("DIR");
    sub->add_flag("--quick", o->quick,
                  "A CI-sized run: sizes 8 and 1024, 9,000 circular and 900 linear poses, budget 0.02 s (options "
                  "given explicitly win)");
    sub->add_flag("--progress", o->progress, "Report progress on stderr even when it is not a terminal");
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
