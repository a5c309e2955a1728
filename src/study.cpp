// SPDX-License-Identifier: BSL-1.0
// `influence2d study`: the method's decisions in every number type against the
// exact reference (verification/study.hpp); writes the tables, a summary and
// the plots of error against run time.

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

namespace influence2d::cli {

namespace {

namespace fs = std::filesystem;
using namespace influence2d::verification;

struct study_cli_options {
    std::vector<std::string> families;
    std::vector<std::string> types;
    std::vector<std::string> decisions;
    std::size_t cases = 3;
    std::size_t frames = 256;
    std::uint64_t seed = study_options{}.seed;
    std::string out;
    std::string regressions;  ///< empty: OUT/regressions
    bool quick = false;
    bool progress = false;
};

/// The sizes of a --quick run, unless given.
constexpr std::size_t quick_cases = 1, quick_frames = 40;

/// Rates are drawn on log axes: a rate of zero is drawn at this floor.
constexpr double rate_floor = 1e-7;

std::vector<std::string> decision_kind_names() {
    std::vector<std::string> names;
    for (decision_kind k : all_decision_kinds) names.push_back(decision_name(k));
    return names;
}

std::string percent(double rate) {
    if (rate == 0) return "0";
    return general(100 * rate, 3) + "%";
}


/// Sums of the rows that pass `keep`, per number type.
template <class Keep>
std::map<std::string, decision_tally> totals(const study_result& r, Keep keep) {
    std::map<std::string, decision_tally> t;
    for (const study_row& row : r.rows) {
        if (!keep(row)) continue;
        decision_tally& s = t[row.number_type];
        s.cases += row.tally.cases;
        s.disagreements += row.tally.disagreements;
        s.nanoseconds += row.tally.nanoseconds;
    }
    return t;
}

bool is_collides(const study_row& row) { return row.decision == "collides"; }
bool is_predicate(const study_row& row) { return row.decision != "collides" && row.decision != "collides_brute_force"; }

std::string study_csv(const study_result& r) {
    std::string s = "number_type,family,decision,cases,disagreements,rate,ns_per_query\n";
    for (const study_row& row : r.rows)
        s += row.number_type + "," + row.family + "," + row.decision + "," + std::to_string(row.tally.cases) + "," +
             std::to_string(row.tally.disagreements) + "," + general(row.tally.rate()) + "," +
             fixed(row.tally.ns_per_query(), 1) + "\n";
    return s;
}

std::string stability_csv(const study_result& r) {
    std::string s = "number_type,sweep,magnitude,cases,disagreements,rate\n";
    for (const stability_row& row : r.stability)
        s += row.number_type + "," + row.sweep + "," + general(row.magnitude) + "," + std::to_string(row.tally.cases) +
             "," + std::to_string(row.tally.disagreements) + "," + general(row.tally.rate()) + "\n";
    return s;
}

/// The paragraph on choosing a number type, from the totals of the run.
std::string advice(const study_result& r) {
    const auto collides = totals(r, is_collides);
    const auto predicates = totals(r, is_predicate);
    const auto all = totals(r, [](const study_row&) { return true; });
    const auto ns = [&](const std::string& t) { return collides.at(t).ns_per_query(); };
    std::vector<const type_summary*> asked;
    for (const type_summary& t : r.summaries)
        if (collides.count(t.number_type) && collides.at(t.number_type).cases > 0) asked.push_back(&t);
    if (asked.empty()) return "No collision question was asked in this run.\n";
    const type_summary* fastest = *std::min_element(asked.begin(), asked.end(), [&](auto* x, auto* y) {
        return ns(x->number_type) < ns(y->number_type);
    });
    const auto times = [&](const std::string& t) {
        return general(ns(t) / std::max(ns(fastest->number_type), 1e-9), 3) + " times " + fastest->number_type;
    };
    const decision_tally& f = collides.at(fastest->number_type);
    std::string s = "For the final answer (collides) the fastest type was " + fastest->number_type + ", at " +
                    fixed(f.ns_per_query(), 0) + " ns per frame; it answered " + std::to_string(f.disagreements) +
                    " of " + std::to_string(f.cases) + " frames wrongly (" + percent(f.rate()) + ").";
    std::string sound_floats;
    for (const type_summary* t : asked) {
        if (t == fastest || t->claims_exact) continue;
        const decision_tally& c = collides.at(t->number_type);
        s += " " + t->number_type + ": " + percent(c.rate()) + " wrong at " + fixed(c.ns_per_query(), 0) + " ns (" +
             times(t->number_type) + ").";
        if (c.disagreements == 0)
            sound_floats += (sound_floats.empty() ? "" : ", ") + t->number_type + " (" +
                            percent(predicates.at(t->number_type).rate()) + ")";
    }
    if (!sound_floats.empty())
        s += " The floating types with no wrong final answer in this run are still not exact: their predicates "
             "disagreed with the reference on a share of the questions: " + sound_floats +
             "; more precision moves the cliff closer to contact, it does not remove it.";
    const type_summary* fastest_exact = nullptr;
    for (const type_summary* t : asked) {
        if (!t->claims_exact) continue;
        const decision_tally& a = all.at(t->number_type);
        s += " " + t->number_type + " (claims exactness): " + fixed(ns(t->number_type), 0) + " ns per frame (" +
             times(t->number_type) + ")";
        if (t->fallbacks > 0)
            s += ", " + percent(static_cast<double>(t->fallbacks) / static_cast<double>(t->questions)) +
                 " of its questions answered in its exact fallback";
        s += a.disagreements == 0 ? ", no disagreement."
                                  : ", " + std::to_string(a.disagreements) +
                                        " disagreements: library bugs, kept as reproducible cases (below).";
        if (a.disagreements == 0 && (!fastest_exact || ns(t->number_type) < ns(fastest_exact->number_type)))
            fastest_exact = t;
    }
    if (fastest_exact)
        s += " The fastest type with no disagreement on any decision was " + fastest_exact->number_type + ".";
    s += " The inputs are aimed at the precision cliff (contacts within ulps, points on cone boundaries, extreme "
         "offsets and scales), so the rates are those of near-degenerate work, far above those of typical frames; "
         "a filtered type's cost grows with the share of such inputs. Choose a floating type where a wrong answer "
         "within rounding of contact is acceptable, and the fastest type without disagreement where it is not.";
    return s + "\n";
}

std::string study_md(const study_result& r, const study_cli_options& o) {
    std::string s = "# Precision study\n\n";
    s += "Each decision of the method is evaluated in every number type on the same input doubles and compared "
         "with the exact reference (verification/decisions.hpp): cases are questions (a query point for the cone "
         "decisions, a pose of B for the others), disagreements are answers that differ from the reference, time "
         "is per question, set-up excluded.\n\n";
    s += "Run: " + std::to_string(r.cases) + " scenes (" + std::to_string(o.cases) +
         " per family or sweep magnitude, " +
         std::to_string(o.frames) + " questions each), seed " + std::to_string(o.seed) + ", " +
         fixed(r.seconds, 1) + " s.\n\n";
    s += "## What this means when choosing a number type\n\n" + advice(r) + "\n";

    for (decision_kind k : all_decision_kinds) {
        const std::string name = decision_name(k);
        if (std::none_of(r.rows.begin(), r.rows.end(), [&](const study_row& row) { return row.decision == name; }))
            continue;  // not asked in this run
        s += "## " + name + "\n\n| number type |";
        for (const std::string& f : r.families) s += " " + f + " |";
        s += " questions | disagreements | rate | ns per question |\n|---|";
        for (std::size_t i = 0; i < r.families.size() + 4; ++i) s += "---:|";
        s += "\n";
        const auto sum = totals(r, [&](const study_row& row) { return row.decision == name; });
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

    s += "## Worst examples\n\nThe first disagreements of each type and decision.\n\n";
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
    std::string s = "set terminal svg size 900,600 dynamic enhanced font 'sans,12' background '#ffffff'\n"
                    "set logscale xy\nset grid\n"
                    "set format x '10^{%L}'\nset format y '10^{%L}'\n"
                    "set ylabel 'disagreement rate with the exact reference'\n"
                    "set arrow 1 from graph 0, first " + general(rate_floor) + " to graph 1, first " +
                    general(rate_floor) + " nohead dashtype 2\n"
                    "set label 1 'no disagreement (drawn at 10^{-7})' at graph 0.02, first " +
                    general(rate_floor * 1.6) + "\n";
    std::vector<std::string> collides, predicates;
    const auto c = totals(r, is_collides), p = totals(r, is_predicate);
    const auto entry = [](const std::string& t, const decision_tally& x) {
        return "\"" + t + "\" " + general(x.ns_per_query()) + " " + shown_rate(x.rate());
    };
    for (const std::string& t : r.types) {
        if (c.count(t)) collides.push_back(entry(t, c.at(t)));
        if (p.count(t)) predicates.push_back(entry(t, p.at(t)));
    }
    s += data_block("collides", collides) + data_block("predicates", predicates);
    s += "set key top right\nset output '" + (dir / "error_vs_time.svg").string() + "'\n"
         "set title 'Error against run time, per number type'\n"
         "set xlabel 'nanoseconds per question (log scale)'\n"
         "set yrange [" + general(rate_floor / 3) + ":2]\n"
         "plot $collides using 2:3 with points pointtype 7 pointsize 1.5 title 'collides (final answer)', "
         "$collides using 2:3:1 with labels rotate by 35 left offset char 0.6,0.6 notitle, "
         "$predicates using 2:3 with points pointtype 5 pointsize 1.5 title 'predicates (pooled)', "
         "$predicates using 2:3:1 with labels rotate by -35 left offset char 0.6,-0.6 notitle\n";
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

/// Writes the plots with gnuplot (plots.gp in the output directory).
void write_plots(const study_result& r, const fs::path& dir) { plot_with_gnuplot(dir / "plots.gp", plot_script(r, dir), "study"); }

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
    so.cases = o.cases;
    so.frames = o.frames;
    so.seed = o.seed;
    if (is_standard_stream(o.regressions))
        throw std::invalid_argument("--regressions -: reproducible cases are files in a directory, which standard "
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
    write_atomically(dir / "study.md", study_md(r, o));
    write_plots(r, dir);

    const auto collides = totals(r, is_collides);
    std::cout << "study: " << r.cases << " scenes in " << fixed(r.seconds, 1) << " s; collides per number type:\n";
    for (const std::string& t : r.types)
        if (collides.count(t))
            std::cout << "  " << t << ": " << collides.at(t).disagreements << " of " << collides.at(t).cases
                      << " frames differ (" << percent(collides.at(t).rate()) << "), "
                      << fixed(collides.at(t).ns_per_query(), 1) << " ns per frame\n";
    if (!r.regressions.empty())
        std::cout << "study: " << r.regressions.size()
                  << " disagreements of types that claim exactness, written as reproducible cases to " << o.regressions
                  << " (listed in study.md)\n";
    std::cout << "written: " << (dir / "study.csv").string() << ", " << (dir / "stability.csv").string() << ", "
              << (dir / "study.md").string() << "\n";
}

}  // namespace

void register_study(CLI::App& app) {
    auto o = std::make_shared<study_cli_options>();
    CLI::App* sub = app.add_subcommand(
        "study",
        "Compare the method's decisions (cone membership, mask, alpha-sign selection, extended-area candidates, "
        "edge pairs, containment, the final answer) in every number type with the exact reference, and report "
        "error against run time: DIR/study.csv, DIR/stability.csv, DIR/study.md and plots (with gnuplot).");
    const std::string family_list = joined(default_study_families()), type_list = joined(mode_names(study_modes{}));
    sub->add_option("--families", o->families, "Case families, separated by commas [default: " + family_list +
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
