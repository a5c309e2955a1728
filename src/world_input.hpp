// SPDX-License-Identifier: BSL-1.0
#pragma once
// What the commands on many polygons (`world`, `pairs`) share: a file of
// polygons, one WKT geometry per line, and the number types a world or a
// layer join runs in.

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "files.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/multiprecision.hpp"
#include "influence2d/scene/prepared.hpp"

namespace influence2d::cli {

/// At most this many bad lines of an input are named in its message (one
/// line each); the count of the others follows.
inline constexpr std::size_t max_reported_lines = 20;

/// Throws one invalid_input listing `errors` (the first max_reported_lines,
/// then how many more, as lines of `shown`); does nothing when it is empty.
inline void throw_line_errors(const std::vector<std::string>& errors, const std::string& shown) {
    if (errors.empty()) return;
    std::string message;
    for (std::size_t k = 0; k < errors.size() && k < max_reported_lines; ++k) message += (k ? "\n" : "") + errors[k];
    if (errors.size() > max_reported_lines)
        message += "\n" + shown + ": and " + std::to_string(errors.size() - max_reported_lines) + " more bad lines";
    throw invalid_input(message);
}

/// Polygons read one per line: each non-blank line of the file a POLYGON
/// or MULTIPOLYGON (read_wkt), polygon k the k-th of them; `line` the
/// line (from 1) each came from.
struct polygon_lines {
    std::vector<polygon> polygons;
    std::vector<std::size_t> line;
};

/// Reads a file of one WKT geometry per line ('-': standard input); blank
/// lines are skipped. Throws one invalid_input naming the file and the line
/// of every bad geometry (the first max_reported_lines), or saying that the
/// file holds none.
inline polygon_lines read_polygon_lines(const std::string& path) {
    const std::string shown = shown_name(path);
    const std::string text = read_wkt_text_input(path);
    polygon_lines out;
    std::vector<std::string> errors;
    std::size_t line_no = 0;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = std::string_view(text).substr(start, end - start);
        start = end + 1;
        ++line_no;
        if (line_no == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
        if (line.find_first_not_of(" \t\r\f\v") == std::string_view::npos) continue;
        const std::string place = shown + ": line " + std::to_string(line_no);
        try {
            out.polygons.push_back(read_wkt(line, place));
            out.line.push_back(line_no);
        } catch (const invalid_input& e) {
            errors.emplace_back(e.what());
        }
    }
    throw_line_errors(errors, shown);
    if (out.polygons.empty())
        throw invalid_input(shown + ": no polygon: expected one POLYGON or MULTIPOLYGON per line");
    return out;
}

/// The polygon named `name` in DIR/LAYER.wkt (read_polygon_lines): the one
/// whose index is that of the line `name` in DIR/LAYER.names
/// (scripts/real_layers.sh writes both). Throws std::invalid_argument for a
/// names file that cannot be read or lacks the name, or a WKT file of fewer
/// polygons; invalid_input as read_polygon_lines does.
inline polygon named_polygon(const std::string& dir, const std::string& layer, const std::string& name) {
    const std::string names_path = dir + "/" + layer + ".names";
    std::ifstream names(names_path);
    if (!names) throw std::invalid_argument(names_path + ": cannot be read (make it with scripts/real_layers.sh)");
    std::string line;
    std::size_t index = 0;
    for (; std::getline(names, line); ++index)
        if (line == name) break;
    if (line != name) throw std::invalid_argument(names_path + ": no polygon named '" + name + "'");
    const polygon_lines all = read_polygon_lines(dir + "/" + layer + ".wkt");
    if (index >= all.polygons.size())
        throw std::invalid_argument(dir + "/" + layer + ".wkt: fewer polygons than names in " + names_path);
    return all.polygons[index];
}

/// Throws invalid_input naming the file and line of the first polygon that
/// NT cannot take (a coordinate beyond float's range, say).
template <class NT>
void check_polygon_lines(const polygon_lines& in, const std::string& path) {
    for (std::size_t k = 0; k < in.polygons.size(); ++k) {
        try {
            accepted_polygon<NT>(in.polygons[k], "line's");
        } catch (const invalid_input& e) {
            throw invalid_input(shown_name(path) + ": line " + std::to_string(in.line[k]) + ": " + e.what());
        }
    }
}

/// A type passed as a value, for the dispatch below.
template <class T>
struct type_tag {
    using type = T;
};

/// Calls f(type_tag<NT>{}, type_tag<Exact>{}) with the types a world or a
/// layer join runs in for --number-type `name`: the floating types and
/// `exact` as themselves (Exact void), `certified` as certified with an
/// exact_rational fallback (certified_world, certified_layer_pairs).
/// `interval` (and any type not listed here) is refused with a message
/// naming `command`: the world's exact answers come from `certified`.
template <class F>
decltype(auto) with_world_number_type(const std::string& name, const std::string& command, F&& f) {
    if (name == "float") return f(type_tag<float>{}, type_tag<void>{});
    if (name == "double") return f(type_tag<double>{}, type_tag<void>{});
    if (name == "long-double") return f(type_tag<long double>{}, type_tag<void>{});
    if (name == "quad") return f(type_tag<quad>{}, type_tag<void>{});
    if (name == "exact") return f(type_tag<exact_rational>{}, type_tag<void>{});
    if (name == "certified") return f(type_tag<certified>{}, type_tag<exact_rational>{});
    throw std::invalid_argument("--number-type " + name + ": " + command +
                                " does not run in this type; its exact answers come from --number-type certified "
                                "(double with an exact fallback) or exact; the rounded ones from float, double, "
                                "long-double or quad");
}

}  // namespace influence2d::cli
