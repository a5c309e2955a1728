// SPDX-License-Identifier: BSL-1.0
// influence2d-bench (bench_main.cpp): the paper's time study (verification/time_study.hpp)
// against the libraries a user would pick instead, on the paper's trajectories,
// on random poses near contact and as one-shot queries; writes bench.csv,
// bench.md (per workload: our speed-up over the fastest peer per cell,
// certified against double, one-shot against each peer, the preparation of
// each method, the targets, peak memory) and heat maps in the style of the
// paper's Figure 12; then the study of motions that turn
// (verification/turning_study.hpp): turning.csv and its section of bench.md.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "report.hpp"
#include "verification/time_study.hpp"
#include "verification/time_study_cells.hpp"
#include "verification/time_study_report.hpp"
#include "verification/turning_study.hpp"
#include "verification/turning_study_report.hpp"

namespace influence2d::cli {

namespace {

namespace fs = std::filesystem;
using namespace influence2d::verification;

struct bench_cli_options {
    std::vector<std::string> types, trajectories, methods;
    std::vector<std::size_t> sizes;
    std::size_t circular_frames = 90000, linear_frames = 9000, random_frames = 20000;
    std::size_t turning_motions = turning_study_options{}.motions;
    double budget = 0.25;
    std::uint64_t seed = default_family_seed;
    std::string out = "bench";
    bool quick = false;
    bool progress = false;
};

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

/// The axes of a panel of cells: static vertices across, moving vertices up,
/// one tic per size of the run.
std::string size_axes(const time_study_options& o) {
    std::string tics;
    for (std::size_t i = 0; i < o.sizes.size(); ++i)
        tics += (i ? ", " : "") + std::string("'") + std::to_string(o.sizes[i]) + "' " + std::to_string(i);
    const std::string range = "[-0.5:" + std::to_string(o.sizes.size()) + "-0.5]";
    return "set xlabel 'static vertices'\nset ylabel 'moving vertices'\nset xtics (" + tics +
           ") rotate by 90 right\nset ytics (" + tics + ")\nset xrange " + range + "\nset yrange " + range + "\n";
}

/// The heat maps of the workloads `group`, one per method (file
/// heatmap_<prefix><method>.png): seconds for all the workload's poses (ns per
/// pose times its poses), a panel per type and workload, on one logarithmic
/// colour scale for every method of the group. Returns the gnuplot script.
std::string heat_maps(const time_study_result& r, const time_study_options& o, const fs::path& dir,
                      const std::vector<std::string>& group, const std::string& prefix) {
    std::vector<std::string> workloads;
    for (const std::string& j : o.trajectories)
        if (has_name(group, j)) workloads.push_back(j);
    const auto in_group = [&](const time_row& row) { return has_name(workloads, row.cell.trajectory); };
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
        const std::string what = workloads.size() == 1 && workloads[0] == "one-shot"
                                     ? "seconds per " + std::to_string(o.random_frames) + " queries"
                                     : "seconds per workload";
        script += "set terminal pngcairo size " + std::to_string(250 * columns + 120) + "," +
                  std::to_string(250 * rows_n + 60) + " font 'sans,9' background '#ffffff'\n";
        script += "set output '" + (dir / ("heatmap_" + prefix + m + ".png")).string() + "'\n";
        script += "set multiplot layout " + std::to_string(rows_n) + "," + std::to_string(columns) + " title '" + m +
                  ": " + what + " (log colour scale, the same for every method)'\n";
        script += "set logscale cb\nset format cb '%g'\nset cbrange [" + general(lo) + ":" + general(hi) + "]\n";
        script += "set palette defined (0 '#1a9850', 1 '#fee08b', 2 '#d73027')\nunset key\n";
        script += size_axes(o);
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
                script +=
                    points ? "plot $d using 1:2:(0.5):(0.5):3 with boxxyerror fillstyle solid 1.0 noborder lc "
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

/// The speed-up colour scale: logarithmic from 1/10 to 100, red below 1,
/// yellow from 1 to 10, green from the target (10) up.
constexpr double speedup_floor = 0.1, speedup_ceiling = 100;

/// The speed-up of `method` over the fastest peer per cell (file
/// speedup_<method>.png): a panel per workload and type, each cell coloured
/// and labelled with its speed-up (the peer's ns per pose over the method's).
/// Returns the gnuplot script, empty when no cell has a peer and the method.
std::string speedup_map(const time_study_result& r, const time_study_options& o, const fs::path& dir,
                        const std::string& method) {
    const cell_table cells = rows_by_cell(r);
    std::vector<std::string> workloads;
    for (const std::string& j : o.trajectories)
        if (ratios_over_cells(cells, j, [&](const cell_rows& rows) { return speedup_over_peer(rows, method); }).n > 0)
            workloads.push_back(j);
    if (workloads.empty()) return "";
    const std::size_t columns = o.types.size(), rows_n = workloads.size();
    std::string script = "set terminal pngcairo size " + std::to_string(250 * columns + 120) + "," +
                         std::to_string(250 * rows_n + 60) + " font 'sans,9' background '#ffffff'\n";
    script += "set output '" + (dir / ("speedup_" + method + ".png")).string() + "'\n";
    script += "set multiplot layout " + std::to_string(rows_n) + "," + std::to_string(columns) + " title '" + method +
              " over the fastest peer (its ns per pose over " + method + "''s)'\n";
    script += "set logscale cb\nset format cb '%g'\nset cbrange [" + general(speedup_floor) + ":" +
              general(speedup_ceiling) + "]\n";
    script +=
        "set palette defined (0 '#b2182b', 0.333 '#fddbc7', 0.334 '#fee08b', 0.666 '#d9ef8b', 0.667 '#66bd63', "
        "1 '#1a9850')\nunset key\n";
    script += size_axes(o);
    const auto at = [&](std::size_t n) { return std::find(o.sizes.begin(), o.sizes.end(), n) - o.sizes.begin(); };
    for (const std::string& j : workloads)
        for (const std::string& t : o.types) {
            script += std::string(t == o.types.back() ? "set colorbox\n" : "unset colorbox\n");
            script += "set title '" + t + ", " + j + "'\n$d << EOD\n";
            std::size_t points = 0;
            for (const auto& [c, rows] : cells) {
                const double x = speedup_over_peer(rows, method);
                if (c.type != t || c.trajectory != j || !(x > 0)) continue;
                script += std::to_string(at(c.static_size)) + " " + std::to_string(at(c.moving_size)) + " " +
                          general(std::min(std::max(x, speedup_floor), speedup_ceiling)) + " \"" +
                          fixed(x, x < 10 ? 1 : 0) + "\"\n";
                ++points;
            }
            script += "EOD\n";
            script += points ? "plot $d using 1:2:(0.5):(0.5):3 with boxxyerror fillstyle solid 1.0 noborder lc "
                               "palette, $d using 1:2:4 with labels font 'sans,7'\n"
                             : "set label 1 'no peer' at graph 0.5, graph 0.5 center\nplot NaN\nunset label 1\n";
        }
    return script + "unset multiplot\n";
}

/// The image-space baseline's share of wrong answers against its time per
/// pose (file raster_error_vs_time.svg): per workload, one point per
/// resolution (geometric mean over the cells), certified's time drawn at the
/// floor of the error axis. Returns the gnuplot script, empty without it.
std::string raster_plot(const time_study_result& r, const time_study_options& o, const fs::path& dir) {
    constexpr double floor = 1e-5;  // a share of zero is drawn here
    const cell_table cells = rows_by_cell(r);
    std::string blocks, plot;
    double fastest = HUGE_VAL, slowest = 0;  // the x range, room left for the labels
    for (std::size_t k = 0; k < o.trajectories.size(); ++k) {
        const std::string& j = o.trajectories[k];
        std::string lines;
        double certified = 0;
        for (const std::string& m : o.methods) {
            if (!method_of(m).approximate) continue;
            const approximate_summary a = approximate_over_cells(cells, j, m);
            if (a.cells == 0) continue;
            lines += "\"" + m + "\" " + general(a.ns) + " " + general(std::max(a.share_wrong(), floor)) + "\n";
            certified = a.certified_ns;
            fastest = std::min({fastest, a.ns, a.certified_ns});
            slowest = std::max({slowest, a.ns, a.certified_ns});
        }
        if (lines.empty()) continue;
        const std::string name = "raster_" + std::to_string(k);
        blocks += "$" + name + " << EOD\n" + lines + "EOD\n$" + name + "_certified << EOD\n\"certified\" " +
                  general(certified) + " " + general(floor) + "\nEOD\n";
        plot += std::string(plot.empty() ? "plot " : ", ") + "$" + name +
                " using 2:3 with linespoints pointtype 7 pointsize 1.3 linewidth 2 title 'raster, " + j + "', $" +
                name + " using 2:3:1 with labels left offset char 0.7,0.4 notitle, $" + name +
                "_certified using 2:3 with points pointtype 5 pointsize 1.5 title 'certified (exact), " + j + "'";
    }
    if (plot.empty()) return "";
    return "set terminal svg size 900,600 dynamic enhanced font 'sans,12' background '#ffffff'\n"
           "set output '" +
           (dir / "raster_error_vs_time.svg").string() +
           "'\nset logscale xy\nset grid\nset format x '10^{%L}'\nset format y '10^{%L}'\nset key top right\n"
           "set title 'The image-space baseline: wrong answers against time per pose'\n"
           "set xlabel 'geometric mean ns per pose over the cells (log scale)'\n"
           "set ylabel 'share of poses answered wrongly (0 drawn at 10^{-5})'\nset yrange [" +
           general(floor / 3) + ":1]\nset xrange [" + general(fastest / 2) + ":" + general(slowest * 8) + "]\n" +
           blocks + plot + "\n";
}

/// The speed-up maps of double and certified, and the raster plot.
void write_speedup_plots(const time_study_result& r, const time_study_options& o, const fs::path& dir) {
    const std::string script =
        speedup_map(r, o, dir, "double") + speedup_map(r, o, dir, "certified") + raster_plot(r, o, dir);
    if (!script.empty()) plot_with_gnuplot(dir / "speedups.gp", script, "bench");
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
    turning_study_options to;
    to.motions = o.quick && !given("--turning-motions") ? 32 : o.turning_motions;
    if (o.quick) {
        to.cells = {{"convex", 8, 8}, {"contour", 64, 64}};
        to.seconds = 0.05;
    }
    to.seed = o.seed;
    const time_study_result r = run_time_study(so);
    const std::vector<turning_row> turning = to.motions ? run_turning_study(to) : std::vector<turning_row>{};
    write_atomically(dir / "bench.csv", bench_csv(r));
    if (!r.work.empty()) write_atomically(dir / "bench_work.csv", work_csv(r));
    if (!turning.empty()) write_atomically(dir / "turning.csv", turning_csv(turning));
    const std::string turning_md = turning_markdown(turning, to);
    const std::string md = time_study_markdown(r, so, command) + turning_md;
    write_atomically(dir / "bench.md", md);
    write_heat_maps(r, so, dir);
    write_speedup_plots(r, so, dir);
    const std::size_t targets = md.find("## Targets"), end = md.find("\n## ", targets + 1);
    std::cout << md.substr(targets, end - targets) << "\nwritten: " << (dir / "bench.csv").string() << ", "
              << (dir / "bench.md").string() << ", heat maps " << (dir / "heatmap_*.png").string() << ", speed-up maps "
              << (dir / "speedup_*.png").string() << (turning.empty() ? "" : ", " + (dir / "turning.csv").string())
              << "\n";
    if (!turning.empty())
        std::cout << "\nturning motions (" << to.motions
                  << " per cell; misses and inventions against the exact answer of each model):\n\n"
                  << turning_md.substr(turning_md.find("### "));
}

/// The methods for --help, from the registry: name, forms, what it needs.
std::string methods_help() {
    std::string s = "Methods (frame form on circular, linear and random; one-shot form on one-shot):\n";
    for (const method_info& m : method_infos()) {
        s += "  " + std::string(m.name) + (m.own ? "" : " (peer)") + (m.available ? "" : " [not in this build]") + "\n";
        if (*m.frames) s += "      frames:   " + std::string(m.frames) + "\n";
        if (*m.one_shot) s += "      one-shot: " + std::string(m.one_shot) + "\n";
    }
    return s;
}

}  // namespace

void configure_bench(CLI::App& app) {
    auto o = std::make_shared<bench_cli_options>();
    CLI::App* sub = &app;
    sub->description(
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
    sub->add_option("--turning-motions", o->turning_motions,
                    "Motions that turn per cell of the turning study (convex 8x8, contour 64x64, starred "
                    "256x256; with --quick 32 motions, the first two cells), or 0 for none")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t{0}, std::size_t{1} << 24))
        ->type_name("N");
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
        std::string command = "influence2d-bench";
        for (const CLI::Option* opt : sub->get_options()) {
            if (opt->count() == 0 || opt->get_name() == "--help") continue;
            command += " " + opt->get_name();
            if (opt->get_type_size() == 0) continue;  // a flag
            for (const std::string& v : opt->results()) command += " " + v;
        }
        run_bench_command(
            *o, [sub](const std::string& name) { return sub->get_option(name)->count() > 0; }, command);
    });
}

}  // namespace influence2d::cli
