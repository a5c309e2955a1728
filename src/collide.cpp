// SPDX-License-Identifier: BSL-1.0
// `influence2d collide`: runs a detector over a sequence of poses of the moving
// polygon and reports the frames that collide.

#include <chrono>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "commands.hpp"
#include "scene_input.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/certified_detector.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/detect/interval_detector.hpp"
#include "influence2d/detect/paper_detector.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/detect/trajectory.hpp"
#include "influence2d/io/csv.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/multiprecision.hpp"

namespace influence2d::cli {

namespace {

struct collide_options {
    scene_options scene;
    std::string number_type = "double";
    std::string algorithm = "sound";
    std::string shape = "capsule";
    double distance = 0.0;
    bool witness = false;
    std::string out;
};

struct run_result {
    std::vector<frame_result> frames;
    double seconds = 0;
    /// Filtered number types (certified, interval): frames answered again in
    /// exact rationals.
    std::optional<std::size_t> exact_frames;
};

/// Times the frame loop of a built detector.
template <class Detector>
run_result time_frames(Detector& det, const std::vector<pose>& poses) {
    run_result r;
    r.frames.resize(poses.size());
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < poses.size(); ++i) r.frames[i] = det.collide(poses[i]);
    const auto stop = std::chrono::steady_clock::now();
    r.seconds = std::chrono::duration<double>(stop - start).count();
    return r;
}

/// Builds the detector (not timed), then times the frame loop alone.
template <template <class...> class Detector, class NT>
run_result run_frames(const polygon& a, const polygon& b, const std::vector<pose>& poses,
                      const detector_options& options) {
    Detector<NT> det(a, b, options);
    return time_frames(det, poses);
}

/// The same for a filtered number type: Wrapper<Detector> runs Detector in the
/// fast type and answers a frame again in exact rationals when a sign is not
/// certain (certified_detector, interval_detector).
template <template <template <class...> class> class Wrapper, template <class...> class Detector>
run_result run_filtered(const polygon& a, const polygon& b, const std::vector<pose>& poses,
                        const detector_options& options) {
    Wrapper<Detector> det(a, b, options);
    run_result r = time_frames(det, poses);
    r.exact_frames = det.exact_frames();
    return r;
}

template <class NT>
run_result run_algorithm(const std::string& algorithm, const polygon& a, const polygon& b,
                         const std::vector<pose>& poses, const detector_options& options) {
    if (algorithm == "paper") return run_frames<paper_detector, NT>(a, b, poses, options);
    if (algorithm == "brute-force") return run_frames<brute_force_detector, NT>(a, b, poses, options);
    return run_frames<detector, NT>(a, b, poses, options);
}

template <template <template <class...> class> class Wrapper>
run_result run_filtered_algorithm(const std::string& algorithm, const polygon& a, const polygon& b,
                                  const std::vector<pose>& poses, const detector_options& options) {
    if (algorithm == "brute-force") return run_filtered<Wrapper, brute_force_detector>(a, b, poses, options);
    return run_filtered<Wrapper, detector>(a, b, poses, options);
}

/// Whether the number type answers through an exact fallback, which the
/// paper's detector cannot use: its influence mask carries over from frame to
/// frame, and a frame redone in exact rationals would not see the mask the
/// fast detector built (nor leave it one), so the two would drift apart.
bool is_filtered(const std::string& number_type) {
    return number_type == "certified" || number_type == "interval";
}

run_result run(const std::string& number_type, const std::string& algorithm, const polygon& a,
               const polygon& b, const std::vector<pose>& poses, const detector_options& options) {
    if (number_type == "float") return run_algorithm<float>(algorithm, a, b, poses, options);
    if (number_type == "long-double")
        return run_algorithm<long double>(algorithm, a, b, poses, options);
    if (number_type == "quad") return run_algorithm<quad>(algorithm, a, b, poses, options);
    if (number_type == "exact") return run_algorithm<exact_rational>(algorithm, a, b, poses, options);
    if (number_type == "certified")
        return run_filtered_algorithm<certified_detector>(algorithm, a, b, poses, options);
    if (number_type == "interval")
        return run_filtered_algorithm<interval_detector>(algorithm, a, b, poses, options);
    return run_algorithm<double>(algorithm, a, b, poses, options);
}

/// Writes the frames to `out` through `out.tmp` in the same directory, renamed
/// into place: a failure leaves neither a partial nor a changed file.
void write_frames_file(const std::string& out, const std::vector<frame_result>& frames,
                       bool witness) {
    const std::string temp = out + ".tmp";
    std::error_code ec;
    {
        std::ofstream file(temp, std::ios::binary | std::ios::trunc);
        if (!file) throw std::runtime_error(temp + ": cannot open file for writing");
        write_frames_csv(file, frames, witness);
        file.close();
        if (!file) {
            std::filesystem::remove(temp, ec);
            throw std::runtime_error(temp + ": write error");
        }
    }
    std::filesystem::rename(temp, out, ec);
    if (ec) {
        const std::string why = ec.message();
        std::filesystem::remove(temp, ec);
        throw std::runtime_error(out + ": cannot rename " + temp + " into place: " + why);
    }
}

std::string format_fixed(double x, int digits) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << x;
    return s.str();
}

void run_collide(const collide_options& o) {
    if (o.algorithm == "paper" && is_filtered(o.number_type))
        throw std::invalid_argument("--number-type " + o.number_type +
                                    " cannot run --algorithm paper: the paper's detector keeps "
                                    "its influence mask from frame to frame, which a frame "
                                    "answered again in exact arithmetic cannot hand back; use "
                                    "--algorithm sound or brute-force, or another number type");
    // Read every input and check the output path first; report all problems at once.
    const scene_input in = read_scene(o.scene, o.out);
    const polygon &a = in.a, &b = in.b;
    const std::vector<pose>& poses = in.poses;

    detector_options options;
    options.distance = o.distance;
    options.witness = o.witness;
    options.shape = o.shape == "band" ? extended_area::band : extended_area::capsule;

    const run_result r = run(o.number_type, o.algorithm, a, b, poses, options);

    std::size_t collisions = 0, first = 0;
    bool any = false;
    for (std::size_t i = 0; i < r.frames.size(); ++i) {
        if (!r.frames[i].collides) continue;
        if (!any) first = i;
        any = true;
        ++collisions;
    }

    if (!o.out.empty()) write_frames_file(o.out, r.frames, o.witness);

    const double total_ms = r.seconds * 1e3;
    std::cout << "frames:          " << r.frames.size() << "\n"
              << "collisions:      " << collisions << "\n"
              << "first collision: " << (any ? "frame " + std::to_string(first) : "none") << "\n"
              << "number type:     " << o.number_type << "\n"
              << "algorithm:       " << o.algorithm << "\n"
              << "time per frame:  "
              << (r.frames.empty()
                      ? std::string("n/a")
                      : format_fixed(r.seconds * 1e6 / static_cast<double>(r.frames.size()), 3) +
                            " us")
              << "   (total " << format_fixed(total_ms, total_ms >= 1 ? 1 : 3) << " ms)\n";
    if (r.exact_frames)
        std::cout << "exact fallbacks: " << *r.exact_frames << " frames\n";
    if (!o.out.empty()) std::cout << "frames written:  " << o.out << "\n";
}

}  // namespace

void register_collide(CLI::App& app) {
    auto o = std::make_shared<collide_options>();
    CLI::App* sub = app.add_subcommand(
        "collide",
        "Run a collision detector between a static polygon and a moving polygon over a "
        "sequence of poses of the moving one (from a CSV file or one of the paper's "
        "trajectories); print a summary and optionally write one line per frame.");

    add_scene_options(sub, o->scene, "--frames");
    sub->add_option("--number-type", o->number_type,
                    "Arithmetic of the detector's decisions: float, double, long-double, quad "
                    "(113-bit software floating point); exact (CGAL rationals: exact answers, "
                    "slower); certified (double with a running error bound: exact answers, a "
                    "frame whose signs double cannot certify is answered again in exact "
                    "rationals, counted as 'exact fallbacks'); interval (the same with CGAL's "
                    "interval arithmetic). certified and interval run with --algorithm sound "
                    "or brute-force only")
        ->capture_default_str()
        ->check(CLI::IsMember({"float", "double", "long-double", "quad", "exact", "certified", "interval"}))
        ->type_name("TYPE");
    sub->add_option("--algorithm", o->algorithm,
                    "Detector: sound (the method with its defects fixed), paper (Algorithm 3 "
                    "as published, which can miss or invent collisions) or brute-force (every "
                    "edge pair, the reference)")
        ->capture_default_str()
        ->check(CLI::IsMember({"sound", "paper", "brute-force"}))
        ->type_name("ALGO");
    sub->add_option("--extended-area", o->shape,
                    "Shape of the extended influence area of an edge: capsule (points within "
                    "the reach of the segment) or band (the paper's band with axis-parallel caps)")
        ->capture_default_str()
        ->check(CLI::IsMember({"capsule", "band"}))
        ->type_name("SHAPE");
    sub->add_option("--distance", o->distance,
                    "Separation distance D: a frame collides when the polygons are at distance "
                    "<= D (0: they intersect or touch)")
        ->capture_default_str()
        ->check(finite_non_negative())
        ->type_name("D");
    sub->add_flag("--witness", o->witness,
                  "Also report, per frame, the pairs (static edge : moving edge) within the "
                  "distance, edges numbered in input order from 0, rings one after another");
    sub->add_option("--out", o->out,
                    "Write one CSV line per frame (frame,collides[,edges]) to this file; it is "
                    "replaced only when the whole run succeeds")
        ->type_name("FRAMES.csv");

    sub->callback([o] { run_collide(*o); });
}

}  // namespace influence2d::cli
