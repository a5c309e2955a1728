// SPDX-License-Identifier: BSL-1.0
#pragma once
/// \file
/// Polygons as WKT text: POLYGON and MULTIPOLYGON, read with Boost.Geometry's
/// WKT reader (its numbers converted by std::from_chars, as
/// boost::lexical_cast would convert them) and checked for what that reader
/// lets through (unclosed rings, points without exactly two coordinates,
/// empty list elements).

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/io/wkt/read.hpp>
#include <boost/geometry/util/coordinate_cast.hpp>
#include <boost/lexical_cast.hpp>

#include "influence2d/core/point.hpp"
#include "influence2d/core/polygon.hpp"
#include "influence2d/core/shortest_decimal.hpp"

namespace influence2d {

/// Files larger than this (512 MiB) are refused by read_wkt_file and
/// read_wkt_text_file.
inline constexpr std::size_t max_wkt_file_bytes = std::size_t{512} << 20;

/// A ring as the WKT gives it: every point, the closing one included when the
/// text has it; nothing checked beyond the syntax.
struct wkt_ring {
    std::vector<point<double>> points;  ///< in text order; may be empty or hold non-finite values
    ring_role role = ring_role::outer;  ///< outer for an exterior ring, hole for an interior one
};

/// Whether ring `index` of the text is an empty exterior ring followed by
/// its holes: holes without a part, which the reader refuses (any other empty
/// ring is no ring, as GEOS and JTS read it).
inline bool empty_exterior_with_holes(const std::vector<wkt_ring>& read, std::size_t index) {
    return read[index].points.empty() && read[index].role == ring_role::outer && index + 1 < read.size() &&
           read[index + 1].role == ring_role::hole;
}

namespace wkt_detail {

/// A coordinate as Boost.Geometry's WKT reader reads it for the library: its
/// own type, so that the reader converts its text by the conversion below
/// (through Boost.Geometry's coordinate_cast, specialised for it after this
/// namespace; its read.hpp converts every coordinate so) rather than by
/// boost::lexical_cast, which builds a stream for every number: half the
/// instructions of reading a layer (Olinda's 470 city blocks, 12,235
/// vertices: 184 million before, 93 million after, callgrind).
struct wkt_number {
    double value = 0;
};

/// The double of a number's text as boost::lexical_cast<double> reads it
/// (the nearest double; a leading '+' taken, "inf" and "nan" too, an
/// exponent beyond double's range refused and one below it giving 0 or a
/// subnormal), or none for any other text, trailing characters included.
inline std::optional<double> number_of(const std::string& text) {
    const char* first = text.data();
    const char* last = first + text.size();
    if (first != last && *first == '+') {
        ++first;
        if (first != last && *first == '-') return std::nullopt;
    }
    double value = 0;
    const auto [end, error] = std::from_chars(first, last, value);
    if (end != last) return std::nullopt;
    if (error == std::errc()) return value;
    if (error != std::errc::result_out_of_range) return std::nullopt;
    // Out of range: strtod tells an overflow (infinite, refused) from an
    // underflow (kept as strtod rounds it).
    const double rounded = std::strtod(text.c_str(), nullptr);
    if (std::isinf(rounded)) return std::nullopt;
    return rounded;
}

}  // namespace wkt_detail
}  // namespace influence2d

namespace boost::geometry::detail {

/// The library's WKT coordinates converted by wkt_detail::number_of.
template <>
struct coordinate_cast<influence2d::wkt_detail::wkt_number> {
    static influence2d::wkt_detail::wkt_number apply(const std::string& text) {
        const std::optional<double> value = influence2d::wkt_detail::number_of(text);
        if (!value) throw boost::bad_lexical_cast();
        return {*value};
    }
};

}  // namespace boost::geometry::detail

namespace influence2d {
namespace wkt_detail {

using bg_point = boost::geometry::model::d2::point_xy<wkt_number>;
using bg_polygon = boost::geometry::model::polygon<bg_point>;
using bg_multi_polygon = boost::geometry::model::multi_polygon<bg_polygon>;
using bg_ring = bg_polygon::ring_type;

[[noreturn]] inline void fail(std::string_view source, const std::string& what) {
    throw invalid_input(std::string(source) + ": " + what);
}

inline std::string ring_place(std::size_t ring) { return "ring " + std::to_string(ring); }

inline std::string vertex_place(std::size_t ring, std::size_t vertex) {
    return ring_place(ring) + ", vertex " + std::to_string(vertex);
}

/// Boost's tokenizer separates on the space character only: other white space
/// would end up inside number tokens. Every white-space character becomes a
/// space, a UTF-8 byte-order mark is dropped, and the ends are trimmed.
inline std::string normalise(std::string_view text) {
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::string out(text);
    for (char& c : out) {
        if (c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f') c = ' ';
    }
    const auto first = out.find_first_not_of(' ');
    if (first == std::string::npos) return {};
    const auto last = out.find_last_not_of(' ');
    return out.substr(first, last - first + 1);
}

/// An element `EMPTY` inside the geometry's list, which Boost's reader does
/// not take, written as the empty list it stands for: `()` for a ring of a
/// polygon, `(())` for a polygon of a multipolygon. `ring_depth` is the
/// nesting depth of a ring's list (2 for POLYGON, 3 for MULTIPOLYGON).
inline std::string empty_elements_as_lists(const std::string& text, int ring_depth) {
    // (No 'Y' inside the lists, as in nearly every text: no EMPTY there.)
    const std::size_t lists = text.find('(');
    if (lists == std::string::npos || text.find_first_of("yY", lists) == std::string::npos) return text;
    std::string out;
    int depth = 0;
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        if (std::isalpha(static_cast<unsigned char>(c))) {
            std::size_t end = i;
            while (end < text.size() && std::isalpha(static_cast<unsigned char>(text[end]))) ++end;
            std::string word = text.substr(i, end - i);
            for (char& w : word) w = static_cast<char>(std::toupper(static_cast<unsigned char>(w)));
            if (depth > 0 && word == "EMPTY")
                out += depth + 1 == ring_depth ? "()" : "(())";
            else
                out.append(text, i, end - i);
            i = end;
            continue;
        }
        if (c == '(') ++depth;
        if (c == ')') --depth;
        out += c;
        ++i;
    }
    return out;
}

/// Boost's reader fills missing coordinates with zero, turns extra
/// coordinates into extra points and accepts an empty element before ')'.
/// This pass, run on text Boost has accepted, checks that every point at
/// the ring level has exactly two coordinates and that no list ends in ','.
/// Rings are numbered in text order, as the polygon numbers them.
inline void check_coordinate_tuples(std::string_view source, const std::string& text, int ring_depth) {
    int depth = 0;
    std::size_t ring = 0, vertex = 0, words = 0;
    bool any_ring = false;
    char prev = '\0';
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == ' ') {
            ++i;
            continue;
        }
        if (c != '(' && c != ')' && c != ',') {
            while (i < text.size() && text[i] != ' ' && text[i] != '(' && text[i] != ')' && text[i] != ',') ++i;
            ++words;
            continue;
        }
        ++i;
        if (c == '(') {
            ++depth;
            if (depth == ring_depth) {
                ring = any_ring ? ring + 1 : 0;
                any_ring = true;
                vertex = 0;
            }
        } else {
            const bool in_ring = depth == ring_depth && any_ring;
            if (c == ')' && prev == ',' && words == 0)
                fail(source, (in_ring ? ring_place(ring) + ": " : std::string()) + "empty element after ','");
            if (in_ring && !(c == ')' && prev == '(' && words == 0)) {
                if (words == 0) fail(source, vertex_place(ring, vertex) + ": missing coordinates");
                if (words != 2)
                    fail(source, vertex_place(ring, vertex) + ": " + std::to_string(words) +
                                     " coordinates, expected 2 (only x y is supported)");
                ++vertex;
            }
            if (c == ')') --depth;
        }
        words = 0;
        prev = c;
    }
}

/// Appends ring `index` of the text as a ring_input after checking it:
/// finite coordinates, closed (first point repeated at the end), three
/// distinct vertices. The closing point goes in with the others: polygon
/// drops it, and only it, so a ring whose last vertex before the closing
/// point equals the first keeps that vertex as a zero-length edge. An empty
/// ring adds nothing, unless it is an exterior followed by holes
/// (empty_exterior_with_holes): refused.
inline void append_ring(std::string_view source, const std::vector<wkt_ring>& read, std::size_t index,
                        std::vector<ring_input>& rings) {
    const wkt_ring& r = read[index];
    const auto& pts = r.points;
    if (empty_exterior_with_holes(read, index)) fail(source, ring_place(index) + ": empty exterior ring with holes");
    if (pts.empty()) return;
    for (std::size_t k = 0; k < pts.size(); ++k) {
        if (!std::isfinite(pts[k].x) || !std::isfinite(pts[k].y))
            fail(source, vertex_place(index, k) + ": coordinate is not a finite number");
    }
    const point<double>& a = pts.front();
    const point<double>& b = pts.back();
    if (a.x != b.x || a.y != b.y)
        fail(source, ring_place(index) + " is not closed: first point (" + shortest_decimal(a.x) + " " +
                         shortest_decimal(a.y) + ") differs from last point (" + shortest_decimal(b.x) + " " +
                         shortest_decimal(b.y) + ")");
    ring_input in;
    in.role = r.role;
    in.vertices = pts;
    if (polygon::count_distinct(in.vertices) < 3)
        fail(source, ring_place(index) + ": fewer than three distinct vertices");
    rings.push_back(std::move(in));
}

}  // namespace wkt_detail

/// The rings of WKT text (POLYGON or MULTIPOLYGON, see read_wkt) without the
/// geometric checks: for audits, which report what read_wkt would refuse.
/// Throws invalid_input, starting with `source`, for what is not WKT of a
/// polygon at all (syntax, geometry type, empty geometry, coordinate count:
/// exactly x and y, no Z or M).
inline std::vector<wkt_ring> read_wkt_rings(std::string_view text, std::string_view source = "<text>") {
    namespace bg = boost::geometry;
    using namespace wkt_detail;
    const std::string plain = normalise(text);
    if (plain.empty()) fail(source, "empty input: expected POLYGON or MULTIPOLYGON");

    std::size_t kw_end = 0;
    while (kw_end < plain.size() && std::isalpha(static_cast<unsigned char>(plain[kw_end]))) ++kw_end;
    std::string keyword = plain.substr(0, kw_end);
    for (char& c : keyword) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const bool multi = keyword == "MULTIPOLYGON";
    if (!multi && keyword != "POLYGON") {
        std::string found = plain.substr(0, plain.find_first_of(" (", kw_end == 0 ? 1 : kw_end));
        if (found.size() > 40) found = found.substr(0, 40) + "...";
        fail(source, "expected POLYGON or MULTIPOLYGON, found '" + found + "'");
    }

    const std::string wkt = empty_elements_as_lists(plain, multi ? 3 : 2);
    std::vector<wkt_ring> rings;
    const auto add = [&](const bg_ring& r, ring_role role) {
        wkt_ring out;
        out.role = role;
        out.points.reserve(r.size());
        for (const auto& q : r) out.points.push_back({q.x().value, q.y().value});
        rings.push_back(std::move(out));
    };
    const auto add_polygon = [&](const bg_polygon& p) {
        add(p.outer(), ring_role::outer);
        for (const auto& hole : p.inners()) add(hole, ring_role::hole);
    };
    try {
        if (multi) {
            bg_multi_polygon mp;
            bg::read_wkt(wkt, mp);
            if (mp.empty()) fail(source, "MULTIPOLYGON is empty");
            check_coordinate_tuples(source, wkt, 3);
            for (const auto& p : mp) add_polygon(p);
        } else {
            bg_polygon p;
            bg::read_wkt(wkt, p);
            if (p.outer().empty() && p.inners().empty()) fail(source, "POLYGON is empty");
            check_coordinate_tuples(source, wkt, 2);
            add_polygon(p);
        }
    } catch (const invalid_input&) {
        throw;
    } catch (const std::exception& e) {
        fail(source, std::string("parse error: ") + e.what());
    }
    return rings;
}

/// The polygon of rings as read_wkt_rings gives them (or any reader of the
/// same rings, WKB say), checked as read_wkt checks them: closed rings,
/// finite coordinates, three distinct vertices, an exterior before its
/// holes. Throws invalid_input with a message starting with `source`.
inline polygon polygon_of_rings(const std::vector<wkt_ring>& read, std::string_view source = "<text>") {
    std::vector<ring_input> rings;
    for (std::size_t k = 0; k < read.size(); ++k) wkt_detail::append_ring(source, read, k, rings);
    try {
        return polygon(std::move(rings));
    } catch (const invalid_input& e) {
        wkt_detail::fail(source, e.what());
    }
}

/// Reads a polygon from WKT text: `POLYGON` (first ring outer, the others
/// holes) or `MULTIPOLYGON` (each part's exterior outer, its interiors holes),
/// keywords in any case, surrounding white space allowed. Rings must be
/// closed; the closing point is dropped. Rings are numbered 0, 1, ... in text
/// order across the whole geometry and vertices 0, 1, ... within a ring.
/// An empty ring (`EMPTY` or `()`) is no ring, as GEOS and JTS read it; it
/// holds no vertex, so the numbers of the edges do not change.
/// Throws invalid_input with a message starting with `source` for what
/// read_wkt_rings refuses, an unclosed ring, an empty exterior ring followed
/// by holes, a non-finite coordinate, a ring with fewer than three distinct
/// vertices, and a geometry whose rings are all empty. Degenerate but usable
/// rings (repeated vertices, collinear runs, self-intersections, zero area)
/// are accepted as polygon takes them; audit_rings (audit/audit.hpp) lists
/// them.
inline polygon read_wkt(std::string_view text, std::string_view source = "<text>") {
    return polygon_of_rings(read_wkt_rings(text, source), source);
}

/// The text of a WKT file, read as bytes; files over max_wkt_file_bytes are
/// refused. Throws invalid_input starting with `path` for that, a file that
/// cannot be opened or read, or a directory.
inline std::string read_wkt_text_file(const std::string& path) {
    const std::string too_large = "file is larger than " + std::to_string(max_wkt_file_bytes >> 20) + " MiB";
    std::ifstream in(path, std::ios::binary);
    if (!in) wkt_detail::fail(path, "cannot open file");
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) wkt_detail::fail(path, "is a directory");
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_wkt_file_bytes) wkt_detail::fail(path, too_large);
    std::string text;
    std::array<char, 1 << 16> buf{};
    while (in) {
        in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
        const auto got = static_cast<std::size_t>(in.gcount());
        if (text.size() + got > max_wkt_file_bytes) wkt_detail::fail(path, too_large);
        text.append(buf.data(), got);
    }
    if (in.bad()) wkt_detail::fail(path, "read error");
    return text;
}

/// Reads a polygon from a WKT file (see read_wkt); messages start with `path`.
/// Files over max_wkt_file_bytes are refused.
inline polygon read_wkt_file(const std::string& path) { return read_wkt(read_wkt_text_file(path), path); }

/// Writes the polygon as WKT with every coordinate in its shortest form that
/// reads back to the same double; rings are closed and in stored orientation
/// (outer counter-clockwise, holes clockwise). One outer ring gives a POLYGON;
/// several give a MULTIPOLYGON, each hole going with the closest preceding
/// outer ring in storage order (the order they were read in). read_wkt of the
/// text gives the same rings, vertices and roles; its input edge numbers are
/// those of the stored order. Throws invalid_input when ring 0 is a hole (WKT
/// needs an outer ring first).
inline std::string to_wkt(const polygon& poly) {
    const std::size_t rings = poly.ring_count();
    if (rings == 0) throw invalid_input("to_wkt: polygon has no ring");
    if (poly.role(0) != ring_role::outer)
        throw invalid_input("to_wkt: ring 0 is a hole; WKT needs an outer ring first");
    std::size_t outers = 0;
    for (std::size_t r = 0; r < rings; ++r) outers += poly.role(r) == ring_role::outer;
    const bool multi = outers > 1;

    std::string out = multi ? "MULTIPOLYGON(" : "POLYGON";
    auto write_ring = [&](std::size_t r) {
        out += '(';
        for (std::size_t i = poly.ring_begin(r); i < poly.ring_end(r); ++i) {
            out += shortest_decimal(poly.vertex(i).x);
            out += ' ';
            out += shortest_decimal(poly.vertex(i).y);
            out += ',';
        }
        const auto& first = poly.vertex(poly.ring_begin(r));
        out += shortest_decimal(first.x);
        out += ' ';
        out += shortest_decimal(first.y);
        out += ')';
    };
    for (std::size_t r = 0; r < rings; ++r) {
        if (poly.role(r) == ring_role::outer) {
            if (r > 0) out += "),";
            out += '(';
        } else {
            out += ',';
        }
        write_ring(r);
    }
    out += ')';
    if (multi) out += ')';
    return out;
}

}  // namespace influence2d
