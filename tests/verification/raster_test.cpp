// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <cstddef>
#include <vector>

#include "influence2d/io/wkt.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "support/shapes.hpp"
#include "verification/cgal_reference.hpp"
#include "verification/families.hpp"
#include "verification/raster.hpp"

using namespace influence2d;
using verification::raster_peer;

TEST_CASE("raster baseline: pixels of both regions, holes respected, touching missed", "[raster]") {
    const polygon a = test_shapes::square(0, 0, 8);
    raster_peer<64> r(a, test_shapes::square(0, 0, 2));
    CHECK(r.collide({3, 3, 0}));         // deep inside
    CHECK(r.collide({7, 7, 0.3}));       // over a corner
    CHECK_FALSE(r.collide({20, 0, 0}));  // far
    // Edge on edge: the closed regions meet, no pixel centre is in both.
    CHECK_FALSE(r.collide({8, 3, 0}));
    // In a hole: the pixels there are not A's.
    const polygon holed = test_shapes::square_with_hole();  // 0..8 with a hole 2..6
    raster_peer<256> h(holed, test_shapes::square(0, 0, 1));
    CHECK_FALSE(h.collide({3.5, 3.5, 0}));
    CHECK(h.collide({0.5, 0.5, 0}));
    // A multipolygon: both parts count.
    const polygon two = read_wkt("MULTIPOLYGON(((0 0, 2 0, 2 2, 0 2, 0 0)), ((10 0, 12 0, 12 2, 10 2, 10 0)))");
    raster_peer<128> m(two, test_shapes::square(0, 0, 1));
    CHECK(m.collide({10.5, 0.5, 0}));
    CHECK(m.collide({0.5, 0.5, 0}));
    CHECK_FALSE(m.collide({5.5, 0.5, 0}));
}

TEST_CASE("raster baseline: against the exact answers, misses only, fewer at a finer grid", "[raster]") {
    // Family polygons nobody tuned the grid for, random poses near contact.
    std::size_t frames = 0, coarse_missed = 0, fine_missed = 0, invented = 0;
    for (auto f : {verification::family::starred, verification::family::with_hole, verification::family::contour}) {
        const polygon a = verification::make_family_polygon(f, 64, 11),
                      b = verification::make_family_polygon(f, 16, 12);
        const verification::cgal_reference exact(a, b);
        raster_peer<32> coarse(a, b);
        raster_peer<1024> fine(a, b);
        double ra = 0, rb = 0;
        for (const auto& v : a.vertices()) ra = std::max(ra, std::hypot(v.x - a.centroid().x, v.y - a.centroid().y));
        for (const auto& v : b.vertices()) rb = std::max(rb, std::hypot(v.x - b.centroid().x, v.y - b.centroid().y));
        for (const pose& p : random_poses(a, b, 400, 0.4 * (ra + rb), 1.1 * (ra + rb), 7)) {
            ++frames;
            const bool want = exact.collide(p).collides;
            const bool c = coarse.collide(p), fn = fine.collide(p);
            invented += (c && !want) + (fn && !want);
            coarse_missed += want && !c;
            fine_missed += want && !fn;
        }
    }
    INFO("frames " << frames << ", missed at 32: " << coarse_missed << ", at 1024: " << fine_missed);
    CHECK(invented == 0);
    CHECK(coarse_missed > 0);
    CHECK(fine_missed < coarse_missed);
}
