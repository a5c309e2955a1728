// SPDX-License-Identifier: BSL-1.0
// The time study (verification/time_study.hpp, influence2d-bench): one
// registry names, parses and builds every method; every method runs on the
// same poses of each cell, influence2d's modes agree with the reference on
// every pose, a peer's strided poses are counted; the random stream is seeded
// and lies in its annulus, and the random and one-shot workloads agree with
// the reference; every row carries its preparation; the largest cell gets its
// peak heap per method; the command writes its tables and heat maps and names
// bad arguments.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/process.hpp"
#include "verification/time_study.hpp"
#include "verification/turning_study.hpp"

namespace {

namespace fs = std::filesystem;
using namespace influence2d;
using namespace influence2d::verification;
using test_process::lines_of;
using test_process::quote;
using test_process::run_bench;
using test_process::slurp;
using test_process::temp_dir;

std::string cell_of(const time_row& row) {
    return row.cell.type + "/" + row.cell.trajectory + "/" + std::to_string(row.cell.static_size) + "x" +
           std::to_string(row.cell.moving_size);
}

/// A tiny grid: two types, the workloads given, two sizes, short budgets.
time_study_options tiny_grid(const std::string& type, const std::vector<std::string>& trajectories, std::size_t size) {
    time_study_options o;
    o.types = {"convex", type};
    o.trajectories = trajectories;
    o.sizes = {8, size};
    o.circular_frames = 400;
    o.linear_frames = 200;
    o.random_frames = 300;
    return o;
}

/// The methods of this build that have a form for the workload.
std::size_t methods_on(const std::string& trajectory) {
    std::size_t n = 0;
    for (const std::string& m : time_study_methods()) n += runs_on(m, trajectory) ? 1 : 0;
    return n;
}

/// Box2D's methods (its overlap test and its contact manifold), which take
/// only the convex 8-gons: 0 when Box2D was not found.
std::size_t box2d_methods() { return method_available("box2d") ? 2 : 0; }

}  // namespace

TEST_CASE("time study: the registry names, parses and builds every method", "[verification][bench][time_study]") {
    REQUIRE(known_methods().size() == method_infos().size());
    std::set<std::string> names;
    const polygon a = make_family_polygon(family::convex, 8, default_family_seed);
    const polygon b = make_family_polygon(family::convex, 8, default_family_seed);
    const pose apart{1000, 0, 0};
    for (const std::string& m : known_methods()) {
        INFO(m);
        CHECK(names.insert(m).second);  // no name twice
        CHECK(method_of(m).name == m);
        CHECK(method_available(m) == method_of(m).available);
        CHECK((runs_on(m, "circular") || runs_on(m, "one-shot")));
        CHECK(runs_on(m, "circular") == runs_on(m, "random"));
        if (!method_available(m)) {
            CHECK_THROWS_AS(check_methods({m}), std::invalid_argument);
            continue;
        }
        // Each form builds for a pair it applies to and answers a pose.
        for (const std::string& j : known_trajectories()) {
            if (!runs_on(m, j)) continue;
            INFO(j);
            REQUIRE(method_of(m).applies(a, b));
            // Apart, and B on A (the same polygon at the identity): the
            // certified detector's answers.
            const pose on_top{0, 0, 0};
            REQUIRE(certified_detector<detector>(a, b).collide(on_top).collides);
            bool answer = true, overlapping = false;
            with_method(m, j, a, b, [&](auto& d) {
                answer = form_collides(d, apart);
                overlapping = form_collides(d, on_top);
            });
            CHECK(!answer);
            CHECK(overlapping);
            // A build was timed: a finite, positive duration (its size is not
            // checked).
            const double built = build_seconds(m, j, a, b);
            CHECK(std::isfinite(built));
            CHECK(built > 0);
        }
    }
    // Influence2d's methods first, then the peers.
    bool peer_seen = false;
    for (const method_info& i : method_infos()) {
        if (!i.own) peer_seen = true;
        CHECK((i.own || peer_seen));
        if (peer_seen) CHECK(!i.own);
    }
    CHECK(runs_on("double-detector", "one-shot"));
    CHECK(!runs_on("double-detector", "circular"));
    CHECK(!runs_on("paper", "one-shot"));
    CHECK(is_own_method("double"));
    CHECK(!is_own_method("geos"));

    // An unknown name is refused with the name and the known ones.
    try {
        (void)method_of("pivot2d");
        FAIL("pivot2d accepted");
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        CHECK(what.find("unknown method 'pivot2d'") != std::string::npos);
        for (const std::string& m : known_methods()) CHECK(what.find(m) != std::string::npos);
    }
    CHECK_THROWS_AS(with_method("double-detector", "linear", a, b, [](auto&) {}), std::invalid_argument);
    time_study_options o;
    o.methods = {"double", "pivot2d"};
    CHECK_THROWS_AS(run_time_study(o), std::invalid_argument);
    o.methods = {"double"};
    o.trajectories = {"spiral"};
    CHECK_THROWS_AS(run_time_study(o), std::invalid_argument);
}

namespace {

/// A stand-in for a method's form: records the poses it is asked and
/// answers tx > 0, as a bool or as a frame_result.
template <bool as_bool>
struct recording_form {
    std::vector<pose> asked;
    auto collide(const pose& p) {
        asked.push_back(p);
        if constexpr (as_bool)
            return p.tx > 0;
        else
            return frame_result{p.tx > 0, {}};
    }
};

template <bool as_bool>
void check_run_frames() {
    std::vector<pose> poses;
    for (int k = 0; k < 10; ++k) poses.push_back({k % 3 == 0 ? 1.0 + k : -1.0 - k, static_cast<double>(k), 0});
    for (const std::size_t stride :
         {std::size_t{1}, std::size_t{3}, std::size_t{4}, std::size_t{10}, std::size_t{11}}) {
        INFO("stride " << stride);
        recording_form<as_bool> d;
        std::vector<char> answers{1, 1, 1};  // cleared by the run
        const double seconds = run_frames(d, poses, stride, answers);
        CHECK(std::isfinite(seconds));
        CHECK(seconds >= 0);
        // Every stride-th pose from the first, in order, once; one answer each.
        const std::size_t expected = (poses.size() + stride - 1) / stride;
        REQUIRE(d.asked.size() == expected);
        REQUIRE(answers.size() == expected);
        for (std::size_t k = 0; k < expected; ++k) {
            CHECK(d.asked[k].ty == poses[k * stride].ty);
            CHECK(answers[k] == (poses[k * stride].tx > 0 ? 1 : 0));
        }
    }
}

}  // namespace

TEST_CASE("time study: a timed run asks every stride-th pose once and keeps each answer",
          "[verification][bench][time_study]") {
    check_run_frames<true>();
    check_run_frames<false>();
}

TEST_CASE("time study: the random poses are seeded and lie in the annulus", "[verification][bench][time_study]") {
    time_study_options o;
    o.random_frames = 2000;
    for (family f : all_families) {
        const polygon a = make_family_polygon(f, 64, o.seed), b = make_family_polygon(f, 16, o.seed);
        INFO(family_name(f));
        const time_cell c{family_name(f), "random", 64, 16};
        const std::vector<pose> poses = time_study_poses(o, c, a, b);
        REQUIRE(poses.size() == 2000);
        // The same seed, the same poses; one-shot asks the same poses.
        const std::vector<pose> again = time_study_poses(o, c, a, b);
        const std::vector<pose> one_shot = time_study_poses(o, {c.type, "one-shot", 64, 16}, a, b);
        time_study_options other = o;
        other.seed = o.seed + 1;
        const std::vector<pose> reseeded = time_study_poses(other, c, a, b);
        std::size_t same = 0;
        for (std::size_t k = 0; k < poses.size(); ++k) {
            CHECK((poses[k].tx == again[k].tx && poses[k].ty == again[k].ty && poses[k].theta == again[k].theta));
            CHECK((poses[k].tx == one_shot[k].tx && poses[k].ty == one_shot[k].ty &&
                   poses[k].theta == one_shot[k].theta));
            same += poses[k].tx == reseeded[k].tx ? 1 : 0;
        }
        CHECK(same == 0);

        // The annulus: 0.4 and 1.1 times R_A + R_B about A's centroid (the
        // families are drawn within radius 50 of their centre, which is near
        // the centroid: about 40..110), B's centroid in it, spread over it.
        const double r = bounding_radius(a, a.centroid()) + bounding_radius(b, b.centroid());
        const auto [inner, outer] = random_annulus(o, a, b);
        CHECK(inner == Approx(0.4 * r));
        CHECK(outer == Approx(1.1 * r));
        CHECK(inner > 30);
        CHECK(inner < 50);
        CHECK(outer > 80);
        CHECK(outer < 130);
        const point<double> oa = a.centroid(), cb = b.centroid();
        double lo = HUGE_VAL, hi = 0;
        std::size_t inside_half = 0;  // nearer than the median radius of the area
        for (const pose& p : poses) {
            const double c2 = std::cos(p.theta), s2 = std::sin(p.theta);
            const double x = c2 * cb.x - s2 * cb.y + p.tx, y = s2 * cb.x + c2 * cb.y + p.ty;
            const double d = std::hypot(x - oa.x, y - oa.y);
            lo = std::min(lo, d);
            hi = std::max(hi, d);
            inside_half += d * d < (inner * inner + outer * outer) / 2 ? 1 : 0;
        }
        CHECK(lo >= inner * (1 - 1e-9));
        CHECK(hi <= outer * (1 + 1e-9));
        CHECK(lo < inner + 0.05 * (outer - inner));
        CHECK(hi > outer - 0.05 * (outer - inner));
        CHECK(inside_half > 900);  // uniform in area: half the poses within the middle radius
        CHECK(inside_half < 1100);
    }
}

TEST_CASE("time study: every method on the same frames, answers against the reference",
          "[verification][bench][time_study]") {
    time_study_options o = tiny_grid("contour", {"circular", "linear"}, 32);
    o.budget = 0.002;
    o.memory_frames = 10;
    const time_study_result r = run_time_study(o);

    std::map<std::string, std::set<std::string>> methods_per_cell;
    for (const time_row& row : r.rows) {
        const std::string cell = cell_of(row);
        INFO(cell << " " << row.method);
        methods_per_cell[cell].insert(row.method);
        CHECK(row.trajectory_frames == (row.cell.trajectory == "circular" ? 400u : 200u));
        CHECK(row.frames == (row.trajectory_frames + row.stride - 1) / row.stride);  // every stride-th frame
        CHECK(row.seconds > 0);
        if (method_of(row.method).repeated) CHECK(row.stride == 1);  // all frames, in order
        if (row.method == "double" || row.method == "exact") CHECK(row.disagreements == 0);
        CHECK(row.reference == (row.method == "certified"));
        if (row.cell.trajectory == "circular" && row.method == "certified") CHECK(row.collisions == 0);
        if (row.cell.trajectory == "linear" && row.method == "certified") CHECK(row.collisions > 0);
    }
    CHECK(methods_per_cell.size() == 2 * 2 * 2 * 2);
    for (const auto& [cell, methods] : methods_per_cell) {
        INFO(cell);
        // Box2D takes only the convex 8-gons; every other method every cell.
        const bool box2d =
            method_available("box2d") && cell.rfind("convex/", 0) == 0 && cell.find("/8x8") != std::string::npos;
        CHECK(methods.size() == methods_on("circular") - (box2d ? 0 : box2d_methods()));
        CHECK(methods.count("box2d") == (box2d ? 1u : 0u));
        CHECK(methods.count("box2d-manifold") == (box2d ? 1u : 0u));
    }
    // The paper-literal variant's false answers show as disagreements.
    std::size_t paper_wrong = 0;
    for (const time_row& row : r.rows)
        if (row.method == "paper") paper_wrong += row.disagreements;
    CHECK(paper_wrong > 0);

    // The largest cell: convex circular 32x32, no Box2D.
    REQUIRE(r.memory.size() == methods_on("circular") - box2d_methods());
    for (const memory_row& m : r.memory) {
        INFO(m.method);
        CHECK(m.cell.static_size == 32);
        CHECK(m.frames > 0);
        if (m.method.rfind("box2d", 0) != 0) CHECK(m.peak_bytes > 0);
    }
}

TEST_CASE("time study: random and one-shot rows, no disagreement, the preparation of each",
          "[verification][bench][time_study]") {
    time_study_options o = tiny_grid("hole", {"random", "one-shot"}, 16);
    o.budget = 0.003;
    o.repeat_seconds = 0.001;
    o.preparation_seconds = 0.0005;
    o.memory_frames = 0;
    const time_study_result r = run_time_study(o);

    std::map<std::string, std::set<std::string>> methods_per_cell;
    for (const time_row& row : r.rows) {
        INFO(cell_of(row) << " " << row.method);
        methods_per_cell[cell_of(row)].insert(row.method);
        CHECK(runs_on(row.method, row.cell.trajectory));
        CHECK(row.trajectory_frames == 300);
        CHECK(row.frames == (row.trajectory_frames + row.stride - 1) / row.stride);
        CHECK(row.frames > 0);
        CHECK(row.seconds > 0);
        if (row.cell.trajectory == "random" && method_of(row.method).repeated) CHECK(row.stride == 1);
        // Every method in passes taking turns, an odd number: the repeated
        // ones repeated_passes at least, the strided ones exactly three.
        CHECK(row.passes % 2 == 1);
        if (method_of(row.method).repeated) CHECK(row.passes >= o.repeated_passes);
        if (!method_of(row.method).repeated) CHECK(row.passes == 3);
        if (row.method != "paper" && !method_of(row.method).approximate) CHECK(row.disagreements == 0);
        CHECK(row.reference == (row.method == "certified" && row.cell.trajectory == "random"));
        // The random poses near contact both collide and miss.
        if (row.method == "certified") {
            CHECK(row.collisions > 0);
            CHECK(row.collisions < row.frames);
        }
        // The preparation: measured, the median of at least 3 builds, an odd number.
        CHECK(row.preparation_builds >= 3);
        CHECK(row.preparation_builds % 2 == 1);
        CHECK(row.preparation_seconds > 0);
    }
    CHECK(methods_per_cell.size() == 2 * 2 * 2 * 2);
    for (const auto& [cell, methods] : methods_per_cell) {
        INFO(cell);
        const std::string workload = cell.find("/one-shot/") != std::string::npos ? "one-shot" : "random";
        const bool box2d =
            method_available("box2d") && cell.rfind("convex/", 0) == 0 && cell.find("/8x8") != std::string::npos;
        CHECK(methods.size() == methods_on(workload) - (box2d ? 0 : box2d_methods()));
        CHECK(methods.count("double-witness") == (workload == "random" ? 1u : 0u));
        CHECK(methods.count("double") == 1);
        CHECK(methods.count("certified") == 1);
        CHECK(methods.count("double-detector") == (workload == "one-shot" ? 1u : 0u));
        CHECK(methods.count("paper") == (workload == "random" ? 1u : 0u));
    }
}

TEST_CASE("time study: the command writes the table, the summary and the heat maps",
          "[verification][bench][cli][time_study][bench_program]") {
    const temp_dir dir;
    const auto r = run_bench(dir,
                             "--quick --types convex --sizes 8,16 --trajectories linear,one-shot "
                             "--random-frames 200 --out " +
                                 quote((dir / "out").string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("## Targets") != std::string::npos);
    CHECK(r.out.find("one-shot: intersects<double> against Boost.Geometry intersects") != std::string::npos);
    const std::vector<std::string> csv = lines_of(slurp(dir / "out" / "bench.csv"));
    REQUIRE(!csv.empty());
    CHECK(csv.front() ==
          "type,trajectory,static,moving,method,trajectory_frames,frames,stride,passes,total_seconds,ns_per_frame,"
          "collisions,disagreements,preparation_seconds,preparation_builds");
    // 4 cells per workload, every method with a form for it but Box2D in
    // each, Box2D in 8x8.
    const std::size_t box2d = box2d_methods();
    CHECK(csv.size() == 1 + 4 * (methods_on("linear") - box2d) + box2d + 4 * (methods_on("one-shot") - box2d) + box2d);
    for (std::size_t k = 1; k < csv.size(); ++k) {
        INFO(csv[k]);
        const std::string prep = csv[k].substr(csv[k].rfind(',', csv[k].rfind(',') - 1) + 1);
        CHECK(std::stod(prep.substr(0, prep.find(','))) > 0);  // preparation_seconds
    }
    const std::string md = slurp(dir / "out" / "bench.md");
    // The turning study, --quick: convex 8x8 (Box2D's time of impact too)
    // and contour 64x64, the library's four routes and a sampling per
    // resolution.
    const std::size_t geos = method_available("geos") ? turning_study_options{}.samples.size() : 0;
    CHECK(lines_of(slurp(dir / "out" / "turning.csv")).size() ==
          1 + 2 * (4 + geos) + (method_available("box2d") ? 1 : 0));
    CHECK(md.find("## Turning motions") != std::string::npos);
    CHECK(r.out.find("turning motions (32 per cell") != std::string::npos);
    CHECK(md.find("## Speed-up of the double mode over the fastest peer") != std::string::npos);
    CHECK(md.find("### convex, one-shot") != std::string::npos);
    CHECK(md.find("## Certified over double") != std::string::npos);
    CHECK(md.find("## One-shot against each peer") != std::string::npos);
    CHECK(md.find("## Preparation") != std::string::npos);
    CHECK(md.find("## Peak heap memory") != std::string::npos);
    if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
        CHECK(slurp(dir / "out" / "heatmap_double.png").substr(1, 3) == "PNG");
        CHECK(slurp(dir / "out" / "heatmap_one-shot_double.png").substr(1, 3) == "PNG");
        CHECK(!fs::exists(dir / "out" / "heatmap_random_double.png"));  // not asked
        // Speed-up maps over the fastest peer, and the raster methods (run by
        // default on the frame workloads) against their time.
        CHECK(slurp(dir / "out" / "speedup_double.png").substr(1, 3) == "PNG");
        CHECK(slurp(dir / "out" / "speedup_certified.png").substr(1, 3) == "PNG");
        CHECK(slurp(dir / "out" / "raster_error_vs_time.svg").find("raster-64") != std::string::npos);
    }
}

TEST_CASE("time study: bad arguments are named, exit code 2", "[verification][bench][cli][time_study][bench_program]") {
    const temp_dir dir;
    const std::string out = " --out " + quote((dir / "out").string());
    const auto bad_size = run_bench(dir, "--sizes 8,100" + out);
    CHECK(bad_size.exit_code == 2);
    CHECK(bad_size.err.find("100") != std::string::npos);
    const auto bad_method = run_bench(dir, "--methods double,pivot2d" + out);
    CHECK(bad_method.exit_code == 2);
    CHECK(bad_method.err.find("pivot2d") != std::string::npos);
    CHECK(bad_method.err.find("double-detector") != std::string::npos);  // the known names
    const auto bad_workload = run_bench(dir, "--trajectories spiral" + out);
    CHECK(bad_workload.exit_code == 2);
    CHECK(bad_workload.err.find("one-shot") != std::string::npos);
    CHECK(!fs::exists(dir / "out" / "bench.csv"));
    // The help lists every method from the registry.
    const auto help = run_bench(dir, "--help");
    CHECK(help.exit_code == 0);
    for (const std::string& m : known_methods()) CHECK(help.out.find("  " + m) != std::string::npos);
}
