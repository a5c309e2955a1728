// SPDX-License-Identifier: BSL-1.0
// `influence2d sweep`: the first contact of the moving polygon along each
// motion between two consecutive poses (continuous collision detection).

#include <cstddef>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "files.hpp"
#include "number_types.hpp"
#include "query_rows.hpp"
#include "report.hpp"
#include "scene_input.hpp"

namespace influence2d::cli {

namespace {

struct sweep_cli_options {
    scene_options scene;
    std::string number_type = default_number_type;
    sweep_options motion;
    std::string out;
};

/// CONTACTS.csv: `motion,contact,t,static_feature,moving_feature`, t and
/// the features empty for a motion without contact; contact `limit` and t
/// where the step limit stopped for a motion left undecided; t with 17
/// significant digits (the double read back is the one written).
std::string sweep_contacts_csv(const std::vector<contact_row>& rows) {
    std::string s = "motion,contact,t,static_feature,moving_feature\n";
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const contact_row& r = rows[k];
        s += std::to_string(k) +
             (r.contact ? ",1," + general(r.t, 17) + "," + feature_text(r.static_feature) + "," +
                              feature_text(r.moving_feature)
              : r.step_limit ? ",limit," + general(r.t, 17) + ",,"
                             : std::string(",0,,,")) +
             "\n";
    }
    return s;
}

void run_sweep(const sweep_cli_options& o) {
    const number_type& type = *find_number_type(o.number_type);  // the option's check has run
    const scene_input in = read_scene(o.scene, o.out);
    if (in.poses.size() < 2)
        throw std::invalid_argument(shown_name(o.scene.poses_path) + ": " + std::to_string(in.poses.size()) + " pose" +
                                    (in.poses.size() == 1 ? "" : "s") +
                                    ": a motion needs two (motion k goes from pose k to pose k + 1)");
    std::vector<contact_row> rows;
    const double seconds = seconds_taken([&] { rows = type.contacts(in.a, in.b, in.poses, o.motion); });
    if (!o.out.empty()) write_output(o.out, sweep_contacts_csv(rows));

    std::size_t contacts = 0, first = 0;
    for (std::size_t k = 0; k < rows.size(); ++k)
        if (rows[k].contact && contacts++ == 0) first = k;
    std::ostream& summary = is_standard_stream(o.out) ? std::cerr : std::cout;
    summary << "motions:         " << rows.size() << "\n"
            << "contacts:        " << contacts << "\n"
            << "first contact:   "
            << (contacts ? "motion " + std::to_string(first) + " at t = " + general(rows[first].t, 17) + " (" +
                               feature_text(rows[first].static_feature) + " of the static polygon, " +
                               feature_text(rows[first].moving_feature) + " of the moving one)"
                         : std::string("none"))
            << "\n"
            << "number type:     " << o.number_type << "\n"
            << "turning motion:  " << (o.motion.model == turning_model::rational ? "rational" : "angle-linear") << "\n"
            << step_limit_line(rows, o.motion.max_steps, "contact")
            << "time per motion: " << fixed(seconds * 1e6 / static_cast<double>(rows.size()), 3) << " us   (total "
            << fixed(seconds * 1e3, seconds * 1e3 >= 1 ? 1 : 3) << " ms)\n";
    if (!o.out.empty()) summary << "contacts written: " << shown_name(o.out, true) << "\n";
}

}  // namespace

void register_sweep(CLI::App& app) {
    auto o = std::make_shared<sweep_cli_options>();
    CLI::App* sub =
        app.add_subcommand("sweep",
                           "First contact along motions: motion k moves the moving polygon from pose k to pose k + 1 "
                           "(translation linear in time; angle linear in time, or the rational model of --motion); "
                           "for each, whether the polygons meet at some time in [0, 1] and the earliest such time, "
                           "with the features that touch first. Exact for translations and for the rational model in "
                           "the exact and certified types; for angle-linear motions that turn, never after the true "
                           "first contact (contact within 1e-9, see docs/sweep.md).");
    add_scene_options(sub, o->scene);
    add_number_type_option(sub, o->number_type);
    add_motion_options(sub, o->motion);
    sub->add_option("--out", o->out,
                    "Write one CSV line per motion (motion,contact,t,static_feature,moving_feature; "
                    "features as v<vertex> or e<edge> in input numbering, or interior) to this file; it "
                    "is replaced only when the whole run succeeds. '-': standard output, and the summary "
                    "goes to standard error")
        ->type_name("CONTACTS.csv");
    sub->callback([o] { run_sweep(*o); });
}

}  // namespace influence2d::cli
