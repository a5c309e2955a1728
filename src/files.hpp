// SPDX-License-Identifier: BSL-1.0
#pragma once
// The tool's files: output written so that a reader never sees a half-written
// file, and '-' for standard input or standard output wherever the tool reads
// or writes one file.

#include <array>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "influence2d/core/invalid_input.hpp"
#include "influence2d/io/csv.hpp"
#include "influence2d/io/wkt.hpp"

namespace influence2d::cli {

/// The file name that stands for standard input (as an input) or standard
/// output (as an output).
inline const std::string standard_stream = "-";

inline bool is_standard_stream(const std::string& path) { return path == standard_stream; }

/// The name messages and reports give a file: '-' is "standard input" or
/// "standard output".
inline std::string shown_name(const std::string& path, bool output = false) {
    if (!is_standard_stream(path)) return path;
    return output ? "standard output" : "standard input";
}

/// Refuses, naming the options, when more than one of the inputs (option,
/// path) is '-': standard input can be read once.
inline void check_one_standard_input(const std::vector<std::pair<std::string, std::string>>& inputs) {
    std::vector<std::string> from_stdin;
    for (const auto& [option, path] : inputs)
        if (is_standard_stream(path)) from_stdin.push_back(option);
    if (from_stdin.size() < 2) return;
    std::string names;
    for (std::size_t i = 0; i < from_stdin.size(); ++i)
        names += (i == 0 ? "" : i + 1 == from_stdin.size() ? " and " : ", ") + from_stdin[i];
    throw std::invalid_argument(names + (from_stdin.size() == 2 ? " both" : " all") +
                                " name '-', standard input, which can be read only once: give at most one of "
                                "them as '-' and the others as files");
}

/// The whole of standard input as bytes; more than `max_bytes` is refused.
/// Messages start with "standard input".
inline std::string read_standard_input(std::size_t max_bytes) {
    std::string text;
    std::array<char, 1 << 16> buf{};
    while (std::cin) {
        std::cin.read(buf.data(), static_cast<std::streamsize>(buf.size()));
        const auto got = static_cast<std::size_t>(std::cin.gcount());
        if (text.size() + got > max_bytes)
            throw invalid_input("standard input: input is larger than " + std::to_string(max_bytes >> 20) + " MiB");
        text.append(buf.data(), got);
    }
    if (std::cin.bad()) throw invalid_input("standard input: read error");
    return text;
}

/// The text of a WKT input: the file, or standard input for '-'.
inline std::string read_wkt_text_input(const std::string& path) {
    return is_standard_stream(path) ? read_standard_input(max_wkt_file_bytes) : read_wkt_text_file(path);
}

/// A polygon read from WKT: the file, or standard input for '-'; messages
/// start with the file name or "standard input".
inline polygon read_wkt_input(const std::string& path) { return read_wkt(read_wkt_text_input(path), shown_name(path)); }

/// Poses read from CSV: the file, or standard input for '-'; messages start
/// with the file name or "standard input".
inline std::vector<pose> read_poses_input(const std::string& path) {
    return is_standard_stream(path) ? read_poses_csv(std::cin, shown_name(path)) : read_poses_csv(path);
}

/// Writes `text` to `path` through a temporary file in the same directory,
/// renamed into place, so that a reader never sees a half-written file.
inline void write_atomically(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::path temp = path;
    temp += ".tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(temp.string() + ": cannot open for writing");
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.close();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temp, ignored);
            throw std::runtime_error(temp.string() + ": write error");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        throw std::runtime_error(path.string() + ": cannot rename the temporary file into place");
    }
}

/// Writes the whole of `text` to `path` as write_atomically does, or to
/// standard output for '-' (in one piece, after everything was computed).
inline void write_output(const std::string& path, const std::string& text) {
    if (!is_standard_stream(path)) {
        write_atomically(path, text);
        return;
    }
    std::cout.write(text.data(), static_cast<std::streamsize>(text.size()));
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("standard output: write error");
}

/// The output directory `out`, created if missing. '-' is refused: a
/// command that writes a directory of files cannot put them on standard
/// output.
inline std::filesystem::path output_directory(const std::string& out) {
    if (is_standard_stream(out))
        throw std::invalid_argument(
            "--out -: this command writes several files into a directory, which standard "
            "output cannot hold; name a directory");
    const std::filesystem::path dir(out);
    std::error_code ec;
    if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
        throw std::runtime_error(out + ": exists and is not a directory; --out names the output directory");
    std::filesystem::create_directories(dir, ec);
    if (!std::filesystem::is_directory(dir, ec))
        throw std::runtime_error(out + ": cannot create the output directory" + (ec ? ": " + ec.message() : ""));
    return dir;
}

/// Checks that `out` can be created: its directory exists and it is not a
/// directory itself ('-', standard output, always can). Returns the reason it
/// cannot, or "".
inline std::string check_output_path(const std::string& out) {
    namespace fs = std::filesystem;
    if (is_standard_stream(out)) return {};
    const fs::path path(out);
    std::error_code ec;
    if (fs::is_directory(path, ec)) return out + ": is a directory";
    const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    if (!fs::is_directory(dir, ec)) return out + ": directory " + dir.string() + " does not exist";
    return {};
}

}  // namespace influence2d::cli
