// SPDX-License-Identifier: BSL-1.0
#pragma once
// The report of the turning study (verification/turning_study.hpp):
// turning.csv and the section "Turning motions" of bench.md.

#include <cstddef>
#include <string>
#include <vector>

#include "verification/report_text.hpp"
#include "verification/turning_study.hpp"

namespace influence2d::verification {

/// A cell's name: type n x m.
inline std::string turning_cell_name(const turning_cell& c) {
    return c.type + " " + std::to_string(c.static_size) + "x" + std::to_string(c.moving_size);
}

/// turning.csv: one line per method and cell.
inline std::string turning_csv(const std::vector<turning_row>& rows) {
    std::string s =
        "type,static_size,moving_size,method,model,motions,contacts,misses,inventions,failed,largest_time_error,"
        "rounds,seconds,us_per_motion,reference\n";
    for (const turning_row& r : rows)
        s += r.cell.type + "," + std::to_string(r.cell.static_size) + "," + std::to_string(r.cell.moving_size) + "," +
             r.method + "," + r.model + "," + std::to_string(r.motions) + "," + std::to_string(r.contacts) + "," +
             std::to_string(r.misses) + "," + std::to_string(r.inventions) + "," + std::to_string(r.failed) + "," +
             general(r.largest_time_error) + "," + std::to_string(r.rounds) + "," + general(r.seconds) + "," +
             fixed(r.us_per_motion(), 2) + "," + (r.reference ? "1" : "0") + "\n";
    return s;
}

/// The section of bench.md: what was asked, then one table per cell.
inline std::string turning_markdown(const std::vector<turning_row>& rows, const turning_study_options& o) {
    if (rows.empty()) return "";
    std::string s =
        "## Turning motions\n\n"
        "The first contact of B moving from a random pose near contact (its centroid 0.7 to 1.2 times R_A + R_B "
        "from A's, any angle) by a random step of up to 0.3 times R_A + R_B, turning by up to half a turn "
        "either way, " +
        std::to_string(o.motions) +
        " motions per cell, every method on the same motions, each compared with the exact answer of its own "
        "model: the rational model's (`certified_first_contact` with `turning_model::rational`, exact) and the "
        "angle-linear model's (`certified_first_contact`: conservative advancement decided on exact distances, "
        "contact within 1e-9). `box2d_toi` is Box2D's `b2TimeOfImpact` in float on the angle-linear motion about "
        "B's origin, shapes without skin: it reports a contact where the shapes come within its target "
        "separation (about 0.005 units), so a pass that close counts as an invented contact. `geos_sampled_S` "
        "tests `GEOSPreparedIntersects_r` at the S + 1 times k / S and reports the first that meets. A miss is "
        "a motion whose reference has a contact and the method none; an invention the reverse; Box2D's "
        "`e_failed` is counted apart (as no contact). The time error is the largest |t - T| over the motions "
        "where both report a contact. Times: the median of at least 3 rounds, the methods taking turns within "
        "each round.\n\n";
    std::string current;
    for (const turning_row& r : rows) {
        const std::string cell = turning_cell_name(r.cell);
        if (cell != current) {
            current = cell;
            s += "### " + cell +
                 "\n\n| method | model | contacts | misses | inventions | largest time error | us per motion |\n"
                 "|---|---|---:|---:|---:|---:|---:|\n";
        }
        const std::string failed = r.failed ? " (" + std::to_string(r.failed) + " failed)" : "";
        s += "| " + r.method + (r.reference ? " (reference)" : "") + " | " + r.model + " | " +
             std::to_string(r.contacts) + " of " + std::to_string(r.motions) + " | " + std::to_string(r.misses) +
             failed + " | " + std::to_string(r.inventions) + " | " + general(r.largest_time_error, 3) + " | " +
             fixed(r.us_per_motion(), 2) + " |\n";
        if (&r == &rows.back() || turning_cell_name((&r)[1].cell) != cell) s += "\n";
    }
    return s;
}

}  // namespace influence2d::verification
