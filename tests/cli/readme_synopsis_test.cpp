// SPDX-License-Identifier: BSL-1.0
// The README's synopsis of the tool (section "The command-line tool", and
// render's in "Pictures") against the tool's own help: the same subcommands,
// the same options for each, and the same number types, in the same order.

#include <catch2/catch.hpp>

#include "support/process.hpp"

#include <cctype>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

using namespace test_process;

namespace {

const fs::path readme_path = fs::path(INFLUENCE2D_DATA_DIR).parent_path() / "README.md";

/// The text of the README's section `title` (a "## " heading), up to the next one.
std::string section(const std::string& readme, const std::string& title) {
    const std::string heading = "\n## " + title + "\n";
    const std::size_t start = readme.find(heading);
    REQUIRE(start != std::string::npos);
    const std::size_t end = readme.find("\n## ", start + heading.size());
    return readme.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

/// The first fenced code block of `text`.
std::string first_block(const std::string& text) {
    const std::size_t open = text.find("```\n");
    REQUIRE(open != std::string::npos);
    const std::size_t close = text.find("```", open + 4);
    REQUIRE(close != std::string::npos);
    return text.substr(open + 4, close - open - 4);
}

/// The synopsis entries of a code block: an entry starts with a line
/// "influence2d WORD" and goes on over the indented lines after it; the text
/// is added to the entry of WORD (the subcommand, or --version).
void add_entries(const std::string& block, std::map<std::string, std::string>& entries) {
    std::string current;
    for (const std::string& line : lines_of(block)) {
        if (line.rfind("influence2d ", 0) == 0) {
            const std::size_t end = line.find(' ', 12);
            current = line.substr(12, end == std::string::npos ? std::string::npos : end - 12);
            entries[current] += line.substr(12 + current.size()) + "\n";
        } else if (!line.empty() && line[0] == ' ' && !current.empty()) {
            entries[current] += line + "\n";
        } else {
            current.clear();
        }
    }
}

/// The options (--name) a synopsis entry mentions.
std::set<std::string> options_in(const std::string& text) {
    static const std::regex option(R"(--[a-z][a-z0-9-]*)");
    std::set<std::string> found;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), option); it != std::sregex_iterator(); ++it)
        found.insert(it->str());
    return found;
}

/// The options a --help output lists (the first word of each option line),
/// --help itself left out.
std::set<std::string> options_of_help(const std::string& help) {
    std::set<std::string> found;
    for (const std::string& line : lines_of(help)) {
        const std::size_t first = line.find_first_not_of(' ');
        if (first == std::string::npos || first == 0 || line[first] != '-') continue;
        std::string names = line.substr(first, line.find(' ', first) - first);
        for (std::size_t start = 0; start < names.size();) {
            const std::size_t comma = names.find(',', start);
            const std::string name =
                names.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            if (name.rfind("--", 0) == 0 && name != "--help") found.insert(name);
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    }
    return found;
}

/// The subcommands the top-level --help lists.
std::set<std::string> subcommands_of_help(const std::string& help) {
    std::set<std::string> found;
    bool in_list = false;
    for (const std::string& line : lines_of(help)) {
        if (line == "Subcommands:") {
            in_list = true;
            continue;
        }
        if (!in_list) continue;
        if (line.empty() || line[0] != ' ') break;
        const std::size_t first = line.find_first_not_of(' ');
        found.insert(line.substr(first, line.find(' ', first) - first));
    }
    return found;
}

std::vector<std::string> split(const std::string& s, char by) {
    std::vector<std::string> parts;
    for (std::size_t start = 0;;) {
        const std::size_t at = s.find(by, start);
        parts.push_back(s.substr(start, at == std::string::npos ? std::string::npos : at - start));
        if (at == std::string::npos) return parts;
        start = at + 1;
    }
}

}  // namespace

TEST_CASE("cli readme: the tool's synopsis names every subcommand and option the tool has, and no other", "[cli]") {
    const std::string readme = slurp(readme_path);
    REQUIRE(!readme.empty());
    std::map<std::string, std::string> entries;
    add_entries(first_block(section(readme, "The command-line tool")), entries);
    add_entries(first_block(section(readme, "Pictures")), entries);  // render's full synopsis

    const temp_dir dir;
    const auto top = run_cli(dir, "--help");
    REQUIRE(top.exit_code == 0);
    std::set<std::string> documented;
    for (const auto& [word, text] : entries)
        if (word.rfind("--", 0) != 0) documented.insert(word);
    CHECK(documented == subcommands_of_help(top.out));
    std::set<std::string> top_options;
    for (const auto& [word, text] : entries)
        if (word.rfind("--", 0) == 0) top_options.insert(word);
    CHECK(top_options == options_of_help(top.out));

    for (const std::string& sub : subcommands_of_help(top.out)) {
        INFO("influence2d " << sub);
        const auto help = run_cli(dir, sub + " --help");
        REQUIRE(help.exit_code == 0);
        CHECK(options_in(entries[sub]) == options_of_help(help.out));
    }
}

TEST_CASE("cli readme: the synopsis lists the number types of --number-type, in the tool's order", "[cli]") {
    const std::string block = first_block(section(slurp(readme_path), "The command-line tool"));
    std::smatch m;
    REQUIRE(std::regex_search(block, m, std::regex(R"(--number-type ([a-z0-9|-]+))")));
    const std::vector<std::string> documented = split(m[1].str(), '|');

    const temp_dir dir;
    const auto help = run_cli(dir, "collide --help");
    REQUIRE(help.exit_code == 0);
    std::smatch h;
    REQUIRE(std::regex_search(help.out, h, std::regex(R"(--number-type TYPE:\{([a-z0-9,-]+)\})")));
    CHECK(documented == split(h[1].str(), ','));
}
