// SPDX-License-Identifier: BSL-1.0
#pragma once
// The subcommands of the influence2d tool, one source file each, and the
// command line of influence2d-bench.

#include <CLI/CLI.hpp>

namespace influence2d::cli {

/// `influence2d collide`: run a detector over a sequence of poses.
void register_collide(CLI::App& app);
/// `influence2d generate`: write the paper's polygon families as WKT.
void register_generate(CLI::App& app);
/// `influence2d generate-stiff`: write the stiff and extreme scenes as WKT and CSV.
void register_generate_stiff(CLI::App& app);
/// `influence2d study`: every number type's decisions against the exact reference.
void register_study(CLI::App& app);
/// `influence2d audit`: the degeneracies of a polygon file.
void register_audit(CLI::App& app);
/// `influence2d render`: a scene drawn as SVG.
void register_render(CLI::App& app);
/// `influence2d sweep`: the first contact along each motion between poses.
void register_sweep(CLI::App& app);
/// `influence2d world`: many bodies moved step by step, the pairs in contact.
void register_world(CLI::App& app);
/// `influence2d pairs`: the pairs of polygons of one layer, or of two, that meet.
void register_pairs(CLI::App& app);

/// influence2d-bench, the time study against the peers: its options and its
/// run set on `app`, the program's whole command line (bench_main.cpp).
void configure_bench(CLI::App& app);

/// Thrown by a command to end the tool with `code` after its output is done.
struct exit_status {
    int code;
};

}  // namespace influence2d::cli
