// SPDX-License-Identifier: BSL-1.0
#pragma once
// The number types the tool runs a detector in (--number-type): one table,
// `number_types` below, gives each its name, the words of the help, whether
// its answers are exact, whether it answers frames in doubt again in exact
// rationals, and how a detector runs in it. The option's accepted names, its
// help text and the dispatch all come from that table: a new type is one line
// there (number_types.cpp).

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/motion/motion.hpp"
#include "query_rows.hpp"

namespace influence2d::cli {

/// What a detector is asked to do: the scene, the options, the algorithm
/// (sound, paper or brute-force) and the threads (1: one detector answers
/// every pose in order; more: collide_batch, one detector per thread on a
/// contiguous run of the poses).
struct detector_job {
    const polygon& a;
    const polygon& b;
    const std::vector<pose>& poses;
    detector_options options;
    std::string algorithm;
    unsigned threads = 1;
};

/// A detector's answers over the poses, and the time of the frame loop alone.
struct frames_run {
    std::vector<frame_result> frames;
    double seconds = 0;
    /// Types with an exact fallback: frames answered again in exact rationals.
    std::optional<std::size_t> exact_frames;
};

/// One number type of the tool.
struct number_type {
    const char* name;         ///< as --number-type takes it
    const char* description;  ///< for the help
    /// Whether every answer is the exact one (else rounded: it may differ
    /// near contact).
    bool claims_exact;
    /// Whether a frame in doubt is answered again in exact rationals. The
    /// paper's detector cannot take such a type: its influence mask carries
    /// over from frame to frame, and a frame redone in exact rationals would
    /// not see the mask the fast detector built (nor leave it one).
    bool exact_fallback;
    /// Runs the detector of an algorithm in this type over the poses.
    frames_run (*run)(const detector_job&);
    /// The separation at every pose (`collide --separation`).
    std::vector<separation_row> (*separations)(const polygon&, const polygon&, const std::vector<pose>&);
    /// The first contact of the motion between each two consecutive poses
    /// (`sweep`, `collide --continuous`).
    std::vector<contact_row> (*contacts)(const polygon&, const polygon&, const std::vector<pose>&,
                                         const sweep_options&);
    /// Whether A and B, each posed in the world, meet, both posed exactly
    /// (`collide --static-poses`); nullptr for a rounded type, which runs
    /// its detector on B's pose relative to A composed in double.
    bool (*meets_both)(const polygon&, const pose&, const polygon&, const pose&);
};

/// Every number type, in the order the help lists them. Defined in
/// number_types.cpp, which holds every type's instantiations: they are
/// compiled there once, not again in each command that names the types.
inline constexpr std::size_t number_type_count = 7;
extern const number_type number_types[number_type_count];

/// The type --number-type takes when not given.
inline constexpr const char* default_number_type = "double";

/// The type named `name`, or nullptr.
inline const number_type* find_number_type(std::string_view name) {
    for (const number_type& t : number_types)
        if (name == t.name) return &t;
    return nullptr;
}

/// The names, in table order.
inline std::vector<std::string> number_type_names() {
    std::vector<std::string> names;
    for (const number_type& t : number_types) names.emplace_back(t.name);
    return names;
}

/// The help of --number-type: every type with its answers and description.
inline std::string number_type_help() {
    std::string help = "Arithmetic of the detector's decisions. ";
    std::vector<std::string> fallback;
    for (const number_type& t : number_types) {
        help += std::string(t.name) + (t.claims_exact ? " (exact answers): " : " (rounded answers): ") + t.description +
                "; ";
        if (t.exact_fallback) fallback.emplace_back(t.name);
    }
    help.replace(help.size() - 2, 2, ".");
    for (std::size_t i = 0; i < fallback.size(); ++i)
        help += (i == 0 ? " " : i + 1 == fallback.size() ? " and " : ", ") + fallback[i];
    if (!fallback.empty()) help += " (exact fallback) run with --algorithm sound or brute-force only";
    return help;
}

/// Adds --number-type to `sub`, storing the name in `value` (which starts
/// as default_number_type): the names, the check and the help from the table.
inline CLI::Option* add_number_type_option(CLI::App* sub, std::string& value) {
    value = default_number_type;
    return sub->add_option("--number-type", value, number_type_help())
        ->capture_default_str()
        ->check(CLI::IsMember(number_type_names()))
        ->type_name("TYPE");
}

/// The options --motion (how a motion that turns moves, docs/sweep.md:
/// angle-linear, the default, or rational) and --max-steps (the
/// angle-linear model's step limit); the first returned.
inline CLI::Option* add_motion_options(CLI::App* sub, sweep_options& value) {
    const std::map<std::string, turning_model> models{{"angle-linear", turning_model::angle_linear},
                                                      {"rational", turning_model::rational}};
    sub->add_option("--max-steps", value.max_steps,
                    "Steps of conservative advancement (angle-linear motions that turn) before a motion is "
                    "reported undecided (contact 'limit', t where it stopped: no contact before), 0 for no "
                    "limit")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t{0}, std::size_t{1} << 40))
        ->type_name("N");
    return sub
        ->add_option("--motion", value.model,
                     "How a motion that turns moves: angle-linear (the angle linear in time; contact within "
                     "1e-9 by conservative advancement) or rational (the tangent of half the turn linear in "
                     "time, in pieces of at most a quarter turn; contact exact in the exact and certified types, "
                     "see docs/sweep.md). Translations are the same in both")
        ->transform(CLI::CheckedTransformer(models, CLI::ignore_case))
        ->type_name("MODEL")
        ->default_str("angle-linear");
}

}  // namespace influence2d::cli
