// SPDX-License-Identifier: BSL-1.0
// The influence2d command-line tool.
//
// Exit codes: 0 success (or --help), 1 `audit`: the library refuses the
// polygon (the findings say why), 2 bad usage, bad input or a file that cannot
// be read or written; messages go to stderr as `influence2d: error: ...`.

#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "influence2d/version.hpp"

namespace {

/// Prints every line of `message` with the tool's error prefix.
void print_error(const std::string& message) {
    std::size_t start = 0;
    for (;;) {
        const std::size_t end = message.find('\n', start);
        std::cerr << "influence2d: error: " << message.substr(start, end - start) << '\n';
        if (end == std::string::npos) break;
        start = end + 1;
    }
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
    influence2d::cli::register_bench(app);
    influence2d::cli::register_audit(app);
    influence2d::cli::register_render(app);
    influence2d::cli::register_sweep(app);

    try {
        app.parse(argc, argv);
    } catch (const influence2d::cli::exit_status& e) {
        return e.code;
    } catch (const CLI::ParseError& e) {
        // --help and --version are "errors" with exit code 0.
        return app.exit(e) == 0 ? 0 : 2;
    } catch (const std::exception& e) {
        print_error(e.what());
        return 2;
    }
    return 0;
}
