// SPDX-License-Identifier: BSL-1.0
#pragma once
// The catalogue of degenerate and contact cases (data/catalogue.json), loaded
// once: each case's polygons and its frames with their expected answers.

#include <catch2/catch.hpp>

#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/detect/result.hpp"
#include "influence2d/io/wkt.hpp"

namespace test_catalogue {

using json = nlohmann::json;

/// The parsed file.
inline const json& document() {
    static const json doc = [] {
        std::ifstream in(std::string(INFLUENCE2D_DATA_DIR) + "/catalogue.json");
        REQUIRE(in);
        return json::parse(in);
    }();
    return doc;
}

/// One frame: the pose, the separation distance and the expected answer.
struct frame {
    influence2d::pose where;
    double distance = 0;
    bool collides = false;
    std::vector<influence2d::edge_pair> pairs;
    std::string note;
};

/// One case: A (fixed), B (moving) and the frames.
struct test_case {
    std::string name;
    influence2d::polygon fixed;
    influence2d::polygon moving;
    std::vector<frame> frames;
};

/// Every case of the catalogue, in file order.
inline const std::vector<test_case>& cases() {
    static const std::vector<test_case> all = [] {
        std::vector<test_case> out;
        for (const json& c : document().at("cases")) {
            test_case t;
            t.name = c.at("name").get<std::string>();
            t.fixed = influence2d::read_wkt(c.at("static").get<std::string>(), t.name + " static");
            t.moving = influence2d::read_wkt(c.at("moving").get<std::string>(), t.name + " moving");
            for (const json& f : c.at("frames")) {
                frame fr;
                const auto p = f.at("pose").get<std::vector<double>>();
                REQUIRE(p.size() == 3);
                fr.where = influence2d::pose{p[0], p[1], p[2]};
                fr.distance = f.value("distance", 0.0);
                fr.collides = f.at("collides").get<bool>();
                for (const json& q : f.value("pairs", json::array()))
                    fr.pairs.push_back({q.at(0).get<std::size_t>(), q.at(1).get<std::size_t>()});
                fr.note = f.value("note", std::string());
                t.frames.push_back(fr);
            }
            out.push_back(std::move(t));
        }
        return out;
    }();
    return all;
}

}  // namespace test_catalogue
