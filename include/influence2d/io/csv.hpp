// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Poses and per-frame results as CSV.
///
///     Poses file:   tx,ty,theta            (header, exactly these names)
///                   1.5,-2,0.785398        (one pose per line, finite numbers)
///     Frames file:  frame,collides[,edges] (frames from 0, collides 0 or 1,
///                                           edges "i:j;i:j" static:moving)

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/core/shortest_decimal.hpp"
#include "influence2d/detect/result.hpp"

namespace influence2d {

/// Pose files larger than this (512 MiB) are refused by read_poses_csv.
inline constexpr std::size_t max_csv_file_bytes = std::size_t{512} << 20;
/// At most this many bad pose rows are named in read_poses_csv's message
/// (one line each); the count of the others follows.
inline constexpr std::size_t max_reported_csv_errors = 20;

namespace csv_detail {

inline constexpr std::array<const char*, 3> pose_columns{"tx", "ty", "theta"};

inline std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

inline std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        fields.push_back(
            trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
        if (comma == std::string_view::npos) return fields;
        start = comma + 1;
    }
}

inline std::string quoted(std::string_view s) {
    std::string q(s.substr(0, 40));
    if (s.size() > 40) q += "...";
    return "\"" + q + "\"";
}

/// Parses the whole field as a double (std::from_chars, one leading '+'
/// allowed); returns an empty string or the reason it is not usable.
inline std::string parse_number(std::string_view field, double& value) {
    if (field.empty()) return "empty value";
    std::string_view digits = field;
    if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
    const char* first = digits.data();
    const char* last = digits.data() + digits.size();
    const auto res = std::from_chars(first, last, value);
    if (res.ec == std::errc::result_out_of_range) return quoted(field) + " is out of range";
    if (res.ec != std::errc() || res.ptr != last) return quoted(field) + " is not a number";
    if (!std::isfinite(value)) return quoted(field) + " is not a finite number";
    return {};
}

}  // namespace csv_detail

/// Reads poses from a stream in the format of the file reader below; messages
/// start with `path`, the name the stream is reported by. A UTF-8 byte-order
/// mark before the header is skipped; more than max_csv_file_bytes of input
/// is refused. Throws invalid_input naming the line (from 1) and column: at
/// once for the header, the size or a read error; for the pose rows after
/// reading them all, one line of the message per bad row (the first
/// max_reported_csv_errors, then how many more).
inline std::vector<pose> read_poses_csv(std::istream& in, const std::string& path) {
    using namespace csv_detail;
    auto fail = [&](const std::string& what) -> void { throw invalid_input(path + ": " + what); };
    std::vector<std::string> bad_rows;
    const auto bad = [&](const std::string& what) { bad_rows.push_back(path + ": " + what); };
    const std::string too_large = "file is larger than " + std::to_string(max_csv_file_bytes >> 20) + " MiB";
    std::vector<pose> poses;
    std::string line;
    std::size_t line_no = 0, bytes = 0, blank_line = 0;
    bool header_seen = false;
    while (std::getline(in, line)) {
        ++line_no;
        bytes += line.size() + 1;
        if (bytes > max_csv_file_bytes + 1) fail(too_large);
        const std::string place = "line " + std::to_string(line_no);
        std::string_view text = line;
        if (line_no == 1 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
        if (trim(text).empty()) {
            if (blank_line == 0) blank_line = line_no;
            continue;
        }
        if (!header_seen) {
            if (blank_line != 0) fail("line " + std::to_string(blank_line) + ": blank line before the header");
            const auto fields = split(text);
            bool ok = fields.size() == pose_columns.size();
            for (std::size_t c = 0; ok && c < fields.size(); ++c) ok = fields[c] == pose_columns[c];
            if (!ok) fail(place + ": expected the header \"tx,ty,theta\", found " + quoted(trim(text)));
            header_seen = true;
            continue;
        }
        if (blank_line != 0) {
            bad("line " + std::to_string(blank_line) + ": blank line between pose rows");
            blank_line = 0;
        }
        const auto fields = split(text);
        if (fields.size() < pose_columns.size()) {
            bad(place + ": " + std::to_string(fields.size()) + (fields.size() == 1 ? " column" : " columns") +
                ", expected 3; missing column " + pose_columns[fields.size()]);
            continue;
        }
        if (fields.size() > pose_columns.size()) {
            bad(place + ": " + std::to_string(fields.size()) + " columns, expected 3 (tx,ty,theta)");
            continue;
        }
        std::array<double, 3> v{};
        bool ok = true;
        for (std::size_t c = 0; c < 3 && ok; ++c) {
            const std::string why = parse_number(fields[c], v[c]);
            if (!why.empty()) bad(place + ", column " + pose_columns[c] + ": " + why);
            ok = why.empty();
        }
        if (ok) poses.push_back(pose{v[0], v[1], v[2]});
    }
    if (in.bad()) fail("read error");
    if (!header_seen)
        fail(line_no == 0 ? "empty file: expected the header \"tx,ty,theta\"" : "no header: expected \"tx,ty,theta\"");
    if (!bad_rows.empty()) {
        std::string message;
        for (std::size_t k = 0; k < bad_rows.size() && k < max_reported_csv_errors; ++k)
            message += (k ? "\n" : "") + bad_rows[k];
        if (bad_rows.size() > max_reported_csv_errors)
            message +=
                "\n" + path + ": and " + std::to_string(bad_rows.size() - max_reported_csv_errors) + " more bad lines";
        throw invalid_input(message);
    }
    return poses;
}

/// Reads poses from a CSV file: the header `tx,ty,theta`, then one line per
/// pose with three finite numbers. Spaces around fields and a trailing
/// carriage return are ignored; blank lines are allowed only at the end.
/// Numbers are read as by std::from_chars (one leading '+' allowed); values
/// out of double's range, infinities and NaN are refused. Throws invalid_input
/// naming the file, the line (from 1) and the column; also for a file that
/// cannot be opened, a directory, or one over max_csv_file_bytes.
inline std::vector<pose> read_poses_csv(const std::string& path) {
    auto fail = [&](const std::string& what) -> void { throw invalid_input(path + ": " + what); };
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("cannot open file");
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) fail("is a directory");
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_csv_file_bytes)
        fail("file is larger than " + std::to_string(max_csv_file_bytes >> 20) + " MiB");
    return read_poses_csv(in, path);
}

/// Writes poses in the format read_poses_csv reads, each number in its
/// shortest form that reads back to the same double. Non-finite values are
/// written as they are (inf, nan), which the reader refuses. Stream errors
/// are left in the stream's state.
inline void write_poses_csv(std::ostream& out, const std::vector<pose>& poses) {
    out << "tx,ty,theta\n";
    for (const auto& p : poses)
        out << shortest_decimal(p.tx) << ',' << shortest_decimal(p.ty) << ',' << shortest_decimal(p.theta) << '\n';
}

/// Writes poses to a file; throws invalid_input when it cannot be written.
inline void write_poses_csv(const std::string& path, const std::vector<pose>& poses) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw invalid_input(path + ": cannot open file for writing");
    write_poses_csv(out, poses);
    out.close();
    if (!out) throw invalid_input(path + ": write error");
}

/// Writes one line per frame, after a header: `frame,collides` (frames from
/// 0, collides 0 or 1), or with `witness` `frame,collides,edges` where edges
/// lists the involved pairs as `static:moving` input edge numbers separated
/// by ';' (empty when there is none). Then the columns named in
/// `extra_columns`, frame f's values being `extra(f)` (already joined by
/// commas, no leading comma). Stream errors are left in the stream's state.
template <class Extra>
void write_frames_csv(std::ostream& out, const std::vector<frame_result>& results, bool witness,
                      const std::vector<std::string>& extra_columns, Extra&& extra) {
    out << (witness ? "frame,collides,edges" : "frame,collides");
    for (const std::string& c : extra_columns) out << ',' << c;
    out << '\n';
    std::string row;
    for (std::size_t f = 0; f < results.size(); ++f) {
        row.clear();
        row += std::to_string(f);
        row += results[f].collides ? ",1" : ",0";
        if (witness) {
            row += ',';
            bool first = true;
            for (const auto& pr : results[f].pairs) {
                if (!first) row += ';';
                first = false;
                row += std::to_string(pr.static_edge);
                row += ':';
                row += std::to_string(pr.moving_edge);
            }
        }
        if (!extra_columns.empty()) {
            row += ',';
            row += extra(f);
        }
        row += '\n';
        out << row;
    }
}

/// write_frames_csv without extra columns.
inline void write_frames_csv(std::ostream& out, const std::vector<frame_result>& results, bool witness) {
    write_frames_csv(out, results, witness, {}, [](std::size_t) { return std::string(); });
}

}  // namespace influence2d
