// SPDX-License-Identifier: BSL-1.0
// The influence2d-world-bench program: the world's time study. For each scene
// of verification/world_scenes.hpp and each body count, every method steps
// through the same poses (posing included for every method), the methods
// interleaved step by step in a shuffled order; the time per step is the
// mean over the steps after the first (which builds what each method keeps),
// so that the steps that rebuild a tree count as often as they come (scenes
// of 100 bodies or fewer run ten times over, each method made anew); the
// median step is shown beside it. Every method's pairs are compared with the certified world's
// (exact) at every step. Real layers (--layers DIR, from
// scripts/real_layers.sh): all meeting pairs of each layer, the methods
// interleaved over repeated runs in a shuffled order, medians. A program of its own because it
// links the peers (one of them GPL through CGAL's Boolean_set_operations_2);
// the influence2d tool links none.
//
// Exit codes: 0 success (or --help), 2 bad usage or a file that cannot be
// read or written.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "files.hpp"
#include "influence2d/exact/certified_world.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/query/both_posed.hpp"
#include "influence2d/world/layer_pairs.hpp"
#include "influence2d/world/world.hpp"
#include "report.hpp"
#include "tool.hpp"
#include "verification/heap_meter.hpp"
#include "verification/world_peers.hpp"
#include "verification/world_scenes.hpp"
#include "world_input.hpp"

namespace influence2d::cli {

namespace {

using verification::world_scene;
using clock_type = std::chrono::steady_clock;

struct bench_options {
    bool quick = false;
    std::string out;
    std::string layers;
    std::size_t steps = 0;
    std::vector<std::size_t> sizes;
};

/// One method of the study: a name and a step function made for a scene.
struct method {
    std::string name;
    std::function<std::vector<body_pair>(const std::vector<pose>&)> step;
};

/// A world of the library as a method: bodies added at the first step, moved
/// (all of them, as the scene gives every pose) at the others.
template <class World>
method world_method(const std::string& name, const world_scene& s, world_options o) {
    auto w = std::make_shared<World>(o);
    for (const polygon& p : s.shapes) w->add_shape(p);
    auto started = std::make_shared<bool>(false);
    auto last = std::make_shared<std::vector<pose>>();
    return {name, [w, started, last, &s](const std::vector<pose>& at) {
                if (!*started) {
                    for (std::size_t b = 0; b < at.size(); ++b) w->add_body(s.shape_of[b], at[b], s.fixed[b]);
                    *started = true;
                } else {
                    // A body whose pose did not change is left where it is
                    // (a fixed body of the scene never moves).
                    for (std::size_t b = 0; b < at.size(); ++b)
                        if (at[b].tx != (*last)[b].tx || at[b].ty != (*last)[b].ty || at[b].theta != (*last)[b].theta)
                            w->move(static_cast<std::uint32_t>(b), at[b]);
                }
                *last = at;
                return w->step();
            }};
}

template <class Peer>
method peer_method(const std::string& name, const world_scene& s) {
    auto p = std::make_shared<Peer>(s);
    return {name, [p](const std::vector<pose>& at) { return p->step(at); }};
}

/// The methods for scene s: the library's worlds, then the peers.
std::vector<method> methods_for(const world_scene& s) {
    std::vector<method> m;
    world_options serial, parallel, fresh;
    parallel.threads = 0;
    fresh.coherence = false;
    m.push_back(world_method<certified_world>("certified", s, serial));
    m.push_back(world_method<world<double>>("double", s, serial));
    if (hardware_threads() > 1) m.push_back(world_method<world<double>>("double, all cores", s, parallel));
    m.push_back(world_method<world<double>>("double, no witness", s, fresh));
#if INFLUENCE2D_HAVE_GEOS
    m.push_back(peer_method<verification::geos_world>("GEOS STRtree + prepared", s));
#endif
    m.push_back(peer_method<verification::boost_world>("Boost.Geometry rtree", s));
#if INFLUENCE2D_HAVE_BOX2D
    if (verification::box2d_world::applies(s))
        m.push_back(peer_method<verification::box2d_world>("Box2D dynamic tree", s));
#endif
    if (s.steps.front().size() <= 1000)
        m.push_back(peer_method<verification::all_pairs_world>("all pairs, one-shot", s));
    return m;
}

double mean(const std::vector<double>& v) {
    double sum = 0;
    for (double x : v) sum += x;
    return v.empty() ? 0 : sum / static_cast<double>(v.size());
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

/// The pairs of `got` not in `want` and of `want` not in `got`.
std::size_t differences(const std::vector<body_pair>& got, const std::vector<body_pair>& want) {
    std::vector<body_pair> d;
    std::set_symmetric_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(d));
    return d.size();
}

/// The order in which the n methods take round t (a step or a run of a
/// layer's join): a permutation drawn anew each round (seeded by t), so that
/// every method follows every other about equally often. In a rotating
/// order a method always follows the same one: the two-thread world,
/// always right after the serial one (the same code on the same poses),
/// then ran 1.13x-1.31x faster than it at 100 bodies, where no pass ran in
/// parallel (three runs of each scene).
std::vector<std::size_t> round_order(std::size_t n, std::size_t t) {
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::mt19937_64 random(t);
    std::shuffle(order.begin(), order.end(), random);
    return order;
}

struct row {
    std::string scene;
    std::size_t bodies = 0;
    std::string method;
    double step_us = 0;        // time per step: the mean over the steps after the first
    double median_us = 0;      // the median of those steps
    double first_ms = 0;       // the first step
    double contacts = 0;       // mean contacts per step
    std::size_t wrong = 0;     // pairs differing from the certified world's, over all steps
    std::size_t heap_kib = 0;  // peak heap of two steps, made anew (0: not measured)
};

/// The scene run `runs` times over, each method made anew for each run:
/// its steps after the first of every run make the mean and the median, its
/// first steps' median the first step, its contacts the mean of its steps.
/// (The study runs scenes of at most 100 bodies ten times: their steps take
/// tens of microseconds, where one interruption of the process moves a mean
/// over 20 steps by a third.)
std::vector<row> run_scene(const std::string& name, std::size_t bodies, std::size_t steps, std::size_t runs) {
    const world_scene s = verification::make_world_scene(name, bodies, steps, 2026 + bodies);
    std::vector<method> methods = methods_for(s);
    const std::size_t n = methods.size();
    std::vector<std::vector<double>> seconds(n), first(n);
    std::vector<std::size_t> wrong(n, 0), contacts(n, 0);
    for (std::size_t run = 0; run < runs; ++run) {
        if (run > 0) methods = methods_for(s);
        for (std::size_t t = 0; t < s.steps.size(); ++t) {
            std::vector<std::vector<body_pair>> answers(n);
            for (const std::size_t m : round_order(n, run * s.steps.size() + t)) {
                const auto start = clock_type::now();
                answers[m] = methods[m].step(s.steps[t]);
                (t == 0 ? first[m] : seconds[m])
                    .push_back(std::chrono::duration<double>(clock_type::now() - start).count());
            }
            for (std::size_t m = 0; m < n; ++m) {
                wrong[m] += differences(answers[m], answers[0]);
                contacts[m] += answers[m].size();
            }
        }
    }
    std::vector<row> out;
    for (std::size_t m = 0; m < n; ++m) {
        row r{name,
              s.steps.front().size(),
              methods[m].name,
              mean(seconds[m]) * 1e6,
              median(seconds[m]) * 1e6,
              median(first[m]) * 1e3,
              static_cast<double>(contacts[m]) / static_cast<double>(s.steps.size() * runs),
              wrong[m],
              0};
        if (verification::heap_meter::available()) {
            // Peak heap over two steps of a method made anew.
            verification::heap_meter::start();
            {
                std::vector<method> again = methods_for(s);
                again[m].step(s.steps[0]);
                if (s.steps.size() > 1) again[m].step(s.steps[1]);
            }
            r.heap_kib = verification::heap_meter::stop() / 1024;
        }
        out.push_back(r);
    }
    return out;
}

/// Real layers: all meeting pairs of one layer, each method run `runs` times,
/// interleaved in shuffled orders; medians. (101 runs in the study: with 21,
/// the two-thread join of the NC counties, serial below
/// join_parallel_vertices, came out 0.74x the one-thread join in two runs,
/// as the few orders drawn put it after GEOS more often.)
std::vector<row> run_layer(const std::string& path, const std::string& name, int runs) {
    if (!std::filesystem::exists(path))
        throw std::invalid_argument(path + ": cannot be read (make it with scripts/real_layers.sh)");
    const std::vector<polygon> layer = read_polygon_lines(path).polygons;
    using pairs_of = std::function<std::vector<body_pair>()>;
    std::vector<std::pair<std::string, pairs_of>> methods = {
        {"certified", [&] { return certified_layer_pairs(layer); }},
        {"double", [&] { return layer_pairs<double>(layer); }},
        {"double, all cores", [&] { return layer_pairs<double>(layer, 0, 0); }},
        {"certified, all cores", [&] { return certified_layer_pairs(layer, 0, 0); }},
    };
    // The peers: the layer's polygons built once (outside the time), then
    // the tree, the queries and the tests timed.
    std::vector<verification::bg_multi> bg;
    for (const polygon& p : layer)
        bg.push_back(verification::bg_multi_posed(verification::peer_parts(p), rotation_pose(pose{})));
    methods.push_back(
        {"Boost.Geometry rtree", [&] {
             namespace bgi = boost::geometry::index;
             using bbox = boost::geometry::model::box<verification::bg_point>;
             std::vector<std::pair<bbox, std::uint32_t>> boxes;
             for (std::size_t k = 0; k < bg.size(); ++k)
                 boxes.emplace_back(boost::geometry::return_envelope<bbox>(bg[k]), static_cast<std::uint32_t>(k));
             const bgi::rtree<std::pair<bbox, std::uint32_t>, bgi::quadratic<16>> tree(boxes.begin(), boxes.end());
             std::vector<body_pair> out;
             std::vector<std::pair<bbox, std::uint32_t>> found;
             for (std::size_t i = 0; i < bg.size(); ++i) {
                 found.clear();
                 tree.query(bgi::intersects(boxes[i].first), std::back_inserter(found));
                 for (const auto& f : found)
                     if (f.second > i && boost::geometry::intersects(bg[i], bg[f.second]))
                         out.push_back({static_cast<std::uint32_t>(i), f.second});
             }
             std::sort(out.begin(), out.end());
             return out;
         }});
#if INFLUENCE2D_HAVE_GEOS
    auto geos = std::make_shared<verification::geos_builder>();
    std::vector<GEOSGeometry*> gg;
    for (const polygon& p : layer)
        gg.push_back(verification::geos_multi_posed(*geos, verification::peer_parts(p), rotation_pose(pose{})));
    methods.push_back({"GEOS STRtree + prepared", [&] {
                           GEOSContextHandle_t ctx = geos->ctx;
                           GEOSSTRtree* tree = GEOSSTRtree_create_r(ctx, 10);
                           for (std::size_t k = 0; k < gg.size(); ++k)
                               GEOSSTRtree_insert_r(ctx, tree, gg[k],
                                                    reinterpret_cast<void*>(static_cast<std::uintptr_t>(k)));
                           std::vector<body_pair> out;
                           std::vector<std::size_t> found;
                           for (std::size_t i = 0; i < gg.size(); ++i) {
                               found.clear();
                               GEOSSTRtree_query_r(
                                   ctx, tree, gg[i],
                                   [](void* item, void* user) {
                                       static_cast<std::vector<std::size_t>*>(user)->push_back(
                                           reinterpret_cast<std::uintptr_t>(item));
                                   },
                                   &found);
                               const GEOSPreparedGeometry* prepared = nullptr;
                               for (std::size_t j : found) {
                                   if (j <= i) continue;
                                   if (!prepared) prepared = GEOSPrepare_r(ctx, gg[i]);
                                   if (geos->answer(GEOSPreparedIntersects_r(ctx, prepared, gg[j]), "intersects"))
                                       out.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
                               }
                               if (prepared) GEOSPreparedGeom_destroy_r(ctx, prepared);
                           }
                           GEOSSTRtree_destroy_r(ctx, tree);
                           std::sort(out.begin(), out.end());
                           return out;
                       }});
#endif
    const std::size_t n = methods.size();
    std::vector<std::vector<double>> seconds(n);
    std::vector<std::vector<body_pair>> answers(n);
    for (int r = 0; r < runs; ++r)
        for (const std::size_t m : round_order(n, static_cast<std::size_t>(r))) {
            const auto start = clock_type::now();
            answers[m] = methods[m].second();
            seconds[m].push_back(std::chrono::duration<double>(clock_type::now() - start).count());
        }
    std::vector<row> out;
    for (std::size_t m = 0; m < n; ++m)
        out.push_back({name, layer.size(), methods[m].first, median(seconds[m]) * 1e6, median(seconds[m]) * 1e6, 0,
                       static_cast<double>(answers[m].size()), differences(answers[m], answers[0]), 0});
#if INFLUENCE2D_HAVE_GEOS
    for (GEOSGeometry* g : gg) GEOSGeom_destroy_r(geos->ctx, g);
#endif
    return out;
}

std::string number(double x, int digits) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << x;
    return s.str();
}

/// The table: per scene and body count, each method's time per step and its
/// ratio to the fastest peer.
std::string table(const std::vector<row>& rows) {
    std::string t =
        "| scene | bodies | method | time per step (us) | median step (us) | first step (ms) | contacts per step | x "
        "fastest peer | wrong pairs | heap (KiB) |\n"
        "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
    std::map<std::pair<std::string, std::size_t>, double> fastest_peer;
    const auto is_peer = [](const std::string& m) {
        return m.find("GEOS") != std::string::npos || m.find("Boost") != std::string::npos ||
               m.find("Box2D") != std::string::npos;
    };
    for (const row& r : rows)
        if (is_peer(r.method)) {
            auto& f = fastest_peer[{r.scene, r.bodies}];
            f = f == 0 ? r.step_us : std::min(f, r.step_us);
        }
    for (const row& r : rows) {
        const double f = fastest_peer[{r.scene, r.bodies}];
        t += "| " + r.scene + " | " + std::to_string(r.bodies) + " | " + r.method + " | " + number(r.step_us, 1) +
             " | " + number(r.median_us, 1) + " | " + number(r.first_ms, 2) + " | " + number(r.contacts, 1) + " | " +
             (f > 0 && r.step_us > 0 ? number(f / r.step_us, 2) : std::string("-")) + " | " + std::to_string(r.wrong) +
             " | " + (r.heap_kib ? std::to_string(r.heap_kib) : std::string("-")) + " |\n";
    }
    return t;
}

std::string csv(const std::vector<row>& rows) {
    std::string t = "scene,bodies,method,step_us,first_ms,contacts,wrong,heap_kib,median_step_us\n";
    for (const row& r : rows)
        t += r.scene + "," + std::to_string(r.bodies) + ",\"" + r.method + "\"," + number(r.step_us, 3) + "," +
             number(r.first_ms, 3) + "," + number(r.contacts, 2) + "," + std::to_string(r.wrong) + "," +
             std::to_string(r.heap_kib) + "," + number(r.median_us, 3) + "\n";
    return t;
}

/// A gnuplot script drawing time per step against the body count, one panel
/// per scene, one line per method (log-log), into `png`.
std::string plot_script(const std::vector<row>& rows, const std::vector<std::string>& scenes, const std::string& png,
                        const std::string& data_dir) {
    std::map<std::string, std::map<std::string, std::vector<std::pair<std::size_t, double>>>> lines;
    for (const row& r : rows) lines[r.scene][r.method].push_back({r.bodies, r.step_us});
    std::string g = "set terminal pngcairo size 2000,900 font ',9'\nset output '" + png +
                    "'\nset multiplot layout 2,4\nset logscale xy\nset key top left\nset xlabel 'bodies'\n"
                    "set ylabel 'time per step (us)'\n";
    std::size_t file = 0;
    for (const std::string& scene : scenes) {
        g += "set title '" + scene + "'\nplot ";
        bool first = true;
        for (const auto& [method, points] : lines[scene]) {
            const std::string path = data_dir + "/plot_" + std::to_string(file++) + ".dat";
            std::ofstream f(path);
            for (const auto& [n, us] : points) f << n << ' ' << us << '\n';
            g += std::string(first ? "" : ", ") + "'" + path + "' with linespoints title '" + method + "'";
            first = false;
        }
        g += "\n";
    }
    return g + "unset multiplot\n";
}

/// What coherence buys a pair that persists: `pairs` pairs of crossing stars
/// (12 points), each pair far from the others, every body moved a little at
/// every step (1e-3 in translation, 1e-3 rad); the world with and without
/// the witness, each step timed with its bodies' moves (move() takes each
/// pose's cosine and sine, as the one-shot query does), and the two-pose
/// one-shot query on every pair, interleaved; ns per persisting pair
/// (medians over the steps), and the moves' share of the world's.
std::string coherence_study(std::size_t pairs, std::size_t steps) {
    ring_input star;
    for (int k = 0; k < 24; ++k) {
        const double a = M_PI * k / 12, r = k % 2 ? 0.6 : 1.2;
        star.vertices.push_back({r * std::cos(a), r * std::sin(a)});
    }
    const polygon shape({star});
    std::vector<pose> at;
    for (std::size_t k = 0; k < pairs; ++k) {
        const double x = 10.0 * static_cast<double>(k % 100), y = 10.0 * static_cast<double>(k / 100);
        at.push_back({x, y, 0});
        at.push_back({x + 1.5, y + 0.2, 0.1});
    }
    world_options with, without;
    without.coherence = false;
    world<double> a(with), b(without);
    a.add_shape(shape);
    b.add_shape(shape);
    for (const pose& q : at) {
        a.add_body(0, q);
        b.add_body(0, q);
    }
    a.step();
    b.step();
    std::vector<double> moves, ta, tb, tc;
    std::size_t met = 0;
    const auto moved = [&](world<double>& w) {
        for (std::size_t k = 0; k < at.size(); ++k) w.move(static_cast<std::uint32_t>(k), at[k]);
    };
    const auto seconds = [](clock_type::time_point from, clock_type::time_point to) {
        return std::chrono::duration<double>(to - from).count();
    };
    for (std::size_t t = 0; t < steps; ++t) {
        for (std::size_t k = 0; k < at.size(); ++k) {
            const double wobble = 1e-3 * std::sin(static_cast<double>(t * 7 + k));
            at[k] = {at[k].tx + wobble, at[k].ty - wobble, at[k].theta + wobble};
        }
        const auto t0 = clock_type::now();
        moved(a);
        const auto tm = clock_type::now();
        met += a.step().size();
        const auto t1 = clock_type::now();
        moved(b);
        b.step();
        const auto t2 = clock_type::now();
        for (std::size_t k = 0; k < pairs; ++k) met += intersects<double>(shape, at[2 * k], shape, at[2 * k + 1]);
        const auto t3 = clock_type::now();
        moves.push_back(seconds(t0, tm));
        ta.push_back(seconds(t0, t1));
        tb.push_back(seconds(t1, t2));
        tc.push_back(seconds(t2, t3));
    }
    const double n = static_cast<double>(pairs);
    const auto ns = [n](const std::vector<double>& v) { return number(median(v) * 1e9 / n, 0); };
    const world_statistics& st = a.statistics();
    return "coherence, " + std::to_string(pairs) + " persisting pairs of crossing 12-point stars, " +
           std::to_string(steps) + " steps (" + std::to_string(met) +
           " answers), the moves timed with each step: " + "witness " + ns(ta) + " ns per pair per step (the moves " +
           ns(moves) + " ns of it), no witness " + ns(tb) + " ns, one-shot two-pose query " + ns(tc) +
           " ns; witness hits " + std::to_string(st.witness_hits) + " of " + std::to_string(st.candidates) +
           " candidates\n";
}

void run(const bench_options& o) {
    const std::vector<std::string> scenes = {"falling", "convex", "parcels", "random", "mixed", "far", "trajectories"};
    std::vector<std::size_t> sizes = o.sizes;
    if (sizes.empty())
        sizes = o.quick ? std::vector<std::size_t>{100, 1000} : std::vector<std::size_t>{100, 1000, 10000, 100000};
    std::vector<row> rows;
    for (const std::string& scene : scenes)
        for (std::size_t n : sizes) {
            const std::size_t steps = o.steps ? o.steps : (n >= 10000 ? 11 : 21);
            std::cerr << "world bench: " << scene << ", " << n << " bodies, " << steps << " steps\n";
            for (const row& r : run_scene(scene, n, steps, n <= 100 ? 10 : 1)) rows.push_back(r);
        }
    if (!o.layers.empty())
        for (const auto& [file, name] : {std::pair<std::string, std::string>{"countries.wkt", "countries (177)"},
                                         {"boroughs.wkt", "NYC boroughs (5)"},
                                         {"counties.wkt", "NC counties (100)"},
                                         {"blocks.wkt", "Olinda blocks (470)"},
                                         {"tracts.wkt", "Boston tracts (506)"},
                                         {"plots.wkt", "wheat plots (500)"}}) {
            std::cerr << "world bench: layer " << name << "\n";
            for (const row& r : run_layer(o.layers + "/" + file, name, o.quick ? 5 : 101)) rows.push_back(r);
        }
    const std::string coherence = coherence_study(o.quick ? 1000 : 10000, 21);
    const std::string text = table(rows) + "\n" + coherence;
    std::cout << text;
    if (!o.out.empty()) {
        std::filesystem::create_directories(o.out);
        write_output(o.out + "/world.md",
                     "# The world's time study\n\nMade by `influence2d-world-bench" +
                         std::string(o.quick ? " --quick" : "") +
                         "`: time per step (the mean over the steps after the first, so that a step that rebuilds a "
                         "tree counts as often as it comes; scenes of 100 bodies run ten times over, each method made "
                         "anew; the median step beside it; a layer's join: the median of its runs in both, 101 (5 with "
                         "--quick)), the methods interleaved step by step in an order shuffled at each step; "
                         "`x fastest peer` is the fastest "
                         "peer's time per step over the method's (above 1: faster); "
                         "`wrong pairs` counts the pairs that differ from the certified world's over all steps.\n\n" +
                         text + "\n![time per step](world_time.png)\n");
        write_output(o.out + "/world.csv", csv(rows));
        const std::string script = plot_script(rows, scenes, o.out + "/world_time.png", o.out);
        write_output(o.out + "/world_time.gp", script);
        if (std::system(("gnuplot " + o.out + "/world_time.gp").c_str()) != 0)
            std::cerr << "world bench: gnuplot failed; the table and the CSV are written\n";
    }
}

}  // namespace

}  // namespace influence2d::cli

int main(int argc, char** argv) {
    using namespace influence2d::cli;
    CLI::App app{
        "The world's time study: many bodies stepped pose by pose, the library's worlds against GEOS, "
        "Boost.Geometry, Box2D and the all-pairs loop, and the layer form on real layers",
        "influence2d-world-bench"};
    auto o = std::make_shared<bench_options>();
    app.add_flag("--quick", o->quick, "100 and 1000 bodies only, fewer runs of the layers");
    app.add_option("--sizes", o->sizes, "Body counts (default 100,1000,10000,100000)")->delimiter(',');
    app.add_option("--steps", o->steps, "Steps per scene (default 21, 11 from 10,000 bodies)");
    app.add_option("--layers", o->layers, "Directory of the real layers' WKT files (scripts/real_layers.sh)")
        ->type_name("DIR");
    app.add_option("--out", o->out, "Write world.md, world.csv and world_time.png into DIR")->type_name("DIR");
    app.callback([o] { run(*o); });
    return run_tool(app, argc, argv);
}
