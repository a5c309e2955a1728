// SPDX-License-Identifier: BSL-1.0
// The influence2d-real-bench program: the time study on pairs of real
// polygons (countries, New York City boroughs and North Carolina counties
// from scripts/real_layers.sh: multipolygons of many parts, long shared
// borders, coordinates far from 0).
// The moving polygon of each pair is posed by poses that mostly overlap the
// static one: a random walk (coherent, each pose a small step from the last)
// and the same poses shuffled (no coherence); and by the walk's poses each
// pushed just clear of the static polygon (apart, within a 4096th of the
// pair's range of touching), in the walk's order and shuffled. Every method
// answers the same
// poses in the same order, posing included, preparation excluded; the methods
// are interleaved in a rotating order over repeated runs and each one's time
// per pose is the median over the runs. Every answer is compared with the
// certified detector's (exact).
//
// Exit codes: 0 success (or --help), 2 bad usage or a file that cannot be
// read or written.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <boost/geometry.hpp>

#include "files.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/number/cgal.hpp"
#include "report.hpp"
#include "tool.hpp"
#include "verification/peers.hpp"
#include "verification/real_pairs.hpp"
#include "verification/world_peers.hpp"
#include "world_input.hpp"

namespace influence2d::cli {

namespace {

using verification::pose_orders;
using verification::real_pair;
using verification::study_pairs;
using clock_type = std::chrono::steady_clock;

/// A method: built for the pair (outside the time), then asked every pose of
/// a sequence in order.
struct method {
    std::string name;
    std::function<std::function<bool(const pose&)>(const polygon&, const polygon&)> make;
    /// Whether the method may answer a prefix of the poses only (to fit the
    /// budget): the slow ones.
    bool budgeted = false;
};

template <class Detector>
method detector_method(const std::string& name, bool budgeted) {
    return {name,
            [](const polygon& a, const polygon& b) {
                auto d = std::make_shared<Detector>(a, b);
                d->build_structures();
                return std::function<bool(const pose&)>([d](const pose& q) { return d->collide(q).collides; });
            },
            budgeted};
}

std::vector<method> methods() {
    std::vector<method> m;
    m.push_back(detector_method<certified_detector<detector>>("certified", false));
    m.push_back(detector_method<detector<double>>("double", false));
    m.push_back(detector_method<detector<exact_rational>>("exact", true));
#if INFLUENCE2D_HAVE_GEOS
    m.push_back({"GEOS prepared",
                 [](const polygon& a, const polygon& b) {
                     struct state {
                         verification::geos_builder g;
                         GEOSGeometry* a = nullptr;
                         const GEOSPreparedGeometry* prepared = nullptr;
                         std::vector<std::vector<std::vector<point<double>>>> b_parts;
                         ~state() {
                             if (prepared) GEOSPreparedGeom_destroy_r(g.ctx, prepared);
                             if (a) GEOSGeom_destroy_r(g.ctx, a);
                         }
                     };
                     auto s = std::make_shared<state>();
                     s->a = verification::geos_multi_posed(s->g, verification::peer_parts(a), rotation_pose(pose{}));
                     s->prepared = GEOSPrepare_r(s->g.ctx, s->a);
                     s->b_parts = verification::peer_parts(b);
                     return std::function<bool(const pose&)>([s](const pose& q) {
                         GEOSGeometry* g = verification::geos_multi_posed(s->g, s->b_parts, rotation_pose(q));
                         const char answer = GEOSPreparedIntersects_r(s->g.ctx, s->prepared, g);
                         GEOSGeom_destroy_r(s->g.ctx, g);
                         return s->g.answer(answer, "GEOSPreparedIntersects_r");
                     });
                 },
                 false});
#endif
    m.push_back(
        {"Boost.Geometry",
         [](const polygon& a, const polygon& b) {
             auto am = std::make_shared<verification::bg_multi>(
                 verification::bg_multi_posed(verification::peer_parts(a), rotation_pose(pose{})));
             auto parts =
                 std::make_shared<std::vector<std::vector<std::vector<point<double>>>>>(verification::peer_parts(b));
             return std::function<bool(const pose&)>([am, parts](const pose& q) {
                 return boost::geometry::intersects(*am, verification::bg_multi_posed(*parts, rotation_pose(q)));
             });
         },
         true});
    return m;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

struct row {
    std::string pair, order, method;
    std::size_t static_vertices = 0, moving_vertices = 0, poses = 0, collisions = 0, wrong = 0;
    double us = 0;  ///< median time per pose
};

/// The rows of one pair and one pose order: each method over `poses` (a
/// budgeted one over the prefix that fits `budget` seconds a run), `runs`
/// runs interleaved.
std::vector<row> run_order(const std::string& pair_name, const std::string& order, const polygon& a, const polygon& b,
                           const std::vector<pose>& poses, int runs, double budget) {
    const std::vector<method> all = methods();
    const std::size_t n = all.size();
    std::vector<std::size_t> count(n, poses.size());
    for (std::size_t m = 0; m < n; ++m)
        if (all[m].budgeted) {
            // A pilot over the first poses sets the prefix.
            auto ask = all[m].make(a, b);
            const std::size_t pilot = std::min<std::size_t>(poses.size(), 4);
            const auto start = clock_type::now();
            for (std::size_t k = 0; k < pilot; ++k) ask(poses[k]);
            const double per =
                std::chrono::duration<double>(clock_type::now() - start).count() / static_cast<double>(pilot);
            count[m] =
                std::clamp<std::size_t>(static_cast<std::size_t>(budget / std::max(per, 1e-9)), pilot, poses.size());
        }
    std::vector<std::vector<double>> seconds(n);
    std::vector<std::vector<char>> answers(n);
    for (int r = 0; r < runs; ++r)
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t m = (k + static_cast<std::size_t>(r)) % n;  // rotating order
            auto ask = all[m].make(a, b);
            std::vector<char> got(count[m]);
            const auto start = clock_type::now();
            for (std::size_t i = 0; i < count[m]; ++i) got[i] = ask(poses[i]);
            seconds[m].push_back(std::chrono::duration<double>(clock_type::now() - start).count() /
                                 static_cast<double>(count[m]));
            answers[m] = std::move(got);
        }
    std::vector<row> out;
    for (std::size_t m = 0; m < n; ++m) {
        row r{pair_name, order, all[m].name, a.size(), b.size(), count[m], 0, 0, median(seconds[m]) * 1e6};
        for (std::size_t i = 0; i < count[m]; ++i) {
            r.collisions += answers[m][i] != 0;
            r.wrong += answers[m][i] != answers[0][i];
        }
        out.push_back(r);
    }
    return out;
}

std::string table(const std::vector<row>& rows) {
    std::string t =
        "| static x moving | vertices | poses | method | time per pose (us) | x GEOS prepared | poses asked | "
        "collisions | wrong |\n|---|---:|---|---|---:|---:|---:|---:|---:|\n";
    for (const row& r : rows) {
        double geos = 0;
        for (const row& g : rows)
            if (g.pair == r.pair && g.order == r.order && g.method == "GEOS prepared") geos = g.us;
        t += "| " + r.pair + " | " + std::to_string(r.static_vertices) + " x " + std::to_string(r.moving_vertices) +
             " | " + r.order + " | " + r.method + " | " + fixed(r.us, 2) + " | " +
             (geos > 0 ? fixed(geos / r.us, 2) : std::string("-")) + " | " + std::to_string(r.poses) + " | " +
             std::to_string(r.collisions) + " | " + std::to_string(r.wrong) + " |\n";
    }
    return t;
}

std::string csv(const std::vector<row>& rows) {
    std::string t = "pair,static_vertices,moving_vertices,order,method,us_per_pose,poses,collisions,wrong\n";
    for (const row& r : rows)
        t += "\"" + r.pair + "\"," + std::to_string(r.static_vertices) + "," + std::to_string(r.moving_vertices) +
             ",\"" + r.order + "\",\"" + r.method + "\"," + fixed(r.us, 3) + "," + std::to_string(r.poses) + "," +
             std::to_string(r.collisions) + "," + std::to_string(r.wrong) + "\n";
    return t;
}

struct bench_options {
    std::string layers, out;
    std::size_t poses = 600;
    int runs = 5;
    double budget = 0.5;
    std::uint64_t seed = 20040202;
};

void run(const bench_options& o) {
    std::vector<row> rows;
    for (const real_pair& p : study_pairs()) {
        const polygon a = named_polygon(o.layers, p.layer, p.a), b = named_polygon(o.layers, p.layer, p.b);
        const std::string name = p.a + " x " + p.b;
        std::cerr << "real bench: " << name << "\n";
        for (const auto& [order, poses] : pose_orders(p, a, b, o.poses, o.seed))
            for (const row& r : run_order(name, order, a, b, poses, o.runs, o.budget)) rows.push_back(r);
    }
    const std::string text = table(rows);
    std::cout << text;
    if (!o.out.empty()) {
        std::filesystem::create_directories(o.out);
        write_output(
            o.out + "/real.md",
            "# Real pairs\n\nMade by `influence2d-real-bench --poses " + std::to_string(o.poses) + " --runs " +
                std::to_string(o.runs) +
                "`: the moving polygon posed along a random walk (`walk`: each pose a "
                "step of up to 1/50 of the range from the last) and the same poses shuffled (`shuffled`), in a "
                "range of translations and turns about the origin where the polygons mostly overlap; then each "
                "pose of the walk pushed along the direction from the static polygon's box centre to the moving "
                "one's just clear of the static polygon (`apart, walk`: the least push found apart by the "
                "certified detector, to within a 4096th of the range's translation; the same poses shuffled: "
                "`apart, shuffled`), where the polygons come nearest without meeting; time per pose "
                "(posing included, preparation excluded), the median of the runs, the methods interleaved; "
                "`x GEOS prepared` above 1 is faster than GEOS's prepared intersects; the exact detector and "
                "Boost.Geometry ask the prefix of the poses that fits the budget; `wrong` counts answers that "
                "differ from the certified detector's.\n\n" +
                text);
        write_output(o.out + "/real.csv", csv(rows));
    }
}

}  // namespace

}  // namespace influence2d::cli

int main(int argc, char** argv) {
    using namespace influence2d::cli;
    CLI::App app{
        "The time study on pairs of real polygons (countries, New York City boroughs, North Carolina counties) "
        "against GEOS and "
        "Boost.Geometry, coherent and shuffled poses",
        "influence2d-real-bench"};
    auto o = std::make_shared<bench_options>();
    app.add_option("--layers", o->layers, "Directory of the real layers (scripts/real_layers.sh)")
        ->required()
        ->type_name("DIR");
    app.add_option("--poses", o->poses, "Poses per pair and order")
        ->capture_default_str()
        ->check(CLI::Range(4, 1000000));
    app.add_option("--runs", o->runs, "Runs of each method, interleaved (the median is reported)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    app.add_option("--budget", o->budget, "Seconds a run of the exact detector or Boost.Geometry may take")
        ->capture_default_str()
        ->check(CLI::Range(0.001, 1e6));
    app.add_option("--seed", o->seed, "Seed of the poses")->capture_default_str();
    app.add_option("--out", o->out, "Write real.md and real.csv into DIR")->type_name("DIR");
    app.callback([o] { run(*o); });
    return run_tool(app, argc, argv);
}
