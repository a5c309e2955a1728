// SPDX-License-Identifier: BSL-1.0
#pragma once
// The scene of the commands that run a detector over poses (`collide`,
// `render`): the options that name it, and the reading of its files with every
// problem reported at once.

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "files.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/io/csv.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/motion/trajectory.hpp"

namespace influence2d::cli {

/// The files and the trajectory that make a scene.
struct scene_options {
    std::string static_path;
    std::string moving_path;
    std::string poses_path;  ///< empty: the trajectory
    std::string trajectory;  ///< circular or linear
    std::size_t frames = 0;  ///< frames of the trajectory (--trajectory-frames); 0: its default
    double gap = 9.0;
};

/// A scene as read: both polygons and the poses of the moving one.
struct scene_input {
    polygon a, b;
    std::vector<pose> poses;
};

/// A CLI11 check: the value is a finite number >= 0.
inline CLI::Validator finite_non_negative() {
    return CLI::Validator(
        [](std::string& value) -> std::string {
            const char* begin = value.c_str();
            char* end = nullptr;
            const double x = std::strtod(begin, &end);
            if (end == begin || *end != '\0' || !std::isfinite(x) || x < 0)
                return "must be a finite number >= 0, got '" + value + "'";
            return {};
        },
        "FINITE>=0");
}

/// The check of a trajectory's frame count.
inline CLI::Validator trajectory_frames_range() { return CLI::Range(std::size_t{1}, std::size_t{100000000}); }

/// Adds --static, --moving, the group of --poses and --trajectory (exactly
/// one), --trajectory-frames and --gap; returns the --trajectory option.
inline CLI::Option* add_scene_options(CLI::App* sub, scene_options& o) {
    sub->add_option("--static", o.static_path,
                    "WKT file (POLYGON or MULTIPOLYGON) of the static polygon A ('-': standard input)")
        ->required()
        ->type_name("A.wkt");
    sub->add_option("--moving", o.moving_path,
                    "WKT file (POLYGON or MULTIPOLYGON) of the moving polygon B, in its own frame ('-': "
                    "standard input)")
        ->required()
        ->type_name("B.wkt");

    CLI::Option_group* motion =
        sub->add_option_group("Poses", "Where the moving polygon is at each frame (give exactly one)");
    CLI::Option* poses_opt =
        motion
            ->add_option("--poses", o.poses_path,
                         "CSV file with the header tx,ty,theta and one pose per line: B is "
                         "rotated by theta radians about its own origin, then moved by (tx, ty) ('-': "
                         "standard input)")
            ->type_name("POSES.csv");
    CLI::Option* trajectory_opt = motion
                                      ->add_option("--trajectory", o.trajectory,
                                                   "The paper's trajectories: circular (B orbits A close by without "
                                                   "touching, 90000 frames) or linear (B approaches A and ends in "
                                                   "collision, 9000 frames)")
                                      ->check(CLI::IsMember({"circular", "linear"}))
                                      ->type_name("KIND");
    motion->require_option(1);
    poses_opt->excludes(trajectory_opt);

    sub->add_option("--trajectory-frames", o.frames,
                    "Number of frames of the trajectory (only with --trajectory; default 90000 "
                    "for circular, 9000 for linear)")
        ->check(trajectory_frames_range())
        ->needs(trajectory_opt)
        ->type_name("N");
    sub->add_option("--gap", o.gap,
                    "Clearance of the trajectory (only with --trajectory): on the circular one, "
                    "the closest B comes to the circle that bounds A; on the linear one, the "
                    "distance between the bounding circles at the start")
        ->capture_default_str()
        ->check(finite_non_negative())
        ->needs(trajectory_opt)
        ->type_name("G");
    return trajectory_opt;
}

/// Reads both polygons and the poses (or makes the trajectory), each from its
/// file or, for '-', from standard input (one of them at most), and checks
/// that `out` (unless empty) can be written; throws one invalid_input naming
/// every problem of the inputs, one per line.
inline scene_input read_scene(const scene_options& o, const std::string& out) {
    check_one_standard_input({{"--static", o.static_path}, {"--moving", o.moving_path}, {"--poses", o.poses_path}});
    scene_input in;
    std::vector<std::string> errors;
    const auto attempt = [&errors](auto&& read) {
        try {
            read();
        } catch (const invalid_input& e) {
            errors.emplace_back(e.what());
        }
    };
    attempt([&] { in.a = read_wkt_input(o.static_path); });
    attempt([&] { in.b = read_wkt_input(o.moving_path); });
    if (!o.poses_path.empty()) attempt([&] { in.poses = read_poses_input(o.poses_path); });
    if (!out.empty()) {
        const std::string why = check_output_path(out);
        if (!why.empty()) errors.push_back(why);
    }
    if (!errors.empty()) {
        std::string all = errors.front();
        for (std::size_t i = 1; i < errors.size(); ++i) all += "\n" + errors[i];
        throw invalid_input(all);
    }
    if (o.poses_path.empty()) {
        const bool circular = o.trajectory == "circular";
        const std::size_t frames = o.frames != 0 ? o.frames : circular ? 90000 : 9000;
        in.poses =
            circular ? circular_trajectory(in.a, in.b, frames, o.gap) : linear_trajectory(in.a, in.b, frames, o.gap);
    }
    return in;
}

}  // namespace influence2d::cli
