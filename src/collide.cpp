// SPDX-License-Identifier: BSL-1.0
// `influence2d collide`: runs a detector over a sequence of poses of the moving
// polygon and reports the frames that collide.

#include <cstddef>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "files.hpp"
#include "motion_queries.hpp"
#include "number_types.hpp"
#include "report.hpp"
#include "scene_input.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/io/csv.hpp"

namespace influence2d::cli {

namespace {

struct collide_options {
    scene_options scene;
    std::string number_type = default_number_type;
    std::string algorithm = "sound";
    std::string shape = "capsule";
    double distance = 0.0;
    bool witness = false;
    bool separation = false;  ///< add the separation at every pose
    bool continuous = false;  ///< a frame collides when the motion into it meets A
    std::string static_poses;  ///< the static polygon's poses too, one per frame (empty: A unmoved)
    unsigned threads = 0;  ///< 0: every hardware thread
    std::string out;
    /// The old spelling of --trajectory-frames, still taken with a warning.
    std::size_t deprecated_frames = 0;
};

/// What a frame adds to FRAMES.csv beyond collides and the edges: the
/// continuous contact time (--continuous), the separation and the closest
/// features (--separation, the features with --witness).
struct frame_extras {
    const std::vector<contact_row>* contacts = nullptr;       ///< motion k - 1 into frame k
    const std::vector<separation_row>* separations = nullptr;  ///< per frame
    bool closest = false;

    std::vector<std::string> columns() const {
        std::vector<std::string> c;
        if (contacts) c.emplace_back("contact_t");
        if (separations) c.emplace_back("separation");
        if (separations && closest) c.emplace_back("closest");
        return c;
    }
    std::string values(std::size_t f) const {
        std::string v;
        bool first = true;
        const auto put = [&](const std::string& x) {
            if (!first) v += ',';
            v += x;
            first = false;
        };
        if (contacts) put(f > 0 && (*contacts)[f - 1].contact ? general((*contacts)[f - 1].t, 17) : std::string());
        if (separations) {
            const separation_row& r = (*separations)[f];
            put(general(r.distance, 17));
            if (closest) put(feature_text(r.static_feature) + ":" + feature_text(r.moving_feature));
        }
        return v;
    }
};

/// The frames as CSV, to `out` through `out.tmp` renamed into place (a
/// failure leaves neither a partial nor a changed file), or to standard output
/// for '-'.
void write_frames(const std::string& out, const std::vector<frame_result>& frames, bool witness,
                  const frame_extras& extras) {
    std::ostringstream text;
    write_frames_csv(text, frames, witness, extras.columns(), [&](std::size_t f) { return extras.values(f); });
    write_output(out, text.str());
}


void run_collide(collide_options o) {
    if (o.deprecated_frames != 0) {
        if (o.scene.frames != 0)
            throw std::invalid_argument("--frames is the old name of --trajectory-frames: give only one of them");
        std::cerr << "influence2d: warning: --frames is the old name of --trajectory-frames; use that\n";
        o.scene.frames = o.deprecated_frames;
    }
    const number_type& type = *find_number_type(o.number_type);  // the option's check has run
    if (o.algorithm == "paper" && type.exact_fallback)
        throw std::invalid_argument("--number-type " + o.number_type +
                                    " cannot run --algorithm paper: the paper's detector keeps "
                                    "its influence mask from frame to frame, which a frame "
                                    "answered again in exact arithmetic cannot hand back; use "
                                    "--algorithm sound or brute-force, or another number type");
    if (o.continuous && o.distance != 0)
        throw std::invalid_argument("--continuous asks whether the polygons meet between poses: it takes "
                                    "--distance 0 only (got " + general(o.distance, 17) + ")");
    if ((o.continuous || o.separation) && o.algorithm == "paper")
        throw std::invalid_argument(std::string(o.continuous ? "--continuous" : "--separation") +
                                    " is answered by the sound queries only, not --algorithm paper");
    // Read every input and check the output path first; report all problems at once.
    check_one_standard_input({{"--static", o.scene.static_path},
                              {"--moving", o.scene.moving_path},
                              {"--poses", o.scene.poses_path},
                              {"--static-poses", o.static_poses}});
    scene_input in = read_scene(o.scene, o.out);
    std::vector<pose> static_poses;
    if (!o.static_poses.empty()) {
        static_poses = read_poses_input(o.static_poses);
        if (static_poses.size() != in.poses.size())
            throw invalid_input(shown_name(o.static_poses) + ": " + std::to_string(static_poses.size()) +
                                " poses of the static polygon for " + std::to_string(in.poses.size()) +
                                " of the moving one: give one per frame");
        if (type.meets_both && (o.witness || o.distance != 0 || o.separation || o.continuous || o.algorithm != "sound"))
            throw std::invalid_argument("--static-poses in --number-type " + o.number_type +
                                        " poses both polygons exactly and answers yes or no only: without "
                                        "--witness, --distance, --separation, --continuous and --algorithm");
        // A rounded type runs its detector on B's pose relative to A, composed in double.
        if (!type.meets_both)
            for (std::size_t k = 0; k < in.poses.size(); ++k) in.poses[k] = relative_pose(static_poses[k], in.poses[k]);
    }
    detector_options options;
    options.distance = o.distance;
    options.witness = o.witness;
    options.shape = o.shape == "band" ? extended_area::band : extended_area::capsule;

    // The paper's detector carries its influence mask from frame to frame:
    // its answers depend on the frames before, so it runs on one thread.
    const unsigned threads = o.algorithm == "paper" ? 1 : batch_threads(o.threads);
    frames_run r;
    if (!static_poses.empty() && type.meets_both) {
        // Both posed exactly, frame by frame.
        r.frames.resize(in.poses.size());
        r.seconds = seconds_taken([&] {
            for (std::size_t k = 0; k < in.poses.size(); ++k)
                r.frames[k].collides = type.meets_both(in.a, static_poses[k], in.b, in.poses[k]);
        });
    } else {
        r = type.run({in.a, in.b, in.poses, options, o.algorithm, threads});
    }

    // Continuous: frame k > 0 also collides when the motion from pose k - 1
    // meets A at some time between the poses.
    std::vector<contact_row> contacts;
    std::size_t between = 0;
    double contact_seconds = 0, separation_seconds = 0;
    if (o.continuous) {
        contact_seconds = seconds_taken([&] { contacts = type.contacts(in.a, in.b, in.poses); });
        for (std::size_t k = 0; k < contacts.size(); ++k)
            if (contacts[k].contact && !r.frames[k + 1].collides) {
                r.frames[k + 1].collides = true;
                ++between;
            }
    }
    std::vector<separation_row> separations;
    if (o.separation) {
        separation_seconds = seconds_taken([&] { separations = type.separations(in.a, in.b, in.poses); });
    }

    std::size_t collisions = 0, first = 0;
    bool any = false;
    for (std::size_t i = 0; i < r.frames.size(); ++i) {
        if (!r.frames[i].collides) continue;
        if (!any) first = i;
        any = true;
        ++collisions;
    }

    if (!o.out.empty())
        write_frames(o.out, r.frames, o.witness,
                     {o.continuous ? &contacts : nullptr, o.separation ? &separations : nullptr, o.witness});

    // With the frames on standard output, the summary goes to standard error.
    std::ostream& summary = is_standard_stream(o.out) ? std::cerr : std::cout;
    const double total_ms = r.seconds * 1e3;
    summary << "frames:          " << r.frames.size() << "\n"
            << "collisions:      " << collisions << "\n"
            << "first collision: " << (any ? "frame " + std::to_string(first) : "none") << "\n"
            << "number type:     " << o.number_type << "\n"
            << "algorithm:       " << o.algorithm << "\n"
            << "threads:         " << threads << "\n"
            << "time per frame:  "
            << (r.frames.empty()
                    ? std::string("n/a")
                    : fixed(r.seconds * 1e6 / static_cast<double>(r.frames.size()), 3) +
                          " us")
            << "   (total " << fixed(total_ms, total_ms >= 1 ? 1 : 3) << " ms)\n";
    if (o.continuous)
        summary << "between poses:   " << between
                << " frames whose motion meets the static polygon only between the poses\n"
                << "time per motion: "
                << (contacts.empty() ? std::string("n/a")
                                     : fixed(contact_seconds * 1e6 / static_cast<double>(contacts.size()), 3) + " us")
                << "\n";
    if (o.separation && !separations.empty()) {
        std::size_t nearest = 0;
        for (std::size_t k = 1; k < separations.size(); ++k)
            if (separations[k].distance < separations[nearest].distance) nearest = k;
        summary << "least separation: " << general(separations[nearest].distance, 17) << " (frame " << nearest
                << ")\n"
                << "time per separation: "
                << fixed(separation_seconds * 1e6 / static_cast<double>(separations.size()), 3) << " us\n";
    }
    if (r.exact_frames) summary << "exact fallbacks: " << *r.exact_frames << " frames\n";
    if (!o.out.empty()) summary << "frames written:  " << shown_name(o.out, true) << "\n";
}

}  // namespace

void register_collide(CLI::App& app) {
    auto o = std::make_shared<collide_options>();
    CLI::App* sub = app.add_subcommand(
        "collide",
        "Run a collision detector between a static polygon and a moving polygon over a "
        "sequence of poses of the moving one (from a CSV file or one of the paper's "
        "trajectories); print a summary and optionally write one line per frame.");

    CLI::Option* trajectory = add_scene_options(sub, o->scene);
    // The old spelling, kept working but left out of the help.
    sub->add_option("--frames", o->deprecated_frames, "Old name of --trajectory-frames")
        ->check(trajectory_frames_range())
        ->needs(trajectory)
        ->group("");
    add_number_type_option(sub, o->number_type);
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
    sub->add_flag("--separation", o->separation,
                  "Also compute the distance between the closed regions at every pose (0 when they "
                  "meet): the column separation of FRAMES.csv and, with --witness, the column closest "
                  "(static feature : moving feature, as v<vertex> or e<edge> in input numbering, or "
                  "interior); the summary gives the least separation. Exact (to the nearest double "
                  "within one unit in the last place) in the exact, certified and interval types");
    sub->add_flag("--continuous", o->continuous,
                  "Treat consecutive poses as motions (translation and angle linear in time): frame k "
                  "also collides when the polygons meet at some time between pose k - 1 and pose k "
                  "(tunneling caught); FRAMES.csv gets the column contact_t, the earliest contact time "
                  "in that motion. With --distance 0 only");
    sub->add_option("--static-poses", o->static_poses,
                    "Poses of the static polygon too, one per frame (the format of POSES.csv): frame k "
                    "asks A posed by its k-th pose against B posed by its own. The exact, certified and "
                    "interval types pose both exactly in the world and answer yes or no; the rounded "
                    "types run their detector on B's pose relative to A composed in double")
        ->type_name("A_POSES.csv");
    sub->add_option("--threads", o->threads,
                    "Threads answering the frames: each runs its own detector over a contiguous "
                    "run of the poses (the answers are those of one detector over all of them); "
                    "0, the default, uses every hardware thread. With several, 'time per frame' "
                    "is the batch's wall time over the frames. --algorithm paper runs on one "
                    "thread (its answers depend on the frames before)")
        ->capture_default_str()
        ->check(CLI::Range(0u, 4096u))
        ->type_name("N");
    sub->add_option("--out", o->out,
                    "Write one CSV line per frame (frame,collides[,edges][,contact_t][,separation[,closest]]) to this file; it is "
                    "replaced only when the whole run succeeds. '-': standard output, and the "
                    "summary goes to standard error")
        ->type_name("FRAMES.csv");

    sub->callback([o] { run_collide(*o); });
}

}  // namespace influence2d::cli
