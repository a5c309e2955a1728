// SPDX-License-Identifier: BSL-1.0
// `influence2d audit POLYGON.wkt`: every degeneracy of the polygon, found with
// exact predicates (include/influence2d/audit/audit.hpp), as readable lines on
// standard output and, with --json, as JSON.

#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "files.hpp"
#include "influence2d/audit/audit.hpp"
#include "report.hpp"

namespace influence2d::cli {

namespace {

struct audit_cli_options {
    std::string file;
    std::string json;
};

std::string place(const finding& f) {
    std::string s = "ring " + std::to_string(f.ring);
    if (f.vertex) s += ", vertex " + std::to_string(*f.vertex);
    if (f.other_ring) s += " / ring " + std::to_string(*f.other_ring) + ", vertex " + std::to_string(*f.other_vertex);
    return s;
}

nlohmann::json to_json(const std::string& file, const audit_report& r) {
    nlohmann::json j;
    j["file"] = file;
    j["accepted"] = r.accepted;
    if (!r.accepted) j["rejection"] = r.rejection;
    j["rings"] = r.rings;
    j["vertices"] = r.vertices;
    j["total"] = r.total;
    j["findings"] = nlohmann::json::array();
    for (const finding& f : r.findings) {
        nlohmann::json g;
        g["kind"] = finding_name(f.kind);
        g["ring"] = f.ring;
        if (f.vertex) g["vertex"] = *f.vertex;
        if (f.other_ring) {
            g["other_ring"] = *f.other_ring;
            g["other_vertex"] = *f.other_vertex;
        }
        if (std::isfinite(f.at.x) && std::isfinite(f.at.y))
            g["at"] = {f.at.x, f.at.y};
        else
            g["at"] = {general(f.at.x, 17), general(f.at.y, 17)};  // JSON has no NaN or infinity
        g["what"] = f.what;
        g["effect"] = f.effect;
        g["rejects"] = f.rejects;
        j["findings"].push_back(std::move(g));
    }
    return j;
}

void run_audit(const audit_cli_options& o) {
    const std::string name = shown_name(o.file);
    const audit_report r = audit_rings(read_wkt_rings(read_wkt_text_input(o.file), name));
    if (!o.json.empty()) write_output(o.json, to_json(name, r).dump(2) + "\n");
    if (!is_standard_stream(o.json)) {
        std::cout << name << ": " << r.rings << " ring(s), " << r.vertices << " vertices, " << r.total << " finding(s)"
                  << (r.total > r.findings.size() ? " (" + std::to_string(r.findings.size()) + " listed)" : "") << "; "
                  << (r.accepted ? "accepted" : "refused: " + r.rejection) << "\n";
        for (const finding& f : r.findings)
            std::cout << name << ": " << place(f) << ": " << finding_name(f.kind) << ": " << f.what << "\n    -> "
                      << f.effect << "\n";
    }
    if (!r.accepted) throw exit_status{1};
}

}  // namespace

void register_audit(CLI::App& app) {
    auto o = std::make_shared<audit_cli_options>();
    CLI::App* sub = app.add_subcommand(
        "audit",
        "Report every degeneracy of a polygon (exact predicates): repeated and near-repeated vertices, collinear "
        "runs and spikes, self-intersections, rings that meet, orientation, holes outside their shell, "
        "non-manifold vertices, zero area, the centroid on an edge's line, coordinates beyond a number type's "
        "range; for each, where it is and what the library does with it. Exit code 0: the library accepts the "
        "polygon; 1: it refuses it; 2: the file cannot be read as WKT.");
    sub->add_option("POLYGON", o->file, "WKT file (POLYGON or MULTIPOLYGON); '-': standard input")
        ->required()
        ->type_name("FILE");
    sub->add_option("--json", o->json,
                    "Also write the findings as JSON to FILE ('-': standard output, instead of "
                    "the readable lines)")
        ->type_name("FILE");
    sub->callback([o] { run_audit(*o); });
}

}  // namespace influence2d::cli
