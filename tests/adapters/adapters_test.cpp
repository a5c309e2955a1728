// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <list>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <boost/geometry/core/cs.hpp>
#include <boost/geometry/geometries/adapted/std_array.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

#include "influence2d/adapters/boost_geometry.hpp"
#include "influence2d/adapters/cgal.hpp"
#include "influence2d/adapters/traits.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/number/cgal.hpp"

// std::array as a Boost.Geometry point too: the two adapters must not clash.
BOOST_GEOMETRY_REGISTER_STD_ARRAY_CS(boost::geometry::cs::cartesian)

using namespace influence2d;
namespace bg = boost::geometry;

namespace {

/// A caller's own point type, with its own member names and float coordinates.
struct survey_mark {
    float east;
    float north;
};

}  // namespace

template <>
struct influence2d::point_traits<survey_mark> {
    static double x(const survey_mark& p) { return p.east; }
    static double y(const survey_mark& p) { return p.north; }
};

namespace {

using xy = std::array<double, 2>;
using epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using exact_kernel = CGAL::Simple_cartesian<exact_rational>;

// The test shapes, open, in input order: the square [0,8]^2 counter-clockwise
// with the hole [2,6]^2 given counter-clockwise too (the polygon reverses it),
// and a second outer ring, a clockwise triangle right of the square.
const std::vector<xy> outer_square{{0, 0}, {8, 0}, {8, 8}, {0, 8}};
const std::vector<xy> square_hole{{2, 2}, {6, 2}, {6, 6}, {2, 6}};
const std::vector<xy> side_triangle{{10, 0}, {10, 3}, {12, 0}};

std::vector<point<double>> to_points(const std::vector<xy>& ring) {
    std::vector<point<double>> out;
    for (const xy& p : ring) out.push_back({p[0], p[1]});
    return out;
}

polygon hand_built(const std::vector<std::pair<std::vector<xy>, ring_role>>& rings) {
    std::vector<ring_input> in;
    for (const auto& [ring, role] : rings) in.push_back(ring_input{to_points(ring), role});
    return polygon(in);
}

polygon hand_square() { return hand_built({{outer_square, ring_role::outer}}); }
polygon hand_square_with_hole() {
    return hand_built({{outer_square, ring_role::outer}, {square_hole, ring_role::hole}});
}

template <class Ring>
Ring closed(Ring ring) {
    ring.push_back(ring.front());
    return ring;
}

/// The same vertices, rings, roles, edge links, source edge numbers, area and
/// centroid.
void require_same(const polygon& got, const polygon& want) {
    REQUIRE(got.size() == want.size());
    REQUIRE(got.ring_count() == want.ring_count());
    for (std::size_t r = 0; r < want.ring_count(); ++r) {
        CHECK(got.ring_begin(r) == want.ring_begin(r));
        CHECK(got.role(r) == want.role(r));
    }
    for (std::size_t i = 0; i < want.size(); ++i) {
        CHECK(got.vertex(i) == want.vertex(i));
        CHECK(got.next(i) == want.next(i));
        CHECK(got.source_edge(i) == want.source_edge(i));
    }
    CHECK(got.centroid() == want.centroid());
    CHECK(got.area() == want.area());
}

/// The ring's points as P, with coordinates of type C.
template <class P, class C = double>
std::vector<P> convert_ring(const std::vector<xy>& ring) {
    std::vector<P> out;
    for (const xy& p : ring) out.push_back(P{static_cast<C>(p[0]), static_cast<C>(p[1])});
    return out;
}

template <class Poly>
Poly bg_polygon(const std::vector<std::vector<xy>>& rings, bool close) {
    using P = typename bg::point_type<Poly>::type;
    Poly poly;
    for (std::size_t r = 0; r < rings.size(); ++r) {
        auto pts = convert_ring<P, typename bg::coordinate_type<P>::type>(close ? closed(rings[r]) : rings[r]);
        if (r == 0) {
            poly.outer().assign(pts.begin(), pts.end());
        } else {
            poly.inners().emplace_back(pts.begin(), pts.end());
        }
    }
    return poly;
}

template <class K>
CGAL::Polygon_2<K> cgal_ring(const std::vector<xy>& ring) {
    const auto pts = convert_ring<typename K::Point_2>(ring);
    return CGAL::Polygon_2<K>(pts.begin(), pts.end());
}

template <class K>
CGAL::Polygon_with_holes_2<K> cgal_square_with_hole() {
    CGAL::Polygon_with_holes_2<K> p(cgal_ring<K>(outer_square));
    p.add_hole(cgal_ring<K>(square_hole));
    return p;
}

}  // namespace

// What counts as a point and a ring, decided at compile time.
static_assert(is_point_v<xy> && is_point_v<std::pair<int, int>> && is_point_v<point<float>>);
static_assert(is_point_v<survey_mark> && is_point_v<bg::model::d2::point_xy<double>>);
static_assert(is_point_v<epeck::Point_2> && is_point_v<exact_kernel::Point_2>);
static_assert(!is_point_v<int> && !is_point_v<std::array<double, 3>> && !is_point_v<std::pair<double, int>>);
static_assert(!is_point_v<bg::model::point<double, 3, bg::cs::cartesian>>);
static_assert(!is_point_v<bg::model::point<double, 2, bg::cs::geographic<bg::degree>>>);
static_assert(is_ring_v<std::vector<xy>> && is_ring_v<std::list<survey_mark>> && is_ring_v<xy[3]>);
static_assert(!is_ring_v<xy> && !is_ring_v<bg::model::polygon<bg::model::d2::point_xy<double>>>);
static_assert(is_ring_range_v<std::vector<std::vector<xy>>> && !is_ring_range_v<std::vector<xy>>);

TEST_CASE("adapters: standard and own point types give the hand-built polygon, open or closed", "[adapters]") {
    const polygon want = hand_square();
    require_same(make_polygon(outer_square), want);
    require_same(make_polygon(closed(outer_square)), want);
    require_same(make_polygon(convert_ring<std::pair<double, double>>(outer_square)), want);
    require_same(make_polygon(closed(convert_ring<std::pair<int, int>, int>(outer_square))), want);
    require_same(make_polygon(convert_ring<point<long double>, long double>(outer_square)), want);
    const xy plain_array[4] = {outer_square[0], outer_square[1], outer_square[2], outer_square[3]};
    require_same(make_polygon(plain_array), want);
    std::list<survey_mark> marks;
    for (const xy& p : closed(outer_square)) marks.push_back({static_cast<float>(p[0]), static_cast<float>(p[1])});
    require_same(make_polygon(marks), want);

    // A clockwise ring is reversed, and the source edges keep the input's
    // numbering: the same polygon as the hand-built clockwise one.
    const std::vector<xy> clockwise(outer_square.rbegin(), outer_square.rend());
    const polygon cw = make_polygon(closed(clockwise));
    require_same(cw, hand_built({{clockwise, ring_role::outer}}));
    CHECK(cw.source_edge(0) != 0);
}

TEST_CASE("adapters: only a closing repetition is dropped, not a repeat of the first point before it", "[adapters]") {
    // Closed, with the first point repeated once before the closing one: the
    // repeat stays as a zero-length edge, as any other repeated point does.
    std::vector<xy> ring = closed(outer_square);
    ring.push_back(outer_square[0]);
    const polygon p = make_polygon(ring);
    REQUIRE(p.size() == 5);
    CHECK(p.vertex(4) == p.vertex(0));
    polygon_builder b;
    b.add_outer(ring);
    REQUIRE(b.rings().size() == 1);
    CHECK(b.rings()[0].vertices.size() == ring.size());
    require_same(b.build(), p);
}

TEST_CASE("adapters: holes and several outer rings", "[adapters]") {
    const std::vector<std::vector<xy>> holes{closed(square_hole)};
    require_same(make_polygon(outer_square, holes), hand_square_with_hole());
    const polygon several = polygon_builder()
                                .add_outer(closed(outer_square))
                                .add_hole(square_hole)
                                .add_outer(convert_ring<std::pair<double, double>>(side_triangle))
                                .build();
    require_same(several, hand_built({{outer_square, ring_role::outer},
                                      {square_hole, ring_role::hole},
                                      {side_triangle, ring_role::outer}}));
    // A repeated point other than the closing one stays as a zero-length edge.
    const std::vector<xy> repeated{{0, 0}, {8, 0}, {8, 0}, {8, 8}, {0, 8}, {0, 0}};
    CHECK(make_polygon(repeated).size() == 5);
}

TEST_CASE("adapters: Boost.Geometry models give the hand-built polygon", "[adapters]") {
    const polygon want = hand_square_with_hole();
    // The default model is clockwise and closed; the rings here are given
    // counter-clockwise and both closed and open: all read the same.
    using xy_polygon = bg::model::polygon<bg::model::d2::point_xy<double>>;
    require_same(make_polygon(bg_polygon<xy_polygon>({outer_square, square_hole}, true)), want);
    require_same(make_polygon(bg_polygon<xy_polygon>({outer_square, square_hole}, false)), want);
    using open_ccw = bg::model::polygon<bg::model::point<double, 2, bg::cs::cartesian>, false, false>;
    require_same(make_polygon(bg_polygon<open_ccw>({outer_square, square_hole}, false)), want);
    using array_polygon = bg::model::polygon<xy, false, false>;
    require_same(make_polygon(bg_polygon<array_polygon>({outer_square, square_hole}, true)), want);
    using int_polygon = bg::model::polygon<bg::model::d2::point_xy<int>>;
    require_same(make_polygon(bg_polygon<int_polygon>({outer_square, square_hole}, true)), want);
    // A ring on its own is a range of points.
    require_same(make_polygon(bg_polygon<xy_polygon>({outer_square}, true).outer()), hand_square());

    bg::model::multi_polygon<xy_polygon> parts;
    parts.push_back(bg_polygon<xy_polygon>({outer_square, square_hole}, true));
    parts.push_back(bg_polygon<xy_polygon>({side_triangle}, true));
    require_same(make_polygon(parts), hand_built({{outer_square, ring_role::outer},
                                                  {square_hole, ring_role::hole},
                                                  {side_triangle, ring_role::outer}}));
}

TEST_CASE("adapters: CGAL polygons of any kernel give the hand-built polygon", "[adapters]") {
    require_same(make_polygon(cgal_ring<epick>(outer_square)), hand_square());
    require_same(make_polygon(cgal_ring<exact_kernel>(outer_square)), hand_square());
    const polygon want = hand_square_with_hole();
    require_same(make_polygon(cgal_square_with_hole<epick>()), want);
    require_same(make_polygon(cgal_square_with_hole<epeck>()), want);
    require_same(make_polygon(cgal_square_with_hole<exact_kernel>()), want);

    std::vector<CGAL::Polygon_with_holes_2<epeck>> parts{
        cgal_square_with_hole<epeck>(), CGAL::Polygon_with_holes_2<epeck>(cgal_ring<epeck>(side_triangle))};
    require_same(make_polygon(parts), hand_built({{outer_square, ring_role::outer},
                                                  {square_hole, ring_role::hole},
                                                  {side_triangle, ring_role::outer}}));
    // A lazy coordinate computed as (1/3) * 3 is exactly 1: accepted.
    const epeck::FT one = epeck::FT(1) / epeck::FT(3) * epeck::FT(3);
    const std::vector<epeck::Point_2> tri{{0, 0}, {one, 0}, {0, one}};
    require_same(make_polygon(tri), hand_built({{{{0, 0}, {1, 0}, {0, 1}}, ring_role::outer}}));
}

TEST_CASE("adapters: a square with a hole answers the same from every source", "[adapters]") {
    const polygon moving = make_polygon(std::vector<xy>{{0, 0}, {1, 0}, {0, 1}});
    using xy_polygon = bg::model::polygon<bg::model::d2::point_xy<double>>;
    const polygon sources[] = {make_polygon(bg_polygon<xy_polygon>({outer_square, square_hole}, true)),
                               make_polygon(cgal_square_with_hole<epeck>()),
                               make_polygon(cgal_square_with_hole<exact_kernel>())};
    const pose poses[] = {
        {3, 3, 0},      // inside the hole: apart
        {5.5, 3, 0},    // across the hole's right side
        {1, 1, 0},      // inside the solid part: containment, no pair
        {8, 4, 0.3},    // a vertex on the outer right side
        {9, 9, 0},      // outside
        {1.5, 5.5, 2},  // turned, across the hole's left side
    };
    detector_options options;
    options.witness = true;
    detector<double> want(hand_square_with_hole(), moving, options);
    detector<exact_rational> want_exact(hand_square_with_hole(), moving, options);
    std::size_t collisions = 0, pairs = 0;
    for (const pose& q : poses) {
        const frame_result w = want.collide(q);
        CHECK(want_exact.collide(q).pairs == w.pairs);
        collisions += w.collides;
        pairs += w.pairs.size();
        for (const polygon& a : sources) {
            detector<double> d(a, moving, options);
            const frame_result got = d.collide(q);
            CHECK(got.collides == w.collides);
            CHECK(got.pairs == w.pairs);
        }
    }
    // Not a vacuous comparison: some frames collide, some with witness pairs.
    CHECK(collisions == 4);
    CHECK(pairs >= 4);
}

TEST_CASE("adapters: invalid input is refused with ring and vertex", "[adapters]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_WITH(make_polygon(std::vector<xy>{{0, 0}, {1, nan}, {1, 1}}),
                      Catch::Contains("ring 0, vertex 1") && Catch::Contains("not a finite number"));
    CHECK_THROWS_WITH(make_polygon(outer_square, std::vector<std::vector<xy>>{{{2, 2}, {3, 2}, {nan, 3}}}),
                      Catch::Contains("ring 1, vertex 2"));
    CHECK_THROWS_WITH(make_polygon(std::vector<xy>{{0, 0}, {1, 0}, {0, 0}, {1, 0}, {0, 0}}),
                      Catch::Contains("ring 0: fewer than three distinct vertices"));
    CHECK_THROWS_AS(make_polygon(std::vector<xy>{}), invalid_input);
    CHECK_THROWS_AS(polygon_builder().build(), invalid_input);

    // Integers: up to 2^53 in magnitude they are doubles; beyond, refused.
    const std::int64_t two53 = std::int64_t{1} << 53, two60 = std::int64_t{1} << 60;
    using int_xy = std::array<std::int64_t, 2>;
    CHECK(make_polygon(std::vector<int_xy>{{0, 0}, {two53, 0}, {0, -two53}}).size() == 3);
    CHECK_THROWS_WITH(make_polygon(std::vector<int_xy>{{0, 0}, {1, 0}, {0, two60}}),
                      Catch::Contains("ring 0, vertex 2: y: integer 1152921504606846976"));
    CHECK_THROWS_WITH(make_polygon(std::vector<int_xy>{{0, 0}, {-two53 - 1, 0}, {0, 1}}),
                      Catch::Contains("ring 0, vertex 1: x"));
    CHECK_THROWS_WITH(make_polygon(std::vector<std::pair<std::uint64_t, std::uint64_t>>{{0, 0}, {1, 0}, {0, ~0ull}}),
                      Catch::Contains("ring 0, vertex 2: y"));
    using big_polygon = bg::model::polygon<bg::model::d2::point_xy<long long>>;
    big_polygon big;
    big.outer() = {{0, 0}, {two60, 0}, {0, 1}, {0, 0}};
    CHECK_THROWS_WITH(make_polygon(big), Catch::Contains("ring 0, vertex 1: x: integer"));
    // A long double that is not a double is refused, not rounded.
    if constexpr (std::numeric_limits<long double>::digits > 53) {
        CHECK_THROWS_WITH(make_polygon(std::vector<point<long double>>{{0, 0}, {1, 0}, {0, 0.1L}}),
                          Catch::Contains("ring 0, vertex 2: y: value 0.1"));
    }

    // Exact CGAL coordinates that no double equals.
    const exact_rational third = exact_rational(1) / exact_rational(3);
    CHECK_THROWS_WITH(make_polygon(std::vector<exact_kernel::Point_2>{{0, 0}, {1, 0}, {third, 1}}),
                      Catch::Contains("ring 0, vertex 2: x: value is not exactly a double"));
    CGAL::Polygon_with_holes_2<epeck> with_hole = cgal_square_with_hole<epeck>();
    with_hole.add_hole(cgal_ring<epeck>({{7, 7}, {7.5, 7}, {7, 7.5}}));
    CHECK_NOTHROW(make_polygon(with_hole));
    CGAL::Polygon_2<epeck> bad_hole;
    bad_hole.push_back({7, 7});
    bad_hole.push_back({epeck::FT(7) + epeck::FT(1) / epeck::FT(3), 7});
    bad_hole.push_back({7, 7.5});
    with_hole.add_hole(bad_hole);
    CHECK_THROWS_WITH(make_polygon(with_hole), Catch::Contains("ring 3, vertex 1: x"));
    const exact_rational huge = exact_rational(std::ldexp(1.0, 1000)) * exact_rational(std::ldexp(1.0, 1000));
    CHECK_THROWS_WITH(make_polygon(std::vector<exact_kernel::Point_2>{{0, 0}, {1, 0}, {0, huge}}),
                      Catch::Contains("ring 0, vertex 2: y: value is beyond the range of double"));
    CHECK_THROWS_WITH(make_polygon(CGAL::Polygon_with_holes_2<epick>()), Catch::Contains("ring 0: unbounded"));
    CHECK_THROWS_AS(make_polygon(std::vector<CGAL::Polygon_with_holes_2<epick>>{}), invalid_input);
    CHECK_THROWS_AS(make_polygon(bg::model::multi_polygon<big_polygon>{}), invalid_input);
}
