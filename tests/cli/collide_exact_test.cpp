// SPDX-License-Identifier: BSL-1.0
// `influence2d collide --number-type exact`, run as a user runs it, against the
// independent CGAL reference on every frame: random poses near contact, exact
// contacts, and contacts moved by one ulp, with witnesses, at d = 0 and d > 0.

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/detect/result.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/io/wkt.hpp"
#include "support/process.hpp"
#include "verification/cgal_reference.hpp"

using namespace influence2d;
using namespace test_process;

namespace {

/// The `edges` field of FRAMES.csv for a list of pairs.
std::string edges_field(const std::vector<edge_pair>& pairs) {
    std::string s;
    for (const auto& p : pairs) {
        if (!s.empty()) s += ';';
        s += std::to_string(p.static_edge) + ":" + std::to_string(p.moving_edge);
    }
    return s;
}

/// Poses for one scene: random ones near A and exact vertex-on-vertex and
/// vertex-on-midpoint contacts (theta = 0; the family coordinates lie on a
/// 2^-20 grid, so t = a - q is exact), each also moved away by one ulp.
std::vector<pose> scene_poses(const polygon& a, const polygon& b, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const auto unit = [&] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
    std::vector<pose> poses;
    const double reach = bounding_radius(a, a.centroid()) + bounding_radius(b, b.centroid());
    for (int k = 0; k < 60; ++k) {
        const double r = reach * (0.5 + 0.6 * unit()), phi = 6.283185307179586 * unit();
        const point<double> c = b.centroid();
        poses.push_back({a.centroid().x + r * std::cos(phi) - c.x, a.centroid().y + r * std::sin(phi) - c.y,
                         6.283185307179586 * unit()});
    }
    for (int k = 0; k < 40; ++k) {
        const std::size_t i = rng() % a.size(), j = rng() % b.size();
        point<double> target = a.vertex(i);
        if (k % 2) {
            const point<double>& e = a.vertex(a.next(i));
            target = {(target.x + e.x) / 2, (target.y + e.y) / 2};
        }
        const pose touching{target.x - b.vertex(j).x, target.y - b.vertex(j).y, 0};
        poses.push_back(touching);
        // One ulp further out, in x, away from A's centroid.
        const double out = target.x > a.centroid().x ? 1e300 : -1e300;
        poses.push_back({std::nextafter(touching.tx, out), touching.ty, 0});
    }
    return poses;
}

}  // namespace

TEST_CASE("cli collide: exact answers equal the CGAL reference on every frame", "[cli][exact]") {
    const std::string data = INFLUENCE2D_DATA_DIR;
    const std::vector<std::pair<std::string, std::string>> scenes{{"contour_16", "irregular_8"},
                                                                  {"hole_32", "starred_16"},
                                                                  {"convex_8", "contour_32"},
                                                                  {"starred_64", "hole_16"}};
    temp_dir dir;
    std::size_t frames = 0, collisions = 0, separated_by_an_ulp = 0;
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        const std::string a_path = data + "/families/" + scenes[s].first + ".wkt";
        const std::string b_path = data + "/families/" + scenes[s].second + ".wkt";
        const polygon a = read_wkt_file(a_path), b = read_wkt_file(b_path);
        const auto poses = scene_poses(a, b, 100 + s);
        std::ostringstream csv;
        csv.precision(17);
        csv << "tx,ty,theta\n";
        for (const auto& p : poses) csv << p.tx << ',' << p.ty << ',' << p.theta << '\n';
        const auto poses_path = dir.file("poses.csv", csv.str());
        for (const double d : {0.0, 0.5}) {
            INFO("scene " << scenes[s].first << " / " << scenes[s].second << ", d = " << d);
            std::ostringstream args;
            args << "collide --static " << quote(a_path) << " --moving " << quote(b_path) << " --poses "
                 << quote(poses_path.string()) << " --number-type exact --witness --distance " << d << " --out "
                 << quote((dir / "frames.csv").string());
            const run_result r = run_cli(dir, args.str());
            REQUIRE(r.exit_code == 0);
            const auto rows = lines_of(slurp(dir / "frames.csv"));
            REQUIRE(rows.size() == poses.size() + 1);
            CHECK(rows[0] == "frame,collides,edges");
            verification::cgal_reference reference(a, b, d, true);
            bool previous = false;
            for (std::size_t k = 0; k < poses.size(); ++k) {
                const frame_result expected = reference.collide(poses[k]);
                // Touching frames are followed by their one-ulp shift (from frame 60 on, in pairs).
                if (d == 0 && k >= 60 && k % 2 == 1 && previous && !expected.collides) ++separated_by_an_ulp;
                previous = expected.collides;
                INFO("frame " << k);
                CHECK(rows[k + 1] ==
                      std::to_string(k) + "," + (expected.collides ? "1" : "0") + "," + edges_field(expected.pairs));
                ++frames;
                collisions += expected.collides;
            }
        }
    }
    CHECK(collisions > frames / 4);
    CHECK(frames - collisions > frames / 10);
    CHECK(separated_by_an_ulp >= 8);  // exact contacts that one ulp undoes (10 with these seeds)
}
