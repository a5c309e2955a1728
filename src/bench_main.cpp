// SPDX-License-Identifier: BSL-1.0
// The influence2d-bench program: the paper's time study against the peer
// libraries (bench.cpp). A program of its own because one peer, CGAL's
// Boolean_set_operations_2, is GPL: the influence2d tool links no peer.
//
// Exit codes: 0 success (or --help), 2 bad usage or a file that cannot be
// written; messages go to stderr as `influence2d-bench: error: ...`.

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "tool.hpp"

int main(int argc, char** argv) {
    CLI::App app{"", "influence2d-bench"};
    influence2d::cli::configure_bench(app);
    return influence2d::cli::run_tool(app, argc, argv);
}
