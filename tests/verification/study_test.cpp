// SPDX-License-Identifier: BSL-1.0
// The precision study (verification/study.hpp, `influence2d study`): a tiny
// run writes its files with the right headers, the types that claim exactness
// never disagree with the reference, float does on a stiff family; the quick
// run's queries (separation, first contact) likewise; the reproducible-case
// format reads back, for decisions and queries; every committed case in
// data/regressions is answered again; the image-space baseline's rows count
// the questions of the d = 0 scenes, per resolution.

#include <catch2/catch.hpp>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/effort.hpp"
#include "support/process.hpp"
#include "verification/study.hpp"

namespace {

namespace fs = std::filesystem;
using namespace influence2d;
using namespace influence2d::verification;
using test_process::lines_of;
using test_process::quote;
using test_process::run_cli;
using test_process::slurp;
using test_process::temp_dir;

std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    for (std::string f; std::getline(in, f, ',');) out.push_back(f);
    return out;
}

polygon make_study_polygon(std::vector<point<double>> v) {
    return polygon({ring_input{std::move(v), ring_role::outer}});
}

}  // namespace

TEST_CASE("study: a tiny run writes the tables, the summary and the plots", "[verification][study][cli]") {
    const temp_dir dir;
    const auto r =
        run_cli(dir, "study --families convex,touching,offset_sweep --cases 1 --frames 12 --out " +
                         quote((dir / "out").string()) + " --regressions " + quote((dir / "regressions").string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("collides per number type") != std::string::npos);

    const std::vector<std::string> study = lines_of(slurp(dir / "out" / "study.csv"));
    REQUIRE(!study.empty());
    CHECK(study.front() == "number_type,family,decision,cases,disagreements,rate,ns_per_query");
    const std::vector<std::string> types = mode_names(study_modes{});
    // Every type, family and decision once.
    CHECK(study.size() == 1 + types.size() * 3 * std::size(all_decision_kinds));
    std::map<std::string, std::size_t> disagreements;  // per type, and float per family
    for (std::size_t i = 1; i < study.size(); ++i) {
        const std::vector<std::string> f = fields(study[i]);
        REQUIRE(f.size() == 7);
        CHECK(std::stoul(f[3]) > 0);
        CHECK(std::stod(f[6]) >= 0);
        disagreements[f[0]] += std::stoul(f[4]);
        if (f[0] == "float") disagreements["float " + f[1]] += std::stoul(f[4]);
    }
    CHECK(disagreements["certified"] == 0);
    CHECK(disagreements["interval"] == 0);
    CHECK(disagreements["exact"] == 0);
    CHECK(disagreements["float touching"] > 0);
    CHECK(!fs::exists(dir / "regressions"));  // nothing to reproduce

    const std::vector<std::string> stability = lines_of(slurp(dir / "out" / "stability.csv"));
    REQUIRE(!stability.empty());
    CHECK(stability.front() == "number_type,sweep,magnitude,cases,disagreements,rate");
    CHECK(stability.size() == 1 + types.size() * offset_magnitudes().size());
    for (std::size_t i = 1; i < stability.size(); ++i) CHECK(fields(stability[i])[1] == "offset");

    const std::string md = slurp(dir / "out" / "study.md");
    CHECK(md.find("# Precision study") != std::string::npos);
    CHECK(md.find("## What this means when choosing a number type") != std::string::npos);
    CHECK(md.find("## collides\n") != std::string::npos);
    CHECK(md.find("## The image-space baseline") != std::string::npos);
    CHECK(lines_of(slurp(dir / "out" / "raster.csv")).size() ==
          1 + default_raster_resolutions().size() * 3);  // every family has d = 0 scenes
    CHECK(md.find("## Worst examples") != std::string::npos);
    if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
        CHECK(slurp(dir / "out" / "error_vs_time.svg").find("<svg") != std::string::npos);
        CHECK(slurp(dir / "out" / "stability_offset.svg").find("<svg") != std::string::npos);
    } else {
        CHECK(r.err.find("gnuplot not found") != std::string::npos);
    }
}

TEST_CASE("study: the image-space baseline answers the collides questions of the d = 0 scenes per resolution",
          "[verification][study][cli]") {
    const temp_dir dir;
    // Three convex scenes (the third has d = 0.5, which the baseline is not
    // asked) and three touching ones; the resolutions given out of order and
    // one twice.
    const auto r = run_cli(dir,
                           "study --families convex,touching --types certified --decisions collides --queries "
                           "none --cases 3 --frames 40 --raster 4096,16,16 --out " +
                               quote((dir / "out").string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::vector<std::string> lines = lines_of(slurp(dir / "out" / "raster.csv"));
    REQUIRE(lines.size() == 5);
    CHECK(lines.front() == "resolution,family,questions,missed,invented,rate,ns_per_question");
    std::map<std::string, std::size_t> wrong;      // per resolution
    std::map<std::string, std::size_t> questions;  // per family and resolution
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const std::vector<std::string> f = fields(lines[i]);
        REQUIRE(f.size() == 7);
        CHECK((f[0] == "16" || f[0] == "4096"));
        questions[f[1] + " " + f[0]] = std::stoul(f[2]);
        CHECK(std::stoul(f[3]) + std::stoul(f[4]) <= std::stoul(f[2]));
        wrong[f[0]] += std::stoul(f[3]) + std::stoul(f[4]);
        CHECK(std::stod(f[6]) > 0);
    }
    CHECK(questions == std::map<std::string, std::size_t>{
                           {"convex 16", 80}, {"convex 4096", 80}, {"touching 16", 120}, {"touching 4096", 120}});
    // Exact touches are missed at any resolution; a coarse grid misses more.
    CHECK(wrong["4096"] > 0);
    CHECK(wrong["16"] > wrong["4096"]);
    const std::string md = slurp(dir / "out" / "study.md");
    CHECK(md.find("## The image-space baseline") != std::string::npos);
    CHECK(md.find("No resolution was right on every question.") != std::string::npos);
    if (std::system("command -v gnuplot > /dev/null 2>&1") == 0)
        CHECK(slurp(dir / "out" / "raster_error_vs_resolution.svg").find("<svg") != std::string::npos);

    const auto none = run_cli(dir,
                              "study --families convex --types double --decisions collides --queries none "
                              "--cases 1 --frames 8 --raster none --out " +
                                  quote((dir / "none").string()));
    REQUIRE(none.exit_code == 0);
    CHECK(lines_of(slurp(dir / "none" / "raster.csv")).size() == 1);
    CHECK(slurp(dir / "none" / "study.md").find("image-space") == std::string::npos);
    for (const char* bad : {"0", "16,x", "-4", "100000"}) {
        const auto b = run_cli(
            dir, std::string("study --families convex --raster ") + bad + " --out " + quote((dir / "bad").string()));
        INFO(bad);
        CHECK(b.exit_code == 2);
        CHECK(b.err.find("--raster") != std::string::npos);
        CHECK(!fs::exists(dir / "bad" / "study.md"));
    }
}

TEST_CASE("study: the queries' section, and no disagreement of the types that claim exactness",
          "[verification][study][cli]") {
    const temp_dir dir;
    // A quick run's 40 poses per scene, fewer under the sanitizers (10 still
    // show float's and double's wrong answers).
    const int frames = test_effort::scaled(40);
    const auto r =
        run_cli(dir, "study --quick --frames " + std::to_string(frames) + " --out " + quote((dir / "out").string()) +
                         " --regressions " + quote((dir / "regressions").string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("separation per number type") != std::string::npos);
    CHECK(r.out.find("first_contact per number type") != std::string::npos);
    CHECK(r.out.find("turning_rational per number type") != std::string::npos);
    CHECK(r.out.find("turning_angle_linear per number type") != std::string::npos);

    const std::string md = slurp(dir / "out" / "study.md");
    CHECK(md.find("## Queries: error against time") != std::string::npos);
    CHECK(md.find("### separation") != std::string::npos);
    CHECK(md.find("### first_contact") != std::string::npos);
    CHECK(md.find("### turning_rational") != std::string::npos);
    CHECK(md.find("### turning_angle_linear") != std::string::npos);

    const std::vector<std::string> rows = lines_of(slurp(dir / "out" / "queries.csv"));
    REQUIRE(!rows.empty());
    CHECK(rows.front() ==
          "number_type,family,query,questions,differing,meeting_differs,features_differ,"
          "values_differ,measured,largest_error,median_error,ns_per_question");
    std::map<std::string, std::size_t> questions, differing;  // per "type query"
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const std::vector<std::string> f = fields(rows[i]);
        REQUIRE(f.size() == 12);
        questions[f[0] + " " + f[2]] += std::stoul(f[3]);
        differing[f[0] + " " + f[2]] += std::stoul(f[4]);
    }
    for (const std::string& type : mode_names(study_modes{}))
        for (const char* query : {"separation", "first_contact", "turning_rational", "turning_angle_linear"}) {
            INFO(type << " " << query);
            CHECK(questions[type + " " + query] > 0);
            if (type == "certified" || type == "interval" || type == "exact") CHECK(differing[type + " " + query] == 0);
        }
    CHECK(differing["float separation"] > 0);  // the cliff is there
    CHECK(differing["double turning_rational"] > 0);
    CHECK(!fs::exists(dir / "regressions"));
}

TEST_CASE("study: a query's reproducible case reads back and is answered again", "[verification][study]") {
    //   +-------+ +-+     A: the square [0,4]^2; B: a unit square moving
    //   |   A   | |B| <-  toward A's right side, which it reaches at t = 1/2
    //   +-------+ +-+
    const polygon a = make_study_polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
    const polygon b = make_study_polygon({{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}});
    const translation motion{{5.5, 2, 0}, {3.5, 2, 0}};
    const std::string expected = exact_answer_text(a, b, query_kind::first_contact, motion);
    CHECK(expected == "contact at 1/2, e1:v0");
    const std::string text =
        query_regression_json(a, b, query_kind::first_contact, motion, "certified", expected, "no contact");
    const regression_case r = parse_regression(text, "<text>");
    REQUIRE(r.asked == query_kind::first_contact);
    CHECK(r.motion.from.tx == 5.5);
    CHECK(r.motion.to.tx == 3.5);
    const replay_outcome ok = replay_regression(r);
    CHECK(ok.reference_agrees);
    CHECK(ok.disagreeing.empty());

    // B turning by 1.5 radians in place, centred at (4.6, 2): its corner
    // (-0.5, 0.5), sqrt(1/2) from the centre, reaches A's side x = 4 after
    // a turn of about 0.228 radians: at t about 0.123 in the rational model,
    // 0.152 in the angle-linear one.
    const translation turn{{4.6, 2, 0}, {4.6, 2, 1.5}};
    const std::string turn_text = exact_answer_text(a, b, query_kind::turning_rational, turn);
    CHECK(turn_text.rfind("contact at ", 0) == 0);
    CHECK(turn_text != exact_answer_text(a, b, query_kind::turning_angle_linear, turn));
    const regression_case tr = parse_regression(
        query_regression_json(a, b, query_kind::turning_rational, turn, "certified", turn_text, "no contact"),
        "<text>");
    REQUIRE(tr.asked == query_kind::turning_rational);
    CHECK(tr.motion.to.theta == 1.5);
    const replay_outcome turned = replay_regression(tr);
    CHECK(turned.reference_agrees);
    CHECK(turned.disagreeing.empty());

    const translation apart{{5.5, 2, 0}, {5.5, 2, 0}};
    const regression_case s = parse_regression(
        query_regression_json(a, b, query_kind::separation, apart, "exact", "apart", "apart"), "<text>");
    REQUIRE(s.asked == query_kind::separation);
    CHECK(s.motion.from.tx == 5.5);
    const replay_outcome wrong = replay_regression(s);  // "apart" is not the exact answer's text
    CHECK(!wrong.reference_agrees);
    CHECK(wrong.disagreeing.empty());
}

TEST_CASE("study: bad arguments are named, exit code 2", "[verification][study][cli]") {
    const temp_dir dir;
    const std::string out = " --out " + quote((dir / "out").string());
    const auto bad_type = run_cli(dir, "study --types double,decimal" + out);
    CHECK(bad_type.exit_code == 2);
    CHECK(bad_type.err.find("decimal") != std::string::npos);
    const auto bad_family = run_cli(dir, "study --families convex,triangles" + out);
    CHECK(bad_family.exit_code == 2);
    CHECK(bad_family.err.find("triangles") != std::string::npos);
    const auto bad_query = run_cli(dir, "study --queries separation,volume" + out);
    CHECK(bad_query.exit_code == 2);
    CHECK(bad_query.err.find("volume") != std::string::npos);
    CHECK(run_cli(dir, "study --cases 0" + out).exit_code == 2);
    CHECK(run_cli(dir, "study --frames x" + out).exit_code == 2);
    CHECK(!fs::exists(dir / "out" / "study.csv"));
}

TEST_CASE("study: a reproducible case reads back and is answered again", "[verification][study]") {
    //   +-------+          A: the square [0,4]^2; B: a unit square posed
    //   |   A  +|-+        across A's right side (pairs with edge 1)
    //   |      +|-+
    //   +-------+
    const polygon a = make_study_polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
    const polygon b = make_study_polygon({{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}});
    const query q{{}, {4.25, 2, 0.1}};
    const answer expected = reference_decisions(a, b, 0).decide(decision_kind::pairs, q);
    REQUIRE(!expected.empty());
    const std::string text = regression_json(a, b, 0, decision_kind::pairs, q, "certified", expected, {});
    const regression_case r = parse_regression(text, "<text>");
    CHECK(r.decision == decision_kind::pairs);
    CHECK(r.number_type == "certified");
    CHECK(r.question.placement.tx == 4.25);
    CHECK(r.question.placement.theta == 0.1);
    CHECK(r.expected == expected);
    const replay_outcome ok = replay_regression(r);
    CHECK(ok.reference_agrees);
    CHECK(ok.disagreeing.empty());

    regression_case wrong = r;
    wrong.expected.clear();
    const replay_outcome bad = replay_regression(wrong);
    CHECK(!bad.reference_agrees);
    CHECK(bad.disagreeing.size() == 3);  // certified, interval, exact

    CHECK_THROWS_WITH(parse_regression("{\"decision\": \"pairs\"}", "case.json"), Catch::Contains("case.json"));
}

namespace {

/// float, pretending to claim the exact answer: the study keeps every
/// disagreement of such a type as a reproducible case, so a run of it makes
/// cases through the study's own path.
struct float_claiming_exact : number_mode<float> {
    static std::string name() { return "float-claiming-exact"; }
    static constexpr bool claims_exact = true;
};

}  // namespace

TEST_CASE("study: every reproducible case in data/regressions is answered exactly", "[verification][study]") {
    // The committed cases (data/regressions: README.md and one JSON file per
    // case; none is the normal state) are copied to a scratch folder, where
    // a short study of a type that claims exactness but answers in float adds
    // the cases it writes (float disagrees on the touching family). Every
    // case there is then replayed: the count replayed must be the count of
    // files present, and at least the study's.
    const fs::path committed = fs::path(INFLUENCE2D_DATA_DIR) / "regressions";
    REQUIRE(fs::is_directory(committed));
    CHECK(fs::exists(committed / "README.md"));
    const temp_dir scratch;
    const fs::path dir = scratch / "regressions";
    fs::create_directories(dir);
    std::size_t committed_cases = 0;
    for (const auto& entry : fs::directory_iterator(committed)) {
        if (entry.path().filename() == "README.md") continue;
        INFO(entry.path().string());
        CHECK(entry.path().extension() == ".json");  // nothing else is kept there
        fs::copy_file(entry.path(), dir / entry.path().filename());
        ++committed_cases;
    }

    study_options o;
    o.families = {"touching"};
    o.cases = 1;
    o.frames = 12;
    o.query_frames = 12;
    o.regressions_dir = dir.string();
    const study_result run = run_study(o, mode_list<float_claiming_exact>{});
    REQUIRE(!run.regressions.empty());
    for (const std::string& written : run.regressions) CHECK(fs::path(written).parent_path() == dir);

    std::size_t present = 0;
    for (const auto& entry : fs::directory_iterator(dir)) present += entry.is_regular_file() ? 1 : 0;
    CHECK(present == committed_cases + run.regressions.size());

    std::size_t replayed = 0, reproduced = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        INFO(entry.path().filename().string());
        const regression_case r = parse_regression(slurp(entry.path()), entry.path().string());
        const replay_outcome o_exact = replay_regression(r);
        CHECK(o_exact.reference_agrees);
        for (const std::string& t : o_exact.disagreeing) FAIL_CHECK(t << " disagrees with the exact answer");
        // The study's cases reproduce the disagreement of the type that wrote them.
        if (r.number_type == float_claiming_exact::name()) {
            const replay_outcome again = replay_regression(r, mode_list<float_claiming_exact>{});
            CHECK(again.reference_agrees);
            reproduced += again.disagreeing == std::vector<std::string>{float_claiming_exact::name()} ? 1 : 0;
        }
        ++replayed;
    }
    CHECK(replayed == present);
    CHECK(replayed >= run.regressions.size());
    CHECK(reproduced > 0);
}

TEST_CASE("study: --decisions selects the kinds, and large keeps every pose only for per-frame decisions",
          "[verification][study][cli]") {
    const temp_dir dir;
    const auto rows = [&](const std::string& decisions) {
        const auto r = run_cli(dir,
                               "study --families large --types double --cases 1 --frames 20 --queries none "
                               "--raster none --decisions " +
                                   decisions + " --out " + quote((dir / decisions).string()));
        INFO(r.err);
        REQUIRE(r.exit_code == 0);
        std::map<std::string, std::string> cases;  // decision -> cases
        const std::vector<std::string> lines = lines_of(slurp(dir / decisions / "study.csv"));
        for (std::size_t i = 1; i < lines.size(); ++i) cases[fields(lines[i])[2]] = fields(lines[i])[3];
        return cases;
    };
    // Only the final answer: every pose asked for.
    CHECK(rows("collides") == std::map<std::string, std::string>{{"collides", "20"}});
    // A decision over all of A's 100,000 edges (the edge pairs, the cheapest
    // of them): at most 16 poses.
    CHECK(rows("collides,pairs") == std::map<std::string, std::string>{{"pairs", "16"}, {"collides", "16"}});
    const auto bad = run_cli(dir, "study --decisions collides,guess --out " + quote((dir / "bad").string()));
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find("guess") != std::string::npos);
}

TEST_CASE("study: the final answer alone, in a type whose answers are all right, is reported",
          "[verification][study][cli]") {
    // quad answers every collides question of the convex scene rightly; with
    // no predicate decision asked, the advice has no predicate rate to give
    // it (that once ended the run with "map::at").
    const temp_dir dir;
    const auto r = run_cli(dir,
                           "study --families convex --types double,quad --cases 1 --frames 20 --decisions "
                           "collides --queries none --raster none --out " +
                               quote((dir / "out").string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const std::string md = slurp(dir / "out" / "study.md");
    // quad's rate is reported in either of the advice's two forms: as the
    // fastest type (which 20 frames timed on a busy machine may make it) or
    // beside the fastest.
    const bool beside = md.find("quad: 0 wrong at") != std::string::npos;
    const bool fastest = md.find("the fastest type was quad, at ") != std::string::npos &&
                         md.find("; it answered 0 of 20 frames wrongly") != std::string::npos;
    CHECK(beside != fastest);
    CHECK(md.find("their predicates disagreed") == std::string::npos);
}
