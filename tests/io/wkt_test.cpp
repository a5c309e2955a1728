// SPDX-License-Identifier: BSL-1.0
// Reading and writing polygons as WKT.

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>

#include <boost/lexical_cast.hpp>

#include "influence2d/io/wkt.hpp"

using namespace influence2d;

namespace {

/// The message of the invalid_input thrown by f, or "" when none is thrown.
template <class F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const invalid_input& e) {
        return e.what();
    }
    return "";
}

std::string wkt_error(const std::string& text) {
    return error_of([&] { (void)read_wkt(text); });
}

std::filesystem::path temp_file(const std::string& name, const std::string& content) {
    static std::atomic<int> counter{0};
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    const auto path = std::filesystem::temp_directory_path() /
                      ("influence2d_wkt_" + std::to_string(stamp) + "_" + std::to_string(counter++) + "_" + name);
    std::ofstream(path, std::ios::binary) << content;
    return path;
}

}  // namespace

TEST_CASE("wkt: POLYGON with a hole", "[io][wkt]") {
    const polygon p = read_wkt("POLYGON((0 0,10 0,10 10,0 10,0 0),(2 2,2 4,4 4,4 2,2 2))");
    REQUIRE(p.ring_count() == 2);
    CHECK(p.role(0) == ring_role::outer);
    CHECK(p.role(1) == ring_role::hole);
    CHECK(p.ring_end(0) - p.ring_begin(0) == 4);  // closing point dropped
    CHECK(p.ring_end(1) - p.ring_begin(1) == 4);
    CHECK(p.size() == 8);
    CHECK(p.area() == Approx(96.0L));
}

TEST_CASE("wkt: keywords in any case with surrounding and inner white space", "[io][wkt]") {
    const polygon p = read_wkt(" \n\tpolygon (\n(0 0,\t1 0,\r\n1 1,0 0)\n)\r\n ");
    REQUIRE(p.size() == 3);
    CHECK(p.vertex(1).x == 1.0);
    const polygon m = read_wkt("MultiPolygon(((0 0,1 0,1 1,0 0)))");
    CHECK(m.size() == 3);
}

TEST_CASE("wkt: MULTIPOLYGON rings in text order with exteriors outer and interiors holes", "[io][wkt]") {
    const polygon p = read_wkt(
        "MULTIPOLYGON(((0 0,10 0,10 10,0 10,0 0),(2 2,2 4,4 4,4 2,2 2)),"
        "((20 0,30 0,30 10,20 0)))");
    REQUIRE(p.ring_count() == 3);
    CHECK(p.role(0) == ring_role::outer);
    CHECK(p.role(1) == ring_role::hole);
    CHECK(p.role(2) == ring_role::outer);
    CHECK(p.ring_end(2) - p.ring_begin(2) == 3);
    CHECK(p.vertex(p.ring_begin(2)).x == 20.0);
}

TEST_CASE("wkt: a clockwise outer ring is stored counter-clockwise and source_edge maps back", "[io][wkt]") {
    // Input edges: 0 (0 0)-(0 1), 1 (0 1)-(1 1), 2 (1 1)-(1 0), 3 (1 0)-(0 0): clockwise.
    const std::vector<point<double>> in{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    const polygon p = read_wkt("POLYGON((0 0,0 1,1 1,1 0,0 0))");
    REQUIRE(p.size() == 4);
    CHECK(p.area() > 0);
    // Stored counter-clockwise: the input order reversed.
    CHECK(p.vertex(0) == in[3]);
    CHECK(p.vertex(1) == in[2]);
    CHECK(p.vertex(2) == in[1]);
    CHECK(p.vertex(3) == in[0]);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const std::size_t s = p.source_edge(i);
        REQUIRE(s < 4);
        // Stored edge i is input edge s run backwards.
        CHECK(p.vertex(i) == in[(s + 1) % 4]);
        CHECK(p.vertex(p.next(i)) == in[s]);
    }
    CHECK(p.source_edge(0) == 2);

    // A counter-clockwise hole is stored clockwise.
    const polygon h = read_wkt("POLYGON((0 0,10 0,10 10,0 10,0 0),(2 2,4 2,4 4,2 4,2 2))");
    CHECK(h.vertex(4) == point<double>{2, 4});
    CHECK(h.source_edge(4) == 4 + 2);
}

TEST_CASE("wkt: rejects an unclosed ring and names it", "[io][wkt]") {
    const std::string e = wkt_error("POLYGON((0 0,1 0,1 1))");
    CHECK(e.find("<text>: ring 0 is not closed") == 0);
    const std::string h = wkt_error("POLYGON((0 0,9 0,9 9,0 0),(1 1,2 1,2 2,1 1),(3 3,4 3,4 4))");
    CHECK(h.find("ring 2 is not closed") != std::string::npos);
    const std::string m = wkt_error("MULTIPOLYGON(((0 0,1 0,1 1,0 0)),((5 5,6 5,6 6)))");
    CHECK(m.find("ring 1 is not closed") != std::string::npos);
}

TEST_CASE("wkt: rejects nan and inf and names ring and vertex", "[io][wkt]") {
    CHECK(wkt_error("POLYGON((0 0,1 0,1 nan,0 0))") == "<text>: ring 0, vertex 2: coordinate is not a finite number");
    CHECK(wkt_error("POLYGON((0 0,9 0,9 9,0 0),(1 1,inf 1,2 2,1 1))") ==
          "<text>: ring 1, vertex 1: coordinate is not a finite number");
    // A non-finite first point is reported as such, not as an unclosed ring.
    CHECK(wkt_error("POLYGON((nan 0,1 0,1 1,nan 0))") == "<text>: ring 0, vertex 0: coordinate is not a finite number");
    CHECK(wkt_error("POLYGON((0 0,1 0,1 1e999,0 0))").find("<text>: parse error") == 0);
}

TEST_CASE("wkt: numbers read as boost::lexical_cast<double> reads them", "[io][wkt]") {
    // The ring's first x is the number's text; the reader's answer against
    // lexical_cast's on the same text: refused by both, or the same double.
    const auto read_x = [](const std::string& number) -> std::optional<double> {
        try {
            return read_wkt_rings("POLYGON((" + number + " 0,1 0,1 1," + number + " 0))").at(0).points.at(0).x;
        } catch (const invalid_input&) {
            return std::nullopt;
        }
    };
    const auto lexical = [](const std::string& number) -> std::optional<double> {
        try {
            return boost::lexical_cast<double>(number);
        } catch (const boost::bad_lexical_cast&) {
            return std::nullopt;
        }
    };
    const auto same = [](std::optional<double> a, std::optional<double> b) {
        if (!a || !b) return !a && !b;
        return std::memcmp(&*a, &*b, sizeof(double)) == 0 || (std::isnan(*a) && std::isnan(*b));
    };
    for (const std::string number : {"1",        "+1",
                                     "-1",       "1.",
                                     ".5",       "-.5",
                                     "+.5",      "1e5",
                                     "1E+5",     "1e-5",
                                     "-0",       "00012",
                                     "1e0005",   "inf",
                                     "-inf",     "nan",
                                     "NaN",      "1e400",
                                     "-1e400",   "1e-400",
                                     "4.9e-324", "2.2250738585072011e-308",
                                     "+-1",      "-+1",
                                     "--1",      "1.5.3",
                                     "1e",       "e5",
                                     ".",        "+",
                                     "-",        "0x10",
                                     "1d5",      "1f",
                                     "1_0"})
        CHECK(same(read_x(number), lexical(number)));
    // Random texts of signs, digits, points and exponents, and random
    // doubles in shortest and 17-digit form.
    std::mt19937_64 rng(20040202);
    const std::string alphabet = "0123456789.eE+-";
    for (int k = 0; k < 20000; ++k) {
        std::string number;
        if (k % 2 == 0) {
            const std::size_t length = 1 + rng() % 8;
            for (std::size_t i = 0; i < length; ++i) number += alphabet[rng() % alphabet.size()];
        } else {
            std::uint64_t bits = rng();
            double x = 0;
            std::memcpy(&x, &bits, sizeof x);
            if (!std::isfinite(x)) continue;
            char buffer[40];
            std::snprintf(buffer, sizeof buffer, "%.17g", x);
            number = k % 4 == 1 ? shortest_decimal(x) : std::string(buffer);
            REQUIRE(read_x(number) == x);
        }
        INFO(number);
        CHECK(same(read_x(number), lexical(number)));
    }
}

TEST_CASE("wkt: rejects a ring with fewer than three distinct vertices", "[io][wkt]") {
    CHECK(wkt_error("POLYGON((0 0,1 0,0 0))") == "<text>: ring 0: fewer than three distinct vertices");
    CHECK(wkt_error("POLYGON((0 0,1 1,1 1,0 0,0 0))") == "<text>: ring 0: fewer than three distinct vertices");
    CHECK(wkt_error("POLYGON((0 0,9 0,9 9,0 0),(1 1))") == "<text>: ring 1: fewer than three distinct vertices");
}

TEST_CASE("wkt: rejects other geometry types and empty input", "[io][wkt]") {
    CHECK(wkt_error("LINESTRING(0 0,1 1)") == "<text>: expected POLYGON or MULTIPOLYGON, found 'LINESTRING'");
    CHECK(wkt_error("POINT(1 2)").find("found 'POINT'") != std::string::npos);
    CHECK(wkt_error("GEOMETRYCOLLECTION(POLYGON((0 0,1 0,1 1,0 0)))").find("found 'GEOMETRYCOLLECTION'") !=
          std::string::npos);
    CHECK(wkt_error("") == "<text>: empty input: expected POLYGON or MULTIPOLYGON");
    CHECK(wkt_error(" \n\t ") == "<text>: empty input: expected POLYGON or MULTIPOLYGON");
    CHECK(wkt_error("POLYGON EMPTY") == "<text>: POLYGON is empty");
    CHECK(wkt_error("multipolygon empty") == "<text>: MULTIPOLYGON is empty");
    CHECK(wkt_error("POLYGON((),(0 0,1 0,1 1,0 0))") == "<text>: ring 0: empty exterior ring with holes");
    CHECK(wkt_error("POLYGON(EMPTY,(0 0,1 0,1 1,0 0))") == "<text>: ring 0: empty exterior ring with holes");
    CHECK(wkt_error("POLYGON((),())") == "<text>: ring 0: empty exterior ring with holes");
    CHECK(wkt_error("MULTIPOLYGON(EMPTY,EMPTY)") == "<text>: polygon has no ring");
}

TEST_CASE("wkt: rejects truncated text and trailing garbage", "[io][wkt]") {
    CHECK(wkt_error("POLYGON((0 0,1 0").find("<text>: parse error: ") == 0);
    CHECK(wkt_error("POLYGON((0 0,1 0,1 1,0 0)) garbage").find("<text>: parse error: ") == 0);
    CHECK(wkt_error("POLYGON((0 0,1 0,1 1,0 0)))").find("<text>: parse error: ") == 0);
    CHECK(wkt_error("POLYGON((0 0,1 0,1 1,0 0));").find("<text>: parse error: ") == 0);
    CHECK(wkt_error("POLYGON((0 0,1 0,1 1,0 0))POLYGON((0 0,1 0,1 1,0 0))").find("<text>: parse error: ") == 0);
    CHECK(wkt_error("POLYGON((0 0,1 0,1 x,0 0))").find("<text>: parse error: ") == 0);
}

TEST_CASE("wkt: rejects points without exactly two coordinates and empty elements", "[io][wkt]") {
    // Boost's reader would zero-fill, split into extra points or skip these.
    CHECK(wkt_error("POLYGON((0 0,1 0,1 1 5,0 0))") ==
          "<text>: ring 0, vertex 2: 3 coordinates, expected 2 (only x y is supported)");
    CHECK(wkt_error("POLYGON((0 0,1,1 1,0 0))") ==
          "<text>: ring 0, vertex 1: 1 coordinates, expected 2 (only x y is supported)");
    CHECK(wkt_error("POLYGON((0 0,,1 0,1 1,0 0))") == "<text>: ring 0, vertex 1: missing coordinates");
    CHECK(wkt_error("POLYGON((0 0,1 0,1 1,0 0,))") == "<text>: ring 0: empty element after ','");
    CHECK(wkt_error("POLYGON((0 0,1 0,1 1,0 0),)") == "<text>: empty element after ','");
    CHECK(wkt_error("MULTIPOLYGON(((0 0,1 0,1 1,0 0)),((5 5,6 5,6 6 6,5 5)))") ==
          "<text>: ring 1, vertex 2: 3 coordinates, expected 2 (only x y is supported)");
    CHECK(wkt_error("POLYGON M((0 0 1,1 0 1,1 1 1,0 0 1))").find("3 coordinates") != std::string::npos);
}

TEST_CASE("wkt: files name the source and missing files are reported", "[io][wkt]") {
    const auto good = temp_file("good.wkt", "POLYGON((0 0,1 0,1 1,0 0))\n");
    CHECK(read_wkt_file(good.string()).size() == 3);
    const auto bad = temp_file("bad.wkt", "POLYGON((0 0,1 0,1 1,0 0),\n(0 0,1 0,nan 1,0 0))\n");
    CHECK(error_of([&] { (void)read_wkt_file(bad.string()); }) ==
          bad.string() + ": ring 1, vertex 2: coordinate is not a finite number");
    const auto missing = std::filesystem::temp_directory_path() / "influence2d_no_such_file.wkt";
    CHECK(error_of([&] { (void)read_wkt_file(missing.string()); }) == missing.string() + ": cannot open file");
    std::filesystem::remove(good);
    std::filesystem::remove(bad);
    CHECK(error_of([] {
              (void)read_wkt_file(std::filesystem::temp_directory_path().string());
          }).find(": is a directory") != std::string::npos);
}

TEST_CASE("wkt: files over the size cap are refused before reading", "[io][wkt]") {
    // A sparse file: no disk space used, refused on its size alone.
    const auto huge = temp_file("huge.wkt", "POLYGON((0 0,1 0,1 1,0 0))");
    std::filesystem::resize_file(huge, max_wkt_file_bytes + 1);
    CHECK(error_of([&] { (void)read_wkt_file(huge.string()); }) == huge.string() + ": file is larger than 512 MiB");
    std::filesystem::remove(huge);
}

TEST_CASE("wkt: to_wkt round-trips exactly with closed rings in stored orientation", "[io][wkt]") {
    const double third = 1.0 / 3.0;
    const polygon p(std::vector<ring_input>{
        {{{0, 0}, {0, 10}, {10, 10}, {10, 0}}, ring_role::outer},  // clockwise
        {{{2, 2}, {2, third}, {0.1, 0.2}}, ring_role::hole},
    });
    const std::string text = to_wkt(p);
    CHECK(text.rfind("POLYGON((10 0,10 10,0 10,0 0,10 0),(", 0) == 0);
    const polygon q = read_wkt(text);
    REQUIRE(q.size() == p.size());
    REQUIRE(q.ring_count() == 2);
    for (std::size_t i = 0; i < p.size(); ++i) CHECK(q.vertex(i) == p.vertex(i));
    CHECK(q.role(1) == ring_role::hole);

    const polygon m =
        read_wkt("MULTIPOLYGON(((0 0,10 0,10 10,0 0),(1 0.5,9 8,9 0.5,1 0.5)),((20 0,30 0,30 1e-300,20 0)))");
    const std::string mt = to_wkt(m);
    CHECK(mt ==
          "MULTIPOLYGON(((0 0,10 0,10 10,0 0),(1 0.5,9 8,9 0.5,1 0.5)),"
          "((20 0,30 0,30 1e-300,20 0)))");
    const polygon m2 = read_wkt(mt);
    REQUIRE(m2.ring_count() == 3);
    CHECK(m2.role(2) == ring_role::outer);
}

TEST_CASE("wkt: only the closing point is dropped, and a first vertex repeated before it stays an edge", "[io][wkt]") {
    // The text's ring has five points, the last the closing one: four
    // vertices, the fourth equal to the first (a zero-length edge 3 -> 0).
    // Dropping the repeat as well would renumber the edges, and the text
    // written back would read back one vertex shorter.
    for (const char* text : {"POLYGON((0 0,1 0,0 1,0 0,0 0))", "MULTIPOLYGON(((0 0,1 0,0 1,0 0,0 0)))"}) {
        INFO(text);
        const polygon p = read_wkt(text);
        REQUIRE(p.size() == 4);
        CHECK(p.vertex(3) == p.vertex(0));
        const std::string written = to_wkt(p);
        CHECK(written == "POLYGON((0 0,1 0,0 1,0 0,0 0))");
        const polygon q = read_wkt(written);
        CHECK(q.vertices() == p.vertices());
    }
    // Repeated thrice before the closing point: three zero-length edges.
    const polygon r = read_wkt("POLYGON((0 0,1 0,0 1,0 0,0 0,0 0,0 0))");
    CHECK(r.size() == 6);
    CHECK(read_wkt(to_wkt(r)).vertices() == r.vertices());
}

TEST_CASE("wkt: an empty polygon has no ring and no WKT", "[wkt]") {
    const influence2d::polygon empty;
    CHECK(empty.ring_count() == 0);
    CHECK(empty.size() == 0);
    CHECK_THROWS_AS(influence2d::to_wkt(empty), influence2d::invalid_input);
}

TEST_CASE("wkt: an empty ring is no ring, as GEOS and JTS read it", "[io][wkt]") {
    // Hole EMPTY, an empty part of a multipolygon, the empty list: ignored;
    // the edges keep their numbers (an empty ring has none).
    for (const char* text : {"POLYGON((0 0,4 0,4 4,0 4,0 0),EMPTY)", "POLYGON((0 0,4 0,4 4,0 4,0 0), empty )",
                             "POLYGON((0 0,4 0,4 4,0 4,0 0),())", "MULTIPOLYGON(((0 0,4 0,4 4,0 4,0 0)),EMPTY)",
                             "MULTIPOLYGON(EMPTY,((0 0,4 0,4 4,0 4,0 0)))"}) {
        INFO(text);
        const influence2d::polygon p = influence2d::read_wkt(text);
        CHECK(p.ring_count() == 1);
        CHECK(p.size() == 4);
    }
    const influence2d::polygon two =
        influence2d::read_wkt("MULTIPOLYGON(((0 0,4 0,4 4,0 4,0 0),EMPTY),((8 0,9 0,9 1,8 0)))");
    CHECK(two.ring_count() == 2);
    CHECK(two.size() == 7);
}
