// SPDX-License-Identifier: BSL-1.0
#pragma once
// Running the influence2d tool (or influence2d-bench) as a separate process on files in a temporary directory.

#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace test_process {

namespace fs = std::filesystem;

inline const std::string cli_path = INFLUENCE2D_CLI_PATH;
/// influence2d-bench, the time study's program.
inline const std::string bench_path = INFLUENCE2D_BENCH_PATH;
/// influence2d-world-bench, the world's time study's program.
inline const std::string world_bench_path = INFLUENCE2D_WORLD_BENCH_PATH;

inline std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

inline std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

/// A fresh directory under the system's temporary directory, removed at the end.
class temp_dir {
public:
    temp_dir() {
        static std::atomic<int> counter{0};
        const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        path_ =
            fs::temp_directory_path() / ("influence2d_cli_" + std::to_string(stamp) + "_" + std::to_string(counter++));
        fs::create_directories(path_);
    }
    ~temp_dir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    temp_dir(const temp_dir&) = delete;
    temp_dir& operator=(const temp_dir&) = delete;

    fs::path file(const std::string& name, const std::string& content) const {
        const fs::path p = path_ / name;
        std::ofstream(p, std::ios::binary) << content;
        return p;
    }
    fs::path operator/(const std::string& name) const { return path_ / name; }

private:
    fs::path path_;
};

struct run_result {
    int exit_code = -1;
    std::string out;
    std::string err;
};

/// Runs `program` with `args` (already quoted), capturing stdout and stderr.
inline run_result run_program(const std::string& program, const temp_dir& dir, const std::string& args) {
    REQUIRE(!program.empty());
    const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    const std::string command = quote(program) + " " + args + " >" + quote(out.string()) + " 2>" + quote(err.string());
    const int status = std::system(command.c_str());
    run_result r;
    REQUIRE(status != -1);
    REQUIRE(WIFEXITED(status));
    r.exit_code = WEXITSTATUS(status);
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

/// Runs the tool with `args` (already quoted), capturing stdout and stderr.
inline run_result run_cli(const temp_dir& dir, const std::string& args) { return run_program(cli_path, dir, args); }

/// Runs influence2d-bench with `args` (already quoted), capturing stdout and stderr.
inline run_result run_bench(const temp_dir& dir, const std::string& args) { return run_program(bench_path, dir, args); }

/// Runs influence2d-world-bench with `args` (already quoted), capturing stdout and stderr.
inline run_result run_world_bench(const temp_dir& dir, const std::string& args) {
    return run_program(world_bench_path, dir, args);
}

}  // namespace test_process
