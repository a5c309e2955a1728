// SPDX-License-Identifier: BSL-1.0
// `influence2d audit POLYGON.wkt`: every degeneracy of each polygon of a file,
// found with exact predicates (include/influence2d/audit/audit.hpp) on all
// cores, grouped by kind (audit/findings_by_kind.hpp), as readable lines on
// standard output and, with --json, as JSON.
//
// The file holds one geometry, as read_wkt_rings reads it (on one line or
// several), or many: a geometry starts at the first non-blank line and at
// every line whose first word is POLYGON or MULTIPOLYGON (in any case); the
// other non-blank lines continue the geometry above them; blank lines are
// skipped. With one geometry per line, geometry k is the k-th non-blank line.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "files.hpp"
#include "influence2d/audit/audit.hpp"
#include "influence2d/audit/findings_by_kind.hpp"
#include "influence2d/query/batch.hpp"
#include "report.hpp"

namespace influence2d::cli {

namespace {

struct audit_cli_options {
    std::string file;
    std::string json;
    unsigned threads = 0;
};

/// At most this many places of a kind are shown for each polygon.
constexpr std::size_t shown_places = 3;

/// One geometry of the file: its text and the lines it spans (from 1).
struct geometry_text {
    std::string text;
    std::size_t first_line = 0, last_line = 0;
};

/// The audits of the file's polygons, in file order.
struct layer_audit {
    std::vector<audit_report> reports;               ///< one per polygon
    std::vector<std::vector<kind_findings>> groups;  ///< each report's findings by kind
};

bool is_blank(std::string_view line) { return line.find_first_not_of(" \t\r\v\f") == std::string_view::npos; }

/// Whether the line's first word is POLYGON or MULTIPOLYGON, in any case.
bool starts_geometry(std::string_view line) {
    const std::size_t start = line.find_first_not_of(" \t\r\v\f");
    if (start == std::string_view::npos) return false;
    std::string word;
    for (std::size_t i = start; i < line.size() && std::isalpha(static_cast<unsigned char>(line[i])); ++i)
        word += static_cast<char>(std::toupper(static_cast<unsigned char>(line[i])));
    return word == "POLYGON" || word == "MULTIPOLYGON";
}

/// The geometries of the text (see the top of this file), in file order.
std::vector<geometry_text> split_geometries(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::vector<geometry_text> geometries;
    std::size_t number = 0;
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = text.substr(start, end - start);
        ++number;
        start = end + 1;
        if (is_blank(line)) continue;
        if (geometries.empty() || starts_geometry(line)) {
            geometries.push_back({std::string(line), number, number});
        } else {
            geometries.back().text += '\n';
            geometries.back().text.append(line);
            geometries.back().last_line = number;
        }
    }
    return geometries;
}

/// "line 4" or "lines 4-9".
std::string lines_of(const geometry_text& g) {
    if (g.first_line == g.last_line) return "line " + std::to_string(g.first_line);
    return "lines " + std::to_string(g.first_line) + "-" + std::to_string(g.last_line);
}

/// What the messages and lines about polygon k start with: "FILE: polygon k".
std::string polygon_name(const std::string& name, std::size_t k) { return name + ": polygon " + std::to_string(k); }

/// At most this many geometries that are not WKT of a polygon are named, one
/// line each; the count of the others follows.
constexpr std::size_t max_named_errors = 20;

/// The rings of each geometry, read on `threads` threads, in file order.
/// Throws one invalid_input naming every geometry that is not WKT of a
/// polygon (up to max_named_errors), each with the file, its polygon number
/// and its lines.
std::vector<std::vector<wkt_ring>> read_geometries(const std::vector<geometry_text>& geometries,
                                                   const std::string& name, unsigned threads) {
    std::vector<std::vector<wkt_ring>> rings(geometries.size());
    std::vector<std::string> errors(geometries.size());
    run_in_blocks(geometries.size(), threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
            const std::string source = polygon_name(name, k) + " (" + lines_of(geometries[k]) + ")";
            try {
                rings[k] = read_wkt_rings(geometries[k].text, source);
            } catch (const invalid_input& e) {
                errors[k] = e.what();
            }
        }
    });
    std::string message;
    std::size_t bad = 0;
    for (const std::string& e : errors) {
        if (e.empty()) continue;
        if (bad++ < max_named_errors) message += (message.empty() ? "" : "\n") + e;
    }
    if (bad > max_named_errors)
        message +=
            "\n" + name + ": " + std::to_string(bad - max_named_errors) + " more geometries are not WKT of a polygon";
    if (bad > 0) throw invalid_input(message);
    return rings;
}

/// Each polygon audited and its findings grouped, on `threads` threads, in file order.
layer_audit audit_polygons(const std::vector<std::vector<wkt_ring>>& rings, unsigned threads) {
    layer_audit a;
    a.reports.resize(rings.size());
    a.groups.resize(rings.size());
    run_in_blocks(rings.size(), threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
            a.reports[k] = audit_rings(rings[k]);
            a.groups[k] = findings_by_kind(a.reports[k], shown_places);
        }
    });
    return a;
}

std::string place(const finding& f) {
    std::string s = "ring " + std::to_string(f.ring);
    if (f.vertex) s += ", vertex " + std::to_string(*f.vertex);
    if (f.other_ring) s += " / ring " + std::to_string(*f.other_ring) + ", vertex " + std::to_string(*f.other_vertex);
    return s;
}

/// The summary line of a polygon: rings, vertices, findings, the verdict.
std::string summary_line(const std::string& name, std::size_t k, const geometry_text& g, const audit_report& r) {
    return polygon_name(name, k) + " (" + lines_of(g) + "): " + std::to_string(r.rings) + " ring(s), " +
           std::to_string(r.vertices) + " vertices, " + std::to_string(r.total) + " finding(s); " +
           (r.accepted ? "accepted" : "refused: " + r.rejection) + "\n";
}

/// A kind's line, its count and first places, then its effect on a line of its own.
std::string group_lines(const std::string& name, std::size_t k, const kind_findings& g) {
    std::string s = polygon_name(name, k) + ": " + finding_name(g.kind) + ", " +
                    (g.count == 1 ? std::string("once") : std::to_string(g.count) + " times");
    for (std::size_t i = 0; i < g.first.size(); ++i) s += (i == 0 ? ", at " : "; ") + place(g.first[i]);
    if (!g.first.empty() && g.count > g.first.size()) s += "; ...";
    if (!g.what.empty()) s += std::string(": ") + (g.same_text ? "" : "at the first, ") + g.what;
    s += "\n";
    if (!g.effect.empty()) s += "    -> " + g.effect + "\n";
    return s;
}

/// The layer's verdicts and its table of kinds: polygons affected, occurrences.
std::string layer_lines(const std::string& name, const layer_findings& t) {
    std::ostringstream s;
    s << name << ": " << t.polygons << " polygon(s): " << t.accepted << " accepted, " << t.refused << " refused";
    if (t.kinds.empty()) {
        s << "; no finding\n";
        return s.str();
    }
    s << "; findings by kind:\n";
    std::size_t width = 4;
    for (const layer_kind_count& c : t.kinds) width = std::max(width, std::string(finding_name(c.kind)).size());
    s << "    " << std::left << std::setw(static_cast<int>(width)) << "kind" << std::right << "  " << std::setw(8)
      << "polygons"
      << "  " << std::setw(11) << "occurrences"
      << "\n";
    for (const layer_kind_count& c : t.kinds)
        s << "    " << std::left << std::setw(static_cast<int>(width)) << finding_name(c.kind) << std::right << "  "
          << std::setw(8) << c.polygons << "  " << std::setw(11) << c.occurrences << "\n";
    return s.str();
}

nlohmann::json point_json(const point<double>& p) {
    if (std::isfinite(p.x) && std::isfinite(p.y)) return {p.x, p.y};
    return {general(p.x, 17), general(p.y, 17)};  // JSON has no NaN or infinity
}

nlohmann::json group_json(const kind_findings& g) {
    nlohmann::json j;
    j["kind"] = finding_name(g.kind);
    j["count"] = g.count;
    j["rejects"] = g.rejects;
    j["what"] = g.what;
    j["effect"] = g.effect;
    j["same_text"] = g.same_text;
    j["first"] = nlohmann::json::array();
    for (const finding& f : g.first) {
        nlohmann::json p;
        p["ring"] = f.ring;
        if (f.vertex) p["vertex"] = *f.vertex;
        if (f.other_ring) {
            p["other_ring"] = *f.other_ring;
            p["other_vertex"] = *f.other_vertex;
        }
        p["at"] = point_json(f.at);
        p["what"] = f.what;
        p["effect"] = f.effect;
        j["first"].push_back(std::move(p));
    }
    return j;
}

nlohmann::json to_json(const std::string& file, const std::vector<geometry_text>& geometries, const layer_audit& a,
                       const layer_findings& t) {
    nlohmann::json j;
    j["file"] = file;
    j["accepted"] = t.refused == 0;
    j["polygons"] = nlohmann::json::array();
    for (std::size_t k = 0; k < a.reports.size(); ++k) {
        const audit_report& r = a.reports[k];
        nlohmann::json p;
        p["index"] = k;
        p["line"] = geometries[k].first_line;
        p["last_line"] = geometries[k].last_line;
        p["rings"] = r.rings;
        p["vertices"] = r.vertices;
        p["total"] = r.total;
        p["accepted"] = r.accepted;
        if (!r.accepted) p["rejection"] = r.rejection;
        p["findings"] = nlohmann::json::array();
        for (const kind_findings& g : a.groups[k]) p["findings"].push_back(group_json(g));
        j["polygons"].push_back(std::move(p));
    }
    nlohmann::json layer;
    layer["polygons"] = t.polygons;
    layer["accepted"] = t.accepted;
    layer["refused"] = t.refused;
    layer["kinds"] = nlohmann::json::array();
    for (const layer_kind_count& c : t.kinds)
        layer["kinds"].push_back(
            {{"kind", finding_name(c.kind)}, {"polygons", c.polygons}, {"occurrences", c.occurrences}});
    j["layer"] = std::move(layer);
    return j;
}

void run_audit(const audit_cli_options& o) {
    const std::string name = shown_name(o.file);
    const std::string text = read_wkt_text_input(o.file);
    const std::vector<geometry_text> geometries = split_geometries(text);
    if (geometries.empty()) throw invalid_input(name + ": empty input: expected POLYGON or MULTIPOLYGON");
    const layer_audit a = audit_polygons(read_geometries(geometries, name, o.threads), o.threads);
    const layer_findings t = findings_over_layer(a.reports);
    if (!o.json.empty()) write_output(o.json, to_json(name, geometries, a, t).dump(2) + "\n");
    if (!is_standard_stream(o.json)) {
        std::string out;
        for (std::size_t k = 0; k < a.reports.size(); ++k) {
            out += summary_line(name, k, geometries[k], a.reports[k]);
            for (const kind_findings& g : a.groups[k]) out += group_lines(name, k, g);
        }
        out += layer_lines(name, t);
        write_output(standard_stream, out);
    }
    if (t.refused > 0) throw exit_status{1};
}

}  // namespace

void register_audit(CLI::App& app) {
    auto o = std::make_shared<audit_cli_options>();
    CLI::App* sub = app.add_subcommand(
        "audit",
        "Report every degeneracy of each polygon of a file (exact predicates): repeated and near-repeated "
        "vertices, collinear runs and spikes, self-intersections, rings that meet, orientation, holes outside "
        "their shell, non-manifold vertices, zero area, the centroid on an edge's line, coordinates beyond a "
        "number type's range; for each, where it is and what the library does with it. Per polygon a summary "
        "line, then each kind found once with its count and first places; at the end the count of each kind "
        "over the file. Exit code 0: the library accepts every polygon; 1: it refuses one or more; 2: the file "
        "cannot be read as WKT (the message names each geometry that is not, with its line).");
    sub->add_option("POLYGON", o->file,
                    "WKT file: one POLYGON or MULTIPOLYGON (on one line or several), or one per line (a line "
                    "starting with POLYGON or MULTIPOLYGON starts a geometry, other lines continue it, blank "
                    "lines are skipped; polygon k is the k-th); '-': standard input")
        ->required()
        ->type_name("FILE");
    sub->add_option("--json", o->json,
                    "Also write the findings as JSON to FILE ('-': standard output, instead of "
                    "the readable lines)")
        ->type_name("FILE");
    sub->add_option("--threads", o->threads,
                    "Threads auditing the polygons, each a contiguous run of them; 0, the default, uses every "
                    "hardware thread. The output is the same for every count")
        ->capture_default_str()
        ->check(CLI::Range(0u, 4096u))
        ->type_name("N");
    sub->callback([o] { run_audit(*o); });
}

}  // namespace influence2d::cli
