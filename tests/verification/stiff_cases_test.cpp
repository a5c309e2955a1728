// SPDX-License-Identifier: BSL-1.0
// The stiff and extreme scenes (verification/stiff_cases.hpp) and their
// committed files (data/stiff): the files are what the generator and the
// generate-stiff command write; every polygon is valid and simple and every
// family has the promised shape; the exact answers of every scene include
// frames that collide, frames that do not, and a change of answer between
// frames a few ulps apart; and on every scene the certified detector gives
// exactly the answers and witness pairs of the exact detector.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/exact/certified_detector.hpp"
#include "influence2d/io/csv.hpp"
#include "influence2d/io/wkt.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/segments.hpp"
#include "support/process.hpp"
#include "verification/stiff_cases.hpp"

namespace {

using namespace influence2d;
namespace v = influence2d::verification;
using v::stiff_family;
using v::stiff_scene;
using dpoint = point<double>;
using epoint = point<exact_rational>;

const std::string stiff_dir = std::string(INFLUENCE2D_DATA_DIR) + "/stiff";

epoint exact(const dpoint& p) { return {exact_rational(p.x), exact_rational(p.y)}; }

int rational_orientation(const dpoint& a, const dpoint& b, const dpoint& c) {
    return orientation(exact(a), exact(b), exact(c));
}

/// The exact sign of the signed area of ring r.
int ring_area_sign(const polygon& p, std::size_t r) {
    exact_rational twice(0);
    for (std::size_t i = p.ring_begin(r); i < p.ring_end(r); ++i) {
        const dpoint& a = p.vertex(i);
        const dpoint& b = p.vertex(p.next(i));
        twice += exact_rational(a.x) * exact_rational(b.y) - exact_rational(a.y) * exact_rational(b.x);
    }
    return static_cast<int>(CGAL::sign(twice));
}

/// Exact simplicity of all rings together: edges that are not neighbours
/// share no point (found through a sweep over x-sorted boxes), neighbours
/// do not fold back along one line.
bool simple_stiff(const polygon& p, std::string& why) {
    for (std::size_t i = 0; i < p.size(); ++i) {
        const std::size_t j = p.next(i), k = p.next(j);
        const epoint a = exact(p.vertex(i)), b = exact(p.vertex(j)), c = exact(p.vertex(k));
        if (orientation(a, b, c) == 0 && (a.x - b.x) * (c.x - b.x) + (a.y - b.y) * (c.y - b.y) > 0) {
            why = "edges " + std::to_string(i) + " and " + std::to_string(j) + " fold back";
            return false;
        }
    }
    struct extent {
        double x0, x1, y0, y1;
        std::size_t edge;
    };
    std::vector<extent> boxes;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const dpoint& a = p.vertex(i);
        const dpoint& b = p.vertex(p.next(i));
        boxes.push_back({std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y), i});
    }
    std::sort(boxes.begin(), boxes.end(), [](const extent& l, const extent& r) { return l.x0 < r.x0; });
    for (std::size_t s = 0; s < boxes.size(); ++s) {
        for (std::size_t t = s + 1; t < boxes.size() && boxes[t].x0 <= boxes[s].x1; ++t) {
            if (boxes[t].y0 > boxes[s].y1 || boxes[s].y0 > boxes[t].y1) continue;
            const std::size_t e = boxes[s].edge, f = boxes[t].edge;
            if (p.next(e) == f || p.next(f) == e) continue;
            if (segments_intersect(exact(p.vertex(e)), exact(p.vertex(p.next(e))), exact(p.vertex(f)),
                                   exact(p.vertex(p.next(f))))) {
                why = "edges " + std::to_string(e) + " and " + std::to_string(f) + " meet";
                return false;
            }
        }
    }
    return true;
}

long double length(const dpoint& a, const dpoint& b) {
    return std::hypot(static_cast<long double>(b.x) - a.x, static_cast<long double>(b.y) - a.y);
}

/// Sine of the angle between edges u->v and v->w (long double).
long double turn_sine(const dpoint& u, const dpoint& v, const dpoint& w) {
    const long double ax = static_cast<long double>(v.x) - u.x, ay = static_cast<long double>(v.y) - u.y;
    const long double bx = static_cast<long double>(w.x) - v.x, by = static_cast<long double>(w.y) - v.y;
    return (ax * by - ay * bx) / (std::hypot(ax, ay) * std::hypot(bx, by));
}

std::size_t previous(const polygon& p, std::size_t i) {
    for (std::size_t r = 0; r < p.ring_count(); ++r)
        if (i >= p.ring_begin(r) && i < p.ring_end(r)) return i == p.ring_begin(r) ? p.ring_end(r) - 1 : i - 1;
    return i;
}

/// B's size about its own origin: its largest absolute coordinate.
double size_of(const polygon& b) {
    double m = 0;
    for (const dpoint& p : b.vertices()) m = std::max({m, std::fabs(p.x), std::fabs(p.y)});
    return m;
}

/// Ulps from a to b (saturating at `cap`).
int ulps_apart(double a, double b, int cap = 64) {
    int n = 0;
    const double to = b > a ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for (double x = a; x != b && n <= cap; ++n) x = std::nextafter(x, to);
    return n;
}

/// The scenes the tests run: the committed set (3 per family, 1 large).
const std::vector<stiff_scene>& data_scenes() {
    static const std::vector<stiff_scene> scenes = v::stiff_data_scenes();
    return scenes;
}

std::vector<const stiff_scene*> scenes_of(stiff_family f) {
    std::vector<const stiff_scene*> out;
    for (const auto& s : data_scenes())
        if (s.family == f) out.push_back(&s);
    return out;
}

/// The exact answers (d = 0) of every frame of a scene.
std::vector<bool> exact_answers(const stiff_scene& s) {
    detector<exact_rational> d(s.a, s.b);
    std::vector<bool> out;
    for (const pose& p : s.poses) out.push_back(d.collide(p).collides);
    return out;
}

std::string texts(const std::vector<stiff_scene>& scenes) {
    std::string all;
    for (const auto& f : v::stiff_data_files(scenes)) all += f.name + "\n" + f.text;
    return all;
}

}  // namespace

TEST_CASE("stiff families: names, magnitudes and scene names", "[verification][stiff]") {
    const auto& families = v::all_stiff_families();
    REQUIRE(families.size() == 13);
    std::set<std::string> names;
    for (const auto f : families) {
        const std::string name = v::stiff_family_name(f);
        CHECK(name.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == std::string::npos);
        names.insert(name);
    }
    CHECK(names.size() == 13);
    CHECK(v::stiff_family_name(stiff_family::near_collinear) == "near_collinear");
    CHECK(v::stiff_family_name(stiff_family::centroid_on_edge_line) == "centroid_on_edge_line");

    const auto offsets = v::offset_magnitudes();
    REQUIRE(offsets.size() == 13);
    CHECK(offsets.front() == 1e3);
    CHECK(offsets.back() == 1e15);
    for (std::size_t i = 1; i < offsets.size(); ++i) CHECK(offsets[i] == offsets[i - 1] * 10);
    const auto scales = v::scale_magnitudes();
    REQUIRE(scales.size() == 11);
    CHECK(scales.front() == 1e-150);
    CHECK(scales[5] == 1);
    CHECK(scales.back() == 1e150);

    const auto offset = v::make_stiff_scenes(stiff_family::offset, 3, 1, 4);
    REQUIRE(offset.size() == 3);
    CHECK(offset[0].name == "offset_1e03_000");
    CHECK(offset[1].name == "offset_1e09_001");
    CHECK(offset[2].name == "offset_1e15_002");
    CHECK(offset[2].magnitude == 1e15);
    const auto scaled = v::make_stiff_scenes(stiff_family::scaled, 3, 1, 4);
    REQUIRE(scaled.size() == 3);
    CHECK(scaled[0].name == "scaled_1e-150_000");
    CHECK(scaled[1].name == "scaled_1e00_001");
    CHECK(scaled[2].name == "scaled_1e150_002");
    CHECK(v::make_stiff_scenes(stiff_family::comb, 2, 1, 4)[1].name == "comb_001");
    CHECK(v::make_stiff_scenes(stiff_family::sliver, 2, 1, 4)[0].magnitude == 0);

    // Sweeps: the same relative scene at each magnitude, named by it.
    CHECK(v::make_offset_scenes(1e12, 2, 1, 4)[1].name == "offset_1e12_001");
    CHECK(v::make_scaled_scenes(1e-30, 1, 1, 4)[0].name == "scaled_1e-30_000");
    CHECK_THROWS_AS(v::make_offset_scenes(0.5, 1, 1), std::invalid_argument);
    CHECK_THROWS_AS(v::make_offset_scenes(1e200, 1, 1), std::invalid_argument);
    CHECK_THROWS_AS(v::make_scaled_scenes(1e-200, 1, 1), std::invalid_argument);
    CHECK_THROWS_AS(v::make_scaled_scenes(std::numeric_limits<double>::infinity(), 1, 1), std::invalid_argument);

    // At most 2 large scenes, of the poses asked for.
    const auto large = v::make_stiff_scenes(stiff_family::large, 20, 1, 24);
    CHECK(large.size() == 2);
    for (const auto& s : large) CHECK(s.poses.size() == 24);
}

TEST_CASE("stiff scenes depend on the seed, the family and the index only", "[verification][stiff]") {
    for (const auto f : v::all_stiff_families()) {
        if (f == stiff_family::large) continue;
        INFO(v::stiff_family_name(f));
        const auto two = v::make_stiff_scenes(f, 2, 5, 16);
        CHECK(texts(two) == texts(v::make_stiff_scenes(f, 2, 5, 16)));
        CHECK(texts(two) != texts(v::make_stiff_scenes(f, 2, 6, 16)));
        if (f != stiff_family::offset && f != stiff_family::scaled)
            CHECK(texts({two[1]}) == texts({v::make_stiff_scenes(f, 3, 5, 16)[1]}));
        for (const auto& s : two) CHECK(s.poses.size() == 16);
    }
    // A sweep keeps the shapes: the offset scenes differ by a translation.
    const auto near = v::make_offset_scenes(1e4, 1, 5, 8)[0];
    const auto far = v::make_offset_scenes(1e8, 1, 5, 8)[0];
    REQUIRE(near.a.size() == far.a.size());
    for (std::size_t i = 0; i < near.a.size(); ++i) {
        CHECK(near.a.vertex(i).x - near.a.vertex(0).x == far.a.vertex(i).x - far.a.vertex(0).x);
        CHECK(near.a.vertex(i).y - near.a.vertex(0).y == far.a.vertex(i).y - far.a.vertex(0).y);
    }
}

TEST_CASE("the committed data/stiff files are exactly what the generator writes", "[verification][stiff][data]") {
    const auto files = v::stiff_data_files(data_scenes());
    std::set<std::string> expected;
    std::size_t bytes = 0;
    for (const auto& f : files) {
        INFO("file data/stiff/" << f.name);
        expected.insert(f.name);
        bytes += f.text.size();
        const std::string path = stiff_dir + "/" + f.name;
        REQUIRE(std::filesystem::exists(path));
        CHECK(test_process::slurp(path) == f.text);
    }
    std::set<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator(stiff_dir))
        found.insert(entry.path().filename().string());
    CHECK(found == expected);
    CHECK(bytes < 20u << 20);

    // They read back as the generated scenes.
    for (const auto& s : data_scenes()) {
        INFO(s.name);
        const polygon a = read_wkt_file(stiff_dir + "/" + s.name + "_a.wkt");
        const polygon b = read_wkt_file(stiff_dir + "/" + s.name + "_b.wkt");
        const auto poses = read_poses_csv(stiff_dir + "/" + s.name + "_poses.csv");
        REQUIRE(a.size() == s.a.size());
        REQUIRE(b.size() == s.b.size());
        REQUIRE(poses.size() == s.poses.size());
        bool same = a.ring_count() == s.a.ring_count() && b.ring_count() == s.b.ring_count();
        for (std::size_t i = 0; i < a.size(); ++i) same = same && a.vertex(i) == s.a.vertex(i);
        for (std::size_t i = 0; i < b.size(); ++i) same = same && b.vertex(i) == s.b.vertex(i);
        for (std::size_t i = 0; i < poses.size(); ++i)
            same = same && poses[i].tx == s.poses[i].tx && poses[i].ty == s.poses[i].ty &&
                   poses[i].theta == s.poses[i].theta;
        CHECK(same);
    }
}

TEST_CASE("generate-stiff writes the committed bytes", "[verification][stiff][cli]") {
    const test_process::temp_dir dir;
    const auto out = dir / "stiff";
    const auto r = test_process::run_cli(dir, "generate-stiff --out " + test_process::quote(out.string()));
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("generate-stiff: wrote 112 files (37 scenes") != std::string::npos);
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out)) {
        ++files;
        const std::string name = entry.path().filename().string();
        INFO(name);
        CHECK(test_process::slurp(entry.path()) == test_process::slurp(stiff_dir + "/" + name));
    }
    CHECK(files == 112);

    const auto small = test_process::run_cli(
        dir, "generate-stiff --count 1 --seed 7 --out " + test_process::quote((dir / "small").string()));
    CHECK(small.exit_code == 0);
    CHECK(std::filesystem::exists(dir / "small" / "spiral_000_poses.csv"));
    CHECK_FALSE(std::filesystem::exists(dir / "small" / "spiral_000_poses.csv.tmp"));
    CHECK(test_process::run_cli(dir, "generate-stiff").exit_code == 2);
    CHECK(test_process::run_cli(dir, "generate-stiff --count 0 --out x").exit_code == 2);
    const auto help = test_process::run_cli(dir, "generate-stiff --help");
    CHECK(help.exit_code == 0);
    for (const char* option : {"--out", "--seed", "--count"}) CHECK(help.out.find(option) != std::string::npos);
}

TEST_CASE("stiff scenes: valid, simple, counter-clockwise polygons and finite poses", "[verification][stiff]") {
    for (const auto& s : data_scenes()) {
        INFO(s.name);
        CHECK(s.poses.size() == (s.family == stiff_family::large ? 16u : 64u));
        for (const polygon* p : {&s.a, &s.b}) {
            for (std::size_t r = 0; r < p->ring_count(); ++r)
                CHECK(ring_area_sign(*p, r) == (p->role(r) == ring_role::outer ? 1 : -1));
            std::string why;
            const bool is_simple = simple_stiff(*p, why);
            INFO(why);
            CHECK(is_simple);
        }
        bool finite = true;
        for (const pose& q : s.poses)
            finite = finite && std::isfinite(q.tx) && std::isfinite(q.ty) && std::isfinite(q.theta);
        CHECK(finite);
    }
}

TEST_CASE("stiff families have their promised shapes", "[verification][stiff]") {
    SECTION("near_collinear: runs collinear up to a few ulps") {
        for (const auto* s : scenes_of(stiff_family::near_collinear)) {
            INFO(s->name);
            std::size_t nearly = 0;
            for (std::size_t i = 0; i < s->a.size(); ++i) {
                const dpoint& u = s->a.vertex(previous(s->a, i));
                const dpoint& w = s->a.vertex(s->a.next(i));
                if (rational_orientation(u, s->a.vertex(i), w) != 0 &&
                    std::fabs(turn_sine(u, s->a.vertex(i), w)) < 1e-13L)
                    ++nearly;
            }
            CHECK(nearly >= 3);
        }
    }
    SECTION("sliver: aspect ratio 1e-14 to 1e-8") {
        for (const auto* s : scenes_of(stiff_family::sliver)) {
            INFO(s->name);
            long double longest = 0;
            for (const auto& a : s->a.vertices())
                for (const auto& b : s->a.vertices()) longest = std::max(longest, length(a, b));
            const long double aspect = 2 * s->a.area() / (longest * longest);
            CHECK(aspect > 1e-15L);
            CHECK(aspect < 1e-8L);
        }
    }
    SECTION("needle: spikes 1e-10 wide for their length") {
        for (const auto* s : scenes_of(stiff_family::needle)) {
            INFO(s->name);
            std::size_t tips = 0;
            for (std::size_t i = 0; i < s->a.size(); ++i) {
                const dpoint& u = s->a.vertex(previous(s->a, i));
                const dpoint& p = s->a.vertex(i);
                const dpoint& w = s->a.vertex(s->a.next(i));
                if (length(u, p) > 5 && length(p, w) > 5 && std::fabs(turn_sine(u, p, w)) < 2e-10L) ++tips;
            }
            CHECK(tips >= 2);
        }
    }
    SECTION("tiny_beside_huge: edges of 1e-9 next to edges of 1e3") {
        for (const auto* s : scenes_of(stiff_family::tiny_beside_huge)) {
            INFO(s->name);
            std::size_t pairs = 0;
            for (std::size_t i = 0; i < s->a.size(); ++i) {
                const std::size_t j = s->a.next(i);
                const long double e = length(s->a.vertex(i), s->a.vertex(j));
                const long double f = length(s->a.vertex(j), s->a.vertex(s->a.next(j)));
                pairs += (e < 5e-9L && f > 500) || (f < 5e-9L && e > 500);
            }
            CHECK(pairs >= 2);
        }
    }
    SECTION("offset: features of 1e-3 at the offset, B posed beside them") {
        std::vector<stiff_scene> scenes;
        for (const double m : v::offset_magnitudes())
            for (auto& s : v::make_offset_scenes(m, 1, 3, 64)) scenes.push_back(std::move(s));
        for (const auto& s : scenes) {
            INFO(s.name);
            const dpoint c = s.a.centroid();
            const double spacing = std::ldexp(1.0, std::ilogb(s.magnitude) - 52);
            const double diameter =
                std::max(s.a.bounds().max_x - s.a.bounds().min_x, s.a.bounds().max_y - s.a.bounds().min_y);
            CHECK(std::fabs(std::hypot(c.x, c.y) / s.magnitude - 1) < 1e-5);
            CHECK(diameter < std::max(1.2e-3, 160 * spacing));
            CHECK(diameter > 2e-4);
            if (s.magnitude <= 1e10) CHECK(diameter < 1e-3);
            const double reach = diameter + 3 * size_of(s.b);
            bool beside = true;
            for (const pose& q : s.poses) beside = beside && std::hypot(q.tx - c.x, q.ty - c.y) < reach;
            CHECK(beside);
        }
    }
    SECTION("scaled: coordinates and translations at their scale") {
        for (const double m : v::scale_magnitudes()) {
            for (const auto& s : v::make_scaled_scenes(m, 2, 3, 32)) {
                INFO(s.name);
                CHECK(s.a.vertex(0) == dpoint{50 * m, 0});
                double largest = 0, b_largest = 0, t_largest = 0;
                for (const auto& p : s.a.vertices()) largest = std::max({largest, std::fabs(p.x), std::fabs(p.y)});
                for (const auto& p : s.b.vertices()) b_largest = std::max({b_largest, std::fabs(p.x), std::fabs(p.y)});
                for (const pose& q : s.poses) t_largest = std::max({t_largest, std::fabs(q.tx), std::fabs(q.ty)});
                CHECK(largest == 50 * m);
                CHECK(b_largest <= 6.25 * m * (1 + 1e-15));
                CHECK(b_largest >= 3 * m);
                CHECK(t_largest <= 100 * m);
                CHECK(t_largest >= 10 * m);
            }
        }
    }
    SECTION("subnormal: every coordinate and translation subnormal, theta 0") {
        for (const auto* s : scenes_of(stiff_family::subnormal)) {
            INFO(s->name);
            const double limit = std::ldexp(1.0, -1030);
            bool in_range = true;
            std::size_t nonzero = 0;
            auto check = [&](double x) {
                in_range = in_range && std::fabs(x) <= limit && std::fabs(x) < std::numeric_limits<double>::min();
                nonzero += x != 0;
            };
            for (const auto& p : s->a.vertices()) check(p.x), check(p.y);
            for (const auto& p : s->b.vertices()) check(p.x), check(p.y);
            bool still = true;
            for (const pose& q : s->poses) check(q.tx), check(q.ty), still = still && q.theta == 0;
            CHECK(in_range);
            CHECK(still);
            CHECK(nonzero > s->a.size() + s->b.size());
        }
    }
    SECTION("grazing: groups of eight frames within 8 ulps, theta 0 or tiny") {
        for (const auto* s : scenes_of(stiff_family::grazing)) {
            INFO(s->name);
            bool close = true;
            std::size_t still = 0, tiny = 0;
            for (std::size_t g = 0; g + 8 <= s->poses.size(); g += 8) {
                const pose& first = s->poses[g];
                still += first.theta == 0;
                tiny += first.theta != 0 && std::fabs(first.theta) < 1e-4;
                for (std::size_t k = g; k < g + 8; ++k)
                    close = close && s->poses[k].theta == first.theta && ulps_apart(first.tx, s->poses[k].tx) <= 8 &&
                            ulps_apart(first.ty, s->poses[k].ty) <= 8;
            }
            CHECK(close);
            CHECK(still > 0);
            CHECK(tiny > 0);
        }
    }
    SECTION("touching: exact contact at d = 0, apart after one ulp, in the exact brute force") {
        for (const auto* s : scenes_of(stiff_family::touching)) {
            INFO(s->name);
            brute_force_detector<exact_rational> bf(s->a, s->b);
            std::size_t touching = 0, apart = 0, moved_one_ulp = 0;
            for (std::size_t i = 0; i + 1 < s->poses.size(); i += 2) {
                const pose& t = s->poses[i];
                const pose& u = s->poses[i + 1];
                CHECK(t.theta == 0);
                touching += bf.collide(t).collides;
                apart += !bf.collide(u).collides;
                moved_one_ulp += ulps_apart(t.tx, u.tx) + ulps_apart(t.ty, u.ty) == 1;
            }
            CHECK(touching == s->poses.size() / 2);
            CHECK(apart == s->poses.size() / 2);
            CHECK(moved_one_ulp == s->poses.size() / 2);
        }
    }
    SECTION("centroid_on_edge_line: an edge's line passes exactly through the centroid") {
        std::vector<stiff_scene> scenes = v::make_stiff_scenes(stiff_family::centroid_on_edge_line, 10, 3, 1);
        for (const auto* s : scenes_of(stiff_family::centroid_on_edge_line)) scenes.push_back(*s);
        for (const auto& s : scenes) {
            INFO(s.name);
            std::size_t through = 0;
            for (std::size_t i = 0; i < s.a.size(); ++i)
                through += rational_orientation(s.a.centroid(), s.a.vertex(i), s.a.vertex(s.a.next(i))) == 0;
            CHECK(through >= 2);
        }
    }
    SECTION("large: 100,000 to 131,072 vertices, a small B, few poses") {
        for (const auto* s : scenes_of(stiff_family::large)) {
            INFO(s->name);
            CHECK(s->a.size() >= 100000);
            CHECK(s->a.size() <= 131072);
            CHECK(s->b.size() <= 8);
            CHECK(s->poses.size() <= 16);
        }
    }
    SECTION("comb: 50 to 500 teeth 1e-3 as wide as long") {
        for (const auto* s : scenes_of(stiff_family::comb)) {
            INFO(s->name);
            REQUIRE(s->a.size() % 4 == 0);
            const std::size_t teeth = s->a.size() / 4 - 1;
            CHECK(teeth >= 50);
            CHECK(teeth <= 500);
            std::size_t tips = 0, sides = 0;
            for (std::size_t i = 0; i < s->a.size(); ++i) {
                const long double e = length(s->a.vertex(i), s->a.vertex(s->a.next(i)));
                tips += std::fabs(e - 1e-3L) < 1e-9L;
                sides += e >= 0.7L && e <= 1;
            }
            CHECK(tips == teeth);
            CHECK(sides == 2 * teeth);
        }
    }
    SECTION("spiral: 5 to 20 turns") {
        for (const auto* s : scenes_of(stiff_family::spiral)) {
            INFO(s->name);
            const std::size_t half = s->a.size() / 2;
            long double turned = 0;
            for (std::size_t i = 0; i + 1 < half; ++i) {
                const dpoint& a = s->a.vertex(i);
                const dpoint& b = s->a.vertex(i + 1);
                turned += std::atan2(static_cast<long double>(a.x) * b.y - static_cast<long double>(a.y) * b.x,
                                     static_cast<long double>(a.x) * b.x + static_cast<long double>(a.y) * b.y);
            }
            const long double turns = turned / (2 * 3.14159265358979323846L);
            CHECK(turns > 4.99L);
            CHECK(turns < 20.01L);
        }
    }
}

TEST_CASE("stiff scenes: exact answers both ways, and a change within a few ulps", "[verification][stiff]") {
    for (const auto& s : data_scenes()) {
        INFO(s.name);
        const std::vector<bool> answers = exact_answers(s);
        const auto colliding = static_cast<std::size_t>(std::count(answers.begin(), answers.end(), true));
        CHECK(colliding > 0);
        CHECK(colliding < answers.size());
        // Two frames with the same rotation, translations at most 8 ulps apart
        // in each coordinate, different exact answers.
        bool flip = false;
        for (std::size_t i = 0; i < answers.size() && !flip; ++i)
            for (std::size_t j = i + 1; j < answers.size() && !flip; ++j)
                flip = answers[i] != answers[j] && s.poses[i].theta == s.poses[j].theta &&
                       ulps_apart(s.poses[i].tx, s.poses[j].tx, 8) <= 8 &&
                       ulps_apart(s.poses[i].ty, s.poses[j].ty, 8) <= 8;
        CHECK(flip);
    }
}

TEST_CASE("stiff scenes: the exact brute force agrees and has both answers in every family", "[verification][stiff]") {
    for (const auto f : v::all_stiff_families()) {
        if (f == stiff_family::large) continue;  // 10^5 x 8 exact segment tests a frame
        INFO(v::stiff_family_name(f));
        std::size_t colliding = 0, apart = 0;
        for (const auto* s : scenes_of(f)) {
            INFO(s->name);
            // About 10^5 exact segment tests per scene at most (every eighth
            // frame at least).
            const std::size_t work = s->a.size() * s->b.size();
            const std::size_t stride = std::max<std::size_t>(1, std::min<std::size_t>(8, work * 64 / 100000));
            brute_force_detector<exact_rational> bf(s->a, s->b);
            detector<exact_rational> d(s->a, s->b);
            for (std::size_t i = 0; i < s->poses.size(); i += stride) {
                const bool answer = bf.collide(s->poses[i]).collides;
                CHECK(answer == d.collide(s->poses[i]).collides);
                (answer ? colliding : apart) += 1;
            }
        }
        CHECK(colliding > 0);
        CHECK(apart > 0);
    }
}

TEST_CASE("stiff scenes: the certified detector gives the exact answers and witnesses", "[verification][stiff]") {
    // The committed scenes and one scene at every offset and every scale.
    std::vector<const stiff_scene*> scenes;
    for (const auto& s : data_scenes()) scenes.push_back(&s);
    static std::vector<stiff_scene> sweeps;
    if (sweeps.empty()) {
        for (const double m : v::offset_magnitudes())
            for (auto& s : v::make_offset_scenes(m, 1, v::default_stiff_seed + 1)) sweeps.push_back(std::move(s));
        for (const double m : v::scale_magnitudes())
            for (auto& s : v::make_scaled_scenes(m, 1, v::default_stiff_seed + 1)) sweeps.push_back(std::move(s));
    }
    for (const auto& s : sweeps) scenes.push_back(&s);

    std::size_t frames = 0, exact_frames = 0;
    for (const stiff_scene* s : scenes) {
        // d = 0 and d = B's size / 64, a small distance at the scene's scale.
        for (const double distance : {0.0, std::ldexp(size_of(s->b), -6)}) {
            INFO(s->name << " at d = " << distance);
            detector_options options;
            options.witness = true;
            options.distance = distance;
            certified_detector<detector> certified(s->a, s->b, options);
            detector<exact_rational> reference(s->a, s->b, options);
            std::size_t differ = 0;
            for (std::size_t i = 0; i < s->poses.size(); ++i) {
                const frame_result c = certified.collide(s->poses[i]);
                const frame_result e = reference.collide(s->poses[i]);
                if (c.collides != e.collides || !(c.pairs == e.pairs)) {
                    ++differ;
                    UNSCOPED_INFO("frame " << i << ": certified " << c.collides << " with " << c.pairs.size()
                                           << " pairs, exact " << e.collides << " with " << e.pairs.size());
                }
            }
            CHECK(differ == 0);
            frames += s->poses.size();
            exact_frames += certified.exact_frames();
        }
    }
    // The scenes are stiff: many frames need the exact fallback.
    CHECK(exact_frames * 4 > frames);
    CHECK(exact_frames < frames);
}
