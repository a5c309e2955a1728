// SPDX-License-Identifier: BSL-1.0
#pragma once
// Pieces shared by the reporting commands (study, bench): number formatting,
// name-list checks and gnuplot.

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "files.hpp"
#include "verification/report_text.hpp"

namespace influence2d::cli {

/// The wall-clock seconds f() takes (steady clock).
template <class F>
double seconds_taken(F&& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The number formats and name lists of the reports, shared with verification/.
using verification::fixed;
using verification::general;
using verification::joined;

/// Throws, naming the known ones, when a name of `given` is not in `known`.
inline void check_names(const std::vector<std::string>& given, const std::vector<std::string>& known,
                        const std::string& what) {
    for (const std::string& g : given) {
        bool found = false;
        for (const std::string& k : known) found = found || k == g;
        if (!found)
            throw std::invalid_argument("--" + what + ": unknown name '" + g + "' (known: " + joined(known) + ")");
    }
}

/// A progress reporter on stderr: report(line, done, milestone) rewrites one
/// line in place on a terminal; elsewhere, when `forced`, it prints the
/// milestones and the end. Empty (no reporting) when neither.
inline std::function<void(const std::string&, bool, bool)> progress_reporter(bool forced) {
    const bool terminal = isatty(fileno(stderr)) != 0;
    if (!terminal && !forced) return {};
    return [terminal](const std::string& line, bool done, bool milestone) {
        if (terminal)
            std::cerr << "\r" << line << "\x1b[K" << (done ? "\n" : "") << std::flush;
        else if (done || milestone)
            std::cerr << line << "\n";
    };
}

/// Writes `script` to `path` and runs gnuplot on it; says so on stderr (as
/// `who`) when gnuplot is missing or fails: the tables are written anyway.
inline void plot_with_gnuplot(const std::filesystem::path& path, const std::string& script, const std::string& who) {
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
        std::cerr << who << ": gnuplot not found (Debian package gnuplot-nox): wrote the tables, no plots\n";
        return;
    }
    write_atomically(path, script);
    const std::string command = "gnuplot '" + path.string() + "' 2>&1";
    if (std::system(command.c_str()) != 0) std::cerr << who << ": gnuplot failed on " << path.string() << "\n";
}

}  // namespace influence2d::cli
