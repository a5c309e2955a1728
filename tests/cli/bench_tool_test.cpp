// SPDX-License-Identifier: BSL-1.0
// influence2d-bench, the time study's program: a small run writes its files;
// its options are the README's synopsis; `influence2d bench`, its former
// name, names it and fails.

#include <catch2/catch.hpp>

#include "support/process.hpp"

#include <regex>
#include <set>
#include <string>

using namespace test_process;

namespace {

/// The options (--name) that `text` mentions, --help left out.
std::set<std::string> bench_options_in(const std::string& text) {
    static const std::regex option(R"(--[a-z][a-z0-9-]*)");
    std::set<std::string> found;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), option); it != std::sregex_iterator(); ++it)
        if (it->str() != "--help") found.insert(it->str());
    return found;
}

}  // namespace

TEST_CASE("cli bench: influence2d-bench runs the time study and writes its tables", "[cli][bench_program]") {
    const temp_dir dir;
    const auto r = run_bench(dir,
                             "--types convex --sizes 8 --trajectories linear --methods double "
                             "--linear-frames 16 --budget 0.001 --out " +
                                 quote((dir / "out").string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    // The targets on standard output (gnuplot, when it runs, may write there too).
    CHECK(r.out.find("## Targets") != std::string::npos);
    CHECK(fs::exists(dir / "out" / "bench.csv"));
    const std::string md = slurp(dir / "out" / "bench.md");
    CHECK(md.find("Command: `influence2d-bench --types convex") != std::string::npos);
    CHECK(slurp(dir / "out" / "bench.csv").find("convex,linear,8,8,double,16,") != std::string::npos);
}

TEST_CASE("cli bench: bad options are refused with the program's name and exit code 2", "[cli][bench_program]") {
    const temp_dir dir;
    const auto r = run_bench(dir, "--types nope --out " + quote((dir / "out").string()));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("influence2d-bench: error: --types: unknown name 'nope'") == 0);
}

TEST_CASE("cli bench: the README's synopsis of influence2d-bench names the options it has", "[cli][bench_program]") {
    const std::string readme = slurp(fs::path(INFLUENCE2D_DATA_DIR).parent_path() / "README.md");
    // The synopsis entry: the line "influence2d-bench ..." and the indented lines after it.
    std::string entry;
    bool in_entry = false;
    for (const std::string& line : lines_of(readme)) {
        if (line.rfind("influence2d-bench ", 0) == 0 && entry.empty())
            in_entry = true;
        else if (in_entry && (line.empty() || line[0] != ' '))
            break;
        if (in_entry) entry += line + "\n";
    }
    REQUIRE(!entry.empty());
    const temp_dir dir;
    const auto help = run_bench(dir, "--help");
    REQUIRE(help.exit_code == 0);
    // The options of --help: the first word of each option line.
    std::set<std::string> listed;
    for (const std::string& line : lines_of(help.out)) {
        const std::size_t first = line.find_first_not_of(' ');
        if (first == std::string::npos || first == 0 || line.compare(first, 2, "--") != 0) continue;
        const std::string name = line.substr(first, line.find_first_of(" ,", first) - first);
        if (name != "--help") listed.insert(name);
    }
    CHECK(bench_options_in(entry) == listed);
}

TEST_CASE("cli bench: influence2d bench names influence2d-bench and fails", "[cli]") {
    const temp_dir dir;
    for (const std::string args : {"bench", "bench --quick --out x", "bench --help"}) {
        INFO(args);
        const auto r = run_cli(dir, args);
        CHECK(r.exit_code == 2);
        CHECK(r.out.empty());
        CHECK(r.err.find("influence2d: error: bench: the time study is the program influence2d-bench now") == 0);
    }
    // And the help does not list it.
    const auto help = run_cli(dir, "--help");
    REQUIRE(help.exit_code == 0);
    CHECK_FALSE(std::regex_search(help.out, std::regex(R"(\n +bench )")));
}
