// SPDX-License-Identifier: BSL-1.0
// The catalogue of degenerate and contact cases (data/catalogue.json): every
// frame's expected answer, for the sound detector (both extended-area shapes,
// with and without temporal coherence) and the brute-force reference, in
// double, long double and exact rationals.

#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/catalogue.hpp"

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/cgal.hpp"

namespace {

using influence2d::detector_options;
using influence2d::edge_pair;
using influence2d::extended_area;
using influence2d::frame_result;
using influence2d::polygon;
using influence2d::pose;
using json = test_catalogue::json;

using test_catalogue::frame;
using test_catalogue::test_case;

const json& catalogue() { return test_catalogue::document(); }

const std::vector<test_case>& load_cases() { return test_catalogue::cases(); }

std::string describe(const std::vector<edge_pair>& pairs) {
    std::ostringstream s;
    s << '[';
    for (std::size_t i = 0; i < pairs.size(); ++i)
        s << (i ? ", " : "") << '[' << pairs[i].static_edge << ", " << pairs[i].moving_edge << ']';
    s << ']';
    return s.str();
}

/// Checks one answer against the frame; without witnesses only `collides`.
void check_frame(const frame_result& got, const frame& expected, bool witness) {
    CHECK(got.collides == expected.collides);
    if (witness)
        CHECK(describe(got.pairs) == describe(expected.pairs));
    else
        CHECK(got.pairs.empty());
}

detector_options options_for(double distance, bool witness, extended_area shape, bool coherence) {
    detector_options o;
    o.distance = distance;
    o.witness = witness;
    o.shape = shape;
    o.temporal_coherence = coherence;
    return o;
}

/// Every frame with a fresh detector, then the frames of each distance in
/// order through one detector (the coherent path of a trajectory).
template <class Detector>
void check_case(const test_case& c, const std::string& label, extended_area shape, bool coherence) {
    for (const bool witness : {true, false}) {
        for (std::size_t k = 0; k < c.frames.size(); ++k) {
            const frame& f = c.frames[k];
            INFO(label << ", case " << c.name << ", frame " << k << " (fresh detector, witness " << witness
                       << "): " << f.note);
            Detector d(c.fixed, c.moving, options_for(f.distance, witness, shape, coherence));
            check_frame(d.collide(f.where), f, witness);
        }
        std::set<double> distances;
        for (const frame& f : c.frames) distances.insert(f.distance);
        for (const double distance : distances) {
            Detector d(c.fixed, c.moving, options_for(distance, witness, shape, coherence));
            for (std::size_t k = 0; k < c.frames.size(); ++k) {
                const frame& f = c.frames[k];
                const frame_result got = d.collide(f.where);
                if (f.distance != distance) continue;
                INFO(label << ", case " << c.name << ", frame " << k << " (in sequence, witness " << witness
                           << "): " << f.note);
                check_frame(got, f, witness);
            }
        }
    }
}

}  // namespace

TEST_CASE("the catalogue is well formed", "[data][catalogue]") {
    const json& doc = catalogue();
    REQUIRE(doc.at("cases").is_array());
    std::set<std::string> names;
    for (const json& c : doc.at("cases")) {
        const std::string name = c.at("name").get<std::string>();
        INFO("case " << name);
        CHECK(names.insert(name).second);
        CHECK(c.at("sketch").is_array());
        CHECK_FALSE(c.at("sketch").empty());
        CHECK_NOTHROW(influence2d::read_wkt(c.at("static").get<std::string>(), name));
        CHECK_NOTHROW(influence2d::read_wkt(c.at("moving").get<std::string>(), name));
        REQUIRE_FALSE(c.at("frames").empty());
        for (const json& f : c.at("frames")) {
            CHECK(f.at("pose").size() == 3);
            CHECK(f.at("pose").at(2).get<double>() == 0);  // translations: exact poses
            CHECK(f.value("distance", 0.0) >= 0);
            CHECK(f.contains("note"));
            std::vector<std::vector<std::size_t>> pairs = f.value("pairs", std::vector<std::vector<std::size_t>>{});
            CHECK(std::is_sorted(pairs.begin(), pairs.end()));
            if (!f.at("collides").get<bool>()) CHECK(pairs.empty());
        }
    }
    CHECK(names.size() >= 20);
}

TEMPLATE_TEST_CASE("catalogue frames: the brute-force reference", "[data][catalogue]", double, long double,
                   influence2d::exact_rational) {
    const std::string label = std::string("brute force, ") + influence2d::number_traits<TestType>::name;
    for (const test_case& c : load_cases())
        check_case<influence2d::brute_force_detector<TestType>>(c, label, extended_area::capsule, true);
}

TEMPLATE_TEST_CASE("catalogue frames: the sound detector", "[data][catalogue]", double, long double,
                   influence2d::exact_rational) {
    for (const auto shape : {extended_area::capsule, extended_area::band}) {
        for (const bool coherence : {true, false}) {
            const std::string label = std::string("detector, ") + influence2d::number_traits<TestType>::name +
                                      (shape == extended_area::capsule ? ", capsule" : ", band") +
                                      (coherence ? ", coherent" : ", no coherence");
            for (const test_case& c : load_cases())
                check_case<influence2d::detector<TestType>>(c, label, shape, coherence);
        }
    }
}
