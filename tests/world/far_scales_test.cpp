// SPDX-License-Identifier: BSL-1.0
// The world, the layer join and the two-pose queries in double far from 1
// in scale (core/range_scaling.hpp): a scene scaled by 2^e (every shape's
// coordinates, every translation, the distance) must give the contacts,
// witnesses, events and pairs it gives at scale 1, where double has room.
// Each answer at scale 1 is also counted against the certified answer (an
// exact one), so that the comparison is not of two wrong answers. Before
// the scaling, double reported pairs apart as touching from 2^+-600 on (its
// orientations' products overflowed or underflowed to 0).

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "influence2d/exact/certified_both_posed.hpp"
#include "influence2d/exact/certified_world.hpp"
#include "influence2d/query/both_posed.hpp"
#include "influence2d/world/layer_pairs.hpp"
#include "influence2d/world/world.hpp"
#include "support/effort.hpp"
#include "support/random_scenes.hpp"
#include "support/shapes.hpp"

using namespace influence2d;

namespace {

pose scaled_pose(const pose& q, int e) { return {std::ldexp(q.tx, e), std::ldexp(q.ty, e), q.theta}; }

std::string show_far(const std::vector<body_pair>& v) {
    std::ostringstream s;
    for (const body_pair& p : v) s << '(' << p.first << ',' << p.second << ')';
    return s.str();
}

std::string show_far(const std::vector<contact_witness>& v) {
    std::ostringstream s;
    for (const contact_witness& w : v)
        s << '(' << static_cast<int>(w.first.kind) << ':' << w.first.index << ',' << static_cast<int>(w.second.kind)
          << ':' << w.second.index << ')';
    return s.str();
}

std::string show_far(const std::vector<contact_event>& v) {
    std::ostringstream s;
    for (const contact_event& e : v) s << (e.begins ? '+' : '-') << e.bodies.first << ',' << e.bodies.second << ' ';
    return s.str();
}

/// A random scene: shapes, and for each step every body's pose (snapped
/// and unturned half of the time: exact touching; small moves between
/// steps).
struct far_scene {
    std::vector<polygon> shapes;
    std::vector<std::uint32_t> shape_of;
    std::vector<std::vector<pose>> steps;
};

far_scene random_scene(std::uint64_t seed, std::size_t bodies, int steps) {
    test_scenes::rng g(seed);
    far_scene s;
    for (int k = 0; k < 4; ++k) s.shapes.push_back(test_scenes::random_multi(g, 6, 5).to_polygon());
    std::vector<pose> at;
    for (std::size_t i = 0; i < bodies; ++i) {
        s.shape_of.push_back(static_cast<std::uint32_t>(g.index(s.shapes.size())));
        const double x = g.uniform(-20, 20), y = g.uniform(-20, 20);
        at.push_back(g.chance(0.5) ? pose{test_scenes::snap(x), test_scenes::snap(y), 0}
                                   : pose{x, y, g.uniform(-3.2, 3.2)});
    }
    for (int k = 0; k < steps; ++k) {
        s.steps.push_back(at);
        for (pose& q : at)
            if (g.chance(0.5))
                q = q.theta == 0
                        ? pose{q.tx + test_scenes::snap(g.uniform(-1, 1)), q.ty, 0}
                        : pose{q.tx + g.uniform(-1, 1), q.ty + g.uniform(-1, 1), q.theta + g.uniform(-0.1, 0.1)};
    }
    return s;
}

/// Each step's contacts, witnesses and events of a world over the scene
/// scaled by 2^e.
template <class World>
std::vector<std::string> run_far(const far_scene& s, int e, double within) {
    world_options o;
    o.witness = true;
    o.within = std::ldexp(within, e);
    World w(o);
    for (const polygon& p : s.shapes) w.add_shape(p.scaled_by_power_of_two(e));
    std::vector<std::string> out;
    for (std::size_t k = 0; k < s.steps.size(); ++k) {
        for (std::size_t i = 0; i < s.steps[k].size(); ++i) {
            const pose q = scaled_pose(s.steps[k][i], e);
            if (k == 0)
                w.add_body(s.shape_of[i], q, i % 5 == 0);
            else if (!(s.steps[k][i].tx == s.steps[k - 1][i].tx && s.steps[k][i].ty == s.steps[k - 1][i].ty &&
                       s.steps[k][i].theta == s.steps[k - 1][i].theta))
                w.move(static_cast<std::uint32_t>(i), q);
        }
        w.step();
        out.push_back(show_far(w.contacts()) + " | " + show_far(w.witnesses()) + " | " + show_far(w.events()));
    }
    return out;
}

}  // namespace

TEST_CASE("world in double far from 1 in scale: the contacts, witnesses and events of scale 1", "[world]") {
    const int scenes = test_effort::scaled(10);
    std::size_t steps_with_contacts = 0, differ_from_certified = 0, steps = 0;
    for (int k = 0; k < scenes; ++k)
        for (const double within : {0.0, 0.25}) {
            const far_scene s = random_scene(static_cast<std::uint64_t>(40 + k), 30, 4);
            const std::vector<std::string> at1 = run_far<world<double>>(s, 0, within);
            const std::vector<std::string> exact = run_far<certified_world>(s, 0, within);
            for (std::size_t step = 0; step < at1.size(); ++step) {
                ++steps;
                differ_from_certified +=
                    at1[step].substr(0, at1[step].find(" |")) != exact[step].substr(0, exact[step].find(" |"));
                steps_with_contacts += at1[step].rfind(" |", 0) != 0;
            }
            for (const int e : {-1000, -600, -300, 300, 600, 1000}) {
                INFO("scene " << k << ", within " << within << ", scale 2^" << e);
                const std::vector<std::string> at_e = run_far<world<double>>(s, e, within);
                for (std::size_t step = 0; step < at1.size(); ++step) {
                    INFO("step " << step);
                    CHECK(at_e[step] == at1[step]);
                }
            }
        }
    INFO("steps " << steps << ", with contacts " << steps_with_contacts << ", double's contacts unlike certified's "
                  << differ_from_certified);
    CHECK(steps_with_contacts == steps);
    CHECK(differ_from_certified * 10 <= steps);  // scale 1 is a reference worth matching
}

TEST_CASE("layer_pairs and the two-pose queries in double far from 1 in scale: the answers of scale 1", "[world]") {
    const int scenes = test_effort::scaled(8);
    std::size_t pairs = 0, met = 0, differ_from_certified = 0;
    for (int k = 0; k < scenes; ++k) {
        const far_scene s = random_scene(static_cast<std::uint64_t>(60 + k), 30, 1);
        std::vector<polygon> layer;
        for (std::size_t i = 0; i < s.shape_of.size(); ++i)
            if (s.steps[0][i].theta == 0)
                layer.push_back(test_shapes::translated(s.shapes[s.shape_of[i]], s.steps[0][i].tx, s.steps[0][i].ty));
        const std::vector<polygon> first(layer.begin(), layer.begin() + static_cast<std::ptrdiff_t>(layer.size() / 2)),
            second(layer.begin() + static_cast<std::ptrdiff_t>(layer.size() / 2), layer.end());
        const auto scaled_layer = [](const std::vector<polygon>& l, int e) {
            std::vector<polygon> out;
            for (const polygon& p : l) out.push_back(p.scaled_by_power_of_two(e));
            return out;
        };
        const std::vector<body_pair> one = layer_pairs<double>(layer), two = layer_pairs<double>(first, second, 0.5);
        CHECK(show_far(one) == show_far(certified_layer_pairs(layer)));
        met += one.size();
        for (const int e : {-1000, -600, -300, 300, 600, 1000}) {
            INFO("scene " << k << ", scale 2^" << e);
            CHECK(show_far(layer_pairs<double>(scaled_layer(layer, e))) == show_far(one));
            CHECK(show_far(layer_pairs<double>(scaled_layer(first, e), scaled_layer(second, e), std::ldexp(0.5, e))) ==
                  show_far(two));
        }
        // Every pair of bodies, each at its own pose; and regions_meet on
        // the vertices posed in double.
        for (std::size_t i = 0; i < s.shape_of.size(); ++i)
            for (std::size_t j = i + 1; j < s.shape_of.size(); ++j) {
                const polygon &a = s.shapes[s.shape_of[i]], &b = s.shapes[s.shape_of[j]];
                const pose &qa = s.steps[0][i], &qb = s.steps[0][j];
                const bool at1 = intersects<double>(a, qa, b, qb);
                differ_from_certified += at1 != certified_intersects(a, qa, b, qb);
                ++pairs;
                std::vector<point<double>> va, vb;
                for (const point<double>& v : a.vertices()) va.push_back(rotation_pose(qa).apply<double>(v));
                for (const point<double>& v : b.vertices()) vb.push_back(rotation_pose(qb).apply<double>(v));
                const bool given1 = regions_meet<double>(a, va, b, vb);
                for (const int e : {-1000, -600, 600, 1000}) {
                    INFO("scene " << k << ", bodies " << i << ", " << j << ", scale 2^" << e);
                    const polygon as = a.scaled_by_power_of_two(e), bs = b.scaled_by_power_of_two(e);
                    CHECK(intersects<double>(as, scaled_pose(qa, e), bs, scaled_pose(qb, e)) == at1);
                    std::vector<point<double>> sa = va, sb = vb;
                    for (std::vector<point<double>>* vs : {&sa, &sb})
                        for (point<double>& v : *vs) v = {std::ldexp(v.x, e), std::ldexp(v.y, e)};
                    CHECK(regions_meet<double>(as, sa, bs, sb) == given1);
                }
            }
    }
    INFO("pairs " << pairs << ", layer pairs met " << met << ", double unlike certified " << differ_from_certified);
    CHECK(met > 0);
    CHECK(differ_from_certified * 20 <= pairs);
}
