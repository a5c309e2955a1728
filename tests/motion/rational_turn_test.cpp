// SPDX-License-Identifier: BSL-1.0
// First contact of turning motions in the rational model
// (motion/rational_turn.hpp) against an independent exact check on CGAL's
// Cartesian kernel over exact rationals: the motion's pose at a rational
// time computed here from the model's definition (docs/sweep.md: pieces of
// at most a quarter turn, the tangent of half the turn since a piece's
// start linear in time), B placed exactly there, and whether the regions
// meet decided by CGAL's own predicates (support/exact_regions.hpp). The
// reported time must have the regions apart at the double before it and
// at every sampled time before that, and meeting at the double after it
// (or, for a contact that only grazes, the reported vertex on the reported
// edge within a hair); a motion reported free must be apart at every
// sampled time. The certified route must give the exact answer, time and
// features alike.

#include <catch2/catch.hpp>

#include <CGAL/squared_distance_2.h>

#include <cmath>
#include <tuple>
#include <vector>

#include "influence2d/exact/certified_first_contact.hpp"
#include "influence2d/influence/bounds.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/motion/rational_apart.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/predicates/convexity.hpp"
#include "influence2d/world/layer_pairs.hpp"
#include "support/effort.hpp"
#include "support/exact_regions.hpp"
#include "support/neighbours.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

using namespace influence2d;
using test_exact::FT;
using test_exact::point_2;

namespace {

const sweep_options rational{1e-9, turning_model::rational};

/// B placed exactly at time t (a double in [0, 1]) of the rational motion
/// from `from` to `to`, from the model's definition: k pieces, k the least
/// power of two with |turn| / k <= pi / 2 (the double 1.5707963267948966);
/// piece j, for t in [j / k, (j + 1) / k), starts at the angle from.theta +
/// j (turn / k) (from.theta itself for j = 0), cosine and sine in double,
/// and turns by 2 atan(u), u = tan(turn / 2k) (in double) times the
/// fraction of the piece gone; the translation is from + t (to - from).
test_exact::placed_shape placed_at(const polygon& b, const pose& from, const pose& to, double t) {
    const double turn = to.theta - from.theta;
    double k = 1;
    while (std::fabs(turn) / k > 1.5707963267948966) k *= 2;
    const double step = turn / k;
    const double j = std::min(std::floor(t * k), k - 1);
    const double angle = j == 0 ? from.theta : from.theta + j * step;
    const FT c(std::cos(angle)), s(std::sin(angle)), w(std::tan(step / 2));
    const FT tau = (FT(t) - FT(j / k)) * FT(k);
    const FT u = w * tau, h = 1 + u * u;
    const FT tx = FT(from.tx) + FT(t) * (FT(to.tx) - FT(from.tx)), ty = FT(from.ty) + FT(t) * (FT(to.ty) - FT(from.ty));
    std::vector<point_2> pts;
    for (const point<double>& v : b.vertices()) {
        const FT mx = (FT(v.x) * (1 - u * u) - 2 * u * FT(v.y)) / h, my = (2 * u * FT(v.x) + FT(v.y) * (1 - u * u)) / h;
        pts.emplace_back(c * mx - s * my + tx, s * mx + c * my + ty);
    }
    return test_exact::placed_shape(b, std::move(pts));
}

bool meet_at(const polygon& a, const polygon& b, const pose& from, const pose& to, double t) {
    return test_exact::regions_meet(test_exact::place(a, pose{}), placed_at(b, from, to, t));
}

/// The squared distance between the reported vertex and edge at time t.
FT feature_gap(const polygon& a, const polygon& b, const pose& from, const pose& to, const contact_result<double>& r) {
    const test_exact::placed_shape pa = test_exact::place(a, pose{}), pb = placed_at(b, from, to, r.time);
    const auto stored_vertex = [](const polygon& p, std::size_t input) {
        for (std::size_t i = 0; i < p.size(); ++i)
            if (input_vertex(p, i) == input) return i;
        return std::size_t{0};
    };
    const auto stored_edge = [](const polygon& p, std::size_t input) {
        for (std::size_t i = 0; i < p.size(); ++i)
            if (p.source_edge(i) == input) return i;
        return std::size_t{0};
    };
    if (r.moving_feature.kind == feature_kind::vertex) {
        const std::size_t v = stored_vertex(b, r.moving_feature.index), e = stored_edge(a, r.static_feature.index);
        return CGAL::squared_distance(pb.v[v], test_exact::segment_2(pa.v[e], pa.end(e)));
    }
    const std::size_t v = stored_vertex(a, r.static_feature.index), e = stored_edge(b, r.moving_feature.index);
    return CGAL::squared_distance(pa.v[v], test_exact::segment_2(pb.v[e], pb.end(e)));
}

/// The counts of a check, for the non-vacuity checks.
struct turn_tally {
    std::size_t motions = 0, contacts = 0, at_start = 0, grazing = 0, free = 0, double_differs = 0,
                double_time_differs = 0;
};

/// Checks one motion against the exact reference; `samples` times before
/// the contact (or over the whole motion) must be apart.
void check_turn_motion(const polygon& a, const polygon& b, const pose& from, const pose& to, int samples,
                       turn_tally& n) {
    INFO("from (" << from.tx << ", " << from.ty << ", " << from.theta << ") to (" << to.tx << ", " << to.ty << ", "
                  << to.theta << ")");
    const contact_result<exact_rational> e = first_contact<exact_rational>(a, b, from, to, rational);
    const contact_result<double> c = certified_first_contact(a, b, from, to, rational);
    const contact_result<double> d = first_contact<double>(a, b, from, to, rational);
    const double time = CGAL::to_double(e.time);
    ++n.motions;
    CHECK(c.contact == e.contact);
    CHECK(c.time == time);
    CHECK(c.static_feature.kind == e.static_feature.kind);
    CHECK(c.static_feature.index == e.static_feature.index);
    CHECK(c.moving_feature.index == e.moving_feature.index);
    n.double_differs += d.contact != e.contact;
    n.double_time_differs += e.contact && d.contact && d.time != time;
    if (!e.contact) {
        ++n.free;
        for (int i = 0; i <= samples; ++i) {
            INFO("sample " << i);
            CHECK_FALSE(meet_at(a, b, from, to, double(i) / samples));
        }
        return;
    }
    ++n.contacts;
    if (time == 0) {
        ++n.at_start;
        CHECK(meet_at(a, b, from, to, 0));
        return;
    }
    CHECK_FALSE(meet_at(a, b, from, to, std::nextafter(time, 0.0)));
    for (int i = 0; i < samples; ++i) {
        INFO("sample " << i);
        CHECK_FALSE(meet_at(a, b, from, to, time * i / samples));
    }
    const double after = std::min(std::nextafter(time, 2.0), 1.0);
    if (!meet_at(a, b, from, to, after) && !meet_at(a, b, from, to, time)) {
        // Grazing: the regions touch at the exact time alone (and are
        // apart again a little later); the reported vertex lies on the
        // reported edge at the nearest double, within its rounding.
        ++n.grazing;
        CHECK_FALSE(meet_at(a, b, from, to, std::min(time + 1e-9, 1.0)));  // and leave again
        const double scale = coordinate_scale(a) + coordinate_scale(b) + std::fabs(from.tx) + std::fabs(to.tx) +
                             std::fabs(from.ty) + std::fabs(to.ty);
        CHECK(feature_gap(a, b, from, to, contact_result<double>{true, time, e.static_feature, e.moving_feature}) <=
              FT(scale * 0x1p-48) * FT(scale * 0x1p-48));
    }
}

}  // namespace

TEST_CASE("rational turning: random multipolygons and stars against the exact reference", "[rational_turn]") {
    const int scenes = test_effort::scaled(24);
    turn_tally n;
    for (int scene = 0; scene < scenes; ++scene) {
        test_random::rng g(static_cast<std::uint64_t>(3100 + scene));
        const polygon a = test_scenes::random_multi(g, 8, 6).to_polygon();
        const polygon b = polygon({{test_scenes::star(g, {0, 0}, 0.5, 2.5, 5 + g.index(8)), ring_role::outer}});
        for (int k = 0; k < 4; ++k) {
            // From a place around A, towards its middle by up to twice the
            // way there, turning by a little or by up to four pieces.
            const pose from{g.uniform(-14, 14), g.uniform(-14, 14), g.uniform(-3, 3)};
            const double turn = k == 0 ? g.uniform(-0.3, 0.3) : g.uniform(-5, 5), go = g.uniform(0, 2);
            const pose to{from.tx * (1 - go) + g.uniform(-2, 2), from.ty * (1 - go) + g.uniform(-2, 2),
                          from.theta + turn};
            check_turn_motion(a, b, from, to, 200, n);
            check_turn_motion(b, a, from, to, 50, n);  // the roles swapped: the multipolygon turns
        }
    }
    INFO("motions " << n.motions << ", contacts " << n.contacts << " (at the start " << n.at_start << ", grazing "
                    << n.grazing << "), free " << n.free << ", double's answers unlike the exact ones "
                    << n.double_differs);
    CHECK(n.contacts > n.at_start + n.motions / 4);
    CHECK(n.free > 0);
    CHECK(n.at_start > 0);
    WARN("motions " << n.motions << ", contacts " << n.contacts << " (at the start " << n.at_start << ", grazing "
                    << n.grazing << "), free " << n.free << ", double's answers unlike the exact ones "
                    << n.double_differs << ", times " << n.double_time_differs);
}

/// The counts of check_against_whole_search.
struct window_tally {
    std::size_t guessed = 0, within = 0, beyond = 0, forced = 0, crossing = 0;
};

/// Checks the certified answer of one convex motion against the exact
/// search over whole pieces (rational_first_contact without advancement's
/// start, free part or guessed window): the same contact and time, and
/// the same features after the start (at the start either names features
/// that meet there); counts where advancement's guess of the contact
/// (rational_start::until) held it, and where the contact lay beyond; and
/// the same answer from advancement's start with other guesses. A start
/// that advancement proves meeting (two edges crossing) meets in the search.
void check_against_whole_search(const polygon& a, const polygon& b, const pose& from, const pose& to, window_tally& w) {
    INFO("from (" << from.tx << ", " << from.ty << ", " << from.theta << ") to (" << to.tx << ", " << to.ty << ", "
                  << to.theta << ")");
    const contact_result<double> whole = rational_first_contact<exact_rational>(a, b, from, to);
    const contact_result<double> c = certified_first_contact(a, b, from, to, rational);
    CHECK(c.contact == whole.contact);
    CHECK(c.time == whole.time);
    if (c.contact && c.time > 0) {
        CHECK(c.static_feature.kind == whole.static_feature.kind);
        CHECK(c.static_feature.index == whole.static_feature.index);
        CHECK(c.moving_feature.index == whole.moving_feature.index);
    }
    const sweep::rational_progress p = sweep::rational_advance(a, b, from, to);
    if (p.crossing_at_start) {
        ++w.crossing;
        CHECK(whole.contact);
        CHECK(whole.time == 0);
        return;
    }
    if (p.apart) return;
    const rational_piece piece = rational_pieces(from, to)[p.start.piece];
    const double span = piece.t1 - piece.t0;
    if (p.start.until > p.start.tau) {
        ++w.guessed;
        ++(whole.contact && whole.time <= piece.t0 + p.start.until * span ? w.within : w.beyond);
    }
    // Other guesses: short of the contact (its window empty), at it, just
    // short of it, and beyond it; the answer stays.
    if (!whole.contact || !(whole.time > piece.t0) || !(whole.time <= piece.t1)) return;
    const double at = (whole.time - piece.t0) / span, tau = p.start.tau;
    for (const double until : {tau + (at - tau) / 2, at, std::nextafter(at, 0.0), at + (1 - at) / 2}) {
        if (!(until > tau) || until > 1) continue;
        INFO("guess " << until << ", contact at " << at);
        ++w.forced;
        const contact_result<double> r =
            rational_first_contact<exact_rational>(a, b, from, to, {p.start.piece, tau, until});
        CHECK(r.contact);
        CHECK(r.time == whole.time);
        CHECK(r.static_feature.index == whole.static_feature.index);
        CHECK(r.moving_feature.index == whole.moving_feature.index);
    }
}

TEST_CASE("rational turning: convex pairs proven apart by advancement", "[rational_turn]") {
    // Two convex polygons (on ellipses, 3 to 16 vertices): where
    // rational_apart says the rational motion keeps them apart, the exact
    // search without it (rational_first_contact) finds no contact and the
    // exact placements at 200 times are apart; every motion is checked as
    // above too (the queries answer with rational_apart first).
    test_random::rng g(0x4a9a7ULL);
    turn_tally n;
    window_tally w;
    std::size_t apart = 0, tried = 0;
    for (int scene = 0; scene < test_effort::scaled(24); ++scene) {
        const double size = std::ldexp(1.0, static_cast<int>(g.uniform(-6, 6)));
        const polygon a({test_shapes::ring(
            test_shapes::ellipse_points(g, 3 + g.index(14), {0, 0}, size, size * g.uniform(0.1, 1)))});
        const polygon b({test_shapes::ring(test_shapes::ellipse_points(
            g, 3 + g.index(14), {0, 0}, size * g.uniform(0.2, 1.5), size * g.uniform(0.05, 1)))});
        for (int k = 0; k < 4; ++k) {
            const double reach = size * g.uniform(1, 4), angle = g.uniform(0, 6.283185307179586);
            const pose from{reach * std::cos(angle), reach * std::sin(angle), g.uniform(-3, 3)};
            const double go = g.uniform(0, 1.5);
            const pose to{from.tx * (1 - go), from.ty * (1 - go), from.theta + g.uniform(-5, 5)};
            ++tried;
            if (sweep::rational_apart(a, b, from, to)) {
                ++apart;
                INFO("from (" << from.tx << ", " << from.ty << ", " << from.theta << ") to (" << to.tx << ", " << to.ty
                              << ", " << to.theta << ")");
                CHECK_FALSE(rational_first_contact<exact_rational>(a, b, from, to).contact);
                for (int i = 0; i <= 200; ++i) CHECK_FALSE(meet_at(a, b, from, to, double(i) / 200));
            }
            check_turn_motion(a, b, from, to, 50, n);
            check_against_whole_search(a, b, from, to, w);
        }
        // A thin bar turning in place beside A, long enough to sweep through
        // it while neither end pose meets it (tunnelling unless the steps
        // follow the turn), or too short to reach it.
        const polygon bar(
            {test_shapes::ring(test_shapes::ellipse_points(g, 4 + g.index(8), {0, 0}, size * 2.5, size * 0.02))});
        for (const double gap : {0.5, 2.0}) {
            const double angle = g.uniform(0, 6.283185307179586), reach = size * (1 + gap);
            const pose from{reach * std::cos(angle), reach * std::sin(angle), g.uniform(-3, 3)};
            const pose to{from.tx, from.ty, from.theta + (g.chance(0.5) ? 3.1 : -3.1)};
            ++tried;
            if (sweep::rational_apart(a, bar, from, to)) {
                ++apart;
                CHECK_FALSE(rational_first_contact<exact_rational>(a, bar, from, to).contact);
                for (int i = 0; i <= 200; ++i) CHECK_FALSE(meet_at(a, bar, from, to, double(i) / 200));
            }
            check_turn_motion(a, bar, from, to, 50, n);
            check_against_whole_search(a, bar, from, to, w);
        }
    }
    WARN("convex pairs turning: " << tried << " motions, " << apart << " proven apart, " << n.contacts << " contacts; "
                                  << w.guessed << " contacts guessed, " << w.within << " within the guess, " << w.beyond
                                  << " beyond it; " << w.forced << " other guesses; " << w.crossing
                                  << " crossing at the start");
    CHECK(apart > tried / 5);
    CHECK(n.contacts > tried / 5);
    CHECK(w.within > 0);
    CHECK(w.forced > 0);
    CHECK(w.crossing > 0);
}

TEST_CASE("rational turning: advancement's vertex step keeps B beyond A's support", "[rational_turn]") {
    // Two convex polygons, B turning by up to 1.5 radians (one piece) from
    // a place beside A, or about A's middle: B posed in double at a random tau as the
    // advancement poses it, and the step rational_largest_step allows along
    // the axis between their middles; at 64 times of that step, B placed
    // exactly by the model's definition has every vertex beyond A's
    // support along the axis. The steps where a vertex comes back to within
    // a quarter of its start's gap show the bound near its edge (half of
    // rational_turn_acceleration fails 3 checks, a tenth 25; half the
    // turn's speed in a vertex's derivative 16).
    test_random::rng g(0x5e7e9ULL);
    std::size_t steps = 0, tight = 0;
    for (int trial = 0; trial < test_effort::scaled(300); ++trial) {
        const polygon a(
            {test_shapes::ring(test_shapes::ellipse_points(g, 3 + g.index(10), {0, 0}, 1, g.uniform(0.1, 1)))});
        // Odd trials: B small and away from its origin, which stays near
        // A's middle, so that B orbits A and curves towards it.
        const bool orbit = trial % 2 == 1;
        const double orbit_radius = g.uniform(1.6, 3);
        const polygon b({test_shapes::ring(
            orbit ? test_shapes::ellipse_points(g, 3 + g.index(10), {orbit_radius, 0}, 0.3, g.uniform(0.05, 0.3))
                  : test_shapes::ellipse_points(g, 3 + g.index(10), {0, 0}, g.uniform(0.3, 3), g.uniform(0.05, 1)))});
        const double reach = orbit ? g.uniform(0, 0.2) : g.uniform(1.5, 5), angle = g.uniform(0, 6.283185307179586);
        const pose from{reach * std::cos(angle), reach * std::sin(angle), g.uniform(-3, 3)};
        const double drift = orbit ? 0.1 : 1;
        const pose to{from.tx + g.uniform(-drift, drift), from.ty + g.uniform(-drift, drift),
                      from.theta + g.uniform(-1.5, 1.5)};
        const rational_piece piece = rational_pieces(from, to).at(0);
        const double tau = g.uniform(0, 1), u = piece.w * tau, h = 1 + u * u, c2 = (1 - u * u) / h, s2 = 2 * u / h;
        const point<double> shift{to.tx - from.tx, to.ty - from.ty};
        const point<double> move{from.tx + tau * shift.x, from.ty + tau * shift.y};
        std::vector<point<double>> av, posed;
        for (std::size_t i = 0; i < a.size(); ++i) av.push_back(a.vertex(i));
        point<double> middle{0, 0};
        for (std::size_t j = 0; j < b.size(); ++j) {
            const point<double>& q = b.vertex(j);
            const double x = c2 * q.x - s2 * q.y, y = s2 * q.x + c2 * q.y;
            posed.push_back({piece.c * x - piece.s * y + move.x, piece.s * x + piece.c * y + move.y});
            middle = {middle.x + posed.back().x / double(b.size()), middle.y + posed.back().y / double(b.size())};
        }
        const double r = bounding_radius(b, {0, 0});
        const double delta = sweep::rational_pose_rounding *
                             (r + std::fabs(from.tx) + std::fabs(from.ty) + std::fabs(to.tx) + std::fabs(to.ty));
        const double v = (std::hypot(shift.x, shift.y) + 2 * std::fabs(piece.w) * r) * 1.001;
        const double step =
            sweep::rational_largest_step(av, posed, move, middle, piece.w, tau, shift, r, posing_spread * delta + 1e-12,
                                         2 * posing_spread * delta + sweep::derivative_slack * v);
        if (!(step > 0)) continue;
        ++steps;
        INFO("trial " << trial << ", tau " << tau << ", step " << step);
        const FT nx(middle.x), ny(middle.y);
        FT support = FT(nx * FT(av[0].x) + ny * FT(av[0].y));
        for (const point<double>& p : av) support = std::max(support, FT(nx * FT(p.x) + ny * FT(p.y)));
        const auto gap = [&](double t) {
            const test_exact::placed_shape pb = placed_at(b, from, to, t);
            FT least = FT(nx * pb.v[0].x() + ny * pb.v[0].y() - support);
            for (const point_2& q : pb.v) least = std::min(least, FT(nx * q.x() + ny * q.y() - support));
            return least;
        };
        const FT start = gap(tau);
        bool near = false;
        for (int i = 1; i <= 64; ++i) {
            const double t = std::min(1.0, tau + step * i / 64);
            const FT at = gap(t);
            CHECK(at > 0);
            near = near || at * 4 < start;
            if (t == 1) break;
        }
        tight += near;
    }
    WARN("vertex steps: " << steps << " checked, " << tight << " coming within a quarter of the start's gap");
    CHECK(steps > std::size_t(test_effort::scaled(300)) / 4);
    CHECK(tight > 0);
}

TEST_CASE("rational turning: a vertex grazing an edge, sliding along one, touching at the start", "[rational_turn]") {
    turn_tally n;
    // B's vertex (3, 4) turned about the origin reaches y = 5 exactly at
    // u = 1/3 (the tangent of half of pi/2 minus its angle's half) and
    // falls back: a contact of one instant, a double root of its cubic.
    const polygon lid({test_shapes::square_ring(-10, 5, 20)});  // y in [5, 25]
    const polygon tri({test_shapes::ring({{0, 0}, {3, 4}, {-1, 1}})});
    const pose start{0, 0, 0};
    for (const double turn : {1.0, 1.4, -1.0, 3.0}) {
        INFO("turn " << turn);
        const pose end{0, 0, turn};
        const contact_result<exact_rational> e = first_contact<exact_rational>(lid, tri, start, end, rational);
        CHECK(e.contact == (turn > 0.65));  // u = tan(turn / 2) (one piece) reaches 1/3 when turn > 2 atan(1/3)
        check_turn_motion(lid, tri, start, end, 200, n);
    }
    CHECK(n.grazing > 0);

    // Tangent at a dyadic time, where bisection evaluates the cubic's Sturm
    // sequence at its double root: B turns about its origin (0, r) by the
    // angle whose half has tangent 1/2 (w = 1/2 exactly), and its vertex at
    // radius r = sqrt(vx^2 + vy^2) reaches the bottom of its circle, (0, 0)
    // on A's top edge, at u = 1/4 (tau 1/2: v = (-8, -15), r = 17) or at
    // u = 1/2 (tau 1: v = (-4, -3), r = 5).
    double half_turn = 2 * std::atan(0.5);
    for (int k = 0; k < 8 && std::tan(half_turn / 2) != 0.5; ++k)
        half_turn = std::nextafter(half_turn, std::tan(half_turn / 2) < 0.5 ? 4.0 : 0.0);
    REQUIRE(std::tan(half_turn / 2) == 0.5);
    const polygon floor({test_shapes::ring({{-30, -5}, {30, -5}, {30, 0}, {-30, 0}})});
    for (const auto& [vx, vy, r, when] : {std::tuple{-8.0, -15.0, 17.0, 0.5}, std::tuple{-4.0, -3.0, 5.0, 1.0}}) {
        INFO("tangent at " << when);
        const polygon wheel({test_shapes::ring({{vx, vy}, {-vx, vy}, {0, 4}})});
        const pose from{0, r, 0}, to{0, r, half_turn};
        const contact_result<exact_rational> e = first_contact<exact_rational>(floor, wheel, from, to, rational);
        CHECK(e.contact);
        CHECK(e.time == exact_rational(when));
        CHECK(e.moving_feature.kind == feature_kind::vertex);
        CHECK(e.moving_feature.index == 0);
        const contact_result<double> c = certified_first_contact(floor, wheel, from, to, rational);
        CHECK(c.contact);
        CHECK(c.time == when);
        CHECK(first_contact<double>(floor, wheel, from, to, rational).contact);
        check_turn_motion(floor, wheel, from, to, 200, n);
    }

    // A contact at a subnormal time, a quarter of its step above a double
    // (the step 2^-1074 halves below the subnormals): B's vertex at its
    // origin falls from y = a = 2^-1030 onto A's top edge (y = 0) and meets
    // it at t = a / (a - b), rounded to a, not to a's neighbour above.
    const double a_sub = std::ldexp(1.0, -1030), b_sub = -(1 - std::ldexp(1.0, -46));
    const exact_rational t_sub = exact_rational(a_sub) / (exact_rational(a_sub) - exact_rational(b_sub));
    const exact_rational up = exact_rational(std::nextafter(a_sub, 1.0));
    REQUIRE(t_sub > exact_rational(a_sub));
    REQUIRE(t_sub - exact_rational(a_sub) < up - t_sub);
    const pose fall_from{0, a_sub, 0}, fall_to{0, b_sub, 0.001};
    const polygon pin({test_shapes::ring({{0, 0}, {1, 2}, {-1, 2}})});
    const contact_result<exact_rational> fall = first_contact<exact_rational>(floor, pin, fall_from, fall_to, rational);
    CHECK(fall.contact);
    CHECK(fall.time == exact_rational(a_sub));
    CHECK(certified_first_contact(floor, pin, fall_from, fall_to, rational).time == a_sub);

    // B's vertex at its own origin slides along A's top edge's line (y = 0)
    // while B turns a little about it, and reaches A's corner (-10, 0)
    // exactly halfway.
    const polygon block({test_shapes::square_ring(-10, -20, 20)});  // [-10, 10] x [-20, 0]
    const polygon spike({test_shapes::ring({{0, 0}, {1, 5}, {-1, 5}})});
    const contact_result<exact_rational> slide =
        first_contact<exact_rational>(block, spike, {-20, 0, -0.1}, {0, 0, 0.1}, rational);
    CHECK(slide.contact);
    CHECK(slide.time == exact_rational(0.5));
    check_turn_motion(block, spike, {-20, 0, -0.1}, {0, 0, 0.1}, 200, n);
    // Touching at the start.
    const contact_result<exact_rational> touching =
        first_contact<exact_rational>(block, spike, {5, 0, 0}, {5, 3, 1}, rational);
    CHECK(touching.contact);
    CHECK(touching.time == exact_rational(0));
}

TEST_CASE("rational turning: far from 1 in scale, the same answers", "[rational_turn]") {
    const int scenes = test_effort::scaled(6);
    std::size_t contacts = 0;
    for (int scene = 0; scene < scenes; ++scene) {
        test_random::rng g(static_cast<std::uint64_t>(3300 + scene));
        const polygon a = test_scenes::random_multi(g, 8, 4).to_polygon();
        const polygon b = polygon({{test_scenes::star(g, {0, 0}, 0.5, 2.5, 7), ring_role::outer}});
        const pose from{g.uniform(-12, 12), g.uniform(-12, 12), g.uniform(-3, 3)};
        const pose to{from.tx + g.uniform(-8, 8), from.ty + g.uniform(-8, 8), from.theta + g.uniform(-3, 3)};
        const contact_result<exact_rational> e = first_contact<exact_rational>(a, b, from, to, rational);
        const contact_result<double> d = first_contact<double>(a, b, from, to, rational);
        contacts += e.contact;
        for (const int k : {-600, 600}) {
            INFO("scene " << scene << ", scale 2^" << k);
            const polygon as = a.scaled_by_power_of_two(k), bs = b.scaled_by_power_of_two(k);
            const pose fs{std::ldexp(from.tx, k), std::ldexp(from.ty, k), from.theta},
                ts{std::ldexp(to.tx, k), std::ldexp(to.ty, k), to.theta};
            const contact_result<double> c = certified_first_contact(as, bs, fs, ts, rational);
            CHECK(c.contact == e.contact);
            CHECK(c.time == CGAL::to_double(e.time));
            CHECK(c.static_feature.index == e.static_feature.index);
            const contact_result<double> ds = first_contact<double>(as, bs, fs, ts, rational);
            CHECK(ds.contact == d.contact);
            CHECK(ds.time == d.time);
        }
    }
    CHECK(contacts > 0);
}

TEST_CASE("rational turning: convex pairs far from 1 in scale, every route alike", "[rational_turn]") {
    // Convex pairs on a coarse grid (so that scaling by 2^k is exact, down
    // among the subnormals), from poses near A, some meeting it at the
    // start: at each scale the exact answer (which scales the advancement
    // into double's window itself) and the certified one (which scales the
    // whole query) agree, features alike, and equal the answer at scale 1.
    // (The exact route advanced only inside the window once, and named
    // other features at a start contact than the certified one.)
    test_random::rng g(0x5ca1eULL);
    std::size_t at_start = 0, later = 0;
    for (int scene = 0; scene < test_effort::scaled(12); ++scene) {
        const auto grid_ring = [&](double rx, double ry) {
            std::vector<point<double>> p = test_shapes::ellipse_points(g, 4 + g.index(6), {0, 0}, rx, ry);
            for (point<double>& q : p)
                q = {std::ldexp(std::round(std::ldexp(q.x, 10)), -10),
                     std::ldexp(std::round(std::ldexp(q.y, 10)), -10)};
            return polygon({test_shapes::ring(p)});
        };
        const polygon a = grid_ring(4, 4 * g.uniform(0.3, 1)), b = grid_ring(2, 2 * g.uniform(0.3, 1));
        if (!is_convex_polygon(a) || !is_convex_polygon(b)) continue;
        const auto on_grid = [](double x) { return std::ldexp(std::round(std::ldexp(x, 10)), -10); };
        const double reach = g.uniform(2, 8), angle = g.uniform(0, 6.283185307179586);
        const pose from{on_grid(reach * std::cos(angle)), on_grid(reach * std::sin(angle)), g.uniform(-3, 3)};
        const pose to{on_grid(from.tx * g.uniform(-0.5, 1)), on_grid(from.ty * g.uniform(-0.5, 1)),
                      from.theta + g.uniform(-3, 3)};
        const contact_result<exact_rational> one = first_contact<exact_rational>(a, b, from, to, rational);
        at_start += one.contact && one.time == 0;
        later += one.contact && one.time > 0;
        for (const int k : {-1040, -600, 600}) {
            INFO("scene " << scene << ", scale 2^" << k);
            const polygon as = a.scaled_by_power_of_two(k), bs = b.scaled_by_power_of_two(k);
            const pose fs{std::ldexp(from.tx, k), std::ldexp(from.ty, k), from.theta},
                ts{std::ldexp(to.tx, k), std::ldexp(to.ty, k), to.theta};
            const contact_result<exact_rational> e = first_contact<exact_rational>(as, bs, fs, ts, rational);
            const contact_result<double> c = certified_first_contact(as, bs, fs, ts, rational);
            CHECK(c.contact == e.contact);
            CHECK(c.time == CGAL::to_double(e.time));
            CHECK(e.time == one.time);
            CHECK(e.contact == one.contact);
            for (const auto& r : {contact_result<double>{e.contact, 0, e.static_feature, e.moving_feature},
                                  contact_result<double>{c.contact, 0, c.static_feature, c.moving_feature}}) {
                CHECK(r.static_feature.kind == one.static_feature.kind);
                CHECK(r.static_feature.index == one.static_feature.index);
                CHECK(r.moving_feature.kind == one.moving_feature.kind);
                CHECK(r.moving_feature.index == one.moving_feature.index);
            }
        }
    }
    WARN("convex pairs far in scale: " << at_start << " meeting at the start, " << later << " later");
    CHECK(at_start > 0);
    CHECK(later > 0);
}

TEST_CASE("rational turning: real neighbours turned back to their place, touching at the same times",
          "[rational_turn][real]") {
    // North Carolina's counties share their border vertices exactly. B,
    // pushed off its neighbour A by 1e-3 of A's size along the line between
    // their centroids and turned by 1e-3 rad about the origin, turns and
    // slides back to its place: its shared vertices come back onto their
    // twins, pairs of features touching within rounding of each other, so
    // that double words cannot order their times and the search orders
    // those two in exact rationals. The times are checked against CGAL's
    // regions; the features of contacts that close are the search's own
    // order of their exact roots, which the search in exact rationals shares.
    const std::vector<polygon> layer = test_data::real_layer("nc_counties.wkt");
    const std::vector<body_pair> pairs = layer_pairs<double>(layer);
    const std::size_t count = static_cast<std::size_t>(test_effort::scaled(24));
    REQUIRE(pairs.size() >= count);
    turn_tally n;
    for (std::size_t k = 0; k < count; ++k) {
        const polygon &a = layer[pairs[k].first], &b = layer[pairs[k].second];
        const point<double> ca = a.centroid(), cb = b.centroid();
        const double size = std::max(a.bounds().max_x - a.bounds().min_x, a.bounds().max_y - a.bounds().min_y);
        const double dx = cb.x - ca.x, dy = cb.y - ca.y, length = std::hypot(dx, dy);
        INFO("counties " << pairs[k].first << " and " << pairs[k].second);
        check_turn_motion(a, b, {1e-3 * size * dx / length, 1e-3 * size * dy / length, 1e-3}, {0, 0, 0}, 8, n);
    }
    INFO("motions " << n.motions << ", contacts " << n.contacts << " (at the start " << n.at_start << "), free "
                    << n.free);
    CHECK(n.contacts > n.at_start);
}
