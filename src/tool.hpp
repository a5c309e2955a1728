// SPDX-License-Identifier: BSL-1.0
#pragma once
// What the two programs (influence2d and influence2d-bench) share around
// their commands: parsing the command line and turning its outcome into an
// exit code and messages.

#include <CLI/CLI.hpp>

namespace influence2d::cli {

/// Parses argc/argv into `app` (whose commands run from their callbacks) and
/// returns the program's exit code: 0 on success and for --help and
/// --version; a command's exit_status; 2 for bad usage, bad input or a file
/// that cannot be read or written, each line of the message on stderr as
/// `NAME: error: ...`, NAME the app's name.
int run_tool(CLI::App& app, int argc, char** argv);

}  // namespace influence2d::cli
