// SPDX-License-Identifier: BSL-1.0
// The turning study (verification/turning_study.hpp, influence2d-bench's
// "Turning motions"): every method answers the same motions, its misses and
// inventions are counted against its model's reference, and the rational
// model's reference is the exact answer (first_contact<exact_rational>,
// computed here apart from the study).

#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "influence2d/motion/first_contact.hpp"
#include "influence2d/number/cgal.hpp"
#include "verification/turning_study.hpp"
#include "verification/turning_study_report.hpp"

using namespace influence2d;
using namespace influence2d::verification;

TEST_CASE("turning study: every method on the same motions, counted against its model's exact answer",
          "[verification][bench][turning]") {
    turning_study_options o;
    o.cells = {{"convex", 8, 8}};
    o.motions = 40;
    o.samples = {4, 64};
    o.seconds = 0;
    const std::vector<turning_row> rows = run_turning_study(o);
    std::vector<std::string> names;
    for (const turning_row& r : rows) names.push_back(r.method);
    std::vector<std::string> expected = {"rational_certified", "rational_double", "angle_linear_certified",
                                         "angle_linear_double"};
    if (INFLUENCE2D_HAVE_BOX2D) expected.push_back("box2d_toi");
    if (INFLUENCE2D_HAVE_GEOS) {
        expected.push_back("geos_sampled_4");
        expected.push_back("geos_sampled_64");
    }
    CHECK(names == expected);

    const family f = family_of("convex");
    const polygon a = make_family_polygon(f, 8, o.seed), b = make_family_polygon(f, 8, o.seed);
    const auto motions = turning_motions(o, a, b);
    REQUIRE(motions.size() == o.motions);
    // The rational reference against exact rationals, motion by motion.
    const sweep_options rational{sweep_options{}.tolerance, turning_model::rational};
    std::size_t contacts = 0;
    for (std::size_t k = 0; k < motions.size(); ++k) {
        const contact_result<exact_rational> x =
            first_contact<exact_rational>(a, b, motions[k].first, motions[k].second, rational);
        INFO("motion " << k);
        CHECK(rows[0].answers[k].contact == x.contact);
        if (x.contact) CHECK(rows[0].answers[k].time == nearest_double(x.time));
        contacts += x.contact;
    }
    CHECK(contacts > 0);
    CHECK(contacts < motions.size());
    for (const turning_row& r : rows) {
        INFO(r.method);
        CHECK(r.motions == o.motions);
        CHECK(r.rounds >= 3);
        CHECK(r.rounds % 2 == 1);
        CHECK(r.seconds > 0);
        REQUIRE(r.answers.size() == o.motions);
        // Each row's counts from its answers and its reference's.
        const turning_row& ref = r.model == "rational" ? rows[0] : rows[2];
        std::size_t got = 0, misses = 0, inventions = 0;
        for (std::size_t k = 0; k < o.motions; ++k) {
            got += r.answers[k].contact;
            misses += ref.answers[k].contact && !r.answers[k].contact;
            inventions += !ref.answers[k].contact && r.answers[k].contact;
        }
        CHECK(r.contacts == got);
        CHECK(r.misses == misses);
        CHECK(r.inventions == inventions);
        CHECK(r.contacts + r.misses == ref.contacts + r.inventions);
        if (r.reference) CHECK(r.misses + r.inventions == 0);
    }
    // Sampling reports a contact at a sample where the polygons meet, never
    // before the angle-linear reference, which stops before the contact.
    for (const turning_row& r : rows) {
        if (r.method.rfind("geos_sampled_", 0) != 0) continue;
        INFO(r.method);
        CHECK(r.inventions == 0);
        for (std::size_t k = 0; k < o.motions; ++k)
            if (r.answers[k].contact) CHECK(r.answers[k].time >= rows[2].answers[k].time);
    }

    const std::string csv = turning_csv(rows);
    CHECK(csv.rfind("type,static_size,moving_size,method,model,motions,contacts,misses,inventions,failed,", 0) == 0);
    const std::string md = turning_markdown(rows, o);
    CHECK(md.find("## Turning motions") != std::string::npos);
    CHECK(md.find("### convex 8x8") != std::string::npos);
    CHECK(md.find("| rational_certified (reference) | rational | ") != std::string::npos);
}
