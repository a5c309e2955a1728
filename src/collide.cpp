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
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/io/csv.hpp"
#include "influence2d/query/batch.hpp"
#include "influence2d/query/both_posed.hpp"
#include "number_types.hpp"
#include "query_rows.hpp"
#include "report.hpp"
#include "scene_input.hpp"

namespace influence2d::cli {

namespace {

struct collide_options {
    scene_options scene;
    std::string number_type = default_number_type;
    std::string algorithm = "sound";
    std::string shape = "capsule";
    double distance = 0.0;
    bool witness = false;
    bool separation = false;   ///< add the separation at every pose
    bool continuous = false;   ///< a frame collides when the motion into it meets A
    sweep_options motion;      ///< how the motions of --continuous turn
    std::string static_poses;  ///< the static polygon's poses too, one per frame (empty: A unmoved)
    unsigned threads = 0;      ///< 0: every hardware thread
    std::string out;
    /// The old spelling of --trajectory-frames, still taken with a warning.
    std::size_t deprecated_frames = 0;
};

/// What a frame adds to FRAMES.csv beyond collides and the edges: the
/// continuous contact time (--continuous), the separation and the closest
/// features (--separation, the features with --witness).
struct frame_extras {
    const std::vector<contact_row>* contacts = nullptr;        ///< motion k - 1 into frame k
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
        if (contacts) {
            const contact_row* c = f > 0 ? &(*contacts)[f - 1] : nullptr;
            put(c && c->contact ? general(c->t, 17) : c && c->step_limit ? std::string("limit") : std::string());
        }
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

/// Checks the options against each other and the number type (before any
/// input is read); turns the old --frames into --trajectory-frames.
void check_options(collide_options& o, const number_type& type) {
    if (o.deprecated_frames != 0) {
        if (o.scene.frames != 0)
            throw std::invalid_argument("--frames is the old name of --trajectory-frames: give only one of them");
        std::cerr << "influence2d: warning: --frames is the old name of --trajectory-frames; use that\n";
        o.scene.frames = o.deprecated_frames;
    }
    if (o.algorithm == "paper" && type.exact_fallback)
        throw std::invalid_argument("--number-type " + o.number_type +
                                    " cannot run --algorithm paper: the paper's detector keeps "
                                    "its influence mask from frame to frame, which a frame "
                                    "answered again in exact arithmetic cannot hand back; use "
                                    "--algorithm sound or brute-force, or another number type");
    if (o.continuous && o.distance != 0)
        throw std::invalid_argument(
            "--continuous asks whether the polygons meet between poses: it takes "
            "--distance 0 only (got " +
            general(o.distance, 17) + ")");
    if ((o.continuous || o.separation) && o.algorithm == "paper")
        throw std::invalid_argument(std::string(o.continuous ? "--continuous" : "--separation") +
                                    " is answered by the sound queries only, not --algorithm paper");
}

/// What collide reads: the scene, and the static polygon's poses when given
/// (empty otherwise).
struct collide_inputs {
    scene_input scene;
    std::vector<pose> static_poses;
};

/// Reads every input and checks the output path first, reporting all their
/// problems at once; then the static poses, one per frame, and the options
/// they allow in `type`. A rounded type's poses of B become its poses
/// relative to A, composed in double.
collide_inputs read_inputs(const collide_options& o, const number_type& type) {
    check_one_standard_input({{"--static", o.scene.static_path},
                              {"--moving", o.scene.moving_path},
                              {"--poses", o.scene.poses_path},
                              {"--static-poses", o.static_poses}});
    collide_inputs in{read_scene(o.scene, o.out), {}};
    if (!o.static_poses.empty()) {
        in.static_poses = read_poses_input(o.static_poses);
        if (in.static_poses.size() != in.scene.poses.size())
            throw invalid_input(shown_name(o.static_poses) + ": " + std::to_string(in.static_poses.size()) +
                                " poses of the static polygon for " + std::to_string(in.scene.poses.size()) +
                                " of the moving one: give one per frame");
        if (type.meets_both && (o.witness || o.distance != 0 || o.separation || o.continuous || o.algorithm != "sound"))
            throw std::invalid_argument("--static-poses in --number-type " + o.number_type +
                                        " poses both polygons exactly and answers yes or no only: without "
                                        "--witness, --distance, --separation, --continuous and --algorithm");
        // A rounded type runs its detector on B's pose relative to A, composed in double.
        if (!type.meets_both)
            for (std::size_t k = 0; k < in.scene.poses.size(); ++k)
                in.scene.poses[k] = relative_pose(in.static_poses[k], in.scene.poses[k]);
    }
    return in;
}

/// What a run of collide found: the frames, the motions between them
/// (--continuous), the separations (--separation), and their times.
struct collide_run {
    frames_run frames;
    unsigned threads = 1;
    std::vector<contact_row> contacts;
    std::size_t between = 0;  ///< frames that collide only between the poses
    double contact_seconds = 0;
    std::vector<separation_row> separations;
    double separation_seconds = 0;
};

/// Runs the detector over the frames, then the motions between them and the
/// separations when asked.
collide_run run_queries(const collide_options& o, const number_type& type, const collide_inputs& inputs) {
    const scene_input& in = inputs.scene;
    const std::vector<pose>& static_poses = inputs.static_poses;
    detector_options options;
    options.distance = o.distance;
    options.witness = o.witness;
    options.shape = o.shape == "band" ? extended_area::band : extended_area::capsule;

    collide_run out;
    // The paper's detector carries its influence mask from frame to frame:
    // its answers depend on the frames before, so it runs on one thread.
    out.threads = o.algorithm == "paper" ? 1 : batch_threads(o.threads);
    frames_run& r = out.frames;
    if (!static_poses.empty() && type.meets_both) {
        // Both posed exactly, frame by frame.
        r.frames.resize(in.poses.size());
        r.seconds = seconds_taken([&] {
            for (std::size_t k = 0; k < in.poses.size(); ++k)
                r.frames[k].collides = type.meets_both(in.a, static_poses[k], in.b, in.poses[k]);
        });
    } else {
        r = type.run({in.a, in.b, in.poses, options, o.algorithm, out.threads});
    }

    // Continuous: frame k > 0 also collides when the motion from pose k - 1
    // meets A at some time between the poses.
    if (o.continuous) {
        out.contact_seconds = seconds_taken([&] { out.contacts = type.contacts(in.a, in.b, in.poses, o.motion); });
        for (std::size_t k = 0; k < out.contacts.size(); ++k)
            if (out.contacts[k].contact && !r.frames[k + 1].collides) {
                r.frames[k + 1].collides = true;
                ++out.between;
            }
    }
    if (o.separation) {
        out.separation_seconds = seconds_taken([&] { out.separations = type.separations(in.a, in.b, in.poses); });
    }
    return out;
}

/// Writes the frames (--out) and the summary: to standard output, or to
/// standard error when the frames go to standard output.
void report_results(const collide_options& o, const collide_run& result) {
    const frames_run& r = result.frames;
    std::size_t collisions = 0, first = 0;
    bool any = false;
    for (std::size_t i = 0; i < r.frames.size(); ++i) {
        if (!r.frames[i].collides) continue;
        if (!any) first = i;
        any = true;
        ++collisions;
    }

    if (!o.out.empty())
        write_frames(
            o.out, r.frames, o.witness,
            {o.continuous ? &result.contacts : nullptr, o.separation ? &result.separations : nullptr, o.witness});

    // With the frames on standard output, the summary goes to standard error.
    std::ostream& summary = is_standard_stream(o.out) ? std::cerr : std::cout;
    const double total_ms = r.seconds * 1e3;
    summary << "frames:          " << r.frames.size() << "\n"
            << "collisions:      " << collisions << "\n"
            << "first collision: " << (any ? "frame " + std::to_string(first) : "none") << "\n"
            << "number type:     " << o.number_type << "\n"
            << "algorithm:       " << o.algorithm << "\n"
            << "threads:         " << result.threads << "\n"
            << "time per frame:  "
            << (r.frames.empty() ? std::string("n/a")
                                 : fixed(r.seconds * 1e6 / static_cast<double>(r.frames.size()), 3) + " us")
            << "   (total " << fixed(total_ms, total_ms >= 1 ? 1 : 3) << " ms)\n";
    summary << step_limit_line(result.contacts, o.motion.max_steps, "contact_t");
    if (o.continuous)
        summary << "between poses:   " << result.between
                << " frames whose motion meets the static polygon only between the poses\n"
                << "time per motion: "
                << (result.contacts.empty()
                        ? std::string("n/a")
                        : fixed(result.contact_seconds * 1e6 / static_cast<double>(result.contacts.size()), 3) + " us")
                << "\n";
    const std::vector<separation_row>& separations = result.separations;
    if (o.separation && !separations.empty()) {
        std::size_t nearest = 0;
        for (std::size_t k = 1; k < separations.size(); ++k)
            if (separations[k].distance < separations[nearest].distance) nearest = k;
        summary << "least separation: " << general(separations[nearest].distance, 17) << " (frame " << nearest << ")\n"
                << "time per separation: "
                << fixed(result.separation_seconds * 1e6 / static_cast<double>(separations.size()), 3) << " us\n";
    }
    if (r.exact_frames) summary << "exact fallbacks: " << *r.exact_frames << " frames\n";
    if (!o.out.empty()) summary << "frames written:  " << shown_name(o.out, true) << "\n";
}

/// `influence2d collide`: check the options, read the inputs, run, report.
void run_collide(collide_options o) {
    const number_type& type = *find_number_type(o.number_type);  // the option's check has run
    check_options(o, type);
    const collide_inputs inputs = read_inputs(o, type);
    report_results(o, run_queries(o, type, inputs));
}

}  // namespace

void register_collide(CLI::App& app) {
    auto o = std::make_shared<collide_options>();
    CLI::App* sub = app.add_subcommand("collide",
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
    CLI::Option* continuous =
        sub->add_flag("--continuous", o->continuous,
                      "Treat consecutive poses as motions (translation and angle linear in time): frame k "
                      "also collides when the polygons meet at some time between pose k - 1 and pose k "
                      "(tunneling caught); FRAMES.csv gets the column contact_t, the earliest contact time "
                      "in that motion ('limit' for a motion left undecided at --max-steps). With --distance 0 "
                      "only");
    add_motion_options(sub, o->motion)->needs(continuous);
    sub->get_option("--max-steps")->needs(continuous);
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
                    "Write one CSV line per frame (frame,collides[,edges][,contact_t][,separation[,closest]]) to this "
                    "file; it is "
                    "replaced only when the whole run succeeds. '-': standard output, and the "
                    "summary goes to standard error")
        ->type_name("FRAMES.csv");

    sub->callback([o] { run_collide(*o); });
}

}  // namespace influence2d::cli
