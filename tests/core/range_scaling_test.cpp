// SPDX-License-Identifier: BSL-1.0
// Queries in double far from 1 in scale (core/range_scaling.hpp): scaling a
// whole query by 2^e must change no answer but its lengths, which scale by
// 2^e exactly. The scenes are random multipolygons with holes and islands
// against random stars, built at scale 1 and again from scaled rings (as a
// user would give them), asked at poses near contact; each answer at 2^e is
// compared with the same type's answer at scale 1, where double has room.
// Before the scaling, double answered wrongly from 2^+-300 on (a time of NaN,
// a distance of 0 for polygons apart, a collision where there is none).

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "influence2d/core/range_scaling.hpp"
#include "influence2d/detect/detector.hpp"
#include "influence2d/distance/separation.hpp"
#include "influence2d/exact/certified_intersects.hpp"
#include "influence2d/motion/exit_distance.hpp"
#include "influence2d/motion/first_contact.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/query/intersects.hpp"
#include "support/effort.hpp"
#include "support/poses.hpp"
#include "support/random_scenes.hpp"

using namespace influence2d;

namespace {

/// The rings of a polygon as given to its constructor, every coordinate
/// times 2^e.
std::vector<ring_input> scaled_rings(const std::vector<ring_input>& rings, int e) {
    std::vector<ring_input> out = rings;
    for (ring_input& r : out)
        for (point<double>& v : r.vertices) v = {std::ldexp(v.x, e), std::ldexp(v.y, e)};
    return out;
}

pose scaled(const pose& q, int e) { return {std::ldexp(q.tx, e), std::ldexp(q.ty, e), q.theta}; }

bool same(const feature& l, const feature& r) { return l.kind == r.kind && l.index == r.index; }

}  // namespace

TEST_CASE("range scaling: the shift, 0 inside the window and for the exact types", "[range_scaling]") {
    CHECK(unscaled_exponent_limit<double>() == 64);
    CHECK(unscaled_exponent_limit<float>() == 8);
    CHECK(range_shift<double>(0.0) == 0);
    CHECK(range_shift<double>(std::ldexp(1.0, 64)) == 0);
    CHECK(range_shift<double>(std::ldexp(1.0, -64)) == 0);
    CHECK(range_shift<double>(std::ldexp(1.0, 65)) == -65);
    CHECK(range_shift<double>(std::ldexp(1.5, -300)) == 300);
    CHECK(range_shift<double>(std::ldexp(1.0, -1070)) == 1070);  // subnormal
    CHECK(range_shift<double>(std::nan("")) == 0);
    CHECK(range_shift<float>(1000.0) == -9);
    CHECK(range_shift<exact_rational>(std::ldexp(1.0, 900)) == 0);
    CHECK(range_shift<certified>(std::ldexp(1.0, -900)) == 0);
    // The window's edges, where its quick comparisons end: the doubles on
    // either side of 2^-W and 2^(W+1) against ilogb's exponent.
    for (const double x :
         {std::ldexp(1.0, -64), std::ldexp(1.0, 65), std::ldexp(1.0, -8), std::ldexp(1.0, 9), std::ldexp(1.0, -1024)})
        for (const double y : {std::nextafter(x, 0.0), x, std::nextafter(x, HUGE_VAL)}) {
            INFO(y);
            const auto shift = [y](int w) {
                const int e = std::ilogb(y);
                return e > w || e < -w ? -e : 0;
            };
            CHECK(range_shift<double>(y) == shift(64));
            CHECK(range_shift<float>(y) == shift(8));
            CHECK(range_shift<long double>(y) == shift(1024));
        }
    CHECK(range_shift<long double>(std::numeric_limits<double>::max()) == 0);
    CHECK(range_shift<double>(-1.0) == 0);
    CHECK(range_shift<double>(HUGE_VAL) == 0);
}

TEST_CASE("range scaling: a scaled polygon keeps its rings, orientation and edge numbers", "[range_scaling]") {
    test_random::rng g(41);
    const std::vector<ring_input> rings = test_scenes::random_multi(g, 20).rings();
    const polygon p(rings);
    const polygon s = p.scaled_by_power_of_two(-700), built(scaled_rings(rings, -700));
    REQUIRE(s.size() == p.size());
    REQUIRE(s.ring_count() == p.ring_count());
    for (std::size_t i = 0; i < p.size(); ++i) {
        CHECK(s.vertex(i) == point<double>{std::ldexp(p.vertex(i).x, -700), std::ldexp(p.vertex(i).y, -700)});
        CHECK(s.vertex(i) == built.vertex(i));
        CHECK(s.source_edge(i) == p.source_edge(i));
        CHECK(s.next(i) == p.next(i));
    }
    CHECK(s.centroid() == built.centroid());
    CHECK(s.bounds().max_x == built.bounds().max_x);
    CHECK(s.area() == built.area());
}

TEST_CASE("range scaling: double answers at 2^e as at scale 1, lengths scaled by 2^e", "[range_scaling]") {
    const int scenes = test_effort::scaled(8);
    std::size_t asked = 0, met = 0, apart = 0, contacts = 0, out_of_range = 0, differ_from_certified = 0;
    for (int scene = 0; scene < scenes; ++scene) {
        test_random::rng g(static_cast<std::uint64_t>(700 + scene));
        const std::vector<ring_input> ra = test_scenes::random_multi(g, 12).rings();
        const std::vector<ring_input> rb = {
            {test_scenes::star(g, {0, 0}, 1.0, 3.0, 5 + g.index(20)), ring_role::outer}};
        const polygon a(ra), b(rb);
        const std::vector<pose> poses = test_poses::near_contact(a, b, 24, 0.3, 0, 900 + scene);
        detector<double> d0(a, b);
        detector<double> w0(a, b, {0, true});
        separation_query<double> s0_query(a, b);
        for (int e : {-1000, -600, -300, -40, 40, 300, 600, 1000}) {
            INFO("scene " << scene << ", scale 2^" << e);
            const polygon as(scaled_rings(ra, e)), bs(scaled_rings(rb, e));
            detector<double> de(as, bs);
            detector<double> we(as, bs, {0, true});
            separation_query<double> se_query(as, bs);
            for (std::size_t k = 0; k < poses.size(); ++k) {
                const pose& q = poses[k];
                const pose qe = scaled(q, e);
                INFO("pose " << k);
                ++asked;
                // Yes or no: the detector (coherent from pose to pose) and the one-shot query.
                const bool meet = d0.collide(q).collides;
                CHECK(de.collide(qe).collides == meet);
                CHECK(intersects<double>(as, bs, qe) == intersects<double>(a, b, q));
                CHECK(we.collide(qe).pairs == w0.collide(q).pairs);
                (meet ? met : apart) += 1;
                // The exact answer at 2^e, an independent reference: double
                // may differ from it near contact as it does at scale 1.
                const bool exact = certified_intersects(as, bs, qe);
                CHECK(exact == certified_intersects(a, b, q));
                differ_from_certified += exact != meet;

                // The separation: the squared distance times 2^2e, or, where
                // that lies beyond double's range, a range_error.
                const separation_result<double> s0 = separation<double>(a, b, q);
                const double want = std::ldexp(s0.squared_distance, 2 * e);
                if (std::isinf(want) || (want == 0 && s0.squared_distance != 0)) {
                    CHECK_THROWS_AS(separation<double>(as, bs, qe), std::range_error);
                    CHECK_THROWS_AS(se_query(qe), std::range_error);
                    ++out_of_range;
                } else {
                    const separation_result<double> se = separation<double>(as, bs, qe);
                    CHECK(se.squared_distance == want);
                    CHECK(same(se.static_feature, s0.static_feature));
                    CHECK(same(se.moving_feature, s0.moving_feature));
                    CHECK(se.moving_point.x == std::ldexp(s0.moving_point.x, e));
                    // The prepared query, coherent from pose to pose, as its own answer at scale 1.
                    const separation_result<double> pe = se_query(qe), p0 = s0_query(q);
                    CHECK(pe.squared_distance == std::ldexp(p0.squared_distance, 2 * e));
                    CHECK(same(pe.static_feature, p0.static_feature));
                }

                // First contact along a translation to the next pose's place,
                // and along a motion that also turns (tolerance scaled too).
                const pose& next = poses[(k + 1) % poses.size()];
                const pose to{next.tx, next.ty, q.theta};
                const contact_result<double> c0 = first_contact<double>(a, b, q, to);
                const contact_result<double> ce = first_contact<double>(as, bs, qe, scaled(to, e));
                CHECK(ce.contact == c0.contact);
                CHECK(ce.time == c0.time);
                CHECK(same(ce.static_feature, c0.static_feature));
                contacts += c0.contact ? 1 : 0;
                if (k % 6 == 0) {
                    const sweep_options at1{1e-6}, at_e{std::ldexp(1e-6, e)};
                    const contact_result<double> t0 = first_contact<double>(a, b, q, next, at1);
                    const contact_result<double> te = first_contact<double>(as, bs, qe, scaled(next, e), at_e);
                    CHECK(te.contact == t0.contact);
                    CHECK(te.time == t0.time);
                }

                // The exit distance along a unit direction: times 2^e.
                const double x0 = exit_distance<double>(a, b, q, 0.6, -0.8);
                CHECK(exit_distance<double>(as, bs, qe, 0.6, -0.8) == std::ldexp(x0, e));
            }
        }
    }
    INFO("asked " << asked << ", met " << met << ", apart " << apart << ", contacts " << contacts
                  << ", squared distances out of range " << out_of_range << ", double against certified "
                  << differ_from_certified);
    CHECK(met > 0);
    CHECK(apart > 0);
    CHECK(contacts > 0);
    CHECK(out_of_range > 0);
}
