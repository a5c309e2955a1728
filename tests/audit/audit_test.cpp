// SPDX-License-Identifier: BSL-1.0
// The audit (include/influence2d/audit/audit.hpp): each kind of degeneracy
// found where it is, with the library's verdict; clean polygons give no
// finding. The command and the comparison with GEOS: audit_tool_test.cpp.

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "influence2d/audit/audit.hpp"
#include "influence2d/detect/brute_force.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/findings.hpp"
#include "verification/cgal_reference.hpp"

namespace {

using namespace influence2d;
using test_findings::audit_wkt;
using test_findings::of;

}  // namespace

TEST_CASE("audit: a clean polygon has no finding", "[audit]") {
    const audit_report r = audit_wkt("POLYGON((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))");
    CHECK(r.accepted);
    CHECK(r.findings.empty());
    CHECK(r.rings == 2);
    CHECK(r.vertices == 8);
}

TEST_CASE("audit: refused inputs say why and where", "[audit]") {
    SECTION("non-finite coordinate") {
        const audit_report r = audit_wkt("POLYGON((0 0, 4 0, nan 4, 0 4, 0 0))");
        CHECK_FALSE(r.accepted);
        const auto f = of(r, finding_kind::non_finite);
        REQUIRE(f.size() == 1);
        CHECK(f[0].ring == 0);
        CHECK(f[0].vertex == 2u);
        CHECK(f[0].rejects);
    }
    SECTION("unclosed ring") {
        const audit_report r = audit_wkt("POLYGON((0 0, 4 0, 4 4, 0 4))");
        CHECK_FALSE(r.accepted);
        CHECK(of(r, finding_kind::unclosed_ring).size() == 1);
        CHECK(r.rejection.find("not closed") != std::string::npos);
    }
    SECTION("fewer than three distinct vertices") {
        const audit_report r = audit_wkt("POLYGON((0 0, 4 0, 0 0, 4 0, 0 0))");
        CHECK_FALSE(r.accepted);
        CHECK(of(r, finding_kind::too_few_vertices).size() == 1);
    }
}

TEST_CASE("audit: vertices and edges", "[audit]") {
    SECTION("repeated vertex: a zero-length edge") {
        const audit_report r = audit_wkt("POLYGON((0 0, 4 0, 4 0, 4 4, 0 4, 0 0))");
        CHECK(r.accepted);
        const auto f = of(r, finding_kind::repeated_vertex);
        REQUIRE(f.size() == 1);
        CHECK(f[0].vertex == 1u);
    }
    SECTION("near-repeated vertex") {
        const audit_report r = audit_wkt("POLYGON((0 0, 4 0, 4 1e-13, 4 4, 0 4, 0 0))");
        CHECK(r.accepted);
        const auto f = of(r, finding_kind::near_repeated_vertex);
        REQUIRE(f.size() == 1);
        CHECK(f[0].vertex == 1u);
    }
    SECTION("collinear run and spike") {
        const audit_report run = audit_wkt("POLYGON((0 0, 2 0, 4 0, 4 4, 0 4, 0 0))");
        const auto c = of(run, finding_kind::collinear_run);
        REQUIRE(c.size() == 1);
        CHECK(c[0].vertex == 1u);
        CHECK(of(run, finding_kind::spike).empty());
        const audit_report spike = audit_wkt("POLYGON((0 0, 4 0, 6 0, 4 0, 4 4, 0 4, 0 0))");
        const auto s = of(spike, finding_kind::spike);
        REQUIRE(!s.empty());
        CHECK(s[0].vertex == 2u);
    }
    SECTION("self-intersection: a bow tie") {
        const audit_report r = audit_wkt("POLYGON((0 0, 4 4, 4 0, 0 4, 0 0))");
        CHECK(r.accepted);
        const auto f = of(r, finding_kind::self_intersection);
        REQUIRE(f.size() == 1);
        CHECK(std::min(*f[0].vertex, *f[0].other_vertex) == 0u);
        CHECK(std::max(*f[0].vertex, *f[0].other_vertex) == 2u);
    }
    SECTION("a near miss is not a self-intersection (exact)") {
        // Edge 2 ends 2^-50 short of edge 0's line: no contact.
        const audit_report r = audit_wkt("POLYGON((0 0, 4 0, 2 2, 2 8.881784197001252e-16, 1 3, 0 0))");
        CHECK(of(r, finding_kind::self_intersection).empty());
    }
}

TEST_CASE("audit: rings", "[audit]") {
    SECTION("clockwise outer ring, counter-clockwise hole") {
        const audit_report r = audit_wkt("POLYGON((0 0, 0 4, 4 4, 4 0, 0 0), (1 1, 2 1, 2 2, 1 2, 1 1))");
        CHECK(r.accepted);
        CHECK(of(r, finding_kind::reversed_orientation).size() == 2);
    }
    SECTION("hole outside its shell, and a hole touching it") {
        const audit_report out = audit_wkt("POLYGON((0 0, 4 0, 4 4, 0 4, 0 0), (5 5, 5 6, 6 6, 6 5, 5 5))");
        CHECK(of(out, finding_kind::hole_outside_shell).size() == 1);
        const audit_report touch = audit_wkt("POLYGON((0 0, 4 0, 4 4, 0 4, 0 0), (0 0, 1 2, 2 1, 0 0))");
        CHECK(of(touch, finding_kind::hole_outside_shell).empty());
        CHECK(!of(touch, finding_kind::rings_meet).empty());
        CHECK(of(touch, finding_kind::non_manifold_vertex).size() == 1);
    }
    SECTION("non-manifold vertex within a ring") {
        // Two squares joined at (2 2), one ring.
        const audit_report r = audit_wkt("POLYGON((0 0, 2 0, 2 2, 4 2, 4 4, 2 4, 2 2, 0 2, 0 0))");
        const auto f = of(r, finding_kind::non_manifold_vertex);
        REQUIRE(f.size() == 1);
        CHECK(f[0].vertex == 2u);
        CHECK(f[0].other_vertex == 6u);
    }
    SECTION("zero and near-zero area") {
        const audit_report zero = audit_wkt("POLYGON((0 0, 2 0, 4 0, 2 0, 0 0))");
        CHECK(of(zero, finding_kind::zero_area).size() == 1);
        const audit_report thin = audit_wkt("POLYGON((0 0, 4 0, 2 1e-14, 0 0))");
        CHECK(of(thin, finding_kind::near_zero_area).size() == 1);
        CHECK(of(thin, finding_kind::zero_area).empty());
    }
}

TEST_CASE("audit: turns and crossings are decided exactly, not in rounded double", "[audit]") {
    // Vertex 1 lies off the line from vertex 0 to vertex 2 by less than
    // double's rounding of the orientation determinant, which evaluates to 0
    // in double: not a collinear run.
    const point<double> a{0.5, 0.5}, b{11.504331949566337, 11.504331949566339}, c{24, 24};
    REQUIRE((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) == 0);
    const audit_report r = audit_rings({wkt_ring{{a, b, c, {0, 24}, a}, ring_role::outer}});
    CHECK(of(r, finding_kind::collinear_run).empty());
    CHECK(of(r, finding_kind::spike).empty());
    // The same vertex on the exact line is one.
    const audit_report on = audit_wkt("POLYGON((0.5 0.5, 11.5 11.5, 24 24, 0 24, 0.5 0.5))");
    CHECK(of(on, finding_kind::collinear_run).size() == 1);
}

TEST_CASE("audit: the centroid on an edge's line, and number ranges", "[audit]") {
    // A square's centroid (2 2) lies on the line of no edge; a half-turn
    // pinwheel's radial edges pass through it.
    CHECK(of(audit_wkt("POLYGON((0 0, 4 0, 4 4, 0 4, 0 0))"), finding_kind::centroid_on_edge_line).empty());
    const audit_report pin = audit_wkt("POLYGON((0 0, 4 0, 4 2, 2 2, 2 4, 0 4, 0 0))");  // L shape: none
    CHECK(of(pin, finding_kind::centroid_on_edge_line).empty());
    const audit_report star = audit_wkt("POLYGON((-2 -1, 0 0, 2 -1, 1 0, 2 1, 0 0, -2 1, -1 0, -2 -1))");
    CHECK(!of(star, finding_kind::centroid_on_edge_line).empty());  // edges through (0 0)

    const audit_report tenth = audit_wkt("POLYGON((0 0, 0.1 0, 0.1 0.1, 0 0.1, 0 0))");
    CHECK(!of(tenth, finding_kind::inexact_in_float).empty());
    CHECK(of(audit_wkt("POLYGON((0 0, 0.5 0, 0.5 0.5, 0 0))"), finding_kind::inexact_in_float).empty());
    const audit_report huge = audit_wkt("POLYGON((0 0, 1e300 0, 1e300 1e300, 0 0))");
    CHECK(!of(huge, finding_kind::beyond_float).empty());
    CHECK(!of(huge, finding_kind::beyond_double_products).empty());
    CHECK(huge.accepted);
}

TEST_CASE("audit: the detector on the degenerate inputs it accepts equals the references", "[audit][detector]") {
    // Each accepted degeneracy of the table in the README, as static and as
    // moving polygon, swept across a unit square in exact arithmetic: the
    // sound detector answers (and names witness edges) as the all-pairs test
    // and as the independent CGAL reference.
    const char* cases[] = {
        "POLYGON((0 0, 4 0, 4 0, 4 4, 0 4, 0 0))",                                 // repeated vertex
        "POLYGON((0 0, 4 0, 4 1e-13, 4 4, 0 4, 0 0))",                             // near-repeated vertex
        "POLYGON((0 0, 2 0, 4 0, 4 4, 0 4, 0 0))",                                 // collinear run
        "POLYGON((0 0, 4 0, 6 0, 4 0, 4 4, 0 4, 0 0))",                            // spike
        "POLYGON((0 0, 4 4, 4 0, 0 4, 0 0))",                                      // self-intersection
        "POLYGON((0 0, 0 4, 4 4, 4 0, 0 0), (1 1, 2 1, 2 2, 1 2, 1 1))",           // reversed rings
        "POLYGON((0 0, 4 0, 4 4, 0 4, 0 0), (5 5, 5 6, 6 6, 6 5, 5 5))",           // hole outside its shell
        "POLYGON((0 0, 4 0, 4 4, 0 4, 0 0), (0 0, 1 2, 2 1, 0 0))",                // hole touching its shell
        "POLYGON((0 0, 2 0, 2 2, 4 2, 4 4, 2 4, 2 2, 0 2, 0 0))",                  // non-manifold vertex
        "POLYGON((0 0, 2 0, 4 0, 2 0, 0 0))",                                      // zero area
        "POLYGON((0 0, 4 0, 2 1e-14, 0 0))",                                       // near-zero area
        "POLYGON((-2 -1, 0 0, 2 -1, 1 0, 2 1, 0 0, -2 1, -1 0, -2 -1))",           // centroid on edges' lines
        "MULTIPOLYGON(((0 0, 4 0, 4 4, 0 4, 0 0)), ((1 1, 3 1, 3 3, 1 3, 1 1)))",  // nested shells
        "POLYGON((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1), (1.5 1.5, 2.5 1.5, 2.5 2.5, 1.5 2.5, 1.5 "
        "1.5))",                                      // nested holes
        "POLYGON((0 0, 4 0, 4 4, 0 4, 0 0), EMPTY)",  // empty ring
    };
    const polygon unit = read_wkt("POLYGON((0 0, 1 0, 1 1, 0 1, 0 0))");
    detector_options o;
    o.witness = true;
    for (const char* wkt : cases) {
        const polygon p = read_wkt(wkt);
        for (int role = 0; role < 2; ++role) {
            const polygon& a = role == 0 ? p : unit;
            const polygon& b = role == 0 ? unit : p;
            detector<exact_rational> d(a, b, o);
            brute_force_detector<exact_rational> brute(a, b, o);
            const verification::cgal_reference reference(a, b, 0, true);
            for (int k = 0; k <= 160; ++k) {
                const pose q{-3 + 0.0625 * k, -2 + 0.05 * k, 0.01 * k};
                const frame_result got = d.collide(q), want = brute.collide(q), exact = reference.collide(q);
                INFO(wkt << (role == 0 ? " static" : " moving") << ", frame " << k);
                CHECK(got.collides == want.collides);
                CHECK(got.pairs == want.pairs);
                CHECK(got.collides == exact.collides);
                CHECK(got.pairs == exact.pairs);
            }
        }
    }
}

namespace {

/// Whether a small square (side 2^-6) at (x, y) meets the polygon, asked of
/// the exact detector and of the independent CGAL reference (which must agree).
bool probe(const polygon& p, double x, double y) {
    const polygon dot = read_wkt("POLYGON((0 0, 0.015625 0, 0.015625 0.015625, 0 0.015625, 0 0))");
    const bool got = detector<exact_rational>(p, dot).collide(pose{x, y, 0}).collides;
    CHECK(got == verification::cgal_reference(p, dot).collide(pose{x, y, 0}).collides);
    return got;
}

bool says(const finding& f, const std::string& words) {
    return f.effect.find(words) != std::string::npos || f.what.find(words) != std::string::npos;
}

}  // namespace

TEST_CASE("audit: its words agree with what the detector does", "[audit][region]") {
    SECTION("a figure eight has zero signed area but bounds both lobes") {
        const char* text = "POLYGON((0 0, 2 2, 2 0, 0 2, 0 0))";
        const auto f = of(audit_wkt(text), finding_kind::zero_area);
        REQUIRE(f.size() == 1);
        CHECK(says(f[0], "each lobe has winding number +1 or -1 and is region"));
        CHECK_FALSE(says(f[0], "bounds no region"));
        const polygon p = read_wkt(text);
        CHECK(probe(p, 0.2, 0.95));  // left lobe
        CHECK(probe(p, 1.7, 0.95));  // right lobe
        CHECK_FALSE(probe(p, 0.95, 0.2));
    }
    SECTION("a ring on one line bounds no region") {
        const auto f = of(audit_wkt("POLYGON((0 0, 2 0, 4 0, 2 0, 0 0))"), finding_kind::zero_area);
        REQUIRE(f.size() == 1);
        CHECK(says(f[0], "it bounds no region"));
    }
    SECTION("a hole outside its shell, and a hole inside a hole, are region") {
        const auto stray = of(audit_wkt("POLYGON((0 0, 10 0, 10 10, 0 10, 0 0), (20 4, 22 4, 22 6, 20 6, 20 4))"),
                              finding_kind::hole_outside_shell);
        REQUIRE(stray.size() == 1);
        CHECK(says(stray[0], "the hole's inside counts as region"));
        CHECK(probe(read_wkt("POLYGON((0 0, 10 0, 10 10, 0 10, 0 0), (20 4, 22 4, 22 6, 20 6, 20 4))"), 21, 5));
        const char* nested =
            "POLYGON((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 8 2, 8 8, 2 8, 2 2), (4 4, 6 4, 6 6, 4 6, 4 4))";
        const audit_report r = audit_wkt(nested);
        const auto inner = of(r, finding_kind::hole_outside_shell);
        REQUIRE(inner.size() == 1);
        CHECK(inner[0].ring == 2);
        const polygon p = read_wkt(nested);
        CHECK(probe(p, 5, 5));        // inside the inner hole: winding -1
        CHECK_FALSE(probe(p, 3, 3));  // inside the outer hole only: winding 0
        CHECK(probe(p, 1, 1));
    }
    SECTION("nested shells: the inner adds no region; a shell inside a stray hole cuts it out") {
        const char* shells = "MULTIPOLYGON(((0 0, 10 0, 10 10, 0 10, 0 0)), ((3 3, 7 3, 7 7, 3 7, 3 3)))";
        const auto f = of(audit_wkt(shells), finding_kind::nested_ring);
        REQUIRE(f.size() == 1);
        CHECK(f[0].ring == 1);
        CHECK(says(f[0], "winding number is 2, region as around it"));
        const polygon p = read_wkt(shells);
        CHECK(probe(p, 5, 5));
        CHECK(probe(p, 1, 1));
        // A stray hole (winding -1 inside) with a shell in it: winding 0 there;
        // a hole in the stray hole: winding -2, region.
        const char* cut =
            "MULTIPOLYGON(((0 0, 1 0, 1 1, 0 1, 0 0), (20 0, 30 0, 30 10, 20 10, 20 0)), ((24 4, 26 4, 26 6, 24 6, 24 "
            "4)))";
        const polygon q = read_wkt(cut);
        const auto g = of(audit_wkt(cut), finding_kind::nested_ring);
        REQUIRE(g.size() == 1);
        CHECK(g[0].ring == 2);
        CHECK(says(g[0], "not region"));
        CHECK_FALSE(probe(q, 25, 5));
        CHECK(probe(q, 21, 1));
        const char* hole_in_stray =
            "POLYGON((0 0, 1 0, 1 1, 0 1, 0 0), (20 0, 30 0, 30 10, 20 10, 20 0), (24 4, 26 4, 26 6, 24 6, 24 4))";
        const auto h = of(audit_wkt(hole_in_stray), finding_kind::nested_ring);
        REQUIRE(h.size() == 1);
        CHECK(says(h[0], "winding number is -2, region as around it"));
        CHECK(probe(read_wkt(hole_in_stray), 25, 5));
    }
    SECTION("size means extent: a short edge far from the origin") {
        // An edge of 1e-9 on a polygon of extent 4 placed at 1e6: not near
        // (2^-40 * 4 ~ 3.6e-12); it would be against the largest coordinate.
        const audit_report far = audit_wkt(
            "POLYGON((1000000 1000000, 1000004 1000000, 1000004 1000000.000000001, 1000004 1000004, "
            "1000000 1000004, 1000000 1000000))");
        CHECK(of(far, finding_kind::near_repeated_vertex).empty());
        const auto near =
            of(audit_wkt("POLYGON((0 0, 4 0, 4 1e-13, 4 4, 0 4, 0 0))"), finding_kind::near_repeated_vertex);
        REQUIRE(near.size() == 1);
        CHECK(says(near[0], "of the polygon's extent (the longer side of its bounding box)"));
    }
    SECTION("an empty ring is ignored, as GEOS and JTS read it") {
        const audit_report r = audit_wkt("POLYGON((0 0, 4 0, 4 4, 0 4, 0 0), EMPTY)");
        CHECK(r.accepted);
        const auto f = of(r, finding_kind::empty_ring);
        REQUIRE(f.size() == 1);
        CHECK_FALSE(f[0].rejects);
        CHECK(says(f[0], "ignored"));
        CHECK_FALSE(audit_wkt("POLYGON(EMPTY, (1 1, 2 1, 2 2, 1 1))").accepted);
    }
}
