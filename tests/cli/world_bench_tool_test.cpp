// SPDX-License-Identifier: BSL-1.0
// influence2d-world-bench, the world's time study: a small run of every scene
// writes its table, its CSV and the coherence line; every method of the
// library answers as the certified world does on these scenes, and so do the
// peers; bad options exit 2.

#include <catch2/catch.hpp>

#include "support/process.hpp"

#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace test_process;

TEST_CASE("cli world bench: every scene, every method, the answers compared", "[cli][bench_program]") {
    const temp_dir dir;
    const auto r = run_world_bench(dir, "--sizes 40 --steps 3 --out " + quote((dir / "out").string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("coherence, ") != std::string::npos);
    const std::string csv = slurp(dir / "out" / "world.csv");
    REQUIRE(csv.rfind("scene,bodies,method,step_us,first_ms,contacts,wrong,heap_kib,median_step_us\n", 0) == 0);
    std::istringstream lines(csv);
    std::string line;
    std::getline(lines, line);
    std::map<std::string, double> contacts;  // per scene, the certified world's
    std::size_t rows = 0;
    while (std::getline(lines, line)) {
        ++rows;
        // scene,bodies,"method",step_us,first_ms,contacts,wrong,heap_kib,median_step_us
        const std::size_t q1 = line.find('"'), q2 = line.find('"', q1 + 1);
        REQUIRE(q2 != std::string::npos);
        const std::string scene = line.substr(0, line.find(','));
        const std::string method = line.substr(q1 + 1, q2 - q1 - 1);
        std::vector<std::string> rest;
        std::istringstream fields(line.substr(q2 + 2));
        for (std::string f; std::getline(fields, f, ',');) rest.push_back(f);
        REQUIRE(rest.size() == 6);
        INFO(line);
        if (method == "certified") contacts[scene] = std::stod(rest[2]);
        // The library's worlds and the peers agree with the certified world
        // on these scenes (no pose within rounding of a contact).
        CHECK(rest[3] == "0");
    }
    CHECK(rows >= 7 * 6);
    for (const char* scene : {"falling", "convex", "parcels", "random", "mixed", "far", "trajectories"}) {
        INFO(scene);
        CHECK(contacts[scene] > 0);  // each scene has contacts to compare
    }
    CHECK(fs::exists(dir / "out" / "world.md"));
}

TEST_CASE("cli world bench: bad options exit 2", "[cli][bench_program]") {
    const temp_dir dir;
    CHECK(run_world_bench(dir, "--sizes x").exit_code == 2);
    CHECK(run_world_bench(dir, "--layers " + quote((dir / "none").string()) + " --sizes 10 --steps 2").exit_code == 2);
}
