// SPDX-License-Identifier: BSL-1.0
// Poses and frame results as CSV.

#include <catch2/catch.hpp>

#include <algorithm>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "influence2d/io/csv.hpp"

using namespace influence2d;

namespace {

class temp_csv {
public:
    explicit temp_csv(const std::string& content) {
        static std::atomic<int> counter{0};
        const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        path_ = std::filesystem::temp_directory_path() /
                ("influence2d_csv_" + std::to_string(stamp) + "_" + std::to_string(counter++) + ".csv");
        std::ofstream(path_, std::ios::binary) << content;
    }
    ~temp_csv() {
        std::error_code ec;
        std::filesystem::remove(path_, ec);
    }
    temp_csv(const temp_csv&) = delete;
    temp_csv& operator=(const temp_csv&) = delete;
    std::string path() const { return path_.string(); }

private:
    std::filesystem::path path_;
};

/// The message of read_poses_csv's invalid_input with the path removed, or
/// "no error".
std::string csv_error(const std::string& content) {
    const temp_csv f(content);
    try {
        (void)read_poses_csv(f.path());
    } catch (const invalid_input& e) {
        const std::string m = e.what();
        const std::string prefix = f.path() + ": ";
        if (m.rfind(prefix, 0) != 0) return "message does not start with the path: " + m;
        return m.substr(prefix.size());
    }
    return "no error";
}

}  // namespace

TEST_CASE("csv: a good poses file", "[io][csv]") {
    const temp_csv f(" tx , ty ,theta \r\n1,2,0.5\r\n-1.5e3, +2 ,-3.25\n0,0,0\n\n");
    const auto poses = read_poses_csv(f.path());
    REQUIRE(poses.size() == 3);
    CHECK(poses[0].tx == 1.0);
    CHECK(poses[0].ty == 2.0);
    CHECK(poses[0].theta == 0.5);
    CHECK(poses[1].tx == -1500.0);
    CHECK(poses[1].ty == 2.0);
    CHECK(poses[1].theta == -3.25);
    CHECK(poses[2].theta == 0.0);
}

TEST_CASE("csv: header only gives no poses", "[io][csv]") {
    const temp_csv f("tx,ty,theta\n");
    CHECK(read_poses_csv(f.path()).empty());
}

TEST_CASE("csv: missing and extra columns", "[io][csv]") {
    CHECK(csv_error("tx,ty,theta\n1,2,3\n4,5\n") == "line 3: 2 columns, expected 3; missing column theta");
    CHECK(csv_error("tx,ty,theta\n1\n") == "line 2: 1 column, expected 3; missing column ty");
    CHECK(csv_error("tx,ty,theta\n1,2,3,4\n") == "line 2: 4 columns, expected 3 (tx,ty,theta)");
    CHECK(csv_error("tx,ty,theta\n1,,3\n") == "line 2, column ty: empty value");
}

TEST_CASE("csv: values that are not finite numbers", "[io][csv]") {
    CHECK(csv_error("tx,ty,theta\n1,2,3\n1,2,3\n1,2,3\n1,2,3\n1,2,3\n1,2,abc\n") ==
          "line 7, column theta: \"abc\" is not a number");
    CHECK(csv_error("tx,ty,theta\nnan,2,3\n") == "line 2, column tx: \"nan\" is not a finite number");
    CHECK(csv_error("tx,ty,theta\n1,-inf,3\n") == "line 2, column ty: \"-inf\" is not a finite number");
    CHECK(csv_error("tx,ty,theta\n1,2,1e999\n") == "line 2, column theta: \"1e999\" is out of range");
    CHECK(csv_error("tx,ty,theta\n1x,2,3\n") == "line 2, column tx: \"1x\" is not a number");
    CHECK(csv_error("tx,ty,theta\n1 2,2,3\n") == "line 2, column tx: \"1 2\" is not a number");
    CHECK(csv_error("tx,ty,theta\n0x10,2,3\n") == "line 2, column tx: \"0x10\" is not a number");
}

TEST_CASE("csv: wrong or missing header and empty or blank files", "[io][csv]") {
    CHECK(csv_error("x,y,theta\n1,2,3\n") == "line 1: expected the header \"tx,ty,theta\", found \"x,y,theta\"");
    CHECK(csv_error("1,2,3\n") == "line 1: expected the header \"tx,ty,theta\", found \"1,2,3\"");
    CHECK(csv_error("tx,ty,theta,extra\n") ==
          "line 1: expected the header \"tx,ty,theta\", found \"tx,ty,theta,extra\"");
    CHECK(csv_error("") == "empty file: expected the header \"tx,ty,theta\"");
    CHECK(csv_error("\n  \n") == "no header: expected \"tx,ty,theta\"");
    CHECK(csv_error("tx,ty,theta\n1,2,3\n\n4,5,6\n") == "line 3: blank line between pose rows");
}

TEST_CASE("csv: a missing file", "[io][csv]") {
    const auto path = (std::filesystem::temp_directory_path() / "influence2d_no_such_poses.csv").string();
    try {
        (void)read_poses_csv(path);
        FAIL("no exception");
    } catch (const invalid_input& e) {
        CHECK(std::string(e.what()) == path + ": cannot open file");
    }
}

TEST_CASE("csv: files over the size cap are refused before reading", "[io][csv]") {
    const temp_csv f("tx,ty,theta\n");
    std::filesystem::resize_file(f.path(), max_csv_file_bytes + 1);  // sparse
    try {
        (void)read_poses_csv(f.path());
        FAIL("no exception");
    } catch (const invalid_input& e) {
        CHECK(std::string(e.what()) == f.path() + ": file is larger than 512 MiB");
    }
}

TEST_CASE("csv: poses round-trip exactly", "[io][csv]") {
    const std::vector<pose> poses{{0.1, -1e-300, std::acos(-1.0)}, {1.0 / 3.0, 2e300, -0.0}};
    std::ostringstream out;
    write_poses_csv(out, poses);
    const temp_csv f(out.str());
    const auto back = read_poses_csv(f.path());
    REQUIRE(back.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK(back[i].tx == poses[i].tx);
        CHECK(back[i].ty == poses[i].ty);
        CHECK(back[i].theta == poses[i].theta);
    }
    CHECK(out.str().rfind("tx,ty,theta\n0.1,", 0) == 0);
}

TEST_CASE("csv: frames with and without witness pairs", "[io][csv]") {
    std::vector<frame_result> results(3);
    results[0].collides = true;
    results[0].pairs = {{0, 2}, {3, 1}};
    results[1].collides = true;  // containment: no pair
    results[2].collides = false;
    std::ostringstream plain, witness;
    write_frames_csv(plain, results, false);
    write_frames_csv(witness, results, true);
    CHECK(plain.str() == "frame,collides\n0,1\n1,1\n2,0\n");
    CHECK(witness.str() == "frame,collides,edges\n0,1,0:2;3:1\n1,1,\n2,0,\n");
}

TEST_CASE("csv: every bad line is reported, not only the first", "[io][csv]") {
    const std::string m = csv_error("tx,ty,theta\n1,2\n1,2,3\n1,x,3\n\n4,5,6\nnan,1,1\n");
    // The message starts with the path (checked by csv_error); each later
    // line starts with it too.
    CHECK(m.find("line 2: 2 columns, expected 3; missing column theta") == 0);
    CHECK(m.find("line 4, column ty: \"x\" is not a number") != std::string::npos);
    CHECK(m.find("line 5: blank line between pose rows") != std::string::npos);
    CHECK(m.find("line 7, column tx: \"nan\" is not a finite number") != std::string::npos);
    CHECK(std::count(m.begin(), m.end(), '\n') == 3);
    // Beyond max_reported_csv_errors, a count.
    std::string many = "tx,ty,theta\n";
    for (int k = 0; k < 30; ++k) many += "a,b,c\n";
    const std::string capped = csv_error(many);
    CHECK(std::count(capped.begin(), capped.end(), '\n') == 20);
    CHECK(capped.find("and 10 more bad lines") != std::string::npos);
}
