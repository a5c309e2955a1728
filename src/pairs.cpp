// SPDX-License-Identifier: BSL-1.0
// `influence2d pairs`: which polygons of a layer meet each other, or which
// of one layer meet which of another (a spatial join), all at their own
// coordinates.

#include <cstddef>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "files.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/exact/certified_world.hpp"
#include "influence2d/query/batch.hpp"
#include "influence2d/world/layer_pairs.hpp"
#include "number_types.hpp"
#include "report.hpp"
#include "scene_input.hpp"
#include "world_input.hpp"

namespace influence2d::cli {

namespace {

struct pairs_cli_options {
    std::string layer_path;
    std::string other_path;  ///< empty: pairs within the one layer
    std::string number_type = default_number_type;
    std::string out;
    double within = 0;
    unsigned threads = 1;  ///< 0: every hardware thread
};

/// Both layers (the second empty without --other), read with every problem
/// reported at once, and the output path checked.
struct pairs_inputs {
    polygon_lines layer, other;
};

pairs_inputs read_pairs_inputs(const pairs_cli_options& o) {
    check_one_standard_input({{"--layer", o.layer_path}, {"--other", o.other_path}});
    pairs_inputs in;
    std::vector<std::string> errors;
    const auto attempt = [&errors](auto&& read) {
        try {
            read();
        } catch (const invalid_input& e) {
            errors.emplace_back(e.what());
        }
    };
    attempt([&] { in.layer = read_polygon_lines(o.layer_path); });
    if (!o.other_path.empty()) attempt([&] { in.other = read_polygon_lines(o.other_path); });
    if (!o.out.empty()) {
        const std::string why = check_output_path(o.out);
        if (!why.empty()) errors.push_back(why);
    }
    if (!errors.empty()) {
        std::string all = errors.front();
        for (std::size_t i = 1; i < errors.size(); ++i) all += "\n" + errors[i];
        throw invalid_input(all);
    }
    return in;
}

/// PAIRS.csv: `a,b`, sorted.
std::string pairs_csv(const std::vector<body_pair>& pairs) {
    std::string s = "a,b\n";
    for (const body_pair& p : pairs) s += std::to_string(p.first) + "," + std::to_string(p.second) + "\n";
    return s;
}

void run_pairs(const pairs_cli_options& o) {
    // The type first: a type the join does not run in is refused before
    // any input is read.
    with_world_number_type(o.number_type, "pairs", [&](auto nt, auto exact) {
        using NT = typename decltype(nt)::type;
        using Exact = typename decltype(exact)::type;
        const pairs_inputs in = read_pairs_inputs(o);
        check_polygon_lines<NT>(in.layer, o.layer_path);
        const bool two = !o.other_path.empty();
        if (two) check_polygon_lines<NT>(in.other, o.other_path);
        // layer_pairs<certified, exact_rational> is certified_layer_pairs.
        std::vector<body_pair> pairs;
        layer_statistics work;
        const double seconds = seconds_taken([&] {
            pairs = two ? layer_pairs<NT, Exact>(in.layer.polygons, in.other.polygons, o.within, o.threads, &work)
                        : layer_pairs<NT, Exact>(in.layer.polygons, o.within, o.threads, &work);
        });
        if (!o.out.empty()) write_output(o.out, pairs_csv(pairs));

        std::ostream& summary = is_standard_stream(o.out) ? std::cerr : std::cout;
        summary << "polygons:      " << in.layer.polygons.size();
        if (two) summary << " and " << in.other.polygons.size();
        summary << "\n"
                << "pairs:         " << pairs.size() << "\n"
                << "candidates:    " << work.candidates << " (again in exact rationals " << work.exact_pairs << ")\n"
                << "broad phase:   " << (work.swept ? "the boxes sorted and swept along x" : "box trees") << "\n"
                << "number type:   " << o.number_type << "\n"
                << "threads:       " << batch_threads(o.threads) << "\n"
                << "time: " << fixed(seconds * 1e3, 3) << " ms\n";
        if (!o.out.empty()) summary << "pairs written: " << shown_name(o.out, true) << "\n";
    });
}

}  // namespace

void register_pairs(CLI::App& app) {
    auto o = std::make_shared<pairs_cli_options>();
    CLI::App* sub = app.add_subcommand(
        "pairs",
        "Spatial join: every pair of polygons of one layer whose closed regions meet (or come within --within), "
        "or, with --other, every polygon of the first layer with every polygon of the second that it meets; all at "
        "their own coordinates. Touching counts. Exact in the exact and certified types.");
    sub->add_option("--layer", o->layer_path,
                    "WKT file, one POLYGON or MULTIPOLYGON per line (blank lines skipped): polygon k is the k-th "
                    "geometry, from 0 ('-': standard input)")
        ->required()
        ->type_name("A.wkt");
    sub->add_option("--other", o->other_path,
                    "A second layer in the same format: pairs (a, b) of a polygon a of the first layer and b of "
                    "this one ('-': standard input)")
        ->type_name("B.wkt");
    sub->add_option("--within", o->within,
                    "Distance D: polygons within D of each other count (0: their closed regions meet)")
        ->capture_default_str()
        ->check(finite_non_negative())
        ->type_name("D");
    add_number_type_option(sub, o->number_type);
    sub->add_option("--threads", o->threads,
                    "Threads of the pair tests (the answers are the same); 0: every hardware thread")
        ->capture_default_str()
        ->check(CLI::Range(0u, 4096u))
        ->type_name("N");
    sub->add_option("--out", o->out,
                    "Write one CSV line per pair (a,b: a < b in one layer; a of the first layer and b of the "
                    "other with --other; sorted) to this file; it is replaced only when the whole run succeeds. "
                    "'-': standard output, and the summary goes to standard error")
        ->type_name("PAIRS.csv");
    sub->callback([o] { run_pairs(*o); });
}

}  // namespace influence2d::cli
