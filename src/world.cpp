// SPDX-License-Identifier: BSL-1.0
// `influence2d world`: many bodies, each a shape of SHAPES.wkt at its own
// pose, moved step by step as STEPS.csv says; the pairs in contact after
// each step (or the contacts that began and ended at it).

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <vector>

#include "commands.hpp"
#include "files.hpp"
#include "influence2d/core/invalid_input.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/exact/certified_world.hpp"
#include "influence2d/query/batch.hpp"
#include "influence2d/world/world.hpp"
#include "number_types.hpp"
#include "report.hpp"
#include "scene_input.hpp"
#include "world_input.hpp"

namespace influence2d::cli {

namespace {

struct world_cli_options {
    std::string shapes_path;
    std::string steps_path;
    std::string number_type = default_number_type;
    std::string out;
    bool events = false;
    double within = 0;
    unsigned threads = 1;  ///< 0: every hardware thread
};

/// What one row of STEPS.csv does to a body before its step: add it (its
/// first row) or move it. `body` is the world's id (0, 1, ... in order of
/// first appearance).
struct body_action {
    std::uint32_t body = 0;
    bool add = false;
    std::uint32_t shape = 0;
    bool fixed = false;
    pose where;
};

/// One step: its number in STEPS.csv and its rows' actions, in file order.
struct world_step {
    std::uint64_t number = 0;
    std::vector<body_action> actions;
};

/// STEPS.csv as the world runs it: the steps, and the user's id of each
/// world body.
struct world_plan {
    std::vector<world_step> steps;
    std::vector<std::uint64_t> user_ids;
};

constexpr std::array<std::string_view, 7> step_columns{"step", "body", "shape", "tx", "ty", "theta", "fixed"};

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> fields_of(std::string_view line) {
    std::vector<std::string_view> fields;
    for (std::size_t start = 0;;) {
        const std::size_t comma = line.find(',', start);
        fields.push_back(
            trimmed(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
        if (comma == std::string_view::npos) return fields;
        start = comma + 1;
    }
}

std::string quoted(std::string_view s) {
    std::string q(s.substr(0, 40));
    if (s.size() > 40) q += "...";
    return "\"" + q + "\"";
}

/// Parses the whole field as an integer >= 0 (decimal digits); returns ""
/// or why it is not one.
std::string parse_integer(std::string_view field, std::uint64_t& value) {
    if (field.empty()) return "empty value";
    const char* last = field.data() + field.size();
    const auto res = std::from_chars(field.data(), last, value);
    if (res.ec == std::errc::result_out_of_range) return quoted(field) + " is out of range";
    if (res.ec != std::errc() || res.ptr != last) return quoted(field) + " is not an integer >= 0";
    return {};
}

/// Parses the whole field as a finite double (one leading '+' allowed);
/// returns "" or why it is not one.
std::string parse_finite(std::string_view field, double& value) {
    if (field.empty()) return "empty value";
    std::string_view digits = field;
    if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
    const char* last = digits.data() + digits.size();
    const auto res = std::from_chars(digits.data(), last, value);
    if (res.ec == std::errc::result_out_of_range) return quoted(field) + " is out of range";
    if (res.ec != std::errc() || res.ptr != last) return quoted(field) + " is not a number";
    if (!std::isfinite(value)) return quoted(field) + " is not a finite number";
    return {};
}

/// A body as the rows so far made it.
struct known_body {
    std::uint32_t id = 0;  ///< the world's
    std::uint64_t shape = 0;
    bool fixed = false;
    std::size_t first_line = 0;
    std::size_t last_step = 0;  ///< index in world_plan::steps of its last row
    std::size_t last_line = 0;
};

/// Reads STEPS.csv ('-': standard input) into the world's plan; `shapes`
/// is the number of shapes when SHAPES.wkt was read (nullopt: shape ids go
/// unchecked). Throws one invalid_input naming the file and the line of
/// every bad row (the first max_reported_lines): a header, a field, a step
/// going back, a body twice in one step, a body changing its shape or
/// fixedness, a shape id out of range.
world_plan read_steps(const std::string& path, std::optional<std::size_t> shapes) {
    const std::string shown = shown_name(path);
    const std::string text = read_wkt_text_input(path);  // as bytes, with the size limit of a WKT file
    const auto fail = [&](const std::string& what) { throw invalid_input(shown + ": " + what); };
    std::vector<std::string> errors;
    world_plan plan;
    std::unordered_map<std::uint64_t, known_body> bodies;
    std::size_t columns = 0;  // 6, or 7 with `fixed`
    std::size_t line_no = 0, blank_line = 0;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = std::string_view(text).substr(start, end - start);
        start = end + 1;
        ++line_no;
        if (line_no == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
        if (trimmed(line).empty()) {
            if (blank_line == 0) blank_line = line_no;
            continue;
        }
        const std::string place = shown + ": line " + std::to_string(line_no);
        const std::vector<std::string_view> fields = fields_of(line);
        if (columns == 0) {
            if (blank_line != 0) fail("line " + std::to_string(blank_line) + ": blank line before the header");
            bool ok = fields.size() == 6 || fields.size() == 7;
            for (std::size_t c = 0; ok && c < fields.size(); ++c) ok = fields[c] == step_columns[c];
            if (!ok)
                fail("line " + std::to_string(line_no) +
                     ": expected the header \"step,body,shape,tx,ty,theta\" (or with \",fixed\"), found " +
                     quoted(trimmed(line)));
            columns = fields.size();
            continue;
        }
        if (blank_line != 0) {
            errors.push_back(shown + ": line " + std::to_string(blank_line) + ": blank line between rows");
            blank_line = 0;
        }
        if (fields.size() != columns) {
            errors.push_back(
                place + ": " + std::to_string(fields.size()) + " columns, expected " + std::to_string(columns) +
                (columns == 6 ? " (step,body,shape,tx,ty,theta)" : " (step,body,shape,tx,ty,theta,fixed)"));
            continue;
        }
        std::uint64_t step = 0, user = 0, shape = 0;
        std::array<double, 3> v{};
        bool fixed = false;
        std::string why;
        std::size_t bad_column = 0;
        const auto check = [&](std::size_t c, const std::string& reason) {
            if (why.empty() && !reason.empty()) {
                why = reason;
                bad_column = c;
            }
        };
        check(0, parse_integer(fields[0], step));
        check(1, parse_integer(fields[1], user));
        check(2, parse_integer(fields[2], shape));
        for (std::size_t c = 0; c < 3; ++c) check(3 + c, parse_finite(fields[3 + c], v[c]));
        if (columns == 7) {
            if (fields[6] == "0" || fields[6] == "1")
                fixed = fields[6] == "1";
            else
                check(6, quoted(fields[6]) + " is not 0 or 1");
        }
        if (!why.empty()) {
            errors.push_back(place + ", column " + std::string(step_columns[bad_column]) + ": " + why);
            continue;
        }
        if (shapes && shape >= *shapes) {
            errors.push_back(place + ", column shape: no shape " + std::to_string(shape) + " (the shapes file has " +
                             std::to_string(*shapes) + ", numbered from 0)");
            continue;
        }
        if (!plan.steps.empty() && step < plan.steps.back().number) {
            errors.push_back(place + ": step " + std::to_string(step) + " after step " +
                             std::to_string(plan.steps.back().number) +
                             ": steps must not go back (the rows of a step are consecutive)");
            continue;
        }
        if (plan.steps.empty() || step != plan.steps.back().number) plan.steps.push_back({step, {}});
        const std::size_t step_index = plan.steps.size() - 1;
        const auto found = bodies.find(user);
        if (found == bodies.end()) {
            if (plan.user_ids.size() >= 0xffffffffu) fail(place + ": too many bodies");
            const auto id = static_cast<std::uint32_t>(plan.user_ids.size());
            plan.user_ids.push_back(user);
            bodies[user] = known_body{id, shape, fixed, line_no, step_index, line_no};
            plan.steps.back().actions.push_back(
                {id, true, static_cast<std::uint32_t>(shape), fixed, {v[0], v[1], v[2]}});
            continue;
        }
        known_body& b = found->second;
        if (b.last_step == step_index) {
            errors.push_back(place + ": body " + std::to_string(user) + " is listed twice in step " +
                             std::to_string(step) + " (also line " + std::to_string(b.last_line) + ")");
            continue;
        }
        if (b.shape != shape) {
            errors.push_back(place + ", column shape: body " + std::to_string(user) + " has shape " +
                             std::to_string(b.shape) + " since line " + std::to_string(b.first_line) + ", not " +
                             std::to_string(shape) + ": a body keeps its shape");
            continue;
        }
        if (b.fixed != fixed) {
            errors.push_back(place + ", column fixed: body " + std::to_string(user) + " is " +
                             (b.fixed ? "fixed" : "free") + " since line " + std::to_string(b.first_line) +
                             ": a body stays fixed or free");
            continue;
        }
        b.last_step = step_index;
        b.last_line = line_no;
        plan.steps.back().actions.push_back({b.id, false, 0, fixed, {v[0], v[1], v[2]}});
    }
    if (columns == 0)
        fail(line_no == 0 ? "empty file: expected the header \"step,body,shape,tx,ty,theta\""
                          : "no header: expected \"step,body,shape,tx,ty,theta\"");
    throw_line_errors(errors, shown);
    return plan;
}

/// Both inputs, read with every problem reported at once.
struct world_inputs {
    polygon_lines shapes;
    world_plan plan;
};

world_inputs read_world_inputs(const world_cli_options& o) {
    check_one_standard_input({{"--shapes", o.shapes_path}, {"--steps", o.steps_path}});
    world_inputs in;
    std::vector<std::string> errors;
    std::optional<std::size_t> shapes;
    try {
        in.shapes = read_polygon_lines(o.shapes_path);
        shapes = in.shapes.polygons.size();
    } catch (const invalid_input& e) {
        errors.emplace_back(e.what());
    }
    try {
        in.plan = read_steps(o.steps_path, shapes);
    } catch (const invalid_input& e) {
        errors.emplace_back(e.what());
    }
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

/// A row of the output in world ids: the step's index, the pair, and for
/// an event whether the contact begins.
struct world_row {
    std::size_t step = 0;
    body_pair bodies;
    bool begins = false;
};

/// What the stepping found and how long it took.
struct world_run {
    std::vector<world_row> rows;  ///< contacts, or events with --events
    std::size_t contacts = 0;     ///< pairs in contact, summed over the steps
    std::size_t events = 0;       ///< contacts begun or ended, summed over the steps
    double seconds = 0;           ///< the steps alone
    world_statistics work;        ///< the world's counters after the last step
};

/// Runs the plan in world<NT, Exact>: the shapes added first, then, timed,
/// each step's bodies added or moved and the step taken.
template <class NT, class Exact>
world_run run_steps(const world_inputs& in, const world_cli_options& o) {
    world_options options;
    options.within = o.within;
    options.threads = o.threads;
    world<NT, Exact> w(options);
    for (std::size_t k = 0; k < in.shapes.polygons.size(); ++k) {
        try {
            w.add_shape(in.shapes.polygons[k]);
        } catch (const invalid_input& e) {
            throw invalid_input(shown_name(o.shapes_path) + ": line " + std::to_string(in.shapes.line[k]) + ": " +
                                e.what());
        }
    }
    world_run r;
    r.seconds = seconds_taken([&] {
        for (std::size_t s = 0; s < in.plan.steps.size(); ++s) {
            for (const body_action& a : in.plan.steps[s].actions) {
                if (a.add)
                    w.add_body(a.shape, a.where, a.fixed);
                else
                    w.move(a.body, a.where);
            }
            const std::vector<body_pair>& contacts = w.step();
            r.contacts += contacts.size();
            r.events += w.events().size();
            if (o.events)
                for (const contact_event& e : w.events()) r.rows.push_back({s, e.bodies, e.begins});
            else
                for (const body_pair& p : contacts) r.rows.push_back({s, p, true});
        }
    });
    r.work = w.statistics();
    return r;
}

/// CONTACTS.csv: `step,a,b` (or `step,a,b,event`), the user's body ids,
/// a < b, sorted by step, a, b.
std::string contacts_csv(const world_plan& plan, const std::vector<world_row>& rows, bool events) {
    struct out_row {
        std::size_t step;
        std::uint64_t a, b;
        bool begins;
    };
    std::vector<out_row> out;
    out.reserve(rows.size());
    for (const world_row& r : rows) {
        const std::uint64_t x = plan.user_ids[r.bodies.first], y = plan.user_ids[r.bodies.second];
        out.push_back({r.step, std::min(x, y), std::max(x, y), r.begins});
    }
    std::sort(out.begin(), out.end(), [](const out_row& l, const out_row& r) {
        return l.step != r.step ? l.step < r.step : l.a != r.a ? l.a < r.a : l.b < r.b;
    });
    std::string s = events ? "step,a,b,event\n" : "step,a,b\n";
    for (const out_row& r : out) {
        s += std::to_string(plan.steps[r.step].number) + "," + std::to_string(r.a) + "," + std::to_string(r.b);
        if (events) s += r.begins ? ",begin" : ",end";
        s += "\n";
    }
    return s;
}

void run_world(const world_cli_options& o) {
    // The type first: a type the world does not run in is refused before
    // any input is read.
    with_world_number_type(o.number_type, "world", [&](auto nt, auto exact) {
        using NT = typename decltype(nt)::type;
        using Exact = typename decltype(exact)::type;
        const world_inputs in = read_world_inputs(o);
        const world_run r = run_steps<NT, Exact>(in, o);
        if (!o.out.empty()) write_output(o.out, contacts_csv(in.plan, r.rows, o.events));

        const std::size_t steps = in.plan.steps.size();
        std::ostream& summary = is_standard_stream(o.out) ? std::cerr : std::cout;
        summary << "bodies:        " << in.plan.user_ids.size() << "\n"
                << "steps:         " << steps << "\n"
                << "contacts:      " << r.contacts << "\n"
                << "events:        " << r.events << "\n"
                << "number type:   " << o.number_type << "\n"
                << "threads:       " << batch_threads(o.threads) << "\n"
                << "candidates:    " << r.work.candidates << " (answered by their last witness " << r.work.witness_hits
                << ", again in exact rationals " << r.work.exact_pairs << ")\n"
                << "time per step: "
                << (steps == 0 ? std::string("n/a") : fixed(r.seconds * 1e6 / static_cast<double>(steps), 3) + " us")
                << "\n"
                << "time total:    " << fixed(r.seconds * 1e3, 3) << " ms\n";
        if (!o.out.empty())
            summary << (o.events ? "events written: " : "contacts written: ") << shown_name(o.out, true) << "\n";
    });
}

}  // namespace

void register_world(CLI::App& app) {
    auto o = std::make_shared<world_cli_options>();
    CLI::App* sub = app.add_subcommand(
        "world",
        "Many bodies moved step by step: each body a shape of SHAPES.wkt at its own pose, placed and moved as "
        "STEPS.csv says; after each step, every pair of bodies whose closed regions meet (or come within --within). "
        "Exact in the exact and certified types.");
    sub->add_option("--shapes", o->shapes_path,
                    "WKT file, one POLYGON or MULTIPOLYGON per line (blank lines skipped): shape k is the k-th "
                    "geometry, from 0 ('-': standard input)")
        ->required()
        ->type_name("SHAPES.wkt");
    sub->add_option("--steps", o->steps_path,
                    "CSV file with the header step,body,shape,tx,ty,theta (optionally a 7th column fixed, 0 or 1): "
                    "the rows of a step are consecutive and steps go up; a body (any integer id >= 0) appears at its "
                    "first row with its shape and keeps its pose until a later row moves it (same shape); the pose "
                    "turns the shape by theta radians about its origin, then moves it by (tx, ty); two fixed bodies "
                    "are never tested against each other ('-': standard input)")
        ->required()
        ->type_name("STEPS.csv");
    add_number_type_option(sub, o->number_type);
    sub->add_flag("--events", o->events,
                  "Write the contacts that begin or end at each step (step,a,b,event with event begin or end) "
                  "instead of every contact");
    sub->add_option("--within", o->within,
                    "Distance D: bodies within D of each other count as in contact (0: their closed regions meet)")
        ->capture_default_str()
        ->check(finite_non_negative())
        ->type_name("D");
    sub->add_option("--threads", o->threads,
                    "Threads of each step's pair tests (the answers are the same); 0: every hardware thread")
        ->capture_default_str()
        ->check(CLI::Range(0u, 4096u))
        ->type_name("N");
    sub->add_option("--out", o->out,
                    "Write one CSV line per pair in contact after each step (step,a,b: the user's body ids, a < b, "
                    "sorted by step, a, b) to this file; it is replaced only when the whole run succeeds. '-': "
                    "standard output, and the summary goes to standard error")
        ->type_name("CONTACTS.csv");
    sub->callback([o] { run_world(*o); });
}

}  // namespace influence2d::cli
