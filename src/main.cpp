// SPDX-License-Identifier: BSL-1.0
// The influence2d command-line tool.
//
// Exit codes: 0 success (or --help), 1 `audit`: the library refuses the
// polygon (the findings say why), 2 bad usage, bad input or a file that cannot
// be read or written; messages go to stderr as `influence2d: error: ...`.
//
// The time study, once `influence2d bench`, is the program influence2d-bench
// (bench_main.cpp): it links the peer libraries, one of them GPL, which this
// tool does not. `influence2d bench` is kept, out of the help, to say so.

#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "influence2d/version.hpp"
#include "tool.hpp"

namespace {

/// `influence2d bench`: not listed in the help; whatever its arguments, it
/// names the program the time study moved to and fails (exit code 2).
void register_moved_bench(CLI::App& app) {
    CLI::App* sub = app.add_subcommand("bench", "The time study: moved to the program influence2d-bench");
    sub->group("");
    sub->allow_extras();
    sub->set_help_flag();
    sub->callback([] {
        throw std::invalid_argument(
            "bench: the time study is the program influence2d-bench now (built beside influence2d; CMake target "
            "influence2d_bench_cli): run `influence2d-bench` with the same options, `influence2d-bench --help` "
            "lists them");
    });
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Collision detection between 2D polygons with triangle coverings and influence areas "
        "(Jimenez, Segura and Feito, WSCG 2004).",
        "influence2d"};
    app.set_version_flag("--version", std::string("influence2d ") + influence2d::version);
    app.require_subcommand(1);
    influence2d::cli::register_collide(app);
    influence2d::cli::register_generate(app);
    influence2d::cli::register_generate_stiff(app);
    influence2d::cli::register_study(app);
    influence2d::cli::register_audit(app);
    influence2d::cli::register_render(app);
    influence2d::cli::register_sweep(app);
    influence2d::cli::register_world(app);
    influence2d::cli::register_pairs(app);
    register_moved_bench(app);
    return influence2d::cli::run_tool(app, argc, argv);
}
