// SPDX-License-Identifier: BSL-1.0
// First contact along a motion and the exit distance (motion/first_contact.hpp)
// against an independent exact reference (support/exact_regions.hpp: every
// vertex-edge contact time solved as a segment intersection on CGAL's
// Cartesian kernel over exact rationals, and the regions' meeting decided
// there at rational times): the cases that matter (tunneling, touching at
// the start, grazing, sliding, parallel edges, holes, multipolygons, the
// roles swapped) and random translations of the families and of random
// multipolygons.

#include <catch2/catch.hpp>

#include "support/effort.hpp"
#include "support/exact_regions.hpp"
#include "support/families.hpp"
#include "support/neighbours.hpp"
#include "support/poses.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/exact/certified_exit_distance.hpp"
#include "influence2d/exact/certified_first_contact.hpp"
#include "influence2d/exact/certified_intersects.hpp"
#include "influence2d/exact/certified_separation.hpp"
#include "influence2d/motion/exit_distance.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/motion/trajectory.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/number/double_word.hpp"
#include "influence2d/predicates/certain_nearest.hpp"
#include "influence2d/predicates/contact_time.hpp"
#include "influence2d/predicates/convexity.hpp"

namespace {

using namespace influence2d;
using test_exact::FT;
using test_exact::placed_shape;
using test_exact::vector_2;

/// p with its rings given again in their stored order and orientation, so
/// that its input numbering is its stored numbering (the reference then
/// reads features off the stored vertices).
polygon renumbered(const polygon& p) {
    std::vector<ring_input> rings;
    for (std::size_t r = 0; r < p.ring_count(); ++r) {
        ring_input in;
        in.role = p.role(r);
        for (std::size_t i = p.ring_begin(r); i < p.ring_end(r); ++i) in.vertices.push_back(p.vertex(i));
        rings.push_back(std::move(in));
    }
    return polygon(rings);
}

polygon outer_polygon(std::vector<point<double>> v) { return polygon({ring_input{std::move(v), ring_role::outer}}); }

polygon square(double x0, double y0, double x1, double y1) {
    return outer_polygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

std::string describe_motion(const polygon& a, const polygon& b, const pose& from, const pose& to) {
    std::ostringstream s;
    s.precision(17);
    s << "static " << a.size() << " vertices, moving " << b.size() << ", from " << from.tx << ',' << from.ty << ','
      << from.theta << " to " << to.tx << ',' << to.ty << ',' << to.theta;
    return s.str();
}

/// The exact scene of a translation: A, B at the start, the displacement.
struct exact_scene {
    placed_shape a, b0;
    vector_2 d;
    exact_scene(const polygon& pa, const polygon& pb, const pose& from, const pose& to)
        : a(test_exact::place(pa, 0, 0, 0)),
          b0(test_exact::place(pb, from)),
          d(FT(to.tx) - FT(from.tx), FT(to.ty) - FT(from.ty)) {}
    /// B at time t.
    placed_shape b_at(const FT& t) const { return test_exact::moved(b0, d * t); }
};

/// Whether the reported features touch at time t (stored numbering is input
/// numbering for the polygons of these tests).
bool features_touch(const exact_scene& s, const FT& t, const feature& fa, const feature& fb) {
    const placed_shape b = s.b_at(t);
    if (fa.kind == feature_kind::edge && fb.kind == feature_kind::vertex)
        return test_exact::on_edge(s.a, fa.index, b.v[fb.index]);
    if (fa.kind == feature_kind::vertex && fb.kind == feature_kind::edge)
        return test_exact::on_edge(b, fb.index, s.a.v[fa.index]);
    if (fa.kind == feature_kind::edge && fb.kind == feature_kind::edge)
        return test_exact::edges_meet(s.a, fa.index, b, fb.index);
    if (fa.kind == feature_kind::interior && fb.kind == feature_kind::vertex)
        return test_exact::in_region(s.a, b.v[fb.index]);
    if (fa.kind == feature_kind::vertex && fb.kind == feature_kind::interior)
        return test_exact::in_region(b, s.a.v[fa.index]);
    return false;
}

/// Counts, so that a run is seen not to be vacuous.
struct contact_tally {
    std::size_t motions = 0, at_start = 0, later = 0, none = 0;
    double worst_double = 0;  ///< the largest |time in double - exact time| seen
};

/// The largest error allowed to first_contact<double>'s time on these scenes
/// (coordinates up to about 100, motions up to about 400): each event time
/// is a quotient of two determinants of rounded posed coordinates, within a
/// few 1e-14 relative of the exact one except where a determinant nearly
/// cancels (a motion nearly parallel to the edge); 1e-9 leaves room for
/// those, and the test records the worst error seen.
constexpr double double_time_error = 1e-9;

/// Every mode of first_contact on a translation against the reference:
/// exact_rational exactly (the time; the regions meet then and not at a few
/// times before; the features touch then), certified the nearest double of
/// the exact time and the same features, double the same contact within
/// double_time_error (near-misses in double excepted: counted), or none
/// when `double_may_miss` (a contact exactly as the motion ends, which
/// double's rounded events may place just past it). Returns the certified
/// answer.
contact_result<double> check_translation(const polygon& a, const polygon& b, const pose& from, const pose& to,
                                         contact_tally& t, bool double_may_miss = false) {
    INFO(describe_motion(a, b, from, to));
    const exact_scene s(a, b, from, to);
    const std::optional<FT> expected = test_exact::first_contact(s.a, s.b0, s.d);
    const contact_result<exact_rational> ex = first_contact<exact_rational>(a, b, from, to);
    ++t.motions;
    REQUIRE(ex.contact == expected.has_value());
    const contact_result<double> ce = certified_first_contact(a, b, from, to);
    CHECK(ce.contact == ex.contact);
    const contact_result<double> db = first_contact<double>(a, b, from, to);
    if (!expected) {
        ++t.none;
        CHECK_FALSE(db.contact);
        return ce;
    }
    CHECK(ex.time == *expected);
    (ex.time == 0 ? t.at_start : t.later) += 1;
    CHECK(test_exact::regions_meet(s.a, s.b_at(ex.time)));
    CHECK(features_touch(s, ex.time, ex.static_feature, ex.moving_feature));
    if (ex.time > 0)
        for (const FT& before : std::vector<FT>{FT(0), ex.time / 2, ex.time * FT(1023) / FT(1024),
                                                ex.time * (FT(1) - FT(std::ldexp(1.0, -40)))})
            CHECK_FALSE(test_exact::regions_meet(s.a, s.b_at(before)));
    if (ce.contact) {
        CHECK(ce.time == test_exact::nearest_double(ex.time));
        CHECK(ce.static_feature.kind == ex.static_feature.kind);
        CHECK(ce.static_feature.index == ex.static_feature.index);
        CHECK(ce.moving_feature.kind == ex.moving_feature.kind);
        CHECK(ce.moving_feature.index == ex.moving_feature.index);
    }
    if (!double_may_miss) CHECK(db.contact);
    if (db.contact) {
        const double err = std::fabs(db.time - CGAL::to_double(ex.time));
        t.worst_double = std::max(t.worst_double, err);
        CHECK(err <= double_time_error);
    }
    return ce;
}

/// A translation of B from beyond A's reach through a random point near A
/// (at the same random angle): the start a random pose near contact, the
/// end across A.
std::pair<pose, pose> random_translation(const polygon& a, const polygon& b, test_scenes::rng& g, double reach) {
    const double theta = g.chance(0.3) ? 0 : g.uniform(-3.2, 3.2);
    const point<double> ca = a.centroid(), cb = b.centroid();
    const double phi = g.uniform(0, 6.283185307179586), rho = reach * g.uniform(0.3, 1.3);
    const point<double> start{ca.x + rho * std::cos(phi), ca.y + rho * std::sin(phi)};
    const double psi = phi + 3.141592653589793 + g.uniform(-1.5, 1.5), len = reach * g.uniform(0.1, 2.5);
    const point<double> end{start.x + len * std::cos(psi), start.y + len * std::sin(psi)};
    return {test_scenes::aimed(cb, start, theta), test_scenes::aimed(cb, end, theta)};
}

/// Checks that the exact contact x and the certified one r are the same:
/// contact, the time rounded, the features.
void check_same_contact(const contact_result<exact_rational>& x, const contact_result<double>& r) {
    CHECK(x.contact == r.contact);
    if (!x.contact) return;
    CHECK(nearest_double(x.time) == r.time);
    CHECK(x.static_feature.kind == r.static_feature.kind);
    CHECK(x.static_feature.index == r.static_feature.index);
    CHECK(x.moving_feature.kind == r.moving_feature.kind);
    CHECK(x.moving_feature.index == r.moving_feature.index);
}

/// Calls check(a, b, from, to) for `motions` random translations
/// (random_translation) of every family's A of n vertices against its B of
/// m, for n in `as` and m in `bs` (renumbered), B turned over the motion by
/// up to `turn` radians either way.
template <class Check>
void family_motions(std::initializer_list<std::size_t> as, std::initializer_list<std::size_t> bs, int motions,
                    std::uint64_t seed, double turn, Check&& check) {
    test_scenes::rng g(seed);
    for (test_families::family f : verification::all_families)
        for (std::size_t n : as)
            for (std::size_t m : bs) {
                const polygon a = renumbered(test_families::load(f, n));
                const polygon b = renumbered(test_families::load(f, m));
                const double reach = test_poses::reach(a, b);
                for (int k = 0; k < motions; ++k) {
                    auto [from, to] = random_translation(a, b, g, reach);
                    if (turn > 0) to.theta = from.theta + g.uniform(-turn, turn);
                    check(a, b, from, to);
                }
            }
}

}  // namespace

TEST_CASE("sweep: the tunneling square is caught", "[sweep]") {
    // A 2 x 2 square jumps from x = -10 to x = +10 across a wall 0.1 wide:
    // neither pose meets the wall, the motion does at t = 9 / 20.
    const polygon wall = square(0, -5, 0.1, 5), box = square(-1, -1, 1, 1);
    const pose from{-10, 0, 0}, to{10, 0, 0};
    CHECK_FALSE(certified_intersects(wall, box, from));
    CHECK_FALSE(certified_intersects(wall, box, to));
    contact_tally t;
    check_translation(wall, box, from, to, t);
    const contact_result<exact_rational> r = first_contact<exact_rational>(wall, box, from, to);
    CHECK(r.time == exact_rational(9) / exact_rational(20));
    CHECK(certified_first_contact(wall, box, from, to).time == 0.45);
    // Turned by pi / 4 the corner comes first.
    const pose turned_from{-10, 0.25, 0.7853981633974483}, turned_to{10, 0.25, 0.7853981633974483};
    check_translation(wall, box, turned_from, turned_to, t);
    CHECK(t.later == 2);
}

TEST_CASE("sweep: touching at the start, sliding, grazing and parallel edges", "[sweep]") {
    contact_tally t;
    const polygon a = square(0, 0, 4, 4);
    const polygon tri = outer_polygon({{0, 0}, {1, 2}, {-1, 2}});  // its vertex 0 at the bottom
    SECTION("touching at the start") {
        const pose from{4, 1, -1.5707963267948966}, to{8, 1, -1.5707963267948966};  // vertex 0 on A's right edge
        check_translation(a, tri, from, to, t);
        const contact_result<exact_rational> r = first_contact<exact_rational>(a, tri, from, to);
        CHECK(r.time == 0);
        CHECK(r.moving_feature.kind == feature_kind::vertex);
        CHECK(r.moving_feature.index == 0);
        CHECK(r.static_feature.kind == feature_kind::edge);
        CHECK(r.static_feature.index == 1);
        // Overlapping at the start: a vertex inside, the interior.
        const contact_result<double> in = certified_first_contact(a, square(0, 0, 1, 1), {1, 1, 0}, {9, 9, 0});
        CHECK(in.contact);
        CHECK(in.time == 0);
        CHECK(in.static_feature.kind == feature_kind::interior);
    }
    SECTION("a vertex sliding along an edge's line into its end") {
        // Vertex 0 moves along y = 4 from x = -3 to x = 2: it reaches A's
        // corner (0, 4) at t = 3 / 5 and then slides along the top edge.
        check_translation(a, tri, {-3, 4, 0}, {2, 4, 0}, t);
        CHECK(first_contact<exact_rational>(a, tri, {-3, 4, 0}, {2, 4, 0}).time ==
              exact_rational(3) / exact_rational(5));
        // Collinear edges end to end: B's top edge on y = 0 slides into A's bottom edge's end.
        const polygon under = square(0, -1, 1, 0);
        check_translation(a, under, {7, 0, 0}, {-1, 0, 0}, t);
        CHECK(first_contact<exact_rational>(a, under, {7, 0, 0}, {-1, 0, 0}).time ==
              exact_rational(3) / exact_rational(8));
    }
    SECTION("grazing: a vertex passing exactly through a vertex") {
        // B's tip moves along y = x - 1, which meets A = [0, 1]^2 only at its
        // corner (1, 0); B's body stays below the line. They touch at t = 1/2
        // only.
        const polygon unit = square(0, 0, 1, 1);
        const polygon spike = outer_polygon({{0, 0}, {-2.125, -2.375}, {-1.875, -2.125}});
        const pose from{-1, -2, 0}, to{3, 2, 0};
        check_translation(unit, spike, from, to, t);
        const contact_result<exact_rational> r = first_contact<exact_rational>(unit, spike, from, to);
        CHECK(r.time == exact_rational(1) / exact_rational(2));
        const exact_scene s(unit, spike, from, to);
        CHECK_FALSE(test_exact::regions_meet(s.a, s.b_at(FT(1) / FT(2) + FT(std::ldexp(1.0, -30)))));
        CHECK_FALSE(test_exact::regions_meet(s.a, s.b_at(FT(1))));
        // The same along the edge's line, touching over an interval.
        const polygon blade = outer_polygon({{0, 0}, {-2, -2}, {-1.875, -2.125}});
        check_translation(unit, blade, from, to, t);
    }
    SECTION("parallel edges meeting") {
        // B's left edge reaches A's right edge: B's vertices on A's edge and
        // A's corner on B's edge at the same time; ties name B's vertex.
        const polygon b = square(0, 0, 2, 2);
        check_translation(a, b, {9, 3, 0}, {1, 3, 0}, t);
        const contact_result<exact_rational> r = first_contact<exact_rational>(a, b, {9, 3, 0}, {1, 3, 0});
        CHECK(r.time == exact_rational(5) / exact_rational(8));
        CHECK(r.static_feature.kind == feature_kind::edge);
        CHECK(r.moving_feature.kind == feature_kind::vertex);
        check_translation(a, b, {9, 1, 0}, {1, 1, 0}, t);
        check_translation(a, b, {9, 4, 0}, {1, 4, 0}, t);  // corner to corner
    }
    CHECK(t.motions > 0);
}

TEST_CASE("sweep: holes let B through, multipolygons are found part by part", "[sweep]") {
    contact_tally t;
    const polygon holed({ring_input{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, ring_role::outer},
                         ring_input{{{2, 2}, {8, 2}, {8, 8}, {2, 8}}, ring_role::hole}});
    const polygon small = square(0, 0, 1, 1);
    // Within the hole, no contact; out of it, the hole's edge.
    check_translation(holed, small, {2.5, 2.5, 0}, {6.5, 6.5, 0}, t);
    check_translation(holed, small, {2.5, 2.5, 0}, {2.5, 6.5, 0}, t);
    CHECK_FALSE(first_contact<exact_rational>(holed, small, {2.5, 2.5, 0}, {6.5, 6.5, 0}).contact);
    check_translation(holed, small, {2.5, 2.5, 0}, {12, 2.5, 0}, t);
    // A passes through B's hole: B, the holed one, moves over A.
    check_translation(small, holed, {-4.5, -4.5, 0}, {-3, -5, 0}, t);
    CHECK_FALSE(certified_first_contact(small, holed, {-4.5, -4.5, 0}, {-3, -5, 0}).contact);
    // A multipolygon: the second part is the first hit.
    const polygon two({ring_input{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, ring_role::outer},
                       ring_input{{{5, 0}, {6, 0}, {6, 1}, {5, 1}}, ring_role::outer}});
    check_translation(two, small, {5, 4, 0}, {5, -4, 0}, t);
    CHECK(first_contact<exact_rational>(two, small, {5, 4, 0}, {5, -4, 0}).time ==
          exact_rational(3) / exact_rational(8));
    CHECK(t.none == 3);
}

TEST_CASE("sweep: input numbering of features on rings stored reversed", "[sweep]") {
    // A given clockwise: input edge 2 runs (4, 4) -> (4, 0), its right side.
    const polygon a = outer_polygon({{0, 0}, {0, 4}, {4, 4}, {4, 0}});
    // B clockwise too: its input vertex 2 is (-1, 0), the one that leads.
    const polygon b = outer_polygon({{0, 1}, {0, -1}, {-1, 0}});
    const contact_result<exact_rational> r = first_contact<exact_rational>(a, b, {9, 2, 0}, {1, 2, 0});
    REQUIRE(r.contact);
    CHECK(r.time == exact_rational(4) / exact_rational(8));
    CHECK(r.static_feature.kind == feature_kind::edge);
    CHECK(r.static_feature.index == 2);
    CHECK(r.moving_feature.kind == feature_kind::vertex);
    CHECK(r.moving_feature.index == 2);
    // A's corner (4, 4), its input vertex 2, reaches B's input edge 1
    // ((0, -1) -> (-1, 0)) at t = 1 / 2.
    const contact_result<double> c = certified_first_contact(a, b, {5.5, 4.5, 0}, {3.5, 4.5, 0});
    REQUIRE(c.contact);
    CHECK(c.time == 0.5);
    CHECK(c.static_feature.kind == feature_kind::vertex);
    CHECK(c.static_feature.index == 2);
    CHECK(c.moving_feature.kind == feature_kind::edge);
    CHECK(c.moving_feature.index == 1);
}

TEST_CASE("sweep: random translations of the families against the reference", "[sweep][reference]") {
    contact_tally t;
    family_motions({8, 64, 256}, {8, 64}, test_effort::scaled(16), 0x5eedULL, 0,
                   [&](const polygon& a, const polygon& b, const pose& from, const pose& to) {
                       check_translation(a, b, from, to, t);
                   });
    INFO("worst error of the double time: " << t.worst_double);
    WARN("random translations of the families: " << t.motions << " motions, " << t.at_start << " meeting at the start, "
                                                 << t.later << " later, " << t.none
                                                 << " never; worst error of the double time " << t.worst_double);
    CHECK(t.at_start > t.motions / 10);
    CHECK(t.later > t.motions / 5);
    CHECK(t.none > t.motions / 20);
}

/// Calls f(a, b, out) for `wanted` pairs of North Carolina's counties
/// (data/real/nc_counties.wkt) that meet, renumbered, A the county of index
/// `first`, first + 9, ..., B each later one that meets it; `out` the
/// displacement of 1e-3 degrees along the line from A's centroid to B's.
/// Returns how many pairs it found.
template <class F>
std::size_t pushed_neighbours(std::size_t first, std::size_t wanted, F&& f) {
    const std::vector<polygon> layer = test_data::real_layer("nc_counties.wkt");
    REQUIRE(layer.size() == 100);
    std::size_t pairs = 0;
    for (std::size_t i = first; i < layer.size() && pairs < wanted; i += 9)
        for (std::size_t j = i + 1; j < layer.size() && pairs < wanted; ++j) {
            if (!intersects<exact_rational>(layer[i], layer[j], pose{})) continue;
            ++pairs;
            const polygon a = renumbered(layer[i]), b = renumbered(layer[j]);
            const point<double> ca = a.centroid(), cb = b.centroid();
            const double length = std::hypot(cb.x - ca.x, cb.y - ca.y), push = 1e-3;
            f(a, b, point<double>{(cb.x - ca.x) / length * push, (cb.y - ca.y) / length * push});
        }
    return pairs;
}

TEST_CASE("sweep: real neighbours pushed apart and translated back, certified as exact", "[sweep][reference][real]") {
    // North Carolina's counties share their border vertices exactly. B
    // pushed off A along the line between the centroids by 1e-3 degrees,
    // then translated back past its place, straight (every shared vertex
    // passes through its twin at once: sweep::same_passage_time) or aside
    // by 0.3 times the push, to either side (the border's collinear runs
    // reach A together: sweep::same_reaching_time): events of one time
    // that no bound orders. The roles swapped too.
    contact_tally t;
    const std::size_t wanted = static_cast<std::size_t>(test_effort::scaled(6));
    const std::size_t pairs = pushed_neighbours(0, wanted, [&](const polygon& a, const polygon& b, point<double> out) {
        for (const double aside : {0.0, 0.3, -0.3}) {
            const pose from{out.x, out.y, 0}, to{-out.x - aside * out.y, -out.y + aside * out.x, 0};
            check_translation(a, b, from, to, t);
            check_translation(b, a, pose{-from.tx, -from.ty, 0}, pose{-to.tx, -to.ty, 0}, t);
        }
    });
    CHECK(pairs == wanted);
    CHECK(t.later == t.motions);
}

TEST_CASE("sweep: real neighbours translated back to their place, touching as the motion ends",
          "[sweep][reference][real]") {
    // As above, but B ends where it stands in the layer: the first contact
    // is at time 1 exactly, where every shared vertex (straight back) or
    // run of the border (from aside by 0.3 of the push) reaches its twin
    // as the motion ends. Each event's time against 1 is decided on the
    // doubles as given (contact_times_on_sides' numerator at the end). The
    // roles swapped too.
    contact_tally t;
    // (At least three pairs: the first one's motions mostly meet before the end.)
    const std::size_t wanted = std::max<std::size_t>(3, static_cast<std::size_t>(test_effort::scaled(6)));
    std::size_t at_end = 0;
    const std::size_t pairs = pushed_neighbours(4, wanted, [&](const polygon& a, const polygon& b, point<double> out) {
        for (const double aside : {0.0, 0.3, -0.3}) {
            const pose from{out.x - aside * out.y, out.y + aside * out.x, 0}, place{0, 0, 0};
            for (const auto& [s, m, f] : {std::tuple{&a, &b, from}, std::tuple{&b, &a, pose{-from.tx, -from.ty, 0}}}) {
                // (Double's rounded events may fall just past the end.)
                at_end += check_translation(*s, *m, f, place, t, true).time == 1;
            }
        }
    });
    CHECK(pairs == wanted);
    CHECK(t.none == 0);
    // Most end touching (a border that zigzags across the push meets
    // earlier, or still overlaps after it).
    INFO(at_end << " of " << t.motions << " end touching");
    CHECK(at_end * 2 > t.motions);
}

TEST_CASE("sweep: a time of 1 held exactly against an event a few units in the last place before it",
          "[sweep][reference]") {
    // Two plots of 2.51 by 3.3 side by side, as in a survey grid of wheat
    // plots (r-cran-spdata's, whose neighbours overlap so): the right one's
    // left side a unit in the last place short of the left one's right
    // side, the two overlapping by that much. B, pushed off to the right
    // and up (aside), translates back to its place. Its left corners reach
    // A's right side's line 2.2e-12 before the end; A's right corners reach
    // B's bottom and top lines exactly as the motion ends (a time of 1
    // settled on the doubles as given, held exactly in `certified`). The
    // certified bound cannot order the two times; the time of 1 is then its
    // own double words, which settle it against the other's. The roles
    // swapped too, along a row of such pairs.
    contact_tally t;
    for (const double left : {36.394999999999996, 41.415, 48.945}) {
        const double middle = left + 2.51, right = middle + 2.51;
        const double shy = std::nextafter(middle, 0.0);
        const polygon a =
            outer_polygon({{left, 64.05}, {middle, 64.05}, {middle, 67.35000000000001}, {left, 67.35000000000001}});
        const polygon b =
            outer_polygon({{shy, 64.05}, {right, 64.05}, {right, 67.35000000000001}, {shy, 67.35000000000001}});
        const pose from{0.0033000000000000113, 0.00099000000000000325, 0}, place{0, 0, 0};
        const contact_result<double> r = check_translation(a, b, from, place, t, true);
        CHECK(r.contact);
        CHECK(r.time < 1);
        check_translation(b, a, pose{-from.tx, -from.ty, 0}, place, t, true);
    }
    CHECK(t.motions == 6);
    CHECK(t.later == 6);
}

TEST_CASE("sweep: real neighbours translated back past their place, passing within rounding of it",
          "[sweep][reference][real]") {
    // As above, but B goes on past its place to -0.37 of the push (straight
    // or from aside by 0.3): no time of the motion puts B exactly where it
    // stands in the layer, its shared vertices passing within rounding of
    // their twins at events a few units in the last place apart that no
    // tie on the doubles as given shows. `certified` cannot order them; they
    // are ordered in double words, else in exact rationals. The roles
    // swapped too.
    contact_tally t;
    const std::size_t wanted = static_cast<std::size_t>(test_effort::scaled(6));
    const std::size_t pairs = pushed_neighbours(6, wanted, [&](const polygon& a, const polygon& b, point<double> out) {
        for (const double aside : {0.0, 0.3}) {
            const pose from{out.x - aside * out.y, out.y + aside * out.x, 0}, past{-0.37 * out.x, -0.37 * out.y, 0};
            check_translation(a, b, from, past, t);
            check_translation(b, a, pose{-from.tx, -from.ty, 0}, pose{-past.tx, -past.ty, 0}, t);
        }
    });
    CHECK(pairs == wanted);
    CHECK(t.none == 0);
}

TEST_CASE("sweep: events a unit in the last place apart are not taken as one time", "[sweep][reference]") {
    // B falls onto A from 2^20 above: two of its vertices, one a unit in the
    // last place higher (2^-32) and first in site order, over A's flat top;
    // then a vertex of B over A's top beside a flat edge of B over a peak of
    // A 2^-32 high. The times differ by 2^-52 of themselves, below any
    // bound of `certified`: only an exact comparison names the first event.
    // The roles swapped too.
    const double y = 0x1p20, up = y + 0x1p-32;
    const polygon top = square(-10, -5, 10, 0);
    const polygon teeth = outer_polygon({{2, up}, {3.5, y + 2}, {5, y}, {6, y + 5}, {1, y + 5}});
    const polygon peaked = outer_polygon({{-10, -5}, {10, -5}, {10, 0}, {8, 0}, {7, 0x1p-32}, {6, 0}, {-10, 0}});
    const polygon tooth_and_flat = outer_polygon({{2, y}, {4, y + 2}, {6, y}, {8, y}, {9, y + 5}, {0, y + 5}});
    contact_tally t;
    for (const auto& [a, b] : {std::pair<const polygon*, const polygon*>{&top, &teeth}, {&peaked, &tooth_and_flat}}) {
        const pose from{0, 0, 0}, to{0, -2 * y, 0};
        check_translation(*a, *b, from, to, t);
        check_translation(*b, *a, pose{0, 0, 0}, pose{0, 2 * y, 0}, t);
    }
    // B's left corners pass through A's right ones, moving along -x: (6, 0)
    // through (4, 0) at t = 0.5 and, standing a unit in the last place
    // further right, (6 + 2^-50, 4) through (4, 4) at 0.5 + 2^-52: vertex
    // passages no bound of `certified` orders (sweep::same_passage_time
    // shows them apart). Each rotation of B's ring, so that either corner
    // comes first in site order.
    const polygon box = square(0, 0, 4, 4);
    const std::vector<point<double>> corners{{6, 0}, {8, 0}, {8, 4}, {6 + 0x1p-50, 4}};
    for (int turn = 0; turn < 4; ++turn) {
        std::vector<point<double>> ring;
        for (int k = 0; k < 4; ++k) ring.push_back(corners[(turn + k) % 4]);
        const polygon b = renumbered(outer_polygon(ring));
        check_translation(box, b, pose{0, 0, 0}, pose{-4, 0, 0}, t);
        check_translation(b, box, pose{0, 0, 0}, pose{4, 0, 0}, t);
    }
    CHECK(t.later == 4 + 8);
}

TEST_CASE("sweep: random translations far from the origin against the reference", "[sweep][reference]") {
    // The families moved to 1e7 and 2^40 (a double's last place there is
    // 2^-12): the exact and certified answers against the reference, at the
    // polygons' own coordinates, where the filters' margins are the widest.
    test_scenes::rng g(0xfa7ULL);
    std::size_t motions = 0, contacts = 0, double_differs = 0;
    for (const double offset : {1e7, std::ldexp(1.0, 40)})
        for (test_families::family f : verification::all_families) {
            const polygon a = test_shapes::translated(renumbered(test_families::load(f, 64)), offset, -offset);
            const polygon b = renumbered(test_families::load(f, 8));
            const double reach = test_poses::reach(a, b);
            for (int k = 0; k < test_effort::scaled(6); ++k) {
                const auto [from, to] = random_translation(a, b, g, reach);
                INFO(describe_motion(a, b, from, to));
                const exact_scene sc(a, b, from, to);
                const std::optional<FT> expected = test_exact::first_contact(sc.a, sc.b0, sc.d);
                const contact_result<exact_rational> ex = first_contact<exact_rational>(a, b, from, to);
                REQUIRE(ex.contact == expected.has_value());
                const contact_result<double> ce = certified_first_contact(a, b, from, to);
                CHECK(ce.contact == ex.contact);
                double_differs += first_contact<double>(a, b, from, to).contact != ex.contact;
                ++motions;
                if (!expected) continue;
                ++contacts;
                CHECK(ex.time == *expected);
                CHECK(ce.time == test_exact::nearest_double(ex.time));
                CHECK(ce.static_feature.index == ex.static_feature.index);
                CHECK(ce.moving_feature.index == ex.moving_feature.index);
            }
        }
    WARN("far translations: " << motions << " motions, " << contacts << " contacts; double's contact differs on "
                              << double_differs);
    CHECK(contacts > motions / 4);
    CHECK(contacts < motions);
}

TEST_CASE("sweep: a contact at the motion's very end far from the origin", "[sweep]") {
    // B's right side (x = 0) moves from 0.1 to 2^40, where A's left side
    // stands: they touch at t = 1 exactly, the last instant of the motion,
    // though to - from = 2^40 - 0.1 is not a double.
    const double far = std::ldexp(1.0, 40);
    const polygon a = square(far, -1, far + 2, 1), b = square(-1, -1, 0, 1);
    const pose from{0.1, 0, 0}, to{far, 0, 0};
    const contact_result<exact_rational> ex = first_contact<exact_rational>(a, b, from, to);
    REQUIRE(ex.contact);
    CHECK(ex.time == 1);
    const contact_result<double> ce = certified_first_contact(a, b, from, to);
    CHECK(ce.contact);
    CHECK(ce.time == 1.0);
    CHECK(first_contact<double>(a, b, from, to).contact);
}

TEST_CASE("sweep: random multipolygons and swallowing polygons, both roles", "[sweep][reference]") {
    contact_tally t;
    const int scenes = test_effort::scaled(16);
    for (int k = 0; k < scenes; ++k) {
        test_scenes::rng g(0x5e1ULL + static_cast<std::uint64_t>(k));
        test_scenes::multi ma = test_scenes::random_multi(g, 30, 8), mb = test_scenes::random_swallower(g);
        if (k % 2 == 1) std::swap(ma, mb);
        const polygon a = renumbered(ma.to_polygon()), b = renumbered(mb.to_polygon());
        for (int f = 0; f < 6; ++f) {
            const test_scenes::part& pa = ma.parts[g.index(ma.parts.size())];
            const test_scenes::part& pb = mb.parts[g.index(mb.parts.size())];
            const double theta = g.chance(0.5) ? 0 : g.uniform(-3.2, 3.2);
            const double phi = g.uniform(0, 6.283185307179586),
                         far = 1.5 * (pa.radius + pb.radius) * g.uniform(0.2, 1.5);
            const point<double> start{pa.center.x + far * std::cos(phi), pa.center.y + far * std::sin(phi)};
            const point<double> end{pa.center.x - far * std::cos(phi + g.uniform(-0.5, 0.5)),
                                    pa.center.y - far * std::sin(phi + g.uniform(-0.5, 0.5))};
            check_translation(a, b, test_scenes::aimed(pb.center, start, theta),
                              test_scenes::aimed(pb.center, end, theta), t);
        }
    }
    CHECK(t.later > t.motions / 5);
    CHECK(t.at_start > 0);
}

TEST_CASE("sweep: the roles swapped give the same first contact", "[sweep][reference]") {
    // B against A moving by d is A against B (placed at the start) moving by
    // -d: the same exact time. Coordinates on the grid keep B's placing and
    // -d exact in double.
    const int scenes = test_effort::scaled(12);
    std::size_t contacts = 0;
    for (int k = 0; k < scenes; ++k) {
        test_scenes::rng g(0x5a9ULL + static_cast<std::uint64_t>(k));
        const test_scenes::multi ma = test_scenes::random_multi(g, 20, 6), mb = test_scenes::random_multi(g, 8, 4);
        const polygon a = renumbered(ma.to_polygon()), b = renumbered(mb.to_polygon());
        for (int f = 0; f < 4; ++f) {
            const pose from = test_scenes::aimed({0, 0}, {g.uniform(-40, 40), g.uniform(-40, 40)}, 0);
            const pose to = test_scenes::aimed({0, 0}, {g.uniform(-40, 40), g.uniform(-40, 40)}, 0);
            std::vector<ring_input> placed = mb.rings();
            for (ring_input& r : placed)
                for (point<double>& v : r.vertices) v = {v.x + from.tx, v.y + from.ty};
            const polygon b_placed = renumbered(polygon(placed));
            const pose back{from.tx - to.tx, from.ty - to.ty, 0};
            INFO(describe_motion(a, b, from, to));
            const contact_result<exact_rational> r = first_contact<exact_rational>(a, b, from, to);
            const contact_result<exact_rational> s = first_contact<exact_rational>(b_placed, a, {0, 0, 0}, back);
            REQUIRE(r.contact == s.contact);
            if (!r.contact) continue;
            ++contacts;
            CHECK(r.time == s.time);
            // The swapped answer's features touch in the swapped scene.
            const exact_scene swapped(b_placed, a, {0, 0, 0}, back);
            CHECK(features_touch(swapped, s.time, s.static_feature, s.moving_feature));
            const contact_result<double> c = certified_first_contact(b_placed, a, {0, 0, 0}, back);
            CHECK(c.time == test_exact::nearest_double(r.time));
        }
    }
    CHECK(contacts > 0);
}

TEST_CASE("sweep: bad input is refused", "[sweep]") {
    const polygon a = square(0, 0, 4, 4);
    const double nan = std::nan("");
    CHECK_THROWS_AS(first_contact<double>(a, polygon{}, {}, {1, 0, 0}), invalid_input);
    CHECK_THROWS_AS(first_contact<double>(polygon{}, a, {}, {1, 0, 0}), invalid_input);
    CHECK_THROWS_AS(first_contact<double>(a, a, {nan, 0, 0}, {1, 0, 0}), invalid_input);
    CHECK_THROWS_AS(first_contact<exact_rational>(a, a, {0, 0, 0}, {1, HUGE_VAL, 0}), invalid_input);
    CHECK_THROWS_AS(certified_first_contact(a, a, {0, 0, 0}, {0, 0, nan}), invalid_input);
    CHECK_THROWS_WITH(first_contact<double>(a, a, {0, 0, 0}, {1, 0, 0}, sweep_options{-1e-9}),
                      "sweep_options: tolerance is -1e-09, not a finite number >= 0");
    // The motions that turn, which pose B by their own formulas, name the
    // pose and its component as translations do, in both models.
    for (const turning_model model : {turning_model::rational, turning_model::angle_linear}) {
        const sweep_options o{sweep_options{}.tolerance, model};
        CHECK_THROWS_WITH(first_contact<double>(a, a, {0, 0, 0}, {1, 0, nan}, o),
                          "end pose: theta is NaN, not a finite number");
        CHECK_THROWS_WITH(certified_first_contact(a, a, {0, 0, 0}, {1, 0, nan}, o),
                          "end pose: theta is NaN, not a finite number");
        CHECK_THROWS_WITH(certified_first_contact(a, a, {HUGE_VAL, 0, 0}, {1, 0, 1}, o),
                          "pose: tx is +infinity, not a finite number");
    }
    CHECK_THROWS_AS(exit_distance<double>(a, a, {0, 0, 0}, nan, 1), invalid_input);
    CHECK_THROWS_AS(exit_distance<double>(a, a, {0, 0, 0}, 0, 0), invalid_input);
    CHECK_THROWS_AS(exit_distance<exact_rational>(a, a, {0, 0, 0}, 1, -HUGE_VAL), invalid_input);
    CHECK_THROWS_AS(exit_distance<double>(a, polygon{}, {0, 0, 0}, 1, 0), invalid_input);
    sweep_options bad;
    bad.tolerance = -1;
    CHECK_THROWS_AS(first_contact<double>(a, a, {0, 0, 0}, {1, 0, 1}, bad), invalid_input);
    bad.tolerance = nan;
    CHECK_THROWS_AS(certified_first_contact(a, a, {0, 0, 0}, {1, 0, 1}, bad), invalid_input);
    // A motion that does not move: the start decides.
    CHECK_FALSE(first_contact<exact_rational>(a, a, {5, 0, 0}, {5, 0, 0}).contact);
    CHECK(certified_first_contact(a, a, {4, 0, 0}, {4, 0, 0}).contact);
}

namespace {

/// How many certified exit distances the search in `certified` answered,
/// of how many (check_exit).
struct exit_tally {
    std::size_t filtered = 0, total = 0;
};
exit_tally exits_seen;

/// exit_distance in exact rationals against the reference: the regions meet
/// at s and at fractions of it, and not just beyond it; certified and double
/// runs agree (certified the exact value rounded, double within
/// double_time_error relative).
void check_exit(const polygon& a, const polygon& b, const pose& q, double dx, double dy, std::size_t& deep,
                bool check_double = true) {
    std::ostringstream what;
    what.precision(17);
    what << "pose " << q.tx << ',' << q.ty << ',' << q.theta << " direction " << dx << ',' << dy;
    INFO(what.str());
    const placed_shape pa = test_exact::place(a, 0, 0, 0), pb = test_exact::place(b, q);
    const vector_2 d{FT(dx), FT(dy)};
    const exact_rational s = exit_distance<exact_rational>(a, b, q, dx, dy);
    // The certified exit is the exact one rounded to the nearest double.
    bool filtered = false;
    CHECK(certified_exit_distance(a, b, q, dx, dy, &filtered) == test_exact::nearest_double(s));
    ++exits_seen.total;
    exits_seen.filtered += filtered ? 1 : 0;
    const bool meet = test_exact::regions_meet(pa, pb);
    if (!meet) {
        CHECK(s == 0);
        return;
    }
    CHECK(s >= 0);
    for (const FT& k : std::vector<FT>{FT(1), FT(1) / FT(3), FT(3) / FT(4)})
        CHECK(test_exact::regions_meet(pa, test_exact::moved(pb, d * (s * k))));
    // Apart just after s: at s + 2^-40, or, where B meets A again sooner
    // (it leaves A for a moment between two events very close together),
    // midway between s and the reference's next contact time.
    const FT soon = s + FT(std::ldexp(1.0, -40));
    if (test_exact::regions_meet(pa, test_exact::moved(pb, d * soon))) {
        std::optional<FT> next;
        for (const FT& x : test_exact::all_contact_times(pa, pb, d, soon))
            if (x > s && (!next || x < *next)) next = x;
        REQUIRE(next);
        CHECK_FALSE(test_exact::regions_meet(pa, test_exact::moved(pb, d * ((s + *next) / 2))));
    }
    if (s > 0) ++deep;
    if (!check_double) return;
    const double sd = exit_distance<double>(a, b, q, dx, dy);
    CHECK(std::fabs(sd - CGAL::to_double(s)) <= double_time_error * (1 + CGAL::to_double(s)));
}

}  // namespace

TEST_CASE("exit distance: through, out of the solid into a hole, touching, apart", "[sweep][exit]") {
    const polygon a = square(0, 0, 4, 4);
    const polygon tri = outer_polygon({{0, 0}, {1, 0}, {0, 1}});
    CHECK(exit_distance<exact_rational>(a, tri, {3.5, 1, 0}, 1, 0) == exact_rational(1) / exact_rational(2));
    CHECK(exit_distance<exact_rational>(a, tri, {3.5, 1, 0}, -1, 0) == exact_rational(9) / exact_rational(2));
    CHECK(exit_distance<exact_rational>(a, tri, {3.5, 1, 0}, -2, 0) == exact_rational(9) / exact_rational(4));
    const polygon unit = square(0, 0, 1, 1);
    CHECK(exit_distance<exact_rational>(a, unit, {4, 0, 0}, 1, 0) == 0);   // touching, moving away
    CHECK(exit_distance<exact_rational>(a, unit, {4, 0, 0}, -1, 0) == 5);  // touching, moving through
    CHECK(exit_distance<exact_rational>(a, unit, {4, 0, 0}, 0, 1) == 4);   // sliding along A's side
    CHECK(exit_distance<double>(a, unit, {6, 0, 0}, -1, 0) == 0);          // apart
    // From A's solid band into its hole: the interval ends there, although
    // B meets A again at the hole's far side.
    const polygon holed({ring_input{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, ring_role::outer},
                         ring_input{{{2, 2}, {8, 2}, {8, 8}, {2, 8}}, ring_role::hole}});
    CHECK(exit_distance<exact_rational>(holed, unit, {0.5, 4.5, 0}, 1, 0) == exact_rational(3) / exact_rational(2));
    std::size_t deep = 0;
    check_exit(holed, unit, {0.5, 4.5, 0}, 1, 0.25, deep);
    check_exit(a, tri, {3.5, 1, 0.5}, -1, 0.125, deep);
    check_exit(holed, tri, {1, 1, -2}, 0.25, 1, deep);
    CHECK(deep == 3);
}

TEST_CASE("exit distance: two events nearer than a double can tell, in either order", "[sweep][exit]") {
    const double tiny = 0x1p-55;
    for (const double side : {1.0, -1.0}) {
        // A: two unit-high blocks with a gap; B from x = -2^-55 to
        // 0.5 - 2^-54, over the first. Moving along +x (or, mirrored, -x) B
        // leaves the first block at s = 1 + 2^-55 and touches the second at
        // s = 1 + 2^-54: both times lie within an ulp above 1, where a
        // rational's double (truncated or rounded) is 1, and only their
        // exact order says where the interval from 0 ends (the second block
        // would take it to about 3).
        const auto at = [side](double x, double y) { return point<double>{side * x, y}; };
        const polygon a({ring_input{{at(0, 0), at(1, 0), at(1, 1), at(0, 1)}, ring_role::outer},
                         ring_input{{at(1.5, 0), at(3, 0), at(3, 1), at(1.5, 1)}, ring_role::outer}});
        const double right = 0.5 - 2 * tiny;
        std::vector<point<double>> corners = {at(-tiny, 0.25), at(right, 0.25), at(right, 0.75), at(-tiny, 0.75)};
        for (int turn = 0; turn < 8; ++turn) {
            std::vector<point<double>> ring;
            for (int k = 0; k < 4; ++k) ring.push_back(corners[(turn + (turn < 4 ? k : 4 - k)) % 4]);
            const polygon b({ring_input{ring, ring_role::outer}});
            CAPTURE(side, turn);
            CHECK(exit_distance<exact_rational>(a, b, pose{}, side, 0) == exact_rational(1) + exact_rational(tiny));
            CHECK(certified_exit_distance(a, b, pose{}, side, 0) == 1.0);
        }
    }
}

TEST_CASE("exit distance: random overlaps of multipolygons against the reference", "[sweep][exit][reference]") {
    const int scenes = test_effort::scaled(24);
    std::size_t deep = 0;
    for (int k = 0; k < scenes; ++k) {
        test_scenes::rng g(0xe817ULL + static_cast<std::uint64_t>(k));
        test_scenes::multi ma = test_scenes::random_multi(g, 20, 6), mb = test_scenes::random_swallower(g);
        if (k % 2 == 1) std::swap(ma, mb);
        const polygon a = ma.to_polygon(), b = mb.to_polygon();
        for (int f = 0; f < 5; ++f) {
            const test_scenes::part& pa = ma.parts[g.index(ma.parts.size())];
            const test_scenes::part& pb = mb.parts[g.index(mb.parts.size())];
            const double reach = pa.radius * g.uniform(0, 1.2) + pb.radius * g.uniform(0, 0.8);
            const double angle = g.uniform(0, 6.283185307179586), theta = g.chance(0.5) ? 0 : g.uniform(-3.2, 3.2);
            const point<double> target{pa.center.x + reach * std::cos(angle), pa.center.y + reach * std::sin(angle)};
            const double heading = g.uniform(0, 6.283185307179586);
            check_exit(a, b, test_scenes::aimed(pb.center, target, theta), std::cos(heading), std::sin(heading), deep);
        }
    }
    CHECK(deep > static_cast<std::size_t>(scenes));
    // The certified search answers nearly all of them without exact
    // arithmetic (ties between events and touching meetings excepted).
    INFO(exits_seen.filtered << " of " << exits_seen.total << " answered in certified");
    CHECK(exits_seen.filtered >= exits_seen.total * 9 / 10);
}

TEST_CASE("exit distance: real neighbours pushed into each other, certified as exact", "[sweep][exit][real]") {
    // North Carolina's counties share their border vertices exactly. B
    // pushed into A along the line between the centroids by 1e-3 degrees,
    // then leaving along the push: straight back onto the shared border,
    // where every shared vertex passes through its twin at once
    // (sweep::same_passage_time, the sides decided on the doubles as given:
    // exact_translated_side); or aside by 0.3 of the push, either way, where
    // the border's straight runs reach A's lines together
    // (sweep::same_reaching_time). The roles swapped too.
    const std::vector<polygon> layer = test_data::real_layer("nc_counties.wkt");
    REQUIRE(layer.size() == 100);
    const exit_tally before = exits_seen;
    const std::size_t wanted = static_cast<std::size_t>(test_effort::scaled(5));
    std::size_t pairs = 0, deep = 0;
    for (std::size_t i = 0; i < layer.size() && pairs < wanted; i += 11)
        for (std::size_t j = i + 1; j < layer.size() && pairs < wanted; ++j) {
            if (!intersects<exact_rational>(layer[i], layer[j], pose{})) continue;
            ++pairs;
            const polygon &a = layer[i], &b = layer[j];
            const point<double> ca = a.centroid(), cb = b.centroid();
            const double length = std::hypot(cb.x - ca.x, cb.y - ca.y), push = 1e-3;
            const point<double> out{(cb.x - ca.x) / length * push, (cb.y - ca.y) / length * push};
            for (const double aside : {0.0, 0.3, -0.3}) {
                const point<double> d{out.x - aside * out.y, out.y + aside * out.x};
                check_exit(a, b, pose{-out.x, -out.y, 0}, d.x, d.y, deep);
                check_exit(b, a, pose{out.x, out.y, 0}, -d.x, -d.y, deep);
            }
        }
    CHECK(pairs == wanted);
    CHECK(deep == 6 * wanted);
    const std::size_t filtered = exits_seen.filtered - before.filtered, total = exits_seen.total - before.total;
    INFO(filtered << " of " << total << " answered in certified");
    CHECK(filtered >= total * 9 / 10);
}

TEST_CASE("exit distance: real neighbours pushed in along a unit direction, leaving within rounding of their place",
          "[sweep][exit][real]") {
    // B pushed into A by 1e-3 degrees along the unit vector u from A's
    // centroid to B's, the pose's doubles -1e-3 u rounded, then leaving
    // along u itself or aside by 0.3: B passes within rounding of its place
    // and its shared vertices within a few units in the last place of their
    // twins, so that consecutive events lie a few units in the last place
    // apart and B between them within rounding of touching A (no tie the
    // doubles as given show). `certified` leaves those meeting tests in
    // doubt; they are settled in double words, else in exact rationals. The
    // roles swapped too.
    std::size_t deep = 0;
    const exit_tally before = exits_seen;
    const std::size_t wanted = static_cast<std::size_t>(test_effort::scaled(12));
    const std::size_t pairs = pushed_neighbours(2, wanted, [&](const polygon& a, const polygon& b, point<double> out) {
        const double length = std::hypot(out.x, out.y);
        const point<double> unit{out.x / length, out.y / length};
        for (const double aside : {0.0, 0.3}) {
            const point<double> d{unit.x - aside * unit.y, unit.y + aside * unit.x};
            check_exit(a, b, pose{-out.x, -out.y, 0}, d.x, d.y, deep, false);
            check_exit(b, a, pose{out.x, out.y, 0}, -d.x, -d.y, deep, false);
        }
    });
    CHECK(pairs == wanted);
    CHECK(deep == 4 * wanted);
    // Two such exits, pushed by 1e-3 of A's box, where B between two
    // events is apart from A (most are between events where they meet).
    const std::vector<polygon> layer = test_data::real_layer("nc_counties.wkt");
    REQUIRE(layer.size() == 100);
    check_exit(layer[3], layer[6], pose{0x1.23f443e835971p-11, 0x1.1254fc0306255p-16, 0}, -0x1.ffc78783d6791p-1,
               -0x1.e0e3813f6db5ap-6, deep, false);
    check_exit(layer[21], layer[45], pose{0x1.e02609ac2811ap-14, 0x1.81900056411f8p-12, 0}, -0x1.306425d6f2b87p-2,
               -0x1.e8db379c888d5p-1, deep, false);
    CHECK(deep == 4 * wanted + 2);
    const std::size_t filtered = exits_seen.filtered - before.filtered, total = exits_seen.total - before.total;
    INFO(filtered << " of " << total << " answered in certified");
    CHECK(filtered == total);
}

TEST_CASE("exit distance: vertex passages a unit in the last place apart are not taken as one time", "[sweep][exit]") {
    // B over A's right side, leaving along +x: its left corners pass through
    // A's right corners, (3, 0) through (4, 0) at s = 1 and the upper one
    // through (4, 4) at s = 1 - 2^-51 when it stands a unit in the last
    // place right of x = 3. The exit is the later: 1, not 1 - 2^-51, below
    // any bound of `certified`: only an exact comparison of the passages
    // orders them. With both corners at x = 3 the passages are one time,
    // which the doubles as given show (sweep::same_passage_time). The roles
    // swapped too.
    const polygon a = square(0, 0, 4, 4);
    for (const double upper : {3.0, 3 + 0x1p-51}) {
        const polygon b = outer_polygon({{3, 0}, {5, 0}, {5, 4}, {upper, 4}});
        CAPTURE(upper);
        bool by_filter[2] = {false, false};
        CHECK(exit_distance<exact_rational>(a, b, pose{}, 1, 0) == 1);
        CHECK(certified_exit_distance(a, b, pose{}, 1, 0, &by_filter[0]) == 1.0);
        CHECK(exit_distance<exact_rational>(b, a, pose{}, -1, 0) == 1);
        CHECK(certified_exit_distance(b, a, pose{}, -1, 0, &by_filter[1]) == 1.0);
        // One time shown on the doubles, or two ordered in double words:
        // the search in certified answers.
        CHECK((by_filter[0] && by_filter[1]));
        // B moved to the right by 0.5 first, and A: the same exit, 0.5.
        std::size_t deep = 0;
        check_exit(a, b, pose{0.5, 0, 0}, 1, 0, deep);
        check_exit(b, a, pose{-0.5, 0, 0}, -1, 0, deep);
        CHECK(deep == 2);
    }
}

TEST_CASE("exit distance: B on A's sides at the start, translated by no double sum, certified as exact",
          "[sweep][exit]") {
    // B's bottom and top sides on A's lines y = 0 and y = 4, B's left side
    // inside A, translated by 0.1 (3 + 0.1 is no double: B's vertices are
    // posed within a bound, and whether they lie on A's sides is a sign of
    // 0 that no bound settles). Leaving along +x and turned up or down by a
    // little or much: events at 0 (B's vertices leave A's sides at once),
    // sides of 0 where B's corners move along A's lines. The search in
    // certified decides them on the doubles as given (the sides, a time's
    // numerator: exact_translated_side, exact_offsets_along) and takes the
    // meeting at the start in exact rationals when its bound leaves it in
    // doubt. The roles swapped too.
    const polygon a = square(0, 0, 4, 4), b = square(3, 0, 5, 4);
    const exit_tally before = exits_seen;
    std::size_t deep = 0;
    for (const double rise : {0.0, 0.3, -0.3, 2.0, -2.0}) {
        check_exit(a, b, pose{0.1, 0, 0}, 1, rise, deep);
        check_exit(b, a, pose{-0.1, 0, 0}, -1, -rise, deep);
    }
    CHECK(deep == 10);
    const std::size_t filtered = exits_seen.filtered - before.filtered, total = exits_seen.total - before.total;
    INFO(filtered << " of " << total << " answered in certified");
    CHECK(filtered == total);
}

TEST_CASE("exit distance: far from the origin against the reference", "[sweep][exit][reference]") {
    // The families moved to 1e7 and 2^40, B overlapping A: the exact and
    // certified exits against the reference. At 1e7 the search in certified
    // answers nearly all (its meeting tests place B at a double time between
    // two events, keeping the posing's bounds); at 2^40 a double's last
    // place (2^-12) is near the features' gaps, and more go to exact
    // rationals.
    test_scenes::rng g(0xe819ULL);
    for (const double offset : {1e7, std::ldexp(1.0, 40)}) {
        const exit_tally before = exits_seen;
        std::size_t deep = 0, poses = 0;
        for (test_families::family f : verification::all_families) {
            const polygon a = test_shapes::translated(test_families::load(f, 64), offset, -offset);
            const polygon b = test_families::load(f, 8);
            const point<double> c = a.centroid(), cb = b.centroid();
            const double r = 0.5 * bounding_radius(a, c);
            for (int k = 0; k < test_effort::scaled(4); ++k) {
                const point<double> at{c.x + r * g.uniform(-1, 1), c.y + r * g.uniform(-1, 1)};
                const double heading = g.uniform(0, 6.283185307179586);
                check_exit(a, b, test_scenes::aimed(cb, at, g.uniform(-3.2, 3.2)), std::cos(heading), std::sin(heading),
                           deep, false);
                ++poses;
            }
        }
        INFO("offset " << offset << ": " << deep << " of " << poses << " overlapping, "
                       << exits_seen.filtered - before.filtered << " of " << exits_seen.total - before.total
                       << " answered in certified");
        CHECK(deep > poses / 3);
        if (offset < 1e8) CHECK(exits_seen.filtered - before.filtered >= (exits_seen.total - before.total) * 9 / 10);
    }
}

TEST_CASE("exit distance: the families overlapping, any direction", "[sweep][exit][reference]") {
    std::size_t deep = 0, poses = 0;
    test_scenes::rng g(0xe818ULL);
    for (test_families::family f : verification::all_families)
        for (std::size_t n : {8u, 64u}) {
            const polygon& a = test_families::load(f, n);
            const polygon& b = test_families::load(f, 8);
            for (const pose& q : influence2d::random_poses(a, b, static_cast<std::size_t>(test_effort::scaled(8)), 0,
                                                           80, n + static_cast<std::size_t>(f) * 7)) {
                const double heading = g.uniform(0, 6.283185307179586);
                check_exit(a, b, q, std::cos(heading), std::sin(heading), deep);
                ++poses;
            }
        }
    CHECK(deep > poses / 3);
}

namespace {

/// Counts of the turning motions.
struct turning_tally {
    std::size_t motions = 0, sampled = 0, reported = 0;
};

/// A motion that turns, against dense sampling with the exact one-shot
/// query at motion_pose(t): every sampled contact is reported, no later
/// than the first sampled one and with no sampled contact before it; at the
/// reported time the exact distance is within the tolerance; certified
/// takes the same steps as exact_rational (the same time and features);
/// double reports a contact whenever a sample meets. (The distance at the
/// reported time is within the tolerance times 1 + `slack`: a tolerance
/// below the motion's resolution, which grows with its coordinates, is
/// raised to it; docs/sweep.md.)
void check_turning(const polygon& a, const polygon& b, const pose& from, const pose& to, turning_tally& t,
                   const sweep_options& options = {}, double slack = 1e-12) {
    INFO(describe_motion(a, b, from, to) << ", tolerance " << options.tolerance);
    const contact_result<exact_rational> ex = first_contact<exact_rational>(a, b, from, to, options);
    const contact_result<double> ce = certified_first_contact(a, b, from, to, options);
    const contact_result<double> db = first_contact<double>(a, b, from, to, options);
    ++t.motions;
    const int samples = 200;
    std::optional<double> first_sample;
    for (int k = 0; k <= samples && !first_sample; ++k) {
        const double tk = static_cast<double>(k) / samples;
        if (intersects<exact_rational>(a, b, motion_pose(from, to, tk))) first_sample = tk;
    }
    CHECK(ce.contact == ex.contact);
    if (first_sample) {
        ++t.sampled;
        REQUIRE(ex.contact);
        CHECK(CGAL::to_double(ex.time) <= *first_sample);
        CHECK(db.contact);
    }
    if (!ex.contact) return;
    ++t.reported;
    // Meeting at the start: double says so too.
    if (ex.time == 0) CHECK((db.contact && db.time == 0));
    const double time = CGAL::to_double(ex.time);
    CHECK(ex.time == exact_rational(time));
    for (int k = 0; k <= samples && static_cast<double>(k) / samples < time; ++k)
        CHECK_FALSE(intersects<exact_rational>(a, b, motion_pose(from, to, static_cast<double>(k) / samples)));
    CHECK(certified_separation(a, b, motion_pose(from, to, time)).distance <= options.tolerance * (1 + slack));
    CHECK(ce.time == time);
    CHECK(ce.static_feature.kind == ex.static_feature.kind);
    CHECK(ce.static_feature.index == ex.static_feature.index);
    CHECK(ce.moving_feature.kind == ex.moving_feature.kind);
    CHECK(ce.moving_feature.index == ex.moving_feature.index);
}

}  // namespace

TEST_CASE("sweep: a spinning bar past a thin wall is caught", "[sweep][turning]") {
    // A bar of length 8 about B's origin, 3.5 from the wall, turned from
    // nearly upright through flat to nearly upright again: it sweeps across
    // the wall although neither end pose meets it.
    const polygon wall = square(0, -5, 0.1, 5), bar = square(-4, -0.05, 4, 0.05);
    const pose from{-3.5, 0, 1.5}, to{-3.5, 0, 4.6};
    CHECK_FALSE(certified_intersects(wall, bar, from));
    CHECK_FALSE(certified_intersects(wall, bar, to));
    turning_tally t;
    check_turning(wall, bar, from, to, t);
    CHECK(t.reported == 1);
    CHECK(t.sampled == 1);
    // Holding still while turning inside a hole large enough: no contact.
    const polygon holed({ring_input{{{-10, -10}, {10, -10}, {10, 10}, {-10, 10}}, ring_role::outer},
                         ring_input{{{-5, -5}, {5, -5}, {5, 5}, {-5, 5}}, ring_role::hole}});
    CHECK_FALSE(first_contact<exact_rational>(holed, bar, {0, 0, 0}, {0, 0, 6.2}).contact);
    CHECK_FALSE(certified_first_contact(holed, bar, {0, 0, 0}, {0.5, 0, -6.2}).contact);
    // Meeting at the start: time 0.
    const contact_result<double> start = certified_first_contact(wall, bar, {0, 0, 0}, {0, 0, 1});
    CHECK(start.contact);
    CHECK(start.time == 0);
}

TEST_CASE("sweep: motions that turn against dense sampling with the exact query", "[sweep][turning][reference]") {
    turning_tally t;
    family_motions({8, 64}, {8}, test_effort::scaled(10), 0x7e55ULL, 3,
                   [&](const polygon& a, const polygon& b, const pose& from, const pose& to) {
                       check_turning(a, b, from, to, t);
                   });
    test_scenes::rng g(0x7e56ULL);
    for (int k = 0; k < test_effort::scaled(12); ++k) {
        const test_scenes::multi ma = test_scenes::random_multi(g, 20, 6), mb = test_scenes::random_swallower(g);
        const polygon a = ma.to_polygon(), b = mb.to_polygon();
        for (int f = 0; f < 3; ++f) {
            auto [from, to] = random_translation(a, b, g, test_poses::reach(a, b));
            to.theta = from.theta + g.uniform(-2, 2);
            check_turning(a, b, from, to, t);
        }
    }
    WARN("motions that turn: " << t.motions << " motions, " << t.sampled << " with a sampled contact, " << t.reported
                               << " reported");
    CHECK(t.sampled > t.motions / 4);
    CHECK(t.reported < t.motions);
}

TEST_CASE("sweep: convex pairs turning on their own probe, against dense sampling", "[sweep][turning][reference]") {
    // Two convex polygons (on ellipses, of 3 to 16 vertices, sizes from 2^-8
    // to 2^8, far from the origin or not) step on convex_gap and each
    // vertex's own approach: every motion against dense sampling with the
    // exact query, certified as exact, in both roles; touching and sliding
    // exactly; B turning in place about a point inside A's reach.
    test_random::rng g(0xc0c0ULL);
    turning_tally t;
    const int scenes = test_effort::scaled(24);
    for (int k = 0; k < scenes; ++k) {
        const double size = std::ldexp(1.0, static_cast<int>(g.uniform(-8, 8)));
        const point<double> offset = g.chance(0.3) ? point<double>{1e5 * size, -3e5 * size} : point<double>{0, 0};
        const polygon a = outer_polygon(test_shapes::ellipse_points(g, 3 + static_cast<std::size_t>(g.uniform(0, 14)),
                                                                    offset, size, size * g.uniform(0.1, 1)));
        const polygon b =
            outer_polygon(test_shapes::ellipse_points(g, 3 + static_cast<std::size_t>(g.uniform(0, 14)), {0, 0},
                                                      size * g.uniform(0.2, 1.5), size * g.uniform(0.05, 1)));
        if (!is_convex_polygon(a) || !is_convex_polygon(b)) continue;
        const double reach = test_poses::reach(a, b);
        for (int f = 0; f < 3; ++f) {
            auto [from, to] = random_translation(a, b, g, reach);
            to.theta = from.theta + g.uniform(-3, 3);
            // Far from the origin the motion's resolution (a few ulps of
            // its coordinates) exceeds 1e-9: a tolerance of 2^-30 times its
            // size stands above it.
            sweep_options o;
            if (offset.x != 0) o.tolerance = 0x1p-30 * sweep::motion_scale(a, b, from, to);
            const double slack = offset.x != 0 ? 0x1p-16 : 1e-12;
            check_turning(a, b, from, to, t, o, slack);
            // The roles swapped: B at rest, A moving along the same poses
            // (a motion of its own).
            check_turning(b, a, from, to, t, o, slack);
            // Turning in place.
            to = from;
            to.theta = from.theta + g.uniform(-6, 6);
            check_turning(a, b, from, to, t, o, slack);
        }
    }
    // A square sliding along another's top side, touching it exactly, and
    // turning by a hair as it goes: contact at the start.
    const polygon floor = square(0, 0, 4, 4), box = square(-0.5, -0.5, 0.5, 0.5);
    check_turning(floor, box, {1, 4.5, 0}, {3, 4.5, 1e-9}, t);
    // Corner first onto the floor's top side, turning through the touch.
    check_turning(floor, box, {2, 6, 0.6}, {2, 4, 0.9}, t);
    WARN("convex pairs turning: " << t.motions << " motions, " << t.sampled << " with a sampled contact, " << t.reported
                                  << " reported");
    CHECK(t.sampled > t.motions / 5);
    CHECK(t.reported < t.motions);
}

TEST_CASE("contact times: the sign decisions of the sweep", "[sweep][predicates]") {
    using ER = exact_rational;
    using P = point<ER>;
    time_fraction<ER> out[2];
    const auto value = [](const time_fraction<ER>& t) { return ER(t.num / t.den); };
    // Crossing: p = (0, 0) moving by (4, 0) reaches x = 1 at t = 1/4.
    REQUIRE(contact_times<ER>(P{0, 0}, P{4, 0}, P{1, -1}, P{1, 1}, true, out) == 1);
    CHECK(value(out[0]) == ER(1) / ER(4));
    CHECK(out[0].den > 0);
    // The same segment given the other way round: the same time, den > 0.
    REQUIRE(contact_times<ER>(P{0, 0}, P{4, 0}, P{1, 1}, P{1, -1}, true, out) == 1);
    CHECK(value(out[0]) == ER(1) / ER(4));
    CHECK(out[0].den > 0);
    // Through an end, and missing the segment by a hair.
    CHECK(contact_times<ER>(P{0, 0}, P{4, 0}, P{1, 0}, P{1, 1}, true, out) == 1);
    CHECK(contact_times<ER>(P{0, 0}, P{4, 0}, P{1, ER(1) / ER(1 << 30)}, P{1, 1}, true, out) == 0);
    // Beyond t = 1: only unbounded; behind p (t < 0): never.
    CHECK(contact_times<ER>(P{0, 0}, P{4, 0}, P{5, -1}, P{5, 1}, true, out) == 0);
    REQUIRE(contact_times<ER>(P{0, 0}, P{4, 0}, P{5, -1}, P{5, 1}, false, out) == 1);
    CHECK(value(out[0]) == ER(5) / ER(4));
    CHECK(contact_times<ER>(P{0, 0}, P{4, 0}, P{-1, -1}, P{-1, 1}, false, out) == 0);
    // Collinear: the times p passes both ends; a segment behind p only ends.
    REQUIRE(contact_times<ER>(P{0, 0}, P{4, 0}, P{3, 0}, P{1, 0}, true, out) == 2);
    CHECK(value(out[0]) == ER(3) / ER(4));
    CHECK(value(out[1]) == ER(1) / ER(4));
    CHECK(value(*earliest_contact_time<ER>(P{0, 0}, P{4, 0}, P{3, 0}, P{1, 0})) == ER(1) / ER(4));
    CHECK(contact_times<ER>(P{0, 0}, P{4, 0}, P{-1, 0}, P{2, 0}, true, out) == 1);
    // Parallel off the line: none. A point (a == b) on the line: once.
    CHECK(contact_times<ER>(P{0, 0}, P{4, 0}, P{1, 1}, P{3, 1}, false, out) == 0);
    REQUIRE(contact_times<ER>(P{0, 0}, P{4, 0}, P{2, 0}, P{2, 0}, true, out) == 2);
    CHECK(value(out[0]) == ER(1) / ER(2));
    CHECK(compare_times(out[0], out[1]) == 0);
    CHECK(compare_times(time_fraction<ER>{1, 3}, time_fraction<ER>{2, 5}) < 0);
    CHECK_FALSE(time_in_range(time_fraction<ER>{4, 3}, true));
    CHECK(time_in_range(time_fraction<ER>{4, 3}, false));
    CHECK_FALSE(time_in_range(time_fraction<ER>{-1, 3}, false));
}

TEST_CASE("contact times: the nearest double of a fraction", "[sweep][predicates]") {
    using ER = exact_rational;
    test_scenes::rng g(0x9ea7ULL);
    for (int k = 0; k < 2000; ++k) {
        const ER num = ER(g.uniform(0, 1)) * ER(g.uniform(0, 1e6)) + ER(g.uniform(0, 1e-9));
        const ER den = ER(g.uniform(1e-3, 1)) * ER(g.uniform(1, 1e6));
        CHECK(nearest_double(time_fraction<ER>{num, den}) == test_exact::nearest_double(ER(num / den)));
    }
    // Ties go to the even neighbour: 1 + 2^-53 lies midway between 1 and 1 + 2^-52.
    const ER tie = ER(1) + ER(std::ldexp(1.0, -53)), three_ties = ER(1) + ER(3) * ER(std::ldexp(1.0, -53));
    CHECK(nearest_double(time_fraction<ER>{tie, ER(1)}) == 1.0);
    CHECK(nearest_double(time_fraction<ER>{three_ties * 7, ER(7)}) == 1 + std::ldexp(1.0, -51));
    // A numerator and denominator beyond double's range.
    const ER huge = ER(std::ldexp(1.0, 1000)) * ER(std::ldexp(1.0, 500));
    CHECK(nearest_double(time_fraction<ER>{huge * 3, huge * 7}) == 3.0 / 7);
    CHECK(nearest_double(time_fraction<ER>{huge, ER(std::ldexp(1.0, 600))}) == std::ldexp(1.0, 900));
    CHECK(nearest_double(time_fraction<ER>{ER(0), ER(5)}) == 0);
    // A numerator and denominator below double's normal range (their doubles
    // subnormal or 0): the quotient is not taken from them.
    const ER tiny = ER(std::ldexp(1.0, -600)) * ER(std::ldexp(1.0, -500));
    CHECK(nearest_double(time_fraction<ER>{tiny * 3, tiny * 7}) == 3.0 / 7);
    CHECK(nearest_double(time_fraction<ER>{tiny, ER(std::ldexp(1.0, -900))}) == std::ldexp(1.0, -200));
    CHECK(nearest_double(time_fraction<ER>{tiny * tiny, tiny}) == 0);
    CHECK(nearest_double(time_fraction<double>{1, 3}) == 1.0 / 3);
}

TEST_CASE("sweep: a site's time rounded in double words is the exact time's nearest double, or none",
          "[sweep][predicates]") {
    // Every site (B's vertex against A's edge, A's against B's) of random
    // translations of the families: where the reference (a segment
    // intersection on CGAL's kernel) finds a contact time, certain_nearest of
    // site_reaching_time gives MPFR's nearest double of the earliest, or
    // nothing.
    const auto rounded = [](const polygon& a, const polygon& b, const pose& from, const pose& to,
                            const sweep::contact_site& site) -> std::optional<double> {
        double x = 0;
        if (!certain_nearest(
                sweep::site_reaching_time(a, b, rotation_pose(from), sweep::displacement<double_word>(from, to), site),
                x))
            return std::nullopt;
        return x;
    };
    std::size_t sites = 0, settled = 0;
    family_motions({8, 64}, {8}, test_effort::scaled(24), 0x717eULL, 0,
                   [&](const polygon& a, const polygon& b, const pose& from, const pose& to) {
                       INFO(describe_motion(a, b, from, to));
                       const exact_scene s(a, b, from, to);
                       for (const bool moving : {true, false})
                           for (std::size_t v = 0; v < (moving ? b : a).size(); ++v)
                               for (std::size_t e = 0; e < (moving ? a : b).size(); ++e) {
                                   const std::vector<FT> ts = moving
                                                                  ? test_exact::contact_times(s.b0.v[v], s.d, s.a, e)
                                                                  : test_exact::contact_times(s.a.v[v], -s.d, s.b0, e);
                                   if (ts.empty()) continue;
                                   ++sites;
                                   const sweep::contact_site site{moving, static_cast<std::uint32_t>(v),
                                                                  static_cast<std::uint32_t>(e)};
                                   const std::optional<double> x = rounded(a, b, from, to, site);
                                   if (!x) continue;
                                   ++settled;
                                   INFO("site " << moving << " " << v << " " << e);
                                   CHECK(*x == test_exact::nearest_double(*std::min_element(ts.begin(), ts.end())));
                               }
                   });
    WARN("site_reaching_time: " << settled << " of " << sites << " sites with a contact time settled");
    CHECK(settled > sites * 9 / 10);
    // B's right side at x0 = k 2^-54 reaches the wall at 0.75 at t = 0.75 - x0:
    // a double for even k, midway between two for odd k, which no bound
    // settles (the exact field rounds it). A vertex sliding along the wall's
    // edge has no one time (the denominator is 0): none either.
    const polygon wall = square(0.75, -5, 1, 5);
    for (int k = -3; k <= 3; ++k) {
        const polygon b = square(-1, -1, std::ldexp(k, -54), 1);
        // B's vertex 1 (x0, -1) against the wall's edge 3 (x = 0.75, from y = 5 down to -5).
        const sweep::contact_site site{true, 1, 3};
        INFO("k = " << k);
        REQUIRE(b.vertex(1).x == std::ldexp(k, -54));
        REQUIRE(wall.vertex(3).x == 0.75);
        REQUIRE(wall.vertex(0).x == 0.75);
        const std::optional<double> x = rounded(wall, b, {0, 0, 0}, {1, 0, 0}, site);
        if (k % 2 != 0) {
            CHECK_FALSE(x.has_value());
        } else {
            REQUIRE(x.has_value());
            CHECK(*x == 0.75 - std::ldexp(k, -54));
        }
    }
    const polygon slider = square(0.75, -7, 1, -6);  // vertex 0 at (0.75, -7)
    CHECK_FALSE(rounded(wall, slider, {0, 0, 0}, {0, 3, 0}, sweep::contact_site{true, 0, 3}).has_value());
}

TEST_CASE("sweep: a certified time midway between two doubles is rounded exactly", "[sweep][exit]") {
    // 0.75 - 2^-54 lies midway between 0.75 - 2^-53 and 0.75: the double
    // words cannot round it (their bound never settles a tie), the exact
    // field rounds it to the even neighbour, 0.75.
    const double tiny = std::ldexp(1.0, -54);
    CHECK_THROWS_AS(nearest_double(time_fraction<double_word>{double_word(0.75) - double_word(tiny), double_word(1)}),
                    uncertain_sign);
    const exact_rational tie = exact_rational(0.75) - exact_rational(tiny);
    REQUIRE(test_exact::nearest_double(tie) == 0.75);
    // B's right side at 2^-54 reaches the wall at 0.75 at t = 0.75 - 2^-54.
    const polygon wall = square(0.75, -5, 1, 5), b = square(-1, -1, tiny, 1);
    const contact_result<exact_rational> ex = first_contact<exact_rational>(wall, b, {0, 0, 0}, {1, 0, 0});
    REQUIRE(ex.contact);
    CHECK(ex.time == tie);
    const contact_result<double> ce = certified_first_contact(wall, b, {0, 0, 0}, {1, 0, 0});
    CHECK(ce.contact);
    CHECK(ce.time == 0.75);
    CHECK(ce.moving_feature.kind == ex.moving_feature.kind);
    CHECK(ce.moving_feature.index == ex.moving_feature.index);
    // B, its one leftmost vertex at x = 2^-54, moving along (1, 1/2), leaves
    // the block ending at 0.75 after s = 0.75 - 2^-54; the search in
    // certified settles every sign, the rounding falls to the exact field.
    const polygon block = square(-1, -5, 0.75, 5), c({outer_polygon({{tiny, -1}, {1, -1}, {1, 1}, {0.5, 1}})});
    CHECK(exit_distance<exact_rational>(block, c, {0, 0, 0}, 1, 0.5) == tie);
    bool by_filter = false;
    CHECK(certified_exit_distance(block, c, {0, 0, 0}, 1, 0.5, &by_filter) == 0.75);
    CHECK(by_filter);
}

TEST_CASE("sweep: far from 1 in scale, and directions of any length", "[sweep][exit]") {
    // The tunneling square and the wall scaled by 2^e: the same exact time.
    for (int e : {-600, -40, 40, 600}) {
        const auto sq = [e](double x0, double y0, double x1, double y1) {
            return square(std::ldexp(x0, e), std::ldexp(y0, e), std::ldexp(x1, e), std::ldexp(y1, e));
        };
        const polygon wall = sq(0, -5, 0.1, 5), box = sq(-1, -1, 1, 1);
        const pose from{std::ldexp(-10, e), 0, 0}, to{std::ldexp(10, e), 0, 0};
        INFO("scale 2^" << e);
        CHECK(first_contact<exact_rational>(wall, box, from, to).time == exact_rational(9) / exact_rational(20));
        CHECK(certified_first_contact(wall, box, from, to).time == 0.45);
        // Double answers on the motion scaled into its range (core/range_scaling.hpp).
        const contact_result<double> rounded = first_contact<double>(wall, box, from, to);
        CHECK(rounded.time == Approx(0.45));
        // B overlapping the wall by 0.05 (scaled) moves right through it:
        // they part once B's left side passes the wall's right side.
        const pose in{std::ldexp(-0.95, e), 0, 0};
        const exact_rational through = exact_rational(std::ldexp(0.1, e)) -
                                       (exact_rational(std::ldexp(-1.0, e)) + exact_rational(std::ldexp(-0.95, e)));
        CHECK(exit_distance<exact_rational>(wall, box, in, 1, 0) == through);
        CHECK(certified_exit_distance(wall, box, in, 1, 0) == test_exact::nearest_double(through));
        const double rounded_exit = exit_distance<double>(wall, box, in, 1, 0);
        CHECK(rounded_exit == Approx(std::ldexp(2.05, e)));
    }
    // The exit distance is in units of the direction, of any length.
    const polygon a = square(0, 0, 4, 4), unit = square(0, 0, 1, 1);
    CHECK(exit_distance<exact_rational>(a, unit, {3.5, 1, 0}, std::ldexp(1.0, -1000), 0) ==
          exact_rational(std::ldexp(0.5, 500)) * exact_rational(std::ldexp(1.0, 500)));
    CHECK(exit_distance<exact_rational>(a, unit, {3.5, 1, 0}, std::ldexp(1.0, 1000), 0) ==
          exact_rational(std::ldexp(0.5, -1000)));
    CHECK(certified_exit_distance(a, unit, {3.5, 1, 0}, std::ldexp(1.0, -1000), 0) == std::ldexp(1.0, 999));
    CHECK(certified_exit_distance(a, unit, {3.5, 1, 0}, 3, 0) == 0.5 / 3);
    CHECK(exit_distance<double>(a, unit, {3.5, 1, 0}, 1e-300, 0) == Approx(0.5e300));
    CHECK_THROWS_AS(certified_exit_distance(a, unit, {3.5, 1, 0}, 1e300, 1e-300), invalid_input);
    CHECK_THROWS_AS(certified_exit_distance(a, unit, {3.5, 1, std::nan("")}, 1, 0), invalid_input);
    CHECK_THROWS_AS(exit_distance<double>(a, unit, {3.5, 1, 0}, 1e300, 1e-300), invalid_input);
}

TEST_CASE("sweep: certified first contact far from 1 in scale answers as at scale 1", "[sweep]") {
    // The same motions scaled by 2^e are the same questions: the exact time
    // and features do not change, so neither does their certified rounding,
    // whether or not the scaled query is brought back near 1.
    using test_shapes::scaled;
    std::size_t contacts = 0, motions = 0;
    family_motions({8, 64}, {8}, test_effort::scaled(3), 0x5ca1eULL, 0.5,
                   [&](const polygon& a, const polygon& b, const pose& from, const pose& to) {
                       const pose still{from.tx, from.ty, from.theta};
                       const pose straight{to.tx, to.ty, from.theta};
                       const contact_result<double> one = certified_first_contact(a, b, still, straight);
                       contacts += one.contact;
                       ++motions;
                       for (int e : {-1000, -500, 500}) {
                           INFO("scale 2^" << e);
                           const polygon sa = scaled(a, e), sb = scaled(b, e);
                           const pose f = scaled_by_power_of_two(still, e), t = scaled_by_power_of_two(straight, e);
                           const contact_result<double> r = certified_first_contact(sa, sb, f, t);
                           CHECK(r.contact == one.contact);
                           CHECK(r.time == one.time);
                           CHECK(r.static_feature.kind == one.static_feature.kind);
                           CHECK(r.static_feature.index == one.static_feature.index);
                           CHECK(r.moving_feature.kind == one.moving_feature.kind);
                           CHECK(r.moving_feature.index == one.moving_feature.index);
                           // The exact query, never scaled.
                           check_same_contact(first_contact<exact_rational>(sa, sb, f, t), r);
                       }
                   });
    CHECK(contacts > 0);
    CHECK(contacts < motions);
    // A's apex 2^-1060 below the line B's bottom edge slides along: they
    // never meet. Scaled into range, that apex would round to the line and
    // touch it, so the query runs as given, still exact.
    const double far = std::ldexp(1.0, 100);
    const polygon peak = outer_polygon({{-far, -far}, {far, -far}, {0, -std::ldexp(1.0, -1060)}});
    const polygon block = square(-far / 1024, 0, far / 1024, far / 512);
    const pose from{-2 * far, 0, 0}, to{2 * far, 0, 0};
    const contact_result<exact_rational> x = first_contact<exact_rational>(peak, block, from, to);
    CHECK_FALSE(x.contact);
    CHECK_FALSE(certified_first_contact(peak, block, from, to).contact);
    // With the apex on that line they touch.
    const polygon touching = outer_polygon({{-far, -far}, {far, -far}, {0, 0}});
    CHECK(certified_first_contact(touching, block, from, to).contact);
}

TEST_CASE("sweep: turning motions far from 1 in scale, certified as exact", "[sweep][turning]") {
    // The families' turning motions scaled by 2^e, the tolerance with them:
    // exact rationals and certified take the same steps (both scaled into
    // double's window when every coordinate scales exactly; at 2^-1040,
    // where the subnormals round the coordinates, both unscaled, the double
    // probe handing over to the exact one where its squared distance leaves
    // double's range), so the same time and features; none throws.
    using test_shapes::scaled;
    std::size_t later = 0, free = 0;
    for (int e : {-1040, -1000, 600}) {
        family_motions({8}, {8}, test_effort::scaled(2), 0x7a11ULL + static_cast<std::uint64_t>(e + 2000), 1.5,
                       [&](const polygon& a, const polygon& b, const pose& from, const pose& to) {
                           INFO("scale 2^" << e);
                           const polygon sa = scaled(a, e), sb = scaled(b, e);
                           const pose f = scaled_by_power_of_two(from, e), t = scaled_by_power_of_two(to, e);
                           sweep_options o;
                           o.tolerance = std::ldexp(1e-9, e);
                           const contact_result<double> r = certified_first_contact(sa, sb, f, t, o);
                           const contact_result<exact_rational> x = first_contact<exact_rational>(sa, sb, f, t, o);
                           check_same_contact(x, r);
                           free += !r.contact;
                           later += r.contact && r.time > 0;
                       });
    }
    CHECK(later > 0);
    CHECK(free > 0);
}

TEST_CASE("sweep: a motion grazing for long stops at the step limit, undecided", "[sweep][turning]") {
    // B, a unit square, slides just above A's top side from x = -2 to x = 6
    // while turning by 1e-12: once over A (from t = 0.1875, B's right side at
    // x = 0) the distance stays near the gap.
    // A is notched below, far from the motion, so that it is not convex
    // (two convex polygons step by their own bound: below).
    const polygon a = outer_polygon({{0, 0}, {1.5, 0}, {1.5, 1}, {2.5, 1}, {2.5, 0}, {4, 0}, {4, 4}, {0, 4}}),
                  b = square(-0.5, -0.5, 0.5, 0.5);
    sweep_options o;
    o.max_steps = 1000;
    // A gap of 3e-9, three times the tolerance: the swept boxes keep B's
    // vertices farther from A's edges than any probe may stop at, so the
    // motion is decided without a step: no contact, in every route.
    {
        const double y = 4.5 + 3e-9;
        const pose from{-2, y, 0}, to{6, y, 1e-12};
        const contact_result<double> d = first_contact<double>(a, b, from, to, o);
        const contact_result<double> c = certified_first_contact(a, b, from, to, o);
        const contact_result<exact_rational> x = first_contact<exact_rational>(a, b, from, to, o);
        const contact_result<long double> l = first_contact<long double>(a, b, from, to, o);
        for (const bool contact : {d.contact, c.contact, x.contact, l.contact}) CHECK_FALSE(contact);
        for (const bool limited : {d.step_limit, c.step_limit, x.step_limit, l.step_limit}) CHECK_FALSE(limited);
    }
    // A gap of 1.04e-9: beyond where double's probes stop (the tolerance and
    // double's error bound, 2^-40 of the scene's size, about 2e-11 here),
    // within the boxes' reach (the probes' reach and the boxes' own slack,
    // about 6e-11 beyond the tolerance): each step of conservative
    // advancement gains about 1e-10 of the motion: millions of steps.
    const double y = 4.5 + 1.04e-9;
    const pose from{-2, y, 0}, to{6, y, 1e-12};
    const contact_result<double> d = first_contact<double>(a, b, from, to, o);
    CHECK_FALSE(d.contact);
    CHECK(d.step_limit);
    CHECK(d.time > 0.1875);
    CHECK(d.time < 0.19);
    const contact_result<double> c = certified_first_contact(a, b, from, to, o);
    const contact_result<exact_rational> x = first_contact<exact_rational>(a, b, from, to, o);
    CHECK_FALSE(c.contact);
    CHECK(c.step_limit);
    CHECK(x.step_limit);
    CHECK(nearest_double(x.time) == c.time);
    CHECK(c.time > 0.1875);
    // With a tolerance above the gap it touches on reaching A; the rational model
    // has no steps and answers exactly: B never meets A.
    o.tolerance = 1e-8;
    const contact_result<double> near = certified_first_contact(a, b, from, to, o);
    CHECK(near.contact);
    CHECK_FALSE(near.step_limit);
    CHECK(near.time == Approx(0.1875).margin(1e-6));
    o.tolerance = 1e-9;
    o.model = turning_model::rational;
    const contact_result<double> exact = certified_first_contact(a, b, from, to, o);
    CHECK_FALSE(exact.contact);
    CHECK_FALSE(exact.step_limit);
    // long double advances on its own distances, within its own error bound
    // (2^-51 of the scene's size, not the 4e-8 of its filters' margin, which
    // would call the gap a contact): its probes reach less far than
    // double's, and the boxes show the gap of 1.04e-9 beyond them.
    sweep_options linear;
    linear.max_steps = 1000;
    const contact_result<long double> l = first_contact<long double>(a, b, from, to, linear);
    CHECK_FALSE(l.contact);
    CHECK_FALSE(l.step_limit);
    // A motion that meets A is decided well within the default limit.
    const contact_result<double> head_on = certified_first_contact(a, b, {-2, 2, 0}, {6, 2, 1}, sweep_options{});
    CHECK(head_on.contact);
    CHECK_FALSE(head_on.step_limit);
    // Over A without its notch (two convex polygons), the step of each
    // vertex's own approach: B turning by 1e-12 comes towards A's top at
    // most at 1e-12 times its radius, so the grazing is passed in a few
    // steps, apart, in double, certified and exact alike.
    const polygon convex = square(0, 0, 4, 4);
    sweep_options few;
    few.max_steps = 20;
    for (const contact_result<double>& r :
         {first_contact<double>(convex, b, from, to, few), certified_first_contact(convex, b, from, to, few)}) {
        CHECK_FALSE(r.contact);
        CHECK_FALSE(r.step_limit);
    }
    const contact_result<exact_rational> cx = first_contact<exact_rational>(convex, b, from, to, few);
    CHECK_FALSE(cx.contact);
    CHECK_FALSE(cx.step_limit);
    // The same slide 3e-9 lower meets A (touching its top side).
    const pose low_from{-2, 4.5, 0}, low_to{6, 4.5, 1e-12};
    const contact_result<double> touch = certified_first_contact(convex, b, low_from, low_to, few);
    CHECK(touch.contact);
    CHECK(touch.time <= 0.1875);
    CHECK(touch.time == Approx(0.1875).margin(1e-9));
}
