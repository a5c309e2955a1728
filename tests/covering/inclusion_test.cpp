// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include "influence2d/covering/inclusion.hpp"
#include "influence2d/number/certified.hpp"
#include "influence2d/number/cgal.hpp"
#include "support/exact_regions.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

template <class NT>
location where(const triangle_covering<NT>& cov, double x, double y) {
    return locate(cov, point<NT>{number_traits<NT>::from_double(x), number_traits<NT>::from_double(y)});
}

TEMPLATE_TEST_CASE("inclusion: square with a hole", "[inclusion]", INFLUENCE2D_NUMBER_TYPES) {
    //  +--------+ 8
    //  |  +--+  |
    //  |  |  |  |   hole [2,6]^2; the centroid (4,4) lies in the hole
    //  |  +--+  |
    //  +--------+ 0
    const polygon p = test_shapes::square_with_hole();
    const triangle_covering<TestType> cov(p, p.centroid());
    CHECK(where(cov, 1, 1) == location::inside);
    CHECK(where(cov, 7, 4) == location::inside);
    CHECK(where(cov, 4, 4) == location::outside);  // the origin itself, in the hole
    CHECK(where(cov, 3, 5) == location::outside);
    CHECK(where(cov, 2, 3) == location::boundary);  // on the hole's edge
    CHECK(where(cov, 6, 6) == location::boundary);  // a hole vertex
    CHECK(where(cov, 0, 8) == location::boundary);
    CHECK(where(cov, 9, 4) == location::outside);
    CHECK(where(cov, 1, 4) == location::inside);  // level with O, between the outer and hole edges
    CHECK(where(cov, 1, 7) == location::inside);  // on the side O-(0,8): counted half twice
}

TEMPLATE_TEST_CASE("inclusion: points on the sides O-V_i count half in each triangle", "[inclusion]",
                   INFLUENCE2D_NUMBER_TYPES) {
    // Square [0,4]^2, origin (2,2): the diagonals are the shared sides O-V_i.
    //   (0,4)+-----+(4,4)
    //        | \ / |
    //        |  O  |   P = (1,1) lies on O-(0,0): half of T_3 and half of T_0
    //        | / \ |
    //   (0,0)+-----+(4,0)
    const polygon sq = test_shapes::square(0, 0, 4);
    const triangle_covering<TestType> cov(sq, sq.centroid());
    CHECK(where(cov, 1, 1) == location::inside);
    CHECK(where(cov, 3, 3) == location::inside);
    CHECK(where(cov, 2, 2) == location::inside);   // the origin: summed from a vertex instead
    CHECK(where(cov, 5, 5) == location::outside);  // on the diagonal's extension
}

TEMPLATE_TEST_CASE("inclusion: centroid outside the polygon", "[inclusion]", INFLUENCE2D_NUMBER_TYPES) {
    const polygon c = test_shapes::c_shape();
    const triangle_covering<TestType> cov(c, c.centroid());
    REQUIRE(c.centroid().x > 1);  // in the opening
    CHECK(where(cov, c.centroid().x, c.centroid().y) == location::outside);
    CHECK(where(cov, 0.5, 3) == location::inside);
    CHECK(where(cov, 5, 0.5) == location::inside);
    CHECK(where(cov, 5, 3) == location::outside);
    CHECK(where(cov, 1, 3) == location::boundary);
}

TEMPLATE_TEST_CASE("inclusion: non-manifold rings touching at a vertex", "[inclusion]", INFLUENCE2D_NUMBER_TYPES) {
    //        +--+ (2,2)
    //        |  |
    //   +----+--+ (1,1) shared vertex
    //   |  |
    //   +--+ (0,0)
    const polygon p({test_shapes::square_ring(0, 0, 1), test_shapes::square_ring(1, 1, 1)});
    const triangle_covering<TestType> cov(p, p.centroid());  // origin (1,1): the shared vertex
    CHECK(where(cov, 1, 1) == location::boundary);
    CHECK(where(cov, 0.5, 0.5) == location::inside);
    CHECK(where(cov, 1.5, 1.5) == location::inside);
    CHECK(where(cov, 0.5, 1.5) == location::outside);
    CHECK(where(cov, 1.5, 0.5) == location::outside);
}

TEMPLATE_TEST_CASE("inclusion: collinear runs and repeated vertices", "[inclusion]", INFLUENCE2D_NUMBER_TYPES) {
    // (0,0) (1,0) (1,0) (2,0) (4,0) (4,4) (0,4): a repeated vertex and a collinear run.
    const polygon p({test_shapes::ring({{0, 0}, {1, 0}, {1, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}})});
    const triangle_covering<TestType> cov(p, p.centroid());
    CHECK(where(cov, 1, 0) == location::boundary);
    CHECK(where(cov, 3, 0) == location::boundary);
    CHECK(where(cov, 1, 1) == location::inside);
    CHECK(where(cov, 1, -1) == location::outside);
}

TEST_CASE("inclusion: exact on a point 2^-60 inside an edge", "[inclusion]") {
    const polygon sq = test_shapes::square(0, 0, 1);
    const triangle_covering<exact_rational> cov(sq, sq.centroid());
    CHECK(where(cov, 0.5, 0x1p-60) == location::inside);
    CHECK(where(cov, 0.5, -0x1p-60) == location::outside);
    CHECK(where(cov, 0.5, 0) == location::boundary);
}

namespace {

/// P where it stands (vertices in NT) located by crossings, for the test below.
template <class NT>
location by_crossings(const polygon& shape, double x, double y) {
    std::vector<point<NT>> v;
    for (const point<double>& q : shape.vertices()) v.push_back(to_point<NT>(q));
    return locate_by_crossings(shape, v, to_point<NT>(point<double>{x, y}));
}

}  // namespace

TEST_CASE("inclusion: locate_by_crossings against Feito's test and an exact reference", "[inclusion]") {
    // Messy rings (nested, overlapping, self-crossing, repeated vertices,
    // holes outside every shell) on a grid, and points on the grid: at
    // vertices, on edges, on the horizontal lines through vertices, and at
    // random. Every type answers exactly there (grid values are exact in
    // float too); the three locations agree, and the reference's closed
    // region is the same.
    test_scenes::rng g(31);
    std::size_t counts[3] = {0, 0, 0};
    for (int round = 0; round < 300; ++round) {
        const polygon p(test_scenes::random_messy(g, 8, 6));
        const test_exact::placed_shape exact = test_exact::place(p, pose{});
        const std::vector<point<exact_rational>> v = [&] {
            std::vector<point<exact_rational>> out;
            for (const point<double>& q : p.vertices()) out.push_back(to_point<exact_rational>(q));
            return out;
        }();
        for (int k = 0; k < 40; ++k) {
            point<double> q;
            const std::size_t i = g.index(p.size());
            switch (k % 4) {
            case 0: q = p.vertex(i); break;
            case 1:
                q = test_scenes::snap(point<double>{(p.vertex(i).x + p.vertex(p.next(i)).x) / 2,
                                                    (p.vertex(i).y + p.vertex(p.next(i)).y) / 2});
                break;
            case 2: q = {test_scenes::snap(g.uniform(-20, 20)), p.vertex(i).y}; break;
            default: q = test_scenes::snap(point<double>{g.uniform(-20, 20), g.uniform(-20, 20)});
            }
            const point<exact_rational> qe = to_point<exact_rational>(q);
            const location feito = locate(p, v, to_point<exact_rational>(p.centroid()), qe);
            const location crossing = locate_by_crossings(p, v, qe);
            INFO("round " << round << " point (" << q.x << ", " << q.y << ")");
            REQUIRE(crossing == feito);
            REQUIRE((crossing != location::outside) == test_exact::in_region(exact, test_exact::point_2(q.x, q.y)));
            CHECK(by_crossings<double>(p, q.x, q.y) == crossing);
            CHECK(by_crossings<certified>(p, q.x, q.y) == crossing);
            ++counts[static_cast<int>(crossing)];
        }
    }
    // Every answer was met many times.
    CHECK(counts[0] > 500);
    CHECK(counts[1] > 500);
    CHECK(counts[2] > 500);
}

TEST_CASE("inclusion: locate_by_crossings filtered in double equals it in exact rationals", "[inclusion]") {
    // The doubles of the vertices and of the point each moved by -e, 0 or
    // +e on each coordinate (the filter's promise at its limit), e near the
    // grid's step so that many ends sit within 2e of the point's height or
    // abscissa; edge by edge, and by runs of three edges: the answer is the
    // exact one, and the doubles settle most edges (a vertex in NT is asked
    // for the others only).
    test_scenes::rng g(57);
    const double e = test_scenes::grid * 0.75;
    std::size_t asked = 0, edges = 0, counts[3] = {0, 0, 0};
    const std::size_t run_length = 3;
    const std::vector<box> no_runs;
    const auto moved = [&](point<double> q) {
        const double steps[3] = {-e, 0, e};
        return point<double>{q.x + steps[g.index(3)], q.y + steps[g.index(3)]};
    };
    for (int round = 0; round < 300; ++round) {
        const polygon p(test_scenes::random_messy(g, 8, 6));
        std::vector<point<exact_rational>> v;
        std::vector<point<double>> approx;
        for (const point<double>& q : p.vertices()) {
            v.push_back(to_point<exact_rational>(q));
            approx.push_back(moved(q));
        }
        // Runs of three edges, some across the end of a ring.
        std::vector<box> runs((p.size() + run_length - 1) / run_length);
        for (std::size_t i = 0; i < p.size(); ++i) {
            runs[i / run_length].add(approx[i]);
            runs[i / run_length].add(approx[p.next(i)]);
        }
        for (int k = 0; k < 40; ++k) {
            point<double> q;
            const std::size_t i = g.index(p.size());
            switch (k % 4) {
            case 0: q = p.vertex(i); break;
            case 1: q = {test_scenes::snap(g.uniform(-20, 20)), p.vertex(i).y}; break;
            case 2: q = {p.vertex(i).x, test_scenes::snap(g.uniform(-20, 20))}; break;
            default: q = test_scenes::snap(point<double>{g.uniform(-20, 20), g.uniform(-20, 20)});
            }
            const point<exact_rational> qe = to_point<exact_rational>(q);
            const location exact = locate_by_crossings(p, v, qe);
            const point<double> q_approx = moved(q);
            for (const std::vector<box>* r : {&no_runs, static_cast<const std::vector<box>*>(&runs)}) {
                const location filtered =
                    locate_by_crossings(p, approx, *r, run_length, q_approx, e, qe, [&](std::size_t j) {
                        ++asked;
                        return v[j];
                    });
                INFO("round " << round << " point (" << q.x << ", " << q.y << "), runs " << r->size());
                REQUIRE(filtered == exact);
            }
            edges += 2 * p.size();
            ++counts[static_cast<int>(exact)];
        }
    }
    CHECK(counts[0] > 500);
    CHECK(counts[1] > 500);
    CHECK(counts[2] > 500);
    // Two vertices per edge left to NT: most edges were settled in double.
    CHECK(asked < edges / 2);
}
