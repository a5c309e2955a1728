// SPDX-License-Identifier: BSL-1.0
// `influence2d study`: the method's decisions and the queries (separation,
// first contact) in every number type against the exact reference
// (verification/study.hpp); writes the tables, a summary and the plots of
// error against run time.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "report.hpp"
#include "verification/study.hpp"
#include "verification/study_advice.hpp"
#include "verification/study_totals.hpp"

namespace influence2d::cli {

namespace {

namespace fs = std::filesystem;
using namespace influence2d::verification;

struct study_cli_options {
    std::vector<std::string> families;
    std::vector<std::string> types;
    std::vector<std::string> decisions;
    std::vector<std::string> queries;  ///< empty: both; "none": neither
    std::vector<std::string> raster;   ///< resolutions; empty: the default ladder; "none": not asked
    std::size_t cases = 3;
    std::size_t frames = 256;
    std::size_t query_frames = study_options{}.query_frames;
    std::uint64_t seed = study_options{}.seed;
    std::string out;
    std::string regressions;  ///< empty: OUT/regressions
    bool quick = false;
    bool progress = false;
};

/// The finest resolution --raster takes: a mask of 16384^2 bits is 32 MiB.
constexpr std::size_t finest_raster = 16384;

/// The sizes of a --quick run, unless given.
constexpr std::size_t quick_cases = 1, quick_frames = 40;

/// Rates are drawn on log axes: a rate of zero is drawn at this floor.
constexpr double rate_floor = 1e-7;
/// The queries' errors likewise: an error of zero (an exact type) is drawn
/// at this floor, below the 113-bit types' errors, and one that is not finite
/// at this ceiling, above every finite one.
constexpr double error_floor = 1e-40, error_ceiling = 1e20;

std::vector<std::string> decision_kind_names() {
    std::vector<std::string> names;
    for (decision_kind k : all_decision_kinds) names.push_back(decision_name(k));
    return names;
}

std::vector<std::string> query_kind_names() {
    std::vector<std::string> names;
    for (query_kind k : all_query_kinds) names.push_back(query_name(k));
    return names;
}

/// The query rows of each number type pooled over the families, for one query.
std::map<std::string, query_tally> query_totals(const study_result& r, const std::string& query) {
    std::map<std::string, query_tally> t;
    for (const query_row& row : r.query_rows)
        if (row.query == query) t[row.number_type].merge(row.tally);
    return t;
}

/// An error as text: "-" when none was measured.
std::string error_text(const std::optional<double>& e) { return e ? general(*e, 3) : "-"; }

std::string study_csv(const study_result& r) {
    std::string s = "number_type,family,decision,cases,disagreements,rate,ns_per_query\n";
    for (const study_row& row : r.rows)
        s += row.number_type + "," + row.family + "," + row.decision + "," + std::to_string(row.tally.cases) + "," +
             std::to_string(row.tally.disagreements) + "," + general(row.tally.rate()) + "," +
             fixed(row.tally.ns_per_query(), 1) + "\n";
    return s;
}

std::string queries_csv(const study_result& r) {
    std::string s =
        "number_type,family,query,questions,differing,meeting_differs,features_differ,values_differ,"
        "measured,largest_error,median_error,ns_per_question\n";
    for (const query_row& row : r.query_rows) {
        const query_tally& t = row.tally;
        s += row.number_type + "," + row.family + "," + row.query + "," + std::to_string(t.questions) + "," +
             std::to_string(t.differing) + "," + std::to_string(t.meeting_differs) + "," +
             std::to_string(t.features_differ) + "," + std::to_string(t.values_differ) + "," +
             std::to_string(t.errors.size()) + "," + (t.largest_error() ? general(*t.largest_error(), 6) : "") + "," +
             (t.median_error() ? general(*t.median_error(), 6) : "") + "," + fixed(t.ns_per_question(), 1) + "\n";
    }
    return s;
}

std::string raster_csv(const study_result& r) {
    std::string s = "resolution,family,questions,missed,invented,rate,ns_per_question\n";
    for (const raster_row& row : r.raster_rows)
        s += std::to_string(row.resolution) + "," + row.family + "," + std::to_string(row.tally.questions) + "," +
             std::to_string(row.tally.missed) + "," + std::to_string(row.tally.invented) + "," +
             general(row.tally.rate()) + "," + fixed(row.tally.ns_per_question(), 1) + "\n";
    return s;
}

/// The image-space baseline's rows pooled over the families, per resolution.
std::map<std::size_t, raster_tally> raster_totals(const study_result& r) {
    std::map<std::size_t, raster_tally> t;
    for (const raster_row& row : r.raster_rows) t[row.resolution].merge(row.tally);
    return t;
}

/// The section on the image-space baseline: per resolution, its share of
/// wrong answers per family, its misses and invented contacts, its time.
std::string raster_md(const study_result& r) {
    if (r.raster_rows.empty()) return "";
    const auto totals = raster_totals(r);
    std::vector<std::string> families;
    for (const std::string& f : r.families)
        if (std::any_of(r.raster_rows.begin(), r.raster_rows.end(), [&](const raster_row& x) { return x.family == f; }))
            families.push_back(f);
    std::string s =
        "## The image-space baseline\n\n"
        "The paper's own comparison (PIVOT2D), on the CPU: both polygons rasterised on a grid of R pixels along "
        "the longer side of A's box, a contact where a pixel centre lies in both (verification/raster.hpp), asked "
        "the `collides` questions of every scene with d = 0 (it has no distance test). A miss is a contact it did "
        "not see (a touch, or an overlap no pixel centre falls in); an invented contact is a pixel centre it "
        "counted in both regions that lies in at most one, by the rounding of B's posing or of the crossings. "
        "The rates are those of the study's poses, aimed at contact (raster.csv has every family).\n\n";
    std::size_t first_right = 0;
    for (const auto& [resolution, t] : totals)
        if (t.wrong() == 0) {
            first_right = resolution;
            break;
        }
    s += first_right ? "The first resolution right on every question was " + std::to_string(first_right) + ".\n\n"
                     : "No resolution was right on every question.\n\n";
    s += "| R |";
    for (const std::string& f : families) s += " " + f + " |";
    s += " questions | missed | invented | rate | ns per question |\n|---:|";
    for (std::size_t i = 0; i < families.size() + 5; ++i) s += "---:|";
    s += "\n";
    for (const auto& [resolution, t] : totals) {
        s += "| " + std::to_string(resolution) + " |";
        for (const std::string& f : families) {
            const auto it = std::find_if(r.raster_rows.begin(), r.raster_rows.end(), [&](const raster_row& x) {
                return x.resolution == resolution && x.family == f;
            });
            s += " " + (it == r.raster_rows.end() ? std::string("-") : percent(it->tally.rate())) + " |";
        }
        s += " " + std::to_string(t.questions) + " | " + std::to_string(t.missed) + " | " + std::to_string(t.invented) +
             " | " + percent(t.rate()) + " | " + fixed(t.ns_per_question(), 1) + " |\n";
    }
    const auto collides = totals_by_type(r, asks_collides);
    std::string beside;
    for (const type_summary& t : r.summaries)
        if (t.claims_exact && collides.count(t.number_type))
            beside += std::string(beside.empty() ? "" : ", ") + t.number_type + " " +
                      fixed(collides.at(t.number_type).ns_per_query(), 1) + " ns";
    if (!beside.empty())
        s += "\nThe types that claim exactness answered every `collides` question of the study (d = 0.5 scenes "
             "included) with no disagreement, per question: " +
             beside + ". The plot raster_error_vs_resolution.svg draws the rate and the time against R.\n";
    return s + "\n";
}

std::string stability_csv(const study_result& r) {
    std::string s = "number_type,sweep,magnitude,cases,disagreements,rate\n";
    for (const stability_row& row : r.stability)
        s += row.number_type + "," + row.sweep + "," + general(row.magnitude) + "," + std::to_string(row.tally.cases) +
             "," + std::to_string(row.tally.disagreements) + "," + general(row.tally.rate()) + "\n";
    return s;
}

/// What a query's error is, for the text.
std::string error_meaning(const std::string& query) {
    return query == "separation" ? "relative error of the distance" : "absolute error of the contact time";
}

/// The paragraph on one query: its fastest type and that type's errors, and
/// the fastest type whose answers never differed.
std::string query_summary(const study_result& r, const std::string& query) {
    const auto totals = query_totals(r, query);
    std::vector<std::string> asked;
    for (const std::string& t : r.types)
        if (totals.count(t) && totals.at(t).questions > 0) asked.push_back(t);
    if (asked.empty()) return "";
    const auto ns = [&](const std::string& t) { return totals.at(t).ns_per_question(); };
    const auto by_time = [&](const std::string& x, const std::string& y) { return ns(x) < ns(y); };
    const std::string fastest = *std::min_element(asked.begin(), asked.end(), by_time);
    const query_tally& f = totals.at(fastest);
    std::string s = "`" + query + "`: the fastest type was " + fastest + ", at " + fixed(ns(fastest), 0) +
                    " ns per question; its answers differed on " + std::to_string(f.differing) + " of " +
                    std::to_string(f.questions) + " questions, its " + error_meaning(query) + " was at most " +
                    error_text(f.largest_error()) + " (median " + error_text(f.median_error()) + ").";
    std::vector<std::string> sound;
    for (const std::string& t : asked)
        if (totals.at(t).differing == 0) sound.push_back(t);
    if (!sound.empty()) {
        const std::string best = *std::min_element(sound.begin(), sound.end(), by_time);
        s += " The fastest type whose answers never differed was " + best + ", at " + fixed(ns(best), 0) + " ns (" +
             general(ns(best) / std::max(ns(fastest), 1e-9), 3) + " times " + fastest + ").";
    }
    for (const type_summary& t : r.summaries)
        if (t.claims_exact && totals.count(t.number_type) && totals.at(t.number_type).differing > 0)
            s += " " + t.number_type + " claims exactness and differed on " +
                 std::to_string(totals.at(t.number_type).differing) +
                 " questions: library bugs, kept as reproducible cases (below).";
    return s + "\n\n";
}

/// The section on the queries: what was asked, then one table per query.
std::string queries_md(const study_result& r, const study_cli_options& o) {
    if (r.query_rows.empty()) return "";
    std::string s = "## Queries: error against time\n\n";
    s += "The separation at a pose (`separation`), the first contact along a translation (`first_contact`) and "
         "along a motion that turns, in the rational model (`turning_rational`) and in the angle-linear one "
         "(`turning_angle_linear`), asked of every type through the library's public API on the first " +
         std::to_string(std::min(o.query_frames, o.frames)) + " poses of each scene" +
         (std::count(r.families.begin(), r.families.end(), "large") ? " (16 on `large`)" : "") +
         ", and on as many translations: toward a pose along the ray from A's centroid through B's, from "
         "R_A + R_B farther out (ending on the pose, near contact); from a pose away along that ray; from one "
         "pose's place to the next pose at its angle. The turning motions are these two rays, turning on the way "
         "by 0.3 to 2.8 radians, and a turn in place from the third pose. The exact answers are "
         "`separation<exact_rational>` and `first_contact<exact_rational>` in the query's model; queries.csv has "
         "every family. The rational model's exact answer is the true first contact of its motion (the time "
         "rounded to the nearest double). The angle-linear model has no exact answer in closed form: its "
         "reference is conservative advancement run in exact rationals (contact when the exact distance is "
         "within the tolerance 1e-9, never after the true first contact), and a type differs when it stops "
         "elsewhere; a floating type stops within its own error bound of the tolerance (8192 units in its last "
         "place times the scene's size; float, coarser than double, and float128, whose precision "
         "std::numeric_limits does not give, take their filters' margin, 4e-4 and 4e-12 times the scene's size, and "
         "stop earlier).\n\n"
         "The floating types and exact answer through `separation_query<NT>` (the polygons prepared once per "
         "scene, not timed) and `first_contact<NT>`; certified and interval through "
         "`certified_separation_query` (the polygons prepared in double words once per scene, not timed; its "
         "exact route prepared on the first question that needs it, inside its time) and "
         "`certified_first_contact`: interval has no route of its own and runs certified's.\n\n"
         "An answer differs when meet or not (contact or not) differs, when the closest (first) features differ, "
         "or, for a type that claims exactness, when its value is not the exact one (exact) or its documented "
         "rounding (certified: `distance_of` the exact squared distance, the exact points and time rounded to "
         "the nearest double). The error is, for the separation, the relative error of the type's distance (the "
         "root of its squared distance, taken exactly) over the questions whose exact distance is positive; for "
         "the first contact, the absolute error of the earliest time over the questions where both touch, but "
         "not both at the start. `inf` is a value that is not finite (a squared distance beyond float's range, a "
         "time whose denominator rounded to 0). A relative error of 1 is a distance given as 0: a floating type's "
         "that says the polygons meet, and certified's on `subnormal` scenes, whose distances lie among "
         "double's subnormals (its distance, a double, then keeps few bits) or below them.\n\n";
    for (query_kind k : all_query_kinds) {
        const std::string query = query_name(k);
        const auto totals = query_totals(r, query);
        if (totals.empty()) continue;
        s += "### " + query + "\n\n" + query_summary(r, query);
        s += std::string("| number type | questions | answers differing | ") +
             (k == query_kind::separation ? "meet differs" : "contact differs") +
             " | features differ | value differs | largest error | median error | ns per question |\n"
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const std::string& t : r.types) {
            if (!totals.count(t)) continue;
            const query_tally& x = totals.at(t);
            s += "| " + t + " | " + std::to_string(x.questions) + " | " + std::to_string(x.differing) + " | " +
                 std::to_string(x.meeting_differs) + " | " + std::to_string(x.features_differ) + " | " +
                 std::to_string(x.values_differ) + " | " + error_text(x.largest_error()) + " | " +
                 error_text(x.median_error()) + " | " + fixed(x.ns_per_question(), 1) + " |\n";
        }
        s += "\n";
    }
    for (const type_summary& t : r.summaries)
        if (t.refused_query_scenes > 0)
            s += t.number_type + " refused the queries of " + std::to_string(t.refused_query_scenes) +
                 " scenes whose coordinates lie beyond its range.\n\n";
    return s;
}

std::string study_md(const study_result& r, const study_cli_options& o) {
    std::string s = "# Precision study\n\n";
    s += "Each decision of the method is evaluated in every number type on the same input doubles and compared "
         "with the exact reference (verification/decisions.hpp): cases are questions (a query point for the cone "
         "decisions, a pose of B for the others), disagreements are answers that differ from the reference, time "
         "is per question, set-up excluded.\n\n";
    s += "Run: " + std::to_string(r.cases) + " scenes (" + std::to_string(o.cases) +
         " per family or sweep magnitude, " + std::to_string(o.frames) + " questions each), seed " +
         std::to_string(o.seed) + ", " + fixed(r.seconds, 1) + " s.\n\n";
    s += "## What this means when choosing a number type\n\n" + number_type_advice(r) + "\n";

    for (decision_kind k : all_decision_kinds) {
        const std::string name = decision_name(k);
        if (std::none_of(r.rows.begin(), r.rows.end(), [&](const study_row& row) { return row.decision == name; }))
            continue;  // not asked in this run
        s += "## " + name + "\n\n| number type |";
        for (const std::string& f : r.families) s += " " + f + " |";
        s += " questions | disagreements | rate | ns per question |\n|---|";
        for (std::size_t i = 0; i < r.families.size() + 4; ++i) s += "---:|";
        s += "\n";
        const auto sum = totals_by_type(r, [&](const study_row& row) { return row.decision == name; });
        for (const std::string& t : r.types) {
            s += "| " + t + " |";
            for (const std::string& f : r.families) {
                const auto it = std::find_if(r.rows.begin(), r.rows.end(), [&](const study_row& row) {
                    return row.number_type == t && row.family == f && row.decision == name;
                });
                s += " " + (it == r.rows.end() ? std::string("-") : percent(it->tally.rate())) + " |";
            }
            const decision_tally& x = sum.count(t) ? sum.at(t) : decision_tally{};
            s += " " + std::to_string(x.cases) + " | " + std::to_string(x.disagreements) + " | " + percent(x.rate()) +
                 " | " + fixed(x.ns_per_query(), 1) + " |\n";
        }
        s += "\n";
    }

    s += raster_md(r);
    s += queries_md(r, o);

    if (!r.stability.empty()) {
        s += "## Stability: offset and scale sweeps\n\nEvery decision of a magnitude pooled (stability.csv).\n\n";
        s += "| sweep | magnitude |";
        for (const std::string& t : r.types) s += " " + t + " |";
        s += "\n|---|---:|";
        for (std::size_t i = 0; i < r.types.size(); ++i) s += "---:|";
        s += "\n";
        std::map<std::pair<std::string, double>, std::map<std::string, double>> grid;
        for (const stability_row& row : r.stability)
            grid[{row.sweep, row.magnitude}][row.number_type] = row.tally.rate();
        for (const auto& [key, rates] : grid) {
            s += "| " + key.first + " | " + general(key.second) + " |";
            for (const std::string& t : r.types) s += " " + (rates.count(t) ? percent(rates.at(t)) : "-") + " |";
            s += "\n";
        }
        s += "\n";
    }

    s += "## Exact fallbacks\n\n"
         "| number type | questions | answered by the fallback | scenes set up in the fallback |\n"
         "|---|---:|---:|---:|\n";
    for (const type_summary& t : r.summaries)
        if (t.has_fallback)
            s += "| " + t.number_type + " | " + std::to_string(t.questions) + " | " + std::to_string(t.fallbacks) +
                 " | " + std::to_string(t.setup_fallbacks) + " |\n";
    s += "\nA scene set up in the fallback is one whose static polygon the type itself could not cover (a covering "
         "sign it could not certify, as for an edge collinear with the centroid); every question of that scene was "
         "answered in the fallback type.\n\n";

    for (const type_summary& t : r.summaries)
        if (t.refused_scenes > 0)
            s += t.number_type + " refused " + std::to_string(t.refused_scenes) +
                 " scenes whose coordinates lie beyond its range; their questions are not in its rows.\n\n";

    s += "## Worst examples\n\nThe first disagreements of each type and decision or query.\n\n";
    if (r.examples.empty()) s += "None.\n";
    for (const study_example& e : r.examples)
        s += "- " + e.number_type + ", " + e.decision + ", " + e.family + " (" + e.scene + "), " + e.question +
             ": got " + e.got + ", exact " + e.expected + "\n";
    s += "\n## Reproducible cases\n\n";
    if (r.regressions.empty()) s += "No type that claims exactness disagreed with the reference.\n";
    for (const std::string& f : r.regressions) s += "- `" + f + "`\n";
    return s;
}

/// A gnuplot data block: one line per entry.
std::string data_block(const std::string& name, const std::vector<std::string>& lines) {
    std::string s = "$" + name + " << EOD\n";
    for (const std::string& l : lines) s += l + "\n";
    return s + "EOD\n";
}

std::string shown_rate(double rate) { return general(std::max(rate, rate_floor), 6); }

std::string plot_script(const study_result& r, const fs::path& dir) {
    std::string s =
        "set terminal svg size 900,600 dynamic enhanced font 'sans,12' background '#ffffff'\n"
        "set logscale xy\nset grid\n"
        "set format x '10^{%L}'\nset format y '10^{%L}'\n"
        "set ylabel 'disagreement rate with the exact reference'\n"
        "set arrow 1 from graph 0, first " +
        general(rate_floor) + " to graph 1, first " + general(rate_floor) +
        " nohead dashtype 2\n"
        "set label 1 'no disagreement (drawn at 10^{-7})' at graph 0.02, first " +
        general(rate_floor * 1.6) + "\n";
    std::vector<std::string> collides, predicates;
    const auto c = totals_by_type(r, asks_collides), p = totals_by_type(r, asks_predicate);
    const auto entry = [](const std::string& t, const decision_tally& x) {
        return "\"" + t + "\" " + general(x.ns_per_query()) + " " + shown_rate(x.rate());
    };
    for (const std::string& t : r.types) {
        if (c.count(t)) collides.push_back(entry(t, c.at(t)));
        if (p.count(t)) predicates.push_back(entry(t, p.at(t)));
    }
    s += data_block("collides", collides) + data_block("predicates", predicates);
    std::vector<std::string> rasters;
    for (const auto& [resolution, t] : raster_totals(r))
        rasters.push_back("\"R " + std::to_string(resolution) + "\" " + general(t.ns_per_question()) + " " +
                          shown_rate(t.rate()));
    if (!rasters.empty()) s += data_block("rasters", rasters);
    s += "set key top right\nset output '" + (dir / "error_vs_time.svg").string() +
         "'\n"
         "set title 'Error against run time, per number type'\n"
         "set xlabel 'nanoseconds per question (log scale)'\n"
         "set yrange [" +
         general(rate_floor / 3) +
         ":2]\n"
         "plot $collides using 2:3 with points pointtype 7 pointsize 1.5 title 'collides (final answer)', "
         "$collides using 2:3:1 with labels rotate by 35 left offset char 0.6,0.6 notitle, "
         "$predicates using 2:3 with points pointtype 5 pointsize 1.5 title 'predicates (pooled)', "
         "$predicates using 2:3:1 with labels rotate by -35 left offset char 0.6,-0.6 notitle" +
         (rasters.empty()
              ? std::string()
              : ", $rasters using 2:3 with linespoints pointtype 9 pointsize 1.2 title 'image-space baseline "
                "(collides, d = 0), R pixels', $rasters using 2:3:1 with labels left offset char 0.6,0 "
                "notitle") +
         "\n";
    for (const char* sweep : {"offset", "scale"}) {
        std::string plot;
        for (std::size_t i = 0; i < r.types.size(); ++i) {
            std::vector<std::string> lines;
            for (const stability_row& row : r.stability)
                if (row.sweep == sweep && row.number_type == r.types[i])
                    lines.push_back(general(row.magnitude, 17) + " " + shown_rate(row.tally.rate()));
            if (lines.empty()) continue;
            const std::string block = std::string(sweep) + "_" + std::to_string(i);
            s += data_block(block, lines);
            plot += std::string(plot.empty() ? "plot " : ", ") + "$" + block +
                    " using 1:2 with linespoints linewidth 2 title '" + r.types[i] + "'";
        }
        if (plot.empty()) continue;
        s += "set key outside right top\nset output '" + (dir / ("stability_" + std::string(sweep) + ".svg")).string() +
             "'\n";
        s += std::string("set title 'Error rate against the ") + sweep + " magnitude'\n";
        s += std::string("set xlabel '") + sweep + " magnitude (log scale)'\nset yrange [" + general(rate_floor / 3) +
             ":2]\n" + plot + "\n";
    }
    return s;
}

std::string shown_error(const std::optional<double>& e) {
    return general(std::min(std::max(*e, error_floor), error_ceiling), 6);
}

/// The plot of the queries: per query and number type, the largest and the
/// median error against the time per question.
std::string query_plot_script(const study_result& r, const fs::path& dir) {
    std::string s, plot;
    for (query_kind k : all_query_kinds) {
        const std::string query = query_name(k);
        const auto totals = query_totals(r, query);
        std::vector<std::string> lines;
        for (const std::string& t : r.types) {
            if (!totals.count(t) || !totals.at(t).largest_error()) continue;
            const query_tally& x = totals.at(t);
            lines.push_back("\"" + t + "\" " + general(x.ns_per_question()) + " " + shown_error(x.largest_error()) +
                            " " + shown_error(x.median_error()));
        }
        if (lines.empty()) continue;
        s += data_block(query, lines);
        // Filled and open points of one shape per query: circles, squares,
        // triangles, diamonds.
        const std::size_t shape = static_cast<std::size_t>(k);
        const char* const filled[] = {"7", "5", "9", "13"};
        const char* const open[] = {"6", "4", "8", "12"};
        const std::string title = k == query_kind::separation         ? "separation"
                                  : k == query_kind::first_contact    ? "first contact (translation)"
                                  : k == query_kind::turning_rational ? "first contact (rational turn)"
                                                                      : "first contact (angle-linear turn)";
        plot += std::string(plot.empty() ? "plot " : ", ") + "$" + query + " using 2:3 with points pointtype " +
                filled[shape] + " pointsize 1.5 title '" + title + ": largest error', $" + query +
                " using 2:3:1 with labels rotate by 35 left offset char 0.6,0.6 notitle, $" + query +
                " using 2:4 with points pointtype " + open[shape] + " pointsize 1.5 title '" + title +
                ": median error'";
    }
    if (plot.empty()) return "";
    return "set terminal svg size 900,600 dynamic enhanced font 'sans,12' background '#ffffff'\n"
           "set logscale xy\nset grid\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
           "set key right center\nset output '" +
           (dir / "queries_error_vs_time.svg").string() +
           "'\n"
           "set title 'Queries: error against run time, per number type'\n"
           "set xlabel 'nanoseconds per question (log scale)'\n"
           "set ylabel 'separation: relative error of the distance; first contact: absolute error of the time'\n"
           "set yrange [" +
           general(error_floor / 1e3) + ":" + general(error_ceiling * 1e3) +
           "]\n"
           "set arrow 1 from graph 0, first " +
           general(error_floor) + " to graph 1, first " + general(error_floor) +
           " nohead dashtype 2\n"
           "set label 1 'no error (drawn at 10^{-40})' at graph 0.02, first " +
           general(error_floor * 10) +
           "\n"
           "set arrow 2 from graph 0, first " +
           general(error_ceiling) + " to graph 1, first " + general(error_ceiling) +
           " nohead dashtype 2\n"
           "set label 2 'not finite (drawn at 10^{20})' at graph 0.3, first " +
           general(error_ceiling * 10) + "\n" + s + plot + "\n";
}

/// The plot of the image-space baseline: its rate of wrong answers and its
/// time per question against the resolution.
std::string raster_plot_script(const study_result& r, const fs::path& dir) {
    std::vector<std::string> lines;
    for (const auto& [resolution, t] : raster_totals(r))
        lines.push_back(std::to_string(resolution) + " " + shown_rate(t.rate()) + " " + general(t.ns_per_question()));
    if (lines.empty()) return "";
    return "set terminal svg size 900,600 dynamic enhanced font 'sans,12' background '#ffffff'\n"
           "unset arrow\nunset label\nset autoscale\n"
           "set logscale x 2\nset logscale y\nset logscale y2\nset grid\n"
           "set format x '%g'\nset format y '10^{%L}'\nset format y2 '10^{%L}'\n"
           "set ytics nomirror\nset y2tics\nset key top center\nset output '" +
           (dir / "raster_error_vs_resolution.svg").string() +
           "'\n"
           "set title 'The image-space baseline: error and time against resolution'\n"
           "set xlabel 'pixels along the longer side of A''s box (log scale)'\n"
           "set ylabel 'share of collides questions answered wrongly'\n"
           "set y2label 'nanoseconds per question'\n"
           "set yrange [" +
           general(rate_floor / 3) + ":2]\n" + data_block("raster", lines) +
           "plot $raster using 1:2 axes x1y1 with linespoints pointtype 7 pointsize 1.5 linewidth 2 title 'wrong "
           "answers (0 drawn at 10^{-7})', $raster using 1:3 axes x1y2 with linespoints pointtype 5 pointsize 1.5 "
           "linewidth 2 dashtype 2 title 'time per question'\n";
}

/// Writes the plots with gnuplot (plots.gp in the output directory).
void write_plots(const study_result& r, const fs::path& dir) {
    plot_with_gnuplot(dir / "plots.gp", plot_script(r, dir) + query_plot_script(r, dir) + raster_plot_script(r, dir),
                      "study");
}

void run_study_command(study_cli_options o, bool cases_given, bool frames_given) {
    if (o.quick) {
        if (!cases_given) o.cases = quick_cases;
        if (!frames_given) o.frames = quick_frames;
    }
    study_options so;
    check_names(o.families, study_family_names(), "families");
    check_names(o.types, mode_names(study_modes{}), "types");
    so.families = o.families.empty() ? default_study_families() : o.families;
    so.types = o.types;
    check_names(o.decisions, decision_kind_names(), "decisions");
    for (const std::string& d : o.decisions) so.decisions.push_back(*decision_from_name(d));
    if (o.queries == std::vector<std::string>{"none"}) {
        so.queries.clear();
    } else if (!o.queries.empty()) {
        check_names(o.queries, query_kind_names(), "queries");
        so.queries.clear();
        for (const std::string& q : o.queries) so.queries.push_back(*query_from_name(q));
    }
    if (o.raster == std::vector<std::string>{"none"}) {
        so.raster_resolutions.clear();
    } else if (!o.raster.empty()) {
        so.raster_resolutions.clear();
        for (const std::string& text : o.raster) {
            std::size_t used = 0;
            unsigned long long v = 0;
            try {
                v = std::stoull(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != text.size() || text.empty() || text[0] == '-' || v < 1 || v > finest_raster)
                throw std::invalid_argument("--raster: '" + text + "' is not a resolution from 1 to " +
                                            std::to_string(finest_raster) + " (or none)");
            so.raster_resolutions.push_back(static_cast<std::size_t>(v));
        }
        std::sort(so.raster_resolutions.begin(), so.raster_resolutions.end());
        so.raster_resolutions.erase(std::unique(so.raster_resolutions.begin(), so.raster_resolutions.end()),
                                    so.raster_resolutions.end());
    }
    so.query_frames = o.query_frames;
    so.cases = o.cases;
    so.frames = o.frames;
    so.seed = o.seed;
    if (is_standard_stream(o.regressions))
        throw std::invalid_argument(
            "--regressions -: reproducible cases are files in a directory, which standard "
            "output cannot hold; name a directory");
    const fs::path dir = output_directory(o.out);
    if (o.regressions.empty()) o.regressions = (dir / "regressions").string();
    so.regressions_dir = o.regressions;
    if (auto report = progress_reporter(o.progress)) {
        so.progress = [report](const study_progress& p) {
            const bool done = p.family == p.families;
            report(done ? "study: " + std::to_string(p.families) + " families done"
                        : "study: family " + std::to_string(p.family + 1) + "/" + std::to_string(p.families) + " (" +
                              p.name + "), scene " + std::to_string(p.scene + 1) + "/" + std::to_string(p.scenes),
                   done, p.scene == 0);
        };
    }
    const study_result r = run_study(so);
    write_atomically(dir / "study.csv", study_csv(r));
    write_atomically(dir / "stability.csv", stability_csv(r));
    write_atomically(dir / "queries.csv", queries_csv(r));
    write_atomically(dir / "raster.csv", raster_csv(r));
    write_atomically(dir / "study.md", study_md(r, o));
    write_plots(r, dir);

    const auto collides = totals_by_type(r, asks_collides);
    std::cout << "study: " << r.cases << " scenes in " << fixed(r.seconds, 1) << " s; collides per number type:\n";
    for (const std::string& t : r.types)
        if (collides.count(t))
            std::cout << "  " << t << ": " << collides.at(t).disagreements << " of " << collides.at(t).cases
                      << " frames differ (" << percent(collides.at(t).rate()) << "), "
                      << fixed(collides.at(t).ns_per_query(), 1) << " ns per frame\n";
    for (query_kind k : all_query_kinds) {
        const auto totals = query_totals(r, query_name(k));
        if (totals.empty()) continue;
        std::cout << "study: " << query_name(k) << " per number type (" << error_meaning(query_name(k)) << "):\n";
        for (const std::string& t : r.types)
            if (totals.count(t))
                std::cout << "  " << t << ": " << totals.at(t).differing << " of " << totals.at(t).questions
                          << " answers differ, largest error " << error_text(totals.at(t).largest_error()) << ", "
                          << fixed(totals.at(t).ns_per_question(), 1) << " ns per question\n";
    }
    if (!r.regressions.empty())
        std::cout << "study: " << r.regressions.size()
                  << " disagreements of types that claim exactness, written as reproducible cases to " << o.regressions
                  << " (listed in study.md)\n";
    std::cout << "written: " << (dir / "study.csv").string() << ", " << (dir / "stability.csv").string() << ", "
              << (dir / "queries.csv").string() << ", " << (dir / "raster.csv").string() << ", "
              << (dir / "study.md").string() << "\n";
}

}  // namespace

void register_study(CLI::App& app) {
    auto o = std::make_shared<study_cli_options>();
    CLI::App* sub = app.add_subcommand(
        "study",
        "Compare the method's decisions (cone membership, mask, alpha-sign selection, extended-area candidates, "
        "edge pairs, containment, the final answer) and the queries (separation, first contact along a "
        "translation and along turning motions in both turning models) in every number type, and the final answer in "
        "the image-space baseline, with the exact "
        "reference, and report error against run time: "
        "DIR/study.csv, DIR/stability.csv, DIR/queries.csv, DIR/raster.csv, DIR/study.md and plots (with gnuplot).");
    const std::string family_list = joined(default_study_families()), type_list = joined(mode_names(study_modes{}));
    std::vector<std::string> resolutions;
    for (std::size_t r : default_raster_resolutions()) resolutions.push_back(std::to_string(r));
    const std::string raster_list = joined(resolutions);
    sub->add_option("--families", o->families,
                    "Case families, separated by commas [default: " + family_list +
                        "; also: large, a static polygon of over 100,000 vertices, slow]")
        ->delimiter(',')
        ->type_name("LIST");
    sub->add_option("--types", o->types, "Number types, separated by commas [default: " + type_list + "]")
        ->delimiter(',')
        ->type_name("LIST");
    const std::string decision_list = joined(decision_kind_names());
    sub->add_option("--decisions", o->decisions, "Decision kinds, separated by commas [default: " + decision_list + "]")
        ->delimiter(',')
        ->type_name("LIST");
    sub->add_option("--queries", o->queries,
                    "Queries, separated by commas, or none [default: " + joined(query_kind_names()) + "]")
        ->delimiter(',')
        ->type_name("LIST");
    sub->add_option("--raster", o->raster,
                    "Resolutions of the image-space baseline asked the collides questions, separated by commas, or "
                    "none [default: " +
                        raster_list + "]")
        ->delimiter(',')
        ->type_name("LIST");
    sub->add_option("--query-frames", o->query_frames,
                    "Questions per scene for each query (at most --frames; 16 on large)")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 32))
        ->type_name("N");
    CLI::Option* cases = sub->add_option("--cases", o->cases, "Scenes per family (per magnitude for the sweeps)")
                             ->capture_default_str()
                             ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 30))
                             ->type_name("N");
    CLI::Option* frames = sub->add_option("--frames", o->frames, "Poses of B (and query points) per scene")
                              ->capture_default_str()
                              ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 32))
                              ->type_name("N");
    sub->add_option("--seed", o->seed, "Seed of the shapes, poses and points")->capture_default_str()->type_name("S");
    sub->add_option("--out", o->out, "Output directory, created if missing")->required()->type_name("DIR");
    sub->add_option("--regressions", o->regressions,
                    "Where a disagreement of a type that claims exactness is written as a reproducible case "
                    "[default: OUT/regressions; the tests replay the cases in data/regressions of the source tree]")
        ->type_name("DIR");
    sub->add_flag("--quick", o->quick,
                  "A short run (" + std::to_string(quick_cases) + " scene per family, " + std::to_string(quick_frames) +
                      " questions each, unless --cases or --frames say otherwise)");
    sub->add_flag("--progress", o->progress, "Report progress on stderr even when it is not a terminal");
    sub->callback([o, cases, frames] { run_study_command(*o, cases->count() > 0, frames->count() > 0); });
}

}  // namespace influence2d::cli
